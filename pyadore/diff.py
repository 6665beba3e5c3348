"""Numeric comparison of two ADORE print files (``pyadore diff RUN GOLDEN``).

Steps are matched by step number (only the steps the golden file prints), tables by
name, rows by index (element number, roller end, body name) and columns by name.  Each
golden value is compared with the run's value under the tolerance rule that applies
(``golden/tolerances.toml``; the last matching rule wins):
``|run - golden| <= max(abs, rel * |golden|)``, where ``abs`` defaults to
``rel * max |golden|`` over the same column of the same table (the zero rule).
Golden values marked unknown (``?``) are skipped and counted.  A value the run prints
as ``NaN`` (the engine does not compute it yet) is a failure of its own category, "not
computed by the engine": counted, listed in the summary and failing the comparison, never
skipped.  The echo is compared exactly to printed precision.

Two rule keys serve the dynamic steps, where a run's rolling elements need not sit where
the golden file's do (a run that reached another time, or a different integrator):
``match = "azimuth"`` compares each golden element with the run's value at the golden
element's orbital position (periodic linear interpolation over the run's elements by
their printed orbital positions, section 1), and ``deviation = "reason"`` marks the
values of that rule as a known deviation: outside its tolerance it is counted as
``deviation`` (listed with the reason, not failing the comparison); within, as usual.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path

from .diff_report import FREE_TEXT, Comparison, DiffReport
from .errors import AdoreInputError
from .printout import PrintFormatError, read_print
from .printout.model import (NOT_COMPUTED, NOT_COMPUTED_VALUE, OVERFLOW, OVERFLOW_VALUE, UNKNOWN, UNKNOWN_VALUE,
                             PrintRun)

try:  # Python 3.11+
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    tomllib = None

REPO_TOLERANCES = Path(__file__).resolve().parent.parent / "golden" / "tolerances.toml"

__all__ = ["diff_prints", "diff_command", "DiffReport", "Comparison", "load_tolerances", "bearing_kind",
           "report_names", "PrintFormatError", "FREE_TEXT"]


# ----------------------------------------------------------------------------- tolerances
@dataclass
class _Rule:
    step: str
    table: str
    columns: tuple
    rel: float
    abs: float | None
    match: str = "index"        #: "index" or "azimuth" (rolling-element tables)
    deviation: str = ""         #: reason of a known deviation ("" for none)
    deviation_max: float = math.inf  #: largest relative error a known deviation may have

    def matches(self, step_kind: set, table: str, column: str) -> bool:
        if self.step != "any" and self.step not in step_kind:
            return False
        if self.table not in ("*", table):
            return False
        return "*" in self.columns or column in self.columns


#: the keys of a tolerance file and of its rules (golden/tolerances.toml explains them)
TOLERANCE_KEYS = ("defaults", "rule")
DEFAULTS_KEYS = ("rel",)
RULE_KEYS = ("step", "table", "columns", "rel", "abs", "match", "deviation", "deviation_max")


def _unknown_keys(found, known, where: str) -> None:
    extra = [k for k in found if k not in known]
    if extra:
        raise ValueError(f"{where}: unknown key{'s' if len(extra) > 1 else ''} "
                         f"{', '.join(repr(k) for k in extra)} (expected {', '.join(known)})")


def load_tolerances(path) -> tuple[float, list]:
    """Read a tolerance file: (default relative tolerance, rules in file order).

    Raises PrintFormatError naming the file when it is unreadable or malformed, when a key
    is unknown (a misspelt ``[[rules]]`` or ``colums`` would silently compare at other
    tolerances) or when it holds no tolerance at all (an empty file, or comments only:
    every value would be compared at the built-in 1 % without anyone choosing it).
    """
    p = Path(path)
    if tomllib is None:  # pragma: no cover
        raise PrintFormatError(f"{p}: reading tolerance files needs Python 3.11 (tomllib)")
    try:
        if p.exists() and not p.is_file():
            raise PrintFormatError(f"{p}: the tolerance file is not a regular file")
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except OSError as exc:
        raise PrintFormatError(f"{p}: cannot read the tolerance file: {exc.strerror or exc}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise PrintFormatError(f"{p}: not a valid TOML tolerance file: {exc}") from None
    if not data.get("defaults") and not data.get("rule"):
        raise PrintFormatError(f"{p}: no tolerances in the tolerance file (neither [defaults] rel nor a [[rule]]"
                               + ("" if not data else f"; it has {', '.join(repr(k) for k in data)}")
                               + "): give a tolerance file with its rules, e.g. golden/tolerances.toml")
    try:
        _unknown_keys(data, TOLERANCE_KEYS, "top level")
        if not isinstance(data.get("defaults", {}), dict):
            raise ValueError("defaults: expected a table [defaults] with rel = ...")
        _unknown_keys(data.get("defaults", {}), DEFAULTS_KEYS, "[defaults]")
        default = float(data.get("defaults", {}).get("rel", 0.01))
        rules = []
        for k, r in enumerate(data.get("rule", []), 1):
            if not isinstance(r, dict):
                raise ValueError(f"rule {k}: expected a table [[rule]]")
            _unknown_keys(r, RULE_KEYS, f"rule {k}")
            step = r.get("step", "any")
            if step not in ("initial", "final", "any"):
                raise ValueError(f"rule {k}: step must be initial, final or any, not {step!r}")
            cols = r.get("columns", ["*"])
            if isinstance(cols, str):
                cols = [cols]
            rel = float(r["rel"])
            ab = r.get("abs")
            if rel < 0 or (ab is not None and float(ab) < 0):
                raise ValueError(f"rule {k}: tolerances must not be negative")
            match = r.get("match", "index")
            if match not in ("index", "azimuth"):
                raise ValueError(f"rule {k}: match must be index or azimuth, not {match!r}")
            deviation = r.get("deviation", "")
            if not isinstance(deviation, str):
                raise ValueError(f"rule {k}: deviation must be a text (the reason)")
            dmax = float(r.get("deviation_max", math.inf))
            if dmax < 0 or ("deviation_max" in r and not deviation):
                raise ValueError(f"rule {k}: deviation_max must be >= 0 and needs a deviation reason")
            rules.append(_Rule(step, r.get("table", "*"), tuple(cols), rel, None if ab is None else float(ab),
                               match, deviation.strip(), dmax))
    except (KeyError, TypeError, ValueError) as exc:
        raise PrintFormatError(f"{p}: malformed tolerance rule: {exc}") from None
    return default, rules


def _rule_for(default: float, rules: list, kinds: set, table: str, column: str) -> _Rule:
    found = _Rule("any", "*", ("*",), default, None)
    for r in rules:
        if r.matches(kinds, table, column):
            found = r
    return found


# ----------------------------------------------------------------------------- comparing
def _compare_value(name, table, column, g, gmark, r, rmark, rule: _Rule, scale: float) -> Comparison:
    tol = f"rel {rule.rel:g}" + (f", abs {rule.abs:g}" if rule.abs is not None else "")
    if gmark == UNKNOWN:
        return Comparison(name, table, column, "?", r, "unknown", tolerance=tol)
    if rmark == NOT_COMPUTED and gmark == NOT_COMPUTED:   # two runs, neither computes it: no difference
        return Comparison(name, table, column, "NaN", "NaN", "nan_both", tolerance=tol)
    if rmark == NOT_COMPUTED:
        return Comparison(name, table, column, g, "NaN", "not_computed", tolerance=tol)
    if rmark == UNKNOWN or r is None:
        return Comparison(name, table, column, g, "?" if rmark == UNKNOWN else None, "missing", tolerance=tol)
    if gmark == OVERFLOW or rmark == OVERFLOW:
        ok = gmark == rmark
        return Comparison(name, table, column, "****" if gmark else g, "****" if rmark else r,
                          "within" if ok else "outside", 0.0 if ok else math.inf, tol)
    atol = rule.abs if rule.abs is not None else rule.rel * scale
    diff = abs(r - g)
    if column.endswith("_deg") and math.isfinite(diff):
        diff = abs((r - g + 180.0) % 360.0 - 180.0)   # angles: 360 and 0 are the same direction
    rel_err = diff / abs(g) if g != 0 else (0.0 if diff == 0 else math.inf)
    ok = diff <= max(atol, rule.rel * abs(g))
    status = "within" if ok else ("deviation" if rule.deviation and rel_err <= rule.deviation_max else "outside")
    return Comparison(name, table, column, g, r, status, rel_err, tol, rule.deviation if not ok else "")


def _compare_echo(report: DiffReport, golden: PrintRun, run: PrintRun) -> None:
    for key, g in golden.echo.items():
        name = f"echo {key}"
        r = run.echo.get(key)
        if g is UNKNOWN_VALUE:
            report.comparisons.append(Comparison(name, "echo", key, "?", r, "unknown", tolerance="printed"))
            continue
        if r is NOT_COMPUTED_VALUE and g is NOT_COMPUTED_VALUE:
            report.comparisons.append(Comparison(name, "echo", key, "NaN", "NaN", "nan_both", tolerance="printed"))
            continue
        if r is NOT_COMPUTED_VALUE:
            report.comparisons.append(Comparison(name, "echo", key, g, "NaN", "not_computed", tolerance="printed"))
            continue
        if r is None or r is UNKNOWN_VALUE:
            report.comparisons.append(Comparison(name, "echo", key, g, r, "missing", tolerance="printed"))
            continue
        if isinstance(g, float) and isinstance(r, (int, float)) and r is not OVERFLOW_VALUE:
            # half a unit in the 5th decimal of the ES12.5 mantissa
            half_ulp = 0.5 * 10.0 ** (math.floor(math.log10(abs(g))) - 5) if g != 0 else 0.0
            diff = abs(float(r) - g)
            ok = diff <= half_ulp * (1 + 1e-9)
            rel = diff / abs(g) if g else (0.0 if diff == 0 else math.inf)
        elif isinstance(g, str) or isinstance(r, str):
            ok = str(r).split() == str(g).split()
            report.comparisons.append(Comparison(name, "echo", key, g, r, "within" if ok else "text",
                                                 0.0 if ok else float("nan"), "text"))
            continue
        else:
            ok = g == r
            rel = 0.0 if ok else math.inf
        report.comparisons.append(Comparison(name, "echo", key, g, r, "within" if ok else "outside", rel, "printed"))


def _compare_scalars(report, table, gvals, gmarks, rvals, rmarks, rule_of) -> None:
    for col, g in gvals.items():
        rule = rule_of(table, col)
        r = rvals.get(col) if rvals else None
        rm = (rmarks or {}).get(col, "")
        report.comparisons.append(_compare_value(f"{table} {col}", table, col, g, gmarks.get(col, ""), r, rm,
                                                 rule, abs(g) if isinstance(g, (int, float)) and not math.isnan(g) else 0.0))


def bearing_kind(run: PrintRun) -> str:
    """``"ball"``, ``"roller"`` or ``""`` (unknown) of a parsed print: its banner's bearing
    type, else (a golden file's ``?``) its tables: a roller print lists its contact slices
    (``slices_<n>``), a ball print has rolling-element contacts and no slices."""
    text = str(run.bearing_type or "").strip().upper()
    if "ROLLER" in text or "CYL" in text:
        return "roller"
    if "BALL" in text:
        return "ball"
    tables = {name for step in run.steps.values() for name in step.tables}
    if any(name.startswith("slices_") for name in tables):
        return "roller"
    if "re_contact" in tables:
        return "ball"
    return ""


def diff_runs(run: PrintRun, golden: PrintRun, tolerances_path=None, names: tuple | None = None) -> DiffReport:
    """Compare two parsed print files; see :func:`diff_prints`.  ``names``: the two files'
    names in the report [default: :func:`report_names`]."""
    kinds = bearing_kind(run), bearing_kind(golden)
    if all(kinds) and kinds[0] != kinds[1]:
        raise PrintFormatError(f"{run.path} is a {kinds[0]} bearing print and {golden.path} a {kinds[1]} "
                               "bearing print: prints of different bearing types cannot be compared (give the "
                               f"golden file of a {kinds[0]} bearing)")
    tpath = Path(tolerances_path) if tolerances_path else _default_tolerances(Path(golden.path))
    default, rules = load_tolerances(tpath)
    report = DiffReport(run.path, golden.path, str(tpath), run_incomplete=run.incomplete,
                        names=tuple(names) if names else report_names(run.path, golden.path))
    _compare_echo(report, golden, run)
    numbers = golden.step_numbers
    for n in numbers:
        kinds = {"any"} | ({"initial"} if n == numbers[0] else set()) | ({"final"} if n == numbers[-1] else set())

        def rule_of(table, col, kinds=kinds):
            return _rule_for(default, rules, kinds, table, col)

        gstep = golden.steps[n]
        rstep = run.steps.get(n)
        _compare_scalars(report, f"step {n} header", gstep.header, gstep.markers.get("header", {}),
                         rstep.header if rstep else None, rstep.markers.get("header", {}) if rstep else None,
                         lambda t, c: rule_of("header", c))
        for tname, gdf in gstep.tables.items():
            gm = gstep.markers[tname]
            rdf = rstep.tables.get(tname) if rstep else None
            rm = rstep.markers.get(tname) if rstep else None
            for col in gdf.columns:
                rule = rule_of(tname, col)
                known = gdf[col][gm[col] == ""].abs()
                scale = float(known.max()) if len(known) else 0.0
                at_azimuth = (_azimuth_values(gstep, rstep, tname, col) if rule.match == "azimuth" and rdf is not None
                              else None)
                for idx in gdf.index:
                    label = "/".join(str(x) for x in idx) if isinstance(idx, tuple) else str(idx)
                    name = f"step {n} {tname} {label} {col}"
                    r = rmark = None
                    if at_azimuth is not None and idx in at_azimuth:
                        r, rmark = at_azimuth[idx]
                        name += " (at its azimuth)"
                    elif rdf is not None and col in rdf.columns and rdf.index.nlevels == gdf.index.nlevels:
                        try:
                            r = float(rdf.at[idx, col])
                            rmark = rm.at[idx, col]
                        except (KeyError, TypeError, ValueError):
                            r = rmark = None
                    report.comparisons.append(_compare_value(name, tname, col, float(gdf.at[idx, col]),
                                                             gm.at[idx, col], r, rmark, rule, scale))
    for table, gvals, gmarks, rvals, rmarks in (
            ("termination", golden.termination, golden.termination_markers, run.termination, run.termination_markers),
            ("statistics", golden.statistics, golden.statistics_markers, run.statistics, run.statistics_markers)):
        _compare_scalars(report, table, gvals, gmarks, rvals, rmarks,
                         lambda t, c: _rule_for(default, rules, {"any"}, t, c))
    return report


#: tables with one row per rolling element (index "element")
ELEMENT_TABLES = ("re_contact", "re_motion", "re_traction", "re_thermal", "re_cage")


def _azimuth_values(gstep, rstep, table: str, column: str):
    """{golden element: (run value, run marker)} of ``table.column`` at each golden element's
    orbital position (elements whose golden position is unknown are left out): periodic linear interpolation over the run's elements by their printed
    orbital positions (deg, section 1); an element's own value where the positions agree.
    None when either step lacks the positions or the table is not per element."""
    if table not in ELEMENT_TABLES:
        return None
    try:
        gpos = gstep.tables["re_contact"]["orbital_position_deg"]
        gpm = gstep.markers["re_contact"]["orbital_position_deg"]
        rpos = rstep.tables["re_contact"]["orbital_position_deg"]
        rpm = rstep.markers["re_contact"]["orbital_position_deg"]
        rdf = rstep.tables[table]
        rmk = rstep.markers[table]
    except (KeyError, AttributeError):
        return None
    if column not in rdf.columns or rdf.index.names != ["element"] or gstep.tables[table].index.names != ["element"]:
        return None                      # e.g. a roller's re_cage: one row per (element, end)
    pts = []
    for e in rpos.index:
        if rpm.at[e] != "" or e not in rdf.index:
            continue
        v = float(rdf.at[e, column])
        pts.append((float(rpos.at[e]) % 360.0, v, rmk.at[e, column]))
    if len(pts) < 2:
        return None
    pts.sort(key=lambda p: p[0])
    out = {}
    for e in gpos.index:
        if gpm.at[e] != "":
            continue                     # golden position unknown: compared row by row
        a = float(gpos.at[e]) % 360.0
        out[e] = _interpolate_periodic(pts, a, angular=column.endswith("_deg"))
    return out


def _interpolate_periodic(pts, a, angular: bool = False):
    """(value, marker) at angle a (deg) from points (angle, value, marker) sorted by angle in
    [0, 360): linear between the two neighbours, across 360 -> 0; a marker (NaN, ?) of
    either neighbour is carried (the value is not known).  angular: the values are angles
    in degrees, interpolated the short way round (359 and 1 give 0, not 180)."""
    for p in pts:
        if abs(p[0] - a) <= 1e-9:
            return p[1], p[2]
    lo = hi = None
    for p in pts:
        if p[0] < a:
            lo = p
        elif hi is None:
            hi = p
    if lo is None:
        lo = (pts[-1][0] - 360.0, pts[-1][1], pts[-1][2])
    if hi is None:
        hi = (pts[0][0] + 360.0, pts[0][1], pts[0][2])
    mark = lo[2] or hi[2]
    if mark:
        return (float("nan"), mark)
    w = (a - lo[0]) / (hi[0] - lo[0])
    step = hi[1] - lo[1]
    if angular:
        step = (step + 180.0) % 360.0 - 180.0
    return lo[1] + w * step, ""


def _default_tolerances(golden_path: Path) -> Path:
    local = golden_path.resolve().parent / "tolerances.toml"
    return local if local.is_file() else REPO_TOLERANCES


def is_engine_print(path) -> bool:
    """True when the print at ``path`` is an engine's print (it lists its deck before the
    banner), False for a transcription of the report (a golden print starts at the banner)."""
    from .printout.layout import BANNER_LINE

    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            for line in handle:
                text = line.strip()
                if text == BANNER_LINE:
                    return False
                if text == "Listing of input data records":
                    return True
    except OSError:
        return False
    return False


def report_names(first, second) -> tuple[str, str]:
    """The names of two compared prints in a report: ``("run", "golden")`` when the second
    is a golden print (a transcription of the report: :func:`is_engine_print` is False),
    else neutral ones: the file stems, or ``a`` and ``b`` when the stems are the same."""
    if not is_engine_print(second):
        return "run", "golden"
    a, b = Path(str(first)).stem, Path(str(second)).stem
    return (a, b) if a and b and a != b else ("a", "b")


def diff_prints(run_path, golden_path, tolerances_path=None) -> DiffReport:
    """Compare print file ``run_path`` with ``golden_path`` within tolerances.

    The tolerance file defaults to ``tolerances.toml`` next to the golden file, else the
    repository's ``golden/tolerances.toml``.  Raises PrintFormatError for an unreadable or
    malformed print or tolerance file (an empty one included), an input that is not a
    regular file (a FIFO would wait for a writer), or prints of different bearing types.
    """
    for path, what in ((golden_path, "golden print"), (run_path, "run's print")):
        p = Path(path)
        if p.exists() and not p.is_file():
            raise PrintFormatError(f"{p}: the {what} is not a regular file")
    golden = read_print(golden_path)
    run = read_print(run_path)
    return diff_runs(run, golden, tolerances_path)


def diff_command(run, golden, tolerances=None, fmt: str = "text", brief: bool = False) -> int:
    """CLI body of ``pyadore diff``: print the report (``brief``: one line per column with
    values outside tolerance), return 0 (within), 1 (outside) or 2 (unreadable).

    Never raises for bad input: the message goes to stderr as one paragraph.
    """
    try:
        report = diff_prints(run, golden, tolerances)
        text = report.render(fmt, brief=brief)
    except AdoreInputError as exc:
        print(f"pyadore: error: {exc}", file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"pyadore: error: {exc}", file=sys.stderr)
        return 2
    print(text)
    return report.exit_code
