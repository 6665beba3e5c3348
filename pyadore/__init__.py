"""pyadore: an open, legacy-compatible rebuild of ADORE 5.0 rolling-bearing dynamics.

``pyadore.run(deck)`` runs an ADORE deck through the Fortran engine; ``pyadore.deck``
reads, validates and writes decks; ``pyadore.printout`` and ``pyadore.diff`` read and
compare print files; ``pyadore.sweep(deck, vary, out_dir)`` runs parametric studies.
Importing pyadore does not load the engine extension, nor numpy or pandas: ``run``,
``sweep`` and the other names below are imported when first used, so that the
``pyadore`` command installs its signal handlers before any heavy import (pyadore/cli.py).
"""

from __future__ import annotations

import os
from importlib import import_module

from .errors import AdoreEngineError, AdoreError, AdoreInputError, AdoreInterrupted

# The engine's threads (run option threads) spin briefly (3 000 rounds) between its parallel
# loops and then sleep, instead of libgomp's long spin, unless the environment sets either
# variable: OpenMP's run-time reads them when the engine extension loads it
# (docs/performance.md, "Threads"; fortran/app/wait_policy.c for adore)
if "OMP_WAIT_POLICY" not in os.environ and "GOMP_SPINCOUNT" not in os.environ:
    os.environ["OMP_WAIT_POLICY"] = "PASSIVE"
    os.environ["GOMP_SPINCOUNT"] = "3000"
#: the process that imported pyadore: a run in a child forked from it takes one thread unless
#: told otherwise (OpenMP's run-time of GCC, libgomp, does not survive a fork: a child's
#: first parallel loop after the parent ran one waits forever; docs/performance.md, "Threads")
_IMPORT_PID = os.getpid()

__all__ = ["run", "sweep", "read_traction_table", "Result", "BALL_STARTS", "AdoreError", "AdoreInputError",
           "AdoreEngineError", "AdoreInterrupted", "__version__"]

#: name -> module of the names imported when first used
_LAZY = {"run": ".api", "Result": ".api", "read_traction_table": ".api", "BALL_STARTS": ".api", "sweep": ".sweeps"}


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("pyadore")
    except PackageNotFoundError:  # running from a source tree that is not installed
        return "0+unknown"


def __getattr__(name: str):
    if name == "__version__":
        globals()[name] = value = _version()
        return value
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'pyadore' has no attribute {name!r}")
    value = getattr(import_module(module, __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_LAZY) | {"__version__"})
