"""Meshes shipped with toonmesh, for demos and examples."""

from __future__ import annotations

import gzip
import os
from typing import List, Tuple

import numpy as np

_HERE = os.path.dirname(os.path.abspath(__file__))

#: Meshes shipped with toonmesh, by name: the command line takes these names for files.
PACKAGED = ("bunny",)


def packaged(name: str) -> "str | None":
    """The path of the shipped mesh called ``name`` ("bunny"), or None."""
    return os.path.join(_HERE, name + ".obj") if name in PACKAGED else None


def load_obj(path: "str | os.PathLike[str]") -> Tuple[np.ndarray, np.ndarray]:
    """Reads the vertices and faces of a Wavefront OBJ file.

    Args:
        path: the OBJ file (str, bytes or os.PathLike).

    Returns:
        (V, F): (N, 3) float64 positions and (M, 3) int64 triangles (polygons are split into
        fans; texture and normal indices are ignored; negative indices count from the end).

    Raises:
        TypeError: ``path`` is not a str, bytes or ``os.PathLike``.
        OSError: the file cannot be read (``FileNotFoundError`` when it does not exist).
        ValueError: the file is not an OBJ this reader understands, naming ``path``.
    """
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise TypeError(f"path: expected a file path (str or os.PathLike), got {type(path).__name__} {path!r}")
    with open(path, "rb") as f:
        data = f.read()
    try:
        return _parse_obj(data)
    except (ValueError, IndexError) as exc:
        raise ValueError(f"path: {os.fsdecode(path)!r} is not an OBJ mesh this reader understands ({exc})") from None


def _parse_obj(data: bytes) -> Tuple[np.ndarray, np.ndarray]:
    lines = data.split(b"\n")
    v = b" ".join(line[2:] for line in lines if line.startswith(b"v "))
    V = np.array(v.split(), dtype=np.float64).reshape(-1, 3)
    tris: List[List[int]] = []
    face_lines = [line[2:].split() for line in lines if line.startswith(b"f ")]
    if all(len(t) == 3 and b"/" not in b"".join(t) for t in face_lines):
        F = np.array(b" ".join(b" ".join(t) for t in face_lines).split(), dtype=np.int64).reshape(-1, 3)
    else:
        for t in face_lines:
            idx = [int(x.split(b"/")[0]) for x in t]
            tris.extend([idx[0], idx[k], idx[k + 1]] for k in range(1, len(idx) - 1))
        F = np.array(tris, dtype=np.int64).reshape(-1, 3)
    F = np.where(F < 0, F + len(V), F - 1)
    return V, F


def bunny() -> Tuple[np.ndarray, np.ndarray]:
    """The Stanford bunny (Stanford 3D Scanning Repository): 35,947 vertices, 69,451 faces.

    (V, F) as float64 (N, 3) and int64 (M, 3); y is up. About 1,100 vertices are used by no face.
    """
    return load_obj(os.path.join(_HERE, "bunny.obj"))


def _load_gzipped(name: str) -> Tuple[np.ndarray, np.ndarray]:
    """A shipped OBJ kept gzip-compressed (``<name>.obj.gz``), parsed like :func:`load_obj`."""
    with gzip.open(os.path.join(_HERE, name + ".obj.gz"), "rb") as f:
        return _parse_obj(f.read())


def fandisk() -> Tuple[np.ndarray, np.ndarray]:
    """The fandisk CAD part (Hoppe et al. 1994): 6,475 vertices, 12,946 faces.

    (V, F) as float64 (N, 3) and int64 (M, 3); y is up, about 5 units across. Flat faces meet at
    sharp creases, the case for crease lines, ``normals="auto"`` and crease-keeping denoising.
    """
    return _load_gzipped("fandisk")


def cow() -> Tuple[np.ndarray, np.ndarray]:
    """The cow (Viewpoint), as in Princeton's suggestive-contours models: 2,903 vertices, 5,804 faces.

    (V, F) as float64 (N, 3) and int64 (M, 3); y is up, about 10 units long along x. Closed and smooth,
    the case for contours and suggestive contours.
    """
    return _load_gzipped("cow")
