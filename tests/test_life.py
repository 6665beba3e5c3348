"""Fatigue life model (fortran/life, report section 3.2) against the report and closed forms.

Report numbers are quoted from the PDF-to-text copy of AFRL-PR-WP-TR-2002-2042
(/work/shared/seed/000_f0ab926e9a2b5d30.txt, "line NNNN"); the step-0 inputs are read
from golden/appendix_c_ball.prt (the report's Appendix C print, transcribed).
"""

from __future__ import annotations

import math
import subprocess

import numpy as np
import pytest

from pyadore import AdoreInputError
from pyadore.printout import read_print

from probes import LIFE_CONSTANT_NAMES, ball_bearing_life, life_default_constants

# Appendix C bearing (BEARING GEOMETRY echo)
D_BALL, D_PITCH, F_OUTER, F_INNER, Z = 1.905e-2, 0.140, 0.52, 0.54, 18
INNER_RPM = 2.0e4
SIGMA_RMS = 1.0e-7          # composite RMS height, FATIGUE PARAMETERS echo
HARRIS_A = 98.1 * 1000.0**1.8   # Lundberg-Palmgren / Harris constant 98.1 N/mm**1.8 in N/m**1.8


def _hertz_fill_from_deflection(q, delta, k):
    """Load of element k from its neighbours' loads and deflections, Q ~ delta**1.5 (Hertz)."""
    est = [q[j] * (delta[k] / delta[j]) ** 1.5 for j in (k - 1, k + 1) if not math.isnan(q[j])]
    return float(np.exp(np.mean(np.log(est))))


def _pressure_fill(p, q):
    """Missing max pressures from the nearest legible element, p ~ Q**(1/3) (Hertz, same geometry)."""
    p = p.copy()
    known = [j for j in range(len(p)) if not math.isnan(p[j])]
    for k in range(len(p)):
        if math.isnan(p[k]):
            j = min(known, key=lambda j: (abs(j - k), j))
            p[k] = p[j] * (q[k] / q[j]) ** (1.0 / 3.0)
    return p


@pytest.fixture(scope="module")
def step0(root):
    """Step-0 inputs of the Appendix C ball bearing, gaps filled from other printed numbers.

    Lost in the text: outer load of balls 5/15, inner load and angle of ball 1, some max
    pressures.  They are rebuilt with Hertz's law from the printed deflections and with the
    inner-race equilibrium (Int IRace force), never from the life model (docs/life-model.md).
    """
    run = read_print(root / "golden" / "appendix_c_ball.prt")
    s = run.step(0)
    c, mo, tr, th = s.table("re_contact"), s.table("re_motion"), s.table("re_traction"), s.table("re_thermal")
    ao = c["contact_angle_outer_deg"].to_numpy(float, copy=True)
    ai = c["contact_angle_inner_deg"].to_numpy(float, copy=True)
    qo = c["contact_load_outer_N"].to_numpy(float, copy=True)
    qi = c["contact_load_inner_N"].to_numpy(float, copy=True)
    psi = np.radians(c["orbital_position_deg"].to_numpy(float, copy=True))
    dlo = th["contact_deflection_outer_m"].to_numpy(float, copy=True)
    for k in np.flatnonzero(np.isnan(qo)):
        qo[k] = _hertz_fill_from_deflection(qo, dlo, k)
    assert not np.isnan(ao).any() and not np.isnan(qo).any()
    # inner ball 1 (index 0): the only unknown inner load/angle; from the inner-race equilibrium
    lost = np.flatnonzero(np.isnan(qi) | np.isnan(ai))
    assert list(lost) == [0]
    loads = s.table("loads")
    f_ax = -float(loads.loc["Int IRace", "force_x_N"])
    f_rad = -float(loads.loc["Int IRace", "force_z_N"])
    rest = slice(1, None)
    r_ax = f_ax - np.sum(qi[rest] * np.sin(np.radians(ai[rest])))
    r_rad = f_rad - np.sum(qi[rest] * np.cos(np.radians(ai[rest])) * np.cos(psi[rest]))
    qi[0], ai[0] = math.hypot(r_ax, r_rad), math.degrees(math.atan2(r_ax, r_rad))
    dli = th["contact_deflection_inner_m"].to_numpy(float, copy=True)
    assert qi[0] == pytest.approx(qi[1] * (dli[0] / dli[1]) ** 1.5, rel=3e-3)  # Hertz cross-check
    po = _pressure_fill(c["contact_stress_outer_Pa"].to_numpy(float, copy=True), qo)
    pi_ = _pressure_fill(c["contact_stress_inner_Pa"].to_numpy(float, copy=True), qi)
    bodies = s.table("bodies")
    perf = s.table("performance")
    return dict(
        q_outer=qo, q_inner=qi, alpha_outer=np.radians(ao), alpha_inner=np.radians(ai),
        orbital_speed=mo["orbital_velocity_rpm"].to_numpy(float, copy=True), p_max_outer=po, p_max_inner=pi_,
        lambda_outer=(tr["film_thickness_outer_m"] * tr["thermal_red_fac_outer"]).to_numpy(float, copy=True) / SIGMA_RMS,
        lambda_inner=(tr["film_thickness_inner_m"] * tr["thermal_red_fac_inner"]).to_numpy(float, copy=True) / SIGMA_RMS,
        mu_outer=tr["trac_coeff_outer"].to_numpy(float, copy=True), mu_inner=tr["trac_coeff_inner"].to_numpy(float, copy=True),
        hoop_outer=float(bodies.loc["ORace", "hoop_stress_Pa"]), hoop_inner=float(bodies.loc["IRace", "hoop_stress_Pa"]),
        inner_speed=float(bodies.loc["IRace", "ang_vel_amplitude_rpm"]),
        report_basic=float(perf["basic_fatigue_life_hours"].iloc[0]),
        report_modified=float(perf["modified_fatigue_life_hours"].iloc[0]),
    )


def _life(d, **constants):
    keys = ["q_outer", "q_inner", "alpha_outer", "alpha_inner", "orbital_speed", "p_max_outer", "p_max_inner"]
    return ball_bearing_life(
        *(d[k] for k in keys), d_ball=D_BALL, d_pitch=D_PITCH, f_outer=F_OUTER, f_inner=F_INNER,
        outer_speed=0.0, inner_speed=d["inner_speed"], outer_rotating=False, inner_rotating=True,
        lambda_outer=d["lambda_outer"], lambda_inner=d["lambda_inner"], mu_outer=d["mu_outer"],
        mu_inner=d["mu_inner"], hoop_outer=d["hoop_outer"], hoop_inner=d["hoop_inner"], constants=constants)


# ------------------------------------------------------------------ the report

def test_step0_inputs_are_the_report(step0):
    assert step0["report_basic"] == 533.4        # "Basic Fatigue Life (hours) 5.334E+02", line 3298
    assert step0["report_modified"] == 4460.0    # "Modified Fatigue Life (hours) 4.460E+03", lines 3299, 3325
    assert step0["inner_speed"] == INNER_RPM
    assert step0["hoop_outer"] == -6.402e6 and step0["hoop_inner"] == 1.184e8


def test_basic_life_reproduces_the_report(step0):
    """Basic life within 3 % of 533.4 h with the default (report) constants."""
    r = _life(step0)
    assert r["basic"] == pytest.approx(step0["report_basic"], rel=0.03)


def test_basic_life_with_lundberg_palmgren_stationary_race(step0):
    """The textbook stationary-race rule (stationary_rule = 1) gives the outer race exactly
    Z**-0.1 of the report rule's life; the bearing then misses the report by about -23 %."""
    rep, lp = _life(step0), _life(step0, stationary_rule=1.0)
    assert lp["basic_outer"] == pytest.approx(rep["basic_outer"] * Z ** -0.1, rel=1e-12)
    assert lp["basic_inner"] == pytest.approx(rep["basic_inner"], rel=1e-12)
    assert lp["basic"] / step0["report_basic"] - 1 == pytest.approx(-0.228, abs=0.005)


@pytest.mark.xfail(strict=True, reason=(
    "Tallian modified life as printed in eqs 77-109 gives 5564 h (Psi outer 0.0945, inner 0.1388) "
    "against the report's 4460 h (+24.8 %). Psi_outer is fixed by the printed constants (s_stat ~ 0); "
    "no reading of the text closes it. See docs/life-model.md, 'Modified life: the open gap'"))
def test_modified_life_reproduces_the_report(step0):
    r = _life(step0)
    assert r["modified"] == pytest.approx(step0["report_modified"], rel=0.03)


def test_outer_race_psi_is_fixed_by_the_constants(step0):
    """With no hoop stress (s_stat = 0) and the printed films (asperity term ~1e-11), the
    outer-race Psi is I + Phi1f Phi2f (t_f0/0.39)**(beta zeta), t_f0 = 1.25 z_frac + 1.22 mu_a,
    whatever the loads, weights or summation (eq 78 is a weighted mean of contact ratios);
    docs/life-model.md, 'Re-derivation of eqs 77-109'."""
    c = life_default_constants()
    bz = c["beta"] * c["zeta"]
    t_f0 = 1.25 * c["z_frac"] + 1.22 * c["mu_asperity"]
    expected = c["processing_i"] + c["phi1_furrow"] * c["phi2f_clean"] * (t_f0 / 0.39) ** bz
    r = _life(dict(step0, hoop_outer=0.0))
    assert r["psi_outer"] == pytest.approx(expected, rel=1e-8)


def test_life_constants_reproduce_the_reports_printed_numbers():
    """Report-internal checks of section 3.2 (no fitting): eq 88 gives the echo's composite
    slope 4.11320E-02 from sigma = 1e-7 m (in mm); Phi_3bLP = 0.39**(beta zeta) = 1.60e-5
    (text before eq 101); (3e-45)**(1/(beta zeta)) per MPa = 1.5985e-10 per Pa (step 6);
    0.0306 of eq 86 is Nayak's 1/(6 pi sqrt 3)."""
    c = life_default_constants()
    bz = c["beta"] * c["zeta"]
    sigma_mm = 1e3 * c["sigma_rms"]
    assert sigma_mm / (0.02683 * sigma_mm ** 0.2607) == pytest.approx(4.11320e-2, rel=2e-6)
    assert c["theta_rms"] == pytest.approx(4.11320e-2, rel=1e-12)
    assert round(0.39 ** bz, 7) == 1.60e-5
    assert 3e-45 ** (1 / bz) * 1e-6 == pytest.approx(c["phi0lp_root_per_pa"], rel=1e-4)
    assert round(1 / (6 * math.pi * math.sqrt(3)), 4) == 0.0306


def test_modified_life_current_value_is_documented(step0):
    """Not a check against the report: pins the number that docs/life-model.md quotes."""
    r = _life(step0)
    assert r["modified"] == pytest.approx(5564.0, rel=1e-3)
    assert (r["psi_outer"], r["psi_inner"]) == pytest.approx((0.0945, 0.1388), abs=5e-4)


# ------------------------------------------------------------ closed forms

def _qc(a, f, alpha, passes, outer, x=0.3, c=2.0):
    """Eq 74 by hand."""
    g = D_BALL * math.cos(alpha) / D_PITCH
    s = 1.0 if outer else -1.0
    return a * (2 * f / (2 * f - 1)) ** 0.41 * (1 + s * g) ** 1.39 * (D_BALL / D_PITCH) ** x * D_BALL ** 1.8 \
        * (c * passes) ** (-1.0 / 3.0)


def _hours(n_mrev, rpm=INNER_RPM):
    return n_mrev * 1e6 / (60.0 * rpm)


def _single(q_o, q_i, alpha=math.radians(20.0), orbit=9000.0, m=1, **constants):
    ones = np.ones(m)
    return ball_bearing_life(q_o * ones, q_i * ones, alpha * ones, alpha * ones, orbit * ones,
                             1.5e9 * ones, 1.5e9 * ones, d_ball=D_BALL, d_pitch=D_PITCH, f_outer=F_OUTER,
                             f_inner=F_INNER, outer_speed=0.0, inner_speed=INNER_RPM, constants=constants)


def test_single_contact_follows_the_cube_law_exactly():
    """One ball, inner race unloaded: bearing life = (Q/Q_c)**-3 with Q_c of eq 74 by hand."""
    a, alpha, orbit = life_default_constants()["a_point"], math.radians(20.0), 9000.0
    qc = _qc(a, F_OUTER, alpha, orbit / INNER_RPM, outer=True)
    for q in (500.0, 1000.0, 4000.0):
        r = _single(q, 0.0, alpha, orbit)
        assert math.isinf(r["basic_inner"])
        assert r["lives_outer"][0] == pytest.approx((q / qc) ** -3, rel=1e-12)
        assert r["basic"] == pytest.approx(_hours((q / qc) ** -3), rel=1e-12)
    assert _single(2000.0, 0.0)["basic"] == pytest.approx(_single(1000.0, 0.0)["basic"] / 8, rel=1e-12)


def test_race_combination_eq102_by_hand():
    """Eq 102: N**-e = N_OR**-e + N_IR**-e, e = 10/9, from the two race lives."""
    r = _single(2000.0, 800.0)
    e = 10.0 / 9.0
    assert r["basic"] == pytest.approx((r["basic_outer"] ** -e + r["basic_inner"] ** -e) ** (-1 / e), rel=1e-12)
    alpha = math.radians(20.0)
    qc_i = _qc(life_default_constants()["a_point"], F_INNER, alpha, (INNER_RPM - 9000.0) / INNER_RPM, outer=False)
    assert r["basic_inner"] == pytest.approx(_hours((800.0 / qc_i) ** -3), rel=1e-12)


@pytest.mark.parametrize("alpha_deg", [0.0, 15.0, 40.0])
def test_race_capacity_is_the_harris_lundberg_palmgren_formula(alpha_deg):
    """Z equal loads, pure rolling (cage at (1 - gamma)/2 of the inner speed): the race lives are
    (Q/Q_c)**-3 with the Lundberg-Palmgren race capacity as given by Harris & Kotzalas,
        Q_c = 98.1 (2f/(2f-1))**0.41 (1 -+ g)**1.39 / (1 +- g)**(1/3) (g/cos a)**0.3 D**1.8 Z**(-1/3)
    (N, mm; upper signs inner race).  This is what cycle_factor = 2 and the exponent 0.3 encode;
    the outer race needs the Lundberg-Palmgren stationary rule (stationary_rule = 1)."""
    alpha = math.radians(alpha_deg)
    g = D_BALL * math.cos(alpha) / D_PITCH
    orbit = INNER_RPM * (1 - g) / 2
    q = 1500.0

    def harris(f, inner):
        s = 1.0 if inner else -1.0
        return HARRIS_A * (2 * f / (2 * f - 1)) ** 0.41 * (1 - s * g) ** 1.39 / (1 + s * g) ** (1 / 3) \
            * (D_BALL / D_PITCH) ** 0.3 * D_BALL ** 1.8 * Z ** (-1 / 3)

    r = _single(q, q, alpha, orbit, m=Z, a_point=HARRIS_A, stationary_rule=1.0)
    assert r["basic_inner"] == pytest.approx(_hours((q / harris(F_INNER, True)) ** -3), rel=1e-12)
    assert r["basic_outer"] == pytest.approx(_hours((q / harris(F_OUTER, False)) ** -3), rel=1e-12)
    # the report rule (default) gives the stationary race Z**0.1 times that
    rep = _single(q, q, alpha, orbit, m=Z, a_point=HARRIS_A)
    assert rep["basic_outer"] == pytest.approx(r["basic_outer"] * Z ** 0.1, rel=1e-12)


def test_stationary_race_is_the_ten_thirds_power_mean_load():
    """Lundberg-Palmgren stationary race with unequal loads and one capacity:
    Q_e = (mean Q**(10/3))**0.3 over all Z positions (unloaded ones count as zero)."""
    alpha = math.radians(10.0)
    g = D_BALL * math.cos(alpha) / D_PITCH
    orbit = INNER_RPM * (1 - g) / 2
    q = np.array([3000.0, 2500.0, 1500.0, 500.0, 0.0, 0.0, 0.0, 0.0])
    m = q.size
    ones = np.ones(m)
    r = ball_bearing_life(q, 0 * ones, alpha * ones, alpha * ones, orbit * ones, 1.5e9 * ones, 1.5e9 * ones,
                          d_ball=D_BALL, d_pitch=D_PITCH, f_outer=F_OUTER, f_inner=F_INNER, outer_speed=0.0,
                          inner_speed=INNER_RPM, constants={"stationary_rule": 1.0})
    qc_race = _qc(life_default_constants()["a_point"], F_OUTER, alpha, (1 - g) / 2, outer=True) * m ** (-1 / 3)
    q_e = np.mean(q ** (10 / 3)) ** 0.3
    assert r["basic_outer"] == pytest.approx(_hours((q_e / qc_race) ** -3), rel=1e-12)


def test_tallian_limit_psi_one():
    """Eq 77 with the factors at their Lundberg-Palmgren values (Psi = 1, tau0 = 0):
    N10 = 12 A M**(-1/beta) N_LP for each race."""
    lp = dict(phi1_asperity=0.0, phi1_furrow=0.0, processing_i=1.0)
    r = _single(2000.0, 800.0, **lp)
    assert (r["psi_outer"], r["psi_inner"]) == pytest.approx((1.0, 1.0), rel=1e-12)
    k = 12 * 0.23 * 1.197 ** (-1 / 1.6)
    assert r["modified_outer"] == pytest.approx(k * r["basic_outer"], rel=1e-12)
    assert r["modified_inner"] == pytest.approx(k * r["basic_inner"], rel=1e-12)


# ------------------------------------------------------------ the interface

def test_default_constants_are_named_and_complete():
    c = life_default_constants()
    assert tuple(c) == LIFE_CONSTANT_NAMES
    assert c["a_point"] == 2.3615e7 and c["dm_exponent"] == 0.3 and c["cycle_factor"] == 2.0
    assert c["stationary_rule"] == 0.0


@pytest.mark.parametrize("bad", [
    dict(q_outer=[1.0, float("nan")]),
    dict(q_outer=[1.0, 2.0, 3.0]),
    dict(constants={"stationary_rule": 0.5}),
    dict(constants={"no_such_constant": 1.0}),
    dict(f_outer=0.5),
    dict(inner_speed=0.0),
    dict(d_pitch=0.01),
])
def test_bad_input_raises(bad):
    args = dict(q_outer=[1000.0, 900.0], q_inner=[500.0, 400.0], alpha_outer=[0.2, 0.2], alpha_inner=[0.3, 0.3],
                orbital_speed=[9000.0, 9000.0], p_max_outer=[1.5e9, 1.5e9], p_max_inner=[1.5e9, 1.5e9],
                d_ball=D_BALL, d_pitch=D_PITCH, f_outer=F_OUTER, f_inner=F_INNER, outer_speed=0.0,
                inner_speed=INNER_RPM)
    args.update(bad)
    with pytest.raises(AdoreInputError):
        ball_bearing_life(**args)


def test_fortran_life_unit_tests_pass(build_dir):
    exe = build_dir / "test_life"
    if not exe.exists():
        pytest.fail(f"{exe} not built: run the tests with `make test`")
    proc = subprocess.run([str(exe)], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "all life tests passed" in proc.stdout
