"""The time history of a run as a table, and its plot-data file beside the print.

A run that integrates time steps records the time histories that the report's figures plot
(issue #20 item 6; columns, units and rows in docs/plots.md, "The plot-data file").  The
engine returns them as an array (:func:`pyadore.run` makes :attr:`pyadore.Result.time_history`
of it with :func:`history_frame`) and writes them beside the print file as
``<print stem>.hist.csv`` (:func:`history_path`), which :func:`read_history_csv` reads back
and :func:`history_beside` finds for a print file.

The table is the contract of :mod:`pyadore.plots.history`: a :class:`pandas.DataFrame`
indexed by ``time_s`` (s), an integer column ``step``, float columns in SI units.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

from typing import TYPE_CHECKING

import numpy as np

from .errors import AdoreInputError

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["history_frame", "history_path", "read_history_csv", "read_history_values", "history_beside",
           "INCOMPLETE_PREFIX"]

#: First words of the last line of a plot-data file whose run stopped early (the print's
#: last line starts with ``*** RUN INCOMPLETE``).
INCOMPLETE_PREFIX = "# RUN INCOMPLETE"


def history_frame(values, columns) -> pd.DataFrame:
    """The time-history table of an engine history array ``values`` (rows x columns) with
    column names ``columns`` (the first two ``time_s``, ``step``)."""
    import pandas as pd

    values = np.asarray(values, dtype=float)
    columns = list(columns)
    if values.ndim != 2 or values.shape[1] != len(columns) or columns[:2] != ["time_s", "step"]:
        raise ValueError(f"a time history needs columns time_s, step, ... matching its array; got {columns[:3]} "
                         f"for an array of shape {values.shape}")
    frame = pd.DataFrame(values[:, 1:], columns=columns[1:], index=pd.Index(values[:, 0], name="time_s"))
    frame["step"] = frame["step"].round().astype(int)
    return frame


def history_path(print_path) -> Path:
    """The plot-data file of the print file ``print_path``: its extension replaced by
    ``.hist.csv`` (``out/appendix_c_ball.prt`` -> ``out/appendix_c_ball.hist.csv``)."""
    p = Path(os.fspath(print_path))
    return p.with_name((p.stem if p.suffix and p.stem else p.name) + ".hist.csv")


def read_history_csv(path) -> tuple[pd.DataFrame, str]:
    """The plot-data file at ``path``: (time-history table, "" or the reason the run stopped
    early, from its last line ``# RUN INCOMPLETE ...``).  Raises AdoreInputError naming the
    file (and line) when it is missing or is not a plot-data file."""
    values, columns, incomplete = read_history_values(path)
    return history_frame(values, columns), incomplete


def read_history_values(path) -> tuple[np.ndarray, list[str], str]:
    """The plot-data file at ``path`` as plain values, without pandas: (array rows x
    columns, column names, "" or the reason the run stopped early); errors as
    :func:`read_history_csv`."""
    p = Path(os.fspath(path))
    try:
        lines = p.read_text(encoding="ascii").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        reason = getattr(exc, "strerror", None) or exc
        raise AdoreInputError(f"{p}: cannot read the plot-data file ({reason})") from None
    incomplete = ""
    if lines and lines[-1].startswith(INCOMPLETE_PREFIX):
        incomplete = lines.pop()[len("# "):].strip()
    if not lines or not lines[0].startswith("time_s,step"):
        raise AdoreInputError(f"{p}: line 1: not a plot-data file (expected the header 'time_s,step,...')")
    columns = lines[0].split(",")
    rows = []
    for number, line in enumerate(lines[1:], start=2):
        cells = line.split(",")
        if len(cells) != len(columns):
            raise AdoreInputError(f"{p}: line {number}: {len(cells)} values, the header names {len(columns)}")
        try:
            rows.append([float(c) for c in cells])
        except ValueError:
            raise AdoreInputError(f"{p}: line {number}: a value is not a number") from None
    values = np.array(rows, dtype=float).reshape(len(rows), len(columns))
    return values, columns, incomplete


def history_beside(run) -> tuple[pd.DataFrame | None, str]:
    """The plot-data file beside a parsed print ``run`` (:class:`pyadore.printout.PrintRun`):
    (its table, "") when the file exists and belongs to the print - it ends at the print's
    last printed step (a run records its last step, and a print without time steps, such as
    a roller run's, has no plot-data file), it is incomplete exactly when the print is, and
    it holds every printed step with the printed time (within the print's 4 digits) - else
    (None, a note saying why it was not used; "" when there is no such file)."""
    path = history_path(run.path)
    if not path.is_file():
        return None, ""
    try:
        frame, incomplete = read_history_csv(path)
    except AdoreInputError as exc:
        return None, f"{path} not used: {exc}"
    other = "(a plot-data file of another run)"
    last_printed = run.step_numbers[-1] if run.step_numbers else None
    last_recorded = int(frame["step"].iloc[-1]) if len(frame) else None
    if last_printed is not None and last_recorded != last_printed:
        what = ("the print has no time steps" if last_printed == 0 else
                f"the print's last step is {last_printed}")
        return None, f"{path} not used: it ends at step {last_recorded}, {what} {other}"
    if bool(incomplete) != bool(run.incomplete):
        return None, (f"{path} not used: " + ("it says its run stopped early, the print does not " if incomplete
                                               else "the print says its run stopped early, it does not ") + other)
    recorded = dict(zip(frame["step"].tolist(), frame.index.to_numpy()))
    for number in run.step_numbers:
        printed = run.steps[number].header.get("time_s", math.nan)
        at = recorded.get(number)
        if at is None or not (isinstance(printed, float) and math.isclose(at, printed, rel_tol=1e-3, abs_tol=1e-12)):
            return None, (f"{path} not used: it does not hold the print's step {number} at its printed time "
                          "(a plot-data file of another run)")
    return frame, ""
