"""Exception hierarchy shared by the deck tools, the engine bridge and the CLI.

Every error a user can cause is an :class:`AdoreInputError`; a failure of the engine
on a valid deck is an :class:`AdoreEngineError`.  Both derive from :class:`AdoreError`,
so ``except pyadore.AdoreError`` catches everything pyadore raises on purpose.
"""

from __future__ import annotations

__all__ = ["AdoreError", "AdoreInputError", "AdoreEngineError", "AdoreInterrupted", "MissingSeriesError",
           "MissingSeriesWarning", "STATUS_OK", "STATUS_INPUT", "STATUS_ENGINE"]

#: Status codes shared with the Fortran engine (fortran/core/error.f90) and used as
#: process exit codes by the ``adore`` executable and the ``pyadore`` CLI.
STATUS_OK = 0
STATUS_INPUT = 1
STATUS_ENGINE = 2


class AdoreError(Exception):
    """Base class of every error pyadore raises deliberately."""

    status = STATUS_ENGINE


class AdoreInputError(AdoreError):
    """The deck (or another input file) is missing, unreadable or invalid."""

    status = STATUS_INPUT


class AdoreEngineError(AdoreError):
    """The engine failed on an input it accepted (no convergence, numerical breakdown).
    ``print_path``, ``time_history`` and ``dataset``: what the failed run kept (each None
    when nothing); the last two are built on first access from :meth:`keep_partial`'s data,
    so a failing run imports neither pandas nor xarray unless they are asked for."""

    status = STATUS_ENGINE

    def keep_partial(self, time_history, dataset) -> None:
        """What the failed run kept, as callables without arguments that build its
        ``time_history`` (a pandas DataFrame) and ``dataset`` (an xarray Dataset) - each
        may return None - called on first access."""
        self._partial = (time_history, dataset)

    def _built(self, name: str, k: int):
        if name not in self.__dict__:
            make = getattr(self, "_partial", (None, None))[k]
            self.__dict__[name] = None if make is None else make()
        return self.__dict__[name]

    @property
    def time_history(self):
        """The steps of the kept plot-data file as a pandas DataFrame, or None."""
        return self._built("_time_history", 0)

    @time_history.setter
    def time_history(self, value) -> None:
        self._time_history = value

    @property
    def dataset(self):
        """The kept steps' results as an xarray Dataset (``run_complete`` 0), or None."""
        return self._built("_dataset", 1)

    @dataset.setter
    def dataset(self, value) -> None:
        self._dataset = value


class AdoreInterrupted(AdoreEngineError):
    """A run stopped by a stop signal: SIGINT (Ctrl-C), SIGTERM or SIGHUP (docs/dynamics.md,
    "Signals").  ``signal``: its number; ``status``: 128 + that number, the exit status a
    shell shows for ``pyadore run`` and ``adore`` stopped by it; ``print_path``: the print
    file kept (marked incomplete, or complete when the signal came after the last time
    step), None when the run stopped before its first time step ended and left no file;
    ``time_history``: the steps recorded in the kept plot-data file, or None."""

    def __init__(self, message: str, signal: int, print_path=None, time_history=None):
        super().__init__(message)
        self.signal = int(signal)
        self.status = 128 + int(signal)
        self.print_path = print_path
        if time_history is not None:
            self.time_history = time_history


class MissingSeriesError(AdoreInputError):
    """A figure cannot be made: the run, print file or time history lacks every series it
    plots.  The message is one line naming the figure type and the missing series."""


class MissingSeriesWarning(UserWarning):
    """A figure was made without one of its series (or without the compared run's): the
    message is one line naming the figure type and the missing series."""
