"""The core's description of the smoothing methods (``_core._smoothing_description()``) is what
the functions do, take and document: each described default, given explicitly, gives the same
bits as leaving it out, for every method and preset; another value in range gives others; the
signatures and the docstrings' Args entries are the description's."""

from __future__ import annotations

import inspect
import math
from typing import Any, Dict, List, Optional

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

DESCRIPTION: List[Dict[str, Any]] = _core._smoothing_description()
CASES = [
    (m["method"], preset, k)
    for m in DESCRIPTION
    for preset in [None, *m["presets"]]
    for k in m["keywords"]
    if k["name"] != "preset"
]


@pytest.fixture(scope="module")
def mesh():
    return tm.shapes.icosphere(2, noise=0.05, seed=3)


def _default(keyword: Dict[str, Any], preset: Optional[str]) -> Any:
    return keyword["presets"].get(preset, keyword["default"]) if preset else keyword["default"]


@pytest.mark.parametrize("method, preset, keyword", CASES, ids=[f"{m}-{p}-{k['name']}" for m, p, k in CASES])
def test_the_described_default_is_what_leaving_it_out_does(mesh, method, preset, keyword):
    V, F = mesh
    f = getattr(tm.smooth, method)
    default = _default(keyword, preset)
    if default is None:  # measured from the mesh (sigma_r): None means it
        assert keyword["default_words"], keyword
        default = None
    left_out = f(V, F, preset=preset) if preset else f(V, F)
    try:
        given = f(V, F, **({"preset": preset} if preset else {}), **{keyword["name"]: default})
    except ValueError as exc:  # an option the preset lacks is refused even at its default, naming both
        assert str(exc).startswith(f"{keyword['name']}: {method}(preset='{preset}')"), exc
        return
    assert np.array_equal(given, left_out), (method, preset, keyword["name"], default)


def _another(keyword: Dict[str, Any]) -> Any:
    """An allowed value other than the default (the middle of a bounded range, twice the default
    of an unbounded one)."""
    lo, hi, default = keyword["min"], keyword["max"], keyword["default"]
    other = 2 * default if math.isinf(hi) else (lo + hi) / 2 if hi < 1e6 else default + 1
    if keyword["kind"] == "int":
        other = int(other)
    return other if other != default else default / 2


@pytest.mark.parametrize("method", [m["method"] for m in DESCRIPTION])
def test_another_value_gives_another_result(mesh, method):
    """So the test above could fail: each number a method takes reaches it."""
    V, F = mesh
    f = getattr(tm.smooth, method)
    described = next(m for m in DESCRIPTION if m["method"] == method)
    numbers = [k for k in described["keywords"] if k["kind"] in ("int", "float") and k["default"] is not None]
    assert numbers
    for k in numbers:
        if k["name"] == "max_iter":  # a bound on the solver's work: the same result while it converges
            continue
        assert not np.array_equal(f(V, F, **{k["name"]: _another(k)}), f(V, F)), k["name"]


def _shown(value: Any) -> str:
    """A default as Python spells it: ``"uniform"``, ``0.5``, ``1.0``, ``10``, ``False``."""
    return f'"{value}"' if isinstance(value, str) else repr(value) if isinstance(value, float) else str(value)


@pytest.mark.parametrize("method", [m["method"] for m in DESCRIPTION])
def test_signatures_and_docstrings_are_the_description(method):
    f = getattr(tm.smooth, method)
    described = next(m for m in DESCRIPTION if m["method"] == method)
    names = [k["name"] for k in described["keywords"]]
    assert list(inspect.signature(f).parameters) == ["vertices", "faces", *names, "pinned"]
    doc = f.__doc__
    for k in described["keywords"]:
        (line,) = [i for i, text in enumerate(doc.splitlines()) if text.startswith(f"        {k['name']}: ")]
        entry = " ".join(doc.splitlines()[line: line + 12])
        default = k["default"]
        if k["default_words"]:
            assert k["default_words"] in " ".join(entry.split()), k["name"]
        else:
            assert f"default {_shown(default)}" in entry, (k["name"], default)
        for preset, value in k["presets"].items():
            assert preset in entry and _shown(value) in entry, (k["name"], preset)
        for choice in k.get("choices", []):
            assert f'"{choice}"' in entry, (k["name"], choice)
        if k["kind"] in ("int", "float"):
            assert "in [" in entry or "in (" in entry or "> " in entry or ">= " in entry, k["name"]
        assert " ".join(k["help"][1:].split()[:4]) in " ".join(entry.split()), k["name"]


def test_the_description_has_the_keys_front_ends_read():
    for m in DESCRIPTION:
        assert set(m) == {"method", "help", "keywords", "presets"}
        for k in m["keywords"]:
            assert {"name", "kind", "optional", "default", "presets", "help"} <= set(k), k
            if k["kind"] in ("int", "float"):
                assert isinstance(k["min"], float) and isinstance(k["max"], float) and len(k["exclusive"]) == 2
            if k["kind"] == "choice":
                assert k["choices"]
    assert [m["method"] for m in DESCRIPTION] == tm.smooth.__all__


def test_the_guides_table_of_defaults_is_the_description():
    """docs/smoothing.md's table of options gives the described defaults (without a preset)."""
    from pathlib import Path
    import re

    text = (Path(__file__).resolve().parent.parent / "docs" / "smoothing.md").read_text()
    checked = 0
    for m in DESCRIPTION:
        (row,) = [line for line in text.splitlines() if re.match(rf"\| (`\w+`, )*`{m['method']}`", line)]
        given = dict(re.findall(r"(\w+)=([^,`\s]+)", row))
        for k in m["keywords"]:
            if k["name"] in given:
                assert given[k["name"]] == _shown(k["default"]), (m["method"], k["name"], given[k["name"]])
                checked += 1
    assert checked >= 15
