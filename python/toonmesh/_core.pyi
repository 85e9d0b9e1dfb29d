# Type stubs for the compiled core (checked against it with `python -m mypy.stubtest toonmesh._core`).
# Written by scripts/stubs.py (`make stubs`) from this template and the core's description of its
# settings classes: edit the template, not the output.
from typing import Any, Dict, Final, List, Literal, Optional, Sequence, Tuple, TypedDict, Union, final, overload

from typing_extensions import Unpack

import numpy as np
import numpy.typing as npt

__all__ = [
    "DITHER_PATTERNS",
    "DITHER_SPACES",
    "HIGHLIGHTS",
    "IMAGE_OUTPUTS",
    "INK_KINDS",
    "ITEM_INKS",
    "LINE_KINDS",
    "MODELS",
    "OUTLINE_KINDS",
    "CONTOUR_RULES",
    "IMAGE_RULES",
    "OUTPUTS",
    "SHADOW_FILTERS",
    "HATCH_MODES",
    "BACKENDS",
    "UP_AXES",
    "FILE_UP_AXES",
    "DEFAULT_UP_AXIS",
    "SMOOTH_METHODS",
    "SMOOTH_WEIGHTS",
    "SMOOTH_BOUNDARIES",
    "SMOOTH_PRESETS",
    "DEFAULT_CREASE_ANGLE",
    "SETTINGS_CLASSES",
    "Dither",
    "Rim",
    "Shadows",
    "Light",
    "Camera",
    "LineStyle",
    "Outlines",
    "Material",
    "Paper",
    "EyeDome",
    "RenderOptions",
    "ConvergenceError",
    "GpuError",
    "GpuUnavailableError",
    "Renderer",
    "_EdgeIndex",
    "__version__",
    "_chains",
    "_curvature",
    "_feature_edges",
    "_intersection_lines",
    "_intersections",
    "_normal_mode",
    "_point_normals",
    "_up_axis",
    "_paper_edges",
    "_pen_strokes",
    "_plotter_order",
    "_restore",
    "_RenderKeywords",
    "_shadow_truth",
    "_srgb_from_linear",
    "_transform",
    "_smooth",
    "_smoothing_description",
    "_sobel",
    "_svg_document",
    "_vertex_count",
    "_view_lines",
    "decode_png",
    "encode_png_rgba",
    "get_num_threads",
    "gpu_info",
    "grid",
    "icosphere",
    "kang_table",
    "set_num_threads",
]
__version__: str

# The names the core accepts (src/py/settings/mod.rs)
OUTPUTS: Tuple[str, ...]
IMAGE_OUTPUTS: Tuple[str, ...]
LINE_KINDS: Tuple[str, ...]
INK_KINDS: Tuple[str, ...]
ITEM_INKS: Tuple[str, ...]
OUTLINE_KINDS: Tuple[str, ...]
CONTOUR_RULES: Tuple[str, ...]
IMAGE_RULES: Tuple[str, ...]
MODELS: Tuple[str, ...]
HIGHLIGHTS: Tuple[str, ...]
DITHER_PATTERNS: Tuple[str, ...]
DITHER_SPACES: Tuple[str, ...]
SHADOW_FILTERS: Tuple[str, ...]
HATCH_MODES: Tuple[str, ...]
BACKENDS: Tuple[str, ...]
#: The up axes a scene may have, each mesh file format's (by suffix, lower case, no dot) and the
#: default of a scene without one.
UP_AXES: Tuple[str, ...]
FILE_UP_AXES: Dict[str, str]
DEFAULT_UP_AXIS: str
#: The settings classes, by name (each is a class of this module).
SETTINGS_CLASSES: Tuple[str, ...]
SMOOTH_METHODS: Tuple[str, ...]
SMOOTH_WEIGHTS: Tuple[str, ...]
SMOOTH_BOUNDARIES: Tuple[str, ...]
SMOOTH_PRESETS: Tuple[str, ...]
DEFAULT_CREASE_ANGLE: float

class ConvergenceError(RuntimeError): ...
class GpuUnavailableError(RuntimeError): ...
class GpuError(RuntimeError): ...

# a mesh argument: (vertices, faces), read as every mesh function reads them (src/py/mesh_input.rs)
_Mesh = Tuple[Any, Any]

def set_num_threads(n: int) -> None: ...
def get_num_threads() -> int: ...
def icosphere(subdivisions: int, noise: float, seed: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def grid(n: int, noise: float, seed: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
# the keywords of toonmesh.smooth's functions (their signatures are the documentation)
def _smooth(method_name: str, mesh: _Mesh, **options: Any) -> npt.NDArray[np.floating[Any]]: ...
def _smoothing_description() -> List[Dict[str, Any]]:
    """Every smoothing method as the core describes it (src/smooth/described.rs): a list of
    {"method", "help", "keywords", "presets"}, each keyword a dict of name, kind, min/max/exclusive
    or choices, optional, default, default_words, presets, preset_ranges and help."""

# --- rendering (src/py/scene.rs, src/py/render.rs); its Python side is toonmesh.rendering._render ---

_Color = Any  # '#rrggbb' or 3 numbers in [0, 1]
_Vec3 = Tuple[float, float, float]


class _RenderKeywords(TypedDict, total=False):
    """The keywords of RenderOptions (None: the core's default)."""
    material: Optional[Material]
    transform: Optional[Any]
    camera: Optional[Camera]
    up: Optional[Literal['x', 'y', 'z']]
    lights: Optional[Union[Light, Sequence[Light]]]
    ambient: Optional[_Color]
    background: Optional[_Color]
    width: Optional[int]
    height: Optional[int]
    outputs: Optional[Union[str, Sequence[str]]]
    msaa: Optional[int]
    supersample: Optional[int]
    pixel_ratio: Optional[float]
    band_antialias: Optional[bool]
    glass_layers: Optional[int]
    outlines: Optional[Union[str, Outlines]]
    paper: Optional[Paper]
    eye_dome: Optional[EyeDome]

class _Settings:
    @staticmethod
    def describe() -> Dict[str, Any]: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

@final
class Dither(_Settings):
    """Dithering between neighbouring bands (Borquez and Yepez): L.n + (t - 1/2) amount is banded,
    t the pattern's threshold at the pixel. pattern: "bayer2", "bayer4" (default), "bayer8"
    (ordered dithering) or "blue" (the R2 sequence, a blue-noise-like pattern). space: "screen"
    (default, as in the paper: the pattern stays put while the object moves) or "object"
    (anchored to the surface, so a turntable does not shimmer). amount: in L.n, 0 to 2 (default
    0.15). scale: pixels a pattern cell covers, 1 to 64 (default 1).

    Fields: pattern: the threshold pattern; space: what the pattern is fixed to: the screen's
    pixels or the surface; amount: how far in L.n a pixel may move toward the neighbouring band,
    0 to 2; scale: pixels a pattern cell covers, 1 to 64; angle: degrees the pattern turns,
    counter-clockwise as seen, -90 to 90 (45: a print's screen angle).
    """
    def __new__(cls, pattern: Optional[Literal['bayer2', 'bayer4', 'bayer8', 'blue']] = ..., *, space: Optional[Literal['screen', 'object']] = ..., amount: Optional[float] = ..., scale: Optional[float] = ..., angle: Optional[float] = ...) -> Dither: ...
    pattern: Final[str]
    space: Final[str]
    amount: Final[float]
    scale: Final[float]
    angle: Final[float]
    def replace(self, *, pattern: Optional[Literal['bayer2', 'bayer4', 'bayer8', 'blue']] = ..., space: Optional[Literal['screen', 'object']] = ..., amount: Optional[float] = ..., scale: Optional[float] = ..., angle: Optional[float] = ...) -> Dither: ...

@final
class Rim(_Settings):
    """A rim light: a band of light (or of a colour) along the silhouette, where the surface turns
    away from the viewer. It covers the surface where n.v < width (n the normal, v toward the
    eye), with a hard border blended over a pixel like the bands' borders (softness 0) or faded
    over softness in n.v, in every shading model. color: sRGB (default white). width: 0 to 1
    (default 0.3). softness: 0 to 1 (default 0). strength: the share of the colour at full
    coverage, 0 to 1 (default 0.6). side: "both" (default), "lit" (where a light reaches the
    surface, n.l > 0) or "shadowed" (where none does: a back light's glow). blend: "add"
    (default: added as light) or "mix" (painted over the shading, as a colour). Give it to a
    material: ``Material.bands(rim=Rim())``.

    Fields: color: the rim's sRGB colour; width: the rim covers the surface where n.v < width, 0
    to 1; softness: how far in n.v its border fades, 0 (a hard border) to 1; strength: the share
    of its colour at full coverage, 0 to 1; side: where it shows: 'both' sides, the 'lit' side
    or the 'shadowed' side; blend: 'add' (as light) or 'mix' (painted over, as a colour).
    """
    def __new__(cls, color: Optional[_Color] = ..., *, width: Optional[float] = ..., softness: Optional[float] = ..., strength: Optional[float] = ..., side: Optional[Literal['both', 'lit', 'shadowed']] = ..., blend: Optional[Literal['add', 'mix']] = ...) -> Rim: ...
    color: Final[_Vec3]
    width: Final[float]
    softness: Final[float]
    strength: Final[float]
    side: Final[str]
    blend: Final[str]
    def replace(self, *, color: Optional[_Color] = ..., width: Optional[float] = ..., softness: Optional[float] = ..., strength: Optional[float] = ..., side: Optional[Literal['both', 'lit', 'shadowed']] = ..., blend: Optional[Literal['add', 'mix']] = ...) -> Rim: ...

@final
class Shadows(_Settings):
    """Shadow settings of a directional light: the shadow map's side in texels (a power of two from
    64 to 8192, default 2048), the depth bias in texels per unit of receiver slope (>= 0,
    default 1.0; more removes shadow acne on lit surfaces, less keeps contact shadows tight),
    the filter: "pcf" (default; percentage-closer filtering, soft edges a few texels wide) or
    "none" (one nearest test), and the strength: the share of the light a shadow takes away
    (default 1, a full shadow; 0.5 leaves half). The map is fitted to the scene's bounding
    sphere.

    Fields: size: the shadow map's side in texels, a power of two; bias: depth bias in texels
    per unit of receiver slope, >= 0; filter: how the map is read: 'pcf' (soft edges) or 'none';
    strength: the share of the light a shadow takes away: 1 a full shadow, 0.5 a half-tone one.
    """
    def __new__(cls, size: Optional[int] = ..., bias: Optional[float] = ..., filter: Optional[Literal['none', 'pcf']] = ..., *, strength: Optional[float] = ...) -> Shadows: ...
    size: Final[int]
    bias: Final[float]
    filter: Final[str]
    strength: Final[float]
    def replace(self, *, size: Optional[int] = ..., bias: Optional[float] = ..., filter: Optional[Literal['none', 'pcf']] = ..., strength: Optional[float] = ...) -> Shadows: ...

@final
class Light(_Settings):
    """A directional or point light; build one with the static methods. ``color`` is sRGB (default
    white) and ``intensity`` (>= 0, default 1) scales its light. ``space``: "world" (default) or
    "camera" (fixed to the camera: x right, y up, -z forward, so it moves with the view).

    Fields: kind: directional (sun-like) or point; direction: a directional light's direction,
    from the light toward the scene; position: a point light's position; color: sRGB colour;
    intensity: factor on the colour, >= 0; space: 'world', or 'camera': fixed to the view (x
    right, y up, -z forward); shadows: a directional light's shadows: True (the default
    Shadows), False or None (none), or a Shadows.
    """
    @staticmethod
    def directional(direction: Sequence[float], *, color: Optional[_Color] = ..., intensity: Optional[float] = ..., space: Optional[Literal['world', 'camera']] = ..., shadows: Optional[Union[bool, Shadows]] = ...) -> Light:
        """Parallel light travelling along ``direction`` (3 numbers, from the light toward the
        scene; any length > 0). ``shadows``: True (default settings), a :class:`Shadows`, or
        False/None (default): the light casts shadows from a shadow map (one light a scene).
        """
        ...
    @staticmethod
    def point(position: Sequence[float], *, color: Optional[_Color] = ..., intensity: Optional[float] = ..., space: Optional[Literal['world', 'camera']] = ...) -> Light:
        """Light radiating from ``position`` (3 numbers; no falloff with distance)."""
        ...
    @staticmethod
    def key() -> Light:
        """The default light: from the upper left, behind the viewer, fixed to the camera."""
        ...
    kind: Final[str]
    direction: Final[Optional[_Vec3]]
    position: Final[Optional[_Vec3]]
    color: Final[_Vec3]
    intensity: Final[float]
    space: Final[str]
    shadows: Final[Optional[Shadows]]
    def replace(self, *, direction: Optional[Sequence[float]] = ..., position: Optional[Sequence[float]] = ..., color: Optional[_Color] = ..., intensity: Optional[float] = ..., space: Optional[Literal['world', 'camera']] = ..., shadows: Optional[Union[bool, Shadows]] = ...) -> Light: ...

@final
class Camera(_Settings):
    """A camera; build one with :meth:`fit` (the default), :meth:`look_at` or :meth:`orthographic`.

    View space is right-handed: x right, y up, the camera looks down -z. ``near``/``far`` (clip
    distances, > 0 for perspective) are chosen to enclose the scene when None.

    Fields: kind: framed to fit the scene, or looking at a point; projection: the projection;
    eye: a look-at camera's position; target: the point a look-at camera looks at; up: the
    direction that is up in the image (a fitted camera's None: the scene's up axis); direction:
    a fitted camera's direction from the scene toward the eye (None: a three-quarter view about
    the up axis, across the scene's longest horizontal extent); margin: a fitted camera's room
    around the scene (1: touching); turn: degrees a fitted camera's view turns about the up
    axis, counter-clockwise seen from above (a turntable's views); fov_y: vertical field of view
    in degrees, in (0, 180); height: height of an orthographic view in world units, > 0; near:
    near clip distance (None: from the scene's bounds); far: far clip distance (None: from the
    scene's bounds).
    """
    @staticmethod
    def fit(direction: Optional[Sequence[float]] = ..., *, up: Optional[Sequence[float]] = ..., fov_y: Optional[float] = ..., margin: Optional[float] = ..., turn: Optional[float] = ..., orthographic: Optional[bool] = ...) -> Camera:
        """Frame the meshes' bounding box (and sphere) as near as they allow, seen from
        ``direction`` (scene -> eye; default None: a three-quarter view about the up axis, from
        the front turned 30 degrees toward the side and raised 25, its front chosen so that the
        camera looks across the scene's longest horizontal extent), turned ``turn`` degrees
        about the up axis (default 0; counter-clockwise seen from above), with ``up`` the
        image's up direction (default None: the scene's up axis, the render's ``up`` or its
        meshes' own, as ``toonmesh.load`` reads a file's convention, else +y). fov_y: vertical
        field of view in degrees (default 35); margin >= 1 leaves room around the scene (default
        1.05: it spans 1 / 1.05 of the image's height or width); orthographic: bool (default
        False).
        """
        ...
    @staticmethod
    def look_at(eye: Sequence[float], target: Optional[Sequence[float]] = ..., *, up: Optional[Sequence[float]] = ..., fov_y: Optional[float] = ..., near: Optional[float] = ..., far: Optional[float] = ...) -> Camera:
        """A perspective camera at ``eye`` looking at ``target`` (default the origin), with ``up``
        (default (0, 1, 0)) and a vertical field of view ``fov_y`` in degrees (default 35).
        """
        ...
    @staticmethod
    def orthographic(eye: Sequence[float], target: Optional[Sequence[float]] = ..., *, up: Optional[Sequence[float]] = ..., height: Optional[float] = ..., near: Optional[float] = ..., far: Optional[float] = ...) -> Camera:
        """An orthographic camera at ``eye`` looking at ``target``; ``height`` is the height of the
        view in world units (default 2).
        """
        ...
    kind: Final[str]
    projection: Final[str]
    eye: Final[Optional[_Vec3]]
    target: Final[Optional[_Vec3]]
    up: Final[Optional[_Vec3]]
    direction: Final[Optional[_Vec3]]
    margin: Final[Optional[float]]
    turn: Final[Optional[float]]
    fov_y: Final[Optional[float]]
    height: Final[Optional[float]]
    near: Final[Optional[float]]
    far: Final[Optional[float]]
    def replace(self, *, eye: Optional[Sequence[float]] = ..., target: Optional[Sequence[float]] = ..., up: Optional[Sequence[float]] = ..., direction: Optional[Sequence[float]] = ..., margin: Optional[float] = ..., turn: Optional[float] = ..., fov_y: Optional[float] = ..., height: Optional[float] = ..., near: Optional[float] = ..., far: Optional[float] = ...) -> Camera: ...

@final
class LineStyle(_Settings):
    """How one kind of ink line is drawn: ``color`` (sRGB, default black) and ``width`` in output
    pixels (default 1.5; the same at every resolution and supersampling factor).

    Fields: color: the ink's sRGB colour; width: width in output pixels, the same at every
    resolution and supersampling factor; dash: dash length in output pixels, gaps as long (0:
    solid).
    """
    def __new__(cls, color: Optional[_Color] = ..., width: Optional[float] = ..., *, dash: Optional[float] = ...) -> LineStyle: ...
    color: Final[_Vec3]
    width: Final[float]
    dash: Final[float]
    def replace(self, *, color: Optional[_Color] = ..., width: Optional[float] = ..., dash: Optional[float] = ...) -> LineStyle: ...

@final
class Outlines(_Settings):
    """Ink outlines for a render.

    kind: "mesh" (lines found on the mesh: Kang, Kim and Yoon), "image" (edges found in the
    frame's normal and depth buffers, by ``image_rule`` below) or "both" (default). color and
    width: the common style of every kind (default black, 1.5 output pixels). Each kind can be
    styled on its own with a keyword: silhouette, boundary, crease (both ridge and valley),
    ridge, valley, nonmanifold, suggestive, material, intersection, image, hidden; each takes
    None or True (the common style), False (not drawn), a :class:`LineStyle` (whose ``dash``
    draws it dashed), or a colour (image edges take the width under the discontinuity rule;
    under the paper rule they are whole pixels). Suggestive contours (DeCarlo et al., see
    :func:`toonmesh.edges.suggestive_contours`) are drawn only when asked for (suggestive=True,
    a style or a colour; default None: not drawn). Material borders are drawn where a boundary
    edge of one scene item lies on a boundary edge of another (the parts of a file with
    different materials, meshes that meet edge to edge), in place of those boundaries.
    Intersection lines are drawn where the surfaces of two scene items cross (a pin through a
    plate; on by default, in a scene of several meshes; items that only meet along an edge or
    rest on each other give none).

    visibility: how lines behind surfaces are found. "exact" (default): each line is cut where
    the scene's surfaces hide it, by rays from its points toward the camera counting the
    surfaces they cross (its quantitative invisibility), against a bounding-volume hierarchy of
    each mesh kept with it; a line under a surface never shows through it however thin the gap.
    "depth": against the frame's depth image with ``depth_offset`` pixel footprints of
    tolerance, per pixel on the GPU (the earlier rule: a line within the tolerance of a surface
    in front of it shows). hidden: the lines behind surfaces, drawn in their own style (True:
    grey, two thirds of the common width, dashed 3 widths on and off; off by default; needs the
    exact rule), as the kind "hidden" in ``RenderResult.lines`` and ``<g id="hidden">`` in the
    SVG. max_occlusion: hidden lines are drawn behind at most this many surfaces (each surface
    crossed counts: a closed part in front counts 2; default None: any number).

    contours: how silhouettes are found: "faces" (face edges between front- and back-facing
    faces, Kang et al.'s rule, exact for flat shading), "smooth" (the smooth contour n . v = 0
    traced through the faces, see :func:`toonmesh.edges.contours`: long clean lines on scans;
    the normals are split at the creases drawn, and on those crease edges the face-edge rule
    draws the silhouette) or "auto" (default: "smooth" for meshes drawn with smooth or auto
    normals, "faces" for flat-shaded ones).

    taper: mesh-space lines thin toward the ends of each chain over this many pixels of its
    length on screen, down to a fifth of their width (default 0: no taper; closed loops have no
    ends). width_by_depth: scale their width by the depth of the scene's centre over the line's
    depth, between 0.25x and 4x (default False). Both shape the ink (the colour and "outline"
    outputs), and ``RenderResult.line_widths`` gives the ink's width at each point of
    ``RenderResult.lines`` (pixels); the SVG then draws each stroke as a filled outline of that
    ink (``svg(widths="kind")``: centre lines at the kind's width, for a pen plotter).
    join_kinds: visible strokes that meet end to end within a line's width are joined into one
    stroke even when their kinds differ (a silhouette running on into a crease), taking the kind
    of their longest part, in ``RenderResult.lines`` and the SVG (default False: strokes of one
    kind only). suggestive_threshold: the derivative test of suggestive contours, relative to
    the mesh's feature size (default 0.01); a suggestive contour fades in by the strength with
    which it passes: its width goes from a fifth of its style's at the threshold toward the full
    width (half way where it passes by 0.03 / feature size^2, as the authors fade them).
    curvature_smoothing: the width, in mean edge lengths, over which the curvature of suggestive
    contours is averaged (as :func:`toonmesh.edges.curvature` with ``smoothing``), so a scan's
    noise does not draw (default None: 2, at most 1% of the bounding-box diagonal so a coarse
    mesh keeps its features; 0 is the one-ring estimate). min_crease_length: crease pieces
    (creases joined at their vertices, ridges and valleys together) shorter than this fraction
    of the mesh's bounding-box diagonal are not drawn, so that a scan's noise does not scatter
    crease dashes while a CAD part's creases stay (default 0.02; 0 draws every crease).
    max_crease_turn: crease pieces that turn by more than this many degrees on average at their
    vertices where two creases meet are not drawn: a scan's creases that follow the
    triangulation in a saw-tooth go, a CAD part's straight and gently curving creases stay
    (default 30; 180 draws every piece; with min_crease_length=0 it is the plain dihedral rule
    of :func:`toonmesh.edges.feature_edges`).

    crease_angle: dihedral angle in degrees above which an edge is a crease (default 30, as in
    :func:`toonmesh.edges.feature_edges`). weld: merge vertices at equal positions first, so UV
    or normal seams are not drawn as boundaries, and a sheet stored double-sided (each face
    twice, back to back) is drawn as one surface with its border (default True).

    image_rule: how image-space edges are found. "discontinuity" (default): between neighbouring
    pixels whose normals turn by more than normal_angle degrees (default 25), whose depths jump
    by more than depth_jump pixel footprints beyond what the surface's slope predicts (default
    3; a footprint is a pixel's size at that depth, so the rule is the same at any model scale),
    or where the surface meets the background; drawn as lines width pixels wide centred on those
    boundaries, antialiased. "paper": Borquez and Yepez's thresholded Sobel, whole edge pixels,
    with normal_threshold (default 1.0) and depth_threshold (default 0.1, in world depth units
    times 4): the rule of :func:`toonmesh.edges.detect_edges`. depth_offset: the depth rule
    (``visibility="depth"``) keeps a point of a line when its depth is at most the largest
    surface depth in the 3x3 pixels around it plus this many pixel footprints (the world size of
    one pixel at that depth; default 1.0); a silhouette or boundary with background among those
    pixels is on the rim and always shows.

    Fields: kind: lines found on the mesh, edges found in the image, or both; silhouette: True
    (the common style), False (not drawn), a LineStyle or a colour; boundary: True (the common
    style), False (not drawn), a LineStyle or a colour; nonmanifold: True (the common style),
    False (not drawn), a LineStyle or a colour; ridge: True (the common style), False (not
    drawn), a LineStyle or a colour; valley: True (the common style), False (not drawn), a
    LineStyle or a colour; suggestive: suggestive contours (DeCarlo et al.): drawn only when
    asked for; material: borders between scene items that meet edge to edge; intersection: where
    the surfaces of two scene items cross; image: image-space edges; hidden: lines behind
    surfaces (True: grey, thinner, dashed; off unless asked for); crease_angle: dihedral angle
    in degrees above which an edge is a crease; weld: merge vertices at equal positions first,
    so seams are not drawn as boundaries; contours: how silhouettes are found: 'faces', 'smooth'
    or 'auto'; suggestive_threshold: the suggestive contours' derivative test, relative to the
    mesh's feature size; curvature_smoothing: width in mean edge lengths over which suggestive
    contours' curvature is averaged (None: 2, at most 1% of the diagonal); suggestive_coherence:
    suggestive contours hold still across render_many's views: faded by how fast they slide,
    with hysteresis between frames; min_crease_length: crease pieces shorter than this fraction
    of the bounding-box diagonal are not drawn; max_crease_turn: crease pieces turning by more
    than this many degrees on average are not drawn (180: all); image_rule: how image-space
    edges are found; normal_angle: degrees of normal turn between pixels drawn as an edge;
    depth_jump: depth jump between pixels drawn as an edge, in pixel footprints;
    normal_threshold: the paper rule's Sobel threshold on normals; depth_threshold: the paper
    rule's Sobel threshold on depth; depth_offset: the depth rule's tolerance in pixel
    footprints; visibility: how lines behind surfaces are found: 'exact' (against the surfaces)
    or 'depth' (the depth image); max_occlusion: hidden lines are drawn behind at most this many
    surfaces (None: any number); taper: pixels over which lines thin toward their ends (0:
    none); width_by_depth: scale line widths by the scene centre's depth over the line's;
    join_kinds: join strokes of different kinds that meet end to end.
    """
    def __new__(cls, kind: Optional[Literal['mesh', 'image', 'both']] = ..., *, color: Optional[_Color] = ..., width: Optional[float] = ..., silhouette: Optional[Union[bool, LineStyle, _Color]] = ..., boundary: Optional[Union[bool, LineStyle, _Color]] = ..., crease: Optional[Union[bool, LineStyle, _Color]] = ..., ridge: Optional[Union[bool, LineStyle, _Color]] = ..., valley: Optional[Union[bool, LineStyle, _Color]] = ..., nonmanifold: Optional[Union[bool, LineStyle, _Color]] = ..., suggestive: Optional[Union[bool, LineStyle, _Color]] = ..., material: Optional[Union[bool, LineStyle, _Color]] = ..., intersection: Optional[Union[bool, LineStyle, _Color]] = ..., image: Optional[Union[bool, LineStyle, _Color]] = ..., hidden: Optional[Union[bool, LineStyle, _Color]] = ..., max_occlusion: Optional[int] = ..., visibility: Optional[Literal['exact', 'depth']] = ..., crease_angle: Optional[float] = ..., weld: Optional[bool] = ..., normal_threshold: Optional[float] = ..., depth_threshold: Optional[float] = ..., depth_offset: Optional[float] = ..., contours: Optional[Literal['faces', 'smooth', 'auto']] = ..., suggestive_threshold: Optional[float] = ..., curvature_smoothing: Optional[float] = ..., suggestive_coherence: Optional[bool] = ..., min_crease_length: Optional[float] = ..., max_crease_turn: Optional[float] = ..., image_rule: Optional[Literal['discontinuity', 'paper']] = ..., normal_angle: Optional[float] = ..., depth_jump: Optional[float] = ..., taper: Optional[float] = ..., width_by_depth: Optional[bool] = ..., join_kinds: Optional[bool] = ...) -> Outlines: ...
    kind: Final[str]
    silhouette: Final[Optional[Union[LineStyle, bool]]]
    boundary: Final[Optional[Union[LineStyle, bool]]]
    nonmanifold: Final[Optional[Union[LineStyle, bool]]]
    ridge: Final[Optional[Union[LineStyle, bool]]]
    valley: Final[Optional[Union[LineStyle, bool]]]
    suggestive: Final[Optional[Union[LineStyle, bool]]]
    material: Final[Optional[Union[LineStyle, bool]]]
    intersection: Final[Optional[Union[LineStyle, bool]]]
    image: Final[Optional[Union[LineStyle, bool]]]
    hidden: Final[Optional[Union[LineStyle, bool]]]
    crease_angle: Final[float]
    weld: Final[bool]
    contours: Final[str]
    suggestive_threshold: Final[float]
    curvature_smoothing: Final[Optional[float]]
    suggestive_coherence: Final[bool]
    min_crease_length: Final[float]
    max_crease_turn: Final[float]
    image_rule: Final[str]
    normal_angle: Final[float]
    depth_jump: Final[float]
    normal_threshold: Final[float]
    depth_threshold: Final[float]
    depth_offset: Final[float]
    visibility: Final[str]
    max_occlusion: Final[Optional[int]]
    taper: Final[float]
    width_by_depth: Final[bool]
    join_kinds: Final[bool]
    styles: Final[Dict[str, Optional[LineStyle]]]
    def replace(self, *, kind: Optional[Literal['mesh', 'image', 'both']] = ..., silhouette: Optional[Union[bool, LineStyle, _Color]] = ..., boundary: Optional[Union[bool, LineStyle, _Color]] = ..., nonmanifold: Optional[Union[bool, LineStyle, _Color]] = ..., ridge: Optional[Union[bool, LineStyle, _Color]] = ..., valley: Optional[Union[bool, LineStyle, _Color]] = ..., suggestive: Optional[Union[bool, LineStyle, _Color]] = ..., material: Optional[Union[bool, LineStyle, _Color]] = ..., intersection: Optional[Union[bool, LineStyle, _Color]] = ..., image: Optional[Union[bool, LineStyle, _Color]] = ..., hidden: Optional[Union[bool, LineStyle, _Color]] = ..., crease_angle: Optional[float] = ..., weld: Optional[bool] = ..., contours: Optional[Literal['faces', 'smooth', 'auto']] = ..., suggestive_threshold: Optional[float] = ..., curvature_smoothing: Optional[float] = ..., suggestive_coherence: Optional[bool] = ..., min_crease_length: Optional[float] = ..., max_crease_turn: Optional[float] = ..., image_rule: Optional[Literal['discontinuity', 'paper']] = ..., normal_angle: Optional[float] = ..., depth_jump: Optional[float] = ..., normal_threshold: Optional[float] = ..., depth_threshold: Optional[float] = ..., depth_offset: Optional[float] = ..., visibility: Optional[Literal['exact', 'depth']] = ..., max_occlusion: Optional[int] = ..., taper: Optional[float] = ..., width_by_depth: Optional[bool] = ..., join_kinds: Optional[bool] = ...) -> Outlines: ...

@final
class Material(_Settings):
    """A shading model with its coefficients; build one with the static methods. Colours are sRGB:
    ``'#rrggbb'`` or three numbers in [0, 1].

    Every model computes, in linear light, ``C = a_l * ambient + sum over lights of (f(L.n) *
    d_l * diffuse + s * S_l * specular)``, where ``a_l`` is the scene's ambient light, ``d_l =
    S_l`` a light's colour times its intensity, ``L`` the unit vector toward the light and ``n``
    the unit normal; the models differ in ``f`` and ``s``. With ``per_vertex=True`` the vertices
    are shaded and the colours interpolated (Gouraud, as Al-Rousan et al. colour vertices);
    otherwise every pixel is shaded.

    ``opacity`` (every constructor, default 1) is how much of what lies behind the surface it
    hides. Below 1 the mesh is glass: it is shaded as any mesh, then composited over what lies
    behind it, in depth order whatever the order of the meshes (depth peeling, exact up to
    ``RenderOptions.glass_layers`` glass surfaces a pixel; see the rendering guide's "Glass"). A
    mesh's colour alpha joins in with its ``alpha_blend`` keyword (glTF's alpha blend, MTL
    ``d``). Glass casts no shadow and receives none, and hides no ink: lines behind it show
    through it.

    Fields: model: the shading model (hatching is 'bands' with hatch strokes); diffuse: the
    diffuse coefficient d_m, sRGB; ambient: the ambient coefficient a_m, sRGB; specular: the
    highlight coefficient S_m, sRGB; per_vertex: shade the vertices and interpolate (Gouraud)
    instead of every pixel; opacity: how much of what lies behind it the surface hides: below 1
    it is glass, composited in depth order over what lies behind it; shininess: Phong's
    exponent, > 0; t_h: the thresholded Phong model's diffuse threshold on L.n; t_s: the
    thresholded Phong model's highlight threshold; highlight: the highlight term: 'blinn' (n .
    h) or 'paper' (L . v, as the paper writes it); thresholds: the bands' thresholds on L.n: 1
    to 8, strictly increasing; values: the bands' tones: one more than the thresholds, each >=
    0; table: a lookup table: (N,) grey or (N, 3) RGB factors, 1 <= N <= 256; ink: hatch
    strokes' sRGB colour; spacing: pixels between hatch strokes, 2 to 256; width: hatch strokes'
    width in pixels, up to the spacing; mode: how hatch strokes are laid: along the principal
    directions ('field') or straight on the axis planes ('triplanar'); dither: dithering between
    bands: None, a pattern name or a Dither (needs per-pixel shading); rim: a rim light along
    the silhouette: None or a Rim.
    """
    @staticmethod
    def lambert(color: Optional[_Color] = ..., *, ambient: Optional[_Color] = ..., diffuse: Optional[_Color] = ..., per_vertex: Optional[bool] = ..., opacity: Optional[float] = ..., rim: Optional[Rim] = ...) -> Material:
        """Plain Lambert: f = max(L.n, 0), no highlight.

        color: base colour (default (0.95, 0.55, 0.25)); the diffuse coefficient is 90% of it
        and ambient (default) 10%, in linear light. per_vertex: bool, default False.
        """
        ...
    @staticmethod
    def phong(color: Optional[_Color] = ..., *, specular: Optional[_Color] = ..., shininess: Optional[float] = ..., ambient: Optional[_Color] = ..., diffuse: Optional[_Color] = ..., per_vertex: Optional[bool] = ..., opacity: Optional[float] = ..., rim: Optional[Rim] = ...) -> Material:
        """Plain Phong: f = max(L.n, 0), s = max(R.v, 0)^shininess on lit points (R: L reflected).

        color as in :meth:`lambert`; specular: highlight colour (default (0.5, 0.5, 0.5));
        shininess: exponent > 0 (default 32).
        """
        ...
    @staticmethod
    def thresholded_phong(color: Optional[_Color] = ..., *, t_h: Optional[float] = ..., t_s: Optional[float] = ..., highlight: Optional[Literal['paper', 'blinn']] = ..., ambient: Optional[_Color] = ..., specular: Optional[_Color] = ..., diffuse: Optional[_Color] = ..., per_vertex: Optional[bool] = ..., opacity: Optional[float] = ..., dither: Optional[Union[str, Dither]] = ..., rim: Optional[Rim] = ...) -> Material:
        """Al-Rousan et al.'s toon model: C = a_l a_m + thresh(L.n, t_h) d_l d_m + thresh(h, t_s)
        S_l S_m.

        thresh(a, b) is 1 where a >= b, else 0; t_h (default 0.0) and t_s (default 0.95) lie in
        [-1, 1]. highlight: "blinn" (default, h = n . normalize(L + v)) or "paper" (h = L.v, as
        the paper writes it). By default the shadow side keeps 35% of ``color`` (ambient) and
        the lit side reaches it; specular defaults to (0.6, 0.6, 0.6). The paper shades
        vertices: pass ``per_vertex=True`` for that.
        """
        ...
    @staticmethod
    def bands(color: Optional[_Color] = ..., *, thresholds: Optional[Sequence[float]] = ..., preset: Optional[Literal['paper']] = ..., values: Optional[Sequence[float]] = ..., per_vertex: Optional[bool] = ..., opacity: Optional[float] = ..., dither: Optional[Union[str, Dither]] = ..., rim: Optional[Rim] = ...) -> Material:
        """Borquez and Yepez's toon bands: f = values[k], k = number of thresholds t with L.n >= t.

        Thresholds default to the paper's (0.2, 0.5, 0.7, 0.9). Values default to (0.3, 0.45,
        0.7, 0.9, 1): L.n >= 0.9 -> 1.0, 0.7-0.9 -> 0.9, 0.5-0.7 -> 0.7, 0.2-0.5 -> 0.45, below
        (and in shadow) -> 0.3, times ``color`` in linear light, so the darkest tone keeps the
        material's hue and black ink shows over it. ``preset="paper"`` takes the paper's values
        (0, 0.2, 0.7, 0.9, 1) instead: a black darkest band, as in its figures. 1 to 8 strictly
        increasing thresholds, and one value more (each >= 0). dither (here and on the other
        toon models): None (default), a pattern name or a :class:`Dither`; needs per-pixel
        shading.
        """
        ...
    @staticmethod
    def hatching(color: Optional[_Color] = ..., *, ink: Optional[_Color] = ..., thresholds: Optional[Sequence[float]] = ..., values: Optional[Sequence[float]] = ..., spacing: Optional[float] = ..., width: Optional[float] = ..., mode: Optional[Literal['field', 'triplanar']] = ..., per_vertex: Optional[bool] = ..., opacity: Optional[float] = ..., dither: Optional[Union[str, Dither]] = ..., rim: Optional[Rim] = ...) -> Material:
        """Cross-hatching (Borquez and Yepez): the bands' tone (their value times the light, as
        :meth:`bands` computes it) picks how many layers of ink strokes cover the paper: none
        where the tone is above 0.8, then one layer below 0.8, two below 0.6 (cross-hatching),
        three below 0.4 and four below 0.2. The strokes keep about ``spacing`` pixels between
        them (default 6, 2 to 256) and ``width`` pixels of width (default 1.25, up to
        ``spacing``) at any distance, are anchored to the surface (they move with it, not with
        the camera) and give the same bits for the same scene.

        mode: how the strokes are laid. ``"field"`` (default) follows the form (Hertzmann and
        Zorin; Praun et al.): the first layer runs along the direction of largest curvature
        (around a cylinder), the second along the other principal direction (along its axis),
        the third and fourth add strokes between those of the first two. The directions are
        smoothed over the surface and settle on a fixed axis where curvature has no direction
        (flats, spheres); the strokes come from a stripe pattern per vertex (Knöppel et al.),
        computed once per mesh on first use (about a second for 40,000 vertices on 2 cores) and
        kept with it; the mesh is cut at creases sharper than 30 degrees (or the mesh's
        ``normals="auto"`` angle), each side hatched on its own. ``"triplanar"``: the paper's
        straight strokes at 45, -45, 0 and 90 degrees in the mesh's own coordinates, blended
        over the three axis planes (no per-mesh work).

        color: the paper (default white); ink: the strokes (default (0.1, 0.1, 0.1));
        thresholds, values (default: the paper's, (0, 0.2, 0.7, 0.9, 1), so that the darkest
        tone gets every layer), dither and per_vertex as in :meth:`bands`.
        """
        ...
    @staticmethod
    def lut(table: Optional[Any] = ..., color: Optional[_Color] = ..., *, per_vertex: Optional[bool] = ..., opacity: Optional[float] = ..., dither: Optional[Union[str, Dither]] = ..., rim: Optional[Rim] = ...) -> Material:
        """A lookup table (gradient map): f = table[min(floor(clamp(L.n, 0, 1) N), N - 1)].

        table: (N,) grey factors or (N, 3) RGB factors (linear, >= 0, 1 <= N <= 256) applied to
        ``color``; the default is :func:`kang_table`, Kang et al.'s 256-to-3-level mapping.
        """
        ...
    model: Final[str]
    diffuse: Final[_Vec3]
    ambient: Final[_Vec3]
    specular: Final[_Vec3]
    per_vertex: Final[bool]
    opacity: Final[float]
    shininess: Final[Optional[float]]
    t_h: Final[Optional[float]]
    t_s: Final[Optional[float]]
    highlight: Final[Optional[str]]
    thresholds: Final[Optional[List[float]]]
    values: Final[Optional[List[float]]]
    table: Final[Optional[List[_Vec3]]]
    ink: Final[Optional[_Vec3]]
    spacing: Final[Optional[float]]
    width: Final[Optional[float]]
    mode: Final[Optional[str]]
    dither: Final[Optional[Dither]]
    rim: Final[Optional[Rim]]
    hatch_style: Final[Optional[Dict[str, Any]]]
    def replace(self, *, diffuse: Optional[_Color] = ..., ambient: Optional[_Color] = ..., specular: Optional[_Color] = ..., per_vertex: Optional[bool] = ..., opacity: Optional[float] = ..., shininess: Optional[float] = ..., t_h: Optional[float] = ..., t_s: Optional[float] = ..., highlight: Optional[Literal['paper', 'blinn']] = ..., thresholds: Optional[Sequence[float]] = ..., values: Optional[Sequence[float]] = ..., table: Optional[Any] = ..., ink: Optional[_Color] = ..., spacing: Optional[float] = ..., width: Optional[float] = ..., mode: Optional[Literal['field', 'triplanar']] = ..., dither: Optional[Union[str, Dither]] = ..., rim: Optional[Rim] = ...) -> Material: ...

@final
class Paper(_Settings):
    """Paper grain over the finished image: the paper's tooth takes pigment on its peaks and leaves
    its valleys light, as paper takes pencil or watercolour, on the tones, the hatching and the
    ink lines alike. With grain height g in [0, 1], the paper takes ``m = 1 - strength * (1 -
    g)`` of a pixel's pigment and shows its own tone ``1 - tone * (1 - g)`` in the rest (in
    linear light). grain: None (default: a built-in value-noise grain) or the user's image, an
    (H, W) or (H, W, C) array of 8-bit integers or of numbers in [0, 1] (its grey is the height;
    it tiles the plane). space: "screen" (default: fixed to the pixels) or "surface" (fixed to
    the scene's surfaces, mapped on the three axis planes of world coordinates; the background
    keeps the screen's grain). scale: output pixels a grain texel covers, 0.25 to 64 (default
    1.5; on the surface, at the scene's centre). strength: 0 to 1 (default 0.3). tone: 0 to 1
    (default 0.1). Give it to a render: ``render(..., paper=Paper())``.

    Fields: grain: the grain's heights: None (a built-in grain) or an image, (H, W) or (H, W,
    C), tiled; space: what the grain is fixed to: the 'screen' or the scene's 'surface'; scale:
    output pixels a grain texel covers, 0.25 to 64; strength: how much pigment the grain's
    valleys refuse, 0 to 1; tone: how much the blank paper's valleys darken it, 0 to 1.
    """
    def __new__(cls, grain: Optional[npt.ArrayLike] = ..., *, space: Optional[Literal['screen', 'surface']] = ..., scale: Optional[float] = ..., strength: Optional[float] = ..., tone: Optional[float] = ...) -> Paper: ...
    grain: Final[Optional[npt.NDArray[np.float32]]]
    space: Final[str]
    scale: Final[float]
    strength: Final[float]
    tone: Final[float]
    def replace(self, *, grain: Optional[npt.ArrayLike] = ..., space: Optional[Literal['screen', 'surface']] = ..., scale: Optional[float] = ..., strength: Optional[float] = ..., tone: Optional[float] = ...) -> Paper: ...

@final
class EyeDome(_Settings):
    """Eye-dome lighting (Boucheny's EDL, as CloudCompare and Potree draw point clouds): each pixel
    is darkened by how far its log-depth lies behind its neighbours', so depth steps (a point
    cloud's silhouettes and creases) show without normals. Over the surfaces after shading,
    before the ink; the background is left as it is. With d the log2 of a pixel's linear depth
    and d_k its eight neighbours' at ``radius`` pixels (those on the background left out), the
    pixel's colour is multiplied by ``exp(-300 * strength * sum(max(0, d - d_k)) / 8)`` in
    linear light. strength: 0 to 10 (default 1). radius: 0.5 to 16 output pixels (default 1.4).
    Give it to a render: ``render(..., eye_dome=EyeDome())``.

    Fields: strength: how strongly a pixel behind its neighbours darkens, 0 to 10; radius: how
    far its neighbours lie, 0.5 to 16 output pixels.
    """
    def __new__(cls, *, strength: Optional[float] = ..., radius: Optional[float] = ...) -> EyeDome: ...
    strength: Final[float]
    radius: Final[float]
    def replace(self, *, strength: Optional[float] = ..., radius: Optional[float] = ...) -> EyeDome: ...

@final
class RenderOptions(_Settings):
    """Every render setting besides the meshes, checked, with the core's defaults: made from the
    keywords of :class:`RenderKeywords` (``RenderOptions(width=640, outlines="mesh")``), which
    lists them; ``replace(**keywords)`` makes a changed copy. Compared by value, hashable and
    picklable, so a batch sends one to its workers.

    Fields: material: the material of meshes that name none; transform: a 4x4 affine model ->
    world matrix (row-major, applied to column vectors) for meshes that give none; camera: the
    camera (Camera.fit(): the scene framed from a three-quarter view about its up axis); up: the
    scene's up axis, which a fitted camera keeps up in the image and turns about (None: its
    meshes' own, as toonmesh.load reads a file's convention, else y); lights: a Light or a list
    of up to 8; ambient: the ambient light's sRGB colour; background: sRGB or sRGBA where no
    mesh is; width: the image's width in pixels, 1 to the device's limit; height: the image's
    height in pixels, 1 to the device's limit; outputs: the outputs computed and read back, and
    only those ('outline' and 'lines' need outlines, 'shadow' a light with shadows); msaa:
    samples per pixel: 1 or 4; supersample: render this many times larger in each direction and
    average down; pixel_ratio: output pixels per pixel of the widths, spacings and scales given
    in pixels: 2 with twice the width and height draws the same picture, sharper (a 2x screen);
    band_antialias: blend across each band border over about one pixel, from the screen-space
    change of the shading term: smooth tone borders at no extra samples (False: the papers' hard
    borders); glass_layers: the most glass surfaces (meshes with opacity below 1) one pixel
    composites, nearest first: each layer costs one more draw of the glass meshes and one full-
    screen pass; opaque scenes pay nothing; outlines: ink outlines: None, 'mesh', 'image',
    'both' or an Outlines; paper: paper grain over the image: None or a Paper; eye_dome: eye-
    dome lighting (surfaces darkened where they lie behind their neighbours, as point-cloud
    viewers draw): None or an EyeDome.
    """
    def __new__(cls, *, material: Optional[Material] = ..., transform: Optional[Any] = ..., camera: Optional[Camera] = ..., up: Optional[Literal['x', 'y', 'z']] = ..., lights: Optional[Union[Light, Sequence[Light]]] = ..., ambient: Optional[_Color] = ..., background: Optional[_Color] = ..., width: Optional[int] = ..., height: Optional[int] = ..., outputs: Optional[Union[str, Sequence[str]]] = ..., msaa: Optional[int] = ..., supersample: Optional[int] = ..., pixel_ratio: Optional[float] = ..., band_antialias: Optional[bool] = ..., glass_layers: Optional[int] = ..., outlines: Optional[Union[str, Outlines]] = ..., paper: Optional[Paper] = ..., eye_dome: Optional[EyeDome] = ...) -> RenderOptions: ...
    material: Final[Material]
    transform: Final[List[List[float]]]
    camera: Final[Camera]
    up: Final[Optional[str]]
    lights: Final[List[Light]]
    ambient: Final[_Vec3]
    background: Final[Tuple[float, float, float, float]]
    width: Final[int]
    height: Final[int]
    outputs: Final[List[str]]
    msaa: Final[int]
    supersample: Final[int]
    pixel_ratio: Final[float]
    band_antialias: Final[bool]
    glass_layers: Final[int]
    outlines: Final[Optional[Outlines]]
    paper: Final[Optional[Paper]]
    eye_dome: Final[Optional[EyeDome]]
    def replace(self, *, material: Optional[Material] = ..., transform: Optional[Any] = ..., camera: Optional[Camera] = ..., up: Optional[Literal['x', 'y', 'z']] = ..., lights: Optional[Union[Light, Sequence[Light]]] = ..., ambient: Optional[_Color] = ..., background: Optional[_Color] = ..., width: Optional[int] = ..., height: Optional[int] = ..., outputs: Optional[Union[str, Sequence[str]]] = ..., msaa: Optional[int] = ..., supersample: Optional[int] = ..., pixel_ratio: Optional[float] = ..., band_antialias: Optional[bool] = ..., glass_layers: Optional[int] = ..., outlines: Optional[Union[str, Outlines]] = ..., paper: Optional[Paper] = ..., eye_dome: Optional[EyeDome] = ...) -> RenderOptions: ...

def _restore(cls: str, state: str) -> Any: ...
def kang_table() -> npt.NDArray[np.float64]: ...


@final
class Renderer:
    def __new__(cls, backend: Optional[str] = ...) -> "Renderer": ...
    info: Final[Dict[str, Any]]
    mesh_count: Final[int]
    def add_mesh(
        self,
        vertices: Any,
        faces: Any,
        normals: Any,  # a mode, None or an (N, 3) float array
        **colors: Any,  # vertex_colors, face_colors, uv, texture, texture_filter, texture_wrap, alpha_cutoff, alpha_blend
    ) -> Tuple[int, Any, List[str]]: ...
    # a point cloud as splats: (N, 3) positions, normals, colours and radius or None, k or None
    def add_points(self, positions: Any, normals: Any, colors: Any, radius: Any, k: Optional[int]) -> int: ...
    def remove_mesh(self, mesh: int) -> bool: ...
    def render(
        self, items: Any, options: RenderOptions, *cameras: Any, lines: Optional[Any] = ...
    ) -> Tuple[Dict[str, Any], List[Dict[str, Any]]]: ...
    # the draft of a scene for a WebGL2 page: its JSON (render::draft) and the bytes it points into
    def _draft(self, items: Any, options: RenderOptions, lines: Optional[Any] = ...) -> Tuple[str, bytes]: ...

def gpu_info(backend: Optional[str] = ...) -> Dict[str, Any]: ...
def encode_png_rgba(color: Any) -> bytes: ...
def decode_png(data: bytes) -> npt.NDArray[np.uint8]: ...
def _srgb_from_linear(values: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]: ...
def _normal_mode(normals: Any, n_vertices: int) -> Any: ...
def _point_normals(positions: npt.ArrayLike, k: Optional[int]) -> npt.NDArray[np.floating[Any]]: ...
def _up_axis(up: Any) -> Optional[str]: ...
def _transform(transform: Any) -> npt.NDArray[np.float64]: ...
def _shadow_truth(
    mesh: _Mesh, view_proj: npt.NDArray[np.float64], shape: Tuple[int, int], toward_light: Any
) -> npt.NDArray[np.float32]: ...


# --- edges (toonmesh.edges wraps these) ---

_Pairs = npt.NDArray[np.int64]
_FeatureTuple = Tuple[
    _Pairs, _Pairs, npt.NDArray[np.float64], npt.NDArray[np.bool_], _Pairs, npt.NDArray[np.int64]
]
_Point = Optional[Any]  # three numbers, or None
_Polylines = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]  # flat points, line starts

# Scalars are checked in the core (src/py/args.rs), which names the argument in errors.
def _feature_edges(mesh: _Mesh, crease_angle: float, weld: bool) -> _FeatureTuple: ...
@overload
def _view_lines(
    what: Literal["silhouette"], mesh: _Mesh, eye: _Point, direction: _Point, weld: bool
) -> _Pairs: ...
@overload
def _view_lines(
    what: Literal["contours", "suggestive"],
    mesh: _Mesh,
    eye: _Point,
    direction: _Point,
    weld: bool,
    threshold: Optional[float] = None,
    smoothing: Optional[float] = None,
) -> _Polylines: ...
def _chains(edges: Any) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]: ...
def _intersections(meshes: Sequence[_Mesh], self_intersections: bool, brute_force: bool) -> npt.NDArray[np.float64]: ...
def _intersection_lines(meshes: Sequence[_Mesh], self_intersections: bool) -> _Polylines: ...
def _curvature(mesh: _Mesh, smoothing: float) -> Tuple[
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
]: ...
def _vertex_count(vertices: Any) -> int: ...
def _pen_strokes(
    lines: List[Any], widths: List[Optional[Any]], smooth: float, simplify: float
) -> List[Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]]: ...
def _plotter_order(starts: Any, ends: Any) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.bool_]]: ...
def _svg_document(width: int, height: int, groups: List[Tuple[Any, ...]]) -> str: ...
def _sobel(image: Any, output: str, convention: str) -> Any: ...
def _paper_edges(name: str, buffer: Any, threshold: float) -> Tuple[Any, npt.NDArray[np.bool_]]: ...

@final
class _EdgeIndex:
    def __new__(cls, mesh: _Mesh, weld: bool) -> _EdgeIndex: ...
    @overload
    def view_lines(self, what: Literal["silhouette"], eye: _Point, direction: _Point) -> _Pairs: ...
    @overload
    def view_lines(
        self,
        what: Literal["contours", "suggestive"],
        eye: _Point,
        direction: _Point,
        threshold: Optional[float] = None,
        smoothing: Optional[float] = None,
    ) -> _Polylines: ...
    def outlines(
        self, crease_angle: float, eye: _Point, direction: _Point, kinds: bool
    ) -> Tuple[_Pairs, Optional[npt.NDArray[np.int8]]]: ...
    def feature_edges(self, crease_angle: float) -> _FeatureTuple: ...
    def face_normals(self) -> npt.NDArray[np.float64]: ...
    def vertices(self) -> npt.NDArray[np.float64]: ...
    sizes: Final[Tuple[int, int, int]]
