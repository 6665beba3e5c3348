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

ROOT = Path(__file__).resolve().parents[1]
RPM = math.pi / 30
COEF = [-1.6e-2, 3.82896e-2, 1.71782, 1.6e-2]  # Rec 10.1C fit (echo A, B, C; D = kinf = 0.016)
D_BALL, F_OUTER, F_INNER = 0.01905, 0.52, 0.54
E_PRIME = 2.0e11 / (1 - 0.25**2)               # equal steels, E' = E / (1 - nu**2)
INNER_SPEED = 20000 * RPM
STEEL = [7750.0, 470.0, 43.0]                  # echo: density, heat capacity, conductivity


def kappa(u):
    a, b, c, d = COEF
    return (a + b * u) * np.exp(-c * u) + d


# --- independent checks ----------------------------------------------------------------------

def test_film_thickness_scaling_and_formula():
    """Hamrock-Dowson central film, h/R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^-0.73k),
    recomputed here; exponents checked by scaling."""
    rx, k, u, q, eta, alpha = 0.0108, 7.5, 75.0, 2457.0, 0.008, 1.1e-8
    h = _core.film_thickness(rx, k, u, q, E_PRIME, eta, alpha)
    ref = rx * 2.69 * (eta * u / (E_PRIME * rx)) ** 0.67 * (alpha * E_PRIME) ** 0.53 \
        * (q / (E_PRIME * rx**2)) ** -0.067 * (1 - 0.61 * math.exp(-0.73 * k))
    assert h == pytest.approx(ref, rel=1e-13)
    assert _core.film_thickness(rx, k, 2 * u, q, E_PRIME, eta, alpha) == pytest.approx(h * 2**0.67, rel=1e-13)
    with pytest.raises(AdoreInputError):
        _core.film_thickness(rx, k, u, q, E_PRIME, -eta, alpha)


def test_lubricant_library_needs_unsourced_properties():
    lub = _core.lubricant(1, 313.15, density=950.0, alpha=1.0e-8, conductivity=0.15)
    assert lub["nu"] == pytest.approx(11.5e-6, rel=1e-12)       # MIL-L-7808 grade 3, 40 C
    with pytest.raises(AdoreInputError, match="required inputs"):
        _core.lubricant(1, 323.0, density=950.0, alpha=0.0, conductivity=0.15)
    with pytest.raises(AdoreInputError, match="unknown lubricant code"):
        _core.lubricant(7, 323.0, density=950.0, alpha=1.0e-8, conductivity=0.15)


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
    t = _core.contact_traction(**c, coef=COEF, n_gauss=16)
    a, q = c["a"], c["load"]
    n = 400_000
    s = -a + (np.arange(n) + 0.5) * (2 * a / n)
    geo = {k: v for k, v in c.items() if k != "load"}
    u = _core.contact_slip(**geo, s=s)
    dq = 0.75 * q / a * (1 - (s / a) ** 2) * (2 * a / n)
    assert t["force"] == pytest.approx(np.sum(np.sign(u) * kappa(np.abs(u)) * dq), rel=1e-6, abs=1e-9 * q)
    assert t["power"] == pytest.approx(np.sum(kappa(np.abs(u)) * np.abs(u) * dq), rel=1e-7)
    ends = _core.contact_slip(**geo, s=[-a, a])
    assert t["max_slip"] == pytest.approx(np.abs(np.r_[u, ends]).max(), rel=1e-9)
    for k in range(int(t["n_rolling"])):
        assert abs(_core.contact_slip(**geo, s=[t[f"s{k + 1}"]])[0]) < 1e-9


@pytest.mark.parametrize("name", list(CONTACTS))
def test_power_is_area_integral_of_traction_times_slip(name):
    """Power loss = integral over the ellipse of tau u dA with tau = sigma kappa(u) (eqs 1, 4, 5),
    Hertz sigma = p0 sqrt(1 - x^2/a^2 - y^2/b^2), Q = 2/3 pi a b p0; 2-D Gauss over the ellipse."""
    c = CONTACTS[name]
    t = _core.contact_traction(**c, coef=COEF, n_gauss=16)
    a, q = c["a"], c["load"]
    b = 0.13 * a
    p0 = 1.5 * q / (math.pi * a * b)
    geo = {k: v for k, v in c.items() if k != "load"}
    x, wx = np.polynomial.legendre.leggauss(4000)
    y, wy = np.polynomial.legendre.leggauss(64)
    xs = a * x
    u = _core.contact_slip(**geo, s=xs)
    half = b * np.sqrt(1 - x**2)
    sigma = p0 * np.sqrt(np.clip(1 - x[:, None] ** 2 - y[None, :] ** 2 * (1 - x[:, None] ** 2), 0, None))
    area_sigma = (sigma * wy[None, :]).sum(axis=1) * half          # integral of sigma dy per strip
    power = np.sum(wx * a * area_sigma * kappa(np.abs(u)) * np.abs(u))
    assert t["power"] == pytest.approx(power, rel=2e-4)


def test_flash_uniform_flux_closed_form():
    xi = np.linspace(-1, 1, 101)
    assert np.allclose(_core.flash_rise(xi, np.full_like(xi, 2.0)), 4 * np.sqrt(xi + 1), atol=1e-12)


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
            t = _core.contact_traction(side, row["alpha"], D_BALL / 2, balls["r"][k], omega, w_race - wm, row["a"],
                                       row["load"], COEF, n_gauss=16)
            row["calc"] = t
            row["calc4"] = _core.contact_traction(side, row["alpha"], D_BALL / 2, balls["r"][k], omega, w_race - wm,
                                                  row["a"], row["load"], COEF, n_gauss=4)
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
    return _core.film_thickness(r["rx"], k, r["u"], r["load"], E_PRIME, 1.0, 1.0)


def _calibration_row(rows):
    return next(r for r in rows if r["ball"] == 10 and r["side"] == "outer")


def _film_errors():
    """One lubricant constant, eta0^0.67 alpha^0.53 at 323 K, is not in the report (no
    sourced alpha for MIL-L-7808): it is calibrated on ball 10's outer contact; the other
    35 contacts test the formula's dependence on speed, load, R_x and k."""
    rows = _report_step0()
    c = _calibration_row(rows)
    lub = c["film"] / _film_unit(c)
    use = _usable(rows, "film", "b")
    return [(r, lub * _film_unit(r), r["film"]) for r in use]


def _loading(r, p, phi):
    lo, hi = 1e-6, 1e4
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if _core.thermal_reduction_factor(p, E_PRIME, [mid], 0.0)[0] > phi:
            lo = mid
        else:
            hi = mid
    return mid


def _thermal_errors():
    """One constant eta0 beta / K_f (s**2/m**2) calibrated on ball 10's outer contact (the
    report gives neither beta nor K_f of its MIL-L-7808); L = const * u**2; the slide-to-roll
    ratio is this code's centre slip over the entraining speed."""
    rows = _report_step0()
    c = _calibration_row(rows)
    const = _loading(c, c["p0"], c["phi"]) / c["u"] ** 2
    out = []
    for r in _usable(rows, "phi", "p0"):
        s = r["calc"]["centre_slip"] / r["calc"]["rolling_speed"]
        out.append((r, _core.thermal_reduction_factor(r["p0"], E_PRIME, [const * r["u"] ** 2], s)[0], r["phi"]))
    return out


def _simple(key, ref, transform=lambda v: v):
    return lambda: [(r, transform(r["calc"][key]), r[ref]) for r in _usable(_report_step0(), ref)]


def _temperature_errors():
    """Eqs 28-53 isolated: the heat is the report's own contact loss, spread as a constant
    kappa u_s over the Hertz pressure (eq 29), surfaces moving at the entraining speed."""
    out = []
    xk, wk = np.polynomial.legendre.leggauss(24)
    for r in _usable(_report_step0(), "rise", "loss", "b", "p0"):
        g = r["loss"] / r["load"]
        avg, _ = _core.contact_temperature_rise(r["a"], r["b"], r["p0"], r["a"] * xk, r["a"] * wk,
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


def test_flat_wrappers_refuse_bad_input_with_a_message():
    """Bad geometry gives AdoreInputError, never NaN (the wrappers return a status)."""
    from pyadore import AdoreInputError

    geo = {k: v for k, v in CONTACTS["outer"].items() if k != "load"}
    geo["a"] = 0.0
    with pytest.raises(AdoreInputError, match="half width"):
        _core.contact_slip(**geo, s=[0.0])
    with pytest.raises(AdoreInputError, match="increase strictly"):
        _core.flash_rise([0.0, 0.0, 1.0], [1.0, 1.0, 1.0])
    with pytest.raises(AdoreInputError, match="p_h > 0"):
        _core.thermal_reduction_factor(0.0, 2.2e11, [1.0], 0.1)
