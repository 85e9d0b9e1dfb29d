"""Mesh files and images written, for the command line and batch renders.

Meshes are written through trimesh (``pip install toonmesh[io]``), which knows OBJ, PLY,
STL, OFF and GLB/glTF among others. Renders are written as PNG (the colour image) or, when float
outputs (normal, depth) are asked for, as NPZ with every output array and the camera used.
"""

from __future__ import annotations

import io
import os
import tempfile
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from toonmesh import _core
from toonmesh.files._load import Surface, trimesh_module

#: Suffixes written for a render: the colour image alone, or every output array.
IMAGE_SUFFIXES = (".png", ".npz")

#: The format that holds several meshes and their placements (node transforms, one geometry
#: placed several times); the others hold one mesh, written in world space.
SCENE = ".glb"

#: What each format holds of a surface besides positions and triangles, as trimesh writes it
#: (a PLY holds a material colour as vertex colours, when it has no texture).
_HOLDS = {
    ".glb": {"texture coordinates", "texture", "material colour", "vertex colours", "face colours", "normals"},
    ".obj": {"texture coordinates", "texture", "material colour", "vertex colours", "normals"},
    ".ply": {"texture coordinates", "texture", "material colour", "vertex colours", "face colours", "normals"},
    ".off": set(),
    ".stl": set(),
}


@dataclass
class Part:
    """One geometry to write: ``surface`` (its faces, colours, UVs, texture, material colour),
    its ``vertices`` (N, 3) in its own frame, ``normals`` (N, 3) or None, and the world
    ``transforms`` (4x4, or None for none) where the file places it."""

    surface: Surface
    vertices: np.ndarray
    normals: Optional[np.ndarray]
    transforms: List[Optional[np.ndarray]]


def check_writable(path: str, placed: int, source: str) -> None:
    """Refuses, before any work, to write ``placed`` meshes of ``source`` into a format that
    holds one, saying which formats keep them."""
    suffix = os.path.splitext(path)[1].lower()
    if placed > 1 and suffix != SCENE:
        raise ValueError(f"{source} holds {placed} placed meshes and a {suffix or 'file without suffix'} file, as "
                         f"written here, one: write a {SCENE}, which keeps each mesh, its colours and its place "
                         f"(-o {os.path.splitext(path)[0]}{SCENE})")


def check_not_input(path: str, source: str, force: bool = False) -> None:
    """Refuses, before any work, to write over the file being read (unless ``force``)."""
    if not force and os.path.exists(path) and os.path.exists(source) and os.path.samefile(path, source):
        raise ValueError(f"-o: {path} is the file being read: writing it would replace it (give another -o, or "
                         "--force to replace it)")


def write_parts(path: str, parts: List[Part], force: bool = False) -> List[str]:
    """Writes the parts; the format follows the file name's suffix (.obj, .ply, .stl, .off,
    .glb, ...). Their texture coordinates, texture, material colour, vertex or face colours and
    normals go along where the format holds them; an OBJ's or PLY's texture (and an OBJ's MTL,
    when it has a texture or a material colour) is written beside the file, named after it
    (``OUT.png``, ``OUT.mtl``), so that two results in one folder keep their own; a mesh
    without a texture gets none. A file beside it that is there already (not written by this
    call: the input's MTL, another file's texture) is not replaced unless ``force``: a
    ValueError names it, before anything is written. Each file is written to a temporary file
    in its folder and renamed into place, so that an error leaves no file half written. A GLB
    holds several parts (their textures inside it) and keeps their placements; the other
    formats hold one, written in world space. Returns what the format does not hold (and so was
    not written), in words, for the caller's warning."""
    trimesh = trimesh_module()
    suffix = os.path.splitext(path)[1].lower()
    stem = os.path.splitext(os.path.basename(path))[0]
    folder = os.path.dirname(os.path.abspath(path))
    check_writable(path, sum(len(p.transforms) for p in parts), path)
    lost: List[str] = []
    meshes = []
    for k, part in enumerate(parts):
        name = stem if len(parts) == 1 else f"{stem}-{k + 1}"
        mesh = trimesh.Trimesh(np.asarray(part.vertices), np.asarray(part.surface.faces), process=False,
                               vertex_normals=part.normals)
        visual, dropped = _visual(trimesh, part.surface, suffix, name)
        if visual is not None:
            mesh.visual = visual
        lost += dropped + [w for w in _carried(part) if w not in _HOLDS.get(suffix, set())]
        meshes.append((name, mesh, part))
    beside: Dict[str, bytes] = {}
    try:
        if suffix == SCENE:
            scene = trimesh.Scene()
            for name, mesh, part in meshes:
                for i, transform in enumerate(part.transforms):
                    scene.add_geometry(mesh, geom_name=name, node_name=f"{name}-{i + 1}", transform=transform)
            data = scene.export(file_type=suffix[1:])
        else:  # one mesh, where it is placed
            (_, mesh, part), = meshes
            mesh = _placed_copy(mesh, part.transforms[0])
            if suffix == ".obj":  # its MTL and texture go beside it, named after it
                data, beside = trimesh.exchange.obj.export_obj(
                    mesh, include_normals=part.normals is not None, include_texture=mesh.visual.kind == "texture",
                    return_texture=True, mtl_name=stem + ".mtl", header=None)
                if part.surface.texture is None:  # trimesh writes a grey placeholder texture: none is
                    data, beside = _obj_without_texture(data, beside, _material_colour(part.surface))
            else:
                data = mesh.export(file_type=suffix[1:])
                if suffix == ".ply" and part.surface.texture is not None and mesh.visual.kind == "texture":
                    data, beside = _ply_with_texture(data, stem, part.surface.texture)
                elif suffix == ".ply":  # trimesh names a texture for texture coordinates: none is written
                    data = _without_lines(data, b"comment TextureFile")
    except Exception as exc:
        raise ValueError(f"{path}: cannot write this format ({_one_line(exc)})") from None
    there = [name for name in beside if os.path.exists(os.path.join(folder, name))]
    if there and not force:
        raise ValueError(f"-o: writing {path} would replace {', '.join(os.path.join(folder, n) for n in there)}, "
                         "not written by this run (give another -o, or --force to replace)")
    blobs = {os.path.join(folder, name): blob for name, blob in beside.items()}
    blobs[os.path.abspath(path)] = data if isinstance(data, bytes) else data.encode()
    _write_all(blobs)
    return list(dict.fromkeys(lost))


def _write_all(blobs: Dict[str, bytes]) -> None:
    """Writes each file through a temporary file in its folder, renamed into place once all
    are written (an error leaves the files that were there as they were)."""
    temporary: Dict[str, str] = {}
    try:
        for target, blob in blobs.items():
            fd, temp = tempfile.mkstemp(prefix="." + os.path.basename(target) + ".", suffix=".tmp",
                                        dir=os.path.dirname(target))
            temporary[target] = temp
            with os.fdopen(fd, "wb") as f:
                f.write(blob)
            mode = os.stat(target).st_mode & 0o777 if os.path.exists(target) else 0o666 & ~_umask()
            os.chmod(temp, mode)
        for target, temp in temporary.items():
            os.replace(temp, target)
    except BaseException:
        for temp in temporary.values():
            if os.path.exists(temp):
                os.remove(temp)
        raise


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _without_lines(data: bytes, start: bytes) -> bytes:
    """``data`` without its lines that start with ``start``."""
    return b"".join(line for line in data.splitlines(keepends=True) if not line.startswith(start))


def _obj_without_texture(data: Any, beside: Dict[str, bytes], coloured: bool) -> Tuple[Any, Dict[str, bytes]]:
    """An OBJ that trimesh wrote for texture coordinates without a texture, as it should be:
    no image, its MTL without ``map_Kd`` (and with no colour but the surface's), or no MTL at
    all (its ``mtllib`` and ``usemtl`` lines dropped) where the surface has no material colour."""
    text = data if isinstance(data, bytes) else data.encode()
    mtl = {name: blob for name, blob in beside.items() if name.endswith(".mtl")}
    if not coloured:
        return _without_lines(_without_lines(text, b"mtllib"), b"usemtl"), {}
    return text, {name: _without_lines(blob, b"map_Kd") for name, blob in mtl.items()}


def _placed_copy(mesh: Any, transform: Optional[np.ndarray]) -> Any:
    """``mesh`` in world space (its normals turned with it), or itself for no transform."""
    if transform is None or np.array_equal(transform, np.eye(4)):
        return mesh
    return mesh.copy().apply_transform(transform)


def _carried(part: Part) -> List[str]:
    """What a part carries besides positions and triangles, in the words of the warning."""
    s = part.surface
    return [what for what, there in (
        ("texture coordinates", s.uv is not None), ("texture", s.texture is not None),
        ("material colour", _material_colour(s)), ("vertex colours", s.vertex_colors is not None),
        ("face colours", s.face_colors is not None), ("normals", part.normals is not None)) if there]


def _material_colour(surface: Surface) -> bool:
    """Whether the surface's material colour changes how it is drawn: the renderer's rule folds
    it into the colours (white, trimesh's default and an OBJ's Kd under a texture it does not)."""
    return surface.base_color is not None and surface.vertex_colors is None and "vertex_colors" in surface.colors


def _ply_with_texture(data: bytes, stem: str, texture: np.ndarray) -> Tuple[bytes, Dict[str, bytes]]:
    """A PLY naming its texture as MeshLab and trimesh read it (``comment TextureFile``), and
    the texture as PNG bytes, named after the file."""
    from PIL import Image

    name = stem + ".png"
    at = data.index(b"\n", data.index(b"format")) + 1
    png = io.BytesIO()
    Image.fromarray(texture).save(png, format="PNG")
    return data[:at] + f"comment TextureFile {name}\n".encode() + data[at:], {name: png.getvalue()}


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


def _visual(trimesh: Any, surface: Surface, suffix: str, name: str) -> Tuple[Any, List[str]]:
    """A trimesh visual holding a Surface's UVs, texture and material colour (a material named
    ``name``: an OBJ's texture is written as ``name.png``), or its colours; and what it leaves
    out (a visual holds a material or colours, not both). A GLB's material colour is written
    as glTF's linear factor; a PLY's, without a texture, as vertex colours."""
    colours = [w for w, c in (("vertex colours", surface.vertex_colors), ("face colours", surface.face_colors))
               if c is not None]
    tinted = _material_colour(surface)
    if suffix == ".ply" and surface.texture is None and tinted and not colours:
        rgba = np.round(np.clip(surface.base_color, 0, 1) * 255).astype(np.uint8)  # drawn the same
        lost = [] if surface.uv is None else ["texture coordinates (a material colour is written as vertex colours)"]
        return trimesh.visual.ColorVisuals(vertex_colors=np.tile(rgba, (len(surface.vertices), 1))), lost
    if surface.uv is not None or tinted:
        image = None
        if surface.texture is not None:
            from PIL import Image

            image = Image.fromarray(surface.texture)
        colour = None if surface.base_color is None else np.clip(surface.base_color, 0, 1)
        if suffix == SCENE:  # a factor multiplies the texture in glTF: written only where it is drawn
            factor = None if not tinted else np.concatenate([linear_from_srgb(colour[:3]), colour[3:]])
            material = trimesh.visual.material.PBRMaterial(
                name=name, baseColorTexture=image,
                baseColorFactor=None if factor is None else np.round(factor * 255).astype(np.uint8))
        else:
            kw: Dict[str, Any] = {}
            if colour is not None:
                kw["diffuse"] = np.round(colour * 255).astype(np.uint8)
            material = trimesh.visual.material.SimpleMaterial(image=image, name=name, **kw)
        lost = colours + (["material colour"] if suffix == ".ply" and tinted else [])  # PLY: no materials
        return trimesh.visual.TextureVisuals(uv=surface.uv, material=material), lost
    if surface.vertex_colors is not None:
        return trimesh.visual.ColorVisuals(vertex_colors=surface.vertex_colors), colours[1:]
    if surface.face_colors is not None:
        return trimesh.visual.ColorVisuals(face_colors=surface.face_colors), []
    return None, []


def linear_from_srgb(values: np.ndarray) -> np.ndarray:
    """sRGB values in [0, 1] as linear light (the inverse of the renderer's
    ``_core._srgb_from_linear``): glTF's base colour factor is linear."""
    v = np.asarray(values, dtype=np.float64)
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


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
