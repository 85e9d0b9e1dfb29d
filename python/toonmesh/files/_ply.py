"""PLY files read by toonmesh where trimesh falls short: triangle strips (``element tristrips``),
which trimesh reads as points (ASCII) or refuses (binary), read here, ASCII and binary, and their
strips turned into triangles; and float colours, checked here for values that are not numbers
(trimesh draws them black)."""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from toonmesh.files._checks import PLY_TYPES, MeshFileError, PlyHeader, strip_triangles


def has_strips(header: PlyHeader) -> bool:
    """Whether a PLY file's header declares a ``tristrips`` element."""
    return any(name == "tristrips" for name, _, _ in header.elements)


def read(path: str, header: PlyHeader, data: bytes) -> Tuple[np.ndarray, np.ndarray, Optional[np.ndarray]]:
    """(V (N, 3) float64, F (M, 3) int64, vertex colours (N, 4) uint8 or None) of a PLY whose
    faces are triangle strips (see :func:`toonmesh.files._checks.strip_triangles`)."""
    found = values(path, header, data)
    vertex = found.get("vertex", {})
    if not all(k in vertex for k in "xyz"):
        raise MeshFileError(f"{path}: no x, y, z vertex properties")
    V = np.stack([np.asarray(vertex[k], dtype=np.float64) for k in "xyz"], axis=1)
    strips = found["tristrips"].get("vertex_indices")
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


#: The colour properties trimesh reads from a PLY element.
COLOUR_PROPERTIES = ("red", "green", "blue", "alpha")


def colour_notes(path: str, header: PlyHeader, data: bytes) -> List[str]:
    """A note per element (vertex, face) whose float colours hold values that are not numbers
    (trimesh turns them into black, silently); the file is read only when its header declares
    float colours."""
    floats = [name for name, _, props in header.elements if any(
        p[-1] in COLOUR_PROPERTIES and p[0] != "list" and PLY_TYPES[p[0]].startswith("f") for p in props)]
    if not floats:
        return []
    try:
        found = values(path, header, data)
    except MeshFileError:
        return []  # trimesh says what is wrong
    notes = []
    for name in floats:
        columns = [np.asarray(found[name][k], dtype=np.float64) for k in COLOUR_PROPERTIES if k in found[name]]
        bad = np.flatnonzero(~np.isfinite(np.stack(columns, axis=1)).all(axis=1))
        if len(bad):
            notes.append(f"{len(bad):,} {name} colours are not numbers (the first of {name} {bad[0] + 1}): drawn black")
    return notes


def values(path: str, header: PlyHeader, data: bytes) -> Dict[str, Dict[str, Any]]:
    """Every element's properties by name, ASCII or binary (``data``: the file's bytes)."""
    fmt, elements = header.format, header.elements
    data = data[header.size :]
    order = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
    words = data.split() if order is None else []
    pos = 0
    values: Dict[str, Dict[str, Any]] = {}
    try:
        for name, count, props in elements:
            if order is None:
                values[name], pos = _ascii_element(words, pos, count, props)
            else:
                values[name], pos = _binary_element(data, pos, order, count, props)
    except (StopIteration, ValueError, IndexError):
        raise MeshFileError(f"{path}: the '{name}' elements are cut off or malformed") from None
    return values


def _ascii_element(words: List[bytes], pos: int, count: int,
                   props: List[Tuple[str, ...]]) -> Tuple[Dict[str, Any], int]:
    """The element's values from ``words[pos:]``, and where the next element starts: numbers
    converted by NumPy a block at a time, as ``float()`` and ``int()`` read them (list counts
    and items are integers); an element of fixed rows as float64 arrays, one per property."""
    if all(p[0] != "list" for p in props):  # fixed rows: one block
        block = words[pos : pos + count * len(props)]
        if len(block) < count * len(props):
            raise ValueError("cut off")
        rows = np.array(block or [b"0"]).astype(np.float64)[: len(block)].reshape(count, len(props))
        return {p[-1]: rows[:, i] for i, p in enumerate(props)}, pos + len(block)
    out: Dict[str, List[Any]] = {p[-1]: [] for p in props}
    for _ in range(count):
        for p in props:
            if pos >= len(words):
                raise ValueError("cut off")
            if p[0] == "list":
                n = max(int(words[pos]), 0)
                items = words[pos + 1 : pos + 1 + n]
                if len(items) < n:
                    raise ValueError("cut off")
                out[p[-1]].append(np.array(items or [b"0"]).astype(np.int64)[:n])
                pos += 1 + n
            else:
                out[p[-1]].append(float(words[pos]))
                pos += 1
    return out, pos


def _binary_element(data: bytes, pos: int, order: str, count: int,
                    props: List[Tuple[str, ...]]) -> Tuple[Dict[str, Any], int]:
    if all(p[0] != "list" for p in props):  # fixed rows: one structured array
        dtype = np.dtype([(p[-1], order + PLY_TYPES[p[0]]) for p in props])
        rows = np.frombuffer(data, dtype=dtype, count=count, offset=pos)
        return {p[-1]: rows[p[-1]] for p in props}, pos + dtype.itemsize * count
    if len(props) == 1 and count:  # one list a row (strips): one array where every row is as long
        n_type = np.dtype(order + PLY_TYPES[props[0][1]])
        item = np.dtype(order + PLY_TYPES[props[0][2]])
        if pos + n_type.itemsize <= len(data):
            n = int(np.frombuffer(data, dtype=n_type, count=1, offset=pos)[0])
            row = np.dtype([("n", n_type), ("items", item, (max(n, 0),))])
            if n >= 0 and pos + row.itemsize * count <= len(data):
                rows = np.frombuffer(data, dtype=row, count=count, offset=pos)
                if np.all(rows["n"] == n):
                    return {props[0][-1]: rows["items"].astype(np.int64)}, pos + row.itemsize * count
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
