"""Generate ``fortran/output/layout.f90``: the print layout as Fortran parameter data.

One source of truth: :mod:`.layout` (step tables, step header, section 3, termination,
statistics) and :mod:`.echo_layout` (echo blocks and the echo record's fields) are what
the Python reader and writer use; this module turns them into the Fortran module
``adore_output_layout`` that the engine's print writer (``fortran/output/print_tables.f90``,
``print_echo.f90``) uses.  The generated file is kept in the tree (meson does not run
Python for it); ``tests/test_print_writer.py`` fails when it differs from a fresh
generation.

Usage: ``python -m pyadore.printout.fortran_layout > fortran/output/layout.f90``
"""

from __future__ import annotations

import sys

from . import echo_layout as E
from . import layout as L

_MAX = 100  # longest source line the generator writes (gfortran's free-form limit is 132)

LABEL_KINDS = {"int": 1, "step": 2, "text": 3, "re_end": 4}
#: Fortran id of each step table (the two RE/cage variants have their own id).
TABLE_IDS = (
    ("TABLE_RE_CONTACT", L.RE_CONTACT), ("TABLE_RE_MOTION", L.RE_MOTION), ("TABLE_RE_TRACTION", L.RE_TRACTION),
    ("TABLE_RE_THERMAL", L.RE_THERMAL), ("TABLE_SLICES", L.SLICES), ("TABLE_RE_CAGE", L.RE_CAGE),
    ("TABLE_RE_CAGE_ROLLER", L.RE_CAGE_ROLLER), ("TABLE_RACE_CAGE", L.RACE_CAGE), ("TABLE_BODIES", L.BODIES),
    ("TABLE_LOADS", L.LOADS), ("TABLE_ACCELERATIONS", L.ACCELERATIONS), ("TABLE_SUMMARY", L.SUMMARY),
)


def _lit(text: str, indent: int) -> str:
    """A Fortran string literal, split into ``// &`` continued pieces when long."""
    assert text.isascii(), text
    pieces, step = [], 60
    for k in range(0, max(len(text), 1), step):
        pieces.append('"' + text[k:k + step].replace('"', '""') + '"')
    return (" // &\n" + " " * indent).join(pieces)


class _Module:
    def __init__(self) -> None:
        self.names: list[str] = []
        self.body: list[str] = []

    def comment(self, text: str) -> None:
        self.body.append("")
        for line in text.splitlines():
            self.body.append(f"   !> {line}".rstrip())

    def int(self, name: str, value: int) -> None:
        self.names.append(name)
        self.body.append(f"   integer, parameter :: {name} = {value}")

    def ints(self, name: str, values) -> None:
        self.names.append(name)
        values = list(values)
        head = f"   integer, parameter :: {name}({len(values)}) = ["
        lines, cur = [], head
        for k, v in enumerate(values):
            item = str(v) + (", " if k < len(values) - 1 else "]")
            if len(cur) + len(item) > _MAX:
                lines.append(cur.rstrip() + " &")
                cur = " " * 6
            cur += item
        lines.append(cur)
        self.body.extend(lines)

    def str(self, name: str, text: str) -> None:
        self.names.append(name)
        head = f"   character(len=*), parameter :: {name} = "
        if len(head) + len(text) + 2 <= _MAX:
            self.body.append(head + _lit(text, 6))
        else:
            self.body.append(head + "&\n" + " " * 6 + _lit(text, 6))

    def strs(self, name: str, texts, length: int | None = None) -> None:
        """A character array parameter; every element padded to ``length`` (default: the longest)."""
        texts = list(texts)
        n = length if length is not None else max(1, max(len(t) for t in texts))
        assert all(len(t) <= n for t in texts), (name, n)
        self.names.append(name)
        out = [f"   character(len={n}), parameter :: {name}({len(texts)}) = [character(len={n}) :: &"]
        for k, t in enumerate(texts):
            out.append(" " * 6 + _lit(t, 6) + (", &" if k < len(texts) - 1 else "]"))
        self.body.extend(out)

    def render(self) -> str:
        head = [
            "!> GENERATED FILE - do not edit.  Source: pyadore/printout/layout.py and echo_layout.py;",
            "!> regenerate with `python -m pyadore.printout.fortran_layout > fortran/output/layout.f90`.",
            "!> tests/test_print_writer.py fails when this file differs from a fresh generation.",
            "!>",
            "!> The ADORE 5.0 print layout (docs/print-layout.md) as parameter data for the engine's",
            "!> print writer (fortran/output/print_tables.f90, print_echo.f90, echo_data.f90).",
            "module adore_output_layout",
            "   implicit none",
            "   private",
            "",
        ]
        names = sorted(set(self.names), key=self.names.index)
        pub, cur = [], "   public :: "
        for k, n in enumerate(names):
            item = n + (", " if k < len(names) - 1 else "")
            if len(cur) + len(item) > _MAX:
                pub.append(cur.rstrip() + " &")
                cur = " " * 6
            cur += item
        pub.append(cur)
        return "\n".join(head + pub + self.body + ["", "end module adore_output_layout", ""])


def generate() -> str:
    """The text of ``fortran/output/layout.f90``."""
    m = _Module()
    m.comment("General rules: line width, table value width (1X,ES10.3), the integer 'not computed' value.")
    m.int("LINE_WIDTH", L.LINE_WIDTH)
    m.int("VALUE_WIDTH", L.VALUE_WIDTH)
    m.int("INT_NOT_COMPUTED", L.INT_NOT_COMPUTED)
    m.str("NOT_COMPUTED_TOKEN", L.NOT_COMPUTED_TOKEN)

    m.comment("Step header block (I6,2(1X,ES10.3),2(5X,ES10.3),2X,A) between these lines; section titles.")
    m.str("STEP_HEADING", L.STEP_HEADING)
    m.str("STEP_UNITS", L.STEP_UNITS)
    m.str("STEP_RULE", L.STEP_RULE)
    for key, name in (("1", "SECTION_TITLE_1"), ("1a", "SECTION_TITLE_1A"), ("2", "SECTION_TITLE_2"),
                      ("3", "SECTION_TITLE_3"), ("4", "SECTION_TITLE_4")):
        m.str(name, L.SECTION_TITLES[key])

    m.comment("Step tables: id, name, value columns, I3 code columns, row-label kind and width,\n"
              "and the range of their heading lines in HEADING_LINE.")
    for k, (name, _) in enumerate(TABLE_IDS, 1):
        m.int(name, k)
    m.int("N_TABLES", len(TABLE_IDS))
    for kind, code in LABEL_KINDS.items():
        m.int(f"LABEL_{kind.upper()}", code)
    specs = [s for _, s in TABLE_IDS]
    m.strs("TABLE_NAME", [s.name for s in specs])
    m.ints("TABLE_NCOL", [len(s.columns) for s in specs])
    m.ints("TABLE_NCODE", [len(s.codes) for s in specs])
    m.ints("TABLE_LABEL_KIND", [LABEL_KINDS[s.label] for s in specs])
    m.ints("TABLE_LABEL_WIDTH", [s.label_width for s in specs])
    first, count, lines = [], [], []
    for s in specs:
        first.append(len(lines) + 1)
        count.append(len(s.headings))
        lines += list(s.headings)
    m.ints("TABLE_HEAD_FIRST", first)
    m.ints("TABLE_HEAD_COUNT", count)
    m.int("N_HEADING_LINES", len(lines))
    m.strs("HEADING_LINE", lines)

    m.comment("Row labels of the text-labelled tables.")
    m.strs("BODY_ROW", L.BODY_ROWS, L.BODIES.label_width)
    m.strs("LOAD_ROW", L.LOAD_ROWS, L.LOADS.label_width)
    m.strs("ACC_ROW", L.ACC_ROWS, L.ACCELERATIONS.label_width)

    m.comment("Section 3: the right-hand cells (T<col>,A30,1X,ES10.3).  RIGHT_LABEL is indexed like the\n"
              "performance vector; *_RIGHT_LINE is the 1-based line of the block (headings, then rows)\n"
              "that carries performance value *_RIGHT_CELL.")
    perf = list(L.PERFORMANCE_COLUMNS)
    m.int("N_PERFORMANCE", len(perf))
    m.strs("RIGHT_LABEL", [L.RIGHT_LABELS[c] for c in perf], 30)
    m.int("LOADS_RIGHT_COL", L.RIGHT3 + 1)
    m.int("ACC_RIGHT_COL", L.RIGHT3_ACC + 1)
    for prefix, spec in (("LOADS", L.LOADS), ("ACC", L.ACCELERATIONS)):
        m.ints(f"{prefix}_RIGHT_LINE", [k + 1 for k in spec.right_cells])
        m.ints(f"{prefix}_RIGHT_CELL", [perf.index(c) + 1 for c in spec.right_cells.values()])

    m.comment("End of run: (5X,A,I8,5X,A,1X,ES10.4); statistics (5X,A22,' =',1X,ES12.5) / (5X,A22,' =',I13).")
    m.str("TERMINATION_STEP_TEXT", L.TERMINATION_STEP_TEXT)
    m.str("TERMINATION_TIME_TEXT", L.TERMINATION_TIME_TEXT)
    m.str("STATISTICS_TITLE", L.STATISTICS_TITLE)
    m.strs("STATISTICS_LABEL", list(L.STATISTICS_LABELS), 22)

    m.comment("Echo record (echo_data_t): sizes, and the 1-based offsets of every field in the flat\n"
              "text / integer / real vectors of the f2py wrapper (order of echo_layout.py).")
    m.int("ECHO_TEXT_LEN", E.TEXT_LEN)
    m.int("ECHO_MAX_GUIDE", E.MAX_GUIDE)
    m.int("ECHO_MAX_QS", E.MAX_QS)
    m.int("ELEMENT_BALL", E.ELEMENT_BALL)
    m.int("ELEMENT_ROLLER", E.ELEMENT_ROLLER)
    for k, name in enumerate(E.TEXT_FIELDS, 1):
        m.int(f"ET_{name.upper()}", k)
    m.int("N_ECHO_TEXT", len(E.TEXT_FIELDS))
    off = 1
    for name, n in E.INT_FIELDS:
        m.int(f"EI_{name.upper()}", off)
        off += n
    m.int("N_ECHO_INT", off - 1)
    off = 1
    for name, shape in E.REAL_FIELDS:
        m.int(f"ER_{name.upper()}", off)
        off += E.size_of(shape)
    m.int("N_ECHO_REAL", off - 1)

    m.comment("Echo: banner box, block titles, item grids (labels row by row; blank = empty cell).")
    m.str("ECHO_COPYRIGHT", E.COPYRIGHT)
    m.str("ECHO_BOX_RULE", E.BOX_RULE)
    m.str("ECHO_BOX_TYPE_TEXT", E.BOX_TYPE_TEXT)
    m.str("ECHO_BOX_MODE_TEXT", E.BOX_MODE_TEXT)
    m.str("ECHO_BOX_RUN_TEXT", E.BOX_RUN_TEXT)
    m.strs("ECHO_BLOCK_TITLE", E.BLOCK_TITLES)
    m.int("ECHO_ITEM_WIDTH", E.ITEM_WIDTH)

    def grid_labels(rows):
        return [c[0] if c else "" for row in rows for c in row]

    m.strs("ECHO_GEOM_BALL_LABEL", grid_labels(E.GEOM_BALL), E.ITEM_WIDTH)
    m.strs("ECHO_GEOM_ROLLER_LABEL", grid_labels(E.GEOM_ROLLER), E.ITEM_WIDTH)
    m.strs("ECHO_CAGE_LABEL", grid_labels(E.CAGE_ITEMS), E.ITEM_WIDTH)
    m.strs("ECHO_GUIDE_HEAD", E.GUIDE_HEAD)

    m.comment("Echo: matrices (1X,A<w>,n(1X,ES12.5)) with their heading lines; the label arrays have\n"
              "the print width as their length.")
    m.str("ECHO_MAT_HEAD", E.MAT_HEAD)
    m.strs("ECHO_MAT_LABEL", E.MAT_LABELS, E.MAT_WIDTH)
    m.ints("ECHO_MAT_COUNT", E.MAT_COUNTS)
    m.strs("ECHO_BODY_LABEL", E.BODY_LABELS, E.BODY_WIDTH)
    m.strs("ECHO_INERTIA_HEAD", E.INERTIA_HEAD)
    m.strs("ECHO_PRINCIPAL_HEAD", E.PRINCIPAL_HEAD)
    m.strs("ECHO_LUB_HEAD", E.LUB_HEAD)
    m.strs("ECHO_LUB_LABEL", E.LUB_LABELS, E.BODY_WIDTH)
    m.strs("ECHO_LUBRICANT_LABEL", [E.LUBRICANT_LABEL], E.LUBRICANT_WIDTH)
    m.strs("ECHO_FAT_HEAD", E.FAT_HEAD)
    m.strs("ECHO_RACE_LABEL", E.RACE_LABELS, E.BODY_WIDTH)
    m.strs("ECHO_FAT_TEXT_LABEL", E.FAT_TEXT_LABELS, E.FAT_TEXT_WIDTH)
    m.strs("ECHO_ASP_HEAD", E.ASP_HEAD)

    m.comment("Echo: initial operating conditions.")
    m.str("ECHO_OPER_RACE_HEAD", E.OPER_RACE_HEAD)
    m.strs("ECHO_OPER_LEFT_LABEL", [lab for lab, _ in E.OPER_LEFT], E.OPER_WIDTH)
    m.strs("ECHO_OPER_RIGHT_LABEL", [lab for lab, _ in E.OPER_RIGHT], E.OPER_RIGHT_WIDTH)
    m.strs("ECHO_LOAD_FRACTION_LABEL", [E.LOAD_FRACTION_LABEL], E.OPER_WIDTH)
    m.strs("ECHO_HTC_LABEL", [E.HTC_LABEL], E.OPER_WIDTH)
    m.strs("ECHO_FLAGS_LABEL", [E.QS_LABEL, E.TRANS_LABEL, E.ROT_LABEL], E.FLAGS_WIDTH)
    m.strs("ECHO_OPER_TEXT_LABEL", [E.COOLANT_LABEL, E.NODE_LABEL, E.VARY_LABEL], E.OPER_TEXT_WIDTH)
    m.str("ECHO_VECTOR_HEAD", E.VECTOR_HEAD)
    m.strs("ECHO_VECTOR_LABEL", [lab for lab, _ in E.VECTORS], E.VECTOR_WIDTH)

    m.comment("Echo: scale factors and output controls.")
    m.str("ECHO_SCALE_HEAD", E.SCALE_HEAD)
    m.strs("ECHO_SCALE_LABEL", [lab for lab, _ in E.SCALE_LABELS], E.SCALE_WIDTH)
    m.strs("ECHO_STEP_LABEL", [lab for lab, _ in E.STEP_LABELS], E.SCALE_WIDTH)
    m.strs("ECHO_CONTROL_LABEL", [E.DATA_CONTROL_LABEL, E.AUTO_PLOTS_LABEL], E.CONTROL_WIDTH)
    m.strs("ECHO_SCALE_RIGHT_LABEL", [E.NO_OF_STEPS_LABEL, E.INT_METHOD_LABEL], E.SCALE_RIGHT_WIDTH)
    m.strs("ECHO_ERROR_LIMIT_LABEL", [E.ERROR_LIMIT_LABEL], E.ERROR_LIMIT_WIDTH)
    return m.render()


def main() -> int:
    sys.stdout.write(generate())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
