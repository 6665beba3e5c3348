import sys
sys.path.insert(0,'/work/main')
from pyadore.printout.writer import format_step, termination_line, statistics_lines
from pyadore.printout.model import UNKNOWN
def write(path, echo, steps, term, stats, stat_marks=None):
    out=list(echo)
    for s in steps:
        out+=format_step(s)
    out.append(termination_line(*term))
    out.append("")
    out+=statistics_lines(stats, stat_marks)
    text="\n".join(l.rstrip() for l in out)+"\n"
    assert max(len(l) for l in text.splitlines())<=132, max(len(l) for l in text.splitlines())
    open(path,'w').write(text)
