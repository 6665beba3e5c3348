"""Roller bearing step 0 (issue "[Roller step 0]"): line contact by slices (report Appendix B,
fortran/contact/line_slices.f90), roller and inner race quasi-static equilibrium
(fortran/quasistatic/roller_equilibrium.f90) and the deck-to-result driver
(fortran/start/roller_step0.f90), against the report's printed step 0
(golden/appendix_d_roller.prt) and against independent closed forms.

Tolerances are those of the issue: contact loads, stresses, half widths, deflections 1 %,
section 1a slice values 2 %, fits and clearance 1 %.  Every comparison names its worst
element and error in the assertion message; `pytest -s` prints them all.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pyadore import AdoreInputError
from pyadore.printout import read_print

import probes


ROOT = Path(__file__).resolve().parents[1]
DECK = ROOT / "decks" / "appendix_d_roller.inp"
RPM = 30 / math.pi
LENGTH_SCALE = 4.0e-3   # echo SCALE FACTORS LENGTH (m) = D/2

# Appendix D roller and races (deck Rec 5B, 8.x)
D, L, LAND, CROWN, CORNER = 8.0e-3, 8.0e-3, 2.0e-3, 0.25, 2.5e-4
E_STAR = 1.0 / ((1 - 0.26**2) / 3.1e11 + (1 - 0.25**2) / 2.0e11)   # Si3N4 roller on steel


@pytest.fixture(scope="module")
def step0():
    return probes.roller_step0_from_deck(DECK)


@pytest.fixture(scope="module")
def golden():
    return read_print(ROOT / "golden" / "appendix_d_roller.prt").steps[0]


def worst(run, ref, label):
    """Largest relative error over the known, non-zero reference values and a message."""
    run = np.asarray(run, dtype=float)
    ref = np.asarray(ref, dtype=float)
    known = ~np.isnan(ref) & (ref != 0)
    assert known.sum() >= 2, label
    rel = np.abs(run[known] - ref[known]) / np.abs(ref[known])
    k = int(np.flatnonzero(known)[rel.argmax()])
    msg = f"{label}: worst {rel.max():.4%} at element {k + 1} (run {run[k]:.5e}, report {ref[k]:.4e})"
    print(msg)
    return rel.max(), msg


# --- section 1: rolling element parameters ------------------------------------------------

COLUMNS = [  # (engine key, golden table, golden column, factor)
    ("q_o", "re_contact", "contact_load_outer_N", 1.0),
    ("q_i", "re_contact", "contact_load_inner_N", 1.0),
    ("p_o", "re_contact", "contact_stress_outer_Pa", 1.0),
    ("p_i", "re_contact", "contact_stress_inner_Pa", 1.0),
    ("a_o", "re_contact", "major_half_width_outer_m", 1.0),
    ("a_i", "re_contact", "major_half_width_inner_m", 1.0),
    ("b_o", "re_contact", "minor_half_width_outer_m", 1.0),
    ("b_i", "re_contact", "minor_half_width_inner_m", 1.0),
    ("delta_o", "re_thermal", "contact_deflection_outer_m", 1.0),
    ("orbital_speed", "re_motion", "orbital_velocity_rpm", RPM),
]


@pytest.mark.parametrize("key,table,column,factor", COLUMNS, ids=[c[2] for c in COLUMNS])
def test_step0_column_matches_report(step0, golden, key, table, column, factor):
    rollers, _, _ = step0
    ref = golden.table(table)[column].astype(float).to_numpy()
    assert len(ref) == len(rollers[key]) == 8
    err, msg = worst(rollers[key] * factor, ref, column)
    assert err <= 0.01, msg


def test_step0_roller_spin_matches_report(step0, golden):
    # printed as amplitude 1.817e5 rpm about theta = 180 deg (the -x direction)
    rollers, _, _ = step0
    motion = golden.table("re_motion")
    assert np.all(rollers["spin_speed"] < 0)
    assert np.all(motion["ang_vel_theta_deg"].astype(float).to_numpy() == 180.0)
    err, msg = worst(-rollers["spin_speed"] * RPM, motion["ang_vel_amplitude_rpm"], "ang_vel_amplitude_rpm")
    assert err <= 0.01, msg


LOADED_OR_FAR = [0, 1, 3, 4, 5, 7]   # rollers 1, 2, 4, 5, 6, 8
NEAR_ZERO = [2, 6]                    # rollers 3 and 7 (90 and 270 deg)


def test_step0_inner_deflection_matches_report(step0, golden):
    rollers, _, _ = step0
    ref = golden.table("re_thermal")["contact_deflection_inner_m"].astype(float).to_numpy()
    err, msg = worst(rollers["delta_i"][LOADED_OR_FAR], ref[LOADED_OR_FAR], "contact_deflection_inner_m (1,2,4-6,8)")
    assert err <= 0.01, msg


@pytest.mark.xfail(strict=True, reason=(
    "rollers 3/7 inner contact (no contact): run -1.511e-7 m vs report -1.534e-7 m (1.5 %). The value is "
    "the difference of the contact-geometry clearance term (2.261e-6 m) and the outer deflection (2.412e-6 m, "
    "0.05 % low because K_L is 0.05 % high): a 2.3e-9 m absolute gap, i.e. 1e-4 of the doubled raceway growth "
    "(4.45e-5 m) the geometry is built from.  Belief: ADORE's growth/clearance differs from the Lame+rotating-disc "
    "mounting (or the 'applied twice' rule) at the 1e-9 m level, which the printed 4 digits cannot resolve."))
def test_step0_inner_no_contact_clearance_matches_report(step0, golden):
    rollers, _, _ = step0
    ref = golden.table("re_thermal")["contact_deflection_inner_m"].astype(float).to_numpy()
    err, msg = worst(rollers["delta_i"][NEAR_ZERO], ref[NEAR_ZERO], "contact_deflection_inner_m (3,7)")
    assert err <= 0.01, msg


# --- section 1a: load distribution along roller 1 -----------------------------------------

SLICE_COLUMNS = [  # (engine key, golden column, factor)
    ("x_o", "axial_pos_outer_m", 1.0),
    ("delta_o", "geo_int_outer_m", 1.0),
    ("b_o", "half_width_outer_m", 1.0),
    # The report prints the outer race's normal load per unit length times the length
    # scale (4.0e-3 m): its half widths in the same rows are the Hertz widths of 250x the
    # printed value, and 250x the column integrates to the outer contact load 769.3 N.
    ("q_o", "normal_load_outer_N_m", LENGTH_SCALE),
    # The inner contact's axial coordinate runs the other way (slice 1 at +1.715e-3 m).
    ("x_i", "axial_pos_inner_m", -1.0),
    ("delta_i", "geo_int_inner_m", 1.0),
    ("b_i", "half_width_inner_m", 1.0),
    ("q_i", "normal_load_inner_N_m", 1.0),
]


@pytest.mark.parametrize("key,column,factor", SLICE_COLUMNS, ids=[c[1] for c in SLICE_COLUMNS])
def test_section_1a_slices_match_report(step0, golden, key, column, factor):
    _, slices, _ = step0
    ref = golden.table("slices_1")[column].astype(float).to_numpy()
    assert len(ref) == 12
    err, msg = worst(slices[key][0] * factor, ref, column)
    assert err <= 0.02, msg


# --- sections 2 and 3: mounting, inner race --------------------------------------------------

def test_section_3_fits_and_clearance_match_report(step0):
    _, _, s = step0
    assert s["outer_fit"] == 0.0
    for key, ref in [("inner_fit", 5.743e-06), ("clearance", 1.774e-05)]:
        err = abs(s[key] - ref) / ref
        print(f"{key}: {err:.4%}")
        assert err <= 0.01, f"{key}: run {s[key]:.5e}, report {ref:.4e}"


def test_inner_race_displacement_and_load_match_report(step0):
    _, _, s = step0
    radial = math.hypot(s["u_y"], s["u_z"])        # section 2, IRace radial 7.758e-6 m
    assert radial == pytest.approx(7.758e-6, rel=0.01)
    assert s["inner_force_z"] == pytest.approx(-1.000e3, rel=0.01)   # section 3, Int IRace
    print(f"IRace radial: {abs(radial - 7.758e-6) / 7.758e-6:.4%}")


def test_inner_race_radial_load_balance(step0):
    _, _, s = step0
    applied = 1000.0
    assert abs(s["inner_force_y"]) / applied <= 1e-8
    assert abs(s["inner_force_z"] + applied) / applied <= 1e-8
    assert max(abs(s["race_residual_y"]), abs(s["race_residual_z"])) / applied <= 1e-8


def test_every_roller_in_radial_equilibrium(step0):
    rollers, _, s = step0
    assert s["max_roller_residual"] <= 1e-8 * rollers["centrifugal"].min()
    assert np.allclose(rollers["q_o"] - rollers["q_i"], rollers["centrifugal"], rtol=1e-10, atol=0)
    assert np.all(np.abs(rollers["tilt"]) < 1e-12)   # symmetric profile, no misalignment


def test_unloaded_rollers_carry_their_centrifugal_force(step0):
    # report: 2.453e2 N on the outer race at 70 000 rpm; crowned-roller mass (echo 1.28108e-3 kg)
    rollers, _, _ = step0
    mass = rollers["centrifugal"] / (rollers["orbital_speed"] ** 2 * rollers["r"])
    assert mass == pytest.approx(1.28108e-3, rel=1e-4)
    assert rollers["q_o"][2:7] == pytest.approx(245.3, rel=0.01)


def test_consistent_clearance_option(step0):
    # growth_count=1: contact geometry clearance is the printed operating clearance
    _, _, s1 = probes.roller_step0_from_deck(DECK, growth_count=1)
    assert s1["contact_clearance"] == pytest.approx(s1["clearance"], rel=1e-12)
    _, _, s2 = step0
    assert s2["contact_clearance"] == pytest.approx(s2["clearance"] - 2 * s2["inner_raceway_growth"], rel=1e-12)
    assert abs(s1["inner_force_z"] + 1000.0) <= 1e-8 * 1000.0


#: light loads (F_y, F_z) in N: along a roller's diameter (one roller takes it, the race has no
#: stiffness across: the Newton step used to cycle through the clearance), and a light load
#: across a diameter that needs a second roller; the applied load is far below one roller's
#: centrifugal force (245 N)
LIGHT_LOADS = [(0.0, -1.0), (0.0, 1.0), (0.0, 0.01), (1.0, 0.01), (-0.5, 0.3), (0.7, 0.7)]


@pytest.mark.parametrize("force", LIGHT_LOADS)
def test_light_radial_load_converges_to_equilibrium(tmp_path, force):
    """The roller start converges for loads of ~1 N (the ±1 N runs failed "inner race Newton
    iterations did not converge"), and the rollers' force on the inner race balances the
    applied load to 1e-10 of the largest roller load."""
    from pyadore.deck import read_deck

    deck = read_deck(DECK)
    deck.set("9.1.1", "applied_force_y", force[0])
    deck.set("9.1.1", "applied_force_z", force[1])
    path = tmp_path / "light.inp"
    deck.save(path)
    rollers, _, s = probes.roller_step0_from_deck(path)
    scale = rollers["q_o"].max()
    assert abs(s["inner_force_y"] + force[0]) <= 1e-10 * scale
    assert abs(s["inner_force_z"] + force[1]) <= 1e-10 * scale
    assert rollers["q_i"].max() > 0.0
    assert s["max_roller_residual"] <= 1e-8 * rollers["centrifugal"].min()


def test_ball_deck_is_refused_by_the_roller_path():
    with pytest.raises(AdoreInputError, match="not a roller-bearing deck"):
        probes.roller_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")


# --- independent truth: closed-form line contacts and a fine quadrature ----------------------

def palmgren_q(delta: float, length: float, e_star: float) -> float:
    """Palmgren's steel relation delta[mm] = 3.84e-5 Q[N]**0.9 / l[mm]**0.8 solved for Q (N),
    scaled linearly in the contact modulus against steel E = 206 GPa, nu = 0.3."""
    e_steel = 2.06e11 / (2 * (1 - 0.3**2))
    q_steel = (delta * 1e3 * (length * 1e3) ** 0.8 / 3.84e-5) ** (1 / 0.9)
    return q_steel * e_star / e_steel


def r_eq_outer():
    r_o = 0.5 * (43e-3 + 8e-3 + 0.5 * 40e-6)
    return 1 / (2 / D - 1 / r_o)


@pytest.mark.parametrize("delta", [1e-6, 5e-6, 2e-5])
def test_uncrowned_roller_is_palmgren(delta):
    """Straight roller, no corners, slice reference length = roller length: the slice
    model must give Palmgren's closed form for the whole roller."""
    length = 0.01
    _, c = probes.line_contact([length, length, 1e10, 0, 0], 1e10, [delta, 0, 0], [-length / 2, length / 2],
                              E_STAR, r_eq_outer(), l_ref=length)
    ref = palmgren_q(delta, length, E_STAR)
    print(f"Palmgren straight roller delta={delta:g}: {abs(c['load'] / ref - 1):.2e}")
    assert c["load"] == pytest.approx(ref, rel=0.02)
    assert c["half_length"] == pytest.approx(length / 2, rel=1e-12)


@pytest.mark.parametrize("delta", [2e-6, 1e-5])
def test_uncrowned_roller_with_corners_is_palmgren_of_effective_length(delta):
    """Corner radii remove the ends: Palmgren with l_eff = l - 2 r_c (Harris) within 2 %
    (the part of the corner arcs still in contact is the difference)."""
    length, rc = 0.01, 2.5e-4
    l_eff = length - 2 * rc
    k_line = palmgren_q(1.0, l_eff, E_STAR) / l_eff     # q = k delta**(10/9) at l_ref = l_eff
    _, c = probes.line_contact([length, length, 1e10, rc, rc], 1e10, [delta, 0, 0], [-length / 2, length / 2],
                              E_STAR, r_eq_outer(), k_line=k_line, n_sub=40)
    ref = palmgren_q(delta, l_eff, E_STAR)
    print(f"Palmgren with corners delta={delta:g}: {abs(c['load'] / ref - 1):.3%}")
    assert c["load"] == pytest.approx(ref, rel=0.02)


def test_slice_half_width_and_pressure_are_hertz():
    """Hertz line contact (Johnson eq. 4.43): b = sqrt(8 q R'/(pi E')), E' = 2 E*, p0 = 2 q/(pi b)."""
    slices, c = probes.line_contact([L, LAND, CROWN, CORNER, CORNER], 1e10, [5e-6, 0, 0], [-L / 2, L / 2],
                                   E_STAR, r_eq_outer(), l_ref=LENGTH_SCALE)
    b = np.sqrt(8 * slices["q"] * r_eq_outer() / (math.pi * 2 * E_STAR))
    assert slices["b"] == pytest.approx(b, rel=1e-12)
    assert c["peak_pressure"] == pytest.approx((2 * slices["q"] / (math.pi * slices["b"])).max(), rel=1e-12)
    # ADORE's contact stress: Q / (pi a b_mean)
    assert c["stress"] == pytest.approx(c["load"] / (math.pi * c["half_length"] * c["mean_half_width"]), rel=1e-12)


def crowned_profile(x):
    """The crowned profile, written independently of the engine (land, crown arc centred on
    the mid-plane, corner arcs)."""
    ax = np.abs(x)
    drop = np.where(ax > LAND / 2, (ax**2 - (LAND / 2) ** 2) / (2 * CROWN), 0.0)
    s = ax - (L / 2 - CORNER)
    return drop + np.where(s > 0, CORNER - np.sqrt(np.clip(CORNER**2 - s**2, 0, None)), 0.0)


@pytest.mark.parametrize("delta,tilt", [(2.4e-6, 0.0), (5.7e-6, 0.0), (2e-5, 0.0), (5e-6, 5e-4)])
def test_slice_integration_against_fine_quadrature(delta, tilt):
    """The 12 slices of ADORE's grid against a 400 000-point trapezoid of the same profile
    (and the engine's own 400-zone Gauss rule): load and moment."""
    k_line = 1.7e11
    slices, c = probes.line_contact([L, LAND, CROWN, CORNER, CORNER], 1e10, [delta, tilt, 0], [-L / 2, L / 2],
                                   E_STAR, r_eq_outer(), k_line=k_line)
    assert len(slices["x"]) == 12
    x = np.linspace(-L / 2, L / 2, 400_001)
    d = delta + tilt * x - crowned_profile(x)
    q = k_line * np.clip(d, 0, None) ** (10 / 9)
    load, moment = np.trapezoid(q, x), np.trapezoid(q * x, x)
    _, fine = probes.line_contact([L, LAND, CROWN, CORNER, CORNER], 1e10, [delta, tilt, 0], [-L / 2, L / 2],
                                 E_STAR, r_eq_outer(), k_line=k_line, n_sub=400)
    print(f"slices vs fine quadrature delta={delta:g} tilt={tilt:g}: load {abs(c['load'] / load - 1):.3%}")
    assert fine["load"] == pytest.approx(load, rel=1e-6)
    assert c["load"] == pytest.approx(load, rel=0.01)   # observed worst 0.49 % (delta 2.4e-6: land-edge kink)
    if tilt:
        assert fine["moment"] == pytest.approx(moment, rel=1e-5)
        assert c["moment"] == pytest.approx(moment, rel=0.02)
    # contact ends: delta = 0 there
    ends = np.array([c["x1"], c["x2"]])
    assert np.abs(delta + tilt * ends - crowned_profile(ends)).max() <= 1e-15 + 1e-12 * delta


def test_no_contact_reports_largest_interaction():
    slices, c = probes.line_contact([L, LAND, CROWN, CORNER, CORNER], 1e10, [-1e-6, 0, 0], [-L / 2, L / 2],
                                   E_STAR, r_eq_outer(), l_ref=LENGTH_SCALE)
    assert c["in_contact"] == 0.0 and c["load"] == 0.0
    assert c["max_deflection"] == pytest.approx(-1e-6, rel=1e-12)
    assert np.all(slices["q"] == 0)


def test_line_contact_rejects_bad_input():
    with pytest.raises(AdoreInputError):
        probes.line_contact([L, LAND, -1.0, 0, 0], 1e10, [1e-6, 0, 0], [-L / 2, L / 2], E_STAR, 1e-3, l_ref=1e-3)


# --- section 3: basic fatigue life (eqs 73, 75, 76, 102; fortran/life/roller.f90) ------

REPORT_BASIC_LIFE_H = 136.9   # "Basic Fatigue Life (hours) 1.369E+02", report line 3898


@pytest.mark.xfail(strict=True, reason=(
    "roller basic life not reproduced: 1213.5 h (outer 3126, inner 1767) against the "
    "report's 136.9 h (+786 %) with l of eq 76 = the contact length, as the report's text "
    "defines it; l = half the contact length would give 140.4 h (+2.6 %), see "
    "docs/life-model.md 'Roller bearings' R3"))
def test_basic_life_reproduces_the_report(step0, golden):
    """Within 3 % (issue "Roller step 0")."""
    _, _, s = step0
    perf = golden.table("performance")
    assert float(perf["basic_fatigue_life_hours"].iloc[0]) == REPORT_BASIC_LIFE_H
    err = s["basic_life_h"] / REPORT_BASIC_LIFE_H - 1
    print(f"basic life: run {s['basic_life_h']:.1f} h (outer {s['basic_life_outer_h']:.1f}, "
          f"inner {s['basic_life_inner_h']:.1f}), report {REPORT_BASIC_LIFE_H} h, {err:+.2%}")
    assert abs(err) <= 0.03


def test_basic_life_half_length_hypothesis(step0):
    """Record of the hypothesis of R3: every contact's Q_c scales as l**(7/9) and N as
    Q_c**p (p = 4), race and bearing lives (eq 102) are homogeneous, so halving l of eq 76
    multiplies the life by 2**(-28/9) exactly; that lands within 3 % of the report."""
    _, _, s = step0
    hypothesis = s["basic_life_h"] * 2.0 ** (-28 / 9)
    assert hypothesis == pytest.approx(REPORT_BASIC_LIFE_H, rel=0.03)


def test_basic_life_race_combination_eq102(step0):
    """The bearing life is eq 102 of the two race lives with e = 9/8 (line contact)."""
    _, _, s = step0
    e = 9 / 8
    by_hand = (s["basic_life_outer_h"] ** -e + s["basic_life_inner_h"] ** -e) ** (-1 / e)
    assert s["basic_life_h"] == pytest.approx(by_hand, rel=1e-12)
    assert s["basic_life_h"] < min(s["basic_life_outer_h"], s["basic_life_inner_h"])


@pytest.mark.parametrize("z", [8, 16])
def test_radial_load_distribution_of_straight_rollers(tmp_path, z):
    """Published case: zero clearance, straight rollers at rest under a radial load carry
    Q_k = Q_max cos(phi_k)**(10/9) (q ~ delta**(10/9) along the roller), so
    F_r = sum Q_k cos(phi_k) fixes Q_max exactly; for many rollers this is the classical
    Q_max = 4.08 F_r / Z of line contacts (Harris & Kotzalas, Rolling Bearing Analysis,
    'radially loaded roller bearing', zero clearance).  The Appendix D deck is modified
    with pyadore.deck: no crown, ~no corner radii, no play, no fit, no speed, Z rollers."""
    from pyadore.deck import read_deck

    deck = read_deck(ROOT / "decks" / "appendix_d_roller.inp")
    deck.set("3.2", "n_rolling_elements", z)
    deck.set("5B", "crown_radius", 1.0e10)
    deck.set("5B", "corner_radius_1", 1.0e-6)
    deck.set("5B", "corner_radius_2", 1.0e-6)
    deck.set("5B", "diametral_play", 0.0)
    deck.set("9.0", "inner_race_fit", 0.0)
    deck.set("9.1.2", "inner_race_speed", 0.0)
    path = tmp_path / "straight.inp"
    deck.save(path)
    balls, _, _ = probes.roller_step0_from_deck(path)
    fr = deck.get("9.1.1", "applied_force_z")
    phi = 2 * math.pi * np.arange(z) / z
    cos = np.clip(np.cos(phi), 0.0, None)
    q_max = fr / np.sum(cos ** (19 / 9))
    assert balls["q_i"] == pytest.approx(q_max * cos ** (10 / 9), rel=1e-4, abs=1e-4 * q_max)
    assert balls["q_i"][0] * z / fr == pytest.approx(4.08, rel=0.02)
