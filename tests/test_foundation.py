"""Foundation: one engine, two front ends (executable and f2py), errors as exceptions."""

from __future__ import annotations

import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from click.testing import CliRunner

import pyadore
from pyadore.cli import cli


def test_version_is_shared_by_package_and_engine():
    from pyadore import _core

    assert pyadore.__version__ == _core.engine_version()


def test_missing_deck_raises_input_error_and_interpreter_survives(tmp_path, ball_deck):
    with pytest.raises(pyadore.AdoreInputError, match="not found"):
        pyadore.run(tmp_path / "no_such_deck.inp", out=tmp_path / "x.prt")
    assert not (tmp_path / "x.prt").exists()
    # the interpreter and the engine are still usable
    result = pyadore.run(ball_deck, steps=0, out=tmp_path / "ok.prt")
    assert result.print_path.exists()


@pytest.mark.parametrize("content", [b"", b"   \n\n  \n"], ids=["empty", "blank"])
def test_empty_deck_raises_input_error(tmp_path, content):
    deck = tmp_path / "empty.inp"
    deck.write_bytes(content)
    with pytest.raises(pyadore.AdoreInputError, match="empty"):
        pyadore.run(deck, out=tmp_path / "empty.prt")
    assert not (tmp_path / "empty.prt").exists()
    assert not (tmp_path / "empty.prt.part").exists()


def test_binary_deck_raises_input_error_with_position(tmp_path):
    deck = tmp_path / "binary.inp"
    deck.write_bytes(b"Rec 1\n\x00\x01\x02")
    with pytest.raises(pyadore.AdoreInputError, match=r"binary\.inp:2:1: not a text file"):
        pyadore.run(deck, out=tmp_path / "binary.prt")


def test_input_error_is_an_adore_error():
    assert issubclass(pyadore.AdoreInputError, pyadore.AdoreError)
    assert issubclass(pyadore.AdoreEngineError, pyadore.AdoreError)


@pytest.mark.parametrize("steps", [-1, 1.5, True, "3"])
def test_bad_steps_argument(tmp_path, ball_deck, steps):
    with pytest.raises(pyadore.AdoreInputError, match="steps"):
        pyadore.run(ball_deck, steps=steps, out=tmp_path / "x.prt")


def test_two_runs_in_one_process_are_identical(tmp_path, short_ball_deck):
    """Appendix C as the deck says, its step count cut to 60: the time integration too."""
    first = pyadore.run(short_ball_deck, out=tmp_path / "a.prt")
    second = pyadore.run(short_ball_deck, out=tmp_path / "b.prt")
    assert first.print_path.read_bytes() == second.print_path.read_bytes()
    assert first.history_path.read_bytes() == second.history_path.read_bytes()
    assert first.steps_integrated == 60


def test_runs_in_threads_are_identical(tmp_path, short_ball_deck, short_roller_deck):
    """Runs in threads other than the main one go through the engine without a progress
    callback, releasing the GIL: they run at once."""
    decks = [short_ball_deck, short_roller_deck] * 3
    with ThreadPoolExecutor(max_workers=4) as pool:
        results = list(pool.map(lambda ij: pyadore.run(ij[1], out=tmp_path / f"t{ij[0]}.prt"),
                                enumerate(decks)))
    for result, deck in zip(results, decks):
        alone = pyadore.run(deck, out=tmp_path / f"alone_{deck.stem}.prt")
        assert result.print_path.read_bytes() == alone.print_path.read_bytes()


@pytest.mark.parametrize("deck_name", ["appendix_c_ball.inp", "appendix_d_roller.inp"])
def test_executable_and_f2py_write_identical_print_files(tmp_path, root, run_exe, deck_name):
    """Step 0 of both decks; the time integration's prints: tests/test_dynamic_run.py."""
    deck = root / "decks" / deck_name
    via_python = pyadore.run(deck, steps=0, out=tmp_path / "python.prt").print_path
    proc = run_exe(deck, tmp_path / "exe.prt", "--steps", "0")
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "exe.prt").read_bytes() == via_python.read_bytes()


def test_print_file_lists_the_deck_verbatim_and_the_banner(tmp_path, ball_deck):
    text = pyadore.run(ball_deck, steps=0, out=tmp_path / "b.prt").text
    lines = text.splitlines()
    start = lines.index("Listing of input data records") + 2
    deck_lines = ball_deck.read_text().splitlines()
    assert lines[start:start + len(deck_lines)] == deck_lines
    assert "ADVANCED DYNAMICS OF ROLLING ELEMENTS" in lines
    assert "[Version (ADORE 5.0)]" in lines


def test_executable_exit_codes(tmp_path, run_exe, ball_deck):
    ok = run_exe(ball_deck, tmp_path / "ok.prt", "--steps", "0")
    assert ok.returncode == 0 and "print file written" in ok.stdout
    missing = run_exe(tmp_path / "missing.inp", tmp_path / "m.prt")
    assert missing.returncode == 1
    assert "missing.inp: deck file not found" in missing.stderr
    assert "Backtrace" not in missing.stderr
    bad_steps = run_exe(ball_deck, tmp_path / "s.prt", "--steps", "x")
    assert bad_steps.returncode == 1 and "--steps" in bad_steps.stderr
    unwritable = run_exe(ball_deck, tmp_path / "no_dir" / "out.prt")
    assert unwritable.returncode == 1 and "cannot write print file" in unwritable.stderr


def test_executable_default_output_next_to_deck(tmp_path, run_exe, short_ball_deck):
    deck = tmp_path / "case.inp"
    deck.write_bytes(short_ball_deck.read_bytes())
    proc = run_exe(deck)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "case.prt").exists() and (tmp_path / "case.hist.csv").exists()


def test_failed_run_keeps_no_partial_file(tmp_path, run_exe):
    deck = tmp_path / "bad.inp"
    deck.write_bytes(b"\x7fELF\x00\x00")
    proc = run_exe(deck, tmp_path / "bad.prt")
    assert proc.returncode == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.inp"]


# --- CLI ----------------------------------------------------------------------

def test_cli_version():
    result = CliRunner().invoke(cli, ["--version"])
    assert result.exit_code == 0
    assert result.output.strip() == f"pyadore {pyadore.__version__}"


def test_cli_run_writes_print_file(tmp_path, ball_deck):
    out = tmp_path / "sub" / "ball.prt"
    result = CliRunner().invoke(cli, ["run", str(ball_deck), "-o", str(out), "--steps", "0"])
    assert result.exit_code == 0, result.output
    assert out.exists()
    assert str(out) in result.output


def test_cli_bad_input_is_one_paragraph_without_traceback(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "pyadore", "run", str(tmp_path / "nope.inp"),
                           "-o", str(tmp_path / "nope.prt")], capture_output=True, text=True)
    assert proc.returncode == 1
    assert "Traceback" not in proc.stderr
    assert proc.stderr.startswith("pyadore: error: ")
    assert "nope.inp: deck file not found" in proc.stderr
    assert len(proc.stderr.strip().split("\n\n")) == 1


def test_cli_rejects_negative_steps(tmp_path, ball_deck):
    result = CliRunner().invoke(cli, ["run", str(ball_deck), "--steps", "-2"])
    assert result.exit_code == 2  # click's usage error
    assert "Traceback" not in result.output


def test_run_says_what_it_leaves_out(tmp_path, short_ball_deck, short_roller_deck, run_exe):
    """A run with time steps says that the thermal model is off, and a roller run what its
    cage and pockets are (Python notes, executable on stderr); a step-0 run has nothing to
    say."""
    ball = pyadore.run(short_ball_deck, out=tmp_path / "ball.prt")
    assert ball.notes and ball.notes[0].startswith("thermal model off")
    roller = pyadore.run(short_roller_deck, out=tmp_path / "roller.prt")
    # the cage as the deck's Rec 3.3 says (the default): Appendix D's pattern leaves it free
    assert roller.notes and roller.notes[0].startswith("thermal model off") and "cage free" in roller.notes[0]
    assert pyadore.run(short_ball_deck, steps=0, out=tmp_path / "s0.prt").notes == []
    proc = run_exe(short_ball_deck, tmp_path / "exe.prt")
    assert proc.returncode == 0 and "adore: note: thermal model off" in proc.stderr
    proc = run_exe(short_roller_deck, tmp_path / "rexe.prt")
    assert proc.returncode == 0 and "rectangular pockets as flat walls" in proc.stderr
    proc = run_exe(short_ball_deck, tmp_path / "exe0.prt", "--steps", "0")
    assert proc.returncode == 0 and proc.stderr == ""
