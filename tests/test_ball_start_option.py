"""The ball start hypothesis as a run option (report 4.4.7): minimum contact dissipation,
the default, or race control at one race, "an input option ... retained" by ADORE
(kAngVel; its deck field is not identified, so pyadore takes it per run:
``--ball-start`` / ``pyadore.run(ball_start=)``).

Independent truths: race control means no spin at the controlling race's contact; the
minimum-dissipation start loses less power than race control at either race (the
report's reason for it).
"""

from __future__ import annotations

import subprocess
import sys

import pytest

import pyadore
from pyadore import AdoreInputError, BALL_STARTS, _core
from pyadore.printout import read_print

NOTE = "INITIAL BALL ANGULAR VELOCITY: "


def _step0(path):
    return read_print(path).steps[0]


@pytest.fixture(scope="module")
def starts(tmp_path_factory, ball_deck):
    """Step-0 print of the ball deck for every start hypothesis, and the default run's."""
    out = tmp_path_factory.mktemp("starts")
    runs = {name: pyadore.run(ball_deck, steps=0, out=out / f"{name}.prt", ball_start=name).print_path
            for name in BALL_STARTS}
    runs[None] = pyadore.run(ball_deck, steps=0, out=out / "default.prt").print_path
    return runs


def test_names_are_the_engines():
    assert BALL_STARTS[0] == "dissipation"      # the default first
    assert set(BALL_STARTS) == {"dissipation", "outer-race-control", "inner-race-control"}


@pytest.mark.parametrize("name, side", [("outer-race-control", "outer"), ("inner-race-control", "inner")])
def test_race_control_has_no_spin_at_the_controlling_race(starts, name, side):
    motion = _step0(starts[name]).table("re_motion")
    other = "inner" if side == "outer" else "outer"
    assert len(motion) == 18
    assert motion[f"spin_roll_{side}"].abs().max() < 1e-12
    # the other race's contact spins (the hypothesis moves all spin there)
    assert motion[f"spin_roll_{other}"].abs().min() > 0.3


def test_minimum_dissipation_loses_less_than_race_control(starts):
    power = {name: float(_step0(starts[name]).table("performance")["total_power_loss_W"].iloc[0])
             for name in BALL_STARTS}
    print(power)
    assert power["dissipation"] < power["outer-race-control"] < power["inner-race-control"]
    # energy balance of each start: the total is the sum of the printed contact losses
    for name in BALL_STARTS:
        motion = _step0(starts[name]).table("re_motion")
        total = motion["contact_loss_outer_W"].sum() + motion["contact_loss_inner_W"].sum()
        assert total == pytest.approx(power[name], rel=1e-3)


def test_default_print_is_the_dissipation_start_and_lists_no_option(starts):
    default = starts[None].read_text()
    assert starts["dissipation"].read_text() == default
    assert NOTE not in default


@pytest.mark.parametrize("name, words", [("outer-race-control", "OUTER RACE CONTROL"),
                                         ("inner-race-control", "INNER RACE CONTROL")])
def test_print_lists_a_race_control_start_before_the_deck(starts, name, words):
    text = starts[name].read_text()
    head = text[:text.index("Listing of input data records")]
    assert NOTE + words in head
    assert "REPLACES THE MINIMUM-DISSIPATION START (REPORT 4.4.7)" in head


def test_unknown_start_is_an_input_error(tmp_path, ball_deck):
    with pytest.raises(AdoreInputError, match="ball start: expected one of dissipation"):
        pyadore.run(ball_deck, steps=0, out=tmp_path / "x.prt", ball_start="race-control")
    # the engine is the one place that checks the name
    with pytest.raises(AdoreInputError, match="got 'race-control'"):
        _core.run_file(ball_deck, tmp_path / "y.prt", "steps=0\nball_start=race-control")
    with pytest.raises(AdoreInputError, match="got '3'"):
        pyadore.run(ball_deck, steps=0, out=tmp_path / "z.prt", ball_start=3)
    assert list(tmp_path.iterdir()) == []


def test_roller_deck_refuses_a_ball_start(tmp_path, roller_deck):
    with pytest.raises(AdoreInputError, match="applies to ball bearings"):
        pyadore.run(roller_deck, steps=0, out=tmp_path / "r.prt", ball_start="outer-race-control")
    assert list(tmp_path.iterdir()) == []


def test_standalone_engine_takes_the_option(tmp_path, ball_deck, run_exe, starts):
    out = tmp_path / "c.prt"
    proc = run_exe(ball_deck, out, "--steps", "0", "--ball-start", "outer-race-control")
    assert proc.returncode == 0, proc.stderr
    assert out.read_text() == starts["outer-race-control"].read_text()
    bad = run_exe(ball_deck, tmp_path / "d.prt", "--ball-start", "sideways")
    assert bad.returncode == 1
    assert "adore: error: ball start: expected one of dissipation, outer-race-control, inner-race-control, " \
           "got 'sideways'" in bad.stderr
    missing = run_exe(ball_deck, tmp_path / "e.prt", "--ball-start")
    assert missing.returncode == 1 and "--ball-start needs a value (NAME)" in missing.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.prt"]


def test_cli_offers_the_choices(tmp_path, ball_deck):
    proc = subprocess.run([sys.executable, "-m", "pyadore", "run", str(ball_deck), "-o", str(tmp_path / "c.prt"),
                           "--steps", "0", "--ball-start", "sideways"], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    assert "'sideways' is not one of 'dissipation', 'outer-race-control', 'inner-race-control'" in proc.stderr
    assert not (tmp_path / "c.prt").exists()
