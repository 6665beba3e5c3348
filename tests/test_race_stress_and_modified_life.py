"""Race hoop stress (section 2 "Stress") and the modified (Tallian) life of the run.

The hoop stress is checked against the report's print of both appendix decks and against
the plane-stress Lame / rotating-disc formulas evaluated here from the deck's geometry and
the engine's own fit pressures; the run's modified life against the life model of
tests/test_life.py fed with the run's own per-ball quantities, and against the report
(strict xfail: the model as printed gives 24 % more, docs/life-model.md).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import pyadore
from pyadore import _core
from pyadore.printout import read_print

import probes


ROOT = Path(__file__).resolve().parents[1]
RPM = math.pi / 30
E, NU, RHO = 2.0e11, 0.25, 7750.0          # steel races, shaft and housing of both decks


def _bodies(path):
    return read_print(path).steps[0].table("bodies")


def _bore_hoop(d_in, d_out, p_in, p_out, w):
    """Plane-stress hoop stress at the bore of a spinning ring (Timoshenko & Goodier)."""
    a, b = d_in / 2, d_out / 2
    lame = (p_in * (a * a + b * b) - 2 * p_out * b * b) / (b * b - a * a)
    return lame + RHO * w * w / 4 * ((3 + NU) * b * b + (1 - NU) * a * a)


CASES = {
    # deck: (shaft id, shaft od, bearing od, housing od, fits [inner, outer], inner rpm,
    #        raceway diameters (outer, inner), dia play)
    "appendix_c_ball": (0.02, 0.10, 0.18, 0.205, [5e-5, 1e-5], 20000.0),
    "appendix_d_roller": (0.01, 0.03, 0.055, 0.065, [2e-5, 0.0], 70000.0),
}


def _raceways(name):
    if name == "appendix_c_ball":
        c = probes.ball_clearance(0.14, 0.01905, 0.52, 0.54, math.radians(25.0))
        return c["outer_groove_dia"], c["inner_groove_dia"], c["dia_play"]
    d_o, d_i = probes.roller_races(0.043, 0.008, 4e-5)
    return d_o, d_i, 4e-5


@pytest.mark.parametrize("name", list(CASES))
def test_race_hoop_stress_is_lame_and_matches_report(tmp_path, name):
    shaft_id, shaft_od, bearing_od, housing_od, fits, rpm = CASES[name]
    d_o, d_i, play = _raceways(name)
    w = rpm * RPM
    rings = [[shaft_id, shaft_od, E, NU, RHO], [shaft_od, d_i, E, NU, RHO], [d_o, bearing_od, E, NU, RHO],
             [bearing_od, housing_od, E, NU, RHO]]
    m = probes.mount_races(rings, fits, [w, 0.0], play)
    inner = _bore_hoop(shaft_od, d_i, m["inner_pressure"], 0.0, w)
    outer = _bore_hoop(d_o, bearing_od, 0.0, m["outer_pressure"], 0.0)
    run = _bodies(pyadore.run(ROOT / "decks" / f"{name}.inp", steps=0, out=tmp_path / "run.prt").print_path)
    # the print keeps 4 digits (E-format): half a unit of the last digit is <= 5e-4 relative
    assert run.loc["IRace", "hoop_stress_Pa"] == pytest.approx(inner, rel=5e-4)
    assert run.loc["ORace", "hoop_stress_Pa"] == pytest.approx(outer, rel=5e-4, abs=1.0)
    gold = _bodies(ROOT / "golden" / f"{name}.prt")
    for race in ("ORace", "IRace"):
        ref = gold.loc[race, "hoop_stress_Pa"]
        if not math.isnan(ref):
            assert run.loc[race, "hoop_stress_Pa"] == pytest.approx(ref, rel=5e-4), race


@pytest.fixture(scope="module")
def ball_step0():
    return _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")


def test_run_modified_life_is_the_life_model_of_its_own_state(ball_step0):
    """The run's Tallian life equals pyadore.probes.ball_bearing_life fed with the run's own
    loads, angles, speeds, pressures, Lambda = film x thermal factor / sigma, mu = printed
    traction coefficient and the Lame hoop stresses (checked above)."""
    b, s = ball_step0
    consts = probes.life_default_constants()
    sigma = consts["sigma_rms"]
    lam = {t: np.nan_to_num(b[f"film_{t}"] * b[f"thermal_factor_{t}"] / sigma) for t in "oi"}
    c = probes.ball_clearance(0.14, 0.01905, 0.52, 0.54, math.radians(25.0))
    w = 20000 * RPM
    rings = [[0.02, 0.1, E, NU, RHO], [0.1, c["inner_groove_dia"], E, NU, RHO],
             [c["outer_groove_dia"], 0.18, E, NU, RHO], [0.18, 0.205, E, NU, RHO]]
    m = probes.mount_races(rings, [5e-5, 1e-5], [w, 0.0], c["dia_play"])
    life = probes.ball_bearing_life(
        b["q_o"], b["q_i"], b["alpha_o"], b["alpha_i"], b["orbital_speed"] / RPM, b["p_o"], b["p_i"],
        d_ball=0.01905, d_pitch=0.14, f_outer=0.52, f_inner=0.54, outer_speed=0.0, inner_speed=20000.0,
        lambda_outer=lam["o"], lambda_inner=lam["i"], mu_outer=np.nan_to_num(b["trac_o"]),
        mu_inner=np.nan_to_num(b["trac_i"]),
        hoop_outer=_bore_hoop(c["outer_groove_dia"], 0.18, 0.0, m["outer_pressure"], 0.0),
        hoop_inner=_bore_hoop(0.1, c["inner_groove_dia"], m["inner_pressure"], 0.0, w))
    assert s["basic_life_h"] == pytest.approx(life["basic"], rel=1e-10)
    assert s["modified_life_h"] == pytest.approx(life["modified"], rel=1e-10)


@pytest.mark.xfail(strict=True, reason="modified life 5540 h vs the report's 4460 h (+24.2 %): the Tallian "
                   "equations as printed give 5564 h with the report's own loads (tests/test_life.py); "
                   "docs/life-model.md lists the excluded candidates")
def test_run_modified_life_matches_report(ball_step0):
    _, s = ball_step0
    assert s["modified_life_h"] == pytest.approx(4460.0, rel=0.03)
