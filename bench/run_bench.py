"""Benchmarks (run by `make bench`): wall time of whole runs of the appendix decks.

Speed targets live here, never in the test suite.  Each case is run a few times;
the best and median wall times are printed, for the standalone executable and the
f2py path.  Results are printed, and written to bench/results/latest.json.
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
    if "sweep" in names:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        from sweep_bench import bench_sweep

        rows += bench_sweep()
    print(f"{'deck':28s} {'case':30s} {'best (s)':>10s} {'median (s)':>11s}")
    for row in rows:
        print(f"{row['deck']:28s} {row['case']:30s} {row['best_s']:10.4f} {row['median_s']:11.4f}")
    results = ROOT / "bench" / "results"
    results.mkdir(exist_ok=True)
    (results / "latest.json").write_text(json.dumps({"python": sys.version, "rows": rows}, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
