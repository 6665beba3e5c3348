"""The key results of one run, taken from its print file (the last printed step).

Columns (SI, the unit in the name; lives in hours as the print gives them):

* ``total_power_loss_W``: section 4 total power loss;
* ``basic_life_h`` / ``modified_life_h``: Lundberg-Palmgren basic and modified fatigue life;
* ``max_contact_load_N`` / ``max_contact_stress_Pa``: the largest race contact load and
  stress over every rolling element, outer and inner race (section 1);
* ``cage_speed_ratio``: cage angular velocity over shaft speed (section 4 summary);
* ``cage_bulk_temp_K``, ``outer_race_bulk_temp_K``, ``inner_race_bulk_temp_K``,
  ``housing_bulk_temp_K``, ``shaft_bulk_temp_K``: bulk temperatures (section 3 and 4).
  Until the thermal model runs they are the initial temperatures of the deck (Rec 2.7).

Beside these last-step values, the time averages of a run with time steps over its last
``revolutions`` shaft revolutions (:func:`mean_results`, from the run's dataset,
docs/results.md): ``mean_total_power_loss_W``, ``mean_max_contact_load_N`` (the largest
time-averaged race contact load), ``mean_cage_speed_ratio`` (the cage's mean angular
velocity about its axis over the shaft speed, both relative to the outer race) and
``mean_revolutions`` (the window's length; NaN without time steps or when the run covers fewer
revolutions than asked: the step count of a sweep gives a fixed time, not a fixed number of
revolutions, so compare cases by their averages over the same number of revolutions).

The cage's whirl-stability measures over the second half of the run
(:func:`pyadore.cage_stability.cage_stability`, issue #25): ``mean_whirl_radius_m``,
``whirl_speed_ratio``, ``whirl_speed_cv``, ``radial_velocity_ratio``,
``max_whirl_radius_ratio``, ``land_contact_fraction`` and ``cage_stability`` (1 stable,
0 erratic, NaN for a cage held centred).

A value the engine does not compute (printed ``NaN``) is NaN here.
"""

from __future__ import annotations

import math

from ..cage_stability import STABILITY_COLUMNS, cage_stability

__all__ = ["RESULT_COLUMNS", "MEAN_COLUMNS", "key_results", "mean_results"]

#: The result columns of a sweep summary, in order.
RESULT_COLUMNS = (
    "total_power_loss_W", "basic_life_h", "modified_life_h", "max_contact_load_N", "max_contact_stress_Pa",
    "cage_speed_ratio", "cage_bulk_temp_K", "outer_race_bulk_temp_K", "inner_race_bulk_temp_K",
    "housing_bulk_temp_K", "shaft_bulk_temp_K",
    "mean_total_power_loss_W", "mean_max_contact_load_N", "mean_cage_speed_ratio", "mean_revolutions",
) + STABILITY_COLUMNS

#: The time-averaged columns (mean_results), part of RESULT_COLUMNS.
MEAN_COLUMNS = ("mean_total_power_loss_W", "mean_max_contact_load_N", "mean_cage_speed_ratio",
                "mean_revolutions") + STABILITY_COLUMNS


def _cell(step, table: str, row, column: str) -> float:
    try:
        frame = step.tables[table]
        return float(frame.loc[row, column])
    except (KeyError, TypeError, ValueError):
        return math.nan


def _largest(step, columns: tuple[str, ...]) -> float:
    frame = step.tables.get("re_contact")
    if frame is None:
        return math.nan
    values = [float(v) for c in columns if c in frame.columns for v in frame[c] if not math.isnan(float(v))]
    return max(values) if values else math.nan


def key_results(print_run) -> dict:
    """The :data:`RESULT_COLUMNS` values of a parsed print file (a
    :class:`pyadore.printout.PrintRun`) at its last printed step, plus ``result_step``."""
    number = print_run.step_numbers[-1]
    step = print_run.step(number)
    perf = "performance"
    out = {
        "total_power_loss_W": _cell(step, perf, "bearing", "total_power_loss_W"),
        "basic_life_h": _cell(step, perf, "bearing", "basic_fatigue_life_hours"),
        "modified_life_h": _cell(step, perf, "bearing", "modified_fatigue_life_hours"),
        "max_contact_load_N": _largest(step, ("contact_load_outer_N", "contact_load_inner_N")),
        "max_contact_stress_Pa": _largest(step, ("contact_stress_outer_Pa", "contact_stress_inner_Pa")),
        "cage_speed_ratio": _cell(step, "summary", number, "cage_omega_ratio"),
        "cage_bulk_temp_K": _cell(step, "accelerations", "Cage", "bulk_temp_K"),
        "outer_race_bulk_temp_K": _cell(step, "accelerations", "ORace", "bulk_temp_K"),
        "inner_race_bulk_temp_K": _cell(step, "accelerations", "IRace", "bulk_temp_K"),
        "housing_bulk_temp_K": _cell(step, perf, "bearing", "hsng_bulk_temp_K"),
        "shaft_bulk_temp_K": _cell(step, perf, "bearing", "shft_bulk_temp_K"),
    }
    out["result_step"] = number
    return out


def mean_results(dataset, revolutions: float = 1.0, guide: str = "inner") -> dict:
    """The :data:`MEAN_COLUMNS` of a run's results (:attr:`pyadore.Result.arrays`, or
    :attr:`pyadore.Result.dataset`): the cage's stability measures over the second half of
    the run (cage_stability, about the ``guide`` race: "inner" or "outer", Rec 7.0's first
    guide type) and time-weighted averages over its last ``revolutions`` shaft revolutions
    (:func:`pyadore.results.time_means`; no xarray imported for arrays); NaN for a run
    without results or one shorter than that."""
    out = {c: math.nan for c in MEAN_COLUMNS}
    if dataset is None:
        return out
    import numpy as np  # here: the sweep command's client imports this module for its columns only

    out.update(cage_stability(dataset, guide=guide))
    from ..errors import AdoreInputError
    from ..results import time_means

    try:
        m = time_means(dataset, last_revolutions=revolutions)
    except AdoreInputError:
        return out

    def value(name):
        return m[name].to_numpy()

    out["mean_total_power_loss_W"] = float(value("total_power_loss_W"))
    loads = value("contact_load_N")
    # the largest average load, NaN ones (contacts never loaded in the window) left out
    out["mean_max_contact_load_N"] = float(np.nanmax(loads)) if np.isfinite(loads).any() else math.nan
    shaft = float(value("inner_race_angular_velocity_x_rad_s") - value("outer_race_angular_velocity_x_rad_s"))
    cage = float(value("cage_angular_velocity_x_rad_s") - value("outer_race_angular_velocity_x_rad_s"))
    out["mean_cage_speed_ratio"] = cage / shaft if shaft != 0.0 else math.nan
    out["mean_revolutions"] = float(m.attrs["revolutions"])
    return out
