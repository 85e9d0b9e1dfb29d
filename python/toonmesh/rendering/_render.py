"""Headless toon rendering: ``toonmesh.render(V, F)`` returns a toon-shaded image as NumPy arrays.

The scene's settings (:class:`Material`, :class:`Light`, :class:`Camera`, :class:`Outlines`,
:class:`LineStyle`) are typed objects of the Rust core: frozen, compared by value, picklable,
with their defaults and checks in one place. Colours are sRGB: ``"#rrggbb"`` or three numbers in
[0, 1]; shading is computed in linear light and the colour output is encoded back to sRGB. See
docs/rendering.md for the conventions of every output.

Every render takes one path: :func:`place_meshes` (or :func:`meshes_on_device` for one render)
puts the scene's meshes on a renderer's device, one upload per geometry, and :func:`draw` or
:func:`draw_views` draws them. :func:`render`, :meth:`Renderer.render`,
:meth:`Renderer.render_many`, :mod:`toonmesh.batch` and the viewer all go through them.
"""

from __future__ import annotations

import contextlib
import copy
import os
import threading
import warnings
from typing import TYPE_CHECKING, Any, Dict, Iterator, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from toonmesh import _core
from toonmesh.scene import _colors
from toonmesh.files import _load
from toonmesh._core import Camera, Light, Material, Outlines, RenderOptions, kang_table
from toonmesh.arguments._input import mesh_arrays
from toonmesh.rendering._results import RenderResult, RenderStack, stack_of
from toonmesh.scene._points import Lines, Points
from toonmesh.scene._scene import Mesh, MeshHandle, Normals, geometry_key, normal_mode, own_normals

if TYPE_CHECKING:
    from typing_extensions import Unpack

    from toonmesh.scene._colors import MeshColors


#: The keywords of :class:`RenderOptions` (a TypedDict made and documented by the core).
RenderKeywords = _core._RenderKeywords


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
    # the core names the iterations as this function's caller does
    return _core._smooth(  # type: ignore[no-any-return]
        "laplacian", (vertices, faces), iterations=iterations, preset="paper", weld=False,
        _as=[("iterations", "smooth_iterations")],
    )


class Renderer:
    """Keeps meshes on the GPU so that many views of them upload nothing again.

    The GPU context is made once per process and shared. Methods may be called from several threads at once. A renderer
    made before ``os.fork()`` cannot render in the child (its device stays with the parent):
    make a new one there (:func:`render` does so by itself).

    Args:
        backend: ``"vulkan"``, ``"gl"`` or ``"auto"`` (Vulkan, then GL through EGL); None
            (default) reads the ``TOONMESH_BACKEND`` environment variable, then uses
            ``"auto"``.

    Examples:
        >>> r = Renderer()
        >>> bunny = r.add_mesh(V, F)
        >>> views = [Camera.fit((np.sin(a), 0.3, np.cos(a))) for a in angles]
        >>> frames = [r.render(bunny, camera=camera) for camera in views]
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
        normals: Normals = None,
        smooth_iterations: int = 0,
        **colors: "Unpack[MeshColors]",
    ) -> MeshHandle:
        """Uploads a mesh, for many views of it.

        Args:
            vertices: (N, 3) float32/float64 positions, or a ``trimesh.Trimesh`` (which brings
                its own colours).
            faces: (M, 3) int faces with ``vertices`` given as an array; else None.
            normals: None (default: ``"auto"``), ``"smooth"``, ``"flat"``, ``"auto"`` (split at
                the creases a drawing keeps, sharper than 30 degrees), ``("auto", degrees)``, or
                the mesh's own (N, 3) vertex normals; see :class:`Mesh`.
            smooth_iterations: Laplacian smoothing first (each vertex to the mean of its
                neighbours, n times), as in Al-Rousan et al.; default 0.
            **colors: ``vertex_colors``, ``face_colors``, ``uv``, ``texture``,
                ``texture_filter``, ``texture_wrap``, ``alpha_cutoff``, ``alpha_blend``: the
                mesh's colour, as :class:`Mesh` describes.

        Returns:
            The uploaded mesh, to render with :meth:`render` or place in a :class:`Mesh`.
        """
        return self._add(vertices, faces, normals, smooth_iterations, _colors.gather(vertices, colors, "add_mesh"))

    def _add(self, vertices: Any, faces: Any, normals: Normals, smooth_iterations: int, colors: Dict[str, Any],
             source: str = "") -> MeshHandle:
        """Every upload goes through here (:meth:`add_mesh`, :func:`place_meshes`): ``colors``
        are colour keywords already gathered; ``source``, the file a mesh was read from, names
        it in the upload's warnings."""
        iterations = _smoothing_iterations(smooth_iterations)
        V, F = mesh_arrays(vertices, faces)
        V = _smoothed(V, F, iterations)
        normals = after_smoothing(normals, iterations > 0, "smooth_iterations")
        mesh_id, normals, notes = self._engine.add_mesh(V, F, normals, **colors)
        for note in notes:
            warnings.warn(f"{source}: {note}" if source else note, UserWarning, stacklevel=3)
        return MeshHandle(self, mesh_id, len(V), len(F), normals)

    def add_points(self, points: Points) -> MeshHandle:
        """Uploads a point cloud as splats, for many views of it.

        The handle places it in a scene like a mesh's (its material, transform and up axis are
        the scene item's: wrap it in a :class:`Mesh` to give them). Normals the cloud lacks are
        estimated here, once, from each point's nearest neighbours
        (:func:`toonmesh.points.normals`).

        Args:
            points: the cloud, a :class:`Points`.

        Returns:
            The uploaded cloud, a :class:`MeshHandle`."""
        if not isinstance(points, Points):
            raise TypeError(f"points: expected a toonmesh.Points, got {type(points).__name__}")
        mesh_id = self._engine.add_points(points.positions, points.normals, points.colors, points.radius, None)
        return MeshHandle(self, mesh_id, 3 * len(points), len(points), None)

    def remove_mesh(self, mesh: MeshHandle) -> None:
        """Frees a mesh's GPU memory.

        Args:
            mesh: a handle this renderer's :meth:`add_mesh` or :meth:`add_points` returned.

        Raises:
            ValueError: ``mesh`` belongs to another renderer.
        """
        if not isinstance(mesh, MeshHandle):
            raise TypeError(f"mesh: expected a toonmesh.MeshHandle, got {type(mesh).__name__}")
        if mesh.renderer is not self:
            raise ValueError("mesh: belongs to another Renderer")
        self._engine.remove_mesh(mesh.id)

    def render(self, meshes: Any = None, **options: "Unpack[RenderKeywords]") -> RenderResult:
        """Renders ``meshes`` with ``options``. Only the outputs asked for are computed and read
        back.

        Args:
            meshes: a :class:`MeshHandle`, a :class:`Mesh`, a :class:`Lines` drawn as ink, or a
                list of them; None (default) or [] for an empty scene.
            **options: the render keywords (:class:`RenderKeywords`: ``width``, ``height``,
                ``material``, ``camera``, ``lights``, ``outputs``, ``outlines``, ...), each with
                its type, default and meaning.

        Returns:
            The images asked for in ``outputs``.
        """
        opts = RenderOptions(**options)
        meshes, lines = split_lines(meshes)
        with meshes_on_device(self, meshes) as placed:
            return draw(self, placed, opts, lines)

    def render_many(self, meshes: Any, cameras: Sequence[Camera], **options: "Unpack[RenderKeywords]") -> "RenderStack":
        """Renders the same scene from each of ``cameras`` (a turntable, a dataset sweep),
        keeping a few frames in flight so that the GPU draws one view while the last is read
        back. Returns a :class:`RenderStack`: the views' images stacked, (K, H, W, 4) colour and
        so on, and one :class:`RenderResult` a view (the same bits as rendering each view alone,
        except for suggestive contours with ``Outlines(suggestive_coherence=True)``, the
        default: between consecutive views whose eye turns by less than 10 degrees about each
        mesh's centre, they fade by how fast they slide across the surface and a line drawn in
        the view before needs a weaker test to stay, so that a turntable's lines hold still;
        views farther apart are drawn as they are alone).

        Args:
            meshes: as in :meth:`render`.
            cameras: the views, a sequence of :class:`Camera`.
            **options: the render keywords (:class:`RenderKeywords`) but ``camera``.

        Returns:
            The views' images and results, a :class:`RenderStack`.
        """
        if "camera" in options:
            raise TypeError("camera: render_many takes cameras=, a list of them")
        opts = RenderOptions(**options)
        meshes, lines = split_lines(meshes)
        with meshes_on_device(self, meshes) as placed:
            return draw_views(self, placed, cameras, opts, lines)


def after_smoothing(normals: Normals, smoothed: bool, how: str) -> Normals:
    """The normals of a mesh whose positions ``how`` moved (``smoothed``): its own normals no
    longer fit them, so the default is used instead, with a warning; a mode stays."""
    if smoothed and own_normals(normals):
        warnings.warn(f"normals: the mesh's own normals do not fit the positions {how} moved; "
                      "drawn with the default normals instead", UserWarning, stacklevel=4)
        return None
    return normals


class PlacedMesh(NamedTuple):
    """A scene item whose geometry is on a renderer's device: what the core draws."""

    handle: MeshHandle
    material: Optional[Material]
    transform: Optional[np.ndarray]
    up: Optional[str] = None


def place_meshes(renderer: Renderer, meshes: Any, smooth_iterations: int = 0,
                 where: str = "meshes") -> Tuple[List[PlacedMesh], List[MeshHandle]]:
    """The scene's items (a :class:`Mesh`, a :class:`Points`, a :class:`MeshHandle`, a list of
    them or None) on ``renderer``'s device, in order, and the handles uploaded for them, which the caller frees
    with :func:`remove_meshes`. Meshes not yet there are uploaded, after ``smooth_iterations``
    of Laplacian smoothing; meshes that share their arrays (instances of one geometry) share one
    upload. ``where`` names the items in errors. Nothing stays uploaded when it fails."""
    items = [] if meshes is None else (list(meshes) if isinstance(meshes, (list, tuple)) else [meshes])
    placed: List[PlacedMesh] = []
    uploaded: List[MeshHandle] = []
    by_geometry: Dict[Tuple[Any, ...], MeshHandle] = {}
    try:
        for i, item in enumerate(items):
            if isinstance(item, MeshHandle):
                item = Mesh(item)
            elif isinstance(item, Points):
                handle = by_geometry.get(("points", id(item)))
                if handle is None:
                    handle = by_geometry[("points", id(item))] = renderer.add_points(item)
                    uploaded.append(handle)
                placed.append(PlacedMesh(handle, item.material, item.transform, item.up))
                continue
            elif not isinstance(item, Mesh):
                raise TypeError(f"{where}[{i}]: expected a toonmesh.Mesh, Points or MeshHandle, "
                                f"got {type(item).__name__}")
            handle = item.handle
            if handle is None:
                key = geometry_key(item)
                handle = by_geometry.get(key)
                if handle is None:
                    handle = renderer._add(item.vertices, item.faces, item.normals, smooth_iterations, item.colors,
                                          getattr(item, "source", ""))
                    by_geometry[key] = handle
                    uploaded.append(handle)
            elif handle.renderer is not renderer:
                raise ValueError(f"{where}[{i}]: the MeshHandle belongs to another Renderer")
            placed.append(PlacedMesh(handle, item.material, item.transform, item.up))
    except BaseException:
        remove_meshes(renderer, uploaded)
        raise
    return placed, uploaded


def remove_meshes(renderer: Renderer, handles: List[MeshHandle]) -> None:
    """Frees the meshes :func:`place_meshes` uploaded."""
    for handle in handles:
        renderer._engine.remove_mesh(handle.id)


@contextlib.contextmanager
def meshes_on_device(renderer: Renderer, meshes: Any, smooth_iterations: int = 0) -> Iterator[List[PlacedMesh]]:
    """:func:`place_meshes` for one render: what it uploads is removed after it."""
    placed, uploaded = place_meshes(renderer, meshes, smooth_iterations)
    try:
        yield placed
    finally:
        remove_meshes(renderer, uploaded)


def _core_items(placed: List[PlacedMesh]) -> List[Tuple[int, Optional[Material], Optional[np.ndarray], Optional[str]]]:
    return [(p.handle.id, p.material, p.transform, p.up) for p in placed]


def split_lines(items: Any) -> Tuple[Any, List[Lines]]:
    """A scene's items (as :meth:`Renderer.render` takes them) parted into its meshes (a list
    where ``items`` was one, as given otherwise) and its :class:`Lines` items, in order."""
    if isinstance(items, Lines):
        return [], [items]
    if not isinstance(items, (list, tuple)):
        return items, []
    return [x for x in items if not isinstance(x, Lines)], [x for x in items if isinstance(x, Lines)]


def _core_lines(lines: Sequence[Lines]) -> List[Tuple[Any, ...]]:
    """The :class:`Lines` items as the core reads them (its checks name ``lines[i]``)."""
    return [(np.asarray(l.positions, np.float64), l.segments, l.transform, l.color, l.width, l.up) for l in lines]


def draw(renderer: Renderer, placed: List[PlacedMesh], options: RenderOptions,
         lines: Sequence[Lines] = ()) -> RenderResult:
    """One view of meshes already on ``renderer``'s device (see :func:`place_meshes`), with
    ``lines`` drawn as ink."""
    images, (report,) = renderer._engine.render(_core_items(placed), options, lines=_core_lines(lines))
    return RenderResult(dict(report, **images), renderer.backend, options.outlines)


def draw_views(renderer: Renderer, placed: List[PlacedMesh], cameras: Sequence[Camera],
               options: RenderOptions, lines: Sequence[Lines] = ()) -> RenderStack:
    """The views of meshes already on ``renderer``'s device from each of ``cameras``, with
    ``lines`` drawn as ink."""
    images, reports = renderer._engine.render(_core_items(placed), options, cameras, lines=_core_lines(lines))
    return stack_of(images, reports, renderer.backend, options.outlines)


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
    normals: Normals = None,
    smooth_iterations: int = 0,
    backend: Optional[str] = None,
    **options: "Unpack[RenderKeywords]",
) -> RenderResult:
    """Renders a mesh (or several) to a toon-shaded image, headless, and returns NumPy arrays.

    Inputs are never modified. Meshes that share their vertex and face arrays (the instances of
    one geometry) are uploaded once. With no ``material`` given, meshes that carry colours or a
    texture and name no material of their own are drawn under the default shading model in
    white, so their colours show as they are, however they were given.

    Args:
        vertices: (N, 3) float32/float64 with ``faces``; or a ``trimesh.Trimesh``; or a
            ``trimesh.Scene`` or a mesh file's path (str or os.PathLike), read as
            :func:`toonmesh.load` reads them (every node, its transform and colours); or a
            :class:`Mesh` or :class:`Points` (a point cloud, drawn as splats) or a list of them
            (each with its own material and transform), where :class:`Lines` items may stand
            beside them (segments drawn as ink, hidden by the surfaces in front of them); None
            (default) for an empty scene.
        faces: (M, 3) int32/int64/uint32 with ``vertices`` given as an array; else None.
        normals: None (default: a file's own normals where it has them, else ``"auto"``: hard
            edges at the creases a drawing keeps, for boxes and CAD parts, and smooth scans),
            ``"smooth"``, ``"flat"``, ``"auto"``, ``("auto", degrees)``, or the mesh's own
            (N, 3) vertex normals; see :class:`Mesh`. A mode given replaces a file's normals and
            a :class:`Mesh`'s (a copy: the caller's mesh is not changed); a
            :class:`MeshHandle`'s are fixed at its upload, so giving ``normals`` with one is a
            ValueError.
        smooth_iterations: Laplacian smoothing first (Al-Rousan et al.'s pipeline), default 0.
        backend: as in :class:`Renderer`; default None.
        **options: the render keywords (:class:`RenderKeywords`: ``width``, ``height``,
            ``material``, ``camera``, ``lights``, ``outputs``, ``outlines``, ...), each with its
            type, default and meaning. The scene's up axis (``up``) is a file's convention
            unless given: ``render("part.stl")`` keeps +z up.

    Returns:
        The images asked for in ``outputs``, as NumPy arrays (``color``: (H, W, 4) uint8).

    Examples:
        >>> img = toonmesh.render(V, F, width=640, height=480, outlines="mesh").color
        >>> img.shape, img.dtype
        ((480, 640, 4), dtype('uint8'))
    """
    iterations = _smoothing_iterations(smooth_iterations)
    opts = RenderOptions(**options)  # checked before any upload
    items = own_colours(scene_items(vertices, faces, normals), opts, options.get("material"))
    meshes, lines = split_lines(items)
    renderer = shared_renderer(backend)
    with meshes_on_device(renderer, meshes, iterations) as placed:
        return draw(renderer, placed, opts, lines)


def scene_items(vertices: Any, faces: Any = None, normals: Normals = None) -> List[Any]:
    """The scene's items as :func:`render` reads its first arguments (so does the viewer): (V, F)
    arrays or a ``trimesh.Trimesh`` as one :class:`Mesh` with ``normals``; a mesh file's path
    (str or os.PathLike) or a ``trimesh.Scene`` read as :func:`toonmesh.load` reads them (with
    ``normals`` in place of a file's own where given); a :class:`Mesh` or :class:`Points`, or a
    list of :class:`Mesh`, :class:`Points`, :class:`MeshHandle` and ``trimesh.Trimesh`` items (a trimesh made a
    :class:`Mesh` with ``normals``); None for an empty scene. Errors name ``vertices``/``faces``."""
    if isinstance(vertices, (list, tuple)) and faces is None:
        return [Mesh(x, normals=normals) if _is_trimesh(x) else _given_normals(x, normals) for x in vertices]
    if vertices is None:
        return []
    if isinstance(vertices, Lines):
        return [vertices]
    if isinstance(vertices, (Mesh, MeshHandle)):
        return [_given_normals(vertices, normals)]
    if isinstance(vertices, Points):
        return [vertices]
    if faces is None and (isinstance(vertices, (str, os.PathLike)) or _load.is_scene(vertices)):
        loaded = _load.load(vertices) if isinstance(vertices, (str, os.PathLike)) else _load.scene_meshes(vertices)
        return loaded if normals is None else [_with_normals(m, normals) for m in loaded]
    return [Mesh(vertices, faces, normals=normals)]  # a trimesh brings its colour


def _given_normals(item: Any, normals: Normals) -> Any:
    """A scene item drawn with the render's ``normals`` where given: a copy of a :class:`Mesh`
    with them in place of its own (the caller's mesh is not changed); a :class:`MeshHandle`'s
    were fixed at its upload, so giving them is an error rather than ignored."""
    if normals is None or not isinstance(item, (Mesh, MeshHandle)):
        return item
    if isinstance(item, MeshHandle) or item.vertices is None:  # a Mesh may place a MeshHandle
        raise ValueError("normals: a MeshHandle's normals are fixed when it is uploaded "
                         "(Renderer.add_mesh(..., normals=...)); not given to the render")
    item = copy.copy(item)
    item.normals = normal_mode(normals, len(item.vertices))
    return item


def _is_trimesh(value: Any) -> bool:
    """Whether a scene item is a ``trimesh.Trimesh`` (without importing trimesh)."""
    return not isinstance(value, (Mesh, MeshHandle)) and hasattr(value, "vertices") and hasattr(value, "faces")


def own_colours_material(opts: RenderOptions, material: Optional[Material]) -> Optional[Material]:
    """The material meshes that carry colours or a texture (and name no material) are drawn
    under when a render names no ``material``: the default shading model (``opts.material``'s)
    in white, so their colours show as they are; None when ``material`` is given."""
    if material is not None:
        return None
    return getattr(Material, opts.material.model)(_load.OWN_COLOURS_WHITE)  # type: ignore[no-any-return]


def own_colours(items: List[Any], opts: RenderOptions, material: Optional[Material]) -> List[Any]:
    """``items`` as :func:`render` draws them with ``material`` (None where none was given):
    see :func:`own_colours_material`. The caller's meshes are not changed (copies)."""
    white = own_colours_material(opts, material)
    if white is None:
        return items
    return [_under(p, white) if isinstance(p, Points) else p for p in _load.under_own_colours(items, white)]


def _under(points: Points, material: Material) -> Points:
    """A cloud with colours of its own and no material drawn under ``material`` (a copy)."""
    if points.colors is None or points.material is not None:
        return points
    points = copy.copy(points)
    points.material = material
    return points


def _with_normals(m: Mesh, normals: Normals) -> Mesh:
    """A mesh just made from a file (nobody else holds it) drawn with ``normals`` instead of its own."""
    assert m.vertices is not None  # read from a file: arrays, not a MeshHandle
    m.normals = normal_mode(normals, len(m.vertices))
    return m


def gpu_info(backend: Optional[str] = None) -> Dict[str, Any]:
    """The adapter renders use. Creates the process-wide GPU context if needed.

    Args:
        backend: as in :class:`Renderer`; default None.

    Returns:
        A dict: ``name``, ``backend`` ("vulkan" or "gl"), ``device_type`` ("cpu" for Mesa's
        lavapipe/llvmpipe), ``driver``, ``driver_info``, ``max_texture_size``,
        ``msaa_samples`` and ``timestamps`` (whether passes are timed on the GPU).

    Raises:
        GpuUnavailableError: there is no adapter.
    """
    return _core.gpu_info(backend)


__all__ = [
    "RenderKeywords",
    "Mesh",
    "MeshHandle",
    "RenderResult",
    "RenderStack",
    "Renderer",
    "gpu_info",
    "kang_table",
    "render",
]
