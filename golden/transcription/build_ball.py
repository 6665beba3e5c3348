import os; os.chdir(os.path.dirname(os.path.abspath(__file__)))
exec(open('gen_ball.py').read())
exec(open('echo_ball.py').read())
from assemble import write
write('/work/main/golden/appendix_c_ball.prt', ECHO, STEPS, TERM, STATS)
