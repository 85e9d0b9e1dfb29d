"""toonmesh: mesh smoothing, outline extraction and headless toon rendering, on NumPy arrays."""

from toonmesh import shapes, smooth
from toonmesh._core import (
    ConvergenceError,
    GpuError,
    GpuUnavailableError,
    __version__,
    get_num_threads,
    set_num_threads,
)

__all__ = [
    "shapes",
    "smooth",
    "ConvergenceError",
    "GpuError",
    "GpuUnavailableError",
    "__version__",
    "get_num_threads",
    "set_num_threads",
]
