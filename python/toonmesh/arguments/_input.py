"""Mesh input shared by every public function: (V, F) arrays or a ``trimesh.Trimesh``."""

from __future__ import annotations

import os
from typing import Any, Optional, Tuple

import numpy as np


def mesh_arrays(vertices: Any, faces: Optional[Any]) -> Tuple[np.ndarray, np.ndarray]:
    """Returns (V, F) as NumPy arrays without copying or modifying the caller's data.

    ``vertices`` may be an (N, 3) array-like, or a ``trimesh.Trimesh`` when ``faces`` is None
    (its ``vertices`` and ``faces`` are read, never changed). Dtype, shape, finiteness and index
    checks happen in the core, which raises ``TypeError``/``ValueError``/``IndexError`` naming
    the argument.
    """
    if faces is None:
        if hasattr(vertices, "vertices") and hasattr(vertices, "faces"):
            return np.asarray(vertices.vertices), np.asarray(vertices.faces)
        if hasattr(vertices, "graph") and hasattr(vertices, "geometry"):
            raise TypeError("vertices: a trimesh.Scene holds several meshes: pass it to toonmesh.render, or "
                            "toonmesh.load(path) / scene.to_mesh() for one mesh")
        if isinstance(vertices, (str, os.PathLike)):
            raise TypeError(f"vertices: got a file path ({os.fspath(vertices)!r}): read it with toonmesh.load")
        raise TypeError("faces: required unless vertices is a trimesh.Trimesh")
    return _as_array("vertices", vertices), _as_array("faces", faces)


def _as_array(name: str, value: Any) -> np.ndarray:
    if isinstance(value, np.ndarray):
        return value
    if value is None or isinstance(value, (str, bytes)):
        raise TypeError(f"{name}: expected an array, got {type(value).__name__} {value!r:.40}")
    if hasattr(value, "vertices") and hasattr(value, "faces"):
        raise TypeError(f"{name}: pass a trimesh.Trimesh alone, as the first argument")
    try:
        return np.asarray(value)
    except Exception as exc:  # ragged lists and other non-arrays
        raise TypeError(f"{name}: cannot be read as an array ({exc})") from None
