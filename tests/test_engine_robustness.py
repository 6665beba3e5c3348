"""The standalone engine on decks with odd but readable values: it runs, or it refuses with a
message, exit status 1 or 2 and no print file - never a crash, a hang or a half-written
file.  Under `make debug` the executable traps floating-point exceptions, so a division by
zero anywhere in the physics fails this test (a degenerate ring in the mounting once did).

The decks are the two appendix decks with one to three real fields scaled by factors from
0 to 100 or negated, drawn with a fixed seed (the same decks on every run).
"""

from __future__ import annotations

import random
import re
from pathlib import Path

import pytest

import pyadore

ROOT = Path(__file__).resolve().parents[1]
REAL = re.compile(r"-?\d+\.\d+E[+-]\d+")
FACTORS = (0.0, 0.01, 0.1, 0.3, 3.0, 10.0, 100.0, -1.0)


def _deck_with(tmp_path: Path, deck_name: str, record: str, col: int, value: str, name: str):
    """Appendix deck `deck_name` with the field at 0-based column `col` of record `record`
    (label as written, e.g. "Rec 2.7") replaced by `value`; returns (path, 1-based line)."""
    src = (ROOT / "decks" / deck_name).read_text().splitlines()
    row = next(i for i, line in enumerate(src) if line.split()[:2] == record.split())
    src[row] = src[row][:col] + value + src[row][col + len(value):]
    path = tmp_path / name
    path.write_text("\n".join(src) + "\n")
    return path, row + 1


def _mutations(deck: Path, n: int, seed: int):
    rng = random.Random(seed)
    lines = deck.read_text().splitlines()
    for _ in range(n):
        out = list(lines)
        changes = []
        for _ in range(rng.choice((1, 2, 3))):
            i = rng.randrange(len(out))
            hits = list(REAL.finditer(out[i], 12))
            if not hits:
                continue
            m = rng.choice(hits)
            new = f"{float(m.group()) * rng.choice(FACTORS):.4E}"
            width = m.end() - m.start()
            if len(new) > width:       # would run into the next field: keep the field
                continue
            out[i] = out[i][:m.start()] + new.rjust(width) + out[i][m.end():]
            changes.append(f"line {i + 1}: {m.group()} -> {new}")
        yield "\n".join(out) + "\n", changes


@pytest.mark.parametrize("deck_name, n, seed", [("appendix_d_roller.inp", 60, 5), ("appendix_c_ball.inp", 6, 7)])
def test_odd_values_never_crash_the_engine(tmp_path, run_exe, deck_name, n, seed):
    outcomes = {0: 0, 1: 0, 2: 0}
    for k, (text, changes) in enumerate(_mutations(ROOT / "decks" / deck_name, n, seed)):
        deck = tmp_path / f"m{k}.inp"
        out = tmp_path / f"m{k}.prt"
        deck.write_text(text)
        proc = run_exe(deck, out, "--steps", "0")
        where = f"{deck_name} with {changes}: exit {proc.returncode}\n{proc.stderr[-2000:]}"
        assert proc.returncode in outcomes, where
        assert "runtime error" not in proc.stderr.lower() and "backtrace" not in proc.stderr.lower(), where
        assert not out.with_name(out.name + ".part").exists(), where
        if proc.returncode == 0:
            assert out.exists(), where
        else:
            assert proc.stderr.startswith("adore: error: "), where
            assert not out.exists(), where
        outcomes[proc.returncode] += 1
    print(deck_name, outcomes)
    assert outcomes[0] > 0          # the sample is not all refused at reading


@pytest.mark.parametrize("record, col, value, name, where", [
    # a solid shaft whose bore equals its OD passed the reader, and the mounting's Lame formula
    # divided by zero (SIGFPE in the checked build, a fit pressure of 0 without traps)
    ("Rec 4", 34, " 3.0000E-02", "wall.inp",
     "36  Rec 4  field shaft_inner_diameter = 0.03: expected < shaft_outer_diameter = 0.03 "
     "(a hollow shaft's bore is inside its OD)"),
    # no applied force: the echo's load scale (the largest applied load) is undefined, and
    # ADORE's rule for an unloaded bearing is not known
    ("Rec 9.1.1", 34, " 0.0000E+00", "unloaded.inp",
     "14  Rec 9.1.1  field applied_force_x = 0: expected a non-zero applied force "
     "(applied_force_x, applied_force_y and applied_force_z are all 0)"),
])
def test_values_the_physics_cannot_use_are_refused_at_the_field(tmp_path, run_exe, record, col, value, name, where):
    """The roller deck with one field changed: an input error at that field (file:line:col,
    record, field, value, what was expected), exit 1, no print file."""
    deck, line = _deck_with(tmp_path, "appendix_d_roller.inp", record, col, value, name)
    proc = run_exe(deck, tmp_path / "x.prt", "--steps", "0")
    assert proc.returncode == 1
    assert f"{deck}:{line}:{where}" in proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]
