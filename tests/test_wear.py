"""Wear rates (fortran/tribology/wear.f90): Archard's law dV/dt = k / H * integral of |u| dQ
with ADORE 5.0's hardness conversion H = 10 RC kgf/mm**2, checked on the three kinds of
rows the report prints: a cage land (steel RC 20), the ceramic rollers (RC 80) and the
steel balls (RC 61, tests/test_tribology.py with the report's own speeds; the end-to-end
run is gated at 5 % in tests/test_run_golden.py).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pyadore import AdoreInputError, _core
from pyadore.deck import read_deck
from pyadore.printout import read_print

import probes


ROOT = Path(__file__).resolve().parents[1]
ROLLER_DECK = ROOT / "decks" / "appendix_d_roller.inp"


def _roller_golden():
    return read_print(ROOT / "golden" / "appendix_d_roller.prt").steps[0]


def test_hardness_conversion_reproduces_the_cage_land_row():
    """Roller deck, cage land 2: the report prints its loss 0.6903 W and wear 3.519E-12 m**3/s.
    With the cage's friction coefficient of Rec 10.5.2B (0.05) the loss is load x slip =
    13.81 N m/s; the cage's k 5E-4 and RC 20 then give the printed wear to its 4 digits only
    with H = 10 RC kgf/mm**2 (a Vickers conversion, HRC 20 -> HV 238, misses by 16 %)."""
    mu = read_deck(ROLLER_DECK).get("10.5.2B", "race_cage_coeff_a")
    assert mu == 0.05
    row = _roller_golden().table("race_cage").iloc[1]
    sliding = row["contact_loss_W"] / mu
    hardness, (rate,) = probes.wear_rate(5e-4, 20.0, [sliding])
    assert hardness == pytest.approx(200 * 9.80665e6, rel=1e-12)
    assert rate == pytest.approx(row["wear_rate_m3_s"], rel=5e-4)
    vickers = (223 * 20 + 14500) / (100 - 20) * 9.80665e6          # HRC -> HV, ASTM E140 fit
    assert abs(5e-4 * sliding / vickers / row["wear_rate_m3_s"] - 1) > 0.1


def test_roller_wear_matches_the_printed_rows():
    """Ceramic rollers (Rec 8.1: k 2E-6, RC 80) over the engine's slice slips and loads:
    the printed rows of the loaded (roller 2, 8) and the unloaded-inner rollers (3-7)."""
    rollers, _, _ = probes.roller_step0_tribology(ROLLER_DECK)
    printed = _roller_golden().table("re_motion")["wear_rate_m3_s"].to_numpy()
    rows = [k for k in range(len(printed)) if not np.isnan(printed[k])]
    assert rows == [1, 2, 3, 4, 5, 6, 7]
    for k in rows:
        assert rollers["wear"][k] == pytest.approx(printed[k], rel=2e-3), f"roller {k + 1}"


def test_run_wear_is_archard_of_the_runs_own_sliding():
    """Energy-style consistency: each element's wear is k/H times the load x slip of its two
    race contacts, and the load x slip is never below loss / largest traction coefficient."""
    balls, _ = _core.ball_step0_from_deck(ROOT / "decks" / "appendix_c_ball.inp")
    _, rates = probes.wear_rate(5e-6, 61.0, balls["sliding_o"] + balls["sliding_i"])
    assert np.allclose(balls["wear"], rates, rtol=1e-13, atol=0)
    assert np.all(balls["sliding_o"] * 0.1 > balls["loss_o"])      # traction coefficients < 0.1
    rollers, _, _ = probes.roller_step0_tribology(ROLLER_DECK)
    _, rates = probes.wear_rate(2e-6, 80.0, rollers["sliding_o"] + rollers["sliding_i"])
    assert np.allclose(rollers["wear"], rates, rtol=1e-13, atol=0)


def test_uniform_sliding_is_archards_closed_form():
    """A load Q sliding at a uniform speed v: dV/dt = k Q v / H."""
    q, v = 250.0, 3.0
    hardness, (rate,) = probes.wear_rate(1e-5, 45.0, [q * v])
    assert rate == pytest.approx(1e-5 * q * v / (450 * 9.80665e6), rel=1e-14)
    assert hardness == pytest.approx(450 * 9.80665e6, rel=1e-14)


@pytest.mark.parametrize("k, rc, sliding", [(-1e-6, 60.0, 1.0), (1e-6, 0.0, 1.0), (1e-6, 60.0, -1.0)])
def test_wear_wrapper_refuses_bad_input(k, rc, sliding):
    with pytest.raises(AdoreInputError, match="wear rate"):
        probes.wear_rate(k, rc, [sliding])


@pytest.fixture(scope="module")
def roller_print(tmp_path_factory):
    from pyadore import run

    return read_print(run(ROLLER_DECK, steps=0, out=tmp_path_factory.mktemp("wear") / "d.prt")
                      .print_path).steps[0]


def test_inner_race_wear_matches_the_printed_row(roller_print):
    """The race rows of section 2 ("Time Ave Wear Rate"): Archard with the race's own k and
    hardness (steel, RC 61, k 5E-6 in the echo) over all the race's contacts.  The report
    prints the inner race of the roller run, 6.540E-15 m**3/s (the outer race's is lost)."""
    printed = _roller_golden().table("bodies").loc["IRace", "wear_rate_m3_s"]
    run = roller_print.table("bodies").loc["IRace", "wear_rate_m3_s"]
    assert printed == 6.540e-15
    assert run == pytest.approx(printed, rel=2e-3)


def test_race_wear_is_archard_of_its_contacts_sliding(roller_print, tmp_path):
    """Independent of the report: each race's wear is k/H times the sum over its contacts of
    integral |u| dQ (the elements' sliding integrals), in both runs; and the balls' and races'
    wear share one k/H in the ball run (all steel RC 61, k 5E-6), so the two races together
    wear as much as all balls together."""
    from pyadore import run

    rollers, _, _ = probes.roller_step0_tribology(ROLLER_DECK)
    _, (outer, inner) = probes.wear_rate(5e-6, 61.0, [rollers["sliding_o"].sum(), rollers["sliding_i"].sum()])
    bodies = roller_print.table("bodies")
    for body, expected in (("ORace", outer), ("IRace", inner)):
        assert bodies.loc[body, "wear_rate_m3_s"] == pytest.approx(expected, rel=6e-4), body  # 4 digits
    ball = read_print(run(ROOT / "decks" / "appendix_c_ball.inp", steps=0, out=tmp_path / "c.prt")
                      .print_path).steps[0]
    races = ball.table("bodies").loc[["ORace", "IRace"], "wear_rate_m3_s"].sum()
    balls = ball.table("re_motion")["wear_rate_m3_s"].sum()
    assert races == pytest.approx(balls, rel=1.1e-3)   # every printed value within 5e-4
