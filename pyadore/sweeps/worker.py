"""A local sweep worker process: ``python -m pyadore.sweeps.worker [--slots R:W,R:W,...]``.

A worker reads one job a line (JSON: the arguments of
:func:`pyadore.sweeps.case.run_case`) and writes one result a line (JSON) on its
protocol channel, until its job channel closes; when the result channel is gone (its client
was killed) it ends quietly, without a BrokenPipeError traceback.  Its first line is
``{"ready": PID}`` once it is warm.  fd 1 is pointed at stderr so that nothing else (a
stray print) can mix into a channel.  A fresh interpreter: nothing of the client's state
(threads, its ``__main__``) is inherited.

Without ``--slots`` the channels are stdin and the original stdout: one worker.  With
``--slots`` (POSIX: the client passes the pipes' file descriptors), on Linux, the process is
a fork server: once warm (the engine, the deck checker and the print reader
imported, nothing run) it forks one worker per slot and waits for them.  N workers cost one
interpreter start, not N, and every worker's first case costs what the others do
(docs/sweeps.md, "Scaling").  The fork is of this fresh, single-threaded process (a
worker's OMP_NUM_THREADS and OPENBLAS_NUM_THREADS are 1, execute.WORKER_ENV: one engine
thread each), never of the client.  Elsewhere the process serves its one slot itself (the
client starts one process a slot).
"""

from __future__ import annotations

import gc
import json
import os
import signal
import sys
import time

def warm() -> None:
    """Import now what every case needs - the engine, the deck checker, the print reader -
    so that the worker's first case costs what the others do: the worker boots while the
    client prepares the cases, and stays warm for the whole sweep.  The engine is its shared
    object loaded without numpy (:mod:`pyadore._core.lite`: a case's run and its deck's
    cross-field checks; numpy was 70-110 ms of the boot's 130-150 ms of CPU, docs/sweeps.md
    "Scaling, eighteenth session"); a case with time steps imports numpy for its arrays.
    Neither pandas nor xarray: a case reads its print's key results into plain tables
    (read_print(frames=False)), and a run with time steps writes its netCDF file and takes
    its averages from numpy arrays (:attr:`pyadore.Result.arrays`).  pandas was 60 % of the
    boot (about 0.6 s of CPU), xarray with dask about 2 s: serial costs that do not shrink
    with more workers (docs/sweeps.md, "Scaling").  Nothing of the engine runs here but the
    lite binding's check (the names of the cross-field checks' fields): a process forked
    after this holds no state of a run."""
    import tempfile  # noqa: F401  (each case's private folder)

    from .. import _core
    from ..api import run  # noqa: F401
    from ..deck import check_deck  # noqa: F401
    from ..printout import read_print  # noqa: F401
    from .case import run_case  # noqa: F401
    from .results import key_results, mean_results  # noqa: F401

    _core.base._engine(lite=True)


def serve(jobs, channel, boot: dict | None = None) -> None:
    """Announce this process (``{"ready": pid, **boot}``: ``boot`` the boot's CPU time and when
    it ended, for the bench's budget), then run the jobs of the text stream ``jobs`` until it
    closes, each result a line on ``channel``."""
    from .case import run_case

    try:
        channel.write(json.dumps({"ready": os.getpid(), **(boot or {})}) + "\n")
        channel.flush()
        for line in jobs:
            if not line.strip():
                continue
            result = run_case(*json.loads(line))
            channel.write(json.dumps(result) + "\n")
            channel.flush()
    except OSError:  # BrokenPipeError: the client is gone (killed); nobody to report to
        os._exit(0)  # at once: closing the channel at exit would raise the same error again


def _slots(argv: list[str]) -> list[tuple[int, int]]:
    """The (job fd, result fd) pairs of ``--slots R:W,R:W,...``; [] without the option."""
    if len(argv) >= 2 and argv[0] == "--slots":
        return [tuple(int(x) for x in pair.split(":")) for pair in argv[1].split(",")]
    return []


def _open(pair: tuple[int, int]):
    return (os.fdopen(pair[0], "r", encoding="utf-8"), os.fdopen(pair[1], "w", encoding="utf-8"))


def main(argv: list[str] | None = None) -> int:
    """Serve jobs until the job channel closes; exit status 0."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the client ends its workers on Ctrl-C
    slots = _slots(sys.argv[1:] if argv is None else argv)
    if not slots:
        channel = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    # no cyclic garbage collection while the boot imports (its collections walk every object
    # the imports made, several times: serial CPU before the first case); the modules' objects
    # then go to the collector's permanent generation before the workers are forked, so that
    # no worker's collections touch - and copy - the pages they share (Python's gc.freeze)
    gc.disable()
    warm()
    # the boot's CPU time (this process's, or the fork server's until it forks) and its end
    boot = {"boot_cpu_s": time.process_time(), "booted_at": time.time()}
    gc.freeze()
    if not slots:
        gc.enable()
        serve(sys.stdin, channel, boot)
        return 0
    if not sys.platform.startswith("linux"):
        gc.enable()
        serve(*_open(slots[0]), boot)  # one slot a process (the client starts one each)
        return 0
    # Linux: this warm process forks one worker per slot and waits for them (a fork server: it
    # runs no case itself, so an engine crash never takes it, and it reaps its workers)
    for k, pair in enumerate(slots):
        pid = os.fork()
        if pid == 0:  # the worker of slot k
            code = 0
            gc.enable()
            try:
                for other in slots[k + 1:]:  # (those of the slots before are closed already)
                    for fd in other:
                        _close(fd)
                serve(*_open(pair), boot)
            except BaseException:
                code = 1
            finally:
                os._exit(code)
        for fd in pair:  # only the worker holds slot k: its end closes the client's channel
            _close(fd)
    while True:
        try:
            os.wait()
        except ChildProcessError:  # every worker ended: so does this process, at once (nothing to
            os._exit(0)            # flush; the interpreter's own clean-up is wall time a sweep waits for)
        except InterruptedError:
            continue


def _close(fd: int) -> None:
    try:
        os.close(fd)
    except OSError:
        pass


if __name__ == "__main__":
    sys.exit(main())
