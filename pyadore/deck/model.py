"""In-memory deck: :class:`Deck`, with its :class:`Record` and :class:`FieldValue` objects
(:mod:`.values`) and :class:`Problem` (:mod:`.problems`), re-exported here.

A :class:`Deck` is a list of records in deck order.  Each record keeps its concrete id
(``"7.2.2"``), its occurrence index among records of the same type, the source line it
came from (so unchanged records are written back verbatim) and its fields as
:class:`FieldValue` objects that carry value, unit, file line and column.
"""

from __future__ import annotations

import json
from pathlib import Path

from .problems import PROBLEM_KINDS, DeckError, Problem
from .schema import record_spec
from .validate import validate_deck
from .values import FieldValue, Record
from .writer import write_deck

__all__ = ["Problem", "FieldValue", "Record", "Deck", "DeckError", "PROBLEM_KINDS"]


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
        write_deck(self, path, canonical=canonical)
