"""Tribology the package and the benchmark use (fortran/tribology): lubricant library, EHD
contact traction by method (pyadore.plots.traction) and its timing (bench/), traction-slip
table files (pyadore.api)."""

from __future__ import annotations

from .base import _engine, check


LUBRICANT_KEYS = ["nu", "eta", "beta", "alpha", "conductivity", "density", "heat_capacity", "t_ref",
                  "eta_t", "alpha_t", "beta_t"]


def lubricant(code: int, temperature: float, pressure: float = 0.0) -> dict:
    """Lubricant of the engine's library (code as Rec 10.0 field 2; 1 = MIL-L-7808 as the
    report's Appendix C echo prints it) at temperature (K) and pressure (Pa).  Keys:
    LUBRICANT_KEYS - nu (m**2/s, at p = 0), eta (Pa s, at the pressure), beta (1/K),
    alpha (1/Pa), conductivity (W/m/K), density (kg/m**3), heat_capacity (J/kg/K), t_ref (K),
    and the EHD traction rheology eta_t (Pa s, at the temperature, p = 0), alpha_t (1/Pa), beta_t (1/K)."""
    values, status, message = _engine().adore_tribo_lubricant(int(code), float(temperature), float(pressure))
    check(int(status), message)
    return dict(zip(LUBRICANT_KEYS, map(float, values)))


def _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load):
    import numpy as np

    return np.array([float(side), alpha, rho, r_b, omega[0], omega[1], race_speed, a, load], dtype=float)


def traction_table(path):
    """Read a traction-slip table file (ADRX7) as the engine reads it: (slip m/s, kappa)."""
    import os

    path = os.fspath(path)
    n, _, _, status, message = _engine().adore_tribo_traction_table(path, 0)
    check(int(status), message)
    n, slip, kappa, status, message = _engine().adore_tribo_traction_table(path, int(n))
    check(int(status), message)
    return slip, kappa


EHD_METHOD_KEYS = ["force", "force_cos", "force_sin", "power", "sliding", "max_slip", "coefficient", "n_rolling"]


EHD_METHODS = {"reference": 0, "fast": 1}


EHD_CROSS_KEYS = ["cross_force", "cross_force_cos", "cross_force_sin"]


def ehd_contact_method(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                       load: float, rheology, film: float, b: float, method: str = "fast", n_major: int = 0,
                       n_strip: int = 0, transverse=None) -> dict:
    """EHD contact traction (model 3) by the reference quadrature (method "reference":
    n_major Gauss points per slip zone x n_strip across each strip) or the fast one (method
    "fast": ehd_contact_traction_fast, 0 = its default orders).  The contact: side +1 outer /
    -1 inner, alpha contact angle (rad), rho radius of the contact surface about the ball
    centre (m), r_b radius of the ball centre from the bearing axis (m), omega the ball's
    angular velocity (axial, radial) in the orbit frame (rad/s), race_speed = Omega - w_m
    (rad/s), a semi-major axis (m), load (N); rheology = (eta_w Pa s, alpha_t 1/Pa, beta_t
    1/K, K_f W/m/K); film h (m); b semi-minor axis (m).  Keys: EHD_METHOD_KEYS (force, its
    moments force_cos / force_sin in N, power W, sliding N m/s, max_slip m/s, coefficient,
    n_rolling).  transverse: the two-dimensional traction with the slip across the rolling
    direction u_m(psi) = m1 + m2 cos psi + m3 sin psi (m/s; report eq 5), and the keys
    EHD_CROSS_KEYS (the traction across the rolling direction and its cos, sin moments, N)."""
    import numpy as np

    if method not in EHD_METHODS:
        raise ValueError(f"EHD contact: method must be one of {sorted(EHD_METHODS)}, got {method!r}")
    cross = np.zeros(3) if transverse is None else np.asarray(transverse, float)
    values, status, message = _engine().adore_tribo_ehd_contact_method(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(rheology, float),
        float(film), float(b), EHD_METHODS[method], int(n_major), int(n_strip), int(transverse is not None), cross)
    check(int(status), message)
    keys = EHD_METHOD_KEYS + (EHD_CROSS_KEYS if transverse is not None else [])
    return dict(zip(keys, map(float, values)))


def ehd_contact_microseconds(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                             load: float, rheology, film: float, b: float, method: str = "fast",
                             repeat: int = 20000) -> float:
    """Mean CPU time (microseconds) of one EHD contact evaluation by `method` ("fast" or
    "reference" 16 x 24), timed inside the engine over `repeat` evaluations: for the
    benchmark only."""
    import numpy as np

    us, status, message = _engine().adore_tribo_ehd_contact_time(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(rheology, float),
        float(film), float(b), EHD_METHODS[method], int(repeat))
    check(int(status), message)
    return float(us)
