"""Builds the API reference from the docstrings with pdoc: ``make docs`` (into docs/api/).

    python docs/api_docs.py [OUT_DIR]

Also lists public functions, classes and methods without a docstring, and fails when there is
one, so a new function cannot slip in undocumented. (Attributes and properties are described in
their class's docstring.)
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path
from typing import List, Tuple

#: The documented modules: the package (with toonmesh.smooth, .edges and .shapes, which it lists
#: in __all__) and the public modules it does not import.
MODULES = ("toonmesh", "toonmesh.batch", "toonmesh.data", "toonmesh.cli", "toonmesh.testing", "toonmesh.pytest_plugin")


def undocumented() -> List[str]:
    """Full names of public functions, classes and methods of MODULES without a docstring."""
    import pdoc.doc

    missing = []
    stack: list = [pdoc.doc.Module.from_name(name) for name in MODULES]
    while stack:
        parent = stack.pop()
        members = parent.own_members if isinstance(parent, pdoc.doc.Class) else list(parent.members.values())
        for m in members:
            if m.name.startswith("_"):
                continue
            if isinstance(m, (pdoc.doc.Class, pdoc.doc.Module)):
                stack.append(m)
            if isinstance(m, (pdoc.doc.Function, pdoc.doc.Class)) and not m.docstring.strip():
                missing.append(m.fullname)
    return sorted(set(missing))


def build(out_dir: Path) -> Tuple[List[Path], List[str]]:
    """Writes the HTML pages into ``out_dir``; returns the pages and pdoc's warnings."""
    import pdoc

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        pdoc.pdoc(*MODULES, output_directory=Path(out_dir))
    return sorted(Path(out_dir).rglob("*.html")), [str(w.message) for w in caught]


def main(argv: List[str]) -> int:
    out_dir = Path(argv[0] if argv else Path(__file__).parent / "api")
    pages, warned = build(out_dir)
    for w in warned:
        print(f"pdoc: {w}", file=sys.stderr)
    missing = undocumented()
    for name in missing:
        print(f"no docstring: {name}", file=sys.stderr)
    print(f"wrote {len(pages)} pages to {out_dir} (open {out_dir / 'index.html'})")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
