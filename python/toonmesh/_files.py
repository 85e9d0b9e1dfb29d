"""Mesh files in and images out, for the command line and batch renders.

Meshes are read and written through trimesh (``pip install toonmesh[io]``), which knows OBJ, PLY,
STL, OFF and GLB/glTF among others. Renders are written as PNG (the colour image) or, when float
outputs (normal, depth) are asked for, as NPZ with every output array and the camera used.
"""

from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from toonmesh import _core
from toonmesh._load import Surface, read_surfaces, trimesh_module

#: Suffixes written for a render: the colour image alone, or every output array.
IMAGE_SUFFIXES = (".png", ".npz")

def read_mesh(path: str) -> Tuple[np.ndarray, np.ndarray]:
    """(V, F) of a mesh file: (N, 3) float64 positions, (M, 3) int64 triangles, every placed
    geometry of a scene (GLB, glTF) in one mesh with its world transform applied.

    The file is read and checked as :func:`toonmesh.load` reads it (vertices as the file lists
    them; an STL's corners merged by position).

    Raises:
        FileNotFoundError: no such file.
        ImportError: trimesh is not installed.
        ValueError: the file cannot be read as a triangle mesh (naming the file and the problem).
    """
    placed = read_surfaces(path)
    if len(placed) == 1 and placed[0][1] is None:
        return placed[0][0].vertices, placed[0][0].faces
    Vs, Fs, n = [], [], 0
    for surface, transform in placed:
        V = surface.vertices if transform is None else surface.vertices @ transform[:3, :3].T + transform[:3, 3]
        Vs.append(V)
        Fs.append(surface.faces + n)
        n += len(V)
    return np.concatenate(Vs), np.concatenate(Fs)


def write_mesh(path: str, vertices: np.ndarray, faces: np.ndarray, surface: Optional[Surface] = None,
               normals: Optional[np.ndarray] = None) -> None:
    """Writes a triangle mesh; the format follows the file name's suffix (.obj, .ply, .stl,
    .off, .glb, ...). With ``surface``, its texture coordinates, texture, base colour and vertex
    or face colours go along (where the format holds them; an OBJ's texture and MTL are written
    beside it); ``normals`` (N, 3) are written where the format holds vertex normals."""
    trimesh = trimesh_module()
    suffix = os.path.splitext(path)[1].lower().lstrip(".")
    mesh = trimesh.Trimesh(np.asarray(vertices), np.asarray(faces), process=False,
                           vertex_normals=normals)
    visual = None if surface is None else _visual(trimesh, surface)
    if visual is not None:
        mesh.visual = visual
    try:
        if suffix == "obj":  # its MTL and texture go beside it, named after it
            stem = os.path.splitext(os.path.basename(path))[0]
            text, beside = trimesh.exchange.obj.export_obj(
                mesh, include_normals=normals is not None, include_texture=visual is not None,
                return_texture=True, mtl_name=stem + ".mtl", header=None)
            for name, data in beside.items():
                with open(os.path.join(os.path.dirname(os.path.abspath(path)), name), "wb") as f:
                    f.write(data)
            data = text
        else:
            data = mesh.export(file_type=suffix)
    except Exception as exc:
        raise ValueError(f"{path}: cannot write this format ({_one_line(exc)})") from None
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def seam_normals(vertices: np.ndarray, faces: np.ndarray, before: np.ndarray) -> np.ndarray:
    """Unit vertex normals of a smoothed mesh that keep the file's normal seams: the area-weighted
    face normals are summed over every copy of a vertex at the same position whose file normal
    was the same (copies split only by texture coordinates shade as one), and kept apart where
    the file's normals differed (a hard edge stays hard). (N, 3) float64."""
    V = np.asarray(vertices, dtype=np.float64)
    corners = V[faces]
    area_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    per_vertex = np.zeros_like(V)
    for k in range(3):
        np.add.at(per_vertex, faces[:, k], area_normals)
    # copies: the same position (before smoothing moves them together) and the same file normal
    _, group = np.unique(np.concatenate([V, np.round(before, 6)], axis=1), axis=0, return_inverse=True)
    group = group.ravel()
    summed = np.zeros((group.max() + 1, 3))
    np.add.at(summed, group, per_vertex)
    out = summed[group]
    length = np.linalg.norm(out, axis=1, keepdims=True)
    return np.where(length > 0, out / np.where(length > 0, length, 1), before)


def _visual(trimesh: Any, surface: Surface) -> Any:
    """A trimesh visual holding a Surface's UVs and texture, or its colours."""
    if surface.uv is not None:
        from PIL import Image

        image = None if surface.texture is None else Image.fromarray(surface.texture)
        kw: Dict[str, Any] = {}
        if surface.base_color is not None:
            kw["diffuse"] = np.round(surface.base_color * 255).astype(np.uint8)
        material = trimesh.visual.material.SimpleMaterial(image=image, **kw)
        return trimesh.visual.TextureVisuals(uv=surface.uv, material=material)
    if surface.vertex_colors is not None:
        return trimesh.visual.ColorVisuals(vertex_colors=surface.vertex_colors)
    if surface.face_colors is not None:
        return trimesh.visual.ColorVisuals(face_colors=surface.face_colors)
    return None


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
