"""The outcome of a print comparison (:mod:`pyadore.diff`): every compared value, counts,
and the report as text (full or ``brief``: one line per column) or JSON.

The two files are named ``run`` and ``golden`` against a golden print, else neutrally
(their file stems, or ``a`` and ``b``): :func:`pyadore.diff.report_names`.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field

__all__ = ["Comparison", "DiffReport", "FREE_TEXT"]


@dataclass
class Comparison:
    """One compared (or skipped) golden value.

    ``name`` is ``step <n> <table> <row> <column>`` (``echo <name>`` for the echo);
    ``status`` is ``within``, ``outside``, ``unknown`` (golden marker, skipped),
    ``missing`` (the run lacks the value: counted as outside), ``not_computed`` (the
    run prints ``NaN``: the engine does not compute it; a failure of its own),
    ``deviation`` (outside the tolerance of a rule that documents a known deviation; not a
    failure; ``reason`` says why), ``text`` (a text field of the echo that differs, such
    as the run title: listed on its own, never a numeric offender) or ``nan_both`` (two
    runs compared, both print ``NaN``: no difference, counted, not compared).
    """

    name: str
    table: str
    column: str
    golden: object
    run: object
    status: str
    rel_error: float = float("nan")
    tolerance: str = ""
    reason: str = ""


@dataclass
class DiffReport:
    """Outcome of a comparison: every Comparison plus counts; ``exit_code`` 0 (all within) or 1
    (some value outside tolerance, missing or not computed by the engine)."""

    run_path: str
    golden_path: str
    tolerances_path: str
    comparisons: list = field(default_factory=list)
    #: "" when the run's print is complete; else why not (PrintRun.incomplete): its time
    #: integration stopped early, so its later steps are missing - never a match
    run_incomplete: str = ""
    #: the names of the two files in the report: ("run", "golden") against a golden print,
    #: else neutral ones (:func:`report_names`)
    names: tuple = ("run", "golden")

    def _count(self, *status: str) -> int:
        return sum(1 for c in self.comparisons if c.status in status)

    @property
    def compared(self) -> int:
        """Values compared (within + outside + missing + not computed + known deviations)."""
        return self._count("within", "outside", "missing", "not_computed", "deviation")

    @property
    def within(self) -> int:
        """Compared values within tolerance."""
        return self._count("within")

    @property
    def outside(self) -> int:
        """Compared values outside tolerance, including values missing from the run."""
        return self._count("outside", "missing")

    @property
    def missing(self) -> int:
        """Golden values the run does not print (counted in ``outside``)."""
        return self._count("missing")

    @property
    def not_computed(self) -> int:
        """Golden values the run prints as ``NaN``: not computed by the engine (a failure, not in ``outside``)."""
        return self._count("not_computed")

    def not_computed_columns(self) -> dict:
        """Count of not-computed values per ``table.column`` (echo values per name)."""
        out: dict = {}
        for c in self.comparisons:
            if c.status == "not_computed":
                key = f"{c.table}.{c.column}"
                out[key] = out.get(key, 0) + 1
        return out

    @property
    def deviations(self) -> int:
        """Values outside the tolerance of a known-deviation rule (not failures)."""
        return self._count("deviation")

    def deviation_columns(self) -> dict:
        """Per ``table.column`` with known deviations: (count, largest relative error, reason)."""
        out: dict = {}
        for c in self.comparisons:
            if c.status == "deviation":
                key = f"{c.table}.{c.column}"
                n, worst, _ = out.get(key, (0, 0.0, c.reason))
                out[key] = (n + 1, max(worst, c.rel_error), c.reason)
        return out

    def text_differences(self) -> list:
        """Text fields of the echo that differ (status ``text``), e.g. the run title."""
        return [c for c in self.comparisons if c.status == "text"]

    def failing_text(self) -> list:
        """The text differences that fail the comparison: all but the run title
        (:data:`FREE_TEXT`), which names a run rather than being a result of it."""
        return [c for c in self.text_differences() if c.column not in FREE_TEXT]

    @property
    def nan_both(self) -> int:
        """Values both prints give as ``NaN`` (two runs compared): counted, not compared."""
        return self._count("nan_both")

    @property
    def unknown(self) -> int:
        """Golden values marked unknown (``?``): skipped, not compared."""
        return self._count("unknown")

    @property
    def exit_code(self) -> int:
        """0 when every compared value is within tolerance, 1 otherwise (outside, missing, not
        computed, a text field other than the run title that differs, or an incomplete run print)."""
        return 0 if (self.outside == 0 and self.not_computed == 0 and not self.run_incomplete
                     and not self.failing_text()) else 1

    def offenders(self, limit: int | None = 10) -> list:
        """Values outside tolerance, worst relative error first (missing ones last)."""
        bad = [c for c in self.comparisons if c.status in ("outside", "missing")]
        bad.sort(key=lambda c: (c.status == "missing", -(c.rel_error if not math.isnan(c.rel_error) else math.inf)))
        return bad if limit is None else bad[:limit]

    def column_max(self) -> dict:
        """Largest relative error per ``table.column`` over the compared values."""
        out: dict = {}
        for c in self.comparisons:
            if c.status in ("within", "outside", "deviation") and not math.isnan(c.rel_error):
                key = f"{c.table}.{c.column}"
                out[key] = max(out.get(key, 0.0), c.rel_error)
        return out

    def column_summary(self) -> list:
        """Per ``table.column`` with a value compared: (key, compared, outside, not computed,
        worst Comparison by relative error or None), the columns with values outside first,
        worst relative error first."""
        groups: dict = {}
        for c in self.comparisons:
            if c.status in ("unknown", "text", "nan_both"):
                continue
            key = f"{c.table}.{c.column}"
            g = groups.setdefault(key, [0, 0, 0, None])
            g[0] += 1
            g[1] += c.status in ("outside", "missing")
            g[2] += c.status == "not_computed"
            if c.status in ("within", "outside", "deviation") and not math.isnan(c.rel_error):
                if g[3] is None or c.rel_error > g[3].rel_error:
                    g[3] = c
        rows = [(k, n, out, nc, worst) for k, (n, out, nc, worst) in groups.items()]
        rows.sort(key=lambda r: (r[2] == 0, -(r[4].rel_error if r[4] is not None else -1.0), r[0]))
        return rows

    def _brief(self) -> str:
        a, b = self.names
        lines = [f"{a}: {self.run_path}", f"{b}: {self.golden_path}", f"tolerances: {self.tolerances_path}",
                 f"compared {self.compared}  within {self.within}  outside {self.outside}  "
                 f"not computed {self.not_computed}  text fields differing {len(self.text_differences())}"]
        summary = self.column_summary()
        rows = [r for r in summary if r[2]]
        if rows:
            lines += ["", f"columns with values outside tolerance ({len(rows)}), worst first:",
                      f"  {'column':<44} {'outside':>9}  worst ({a} vs {b}, relative difference)"]
            for key, n, out, _nc, worst in rows[:BRIEF_ROWS]:
                text = "-" if worst is None else (f"{worst.name}: {_show(worst.run)} vs {_show(worst.golden)}, "
                                                  f"{_percent(worst.rel_error)}")
                lines.append(f"  {key:<44} {f'{out}/{n}':>9}  {text}")
            if len(rows) > BRIEF_ROWS:
                lines.append(f"  ... and {len(rows) - BRIEF_ROWS} more column(s) (the full report: without --brief)")
        nan = [(r[0], r[3]) for r in summary if r[3]]
        if nan:
            shown = ", ".join(f"{k} ({n})" for k, n in nan[:6]) + (f", ... ({len(nan) - 6} more)" if len(nan) > 6 else "")
            lines += ["", f"not computed by the engine (NaN in {a}): {self.not_computed} value(s) in {len(nan)} "
                          f"column(s): {shown}"]
        if self.nan_both:
            lines += ["", f"NaN in both (not computed by the engine in either run; not compared): {self.nan_both}"]
        texts = self.text_differences()
        if texts:
            lines += ["", "text fields that differ:"]
            lines += [f"  {c.column}: {str(c.run)!r} vs {str(c.golden)!r}" for c in texts]
        lines += ["", "result: " + self._result()]
        if self.run_incomplete:
            lines.insert(0, f"INCOMPLETE RUN: {self.run_path}: {self.run_incomplete}; the steps after it are missing")
        return "\n".join(lines)

    def _result(self) -> str:
        if self.exit_code == 0:
            return "all compared values within tolerance"
        parts = [f"the {self.names[0]} print is incomplete"] if self.run_incomplete else []
        parts += [f"{self.outside} value(s) outside tolerance"] if self.outside else []
        if self.not_computed:
            parts.append(f"{self.not_computed} value(s) not computed by the engine")
        if self.failing_text():
            parts.append(f"{len(self.failing_text())} text field(s) differ")
        return ", ".join(parts)

    def render(self, fmt: str = "text", brief: bool = False) -> str:
        """The report as ``text`` (counts, worst offenders, per-column maxima; with ``brief``
        one line per column with values outside tolerance: counts and its worst value) or
        ``json``."""
        if fmt == "text" and brief:
            return self._brief()
        if fmt == "json":
            def num(v):
                if isinstance(v, float) and (math.isnan(v) or math.isinf(v)):
                    return None
                return v if isinstance(v, (int, float, str)) or v is None else repr(v)
            return json.dumps({
                "run": self.run_path, "golden": self.golden_path, "tolerances": self.tolerances_path,
                "names": list(self.names),
                "text_differences": [{"name": c.column, "run": c.run, "golden": c.golden,
                                      "fails": c.column not in FREE_TEXT} for c in self.text_differences()],
                "run_incomplete": self.run_incomplete,
                "compared": self.compared, "within": self.within, "outside": self.outside,
                "missing": self.missing, "not_computed": self.not_computed,
                "not_computed_columns": self.not_computed_columns(),
                "unknown": self.unknown, "deviations": self.deviations, "nan_both": self.nan_both,
                "deviation_columns": {k: {"count": n, "max_rel_error": num(w), "reason": why}
                                      for k, (n, w, why) in self.deviation_columns().items()},
                "exit_code": self.exit_code,
                "offenders": [{"name": c.name, "golden": num(c.golden), "run": num(c.run), "status": c.status,
                               "rel_error": num(c.rel_error), "tolerance": c.tolerance}
                              for c in self.offenders(None)],
                "column_max_rel_error": self.column_max(),
            }, indent=2)
        if fmt != "text":
            raise ValueError(f"unknown report format {fmt!r} (text or json)")
        a, b = self.names
        lines = [f"{a + ':':<11} {self.run_path}", f"{b + ':':<11} {self.golden_path}",
                 f"tolerances: {self.tolerances_path}",
                 f"compared {self.compared}  within {self.within}  outside {self.outside}"
                 f" (missing {self.missing})  not computed by the engine {self.not_computed}"
                 f"  unknown {self.unknown} ({b} '?', not compared)"
                 f"  known deviations {self.deviations}"
                 + (f"  NaN in both {self.nan_both} (not compared)" if self.nan_both else "")]
        off = self.offenders(20)
        if off:
            lines.append("")
            lines.append(f"worst offenders ({len(off)} of {self.outside}):")
            lines.append(f"  {'name':<60} {b:>12} {a:>12} {'rel err':>10}  tolerance")
            for c in off:
                g = _show(c.golden)
                r = _show(c.run)
                e = "-" if math.isnan(c.rel_error) else f"{c.rel_error:.3%}"
                lines.append(f"  {c.name:<60} {g:>12} {r:>12} {e:>10}  {c.tolerance}")
        nc = self.not_computed_columns()
        if nc:
            lines.append("")
            lines.append(f"not computed by the engine ({self.not_computed} value(s) printed NaN), per column:")
            for key in sorted(nc):
                lines.append(f"  {key:<52} {nc[key]}")
        texts = self.text_differences()
        if texts:
            lines.append("")
            lines.append("text fields that differ (not numeric; the run title does not fail the comparison):")
            lines += [f"  {c.column}: {str(c.run)!r} vs {str(c.golden)!r}" for c in texts]
        dv = self.deviation_columns()
        if dv:
            lines.append("")
            lines.append(f"known deviations ({self.deviations} value(s) outside tolerance, documented in the tolerance file):")
            for key in sorted(dv):
                n, worst, why = dv[key]
                lines.append(f"  {key:<52} {n:4d}  worst {worst:.3%}  {why}")
        cm = self.column_max()
        if cm:
            lines.append("")
            lines.append("largest relative error per column:")
            for key in sorted(cm):
                lines.append(f"  {key:<52} {cm[key]:.3%}")
        lines.append("")
        lines.append("result: " + self._result())
        if self.run_incomplete:
            lines.insert(0, f"INCOMPLETE RUN: {self.run_path}: {self.run_incomplete}; the steps after it are missing")
        return "\n".join(lines)


#: Text fields of the echo that name a run rather than result from it: a difference is
#: listed, never a failure (the run title: a variant of a deck is often titled anew).
FREE_TEXT = ("banner.run_id",)

#: Columns listed by the brief report (the worst first); the rest are counted.
BRIEF_ROWS = 25


def _percent(rel: float) -> str:
    return "-" if math.isnan(rel) else ("inf" if math.isinf(rel) else f"{rel:.3%}")


def _show(v) -> str:
    if isinstance(v, float):
        return "nan" if math.isnan(v) else f"{v:.4E}"
    return str(v)
