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

A value the engine does not compute (printed ``NaN``) is NaN here.
"""

from __future__ import annotations

import math

__all__ = ["RESULT_COLUMNS", "key_results"]

#: The result columns of a sweep summary, in order.
RESULT_COLUMNS = (
    "total_power_loss_W", "basic_life_h", "modified_life_h", "max_contact_load_N", "max_contact_stress_Pa",
    "cage_speed_ratio", "cage_bulk_temp_K", "outer_race_bulk_temp_K", "inner_race_bulk_temp_K",
    "housing_bulk_temp_K", "shaft_bulk_temp_K",
)


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
