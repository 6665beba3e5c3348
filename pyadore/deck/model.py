"""In-memory deck: :class:`Deck`, its :class:`Record` objects, :class:`FieldValue` and :class:`Problem`.

A :class:`Deck` is a list of records in deck order.  Each record keeps its concrete id
(``"7.2.2"``), its occurrence index among records of the same type, the source line it
came from (so unchanged records are written back verbatim) and its fields as
:class:`FieldValue` objects that carry value, unit, file line and column.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import AdoreInputError
from .schema import FieldSpec, RecordSpec, record_spec

__all__ = ["Problem", "FieldValue", "Record", "Deck", "DeckError", "PROBLEM_KINDS"]

#: Problem classes (also used in tests/data/bad_decks/expected.json).
PROBLEM_KINDS = (
    "io",              # file missing or unreadable
    "non_text",        # binary content, NUL bytes, not UTF-8
    "empty",           # no records at all
    "truncated",       # the file ends before the last required record
    "format",          # tab, text in the label zone, data beyond the last field
    "type",            # a field that is not a valid integer / real / text
    "missing_value",   # a required field left blank
    "range",           # a value outside its valid range
    "cross_field",     # inconsistent values, or a record required / forbidden by a flag or count
    "missing_record",  # an unconditional record absent (labelled decks)
    "surplus_record",  # a record where none is expected (duplicate, out of order, after the end)
    "unknown_record",  # a label naming no record of the schema
)


@dataclass
class Problem:
    """One problem found in a deck, with its location.

    ``line`` and ``col`` are 1-based (0 when not applicable); ``source_line`` is the text of
    the offending line (None when there is none, e.g. a missing file).
    """

    path: str
    line: int
    col: int
    record: str | None
    field: str | None
    value: object
    message: str
    kind: str
    source_line: str | None = None

    def format(self) -> str:
        """``file:line:col  Rec X  field name = value: expected ...`` plus the offending line
        and a caret line pointing at the column."""
        loc = f"{self.path}:{self.line}:{self.col}" if self.line else self.path
        parts = [loc]
        if self.record:
            parts.append(f"Rec {self.record}")
        head = "  ".join(parts)
        if self.field is not None:
            head += f"  field {self.field} = {_show(self.value)}"
        head += f": {self.message}"
        if self.source_line is None:
            return head
        caret = " " * max(self.col - 1, 0) + "^"
        shown = self.source_line.replace("\t", " ")  # one column per character, so the caret lines up
        return f"{head}\n    {shown}\n    {caret}"

    def to_dict(self) -> dict:
        """JSON-friendly dict of the problem."""
        return {"path": self.path, "line": self.line, "col": self.col, "record": self.record,
                "field": self.field, "value": _jsonable(self.value), "message": self.message,
                "kind": self.kind}


def _show(v: object) -> str:
    if v is None:
        return "(blank)"
    if isinstance(v, float):
        return f"{v:.6G}"
    if isinstance(v, str):
        return repr(v)
    return str(v)


def _jsonable(v):
    return v if isinstance(v, (int, float, str, type(None))) else str(v)


class DeckError(AdoreInputError):
    """A deck could not be read or written; ``problems`` lists every problem found."""

    def __init__(self, message: str, problems: list[Problem] | None = None):
        super().__init__(message)
        self.problems = list(problems or [])

    def __str__(self) -> str:
        base = super().__str__()
        if not self.problems:
            return base
        return base + "\n" + "\n".join(p.format() for p in self.problems)


@dataclass
class FieldValue:
    """One field of a record: value (``int``/``float``/``str``, None if unreadable), its
    spec, whether it was blank in the file, and its 1-based line and column (0 if built in memory)."""

    name: str
    spec: FieldSpec
    value: object
    blank: bool = False
    line: int = 0
    col: int = 0
    raw: str = ""

    @property
    def unit(self) -> str:
        """Unit of the value (SI; ``-`` for dimensionless)."""
        return self.spec.unit


@dataclass
class Record:
    """One record of a deck: concrete id, occurrence index (0-based among records of the
    same spec), fields in order, and the source line it was read from."""

    rid: str
    spec: RecordSpec
    fields: dict[str, FieldValue]
    occurrence: int = 0
    line: int = 0
    labelled: bool = True
    source: str | None = None
    _read_values: tuple | None = field(default=None, repr=False, compare=False)

    def __getitem__(self, name: str) -> object:
        return self.fields[name].value

    def values(self) -> dict[str, object]:
        """Field name -> value, in order."""
        return {n: f.value for n, f in self.fields.items()}

    def unchanged(self) -> bool:
        """True when the values still equal those read from ``source`` (write it verbatim)."""
        return self.source is not None and self._read_values == tuple(self.values().items())

    def mark_read(self) -> None:
        """Remember the current values as the values read from ``source``."""
        self._read_values = tuple(self.values().items())


class Deck:
    """A parsed ADORE deck: ``records`` in deck order, ``path`` it came from.

    Field access: ``deck.get("5A", "pitch_diameter")``; ``deck.set(...)`` changes a value
    (the record is then re-formatted by the writer instead of copied verbatim).
    """

    def __init__(self, records: list[Record], path: str = "<memory>"):
        self.records = records
        self.path = path

    # -- access -------------------------------------------------------------------------
    def record(self, rid: str, occurrence: int = 0) -> Record | None:
        """The record with concrete id ``rid`` (``occurrence`` among equal ids), or None."""
        hits = [r for r in self.records if r.rid == rid]
        return hits[occurrence] if len(hits) > occurrence else None

    def get(self, rid: str, name: str, default=None):
        """Value of field ``name`` of record ``rid`` (``default`` if absent)."""
        rec = self.record(rid)
        if rec is None or name not in rec.fields:
            return default
        return rec.fields[name].value

    def set(self, rid: str, name: str, value) -> None:
        """Set field ``name`` of record ``rid`` (KeyError if absent).  The value must have the
        field's kind (int for ``int`` fields, float for ``real``, str for ``text``)."""
        rec = self.record(rid)
        if rec is None or name not in rec.fields:
            raise KeyError(f"Rec {rid} field {name}")
        fv = rec.fields[name]
        fv.value = value
        fv.blank = False

    def lookup(self, name: str):
        """Value of the first field called ``name`` anywhere in the deck (None if absent)."""
        for rec in self.records:
            if name in rec.fields:
                return rec.fields[name].value
        return None

    def values(self) -> dict[str, object]:
        """All field values by name (first occurrence wins), as the schema conditions see them."""
        out: dict[str, object] = {}
        for rec in self.records:
            for n, f in rec.fields.items():
                out.setdefault(n, f.value)
        return out

    @property
    def bearing_type(self) -> int | None:
        """1 = ball, 2 = cylindrical roller (Rec 3.2)."""
        return self.get("3.2", "bearing_type")

    # -- comparison and serialisation ------------------------------------------------------
    def key(self) -> list[tuple[str, tuple]]:
        """The deck's content as comparable data: (record id, ((field, value), ...)) in order."""
        return [(r.rid, tuple(r.values().items())) for r in self.records]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Deck) and self.key() == other.key()

    def __repr__(self) -> str:
        return f"Deck({self.path!r}, {len(self.records)} records)"

    def to_dict(self) -> dict:
        """JSON-friendly dict: path and records, each with id, occurrence, line, label flag,
        field values, units and ``[line, col]`` positions."""
        return {
            "path": str(self.path),
            "records": [{
                "id": r.rid, "occurrence": r.occurrence, "line": r.line, "labelled": r.labelled,
                "fields": {n: f.value for n, f in r.fields.items()},
                "units": {n: f.unit for n, f in r.fields.items()},
                "positions": {n: [f.line, f.col] for n, f in r.fields.items()},
            } for r in self.records],
        }

    def to_json(self, indent: int | None = 1) -> str:
        """:meth:`to_dict` as JSON text."""
        return json.dumps(self.to_dict(), indent=indent)

    @classmethod
    def from_dict(cls, data: dict) -> "Deck":
        """Rebuild a deck from :meth:`to_dict` output (or any dict with ``records`` of
        ``{"id", "fields"}``); raises DeckError for unknown ids or fields."""
        records: list[Record] = []
        counts: dict[str, int] = {}
        for item in data["records"]:
            rid = item["id"]
            spec = record_spec(rid)
            if spec is None:
                raise DeckError(f"unknown record id {rid!r}")
            values = dict(item["fields"])
            names = spec.expand_fields(values)
            if names is None or [n for n, _ in names] != list(values):
                raise DeckError(f"Rec {rid}: fields {list(values)} do not match the schema")
            fields = {n: FieldValue(n, fs, values[n]) for n, fs in names}
            occ = counts.get(spec.rid, 0)
            counts[spec.rid] = occ + 1
            records.append(Record(rid, spec, fields, occurrence=occ, source=None))
        return cls(records, data.get("path", "<memory>"))

    # -- reports ----------------------------------------------------------------------------
    def validate(self) -> list[Problem]:
        """Range and cross-field checks (all problems at once); see :mod:`.validate`."""
        from .validate import validate_deck
        return validate_deck(self)

    def summary(self) -> str:
        """One line, e.g. ``decks/appendix_c_ball.inp: BALL bearing, 18 balls, 29 records, OK``."""
        btype = {1: ("BALL", "balls"), 2: ("CYLINDRICAL ROLLER", "rollers")}.get(
            self.bearing_type, ("UNKNOWN", "rolling elements"))
        n = self.get("3.2", "n_rolling_elements")
        problems = self.validate()
        status = "OK" if not problems else f"{len(problems)} problem(s)"
        return f"{self.path}: {btype[0]} bearing, {n} {btype[1]}, {len(self.records)} records, {status}"

    def save(self, path: str | Path, canonical: bool = False) -> None:
        """Write the deck to ``path`` (see :func:`pyadore.deck.write_deck`)."""
        from .writer import write_deck
        write_deck(self, path, canonical=canonical)
