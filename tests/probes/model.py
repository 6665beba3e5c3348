"""Derived echo quantities: clearance, inertia, traction-curve fit, scale factors (fortran/model)."""

from __future__ import annotations

from .base import _probes, check


_INERTIA_KINDS = {"sphere": 1, "solid_cylinder": 2, "hollow_cylinder": 3, "ball_cage": 4,
                  "roller_cage": 5, "roller_moments": 6}


def ball_clearance(pitch_dia: float, ball_dia: float, fo: float, fi: float, alpha0: float) -> dict:
    """Ball bearing clearance (SI, alpha0 in rad): keys dia_play, end_play,
    outer_groove_dia, inner_groove_dia (m)."""
    values, status, message = _probes().adore_model_ball_clearance(pitch_dia, ball_dia, fo, fi, alpha0)
    check(int(status), message)
    keys = ["dia_play", "end_play", "outer_groove_dia", "inner_groove_dia"]
    return dict(zip(keys, (float(v) for v in values)))


def roller_races(pitch_dia: float, roller_dia: float, dia_play: float) -> tuple[float, float]:
    """Raceway diameters (outer, inner) in m of a cylindrical roller bearing."""
    values, status, message = _probes().adore_model_roller_races(pitch_dia, roller_dia, dia_play)
    check(int(status), message)
    return float(values[0]), float(values[1])


def body_inertia(kind: str, params, rho: float, n: int = 0) -> tuple[float, list[float]]:
    """Mass (kg) and principal moments [Ix, Iy, Iz] (kg m**2) of a body.

    kind / params (m): ``sphere`` [d]; ``solid_cylinder`` [d, length];
    ``hollow_cylinder`` [d_out, d_in, width]; ``ball_cage`` [d_out, d_in, width,
    pocket_dia] with n pockets; ``roller_cage`` [d_out, d_in, width, pocket_circ,
    pocket_axial] with n pockets; ``roller_moments`` [d, length] with ``rho`` the mass (kg).
    """
    import numpy as np

    p = np.zeros(5)
    p[: len(params)] = params
    values, status, message = _probes().adore_model_inertia(_INERTIA_KINDS[kind], p, int(n), rho)
    check(int(status), message)
    return float(values[0]), [float(v) for v in values[1:]]


def traction_fit(k0: float, kmax: float, kinf: float, umax: float) -> tuple[float, float, float, float]:
    """Coefficients (A, B, C, D) of kappa(u) = (A + B u) exp(-C u) + D (B, C in s/m)."""
    values, status, message = _probes().adore_tribology_traction_fit(k0, kmax, kinf, umax)
    check(int(status), message)
    return tuple(float(v) for v in values)


def scale_factors(re_dia: float, re_mass: float, load) -> tuple[float, float, float]:
    """Scale factors (length m, load N, time s) from the rolling-element diameter and
    mass and the applied load vector [Fx, Fy, Fz] (N)."""
    import numpy as np

    values, status, message = _probes().adore_model_scales(re_dia, re_mass, np.asarray(load, dtype=float))
    check(int(status), message)
    return tuple(float(v) for v in values)
