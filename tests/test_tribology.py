"""Step-0 tribology building blocks (engine modules adore_tribology_film / _slip / _flash):
independent checks (scaling laws, quadrature against a fine uniform sum, power against
the area integral of traction times slip) and a comparison with the report's printed
step 0 (golden/appendix_c_ball.prt) with the report's own loads, angles, half widths and
ball speeds fed in.  Issue "[Step-0 tribology]" asks 5 %; a column that misses is a
strict xfail carrying its numbers and the believed cause.
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from pyadore import AdoreInputError, _core
from pyadore.printout import read_print

import probes


ROOT = Path(__file__).resolve().parents[1]
RPM = math.pi / 30
COEF = [-1.6e-2, 3.82896e-2, 1.71782, 1.6e-2]  # Rec 10.1C fit (echo A, B, C; D = kinf = 0.016)
D_BALL, F_OUTER, F_INNER = 0.01905, 0.52, 0.54
E_PRIME = 2.0e11 / (1 - 0.25**2)               # equal steels, E' = E / (1 - nu**2)
INNER_SPEED = 20000 * RPM
THERMAL_LOADING_SCALE = 1.2321                 # fortran/tribology/film.f90 (calibrated)
STEEL = [7750.0, 470.0, 43.0]                  # echo: density, heat capacity, conductivity


def kappa(u):
    a, b, c, d = COEF
    return (a + b * u) * np.exp(-c * u) + d


# --- independent checks ----------------------------------------------------------------------

def test_film_thickness_scaling_and_formula():
    """Hamrock-Dowson central film, h/R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^-0.73k),
    recomputed here; exponents checked by scaling."""
    rx, k, u, q, eta, alpha = 0.0108, 7.5, 75.0, 2457.0, 0.008, 1.1e-8
    h = probes.film_thickness(rx, k, u, q, E_PRIME, eta, alpha)
    ref = rx * 2.69 * (eta * u / (E_PRIME * rx)) ** 0.67 * (alpha * E_PRIME) ** 0.53 \
        * (q / (E_PRIME * rx**2)) ** -0.067 * (1 - 0.61 * math.exp(-0.73 * k))
    assert h == pytest.approx(ref, rel=1e-13)
    assert probes.film_thickness(rx, k, 2 * u, q, E_PRIME, eta, alpha) == pytest.approx(h * 2**0.67, rel=1e-13)
    with pytest.raises(AdoreInputError):
        probes.film_thickness(rx, k, u, q, E_PRIME, -eta, alpha)


def test_lubricant_library_is_the_reports_echo():
    """MIL-L-7808 as the Appendix C echo prints it (text-copy lines 3112-3113): eta at the
    reference temperature and p = 0 is the echoed 8.61565E-03 Pa s; pressure and
    temperature act as exp(alpha p + B (1/T - 1/T_ref)); beta = -d ln(eta)/dT = B/T**2."""
    lub = _core.lubricant(1, 323.0)
    assert lub["eta"] == pytest.approx(8.61565e-3, rel=1e-14)
    assert lub["alpha"] == pytest.approx(1.07562e-8, rel=1e-14)
    assert lub["density"] == pytest.approx(945.429, rel=1e-14)
    assert lub["heat_capacity"] == pytest.approx(1836.10, rel=1e-14)
    assert lub["nu"] == pytest.approx(8.61565e-3 / 945.429, rel=1e-14)
    # pressure: Barus law with the echoed alpha
    assert _core.lubricant(1, 323.0, 1.0e8)["eta"] == pytest.approx(8.61565e-3 * math.exp(1.07562), rel=1e-13)
    # beta against a central difference of ln(eta)
    h = 1e-3
    fd = -(math.log(_core.lubricant(1, 350 + h)["eta"]) - math.log(_core.lubricant(1, 350 - h)["eta"])) / (2 * h)
    assert _core.lubricant(1, 350.0)["beta"] == pytest.approx(fd, rel=1e-8)
    # the reference temperature (its leading digits are lost in the echo) is 323 K: at 40 C
    # the viscosity meets the MIL-PRF-7808 grade-3 minimum (11.5 mm**2/s), at 313 K it would not
    assert _core.lubricant(1, 313.15)["nu"] > 11.5e-6
    with pytest.raises(AdoreInputError, match="unknown lubricant code"):
        _core.lubricant(7, 323.0)
    with pytest.raises(AdoreInputError, match="temperature"):
        _core.lubricant(1, 0.0)


def _bratu_slip(tau, eta_w, beta, k_f, h, n=2000):
    """Slip u (m/s) of a film carrying shear stress tau, from the energy equation
    k T'' = -tau**2 / eta(T), eta = eta_w exp(-beta (T - T_w)), T = T_w on both walls,
    solved by Newton on a finite-difference grid (lower branch), u = int tau / eta dz."""
    z = np.linspace(0.0, h, n + 1)
    dz = z[1] - z[0]
    lam = beta * tau**2 / (k_f * eta_w)
    th = np.zeros(n + 1)
    for _ in range(50):
        inner = th[1:-1]
        res = (th[2:] - 2 * inner + th[:-2]) / dz**2 + lam * np.exp(inner)
        jac = (np.diag(np.full(n - 1, -2.0 / dz**2) + lam * np.exp(inner)) + np.diag(np.full(n - 2, 1 / dz**2), 1)
               + np.diag(np.full(n - 2, 1 / dz**2), -1))
        step = np.linalg.solve(jac, -res)
        th[1:-1] += step
        if np.max(np.abs(step)) < 1e-13:
            break
    f = np.exp(th)
    return tau / eta_w * dz * (f.sum() - 0.5 * (f[0] + f[-1]))


def test_film_shear_stress_solves_the_film_energy_equation():
    """The closed form of the EHD film shear against an independent numerical solution of
    the film's energy equation (finite differences, Newton), and its isothermal limit."""
    eta_w, beta, k_f, h = 0.5, 0.0425519, 0.1425185, 0.5e-6
    u = np.array([0.05, 0.5, 2.0, 4.0])
    tau = probes.film_shear_stress(u, eta_w, beta, k_f, h)
    for ui, ti in zip(u, tau):
        assert _bratu_slip(ti, eta_w, beta, k_f, h) == pytest.approx(ui, rel=1e-5)
    assert tau[-1] < 0.99 * eta_w * u[-1] / h                      # heating thins the film's shear
    iso = probes.film_shear_stress([1e-4, 2e-4], eta_w, beta, k_f, h)
    assert iso[0] == pytest.approx(eta_w * 1e-4 / h, rel=1e-6)
    assert probes.film_shear_stress([3.0], eta_w, 0.0, 0.0, h)[0] == pytest.approx(eta_w * 3.0 / h, rel=1e-14)
    with pytest.raises(AdoreInputError, match="film shear"):
        probes.film_shear_stress([1.0], eta_w, beta, 0.0, h)


def test_ehd_contact_isothermal_limit_is_the_viscous_integral():
    """beta = 0, alpha = 0: tau = eta |u| / h, so the heat is eta / h times the integral of
    u**2 over the ellipse area - checked against a fine uniform grid."""
    g = CONTACTS["outer"]
    eta, h, b = 0.01, 1.0e-6, 0.4e-3
    s = np.linspace(-g["a"], g["a"], 20001)
    mid = 0.5 * (s[1:] + s[:-1])
    u = np.asarray(probes.contact_slip(**{k: v for k, v in g.items() if k != "load"}, s=mid))
    width = 2 * b * np.sqrt(1 - (mid / g["a"]) ** 2)
    exact = np.sum(eta / h * u**2 * width) * (s[1] - s[0])
    err = []
    for n in (16, 64):
        t = probes.ehd_contact_traction(g["side"], g["alpha"], g["rho"], g["r_b"], g["omega"], g["race_speed"],
                                       g["a"], g["load"], (eta, 0.0, 0.0, 0.14), h, b, n_gauss=n, n_strip=24)
        err.append(abs(t["power"] / exact - 1))
    # the strip width's square root at the contact ends limits Gauss-Legendre to ~n**-3
    assert err[0] < 5e-4
    assert err[1] < err[0] / 10


def test_ehd_flash_isothermal_film_is_the_uniform_flux_closed_form():
    """beta = alpha = 0: the film's heat eta u**2 / h is uniform across each strip, and a
    uniform flux q on a strip of half width b_k raises it by 2 q sqrt(b_k (1 + y/b_k)) /
    (2 sqrt(pi rho c k U)) (eq 35); the contact average (eq 36) is then a single integral
    along the major axis, evaluated here on a fine uniform grid."""
    g = CONTACTS["inner"]
    eta, h, b, speed = 0.01, 1.0e-6, 0.4e-3, 75.0
    avg, peak = probes.ehd_temperature_rise(g["side"], g["alpha"], g["rho"], g["r_b"], g["omega"], g["race_speed"],
                                           g["a"], g["load"], (eta, 0.0, 0.0, 0.14), h, b, speed, speed,
                                           STEEL, STEEL, n_gauss=64, ny=401)
    s = np.linspace(-g["a"], g["a"], 40001)
    mid = 0.5 * (s[1:] + s[:-1])
    u = np.asarray(probes.contact_slip(**{k: v for k, v in g.items() if k != "load"}, s=mid))
    bk = b * np.sqrt(1 - (mid / g["a"]) ** 2)
    q = eta * u**2 / h
    denom = 2 * math.sqrt(math.pi * STEEL[0] * STEEL[1] * STEEL[2] * speed)
    # integral over the strip of 2 q sqrt(b_k + y) dy, y in [-b_k, b_k] = 2 q (2/3) (2 b_k)**1.5
    strip = 2 * q * (2 / 3) * (2 * bk) ** 1.5 / denom
    exact = np.sum(strip) * (s[1] - s[0]) / (math.pi * g["a"] * b)
    assert avg == pytest.approx(exact, rel=2e-4)           # measured 4e-5 (trapezoid in y, sqrt edge)
    assert peak == pytest.approx(np.max(2 * q * np.sqrt(2 * bk) / denom), rel=1e-4)


CONTACTS = {  # report-like contacts (ball 2 of Appendix C, outer and inner), orbit frame
    "outer": dict(side=1, alpha=math.radians(8.334), rho=D_BALL / 2, r_b=0.070045,
                  omega=(-7801.3, 1139.7), race_speed=-943.11, a=2.367e-3, load=2457.0),
    "inner": dict(side=-1, alpha=math.radians(27.53), rho=D_BALL / 2, r_b=0.070045,
                  omega=(-7801.3, 1139.7), race_speed=INNER_SPEED - 943.11, a=1.249e-3, load=770.4),
}


@pytest.mark.parametrize("name", list(CONTACTS))
def test_slip_integral_matches_fine_uniform_quadrature(name):
    """Zone-split Gauss (report 2.1) against a 400 000-point midpoint sum of eq (1)."""
    c = CONTACTS[name]
    t = probes.contact_traction(**c, coef=COEF, n_gauss=16)
    a, q = c["a"], c["load"]
    n = 400_000
    s = -a + (np.arange(n) + 0.5) * (2 * a / n)
    geo = {k: v for k, v in c.items() if k != "load"}
    u = probes.contact_slip(**geo, s=s)
    dq = 0.75 * q / a * (1 - (s / a) ** 2) * (2 * a / n)
    assert t["force"] == pytest.approx(np.sum(np.sign(u) * kappa(np.abs(u)) * dq), rel=1e-6, abs=1e-9 * q)
    assert t["power"] == pytest.approx(np.sum(kappa(np.abs(u)) * np.abs(u) * dq), rel=1e-7)
    assert t["sliding"] == pytest.approx(np.sum(np.abs(u) * dq), rel=1e-7)   # Archard's load x slip
    ends = probes.contact_slip(**geo, s=[-a, a])
    assert t["max_slip"] == pytest.approx(np.abs(np.r_[u, ends]).max(), rel=1e-9)
    for k in range(int(t["n_rolling"])):
        assert abs(probes.contact_slip(**geo, s=[t[f"s{k + 1}"]])[0]) < 1e-9


@pytest.mark.parametrize("name", list(CONTACTS))
def test_power_is_area_integral_of_traction_times_slip(name):
    """Power loss = integral over the ellipse of tau u dA with tau = sigma kappa(u) (eqs 1, 4, 5),
    Hertz sigma = p0 sqrt(1 - x^2/a^2 - y^2/b^2), Q = 2/3 pi a b p0; 2-D Gauss over the ellipse."""
    c = CONTACTS[name]
    t = probes.contact_traction(**c, coef=COEF, n_gauss=16)
    a, q = c["a"], c["load"]
    b = 0.13 * a
    p0 = 1.5 * q / (math.pi * a * b)
    geo = {k: v for k, v in c.items() if k != "load"}
    x, wx = np.polynomial.legendre.leggauss(4000)
    y, wy = np.polynomial.legendre.leggauss(64)
    xs = a * x
    u = probes.contact_slip(**geo, s=xs)
    half = b * np.sqrt(1 - x**2)
    sigma = p0 * np.sqrt(np.clip(1 - x[:, None] ** 2 - y[None, :] ** 2 * (1 - x[:, None] ** 2), 0, None))
    area_sigma = (sigma * wy[None, :]).sum(axis=1) * half          # integral of sigma dy per strip
    power = np.sum(wx * a * area_sigma * kappa(np.abs(u)) * np.abs(u))
    assert t["power"] == pytest.approx(power, rel=2e-4)


def test_flash_uniform_flux_closed_form():
    xi = np.linspace(-1, 1, 101)
    assert np.allclose(probes.flash_rise(xi, np.full_like(xi, 2.0)), 4 * np.sqrt(xi + 1), atol=1e-12)


# --- against the report's printed step 0 ---------------------------------------------------

@lru_cache(maxsize=1)
def _report_step0():
    """Per contact (ball 1-18 x outer/inner): the report's printed step-0 inputs and values,
    and this code's results for them.  The ball centre radius is not printed: it comes from
    the engine's own step 0 (tests/test_ball_step0_deck.py: within 1 % of the report)."""
    step = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0]
    con, mot, tra, the = (step.table(n) for n in ("re_contact", "re_motion", "re_traction", "re_thermal"))
    balls, _ = _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")
    rows = []
    for k in range(18):
        wm = mot["orbital_velocity_rpm"].iloc[k] * RPM
        amp = mot["ang_vel_amplitude_rpm"].iloc[k] * RPM
        theta = math.radians(mot["ang_vel_theta_deg"].iloc[k])
        # the print's (amplitude, theta) in the engine's orbit-frame (axial, radial) convention
        omega = (-amp * math.cos(theta), -amp * math.sin(theta))
        for side, tag, f, w_race in ((1, "outer", F_OUTER, 0.0), (-1, "inner", F_INNER, INNER_SPEED)):
            g = lambda table, col: table[f"{col}_{tag}{'_m' if col.endswith(('width', 'thickness')) else ''}"]  # noqa: E731
            row = dict(ball=k + 1, side=tag,
                       alpha=math.radians(con[f"contact_angle_{tag}_deg"].iloc[k]),
                       load=con[f"contact_load_{tag}_N"].iloc[k], p0=con[f"contact_stress_{tag}_Pa"].iloc[k],
                       a=con[f"major_half_width_{tag}_m"].iloc[k], b=con[f"minor_half_width_{tag}_m"].iloc[k],
                       film=tra[f"film_thickness_{tag}_m"].iloc[k], phi=tra[f"thermal_red_fac_{tag}"].iloc[k],
                       slip=tra[f"slip_velocity_{tag}_m_s"].iloc[k], trac=tra[f"trac_coeff_{tag}"].iloc[k],
                       spin_roll=mot[f"spin_roll_{tag}"].iloc[k], loss=mot[f"contact_loss_{tag}_W"].iloc[k],
                       rise=the[f"contact_temp_rise_{tag}_K"].iloc[k])
            del g
            inputs = [row["alpha"], row["load"], row["a"], amp, theta, wm]
            if any(math.isnan(v) for v in inputs):
                rows.append(row)
                continue
            t = probes.contact_traction(side, row["alpha"], D_BALL / 2, balls["r"][k], omega, w_race - wm, row["a"],
                                       row["load"], COEF, n_gauss=16)
            row["calc"] = t
            row["calc4"] = probes.contact_traction(side, row["alpha"], D_BALL / 2, balls["r"][k], omega, w_race - wm,
                                                  row["a"], row["load"], COEF, n_gauss=4)
            row["geo"] = dict(side=side, r_b=balls["r"][k], omega=omega, race_speed=w_race - wm)
            rx = t["rx"]
            ry = 1 / (2 / D_BALL - 1 / (f * D_BALL))
            row["rx"], row["ry"], row["u"] = rx, ry, abs(t["rolling_speed"])
            rows.append(row)
    return rows


def _usable(rows, *keys):
    return [r for r in rows if "calc" in r and not any(math.isnan(r[k]) for k in keys)]


def _film_unit(r):
    """Central film for eta0 = 1 Pa s and alpha = 1/Pa: h = this * eta0^0.67 alpha^0.53."""
    k = r["a"] / r["b"]
    return probes.film_thickness(r["rx"], k, r["u"], r["load"], E_PRIME, 1.0, 1.0)


def _calibration_row(rows):
    return next(r for r in rows if r["ball"] == 10 and r["side"] == "outer")


def _film_errors():
    """No calibration: the echo's eta0 and alpha (MIL-L-7808 at the deck's 323 K) on every
    contact with the report's own loads, half widths and speeds."""
    lub = _core.lubricant(1, 323.0)
    scale = lub["eta"] ** 0.67 * lub["alpha"] ** 0.53
    return [(r, scale * _film_unit(r), r["film"]) for r in _usable(_report_step0(), "film", "b")]


def _loading(r, p, phi):
    lo, hi = 1e-6, 1e4
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if probes.thermal_reduction_factor(p, E_PRIME, [mid], 0.0)[0] > phi:
            lo = mid
        else:
            hi = mid
    return mid


def _thermal_errors():
    """L = scale eta0 beta u**2 / K_f with the echo's eta0 and beta = B/T**2 (323 K), the
    library's K_f and the engine's thermal-loading scale, calibrated on ball 10's outer
    contact: that contact is left out, the other 29 test the form.  The slide-to-roll
    ratio is this code's centre slip over the entraining speed."""
    lub = _core.lubricant(1, 323.0)
    out = []
    for r in _usable(_report_step0(), "phi", "p0"):
        if r is _calibration_row(_report_step0()):
            continue
        s = r["calc"]["centre_slip"] / r["calc"]["rolling_speed"]
        load = THERMAL_LOADING_SCALE * lub["eta"] * lub["beta"] * r["u"] ** 2 / lub["conductivity"]
        out.append((r, probes.thermal_reduction_factor(r["p0"], E_PRIME, [load], s)[0], r["phi"]))
    return out


def test_thermal_loading_scale_is_the_calibration_contacts_value():
    """The engine's thermal-loading scale is the value that reproduces ball 10's outer
    thermal factor with the library's K_f (to the 5 digits kept) - the calibration, stated
    as a test so a change is seen; with scale 1 the printed factors miss by ~9.5 %."""
    lub = _core.lubricant(1, 323.0)
    c = _calibration_row(_report_step0())
    needed = _loading(c, c["p0"], c["phi"]) / (lub["eta"] * lub["beta"] * c["u"] ** 2 / lub["conductivity"])
    assert THERMAL_LOADING_SCALE == pytest.approx(needed, rel=5e-4)


def _ehd(r, n_gauss):
    """EHD traction (model 3) of one printed contact: the report's own speeds, load, half
    widths, film x thermal reduction factor; MIL-L-7808's traction rheology at 323 K."""
    lub = _core.lubricant(1, 323.0)
    g = r["geo"]
    return probes.ehd_contact_traction(g["side"], r["alpha"], D_BALL / 2, g["r_b"], g["omega"], g["race_speed"],
                                      r["a"], r["load"], (lub["eta_t"], lub["alpha_t"], lub["beta_t"],
                                                          lub["conductivity"]),
                                      r["film"] * r["phi"], r["b"], n_gauss=n_gauss)


def _ehd_errors(key, ref, n_gauss):
    return lambda: [(r, _ehd(r, n_gauss)[key], r[ref])
                    for r in _usable(_report_step0(), ref, "b", "film", "phi")]


def _simple(key, ref, transform=lambda v: v):
    return lambda: [(r, transform(r["calc"][key]), r[ref]) for r in _usable(_report_step0(), ref)]


def _temperature_errors():
    """Eqs 28-53 isolated: the heat is the report's own contact loss, spread as a constant
    kappa u_s over the Hertz pressure (eq 29), surfaces moving at the entraining speed."""
    out = []
    xk, wk = np.polynomial.legendre.leggauss(24)
    for r in _usable(_report_step0(), "rise", "loss", "b", "p0"):
        g = r["loss"] / r["load"]
        avg, _ = probes.contact_temperature_rise(r["a"], r["b"], r["p0"], r["a"] * xk, r["a"] * wk,
                                                np.full(24, g), r["u"], r["u"], STEEL, STEEL, ny=201)
        out.append((r, avg, r["rise"]))
    return out


SLIP_CAUSE = ("the slip along the major axis is dominated by the curvature (Heathcote) term "
              "rho w_roll (1 - cos(s/rho)), ~2 m/s at the ends, and by a centre slip that is the "
              "difference of two ~75 m/s surface speeds; both depend on where ADORE puts the contact "
              "points (ball radius here; the deformed surface, deflection or groove radius in ADORE is "
              "unknown) and on the 4-digit printed speeds (0.01 % of 75 m/s = 0.0075 m/s)")
COLUMNS = {  # column: (errors function, xfail reason or None)
    "iso_lub_film": (_film_errors, None),
    "thermal_red_fac": (_thermal_errors, None),
    "spin_roll": (_simple("spin_roll", "spin_roll"), None),
    # the printed slip velocity is the largest |u| at the nodes of the 4-point Gauss rule
    # per slip zone (worst 0.6 %); the largest |u| on the major axis misses by 12 %
    "slip_velocity": (lambda: [(r, r["calc4"]["node_slip"], r["slip"]) for r in _usable(_report_step0(), "slip")],
                      None),
    "slip_velocity_axis_max": (_simple("max_slip", "slip"),
                               "largest |u| on the whole major axis: worst 12.2 % (ball 10 outer 1.819 vs "
                               "1.622 m/s), inner 9.0 % (ball 2 4.591 vs 4.212): not the printed quantity"),
    "trac_coeff": (_simple("coefficient", "trac", abs),
                   "net traction / load: worst 99 % (ball 2 inner 1.2e-4 vs 1.253e-2), outer 57 %.  The "
                   "report's own speeds roll at the inner contact centre (rolling radius D/2 within 2e-6 m) "
                   "with spin-dominated, nearly antisymmetric slip (+3.0 .. -4.2 m/s at the nodes), so any "
                   "kappa(|u|) gives a net rolling traction near zero, yet 0.0087-0.0127 is printed: the "
                   "printed coefficient is not eq (1)'s net rolling traction over the load (definition "
                   "not identified; mean |kappa| is 0.0169 for every ball, also not it)"),
    "contact_loss": (_simple("power", "loss"),
                     "integral of kappa |u| dQ: worst 38 % (ball 10 inner 7.62 vs 5.51 W), outer 23 % "
                     "(ball 2 13.96 vs 18.03 W).  Report loss / load at the inner contact grows 2.1x from "
                     "ball 10 to ball 2 while the slips at the Gauss nodes agree within 8 %: ADORE's 'EHD' "
                     "traction (report Table 5) depends on more than the slip (load, pressure or film); "
                     "two-dimensional slip (eq 5) adds only 4 %, a rescaled slip unit fits no two contacts"),
    # ADORE's traction model 3 (EHD film, adore_tribology_ehd_traction), nothing fitted:
    # the printed coefficient is the local one at the node of the printed slip (4 points)
    "ehd_trac_coeff": (_ehd_errors("node_coefficient", "trac", 4), None),
    "ehd_contact_loss": (_ehd_errors("power", "loss", 16), None),
    "contact_temp_rise": (_temperature_errors,
                          "eqs 35-36 with the report's own loss as a constant kappa u_s: worst 7.7 % high "
                          "(ball 2 inner 2.548 vs 2.365 K), outer 5.7 % (ball 7 0.4386 vs 0.4148 K); "
                          "ADORE's heat flux follows its kappa(u(x)) |u(x)| across the strips (more heat "
                          "at the low-pressure ends), and its surface speeds U1, U2 and grid are unknown"),
}


def _worst(errors):
    worst = max(errors, key=lambda e: abs(e[1] / e[2] - 1))
    r, calc, ref = worst
    return abs(calc / ref - 1), f"ball {r['ball']} {r['side']}: {calc:.4g} vs report {ref:.4g}"


@pytest.mark.parametrize("column", [
    pytest.param(c, marks=pytest.mark.xfail(strict=True, reason=why)) if why else c
    for c, (_, why) in COLUMNS.items()])
def test_step0_tribology_column_matches_report(column):
    errors_fn, _ = COLUMNS[column]
    errors = errors_fn()
    assert len(errors) >= 20
    for side in ("outer", "inner"):
        sub = [e for e in errors if e[0]["side"] == side]
        worst, where = _worst(sub)
        print(f"{column} {side}: worst {100 * worst:.2f} % ({where}), {len(sub)} contacts")
    worst, where = _worst(errors)
    assert worst <= 0.05, f"{column}: worst {100 * worst:.2f} % at {where}"


def test_ball_wear_is_archard_over_both_race_contacts_with_the_reports_speeds():
    """Printed 'Time Ave Wear Rate' of each ball over the load x slip (integral of |u| dQ)
    of its two race contacts, computed from the report's own speeds, loads and half widths:
    one constant for all complete rows (a different form would vary with spin/roll, which
    changes 2.4x from ball 2 to ball 10), and that constant is the ball's k / H with ADORE's
    hardness H = 10 RC kgf/mm**2 (fortran/tribology/wear.f90)."""
    step = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0]
    printed = step.table("re_motion")["wear_rate_m3_s"]
    by_ball = {}
    for r in _usable(_report_step0()):
        g = r["geo"]
        ehd = probes.ehd_contact_traction(g["side"], r["alpha"], D_BALL / 2, g["r_b"], g["omega"], g["race_speed"],
                                         r["a"], r["load"], (1e-2, 0.0, 0.0, 0.1), 1e-6, 0.1 * r["a"])
        by_ball.setdefault(r["ball"], []).append(ehd["sliding"])
    ratios = [printed.iloc[k - 1] / sum(s) for k, s in by_ball.items()
              if len(s) == 2 and not math.isnan(printed.iloc[k - 1])]
    assert len(ratios) >= 14
    hardness, (k_over_h,) = probes.wear_rate(5e-6, 61.0, [1.0])
    assert hardness == pytest.approx(61 * 9.80665e7)
    assert max(ratios) / min(ratios) - 1 < 0.006          # one constant (spread 0.5 %)
    assert np.mean(ratios) == pytest.approx(k_over_h, rel=0.01)   # 0.5 % below k / H


def test_flat_wrappers_refuse_bad_input_with_a_message():
    """Bad geometry gives AdoreInputError, never NaN (the wrappers return a status)."""
    from pyadore import AdoreInputError

    geo = {k: v for k, v in CONTACTS["outer"].items() if k != "load"}
    geo["a"] = 0.0
    with pytest.raises(AdoreInputError, match="half width"):
        probes.contact_slip(**geo, s=[0.0])
    with pytest.raises(AdoreInputError, match="increase strictly"):
        probes.flash_rise([0.0, 0.0, 1.0], [1.0, 1.0, 1.0])
    with pytest.raises(AdoreInputError, match="p_h > 0"):
        probes.thermal_reduction_factor(0.0, 2.2e11, [1.0], 0.1)


def _pitch_of_least_power(o, i, orbital_speed, lo, hi):
    """Pitch (deg) minimising the EHD power of one ball's two printed contacts at the given
    orbital speed (rad/s), the spin speed set by rolling at the inner contact centre (ball
    radius D/2; the engine's kinematic condition): golden section on [lo, hi] deg."""
    lub = _core.lubricant(1, 323.0)
    rheology = (lub["eta_t"], lub["alpha_t"], lub["beta_t"], lub["conductivity"])
    r_b = o["geo"]["r_b"]
    n_i = (-math.sin(i["alpha"]), -math.cos(i["alpha"]))

    def power(theta_deg):
        beta = math.radians(theta_deg)
        # rolling at the inner centre: w_b D/2 (cos b n_r - sin b n_x) = (w_i - w_m) (r_b + D/2 n_r)
        w_b = ((INNER_SPEED - orbital_speed) * (r_b + D_BALL / 2 * n_i[1])
               / (D_BALL / 2 * (math.cos(beta) * n_i[1] - math.sin(beta) * n_i[0])))
        total = 0.0
        for r, race_speed in ((o, -orbital_speed), (i, INNER_SPEED - orbital_speed)):
            total += probes.ehd_contact_traction(
                r["geo"]["side"], r["alpha"], D_BALL / 2, r_b, (w_b * math.cos(beta), w_b * math.sin(beta)),
                race_speed, r["a"], r["load"], rheology, r["film"] * r["phi"], r["b"], n_gauss=8,
                n_strip=12)["power"]
        return total

    g = (math.sqrt(5) - 1) / 2
    x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
    f1, f2 = power(x1), power(x2)
    while hi - lo > 0.005:
        if f1 <= f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - g * (hi - lo)
            f1 = power(x1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + g * (hi - lo)
            f2 = power(x2)
    return 0.5 * (lo + hi)


def test_report_pitch_is_the_least_ehd_power_at_the_reports_orbital_speed():
    """Report 4.4.7 determines the *orientation* of the ball's angular velocity by minimum
    contact dissipation.  Given the report's own orbital speed, loads, angles, half widths and
    films, the pitch that minimises the EHD power of the two contacts (spin speed from rolling
    at the inner contact centre) is the printed pitch within 0.15 deg for every ball whose
    inputs are all printed - on both sides of the printed jump between balls 7 and 8 (-5.085
    -> -3.612 deg).  The engine's own start, which also chooses the orbital speed by minimum
    power, misses the pitch by up to 0.55 deg; a shift of the orbital speed by 0.1 % moves
    this minimum by ~0.22 deg (docs/tribology.md, "What sets the report's orbital speed")."""
    rows = _usable(_report_step0(), "b", "film", "phi")
    balls = sorted({r["ball"] for r in rows if r["side"] == "outer"} & {r["ball"] for r in rows if r["side"] == "inner"})
    assert {7, 9, 10} <= set(balls) and len(balls) >= 10
    step = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0]
    mot = step.table("re_motion")
    worst = 0.0
    for k in sorted(set(balls) & set(range(1, 11))):       # balls 11-18 mirror 1-9
        o, i = (next(r for r in rows if r["ball"] == k and r["side"] == s) for s in ("outer", "inner"))
        printed = mot["ang_vel_theta_deg"].iloc[k - 1]
        w_m = mot["orbital_velocity_rpm"].iloc[k - 1] * RPM
        found = _pitch_of_least_power(o, i, w_m, printed - 1.5, printed + 1.5)
        print(f"ball {k}: least power at {found:.3f} deg, printed {printed:.3f} deg")
        worst = max(worst, abs(found - printed))
        assert abs(found - printed) <= 0.15, (k, found, printed)
    print(f"worst {worst:.3f} deg")


def test_report_orbital_speed_is_a_multiple_of_outer_race_control():
    """The engine's outer-race-control orbital speed (report 4.4.7's race-control option),
    evaluated on the report's printed contact angles, against the printed orbital speed: balls
    8-12 agree within 0.03 %, and balls 1-7 and 13-18 are one constant 0.44 % below it (spread
    0.04 %).  Evidence that ADORE's minimum-dissipation start chooses the orbital speed from
    a discrete set anchored at race control (docs/tribology.md); the engine does not
    implement that set, because its step is not given in the report."""
    step = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0]
    con, mot = step.table("re_contact"), step.table("re_motion")
    balls, _ = _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")
    ratios = {}
    for k in range(18):
        a_o, a_i = (math.radians(con[f"contact_angle_{s}_deg"].iloc[k]) for s in ("outer", "inner"))
        if math.isnan(a_o) or math.isnan(a_i):
            continue
        w_m, _, _ = probes.race_control(D_BALL, balls["r"][k], (math.sin(a_o), math.cos(a_o)),
                                       (-math.sin(a_i), -math.cos(a_i)), 0.0, INNER_SPEED, 1)
        ratios[k + 1] = mot["orbital_velocity_rpm"].iloc[k] * RPM / w_m
    near = [v for b, v in ratios.items() if 8 <= b <= 12]
    far = [v for b, v in ratios.items() if not 8 <= b <= 12]
    assert len(near) == 5 and len(far) >= 10
    assert max(abs(v - 1) for v in near) < 3e-4
    assert max(far) - min(far) < 4e-4
    assert np.mean(far) == pytest.approx(0.99575, abs=2e-4)
