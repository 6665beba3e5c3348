"""Figure types 6-9: cage motion against time (report figures 20-23, 28-31, 36-38, 42-44):
mass-centre velocities, cage/race (guide land) contact force, the whirl orbit with the
guide clearance circle, and a ball/cage pocket contact force.  Data: the time-history
table of :mod:`pyadore.plots.history`.
"""

from __future__ import annotations

import math
import re
import textwrap
import warnings

import numpy as np

from ..errors import MissingSeriesWarning
from . import style
from .history import finite
from .timeplot import (Panel, check_series, condition_title, history_figure, run_style, runs_and_histories, sparse,
                       steps_text)

_LAND = re.compile(r"^land(\d+)_force_N$")
#: Orbit axes are in mm (an SI unit; the mass centre moves by tenths of a millimetre).
MM = 1.0e3


def cage_reason(source) -> str:
    """Why a run's cage contact forces stay zero, from its print: the cage contacts were off."""
    return ("the cage contacts are off in this run (no pocket or guide-land forces)"
            if getattr(source, "condition", None) and source.condition("CAGE CONTACTS OFF") else "")


def centred_reason(source, what: str) -> str:
    """Why a run's cage does not whirl, from its print: its translation was constrained
    (report 4.4.6's DOF constraint; the run's listing says "CAGE CENTRED ...")."""
    if not (getattr(source, "condition", None) and source.condition("CAGE CENTRED")):
        return ""
    why = "the cage is centred in this run (translation and tilt constrained, report 4.4.6)"
    return f"{why}: {what}"


@style.styled
def cage_velocities(source, *, compare=None, label: str | None = None, compare_label: str | None = None,
                    ax=None):
    """Figure type 6: whirl (tangential) and radial velocity (m/s) of the cage mass centre
    vs time (s) (report figs 20, 28, 36, 42; columns cage_whirl_velocity_m_s,
    cage_radial_velocity_m_s; a print gives the whirl velocity only)."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    panels = [Panel("Cage mass center velocity", "m/s",
                    (("cage_whirl_velocity_m_s", "whirl"), ("cage_radial_velocity_m_s", "radial")),
                    constant_reason=centred_reason(pairs[0][0], "no whirl"))]
    return history_figure("figure type 6 (cage mass-centre velocities vs time)", "cage mass-centre velocity",
                          "Cage mass center velocities", panels, pairs, ax)


@style.styled
def cage_land_force(source, *, compare=None, label: str | None = None, compare_label: str | None = None,
                    ax=None):
    """Figure type 7: cage/race (guide land) contact force (N) of each land vs time (s)
    (report figs 21, 29, 37, 43; columns land<k>_force_N)."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    lands = sorted({int(m.group(1)) for _r, h in pairs for c in h.columns if (m := _LAND.match(c))})
    panels = [Panel("Cage/race contact force", "N", tuple((f"land{k}_force_N", f"guide land {k}") for k in lands),
                    constant_reason=cage_reason(pairs[0][0]) or
                    centred_reason(pairs[0][0], "it never reaches its guide lands"))]
    return history_figure("figure type 7 (cage/race contact force vs time)", "guide land contact force",
                          "Cage/race contacts", panels, pairs, ax)


@style.styled
def pocket_force(source, *, element: int = 1, compare=None, label: str | None = None,
                 compare_label: str | None = None, ax=None):
    """Figure type 9: pocket contact force (N) between rolling element ``element`` and the
    cage vs time (s) (report figs 23, 31; column pocket<element>_force_N, a roller's two
    ends summed)."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    word = pairs[0][0].element_word()
    panels = [Panel(f"{word.capitalize()}/cage contact force", "N",
                    ((f"pocket{element}_force_N", f"{word} {element} pocket"),), log=True,
                    constant_reason=cage_reason(pairs[0][0]))]
    return history_figure(f"figure type 9 ({word}/cage pocket contact force vs time)",
                          f"pocket contact force of {word} {element}",
                          f"Typical {word}/cage contacts ({word} {element})", panels, pairs, ax)


def guide_clearance(source, history) -> float:
    """Diametral guide-land clearance (m) for the clearance circle: the last one the
    history records (the print's effective diametral play), else the smallest land
    clearance of the echo's guide-land table; NaN when neither is known."""
    recorded = finite(history, "guide_clearance_m")
    if len(recorded):
        return float(recorded.iloc[-1])
    if source.run is None:
        return math.nan
    values = [v for k, v in source.run.echo.items()
              if re.fullmatch(r"bearing_geometry\.row\d+\[4\]", k) and isinstance(v, (int, float))]
    return float(min(values)) if values else math.nan


@style.styled
def cage_orbit(source, *, compare=None, label: str | None = None, compare_label: str | None = None, ax=None):
    """Figure type 8: path of the cage mass centre in the transverse plane (y, z in mm) with
    the guide clearance circle (dotted; radius = diametral clearance / 2), to scale with
    equal axes (report figs 22, 30, 38, 44; columns cage_y_m, cage_z_m, guide_clearance_m)."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    figure = "figure type 8 (cage whirl orbit)"
    have = check_series(figure, "cage mass-centre position", pairs, ["cage_y_m", "cage_z_m"],
                        {"cage_y_m": "cage y position", "cage_z_m": "cage z position"})
    fig, axes, own = style.figure_axes(ax, height=6.0, width=9.0)
    a = axes[0]
    extent = 0.0
    radii = []
    for i, ((run, hist), got) in enumerate(zip(pairs, have)):
        if not {"cage_y_m", "cage_z_m"} <= got:
            continue
        both = hist[["cage_y_m", "cage_z_m"]].astype(float).dropna()
        y, z = both["cage_y_m"].to_numpy() * MM, both["cage_z_m"].to_numpy() * MM
        marks = sparse(hist)
        radius = np.hypot(y, z)
        which = f" ({run.label})" if len(pairs) > 1 else ""
        a.plot(y, z, **run_style(i, marks, style.COLORS[0 if i == 0 else 4]),
               label=(f"mass center, {steps_text(hist.loc[both.index])}" if marks else
                      f"mass-center path, largest radius {radius.max():.4g} mm") + which)
        if not marks:
            a.plot(y[:1], z[:1], "^", color=style.COLORS[2], markersize=7, label="start" if i == 0 else None)
            a.plot(y[-1:], z[-1:], "v", color=style.COLORS[3], markersize=7, label="end" if i == 0 else None)
        extent = max(extent, float(np.max(radius)))
        c = guide_clearance(run, hist)
        if math.isfinite(c) and c > 0.0:
            r = 0.5 * c * MM
            if not any(abs(r - q) <= 1e-9 * r for q in radii):
                theta = np.linspace(0.0, 2.0 * math.pi, 361)
                a.plot(r * np.cos(theta), r * np.sin(theta), ":", color=style.COLORS[1 if i == 0 else 3],
                       linewidth=1.8, label=f"guide clearance circle, r = {r:.4g} mm" + which)
                radii.append(r)
                extent = max(extent, r)
        elif i == 0:
            warnings.warn(f"{figure}: {run.label} gives no guide-land clearance; plotted without the clearance "
                          "circle", MissingSeriesWarning, stacklevel=2)
    a.plot([0.0], [0.0], "+", color="0.3", markersize=9)
    note = centred_reason(pairs[0][0], "its mass centre stays on the bearing axis")
    if note:
        a.text(1.03, 0.02, "\n".join(textwrap.wrap(note, 36)), transform=a.transAxes, ha="left", va="bottom",
               fontsize=9, bbox={"boxstyle": "round", "facecolor": "#fff8dc", "edgecolor": "0.55"})
    lim = 1.12 * extent if extent > 0.0 else 1.0
    a.set_aspect("equal", adjustable="box")
    a.set_anchor("W")  # the square box at the left of its space: the legend beside it stays on the page
    a.set_xlim(-lim, lim)
    a.set_ylim(-lim, lim)
    a.set_xlabel(style.label("Cage mass center y", "mm"))
    a.set_ylabel(style.label("Cage mass center z", "mm"))
    style.legend(a)
    style.title(fig, axes, own, condition_title(pairs[0][0], "Cage mass center whirl orbit"))
    return fig
