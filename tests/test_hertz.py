"""Hertz point contact (fortran/contact/hertz.f90) against independent truth and the report."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pyadore import AdoreInputError

from probes import hertz_point

STEEL = (2.0e11, 0.25)


def _elliptic_by_quadrature(m: float) -> tuple[float, float]:
    """K(m), E(m) by composite Gauss–Legendre quadrature (independent of the engine's AGM)."""
    x, w = np.polynomial.legendre.leggauss(40)
    edges = np.linspace(0.0, math.pi / 2, 401)
    k = e = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        theta = 0.5 * (hi - lo) * x + 0.5 * (hi + lo)
        root = np.sqrt(1.0 - m * np.sin(theta) ** 2)
        k += 0.5 * (hi - lo) * np.sum(w / root)
        e += 0.5 * (hi - lo) * np.sum(w * root)
    return k, e


def _ball_race_curvatures(ball_dia, pitch_dia, conformity, angle_deg, race):
    """Principal curvatures (1/m) of a ball on a race groove (Harris & Kotzalas, Table 2.1)."""
    gamma = ball_dia * math.cos(math.radians(angle_deg)) / pitch_dia
    if race == "outer":
        return [2 / ball_dia, 2 / ball_dia, -2 / ball_dia * gamma / (1 + gamma), -1 / (conformity * ball_dia)]
    return [2 / ball_dia, 2 / ball_dia, 2 / ball_dia * gamma / (1 - gamma), -1 / (conformity * ball_dia)]


@pytest.mark.parametrize("ratio", [1.5, 2.0, 5.0, 10.0, 30.0, 100.0, 1000.0])
def test_ellipse_against_exact_elliptic_integrals(ratio):
    """Body 1 with radii Rx = 0.01 m, Ry = ratio*Rx on a flat: the engine's ellipse must
    satisfy the Hertz equations with independently integrated K and E to <= 1e-4."""
    rx = 0.01
    rho = [1 / rx, 1 / (ratio * rx), 0.0, 0.0]
    load = 1000.0
    r = hertz_point(rho, *STEEL, *STEEL, load)
    kappa = r["kappa"]
    k, e = _elliptic_by_quadrature(1 - 1 / kappa**2)
    f_rho = (rho[0] - rho[1]) / sum(rho)
    f_kappa = ((kappa**2 + 1) * e - 2 * k) / ((kappa**2 - 1) * e)
    assert f_kappa == pytest.approx(f_rho, rel=1e-4)
    a_star = (2 * kappa**2 * e / math.pi) ** (1 / 3)
    b_star = (2 * e / (math.pi * kappa)) ** (1 / 3)
    delta_star = 2 * k / math.pi * (math.pi / (2 * kappa**2 * e)) ** (1 / 3)
    scale = (1.5 * load * 2 * (1 - 0.25**2) / 2.0e11 / sum(rho)) ** (1 / 3)
    assert r["semi_major"] == pytest.approx(a_star * scale, rel=1e-4)
    assert r["semi_minor"] == pytest.approx(b_star * scale, rel=1e-4)
    assert r["deflection"] == pytest.approx(delta_star * scale**2 * sum(rho) / 2, rel=1e-4)
    assert r["max_pressure"] == pytest.approx(1.5 * load / (math.pi * r["semi_major"] * r["semi_minor"]), rel=1e-12)


def test_sphere_on_flat_is_the_closed_form_circle():
    """Sphere R on a flat: a = b = (3 Q R / (4 E*))**(1/3), delta = a**2 / R (Johnson, Contact Mechanics 4.2)."""
    radius, load = 0.01, 500.0
    e_star = 1 / (2 * (1 - 0.25**2) / 2.0e11)
    r = hertz_point([1 / radius, 1 / radius, 0.0, 0.0], *STEEL, *STEEL, load)
    a = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    assert r["kappa"] == pytest.approx(1.0, abs=1e-12)
    assert r["semi_major"] == pytest.approx(a, rel=1e-10)
    assert r["semi_minor"] == pytest.approx(a, rel=1e-10)
    assert r["deflection"] == pytest.approx(a**2 / radius, rel=1e-10)
    assert r["max_pressure"] == pytest.approx(3 * load / (2 * math.pi * a**2), rel=1e-10)


def test_load_deflection_law_is_consistent():
    rho = _ball_race_curvatures(19.05e-3, 0.14, 0.52, 20.0, "outer")
    for load in (10.0, 1000.0, 1.0e5):
        r = hertz_point(rho, *STEEL, *STEEL, load)
        assert r["stiffness"] * r["deflection"] ** 1.5 == pytest.approx(load, rel=1e-12)


def test_dissimilar_materials_use_the_combined_compliance():
    """Ceramic on steel equals steel on steel with the same combined (1-nu**2)/E."""
    rho = _ball_race_curvatures(19.05e-3, 0.14, 0.54, 25.0, "inner")
    ceramic = (3.1e11, 0.26)
    mixed = hertz_point(rho, *ceramic, *STEEL, 800.0)
    compliance = (1 - 0.26**2) / 3.1e11 + (1 - 0.25**2) / 2.0e11
    # body 1 carries the whole compliance (nu = 0), body 2 is rigid
    equivalent = hertz_point(rho, 1 / compliance, 0.0, 1e300, 0.0, 800.0)
    assert mixed["semi_major"] == pytest.approx(equivalent["semi_major"], rel=1e-12)
    assert mixed["deflection"] == pytest.approx(equivalent["deflection"], rel=1e-12)


# Report Appendix C, step 0 (section 1): contact angle (deg), load (N) as printed, and
# the printed major/minor half widths (m) and stresses (Pa) that Hertz must reproduce.
REPORT_STEP0 = [
    # ball, race, angle, load, a, b, stress
    (2, "outer", 8.334, 2.457e3, 2.367e-3, 3.142e-4, 1.577e9),
    (2, "inner", 27.53, 7.704e2, 1.249e-3, 2.123e-4, 1.386e9),
    (10, "outer", 4.014, 2.127e3, 2.256e-3, 2.996e-4, 1.503e9),
    (10, "inner", 30.24, 2.955e2, 9.076e-4, 1.546e-4, 1.006e9),
]


@pytest.mark.parametrize("ball, race, angle, load, a, b, stress", REPORT_STEP0)
def test_report_half_widths_and_stresses_from_printed_loads(ball, race, angle, load, a, b, stress):
    """Appendix C geometry (D = 19.05 mm, d_m = 140 mm, f_o = 0.52, f_i = 0.54, steel):
    Hertz on the printed loads and angles reproduces the printed ellipse within 0.1 %
    (the printed values have 4 significant digits)."""
    conformity = 0.52 if race == "outer" else 0.54
    rho = _ball_race_curvatures(19.05e-3, 0.14, conformity, angle, race)
    r = hertz_point(rho, *STEEL, *STEEL, load)
    assert r["semi_major"] == pytest.approx(a, rel=1e-3)
    assert r["semi_minor"] == pytest.approx(b, rel=1e-3)
    assert r["max_pressure"] == pytest.approx(stress, rel=1e-3)


def test_non_convex_contact_is_an_input_error():
    with pytest.raises(AdoreInputError, match="convex"):
        hertz_point([-1.0, -1.0, 0.0, 0.0], *STEEL, *STEEL, 100.0)
