"""The engine's print writer (fortran/output/print_*.f90) against the Python writer and the golden files.

* ``fortran/output/layout.f90`` is what ``pyadore.printout.fortran_layout`` generates
  from ``layout.py`` / ``echo_layout.py`` (one source of truth).
* The Python echo writer reproduces the golden echo blocks line for line (``?`` kept).
* Every golden step (unknown ``?`` replaced by arbitrary finite values), the end of run
  and the echo are written by the Python writer and by the Fortran writer through the f2py
  wrappers: the files are byte-identical.
* NaN (not computed) prints ``NaN``, reads back as the marker "not computed" and is a
  failure category of its own in ``pyadore diff``; values too wide print asterisks.
"""

from __future__ import annotations

import copy
import math
import random
from pathlib import Path

import pytest

from pyadore.diff import diff_prints
from pyadore.printout import echo_layout as E
from pyadore.printout import format_step, read_print
from pyadore.printout.echo_writer import echo_data_from_print, format_echo
from pyadore.printout.fortran_layout import generate
from pyadore.printout.layout import INT_NOT_COMPUTED
from pyadore.printout.model import NOT_COMPUTED, NOT_COMPUTED_VALUE, OVERFLOW, UNKNOWN, UNKNOWN_VALUE
from pyadore.printout.writer import format_int, format_value, statistics_lines, termination_line

import probes


ROOT = Path(__file__).resolve().parent.parent
BALL = ROOT / "golden" / "appendix_c_ball.prt"
ROLLER = ROOT / "golden" / "appendix_d_roller.prt"
GOLDEN = {"ball": BALL, "roller": ROLLER}
LAYOUT_F90 = ROOT / "fortran" / "output" / "layout.f90"
BANNER_LINES = 5  # written by fortran/output/banner.f90 (write_banner)


@pytest.fixture(scope="module")
def runs():
    return {k: read_print(p) for k, p in GOLDEN.items()}


def _first_step_line(lines: list[str]) -> int:
    return next(k for k, s in enumerate(lines) if s.lstrip().startswith("step") and "(ADORE 5.0)" in s)


def _random_value(rng: random.Random) -> float:
    """An arbitrary finite value over the whole double range (three-digit exponents included)."""
    return rng.choice((-1.0, 1.0)) * 10.0 ** rng.uniform(-300.0, 300.0) if rng.random() < 0.2 else \
        rng.choice((-1.0, 1.0)) * 10.0 ** rng.uniform(-12.0, 12.0)


def fill_step(step, seed: int):
    """Copy of ``step`` with every unknown ``?`` replaced by an arbitrary finite value (codes: 0..9)."""
    rng = random.Random(seed)
    s = copy.deepcopy(step)
    n = 0
    for name, marks in s.markers.items():
        if name == "header":
            for col, mark in marks.items():
                if mark == UNKNOWN:
                    s.header[col], marks[col] = _random_value(rng), ""
                    n += 1
            continue
        values = s.tables[name]
        for col in marks.columns:
            for idx in marks.index:
                if marks.at[idx, col] == UNKNOWN:
                    values.at[idx, col] = float(rng.randint(0, 9)) if col == "code" else _random_value(rng)
                    marks.at[idx, col] = ""
                    n += 1
    return s, n


def fill_echo(record: dict, seed: int) -> dict:
    """Echo record with every unknown replaced: reals arbitrary, integers 0..9, texts '?' kept as text."""
    rng = random.Random(seed)
    ints = {name for name, _ in E.INT_FIELDS}
    out = {}
    for key, v in record.items():
        def one(x, key=key):
            if x is not UNKNOWN_VALUE:
                return x
            return rng.randint(0, 9) if key in ints else _random_value(rng)
        out[key] = [one(x) for x in v] if isinstance(v, list) else one(v)
    return out


def fill_scalars(values: dict, marks: dict, seed: int) -> dict:
    rng = random.Random(seed)
    return {k: (rng.randint(1, 10**6) if k in ("last_step_number", "total_derivative_calls") else _random_value(rng))
            if marks.get(k) == UNKNOWN else v for k, v in values.items()}


def text_of(lines: list[str]) -> str:
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------- one source of truth
def test_generated_layout_table_is_current():
    """fortran/output/layout.f90 == a fresh `python -m pyadore.printout.fortran_layout`."""
    assert LAYOUT_F90.read_text() == generate(), (
        "fortran/output/layout.f90 is stale: run "
        "`python -m pyadore.printout.fortran_layout > fortran/output/layout.f90`")


def test_generated_layout_table_fits_free_form_lines():
    assert max(len(s) for s in LAYOUT_F90.read_text().splitlines()) <= 132


@pytest.mark.parametrize("kind", ["ball", "roller"])
def test_python_echo_writer_reproduces_the_golden_echo(runs, kind):
    lines = GOLDEN[kind].read_text().splitlines()
    golden_echo = lines[BANNER_LINES:_first_step_line(lines)]
    assert format_echo(echo_data_from_print(runs[kind])) == golden_echo


# -------------------------------------------------------------------- Fortran == Python
@pytest.mark.parametrize("kind,number", [("ball", 0), ("ball", 2500), ("roller", 0), ("roller", 4000)])
def test_fortran_step_is_byte_identical_to_python(runs, kind, number, tmp_path):
    step, n_filled = fill_step(runs[kind].step(number), seed=number + len(kind))
    if kind == "ball":
        assert len(step.table("re_contact")) == 18 and not any(k.startswith("slices") for k in step.tables)
    else:
        assert len(step.table("re_contact")) == 8 and len(step.table("slices_1")) == 12
        assert len(step.table("re_cage")) == 16
    assert n_filled > 0
    out = tmp_path / "step.prt"
    probes.fortran_print_step(out, step)
    assert out.read_bytes() == text_of(format_step(step)).encode("ascii")


@pytest.mark.parametrize("kind", ["ball", "roller"])
def test_fortran_end_of_run_is_byte_identical_to_python(runs, kind, tmp_path):
    run = runs[kind]
    term = fill_scalars(run.termination, run.termination_markers, 7)
    stats = fill_scalars(run.statistics, run.statistics_markers, 8)
    out = tmp_path / "end.prt"
    probes.fortran_print_end(out, term, stats, append=False)
    expected = [termination_line(term["last_step_number"], term["final_time"]), ""] + statistics_lines(stats)
    assert out.read_bytes() == text_of(expected).encode("ascii")


@pytest.mark.parametrize("kind", ["ball", "roller"])
def test_fortran_echo_is_byte_identical_to_python(runs, kind, tmp_path):
    record = fill_echo(echo_data_from_print(runs[kind]), seed=3)
    out = tmp_path / "echo.prt"
    probes.fortran_print_echo(out, record)
    banner = GOLDEN[kind].read_text().splitlines()[:BANNER_LINES]
    assert out.read_bytes() == text_of(banner + format_echo(record)).encode("ascii")


@pytest.mark.parametrize("kind", ["ball", "roller"])
def test_whole_fortran_file_equals_python_and_matches_golden(runs, kind, tmp_path):
    """Echo, every step, end of run: the Fortran file equals the Python one and diffs clean against golden."""
    run = runs[kind]
    out = tmp_path / "whole.prt"
    record = fill_echo(echo_data_from_print(run), seed=5)
    probes.fortran_print_echo(out, record)
    expected = GOLDEN[kind].read_text().splitlines()[:BANNER_LINES] + format_echo(record)
    for n in run.step_numbers:
        step, _ = fill_step(run.step(n), seed=n)
        probes.fortran_print_step(out, step, append=True)
        expected += format_step(step)
    term = fill_scalars(run.termination, run.termination_markers, 1)
    stats = fill_scalars(run.statistics, run.statistics_markers, 2)
    probes.fortran_print_end(out, term, stats)
    expected += [termination_line(term["last_step_number"], term["final_time"]), ""] + statistics_lines(stats)
    assert out.read_bytes() == text_of(expected).encode("ascii")
    report = diff_prints(out, GOLDEN[kind])
    assert report.exit_code == 0 and report.outside == 0 and report.not_computed == 0
    assert report.unknown > 0 and report.compared > 1000


# -------------------------------------------------------------- not computed and overflow
def test_nan_prints_not_computed_reads_back_and_fails_diff(runs, tmp_path):
    run = runs["ball"]
    out = tmp_path / "nan.prt"
    record = fill_echo(echo_data_from_print(run), seed=11)
    record["element_dia"] = math.nan                    # echo real not computed
    record["material"][0] = math.nan                    # density of the rolling element
    record["n_steps"] = INT_NOT_COMPUTED                # echo integer not computed
    probes.fortran_print_echo(out, record)
    banner = BALL.read_text().splitlines()[:BANNER_LINES]
    assert " BALL DIA (m)                 NaN INNER CUR FAC" in out.read_text()
    assert out.read_text() == text_of(banner + format_echo(record))

    step, _ = fill_step(run.step(0), seed=12)
    nan_cells = [("re_contact", 2, "contact_load_outer_N"), ("re_motion", 3, "orbital_velocity_rpm"),
                 ("re_cage", 4, "code"), ("race_cage", 1, "geo_int_m"), ("bodies", "Cage", "hoop_stress_Pa"),
                 ("loads", "Int ORace", "force_x_N"), ("accelerations", "IRace", "bulk_temp_K"),
                 ("performance", "bearing", "total_power_loss_W"), ("summary", 0, "power_loss_W")]
    for table, idx, col in nan_cells:
        step.tables[table].at[idx, col] = math.nan
    step.header["time_s"] = math.nan
    probes.fortran_print_step(out, step, append=True)
    stats = dict(run.statistics, max_truncation=math.nan)
    probes.fortran_print_end(out, run.termination, stats)
    text = out.read_text()
    py = text_of(banner + format_echo(record) + format_step(step)
                 + [termination_line(run.termination["last_step_number"], run.termination["final_time"]), ""]
                 + statistics_lines(stats))
    assert text == py                                   # the Python writer prints NaN the same way
    assert "     0  0.000E+00        NaN      0.000E+00" in text
    assert "    4NaN" in text                             # I3 code not computed

    back = read_print(out)
    s0 = back.step(0)
    for table, idx, col in nan_cells:
        assert s0.markers[table].at[idx, col] == NOT_COMPUTED, (table, idx, col)
        assert math.isnan(s0.tables[table].at[idx, col])
    assert s0.markers["header"]["time_s"] == NOT_COMPUTED
    assert back.statistics_markers["max_truncation"] == NOT_COMPUTED
    assert back.echo["bearing_geometry.ball_dia_m"] is NOT_COMPUTED_VALUE
    assert back.echo["material_properties.density_kg_m_3[1]"] is NOT_COMPUTED_VALUE
    assert back.echo["scale_factors_and_output_controls.no_of_steps"] is NOT_COMPUTED_VALUE

    report = diff_prints(out, BALL)
    flagged = {c.name for c in report.comparisons if c.status == "not_computed"}
    # every NaN where the golden value is known; none where golden is '?'
    gold0 = run.step(0)
    expected = {f"step 0 {t} {i} {c}" for t, i, c in nan_cells if gold0.markers[t].at[i, c] != UNKNOWN}
    expected |= {"echo bearing_geometry.ball_dia_m", "echo material_properties.density_kg_m_3[1]",
                 "statistics max_truncation"}
    assert {n for n in flagged if not n.startswith("step 0 header")} == expected
    assert any(n.startswith("step 0 header") and n.endswith("time_s") for n in flagged)
    assert report.not_computed == len(flagged) > 0
    assert report.exit_code == 1
    assert all(c.status != "not_computed" for c in report.comparisons if c.status == "unknown")
    summary = report.render("text")
    assert f"not computed by the engine {report.not_computed}" in summary
    assert "value(s) not computed by the engine" in summary.splitlines()[-1]
    assert '"not_computed": ' in report.render("json")


def test_too_wide_values_print_asterisks_like_fortran(runs, tmp_path):
    step, _ = fill_step(runs["ball"].step(0), seed=21)
    step.tables["re_cage"].at[1, "code"] = 1000.0                       # I3
    step.tables["race_cage"].at[2, "code"] = -100.0                     # I3
    step.tables["re_contact"].at[3, "contact_load_outer_N"] = math.inf  # 'Infinity' in ES10.3
    step.tables["re_contact"].at[4, "contact_load_outer_N"] = -math.inf
    out = tmp_path / "over.prt"
    probes.fortran_print_step(out, step)
    probes.fortran_print_end(out, {"last_step_number": 123456789, "final_time": -353.4},
                            {"minimum_step_size": 5e-3, "total_derivative_calls": 21160})
    text = out.read_text()
    expected = format_step(step) + [termination_line(123456789, -353.4), ""]
    assert text.startswith(text_of(expected))
    assert "    1***" in text and "    2***" in text
    assert "  Infinity" in text and " -Infinity" in text
    assert "Last Step Number =********     Final Time = **********" in text  # I8 and ES10.4 overflow
    # the Python field rules are the Fortran ones
    assert format_int(1000, width=3) == "***" and format_int(INT_NOT_COMPUTED, width=3) == "NaN"
    assert format_value(-353.4, width=10, decimals=4) == " **********"
    assert format_value(math.nan) == "        NaN" and format_value(math.nan, NOT_COMPUTED) == "        NaN"
    assert format_value(-math.inf) == "  -Infinity"
    # overflow reads back as overflow, not as not-computed or unknown
    back = read_print_partial(out)
    assert back.step(0).markers["re_cage"].at[1, "code"] == OVERFLOW
    assert back.step(0).markers["re_contact"].at[3, "contact_load_outer_N"] == OVERFLOW
    assert back.step(0).tables["re_contact"].at[4, "contact_load_outer_N"] == -math.inf


def read_print_partial(path: Path):
    """read_print of a file holding only steps: prepend a banner line."""
    p = path.with_suffix(".full.prt")
    p.write_text("ADVANCED DYNAMICS OF ROLLING ELEMENTS\n" + path.read_text().split("     Normal termination")[0])
    return read_print(p)
