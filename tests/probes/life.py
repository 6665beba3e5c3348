"""Fatigue life (fortran/life): Lundberg-Palmgren and Tallian."""

from __future__ import annotations

import math

from pyadore.errors import AdoreInputError
from .base import _probes, check


LIFE_CONSTANT_NAMES = (
    "a_point", "b_line", "dm_exponent", "cycle_factor", "load_exp_point", "load_exp_line",
    "weibull_e_point", "weibull_e_line", "scale_a", "beta", "zeta", "matrix_m", "tau0",
    "phi0lp_root_per_pa", "phi1_asperity", "phi1_furrow", "phi1_subsurface", "processing_i",
    "phi2f_clean", "contamination", "spectrum_alpha", "sigma_rms", "theta_rms", "z_frac",
    "mu_asperity", "hoop_factor", "sigma_residual", "e_prime", "stationary_rule",
    "line_length_factor",
)


_HUGE = 1.0e300  # the engine's huge(1.0_wp) ("never fails") is returned as math.inf


def life_default_constants() -> dict:
    """Default fatigue model constants of the engine (report section 3.2), by name."""
    values = _probes().adore_life_default_constants()
    return dict(zip(LIFE_CONSTANT_NAMES, (float(v) for v in values)))


def _finite_life(value: float) -> float:
    value = float(value)
    return math.inf if value >= _HUGE else value


def ball_bearing_life(q_outer, q_inner, alpha_outer, alpha_inner, orbital_speed, p_max_outer, p_max_inner, *,
                      d_ball: float, d_pitch: float, f_outer: float, f_inner: float,
                      outer_speed: float, inner_speed: float,
                      outer_rotating: bool = False, inner_rotating: bool = True,
                      lambda_outer=None, lambda_inner=None, mu_outer=None, mu_inner=None,
                      hoop_outer: float = 0.0, hoop_inner: float = 0.0, constants: dict | None = None) -> dict:
    """Basic (Lundberg-Palmgren) and modified (Tallian) life of a ball bearing, report eqs 73-109.

    Per rolling element k (equal-length sequences, in ball order): contact loads q (N),
    contact angles alpha (rad), orbital speed (rpm), max Hertz pressures p_max (Pa),
    film parameters lambda = film / composite RMS height (-; None or <= 0: no film) and
    EHD traction coefficients mu (-; None: 0).  Race data: hoop stresses (Pa), ball and
    pitch diameters (m), groove curvature factors f, race speeds (rpm), and whether each
    race turns relative to the load.  ``constants`` overrides defaults by name
    (:data:`LIFE_CONSTANT_NAMES`, :func:`life_default_constants`).

    Returns hours for ``basic_outer``, ``basic_inner``, ``basic`` (bearing, eq 102),
    ``modified_outer``, ``modified_inner``, ``modified``; the hazard ratios ``psi_outer``,
    ``psi_inner`` (eq 78); and ``lives_outer``, ``lives_inner``, the contact lives
    (10**6 relative revolutions, numpy arrays).  ``math.inf`` means "never fails".
    """
    import numpy as np

    q_outer = np.asarray(q_outer, dtype=float)
    m = q_outer.shape[0] if q_outer.ndim == 1 else -1
    if m < 1:
        raise AdoreInputError("life: per-element inputs must be non-empty 1-d sequences")

    def per_element(name, value, default):
        arr = np.full(m, default, dtype=float) if value is None else np.asarray(value, dtype=float)
        if arr.shape != (m,):
            raise AdoreInputError(f"life: {name} has shape {arr.shape}, expected ({m},) like q_outer")
        if not np.all(np.isfinite(arr)):
            raise AdoreInputError(f"life: {name} contains NaN or infinite values")
        return arr

    arrays = [per_element(name, value, 0.0) for name, value in (
        ("q_outer", q_outer), ("q_inner", q_inner), ("alpha_outer", alpha_outer), ("alpha_inner", alpha_inner),
        ("orbital_speed", orbital_speed), ("p_max_outer", p_max_outer), ("p_max_inner", p_max_inner))]
    arrays += [per_element(name, value, 0.0) for name, value in (
        ("lambda_outer", lambda_outer), ("lambda_inner", lambda_inner),
        ("mu_outer", mu_outer), ("mu_inner", mu_inner))]
    values = life_default_constants()
    unknown = sorted(set(constants or {}) - set(values))
    if unknown:
        raise AdoreInputError(f"life: unknown constant(s) {', '.join(unknown)}")
    values.update({k: float(v) for k, v in (constants or {}).items()})
    result, lives_o, lives_i, status, message = _probes().adore_life_ball_bearing(
        *arrays, float(hoop_outer), float(hoop_inner), float(d_ball), float(d_pitch), float(f_outer),
        float(f_inner), float(outer_speed), float(inner_speed), int(bool(outer_rotating)),
        int(bool(inner_rotating)), np.array([values[k] for k in LIFE_CONSTANT_NAMES], dtype=float))
    check(int(status), message)
    keys = ["basic_outer", "basic_inner", "basic", "modified_outer", "modified_inner", "modified"]
    out = {k: _finite_life(v) for k, v in zip(keys, result[:6])}
    out["psi_outer"], out["psi_inner"] = float(result[6]), float(result[7])
    out["lives_outer"] = np.where(lives_o >= _HUGE, np.inf, lives_o)
    out["lives_inner"] = np.where(lives_i >= _HUGE, np.inf, lives_i)
    return out
