"""Boundary friction of the race contacts (run option ``boundary_friction``; docs/tribology.md,
"Boundary friction"; issue #28, the deep-groove power loss against the SKF model).

Independent truth: Heathcote's free rolling of a ball in a conforming groove with Coulomb
friction (Johnson, Contact Mechanics, 1985, the ball in a groove: the two bands of pure
rolling at y = +-0.347 a for an elliptical contact's load per strip 3 Q / (4 a) (1 - y**2 /
a**2)), and the sliding power of that slip integrated by hand (a dense trapezoidal rule of
the same strip form, independent of the engine's Gauss rule per slip zone).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import probes
import pyadore
from pyadore.deck import read_deck
from pyadore.errors import AdoreError
from pyadore.printout import read_print

ROOT = Path(__file__).resolve().parents[1]
DEEP_GROOVE = ROOT / "decks" / "examples" / "deep_groove_radial.inp"
ROLLER = ROOT / "decks" / "appendix_d_roller.inp"

# the deep-groove radial deck's inner contact of its most loaded ball at 1 000 r/min and
# 3 kN radial (the engine's step-0 Hertz load and semi-major axis)
R_BALL, R_PITCH = 5.75e-3, 21.75e-3          # m: ball radius, ball centre's radius
A_INNER, Q_INNER = 1.916e-3, 1955.0          # m, N
RACE_SPEED = 1000.0 * math.pi / 30.0 - 38.65  # rad/s: inner race relative to the cage
MU, U_B = 0.1, 1.0e-3                        # the boundary law: mu (1 - exp(-|u| / u_b))


def _law(u):
    return MU * np.sign(u) * (1.0 - np.exp(-np.abs(u) / U_B))


def _engine(omega_axial: float) -> dict:
    return probes.contact_traction(-1, 0.0, R_BALL, R_PITCH, (omega_axial, 0.0), RACE_SPEED, A_INNER, Q_INNER,
                                   [-MU, 0.0, 1.0 / U_B, MU], n_gauss=16)


def test_boundary_law_rolls_freely_as_heathcote():
    """The strip traction with the boundary law: the ball spin at which the inner contact's
    net traction vanishes (free rolling) puts its pure-rolling points at Heathcote's +-0.347 a
    (+0.0012 a from the law's 1 mm/s rise: the hand integral's own points), and its power is
    the hand integral of mu(|u|) |u| over the strip load."""
    rolling = RACE_SPEED * (R_PITCH - R_BALL) / R_BALL
    sign = 1.0 if abs(_engine(rolling)["centre_slip"]) < abs(_engine(-rolling)["centre_slip"]) else -1.0
    omega = brentq(lambda w: _engine(sign * w)["force"], 0.99 * rolling, 1.01 * rolling, xtol=1e-12)
    t = _engine(sign * omega)
    assert t["n_rolling"] == 2
    # the hand calculation at the same spin: slip of ball-surface points along the major axis,
    # y the arc length from the centre (the point at angle y / R from the contact normal)
    y = np.linspace(-A_INNER, A_INNER, 200001)
    rho = R_BALL * np.cos(y / R_BALL)
    u = RACE_SPEED * (R_PITCH - rho) - omega * rho
    q = 0.75 * Q_INNER / A_INNER * (1.0 - (y / A_INNER) ** 2)
    assert abs(np.trapezoid(_law(u) * q, y)) < 1e-4 * MU * Q_INNER      # the hand rule agrees: free rolling
    k = np.where(np.diff(np.sign(u)) != 0)[0]
    y0 = y[k] - u[k] * (y[k + 1] - y[k]) / (u[k + 1] - u[k])
    assert sorted(abs(y0 / A_INNER)) == pytest.approx([0.3485, 0.3485], abs=2e-4)
    assert sorted([abs(t["s1"]), abs(t["s2"])]) == pytest.approx(list(abs(y0)), rel=1e-3)
    assert abs(y0[-1] / A_INNER - 0.3473) < 0.002                          # Heathcote's Coulomb value
    power = np.trapezoid(_law(u) * u * q, y)
    assert abs(t["power"]) == pytest.approx(power, rel=1e-3)
    # the differential slip: 6.6 % of the rolling speed at the contact's ends
    assert np.abs(u).max() / t["rolling_speed"] == pytest.approx(0.066, abs=1e-3)


def _deck(tmp_path: Path, speed: float, load: float) -> Path:
    deck = read_deck(DEEP_GROOVE)
    deck.set("9.1.2", "inner_race_speed", speed)
    deck.set("9.1.1", "applied_force_z", load)
    path = tmp_path / "case.inp"
    deck.save(path)
    return path


def test_boundary_friction_replaces_the_curve_of_thin_films(tmp_path):
    """Off (0, the default) the print is the deck's curve's, byte for byte; on, the
    boundary-lubricated deep-groove contacts at 1 000 r/min and 3 kN (film parameter below 1)
    lose what Coulomb friction on their Heathcote slip loses - tens of times the curve's -
    and the total is the sum of the contact losses."""
    path = _deck(tmp_path, 1000.0, 3000.0)
    default = pyadore.run(path, steps=0, out=tmp_path / "default.prt").text
    zero = pyadore.run(path, steps=0, out=tmp_path / "zero.prt", boundary_friction=0.0).text
    assert zero == default
    on = pyadore.run(path, steps=0, out=tmp_path / "on.prt", boundary_friction=MU)
    off = read_print(tmp_path / "default.prt").steps[0]
    step = read_print(on.print_path).steps[0]
    loss_on = float(step.table("performance")["total_power_loss_W"].iloc[0])
    loss_off = float(off.table("performance")["total_power_loss_W"].iloc[0])
    assert loss_on > 20.0 * loss_off
    # the contact losses add up to the total, ball 1's inner contact (the most loaded) the largest
    losses = step.table("re_motion")[["contact_loss_outer_W", "contact_loss_inner_W"]].fillna(0.0)
    assert losses.to_numpy().sum() == pytest.approx(loss_on, rel=2e-3)
    assert losses.to_numpy().argmax() == 1
    # a run with time steps says so in its listing and its note
    one = pyadore.run(path, steps=1, out=tmp_path / "one.prt", boundary_friction=MU)
    assert "BOUNDARY FRICTION 1.000E-01 (COULOMB)" in one.text


@pytest.mark.parametrize("deck, option", [(ROLLER, {}), (DEEP_GROOVE, {"traction_table": "x"})])
def test_boundary_friction_needs_an_ehd_ball_deck(tmp_path, deck, option):
    """The option replaces the curve of a model-3 ball deck only: refused, naming it, for a
    roller deck (model 2) or with a traction table."""
    if option.get("traction_table"):
        table = tmp_path / "table.dat"
        table.write_text("0.0 0.0\n1.0 0.05\n")
        option = {"traction_table": str(table)}
    with pytest.raises(AdoreError, match="boundary_friction"):
        pyadore.run(deck, steps=0, out=tmp_path / "x.prt", boundary_friction=MU, **option)
