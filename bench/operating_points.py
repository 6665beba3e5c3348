"""The operating-point grid of issue #28 (not part of `make test`; run by hand or from
`make bench` with a small step count): every example ball deck and Appendix C over shaft
speed {0, 10, 100, 1 000, 10 000, 60 000 rpm} x applied load {1 N, 10 N, 100 N, 1 kN,
10 kN, the static capacity} x inner race fit {-20, 0, +20 um}, each run for STEPS time steps
by the standalone engine.  The load keeps the deck's own direction; the static capacity is
found per deck as ISO 76 defines it for ball bearings: the load (in the deck's direction)
at which the largest contact pressure of the step-0 solution reaches 4 200 MPa (bisection
on step-0 runs).

Each case ends in one of: ran (exit 0), refused by validate (a deck problem naming the
field; counted apart: the goal is none), or failed (the engine's message).  Results:
counts by outcome and by message, written to bench/results/operating_points.json.

    .venv/bin/python bench/operating_points.py [--steps 300] [--workers 2] [--decks a.inp,b.inp]
"""

from __future__ import annotations

import argparse
import collections
import itertools
import json
import os
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
SPEEDS = (0.0, 10.0, 100.0, 1000.0, 10000.0, 60000.0)
LOADS = (1.0, 10.0, 100.0, 1e3, 1e4, "C0")
FITS = (-20e-6, 0.0, 20e-6)
ISO76_BALL_PRESSURE = 4.2e9   # Pa: ISO 76's contact pressure at the static capacity (ball bearings)


def _ball_decks() -> list[Path]:
    from pyadore.deck import read_deck

    decks = [ROOT / "decks" / "appendix_c_ball.inp"]
    for p in sorted((ROOT / "decks" / "examples").glob("*.inp")):
        if read_deck(p).bearing_type == 1:
            decks.append(p)
    return decks


def _variant(base: Path, out: Path, speed: float, load: float, fit: float) -> Path:
    from pyadore.deck import read_deck

    deck = read_deck(base)
    force = np.array([deck.lookup(f"applied_force_{c}") for c in "xyz"], dtype=float)
    force = force / np.linalg.norm(force) * load
    for c, v in zip("xyz", force):
        deck.set("9.1.1", f"applied_force_{c}", float(f"{v:.4E}"))
    deck.set("9.1.2", "inner_race_speed", float(speed))
    deck.set("9.0", "inner_race_fit", float(fit))
    deck.save(out)
    return out


def static_capacity(base: Path, tmp: Path) -> float:
    """ISO 76 static capacity of a ball deck in its load direction (N): the load at which the
    largest step-0 contact pressure reaches 4 200 MPa (at 0 rpm, no fit change)."""
    from pyadore import _core

    def pmax(load: float) -> float:
        path = _variant(base, tmp / "c0.inp", 0.0, load, 0.0)
        balls, _ = _core.ball_step0_from_deck(path)
        return float(np.nanmax(np.concatenate([balls["p_o"], balls["p_i"]])))

    lo, hi = 1.0, 1e3
    while pmax(hi) < ISO76_BALL_PRESSURE:
        lo, hi = hi, hi * 4.0
    for _ in range(30):
        mid = np.sqrt(lo * hi)
        if pmax(mid) < ISO76_BALL_PRESSURE:
            lo = mid
        else:
            hi = mid
    return float(f"{hi:.3E}")


def _case(args) -> dict:
    base, speed, load, fit, steps, exe = args
    from pyadore.deck import check_deck

    with tempfile.TemporaryDirectory() as tmp:
        path = _variant(Path(base), Path(tmp) / "case.inp", speed, load, fit)
        _, problems = check_deck(path)
        row = {"deck": Path(base).name, "speed_rpm": speed, "load_N": load, "fit_m": fit}
        if problems:
            return row | {"outcome": "refused", "message": problems[0].format().split("\n")[0]}
        start = time.perf_counter()
        proc = subprocess.run([exe, str(path), str(Path(tmp) / "case.prt"), "--steps", str(steps)],
                              capture_output=True, text=True)
        row["seconds"] = round(time.perf_counter() - start, 3)
        if proc.returncode == 0:
            return row | {"outcome": "ran"}
        message = proc.stderr.strip().split("\n")[0].replace(str(path) + ": ", "")
        return row | {"outcome": "failed", "message": message}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--decks", default="", help="comma-separated decks (default: every ball deck)")
    ap.add_argument("--exe", default=os.environ.get("ADORE_EXE", str(ROOT / "build" / "native" / "adore")))
    a = ap.parse_args()
    decks = [Path(d) for d in a.decks.split(",")] if a.decks else _ball_decks()
    cases = []
    capacities = {}
    with tempfile.TemporaryDirectory() as tmp:
        for d in decks:
            capacities[d.name] = static_capacity(d, Path(tmp))
    for d in decks:
        for s, L, f in itertools.product(SPEEDS, LOADS, FITS):
            cases.append((str(d), s, capacities[d.name] if L == "C0" else L, f, a.steps, a.exe))
    start = time.perf_counter()
    with ProcessPoolExecutor(max_workers=a.workers) as pool:
        rows = list(pool.map(_case, cases, chunksize=4))
    counts = collections.Counter(r["outcome"] for r in rows)
    messages = collections.Counter(r["message"][:120] for r in rows if r["outcome"] != "ran")
    summary = {"steps": a.steps, "cases": len(rows), "outcomes": dict(counts),
               "static_capacity_N": capacities, "wall_s": round(time.perf_counter() - start, 1),
               "messages": messages.most_common(), "failures": [r for r in rows if r["outcome"] != "ran"]}
    out = ROOT / "bench" / "results" / "operating_points.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(summary, indent=1) + "\n")
    print(f"{len(rows)} cases, {a.steps} steps: {dict(counts)} ({summary['wall_s']} s)")
    for m, n in messages.most_common(12):
        print(f"  {n:4d}  {m}")
    print(f"static capacities (ISO 76, 4200 MPa): {capacities}")
    print(f"written: {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
