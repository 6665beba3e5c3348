"""The fast EHD contact traction (adore_tribology_ehd_traction's ehd_contact_traction_fast,
issue #16) against the reference quadrature (16 Gauss points per slip zone x 24 across each
strip, the step-0 print's): force, its moments about the ball centre (force_cos,
force_sin) and loss of every race contact of the Appendix C step 0, and of those contacts
with their slide/roll and spin/roll ratios and loads scaled.  The fast traction takes the
across-strip integral from a compile-time table (fortran/tribology/ehd_strip_table.f90,
written by tools/ehd_strip_table.py); that table is also checked against the Gauss rule
across the strip, with the film's constants and the contacts' pressures varied so that
it is used beyond its range (its fallbacks).

Errors of the force and its moments are relative to the contact's gross traction (a
contact's net traction is a difference of opposing tractions and can be near zero): the
lower bound power / max slip of the integral of |traction| is used.  The Appendix D roller
deck has no ball/race EHD contact (its line contacts use the deck's traction curve by
slices), so only Appendix C's contacts enter.  Speed is in bench/run_bench.py, not here.
"""

from __future__ import annotations

import itertools
import math
import re
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from pyadore import _core

ROOT = Path(__file__).resolve().parents[1]
D_BALL = 0.01905
INNER_SPEED = 20000 * math.pi / 30


@lru_cache(maxsize=1)
def _contacts():
    """Every race contact of the Appendix C step 0 (outer and inner of each ball) as the
    arguments of ehd_contact_method: the run's speeds, loads, ellipses and films."""
    b, _ = _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")
    lub = _core.lubricant(1, 323.0)
    rheo = (lub["eta_t"], lub["alpha_t"], lub["beta_t"], lub["conductivity"])
    out = []
    for k in range(len(b["r"])):
        om = (b["spin_speed"][k] * math.cos(b["pitch"][k]), b["spin_speed"][k] * math.sin(b["pitch"][k]))
        for tag, side, w_race in (("o", 1, 0.0), ("i", -1, INNER_SPEED)):
            out.append(dict(side=side, alpha=b[f"alpha_{tag}"][k], rho=D_BALL / 2, r_b=b["r"][k], omega=om,
                            race_speed=w_race - b["orbital_speed"][k], a=b[f"a_{tag}"][k], load=b[f"q_{tag}"][k],
                            rheology=rheo, film=b[f"film_{tag}"][k] * b[f"thermal_factor_{tag}"][k],
                            b=b[f"b_{tag}"][k]))
    return out


def _scaled(c, k_slide, k_spin, k_load):
    """Contact c with its centre slip and spin scaled by k_slide, k_spin (the ball's angular
    velocity solved from the two linear conditions) and its load by k_load (Hertz: both
    semi-axes ~ load**(1/3); the film kept)."""
    c = dict(c)
    nx, nr = c["side"] * math.sin(c["alpha"]), c["side"] * math.cos(c["alpha"])
    rho, ws = c["rho"], c["race_speed"]
    m = np.array([[rho * nr, -rho * nx], [nx, nr]])      # (centre slip, spin) = m omega + m0
    m0 = np.array([-ws * (c["r_b"] + rho * nr), -ws * nx])
    slip, spin = m @ np.asarray(c["omega"]) + m0
    c["omega"] = tuple(np.linalg.solve(m, np.array([k_slide * slip, k_spin * spin]) - m0))
    f = k_load ** (1 / 3)
    c.update(load=c["load"] * k_load, a=c["a"] * f, b=c["b"] * f)
    return c


def _error(f, r):
    """Largest relative error of f against r: force and its moments against the gross
    traction (module docstring), loss against itself."""
    gross = r["power"] / r["max_slip"]
    return max(abs(f["force"] - r["force"]) / max(abs(r["force"]), gross),
               abs(f["force_cos"] - r["force_cos"]) / max(abs(r["force_cos"]), gross),
               abs(f["force_sin"] - r["force_sin"]) / max(abs(r["force_sin"]), gross * 0.1),
               abs(f["power"] / r["power"] - 1))


def test_fast_ehd_traction_at_the_appendix_c_contacts_is_the_reference_within_1e_4():
    """All 36 race contacts of the Appendix C step 0: the fast traction's default orders
    against the print's 16 x 24 quadrature (measured: 1.3e-5)."""
    errors = [_error(_core.ehd_contact_method(**c, method="fast"),
                     _core.ehd_contact_method(**c, method="reference", n_major=16, n_strip=24))
              for c in _contacts()]
    assert max(errors) <= 1e-4


def test_fast_ehd_traction_over_scaled_slips_and_loads():
    """Slide/roll and spin/roll x 0.5 .. x 2 and loads x 0.5 .. x 2 on every contact: the
    fast traction's default orders against the 16 x 24 reference within the issue's 1e-4
    (measured 2.8e-5, which is the reference's own error there: the fast traction is 1.0e-5
    from the converged quadrature)."""
    worst = 0.0
    for c, k in itertools.product(_contacts(), itertools.product([0.5, 1, 2], [0.5, 1, 2], [0.5, 2])):
        cs = _scaled(c, *k)
        worst = max(worst, _error(_core.ehd_contact_method(**cs, method="fast"),
                                  _core.ehd_contact_method(**cs, method="reference", n_major=16, n_strip=24)))
    assert worst <= 1e-4, worst


def test_fast_ehd_traction_converges_to_the_reference_quadratures_limit():
    """Slips x 0.1 .. x 10 and loads x 0.1 .. x 3: with 24 x 12 points the fast traction is
    within 3e-5 of the reference quadrature converged (128 x 128 points), where the print's
    16 x 24 is itself up to 1.2e-3 off (the film's shear saturates in thin layers at the
    pure-rolling points, which the fast rule grades and the reference does not)."""
    worst_fast, worst_ref = 0.0, 0.0
    for c, k in itertools.product(_contacts()[::5], itertools.product([0.1, 1, 10], [0.1, 1, 10], [0.1, 3])):
        cs = _scaled(c, *k)
        conv = _core.ehd_contact_method(**cs, method="reference", n_major=128, n_strip=128)
        worst_fast = max(worst_fast, _error(_core.ehd_contact_method(**cs, method="fast", n_major=24, n_strip=12),
                                            conv))
        worst_ref = max(worst_ref, _error(_core.ehd_contact_method(**cs, method="reference", n_major=16,
                                                                   n_strip=24), conv))
    assert worst_fast <= 3e-5
    assert worst_ref > 10 * worst_fast


def _strip_table_error():
    """The table's measured error bound of the strip integral (STRIP_ERROR, relative),
    as written into the generated Fortran file by tools/ehd_strip_table.py."""
    text = (ROOT / "fortran" / "tribology" / "ehd_strip_table.f90").read_text()
    return float(re.search(r"STRIP_ERROR = ([0-9.eE+-]+)_wp", text).group(1))


def _with_rheology(c, eta=1.0, alpha=1.0, beta=1.0):
    """Contact c with its film's viscosity, pressure and temperature coefficients scaled."""
    r = c["rheology"]
    return dict(c, rheology=(r[0] * eta, r[1] * alpha, r[2] * beta, r[3]))


def test_strip_table_is_the_gauss_rule_across_the_strip():
    """The fast traction's default (the strip integral from the table) against the same
    major-axis nodes with 48 Gauss points across each strip, over slips x 0.1 .. x 10 and
    loads x 0.1 .. x 3: the loss (a sum of positive strip integrals) within the table's
    error bound STRIP_ERROR (2.1e-6; measured 1.25e-6), force and moments within 1e-5
    (measured 2.9e-6; the moment's error is relative to a tenth of a lower bound of the
    gross traction).  Also beyond the table: the isothermal film (its integral of E**2 is
    the table at Z -> 0), the pressure coefficient x 3 (A = alpha p / 2 up to 17, past the
    table's 12: Gauss on psi) and the viscosity x 1e8 (zeta |u| past the table: the large-Z
    asymptote)."""
    bound = _strip_table_error()
    base = [_scaled(c, *k) for c, k in itertools.product(_contacts()[::3], itertools.product([0.1, 1, 10], [0.1, 1, 10],
                                                                                              [0.1, 1, 3]))]
    for label, cases in [("thermal", base),
                         ("isothermal", [_with_rheology(c, beta=0.0) for c in base]),
                         ("alpha x 3", [_with_rheology(c, alpha=3.0) for c in base]),
                         ("viscosity x 1e8", [_with_rheology(c, eta=1e8) for c in base])]:
        worst, worst_power = 0.0, 0.0
        for cs in cases:
            f = _core.ehd_contact_method(**cs, method="fast")
            r = _core.ehd_contact_method(**cs, method="fast", n_major=16, n_strip=48)
            worst = max(worst, _error(f, r))
            worst_power = max(worst_power, abs(f["power"] / r["power"] - 1))
        assert worst_power <= bound, (label, worst_power)
        assert worst <= 1e-5, (label, worst)


def test_fast_ehd_traction_rejects_bad_input():
    c = dict(_contacts()[0], film=-1.0)
    with pytest.raises(Exception, match="film h > 0"):
        _core.ehd_contact_method(**c, method="fast")
    with pytest.raises(ValueError, match="method"):
        _core.ehd_contact_method(**_contacts()[0], method="quick")


# ---- the two-dimensional traction (report eq 5): the slip across the rolling direction
# u_m(psi) = m1 + m2 cos psi + m3 sin psi joins the rolling slip at every node; its fast
# quadrature is the one-dimensional fast rule at the slip vector's length (the force
# assembly's `two_d`, docs/dynamics.md)

CROSS_SHAPE = np.array([1.0, 0.3, -0.2])          # m1 : m2 : m3 of the transverse slip


def _error_2d(f, r):
    """_error with the traction across the rolling direction and its moments (the sin
    moment against a tenth of the gross traction, as along it)."""
    gross = r["power"] / r["max_slip"]
    cross = max(abs(f["cross_force"] - r["cross_force"]) / max(abs(r["cross_force"]), gross),
                abs(f["cross_force_cos"] - r["cross_force_cos"]) / max(abs(r["cross_force_cos"]), gross),
                abs(f["cross_force_sin"] - r["cross_force_sin"]) / max(abs(r["cross_force_sin"]), gross * 0.1))
    return max(_error(f, r), cross)


def _transverse(c, k):
    """Transverse slip coefficients k times the contact's largest rolling slip (m/s)."""
    u = _core.ehd_contact_method(**c, method="reference", n_major=16, n_strip=24)["max_slip"]
    return k * u * CROSS_SHAPE


def test_fast_2d_traction_at_the_appendix_c_contacts_is_the_reference_within_1e_4():
    """All 36 race contacts of the Appendix C step 0 with transverse slips of 0, 1e-3 .. 10
    times their largest rolling slip (both signs): the fast two-dimensional traction
    against the print's 16 x 24 quadrature at every node, all six sums and the loss
    (the 1-D fast traction's 1e-4; measured 3.9e-5, the reference's own error: the fast
    traction is 3.7e-6 from the converged quadrature there)."""
    worst = 0.0
    for c, k in itertools.product(_contacts(), [0.0, 1e-3, -1e-2, 0.1, -1.0, 10.0]):
        m = _transverse(c, k)
        worst = max(worst, _error_2d(_core.ehd_contact_method(**c, method="fast", transverse=m),
                                     _core.ehd_contact_method(**c, method="reference", n_major=16, n_strip=24,
                                                              transverse=m)))
    assert worst <= 1e-4, worst


def test_fast_2d_traction_converges_to_the_reference_quadratures_limit():
    """Slips x 0.1 .. x 10, loads x 0.1 .. x 3 and transverse slips 0 .. 3 times the rolling
    slip: with 24 x 12 points the fast two-dimensional traction is within 3e-5 of the
    reference quadrature converged (128 x 128 points), as the one-dimensional one (measured
    1.2e-5; the print's 16 x 24 is up to 1.2e-3 off there)."""
    worst = 0.0
    for c, k, kt in itertools.product(_contacts()[::9], itertools.product([0.1, 1, 10], [0.1, 10], [0.1, 3]),
                                      [0.0, 0.03, 3.0]):
        cs = _scaled(c, *k)
        m = _transverse(cs, kt)
        conv = _core.ehd_contact_method(**cs, method="reference", n_major=128, n_strip=128, transverse=m)
        worst = max(worst, _error_2d(_core.ehd_contact_method(**cs, method="fast", n_major=24, n_strip=12,
                                                              transverse=m), conv))
    assert worst <= 3e-5, worst


def test_2d_traction_without_transverse_slip_is_the_1d_traction():
    """With u_m = 0 the slip vector is the rolling slip: the two-dimensional fast traction
    gives the one-dimensional one (to round-off) and no traction across."""
    for c in _contacts()[::4]:
        one = _core.ehd_contact_method(**c, method="fast")
        two = _core.ehd_contact_method(**c, method="fast", transverse=[0.0, 0.0, 0.0])
        for key in ("force", "force_cos", "force_sin", "power", "sliding"):
            assert two[key] == pytest.approx(one[key], rel=1e-13, abs=1e-13 * one["power"] / one["max_slip"])
        assert two["cross_force"] == 0.0
