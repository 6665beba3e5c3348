"""Step-0 roller/race traction by slices (fortran/tribology/roller_traction.f90)."""

from __future__ import annotations

import os

from .base import _probes, check

ROLLER_TRIBOLOGY_COLUMNS = ["spin", "moment_residual", "tangential_force",
                            "slip_o", "kappa_o", "power_o", "force_o", "moment_o",
                            "slip_i", "kappa_i", "power_i", "force_i", "moment_i", "orbital_speed",
                            "sliding_o", "sliding_i", "wear", "temp_rise_o", "temp_rise_i"]

ROLLER_TRIBOLOGY_SLICES = ["x_o", "w_o", "u_o", "t_o", "x_i", "w_i", "u_i", "t_i"]

ROLLER_TRIBOLOGY_SUMMARY = ["contact_power", "power_loss", "rolling_spin"]

SPIN_ROLLING = 1
SPIN_EQUILIBRIUM = 2


def roller_step0_tribology(deck_path: str | os.PathLike, *, growth_count: int = 2,
                           spin_method: int = SPIN_ROLLING, nmax: int = 200) -> tuple[dict, dict, dict]:
    """Step-0 tractions of a roller-bearing deck (SI: m, m/s, rad/s, N, N/m, N m, W).

    spin_method SPIN_ROLLING (the report's start: the land rolls on both races) or
    SPIN_EQUILIBRIUM (spin from each roller's traction moment balance).  Returns (per-roller
    arrays ROLLER_TRIBOLOGY_COLUMNS, per-roller slice arrays (n, 12) ROLLER_TRIBOLOGY_SLICES,
    scalars ROLLER_TRIBOLOGY_SUMMARY); slip_x = printed Slip Velocity (largest |u| over the
    slices), kappa_x = kappa(slip_x) (printed Trac Coeff), power_x = contact loss (eq 4).
    """
    n, rollers, slices, summary, status, message = _probes().adore_roller_step0_tribology(
        os.fspath(deck_path), int(growth_count), int(spin_method), int(nmax))
    check(int(status), message)
    n = int(n)
    per_roller = {name: rollers[:n, k].copy() for k, name in enumerate(ROLLER_TRIBOLOGY_COLUMNS)}
    per_slice = {name: slices[:n, :, k].copy() for k, name in enumerate(ROLLER_TRIBOLOGY_SLICES)}
    return per_roller, per_slice, {name: float(summary[k]) for k, name in enumerate(ROLLER_TRIBOLOGY_SUMMARY)}
