"""Parametric sweeps of a deck: ``pyadore.sweep(...)`` and ``pyadore sweep DECK --vary ...``.

``grid`` names the varied fields and builds the case decks, ``execute`` runs the cases on
a local process pool or a Dask cluster, ``store`` holds the folder layout and its atomic
writes, ``results`` takes the key results from a print file, ``runner`` ties them together.
"""

from __future__ import annotations

from .grid import SweepError
from .results import RESULT_COLUMNS
from .runner import read_summary, sweep

__all__ = ["sweep", "read_summary", "SweepError", "RESULT_COLUMNS"]

