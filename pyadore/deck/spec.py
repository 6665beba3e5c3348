"""The types of the deck's record schema: field and record specs, presence conditions and
the fixed field widths.  The record table itself is :mod:`pyadore.deck.records` (built from
these types); :mod:`pyadore.deck.schema` answers questions about it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable, Mapping

__all__ = [
    "LABEL_WIDTH", "INT_WIDTH", "REAL_WIDTH", "TEXT_WIDTH", "FieldSpec", "RecordSpec",
    "Condition", "parse_condition", "ExpectedRecord",
]

#: Width of the optional label zone ("Rec 5B.1" padded with blanks), columns 1-12.
LABEL_WIDTH = 12
#: Width of an integer field (Fortran ``I6``, right-aligned).
INT_WIDTH = 6
#: Width of a real field (Fortran ``E11.4`` on output; any real form on input).
REAL_WIDTH = 11
#: Width of the run-id text field (``character*36 :: runId``, Appendix A).
TEXT_WIDTH = 36

_WIDTHS = {"int": INT_WIDTH, "real": REAL_WIDTH, "text": TEXT_WIDTH}


@dataclass(frozen=True)
class FieldSpec:
    """One field of a record.

    ``kind`` is ``"int"``, ``"real"`` or ``"text"``; ``unit`` uses SI (``m``, ``K``, ``s``,
    ``N``, ``rpm``, ``deg``; ``-`` for dimensionless); ``default`` is the value a blank field
    takes (``None``: the field is required).  ``lo``/``hi`` bound the value (``lo_open``/
    ``hi_open``: strict bound); ``choices`` lists the allowed integers.  ``count`` names an
    earlier integer field: the field then occurs that many times (``name[1]``, ``name[2]``...).
    ``adore`` is the ADORE variable set (Appendix A names where known); ``evidence`` says
    how the meaning is known (``echo``, ``listing``, ``table``, ``section ...``, ``unknown``).
    """

    name: str
    kind: str
    unit: str = "-"
    meaning: str = ""
    adore: str = ""
    evidence: str = "echo"
    default: object = None
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    hi_open: bool = False
    choices: tuple[int, ...] | None = None
    count: str | None = None

    @property
    def width(self) -> int:
        """Width of the field in columns."""
        return _WIDTHS[self.kind]

    @property
    def required(self) -> bool:
        """True when a blank field is an error (no default)."""
        return self.default is None

    def range_text(self) -> str:
        """Human-readable valid range, e.g. ``> 0.5`` or ``-2 ... 2`` or ``1, 2``."""
        if self.choices is not None:
            return ", ".join(str(c) for c in self.choices)
        if self.kind == "text":
            return f"at most {TEXT_WIDTH} characters"
        lo, hi = self.lo, self.hi
        if lo is None and hi is None:
            return "any"
        if hi is None:
            return f"{'>' if self.lo_open else '>='} {_num(lo)}"
        if lo is None:
            return f"{'<' if self.hi_open else '<='} {_num(hi)}"
        left = "(" if self.lo_open else "["
        right = ")" if self.hi_open else "]"
        return f"{left}{_num(lo)}, {_num(hi)}{right}"

    def in_range(self, value) -> bool:
        """True when ``value`` satisfies ``choices`` and the ``lo``/``hi`` bounds."""
        if self.choices is not None:
            return value in self.choices
        if self.lo is not None and (value <= self.lo if self.lo_open else value < self.lo):
            return False
        if self.hi is not None and (value >= self.hi if self.hi_open else value > self.hi):
            return False
        return True


def _num(x: float) -> str:
    return str(int(x)) if float(x).is_integer() and abs(x) < 1e9 else repr(x)


@dataclass(frozen=True)
class Condition:
    """A presence condition ``<field> <op> <value>`` evaluated against already-read fields."""

    field: str
    op: str
    value: int

    def holds(self, values: Mapping[str, object]) -> bool | None:
        """Evaluate against ``values`` (field name -> value); ``None`` if the field is unknown."""
        v = values.get(self.field)
        if v is None:
            return None
        return _OPERATORS[self.op](v, self.value)

    def __str__(self) -> str:
        return f"{self.field} {self.op} {self.value}"


_OPERATORS: dict[str, Callable[[int, int], bool]] = {
    "==": lambda a, b: a == b, "!=": lambda a, b: a != b, "<": lambda a, b: a < b,
    "<=": lambda a, b: a <= b, ">": lambda a, b: a > b, ">=": lambda a, b: a >= b,
}
_COND_RE = re.compile(r"^\s*([a-z][a-z0-9_]*)\s*(==|!=|<=|>=|<|>)\s*(-?\d+)\s*$")


def parse_condition(text: str) -> Condition:
    """Parse ``"bearing_type == 1"`` into a :class:`Condition` (ValueError if malformed)."""
    m = _COND_RE.match(text)
    if not m:
        raise ValueError(f"malformed record condition {text!r}")
    return Condition(m.group(1), m.group(2), int(m.group(3)))


@dataclass(frozen=True)
class RecordSpec:
    """One record type of the deck.

    ``rid`` is the record id as printed in the report (``"5A"``, ``"7.2.n"`` for a repeated
    record whose occurrences are ``7.2.1``, ``7.2.2``, ...).  ``when`` is a presence
    condition (``None``: always present); ``repeat`` names the integer field giving the
    number of occurrences.  ``section`` cites where the report defines the record.
    """

    rid: str
    title: str
    fields: tuple[FieldSpec, ...]
    when: str | None = None
    repeat: str | None = None
    section: str = ""
    notes: str = ""

    @property
    def condition(self) -> Condition | None:
        """The parsed ``when`` condition, or None."""
        return parse_condition(self.when) if self.when else None

    def occurrence_id(self, n: int) -> str:
        """Record id of occurrence ``n`` (1-based) of a repeated record (``7.2.n`` -> ``7.2.2``)."""
        return self.rid.replace(".n", f".{n}") if self.repeat else self.rid

    def expand_fields(self, values: Mapping[str, object]) -> list[tuple[str, FieldSpec]] | None:
        """Concrete (name, spec) list for this record; counted fields are expanded using
        ``values`` (earlier fields of the same record included).  None if a count is unknown."""
        out: list[tuple[str, FieldSpec]] = []
        local = dict(values)
        for spec in self.fields:
            if spec.count is None:
                out.append((spec.name, spec))
                continue
            n = local.get(spec.count)
            if not isinstance(n, int) or n < 0:
                return None
            out.extend((f"{spec.name}[{i}]", spec) for i in range(1, n + 1))
        return out


@dataclass(frozen=True)
class ExpectedRecord:
    """A record the reader expects next: its spec, concrete id and 0-based occurrence."""

    spec: RecordSpec
    rid: str
    occurrence: int
