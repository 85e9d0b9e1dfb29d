"""Shared test helpers: mesh loading, peer imports and scale-relative comparisons."""

from __future__ import annotations

import importlib
import os
from pathlib import Path
from typing import Any, Tuple

import numpy as np
import pytest

MESHES = Path(__file__).parent / "data" / "meshes"


def need(module: str) -> Any:
    """Imports an optional peer library: skipped on a user's machine without it, but a hard
    failure in CI, where every peer must be installed."""
    try:
        return importlib.import_module(module)
    except ImportError:
        if os.environ.get("CI", "").lower() == "true":
            raise
        pytest.skip(f"{module} is not installed")


def load_mesh(name: str) -> Tuple[np.ndarray, np.ndarray]:
    """(V float64, F int64) of a test mesh, exactly as stored (no merging, no cleanup)."""
    trimesh = need("trimesh")
    m = trimesh.load(MESHES / f"{name}.obj", process=False, force="mesh")
    return np.asarray(m.vertices, dtype=np.float64), np.asarray(m.faces, dtype=np.int64)


def diagonal(V: np.ndarray) -> float:
    return float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))


def rel_err(a: np.ndarray, b: np.ndarray, V: np.ndarray) -> float:
    """Largest coordinate difference relative to the bounding-box diagonal of V."""
    return float(np.abs(np.asarray(a, np.float64) - np.asarray(b, np.float64)).max() / diagonal(V))


def long_tests() -> bool:
    """TOONMESH_LONG_TESTS=1 asks for the long soak and many property examples; CI runs a
    bounded, deterministic number."""
    return os.environ.get("TOONMESH_LONG_TESTS", "") == "1"


try:
    from hypothesis import HealthCheck, settings

    # "ci" (the default): few examples, derandomized, so every run checks the same cases.
    settings.register_profile(
        "ci", max_examples=30, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow]
    )
    settings.register_profile(
        "long", max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow]
    )
    settings.load_profile("long" if long_tests() else "ci")
except ImportError:  # the property tests say so themselves (and fail in CI)
    pass
