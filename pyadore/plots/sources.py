"""Where a figure's data comes from: a print file, a parsed print, a run's Result.

:func:`load` turns what a figure function is given into a :class:`Source`: the parsed
print (:class:`pyadore.printout.PrintRun`), the lines an engine print keeps before its
banner (the deck listing and an ADRX7 traction-slip table; golden files have neither),
a label for legends, and the run's own time history when a :class:`pyadore.Result`
carries one (attribute ``time_history``, the DataFrame contract of
:mod:`pyadore.plots.history`).
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from ..errors import AdoreInputError
from ..printout import PrintRun, read_print
from ..printout.layout import BANNER_LINE, TIME_INTEGRATION_PREFIX

_TABLE_TITLE = re.compile(r"^ADRX7 TRACTION-SLIP TABLE \((\d+) POINTS\)")
_LISTING_TITLE = "Listing of input data records"


@dataclass
class Source:
    """One run to plot.  ``run`` is the parsed print (None for a bare time history);
    ``history`` a time-history DataFrame given with the run (None: built from the print's
    steps); ``listing`` the deck text the engine listed before the banner ("" if none);
    ``traction_table`` the ADRX7 table listed there (columns slip_m_s, kappa) or None."""

    label: str
    run: PrintRun | None = None
    history: pd.DataFrame | None = None
    listing: str = ""
    traction_table: pd.DataFrame | None = None
    path: str = ""
    notes: list = field(default_factory=list)
    #: the run-condition lines an engine print gives under ``TIME INTEGRATION:`` (what its
    #: time integration leaves out: "THERMAL MODEL OFF: ...", "CAGE CONTACTS OFF: ...").
    conditions: list = field(default_factory=list)
    #: (start, end) in s: the time window of the time-history figures (None: the whole run;
    #: either end None: open); set by :func:`pyadore.plots.make_set`'s ``window``
    window: tuple | None = None

    def condition(self, prefix: str) -> str:
        """The run-condition line starting with ``prefix`` (e.g. ``"THERMAL MODEL OFF"``), or ""."""
        return next((c for c in self.conditions if c.startswith(prefix)), "")

    @property
    def thermal_off(self) -> bool:
        """True when the print says its time integration ran with the thermal model off."""
        return bool(self.condition("THERMAL MODEL OFF"))

    @property
    def bearing_type(self) -> str:
        """``"ball"``, ``"roller"`` or ``""`` (unknown: a golden file's ``?``)."""
        text = ""
        if self.run is not None:
            text = str(self.run.bearing_type).lower()
        if not text or text == "?":
            deck = self.deck()
            if deck is not None and deck.bearing_type in (1, 2):
                return "ball" if deck.bearing_type == 1 else "roller"
            if self.run is not None and any(k.startswith("slices_") for s in self.run.steps.values()
                                            for k in s.tables):
                return "roller"
            return ""
        return "roller" if "roller" in text or "cyl" in text else "ball" if "ball" in text else ""

    def element_word(self) -> str:
        """``ball`` or ``roller`` (``rolling element`` when the type is unknown)."""
        return {"ball": "ball", "roller": "roller"}.get(self.bearing_type, "rolling element")

    def deck(self):
        """The deck the engine listed before the banner (a :class:`pyadore.deck.Deck`), or None."""
        if not self.listing.strip():
            return None
        from ..deck import parse_text

        deck, _problems = parse_text(self.listing, path=f"{self.path} (deck listing)")
        return deck


def _conditions(head: list[str]) -> list[str]:
    """The indented run-condition lines under the print's ``TIME INTEGRATION:`` line
    (docs/print-layout.md, section 1), stripped."""
    start = next((k for k, s in enumerate(head) if s.startswith(TIME_INTEGRATION_PREFIX)), None)
    out = []
    if start is not None:
        for s in head[start + 1:]:
            if not s.startswith("  ") or not s.strip():
                break
            out.append(s.strip())
    return out


def _pre_banner(path: Path) -> tuple[str, pd.DataFrame | None, list[str]]:
    """(deck listing text, ADRX7 table or None, run-condition lines) from the lines before
    the banner of the engine print at ``path``; ("", None, []) for a golden file that has
    no such lines."""
    try:
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return "", None, []
    end = next((k for k, s in enumerate(lines) if s.strip() == BANNER_LINE), len(lines))
    head = lines[:end]
    table = None
    for k, line in enumerate(head):
        m = _TABLE_TITLE.match(line.strip())
        if m:
            n = int(m.group(1))
            rows = []
            for j in range(k + 3, min(k + 3 + n, len(head))):
                parts = head[j].split()
                try:
                    rows.append((float(parts[0]), float(parts[1])))
                except (IndexError, ValueError):
                    raise AdoreInputError(f"{path}: line {j + 1}: expected a traction-slip table point (slip "
                                          "m/s, coefficient) of the ADRX7 listing") from None
            if len(rows) != n:
                raise AdoreInputError(f"{path}: the ADRX7 listing ends after {len(rows)} of its {n} points")
            table = pd.DataFrame(rows, columns=["slip_m_s", "kappa"])
    listing = ""
    starts = [k for k, s in enumerate(head) if s.strip() == _LISTING_TITLE]
    if starts:
        body = head[starts[0] + 1:]
        # the listing runs to the blank line before the banner's leading lines
        while body and not body[0].strip():
            body.pop(0)
        out = []
        for s in body:
            if not s.strip():
                break
            out.append(s)
        listing = "\n".join(out) + "\n"
    return listing, table, _conditions(head)


def _with_history(source: Source) -> Source:
    """The source with the time history of the plot-data file beside its print
    (:func:`pyadore.timehistory.history_beside`) when there is one that belongs to it; a note
    when a file there was not used, or when the print is incomplete."""
    from ..timehistory import history_beside

    history, note = history_beside(source.run)
    if history is not None:
        source.history = history
    if note:
        source.notes.append(note)
    if source.run.incomplete:
        source.notes.append(f"{source.label} is an incomplete print: {source.run.incomplete}")
    return source


def load(source, label: str | None = None) -> Source:
    """A :class:`Source` from a print-file path (str or Path), a PrintRun, a
    :class:`pyadore.Result`, a time-history DataFrame or a Source.  ``label`` names the run
    in legends (default: the print file's path).  Raises AdoreInputError for an unreadable
    print file."""
    if isinstance(source, Source):
        if label is not None:
            source.label = label
        return source
    if isinstance(source, pd.DataFrame):
        return Source(label=label or "time history", history=source)
    history = getattr(source, "time_history", None)
    if hasattr(source, "print_path") and hasattr(source, "print_run"):  # a pyadore.Result
        src = load(source.print_path, label)
        if isinstance(history, pd.DataFrame):
            src.history = history
            src.notes = [n for n in src.notes if "not used:" not in n]   # the Result's own history
        return src
    if isinstance(source, PrintRun):
        path = Path(source.path)
        listing, table, conditions = _pre_banner(path) if path.exists() else ("", None, [])
        return _with_history(Source(label=label or str(source.path), run=source, listing=listing,
                                    traction_table=table, path=str(source.path), conditions=conditions))
    if isinstance(source, (str, os.PathLike)):
        path = Path(os.fspath(source))
        run = read_print(path)
        listing, table, conditions = _pre_banner(path)
        return _with_history(Source(label=label or str(path), run=run, listing=listing, traction_table=table,
                                    path=str(path), conditions=conditions))
    raise TypeError(f"cannot plot a {type(source).__name__}: expected a print file path, a PrintRun, "
                    "a pyadore.Result or a time-history DataFrame")
