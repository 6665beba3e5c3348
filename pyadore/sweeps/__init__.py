"""Parametric sweeps of a deck: ``pyadore.sweep(...)`` and ``pyadore sweep DECK --vary ...``.

``grid`` names the varied fields and builds the case decks, ``execute`` runs the cases on
a local process pool or a Dask cluster, ``store`` holds the folder layout and its atomic
writes, ``results`` takes the key results from a print file, ``runner`` ties them together.
"""

from __future__ import annotations

from .grid import SweepError
from .results import RESULT_COLUMNS
from .runner import read_summary, sweep

__all__ = ["sweep", "read_summary", "SweepError", "RESULT_COLUMNS", "sweep_plot_command"]


def sweep_plot_command(out_dir, x: str, y: str, by: str | None = None, where: dict | None = None, out=None,
                       log_y: bool = False):
    """``pyadore plot-sweep DIR``: draw result ``y`` of the sweep in ``out_dir`` against the
    varied parameter ``x``, one line per value of ``by`` (the others held by ``where``);
    save it to ``out`` [default: ``DIR/<y>_vs_<x>[_by_<by>].png``] and return the path."""
    from pathlib import Path

    from ..plots.sweep import plot_sweep

    fig = plot_sweep(out_dir, x=x, y=y, by=by, where=where, log_y=log_y)
    if out is None:
        stem = f"{y}_vs_{x}" + (f"_by_{by}" if by else "")
        out = Path(out_dir) / (stem.replace("/", "_") + ".png")  # a REC/FIELD name in a file name
    out = Path(out)
    fig.savefig(out, dpi=120)
    return out
