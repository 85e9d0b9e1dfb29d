# Type stubs for the compiled core (checked against it with `python -m mypy.stubtest toonmesh._core`).
from typing import Any, Dict, Final, List, Literal, Optional, Tuple, Union, final

from typing_extensions import Unpack

from toonmesh._render import RenderKeywords

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
    "_contours",
    "_curvature",
    "_denoise",
    "_feature_edges",
    "_normal_mode",
    "_paper_edges",
    "_pen_strokes",
    "_plotter_order",
    "_restore",
    "_segments",
    "_shadow_truth",
    "_srgb_from_linear",
    "_suggestive_contours",
    "_transform",
    "_silhouette",
    "_smooth",
    "_sobel",
    "_svg_document",
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

class ConvergenceError(RuntimeError): ...
class GpuUnavailableError(RuntimeError): ...
class GpuError(RuntimeError): ...

def set_num_threads(n: int) -> None: ...
def get_num_threads() -> int: ...
def icosphere(subdivisions: int, noise: float, seed: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def grid(n: int, noise: float, seed: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def _smooth(
    method_name: str,
    vertices: Any,
    faces_arr: Any,
    *,
    iterations: Optional[int] = None,
    lamb: Optional[float] = None,
    mu: Optional[float] = None,
    alpha: Optional[float] = None,
    beta: Optional[float] = None,
    step: Optional[float] = None,
    tol: Optional[float] = None,
    max_iter: Optional[int] = None,
    weights: Optional[str] = None,
    boundary: Optional[str] = None,
    pinned: Optional[Any] = None,
    volume_constraint: Optional[bool] = None,
    preset: Optional[str] = None,
    weld: bool,
) -> npt.NDArray[np.floating[Any]]: ...
def _denoise(
    method_name: str,
    vertices: Any,
    faces_arr: Any,
    *,
    iterations: Optional[int] = None,
    vertex_iterations: Optional[int] = None,
    sigma_s: Optional[float] = None,
    sigma_r: Optional[float] = None,
    pinned: Optional[Any] = None,
    weld: bool,
) -> npt.NDArray[np.floating[Any]]: ...

# --- rendering (src/py/scene.rs, src/py/render.rs); the public API is toonmesh._render ---

_Color = Any  # '#rrggbb' or 3 numbers in [0, 1]
_Vec3 = Tuple[float, float, float]

@final
class Dither:
    """Dithering between neighbouring bands: pattern "bayer2", "bayer4" (default), "bayer8" or
    "blue"; space "screen" (default) or "object"; amount in L.n, 0 to 2 (default 0.15); scale:
    pixels a cell covers, 1 to 64 (default 1)."""

    def __new__(
        cls,
        pattern: Optional[str] = ...,
        *,
        space: Optional[str] = ...,
        amount: Optional[float] = ...,
        scale: Optional[float] = ...,
    ) -> Dither: ...
    pattern: Final[str]
    space: Final[str]
    amount: Final[float]
    scale: Final[float]
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

_DitherArg = Union[None, str, Dither]

@final
class Material:
    @staticmethod
    def lambert(color: Optional[_Color] = ..., *, ambient: Optional[_Color] = ..., per_vertex: Optional[bool] = ...) -> Material: ...
    @staticmethod
    def phong(
        color: Optional[_Color] = ...,
        *,
        specular: Optional[_Color] = ...,
        shininess: Optional[float] = ...,
        ambient: Optional[_Color] = ...,
        per_vertex: Optional[bool] = ...,
    ) -> Material: ...
    @staticmethod
    def thresholded_phong(
        color: Optional[_Color] = ...,
        *,
        t_h: Optional[float] = ...,
        t_s: Optional[float] = ...,
        highlight: Optional[str] = ...,
        ambient: Optional[_Color] = ...,
        specular: Optional[_Color] = ...,
        per_vertex: Optional[bool] = ...,
        dither: _DitherArg = ...,
    ) -> Material: ...
    @staticmethod
    def bands(
        color: Optional[_Color] = ...,
        *,
        thresholds: Optional[Any] = ...,
        values: Optional[Any] = ...,
        preset: Optional[Literal["paper"]] = ...,
        per_vertex: Optional[bool] = ...,
        dither: _DitherArg = ...,
    ) -> Material: ...
    @staticmethod
    def hatching(
        color: Optional[_Color] = ...,
        *,
        ink: Optional[_Color] = ...,
        thresholds: Optional[Any] = ...,
        values: Optional[Any] = ...,
        spacing: Optional[float] = ...,
        width: Optional[float] = ...,
        mode: Optional[Literal["field", "triplanar"]] = ...,
        per_vertex: Optional[bool] = ...,
        dither: _DitherArg = ...,
    ) -> Material: ...
    @staticmethod
    def lut(
        table: Optional[Any] = ..., color: Optional[_Color] = ..., *, per_vertex: Optional[bool] = ..., dither: _DitherArg = ...
    ) -> Material: ...
    model: Final[str]
    hatch_style: Final[Optional[Dict[str, Any]]]
    dither: Final[Optional[Dither]]
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
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

@final
class Shadows:
    """Shadow settings of a directional light: the shadow map's side in texels (a power of two
    from 64 to 8192, default 2048), the depth bias in texels per unit of receiver slope (>= 0,
    default 1.0) and the filter, "pcf" (default) or "none"."""

    def __new__(
        cls, size: Optional[int] = ..., bias: Optional[float] = ..., filter: Optional[str] = ...
    ) -> Shadows: ...
    size: Final[int]
    bias: Final[float]
    filter: Final[str]
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

@final
class Light:
    @staticmethod
    def directional(
        direction: Any,
        *,
        color: Optional[_Color] = ...,
        intensity: Optional[float] = ...,
        space: Optional[str] = ...,
        shadows: Union[None, bool, Shadows] = ...,
    ) -> Light: ...
    @staticmethod
    def point(
        position: Any, *, color: Optional[_Color] = ..., intensity: Optional[float] = ..., space: Optional[str] = ...
    ) -> Light: ...
    @staticmethod
    def key() -> Light: ...
    kind: Final[str]
    direction: Final[Optional[_Vec3]]
    position: Final[Optional[_Vec3]]
    color: Final[_Vec3]
    intensity: Final[float]
    space: Final[str]
    shadows: Final[Optional[Shadows]]
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

@final
class Camera:
    @staticmethod
    def fit(
        direction: Optional[Any] = ...,
        *,
        up: Optional[Any] = ...,
        fov_y: Optional[float] = ...,
        margin: Optional[float] = ...,
        orthographic: Optional[bool] = ...,
    ) -> Camera: ...
    @staticmethod
    def look_at(
        eye: Any,
        target: Optional[Any] = ...,
        *,
        up: Optional[Any] = ...,
        fov_y: Optional[float] = ...,
        near: Optional[float] = ...,
        far: Optional[float] = ...,
    ) -> Camera: ...
    @staticmethod
    def orthographic(
        eye: Any,
        target: Optional[Any] = ...,
        *,
        up: Optional[Any] = ...,
        height: Optional[float] = ...,
        near: Optional[float] = ...,
        far: Optional[float] = ...,
    ) -> Camera: ...
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
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

@final
class LineStyle:
    def __new__(cls, color: Optional[_Color] = ..., width: Optional[float] = ...) -> LineStyle: ...
    color: Final[_Vec3]
    width: Final[float]
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

_Style = Any  # None, True, False, a LineStyle or a colour

@final
class Outlines:
    def __new__(
        cls,
        kind: Optional[str] = ...,
        *,
        color: Optional[_Color] = ...,
        width: Optional[float] = ...,
        silhouette: _Style = ...,
        boundary: _Style = ...,
        crease: _Style = ...,
        ridge: _Style = ...,
        valley: _Style = ...,
        nonmanifold: _Style = ...,
        suggestive: _Style = ...,
        material: _Style = ...,
        image: _Style = ...,
        crease_angle: Optional[float] = ...,
        weld: Optional[bool] = ...,
        normal_threshold: Optional[float] = ...,
        depth_threshold: Optional[float] = ...,
        depth_offset: Optional[float] = ...,
        contours: Optional[str] = ...,
        suggestive_threshold: Optional[float] = ...,
        curvature_smoothing: Optional[float] = ...,
        min_crease_length: Optional[float] = ...,
        max_crease_turn: Optional[float] = ...,
        image_rule: Optional[str] = ...,
        normal_angle: Optional[float] = ...,
        depth_jump: Optional[float] = ...,
        taper: Optional[float] = ...,
        width_by_depth: Optional[bool] = ...,
        join_kinds: Optional[bool] = ...,
    ) -> Outlines: ...
    kind: Final[str]
    styles: Final[Dict[str, Optional[LineStyle]]]
    crease_angle: Final[float]
    weld: Final[bool]
    normal_threshold: Final[float]
    depth_threshold: Final[float]
    depth_offset: Final[float]
    contours: Final[str]
    suggestive_threshold: Final[float]
    curvature_smoothing: Final[Optional[float]]
    min_crease_length: Final[float]
    max_crease_turn: Final[float]
    image_rule: Final[str]
    normal_angle: Final[float]
    depth_jump: Final[float]
    taper: Final[float]
    width_by_depth: Final[bool]
    join_kinds: Final[bool]
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

def _restore(cls: str, state: str) -> Any: ...
def kang_table() -> npt.NDArray[np.float64]: ...

@final
class RenderOptions:
    """Every render setting besides the meshes (the keywords of RenderKeywords), checked,
    with the core's defaults."""

    def __new__(cls, **options: Unpack[RenderKeywords]) -> RenderOptions: ...
    def replace(self, **options: Unpack[RenderKeywords]) -> RenderOptions: ...
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
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]: ...

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
        vertex_colors: Any = ...,
        face_colors: Any = ...,
        uv: Any = ...,
        texture: Any = ...,
        texture_filter: Optional[str] = ...,
        texture_wrap: Optional[str] = ...,
        alpha_cutoff: Optional[float] = ...,
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

# Scalars are checked in the core (src/py/args.rs), which names the argument in errors.
def _feature_edges(vertices: Any, faces: Any, crease_angle: float, weld: bool) -> _FeatureTuple: ...
def _silhouette(vertices: Any, faces: Any, eye: _Point, direction: _Point, weld: bool) -> _Pairs: ...
def _chains(edges: Any) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]: ...
def _contours(
    vertices: Any, faces: Any, eye: _Point, direction: _Point, weld: bool
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def _suggestive_contours(
    vertices: Any,
    faces: Any,
    eye: _Point,
    direction: _Point,
    weld: bool,
    threshold: Optional[float],
    smoothing: Optional[float],
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def _curvature(vertices: Any, faces: Any, smoothing: float) -> Tuple[
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
    npt.NDArray[np.float64],
]: ...
def _segments(vertices: Any, edges: Any) -> Any: ...
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
    def silhouette(self, eye: _Point, direction: _Point) -> _Pairs: ...
    def outlines(
        self, crease_angle: float, eye: _Point, direction: _Point, kinds: bool
    ) -> Tuple[_Pairs, Optional[npt.NDArray[np.int8]]]: ...
    def feature_edges(self, crease_angle: float) -> _FeatureTuple: ...
    def face_normals(self) -> npt.NDArray[np.float64]: ...
    def vertices(self) -> npt.NDArray[np.float64]: ...
    def weld_map(self) -> Optional[npt.NDArray[np.int64]]: ...
    def contours(self, eye: _Point, direction: _Point) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
    def suggestive_contours(
        self, eye: _Point, direction: _Point, threshold: Optional[float], smoothing: Optional[float]
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
    n_vertices: Final[int]
    n_faces: Final[int]
    n_edges: Final[int]
