"""The ``pyadore`` command line: run, validate and diff ADORE decks and print files.

Bad input never shows a traceback: the message goes to stderr as one paragraph and
the exit status is 1 (2 when the engine fails on a valid deck, or for ``diff`` when
an input is unreadable).  A stop signal - SIGINT (Ctrl-C), SIGTERM, SIGHUP - at any
moment ends the command with one line saying what became of its files, and then by the
signal itself (a shell shows exit status 128 + its number: 130, 143, 129); a run stops at
its next time step first (pyadore/progress.py).  The handlers (pyadore/_signals.py) are
installed by the entry point (pyadore/__main__.py) before this module's imports.
"""

from __future__ import annotations

import stat
import sys
from pathlib import Path

import click

from ._signals import (SignalInterrupt, exit_by_signal, hold_signals, install_command_handlers, raised_signal,
                       signal_label)
from .errors import AdoreError, AdoreInputError, AdoreInterrupted
from .options import click_options

CONTEXT = {"help_option_names": ["-h", "--help"]}

#: True when this is the process's command (main()): a stop signal then ends the process
#: by the signal; under click's test runner a command exits with status 128 + the signal.
_COMMAND = {"process": False}


def _say(text: str) -> None:
    """A line on stderr; a terminal gone (SIGHUP) or closed pipe is not an error here."""
    try:
        click.echo(text, err=True)
    except (OSError, ValueError):
        pass


def _end_by_signal(signum: int, message: str) -> None:
    """Say what a stop signal left and end by it (exit_by_signal), or exit 128 + signum when
    this is not the process's command."""
    if _COMMAND["process"]:
        hold_signals()
    _say(message)
    if _COMMAND["process"]:
        exit_by_signal(signum)
    sys.exit(128 + signum)


def _fail(exc: AdoreError) -> None:
    if isinstance(exc, AdoreInterrupted):
        _end_by_signal(exc.signal, f"pyadore: {exc}")
    click.echo(f"pyadore: error: {exc}", err=True)
    sys.exit(exc.status)


_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISCHR, "a device"),
          (stat.S_ISBLK, "a device"), (stat.S_ISSOCK, "a socket"))


def _check_input_file(path: Path, what: str) -> None:
    """AdoreInputError when ``path`` exists but is not a regular file (a FIFO would make the
    reader wait for a writer for ever); a missing file is left to its reader."""
    try:
        mode = path.stat().st_mode
    except OSError:
        return
    if not stat.S_ISREG(mode):
        kind = next((words for test, words in _KINDS if test(mode)), "a special file")
        raise AdoreInputError(f"{path}: the {what} is {kind}, not a regular file: give the {what} file itself")


def _version() -> str:
    from . import __version__

    return __version__


def _show_version(ctx, _param, value) -> None:
    """``--version``: the version is looked up only when asked for (importlib.metadata costs
    a tenth of a second at every start otherwise)."""
    if not value or ctx.resilient_parsing:
        return
    click.echo(f"pyadore {_version()}")
    ctx.exit()


@click.group(context_settings=CONTEXT)
@click.option("--version", is_flag=True, expose_value=False, is_eager=True, callback=_show_version,
              help="Show the version and exit.")
def cli() -> None:
    """pyadore: run ADORE 5.0 decks, validate them, compare print files, plot them, sweep parameters."""


@cli.command()
@click.argument("deck", type=click.Path(dir_okay=False, path_type=Path))
@click.option("-o", "--out", type=click.Path(dir_okay=False, path_type=Path),
              help="print file to write [default: out/<deck name>.prt]")
@click.option("--steps", type=click.IntRange(min=0),
              help="time steps to integrate after step 0 (ball decks; thermal model off); 0 = the "
                   "quasi-static start only [default: as the deck says, Rec 1]")
@click_options(skip=("steps",))
def run(deck: Path, out: Path | None, steps: int | None, **options) -> None:
    """Run DECK through the engine and write its print file.

    A run with time steps also writes its plot-data file (time histories) beside the print,
    <print stem>.hist.csv, and shows a progress bar when stderr is a terminal.  Ctrl-C stops
    the time integration after its current step: the print is kept, marked incomplete on
    its last line; stopped before its first time step ended, it leaves no print.  Ctrl-C,
    SIGTERM and SIGHUP all do so, and the command then ends by the signal (exit status
    128 + its number: 130, 143, 129).  The print file, its plot-data file and their .part
    files at OUT are removed as the run starts: a refused, failed or stopped run never
    leaves an older print there."""
    import signal

    from .api import run as run_deck

    if out is None:
        out = Path("out") / (deck.stem + ".prt")
    finished = False
    try:
        try:
            out.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            click.echo(f"pyadore: error: cannot create the output directory {out.parent}: {exc.strerror}", err=True)
            sys.exit(1)
        try:
            result = run_deck(deck, steps=steps, out=out, **options)
        except AdoreError as exc:
            _fail(exc)
        finished = True
        click.echo(f"print file written: {result.print_path}")
        if result.history_path is not None:
            click.echo(f"plot-data file written: {result.history_path}")
        if result.results_path is not None:
            click.echo(f"results written: {result.results_path} (netCDF; docs/results.md)")
        for note in result.notes:
            click.echo(f"pyadore: note: {note}", err=True)
    except (SignalInterrupt, KeyboardInterrupt) as exc:  # outside the engine run (its own: AdoreInterrupted)
        signum = getattr(exc, "signum", signal.SIGINT)
        if finished:
            _end_by_signal(signum, f"pyadore: {signal_label(signum)} came after the run had ended: its files are "
                                   "complete")
        _end_by_signal(signum, f"pyadore: stopped by {signal_label(signum)} before the run started: no file "
                               f"written ({out})")


@cli.command()
@click.argument("deck", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--traction-table", type=click.Path(dir_okay=False, path_type=Path),
              help="also check a traction-slip table file (ADRX7) as `run` would read it")
def validate(deck: Path, traction_table: Path | None) -> None:
    """Check DECK against the record schema; list every problem at once."""
    from .deck import check_deck
    from .deck.problems import format_problems

    try:
        _check_input_file(deck, "deck")
        if traction_table is not None:
            _check_input_file(traction_table, "traction-slip table")
    except AdoreError as exc:
        _fail(exc)
    parsed, problems = check_deck(deck)
    table_error = None
    table = None
    if traction_table is not None:
        from .api import read_traction_table

        try:
            table = read_traction_table(traction_table)
        except AdoreError as exc:
            table_error = exc
    if problems:
        for text in format_problems(problems):
            click.echo(text, err=True)
        click.echo(f"{deck}: {len(problems)} problem(s)", err=True)
    if table_error is not None:
        click.echo(f"pyadore: error: {table_error}", err=True)
    if problems or table_error is not None:
        sys.exit(1)
    from .deck.validate import deck_warnings

    warnings = deck_warnings(parsed)
    for text in format_problems(warnings):
        click.echo("warning: " + text, err=True)
    summary = parsed.summary()
    click.echo(summary + (f" ({len(warnings)} warning(s))" if warnings else ""))
    if table is not None:
        click.echo(f"{traction_table}: traction-slip table, {len(table)} points, slip 0 to "
                   f"{table.slip_m_s.iloc[-1]:.5g} m/s, coefficient {table.kappa.min():.5g} to "
                   f"{table.kappa.max():.5g}")


@cli.command()
@click.argument("run_file", metavar="A", type=click.Path(dir_okay=False, path_type=Path))
@click.argument("golden", metavar="B", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--tolerances", type=click.Path(dir_okay=False, path_type=Path),
              help="tolerance file [default: golden/tolerances.toml]")
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text", show_default=True)
@click.option("--brief", is_flag=True,
              help="one line per column with values outside tolerance: counts and its worst value")
def diff(run_file: Path, golden: Path, tolerances: Path | None, fmt: str, brief: bool) -> None:
    """Compare print file A (a run) with B (a golden print, or another run) within tolerances.

    B's values are the reference of the relative differences.  The files are called "run"
    and "golden" when B is a golden print (a transcription of the report), else by their
    file names.  Text fields (the run title, ...) are listed on their own, never as numeric
    offenders; the run title never fails the comparison.  Exit 0 within, 1 outside, 2
    unreadable or not comparable (an empty or misspelt tolerance file, prints of different
    bearing types)."""
    from .diff import diff_command

    if brief and fmt == "json":
        click.echo("pyadore: error: --brief is a text report; the JSON report is always complete", err=True)
        sys.exit(2)
    sys.exit(diff_command(run_file, golden, tolerances, fmt, brief=brief))


def _plot_input(path: Path, what: str, tmpdir: Path, steps: int | None = None, options: dict | None = None):
    """A print file to plot: ``path`` itself when it is one (it has the banner line), else
    ``path`` run as a deck (``steps`` time steps, as it asks for when None, with the run
    ``options``) into ``tmpdir``."""
    from .api import run as run_deck
    from .errors import AdoreInputError
    from .printout.layout import BANNER_LINE

    _check_input_file(path, {"run": "print file (or deck)"}.get(what, "compared print file (or deck)"))
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            is_print = any(line.strip() == BANNER_LINE for line in handle)
    except OSError as exc:
        raise AdoreInputError(f"{path}: cannot read the {what} ({exc.strerror or exc})") from None
    if is_print:
        if steps is not None or any(v is not None for k, v in (options or {}).items()
                                    if k not in ("history_element", "traction_table")):
            click.echo(f"pyadore: note: {path} is a print file: --steps and the run options apply to a deck "
                       "only", err=True)
        return path
    click.echo(f"pyadore: {path} is not a print file: running it as a deck", err=True)
    result = run_deck(path, steps=steps, out=tmpdir / f"{what}-{path.stem}.prt", **(options or {}))
    for note in result.notes:
        click.echo(f"pyadore: note: {note}", err=True)
    return result.print_path


def _run_labels(run_file: Path, compare: Path | None) -> tuple[str, str | None]:
    """Legend names of the plotted and the compared run: their file stems, with their
    folder when the stems are the same (``out/appendix_c_ball``, ``golden/appendix_c_ball``)."""
    if compare is None:
        return run_file.stem, None
    if run_file.stem != compare.stem:
        return run_file.stem, compare.stem
    a = f"{run_file.parent.name}/{run_file.stem}" if run_file.parent.name else run_file.stem
    b = f"{compare.parent.name}/{compare.stem}" if compare.parent.name else compare.stem
    return (a, b) if a != b else (str(run_file), str(compare))


def _pair(text: str | None, what: str, unit: str) -> tuple | None:
    """``LOW:HIGH`` (either may be empty: open) as a (low, high) pair of floats."""
    if text is None:
        return None
    low, sep, high = text.partition(":")
    try:
        if not sep:
            raise ValueError
        pair = (float(low) if low.strip() else None, float(high) if high.strip() else None)
    except ValueError:
        raise AdoreInputError(f"{what} {text!r}: expected LOW:HIGH in {unit} (either may be left out, e.g. "
                              f"{'0.01:' if what == '--window' else '0:1000'})") from None
    if pair[0] is not None and pair[1] is not None and not pair[1] > pair[0]:
        raise AdoreInputError(f"{what} {text!r}: the high end must be above the low end")
    return pair


def _deprecated_element(ctx, param, value):
    if value is not None:
        click.echo("pyadore: note: --element is deprecated; use --history-element (the name `run` and "
                   "`sweep` use)", err=True)
    return value


@cli.command()
@click.argument("run_file", metavar="RUN", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--set", "set_name", default="report", show_default=True,
              help="figure set: 'report' = every figure type of the report that the data supports")
@click.option("--figure", "figures", multiple=True, metavar="N",
              help="only figure type N (1-10, or its name, e.g. power-loss); repeat for several. With one "
                   "figure, -o may name an image file (.png, .svg, .pdf)")
@click.option("-o", "--out", type=click.Path(path_type=Path),
              help="a .pdf file (one page per figure), a directory (one PNG per figure), or with one --figure "
                   "an image file [default: out/<RUN name>-report.pdf]")
@click.option("--compare", type=click.Path(dir_okay=False, path_type=Path),
              help="a second print file (or deck) overlaid on every figure, e.g. the golden print")
@click.option("--label", metavar="TEXT", help="the run's name in legends [default: its file name]")
@click.option("--compare-label", metavar="TEXT",
              help="the compared run's name in legends [default: its file name]")
@click.option("--t-start", type=float, metavar="SECONDS",
              help="time-history figures start here (s); their value axes scale to the window")
@click.option("--t-end", type=float, metavar="SECONDS", help="time-history figures end here (s)")
@click.option("--window", metavar="START:END",
              help="both ends of the time window at once, in s (either may be left out: 0.01:)")
@click.option("--ylim", metavar="LOW:HIGH",
              help="value-axis limits of every figure made (either may be left out), in the axis' unit")
@click.option("--step", type=int, help="printed step of the load distribution [default: the first printed step]")
@click.option("--steps", type=click.IntRange(min=0),
              help="a deck given as RUN or --compare: time steps to run after step 0 [default: as the deck says]")
@click.option("--history-element", "history_element", type=click.IntRange(min=1), default=None, metavar="N",
              help="rolling element of the race-contact and pocket-force figures (a deck is run with it) "
                   "[default: 1]")
@click.option("--element", "element_alias", type=click.IntRange(min=1), default=None, hidden=True,
              callback=_deprecated_element, expose_value=True)
@click.option("--traction-table", type=click.Path(dir_okay=False, path_type=Path),
              help="traction-slip table file (ADRX7) drawn in the traction-slip figure (a deck is run with it)")
@click_options(skip=("steps", "history_element", "traction_table"))
def plot(run_file: Path, set_name: str, figures: tuple[str, ...], out: Path | None, compare: Path | None,
         label: str | None, compare_label: str | None, t_start: float | None, t_end: float | None,
         window: str | None, ylim: str | None, step: int | None, steps: int | None, history_element: int | None,
         element_alias: int | None, traction_table: Path | None, **options) -> None:
    """Write the report's figures (figure types 1-10) from RUN, a print file or a deck.

    A deck is run first (with --steps and the run options of `pyadore run`).  Figures the
    data cannot support are skipped with one line per reason on stderr; exit 1 if none can
    be made.  A PDF is written whole or not at all."""
    import tempfile

    from .plots import figure_types, make_set, skipped_lines, write_image, write_pdf, write_pngs

    if history_element is not None and element_alias is not None and history_element != element_alias:
        click.echo("pyadore: error: --element and --history-element disagree; give --history-element only",
                   err=True)
        sys.exit(1)
    element = history_element or element_alias or 1
    try:
        span = _pair(window, "--window", "s")
        if span is not None and (t_start is not None or t_end is not None):
            raise AdoreInputError("--window and --t-start/--t-end say the same thing: give one of them")
        if span is None and (t_start is not None or t_end is not None):
            span = _pair(f"{'' if t_start is None else repr(t_start)}:{'' if t_end is None else repr(t_end)}",
                         "--t-start/--t-end", "s")
        limits = _pair(ylim, "--ylim", "the axis' unit")
        chosen = figure_types(figures) if figures else None
    except AdoreError as exc:
        _fail(exc)
    if out is None:
        out = Path("out") / f"{run_file.stem}-{set_name}.pdf"
    to_pdf = out.suffix.lower() == ".pdf"
    one_image = bool(out.suffix) and not to_pdf and chosen is not None and len(chosen) == 1
    if out.suffix and not to_pdf and not one_image and not out.is_dir():
        click.echo(f"pyadore: error: {out}: an image file holds one figure: choose it with --figure N, or give "
                   "a .pdf file or a directory", err=True)
        sys.exit(1)
    if one_image or (to_pdf and chosen is not None and len(chosen) == 1):
        from matplotlib.figure import Figure

        kinds = Figure().canvas.get_supported_filetypes()
        if out.suffix.lower().lstrip(".") not in kinds:
            click.echo(f"pyadore: error: {out}: unknown image type; use one of {', '.join(sorted(kinds))}", err=True)
            sys.exit(1)
    folder = out.parent if (to_pdf or one_image) else out
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        click.echo(f"pyadore: error: cannot create the output directory {folder}: {exc.strerror}", err=True)
        sys.exit(1)
    default_label, default_compare = _run_labels(run_file, compare)
    run_options = dict(options, history_element=element, traction_table=traction_table)
    try:
        if traction_table is not None:
            _check_input_file(traction_table, "traction-slip table")
        with tempfile.TemporaryDirectory(prefix="pyadore-plot-") as tmp:
            run_print = _plot_input(run_file, "run", Path(tmp), steps, run_options)
            other = (_plot_input(compare, "compare", Path(tmp), steps, run_options) if compare is not None
                     else None)
            made = make_set(run_print, set_name, compare=other, step=step, element=element, table=traction_table,
                            label=label or default_label, compare_label=compare_label or default_compare,
                            figures=chosen, window=span, ylim=limits)
    except AdoreError as exc:
        _fail(exc)
    for line in skipped_lines(made.skipped):
        click.echo(f"pyadore: skipped {line}", err=True)
    for note in made.notes:
        click.echo(f"pyadore: note: {note}", err=True)
    if not made.figures:
        which = f"figure(s) {', '.join(figures)}" if figures else f"set {set_name!r}"
        click.echo(f"pyadore: error: {run_file}: no figure of {which} can be made from its data", err=True)
        sys.exit(1)
    types = ", ".join(str(t.number) for t, _fig in made.figures)
    try:
        if one_image:
            write_image(made.figures[0][1], out)
        elif to_pdf:
            write_pdf(made.figures, out)
        else:
            paths = write_pngs(made.figures, out)
    except OSError as exc:
        click.echo(f"pyadore: error: cannot write {exc.filename or out}: {exc.strerror or exc}", err=True)
        sys.exit(1)
    if one_image:
        click.echo(f"figure written: {out} (figure type {types})")
    elif to_pdf:
        click.echo(f"figures written: {out} ({len(made.figures)} pages: figure types {types})")
    else:
        click.echo(f"figures written: {len(paths)} PNG files in {out} (figure types {types})")


@cli.command()
@click.argument("deck", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--vary", "vary", multiple=True, required=True, metavar="FIELD=V1,V2,...",
              help="a deck field and its values, in the deck's units (rpm for speeds, N for forces, m for "
                   "lengths and fits, K for temperatures); a value may be a range START:STOP:COUNT (both ends "
                   "included); FIELD as in docs/deck-format.md, REC/FIELD where several records have it (e.g. "
                   "8.2/density), or diametral_clearance (m) of a ball deck. Repeat for a grid.")
@click.option("--zip", "zip_values", is_flag=True,
              help="pair the i-th values of every --vary instead of the full grid")
@click.option("--steps", type=click.IntRange(min=0),
              help="time steps per case; 0 = the quasi-static start only [default: as the deck says]")
@click.option("-o", "--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="sweep folder: case decks and prints, manifest.json, summary.csv; rerun to resume")
@click.option("--workers", type=click.IntRange(min=1),
              help="local worker processes [default: the number of CPUs]")
@click.option("--scheduler", metavar="ADDRESS",
              help="run the cases on the Dask distributed scheduler at ADDRESS (e.g. tcp://127.0.0.1:8786)")
@click_options(skip=("steps",))
def sweep(deck: Path, vary: tuple[str, ...], zip_values: bool, steps: int | None, out_dir: Path,
          workers: int | None, scheduler: str | None, **options) -> None:
    """Run DECK over a grid of field values, one case folder each, into a summary table.

    Every run option of `pyadore run` applies to every case.

    Every case deck is the deck with the varied fields changed (the other records copied
    verbatim), validated before it runs.  A failed case is recorded with its message and
    never stops the others.  Rerunning the same command keeps the finished cases and runs
    only the missing and failed ones.  Exit status 0 when every case finished, 1 when some
    failed or the sweep could not start; a stop signal (Ctrl-C, SIGTERM, SIGHUP) ends the
    workers and then the command by that signal (exit status 128 + its number).
    """
    import os
    import signal

    if workers is not None and scheduler is not None:
        click.echo("pyadore: error: --workers and --scheduler exclude each other (the Dask cluster has its "
                   "own workers)", err=True)
        sys.exit(1)
    # the local workers boot first, while the client imports its modules and reads the deck:
    # started by pyadore/__main__.py before this module loaded, or here (a light module: the
    # runner, the deck reader and pandas are not needed for this)
    from .sweeps.execute import WorkerPool, take_early

    pool = None
    if scheduler is None:
        n = workers or os.cpu_count() or 1
        pool = take_early(n)
        if pool is None:
            pool = WorkerPool(n)
            pool.once = True  # the command's one sweep: its workers end with its last job
            pool.start()
    try:
        from .sweeps.runner import run_sweep

        run = run_sweep(deck, list(vary), out_dir, zip=zip_values, steps=steps, workers=pool,
                        scheduler=scheduler, **options)
    except AdoreError as exc:
        _fail(exc)
    except OSError as exc:  # the sweep folder cannot be made or written
        click.echo(f"pyadore: error: {out_dir}: {exc.strerror or exc}"
                   + (f" ({exc.filename})" if exc.filename else ""), err=True)
        sys.exit(1)
    except (SignalInterrupt, KeyboardInterrupt) as exc:  # the workers are ended (sweeps/execute.py)
        signum = getattr(exc, "signum", signal.SIGINT)
        if pool is not None:
            pool.close()
        _end_by_signal(signum, f"pyadore: sweep interrupted by {signal_label(signum)}; finished cases are kept "
                               f"in {out_dir}: rerun the same command to run the rest")
    finally:
        if pool is not None:
            pool.close()
    counts = run.status_counts()
    done = counts.get("ok", 0)
    click.echo(f"{len(run.cases)} cases: {done} finished" + "".join(
        f", {n} {status}" for status, n in counts.items() if status != "ok"))
    failed = [c.case_id for c in run.cases if run.entries.get(c.case_id, {}).get("status", "pending") != "ok"]
    if failed:
        for case in failed:
            first = (run.entries.get(case, {}).get("error") or "").strip().splitlines()
            click.echo(f"  {case}: {first[0] if first else 'no message'}", err=True)
        click.echo(f"full messages: {out_dir / 'manifest.json'}", err=True)
    click.echo(f"summary: {out_dir / 'summary.csv'}")
    sys.exit(1 if failed else 0)


@cli.command("plot-sweep")
@click.argument("sweep_dir", metavar="DIR", type=click.Path(file_okay=False, path_type=Path))
@click.option("--x", "x", required=True, metavar="FIELD", help="varied parameter on the horizontal axis")
@click.option("--y", "y", default="total_power_loss_W", show_default=True, metavar="COLUMN",
              help="result column of summary.csv to draw")
@click.option("--by", metavar="FIELD", help="varied parameter drawn as one line per value")
@click.option("--where", "where", multiple=True, metavar="FIELD=VALUE",
              help="hold another varied parameter at one value (repeat as needed)")
@click.option("--log-y", is_flag=True, help="logarithmic result axis (e.g. for lives)")
@click.option("--map", "as_map", is_flag=True,
              help="a map over --x and --by coloured by --y, stable/erratic cage whirl marked (cage stability map)")
@click.option("-o", "--out", type=click.Path(dir_okay=False, path_type=Path),
              help="image file to write [default: DIR/<y>_vs_<x>[_by_<by>][_map].png]")
def plot_sweep(sweep_dir: Path, x: str, y: str, by: str | None, where: tuple[str, ...], log_y: bool,
               as_map: bool, out: Path | None) -> None:
    """Draw a result of the sweep in DIR against a varied parameter, one line per value of --by."""
    from .plots.sweep import sweep_plot_command

    held = {}
    for item in where:
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip():
            click.echo(f"pyadore: error: --where {item!r}: expected FIELD=VALUE", err=True)
            sys.exit(1)
        held[name.strip()] = value.strip()
    try:
        path = sweep_plot_command(sweep_dir, x=x, y=y, by=by, where=held, out=out, log_y=log_y, map=as_map)
    except AdoreError as exc:
        _fail(exc)
    except OSError as exc:
        click.echo(f"pyadore: error: cannot write the plot: {exc}", err=True)
        sys.exit(1)
    click.echo(f"plot written: {path}")


def main() -> None:
    """The ``pyadore`` command (the entry point pyadore/__main__.py calls it once its signal
    handlers are in place; installed here too for a direct call)."""
    _COMMAND["process"] = True
    install_command_handlers()
    try:
        cli(prog_name="pyadore")
    except SignalInterrupt as exc:
        _end_by_signal(exc.signum, f"pyadore: stopped by {signal_label(exc.signum)}")
    except Exception:
        # raised after a stop signal interrupted something (an import a C extension turned
        # into ImportError, a library's clean-up): the signal's doing, not an error to show
        signum = raised_signal()
        if signum is None:
            raise
        _end_by_signal(signum, f"pyadore: stopped by {signal_label(signum)}")


if __name__ == "__main__":
    main()
