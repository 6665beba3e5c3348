"""Step-0 roller/race tribology (fortran/tribology/roller_traction.f90, docs/tribology.md):
the engine end to end from the Appendix D deck against the report's step-0 print, plus
independent truths (energy balance, slice sums recomputed, roller moment balance).
The slice quadrature against a fine uniform rule is fortran/tests/test_roller_traction.f90."""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

from pyadore._core import traction_eval
from pyadore.printout import read_print

from probes import SPIN_EQUILIBRIUM, roller_step0_tribology, traction_fit


ROOT = Path(__file__).resolve().parents[1]
DECK = ROOT / "decks" / "appendix_d_roller.inp"
D = 8.0e-3
TOL = 0.05


@pytest.fixture(scope="module")
def golden():
    return read_print(ROOT / "golden" / "appendix_d_roller.prt").steps[0]


@pytest.fixture(scope="module")
def run():
    return roller_step0_tribology(DECK)


def _pairs(golden, table, column, values):
    col = golden.table(table)[column].to_numpy(dtype=float)
    return [(k, float(g), float(values[k])) for k, g in enumerate(col) if not np.isnan(g)]


def _check(pairs, what):
    assert pairs, what
    bad = [(k + 1, g, r) for k, g, r in pairs
           if not (abs(r - g) <= TOL * abs(g) if g else r == 0.0)]
    assert bad == [], f"{what}: (row, golden, run) outside {TOL:.0%}: {bad}"


@pytest.mark.parametrize("column,key", [
    ("slip_velocity_outer_m_s", "slip_o"), ("slip_velocity_inner_m_s", "slip_i"),
    ("trac_coeff_outer", "kappa_o"), ("trac_coeff_inner", "kappa_i")])
def test_re_traction_columns(golden, run, column, key):
    _check(_pairs(golden, "re_traction", column, run[0][key]), column)


@pytest.mark.parametrize("column,key", [("contact_loss_outer_W", "power_o"), ("contact_loss_inner_W", "power_i")])
def test_contact_losses(golden, run, column, key):
    _check(_pairs(golden, "re_motion", column, run[0][key]), column)


def test_slice_traction_loads_roller_1(golden, run):
    """Section 1a: inner column in N/m, inner contact frame (axis reversed, same slice
    order as the engine's since the contact is symmetric); the outer column of the report
    is N/m x D/2 (as its normal load column, tests/test_run_golden.py)."""
    s = run[1]
    _check(_pairs(golden, "slices_1", "trac_load_inner_N_m", s["t_i"][0][::-1]), "inner trac load")
    _check(_pairs(golden, "slices_1", "trac_load_outer_N_m", s["t_o"][0] * 0.5 * D), "outer trac load x D/2")


def test_printed_coefficient_is_kappa_of_the_printed_slip(run):
    coef = traction_fit(0.0, 0.1, 0.08, 0.2)
    r = run[0]
    for side in "oi":
        expect = np.ravel(traction_eval(coef, np.asarray(r["slip_" + side])))
        assert np.allclose(r["kappa_" + side], expect, rtol=1e-12, atol=0.0)


def test_energy_balance(run):
    """Total contact power = sum of the contact losses = sum over slices of w t u
    (t u = kappa |u| q >= 0 slice by slice)."""
    r, s, summ = run
    assert summ["contact_power"] == pytest.approx(r["power_o"].sum() + r["power_i"].sum(), rel=1e-13)
    for side in "oi":
        tu = s["t_" + side] * s["u_" + side]
        assert (tu >= 0.0).all()
        assert np.allclose((s["w_" + side] * tu).sum(axis=1), r["power_" + side], rtol=1e-12, atol=1e-300)


def test_land_rolls_and_tangential_force(run):
    """Rolling start: slip and traction 0 on the land; the cage would have to carry the net
    tangential traction (the report's roller 1: outer 8.48 N, inner 5.48 N)."""
    r, s, _ = run
    assert (s["u_o"][0][4:8] == 0.0).all() and (s["t_i"][0][3:9] == 0.0).all()
    assert np.allclose(r["tangential_force"], -(r["force_o"] + r["force_i"]), rtol=1e-13)


def test_spin_from_moment_balance():
    """SPIN_EQUILIBRIUM: each roller's traction moment about its axis vanishes (relative
    to the gross moment sum w D/2 |t| of both races), and recomputed from the slices with
    rho = D/2 - p(x)."""
    r, s, _ = roller_step0_tribology(DECK, spin_method=SPIN_EQUILIBRIUM)
    scale = 0.5 * D * ((s["w_o"] * np.abs(s["t_o"])).sum(axis=1) + (s["w_i"] * np.abs(s["t_i"])).sum(axis=1))
    assert (scale > 0.0).all()
    assert (np.abs(r["moment_residual"]) <= 1e-9 * scale).all()

    def drop(x):
        ax = np.abs(x)
        return np.where(ax > 1.0e-3, (ax**2 - 1.0e-6) / (2 * 0.25), 0.0)

    m = (-(s["w_o"] * (0.5 * D - drop(s["x_o"])) * s["t_o"]).sum(axis=1)
         + (s["w_i"] * (0.5 * D - drop(s["x_i"])) * s["t_i"]).sum(axis=1))
    assert (np.abs(m) <= 1e-6 * scale).all()
    # the balance spins the rollers up (the rolling start's tractions both drive them)
    assert (r["spin"] < roller_step0_tribology(DECK)[0]["spin"]).all()


@pytest.mark.xfail(strict=True, reason=(
    "Total power loss 69.21 W includes the cage: engine contact losses 1.099 W (report's "
    "printed contact losses agree within 0.2 %), the report's two land losses 2 x 0.6903 W, "
    "and 66.74 W at one pocket contact (roller 3, 15.16 N, mu 0.05, sliding 88.0 m/s; "
    "test_report_cage_row_is_one_pocket_and_two_land_contacts).  What sets the 15.16 N and "
    "the 0.2052 N land forces at zero geometric interaction is not identified, so pocket and "
    "land forces are not modelled: total is NaN."))
def test_total_power_loss(golden):
    r, _, summ = roller_step0_tribology(DECK)
    g = 69.21
    assert abs(summ["power_loss"] - g) <= TOL * g


def test_report_cage_row_is_one_pocket_and_two_land_contacts(golden, run):
    """Report-internal evidence for the cage at step 0 (docs/tribology.md, "Power balance and
    the cage"): the printed cage row (section 3) and total power are one pocket contact on
    roller 3 (90 deg; its wall at -D/2 in z from the roller centre, the engine's roller 3 end
    2 at zero gap) plus the two printed land contacts at the top (Con Angle 0), all with the
    deck's cage friction 0.05 (Rec 10.5.1B/10.5.2B):
    * pocket normal force F_n = -(F_z + 2 F_land) = 15.16 N;
    * F_y = -mu F_n + 2 mu F_land (friction along the roller surface and the cage surface);
    * M_x about the cage centre (0, 0, e) from those forces at the roller 3 contact
      (y = -(R_c + Pos Z), z = -D/2) and the land contacts (z = cage OD/2);
    * M_z / M_y = mu (the pocket contact's friction and normal force at one axial offset);
    * land loss = mu F_land x sliding omega_c (OD/2 + e): the cage surface plus the whirl of
      its centre at radius e;
    * pocket loss = mu F_n x sliding (|omega_roller| + omega_c) D/2 = 88.0 m/s (the printed
      roller angular velocity is inertial, about -x; relative to the cage it adds omega_c),
      and with the contact losses it closes the printed total;
    * the cage wear rate of section 4 is Archard's law over the same two kinds of contact."""
    rpm = np.pi / 30
    mu, e, od, id_, d = 0.05, 5.0e-5, 0.045, 0.040, D
    loads, land = golden.table("loads").loc["Cage"], golden.table("race_cage")
    f_land = float(land["force_N"].iloc[0])
    assert float(land["force_N"].iloc[1]) == f_land
    f_n = -(loads.force_z_N + 2 * f_land)
    assert f_n == pytest.approx(15.16, abs=0.01)
    # F_y: printed -0.7374 (4 digits); F_z rounding (+-0.005 N) moves it by mu x 0.005
    assert abs(-mu * f_n + 2 * mu * f_land - loads.force_y_N) <= 5e-5 + mu * 5e-3
    pos_z = float(golden.table("re_cage").loc[(3, 1), "contact_pos_z_m"])
    y_c, z_c = -((od + id_) / 4 + pos_z), -d / 2 - e
    m_x = y_c * (-f_n) - z_c * (-mu * f_n) - (od / 2) * (2 * mu * f_land)
    assert abs(m_x - loads.moment_x_Nm) <= 5e-5 + 0.0215 * 5e-3
    assert loads.moment_z_Nm / loads.moment_y_Nm == pytest.approx(mu, rel=1e-3)
    omega_c = golden.table("bodies").loc["Cage", "ang_vel_amplitude_rpm"] * rpm
    land_loss = mu * f_land * omega_c * (od / 2 + e)
    assert land_loss == pytest.approx(float(land["contact_loss_W"].iloc[1]), abs=5e-5)
    omega_r = golden.table("re_motion")["ang_vel_amplitude_rpm"].iloc[2] * rpm
    pocket_loss = mu * f_n * (omega_r + omega_c) * d / 2
    assert pocket_loss == pytest.approx(66.74, abs=0.01)
    # contact losses: the printed ones, roller 1 inner (lost in the print) from the engine
    m = golden.table("re_motion")
    printed = np.nansum(m["contact_loss_outer_W"]) + np.nansum(m["contact_loss_inner_W"])
    contact = printed + float(run[0]["power_i"][0])
    total = contact + 2 * land_loss + pocket_loss
    # print rounding: F_z +-0.005 N (x mu x 88 m/s = 0.022 W), the total +-0.005 W
    assert abs(total - golden.table("performance")["total_power_loss_W"].iloc[0]) <= 0.03
    # the cage wear (section 4): Archard over the same contacts, cage steel k 5E-4, RC 20
    # (echo; H = RC x 9.80665E+07 Pa, docs/tribology.md "Wear rates")
    sliding = f_n * (omega_r + omega_c) * d / 2 + 2 * f_land * omega_c * (od / 2 + e)
    wear = 5e-4 / (20 * 9.80665e7) * sliding
    assert wear == pytest.approx(golden.table("summary")["cage_wear_rate_m3_s"].iloc[0], rel=2e-3)


def test_report_cage_accelerations_follow_its_cage_row(golden):
    """Section 3's cage accelerations from the same row (report-internal): the mass centre
    acceleration is F/m plus gravity (Rec 11: -9.81 m/s**2 along z), and the printed
    angular acceleration, labelled rpm/s, is M/I in rad/s**2 times the length scale
    L = 4e-3 m of the echo (Euler's equations without gyroscopic terms: the cage spins about
    its symmetry axis x, I_y = I_z).  The same factor L appears in the outer 'Nor Load'
    column of section 1a (test_run_golden.py): ADORE prints these two with the length
    scale where the unit needs none.  Inertias from the echo."""
    from pyadore.printout import read_print

    echo = read_print(ROOT / "golden" / "appendix_d_roller.prt").echo
    mass = echo["inertial_parameters.cage[1]"]
    inertia = [echo[f"inertial_parameters.cage[{i}]"] for i in (2, 3, 4)]
    length = echo["scale_factors_and_output_controls.length_m"]
    assert (mass, length) == (0.0158251, 0.004)
    loads, acc = golden.table("loads").loc["Cage"], golden.table("accelerations").loc["Cage"]
    force = [loads.force_x_N, loads.force_y_N, loads.force_z_N]
    for f, g, a in zip(force, (0.0, 0.0, -9.81), (acc.acc_x_m_s2, acc.acc_y_m_s2, acc.acc_z_m_s2)):
        assert f / mass + g == pytest.approx(a, rel=1e-3, abs=1e-9)
    moment = [loads.moment_x_Nm, loads.moment_y_Nm, loads.moment_z_Nm]
    printed = [acc.ang_acc_x_rpm_s, acc.ang_acc_y_rpm_s, acc.ang_acc_z_rpm_s]
    for m, i, a in zip(moment, inertia, printed):
        assert m / i * length == pytest.approx(a, rel=1e-3)
        assert abs(m / i * 30 / np.pi / a) > 1e3          # not rpm/s: that is 2.4e3 x larger


# --- contact temperature rise (report 2.7-2.8, eqs 35-36) ----------------------------------
# The engine applies the ball's flash model to each line contact as the ellipse the print
# reports for it (major half width = half contact length, minor = mean slice half width,
# pressure = printed contact stress, eq 36's 1/(pi a b)), one strip per slice carrying the
# slice's heat factor kappa |u| (eq 29).  Nothing is fitted; docs/tribology.md.

def test_contact_temperature_rise_inner(golden, run):
    """Rollers 1, 2, 8: +2.2 %, -1.4 %; rollers 3-7 are out of contact (0 as printed)."""
    _check(_pairs(golden, "re_thermal", "contact_temp_rise_inner_K", run[0]["temp_rise_i"]), "inner rise")


def test_contact_temperature_rise_outer_loaded_rollers(golden, run):
    """Rollers 1, 2 and 8 (the loaded zone): +0.4 %, +1.3 %."""
    pairs = [p for p in _pairs(golden, "re_thermal", "contact_temp_rise_outer_K", run[0]["temp_rise_o"])
             if p[0] in (0, 1, 7)]
    assert len(pairs) == 3
    _check(pairs, "outer rise, loaded rollers")


@pytest.mark.xfail(strict=True, reason=(
    "rollers 3-7 (centrifugal load only, 245 N): 8.005e-4 K against the printed 8.495e-4 K "
    "(-5.8 %); the loaded rollers are within 1.4 %.  Not a quadrature error (converged in the "
    "points per strip); ADORE's strip grid for the short, lightly loaded contact is not given"))
def test_contact_temperature_rise_outer_all_rollers(golden, run):
    _check(_pairs(golden, "re_thermal", "contact_temp_rise_outer_K", run[0]["temp_rise_o"]), "outer rise")


@pytest.fixture(scope="module")
def printed(tmp_path_factory):
    """Step 0 of the engine's own print of the Appendix D deck."""
    out = tmp_path_factory.mktemp("roller_print") / "d.prt"
    subprocess.run([sys.executable, "-m", "pyadore", "run", str(DECK), "-o", str(out)], check=True,
                   capture_output=True)
    return read_print(out).steps[0]


def test_contact_temperature_is_the_wall_temperature(golden, printed):
    """Contact Temp at step 0 = the initial roller/race temperatures (294 K, Rec 2.7): the
    rise is not fed back before the thermal model runs."""
    for side in ("outer", "inner"):
        col = f"contact_temp_{side}_K"
        assert printed.table("re_thermal")[col].to_numpy(dtype=float) == pytest.approx(
            golden.table("re_thermal")[col].to_numpy(dtype=float), abs=0.05)


# --- section 3: race loads with the slice tractions ---------------------------------------

def _load(step, body, column):
    return float(step.table("loads").loc[body, column])


@pytest.mark.parametrize("body,column", [("Int ORace", "force_y_N"), ("Int ORace", "moment_x_Nm"),
                                         ("Int IRace", "moment_x_Nm"), ("Ext ORace", "force_y_N"),
                                         ("Ext ORace", "moment_x_Nm"), ("Ext IRace", "moment_x_Nm")])
def test_race_loads_carry_the_slice_tractions(golden, printed, body, column):
    """The y force and the moment about the bearing axis of the rollers on each race are
    their net slice tractions along the orbit direction (normal loads give none): outer
    Fy -13.74 vs -13.76 N, Mx 0.5633 vs 0.5640 N m, inner Mx -0.1741 vs -0.1742 N m."""
    assert _load(printed, body, column) == pytest.approx(_load(golden, body, column), rel=0.01)


@pytest.mark.xfail(strict=True, reason=(
    "inner race Fy 8.637 N against the printed 8.763 N (-1.4 %, outside the 1 % of section 3); "
    "the same slice tractions give the outer Fy and both moments within 0.15 %.  The report's "
    "roller 1 also touches its cage pocket (not modelled), which may shift its inner traction"))
def test_inner_race_traction_force_y(golden, printed):
    assert _load(printed, "Int IRace", "force_y_N") == pytest.approx(_load(golden, "Int IRace", "force_y_N"),
                                                                     rel=0.01)


def test_race_traction_loads_balance_the_roller_tractions(run, printed):
    """Independent of the print's convention: the tractions the rollers put on the two races
    sum (over rollers and races) to minus the net tangential force the cage would have to
    take, and the moment about the axis of each race is its raceway radius times the sum of
    the roller forces on it (all along the orbit direction)."""
    r = run[0]
    assert r["tangential_force"].sum() == pytest.approx(-(r["force_o"].sum() + r["force_i"].sum()), rel=1e-12)
    mx_o, mx_i = (_load(printed, b, "moment_x_Nm") for b in ("Int ORace", "Int IRace"))
    # the raceway radii bracket the pitch radius by about D/2
    assert mx_o / r["force_o"].sum() == pytest.approx(0.043 / 2 + D / 2, rel=2e-3)
    assert mx_i / r["force_i"].sum() == pytest.approx(0.043 / 2 - D / 2, rel=2e-3)
