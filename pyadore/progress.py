"""Progress and stop signals of one engine run (issue #20 item 7, issue #28 item 4).

The engine calls a Python function after every accepted time step (the f2py callback of
``_core.run_file``); its return value asks the run to stop.  :class:`RunProgress` makes
that function: it draws a tqdm progress bar (step, simulated time, time left) and stops the
run after a stop signal - SIGINT (Ctrl-C), SIGTERM, SIGHUP - which it catches while the
run lasts: in the main thread (Python delivers signals there), each signal the process
handles in Python (SIGINT always, unless ignored; SIGTERM and SIGHUP where a handler is
installed, as the ``pyadore`` command installs one: pyadore/_signals.py).  A signal
ignored (a sweep worker ignores SIGINT) or left to its default action (SIGTERM in a
script of the user's) keeps its effect.  The callback never raises into the
engine (an exception inside it would unwind through Fortran frames): anything that goes
wrong stops the run and is raised afterwards.

What a stop signal leaves (the rule ``adore`` follows too, docs/dynamics.md "Signals"):
the run stops at its next step boundary - the end of a time step; the engine has none in
step 0 - and :func:`pyadore.run` raises :class:`~pyadore.errors.AdoreInterrupted`:

* seen after the first time step ended: the print and plot-data file are kept, their last
  line "*** RUN INCOMPLETE after step N ...: interrupted";
* seen before (reading the deck, step 0, the first time step, a run without time steps):
  no file is left - what the run wrote is removed;
* seen at or after the last time step: the run ends complete, its files kept.

The ``pyadore`` command (``pyadore/_signals.py``, ``pyadore/cli.py``) then ends by the
signal itself, so a shell sees 128 + its number.

tqdm is the progress bar of ``pyadore sweep`` already: no new dependency.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from pathlib import Path

from ._signals import STOP_SIGNALS, SignalInterrupt, signal_label

__all__ = ["RunProgress", "remove_run_outputs"]

def _output_paths(print_path: Path) -> list[Path]:
    """The files a run with print file ``print_path`` writes: the print, its plot-data file,
    element file and netCDF results file, and each being written (``.part``), as the
    engine names them (adore_output_run_files)."""
    from .results import element_path, results_path
    from .timehistory import history_path

    files = [print_path, history_path(print_path), element_path(print_path), results_path(print_path)]
    return [q for p in files for q in (p, p.with_name(p.name + ".part"))]


def remove_run_outputs(print_path) -> None:
    """Remove the regular files a run with print file ``print_path`` wrote (best effort)."""
    for path in _output_paths(Path(os.fspath(print_path))):
        try:
            if path.is_file():
                path.unlink()
        except OSError:
            pass


class RunProgress:
    """Progress reporting and stop signals around one run (a context manager).

    progress: ``None`` - a bar on stderr when it is a terminal; ``True`` - always a bar;
    ``False`` - no bar; a function ``f(step, n_steps, time_s)`` - called after every step
    (a KeyboardInterrupt it raises counts as Ctrl-C).
    ``callback`` is the function to give the engine, or None when nothing needs it (no bar,
    no function, no signal to catch): the engine then runs without holding the GIL.
    ``print_path``: the run's print file; when a stop signal came while the context lasted,
    leaving it raises :class:`~pyadore.errors.AdoreInterrupted` (module docstring: what is
    kept), chained to the run's own error if it had one.
    """

    def __init__(self, progress=None, label: str = "", print_path=None):
        if progress is not None and not isinstance(progress, bool) and not callable(progress):
            from .errors import AdoreInputError

            raise AdoreInputError(f"progress must be None, True, False or a function, got {progress!r}")
        self.function = progress if callable(progress) and not isinstance(progress, bool) else None
        self.bar_wanted = bool(progress) if isinstance(progress, bool) else (
            progress is None and sys.stderr is not None and sys.stderr.isatty())
        self.label = label
        self.print_path = Path(os.fspath(print_path)) if print_path is not None else None
        # stop signals are caught in the main thread (where Python delivers them), those the
        # process handles in Python: SIGINT (Python's KeyboardInterrupt), and SIGTERM and
        # SIGHUP once a handler is installed (the pyadore command's).  A signal ignored (a
        # sweep worker ignores SIGINT: its client ends it) or left to its default action (a
        # script's SIGTERM ends it at once) keeps doing so.
        self.signals: tuple[int, ...] = ()
        if threading.current_thread() is threading.main_thread():
            self.signals = tuple(s for s in STOP_SIGNALS
                                 if signal.getsignal(s) not in (signal.SIG_IGN, signal.SIG_DFL, None))
        self.signum: int | None = None      # the first stop signal that came
        self.last_step = 0                  # the last time step the engine called back after
        self.stopped = False                # the callback asked the run to stop
        self.error: BaseException | None = None
        self._bar = None
        self._previous: dict[int, object] = {}

    @property
    def interrupted(self) -> bool:
        """A stop signal came while the run lasted."""
        return self.signum is not None

    @property
    def callback(self):
        """The engine's progress function, or None when the run needs none."""
        if self.function is None and not self.bar_wanted and not self.signals:
            return None
        return self._on_step

    def __enter__(self):
        for sig in self.signals:
            try:
                self._previous[sig] = signal.signal(sig, self._on_signal)
            except (ValueError, OSError):  # not allowed here (an embedded interpreter)
                pass
        return self

    def __exit__(self, exc_type, exc, tb):
        for sig, previous in self._previous.items():
            try:
                signal.signal(sig, previous)
            except (ValueError, OSError, TypeError):
                pass
        self._previous = {}
        if self._bar is not None:
            try:
                self._bar.close()
            except Exception:  # noqa: BLE001 - a broken stderr must not hide the run's outcome
                pass
            self._bar = None
        if self.signum is not None:
            raise self._interrupted(exc) from exc
        if exc_type is not None and self.error is not None and exc is not self.error:
            raise self.error from exc
        return False

    def _interrupted(self, exc):
        """The AdoreInterrupted that a run stopped by self.signum ends with (module
        docstring); exc: the run's own exception, or None."""
        from .errors import AdoreError, AdoreInterrupted

        name = signal_label(self.signum)
        out = self.print_path
        failed = ""
        if exc is not None and not (self.stopped and isinstance(exc, AdoreError)):
            failed = f" (the run had failed: {exc})" if isinstance(exc, AdoreError) else (
                f" (the run had failed: {type(exc).__name__}: {exc})")
        if self.last_step <= 1:
            if out is not None:
                remove_run_outputs(out)
            where = f" ({out})" if out is not None else ""
            return AdoreInterrupted(f"stopped by {name} before the first time step ended: no print file "
                                    f"written{where}{failed}", self.signum)
        partial = getattr(exc, "_partial", None)  # the kept steps, built on access (errors.py)
        if self.stopped and isinstance(exc, AdoreError):
            return _keeping(AdoreInterrupted(f"stopped by {name}: {exc}", self.signum, print_path=out), partial)
        if exc is None:
            from .timehistory import history_path

            return AdoreInterrupted(f"{name} came after the last time step: the print file {out} and its "
                                    f"plot-data file {history_path(out)} are complete", self.signum,
                                    print_path=out)
        return _keeping(AdoreInterrupted(f"stopped by {name}{failed}", self.signum,
                                         print_path=getattr(exc, "print_path", None)), partial)

    def _on_signal(self, signum, frame):
        if self.signum is None:
            self.signum = signum

    def _on_step(self, step, n_steps, tau, time_s):
        """The engine's callback: 1 stops the run after this step (a stop signal came and
        this is not the last step)."""
        self.last_step = int(step)
        try:
            if self.bar_wanted:
                self._draw(int(step), int(n_steps), float(time_s))
            if self.function is not None:
                self.function(int(step), int(n_steps), float(time_s))
        except KeyboardInterrupt as exc:  # Ctrl-C as Python raises it, or the function's own
            if self.signum is None:
                self.signum = getattr(exc, "signum", signal.SIGINT)
        except SignalInterrupt as exc:
            if self.signum is None:
                self.signum = exc.signum
        except BaseException as exc:  # noqa: BLE001 - raised after the run (see __exit__)
            self.error = exc
            self.stopped = True
            return 1
        if self.signum is not None and int(step) < int(n_steps):
            self.stopped = True
            return 1
        return 0

    def _draw(self, step: int, n_steps: int, time_s: float) -> None:
        try:
            if self._bar is None:
                from tqdm import tqdm

                self._bar = tqdm(total=n_steps, unit="step", desc=self.label or "run", file=sys.stderr,
                                 dynamic_ncols=True, leave=True)
            self._bar.set_postfix_str(f"simulated time {time_s:.4g} s", refresh=False)
            self._bar.update(step - self._bar.n)
        except Exception:  # noqa: BLE001 - no bar rather than a failed run
            self.bar_wanted = False


def _keeping(err, partial):
    """``err`` with a failed run's kept steps (``partial``: errors.AdoreEngineError's
    (history, arrays), or None)."""
    if partial is not None:
        err.keep_partial(*partial)
    return err
