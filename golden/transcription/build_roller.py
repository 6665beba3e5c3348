import os; os.chdir(os.path.dirname(os.path.abspath(__file__)))
exec(open('gen_roller.py').read())
exec(open('echo_roller.py').read())
from assemble import write
write('/work/main/golden/appendix_d_roller.prt', ECHO, STEPS, TERM, STATS)
