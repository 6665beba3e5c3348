"""Tribology building blocks (fortran/tribology): film, thermal reduction, slip/traction, flash
temperature, wear."""

from __future__ import annotations

from pyadore._core.tribology import _contact_geom

from .base import _probes, check


def film_thickness(rx: float, k: float, u: float, load: float, e_prime: float, eta0: float,
                   alpha: float) -> float:
    """Hamrock-Dowson isothermal central film thickness (m): R_x (m), ellipticity a/b,
    mean entraining speed (m/s), load (N), E' (Pa), eta0 (Pa s), alpha (1/Pa)."""
    h, status, message = _probes().adore_tribo_film(rx, k, u, load, e_prime, eta0, alpha)
    check(int(status), message)
    return float(h)


def thermal_reduction_factor(p_h: float, e_prime: float, loading, slide_roll: float = 0.0):
    """Gupta et al. (1992) inlet-shear thermal reduction factor for thermal loading(s) L."""
    import numpy as np

    phi, status, message = _probes().adore_tribo_thermal_factor(
        p_h, e_prime, np.atleast_1d(np.asarray(loading, float)), slide_roll)
    check(int(status), message)
    return phi


CONTACT_TRACTION_KEYS = ["force", "coefficient", "power", "max_slip", "centre_slip", "rolling_speed", "spin",
                         "spin_roll", "rx", "n_rolling", "s1", "s2", "node_slip", "node_coefficient", "sliding"]


def contact_traction(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                     load: float, coef, kappa_scale: float = 1.0, n_gauss: int = 16) -> dict:
    """Ball/race contact traction, power loss and kinematics (report eqs 1, 3, 4); side +1
    outer / -1 inner; omega = ball angular velocity (axial, radial) in the orbit frame
    (rad/s); race_speed = Omega - w_m (rad/s).  Keys: CONTACT_TRACTION_KEYS."""
    import numpy as np

    values, status, message = _probes().adore_tribo_contact(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(coef, float),
        kappa_scale, int(n_gauss))
    check(int(status), message)
    return dict(zip(CONTACT_TRACTION_KEYS, map(float, values)))


def contact_slip(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float, s):
    """Slip velocity (m/s) at major-axis positions s (m) (report eq 3, rolling component)."""
    import numpy as np

    u, status, message = _probes().adore_tribo_slip(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, 0.0), np.asarray(s, float))
    check(int(status), message)
    return u


def wear_rate(k: float, rockwell_c: float, sliding):
    """Archard wear rates (m**3/s) of a body with wear coefficient k and Rockwell C hardness
    under sliding = integral of |u| dQ (N m/s), with ADORE 5.0's hardness conversion; returns
    (hardness in Pa, rates)."""
    import numpy as np

    h, rate, status, message = _probes().adore_tribo_wear(float(k), float(rockwell_c),
                                                          np.atleast_1d(np.asarray(sliding, float)))
    check(int(status), message)
    return float(h), rate


def flash_rise(xi, q):
    """Dimensionless flash temperature rise (report eq 53) on the grid xi for flux q."""
    import numpy as np

    dt, status, message = _probes().adore_tribo_flash_strip(np.asarray(xi, float), np.asarray(q, float))
    check(int(status), message)
    return dt


def contact_temperature_rise(a: float, b: float, p0: float, xk, wk, g, u1: float, u2: float, th1, th2,
                             ny: int = 201) -> tuple[float, float]:
    """(average, largest) contact temperature rise (K), report eqs 35-36; see the engine's
    adore_tribology_flash.contact_temperature_rise."""
    import numpy as np

    values, status, message = _probes().adore_tribo_contact_temperature(
        a, b, p0, np.asarray(xk, float), np.asarray(wk, float), np.asarray(g, float), u1, u2,
        np.asarray(th1, float), np.asarray(th2, float), int(ny))
    check(int(status), message)
    return float(values[0]), float(values[1])


def ehd_contact_traction(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                         load: float, rheology, film: float, b: float, n_gauss: int = 16,
                         n_strip: int = 24) -> dict:
    """Ball/race contact traction of the EHD film model (ADORE traction model 3): geometry as
    contact_traction; rheology = (eta_w Pa s, alpha_t 1/Pa, beta_t 1/K, K_f W/m/K); film h
    (m); b semi-minor axis (m).  Keys: CONTACT_TRACTION_KEYS."""
    import numpy as np

    values, status, message = _probes().adore_tribo_ehd_contact(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(rheology, float),
        float(film), float(b), int(n_gauss), int(n_strip))
    check(int(status), message)
    return dict(zip(CONTACT_TRACTION_KEYS, map(float, values)))


def film_shear_stress(u, eta_w: float, beta: float, k_f: float, h: float):
    """Shear stress (Pa) of a Newtonian film of thickness h (m) at slips u (m/s), walls at
    the temperature of the wall viscosity eta_w (Pa s); beta (1/K), K_f (W/m/K)."""
    import numpy as np

    tau, status, message = _probes().adore_tribo_film_shear(np.atleast_1d(np.asarray(u, float)), eta_w, beta,
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

    values, status, message = _probes().adore_tribo_ehd_temperature(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(rheology, float),
        float(film), float(b), int(n_gauss), int(ny), float(u1), float(u2), np.asarray(th1, float),
        np.asarray(th2, float))
    check(int(status), message)
    return float(values[0]), float(values[1])
