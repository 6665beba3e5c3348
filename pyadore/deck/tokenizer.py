"""Fixed-field tokenising of deck lines, as a Fortran formatted READ would see them.

A line is cut into its optional label zone and fixed-width fields (widths from
:mod:`.schema`); every field keeps its 1-based column.  Numbers are converted the way
Fortran input editing does, with a few deliberate refusals where Fortran would silently
read something the author almost certainly did not mean:

* fields are fixed, so run-together numbers (``0.0000E+00-6.0000E-04``) split correctly;
* ``D`` exponents (``1.0D-05``) and a sign-started exponent (``1.0-05``) are accepted;
* a blank field takes the schema default (Fortran reads a blank numeric field as 0);
* refused: a real without a decimal point (Fortran ``E11.4`` would read ``12345`` as
  1.2345), a field holding two numbers separated by blanks (Fortran's blank-ignoring
  would read ``1 0`` as 10; this is what a free-format line looks like), tabs.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .schema import LABEL_WIDTH, FieldSpec

__all__ = ["Token", "split_label", "cut_fields", "parse_value", "LABEL_PREFIX"]

#: A labelled line starts with this text (case-insensitive) in column 1.
LABEL_PREFIX = "rec "

_INT_RE = re.compile(r"^[+-]?[0-9]+$")
# mantissa with a decimal point, optional exponent: E/D letter with optional sign, or a bare sign
_REAL_RE = re.compile(r"^[+-]?([0-9]+\.[0-9]*|\.[0-9]+)(?:[EeDd][+-]?[0-9]+|[+-][0-9]+)?$")
_REAL_NO_POINT_RE = re.compile(r"^[+-]?[0-9]+(?:[EeDd][+-]?[0-9]+)?$")


@dataclass(frozen=True)
class Token:
    """The raw text of one field and where it sits: 1-based ``col`` of its first column."""

    text: str
    col: int
    width: int


def split_label(line: str) -> tuple[str | None, int, str | None]:
    """Split off the optional ``Rec <id>`` label.

    Returns ``(label_id, data_offset, error)``: ``label_id`` is None for an unlabelled line,
    ``data_offset`` is the 0-based index where the data fields start (0 or
    :data:`~pyadore.deck.schema.LABEL_WIDTH`), ``error`` describes stray text in the label zone.
    """
    if line[:len(LABEL_PREFIX)].lower() != LABEL_PREFIX:
        return None, 0, None
    zone = line[:LABEL_WIDTH]
    parts = zone[len(LABEL_PREFIX):].split()
    if not parts:
        return "", LABEL_WIDTH, "label 'Rec' without a record id"
    error = None
    if len(parts) > 1:
        error = (f"text {' '.join(parts[1:])!r} inside the label zone (columns 1-{LABEL_WIDTH}); "
                 f"data fields start in column {LABEL_WIDTH + 1}")
    return parts[0], LABEL_WIDTH, error


def cut_fields(line: str, offset: int, specs: list[tuple[str, FieldSpec]]) -> tuple[list[Token], Token | None]:
    """Cut ``line`` into fixed fields starting at 0-based ``offset``.

    Returns one :class:`Token` per spec (text beyond the end of the line is blank, as a
    Fortran READ pads short records) and a Token for any non-blank text after the last
    field (None if there is none).
    """
    tokens: list[Token] = []
    pos = offset
    for _, spec in specs:
        w = spec.width
        tokens.append(Token(line[pos:pos + w], pos + 1, w))
        pos += w
    rest = line[pos:]
    extra = None
    if rest.strip():
        lead = len(rest) - len(rest.lstrip())
        extra = Token(rest.strip(), pos + lead + 1, len(rest.strip()))
    return tokens, extra


def parse_value(spec: FieldSpec, text: str) -> tuple[object, bool, str | None]:
    """Convert field text to a value of ``spec.kind``.

    Returns ``(value, blank, error)``: ``blank`` is True for an all-blank field (the value is
    then the schema default, or None with an error if the field is required); ``error`` is a
    message of the form "expected ..." when the text is not a valid value.
    """
    if spec.kind == "text":
        return text.rstrip(), text.strip() == "", None
    s = text.strip()
    if not s:
        if spec.default is None:
            return None, True, "expected a value (the field is required and has no default)"
        return spec.default, True, None
    if "\t" in text:
        return None, False, "expected no tab characters (fields are fixed columns)"
    if re.search(r"\s", s):
        return None, False, (f"expected one number in the {spec.width}-column field, found blanks inside "
                             "(free-format spacing? Fortran would ignore the blanks)")
    if spec.kind == "int":
        if _INT_RE.match(s):
            return int(s), False, None
        return None, False, f"expected an integer (I{spec.width}, right-aligned)"
    # real
    if _REAL_RE.match(s):
        m = s.replace("D", "E").replace("d", "E")
        if "E" not in m and "e" not in m:
            # sign-started exponent "1.0-05": split at the last sign after the mantissa
            k = max(m.rfind("+"), m.rfind("-"))
            if k > 0:
                m = m[:k] + "E" + m[k:]
        try:
            v = float(m)
        except ValueError:  # pragma: no cover - the regex admits only float syntax
            return None, False, "expected a real number"
        if v != v or v in (float("inf"), float("-inf")):
            return None, False, "expected a finite real number"
        return v, False, None
    if _REAL_NO_POINT_RE.match(s):
        return None, False, (f"expected a real with a decimal point (Fortran E{spec.width}.4 would read "
                             f"{s!r} with an implied decimal point)")
    return None, False, f"expected a real number (E{spec.width}.4)"
