"""Runs the engine's own unit tests (fortran/tests) through meson, and source-level rules."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from builds import checks_build

ROOT = Path(__file__).resolve().parent.parent
# every engine folder except the unit-test programs and the standalone program
LIBRARY_DIRS = sorted(p.name for p in (ROOT / "fortran").iterdir() if p.is_dir() and p.name not in ("tests", "app"))


def test_engine_unit_tests_pass(build_dir):
    meson = Path(sys.executable).parent / "meson"
    # meson.build's per-test timeouts (120 s) are for the release build; `make debug`'s -O0
    # build with run-time checks runs several times slower (test_dynamics: 120 s on a loaded
    # machine), so its limits are stretched three-fold
    slow = checks_build(build_dir)
    proc = subprocess.run([str(meson), "test", "-C", str(build_dir), "--print-errorlogs"]
                          + (["--timeout-multiplier", "3"] if slow else []),
                          capture_output=True, text=True, timeout=1800 if slow else 600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert re.search(r"^Ok:\s+[1-9]", proc.stdout, re.M), proc.stdout
    assert re.search(r"deck tokenizer and reader unit tests\s+OK", proc.stdout), proc.stdout


def _library_sources():
    for sub in LIBRARY_DIRS:
        yield from (ROOT / "fortran" / sub).rglob("*.f90")


def test_library_code_never_stops_the_process():
    offenders = []
    for path in _library_sources():
        for n, line in enumerate(path.read_text().splitlines(), 1):
            code = line.split("!", 1)[0]
            if re.search(r"(^|\)|;)\s*(error\s+)?stop\b", code.strip(), re.I) or re.search(r"\bcall\s+exit\b", code, re.I):
                offenders.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert offenders == []


def test_library_code_has_no_saved_state():
    """No SAVE and no module variables: only parameters (constants) at module level."""
    offenders = []
    for path in _library_sources():
        in_spec = False  # inside a module's specification part
        in_type = 0
        in_interface = 0
        for n, line in enumerate(path.read_text().splitlines(), 1):
            code = line.split("!", 1)[0].strip().lower()
            if not code:
                continue
            if re.match(r"module\s+(?!procedure\b)\w+\s*$", code):
                in_spec = True
            elif re.match(r"contains\b", code) or re.match(r"end\s*module\b", code):
                in_spec = False
            if re.search(r"\bsave\b", code):
                offenders.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
            if re.match(r"(abstract\s+)?interface\b", code):
                in_interface += 1
            elif re.match(r"end\s*interface\b", code):
                in_interface -= 1
            if re.match(r"type\s*(,|::|\s+\w+\s*$)", code) and not code.startswith("type("):
                in_type += 1
            elif re.match(r"end\s*type\b", code):
                in_type -= 1
            elif (in_spec and in_type == 0 and in_interface == 0 and "::" in code and "parameter" not in code
                  and not re.match(r"(use|public|private|procedure|import|generic|interface)\b", code)
                  and not re.search(r"intent\s*\(", code)):
                offenders.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert offenders == []


def test_engine_folders_depend_one_way():
    """The library folders' `use` graph has no cycle (docs/architecture.md draws its order)."""
    mod_dir = {}
    for path in _library_sources():
        for name in re.findall(r"^\s*module\s+(\w+)\s*$", path.read_text(), re.M | re.I):
            mod_dir[name.lower()] = path.parent.name
    edges = {}
    for path in _library_sources():
        for name in re.findall(r"^\s*use\s+(\w+)", path.read_text(), re.M | re.I):
            target = mod_dir.get(name.lower())
            if target and target != path.parent.name:
                edges.setdefault(path.parent.name, set()).add(target)

    def reaches(start, goal, seen=()):
        return any(t == goal or (t not in seen and reaches(t, goal, seen + (t,))) for t in edges.get(start, ()))

    assert [d for d in sorted(edges) if reaches(d, d)] == []


# folders allowed to use fortran/thermal/ (docs/architecture.md: the thermal model sits above geometry)
THERMAL_USERS = {"start", "dynamics", "bearings", "driver", "output", "api"}


def test_thermal_folder_is_used_only_above_it():
    """fortran/thermal/ may use core, tribology, cage, model, geometry; only start/, dynamics/,
    bearings/, driver/, output/ (and the f2py boundary) may use it."""
    allowed_below = {"core", "tribology", "cage", "model", "geometry", "thermal"}
    mod_dir = {}
    for path in _library_sources():
        for name in re.findall(r"^\s*module\s+(\w+)\s*$", path.read_text(), re.M | re.I):
            mod_dir[name.lower()] = path.parent.name
    users, uses = [], []
    for path in _library_sources():
        folder = path.parent.name
        for name in re.findall(r"^\s*use\s+(\w+)", path.read_text(), re.M | re.I):
            target = mod_dir.get(name.lower())
            if target == "thermal" and folder not in THERMAL_USERS | {"thermal"}:
                users.append(f"{path.relative_to(ROOT)} uses {name}")
            if folder == "thermal" and target and target not in allowed_below:
                uses.append(f"{path.relative_to(ROOT)} uses {name} ({target})")
    assert users == [] and uses == []
