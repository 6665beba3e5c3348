"""Thermal transients through a run (issue #27 item 5; docs/thermal.md, "Thermal transients").

The engine's test (fortran/tests/test_thermal_transient.f90) checks the lumps against their
closed form, the steady limit and the energy balance; this one checks the run option as the
user sees it: Appendix C to just past its first update (3 ms), temperatures updated, with and
without transients.  Up to the first update both runs are the same run (the same heat), so
at the update each body's bulk temperature with transients is the initial one plus the
steady rise times 1 - exp(-dt / tau), tau = C / G of the body; for a ring (housing, hollow
shaft) tau = rho c (D1^2 - D2^2) ln(D1 / D2) / (8 k), its width cancelling.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import pyadore
from pyadore.printout import read_print

#: Rec 2.5 of Appendix C: heat averaged every 3 ms.
INTERVAL = 3.0e-3
#: Appendix C's materials (its echo: no Rec 8, steel; the echo prints no heat capacity for
#: the shaft and the housing: the same steel's 470 J/(kg K), docs/thermal.md)
RHO, C_P, K = 7750.0, 470.0, 43.0


@pytest.fixture(scope="module")
def pair(tmp_path_factory, ball_deck):
    out = tmp_path_factory.mktemp("transient")
    kw = dict(progress=False, thermal="temperatures", duration=3.5e-3)
    steady = pyadore.run(ball_deck, out=out / "steady.prt", **kw)
    transient = pyadore.run(ball_deck, out=out / "transient.prt", thermal_transient=True, **kw)
    return steady, transient


def _ring_tau(d1: float, d2: float) -> float:
    return RHO * C_P * (d1 * d1 - d2 * d2) * math.log(d1 / d2) / (8.0 * K)


def test_transient_bodies_lag_the_steady_field_by_their_time_constants(pair):
    steady, transient = pair
    assert "TRANSIENTS WITH LUMPED HEAT CAPACITIES" in transient.print_path.read_text()
    assert "TRANSIENTS" not in steady.print_path.read_text()
    echo = read_print(transient.print_path).echo
    g = {k.split(".")[-1]: float(v) for k, v in echo.items() if k.startswith("bearing_geometry.")
         and k.endswith("_m")}
    taus = {"housing": _ring_tau(g["housing_od_m"], g["bearing_od_m"]),
            "shaft": _ring_tau(g["shaft_od_m"], g["shaft_id_m"])}
    a, b = steady.time_history, transient.time_history
    ta, tb = a.index.to_numpy(), b.index.to_numpy()
    before, after = ta < INTERVAL * (1 - 1e-9), ta >= INTERVAL * (1 - 1e-9)
    after_b = tb >= INTERVAL * (1 - 1e-9)
    assert before.any() and after.any() and after_b.any()
    for body, tau in taus.items():
        col = f"bulk_temp_{body}_K"
        rise_steady = a[col].to_numpy()[after][-1] - 323.0
        rise = b[col].to_numpy()[after_b][-1] - 323.0
        assert abs(rise_steady) > 1.0   # (the shaft falls: heat leaves at its bore, docs/thermal.md)
        # the echo's five digits bound tau's accuracy
        assert rise == pytest.approx(rise_steady * -math.expm1(-INTERVAL / tau), rel=1e-4), body
        assert 10.0 < tau < 200.0
    # every body and the coolant: between the initial temperature and the steady one
    for col in ("bulk_temp_re_K", "bulk_temp_cage_K", "bulk_temp_outer_race_K", "bulk_temp_inner_race_K",
                "exit_fluid_temp_K"):
        x, y = a[col].to_numpy()[after][-1], b[col].to_numpy()[after_b][-1]
        assert min(323.0, x) < y < max(323.0, x), col
    # before the update the runs are the same run
    assert np.array_equal(ta[before], tb[tb < INTERVAL * (1 - 1e-9)])
    for col in ("total_power_loss_W", "re1_contact_loss_inner_W"):
        assert np.array_equal(a[col].to_numpy()[before], b[col].to_numpy()[: before.sum()])
