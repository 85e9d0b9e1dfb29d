"""An interactive toon render in Jupyter: ``toonmesh.Viewer(V, F, **render keywords)``.

While the pointer moves, the browser draws draft frames itself in WebGL2 with toonmesh's own
shaders (the core translates them to GLSL ES 3.00 and sends them with the uniform bytes and the
mesh: ``toonmesh.viewer._draft``); when it stops, the kernel renders the exact frame with
toonmesh itself (toon bands, mesh-space lines, hatching, shadows) and sends it as a PNG or JPEG.
Where the browser cannot draw the drafts, the kernel draws them too. The mesh is uploaded to
the GPU once. The widget needs the ``notebook`` extra (``pip install
'toonmesh[notebook]'``: anywidget, ipywidgets, JupyterLab); without it, or where no widget front
end runs (nbconvert, GitHub, a terminal), the viewer shows its current frame as a still PNG.

Flow control: the browser sends a view (the pointer's moves since the last one, numbered) only
once the kernel has answered the last one, keeping the newest moves merged meanwhile; pointer
events only move the camera (no render each); one thread renders the latest view when it is
free, so a slow frame never queues a backlog, and each frame carries the number of the view it
was made for (the browser drops one older than the frame it shows). While the pointer moves,
frames are drawn at ``drag_scale`` of the size (by the browser, or by the kernel and sent as
JPEG); when it stops (or is released) the full-size frame follows in ``image_format``.

Lifetime: the render thread runs only while frames are wanted, and neither it nor the widget
holds the viewer (weak references), so a viewer no longer referenced is freed with its uploaded
meshes and its front end; :meth:`Viewer.close` frees them at once. A viewer shown on the page is
referenced by the page itself: each of its views tells the kernel when it is drawn and when it
is removed (``widget.js``), and ``_SHOWN`` holds the viewer while at least one view is on the
page (``display(tm.Viewer(...))`` in a function or a loop keeps drawing), letting it go when the
last one goes (its output cleared, its cell run again).
"""

from __future__ import annotations

import copy
import io
import json
import math
import os
import re
import sys
import threading
import time
import types
import weakref
from typing import TYPE_CHECKING, Any, Callable, Dict, Generic, List, Optional, Set, Tuple, TypeVar, overload

import numpy as np

from toonmesh import _core
from toonmesh._core import Camera, Light, Material, Outlines, RenderOptions
from toonmesh.arguments._described import default
from toonmesh.files._load import is_scene
from toonmesh.rendering._render import (PlacedMesh, Renderer, _core_items, _core_lines, draw, draw_views, own_colours,
                              scene_items, shared_renderer, split_lines)
from toonmesh.rendering._results import RenderResult
from toonmesh.scene._points import Points
from toonmesh.scene._scene import Mesh, MeshHandle, Normals, own_normals
from toonmesh.viewer._layout import KEYWORDS as LAYOUT, Layout, checked
from toonmesh.viewer._uploads import SharedUpload, shared_upload
from toonmesh.rendering._video import DEFAULT_FPS, DEFAULT_SECONDS, check_fps, check_video_size, video_kind, video_writer

if TYPE_CHECKING:
    from typing_extensions import Unpack

    from toonmesh.rendering._render import RenderKeywords

NOTEBOOK_EXTRA = "pip install 'toonmesh[notebook]'"

# Radians of orbit per pixel of drag, as a fraction of the frame's height: a drag across the
# whole height turns the view half way round.
_ORBIT_PER_HEIGHT = math.pi
# Zoom factor per unit of wheel delta (a browser's wheel notch is about 100 units: ~14%).
_WHEEL_ZOOM = 0.0015
# The largest moves one call takes (pixels of drag, zoom factor): beyond them the view leaves
# float precision, and no pointer gets there.
_MAX_DRAG = 1e6
_MAX_ZOOM = 1e3
# How close the view may come to looking straight along ``up`` (radians), so it never flips.
_POLE_MARGIN = math.radians(1.0)
# What the view keeps for the projection it does not use (an orthographic camera has no field of
# view): the core's defaults, should the view be switched to that projection.
_FOV_Y = float(default(Camera, "look_at", "fov_y"))
_HEIGHT = float(default(Camera, "orthographic", "height"))
# The moves as the browser's draft renderer makes them (moves.js), from the constants above.
_MOVES = {"orbit_per_height": _ORBIT_PER_HEIGHT, "wheel_zoom": _WHEEL_ZOOM, "pole_margin": _POLE_MARGIN,
          "max_zoom": _MAX_ZOOM}
#: The sides :meth:`Viewer.view_from` (and the toolbar's axis buttons) look from.
AXES = ("+x", "-x", "+y", "-y", "+z", "-z")
#: The projections :attr:`Viewer.projection` (and the toolbar's toggle) switches between.
PROJECTIONS = ("perspective", "orthographic")


class ViewerClosedError(RuntimeError):
    """A closed :class:`Viewer` was asked to move, change or render."""


def _unit(v: np.ndarray) -> np.ndarray:
    n = float(np.linalg.norm(v))
    return v / n if n > 0 else v


class _View:
    """The camera as the viewer moves it: eye, target, world up, and the projection's size
    (vertical field of view in degrees, or the orthographic view's height in world units)."""

    def __init__(self, eye: Any, target: Any, up: Any, orthographic: bool, fov_y: float, height: float):
        self.eye = np.asarray(eye, np.float64)
        self.target = np.asarray(target, np.float64)
        self.up = _unit(np.asarray(up, np.float64))
        self.orthographic = orthographic
        self.fov_y = fov_y
        self.height = height

    def camera(self) -> Camera:
        eye, target, up = (tuple(float(x) for x in v) for v in (self.eye, self.target, self.up))
        if self.orthographic:
            return Camera.orthographic(eye, target, up=up, height=self.height)
        return Camera.look_at(eye, target, up=up, fov_y=self.fov_y)

    def source(self) -> str:
        eye, target, up = (repr(tuple(float(x) for x in v)) for v in (self.eye, self.target, self.up))
        if self.orthographic:
            return f"tm.Camera.orthographic({eye}, {target}, up={up}, height={self.height!r})"
        return f"tm.Camera.look_at({eye}, {target}, up={up}, fov_y={self.fov_y!r})"

    def _basis(self) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        forward = _unit(self.target - self.eye)
        right = _unit(np.cross(forward, self.up))
        return forward, right, np.cross(right, forward)

    def world_per_pixel(self, pixels_high: int) -> float:
        if self.orthographic:
            return self.height / pixels_high
        distance = float(np.linalg.norm(self.target - self.eye))
        return 2.0 * distance * math.tan(math.radians(self.fov_y) / 2.0) / pixels_high

    def orbit(self, dx: float, dy: float, pixels_high: int) -> None:
        """Turntable orbit about the target: ``dx`` turns about ``up`` (dragging right turns the
        scene right), ``dy`` tilts (dragging down shows more of the top), short of the poles."""
        per_pixel = _ORBIT_PER_HEIGHT / pixels_high
        offset = _rotate(self.eye - self.target, self.up, -dx * per_pixel)
        radius = float(np.linalg.norm(offset))
        along = float(np.dot(offset, self.up))
        level = offset - along * self.up
        if np.linalg.norm(level) == 0:  # looking straight along up: any side will do
            level = np.cross(self.up, (1.0, 0.0, 0.0) if abs(self.up[0]) < 0.9 else (0.0, 0.0, 1.0))
        polar = math.acos(float(np.clip(along / radius, -1.0, 1.0)))
        polar = float(np.clip(polar - dy * per_pixel, _POLE_MARGIN, math.pi - _POLE_MARGIN))
        self.eye = self.target + radius * (math.cos(polar) * self.up + math.sin(polar) * _unit(level))

    def pan(self, dx: float, dy: float, pixels_high: int) -> None:
        """Moves eye and target so that the scene follows the pointer."""
        _, right, up = self._basis()
        step = (-dx * right + dy * up) * self.world_per_pixel(pixels_high)
        self.eye = self.eye + step
        self.target = self.target + step

    def zoom(self, factor: float) -> None:
        if self.orthographic:
            self.height /= factor
        else:
            self.eye = self.target + (self.eye - self.target) / factor

    def project(self, orthographic: bool) -> None:
        """Switches the projection keeping the framing: the target's plane shows the same height
        of the world. An orthographic view takes the height the perspective one saw at the
        target's distance; back, the eye moves along the view axis to the distance at which the
        field of view sees that height."""
        if orthographic == self.orthographic:
            return
        half = math.tan(math.radians(self.fov_y) / 2.0)
        if orthographic:
            self.height = 2.0 * float(np.linalg.norm(self.target - self.eye)) * half
        else:
            forward = _unit(self.target - self.eye)
            self.eye = self.target - forward * (self.height / (2.0 * half))
        self.orthographic = orthographic


def _rotate(v: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    """``v`` turned by ``angle`` radians about the unit ``axis`` (Rodrigues)."""
    c, s = math.cos(angle), math.sin(angle)
    return v * c + np.cross(axis, v) * s + axis * float(np.dot(axis, v)) * (1.0 - c)


def _view_of(result: RenderResult, camera: Camera, center: np.ndarray) -> _View:
    """The eye, target and projection a render used (for a fitted camera, whose eye the core
    chose): the target is the point on the view axis nearest ``center``."""
    rotation, translation = result.view_matrix[:3, :3], result.view_matrix[:3, 3]
    eye = -rotation.T @ translation
    forward = -rotation[2]
    target = eye + forward * max(float(np.dot(center - eye, forward)), 1e-6)
    orthographic = camera.projection == "orthographic"
    # a fitted orthographic view's height is the fit's (the camera holds only the default)
    height = 2.0 / float(result.projection[1, 1]) if orthographic else _HEIGHT
    fov_y = camera.fov_y if camera.fov_y is not None else _FOV_Y
    up = camera.up if camera.up is not None else np.eye(3)["xyz".index(result.up)]  # the scene's up axis
    return _View(eye, target, up, orthographic, float(fov_y), float(height))


def _encode(color: np.ndarray, image_format: str, quality: int = 85) -> Tuple[bytes, str]:
    """The frame as file bytes: PNG by the core, JPEG by Pillow (PNG when it is missing)."""
    if image_format == "jpeg":
        try:
            from PIL import Image
        except ImportError:
            return _core.encode_png_rgba(color), "png"
        out = io.BytesIO()
        Image.fromarray(np.ascontiguousarray(color[..., :3])).save(out, format="JPEG", quality=quality)
        return out.getvalue(), "jpeg"
    return _core.encode_png_rgba(color), "png"


T = TypeVar("T")


class _Setting(Generic[T]):
    """A render setting as a viewer attribute: reads the viewer's :class:`RenderOptions` (so it
    reads back as the core holds it: ``v.outlines = "mesh"`` reads an :class:`Outlines`);
    setting it (to anything ``RenderOptions`` takes) re-renders. A setting of the view's layout
    (its size, its pixel ratio) reads what the view shows now instead (``shown``, from the
    viewer's :class:`Layout`: the cell's width or the screen's ratio where none was given)."""

    def __init__(self, shown: Optional[Callable[[Layout], T]] = None, doc: Optional[str] = None) -> None:
        self.shown = shown
        if doc is not None:
            self.__doc__ = doc

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    @overload
    def __get__(self, viewer: None, owner: type) -> "_Setting[T]": ...
    @overload
    def __get__(self, viewer: "Viewer", owner: type) -> T: ...
    def __get__(self, viewer: Optional["Viewer"], owner: type) -> Any:
        if viewer is None:
            return self
        return getattr(viewer._options, self.name) if self.shown is None else self.shown(viewer._layout)

    def __set__(self, viewer: "Viewer", value: Any) -> None:
        viewer.set(**{self.name: value})


class ViewerCode(str):
    """Python source, shown as itself (not quoted) in a notebook."""

    def __repr__(self) -> str:
        return str(self)


class _Shared:
    """What a viewer shares with its render thread and its finaliser, none of which holds the
    viewer: the lock over the view, the frame asked for, and whether the viewer is closed."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.wake = threading.Condition(self.lock)
        self.wanted: Optional[bool] = None  # the draft flag of the latest frame asked for
        self.closed = False
        self.worker: Optional[threading.Thread] = None
        self.view_id = 0  # the number of the browser's latest view applied (0: none yet)
        self.answered = 0  # the number of the latest view a frame or an error answered
        self.views = 0  # the views the browser sent
        self.early = 0  # the views that came before the last one was answered (the browser waits: 0)


# Seconds a viewer displayed in a kernel is held for its first view to be drawn: a front end
# that never draws it (nbconvert, a console) lets it go after this, once another viewer is shown.
_FIRST_VIEW_S = 60.0


class _Shown:
    """The viewers on the page: each held (strongly) while at least one of its views is drawn,
    so that a viewer nothing else refers to (``display(tm.Viewer(...))`` in a function) keeps
    drawing, and let go when its last view is removed, or when it is closed. A viewer displayed
    in a kernel is held from then until its first view comes, for at most ``_FIRST_VIEW_S``."""

    def __init__(self) -> None:
        self.held: Dict[int, "Viewer"] = {}
        self.views: Dict[int, Set[str]] = {}
        self.waiting: Dict[int, float] = {}  # displayed, no view yet: since when (monotonic seconds)

    def displayed(self, viewer: "Viewer") -> None:
        self._expire()
        key = id(viewer)
        if not viewer.closed and not self.views.get(key):
            self.held[key] = viewer
            self.waiting[key] = time.monotonic()

    def view(self, viewer: "Viewer", view: str, shown: bool) -> None:
        """A view of ``viewer`` drawn (``shown``) or removed."""
        self._expire()
        key = id(viewer)
        views = self.views.setdefault(key, set())
        if shown:
            views.add(view)
            self.held[key] = viewer
            self.waiting.pop(key, None)
        else:
            views.discard(view)
            if not views and key not in self.waiting:
                self.drop(viewer)

    def drop(self, viewer: "Viewer") -> None:
        key = id(viewer)
        if self.held.get(key) is viewer:
            del self.held[key]
        self.views.pop(key, None)
        self.waiting.pop(key, None)

    def _expire(self) -> None:
        now = time.monotonic()
        for key, since in list(self.waiting.items()):
            if now - since > _FIRST_VIEW_S:
                self.drop(self.held[key])


_SHOWN = _Shown()


def _in_kernel() -> bool:
    """Whether this runs in a Jupyter kernel (where a displayed viewer may get views)."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    return getattr(shell, "kernel", None) is not None


class Viewer:
    """An interactive toon render of a mesh in Jupyter, rendered by toonmesh in the kernel.

    ``Viewer(V, F, **render keywords)`` takes the scene as :func:`toonmesh.render` does (one
    function reads it for both). ``width`` and ``height`` are the view's size in layout (CSS)
    pixels: without a width the view fits the notebook cell's width (512 until the browser
    reports it), the height defaults to 512; the frames are rendered at the screen's pixel
    ratio (``pixel_ratio``: given, or the browser's device pixel ratio), so on a 2x screen they
    have twice the pixels each way with every length in pixels doubled: the same picture,
    sharp. Full screen fills the screen while it lasts. With no ``material``, meshes that carry
    colours or a texture are drawn as :func:`toonmesh.render` draws them (under a white
    material), so the view shows what ``tm.render`` shows.

    Args:
        vertices: (N, 3) float32/float64 with ``faces``, a ``trimesh.Trimesh``, a mesh file's
            path, a ``trimesh.Scene``, a :class:`toonmesh.Mesh` or a list of meshes.
        faces: (M, 3) int32/int64/uint32 with ``vertices`` given as an array; else None.
        normals: as in :func:`toonmesh.render`.
        smooth_iterations: as in :func:`toonmesh.render`.
        backend: as in :class:`toonmesh.Renderer`.
        renderer: the renderer the meshes are uploaded to, once; None (default): the process's
            shared renderer for ``backend``.
        controls: show ipywidgets controls beside the frame; default False (see below).
        image_format: of the full-size frames, ``"png"`` (default) or ``"jpeg"``.
        drag_scale: the size of the frames drawn while the pointer moves, as a fraction of the
            full size (0.05 to 1, default 0.5; the browser draws them smaller where it cannot
            keep up, the kernel's are sent as JPEG).
        **options: the render keywords (:class:`toonmesh.RenderKeywords`: ``material``,
            ``lights``, ``outlines``, ``camera``, ``width``, ``height``, ...).

    In the browser: drag to orbit, wheel to zoom (once the view has focus: click it; otherwise
    the wheel scrolls the notebook), shift-drag or right-drag to pan, double-click to frame the
    scene again; the toolbar has home (the first view), views from each axis, the projection
    (perspective or orthographic), the parts list (a scene of several meshes), a PNG download of
    the current full-size frame, full screen, and the frame rate and latency; an orientation
    triad in the view's corner turns with it (click a label to view from that axis). From
    Python: :meth:`orbit`, :meth:`zoom`, :meth:`pan`, :meth:`home`, :meth:`view_from` (each
    renders the full-size frame before it returns), ``camera`` (read or set), ``projection``,
    ``parts`` and ``visible`` (show or hide parts), and every render setting as an attribute
    that re-renders when set (``v.outlines = "both"``, ``v.width = 640``).

    ``controls=True`` shows ipywidgets controls beside the frame, one per field of the
    material, the first light, the outlines (and each line kind's style), the camera's field of
    view, the paper and the other render options, in collapsible sections (the material's
    open), each following the core's description of the field (its kind, bounds and choices)
    and showing the settings as they are now (``controls`` is that column as a widget, to place
    yourself).

    While the pointer moves, the browser draws the drafts in WebGL2 from toonmesh's own shaders:
    the bands, tones, colours and texture, dithering, rim light, hatching, image-space ink and
    mesh-space lines (silhouettes along face edges); it leaves smooth and suggestive contours,
    shadows, paper, multisampling and supersampling to the exact frame that follows from the
    kernel, and the view's tooltip says which.

    ``frame`` is the last frame shown, (H, W, 4) uint8; ``render_count`` counts the renders;
    :meth:`snapshot` renders the current view at full quality (any size, any outputs);
    :meth:`turntable` writes a turn about the view as a GIF or MP4; :meth:`to_html` writes a
    standalone page that orbits the scene in a browser (WebGL2, no kernel);
    :meth:`code` gives the ``tm.render(...)`` call that reproduces the view.
    :meth:`close` frees the viewer's meshes, render thread and front end (so does dropping the
    last reference to it once no view of it is on the page: a viewer displayed from a function
    lives while its output is shown); a closed viewer raises :class:`ViewerClosedError` when used.
    The view takes the keys while it has focus; Escape gives them back to the notebook.
    """

    # The render settings, each re-rendering when set (see toonmesh.RenderOptions for what each
    # takes and its default); ``camera`` is a property of its own, ``outputs`` always "color".
    material: _Setting[Material] = _Setting()
    transform: _Setting[List[List[float]]] = _Setting()
    lights: _Setting[List[Light]] = _Setting()
    ambient: _Setting[Tuple[float, float, float]] = _Setting()
    background: _Setting[Tuple[float, float, float, float]] = _Setting()
    msaa: _Setting[int] = _Setting()
    supersample: _Setting[int] = _Setting()
    outlines: _Setting[Optional[Outlines]] = _Setting()

    def __init__(
        self,
        vertices: Any,
        faces: Any = None,
        *,
        normals: Normals = None,
        smooth_iterations: int = 0,
        backend: Optional[str] = None,
        renderer: Optional[Renderer] = None,
        controls: bool = False,
        image_format: str = "png",
        drag_scale: float = 0.5,
        **options: "Unpack[RenderKeywords]",
    ):
        if "outputs" in options:
            raise TypeError("outputs: a Viewer shows the colour image; use snapshot(outputs=...) for others")
        if renderer is not None and not isinstance(renderer, Renderer):
            raise TypeError(f"renderer: expected a toonmesh.Renderer, got {type(renderer).__name__}")
        if not isinstance(controls, (bool, np.bool_)):
            raise TypeError(f"controls: expected True or False, got {type(controls).__name__}")
        if vertices is None:
            raise TypeError("vertices: expected the scene (arrays with faces, a trimesh, a file's path, a "
                            "trimesh.Scene, a toonmesh.Mesh or a list of meshes), got None")
        self._renderer = renderer if renderer is not None else shared_renderer(backend)
        self._layout = Layout(**{k: checked(k, options.pop(k)) for k in LAYOUT if k in options})  # type: ignore[misc]
        self._options = RenderOptions(**options, **self._layout.frame())  # checked before any upload
        self._given: Dict[str, Any] = {k: v for k, v in options.items() if k != "camera" and v is not None}
        self.image_format = _format(image_format)
        self.drag_scale = drag_scale
        self._normals = normals
        self._smooth_iterations = smooth_iterations
        self._shared = _Shared()
        self._state_lock = self._shared.lock
        self._render_lock = threading.RLock()
        # what the finaliser frees (close(), or the viewer freed): the upload of its meshes (shared
        # with live viewers of the same meshes; not MeshHandles it was given) and the front end's
        # widgets
        self._uploads: List[SharedUpload] = []
        self._front: List[Any] = []
        self._release = weakref.finalize(self, _release, self._shared, self._uploads, self._front)
        self._mesh_source = _mesh_source(vertices, faces)
        self._placed, self._placed_own, self._center = self._upload(vertices, faces, normals, smooth_iterations)
        self.render_count = 0
        self.frame: Optional[np.ndarray] = None
        self._frame_id = 0
        self._widget: Any = _make_widget(self)
        if self._widget is not None:
            self._front.append(self._widget)
            self._send_parts()
        self._controls: Any = None  # the on-screen controls (a ControlPanel), refreshed when a setting changes
        self._set_camera(options.get("camera"))
        self._home = copy.deepcopy(self._view)
        self._show(draft=False)
        if controls and self._widget is not None:  # without the notebook extra: the still frame
            self._make_controls(beside=True)

    def _make_controls(self, beside: bool) -> Any:
        from toonmesh.viewer._controls import ControlPanel

        self._controls = ControlPanel(self, beside=beside)
        self._front.append(self._controls)
        return self._controls

    @property
    def controls(self) -> Any:
        """The on-screen controls as a widget, to place where you like (``ipywidgets.HBox([v.widget,
        v.controls])``): an ``ipywidgets.VBox`` of collapsible sections (the material, the first
        light, the outlines, the camera, the paper, the other options; the material's open), a
        control per field of each, as ``controls=True`` shows them beside the frame. Made on first
        read where the viewer was made without ``controls=True`` (displaying ``v`` then still shows
        the frame alone); None without the notebook extra. Closed with the viewer."""
        if self._controls is None:
            if self._widget is None:
                return None
            self._check_open()
            self._make_controls(beside=False)
        return self._controls.column

    # -- the view's size ------------------------------------------------------------------------

    width: _Setting[int] = _Setting(
        lambda layout: layout.view_size()[0],
        """The view's width in layout (CSS) pixels, as shown now: as given, or the notebook
        cell's width where none was given (512 until the browser reports it; it follows the
        cell as the window changes). Set an int to fix it, None to fit the cell again; either
        re-renders. A frame is ``width * pixel_ratio`` output pixels wide.""",
    )
    height: _Setting[int] = _Setting(
        lambda layout: layout.view_size()[1],
        """The view's height in layout (CSS) pixels (default 512; None sets the default);
        setting it re-renders. A frame is ``height * pixel_ratio`` output pixels high.""",
    )
    pixel_ratio: _Setting[float] = _Setting(
        Layout.ratio,
        """Output pixels per layout pixel of the frames (:class:`toonmesh.RenderOptions`'
        ``pixel_ratio``: the lengths the settings give in pixels scale with it, so the picture is
        the same, sharper): as given, or the screen's device pixel ratio as the browser reports
        it where none was given (1 until then). Set a number (0.25 to 8) to fix it, None to
        follow the screen again; either re-renders.""",
    )

    def _resized(self) -> None:
        """The render options follow the view's size and pixel ratio (the caller renders)."""
        self._options = self._options.replace(**self._layout.frame())

    @property
    def drag_scale(self) -> float:
        """The size of the frames drawn while the pointer moves, as a fraction of the full size
        (0.05 to 1); setting it reaches the browser's drafts at once."""
        return self._drag_scale

    @drag_scale.setter
    def drag_scale(self, value: float) -> None:
        self._drag_scale = _number("drag_scale", value, 0.05, 1.0)
        widget = getattr(self, "_widget", None)  # None while the viewer is being made
        if widget is not None:
            widget._moves = self._moves()

    def _moves(self) -> Dict[str, float]:
        """The constants of the viewer's moves and its drag_scale, for the browser's drafts."""
        return dict(_MOVES, drag_scale=self._drag_scale)

    # -- the scene ----------------------------------------------------------------------------

    def _upload(self, vertices: Any, faces: Any, normals: Normals,
                smooth_iterations: int) -> Tuple[List[PlacedMesh], List[PlacedMesh], np.ndarray]:
        """The scene's meshes on the renderer (uploaded once), read as tm.render reads them; as
        placed, and as drawn with no material given (meshes with colours of their own under
        tm.render's white material); and the centre of their bounding box in world space."""
        items, self._lines = split_lines(scene_items(vertices, faces, normals))  # Lines: drawn as ink, always shown
        if not items and not self._lines:
            raise ValueError("vertices: the scene has no mesh")
        meshes = [item if isinstance(item, (Mesh, Points)) else Mesh(item) for item in items]  # a MeshHandle in a list
        upload = shared_upload(self._renderer, meshes, smooth_iterations, where="vertices")
        self._uploads.append(upload)
        self._parts = _part_names(meshes)
        self._shown = [True] * len(meshes)
        placed = upload.placed(meshes)
        try:
            own = own_colours(meshes, self._options, None)  # the same meshes, some under another material
            placed_own = [p._replace(material=o.material) for p, o in zip(placed, own)]
            center = self._center_of([*meshes, *self._lines])
        except BaseException:
            self._free_meshes()
            raise
        return placed, placed_own, center

    def _center_of(self, meshes: List[Any]) -> np.ndarray:
        """The centre of the world-space bounding box of the items (meshes, points, lines) given
        as arrays (a MeshHandle's arrays are on the device only)."""
        lows: List[np.ndarray] = []
        highs: List[np.ndarray] = []
        for mesh in meshes:
            arrays = mesh.vertices if isinstance(mesh, Mesh) else mesh.positions  # Points and Lines: positions
            if arrays is None:
                continue
            transform = mesh.transform if mesh.transform is not None else self._options_transform()
            V = arrays @ transform[:3, :3].T + transform[:3, 3]
            lows.append(V.min(axis=0))
            highs.append(V.max(axis=0))
        return (np.min(lows, axis=0) + np.max(highs, axis=0)) / 2 if lows else np.zeros(3)

    def _free_meshes(self) -> None:
        self._uploads.clear()

    def _options_transform(self) -> np.ndarray:
        return np.asarray(self._options.transform, np.float64)

    def _scene(self) -> List[PlacedMesh]:
        """The placed meshes as a render with the viewer's settings draws them: with no material
        given, those with colours of their own under tm.render's white material; the hidden
        parts left out."""
        return self._shown_of(self._placed if "material" in self._given else self._placed_own)

    def _shown_of(self, placed: List[PlacedMesh]) -> List[PlacedMesh]:
        return [p for p, shown in zip(placed, self._shown) if shown]

    @property
    def closed(self) -> bool:
        """Whether :meth:`close` was called (or the viewer's resources were freed)."""
        return self._shared.closed

    def _check_open(self) -> None:
        if self._shared.closed:
            raise ViewerClosedError("this toonmesh.Viewer is closed (close() freed its meshes and front end): "
                                    "make a new tm.Viewer")

    def close(self) -> None:
        """Frees what the viewer holds: stops its render thread, frees the meshes it uploaded (not
        MeshHandles it was given) and closes its widget and controls, which leave the notebook.
        Using the viewer afterwards raises :class:`ViewerClosedError`. Dropping the last
        reference to a viewer does the same. Closing twice does nothing."""
        _SHOWN.drop(self)  # the page no longer holds it
        with self._render_lock:  # after the frame being drawn, if any
            self._release()
            self._placed = []
            self._placed_own = []

    # -- the camera ---------------------------------------------------------------------------

    @property
    def camera(self) -> Camera:
        """The current view as a :class:`toonmesh.Camera` (a ``look_at`` or ``orthographic``
        one); setting a camera (a fitted one too) re-renders."""
        with self._state_lock:
            return self._view.camera()

    @camera.setter
    def camera(self, camera: Camera) -> None:
        self._check_open()
        self._set_camera(camera)
        self._settings_shown()
        self._show(draft=False)

    def _set_camera(self, camera: Optional[Camera]) -> None:
        """Holds ``camera`` as the view (a fitted one as the eye and target the core chose); the
        caller renders."""
        camera = self._options.replace(camera=camera).camera  # checked, with the core's default
        if camera.kind == "fit":
            result = self._render(camera, self._options.width, self._options.height)
            view = _view_of(result, camera, self._center)
        else:
            view = _View(camera.eye, camera.target, camera.up, camera.projection == "orthographic",
                         float(camera.fov_y or _FOV_Y), float(camera.height or _HEIGHT))
        with self._state_lock:
            self._view = view

    def orbit(self, dx: float, dy: float) -> None:
        """Orbits about the target as a drag would, then renders the full-size frame.

        Args:
            dx: pixels dragged right (a drag over the frame's height turns half way round); at
                most 1e6 either way.
            dy: pixels dragged down; at most 1e6 either way.
        """
        self._check_open()
        self._move("orbit", _pixels("dx", dx), _pixels("dy", dy))
        self._show(draft=False)

    def pan(self, dx: float, dy: float) -> None:
        """Moves the view as a shift-drag would (the scene follows the pointer), then renders the
        full-size frame.

        Args:
            dx: pixels dragged right; at most 1e6 either way.
            dy: pixels dragged down; at most 1e6 either way.
        """
        self._check_open()
        self._move("pan", _pixels("dx", dx), _pixels("dy", dy))
        self._show(draft=False)

    def zoom(self, factor: float) -> None:
        """Zooms in by ``factor``, then renders the full-size frame.

        Args:
            factor: 0.001 to 1000; 2 halves the distance to the target or the orthographic view's
                height, 0.5 doubles it.
        """
        self._check_open()
        factor = _number("factor", factor, 1.0 / _MAX_ZOOM, _MAX_ZOOM)
        self._move("zoom", factor, 0.0)
        self._show(draft=False)

    def reframe(self) -> None:
        """Frames the scene again from the current direction (what a double-click does)."""
        self._check_open()
        self._reframe()
        self._show(draft=False)

    def home(self) -> None:
        """Goes back to the first view (the camera the viewer was made with; the toolbar's home
        button), then renders the full-size frame."""
        self._check_open()
        self._go_home()
        self._show(draft=False)

    def view_from(self, axis: str) -> None:
        """Frames the scene seen from the side ``axis`` names (the toolbar's axis buttons),
        keeping the projection and the world's up, and renders the full-size frame. From the up
        axis's ends the view stays a degree short of the pole, as orbiting does.

        Args:
            axis: ``"+x"``, ``"-x"``, ``"+y"``, ``"-y"``, ``"+z"`` or ``"-z"``: the eye on that
                side, looking back along the axis.
        """
        self._check_open()
        self._view_from(_axis(axis))
        self._show(draft=False)

    @property
    def projection(self) -> str:
        """The camera's projection: ``"perspective"`` or ``"orthographic"`` (the toolbar's
        toggle). Setting it switches the camera (:meth:`toonmesh.Camera.look_at` and
        :meth:`toonmesh.Camera.orthographic`) keeping the view's framing: the orthographic
        view's height is what the perspective view saw at the target's distance, and back, the
        eye moves along the view axis so that the field of view sees that height again; the
        field of view and the eye's direction are kept. Re-renders."""
        with self._state_lock:
            return PROJECTIONS[self._view.orthographic]

    @projection.setter
    def projection(self, value: str) -> None:
        self._check_open()
        self._project(_projection(value))
        self._settings_shown()
        self._show(draft=False)

    def _project(self, projection: str) -> None:
        with self._state_lock:
            self._view.project(projection == "orthographic")

    @property
    def parts(self) -> Tuple[str, ...]:
        """The names of the scene's parts, its meshes in order (a file's or a ``trimesh.Scene``'s
        placed geometries, a list's items): each mesh's ``name``, ``"part N"`` (from 1) where it
        has none, and ``" (2)"``, ``" (3)"``... after a name met again (instances of one
        geometry). The toolbar lists them where there are several."""
        return tuple(self._parts)

    @property
    def visible(self) -> Dict[str, bool]:
        """Which parts are shown, ``{name: True or False}`` in the order of :attr:`parts` (all
        shown at first). Set a dict of parts, each by name or by its index in :attr:`parts`, to
        ``True`` or ``False`` to show or hide them (the parts not named stay as they are; the
        toolbar's parts list does the same): the exact frame, the drafts, :meth:`snapshot`,
        :meth:`turntable`, :meth:`to_html` and :meth:`code` leave the hidden ones out.
        Re-renders."""
        return dict(zip(self._parts, self._shown))

    @visible.setter
    def visible(self, value: Dict[Any, bool]) -> None:
        self._check_open()
        self._show_parts(_visible(value, self._parts))
        self._show(draft=False)

    def _show_parts(self, changes: Dict[int, bool]) -> None:
        """Shows or hides parts (by index), and the toolbar's list follows (the caller renders)."""
        shown = list(self._shown)
        for i, on in changes.items():
            shown[i] = on
        self._shown = shown
        self._send_parts()

    def _send_parts(self) -> None:
        if self._widget is not None:
            self._widget._parts = {"names": list(self._parts), "visible": list(self._shown)}

    def _go_home(self) -> None:
        with self._state_lock:
            self._view = copy.deepcopy(self._home)

    def _view_from(self, axis: str) -> None:
        direction = np.zeros(3)
        direction["xyz".index(axis[1])] = 1.0 if axis[0] == "+" else -1.0
        with self._state_lock:
            view = self._view
        along = float(np.dot(direction, view.up))
        if abs(along) > math.cos(_POLE_MARGIN):  # from the pole: as far as orbiting goes, facing as now
            level = (view.eye - view.target) - float(np.dot(view.eye - view.target, view.up)) * view.up
            if np.linalg.norm(level) < 1e-12:
                level = np.cross(view.up, (1.0, 0.0, 0.0) if abs(view.up[0]) < 0.9 else (0.0, 0.0, 1.0))
            direction = math.copysign(math.cos(_POLE_MARGIN), along) * view.up + math.sin(_POLE_MARGIN) * _unit(level)
        self._fit(direction, view)

    def _reframe(self) -> None:
        with self._state_lock:
            view = self._view
        self._fit(view.eye - view.target, view)

    def _fit(self, direction: np.ndarray, view: _View) -> None:
        """Frames the scene from ``direction`` (target to eye) with ``view``'s up and projection."""
        up = tuple(float(x) for x in view.up)
        camera = Camera.fit(tuple(float(x) for x in direction), up=up, orthographic=view.orthographic,
                            fov_y=None if view.orthographic else view.fov_y)
        self._set_camera(camera)

    def _move(self, kind: str, a: float, b: float) -> None:
        with self._state_lock:
            if kind == "orbit":  # pointer moves are in layout pixels, the view's
                self._view.orbit(a, b, self.height)
            elif kind == "pan":
                self._view.pan(a, b, self.height)
            else:
                self._view.zoom(a)

    # -- render settings ----------------------------------------------------------------------

    @property
    def options(self) -> RenderOptions:
        """The render settings of the current view (:class:`toonmesh.RenderOptions`)."""
        return self._options.replace(camera=self.camera)

    def set(self, **options: "Unpack[RenderKeywords]") -> None:
        """Changes several render settings at once, then renders once; where the settings or the
        render are refused, the viewer keeps the settings it had.

        Args:
            **options: render keywords (:class:`toonmesh.RenderKeywords`).
        """
        self._check_open()
        if "outputs" in options:
            raise TypeError("outputs: a Viewer shows the colour image; use snapshot(outputs=...) for others")
        with self._state_lock:
            before = (self._options, self._layout, dict(self._given), copy.deepcopy(self._view))
        try:
            self._set(dict(options))
        except BaseException:
            with self._state_lock:
                self._options, self._layout, self._given, self._view = before
            self._settings_shown()
            raise

    def _set(self, options: Dict[str, Any]) -> None:
        camera = options.pop("camera", None)
        sides = {k: checked(k, options.pop(k)) for k in LAYOUT if k in options}
        layout = copy.copy(self._layout)  # held once the options it makes are checked
        for name, value in sides.items():
            setattr(layout, name, value)
        self._options = self._options.replace(**options, **layout.frame())
        self._layout = layout
        for k, v in options.items():
            if v is None:
                self._given.pop(k, None)
            else:
                self._given[k] = v
        if camera is not None:
            self._set_camera(camera)
        self._settings_shown()
        self._show(draft=False)

    def _settings_shown(self) -> None:
        """The on-screen controls show the settings as they are now."""
        if self._controls is not None:
            self._controls.refresh()

    # -- rendering ----------------------------------------------------------------------------

    def _render(self, camera: Camera, width: int, height: int) -> RenderResult:
        with self._render_lock:
            self._check_open()
            options = self._options.replace(camera=camera, width=width, height=height, outputs=("color",))
            result = draw(self._renderer, self._scene(), options, self._lines)
            self.render_count += 1
            return result

    def _show(self, draft: bool) -> RenderResult:
        """Renders the current view (at ``drag_scale`` of the size when ``draft``) and sends it
        to the front end, marked with the number of the browser's view it shows."""
        with self._render_lock:
            with self._state_lock:
                camera = self._view.camera()
                view_id = self._shared.view_id
            width, height = self._options.width, self._options.height
            if draft:
                width = max(1, round(width * self.drag_scale))
                height = max(1, round(height * self.drag_scale))
            result = self._render(camera, width, height)
            assert result.color is not None
            data, fmt = _encode(result.color, "jpeg" if draft else self.image_format)
            self.frame = result.color
            self._frame_id += 1
            if self._widget is not None:
                if not draft:
                    self._send_draft()
                width, height = self._layout.view_size()
                self._widget.show_frame(data, fmt, self._frame_id, width, height, view_id=view_id,
                                        exact=not draft, camera=self._camera_state(), layout=self._layout.state())
            self._shared.answered = view_id
            return result

    # -- drafts drawn in the browser ----------------------------------------------------------

    def _camera_state(self) -> Dict[str, Any]:
        """The current view as the browser's draft renderer moves it (``moves.js``)."""
        with self._state_lock:
            v = self._view
            return {"eye": v.eye.tolist(), "target": v.target.tolist(), "up": v.up.tolist(),
                    "orthographic": v.orthographic, "fov_y": v.fov_y, "height": v.height}

    def _draft(self) -> Tuple[str, bytes]:
        """The core's draft of the scene with the viewer's settings from the current view: its
        JSON and its bytes (see ``toonmesh.viewer._draft``)."""
        with self._render_lock:
            self._check_open()
            with self._state_lock:
                camera = self._view.camera()
            options = self._options.replace(camera=camera, outputs=("color",))
            spec, blob = self._renderer._engine._draft(_core_items(self._scene()), options, lines=_core_lines(self._lines))
            data = bytes(blob)
            return spec, self._uploads[0].shared_bytes(data) if self._uploads else data

    # Whether the browser draws the drafts (False: the kernel does, as before WebGL2 drafts; the
    # viewer benchmark's yardstick).
    _browser_drafts = True

    def _send_draft(self) -> None:
        """Sends the draft to the browser once, and again when a setting changed."""
        if not self._browser_drafts:
            return
        # the settings, the projection the draft's footprint is for and the parts shown (not the
        # size: the browser draws the draft at any size and pixel ratio)
        with self._state_lock:
            settings = self._options.replace(camera=None, width=1, height=1, pixel_ratio=1.0)
            key = repr((settings, self._view.orthographic, self._shown))
        if key == getattr(self, "_draft_key", None):
            return
        try:
            spec, blob = self._draft()
        except ViewerClosedError:
            raise
        except Exception as exc:  # the kernel's drafts remain; the tooltip says why
            spec, blob = json.dumps({"error": f"{type(exc).__name__}: {exc}"}), b""
        self._draft_key = key
        self._widget.show_draft(spec, blob, self._moves())

    def to_html(self, path: "str | os.PathLike[str]") -> str:
        """Writes a standalone HTML page that orbits the scene from the current view.

        The page draws it in the browser by WebGL2 with toonmesh's own shaders (translated to GLSL
        ES 3.00 by the core; the draft the viewer shows while the pointer moves: the toon shading,
        the mesh's colours and texture, hatching, image-space ink and mesh-space lines; smooth
        contours, shadows, paper and supersampling are left out, and the page's tooltip says
        which). Everything is inlined (the script, the shaders, the mesh as base64): the page needs
        no kernel and no network. Drag to orbit, shift-drag to pan, wheel to zoom, double-click for
        the first view. The page's root element has the ``toonmesh-viewer`` class and counts the
        frames drawn in ``data-frames-shown``.

        Args:
            path: the HTML file to write (str or os.PathLike).

        Returns:
            The path written, as a string.
        """
        self._check_open()
        target = os.fspath(path) if isinstance(path, (str, os.PathLike)) else None
        if not isinstance(target, str):
            raise TypeError(f"path: expected a str or os.PathLike, got {type(path).__name__}")
        from toonmesh.viewer._draft import page

        spec, blob = self._draft()
        text = page(spec, blob, self._camera_state(), self._moves(), self._layout.view_size(), "toonmesh viewer")
        with open(target, "w", encoding="utf-8") as out:
            out.write(text)
        return target

    def snapshot(self, **options: "Unpack[RenderKeywords]") -> RenderResult:
        """The current view rendered at full quality.

        Args:
            **options: render keywords (:class:`toonmesh.RenderKeywords`) that override the
                viewer's settings for this render only (``width``, ``height`` in output pixels,
                ``supersample``, ``outputs``, ...; by default the frame's size and pixel ratio, so
                ``pixel_ratio=1`` for widths as ``tm.render`` draws them).

        Returns:
            The render, a :class:`toonmesh.RenderResult`.
        """
        self._check_open()
        with self._render_lock:
            opts = self.options.replace(**options)
            placed = self._placed if "material" in self._given or options.get("material") is not None else self._placed_own
            placed = self._shown_of(placed)
            result = draw(self._renderer, placed, opts, self._lines)
            self.render_count += 1
            return result

    def turntable(self, path: "str | os.PathLike[str]", seconds: float = DEFAULT_SECONDS, fps: int = DEFAULT_FPS) -> str:
        """Writes a turn of the view about its target and the world's up, from the current view
        all the way round, at the viewer's size and settings, with a progress bar while it is
        written (:meth:`toonmesh.RenderStack.save`). The views are drawn by the renderer's
        many-view render (:meth:`toonmesh.Renderer.render_many`).

        Args:
            path: a ``.gif`` (Pillow), ``.mp4`` (H.264) or ``.webm`` (VP9; both through
                imageio-ffmpeg, width and height even).
            seconds: the turn's length, in (0, 600]; default 4.
            fps: frames per second, an int in [1, 60]; default 24. The video has
                ``round(seconds * fps)`` frames, at least one.

        Returns:
            The path written, as a string.
        """
        self._check_open()
        kind = video_kind(path)
        seconds = _number("seconds", seconds, 0.0, 600.0)
        fps = check_fps(fps)
        if seconds == 0:
            raise ValueError("seconds: must be more than 0, got 0")
        count = max(1, round(seconds * fps))
        check_video_size(kind, self._options.width, self._options.height, "path")
        video_writer(kind, "turntable")
        with self._state_lock:
            start = copy.deepcopy(self._view)
        cameras = []
        for i in range(count):
            view = copy.deepcopy(start)
            view.eye = view.target + _rotate(start.eye - start.target, start.up, 2.0 * math.pi * i / count)
            cameras.append(view.camera())
        with self._render_lock:
            self._check_open()
            options = self._options.replace(camera=None, outputs=("color",))
            stack = draw_views(self._renderer, self._scene(), cameras, options, self._lines)
            self.render_count += count
        return stack.save(path, fps=fps)

    def code(self) -> ViewerCode:
        """The ``tm.render(...)`` call that reproduces the current frame (shown unquoted in a
        notebook; ``print(v.code())`` elsewhere). Settings without a constructor spelling are
        written in their pickled form. The scene is named as it was given: ``V, F``, ``mesh``
        (a trimesh or a :class:`toonmesh.Mesh`), ``scene`` (a trimesh.Scene), ``meshes`` (a
        list) or the file's path."""
        parts = [self._scene_source()]
        if self._normals is not None:
            parts.append("normals=normals" if own_normals(self._normals) else f"normals={self._normals!r}")
        if self._smooth_iterations:
            parts.append(f"smooth_iterations={self._smooth_iterations!r}")
        with self._state_lock:
            parts.append(f"camera={self._view.source()}")
        parts += [f"width={self._options.width}", f"height={self._options.height}"]  # the frame's, in pixels
        if self._options.pixel_ratio != 1.0:
            parts.append(f"pixel_ratio={self._options.pixel_ratio!r}")
        for name in SETTINGS:
            if name in self._given:
                parts.append(f"{name}={_source(self._given[name])}")
        arguments = "".join(f"    {p},\n" for p in parts)
        return ViewerCode(f"import toonmesh as tm\n\nr = tm.render(\n{arguments})\n")

    def _scene_source(self) -> str:
        """The scene as code() names it: as it was given, with only the parts shown."""
        kept = tuple(i for i, shown in enumerate(self._shown) if shown)
        if len(kept) == len(self._shown):
            return self._mesh_source
        if not kept:
            return "None"  # an empty scene
        if self._mesh_source == "meshes":
            return f"[meshes[i] for i in {kept!r}]"
        # a file or a trimesh.Scene, read as tm.render reads it (a single mesh is one part: all
        # shown or none)
        return f"[m for i, m in enumerate(tm.load({self._mesh_source})) if i in {kept!r}]"

    # -- the front end's events and flow control ----------------------------------------------

    def _on_event(self, content: Dict[str, Any]) -> None:
        """A message from the front end. ``{"event": "view", "id": n, "steps": [...], "exact":
        bool}``: the browser's view number ``n`` (it sends the next only once a frame or an
        error answers this one); the camera takes the steps at once (each ``{"event": kind,
        ...}``, as below) and a frame of the result is asked for, full size when ``exact``, else
        a draft. A single step alone: ``orbit``/``pan``/``zoom`` with ``dx``, ``dy`` (a draft),
        ``settle`` (the full-size frame), ``frame`` (frame the scene again), ``home``, ``axis``
        with ``axis`` (see :meth:`view_from`), ``projection`` with ``projection`` (see
        :attr:`projection`), ``part`` with ``part`` (an index in :attr:`parts`) and ``visible``
        (True or False; see :attr:`visible`)."""
        if self._shared.closed:
            return
        # {"event": "shown" | "gone", "view": token}: a view of the widget drawn on the page, or
        # removed (the page holds the viewer meanwhile: _Shown)
        if content.get("event") in ("shown", "gone"):
            _SHOWN.view(self, str(content.get("view")), content["event"] == "shown")
            return
        try:
            if content.get("event") == "view":
                steps = content.get("steps") or []
                exact = bool(content.get("exact"))
                view_id = int(content.get("id", 0))
                with self._state_lock:
                    self._shared.views += 1
                    self._shared.early += self._shared.answered < self._shared.view_id
            else:
                steps = [content]
                exact = content.get("event") not in ("orbit", "pan", "zoom")
                view_id = None
            for step in steps:
                self._step(step)
        except Exception as exc:  # answered, so that the browser sends its next view
            if view_id is not None:
                with self._state_lock:
                    self._shared.view_id = self._shared.answered = max(self._shared.view_id, view_id)
            if self._widget is not None:
                self._widget.show_error(f"{type(exc).__name__}: {exc}", self._shared.view_id)
            return
        if view_id is not None:
            with self._state_lock:
                self._shared.view_id = max(self._shared.view_id, view_id)
        self._ask(draft=not exact)

    def _step(self, step: Dict[str, Any]) -> None:
        event = step.get("event")
        if event in ("orbit", "pan"):
            self._move(event, _pixels("dx", float(step.get("dx", 0))), _pixels("dy", float(step.get("dy", 0))))
        elif event == "zoom":
            wheel = _number("dy", float(step.get("dy", 0)), -_MAX_DRAG, _MAX_DRAG)
            factor = float(np.clip(math.exp(-_WHEEL_ZOOM * wheel), 1.0 / _MAX_ZOOM, _MAX_ZOOM))
            self._move("zoom", factor, 0.0)
            # toward the cursor (x, y: its offset from the view's centre, pixels): the point under
            # it at the target's depth stays under it (draftZoom in moves.js moves the same way)
            x, y = (_pixels(k, float(step.get(k, 0))) for k in ("x", "y"))
            if x or y:
                self._move("pan", -x * (factor - 1.0), -y * (factor - 1.0))
        elif event == "frame":
            self._reframe()
        elif event == "home":
            self._go_home()
        elif event == "axis":
            self._view_from(_axis(step.get("axis")))
        elif event == "projection":
            self._project(_projection(step.get("projection")))
            self._settings_shown()
        elif event == "part":
            part, on = step.get("part"), step.get("visible")
            self._show_parts(_visible({part: on}, self._parts))
        elif event == "size":
            self._layout.reported(step)
            self._resized()
        elif event != "settle":
            raise ValueError(f"event: unknown front-end event {event!r}")

    def _ask(self, draft: bool) -> None:
        """Asks the render thread for a frame of the current view (started if none runs; it
        ends when no frame is wanted); only the latest request is kept."""
        shared = self._shared
        with shared.lock:
            if shared.closed:
                return
            shared.wanted = draft
            if shared.worker is None:
                shared.worker = threading.Thread(target=_serve, args=(weakref.ref(self), shared),
                                                 name="toonmesh-viewer", daemon=True)
                shared.worker.start()
            shared.wake.notify_all()

    def _wait(self, timeout: float = 30.0) -> bool:
        """Waits until every frame asked for is sent (for tests and scripts); False on timeout."""
        shared = self._shared
        with shared.lock:
            return shared.wake.wait_for(lambda: shared.worker is None, timeout)

    # -- display ------------------------------------------------------------------------------

    @property
    def widget(self) -> Any:
        """The Jupyter widget (an ``anywidget.AnyWidget``), or None without the notebook extra."""
        return self._widget

    def _displayed(self) -> None:
        """Shown in a kernel: held until its views are drawn (see ``_Shown``)."""
        if self._widget is not None and _in_kernel():
            _SHOWN.displayed(self)

    def _repr_png_(self) -> Optional[bytes]:
        return None if self.frame is None else _core.encode_png_rgba(self.frame)

    def _repr_mimebundle_(self, include: Any = None,
                          exclude: Any = None) -> Tuple[Dict[str, Any], Dict[str, Any]]:
        """The widget where a front end shows widgets, and always the current frame as PNG (what
        nbconvert, GitHub and an untrusted notebook show) with a line of text; with the metadata
        that shows the PNG at the view's size in layout pixels (sharp at a pixel ratio above 1,
        as the live view is)."""
        bundle: Dict[str, Any] = {}
        self._displayed()
        shown = self._controls.widget if self._controls is not None and self._controls.beside else self._widget
        if shown is not None and not self._shared.closed:
            widget_bundle = shown._repr_mimebundle_(include=include, exclude=exclude)
            if isinstance(widget_bundle, tuple):
                widget_bundle = widget_bundle[0]
            bundle.update(widget_bundle or {})
        png = self._repr_png_()
        metadata: Dict[str, Any] = {}
        if png is not None:
            bundle["image/png"] = png
            width, height = self._layout.view_size()
            metadata["image/png"] = {"width": width, "height": height}
        bundle["text/plain"] = repr(self)
        return bundle, metadata

    def __repr__(self) -> str:
        width, height = self._layout.view_size()
        ratio = self._layout.ratio()
        size = f"{width}x{height}" + ("" if ratio == 1.0 else f" at {ratio:g}x")
        if self._shared.closed:
            return f"toonmesh.Viewer({size}): closed"
        if self._widget is None:
            return f"toonmesh.Viewer({size}): a still frame; for the interactive view, {NOTEBOOK_EXTRA}"
        return f"toonmesh.Viewer({size}): interactive where Jupyter widgets run (JupyterLab, Notebook 7, VS Code)"


def _serve(ref: "weakref.ref[Viewer]", shared: _Shared) -> None:
    """The render thread: draws the latest frame asked for until none is wanted, then ends. It
    holds the viewer only while drawing, so a viewer no longer referenced is freed."""
    while True:
        with shared.lock:
            if shared.wanted is None or shared.closed:
                shared.wanted = None
                shared.worker = None
                shared.wake.notify_all()
                return
            draft, shared.wanted = shared.wanted, None
        viewer = ref()
        if viewer is None:
            continue
        try:
            viewer._show(draft=draft)
        except ViewerClosedError:
            pass
        except Exception as exc:  # shown in the widget, not lost in a thread
            shared.answered = shared.view_id
            if viewer._widget is not None:
                viewer._widget.show_error(f"{type(exc).__name__}: {exc}", shared.view_id)
        finally:
            del viewer


def _release(shared: _Shared, uploads: List[SharedUpload], front: List[Any]) -> None:
    """Frees a viewer's resources (its close(), or its finaliser once nothing refers to it):
    ends its render thread, lets go of its meshes' upload (freed with the last viewer that
    shares it) and closes its widgets."""
    with shared.lock:
        shared.closed = True
        shared.wanted = None
        shared.wake.notify_all()
    uploads.clear()
    for item in reversed(front):  # the controls (a ControlPanel: its box and every control), then the frame's widget
        item.close()
    front.clear()


def _mesh_source(vertices: Any, faces: Any) -> str:
    """How code() names the scene: as it was given."""
    if faces is not None:
        return "V, F"
    if isinstance(vertices, (str, os.PathLike)):
        return repr(os.fspath(vertices))
    if is_scene(vertices):
        return "scene"
    if isinstance(vertices, (list, tuple)):
        return "meshes"
    return "mesh"


def _one_of(name: str, value: Any, choices: Tuple[str, ...], expected: str) -> str:
    """``value``, one of ``choices``: else TypeError (not a string) or ValueError (another one),
    each naming ``name`` and what it ``expected``."""
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected {expected}, got {type(value).__name__}")
    if value not in choices:
        raise ValueError(f"{name}: expected {expected}, got {value!r}")
    return value


def _projection(projection: Any) -> str:
    return _one_of("projection", projection, PROJECTIONS, " or ".join(map(repr, PROJECTIONS)))


def _part_names(meshes: List[Mesh]) -> List[str]:
    """Each mesh's name, ``part N`` (from 1) where it has none; a name met again gets `` (2)``,
    `` (3)``..."""
    names: List[str] = []
    for i, mesh in enumerate(meshes):
        base = mesh.name or f"part {i + 1}"
        name, n = base, 1
        while name in names:
            n += 1
            name = f"{base} ({n})"
        names.append(name)
    return names


def _visible(value: Any, parts: List[str]) -> Dict[int, bool]:
    """``visible``'s dict of parts (names or indices in ``parts``) to True or False, by index."""
    if not isinstance(value, dict):
        raise TypeError(f"visible: expected a dict of parts (names or indices) to True or False, got "
                        f"{type(value).__name__}")
    out: Dict[int, bool] = {}
    for part, on in value.items():
        if isinstance(part, str):
            if part not in parts:
                raise ValueError(f"visible: no part named {part!r} (the parts: {', '.join(map(repr, parts))})")
            index = parts.index(part)
        elif isinstance(part, (int, np.integer)) and not isinstance(part, (bool, np.bool_)):
            if not 0 <= part < len(parts):
                raise ValueError(f"visible: part {part} is out of range (the scene has {len(parts)} parts)")
            index = int(part)
        else:
            raise TypeError(f"visible: a part is a name or an index, got {type(part).__name__}")
        if not isinstance(on, (bool, np.bool_)):
            raise TypeError(f"visible[{part!r}]: expected True or False, got {type(on).__name__}")
        out[index] = bool(on)
    return out


def _axis(axis: Any) -> str:
    return _one_of("axis", axis, AXES, "one of " + ", ".join(AXES))


#: The render settings a viewer holds as attributes, in the order code() writes them (not those
#: of the view's layout, read as shown: code() writes the frame's size and ratio instead).
SETTINGS = tuple(name for name, value in vars(Viewer).items() if isinstance(value, _Setting) and value.shown is None)


def _number(name: str, value: Any, lo: float, hi: float) -> float:
    """``value`` as a float in [lo, hi]: TypeError for a non-number (a bool too), ValueError
    outside the range (NaN always is)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: expected a number, got {type(value).__name__}")
    big = isinstance(value, int) and abs(value) >= 2**1023  # beyond a float: out of any range here
    number = (math.inf if value > 0 else -math.inf) if big else float(value)
    if not lo <= number <= hi:
        raise ValueError(f"{name}: must be in [{lo:g}, {hi:g}], got {value}")
    return number


def _pixels(name: str, value: Any) -> float:
    """A drag's length in pixels (finite; at most a million either way)."""
    return _number(name, value, -_MAX_DRAG, _MAX_DRAG)


def _format(image_format: Any) -> str:
    if not isinstance(image_format, str):
        raise TypeError(f"image_format: expected 'png' or 'jpeg', got {type(image_format).__name__}")
    if image_format not in ("png", "jpeg"):
        raise ValueError(f"image_format: expected 'png' or 'jpeg', got {image_format!r}")
    return image_format


# -- code() ---------------------------------------------------------------------------------------


def _source(value: Any) -> str:
    """Python source for a setting's value, checked to give the value back."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return repr(value)
    if isinstance(value, np.ndarray):
        return repr(value.tolist())
    if isinstance(value, (list, tuple)):
        inner = ", ".join(_source(v) for v in value)
        return f"[{inner}]" if isinstance(value, list) else f"({inner}{',' if len(value) == 1 else ''})"
    for candidate in _spellings(value):
        if _gives(candidate, value):
            short = _FLOAT.sub(lambda m: repr(float(f"{float(m.group()):.7g}")), candidate)  # float32 noise off
            return short if _gives(short, value) else candidate
    restore, (cls, state) = value.__reduce__()
    return f"tm._core._restore({cls!r}, {state!r})"


_FLOAT = re.compile(r"(?<![\w.])-?\d+\.\d+(?:e[-+]?\d+)?")


#: What ``tm`` names in the source code() writes, to check that source here: the settings classes,
#: taken from the core (the package imports this module, so this one does not import it).
_TM = types.SimpleNamespace(**{name: getattr(_core, name) for name in _core.SETTINGS_CLASSES}, _core=_core)
#: A settings class's name where a repr calls it or one of its constructors.
_CLASS = re.compile(r"(?<![\w.'\"])(" + "|".join(_core.SETTINGS_CLASSES) + r")(?=[.(])")


def _gives(source: str, value: Any) -> bool:
    try:
        return bool(eval(source, {"tm": _TM}) == value)
    except Exception:
        return False


def _spellings(value: Any) -> List[str]:
    """Constructor calls that may give ``value`` back (each is checked): a settings value's repr
    (which evaluates back to it) with its classes as ``tm``'s; an outline set by its kind first."""
    out: List[str] = [repr(value.kind)] if isinstance(value, Outlines) else []
    if type(value).__name__ in _core.SETTINGS_CLASSES:
        out.append(_CLASS.sub(r"tm.\1", repr(value)))
    return out


# -- the widget -----------------------------------------------------------------------------------


def _make_widget(viewer: Viewer) -> Any:
    """The anywidget front end, or None where anywidget is not installed."""
    try:
        from toonmesh.viewer._widget import ViewerWidget
    except ImportError:
        return None
    widget = ViewerWidget()
    widget._moves = viewer._moves()  # for pinches, before any draft
    widget.attach(weakref.WeakMethod(viewer._on_event), weakref.WeakMethod(viewer._displayed))
    return widget


__all__ = ["AXES", "PROJECTIONS", "Viewer", "ViewerClosedError", "ViewerCode"]
