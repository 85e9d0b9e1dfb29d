"""toonmesh: mesh smoothing, outline extraction and headless toon rendering, on NumPy arrays."""

from toonmesh._core import (
    ConvergenceError,
    GpuError,
    GpuUnavailableError,
    __version__,
    get_num_threads,
    set_num_threads,
)
from toonmesh import edges

__all__ = [
    "ConvergenceError",
    "GpuError",
    "GpuUnavailableError",
    "__version__",
    "edges",
    "get_num_threads",
    "set_num_threads",
]
