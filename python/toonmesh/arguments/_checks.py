"""Argument checks for the functions written in Python (the core checks its own): the package's
type rules for a flag, an integer and a number, with errors that name the argument."""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np


def flag(name: str, value: Any) -> bool:
    """``value`` as a bool: True or False (NumPy's too), nothing else."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: expected True or False, got {type(value).__name__}")
    return bool(value)


def integer(name: str, value: Any, lo: int, hi: int) -> int:
    """``value`` as an int in [lo, hi]: an int or NumPy integer, never a bool or a float."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name}: expected an int, got {type(value).__name__} {value!r:.40}")
    if not lo <= int(value) <= hi:
        raise ValueError(f"{name}: must be in [{lo}, {hi}], got {value}")
    return int(value)


def number(name: str, value: Any, lo: float = -math.inf, hi: float = math.inf, *, open_lo: bool = False) -> float:
    """``value`` as a finite float in [lo, hi] (or (lo, hi] with ``open_lo``): an int, float or
    NumPy number, never a bool, a string or a complex number."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: expected a number, got {type(value).__name__} {value!r:.40}")
    try:
        v = float(value)
    except OverflowError:  # an int beyond float's range
        raise ValueError(f"{name}: must be a finite number, got an int of {int(value).bit_length()} bits") from None
    low_ok = v > lo if open_lo else v >= lo
    if not (math.isfinite(v) and low_ok and v <= hi):
        bracket = "(" if open_lo else "["
        raise ValueError(f"{name}: must be a finite number in {bracket}{lo:g}, {hi:g}], got {value!r}")
    return v
