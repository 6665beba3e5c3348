"""The flanged example deck (issue #26 item 2; docs/rollers.md "Flanges"): the NUP-type
cylindrical roller bearing under 5 kN radial + 0.5 kN axial load runs step 0 and its time
steps with the roller end / flange contacts, the cylindrical pocket variant (kPocType -1)
runs, and what the flange model cannot honour is an input error.  The hand calculations
(face geometry and Hertz load, the inner race's axial balance, each roller's axial and
tilt balance, the cylindrical pocket's load, friction and torque) are in
fortran/tests/test_roller_flange.f90 (run by tests/test_engine_units.py).
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pyadore.printout import read_print

ROOT = Path(__file__).resolve().parents[1]
DECK = ROOT / "decks" / "examples" / "cylindrical_roller_nup_combined.inp"


def _run(adore_exe, deck, out, steps):
    return subprocess.run([str(adore_exe), str(deck), str(out), "--steps", str(steps)],
                          capture_output=True, text=True, timeout=600)


def test_flanged_deck_runs_with_flange_contacts(tmp_path, adore_exe):
    """Step 0 and 200 steps: Normal termination, the listing and the note name the flanges,
    the flange contacts dissipate (history's flange_loss_W > 0 after the start) and the
    total loss is the sum of its parts."""
    out = tmp_path / "nup.prt"
    proc = _run(adore_exe, DECK, out, 200)
    assert proc.returncode == 0, proc.stderr
    text = out.read_text()
    assert "Normal termination: Last Step Number =     200" in text
    assert "ROLLER END / FLANGE CONTACTS" in text
    assert "roller ends on the flanges of Rec 5B.2" in proc.stderr
    h = pd.read_csv(out.with_suffix(".hist.csv"))
    assert (h["flange_loss_W"].iloc[-50:] > 0.0).all()
    parts = h[["race_contact_loss_W", "pocket_loss_W", "land_loss_W", "flange_loss_W"]].sum(axis=1)
    np.testing.assert_allclose(h["total_power_loss_W"], parts, rtol=1e-12)


def test_cylindrical_pocket_variant_runs(tmp_path, adore_exe):
    """The same deck with Rec 5B.2's pocket code -1 (report 4.4.11): the run names the
    cylindrical pocket."""
    deck = tmp_path / "cyl.inp"
    deck.write_text(DECK.read_text().replace("Rec 5B.2         0", "Rec 5B.2        -1"))
    proc = _run(adore_exe, deck, tmp_path / "cyl.prt", 50)
    assert proc.returncode == 0, proc.stderr
    assert "CYLINDRICAL ROLLER POCKETS (KPOCTYPE -1" in (tmp_path / "cyl.prt").read_text()


def test_flat_roller_end_on_a_flange_is_an_input_error(tmp_path, adore_exe):
    """A flat roller end (Rec 5B.2 roller_end_radius 0) on a flange is refused (exit 1),
    not run with a default."""
    deck = tmp_path / "flat.inp"
    deck.write_text(DECK.read_text().replace(" 6.0000E-02 2.0000E-03", " 0.0000E+00 2.0000E-03"))
    proc = _run(adore_exe, deck, tmp_path / "flat.prt", 10)
    assert proc.returncode == 1
    assert "spherical roller end" in proc.stderr


def test_roller_extension_record_on_a_ball_deck_is_an_input_error(tmp_path, adore_exe):
    """Rec 5B.2 in a ball deck (Rec 3.2 field 11 = 1) is refused, not ignored."""
    lines = []
    for line in (ROOT / "decks" / "appendix_c_ball.inp").read_text().splitlines():
        lines.append(line + "     1" if line.startswith("Rec 3.2 ") else line)
        if line.startswith("Rec 5A "):
            lines.append("Rec 5B.2         0")
    deck = tmp_path / "ball.inp"
    deck.write_text("\n".join(lines) + "\n")
    proc = _run(adore_exe, deck, tmp_path / "ball.prt", 0)
    assert proc.returncode == 1
    assert "applies to cylindrical roller bearings" in proc.stderr


def test_flanged_deck_step0_carries_the_axial_load(tmp_path, adore_exe):
    """Step 0 of the flanged deck (docs/rollers.md, "Flanges at step 0"): the quasi-static
    start puts the flange contacts into the equilibrium, so section 3's roller force on the
    inner race has the axial component -500 N against the applied 500 N (it printed 0 before),
    and the block after step 0 lists each roller's flange loads, whose axial components
    Q cos(2.5 deg) on the inner race's -x flange add up to the 500 N by hand."""
    out = tmp_path / "nup0.prt"
    proc = _run(adore_exe, DECK, out, 0)
    assert proc.returncode == 0, proc.stderr
    lines = out.read_text().splitlines()
    race = next(ln for ln in lines if ln.startswith("Int IRace"))
    assert float(race.split()[2]) == pytest.approx(-500.0, abs=0.05)
    start = next(i for i, ln in enumerate(lines) if "FLANGE CONTACTS AT STEP 0" in ln)
    assert lines[start + 1].split()[-8:] == ["Outer", "-x", "Outer", "+x", "Inner", "-x", "Inner", "+x"]
    rows = [ln.split() for ln in lines[start + 2:start + 16]]
    assert [int(r[0]) for r in rows] == list(range(1, 15))
    inner_minus_x = np.array([float(r[5]) for r in rows])   # columns: no, x, tilt, O-x, O+x, I-x, I+x
    outer_plus_x = np.array([float(r[4]) for r in rows])
    assert np.sum(inner_minus_x) * np.cos(np.radians(2.5)) == pytest.approx(500.0, rel=2e-4)  # 5-digit print
    np.testing.assert_allclose(inner_minus_x, outer_plus_x, rtol=1e-4)
    # the load zone (+z, rollers 1, 2, 14, 13, 3) carries it; the rollers out of it tilt free
    assert inner_minus_x[[0, 1, 13]].min() > 100.0 and inner_minus_x[4:11].max() < 1.0
    assert "flanges' axial force on it  -5.0000E+02" in lines[start + 16]
    # the print reader takes the block as the step's flange tables
    step0 = read_print(out).step(0)
    fl = step0.tables["flanges"]
    assert list(fl.columns) == ["axial_pos_m", "tilt_rad", "outer_minus_x_N", "outer_plus_x_N",
                                "inner_minus_x_N", "inner_plus_x_N"]
    np.testing.assert_allclose(fl["inner_minus_x_N"].to_numpy(), inner_minus_x)
    assert float(step0.tables["flanges_race"]["flange_axial_force_on_inner_race_N"].iloc[0]) == -500.0
