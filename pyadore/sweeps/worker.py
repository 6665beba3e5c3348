"""A local sweep worker process: ``python -m pyadore.sweeps.worker``.

It reads one job a line on stdin (JSON: the arguments of
:func:`pyadore.sweeps.execute.run_case`) and writes one result a line (JSON) on its
protocol channel, until stdin closes; when the channel is gone (its client was killed) it
ends quietly, without a BrokenPipeError traceback.  The channel is the original stdout; fd 1 is
pointed at stderr so that nothing else (a stray print) can mix into it.  A fresh
interpreter: nothing of the client's state (threads, its ``__main__``) is inherited.
Before its first job it imports the engine and the print reader (:func:`warm`), and it
serves every job of the sweep that comes to it: started once, it stays warm.
"""

from __future__ import annotations

import json
import os
import signal
import sys


def warm() -> None:
    """Import now what every case needs - the engine extension, numpy, the deck checker,
    the print reader - so that the worker's first case costs what the others do: the
    worker boots while the client prepares the cases, and stays warm for the whole sweep.
    Neither pandas nor xarray: a case reads its print's key results into plain tables
    (read_print(frames=False)), and a run with time steps writes its netCDF file and takes
    its averages from numpy arrays (:attr:`pyadore.Result.arrays`).  pandas was 60 % of the
    boot (about 0.6 s of CPU), xarray with dask about 2 s: serial costs that do not shrink
    with more workers (docs/sweeps.md, "Scaling")."""
    from .. import _core
    from ..api import run  # noqa: F401
    from ..deck import check_deck  # noqa: F401
    from ..printout import read_print  # noqa: F401
    from .results import key_results  # noqa: F401

    _core.base._engine()


def main() -> int:
    """Serve jobs until stdin closes; exit status 0."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the client ends its workers on Ctrl-C
    channel = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    from .execute import run_case

    warm()
    for line in sys.stdin:
        if not line.strip():
            continue
        job = json.loads(line)
        result = run_case(*job)
        try:
            channel.write(json.dumps(result) + "\n")
            channel.flush()
        except OSError:  # BrokenPipeError: the client is gone (killed); nobody to report to
            os._exit(0)  # at once: closing the channel at exit would raise the same error again
    return 0


if __name__ == "__main__":
    sys.exit(main())
