"""Test helpers: assert that a print file matches a golden file within the tolerance file."""

from __future__ import annotations

from .diff import diff_prints


def assert_matches_golden(run_path, golden_path, tolerances_path=None, sections=None, max_listed: int = 25) -> None:
    """Raise AssertionError listing the offenders unless ``run_path`` matches ``golden_path``.

    ``tolerances_path`` defaults as in :func:`pyadore.diff.diff_prints`.  ``sections``
    optionally restricts the check to some tables (names such as ``"re_contact"``,
    ``"echo"``, ``"header"``, ``"termination"``, ``"statistics"``); values of other tables
    are ignored (without ``sections``, an incomplete run print fails).  Unknown golden
    values are never compared; values the run prints as
    ``NaN`` (not computed by the engine) fail.  Raises AssertionError also when nothing at
    all was compared (a vacuous match is a failure).
    """
    report = diff_prints(run_path, golden_path, tolerances_path)
    if report.run_incomplete and sections is None:
        raise AssertionError(f"{run_path} is an incomplete print: {report.run_incomplete}")
    comps = report.comparisons
    if sections is not None:
        wanted = set(sections)
        comps = [c for c in comps if c.table in wanted or c.table.split()[-1] in wanted]
    compared = [c for c in comps if c.status in ("within", "outside", "missing", "not_computed")]
    bad = [c for c in compared if c.status != "within"]
    if not compared:
        raise AssertionError(f"{run_path} vs {golden_path}: no value compared"
                             + (f" in sections {sorted(sections)}" if sections else ""))
    if bad:
        bad.sort(key=lambda c: -(c.rel_error if c.rel_error == c.rel_error else float("inf")))
        nc = sum(1 for c in bad if c.status == "not_computed")
        lines = [f"{run_path} does not match {golden_path}: {len(bad)} of {len(compared)} compared values "
                 f"outside tolerance or not computed by the engine ({nc} not computed; {report.tolerances_path})"]
        for c in bad[:max_listed]:
            err = ("missing" if c.status == "missing" else "not computed by the engine"
                   if c.status == "not_computed" else f"rel err {c.rel_error:.3%}")
            lines.append(f"  {c.name}: golden {c.golden!r} run {c.run!r} ({err}, {c.tolerance})")
        if len(bad) > max_listed:
            lines.append(f"  ... and {len(bad) - max_listed} more")
        raise AssertionError("\n".join(lines))
