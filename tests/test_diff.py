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


def _tolerances(tmp_path, extra: str) -> Path:
    """The repository's tolerance file with ``extra`` rules appended (the last rule wins)."""
    p = tmp_path / "tolerances.toml"
    p.write_text(TOL.read_text() + "\n" + extra)
    return p


def _rotated_section1(tmp_path) -> Path:
    """Appendix C's golden print with the rows of step 0's first table (section 1) moved one
    element on: element k prints what element k + 1 printed (18 -> 1), its orbital position
    included - the same physical state with the balls numbered differently."""
    lines = BALL.read_text().splitlines()
    first = next(i for i, s in enumerate(lines) if s.startswith("    1  0.000E+00  8.472E+00"))
    rows = lines[first:first + 18]
    assert all(r[:5].strip() == str(k + 1) for k, r in enumerate(rows))
    for k in range(18):
        lines[first + k] = f"{k + 1:5d}" + rows[(k + 1) % 18][5:]
    p = tmp_path / "rotated.prt"
    p.write_text("\n".join(lines) + "\n")
    return p


def test_azimuth_matching_compares_elements_at_the_same_orbital_position(tmp_path):
    run = _rotated_section1(tmp_path)
    by_index = diff_prints(run, BALL)
    assert by_index.exit_code == 1
    assert any(c.table == "re_contact" and c.status == "outside" for c in by_index.comparisons)
    tol = _tolerances(tmp_path, '[[rule]]\nstep = "initial"\ntable = "re_contact"\ncolumns = ["*"]\n'
                                'rel = 0.01\nmatch = "azimuth"\n')
    by_azimuth = diff_prints(run, BALL, tol)
    contact = [c for c in by_azimuth.comparisons if c.table == "re_contact"]
    assert contact and all(c.status in ("within", "unknown") for c in contact)
    assert sum(c.status == "within" for c in contact) > 150
    assert all(c.rel_error == 0.0 for c in contact if c.status == "within")
    assert by_azimuth.exit_code == 0
    assert any(c.name.endswith("(at its azimuth)") for c in contact)


def test_azimuth_matching_interpolates_between_elements():
    from pyadore.diff import _interpolate_periodic
    pts = [(10.0, 1.0, ""), (100.0, 10.0, ""), (350.0, 3.0, "")]
    assert _interpolate_periodic(pts, 55.0) == (5.5, "")
    assert _interpolate_periodic(pts, 100.0) == (10.0, "")
    v, m = _interpolate_periodic(pts, 0.0)            # across 360 -> 0: between 350 and 370
    assert m == "" and v == pytest.approx(3.0 + (1.0 - 3.0) * 0.5)
    v, m = _interpolate_periodic([(0.0, 1.0, ""), (180.0, 2.0, "NaN")], 90.0)
    assert m == "NaN"
    # angles the short way round: 359 deg and 1 deg halfway give 0 (mod 360), not 180
    v, m = _interpolate_periodic([(0.0, 359.0, ""), (20.0, 1.0, "")], 10.0, angular=True)
    assert v % 360.0 == pytest.approx(0.0, abs=1e-12)


def test_angles_compare_modulo_360(tmp_path):
    from pyadore.diff import _Rule, _compare_value
    rule = _Rule("any", "*", ("*",), 0.01, None)
    assert _compare_value("x", "re_motion", "ang_vel_phi_deg", 360.0, "", 1.0e-4, "", rule, 360.0).status == "within"
    assert _compare_value("x", "re_motion", "ang_vel_phi_deg", 90.0, "", 120.0, "", rule, 360.0).status == "outside"
    # not an angle: no wrapping
    assert _compare_value("x", "re_contact", "contact_load_outer_N", 360.0, "", 0.0, "", rule, 360.0).status == \
        "outside"


def test_known_deviation_is_reported_with_its_reason_and_does_not_fail(tmp_path):
    run = perturbed(tmp_path, 1.02)  # outer contact load of ball 3 at step 0, 2 % off
    tol = _tolerances(tmp_path, '[[rule]]\nstep = "initial"\ntable = "re_contact"\n'
                                'columns = ["contact_load_outer_N"]\nrel = 0.01\n'
                                'deviation = "test reason: documented in docs/x.md"\n')
    report = diff_prints(run, BALL, tol)
    assert report.exit_code == 0 and report.outside == 0
    assert report.deviations == 1
    (c,) = [c for c in report.comparisons if c.status == "deviation"]
    assert c.name == "step 0 re_contact 3 contact_load_outer_N" and c.reason.startswith("test reason")
    text = report.render("text")
    assert "known deviations 1" in text and "test reason: documented in docs/x.md" in text
    data = json.loads(report.render("json"))
    assert data["deviations"] == 1
    assert data["deviation_columns"]["re_contact.contact_load_outer_N"]["count"] == 1
    # within tolerance, a deviation rule changes nothing
    assert diff_prints(perturbed(tmp_path, 1.005), BALL, tol).deviations == 0
    # beyond deviation_max the value fails as usual
    capped = _tolerances(tmp_path, '[[rule]]\nstep = "initial"\ntable = "re_contact"\n'
                                   'columns = ["contact_load_outer_N"]\nrel = 0.01\n'
                                   'deviation = "test reason"\ndeviation_max = 0.015\n')
    over = diff_prints(perturbed(tmp_path, 1.02), BALL, capped)
    assert over.exit_code == 1 and over.deviations == 0 and over.outside == 1


@pytest.mark.parametrize("extra", ['match = "nearest"', "deviation = 3", "deviation_max = 0.1"])
def test_bad_match_or_deviation_is_a_clear_error(tmp_path, extra):
    tol = _tolerances(tmp_path, f'[[rule]]\nstep = "final"\ntable = "*"\ncolumns = ["*"]\nrel = 0.1\n{extra}\n')
    with pytest.raises(PrintFormatError, match="malformed tolerance rule"):
        diff_prints(BALL, BALL, tol)
    assert diff_command(BALL, BALL, tol, "text") == 2
