"""The Python package's module graph: no import cycle among its modules, and no module of the
package importing the package's front door (``toonmesh``, its ``__init__``), which imports them.

The graph is read from the source (ast): every import, at module level or inside a function,
except those under ``if TYPE_CHECKING:`` (they never run). ``from toonmesh import X`` is an
arrow to the submodule ``toonmesh.X`` when X is one, and to the front door otherwise.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Dict, Iterable, Iterator, List, Optional, Set, Union

PACKAGE = Path(__file__).resolve().parent.parent / "python" / "toonmesh"
NAME = "toonmesh"

#: Modules that may import the front door: the package itself and ``python -m toonmesh``.
FRONT_DOOR_ALLOWED = {NAME, f"{NAME}.__main__"}
#: The benchmarks time the public API as a user calls it (``import toonmesh as tm``); nothing in
#: the package imports them, so they sit above the front door rather than below it.
ABOVE_THE_FRONT_DOOR = f"{NAME}.bench"


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def package_modules() -> Dict[str, Path]:
    """Every module of the package by name (``_core``, compiled, by its stubs)."""
    found = {module_name(p): p for p in PACKAGE.rglob("*.py")}
    found[f"{NAME}._core"] = PACKAGE / "_core.pyi"
    return found


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _imports(nodes: Iterable[ast.AST]) -> Iterator[Union[ast.Import, ast.ImportFrom]]:
    """Every import statement in ``nodes`` and below, skipping ``if TYPE_CHECKING:`` bodies."""
    for node in nodes:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
        elif isinstance(node, ast.If) and _is_type_checking(node.test):
            yield from _imports(node.orelse)  # only the else branch runs
        else:
            yield from _imports(ast.iter_child_nodes(node))


def _absolute(module: str, node: ast.ImportFrom, is_package: bool) -> Optional[str]:
    if node.level == 0:
        return node.module
    base = module.split(".") if is_package else module.split(".")[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def imported_modules(module: str, path: Path, known: Set[str]) -> Set[str]:
    """The package's modules that ``module`` imports."""
    if path.suffix == ".pyi":
        return set()
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    out: Set[str] = set()
    for node in _imports([tree]):
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        else:
            base = _absolute(module, node, path.name == "__init__.py")
            if base is None:
                continue
            # a name that is a submodule is an arrow to it; any other name is the base's attribute
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in known else base for a in node.names]
        for target in targets:
            if target == NAME or target.startswith(NAME + "."):
                out.add(target)
    return out


def import_graph() -> Dict[str, Set[str]]:
    modules = package_modules()
    known = set(modules)
    return {name: imported_modules(name, path, known) for name, path in modules.items()}


def find_cycle(graph: Dict[str, Set[str]]) -> Optional[List[str]]:
    """One import cycle as a path that ends where it starts, or None."""
    state: Dict[str, int] = {}  # 1: on the current path, 2: done
    path: List[str] = []

    def visit(node: str) -> Optional[List[str]]:
        state[node] = 1
        path.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return path[path.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        path.pop()
        state[node] = 2
        return None

    for start in sorted(graph):
        if start not in state:
            found = visit(start)
            if found:
                return found
    return None


def test_the_graph_is_read():
    graph = import_graph()
    assert {f"{NAME}._render", f"{NAME}.files._load", f"{NAME}._scene", f"{NAME}.viewer", f"{NAME}.batch"} <= set(graph)
    assert f"{NAME}._core" in graph[f"{NAME}._scene"]  # an arrow found, so the others would be too


def test_no_import_cycles():
    cycle = find_cycle(import_graph())
    assert cycle is None, "import cycle: " + " -> ".join(cycle or [])


def test_no_module_imports_the_front_door():
    graph = import_graph()
    offenders = sorted(
        name for name, targets in graph.items()
        if NAME in targets
        and name not in FRONT_DOOR_ALLOWED
        and not (name == ABOVE_THE_FRONT_DOOR or name.startswith(ABOVE_THE_FRONT_DOOR + "."))
    )
    assert offenders == [], f"these modules import {NAME} itself (import the submodule they need instead): {offenders}"


def test_the_scene_description_sits_below_files_and_rendering():
    graph = import_graph()
    scene = f"{NAME}._scene"
    assert scene in graph[f"{NAME}.files._load"] and scene in graph[f"{NAME}._render"]
    assert not graph[scene] & {f"{NAME}.files._load", f"{NAME}._render", NAME}, graph[scene]
