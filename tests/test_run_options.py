"""The run options come from one table in the engine (fortran/model/run_options.f90,
issue #24 item 2): `adore --help`, `pyadore run --help`, `pyadore sweep --help` and
`pyadore.run(**options)` offer the same options, and the engine checks every value."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

import pyadore
from pyadore.options import FLAG_OFF, options_text, run_options


def _flag(opt) -> str:
    return "--" + (opt.flag if opt.kind == FLAG_OFF else opt.name).replace("_", "-")


def test_every_command_line_offers_every_option(adore_exe):
    names = [o.name for o in run_options()]
    assert names[:3] == ["steps", "substeps", "history_element"] and len(set(names)) == len(names)
    adore = subprocess.run([str(adore_exe), "--help"], capture_output=True, text=True, timeout=60).stdout
    run = subprocess.run([sys.executable, "-m", "pyadore", "run", "--help"], capture_output=True, text=True,
                         timeout=120).stdout
    sweep = subprocess.run([sys.executable, "-m", "pyadore", "sweep", "--help"], capture_output=True, text=True,
                           timeout=120).stdout
    for opt in run_options():
        assert _flag(opt) in adore, opt.name
        assert opt.help.split()[0] in adore
        if opt.name != "steps":  # pyadore's own --steps (None: the deck's count)
            assert _flag(opt) in run, opt.name
            assert _flag(opt) in sweep, opt.name


def test_options_text_is_what_the_engine_reads():
    text = options_text(substeps=3, traction_2d=False, ball_start="outer-race-control", duration=1.5e-3)
    assert text.splitlines() == ["substeps=3", "traction_2d=false", "ball_start=outer-race-control",
                                 "duration=0.0015"]
    with pytest.raises(pyadore.AdoreInputError, match="unknown run option 'colour'"):
        options_text(colour="red")
    with pytest.raises(pyadore.AdoreInputError, match="substeps must be an integer >= 1"):
        options_text(substeps=True)


def test_the_engine_checks_ranges_and_names_every_bad_option(tmp_path, ball_deck):
    from pyadore import _core

    with pytest.raises(pyadore.AdoreInputError) as info:
        _core.run_file(ball_deck, tmp_path / "x.prt", "substeps=0\ncolour=red\nsteps")
    message = str(info.value)
    assert "substeps (--substeps): 0 is below its minimum 1" in message
    assert "run option 'colour': unknown" in message and "run option 'steps': expected name=value" in message
    assert not list(tmp_path.iterdir())


def test_no_option_help_is_cut_by_the_table_field():
    """The option table's help field is a fixed-length character (option_spec_t%help): a longer
    help text would be cut silently in `adore --help` and in the click options (it was twice,
    mid-word).  Every help text in the table's source fits the declared length."""
    import re
    from pathlib import Path

    src = (Path(__file__).resolve().parents[1] / "fortran" / "model" / "run_options.f90").read_text()
    width = int(re.search(r"character\(len=(\d+)\)\s*::\s*help\b", src).group(1))
    table = src[src.index("OPTION_TABLE(N_OPTIONS)"):src.index("contains")]
    rows = re.split(r"option_spec_t\(", table)[1:]
    assert len(rows) == len(run_options())
    for row in rows:
        strings = re.findall(r'"((?:[^"]|"")*)"', row)
        help_text = "".join(strings[5:])          # name, default, units, metavar, choices, then the help
        assert 0 < len(help_text) <= width, (strings[0], len(help_text), width)


def test_the_option_table_is_cached_per_build_of_the_engine(tmp_path):
    """The command line reads the option table from a copy in the cache folder, keyed by the
    engine extension's file, size and time: the same table as the engine's, without importing
    numpy or the engine; a copy of another build is not used (docs/sweeps.md, "Scaling")."""
    import json

    from pyadore._core import run_option_table

    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path)}
    probe = ("import json, sys; from pyadore.options import run_options; rows = run_options(); "
             "print(json.dumps(['numpy' in sys.modules, [list(r.__dict__.values()) for r in rows]]))")

    def run():
        proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env, timeout=300)
        assert proc.returncode == 0, proc.stderr
        return json.loads(proc.stdout)

    engine = [list(r[:6]) + [list(r[6]), r[7]] for r in run_option_table()]
    first = run()
    assert first == [True, engine]                  # read from the engine, and kept
    files = list((tmp_path / "pyadore").glob("run-options-*.json"))
    assert len(files) == 1
    assert run() == [False, engine]                 # the copy: no numpy, no engine
    data = json.loads(files[0].read_text())
    data["key"] += "0"                              # a copy of another build of the engine
    data["rows"] = data["rows"][:1]
    files[0].write_text(json.dumps(data))
    assert run() == [True, engine]                  # not used: the engine is read again
    assert json.loads(files[0].read_text())["rows"] == engine
