"""Colour on a mesh: the keywords of :class:`toonmesh.Mesh` and :meth:`toonmesh.Renderer.add_mesh`
about it, and what a ``trimesh.Trimesh`` brings by itself (its vertex or face colours, or its
texture: uv and the material's image, with a glTF material's base colour factor, alpha mask and
alpha blend, and an MTL material's ``d`` or ``Tr``).

Arrays are checked by the core (shape, dtype, range, NaN: errors name the argument); this module
only gathers them and warns about whatever is given but not used.
"""

from __future__ import annotations

import warnings
from typing import Any, Dict, List, Mapping, Optional, TypedDict

import numpy as np

from toonmesh import _core


class MeshColors(TypedDict, total=False):
    """The keywords about a mesh's colour (:class:`toonmesh.Mesh` says what each takes), in the
    order the core takes them. None, or a keyword left out, is not given."""

    vertex_colors: Any
    face_colors: Any
    uv: Any
    texture: Any
    texture_filter: Optional[str]
    texture_wrap: Optional[str]
    alpha_cutoff: Optional[float]
    alpha_blend: Optional[bool]


#: Their names.
KEYS = tuple(MeshColors.__annotations__)
_DATA = KEYS[:4]
# the textures of a glTF material the renderer does not draw with
_PBR_UNUSED = ("emissiveTexture", "normalTexture", "occlusionTexture", "metallicRoughnessTexture")


def texture_array(texture: Any) -> Any:
    """A PIL image as an (H, W, 4) uint8 array (top row first); anything else as given."""
    if hasattr(texture, "convert") and hasattr(texture, "size") and not isinstance(texture, np.ndarray):
        return np.asarray(texture.convert("RGBA"))
    return texture


def _array(value: Any) -> Any:
    if value is None or isinstance(value, np.ndarray) or isinstance(value, (str, bytes)):
        return value
    try:
        return np.asarray(value)
    except Exception:  # ragged lists: the core names the argument
        return value


def _placeholder(material: Any) -> bool:
    """Whether a material is the one trimesh makes for texture coordinates without one (an OBJ
    with ``vt`` lines and no material): a tiny grey image that is no part of the file."""
    from trimesh.visual.material import color_image

    image = getattr(material, "image", None)
    if image is None or getattr(image, "size", None) != color_image().size:
        return False
    return bool(np.array_equal(np.asarray(image.convert("RGBA")), np.asarray(color_image().convert("RGBA"))))


def _default_diffuse() -> Any:
    from trimesh.visual.material import SimpleMaterial

    return SimpleMaterial().diffuse


def _mtl_alpha(material: Any) -> Optional[float]:
    """An MTL material's alpha: ``d`` (dissolve), else 1 - ``Tr``; None when it gives neither
    (or not as a number)."""
    extra = getattr(material, "kwargs", None) or {}
    for key, to_alpha in (("d", lambda v: v), ("tr", lambda v: 1.0 - v)):
        words = extra.get(key)
        try:
            value = float(words[0] if isinstance(words, (list, tuple)) else words)
        except (TypeError, ValueError, IndexError):
            continue
        if np.isfinite(value):
            return float(np.clip(to_alpha(value), 0.0, 1.0))
    return None


def from_trimesh(mesh: Any) -> Dict[str, Any]:
    """The colour keywords a trimesh carries (empty when it has none), and "unused": notes on
    what it carries that is not drawn. Texture coordinates without an image of the file's
    (trimesh's grey placeholder) and trimesh's default material colour bring nothing."""
    visual = getattr(mesh, "visual", None)
    kind = getattr(visual, "kind", None)
    found: Dict[str, Any] = {}
    unused: List[str] = []
    if kind == "vertex":
        found["vertex_colors"] = np.asarray(visual.vertex_colors)
    elif kind == "face":
        found["face_colors"] = np.asarray(visual.face_colors)
    elif kind == "texture":
        material = getattr(visual, "material", None)
        uv = getattr(visual, "uv", None)
        image, factor, own_white = None, None, False
        if hasattr(material, "baseColorTexture"):  # a glTF (PBR) material
            image = material.baseColorTexture
            if material.baseColorFactor is not None:
                # glTF's factor is linear light (alpha aside); the colour keywords take sRGB
                factor = np.asarray(material.baseColorFactor, dtype=np.float64) / 255.0
                factor[:3] = _core._srgb_from_linear(np.ascontiguousarray(factor[:3]))
            if getattr(material, "alphaMode", None) == "MASK":
                cutoff = getattr(material, "alphaCutoff", None)
                found["alpha_cutoff"] = 0.5 if cutoff is None else float(cutoff)  # glTF's default
            elif getattr(material, "alphaMode", None) == "BLEND":
                found["alpha_blend"] = True  # the factor's and the texture's alpha count
            unused += [n for n in _PBR_UNUSED if getattr(material, n, None) is not None]
        elif material is not None and not _placeholder(material):
            # trimesh's SimpleMaterial (OBJ files): the image, else Kd unless it is trimesh's default
            image = getattr(material, "image", None)
            diffuse = getattr(material, "diffuse", None)
            if image is None and diffuse is not None and not np.array_equal(diffuse, _default_diffuse()):
                factor = np.asarray(diffuse, dtype=np.float64) / 255.0
                own_white = bool(np.all(factor == 1.0))  # a white Kd is the file's colour: drawn white
            alpha = _mtl_alpha(material)
            if alpha is not None and alpha < 1.0:
                if factor is None:
                    factor = np.ones(4) if image is not None else np.asarray(diffuse, dtype=np.float64) / 255.0
                factor = np.append(np.asarray(factor, dtype=np.float64)[:3], alpha)
                found["alpha_blend"] = True
        if image is not None and uv is not None:
            found["texture"], found["uv"] = image, np.asarray(uv)
        elif image is not None:
            unused.append("its material's image (the mesh has no uv)")
        if factor is not None and (own_white or not np.all(factor == 1.0)):
            found["vertex_colors"] = np.tile(np.asarray(factor, dtype=np.float64)[:4], (len(mesh.vertices), 1))
    if unused:
        found["unused"] = unused
    return found


def given(colors: Mapping[str, Any], where: str) -> Dict[str, Any]:
    """The colour keywords a caller was given (``**colors``), None values left out; another
    keyword is a TypeError, as for any Python function (``where`` names the function)."""
    for k in colors:
        if k not in KEYS:
            raise TypeError(f"{where}() got an unexpected keyword argument {k!r}")
    return {k: v for k, v in colors.items() if v is not None}


def gather(source: Any, colors: Mapping[str, Any], where: str, stacklevel: int = 3) -> Dict[str, Any]:
    """The colour keywords for a mesh: those of ``colors`` given (see :func:`given`), else the
    trimesh's when `source` is one. Warns (from the caller's caller) about what is given but
    not used."""
    chosen = given(colors, where)
    notes: List[str] = []
    if hasattr(source, "vertices") and hasattr(source, "faces") and hasattr(source, "visual"):
        carried = from_trimesh(source)
        notes += [f"{where}: the trimesh's {n} is not drawn" for n in carried.pop("unused", [])]
        if any(k in chosen for k in _DATA):
            dropped = [k for k in _DATA if k in carried]
            if dropped:
                notes.append(f"{where}: colour keywords given, so the trimesh's own {', '.join(dropped)} are not used")
        else:
            for k, v in carried.items():
                chosen.setdefault(k, v)
    textured = "texture" in chosen
    for k in ("texture_filter", "texture_wrap"):
        if k in chosen and not textured:
            notes.append(f"{k}: not used, the mesh has no texture")
    uncoloured = not any(c in chosen for c in ("vertex_colors", "face_colors", "texture"))
    for k in ("alpha_cutoff", "alpha_blend"):
        if uncoloured and k in chosen and chosen[k] is not False:
            notes.append(f"{k}: not used, the mesh has no colours or texture")
    for n in notes:
        warnings.warn(n, UserWarning, stacklevel=stacklevel)
    if "texture" in chosen:
        chosen["texture"] = texture_array(chosen["texture"])
    return {k: _array(v) if k in _DATA else v for k, v in chosen.items()}
