"""The Appendix C step-2500 values that moved with issue #30 (`python bench/step2500_moved.py [OUT]`).

Runs the Appendix C deck twice with the executable (ADORE_EXE, else build/native/adore): the explicit
DP5 in the orbit frame (`--integrator dp5`, issue #30 item 1 alone) and the deck's own method (the
stiff-aware ARK4(3)6L[2]SA, item 2, with every later change), compares both prints with the report's
(golden/appendix_c_ball.prt, `pyadore.diff.diff_prints`), and writes the list of step-2500 values that
differ between the two runs, each with the report's value, both runs' and its golden status in both
(default OUT: docs/dynamics_step2500_moved.txt).  About 10 s.
"""

from __future__ import annotations

import collections
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from pyadore.diff import diff_prints

ROOT = Path(__file__).resolve().parent.parent
DECK = ROOT / "decks" / "appendix_c_ball.inp"
GOLDEN = ROOT / "golden" / "appendix_c_ball.prt"


def _run(exe: str, out: Path, *args: str) -> None:
    proc = subprocess.run([exe, str(DECK), str(out), *args], capture_output=True, text=True)
    if proc.returncode != 0:
        raise SystemExit(f"step2500_moved: {exe} {' '.join(args)} failed:\n{proc.stderr}")


def _step2500(report) -> dict:
    return {c.name: c for c in report.comparisons if c.name.startswith("step 2500 ")}


def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float) and a != a and b != b:
        return True
    return a == b


def main() -> int:
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "dynamics_step2500_moved.txt"
    exe = os.environ.get("ADORE_EXE", str(ROOT / "build" / "native" / "adore"))
    with tempfile.TemporaryDirectory() as tmp:
        dp5_prt, ark_prt = Path(tmp) / "dp5.prt", Path(tmp) / "ark4.prt"
        _run(exe, dp5_prt, "--integrator", "dp5")
        _run(exe, ark_prt)
        dp5, ark = _step2500(diff_prints(dp5_prt, GOLDEN)), _step2500(diff_prints(ark_prt, GOLDEN))
    tau_dp5, tau_ark = dp5["step 2500 header tau"].run, ark["step 2500 header tau"].run
    moved = [name for name in ark if name in dp5 and not _same(dp5[name].run, ark[name].run)]
    by_column = collections.Counter((ark[n].table, ark[n].column) for n in moved)
    lines = [
        "# Step-2500 values of the Appendix C run that moved with issue #30 (bench/step2500_moved.py: both prints",
        f"# compared with golden/appendix_c_ball.prt by pyadore.diff.diff_prints): DP5 in the orbit frame (--integrator",
        f"# dp5, tau {tau_dp5}) -> the deck's method ARK4(3)6L[2]SA (tau {tau_ark}); [status] is each value's golden status.",
        f"step-2500 values compared: {len(ark)} moved: {len(moved)}",
        f"moved by column: {dict(by_column.most_common())}",
        "status old->new counts "
        f"{dict(collections.Counter(c.status for c in dp5.values()))} "
        f"{dict(collections.Counter(c.status for c in ark.values()))}",
    ]
    for name in moved:
        d, a = dp5[name], ark[name]
        lines.append(f"{name}: golden {a.golden} DP5(tau {tau_dp5}) {d.run} [{d.status}] -> "
                     f"ARK4(tau {tau_ark}) {a.run} [{a.status}]")
    out.write_text("\n".join(lines) + "\n")
    print(f"{out}: {len(moved)} of {len(ark)} step-2500 values moved (tau {tau_dp5} -> {tau_ark})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
