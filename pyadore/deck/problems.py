"""A problem found in a deck (:class:`Problem`, with its location and the ``file:line:col``
format every reader and checker uses), the problem classes and :class:`DeckError`."""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import AdoreInputError

__all__ = ["Problem", "DeckError", "PROBLEM_KINDS"]

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
