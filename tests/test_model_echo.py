"""Derived quantities of the input echo (engine modules fortran/model/) against the
report's print output (golden/appendix_*.prt), to the printed 6 significant digits,
plus independent checks of the formulas."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pyadore import _core
from pyadore.deck import read_deck
from pyadore.errors import AdoreInputError
from pyadore.printout import read_print

import probes


STEEL = 7750.0  # default steel density of the echo (docs/deck-format.md, Rec 8.1)


def agrees(value: float, printed: float) -> bool:
    """value is within half a unit of the printed 6th significant digit (E12.5 format)."""
    if printed == 0.0:
        return value == 0.0
    unit = 10.0 ** (math.floor(math.log10(abs(printed))) - 5)
    return abs(value - printed) <= 0.5 * unit * (1 + 1e-9)


@pytest.fixture(scope="module")
def ball(root):
    return read_deck(root / "decks" / "appendix_c_ball.inp"), read_print(root / "golden" / "appendix_c_ball.prt").echo


@pytest.fixture(scope="module")
def roller(root):
    return (read_deck(root / "decks" / "appendix_d_roller.inp"),
            read_print(root / "golden" / "appendix_d_roller.prt").echo)


def body(echo, name):
    return echo[f"inertial_parameters.{name}[1]"], [echo[f"inertial_parameters.{name}[{i}]"] for i in (2, 3, 4)]


def check_body(mass, moments, echo, name):
    m_echo, mom_echo = body(echo, name)
    assert agrees(mass, m_echo), (name, mass, m_echo)
    for got, want in zip(moments, mom_echo):
        assert agrees(got, want), (name, moments, mom_echo)


# --- ball bearing, Appendix C ---------------------------------------------------------

def ball_geometry(deck):
    g = lambda rid, name: deck.get(rid, name)  # noqa: E731
    return dict(d=g("5A", "ball_diameter"), dm=g("5A", "pitch_diameter"),
                a0=math.radians(g("5A", "free_contact_angle")),
                fo=g("5A", "outer_curvature_factor"), fi=g("5A", "inner_curvature_factor"))


def test_ball_dia_and_end_play(ball):
    deck, echo = ball
    b = ball_geometry(deck)
    c = probes.ball_clearance(b["dm"], b["d"], b["fo"], b["fi"], b["a0"])
    assert agrees(c["dia_play"], echo["bearing_geometry.dia_play_m"])
    assert agrees(c["end_play"], echo["bearing_geometry.end_play_m"])
    assert c["outer_groove_dia"] - c["inner_groove_dia"] - 2 * b["d"] == pytest.approx(c["dia_play"], rel=1e-9)


def test_ball_rolling_element(ball):
    deck, echo = ball
    d = deck.get("5A", "ball_diameter")
    mass, moments = probes.body_inertia("sphere", [d], STEEL)
    check_body(mass, moments, echo, "re")
    assert moments == pytest.approx([0.4 * mass * (d / 2) ** 2] * 3, rel=1e-14)


def test_ball_cage(ball):
    deck, echo = ball
    g = lambda name: deck.get("7.1", name)  # noqa: E731
    n = int(deck.get("3.2", "n_rolling_elements"))
    pocket = deck.get("5A", "ball_diameter") + g("pocket_clearance_1")
    mass, moments = probes.body_inertia(
        "ball_cage", [g("cage_outer_diameter"), g("cage_inner_diameter"), g("cage_width"), pocket], STEEL, n)
    check_body(mass, moments, echo, "cage")


@pytest.mark.parametrize("race", ["outer", "inner"])
def test_ball_races(ball, race):
    deck, echo = ball
    b = ball_geometry(deck)
    c = probes.ball_clearance(b["dm"], b["d"], b["fo"], b["fi"], b["a0"])
    if race == "outer":
        dims = [deck.get("4", "bearing_outer_diameter"), c["outer_groove_dia"], deck.get("4", "outer_race_width")]
    else:
        dims = [c["inner_groove_dia"], deck.get("4", "shaft_outer_diameter"), deck.get("4", "inner_race_width")]
    mass, moments = probes.body_inertia("hollow_cylinder", dims, STEEL)
    check_body(mass, moments, echo, f"{race}_race")


def test_ball_traction_curve(ball):
    deck, echo = ball
    g = lambda name: deck.get("10.1C", name)  # noqa: E731
    k = (g("traction_at_zero_slip"), g("max_traction"), g("traction_at_infinite_slip"), g("slip_at_max_traction"))
    a, b, c, d = probes.traction_fit(*k)
    for row in ("re_race1", "re_race2"):
        assert agrees(a, echo[f"lubrication_parameters.{row}[6]"])
        assert agrees(b, echo[f"lubrication_parameters.{row}[7]"])
        assert agrees(c, echo[f"lubrication_parameters.{row}[8]"])
    assert d == k[2]


def test_ball_scale_factors(ball):
    deck, echo = ball
    d = deck.get("5A", "ball_diameter")
    mass, _ = probes.body_inertia("sphere", [d], STEEL)
    load = [deck.get("9.1.1", f"applied_force_{c}") for c in "xyz"]
    length, force, time = probes.scale_factors(d, mass, load)
    block = "scale_factors_and_output_controls"
    assert agrees(length, echo[f"{block}.length_m"])
    assert agrees(force, echo[f"{block}.load_n"])
    assert agrees(time, echo[f"{block}.time_s"])


# --- cylindrical roller bearing, Appendix D ---------------------------------------------

def test_roller_rolling_element_moments_from_printed_mass(roller):
    deck, echo = roller
    mass, _ = body(echo, "re")
    d, length = deck.get("5B", "roller_diameter"), deck.get("5B", "roller_length")
    _, moments = probes.body_inertia("roller_moments", [d, length], mass)
    check_body(mass, moments, echo, "re")


def _engine_echo_roller_mass(tmp_path):
    """RE mass as the engine's print of the Appendix D deck echoes it."""
    import pyadore

    deck_path = Path(__file__).resolve().parents[1] / "decks" / "appendix_d_roller.inp"
    out = pyadore.run(deck_path, steps=0, out=tmp_path / "r.prt").print_path
    return read_print(out).echo["inertial_parameters.re[1]"]


@pytest.mark.xfail(strict=True, reason="the engine's crowned roller (land + crown arcs, "
                   "adore_contact_line_slices.roller_mass) weighs 1.28102e-3 kg against the echo's "
                   "1.28108e-3 (4.7e-5 relative, outside the printed 6 digits); the plain cylinder "
                   "rho pi D**2 L / 4 is 0.45 % heavier")
def test_roller_rolling_element_mass(roller, tmp_path):
    """The echo's RE mass to printed precision (the engine's model: the crowned roller)."""
    deck, echo = roller
    run_mass = _engine_echo_roller_mass(tmp_path)
    assert agrees(run_mass, body(echo, "re")[0])


def test_roller_mass_crown_explains_most_of_the_plain_cylinder_residual(roller, tmp_path):
    """The plain cylinder is 0.446 % above the echo; the crowned roller the engine uses is
    within 5e-5 of it: the crown, not an unknown factor, is the difference."""
    deck, echo = roller
    d, length = deck.get("5B", "roller_diameter"), deck.get("5B", "roller_length")
    mass, _ = probes.body_inertia("solid_cylinder", [d, length], deck.get("8.1", "density"))
    assert mass / body(echo, "re")[0] - 1 == pytest.approx(4.4621e-3, abs=1e-5)
    run_mass = _engine_echo_roller_mass(tmp_path)
    assert abs(run_mass / body(echo, "re")[0] - 1) < 5e-5


def test_roller_cage(roller):
    deck, echo = roller
    g = lambda name: deck.get("7.1", name)  # noqa: E731
    pocket_c = deck.get("5B", "roller_diameter") + g("pocket_clearance_1")
    pocket_a = deck.get("5B", "roller_length") + g("pocket_clearance_2")
    mass, moments = probes.body_inertia(
        "roller_cage", [g("cage_outer_diameter"), g("cage_inner_diameter"), g("cage_width"), pocket_c, pocket_a],
        STEEL, int(deck.get("3.2", "n_rolling_elements")))
    check_body(mass, moments, echo, "cage")


@pytest.mark.parametrize("race", ["outer", "inner"])
def test_roller_races(roller, race):
    deck, echo = roller
    assert echo["bearing_geometry.dia_play_m"] == deck.get("5B", "diametral_play")  # an input, echoed
    d_out, d_in = probes.roller_races(deck.get("5B", "pitch_diameter"), deck.get("5B", "roller_diameter"),
                                     deck.get("5B", "diametral_play"))
    if race == "outer":
        dims = [deck.get("4", "bearing_outer_diameter"), d_out, deck.get("4", "outer_race_width")]
    else:
        dims = [d_in, deck.get("4", "shaft_outer_diameter"), deck.get("4", "inner_race_width")]
    mass, moments = probes.body_inertia("hollow_cylinder", dims, STEEL)
    check_body(mass, moments, echo, f"{race}_race")


def test_roller_traction_curve(roller):
    deck, echo = roller
    g = lambda name: deck.get("10.1B", name)  # noqa: E731
    k = (g("traction_at_zero_slip"), g("max_traction"), g("traction_at_infinite_slip"), g("slip_at_max_traction"))
    a, b, c, d = probes.traction_fit(*k)
    for row in ("re_race1", "re_race2"):
        assert agrees(a, echo[f"lubrication_parameters.{row}[6]"])
        assert agrees(c, echo[f"lubrication_parameters.{row}[8]"])
    # B is lost in the roller echo; the brief/golden README quote 9.57239E-01.
    assert agrees(b, 9.57239e-01)
    # golden/README.md: the step-0 traction table confirms the curve.
    assert _core.traction_eval((a, b, c, d), [3.388e-2, 6.412e-2]) == pytest.approx([4.444e-2, 6.926e-2], abs=6e-6)


def test_roller_scale_factors(roller):
    deck, echo = roller
    d = deck.get("5B", "roller_diameter")
    mass, _ = body(echo, "re")  # the roller mass itself is not reproduced (see above)
    load = [deck.get("9.1.1", f"applied_force_{c}") for c in "xyz"]
    length, force, time = probes.scale_factors(d, mass, load)
    block = "scale_factors_and_output_controls"
    assert agrees(length, echo[f"{block}.length_m"])
    assert agrees(force, echo[f"{block}.load_n"])
    # The mass is itself rounded to 6 digits: some mass inside its rounding interval
    # must give the printed time (T is monotone in m).
    half = 0.5 * 10.0 ** (math.floor(math.log10(mass)) - 5)
    t_lo = probes.scale_factors(d, mass - half, load)[2]
    t_hi = probes.scale_factors(d, mass + half, load)[2]
    printed = echo[f"{block}.time_s"]
    half_t = 0.5 * 10.0 ** (math.floor(math.log10(printed)) - 5)
    assert t_lo <= printed + half_t and t_hi >= printed - half_t, (t_lo, time, t_hi, printed)


# --- independent checks -------------------------------------------------------------------

def test_hollow_cylinder_closed_forms():
    ro, ri, w, rho = 0.05, 0.03, 0.02, 8000.0
    mass, (ix, iy, iz) = probes.body_inertia("hollow_cylinder", [2 * ro, 2 * ri, w], rho)
    assert mass == pytest.approx(rho * math.pi * (ro**2 - ri**2) * w, rel=1e-14)
    assert ix == pytest.approx(mass * (ro**2 + ri**2) / 2, rel=1e-14)
    assert iy == iz == pytest.approx(mass * (3 * (ro**2 + ri**2) + w**2) / 12, rel=1e-14)


def test_hollow_cylinder_by_quadrature():
    """Ix and Iy by numerical integration over the annulus cross-section."""
    ro, ri, w, rho = 0.05, 0.03, 0.02, 8000.0
    mass, (ix, iy, _) = probes.body_inertia("hollow_cylinder", [2 * ro, 2 * ri, w], rho)
    r = np.linspace(ri, ro, 2001)
    x = np.linspace(-w / 2, w / 2, 2001)
    R, X = np.meshgrid(r, x, indexing="ij")
    dm = rho * 2 * np.pi * R  # mass per unit area of the (r, x) half-plane
    integ = lambda f: np.trapezoid(np.trapezoid(f * dm, x, axis=1), r)  # noqa: E731
    assert integ(np.ones_like(R)) == pytest.approx(mass, rel=1e-6)
    assert integ(R**2) == pytest.approx(ix, rel=1e-6)
    assert integ(R**2 / 2 + X**2) == pytest.approx(iy, rel=1e-6)


def test_solid_sphere():
    mass, moments = probes.body_inertia("sphere", [0.02], 7000.0)
    assert mass == pytest.approx(7000.0 * 4 / 3 * math.pi * 0.01**3, rel=1e-14)
    assert moments == pytest.approx([0.4 * mass * 0.01**2] * 3, rel=1e-14)


@pytest.mark.parametrize("k", [(0.0, 0.02, 0.016, 1.0), (0.0, 0.1, 0.08, 0.2), (0.06, 0.09, 0.01, 0.5),
                               (0.03, 0.05, 0.03, 2.0)])
def test_traction_curve_defining_conditions(k):
    k0, kmax, kinf, umax = k
    coef = probes.traction_fit(*k)
    kap = _core.traction_eval(coef, [0.0, umax, umax * (1 - 1e-4), umax * (1 + 1e-4), 1e4])
    assert kap[0] == pytest.approx(k0, abs=1e-14)
    assert kap[1] == pytest.approx(kmax, abs=1e-13)
    assert kap[2] < kap[1] and kap[3] < kap[1]
    assert kap[4] == pytest.approx(kinf, abs=1e-13)


@pytest.mark.parametrize("k", [(0.0, 0.02, 0.016, 0.0), (0.0, 0.02, 0.016, -1.0), (0.0, 0.016, 0.016, 1.0),
                               (0.03, 0.02, 0.01, 1.0), (0.0, 0.0, 0.0, 1.0)])
def test_traction_fit_rejects_impossible_input(k):
    with pytest.raises(AdoreInputError, match="traction curve"):
        probes.traction_fit(*k)


def test_scale_factors_reject_zero_load():
    with pytest.raises(AdoreInputError, match="load"):
        probes.scale_factors(0.01, 0.1, [0.0, 0.0, 0.0])


@pytest.mark.parametrize("label, field", [("Rec 10.5.1B", "re_cage_coeff_a"), ("Rec 10.5.2B", "race_cage_coeff_a")])
def test_negative_cage_friction_is_an_input_error(root, tmp_path, label, field):
    """The cage contacts' friction is coefficient A of Rec 10.5.1B (RE/cage) and 10.5.2B
    (race/cage) (bearing_t%cage_friction): a negative value is an input error of the deck
    reader naming record and field."""
    import pyadore

    text = (root / "decks" / "appendix_c_ball.inp").read_text().splitlines()
    hits = [i for i, line in enumerate(text) if line.startswith(label)]
    assert len(hits) == 1 and text[hits[0]].count("5.0000E-02") == 1
    text[hits[0]] = text[hits[0]].replace("5.0000E-02", "-5.000E-02")
    deck = tmp_path / "friction.inp"
    deck.write_text("\n".join(text) + "\n")
    with pytest.raises(AdoreInputError, match=rf"{label}\s+field {field} = -0.05: expected >= 0"):
        pyadore.run(deck, steps=0, out=tmp_path / "friction.prt")


def test_hypothetical_models_column_echoes_its_deck_fields(root, tmp_path):
    """LUBRICATION PARAMETERS, first column: RE/RACE rows echo Rec 10.3 field 1 (0 when the
    record is absent, as the roller print shows), RE/CAGE and RACE/CAGE field 5 of
    Rec 10.5.1B / 10.5.2B.  Changed values in a copy of the ball deck reach the print."""
    import pyadore

    text = (root / "decks" / "appendix_c_ball.inp").read_text().splitlines()
    edits = {"Rec 10.3 ": ("1.2500E-07", "3.7500E-07"), "Rec 10.5.1B": ("1.2500E-07", "4.5000E-07"),
             "Rec 10.5.2B": ("1.2500E-07", "5.5000E-07")}
    for i, line in enumerate(text):
        for label, (old, new) in edits.items():
            if line.startswith(label):
                assert line.count(old) == 1
                text[i] = line.replace(old, new)
    deck = tmp_path / "hyp.inp"
    deck.write_text("\n".join(text) + "\n")
    echo = read_print(pyadore.run(deck, steps=0, out=tmp_path / "hyp.prt").print_path).echo
    got = [echo[f"lubrication_parameters.{row}[1]"] for row in ("re_race1", "re_race2", "re_cage", "race_cage")]
    assert got == [3.75e-7, 3.75e-7, 4.5e-7, 5.5e-7]
