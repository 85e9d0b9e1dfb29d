"""Point clouds and ink lines as scene items: :class:`Points` (a scan's points, drawn as
splats) and :class:`Lines` (segments drawn as ink), beside :class:`toonmesh.Mesh`."""

from __future__ import annotations

import warnings
from typing import Any, Optional

import numpy as np

from toonmesh import _core
from toonmesh._core import LineStyle, Material


def _floats(name: str, value: Any, width: int, n: Optional[int] = None) -> np.ndarray:
    """``value`` as a C-contiguous (N, width) float array (float32 kept, anything else float64),
    finite, with ``n`` rows where given; errors name ``name``."""
    try:
        a = np.asarray(value)
    except Exception as exc:  # a ragged list
        raise ValueError(f"{name}: not an array ({exc})") from None
    if a.dtype.kind not in "fiu":
        raise TypeError(f"{name}: expected numbers, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != width:
        raise ValueError(f"{name}: expected shape (N, {width}), got {a.shape}")
    if n is not None and a.shape[0] != n:
        raise ValueError(f"{name}: expected {n} rows (one per point), got {a.shape[0]}")
    a = np.ascontiguousarray(a, dtype=np.float32 if a.dtype == np.float32 else np.float64)
    bad = ~np.isfinite(a).all(axis=1)
    if bad.any():
        raise ValueError(f"{name}: row {int(np.argmax(bad)) + 1} (1-based) is not finite")
    return a


def _name(name: Any) -> str:
    if not isinstance(name, str):
        raise TypeError(f"name: expected a str, got {type(name).__name__}")
    return name


class Points:
    """A point cloud placed in a scene, drawn as splats (small discs) with the material's toon
    tones, like a surface.

    Nothing given is modified.

    Args:
        positions: (N, 3) float32/float64 in world units (N >= 1).
        normals: (N, 3) floats, one per point, not zero (scaled to unit length); None
            (default): estimated from each point's nearest neighbours.
        colors: (N, 3) or (N, 4) sRGB(A) per point, uint8 codes or floats in [0, 1] (an alpha
            channel is not drawn: a warning says so); None (default): white (the material's
            colour shows).
        radius: the splats' radius in world units, a float or an (N,) array, > 0; None
            (default): from the cloud's own spacing, so any scale works (0.9 times the mean
            distance to the 12th nearest neighbour; a cloud of 12 points or fewer samples no
            surface, and gets dots 0.4 times the mean nearest distance).
        material: as for :class:`toonmesh.Mesh`.
        transform: as for :class:`toonmesh.Mesh`.
        up: as for :class:`toonmesh.Mesh`.
        name: as for :class:`toonmesh.Mesh`.
    """

    def __init__(
        self,
        positions: Any,
        normals: Any = None,
        colors: Any = None,
        radius: Any = None,
        *,
        material: Optional[Material] = None,
        transform: Optional[Any] = None,
        up: Optional[str] = None,
        name: str = "",
    ):
        self.name = _name(name)
        self.positions = _floats("positions", positions, 3)
        n = len(self.positions)
        if n == 0:
            raise ValueError("positions: a point cloud needs at least 1 point, got 0")
        self.normals = None if normals is None else _floats("normals", normals, 3, n)
        if self.normals is not None:
            zero = ~(np.abs(self.normals).max(axis=1) > 0)
            if zero.any():
                raise ValueError(f"normals: row {int(np.argmax(zero)) + 1} (1-based) is zero")
        self.colors = None
        if colors is not None:
            c = np.asarray(colors)
            width = c.shape[1] if c.ndim == 2 else 0
            self.colors = _floats("colors", c, width if width in (3, 4) else 3, n)
            if c.dtype == np.uint8:
                self.colors = np.ascontiguousarray(c)
            elif not ((self.colors >= 0) & (self.colors <= 1)).all():
                raise ValueError("colors: floats must be in [0, 1] (uint8 codes for 0 to 255)")
            opaque = 255 if self.colors.dtype == np.uint8 else 1.0
            if width == 4 and (self.colors[:, 3] < opaque).any():
                warnings.warn("colors: the alpha channel is not drawn on points (splats are opaque; a material's "
                              "opacity makes a cloud see-through)", UserWarning, stacklevel=2)
        self.radius: Any = None
        if radius is not None:
            r = np.asarray(radius, dtype=np.float64)
            if r.ndim == 0:
                r = r.reshape(())
            elif r.shape != (n,):
                raise ValueError(f"radius: expected a float or shape ({n},), got {r.shape}")
            if not (np.isfinite(r) & (r > 0)).all():
                raise ValueError("radius: must be finite and > 0")
            self.radius = float(r) if r.ndim == 0 else r
        if material is not None and not isinstance(material, Material):
            raise TypeError(f"material: expected a toonmesh.Material, got {type(material).__name__}")
        self.material = material
        self.transform: Optional[np.ndarray] = None if transform is None else _core._transform(transform)
        self.up: Optional[str] = _core._up_axis(up)
        #: The file the points were read from ("" for none).
        self.source = ""

    def __len__(self) -> int:
        return len(self.positions)

    def __repr__(self) -> str:
        return f"Points({len(self)} points{', ' + repr(self.name) if self.name else ''})"


class Lines:
    """Line segments placed in a scene, drawn as ink (a wire, a path, a glTF ``LINES``
    primitive or an OBJ ``l`` element), hidden by surfaces in front of them, in the SVG.

    Args:
        positions: (N, 3) float32/float64 in world units.
        segments: (K, 2) integer indices into ``positions``, each a segment; None (default):
            one polyline through the positions in order.
        color: the ink's sRGB colour, as :class:`LineStyle` takes it (``"#203040"``, 3 floats
            in [0, 1]); None (default): the outlines' ink colour.
        width: the ink's width in output pixels, in (0, 64]; None (default): the outlines'
            line width.
        transform: as for :class:`toonmesh.Mesh`.
        up: as for :class:`toonmesh.Mesh`.
        name: as for :class:`toonmesh.Mesh`.
    """

    def __init__(
        self,
        positions: Any,
        segments: Any = None,
        *,
        color: Any = None,
        width: Optional[float] = None,
        transform: Optional[Any] = None,
        up: Optional[str] = None,
        name: str = "",
    ):
        self.name = _name(name)
        self.positions = _floats("positions", positions, 3)
        n = len(self.positions)
        if segments is None:
            if n < 2:
                raise ValueError(f"positions: a polyline needs at least 2 points, got {n}")
            i = np.arange(n - 1, dtype=np.int64)
            self.segments = np.stack([i, i + 1], axis=1)
        else:
            s = np.asarray(segments)
            if s.dtype.kind not in "iu":
                raise TypeError(f"segments: expected integers, got dtype {s.dtype}")
            if s.ndim != 2 or s.shape[1] != 2:
                raise ValueError(f"segments: expected shape (K, 2), got {s.shape}")
            if s.size and (s.min() < 0 or s.max() >= n):
                bad = int(np.argmax(((s < 0) | (s >= n)).any(axis=1)))
                raise IndexError(f"segments: row {bad + 1} (1-based) indexes past the {n} positions")
            self.segments = np.ascontiguousarray(s, dtype=np.int64)
        # checked as a LineStyle checks them: any colour the settings take (hex, floats, codes)
        self.color: Optional[tuple] = None if color is None else tuple(LineStyle(color=color).color)
        self.width: Optional[float] = None if width is None else float(LineStyle(width=width).width)
        self.transform: Optional[np.ndarray] = None if transform is None else _core._transform(transform)
        self.up: Optional[str] = _core._up_axis(up)
        #: The file the lines were read from ("" for none).
        self.source = ""

    def __len__(self) -> int:
        return len(self.segments)

    def __repr__(self) -> str:
        return f"Lines({len(self)} segments{', ' + repr(self.name) if self.name else ''})"
