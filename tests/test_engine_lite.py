"""pyadore/_core/lite.py: the engine's run and cross-field checks called through ctypes on the
extension's shared object, without numpy (a process that has not imported the extension: a
`pyadore run`, a sweep worker).  Each routine is compared with the extension module itself
(f2py's wrapper of the same routine), output for output, byte for byte."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

import pyadore
from pyadore import _core
from pyadore._core.base import _text
from pyadore._core.lite import lite_engine
from pyadore.errors import AdoreError

ROOT = Path(__file__).resolve().parent.parent
BALL = ROOT / "decks" / "appendix_c_ball.inp"
ROLLER = ROOT / "decks" / "appendix_d_roller.inp"


@pytest.fixture(scope="module")
def lite():
    engine = lite_engine()
    assert engine is not None  # this platform's build: the binding must load and answer
    return engine


def _fresh(code: str, *args) -> dict:
    """Run ``code`` in a fresh interpreter (no extension imported yet); its last stdout line as JSON."""
    proc = subprocess.run([sys.executable, "-c", code, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return json.loads(proc.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("deck", [BALL, ROLLER], ids=["ball", "roller"])
def test_a_step_0_run_without_numpy_writes_the_extensions_print(deck, tmp_path):
    """A fresh interpreter's `pyadore.run(steps=0)` imports neither numpy nor the extension
    module and writes the print the extension module writes, byte for byte."""
    code = ("import sys, json, pyadore; r = pyadore.run(sys.argv[1], steps=0, out=sys.argv[2], progress=False); "
            "print(json.dumps({'numpy': 'numpy' in sys.modules, 'ext': 'pyadore._engine' in sys.modules, "
            "'notes': r.notes}))")
    seen = _fresh(code, deck, tmp_path / "lite.prt")
    assert seen["numpy"] is False and seen["ext"] is False
    _core.base._engine()  # this process: the extension module
    assert "pyadore._engine" in sys.modules
    ref = pyadore.run(deck, steps=0, out=tmp_path / "ext.prt", progress=False)
    assert (tmp_path / "lite.prt").read_bytes() == ref.print_path.read_bytes()
    assert seen["notes"] == ref.notes


def test_a_run_with_a_progress_function_that_stops_it(short_ball_deck, tmp_path, lite):
    """adore_run_file_progress through ctypes: the progress function called after every
    step with what the extension gives it, a non-zero return stops the run there (status 2,
    the print incomplete), the same print and plot-data file as the extension's; an exception
    the function raises stops the run and is raised after it."""
    ext = _core.base._engine()
    options = "steps=40\nthreads=1"

    def stopper(calls):
        def progress(step, n, tau, t):
            calls.append((step, n, tau, t))
            return 1 if step == 15 else 0
        return progress

    runs = {}
    for name, engine in (("lite", lite), ("ext", ext)):
        calls: list = []
        out = tmp_path / name / "run.prt"
        out.parent.mkdir()
        integrated, rows, note, status, message = engine.adore_run_file_progress(
            str(short_ball_deck), str(out), options, stopper(calls))
        runs[name] = (int(integrated), int(rows), _text(note), int(status), _text(message).replace(name, "X"), calls,
                      out.read_bytes(), out.with_suffix(".hist.csv").read_bytes())
    assert runs["lite"][3] == 2 and runs["lite"][0] == 15 and len(runs["lite"][5]) == 15
    assert runs["lite"] == runs["ext"]

    def failing(step, n, tau, t):
        raise ValueError(f"stop at {step}")

    with pytest.raises(ValueError, match="stop at 1"):
        lite.adore_run_file_progress(str(short_ball_deck), str(tmp_path / "f.prt"), options, failing)


def test_a_refused_run_gives_the_extensions_status_and_message(tmp_path, lite):
    ext = _core.base._engine()
    outs = [engine.adore_run_file(str(tmp_path / "missing.inp"), str(tmp_path / f"{k}.prt"), "steps=0")
            for k, engine in enumerate((lite, ext))]
    (i1, r1, n1, s1, m1), (i2, r2, n2, s2, m2) = outs
    assert s1 == s2 != 0 and _text(m1).replace("0.prt", "1.prt") == _text(m2) != ""
    with pytest.raises(AdoreError):  # through the wrapper's status check
        _core.run_file(tmp_path / "missing.inp", tmp_path / "x.prt", "steps=0")


def test_the_cross_field_checks_give_the_extensions_problems(lite):
    """adore_deck_cross_checks and its field names through ctypes against the extension: the
    same names, and on values that break several rules (a ball larger than the race allows, a
    negative clearance, a missing value) the same problems, fields, warnings and status."""
    ext = _core.base._engine()
    for what in (1, 2):
        assert _text(lite.adore_deck_cross_check_names(what)) == _text(ext.adore_deck_cross_check_names(what))
    names = _core.cross_field_fields()
    values = {n: 0.01 for n in names}
    values.update(ball_diameter=0.5, pitch_diameter=0.05, diametral_play=-1e-3, n_rolling_elements=3,
                  step_min=1e-3, step_max=1e-6)
    values.pop("error_limit")
    have = [int(n in values) for n in names]
    vals = [float(values.get(n, 0.0)) for n in names]
    a = lite.adore_deck_cross_checks(vals, have, len(names) + 8)
    b = ext.adore_deck_cross_checks(vals, have, len(names) + 8)
    n = int(a[0])
    assert n >= 2 and n == int(b[0]) and a[4] == int(b[4]) == 0
    assert list(a[1][:n]) == [int(x) for x in b[1][:n]] and list(a[2][:n]) == [int(x) for x in b[2][:n]]
    assert _text(a[3]) == _text(b[3]) and _text(a[5]) == _text(b[5])
    wrong = lite.adore_deck_cross_checks(vals[:-1], have[:-1], 4)  # the size check of the routine
    assert wrong[4] == 2 and "values given" in _text(wrong[5])


def test_a_sweep_worker_boots_without_numpy():
    """The fork server's boot (pyadore.sweeps.worker.warm): the engine loaded, numpy not."""
    code = ("import sys, json; from pyadore.sweeps import worker; worker.warm(); "
            "print(json.dumps({'numpy': 'numpy' in sys.modules, 'lite': 'pyadore._core.lite' in sys.modules}))")
    assert _fresh(code) == {"numpy": False, "lite": True}
