"""Headless toon rendering: ``toonmesh.render(V, F)`` returns a toon-shaded image as NumPy arrays.

Colours are sRGB triples of floats in [0, 1] (or ``"#rrggbb"`` strings); shading is computed in
linear light and the colour output is encoded back to sRGB. See README "Rendering" for the
conventions of every output.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from toonmesh import _core
from toonmesh._input import mesh_arrays

RGB = Tuple[float, float, float]
ColorLike = Union[str, Sequence[float]]

#: The default base colour of materials (sRGB).
DEFAULT_COLOR: RGB = (0.95, 0.55, 0.25)


def _rgb(name: str, value: ColorLike) -> RGB:
    if isinstance(value, str):
        s = value.lstrip("#")
        if len(s) != 6:
            raise ValueError(f"{name}: expected '#rrggbb', got {value!r}")
        try:
            return (int(s[0:2], 16) / 255.0, int(s[2:4], 16) / 255.0, int(s[4:6], 16) / 255.0)
        except ValueError:
            raise ValueError(f"{name}: expected '#rrggbb', got {value!r}") from None
    try:
        c = [float(x) for x in value]
    except TypeError:
        raise TypeError(f"{name}: expected 3 numbers or '#rrggbb', got {type(value).__name__}") from None
    if len(c) != 3:
        raise ValueError(f"{name}: expected 3 numbers, got {len(c)}")
    if not all(np.isfinite(c)) or min(c) < 0.0:
        raise ValueError(f"{name}: channels must be finite and >= 0, got {tuple(c)}")
    return (c[0], c[1], c[2])


def _vec3(name: str, value: Sequence[float]) -> Tuple[float, float, float]:
    try:
        v = np.asarray(value, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected 3 numbers") from None
    if v.shape != (3,):
        raise ValueError(f"{name}: expected 3 numbers, got shape {np.shape(value)}")
    if not np.all(np.isfinite(v)):
        raise ValueError(f"{name}: must be finite, got {tuple(v)}")
    return (float(v[0]), float(v[1]), float(v[2]))


def _srgb_to_linear(c: np.ndarray) -> np.ndarray:
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _linear_to_srgb(c: np.ndarray) -> np.ndarray:
    c = np.clip(c, 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


def _scaled(color: RGB, k: float) -> RGB:
    """``color`` with its light scaled by ``k`` (in linear light), as sRGB."""
    s = _linear_to_srgb(_srgb_to_linear(np.asarray(color, dtype=np.float64)) * k)
    return (float(s[0]), float(s[1]), float(s[2]))


def kang_table() -> np.ndarray:
    """Kang et al.'s 256-to-3-level lookup table: (256,) float64 with 0.3 / 0.65 / 1.0 in thirds.

    The paper maps 256 Phong intensities to three tones without giving numbers; these split the
    range in thirds.
    """
    return np.array([(0.3, 0.65, 1.0)[i * 3 // 256] for i in range(256)], dtype=np.float64)


@dataclass(frozen=True)
class Material:
    """A shading model with its coefficients. Build one with the class methods.

    Every model computes, per pixel (or per vertex with ``per_vertex=True``, Gouraud-style as
    Al-Rousan et al. colour vertices), in linear light:
    ``C = a_l * ambient + sum over lights of (f(L.n) * d_l * diffuse + s * S_l * specular)``,
    where ``a_l`` is the scene's ambient light, ``d_l = S_l`` a light's colour times intensity,
    ``L`` the unit vector toward the light and ``n`` the unit normal. The models differ in ``f``
    and ``s``; colours are sRGB in [0, 1].
    """

    model: str
    diffuse: RGB
    ambient: RGB = (0.0, 0.0, 0.0)
    specular: RGB = (0.0, 0.0, 0.0)
    shininess: float = 32.0
    t_h: float = 0.0
    t_s: float = 0.95
    highlight: str = "blinn"
    thresholds: Tuple[float, ...] = (0.2, 0.5, 0.7, 0.9)
    values: Tuple[float, ...] = (0.0, 0.2, 0.7, 0.9, 1.0)
    table: Optional[Tuple[Tuple[float, float, float], ...]] = field(default=None, repr=False)
    per_vertex: bool = False

    @classmethod
    def lambert(cls, color: ColorLike = DEFAULT_COLOR, *, ambient: Optional[ColorLike] = None, per_vertex: bool = False) -> "Material":
        """Plain Lambert: f = max(L.n, 0), no highlight. ``ambient`` defaults to 10% of ``color``."""
        c = _rgb("color", color)
        a = _scaled(c, 0.1) if ambient is None else _rgb("ambient", ambient)
        return cls("lambert", diffuse=_scaled(c, 0.9), ambient=a, per_vertex=per_vertex)

    @classmethod
    def phong(
        cls,
        color: ColorLike = DEFAULT_COLOR,
        *,
        specular: ColorLike = (0.5, 0.5, 0.5),
        shininess: float = 32.0,
        ambient: Optional[ColorLike] = None,
        per_vertex: bool = False,
    ) -> "Material":
        """Plain Phong: f = max(L.n, 0), s = max(R.v, 0)^shininess on lit points (R = reflected L)."""
        c = _rgb("color", color)
        a = _scaled(c, 0.1) if ambient is None else _rgb("ambient", ambient)
        return cls("phong", diffuse=_scaled(c, 0.9), ambient=a, specular=_rgb("specular", specular), shininess=float(shininess), per_vertex=per_vertex)

    @classmethod
    def thresholded_phong(
        cls,
        color: ColorLike = DEFAULT_COLOR,
        *,
        t_h: float = 0.0,
        t_s: float = 0.95,
        highlight: str = "blinn",
        ambient: Optional[ColorLike] = None,
        specular: ColorLike = (0.6, 0.6, 0.6),
        per_vertex: bool = False,
    ) -> "Material":
        """Al-Rousan et al.'s toon model: C = a_l a_m + thresh(L.n, t_h) d_l d_m + thresh(h, t_s) S_l S_m.

        ``thresh(a, b)`` is 1 where ``a >= b`` else 0; ``t_h`` and ``t_s`` lie in [-1, 1].
        ``highlight="paper"`` uses h = L.v (light against view direction) as the paper writes it;
        ``"blinn"`` (default) uses the usual h = n . normalize(L + v). By default the shadow side
        keeps 35% of ``color`` (``ambient``) and the lit side reaches ``color``. The paper shades
        vertices: pass ``per_vertex=True`` for that.
        """
        if highlight not in ("paper", "blinn"):
            raise ValueError(f"highlight: must be 'paper' or 'blinn', got {highlight!r}")
        c = _rgb("color", color)
        a = _scaled(c, 0.35) if ambient is None else _rgb("ambient", ambient)
        return cls(
            "thresholded_phong",
            diffuse=_scaled(c, 0.65),
            ambient=a,
            specular=_rgb("specular", specular),
            t_h=float(t_h),
            t_s=float(t_s),
            highlight=highlight,
            per_vertex=per_vertex,
        )

    @classmethod
    def bands(
        cls,
        color: ColorLike = DEFAULT_COLOR,
        *,
        thresholds: Sequence[float] = (0.2, 0.5, 0.7, 0.9),
        values: Sequence[float] = (0.0, 0.2, 0.7, 0.9, 1.0),
        per_vertex: bool = False,
    ) -> "Material":
        """Borquez and Yepez's toon bands: f = values[k], k = number of thresholds t with L.n >= t.

        Defaults are the paper's: L.n >= 0.9 -> 1.0, 0.7-0.9 -> 0.9, 0.5-0.7 -> 0.7, 0.2-0.5 -> 0.2,
        below 0.2 -> 0.0, times ``color``. 1 to 8 increasing thresholds; one value more.
        """
        return cls(
            "bands",
            diffuse=_rgb("color", color),
            thresholds=tuple(float(t) for t in thresholds),
            values=tuple(float(v) for v in values),
            per_vertex=per_vertex,
        )

    @classmethod
    def lut(cls, table: Optional[Any] = None, color: ColorLike = DEFAULT_COLOR, *, per_vertex: bool = False) -> "Material":
        """A lookup table (gradient map): f = table[min(floor(clamp(L.n, 0, 1) N), N - 1)].

        ``table`` is (N,) grey factors or (N, 3) RGB factors (linear, 1 <= N <= 256) applied to
        ``color``; the default is :func:`kang_table`, Kang et al.'s 256-to-3-level mapping.
        """
        t = kang_table() if table is None else np.asarray(table, dtype=np.float64)
        if t.ndim == 1:
            t = np.repeat(t[:, None], 3, axis=1)
        if t.ndim != 2 or t.shape[1] != 3 or not 1 <= t.shape[0] <= 256:
            raise ValueError(f"table: expected shape (N,) or (N, 3) with 1 <= N <= 256, got {t.shape}")
        if not np.all(np.isfinite(t)) or (t < 0).any():
            raise ValueError("table: entries must be finite and >= 0")
        rows = tuple((float(r[0]), float(r[1]), float(r[2])) for r in t)
        return cls("lut", diffuse=_rgb("color", color), table=rows, per_vertex=per_vertex)

    def _spec(self) -> Dict[str, Any]:
        d: Dict[str, Any] = {
            "model": self.model,
            "diffuse": self.diffuse,
            "ambient": self.ambient,
            "specular": self.specular,
            "per_vertex": bool(self.per_vertex),
        }
        if self.model == "phong":
            d["shininess"] = self.shininess
        elif self.model == "thresholded_phong":
            d.update(t_h=self.t_h, t_s=self.t_s, highlight=self.highlight)
        elif self.model == "bands":
            d.update(thresholds=list(self.thresholds), values=list(self.values))
        elif self.model == "lut" and self.table is not None:
            d["table"] = [list(r) for r in self.table]
        return d


@dataclass(frozen=True)
class Light:
    """A directional or point light. Build one with :meth:`directional` or :meth:`point`."""

    kind: str
    direction: Optional[Tuple[float, float, float]] = None
    position: Optional[Tuple[float, float, float]] = None
    color: RGB = (1.0, 1.0, 1.0)
    intensity: float = 1.0
    space: str = "world"

    @classmethod
    def directional(
        cls, direction: Sequence[float], *, color: ColorLike = (1.0, 1.0, 1.0), intensity: float = 1.0, space: str = "world"
    ) -> "Light":
        """Parallel light travelling along ``direction`` (from the light toward the scene; any length > 0).

        ``space="camera"`` fixes it to the camera (x right, y up, -z forward) so it moves with the view.
        """
        d = _vec3("direction", direction)
        if not np.linalg.norm(d) > 0:
            raise ValueError("direction: must not be the zero vector")
        return cls("directional", direction=d, color=_rgb("color", color), intensity=float(intensity), space=_space(space))

    @classmethod
    def point(
        cls, position: Sequence[float], *, color: ColorLike = (1.0, 1.0, 1.0), intensity: float = 1.0, space: str = "world"
    ) -> "Light":
        """Light radiating from ``position`` (no falloff with distance)."""
        return cls("point", position=_vec3("position", position), color=_rgb("color", color), intensity=float(intensity), space=_space(space))

    @classmethod
    def key(cls) -> "Light":
        """The default light: from the upper left, behind the viewer, fixed to the camera."""
        return cls.directional((0.4, -0.55, -0.75), space="camera")

    def _spec(self) -> Dict[str, Any]:
        return {
            "kind": self.kind,
            "direction": self.direction,
            "position": self.position,
            "color": self.color,
            "intensity": self.intensity,
            "space": self.space,
        }


def _space(space: str) -> str:
    if space not in ("world", "camera"):
        raise ValueError(f"space: must be 'world' or 'camera', got {space!r}")
    return space


@dataclass(frozen=True)
class Camera:
    """A camera. Build one with :meth:`fit` (the default), :meth:`look_at` or :meth:`orthographic`.

    View space is right-handed: x right, y up, the camera looks down -z. ``near``/``far`` are
    chosen to enclose the scene when left as None.
    """

    kind: str = "fit"
    projection: str = "perspective"
    eye: Optional[Tuple[float, float, float]] = None
    target: Optional[Tuple[float, float, float]] = None
    up: Tuple[float, float, float] = (0.0, 1.0, 0.0)
    direction: Tuple[float, float, float] = (0.35, 0.3, 1.0)
    margin: float = 1.05
    fov_y: float = 35.0
    height: float = 2.0
    near: Optional[float] = None
    far: Optional[float] = None

    @classmethod
    def fit(
        cls,
        direction: Sequence[float] = (0.35, 0.3, 1.0),
        *,
        up: Sequence[float] = (0.0, 1.0, 0.0),
        fov_y: float = 35.0,
        margin: float = 1.05,
        orthographic: bool = False,
    ) -> "Camera":
        """Frame the meshes' bounding sphere, seen from ``direction`` (scene -> eye), ``margin`` >= 1 leaves room."""
        return cls(
            kind="fit",
            projection="orthographic" if orthographic else "perspective",
            direction=_vec3("direction", direction),
            up=_vec3("up", up),
            fov_y=float(fov_y),
            margin=float(margin),
        )

    @classmethod
    def look_at(
        cls,
        eye: Sequence[float],
        target: Sequence[float] = (0.0, 0.0, 0.0),
        *,
        up: Sequence[float] = (0.0, 1.0, 0.0),
        fov_y: float = 35.0,
        near: Optional[float] = None,
        far: Optional[float] = None,
    ) -> "Camera":
        """A perspective camera at ``eye`` looking at ``target``; ``fov_y`` is the vertical field of view in degrees."""
        return cls(kind="look_at", eye=_vec3("eye", eye), target=_vec3("target", target), up=_vec3("up", up), fov_y=float(fov_y), near=near, far=far)

    @classmethod
    def orthographic(
        cls,
        eye: Sequence[float],
        target: Sequence[float] = (0.0, 0.0, 0.0),
        *,
        up: Sequence[float] = (0.0, 1.0, 0.0),
        height: float = 2.0,
        near: Optional[float] = None,
        far: Optional[float] = None,
    ) -> "Camera":
        """An orthographic camera; ``height`` is the height of the view in world units."""
        return cls(
            kind="look_at",
            projection="orthographic",
            eye=_vec3("eye", eye),
            target=_vec3("target", target),
            up=_vec3("up", up),
            height=float(height),
            near=near,
            far=far,
        )

    def __post_init__(self) -> None:
        # Caught when the camera is made rather than at the first render, far from the mistake.
        if self.kind == "look_at" and self.eye is not None and self.eye == self.target:
            raise ValueError(f"target: must differ from eye, both are {self.eye}")

    def _spec(self) -> Dict[str, Any]:
        return {k: getattr(self, k) for k in ("kind", "projection", "eye", "target", "up", "direction", "margin", "fov_y", "height", "near", "far")}


class MeshHandle:
    """A mesh uploaded to a :class:`Renderer` (see :meth:`Renderer.add_mesh`)."""

    def __init__(self, renderer: "Renderer", mesh_id: int, n_vertices: int, n_faces: int, normals: str):
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
    ``transform`` is a 4x4 affine model -> world matrix (row-major, applied to column vectors);
    ``normals`` is ``"smooth"`` (area-weighted vertex normals) or ``"flat"`` (one per face).
    """

    def __init__(
        self,
        vertices: Any,
        faces: Any = None,
        *,
        material: Optional[Material] = None,
        transform: Optional[Any] = None,
        normals: str = "smooth",
    ):
        self.handle: Optional[MeshHandle] = vertices if isinstance(vertices, MeshHandle) else None
        if self.handle is not None:
            if faces is not None:
                raise TypeError("faces: must be None when vertices is a MeshHandle")
            self.vertices: Optional[np.ndarray] = None
            self.faces: Optional[np.ndarray] = None
        else:
            self.vertices, self.faces = mesh_arrays(vertices, faces)
        if material is not None and not isinstance(material, Material):
            raise TypeError(f"material: expected a toonmesh.Material, got {type(material).__name__}")
        self.material = material
        self.transform = None if transform is None else np.asarray(transform, dtype=np.float64)
        if normals not in ("smooth", "flat"):
            raise ValueError(f"normals: must be 'smooth' or 'flat', got {normals!r}")
        self.normals = normals


class RenderResult:
    """The images of one render. Arrays are row-major with the top row first.

    - ``color``: (H, W, 4) uint8, sRGB with straight alpha (None unless asked for);
    - ``depth``: (H, W) float32, linear view depth (distance from the camera plane along the
      viewing axis, world units); ``inf`` where no mesh is;
    - ``normal``: (H, W, 3) float32, unit view-space normals (x right, y up, z toward the
      camera), turned toward the camera; (0, 0, 0) where no mesh is;
    - ``passes``: the passes that ran, in order; ``timings``: seconds per pass;
    - ``view_matrix``, ``projection`` (4x4 float64), ``near``, ``far``: the camera used.
    """

    def __init__(self, raw: Dict[str, Any], backend: str):
        self.color: Optional[np.ndarray] = raw["color"]
        self.normal: Optional[np.ndarray] = raw["normal"]
        self.depth: Optional[np.ndarray] = raw["depth"]
        self.timings: Dict[str, float] = dict(raw["timings"])
        self.passes: List[str] = [name for name, _ in raw["timings"]]
        self.view_matrix: np.ndarray = raw["view"]
        self.projection: np.ndarray = raw["proj"]
        self.near: float = raw["near"]
        self.far: float = raw["far"]
        self.backend = backend
        first = next(a for a in (self.color, self.depth, self.normal) if a is not None)
        self.height, self.width = int(first.shape[0]), int(first.shape[1])

    @property
    def total_time(self) -> float:
        """Seconds spent in all passes."""
        return float(sum(self.timings.values()))

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

    def to_pil(self) -> Any:
        """The colour image as a ``PIL.Image.Image`` in mode RGBA (needs Pillow)."""
        from PIL import Image

        return Image.fromarray(self._color(), mode="RGBA") if _pil_takes_mode() else Image.fromarray(self._color())

    def _repr_png_(self) -> Optional[bytes]:
        return None if self.color is None else self.png_bytes()

    def __repr__(self) -> str:
        outs = [n for n in ("color", "normal", "depth") if getattr(self, n) is not None]
        return f"RenderResult({self.width}x{self.height}, outputs={outs}, passes={self.passes}, {self.total_time * 1e3:.1f} ms, {self.backend})"


def _pil_takes_mode() -> bool:
    import PIL

    return tuple(int(x) for x in PIL.__version__.split(".")[:2]) < (11, 3)


def _smoothed(vertices: np.ndarray, faces: np.ndarray, iterations: int) -> np.ndarray:
    if isinstance(iterations, bool) or not isinstance(iterations, (int, np.integer)):
        raise TypeError(f"smooth_iterations: expected an int, got {type(iterations).__name__}")
    if iterations < 0:
        raise ValueError(f"smooth_iterations: must be >= 0, got {iterations}")
    if iterations == 0:
        return vertices
    from toonmesh import smooth

    return smooth.laplacian(vertices, faces, iterations=int(iterations), preset="paper")


def _outputs(outputs: Union[str, Iterable[str]]) -> List[str]:
    names = [outputs] if isinstance(outputs, str) else list(outputs)
    for n in names:
        if n not in ("color", "normal", "depth"):
            raise ValueError(f"outputs: unknown output {n!r}; use 'color', 'normal', 'depth'")
    if not names:
        raise ValueError("outputs: ask for at least one of 'color', 'normal', 'depth'")
    return names


class Renderer:
    """Keeps meshes on the GPU so that many views of them upload nothing again.

    ``backend`` is ``"vulkan"``, ``"gl"`` or ``"auto"`` (Vulkan, then GL through EGL); None reads
    the ``TOONMESH_BACKEND`` environment variable, then uses ``"auto"``. The GPU context is made
    once per process and shared. Methods may be called from several threads at once.

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

    def add_mesh(self, vertices: Any, faces: Any = None, *, normals: str = "smooth", smooth_iterations: int = 0) -> MeshHandle:
        """Uploads a mesh ((N, 3) float32/float64 and (M, 3) int faces, or a trimesh.Trimesh).

        ``normals``: ``"smooth"`` or ``"flat"``. ``smooth_iterations``: Laplacian smoothing
        first (each vertex to the mean of its neighbours, n times), as in Al-Rousan et al.
        """
        V, F = mesh_arrays(vertices, faces)
        V = _smoothed(V, F, smooth_iterations) if smooth_iterations else V
        mesh_id = self._engine.add_mesh(V, F, normals)
        return MeshHandle(self, mesh_id, len(V), len(F), normals)

    def remove_mesh(self, mesh: MeshHandle) -> None:
        """Frees a mesh's GPU memory."""
        if mesh.renderer is not self:
            raise ValueError("mesh: belongs to another Renderer")
        self._engine.remove_mesh(mesh.id)

    def render(
        self,
        meshes: Any = None,
        *,
        material: Optional[Material] = None,
        transform: Optional[Any] = None,
        camera: Optional[Camera] = None,
        lights: Optional[Sequence[Light]] = None,
        ambient: ColorLike = (1.0, 1.0, 1.0),
        background: Sequence[float] = (1.0, 1.0, 1.0, 1.0),
        width: int = 512,
        height: int = 512,
        outputs: Union[str, Iterable[str]] = ("color",),
        msaa: int = 1,
        supersample: int = 1,
    ) -> RenderResult:
        """Renders ``meshes`` (a MeshHandle, a :class:`Mesh`, or a list of them; None or [] for an empty scene).

        ``material``/``transform`` apply to meshes that do not set their own (default
        :meth:`Material.bands`). ``camera`` defaults to :meth:`Camera.fit`, ``lights`` to
        ``[Light.key()]``. ``ambient`` is the ambient light colour. ``background`` is sRGB(A) in
        [0, 1]. ``width``/``height`` in pixels (1 to the device's limit). ``outputs``: any of
        ``"color"``, ``"normal"``, ``"depth"``; only those are computed and read back.
        ``msaa`` (1 or 4) and ``supersample`` (1 to 4, renders ``supersample`` times larger and
        averages) trade time for smoother edges.
        """
        items = [] if meshes is None else (list(meshes) if isinstance(meshes, (list, tuple)) else [meshes])
        default_material = material if material is not None else Material.bands()
        if not isinstance(default_material, Material):
            raise TypeError(f"material: expected a toonmesh.Material, got {type(default_material).__name__}")
        uploaded: List[MeshHandle] = []
        try:
            specs = []
            for i, item in enumerate(items):
                if isinstance(item, MeshHandle):
                    item = Mesh(item)
                elif not isinstance(item, Mesh):
                    raise TypeError(f"meshes[{i}]: expected a toonmesh.Mesh or MeshHandle, got {type(item).__name__}")
                handle = item.handle
                if handle is None:
                    handle = self.add_mesh(item.vertices, item.faces, normals=item.normals)
                    uploaded.append(handle)
                elif handle.renderer is not self:
                    raise ValueError(f"meshes[{i}]: the MeshHandle belongs to another Renderer")
                m = item.material or default_material
                t = item.transform if item.transform is not None else transform
                specs.append((handle.id, m._spec(), None if t is None else np.asarray(t, dtype=np.float64).tolist()))
            if lights is None:
                lights = [Light.key()]
            for i, light in enumerate(lights):
                if not isinstance(light, Light):
                    raise TypeError(f"lights[{i}]: expected a toonmesh.Light, got {type(light).__name__}")
            if camera is not None and not isinstance(camera, Camera):
                raise TypeError(f"camera: expected a toonmesh.Camera, got {type(camera).__name__}")
            raw = self._engine.render(
                specs,
                camera=(camera or Camera())._spec(),
                lights=[light._spec() for light in lights],
                ambient=_rgb("ambient", ambient),
                background=[float(c) for c in background],
                width=width,
                height=height,
                outputs=_outputs(outputs),
                msaa=msaa,
                supersample=supersample,
            )
        finally:
            for h in uploaded:
                self._engine.remove_mesh(h.id)
        return RenderResult(raw, self.backend)


_renderers: Dict[Optional[str], Renderer] = {}
_renderers_lock = threading.Lock()


def _shared_renderer(backend: Optional[str]) -> Renderer:
    with _renderers_lock:
        r = _renderers.get(backend)
        if r is None:
            r = _renderers[backend] = Renderer(backend)
        return r


def render(
    vertices: Any = None,
    faces: Any = None,
    *,
    material: Optional[Material] = None,
    transform: Optional[Any] = None,
    normals: str = "smooth",
    smooth_iterations: int = 0,
    camera: Optional[Camera] = None,
    lights: Optional[Sequence[Light]] = None,
    ambient: ColorLike = (1.0, 1.0, 1.0),
    background: Sequence[float] = (1.0, 1.0, 1.0, 1.0),
    width: int = 512,
    height: int = 512,
    outputs: Union[str, Iterable[str]] = ("color",),
    msaa: int = 1,
    supersample: int = 1,
    backend: Optional[str] = None,
) -> RenderResult:
    """Renders a mesh (or several) to a toon-shaded image, headless, and returns NumPy arrays.

    ``vertices``: (N, 3) float32/float64 with ``faces`` (M, 3) int32/int64/uint32; or a
    ``trimesh.Trimesh``; or a :class:`Mesh` or list of them (each with its own material and
    transform); None for an empty scene. Inputs are never modified.
    ``material`` defaults to :meth:`Material.bands` (Borquez and Yepez's bands).
    ``normals``: ``"smooth"`` or ``"flat"``. ``smooth_iterations``: Laplacian smoothing first
    (Al-Rousan et al.'s pipeline). Other arguments as in :meth:`Renderer.render`; ``backend``
    as in :class:`Renderer`.

    >>> img = toonmesh.render(V, F, width=640, height=480).color   # (480, 640, 4) uint8
    """
    if isinstance(vertices, (list, tuple)) and faces is None:
        items: List[Any] = list(vertices)
    elif vertices is None:
        items = []
    elif isinstance(vertices, Mesh):
        items = [vertices]
    else:
        V, F = mesh_arrays(vertices, faces)
        items = [Mesh(V, F, normals=normals)]
    if smooth_iterations:
        items = [
            _with_vertices(m, _smoothed(m.vertices, m.faces, smooth_iterations)) if m.vertices is not None and m.faces is not None else m
            for m in (x if isinstance(x, Mesh) else Mesh(x) for x in items)
        ]
    return _shared_renderer(backend).render(
        items,
        material=material,
        transform=transform,
        camera=camera,
        lights=lights,
        ambient=ambient,
        background=background,
        width=width,
        height=height,
        outputs=outputs,
        msaa=msaa,
        supersample=supersample,
    )


def _with_vertices(m: Mesh, vertices: np.ndarray) -> Mesh:
    return Mesh(vertices, m.faces, material=m.material, transform=m.transform, normals=m.normals)


def gpu_info(backend: Optional[str] = None) -> Dict[str, Any]:
    """The adapter renders use: ``name``, ``backend`` ("vulkan" or "gl"), ``device_type``
    ("cpu" for Mesa's lavapipe/llvmpipe), ``driver``, ``driver_info``, ``max_texture_size``
    and ``msaa_samples``. Creates the process-wide GPU context if needed; raises
    :class:`toonmesh.GpuUnavailableError` when there is no adapter.
    """
    return _core.gpu_info(backend)


__all__ = ["Camera", "Light", "Material", "Mesh", "MeshHandle", "RenderResult", "Renderer", "gpu_info", "kang_table", "render"]
