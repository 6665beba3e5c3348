"""The machine-readable record schema of an ADORE 5.0 input deck (the single source of truth).

Everything that knows the deck layout is driven from this module and the record table in
:mod:`pyadore.deck.records`: the reader (:mod:`.reader`), the writer (:mod:`.writer`), the
validator (:mod:`.validate`) and the documentation generator (:mod:`.docgen`, which writes
``docs/deck-format.md``).  The Fortran reader mirrors the same table.

Layout rules (see ``docs/deck-format.md`` for the full text):

* One record per line.  A line may start with the optional label ``Rec <id>`` in the
  *label zone*, columns 1-12 (:data:`LABEL_WIDTH`); the data fields then start in column 13.
  A line that does not start with ``Rec `` has no label and its data start in column 1.
* Fields are fixed width: integers ``I6`` (:data:`INT_WIDTH`), reals 11 columns
  (:data:`REAL_WIDTH`, written ``E11.4``, or with five decimals when the value needs it),
  the run id ``A36`` (:data:`TEXT_WIDTH`).
* Which records follow depends on values already read: a record may carry a ``when``
  condition (``"bearing_type == 1"``) and a ``repeat`` count (``"n_guide_lands"``); a
  field may carry a ``count`` (repeat that field ``n`` times).  Conditions are a single
  comparison ``<field> <op> <integer>`` with ``op`` one of ``== != < <= > >=`` so that the
  Fortran reader can evaluate them with a table lookup; counts name one earlier integer field.
"""

from __future__ import annotations

import re
from typing import Callable, Iterator, Mapping

from .records import RECORDS
from .spec import (INT_WIDTH, LABEL_WIDTH, REAL_WIDTH, TEXT_WIDTH, Condition, ExpectedRecord, FieldSpec,
                   RecordSpec, parse_condition)

__all__ = [
    "LABEL_WIDTH", "INT_WIDTH", "REAL_WIDTH", "TEXT_WIDTH", "FieldSpec", "RecordSpec",
    "Condition", "parse_condition", "expected_records", "ExpectedRecord", "record_spec",
    "known_record_id", "static_order", "all_specs", "check_schema",
]


def _schema() -> tuple[RecordSpec, ...]:
    return RECORDS


def record_spec(rid: str) -> RecordSpec | None:
    """The spec for a concrete record id (``"7.2.3"`` maps to ``7.2.n``), or None if unknown."""
    for spec in _schema():
        if spec.rid == rid:
            return spec
        if spec.repeat and re.fullmatch(re.escape(spec.rid).replace(r"\.n", r"\.[1-9][0-9]*"), rid):
            return spec
    return None


def known_record_id(rid: str) -> bool:
    """True when ``rid`` names a record of the schema."""
    return record_spec(rid) is not None


def static_order(rid: str) -> int:
    """Position of a record type in the fixed deck order (-1 if unknown)."""
    spec = record_spec(rid)
    return -1 if spec is None else _schema().index(spec)


def expected_records(values_so_far: Callable[[], Mapping[str, object]]) -> Iterator[ExpectedRecord]:
    """Yield the records a deck must contain, in order.

    ``values_so_far`` is called before each decision and returns the field values read so
    far (name -> value).  Conditions and repeat counts are evaluated lazily, so the caller
    must have stored the fields of each yielded record before asking for the next one.
    If a condition or count cannot be evaluated (the field is missing or unreadable), the
    generator raises :class:`LookupError` naming the field.
    """
    for spec in _schema():
        values = values_so_far()
        cond = spec.condition
        if cond is not None:
            ok = cond.holds(values)
            if ok is None:
                raise LookupError(cond.field)
            if not ok:
                continue
        if spec.repeat:
            n = values.get(spec.repeat)
            if not isinstance(n, int):
                raise LookupError(spec.repeat)
            for i in range(1, n + 1):
                yield ExpectedRecord(spec, spec.occurrence_id(i), i - 1)
        else:
            yield ExpectedRecord(spec, spec.rid, 0)


def all_specs() -> tuple[RecordSpec, ...]:
    """Every record spec in deck order."""
    return _schema()


def check_schema() -> None:
    """Assert the schema is self-consistent (names unique where referenced, conditions parse,
    counts refer to earlier integer fields).  Raises AssertionError otherwise."""
    seen: dict[str, FieldSpec] = {}
    for spec in _schema():
        if spec.when:
            c = parse_condition(spec.when)
            assert c.field in seen and seen[c.field].kind == "int", (spec.rid, c.field)
        if spec.repeat:
            assert spec.repeat in seen and seen[spec.repeat].kind == "int", spec.rid
        local = dict(seen)
        for f in spec.fields:
            if f.count:
                assert f.count in local and local[f.count].kind == "int", (spec.rid, f.name)
            local[f.name] = f
        for f in spec.fields:
            seen.setdefault(f.name, f)
    referenced = {parse_condition(s.when).field for s in _schema() if s.when}
    referenced |= {s.repeat for s in _schema() if s.repeat}
    for name in referenced:
        owners = [s.rid for s in _schema() for f in s.fields if f.name == name]
        assert len(owners) == 1, (name, owners)
