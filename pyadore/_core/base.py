"""The engine handle and the status check shared by every wrapper group."""

from __future__ import annotations

import os

from ..errors import (
    STATUS_ENGINE,
    STATUS_INPUT,
    STATUS_OK,
    AdoreEngineError,
    AdoreError,
    AdoreInputError,
)


def _engine():
    try:
        from .. import _engine as engine
    except ImportError as exc:  # the package was installed without its extension
        raise AdoreEngineError(
            "the pyadore engine extension (pyadore._engine) is not built; "
            "run `make setup` (or `pip install -e .`) first"
        ) from exc
    return engine


def _text(value) -> str:
    if isinstance(value, bytes):
        value = value.decode("utf-8", errors="replace")
    return str(value).rstrip()


def check(status: int, message) -> None:
    """Raise the AdoreError subclass that ``status`` stands for (0: return)."""
    if status == STATUS_OK:
        return
    text = _text(message) or f"engine returned status {status}"
    if status == STATUS_INPUT:
        raise AdoreInputError(text)
    if status == STATUS_ENGINE:
        raise AdoreEngineError(text)
    raise AdoreError(f"{text} (unknown engine status {status})")


def run_file(deck_path: str | os.PathLike, out_path: str | os.PathLike, steps: int,
             traction_table: str | os.PathLike | None = None, ball_start: str | None = None,
             moment_equilibrium: bool = False, traction_2d: bool = False) -> None:
    """Run the engine on a deck file and write the print file (status checked).

    traction_table: a traction-slip table file (ADRX7) replacing the deck's RE/race
    traction model; ``None`` for the deck's model.
    ball_start: the ball start hypothesis by name (report 4.4.7; the engine checks it);
    ``None`` for the default, minimum dissipation.
    moment_equilibrium: solve the inner race's misalignment for moment equilibrium
    (ADORE kFS4 = kFS5 = 0) instead of prescribing it zero (ball decks only).
    traction_2d: the opt-in dynamics with the two-dimensional race traction (developer
    option, docs/dynamics.md).
    """
    table = "" if traction_table is None else os.fspath(traction_table)
    start = "" if ball_start is None else str(ball_start)
    status, message = _engine().adore_run_file(os.fspath(deck_path), os.fspath(out_path), int(steps), table,
                                               start, int(bool(moment_equilibrium)),
                                               int(bool(traction_2d)))
    check(int(status), message)


def engine_version() -> str:
    """Version string compiled into the engine."""
    return _text(_engine().adore_version())


def time_steps_implemented() -> int:
    """Time steps a run with the deck's own count integrates (0: such a print ends after
    step 0 while the dynamics, issue #20, is in progress; explicit steps > 0 on a ball deck
    integrate opt-in)."""
    return int(_engine().adore_time_steps_implemented())
