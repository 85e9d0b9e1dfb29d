# Type stubs for the compiled core (checked against it with `python -m mypy.stubtest toonmesh._core`).
from typing import Any, Dict, List, Optional, Tuple, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "ConvergenceError",
    "GpuError",
    "GpuUnavailableError",
    "Renderer",
    "__version__",
    "_smooth",
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
