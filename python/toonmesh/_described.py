"""The core's description of its settings classes (``Class.describe()``), read where a front end
needs one of its defaults instead of typing the number again."""

from __future__ import annotations

from typing import Any


def default(cls: Any, constructor: str, param: str) -> Any:
    """The default of ``param`` in ``cls.constructor(...)`` (``constructor`` "" for ``cls(...)``)."""
    for made in cls.describe()["constructors"]:
        if made["name"] == constructor:
            for p in made["params"]:
                if p["name"] == param:
                    return p["default"]
    raise KeyError(f"{cls.__name__}.{constructor or '__init__'} has no parameter {param!r}")
