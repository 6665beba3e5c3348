"""Progress and Ctrl-C of one engine run (issue #20 item 7: long runs are usable).

The engine calls a Python function after every accepted time step (the f2py callback of
``_core.run_file``); its return value asks the run to stop.  :class:`RunProgress` makes
that function: it draws a tqdm progress bar (step, simulated time, time left) and stops the
run after Ctrl-C, which it catches while the run lasts (main thread only: Python delivers
signals there; a process that ignores SIGINT, such as a sweep worker, keeps ignoring it).
The callback never raises into the engine (an exception inside it would
unwind through Fortran frames): anything that goes wrong stops the run and is raised
afterwards.

tqdm is the progress bar of ``pyadore sweep`` already: no new dependency.
"""

from __future__ import annotations

import signal
import sys
import threading

__all__ = ["RunProgress"]


class RunProgress:
    """Progress reporting and Ctrl-C handling around one run (a context manager).

    progress: ``None`` - a bar on stderr when it is a terminal; ``True`` - always a bar;
    ``False`` - no bar; a function ``f(step, n_steps, time_s)`` - called after every step.
    ``callback`` is the function to give the engine, or None when nothing needs it (no bar,
    no function, no Ctrl-C to catch): the engine then runs without holding the GIL.
    """

    def __init__(self, progress=None, label: str = ""):
        if progress is not None and not isinstance(progress, bool) and not callable(progress):
            from .errors import AdoreInputError

            raise AdoreInputError(f"progress must be None, True, False or a function, got {progress!r}")
        self.function = progress if callable(progress) and not isinstance(progress, bool) else None
        self.bar_wanted = bool(progress) if isinstance(progress, bool) else (
            progress is None and sys.stderr is not None and sys.stderr.isatty())
        self.label = label
        # Ctrl-C is caught in the main thread (where Python delivers signals), unless the
        # process ignores it (a sweep worker: its client ends it)
        self.catch_sigint = (threading.current_thread() is threading.main_thread()
                             and signal.getsignal(signal.SIGINT) is not signal.SIG_IGN)
        self.interrupted = False
        self.stopped = False
        self.error: BaseException | None = None
        self._bar = None
        self._previous = None

    @property
    def callback(self):
        """The engine's progress function, or None when the run needs none."""
        if self.function is None and not self.bar_wanted and not self.catch_sigint:
            return None
        return self._on_step

    def __enter__(self):
        if self.catch_sigint:
            try:
                self._previous = signal.signal(signal.SIGINT, self._on_sigint)
            except (ValueError, OSError):  # not allowed here (an embedded interpreter)
                self._previous = None
        return self

    def __exit__(self, exc_type, exc, tb):
        if self._previous is not None:
            signal.signal(signal.SIGINT, self._previous)
            self._previous = None
        if self._bar is not None:
            try:
                self._bar.close()
            except Exception:  # noqa: BLE001 - a broken stderr must not hide the run's outcome
                pass
            self._bar = None
        if exc_type is not None and self.error is not None and exc is not self.error:
            raise self.error from exc
        return False

    def _on_sigint(self, signum, frame):
        self.interrupted = True

    def _on_step(self, step, n_steps, tau, time_s):
        """The engine's callback: 1 stops the run after this step."""
        try:
            if self.bar_wanted:
                self._draw(int(step), int(n_steps), float(time_s))
            if self.function is not None:
                self.function(int(step), int(n_steps), float(time_s))
        except KeyboardInterrupt:
            self.interrupted = True
        except BaseException as exc:  # noqa: BLE001 - raised after the run (see __exit__)
            self.error = exc
            self.stopped = True
            return 1
        if self.interrupted:
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

    def raise_pending_interrupt(self) -> None:
        """After a run that ended normally: raise KeyboardInterrupt when Ctrl-C came while
        no time step could stop it (the quasi-static start), so that it is not lost."""
        if self.interrupted and not self.stopped:
            raise KeyboardInterrupt
