"""The cases of a parametric sweep: which deck fields vary, their values, and the case decks.

A varied field is named as in the deck schema (``docs/deck-format.md``): ``FIELD`` when
one record of the deck has a field of that name, ``REC/FIELD`` otherwise (``8.2/density``;
``7.2.n/guide_land_clearance`` sets the field in every occurrence of a repeated record).
Values are in the deck's units (the schema's unit of the field: rpm for speeds, N for
forces, m for lengths, K for temperatures).  Several varied fields make the full grid
(first field slowest) or, with ``zip``, the cases pair the i-th values.  A range
``START:STOP:COUNT`` gives COUNT evenly spaced values, both ends included.

Each case deck is the base deck with the varied fields changed, written by
:func:`pyadore.deck.format_deck`: every record that did not change is copied verbatim.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

from ..deck import Deck, DeckError, FieldValue, format_deck
from ..deck.derived import DERIVED_FIELDS
from ..deck.model import DeckFieldError
from ..deck.spec import FieldSpec
from ..deck.writer import format_value
from ..errors import AdoreInputError

__all__ = ["SweepError", "Varied", "Case", "resolve_field", "parse_vary", "make_cases", "case_deck_text"]


class SweepError(AdoreInputError):
    """A sweep cannot start: a bad ``--vary``, an unknown field, a DIR holding another sweep."""


@dataclass(frozen=True)
class Varied:
    """One varied field: the name as the user gave it (the summary's column), the records
    (concrete ids, e.g. ``9.1.2``) and field name it sets, its unit and its values."""

    name: str
    records: tuple[str, ...]
    field: str
    unit: str
    values: tuple


@dataclass(frozen=True)
class Case:
    """One case of a sweep: its id (``case_0001``) and the value of each varied field."""

    case_id: str
    params: dict


def resolve_field(name: str, deck: Deck) -> tuple[tuple[str, ...], str, object]:
    """The records (concrete ids) and field that ``name`` (``FIELD`` or ``REC/FIELD``)
    names in ``deck`` (:meth:`pyadore.deck.Deck.locate`), and the field's spec.  Raises
    :class:`SweepError` when the field is unknown, absent from the deck, or in several
    records without ``REC/`` to choose."""
    derived = deck._derived(name)
    if derived is not None:  # e.g. diametral_clearance: sets the free contact angle
        try:
            derived.get(deck)
        except DeckError as exc:
            raise SweepError(f"--vary {exc}") from None
        return (derived.record,), derived.name, FieldSpec(derived.name, derived.kind, derived.unit, derived.meaning)
    try:
        hits, field = deck.locate(name)
    except DeckFieldError as exc:
        raise SweepError(f"--vary {exc}") from None
    return tuple(r.rid for r in hits), field, hits[0].fields[field].spec


def _convert(name: str, spec, text: str):
    t = text.strip()
    if spec.kind == "text":
        return t
    try:
        if spec.kind == "int":
            return int(t)
        return float(t.replace("D", "E").replace("d", "e"))
    except ValueError:
        kind = "an integer" if spec.kind == "int" else "a number"
        raise SweepError(f"--vary {name}: value {text!r} is not {kind} (the field is "
                         f"{'an integer' if spec.kind == 'int' else 'a real'} in {spec.unit})") from None


def _expand(name: str, spec, text: str) -> list:
    """The values of one comma-separated item: a value, or ``START:STOP:COUNT``, COUNT
    evenly spaced values from START to STOP, both included (``10000:25000:4`` gives
    10000, 15000, 20000, 25000); an integer field's range must fall on integers."""
    if ":" not in text:
        return [_convert(name, spec, text)]
    parts = text.split(":")
    if len(parts) != 3 or spec.kind == "text":
        raise SweepError(f"--vary {name}: {text.strip()!r}: a range is START:STOP:COUNT (e.g. 10000:25000:4, "
                         "both ends included)" + (" of a numeric field" if spec.kind == "text" else ""))
    try:
        start, stop = (float(p.strip().replace("D", "E").replace("d", "e")) for p in parts[:2])
        count = int(parts[2].strip())
    except ValueError:
        raise SweepError(f"--vary {name}: {text.strip()!r}: a range is START:STOP:COUNT with numbers START, "
                         "STOP and an integer COUNT >= 2 (e.g. 10000:25000:4)") from None
    if count < 2 or start == stop:
        raise SweepError(f"--vary {name}: {text.strip()!r}: a range needs COUNT >= 2 and START != STOP "
                         "(a single value is written as it is)")
    values = [start + (stop - start) * k / (count - 1) for k in range(count)]
    values[-1] = stop
    if spec.kind == "int":
        if any(abs(v - round(v)) > 1e-9 * max(1.0, abs(v)) for v in values):
            raise SweepError(f"--vary {name}: {text.strip()!r}: the field is an integer and this range "
                             f"gives {', '.join(f'{v:g}' for v in values)}")
        return [int(round(v)) for v in values]
    # a value a hair off a round number (0.1 steps) is written as the round number
    return [float(f"{v:.12g}") for v in values]


def parse_vary(spec_text: str, deck: Deck) -> Varied:
    """``FIELD=V1,V2,...`` (values in the deck's units) resolved against ``deck``; an
    item may be a range ``START:STOP:COUNT`` (:func:`_expand`)."""
    if "=" not in spec_text:
        raise SweepError(f"--vary {spec_text!r}: expected FIELD=V1,V2,... or FIELD=START:STOP:COUNT (e.g. "
                         "inner_race_speed=10000,20000 or inner_race_speed=10000:25000:4)")
    name, _, rest = spec_text.partition("=")
    name = name.strip()
    texts = [v for v in rest.split(",")]
    if not name or not rest.strip() or any(not v.strip() for v in texts):
        raise SweepError(f"--vary {spec_text!r}: expected FIELD=V1,V2,... with no empty value")
    records, field, fspec = resolve_field(name, deck)
    values = tuple(v for text in texts for v in _expand(name, fspec, text))
    for value in values if field not in DERIVED_FIELDS else ():  # a derived field is rounded to fit
        try:
            format_value(FieldValue(field, fspec, value))
        except DeckError as exc:
            raise SweepError(f"--vary {name}: {exc} (the deck's fixed columns; round the value)") from None
    if len(set(values)) != len(values):
        raise SweepError(f"--vary {name}: a value is repeated in {rest!r}")
    return Varied(name=name, records=records, field=field, unit=fspec.unit, values=values)


def make_cases(varied: list[Varied], zip_values: bool = False) -> list[Case]:
    """The cases: the full grid of the varied values (first field slowest), or with
    ``zip_values`` the i-th value of every field together (all lists of one length)."""
    if not varied:
        raise SweepError("nothing to vary: give at least one --vary FIELD=V1,V2,...")
    names = [v.name for v in varied]
    if len(set(names)) != len(names):
        raise SweepError(f"a field is varied twice: {', '.join(names)}")
    targets = [(r, DERIVED_FIELDS[v.field].sets if v.field in DERIVED_FIELDS else v.field)
               for v in varied for r in v.records]
    if len(set(targets)) != len(targets):
        raise SweepError(f"two --vary name the same deck field: {', '.join(names)}")
    if zip_values:
        lengths = {len(v.values) for v in varied}
        if len(lengths) != 1:
            raise SweepError("--zip pairs the values: every --vary needs the same number of values (got "
                             + ", ".join(f"{v.name}: {len(v.values)}" for v in varied) + ")")
        rows = list(zip(*(v.values for v in varied)))
    else:
        rows = list(itertools.product(*(v.values for v in varied)))
    width = max(4, len(str(len(rows))))
    return [Case(f"case_{i + 1:0{width}d}", dict(zip(names, row))) for i, row in enumerate(rows)]


def case_deck_text(base_text: str, base_path: str, varied: list[Varied], case: Case, base=None) -> str:
    """The deck text of ``case``: the base deck with the varied fields set, unchanged records
    verbatim.  ``base``: the base deck already parsed from ``base_text`` (a sweep parses it once;
    its values are restored before this returns, so it serves every case).  Raises
    :class:`~pyadore.deck.DeckError` when a value cannot be written in its field (the case is
    then invalid)."""
    from ..deck import parse_text

    deck = base
    if deck is None:
        deck, problems = parse_text(base_text, base_path)
        if problems:
            raise DeckError(f"{base_path}: {len(problems)} problem(s) reading the deck", problems)
    saved = [(fv, fv.value, fv.blank) for rec in deck.records for fv in rec.fields.values()]
    try:
        for v in varied:
            value = case.params[v.name]
            if v.field in DERIVED_FIELDS:
                deck.set(v.field, value)
                continue
            for rec in deck.records:
                if rec.rid in v.records and v.field in rec.fields:
                    fv = rec.fields[v.field]
                    fv.value = value
                    fv.blank = False
        for rec in deck.records:  # the case's print is titled with its parameters (Rec 3.1)
            if rec.rid == "3.1" and "run_id" in rec.fields:
                rec.fields["run_id"].value = case_title(case)
                rec.fields["run_id"].blank = False
        return format_deck(deck)
    finally:  # the base deck as read, for the next case
        for fv, value, blank in saved:
            fv.value = value
            fv.blank = blank


def case_title(case: Case) -> str:
    """The run identification of a case deck (Rec 3.1, at most 36 characters): its varied
    parameters ``name=value`` (the value as short as it reads back exactly), cut to 36
    characters after the case id when longer."""
    def short(value) -> str:
        if isinstance(value, float) and float(f"{value:g}") == value:
            return f"{value:g}"
        return str(value)

    text = " ".join(f"{name}={short(value)}" for name, value in case.params.items())
    if len(text) > 36:
        text = (case.case_id.replace("case_", "#") + " " + text)[:36]
    return text
