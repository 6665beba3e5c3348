"""Figure type 1: the load distribution around the bearing (report figures 14 and 15).

Contact load of each rolling element at the outer and inner race against its orbital
(azimuth) position, from one printed step's "Rolling Element Parameters" table; the
report compares an aligned run with one misaligned by moment equilibrium, which is
``compare=``.
"""

from __future__ import annotations

import numpy as np

from ..errors import MissingSeriesError
from . import style
from .sources import load

FIGURE = "figure type 1 (load distribution around the bearing)"


def pick_step(source, step: int | None, default_first: bool = True) -> int:
    """The printed step to plot: ``step`` if given (MissingSeriesError naming the printed
    steps if absent), else the first printed step (the last when default_first is False)."""
    if source.run is None or not source.run.steps:
        raise MissingSeriesError(f"{FIGURE}: {source.label} has no printed steps")
    numbers = source.run.step_numbers
    if step is None:
        return numbers[0] if default_first else numbers[-1]
    if step not in source.run.steps:
        raise MissingSeriesError(f"{FIGURE}: {source.label} has no step {step}; its printed steps are "
                                 f"{', '.join(map(str, numbers))}")
    return step


def load_points(source, step: int, race: str) -> tuple[np.ndarray, np.ndarray]:
    """(orbital position in deg within [0, 360), contact load in N) of every rolling
    element with both values printed at ``step``, sorted by position; race outer/inner."""
    table = source.run.step(step).tables.get("re_contact")
    if table is None:
        return np.array([]), np.array([])
    pos = table["orbital_position_deg"].to_numpy(float)
    q = table[f"contact_load_{race}_N"].to_numpy(float)
    keep = np.isfinite(pos) & np.isfinite(q)
    pos, q = np.mod(pos[keep], 360.0), q[keep]
    order = np.argsort(pos, kind="stable")
    return pos[order], q[order]


@style.styled
def load_distribution(source, *, step: int | None = None, race: str = "both", compare=None,
                      compare_step: int | None = None, label: str | None = None,
                      compare_label: str | None = None, ax=None):
    """Figure type 1: rolling-element/race contact load (N) vs orbital position (deg) at
    the outer and inner race contacts (report figs 14, 15), at printed step ``step``
    (default: the first printed step, the quasi-static start).  ``race`` "both" (two
    panels), "outer" or "inner"; ``compare`` overlays a second run (print path, PrintRun
    or Result) at ``compare_step`` (default: the same step number if it printed it, else
    its first).  ``ax``: one axes (one race) or two (both).  Returns the figure; raises
    MissingSeriesError when no contact load was printed."""
    if race not in ("both", "outer", "inner"):
        raise ValueError(f"race must be 'both', 'outer' or 'inner', got {race!r}")
    races = ("outer", "inner") if race == "both" else (race,)
    runs = [load(source, label)]
    steps = [pick_step(runs[0], step)]
    if compare is not None:
        other = load(compare, compare_label)
        if compare_step is None and steps[0] in (other.run.steps if other.run else {}):
            compare_step = steps[0]
        runs.append(other)
        steps.append(pick_step(other, compare_step))
    data = {(i, r): load_points(run, steps[i], r) for i, run in enumerate(runs) for r in races}
    if not any(len(data[(0, r)][0]) for r in races):
        raise MissingSeriesError(f"{FIGURE}: {runs[0].label} printed no {' or '.join(races)} race contact "
                                 f"load at step {steps[0]}")
    fig, axes, own = style.figure_axes(ax, nrows=len(races), sharex=True)
    word = runs[0].element_word().capitalize()
    for k, (a, r) in enumerate(zip(axes, races)):
        for i, run in enumerate(runs):
            x, y = data[(i, r)]
            if len(x):
                a.plot(x, y, style.line_style(i), marker="o" if i == 0 else "s", color=style.COLORS[i],
                       label=f"{run.label}, step {steps[i]}")
        a.set_ylabel(style.label("Contact load", "N"))
        a.set_xlim(0.0, 360.0)
        a.set_xticks(np.arange(0.0, 361.0, 45.0))
        if len(races) > 1:
            a.set_title(f"{r.capitalize()} race contact")
        if k == 0:  # the panels show the same runs: one legend
            style.legend(a)
    axes[-1].set_xlabel(style.label(f"{word} orbital position", "deg"))
    where = "the outer and inner race contacts" if len(races) > 1 else f"the {races[0]} race contact"
    style.title(fig, axes, own, f"{word}/race load distribution at {where}")
    return fig
