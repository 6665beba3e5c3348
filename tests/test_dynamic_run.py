"""The opt-in time loop of ball bearings (issue #20 [Dynamics], items 5 and 7).

`adore DECK --steps N`, `pyadore run DECK --steps N` and `pyadore.run(deck, steps=N)`
integrate N time steps of a ball deck after step 0 and print them (ADORE 5.0 layout,
termination line, "Statistics of this Run"); the default run keeps ending after step 0.
Runs are short (30 steps of Appendix C take about 0.1 s).
"""

from __future__ import annotations

import math
import subprocess

import numpy as np
import pytest
from click.testing import CliRunner

import pyadore
from pyadore.cli import cli
from pyadore.errors import AdoreEngineError, AdoreInputError
from pyadore.printout import read_print

N = 30
#: Appendix C echo: TIME scale (s) and the inner race speed (rpm); Rec 2.1 MINIMUM, MAXIMUM
TIME_SCALE = 2.43679e-4
INNER_RPM = 20000.0
STEP_MIN, STEP_MAX = 5.0e-3, 3.0e-1
MARKER = "DYNAMICS IN PROGRESS (ISSUE #20)"


def _exe(adore_exe, *args):
    return subprocess.run([str(adore_exe), *map(str, args)], capture_output=True, text=True, timeout=600)


@pytest.fixture(scope="module")
def runs(tmp_path_factory, ball_deck, adore_exe):
    """Appendix C: default run, step-0 run, N steps through f2py and through `adore`."""
    out = tmp_path_factory.mktemp("dynrun")
    res = {
        "default": pyadore.run(ball_deck, out=out / "default.prt"),
        "zero": pyadore.run(ball_deck, steps=0, out=out / "zero.prt"),
        "dyn": pyadore.run(ball_deck, steps=N, out=out / "dyn.prt"),
    }
    res["exe"] = _exe(adore_exe, ball_deck, out / "exe.prt", "--steps", N)
    res["exe_path"] = out / "exe.prt"
    return res


def test_default_run_is_step_0_only_and_says_dynamics_is_opt_in(runs):
    default, zero = runs["default"], runs["zero"]
    assert default.print_path.read_bytes() == zero.print_path.read_bytes()
    assert MARKER not in default.text
    assert list(read_print(default.print_path).steps) == [0]
    assert default.notes and "opt-in (--steps N)" in default.notes[0] and "ends after step 0" in default.notes[0]
    assert zero.notes == []


def test_dynamic_print_starts_with_the_default_print(runs):
    """The dynamic print is the default print plus the listing's dynamics lines and the
    time steps: step 0 and everything before it are byte-identical."""
    dyn = runs["dyn"].text.splitlines(keepends=True)
    default = runs["default"].text.splitlines(keepends=True)
    assert dyn[2].startswith(MARKER) and f"; {N} TIME STEPS" in dyn[2]
    assert "NOT A VALIDATED ADORE RUN" in dyn[3] and dyn[4] == "\n"
    assert dyn[:2] + dyn[5:5 + len(default) - 2] == default
    assert runs["dyn"].notes == ["dynamics in progress (issue #20): no cage contacts, thermal model off"]


def test_f2py_and_standalone_prints_are_identical(runs):
    proc = runs["exe"]
    assert proc.returncode == 0, proc.stderr
    assert "dynamics in progress (issue #20)" in proc.stderr
    assert runs["exe_path"].read_bytes() == runs["dyn"].print_path.read_bytes()


def test_step_n_has_sections_1_to_4_termination_and_statistics(runs):
    run = read_print(runs["dyn"].print_path)
    assert list(run.steps) == [0, N]       # Rec 1 data_control_2 = 500: only the last step
    step = run.steps[N]
    for name in ("re_contact", "re_motion", "re_traction", "re_thermal", "re_cage", "race_cage", "bodies",
                 "loads", "accelerations", "performance", "summary"):
        assert name in step.tables
    assert len(step.table("re_contact")) == 18
    text = runs["dyn"].text
    assert f"Normal termination: Last Step Number = {N:7d}" in text
    assert run.termination["last_step_number"] == N
    tau = step.header["tau"]
    assert run.termination["final_time"] == pytest.approx(tau, rel=1e-3)
    # header and summary: time = tau T, inner race rotation = speed x time
    assert step.header["time_s"] == pytest.approx(tau * TIME_SCALE, rel=2e-3)
    assert step.header["inner_race_rot_rev"] == pytest.approx(INNER_RPM / 60 * step.header["time_s"], rel=2e-3)
    assert step.header["outer_race_rot_rev"] == 0.0
    summary = step.table("summary").iloc[0]
    assert summary["time_s"] == pytest.approx(step.header["time_s"], rel=1e-3)
    # the integrator's statistics: steps within Rec 2.1, the truncation an error estimate
    st = run.statistics
    assert STEP_MIN <= st["minimum_step_size"] <= st["last_step_size"] <= st["maximum_step_size"] <= STEP_MAX
    assert N * st["minimum_step_size"] <= tau <= N * st["maximum_step_size"] * 1.00001
    assert 0 < st["max_truncation"]
    # Dormand-Prince with FSAL: 1 + 6 derivative calls per attempt, at least one attempt a step
    calls = int(st["total_derivative_calls"])
    assert calls >= 1 + 6 * N and (calls - 1) % 6 == 0


def test_step_n_stays_near_step_0(runs):
    """Early in the run the bearing hardly moves: every ball's contact loads within 5 % of
    step 0's load distribution at the azimuth the ball has reached, the mean orbital
    velocity within 2 %, the balls advanced by their orbital speed, the power loss and the
    orbital velocity ratio near step 0's.

    The balls move about 27 deg in N = 30 steps, more than the 20 deg between two balls, and
    Appendix C's combined load makes a ball's load depend on its azimuth (the inner contact
    by up to 19 % over those 27 deg): the step-0 loads are interpolated (periodically,
    linearly over the 18 balls) at each ball's step-N azimuth (measured: within 2.6 %)."""
    run = read_print(runs["dyn"].print_path)
    s0, sn = run.steps[0], run.steps[N]
    c0, cn = s0.table("re_contact"), sn.table("re_contact")
    az0 = c0["orbital_position_deg"].to_numpy()
    az = cn["orbital_position_deg"].to_numpy() % 360
    for col in ("contact_load_outer_N", "contact_load_inner_N"):
        q0 = c0[col].to_numpy()
        expected = np.interp(az, np.r_[az0, 360.0], np.r_[q0, q0[0]])
        ratio = cn[col].to_numpy() / expected
        assert np.all(np.abs(ratio - 1) < 0.05), (col, ratio)
    w0 = s0.table("re_motion")["orbital_velocity_rpm"].to_numpy()
    wn = sn.table("re_motion")["orbital_velocity_rpm"].to_numpy()
    assert abs(wn.mean() / w0.mean() - 1) < 0.02
    # orbital positions: cumulative, advanced by about the orbital speed over the time
    advance = cn["orbital_position_deg"].to_numpy() - c0["orbital_position_deg"].to_numpy()
    expected = w0.mean() / 60 * 360 * sn.header["time_s"]
    assert np.all(np.abs(advance / expected - 1) < 0.05), advance
    # every loaded contact has its loss and spin/roll; no made-up columns
    mot = sn.table("re_motion")
    assert np.all(np.isfinite(mot["contact_loss_outer_W"])) and np.all(mot["contact_loss_outer_W"] > 0)
    assert np.all(np.isnan(mot["wear_rate_m3_s"]))
    assert np.all(np.isnan(sn.table("re_traction").to_numpy()))
    summary_0, summary_n = s0.table("summary").iloc[0], sn.table("summary").iloc[0]
    assert summary_n["power_loss_W"] == pytest.approx(sn.table("performance").iloc[0]["total_power_loss_W"])
    assert summary_n["power_loss_W"] == pytest.approx(summary_0["power_loss_W"], rel=0.10)
    ratio_col = "re_orbital_vel_ratio"
    assert summary_n[ratio_col] == pytest.approx(wn.mean() / INNER_RPM, rel=2e-3)
    assert summary_n[ratio_col] == pytest.approx(summary_0[ratio_col], rel=0.02)
    assert math.isnan(summary_n["fatigue_life_hours"])
    # section 3: the outer race's support carries the balls' load and its weight
    loads = sn.table("loads")
    np.testing.assert_allclose(loads.loc["Ext ORace", "force_x_N"], -loads.loc["Int ORace", "force_x_N"])


def test_print_interval_of_rec_1(tmp_path, ball_deck):
    """Every data_control_2-th step is printed, and always the last."""
    lines = ball_deck.read_text().splitlines(keepends=True)
    assert lines[0].startswith("Rec 1") and "   500 " in lines[0]
    deck = tmp_path / "every10.inp"
    deck.write_text(lines[0].replace("   500 ", "    10 ", 1) + "".join(lines[1:]))
    run = read_print(pyadore.run(deck, steps=25, out=tmp_path / "every10.prt").print_path)
    assert list(run.steps) == [0, 10, 20, 25]
    assert run.termination["last_step_number"] == 25


def test_cli_steps_runs_the_dynamics(tmp_path, ball_deck):
    out = tmp_path / "cli.prt"
    result = CliRunner().invoke(cli, ["run", str(ball_deck), "-o", str(out), "--steps", "3"])
    assert result.exit_code == 0, result.output
    assert list(read_print(out).steps) == [0, 3]
    assert "dynamics in progress" in result.output


def test_roller_deck_with_steps_ends_after_step_0(tmp_path, roller_deck, adore_exe):
    res = pyadore.run(roller_deck, steps=5, out=tmp_path / "r5.prt")
    zero = pyadore.run(roller_deck, steps=0, out=tmp_path / "r0.prt")
    assert res.print_path.read_bytes() == zero.print_path.read_bytes()
    assert res.notes and "roller bearings is not implemented" in res.notes[0]
    proc = _exe(adore_exe, roller_deck, tmp_path / "r5exe.prt", "--steps", 5)
    assert proc.returncode == 0 and "roller bearings is not implemented" in proc.stderr


def _int_method_4(text):
    line1 = text.splitlines()[0]
    return text.replace(line1, line1[:-1] + "4", 1)


def _fixed_step_5(text):
    return text.replace("Rec 2.1      5.0000E-02 5.0000E-03 3.0000E-01", "Rec 2.1      5.0000E+00 5.0000E+00 5.0000E+00", 1)


@pytest.mark.parametrize("edit, status, error, message", [
    # INT METHOD 4 is used only by the dynamics: an input error naming the field
    (_int_method_4, 1, AdoreInputError, "Rec 1 field int_method = 4"),
    # Rec 2.1 MINIMUM = MAXIMUM = INITIAL = 5 tau (about 1.2 ms, a fifth of a ball's orbit):
    # the first step drives the contacts out of the model's range
    (_fixed_step_5, 2, AdoreEngineError, "integration stopped"),
], ids=["unknown-int-method", "failed-integration"])
def test_dynamics_error_leaves_no_print(tmp_path, ball_deck, adore_exe, edit, status, error, message):
    """A dynamic run that cannot start or stops midway: exit status 1 (input) or 2 (engine),
    the cause in the message, no print file nor its .part; the default run of the same deck
    (step 0 only) still succeeds."""
    text = ball_deck.read_text()
    assert edit(text) != text
    deck = tmp_path / "edited.inp"
    deck.write_text(edit(text))
    proc = _exe(adore_exe, deck, tmp_path / "exe.prt", "--steps", 5)
    assert proc.returncode == status
    assert message in proc.stderr
    with pytest.raises(error, match=message):
        pyadore.run(deck, steps=5, out=tmp_path / "py.prt")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["edited.inp"]
    assert _exe(adore_exe, deck, tmp_path / "default.prt").returncode == 0


def test_basic_life_of_a_dynamic_step_follows_its_printed_loads(runs):
    """The basic life printed at a dynamic step (section 3) is eqs 73-74 and 102 of the
    loads, contact angles and orbital speeds printed at that step (to print precision:
    4 digits, life ~ Q**-3)."""
    from pyadore._core import ball_bearing_life

    step = read_print(runs["dyn"].print_path).step(N)
    c, mo = step.table("re_contact"), step.table("re_motion")
    ones = np.ones(len(c))
    life = ball_bearing_life(
        c["contact_load_outer_N"].to_numpy(float), c["contact_load_inner_N"].to_numpy(float),
        np.radians(c["contact_angle_outer_deg"].to_numpy(float)), np.radians(c["contact_angle_inner_deg"].to_numpy(float)),
        mo["orbital_velocity_rpm"].to_numpy(float), 1.5e9 * ones, 1.5e9 * ones, d_ball=1.905e-2, d_pitch=0.140,
        f_outer=0.52, f_inner=0.54, outer_speed=0.0, inner_speed=INNER_RPM)
    printed = float(step.table("performance")["basic_fatigue_life_hours"].iloc[0])
    assert math.isfinite(printed)
    assert printed == pytest.approx(life["basic"], rel=3e-3)
