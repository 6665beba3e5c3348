"""The EHD film's limiting shear stress (run option limiting_shear; docs/tribology.md,
"Limiting shear stress (run option limiting_shear)"; issue #28).

Traction model 3's thermal Newtonian film has no limiting shear stress; the option caps its
local shear stress smoothly at tau_L = Lambda p (tau_L tanh(tau_N / tau_L)).  Off (0, the
default) the runs are the report's physics byte for byte (checked against main's build by
cmp when the option was added: Appendix C's 2 500-step print, plot data and element file,
and step 0 of every example deck); here: 0 given explicitly is the default, the cap lowers
the step-0 loss, the option is refused outside [0, 1) with its name, and a dynamic run with
the cap closes its power balance (the cap changes the traction, not the power identity:
the heat of a film point stays tau |u|).  The engine-level checks (the law, strips at most
Lambda times their load, the saturated film, fast against reference) are
fortran/tests/test_limiting_shear.f90.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import pyadore
from pyadore.errors import AdoreInputError

ROOT = Path(__file__).resolve().parents[1]
BALL = ROOT / "decks" / "appendix_c_ball.inp"


def _total_loss(text: str) -> float:
    """Step 0's printed Total Power Loss (W)."""
    return float(re.search(r"Total Power Loss\s+\(W\)\s+(\S+)", text).group(1))


def test_option_off_is_the_default_and_on_lowers_the_loss(tmp_path):
    """limiting_shear=0 prints what the default prints (step 0, byte for byte); 0.08 lowers
    Appendix C's step-0 loss (its contacts at 1.0-1.6 GPa)."""
    default = pyadore.run(BALL, steps=0, out=tmp_path / "default.prt")
    off = pyadore.run(BALL, steps=0, out=tmp_path / "off.prt", limiting_shear=0)
    on = pyadore.run(BALL, steps=0, out=tmp_path / "on.prt", limiting_shear=0.08)
    assert off.text == default.text
    assert _total_loss(on.text) < _total_loss(default.text)


@pytest.mark.parametrize("value", [-0.05, 1.0, 2.0])
def test_refused_outside_zero_to_one(tmp_path, value):
    """A negative Lambda, or one of 1 and above (a limiting traction coefficient no film
    has), is an input error naming the option."""
    with pytest.raises(AdoreInputError, match="limiting_shear"):
        pyadore.run(BALL, steps=0, out=tmp_path / "bad.prt", limiting_shear=value)


def _tight(tmp_path: Path) -> Path:
    """Appendix C at error limit 1e-8 (Rec 2.1; its minimum step 1e-6), as tests/test_balances.py."""
    text = BALL.read_text().splitlines()
    for i, line in enumerate(text):
        if line.startswith("Rec 2.1 "):
            v = line.split()[2:]
            v[1], v[4] = "1.0000E-06", "1.0000E-08"
            text[i] = "Rec 2.1     " + "".join(f" {x:>10s}" for x in v)
    path = tmp_path / "tight.inp"
    path.write_text("\n".join(text) + "\n")
    return path


def test_dynamic_run_with_the_cap_closes_its_balance(tmp_path):
    """Appendix C at error limit 1e-8, 0.5 revolutions, Lambda = 0.08: drive power =
    dissipation + rate of mechanical energy + whirl-frame line within 1e-3 (the engine's
    Result.balance["closure"]), as without the cap (tests/test_balances.py)."""
    result = pyadore.run(_tight(tmp_path), revolutions=0.5, out=tmp_path / "cap.prt", limiting_shear=0.08)
    bal = result.balance
    assert bal["dissipation_W"] > 0.0
    assert abs(bal["closure"]) <= 1e-3, bal
