"""Benchmarks (run by `make bench`): wall time of whole runs of the appendix decks, and the
CPU time of one EHD contact evaluation.

Speed targets live here, never in the test suite.  Each case is run a few times;
the best and median wall times are printed, for the standalone executable and the
f2py path.  The EHD contact evaluation (force, moment and loss of one ball/race contact,
traction model 3; issue #16) is timed inside the engine over many evaluations, for every
race contact of the Appendix C step 0, by the fast and the reference quadrature, and by the
fast one over those contacts with slide/roll, spin/roll x 0.5 .. x 2 and loads x 0.5, x 2
(tests/test_ehd_fast.py's range of the 1e-4 accuracy test): its rows give the mean over the
contacts (best_s) and the slowest contact (median_s column: the largest), in seconds, and
us_per_contact.  Results are printed, and written to
bench/results/latest.json.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pyadore
from pyadore import _core

ROOT = Path(__file__).resolve().parent.parent
DECKS = [ROOT / "decks" / "appendix_c_ball.inp", ROOT / "decks" / "appendix_d_roller.inp"]
REPEAT = 5


def _time(fn, repeat=REPEAT):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times), statistics.median(times)


def _ehd_contact_rows(deck):
    """Microseconds per EHD contact evaluation over the race contacts of deck's step 0."""
    import math

    balls, _ = _core.ball_step0_from_deck(deck)
    lub = _core.lubricant(1, 323.0)
    rheo = (lub["eta_t"], lub["alpha_t"], lub["beta_t"], lub["conductivity"])
    inner_speed = 20000 * math.pi / 30          # Appendix C: inner race at 20000 rpm, outer fixed
    contacts = []
    for k in range(len(balls["r"])):
        om = (balls["spin_speed"][k] * math.cos(balls["pitch"][k]), balls["spin_speed"][k] * math.sin(balls["pitch"][k]))
        for tag, side, w_race in (("o", 1, 0.0), ("i", -1, inner_speed)):
            contacts.append(dict(side=side, alpha=balls[f"alpha_{tag}"][k], rho=0.01905 / 2, r_b=balls["r"][k],
                                 omega=om, race_speed=w_race - balls["orbital_speed"][k], a=balls[f"a_{tag}"][k],
                                 load=balls[f"q_{tag}"][k], rheology=rheo,
                                 film=balls[f"film_{tag}"][k] * balls[f"thermal_factor_{tag}"][k],
                                 b=balls[f"b_{tag}"][k]))
    # the accuracy test's scaling of slips and loads (imported, not copied)
    sys.path.insert(0, str(ROOT / "tests"))
    from itertools import product

    from test_ehd_fast import _scaled

    scaled = [_scaled(c, *k) for c, k in product(contacts, product([0.5, 1, 2], [0.5, 1, 2], [0.5, 2]))]
    rows = []
    for label, method, cases, repeat, tries in (("fast", "fast", contacts, 20000, 3),
                                                ("reference", "reference", contacts, 5000, 3),
                                                ("fast, scaled", "fast", scaled, 2000, 2)):
        us = [min(_core.ehd_contact_microseconds(**c, method=method, repeat=repeat) for _ in range(tries))
              for c in cases]
        rows.append({"deck": deck.name, "case": f"EHD contact, {label}", "best_s": statistics.mean(us) * 1e-6,
                     "median_s": max(us) * 1e-6, "us_per_contact": statistics.mean(us)})
    return rows


def main() -> int:
    """`run_bench.py [runs] [sweep]`: the runs of the appendix decks and/or the sweep bench [default: both]."""
    names = sys.argv[1:] or ["runs", "sweep"]
    exe = os.environ.get("ADORE_EXE", str(ROOT / "build" / "native" / "adore"))
    rows = []
    decks = DECKS if "runs" in names else []
    with tempfile.TemporaryDirectory() as tmp:
        for deck in decks:
            out = Path(tmp) / (deck.stem + ".prt")
            for label, fn in [
                ("step 0, f2py", lambda: pyadore.run(deck, steps=0, out=out)),
                ("step 0, executable", lambda: subprocess.run([exe, str(deck), str(out), "--steps", "0"],
                                                              check=True, capture_output=True)),
            ]:
                best, median = _time(fn)
                rows.append({"deck": deck.name, "case": label, "best_s": best, "median_s": median})
        # the physics alone: Appendix C deck -> model -> mounting -> quasi-static start -> life
        for deck in decks[:1]:
            best, median = _time(lambda: _core.ball_step0_from_deck(deck), repeat=20)
            rows.append({"deck": deck.name, "case": "step-0 solve (ball)", "best_s": best, "median_s": median})
            rows += _ehd_contact_rows(deck)
    if "sweep" in names:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        from sweep_bench import bench_sweep

        rows += bench_sweep()
    print(f"{'deck':28s} {'case':30s} {'best (s)':>10s} {'median (s)':>11s}")
    for row in rows:
        if "us_per_contact" in row:
            print(f"{row['deck']:28s} {row['case']:30s} {row['us_per_contact']:7.2f} us mean, "
                  f"{row['median_s'] * 1e6:.2f} us slowest contact")
            continue
        print(f"{row['deck']:28s} {row['case']:30s} {row['best_s']:10.4f} {row['median_s']:11.4f}")
    results = ROOT / "bench" / "results"
    results.mkdir(exist_ok=True)
    (results / "latest.json").write_text(json.dumps({"python": sys.version, "rows": rows}, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
