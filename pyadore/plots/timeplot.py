"""Drawing time histories: the shared machinery of figure types 2-9.

:func:`history_figure` draws panels of time-history columns (module
:mod:`pyadore.plots.history`) of a run and of a compared run; colours name the series,
line styles (or marker shapes) the runs.  A column the run lacks is left out with a
:class:`~pyadore.errors.MissingSeriesWarning` naming it; a figure none of whose columns
the run has raises :class:`~pyadore.errors.MissingSeriesError` (never an empty axis).

What is drawn is the data, shown honestly:

* time in ms (s from 1 s on, :func:`pyadore.plots.style.time_unit`);
* a run known only at a few printed steps (at most MARKER_LIMIT instants: a print file
  without its plot-data file, a golden file) is drawn as markers, never joined by lines
  (a straight line between steps 0 and 2500 would claim values nobody computed); a
  compared run's series is drawn from one known point on;
* a series of more than DISPLAY_POINTS points is thinned for display only
  (:func:`display_indices`: the first, smallest, largest and last point of each bin, so
  every peak stays visible); the data are not changed;
* series of a run that are equal at every instant are one line naming them all
  ("(equal)"), and a panel whose series are constant says so in a note on the axes, with
  the reason the figure gives (the thermal model off);
* a logarithmic axis only on the panels that ask for it (wear rates, pocket forces) and
  only when the values are positive and span more than two decades.
"""

from __future__ import annotations

import textwrap
import warnings
from dataclasses import dataclass

import numpy as np
from matplotlib.lines import Line2D

from ..errors import MissingSeriesError, MissingSeriesWarning
from . import style
from .history import finite, has_series, require, time_history
from .sources import load

#: A run with at most this many recorded instants (printed steps) is drawn as markers only.
MARKER_LIMIT = 40
#: A series of more than this many points is thinned for display (:func:`display_indices`).
DISPLAY_POINTS = 4000
#: Marker of the run (filled) and of the compared run (hollow) when drawn as markers.
MARKERS = ("o", "s")


@dataclass(frozen=True)
class Panel:
    """One panel: y quantity and unit, its series as (column, legend name); ``log`` allows
    a logarithmic axis (:func:`use_log_scale`); ``constant_reason`` says why the series
    may be constant (shown in the note of a panel whose series are all constant)."""

    quantity: str
    unit: str
    series: tuple
    log: bool = False
    constant_reason: str = ""
    #: the quantity in messages ("wear rate"); default the quantity in lower case
    noun: str = ""

    @property
    def columns(self) -> list[str]:
        return [c for c, _ in self.series]


def runs_and_histories(source, compare, label, compare_label):
    """[(Source, time-history DataFrame)] of the run and the compared run (if any)."""
    runs = [load(source, label)]
    if compare is not None:
        runs.append(load(compare, compare_label))
    return [(run, time_history(run)) for run in runs]


def check_series(figure: str, what: str, pairs, columns: list[str], names: dict) -> list[set]:
    """For each run, the set of ``columns`` it has; MissingSeriesError when the first run
    has none, a MissingSeriesWarning naming each column a run lacks."""
    first, hist = pairs[0]
    have = [set(require(first, hist, columns, figure, what))]
    for run, h in pairs[1:]:   # a compared run is drawn from one known point on (as markers)
        have.append({c for c in columns if has_series(h, c, points=1)})
    for i, ((run, _h), got) in enumerate(zip(pairs, have)):
        where = "at two or more printed times" if i == 0 else "at any printed time"
        lacking = [names.get(c, c) for c in columns if c not in got]
        if lacking and got:
            warnings.warn(f"{figure}: {run.label} has no {', '.join(lacking)} {where}; plotted without",
                          MissingSeriesWarning, stacklevel=3)
        elif not got:
            warnings.warn(f"{figure}: {run.label} has no {what} {where}; plotted without that run",
                          MissingSeriesWarning, stacklevel=3)
    return have


def sparse(history) -> bool:
    """True when a run is known at only a few instants (printed steps): drawn as markers."""
    return history.index.nunique() <= MARKER_LIMIT


def display_indices(y: np.ndarray, max_points: int = DISPLAY_POINTS) -> np.ndarray:
    """Indices of the points of a series ``y`` drawn on a figure: all of them up to
    ``max_points``, else, for max_points // 4 bins of consecutive points, each bin's
    first, smallest, largest and last point in time order (the envelope: no peak is
    lost).  Display only: the data are not changed."""
    n = len(y)
    if n <= max_points:
        return np.arange(n)
    keep = []
    for part in np.array_split(np.arange(n), max(1, max_points // 4)):
        seg = y[part]
        keep.extend((part[0], part[int(np.argmin(seg))], part[int(np.argmax(seg))], part[-1]))
    return np.unique(np.asarray(keep))


def run_style(i: int, marks: bool, color) -> dict:
    """Matplotlib line keywords of run ``i`` (0 the plotted run, 1 the compared one): a line
    (solid, dashed), or markers only (filled circles, hollow squares) when ``marks``."""
    if not marks:
        return {"linestyle": style.line_style(i), "color": color}
    kw = {"linestyle": "none", "marker": MARKERS[i % 2], "color": color, "markersize": 6.0 if i else 5.0}
    if i:
        kw.update(markerfacecolor="none", markeredgewidth=1.4)
    return kw


def constant_note(ax, panel: Panel, lines: list) -> None:
    """When every series drawn of the run in ``lines`` ([(names, y)]) is constant, say so
    beside the axes (below the legend, never over the data): which series, their values
    and the panel's reason (a flat line is not a result).  Series constant but for their
    first row are said constant after step 0: the plot data's step-0 row is the print's
    quasi-static start (docs/plots.md), which the dynamics may leave at once (a cage
    centred by its DOF constraint starts where the quasi-static cage is not)."""
    if not lines:
        return
    after_start = any(np.ptp(y) > 0.0 for _n, y in lines if len(y))
    if after_start and not all(len(y) > 2 and np.ptp(y[1:]) == 0.0 for _n, y in lines if len(y)):
        return
    names = [n for group, _y in lines for n in group]
    values = sorted({float(y[-1]) for _n, y in lines if len(y)})
    unit = style.label("", panel.unit).strip().strip("()")
    when = "after step 0 (the quasi-static start)" if after_start else "throughout the run"
    text = (f"{', '.join(names)}: constant, {' and '.join(f'{v:.6g}' for v in values)} {unit}, {when}"
            + (f"; {panel.constant_reason}" if panel.constant_reason else ""))
    ax.text(1.01, 0.0, textwrap.fill(text, style.LEGEND_WIDTH), transform=ax.transAxes, ha="left", va="bottom",
            fontsize=8.5, bbox={"boxstyle": "round", "facecolor": "#fff8dc", "edgecolor": "0.6"})


def use_log_scale(values: list[np.ndarray]) -> bool:
    """True when every plotted value is positive and they span more than two decades."""
    vals = np.concatenate([v for v in values if len(v)]) if values else np.array([])
    return bool(len(vals)) and bool(np.all(vals > 0.0)) and vals.max() / vals.min() > 100.0


def run_legend(ax, pairs, drawn=None) -> None:
    """Legend: one entry per series (colour) and, with a compared run or a run drawn as
    markers, one per run drawn (line style or marker; ``drawn`` = indices into ``pairs``,
    default all)."""
    handles, labels = ax.get_legend_handles_labels()
    if len(pairs) > 1 or sparse(pairs[0][1]):
        for i, (run, h) in enumerate(pairs):
            if drawn is not None and i not in drawn:
                continue
            marks = sparse(h)
            handles.append(Line2D([], [], **run_style(i, marks, "0.25")))
            labels.append(run.label + (f" ({steps_text(h)})" if marks else ""))
    style.legend(ax, handles, labels)


def steps_text(history) -> str:
    """``printed steps 0, 2500`` (up to six steps named) or ``printed steps``."""
    if "step" in history.columns and 0 < len(history) <= 6:
        return "printed steps " + ", ".join(str(int(n)) for n in history["step"])
    return "printed steps"


def condition_title(source, text: str) -> str:
    """The report's title words for a run whose print says the thermal model was off
    (figures 16-23: "... with no thermal interactions")."""
    return f"{text} with no thermal interactions" if getattr(source, "thermal_off", False) else text


def series_name(panel: Panel, name: str, several: bool) -> str:
    """A series' name in messages: ``contact loss at the outer race``, ``cage temperature``."""
    quantity = panel.noun or panel.quantity.lower()
    if several:
        return f"{quantity} at the {name}"
    return name if quantity.split()[-1] in name else f"{name} {quantity}"


def history_figure(figure: str, what: str, title: str, panels: list[Panel], pairs, ax=None):
    """Draw ``panels`` of the histories in ``pairs`` ([(Source, DataFrame)]): run i with
    line style (or marker) i, series j with colour j; x = time (ms, or s from 1 s on).
    ``figure`` and ``what`` name the figure and its data in messages.  Returns the figure."""
    columns = [c for p in panels for c in p.columns]
    names = {c: series_name(p, n, len(panels) > 1) for p in panels for c, n in p.series}
    have = check_series(figure, what, pairs, columns, names)
    drawn = [p for p in panels if any(c in have[0] for c in p.columns)]
    if ax is not None and len(drawn) != len(panels):
        empty = [p.quantity for p in panels if p not in drawn]
        raise MissingSeriesError(f"{figure}: {pairs[0][0].label} has no {', '.join(empty).lower()}")
    fig, axes, own = style.figure_axes(ax, nrows=len(drawn), sharex=True)
    t_max = max((float(np.nanmax(h.index.to_numpy(float))) for (_r, h), got in zip(pairs, have) if got and len(h)),
                default=0.0)
    factor, t_unit = style.time_unit(t_max)
    # panels showing the same series share the top panel's legend
    same = len({tuple(n for _c, n in p.series) for p in drawn}) == 1
    for k, (a, panel) in enumerate(zip(axes, drawn)):
        values, runs_drawn, first_run, named = [], set(), [], set()   # named: series with a legend entry
        for i, ((_run, hist), got) in enumerate(zip(pairs, have)):
            marks = sparse(hist)
            lines = []   # [names, x, y, Line2D] of this run in this panel
            for j, (column, name) in enumerate(panel.series):
                if column not in got:
                    continue
                runs_drawn.add(i)
                s = finite(hist, column)
                x, y = s.index.to_numpy(float) * factor, s.to_numpy(float)
                twin = next((ln for ln in lines if np.array_equal(ln[1], x)
                             and np.array_equal(ln[2], y)), None)
                if twin is not None:   # equal at every instant: one line naming both
                    twin[0].append(name)
                    continue
                values.append(y)
                keep = display_indices(y)
                line, = a.plot(x[keep], y[keep], **run_style(i, marks, style.COLORS[j % len(style.COLORS)]))
                lines.append([[name], x, y, line, j])
            for names_, _x, y, line, j in lines:
                if j not in named:   # a series the plotted run drew (or named) already is not named again
                    named.add(j)
                    text = names_[0] if len(names_) == 1 else ", ".join(names_) + " (equal)"
                    if len(names_) == 1 and len(y) > 1 and np.ptp(y) == 0.0 and len(lines) > 1:
                        text += " (constant)"
                    line.set_label(text)
            if i == 0:
                first_run = [(n, y) for n, _x, y, _l, _b in lines]
        constant_note(a, panel, first_run)
        if panel.log and use_log_scale(values):
            a.set_yscale("log")
        a.set_ylabel(style.label(panel.quantity, panel.unit))
        if len(drawn) > 1:
            a.set_title(panel.quantity)
        if k == 0 or not same:
            run_legend(a, pairs, runs_drawn)
    axes[-1].set_xlabel(style.label("Time", t_unit))
    style.title(fig, axes, own, condition_title(pairs[0][0], title))
    return fig
