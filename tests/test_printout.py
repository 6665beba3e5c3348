"""The print-file reader: golden files parse into the report's tables; malformed files fail clearly."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from pyadore.printout import OVERFLOW, UNKNOWN, PrintFormatError, UNKNOWN_VALUE, parse_number, read_print
from pyadore.printout.writer import format_value

ROOT = Path(__file__).resolve().parent.parent
BALL = ROOT / "golden" / "appendix_c_ball.prt"
ROLLER = ROOT / "golden" / "appendix_d_roller.prt"
DATA = Path(__file__).resolve().parent / "data" / "prints"

ELEMENT_TABLES = ("re_contact", "re_motion", "re_traction", "re_thermal")
ELEMENT_COLUMNS = {"re_contact": 11, "re_motion": 11, "re_traction": 11, "re_thermal": 11}


@pytest.fixture(scope="module")
def ball():
    return read_print(BALL)


@pytest.fixture(scope="module")
def roller():
    return read_print(ROLLER)


def test_ball_golden_has_report_steps_and_table_shapes(ball):
    assert ball.bearing_type == "BALL"
    assert ball.run_id == "Ball Bearing Test Case kGeoMod=100"
    assert ball.step_numbers == [0, 2500]
    for n in ball.step_numbers:
        step = ball.step(n)
        for name in ELEMENT_TABLES:
            assert step.table(name).shape == (18, ELEMENT_COLUMNS[name]), (n, name)
            assert list(step.table(name).index) == list(range(1, 19))
        assert step.table("re_cage").shape == (18, 9)
        assert step.table("race_cage").shape == (2, 8)
        assert list(step.table("bodies").index) == ["Cage", "ORace", "IRace"]
        assert list(step.table("loads").index) == ["Cage", "Int ORace", "Int IRace", "Ext ORace", "Ext IRace"]
        assert step.table("accelerations").shape == (3, 7)
        assert step.table("performance").shape == (1, 14)
        assert list(step.table("summary").index) == [n]
        assert not any(k.startswith("slices") for k in step.tables)


def test_roller_golden_has_report_steps_and_table_shapes(roller):
    assert roller.step_numbers == [0, 4000]
    for n in roller.step_numbers:
        step = roller.step(n)
        for name in ELEMENT_TABLES:
            assert step.table(name).shape == (8, 11), (n, name)
        assert step.table("slices_1").shape == (12, 10)
        assert list(step.table("slices_1").index) == list(range(1, 13))
        cage = step.table("re_cage")
        assert cage.shape == (16, 9)
        assert list(cage.index)[:3] == [(1, 1), (1, 2), (2, 1)]


def test_values_named_with_units(ball, roller):
    s0 = ball.step(0)
    assert s0.table("re_contact").at[2, "contact_stress_outer_Pa"] == pytest.approx(1.577e9)
    assert s0.table("re_contact").at[2, "contact_load_outer_N"] == pytest.approx(2457.0)
    assert s0.table("performance").at["bearing", "basic_fatigue_life_hours"] == pytest.approx(533.4)
    assert s0.table("loads").at["Int ORace", "force_x_N"] == pytest.approx(4495.0)
    assert s0.header == {"tau": 0.0, "time_s": 0.0, "outer_race_rot_rev": 0.0, "inner_race_rot_rev": 0.0}
    assert ball.step(2500).header["time_s"] == pytest.approx(8.612e-2)
    assert roller.step(4000).table("slices_1").at[1, "normal_load_outer_N_m"] == pytest.approx(38.79)
    assert ball.termination == {"last_step_number": 2500, "final_time": pytest.approx(353.4)}
    assert ball.statistics["total_derivative_calls"] == 21160
    assert roller.statistics["max_truncation"] == pytest.approx(9.93185e-5)


def test_echo_named_values(ball, roller):
    assert ball.echo["bearing_geometry.no_of_balls"] == 18
    assert ball.echo["bearing_geometry.ball_dia_m"] == pytest.approx(1.905e-2)
    assert ball.echo["initial_operating_conditions.gravity_vector_m_s_2[3]"] == pytest.approx(-9.81)
    assert ball.echo["lubrication_parameters.re_race1[6]"] == pytest.approx(-1.6e-2)
    assert ball.echo["lubrication_parameters.lubricant"] == "MIL-L-7808"
    assert ball.echo["initial_operating_conditions.vary_geometry_with_temperature"] == "Yes"
    assert ball.echo["initial_operating_conditions.applied_moment_vector_n_m[1]"] is UNKNOWN_VALUE
    assert roller.echo["bearing_geometry.no_of_rollers"] == 8
    assert roller.echo["initial_operating_conditions.node_at_base_temperature"] == "Housing/Outer"
    assert roller.echo["banner.bearing_type"] is UNKNOWN_VALUE


def test_unknown_markers_are_nan_and_flagged(ball):
    s0 = ball.step(0)
    assert math.isnan(s0.table("re_contact").at[1, "contact_angle_inner_deg"])
    assert s0.markers["re_contact"].at[1, "contact_angle_inner_deg"] == UNKNOWN
    assert s0.markers["re_contact"].at[2, "contact_angle_inner_deg"] == ""
    # the symmetry recovery: ball 18 equals ball 2 at step 0
    assert s0.table("re_contact").loc[18].iloc[1:].tolist() == s0.table("re_contact").loc[2].iloc[1:].tolist()


def test_listing_before_banner_run_together_and_overflow(tmp_path):
    text = BALL.read_text()
    listing = "Input from optional user subroutines\n\nListing of input data records\n\n1 0 0 0 0 1 500\n0.0000E+00-6.0000E-04\n\n"
    row = "    2  2.000E+01  8.334E+00  2.753E+01  2.457E+03  7.704E+02  1.577E+09  1.386E+09  2.367E-03  1.249E-03  3.142E-04  2.123E-04"
    assert row in text
    over = row.replace("  1.577E+09", " **********")
    # run-together: numbers written without the separating blank (a writer off by one column)
    tight = "    3" + "".join(f"{v:10.3E}" for v in (40, 7.936, 27.78, 2411, 714.2, -1.568e9, 1.352e9, 2.352e-3, 1.218e-3,
                                                    3.122e-4, 2.071e-4))
    old3 = next(line for line in text.splitlines() if line.startswith("    3  4.000E+01"))
    text = listing + text.replace(row, over, 1).replace(old3, tight, 1)
    p = tmp_path / "engine.prt"
    p.write_text(text)
    run = read_print(p)
    m = run.step(0).markers["re_contact"]
    assert m.at[2, "contact_stress_outer_Pa"] == OVERFLOW
    assert math.isnan(run.step(0).table("re_contact").at[2, "contact_stress_outer_Pa"])
    assert run.step(0).table("re_contact").at[3, "contact_stress_outer_Pa"] == pytest.approx(-1.568e9)
    assert run.step(0).table("re_contact").at[3, "minor_half_width_inner_m"] == pytest.approx(2.071e-4)


@pytest.mark.parametrize("text,value", [("1.577E+09", 1.577e9), (" -2.5D-03", -2.5e-3), ("1.000-100", 1e-100),
                                        ("1.000+100", 1e100), ("42", 42.0), ("abc", None), ("1.2.3", None)])
def test_parse_number(text, value):
    got = parse_number(text)
    assert got == (pytest.approx(value) if value is not None else None)


def test_format_value_matches_fortran_es10_3():
    assert format_value(1.577e9) == "  1.577E+09"
    assert format_value(-1.926e-2) == " -1.926E-02"
    assert format_value(1e-100) == "  1.000-100"
    assert format_value(float("nan"), UNKNOWN) == "          ?"
    assert format_value(0.0, OVERFLOW) == " **********"


@pytest.mark.parametrize("name,fragment", [
    ("no_banner.prt", "no banner line"),
    ("binary.prt", "not a text print file"),
    ("bad_step_header.prt", "line 5: expected a step number"),
])
def test_malformed_fixtures(name, fragment):
    with pytest.raises(PrintFormatError) as exc:
        read_print(DATA / name)
    assert fragment in str(exc.value)
    assert name in str(exc.value)


def test_bad_value_and_truncated_row_name_the_line(tmp_path):
    lines = BALL.read_text().splitlines()
    k = next(i for i, s in enumerate(lines) if s.startswith("    3  4.000E+01"))
    bad = list(lines)
    bad[k] = bad[k][:27] + "  x.yzE+01" + bad[k][38:]
    p = tmp_path / "bad.prt"
    p.write_text("\n".join(bad) + "\n")
    with pytest.raises(PrintFormatError, match=rf"line {k + 1}: expected 11 values"):
        read_print(p)
    short = list(lines)
    short[k] = short[k][:40]
    p.write_text("\n".join(short) + "\n")
    with pytest.raises(PrintFormatError, match=rf"bad.prt: line {k + 1}: expected 11 values"):
        read_print(p)


def test_missing_file():
    with pytest.raises(PrintFormatError, match="cannot read the print file"):
        read_print(DATA / "does_not_exist.prt")
