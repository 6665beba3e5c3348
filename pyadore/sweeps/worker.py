"""A local sweep worker process: ``python -m pyadore.sweeps.worker [--slots R:W,R:W,...]``.

A worker reads one job a line (JSON: the arguments of
:func:`pyadore.sweeps.execute.run_case`) and writes one result a line (JSON) on its
protocol channel, until its job channel closes; when the result channel is gone (its client
was killed) it ends quietly, without a BrokenPipeError traceback.  Its first line is
``{"ready": PID}`` once it is warm.  fd 1 is pointed at stderr so that nothing else (a
stray print) can mix into a channel.  A fresh interpreter: nothing of the client's state
(threads, its ``__main__``) is inherited.

Without ``--slots`` the channels are stdin and the original stdout: one worker.  With
``--slots`` (POSIX: the client passes the pipes' file descriptors) the process serves the
first slot itself and, on Linux, forks one child per other slot *after* it is warm (the
engine extension, numpy, the deck checker and the print reader imported, nothing run):
N workers cost one interpreter start, not N, and every worker's first case costs what the
others do (docs/sweeps.md, "Scaling").  The fork is of this fresh, single-threaded process
(OMP_NUM_THREADS and OPENBLAS_NUM_THREADS are 1 in a worker: one engine thread each), never
of the client.  Elsewhere each slot gets its own process (``--slots`` with one pair).
"""

from __future__ import annotations

import json
import os
import signal
import sys

#: The environment of a worker process: one engine (OpenMP) thread and one BLAS thread per
#: worker (a sweep's parallelism is its workers; a forked process must hold one thread).
WORKER_ENV = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}


def warm() -> None:
    """Import now what every case needs - the engine extension, numpy, the deck checker,
    the print reader - so that the worker's first case costs what the others do: the
    worker boots while the client prepares the cases, and stays warm for the whole sweep.
    Neither pandas nor xarray: a case reads its print's key results into plain tables
    (read_print(frames=False)), and a run with time steps writes its netCDF file and takes
    its averages from numpy arrays (:attr:`pyadore.Result.arrays`).  pandas was 60 % of the
    boot (about 0.6 s of CPU), xarray with dask about 2 s: serial costs that do not shrink
    with more workers (docs/sweeps.md, "Scaling").  Nothing of the engine runs here: a
    process forked after this holds no state of a run."""
    import tempfile  # noqa: F401  (each case's private folder)

    from .. import _core
    from ..api import run  # noqa: F401
    from ..deck import check_deck  # noqa: F401
    from ..printout import read_print  # noqa: F401
    from .execute import run_case  # noqa: F401
    from .results import key_results, mean_results  # noqa: F401

    _core.base._engine()


def serve(jobs, channel) -> None:
    """Announce this process (``{"ready": pid}``), then run the jobs of the text stream
    ``jobs`` until it closes, each result a line on ``channel``."""
    from .execute import run_case

    try:
        channel.write(json.dumps({"ready": os.getpid()}) + "\n")
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
    warm()
    if not slots:
        serve(sys.stdin, channel)
        return 0
    forking = len(slots) > 1 and sys.platform.startswith("linux")
    if forking:
        # the children end on their own (the kernel reaps them: no zombie while this one serves)
        signal.signal(signal.SIGCHLD, signal.SIG_IGN)
    for k, pair in enumerate(slots[1:] if forking else [], start=1):
        pid = os.fork()
        if pid == 0:  # the child: slot k only
            code = 0
            try:
                signal.signal(signal.SIGCHLD, signal.SIG_DFL)
                for other in slots[:k] + slots[k + 1:]:
                    for fd in other:
                        _close(fd)
                serve(*_open(pair))
            except BaseException:
                code = 1
            finally:
                os._exit(code)
        for fd in pair:  # the parent: only the child holds slot k (its death closes the channel)
            _close(fd)
    serve(*_open(slots[0]))
    return 0


def _close(fd: int) -> None:
    try:
        os.close(fd)
    except OSError:
        pass


if __name__ == "__main__":
    sys.exit(main())
