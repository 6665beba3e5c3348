"""The deck's cross-field checks have one implementation, the engine's (fortran/model/checks.f90):
pyadore validate calls it through the extension, on the deck in memory, and reports each
problem at its field, so validate accepts exactly the decks whose values the engine accepts
(also the engine's own limit, a deck without applied force)."""

from __future__ import annotations

from pathlib import Path

import pytest

import pyadore
from pyadore import _core
from pyadore.deck import read_deck

ROOT = Path(__file__).resolve().parents[1]
BALL = ROOT / "decks" / "appendix_c_ball.inp"


def test_engine_names_the_fields_and_rules():
    fields = _core.cross_field_fields()
    assert len(fields) == len(set(fields)) == 31
    assert fields[:5] == ("shaft_inner_diameter", "shaft_outer_diameter", "bearing_outer_diameter",
                          "housing_outer_diameter", "pitch_diameter")
    rules = _core.cross_field_rules()
    assert len(rules) == 16 and rules[10].startswith("max_traction > traction_at_zero_slip")
    assert rules[11].startswith("applied_force_x, applied_force_y, applied_force_z not all 0")
    assert all(r.startswith("warning: ") for r in rules[12:])


def test_appendix_deck_values_pass_and_a_changed_value_fails():
    deck = read_deck(BALL)
    values = {n: deck.lookup(n) for n in _core.cross_field_fields()}
    assert _core.cross_field_problems(values) == []
    values["pitch_diameter"] = 0.5          # beyond the bearing OD (0.18 m)
    out = _core.cross_field_problems(values)
    assert out[0] == ("pitch_diameter", "expected between the bore (shaft_outer_diameter = 0.1) and "
                      f"bearing_outer_diameter = {values['bearing_outer_diameter']:.6G}", False)
    # a missing value skips the rules that need it
    values["pitch_diameter"] = None
    assert _core.cross_field_problems(values) == []


def test_validate_checks_the_deck_in_memory_at_the_field():
    deck = read_deck(BALL)
    deck.set("2.1", "step_initial", 1.0)
    problems = [p for p in deck.validate() if p.kind == "cross_field"]
    assert [(p.record, p.field) for p in problems] == [("2.1", "step_initial")]
    fv = deck.record("2.1").fields["step_initial"]
    assert problems[0].line == fv.line and problems[0].message.startswith("expected between step_min = ")


@pytest.mark.parametrize("changes", [
    # no applied force: the echo's load scale is undefined (this engine's limit)
    {("9.1.1", "applied_force_x"): 0.0, ("9.1.1", "applied_force_y"): 0.0, ("9.1.1", "applied_force_z"): 0.0},
    # a traction curve whose maximum is its zero-slip value: no curve of the fit has it
    {("10.1C", "traction_at_zero_slip"): 0.02},
])
def test_validate_and_the_run_refuse_the_same_deck_at_the_same_field(tmp_path, run_exe, changes):
    """A deck the engine refuses is not valid for `pyadore validate` either: both report the
    same problem at the same field (these two passed validate and failed the run)."""
    import subprocess
    import sys

    deck = read_deck(BALL)
    for (rec, field), value in changes.items():
        deck.set(rec, field, value)
    problems = deck.validate()
    assert len(problems) == 1 and problems[0].kind == "cross_field"
    path = tmp_path / "refused.inp"
    deck.save(path)
    cli = subprocess.run([sys.executable, "-m", "pyadore", "validate", str(path)], capture_output=True,
                         text=True, timeout=120)
    assert cli.returncode == 1
    with pytest.raises(pyadore.AdoreInputError) as info:
        pyadore.run(path, steps=0, out=tmp_path / "x.prt")
    exe = run_exe(path, tmp_path / "y.prt", "--steps", "0")
    assert exe.returncode == 1
    line = cli.stderr.splitlines()[0]
    assert line.startswith(f"{path}:") and problems[0].message in line
    assert line in str(info.value) and line in exe.stderr
    assert not (tmp_path / "x.prt").exists() and not (tmp_path / "y.prt").exists()


def test_wrong_number_of_values_is_an_engine_error():
    from pyadore._core.base import _engine, check
    n, fields, warning, messages, status, message = _engine().adore_deck_cross_checks([0.0] * 3, [1] * 3, 30)
    with pytest.raises(pyadore.AdoreEngineError, match="3 values given, the rules read 31"):
        check(int(status), message)
