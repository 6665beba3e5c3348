"""Golden-output regression of whole runs: the engine's print file of each appendix deck
against the report's print (golden/*.prt) with the tolerances of golden/tolerances.toml.

Only what the engine computes so far is gated: the input echo and the step-0 mechanics
of the ball bearing (issue "Ball step 0").  Everything else prints NaN ("not computed")
or is absent (later steps), and the diff counts it as such - the whole-file diff still
fails, honestly, until the remaining issues land.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import pyadore
from pyadore.diff import diff_prints

ROOT = Path(__file__).resolve().parents[1]

#: Step-0 cells both bearing types compute: the section 4 speed ratios and the initial
#: temperatures of Rec 2.7 (docs/print-layout.md).
STEP0_SECTION4_AND_TEMPERATURES = [
    ("summary", "re_orbital_vel_ratio"),
    ("summary", "cage_omega_ratio"),
    ("summary", "cage_whirl_ratio"),
    ("re_thermal", "bulk_temp_K"),
    ("accelerations", "bulk_temp_K"),
    ("performance", "hsng_bulk_temp_K"),
    ("performance", "hsng_outer_temp_K"),
    ("performance", "hsng_inner_temp_K"),
    ("performance", "shft_bulk_temp_K"),
    ("performance", "shft_outer_temp_K"),
    ("performance", "shft_inner_temp_K"),
]

#: Section 2's bodies columns but the hoop stress (the cage's is not computed; the ball
#: report prints 0 for it): cage state (tests/test_cage_step0.py) and the race rows
#: (output/step_report.f90 race_rows; Archard race wear).
BODY_COLUMNS_BUT_HOOP = ["mc_pos_axial_m", "mc_pos_radial_m", "mc_pos_orbital_deg", "orbital_velocity_rpm",
                         "ang_vel_amplitude_rpm", "ang_vel_theta_deg", "ang_vel_phi_deg", "ang_pos_theta_deg",
                         "ang_pos_phi_deg", "wear_rate_m3_s"]

#: (table, column) of step 0 that the engine computes for a ball bearing.
BALL_STEP0_COMPUTED = [
    ("re_contact", "*"),
    ("re_thermal", "contact_deflection_outer_m"),
    ("re_thermal", "contact_deflection_inner_m"),
    ("re_motion", "orbital_velocity_rpm"),
    ("re_traction", "trac_coeff_inner"),
    ("re_motion", "contact_loss_inner_W"),
    ("re_motion", "contact_loss_outer_W"),
    ("re_motion", "wear_rate_m3_s"),
    ("summary", "cage_wear_rate_m3_s"),
    *STEP0_SECTION4_AND_TEMPERATURES,
    ("accelerations", "*"),
    ("performance", "total_power_loss_W"),
    ("re_thermal", "contact_temp_rise_outer_K"),
    ("re_thermal", "contact_temp_outer_K"),
    ("re_thermal", "contact_temp_inner_K"),
    ("re_traction", "film_thickness_outer_m"),
    ("re_traction", "film_thickness_inner_m"),
    ("re_traction", "thermal_red_fac_outer"),
    ("re_traction", "thermal_red_fac_inner"),
    ("re_motion", "ang_vel_amplitude_rpm"),
    ("performance", "outer_race_fit_m"),
    ("performance", "inner_race_fit_m"),
    ("performance", "internal_clearance_m"),
    ("performance", "basic_fatigue_life_hours"),
    # contact_pos_x_m: ball 5 is 5.4 % off (xfail in tests/test_cage_step0.py)
    ("re_cage", "geo_int_m"),
    ("re_cage", "contact_force_N"),
    ("re_cage", "con_ang_theta_deg"),
    ("re_cage", "con_ang_phi_deg"),
    ("re_cage", "contact_pos_z_m"),
    ("re_cage", "contact_loss_W"),
    ("re_cage", "wear_rate_m3_s"),
    ("race_cage", "*"),
    *[("bodies", column) for column in BODY_COLUMNS_BUT_HOOP],
]


def _run(tmp_path, deck):
    out = tmp_path / (deck + ".prt")
    pyadore.run(ROOT / "decks" / f"{deck}.inp", steps=0, out=out)
    return out


@pytest.fixture(scope="module")
def ball_report(tmp_path_factory):
    out = _run(tmp_path_factory.mktemp("ball"), "appendix_c_ball")
    return diff_prints(out, ROOT / "golden" / "appendix_c_ball.prt")


@pytest.fixture(scope="module")
def roller_report(tmp_path_factory):
    out = _run(tmp_path_factory.mktemp("roller"), "appendix_d_roller")
    return diff_prints(out, ROOT / "golden" / "appendix_d_roller.prt")


def _selected(report, step_prefix, wanted):
    out = []
    for c in report.comparisons:
        if not c.name.startswith(step_prefix):
            continue
        table = c.table.split()[-1]
        if any(table == t and (col == "*" or c.column == col) for t, col in wanted):
            out.append(c)
    return out


def test_ball_echo_has_no_value_outside_its_printed_precision(ball_report):
    echo = [c for c in ball_report.comparisons if c.name.startswith("echo ")]
    outside = [f"{c.name}: golden {c.golden} run {c.run}" for c in echo if c.status == "outside"]
    assert outside == []
    assert sum(c.status == "within" for c in echo) >= 170


def test_ball_step0_mechanics_within_tolerance(ball_report):
    comps = _selected(ball_report, "step 0 ", BALL_STEP0_COMPUTED)
    compared = [c for c in comps if c.status != "unknown"]
    assert len(compared) >= 250, "the step-0 mechanics columns were not found in the run"
    bad = [f"{c.name}: golden {c.golden} run {c.run} ({c.rel_error:.2%}, {c.tolerance})"
           for c in compared if c.status != "within"]
    assert bad == []


def test_ball_run_reports_what_it_does_not_compute(ball_report):
    """Columns of later issues print NaN and the differ counts them, never as a pass."""
    assert ball_report.exit_code == 1
    not_computed = {c.column for c in ball_report.comparisons if c.status == "not_computed"}
    assert {"convec_htc_W_m2K"} <= not_computed
    assert "rel_axial_pos_m" not in not_computed   # issue #29: computed, a known deviation (origin)
    assert not {"film_thickness_inner_m", "thermal_red_fac_outer", "contact_temp_rise_inner_K"} & not_computed


def test_roller_echo_matches_except_the_roller_mass(roller_report):
    """The roller's mass (and the inertia and time scale derived from it): the engine's
    crowned roller is 4.7e-5 below the echo's 1.28108E-03 kg, outside the printed six
    digits (the plain cylinder would be 0.45 % above; see test_model_echo)."""
    echo = [c for c in roller_report.comparisons if c.name.startswith("echo ")]
    outside = {c.name for c in echo if c.status == "outside"}
    assert outside == {"echo inertial_parameters.re[1]", "echo inertial_parameters.re[2]",
                       "echo inertial_parameters.re[3]", "echo inertial_parameters.re[4]",
                       "echo scale_factors_and_output_controls.time_s"}
    assert sum(c.status == "within" for c in echo) >= 150


ROLLER_STEP0_COMPUTED = [
    ("re_contact", "*"),
    ("re_thermal", "contact_deflection_outer_m"),
    ("re_thermal", "contact_deflection_inner_m"),
    ("re_motion", "orbital_velocity_rpm"),
    ("re_motion", "ang_vel_amplitude_rpm"),
    ("re_motion", "spin_roll_outer"),
    ("re_motion", "spin_roll_inner"),
    ("re_motion", "contact_loss_outer_W"),
    ("re_motion", "contact_loss_inner_W"),
    ("re_motion", "wear_rate_m3_s"),
    *STEP0_SECTION4_AND_TEMPERATURES,
    ("re_traction", "slip_velocity_outer_m_s"),
    ("re_traction", "slip_velocity_inner_m_s"),
    ("re_traction", "trac_coeff_outer"),
    ("re_traction", "trac_coeff_inner"),
    ("slices_1", "axial_pos_outer_m"),
    ("slices_1", "geo_int_outer_m"),
    ("slices_1", "half_width_outer_m"),
    ("slices_1", "axial_pos_inner_m"),
    ("slices_1", "geo_int_inner_m"),
    ("slices_1", "half_width_inner_m"),
    ("slices_1", "normal_load_inner_N_m"),
    ("slices_1", "trac_load_inner_N_m"),
    ("performance", "outer_race_fit_m"),
    ("performance", "inner_race_fit_m"),
    ("performance", "internal_clearance_m"),
    ("re_cage", "contact_force_N"),
    ("re_cage", "con_ang_theta_deg"),
    ("re_cage", "con_ang_phi_deg"),
    ("re_cage", "contact_pos_x_m"),
    ("re_cage", "contact_pos_z_m"),
    ("re_cage", "contact_loss_W"),
    ("re_cage", "wear_rate_m3_s"),
    ("race_cage", "effective_dia_play_m"),
    # flash temperature (tests/test_roller_tribology.py); the outer rise of rollers 3-7 is
    # 5.8 % low and stays out of this list
    ("re_thermal", "contact_temp_rise_inner_K"),
    ("re_thermal", "contact_temp_outer_K"),
    ("re_thermal", "contact_temp_inner_K"),
    ("bodies", "*"),
]


# The two pockets at zero gap (roller 3 end 2, roller 7 end 1) are contacts of unknown force:
# the report's cage row puts 15.16 N on roller 3 end 2 yet prints 0 for roller 7 end 1
# (docs/tribology.md), so the run prints NaN for both; the legible golden 0 of roller 7 end 1
# is then "not computed", never a pass.
ROLLER_TOUCHING_POCKETS = ("re_cage 3/2 ", "re_cage 7/1 ")


def test_roller_step0_mechanics_within_tolerance(roller_report):
    comps = _selected(roller_report, "step 0 ", ROLLER_STEP0_COMPUTED)
    touching = [c for c in comps if any(p in c.name for p in ROLLER_TOUCHING_POCKETS)
                and c.column in ("contact_force_N", "contact_loss_W", "wear_rate_m3_s")]
    assert {c.status for c in touching} <= {"unknown", "not_computed"}
    assert any(c.status == "not_computed" for c in touching)
    compared = [c for c in comps if c.status != "unknown" and c not in touching]
    assert len(compared) >= 200
    bad = [f"{c.name}: golden {c.golden} run {c.run} ({c.rel_error:.2%}, {c.tolerance})"
           for c in compared if c.status != "within"]
    assert bad == []


def test_roller_section_1a_outer_load_is_printed_in_n_per_m(roller_report):
    """Known difference, kept visible: the report's outer 'Nor Load (N/m)' column is the
    load per unit length times the length scale D/2 = 4e-3 m (its own half widths in the
    same rows are the Hertz widths of 250x the printed value, and 250x the column sums to
    the 769.3 N contact load); pyadore prints N/m as the heading says."""
    comps = _selected(roller_report, "step 0 ", [("slices_1", "normal_load_outer_N_m")])
    ratios = [c.run / c.golden for c in comps if c.status != "unknown" and c.golden]
    assert len(ratios) == 12
    assert all(abs(r * 4.0e-3 - 1.0) < 0.01 for r in ratios)


def test_roller_section_1a_outer_traction_is_printed_in_n_per_m(roller_report):
    """Same known difference for the outer 'Trac Load (N/m)' column: the report's values
    are the traction per unit length times D/2 = 4e-3 m (5.749 printed = 0.07979 x 18015
    N/m x 4e-3); pyadore prints N/m.  Zero slices (the land rolls) compare exactly."""
    comps = _selected(roller_report, "step 0 ", [("slices_1", "trac_load_outer_N_m")])
    known = [c for c in comps if c.status != "unknown"]
    assert len(known) == 12
    ratios = [c.run / c.golden for c in known if c.golden]
    assert len(ratios) == 8
    assert all(abs(r * 4.0e-3 - 1.0) < 0.01 for r in ratios)
    assert all(c.run == 0.0 for c in known if not c.golden)


@pytest.mark.parametrize("deck, inner_rpm", [("appendix_c_ball", 20000.0), ("appendix_d_roller", 70000.0)])
def test_section4_ratios_are_the_runs_own_speeds_over_the_inner_race(tmp_path, deck, inner_rpm):
    """Section 4 at step 0: mean RE orbital speed, cage angular and whirl speed over the
    inner race speed (outer race at rest in both decks), from the run's own section 1/2."""
    from pyadore.printout import read_print

    step = read_print(_run(tmp_path, deck)).steps[0]
    summary = step.table("summary").iloc[0]
    cage = step.table("bodies").iloc[0]
    assert summary["re_orbital_vel_ratio"] == pytest.approx(
        step.table("re_motion")["orbital_velocity_rpm"].mean() / inner_rpm, rel=2e-3)   # 4 printed digits
    assert summary["cage_omega_ratio"] == pytest.approx(cage["ang_vel_amplitude_rpm"] / inner_rpm, rel=2e-3)
    assert summary["cage_whirl_ratio"] == pytest.approx(cage["orbital_velocity_rpm"] / inner_rpm, rel=2e-3)


#: Issue #20's acceptance columns at the last step of the full Appendix C run (compared at
#: the golden ball's orbital position, golden/tolerances.toml): contact loads and angles 3 %
#: (the light-zone inner load and outer angle are documented known deviations there),
#: orbital speeds 1 %, total power loss and basic life 10 %.
BALL_FINAL_GATED = [
    ("re_contact", "contact_angle_outer_deg"),
    ("re_contact", "contact_angle_inner_deg"),
    ("re_contact", "contact_load_outer_N"),
    ("re_contact", "contact_load_inner_N"),
    ("re_motion", "orbital_velocity_rpm"),
    ("performance", "total_power_loss_W"),
    ("performance", "basic_fatigue_life_hours"),
]


def test_ball_final_step_within_the_dynamics_tolerances(full_ball_run):
    """The full run's step 2500 against the report's (issue #20): every gated value within
    its tolerance or a documented known deviation, and the deviations only where the
    tolerance file documents them."""
    report = diff_prints(full_ball_run.print_path, ROOT / "golden" / "appendix_c_ball.prt")
    comps = _selected(report, "step 2500 ", BALL_FINAL_GATED)
    compared = [c for c in comps if c.status != "unknown"]
    assert len(compared) >= 80, "the step-2500 columns were not found in the run"
    bad = [f"{c.name}: golden {c.golden} run {c.run} ({c.rel_error:.2%}, {c.tolerance})"
           for c in compared if c.status not in ("within", "deviation")]
    assert bad == []
    deviating = {c.column for c in compared if c.status == "deviation"}
    assert deviating <= {"contact_angle_outer_deg", "contact_load_inner_N"}
    # the documented sizes: the known deviations stay below their measured worst
    worst = max((c.rel_error for c in compared if c.status == "deviation"), default=0.0)
    assert worst < 0.20


#: Step 2500's thermal columns (issue #27 [Thermal]): the only ones a ball run may print NaN.
THERMAL_COLUMNS = {("re_traction", "drag_N"), ("re_traction", "churning_moment_Nm"), ("re_traction", "net_loss_W"),
                   ("re_thermal", "convec_htc_W_m2K"), ("performance", "churning_loss_fraction"),
                   ("performance", "exit_fluid_temp_K")}


def test_ball_final_step_has_no_nan_outside_the_thermal_columns(full_ball_run):
    """Issue #29's acceptance: the full Appendix C print has no NaN at step 2500 outside
    the thermal columns; the columns it added agree with their own definitions
    (docs/print-layout.md, Dynamic steps) and with the report or a documented deviation."""
    from pyadore.printout import read_print

    step = read_print(full_ball_run.print_path).step(2500)
    nan = sorted({(table, col) for table, marks in step.markers.items() if hasattr(marks, "columns")
                  for col in marks.columns if (marks[col] == "not_computed").any()})
    assert len(nan) == len(THERMAL_COLUMNS)       # the tables were found
    assert [c for c in nan if c not in THERMAL_COLUMNS] == []
    t = step.tables
    # section 4's cage wear is the cage row's, the sum of the pockets' and lands' averages
    cage_wear = t["bodies"].loc["Cage", "wear_rate_m3_s"]
    assert t["summary"]["cage_wear_rate_m3_s"].iloc[0] == cage_wear
    parts = t["re_cage"]["wear_rate_m3_s"].sum() + t["race_cage"]["wear_rate_m3_s"].sum()
    assert parts == pytest.approx(cage_wear, rel=2e-3 * 20)   # 20 values of 4 printed digits
    # the cage's hoop stress: the thin rotating ring rho (omega r_m)**2 (Rec 7.1 diameters,
    # the cage's density 7750 kg/m**3 in the echo), at the printed angular velocity
    omega = t["bodies"].loc["Cage", "ang_vel_amplitude_rpm"] * 2.0 * 3.141592653589793 / 60.0
    r_m = 0.25 * (1.30073e-01 + 1.46292e-01)
    assert t["bodies"].loc["Cage", "hoop_stress_Pa"] == pytest.approx(7750.0 * (omega * r_m) ** 2, rel=2e-3)
    # the Palmgren-Miner life since the start: positive and finite; the excursion a
    # distance inside the pocket clearance's reach (pocket clearance 1.2e-3 m, cage offset)
    life = t["summary"]["fatigue_life_hours"].iloc[0]
    assert 0.0 < life < float("inf")
    assert 0.0 < t["summary"]["average_re_excursion_m"].iloc[0] < 5e-3
    # the new columns against the report: within tolerance or the documented deviations
    report = diff_prints(full_ball_run.print_path, ROOT / "golden" / "appendix_c_ball.prt")
    new = _selected(report, "step 2500 ", [("re_thermal", "rel_axial_pos_m"), ("re_cage", "wear_rate_m3_s"),
                                           ("bodies", "ang_pos_theta_deg"), ("bodies", "ang_pos_phi_deg"),
                                           ("race_cage", "*")])   # hoop stress: the races' follow [Thermal]
    compared = [c for c in new if c.status != "unknown"]
    assert len(compared) >= 36
    assert [f"{c.name}: {c.status}" for c in compared if c.status not in ("within", "deviation")] == []


def test_ball_final_pocket_wear_level_against_the_report(full_ball_run):
    """The RE/cage pocket wear at step 2500 (Archard wear of each pocket averaged since the
    start) as a level: the mean over the 18 pockets within a factor 2-4 of the report's (the
    documented deviation: measured 2.80-3.38 over variants of the default run, session 18;
    golden/tolerances.toml) and each pocket within 0.5-2 of the run's own mean (measured
    0.68-1.40; the report's 0.44-1.75).  The per-pocket comparison at matched azimuths is
    that level times both prints' scatter, so it carries a wide known deviation; this is the
    gate on the level."""
    from pyadore.printout import read_print

    run = read_print(full_ball_run.print_path).step(2500).tables["re_cage"]["wear_rate_m3_s"].to_numpy(float)
    report = read_print(ROOT / "golden" / "appendix_c_ball.prt").step(2500).tables["re_cage"][
        "wear_rate_m3_s"].to_numpy(float)
    assert len(run) == len(report) == 18
    assert (run > 0).all() and (report > 0).all()
    assert 2.0 <= run.mean() / report.mean() <= 4.0
    assert 0.5 <= run.min() / run.mean() and run.max() / run.mean() <= 2.0
