"""The engine's Fortran deck reader (fortran/deck/parser.f90 and its modules) against the Python reader.

* the generated Fortran schema table is current (Python and Fortran read one table);
* both appendix decks: every field equal, exactly, with the same kind;
* every bad deck of tests/data/bad_decks: the Fortran reader rejects it with the same
  problem list, word for word, as the Python reader plus the range checks of validate();
  decks whose only problem is a cross-field value check are accepted by the Fortran
  reader (the engine's model applies those checks, fortran/model/checks.f90);
* the engine's run refuses every deck with a cross-field value problem, with
  validate()'s words, location and caret, before any physics (a degenerate ring once
  divided by zero in the mounting);
* a malformed deck makes `adore` exit 1 and pyadore.run raise AdoreInputError, with no
  print file, and the interpreter keeps working.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import pyadore
from pyadore.deck import field_table, read_deck
from pyadore.deck.fortran_schema import generate
from pyadore.deck.reader import _load, parse_text
from pyadore.deck.validate import _ranges, validate_deck

import probes


ROOT = Path(__file__).resolve().parents[1]
BAD = ROOT / "tests" / "data" / "bad_decks"
EXPECTED = json.loads((BAD / "expected.json").read_text())
FILE_LEVEL = {"io", "non_text", "empty"}  # reported by the engine's text stage (deck/text.f90)


def test_generated_schema_table_is_current():
    committed = (ROOT / "fortran" / "deck" / "schema.f90").read_text()
    assert committed == generate(), (
        "fortran/deck/schema.f90 is stale: run "
        "`python -m pyadore.deck.fortran_schema > fortran/deck/schema.f90`")


def test_generated_schema_table_covers_every_record_and_field():
    from pyadore.deck.records import RECORDS
    text = generate()
    assert f"N_RECORDS = {len(RECORDS)}" in text
    assert f"N_FIELDS = {sum(len(r.fields) for r in RECORDS)}" in text
    for r in RECORDS:
        assert f'"{r.rid}"' in text
        for f in r.fields:
            assert f'"{f.name}"' in text


@pytest.mark.parametrize("deck_name", ["appendix_c_ball.inp", "appendix_d_roller.inp"])
def test_appendix_decks_agree_field_by_field(deck_name):
    path = ROOT / "decks" / deck_name
    fortran = probes.deck_field_table(path)
    python = field_table(read_deck(path))
    assert len(fortran) == len(python) > 100
    for f, p in zip(fortran, python):
        assert f[:3] == p[:3]
        assert type(f[3]) is type(p[3]), (f, p)
        assert f[3] == p[3], (f, p)  # exact: es24.16 carries every bit of the double


def test_blank_fields_take_the_schema_defaults():
    # Rec 2.4 of the ball deck leaves its fourth field blank: both readers give the default 0
    rows = {(r, n): v for r, _, n, v in probes.deck_field_table(ROOT / "decks" / "appendix_c_ball.inp")}
    assert rows[("2.4", "rec2_4_flag_4")] == 0
    assert rows[("9.5.1", "cage_center_z")] == -6.0e-4   # run together with its neighbour
    assert rows[("7.1", "cage_outer_diameter")] == 1.46292e-01
    assert rows[("7.0", "guide_type[2]")] == 2


def _python_read_and_range_problems(path: Path):
    """What the Fortran reader checks: Python's reading problems plus validate()'s range
    problems, in check_deck's order."""
    text, problems = _load(path)
    if text is None:
        return problems, None
    deck, problems = parse_text(text, str(path))
    problems = problems + _ranges(deck)
    problems.sort(key=lambda p: (p.line == 0, p.line, p.col))
    return problems, deck


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_bad_deck_rejected_by_fortran_reader(name):
    e = EXPECTED[name]
    path = BAD / name
    problems, deck = _python_read_and_range_problems(path)
    if not problems:
        # only a cross-field value check fails: the reader accepts it, the model's checks refuse it
        assert e["kind"] == "cross_field" and e["field"] is not None
        assert probes.deck_field_table(path) == field_table(deck)
        assert any(p.kind == "cross_field" and p.field == e["field"] for p in validate_deck(deck))
        return
    with pytest.raises(pyadore.AdoreInputError) as info:
        probes.deck_field_table(path)
    message = str(info.value)
    assert message.startswith(str(path))
    assert "Traceback" not in message and "Backtrace" not in message
    if e["record"] is not None:
        assert f"  Rec {e['record']}" in message
    if e["field"] is not None:
        assert f"  field {e['field']} = " in message
    if e["kind"] in FILE_LEVEL:
        assert any(w in message for w in ("not found", "not a text file", "empty")), message
        return
    # the same problems, word for word, as Python's Problem.format(), in the same order
    head, body = message.split("\n", 1)
    assert head == f"{path}: {len(problems)} problem(s) reading the deck"
    assert body == "\n".join(p.format() for p in problems)


CROSS_VALUE_DECKS = sorted(n for n, e in EXPECTED.items() if e["kind"] == "cross_field" and e["field"] is not None)


@pytest.mark.parametrize("name", CROSS_VALUE_DECKS)
def test_engine_run_refuses_cross_field_values_with_validates_words(name, tmp_path):
    """The reader accepts these decks (above); building the bearing model then refuses them
    with every cross-field problem of pyadore validate, word for word, and writes nothing."""
    path = BAD / name
    deck = read_deck(path)
    problems = [p for p in validate_deck(deck) if p.kind == "cross_field" and p.field is not None]
    assert problems and any(p.field == EXPECTED[name]["field"] for p in problems)
    with pytest.raises(pyadore.AdoreInputError) as info:
        pyadore.run(path, steps=0, out=tmp_path / "x.prt")
    head, body = str(info.value).split("\n", 1)
    assert head == f"{path}: {len(problems)} problem(s) in the deck's values"
    assert body == "\n".join(p.format() for p in problems)
    assert list(tmp_path.iterdir()) == []


def test_fortran_reader_reports_all_problems_at_once(tmp_path):
    src = (ROOT / "decks" / "appendix_c_ball.inp").read_text().splitlines()
    src[0] = src[0][:12] + "     9" + src[0][18:]                        # MODE out of range
    src[10] = src[10][:23] + " 1.4OOOE-01" + src[10][34:]                # letter O in a real
    src[12] = src[12][:34] + "-3.6241E-02" + src[12][45:]                # negative cage width
    src[15] = src[15][:12] + " " * 11 + src[15][23:]                     # required room temperature blank
    path = tmp_path / "many.inp"
    path.write_text("\n".join(src) + "\n")
    with pytest.raises(pyadore.AdoreInputError) as info:
        probes.deck_field_table(path)
    lines = str(info.value).split("\n")
    assert lines[0] == f"{path}: 4 problem(s) reading the deck"
    assert lines[1] == f"{path}:1:18  Rec 1  field mode = 9: expected [-2, 2] (program mode MODE (1 in both decks)"
    assert lines[4].startswith(f"{path}:11:25  Rec 5A  field pitch_diameter = '1.4OOOE-01': expected a real number")
    assert lines[7].startswith(f"{path}:13:35  Rec 7.1  field cage_width = -0.036241: expected > 0")
    assert lines[10].startswith(f"{path}:16:13  Rec 9.0  field room_temperature = (blank): expected a value")
    assert lines[11] == "    " + src[15] and lines[12] == "    " + " " * 12 + "^"


def test_interpreter_survives_every_bad_deck(tmp_path):
    for name in sorted(EXPECTED):
        try:
            probes.deck_field_table(BAD / name)
        except pyadore.AdoreInputError:
            pass
    assert len(probes.deck_field_table(ROOT / "decks" / "appendix_d_roller.inp")) > 100
    assert pyadore.run(ROOT / "decks" / "appendix_c_ball.inp", steps=0, out=tmp_path / "ok.prt").print_path.exists()


def test_malformed_deck_stops_the_run_before_the_print_file(tmp_path, run_exe):
    bad = BAD / "type_real_letter.inp"
    out = tmp_path / "bad.prt"
    with pytest.raises(pyadore.AdoreInputError, match=r"Rec 5A  field pitch_diameter = '1\.4O00E-01'"):
        pyadore.run(bad, out=out)
    assert sorted(tmp_path.iterdir()) == []
    proc = run_exe(bad, out)
    assert proc.returncode == 1
    assert "Rec 5A  field pitch_diameter = '1.4O00E-01': expected a real number (E11.4)" in proc.stderr
    assert "Backtrace" not in proc.stderr
    assert sorted(tmp_path.iterdir()) == []


def test_deck_table_of_a_missing_file_is_an_input_error(tmp_path):
    with pytest.raises(pyadore.AdoreInputError, match="not found"):
        probes.deck_field_table(tmp_path / "nope.inp")
