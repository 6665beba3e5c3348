"""Sweep benchmark (`python bench/run_bench.py sweep`): the issue's 32-case step-0 grid of
Appendix C on 1 and on 2 local worker processes, the speedup, and a rerun that must
recompute nothing; then 64 fast roller cases for the sweep's own cost per case.

Target (issue #29): 2 workers at least 1.8x faster than 1, on 2 free cores.  On a shared machine
the wall-time speedup also measures the other load, so the bench prints how busy the
workers were: the sum of the cases' own run times over (workers x wall time).  Near 100 %
the pool loses nothing to its own overhead and the speedup is what the free cores allow.
"""

from __future__ import annotations

import json
import os
import tempfile
import time
from pathlib import Path

import pyadore

ROOT = Path(__file__).resolve().parent.parent
BALL = ROOT / "decks" / "appendix_c_ball.inp"
ROLLER = ROOT / "decks" / "appendix_d_roller.inp"
GRID = {"inner_race_speed": [10000, 15000, 20000, 25000], "applied_force_z": [1000, 2000, 3000, 4000],
        "applied_force_x": [3000, 4500]}
ROLLER_GRID = {"inner_race_speed": [50000 + 500 * k for k in range(16)], "applied_force_z": [500, 750, 1000, 1250]}
SPEEDUP_TARGET = 1.8


def _one(deck: Path, grid: dict, workers) -> dict:
    """One sweep into a fresh folder, then its rerun; wall times, case time sum, busy fraction.
    workers: a number (the sweep starts its own processes) or a warm WorkerPool."""
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp) / "sweep"
        start = time.perf_counter()
        frame = pyadore.sweep(deck, grid, folder, steps=0, workers=workers, progress=False)
        wall = time.perf_counter() - start
        if set(frame["status"]) != {"ok"}:
            raise SystemExit(f"sweep bench: not every case finished: {frame['status'].value_counts().to_dict()}")
        events = (folder / "events.log").read_text()
        start = time.perf_counter()
        pyadore.sweep(deck, grid, folder, steps=0, workers=workers, progress=False)
        rerun = time.perf_counter() - start
        if (folder / "events.log").read_text() != events:
            raise SystemExit("sweep bench: the rerun recomputed cases")
        cases = json.loads((folder / "manifest.json").read_text())["cases"]
    busy = sum(c["duration_s"] for c in cases)
    n = workers if isinstance(workers, int) else workers.size
    return {"n": len(frame), "wall": wall, "rerun": rerun, "busy": busy, "fraction": busy / (n * wall)}


def bench_warm_pool(workers=(1, 2), repeats: int = 3) -> list[dict]:
    """The 32-case sweep on WorkerPools already booted (a sweep of one case each first): the speedup
    without the workers' start-up, for studies that run several sweeps in one process.  The pools
    stay open side by side (an idle worker waits on its pipe) and their sweeps alternate, best of
    ``repeats`` each, so a drift of the machine's speed does not favour one worker count."""
    from contextlib import ExitStack

    from pyadore.sweeps import WorkerPool

    best: dict[int, float] = {}
    with ExitStack() as stack:
        pools = {n: stack.enter_context(WorkerPool(n)) for n in workers}
        for n, pool in pools.items():
            with tempfile.TemporaryDirectory() as tmp:  # boots the processes
                pyadore.sweep(BALL, {"inner_race_speed": [20000 + k for k in range(n)]}, Path(tmp) / "w",
                              steps=0, workers=pool, progress=False)
        for _ in range(repeats):
            for n, pool in pools.items():
                wall = _one(BALL, GRID, pool)["wall"]
                best[n] = min(best.get(n, wall), wall)
    rows = [{"deck": BALL.name, "case": f"sweep 32 cases, warm pool of {n}", "best_s": t, "median_s": t}
            for n, t in best.items()]
    if 1 in best and 2 in best:
        speedup = best[1] / best[2]
        verdict = "met" if speedup >= SPEEDUP_TARGET else "NOT met"
        print(f"sweep on a warm WorkerPool: 32 ball cases, 1 worker {best[1]:.2f} s, 2 workers {best[2]:.2f} s "
              f"(best of {repeats}, alternating): speedup {speedup:.2f}x (target >= {SPEEDUP_TARGET}x: {verdict})")
        rows.append({"deck": BALL.name, "case": "sweep speedup 2 vs 1, warm pool", "best_s": speedup,
                     "median_s": speedup})
    return rows


def bench_sweep(workers=(1, 2), repeats: int = 2) -> list[dict]:
    """Time the sweeps per worker count, print the speedup; returns rows for bench/results/latest.json.
    The worker counts alternate and each keeps its best of ``repeats`` sweeps: the first sweep of the
    process pays the client's one-time imports (pandas for the summary, about 0.6 s), which would
    otherwise count against whichever worker count ran first."""
    rows, ball = [], {}
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    for deck, grid, label in ((BALL, GRID, "ball"), (ROLLER, ROLLER_GRID, "roller")):
        best: dict[int, dict] = {}
        for _ in range(repeats):
            for n in workers:
                r = _one(deck, grid, n)
                if n not in best or r["wall"] < best[n]["wall"]:
                    best[n] = r
        for n in workers:
            r = best[n]
            if label == "ball":
                ball[n] = r
            print(f"sweep {label}: {r['n']} cases on {n} worker(s): {r['wall']:.2f} s wall (best of {repeats}), "
                  f"cases' own time {r['busy']:.2f} s, workers busy {100 * r['fraction']:.0f} %, sweep cost "
                  f"{1000 * (n * r['wall'] - r['busy']) / r['n']:.1f} ms a case; rerun {r['rerun']:.3f} s")
            rows.append({"deck": deck.name, "case": f"sweep {r['n']} cases, {n} worker(s)", "best_s": r["wall"],
                         "median_s": r["wall"]})
            rows.append({"deck": deck.name, "case": f"sweep rerun, {n} worker(s)", "best_s": r["rerun"],
                         "median_s": r["rerun"]})
    if 1 in ball and 2 in ball:
        speedup = ball[1]["wall"] / ball[2]["wall"]
        verdict = "met" if speedup >= SPEEDUP_TARGET else "NOT met"
        print(f"sweep: 32 ball cases, 1 worker {ball[1]['wall']:.2f} s, 2 workers {ball[2]['wall']:.2f} s: speedup "
              f"{speedup:.2f}x (target >= {SPEEDUP_TARGET}x: {verdict}; {os.cpu_count()} CPUs, load average "
              f"{load:.1f} before the bench)")
        rows.append({"deck": BALL.name, "case": "sweep speedup 2 vs 1", "best_s": speedup, "median_s": speedup})
    return rows + bench_warm_pool(workers)
