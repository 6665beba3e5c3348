"""The engine keeps no state between calls, so Python threads can run decks at once.

Two ways state could hide in the Fortran code, both checked here for every engine source
listed in meson.build:

* SAVE'd variables written by the programmer: a ``save`` attribute, or a declaration with
  an initial value (which implies SAVE in Fortran) outside a derived-type definition.
* static storage the compiler creates by itself.  gfortran 12 (Debian's, the CI
  compiler) keeps the length of every deferred-length character *function result* in a
  ``static integer(kind=8) slen.N`` at the call site; two threads calling such a function
  overwrote each other's lengths and the deck reader then saw '4.5000E-02' as a blank
  field (CI failure of tests/test_foundation.py::test_runs_in_threads_are_identical).
  The compiler's own view (``-fdump-tree-original``) must hold no static variable
  without an initial value: initialised ones are the constant tables of array
  constructors and PARAMETER arrays, which are never written.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _engine_sources() -> list[Path]:
    """Engine and f2py-wrapper sources of meson.build, each after the modules it uses."""
    text = (ROOT / "meson.build").read_text()
    names = re.findall(r"'(fortran/[^']+\.f90(?:\.in)?)'", text)
    sources = [ROOT / n for n in names if "/tests/" not in n and "/app/" not in n]
    assert len(sources) > 40, "meson.build's source lists were not found"
    provides, uses = {}, {}
    for src in sources:
        code = src.read_text().lower()
        for name in re.findall(r"^\s*module\s+(\w+)\s*$", code, re.M):
            provides[name] = src
        uses[src] = set(re.findall(r"^\s*use\s*(?:,\s*\w+\s*::)?\s*(\w+)", code, re.M))
    ordered, done = [], set()

    def visit(src, path=()):
        if src in done:
            return
        assert src not in path, f"module cycle through {src.name}"
        for name in sorted(uses[src]):
            if name in provides and provides[name] != src:
                visit(provides[name], path + (src,))
        done.add(src)
        ordered.append(src)

    for src in sources:
        visit(src)
    return ordered


def _strip_comment(line: str) -> str:
    out, quote = [], None
    for ch in line:
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            break
        out.append(ch)
    return "".join(out)


def _saved_declarations(path: Path) -> list[str]:
    found, in_type = [], False
    for number, raw in enumerate(path.read_text().splitlines(), 1):
        code = _strip_comment(raw).strip().lower()
        if re.match(r"type\s*(,[^:]*)?::\s*\w+$|type\s+\w+$", code):
            in_type = True
        elif re.match(r"end\s*type", code):
            in_type = False
        elif not in_type and re.search(r"\bsave\b", code):
            found.append(f"{path.name}:{number}: {raw.strip()}")
        elif not in_type and "::" in code and "parameter" not in code.split("::")[0]:
            names = code.split("::", 1)[1]
            while re.search(r"\([^()]*\)", names):
                names = re.sub(r"\([^()]*\)", "", names)
            names = re.sub(r"\[[^\]]*\]", "", names)
            if re.search(r"(?<![=<>/])=(?![=>])", names):
                found.append(f"{path.name}:{number}: {raw.strip()}")
    return found


def test_no_saved_variables_in_the_engine_sources():
    found = [hit for src in _engine_sources() if src.suffix == ".f90" for hit in _saved_declarations(src)]
    assert found == [], "SAVE'd (shared) variables in the engine:\n" + "\n".join(found)


def test_the_saved_variable_check_finds_what_it_should(tmp_path):
    src = tmp_path / "m.f90"
    src.write_text("module m\n type :: t\n  integer :: n = 0\n end type t\n"
                   " integer, parameter :: k = 3\ncontains\n subroutine s()\n"
                   "  integer :: calls = 0  ! implied SAVE\n  real, save :: x\n"
                   "  if (k == 3) calls = calls + 1\n end subroutine s\nend module m\n")
    assert [h.split(":")[1] for h in _saved_declarations(src)] == ["8", "9"]


def _writable_static(decl: str) -> bool:
    """A static variable without an initial value (not a prototype, not const)."""
    return (decl.startswith("static ") and not decl.startswith("static const")
            and decl.endswith(";") and " = " not in decl and not re.search(r"\w \(", decl))


def test_the_static_check_tells_variables_from_constants_and_prototypes():
    assert _writable_static("static integer(kind=8) slen.59;")
    assert _writable_static("static real(kind=8) total[3];")
    assert not _writable_static("static integer(kind=4) C.5328 = 0;")
    assert not _writable_static('static character(kind=1) kind_name[3][1:4] = {"int ", "real", "text"};')
    assert not _writable_static("static real(kind=8) root (real(kind=8) & restrict, real(kind=8) & restrict);")
    assert not _writable_static("static const integer(kind=4) n = 3;")


@pytest.mark.skipif(shutil.which("gfortran") is None, reason="needs gfortran (make setup installs it)")
def test_compiler_keeps_no_writable_static_storage(tmp_path):
    # the build must put every local on the stack too; this check compiles with the same flag
    assert "'-frecursive'" in (ROOT / "meson.build").read_text()
    writable, compiled_code = [], 0
    for src in _engine_sources():
        if src.name.endswith(".in"):
            text = src.read_text().replace("@VERSION@", "0")
            src = tmp_path / src.name.removesuffix(".in")
            src.write_text(text)
        proc = subprocess.run(
            ["gfortran", "-c", "-O0", "-frecursive", "-fdump-tree-original", f"-J{tmp_path}",
             f"-I{tmp_path}", str(src), "-o", str(tmp_path / (src.stem + ".o"))],
            cwd=tmp_path, capture_output=True, text=True)
        assert proc.returncode == 0, proc.stderr
        for dump in tmp_path.glob(f"{src.name}.*.original"):  # none for a module without procedures
            for line in dump.read_text().splitlines():
                if _writable_static(line.strip()):
                    writable.append(f"{src.name}: {line.strip()}")
            dump.unlink()
            compiled_code += 1
    assert compiled_code > 30, "gfortran wrote no tree dumps: the check would see nothing"
    assert writable == [], ("static variables the compiler writes at run time (shared by threads); "
                            "a deferred-length character function result is the usual cause "
                            "(see fortran/core/strings.f90):\n" + "\n".join(writable))
