"""Traction-slip table (ADORE's user subroutine ADRX7, report 4.4.9) in whole runs.

The interpolation, the table checks and the file reader have engine unit tests
(fortran/tests/test_traction_law.f90).  Here: the table replaces the deck's traction in
both appendix runs, through `pyadore run` and the standalone engine, and bad tables fail
cleanly.  Every comparison is against an independent expectation (the curve the table
samples, a linear law, a constant coefficient), never against a stored engine output.
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

import pyadore
from pyadore import _core, api
from pyadore.errors import AdoreInputError
from pyadore.printout import read_print

# the Appendix D curve (k0 0, kmax 0.1, kinf 0.08, umax 0.2 m/s), fitted; the echo's A-D
ROLLER_CURVE = np.array([-0.08, 0.9572392597877629, 8.589122562472975, 0.08])


def _write_table(path, slip, kappa, header="slip_m_s, kappa"):
    lines = ["# traction-slip table for a pyadore test", header]
    lines += [f"{u:.9e}, {k:.12e}" for u, k in zip(slip, kappa)]
    path.write_text("\n".join(lines) + "\n")
    return path


def _half_unit(value: float) -> float:
    """Half a unit in the last printed digit of an ES10.3 value (the print's resolution)."""
    if value == 0.0:
        return 0.0
    return 0.5 * 10.0 ** (math.floor(math.log10(abs(value))) - 3)


def _step0(path):
    return read_print(path).steps[0]


@pytest.fixture(scope="module")
def roller_curve_and_table(tmp_path_factory, request):
    """The roller deck run with its own curve and with that curve sampled every 1 mm/s."""
    from pathlib import Path

    deck = Path(request.config.rootpath) / "decks" / "appendix_d_roller.inp"
    tmp = tmp_path_factory.mktemp("roller_table")
    slip = np.linspace(0.0, 3.0, 3001)
    table = _write_table(tmp / "curve.txt", slip, _core.traction_eval(ROLLER_CURVE, slip))
    curve_run = api.run(deck, steps=0, out=tmp / "curve.prt")
    table_run = api.run(deck, steps=0, out=tmp / "table.prt", traction_table=table)
    return curve_run, table_run


def test_table_sampling_the_deck_curve_reproduces_the_curve_run(roller_curve_and_table):
    """Linear interpolation at 1 mm/s differs from the curve by <= h**2/8 max|kappa''|
    = 2.8e-6 (3e-5 of the coefficients here), below the print's resolution: every traction
    quantity must agree to the last printed digit."""
    curve, table = (_step0(r.print_path) for r in roller_curve_and_table)
    checked = 0
    for name, columns in [("re_traction", ["slip_velocity_outer_m_s", "slip_velocity_inner_m_s",
                                            "trac_coeff_outer", "trac_coeff_inner"]),
                          ("re_motion", ["contact_loss_outer_W", "contact_loss_inner_W", "wear_rate_m3_s"]),
                          ("slices_1", ["trac_load_outer_N_m", "trac_load_inner_N_m"])]:
        for column in columns:
            for a, b in zip(curve.tables[name][column], table.tables[name][column]):
                # at most one unit in the last printed digit (values may straddle a rounding edge)
                unit = 2.0 * _half_unit(max(abs(a), abs(b)))
                assert abs(a - b) <= unit * (1.0 + 1e-9), (name, column, a, b)
                checked += 1
    assert checked > 60
    # the slips stay inside the table (3 m/s), so no value comes from the held end
    assert curve.tables["re_traction"][["slip_velocity_outer_m_s", "slip_velocity_inner_m_s"]].max().max() < 3.0


def test_print_lists_the_table_under_user_subroutine_input(roller_curve_and_table):
    curve_run, run = roller_curve_and_table
    head = run.text.split("Listing of input data records")[0]
    assert head.startswith("Input from optional user subroutines")
    assert "ADRX7 TRACTION-SLIP TABLE (3001 POINTS)" in head
    assert "  1.00000E-03  1.63324E-03" in head   # kappa(1 mm/s) of the curve, E-format 5 decimals
    # the deck, its listing and its echo are unchanged: the print parser reads the same echo
    assert run.text.split("Listing of input data records")[1] != ""
    assert read_print(run.print_path).echo == read_print(curve_run.print_path).echo


def test_linear_table_sets_the_ball_runs_printed_coefficients(tmp_path, ball_deck):
    """kappa = 0.02 + 0.006 u (two points, 0 and 10 m/s) replaces the deck's EHD traction:
    each printed coefficient is that line at the printed slip."""
    table = _write_table(tmp_path / "linear.txt", [0.0, 10.0], [0.02, 0.08])
    step = _step0(api.run(ball_deck, steps=0, out=tmp_path / "ball.prt", traction_table=table).print_path)
    t = step.tables["re_traction"]
    for side in ("outer", "inner"):
        for u, k in zip(t[f"slip_velocity_{side}_m_s"], t[f"trac_coeff_{side}"]):
            assert 0.0 < u < 10.0
            assert abs(k - (0.02 + 0.006 * u)) <= 0.006 * _half_unit(u) + _half_unit(k), (side, u, k)


def test_constant_table_makes_loss_proportional_to_wear(tmp_path, roller_deck):
    """kappa = 0.05 at every slip: each roller's contact loss is 0.05 x its sliding integral
    (int |u| dQ) and its Archard wear rate is k/H x the same integral, so loss / wear is one
    constant, 0.05 H / k (ceramic roller, Rec 8.1: RC 80, k 2e-6; H = RC x 9.80665e7 Pa,
    docs/tribology.md), and every printed coefficient is 0.05."""
    table = _write_table(tmp_path / "constant.txt", [0.0, 1.0], [0.05, 0.05])
    step = _step0(api.run(roller_deck, steps=0, out=tmp_path / "c.prt", traction_table=table).print_path)
    t = step.tables["re_traction"]
    m = step.tables["re_motion"]
    loaded = m.index[(m.contact_loss_outer_W > 0)]
    assert len(loaded) == 8
    for k in loaded:
        assert t.trac_coeff_outer[k] == 0.05
        loss = m.contact_loss_outer_W[k] + m.contact_loss_inner_W[k]
        ratio = loss / m.wear_rate_m3_s[k]
        expected = 0.05 * 80 * 9.80665e7 / 2e-6
        # print resolution: 4 significant digits in loss and wear
        tol = (_half_unit(m.contact_loss_outer_W[k]) + _half_unit(m.contact_loss_inner_W[k])) / loss \
            + _half_unit(m.wear_rate_m3_s[k]) / m.wear_rate_m3_s[k]
        assert abs(ratio / expected - 1.0) <= tol, (k, ratio, expected)


BAD_TABLES = [
    ("0 0\n0.1 abc\n", ":2:5: traction table: expected a number", "    0.1 abc\n        ^"),
    ("0.1 0\n0.2 0.1\n", "traction table point 1: expected slip 0 m/s", None),
    ("0 0\n0.2 0.1\n0.1 0.1\n", "traction table point 3: expected a slip greater", None),
    ("0 0.1\n", "expected at least 2 points", None),
    ("0 0 0\n1 0.1\n", ":1:5: traction table: expected two numbers", None),
]


@pytest.mark.parametrize("content, message, caret", BAD_TABLES)
def test_bad_table_fails_cleanly_through_the_cli(tmp_path, roller_deck, content, message, caret):
    table = tmp_path / "bad.txt"
    table.write_text(content)
    out = tmp_path / "out.prt"
    proc = subprocess.run([sys.executable, "-m", "pyadore", "run", str(roller_deck), "-o", str(out),
                           "--traction-table", str(table)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    assert str(table) in proc.stderr and message in proc.stderr
    if caret:
        assert caret in proc.stderr
    assert not out.exists() and not list(tmp_path.glob("*.part"))


def test_bad_table_fails_cleanly_in_the_standalone_engine(tmp_path, roller_deck, run_exe):
    table = tmp_path / "bad.txt"
    table.write_text("0 0\n0.2 -0.1\n")
    out = tmp_path / "out.prt"
    proc = run_exe(roller_deck, out, "--traction-table", table)
    assert proc.returncode == 1
    assert f"{table}: traction table point 2: expected a traction coefficient >= 0" in proc.stderr
    assert not out.exists() and not list(tmp_path.glob("*.part"))


def test_missing_table_is_an_input_error(tmp_path, roller_deck):
    with pytest.raises(AdoreInputError, match="nothere.txt: traction table file not found"):
        api.run(roller_deck, steps=0, out=tmp_path / "x.prt", traction_table=tmp_path / "nothere.txt")
    assert not (tmp_path / "x.prt").exists()


def test_standalone_engine_runs_with_a_table(tmp_path, roller_deck, run_exe):
    table = _write_table(tmp_path / "t.txt", [0.0, 0.2, 2.0], [0.0, 0.1, 0.08])
    out = tmp_path / "r.prt"
    proc = run_exe(roller_deck, out, "--steps", "0", "--traction-table", table)
    assert proc.returncode == 0, proc.stderr
    text = out.read_text()
    assert "ADRX7 TRACTION-SLIP TABLE (3 POINTS)" in text and f"FILE: {table}" in text


def test_ball_contact_temperature_rise_is_linear_in_a_constant_coefficient(tmp_path, ball_deck):
    """With kappa = mu everywhere the start (least mu * int |u| dQ) does not depend on mu, and
    the flash temperature (eqs 35-36, linear in the heat kappa |u| p) doubles with mu:
    speeds equal, every contact loss and temperature rise twice, to print resolution."""
    steps = []
    for mu in (0.05, 0.10):
        table = _write_table(tmp_path / f"mu{mu}.txt", [0.0, 1.0], [mu, mu])
        steps.append(_step0(api.run(ball_deck, steps=0, out=tmp_path / f"b{mu}.prt",
                                    traction_table=table).print_path))
    one, two = steps
    assert (one.tables["re_motion"].orbital_velocity_rpm == two.tables["re_motion"].orbital_velocity_rpm).all()
    checked = 0
    for name, column in [("re_thermal", "contact_temp_rise_outer_K"), ("re_thermal", "contact_temp_rise_inner_K"),
                         ("re_motion", "contact_loss_outer_W"), ("re_motion", "contact_loss_inner_W")]:
        for a, b in zip(one.tables[name][column], two.tables[name][column]):
            assert a > 0.0
            assert abs(b - 2.0 * a) <= 2.0 * _half_unit(a) + _half_unit(b) + 1e-12 * b, (column, a, b)
            checked += 1
    assert checked == 4 * 18


def test_read_traction_table_returns_what_the_run_uses(tmp_path):
    table = _write_table(tmp_path / "t.txt", [0.0, 0.2, 2.0], [0.0, 0.1, 0.08])
    frame = pyadore.read_traction_table(table)
    assert list(frame.columns) == ["slip_m_s", "kappa"]
    assert frame.slip_m_s.tolist() == [0.0, 0.2, 2.0] and frame.kappa.tolist() == [0.0, 0.1, 0.08]
    (tmp_path / "bad.txt").write_text("0 0\n0.2 x\n")
    with pytest.raises(AdoreInputError, match=r"bad.txt:2:5: traction table: expected a number"):
        pyadore.read_traction_table(tmp_path / "bad.txt")


def test_validate_checks_the_traction_table_too(tmp_path, roller_deck):
    good = _write_table(tmp_path / "t.txt", [0.0, 0.2, 2.0], [0.0, 0.1, 0.08])
    proc = subprocess.run([sys.executable, "-m", "pyadore", "validate", str(roller_deck), "--traction-table",
                           str(good)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "traction-slip table, 3 points, slip 0 to 2 m/s, coefficient 0 to 0.1" in proc.stdout
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0\n0.2 0.1\n0.1 0.1\n")
    proc = subprocess.run([sys.executable, "-m", "pyadore", "validate", str(roller_deck), "--traction-table",
                           str(bad)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 1
    assert "Traceback" not in proc.stderr
    assert f"{bad}: traction table point 3: expected a slip greater" in proc.stderr


def test_standalone_engine_needs_the_table_file_name(tmp_path, roller_deck, run_exe):
    proc = run_exe(roller_deck, tmp_path / "r.prt", "--traction-table")
    assert proc.returncode == 1
    assert "adore: error: --traction-table needs a value (FILE)" in proc.stderr
    assert not (tmp_path / "r.prt").exists()
