"""The core's descriptions of its settings classes (``Class.describe()``) and smoothing methods
(``_core._smoothing_description()``), as the generated tests read them.

A number is described by its rule's bounds (``min``, ``max``: ±inf where unbounded, and
``exclusive``: [min excluded, max excluded]), a control's finite range (``slider``) and, for a
rule that is not a range, its text (``rule``). A key the tests need and the build lacks is an
error that names it: the tests never guess a bound."""

from __future__ import annotations

from typing import Any, Dict, List, Tuple

import toonmesh as tm

NEEDED = {"int": ("min", "max", "exclusive"), "float": ("min", "max", "exclusive"), "choice": ("choices",),
          "names": ("choices",), "setting": ("class",)}
SLIDER = ("slider",)  # a settings number's control range (the smoothing keywords have none)


def checked(entry: Dict[str, Any], where: str, more: Tuple[str, ...] = ()) -> Dict[str, Any]:
    """``entry`` (a field, parameter or keyword) once it has every key its kind needs (and, for
    a number, the keys ``more``)."""
    needed = NEEDED.get(entry.get("kind", ""), ())
    needed += more if entry.get("kind") in ("int", "float") else ()
    missing = [k for k in ("name", "kind", "optional", *needed) if k not in entry]
    if missing:
        raise KeyError(f"{where}.{entry.get('name')}: the core's description has no {missing} ({sorted(entry)})")
    return entry


def settings_classes() -> List[Any]:
    """Every settings class the core lists, as the package exports it."""
    return [getattr(tm, name) for name in tm._core.SETTINGS_CLASSES]


def fields(cls: Any) -> List[Dict[str, Any]]:
    return [checked(f, cls.__name__, SLIDER) for f in cls.describe()["fields"]]


def constructors(cls: Any) -> List[Tuple[str, Any, int, List[Dict[str, Any]]]]:
    """(name, the callable, how many leading parameters are required, its parameters) of each
    of ``cls``'s constructors (name "" for ``cls(...)``)."""
    out = []
    for c in cls.describe()["constructors"]:
        name = f"{cls.__name__}.{c['name']}" if c["name"] else cls.__name__
        make = getattr(cls, c["name"]) if c["name"] else cls
        out.append((name, make, c["required"], [checked(p, name, SLIDER) for p in c["params"]]))
    return out


def smoothing() -> List[Dict[str, Any]]:
    """Each smoothing method with its keywords."""
    methods = tm._core._smoothing_description()
    for m in methods:
        m["keywords"] = [checked(k, f"smooth.{m['method']}") for k in m["keywords"]]
    return methods
