"""ADORE 5.0 input decks: read, validate, write, document.

Public API::

    deck = read_deck("decks/appendix_c_ball.inp")       # raises DeckError on bad input
    deck, problems = check_deck(path)                    # never raises; problems as objects
    for p in problems: print(p.format())                 # file:line:col  Rec X  field ...
    deck.validate(); deck.summary(); deck.to_json()
    write_deck(deck, "out.inp")                          # unchanged records verbatim
    field_table(deck)                                    # [(record id, occurrence, field, value)]

The layout is defined once, in :mod:`pyadore.deck.spec` (types), :mod:`pyadore.deck.records`
(the record table) and :mod:`pyadore.deck.schema` (queries on it); ``python -m
pyadore.deck.docgen`` prints ``docs/deck-format.md`` from it.  Importing this package never
loads the compiled engine; validation calls the engine's cross-field checks
(:mod:`pyadore._core`), the one implementation of those checks.
"""

from __future__ import annotations

from .model import PROBLEM_KINDS, Deck, DeckError, DeckFieldError, FieldValue, Problem, Record
from .reader import check_deck, parse_text, read_deck
from .schema import all_specs, record_spec
from .writer import format_deck, write_deck

__all__ = [
    "read_deck", "check_deck", "write_deck", "format_deck", "parse_text", "field_table",
    "run_validate", "Deck", "Record", "FieldValue", "Problem", "DeckError", "DeckFieldError", "PROBLEM_KINDS",
    "all_specs", "record_spec",
]


def field_table(deck: Deck) -> list[tuple[str, int, str, object]]:
    """Every field in deck order as ``(record id, occurrence index, field name, value)``.

    ``occurrence`` is the 0-based index among records of the same type (``7.2.1`` -> 0,
    ``7.2.2`` -> 1); repeated fields are named ``guide_type[1]``, ``guide_type[2]``...
    Values are int, float or str in the field's schema unit.  Used to compare the Python
    reader with the Fortran reader's dump field by field.
    """
    return [(rec.rid, rec.occurrence, name, fv.value)
            for rec in deck.records for name, fv in rec.fields.items()]


def run_validate(path, echo=print) -> int:
    """``pyadore validate DECK`` behaviour: print every problem (or a one-line summary) with
    ``echo`` and return the exit status (1 with problems, 0 without)."""
    deck, problems = check_deck(path)
    if problems:
        for p in problems:
            echo(p.format())
        echo(f"{path}: {len(problems)} problem(s)")
        return 1
    echo(deck.summary())
    return 0
