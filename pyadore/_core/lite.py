"""The engine's entry points of a run (with or without a progress function) and of a deck's
cross-field checks, called without numpy: the production extension's shared object
(``pyadore._engine``) loaded with ctypes, its Fortran routines (fortran/api/wrappers.f90
``adore_run_file`` and ``adore_run_file_progress``, fortran/api/deck.f90
``adore_deck_cross_checks`` and ``adore_deck_cross_check_names``) called as f2py's generated
wrapper calls them: every argument by reference, the progress procedure as a C function
pointer, then one hidden length (``size_t``, gfortran >= 8) per character argument, in order
(build/*/_enginemodule.c).

Importing the extension as a module runs f2py's module initialisation, which imports numpy
(its C API): 70-110 ms of CPU on this machine, more than the rest of a step-0 run's start-up
and half of a sweep worker's boot (docs/sweeps.md, "Scaling, eighteenth session").  Loading
its shared object runs no Python and imports nothing; the same object (the same Fortran
state) serves the module if it is imported later.  :func:`lite_engine` returns None - and
:func:`pyadore._core.base._engine` the extension module - where the object cannot be loaded
this way or does not answer a first call as expected.
"""

from __future__ import annotations

import ctypes
import os
from functools import lru_cache

__all__ = ["LiteEngine", "lite_engine"]

#: the fixed lengths of the routines' character results (fortran/api/*.f90)
_NOTE, _MESSAGE, _MESSAGES, _CHECK_MESSAGE, _NAMES = 4096, 16384, 16384, 2048, 8192

_INT = ctypes.POINTER(ctypes.c_int)
_LEN = ctypes.c_size_t
_REAL = ctypes.POINTER(ctypes.c_double)
#: the progress procedure the engine calls after each time step: (step, n_steps, tau, time, stop)
_PROGRESS = ctypes.CFUNCTYPE(None, _INT, _INT, _REAL, _REAL, _INT)


def _blank(n: int):
    """A character result's buffer of ``n`` blanks (what a routine leaves unwritten reads as
    blank, as Fortran's own blank padding does)."""
    return ctypes.create_string_buffer(b" " * n, n)


class LiteEngine:
    """The four routines, with the f2py module's argument lists and results (character
    results as the bytes the routine wrote, blank-padded, as f2py gives them)."""

    def __init__(self, path: str) -> None:
        lib = ctypes.CDLL(path)
        self._run = lib.adore_run_file_
        self._run.restype = None
        self._run.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, _INT, _INT, ctypes.c_char_p, _INT,
                              ctypes.c_char_p, _LEN, _LEN, _LEN, _LEN, _LEN]
        self._run_progress = lib.adore_run_file_progress_
        self._run_progress.restype = None
        self._run_progress.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, _INT, _INT, ctypes.c_char_p,
                                       _INT, ctypes.c_char_p, _PROGRESS, _LEN, _LEN, _LEN, _LEN, _LEN]
        self._checks = lib.adore_deck_cross_checks_
        self._checks.restype = None
        self._checks.argtypes = [_INT, ctypes.POINTER(ctypes.c_double), _INT, _INT, _INT, _INT, _INT, ctypes.c_char_p,
                                 _INT, ctypes.c_char_p, _LEN, _LEN]
        self._names = lib.adore_deck_cross_check_names_
        self._names.restype = None
        self._names.argtypes = [_INT, ctypes.c_char_p, _LEN]

    def adore_run_file(self, deck_path: str, out_path: str, options: str):
        """Run a deck file, write its print: (integrated, history_rows, note, status, message)."""
        deck, out, opts = os.fsencode(deck_path), os.fsencode(out_path), options.encode("utf-8")
        integrated, rows, status = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
        note, message = _blank(_NOTE), _blank(_MESSAGE)
        self._run(deck, out, opts, ctypes.byref(integrated), ctypes.byref(rows), note, ctypes.byref(status), message,
                  len(deck), len(out), len(opts), _NOTE, _MESSAGE)
        return integrated.value, rows.value, note.raw, status.value, message.raw

    def adore_run_file_progress(self, deck_path: str, out_path: str, options: str, progress):
        """:meth:`adore_run_file` with ``progress(step, n_steps, tau, time_s) -> int`` called
        after every accepted time step (non-zero: stop there), as f2py's callback is; an
        exception it raises stops the run and is raised once the engine has returned (f2py
        raises it from the call as well).  The engine runs without the GIL between the calls
        (ctypes takes it for each call)."""
        raised: list[BaseException] = []

        def step(k, n, tau, time_s, stop) -> None:
            try:
                stop[0] = 1 if raised else int(progress(k[0], n[0], tau[0], time_s[0]) or 0)
            except BaseException as exc:  # noqa: BLE001 - raised again below, once the engine returned
                raised.append(exc)
                stop[0] = 1

        callback = _PROGRESS(step)
        deck, out, opts = os.fsencode(deck_path), os.fsencode(out_path), options.encode("utf-8")
        integrated, rows, status = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
        note, message = _blank(_NOTE), _blank(_MESSAGE)
        self._run_progress(deck, out, opts, ctypes.byref(integrated), ctypes.byref(rows), note, ctypes.byref(status),
                           message, callback, len(deck), len(out), len(opts), _NOTE, _MESSAGE)
        if raised:
            raise raised[0]
        return integrated.value, rows.value, note.raw, status.value, message.raw

    def adore_deck_cross_checks(self, values, have, nmax: int):
        """The cross-field checks on deck values (SI): (n, fields, warning, messages, status, message)."""
        k = len(values)
        vals = (ctypes.c_double * k)(*[float(v) for v in values])
        flags = (ctypes.c_int * k)(*[int(h) for h in have])
        fields, warning = (ctypes.c_int * nmax)(), (ctypes.c_int * nmax)()
        n, status = ctypes.c_int(), ctypes.c_int()
        messages, message = _blank(_MESSAGES), _blank(_CHECK_MESSAGE)
        self._checks(ctypes.byref(ctypes.c_int(k)), vals, flags, ctypes.byref(ctypes.c_int(nmax)), ctypes.byref(n),
                     fields, warning, messages, ctypes.byref(status), message, _MESSAGES, _CHECK_MESSAGE)
        return n.value, list(fields), list(warning), messages.raw, status.value, message.raw

    def adore_deck_cross_check_names(self, what: int) -> bytes:
        """The fields the cross-field checks read (1) or their rules (2), one a line."""
        text = _blank(_NAMES)
        self._names(ctypes.byref(ctypes.c_int(what)), text, _NAMES)
        return text.raw


@lru_cache(maxsize=1)
def lite_engine() -> LiteEngine | None:
    """The extension's shared object loaded with ctypes (once a process), or None when it
    cannot be found or loaded, lacks a routine, or its first call does not give the field
    names the cross-field checks read (identifiers, one a line): a calling convention other
    than the one above.  Imports neither numpy nor the extension module."""
    from importlib.util import find_spec

    try:
        spec = find_spec("pyadore._engine")
        if spec is None or not spec.origin or not os.path.isfile(spec.origin):
            return None
        engine = LiteEngine(spec.origin)
        names = engine.adore_deck_cross_check_names(1).decode("utf-8", errors="replace").rstrip().split("\n")
    except (ImportError, OSError, AttributeError, ValueError):
        return None
    if not names or not all(n.replace("_", "a").replace("/", "a").isalnum() for n in names):
        return None
    return engine
