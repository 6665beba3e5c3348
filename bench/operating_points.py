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
counts by outcome and by message, written to bench/results/NAME.json (NAME: --out).

    .venv/bin/python bench/operating_points.py [--steps 300] [--workers 2] [--decks a.inp,b.inp]
        [--speeds 0,10] [--loads 1,C0] [--fits 0] [--out NAME] [--rerun a.csv[,b.csv]] [--sample N]
        [--extra '--traction-table t.txt'] [--set 2.1:step_min=5e-4] [--exe other/adore]
    .venv/bin/python bench/operating_points.py --summarize bench/operating_points_grid.csv
    .venv/bin/python bench/operating_points.py --compare bench/operating_points_grid_s16.csv,bench/operating_points_grid.csv
    .venv/bin/python bench/operating_points.py --merge bench/results/NAME.csv --mark s15

Every case is also appended, as it ends, to bench/results/NAME.csv (deck, speed, load, fit,
outcome, a message category, the message, seconds, and for a run that ran the balance line's
revolutions in the window, drive power, dissipation, energy change, drive/dissipation, closure,
the inner race's force residual as a fraction of its load and the number of time steps accepted
at the minimum step with their error above the limit - a run that ran without error control,
not resolved: pyadore.api.parse_forced_steps), so a long grid
run killed part way keeps what it measured.  ``--rerun`` takes the failed cases of one or
more earlier CSVs (e.g. after a fix, or with ``--extra`` engine options / ``--exe`` another
executable to find a cause), ``--sample N`` adds N cases that ran in the first of them (a
fixed random choice: did the fix break what ran?); ``--merge`` writes such a re-run's rows
into bench/operating_points_grid.csv in place of the same cases, marked in its ``rerun``
column, and prints the before -> after transitions; ``--summarize`` prints a CSV's failures by message category,
deck, speed, load and fit; ``--compare`` prints several CSVs side by side (failures, runs with
forced steps by speed and load, closures within 1 % and 10 %, the cases that moved).  The measured grid and its diagnosis re-runs are kept in
bench/operating_points_grid.csv (the last full grid, session 19: the forced-step diagnosis and report
4.4.12's reduced step below the minimum; session 18's final one in bench/operating_points_grid_s18c.csv, its grid
after main's arrowhead border rows in bench/operating_points_grid_s18b.csv;
the same session's on 5bac9b8 in bench/operating_points_grid_s18a.csv, session 16's in
bench/operating_points_grid_s16.csv, session 15's in bench/operating_points_grid_s15.csv, session 14's in bench/operating_points_grid_s14.csv,
session 13's in bench/operating_points_grid_s13.csv,
the one before in bench/operating_points_grid_before.csv) and bench/operating_points_diagnosis.csv
(docs/operating-points.md, "The dynamic grid, all 14 decks").
"""

from __future__ import annotations

import argparse
import collections
import csv
import itertools
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
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


def _variant(base: Path, out: Path, speed: float, load: float, fit: float, sets: tuple = ()) -> Path:
    """The deck at base with the shaft speed (rpm), the applied load's magnitude (N, the deck's
    direction) and the inner race fit (m) replaced, and further fields set: sets holds
    (record, field, value) triples (--set)."""
    from pyadore.deck import read_deck

    deck = read_deck(base)
    for record, field, value in sets:
        deck.set(record, field, value)
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


_NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


def category(message: str) -> str:
    """A failure message without its numbers, ball and contact names: the class it is
    counted in ("the derivative refused the step: ball N, outer race contact: ...")."""
    m = message.split("; kept: ")[0].split("; before it, ")[0]
    for head in ("integration stopped: ", "the derivative refused the step (report 4.4.12): "):
        if head in m:
            m = m.split(head, 1)[1]
    m = m.split(" (t ")[0]
    m = re.sub(r" at time t = .*?\)", "", m)
    m = re.sub(r"(outside the model \(need 0 < a < rho < r_b\)).*", r"\1", m)
    m = re.sub(r"ball \d+", "ball N", m)
    m = re.sub(r"pocket \d+", "pocket N", m)
    m = _NUMBER.sub("#", m)
    return m[:160]


def balance(stderr: str) -> dict:
    """The run note's balance numbers (pyadore.api.parse_balance): revolutions in the window,
    drive power, dissipation, energy change (W), their ratio, the closure (drive - dissipation
    - energy change - whirl frame) / max(|drive|, dissipation) and the inner race's force residual and
    its momentum change over the window's duration against the applied load (fractions)."""
    from pyadore.api import parse_balance

    b = parse_balance(stderr.replace("\n", " "))
    if not b:
        return {}
    load = float(np.linalg.norm(b["inner_carried_N"]))
    return {"revolutions": b["revolutions"], "drive_W": b["drive_power_W"], "dissipation_W": b["dissipation_W"],
            "energy_rate_W": b["energy_rate_W"], "drive_over_dissipation": b["drive_ratio"],
            "closure": b["closure"],
            "inner_force_residual": b["inner_residual_N"] / load if load > 0 else float("nan"),
            "inner_momentum_rate": b["inner_momentum_rate_N"] / load if load > 0 else float("nan")}


def forced_diagnosis(stderr: str) -> dict:
    """The run note's diagnosis of its forced steps (pyadore.api.parse_forced_diagnosis): the
    largest error over the limit and the unknown that led most of them with its steps
    ("ball 1's angular velocity (body y): 100"); {} without forced steps."""
    from pyadore.api import parse_forced_diagnosis

    d = parse_forced_diagnosis(stderr.replace("\n", " "))
    if not d:
        return {}
    lead = f"{d['leaders'][0][0]}: {d['leaders'][0][1]}" if d["leaders"] else ""
    return {"forced_err_max": d["err_max"], "forced_lead": lead}


def leader_kind(lead: str) -> str:
    """A forced-step leader without its element's number: "ball 1's angular velocity (body y): 100"
    -> "a ball's angular velocity"."""
    name = re.sub(r": \d+$", "", lead)
    name = re.sub(r" \((body|orbit) [a-z]\)$", "", name)
    return re.sub(r"^(ball|roller) \d+'s", r"a \1's", name)


def _case(args) -> dict:
    base, speed, load, fit, steps, exe, extra, sets = args
    from pyadore.deck import check_deck

    with tempfile.TemporaryDirectory() as tmp:
        path = _variant(Path(base), Path(tmp) / "case.inp", speed, load, fit, sets)
        _, problems = check_deck(path)
        problems = [p for p in problems if p.kind != "warning"]
        row = {"deck": Path(base).name, "speed_rpm": speed, "load_N": load, "fit_m": fit}
        if problems:
            message = problems[0].format().split("\n")[0].replace(str(path), "deck")
            return row | {"outcome": "refused", "category": category(message), "message": message}
        start = time.perf_counter()
        # one thread a case: the pool's workers share the cores (docs/performance.md, "Threads")
        proc = subprocess.run([exe, str(path), str(Path(tmp) / "case.prt"), "--steps", str(steps), "--threads", "1",
                               *extra],
                              capture_output=True, text=True)
        row["seconds"] = round(time.perf_counter() - start, 3)
        if proc.returncode == 0:
            from pyadore.api import parse_forced_steps

            forced = parse_forced_steps(proc.stderr.replace("\n", " "))
            return row | {"outcome": "ran", "forced_steps": forced[0] if forced else 0} | balance(proc.stderr) \
                | forced_diagnosis(proc.stderr)
        message = proc.stderr.strip().split("\n")[0].replace(str(path) + ": ", "")
        return row | {"outcome": "failed", "category": category(message), "message": message}


FIELDS = ("deck", "speed_rpm", "load_N", "fit_m", "outcome", "category", "message", "seconds",
          "revolutions", "drive_W", "dissipation_W", "energy_rate_W", "drive_over_dissipation", "closure",
          "inner_force_residual", "inner_momentum_rate", "forced_steps", "forced_err_max", "forced_lead")
GRID = ROOT / "bench" / "operating_points_grid.csv"


def _key(r: dict) -> tuple:
    """A case's identity in a CSV: deck, speed, load, fit (as numbers)."""
    return (r["deck"], float(r["speed_rpm"]), float(r["load_N"]), float(r["fit_m"]))


def _short(r: dict) -> str:
    """A row's outcome for the transition table: "ran" or its message class."""
    return "ran" if r["outcome"] == "ran" else f"{r['outcome']}: {category(r['message'])[:90]}"


def merge(results: Path, mark: str, grid: Path = GRID) -> None:
    """Write the rows of a re-run (results CSV) into the grid CSV in place of the same cases,
    their ``rerun`` column set to mark (the other rows keep theirs), and print how the re-run
    cases moved (before -> after, counted)."""
    with open(grid, newline="") as f:
        old = list(csv.DictReader(f))
    with open(results, newline="") as f:
        new = {_key(r): r for r in csv.DictReader(f)}
    moves = collections.Counter()
    rows = []
    for r in old:
        n = new.pop(_key(r), None)
        if n is not None:
            moves[(_short(r), _short(n))] += 1
            r = {k: n.get(k, "") for k in FIELDS} | {"rerun": mark}
        rows.append({k: r.get(k, "") for k in (*FIELDS, "rerun")})
    if new:
        raise SystemExit(f"{len(new)} re-run cases are not in {grid}")
    with open(grid, "w", newline="") as f:
        writer = csv.DictWriter(f, (*FIELDS, "rerun"))
        writer.writeheader()
        writer.writerows(rows)
    for (before, after), n in sorted(moves.items(), key=lambda kv: -kv[1]):
        print(f"  {n:4d}  {before}  ->  {after}")


def summarize(rows: list[dict]) -> None:
    """Print a grid's counts: outcomes, failures by category, deck, speed, load and fit."""
    print(f"{len(rows)} cases: {dict(collections.Counter(r['outcome'] for r in rows))}")
    bad = [r for r in rows if r["outcome"] != "ran"]
    counted = [r for r in rows if r["outcome"] == "ran" and (r.get("forced_steps") or "") != ""]
    if counted:
        forced = [r for r in counted if int(r["forced_steps"]) > 0]
        print(f"ran with steps forced at the minimum step (error above the limit, not resolved): "
              f"{len(forced)} of {len(counted)} that ran and record it")
        led = [r for r in forced if r.get("forced_lead")]
        if led:
            print(f"  the unknown that led most of a run's forced steps ({len(led)} runs that record it):")
            for k, n in collections.Counter(leader_kind(r["forced_lead"]) for r in led).most_common():
                print(f"  {n:4d}  {k}")
    balances(rows)
    for title, key in (("category", lambda r: category(r["message"])[:110]), ("deck", lambda r: r["deck"]),
                       ("speed (rpm)", lambda r: float(r["speed_rpm"])), ("load (N)", lambda r: float(r["load_N"]) if float(r["load_N"]) in LOADS else "C0"),
                       ("fit (um)", lambda r: round(float(r["fit_m"]) * 1e6))):
        print(f"failures by {title}:")
        for k, n in sorted(collections.Counter(key(r) for r in bad).items(), key=lambda kv: -kv[1]):
            print(f"  {n:4d}  {k}")


def balances(rows: list[dict]) -> None:
    """Print how the runs' balances close (issue #28 item 2): the closure (drive - dissipation -
    energy change) / max(|drive|, dissipation) within 1 % and 10 % and the inner race's force
    residual within 1 % of the load, for every run, by speed, and for the runs the acceptance's
    "once steady" can mean: at least one shaft revolution in the balance window and no step
    forced at the minimum (at 0-100 rpm 300 steps cover at most 0.04 revolutions: the window is
    the settling of the start)."""
    def num(r, k):
        try:
            return float(r[k])
        except (KeyError, TypeError, ValueError):
            return float("nan")

    ran = [r for r in rows if r["outcome"] == "ran" and r.get("closure", "") != ""]
    if not ran:
        return

    def line(name, group):
        c = [abs(num(r, "closure")) for r in group]
        f = [num(r, "inner_force_residual") for r in group]
        print(f"  {name:>44}: {len(group):5d} runs, closure within 1 % {sum(x <= 0.01 for x in c):5d}, "
              f"within 10 % {sum(x <= 0.1 for x in c):5d}; inner race force within 1 % {sum(x <= 0.01 for x in f):5d}")

    print("balances (closure and inner race force residual):")
    line("all", ran)
    for speed in sorted({num(r, "speed_rpm") for r in ran}):
        line(f"{speed:g} rpm", [r for r in ran if num(r, "speed_rpm") == speed])
    line("window >= 1 revolution, no forced step", [r for r in ran if num(r, "revolutions") >= 1.0
                                                     and int(num(r, "forced_steps") or 0) == 0])
    # a residual is the race's mean m dv/dt: its momentum change over the window (a race that
    # vibrates at the ball passage under a light load leaves it in a short window)
    out = [r for r in ran if num(r, "inner_force_residual") > 0.01 and num(r, "inner_momentum_rate") >= 0.0]
    if out:
        inertia = sum(abs(num(r, "inner_force_residual") - num(r, "inner_momentum_rate"))
                      <= 0.01 * num(r, "inner_force_residual") for r in out)
        print(f"  inner race force residual above 1 %: {len(out)} runs; in {inertia} of them the residual is the "
              "race's momentum change over the window (within 1 % of it)")


def _table(title: str, counts: list[tuple[str, collections.Counter]]) -> None:
    """Print counters side by side (one column a grid) under title, the keys sorted."""
    keys = sorted(set().union(*(c for _, c in counts)), key=lambda k: (isinstance(k, str), k))
    print(f"{title}: " + " | ".join(name for name, _ in counts))
    for k in keys:
        print(f"  {k!s:>40}  " + " | ".join(f"{c[k]:5d}" for _, c in counts))


def compare(grids: list[tuple[str, list[dict]]]) -> None:
    """Print grids side by side (e.g. session 16's CSV and a new one): outcomes; failures by
    message class, deck, speed, load and fit; runs with steps forced at the minimum step by
    speed; runs whose closure (drive - dissipation - energy change) / max(|drive|, dissipation)
    is within 1 % and 10 %, all and among the resolved runs (no forced step); and how the
    cases moved from the first grid to each other one."""
    def load(r):
        return float(r["load_N"]) if float(r["load_N"]) in LOADS else "C0"

    def closure(r):
        try:
            return abs(float(r["closure"]))
        except (KeyError, TypeError, ValueError):
            return float("nan")

    def forced(r):
        return r["outcome"] == "ran" and int(r.get("forced_steps") or 0) > 0

    _table("outcomes", [(n, collections.Counter(r["outcome"] for r in rows)) for n, rows in grids])
    for title, key in (("failures by message", lambda r: category(r["message"])[:90]),
                       ("failures by deck", lambda r: r["deck"]),
                       ("failures by speed (rpm)", lambda r: float(r["speed_rpm"])),
                       ("failures by load (N)", load), ("failures by fit (um)", lambda r: round(float(r["fit_m"]) * 1e6))):
        _table(title, [(n, collections.Counter(key(r) for r in rows if r["outcome"] != "ran")) for n, rows in grids])
    _table("runs with forced steps by speed (rpm)",
           [(n, collections.Counter(float(r["speed_rpm"]) for r in rows if forced(r))) for n, rows in grids])
    _table("runs with forced steps by load (N)", [(n, collections.Counter(load(r) for r in rows if forced(r)))
                                                  for n, rows in grids])
    _table("forced steps in all, by speed (rpm)",
           [(n, collections.Counter({s: sum(int(r.get("forced_steps") or 0) for r in rows
                                           if r["outcome"] == "ran" and float(r["speed_rpm"]) == s)
                                     for s in SPEEDS})) for n, rows in grids])
    for bound in (0.01, 0.1):
        _table(f"closure within {bound:.0%}: all runs / resolved runs",
               [(n, collections.Counter({"all": sum(closure(r) <= bound for r in rows if r["outcome"] == "ran"),
                                         "resolved": sum(closure(r) <= bound for r in rows
                                                         if r["outcome"] == "ran" and not forced(r))}))
                for n, rows in grids])
    _table("closure within 1 % by speed (rpm), all runs",
           [(n, collections.Counter(float(r["speed_rpm"]) for r in rows if r["outcome"] == "ran" and closure(r) <= 0.01))
            for n, rows in grids])
    first_name, first = grids[0]
    before = {_key(r): r for r in first}
    for name, rows in grids[1:]:
        moves = collections.Counter()
        for r in rows:
            b = before.get(_key(r))
            if b is None:
                continue
            tb = "forced" if forced(b) else _short(b)
            ta = "forced" if forced(r) else _short(r)
            if tb != ta:
                moves[(tb, ta)] += 1
        print(f"moved {first_name} -> {name} (ran: no forced step; forced: ran with forced steps):")
        for (tb, ta), n in sorted(moves.items(), key=lambda kv: -kv[1]):
            print(f"  {n:4d}  {tb}  ->  {ta}")


def _floats(text: str) -> tuple:
    return tuple("C0" if v.strip() == "C0" else float(v) for v in text.split(","))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--decks", default="", help="comma-separated decks (default: every ball deck)")
    ap.add_argument("--speeds", default="", help="comma-separated shaft speeds, rpm (default: the grid's)")
    ap.add_argument("--loads", default="", help="comma-separated loads, N, or C0 (default: the grid's)")
    ap.add_argument("--fits", default="", help="comma-separated inner race fits, m (default: the grid's)")
    ap.add_argument("--rerun", default="", help="CSVs of earlier runs (comma-separated): run their failed cases again")
    ap.add_argument("--sample", type=int, default=0, help="with --rerun: also N cases that ran in the first CSV")
    ap.add_argument("--merge", default="", help="a re-run's CSV: write its rows into the grid CSV, marked")
    ap.add_argument("--mark", default="rerun", help="with --merge: the rerun column's value")
    ap.add_argument("--out", default="operating_points", help="name of the results in bench/results/")
    ap.add_argument("--exe", default=os.environ.get("ADORE_EXE", str(ROOT / "build" / "native" / "adore")))
    ap.add_argument("--extra", default="", help="further engine options, e.g. '--traction-table t.txt' (diagnosis)")
    ap.add_argument("--set", default="", help="deck fields set in every case, comma-separated RECORD:FIELD=VALUE, "
                                              "e.g. '2.1:step_min=5e-4' (diagnosis)")
    ap.add_argument("--summarize", default="", help="a CSV of an earlier run: print its counts and stop")
    ap.add_argument("--compare", default="", help="CSVs (comma-separated, the first the reference): print them "
                                                  "side by side and stop")
    a = ap.parse_args()
    if a.compare:
        grids = []
        for name in a.compare.split(","):
            with open(name, newline="") as f:
                grids.append((Path(name).stem, list(csv.DictReader(f))))
        compare(grids)
        return 0
    if a.summarize:
        with open(a.summarize, newline="") as f:
            summarize(list(csv.DictReader(f)))
        return 0
    if a.merge:
        merge(Path(a.merge), a.mark)
        return 0
    extra = a.extra.split()
    sets = tuple((item.split(":", 1)[0], item.split(":", 1)[1].split("=", 1)[0], float(item.split("=", 1)[1]))
                 for item in a.set.split(",") if item)
    decks = [Path(d) for d in a.decks.split(",")] if a.decks else _ball_decks()
    speeds = _floats(a.speeds) if a.speeds else SPEEDS
    loads = _floats(a.loads) if a.loads else LOADS
    fits = _floats(a.fits) if a.fits else FITS
    cases = []
    capacities = {}
    if a.rerun:
        old = {}
        for k, name in enumerate(a.rerun.split(",")):
            with open(name, newline="") as f:
                rows_k = list(csv.DictReader(f))
            old |= {_key(r): r for r in rows_k if r["outcome"] != "ran"}
            if k == 0 and a.sample:
                ran = sorted(_key(r) for r in rows_k if r["outcome"] == "ran")
                pick = np.random.default_rng(15).choice(len(ran), size=min(a.sample, len(ran)), replace=False)
                old |= {ran[j]: {} for j in sorted(pick)}
        by_name = {d.name: d for d in _ball_decks()}
        for deck, speed, load, fit in old:
            cases.append((str(by_name[deck]), speed, load, fit, a.steps, a.exe, extra, sets))
    else:
        cache = ROOT / "bench" / "results" / "static_capacity.json"
        known = json.loads(cache.read_text()) if cache.exists() else {}
        with tempfile.TemporaryDirectory() as tmp:
            if "C0" in loads:
                for d in decks:
                    capacities[d.name] = known.get(d.name) or static_capacity(d, Path(tmp))
        if capacities:
            cache.parent.mkdir(exist_ok=True)
            cache.write_text(json.dumps(known | capacities, indent=1) + "\n")
        for d in decks:
            for s, L, f in itertools.product(speeds, loads, fits):
                cases.append((str(d), s, capacities[d.name] if L == "C0" else L, f, a.steps, a.exe, extra, sets))
    # a fixed random order: a run stopped part way is a sample of the whole grid
    order = np.random.default_rng(28).permutation(len(cases))
    cases = [cases[k] for k in order]
    out = ROOT / "bench" / "results" / a.out
    out.parent.mkdir(exist_ok=True)
    start = time.perf_counter()
    rows = []
    with open(out.with_suffix(".csv"), "w", newline="") as f, ProcessPoolExecutor(max_workers=a.workers) as pool:
        writer = csv.DictWriter(f, FIELDS)
        writer.writeheader()
        for fut in as_completed([pool.submit(_case, c) for c in cases]):
            row = fut.result()
            rows.append(row)
            writer.writerow(row)
            f.flush()
    counts = collections.Counter(r["outcome"] for r in rows)
    messages = collections.Counter(r["category"] for r in rows if r["outcome"] != "ran")
    by_deck = collections.Counter(r["deck"] for r in rows if r["outcome"] != "ran")
    summary = {"steps": a.steps, "cases": len(rows), "outcomes": dict(counts),
               "static_capacity_N": capacities, "wall_s": round(time.perf_counter() - start, 1),
               "categories": messages.most_common(), "failures_by_deck": by_deck.most_common(),
               "failures": [r for r in rows if r["outcome"] != "ran"]}
    out.with_suffix(".json").write_text(json.dumps(summary, indent=1) + "\n")
    print(f"{len(rows)} cases, {a.steps} steps: {dict(counts)} ({summary['wall_s']} s)")
    for m, n in messages.most_common(12):
        print(f"  {n:4d}  {m}")
    for d, n in by_deck.most_common():
        print(f"  {n:4d}  {d}")
    if capacities:
        print(f"static capacities (ISO 76, 4200 MPa): {capacities}")
    print(f"written: {out.with_suffix('.csv')}, {out.with_suffix('.json')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
