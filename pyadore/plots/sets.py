"""Figure sets and their files: which figure types a set holds, making them from one run
(and a compared one), and writing them as one multi-page PDF or one PNG per figure.

``report`` is every one of the report's ten figure types (figures 14-44) that the data
supports.  A figure the data cannot support is skipped with a one-line reason (the
:class:`~pyadore.errors.MissingSeriesError` message); a series missing from a figure that
is made is a one-line note (the :class:`~pyadore.errors.MissingSeriesWarning` message).
A PDF is written to a temporary file beside the target and renamed onto it only when every
page is written, so a failure never leaves a partial PDF.
"""

from __future__ import annotations

import os
import tempfile
import warnings
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import AdoreInputError, MissingSeriesError, MissingSeriesWarning
from . import style
from .cage import cage_land_force, cage_orbit, cage_velocities, pocket_force
from .load import load_distribution
from .performance import bulk_temperatures, power_loss, race_contacts, wear_rates
from .sources import load
from .traction import traction_slip


@dataclass(frozen=True)
class FigureType:
    """One of the report's figure types: number, file name, what it shows, its function
    and the report figures it reproduces."""

    number: int
    name: str
    caption: str
    function: object
    report_figures: str


FIGURE_TYPES = (
    FigureType(1, "load-distribution", "load distribution around the bearing", load_distribution, "14, 15"),
    FigureType(2, "power-loss", "total power loss vs time", power_loss, "16, 24, 33, 39"),
    FigureType(3, "wear-rates", "time-averaged wear rates vs time", wear_rates, "17, 25"),
    FigureType(4, "bulk-temperatures", "bulk temperatures vs time", bulk_temperatures, "18, 26, 34, 40"),
    FigureType(5, "race-contacts", "one rolling element's race contacts vs time", race_contacts,
               "19, 27, 35, 41"),
    FigureType(6, "cage-velocities", "cage mass-centre velocities vs time", cage_velocities, "20, 28, 36, 42"),
    FigureType(7, "cage-land-force", "cage/race contact force vs time", cage_land_force, "21, 29, 37, 43"),
    FigureType(8, "cage-orbit", "cage whirl orbit", cage_orbit, "22, 30, 38, 44"),
    FigureType(9, "pocket-force", "rolling element/cage pocket contact force vs time", pocket_force, "23, 31"),
    FigureType(10, "traction-slip", "traction-slip curve", traction_slip, "32"),
)

#: Figure sets by name: the figure type numbers each holds, in page order.
SETS = {"report": tuple(t.number for t in FIGURE_TYPES)}


@dataclass
class FigureSet:
    """The outcome of :func:`make_set`: ``figures`` [(FigureType, Figure)] in page order,
    ``skipped`` [(FigureType, reason)] and ``notes`` (one line each)."""

    figures: list = field(default_factory=list)
    skipped: list = field(default_factory=list)
    notes: list = field(default_factory=list)


def figure_types(chosen) -> list[FigureType]:
    """The figure types ``chosen`` names (numbers 1-10 or names such as ``power-loss``, as
    ints or texts), in page order; AdoreInputError naming the types for an unknown one."""
    picked = set()
    for item in chosen:
        if isinstance(item, FigureType):
            picked.add(item.number)
            continue
        text = str(item).strip()
        hit = next((t for t in FIGURE_TYPES if text in (str(t.number), f"{t.number:02d}", t.name)), None)
        if hit is None:
            names = ", ".join(f"{t.number} {t.name}" for t in FIGURE_TYPES)
            raise AdoreInputError(f"unknown figure {text!r}; the figure types are {names}")
        picked.add(hit.number)
    return [t for t in FIGURE_TYPES if t.number in picked]


def make_set(source, set_name: str = "report", *, compare=None, step: int | None = None, element: int = 1,
             table=None, label: str | None = None, compare_label: str | None = None, figures=None,
             window=None, ylim=None) -> FigureSet:
    """Make every figure of set ``set_name`` that the data of ``source`` (a print path,
    PrintRun or Result) supports; ``compare`` a second run overlaid on each; ``step`` the
    printed step of the load distribution; ``element`` the rolling element of types 5 and
    9; ``table`` an ADRX7 table file for type 10.  ``figures``: only these figure types
    (numbers or names, :func:`figure_types`).  ``window``: (start, end) in s, the time
    span of the time-history figures (types 2-9; either end None: open); their value axes
    scale to the data in the window.  ``ylim``: (low, high) of the value axis of every
    figure made (either None: automatic).  Raises AdoreInputError for an unknown set name
    or figure type or an unreadable print file."""
    if set_name not in SETS:
        raise AdoreInputError(f"unknown figure set {set_name!r}; the sets are {', '.join(SETS)}")
    if window is not None:
        start, end = window
        if start is not None and end is not None and not end > start:
            raise AdoreInputError(f"time window: the end ({end:g} s) must come after the start ({start:g} s)")
    run = load(source, label)
    other = load(compare, compare_label) if compare is not None else None
    for src in (run, other):
        if src is not None:
            src.window = window
    out = FigureSet()
    out.notes.extend(run.notes + (other.notes if other is not None else []))
    options = {1: {"step": step}, 5: {"element": element}, 9: {"element": element}, 10: {"table": table}}
    types = [t for t in FIGURE_TYPES if t.number in SETS[set_name]]
    if figures is not None:
        types = [t for t in figure_types(figures) if t in types]
    for ftype in types:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", MissingSeriesWarning)
            try:
                fig = ftype.function(run, compare=other, **options.get(ftype.number, {}))
            except MissingSeriesError as exc:
                out.skipped.append((ftype, str(exc)))
                continue
            finally:
                out.notes.extend(str(w.message) for w in caught if issubclass(w.category, MissingSeriesWarning))
        if ylim is not None:
            for ax in fig.axes:
                if ax.get_label() != "<colorbar>":
                    ax.set_ylim(*ylim)
        out.figures.append((ftype, fig))
    return out


def skipped_lines(skipped) -> list[str]:
    """The reasons of ``skipped`` ([(FigureType, reason)], :attr:`FigureSet.skipped`) as
    lines: figure types skipped for the same reason (a print of step 0 alone has no time
    history for types 2-9) share one line, ``figure types 2-9 (power-loss, wear-rates,
    ...): <reason>`` (the types by name)."""
    groups: dict[str, list] = {}
    for ftype, reason in skipped:
        head, sep, rest = reason.partition("): ")
        key = rest if sep and head.startswith("figure type") else reason
        groups.setdefault(key, []).append((ftype, reason))
    lines = []
    for key, items in groups.items():
        if len(items) == 1:
            lines.append(items[0][1])
            continue
        numbers = [t.number for t, _r in items]
        span = (f"{numbers[0]}-{numbers[-1]}" if numbers == list(range(numbers[0], numbers[-1] + 1))
                else ", ".join(map(str, numbers)))
        lines.append(f"figure types {span} ({', '.join(t.name for t, _r in items)}): {key}")
    return lines


def _file_mode(path: Path) -> int:
    """Permission bits of a file written at ``path``: those of the file it replaces, else
    what the umask gives a new file (a temporary file is created private, 0600)."""
    try:
        return path.stat().st_mode & 0o777
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def write_pdf(figures, path) -> Path:
    """Write ``figures`` ([(FigureType, Figure)]) as one PDF page each to ``path``, whole or
    not at all: a temporary file in the same directory, renamed onto ``path`` at the end."""
    from matplotlib.backends.backend_pdf import PdfPages

    path = Path(os.fspath(path))
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent)
    os.close(fd)
    try:
        with PdfPages(tmp, metadata={"Title": f"pyadore figures: {path.stem}", "Creator": "pyadore"}) as pdf:
            for _ftype, fig in figures:
                pdf.savefig(fig)
        os.chmod(tmp, _file_mode(path))
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def png_name(ftype: FigureType) -> str:
    """File name of a figure type's PNG: ``NN-name.png`` (type number, two digits)."""
    return f"{ftype.number:02d}-{ftype.name}.png"


def write_image(figure, path) -> Path:
    """Write one figure to ``path``, its type from the suffix (``.png``, ``.svg``, ``.pdf``,
    ...), whole or not at all (a temporary name, then renamed)."""
    path = Path(os.fspath(path))
    tmp = path.with_name(f".{path.name}.part")
    try:
        figure.savefig(tmp, format=path.suffix.lstrip(".").lower(), dpi=style.PNG_DPI)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path


def write_pngs(figures, directory) -> list[Path]:
    """Write each figure as ``directory/NN-name.png`` (each file whole: written to a
    temporary name, then renamed); returns the paths."""
    directory = Path(os.fspath(directory))
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for ftype, fig in figures:
        target = directory / png_name(ftype)
        tmp = target.with_name(f".{target.name}.part")
        try:
            fig.savefig(tmp, format="png", dpi=style.PNG_DPI)
            os.replace(tmp, target)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
        paths.append(target)
    return paths
