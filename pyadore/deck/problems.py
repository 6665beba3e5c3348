"""A problem found in a deck (:class:`Problem`, with its location and the ``file:line:col``
format every reader and checker uses), the problem classes and :class:`DeckError`."""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import AdoreInputError

__all__ = ["Problem", "DeckError", "PROBLEM_KINDS", "MAX_SHOWN_PROBLEMS", "SOURCE_WINDOW", "shown_source",
           "format_problems"]

#: At most this many problems are listed in one message; the rest are counted
#: (fortran/deck/problems.f90 uses the same number).
MAX_SHOWN_PROBLEMS = 50
#: A source line longer than this many characters is shown as a window of this width
#: around the caret, cut ends marked "..." (fortran/deck/problems.f90: the same rule).
SOURCE_WINDOW = 160

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
# A warning (pyadore.deck.validate.deck_warnings: a legal but implausible value, reported
# while the run goes on) is a Problem of kind "warning", not a problem class of a bad deck.


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
        shown, col = shown_source(self.source_line.replace("\t", " "), self.col)  # one column per character
        caret = " " * max(col - 1, 0) + "^"
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


def shown_source(line: str, col: int) -> tuple[str, int]:
    """The part of a source ``line`` shown under a problem and the caret's column in it:
    the whole line up to :data:`SOURCE_WINDOW` characters, else a window of that width
    around column ``col`` (1-based, characters) with "..." marking each cut end."""
    n = len(line)
    if n <= SOURCE_WINDOW:
        return line, col
    start = max(0, col - 1 - SOURCE_WINDOW // 2)
    end = min(n, start + SOURCE_WINDOW)
    start = max(0, end - SOURCE_WINDOW)
    head = "..." if start > 0 else ""
    tail = "..." if end < n else ""
    return head + line[start:end] + tail, col - start + len(head)


def format_problems(problems: list[Problem]) -> list[str]:
    """The formatted problems, at most :data:`MAX_SHOWN_PROBLEMS` of them, then one line
    counting the rest."""
    out = [p.format() for p in problems[:MAX_SHOWN_PROBLEMS]]
    if len(problems) > MAX_SHOWN_PROBLEMS:
        out.append(f"... and {len(problems) - MAX_SHOWN_PROBLEMS} more problem(s) not shown")
    return out


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
        return base + "\n" + "\n".join(format_problems(self.problems))
