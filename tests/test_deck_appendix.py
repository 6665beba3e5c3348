"""The two reconstructed appendix decks: they read, validate, round-trip, and agree with the
report's input echo (values the echo prints or derives)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from pyadore.deck import check_deck, field_table, format_deck, parse_text, read_deck, write_deck
from pyadore.deck.model import Deck

ROOT = Path(__file__).resolve().parents[1]
BALL = ROOT / "decks" / "appendix_c_ball.inp"
ROLLER = ROOT / "decks" / "appendix_d_roller.inp"


@pytest.mark.parametrize("path", [BALL, ROLLER], ids=["ball", "roller"])
def test_appendix_deck_validates(path):
    deck, problems = check_deck(path)
    assert problems == []
    assert deck is not None and deck.validate() == []


@pytest.mark.parametrize("path", [BALL, ROLLER], ids=["ball", "roller"])
def test_appendix_deck_round_trips_byte_identical(path, tmp_path):
    text = path.read_text()
    deck = read_deck(path)
    assert format_deck(deck) == text                    # verbatim copy of unchanged records
    assert format_deck(deck, canonical=True) == text    # and the checked-in deck is canonical
    out = tmp_path / "copy.inp"
    write_deck(deck, out)
    assert out.read_bytes() == path.read_bytes()
    assert read_deck(out) == deck


def test_record_sequences():
    ball = [r.rid for r in read_deck(BALL).records]
    roller = [r.rid for r in read_deck(ROLLER).records]
    common_head = ["1", "2.1", "2.4", "2.5", "2.7", "3.1", "3.2", "3.3", "3.4", "4"]
    assert ball == common_head + ["5A", "7.0", "7.1", "7.2.1", "7.2.2", "9.0", "9.1.1", "9.1.2", "9.5.1",
                                  "10.0", "10.1C", "10.3", "10.5.1B", "10.5.2B", "11"]
    assert roller == common_head + ["5B", "5B.1", "7.0", "7.1", "7.2.1", "7.2.2", "8.1", "9.0", "9.1.1",
                                    "9.1.2", "9.5.1", "10.0", "10.1B", "10.5.1B", "10.5.2B", "11"]


def test_summary_line():
    assert read_deck(BALL).summary().endswith("BALL bearing, 18 balls, 25 records, OK")
    assert read_deck(ROLLER).summary().endswith("CYLINDRICAL ROLLER bearing, 8 rollers, 26 records, OK")


def test_ball_values_match_echo_and_table5():
    d = read_deck(BALL)
    assert d.get("3.1", "run_id") == "Ball Bearing Test Case kGeoMod=100"
    assert d.get("7.1", "cage_outer_diameter") == pytest.approx(1.46292e-01, rel=0, abs=0)
    assert d.get("7.1", "cage_inner_diameter") == 1.30073e-01
    assert d.get("7.2.2", "guide_land_position") == 1.81204e-02
    assert d.get("9.0", "outer_race_fit") == 1.0e-05 and d.get("9.0", "inner_race_fit") == 5.0e-05
    assert d.get("9.5.1", "cage_center_z") == -6.0e-04            # run-together field
    assert d.get("1", "n_steps") == 2500
    # echo: DIA PLAY = 2(fo+fi-1) D (1 - cos a0), END PLAY = 2(fo+fi-1) D sin a0
    D, a = d.get("5A", "ball_diameter"), math.radians(d.get("5A", "free_contact_angle"))
    k = 2 * (d.get("5A", "outer_curvature_factor") + d.get("5A", "inner_curvature_factor") - 1) * D
    assert f"{k * (1 - math.cos(a)):.5E}" == "2.14180E-04"
    assert f"{k * math.sin(a):.5E}" == "9.66105E-04"
    # the blank fourth thermal flag reads as its default
    rec = d.record("2.4")
    assert rec.fields["rec2_4_flag_4"].blank and rec["rec2_4_flag_4"] == 0


def test_roller_values_match_echo_and_table6():
    d = read_deck(ROLLER)
    assert d.get("5B", "diametral_play") == 4.0e-05
    assert d.get("4", "bearing_outer_diameter") == 5.5e-02
    assert d.get("8.1", "density") == 3.2e3
    assert d.get("9.1.2", "inner_race_speed") == 7.0e4


def _kappa_fit(k0, kmax, kinf, umax):
    """Coefficients of kappa(u) = (A + B u) exp(-C u) + D with kappa(0) = k0, kappa(inf) = kinf and
    the maximum kmax at u = umax (the fit the echo prints)."""
    A, D = k0 - kinf, kinf
    # dk/du = 0 at umax  ->  B/C = A + B umax ;  kmax - D = (B/C) exp(-C umax)
    # with x = C umax: A exp(-x) / (1 - x) = kmax - D ; solve by bisection on x > 1
    f = lambda x: A * math.exp(-x) / (1 - x) - (kmax - D)
    lo, hi = 1.0 + 1e-12, 50.0
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if f(lo) * f(mid) > 0 else (lo, mid)
    C = lo / umax
    B = A * C / (1 - lo)
    return A, B, C, D


@pytest.mark.parametrize("path,rid,echo", [
    (BALL, "10.1C", ("-1.60000E-02", "3.82896E-02", "1.71782E+00", "1.60000E-02")),
    (ROLLER, "10.1B", ("-8.00000E-02", "9.57239E-01", "8.58912E+00", "8.00000E-02")),
], ids=["ball", "roller"])
def test_traction_record_reproduces_echo_fit(path, rid, echo):
    r = read_deck(path).record(rid)
    coeffs = _kappa_fit(r["traction_at_zero_slip"], r["max_traction"], r["traction_at_infinite_slip"],
                        r["slip_at_max_traction"])
    assert tuple(f"{c:.5E}" for c in coeffs) == echo


def test_field_table_and_json():
    d = read_deck(BALL)
    table = field_table(d)
    assert table[0] == ("1", 0, "mode", 1)
    assert ("7.0", 0, "guide_type[2]", 2) in table
    assert ("7.2.2", 1, "guide_land_clearance", 1.5e-3) in table
    assert len(table) == sum(len(r.fields) for r in d.records)
    data = json.loads(d.to_json())
    assert Deck.from_dict(data) == d
    rec5a = next(r for r in data["records"] if r["id"] == "5A")
    assert rec5a["units"]["pitch_diameter"] == "m"
    assert rec5a["positions"]["pitch_diameter"] == [11, 24]


def test_positions_are_kept():
    d = read_deck(BALL)
    fv = d.record("7.1").fields["cage_inner_diameter"]
    assert (fv.line, fv.col, fv.raw) == (13, 24, "1.30073E-01")


def test_unlabelled_deck_reads_the_same():
    text = BALL.read_text()
    bare = "".join(line[12:] + "\n" for line in text.splitlines())
    deck, problems = parse_text(bare, "bare.inp")
    assert problems == []
    assert deck == read_deck(BALL)
    assert not any(r.labelled for r in deck.records)
    assert format_deck(deck) == bare


def test_changed_record_is_reformatted_others_verbatim(tmp_path):
    src = BALL.read_text().splitlines()
    src[0] = src[0][12:]              # Rec 1 unlabelled: must stay so when unchanged
    p = tmp_path / "in.inp"
    p.write_text("\n".join(src) + "\n")
    d = read_deck(p)
    d.set("5A", "pitch_diameter", 0.145)
    out = format_deck(d).splitlines()
    assert out[0] == src[0]
    assert out[10] == "Rec 5A       1.9050E-02 1.4500E-01 2.5000E+01 0.0000E+00 5.2000E-01 5.4000E-01"
    d2, problems = parse_text("\n".join(out) + "\n")
    assert problems == [] and d2 == d
