"""Python facade: run a deck and get a :class:`Result`."""

from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

from . import _IMPORT_PID, _core
from .errors import AdoreEngineError, AdoreError, AdoreInputError

if TYPE_CHECKING:
    import pandas as pd
    import xarray as xr

    from .results import ResultArrays

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
    #: the run's balances over the last half of a completed time integration (issue #28;
    #: docs/operating-points.md, "Balances"): ``window_s`` (start, end), ``revolutions``,
    #: ``drive_power_W``, ``dissipation_W`` (race contacts' heat, their damping, and what
    #: the cage contacts take), ``race_heat_W``, ``damping_W``, ``cage_work_W``,
    #: ``cage_heat_W`` (the cage contacts' friction heat, part of the print's power loss),
    #: ``energy_rate_W`` (mechanical energy's mean rate), ``whirl_frame_W`` (the power of the
    #: centripetal and Coriolis terms a free cage's ADORE whirl coordinates omit, 0 by
    #: Newton's equations: docs/cage.md, "The cage's whirl frame"),
    #: ``drive_ratio`` (drive / dissipation), ``inner_force_N`` and ``inner_carried_N``
    #: (the inner race's mean contact force and the applied load plus its weight),
    #: ``inner_residual_N``, ``inner_momentum_rate_N`` (the inner race's momentum change over
    #: the window over its duration: the residual's inertia, NaN in notes written before it),
    #: ``outer_force_N``, ``outer_expected_N``, ``outer_residual_N``,
    #: ``closure`` ((drive - dissipation - energy change - whirl frame) / max(|drive|,
    #: dissipation, 1 uW), as the engine computes it from its full-precision means; the
    #: means are the integrator's stage quadrature for the deck's IMEX method, else the
    #: trapezoid of the steps' ends: docs/operating-points.md, "Stage quadrature");
    #: None without time steps or for a run that stopped early
    balance: dict | None = None
    #: the run's full results as numpy arrays (:class:`pyadore.results.ResultArrays`: the
    #: variables of :attr:`dataset`, without xarray); None without time steps
    arrays: "ResultArrays | None" = field(default=None, repr=False)
    #: the time history's values and column names (the plot-data file's), from which
    #: :attr:`time_history` is built when first asked for
    _history: tuple | None = field(default=None, repr=False)
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    def _built(self, key: str, source, build):
        """The value ``key`` set on this Result, else built from ``source`` by ``build`` once
        (and kept); None when there is no source."""
        if key not in self._cache:
            if source is None:
                return None
            self._cache[key] = build(source)
        return self._cache[key]

    @property
    def time_history(self) -> "pd.DataFrame | None":
        """The time history the run recorded (docs/plots.md: index ``time_s``, column
        ``step``, SI columns), the same as its plot-data file :attr:`history_path`; None
        without time steps.  Built on first access (pandas is imported then)."""
        from .timehistory import history_frame

        return self._built("time_history", self._history, lambda history: history_frame(*history))

    @time_history.setter
    def time_history(self, value: "pd.DataFrame | None") -> None:
        self._cache["time_history"] = value

    @time_history.deleter
    def time_history(self) -> None:  # back to the run's own
        self._cache.pop("time_history", None)

    @property
    def dataset(self) -> "xr.Dataset | None":
        """The run's full results (docs/results.md): every element's race contacts, speeds and
        positions, the cage and the races at every recorded step, full precision, dimensions
        ``time``, ``element``, ``race``; the same as its netCDF file :attr:`results_path`;
        None without time steps (or for a bearing kind without element results).  Built from
        :attr:`arrays` on first access (xarray is imported then, not by the run)."""
        return self._built("dataset", self.arrays, lambda arrays: arrays.to_dataset())

    @dataset.setter
    def dataset(self, value: "xr.Dataset | None") -> None:
        self._cache["dataset"] = value

    @dataset.deleter
    def dataset(self) -> None:  # back to the run's own
        self._cache.pop("dataset", None)

    @property
    def results_path(self) -> Path | None:
        """The netCDF file beside the print (``<print stem>.nc``); None without a dataset."""
        if self.arrays is None and self._cache.get("dataset") is None:
            return None
        from .results import results_path

        return results_path(self.print_path)

    def mean(self, last_revolutions: float | None = None, t_start: float | None = None,
             t_end: float | None = None) -> "xr.Dataset":
        """Time-weighted averages of every :attr:`dataset` variable over the last
        ``last_revolutions`` shaft revolutions, or over the window [t_start, t_end] (s; by
        default the whole run): :func:`pyadore.results.time_mean`.  Raises AdoreInputError
        for a run without a dataset or a window outside the run."""
        given = self._cache.get("dataset")  # a dataset set on the Result, else the run's own arrays
        source = given if given is not None else self.arrays
        if source is None:
            raise AdoreInputError(f"{self.print_path}: the run has no dataset (no time steps) to average")
        from .results import time_mean

        return time_mean(source, last_revolutions=last_revolutions, t_start=t_start, t_end=t_end)

    @property
    def history_path(self) -> Path | None:
        """The plot-data file beside the print (``<print stem>.hist.csv``); None without
        time steps."""
        if self._history is None and self._cache.get("time_history") is None:
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


def run(deck_path, steps: int | None = None, out=None, progress=None, overrides: dict | None = None,
        **options) -> Result:
    """Run the ADORE deck at ``deck_path`` and return its :class:`Result`.

    deck_path: a deck file, or a :class:`pyadore.deck.Deck` (written to a temporary file for
    the run; the Deck itself is not changed).
    overrides: ``{field: value}`` changes to the deck for this run, fields named as
    :meth:`pyadore.deck.Deck.set` takes them (``"inner_race_speed"``, or ``"REC/FIELD"``
    where several records have the field), values in the deck's units (rpm, N, m, K); the
    deck file is not changed.  An unknown or ambiguous field, or a value that does not fit
    its field, raises AdoreInputError.

    steps: ``None`` runs as many time steps as the deck asks for (Rec 1; Appendix C: 2500),
    ``0`` only the quasi-static start, ``n`` integrates ``n`` time steps after step 0.
    Time steps are integrated for ball decks (thermal model off by default: the bulk
    temperatures stay at the initial ones; ``thermal="deck"`` runs the deck's thermal model,
    docs/thermal.md; ``notes`` says what the run leaves out); a roller deck's print
    ends after step 0 (``notes`` says so).  A run with time steps also writes its plot-data
    file beside the print (:attr:`Result.history_path`) and returns the same table as
    :attr:`Result.time_history`.
    out: the print file to write; by default a file in a fresh temporary directory.
    progress: ``None`` shows a progress bar (tqdm: step, simulated time, time left) on
    stderr when it is a terminal; ``True`` always, ``False`` never; or a function
    ``progress(step, n_steps, time_s)`` called after every time step.
    options: the run options of the engine's table (:func:`pyadore.options.run_options`;
    ``pyadore run --help`` lists them with their help), by name, e.g.
    ``substeps=5`` (integrator steps in each printed time step, report 4.4.5),
    ``history_element=3`` (the rolling element of the time history's contact columns),
    ``traction_table="table.txt"`` (an ADRX7 traction-slip table replacing the deck's
    RE/race traction model, listed in the print), ``ball_start="outer-race-control"``
    (report 4.4.7; ball decks), ``moment_equilibrium=True`` (the inner race's
    misalignment solved for moment equilibrium in the quasi-static start, ADORE kFS4 =
    kFS5 = 0; ball decks), ``traction_2d=False`` (the one-dimensional race traction, a
    developer option).  ``None`` for an option means its default.
    The paths are checked before anything is read or written (a deck or traction table
    that is not a regular file, an output that is an input or a directory:
    AdoreInputError), then the print file, its plot-data file and their ``.part`` files
    left at ``out`` by an earlier run are removed: a run that is refused, fails or is
    stopped never leaves an older print posing as its own.
    Raises :class:`~pyadore.errors.AdoreInputError` for bad input (an unknown option
    included) and :class:`~pyadore.errors.AdoreEngineError` when the engine fails.  A time
    integration that stops early (a failed integration, a non-finite state) raises
    AdoreEngineError naming the step and time; its print is kept and ends with the line
    ``*** RUN INCOMPLETE ...`` (the error's ``print_path``; ``time_history``: the steps
    done).  A stop signal (main thread: SIGINT/Ctrl-C; SIGTERM and SIGHUP where the process
    has a handler for them, as the ``pyadore`` command has) stops the run at its next time
    step and raises :class:`~pyadore.errors.AdoreInterrupted` (an
    AdoreEngineError): the print kept and marked incomplete, or no print when the run had
    not ended its first time step (pyadore/progress.py).
    """
    from .options import options_text

    if steps is None:
        engine_steps = STEPS_FROM_DECK
    else:
        if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
            raise AdoreInputError(f"steps must be None or an integer >= 0, got {steps!r}")
        engine_steps = steps
    if "steps" in options:
        raise AdoreInputError("steps is run()'s own argument; pass it once")
    if options.get("threads") is None and os.getpid() != _IMPORT_PID:
        options["threads"] = 1  # a forked child (pyadore/__init__.py, _IMPORT_PID)
    text = options_text(steps=engine_steps, **options)
    if not isinstance(deck_path, (str, os.PathLike)) or overrides:
        with tempfile.TemporaryDirectory(prefix="pyadore-deck-") as tmp:
            written, shown = _deck_file(deck_path, overrides, Path(tmp))
            try:
                result = run(written, steps=steps, out=out, progress=progress, **options)
            except AdoreError as exc:  # name the deck as the caller knows it, not the temporary file
                if exc.args and isinstance(exc.args[0], str):
                    what = f"{shown} ({'with overrides' if overrides else 'a Deck'})"
                    exc.args = (exc.args[0].replace(str(written), what),) + exc.args[1:]
                raise
        result.deck_path = shown
        return result
    deck = Path(os.fspath(deck_path))
    if out is None:
        out_path = Path(tempfile.mkdtemp(prefix="pyadore-")) / (deck.stem + ".prt")
    else:
        out_path = Path(os.fspath(out))
        if out_path.parent and not out_path.parent.exists():
            raise AdoreInputError(f"{out_path}: the output directory {out_path.parent} does not exist")
    from .progress import RunProgress

    # a stop signal while the run and the reading of its files last: AdoreInterrupted (progress.py)
    with RunProgress(progress, label=deck.name, print_path=out_path) as watch:
        try:
            output = _core.run_file(deck, out_path, text, watch.callback)
        except AdoreEngineError as exc:
            done = getattr(exc, "output", None)
            exc.print_path = out_path if out_path.exists() else None
            history = _written_history(out_path, done)
            arrays = _written_results(deck, out_path, done, history)
            exc.keep_partial(None if history is None else partial(_history_frame, history),
                             None if arrays is None else arrays.to_dataset)
            raise
        text = out_path.read_text(encoding="utf-8", errors="replace")
        history = _written_history(out_path, output)
        arrays = _written_results(deck, out_path, output, history)
    return Result(deck_path=deck, print_path=out_path, steps=steps, text=text,
                  notes=[output.note] if output.note else [], steps_integrated=output.integrated,
                  _history=history, arrays=arrays, balance=parse_balance(output.note))


def _history_frame(history: tuple) -> "pd.DataFrame":
    from .timehistory import history_frame

    return history_frame(*history)


_NUM = r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)"
_VEC = _NUM * 3


def parse_balance(note: str) -> dict | None:
    """The balance line of a run note (the engine's ``balance over the last half of the
    run ...``; fortran/bearings/ball.f90) as numbers (:attr:`Result.balance`); None when
    the note has none."""
    if "balance over the last half" not in (note or ""):
        return None  # no pattern to compile (tens of ms): a step-0 run has no balance
    import re

    m = re.search(
        r"balance over the last half of the run \(t" + _NUM + " to" + _NUM + " s," + _NUM +
        r" shaft revolutions\): drive power" + _NUM + " W, dissipation" + _NUM +
        r" W \(race contacts" + _NUM + " W, contact damping" + _NUM + " W, cage contacts" + _NUM +
        " W of which friction heat" + _NUM + r" W\), energy change" + _NUM + " W, whirl frame" + _NUM +
        " W, drive/dissipation" + _NUM + "; inner race contact force" + _VEC +
        " N against applied load and weight" + _VEC + " N, residual" + _NUM +
        r" N(?: \(the race's momentum change over the window" + _NUM + r" N\))?; outer race contact force" + _VEC +
        " N against" + _VEC + " N, residual" + _NUM + " N",
        note or "")
    if m is None:
        return None
    v = [float(x) if x is not None else float("nan") for x in m.groups()]
    return {"window_s": (v[0], v[1]), "revolutions": v[2], "drive_power_W": v[3], "dissipation_W": v[4],
            "race_heat_W": v[5], "damping_W": v[6], "cage_work_W": v[7], "cage_heat_W": v[8],
            "energy_rate_W": v[9], "whirl_frame_W": v[10], "drive_ratio": v[11],
            "inner_force_N": tuple(v[12:15]), "inner_carried_N": tuple(v[15:18]), "inner_residual_N": v[18],
            "inner_momentum_rate_N": v[19],
            "outer_force_N": tuple(v[20:23]), "outer_expected_N": tuple(v[23:26]), "outer_residual_N": v[26],
            "closure": _printed_closure(note, v)}


def parse_forced_steps(note: str) -> tuple[int, int] | None:
    """The run note's count of time steps accepted at the Rec 2.1 minimum step with their
    error above the error limit (ADORE's rule; fortran/driver/run.f90 add_forced_steps_note) as
    (forced, accepted); None when the note has none (no such step, or no time steps)."""
    import re

    m = re.search(r"(\d+) of (\d+) time steps accepted at the minimum step", note or "")
    return (int(m.group(1)), int(m.group(2))) if m else None


def parse_forced_diagnosis(note: str) -> dict | None:
    """The run note's diagnosis of its forced steps (fortran/driver/run.f90
    add_forced_steps_note, issue #28): ``err_max`` (the largest error estimate of those steps
    over the error limit), ``within_2`` (how many of them were within twice the limit) and
    ``leaders``, the unknowns whose error component led most of them, as (name, steps) pairs,
    most first (at most three); None when the note has no forced steps."""
    import re

    m = re.search(r"their error up to ([0-9.]+) times the limit \((\d+) of them within twice it\), led by (.*?)"
                  r" \(a smaller Rec 2\.1 minimum step", note or "")
    if not m:
        return None
    leaders = [(name, int(steps)) for name, steps in re.findall(r"(.+?) at (\d+)(?:, |$)", m.group(3))
               if name != "other unknowns"]
    return {"err_max": float(m.group(1)), "within_2": int(m.group(2)), "leaders": leaders}


def _printed_closure(note: str, v: list) -> float:
    """The note's closure, which the engine computes from its full-precision means (a small
    closure is a difference of large terms, lost in their five printed digits); from the
    printed terms when the note has none."""
    import re

    m = re.search(r"closure \(drive - dissipation - energy change - whirl frame\)/max\(\|drive\|, dissipation, 1 uW\)"
                  + _NUM, note)
    return float(m.group(1)) if m else _closure(v[3], v[4], v[9], v[10])


def _closure(drive: float, dissipation: float, rate: float, whirl_frame: float = 0.0) -> float:
    """(drive - dissipation - energy change - whirl frame) / max(|drive|, dissipation, 1 uW):
    0 up to the integration error (Newton-Euler, with the power of the terms a free cage's
    ADORE whirl coordinates omit: fortran/forces/ball_power.f90; the run note flags it above
    0.01; below a microwatt, a shaft at rest, there is nothing to balance:
    fortran/bearings/ball.f90)."""
    return (drive - dissipation - rate - whirl_frame) / max(abs(drive), dissipation, 1e-6)


def run_title(deck_path: Path) -> str:
    """The run identification of a deck (Rec 3.1's text), "" when it has none."""
    import re

    try:
        text = deck_path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""
    m = re.search(r"^Rec 3\.1[ \t]+(.*?)[ \t]*$", text, re.MULTILINE)
    return m.group(1) if m else ""


def _written_results(deck_path: Path, print_path: Path, output, history: tuple | None) -> "ResultArrays | None":
    """The results of the element file the engine wrote beside the print (when it wrote
    one) as numpy arrays, written to its netCDF file (``run_complete`` 0 for a run that
    stopped early); None otherwise.  ``history``: the plot-data file's (values, column
    names), already read.  Neither xarray nor pandas is imported."""
    if output is None or output.history_rows <= 0:
        return None
    from .results import element_path, results_arrays, results_path, write_netcdf

    if not element_path(print_path).is_file():
        return None
    arrays = results_arrays(print_path, title=run_title(deck_path), history=history)
    write_netcdf(arrays, results_path(print_path))
    return arrays


def _deck_file(deck, overrides, tmp: Path) -> tuple[Path, Path]:
    """The deck (a Deck, or a deck file) with ``overrides`` applied, written into ``tmp``:
    (that file, the path the Result names: the deck's own)."""
    import copy

    from .deck import Deck, DeckError, read_deck, write_deck

    if isinstance(deck, Deck):
        deck = copy.deepcopy(deck)
    elif isinstance(deck, (str, os.PathLike)):
        deck = read_deck(Path(os.fspath(deck)))
    else:
        raise AdoreInputError(f"run: expected a deck file path or a pyadore.deck.Deck, got {type(deck).__name__}")
    if overrides is not None and not isinstance(overrides, dict):
        raise AdoreInputError(f"overrides: expected a dict {{field: value}}, got {type(overrides).__name__}")

    for name, value in (overrides or {}).items():
        if deck._derived(str(name)) is not None:
            try:
                deck.set(str(name), value)
            except DeckError as exc:
                raise AdoreInputError(f"overrides: {exc}") from None
            continue
        try:
            records, field = deck.locate(str(name))
        except DeckError as exc:
            raise AdoreInputError(f"overrides: {exc}") from None
        kind = records[0].fields[field].spec.kind
        ok = (isinstance(value, str) if kind == "text" else
              isinstance(value, int) and not isinstance(value, bool) if kind == "int" else
              isinstance(value, (int, float)) and not isinstance(value, bool))
        if not ok:
            what = {"text": "a text", "int": "an integer"}.get(kind, "a real")
            raise AdoreInputError(f"overrides: {name} is {what} field ({records[0].fields[field].spec.unit}), "
                                  f"got {value!r}")
        deck.set(str(name), value)
    shown = Path(str(deck.path))
    target = tmp / ((shown.stem if shown.stem and not shown.stem.startswith("<") else "deck") + ".inp")
    try:
        write_deck(deck, target)
    except DeckError as exc:
        raise AdoreInputError(f"overrides: {exc}") from None
    return target, shown


def _written_history(print_path: Path, output) -> tuple | None:
    """The time history the engine wrote beside the print (every value to its last digit,
    ES24.16E3), when the run wrote one, as (values, column names) without pandas; None
    otherwise."""
    if output is None or output.history_rows <= 0:
        return None
    from .timehistory import history_path, read_history_values

    path = history_path(print_path)
    if not path.exists():
        return None
    values, columns, _incomplete = read_history_values(path)
    return values, columns
