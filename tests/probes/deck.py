"""The engine's Fortran deck reader, as a field table (test_deck_fortran.py)."""

from __future__ import annotations

import os
import tempfile

from .base import _probes, _text, check


def deck_field_table(deck_path: str | os.PathLike) -> list[tuple[str, int, str, object]]:
    """Read a deck with the engine's Fortran reader and return its field table.

    Same shape as :func:`pyadore.deck.field_table`: ``(record id, occurrence, field name,
    value)`` per field in deck order, occurrence 0-based among records of the same type,
    value int, float (exact: written with 17 significant digits) or str in the schema's
    SI unit.  Raises :class:`AdoreInputError` listing every problem for a bad deck.
    """
    with tempfile.TemporaryDirectory(prefix="pyadore-deck-") as tmp:
        table = os.path.join(tmp, "fields.txt")
        status, message = _probes().adore_deck_table(os.fspath(deck_path), table)
        check(int(status), message)
        with open(table, encoding="utf-8") as fh:
            lines = fh.read().split("\n")
    out: list[tuple[str, int, str, object]] = []
    convert = {"int": int, "real": float, "text": str}
    for line in lines:
        if not line:
            continue
        rid, occ, name, kind, value = line.split("\t", 4)
        out.append((rid, int(occ), name, convert[kind](value.strip() if kind != "text" else value)))
    return out
