"""Hertz point contact and line contact by slices (fortran/contact)."""

from __future__ import annotations

from .base import _probes, check


def hertz_point(rho, e1: float, nu1: float, e2: float, nu2: float, load: float) -> dict:
    """Hertz point contact (engine module adore_contact_hertz) as a dict of SI values.

    rho: the four principal curvatures (1/m) [body 1 plane I, II, body 2 plane I, II],
    concave negative.  Keys: kappa, a_star, b_star, delta_star, semi_major (m),
    semi_minor (m), max_pressure (Pa), deflection (m), stiffness (N/m**1.5).
    """
    import numpy as np

    values, status, message = _probes().adore_hertz_point(
        np.asarray(rho, dtype=float), e1, nu1, e2, nu2, load)
    check(int(status), message)
    keys = ["kappa", "a_star", "b_star", "delta_star", "semi_major", "semi_minor",
            "max_pressure", "deflection", "stiffness"]
    return dict(zip(keys, (float(v) for v in values)))


LINE_CONTACT_RESULT = ["in_contact", "x1", "x2", "half_length", "load", "moment", "max_deflection",
                       "mean_half_width", "stress", "peak_pressure", "k0", "k_line"]


def line_contact(profile, race_crown: float, h, lim, e_star: float, r_eq: float, *, l_ref: float = 0.0,
                 k_line: float = 0.0, n_sub: int = 3) -> tuple[dict, dict]:
    """One roller/race line contact by slices (SI).

    profile: [length, land, crown radius, corner radius -x, corner radius +x] (m);
    h: [approach (m), tilt (rad), curvature (1/m)] of delta(x); lim: permissible ends (m);
    l_ref > 0: slice stiffness from Palmgren at reference length l_ref, else k_line.
    Returns (slices: x, weight, delta, q, b arrays; totals: LINE_CONTACT_RESULT).
    """
    import numpy as np

    nmax = 4 * int(n_sub)
    n, slices, result, status, message = _probes().adore_line_contact(
        np.asarray(profile, dtype=float), float(race_crown), np.asarray(h, dtype=float),
        np.asarray(lim, dtype=float), float(e_star), float(r_eq), float(l_ref), float(k_line),
        int(n_sub), nmax)
    check(int(status), message)
    cols = {name: slices[: int(n), k].copy() for k, name in enumerate(["x", "weight", "delta", "q", "b"])}
    return cols, {name: float(v) for name, v in zip(LINE_CONTACT_RESULT, result)}
