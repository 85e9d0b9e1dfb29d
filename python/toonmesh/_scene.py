"""The scene as Python describes it: :class:`Mesh` (geometry, material, transform, normal mode and
colour), :class:`MeshHandle` (a mesh already on a renderer's device) and the normal modes.

This is the bottom of the rendering layers: files (:mod:`toonmesh._load`) make meshes and the
renderer (:mod:`toonmesh._render`) draws them; both take them from here, so that neither needs
the other to describe a scene.
"""

from __future__ import annotations

from typing import Any, Dict, Optional, Tuple, Union

import numpy as np

from toonmesh import _colors, _core
from toonmesh._core import Material
from toonmesh._input import mesh_arrays

#: A normal mode: ``"smooth"``, ``"flat"``, ``"auto"`` or ``("auto", crease angle in degrees)``.
Normals = Union[str, Tuple[str, float]]


class MeshHandle:
    """A mesh uploaded to a :class:`Renderer` (see :meth:`Renderer.add_mesh`)."""

    def __init__(self, renderer: Any, mesh_id: int, n_vertices: int, n_faces: int, normals: Normals):
        self.renderer = renderer  # the toonmesh.Renderer that holds it (Any: this module sits below that one)
        self.id = mesh_id
        self.n_vertices = n_vertices
        self.n_faces = n_faces
        self.normals = normals

    def __repr__(self) -> str:
        return f"MeshHandle(id={self.id}, vertices={self.n_vertices}, faces={self.n_faces}, normals={self.normals!r})"


class Mesh:
    """A mesh placed in a scene: geometry, material, transform and normal mode.

    ``vertices`` is an (N, 3) float32/float64 array with ``faces`` (M, 3) int32/int64/uint32, a
    ``trimesh.Trimesh`` (faces None), or a :class:`MeshHandle` already on a renderer's device.
    ``material``: a :class:`Material` (default: the render's ``material``). ``transform`` is a
    4x4 affine model -> world matrix (row-major, applied to column vectors).

    ``normals`` says how the surface is shaded between vertices:

    - ``"smooth"`` (default): area-weighted vertex normals, interpolated across faces. Curved
      surfaces look curved, and so do a box's edges (bands bend across its corners).
    - ``"flat"``: one normal per face; curved surfaces show their facets.
    - ``"auto"``: smooth, but with vertices split where faces meet at more than 30 degrees (the
      crease angle of :class:`Outlines`, so shading breaks where crease lines are drawn) and at
      boundary and non-manifold edges, as Blender's auto smooth does: boxes, chess pieces and
      CAD parts get hard edges and smooth curved parts. ``("auto", degrees)`` sets the angle
      (0 to 180). On a finely tessellated smooth mesh it gives the smooth normals bit for bit;
      on a noisy scan (the bunny) it sharpens the few folds sharper than the angle, which is why
      it is not the default.

    Colour (see docs/colour.md); the surface's albedo is the product of its
    colour and its texture sample, decoded from sRGB to linear light, and multiplies the
    material's colour (its ambient and diffuse, the paper of hatching) in every model:

    - ``vertex_colors``: (N, 3) or (N, 4) sRGB(A), uint8 codes or floats in [0, 1],
      interpolated across faces; or ``face_colors``: (M, 3) or (M, 4), flat per face (not
      both). Default None: white.
    - ``uv``: (N, 2) float texture coordinates, u to the right and v up (v = 0 is the image's
      bottom row, as in OBJ files and trimesh; trimesh turns glTF's v-down coordinates over
      when it loads them), with ``texture``: an (H, W, 3) or (H, W, 4) sRGB(A) image, uint8
      or floats in [0, 1] (kept as 8-bit codes), top row first, or a PIL image. Each needs
      the other. A texture larger than the device's ``max_texture_size`` is halved until it
      fits, with a warning.
    - ``texture_filter``: ``"linear"`` (default: bilinear, trilinear between mip levels made
      by a 2x2 box filter) or ``"nearest"`` (the nearest texel of the full-size image);
      ``texture_wrap``: ``"repeat"`` (default), ``"clamp"`` or ``"mirror"`` (glTF's sampler).
    - ``alpha_cutoff``: in [0, 1]: pixels whose alpha (colour alpha times texture alpha) is
      below it are not drawn (glTF's alpha mask); default None: alpha is ignored.

    A ``trimesh.Trimesh`` brings its own colour: vertex or face colours, or its texture (uv and
    the material's image; for a glTF material, its base colour texture, base colour factor and
    alpha mask). Colour keywords given replace it. Whatever is given or carried but not drawn
    is named in a ``UserWarning``.
    """

    def __init__(
        self,
        vertices: Any,
        faces: Any = None,
        *,
        material: Optional[Material] = None,
        transform: Optional[Any] = None,
        normals: Normals = "smooth",
        vertex_colors: Any = None,
        face_colors: Any = None,
        uv: Any = None,
        texture: Any = None,
        texture_filter: Optional[str] = None,
        texture_wrap: Optional[str] = None,
        alpha_cutoff: Optional[float] = None,
    ):
        self.handle: Optional[MeshHandle] = vertices if isinstance(vertices, MeshHandle) else None
        given = dict(
            vertex_colors=vertex_colors, face_colors=face_colors, uv=uv, texture=texture,
            texture_filter=texture_filter, texture_wrap=texture_wrap, alpha_cutoff=alpha_cutoff,
        )
        if self.handle is not None:
            if faces is not None:
                raise TypeError("faces: must be None when vertices is a MeshHandle")
            named = [k for k, v in given.items() if v is not None]
            if named:
                raise TypeError(f"{named[0]}: a MeshHandle has its colour already (give it to Renderer.add_mesh)")
            self.vertices: Optional[np.ndarray] = None
            self.faces: Optional[np.ndarray] = None
            self.colors: Dict[str, Any] = {}
        else:
            self.vertices, self.faces = mesh_arrays(vertices, faces)
            self.colors = _colors.gather(vertices, given, "Mesh")
        if material is not None and not isinstance(material, Material):
            raise TypeError(f"material: expected a toonmesh.Material, got {type(material).__name__}")
        self.material = material
        self.transform: Optional[np.ndarray] = None if transform is None else _core._transform(transform)
        self.normals: Normals = normal_mode(normals)


def normal_mode(normals: Any) -> Normals:
    """``normals`` checked by the core, in its shortest spelling (``("auto", 30)`` is ``"auto"``)."""
    return _core._normal_mode(normals)  # type: ignore[no-any-return]


def geometry_key(mesh: Mesh) -> Tuple[Any, ...]:
    """What a mesh's upload depends on: its arrays and colour arrays (by identity; they live as
    long as the scene's Mesh objects do, so ids are not reused meanwhile), its colour settings
    and its normal mode. Meshes with equal keys (instances of one geometry) share one upload."""
    colors = tuple(sorted((k, id(v)) for k, v in mesh.colors.items()))  # any value, hashable or not
    return (id(mesh.vertices), id(mesh.faces), mesh.normals, colors)
