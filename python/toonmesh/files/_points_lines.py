"""Points and lines in files, read by toonmesh as :class:`toonmesh.Points` and
:class:`toonmesh.Lines` (trimesh reads them as point clouds and paths that draw nothing, misreads
glTF ``LINES`` indices and drops ``LINE_LOOP``, ``LINE_STRIP`` and the normals of ``POINTS``):

- PLY with vertices and no faces: points, with ``nx ny nz`` normals and ``red green blue
  [alpha]`` colours where the file has them; an ``edge`` element (``vertex1 vertex2``): lines.
- OBJ ``l`` elements (polylines) as lines, ``p`` elements as points, and an OBJ of ``v`` lines
  alone as points (``v x y z r g b`` colours, and ``vn`` normals where there is one per point).
- ``.xyz`` text: one point a row (see :func:`xyz_items`).
- glTF primitives of modes ``POINTS`` (0), ``LINES`` (1), ``LINE_LOOP`` (2), ``LINE_STRIP`` (3),
  placed by their nodes' world transforms.

Errors name the file and the 1-based line, element or glTF primitive, as the checks of
:mod:`toonmesh.files._checks` do.
"""

from __future__ import annotations

import math
import warnings
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from toonmesh import _core
from toonmesh.files import _ply
from toonmesh.files._gltf import POINTS_AND_LINES, _dense
from toonmesh.files._checks import PLY_TYPES, MeshFileError, PlyHeader, gltf_accessor
from toonmesh.scene._points import Lines, Points

Item = Union[Points, Lines]

# ------------------------------------------------------------------------------------------------
# Items, made once each, with the file's normals kept only where the core takes them


def points_item(path: str, positions: np.ndarray, normals: Optional[np.ndarray], colors: Optional[np.ndarray],
                name: str = "", where: str = "") -> Points:
    """:class:`Points` of a file's positions (finite: checked by the reader); normals with a zero
    or non-finite one are dropped with a warning (the points then get estimated ones), as a
    mesh's are."""
    if normals is not None:
        bad = ~(np.isfinite(normals).all(axis=1) & (np.abs(normals).max(axis=1) > 0))
        if bad.any():
            warnings.warn(f"{path}{where}: the file's normal of point {int(np.argmax(bad)) + 1} is zero or not "
                          "finite; the points' normals are estimated instead", stacklevel=3)
            normals = None
    return Points(positions, normals, colors, name=name)


def lines_item(positions: np.ndarray, segments: np.ndarray, name: str = "") -> Lines:
    """:class:`Lines` of the positions the segments use (the others left out), renumbered."""
    used, inverse = np.unique(segments.reshape(-1), return_inverse=True)
    return Lines(positions[used], inverse.reshape(-1, 2).astype(np.int64), name=name)


def _colour_codes(rgb: np.ndarray, integer: bool) -> np.ndarray:
    """Colour values as :class:`Points` takes them: uint8 codes where the file writes integers
    0 to 255, 16-bit codes scaled to [0, 1], floats in [0, 1] as they are, and floats above 1
    read as 0 to 255 codes; values that are not numbers are drawn black (as trimesh draws a
    mesh's)."""
    rgb = np.where(np.isfinite(rgb), rgb, 0.0)
    if integer and rgb.min(initial=0) >= 0 and rgb.max(initial=0) <= 255:
        return rgb.astype(np.uint8)
    if integer:
        return np.clip(rgb / 65535.0, 0, 1)
    if rgb.max(initial=0) > 1:
        return np.clip(np.round(rgb), 0, 255).astype(np.uint8)
    return np.clip(rgb, 0, 1)


def _first_not_finite(path: str, values: np.ndarray, what: str) -> None:
    bad = ~np.isfinite(values).all(axis=1)
    if bad.any():
        i = int(np.argmax(bad))
        raise MeshFileError(f"{path}: {what} {i + 1} is not finite: {values[i].tolist()}")


# ------------------------------------------------------------------------------------------------
# PLY


def ply_drawn_as_points(header: PlyHeader) -> bool:
    """Whether a PLY holds no faces (none declared, or 0) and no triangle strips: its vertices
    are points (and its edges lines)."""
    return not any(name in ("face", "tristrips") and count > 0 for name, count, _ in header.elements)


def ply_has_edges(header: PlyHeader) -> bool:
    """Whether a PLY declares edges (an ``edge`` element of 1 or more)."""
    return any(name == "edge" and count > 0 for name, count, _ in header.elements)


def ply_items(path: str, header: PlyHeader, data: bytes, points: bool = True) -> List[Item]:
    """The lines (``edge`` elements, ``vertex1 vertex2``) of a PLY, and, where it has none and
    ``points`` (a PLY without faces), its vertices as points."""
    counts = {name: count for name, count, _ in header.elements}
    if not counts.get("edge") and not (points and counts.get("vertex")):
        return []
    found = _ply.values(path, header, data)
    vertex = found.get("vertex", {})
    if not all(k in vertex for k in "xyz"):
        raise MeshFileError(f"{path}: the vertex element has no x, y, z properties")
    V = np.stack([np.asarray(vertex[k], dtype=np.float64) for k in "xyz"], axis=1)
    _first_not_finite(path, V, "vertex")
    kinds = {p[-1]: p[0] for name, _, props in header.elements if name == "vertex" for p in props}
    items: List[Item] = []
    edge = found.get("edge")
    if edge is not None and counts.get("edge"):
        if "vertex1" not in edge or "vertex2" not in edge:
            raise MeshFileError(f"{path}: the edge element has no vertex1, vertex2 properties")
        segments = np.stack([np.asarray(edge["vertex1"]), np.asarray(edge["vertex2"])], axis=1).astype(np.int64)
        bad = ((segments < 0) | (segments >= len(V))).any(axis=1)
        if bad.any():
            i = int(np.argmax(bad))
            raise MeshFileError(f"{path}: edge {i + 1} names a vertex outside the {len(V):,} vertices: "
                                f"{segments[i].tolist()}")
        items.append(lines_item(V, segments))
        return items  # the vertices are the lines' ends, not points of their own
    if not len(V) or not points:
        return items
    normals = None
    if all(k in vertex for k in ("nx", "ny", "nz")):
        normals = np.stack([np.asarray(vertex[k], dtype=np.float64) for k in ("nx", "ny", "nz")], axis=1)
    colors = None
    names = [k for k in _ply.COLOUR_PROPERTIES if k in vertex]
    if all(k in vertex for k in ("red", "green", "blue")):
        integer = all(not PLY_TYPES[kinds[k]].startswith("f") for k in names)
        colors = _colour_codes(np.stack([np.asarray(vertex[k], dtype=np.float64) for k in names], axis=1), integer)
    items.append(points_item(path, V, normals, colors))
    return items


# ------------------------------------------------------------------------------------------------
# OBJ


def obj_has_points_or_lines(data: bytes) -> bool:
    """Whether an OBJ's text has ``l`` or ``p`` statements."""
    return any(data.startswith(k) or b"\n" + k in data for k in (b"l ", b"p ", b"l\t", b"p\t"))


def obj_items(path: str, data: bytes, faces: int) -> List[Item]:
    """The lines (``l`` elements: a polyline each, ``l 1 2 3`` two segments) and points (``p``
    elements) of an OBJ; an OBJ with neither, and no faces (``faces``: their count), has its
    vertices as points, with ``v x y z r g b`` colours where every vertex has them and ``vn``
    normals where there is one per vertex. Indices are 1-based, negative ones counted back
    from the vertices listed before the element. ``data``: the text, statements continued over
    lines joined (:func:`toonmesh.files._checks.join_continued`)."""
    rows: List[List[bytes]] = []
    normals: List[List[bytes]] = []
    strokes: List[Tuple[int, List[int]]] = []  # (line, 0-based indices or negative counts back)
    dots: List[Tuple[int, List[int]]] = []
    for number, raw in enumerate(data.split(b"\n"), start=1):
        words = (raw.split(b"#", 1)[0] if b"#" in raw else raw).split()
        if not words:
            continue
        head = words[0]
        if head == b"v":
            rows.append(words[1:])
        elif head == b"vn":
            normals.append(words[1:4])
        elif head in (b"l", b"p"):
            least = 2 if head == b"l" else 1
            if len(words) - 1 < least:
                what = "a line element needs 2 or more points" if head == b"l" else "a point element needs a vertex"
                raise MeshFileError(f"{path}: line {number}: {what}, got {len(words) - 1}")
            try:
                ints = [int(w.split(b"/")[0]) for w in words[1:]]
            except ValueError:
                raise MeshFileError(f"{path}: line {number}: not an index in "
                                    f"{raw.strip()[:60].decode('utf-8', 'replace')!r}") from None
            listed = len(rows)
            indices = []
            for i in ints:
                if i == 0 or i < -listed:
                    raise MeshFileError(f"{path}: line {number}: {'line' if head == b'l' else 'point'} index {i} "
                                        f"points past the {listed} vertices listed before it")
                indices.append(i - 1 if i > 0 else listed + i)
            (strokes if head == b"l" else dots).append((number, indices))
    n = len(rows)
    for number, indices in strokes + dots:
        past = [i for i in indices if i >= n]
        if past:
            raise MeshFileError(f"{path}: line {number}: index {past[0] + 1} points past the {n} vertices in the file")
    if not strokes and not dots and (faces or not n):
        return []
    V = np.array([[float(w) for w in r[:3]] for r in rows], dtype=np.float64).reshape(-1, 3)  # checked: finite
    items: List[Item] = []
    if strokes:
        segments = np.concatenate([np.stack([s[:-1], s[1:]], axis=1) for s in (np.array(i) for _, i in strokes)])
        items.append(lines_item(V, segments.astype(np.int64)))
    if dots or not (faces or strokes):
        chosen = np.unique(np.concatenate([np.array(i, np.int64) for _, i in dots])) if dots else np.arange(n)
        colors = None
        if rows and all(len(r) >= 6 for r in rows):
            try:
                rgb = np.array([[float(w) for w in r[3:6]] for r in rows], dtype=np.float64)
                colors = _colour_codes(rgb, False)[chosen]
            except ValueError:
                colors = None  # not numbers: noted by the checks, not drawn
        N = None
        if len(normals) == n and all(len(w) == 3 for w in normals):
            try:
                N = np.array([[float(w) for w in r] for r in normals], dtype=np.float64)[chosen]
            except ValueError:
                N = None
        items.append(points_item(path, V[chosen], N, colors))
    return items


# ------------------------------------------------------------------------------------------------
# XYZ


def xyz_items(path: str, data: bytes) -> List[Item]:
    """The points of an ``.xyz`` text file: one point a row of numbers separated by blanks or
    commas; blank lines and lines starting with ``#`` (or ``//``) skipped. Every row has as many
    numbers, read by their count: 3 ``x y z``; 4 ``x y z`` and a value not drawn (intensity);
    6 ``x y z nx ny nz`` where every row's last three are a unit vector (within 1%), else
    ``x y z r g b``; 7 ``x y z r g b a``; 9 ``x y z nx ny nz r g b``; 10 ``x y z nx ny nz r g b
    a``. Colours are floats in [0, 1] where none is above 1, else 0 to 255 codes."""
    values = _xyz_at_once(data)
    lines: Optional[np.ndarray] = None
    if values is None:
        values, lines = _xyz_by_line(path, data)
    if not len(values):
        return []
    width = values.shape[1]
    if width not in (3, 4, 6, 7, 9, 10):
        first = 1 if lines is None else int(lines[0])
        raise MeshFileError(f"{path}: line {first}: {width} numbers a row; an .xyz row has 3 (x y z), 4 (and "
                            "intensity), 6 (and normals or r g b), 7 (and r g b a), 9 or 10 (normals and colours)")
    bad = ~np.isfinite(values[:, :3]).all(axis=1)
    if bad.any():
        i = int(np.argmax(bad))
        if lines is None:
            lines = _xyz_by_line(path, data)[1]
        raise MeshFileError(f"{path}: line {lines[i]}: point {i + 1} is not finite: {values[i, :3].tolist()}")
    normals = colors = None
    if width == 6:
        unit = np.abs(np.linalg.norm(values[:, 3:6], axis=1) - 1) <= 0.01
        if unit.all():
            normals = values[:, 3:6]
        else:
            colors = values[:, 3:6]
    elif width == 7:
        colors = values[:, 3:7]
    elif width >= 9:
        normals, colors = values[:, 3:6], values[:, 6:]
    if colors is not None:
        colors = _colour_codes(colors, False)
    return [points_item(path, values[:, :3], normals, colors)]


#: The bytes that separate an .xyz row's numbers: blanks and commas.
_SEPARATORS = np.zeros(256, bool)
_SEPARATORS[list(b" \t\r\x0b\x0c,")] = True


def _xyz_at_once(data: bytes) -> Optional[np.ndarray]:
    """An .xyz file's (rows, numbers) float64 values, parsed by NumPy in one call, for a file
    without comments whose rows all have as many numbers; None for any other (the line scan
    then reads it and names the line that is wrong)."""
    if b"#" in data or b"//" in data:
        return None
    raw = np.frombuffer(data, np.uint8)
    newline = raw == ord("\n")
    gap = _SEPARATORS[raw] | newline
    starts = np.flatnonzero(~gap & np.concatenate([[True], gap[:-1]]))  # each number's first byte
    per_line = np.bincount(np.cumsum(newline)[starts], minlength=1) if len(starts) else np.zeros(0, np.int64)
    widths = per_line[per_line > 0]
    if not len(widths):
        return np.zeros((0, 3))
    if np.any(widths != widths[0]):
        return None
    text = np.where(_SEPARATORS[raw], ord(" "), raw).astype(np.uint8).tobytes()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # NumPy warns (later raises) where a word is not a number
            values = np.fromstring(text, dtype=np.float64, sep=" ")
    except (ValueError, DeprecationWarning):
        return None
    if len(values) != int(widths.sum()):
        return None
    return values.reshape(len(widths), int(widths[0]))


def _xyz_by_line(path: str, data: bytes) -> Tuple[np.ndarray, np.ndarray]:
    """An .xyz file's values and the 1-based line of each row, read a line at a time; the
    first row that is wrong is named by its line."""
    rows: List[List[bytes]] = []
    lines: List[int] = []
    for number, raw in enumerate(data.split(b"\n"), start=1):
        text = raw.strip()
        if not text or text.startswith((b"#", b"//")):
            continue
        words = text.replace(b",", b" ").split()
        if rows and len(words) != len(rows[0]):
            raise MeshFileError(f"{path}: line {number}: {len(words)} numbers, but the rows before have "
                                f"{len(rows[0])}")
        for w in words:
            try:
                float(w)
            except ValueError:
                raise MeshFileError(f"{path}: line {number}: not a number: "
                                    f"{w[:30].decode('utf-8', 'replace')!r}") from None
        rows.append(words)
        lines.append(number)
    if not rows:
        return np.zeros((0, 3)), np.zeros(0, np.int64)
    return np.array([[float(w) for w in r] for r in rows], dtype=np.float64), np.array(lines)


# ------------------------------------------------------------------------------------------------
# glTF

POINTS, LINES, LINE_LOOP, LINE_STRIP = READ_HERE = POINTS_AND_LINES
_MODE_NAMES = {POINTS: "POINTS", LINES: "LINES", LINE_LOOP: "LINE_LOOP", LINE_STRIP: "LINE_STRIP"}
#: Normalised integer colours: their largest code.
_NORMALISED = {5121: 255.0, 5123: 65535.0}


def gltf_has_triangles(doc: Dict[str, Any]) -> bool:
    """Whether a glTF has a primitive of triangles (a mode other than those read here)."""
    return any(p.get("mode", 4) not in READ_HERE for m in doc.get("meshes") or [] for p in m.get("primitives") or [])


def gltf_items(path: str, doc: Dict[str, Any], data: bytes) -> List[Item]:
    """Every placed glTF primitive of points or lines, with its node's world transform (a mesh
    placed by several nodes gives an item per node, sharing their arrays): ``POINTS`` as
    :class:`Points` (``NORMAL`` and ``COLOR_0`` where given), ``LINES`` (index pairs),
    ``LINE_STRIP`` (a polyline) and ``LINE_LOOP`` (closed) as :class:`Lines`; ``indices`` where
    given, else the vertices in order. ``data``: the file's bytes."""
    meshes = doc.get("meshes") or []
    wanted = {m for m, mesh in enumerate(meshes)
              if any(p.get("mode", 4) in READ_HERE for p in mesh.get("primitives") or [])}
    if not wanted:
        return []
    buffers: Dict[int, Optional[bytes]] = {-1: data}
    made: Dict[int, List[Item]] = {}
    out: List[Item] = []
    for node, world in node_transforms(doc):
        m = (doc["nodes"][node]).get("mesh")
        if m not in wanted:
            continue
        if m not in made:
            made[m] = [_primitive(path, doc, m, p, buffers) for p, primitive in enumerate(meshes[m]["primitives"])
                       if primitive.get("mode", 4) in READ_HERE]
        for item in made[m]:
            if item is None:
                continue
            placed = _placed_copy(item)
            placed.transform = _core._transform(world)
            out.append(placed)
    return out


def _placed_copy(item: Item) -> Item:
    """A shallow copy of an item (its arrays shared), for another node to place."""
    new = object.__new__(type(item))
    new.__dict__.update(item.__dict__)
    return new


def _primitive(path: str, doc: Dict[str, Any], m: int, p: int, buffers: Dict[int, Optional[bytes]]) -> Any:
    """The item of primitive ``p`` of mesh ``m`` (None for one without vertices)."""
    mesh = doc["meshes"][m]
    primitive = mesh["primitives"][p]
    mode = primitive.get("mode", 4)
    name = mesh.get("name") or ""
    where = f"mesh {m}{f' ({name})' if name else ''} primitive {p} ({_MODE_NAMES[mode]})"
    attributes = primitive.get("attributes") or {}

    def read(index: Any, what: str) -> np.ndarray:
        accessor = doc["accessors"][index]
        values = _dense(path, doc, index, buffers) if "sparse" in accessor else gltf_accessor(path, doc, index, buffers)
        if values is None:
            raise MeshFileError(f"{path}: {where}: its {what} (accessor {index}) cannot be read: component type "
                                f"{accessor.get('componentType')} is not one of float or unsigned integer")
        if what == "colours" and accessor.get("componentType") in _NORMALISED:
            return values.astype(np.float64) / _NORMALISED[accessor["componentType"]]
        return values.astype(np.float64)

    if "POSITION" not in attributes:
        raise MeshFileError(f"{path}: {where}: no POSITION attribute")
    V = read(attributes["POSITION"], "positions")
    if V.shape[1] != 3:
        raise MeshFileError(f"{path}: {where}: POSITION is not VEC3")
    bad = ~np.isfinite(V).all(axis=1)
    if bad.any():
        i = int(np.argmax(bad))
        raise MeshFileError(f"{path}: {where}: vertex {i + 1} is not finite: {V[i].tolist()}")
    if "indices" in primitive:
        order = read(primitive["indices"], "indices").reshape(-1).astype(np.int64)
        past = np.flatnonzero(order >= len(V))
        if len(past):
            raise MeshFileError(f"{path}: {where}: index {past[0] + 1} ({order[past[0]]}) points past the "
                                f"{len(V):,} vertices")
    else:
        order = np.arange(len(V), dtype=np.int64)
    if mode == POINTS:
        if not len(order):
            return None
        chosen = np.unique(order) if "indices" in primitive else order
        normals = read(attributes["NORMAL"], "normals")[chosen] if "NORMAL" in attributes else None
        colors = None
        if "COLOR_0" in attributes:
            colors = np.clip(np.nan_to_num(read(attributes["COLOR_0"], "colours")), 0, 1)[chosen]
            # taken as the codes they are, as a mesh's vertex colours are
            colors = np.ascontiguousarray(colors) if colors.shape[1] in (3, 4) else None
        base = _base_colour(doc, primitive)
        if base is not None:  # multiplies the points' colours, as a mesh's base colour does
            colors = np.ones((len(chosen), 3)) if colors is None else colors
            colors[:, :3] *= base
        return points_item(path, V[chosen], normals, colors, name, f" ({where})")
    if mode == LINES:
        if len(order) % 2:
            raise MeshFileError(f"{path}: {where}: LINES takes pairs of vertices, got {len(order):,}")
        segments = order.reshape(-1, 2)
    else:
        if len(order) == 1:
            raise MeshFileError(f"{path}: {where}: a line needs 2 or more vertices, got 1")
        ends = np.append(order, order[0]) if mode == LINE_LOOP and len(order) > 2 else order
        segments = np.stack([ends[:-1], ends[1:]], axis=1)
    if not len(segments):
        return None
    lines = lines_item(V, segments, name)
    base = _base_colour(doc, primitive)
    if base is not None:  # the material's colour is the ink's
        lines.color = tuple(float(c) for c in base)
    return lines


def _base_colour(doc: Dict[str, Any], primitive: Dict[str, Any]) -> Optional[np.ndarray]:
    """The sRGB (3,) colour of a primitive's material (its ``baseColorFactor``, linear light, as
    drawn), or None where it names none."""
    try:
        factor = doc["materials"][primitive["material"]]["pbrMetallicRoughness"]["baseColorFactor"]
    except (LookupError, TypeError):
        return None
    rgb = np.clip(np.asarray(factor, dtype=np.float64)[:3], 0, 1)
    return np.clip(_core._srgb_from_linear(np.ascontiguousarray(rgb)).reshape(3), 0, 1)


def node_transforms(doc: Dict[str, Any]) -> List[Tuple[int, np.ndarray]]:
    """(node, world transform (4, 4) float64) of every node the glTF's scene places (its
    default scene, or the first; a file without scenes: every root node), parents before
    children; a node reached twice (a cycle) is placed once."""
    nodes = doc.get("nodes") or []
    scenes = doc.get("scenes") or []
    if scenes:
        roots = list(scenes[doc.get("scene", 0)].get("nodes") or [])
    else:
        children = {c for n in nodes for c in n.get("children") or []}
        roots = [i for i in range(len(nodes)) if i not in children]
    out: List[Tuple[int, np.ndarray]] = []
    seen = set()
    stack = [(i, np.eye(4)) for i in reversed(roots)]
    while stack:
        i, parent = stack.pop()
        if i in seen:
            continue
        seen.add(i)
        world = parent @ _local(nodes[i])
        out.append((i, world))
        stack.extend((c, world) for c in reversed(nodes[i].get("children") or []))
    return out


def _local(node: Dict[str, Any]) -> np.ndarray:
    """A node's transform in its parent's frame: its ``matrix`` (column-major), or translation
    times rotation (a unit quaternion x, y, z, w) times scale."""
    if "matrix" in node:
        return np.array(node["matrix"], dtype=np.float64).reshape(4, 4).T
    x, y, z, w = (float(v) for v in node.get("rotation", (0, 0, 0, 1)))
    norm = math.sqrt(x * x + y * y + z * z + w * w) or 1.0
    x, y, z, w = x / norm, y / norm, z / norm, w / norm
    out = np.eye(4)
    out[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                   [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                   [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    out[:3, :3] *= np.array(node.get("scale", (1, 1, 1)), dtype=np.float64)
    out[:3, 3] = node.get("translation", (0, 0, 0))
    return out
