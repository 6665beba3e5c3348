"""The run option ``threads`` (docs/performance.md, "Threads"): the rolling elements' contacts of
every derivative call on an OpenMP team, the sums over the elements in element order, so a
run's files are the same bit for bit on any number of threads - the print apart from its
listing line naming the threads.  Also: the default count (OMP_NUM_THREADS, else the
processors, at most 4), the passive wait policy both front ends set, and a sweep's cases on
one thread each.  The engine's own checks (loads and rates on 1, 2 and 5 threads) are in
fortran/tests/test_forces.f90 and test_roller_dynamics.f90."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

import pyadore
from builds import checks_build

THREADS_LINE = "  DERIVATIVE ON "


def _run(exe, deck, out, *args, env=None):
    proc = subprocess.run([str(exe), str(deck), str(out), *map(str, args)], capture_output=True, text=True,
                          timeout=600, env=env)
    assert proc.returncode == 0, proc.stderr
    return out.read_text().splitlines()


def _threads_line(lines):
    found = [line for line in lines if line.startswith(THREADS_LINE)]
    assert len(found) == 1, found
    return found[0]


def _same_but_threads(a, b):
    """The two prints differ in their threads line only."""
    assert len(a) == len(b)
    differ = [(x, y) for x, y in zip(a, b) if x != y]
    assert len(differ) == 1 and all(x.startswith(THREADS_LINE) for x in differ[0]), differ[:3]


@pytest.mark.parametrize("kind", ["ball", "roller"])
def test_files_same_on_one_and_two_threads(kind, adore_exe, short_ball_deck, short_roller_deck, tmp_path):
    """Appendix C (60 steps) and D (60 steps) on 1 and 2 threads: the prints equal but for
    the listing's threads line, the plot-data files and (ball) the element files byte for
    byte."""
    deck = short_ball_deck if kind == "ball" else short_roller_deck
    one = _run(adore_exe, deck, tmp_path / "one.prt", "--threads", 1)
    two = _run(adore_exe, deck, tmp_path / "two.prt", "--threads", 2)
    assert _threads_line(one).startswith(THREADS_LINE + "1 THREAD ")
    assert _threads_line(two).startswith(THREADS_LINE + "2 THREADS ")
    _same_but_threads(one, two)
    assert any("Total Derivative Calls" in line for line in one)
    assert (tmp_path / "one.hist.csv").read_bytes() == (tmp_path / "two.hist.csv").read_bytes()
    if kind == "ball":
        assert (tmp_path / "one.elements.bin").read_bytes() == (tmp_path / "two.elements.bin").read_bytes()


def test_extension_on_two_threads_equals_the_executable(adore_exe, build_dir, short_ball_deck, tmp_path):
    """pyadore.run(threads=2) (the f2py extension, linked with OpenMP) prints what the
    executable prints on one thread.  `make debug` pairs a debug `adore` with the release
    extension, whose round-off differs (tests/builds.py; after 60 steps of the implicit method
    their step sequences part): there the extension on 2 threads is held to itself on 1."""
    if checks_build(build_dir):
        one = pyadore.run(short_ball_deck, out=tmp_path / "ext1.prt", threads=1, progress=False)
        one = one.print_path.read_text().splitlines()
    else:
        one = _run(adore_exe, short_ball_deck, tmp_path / "exe.prt", "--threads", 1)
    result = pyadore.run(short_ball_deck, out=tmp_path / "ext.prt", threads=2, progress=False)
    two = result.print_path.read_text().splitlines()
    assert _threads_line(two).startswith(THREADS_LINE + "2 THREADS ")
    _same_but_threads(one, two)


def test_default_threads(adore_exe, short_ball_deck, tmp_path):
    """threads 0 (the default): OMP_NUM_THREADS when set, else the processors this process
    may run on, at most 4."""
    env = {k: v for k, v in os.environ.items() if k != "OMP_NUM_THREADS"}
    auto = _run(adore_exe, short_ball_deck, tmp_path / "auto.prt", "--steps", 1, env=env)
    expected = min(len(os.sched_getaffinity(0)), 4)
    assert _threads_line(auto).startswith(f"{THREADS_LINE}{expected} THREAD")
    env["OMP_NUM_THREADS"] = "3"
    three = _run(adore_exe, short_ball_deck, tmp_path / "three.prt", "--steps", 1, env=env)
    assert _threads_line(three).startswith(THREADS_LINE + "3 THREADS ")
    given = _run(adore_exe, short_ball_deck, tmp_path / "given.prt", "--steps", 1, "--threads", 5, env=env)
    assert _threads_line(given).startswith(THREADS_LINE + "5 THREADS ")


def _spin_count(cmd, policy, spin=None):
    """GOMP_SPINCOUNT as libgomp reports it (OMP_DISPLAY_ENV) for a process started with
    OMP_WAIT_POLICY=policy and GOMP_SPINCOUNT=spin (None: unset)."""
    env = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
    env["OMP_DISPLAY_ENV"] = "verbose"
    if policy is not None:
        env["OMP_WAIT_POLICY"] = policy
    if spin is not None:
        env["GOMP_SPINCOUNT"] = spin
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600, env=env)
    assert proc.returncode == 0, proc.stderr
    found = [line.split("=", 1)[1].strip().strip("'") for line in (proc.stdout + proc.stderr).splitlines()
             if line.strip().startswith("GOMP_SPINCOUNT")]
    assert len(found) == 1, proc.stderr
    return int(found[0])


def test_wait_policy_short_spin_unless_set(adore_exe):
    """Both front ends load OpenMP with a short spin (3 000 rounds, then sleep) between the
    parallel loops unless the environment sets the wait policy or the spin count: the user's
    setting is kept as given."""
    exe = [str(adore_exe), "--version"]
    py = [sys.executable, "-c", "import pyadore._core.base as b; b._engine()"]
    for cmd in (exe, py):
        assert _spin_count(cmd, None) == 3000
        assert _spin_count(cmd, "passive") == 0
        assert _spin_count(cmd, "active") > 3000
        assert _spin_count(cmd, None, "0") == 0
        assert _spin_count(cmd, None, "50000") == 50000


def test_sweep_case_on_one_thread(short_ball_deck):
    """A sweep's case runs on one thread (its workers share the cores) unless the sweep's
    options give threads."""
    from pyadore.sweeps.execute import run_case

    text = short_ball_deck.read_text()
    one = run_case("c1", text, 1)
    assert one["status"] == "ok", one["error"]
    assert _threads_line(one["print_text"].splitlines()).startswith(THREADS_LINE + "1 THREAD ")
    two = run_case("c2", text, 1, {"threads": 2})
    assert two["status"] == "ok", two["error"]
    assert _threads_line(two["print_text"].splitlines()).startswith(THREADS_LINE + "2 THREADS ")


FORK_SCRIPT = """
import os, sys
import pyadore
deck, out = sys.argv[1], sys.argv[2]
pyadore.run(deck, out=out + "/parent.prt", steps=2, threads=2, progress=False)
pid = os.fork()
if pid == 0:
    result = pyadore.run(deck, out=out + "/child.prt", steps=2, progress=False)
    os._exit(0)
_, status = os.waitpid(pid, 0)
sys.exit(os.waitstatus_to_exitcode(status))
"""


def test_forked_child_runs_on_one_thread(short_ball_deck, tmp_path):
    """A run in a child forked after the parent ran on 2 threads: on one thread by default
    (libgomp does not survive a fork: on 2 it would wait forever), and it completes."""
    proc = subprocess.run([sys.executable, "-c", FORK_SCRIPT, str(short_ball_deck), str(tmp_path)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    child = (tmp_path / "child.prt").read_text().splitlines()
    assert _threads_line(child).startswith(THREADS_LINE + "1 THREAD ")
