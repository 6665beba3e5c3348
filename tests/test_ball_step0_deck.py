"""Step 0 of the Appendix C deck computed end to end by the engine (deck -> model ->
mounting -> consistent quasi-static start with race-control kinematics -> basic life),
against the report's printed step 0 (golden/appendix_c_ball.prt).

Unlike tests/test_ball_quasistatic.py, nothing here is fed from the report: the orbital
speeds are the engine's own (outer race control; the report minimises contact
dissipation, which needs traction).  Issue "Ball step 0" asks 1 % for the mechanics and
3 % for the life.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pyadore import AdoreInputError, _core
from pyadore.printout import read_print

ROOT = Path(__file__).resolve().parents[1]
DEG = 180 / math.pi
RPM = 30 / math.pi


@pytest.fixture(scope="module")
def step0():
    return _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")


@pytest.fixture(scope="module")
def golden():
    return read_print(ROOT / "golden" / "appendix_c_ball.prt").steps[0]


COLUMNS = [  # (engine key, golden table, golden column, factor, tolerance)
    ("azimuth", "re_contact", "orbital_position_deg", DEG, 1e-4),
    ("alpha_o", "re_contact", "contact_angle_outer_deg", DEG, 0.01),
    ("alpha_i", "re_contact", "contact_angle_inner_deg", DEG, 0.01),
    ("q_o", "re_contact", "contact_load_outer_N", 1.0, 0.01),
    ("q_i", "re_contact", "contact_load_inner_N", 1.0, 0.01),
    ("p_o", "re_contact", "contact_stress_outer_Pa", 1.0, 0.01),
    ("p_i", "re_contact", "contact_stress_inner_Pa", 1.0, 0.01),
    ("a_o", "re_contact", "major_half_width_outer_m", 1.0, 0.01),
    ("a_i", "re_contact", "major_half_width_inner_m", 1.0, 0.01),
    ("b_o", "re_contact", "minor_half_width_outer_m", 1.0, 0.01),
    ("b_i", "re_contact", "minor_half_width_inner_m", 1.0, 0.01),
    ("delta_o", "re_thermal", "contact_deflection_outer_m", 1.0, 0.01),
    ("delta_i", "re_thermal", "contact_deflection_inner_m", 1.0, 0.01),
    ("orbital_speed", "re_motion", "orbital_velocity_rpm", RPM, 0.01),
]


@pytest.mark.parametrize("key,table,column,factor,tol", COLUMNS, ids=[c[2] for c in COLUMNS])
def test_step0_column_matches_report(step0, golden, key, table, column, factor, tol):
    balls, _ = step0
    ref = golden.table(table)[column].astype(float).to_numpy()
    run = balls[key] * factor
    assert len(run) == len(ref) == 18
    known = ~np.isnan(ref) & (ref != 0)
    assert known.sum() >= 10
    rel = np.abs(run[known] - ref[known]) / np.abs(ref[known])
    assert rel.max() <= tol, f"{column}: worst {rel.max():.3%} at element {np.flatnonzero(known)[rel.argmax()] + 1}"


def test_step0_section_3_matches_report(step0):
    _, s = step0
    assert s["inner_fit"] == pytest.approx(9.918e-07, abs=0.0005e-07)
    assert s["outer_fit"] == pytest.approx(1.000e-05, abs=0.0005e-05)
    assert s["clearance"] == pytest.approx(1.525e-04, abs=0.0005e-04)
    assert s["basic_life_h"] == pytest.approx(533.4, rel=0.03)
    assert s["inner_force_x"] == pytest.approx(-4.495e3, rel=0.01)
    assert s["inner_force_z"] == pytest.approx(-1.995e3, rel=0.01)
    assert s["inner_moment_y"] == pytest.approx(-6.827e1, rel=0.01)
    assert math.hypot(s["u_y"], s["u_z"]) == pytest.approx(1.002e-05, rel=0.01)  # section 2 IRace radial


def test_step0_is_repeatable_in_one_process(step0):
    again = _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")
    for key, values in step0[0].items():
        assert np.array_equal(values, again[0][key]), key
    assert step0[1] == again[1]


def test_roller_deck_is_refused_by_the_ball_path():
    with pytest.raises(AdoreInputError, match="not a ball-bearing deck"):
        _core.ball_step0_from_deck(ROOT / "decks" / "appendix_d_roller.inp")
