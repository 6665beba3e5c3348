"""Shared fixtures: repository paths and the standalone engine executable."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def ball_deck() -> Path:
    return ROOT / "decks" / "appendix_c_ball.inp"


@pytest.fixture(scope="session")
def roller_deck() -> Path:
    return ROOT / "decks" / "appendix_d_roller.inp"


@pytest.fixture(scope="session")
def build_dir() -> Path:
    """The meson build directory holding `adore` and the engine unit tests.

    `make test` sets ADORE_BUILD_DIR (build/native; build/debug for `make debug`).
    """
    path = Path(os.environ.get("ADORE_BUILD_DIR", ROOT / "build" / "native"))
    if not (path / "build.ninja").exists():
        pytest.fail(f"no engine build in {path}: run the tests with `make test`")
    return path


@pytest.fixture(scope="session")
def adore_exe(build_dir: Path) -> Path:
    exe = Path(os.environ.get("ADORE_EXE", build_dir / "adore"))
    if not exe.exists():
        pytest.fail(f"standalone engine {exe} not built: run the tests with `make test`")
    return exe


@pytest.fixture
def run_exe(adore_exe):
    """Run the standalone engine with arguments; returns the CompletedProcess."""

    def _run(*args, cwd=None):
        return subprocess.run([str(adore_exe), *map(str, args)], capture_output=True, text=True,
                              cwd=cwd, timeout=600)

    return _run


def deck_with_steps(text: str, n_steps: int, print_interval: int) -> str:
    """An appendix deck's text (Appendix C: 2500 steps, D: 4000) with Rec 1 n_steps and
    data_control_2 (the print interval, 500) replaced: the fields keep their I6 columns."""
    line1 = text.splitlines(keepends=True)[0]
    assert line1.startswith("Rec 1") and line1[48:54] == "   500" and line1[78:84] in ("  2500", "  4000"), line1
    new = line1[:48] + f"{print_interval:6d}" + line1[54:78] + f"{n_steps:6d}" + line1[84:]
    return new + text[len(line1):]


#: Time steps and print interval of the short ball deck (`short_ball_deck`).
SHORT_STEPS, SHORT_INTERVAL = 60, 20


@pytest.fixture(scope="session")
def short_ball_deck(tmp_path_factory) -> Path:
    """Appendix C with its own step count cut to SHORT_STEPS (printed every SHORT_INTERVAL):
    a deck-count run of it integrates and prints like the full deck in a fraction of a
    second, for the tests that need a complete time integration but not 2500 steps."""
    path = tmp_path_factory.mktemp("short_deck") / "appendix_c_short.inp"
    path.write_text(deck_with_steps((ROOT / "decks" / "appendix_c_ball.inp").read_text(), SHORT_STEPS,
                                    SHORT_INTERVAL))
    return path


@pytest.fixture(scope="session")
def short_roller_deck(tmp_path_factory) -> Path:
    """Appendix D with its own step count cut to SHORT_STEPS (printed every SHORT_INTERVAL):
    the roller bearing's time integration in a fraction of a second."""
    path = tmp_path_factory.mktemp("short_roller_deck") / "appendix_d_short.inp"
    path.write_text(deck_with_steps((ROOT / "decks" / "appendix_d_roller.inp").read_text(), SHORT_STEPS,
                                    SHORT_INTERVAL))
    return path


@pytest.fixture(scope="session")
def full_ball_run(tmp_path_factory, ball_deck):
    """The one full run of the suite: Appendix C as the deck says (2500 steps, about 5 s in
    the release build), through pyadore.run (what `make run` does)."""
    import pyadore

    return pyadore.run(ball_deck, out=tmp_path_factory.mktemp("full_run") / "appendix_c_ball.prt")
