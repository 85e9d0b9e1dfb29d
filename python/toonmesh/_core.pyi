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
    "LINE_KINDS",
    "MODELS",
    "OUTLINE_KINDS",
    "CONTOUR_RULES",
    "IMAGE_RULES",
    "OUTPUTS",
    "SHADOW_FILTERS",
    "HATCH_MODES",
    "BACKENDS",
    "SMOOTH_METHODS",
    "SMOOTH_WEIGHTS",
    "SMOOTH_BOUNDARIES",
    "SMOOTH_PRESETS",
    "DEFAULT_CREASE_ANGLE",
    "Camera",
    "ConvergenceError",
    "Dither",
    "GpuError",
    "GpuUnavailableError",
    "Light",
    "LineStyle",
    "Material",
    "Outlines",
    "RenderOptions",
    "Renderer",
    "Shadows",
    "_EdgeIndex",
    "__version__",
    "_chains",
    "_curvature",
    "_feature_edges",
    "_normal_mode",
    "_paper_edges",
    "_pen_strokes",
    "_plotter_order",
    "_restore",
    "_RenderKeywords",
    "_shadow_truth",
    "_srgb_from_linear",
    "_transform",
    "_smooth",
    "_sobel",
    "_svg_document",
    "_vertex_count",
    "_view_lines",
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
SMOOTH_METHODS: Tuple[str, ...]
SMOOTH_WEIGHTS: Tuple[str, ...]
SMOOTH_BOUNDARIES: Tuple[str, ...]
SMOOTH_PRESETS: Tuple[str, ...]
DEFAULT_CREASE_ANGLE: float

class ConvergenceError(RuntimeError): ...
class GpuUnavailableError(RuntimeError): ...
class GpuError(RuntimeError): ...

def set_num_threads(n: int) -> None: ...
def get_num_threads() -> int: ...
def icosphere(subdivisions: int, noise: float, seed: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def grid(n: int, noise: float, seed: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
# the keywords of toonmesh.smooth's functions (their signatures are the documentation)
def _smooth(method_name: str, vertices: Any, faces_arr: Any, **options: Any) -> npt.NDArray[np.floating[Any]]: ...

# --- rendering (src/py/scene.rs, src/py/render.rs); the public API is toonmesh._render ---

_Color = Any  # '#rrggbb' or 3 numbers in [0, 1]
_Vec3 = Tuple[float, float, float]


class _RenderKeywords(TypedDict, total=False):
    """The keywords of RenderOptions (None: the core's default)."""
    material: Optional[Material]
    transform: Optional[Any]
    camera: Optional[Camera]
    lights: Optional[Union[Light, Sequence[Light]]]
    ambient: Optional[_Color]
    background: Optional[_Color]
    width: Optional[int]
    height: Optional[int]
    outputs: Optional[Union[str, Sequence[str]]]
    msaa: Optional[int]
    supersample: Optional[int]
    band_antialias: Optional[bool]
    outlines: Optional[Union[str, Outlines]]

class _Settings:
    @staticmethod
    def describe() -> Dict[str, Any]: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

@final
class Dither(_Settings):
    """Dithering between neighbouring bands of a toon material. Fields: pattern: the threshold
    pattern; space: what the pattern is fixed to: the screen's pixels or the surface; amount:
    how far in L.n a pixel may move toward the neighbouring band, 0 to 2; scale: pixels a
    pattern cell covers, 1 to 64.
    """
    def __new__(cls, pattern: Optional[Literal['bayer2', 'bayer4', 'bayer8', 'blue']] = ..., *, space: Optional[Literal['screen', 'object']] = ..., amount: Optional[float] = ..., scale: Optional[float] = ...) -> Dither: ...
    pattern: Final[str]
    space: Final[str]
    amount: Final[float]
    scale: Final[float]
    def replace(self, *, pattern: Optional[Literal['bayer2', 'bayer4', 'bayer8', 'blue']] = ..., space: Optional[Literal['screen', 'object']] = ..., amount: Optional[float] = ..., scale: Optional[float] = ...) -> Dither: ...

@final
class Shadows(_Settings):
    """Shadow settings of a directional light. Fields: size: the shadow map's side in texels, a
    power of two; bias: depth bias in texels per unit of receiver slope, >= 0; filter: how the
    map is read: 'pcf' (soft edges) or 'none'; strength: the share of the light a shadow takes
    away: 1 a full shadow, 0.5 a half-tone one.
    """
    def __new__(cls, size: Optional[int] = ..., bias: Optional[float] = ..., filter: Optional[Literal['none', 'pcf']] = ..., *, strength: Optional[float] = ...) -> Shadows: ...
    size: Final[int]
    bias: Final[float]
    filter: Final[str]
    strength: Final[float]
    def replace(self, *, size: Optional[int] = ..., bias: Optional[float] = ..., filter: Optional[Literal['none', 'pcf']] = ..., strength: Optional[float] = ...) -> Shadows: ...

@final
class Light(_Settings):
    """A light: directional or point, in world or camera space. Fields: kind: directional (sun-
    like) or point; direction: a directional light's direction, from the light toward the scene;
    position: a point light's position; color: sRGB colour; intensity: factor on the colour, >=
    0; space: 'world', or 'camera': fixed to the view (x right, y up, -z forward); shadows: a
    directional light's shadows: True (the default Shadows), False or None (none), or a Shadows.
    """
    @staticmethod
    def directional(direction: Sequence[float], *, color: Optional[_Color] = ..., intensity: Optional[float] = ..., space: Optional[Literal['world', 'camera']] = ..., shadows: Optional[Union[bool, Shadows]] = ...) -> Light:
        """Parallel light travelling along `direction`."""
        ...
    @staticmethod
    def point(position: Sequence[float], *, color: Optional[_Color] = ..., intensity: Optional[float] = ..., space: Optional[Literal['world', 'camera']] = ...) -> Light:
        """Light radiating from `position`, without falloff."""
        ...
    @staticmethod
    def key() -> Light:
        """The default key light: from the upper left, behind the viewer, moving with the camera."""
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
    """A camera: framed to fit the scene, looking at a point, or orthographic. Fields: kind: framed
    to fit the scene, or looking at a point; projection: the projection; eye: a look-at camera's
    position; target: the point a look-at camera looks at; up: the direction that is up in the
    image; direction: a fitted camera's direction from the scene toward the eye (the scene is
    framed to fit); margin: a fitted camera's room around the scene (1: touching); fov_y:
    vertical field of view in degrees, in (0, 180); height: height of an orthographic view in
    world units, > 0; near: near clip distance (None: from the scene's bounds); far: far clip
    distance (None: from the scene's bounds).
    """
    @staticmethod
    def fit(direction: Optional[Sequence[float]] = ..., *, up: Optional[Sequence[float]] = ..., fov_y: Optional[float] = ..., margin: Optional[float] = ..., orthographic: Optional[bool] = ...) -> Camera:
        """Frames the scene's bounding sphere from `direction`."""
        ...
    @staticmethod
    def look_at(eye: Sequence[float], target: Optional[Sequence[float]] = ..., *, up: Optional[Sequence[float]] = ..., fov_y: Optional[float] = ..., near: Optional[float] = ..., far: Optional[float] = ...) -> Camera:
        """A perspective camera at `eye` looking at `target`."""
        ...
    @staticmethod
    def orthographic(eye: Sequence[float], target: Optional[Sequence[float]] = ..., *, up: Optional[Sequence[float]] = ..., height: Optional[float] = ..., near: Optional[float] = ..., far: Optional[float] = ...) -> Camera:
        """An orthographic camera at `eye` looking at `target`."""
        ...
    kind: Final[str]
    projection: Final[str]
    eye: Final[Optional[_Vec3]]
    target: Final[Optional[_Vec3]]
    up: Final[_Vec3]
    direction: Final[Optional[_Vec3]]
    margin: Final[Optional[float]]
    fov_y: Final[Optional[float]]
    height: Final[Optional[float]]
    near: Final[Optional[float]]
    far: Final[Optional[float]]
    def replace(self, *, eye: Optional[Sequence[float]] = ..., target: Optional[Sequence[float]] = ..., up: Optional[Sequence[float]] = ..., direction: Optional[Sequence[float]] = ..., margin: Optional[float] = ..., fov_y: Optional[float] = ..., height: Optional[float] = ..., near: Optional[float] = ..., far: Optional[float] = ...) -> Camera: ...

@final
class LineStyle(_Settings):
    """How one kind of ink line is drawn. Fields: color: the ink's sRGB colour; width: width in
    output pixels, the same at every resolution and supersampling factor.
    """
    def __new__(cls, color: Optional[_Color] = ..., width: Optional[float] = ...) -> LineStyle: ...
    color: Final[_Vec3]
    width: Final[float]
    def replace(self, *, color: Optional[_Color] = ..., width: Optional[float] = ...) -> LineStyle: ...

@final
class Outlines(_Settings):
    """Ink outlines for a render: lines found on the mesh and edges found in the image. Fields:
    kind: lines found on the mesh, edges found in the image, or both; silhouette: True (the
    common style), False (not drawn), a LineStyle or a colour; boundary: True (the common
    style), False (not drawn), a LineStyle or a colour; nonmanifold: True (the common style),
    False (not drawn), a LineStyle or a colour; ridge: True (the common style), False (not
    drawn), a LineStyle or a colour; valley: True (the common style), False (not drawn), a
    LineStyle or a colour; suggestive: suggestive contours (DeCarlo et al.): drawn only when
    asked for; material: borders between scene items that meet edge to edge; image: image-space
    edges; crease_angle: dihedral angle in degrees above which an edge is a crease; weld: merge
    vertices at equal positions first, so seams are not drawn as boundaries; contours: how
    silhouettes are found: 'faces', 'smooth' or 'auto'; suggestive_threshold: the suggestive
    contours' derivative test, relative to the mesh's feature size; curvature_smoothing: width
    in mean edge lengths over which suggestive contours' curvature is averaged (None: 2, at most
    1% of the diagonal); min_crease_length: crease pieces shorter than this fraction of the
    bounding-box diagonal are not drawn; max_crease_turn: crease pieces turning by more than
    this many degrees on average are not drawn (180: all); image_rule: how image-space edges are
    found; normal_angle: degrees of normal turn between pixels drawn as an edge; depth_jump:
    depth jump between pixels drawn as an edge, in pixel footprints; normal_threshold: the paper
    rule's Sobel threshold on normals; depth_threshold: the paper rule's Sobel threshold on
    depth; depth_offset: hidden-line removal's tolerance in pixel footprints; taper: pixels over
    which lines thin toward their ends (0: none); width_by_depth: scale line widths by the scene
    centre's depth over the line's; join_kinds: join strokes of different kinds that meet end to
    end.
    """
    def __new__(cls, kind: Optional[Literal['mesh', 'image', 'both']] = ..., *, color: Optional[_Color] = ..., width: Optional[float] = ..., silhouette: Optional[Union[bool, LineStyle, _Color]] = ..., boundary: Optional[Union[bool, LineStyle, _Color]] = ..., crease: Optional[Union[bool, LineStyle, _Color]] = ..., ridge: Optional[Union[bool, LineStyle, _Color]] = ..., valley: Optional[Union[bool, LineStyle, _Color]] = ..., nonmanifold: Optional[Union[bool, LineStyle, _Color]] = ..., suggestive: Optional[Union[bool, LineStyle, _Color]] = ..., material: Optional[Union[bool, LineStyle, _Color]] = ..., image: Optional[Union[bool, LineStyle, _Color]] = ..., crease_angle: Optional[float] = ..., weld: Optional[bool] = ..., normal_threshold: Optional[float] = ..., depth_threshold: Optional[float] = ..., depth_offset: Optional[float] = ..., contours: Optional[Literal['faces', 'smooth', 'auto']] = ..., suggestive_threshold: Optional[float] = ..., curvature_smoothing: Optional[float] = ..., min_crease_length: Optional[float] = ..., max_crease_turn: Optional[float] = ..., image_rule: Optional[Literal['discontinuity', 'paper']] = ..., normal_angle: Optional[float] = ..., depth_jump: Optional[float] = ..., taper: Optional[float] = ..., width_by_depth: Optional[bool] = ..., join_kinds: Optional[bool] = ...) -> Outlines: ...
    kind: Final[str]
    silhouette: Final[Optional[Union[LineStyle, bool]]]
    boundary: Final[Optional[Union[LineStyle, bool]]]
    nonmanifold: Final[Optional[Union[LineStyle, bool]]]
    ridge: Final[Optional[Union[LineStyle, bool]]]
    valley: Final[Optional[Union[LineStyle, bool]]]
    suggestive: Final[Optional[Union[LineStyle, bool]]]
    material: Final[Optional[Union[LineStyle, bool]]]
    image: Final[Optional[Union[LineStyle, bool]]]
    crease_angle: Final[float]
    weld: Final[bool]
    contours: Final[str]
    suggestive_threshold: Final[float]
    curvature_smoothing: Final[Optional[float]]
    min_crease_length: Final[float]
    max_crease_turn: Final[float]
    image_rule: Final[str]
    normal_angle: Final[float]
    depth_jump: Final[float]
    normal_threshold: Final[float]
    depth_threshold: Final[float]
    depth_offset: Final[float]
    taper: Final[float]
    width_by_depth: Final[bool]
    join_kinds: Final[bool]
    styles: Final[Dict[str, Optional[LineStyle]]]
    def replace(self, *, kind: Optional[Literal['mesh', 'image', 'both']] = ..., silhouette: Optional[Union[bool, LineStyle, _Color]] = ..., boundary: Optional[Union[bool, LineStyle, _Color]] = ..., nonmanifold: Optional[Union[bool, LineStyle, _Color]] = ..., ridge: Optional[Union[bool, LineStyle, _Color]] = ..., valley: Optional[Union[bool, LineStyle, _Color]] = ..., suggestive: Optional[Union[bool, LineStyle, _Color]] = ..., material: Optional[Union[bool, LineStyle, _Color]] = ..., image: Optional[Union[bool, LineStyle, _Color]] = ..., crease_angle: Optional[float] = ..., weld: Optional[bool] = ..., contours: Optional[Literal['faces', 'smooth', 'auto']] = ..., suggestive_threshold: Optional[float] = ..., curvature_smoothing: Optional[float] = ..., min_crease_length: Optional[float] = ..., max_crease_turn: Optional[float] = ..., image_rule: Optional[Literal['discontinuity', 'paper']] = ..., normal_angle: Optional[float] = ..., depth_jump: Optional[float] = ..., normal_threshold: Optional[float] = ..., depth_threshold: Optional[float] = ..., depth_offset: Optional[float] = ..., taper: Optional[float] = ..., width_by_depth: Optional[bool] = ..., join_kinds: Optional[bool] = ...) -> Outlines: ...

@final
class Material(_Settings):
    """A shading model with its colour coefficients and per-pixel effects. Fields: model: the
    shading model (hatching is 'bands' with hatch strokes); diffuse: the diffuse coefficient
    d_m, sRGB; ambient: the ambient coefficient a_m, sRGB; specular: the highlight coefficient
    S_m, sRGB; per_vertex: shade the vertices and interpolate (Gouraud) instead of every pixel;
    shininess: Phong's exponent, > 0; t_h: the thresholded Phong model's diffuse threshold on
    L.n; t_s: the thresholded Phong model's highlight threshold; highlight: the highlight term:
    'blinn' (n . h) or 'paper' (L . v, as the paper writes it); thresholds: the bands'
    thresholds on L.n: 1 to 8, strictly increasing; values: the bands' tones: one more than the
    thresholds, each >= 0; table: a lookup table: (N,) grey or (N, 3) RGB factors, 1 <= N <=
    256; ink: hatch strokes' sRGB colour; spacing: pixels between hatch strokes, 2 to 256;
    width: hatch strokes' width in pixels, up to the spacing; mode: how hatch strokes are laid:
    along the principal directions ('field') or straight on the axis planes ('triplanar');
    dither: dithering between bands: None, a pattern name or a Dither (needs per-pixel shading).
    """
    @staticmethod
    def lambert(color: Optional[_Color] = ..., *, ambient: Optional[_Color] = ..., diffuse: Optional[_Color] = ..., per_vertex: Optional[bool] = ...) -> Material:
        """Plain Lambert: f = max(L.n, 0), no highlight."""
        ...
    @staticmethod
    def phong(color: Optional[_Color] = ..., *, specular: Optional[_Color] = ..., shininess: Optional[float] = ..., ambient: Optional[_Color] = ..., diffuse: Optional[_Color] = ..., per_vertex: Optional[bool] = ...) -> Material:
        """Plain Phong: f = max(L.n, 0), s = max(R.v, 0)^shininess on lit points."""
        ...
    @staticmethod
    def thresholded_phong(color: Optional[_Color] = ..., *, t_h: Optional[float] = ..., t_s: Optional[float] = ..., highlight: Optional[Literal['paper', 'blinn']] = ..., ambient: Optional[_Color] = ..., specular: Optional[_Color] = ..., diffuse: Optional[_Color] = ..., per_vertex: Optional[bool] = ..., dither: Optional[Union[str, Dither]] = ...) -> Material:
        """Al-Rousan et al.'s toon model: thresholded diffuse and highlight terms."""
        ...
    @staticmethod
    def bands(color: Optional[_Color] = ..., *, thresholds: Optional[Sequence[float]] = ..., preset: Optional[Literal['paper']] = ..., values: Optional[Sequence[float]] = ..., per_vertex: Optional[bool] = ..., dither: Optional[Union[str, Dither]] = ...) -> Material:
        """Borquez and Yepez's toon bands: f = values[number of thresholds <= L.n]."""
        ...
    @staticmethod
    def hatching(color: Optional[_Color] = ..., *, ink: Optional[_Color] = ..., thresholds: Optional[Sequence[float]] = ..., values: Optional[Sequence[float]] = ..., spacing: Optional[float] = ..., width: Optional[float] = ..., mode: Optional[Literal['field', 'triplanar']] = ..., per_vertex: Optional[bool] = ..., dither: Optional[Union[str, Dither]] = ...) -> Material:
        """Cross-hatching: the bands' tone picks how many layers of ink strokes cover the paper."""
        ...
    @staticmethod
    def lut(table: Optional[Any] = ..., color: Optional[_Color] = ..., *, per_vertex: Optional[bool] = ..., dither: Optional[Union[str, Dither]] = ...) -> Material:
        """A lookup table (gradient map) of L.n applied to the colour."""
        ...
    model: Final[str]
    diffuse: Final[_Vec3]
    ambient: Final[_Vec3]
    specular: Final[_Vec3]
    per_vertex: Final[bool]
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
    hatch_style: Final[Optional[Dict[str, Any]]]
    def replace(self, *, diffuse: Optional[_Color] = ..., ambient: Optional[_Color] = ..., specular: Optional[_Color] = ..., per_vertex: Optional[bool] = ..., shininess: Optional[float] = ..., t_h: Optional[float] = ..., t_s: Optional[float] = ..., highlight: Optional[Literal['paper', 'blinn']] = ..., thresholds: Optional[Sequence[float]] = ..., values: Optional[Sequence[float]] = ..., table: Optional[Any] = ..., ink: Optional[_Color] = ..., spacing: Optional[float] = ..., width: Optional[float] = ..., mode: Optional[Literal['field', 'triplanar']] = ..., dither: Optional[Union[str, Dither]] = ...) -> Material: ...

@final
class RenderOptions(_Settings):
    """Every render setting besides the meshes, checked, with the core's defaults. Fields:
    material: the material of meshes that name none; transform: a 4x4 affine model -> world
    matrix (row-major, applied to column vectors) for meshes that give none; camera: the camera
    (Camera.fit(): the scene framed from the front); lights: a Light or a list of up to 8;
    ambient: the ambient light's sRGB colour; background: sRGB or sRGBA where no mesh is; width:
    the image's width in pixels, 1 to the device's limit; height: the image's height in pixels,
    1 to the device's limit; outputs: the outputs computed and read back, and only those
    ('outline' and 'lines' need outlines, 'shadow' a light with shadows); msaa: samples per
    pixel: 1 or 4; supersample: render this many times larger in each direction and average
    down; band_antialias: blend across each band border over about one pixel, from the screen-
    space change of the shading term: smooth tone borders at no extra samples (False: the
    papers' hard borders); outlines: ink outlines: None, 'mesh', 'image', 'both' or an Outlines.
    """
    def __new__(cls, *, material: Optional[Material] = ..., transform: Optional[Any] = ..., camera: Optional[Camera] = ..., lights: Optional[Union[Light, Sequence[Light]]] = ..., ambient: Optional[_Color] = ..., background: Optional[_Color] = ..., width: Optional[int] = ..., height: Optional[int] = ..., outputs: Optional[Union[str, Sequence[str]]] = ..., msaa: Optional[int] = ..., supersample: Optional[int] = ..., band_antialias: Optional[bool] = ..., outlines: Optional[Union[str, Outlines]] = ...) -> RenderOptions: ...
    material: Final[Material]
    transform: Final[List[List[float]]]
    camera: Final[Camera]
    lights: Final[List[Light]]
    ambient: Final[_Vec3]
    background: Final[Tuple[float, float, float, float]]
    width: Final[int]
    height: Final[int]
    outputs: Final[List[str]]
    msaa: Final[int]
    supersample: Final[int]
    band_antialias: Final[bool]
    outlines: Final[Optional[Outlines]]
    def replace(self, *, material: Optional[Material] = ..., transform: Optional[Any] = ..., camera: Optional[Camera] = ..., lights: Optional[Union[Light, Sequence[Light]]] = ..., ambient: Optional[_Color] = ..., background: Optional[_Color] = ..., width: Optional[int] = ..., height: Optional[int] = ..., outputs: Optional[Union[str, Sequence[str]]] = ..., msaa: Optional[int] = ..., supersample: Optional[int] = ..., band_antialias: Optional[bool] = ..., outlines: Optional[Union[str, Outlines]] = ...) -> RenderOptions: ...

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
        normals: Union[str, Tuple[str, float]],
        **colors: Any,  # vertex_colors, face_colors, uv, texture, texture_filter, texture_wrap, alpha_cutoff
    ) -> Tuple[int, Union[str, Tuple[str, float]], List[str]]: ...
    def remove_mesh(self, mesh: int) -> bool: ...
    def render(self, items: Any, options: RenderOptions) -> Dict[str, Any]: ...
    def render_views(
        self, items: Any, cameras: Any, options: RenderOptions
    ) -> Tuple[Dict[str, Any], List[Dict[str, Any]]]: ...

def gpu_info(backend: Optional[str] = ...) -> Dict[str, Any]: ...
def encode_png_rgba(color: Any) -> bytes: ...
def _srgb_from_linear(values: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]: ...
def _normal_mode(normals: Any) -> Union[str, Tuple[str, float]]: ...
def _transform(transform: Any) -> npt.NDArray[np.float64]: ...
def _shadow_truth(
    vertices: Any, faces_arr: Any, view_proj: npt.NDArray[np.float64], width: int, height: int, toward_light: Any
) -> npt.NDArray[np.float32]: ...


# --- edges (toonmesh.edges wraps these) ---

_Pairs = npt.NDArray[np.int64]
_FeatureTuple = Tuple[
    _Pairs, _Pairs, npt.NDArray[np.float64], npt.NDArray[np.bool_], _Pairs, npt.NDArray[np.int64]
]
_Point = Optional[Any]  # three numbers, or None
_Polylines = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]  # flat points, line starts

# Scalars are checked in the core (src/py/args.rs), which names the argument in errors.
def _feature_edges(vertices: Any, faces: Any, crease_angle: float, weld: bool) -> _FeatureTuple: ...
@overload
def _view_lines(
    what: Literal["silhouette"], vertices: Any, faces: Any, eye: _Point, direction: _Point, weld: bool
) -> _Pairs: ...
@overload
def _view_lines(
    what: Literal["contours", "suggestive"],
    vertices: Any,
    faces: Any,
    eye: _Point,
    direction: _Point,
    weld: bool,
    threshold: Optional[float] = None,
    smoothing: Optional[float] = None,
) -> _Polylines: ...
def _chains(edges: Any) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]: ...
def _curvature(vertices: Any, faces: Any, smoothing: float) -> Tuple[
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
    def __new__(cls, vertices: Any, faces: Any, weld: bool) -> _EdgeIndex: ...
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
    def weld_map(self) -> Optional[npt.NDArray[np.int64]]: ...
    n_vertices: Final[int]
    n_faces: Final[int]
    n_edges: Final[int]
