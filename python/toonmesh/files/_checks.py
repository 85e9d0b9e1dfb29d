"""Checks of mesh files that trimesh does not make, before it reads them.

trimesh drops an OBJ face whose indices point past the vertices, reads an OBJ cut off mid-line as
if it ended there, and allocates what a PLY header claims before finding the data missing. These
pre-scans refuse such files with the file's name, the line or element, and what is wrong, so a
broken file never renders with holes and exit status 0.
"""

from __future__ import annotations

import base64
import contextlib
import contextvars
import io
import json
import math
import os
import struct
import warnings
from urllib.parse import unquote
from typing import Any, Dict, Iterator, List, NamedTuple, Optional, Sequence, Tuple

import numpy as np


class MeshFileError(ValueError):
    """A mesh file that cannot be read as it claims to be; the message names the file."""


#: The bytes of the files opened while one mesh file is read (itself, its MTL, textures and
#: buffers), by full path: each is opened once, by the checks or trimesh, whichever comes first.
_OPENED: "contextvars.ContextVar[Optional[Dict[str, bytes]]]" = contextvars.ContextVar("opened", default=None)


@contextlib.contextmanager
def reading() -> Iterator[None]:
    """While a mesh file is read: each file it names opened once (see :func:`file_bytes`)."""
    token = _OPENED.set({})
    try:
        yield
    finally:
        _OPENED.reset(token)


def file_bytes(path: str) -> bytes:
    """The bytes of the file ``path``, opened once while a mesh file is read."""
    opened = _OPENED.get()
    full = os.path.realpath(path)
    if opened is not None and full in opened:
        return opened[full]
    with open(full, "rb") as f:
        data = f.read()
    if opened is not None:
        opened[full] = data
    return data


# ------------------------------------------------------------------------------------------------
# What a file is


#: The first bytes of formats a mesh file is mistaken for, and their names in messages.
_MAGIC = (
    (b"\x89PNG", "a PNG image"), (b"\xff\xd8\xff", "a JPEG image"), (b"GIF8", "a GIF image"),
    (b"%PDF", "a PDF document"), (b"PK\x03\x04", "a zip archive"), (b"\x1f\x8b", "a gzip file"),
    (b"BZh", "a bzip2 file"), (b"\xfd7zXZ", "an xz file"), (b"7z\xbc\xaf", "a 7z archive"),
    (b"RIFF", "a RIFF file (WAV, WebP or AVI)"), (b"glTF", "a GLB file"), (b"ply\n", "a PLY file"),
    (b"ply\r", "a PLY file"), (b"\x7fELF", "a program"),
)
#: The suffixes whose files start with one of those (a 3MF is a zip archive).
_OWN_MAGIC = {".glb": "a GLB file", ".ply": "a PLY file", ".3mf": "a zip archive", ".zip": "a zip archive"}
#: Format names by suffix, for "not an STL file".
_FORMAT = {".stl": "an STL", ".obj": "an OBJ", ".ply": "a PLY", ".off": "an OFF", ".glb": "a GLB",
           ".gltf": "a glTF", ".3mf": "a 3MF"}


def looks_like(data: bytes) -> str:
    """What a file's first bytes look like, in words: "a PNG image", "text ('hello')", ...
    (for messages about a file that is not what its suffix says)."""
    for magic, what in _MAGIC:
        if data.startswith(magic):
            return what
    head = data[:512]
    try:
        text = head.decode("utf-8")
    except UnicodeDecodeError as exc:
        text = head[: exc.start].decode("utf-8") if exc.start > len(head) - 4 else ""
        if not text:
            return "binary data"
    if any(c < " " and c not in "\t\r\n\f\v" for c in text):
        return "binary data"
    stripped = text.lstrip()
    lower = stripped.lower()
    if lower.startswith(("<!doctype html", "<html")):
        return "an HTML page"
    if lower.startswith("<?xml"):
        return "an XML document"
    if stripped.startswith(("{", "[")):
        return "JSON"
    if lower.startswith("solid"):
        return "an ASCII STL file"
    first = stripped.split("\n", 1)[0].strip()
    return f"text ({first[:40]!r})" if first else "blank text"


def check_kind(path: str, suffix: str, data: bytes) -> None:
    """Refuses an empty file, and a file that starts like another format (an image, an
    archive, a mesh format of another suffix) than its suffix says, naming what it looks like."""
    if not data.strip():
        raise MeshFileError(f"{path}: the file is empty" + (f" ({len(data):,} blank bytes)" if data else ""))
    what = looks_like(data)
    if any(what == w for _, w in _MAGIC) and _OWN_MAGIC.get(suffix) != what and suffix in _FORMAT:
        raise MeshFileError(f"{path}: not {_FORMAT[suffix]} file: it starts like {what}")


def unlike(path: str, suffix: str, data: bytes) -> Optional[str]:
    """For a file of which nothing could be read: "not an STL file: it starts like text ('hello')"
    where it does not look like its suffix's format, else None."""
    if suffix not in _FORMAT:
        return None
    what = looks_like(data)
    if suffix == ".stl":
        binary = len(data) >= 84 and len(data) == 84 + 50 * struct.unpack("<I", data[80:84])[0]
        if binary or what == "an ASCII STL file":
            return None
    elif suffix == ".obj":
        if what.startswith("text"):  # text of OBJ statements or comments: its own checks say what is wrong
            return None
    elif suffix == ".off":
        if data.lstrip()[:4].upper().startswith((b"OFF", b"COFF", b"NOFF", b"STOFF", b"4OFF")):
            return None
    else:
        return None  # PLY, GLB, glTF, 3MF: their own checks name the problem
    return f"{path}: not {_FORMAT[suffix]} file: it starts like {what}"


# ------------------------------------------------------------------------------------------------
# OBJ


def check_obj(path: str, data: Optional[bytes] = None) -> Dict[str, Any]:
    """Scans an OBJ's statements: every face has 3+ corners whose position indices (1-based, or
    negative from the end of those listed so far) name existing vertices, and every ``v`` has 3
    finite coordinates. Returns counts: ``vertices``, ``texcoords``, ``faces``, ``normals``,
    ``materials`` (distinct ``usemtl`` names) and ``libraries`` (``mtllib`` statements); and
    what the reader must know: ``negative`` (a face counts back from the entries so far),
    ``comments`` (a comment after a statement), ``polygons`` (a face of more than 3 corners),
    ``drop`` (the index columns, ``b"vt"`` or ``b"vn"``, that name entries the file lacks: they
    are left out, the positions kept) and ``notes`` (one line each about what is not read as
    written: those columns, the first vertex whose colour is not a number); and ``mesh``, for a
    file of positions and triangles alone, its (V, F) arrays as trimesh reads them (read once,
    here: the bunny loads in half the time). Raises
    :class:`MeshFileError` naming the 1-based line. ``data``: the file's bytes, when read already."""
    if data is None:
        with open(path, "rb") as f:
            data = f.read()
    counts, mesh = _obj_scan_at_once(data)
    if counts is None:
        return _check_obj_by_line(path, data)
    if mesh is not None:
        counts["mesh"] = mesh
    return counts


_KINDS = (b"v", b"vt", b"vn")


def _face_columns(path: str, number: int, lines: List[bytes], raw: bytes, words: List[bytes]) -> List[List[int]]:
    """The indices of a face line, one list per kind (v, then vt and vn where written)."""
    if len(words) < 4:
        raise MeshFileError(_obj_where(path, number, lines, f"a face needs 3 or more corners, got {len(words) - 1}"))
    # one list of indices per kind: v, or v/vt, v//vn, v/vt/vn
    columns = [words[1:]] if b"/" not in raw else list(zip(*(c.split(b"/") for c in words[1:])))
    try:
        return [[int(t) for t in texts if t] for texts in columns]
    except ValueError:
        raise MeshFileError(_obj_where(path, number, lines, f"not an index in {_text(raw)!r}")) from None


def _statements(lines: List[bytes]) -> Iterator[Tuple[int, bytes, List[bytes]]]:
    """(1-based line number, line, words before any comment) of each non-empty line."""
    for number, raw in enumerate(lines, start=1):
        words = (raw.split(b"#", 1)[0] if b"#" in raw else raw).split()
        if words:
            yield number, raw, words


def _check_obj_by_line(path: str, data: bytes) -> Dict[str, Any]:
    """:func:`check_obj` one line at a time: the rule itself, and the messages that name where
    a file breaks it."""
    counts = {b"v": 0, b"vt": 0, b"vn": 0}
    faces = 0
    materials = set()  # the names 'usemtl' switches to
    libraries = 0
    negative = False
    largest = {k: 0 for k in _KINDS}  # the largest positive index of each kind
    absent: Dict[bytes, Tuple[int, int, int]] = {}  # kind -> (line, index, entries then) of the first miss
    notes: List[str] = []
    colour_noted = False
    coloured: List[int] = []  # the lines of vertices with a colour
    comments = False  # a comment after a statement (trimesh reads it as part of the statement)
    polygons = False  # a face of more than 3 corners
    lines = data.split(b"\n")
    for number, raw, words in _statements(lines):
        head = words[0]
        comments = comments or b"#" in raw
        if head == b"v":
            if len(words) < 4:
                raise MeshFileError(_obj_where(path, number, lines, f"a vertex needs 3 coordinates, got {len(words) - 1}"))
            try:
                xyz = [float(w) for w in words[1:4]]
            except ValueError:
                raise MeshFileError(_obj_where(path, number, lines, f"not a number in {_text(raw)!r}")) from None
            counts[b"v"] += 1
            if not all(math.isfinite(x) for x in xyz):
                raise MeshFileError(f"{path}: vertex {counts[b'v']} (line {number}) is not finite: {xyz}")
            if len(words) > 4:
                coloured.append(number)
            if len(words) > 4 and not colour_noted and not _finite_words(words[4:]):
                colour_noted = True
                notes.append(f"line {number}: vertex {counts[b'v']}'s colour is not a number "
                             f"({b' '.join(words[4:]).decode(errors='replace')}): drawn black")
        elif head == b"f":
            polygons = polygons or len(words) > 4
            for kind, ints in zip(_KINDS, _face_columns(path, number, lines, raw, words)):
                if not ints:
                    continue
                lo, hi, n = min(ints), max(ints), counts[kind]
                negative = negative or lo < 0
                if lo < -n or 0 in ints:  # negative: counted back from the entries so far
                    i = 0 if 0 in ints else lo
                    if kind == b"v":
                        raise MeshFileError(f"{path}: line {number}: face index {i} points past the {n} "
                                            f"{_NAMES[kind]} listed before it")
                    absent.setdefault(kind, (number, i, n))
                largest[kind] = max(largest[kind], hi)
            faces += 1
        elif head == b"vt" or head == b"vn":
            counts[head] += 1
        elif head == b"usemtl":
            materials.add(b" ".join(words[1:]))
        elif head == b"mtllib":
            libraries += 1
    for kind in _KINDS:
        if largest[kind] > counts[kind]:  # the first line past the entries in the whole file
            number, i = _first_past(path, lines, kind, counts[kind])
            if kind == b"v":
                raise MeshFileError(f"{path}: line {number}: face index {i} points past the {counts[kind]} "
                                    f"{_NAMES[kind]} in the file")
            if kind not in absent or number < absent[kind][0]:
                absent[kind] = (number, i, counts[kind])
    if coloured and len(coloured) < counts[b"v"]:
        notes.append(partial_colours(len(coloured), counts[b"v"], coloured[0]))
    for kind, (number, i, n) in sorted(absent.items(), key=lambda item: item[1][0]):
        notes.append(f"line {number}: a face names {_ONE[kind]} {i}, of {n} listed: the file's {_NAMES[kind]} are "
                     "not read (positions kept)")
    return {"vertices": counts[b"v"], "texcoords": counts[b"vt"], "normals": counts[b"vn"], "faces": faces,
            "materials": len(materials), "libraries": libraries, "negative": negative,
            "drop": tuple(sorted(absent)), "notes": notes, "comments": comments, "polygons": polygons}


def partial_colours(coloured: int, vertices: int, line: int) -> str:
    """The note on an OBJ whose vertices have colours only in part (trimesh drops them all)."""
    return (f"vertex colours on {coloured:,} of the {vertices:,} vertices (the first on line {line}): not drawn, "
            "as a colour is read only where every vertex has one")


def _finite_words(words: List[bytes]) -> bool:
    try:
        return all(math.isfinite(float(w)) for w in words)
    except ValueError:
        return True  # not numbers: not a colour trimesh reads


def _first_past(path: str, lines: List[bytes], kind: bytes, count: int) -> Tuple[int, int]:
    """(line, index) of the first face that names an entry of ``kind`` past the ``count`` in the file."""
    column = _KINDS.index(kind)
    for number, raw, words in _statements(lines):
        if words[0] == b"f":
            ints = _face_columns(path, number, lines, raw, words)
            past = [i for i in (ints[column] if column < len(ints) else []) if i > count]
            if past:
                return number, past[0]
    raise AssertionError("no face past the entries")  # pragma: no cover: called only when one is


def join_continued(data: bytes) -> bytes:
    """An OBJ's text with each statement continued over lines (a line ending in a backslash) on
    one line, the lines it took kept as empty ones after it, so that line numbers stay."""
    if b"\\\n" not in data and b"\\\r\n" not in data:
        return data
    out: List[bytes] = []
    carried: List[bytes] = []
    for line in data.split(b"\n"):
        text = line.rstrip(b"\r")
        if text.endswith(b"\\"):
            carried.append(text[:-1])
            continue
        out.append(b" ".join(carried + [line]))
        out.extend([b""] * len(carried))
        carried = []
    if carried:
        out.append(b" ".join(carried))
        out.extend([b""] * (len(carried) - 1))
    return b"\n".join(out)


def obj_for_trimesh(data: bytes, drop: Sequence[bytes] = ()) -> bytes:
    """An OBJ's text as trimesh reads it right: each face's negative indices written as the
    positive ones they mean (counted back from the entries listed before the face; trimesh
    counts from the end of the file, or fails), the index columns of the kinds in ``drop``
    (``b"vt"``, ``b"vn"``) left out, and comments after statements cut off (trimesh reads them
    as numbers). Other lines are kept as they are."""
    counts = {k: 0 for k in _KINDS}
    out = []
    for raw in data.split(b"\n"):
        words = (raw.split(b"#", 1)[0] if b"#" in raw else raw).split()
        if words and b"#" in raw and words[0] not in (b"mtllib", b"usemtl", b"newmtl", b"g", b"o"):
            raw = raw.split(b"#", 1)[0]  # a comment after a statement: cut off, as trimesh reads none
        if words and words[0] in counts:
            counts[words[0]] += 1
        elif words and words[0] == b"f":
            corners = []
            for corner in words[1:]:
                parts = corner.split(b"/") + [b"", b""]
                fixed = [b"" if not text or kind in drop else
                         (b"%d" % (int(text) + counts[kind] + 1) if text.startswith(b"-") else text)
                         for kind, text in zip(_KINDS, parts)]
                corners.append(fixed[0] + (b"/" + fixed[1] + b"/" + fixed[2] if fixed[2] else
                                           b"/" + fixed[1] if fixed[1] else b""))
            raw = b"f " + b" ".join(corners)
        out.append(raw)
    return b"\n".join(out)


_NAMES = {b"v": "vertices", b"vt": "texture coordinates", b"vn": "normals"}
_ONE = {b"vt": "texture coordinate", b"vn": "normal"}

#: The bytes that ``bytes.split()`` splits at.
_BLANK = np.zeros(256, bool)
_BLANK[list(b" \t\n\r\x0b\x0c")] = True


def _obj_counts_at_once(data: bytes) -> Optional[Dict[str, Any]]:
    """:func:`check_obj`'s counts of a file that keeps its rules (see :func:`_obj_scan_at_once`)."""
    return _obj_scan_at_once(data)[0]


def _obj_scan_at_once(data: bytes) -> Tuple[Optional[Dict[str, Any]], Optional[Tuple[np.ndarray, np.ndarray]]]:
    """:func:`check_obj`'s counts of a file that keeps its rules, found with whole-file array
    operations instead of a Python loop over lines; None where the file breaks a rule or is
    written in a way this does not follow (a comment after a statement, faces whose corners are
    written in different ways), so that the line-by-line scan decides and names the line; and
    the mesh ((N, 3) float64 positions, (M, 3) int64 triangles, 0-based) of a file of positions
    and triangles alone, else None."""
    raw = np.frombuffer(data, np.uint8)
    if not len(raw):
        return None, None
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
        return None, None  # a comment after a statement: the line scan cuts it off
    one_letter = lambda c: (c0 == ord(c)) & _BLANK[c1]  # noqa: E731
    two_letters = lambda c: (c0 == ord(c[0])) & (c1 == ord(c[1])) & _BLANK[c2]  # noqa: E731
    listed = {b"v": spoken[one_letter("v")], b"vt": spoken[two_letters("vt")], b"vn": spoken[two_letters("vn")]}
    faces = spoken[one_letter("f")]
    # vertices: 3 finite coordinates each (any more, a colour, are numbers too)
    v = listed[b"v"]
    numbers = per_line[v] - 1
    if np.any(numbers < 3):
        return None, None
    xyz = _numbers_of_lines(raw, line_bytes, v, word_starts[first_word[v]], float, numbers)
    if xyz is None or not np.all(np.isfinite(xyz)):  # colours too: the line scan names the first
        return None, None
    notes = []
    coloured = np.flatnonzero(numbers > 3)
    if 0 < len(coloured) < len(v):
        notes.append(partial_colours(len(coloured), len(v), int(v[coloured[0]]) + 1))
    negative = False
    # faces: 3 or more corners, all written one way (v, v/vt, v//vn or v/vt/vn)
    corners = per_line[faces] - 1
    if np.any(corners < 3):
        return None, None
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
            return None, None
        columns = [b"v", b"vn"] if doubled else [b"v", b"vt", b"vn"][: int(slashes[0]) + 1]
        index = _numbers_of_lines(raw, line_bytes, faces, word_starts[first_word[faces]], np.int64,
                                  corners * len(columns), at_slash)
        if index is None:
            return None, None
        index = index.reshape(-1, len(columns))
        face_of = np.repeat(faces, corners)
        for column, name in enumerate(columns):
            so_far = np.zeros(n_lines, np.int64)
            so_far[listed[name]] = 1
            before = np.cumsum(so_far)[face_of]  # negative indices count back from these
            i = index[:, column]
            if np.any(i == 0) or np.any(i < -before) or i.max() > len(listed[name]):
                return None, None
            negative = negative or bool(np.any(i < 0))
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
    counts = {"vertices": len(v), "texcoords": len(listed[b"vt"]), "normals": len(listed[b"vn"]),
              "faces": len(faces), "materials": len(materials), "libraries": libraries, "negative": negative,
              "drop": (), "notes": notes, "comments": False, "polygons": bool(len(faces) and corners.max() > 3)}
    # a file of positions and triangles alone (no colours, texture coordinates, normals, groups,
    # materials or other statements): the arrays read here are the mesh, as trimesh reads it
    plain = (len(v) + len(faces) + int(np.count_nonzero(c0 == ord("#"))) == len(spoken) and len(faces)
             and not negative and not np.any(numbers != 3) and not np.any(corners != 3) and columns == [b"v"])
    return counts, (xyz.reshape(-1, 3), index.reshape(-1, 3) - 1) if plain else None


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


def _text(raw: bytes) -> str:
    """A line of a file as text, for a message: its first 60 characters."""
    return raw.strip()[:60].decode("utf-8", errors="replace")


def _obj_where(path: str, number: int, lines: List[bytes], problem: str) -> str:
    cut = number == len(lines) and lines[-1].strip() != b""  # the last line, with no line end
    return f"{path}: line {number}: {problem}" + (" (the file ends mid-line: cut off?)" if cut else "")


# ------------------------------------------------------------------------------------------------
# Files a mesh file names: MTL files, texture images, glTF buffers


def asset_path(folder: str, name: str) -> Optional[str]:
    """The file ``name`` beside a mesh file in ``folder``, found as trimesh's resolver finds it
    (the name, then without a leading ``/``, then its last part; percent-escapes decoded too),
    inside that folder; None where there is none."""
    root = os.path.realpath(folder)
    # as written, percent-escapes decoded, and with Windows' backslashes as slashes
    names = [name, unquote(name), name.replace("\\", "/"), unquote(name).replace("\\", "/")]
    candidates = [c for n in names for c in (n.strip(), n.strip().lstrip("/"), os.path.basename(n.strip()))]
    for candidate in dict.fromkeys(candidates):
        if not candidate:
            continue
        full = os.path.realpath(os.path.join(root, candidate))
        if full.startswith(root + os.sep) and os.path.isfile(full):
            return full
    for candidate in dict.fromkeys(candidates):  # then in another case (a file written on Windows or macOS)
        found = _any_case(root, candidate)
        if found is not None:
            return found
    return None


def _any_case(root: str, relative: str) -> Optional[str]:
    """The file ``relative`` inside ``root`` whose path matches in any letter case, or None."""
    here = root
    for part in [p for p in relative.split("/") if p not in ("", ".")]:
        if part == ".." or not os.path.isdir(here):
            return None
        match = [e for e in os.listdir(here) if e.lower() == part.lower()]
        if not match:
            return None
        here = os.path.join(here, sorted(match)[0])
    full = os.path.realpath(here)
    return full if full.startswith(root + os.sep) and os.path.isfile(full) else None


def _image_notes(folder: str, name: str, what: str) -> List[str]:
    """A note when the image ``name`` is not beside the file or cannot be decoded."""
    found = asset_path(folder, name)
    if found is None:
        return [f"{what} {os.path.join(folder, name.strip())} not found: not drawn"]
    try:
        from PIL import Image
    except ImportError:  # trimesh reads no image either; nothing to check it with
        return []
    try:
        with Image.open(io.BytesIO(file_bytes(found))) as image:
            image.size
    except Exception as exc:  # PIL raises several kinds for what it cannot decode
        return [f"{what} {found} cannot be read as an image ({_one_line(exc)}): not drawn"]
    return []


def obj_file_notes(path: str, data: bytes) -> Tuple[List[str], bool]:
    """Notes on the files an OBJ (its bytes ``data``) names, as trimesh reads them (the first
    ``mtllib``; each ``map_Kd`` of that MTL): one not found (the path tried) or not an image,
    and an MTL colour ``Kd`` that is not a number (drawn black); and whether a texture is found
    (trimesh then reads it, with Pillow)."""
    at = data.find(b"mtllib")
    if at < 0:
        return [], False
    end = data.find(b"\n", at)
    name = data[at + 6 : end if end >= 0 else len(data)].strip().decode(errors="replace")
    folder = os.path.dirname(os.path.abspath(path))
    found = asset_path(folder, name)
    if found is None:
        return [f"MTL file {os.path.join(folder, name)} not found: its materials (colours, textures) are not drawn"], False
    text = file_bytes(found).decode(errors="replace")
    notes: List[str] = []
    material = ""
    textured = False
    for line in text.splitlines():
        words = line.strip().split()
        key = words[0].lower() if len(words) > 1 else ""
        if key == "newmtl":
            material = " ".join(words[1:])
        elif key == "map_kd":
            texture = line[line.lower().index("map_kd") + 6 :].strip()
            problems = _image_notes(folder, texture, f"texture of material {material!r}")
            notes += problems
            textured = textured or (not problems and _has_pillow())
        elif key == "kd" and not _finite_words([w.encode() for w in words[1:]]):
            notes.append(f"{found}: material {material!r}: Kd {' '.join(words[1:])} is not a colour: drawn black")
    return notes, textured


def _has_pillow() -> bool:
    try:
        import PIL  # noqa: F401
    except ImportError:
        return False
    return True


def ply_file_notes(path: str, header: "PlyHeader") -> List[str]:
    """A note when the texture a PLY names (``comment TextureFile NAME``, as trimesh reads it;
    ``header.texture``) is not beside it or not an image."""
    if header.texture is None:
        return []
    return _image_notes(os.path.dirname(os.path.abspath(path)), header.texture, "texture")


def gltf_file_notes(path: str, doc: Dict[str, Any]) -> List[str]:
    """Refuses a glTF whose buffer file is not there, or shorter than it claims (naming the
    path tried); notes on images named by file that are not there or not images."""
    folder = os.path.dirname(os.path.abspath(path))
    for i, buffer in enumerate(doc.get("buffers") or []):
        uri = buffer.get("uri")
        if not isinstance(uri, str) or "base64," in uri:
            continue
        found = asset_path(folder, uri)
        if found is None:
            raise MeshFileError(f"{path}: buffer {i} is read from {os.path.join(folder, uri)}, which is not there")
        size, claimed = os.path.getsize(found), int(buffer.get("byteLength", 0))
        if size < claimed:
            raise MeshFileError(f"{path}: buffer {i} ({found}) holds {size:,} bytes but the glTF claims {claimed:,}: "
                                "truncated or corrupt")
    notes: List[str] = []
    for i, image in enumerate(doc.get("images") or []):
        uri = image.get("uri")
        if isinstance(uri, str) and "base64," not in uri:
            notes += _image_notes(folder, uri, f"image {i}")
    return notes


def _one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__


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


class PlyHeader(NamedTuple):
    """A PLY file's header, parsed once: ``format`` (ascii, binary_little_endian or
    binary_big_endian), ``elements`` [(name, count, properties)], each property (type, name) or
    ("list", count type, item type, name); ``size``, the header's bytes; ``texture``, the name a
    ``comment TextureFile NAME`` gives (as trimesh reads it), or None."""

    format: str
    elements: List[Tuple[str, int, List[Tuple[str, ...]]]]
    size: int
    texture: Optional[str]


def ply_header(path: str, head: Optional[bytes] = None) -> PlyHeader:
    """The header of the PLY file ``path`` (``head``: its first bytes, when read already)."""
    if head is None:
        with open(path, "rb") as f:
            head = f.read(65536)
    end = head.find(b"end_header")
    if not head.startswith(b"ply") or end < 0:
        raise MeshFileError(f"{path}: not a PLY file (no 'ply' ... 'end_header' header)")
    newline = head.find(b"\n", end)
    size = (newline + 1) if newline >= 0 else len(head)
    fmt = ""
    texture: Optional[str] = None
    elements: List[Tuple[str, int, List[Tuple[str, ...]]]] = []
    for number, raw in enumerate(head[:end].split(b"\n"), start=1):
        words = raw.decode("ascii", errors="replace").split()
        if not words:
            continue
        if words[0] == "comment" and texture is None:
            text = raw.decode(errors="replace").strip()
            at = text.lower().find("texturefile")
            if at >= 0:
                texture = text[at + 11 :].strip()
        elif words[0] == "format" and len(words) >= 2:
            fmt = words[1]
        elif words[0] == "element":
            try:
                count = int(words[2])
                if count < 0:
                    raise ValueError
            except (IndexError, ValueError):
                raise MeshFileError(f"{path}: header line {number}: bad element count in {_text(raw)!r}") from None
            elements.append((words[1], count, []))
        elif words[0] == "property" and elements:
            prop = tuple(words[1:])
            types = prop[1:3] if prop[:1] == ("list",) else prop[:1]
            if not prop or any(t not in _PLY_SIZES for t in types):
                raise MeshFileError(f"{path}: header line {number}: unknown property type in {_text(raw)!r}")
            elements[-1][2].append(prop)
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise MeshFileError(f"{path}: unknown PLY format {fmt!r}")
    return PlyHeader(fmt, elements, size, texture)


def check_ply(path: str, header: PlyHeader, size: int) -> Dict[str, int]:
    """Refuses a PLY whose header claims more elements than the file can hold (each binary row
    takes at least its fixed-size properties and list counts, each ASCII row at least one
    character per property and a line end), before anything the size of the claim is
    allocated (``size``: the file's bytes). Returns the element counts by name."""
    fmt, elements = header.format, header.elements
    left = size - header.size
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


def gltf_document(path: str, data: bytes) -> Optional[Dict[str, Any]]:
    """The JSON document of a .gltf or .glb file whose bytes are ``data`` (None for other
    files)."""
    lower = path.lower()
    try:
        if lower.endswith(".gltf"):
            return json.loads(data)  # type: ignore[no-any-return]
        if lower.endswith(".glb"):
            if len(data) < 20 or data[:4] != b"glTF":
                raise MeshFileError(f"{path}: not a GLB file (no 'glTF' magic number)")
            length, chunk_type = struct.unpack("<II", data[12:20])
            if chunk_type != 0x4E4F534A or length > len(data) - 20:
                raise MeshFileError(f"{path}: the GLB's JSON chunk is missing or cut off")
            return json.loads(data[20 : 20 + length])  # type: ignore[no-any-return]
    except (ValueError, UnicodeDecodeError) as exc:
        if isinstance(exc, MeshFileError):
            raise
        raise MeshFileError(f"{path}: the glTF JSON cannot be read ({_one_line(exc)})") from None
    return None


def _json_kind(value: Any) -> str:
    """A JSON value's kind, in words."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true or false"
    if isinstance(value, int):
        return "an integer"
    if isinstance(value, float):
        return "a number"
    if isinstance(value, str):
        return "a string"
    return "an array" if isinstance(value, list) else "an object"


#: What the glTF properties that toonmesh and trimesh read hold, by the schema of the object they
#: sit in: ("int", ARRAY) an integer 0 or more, an index into the document's ARRAY where one is
#: named (a count or a scene's index where None); ("num",) a number; ("str",) a string;
#: ("obj", SCHEMA) an object checked by SCHEMA; ("map", ARRAY) an object of indices into ARRAY;
#: ("ints", ARRAY) an array of indices; ("strs",) an array of strings; ("nums", n) an array of
#: n numbers; ("objs", SCHEMA) an array of objects, each checked by SCHEMA (None: not looked into).
_GLTF: Dict[str, Dict[str, Any]] = {
    "": {"scene": ("int", None), "scenes": ("objs", "scene"), "nodes": ("objs", "node"),
         "meshes": ("objs", "mesh"), "accessors": ("objs", "accessor"), "bufferViews": ("objs", "bufferView"),
         "buffers": ("objs", "buffer"), "materials": ("objs", "material"), "textures": ("objs", "texture"),
         "images": ("objs", "image"), "samplers": ("objs", None), "cameras": ("objs", None),
         "animations": ("objs", None), "skins": ("objs", None), "extensionsUsed": ("strs",)},
    "scene": {"nodes": ("ints", "nodes")},
    "node": {"mesh": ("int", "meshes"), "children": ("ints", "nodes"), "matrix": ("nums", 16),
             "translation": ("nums", 3), "rotation": ("nums", 4), "scale": ("nums", 3)},
    "mesh": {"primitives": ("objs", "primitive")},
    "primitive": {"attributes": ("map", "accessors"), "indices": ("int", "accessors"), "mode": ("int", None),
                  "material": ("int", "materials"), "targets": ("objs", None)},
    "accessor": {"bufferView": ("int", "bufferViews"), "byteOffset": ("int", None), "count": ("int", None),
                 "componentType": ("int", None), "type": ("str",)},
    "bufferView": {"buffer": ("int", "buffers"), "byteOffset": ("int", None), "byteLength": ("int", None),
                   "byteStride": ("int", None)},
    "buffer": {"uri": ("str",), "byteLength": ("int", None)},
    "material": {"pbrMetallicRoughness": ("obj", "pbr"), "alphaMode": ("str",), "alphaCutoff": ("num",),
                 "extensions": ("obj", "material extensions")},
    "material extensions": {"KHR_materials_pbrSpecularGlossiness": ("obj", "specular-glossiness")},
    "pbr": {"baseColorFactor": ("nums", 4), "baseColorTexture": ("obj", "texture info")},
    "specular-glossiness": {"diffuseFactor": ("nums", 4), "diffuseTexture": ("obj", "texture info")},
    "texture info": {"index": ("int", "textures"), "texCoord": ("int", None)},
    "texture": {"source": ("int", "images"), "sampler": ("int", None)},
    "image": {"uri": ("str",), "bufferView": ("int", "bufferViews"), "mimeType": ("str",)},
}


def check_gltf_shape(path: str, doc: Any) -> None:
    """Refuses a glTF whose JSON does not have the shape the spec gives where toonmesh and
    trimesh read it (an array where an object belongs, a string for an index, an index past its
    array), naming the JSON path and what was expected: ``meshes[0].primitives: expected an
    array, got a string``."""
    if not isinstance(doc, dict):
        raise MeshFileError(f"{path}: the glTF JSON: expected an object, got {_json_kind(doc)}")
    _check_shape(path, doc, doc, "", "")


def _check_shape(path: str, doc: Dict[str, Any], value: Dict[str, Any], schema: str, where: str) -> None:
    def fail(at: str, expected: str, got: Any) -> None:
        raise MeshFileError(f"{path}: {at}: expected {expected}, got {_json_kind(got)}")

    def index(at: str, item: Any, into: Optional[str]) -> None:
        if not isinstance(item, int) or isinstance(item, bool) or item < 0:
            fail(at, "an index (an integer 0 or more)" if into else "an integer 0 or more", item)
        if into is not None and item >= len(doc.get(into) or []):
            raise MeshFileError(f"{path}: {at}: index {item} names no entry of '{into}' "
                                f"(it has {len(doc.get(into) or [])})")

    for key, rule in _GLTF[schema].items():
        if key not in value:
            continue
        item, at = value[key], f"{where}.{key}" if where else key
        kind = rule[0]
        if kind == "int":
            index(at, item, rule[1])
        elif kind == "num":
            if isinstance(item, bool) or not isinstance(item, (int, float)):
                fail(at, "a number", item)
        elif kind == "str":
            if not isinstance(item, str):
                fail(at, "a string", item)
        elif kind == "obj":
            if not isinstance(item, dict):
                fail(at, "an object", item)
            _check_shape(path, doc, item, rule[1], at)
        elif kind == "map":
            if not isinstance(item, dict):
                fail(at, "an object", item)
            for name, i in item.items():
                index(f"{at}.{name}", i, rule[1])
        else:  # arrays
            if not isinstance(item, list):
                fail(at, "an array", item)
            for k, entry in enumerate(item):
                here = f"{at}[{k}]"
                if kind == "objs":
                    if not isinstance(entry, dict):
                        fail(here, "an object", entry)
                    if rule[1] is not None:
                        _check_shape(path, doc, entry, rule[1], here)
                elif kind == "ints":
                    index(here, entry, rule[1])
                elif kind == "strs":
                    if not isinstance(entry, str):
                        fail(here, "a string", entry)
                elif isinstance(entry, bool) or not isinstance(entry, (int, float)):
                    fail(here, "a number", entry)
            if kind == "nums" and len(item) != rule[1]:
                raise MeshFileError(f"{path}: {at}: expected {rule[1]} numbers, got {len(item)}")


_COMPONENT_BYTES = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
_COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


def check_gltf_sizes(path: str, doc: Dict[str, Any], data: bytes) -> None:
    """Refuses a glTF (its bytes ``data``) whose accessors claim more elements than their buffer
    views hold, or whose buffer views reach past their buffers (and a GLB's binary chunk),
    before anything is read."""
    buffers = doc.get("buffers") or []
    views = doc.get("bufferViews") or []
    if path.lower().endswith(".glb") and buffers and "uri" not in buffers[0]:
        size = len(data)
        json_length = struct.unpack("<I", data[12:16])[0]
        head = data[20 + json_length : 28 + json_length]
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


def gltf_colour_notes(path: str, doc: Dict[str, Any], data: bytes) -> List[str]:
    """A note per primitive whose float vertex colours (``COLOR_0``) hold values that are not
    numbers: trimesh turns them into black, silently. ``data``: the file's bytes."""
    notes: List[str] = []
    buffers: Dict[int, Optional[bytes]] = {-1: data}
    for m, mesh in enumerate(doc.get("meshes") or []):
        for p, primitive in enumerate(mesh.get("primitives") or []):
            values = _float_accessor(path, doc, (primitive.get("attributes") or {}).get("COLOR_0"), buffers)
            bad = np.zeros(0, np.int64) if values is None else np.flatnonzero(~np.isfinite(values).all(axis=1))
            if len(bad):
                name = f" ({mesh['name']})" if mesh.get("name") else ""
                notes.append(f"mesh {m}{name} primitive {p}: {len(bad):,} vertex colours are not numbers "
                             f"(the first of vertex {bad[0] + 1}): drawn black")
    return notes


_INDEX_TYPES = {5121: "<u1", 5123: "<u2", 5125: "<u4"}
_FLOAT_TYPES = {5126: "<f4"}


def gltf_accessor(path: str, doc: Dict[str, Any], index: Any, buffers: Dict[int, Optional[bytes]]
                  ) -> Optional[np.ndarray]:
    """The (count, components) values of an accessor of unsigned integers (indices) or floats,
    or None (another kind, or not readable). ``buffers``: the buffers read so far, the file's
    own bytes as ``buffers[-1]``."""
    return _accessor(path, doc, index, buffers, {**_INDEX_TYPES, **_FLOAT_TYPES})


def _float_accessor(path: str, doc: Dict[str, Any], index: Any, buffers: Dict[int, Optional[bytes]]
                    ) -> Optional[np.ndarray]:
    """The (count, components) values of a float accessor, or None (not one, or not readable:
    trimesh then says why)."""
    return _accessor(path, doc, index, buffers, _FLOAT_TYPES)


def _accessor(path: str, doc: Dict[str, Any], index: Any, buffers: Dict[int, Optional[bytes]],
              types: Dict[int, str]) -> Optional[np.ndarray]:
    """The (count, components) values of an accessor whose component type is one of ``types``
    (glTF's component type -> NumPy dtype), or None (another, sparse, or not readable)."""
    try:
        accessor = doc["accessors"][index]
        dtype = types.get(accessor.get("componentType"))
        if dtype is None or "bufferView" not in accessor or "sparse" in accessor:
            return None
        view = doc["bufferViews"][accessor["bufferView"]]
        b = int(view.get("buffer", 0))
        if b not in buffers:
            buffers[b] = _gltf_buffer(path, doc, b, buffers)
        data = buffers[b]
        n = _COMPONENTS[accessor["type"]]
        size = np.dtype(dtype).itemsize
        stride = int(view.get("byteStride", 0)) or size * n
        offset = int(view.get("byteOffset", 0)) + int(accessor.get("byteOffset", 0))
        if data is None:
            return None
        return np.ndarray((int(accessor["count"]), n), dtype, data, offset, (stride, size)).copy()
    except (LookupError, TypeError, ValueError):
        return None


def _gltf_buffer(path: str, doc: Dict[str, Any], index: int, buffers: Dict[int, Optional[bytes]]) -> Optional[bytes]:
    """The bytes of buffer ``index``: a GLB's binary chunk (of the file's bytes, ``buffers[-1]``),
    a base64 data URI, or the file it names."""
    uri = doc["buffers"][index].get("uri")
    if uri is None:
        data = buffers[-1]  # the file's own bytes
        if data is None:
            return None
        start = 28 + struct.unpack("<I", data[12:16])[0]
        return data[start:]
    if "base64," in uri:
        return base64.b64decode(uri[uri.index("base64,") + 7 :])
    found = asset_path(os.path.dirname(os.path.abspath(path)), uri)
    if found is None:
        return None
    return file_bytes(found)


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
        if ext == "KHR_materials_pbrSpecularGlossiness":  # its diffuse colour and texture are drawn
            out.append("specular and glossiness")
        elif ext not in ("KHR_lights_punctual", "KHR_materials_unlit", "KHR_mesh_quantization"):
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
    return sorted(set(out), key=out.index)
