"""Writing decks in the legacy fixed-column layout.

Canonical form of a record: the label ``Rec <id>`` left-aligned in columns 1-12, then the
fields: integers right-aligned in 6 columns, reals in 11 columns as ``E11.4``
(``  1.0000E-01``) or, when four decimals would change the value, with five
(``1.46292E-01``, which fills the field), the run id left-aligned; trailing blanks removed;
a blank field that still holds its default stays blank.  Lines end with ``\\n``.

:func:`write_deck` copies records whose values did not change since they were read
verbatim from their source line, and formats the others canonically.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from .problems import DeckError
from .schema import LABEL_WIDTH
from .tokenizer import parse_value
from .values import FieldValue, Record

if TYPE_CHECKING:  # annotations only: model.py imports this module
    from .model import Deck

__all__ = ["write_deck", "format_deck", "format_record", "format_value"]


def format_value(fv: FieldValue) -> str:
    """The field text (exactly ``fv.spec.width`` columns) for a value; raises DeckError if
    the value does not fit the field or cannot be written without changing it."""
    spec, v = fv.spec, fv.value
    w = spec.width
    if fv.blank and v == spec.default:
        return " " * w
    if v is None:
        raise DeckError(f"field {fv.name}: no value to write")
    if spec.kind == "text":
        s = str(v)
        if len(s) > w:
            raise DeckError(f"field {fv.name}: text of {len(s)} characters does not fit {w} columns")
        return s.ljust(w)
    if spec.kind == "int":
        if isinstance(v, bool) or not isinstance(v, int):
            raise DeckError(f"field {fv.name}: expected an integer, got {v!r}")
        s = str(v)
        if len(s) > w:
            raise DeckError(f"field {fv.name}: {v} does not fit I{w}")
        return s.rjust(w)
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise DeckError(f"field {fv.name}: expected a real, got {v!r}")
    v = float(v)
    for cand in (f"{v:.4E}", f"{v:.5E}", f"{v:.3E}", f"{v:.2E}", f"{v:.1E}", repr(v)):
        if len(cand) > w:
            continue
        parsed, _, err = parse_value(spec, cand)
        if err is None and parsed == v:
            return cand.rjust(w)
    raise DeckError(f"field {fv.name}: {v!r} cannot be written exactly in {w} columns")


def format_record(rec: Record) -> str:
    """The canonical line (without newline) for a record."""
    label = f"Rec {rec.rid}".ljust(LABEL_WIDTH)
    return (label + "".join(format_value(fv) for fv in rec.fields.values())).rstrip()


def format_deck(deck: Deck, canonical: bool = False) -> str:
    """The deck as text; unchanged records verbatim unless ``canonical``."""
    lines = []
    for rec in deck.records:
        if not canonical and rec.unchanged():
            lines.append(rec.source)
        else:
            lines.append(format_record(rec))
    return "".join(line + "\n" for line in lines)


def write_deck(deck: Deck, path, canonical: bool = False) -> None:
    """Write ``deck`` to ``path`` in the legacy layout (see the module docstring).

    ``canonical=True`` re-formats every record; otherwise records read from a file and not
    changed since are copied verbatim.  Raises DeckError if a value cannot be written.
    """
    Path(path).write_bytes(format_deck(deck, canonical).encode("utf-8"))
