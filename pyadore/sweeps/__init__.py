"""Parametric sweeps of a deck: ``pyadore.sweep(...)`` and ``pyadore sweep DECK --vary ...``.

``grid`` names the varied fields and builds the case decks, ``execute`` runs the cases on
a local process pool or a Dask cluster, ``store`` holds the folder layout and its atomic
writes, ``results`` takes the key results from a print file, ``runner`` ties them together.
"""

from __future__ import annotations

__all__ = ["sweep", "read_summary", "SweepError", "RESULT_COLUMNS", "WorkerPool"]

_LAZY = {"sweep": ".runner", "read_summary": ".runner", "SweepError": ".grid", "RESULT_COLUMNS": ".results",
         "WorkerPool": ".execute"}


def __getattr__(name: str):
    """The package's names, imported on first use: a local worker process
    (``python -m pyadore.sweeps.worker``) imports this package but needs neither the deck
    reader nor the runner (a shorter serial start-up, docs/sweeps.md "Speed")."""
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

