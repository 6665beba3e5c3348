"""One style for every pyadore figure: sizes, fonts, colours, line kinds and axis labels.

Every figure function of :mod:`pyadore.plots` builds its figure inside :func:`styled`
(matplotlib ``rc_context``), creates it with :func:`figure_axes` (a pyplot-free
:class:`matplotlib.figure.Figure` with constrained layout, so labels are never cut off)
and labels its axes with :func:`label` (quantity and SI unit).  A compared run is drawn
with the same colours and a dashed line, so a legend entry says which run is which.
"""

from __future__ import annotations

import functools
import re
import textwrap

import matplotlib
from matplotlib.figure import Figure

#: Figure size (inches) of a one-panel figure; panels stack below at PANEL_HEIGHT each.
FIGSIZE = (8.0, 4.8)
PANEL_HEIGHT = 2.9
#: Resolution (dots per inch) of PNG files.
PNG_DPI = 120

#: Colour cycle (matplotlib's colour-blind-safe "tab10" order, first six).
COLORS = ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#17becf", "#7f7f7f")
#: Legend entries longer than this many characters are wrapped (long file paths).
LEGEND_WIDTH = 40
#: Line style of the first (the plotted) run and of the compared run.
RUN_LINE = "-"
COMPARE_LINE = "--"

RC = {
    "font.size": 10.0,
    "axes.titlesize": 11.0,
    "axes.labelsize": 10.0,
    "figure.titlesize": 12.0,
    "legend.fontsize": 8.5,
    "legend.framealpha": 0.85,
    "axes.grid": True,
    "grid.alpha": 0.35,
    "grid.linewidth": 0.6,
    "lines.linewidth": 1.5,
    "lines.markersize": 4.5,
    "axes.formatter.useoffset": False,
    "axes.formatter.limits": (-3, 4),
    "axes.formatter.use_mathtext": True,   # a scale factor reads "x10^-11", not "1e-11"
    "axes.prop_cycle": matplotlib.cycler(color=list(COLORS)),
}


def styled(func):
    """Decorator: run a figure function inside the pyadore style (rc_context)."""

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        with matplotlib.rc_context(RC):
            return func(*args, **kwargs)

    return wrapper


def figure_axes(ax=None, nrows: int = 1, sharex: bool = True, height: float | None = None,
                width: float | None = None):
    """(figure, list of axes, own): the given ``ax`` (one axes, or a sequence of ``nrows``
    axes) and its figure with own = False, or a new figure with ``nrows`` stacked panels
    and own = True."""
    if ax is not None:
        axes = list(ax) if isinstance(ax, (list, tuple)) else [ax]
        if len(axes) != nrows:
            raise ValueError(f"this figure needs {nrows} axes, got {len(axes)}")
        return axes[0].figure, axes, False
    if height is None:
        height = FIGSIZE[1] if nrows == 1 else 1.0 + PANEL_HEIGHT * nrows
    fig = Figure(figsize=(width or FIGSIZE[0], height), layout="constrained")
    axes = fig.subplots(nrows, 1, sharex=sharex, squeeze=False)[:, 0]
    return fig, list(axes), True


def label(quantity: str, unit: str = "") -> str:
    """Axis label ``Quantity (unit)``; ``unit`` in SI as the print writes it (``m**3/s``),
    drawn with a superscript power (mathtext ``m$^{3}$/s``)."""
    if unit and "**" in unit:
        unit = re.sub(r"\*\*(-?\d+)", r"$^{\1}$", unit)
    return f"{quantity} ({unit})" if unit else quantity


def time_unit(t_max: float) -> tuple[float, str]:
    """(factor, unit) of a time axis reaching ``t_max`` seconds: milliseconds below 1 s
    (a run of a few thousand steps lasts tens of ms), else seconds."""
    return (1.0e3, "ms") if t_max < 1.0 else (1.0, "s")


def line_style(run_index: int) -> str:
    """Line style of run 0 (the plotted run) and run 1 (the compared one)."""
    return RUN_LINE if run_index == 0 else COMPARE_LINE


def legend(ax, handles=None, labels=None) -> None:
    """The legend, outside the axes on the right (it never hides data), only when there
    are labelled lines; ``handles``/``labels`` default to the axes' own."""
    if handles is None:
        handles, labels = ax.get_legend_handles_labels()
    labels = [textwrap.fill(text, LEGEND_WIDTH, break_on_hyphens=False, break_long_words=False) for text in labels]
    if handles:
        ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)


def title(fig, axes, own: bool, text: str) -> None:
    """The figure title: on a figure of several panels that pyadore made, else on the
    first axes (a caller's figure keeps its own title)."""
    if own and len(axes) > 1:
        fig.suptitle(text)
    else:
        axes[0].set_title(text)
