"""Import structure of the pyadore package: every module imports on its own in a fresh
interpreter, and the modules' imports form a DAG (no import circles; an import needed only
for annotations, under ``if TYPE_CHECKING:``, is not a run-time import and is not counted)."""

from __future__ import annotations

import ast
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "pyadore"


def _modules() -> dict[str, Path]:
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _is_type_checking(node: ast.If) -> bool:
    t = node.test
    return (isinstance(t, ast.Name) and t.id == "TYPE_CHECKING") or (
        isinstance(t, ast.Attribute) and t.attr == "TYPE_CHECKING")


def _imports(tree: ast.AST):
    """Import statements run at import or call time (module level and inside functions),
    without those under ``if TYPE_CHECKING:``."""
    stack = [tree]
    while stack:
        node = stack.pop()
        if isinstance(node, ast.If) and _is_type_checking(node):
            stack.extend(node.orelse)
            continue
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
        stack.extend(ast.iter_child_nodes(node))


def import_graph(prefix: str = "pyadore") -> dict[str, set[str]]:
    """Module -> the package modules it imports (its own ancestor packages left out: a
    package is always initialised before its modules)."""
    mods = _modules()
    graph: dict[str, set[str]] = {}
    for name, path in mods.items():
        if not name.startswith(prefix):
            continue
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        deps: set[str] = set()
        for node in _imports(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                deps.update(a.name for a in node.names if a.name in mods)
                continue
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            for a in node.names:
                sub = f"{target}.{a.name}"
                if sub in mods:
                    deps.add(sub)
                elif target in mods:
                    deps.add(target)
        graph[name] = {d for d in deps if d != name and not name.startswith(d + ".")}
    return graph


def _cycle(graph: dict[str, set[str]]) -> list[str] | None:
    state: dict[str, int] = {}
    path: list[str] = []

    def visit(v: str) -> list[str] | None:
        state[v] = 1
        path.append(v)
        for w in sorted(graph.get(v, ())):
            if state.get(w) == 1:
                return path[path.index(w):] + [w]
            if w not in state and (found := visit(w)):
                return found
        state[v] = 2
        path.pop()
        return None

    for v in sorted(graph):
        if v not in state and (found := visit(v)):
            return found
    return None


def test_the_graph_walker_finds_a_cycle():
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b"}, "b": set(), "c": {"a", "b"}}) is None


def test_deck_imports_form_a_dag():
    graph = import_graph("pyadore.deck")
    assert {"pyadore.deck.model", "pyadore.deck.validate", "pyadore.deck.writer",
            "pyadore.deck.schema", "pyadore.deck.records"} <= set(graph)
    assert _cycle(graph) is None, " -> ".join(_cycle(graph))


def test_package_imports_form_a_dag():
    graph = import_graph("pyadore")
    assert _cycle(graph) is None, " -> ".join(_cycle(graph))


def test_every_module_imports_alone_in_a_fresh_interpreter():
    names = [n for n in _modules() if not n.endswith("__main__")]   # __main__ runs the CLI

    def load(name: str):
        proc = subprocess.run([sys.executable, "-c", f"import {name}"], capture_output=True, text=True,
                              timeout=120)
        return name, proc.returncode, proc.stderr[-1500:]

    with ThreadPoolExecutor(max_workers=2) as pool:
        failed = [r for r in pool.map(load, names) if r[1] != 0]
    assert len(names) > 30
    assert not failed, failed
