"""Python facade: run a deck and get a :class:`Result`."""

from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from . import _core
from .errors import AdoreInputError

__all__ = ["Result", "run", "read_traction_table", "STEPS_FROM_DECK", "BALL_STARTS"]

#: ``steps`` value the engine reads as "as many time steps as the deck asks for".
STEPS_FROM_DECK = -1

#: First words of the listing line of a print whose time steps come from the opt-in dynamics
#: (issue #20 in progress; fortran/output/banner.f90 writes it).
DYNAMICS_MARKER = "DYNAMICS IN PROGRESS (ISSUE #20)"

#: ``ball_start`` names of :func:`run` (report 4.4.7), the engine's default first: the
#: ball angular velocity of least contact dissipation, or race control at one race.
BALL_STARTS = ("dissipation", "outer-race-control", "inner-race-control")


@dataclass
class Result:
    """The outcome of one run: where the print file is and its text."""

    deck_path: Path
    print_path: Path
    steps: int | None
    text: str = field(repr=False)
    #: what the run did not do that was asked for (e.g. time steps the engine does not
    #: integrate yet); empty for a complete run
    notes: list[str] = field(default_factory=list)

    def print_run(self):
        """The print file parsed by :func:`pyadore.printout.read_print`."""
        from .printout import read_print

        return read_print(self.print_path)


def read_traction_table(path):
    """The traction-slip table file at ``path`` (ADORE's ADRX7, report 4.4.9), read and
    checked by the engine exactly as a run reads it: a :class:`pandas.DataFrame` with
    columns ``slip_m_s`` and ``kappa``.  Raises :class:`~pyadore.errors.AdoreInputError`
    (file:line:col and a caret for an unreadable line) for a bad table."""
    import pandas as pd

    slip, kappa = _core.traction_table(Path(os.fspath(path)))
    return pd.DataFrame({"slip_m_s": slip, "kappa": kappa})


def run(deck_path, steps: int | None = None, out=None, traction_table=None, ball_start=None,
        moment_equilibrium: bool = False, traction_2d: bool = True) -> Result:
    """Run the ADORE deck at ``deck_path`` and return its :class:`Result`.

    steps: ``None`` runs as many time steps as the deck asks for (while the dynamics,
    issue #20, is in progress: the print ends after step 0, and ``notes`` says so), ``0``
    only the quasi-static start, ``n`` integrates ``n`` time steps after step 0 - opt-in
    dynamics of ball decks (no cage contacts, thermal model off; the print's listing says
    so); a roller deck ends after step 0.
    out: the print file to write; by default a file in a fresh temporary directory.
    traction_table: a traction-slip table file (ADORE's ADRX7, report 4.4.9; format in
    docs/tribology.md) replacing the deck's RE/race traction model; the print lists it
    under "Input from optional user subroutines".
    ball_start: the initial ball angular velocity (report 4.4.7), one of
    :data:`BALL_STARTS`; ``None`` for the default (minimum dissipation).  Race control
    is listed in the print's first section.  Ball decks only.
    moment_equilibrium: ``True`` solves the inner race's misalignments about y and z for
    moment equilibrium in the quasi-static start (ADORE kFS4 = kFS5 = 0) instead of
    prescribing them zero (the default; the deck's Rec 3.3 flags are not identified, see
    docs/examples.md).  Listed in the print's first section; the tilts are printed in
    section 2 (IRace Ang Position Theta, Phi).  Ball decks only.
    traction_2d: ``True`` (default): the dynamics' race traction acts along the slip vector
    along and across the rolling direction (report eqs 2-3); ``False`` is a developer option,
    the one-dimensional traction along the rolling direction only (eq 1), listed in the print
    (docs/dynamics.md, "Ball gyroscopic moment and the 2-D traction").
    Raises :class:`~pyadore.errors.AdoreInputError` for bad input and
    :class:`~pyadore.errors.AdoreEngineError` when the engine fails.
    """
    if steps is None:
        engine_steps = STEPS_FROM_DECK
    else:
        if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
            raise AdoreInputError(f"steps must be None or an integer >= 0, got {steps!r}")
        engine_steps = steps
    deck = Path(os.fspath(deck_path))
    if out is None:
        out_path = Path(tempfile.mkdtemp(prefix="pyadore-")) / (deck.stem + ".prt")
    else:
        out_path = Path(os.fspath(out))
        if out_path.parent and not out_path.parent.exists():
            raise AdoreInputError(f"{out_path}: the output directory {out_path.parent} does not exist")
    table = None
    if traction_table is not None:
        table = Path(os.fspath(traction_table))
        if not str(traction_table).strip():
            raise AdoreInputError("traction table: the file name is blank")
    if not isinstance(moment_equilibrium, bool):
        raise AdoreInputError(f"moment_equilibrium must be True or False, got {moment_equilibrium!r}")
    if not isinstance(traction_2d, bool):
        raise AdoreInputError(f"traction_2d must be True or False, got {traction_2d!r}")
    _core.run_file(deck, out_path, engine_steps, table, ball_start, moment_equilibrium, traction_2d)
    text = out_path.read_text(encoding="utf-8", errors="replace")
    return Result(deck_path=deck, print_path=out_path, steps=steps, text=text,
                  notes=_run_notes(engine_steps, DYNAMICS_MARKER in text.split("Listing of input data records", 1)[0]))


def _run_notes(engine_steps: int, integrated: bool) -> list[str]:
    """What a run's print holds when it is not what was asked for (the standalone
    ``adore`` writes the same notes on stderr)."""
    if engine_steps == STEPS_FROM_DECK and _core.time_steps_implemented() == 0:
        return ["time integration is opt-in (--steps N) while [Dynamics] is in progress; "
                "the print file ends after step 0 (the quasi-static start)"]
    if engine_steps > 0 and not integrated:
        return ["time integration of roller bearings is not implemented yet; the print file ends after "
                "step 0 (the quasi-static start)"]
    if engine_steps > 0:
        return ["dynamics in progress (issue #20): no cage contacts, thermal model off"]
    return []
