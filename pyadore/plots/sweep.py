"""The sweep plot: a result of a parametric sweep against a varied parameter.

``plot_sweep(summary_or_dir, x="inner_race_speed", y="total_power_loss_W",
by="applied_force_z")`` draws one line per value of ``by``; the other varied parameters
must be held at one value with ``where``.  Only cases that finished (status ``ok``) are
drawn; a value the engine does not compute (NaN) leaves a gap.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path

__all__ = ["plot_sweep", "sweep_plot_command", "RESULT_TITLES", "RESULTS", "si_scale", "field_title"]

#: Titles and SI units of the summary's result columns (the report's words).
RESULTS = {
    "total_power_loss_W": ("Total power loss", "W"),
    "basic_life_h": ("Basic fatigue life", "h"),
    "modified_life_h": ("Modified fatigue life", "h"),
    "max_contact_load_N": ("Largest contact load", "N"),
    "max_contact_stress_Pa": ("Largest contact stress", "Pa"),
    "cage_speed_ratio": ("Cage speed ratio", "-"),
    "cage_bulk_temp_K": ("Cage bulk temperature", "K"),
    "outer_race_bulk_temp_K": ("Outer race bulk temperature", "K"),
    "inner_race_bulk_temp_K": ("Inner race bulk temperature", "K"),
    "housing_bulk_temp_K": ("Housing bulk temperature", "K"),
    "shaft_bulk_temp_K": ("Shaft bulk temperature", "K"),
    # time averages over the last shaft revolution (docs/sweeps.md)
    "mean_total_power_loss_W": ("Total power loss, time-averaged", "W"),
    "mean_max_contact_load_N": ("Largest contact load, time-averaged", "N"),
    "mean_cage_speed_ratio": ("Cage speed ratio, time-averaged", "-"),
    "mean_revolutions": ("Revolutions averaged over", "-"),
    "mean_whirl_radius_m": ("Mean cage whirl radius", "m"),
    "whirl_speed_ratio": ("Cage whirl / cage speed", "-"),
    "whirl_speed_cv": ("Cage whirl speed std / mean", "-"),
    "radial_velocity_ratio": ("Cage radial velocity rms / whirl velocity", "-"),
    "max_whirl_radius_ratio": ("Largest whirl radius / land clearance", "-"),
    "land_contact_fraction": ("Guide-land near-contact time fraction", "-"),
    "cage_stability": ("Cage whirl stable (1) or erratic (0)", "-"),
}

#: Axis titles of the summary's result columns, ``Title (unit)``.
RESULT_TITLES = {k: f"{title} ({unit})" for k, (title, unit) in RESULTS.items()}

#: Units drawn with an SI prefix (kN, GPa, um) when their values are far from 1.
PREFIXED_UNITS = ("m", "Pa", "N", "W", "N*m", "J", "s")
_PREFIXES = {-9: "n", -6: "\u00b5", -3: "m", 0: "", 3: "k", 6: "M", 9: "G"}



def _in_sentence(title: str) -> str:
    """A field's title inside a sentence: its first letter lower case, unless the first word
    is an abbreviation ("RE/cage ...", "EHD ...": two capitals in a row stay as they are)."""
    head = title.split(" ", 1)[0]
    if len(head) > 1 and head[:2].isupper():
        return title
    return title[:1].lower() + title[1:]

def si_scale(unit: str, values) -> tuple[float, str]:
    """(divisor, unit) of an axis of ``values`` in ``unit``: an SI prefix (GPa, kN, um)
    when ``unit`` takes one and the largest magnitude is below 0.1 or from 10 000 on; else
    (1, unit).  Values are drawn divided by the divisor (never a 1e9 offset)."""
    import numpy as np

    vals = np.abs(np.asarray([v for v in values if isinstance(v, (int, float))], dtype=float))
    vals = vals[np.isfinite(vals) & (vals > 0)]
    if unit not in PREFIXED_UNITS or not len(vals):
        return 1.0, unit
    top = float(vals.max())
    if 0.1 <= top < 1.0e4:
        return 1.0, unit
    exp = int(math.floor(math.log10(top) / 3.0) * 3)
    exp = max(-9, min(9, exp))
    return 10.0 ** exp, _PREFIXES[exp] + unit


def field_title(name: str) -> str:
    """The human name of deck field ``name`` (``FIELD`` or ``REC/FIELD``) from the record
    table (docs/deck-format.md) without its remarks in brackets, e.g. ``Inner race speed``;
    ``name`` itself when the
    table has no meaning for it."""
    spec = _spec(name)
    text = getattr(spec, "meaning", "") or ""
    text = re.sub(r"\s*\([^()]*\)", "", text).strip().rstrip(".;,")   # the table's remarks in brackets
    text = re.split(r";", text)[0].strip()
    if not text:
        return name
    return text[0].upper() + text[1:]


def _load(summary_or_dir):
    import pandas as pd

    from ..sweeps import SweepError, read_summary
    from ..sweeps.runner import read_summary_file

    if isinstance(summary_or_dir, pd.DataFrame):
        return summary_or_dir, "sweep"
    path = Path(os.fspath(summary_or_dir))
    if path.is_file():
        return read_summary_file(path), path.parent.name
    if not path.is_dir():
        raise SweepError(f"{path}: no such sweep folder or summary file")
    return read_summary(path), path.name


def _spec(name: str):
    """The record table's spec of field ``name`` (``FIELD`` or ``REC/FIELD``: that record's
    field first), or None."""
    from ..deck import all_specs
    from ..deck.derived import DERIVED_FIELDS
    from ..deck.spec import FieldSpec

    rid, _sep, field = name.rpartition("/")
    if field in DERIVED_FIELDS:
        d = DERIVED_FIELDS[field]
        return FieldSpec(d.name, d.kind, d.unit, d.meaning.split(" (")[0])
    hits = [(spec.rid, f) for spec in all_specs() for f in spec.fields if f.name == field]
    hits.sort(key=lambda h: h[0] != rid)
    return hits[0][1] if hits else None


def _unit(name: str) -> str:
    spec = _spec(name)
    return spec.unit if spec is not None else ""


def _label(name: str, unit: str | None = None) -> str:
    unit = _unit(name) if unit is None else unit
    title = field_title(name)
    return f"{title} ({unit})" if unit and unit != "-" else title


def _value_text(v) -> str:
    return f"{v:g}" if isinstance(v, float) else str(v)


def plot_sweep(summary_or_dir, x: str, y: str, by: str | None = None, where: dict | None = None, ax=None,
               log_y: bool = False, map: bool = False):
    """Draw result ``y`` against varied parameter ``x``, one line per value of ``by``.

    map: a map over ``x`` (horizontal) and ``by`` (vertical) instead: each case a marker
    coloured by ``y`` and labelled with its value; with the summary's ``cage_stability``
    column a filled circle marks a stable cage whirl, a cross an erratic one (issue #25's
    cage stability map, e.g. ``x="10.5.1B/re_cage_coeff_a"``, ``by="inner_race_speed"``).

    summary_or_dir: a sweep folder, its ``summary.csv`` or the DataFrame of
    :func:`pyadore.sweep`.  where: ``{parameter: value}`` holding every other varied
    parameter at one value.  ax: a matplotlib Axes to draw on [default: a new figure].
    log_y: a logarithmic result axis (lives span decades).
    Returns the matplotlib Figure.  Raises :class:`~pyadore.sweeps.SweepError` naming the
    valid columns for an unknown ``x``/``y``/``by``, or when a parameter is left free.
    """
    from ..sweeps import SweepError

    frame, name = _load(summary_or_dir)
    cols = list(frame.columns)
    if "case" not in cols or "status" not in cols:
        raise SweepError("not a sweep summary: it needs the columns case and status")
    params = cols[cols.index("case") + 1:cols.index("status")]
    results = cols[cols.index("status") + 1:]
    where = dict(where or {})
    for what, col, allowed in (("x", x, params), ("by", by, params), ("y", y, results)):
        if col is not None and col not in allowed:
            raise SweepError(f"{what} = {col!r}: not a {'result' if what == 'y' else 'varied parameter'} of this "
                             f"sweep; choose one of {', '.join(allowed)}")
    if by is not None and by == x:
        raise SweepError(f"x and by are both {x!r}: choose two different varied parameters")
    for col, value in where.items():
        if col not in params or col in (x, by):
            raise SweepError(f"where {col}: not a varied parameter other than x and by; choose among "
                             f"{', '.join(p for p in params if p not in (x, by))}")
        values = frame[col].unique()
        match = [v for v in values if _value_text(v) == _value_text(value) or str(v) == str(value)
                 or (isinstance(v, float) and _is_close(v, value))]
        if not match:
            raise SweepError(f"where {col}={value}: the sweep has {col} = {', '.join(_value_text(v) for v in values)}")
        frame = frame[frame[col] == match[0]]
    free = [p for p in params if p not in (x, by) and p not in where and frame[p].nunique() > 1]
    if free:
        options = "; ".join(f"{p} = {', '.join(_value_text(v) for v in sorted(frame[p].unique()))}" for p in free)
        raise SweepError(f"the sweep also varies {options}: hold each at one value (where / --where FIELD=VALUE)"
                         + ("" if by is not None else " or draw it as the lines (by / --by)"))
    ok = frame[frame["status"] == "ok"]
    if ok.empty or ok[y].isna().all():
        raise SweepError(f"nothing to draw: no finished case has a value of {y} (the engine prints NaN for "
                         f"a value it does not compute)")
    if ax is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(7.0, 4.6), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    if map:
        if by is None:
            raise SweepError("a map needs two varied parameters: x and by")
        return _draw_map(fig, ax, ok, x, y, by, name)
    groups = [(None, ok)] if by is None else list(ok.groupby(by, sort=True))
    x_div, x_unit = si_scale(_unit(x), ok[x])
    y_title, y_unit = RESULTS.get(y, (y, ""))
    y_div, y_unit = si_scale(y_unit, ok[y])
    if by is not None:
        by_div, by_unit = si_scale(_unit(by), ok[by])
    for value, part in groups:
        part = part.sort_values(x)
        label = None
        if by is not None:
            label = f"{field_title(by)} = {_value_text(value / by_div if by_div != 1 else value)} {by_unit}".rstrip()
        ax.plot(part[x] / x_div, part[y] / y_div, marker="o", label=label)
    ax.set_xlabel(_label(x, x_unit))
    ax.set_ylabel(f"{y_title} ({y_unit})" if y_unit and y_unit != "-" else y_title)
    held = ", ".join(f"{field_title(k)} = {v} {_unit(k)}".rstrip() for k, v in where.items())
    ax.set_title(f"{y_title} against {_in_sentence(field_title(x))}"
                 + (f"\n({held})" if held else ""), fontsize="medium")
    if log_y:
        ax.set_yscale("log")
    else:
        ax.ticklabel_format(axis="y", useOffset=False, style="plain")
    ax.ticklabel_format(axis="x", useOffset=False, style="plain")
    ax.grid(True, which="both" if log_y else "major", alpha=0.3)
    if by is not None:
        ax.legend(title=None, fontsize="small")
    if len(fig.axes) == 1:
        fig.suptitle(f"sweep {name}", fontsize="small", x=0.01, ha="left")
    return fig


def _draw_map(fig, ax, ok, x: str, y: str, by: str, name: str):
    """The map of plot_sweep(map=True): cases at (x, by), coloured by y."""
    import numpy as np

    x_div, x_unit = si_scale(_unit(x), ok[x])
    by_div, by_unit = si_scale(_unit(by), ok[by])
    y_title, y_unit = RESULTS.get(y, (y, ""))
    y_div, y_unit = si_scale(y_unit, ok[y])
    xs, bys = ok[x].to_numpy(float) / x_div, ok[by].to_numpy(float) / by_div
    vals = ok[y].to_numpy(float) / y_div
    finite = np.isfinite(vals)
    lo, hi = (float(np.nanmin(vals)), float(np.nanmax(vals))) if finite.any() else (0.0, 1.0)
    stable = ok["cage_stability"].to_numpy(float) if "cage_stability" in ok.columns else np.full(len(ok), np.nan)
    kinds = ((stable == 1.0, "o", "stable whirl"), (stable == 0.0, "X", "erratic whirl"),
             (~np.isin(stable, (0.0, 1.0)), "s", "no whirl measure"))
    sc = None
    for mask, marker, label in kinds:
        if mask.any():
            sc = ax.scatter(xs[mask], bys[mask], c=vals[mask], cmap="viridis", vmin=lo, vmax=hi, s=260,
                            marker=marker, edgecolors="k", label=label)
    for xv, bv, v in zip(xs, bys, vals):
        ax.annotate(f"{v:.3g}", (xv, bv), textcoords="offset points", xytext=(0, 12), ha="center", fontsize="x-small")
    if sc is not None:
        fig.colorbar(sc, ax=ax, label=f"{y_title} ({y_unit})" if y_unit and y_unit != "-" else y_title)
    ax.set_xlabel(_label(x, x_unit))
    ax.set_ylabel(_label(by, by_unit))
    ax.set_title(f"{y_title} over {_in_sentence(field_title(x))} and {_in_sentence(field_title(by))}",
                 fontsize="medium")
    ax.margins(0.15)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="best")
    if len(fig.axes) <= 2:
        fig.suptitle(f"sweep {name}", fontsize="small", x=0.01, ha="left")
    return fig


def _is_close(a: float, b) -> bool:
    try:
        return math.isclose(float(a), float(b), rel_tol=1e-9, abs_tol=0.0)
    except (TypeError, ValueError):
        return False


def sweep_plot_command(out_dir, x: str, y: str, by: str | None = None, where: dict | None = None, out=None,
                       log_y: bool = False, map: bool = False):
    """``pyadore plot-sweep DIR``: draw result ``y`` of the sweep in ``out_dir`` against the
    varied parameter ``x``, one line per value of ``by`` (the others held by ``where``);
    save it to ``out`` [default: ``DIR/<y>_vs_<x>[_by_<by>].png``] and return the path."""
    from matplotlib.figure import Figure

    from ..sweeps import SweepError

    if out is not None:
        kinds = Figure().canvas.get_supported_filetypes()
        suffix = Path(out).suffix.lower().lstrip(".")
        if suffix not in kinds:
            raise SweepError(f"{out}: unknown image type {suffix!r}; use one of " + ", ".join(sorted(kinds)))
    fig = plot_sweep(out_dir, x=x, y=y, by=by, where=where, log_y=log_y, map=map)
    if out is None:
        stem = f"{y}_vs_{x}" + (f"_by_{by}" if by else "") + ("_map" if map else "")
        out = Path(out_dir) / (stem.replace("/", "_") + ".png")  # a REC/FIELD name in a file name
    out = Path(out)
    fig.savefig(out, dpi=120)
    return out
