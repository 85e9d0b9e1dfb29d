"""MkDocs hook: every public function, class and method of the API reference has a docstring.

The reference (docs/api.md) is made by mkdocstrings from the docstrings, read by griffe, as this
check reads them; a public name without one is a warning, which fails the strict build. (Data
attributes and properties are described in their class's docstring.)
"""

from __future__ import annotations

import logging
import sys
import warnings
from pathlib import Path
from typing import List

import griffe

log = logging.getLogger("mkdocs.hooks.api")

#: the documented modules: the package (with toonmesh.smooth, .edges and .shapes, which it lists in
#: __all__) and the public modules it does not import
MODULES = ("toonmesh", "toonmesh.smooth", "toonmesh.edges", "toonmesh.shapes", "toonmesh.batch",
           "toonmesh.data", "toonmesh.figures", "toonmesh.cli", "toonmesh.testing", "toonmesh.pytest_plugin")


def undocumented(python_dir: Path) -> List[str]:
    """Full names of the public functions, classes and methods of MODULES without a docstring."""
    with warnings.catch_warnings():  # importing every module to read it: their deprecation notices
        warnings.simplefilter("ignore", DeprecationWarning)
        package = griffe.load("toonmesh", search_paths=[str(python_dir), *sys.path], force_inspection=True)
    missing = set()
    seen = set()
    stack = [package[name[len("toonmesh."):]] if name != "toonmesh" else package for name in MODULES]
    while stack:
        obj = stack.pop()
        if obj.path in seen:
            continue
        seen.add(obj.path)
        for name, member in obj.members.items():
            if name.startswith("_"):
                continue
            if member.is_alias:
                try:
                    member = member.final_target
                except (griffe.AliasResolutionError, griffe.CyclicAliasError):
                    continue
                if not member.path.startswith("toonmesh"):
                    continue  # imported from elsewhere (numpy, typing): not toonmesh's to document
            if obj.is_class and member.parent is not obj:
                continue  # inherited
            if member.is_module and not member.path.startswith(obj.path + "."):
                continue
            if member.is_class or member.is_function:
                if not (member.docstring and member.docstring.value.strip()):
                    missing.add(member.path)
            if member.is_class or (member.is_module and member.path in MODULES):
                stack.append(member)
    return sorted(missing)


def on_config(config):
    for name in undocumented(Path(config["config_file_path"]).parent / "python"):
        log.warning("no docstring: %s (every public function, class and method of the API has one)", name)
    return config


def on_page_markdown(markdown: str, page, config, files) -> str:
    """The API page's ``<!-- toonmesh.RenderKeywords -->``: that TypedDict's docstring (the render
    keywords). The core makes the class at run time, where griffe cannot follow it."""
    if page.file.src_uri != "api.md":
        return markdown
    import inspect

    import toonmesh

    doc = inspect.getdoc(toonmesh.RenderKeywords)
    section = f"### `toonmesh.RenderKeywords`\n\n{doc}\n"
    marker = "<!-- toonmesh.RenderKeywords -->"
    if marker not in markdown:
        log.warning("api.md: no %s marker for the render keywords", marker)
    return markdown.replace(marker, section)
