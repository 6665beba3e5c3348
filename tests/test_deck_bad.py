"""Malformed decks: every case in tests/data/bad_decks/expected.json is reported with the
expected record, field, problem class and line, formatted with location and caret, and
without a traceback.  The Fortran reader is checked against the same expectations."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pyadore.deck import PROBLEM_KINDS, DeckError, check_deck, read_deck, run_validate
from pyadore.deck.problems import SOURCE_WINDOW, shown_source

BAD = Path(__file__).resolve().parent / "data" / "bad_decks"
EXPECTED = json.loads((BAD / "expected.json").read_text())


def test_enough_cases_and_every_class_covered():
    files = {p.name for p in BAD.glob("*.inp")}
    present = {n for n, e in EXPECTED.items() if not e.get("absent")}
    assert present == files and len(files) >= 25
    assert {e["kind"] for e in EXPECTED.values()} == set(PROBLEM_KINDS)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_bad_deck_reported(name):
    e = EXPECTED[name]
    path = BAD / name
    deck, problems = check_deck(path)
    assert problems, name
    hits = [p for p in problems
            if (p.record, p.field, p.kind, p.line) == (e["record"], e["field"], e["kind"], e["line"])]
    assert hits, [(p.record, p.field, p.kind, p.line) for p in problems]
    for p in problems:
        assert p.kind in PROBLEM_KINDS
        text = p.format()
        assert text.startswith(str(path))
        if p.line and p.source_line is not None:
            head, shown, caret = text.split("\n")
            assert head.startswith(f"{path}:{p.line}:{p.col}  ")
            shown_line, caret_col = shown_source(p.source_line.replace("\t", " "), p.col)
            assert shown == "    " + shown_line and len(shown_line) <= SOURCE_WINDOW + 6
            assert caret.index("^") - 4 == caret_col - 1
            if p.col <= len(p.source_line):
                assert shown_line[caret_col - 1] == p.source_line.replace("\t", " ")[p.col - 1]
        if p.record:
            assert f"  Rec {p.record}" in text.split("\n")[0]
        if p.field:
            assert f"field {p.field} = " in text


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_read_deck_raises_input_error_or_validate_fails(name):
    """Reading problems raise DeckError from read_deck; value problems show in validate()."""
    e = EXPECTED[name]
    try:
        deck = read_deck(BAD / name)
    except DeckError as exc:
        assert exc.problems
        assert e["kind"] not in ("range", "cross_field") or e["field"] is None or len(exc.problems) >= 1
    else:
        assert e["kind"] in ("range", "cross_field")
        assert deck.validate()


def test_run_validate_exit_status(capsys):
    assert run_validate(BAD / "range_mode.inp") == 1
    out = capsys.readouterr().out
    assert "range_mode.inp:1:18  Rec 1  field mode = 3: expected [-2, 2]" in out
    assert run_validate(Path(__file__).resolve().parents[1] / "decks" / "appendix_c_ball.inp") == 0
    assert capsys.readouterr().out.strip().endswith("OK")


def test_all_problems_reported_at_once(tmp_path):
    src = (Path(__file__).resolve().parents[1] / "decks" / "appendix_c_ball.inp").read_text().splitlines()
    src[0] = src[0][:12] + "     9" + src[0][18:]                                 # MODE out of range
    src[10] = src[10][:23] + " 9.9999E+01" + src[10][34:]                          # pitch > OD
    src[12] = src[12][:34] + "-3.6241E-02" + src[12][45:]                          # negative cage width
    p = tmp_path / "many.inp"
    p.write_text("\n".join(src) + "\n")
    _, problems = check_deck(p)
    fields = {(pr.record, pr.field) for pr in problems}
    assert {("1", "mode"), ("5A", "pitch_diameter"), ("7.1", "cage_width")} <= fields


def test_directory_and_missing_file_are_problems(tmp_path):
    for target in (tmp_path, tmp_path / "nope.inp"):
        deck, problems = check_deck(target)
        assert deck is None and [p.kind for p in problems] == ["io"]
