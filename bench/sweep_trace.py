"""`python bench/sweep_trace.py OUT.json sweep DECK --vary ...`: the `pyadore sweep` command
(its own entry point, pyadore/__main__.py) with stamps for the bench's CPU budget
(bench/sweep_bench.py `budget`, docs/sweeps.md "Scaling").

Written to OUT.json once summary.csv is written: when and at what CPU time of this process
(``time.process_time``: the whole process since its start, the interpreter's included) the
command reached its entry point, its first job, each result and the end of the summary; each
case's own stamps and CPU time (``timing``, from its worker); each worker's ready line (the
boot's CPU time and end).  What follows the summary - the pool's end and the exit - the bench
times from outside (the process's end and its CPU by RUSAGE_CHILDREN).  The command runs as
`python -m pyadore` runs it: this script imports only what its first line imports anyway
(pyadore.sweeps.execute, for start_early) before it calls the entry point.
"""

from __future__ import annotations

import json
import sys
import time

MARKS: dict = {"main": [time.time(), time.process_time()], "results": [], "boot": []}

from pyadore.sweeps import execute  # noqa: E402  (what pyadore/__main__.py's start_early imports)

_run_local = execute.run_local


def _stamp() -> list[float]:
    return [time.time(), time.process_time()]


def run_local(jobs, pool, on_result, count, **kwargs):
    """execute.run_local with stamps: the first job, each result's arrival and its records."""

    def timed_jobs():
        for job in jobs:
            MARKS.setdefault("first_job", _stamp())
            yield job
        MARKS["jobs_done"] = _stamp()

    def timed_result(res):
        arrived = _stamp()
        on_result(res)
        MARKS["results"].append({"case": res["case"], "worker": res.get("worker"), "timing": res.get("timing"),
                                 "arrived": arrived,
                                 "recorded": _stamp()})

    from pyadore.sweeps import runner  # imported by now: it called this

    write_end = runner._Sweep.write_end  # the manifest and summary.csv at the sweep's end

    def summary_then_marks(self):
        write_end(self)
        MARKS["summary"] = _stamp()
        MARKS["heavy"] = sorted(m for m in ("numpy", "pandas", "xarray", "pyadore._engine", "tqdm")
                                if m in sys.modules)  # what the client imported
        with open(sys.argv[0], "w", encoding="utf-8") as fh:
            json.dump(MARKS, fh)

    runner._Sweep.write_end = summary_then_marks
    try:
        _run_local(timed_jobs(), pool, timed_result, count, **kwargs)
    finally:
        MARKS["boot"] = [dict(w.boot) for w in getattr(pool, "_workers", [])]


def main() -> None:
    sys.argv = [sys.argv[1], *sys.argv[2:]]  # argv[0]: the output file (click reads argv[1:])
    execute.run_local = run_local  # before the runner imports it
    from pyadore.__main__ import main as command

    command()


if __name__ == "__main__":
    main()
