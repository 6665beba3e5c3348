"""Property test: random valid decks written in the legacy layout read back equal."""

from __future__ import annotations

import string
from pathlib import Path

from hypothesis import given, settings, strategies as st

from pyadore.deck import format_deck, parse_text, read_deck
from pyadore.deck.model import Deck
from pyadore.deck.schema import expected_records

ROOT = Path(__file__).resolve().parents[1]
TEMPLATES = [read_deck(ROOT / "decks" / "appendix_c_ball.inp"), read_deck(ROOT / "decks" / "appendix_d_roller.inp")]
# fields tied together by cross-field checks: taken from a template (lengths scaled together)
TIED = {"shaft_inner_diameter", "shaft_outer_diameter", "bearing_outer_diameter", "housing_outer_diameter",
        "pitch_diameter", "ball_diameter", "roller_diameter", "cage_inner_diameter", "cage_outer_diameter",
        "n_rolling_elements", "step_min", "step_initial", "step_max", "max_traction",
        "traction_at_zero_slip", "traction_at_infinite_slip", "bearing_type",
        # the raceway diameters (race walls): ball curvature factors and free angle, roller play
        "outer_curvature_factor", "inner_curvature_factor", "free_contact_angle", "diametral_play",
        # the applied load (not all zero: an unloaded bearing is a cross-field error, Rec 9.1.1)
        "applied_force_x", "applied_force_y", "applied_force_z"}


def _template_value(tpl: Deck, name: str):
    for deck in (tpl, *TEMPLATES):
        v = deck.lookup(name)
        if v is not None:
            return v
    raise KeyError(name)


@st.composite
def reals(draw, spec):
    if spec.lo is not None and spec.hi is not None:
        u = draw(st.integers(0, 10000)) / 10000
        v = float(f"{spec.lo + (spec.hi - spec.lo) * u:.4E}")
    else:
        mant = draw(st.integers(10000, 99999)) / 10000
        v = float(f"{mant:.4f}E{draw(st.integers(-12, 12))}")
        if spec.lo is None or spec.lo < 0:
            v = draw(st.sampled_from([v, -v, 0.0]))
    if not spec.in_range(v):
        v = spec.default if spec.default is not None else _fallback(spec)
    return v


def _fallback(spec):
    if spec.lo is not None and spec.hi is not None:
        return float(f"{(spec.lo + spec.hi) / 2:.4E}")
    return float(f"{(spec.lo or 0.0) + 1.0:.4E}")


@st.composite
def decks(draw):
    tpl = draw(st.sampled_from(TEMPLATES))
    scale = draw(st.sampled_from([0.5, 1.0, 2.0, 10.0]))
    override = {
        "n_guide_lands": draw(st.integers(1, 4)),
        "traction_model": draw(st.sampled_from([2, 3])),
        "lubricant_code": draw(st.sampled_from([0, 1])),
        **{f"material_flag_{p}": draw(st.integers(0, 1))
           for p in ("rolling_element", "outer_race", "inner_race", "cage", "shaft", "housing")},
    }
    values: dict[str, object] = {}
    records = []
    blanks = []
    for exp in expected_records(lambda: values):
        fields: dict[str, object] = {}
        for fs in exp.spec.fields:
            names = [fs.name] if fs.count is None else [f"{fs.name}[{i}]" for i in range(1, fields[fs.count] + 1)]
            for name in names:
                if fs.name in override:
                    v = override[fs.name]
                elif fs.name in TIED:
                    v = _template_value(tpl, fs.name)
                    if fs.unit == "m":
                        v = float(f"{v * scale:.4E}")
                elif fs.kind == "int":
                    if fs.choices:
                        v = draw(st.sampled_from(fs.choices))
                    else:
                        v = draw(st.integers(int(fs.lo) if fs.lo is not None else -99999,
                                             int(fs.hi) if fs.hi is not None else 999999))
                elif fs.kind == "text":
                    v = draw(st.text(string.ascii_letters + string.digits + " =-_.", max_size=36)).rstrip()
                else:
                    v = draw(reals(fs))
                fields[name] = v
                if fs.kind == "text" and v == "":
                    blanks.append((len(records), name))  # an empty text field is blank by definition
                elif fs.default is not None and v == fs.default and draw(st.booleans()):
                    blanks.append((len(records), name))
        records.append({"id": exp.rid, "fields": fields})
        for n, v in fields.items():
            values.setdefault(n, v)
    deck = Deck.from_dict({"records": records, "path": "random.inp"})
    for i, name in blanks:
        deck.records[i].fields[name].blank = True
    return deck


@settings(max_examples=100, deadline=None)
@given(decks())
def test_random_valid_decks_round_trip(deck):
    assert deck.validate() == []
    text = format_deck(deck, canonical=True)
    back, problems = parse_text(text, "random.inp")
    assert problems == []
    assert back == deck
    assert back.validate() == []
    assert format_deck(back) == text
    assert format_deck(back, canonical=True) == text
    for a, b in zip(back.records, deck.records):
        assert [f.blank for f in a.fields.values()] == [f.blank for f in b.fields.values()]
    bare = "".join(line[12:] + "\n" for line in text.splitlines())
    if not deck.get("3.1", "run_id", "").lower().startswith("rec "):
        unlabelled, problems = parse_text(bare, "bare.inp")
        assert problems == [] and unlabelled == deck
