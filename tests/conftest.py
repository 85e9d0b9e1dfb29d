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
