"""Quasi-static start: ball equilibrium, race control, mounting, roller-bearing step 0."""

from __future__ import annotations

import os

from .base import _probes, check


BALL_QS_COLUMNS = ["x", "r", "alpha_o", "alpha_i", "q_o", "q_i", "delta_o", "delta_i",
                   "a_o", "a_i", "b_o", "b_i", "p_o", "p_i", "centrifugal"]


def _ball_qs_args(geom, load, solve_moment, orbital_speed):
    import numpy as np

    return (np.asarray(geom, dtype=float), np.asarray(load, dtype=float),
            np.asarray(solve_moment, dtype=np.int32), np.asarray(orbital_speed, dtype=float))


def ball_quasi_static(geom, load, solve_moment, orbital_speed) -> dict:
    """Quasi-static ball-bearing equilibrium (engine module adore_quasistatic_ball_equilibrium).

    geom(13), load(11), solve_moment(2) as documented in fortran/api/probes/quasistatic.f90;
    orbital_speed: per-ball orbital speeds (rad/s).  Returns per-ball arrays under the
    names of BALL_QS_COLUMNS (SI, angles in rad) and the race results ``u`` (5),
    ``inner_force``, ``inner_moment``, ``outer_force``, ``outer_moment`` (3 each),
    ``race_residual`` (5), ``max_ball_residual`` and ``iterations``.
    """
    balls, race, status, message = _probes().adore_ball_qs(*_ball_qs_args(geom, load, solve_moment,
                                                                          orbital_speed))
    check(int(status), message)
    out = {name: balls[:, k].copy() for k, name in enumerate(BALL_QS_COLUMNS)}
    out.update(u=race[0:5].copy(), inner_force=race[5:8].copy(), inner_moment=race[8:11].copy(),
               outer_force=race[11:14].copy(), outer_moment=race[14:17].copy(),
               race_residual=race[17:22].copy(), max_ball_residual=float(race[22]),
               iterations=int(race[23]))
    return out


def ball_race_jacobian(geom, load, solve_moment, orbital_speed, u):
    """Inner race residual (5) and analytic Jacobian (5 x 5) at race position ``u``."""
    import numpy as np

    res, jac, status, message = _probes().adore_ball_race_jacobian(
        *_ball_qs_args(geom, load, solve_moment, orbital_speed), np.asarray(u, dtype=float))
    check(int(status), message)
    return res.copy(), jac.copy()


def race_control(d, r_b, n_o, n_i, w_o, w_i, control: int):
    """Race-control ball kinematics: (orbital speed, spin speed (rad/s), pitch (rad))."""
    import numpy as np

    kin, status, message = _probes().adore_race_control(
        float(d), float(r_b), np.asarray(n_o, dtype=float), np.asarray(n_i, dtype=float),
        float(w_o), float(w_i), int(control))
    check(int(status), message)
    return float(kin[0]), float(kin[1]), float(kin[2])


def mount_races(rings, fits, speeds, dia_play: float) -> dict:
    """Effective fits, raceway displacements and internal clearance (adore_geometry_fits).

    rings: 4 rows (shaft, inner race, outer race, housing) of [inner diameter, outer
    diameter (m), E (Pa), nu, density (kg/m**3)]; fits, speeds: [inner, outer] (m, rad/s).
    """
    import numpy as np

    result, status, message = _probes().adore_mount_races(
        np.asarray(rings, dtype=float).T.copy(order="F"), np.asarray(fits, dtype=float),
        np.asarray(speeds, dtype=float), float(dia_play))
    check(int(status), message)
    keys = ["inner_fit", "outer_fit", "inner_pressure", "outer_pressure", "inner_raceway_growth",
            "outer_raceway_shrink", "clearance"]
    return dict(zip(keys, (float(v) for v in result)))


ROLLER_STEP0_COLUMNS = ["azimuth", "r", "tilt", "q_o", "q_i", "p_o", "p_i", "a_o", "a_i", "b_o", "b_i",
                        "delta_o", "delta_i", "centrifugal", "orbital_speed", "spin_speed", "peak_o", "peak_i"]


ROLLER_STEP0_SLICES = ["x_o", "delta_o", "b_o", "q_o", "x_i", "delta_i", "b_i", "q_i"]


ROLLER_STEP0_SUMMARY = ["inner_fit", "outer_fit", "clearance", "contact_clearance", "u_y", "u_z",
                        "inner_force_x", "inner_force_y", "inner_force_z", "inner_moment_x", "inner_moment_y",
                        "inner_moment_z", "race_residual_y", "race_residual_z", "max_roller_residual",
                        "iterations", "inner_raceway_growth", "outer_raceway_shrink", "k_line_outer",
                        "k_line_inner", "basic_life_outer_h", "basic_life_inner_h", "basic_life_h"]


def roller_step0_from_deck(deck_path: str | os.PathLike, *, growth_count: int = 2,
                           misalignment: tuple[float, float] = (0.0, 0.0),
                           nmax: int = 200) -> tuple[dict, dict, dict]:
    """Step 0 of a roller-bearing deck computed by the engine end to end (SI, rad, rad/s).

    growth_count 2 reproduces ADORE 5.0 (raceway growth applied twice in the contact
    geometry, see fortran/start/roller_step0.f90), 1 is the consistent clearance.
    misalignment: the inner race's prescribed misalignment about y and z (rad; the report
    runs roller bearings with prescribed misalignment, section 4.4.1).  No deck field is
    identified for it (docs/examples.md), so it is given here.
    Returns (per-roller arrays ROLLER_STEP0_COLUMNS, per-roller slice arrays (n, 12)
    ROLLER_STEP0_SLICES, scalars ROLLER_STEP0_SUMMARY).
    """
    n, rollers, slices, summary, status, message = _probes().adore_roller_step0_deck(
        os.fspath(deck_path), int(growth_count), [float(m) for m in misalignment], int(nmax))
    check(int(status), message)
    n = int(n)
    per_roller = {name: rollers[:n, k].copy() for k, name in enumerate(ROLLER_STEP0_COLUMNS)}
    per_slice = {name: slices[:n, :, k].copy() for k, name in enumerate(ROLLER_STEP0_SLICES)}
    return per_roller, per_slice, {name: float(summary[k]) for k, name in enumerate(ROLLER_STEP0_SUMMARY)}
