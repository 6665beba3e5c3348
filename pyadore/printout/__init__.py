"""Reading (and writing) ADORE 5.0 print files in the fixed layout of docs/print-layout.md.

``read_print(path)`` parses golden files and engine output alike; ``format_step`` and
friends format tables in the same layout, ``?`` markers included, which the engine's writer
never writes (used to build the golden files and in tests; print files come from the
engine).
"""

from .model import (NOT_COMPUTED, NOT_COMPUTED_VALUE, OVERFLOW, OVERFLOW_VALUE, UNKNOWN, UNKNOWN_VALUE,
                    PrintFormatError, PrintRun, Step, parse_field, parse_number)
from .reader import read_print
from .writer import format_step, format_table, format_value

__all__ = [
    "read_print", "PrintRun", "Step", "PrintFormatError", "UNKNOWN", "OVERFLOW", "UNKNOWN_VALUE",
    "OVERFLOW_VALUE", "NOT_COMPUTED", "NOT_COMPUTED_VALUE", "parse_field", "parse_number", "format_step",
    "format_table", "format_value",
]
