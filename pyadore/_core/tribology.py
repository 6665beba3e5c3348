"""Tribology building blocks (fortran/tribology): film, thermal reduction, slip/traction, flash temperature."""

from __future__ import annotations

from .base import _engine, check


def film_thickness(rx: float, k: float, u: float, load: float, e_prime: float, eta0: float,
                   alpha: float) -> float:
    """Hamrock-Dowson isothermal central film thickness (m): R_x (m), ellipticity a/b,
    mean entraining speed (m/s), load (N), E' (Pa), eta0 (Pa s), alpha (1/Pa)."""
    h, status, message = _engine().adore_tribo_film(rx, k, u, load, e_prime, eta0, alpha)
    check(int(status), message)
    return float(h)


def thermal_reduction_factor(p_h: float, e_prime: float, loading, slide_roll: float = 0.0):
    """Gupta et al. (1992) inlet-shear thermal reduction factor for thermal loading(s) L."""
    import numpy as np

    phi, status, message = _engine().adore_tribo_thermal_factor(
        p_h, e_prime, np.atleast_1d(np.asarray(loading, float)), slide_roll)
    check(int(status), message)
    return phi


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


CONTACT_TRACTION_KEYS = ["force", "coefficient", "power", "max_slip", "centre_slip", "rolling_speed", "spin",
                         "spin_roll", "rx", "n_rolling", "s1", "s2", "node_slip", "node_coefficient", "sliding"]


def _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load):
    import numpy as np

    return np.array([float(side), alpha, rho, r_b, omega[0], omega[1], race_speed, a, load], dtype=float)


def contact_traction(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                     load: float, coef, kappa_scale: float = 1.0, n_gauss: int = 16) -> dict:
    """Ball/race contact traction, power loss and kinematics (report eqs 1, 3, 4); side +1
    outer / -1 inner; omega = ball angular velocity (axial, radial) in the orbit frame
    (rad/s); race_speed = Omega - w_m (rad/s).  Keys: CONTACT_TRACTION_KEYS."""
    import numpy as np

    values, status, message = _engine().adore_tribo_contact(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(coef, float),
        kappa_scale, int(n_gauss))
    check(int(status), message)
    return dict(zip(CONTACT_TRACTION_KEYS, map(float, values)))


def contact_slip(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float, s):
    """Slip velocity (m/s) at major-axis positions s (m) (report eq 3, rolling component)."""
    import numpy as np

    u, status, message = _engine().adore_tribo_slip(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, 0.0), np.asarray(s, float))
    check(int(status), message)
    return u


def wear_rate(k: float, rockwell_c: float, sliding):
    """Archard wear rates (m**3/s) of a body with wear coefficient k and Rockwell C hardness
    under sliding = integral of |u| dQ (N m/s), with ADORE 5.0's hardness conversion; returns
    (hardness in Pa, rates)."""
    import numpy as np

    h, rate, status, message = _engine().adore_tribo_wear(float(k), float(rockwell_c),
                                                          np.atleast_1d(np.asarray(sliding, float)))
    check(int(status), message)
    return float(h), rate


def traction_table(path):
    """Read a traction-slip table file (ADRX7) as the engine reads it: (slip m/s, kappa)."""
    import os

    path = os.fspath(path)
    n, _, _, status, message = _engine().adore_tribo_traction_table(path, 0)
    check(int(status), message)
    n, slip, kappa, status, message = _engine().adore_tribo_traction_table(path, int(n))
    check(int(status), message)
    return slip, kappa


def flash_rise(xi, q):
    """Dimensionless flash temperature rise (report eq 53) on the grid xi for flux q."""
    import numpy as np

    dt, status, message = _engine().adore_tribo_flash_strip(np.asarray(xi, float), np.asarray(q, float))
    check(int(status), message)
    return dt


def contact_temperature_rise(a: float, b: float, p0: float, xk, wk, g, u1: float, u2: float, th1, th2,
                             ny: int = 201) -> tuple[float, float]:
    """(average, largest) contact temperature rise (K), report eqs 35-36; see the engine's
    adore_tribology_flash.contact_temperature_rise."""
    import numpy as np

    values, status, message = _engine().adore_tribo_contact_temperature(
        a, b, p0, np.asarray(xk, float), np.asarray(wk, float), np.asarray(g, float), u1, u2,
        np.asarray(th1, float), np.asarray(th2, float), int(ny))
    check(int(status), message)
    return float(values[0]), float(values[1])


# --- roller bearings: line contact by slices, step 0 (fortran/contact/line_slices.f90,
# fortran/start/roller_step0.f90) ---------------------------------------------------


def ehd_contact_traction(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                         load: float, rheology, film: float, b: float, n_gauss: int = 16,
                         n_strip: int = 24) -> dict:
    """Ball/race contact traction of the EHD film model (ADORE traction model 3): geometry as
    contact_traction; rheology = (eta_w Pa s, alpha_t 1/Pa, beta_t 1/K, K_f W/m/K); film h
    (m); b semi-minor axis (m).  Keys: CONTACT_TRACTION_KEYS."""
    import numpy as np

    values, status, message = _engine().adore_tribo_ehd_contact(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(rheology, float),
        float(film), float(b), int(n_gauss), int(n_strip))
    check(int(status), message)
    return dict(zip(CONTACT_TRACTION_KEYS, map(float, values)))


EHD_METHOD_KEYS = ["force", "force_cos", "force_sin", "power", "sliding", "max_slip", "coefficient", "n_rolling"]
EHD_METHODS = {"reference": 0, "fast": 1}
EHD_CROSS_KEYS = ["cross_force", "cross_force_cos", "cross_force_sin"]


def ehd_contact_method(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                       load: float, rheology, film: float, b: float, method: str = "fast", n_major: int = 0,
                       n_strip: int = 0, transverse=None) -> dict:
    """EHD contact traction (model 3) by the reference quadrature (method "reference":
    n_major Gauss points per slip zone x n_strip across each strip, as ehd_contact_traction)
    or the fast one (method "fast": ehd_contact_traction_fast, 0 = its default orders);
    arguments as ehd_contact_traction.  Keys: EHD_METHOD_KEYS (force, its moments
    force_cos / force_sin in N, power W, sliding N m/s, max_slip m/s, coefficient, n_rolling).
    transverse: the two-dimensional traction with the slip across the rolling direction
    u_m(psi) = m1 + m2 cos psi + m3 sin psi (m/s; report eq 5), and the keys
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


def film_shear_stress(u, eta_w: float, beta: float, k_f: float, h: float):
    """Shear stress (Pa) of a Newtonian film of thickness h (m) at slips u (m/s), walls at
    the temperature of the wall viscosity eta_w (Pa s); beta (1/K), K_f (W/m/K)."""
    import numpy as np

    tau, status, message = _engine().adore_tribo_film_shear(np.atleast_1d(np.asarray(u, float)), eta_w, beta,
                                                            k_f, h)
    check(int(status), message)
    return tau


def ehd_temperature_rise(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                         load: float, rheology, film: float, b: float, u1: float, u2: float, th1, th2,
                         n_gauss: int = 16, ny: int = 201) -> tuple[float, float]:
    """(average, largest) flash temperature rise (K) of a ball/race contact heated by its EHD
    film (report eqs 35-36); arguments as ehd_contact_traction plus the surface speeds u1, u2
    (m/s) and th1, th2 = (density, heat capacity, conductivity) of the two bodies."""
    import numpy as np

    values, status, message = _engine().adore_tribo_ehd_temperature(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(rheology, float),
        float(film), float(b), int(n_gauss), int(ny), float(u1), float(u2), np.asarray(th1, float),
        np.asarray(th2, float))
    check(int(status), message)
    return float(values[0]), float(values[1])
