import sys
sys.path.insert(0,'/work/main')
import pandas as pd
from pyadore.printout import layout as L
from pyadore.printout.model import Step, UNKNOWN
RECOVERED=[]
def table(spec_cols, rows, index_name='element', multi=False):
    """rows: list of (label, tokens) -> (values df, markers df)"""
    idx=[r[0] for r in rows]
    vals=[]; marks=[]
    for lab,toks in rows:
        assert len(toks)==len(spec_cols), (lab, len(toks), len(spec_cols), toks)
        vals.append([float('nan') if t=='?' else float(t) for t in toks])
        marks.append([UNKNOWN if t=='?' else '' for t in toks])
    if multi:
        index=pd.MultiIndex.from_tuples(idx, names=['element','end'])
    else:
        index=pd.Index(idx, name=index_name)
    return pd.DataFrame(vals,index=index,columns=list(spec_cols)), pd.DataFrame(marks,index=index,columns=list(spec_cols))
def put(step, name, cols, rows, **kw):
    v,m=table(cols, rows, **kw)
    step.tables[name]=v; step.markers[name]=m
def rec(where, value, reason):
    RECOVERED.append((where, value, reason))
