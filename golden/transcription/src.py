"""Transcription helpers: read fields of the seed text by line number."""
import re
T=open('/work/shared/seed/000_f0ab926e9a2b5d30.txt').read().split('\n')
NUM=re.compile(r'^-?\d\.\d{3}E[-+]\d\d$')
def F(n):
    """tab fields of line n (1-based)"""
    return [x.strip() for x in T[n-1].split('\t')]
def vals(n, start, count):
    f=F(n)[start:start+count]
    f+=['']*(count-len(f))
    return [x if NUM.match(x) else '?' for x in f]
