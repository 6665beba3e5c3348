"""The race traction of the dynamics (issue #20; docs/dynamics.md, "Two-dimensional race
traction"): two-dimensional by default; the one-dimensional traction is a developer option,
`adore --traction-1d` and `pyadore.run(..., traction_2d=False)` select it through run_deck,
the print's listing says so, the f2py and standalone prints are identical, and the traction
really changes the run.
The fast two-dimensional traction's accuracy is tested in fortran/tests/test_forces.f90.
"""

from __future__ import annotations

import subprocess

import pytest

import pyadore
from builds import checks_build, same_to_the_printed_digit
from pyadore.errors import AdoreInputError

N = 10
LINE = "ONE-DIMENSIONAL RACE TRACTION"


@pytest.fixture(scope="module")
def prints(tmp_path_factory, ball_deck, adore_exe):
    out = tmp_path_factory.mktemp("traction2d")
    # "one": the default run (two-dimensional traction); "two": the developer option (1-D)
    one = pyadore.run(ball_deck, steps=N, out=out / "one.prt")
    two = pyadore.run(ball_deck, steps=N, out=out / "two.prt", traction_2d=False)
    proc = subprocess.run([str(adore_exe), str(ball_deck), str(out / "exe.prt"), "--steps", str(N), "--traction-1d"],
                          capture_output=True, text=True, timeout=600)
    return one, two, proc, out / "exe.prt"


def test_the_option_is_listed_and_f2py_equals_the_executable(prints, build_dir):
    one, two, proc, exe_print = prints
    assert proc.returncode == 0, proc.stderr
    if checks_build(build_dir):
        # `make debug`: a debug `adore` (-O0, scalar libm) beside the release extension
        # (libmvec in its vectorised loops; tests/builds.py): alike to the printed digit, but
        # section 2's pocket forces of a few uN, which the centred cage's pocket impacts make
        # sensitive to round-off (measured 4.049E-06 against 4.068E-06 N, 0.47 %): within 1 %
        assert same_to_the_printed_digit(exe_print.read_text(), two.print_path.read_text(), rel=1e-2)
    else:
        assert exe_print.read_bytes() == two.print_path.read_bytes()
    listing = two.text.split("Listing of input data records", 1)[0]
    assert LINE in listing and "DEVELOPER OPTION" in listing
    assert LINE not in one.text


def test_the_one_dimensional_traction_changes_the_time_steps_only(prints):
    """Step 0 (the quasi-static start, the print up to step N's heading) does not use the
    force assembly: identical but for the listing line; step N differs."""
    one, two, _, _ = prints
    head = "  step        tau"
    one_text = one.text
    two_text = "".join(ln for ln in two.text.splitlines(keepends=True) if LINE not in ln)
    split_one = one_text.index(head)
    split_two = two_text.index(head)
    assert one_text[:split_one] == two_text[:split_two]
    assert one_text[split_one:] != two_text[split_two:]
    assert "Normal termination" in two_text[split_two:]


def test_traction_2d_must_be_a_bool(ball_deck, tmp_path):
    with pytest.raises(AdoreInputError, match="traction_2d"):
        pyadore.run(ball_deck, steps=1, out=tmp_path / "x.prt", traction_2d="yes")
