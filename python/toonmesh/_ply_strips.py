"""PLY files of triangle strips (``element tristrips``), which trimesh reads as points (ASCII) or
refuses (binary): read here, ASCII and binary, and their strips turned into triangles."""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from toonmesh._file_checks import PLY_TYPES, MeshFileError, ply_header, strip_triangles


def has_strips(path: str) -> bool:
    """Whether a PLY file's header declares a ``tristrips`` element."""
    return any(name == "tristrips" for name, _, _ in ply_header(path)[1])


def read(path: str) -> Tuple[np.ndarray, np.ndarray, Optional[np.ndarray]]:
    """(V (N, 3) float64, F (M, 3) int64, vertex colours (N, 4) uint8 or None) of a PLY whose
    faces are triangle strips (see :func:`toonmesh._file_checks.strip_triangles`)."""
    fmt, elements, header = ply_header(path)
    with open(path, "rb") as f:
        f.seek(header)
        data = f.read()
    order = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
    tokens = iter(data.split()) if order is None else None
    pos = 0
    values: Dict[str, Dict[str, Any]] = {}
    try:
        for name, count, props in elements:
            if order is None:
                values[name] = _ascii_element(tokens, count, props)
            else:
                values[name], pos = _binary_element(data, pos, order, count, props)
    except (StopIteration, ValueError, IndexError):
        raise MeshFileError(f"{path}: the '{name}' elements are cut off or malformed") from None
    vertex = values.get("vertex", {})
    if not all(k in vertex for k in "xyz"):
        raise MeshFileError(f"{path}: no x, y, z vertex properties")
    V = np.stack([np.asarray(vertex[k], dtype=np.float64) for k in "xyz"], axis=1)
    strips = values["tristrips"].get("vertex_indices")
    if strips is None:
        raise MeshFileError(f"{path}: the tristrips element has no vertex_indices list")
    F = strip_triangles(strips)
    if len(F) and (F.max() >= len(V)):
        raise MeshFileError(f"{path}: a strip points past the {len(V):,} vertices (index {int(F.max())})")
    colors = None
    if all(k in vertex for k in ("red", "green", "blue")):
        rgb = [np.asarray(vertex[k]) for k in ("red", "green", "blue")]
        alpha = np.asarray(vertex["alpha"]) if "alpha" in vertex else np.full(len(V), 255)
        colors = np.stack(rgb + [alpha], axis=1).astype(np.uint8)
    return V, F, colors


def _ascii_element(tokens: Any, count: int, props: List[Tuple[str, ...]]) -> Dict[str, Any]:
    out: Dict[str, List[Any]] = {p[-1]: [] for p in props}
    for _ in range(count):
        for p in props:
            if p[0] == "list":
                n = int(next(tokens))
                out[p[-1]].append([int(next(tokens)) for _ in range(n)])
            else:
                out[p[-1]].append(float(next(tokens)))
    return out


def _binary_element(data: bytes, pos: int, order: str, count: int,
                    props: List[Tuple[str, ...]]) -> Tuple[Dict[str, Any], int]:
    if all(p[0] != "list" for p in props):  # fixed rows: one structured array
        dtype = np.dtype([(p[-1], order + PLY_TYPES[p[0]]) for p in props])
        rows = np.frombuffer(data, dtype=dtype, count=count, offset=pos)
        return {p[-1]: rows[p[-1]] for p in props}, pos + dtype.itemsize * count
    out: Dict[str, List[Any]] = {p[-1]: [] for p in props}
    for _ in range(count):
        for p in props:
            if p[0] == "list":
                n_type = np.dtype(order + PLY_TYPES[p[1]])
                item = np.dtype(order + PLY_TYPES[p[2]])
                n = int(np.frombuffer(data, dtype=n_type, count=1, offset=pos)[0])
                pos += n_type.itemsize
                out[p[-1]].append(np.frombuffer(data, dtype=item, count=n, offset=pos).astype(np.int64))
                pos += item.itemsize * n
            else:
                t = np.dtype(order + PLY_TYPES[p[0]])
                out[p[-1]].append(np.frombuffer(data, dtype=t, count=1, offset=pos)[0])
                pos += t.itemsize
    return out, pos
