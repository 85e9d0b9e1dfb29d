"""The Python package's module graph: no import cycle among its modules, nor among the folders
of its top level; no module of the package importing the package's front door (``toonmesh``,
its ``__init__``), which imports them; and a top level of at most ``MOST_AT_THE_TOP`` modules.

The graph is read from the source (ast): every import, at module level, inside a function or
under ``if TYPE_CHECKING:`` (an import only the type checker runs is still a circle to read and
to check). ``from toonmesh import X`` is an arrow to the submodule ``toonmesh.X`` when X is one,
and to the front door otherwise.
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


def _imports(nodes: Iterable[ast.AST]) -> Iterator[Union[ast.Import, ast.ImportFrom]]:
    """Every import statement in ``nodes`` and below, ``if TYPE_CHECKING:`` bodies included."""
    for node in nodes:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
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


def top_level_of(module: str) -> str:
    """The entry of the package's top level that ``module`` is or lies in (``toonmesh.files``
    for ``toonmesh.files._load``); the front door is its own."""
    return ".".join(module.split(".")[:2])


def folder_graph(graph: Dict[str, Set[str]]) -> Dict[str, Set[str]]:
    """The module graph seen from the top level: an arrow between two of its entries where a
    module of one imports a module of the other (arrows inside an entry left out)."""
    out: Dict[str, Set[str]] = {}
    for name, targets in graph.items():
        here = top_level_of(name)
        out.setdefault(here, set()).update(t for t in map(top_level_of, targets) if t != here)
    return out


def top_level_modules() -> List[str]:
    """The modules at the package's top level: each .py file (``__init__`` and ``__main__``
    included), each folder that is a package, and the compiled core."""
    found = {p.stem for p in PACKAGE.glob("*.py")}
    found |= {p.name for p in PACKAGE.iterdir() if (p / "__init__.py").is_file()}
    found |= {p.name.split(".")[0] for p in PACKAGE.iterdir() if p.suffix in (".so", ".pyd", ".pyi")}
    return sorted(found)


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


RENDER, SCENE = f"{NAME}.rendering._render", f"{NAME}.scene._scene"


def test_the_graph_is_read():
    graph = import_graph()
    assert {RENDER, f"{NAME}.files._load", SCENE, f"{NAME}.viewer", f"{NAME}.batch"} <= set(graph)
    assert f"{NAME}._core" in graph[SCENE]  # an arrow found, so the others would be too


def test_no_import_cycles():
    cycle = find_cycle(import_graph())
    assert cycle is None, "import cycle: " + " -> ".join(cycle or [])


def test_a_cycle_under_type_checking_is_found(tmp_path):
    """The check sees a circle that only the type checker runs (as the viewer's controls once
    imported the viewer, which imports them)."""
    module = tmp_path / "m.py"
    module.write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from toonmesh.b import B\n")
    known = {f"{NAME}.m", f"{NAME}.b"}
    graph = {f"{NAME}.m": imported_modules(f"{NAME}.m", module, known), f"{NAME}.b": {f"{NAME}.m"}}
    assert find_cycle(graph) == [f"{NAME}.b", f"{NAME}.m", f"{NAME}.b"]


def test_no_cycles_between_the_folders_of_the_top_level():
    """Each folder is a layer: files sit on the scene, rendering on files, the viewer and the
    line drawings on rendering; none reaches back up into one that uses it."""
    cycle = find_cycle(folder_graph(import_graph()))
    assert cycle is None, "cycle between the top level's folders: " + " -> ".join(cycle or [])


#: The package's top level in folders by concept: this many modules at most (folders counted).
MOST_AT_THE_TOP = 20


def test_the_top_level_stays_small():
    top = top_level_modules()
    assert {"__init__", "_core", "smooth", "edges", "viewer", "files", "rendering"} <= set(top), top
    assert len(top) <= MOST_AT_THE_TOP, f"{len(top)} modules at the top level (at most {MOST_AT_THE_TOP}): {top}"


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
    assert SCENE in graph[f"{NAME}.files._load"] and SCENE in graph[RENDER]
    assert not graph[SCENE] & {f"{NAME}.files._load", RENDER, NAME}, graph[SCENE]
