"""Value checks of a parsed deck: ranges from the schema, cross-field consistency (the
engine's checks, called through the extension), structure.

All problems are collected and returned at once; nothing raises.  Fields whose value is
None (unreadable; already reported by the reader) are skipped.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .. import _core
from .problems import Problem
from .schema import expected_records
from .values import FieldValue, Record

if TYPE_CHECKING:  # annotations only: model.py imports this module
    from .model import Deck

__all__ = ["validate_deck", "deck_warnings"]


def _problem(deck: Deck, rec: Record | None, fv: FieldValue | None, msg: str, kind: str) -> Problem:
    if rec is None:
        return Problem(str(deck.path), 0, 0, None, None, None, msg, kind)
    if fv is None:
        return Problem(str(deck.path), rec.line, 1 if rec.line else 0, rec.rid, None, None, msg, kind,
                       rec.source if rec.line else None)
    lead = len(fv.raw) - len(fv.raw.lstrip()) if fv.raw.strip() else 0  # caret on the first character
    return Problem(str(deck.path), fv.line, fv.col + lead if fv.line else 0, rec.rid, fv.name, fv.value, msg,
                   kind, rec.source if fv.line else None)


def _ranges(deck: Deck) -> list[Problem]:
    out = []
    for rec in deck.records:
        for fv in rec.fields.values():
            v = fv.value
            if v is None:
                continue
            spec = fv.spec
            if spec.kind == "text":
                if len(v) > 36:
                    out.append(_problem(deck, rec, fv, "expected at most 36 characters", "range"))
                continue
            if not spec.in_range(v):
                out.append(_problem(deck, rec, fv, f"expected {spec.range_text()} ({spec.meaning.split(';')[0]})",
                                    "range"))
    return out


def _find(deck: Deck, name: str) -> tuple[Record | None, FieldValue | None]:
    for rec in deck.records:
        fv = rec.fields.get(name)
        if fv is not None:
            return rec, fv
    return None, None


def _num(deck: Deck, name: str):
    _, fv = _find(deck, name)
    return None if fv is None else fv.value


def _cross_fields(deck: Deck, warnings: bool = False) -> list[Problem]:
    """The engine's cross-field checks (fortran/model/checks.f90, the ones ``adore`` applies
    before a run), each reported at its field of this deck: the errors, or with
    ``warnings`` the warnings (legal but implausible values, kind ``warning``)."""
    values = {name: _num(deck, name) for name in _core.cross_field_fields()}
    out = []
    for name, message, warning in _core.cross_field_problems(values):
        if warning != warnings:
            continue
        rec, fv = _find(deck, name)
        out.append(_problem(deck, rec, fv, message, "warning" if warning else "cross_field"))
    return out


def deck_warnings(deck: Deck) -> list[Problem]:
    """Legal but implausible values of ``deck`` (kind ``warning``): the engine's warning
    rules (fortran/model/checks.f90), which ``adore`` reports in its run note and runs on."""
    return _cross_fields(deck, warnings=True)


def _structure(deck: Deck) -> list[Problem]:
    """Records present exactly as the schema and the deck's own flags/counts require."""
    values = deck.values()
    try:
        expected = [e.rid for e in expected_records(lambda: values)]
    except LookupError as exc:
        return [_problem(deck, None, None, f"cannot determine the record sequence: field {exc.args[0]} "
                         "is missing or unreadable", "cross_field")]
    actual = [r.rid for r in deck.records]
    out = []
    for rid in expected:
        if rid not in actual:
            out.append(_problem(deck, deck.records[-1] if deck.records else None, None,
                                f"missing record: expected Rec {rid} (required by the deck's flags/counts)",
                                "cross_field"))
    for rec in deck.records:
        if rec.rid not in expected:
            out.append(_problem(deck, rec, None, f"unexpected record: Rec {rec.rid} is not required by "
                                "the deck's flags/counts", "cross_field"))
    return out


def validate_deck(deck: Deck, structure: bool = True) -> list[Problem]:
    """All range, cross-field (and, if ``structure``, record-presence) problems of ``deck``."""
    out = _ranges(deck)
    out.extend(_cross_fields(deck))
    if structure and deck.records:
        out.extend(_structure(deck))
    return out
