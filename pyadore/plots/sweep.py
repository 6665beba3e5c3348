"""The sweep plot: a result of a parametric sweep against a varied parameter.

``plot_sweep(summary_or_dir, x="inner_race_speed", y="total_power_loss_W",
by="applied_force_z")`` draws one line per value of ``by``; the other varied parameters
must be held at one value with ``where``.  Only cases that finished (status ``ok``) are
drawn; a value the engine does not compute (NaN) leaves a gap.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

__all__ = ["plot_sweep", "sweep_plot_command", "RESULT_TITLES"]

#: Axis titles of the summary's result columns (the report's words, SI units).
RESULT_TITLES = {
    "total_power_loss_W": "Total power loss (W)",
    "basic_life_h": "Basic fatigue life (h)",
    "modified_life_h": "Modified fatigue life (h)",
    "max_contact_load_N": "Largest contact load (N)",
    "max_contact_stress_Pa": "Largest contact stress (Pa)",
    "cage_speed_ratio": "Cage speed ratio (-)",
    "cage_bulk_temp_K": "Cage bulk temperature (K)",
    "outer_race_bulk_temp_K": "Outer race bulk temperature (K)",
    "inner_race_bulk_temp_K": "Inner race bulk temperature (K)",
    "housing_bulk_temp_K": "Housing bulk temperature (K)",
    "shaft_bulk_temp_K": "Shaft bulk temperature (K)",
}


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


def _unit(name: str) -> str:
    from ..deck import all_specs

    field = name.split("/", 1)[-1]
    for spec in all_specs():
        for f in spec.fields:
            if f.name == field:
                return f.unit
    return ""


def _label(name: str) -> str:
    unit = _unit(name)
    return f"{name} ({unit})" if unit and unit != "-" else name


def _value_text(v) -> str:
    return f"{v:g}" if isinstance(v, float) else str(v)


def plot_sweep(summary_or_dir, x: str, y: str, by: str | None = None, where: dict | None = None, ax=None,
               log_y: bool = False):
    """Draw result ``y`` against varied parameter ``x``, one line per value of ``by``.

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
    groups = [(None, ok)] if by is None else list(ok.groupby(by, sort=True))
    for value, part in groups:
        part = part.sort_values(x)
        label = None if by is None else f"{by} = {_value_text(value)} {_unit(by)}".rstrip()
        ax.plot(part[x], part[y], marker="o", label=label)
    ax.set_xlabel(_label(x))
    ax.set_ylabel(RESULT_TITLES.get(y, y))
    held = ", ".join(f"{k} = {v} {_unit(k)}".rstrip() for k, v in where.items())
    ax.set_title(f"{RESULT_TITLES.get(y, y).split(' (')[0]} against {x}" + (f" ({held})" if held else ""))
    if log_y:
        ax.set_yscale("log")
    ax.grid(True, which="both" if log_y else "major", alpha=0.3)
    if by is not None:
        ax.legend(title=None, fontsize="small")
    if len(fig.axes) == 1:
        fig.suptitle(f"sweep {name}", fontsize="small", x=0.01, ha="left")
    return fig


def _is_close(a: float, b) -> bool:
    try:
        return math.isclose(float(a), float(b), rel_tol=1e-9, abs_tol=0.0)
    except (TypeError, ValueError):
        return False


def sweep_plot_command(out_dir, x: str, y: str, by: str | None = None, where: dict | None = None, out=None,
                       log_y: bool = False):
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
    fig = plot_sweep(out_dir, x=x, y=y, by=by, where=where, log_y=log_y)
    if out is None:
        stem = f"{y}_vs_{x}" + (f"_by_{by}" if by else "")
        out = Path(out_dir) / (stem.replace("/", "_") + ".png")  # a REC/FIELD name in a file name
    out = Path(out)
    fig.savefig(out, dpi=120)
    return out
