"""Headless toon rendering: ``toonmesh.render(V, F)`` returns a toon-shaded image as NumPy arrays.

The scene's settings (:class:`Material`, :class:`Light`, :class:`Camera`, :class:`Outlines`,
:class:`LineStyle`) are typed objects of the Rust core: frozen, compared by value, picklable,
with their defaults and checks in one place. Colours are sRGB: ``"#rrggbb"`` or three numbers in
[0, 1]; shading is computed in linear light and the colour output is encoded back to sRGB. See
README "Rendering" for the conventions of every output.
"""

from __future__ import annotations

import contextlib
import copy
import os
import threading
import warnings
from typing import TYPE_CHECKING, Any, Callable, Dict, Iterator, List, Optional, Sequence, Tuple, TypedDict, Union

import numpy as np

from toonmesh import _colors, _core, _load, _strokes
from toonmesh._core import Camera, Dither, Light, LineStyle, Material, Outlines, RenderOptions, Shadows, kang_table
from toonmesh._input import mesh_arrays

if TYPE_CHECKING:
    from typing_extensions import Unpack


class RenderKeywords(TypedDict, total=False):
    """The keywords of :class:`RenderOptions`, and so of :func:`render`,
    :meth:`Renderer.render` and :meth:`Renderer.render_many`. Each has its default in the core;
    a keyword given as None takes it.

    - ``material``: a :class:`Material` for meshes that name none (default
      ``Material.bands()``, Borquez and Yepez's bands);
    - ``transform``: a 4x4 affine model -> world matrix (row-major, applied to column vectors)
      for meshes that give none (default identity);
    - ``camera``: a :class:`Camera` (default ``Camera.fit()``: the scene framed from the front);
    - ``lights``: a :class:`Light` or a list of up to 8 (default ``[Light.key()]``);
    - ``ambient``: the ambient light's sRGB colour (default white);
    - ``background``: sRGB or sRGBA where no mesh is (default opaque white);
    - ``width``, ``height``: the image's size in pixels, 1 to the device's limit (default 512);
    - ``outputs``: any of "color", "normal", "depth", "outline", "lines", "shadow" (default
      ("color",)); only those are computed and read back ("outline" and "lines" need outlines,
      "shadow" a light with ``shadows=True``);
    - ``msaa``: samples per pixel, 1 or 4 (default 1); ``supersample``: render 1 to 4 times
      larger in each direction and average down (default 1); ``band_antialias``: blend across
      each band border and threshold over about one pixel, from the screen-space change of the
      shading term (default True): smooth tone borders at no extra samples; False gives the
      hard borders of the papers' figures;
    - ``outlines``: None (default), "mesh", "image", "both" or an :class:`Outlines`.
    """

    material: Optional[Material]
    transform: Optional[Any]
    camera: Optional[Camera]
    lights: Union[None, Light, Sequence[Light]]
    ambient: Optional[Any]
    background: Optional[Any]
    width: int
    height: int
    outputs: Union[None, str, Sequence[str]]
    msaa: int
    supersample: int
    band_antialias: bool
    outlines: Union[None, str, Outlines]

#: A normal mode: ``"smooth"``, ``"flat"``, ``"auto"`` or ``("auto", crease angle in degrees)``.
Normals = Union[str, Tuple[str, float]]


class MeshHandle:
    """A mesh uploaded to a :class:`Renderer` (see :meth:`Renderer.add_mesh`)."""

    def __init__(self, renderer: "Renderer", mesh_id: int, n_vertices: int, n_faces: int, normals: Normals):
        self.renderer = renderer
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

    Colour (see README "Colour and textures"); the surface's albedo is the product of its
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
        self.normals: Normals = _normal_mode(normals)


def _normal_mode(normals: Any) -> Normals:
    """``normals`` checked by the core, in its shortest spelling (``("auto", 30)`` is ``"auto"``)."""
    return _core._normal_mode(normals)  # type: ignore[no-any-return]


class RenderResult:
    """The images of one render. Arrays are row-major with the top row first.

    - ``color``: (H, W, 4) uint8, sRGB with straight alpha (None unless asked for);
    - ``depth``: (H, W) float32, linear view depth (distance from the camera plane along the
      viewing axis, world units); ``inf`` where no mesh is;
    - ``normal``: (H, W, 3) float32, unit view-space normals (x right, y up, z toward the
      camera), turned toward the camera; (0, 0, 0) where no mesh is;
    - ``outline``: (H, W) float32 ink coverage of the outlines in [0, 1] (the line drawing);
    - ``shadow``: (H, W) float32 visibility of the shadow-casting light in [0, 1]: 1 lit,
      0 in shadow or facing away from the light, fractions at filtered edges, 1 where no mesh is;
    - ``lines``: the visible mesh-space lines, a list of (K, 2) float64 arrays of pixel
      coordinates (x right, y down, origin at the image's top-left corner), with
      ``line_kinds`` naming each one's kind ("silhouette", "boundary", ...) and
      ``line_widths`` the width of its ink at each point, a (K,) float32 array of pixels (the
      kind's width, times the outlines' taper and width by depth where they are used and a
      suggestive contour's strength, as the ink is drawn);
    - ``passes``: every step that ran, in order; ``timings``: seconds per step, with ``frame``
      the whole render; GPU passes are timed on the GPU when ``timing_source`` is ``"gpu"``,
      otherwise only the frame as a whole (``"wall"``);
    - ``view_matrix``, ``projection`` (4x4 float64), ``near``, ``far``: the camera used;
    - ``culled``: per scene mesh, in order, whether its inner sides were skipped. That happens
      only where they cannot show (a closed, consistently wound mesh whose bounding sphere lies
      wholly beyond the near plane), so the image is the same, drawn in about half the time.
    """

    def __init__(self, raw: Dict[str, Any], backend: str, outlines: Optional[Outlines] = None):
        self.color: Optional[np.ndarray] = raw["color"]
        self.normal: Optional[np.ndarray] = raw["normal"]
        self.depth: Optional[np.ndarray] = raw["depth"]
        self.outline: Optional[np.ndarray] = raw["outline"]
        self.shadow: Optional[np.ndarray] = raw["shadow"]
        self.lines: Optional[List[np.ndarray]] = raw["lines"]
        self.line_kinds: Optional[List[str]] = raw["line_kinds"]
        self.line_widths: Optional[List[np.ndarray]] = raw["line_widths"]
        self.passes: List[str] = list(raw["passes"])
        self.timings: Dict[str, float] = dict(raw["timings"])
        self.timing_source: str = "gpu" if raw["gpu_timed"] else "wall"
        self.culled: List[bool] = list(raw["culled"])
        self.view_matrix: np.ndarray = raw["view"]
        self.projection: np.ndarray = raw["proj"]
        self.near: float = raw["near"]
        self.far: float = raw["far"]
        self.backend = backend
        self.outlines = outlines
        self.width: int = raw["width"]
        self.height: int = raw["height"]

    @property
    def total_time(self) -> float:
        """Seconds the whole render took (wall clock)."""
        return float(self.timings["frame"])

    def _color(self) -> np.ndarray:
        if self.color is None:
            raise ValueError("color: this render did not ask for the 'color' output")
        return self.color

    def png_bytes(self) -> bytes:
        """The colour image as PNG file bytes (encoded by the Rust core)."""
        return _core.encode_png_rgba(self._color())

    def save(self, path: Any) -> None:
        """Writes the colour image to ``path`` as PNG (whatever the file name's extension)."""
        data = self.png_bytes()
        with open(path, "wb") as f:
            f.write(data)

    def strokes(
        self, *, smooth: float = _strokes.SMOOTH, simplify: float = _strokes.SIMPLIFY
    ) -> List[Tuple[np.ndarray, np.ndarray, str]]:
        """The visible mesh-space lines as :meth:`svg` draws them: for each of :attr:`lines`, in
        order, ``(points, widths, kind)``: (K, 2) float64 pixel coordinates, (K,) float32 widths
        of the ink in pixels at those points (from :attr:`line_widths`), and the kind's name.

        Args:
            smooth: radius in output pixels (default 0: off) over which each stroke's points are
                averaged along its length (Gaussian weights, sigma a third of the radius), so
                the stroke flows without the facets of the mesh's edges. The ends of a stroke
                stay where they are (the window shrinks toward them), a closed stroke stays
                closed, and no point moves more than ``smooth`` pixels. At most 4096.
            simplify: drop points within this many pixels of the stroke, after smoothing
                (Douglas-Peucker; default 0.25, as :meth:`svg`; 0 keeps every point). Where the
                width varies along a stroke, its edges too stay within the tolerance.
        """
        _strokes.check("drawing", simplify, smooth)
        return self._drawn_strokes(smooth, simplify, by_width=lambda kind: True)

    def _drawn_strokes(
        self, smooth: float, simplify: float, by_width: Callable[[str], bool]
    ) -> List[Tuple[np.ndarray, np.ndarray, str]]:
        if self.lines is None or self.line_kinds is None or self.line_widths is None:
            raise ValueError("lines: this render did not ask for the 'lines' output (outputs=(..., 'lines'))")
        by_widths = [w if by_width(k) else None for w, k in zip(self.line_widths, self.line_kinds)]
        drawn = _strokes.drawn(self.lines, by_widths, smooth, simplify)
        return [(p, w[keep], k) for (p, keep), w, k in zip(drawn, self.line_widths, self.line_kinds)]

    def svg(
        self,
        *,
        order: str = "drawing",
        simplify: float = _strokes.SIMPLIFY,
        smooth: float = _strokes.SMOOTH,
        widths: str = "auto",
    ) -> str:
        """The visible mesh-space lines as an SVG document of the image's size (pixel units),
        one group per kind, one shape per stroke in its kind's colour: a ``<polyline>`` stroked
        at its kind's width, or, where the width varies along the stroke, a filled ``<path>``
        outlining the ink as the render draws it (:attr:`line_widths`).

        Args:
            order: "drawing" (default: the order the renderer found them) or "plotter": within
                each group, each next stroke is the one whose nearer end is closest to where the
                pen stopped, drawn from that end (greedy nearest neighbour, as vpype's
                ``linesort``), so a pen plotter travels little with the pen up.
            simplify: drop points within this many pixels of the stroke (Douglas-Peucker;
                default 0.25: the drawing stays the same to the eye, with a fraction of the
                points and without the sub-pixel wobble of contours traced on scans); 0 keeps
                every point. Filled outlines keep their edges within it too.
            smooth: smooth each stroke over this radius in pixels first (default 0: off; see
                :meth:`strokes`: ends stay, closed strokes stay closed, no point moves more).
            widths: "auto" (default: filled outlines for the kinds whose ink changes width
                along a stroke, with taper, width by depth or a suggestive contour's strength;
                polylines at the kind's width for the others), "kind" (polylines at each kind's
                width, centre lines a pen plotter can draw) or "point" (filled outlines always).
        """
        _strokes.check(order, simplify, smooth, widths)
        return _strokes.svg_document(self.width, self.height, self._svg_groups(order, simplify, smooth, widths))

    def _svg_groups(self, order: str, simplify: float, smooth: float, widths: str) -> List[_strokes.SvgGroup]:
        """The groups of :meth:`svg`'s document: one per kind, in name order."""
        styles = self.outlines.styles if self.outlines is not None else {}
        if self.line_kinds is None or self.line_widths is None:
            raise ValueError("lines: this render did not ask for the 'lines' output (outputs=(..., 'lines'))")
        # the kinds whose ink changes width along a stroke (taper, width by depth, a suggestive
        # contour's strength)
        uneven = {k for w, k in zip(self.line_widths, self.line_kinds) if len(w) and np.ptp(w) > 0}
        filled = lambda kind: widths == "point" or (widths == "auto" and kind in uneven)  # noqa: E731
        strokes = self._drawn_strokes(smooth, simplify, by_width=filled)
        groups: List[_strokes.SvgGroup] = []
        for kind in sorted({k for _, _, k in strokes}):
            style = styles.get(kind) or LineStyle()
            group = _strokes.in_order([(p, w) for p, w, k in strokes if k == kind], order)
            groups.append((kind, style.color, None if filled(kind) else style.width, None, group))
        return groups

    def save_svg(
        self,
        path: Any,
        *,
        order: str = "drawing",
        simplify: float = _strokes.SIMPLIFY,
        smooth: float = _strokes.SMOOTH,
        widths: str = "auto",
    ) -> None:
        """Writes :meth:`svg` (with its ``order``, ``simplify``, ``smooth`` and ``widths``) to
        ``path``."""
        text = self.svg(order=order, simplify=simplify, smooth=smooth, widths=widths)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)

    def to_pil(self) -> Any:
        """The colour image as a ``PIL.Image.Image`` in mode RGBA (needs Pillow)."""
        try:
            from PIL import Image
        except ImportError:
            raise ImportError("to_pil needs Pillow: pip install pillow (or 'toonmesh[io]')") from None

        return Image.fromarray(self._color(), mode="RGBA") if _pil_takes_mode() else Image.fromarray(self._color())

    def _repr_png_(self) -> Optional[bytes]:
        return None if self.color is None else self.png_bytes()

    def __repr__(self) -> str:
        outs = [n for n in _core.OUTPUTS if getattr(self, n) is not None]
        return f"RenderResult({self.width}x{self.height}, outputs={outs}, passes={self.passes}, {self.total_time * 1e3:.1f} ms, {self.backend})"


def _pil_takes_mode() -> bool:
    import PIL

    return tuple(int(x) for x in PIL.__version__.split(".")[:2]) < (11, 3)


def _smoothing_iterations(iterations: Any) -> int:
    """``smooth_iterations`` checked for its type (0 skips smoothing, so it is checked even then)."""
    if isinstance(iterations, (bool, np.bool_)) or not isinstance(iterations, (int, np.integer)):
        raise TypeError(f"smooth_iterations: expected an int, got {type(iterations).__name__}")
    if iterations < 0:
        raise ValueError(f"smooth_iterations: must be >= 0, got {iterations}")
    return int(iterations)


def _smoothed(vertices: np.ndarray, faces: np.ndarray, iterations: int) -> np.ndarray:
    if iterations == 0:
        return vertices
    from toonmesh import smooth

    try:
        return smooth.laplacian(vertices, faces, iterations=iterations, preset="paper")
    except ValueError as exc:  # the core's range of iterations, under this function's name for it
        if str(exc).startswith("iterations:"):
            raise ValueError(f"smooth_{exc}") from None
        raise


class Renderer:
    """Keeps meshes on the GPU so that many views of them upload nothing again.

    ``backend`` is ``"vulkan"``, ``"gl"`` or ``"auto"`` (Vulkan, then GL through EGL); None reads
    the ``TOONMESH_BACKEND`` environment variable, then uses ``"auto"``. The GPU context is made
    once per process and shared. Methods may be called from several threads at once. A renderer
    made before ``os.fork()`` cannot render in the child (its device stays with the parent):
    make a new one there (:func:`render` does so by itself).

    >>> r = Renderer()
    >>> bunny = r.add_mesh(V, F)
    >>> frames = [r.render(bunny, camera=Camera.fit((np.sin(a), 0.3, np.cos(a)))) for a in angles]
    """

    def __init__(self, backend: Optional[str] = None):
        self._engine = _core.Renderer(backend)
        self.info: Dict[str, Any] = self._engine.info

    @property
    def backend(self) -> str:
        """``"vulkan"`` or ``"gl"``."""
        return str(self.info["backend"])

    def add_mesh(
        self,
        vertices: Any,
        faces: Any = None,
        *,
        normals: Normals = "smooth",
        smooth_iterations: int = 0,
        vertex_colors: Any = None,
        face_colors: Any = None,
        uv: Any = None,
        texture: Any = None,
        texture_filter: Optional[str] = None,
        texture_wrap: Optional[str] = None,
        alpha_cutoff: Optional[float] = None,
    ) -> MeshHandle:
        """Uploads a mesh ((N, 3) float32/float64 and (M, 3) int faces, or a trimesh.Trimesh).

        ``normals``: ``"smooth"`` (default), ``"flat"``, ``"auto"`` (split at edges sharper than
        30 degrees) or ``("auto", degrees)``; see :class:`Mesh`. ``smooth_iterations``: Laplacian smoothing
        first (each vertex to the mean of its neighbours, n times), as in Al-Rousan et al.
        ``vertex_colors``, ``face_colors``, ``uv``, ``texture``, ``texture_filter``,
        ``texture_wrap``, ``alpha_cutoff``: the mesh's colour, as :class:`Mesh` describes (a
        trimesh brings its own).
        """
        given = dict(
            vertex_colors=vertex_colors, face_colors=face_colors, uv=uv, texture=texture,
            texture_filter=texture_filter, texture_wrap=texture_wrap, alpha_cutoff=alpha_cutoff,
        )
        return self._add(vertices, faces, normals, smooth_iterations, _colors.gather(vertices, given, "add_mesh"))

    def _add(self, vertices: Any, faces: Any, normals: Normals, smooth_iterations: int, colors: Dict[str, Any]) -> MeshHandle:
        iterations = _smoothing_iterations(smooth_iterations)
        V, F = mesh_arrays(vertices, faces)
        V = _smoothed(V, F, iterations)
        mesh_id, normals, notes = self._engine.add_mesh(V, F, normals, **colors)
        for note in notes:
            warnings.warn(note, UserWarning, stacklevel=3)
        return MeshHandle(self, mesh_id, len(V), len(F), normals)

    def remove_mesh(self, mesh: MeshHandle) -> None:
        """Frees a mesh's GPU memory."""
        if not isinstance(mesh, MeshHandle):
            raise TypeError(f"mesh: expected a toonmesh.MeshHandle, got {type(mesh).__name__}")
        if mesh.renderer is not self:
            raise ValueError("mesh: belongs to another Renderer")
        self._engine.remove_mesh(mesh.id)

    def render(self, meshes: Any = None, **options: "Unpack[RenderKeywords]") -> RenderResult:
        """Renders ``meshes`` (a MeshHandle, a :class:`Mesh`, or a list of them; None or [] for an
        empty scene) with ``options``: the keywords of :class:`RenderOptions` (``width``,
        ``height``, ``material``, ``camera``, ``lights``, ``outputs``, ``outlines``, ...), each
        defaulting as that class says. Only the outputs asked for are computed and read back.
        """
        return self._render(meshes, RenderOptions(**options))

    def _render(self, meshes: Any, options: RenderOptions) -> RenderResult:
        with self._scene(meshes) as specs:
            raw = self._engine.render(specs, options)
        return RenderResult(raw, self.backend, options.outlines)

    def render_many(self, meshes: Any, cameras: Sequence[Camera], **options: "Unpack[RenderKeywords]") -> "RenderStack":
        """Renders the same scene from each of ``cameras`` (a turntable, a dataset sweep),
        keeping a few frames in flight so that the GPU draws one view while the last is read
        back. Returns a :class:`RenderStack`: the views' images stacked, (K, H, W, 4) colour and
        so on, and one :class:`RenderResult` a view (the same bits as rendering each view alone).
        ``options`` as in :meth:`render` (``camera`` is not one of them here).
        """
        if "camera" in options:
            raise TypeError("camera: render_many takes cameras=, a list of them")
        opts = RenderOptions(**options)
        with self._scene(meshes) as specs:
            images, reports = self._engine.render_views(specs, cameras, opts)
        results = []
        for i, raw in enumerate(reports):
            raw.update({k: None if v is None else v[i] for k, v in images.items()})
            results.append(RenderResult(raw, self.backend, opts.outlines))
        return RenderStack(images, results)

    @contextlib.contextmanager
    def _scene(self, meshes: Any) -> Iterator[List[Any]]:
        """The scene's items as the core takes them: meshes not yet on the device are uploaded
        for the render and removed after it."""
        items = [] if meshes is None else (list(meshes) if isinstance(meshes, (list, tuple)) else [meshes])
        uploaded: List[MeshHandle] = []
        # meshes that share their arrays (instances of one geometry) share one upload
        by_arrays: Dict[Tuple[Any, ...], MeshHandle] = {}
        try:
            specs = []
            for i, item in enumerate(items):
                if isinstance(item, MeshHandle):
                    item = Mesh(item)
                elif not isinstance(item, Mesh):
                    raise TypeError(f"meshes[{i}]: expected a toonmesh.Mesh or MeshHandle, got {type(item).__name__}")
                handle = item.handle
                if handle is None:
                    key = _geometry_key(item)
                    handle = by_arrays.get(key)
                    if handle is None:
                        handle = by_arrays[key] = self._add(item.vertices, item.faces, item.normals, 0, item.colors)
                        uploaded.append(handle)
                elif handle.renderer is not self:
                    raise ValueError(f"meshes[{i}]: the MeshHandle belongs to another Renderer")
                specs.append((handle.id, item.material, item.transform))
            yield specs
        finally:
            for h in uploaded:
                self._engine.remove_mesh(h.id)


def _geometry_key(mesh: Mesh) -> Tuple[Any, ...]:
    """What a mesh's upload depends on: its arrays and colour arrays (by identity; they live as
    long as the scene's Mesh objects do, so ids are not reused meanwhile), its colour settings
    and its normal mode."""
    colors = tuple(sorted((k, id(v)) for k, v in mesh.colors.items()))  # any value, hashable or not
    return (id(mesh.vertices), id(mesh.faces), mesh.normals, colors)


class RenderStack(Sequence[RenderResult]):
    """The views of :meth:`Renderer.render_many`: a sequence of :class:`RenderResult`, one a
    camera, whose images are slices of the stacked arrays ``color`` (K, H, W, 4) uint8,
    ``normal`` (K, H, W, 3) float32, ``depth`` (K, H, W) float32, ``outline`` (K, H, W)
    float32 and ``shadow`` (K, H, W) float32 (None for outputs not asked for)."""

    def __init__(self, images: Dict[str, Any], results: List[RenderResult]):
        self.color: Optional[np.ndarray] = images["color"]
        self.normal: Optional[np.ndarray] = images["normal"]
        self.depth: Optional[np.ndarray] = images["depth"]
        self.outline: Optional[np.ndarray] = images["outline"]
        self.shadow: Optional[np.ndarray] = images["shadow"]
        self._results = results

    def __len__(self) -> int:
        return len(self._results)

    def __getitem__(self, i: Any) -> Any:
        return self._results[i]

    def __repr__(self) -> str:
        return f"RenderStack({len(self)} views)"


_renderers: Dict[Optional[str], Renderer] = {}
_renderers_lock = threading.Lock()


def _forget_renderers() -> None:
    """In a forked child: the parent's renderers hold its device; start afresh."""
    global _renderers_lock
    _renderers.clear()
    _renderers_lock = threading.Lock()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forget_renderers)


def shared_renderer(backend: Optional[str] = None) -> Renderer:
    """This process's :class:`Renderer` for ``backend``, made on first use and kept (so that
    :func:`render` and every batch task of a worker share one GPU context and its cached
    pipelines); a forked child starts afresh."""
    if backend is not None and not isinstance(backend, str):  # it is a key here
        raise TypeError(f"backend: expected a string or None, got {type(backend).__name__}")
    with _renderers_lock:
        r = _renderers.get(backend)
        if r is None:
            r = _renderers[backend] = Renderer(backend)
        return r


def render(
    vertices: Any = None,
    faces: Any = None,
    *,
    normals: Normals = "smooth",
    smooth_iterations: int = 0,
    backend: Optional[str] = None,
    **options: "Unpack[RenderKeywords]",
) -> RenderResult:
    """Renders a mesh (or several) to a toon-shaded image, headless, and returns NumPy arrays.

    ``vertices``: (N, 3) float32/float64 with ``faces`` (M, 3) int32/int64/uint32; or a
    ``trimesh.Trimesh``; or a ``trimesh.Scene`` or a mesh file's path (str or os.PathLike),
    read as :func:`toonmesh.load` reads them (every node, its transform and colours); or a
    :class:`Mesh` or list of them (each with its own material and transform); None for an
    empty scene. With no ``material`` given, meshes that carry colours or a texture and name no
    material of their own are drawn under the default shading model in white, so their colours
    show as they are, however they were given. Inputs are never modified. Meshes that share their vertex and face arrays (the
    instances of one geometry) are uploaded once.
    ``normals``: ``"smooth"`` (default), ``"flat"``, ``"auto"`` (split at edges sharper than 30
    degrees: hard edges for boxes and CAD parts) or ``("auto", degrees)``; see :class:`Mesh`.
    ``smooth_iterations``: Laplacian smoothing first (Al-Rousan et al.'s pipeline).
    ``backend`` as in :class:`Renderer`. ``options``: the keywords of :class:`RenderOptions`
    (``width``, ``height``, ``material``, ``camera``, ``lights``, ``outputs``, ``outlines``, ...),
    each defaulting as that class says.

    >>> img = toonmesh.render(V, F, width=640, height=480, outlines="mesh").color   # (480, 640, 4) uint8
    """
    iterations = _smoothing_iterations(smooth_iterations)
    opts = RenderOptions(**options)  # checked before any upload
    if isinstance(vertices, (list, tuple)) and faces is None:
        items: List[Any] = list(vertices)
    elif vertices is None:
        items = []
    elif isinstance(vertices, Mesh):
        items = [vertices]
    elif faces is None and (isinstance(vertices, (str, os.PathLike)) or _load.is_scene(vertices)):
        loaded = _load.load(vertices) if isinstance(vertices, (str, os.PathLike)) else _load.scene_meshes(vertices)
        items = [_with_normals(m, normals) for m in loaded]
    else:
        items = [Mesh(vertices, faces, normals=normals)]  # a trimesh brings its colour
    if options.get("material") is None:  # colours as the mesh has them: under a white material
        white = getattr(Material, opts.material.model)(_load.OWN_COLOURS_WHITE)
        items = _load.under_own_colours(items, white)
    if iterations:
        smoothed: Dict[Tuple[int, int], np.ndarray] = {}  # instances of one geometry: smoothed once, shared
        out = []
        for m in (x if isinstance(x, Mesh) else Mesh(x) for x in items):
            if m.vertices is not None and m.faces is not None:
                key = (id(m.vertices), id(m.faces))
                if key not in smoothed:
                    smoothed[key] = _smoothed(m.vertices, m.faces, iterations)
                m = _with_vertices(m, smoothed[key])
            out.append(m)
        items = out
    return shared_renderer(backend)._render(items, opts)


def _with_vertices(m: Mesh, vertices: np.ndarray) -> Mesh:
    smoothed = copy.copy(m)
    smoothed.vertices = vertices
    return smoothed


def _with_normals(m: Mesh, normals: Normals) -> Mesh:
    m.normals = _normal_mode(normals)  # a mesh just made from a file: nobody else holds it
    return m


def gpu_info(backend: Optional[str] = None) -> Dict[str, Any]:
    """The adapter renders use: ``name``, ``backend`` ("vulkan" or "gl"), ``device_type``
    ("cpu" for Mesa's lavapipe/llvmpipe), ``driver``, ``driver_info``, ``max_texture_size``,
    ``msaa_samples`` and ``timestamps`` (whether passes are timed on the GPU). Creates the
    process-wide GPU context if needed; raises :class:`toonmesh.GpuUnavailableError` when there
    is no adapter.
    """
    return _core.gpu_info(backend)


__all__ = [
    "RenderKeywords",
    "RenderOptions",
    "Camera",
    "Dither",
    "Light",
    "LineStyle",
    "Material",
    "Mesh",
    "MeshHandle",
    "Outlines",
    "RenderResult",
    "RenderStack",
    "Renderer",
    "Shadows",
    "gpu_info",
    "kang_table",
    "render",
]
