"""Fortran-like tokenising of fixed fields."""

from __future__ import annotations

import pytest

from pyadore.deck.schema import FieldSpec, record_spec
from pyadore.deck.tokenizer import cut_fields, parse_value, split_label

REAL = FieldSpec("x", "real", default=None)
REAL0 = FieldSpec("x", "real", default=0.0)
INT = FieldSpec("n", "int", default=None)


@pytest.mark.parametrize("text,value", [
    (" 1.0000E-05", 1.0e-05), ("1.46292E-01", 0.146292), (" 1.0000D-05", 1.0e-05), ("     1.0-05", 1.0e-05),
    ("    -9.81  ", -9.81), ("        .5 ", 0.5), ("       +2. ", 2.0), (" 1.0000e+03", 1000.0),
    ("  1.0E+10  ", 1.0e10), ("    1.0+03 ", 1000.0),
])
def test_reals(text, value):
    v, blank, err = parse_value(REAL, text)
    assert err is None and not blank and v == value


@pytest.mark.parametrize("text,fragment", [
    ("      12345", "decimal point"), (" 1.4O00E-01", "real number"), ("   1.0 2.0 ", "blanks inside"),
    ("  1.0E+400 ", "finite"), ("      1.0E ", "real number"),
])
def test_bad_reals(text, fragment):
    v, _, err = parse_value(REAL, text)
    assert v is None and fragment in err


def test_blank_fields_take_default_or_fail():
    assert parse_value(REAL0, " " * 11) == (0.0, True, None)
    v, blank, err = parse_value(REAL, " " * 11)
    assert v is None and blank and "required" in err


@pytest.mark.parametrize("text,value,ok", [("   500", 500, True), ("    -2", -2, True), ("  2500.", None, False),
                                          ("  1 0 ", None, False), ("   +7 ", 7, True)])
def test_ints(text, value, ok):
    v, _, err = parse_value(INT, text)
    assert (err is None) is ok and v == value


def test_run_together_numbers_split_by_columns():
    spec = record_spec("11")
    names = [(f.name, f) for f in spec.fields]
    tokens, extra = cut_fields(" 0.0000E+00 0.0000E+00-9.8100E+00", 0, names)
    assert [parse_value(f, t.text)[0] for (_, f), t in zip(names, tokens)] == [0.0, 0.0, -9.81]
    assert [t.col for t in tokens] == [1, 12, 23] and extra is None


def test_labels():
    assert split_label("Rec 5B.1     1.0000E-02") == ("5B.1", 12, None)
    assert split_label("REC 1            1") == ("1", 12, None)
    assert split_label("     1     0") == (None, 0, None)
    label, off, err = split_label("Rec 2.1 5.0000E-02")
    assert label == "2.1" and off == 12 and "label zone" in err


def test_short_line_is_padded():
    spec = record_spec("2.4")
    names = [(f.name, f) for f in spec.fields]
    tokens, _ = cut_fields("     1     0     2", 0, names)
    assert [parse_value(f, t.text)[:2] for (_, f), t in zip(names, tokens)] == [
        (1, False), (0, False), (2, False), (0, True)]
