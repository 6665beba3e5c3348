"""Thin layer over the f2py extension: status codes become exceptions.

Nothing else in pyadore imports ``pyadore._engine`` directly.  Every wrapper of the
extension returns ``(status, message)``; :func:`check` raises the matching
:class:`~pyadore.errors.AdoreError` subclass for a non-zero status.
"""

from __future__ import annotations

import math
import os

from .errors import (
    STATUS_ENGINE,
    STATUS_INPUT,
    STATUS_OK,
    AdoreEngineError,
    AdoreError,
    AdoreInputError,
)

__all__ = ["check", "run_file", "engine_version", "hertz_point", "LIFE_CONSTANT_NAMES",
           "life_default_constants", "ball_bearing_life"]


def _engine():
    try:
        from . import _engine as engine
    except ImportError as exc:  # the package was installed without its extension
        raise AdoreEngineError(
            "the pyadore engine extension (pyadore._engine) is not built; "
            "run `make setup` (or `pip install -e .`) first"
        ) from exc
    return engine


def _text(value) -> str:
    if isinstance(value, bytes):
        value = value.decode("utf-8", errors="replace")
    return str(value).rstrip()


def check(status: int, message) -> None:
    """Raise the AdoreError subclass that ``status`` stands for (0: return)."""
    if status == STATUS_OK:
        return
    text = _text(message) or f"engine returned status {status}"
    if status == STATUS_INPUT:
        raise AdoreInputError(text)
    if status == STATUS_ENGINE:
        raise AdoreEngineError(text)
    raise AdoreError(f"{text} (unknown engine status {status})")


def run_file(deck_path: str | os.PathLike, out_path: str | os.PathLike, steps: int) -> None:
    """Run the engine on a deck file and write the print file (status checked)."""
    status, message = _engine().adore_run_file(os.fspath(deck_path), os.fspath(out_path), int(steps))
    check(int(status), message)


def engine_version() -> str:
    """Version string compiled into the engine."""
    return _text(_engine().adore_version())


def hertz_point(rho, e1: float, nu1: float, e2: float, nu2: float, load: float) -> dict:
    """Hertz point contact (engine module adore_contact_hertz) as a dict of SI values.

    rho: the four principal curvatures (1/m) [body 1 plane I, II, body 2 plane I, II],
    concave negative.  Keys: kappa, a_star, b_star, delta_star, semi_major (m),
    semi_minor (m), max_pressure (Pa), deflection (m), stiffness (N/m**1.5).
    """
    import numpy as np

    values, status, message = _engine().adore_hertz_point(
        np.asarray(rho, dtype=float), e1, nu1, e2, nu2, load)
    check(int(status), message)
    keys = ["kappa", "a_star", "b_star", "delta_star", "semi_major", "semi_minor",
            "max_pressure", "deflection", "stiffness"]
    return dict(zip(keys, (float(v) for v in values)))


#: Names of the fatigue model constants, in the engine's order (life_params_to_array in
#: fortran/life/lundberg_palmgren.f90); units SI.  docs/life-model.md explains each.
LIFE_CONSTANT_NAMES = (
    "a_point", "b_line", "dm_exponent", "cycle_factor", "load_exp_point", "load_exp_line",
    "weibull_e_point", "weibull_e_line", "scale_a", "beta", "zeta", "matrix_m", "tau0",
    "phi0lp_root_per_pa", "phi1_asperity", "phi1_furrow", "phi1_subsurface", "processing_i",
    "phi2f_clean", "contamination", "spectrum_alpha", "sigma_rms", "theta_rms", "z_frac",
    "mu_asperity", "hoop_factor", "sigma_residual", "e_prime", "stationary_rule",
)

_HUGE = 1.0e300  # the engine's huge(1.0_wp) ("never fails") is returned as math.inf


def life_default_constants() -> dict:
    """Default fatigue model constants of the engine (report section 3.2), by name."""
    values = _engine().adore_life_default_constants()
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
    result, lives_o, lives_i, status, message = _engine().adore_life_ball_bearing(
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
