"""The module graph of the Rust core: which module uses which, its cycles, and the arrows that
point from a lower layer to a higher one.

    python scripts/layers.py            # prints the cycles and upward arrows; exit 1 if any

A module is a file (`src/render/passes/shade/mod.rs` is `render::passes::shade`). A module
uses another when its code (tests left out) names a path into it: `use crate::a::b`,
`super::x`, or a path written in the code. The layers are listed in `LAYERS`, lowest first: a
module may use modules of its own layer or below, never above.
"""

from __future__ import annotations

import fnmatch
import re
import sys
from pathlib import Path
from typing import Dict, List, Set, Tuple

SRC = Path(__file__).resolve().parent.parent / "src"


def surface_effects() -> List[str]:
    """The per-pixel effects, as `effects/surface.rs` registers them (`name: Settings`)."""
    text = (SRC / "render" / "effects" / "surface.rs").read_text()
    listed = text[text.index("registry! {") :]
    return re.findall(r"^\s+(\w+): [\w:]+,$", listed, re.M)


def frame_effects() -> List[str]:
    """The frame effects, as `effects/frame.rs` registers them (`&name::EFFECT` in `FRAME`)."""
    text = (SRC / "render" / "effects" / "frame.rs").read_text()
    return re.findall(r"&(\w+)::EFFECT", text[text.index("pub static FRAME") :].split(";")[0])


# Lowest first. A module belongs to the first pattern that matches its path.
LAYERS: List[List[str]] = [
    ["error", "real", "cancel", "parallel", "huge_pages", "names"],
    ["mesh", "mesh::*", "points", "points::*"],
    ["edges", "edges::*", "smooth", "smooth::*"],
    # plain data: settings, uniform blocks, WGSL text, and the per-pixel effects (no device)
    [
        "render::color", "render::albedo", "render::albedo::*", "render::block", "render::wgsl", "render::stage_part", "render::scene", "render::scene::*",
        "render::effects::surface", "render::effects::surface_effect",
        *[m for name in surface_effects() for m in (f"render::effects::{name}", f"render::effects::{name}::*")],
        "render::effects::*::settings", "render::effects::outlines::stroke_width", "render::effects::scene_settings",
        # each settings type described for front ends
        "render::settings", "render::settings::*",
    ],
    # the device and the meshes on it
    ["render::device", "render::gpu_albedo", "render::gpu_mesh", "render::mesh_record", "render::derived_vertices", "render::framing", "render::culling", "render::reference",
     "render::image_out"],
    ["render::uniforms", "render::pipelines", "render::graph", "render::graph::*", "render::context"],
    # passes, and the frame effects with theirs
    ["render::passes", "render::passes::*",
     *[m for name in frame_effects() for m in (f"render::effects::{name}", f"render::effects::{name}::*")]],
    # the registries that list the frame effects, and what is built from them
    ["render::effects", "render::effects::frame", "render::plan", "render::shader"],
    ["render::renderer", "render::splats", "render::draft", "render::draft::*", "render"],
    ["py", "py::*", "lib"],
]


def module_of(path: Path) -> str:
    rel = path.relative_to(SRC).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "mod":
        parts.pop()
    return "::".join(parts) if parts != ["lib"] else "lib"


def strip_tests(text: str) -> str:
    """The code without its `#[cfg(test)]` items (a test module runs above every layer)."""
    out = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].strip().startswith("#[cfg(test)]"):
            j = i + 1
            if j < len(lines) and lines[j].rstrip().endswith(";"):
                i = j + 1
                continue
            depth = 0
            started = False
            while j < len(lines):
                depth += lines[j].count("{") - lines[j].count("}")
                started = started or "{" in lines[j]
                j += 1
                if started and depth <= 0:
                    break
            i = j
            continue
        out.append(re.sub(r"//.*", "", lines[i]))
        i += 1
    return "\n".join(out)


def test_files(text: str, path: Path) -> Set[Path]:
    """Files declared only for tests (`#[cfg(test)] mod x;`)."""
    found = set()
    lines = text.splitlines()
    for a, b in zip(lines, lines[1:]):
        m = re.match(r"\s*(?:pub\s+)?mod\s+(\w+);", b)
        if a.strip().startswith("#[cfg(test)]") and m:
            base = path.parent if path.name in ("mod.rs", "lib.rs") else path.with_suffix("")
            for cand in (base / f"{m.group(1)}.rs", base / m.group(1) / "mod.rs"):
                found.add(cand)
    return found


def graph() -> Dict[str, Set[str]]:
    files = sorted(SRC.rglob("*.rs"))
    texts = {p: p.read_text() for p in files}
    skip: Set[Path] = set()
    for p, t in texts.items():
        skip |= test_files(t, p)
    modules = {module_of(p): p for p in files if p not in skip}
    edges: Dict[str, Set[str]] = {m: set() for m in modules}

    def resolve(parts: List[str]) -> str:
        for k in range(len(parts), 0, -1):
            cand = "::".join(parts[:k])
            if cand in modules:
                return cand
        return ""

    for m, p in modules.items():
        code = strip_tests(texts[p])
        here = [] if m == "lib" else m.split("::")
        is_dir = p.name == "mod.rs"
        parent = here if is_dir else here[:-1]
        # expand `use a::{b, c::{d, e}}` into paths
        for raw in re.findall(r"\b((?:crate|super|self)(?:::(?:\w+|\{[^;]*?\}))+)", code):
            for path in expand(raw):
                parts = path.split("::")
                if parts[0] == "crate":
                    target = resolve(parts[1:])
                else:
                    base = list(here if is_dir else here) if parts[0] == "self" else list(parent)
                    rest = parts[1:]
                    if parts[0] == "self" and not is_dir:
                        base = list(here)
                    while rest and rest[0] == "super":
                        base = base[:-1]
                        rest = rest[1:]
                    target = resolve(base + rest)
                if target and target != m and not m.startswith(target + "::") and target != "":
                    edges[m].add(target)
    return edges


def expand(path: str) -> List[str]:
    """`a::{b, c::{d}}` -> ['a::b', 'a::c::d']."""
    i = path.find("{")
    if i < 0:
        return [path]
    prefix = path[:i]
    body = path[i + 1 : path.rfind("}")]
    items, depth, cur = [], 0, ""
    for ch in body:
        if ch == "," and depth == 0:
            items.append(cur)
            cur = ""
            continue
        depth += ch == "{"
        depth -= ch == "}"
        cur += ch
    items.append(cur)
    out = []
    for it in items:
        it = it.strip()
        if not it or it == "self":
            out.append(prefix.rstrip(":"))
            continue
        it = re.split(r"\s+as\s+", it)[0]
        out += expand(prefix + it)
    return out


def layer(m: str) -> int:
    for i, pats in enumerate(LAYERS):
        if any(fnmatch.fnmatchcase(m, p) for p in pats):
            return i
    return -1


def cycles(edges: Dict[str, Set[str]]) -> List[List[str]]:
    """Strongly connected components of more than one module (Tarjan)."""
    index: Dict[str, int] = {}
    low: Dict[str, int] = {}
    stack: List[str] = []
    on: Set[str] = set()
    out: List[List[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def upward(edges: Dict[str, Set[str]]) -> List[Tuple[str, str]]:
    """Arrows from a module to one of a higher layer, and modules no layer names."""
    bad = []
    for m, ts in sorted(edges.items()):
        for t in sorted(ts):
            if layer(m) < layer(t) or layer(m) < 0 or layer(t) < 0:
                bad.append((m, t))
    return bad


def main() -> int:
    edges = graph()
    cyc = cycles(edges)
    up = upward(edges)
    unlayered = sorted(m for m in edges if layer(m) < 0)
    print(f"{len(edges)} modules, {sum(len(t) for t in edges.values())} arrows")
    print(f"import cycles: {len(cyc)}")
    for c in cyc:
        print("  cycle:", " <-> ".join(c))
    print(f"arrows from a lower layer to a higher one: {len(up)}")
    for a, b in up:
        print(f"  {a} (layer {layer(a)}) -> {b} (layer {layer(b)})")
    if unlayered:
        print("modules in no layer:", ", ".join(unlayered))
    return 1 if cyc or up or unlayered else 0


if __name__ == "__main__":
    sys.exit(main())
