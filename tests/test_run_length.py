"""Run length by simulated time (issue #30 item 3): the run options ``duration`` (s) and
``revolutions`` (shaft revolutions) end the time integration exactly at that time, its last
step printed, instead of after the deck's step count.  They come from the engine's one option
table (fortran/model/run_options.f90), so ``adore``, ``pyadore run`` and ``pyadore.run`` take
them alike."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import pyadore
from pyadore.printout import read_print

RPM = 20000.0  # Appendix C's inner race (shaft) speed, Rec 9.1.2


def test_duration_ends_exactly_there_with_the_last_step_printed(tmp_path, ball_deck):
    duration = 1.5e-3
    res = pyadore.run(ball_deck, out=tmp_path / "d.prt", duration=duration, progress=False)
    hist = res.time_history
    assert hist.index[-1] == duration  # the last step lands on it, to the last bit
    assert np.all(np.diff(hist.index) > 0)
    # every step recorded (the history grew beyond its first estimate, Rec 2.1's largest step)
    assert len(hist) == res.steps_integrated + 1 and list(hist["step"]) == list(range(res.steps_integrated + 1))
    run = read_print(res.print_path)
    last = run.step(run.step_numbers[-1])
    assert last.number == res.steps_integrated
    assert last.header["time_s"] == pytest.approx(duration, rel=1e-4)  # printed to 5 digits
    assert "TIME INTEGRATION: TO 1.5000E-03 S SIMULATED TIME (0.500 SHAFT REVOLUTIONS)" in res.text
    assert f"Last Step Number = {res.steps_integrated:7d}" in res.text


def test_revolutions_are_shaft_revolutions(tmp_path, ball_deck):
    res = pyadore.run(ball_deck, out=tmp_path / "r.prt", revolutions=0.25, progress=False)
    assert res.time_history.index[-1] == pytest.approx(0.25 * 60.0 / RPM, rel=1e-15)


def test_the_end_is_one_choice(tmp_path, ball_deck, roller_deck):
    with pytest.raises(pyadore.AdoreInputError, match="give one of them"):
        pyadore.run(ball_deck, steps=5, out=tmp_path / "a.prt", duration=1e-3)
    with pytest.raises(pyadore.AdoreInputError, match="duration and revolutions: give one of them"):
        pyadore.run(ball_deck, out=tmp_path / "b.prt", duration=1e-3, revolutions=1.0)
    with pytest.raises(pyadore.AdoreInputError, match="duration must be a finite number >= 0"):
        pyadore.run(ball_deck, out=tmp_path / "c.prt", duration=-1.0)
    with pytest.raises(pyadore.AdoreInputError, match="duration must be a finite number"):
        pyadore.run(ball_deck, out=tmp_path / "c.prt", duration=float("nan"))
    assert not list(tmp_path.iterdir())
    # a roller deck integrates to the simulated time too (issue #26)
    res = pyadore.run(roller_deck, out=tmp_path / "r.prt", duration=2e-4, progress=False)
    # 2e-4 s / T (the engine's 7.15827e-5 s: its crowned roller mass, tests/test_run_golden.py)
    assert res.steps_integrated > 0 and "Final Time = 2.7940E+00" in res.text


def test_command_lines_take_them(tmp_path, ball_deck, run_exe):
    proc = run_exe(ball_deck, tmp_path / "e.prt", "--duration", "4e-4")
    assert proc.returncode == 0, proc.stderr
    assert "TIME INTEGRATION: TO 4.0000E-04 S" in (tmp_path / "e.prt").read_text()
    bad = run_exe(ball_deck, tmp_path / "f.prt", "--duration", "soon")
    assert bad.returncode == 1 and "duration (--duration): expected a number, got 'soon'" in bad.stderr
    cli = subprocess.run([sys.executable, "-m", "pyadore", "run", str(ball_deck), "-o", str(tmp_path / "g.prt"),
                          "--revolutions", "0.1"], capture_output=True, text=True, timeout=600)
    assert cli.returncode == 0, cli.stderr
    assert "(0.100 SHAFT REVOLUTIONS)" in (tmp_path / "g.prt").read_text()
