"""The differ, its CLI body and the pytest helper."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pyadore.diff import diff_command, diff_prints
from pyadore.printout import PrintFormatError
from pyadore.testing import assert_matches_golden

ROOT = Path(__file__).resolve().parent.parent
BALL = ROOT / "golden" / "appendix_c_ball.prt"
ROLLER = ROOT / "golden" / "appendix_d_roller.prt"
TOL = ROOT / "golden" / "tolerances.toml"
DATA = Path(__file__).resolve().parent / "data" / "prints"
ROW3 = "    3  4.000E+01  7.936E+00  2.778E+01  2.411E+03  7.142E+02  1.568E+09"


def perturbed(tmp_path, factor: float, golden: Path = BALL, prefix: str = ROW3, col: int = 3) -> Path:
    """Copy of ``golden`` with one value (column ``col`` of the row starting ``prefix``) times ``factor``."""
    lines = golden.read_text().splitlines()
    k = next(i for i, s in enumerate(lines) if s.startswith(prefix))
    start = 5 + 11 * col
    value = float(lines[k][start:start + 11]) * factor
    lines[k] = lines[k][:start] + f" {value:10.3E}" + lines[k][start + 11:]
    p = tmp_path / "run.prt"
    p.write_text("\n".join(lines) + "\n")
    return p


@pytest.mark.parametrize("golden", [BALL, ROLLER])
def test_self_diff_is_clean(golden):
    report = diff_prints(golden, golden)
    assert report.exit_code == 0
    assert report.outside == 0 and report.missing == 0
    assert report.compared > 1000
    assert report.within == report.compared


def test_unknown_markers_are_skipped_and_counted(tmp_path):
    report = diff_prints(BALL, BALL)
    unknown = [c for c in report.comparisons if c.status == "unknown"]
    assert report.unknown == len(unknown) > 0
    assert any(c.name == "step 0 re_contact 1 contact_angle_inner_deg" for c in unknown)
    text = report.render("text")
    assert f"unknown {report.unknown}" in text
    # an unknown golden value stays unknown whatever the run prints there
    lines = BALL.read_text().splitlines()
    k = next(i for i, s in enumerate(lines) if s.startswith("    1  0.000E+00  8.472E+00"))
    lines[k] = lines[k][:27] + "  9.999E+09" + lines[k][38:]
    p = tmp_path / "run.prt"
    p.write_text("\n".join(lines) + "\n")
    again = diff_prints(p, BALL)
    assert again.exit_code == 0 and again.unknown == report.unknown


def test_two_percent_perturbation_is_flagged_with_its_name(tmp_path):
    run = perturbed(tmp_path, 1.02)  # contact load outer of ball 3 at step 0 (1 % tolerance)
    report = diff_prints(run, BALL)
    assert report.exit_code == 1
    assert report.outside == 1
    worst = report.offenders()[0]
    assert worst.name == "step 0 re_contact 3 contact_load_outer_N"
    assert worst.golden == pytest.approx(2411.0) and worst.run == pytest.approx(2459.0)
    assert worst.rel_error == pytest.approx(0.02, rel=0.01)
    text = report.render("text")
    assert "step 0 re_contact 3 contact_load_outer_N" in text and "outside 1" in text
    data = json.loads(report.render("json"))
    assert data["exit_code"] == 1 and data["outside"] == 1
    assert data["offenders"][0]["name"] == worst.name
    assert data["column_max_rel_error"]["re_contact.contact_load_outer_N"] == pytest.approx(0.02, rel=0.01)


def test_half_percent_perturbation_is_within_one_percent(tmp_path):
    report = diff_prints(perturbed(tmp_path, 1.005), BALL)
    assert report.exit_code == 0 and report.outside == 0


def test_tolerance_file_override(tmp_path):
    run = perturbed(tmp_path, 1.02)
    loose = tmp_path / "loose.toml"
    loose.write_text(TOL.read_text() + '\n[[rule]]\nstep = "initial"\ntable = "re_contact"\n'
                     'columns = ["contact_load_outer_N"]\nrel = 0.03\n')
    assert diff_prints(run, BALL, loose).exit_code == 0
    strict = tmp_path / "strict.toml"
    strict.write_text('[defaults]\nrel = 0.0\n')
    report = diff_prints(BALL, BALL, strict)
    assert report.exit_code == 0  # identical values pass even at zero tolerance
    assert diff_prints(perturbed(tmp_path, 1.005), BALL, strict).exit_code == 1


def test_tolerances_next_to_golden_are_the_default(tmp_path):
    golden = tmp_path / "golden.prt"
    golden.write_text(BALL.read_text())
    (tmp_path / "tolerances.toml").write_text('[defaults]\nrel = 0.5\n')
    run = perturbed(tmp_path, 1.2)
    report = diff_prints(run, golden)
    assert report.tolerances_path == str(tmp_path / "tolerances.toml")
    assert report.exit_code == 0


def test_missing_step_counts_as_outside(tmp_path):
    text = BALL.read_text()
    cut = text.index("  step        tau       Time Outer Race Rot Inner Race Rot  (ADORE 5.0)\n    no"
                     "                   (s)          (rev)          (rev)\n  2500")
    p = tmp_path / "short.prt"
    p.write_text(text[:cut])
    report = diff_prints(p, BALL)
    assert report.exit_code == 1 and report.missing > 0


def test_echo_exact_to_printed_precision(tmp_path):
    text = BALL.read_text().replace(" BALL DIA (m)         1.90500E-02", " BALL DIA (m)         1.90501E-02")
    p = tmp_path / "run.prt"
    p.write_text(text)
    report = diff_prints(p, BALL)
    assert report.exit_code == 1
    assert report.offenders()[0].name == "echo bearing_geometry.ball_dia_m"


@pytest.mark.parametrize("name", ["no_banner.prt", "binary.prt", "bad_step_header.prt", "does_not_exist.prt"])
def test_malformed_input_exit_2_with_message(name, capsys):
    assert diff_command(DATA / name, BALL, None, "text") == 2
    err = capsys.readouterr().err
    assert err.startswith("pyadore: error:") and name in err and "Traceback" not in err
    assert diff_command(BALL, DATA / name, None, "json") == 2


def test_malformed_tolerance_file_exit_2(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[[rule]]\nstep = 'sometimes'\nrel = 0.1\n")
    assert diff_command(BALL, BALL, bad, "text") == 2
    assert "bad.toml" in capsys.readouterr().err
    with pytest.raises(PrintFormatError):
        diff_prints(BALL, BALL, tmp_path / "none.toml")


def test_diff_command_exit_codes(tmp_path, capsys):
    assert diff_command(BALL, BALL, None, "json") == 0
    assert json.loads(capsys.readouterr().out)["exit_code"] == 0
    assert diff_command(perturbed(tmp_path, 1.02), BALL, None, "text") == 1
    assert "contact_load_outer_N" in capsys.readouterr().out


def test_assert_matches_golden(tmp_path):
    assert_matches_golden(BALL, BALL)
    assert_matches_golden(ROLLER, ROLLER, sections=["slices_1"])
    run = perturbed(tmp_path, 1.02)
    with pytest.raises(AssertionError, match="step 0 re_contact 3 contact_load_outer_N"):
        assert_matches_golden(run, BALL)
    assert_matches_golden(run, BALL, sections=["re_thermal", "echo"])
    with pytest.raises(AssertionError, match="no value compared"):
        assert_matches_golden(BALL, BALL, sections=["no_such_table"])
