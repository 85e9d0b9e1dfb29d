"""What a render gives back. The core returns each render as a plain dict of arrays and
numbers; this module is the one place those dicts are read, into :class:`RenderResult` (one view)
and :class:`RenderStack` (the views of one scene), which the rest of the package uses.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any, Callable, Dict, List, Optional, Sequence, Tuple, TypedDict

import numpy as np

from toonmesh import _core
from toonmesh.rendering import _strokes
from toonmesh._core import LineStyle, Outlines
from toonmesh.rendering._video import DEFAULT_FPS, save_video

#: The kind of the lines of :class:`toonmesh.Lines` items (the core names it).
LINES: str = _core.ITEM_INKS[0]

if TYPE_CHECKING:
    from typing_extensions import Unpack


class SvgOptions(TypedDict, total=False):
    """The keywords of :meth:`RenderResult.svg`, :meth:`RenderResult.save_svg` and
    :meth:`RenderResult.svg_groups`, whose signature gives their defaults."""

    order: str
    simplify: float
    smooth: float
    widths: str


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
      suggestive contour's strength, as the ink is drawn); the visible parts of
      :class:`toonmesh.Lines` items are among them, of kind ``"lines"``, with ``line_items``
      giving each line's item (its index among the scene's Lines items; None for a mesh's
      line) and ``line_inks`` each item's ``(sRGB colour, width in pixels)`` as drawn;
    - ``passes``: every step that ran, in order; ``timings``: seconds per step, with ``frame``
      the whole render; GPU passes are timed on the GPU when ``timing_source`` is ``"gpu"``,
      otherwise only the frame as a whole (``"wall"``);
    - ``view_matrix``, ``projection`` (4x4 float64), ``near``, ``far``: the camera used;
      ``up``: the scene's up axis ("x", "y" or "z"), which a fitted camera keeps up;
    - ``culled``: per scene mesh, in order, whether its inner sides were skipped. That happens
      only where they cannot show (a closed, consistently wound mesh whose bounding sphere lies
      wholly beyond the near plane), so the image is the same, drawn in about half the time.
    """

    def __init__(self, raw: Dict[str, Any], backend: str, outlines: Optional[Outlines] = None):
        # raw: the core's dict of one render; read here and nowhere else
        self.color: Optional[np.ndarray] = raw["color"]
        self.normal: Optional[np.ndarray] = raw["normal"]
        self.depth: Optional[np.ndarray] = raw["depth"]
        self.outline: Optional[np.ndarray] = raw["outline"]
        self.shadow: Optional[np.ndarray] = raw["shadow"]
        self.lines: Optional[List[np.ndarray]] = None
        self.line_kinds: Optional[List[str]] = raw["line_kinds"]
        self.line_widths: Optional[List[np.ndarray]] = None
        self.line_items: Optional[List[Optional[int]]] = raw["line_items"]
        self.line_inks: List[Tuple[Tuple[float, float, float], float]] = [
            (tuple(c), float(w)) for c, w in raw["line_inks"]]
        if raw["lines"] is not None:  # every point, where each line starts, every point's width
            points, starts, widths = raw["lines"]
            self.lines = [points[a:b] for a, b in zip(starts[:-1], starts[1:])]
            self.line_widths = [widths[a:b] for a, b in zip(starts[:-1], starts[1:])]
        self.passes: List[str] = list(raw["passes"])
        self.timings: Dict[str, float] = dict(raw["timings"])
        self.timing_source: str = "gpu" if raw["gpu_timed"] else "wall"
        self.culled: List[bool] = list(raw["culled"])
        self.view_matrix: np.ndarray = np.array(raw["view"])
        self.projection: np.ndarray = np.array(raw["proj"])
        self.near: float = raw["near"]
        self.far: float = raw["far"]
        self.up: str = raw["up"]
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
        """Writes the colour image as PNG (whatever the file name's extension).

        Args:
            path: the file to write (str or os.PathLike).
        """
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

    def svg(self, **options: "Unpack[SvgOptions]") -> str:
        """The visible mesh-space lines as an SVG document of the image's size (pixel units),
        one group per kind, one shape per stroke in its kind's colour: a ``<polyline>`` stroked
        at its kind's width, or, where the width varies along the stroke, a filled ``<path>``
        outlining the ink as the render draws it (:attr:`line_widths`).

        Keyword Args:
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
        return _strokes.svg_document(self.width, self.height, self.svg_groups(**options))

    def svg_groups(
        self,
        *,
        order: str = "drawing",
        simplify: float = _strokes.SIMPLIFY,
        smooth: float = _strokes.SMOOTH,
        widths: str = "auto",
    ) -> List["_strokes.SvgGroup"]:
        """The groups of :meth:`svg`'s document (the same arguments; their defaults are these),
        hidden lines first (underneath), then one per kind in name order, then one per
        :class:`toonmesh.Lines` item on top, in the scene's order (``"lines"``; ``"lines-0"``,
        ``"lines-1"``, ... where there are several), in its own colour and width:
        ``(kind, colour, width or None for filled outlines, dashes, [(points, widths), ...])``
        (dashes: None for solid lines, else (dash, gap) in pixels from the kind's
        :class:`LineStyle`), for a caller that adds groups of its own before writing the document
        with the same writer."""
        _strokes.check(order, simplify, smooth, widths)
        styles = self.outlines.styles if self.outlines is not None else {}
        if self.line_kinds is None or self.line_widths is None:
            raise ValueError("lines: this render did not ask for the 'lines' output (outputs=(..., 'lines'))")
        # the kinds whose ink changes width along a stroke (taper, width by depth, a suggestive
        # contour's strength)
        uneven = {k for w, k in zip(self.line_widths, self.line_kinds) if len(w) and np.ptp(w) > 0}
        filled = lambda kind: widths == "point" or (widths == "auto" and kind in uneven)  # noqa: E731
        strokes = self._drawn_strokes(smooth, simplify, by_width=filled)
        groups: List[_strokes.SvgGroup] = []
        # hidden lines underneath, then the kinds in name order
        for kind in sorted({k for _, _, k in strokes} - {LINES}, key=lambda k: (k != "hidden", k)):
            style = styles.get(kind) or LineStyle()
            group = _strokes.in_order([(p, w) for p, w, k in strokes if k == kind], order)
            dashes = (style.dash, style.dash) if style.dash > 0 else None
            groups.append((kind, style.color, None if filled(kind) and not dashes else style.width, dashes, group))
        # the Lines items on top, each in its own ink
        items = self.line_items or [None] * len(strokes)
        for i, (color, width) in enumerate(self.line_inks):
            group = _strokes.in_order([(p, w) for (p, w, k), item in zip(strokes, items) if k == LINES and item == i],
                                      order)
            gid = LINES if len(self.line_inks) == 1 else f"{LINES}-{i}"
            groups.append((gid, color, width, None, group))
        return groups

    def save_svg(self, path: Any, **options: "Unpack[SvgOptions]") -> None:
        """Writes :meth:`svg`'s document to ``path``.

        Args:
            path: the file to write (str or os.PathLike).
            **options: :meth:`svg`'s ``order``, ``simplify``, ``smooth`` and ``widths``."""
        text = self.svg(**options)
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

    def save(self, path: "str | os.PathLike[str]", fps: int = DEFAULT_FPS, progress: bool = True) -> str:
        """Writes the views' colour images as a video, one frame a view in order (a turntable
        from :meth:`Renderer.render_many`).

        Args:
            path: a ``.gif`` (Pillow), ``.mp4`` (H.264) or ``.webm`` (VP9; both through
                imageio-ffmpeg, which ships its own ffmpeg; width and height even).
            fps: frames per second, an int in [1, 60]; default 24.
            progress: show a progress bar (tqdm) while it is written, where there are 8 views
                or more; default True.

        Returns:
            The path written, as a string."""
        if self.color is None:
            raise ValueError("path: a video holds the colour images: render them (outputs=('color', ...))")
        return save_video(path, self.color, fps, progress)


def stack_of(images: Dict[str, Any], reports: List[Dict[str, Any]], backend: str,
             outlines: Optional[Outlines]) -> RenderStack:
    """The views of one ``render`` call of the core with cameras: its stacked images, and one report
    (passes, timings, camera) a view, whose images are that view's slices."""
    results = []
    for i, report in enumerate(reports):
        raw = dict(report, **{k: None if v is None else v[i] for k, v in images.items()})
        results.append(RenderResult(raw, backend, outlines))
    return RenderStack(images, results)
