"""The roller bearing's time integration (issue #26 [Roller dynamics]) against the report's
Appendix D print.

The report's step 4000 is at tau = 76.18 (5.453 ms); the engine's steps are its own (the
deck's INT METHOD 5 is the IMEX ARK4 here, docs/rollers.md "Roller dynamics"), so its step
4000 is at another time and its rollers at other azimuths.  The comparison with the report is
made at the report's simulated time (`--duration 5.453e-3`), where every roller sits within
0.2 deg of the golden roller's azimuth: contact loads (5 %), orbital speeds (1 %) and the
total power loss (15 %) of each golden roller.  The one full 4000-step run checks the run
itself (termination, derivative calls against ADORE's 43 010, a section 1a at every printed
step).  The physics' independent checks are in fortran/tests/test_roller_dynamics.f90.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pyadore import plots
from pyadore.printout import read_print

ROOT = Path(__file__).resolve().parents[1]
DECK = ROOT / "decks" / "appendix_d_roller.inp"
GOLDEN = ROOT / "golden" / "appendix_d_roller.prt"
REPORT_TIME = 5.453e-3          # s: the report's step 4000 (tau 76.18)
ADORE_CALLS = 43010
#: the golden roller whose inner load misses (module docstring of the xfail below)
EDGE_ROLLER = 6


def _sections_1a(text: str) -> int:
    return text.count("1a. Load Distribution Along Roller no. 1")


def _printed_steps(text: str) -> int:
    return len(re.findall(r"^1\. Rolling Element Parameters", text, re.M))


def test_cli_runs_appendix_d_some_steps(tmp_path):
    """`pyadore run` integrates the roller deck: Normal termination, the roller run's note,
    section 1a at every printed step (0 and the last), the time history beside the print."""
    out = tmp_path / "d.prt"
    proc = subprocess.run([sys.executable, "-m", "pyadore", "run", str(DECK), "-o", str(out), "--steps", "100"],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    text = out.read_text()
    assert "Normal termination: Last Step Number =     100" in text
    assert _printed_steps(text) == 2 and _sections_1a(text) == 2
    # the cage as the deck's Rec 3.3 says (the default): Appendix D's pattern leaves it free
    assert "CAGE FREE" in text and "CAGE CENTRED" not in text
    history = out.with_suffix(".hist.csv").read_text().splitlines()
    assert history[0].startswith("time_s,step,total_power_loss_W,re1_contact_load_outer_N")
    assert len(history) == 1 + 101


@pytest.fixture(scope="module")
def report_time_run(tmp_path_factory, adore_exe):
    """Appendix D to the report's time with its cage held centred (`--cage centred`; the
    default, the deck's Rec 3.3, frees it: free_report_time_run below)."""
    out = tmp_path_factory.mktemp("roller_report_time") / "d.prt"
    proc = subprocess.run([str(adore_exe), str(DECK), str(out), "--cage", "centred", "--duration", str(REPORT_TIME)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    return read_print(out)


def _paired(run):
    """(golden row, run row) of section 1's tables for each golden roller, the run's roller
    the one nearest to the golden roller's azimuth (golden roller 1's azimuth is illegible:
    45 deg before roller 2's)."""
    golden = read_print(GOLDEN).step(4000)
    mine = run.step(run.step_numbers[-1])
    g_az = golden.tables["re_contact"]["orbital_position_deg"].to_numpy() % 360.0
    g_az[0] = (g_az[1] - 45.0) % 360.0
    m_az = mine.tables["re_contact"]["orbital_position_deg"].to_numpy() % 360.0
    pairs = []
    for k, a in enumerate(g_az, start=1):
        gap = abs((m_az - a + 180.0) % 360.0 - 180.0)
        j = int(gap.argmin()) + 1
        assert gap.min() < 0.5, f"no roller of the run near golden roller {k}'s azimuth {a:.1f} deg"
        pairs.append((k, golden, mine, j))
    return pairs


def _errors(run, table, column):
    """Relative errors (run - golden)/golden of the legible, non-zero golden values."""
    out = {}
    for k, golden, mine, j in _paired(run):
        g = golden.tables[table][column][k]
        m = mine.tables[table][column][j]
        if g == g and g != 0.0:
            out[k] = (m - g) / g
    return out


def test_report_time_is_reached_with_fewer_calls(report_time_run):
    assert report_time_run.termination["final_time"] == pytest.approx(76.18, abs=5e-3)
    assert report_time_run.statistics["total_derivative_calls"] < ADORE_CALLS


def test_orbital_speeds_within_1_percent(report_time_run):
    errors = _errors(report_time_run, "re_motion", "orbital_velocity_rpm")
    assert len(errors) == 8
    assert max(map(abs, errors.values())) < 0.01


def test_outer_contact_loads_within_5_percent(report_time_run):
    errors = _errors(report_time_run, "re_contact", "contact_load_outer_N")
    assert len(errors) == 8
    assert max(map(abs, errors.values())) < 0.05, errors


def test_inner_contact_loads_within_5_percent_in_the_load_zone(report_time_run):
    errors = _errors(report_time_run, "re_contact", "contact_load_inner_N")
    assert set(errors) == {3, 4, 5, 6}
    assert max(abs(e) for k, e in errors.items() if k != EDGE_ROLLER) < 0.05, errors
    # the known deviation at the load zone's edge (+7.7 %, the xfail below), bounded
    assert abs(errors[EDGE_ROLLER]) < 0.10, errors


@pytest.mark.xfail(strict=True, reason="known deviation: golden roller 6 (77.2 deg, the load zone's edge) 77.78 N, "
                   "the run's 83.79 N (+7.7 %) at the same azimuth (+-0.1 deg): the inner race's lateral position at "
                   "that instant (run -0.113 um, report 0.000 um with an unbalanced -11.6 N on it: their roller-"
                   "passage vibrations differ, ~5.9 N) and ADORE's thermal clearance change (~0.6 N) (docs/dynamics.md, "
                   "Roller 6's inner load at the load-zone edge)")
def test_inner_contact_load_at_the_load_zone_edge_within_5_percent(report_time_run):
    errors = _errors(report_time_run, "re_contact", "contact_load_inner_N")
    assert abs(errors[EDGE_ROLLER]) < 0.05


def test_total_power_loss_within_15_percent(report_time_run):
    golden = read_print(GOLDEN).step(4000).tables["performance"]
    mine = report_time_run.step(report_time_run.step_numbers[-1]).tables["performance"]
    g = float(golden["total_power_loss_W"].iloc[0])
    m = float(mine["total_power_loss_W"].iloc[0])
    assert g == pytest.approx(0.9677)
    assert abs(m - g) / g < 0.15


def test_full_appendix_d_run(tmp_path, adore_exe):
    """The one full run, its cage held centred: the deck's 4000 steps end in Normal
    termination with at most ADORE's derivative calls, every printed step (Rec 1: every 500)
    with its section 1a.  (The free cage, the default, is integrated by ROS34PW2 with a
    block Jacobian every step: 62 509 calls for the 4000 steps, docs/cage.md, "The
    cage's whirl frame".)"""
    out = tmp_path / "full.prt"
    proc = subprocess.run([str(adore_exe), str(DECK), str(out), "--cage", "centred"], capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stderr
    run = read_print(out)
    assert run.termination["last_step_number"] == 4000
    assert run.step_numbers == list(range(0, 4001, 500))
    text = out.read_text()
    assert _sections_1a(text) == len(run.step_numbers)
    assert run.statistics["total_derivative_calls"] <= ADORE_CALLS
    assert run.statistics["max_truncation"] <= 1e-4


@pytest.fixture(scope="module")
def free_report_time_run(tmp_path_factory, adore_exe):
    """Appendix D with its cage as the deck's Rec 3.3 says (free: `--cage deck`) to the
    report's time; a free roller cage under the deck's INT METHOD 5 is integrated by
    ROS34PW2 (docs/rollers.md, "The free roller cage's pocket episode")."""
    out = tmp_path_factory.mktemp("roller_free_report_time") / "f.prt"
    proc = subprocess.run([str(adore_exe), str(DECK), str(out), "--cage", "deck", "--duration", str(REPORT_TIME)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    assert "integrated by ROS34PW2" in proc.stderr
    return out


def test_free_cage_at_the_report_time_meets_the_golden_gates(free_report_time_run):
    """The report's runs had a free cage (Rec 3.3, docs/cage.md "The cage's degrees of
    freedom"): with it, the gates of the centred run above - orbital speeds 1 %, outer
    loads 5 %, inner loads 5 % (the load zone's edge, the known deviation, 10 %), total
    power loss 15 % - and fewer derivative calls than ADORE."""
    run = read_print(free_report_time_run)
    assert run.termination["final_time"] == pytest.approx(76.18, abs=5e-3)
    assert run.statistics["total_derivative_calls"] < ADORE_CALLS
    orbital = _errors(run, "re_motion", "orbital_velocity_rpm")
    outer = _errors(run, "re_contact", "contact_load_outer_N")
    inner = _errors(run, "re_contact", "contact_load_inner_N")
    assert len(orbital) == 8 and max(map(abs, orbital.values())) < 0.01
    assert len(outer) == 8 and max(map(abs, outer.values())) < 0.05, outer
    assert set(inner) == {3, 4, 5, 6}
    assert max(abs(e) for k, e in inner.items() if k != EDGE_ROLLER) < 0.05, inner
    assert abs(inner[EDGE_ROLLER]) < 0.10, inner
    g = float(read_print(GOLDEN).step(4000).tables["performance"]["total_power_loss_W"].iloc[0])
    m = float(run.step(run.step_numbers[-1]).tables["performance"]["total_power_loss_W"].iloc[0])
    assert abs(m - g) / g < 0.15


def _time_mean(h, column):
    t = h["time_s"].to_numpy()
    return float(np.sum(h[column].to_numpy()[1:] * np.diff(t)) / (t[-1] - t[0]))


def test_free_cage_pocket_contacts_agree_with_a_tight_integration(free_report_time_run, adore_exe, tmp_path):
    """The free cage's pocket contacts are the equations' and not the integrator's: the run
    agrees with the IMEX ARK4 at ERROR LIMIT 1e-6 (100 x tighter than the deck's; its
    steps resolve the pocket contact's nanometre interference).  At the deck's error limit
    the ARK4 held roller 3 on its leading pocket wall for 1.4 ms (2 N, 7.7 W: time-mean
    pocket loss 2.5 W, cage 0.25 rad/s fast at the report's time); the tight run and this
    one have one short impact of that roller as it enters the load zone (~1.3 ms: the cage
    spun up by ~0.37 rad/s, its centre sent inward) and no lasting contact."""
    lines = DECK.read_text().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("Rec 2.1"))
    f = lines[k].split()[2:]
    f[1], f[4] = "1.0000E-06", "1.0000E-06"    # MINIMUM step and ERROR LIMIT
    lines[k] = lines[k][:12] + "".join(f"{v:>11}" for v in f)     # the deck's fixed columns
    tight = tmp_path / "tight.inp"
    tight.write_text("\n".join(lines) + "\n")
    out = tmp_path / "tight.prt"
    proc = subprocess.run([str(adore_exe), str(tight), str(out), "--cage", "deck", "--integrator", "ark4",
                           "--duration", str(REPORT_TIME)], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    ref = pd.read_csv(out.with_suffix(".hist.csv"))
    run = pd.read_csv(free_report_time_run.with_suffix(".hist.csv"))
    for h in (ref, run):
        assert _time_mean(h, "pocket_loss_W") < 0.3
        assert h["land_loss_W"].max() == 0.0
    assert abs(_time_mean(run, "pocket_loss_W") - _time_mean(ref, "pocket_loss_W")) < 0.2
    # the impact's spin-up (~0.37 rad/s) and the cage's centre at the report's time
    assert run["cage_angular_velocity_x_rad_s"].iloc[-1] - run["cage_angular_velocity_x_rad_s"].iloc[0] > 0.3
    assert abs(run["cage_angular_velocity_x_rad_s"].iloc[-1] - ref["cage_angular_velocity_x_rad_s"].iloc[-1]) < 0.05
    radius = [float(np.hypot(h["cage_y_m"].iloc[-1], h["cage_z_m"].iloc[-1])) for h in (run, ref)]
    assert abs(radius[0] - radius[1]) < 3e-6, radius


def _free_cage(out, whirl, adore_exe):
    proc = subprocess.run([str(adore_exe), str(DECK), str(out), "--steps", "300", "--cage", "free",
                           "--cage-whirl", whirl], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    return out


@pytest.fixture(scope="module")
def free_cage_run(tmp_path_factory, adore_exe):
    """Appendix D with its outer-guided cage free (run option cage=free), 300 steps, in
    ADORE's whirl coordinates (cage_whirl=adore, the default)."""
    return _free_cage(tmp_path_factory.mktemp("roller_free_cage") / "f.prt", "adore", adore_exe)


@pytest.mark.parametrize("whirl", ["adore", "inertial"])
def test_free_roller_cage_starts_on_the_deck_whirl_and_touches_its_dry_lands_only_outside(
        free_cage_run, adore_exe, tmp_path, whirl):
    """The free roller cage (issue #25 for Appendix D): the listing says so; it starts at the
    deck's Rec 9.5.1 centre (0, 0, 5e-5 m: on its 50 um radial land clearance) and moves off
    it; in air the lands carry no film, so a land force is recorded exactly when the cage's
    eccentricity about the (fixed) outer race exceeds the radial clearance (metal), never
    inside it.  By Newton's equations (cage_whirl=inertial) the cage rides its lands (land
    force in some steps); in ADORE's whirl coordinates it moves inside the clearance without
    touching them over these 300 steps (docs/cage.md, "The cage's whirl frame")."""
    run = free_cage_run if whirl == "adore" else _free_cage(tmp_path / "i.prt", whirl, adore_exe)
    text = run.read_text()
    assert "Normal termination: Last Step Number =     300" in text
    assert "CAGE FREE: ALL SIX DEGREES OF FREEDOM INTEGRATED" in text
    assert ("CAGE MASS CENTRE IN ADORE'S WHIRL COORDINATES" in text) == (whirl == "adore")
    h = pd.read_csv(run.with_suffix(".hist.csv"))
    assert h["cage_y_m"].iloc[0] == 0.0 and h["cage_z_m"].iloc[0] == pytest.approx(5.0e-5, rel=1e-12)
    assert np.ptp(h["cage_y_m"]) > 1.0e-5
    e = np.hypot(h["cage_y_m"], h["cage_z_m"]).to_numpy()
    c = 0.5 * h["guide_clearance_m"].to_numpy()
    land = (h["land1_force_N"] + h["land2_force_N"]).to_numpy()
    assert c[0] == pytest.approx(5.0e-5, rel=1e-9)
    assert (e < c).any()
    assert np.all((land > 0) == (e > c))
    assert (land > 0).any() == (whirl == "inertial")
    # the two lands (same diameter, clearance and width) carry the same force
    np.testing.assert_allclose(h["land1_force_N"], h["land2_force_N"], rtol=1e-12, atol=0.0)


def test_roller_run_draws_the_report_roller_figure_types(free_cage_run, adore_exe, tmp_path):
    """Figures 33-44 of the report's roller runs (power loss, bulk temperatures, one roller's
    race contacts, cage velocities, land forces, whirl orbit) from a roller run: figure types
    2 and 4-9 are made (type 3, the wear rates, is not among the roller run's figures and
    the roller history has none: skipped with a one-line reason naming a few steps only);
    the orbit is the history's cage path.  A centred cage's figures 6-8 say it is centred."""
    made = plots.make_set(free_cage_run)
    assert [t.number for t, _f in made.figures] == [1, 2, 4, 5, 6, 7, 8, 9, 10]
    assert [t.number for t, _r in made.skipped] == [3]
    reason = made.skipped[0][1]
    assert "..., 300 (301 steps)" in reason and len(reason) < 300
    h = pd.read_csv(free_cage_run.with_suffix(".hist.csv"))
    orbit = dict((t.number, f) for t, f in made.figures)[8]
    path, = [ln for ln in orbit.get_axes()[0].get_lines() if ln.get_label().startswith("mass-center path")]
    np.testing.assert_allclose(path.get_xdata(), 1e3 * h["cage_y_m"], rtol=1e-12)
    np.testing.assert_allclose(path.get_ydata(), 1e3 * h["cage_z_m"], rtol=1e-12)
    centred = tmp_path / "c.prt"
    proc = subprocess.run([str(adore_exe), str(DECK), str(centred), "--steps", "50", "--cage", "centred"],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    made = plots.make_set(centred)
    assert {6, 7, 8} <= {t.number for t, _f in made.figures}
    texts = [t.get_text() for t_, f in made.figures if t_.number in (6, 7, 8) for ax in f.get_axes() for t in ax.texts]
    assert any("the cage is centred in this run" in s for s in texts)


def _with_rec_3_3(tmp_path, flags, name):
    lines = DECK.read_text().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("Rec 3.3"))
    lines[k] = "Rec 3.3     " + "".join(f"{v:6d}" for v in flags)
    deck = tmp_path / name
    deck.write_text("\n".join(lines) + "\n")
    return deck


def test_rec_3_3_sets_the_rollers_and_the_cage_degrees_of_freedom(tmp_path, adore_exe):
    """Rec 3.3 (report 4.4.6, docs/deck-format.md): Appendix D's 1 1 1 1 0 0 0 0 0 0 1 holds the
    rollers' axial motion, tilt and skew and leaves the cage free - `--cage deck` is then the
    free cage, the same run as `--cage free`; all zeros free the rollers too; a pattern that is
    neither is an input error naming a field."""
    def run(deck, out, *opts):
        return subprocess.run([str(adore_exe), str(deck), str(tmp_path / out), "--steps", "20", *opts],
                              capture_output=True, text=True, timeout=600)
    free, deck = run(DECK, "f.prt", "--cage", "free"), run(DECK, "d.prt", "--cage", "deck")
    assert free.returncode == 0 and deck.returncode == 0, deck.stderr
    assert "rollers' axial motion, tilt and skew held (Rec 3.3" in deck.stderr
    assert (tmp_path / "f.hist.csv").read_text() == (tmp_path / "d.hist.csv").read_text()
    zeros = run(_with_rec_3_3(tmp_path, [0] * 11, "zeros.inp"), "z.prt")
    assert zeros.returncode == 0, zeros.stderr
    assert "rollers free in all six degrees of freedom (Rec 3.3 all zero)" in zeros.stderr
    bad = run(_with_rec_3_3(tmp_path, [1] + [0] * 10, "bad.inp"), "b.prt")
    assert bad.returncode != 0 and "Rec 3.3 field 1 = 1: " in bad.stderr
