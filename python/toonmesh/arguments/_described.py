"""The core's description of its settings classes (``Class.describe()``), read where a front end
needs a parameter's kind, choices, help or default instead of typing them again."""

from __future__ import annotations

from typing import Any, Dict


def described(cls: Any, name: str, constructor: str = "") -> Dict[str, Any]:
    """The parameter ``name`` of ``cls``'s constructor ``constructor`` (``""``: ``cls(...)``) as
    the core describes it: kind, choices or bounds, help and default."""
    for made_by in cls.describe()["constructors"]:
        if made_by["name"] == constructor:
            for param in made_by["params"]:
                if param["name"] == name:
                    return dict(param)
    raise LookupError(f"{cls.__name__}.{constructor or '__init__'} has no parameter {name!r}")


def default(cls: Any, constructor: str, param: str) -> Any:
    """The default of ``param`` in ``cls.constructor(...)`` (``constructor`` "" for ``cls(...)``)."""
    return described(cls, param, constructor)["default"]
