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


def run_option_table() -> list[tuple]:
    """The engine's run option table (fortran/model/run_options.f90), one tuple per option:
    (name, kind, default, minimum, off-flag, value name, choices tuple, help)."""
    n, names, kinds, defaults, minimums, flags, metavars, choices, helps = _engine().adore_run_option_table(64)
    rows = []
    for k in range(int(n)):
        rows.append((_text(names[k]), int(kinds[k]), _text(defaults[k]), int(minimums[k]), _text(flags[k]),
                     _text(metavars[k]), tuple(c for c in _text(choices[k]).split(",") if c), _text(helps[k])))
    return rows


def run_plan(deck_path: str | os.PathLike, options: str = "") -> tuple[int, int, int]:
    """(time steps after step 0, history rows, history columns) of a run of the deck with
    the run options ``options`` (the engine's ``name=value`` lines, :mod:`pyadore.options`):
    what :func:`run_file` will integrate and the shape of the arrays holding its time
    history (0, 0 without time steps).  Status checked."""
    n_steps, rows, cols, status, message = _engine().adore_run_plan(os.fspath(deck_path), options)
    check(int(status), message)
    return int(n_steps), int(rows), int(cols)


class RunOutput:
    """What :func:`run_file` returns: ``integrated`` time steps after step 0, the engine's
    ``note`` ("" when it has nothing to say), and the time history as a 2-D float array
    ``history`` (rows x columns, SI units) with its ``columns`` names (docs/plots.md); an
    empty array and no names for a run without time steps."""

    def __init__(self, integrated: int, note: str, history, columns: list[str]):
        self.integrated = integrated
        self.note = note
        self.history = history
        self.columns = columns


def run_file(deck_path: str | os.PathLike, out_path: str | os.PathLike, options: str = "",
             progress=None) -> RunOutput:
    """Run the engine on a deck file and write the print file (and, with time steps, the
    plot-data file beside it); return a :class:`RunOutput`.  Status checked: an engine
    failure raises :class:`~pyadore.errors.AdoreEngineError`, whose ``output`` attribute
    then holds the RunOutput of the steps done (a time integration that stopped early).

    options: the run options as the engine's ``name=value`` lines
    (:func:`pyadore.options.options_text`; the engine checks names, ranges and choices).
    progress: ``None``, or a function ``progress(step, n_steps, tau, time_s) -> int`` the
    engine calls after every accepted time step; a non-zero return stops the run there
    (incomplete).  It must not raise.  With a progress function the call holds the GIL
    (the function is Python); without one it releases it (threads run at once).
    """
    engine = _engine()
    _n_steps, rows, cols = run_plan(deck_path, options)
    args = (os.fspath(deck_path), os.fspath(out_path), options, max(rows, 1), max(cols, 1))
    if progress is None:
        out = engine.adore_run_file(*args)
    else:
        out = engine.adore_run_file_progress(*args, progress)
    hist, n_rows, n_cols, columns, integrated, note, status, message = out
    names = [c for c in _text(columns).split(",") if c] if n_cols > 0 else []
    output = RunOutput(int(integrated), _text(note), hist[:int(n_rows), :int(n_cols)].copy(), names)
    try:
        check(int(status), message)
    except AdoreEngineError as exc:
        exc.output = output
        raise
    return output


def engine_version() -> str:
    """Version string compiled into the engine."""
    return _text(_engine().adore_version())
