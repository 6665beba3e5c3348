"""Sweep benchmark (`python bench/run_bench.py sweep`): the issue's 32-case step-0 grid of
Appendix C on 1 and on 2 local worker processes, the speedup, and a rerun that must
recompute nothing.  Target: 2 workers at least 1.6x faster than 1 (on 2 free cores)."""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

import pyadore

ROOT = Path(__file__).resolve().parent.parent
DECK = ROOT / "decks" / "appendix_c_ball.inp"
GRID = {"inner_race_speed": [10000, 15000, 20000, 25000], "applied_force_z": [1000, 2000, 3000, 4000],
        "applied_force_x": [3000, 4500]}
SPEEDUP_TARGET = 1.6


def bench_sweep(workers=(1, 2)) -> list[dict]:
    """Time the 32-case grid per worker count; returns rows for bench/results/latest.json."""
    rows, wall = [], {}
    for n in workers:
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp) / "sweep"
            start = time.perf_counter()
            frame = pyadore.sweep(DECK, GRID, folder, steps=0, workers=n, progress=False)
            wall[n] = time.perf_counter() - start
            if len(frame) != 32 or set(frame["status"]) != {"ok"}:
                raise SystemExit(f"sweep bench: expected 32 finished cases, got {frame['status'].value_counts()}")
            events = (folder / "events.log").read_text()
            start = time.perf_counter()
            pyadore.sweep(DECK, GRID, folder, steps=0, workers=n, progress=False)
            rerun = time.perf_counter() - start
            if (folder / "events.log").read_text() != events:
                raise SystemExit("sweep bench: the rerun recomputed cases")
        rows.append({"deck": DECK.name, "case": f"sweep 32 cases, {n} worker(s)", "best_s": wall[n],
                     "median_s": wall[n]})
        rows.append({"deck": DECK.name, "case": f"sweep rerun, {n} worker(s)", "best_s": rerun, "median_s": rerun})
    if 1 in wall and 2 in wall:
        speedup = wall[1] / wall[2]
        verdict = "met" if speedup >= SPEEDUP_TARGET else "NOT met"
        load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
        print(f"sweep: 32 cases, 1 worker {wall[1]:.1f} s, 2 workers {wall[2]:.1f} s: speedup {speedup:.2f}x "
              f"(target >= {SPEEDUP_TARGET}x: {verdict}; {os.cpu_count()} CPUs, load average {load:.1f})")
        rows.append({"deck": DECK.name, "case": "sweep speedup 2 vs 1", "best_s": speedup, "median_s": speedup})
    return rows
