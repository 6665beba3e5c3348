"""Reading (and writing) ADORE 5.0 print files in the fixed layout of docs/print-layout.md.

``read_print(path)`` parses golden files and engine output alike; ``format_step`` and
friends format tables in the same layout, ``?`` markers included, which the engine's writer
never writes (used to build the golden files and in tests; print files come from the
engine).
"""

from .model import (NOT_COMPUTED, NOT_COMPUTED_VALUE, OVERFLOW, OVERFLOW_VALUE, UNKNOWN, UNKNOWN_VALUE,
                    PrintFormatError, PrintRun, Step, parse_field, parse_number)
from .reader import read_print

_WRITER = ("format_step", "format_table", "format_value")


def __getattr__(name: str):
    """The writer's functions, imported on first use (the writer needs pandas; reading a
    print plainly does not: a sweep worker starts without it)."""
    if name in _WRITER:
        from . import writer

        return getattr(writer, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = [
    "read_print", "PrintRun", "Step", "PrintFormatError", "UNKNOWN", "OVERFLOW", "UNKNOWN_VALUE",
    "OVERFLOW_VALUE", "NOT_COMPUTED", "NOT_COMPUTED_VALUE", "parse_field", "parse_number", "format_step",
    "format_table", "format_value",
]
