# Type stubs for the compiled core (checked against it with `python -m mypy.stubtest toonmesh._core`).
from typing import Any, Optional, Tuple

import numpy as np
import numpy.typing as npt

__all__ = [
    "ConvergenceError",
    "GpuError",
    "GpuUnavailableError",
    "__version__",
    "_smooth",
    "get_num_threads",
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
