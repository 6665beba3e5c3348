"""The input echo in the ADORE 5.0 layout: Python reference of the engine's echo writer.

:func:`format_echo` formats an echo record - a dict holding every field of
:mod:`.echo_layout` (the fields of the engine's ``echo_data_t``) - into the lines from
the copyright line of the banner to the blank line before the first step, exactly as the
golden files show them and as ``fortran/output/print_echo.f90`` writes them.  It formats
only.  :func:`echo_data_from_print` fills such a record from a parsed print file (the
golden files), :func:`pack_echo` flattens it for the f2py wrapper.

Values: reals are floats (NaN: not computed, printed ``NaN``) or the markers
UNKNOWN_VALUE / OVERFLOW_VALUE / NOT_COMPUTED_VALUE; integers are ints (or those
markers; :data:`layout.INT_NOT_COMPUTED` prints ``NaN``); texts are strings.
"""

from __future__ import annotations

import math
import re

from . import echo_layout as E
from .echo import slug
from .model import (NOT_COMPUTED, NOT_COMPUTED_VALUE, OVERFLOW, OVERFLOW_VALUE, UNKNOWN, UNKNOWN_VALUE,
                    PrintRun)
from .writer import format_int, format_value

_REF = re.compile(r"^(i:)?(\w+)(?:\[(\d+)\])?$")
_MARK = {id(UNKNOWN_VALUE): UNKNOWN, id(OVERFLOW_VALUE): OVERFLOW, id(NOT_COMPUTED_VALUE): NOT_COMPUTED}


def empty_echo_data() -> dict:
    """An echo record with every field present: reals NaN (not computed), integers 0, texts blank."""
    d: dict = {name: "" for name in E.TEXT_FIELDS}
    for name, n in E.INT_FIELDS:
        d[name] = 0 if n == 1 else [0] * n
    for name, shape in E.REAL_FIELDS:
        d[name] = math.nan if not shape else [math.nan] * E.size_of(shape)
    return d


def _get(d: dict, ref: str):
    m = _REF.match(ref)
    value = d[m.group(2)]
    return value[int(m.group(3)) - 1] if m.group(3) else value


def _real(v, width: int = 12) -> str:
    """``ESw.5`` without the leading blank (the cell's label precedes it directly)."""
    mark = _MARK.get(id(v), "")
    return format_value(math.nan if mark else float(v), mark, width=width, decimals=5)[1:]


def _int(v, width: int) -> str:
    mark = _MARK.get(id(v), "")
    return format_int(None if mark else v, mark, width)


def _text(v) -> str:
    if v is UNKNOWN_VALUE:
        return "?"
    return str(v).rstrip()


def _label(label: str, width: int) -> str:
    return f"{label:<{width}}"[:width]


def _cell(d: dict, label: str, ref: str, width: int) -> str:
    """Item cell ``(1X,A<w>,ES12.5)`` or ``(1X,A<w>,I12)``."""
    value = _get(d, ref)
    return " " + _label(label, width) + (_int(value, 12) if ref.startswith("i:") else _real(value))


def _grid(d: dict, rows, width: int = E.ITEM_WIDTH) -> list[str]:
    out = []
    for row in rows:
        line = ""
        for cell in row:
            line += " " * (1 + width + 12) if cell is None else _cell(d, cell[0], cell[1], width)
        out.append(line.rstrip())
    return out


def _matrix_line(label: str, values, width: int) -> str:
    """``(1X,A<w>,n(1X,ES12.5))``."""
    return (" " + _label(label, width) + "".join(" " + _real(v) for v in values)).rstrip()


def _rows(d: dict, field: str, labels, per_row: int, width: int, counts=None) -> list[str]:
    flat = d[field]
    out = []
    for k, label in enumerate(labels):
        n = counts[k] if counts else per_row
        out.append(_matrix_line(label, flat[k * per_row:k * per_row + n], width))
    return out


def _ints_line(label: str, width: int, values, iwidth: int) -> str:
    return (" " + _label(label, width) + "".join(_int(v, iwidth) for v in values)).rstrip()


def _text_line(label: str, width: int, value) -> str:
    return (" " + _label(label, width) + _text(value)).rstrip()


def _title(t: str) -> list[str]:
    return [t, "-" * len(t), ""]


def banner_box(d: dict) -> list[str]:
    """Copyright line and the starred box
    ``('*  Bearing Type = ',A12,'Program Mode = ',I1,5X,'Run Id = ',A,T120,'*')``."""
    box = (E.BOX_TYPE_TEXT + _label(_text(d["bearing_type"]), 12) + E.BOX_MODE_TEXT + _int(d["program_mode"], 1)
           + " " * 5 + E.BOX_RUN_TEXT + _text(d["run_id"]))
    box = box.ljust(119)[:119] + "*"
    return [E.COPYRIGHT, "", E.BOX_RULE, box, E.BOX_RULE, ""]


def format_echo(d: dict) -> list[str]:
    """The banner box and the seven echo blocks of echo record ``d``, line for line."""
    out = banner_box(d)
    roller = d["element_kind"] == E.ELEMENT_ROLLER
    # -- bearing geometry
    out += _title(E.BLOCK_TITLES[0])
    out += _grid(d, E.GEOM_ROLLER if roller else E.GEOM_BALL) + [""]
    out += _grid(d, E.CAGE_ITEMS) + [""]
    out += list(E.GUIDE_HEAD)
    for k in range(int(d["n_guide"])):
        out.append((_int(d["guide_land"][k], 9) + _int(d["guide_type"][k], 9)
                    + "".join(" " + _real(v) for v in d["guide"][4 * k:4 * k + 4])).rstrip())
    out.append("")
    # -- material properties
    out += _title(E.BLOCK_TITLES[1])
    out += [E.MAT_HEAD] + _rows(d, "material", E.MAT_LABELS, 6, E.MAT_WIDTH, E.MAT_COUNTS) + [""]
    # -- inertial parameters
    out += _title(E.BLOCK_TITLES[2])
    out += list(E.INERTIA_HEAD) + _rows(d, "inertia", E.BODY_LABELS, 7, E.BODY_WIDTH) + [""]
    out += list(E.PRINCIPAL_HEAD) + _rows(d, "principal", E.BODY_LABELS, 3, E.BODY_WIDTH) + [""]
    # -- lubrication parameters
    out += _title(E.BLOCK_TITLES[3])
    out += list(E.LUB_HEAD) + _rows(d, "lubrication", E.LUB_LABELS, 9, E.BODY_WIDTH) + [""]
    if _text(d["lubricant"]):
        out += [_text_line(E.LUBRICANT_LABEL, E.LUBRICANT_WIDTH, d["lubricant"]), ""]
    # -- fatigue parameters
    out += _title(E.BLOCK_TITLES[4])
    out += list(E.FAT_HEAD) + _rows(d, "fatigue", E.RACE_LABELS, 5, E.BODY_WIDTH) + [""]
    out += [_text_line(E.FAT_TEXT_LABELS[0], E.FAT_TEXT_WIDTH, d["weibull_slope"]),
            _text_line(E.FAT_TEXT_LABELS[1], E.FAT_TEXT_WIDTH, d["life_mod_code"]), ""]
    out += list(E.ASP_HEAD) + _rows(d, "asperity", E.RACE_LABELS, 8, E.BODY_WIDTH) + [""]
    # -- initial operating conditions
    out += _title(E.BLOCK_TITLES[5])
    out += [(" " + _text(d["title"])).rstrip(), "", E.OPER_RACE_HEAD]
    for k, (label, ref) in enumerate(E.OPER_LEFT):
        line = _cell(d, label, ref, E.OPER_WIDTH)
        if k < len(E.OPER_RIGHT):
            rlabel, rref = E.OPER_RIGHT[k]
            line += _cell(d, rlabel, rref + "[1]", E.OPER_RIGHT_WIDTH) + " " + _real(_get(d, rref + "[2]"))
        out.append(line.rstrip())
    out.append("")
    out.append(_ints_line(E.QS_LABEL, E.FLAGS_WIDTH, d["qs_constraints"][:int(d["n_qs"])], 3))
    out.append(_cell(d, E.LOAD_FRACTION_LABEL, "load_fraction", E.OPER_WIDTH).rstrip())
    out.append(_ints_line(E.TRANS_LABEL, E.FLAGS_WIDTH, d["trans_constraints"], 3))
    out.append(_ints_line(E.ROT_LABEL, E.FLAGS_WIDTH, d["rot_constraints"], 3))
    out.append(_text_line(E.COOLANT_LABEL, E.OPER_TEXT_WIDTH, d["coolant_type"]))
    if _text(d["node_base_temp"]):
        out.append(_text_line(E.NODE_LABEL, E.OPER_TEXT_WIDTH, d["node_base_temp"]))
    out.append(_text_line(E.VARY_LABEL, E.OPER_TEXT_WIDTH, d["vary_geometry"]))
    if d["print_htc"]:
        out.append(_cell(d, E.HTC_LABEL, "heat_trans_coeff", E.OPER_WIDTH).rstrip())
    out += ["", E.VECTOR_HEAD]
    for label, field in E.VECTORS:
        v = d[field]
        out.append(_matrix_line(label, v if isinstance(v, list) else [v], E.VECTOR_WIDTH))
    out.append("")
    # -- scale factors and output controls
    out += _title(E.BLOCK_TITLES[6])
    out.append(E.SCALE_HEAD)
    for k in range(3):
        line = (_cell(d, *E.SCALE_LABELS[k], E.SCALE_WIDTH) + _cell(d, *E.STEP_LABELS[k], E.SCALE_WIDTH))
        if k == 0:
            line += _cell(d, E.NO_OF_STEPS_LABEL, "i:n_steps", E.SCALE_RIGHT_WIDTH)
        else:
            label, field = ((E.DATA_CONTROL_LABEL, "data_control") if k == 1 else (E.AUTO_PLOTS_LABEL, "auto_plots"))
            line += _ints_line(label, E.CONTROL_WIDTH, d[field], 6)
        out.append(line.rstrip())
    out.append((_cell(d, E.ERROR_LIMIT_LABEL, "error_limit", E.ERROR_LIMIT_WIDTH)
                + _cell(d, E.INT_METHOD_LABEL, "i:int_method", E.SCALE_RIGHT_WIDTH)).rstrip())
    out.append("")
    return out


# ------------------------------------------------------------------ record from a print file
def _set(d: dict, ref: str, value) -> None:
    m = _REF.match(ref)
    name = m.group(2)
    if m.group(3):
        d[name][int(m.group(3)) - 1] = value
    else:
        d[name] = value


def _as_text(v) -> str:
    return "?" if v is UNKNOWN_VALUE else ("" if v is None else str(v))


def echo_data_from_print(run: PrintRun) -> dict:
    """The echo record of a parsed print file (golden or engine output), for the writers.

    Every echo value the file prints is placed in its field (markers kept); fields the
    file does not print stay as :func:`empty_echo_data` has them.  The run title of the
    operating-conditions block is taken from the banner's run id (the reader does not
    name it).
    """
    echo = run.echo
    d = empty_echo_data()
    roller = "bearing_geometry.no_of_rollers" in echo
    d["element_kind"] = E.ELEMENT_ROLLER if roller else E.ELEMENT_BALL
    d["bearing_type"] = _as_text(echo.get("banner.bearing_type", run.bearing_type))
    d["program_mode"] = echo.get("banner.program_mode", run.program_mode or 0)
    d["run_id"] = d["title"] = run.run_id

    def take(name: str, ref: str) -> None:
        if name in echo:
            _set(d, ref, echo[name])

    for rows, block in (((E.GEOM_ROLLER if roller else E.GEOM_BALL), "bearing_geometry"),
                        (E.CAGE_ITEMS, "bearing_geometry")):
        for row in rows:
            for cell in row:
                if cell is not None:
                    take(f"{block}.{slug(cell[0])}", cell[1].removeprefix("i:"))
    k = 0
    while f"bearing_geometry.row{k + 1}[1]" in echo:
        row = [echo[f"bearing_geometry.row{k + 1}[{j}]"] for j in range(1, 7)]
        d["guide_land"][k], d["guide_type"][k] = row[0], row[1]
        d["guide"][4 * k:4 * k + 4] = row[2:]
        k += 1
    d["n_guide"] = k

    def matrix(block: str, labels, field: str, per_row: int, suffix: str = "") -> None:
        for r, label in enumerate(labels):
            for j in range(per_row):
                name = f"{block}.{slug(label)}{suffix}[{j + 1}]"
                if name in echo:
                    d[field][r * per_row + j] = echo[name]

    matrix("material_properties", E.MAT_LABELS, "material", 6)
    matrix("inertial_parameters", E.BODY_LABELS, "inertia", 7)
    matrix("inertial_parameters", E.BODY_LABELS, "principal", 3, "#2")
    matrix("lubrication_parameters", E.LUB_LABELS, "lubrication", 9)
    d["lubricant"] = _as_text(echo.get("lubrication_parameters.lubricant"))
    matrix("fatigue_parameters", E.RACE_LABELS, "fatigue", 5)
    matrix("fatigue_parameters", E.RACE_LABELS, "asperity", 8, "#2")
    d["weibull_slope"] = _as_text(echo.get("fatigue_parameters." + slug(E.FAT_TEXT_LABELS[0])))
    d["life_mod_code"] = _as_text(echo.get("fatigue_parameters." + slug(E.FAT_TEXT_LABELS[1])))
    op = "initial_operating_conditions."
    for label, ref in E.OPER_LEFT:
        take(op + slug(label), ref)
    for label, field in E.OPER_RIGHT:
        for j in (1, 2):
            take(f"{op}{slug(label)}[{j}]", f"{field}[{j}]")
    n = 0
    while f"{op}{slug(E.QS_LABEL)}[{n + 1}]" in echo:
        d["qs_constraints"][n] = echo[f"{op}{slug(E.QS_LABEL)}[{n + 1}]"]
        n += 1
    d["n_qs"] = n
    take(op + slug(E.LOAD_FRACTION_LABEL), "load_fraction")
    for label, field in ((E.TRANS_LABEL, "trans_constraints"), (E.ROT_LABEL, "rot_constraints")):
        for j in range(6):
            take(f"{op}{slug(label)}[{j + 1}]", f"{field}[{j + 1}]")
    d["coolant_type"] = _as_text(echo.get(op + slug(E.COOLANT_LABEL)))
    d["node_base_temp"] = _as_text(echo.get(op + slug(E.NODE_LABEL)))
    d["vary_geometry"] = _as_text(echo.get(op + slug(E.VARY_LABEL)))
    d["print_htc"] = int(op + slug(E.HTC_LABEL) in echo)
    take(op + slug(E.HTC_LABEL), "heat_trans_coeff")
    for label, field in E.VECTORS:
        if isinstance(d[field], list):
            for j in range(3):
                take(f"{op}{slug(label)}[{j + 1}]", f"{field}[{j + 1}]")
        else:
            take(op + slug(label), field)
    sc = "scale_factors_and_output_controls."
    for label, field in E.SCALE_LABELS + E.STEP_LABELS:
        take(sc + slug(label), field)
    take(sc + slug(E.NO_OF_STEPS_LABEL), "n_steps")
    take(sc + slug(E.ERROR_LIMIT_LABEL), "error_limit")
    take(sc + slug(E.INT_METHOD_LABEL), "int_method")
    for label, field in ((E.DATA_CONTROL_LABEL, "data_control"), (E.AUTO_PLOTS_LABEL, "auto_plots")):
        for j in range(3):
            take(f"{sc}{slug(label)}[{j + 1}]", f"{field}[{j + 1}]")
    return d


# --------------------------------------------------------------------------- f2py packing
def pack_echo(d: dict) -> tuple[list[str], list[int], list[float]]:
    """Flatten an echo record into (texts, integers, reals) in the field order of
    :mod:`.echo_layout` (the offsets of ``fortran/output/layout.f90``).

    Markers cannot cross the boundary: the caller replaces them first (a NOT_COMPUTED
    real may be passed as NaN).  Raises ValueError for a marker.
    """
    def scalar(v, kind):
        if isinstance(v, type(UNKNOWN_VALUE)):
            if v is NOT_COMPUTED_VALUE:
                return math.nan if kind is float else None
            raise ValueError(f"echo record holds {v!r}: replace unknown/overflow values before packing")
        return kind(v)

    texts = [_text(d[name]) for name in E.TEXT_FIELDS]
    ints: list[int] = []
    for name, n in E.INT_FIELDS:
        vals = [d[name]] if n == 1 else list(d[name])
        ints += [scalar(v, int) for v in vals]
    reals: list[float] = []
    for name, shape in E.REAL_FIELDS:
        vals = [d[name]] if not shape else list(d[name])
        reals += [scalar(v, float) for v in vals]
    return texts, ints, reals
