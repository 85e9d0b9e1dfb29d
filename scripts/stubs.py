"""Writes the type stub of the compiled core, `python/toonmesh/_core.pyi`: the template
`scripts/core_stub.pyi.in` with its settings classes generated from the core's description of
them (`Class.describe()`), so that a field added to the core reaches the stub with no other edit;
and the smoothing functions' keyword TypedDicts (`LaplacianOptions`, ... for
`**options: Unpack[...]`) between the markers of `python/toonmesh/smooth.py`, from the core's
description of each method (`_core._smoothing_description()`).

    python scripts/stubs.py            # writes the stub and the TypedDicts
    python scripts/stubs.py --check    # exit 1 if either committed file differs (tests run this)
"""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path
from typing import Any, Dict, List

ROOT = Path(__file__).resolve().parent.parent
TEMPLATE = ROOT / "scripts" / "core_stub.pyi.in"
STUB = ROOT / "python" / "toonmesh" / "_core.pyi"
SMOOTH = ROOT / "python" / "toonmesh" / "smooth.py"
SMOOTH_BEGIN = "# @generated keywords: `python scripts/stubs.py` writes this block from the core's description\n"
SMOOTH_END = "# @end generated keywords\n"
MARK = "# @settings-classes\n"
NAMES_MARK = "# @settings-class-names\n"

# The read-only views that are not fields (src/py/settings/classes.rs).
VIEWS: Dict[str, List[str]] = {
    "Outlines": ["styles: Final[Dict[str, Optional[LineStyle]]]"],
    "Material": ["hatch_style: Final[Optional[Dict[str, Any]]]"],
}

# What each kind of field takes, and what its getter gives.
TAKES = {
    "bool": "bool",
    "int": "int",
    "float": "float",
    "color": "_Color",
    "rgba": "_Color",
    "vec3": "Sequence[float]",
    "floats": "Sequence[float]",
    "table": "Any",
    "matrix": "Any",
    "names": "Union[str, Sequence[str]]",
    "style": "Union[bool, LineStyle, _Color]",
    "lights": "Union[Light, Sequence[Light]]",
    "image": "npt.ArrayLike",
}
GIVES = {
    "bool": "bool",
    "int": "int",
    "float": "float",
    "choice": "str",
    "color": "_Vec3",
    "rgba": "Tuple[float, float, float, float]",
    "vec3": "_Vec3",
    "floats": "List[float]",
    "table": "List[_Vec3]",
    "matrix": "List[List[float]]",
    "names": "List[str]",
    "style": "Union[LineStyle, bool]",
    "lights": "List[Light]",
    "image": "npt.NDArray[np.float32]",
}
# The other forms a settings field takes besides the class (src/py/settings/values.rs).
ALSO = {"Dither": "str", "Outlines": "str", "Shadows": "bool"}


def takes(f: Dict[str, Any]) -> str:
    if f["kind"] == "choice":
        return "Literal[" + ", ".join(repr(c) for c in f["choices"]) + "]"
    if f["kind"] == "setting":
        other = ALSO.get(f["class"])
        return f"Union[{other}, {f['class']}]" if other else f["class"]
    return TAKES[f["kind"]]


def gives(f: Dict[str, Any]) -> str:
    t = f["class"] if f["kind"] == "setting" else GIVES[f["kind"]]
    return f"Optional[{t}]" if f["optional"] else t


def signature(params: List[Dict[str, Any]], positional: int, required: int, first: str) -> str:
    out = [first] if first else []
    for i, p in enumerate(params):
        if i == positional:
            out.append("*")
        default = "" if i < required else " = ..."
        t = takes(p) if i < required else f"Optional[{takes(p)}]"
        out.append(f"{p['name']}: {t}{default}")
    return ", ".join(out)


def docstring(text: str, indent: str) -> List[str]:
    """`text` as a docstring, each paragraph wrapped to the stub's width."""
    lines: List[str] = []
    for paragraph in text.strip().split("\n\n"):
        if lines:
            lines.append("")
        lines += textwrap.wrap(" ".join(paragraph.split()), 96 - len(indent))
    if len(lines) == 1:
        return [f'{indent}"""{lines[0]}"""']
    return [f'{indent}"""{lines[0]}'] + [indent + line if line else "" for line in lines[1:]] + [f'{indent}"""']


def settings_class(cls: Any) -> str:
    d = cls.describe()
    name = d["class"]
    fields = "; ".join(f"{f['name']}: {f['help']}" for f in d["fields"])
    lines = ["@final", f"class {name}(_Settings):", *docstring(f"{d['help']}\n\nFields: {fields}.", "    ")]
    for c in d["constructors"]:
        sig = signature(c["params"], c["positional"], c["required"], "cls" if not c["name"] else "")
        if c["name"]:
            lines += ["    @staticmethod", f"    def {c['name']}({sig}) -> {name}:"]
            lines += docstring(c["help"], "        ") + ["        ..."]
        else:
            lines.append(f"    def __new__({sig}) -> {name}: ...")
    lines += [f"    {f['name']}: Final[{gives(f)}]" for f in d["fields"]]
    lines += [f"    {v}" for v in VIEWS.get(name, [])]
    changes = [f for f in d["fields"] if not f["fixed"]]
    sig = signature(changes, 0, 0, "self")
    lines.append(f"    def replace({sig}) -> {name}: ...")
    return "\n".join(lines) + "\n"


# What every settings class has besides its fields and constructors (src/py/settings/mod.rs).
SETTINGS_BASE = """class _Settings:
    @staticmethod
    def describe() -> Dict[str, Any]: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...
"""


def render_keywords() -> str:
    """The render keywords as a TypedDict, for `**options: Unpack[...]` in the public API."""
    d = __import__("toonmesh._core", fromlist=["RenderOptions"]).RenderOptions.describe()
    lines = ["class _RenderKeywords(TypedDict, total=False):"]
    lines += docstring("The keywords of RenderOptions (None: the core's default).", "    ")
    for f in d["fields"]:
        lines.append(f"    {f['name']}: Optional[{takes(f)}]")
    return "\n".join(lines) + "\n"


def generate() -> str:
    import toonmesh._core as core

    classes = "\n".join(settings_class(getattr(core, c)) for c in core.SETTINGS_CLASSES)
    text = TEMPLATE.read_text()
    assert MARK in text and NAMES_MARK in text, f"{TEMPLATE} lacks {MARK.strip()!r} or {NAMES_MARK.strip()!r}"
    names = "".join(f'    "{c}",\n' for c in core.SETTINGS_CLASSES)
    return text.replace(NAMES_MARK, names).replace(MARK, render_keywords() + "\n" + SETTINGS_BASE + "\n" + classes)


def smooth_keywords() -> str:
    """Each smoothing method's keywords as a TypedDict, for `**options: Unpack[...]`: the
    keywords every method takes (and `pinned`, the mesh's, not a method's) in a base that each
    method's class extends with its own."""
    import toonmesh.smooth as smooth

    lines_of = {method: [f"    {k['name']}: {smooth._annotation(k)}" for k in d["keywords"]]
                for method, d in smooth._DESCRIBED.items()}
    shared = [line for line in next(iter(lines_of.values())) if all(line in ls for ls in lines_of.values())]
    base = "SmoothingOptions"
    blocks = ["\n".join([f"class {base}(TypedDict, total=False):",
                          *docstring("The keywords every smoothing function takes, for type checkers.", "    "),
                          "", *shared, f"    {smooth._PINNED}: Optional[Any]"]) + "\n"]
    seen: Dict[str, str] = {}
    for method, lines in lines_of.items():
        name = method.capitalize() + "Options"
        own = [line for line in lines if line not in shared]
        same = seen.setdefault("\n".join(own), name)
        if same != name:  # the same keywords as an earlier method's (guided's are bilateral's)
            blocks.append(f"{name} = {same}\n")
            continue
        head = [f"class {name}({base}, total=False):"]
        head += docstring(f"The keywords of :func:`{method}`, for type checkers (see its docstring).", "    ")
        blocks.append("\n".join(head + [""] + own) + "\n")
    return "\n\n".join(blocks)


def smooth_module() -> str:
    """smooth.py with its generated block (between its markers) as the description says now."""
    text = SMOOTH.read_text()
    assert SMOOTH_BEGIN in text and SMOOTH_END in text, f"{SMOOTH} lacks its @generated markers"
    before, rest = text.split(SMOOTH_BEGIN, 1)
    _, after = rest.split(SMOOTH_END, 1)
    return before + SMOOTH_BEGIN + smooth_keywords() + SMOOTH_END + after


def main(argv: List[str]) -> int:
    written = [(STUB, generate()), (SMOOTH, smooth_module())]
    if "--check" in argv:
        stale = [path for path, text in written if path.read_text() != text]
        for path in stale:
            print(f"{path.relative_to(ROOT)} differs from what scripts/stubs.py writes: run `make stubs`")
        return 1 if stale else 0
    for path, text in written:
        path.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
