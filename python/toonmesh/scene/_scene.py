"""The scene as Python describes it: :class:`Mesh` (geometry, material, transform, normals, up
axis and colour), :class:`MeshHandle` (a mesh already on a renderer's device) and the normal modes.

This is the bottom of the rendering layers: files (:mod:`toonmesh.files._load`) make meshes and the
renderer (:mod:`toonmesh.rendering._render`) draws them; both take them from here, so that neither needs
the other to describe a scene.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Dict, Optional, Tuple, Union

import numpy as np

from toonmesh import _core
from toonmesh.scene import _colors
from toonmesh._core import Material
from toonmesh.arguments._input import mesh_arrays

if TYPE_CHECKING:
    from typing_extensions import Unpack

    from toonmesh.scene._colors import MeshColors

#: Normals: a mode, ``"smooth"``, ``"flat"``, ``"auto"`` or ``("auto", crease angle in degrees)``;
#: the mesh's own, an (N, 3) float array; or None, the core's default (``"auto"``).
Normals = Union[str, Tuple[str, float], np.ndarray, None]


class MeshHandle:
    """A mesh uploaded to a :class:`Renderer` (see :meth:`Renderer.add_mesh`)."""

    def __init__(self, renderer: Any, mesh_id: int, n_vertices: int, n_faces: int, normals: Normals):
        self.renderer = renderer  # the toonmesh.Renderer that holds it (Any: this module sits below that one)
        self.id = mesh_id
        self.n_vertices = n_vertices
        self.n_faces = n_faces
        self.normals = normals

    def __repr__(self) -> str:
        normals = "own" if own_normals(self.normals) else repr(self.normals)
        return f"MeshHandle(id={self.id}, vertices={self.n_vertices}, faces={self.n_faces}, normals={normals})"


class Mesh:
    """A mesh placed in a scene: geometry, material, transform, normals and up axis.

    A render's fitted camera keeps the scene's up axis up: its ``up`` option, else its meshes'
    (which must agree), else y.

    Args:
        vertices: an (N, 3) float32/float64 array, a ``trimesh.Trimesh`` (faces None), or a
            :class:`MeshHandle` already on a renderer's device.
        faces: (M, 3) int32/int64/uint32 with ``vertices`` given as an array; else None.
        material: a :class:`Material`; None (default): the render's ``material``.
        transform: a 4x4 affine model -> world matrix (row-major, applied to column vectors);
            None (default): the render's ``transform``.
        normals: how the surface is shaded between vertices; see below. None (default):
            ``"auto"``.
        up: the axis that is up for this mesh, ``"x"``, ``"y"`` or ``"z"``
            (:func:`toonmesh.load` sets its file format's convention); None (default): the mesh
            names none.
        name: what the mesh is called (default ``""``; :func:`toonmesh.load` gives each mesh
            its geometry's name in the file); :class:`toonmesh.Viewer`'s parts list shows it.
        **colors: the colour keywords below.

    ``normals`` says how the surface is shaded between vertices:

    - None (default): ``"auto"``, the core's default.
    - an (N, 3) float32/float64 array: the mesh's own vertex normals (a file's), one a vertex,
      finite and not zero (scaled to unit length), interpolated across faces. After smoothing
      (``smooth_iterations``) they no longer fit the surface: the default is used, with a warning.
    - ``"smooth"``: area-weighted vertex normals, interpolated across faces. Curved surfaces
      look curved, and so do a box's edges (bands bend across its corners).
    - ``"flat"``: one normal per face; curved surfaces show their facets.
    - ``"auto"``: smooth, but with vertices split where faces meet at more than 30 degrees (the
      crease angle of :class:`Outlines`) and at boundary and non-manifold edges, as Blender's
      auto smooth does, except where the creases are a scan's noise: pieces of crease shorter
      than 2% of the bounding-box diagonal or zig-zagging (the crease lines a drawing keeps, so
      shading breaks where crease lines are drawn). Boxes, chess pieces and CAD parts get hard
      edges and smooth curved parts; scans stay smooth. ``("auto", degrees)`` sets the angle (0
      to 180). On a finely tessellated smooth mesh it gives the smooth normals bit for bit.

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
    - ``alpha_blend``: bool, default False. True: a pixel's opacity is the material's
      ``opacity`` times its alpha (colour alpha times texture alpha), and the mesh is drawn as
      glass, composited in depth order over what lies behind it (glTF's alpha blend; an MTL
      material's ``d`` or ``Tr``).

    A ``trimesh.Trimesh`` brings its own colour: vertex or face colours, or its texture (uv and
    the material's image; for a glTF material, its base colour texture, base colour factor,
    alpha mask and alpha blend; for an MTL material, its ``d`` or ``Tr``). Colour keywords given replace it. Whatever is given or carried but not drawn
    is named in a ``UserWarning``.
    """

    def __init__(
        self,
        vertices: Any,
        faces: Any = None,
        *,
        material: Optional[Material] = None,
        transform: Optional[Any] = None,
        normals: Normals = None,
        up: Optional[str] = None,
        name: str = "",
        **colors: "Unpack[MeshColors]",
    ):
        if not isinstance(name, str):
            raise TypeError(f"name: expected a str, got {type(name).__name__}")
        self.name = name
        self.handle: Optional[MeshHandle] = vertices if isinstance(vertices, MeshHandle) else None
        if self.handle is not None:
            if faces is not None:
                raise TypeError("faces: must be None when vertices is a MeshHandle")
            named = list(_colors.given(colors, "Mesh"))
            if named:
                raise TypeError(f"{named[0]}: a MeshHandle has its colour already (give it to Renderer.add_mesh)")
            self.vertices: Optional[np.ndarray] = None
            self.faces: Optional[np.ndarray] = None
            self.colors: Dict[str, Any] = {}
        else:
            self.vertices, self.faces = mesh_arrays(vertices, faces)
            self.colors = _colors.gather(vertices, colors, "Mesh")
        if material is not None and not isinstance(material, Material):
            raise TypeError(f"material: expected a toonmesh.Material, got {type(material).__name__}")
        self.material = material
        self.transform: Optional[np.ndarray] = None if transform is None else _core._transform(transform)
        # the vertices' own checks come at upload: here only their count, for normals of their own
        n_vertices = self.handle.n_vertices if self.handle is not None else int(np.shape(self.vertices)[0] if np.ndim(self.vertices) else 0)
        self.normals: Normals = normal_mode(normals, n_vertices)
        self.up: Optional[str] = _core._up_axis(up)
        #: The file the mesh was read from (set by :func:`toonmesh.load`; "" for none): the
        #: warnings of its upload name it.
        self.source = ""


def normal_mode(normals: Any, n_vertices: int) -> Normals:
    """``normals`` for a mesh of ``n_vertices`` checked by the core: a mode in its shortest
    spelling (``("auto", 30)`` is ``"auto"``, None the default mode), or the array itself."""
    return _core._normal_mode(normals, n_vertices)  # type: ignore[no-any-return]


def own_normals(normals: Normals) -> bool:
    """Whether ``normals`` are a mesh's own (an array), not a mode."""
    return isinstance(normals, np.ndarray)


def geometry_key(mesh: Mesh) -> Tuple[Any, ...]:
    """What a mesh's upload depends on: its arrays and colour arrays (by identity; they live as
    long as the scene's Mesh objects do, so ids are not reused meanwhile), its colour settings
    and its normals (a mode, or its own array by identity). Meshes with equal keys (instances of
    one geometry) share one upload."""
    colors = tuple(sorted((k, id(v)) for k, v in mesh.colors.items()))  # any value, hashable or not
    normals = id(mesh.normals) if own_normals(mesh.normals) else mesh.normals
    return (id(mesh.vertices), id(mesh.faces), normals, colors)
