"""toonmesh: mesh smoothing, outline extraction and headless toon rendering, on NumPy arrays."""

from toonmesh.rendering._runtime_dir import ensure_runtime_dir

ensure_runtime_dir()  # before any GPU device is made: keeps Mesa's Wayland probe quiet

from toonmesh import edges, points, shapes, smooth
from toonmesh._core import (
    ConvergenceError,
    GpuError,
    GpuUnavailableError,
    __version__,
    get_num_threads,
    set_num_threads,
)

# the settings classes (the core's SETTINGS_CLASSES, each a class of the core)
from toonmesh._core import (
    Camera,
    Dither,
    EyeDome,
    Light,
    LineStyle,
    Material,
    Outlines,
    Paper,
    RenderOptions,
    Rim,
    Shadows,
)
from toonmesh.rendering._render import (
    Mesh,
    MeshHandle,
    Renderer,
    RenderKeywords,
    RenderResult,
    RenderStack,
    gpu_info,
    kang_table,
    render,
)

from toonmesh.files._load import load
from toonmesh.scene._points import Lines, Points
from toonmesh.rendering._render import __all__ as _rendering
from toonmesh.viewer import Viewer, ViewerClosedError

__all__ = [
    *_rendering,
    "Lines",
    "Points",
    "Camera",
    "Dither",
    "EyeDome",
    "Light",
    "LineStyle",
    "Material",
    "Outlines",
    "Paper",
    "RenderOptions",
    "Rim",
    "Shadows",
    "ConvergenceError",
    "GpuError",
    "GpuUnavailableError",
    "Viewer",
    "ViewerClosedError",
    "__version__",
    "edges",
    "get_num_threads",
    "load",
    "set_num_threads",
    "shapes",
    "smooth",
]
