"""Step-0 ball kinematics by minimum contact dissipation (report 4.4.7) and the race-contact
tribology printed at step 0 (report 2.1), computed end to end by the engine from the
Appendix C deck and compared with the report's print (golden/appendix_c_ball.prt).

Issue "[Step-0 tribology]" asks 5 % per column; a column that misses is a strict xfail with
its numbers and the believed cause (docs/tribology.md).  Independent checks: the energy
balance of the printed power loss, the engine's minimum against a brute-force scan of
the dissipation with the inner contact centre rolling, and the run's film against the
Hamrock-Dowson formula evaluated here.
"""

from __future__ import annotations

import math
import subprocess
import sys
import tempfile
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from pyadore import _core
from pyadore.printout import read_print

import probes


ROOT = Path(__file__).resolve().parents[1]
RPM = math.pi / 30
DEG = math.pi / 180
D_BALL = 0.01905
COEF = [-1.6e-2, 3.82896e-2, 1.71782, 1.6e-2]
INNER_SPEED = 20000 * RPM


@lru_cache(maxsize=1)
def _step0():
    return _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")


@lru_cache(maxsize=1)
def _golden():
    step = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0]
    return {n: step.table(n) for n in ("re_motion", "re_traction", "re_thermal", "performance")}


def _theta_deg(b):
    """Print convention: omega = -amplitude (cos theta, sin theta) in the orbit frame."""
    w, beta = b["spin_speed"], b["pitch"]
    return np.degrees(np.arctan2(-w * np.sin(beta), -w * np.cos(beta)))


def _column(key):
    balls, _ = _step0()
    if key == "theta":
        return _theta_deg(balls)
    return balls[key]


COLUMNS = {  # printed column: (engine key, table, scale, absolute tolerance or None, xfail reason)
    # spin-axis pitch: golden/tolerances.toml's rule for re_motion (5 %, zero rule: 5 % of
    # the column's largest |value| = 0.42 deg); balls 1-7 within 0.23 deg, balls 8-12 miss
    "ang_vel_theta_deg": ("theta", "re_motion", 1.0, "zero-rule",
                          "worst 0.54 deg (balls 1-7 high by 0.37-0.54 deg, balls 8-12 low by up to 0.55 deg) "
                          "against 0.42 deg: the minimum of the EHD dissipation is shallow (1 % in power over "
                          "+-1 deg); on balls 8-12 the report's pitch jumps 1.5 deg between balls 7 and 8 and "
                          "sits within 0.04 % of outer race control - what selects that branch is not known"),
    "orbital_velocity_rpm": ("orbital_speed", "re_motion", 1 / RPM, None, None),
    "slip_velocity_outer_m_s": ("slip_o", "re_traction", 1.0, None,
                                "worst 8.7 % (ball 4 1.730 vs 1.895 m/s): the definition reproduces the report "
                                "within 0.6 % with the report's speeds (tests/test_tribology.py); here it follows "
                                "the pitch (0.4-0.55 deg off) and the orbital speed (0.15-0.23 % off) of the start"),
    "slip_velocity_inner_m_s": ("slip_i", "re_traction", 1.0, None, None),
    "spin_roll_inner": ("spin_roll_i", "re_motion", 1.0, None, None),
    "spin_roll_outer": ("spin_roll_o", "re_motion", 1.0, None,
                        "outer spin/roll is a small difference of two large terms (-0.0093 vs -0.0196 ball 1; "
                        "report +0.0070 for balls 8-12, here -0.0034, 148 %): follows the pitch error"),
    # traction model 3 (EHD film, docs/tribology.md) at this model's own speeds and film (the
    # start minimises the EHD dissipation); the printed coefficient is the local one at the
    # node of the printed slip
    "trac_coeff_outer": ("trac_o", "re_traction", 1.0, None,
                         "worst 11.0 % (ball 4 0.00640 vs 0.00719; -1 to -11 %): follows the outer slip of the "
                         "start's speeds (8.7 % off); with the report's own speeds the same EHD model is within "
                         "1.2 % (tests/test_tribology.py)"),
    "trac_coeff_inner": ("trac_i", "re_traction", 1.0, None, None),
    "contact_loss_outer_W": ("loss_o", "re_motion", 1.0, None, None),
    # flash temperature (eqs 35-36) with the EHD film's heat, surfaces at the entraining speed
    "contact_temp_rise_outer_K": ("temp_rise_o", "re_thermal", 1.0, None, None),
    "contact_temp_rise_inner_K": ("temp_rise_i", "re_thermal", 1.0, None,
                                  "worst 11.0 % high (ball 1 2.706 vs 2.437 K; balls 8-12 within 1 %): with the "
                                  "report's own speeds and films the same model is 6.8 % high on the inner race "
                                  "(the contact loss there is +3.9 %); ADORE's surface speeds or grid for eq 35 "
                                  "are not given"),
    "contact_loss_inner_W": ("loss_i", "re_motion", 1.0, None, None),
}


def _errors(column):
    key, table, scale, _, _ = COLUMNS[column]
    calc = np.asarray(_column(key)) * scale
    ref = _golden()[table][column].to_numpy()
    return [(k + 1, c, r) for k, (c, r) in enumerate(zip(calc, ref)) if not math.isnan(r)]


@pytest.mark.parametrize("column", [
    pytest.param(c, marks=pytest.mark.xfail(strict=True, reason=v[4])) if v[4] else c
    for c, v in COLUMNS.items()])
def test_step0_tribology_column_matches_report(column):
    atol = COLUMNS[column][3]
    errs = _errors(column)
    assert len(errs) >= 14
    if atol == "zero-rule":   # as golden/tolerances.toml: rel 5 % of the column's largest |golden|
        atol = 0.05 * max(abs(e[2]) for e in errs)
    if atol is not None:
        worst = max(errs, key=lambda e: abs(e[1] - e[2]))
        print(f"{column}: worst {worst[1] - worst[2]:+.3f} at ball {worst[0]} ({worst[1]:.4g} vs {worst[2]:.4g})")
        assert abs(worst[1] - worst[2]) <= atol
        return
    worst = max(errs, key=lambda e: abs(e[1] / e[2] - 1))
    rel = abs(worst[1] / worst[2] - 1)
    print(f"{column}: worst {100 * rel:.2f} % at ball {worst[0]} ({worst[1]:.4g} vs {worst[2]:.4g})")
    assert rel <= 0.05


def test_total_power_loss_matches_report():
    _, summary = _step0()
    ref = _golden()["performance"]["total_power_loss_W"].iloc[0]
    assert summary["power_loss"] == pytest.approx(ref, rel=0.05)


def test_power_loss_is_sum_of_contact_losses():
    """Energy balance at step 0: bearing power loss = the race contacts' losses (no cage
    contact force, no drag at step 0); the report's own columns obey it too (546.4 W)."""
    balls, summary = _step0()
    assert summary["power_loss"] == pytest.approx(np.sum(balls["loss_o"]) + np.sum(balls["loss_i"]), rel=1e-12)
    g = _golden()
    mot = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0].table("re_motion")
    total = mot["contact_loss_outer_W"].sum() + mot["contact_loss_inner_W"].sum()
    assert total == pytest.approx(g["performance"]["total_power_loss_W"].iloc[0], rel=2e-3)


def _dissipation(b, k, beta, w_b):
    """Both contacts' EHD power (traction model 3; the fast quadrature, as the engine's
    search) at (beta, w_b), inner centre rolling, with the run's own films (iso film x
    thermal reduction factor)."""
    lub = _core.lubricant(1, 323.0)
    rheo = (lub["eta_t"], lub["alpha_t"], lub["beta_t"], lub["conductivity"])
    r = b["r"][k]
    ai = b["alpha_i"][k]
    n_i = (-math.sin(ai), -math.cos(ai))
    ri = r + D_BALL / 2 * n_i[1]
    w_m = INNER_SPEED - w_b * D_BALL / 2 * (math.cos(beta) * n_i[1] - math.sin(beta) * n_i[0]) / ri
    om = (w_b * math.cos(beta), w_b * math.sin(beta))
    p = 0.0
    for tag, side, wr in (("o", 1, 0.0), ("i", -1, INNER_SPEED)):
        h = b[f"film_{tag}"][k] * b[f"thermal_factor_{tag}"][k]
        p += _core.ehd_contact_method(side=side, alpha=b[f"alpha_{tag}"][k], rho=D_BALL / 2, r_b=r, omega=om,
                                      race_speed=wr - w_m, a=b[f"a_{tag}"][k], load=b[f"q_{tag}"][k], rheology=rheo,
                                      film=h, b=b[f"b_{tag}"][k], method="fast")["power"]
    return p, w_m


@pytest.mark.parametrize("k", [1, 9])
def test_minimum_dissipation_beats_a_brute_force_scan(k):
    """The engine's (pitch, spin speed) is the least EHD dissipation of a 21 x 21 scan
    around it (+-2 deg, +-0.5 %), and its orbital speed is the inner-rolling one."""
    balls, _ = _step0()
    beta0, w0 = balls["pitch"][k], balls["spin_speed"][k]
    p0, wm0 = _dissipation(balls, k, beta0, w0)
    assert wm0 == pytest.approx(balls["orbital_speed"][k], rel=1e-6)
    best = min(_dissipation(balls, k, beta0 + db * DEG, w0 * (1 + f))[0]
               for db in np.linspace(-2, 2, 21) for f in np.linspace(-5e-3, 5e-3, 21))
    assert p0 <= best * (1 + 1e-9)
    # the printed losses integrate the same EHD traction with 16 x 24 points (the search's
    # fast quadrature against the print's: 6.5e-6 on ball 7; it was 0.23 % with the 4 x 8
    # points the search took before, docs/operating-points.md "Two pitch minima")
    assert p0 == pytest.approx(balls["loss_o"][k] + balls["loss_i"][k], rel=2e-5)


def test_minimum_dissipation_is_closer_to_the_report_than_outer_race_control():
    """Why minimum dissipation is the step-0 default: worst pitch error 0.55 vs 0.99 deg and
    worst orbital-speed error 0.23 vs 0.44 % against outer race control on the same contact
    geometry, and nearer on balls 1-7 and 13-18.  Balls 8-12 are the exception: there the
    report's speeds are within 0.04 % of outer race control (its outer spin/roll turns
    positive; docs/tribology.md)."""
    balls, _ = _step0()
    mot = _golden()["re_motion"]
    theta_md = _theta_deg(balls)
    err = {"md_t": [], "rc_t": [], "md_w": [], "rc_w": []}
    for k in range(18):
        ao, ai = balls["alpha_o"][k], balls["alpha_i"][k]
        wm_rc, w, beta = probes.race_control(D_BALL, balls["r"][k], (math.sin(ao), math.cos(ao)),
                                            (-math.sin(ai), -math.cos(ai)), 0.0, INNER_SPEED, 1)
        theta_rc = math.degrees(math.atan2(-w * math.sin(beta), -w * math.cos(beta)))
        ref_t, ref_w = mot["ang_vel_theta_deg"].iloc[k], mot["orbital_velocity_rpm"].iloc[k] * RPM
        err["md_t"].append(abs(theta_md[k] - ref_t))
        err["rc_t"].append(abs(theta_rc - ref_t))
        err["md_w"].append(abs(balls["orbital_speed"][k] / ref_w - 1))
        err["rc_w"].append(abs(wm_rc / ref_w - 1))
    e = {key: np.array(v) for key, v in err.items()}
    assert e["md_t"].max() < e["rc_t"].max()
    assert e["md_w"].max() < e["rc_w"].max()
    better = (e["md_t"] < e["rc_t"]) & (e["md_w"] < e["rc_w"])
    assert list(np.flatnonzero(~better) + 1) == [8, 9, 10, 11, 12]


def test_run_film_is_hamrock_dowson_with_the_echoed_lubricant():
    """Every race contact's film in the run equals the Hamrock-Dowson central film of its own
    load, half widths, entraining speed and R_x with MIL-L-7808 at 323 K (independent
    evaluation of the formula in Python)."""
    balls, _ = _step0()
    lub = _core.lubricant(1, 323.0)
    e_prime = 2.0e11 / (1 - 0.25**2)
    for k in (0, 9):
        for tag, side, wr in (("o", 1, 0.0), ("i", -1, INNER_SPEED)):
            w_b, beta = balls["spin_speed"][k], balls["pitch"][k]
            t = probes.contact_traction(side, balls[f"alpha_{tag}"][k], D_BALL / 2, balls["r"][k],
                                       (w_b * math.cos(beta), w_b * math.sin(beta)), wr - balls["orbital_speed"][k],
                                       balls[f"a_{tag}"][k], balls[f"q_{tag}"][k], COEF, n_gauss=4)
            u, rx = abs(t["rolling_speed"]), t["rx"]
            ell = balls[f"a_{tag}"][k] / balls[f"b_{tag}"][k]
            h = rx * 2.69 * (lub["eta"] * u / (e_prime * rx)) ** 0.67 * (lub["alpha"] * e_prime) ** 0.53 \
                * (balls[f"q_{tag}"][k] / (e_prime * rx**2)) ** -0.067 * (1 - 0.61 * math.exp(-0.73 * ell))
            assert balls[f"film_{tag}"][k] == pytest.approx(h, rel=1e-9)


# --- section 3: race loads with the contact tractions ---------------------------------------

@lru_cache(maxsize=1)
def _printed_loads():
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "c.prt"
        subprocess.run([sys.executable, "-m", "pyadore", "run", str(ROOT / "decks" / "appendix_c_ball.inp"),
                        "-o", str(out), "--steps", "0"], check=True, capture_output=True)
        return read_print(out).steps[0].table("loads")


def test_race_y_force_is_the_sum_of_the_contact_tractions():
    """Normal loads give no y force (the load plane is x-z); the printed y force on each race
    is the sum of its contacts' net tractions along the orbit direction e_t = (0, -cos phi,
    -sin phi), and the z force changes by the same sum with -sin phi."""
    balls, summary = _step0()
    loads = _printed_loads()
    phi = balls["azimuth"]
    for body, key in (("Int ORace", "traction_o"), ("Int IRace", "traction_i")):
        fy = float(np.sum(balls[key] * -np.cos(phi)))
        assert loads.loc[body, "force_y_N"] == pytest.approx(fy, rel=1e-3, abs=1e-3)
    assert loads.loc["Int IRace", "force_z_N"] == pytest.approx(
        summary["inner_force_z"] + float(np.sum(balls["traction_i"] * -np.sin(phi))), rel=1e-3)


@pytest.mark.xfail(strict=True, reason=(
    "race traction loads follow the outer contact's kinematics (docs/tribology.md): inner Mx "
    "-0.0946 vs -0.1004 N m (5.8 %), inner Fy -0.112 vs -0.4926 N; outer Mx +2.00 vs -0.347 N m, "
    "outer Fy -5.66 vs -73.94 N.  With the report's own speeds the outer EHD tractions are +7.7 to +10.4 N on balls 2-4 and -1.9 to -8.7 N on balls 7-10, so their sum is set by the kinematics.  The "
    "same definition reproduces the roller run's Fy and Mx within 0.15 % "
    "(tests/test_roller_tribology.py)"))
def test_race_traction_loads_match_report():
    golden = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0].table("loads")
    loads = _printed_loads()
    for body in ("Int ORace", "Int IRace"):
        for col in ("force_y_N", "moment_x_Nm"):
            assert loads.loc[body, col] == pytest.approx(golden.loc[body, col], rel=0.01), (body, col)


def test_outer_race_z_force_follows_the_orbital_speeds():
    """Balls in radial equilibrium: the outer race's z force is the inner race's plus the
    net centrifugal force sum m r w_m**2 cos(phi) of the balls.  With the report's printed
    orbital speeds that sum is the report's own ORace - IRace difference (1453 - 1995 N =
    -542 N) within 0.5 %.  So the engine's outer Fz (1509 N, 3.9 % off) misses through its
    orbital speeds (range 9014-9285 rpm against the report's 8999-9306 rpm, sum -482 N), not
    through the mechanics (docs/tribology.md, "What sets the report's orbital speed")."""
    step = read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0]
    w = step.table("re_motion")["orbital_velocity_rpm"].to_numpy(float) * RPM
    loads = step.table("loads")
    balls, _ = _step0()
    mass = 2.80534e-2                                   # echo: RE mass (kg)
    net = float(np.sum(mass * balls["r"] * w**2 * np.cos(balls["azimuth"])))
    printed = loads.loc["Int ORace", "force_z_N"] + loads.loc["Int IRace", "force_z_N"]
    assert net == pytest.approx(printed, rel=5e-3)
    own = float(np.sum(mass * balls["r"] * balls["orbital_speed"]**2 * np.cos(balls["azimuth"])))
    run = _printed_loads()
    assert run.loc["Int ORace", "force_z_N"] + run.loc["Int IRace", "force_z_N"] == pytest.approx(own, rel=5e-3)
