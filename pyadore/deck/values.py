"""The values read from a deck: :class:`FieldValue` (one field: value, spec, where it was
read) and :class:`Record` (one record: concrete id, occurrence, fields, source line)."""

from __future__ import annotations

from dataclasses import dataclass, field

from .spec import FieldSpec, RecordSpec

__all__ = ["FieldValue", "Record"]


@dataclass
class FieldValue:
    """One field of a record: value (``int``/``float``/``str``, None if unreadable), its
    spec, whether it was blank in the file, and its 1-based line and column (0 if built in memory)."""

    name: str
    spec: FieldSpec
    value: object
    blank: bool = False
    line: int = 0
    col: int = 0
    raw: str = ""

    @property
    def unit(self) -> str:
        """Unit of the value (SI; ``-`` for dimensionless)."""
        return self.spec.unit


@dataclass
class Record:
    """One record of a deck: concrete id, occurrence index (0-based among records of the
    same spec), fields in order, and the source line it was read from."""

    rid: str
    spec: RecordSpec
    fields: dict[str, FieldValue]
    occurrence: int = 0
    line: int = 0
    labelled: bool = True
    source: str | None = None
    _read_values: tuple | None = field(default=None, repr=False, compare=False)

    def __getitem__(self, name: str) -> object:
        return self.fields[name].value

    def values(self) -> dict[str, object]:
        """Field name -> value, in order."""
        return {n: f.value for n, f in self.fields.items()}

    def unchanged(self) -> bool:
        """True when the values still equal those read from ``source`` (write it verbatim)."""
        return self.source is not None and self._read_values == tuple(self.values().items())

    def mark_read(self) -> None:
        """Remember the current values as the values read from ``source``."""
        self._read_values = tuple(self.values().items())
