"""The thermal model wired into a ball run (issue #27; docs/thermal.md, "The wiring").

The engine's own test (fortran/tests/test_bearing_system.f90, test_ball_thermal_run) checks
the update schedule at the deck's times, the heat balance at every update (1e-6) and the
load-holding constraint's equilibrium residual through Appendix C's run to 33.5 ms; these
tests check what the user sees: the option, the print and the time history.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import pyadore
from pyadore.printout import read_print

#: Rec 2.5 of Appendix C: heat averaged every 3 ms (field 4), geometry from 30 ms (field 5).
INTERVAL = 3.0e-3
#: The thermal columns of the print (sections 1 and 3); everything else is the dynamics'.
THERMAL_COLUMNS = {
    "re_traction": ("drag_N", "churning_moment_Nm", "net_loss_W"),
    "re_thermal": ("contact_temp_outer_K", "contact_temp_inner_K", "bulk_temp_K", "convec_htc_W_m2K"),
    "performance": ("churning_loss_fraction", "exit_fluid_temp_K", "hsng_bulk_temp_K", "hsng_outer_temp_K",
                    "hsng_inner_temp_K", "shft_bulk_temp_K", "shft_outer_temp_K", "shft_inner_temp_K"),
}


def _listing_free(text: str) -> str:
    """The print without its lines on the thermal model (the listing and the run note)."""
    return "\n".join(x for x in text.splitlines() if "THERMAL MODEL" not in x)


def test_thermal_off_by_default_the_option_and_the_deck_without_times_print_the_same(tmp_path, short_ball_deck):
    """Thermal off: the default and the option give the same print and plot data, byte for
    byte; the deck's own switch (Rec 2.5 field 4 = 0 under thermal="deck") the same plot
    data and every step's printed tables (its echo shows the changed record)."""
    default = pyadore.run(short_ball_deck, out=tmp_path / "default.prt", progress=False)
    off = pyadore.run(short_ball_deck, out=tmp_path / "off.prt", progress=False, thermal="off")
    no_times = pyadore.run(short_ball_deck, out=tmp_path / "deck.prt", progress=False, thermal="deck",
                           overrides={"thermal_time_1": 0.0, "thermal_time_2": 0.0})
    assert "THERMAL MODEL OFF" in default.print_path.read_text()
    assert off.print_path.read_bytes() == default.print_path.read_bytes()
    for other in (off, no_times):
        assert other.history_path.read_bytes() == default.history_path.read_bytes()
    # the deck's echo shows its changed Rec 2.5; every step's tables are the same
    a, b = read_print(default.print_path), read_print(no_times.print_path)
    assert list(a.steps) == list(b.steps)
    for n in a.steps:
        for name, frame in a.steps[n].tables.items():
            assert frame.equals(b.steps[n].tables[name]), (n, name)
    assert "exit_fluid_temp_K" not in default.time_history.columns


def test_thermal_model_changes_nothing_before_its_first_update(tmp_path, short_ball_deck):
    """The short deck ends (1.1 ms) before the first update (3 ms): with the thermal model
    on, every printed value but the thermal columns (drag, churning and their fraction: 0
    instead of NaN, the deck giving no lubricant fraction) is the run's without it, and the
    listing says the model is on."""
    off = pyadore.run(short_ball_deck, out=tmp_path / "off.prt", progress=False)
    on = pyadore.run(short_ball_deck, out=tmp_path / "on.prt", progress=False, thermal="deck")
    assert off.time_history.index[-1] < INTERVAL
    text = on.print_path.read_text()
    assert "THERMAL MODEL ON: HEAT AVERAGED OVER 3.000E-03 S" in text
    assert "GEOMETRY UPDATED FROM 3.000E-02 S WITH THE APPLIED LOAD HELD" in text
    a, b = read_print(off.print_path), read_print(on.print_path)
    assert list(a.steps) == list(b.steps) and len(a.steps) > 2
    for n in list(a.steps)[1:]:
        for name, frame in a.steps[n].tables.items():
            other = b.steps[n].tables[name]
            for column in frame.columns:
                x, y = frame[column], other[column]
                if column in THERMAL_COLUMNS.get(name, ()):
                    if column in ("drag_N", "churning_moment_Nm", "net_loss_W", "churning_loss_fraction"):
                        assert x.isna().all() and (y == 0.0).all(), (n, name, column)
                    continue
                assert x.equals(y), (n, name, column)
    # the text around the tables too, but for the lines on the thermal model and the thermal
    # columns' values
    assert len(_listing_free(off.print_path.read_text()).splitlines()) == \
        len(_listing_free(on.print_path.read_text()).splitlines())


@pytest.fixture(scope="module")
def geometry_run(tmp_path_factory, ball_deck):
    """Appendix C with temperatures and geometry updated from the first update on (Rec 2.5
    field 5 set to 3 ms for the test), to 7.5 ms: updates at 3 and 6 ms."""
    out = tmp_path_factory.mktemp("thermal") / "geometry.prt"
    return pyadore.run(ball_deck, out=out, progress=False, thermal="geometry", duration=7.5e-3,
                       overrides={"thermal_time_2": INTERVAL})


def test_thermal_run_prints_every_thermal_column(geometry_run):
    """After the first update the print's thermal columns are numbers: each ball's contact
    node and bulk temperatures and HTC, the exit fluid, housing and shaft temperatures; the
    drag, churning moment, net loss and churning loss fraction 0 (no lubricant fraction in
    the deck); the fits and the clearance are the updated geometry's, not step 0's."""
    run = read_print(geometry_run.print_path)
    last = run.steps[max(run.steps)]
    step0 = run.steps[0]
    for name, columns in THERMAL_COLUMNS.items():
        frame = last.table(name)
        for column in columns:
            assert np.isfinite(frame[column].to_numpy(dtype=float)).all(), (name, column)
    perf, perf0 = last.table("performance").iloc[0], step0.table("performance").iloc[0]
    assert perf["churning_loss_fraction"] == 0.0
    assert (last.table("re_traction")["net_loss_W"] == 0.0).all()
    inlet = 323.0
    # heat flows from the bearing to the coolant and to the housing's reference (323 K)
    assert perf["exit_fluid_temp_K"] > inlet and perf["hsng_inner_temp_K"] > perf["hsng_outer_temp_K"] >= inlet
    # the balls' bulk temperatures: in ADORE's march (the default field) each ball's mid point
    # lies below its outer contact by its share of the outer contact's heat, so the balls can
    # sit below the inlet (the report prints ball mid points below the fluid); eq 17 holds:
    # bulk = T0 / 2 + (T1 + T2) / 4 puts it below the mean of the contact nodes
    thermal = last.table("re_thermal")
    contact_mean = 0.5 * (thermal["contact_temp_outer_K"] + thermal["contact_temp_inner_K"])
    assert (thermal["bulk_temp_K"] < contact_mean).all()
    assert perf["internal_clearance_m"] != perf0["internal_clearance_m"]
    assert perf["outer_race_fit_m"] != perf0["outer_race_fit_m"]
    # section 3's bulk temperatures are the field's (the condition the dynamics runs in)
    acc = last.table("accelerations")
    assert acc.loc["IRace", "bulk_temp_K"] > inlet and acc.loc["ORace", "bulk_temp_K"] > inlet


def test_thermal_run_history_steps_at_the_updates(geometry_run):
    """The time history's exit fluid and bulk temperatures are constant between updates
    and change at them (figures 4 and 5 draw steps); the exit fluid is unknown (NaN) before
    the first update and equals the print's at the last step."""
    h = geometry_run.time_history
    t = h.index.to_numpy()
    before, first, second = t < INTERVAL * (1 - 1e-9), (t >= INTERVAL * (1 - 1e-9)) & (t < 2 * INTERVAL * (1 - 1e-9)), \
        t >= 2 * INTERVAL * (1 - 1e-9)
    assert before.any() and first.any() and second.any()
    exit_ = h["exit_fluid_temp_K"].to_numpy()
    assert np.isnan(exit_[before]).all()
    for span in (first, second):
        assert np.isfinite(exit_[span]).all() and np.ptp(exit_[span]) == 0.0
        for body in ("re", "outer_race", "inner_race", "housing", "shaft", "cage"):
            assert np.ptp(h[f"bulk_temp_{body}_K"].to_numpy()[span]) == 0.0, body
    assert exit_[first][0] != exit_[second][0]
    assert (h["bulk_temp_inner_race_K"].to_numpy()[before] == 323.0).all()
    printed = read_print(geometry_run.print_path)
    last = printed.steps[max(printed.steps)].table("performance").iloc[0]["exit_fluid_temp_K"]
    assert math.isclose(exit_[-1], last, rel_tol=5e-4)
    contact = h["re1_contact_temp_outer_K"].to_numpy()
    assert np.ptp(contact[second]) == 0.0 and contact[second][0] != contact[before][0]

