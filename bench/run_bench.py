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
us_per_contact.  The dynamics (`dynamics`): the full Appendix C run, DYNAMIC_STEPS time steps
after step 0 (the deck's 2500), standalone and f2py (`pyadore.run`, which also reads the print and plot data and
writes the netCDF results dataset, and the extension's engine call alone), with the default two-dimensional race
traction and with the one-dimensional developer option (`--traction-1d`, `traction_2d=False`;
docs/dynamics.md): best and median wall time of DYNAMIC_REPEAT runs, the least CPU time
(the process's own, or the child's for the executable: steadier than wall time on a shared
machine), the print's "Total Derivative Calls" and final tau, and microseconds per
derivative call (the whole run, start and print included, over the calls; of the best wall
time and of the least CPU time); and once, the run to the report's simulated time
(`--duration REPORT_DURATION`, issue #30) with its steps, calls and final tau.  Issue #20's budget: at most 10 s for
the full run (goal 2 s).  The command's start-up (`startup`, issue #29): `pyadore run DECK --steps 0` in a fresh
interpreter against `adore DECK --steps 0`, budget STARTUP_BUDGET over the engine, and the heavy modules
(HEAVY_MODULES) the command imported (none expected); a first `pyadore.run` with time steps in a fresh
interpreter against the engine, and a sweep worker's boot.  The roller dynamics (`roller`, issue #26): the full
Appendix D run (the deck's 4000 steps; budget ROLLER_BUDGET s wall, goal 1 s) standalone and f2py, as the ball
dynamics' rows, and once the run to the report's simulated time (`--duration ROLLER_REPORT_DURATION`, the report's
tau 76.18).  Every run takes the default threads (run option threads: OMP_NUM_THREADS, else the
cores, at most 4; docs/performance.md, "Threads"), and the executable's full runs once more with `--threads 1`.
Results are printed, and written to bench/results/latest.json.
"""

from __future__ import annotations

import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pyadore
from pyadore import _core
from pyadore.options import options_text

ROOT = Path(__file__).resolve().parent.parent
DECKS = [ROOT / "decks" / "appendix_c_ball.inp", ROOT / "decks" / "appendix_d_roller.inp"]
REPEAT = 5
DYNAMIC_STEPS = 2500        # Appendix C's last step
REPORT_DURATION = 0.08612   # s: the simulated time of the report's Appendix C step 2500 (tau 353.4)
DYNAMIC_REPEAT = 3
ROLLER_STEPS = 4000             # Appendix D's last step
ROLLER_REPORT_DURATION = 5.453e-3   # s: the report's Appendix D step 4000 (tau 76.18)
ROLLER_BUDGET = 5.0             # s wall for the full Appendix D run (issue #26; goal 1 s)


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


def _cpu_time():
    """CPU time (s) of this process and its finished children."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def _run_row(deck, case, fn, out, repeat):
    """One dynamic-run row: best and median wall time, least CPU time, calls, final tau."""
    cpu = []

    def timed():
        start = _cpu_time()
        fn()
        cpu.append(_cpu_time() - start)

    best, median = _time(timed, repeat=repeat)
    text = out.read_text()
    calls = int(re.search(r"Total Derivative Calls\s*=\s*(\d+)", text).group(1))
    tau = float(re.search(r"Final Time\s*=\s*(\S+)", text).group(1))
    steps = int(re.search(r"Last Step Number\s*=\s*(\d+)", text).group(1))
    return {"deck": deck.name, "case": case.format(steps=steps), "best_s": best, "median_s": median,
            "cpu_s": min(cpu), "derivative_calls": calls, "final_tau": tau, "us_per_call": best / calls * 1e6,
            "cpu_us_per_call": min(cpu) / calls * 1e6}


def _roller_rows(exe):
    """The full Appendix D dynamic run (module docstring), standalone and f2py, and the run to
    the report's simulated time."""
    deck = DECKS[1]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "roller.prt"
        rows.append(_run_row(deck, f"{ROLLER_STEPS} steps, executable",
                             lambda: subprocess.run([exe, str(deck), str(out), "--steps", str(ROLLER_STEPS)],
                                                    check=True, capture_output=True), out, DYNAMIC_REPEAT))
        rows.append(_run_row(deck, f"{ROLLER_STEPS} steps, executable, --threads 1",
                             lambda: subprocess.run([exe, str(deck), str(out), "--steps", str(ROLLER_STEPS),
                                                     "--threads", "1"], check=True, capture_output=True),
                             out, DYNAMIC_REPEAT))
        rows.append(_run_row(deck, f"{ROLLER_STEPS} steps, f2py",
                             lambda: pyadore.run(deck, steps=ROLLER_STEPS, out=out, progress=False), out,
                             DYNAMIC_REPEAT))
        rows.append(_run_row(deck, f"--duration {ROLLER_REPORT_DURATION} (the report's time), {{steps}} steps, "
                             "executable", lambda: subprocess.run([exe, str(deck), str(out), "--duration",
                                                                   str(ROLLER_REPORT_DURATION)],
                                                                  check=True, capture_output=True), out, 1))
    for row in rows[:3]:
        row["within_budget"] = row["best_s"] <= ROLLER_BUDGET
    return rows


def _dynamic_rows(exe):
    """The full Appendix C dynamic run (module docstring): one row per traction and path."""
    deck = DECKS[0]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "dynamics.prt"
        for traction, two_d in (("2-D traction (default)", True), ("1-D traction (--traction-1d)", False)):
            flag = [] if two_d else ["--traction-1d"]
            engine_options = options_text(steps=DYNAMIC_STEPS, traction_2d=two_d)
            for label, fn in [
                # pyadore.run: the engine, then the print, plot data and the netCDF results dataset read and written
                ("f2py", lambda: pyadore.run(deck, steps=DYNAMIC_STEPS, out=out, traction_2d=two_d, progress=False)),
                # the extension's engine call alone (the same run; no Python progress callback, no dataset)
                ("f2py engine call", lambda: _core.run_file(deck, out, engine_options)),
                ("executable", lambda: subprocess.run([exe, str(deck), str(out), "--steps", str(DYNAMIC_STEPS)] + flag,
                                                      check=True, capture_output=True)),
            ]:
                rows.append(_run_row(deck, f"{DYNAMIC_STEPS} steps, {traction}, {label}", fn, out, DYNAMIC_REPEAT))
        # the default's threads (run option threads: OMP_NUM_THREADS, else the cores, at most 4) against one
        rows.append(_run_row(deck, f"{DYNAMIC_STEPS} steps, 2-D traction (default), executable, --threads 1",
                             lambda: subprocess.run([exe, str(deck), str(out), "--steps", str(DYNAMIC_STEPS),
                                                     "--threads", "1"], check=True, capture_output=True),
                             out, DYNAMIC_REPEAT))
        # the report's simulated time (Appendix C step 2500: 8.612E-02 s; issue #30), once
        rows.append(_run_row(deck, f"--duration {REPORT_DURATION} (the report's time), {{steps}} steps, executable",
                             lambda: subprocess.run([exe, str(deck), str(out), "--duration", str(REPORT_DURATION)],
                                                    check=True, capture_output=True), out, 1))
    return rows


#: Issue #29: `pyadore run --steps 0` at most this much wall time (s) over the standalone engine.
STARTUP_BUDGET = 0.35
#: Modules `pyadore run --steps 0` must not import (imported on demand only).
HEAVY_MODULES = ("pandas", "matplotlib", "xarray", "scipy.io", "scipy.sparse", "dask", "distributed")


#: Time steps of the start-up bench's first run with time steps (it writes the netCDF results).
STARTUP_STEPS = 20


def _heavy(trace: str) -> list[str]:
    """The HEAVY_MODULES a ``python -X importtime`` trace imported (a module or one of its submodules;
    scipy's netCDF writer module alone, without the package scipy.io, is not one)."""
    names = {line.split("|")[-1].strip() for line in trace.splitlines() if line.startswith("import time:")}
    return sorted(h for h in HEAVY_MODULES if any(n == h or n.startswith(h + ".") for n in names))


def _startup_rows(exe):
    """The command's start-up: best of REPEAT wall times of `pyadore run DECK --steps 0` (a
    fresh interpreter each time) and of `adore DECK --steps 0`, their difference against
    STARTUP_BUDGET, and the heavy modules the command imported (python -X importtime); the
    same for a first run with STARTUP_STEPS time steps in a fresh interpreter (it also writes
    the time history and the netCDF results: no xarray, pandas or scipy.io expected), and the
    boot of a sweep worker (`python -m pyadore.sweeps.worker` with no job: interpreter, the
    engine's shared object without numpy (pyadore/_core/lite.py), the deck checker and print
    reader; docs/sweeps.md "Scaling").  The
    commands alternate, so that a drift of the machine's speed does not favour one."""
    deck = DECKS[0]
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "startup.prt"
        py = [sys.executable, "-m", "pyadore", "run", str(deck), "--steps", "0", "-o", str(out)]
        engine = [exe, str(deck), str(out), "--steps", "0"]
        first = [sys.executable, "-c", "import sys, pyadore; pyadore.run(sys.argv[1], steps=int(sys.argv[3]), "
                 "out=sys.argv[2], progress=False)", str(deck), str(Path(tmp) / "first.prt"), str(STARTUP_STEPS)]
        engine_steps = [exe, str(deck), str(Path(tmp) / "first_exe.prt"), "--steps", str(STARTUP_STEPS)]
        worker = [sys.executable, "-m", "pyadore.sweeps.worker"]
        commands = {"cli": py, "exe": engine, "first": first, "exe_steps": engine_steps, "worker": worker}
        times: dict[str, list[float]] = {k: [] for k in commands}
        cpu: dict[str, list[float]] = {k: [] for k in commands}
        for _ in range(REPEAT):
            for key, cmd in commands.items():
                start, start_cpu = time.perf_counter(), _cpu_time()
                subprocess.run(cmd, check=True, capture_output=True, stdin=subprocess.DEVNULL)
                times[key].append(time.perf_counter() - start)
                cpu[key].append(_cpu_time() - start_cpu)
        traces = {key: subprocess.run([sys.executable, "-X", "importtime"] + commands[key][1:], check=True,
                                      capture_output=True, text=True, stdin=subprocess.DEVNULL).stderr
                  for key in ("cli", "first", "worker")}
    best = {k: min(v) for k, v in times.items()}
    med = {k: statistics.median(v) for k, v in times.items()}
    least = {k: min(v) for k, v in cpu.items()}  # CPU (user + sys): less inflated by the machine's load
    over = best["cli"] - best["exe"]
    verdict = "met" if over <= STARTUP_BUDGET else "NOT met"
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"start-up: pyadore run --steps 0 {best['cli']:.3f} s best, adore --steps 0 {best['exe']:.3f} s best: "
          f"{over:.3f} s over the engine (budget {STARTUP_BUDGET} s: {verdict}; load average {load:.1f}; CPU "
          f"{least['cli']:.3f} s against {least['exe']:.3f} s); heavy modules imported: "
          f"{', '.join(_heavy(traces['cli'])) or 'none'}")
    print(f"start-up: first pyadore.run of {STARTUP_STEPS} steps in a fresh interpreter {best['first']:.3f} s best, "
          f"adore {best['exe_steps']:.3f} s: {best['first'] - best['exe_steps']:.3f} s over the engine (CPU "
          f"{least['first']:.3f} s against {least['exe_steps']:.3f} s); heavy modules imported: "
          f"{', '.join(_heavy(traces['first'])) or 'none'}")
    print(f"start-up: sweep worker boot {best['worker']:.3f} s best ({med['worker']:.3f} s median, CPU "
          f"{least['worker']:.3f} s); heavy modules imported: {', '.join(_heavy(traces['worker'])) or 'none'}")
    rows = [("cli", "pyadore run --steps 0 (CLI)"), ("exe", "adore --steps 0"),
            ("first", f"first pyadore.run, {STARTUP_STEPS} steps"), ("exe_steps", f"adore --steps {STARTUP_STEPS}"),
            ("worker", "sweep worker boot")]
    out = [{"deck": deck.name, "case": case, "best_s": best[k], "median_s": med[k], "least_cpu_s": least[k]}
           for k, case in rows]
    out.insert(2, {"deck": deck.name, "case": "CLI start-up over the engine", "best_s": over,
                   "median_s": med["cli"] - med["exe"], "least_cpu_s": least["cli"] - least["exe"]})
    return out


def main() -> int:
    """`run_bench.py [runs] [startup] [sweep] [dynamics] [roller]`: the runs of the appendix decks, the
    command's start-up, the sweep bench, the full dynamic run of Appendix C and/or of Appendix D
    [default: all]."""
    names = sys.argv[1:] or ["runs", "startup", "sweep", "dynamics", "roller"]
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
    if "startup" in names:
        rows += _startup_rows(exe)
    if "sweep" in names:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        from sweep_bench import bench_sweep

        rows += bench_sweep()
    if "dynamics" in names:
        rows += _dynamic_rows(exe)
    if "roller" in names:
        rows += _roller_rows(exe)
    print(f"{'deck':28s} {'case':30s} {'best (s)':>10s} {'median (s)':>11s}")
    for row in rows:
        if "us_per_call" in row:
            print(f"{row['deck']:28s} {row['case']:40s} {row['best_s']:6.3f} s best, {row['median_s']:6.3f} s median, "
                  f"{row['cpu_s']:6.3f} s CPU, {row['derivative_calls']} calls, {row['us_per_call']:.1f} us/call "
                  f"({row['cpu_us_per_call']:.1f} CPU), tau = {row['final_tau']:.4g}")
            continue
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
