"""A NumPy reference of toonmesh's shading formulas (the same ones as the shaders), used by the
rendering tests to recompute every pixel's colour from the rendered normal and depth outputs."""

from __future__ import annotations

from typing import Any, List, Tuple

import numpy as np

import toonmesh as tm
from toonmesh.testing import need_peer


def need(module: str) -> Any:
    """Imports an optional test dependency: skipped on a user's machine, a failure in CI."""
    return need_peer(module)


def srgb_to_linear(c: Any) -> np.ndarray:
    c = np.asarray(c, dtype=np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb8(c: np.ndarray) -> np.ndarray:
    c = np.clip(c, 0.0, 1.0)
    s = np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)
    return np.round(s * 255.0).astype(np.int32)


def is_orthographic(res: tm.RenderResult) -> bool:
    return bool(res.projection[3, 3] == 1.0)


def view_positions(res: tm.RenderResult) -> np.ndarray:
    """View-space point of every pixel centre at its rendered linear depth, (H, W, 3)."""
    h, w = res.depth.shape
    x = (np.arange(w) + 0.5) / w * 2 - 1
    y = 1 - (np.arange(h) + 0.5) / h * 2
    X, Y = np.meshgrid(x, y)
    z = np.where(np.isfinite(res.depth), res.depth, 1.0).astype(np.float64)  # background: any value
    P = res.projection
    if is_orthographic(res):
        vx = (X - P[0, 3]) / P[0, 0]
        vy = (Y - P[1, 3]) / P[1, 1]
        return np.stack([vx, vy, -z], axis=-1)
    return np.stack([X * z / P[0, 0], Y * z / P[1, 1], -z], axis=-1)


def view_lights(res: tm.RenderResult, lights: List[tm.Light]) -> List[Tuple[str, np.ndarray, np.ndarray]]:
    out = []
    V = res.view_matrix
    for light in lights:
        M = V if light.space == "world" else np.eye(4)
        color = srgb_to_linear(light.color) * light.intensity
        if light.kind == "directional":
            d = M[:3, :3] @ np.asarray(light.direction, dtype=np.float64)
            out.append(("toward", -d / np.linalg.norm(d), color))
        else:
            p = M @ np.append(np.asarray(light.position, dtype=np.float64), 1.0)
            out.append(("at", p[:3], color))
    return out


def light_dots(res: tm.RenderResult, lights: List[tm.Light]) -> List[np.ndarray]:
    """L.n per light and pixel, for excluding pixels right at a band edge."""
    n = res.normal.astype(np.float64)
    p = view_positions(res)
    dots = []
    for kind, v, _ in view_lights(res, lights):
        dots.append(np.sum(n * _toward(kind, v, p), axis=-1))
    return dots


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _toward(kind: str, vec: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The unit vector from view-space points ``p`` toward a light of ``view_lights``."""
    return np.broadcast_to(vec, p.shape) if kind == "toward" else _unit(vec - p)


def shade(material: tm.Material, n: np.ndarray, p: np.ndarray, orthographic: bool, ambient: Any, lights: Any) -> np.ndarray:
    """Linear RGB for unit view-space normals ``n`` at view-space points ``p`` (both (..., 3))."""
    m = material
    v = np.broadcast_to([0.0, 0.0, 1.0], p.shape) if orthographic else _unit(-p)
    c = np.broadcast_to(srgb_to_linear(ambient) * srgb_to_linear(m.ambient), p.shape).copy()
    diffuse, specular = srgb_to_linear(m.diffuse), srgb_to_linear(m.specular)
    for kind, vec, color in lights:
        L = _toward(kind, vec, p)
        d = np.sum(n * L, axis=-1)
        s = np.zeros_like(d)
        if m.model == "lambert":
            f = np.maximum(d, 0)[..., None] * np.ones(3)
        elif m.model == "phong":
            f = np.maximum(d, 0)[..., None] * np.ones(3)
            r = 2 * d[..., None] * n - L
            s = np.where(d > 0, np.maximum(np.sum(r * v, axis=-1), 0) ** m.shininess, 0.0)
        elif m.model == "thresholded_phong":
            f = (d >= m.t_h)[..., None] * np.ones(3)
            if m.highlight == "paper":
                hl = np.sum(L * v, axis=-1)
            else:
                hl = np.sum(n * _unit(L + v), axis=-1)
            s = (hl >= m.t_s).astype(np.float64)
        elif m.model == "bands":
            k = np.zeros(d.shape, dtype=np.int64)
            for t in m.thresholds:
                k += d >= t
            f = np.asarray(m.values)[k][..., None] * np.ones(3)
        else:
            table = np.asarray(m.table if m.table is not None else np.repeat(tm.kang_table()[:, None], 3, 1))
            i = np.minimum(np.floor(np.clip(d, 0, 1) * len(table)).astype(np.int64), len(table) - 1)
            f = table[i]
        c += f * color * diffuse + s[..., None] * color * specular
    return c


def rim(r: Any, c: np.ndarray, n: np.ndarray, p: np.ndarray, orthographic: bool, lights: Any) -> np.ndarray:
    """The linear colour ``c`` with the rim ``r`` (a :class:`toonmesh.Rim`) over it, its borders
    hard (``band_antialias=False``): ``Rim::finish`` and ``rim_amount`` in Rust."""
    v = np.broadcast_to([0.0, 0.0, 1.0], p.shape) if orthographic else _unit(-p)
    t = (np.sum(n * v, axis=-1) <= r.width).astype(np.float64)
    lit = np.max([np.sum(n * _toward(kind, vec, p), axis=-1) for kind, vec, _ in lights], axis=0)
    if r.side != "both":
        t *= (lit >= 0) if r.side == "lit" else (lit < 0)
    k = (t * r.strength)[..., None]
    color = srgb_to_linear(r.color)
    return c + color * k if r.blend == "add" else c + (color - c) * k


def expected_color(res: tm.RenderResult, material: tm.Material, lights: List[tm.Light], ambient: Any = (1, 1, 1),
                   albedo: Any = (1.0, 1.0, 1.0)) -> np.ndarray:
    """(H, W, 3) int sRGB codes the renderer should produce, from its own normal and depth outputs;
    ``albedo``: the surface's linear colour (a coloured mesh's, which multiplies the ambient and
    diffuse light; a material without a highlight is all that)."""
    n = res.normal.astype(np.float64)
    n[np.linalg.norm(n, axis=-1) == 0] = (0.0, 0.0, 1.0)  # background: any unit normal
    p, ortho, view = view_positions(res), is_orthographic(res), view_lights(res, lights)
    lin = shade(material, n, p, ortho, ambient, view) * np.asarray(albedo)
    if material.rim is not None:
        lin = rim(material.rim, lin, n, p, ortho, view)
    return linear_to_srgb8(lin)


def match_fraction(res: tm.RenderResult, expected: np.ndarray, mask: np.ndarray) -> float:
    diff = np.abs(res.color[..., :3].astype(np.int32) - expected)
    ok = np.all(diff <= 1, axis=-1)
    return float(ok[mask].mean())
