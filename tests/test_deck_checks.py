"""The deck's cross-field checks have one implementation, the engine's (fortran/model/checks.f90):
pyadore validate calls it through the extension, on the deck in memory, and reports each
problem at its field; the engine-only limit (no applied force) is left to the run."""

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
    assert len(fields) == len(set(fields)) == 23
    assert fields[:5] == ("shaft_inner_diameter", "shaft_outer_diameter", "bearing_outer_diameter",
                          "housing_outer_diameter", "pitch_diameter")
    rules = _core.cross_field_rules()
    assert len(rules) == 11 and rules[-1].startswith("max_traction >= traction_at_zero_slip")


def test_appendix_deck_values_pass_and_a_changed_value_fails():
    deck = read_deck(BALL)
    values = {n: deck.lookup(n) for n in _core.cross_field_fields()}
    assert _core.cross_field_problems(values) == []
    values["pitch_diameter"] = 0.5          # beyond the bearing OD (0.18 m)
    out = _core.cross_field_problems(values)
    assert out[0] == ("pitch_diameter", "expected between the bore (shaft_outer_diameter = 0.1) and "
                      f"bearing_outer_diameter = {values['bearing_outer_diameter']:.6G}")
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


def test_unloaded_bearing_is_valid_deck_but_refused_by_the_run(tmp_path):
    deck = read_deck(BALL)
    for c in "xyz":
        deck.set("9.1.1", f"applied_force_{c}", 0.0)
    assert deck.validate() == []
    path = tmp_path / "unloaded.inp"
    deck.save(path)
    with pytest.raises(pyadore.AdoreInputError, match="expected a non-zero applied force"):
        pyadore.run(path, steps=0, out=tmp_path / "x.prt")


def test_wrong_number_of_values_is_an_engine_error():
    from pyadore._core.base import _engine, check
    n, fields, messages, status, message = _engine().adore_deck_cross_checks([0.0] * 3, [1] * 3, 30)
    with pytest.raises(pyadore.AdoreEngineError, match="3 values given, the rules read 23"):
        check(int(status), message)
