"""The time-history table that figure types 2-9 plot: its contract, and building it from
the printed steps of a print file.

**Contract** (docs/plots.md): a :class:`pandas.DataFrame` indexed by time ``time_s`` (s,
ascending), one row per recorded instant, float columns in SI units named
``<what>_<unit>``; a column may be absent or NaN where a value is not known.  Bearing:

* ``total_power_loss_W`` - total power loss (heat generation) of the bearing (W);
* ``exit_fluid_temp_K`` - exit fluid temperature (K);
* ``bulk_temp_<body>_K`` - bulk temperature (K) of ``re`` (mean over all rolling
  elements; NaN when one is unknown), ``cage``, ``outer_race``, ``inner_race``, ``housing``, ``shaft``;
* ``wear_rate_<body>_m3_s`` - time-averaged wear rate (m**3/s) of ``re`` (mean over all
  rolling elements; NaN when one is unknown), ``cage``, ``outer_race``, ``inner_race``;
* ``cage_y_m``, ``cage_z_m`` - cage mass-centre position in the transverse plane (m,
  inertial frame: y horizontal, z vertical);
* ``cage_whirl_velocity_m_s``, ``cage_radial_velocity_m_s`` - tangential (whirl) and
  radial components of the cage mass-centre velocity in the transverse plane (m/s);
* ``guide_clearance_m`` - diametral clearance of the cage guide land (m).

Per rolling element ``n`` (1-based) and race ``outer``/``inner``:
``re<n>_contact_load_<race>_N`` (N), ``re<n>_contact_loss_<race>_W`` (W),
``re<n>_contact_temp_rise_<race>_K`` (K),
``re<n>_contact_temp_<race>_K`` (K); ``pocket<n>_force_N`` - ball (roller: both ends
summed)/cage pocket contact force (N).  Per guide land ``k``: ``land<k>_force_N`` -
cage/race contact force (N).

:func:`history_from_print` fills the table from every printed step; a run with time steps
records the table at every step itself (:attr:`pyadore.Result.time_history`, and the
plot-data file beside its print: :mod:`pyadore.timehistory`).  Printed values map one to one, except:
the cage position (y, z) = r (-sin theta, cos theta) from the printed radial position r
and orbital angle theta (measured from +z towards -y); the whirl velocity = r times the
printed cage orbital velocity; the radial velocity is not printed; a printed temperature
of 0 K or less (a temperature not computed yet: the report's exit fluid temperature at
step 0) is NaN.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ..errors import MissingSeriesError

#: Bodies of the bulk temperature and wear rate columns, with their legend names.
BULK_BODIES = {"re": "rolling elements (mean)", "cage": "cage", "outer_race": "outer race",
               "inner_race": "inner race", "housing": "housing", "shaft": "shaft"}
WEAR_BODIES = {"re": "rolling elements (mean)", "cage": "cage", "outer_race": "outer race",
               "inner_race": "inner race"}
_BODY_ROWS = {"cage": "Cage", "outer_race": "ORace", "inner_race": "IRace"}
RACES = ("outer", "inner")


def _cell(step, table: str, row, column: str) -> float:
    """A printed value (NaN when the table, row or column is absent)."""
    frame = step.tables.get(table)
    if frame is None or column not in frame.columns or row not in frame.index:
        return math.nan
    return float(frame.at[row, column])


def _temperature(value: float) -> float:
    """A printed temperature (K); NaN for a value <= 0 K, which the print shows for a
    temperature not computed yet (the report's exit fluid temperature at step 0 is 0)."""
    return value if value > 0.0 else math.nan


def _step_row(step) -> dict:
    row = {"total_power_loss_W": _cell(step, "performance", "bearing", "total_power_loss_W"),
           "exit_fluid_temp_K": _temperature(_cell(step, "performance", "bearing", "exit_fluid_temp_K")),
           "bulk_temp_housing_K": _temperature(_cell(step, "performance", "bearing", "hsng_bulk_temp_K")),
           "bulk_temp_shaft_K": _temperature(_cell(step, "performance", "bearing", "shft_bulk_temp_K"))}
    for body, label in _BODY_ROWS.items():
        row[f"bulk_temp_{body}_K"] = _temperature(_cell(step, "accelerations", label, "bulk_temp_K"))
        row[f"wear_rate_{body}_m3_s"] = _cell(step, "bodies", label, "wear_rate_m3_s")
    thermal, motion = step.tables.get("re_thermal"), step.tables.get("re_motion")
    row["bulk_temp_re_K"] = _temperature(float(thermal["bulk_temp_K"].mean(skipna=False))) if thermal is not None else math.nan
    row["wear_rate_re_m3_s"] = float(motion["wear_rate_m3_s"].mean(skipna=False)) if motion is not None else math.nan
    for frame, names in ((motion, (("contact_loss", "W"),)),
                         (thermal, (("contact_temp_rise", "K"), ("contact_temp", "K")))):
        if frame is None:
            continue
        for n in frame.index:
            for what, unit in names:
                for race in RACES:
                    value = float(frame.at[n, f"{what}_{race}_{unit}"])
                    row[f"re{n}_{what}_{race}_{unit}"] = _temperature(value) if what == "contact_temp" else value
    r = _cell(step, "bodies", "Cage", "mc_pos_radial_m")
    theta = math.radians(_cell(step, "bodies", "Cage", "mc_pos_orbital_deg"))
    whirl = _cell(step, "bodies", "Cage", "orbital_velocity_rpm") * 2.0 * math.pi / 60.0
    row["cage_y_m"], row["cage_z_m"] = -r * math.sin(theta), r * math.cos(theta)
    row["cage_whirl_velocity_m_s"] = r * whirl
    lands = step.tables.get("race_cage")
    if lands is not None:
        for k in lands.index:
            row[f"land{k}_force_N"] = float(lands.at[k, "force_N"])
        play = lands["effective_dia_play_m"].dropna()
        row["guide_clearance_m"] = float(play.min()) if len(play) else math.nan
    pockets = step.tables.get("re_cage")
    if pockets is not None:
        force = pockets["contact_force_N"]
        if isinstance(pockets.index, pd.MultiIndex):  # roller: both ends of a roller summed
            force = force.groupby(level="element").sum(min_count=len(pockets.index.levels[1]))
        for n, value in force.items():
            row[f"pocket{n}_force_N"] = float(value)
    return row


def history_from_print(run) -> pd.DataFrame:
    """The time-history table (module contract) of a parsed print: one row per printed
    step at its printed time (s), with a ``step`` column holding the step number."""
    rows, times, numbers = [], [], []
    for n in run.step_numbers:
        step = run.step(n)
        rows.append(_step_row(step))
        times.append(float(step.header.get("time_s", math.nan)))
        numbers.append(n)
    frame = pd.DataFrame(rows, index=pd.Index(times, name="time_s"))
    frame.insert(0, "step", numbers)
    return frame


def time_history(source) -> pd.DataFrame:
    """The time-history table of a :class:`~pyadore.plots.sources.Source`: the one it
    carries, else the one built from its print's steps; only the rows in its time window
    (``source.window``, s) when it has one."""
    if source.history is not None:
        frame = source.history
        if frame.index.name != "time_s":
            raise ValueError(f"{source.label}: a time-history DataFrame is indexed by time_s (s), "
                             f"got index {frame.index.name!r}")
    else:
        frame = history_from_print(source.run)
    return in_window(frame, getattr(source, "window", None))


def in_window(frame: pd.DataFrame, window) -> pd.DataFrame:
    """The rows of ``frame`` (index time_s) with start <= time <= end (``window`` =
    (start, end) in s, either None for open; None: every row)."""
    if window is None:
        return frame
    start, end = window
    t = frame.index.to_numpy(float)
    keep = np.ones(len(t), dtype=bool)
    if start is not None:
        keep &= t >= start - 1e-12
    if end is not None:
        keep &= t <= end + 1e-12
    return frame[keep]


def window_text(window) -> str:
    """``the time window 10 ms to 62.5 ms`` for messages ("" without a window)."""
    if window is None:
        return ""
    start, end = window
    show = (lambda t: f"{t * 1e3:g} ms")
    if start is not None and end is not None:
        return f"the time window {show(start)} to {show(end)}"
    return f"the time window from {show(start)}" if start is not None else f"the time window up to {show(end)}"


def finite(history: pd.DataFrame, column: str) -> pd.Series:
    """The finite values of ``column`` (an empty Series when it is absent)."""
    if column not in history.columns:
        return pd.Series([], dtype=float, index=pd.Index([], name="time_s"))
    s = history[column].astype(float)
    return s[np.isfinite(s.to_numpy())]


def has_series(history: pd.DataFrame, column: str, points: int = 2) -> bool:
    """True when ``column`` has finite values at ``points`` (default two) or more distinct
    times."""
    return finite(history, column).index.nunique() >= points


#: The most step numbers a figure's reason names (a run's history holds every step).
STEPS_NAMED = 6


def _steps_text(source, history: pd.DataFrame) -> str:
    if "step" in history.columns:
        steps = [int(s) for s in history["step"]]
        if not steps:
            return "no step"
        if len(steps) > STEPS_NAMED:   # a history of every step: first ones, last one, count
            head = ", ".join(map(str, steps[:STEPS_NAMED - 1]))
            return f"steps {head}, ..., {steps[-1]} ({len(steps)} steps)"
        return ("only step " if len(steps) == 1 else "steps ") + ", ".join(map(str, steps))
    return f"{len(history)} instant(s)"


def require(source, history: pd.DataFrame, columns: list[str], figure: str, what: str) -> list[str]:
    """The columns of ``columns`` that ``history`` has (:func:`has_series`); raises
    MissingSeriesError naming ``figure`` and ``what`` when it has none of them."""
    present = [c for c in columns if has_series(history, c)]
    if present:
        return present
    window = getattr(source, "window", None)
    if window is not None:
        raise MissingSeriesError(f"{figure}: {source.label} has {_steps_text(source, history)} in "
                                 f"{window_text(window)}; the figure needs two or more")
    if history.index.nunique() < 2:
        raise MissingSeriesError(f"{figure}: {source.label} has {_steps_text(source, history)}; the time "
                                 f"history needs the time integration (two or more printed steps)")
    raise MissingSeriesError(f"{figure}: {source.label} has no {what} at two or more printed times "
                             f"({_steps_text(source, history)})")
