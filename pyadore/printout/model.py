"""Data model of a parsed print file and the parsing of single fields.

A :class:`PrintRun` holds the banner facts, the input echo as named values, every
printed step (:class:`Step`) with its tables as pandas DataFrames, the termination line
and the run statistics.  Table values are floats in the units named by the column suffix
(``_N``, ``_m``, ``_deg`` ...); a field that is unknown (golden ``?``), overflowed
(Fortran ``****`` or ``Infinity``) or not computed by the engine (Fortran ``NaN``) is NaN
(``+-inf`` for ``Infinity``) in the values frame and flagged in the parallel marker frame.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pandas is imported where frames are built (reader), not to read a print plainly
    import pandas as pd

from ..errors import AdoreInputError

#: Marker codes used in :attr:`Step.markers` (``""`` = an ordinary printed value).
UNKNOWN = "unknown"
OVERFLOW = "overflow"
#: The engine printed ``NaN``: a value it does not compute (yet).  Not unknown (that is a
#: golden-file marker) and not overflow; ``pyadore diff`` counts it as a failure of its own.
NOT_COMPUTED = "not_computed"


class PrintFormatError(AdoreInputError):
    """A print file is missing, unreadable or does not follow docs/print-layout.md."""


class _Marker:
    """A non-numeric echo value: :data:`UNKNOWN_VALUE`, :data:`OVERFLOW_VALUE` or :data:`NOT_COMPUTED_VALUE`."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __repr__(self) -> str:
        return self.name.upper()


UNKNOWN_VALUE = _Marker(UNKNOWN)
OVERFLOW_VALUE = _Marker(OVERFLOW)
NOT_COMPUTED_VALUE = _Marker(NOT_COMPUTED)

#: How a Fortran numeric write prints NaN (right-aligned in the field) and infinities.
NAN_TOKEN = "NaN"
_INFINITY = re.compile(r"^[-+]?(?:Infinity|Inf)$")

_FLOAT = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+|[-+]\d{2,3})?$")
_INT = re.compile(r"^[-+]?\d+$")
#: One numeric token, also when several are run together (``1.0E+00-2.0E-01``).
NUMBER_TOKEN = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+)(?:[EeDd][-+]?\d+|[-+]\d{3})|[-+]?\d+|\?|\*+|NaN|[-+]?Infinity")


def parse_number(text: str) -> float | None:
    """Parse one Fortran real or integer (``1.234E+05``, ``1.234D+05``, ``1.234-100``); None if not a number."""
    t = text.strip()
    if not _FLOAT.match(t):
        return None
    t = t.replace("D", "E").replace("d", "E")
    if "E" not in t and "e" not in t:
        m = re.match(r"^([-+]?[\d.]+)([-+]\d{2,3})$", t)
        if m:
            t = m.group(1) + "E" + m.group(2)
    return float(t)


def parse_field(text: str) -> tuple[float, str] | None:
    """Parse one table field: (value, marker) with marker "", UNKNOWN, OVERFLOW or NOT_COMPUTED; None if invalid.

    ``NaN`` (what a Fortran write prints for IEEE NaN) is NOT_COMPUTED; ``Infinity`` /
    ``-Infinity`` (``Inf`` in narrow fields) is OVERFLOW with the value +-inf.
    """
    t = text.strip()
    if t == "?":
        return float("nan"), UNKNOWN
    if t and set(t) == {"*"}:
        return float("nan"), OVERFLOW
    if t == NAN_TOKEN:
        return float("nan"), NOT_COMPUTED
    if _INFINITY.match(t):
        return (-math.inf if t.startswith("-") else math.inf), OVERFLOW
    v = parse_number(t)
    if v is None:
        return None
    return v, ""


def parse_echo_token(text: str):
    """Parse one echo value token: int, float, UNKNOWN_VALUE, OVERFLOW_VALUE or NOT_COMPUTED_VALUE.

    None if the token is not a value.
    """
    t = text.strip()
    if t == "?":
        return UNKNOWN_VALUE
    if (t and set(t) == {"*"}) or _INFINITY.match(t):
        return OVERFLOW_VALUE
    if t == NAN_TOKEN:
        return NOT_COMPUTED_VALUE
    if _INT.match(t):
        return int(t)
    return parse_number(t)


@dataclass
class Step:
    """One printed step: header values and its tables.

    ``header`` holds tau (dimensionless), time (s) and the race rotations (rev).
    ``tables`` maps a table name (``re_contact``, ``re_motion``, ``re_traction``,
    ``re_thermal``, ``slices_<roller>``, ``re_cage``, ``race_cage``, ``bodies``, ``loads``,
    ``accelerations``, ``performance``, ``summary``) to a float DataFrame; ``markers`` has
    the same shape with "" / "unknown" / "overflow" / "not_computed" per cell.
    """

    number: int
    header: dict = field(default_factory=dict)
    run_id: str = ""
    tables: dict = field(default_factory=dict)
    markers: dict = field(default_factory=dict)

    def table(self, name: str) -> "pd.DataFrame":
        """The DataFrame of table ``name`` (KeyError naming the available tables if absent)."""
        try:
            return self.tables[name]
        except KeyError:
            raise KeyError(f"step {self.number} has no table {name!r}; it has {sorted(self.tables)}") from None


@dataclass
class PrintRun:
    """A whole print file: banner facts, echo, steps (by step number), termination, statistics.

    ``echo`` maps ``block.label`` names (snake_case, units as suffix, ``[i]`` for the i-th
    of several values on one label) to int, float, str, UNKNOWN_VALUE, OVERFLOW_VALUE or
    NOT_COMPUTED_VALUE.
    ``termination`` has ``last_step_number`` and ``final_time`` (dimensionless tau);
    ``statistics`` has the step sizes and truncation (dimensionless) and the derivative calls;
    ``termination_markers`` / ``statistics_markers`` flag unknown, overflowed or not computed entries.
    ``incomplete`` says why a print is incomplete ("" when it is not).
    """

    path: str
    bearing_type: str = ""
    program_mode: int | None = None
    run_id: str = ""
    echo: dict = field(default_factory=dict)
    steps: dict = field(default_factory=dict)
    termination: dict = field(default_factory=dict)
    statistics: dict = field(default_factory=dict)
    termination_markers: dict = field(default_factory=dict)
    statistics_markers: dict = field(default_factory=dict)
    #: "" for a complete print; else why it is incomplete: the text of its last line
    #: ``*** RUN INCOMPLETE ...`` (a time integration that stopped early), or a note that a
    #: print announcing time steps has no termination line
    incomplete: str = ""

    @property
    def step_numbers(self) -> list[int]:
        """Printed step numbers in ascending order."""
        return sorted(self.steps)

    def step(self, number: int) -> Step:
        """The step printed with ``number`` (KeyError naming the printed steps if absent)."""
        try:
            return self.steps[number]
        except KeyError:
            raise KeyError(f"{self.path}: no step {number}; printed steps are {self.step_numbers}") from None


class PlainTable:
    """A print table without pandas (``read_print(path, frames=False)``): rows by label.
    ``t.loc[row, column]`` a value (KeyError for an unknown row, ValueError for an unknown
    column), ``t.loc[[row, ...]]`` those rows, ``t[column]`` the column's values in row
    order, ``t.index`` the row labels, ``t.columns`` the column names."""

    def __init__(self, rows: list, index: list, columns: list, index_name: str | None = None) -> None:
        self.index = list(index)
        self.columns = list(columns)
        self.index_name = index_name
        self._rows = dict(zip(self.index, rows))

    class _Loc:
        def __init__(self, table: "PlainTable") -> None:
            self.t = table

        def __getitem__(self, key):
            t = self.t
            if isinstance(key, list):
                return PlainTable([t._rows[k] for k in key], key, t.columns, t.index_name)
            row, column = key
            return t._rows[row][t.columns.index(column)]

    @property
    def loc(self) -> "PlainTable._Loc":
        return PlainTable._Loc(self)

    def __getitem__(self, column: str) -> list:
        j = self.columns.index(column)
        return [self._rows[k][j] for k in self.index]

    def __len__(self) -> int:
        return len(self.index)
