"""Step 0 of a ball-bearing deck, end to end (fortran/start/ball_step0.f90; bench/)."""

from __future__ import annotations

import os

from .base import _engine, check


BALL_STEP0_COLUMNS = ["azimuth", "x", "r", "alpha_o", "alpha_i", "q_o", "q_i", "p_o", "p_i", "a_o", "a_i",
                      "b_o", "b_i", "delta_o", "delta_i", "orbital_speed", "spin_speed", "pitch",
                      "slip_o", "slip_i", "trac_o", "trac_i", "spin_roll_o", "spin_roll_i", "loss_o", "loss_i",
                      "film_o", "film_i", "thermal_factor_o", "thermal_factor_i", "temp_rise_o", "temp_rise_i",
                      "sliding_o", "sliding_i", "wear", "traction_o", "traction_i"]


BALL_STEP0_SUMMARY = ["inner_fit", "outer_fit", "clearance", "basic_life_h", "basic_life_outer_h",
                      "basic_life_inner_h", "u_x", "u_y", "u_z", "theta_y", "theta_z", "inner_force_x",
                      "inner_force_y", "inner_force_z", "inner_moment_x", "inner_moment_y", "inner_moment_z",
                      "passes", "power_loss", "modified_life_h"]


def ball_step0_from_deck(deck_path: str | os.PathLike, nmax: int = 200, *, mech_tol: float | None = None,
                         moment_equilibrium: bool = False) -> tuple[dict, dict]:
    """Step 0 of a ball-bearing deck computed by the engine end to end (SI, angles in rad):
    per-ball arrays (BALL_STEP0_COLUMNS) and scalars (BALL_STEP0_SUMMARY).

    mech_tol: the start's consistency test on the centrifugal forces, a fraction of the load
    scale (None: the engine's MECH_TOL, 1e-8; fortran/quasistatic/ball_start.f90);
    moment_equilibrium: solve the inner race's tilts (as the run option)."""
    tol = 0.0 if mech_tol is None else float(mech_tol)
    if not tol >= 0.0:
        raise ValueError(f"mech_tol must be > 0 or None, got {mech_tol!r}")
    n, balls, summary, status, message = _engine().adore_ball_step0_deck(
        os.fspath(deck_path), int(nmax), tol, int(bool(moment_equilibrium)))
    check(int(status), message)
    per_ball = {name: balls[: int(n), k].copy() for k, name in enumerate(BALL_STEP0_COLUMNS)}
    return per_ball, {name: float(summary[k]) for k, name in enumerate(BALL_STEP0_SUMMARY)}
