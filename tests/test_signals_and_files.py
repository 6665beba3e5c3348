"""Signals and files (issue #28 item 4): what a stop signal, a refused or failed run leaves
at the output path, the run's paths, sweeps killed or failing, diff and plot inputs.

The rule (docs/dynamics.md "Signals", README): SIGINT (Ctrl-C), SIGTERM and SIGHUP stop a
run of ``adore`` or ``pyadore run`` at its next step boundary; the program then ends by
that signal (the parent sees a death by it: a shell's exit status 128 + its number).  Seen
after the first time step ended: the print and plot-data file are kept, marked incomplete.
Seen before (step 0, a run without time steps): no file is left.  Seen at the last step:
the files are complete.  Never a traceback, never a ``.part`` left behind.  As a run starts
the output path is cleared, so an older print never poses as a refused, failed or stopped
run's.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

import pyadore
from conftest import deck_with_steps
from pyadore.cli import cli
from pyadore.errors import AdoreEngineError, AdoreInputError, AdoreInterrupted
from pyadore.printout import read_print
from pyadore.results import element_path, results_path
from pyadore.timehistory import history_path, read_history_csv

ROOT = Path(__file__).resolve().parent.parent
BALL = ROOT / "decks" / "appendix_c_ball.inp"
ROLLER = ROOT / "decks" / "appendix_d_roller.inp"
FRONT_ENDS = ["adore", "pyadore"]
NAMES = {signal.SIGINT: "SIGINT (Ctrl-C)", signal.SIGTERM: "SIGTERM", signal.SIGHUP: "SIGHUP"}
STALE = "an older run's file\n"


def _cmd(front_end: str, adore_exe: Path, deck: Path, out: Path, *args) -> list[str]:
    if front_end == "adore":
        return [str(adore_exe), str(deck), str(out), *map(str, args)]
    return [sys.executable, "-m", "pyadore", "run", str(deck), "-o", str(out), *map(str, args)]


def _start(cmd) -> subprocess.Popen:
    return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _wait_for(proc: subprocess.Popen, condition, what: str, timeout: float = 120.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if proc.poll() is not None:
            out, err = proc.communicate()
            pytest.fail(f"the run ended (status {proc.returncode}) before {what}: {out}{err}")
        if time.monotonic() > deadline:
            proc.kill()
            pytest.fail(f"no {what} within {timeout} s")
        time.sleep(0.001)


def _handlers_installed(pid: int) -> bool:
    """The process catches SIGINT, SIGTERM and SIGHUP (Linux: SigCgt of /proc/PID/status)."""
    try:
        with open(f"/proc/{pid}/status", encoding="ascii") as fh:
            caught = next(int(line.split()[1], 16) for line in fh if line.startswith("SigCgt:"))
    except (OSError, StopIteration):
        return False
    return all(caught >> (s - 1) & 1 for s in NAMES)


def _finish(proc: subprocess.Popen) -> tuple[int, str, str]:
    out, err = proc.communicate(timeout=300)
    return proc.returncode, out, err


def _stale(out: Path) -> list[Path]:
    """Older outputs at the print path ``out``: print, plot-data file, element file, netCDF
    results file and their .part files."""
    files = [out, history_path(out), element_path(out), results_path(out)]
    paths = [q for p in files for q in (p, p.with_name(p.name + ".part"))]
    for p in paths:
        p.write_text(STALE)
    return paths


def _kept(stem: str, front_end: str) -> list[str]:
    """The files a ball run with time steps keeps at print path ``<stem>.prt``: the print,
    plot-data and element files, and (pyadore) the netCDF results file."""
    names = [f"{stem}.elements.bin", f"{stem}.hist.csv", f"{stem}.prt"]
    return sorted(names + ([f"{stem}.nc"] if front_end == "pyadore" else []))


def _outputs(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if not p.name.endswith(".inp"))


def _no_traceback(stderr: str) -> None:
    assert "Traceback" not in stderr and "Error termination" not in stderr and "Backtrace" not in stderr, stderr


def _steps_printed(part: Path) -> int:
    """Time steps printed so far in the print being written (its step summaries after step 0)."""
    try:
        return part.read_bytes().count(b"4. Time Step Summary") - 1
    except OSError:
        return -1


# --- stop signals at several moments of a run --------------------------------------------------

@pytest.mark.parametrize("front_end", FRONT_ENDS)
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_signal_in_step_0_ends_the_run_without_any_file(tmp_path, adore_exe, front_end, sig):
    """A signal while the run reads its deck and solves step 0 (the older print at the path is
    gone: the run has started): the program ends by the signal, no print, no plot-data file,
    no .part, not the older files either."""
    out = tmp_path / "c.prt"
    stale = _stale(out)
    proc = _start(_cmd(front_end, adore_exe, BALL, out, "--steps", 50))
    _wait_for(proc, lambda: not stale[0].exists(), "the output path cleared")
    proc.send_signal(sig)
    code, stdout, stderr = _finish(proc)
    assert code == -sig, stderr
    _no_traceback(stderr)
    assert f"stopped by {NAMES[sig]} before the first time step ended: no print file written" in stderr
    assert "written" not in stdout
    assert _outputs(tmp_path) == []


@pytest.mark.parametrize("front_end", FRONT_ENDS)
def test_signal_in_a_run_without_time_steps_leaves_no_print(tmp_path, adore_exe, front_end):
    """--steps 0: the run has no step boundary to stop at; it ends by the signal and removes
    the print it finished rather than leave it posing as a run that was not stopped."""
    out = tmp_path / "s0.prt"
    stale = _stale(out)
    proc = _start(_cmd(front_end, adore_exe, BALL, out, "--steps", 0))
    _wait_for(proc, lambda: not stale[0].exists(), "the output path cleared")
    proc.send_signal(signal.SIGTERM)
    code, _stdout, stderr = _finish(proc)
    assert code == -signal.SIGTERM, stderr
    _no_traceback(stderr)
    assert "before the first time step ended: no print file written" in stderr
    assert _outputs(tmp_path) == []


@pytest.mark.parametrize("front_end", FRONT_ENDS)
@pytest.mark.parametrize("sig", [signal.SIGHUP, signal.SIGTERM])
def test_signal_in_the_time_steps_keeps_the_print_marked_incomplete(tmp_path, adore_exe, front_end, sig):
    out = tmp_path / "c.prt"
    _stale(out)
    proc = _start(_cmd(front_end, adore_exe, BALL, out, "--steps", 2000))
    part = out.with_name(out.name + ".part")
    _wait_for(proc, lambda: _steps_printed(part) >= 0, "the print being written")
    time.sleep(0.5)
    proc.send_signal(sig)
    code, _stdout, stderr = _finish(proc)
    assert code == -sig, stderr
    _no_traceback(stderr)
    assert f"stopped by {NAMES[sig]}: run incomplete after step " in stderr
    assert ": interrupted; kept: the print file" in stderr
    assert _outputs(tmp_path) == _kept("c", front_end)
    run = read_print(out)
    last = run.step_numbers[-1]
    assert 2 <= last < 2000 and run.incomplete.startswith(f"RUN INCOMPLETE after step {last} (tau = ")
    assert out.read_text().splitlines()[-1].endswith(": interrupted ***")
    frame, incomplete = read_history_csv(history_path(out))
    assert incomplete.startswith(f"RUN INCOMPLETE after step {last} ") and int(frame["step"].iloc[-1]) == last


@pytest.fixture(scope="module")
def every_step_deck(tmp_path_factory) -> Path:
    """Appendix C, 120 time steps, every step printed: the print being written shows where
    the run is."""
    path = tmp_path_factory.mktemp("every") / "every.inp"
    path.write_text(deck_with_steps(BALL.read_text(), 120, 1))
    return path


@pytest.mark.parametrize("front_end", FRONT_ENDS)
def test_signal_near_the_end_leaves_incomplete_or_complete_files_never_a_part(tmp_path, adore_exe, front_end,
                                                                             every_step_deck):
    """Ctrl-C within the last ten steps: the print is incomplete after one of them, or, when
    the signal came with the last step, complete; either way the program ends by SIGINT and
    its message says which."""
    n = 120
    out = tmp_path / "e.prt"
    part = out.with_name(out.name + ".part")
    proc = _start(_cmd(front_end, adore_exe, every_step_deck, out))
    _wait_for(proc, lambda: _steps_printed(part) >= n - 10, "step 110 printed")
    proc.send_signal(signal.SIGINT)
    code, _stdout, stderr = _finish(proc)
    assert code == -signal.SIGINT, stderr
    _no_traceback(stderr)
    assert _outputs(tmp_path) == _kept("e", front_end)
    run = read_print(out)
    frame, incomplete = read_history_csv(history_path(out))
    last = run.step_numbers[-1]
    assert int(frame["step"].iloc[-1]) == last
    if run.incomplete:
        assert n - 10 <= last < n and incomplete and "stopped by SIGINT (Ctrl-C): run incomplete after step" in stderr
    else:
        assert last == n and not incomplete and run.termination
        assert "SIGINT (Ctrl-C) came after the last time step" in stderr and "are complete" in stderr


@pytest.mark.parametrize("delay", [0.0, 0.1, 0.2, 0.3, 0.45])
def test_pyadore_ctrl_c_at_any_moment_gives_no_traceback(tmp_path, delay):
    """Ctrl-C from the moment the command's handlers are in place (before its imports) to
    the time steps: never a traceback, always the death by SIGINT, and the print absent,
    or kept and marked incomplete - never a .part.  2 000 steps (about 1.2 s of time steps on
    two free cores, more on one): every delay lands before the run's end (400 steps, the
    earlier count, ended before the signal of 0.45 s once the threads' wait got shorter)."""
    out = tmp_path / "m.prt"
    proc = _start(_cmd("pyadore", Path(), BALL, out, "--steps", 2000))
    _wait_for(proc, lambda: _handlers_installed(proc.pid), "the signal handlers")
    time.sleep(delay)
    proc.send_signal(signal.SIGINT)
    code, _stdout, stderr = _finish(proc)
    assert code == -signal.SIGINT, stderr
    _no_traceback(stderr)
    assert "pyadore: stopped by SIGINT (Ctrl-C)" in stderr or "SIGINT (Ctrl-C) came after" in stderr, stderr
    names = _outputs(tmp_path)
    assert names in ([], _kept("m", "pyadore")), names
    if names:
        assert read_print(out).incomplete or "came after the last time step" in stderr


def test_adore_ignored_signal_stays_ignored(tmp_path, adore_exe):
    """A signal the process was started with ignored (nohup: SIGHUP) does not stop it."""
    out = tmp_path / "n.prt"
    proc = subprocess.Popen(_cmd("adore", adore_exe, BALL, out, "--steps", 30), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGHUP, signal.SIG_IGN))
    _wait_for(proc, lambda: out.with_name("n.prt.part").exists() or out.exists(), "the print")
    proc.send_signal(signal.SIGHUP)
    code, _stdout, stderr = _finish(proc)
    assert code == 0, stderr
    assert not read_print(out).incomplete


# --- the library: deterministic moments through the progress function -------------------------

def _signal_at(step_wanted: int, sig=signal.SIGINT):
    def progress(step, n_steps, time_s):
        if step == step_wanted:
            os.kill(os.getpid(), sig)
    return progress


def test_library_signal_before_the_first_step_ended_leaves_no_file(tmp_path):
    out = tmp_path / "a.prt"
    _stale(out)
    with pytest.raises(AdoreInterrupted, match=r"stopped by SIGINT \(Ctrl-C\) before the first time step ended: "
                                               r"no print file written") as info:
        pyadore.run(BALL, steps=20, out=out, progress=_signal_at(1))
    assert info.value.signal == signal.SIGINT and info.value.status == 130 and info.value.print_path is None
    assert isinstance(info.value, AdoreEngineError)
    assert _outputs(tmp_path) == []


def test_library_signal_in_the_steps_keeps_an_incomplete_print(tmp_path):
    out = tmp_path / "b.prt"
    previous = signal.signal(signal.SIGTERM, lambda *a: None)   # a handler, as the pyadore command has
    try:
        with pytest.raises(AdoreInterrupted, match=r"stopped by SIGTERM: run incomplete after step 5 ") as info:
            pyadore.run(BALL, steps=20, out=out, progress=_signal_at(5, signal.SIGTERM))
    finally:
        signal.signal(signal.SIGTERM, previous)
    exc = info.value
    assert exc.status == 128 + signal.SIGTERM and exc.print_path == out
    assert list(exc.time_history["step"]) == list(range(6))
    assert read_print(out).incomplete.startswith("RUN INCOMPLETE after step 5 ")
    assert _outputs(tmp_path) == _kept("b", "pyadore")


def test_library_signal_at_the_last_step_keeps_the_complete_run(tmp_path):
    out = tmp_path / "c.prt"
    with pytest.raises(AdoreInterrupted, match="came after the last time step") as info:
        pyadore.run(BALL, steps=6, out=out, progress=_signal_at(6))
    assert info.value.print_path == out
    run = read_print(out)
    assert not run.incomplete and run.termination and run.step_numbers[-1] == 6
    assert _outputs(tmp_path) == _kept("c", "pyadore")


def test_library_leaves_default_signals_alone():
    """pyadore.run catches SIGINT (Python's KeyboardInterrupt) and SIGTERM/SIGHUP only where
    the process handles them: a script's SIGTERM still ends it at once."""
    from pyadore.progress import RunProgress

    assert signal.getsignal(signal.SIGTERM) is signal.SIG_DFL
    assert RunProgress(False).signals == (signal.SIGINT,)
    previous = signal.signal(signal.SIGHUP, lambda *a: None)
    try:
        assert RunProgress(False).signals == (signal.SIGINT, signal.SIGHUP)
    finally:
        signal.signal(signal.SIGHUP, previous)


# --- older outputs and the run's paths ---------------------------------------------------------

@pytest.mark.parametrize("front_end", FRONT_ENDS)
def test_refused_run_leaves_no_older_print(tmp_path, adore_exe, front_end):
    """A deck the engine refuses (exit 1): the print, plot-data file and .part files an
    earlier run left at the path are gone, none poses as this run's."""
    deck = tmp_path / "bad.inp"
    deck.write_text(BALL.read_text().replace("Rec 2.1      5.0000E-02", "Rec 2.1      x.0000E-02", 1))
    out = tmp_path / "old.prt"
    _stale(out)
    proc = subprocess.run(_cmd(front_end, adore_exe, deck, out, "--steps", 3), capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 1, proc.stderr
    assert "Rec 2.1" in proc.stderr
    _no_traceback(proc.stderr)
    assert _outputs(tmp_path) == []


def test_library_failed_and_refused_runs_leave_no_older_print(tmp_path):
    out = tmp_path / "lib.prt"
    _stale(out)
    with pytest.raises(AdoreInputError):
        pyadore.run(tmp_path / "missing.inp", out=out)
    assert _outputs(tmp_path) == []
    # a failed time integration: the print at the path is the new, incomplete one
    _stale(out)
    deck = tmp_path / "step5.inp"
    deck.write_text(BALL.read_text().replace("Rec 2.1      5.0000E-02 5.0000E-03 3.0000E-01",
                                             "Rec 2.1      5.0000E+03 5.0000E+03 5.0000E+03", 1))
    with pytest.raises(AdoreEngineError, match="integration stopped"):
        pyadore.run(deck, steps=5, out=out)
    assert _outputs(tmp_path) == _kept("lib", "pyadore")
    assert STALE not in out.read_text() and read_print(out).incomplete
    assert read_history_csv(history_path(out))[1]


@pytest.mark.parametrize("front_end", FRONT_ENDS)
def test_output_that_is_an_input_is_refused(tmp_path, adore_exe, front_end):
    """-o DECK, an output linked to the deck, the traction table as output: refused before
    anything is read or written; the inputs unchanged."""
    deck = tmp_path / "deck.inp"
    deck.write_bytes(BALL.read_bytes())
    table = tmp_path / "table.txt"
    table.write_text("0.0 0.0\n1.0 0.05\n5.0 0.07\n")
    (tmp_path / "link.prt").symlink_to(deck)
    cases = [(deck, [], "the print file would overwrite the deck"),
             (tmp_path / "link.prt", [], "the print file would overwrite the deck"),
             (table, ["--traction-table", table], "would overwrite the traction-slip table")]
    for out, extra, message in cases:
        proc = subprocess.run(_cmd(front_end, adore_exe, deck, out, "--steps", 0, *extra), capture_output=True,
                              text=True, timeout=300)
        assert proc.returncode == 1 and message in proc.stderr and str(out) in proc.stderr, proc.stderr
        _no_traceback(proc.stderr)
    assert deck.read_bytes() == BALL.read_bytes()
    assert table.read_text() == "0.0 0.0\n1.0 0.05\n5.0 0.07\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["deck.inp", "link.prt", "table.txt"]


def test_adore_default_print_that_is_the_deck_is_refused(tmp_path, run_exe):
    """`adore x.prt` would write its print onto the deck x.prt itself."""
    deck = tmp_path / "x.prt"
    deck.write_bytes(BALL.read_bytes())
    proc = run_exe(deck, "--steps", 0)
    assert proc.returncode == 1 and "would overwrite the deck" in proc.stderr
    assert deck.read_bytes() == BALL.read_bytes()
    # the plot-data file of a print path may not be the deck either
    hist_deck = tmp_path / "y.hist.csv"
    hist_deck.write_bytes(BALL.read_bytes())
    proc = run_exe(hist_deck, tmp_path / "y.prt", "--steps", 2)
    assert proc.returncode == 1 and "the plot-data file would overwrite the deck" in proc.stderr
    assert hist_deck.read_bytes() == BALL.read_bytes()


@pytest.mark.parametrize("front_end", FRONT_ENDS)
def test_output_directory_is_refused_before_the_run(tmp_path, adore_exe, front_end):
    """A directory as the print file: refused at once (not after every time step)."""
    target = tmp_path / "dir.prt"
    target.mkdir()
    cmd = _cmd(front_end, adore_exe, BALL, target, "--steps", 2000)
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert proc.returncode in (1, 2) and str(target) in proc.stderr, proc.stderr
    assert "directory" in proc.stderr
    _no_traceback(proc.stderr)
    if front_end == "adore":  # pyadore's command line refuses it itself (click: exit 2)
        assert proc.returncode == 1 and "the print file would replace a directory" in proc.stderr
        assert time.monotonic() - start < 2.0, "refused only after the steps ran"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dir.prt"] and not any(target.iterdir())
    with pytest.raises(AdoreInputError, match="the print file would replace a directory"):
        pyadore.run(BALL, steps=2000, out=target)


def test_fifo_inputs_are_refused_with_the_file_named(tmp_path, adore_exe):
    """A FIFO as the deck (or traction table, or a diff, plot, validate or sweep input) would
    make the reader wait for a writer for ever: refused at once, naming the file."""
    fifo = tmp_path / "deck.fifo"
    os.mkfifo(fifo)
    message = f"{fifo}: the deck is a FIFO (named pipe), not a regular file"
    proc = subprocess.run([str(adore_exe), str(fifo), str(tmp_path / "f.prt")], capture_output=True, text=True,
                          timeout=30)
    assert proc.returncode == 1 and message in proc.stderr
    proc = subprocess.run([str(adore_exe), str(BALL), str(tmp_path / "f.prt"), "--traction-table", str(fifo)],
                          capture_output=True, text=True, timeout=30)
    assert proc.returncode == 1 and f"{fifo}: the traction-slip table is a FIFO" in proc.stderr
    with pytest.raises(AdoreInputError, match="the deck is a FIFO"):
        pyadore.run(fifo, out=tmp_path / "g.prt")
    runner = CliRunner()
    for args, text in ((["run", str(fifo), "-o", str(tmp_path / "h.prt")], "the deck is a FIFO"),
                       (["validate", str(fifo)], "the deck is a FIFO"),
                       (["diff", str(fifo), str(ROOT / "golden" / "appendix_c_ball.prt")], "is not a regular file"),
                       (["diff", str(ROOT / "golden" / "appendix_c_ball.prt"), str(ROOT / "golden" / "appendix_c_ball.prt"),
                         "--tolerances", str(fifo)], "the tolerance file is not a regular file"),
                       (["plot", str(fifo), "-o", str(tmp_path / "p.pdf")], "is a FIFO"),
                       (["sweep", str(fifo), "--vary", "inner_race_speed=1000", "-o", str(tmp_path / "sw")],
                        "the deck is not a regular file")):
        result = runner.invoke(cli, args)
        assert result.exit_code in (1, 2) and text in result.output, (args, result.output)
        assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    assert sorted(p.name for p in tmp_path.iterdir()) == ["deck.fifo"]


# --- sweeps ------------------------------------------------------------------------------------

def _events(folder: Path) -> list[list[str]]:
    path = folder / "events.log"
    return [line.split() for line in path.read_text().splitlines()] if path.exists() else []


def test_killed_sweep_client_leaves_no_traceback_and_no_manifest_behind_its_events(tmp_path):
    """SIGKILL of the sweep's client alone: its workers end quietly (no BrokenPipeError
    traceback) and every case of events.log is finished in manifest.json."""
    folder = tmp_path / "s"
    speeds = ",".join(str(50000 + 250 * k) for k in range(60))
    proc = subprocess.Popen([sys.executable, "-m", "pyadore", "sweep", str(ROLLER), "--vary",
                             f"inner_race_speed={speeds}", "--steps", "0", "-o", str(folder), "--workers", "2"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _wait_for(proc, lambda: len(_events(folder)) >= 3, "three finished cases")
    proc.kill()
    _out, err = proc.communicate(timeout=120)   # returns once the workers closed the shared stderr too
    assert "Traceback" not in err and "BrokenPipe" not in err, err
    manifest = json.loads((folder / "manifest.json").read_text())
    status = {c["case"]: c["status"] for c in manifest["cases"]}
    logged = [e[1] for e in _events(folder)]
    assert logged and all(status[c] == "ok" for c in logged), (logged, manifest["counts"])


def test_failed_sweep_case_keeps_the_print_its_message_names(tmp_path):
    """A case whose time integration fails at once: its message names the incomplete print
    and plot-data file kept in the case folder (the worker's own folder is gone)."""
    folder = tmp_path / "f"
    result = CliRunner().invoke(cli, ["sweep", str(BALL), "--vary", "step_min=5000", "--vary", "step_initial=5000",
                                      "--vary", "step_max=5000", "--steps", "3", "-o", str(folder), "--workers", "1"])
    assert result.exit_code == 1, result.output
    (entry,) = json.loads((folder / "manifest.json").read_text())["cases"]
    case = folder / "cases" / "case_0001"
    assert entry["status"] == "engine-failure" and "pyadore-case-" not in entry["error"]
    assert f"kept: the print file {case / 'incomplete.prt'}" in entry["error"]
    assert f"its plot-data file {case / 'incomplete.hist.csv'}" in entry["error"]
    assert read_print(case / "incomplete.prt").incomplete and read_history_csv(case / "incomplete.hist.csv")[1]
    assert not (case / "case.prt").exists()
    assert [e[1:3] for e in _events(folder)] == [["case_0001", "engine-failure"]]


# --- diff and plot inputs ----------------------------------------------------------------------

@pytest.fixture(scope="module")
def roller_print(tmp_path_factory) -> Path:
    """Appendix D's step-0 print (a print without time steps)."""
    return pyadore.run(ROLLER, steps=0, out=tmp_path_factory.mktemp("roller") / "r.prt").print_path


def test_diff_refuses_prints_of_different_bearing_types(roller_print):
    runner = CliRunner()
    for run, golden in ((roller_print, ROOT / "golden" / "appendix_c_ball.prt"),
                        (ROOT / "golden" / "appendix_c_ball.prt", ROOT / "golden" / "appendix_d_roller.prt")):
        result = runner.invoke(cli, ["diff", str(run), str(golden)])
        assert result.exit_code == 2, result.output
        assert "prints of different bearing types cannot be compared" in result.output
        assert "outside tolerance" not in result.output
    same = runner.invoke(cli, ["diff", str(roller_print), str(ROOT / "golden" / "appendix_d_roller.prt")])
    assert same.exit_code == 1 and "different bearing types" not in same.output   # compared (NaN values)


def test_diff_refuses_an_empty_or_misspelt_tolerance_file(tmp_path, roller_print):
    golden = ROOT / "golden" / "appendix_d_roller.prt"
    for name, text, message in (("empty.toml", "", "no tolerances in the tolerance file"),
                                ("comments.toml", "# nothing yet\n", "no tolerances in the tolerance file"),
                                ("rules.toml", "[[rules]]\nrel = 0.5\n", "no tolerances in the tolerance file"),
                                ("extra.toml", "[defaults]\nrel = 0.5\n[[rules]]\nrel = 1\n", "unknown key 'rules'"),
                                ("colums.toml", "[[rule]]\ncolums = ['x']\nrel = 0.5\n", "rule 1: unknown key 'colums'")):
        path = tmp_path / name
        path.write_text(text)
        result = CliRunner().invoke(cli, ["diff", str(roller_print), str(golden), "--tolerances", str(path)])
        assert result.exit_code == 2 and message in result.output and str(path) in result.output, result.output


def test_plot_ignores_a_plot_data_file_of_another_run(tmp_path, roller_print, short_ball_deck):
    """A ball run's .hist.csv beside a roller print (same stem): not the print's; its time
    figures are not drawn from it and a note says why."""
    from pyadore.plots.sources import load

    ball = pyadore.run(short_ball_deck, steps=4, out=tmp_path / "ball.prt")
    roller = tmp_path / "r.prt"
    roller.write_bytes(roller_print.read_bytes())
    history_path(roller).write_bytes(history_path(ball.print_path).read_bytes())
    src = load(roller)
    assert src.history is None
    assert any("not used: it ends at step 4, the print has no time steps" in n for n in src.notes), src.notes
    result = CliRunner().invoke(cli, ["plot", str(roller), "-o", str(tmp_path / "r.pdf")])
    assert result.exit_code == 0 and "r.hist.csv not used" in result.output
    # the complete 4-step run's plot-data file beside a print stopped after the same step 4
    # (same steps, same times) is not its own either
    def stop_at_4(step, n_steps, time_s):
        if step == 4:
            raise KeyboardInterrupt

    incomplete = tmp_path / "i.prt"
    with pytest.raises(AdoreInterrupted):
        pyadore.run(short_ball_deck, steps=6, out=incomplete, progress=stop_at_4)
    assert read_print(incomplete).step_numbers == [0, 4] and load(incomplete).history is not None
    history_path(incomplete).write_bytes(history_path(ball.print_path).read_bytes())
    src = load(incomplete)
    assert src.history is None and any("the print says its run stopped early" in n for n in src.notes), src.notes
