"""Mesh files and trimesh scenes as lists of :class:`toonmesh.Mesh`: ``toonmesh.load(path)``.

Files are read by trimesh (``pip install 'toonmesh[io]'``) after toonmesh's own checks
(:mod:`toonmesh.files._checks`). A scene's node transforms are composed into each mesh's world
transform; a geometry drawn by several nodes gives several meshes that share the same vertex and
face arrays (a renderer uploads it once). What a mesh carries besides its triangles (texture
coordinates, a texture, vertex or face colours, a base colour) is read into a :class:`Surface`
record first; :func:`_mesh_of` is the one place that turns it into a :class:`toonmesh.Mesh`.
"""

from __future__ import annotations

import contextlib
import copy
import io
import logging
import os
import struct
import warnings
from dataclasses import dataclass, field
from typing import Any, Dict, Iterator, List, Optional, Tuple, Type

import numpy as np

from toonmesh import _core
from toonmesh.scene import _colors
from toonmesh.files import _archives, _gltf, _ply, _points_lines, _polygons, _threemf
from toonmesh.files._checks import (
    MeshFileError, asset_path, check_gltf_shape, check_gltf_sizes, check_kind, check_obj, check_ply, file_bytes,
    gltf_colour_notes, gltf_document, gltf_file_notes, gltf_ignored, join_continued, obj_file_notes, obj_for_trimesh,
    ply_file_notes, ply_header, reading, unlike,
)
from toonmesh.scene._points import Lines, Points
from toonmesh.scene._scene import Mesh, normal_mode

#: Why a file of which nothing is drawn is refused.
NOTHING_DRAWN = "no triangles in the file (nor points or lines)"

#: The most mesh instances (scene nodes with geometry) one file or scene may place.
MAX_INSTANCES = 65_536
#: The most distinct materials (and so textures) one file or scene may use.
MAX_MATERIALS = 1_024

#: A mesh whose area is at most this share of its bounding-box diagonal squared has none (its
#: faces are lines or points, up to rounding): named in a warning, as it draws nothing.
ZERO_AREA = 1e-12

_TRIMESH_HINT = "reading mesh files needs trimesh: pip install 'toonmesh[io]'"


def trimesh_module() -> Any:
    """trimesh, or an ImportError that says how to install it."""
    try:
        import trimesh
    except ImportError:
        raise ImportError(_TRIMESH_HINT) from None
    return trimesh


@dataclass
class Surface:
    """One geometry of a file and what it carries besides positions and triangles.

    ``vertices`` (N, 3) float64 and ``faces`` (M, 3) int64 in the geometry's own frame;
    ``uv`` (N, 2) float64 texture coordinates (origin bottom-left, as glTF after trimesh and
    OBJ); ``texture`` (H, W, 4) uint8 RGBA image (top row first); ``vertex_colors`` (N, 4) and
    ``face_colors`` (M, 4) uint8 RGBA; ``base_color`` (4,) float64 in [0, 1], the material's
    colour (MTL Kd; a glTF baseColorFactor turned from linear light to sRGB, as drawn) that
    multiplies texture and vertex colours;
    ``normals`` (N, 3) float64, the file's own vertex normals (glTF ``NORMAL``, OBJ ``vn``, PLY
    ``nx ny nz``; read from files only, never computed).
    Any of them may be None: these are what ``toonmesh smooth`` writes back. ``colors``: the
    colour keywords of :class:`toonmesh.Mesh` that draw the geometry (its albedo, by the
    renderer's own rule in :mod:`toonmesh.scene._colors`), made once per geometry so that its
    instances share them.
    """

    vertices: np.ndarray
    faces: np.ndarray
    uv: Optional[np.ndarray] = None
    texture: Optional[np.ndarray] = None
    vertex_colors: Optional[np.ndarray] = None
    face_colors: Optional[np.ndarray] = None
    base_color: Optional[np.ndarray] = None
    normals: Optional[np.ndarray] = None
    name: str = ""
    colors: Dict[str, Any] = field(default_factory=dict)


def load(path: "str | os.PathLike[str] | Any", up: Optional[str] = None) -> "List[Mesh | Points | Lines]":
    """Reads a mesh file (or a ``trimesh.Scene`` already read) into a list of
    :class:`toonmesh.Mesh`, one per placed geometry, as :func:`toonmesh.render` takes them,
    followed by the file's points and lines as :class:`toonmesh.Points` and
    :class:`toonmesh.Lines` (read by toonmesh, :mod:`toonmesh.files._points_lines`: a PLY
    without faces, with ``nx ny nz`` normals and ``red green blue [alpha]`` colours, and its
    ``edge`` element; OBJ ``l`` polylines and ``p`` points, or the ``v`` lines of an OBJ without
    faces, with ``v x y z r g b`` colours and one ``vn`` per point; ``.xyz`` rows; glTF
    primitives of modes POINTS, LINES, LINE_LOOP and LINE_STRIP), each with its world
    ``transform``, the file as ``source``, its ``name`` and ``up`` as meshes get them.

    Formats: OBJ (with its MTL: diffuse colour ``Kd``, alpha ``d`` or ``Tr`` and texture ``map_Kd``), PLY (vertex and
    face colours; faces and triangle strips), STL, OFF, GLB and glTF (node transforms, mesh
    instances, PBR ``baseColorFactor`` and ``baseColorTexture``, vertex colours ``COLOR_0``),
    and whatever else trimesh reads. Each mesh has its world ``transform`` (4x4 float64, the
    scene's node transforms composed; None for a single mesh) and its colour as
    :class:`toonmesh.Mesh` takes it (``vertex_colors`` or ``face_colors``, or ``uv`` and
    ``texture``, the base colour factor folded in, ``alpha_cutoff`` for a glTF alpha mask,
    ``alpha_blend`` for a glTF alpha blend or an MTL alpha below 1), as a
    ``trimesh.Trimesh`` brings it; ``material`` is None (the render's). Meshes of one geometry
    placed by several nodes share their vertex, face and colour arrays, so a renderer uploads
    them once. Each mesh has the file's own vertex normals as ``normals`` where it holds them
    (glTF ``NORMAL``, OBJ ``vn``, PLY ``nx ny nz``; a file whose normals include a zero or
    non-finite one is drawn with the default normals, with a warning), else None (the default,
    ``"auto"``); and ``up``, the file format's up axis (``up`` when given).
    Vertices are kept as the file lists them (no merging or cleanup), except that an OBJ with a
    texture or normals is split where its texture coordinates or normals change (a vertex gets
    one of each) and an STL's corners are merged by position. A zip or tar archive, or a file
    compressed as ``.gz``, ``.bz2`` or ``.xz``, is unpacked and each mesh file in it read as the
    plain file. What the file holds and toonmesh does not draw (cameras, lights, animations,
    normal, emissive and metallic-roughness maps, ...) is named in one warning; so is, each in
    one warning, what is read other than written: OBJ faces naming texture coordinates or
    normals the file lacks (their positions kept; the first such line), an MTL file or texture
    image that is not there (the path tried), colours that are not numbers (drawn black), a mesh
    without area. Warnings raised while reading (trimesh's, NumPy's) name the file.

    Args:
        path: the file (str or os.PathLike), or a ``trimesh.Scene`` (its geometries placed by
            its graph, as ``tm.render(scene)`` draws them).
        up: the file's up axis, "x", "y" or "z"; None (default): its format's convention
            (:func:`file_up_axis`: z for STL, PLY and 3MF, y for glTF, GLB and OBJ), or none
            (the render's default, y) for other formats.

    Returns:
        A list of :class:`toonmesh.Mesh`, then :class:`toonmesh.Points` and
        :class:`toonmesh.Lines` (never empty; a file of points or lines alone gives no mesh).

    Raises:
        TypeError: ``path`` is not a str or os.PathLike.
        FileNotFoundError: no such file. IsADirectoryError: ``path`` is a folder.
        ImportError: trimesh is not installed.
        ValueError: the file cannot be read, naming the file and what is wrong (1-based line
            numbers in OBJ and .xyz, 1-based vertices when not finite, element counts and
            1-based edges in PLY, the mesh and primitive of a glTF, a glTF buffer file that is
            not there with the path tried); it holds no triangles, points or lines; or it places more
            than :data:`MAX_INSTANCES` meshes or uses more than :data:`MAX_MATERIALS`
            materials; ``up`` is not an axis name.
    """
    if is_scene(path):
        return [_mesh_of(s, t, _core._up_axis(up) if up is not None else None) for s, t in scene_surfaces(path, "scene")]
    up = _core._up_axis(up) if up is not None else file_up_axis(path)
    placed, others = _read_items(path, False, stacklevel=3)
    items: List["Mesh | Points | Lines"] = [_mesh_of(s, t, up) for s, t in placed]
    for other in others:
        other.up = up
    items += others
    for item in items:
        item.source = os.fspath(path)  # type: ignore[assignment]
    return items


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


def file_up_axis(path: Any) -> Optional[str]:
    """The up axis of a mesh file's format by its suffix (the core's ``FILE_UP_AXES``), or None
    for a format without a convention."""
    suffix = os.path.splitext(os.fspath(path))[1].lower().lstrip(".") if isinstance(path, (str, os.PathLike)) else ""
    return _core.FILE_UP_AXES.get(suffix)  # type: ignore[no-any-return]


def up_conventions() -> str:
    """The formats' up axes in words: ``"z for .stl, .ply, .3mf; y for .glb, .gltf, .obj and
    others"``."""
    by_axis: Dict[str, List[str]] = {}
    for suffix, axis in _core.FILE_UP_AXES.items():
        by_axis.setdefault(axis, []).append("." + suffix)
    words = [f"{axis} for {', '.join(s)}{' and others' if axis == _core.DEFAULT_UP_AXIS else ''}"
             for axis, s in by_axis.items()]
    return "; ".join(sorted(words, key=lambda w: w.endswith("others")))


def read_surfaces(path: Any, *, keep_seams: bool = False) -> List[Tuple[Surface, Optional[np.ndarray]]]:
    """(surface, world transform or None) per placed geometry of a file, with the file's own
    normals; see :func:`load`. ``keep_seams``: read an OBJ with texture coordinates split per
    corner (each vertex one UV), as the file means them, even without a texture (one with
    normals is always read so). Warnings raised while reading (toonmesh's, trimesh's, NumPy's)
    are given again naming the file. A file of points or lines alone is refused (no triangles)."""
    placed, others = _read_items(path, keep_seams, stacklevel=4)
    if not placed:
        held = ", ".join(f"{len(o):,} {'points' if isinstance(o, Points) else 'segments'}" for o in others[:3])
        raise MeshFileError(f"{os.fspath(path)}: no triangles in the file (it holds {held})")
    return placed


def _read_items(path: Any, keep_seams: bool, stacklevel: int,
                ) -> Tuple[List[Tuple[Surface, Optional[np.ndarray]]], List["Points | Lines"]]:
    """:func:`read_surfaces` and the file's points and lines (:class:`toonmesh.Points` and
    :class:`toonmesh.Lines`, each with its world transform; see :func:`load`); refuses a file
    that holds none of them. Its warnings are given ``stacklevel`` frames up."""
    path = _path(path)
    notes: List[Tuple[str, Type[Warning]]] = []
    if _archives.kind(path):
        placed, others = _read_archive(path, keep_seams, notes)
    else:
        placed, others = _read_file(path, path, keep_seams, notes)
    for text, category in dict.fromkeys(notes):
        warnings.warn(text, category, stacklevel=stacklevel)
    return placed, others


def _read_file(path: str, shown: str, keep_seams: bool, notes: List[Tuple[str, Type[Warning]]],
               ) -> Tuple[List[Tuple[Surface, Optional[np.ndarray]]], List["Points | Lines"]]:
    """:func:`_read_items` of one plain file; its warnings go to ``notes`` and its errors and
    notes name it ``shown`` (a file in an archive: ``ARCHIVE:NAME``)."""
    ignored: List[str] = []
    said: List[str] = []
    data = b""
    try:
        data = _bytes(path)  # the one time the file is opened
        with warnings.catch_warnings(record=True) as caught, _quiet_trimesh_log(), reading():
            warnings.simplefilter("always")
            try:
                scene, materials, others = _read(path, data, keep_seams, ignored, said)
                placed = [] if scene is None else _placed(scene, path, ignored, materials, needed=not others)
                if scene is None and not others:
                    raise MeshFileError(f"{path}: {NOTHING_DRAWN}")
            except MeshFileError as exc:
                if str(exc).endswith(("no triangles in the file", ")")) and not str(exc).endswith("claims)"):
                    raise MeshFileError(unlike(path, _suffix(path), data) or str(exc)) from None
                raise
            except (LookupError, TypeError, ValueError, AttributeError, struct.error, OverflowError, MemoryError):
                # a check tripped by a shape it does not expect: said in one line, not a traceback
                raise MeshFileError(unlike(path, _suffix(path), data) or
                                    f"{path}: cannot read a mesh: the file is malformed") from None
            geometries = _geometries(scene) if scene is not None else {}
            for surface in {id(s): s for s, _ in placed}.values():
                surface.normals = _file_normals(geometries.get(surface.name), surface, path)
    except MeshFileError as exc:
        if shown == path:
            raise
        raise MeshFileError(str(exc).replace(path, shown)) from None
    for text in said:
        notes.append((f"{shown}: {text}", UserWarning))
    for w in caught:
        if not _ours(w):
            continue  # NumPy's and trimesh's: what they mean is checked and said above, in words
        text = str(w.message).replace(path, shown)
        notes.append((text if text.startswith(shown) else f"{shown}: {text}", w.category))
    if ignored:
        notes.append((f"{shown}: not drawn: {', '.join(dict.fromkeys(ignored))}", UserWarning))
    return placed, others


def _read_archive(path: str, keep_seams: bool, notes: List[Tuple[str, Type[Warning]]],
                  ) -> Tuple[List[Tuple[Surface, Optional[np.ndarray]]], List["Points | Lines"]]:
    """Every mesh file in a zip or tar archive or compressed file, each read as the plain file."""
    formats = set(trimesh_module().available_formats())
    placed: List[Tuple[Surface, Optional[np.ndarray]]] = []
    others: List["Points | Lines"] = []
    with _archives.unpacked(path) as (folder, names):
        meshes = [n for n in names if not _archives.kind(n) and os.path.splitext(n)[1].lower().lstrip(".") in formats]
        if not meshes:
            held = ", ".join(names[:8]) + (", ..." if len(names) > 8 else "") if names else "nothing"
            raise MeshFileError(f"{path}: no mesh file inside (it holds {held})")
        for name in meshes:
            more, also = _read_file(os.path.join(folder, name), f"{path}:{name}", keep_seams, notes)
            placed += more
            others += also
    return placed, others


def scene_surfaces(scene: Any, source: str = "scene") -> List[Tuple[Surface, Optional[np.ndarray]]]:
    """(surface, world transform) per placed geometry of a ``trimesh.Scene``."""
    ignored: List[str] = []
    placed = _placed(scene, source, ignored)
    if ignored:
        warnings.warn(f"{source}: not drawn: {', '.join(dict.fromkeys(ignored))}", stacklevel=3)
    return placed


def scene_meshes(scene: Any, source: str = "scene") -> List[Mesh]:
    """A ``trimesh.Scene`` as :class:`toonmesh.Mesh` objects (see :func:`load`)."""
    return [_mesh_of(s, t) for s, t in scene_surfaces(scene, source)]


def is_scene(value: Any) -> bool:
    """Whether ``value`` is a ``trimesh.Scene`` (without importing trimesh)."""
    return hasattr(value, "graph") and hasattr(value, "geometry")


#: The colour of the material under a file's own colours (they multiply it): white, so that
#: they show as the file has them.
OWN_COLOURS_WHITE = "#ffffff"


def carries_colour(mesh: Any) -> bool:
    """Whether a :class:`toonmesh.Mesh` has colours or a texture of its own."""
    return any(k in getattr(mesh, "colors", {}) for k in ("vertex_colors", "face_colors", "texture"))


def under_own_colours(meshes: List[Any], material: Any) -> List[Any]:
    """``meshes`` with ``material`` on those that carry their own colours and name no material
    (copies of those: the caller's meshes are left as they are)."""
    out = []
    for m in meshes:
        if isinstance(m, Mesh) and m.material is None and carries_colour(m):
            m = copy.copy(m)
            m.material = material
        out.append(m)
    return out


def _mesh_of(surface: Surface, transform: Optional[np.ndarray], up: Optional[str] = None) -> Mesh:
    """The one place a :class:`Surface` becomes a :class:`toonmesh.Mesh`."""
    return Mesh(surface.vertices, surface.faces, transform=transform, normals=surface.normals, up=up,
                name=surface.name, **surface.colors)


def _file_normals(geom: Any, surface: Surface, path: str) -> Optional[np.ndarray]:
    """The vertex normals trimesh read from the file for ``geom`` (in its cache before anything
    computes them), or None; a file whose normals the core refuses (a zero or non-finite one) is
    named in a warning and drawn with the default normals."""
    cache = getattr(geom, "_cache", None)
    given = cache["vertex_normals"] if cache is not None and "vertex_normals" in cache else None
    if given is None or len(given) != len(surface.vertices):
        return None
    normals = np.asarray(given, dtype=np.float64)
    try:
        normal_mode(normals, len(surface.vertices))
    except ValueError as exc:
        where = f" (mesh {surface.name!r})" if surface.name else ""
        warnings.warn(f"{path}{where}: the file's {exc}; drawn with the default normals", stacklevel=4)
        return None
    return normals


# ------------------------------------------------------------------------------------------------


def _path(path: Any) -> str:
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path: expected a file path (str or os.PathLike), got {type(path).__name__}")
    path = os.fspath(path)
    if not isinstance(path, str):
        raise TypeError("path: expected a str path, got bytes")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such file")
    if os.path.isdir(path):
        raise IsADirectoryError(f"{path}: is a folder, not a mesh file")
    return path


def _read(path: str, data: bytes, keep_seams: bool, ignored: List[str], said: List[str],
          ) -> Tuple[Any, bool, List["Points | Lines"]]:
    """The file (its bytes ``data``, read once) as trimesh reads it (a Trimesh or Scene; None
    for a file of points or lines alone), after the pre-scans; whether its materials are the
    file's (an OBJ without an MTL gets trimesh's placeholder); and its points and lines, read
    by toonmesh (:mod:`toonmesh.files._points_lines`). What the pre-scans find and does not
    stop the reading goes to ``said``."""
    trimesh = trimesh_module()
    suffix = os.path.splitext(path)[1].lower()
    check_kind(path, suffix, data)
    extra: Dict[str, Any] = {}
    materials = True
    others: List["Points | Lines"] = []
    if suffix == ".xyz":  # points alone, one a row
        return None, materials, _points_lines.xyz_items(path, data)
    if suffix == ".obj":
        data = join_continued(data)  # statements continued over lines (a backslash at the end)
        counts = check_obj(path, data)
        if counts["materials"] > MAX_MATERIALS:
            raise MeshFileError(f"{path}: {counts['materials']:,} materials ('usemtl' names); toonmesh reads at "
                                f"most {MAX_MATERIALS:,} materials a file")
        notes, textured = obj_file_notes(path, data)
        said += counts["notes"] + notes
        if "mesh" in counts:  # positions and triangles alone: the checks' scan read them (trimesh read them again)
            return trimesh.Trimesh(*counts["mesh"], process=False), False, others
        if not counts["faces"] or _points_lines.obj_has_points_or_lines(data):
            others = _points_lines.obj_items(path, data, counts["faces"])
            if not counts["faces"]:
                return None, False, others
        if counts["negative"] or counts["drop"] or counts["comments"]:
            data = obj_for_trimesh(data, counts["drop"])
        if counts["polygons"]:  # trimesh splits each as a fan: a concave one is split by ear clipping
            data = _polygons.split_obj(data)
        texcoords, normals = (counts[k] if kind not in counts["drop"] else 0 for k, kind in (("texcoords", b"vt"), ("normals", b"vn")))
        materials = counts["libraries"] > 0
        # positions as listed (not split at texture seams) unless the corners' normals (drawn) or
        # UVs (kept, or drawn with a texture) matter: a vertex gets one of each
        extra["maintain_order"] = not (normals or (keep_seams and texcoords) or (materials and textured))
    header = None
    if suffix == ".ply":
        header = ply_header(path, data)  # parsed once, for every check below
        check_ply(path, header, len(data))
        said += ply_file_notes(path, header) + _ply.colour_notes(path, header, data)
        if _ply.has_strips(header):  # trimesh reads strips as points, or not at all
            V, F, colors = _ply.read(path, header, data)
            return trimesh.Trimesh(V, F, vertex_colors=colors, process=False), materials, others
        if _points_lines.ply_drawn_as_points(header):  # no faces: points (or edges), read here
            return None, materials, _points_lines.ply_items(path, header, data)
    if suffix == ".3mf":  # the production extension's parts, which trimesh places wrong: read here
        produced = _threemf.read(path, data)
        if produced is not None:
            return _threemf_scene(trimesh, *produced), materials, others
    if suffix == ".off":  # read once, here, as trimesh reads it; a concave polygon by ear clipping
        mesh = _polygons.off_mesh(trimesh.util.comment_strip(trimesh.util.decode_text(data)))
        if mesh is not None:
            return trimesh.Trimesh(*mesh, process=False), materials, others
    doc = gltf_document(path, data) if suffix in (".glb", ".gltf") else None
    if doc is not None:
        check_gltf_shape(path, doc)
        said += gltf_file_notes(path, doc)
        _check_gltf_counts(path, doc)
        check_gltf_sizes(path, doc, data)
        said += gltf_colour_notes(path, doc, data)
        ignored.extend(gltf_ignored(doc))
        others = _points_lines.gltf_items(path, doc, data)  # points and lines, read here
        if others and not _points_lines.gltf_has_triangles(doc):
            return None, materials, others
        # fans as triangles, specular-glossiness as base colour, points and lines left out
        data = _gltf.readable(path, doc, data) or data
    try:
        loaded = trimesh.load(io.BytesIO(data), file_type=suffix[1:], process=False, resolver=_Beside(trimesh, path),
                              **extra)
    except MeshFileError:
        raise
    except ModuleNotFoundError as exc:  # trimesh reads some formats (3MF) with packages of their own
        name = exc.name or str(exc).rpartition("No module named ")[2].strip("'\"") or "more packages"
        raise ImportError(f"{path}: reading {suffix or 'this'} files needs {name}: pip install "
                          "'toonmesh[io]'") from None
    except Exception as exc:  # trimesh raises many kinds for files it cannot parse
        ragged = _ragged_ply(trimesh, path, header, data) if header is not None else None
        if ragged is None:
            raise MeshFileError(f"{path}: cannot read a mesh ({_one_line(exc)})") from None
        loaded = ragged
    if suffix == ".stl" and hasattr(loaded, "merge_vertices") and np.isfinite(loaded.vertices).all():
        loaded.merge_vertices()  # an STL stores every corner apart: connect the surface
    if suffix == ".ply" and getattr(loaded, "faces", None) is not None:
        _split_concave(loaded, data, header, path)
    if header is not None and _points_lines.ply_has_edges(header):  # a mesh with edges of its own: lines too
        others = _points_lines.ply_items(path, header, data, points=False)
    return loaded, materials, others


def _threemf_scene(trimesh: Any, geometries: Dict[Any, Tuple[str, np.ndarray, np.ndarray]],
                   placements: List[Tuple[Any, np.ndarray]]) -> Any:
    """A ``trimesh.Scene`` of the geometries and placements :func:`toonmesh.files._threemf.read`
    gives: one geometry per object, one node per placement."""
    scene = trimesh.Scene()
    for name, V, F in geometries.values():
        scene.geometry[name] = trimesh.Trimesh(V, F, process=False)
    for number, (key, transform) in enumerate(placements):
        name = geometries[key][0]
        scene.graph.update(frame_to=f"{name} {number}", frame_from=scene.graph.base_frame, matrix=transform,
                           geometry=name)
    return scene


def _ragged_ply(trimesh: Any, path: str, header: Any, data: bytes) -> Any:
    """A binary PLY whose faces have different numbers of corners (trimesh reads every face
    as long as the first, and refuses the file), read here: positions, vertex colours, and the
    faces as trimesh lays out polygons (:func:`toonmesh.files._polygons.fan_layout`), a concave
    one's by ear clipping; None for any other file trimesh refuses (its reason is then said)."""
    if header.format == "ascii" or _ply.has_strips(header):
        return None
    try:
        found = _ply.values(path, header, data)
    except MeshFileError:
        return None
    vertex, face = found.get("vertex", {}), found.get("face", {})
    polygons = face.get("vertex_indices", face.get("vertex_index"))
    if polygons is None or not all(k in vertex for k in "xyz") or len({len(p) for p in polygons}) < 2:
        return None
    lengths = np.array([len(p) for p in polygons])
    V = np.stack([np.asarray(vertex[k], dtype=np.float64) for k in "xyz"], axis=1)
    if lengths.min() < 3 or any(len(p) and (np.min(p) < 0 or np.max(p) >= len(V)) for p in polygons):
        return None
    fans, rows = _polygons.fan_layout(polygons)
    F = _polygons.split(V, fans, rows, polygons, lengths)
    colors = None
    if all(k in vertex for k in ("red", "green", "blue")):
        rgb = [np.asarray(vertex[k]) for k in ("red", "green", "blue")]
        alpha = np.asarray(vertex["alpha"]) if "alpha" in vertex else np.full(len(V), 255)
        colors = np.stack(rgb + [alpha], axis=1).astype(np.uint8)
    return trimesh.Trimesh(V, fans if F is None else F, vertex_colors=colors, process=False)


def _split_concave(loaded: Any, data: bytes, header: Any, path: str) -> None:
    """A PLY's concave polygons, which trimesh splits as fans (covering what is outside them),
    split by ear clipping instead (:func:`toonmesh.files._polygons.split_fans`). The polygons
    are read again only where trimesh made more triangles than the file has faces."""
    count = next((n for name, n, _ in header.elements if name == "face"), 0)
    if len(loaded.faces) <= count:
        return  # triangles only
    try:
        face = _ply.values(path, header, data).get("face", {})
    except MeshFileError:
        return
    polygons = face.get("vertex_indices", face.get("vertex_index"))
    if polygons is None or len(polygons) != count:
        return
    split = _polygons.split_fans(loaded.vertices, loaded.faces, polygons)
    if split is not None:
        loaded.faces = split


def _Beside(trimesh: Any, path: str) -> Any:
    """trimesh's resolver of the files beside ``path``, finding them as
    :func:`toonmesh.files._checks.asset_path` does (percent-escaped glTF names too), so that what
    the checks found is what trimesh reads."""

    class Beside(trimesh.resolvers.FilePathResolver):  # type: ignore[misc]
        def get(self, name: str) -> bytes:
            found = asset_path(self.parent, name)
            if found is None:
                return super().get(name)  # type: ignore[no-any-return]
            return file_bytes(found)  # opened once: the checks may have read it

    return Beside(path)


def _geometries(loaded: Any) -> Dict[str, Any]:
    return dict(loaded.geometry) if hasattr(loaded, "geometry") else {"": loaded}


_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _ours(w: warnings.WarningMessage) -> bool:
    """Whether a warning caught while reading is toonmesh's own (raised by its code)."""
    return os.path.abspath(w.filename).startswith(_PACKAGE + os.sep) and issubclass(w.category, UserWarning)


@contextlib.contextmanager
def _quiet_trimesh_log() -> Iterator[None]:
    """trimesh's log lines kept from the user while it reads (what they report is checked and
    said by toonmesh, naming the file)."""
    logger = logging.getLogger("trimesh")
    handler = logging.NullHandler()
    propagate, handlers = logger.propagate, logger.handlers[:]
    logger.propagate, logger.handlers = False, [handler]
    try:
        yield
    finally:
        logger.propagate, logger.handlers = propagate, handlers


def _suffix(path: str) -> str:
    return os.path.splitext(path)[1].lower()


def _bytes(path: str) -> bytes:
    try:
        with open(path, "rb") as f:
            return f.read()
    except OSError as exc:
        raise MeshFileError(f"{path}: cannot be read ({exc.strerror or _one_line(exc)})") from None


def _check_gltf_counts(path: str, doc: Dict[str, Any]) -> None:
    placing = sum(1 for n in doc.get("nodes") or [] if "mesh" in n)
    if placing > MAX_INSTANCES:
        raise MeshFileError(f"{path}: {placing:,} nodes place meshes; toonmesh draws at most "
                            f"{MAX_INSTANCES:,} mesh instances a scene")
    for key in ("materials", "images"):  # a texture per face: refused before trimesh decodes them
        n = len(doc.get(key) or [])
        if n > MAX_MATERIALS:
            raise MeshFileError(f"{path}: {n:,} {key}; toonmesh reads at most {MAX_MATERIALS:,} materials a file")


def _placed(loaded: Any, source: str, ignored: List[str], materials: bool = True, needed: bool = True,
            ) -> List[Tuple[Surface, Optional[np.ndarray]]]:
    """Every drawn geometry with its world transform; one Surface per geometry, shared. A scene
    without one is refused unless ``needed`` is False (the file has points or lines)."""
    if not hasattr(loaded, "graph"):  # a single mesh (or point cloud)
        surface = _surface(loaded, source, "", ignored, materials)
        if surface is None:
            if not needed:
                return []
            raise MeshFileError(f"{source}: no triangles in the file")
        return [(surface, None)]
    nodes = list(loaded.graph.nodes_geometry)
    if len(nodes) > MAX_INSTANCES:
        raise MeshFileError(f"{source}: {len(nodes):,} nodes place meshes; toonmesh draws at most "
                            f"{MAX_INSTANCES:,} mesh instances a scene")
    materials = {id(m) for m in (getattr(getattr(g, "visual", None), "material", None)
                                 for g in loaded.geometry.values()) if m is not None}
    if len(materials) > MAX_MATERIALS:
        raise MeshFileError(f"{source}: {len(materials):,} materials; toonmesh reads at most {MAX_MATERIALS:,} "
                            "materials a scene")
    surfaces: Dict[str, Optional[Surface]] = {}
    out: List[Tuple[Surface, Optional[np.ndarray]]] = []
    for node in nodes:
        transform, name = loaded.graph[node]
        if name not in surfaces:
            surfaces[name] = _surface(loaded.geometry[name], source, name, ignored, materials)
        surface = surfaces[name]
        if surface is not None:
            out.append((surface, np.asarray(transform, dtype=np.float64)))
    if not out and needed:
        raise MeshFileError(f"{source}: no triangles in the file")
    return out


def _surface(geom: Any, source: str, name: str, ignored: List[str], materials: bool) -> Optional[Surface]:
    """A Surface of one trimesh geometry; None (and a note in ``ignored``) for one without faces."""
    faces = getattr(geom, "faces", None)
    if faces is None:
        kind = type(geom).__name__
        ignored.append({"PointCloud": "points", "Path3D": "lines", "Path2D": "2D paths"}.get(kind, kind))
        return None
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    vertices = np.asarray(geom.vertices, dtype=np.float64)
    bad = np.flatnonzero(~np.isfinite(vertices).all(axis=1))
    where = f" of mesh {name!r}" if name else ""
    if len(bad):
        raise MeshFileError(f"{source}: vertex {bad[0] + 1}{where} is not finite: {vertices[bad[0]].tolist()}")
    if len(faces) == 0:
        return None
    if faces.min() < 0 or faces.max() >= len(vertices):
        i = int(np.flatnonzero((faces < 0).any(axis=1) | (faces >= len(vertices)).any(axis=1))[0])
        raise MeshFileError(f"{source}: face {i + 1}{where} has an index outside the {len(vertices):,} vertices: "
                            f"{faces[i].tolist()}")
    corners = vertices[faces]
    area = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1).sum() / 2
    diagonal = np.linalg.norm(np.ptp(corners.reshape(-1, 3), axis=0))
    if area <= ZERO_AREA * diagonal**2:
        subject = f"mesh {name!r}" if name else "the mesh"
        warnings.warn(f"{source}: {subject} has no area ({len(faces):,} faces, their corners in a line or at one "
                      "point): nothing to draw", stacklevel=2)
    surface = Surface(vertices, faces, name=name)
    visual = getattr(geom, "visual", None)
    if visual is not None:
        _visual_into(surface, visual, ignored, materials)
        surface.colors = _colors.from_trimesh(geom)  # the renderer's rule (trimesh's placeholder brings nothing)
        ignored.extend(_UNUSED.get(n, n) for n in surface.colors.pop("unused", []))
        if "texture" in surface.colors:  # one array, shared by the geometry's instances
            surface.colors["texture"] = _colors.texture_array(surface.colors["texture"])
    return surface


# what the renderer's colour rule leaves unused, in the words of the warning
_UNUSED = {"emissiveTexture": "emissive maps", "normalTexture": "normal maps", "occlusionTexture": "occlusion maps",
           "metallicRoughnessTexture": "metallic-roughness"}


def _visual_into(surface: Surface, visual: Any, ignored: List[str], materials: bool) -> None:
    """Colours, UVs, texture and base colour of a trimesh visual as the file holds them, for
    writing back (UVs only when ``materials`` is False: the material is trimesh's placeholder)."""
    kind = getattr(visual, "kind", None)
    if kind == "vertex":
        surface.vertex_colors = np.asarray(visual.vertex_colors, dtype=np.uint8)
    elif kind == "face":
        surface.face_colors = np.asarray(visual.face_colors, dtype=np.uint8)
    material = getattr(visual, "material", None)
    if material is None:
        return
    uv = getattr(visual, "uv", None)
    if uv is not None and len(uv) == len(surface.vertices):
        surface.uv = np.asarray(uv, dtype=np.float64)
    if not materials or _colors._placeholder(material):  # trimesh's grey stand-in, not the file's
        return
    factor = getattr(material, "baseColorFactor", None)
    if factor is not None:  # glTF's factor is linear light: the colour as drawn is sRGB
        surface.base_color = np.asarray(factor, dtype=np.float64).ravel()[:4] / 255.0
        surface.base_color[:3] = _core._srgb_from_linear(np.ascontiguousarray(surface.base_color[:3]))
    elif hasattr(material, "diffuse"):  # an MTL's Kd
        surface.base_color = np.asarray(material.diffuse, dtype=np.float64).ravel()[:4] / 255.0
    image = getattr(material, "baseColorTexture", None)
    if image is None:
        image = getattr(material, "image", None)
    if image is not None and surface.uv is not None:
        surface.texture = np.asarray(image.convert("RGBA"))


def _one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__
