"""Checks of mesh files that trimesh does not make, before it reads them.

trimesh drops an OBJ face whose indices point past the vertices, reads an OBJ cut off mid-line as
if it ended there, and allocates what a PLY header claims before finding the data missing. These
pre-scans refuse such files with the file's name, the line or element, and what is wrong, so a
broken file never renders with holes and exit status 0.
"""

from __future__ import annotations

import json
import math
import os
import struct
import warnings
from typing import Any, Dict, List, Optional, Tuple

import numpy as np


class MeshFileError(ValueError):
    """A mesh file that cannot be read as it claims to be; the message names the file."""


# ------------------------------------------------------------------------------------------------
# OBJ


def check_obj(path: str) -> Dict[str, Any]:
    """Scans an OBJ's statements: every face has 3+ corners whose position, texture and normal
    indices (1-based, or negative from the end of those listed so far) name existing entries, and
    every ``v`` has 3 finite coordinates. Returns counts: ``vertices``, ``texcoords``, ``faces``
    ``normals``, ``materials`` (distinct ``usemtl`` names) and ``libraries`` (``mtllib``
    statements). Raises :class:`MeshFileError` naming the 1-based
    line."""
    with open(path, "rb") as f:
        data = f.read()
    counts = _obj_counts_at_once(data)
    return counts if counts is not None else _check_obj_by_line(path, data)


def _check_obj_by_line(path: str, data: bytes) -> Dict[str, Any]:
    """:func:`check_obj` one line at a time: the rule itself, and the messages that name where
    a file breaks it."""
    counts = {b"v": 0, b"vt": 0, b"vn": 0}
    faces = 0
    materials = set()  # the names 'usemtl' switches to
    libraries = 0
    kinds = (b"v", b"vt", b"vn")
    largest = {k: (0, 0) for k in kinds}  # the largest positive index of each kind, and its line
    lines = data.split(b"\n")
    for number, raw in enumerate(lines, start=1):
        words = (raw.split(b"#", 1)[0] if b"#" in raw else raw).split()
        if not words:
            continue
        head = words[0]
        if head == b"v":
            if len(words) < 4:
                raise MeshFileError(_obj_where(path, number, lines, f"a vertex needs 3 coordinates, got {len(words) - 1}"))
            try:
                x, y, z = float(words[1]), float(words[2]), float(words[3])
            except ValueError:
                raise MeshFileError(_obj_where(path, number, lines, f"not a number in {raw.strip()[:60]!r}")) from None
            counts[b"v"] += 1
            if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(z)):
                raise MeshFileError(f"{path}: vertex {counts[b'v']} (line {number}) is not finite: {[x, y, z]}")
        elif head == b"f":
            if len(words) < 4:
                raise MeshFileError(_obj_where(path, number, lines, f"a face needs 3 or more corners, got {len(words) - 1}"))
            # one list of indices per kind: v, or v/vt, v//vn, v/vt/vn
            columns = [words[1:]] if b"/" not in raw else list(zip(*(c.split(b"/") for c in words[1:])))
            for kind, texts in zip(kinds, columns):
                try:
                    ints = [int(t) for t in texts if t]
                except ValueError:
                    raise MeshFileError(_obj_where(path, number, lines, f"not an index in {raw.strip()[:60]!r}")) from None
                if not ints:
                    continue
                lo, hi, n = min(ints), max(ints), counts[kind]
                if lo < -n or 0 in ints:  # negative: counted back from the entries so far
                    i = 0 if 0 in ints else lo
                    raise MeshFileError(f"{path}: line {number}: face index {i} points past the {n} "
                                        f"{_NAMES[kind]} listed before it")
                if hi > largest[kind][0]:
                    largest[kind] = (hi, number)
            faces += 1
        elif head == b"vt" or head == b"vn":
            counts[head] += 1
        elif head == b"usemtl":
            materials.add(b" ".join(words[1:]))
        elif head == b"mtllib":
            libraries += 1
    for kind, (i, number) in largest.items():
        if i > counts[kind]:
            raise MeshFileError(f"{path}: line {number}: face index {i} points past the {counts[kind]} "
                                f"{_NAMES[kind]} in the file")
    return {"vertices": counts[b"v"], "texcoords": counts[b"vt"], "normals": counts[b"vn"], "faces": faces,
            "materials": len(materials), "libraries": libraries}


_NAMES = {b"v": "vertices", b"vt": "texture coordinates", b"vn": "normals"}

#: The bytes that ``bytes.split()`` splits at.
_BLANK = np.zeros(256, bool)
_BLANK[list(b" \t\n\r\x0b\x0c")] = True


def _obj_counts_at_once(data: bytes) -> Optional[Dict[str, Any]]:
    """:func:`check_obj`'s counts of a file that keeps its rules, found with whole-file array
    operations instead of a Python loop over lines; None where the file breaks a rule or is
    written in a way this does not follow (a comment after a statement, faces whose corners are
    written in different ways), so that the line-by-line scan decides and names the line."""
    raw = np.frombuffer(data, np.uint8)
    if not len(raw):
        return None
    blank = _BLANK[raw]
    newlines = np.flatnonzero(raw == ord("\n"))
    line_of = lambda at: np.searchsorted(newlines, at)  # noqa: E731
    # a line's bytes, its newline first (blank), for picking whole lines
    line_bytes = np.diff(np.concatenate([[0], newlines, [len(raw)]]))
    n_lines = len(newlines) + 1
    # the words (as data.split() finds them), the line of each, and each line's first word
    word_starts = np.flatnonzero(~blank & np.concatenate([[True], blank[:-1]]))
    per_line = np.bincount(line_of(word_starts), minlength=n_lines)
    first_word = np.concatenate([[0], np.cumsum(per_line)[:-1]])
    spoken = np.flatnonzero(per_line)
    head = word_starts[first_word[spoken]]
    padded = np.concatenate([raw, np.full(3, ord(" "), np.uint8)])
    c0, c1, c2 = padded[head], padded[head + 1], padded[head + 2]
    hashes = np.flatnonzero(raw == ord("#"))
    if len(hashes) and np.any(c0[np.searchsorted(spoken, line_of(hashes))] != ord("#")):
        return None  # a comment after a statement: the line scan cuts it off
    one_letter = lambda c: (c0 == ord(c)) & _BLANK[c1]  # noqa: E731
    two_letters = lambda c: (c0 == ord(c[0])) & (c1 == ord(c[1])) & _BLANK[c2]  # noqa: E731
    listed = {b"v": spoken[one_letter("v")], b"vt": spoken[two_letters("vt")], b"vn": spoken[two_letters("vn")]}
    faces = spoken[one_letter("f")]
    # vertices: 3 finite coordinates each (any more, a colour, are numbers too)
    v = listed[b"v"]
    numbers = per_line[v] - 1
    if np.any(numbers < 3):
        return None
    xyz = _numbers_of_lines(raw, line_bytes, v, word_starts[first_word[v]], float, numbers)
    if xyz is None or not np.all(np.isfinite(xyz[(np.cumsum(numbers) - numbers)[:, None] + np.arange(3)])):
        return None
    # faces: 3 or more corners, all written one way (v, v/vt, v//vn or v/vt/vn)
    corners = per_line[faces] - 1
    if np.any(corners < 3):
        return None
    if len(faces):
        on_face = np.zeros(n_lines, bool)
        on_face[faces] = True
        at_slash = np.flatnonzero(raw == ord("/"))
        at_slash = at_slash[on_face[line_of(at_slash)]]
        per_word = np.bincount(np.searchsorted(word_starts, at_slash, side="right") - 1, minlength=len(word_starts))
        corner_words = (np.repeat(first_word[faces] + 1 - np.concatenate([[0], np.cumsum(corners)[:-1]]), corners)
                        + np.arange(corners.sum()))
        slashes = per_word[corner_words]
        doubled = int(np.count_nonzero(np.diff(at_slash) == 1))  # "v//vn": no texture coordinate
        if np.any(slashes != slashes[0]) or slashes[0] > 2 or doubled not in (0, len(slashes)):
            return None
        columns = [b"v", b"vn"] if doubled else [b"v", b"vt", b"vn"][: int(slashes[0]) + 1]
        index = _numbers_of_lines(raw, line_bytes, faces, word_starts[first_word[faces]], np.int64,
                                  corners * len(columns), at_slash)
        if index is None:
            return None
        index = index.reshape(-1, len(columns))
        face_of = np.repeat(faces, corners)
        for column, name in enumerate(columns):
            so_far = np.zeros(n_lines, np.int64)
            so_far[listed[name]] = 1
            before = np.cumsum(so_far)[face_of]  # negative indices count back from these
            i = index[:, column]
            if np.any(i == 0) or np.any(i < -before) or i.max() > len(listed[name]):
                return None
    # materials and libraries: a few lines, read as the line scan reads them
    bounds = np.concatenate([[-1], newlines, [len(data)]])
    materials = set()
    libraries = 0
    for number in spoken[(c0 == ord("u")) | (c0 == ord("m"))]:
        words = data[bounds[number] + 1 : bounds[number + 1]].split()
        if words[0] == b"usemtl":
            materials.add(b" ".join(words[1:]))
        elif words[0] == b"mtllib":
            libraries += 1
    return {"vertices": len(v), "texcoords": len(listed[b"vt"]), "normals": len(listed[b"vn"]),
            "faces": len(faces), "materials": len(materials), "libraries": libraries}


def _numbers_of_lines(raw: np.ndarray, line_bytes: np.ndarray, lines: np.ndarray, keywords: np.ndarray, dtype: Any,
                      expected: np.ndarray, also_blank: Optional[np.ndarray] = None) -> Optional[np.ndarray]:
    """The numbers written on ``lines`` (of ``line_bytes`` bytes each) after their one-letter
    keywords (at ``keywords``), one after another, parsed by NumPy in one call (``also_blank``
    marks more separators: a face's slashes); None unless every word parses, and there are as
    many as ``expected`` per line."""
    text = raw.copy()
    text[keywords] = ord(" ")
    if also_blank is not None:
        text[also_blank] = ord(" ")
    chosen = np.zeros(len(line_bytes), bool)
    chosen[lines] = True
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # NumPy warns (later raises) where a word is not a number
            out = np.fromstring(text[np.repeat(chosen, line_bytes)].tobytes(), dtype=dtype, sep=" ")
    except (ValueError, DeprecationWarning):
        return None
    return out if len(out) == int(expected.sum()) else None


def _obj_where(path: str, number: int, lines: List[bytes], problem: str) -> str:
    cut = number == len(lines) and lines[-1].strip() != b""  # the last line, with no line end
    return f"{path}: line {number}: {problem}" + (" (the file ends mid-line: cut off?)" if cut else "")


# ------------------------------------------------------------------------------------------------
# PLY

_PLY_SIZES = {
    "char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2, "int16": 2, "uint16": 2,
    "int": 4, "uint": 4, "int32": 4, "uint32": 4, "float": 4, "float32": 4, "double": 8, "float64": 8,
}
#: NumPy dtype codes of PLY's property types (byte order added by the reader).
PLY_TYPES = {
    "char": "i1", "uchar": "u1", "int8": "i1", "uint8": "u1", "short": "i2", "ushort": "u2", "int16": "i2",
    "uint16": "u2", "int": "i4", "uint": "u4", "int32": "i4", "uint32": "u4", "float": "f4", "float32": "f4",
    "double": "f8", "float64": "f8",
}


def ply_header(path: str) -> Tuple[str, List[Tuple[str, int, List[Tuple[str, ...]]]], int]:
    """(format, [(element, count, properties)], header bytes) of a PLY file; each property is
    (type, name) or ("list", count type, item type, name)."""
    with open(path, "rb") as f:
        head = f.read(65536)
    end = head.find(b"end_header")
    if not head.startswith(b"ply") or end < 0:
        raise MeshFileError(f"{path}: not a PLY file (no 'ply' ... 'end_header' header)")
    newline = head.find(b"\n", end)
    size = (newline + 1) if newline >= 0 else len(head)
    fmt = ""
    elements: List[Tuple[str, int, List[Tuple[str, ...]]]] = []
    for number, raw in enumerate(head[:end].split(b"\n"), start=1):
        words = raw.decode("ascii", errors="replace").split()
        if not words:
            continue
        if words[0] == "format" and len(words) >= 2:
            fmt = words[1]
        elif words[0] == "element":
            try:
                count = int(words[2])
                if count < 0:
                    raise ValueError
            except (IndexError, ValueError):
                raise MeshFileError(f"{path}: header line {number}: bad element count in {raw.strip()[:60]!r}") from None
            elements.append((words[1], count, []))
        elif words[0] == "property" and elements:
            prop = tuple(words[1:])
            types = prop[1:3] if prop[:1] == ("list",) else prop[:1]
            if not prop or any(t not in _PLY_SIZES for t in types):
                raise MeshFileError(f"{path}: header line {number}: unknown property type in {raw.strip()[:60]!r}")
            elements[-1][2].append(prop)
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise MeshFileError(f"{path}: unknown PLY format {fmt!r}")
    return fmt, elements, size


def check_ply(path: str) -> Dict[str, int]:
    """Refuses a PLY whose header claims more elements than the file can hold (each binary row
    takes at least its fixed-size properties and list counts, each ASCII row at least one
    character per property and a line end), before anything the size of the claim is
    allocated. Returns the element counts by name."""
    fmt, elements, header = ply_header(path)
    left = os.path.getsize(path) - header
    for name, count, props in elements:
        if fmt == "ascii":
            row = 2 * len(props)  # a digit and a separator per value, at least
        else:
            row = sum(_PLY_SIZES[p[1]] if p[0] == "list" else _PLY_SIZES[p[0]] for p in props)
        need = count * row
        if need > left:
            raise MeshFileError(
                f"{path}: the header claims {count:,} '{name}' elements (at least {need:,} bytes) but only "
                f"{max(left, 0):,} bytes follow: truncated or corrupt")
        left -= need
    return {name: count for name, count, _ in elements}


def strip_triangles(strips: Any) -> np.ndarray:
    """Triangles of triangle strips: a flat index sequence where -1 restarts a strip (or a list
    of strips). Triangle k of a strip is (s[k], s[k+1], s[k+2]) for even k and (s[k+1], s[k],
    s[k+2]) for odd k, so that all face the same way; triangles with a repeated corner (the
    joins between strips) are dropped. Returns (M, 3) int64."""
    # one sequence, each row ended by a restart
    if isinstance(strips, np.ndarray) and strips.dtype != object and strips.ndim == 2:
        s = np.hstack([strips.astype(np.int64), np.full((len(strips), 1), -1)]).ravel()
    else:
        rows = strips if isinstance(strips, (list, tuple)) or strips.dtype == object else [strips]
        ends = [np.append(np.asarray(row, dtype=np.int64).ravel(), -1) for row in rows]
        s = np.concatenate(ends) if ends else np.zeros(0, np.int64)
    k = np.flatnonzero((s[:-2] >= 0) & (s[1:-1] >= 0) & (s[2:] >= 0))  # first corners of whole triangles
    restarts = np.where(s < 0, np.arange(len(s)), -1)
    odd = (k - np.maximum.accumulate(restarts)[k]) % 2 == 0  # even distance from the restart: odd in its strip
    out = np.stack([np.where(odd, s[k + 1], s[k]), np.where(odd, s[k], s[k + 1]), s[k + 2]], axis=1)
    keep = (out[:, 0] != out[:, 1]) & (out[:, 1] != out[:, 2]) & (out[:, 0] != out[:, 2])
    return out[keep]


# ------------------------------------------------------------------------------------------------
# glTF


def gltf_document(path: str) -> Optional[Dict[str, Any]]:
    """The JSON document of a .gltf or .glb file (None for other files or an unreadable one:
    trimesh then reports the problem)."""
    lower = path.lower()
    try:
        if lower.endswith(".gltf"):
            with open(path, "rb") as f:
                return json.loads(f.read())  # type: ignore[no-any-return]
        if lower.endswith(".glb"):
            with open(path, "rb") as f:
                head = f.read(20)
                if len(head) < 20 or head[:4] != b"glTF":
                    raise MeshFileError(f"{path}: not a GLB file (no 'glTF' magic number)")
                length, chunk_type = struct.unpack("<II", head[12:20])
                if chunk_type != 0x4E4F534A or length > os.path.getsize(path) - 20:
                    raise MeshFileError(f"{path}: the GLB's JSON chunk is missing or cut off")
                return json.loads(f.read(length))  # type: ignore[no-any-return]
    except (ValueError, UnicodeDecodeError) as exc:
        if isinstance(exc, MeshFileError):
            raise
        raise MeshFileError(f"{path}: the glTF JSON cannot be read ({exc})") from None
    return None


_COMPONENT_BYTES = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
_COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


def check_gltf_sizes(path: str, doc: Dict[str, Any]) -> None:
    """Refuses a glTF whose accessors claim more elements than their buffer views hold, or whose
    buffer views reach past their buffers (and a GLB's binary chunk), before anything is read."""
    buffers = doc.get("buffers") or []
    views = doc.get("bufferViews") or []
    if path.lower().endswith(".glb") and buffers and "uri" not in buffers[0]:
        size = os.path.getsize(path)
        with open(path, "rb") as f:
            f.seek(12)
            json_length = struct.unpack("<I", f.read(4))[0]
            f.seek(20 + json_length)
            head = f.read(8)
        held = struct.unpack("<I", head[:4])[0] if len(head) == 8 else 0
        held = min(held, max(size - 28 - json_length, 0))
        if int(buffers[0].get("byteLength", 0)) > held:
            raise MeshFileError(f"{path}: the binary buffer claims {int(buffers[0]['byteLength']):,} bytes but the "
                                f"file holds {held:,}: truncated or corrupt")
    for i, view in enumerate(views):
        b = view.get("buffer", 0)
        end = int(view.get("byteOffset", 0)) + int(view.get("byteLength", 0))
        if not 0 <= b < len(buffers) or end > int(buffers[b].get("byteLength", 0)):
            raise MeshFileError(f"{path}: buffer view {i} reaches past its buffer ({end:,} bytes)")
    for i, acc in enumerate(doc.get("accessors") or []):
        if "bufferView" not in acc:
            continue  # zeros, by the spec
        v = acc["bufferView"]
        if not 0 <= v < len(views):
            raise MeshFileError(f"{path}: accessor {i} names buffer view {v}, of {len(views)}")
        item = _COMPONENT_BYTES.get(acc.get("componentType"), 4) * _COMPONENTS.get(acc.get("type"), 1)
        stride = int(views[v].get("byteStride", 0)) or item
        count = int(acc.get("count", 0))
        need = int(acc.get("byteOffset", 0)) + (stride * (count - 1) + item if count else 0)
        if need > int(views[v].get("byteLength", 0)):
            raise MeshFileError(f"{path}: accessor {i} claims {count:,} elements ({need:,} bytes) but its buffer "
                                f"view holds {int(views[v].get('byteLength', 0)):,} bytes")


def gltf_ignored(doc: Dict[str, Any]) -> List[str]:
    """What a glTF document holds that toonmesh does not draw (cameras, lights, animations,
    skins, morph targets, normal/occlusion/emissive/metallic-roughness maps and factors, ...)."""
    out = []
    for key, what in (("cameras", "cameras"), ("animations", "animations"), ("skins", "skins")):
        if doc.get(key):
            out.append(what)
    if "KHR_lights_punctual" in (doc.get("extensionsUsed") or []):
        out.append("lights")
    if any(p.get("targets") for m in doc.get("meshes") or [] for p in m.get("primitives") or []):
        out.append("morph targets")
    for ext in doc.get("extensionsUsed") or []:
        if ext not in ("KHR_lights_punctual", "KHR_materials_unlit", "KHR_mesh_quantization"):
            out.append(f"extension {ext}")
    for mat in doc.get("materials") or []:
        pbr = mat.get("pbrMetallicRoughness") or {}
        if "metallicRoughnessTexture" in pbr or "metallicFactor" in pbr or "roughnessFactor" in pbr:
            out.append("metallic-roughness")
        for key, what in (("normalTexture", "normal maps"), ("occlusionTexture", "occlusion maps"),
                          ("emissiveTexture", "emissive maps")):
            if key in mat:
                out.append(what)
        if any(mat.get("emissiveFactor") or []):
            out.append("emissive colour")
        if mat.get("alphaMode") == "BLEND":  # MASK is drawn (alpha_cutoff)
            out.append("alpha blending")
    return sorted(set(out), key=out.index)
