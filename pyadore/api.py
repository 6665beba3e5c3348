"""Python facade: run a deck and get a :class:`Result`."""

from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from . import _core
from .errors import AdoreEngineError, AdoreInputError

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["Result", "run", "read_traction_table", "STEPS_FROM_DECK", "BALL_STARTS"]

#: ``steps`` value the engine reads as "as many time steps as the deck asks for".
STEPS_FROM_DECK = -1

#: ``ball_start`` names of :func:`run` (report 4.4.7), the engine's default first: the
#: ball angular velocity of least contact dissipation, or race control at one race.
BALL_STARTS = ("dissipation", "outer-race-control", "inner-race-control")


@dataclass
class Result:
    """The outcome of one run: where the print file is, its text and its time history."""

    deck_path: Path
    print_path: Path
    steps: int | None
    text: str = field(repr=False)
    #: what the run does not do that a user may expect (the thermal model is off, a roller
    #: deck's time steps are not integrated, ...); empty when there is nothing to say
    notes: list[str] = field(default_factory=list)
    #: time steps integrated after step 0 (0: the print ends after step 0)
    steps_integrated: int = 0
    #: the time history the run recorded (docs/plots.md: index ``time_s``, column ``step``,
    #: SI columns), the same as its plot-data file :attr:`history_path`; None without time steps
    time_history: "pd.DataFrame | None" = field(default=None, repr=False)

    @property
    def history_path(self) -> Path | None:
        """The plot-data file beside the print (``<print stem>.hist.csv``); None without
        time steps."""
        if self.time_history is None:
            return None
        from .timehistory import history_path

        return history_path(self.print_path)

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
        moment_equilibrium: bool = False, history_element: int = 1, progress=None,
        traction_2d: bool = True, substeps: int = 1) -> Result:
    """Run the ADORE deck at ``deck_path`` and return its :class:`Result`.

    steps: ``None`` runs as many time steps as the deck asks for (Rec 1; Appendix C: 2500),
    ``0`` only the quasi-static start, ``n`` integrates ``n`` time steps after step 0.
    Time steps are integrated for ball decks (thermal model off: the bulk temperatures stay
    at the initial ones; ``notes`` says what the run leaves out); a roller deck's print
    ends after step 0 (``notes`` says so).  A run with time steps also writes its plot-data
    file beside the print (:attr:`Result.history_path`) and returns the same table as
    :attr:`Result.time_history`.
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
    history_element: the rolling element whose race contacts and pocket force the time
    history records (default 1).
    substeps: integrator steps in each time step (report 4.4.5): the deck's step count and
    print interval count time steps of ``substeps`` integrator steps each; output is neither
    printed nor recorded over the substeps (default 1).
    traction_2d: ``True`` (default): the dynamics' race traction acts along the slip vector
    along and across the rolling direction (report eqs 2-3); ``False`` is a developer option,
    the one-dimensional traction along the rolling direction only (eq 1), listed in the print
    (docs/dynamics.md, "Ball gyroscopic moment and the 2-D traction").
    progress: ``None`` shows a progress bar (tqdm: step, simulated time, time left) on
    stderr when it is a terminal; ``True`` always, ``False`` never; or a function
    ``progress(step, n_steps, time_s)`` called after every time step.
    Ctrl-C during the time steps (main thread) stops the run after its current step.
    Raises :class:`~pyadore.errors.AdoreInputError` for bad input and
    :class:`~pyadore.errors.AdoreEngineError` when the engine fails.  A time integration
    that stops early (Ctrl-C, a failed integration, a non-finite state) raises
    AdoreEngineError naming the step and time; its print is kept and ends with the line
    ``*** RUN INCOMPLETE ...`` (the error's ``print_path``; ``time_history``: the steps
    done).
    """
    if steps is None:
        engine_steps = STEPS_FROM_DECK
    else:
        if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
            raise AdoreInputError(f"steps must be None or an integer >= 0, got {steps!r}")
        engine_steps = steps
    if isinstance(history_element, bool) or not isinstance(history_element, int) or history_element < 1:
        raise AdoreInputError(f"history_element must be a rolling element number >= 1, got {history_element!r}")
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
    if isinstance(substeps, bool) or not isinstance(substeps, int) or substeps < 1:
        raise AdoreInputError(f"substeps must be an integer >= 1 (integrator steps per printed time step), "
                              f"got {substeps!r}")
    from .progress import RunProgress
    from .timehistory import history_frame

    watch = RunProgress(progress, label=deck.name)
    try:
        with watch:
            output = _core.run_file(deck, out_path, engine_steps, table, ball_start, moment_equilibrium,
                                    history_element, watch.callback, traction_2d, substeps)
    except AdoreEngineError as exc:
        done = getattr(exc, "output", None)
        exc.print_path = out_path if out_path.exists() else None
        exc.time_history = history_frame(done.history, done.columns) if done is not None and done.columns else None
        raise
    watch.raise_pending_interrupt()
    text = out_path.read_text(encoding="utf-8", errors="replace")
    history = history_frame(output.history, output.columns) if output.columns else None
    return Result(deck_path=deck, print_path=out_path, steps=steps, text=text,
                  notes=[output.note] if output.note else [], steps_integrated=output.integrated,
                  time_history=history)
