"""Comparing the outputs of two builds of the engine (`make test`: one release build; `make
debug`: a debug `adore` (-O0, run-time checks) beside the release f2py extension).

The release build's vectorised loops call glibc's libmvec exp/log/sin/cos, the -O0 build the
scalar functions: the two differ in round-off (docs/performance.md, "Cost of a derivative call"),
so their prints can differ by one unit of a printed digit where a value sits on a rounding
boundary.
"""

from __future__ import annotations

import re

def checks_build(build_dir) -> bool:
    """Whether the meson build of `adore` has the debug checks (`make debug`: -O0, FP traps)."""
    import json

    options = json.loads((build_dir / "meson-info" / "intro-buildoptions.json").read_text())
    return any(o["name"] == "checks" and o["value"] is True for o in options)


def same_to_the_printed_digit(a: str, b: str, rel: float = 0.0) -> bool:
    """Two prints alike line by line, a number differing at most by one unit of its last
    printed digit (a value on a rounding boundary of two builds' round-off) or, if `rel` is
    given, by at most `rel` of its value."""
    la, lb = a.splitlines(), b.splitlines()
    if len(la) != len(lb):
        return False
    for x, y in zip(la, lb):
        if x == y:
            continue
        tx, ty = x.split(), y.split()
        if len(tx) != len(ty):
            return False
        for u, v in zip(tx, ty):
            if u == v:
                continue
            mu, mv = re.fullmatch(r"(-?\d\.(\d+))E([+-]\d+)", u), re.fullmatch(r"(-?\d\.(\d+))E([+-]\d+)", v)
            if not (mu and mv and mu.group(3) == mv.group(3)):
                return False
            unit = 10.0 ** (int(mu.group(3)) - len(mu.group(2)))
            if abs(float(u) - float(v)) > max(1.001 * unit, rel * abs(float(v))):
                return False
    return True
