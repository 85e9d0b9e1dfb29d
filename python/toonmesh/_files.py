"""Mesh files in and images out, for the command line and batch renders.

Meshes are read and written through trimesh (``pip install toonmesh[io]``), which knows OBJ, PLY,
STL, OFF and GLB/glTF among others. Renders are written as PNG (the colour image) or, when float
outputs (normal, depth) are asked for, as NPZ with every output array and the camera used.
"""

from __future__ import annotations

import os
from typing import Any, Dict, List, Sequence, Tuple

import numpy as np

from toonmesh import _colors, _core

#: Suffixes written for a render: the colour image alone, or every output array.
IMAGE_SUFFIXES = (".png", ".npz")

_TRIMESH_HINT = "reading and writing mesh files needs trimesh: pip install 'toonmesh[io]'"


def _trimesh() -> Any:
    try:
        import trimesh
    except ImportError:
        raise ImportError(_TRIMESH_HINT) from None
    return trimesh


def read_mesh(path: str) -> Tuple[np.ndarray, np.ndarray]:
    """(V, F) of a mesh file: (N, 3) float64 positions, (M, 3) int64 triangles.

    Vertices are kept as the file lists them (no merging or cleanup; an OBJ's positions are
    not split where texture coordinates change), except in STL files, which
    store every triangle's corners separately: those are merged by position, so that the mesh is
    connected (smoothing and smooth normals need that). A scene (GLB, glTF) is flattened into one
    mesh with its transforms applied.

    Raises:
        FileNotFoundError: no such file.
        ImportError: trimesh is not installed.
        ValueError: the file cannot be read as a triangle mesh.
    """
    mesh = _load(path, keep_obj_order=True)
    return _arrays(path, mesh)


def read_colored_mesh(path: str) -> Tuple[np.ndarray, np.ndarray, Dict[str, Any]]:
    """(V, F, colour keywords) of a mesh file, for rendering: as :func:`read_mesh`, with the
    colour the file carries (vertex or face colours, or uv and the material's image) as the
    keywords of :class:`toonmesh.Mesh`; what it carries but is not drawn is named in a
    ``UserWarning``. A textured OBJ's vertices are split where its texture coordinates change,
    so that the texture maps right (smooth normals then break along those seams)."""
    mesh = _load(path, keep_obj_order=True)
    if path.lower().endswith(".obj") and "texture" in _colors.from_trimesh(mesh):
        mesh = _load(path, keep_obj_order=False)
    V, F = _arrays(path, mesh)
    return V, F, _colors.gather(mesh, {}, path)


def _load(path: str, keep_obj_order: bool) -> Any:
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such file")
    if os.path.isdir(path):
        raise IsADirectoryError(f"{path}: is a folder, not a mesh file")
    trimesh = _trimesh()
    try:
        # maintain_order: OBJ positions as listed, not split at texture seams
        extra = {"maintain_order": True} if keep_obj_order and path.lower().endswith(".obj") else {}
        mesh = trimesh.load(path, process=False, force="mesh", **extra)
    except Exception as exc:  # trimesh raises many kinds for files it cannot parse
        raise ValueError(f"{path}: cannot read a mesh ({_one_line(exc)})") from None
    if path.lower().endswith(".stl") and hasattr(mesh, "merge_vertices"):
        mesh.merge_vertices()
    return mesh


def _arrays(path: str, mesh: Any) -> Tuple[np.ndarray, np.ndarray]:
    faces = np.asarray(getattr(mesh, "faces", np.zeros((0, 3))))
    if faces.ndim != 2 or faces.shape[1] != 3 or len(faces) == 0:
        raise ValueError(f"{path}: no triangles in the file")
    return np.asarray(mesh.vertices, dtype=np.float64), faces.astype(np.int64, copy=False)


def write_mesh(path: str, vertices: np.ndarray, faces: np.ndarray) -> None:
    """Writes a triangle mesh; the format follows the file name's suffix (.obj, .ply, .stl,
    .off, .glb, ...)."""
    trimesh = _trimesh()
    suffix = os.path.splitext(path)[1].lower().lstrip(".")
    mesh = trimesh.Trimesh(np.asarray(vertices), np.asarray(faces), process=False)
    try:
        data = mesh.export(file_type=suffix)
    except Exception as exc:
        raise ValueError(f"{path}: cannot write this format ({_one_line(exc)})") from None
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def image_suffix(outputs: Sequence[str]) -> str:
    """".png" when only the colour image is asked for, else ".npz"."""
    return ".png" if list(outputs) == ["color"] else ".npz"


def save_result(result: Any, path: str) -> None:
    """Writes a render result: PNG (colour) or NPZ (every output present, plus ``view_matrix``,
    ``projection``, ``near`` and ``far``), by the suffix of ``path``."""
    suffix = os.path.splitext(path)[1].lower()
    if suffix == ".png":
        result.save(path)
    elif suffix == ".npz":
        arrays = {n: getattr(result, n) for n in _core.IMAGE_OUTPUTS if getattr(result, n) is not None}
        np.savez_compressed(
            path, **arrays, view_matrix=result.view_matrix, projection=result.projection,
            near=np.float64(result.near), far=np.float64(result.far),
        )
    else:
        raise ValueError(f"{path}: an image is written as .png or .npz")


def view_paths(mesh_path: str, out_dir: str, views: int, suffix: str) -> List[str]:
    """Output files of one mesh's views: ``out_dir/STEM.png``, or ``STEM-000.png``,
    ``STEM-001.png``, ... for a turntable."""
    stem = os.path.splitext(os.path.basename(mesh_path))[0]
    if views == 1:
        return [os.path.join(out_dir, stem + suffix)]
    return [os.path.join(out_dir, f"{stem}-{k:03d}{suffix}") for k in range(views)]


def check_distinct_names(paths: Sequence[str]) -> None:
    """Meshes written into one folder must not share a file name stem."""
    seen: Dict[str, str] = {}
    for p in paths:
        stem = os.path.splitext(os.path.basename(p))[0]
        if stem in seen:
            raise ValueError(f"{seen[stem]} and {p} would write the same images ({stem}.*): rename one")
        seen[stem] = p


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    return text or type(exc).__name__
