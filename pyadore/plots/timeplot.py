"""Drawing time histories: the shared machinery of figure types 2-9.

:func:`history_figure` draws panels of time-history columns (module
:mod:`pyadore.plots.history`) of a run and, dashed, of a compared run; colours name the
series, line styles the runs.  A column the run lacks is left out with a
:class:`~pyadore.errors.MissingSeriesWarning` naming it; a figure none of whose columns
the run has raises :class:`~pyadore.errors.MissingSeriesError` (never an empty axis).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
from matplotlib.lines import Line2D

from ..errors import MissingSeriesError, MissingSeriesWarning
from . import style
from .history import finite, has_series, require, time_history
from .sources import load

#: Markers are drawn on a series with at most this many points (sparse printed steps).
MARKER_LIMIT = 40


@dataclass(frozen=True)
class Panel:
    """One panel: y quantity and unit, and its series as (column, legend name)."""

    quantity: str
    unit: str
    series: tuple

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
    for run, h in pairs[1:]:
        have.append({c for c in columns if has_series(h, c)})
    for (run, _h), got in zip(pairs, have):
        lacking = [names.get(c, c) for c in columns if c not in got]
        if lacking and got:
            warnings.warn(f"{figure}: {run.label} has no {', '.join(lacking)} at two or more printed times; "
                          "plotted without", MissingSeriesWarning, stacklevel=3)
        elif not got:
            warnings.warn(f"{figure}: {run.label} has no {what} at two or more printed times; plotted without "
                          "that run", MissingSeriesWarning, stacklevel=3)
    return have


def use_log_scale(values: list[np.ndarray]) -> bool:
    """True when every plotted value is positive and they span more than two decades."""
    vals = np.concatenate([v for v in values if len(v)]) if values else np.array([])
    return bool(len(vals)) and bool(np.all(vals > 0.0)) and vals.max() / vals.min() > 100.0


def run_legend(ax, pairs, drawn=None) -> None:
    """Legend: one entry per series (colour) and, with a compared run, one per run drawn
    (line style; ``drawn`` = indices into ``pairs``, default all)."""
    handles, labels = ax.get_legend_handles_labels()
    if len(pairs) > 1:
        for i, (run, _h) in enumerate(pairs):
            if drawn is not None and i not in drawn:
                continue
            handles.append(Line2D([], [], color="0.25", linestyle=style.line_style(i)))
            labels.append(run.label)
    style.legend(ax, handles, labels)


def history_figure(figure: str, what: str, title: str, panels: list[Panel], pairs, ax=None):
    """Draw ``panels`` of the histories in ``pairs`` ([(Source, DataFrame)]): run i with
    line style i, series j with colour j; x = time (s).  ``figure`` and ``what`` name the
    figure and its data in messages.  Returns the figure."""
    columns = [c for p in panels for c in p.columns]
    names = {c: (f"{p.quantity.lower()} at the {n}" if len(panels) > 1 else n) for p in panels for c, n in p.series}
    have = check_series(figure, what, pairs, columns, names)
    drawn = [p for p in panels if any(c in have[0] for c in p.columns)]
    if ax is not None and len(drawn) != len(panels):
        empty = [p.quantity for p in panels if p not in drawn]
        raise MissingSeriesError(f"{figure}: {pairs[0][0].label} has no {', '.join(empty).lower()}")
    fig, axes, own = style.figure_axes(ax, nrows=len(drawn), sharex=True)
    # panels showing the same series share the top panel's legend
    same = len({tuple(n for _c, n in p.series) for p in drawn}) == 1
    for k, (a, panel) in enumerate(zip(axes, drawn)):
        values, runs_drawn = [], set()
        for i, ((_run, hist), got) in enumerate(zip(pairs, have)):
            for j, (column, name) in enumerate(panel.series):
                if column not in got:
                    continue
                runs_drawn.add(i)
                s = finite(hist, column)
                values.append(s.to_numpy())
                a.plot(s.index.to_numpy(float), s.to_numpy(float), style.line_style(i),
                       color=style.COLORS[j % len(style.COLORS)],
                       marker="o" if len(s) <= MARKER_LIMIT else None,
                       label=name if i == 0 or column not in have[0] else None)
        if use_log_scale(values):
            a.set_yscale("log")
        a.set_ylabel(style.label(panel.quantity, panel.unit))
        if len(drawn) > 1:
            a.set_title(panel.quantity)
        if k == 0 or not same:
            run_legend(a, pairs, runs_drawn)
    axes[-1].set_xlabel(style.label("Time", "s"))
    style.title(fig, axes, own, title)
    return fig
