"""The engine handle and the status check shared by every wrapper group."""

from __future__ import annotations

import os
import sys

from ..errors import (
    STATUS_ENGINE,
    STATUS_INPUT,
    STATUS_OK,
    AdoreEngineError,
    AdoreError,
    AdoreInputError,
)


def _engine(lite: bool = False):
    """The engine extension module; ``lite`` (a run, the deck's cross-field checks): while the
    module is not imported, its shared object loaded without numpy (:mod:`.lite`; the module
    where that cannot be done), which offers those routines only."""
    if lite and "pyadore._engine" not in sys.modules:
        from .lite import lite_engine

        engine = lite_engine()
        if engine is not None:
            return engine
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


def run_option_table() -> list[tuple]:
    """The engine's run option table (fortran/model/run_options.f90), one tuple per option:
    (name, kind, default, minimum, off-flag, value name, choices tuple, help)."""
    n, names, kinds, defaults, minimums, flags, metavars, choices, helps = _engine().adore_run_option_table(64)
    rows = []
    for k in range(int(n)):
        rows.append((_text(names[k]), int(kinds[k]), _text(defaults[k]), int(minimums[k]), _text(flags[k]),
                     _text(metavars[k]), tuple(c for c in _text(choices[k]).split(",") if c), _text(helps[k])))
    return rows


class RunOutput:
    """What :func:`run_file` returns: ``integrated`` time steps after step 0, the engine's
    ``note`` ("" when it has nothing to say) and ``history_rows``, the rows of the time
    history the engine wrote to the plot-data file beside the print (0: none written)."""

    def __init__(self, integrated: int, note: str, history_rows: int):
        self.integrated = integrated
        self.note = note
        self.history_rows = history_rows


def run_file(deck_path: str | os.PathLike, out_path: str | os.PathLike, options: str = "",
             progress=None) -> RunOutput:
    """Run the engine on a deck file and write the print file (and, with time steps, the
    plot-data file beside it, every value to its last digit); return a :class:`RunOutput`.
    The deck is read once.  Status checked: an engine failure raises
    :class:`~pyadore.errors.AdoreEngineError`, whose ``output`` attribute then holds the
    RunOutput of the steps done (a time integration that stopped early).

    options: the run options as the engine's ``name=value`` lines
    (:func:`pyadore.options.options_text`; the engine checks names, ranges and choices).
    progress: ``None``, or a function ``progress(step, n_steps, tau, time_s) -> int`` the
    engine calls after every accepted time step; a non-zero return stops the run there
    (incomplete).  It must not raise.  With a progress function the call holds the GIL
    (the function is Python); without one it releases it (threads run at once).  A process that
    has not imported the engine extension calls it without importing numpy (:mod:`.lite`; the
    engine then runs without the GIL between the progress function's calls).
    """
    engine = _engine(lite=True)
    args = (os.fspath(deck_path), os.fspath(out_path), options)
    if progress is None:
        out = engine.adore_run_file(*args)
    else:
        out = engine.adore_run_file_progress(*args, progress)
    integrated, history_rows, note, status, message = out
    output = RunOutput(int(integrated), _text(note), int(history_rows))
    try:
        check(int(status), message)
    except AdoreEngineError as exc:
        exc.output = output
        raise
    return output


def engine_version() -> str:
    """Version string compiled into the engine."""
    return _text(_engine().adore_version())
