"""Report-style figures (report AFRL-PR-WP-TR-2002-2042, figures 14-44) from a run.

One function per figure type; each takes a print-file path, a parsed print
(:class:`pyadore.printout.PrintRun`) or a :class:`pyadore.Result` (types 2-9 also a
time-history DataFrame, contract in :mod:`pyadore.plots.history` and docs/plots.md), an
optional ``compare=`` run overlaid dashed and an optional ``ax=``, and returns the
matplotlib Figure:

====  ==========================  ======================================================
type  function                    report figures
====  ==========================  ======================================================
1     :func:`load_distribution`   14, 15 - contact load vs orbital position
2     :func:`power_loss`          16, 24, 33, 39 - total power loss vs time
3     :func:`wear_rates`          17, 25 - time-averaged wear rates vs time
4     :func:`bulk_temperatures`   18, 26, 34, 40 - bulk and exit fluid temperatures
5     :func:`race_contacts`       19, 27, 35, 41 - one element's race contacts vs time
6     :func:`cage_velocities`     20, 28, 36, 42 - cage mass-centre velocities
7     :func:`cage_land_force`     21, 29, 37, 43 - cage/race (guide land) force
8     :func:`cage_orbit`          22, 30, 38, 44 - whirl orbit and clearance circle
9     :func:`pocket_force`        23, 31 - rolling element/cage pocket force
10    :func:`traction_slip`       32 - traction-slip relation
====  ==========================  ======================================================

:func:`make_set` makes a named set (``"report"``: every type the data supports),
:func:`write_pdf` / :func:`write_pngs` write it (``pyadore plot`` on the command line).
A figure whose data is missing raises :class:`pyadore.errors.MissingSeriesError` (one
line naming the figure type and the series); a missing secondary series is a
:class:`pyadore.errors.MissingSeriesWarning`.
"""

from __future__ import annotations

from .cage import cage_land_force, cage_orbit, cage_velocities, pocket_force
from .history import history_from_print, time_history
from .load import load_distribution
from .performance import bulk_temperatures, power_loss, race_contacts, wear_rates
from .sets import (FIGURE_TYPES, SETS, FigureSet, FigureType, figure_types, make_set, png_name, skipped_lines,
                   write_image, write_pdf, write_pngs)
from .sources import Source, load
from .traction import traction_slip

__all__ = [
    # figure types 1-10
    "load_distribution",
    "power_loss",
    "wear_rates",
    "bulk_temperatures",
    "race_contacts",
    "cage_velocities",
    "cage_land_force",
    "cage_orbit",
    "pocket_force",
    "traction_slip",
    # data
    "Source",
    "load",
    "time_history",
    "history_from_print",
    # sets and files
    "FIGURE_TYPES",
    "SETS",
    "FigureType",
    "FigureSet",
    "make_set",
    "figure_types",
    "skipped_lines",
    "write_image",
    "write_pdf",
    "write_pngs",
    "png_name",
]
