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
