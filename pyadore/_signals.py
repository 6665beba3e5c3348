"""The stop signals of the ``pyadore`` command: SIGINT (Ctrl-C), SIGTERM, SIGHUP.

Installed first thing by the entry point (pyadore/__main__.py), before the command's
imports (click, the engine extension, numpy), so that a signal at any moment of the
command ends it with one line and no traceback (pyadore/cli.py):

* outside an engine run a signal raises :class:`SignalInterrupt` where the program is (an
  exception escaping the command after it counts as the signal: :func:`raised_signal`);
  inside an import it ends the command at once instead (a C extension's initialisation
  would print the exception as a traceback and turn it into an ImportError);
* during a run :class:`pyadore.progress.RunProgress` defers it to the run's next step
  boundary;
* the command then ends by the signal itself (:func:`exit_by_signal`): a shell sees 128 +
  its number (130, 143, 129).

Only the standard library's ``signal``, ``os`` and ``sys``: this module is imported before
anything else of the command.  A signal the process ignores (nohup, a background job)
stays ignored.
"""

from __future__ import annotations

import os
import signal
import sys

__all__ = ["STOP_SIGNALS", "SignalInterrupt", "signal_label", "install_command_handlers", "raised_signal",
           "set_phase", "hold_signals", "exit_by_signal"]

#: The signals that stop a run: Ctrl-C, ``kill``, a closed terminal (where the platform has them).
STOP_SIGNALS = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name))

_LABELS = {"SIGINT": "SIGINT (Ctrl-C)"}


def signal_label(signum: int) -> str:
    """``"SIGTERM"``, ``"SIGINT (Ctrl-C)"``, ... for a signal number."""
    try:
        name = signal.Signals(signum).name
    except ValueError:
        return f"signal {signum}"
    return _LABELS.get(name, name)


class SignalInterrupt(BaseException):
    """A stop signal that came to the ``pyadore`` command outside an engine run (its
    handlers, :func:`install_command_handlers`): ``signum`` is its number.  A BaseException,
    as KeyboardInterrupt is, so that no ``except Exception`` takes it for an error."""

    def __init__(self, signum: int):
        super().__init__(signal_label(signum))
        self.signum = signum


_raised: list[int] = []   # the command's stop signal, once raised (the command is ending)


def raised_signal() -> int | None:
    """The stop signal a :class:`SignalInterrupt` was raised for in this process, or None."""
    return _raised[0] if _raised else None


#: what the command is doing, for the line of a signal that ends it inside an import
_phase: list[str] = []


def set_phase(text: str) -> None:
    """What the command does now (e.g. ``"while starting: nothing done"``), said by a stop
    signal that has to end it inside an import; "" for nothing."""
    _phase[:] = [text] if text else []


def _in_import(frame) -> bool:
    """True when ``frame`` runs inside an import (importlib's frames below it)."""
    while frame is not None:
        if frame.f_code.co_filename.startswith("<frozen importlib"):
            return True
        frame = frame.f_back
    return False


def _raise_interrupt(signum, frame):
    if _raised:  # the command is ending already: a second signal must not interrupt its exit
        return
    _raised.append(signum)
    if _in_import(frame):
        # an exception raised inside an import may reach a C extension's initialisation
        # (numpy's import_array prints it as a traceback and raises ImportError): end here,
        # nothing is half-written by an import
        hold_signals()
        try:
            print(f"pyadore: stopped by {signal_label(signum)}" + (f" {_phase[0]}" if _phase else ""),
                  file=sys.stderr)
        except (OSError, ValueError):
            pass
        exit_by_signal(signum)
    raise SignalInterrupt(signum)


def install_command_handlers() -> None:
    """The ``pyadore`` command's handlers (main thread): every stop signal the process does
    not ignore raises :class:`SignalInterrupt` where the program is; an engine run
    (:class:`pyadore.progress.RunProgress`) defers them to its next step boundary meanwhile."""
    for sig in STOP_SIGNALS:
        try:
            if signal.getsignal(sig) is not signal.SIG_IGN:
                signal.signal(sig, _raise_interrupt)
        except (ValueError, OSError):  # not the main thread, an embedded interpreter
            pass


def hold_signals() -> None:
    """Ignore every stop signal from now on (main thread): the command is ending, a second
    signal must not interrupt its clean-up and message."""
    for sig in STOP_SIGNALS:
        try:
            signal.signal(sig, signal.SIG_IGN)
        except (ValueError, OSError):
            pass


def exit_by_signal(signum: int) -> None:
    """End the process by signal ``signum`` (its default action), after flushing stdout and
    stderr, so that the parent sees a death by that signal (a shell: exit status 128 +
    ``signum``); exit status 128 + ``signum`` should the signal not end the process."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:  # noqa: BLE001 - a closed terminal (SIGHUP) must not stop the exit
            pass
    try:
        signal.signal(signum, signal.SIG_DFL)
        if hasattr(signal, "pthread_sigmask"):
            signal.pthread_sigmask(signal.SIG_UNBLOCK, {signum})
        os.kill(os.getpid(), signum)
    except Exception:  # noqa: BLE001
        pass
    os._exit(128 + signum)
