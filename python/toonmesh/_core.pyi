# Type stubs for the compiled core (checked against it with `python -m mypy.stubtest toonmesh._core`).
from typing import Any, Dict, List, Optional, Tuple, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "ConvergenceError",
    "GpuError",
    "GpuUnavailableError",
    "Renderer",
    "_EdgeIndex",
    "__version__",
    "_chains",
    "_feature_edges",
    "_paper_gradient",
    "_silhouette",
    "_smooth",
    "_sobel",
    "encode_png_rgba",
    "get_num_threads",
    "gpu_info",
    "grid",
    "icosphere",
    "set_num_threads",
]
__version__: str

class ConvergenceError(RuntimeError): ...
class GpuUnavailableError(RuntimeError): ...
class GpuError(RuntimeError): ...

def set_num_threads(n: int) -> None: ...
def get_num_threads() -> int: ...
def icosphere(
    subdivisions: int = 3, noise: float = 0.0, seed: int = 0
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def grid(n: int = 32, noise: float = 0.0, seed: int = 0) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
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
    weld: bool = False,
) -> npt.NDArray[np.floating[Any]]: ...

# --- rendering (src/py/render.rs); the public API is toonmesh._render ---

@final
class Renderer:
    def __new__(cls, backend: Optional[str] = None) -> "Renderer": ...
    @property
    def info(self) -> Dict[str, Any]: ...
    @property
    def mesh_count(self) -> int: ...
    def add_mesh(self, vertices: Any, faces: Any, normals: str = "smooth") -> int: ...
    def remove_mesh(self, mesh: int) -> bool: ...
    def render(
        self,
        items: List[Any],
        *,
        camera: Optional[Any] = None,
        lights: Optional[List[Any]] = None,
        ambient: Optional[Any] = None,
        background: Optional[Any] = None,
        width: int = 512,
        height: int = 512,
        outputs: Optional[List[str]] = None,
        msaa: int = 1,
        supersample: int = 1,
    ) -> Dict[str, Any]: ...

def gpu_info(backend: Optional[str] = None) -> Dict[str, Any]: ...
def encode_png_rgba(color: Any) -> bytes: ...


# --- edges (toonmesh.edges wraps these) ---

_Pairs = npt.NDArray[np.int64]
_FeatureTuple = Tuple[
    _Pairs, _Pairs, npt.NDArray[np.float64], npt.NDArray[np.bool_], _Pairs, npt.NDArray[np.int64]
]
_Point = Optional[Tuple[float, float, float]]

def _feature_edges(vertices: Any, faces: Any, crease_angle: float = 30.0, weld: bool = False) -> _FeatureTuple: ...
def _silhouette(
    vertices: Any, faces: Any, eye: _Point = None, direction: _Point = None, weld: bool = False
) -> _Pairs: ...
def _chains(edges: Any) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]: ...
def _sobel(image: Any, output: str = "magnitude", convention: str = "skimage") -> Any: ...
def _paper_gradient(buffer: Any) -> Any: ...

@final
class _EdgeIndex:
    def __new__(cls, vertices: Any, faces: Any, weld: bool = False) -> _EdgeIndex: ...
    def silhouette(self, eye: _Point = None, direction: _Point = None) -> _Pairs: ...
    def feature_edges(self, crease_angle: float = 30.0) -> _FeatureTuple: ...
    def face_normals(self) -> npt.NDArray[np.float64]: ...
    def vertices(self) -> npt.NDArray[np.float64]: ...
    def weld_map(self) -> Optional[npt.NDArray[np.int64]]: ...
    @property
    def n_vertices(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def n_edges(self) -> int: ...
