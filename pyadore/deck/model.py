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
from .schema import all_specs, record_spec
from .validate import validate_deck
from .values import FieldValue, Record
from .writer import write_deck

__all__ = ["Problem", "FieldValue", "Record", "Deck", "DeckError", "DeckFieldError", "PROBLEM_KINDS"]


class DeckFieldError(DeckError, KeyError):
    """A field name that names no field of the deck, or several (:meth:`Deck.locate`): a
    :class:`DeckError` (so an AdoreInputError) and a KeyError."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def _unknown_field(name: str, deck: "Deck") -> DeckFieldError:
    """Why ``name`` names no field of ``deck``: the records of the schema that have it, or
    the deck's field names closest to it."""
    import difflib

    known = [spec.rid for spec in all_specs() if any(f.name == name for f in spec.fields)]
    if known:
        recs = ", ".join(f"Rec {r}" for r in known)
        return DeckFieldError(f"{name}: the field is in {recs}, which this deck ({deck.path}) does not have")
    in_deck = sorted({n for rec in deck.records for n in rec.fields})
    close = difflib.get_close_matches(name, in_deck, n=4, cutoff=0.6)
    hint = f"; did you mean {', '.join(close)}?" if close else ""
    return DeckFieldError(f"{name}: no deck field of that name{hint} (field names are those of "
                          f"docs/deck-format.md, e.g. inner_race_speed, applied_force_z, inner_race_fit)")


class Deck:
    """A parsed ADORE deck: ``records`` in deck order, ``path`` it came from.

    Field access: ``deck.get("5A", "pitch_diameter")`` or ``deck.lookup("pitch_diameter")``;
    ``deck.set("inner_race_speed", 15000.0)`` (or with the record id first) changes a value
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

    def locate(self, name: str) -> tuple[list[Record], str]:
        """The records holding the field ``name`` and the field's name: ``FIELD`` when one
        record of the deck has a field of that name, ``REC/FIELD`` to choose among several
        (``9.1.1/applied_force_x``; a record type such as ``7.2.n`` names every occurrence).
        Raises :class:`DeckFieldError` (a KeyError) saying what is wrong: no such field (with
        the closest names), a record the deck lacks, several records without ``REC/``."""
        if "/" in name:
            rid, field = (s.strip() for s in name.split("/", 1))
            hits = [r for r in self.records if r.rid == rid or r.spec.rid == rid]
            if not hits:
                raise DeckFieldError(f"{name}: this deck ({self.path}) has no Rec {rid}")
            held = [r for r in hits if field in r.fields]
            if not held:
                raise DeckFieldError(f"{name}: Rec {rid} has no field {field}; its fields are "
                               f"{', '.join(hits[0].fields)}")
            return held, field
        field = name.strip()
        hits = [r for r in self.records if field in r.fields]
        if not hits:
            raise _unknown_field(field, self)
        if len(hits) > 1:
            raise DeckFieldError(f"{name}: the field is in several records of this deck; name one as REC/FIELD: "
                           + ", ".join(f"{r.rid}/{field}" for r in hits))
        return hits, field

    def set(self, *args) -> None:
        """Set a field: ``deck.set("inner_race_speed", 15000.0)`` by field name as
        :meth:`lookup` takes it (``REC/FIELD`` where several records have the field:
        :meth:`locate`; a derived field such as ``diametral_clearance`` sets the field it
        stands for, :mod:`pyadore.deck.derived`), or ``deck.set("9.1.1", "applied_force_x", 500.0)`` by record id and
        field.  KeyError (:class:`DeckFieldError` for a field name) when the field is absent
        (or the name ambiguous).  The value must
        have the field's kind (int for ``int`` fields, a number for ``real``, str for
        ``text``); an int given to a real field is stored as float."""
        if len(args) == 3:
            rid, name, value = args
            rec = self.record(rid)
            if rec is None or name not in rec.fields:
                raise KeyError(f"Rec {rid} field {name}")
            records = [rec]
        elif len(args) == 2:
            field, value = args
            derived = self._derived(field)
            if derived is not None:
                derived.set(self, value)
                return
            records, name = self.locate(field)
        else:
            raise TypeError(f"Deck.set takes (field, value) or (record id, field, value), got {len(args)} "
                            "arguments")
        for rec in records:
            fv = rec.fields[name]
            if fv.spec.kind == "real" and isinstance(value, int) and not isinstance(value, bool):
                value = float(value)
            fv.value = value
            fv.blank = False

    def lookup(self, name: str):
        """Value of the first field called ``name`` anywhere in the deck (None if absent);
        ``REC/FIELD`` names the record (:meth:`locate`); a derived field
        (:mod:`pyadore.deck.derived`, e.g. ``diametral_clearance``) is computed."""
        derived = self._derived(name)
        if derived is not None:
            try:
                return derived.get(self)
            except DeckError:
                return None
        if "/" in name:
            try:
                records, field = self.locate(name)
            except DeckFieldError:
                return None
            return records[0].fields[field].value
        for rec in self.records:
            if name in rec.fields:
                return rec.fields[name].value
        return None

    def _derived(self, name: str):
        """The derived field ``name`` (:data:`pyadore.deck.derived.DERIVED_FIELDS`) when the
        deck has no field of that name, else None."""
        from .derived import DERIVED_FIELDS

        derived = DERIVED_FIELDS.get(str(name).strip())
        if derived is None or any(derived.name in r.fields for r in self.records):
            return None
        return derived

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
