"""pyadore: an open, legacy-compatible rebuild of ADORE 5.0 rolling-bearing dynamics.

``pyadore.run(deck)`` runs an ADORE deck through the Fortran engine; ``pyadore.deck``
reads, validates and writes decks; ``pyadore.printout`` and ``pyadore.diff`` read and
compare print files; ``pyadore.sweep(deck, vary, out_dir)`` runs parametric studies.
Importing pyadore does not load the engine extension.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version as _dist_version

from .api import BALL_STARTS, Result, read_traction_table, run
from .errors import AdoreEngineError, AdoreError, AdoreInputError
from .sweeps import sweep

try:
    __version__ = _dist_version("pyadore")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

__all__ = ["run", "sweep", "read_traction_table", "Result", "BALL_STARTS", "AdoreError", "AdoreInputError",
           "AdoreEngineError", "__version__"]
