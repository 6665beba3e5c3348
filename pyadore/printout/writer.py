"""Formatting of step tables in the fixed ADORE 5.0 layout (docs/print-layout.md).

The writer is the executable form of the layout: the golden files' steps were built with it
(golden/transcription/assemble.py: it writes the unknown marker ``?``, which the engine's
writer never does) and the tests use it to make perturbed or malformed copies and as the
reference of the engine's writer.  It formats only; it computes nothing.
"""

from __future__ import annotations

import math

import pandas as pd

from . import layout as L
from .model import NOT_COMPUTED, OVERFLOW, UNKNOWN, Step


def format_value(value: float, marker: str = "", width: int = 10, decimals: int = 3) -> str:
    """One field ``1X,ESw.d`` (``width + 1`` characters) as gfortran writes it.

    Unknown prints ``?`` right-aligned; overflow, or a value too wide for the field, prints
    ``*`` (Fortran's overflow).  NaN - a value the engine does not compute, or the marker
    NOT_COMPUTED - prints ``NaN`` right-aligned, +-inf ``Infinity`` / ``-Infinity``, as
    gfortran does.  Exponents beyond two digits drop the ``E`` (``1.000-100``).
    """
    if marker == UNKNOWN:
        return " " + L.UNKNOWN_TOKEN.rjust(width)
    if marker == OVERFLOW:
        return " " + "*" * width
    if marker == NOT_COMPUTED or value is None or (isinstance(value, float) and math.isnan(value)):
        text = L.NOT_COMPUTED_TOKEN
    elif math.isinf(value):
        text = "Infinity" if width >= 9 or (value > 0 and width >= 8) else "Inf"
        text = ("-" + text) if value < 0 else text
    else:
        text = f"{value:.{decimals}E}"
        mant, exp = text.split("E")
        if abs(int(exp)) >= 100:
            text = mant + exp
    if len(text) > width:
        return " " + "*" * width
    return " " + text.rjust(width)


def format_int(value, marker: str = "", width: int = 3) -> str:
    """One integer field ``Iw`` as Fortran writes it: ``*`` when too wide, ``?`` unknown,
    ``NaN`` when not computed (NaN, the marker NOT_COMPUTED or :data:`layout.INT_NOT_COMPUTED`)."""
    if marker == UNKNOWN:
        return L.UNKNOWN_TOKEN.rjust(width)
    if marker == OVERFLOW:
        return "*" * width
    if (marker == NOT_COMPUTED or value is None or (isinstance(value, float) and math.isnan(value))
            or int(value) == L.INT_NOT_COMPUTED):
        text = L.NOT_COMPUTED_TOKEN
    else:
        text = str(int(value))
    return "*" * width if len(text) > width else text.rjust(width)


def format_label(spec: L.TableSpec, label) -> str:
    """The row label of ``spec`` (``I5``/``I6``, ``A5``/``A10`` or ``I5,I3`` for roller ends)."""
    if spec.label == "re_end":
        re_no, end = label
        return format_int(re_no, width=5) + format_int(end, width=3)
    if spec.label == "text":
        return f"{label:<{spec.label_width}}"[: spec.label_width]
    return format_int(label, width=spec.label_width)


def format_row(spec: L.TableSpec, label, values: list, markers: list) -> str:
    """One data row: label, integer code columns (I3), value columns (1X,ES10.3)."""
    out = format_label(spec, label)
    ncode = len(spec.codes)
    for v, m in zip(values[:ncode], markers[:ncode]):
        out += format_int(v, m, 3)
    for v, m in zip(values[ncode:], markers[ncode:]):
        out += format_value(v, m)
    return out.rstrip()


def format_table(spec: L.TableSpec, values: pd.DataFrame, markers: pd.DataFrame | None = None) -> list[str]:
    """Heading lines and rows of one table (no section 3 right-hand cells)."""
    lines = list(spec.headings)
    for i, label in enumerate(values.index):
        vals = list(values.iloc[i])
        marks = list(markers.iloc[i]) if markers is not None else [""] * len(vals)
        lines.append(format_row(spec, label, vals, marks))
    return lines


def header_block(number: int, header: dict, run_id: str, marks: dict | None = None) -> list[str]:
    """The four-line step header: headings, units, values ``(I6,2(1X,ES10.3),2(5X,ES10.3),2X,A)``, rule."""
    marks = marks or {}
    vals = [format_value(header[c], marks.get(c, "")) for c in L.HEADER_COLUMNS]
    line = format_int(number, width=6) + vals[0] + vals[1] + "    " + vals[2] + "    " + vals[3] + "  " + run_id
    return [L.STEP_HEADING, L.STEP_UNITS, line.rstrip(), L.STEP_RULE, ""]


def _right(line: str, start: int, name: str, perf: pd.DataFrame, pmarks: pd.DataFrame | None) -> str:
    mark = pmarks.iloc[0][name] if pmarks is not None else ""
    cell = L.RIGHT_LABELS[name].ljust(30) + format_value(perf.iloc[0][name], mark)
    return line.ljust(start) + "  " + cell if start == 0 else line.ljust(start) + cell


def section3_lines(step: Step) -> list[str]:
    """Section 3: force/moment rows and acceleration rows with the labelled cells on the right."""
    perf, pmarks = step.tables["performance"], step.markers.get("performance")
    out = []
    for spec, start in ((L.LOADS, L.RIGHT3), (L.ACCELERATIONS, L.RIGHT3_ACC)):
        block = format_table(spec, step.tables[spec.name], step.markers.get(spec.name))
        for k, line in enumerate(block):
            if k in spec.right_cells:
                line = _right(line, start, spec.right_cells[k], perf, pmarks)
            out.append(line.rstrip())
        out.append("")
    return out


def format_step(step: Step) -> list[str]:
    """Every line of one printed step: sections 1, 1a (rollers), 2, 3 and 4, each with its header."""
    out = header_block(step.number, step.header, step.run_id, step.markers.get("header"))
    out += [L.SECTION_TITLES["1"], ""]
    for spec in L.SECTION_TABLES["1"]:
        out += format_table(spec, step.tables[spec.name], step.markers.get(spec.name)) + [""]
    for name in sorted((n for n in step.tables if n.startswith("slices_")), key=lambda n: int(n.split("_")[1])):
        out += header_block(step.number, step.header, step.run_id, step.markers.get("header"))
        out += [f"{L.SECTION_TITLES['1a']} {name.split('_')[1]}", ""]
        out += format_table(L.SLICES, step.tables[name], step.markers.get(name)) + [""]
    out += header_block(step.number, step.header, step.run_id, step.markers.get("header"))
    out += [L.SECTION_TITLES["2"], ""]
    cage = step.tables["re_cage"]
    spec = L.RE_CAGE_ROLLER if isinstance(cage.index, pd.MultiIndex) else L.RE_CAGE
    out += format_table(spec, cage, step.markers.get("re_cage")) + [""]
    for spec in (L.RACE_CAGE, L.BODIES):
        out += format_table(spec, step.tables[spec.name], step.markers.get(spec.name)) + [""]
    out += header_block(step.number, step.header, step.run_id, step.markers.get("header"))
    out += [L.SECTION_TITLES["3"], ""]
    out += section3_lines(step)
    out += [L.SECTION_TITLES["4"], ""]
    out += format_table(L.SUMMARY, step.tables["summary"], step.markers.get("summary")) + [""]
    return out


def termination_line(last_step: int, final_time: float, marks: dict | None = None) -> str:
    """``(5X,'Normal termination: Last Step Number =',I8,5X,'Final Time =',1X,ES10.4)``."""
    marks = marks or {}
    ft = format_value(final_time, marks.get("final_time", ""), width=10, decimals=4)
    return "     " + L.TERMINATION_STEP_TEXT + format_int(last_step, width=8) + "     " + L.TERMINATION_TIME_TEXT + ft


def statistics_lines(stats: dict, marks: dict | None = None) -> list[str]:
    """``Statistics of this Run`` and one ``(5X,A22,' =',1X,ES12.5)`` / ``(5X,A22,' =',I13)`` line each."""
    marks = marks or {}
    out = [L.STATISTICS_TITLE, ""]
    for label, name in L.STATISTICS_LABELS.items():
        if name not in stats and name not in marks:
            continue
        mark = marks.get(name, "")
        if name == "total_derivative_calls":
            val = format_int(stats.get(name), mark, 13)
        else:
            val = format_value(stats.get(name, float("nan")), mark, width=12, decimals=5)
        out.append(f"     {label:<22} ={val}")
    return out
