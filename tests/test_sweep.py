"""Parametric sweeps (pyadore.sweep, `pyadore sweep`, `pyadore plot-sweep`).

Kept small: a 2 x 2 ball grid at step 0 (about 3 s a case) for the physics, resume and
plot checks, and the roller deck (a few hundredths of a second a case) for the rest.
The 32-case grid of the issue and the 1-vs-2-worker timing are in bench/run_bench.py.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

import pyadore
from pyadore.deck import read_deck
from pyadore.printout import read_print
from pyadore.sweeps import RESULT_COLUMNS, SweepError
from pyadore.sweeps.grid import make_cases, parse_vary

ROOT = Path(__file__).resolve().parent.parent
BALL = ROOT / "decks" / "appendix_c_ball.inp"
ROLLER = ROOT / "decks" / "appendix_d_roller.inp"
BALL_GRID = {"inner_race_speed": [10000, 20000], "applied_force_z": [1000, 3000]}


def _cli(*args, **kw):
    return subprocess.run([sys.executable, "-m", "pyadore", *map(str, args)], capture_output=True, text=True,
                          timeout=600, **kw)


def _events(folder: Path) -> list[list[str]]:
    return [line.split() for line in (folder / "events.log").read_text().splitlines() if line.strip()]


@pytest.fixture(scope="module")
def ball_sweep(tmp_path_factory):
    folder = tmp_path_factory.mktemp("ball_sweep") / "sweep"
    frame = pyadore.sweep(BALL, BALL_GRID, folder, steps=0, workers=2, progress=False)
    return folder, frame


def test_ball_grid_physics(ball_sweep):
    """Step 0 of Appendix C: power loss rises with shaft speed, life falls with load."""
    _, frame = ball_sweep
    assert list(frame.columns) == ["case", "inner_race_speed", "applied_force_z", "status", *RESULT_COLUMNS]
    assert len(frame) == 4
    assert list(frame["status"]) == ["ok"] * 4
    for _, part in frame.groupby("applied_force_z"):
        part = part.sort_values("inner_race_speed")
        assert part["total_power_loss_W"].is_monotonic_increasing and part["total_power_loss_W"].nunique() == 2
    for speed, part in frame.groupby("inner_race_speed"):
        part = part.sort_values("applied_force_z")
        for col in ("basic_life_h", "modified_life_h"):
            assert part[col].iloc[1] < part[col].iloc[0], (speed, col)
        assert part["max_contact_load_N"].iloc[1] > part["max_contact_load_N"].iloc[0]
        assert part["max_contact_stress_Pa"].iloc[1] > part["max_contact_stress_Pa"].iloc[0]
    assert frame["cage_speed_ratio"].between(0.3, 0.6).all()


def test_ball_results_are_the_prints(ball_sweep):
    """The summary row of a case is its own print's values, and the case deck differs from
    the base only in the varied records (the others verbatim)."""
    folder, frame = ball_sweep
    row = frame.iloc[3]
    case = folder / "cases" / row["case"]
    step = read_print(case / "case.prt").step(0)
    perf = step.table("performance").loc["bearing"]
    assert row["total_power_loss_W"] == perf["total_power_loss_W"]
    assert row["basic_life_h"] == perf["basic_fatigue_life_hours"]
    contact = step.table("re_contact")
    largest = max(contact["contact_load_outer_N"].max(), contact["contact_load_inner_N"].max())
    assert row["max_contact_load_N"] == largest
    base = BALL.read_text().splitlines()
    mine = (case / "deck.inp").read_text().splitlines()
    changed = sorted(b.split()[1] for a, b in zip(base, mine) if a != b)
    deck, base_deck = read_deck(case / "deck.inp"), read_deck(BALL)
    differ = sorted(r.rid for r, b in zip(deck.records, base_deck.records) if r.values() != b.values())
    # the varied records, and the run identification titling the case's print (issue #29)
    assert len(base) == len(mine) and changed == differ and set(differ) <= {"3.1", "9.1.1", "9.1.2"} and differ
    assert deck.get("3.1", "run_id") == "#0004 inner_race_speed=20000 applied"[:36]
    assert deck.get("9.1.2", "inner_race_speed") == row["inner_race_speed"] == 20000
    assert deck.get("9.1.1", "applied_force_z") == row["applied_force_z"] == 3000
    on_disk = pd.read_csv(folder / "summary.csv")
    pd.testing.assert_frame_equal(on_disk, frame, check_dtype=False)
    # written without pandas (the command's serial end): the bytes pandas writes
    assert (folder / "summary.csv").read_text() == frame.to_csv(index=False)
    manifest = json.loads((folder / "manifest.json").read_text())
    assert [e["status"] for e in manifest["cases"]] == ["ok"] * 4
    assert all(e["duration_s"] > 0 and e["error"] == "" for e in manifest["cases"])


def test_rerun_recomputes_nothing(ball_sweep):
    folder, frame = ball_sweep
    def files():
        return {p: (p.read_text(), p.stat().st_mtime_ns) for p in (folder / "cases").rglob("*") if p.is_file()}

    before = files()
    events = _events(folder)
    again = pyadore.sweep(BALL, BALL_GRID, folder, steps=0, workers=2, progress=False)
    pd.testing.assert_frame_equal(again, frame)
    assert _events(folder) == events  # no case finished again
    assert files() == before  # not one case file rewritten


def test_another_sweep_in_the_same_folder_is_refused(ball_sweep):
    folder, _ = ball_sweep
    with pytest.raises(SweepError, match="holds another sweep.*varied fields or values"):
        pyadore.sweep(BALL, {"inner_race_speed": [10000, 25000]}, folder, steps=0, progress=False)
    with pytest.raises(SweepError, match="--steps"):
        pyadore.sweep(BALL, BALL_GRID, folder, steps=1, progress=False)


def test_plot_sweep(ball_sweep, tmp_path):
    from pyadore.plots.sweep import plot_sweep

    folder, frame = ball_sweep
    fig = plot_sweep(folder, x="inner_race_speed", y="total_power_loss_W", by="applied_force_z")
    ax = fig.axes[0]
    # the fields in words from the record table (issue #29)
    assert [line.get_label() for line in ax.lines] == ["Applied force z = 1000 N", "Applied force z = 3000 N"]
    low = frame[frame["applied_force_z"] == 1000].sort_values("inner_race_speed")
    assert list(ax.lines[0].get_xdata()) == list(low["inner_race_speed"])
    assert list(ax.lines[0].get_ydata()) == list(low["total_power_loss_W"])
    assert ax.get_xlabel() == "Inner race speed (rpm)" and ax.get_ylabel() == "Total power loss (W)"
    with pytest.raises(SweepError, match="also varies applied_force_z"):
        plot_sweep(folder, x="inner_race_speed", y="total_power_loss_W")
    with pytest.raises(SweepError, match="choose one of inner_race_speed, applied_force_z"):
        plot_sweep(folder, x="speed", y="total_power_loss_W")
    out = tmp_path / "life.png"
    proc = _cli("plot-sweep", folder, "--x", "applied_force_z", "--y", "basic_life_h",
                "--where", "inner_race_speed=20000", "-o", out)
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_invalid_and_refused_cases_are_reported(tmp_path):
    """A deck validate refuses (an out-of-range value, no applied force) is reported with
    validate's message, which for the unloaded deck is also the engine's; a deck the engine
    refuses for its run options with the engine's; the other cases run."""
    folder = tmp_path / "s"
    proc = _cli("sweep", ROLLER, "--vary", "applied_force_z=0,1000", "--vary", "constraining_load_fraction=0.5,2",
                "--steps", "0", "-o", folder, "--workers", "2")
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    frame = pd.read_csv(folder / "summary.csv")
    assert list(frame["status"]) == ["invalid", "invalid", "ok", "invalid"]
    manifest = {e["case"]: e for e in json.loads((folder / "manifest.json").read_text())["cases"]}
    for case in ("case_0001", "case_0002", "case_0004"):
        deck = folder / "cases" / case / "deck.inp"
        validate = _cli("validate", deck)
        assert validate.returncode == 1
        assert manifest[case]["error"].strip() == validate.stderr.strip()
        assert not (folder / "cases" / case / "case.prt").exists()
    for case in ("case_0002", "case_0004"):
        assert "constraining_load_fraction = 2: expected [0, 1]" in manifest[case]["error"]
    unloaded = manifest["case_0001"]["error"]
    assert "expected a non-zero applied force" in unloaded
    engine = _cli("run", folder / "cases" / "case_0001" / "deck.inp", "-o", tmp_path / "x.prt", "--steps", "0")
    assert engine.returncode == 1 and unloaded.splitlines()[0] in engine.stderr
    assert manifest["case_0003"]["status"] == "ok" and frame.loc[2, "basic_life_h"] > 0
    assert "case_0002: " in proc.stderr and "4 cases: 1 finished" in proc.stdout
    # a valid deck the engine refuses (the ball start option on a roller deck): the engine's message
    refused_folder = tmp_path / "r"
    proc = _cli("sweep", ROLLER, "--vary", "applied_force_z=1000", "--steps", "0", "-o", refused_folder,
                "--workers", "1", "--ball-start", "dissipation")
    assert proc.returncode == 1 and "Traceback" not in proc.stderr
    (entry,) = json.loads((refused_folder / "manifest.json").read_text())["cases"]
    assert entry["status"] == "input-error"
    assert "the ball start option applies to ball bearings" in entry["error"]
    assert str(refused_folder / "cases" / "case_0001" / "deck.inp") in entry["error"]  # not the worker's copy


def _roller_speeds(n: int) -> str:
    return ",".join(str(50000 + 250 * k) for k in range(n))


def test_killed_sweep_resumes_with_nothing_lost_or_run_twice(tmp_path):
    folder = tmp_path / "s"
    n = 60
    args = ["sweep", ROLLER, "--vary", f"inner_race_speed={_roller_speeds(n)}", "--steps", "0", "-o", folder,
            "--workers", "1"]
    proc = subprocess.Popen([sys.executable, "-m", "pyadore", *map(str, args)], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        deadline = time.monotonic() + 300
        while time.monotonic() < deadline and proc.poll() is None:
            if (folder / "events.log").exists() and len(_events(folder)) >= 5:
                break
            time.sleep(0.01)
    finally:
        os.killpg(proc.pid, signal.SIGKILL)  # the sweep and its worker: no clean-up at all
        proc.wait()
    finished_before = {e[1]: e for e in _events(folder)}
    assert 5 <= len(finished_before) < n, "the sweep was not stopped midway"
    kept = {c: (folder / "cases" / c / "result.json").read_text() for c in finished_before}

    rerun = _cli(*args)
    assert rerun.returncode == 0, rerun.stderr
    frame = pd.read_csv(folder / "summary.csv")
    assert len(frame) == n and set(frame["status"]) == {"ok"}
    finished = [e[1] for e in _events(folder)]
    assert sorted(finished) == sorted(frame["case"]), "every case finished exactly once"
    for case, text in kept.items():
        assert (folder / "cases" / case / "result.json").read_text() == text
    assert not [p for p in folder.rglob("*") if ".tmp-" in p.name], "no temporary file left"
    for row in frame.itertuples():
        case = folder / "cases" / row.case
        assert read_print(case / "case.prt").step_numbers == [0]
        assert read_deck(case / "deck.inp").get("9.1.2", "inner_race_speed") == row.inner_race_speed


def _assert_forked_from_the_command(command: int, worker: int) -> None:
    """The worker's parent is the fork server and the server's parent the `pyadore sweep`
    command, whose command line it has: a fork of the command at its start, not a second
    interpreter (`python -m pyadore.sweeps.worker`; docs/sweeps.md, "Where the cases run").
    The worker holds one thread: the server set OMP_NUM_THREADS and OPENBLAS_NUM_THREADS to 1
    before numpy and the engine loaded (set after the fork, they are not in /proc's environ of
    the exec; without them numpy's OpenBLAS starts a thread per further core)."""
    try:
        server, _ = _parent_and_environment(worker)
        parent, _ = _parent_and_environment(server)
        cmdline = Path(f"/proc/{server}/cmdline").read_bytes()
        threads = [line for line in Path(f"/proc/{worker}/status").read_text().splitlines()
                   if line.startswith("Threads:")]
    except (FileNotFoundError, ProcessLookupError):
        pytest.skip("the sweep ended before its processes could be read")
    assert parent == command
    assert cmdline == Path(f"/proc/{command}/cmdline").read_bytes() and b"pyadore.sweeps.worker" not in cmdline
    assert threads == ["Threads:\t1"]


def test_terminated_sweep_ends_its_workers(tmp_path):
    """SIGTERM (or Ctrl-C) stops the sweep at once: its worker processes ended, the finished
    cases kept, and the command ends by the signal (a shell's exit status 128 + 15; the
    rule of docs/dynamics.md "Signals")."""
    folder = tmp_path / "s"
    # many more cases than the signal waits for: a test process starved on a loaded machine
    # still signals the sweep before it ends (60 cases could all finish first)
    n = 240
    speeds = ",".join(str(50000 + 100 * k) for k in range(n))
    proc = subprocess.Popen([sys.executable, "-m", "pyadore", "sweep", str(ROLLER), "--vary",
                             f"inner_race_speed={speeds}", "--steps", "0", "-o", str(folder),
                             "--workers", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline and proc.poll() is None:
        if (folder / "events.log").exists() and len(_events(folder)) >= 3:
            break
        time.sleep(0.01)
    if sys.platform.startswith("linux") and proc.poll() is None:
        _assert_forked_from_the_command(proc.pid, int(_events(folder)[0][4].rsplit(":", 1)[1]))
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == -signal.SIGTERM, err
    assert "interrupted by SIGTERM" in err and "Traceback" not in err
    events = _events(folder)
    assert 3 <= len(events) < n
    workers = {int(e[4].rsplit(":", 1)[1]) for e in events}
    time.sleep(0.5)
    for pid in workers:
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)
    for e in events:
        assert (folder / "cases" / e[1] / "case.prt").exists()


def test_dask_cluster_gives_the_local_summary(tmp_path):
    distributed = pytest.importorskip("distributed")
    grid = {"inner_race_speed": [50000, 70000], "applied_force_z": [500, 1000]}
    local = pyadore.sweep(ROLLER, grid, tmp_path / "local", steps=0, workers=2, progress=False)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster:
        remote = pyadore.sweep(ROLLER, grid, tmp_path / "dask", steps=0, scheduler=cluster.scheduler_address,
                               progress=False)
    assert list(remote["status"]) == ["ok"] * 4
    pd.testing.assert_frame_equal(remote, local)
    for case in local["case"]:
        a = (tmp_path / "local" / "cases" / case / "case.prt").read_text()
        b = (tmp_path / "dask" / "cases" / case / "case.prt").read_text()
        assert a == b
    assert (tmp_path / "dask" / "summary.csv").read_text() == (tmp_path / "local" / "summary.csv").read_text()


def test_field_names_and_values():
    deck = read_deck(ROLLER)
    v = parse_vary("inner_race_speed=1e4,2.5E4", deck)
    assert v.records == ("9.1.2",) and v.unit == "rpm" and v.values == (10000.0, 25000.0)
    assert parse_vary("9.1.2/inner_race_speed=1", deck).records == ("9.1.2",)
    assert parse_vary("7.2.n/guide_land_clearance=1e-4", deck).records == ("7.2.1", "7.2.2")
    assert parse_vary("7.2.2/guide_land_clearance=1e-4", deck).records == ("7.2.2",)
    with pytest.raises(SweepError, match="did you mean inner_race_speed"):
        parse_vary("inner_race_sped=1", deck)
    with pytest.raises(SweepError, match="several records.*7.2.1/guide_land_clearance, 7.2.2/guide_land_clearance"):
        parse_vary("guide_land_clearance=1e-4", deck)
    with pytest.raises(SweepError, match="Rec 5A, which this deck"):
        parse_vary("ball_diameter=1", deck)
    with pytest.raises(SweepError, match="is not a number"):
        parse_vary("applied_force_z=10 kN", deck)
    with pytest.raises(SweepError, match="FIELD=V1,V2"):
        parse_vary("applied_force_z", deck)


def test_grid_and_zip():
    deck = read_deck(ROLLER)
    a = parse_vary("inner_race_speed=1,2,3", deck)
    b = parse_vary("applied_force_z=10,20,30", deck)
    grid = make_cases([a, b])
    assert len(grid) == 9 and grid[1].params == {"inner_race_speed": 1.0, "applied_force_z": 20.0}
    zipped = make_cases([a, b], zip_values=True)
    assert [c.params["applied_force_z"] for c in zipped] == [10.0, 20.0, 30.0]
    assert [c.case_id for c in zipped] == ["case_0001", "case_0002", "case_0003"]
    with pytest.raises(SweepError, match="same number of values"):
        make_cases([a, parse_vary("applied_force_z=1,2", deck)], zip_values=True)


def test_cli_errors_have_no_traceback(tmp_path):
    proc = _cli("sweep", ROLLER, "--vary", "speed=1,2", "-o", tmp_path / "x")
    assert proc.returncode == 1 and "Traceback" not in proc.stderr
    assert "--vary speed: no deck field of that name" in proc.stderr
    proc = _cli("sweep", ROLLER, "--vary", "inner_race_speed=1,2", "-o", tmp_path / "x", "--workers", "2",
                "--scheduler", "tcp://127.0.0.1:1")
    assert proc.returncode == 1 and "exclude each other" in proc.stderr



def test_every_run_option_applies_to_every_case(tmp_path):
    """The sweep takes the run options of `pyadore run` from the engine's one table: here
    substeps (report 4.4.5), which the sweep never named before the table; the sweep folder
    remembers them and refuses to resume with others; a bad option stops it before any case."""
    from pyadore.sweeps import store

    folder = tmp_path / "s"
    proc = _cli("sweep", BALL, "--vary", "inner_race_speed=10000,12000", "--steps", "2", "--substeps", "2",
                "-o", folder, "--workers", "1")
    assert proc.returncode == 0, proc.stderr
    assert json.loads((folder / store.SWEEP_FILE).read_text())["options"] == {"substeps": 2}
    for case in ("case_0001", "case_0002"):
        text = (folder / "cases" / case / store.CASE_PRINT).read_text()
        assert "TIME INTEGRATION: 2 TIME STEPS\n  2 SUBSTEPS IN EACH TIME STEP (REPORT 4.4.5)" in text
    again = _cli("sweep", BALL, "--vary", "inner_race_speed=10000,12000", "--steps", "2", "--substeps", "3",
                 "-o", folder, "--workers", "1")
    assert again.returncode == 1 and "it differs in the run options" in again.stderr
    with pytest.raises(pyadore.AdoreInputError, match="unknown run option 'colour'"):
        pyadore.sweep(ROLLER, {"applied_force_z": [1000]}, tmp_path / "t", steps=0, colour="red", progress=False)
    assert not (tmp_path / "t").exists()


def test_worker_starts_without_pandas_and_reads_the_same_key_results(tmp_path):
    """Sweep scaling (issue #29 item 8): a worker boots without pandas (60 % of its start-up,
    a serial cost more workers do not share) and a step-0 case stays without it; the plain
    reading of a print gives exactly the key results of the pandas one, for a step-0 print
    and a print with dynamic steps."""
    code = ("import sys\n"
            "from pyadore.sweeps import worker\n"
            "worker.warm()\n"
            "from pyadore.sweeps.execute import run_case\n"
            f"r = run_case('c', open({str(ROOT / 'decks' / 'appendix_c_ball.inp')!r}).read(), 0, {{}})\n"
            "assert r['status'] == 'ok', r['error']\n"
            "print('pandas' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"
    from pyadore.sweeps.results import key_results

    static = pyadore.run(ROOT / "decks" / "appendix_c_ball.inp", steps=0, out=tmp_path / "s.prt").print_path
    dynamic = pyadore.run(ROOT / "decks" / "appendix_c_ball.inp", steps=3, out=tmp_path / "d.prt").print_path
    for prt in (static, dynamic):
        framed, plain = read_print(prt), read_print(prt, frames=False, echo=False)
        assert plain.step_numbers == framed.step_numbers and plain.echo == {}
        assert key_results(plain) == key_results(framed)
        assert all(v == v for v in key_results(plain).values())   # no NaN: every value found


def _parent_and_environment(pid: int) -> tuple[int, list[bytes]]:
    """A Linux process's parent pid and environment (/proc)."""
    stat = Path(f"/proc/{pid}/stat").read_bytes().rsplit(b")", 1)[1].split()
    return int(stat[1]), Path(f"/proc/{pid}/environ").read_bytes().split(b"\0")


def test_a_worker_pool_stays_warm_across_sweeps(tmp_path):
    """Two sweeps on one WorkerPool run on the same two processes (booted once) and give the
    summary a sweep with its own workers gives; closing the pool ends the processes.  On
    Linux both are forked by one warm fork server (one interpreter start for the pool), each
    with one engine thread (OMP_NUM_THREADS=1); a worker killed between sweeps is replaced."""
    from pyadore.sweeps import WorkerPool

    grid = {"applied_force_z": [500, 750, 1000, 1250]}
    own = pyadore.sweep(ROLLER, grid, tmp_path / "own", steps=0, workers=2, progress=False)
    with WorkerPool(2) as pool:
        first = pyadore.sweep(ROLLER, grid, tmp_path / "a", steps=0, workers=pool, progress=False)
        procs = [w.proc for w in pool._workers]
        assert all(p is not None and p.poll() is None for p in procs)
        if sys.platform.startswith("linux"):
            server = pool._workers[0].server
            assert server is not None and all(w.server is server for w in pool._workers)
            for p in procs:
                parent, env = _parent_and_environment(p.pid)
                assert parent == server.pid and b"OMP_NUM_THREADS=1" in env
        second = pyadore.sweep(ROLLER, {"inner_race_speed": [60000, 65000]}, tmp_path / "b", steps=0,
                               workers=pool, progress=False)
        assert [w.proc for w in pool._workers] == procs       # the same processes, not restarted
        pids = {f"{p.pid}" for p in procs}
        for folder in (tmp_path / "a", tmp_path / "b"):
            used = {e["worker"].rsplit(":", 1)[1] for e in json.loads((folder / "manifest.json").read_text())["cases"]}
            assert used <= pids
        os.kill(procs[1].pid, signal.SIGKILL)                    # a worker lost between sweeps
        procs[1].wait(timeout=10)
        third = pyadore.sweep(ROLLER, grid, tmp_path / "c", steps=0, workers=pool, progress=False)
        assert pool._workers[1].proc is not procs[1] and pool._workers[1].proc.poll() is None
        manifest = json.loads((tmp_path / "c" / "manifest.json").read_text())
        used = {e["worker"].rsplit(":", 1)[1] for e in manifest["cases"]}
        assert str(procs[1].pid) not in used and str(procs[0].pid) in used
        pd.testing.assert_frame_equal(third, own)
        procs.append(pool._workers[1].proc)
    assert all(p.poll() is not None for p in procs)             # ended with the pool
    if sys.platform.startswith("linux"):
        assert server.poll() is not None                        # and its fork server with them
    assert list(second["status"]) == ["ok", "ok"]
    pd.testing.assert_frame_equal(first, own)
    with pytest.raises(SweepError, match="WorkerPool"):
        pyadore.sweep(ROLLER, grid, tmp_path / "c", steps=0, workers=0, progress=False)


def test_summary_csv_is_the_text_pandas_writes():
    """summary.csv is written without pandas (0.3-0.6 s of the `pyadore sweep` command's serial
    end, docs/sweeps.md "Scaling"): the bytes pandas' to_csv writes, for a column of integers,
    of floats (shortest repr, the exponent forms, -0.0, inf, NaN as empty), of integers mixed
    with floats or NaN (all written as floats), of text that needs quoting and of NaN only."""
    from pyadore.sweeps.runner import summary_csv

    floats = [1e16, 1e15, 1.5e-5, 1e-4, 0.1 + 0.2, -0.0, 12.7, 1e22, 123456789.123, float("inf"), 5e-324,
              1201000000.0, 2.2250738585072014e-308, 9007199254740993.0, 0.4435]
    rows = [{"case": f"case_{i:04d}", "n": 1000 * i, "x": v, "mixed": i if i % 2 else i + 0.5,
             "with_nan": float("nan") if i == 3 else i, "status": "ok" if i % 3 else 'a, "b"\nc',
             "empty": float("nan")} for i, v in enumerate(floats)]
    columns = ["case", "n", "x", "mixed", "with_nan", "status", "empty"]
    assert summary_csv(columns, rows) == pd.DataFrame(rows, columns=columns).to_csv(index=False)



def test_the_sweep_command_never_imports_pandas(tmp_path):
    """`pyadore sweep` writes summary.csv and its report without pandas (its import was the
    largest serial part of the command's end, docs/sweeps.md "Scaling"); the workers it
    started before its own modules loaded ran the cases."""
    proc = subprocess.run([sys.executable, "-X", "importtime", "-m", "pyadore", "sweep", str(ROLLER), "--vary",
                           "applied_force_z=500,750", "--steps", "0", "-o", str(tmp_path / "s"), "--workers", "2"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    names = {line.split("|")[-1].strip() for line in proc.stderr.splitlines() if line.startswith("import time:")}
    assert "pyadore.sweeps.runner" in names and "pyadore.sweeps.execute" in names   # the client's own trace
    assert not [n for n in names if n == "pandas" or n.startswith("pandas.")]
    assert "2 cases: 2 finished" in proc.stdout
    frame = pd.read_csv(tmp_path / "s" / "summary.csv")
    assert list(frame["status"]) == ["ok", "ok"] and list(frame["applied_force_z"]) == [500, 750]


def test_cases_are_dispatched_longest_first():
    """The workers take the cases fastest shaft first (the longest step-0 solves: 90-137 ms of
    CPU at 25 000 rpm against 55-80 ms at 10 000-15 000 rpm for Appendix C), the grid's order
    within a speed, so that two workers end together (docs/sweeps.md, "Scaling"); without a
    varied speed the grid's order.  The folder keeps the grid's order (test_ball_results_...)."""
    from pyadore.deck import read_deck
    from pyadore.sweeps.runner import dispatch_order

    deck = read_deck(BALL)
    varied = [parse_vary("applied_force_z=1000,2000", deck), parse_vary("inner_race_speed=10000,25000,15000", deck)]
    cases = make_cases(varied)
    order = dispatch_order(cases, varied)
    assert [(c.params["inner_race_speed"], c.params["applied_force_z"]) for c in order] == [
        (25000, 1000), (25000, 2000), (15000, 1000), (15000, 2000), (10000, 1000), (10000, 2000)]
    assert sorted(c.case_id for c in order) == [c.case_id for c in cases]
    loads = [parse_vary("applied_force_z=3000,1000,2000", deck)]
    assert dispatch_order(make_cases(loads), loads) == make_cases(loads)


def test_the_workers_take_the_cases_by_the_costs_learnt_from_those_finished():
    """runner.CostModel (docs/sweeps.md, "Scaling, nineteenth session"): before LEARN_AFTER
    cases finished, the cheap estimate's order (the faster shaft first, the grid's order within
    a speed); then, within a speed, the case of the highest learnt cost first - the loads'
    additive effects from the finished cases' CPU times, here costs made additive so that the
    learnt effects are exact: a + b(Fz) + c(Fx).  A value no finished case had adds nothing; a
    case without a finite cost teaches nothing; a zipped field that repeats another adds
    nothing (one backfitting pass).  execute._Pending takes the job of the highest rank, a
    None only once no job is left."""
    import queue

    from pyadore.sweeps.execute import _Pending
    from pyadore.sweeps.runner import CostModel, dispatch_order

    deck = read_deck(BALL)
    varied = [parse_vary("inner_race_speed=10000,25000", deck), parse_vary("applied_force_z=1000,2000,3000", deck),
              parse_vary("applied_force_x=3000,4500", deck)]
    cases = make_cases(varied)
    order = dispatch_order(cases, varied)
    model = CostModel(order, varied)

    def taken(model) -> list:
        pending = _Pending(model.rank)
        for case in order:
            pending.put((case.case_id,))
        pending.put(None)
        out = [pending.get() for _ in range(len(order) + 1)]
        with pytest.raises(queue.Empty):
            pending.get_nowait()
        assert out[-1] is None
        return [job[0] for job in out[:-1]]

    assert taken(model) == [c.case_id for c in order]  # nothing learnt yet: the cheap estimate's order
    b = {1000: 0.030, 2000: 0.0, 3000: 0.010}
    c = {3000: 0.0, 4500: 0.020}

    def cost(case):
        return 0.05 + b[case.params["applied_force_z"]] + c[case.params["applied_force_x"]]

    fast = [case for case in order if case.params["inner_race_speed"] == 25000]
    for case in fast[:CostModel.LEARN_AFTER - 1]:
        model.add(case.case_id, cost(case))
    model.add(fast[-1].case_id, float("nan"))  # teaches nothing
    model.add(fast[-1].case_id, None)
    assert model.estimate is None and model.cost(fast[-1].case_id) is None
    for case in fast:  # every value of both loads seen once at 25 000 rpm
        model.add(case.case_id, cost(case))
    for case in cases:
        assert model.cost(case.case_id) == pytest.approx(cost(case), abs=1e-12)
    slow = sorted((case for case in order if case.params["inner_race_speed"] == 10000), key=cost, reverse=True)
    ranked = taken(model)
    assert ranked[:len(fast)] == [case.case_id for case in sorted(fast, key=cost, reverse=True)]
    assert ranked[len(fast):] == [case.case_id for case in slow]  # the faster shaft still first
    # a value no finished case had adds nothing; a zipped field repeating another adds nothing
    zipped = [parse_vary("applied_force_z=1000,2000,3000,4000,5000", deck),
              parse_vary("applied_force_x=1000,2000,3000,4000,5000", deck)]
    zcases = make_cases(zipped, zip_values=True)
    zmodel = CostModel(dispatch_order(zcases, zipped), zipped)
    for case, value in zip(zcases, (0.1, 0.2, 0.3, 0.4)):
        zmodel.add(case.case_id, value)
    assert [zmodel.cost(case.case_id) for case in zcases] == pytest.approx([0.1, 0.2, 0.3, 0.4, 0.25])
    fifo = _Pending()
    for job in ((1,), None, (2,)):
        fifo.put(job)
    assert [fifo.get(), fifo.get(), fifo.get()] == [(1,), (2,), None]


def test_a_fresh_sweep_folder_is_not_searched_and_its_pending_manifest_follows_the_first_job(tmp_path, monkeypatch):
    """A sweep into a folder without cases/ looks for no finished case and no earlier case file
    (_Sweep._fresh: the client's path to its first job), and writes the manifest listing every
    case pending once its first job is out (docs/sweeps.md, "Scaling, nineteenth session");
    a second sweep into the folder still resumes (nothing run again) and a case folder's stale
    print is still removed before a case of a folder not fresh is recorded."""
    from pyadore.sweeps import execute, runner

    seen: list = []
    original = execute.run_local

    def spy(jobs, pool, on_result, count, **kwargs):
        def watched():
            for job in jobs:
                seen.append((job[0], (folder / "manifest.json").exists()))
                yield job
        original(watched(), pool, on_result, count, **kwargs)

    folder = tmp_path / "s"
    monkeypatch.setattr(runner, "run_local", spy)
    looked: list = []
    real = runner._Sweep._load_finished
    monkeypatch.setattr(runner._Sweep, "_load_finished", lambda self: (looked.append(1), real(self)))
    grid = {"applied_force_z": [500, 750]}
    pyadore.sweep(ROLLER, grid, folder, steps=0, workers=1, progress=False)
    assert [exists for _, exists in seen] == [False, True] and looked == []
    manifest = json.loads((folder / "manifest.json").read_text())
    assert [c["status"] for c in manifest["cases"]] == ["ok", "ok"]
    events = (folder / "events.log").read_text()
    pyadore.sweep(ROLLER, grid, folder, steps=0, workers=1, progress=False)
    assert looked == [1] and (folder / "events.log").read_text() == events  # resumed: nothing run
    run, cases = _roller_sweep(folder, "applied_force_z=500,750")
    run.open_folder()
    assert not run._fresh
    stale = folder / "cases" / cases[0].case_id / "case.nc"
    stale.write_bytes(b"old")
    run.record(cases[0], "engine-failure", error="stopped", duration=0.1, worker="w:1")
    assert not stale.exists() and not (folder / "cases" / cases[0].case_id / "case.prt").exists()


def test_the_deck_digest_is_sha256_without_openssl():
    """sweep.json's deck_sha256 is hashlib's SHA-256 digest, computed without importing hashlib
    (OpenSSL's library: 3-6 ms of the client's path to its first job)."""
    import hashlib

    from pyadore.sweeps.runner import _sha256_hex

    for data in (b"", b"abc", BALL.read_bytes()):
        assert _sha256_hex(data) == hashlib.sha256(data).hexdigest()
    probe = "import sys, pyadore.sweeps.runner as r; r._sha256_hex(b'x'); print('hashlib' in sys.modules)"
    proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "False"


def test_the_sweep_client_starts_without_numpy():
    """What the `pyadore sweep` command imports before its first case goes to a worker - the
    command line (its options from the option table's cached copy), the runner, the deck
    reader, the result columns - imports neither numpy nor the engine (0.15 s of CPU on the
    serial path to the first case, docs/sweeps.md "Scaling"); the fork server does."""
    from pyadore.options import run_options

    run_options()  # the table's copy is written (it is, by any earlier command)
    probe = ("import sys, pyadore.cli, pyadore.sweeps.runner, pyadore.sweeps.results; "
             "print(sorted(m for m in ('numpy', 'pyadore._engine', 'pandas') if m in sys.modules))")
    proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


def test_write_atomic_writes_the_whole_file_or_nothing(tmp_path, monkeypatch):
    """store.write_atomic (every file of a sweep folder): the exact bytes, an ordinary file's
    permissions (0o666 less the umask, as open() gives), the old file replaced whole, no
    temporary left; a temporary name that is taken is passed over (O_EXCL), never reused; a
    write that fails leaves the old file and no temporary."""
    from pyadore.sweeps import store

    path = tmp_path / "f.json"
    store.write_atomic(path, "é\r\nline\n")  # newline="" of the text stream it replaced: bytes as given
    assert path.read_bytes() == "é\r\nline\n".encode("utf-8")
    mask = os.umask(0)
    os.umask(mask)
    assert path.stat().st_mode & 0o777 == 0o666 & ~mask
    store.write_atomic(path, b"\x00bytes", durable=False)
    assert path.read_bytes() == b"\x00bytes"
    taken = tmp_path / f".f.json{store._TMP_TAG}{os.getpid()}-{next(store._counter) + 1}"
    taken.write_text("someone else's")
    store.write_atomic(path, "new")
    assert path.read_text() == "new" and taken.read_text() == "someone else's"
    taken.unlink()

    def full(fd, data):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(store.os, "write", full)
    with pytest.raises(OSError, match="No space"):
        store.write_atomic(path, "lost")
    monkeypatch.undo()
    assert path.read_text() == "new"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.json"]


def _roller_sweep(folder: Path, vary: str):
    """A sweep's state (runner._Sweep, no folder made yet) over Appendix D with one --vary, and its cases."""
    from pyadore.deck import parse_text
    from pyadore.sweeps.runner import _Sweep

    text = ROLLER.read_text()
    base, _ = parse_text(text, str(ROLLER))
    varied = [parse_vary(vary, base)]
    cases = make_cases(varied)
    return _Sweep(ROLLER, text, varied, cases, folder, 0, False, {}, base_deck=base), cases


def test_write_atomic_many_flushes_every_file_before_any_replaces_its_old_one(tmp_path, monkeypatch):
    """store.write_atomic_many (the sweep's end: manifest.json and summary.csv flushed at the
    same time): the exact bytes of each, every file flushed (fsync) before the first rename,
    renamed in the order given, no temporary left; a flush that fails renames none, leaves the
    old files and removes every temporary."""
    from pyadore.sweeps import store

    a, b = tmp_path / "manifest.json", tmp_path / "summary.csv"
    a.write_text("old a")
    b.write_text("old b")
    events: list = []
    fsync, replace = store.os.fsync, store.os.replace

    def logged_fsync(fd):
        fsync(fd)
        events.append(("fsync", fd))

    def logged_replace(src, dst):
        events.append(("replace", Path(dst).name))
        replace(src, dst)

    monkeypatch.setattr(store.os, "fsync", logged_fsync)
    monkeypatch.setattr(store.os, "replace", logged_replace)
    store.write_atomic_many([(a, "é new a\n"), (b, b"new b\n")])
    assert a.read_bytes() == "é new a\n".encode("utf-8") and b.read_bytes() == b"new b\n"
    assert [e[0] for e in events] == ["fsync", "fsync", "replace", "replace"]
    assert [e[1] for e in events[2:]] == ["manifest.json", "summary.csv"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["manifest.json", "summary.csv"]
    monkeypatch.undo()

    def failing(fd):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(store.os, "fsync", failing)
    with pytest.raises(OSError, match="Input/output"):
        store.write_atomic_many([(a, "lost a"), (b, "lost b")])
    monkeypatch.undo()
    assert a.read_bytes() == "é new a\n".encode("utf-8") and b.read_bytes() == b"new b\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["manifest.json", "summary.csv"]


def test_the_path_to_the_first_job_flushes_nothing_and_sweep_json_precedes_every_case(tmp_path, monkeypatch):
    """The sweep's start writes sweep.json, the pending manifest and the case decks without
    fsync (the path to the first job is serial; docs/sweeps.md, "Scaling, eighteenth
    session"); sweep.json is flushed before the first case's print, every print before its
    result.json replaces anything, and the end flushes the manifest and the summary."""
    from pyadore.sweeps import store

    flushed: list = []
    fsync = store.os.fsync

    def logged(fd):
        fsync(fd)
        flushed.append(Path(os.readlink(f"/proc/self/fd/{fd}")).name)

    monkeypatch.setattr(store.os, "fsync", logged)
    run, cases = _roller_sweep(tmp_path / "s", "applied_force_z=500,750")
    run.open_folder()
    run.load_finished()
    run.write_manifest(durable=False)
    for case in cases:
        run.prepare(case)
    assert flushed == [] and (tmp_path / "s" / "sweep.json").is_file()
    run.record(cases[0], "ok", duration=0.1, worker="w:1", print_text="print 1")
    run.record(cases[1], "ok", duration=0.1, worker="w:1", print_text="print 2")
    assert [f.split(".tmp-")[0] for f in flushed] == ["sweep.json", ".case.prt", ".case.prt"]
    flushed.clear()
    run.write_end()
    assert sorted(f.split(".tmp-")[0] for f in flushed) == [".manifest.json", ".summary.csv"]
    assert json.loads((tmp_path / "s" / "sweep.json").read_text()) == run.definition


def test_the_pool_waits_for_its_processes_on_their_pidfd(monkeypatch):
    """The pool's end waits for its workers and their fork server blocked on a descriptor of
    each pid (execute._wait_for), not by 1 ms polls: a child that sleeps 0.3 s is seen ended
    after one wait, without sleeps in between; a timeout raises TimeoutExpired."""
    import subprocess
    import sys

    from pyadore.sweeps import execute

    if not hasattr(os, "pidfd_open"):
        pytest.skip("no pidfd on this system")
    sleeps: list = []
    monkeypatch.setattr(execute.time, "sleep", lambda s: sleeps.append(s))
    proc = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(0.3)"])
    child = execute._Child(proc.pid)
    with pytest.raises(subprocess.TimeoutExpired):
        child.wait(timeout=0.01)
    assert child.wait(timeout=60) == 0
    assert sleeps == []
    proc.returncode = 0  # reaped by the child's waitpid: Popen must not wait for it again


def test_the_manifest_lists_every_case_as_encoded_when_it_last_changed(tmp_path):
    """manifest.json's case lines are encoded once per entry (the client rewrites it after the
    cases while the workers run; docs/sweeps.md, "Scaling"): its text after cases finish,
    finish again (a new entry) and stay pending is the text of every case's current entry."""
    run, cases = _roller_sweep(tmp_path / "s", "applied_force_z=500,750,1000")
    run.open_folder()
    for case in cases:
        assert run.prepare(case) is not None  # its folder and deck

    def expected() -> str:
        rows = [run.entries.get(c.case_id) or {"case": c.case_id, "params": c.params, "status": "pending",
                                               "duration_s": None, "error": "", "notes": [], "worker": "",
                                               "finished_at": None, "results": {}} for c in cases]
        written = json.loads((tmp_path / "s" / "manifest.json").read_text())
        counts: dict = {}
        for r in rows:
            counts[r["status"]] = counts.get(r["status"], 0) + 1
        head = json.dumps({"sweep": run.definition, "updated_at": written["updated_at"], "counts": counts}, indent=1)
        return head[:-2] + ',\n "cases": [\n  ' + ",\n  ".join(json.dumps(r) for r in rows) + "\n ]\n}"

    run.write_manifest()
    assert (tmp_path / "s" / "manifest.json").read_text() == expected()
    run.record(cases[1], "engine-failure", error="no convergence", duration=0.5, worker="w:1")
    run.write_manifest()
    assert (tmp_path / "s" / "manifest.json").read_text() == expected()
    run.record(cases[1], "ok", duration=0.25, worker="w:2", results={"total_power_loss_W": 12.5},
               print_text="print")
    run.record(cases[2], "invalid", error="bad deck")
    run.write_manifest(durable=False)
    manifest = (tmp_path / "s" / "manifest.json").read_text()
    assert manifest == expected()
    assert [e["status"] for e in json.loads(manifest)["cases"]] == ["pending", "ok", "invalid"]


def test_a_result_json_lost_to_a_power_cut_is_recovered_from_the_print(tmp_path):
    """result.json is written without fsync (docs/sweeps.md, "Resume"): the print it vouches for
    was flushed to the disk before it, so a result.json that a power cut left empty or never
    wrote reads as absent and a resume takes the case's results from its print - the same
    results its worker gave (the step-0 case has no time averages: NaN) - without running it
    again; the summary is the same."""
    folder = tmp_path / "s"
    grid = {"applied_force_z": [500, 750, 1000]}
    pyadore.sweep(ROLLER, grid, folder, steps=0, workers=1, progress=False)
    summary = (folder / "summary.csv").read_text()
    events = (folder / "events.log").read_text()
    before = {c: json.loads((folder / "cases" / c / "result.json").read_text())
              for c in ("case_0001", "case_0002")}
    (folder / "cases" / "case_0001" / "result.json").write_text("")  # a power cut: renamed, data lost
    (folder / "cases" / "case_0002" / "result.json").unlink()        # or the rename lost
    frame = pyadore.sweep(ROLLER, grid, folder, steps=0, workers=1, progress=False)
    assert list(frame["status"]) == ["ok"] * 3
    assert (folder / "events.log").read_text() == events, "nothing ran again"
    assert (folder / "summary.csv").read_text() == summary
    for case, old in before.items():
        new = json.loads((folder / "cases" / case / "result.json").read_text())
        assert new["recovered"] is True and new["status"] == "ok"
        assert new["results"] == old["results"] and new["params"] == old["params"]
