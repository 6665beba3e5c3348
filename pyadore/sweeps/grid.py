"""The cases of a parametric sweep: which deck fields vary, their values, and the case decks.

A varied field is named as in the deck schema (``docs/deck-format.md``): ``FIELD`` when
one record of the deck has a field of that name, ``REC/FIELD`` otherwise (``8.2/density``;
``7.2.n/guide_land_clearance`` sets the field in every occurrence of a repeated record).
Values are in the deck's units (the schema's unit of the field: rpm for speeds, N for
forces, m for lengths, K for temperatures).  Several varied fields make the full grid
(first field slowest) or, with ``zip``, the cases pair the i-th values.

Each case deck is the base deck with the varied fields changed, written by
:func:`pyadore.deck.format_deck`: every record that did not change is copied verbatim.
"""

from __future__ import annotations

import difflib
import itertools
from dataclasses import dataclass

from ..deck import Deck, DeckError, FieldValue, all_specs, format_deck
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


def _schema_fields() -> dict[str, list[str]]:
    names: dict[str, list[str]] = {}
    for spec in all_specs():
        for f in spec.fields:
            names.setdefault(f.name, []).append(spec.rid)
    return names


def _unknown_field(name: str, deck: Deck) -> SweepError:
    known = _schema_fields()
    if name in known:
        recs = ", ".join(f"Rec {r}" for r in known[name])
        return SweepError(f"--vary {name}: the field is in {recs}, which this deck ({deck.path}) does not have")
    in_deck = sorted({n for rec in deck.records for n in rec.fields})
    close = difflib.get_close_matches(name, in_deck, n=4, cutoff=0.6)
    hint = f"; did you mean {', '.join(close)}?" if close else ""
    return SweepError(f"--vary {name}: no deck field of that name{hint} (field names are those of "
                      f"docs/deck-format.md, e.g. inner_race_speed, applied_force_z, inner_race_fit)")


def resolve_field(name: str, deck: Deck) -> tuple[tuple[str, ...], str, object]:
    """The records (concrete ids) and field that ``name`` (``FIELD`` or ``REC/FIELD``)
    names in ``deck``, and the field's spec.  Raises :class:`SweepError` when the field is
    unknown, absent from the deck, or in several records without ``REC/`` to choose."""
    if "/" in name:
        rid, field = (s.strip() for s in name.split("/", 1))
        hits = [r for r in deck.records if (r.rid == rid or r.spec.rid == rid)]
        if not hits:
            raise SweepError(f"--vary {name}: this deck ({deck.path}) has no Rec {rid}")
        hits = [r for r in hits if field in r.fields]
        if not hits:
            fields = ", ".join(deck.record(rid).fields) if deck.record(rid) else "(see docs/deck-format.md)"
            raise SweepError(f"--vary {name}: Rec {rid} has no field {field}; its fields are {fields}")
    else:
        field = name.strip()
        hits = [r for r in deck.records if field in r.fields]
        if not hits:
            raise _unknown_field(field, deck)
        if len(hits) > 1:
            choices = ", ".join(f"{r.rid}/{field}" for r in hits)
            raise SweepError(f"--vary {name}: the field is in several records of this deck; name one as "
                             f"REC/FIELD: {choices}")
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


def parse_vary(spec_text: str, deck: Deck) -> Varied:
    """``FIELD=V1,V2,...`` (values in the deck's units) resolved against ``deck``."""
    if "=" not in spec_text:
        raise SweepError(f"--vary {spec_text!r}: expected FIELD=V1,V2,... (e.g. inner_race_speed=10000,20000)")
    name, _, rest = spec_text.partition("=")
    name = name.strip()
    texts = [v for v in rest.split(",")]
    if not name or not rest.strip() or any(not v.strip() for v in texts):
        raise SweepError(f"--vary {spec_text!r}: expected FIELD=V1,V2,... with no empty value")
    records, field, fspec = resolve_field(name, deck)
    values = tuple(_convert(name, fspec, v) for v in texts)
    for value in values:
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
    targets = [(r, v.field) for v in varied for r in v.records]
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


def case_deck_text(base_text: str, base_path: str, varied: list[Varied], case: Case) -> str:
    """The deck text of ``case``: the base deck with the varied fields set, unchanged records
    verbatim.  Raises :class:`~pyadore.deck.DeckError` when a value cannot be written in its
    field (the case is then invalid)."""
    from ..deck import parse_text

    deck, problems = parse_text(base_text, base_path)
    if problems:
        raise DeckError(f"{base_path}: {len(problems)} problem(s) reading the deck", problems)
    for v in varied:
        value = case.params[v.name]
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
