"""Outlines found on the mesh and in the image.

Mesh-space outlines (toonmesh.edges.EdgeIndex) and image-space outlines
(toonmesh.edges.detect_edges) of the fandisk (``toonmesh.data``) and the teapot
(``toonmesh.shapes``). Needs matplotlib (``pip install matplotlib``).

Hidden lines are removed with a small NumPy z-buffer, which also provides the normal and depth
buffers for the image-space panel.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

import toonmesh as tm  # noqa: E402
from toonmesh import edges as te  # noqa: E402
from toonmesh.data import fandisk  # noqa: E402

SIZE = 260
DISTANCE = 2.6  # eye distance in bounding-sphere radii


def camera(V, eye_dir, up=(0.0, 1.0, 0.0), distance=DISTANCE):
    centre = (V.min(0) + V.max(0)) / 2
    radius = np.linalg.norm(V.max(0) - V.min(0)) / 2
    forward = -np.asarray(eye_dir, float) / np.linalg.norm(eye_dir)
    eye = centre - forward * radius * distance
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    return eye, np.stack([right, true_up, forward]), radius


def project(P, eye, R, radius):
    """Perspective projection to pixels; returns (x, y, depth)."""
    q = (P - eye) @ R.T
    f = SIZE * 0.42 * DISTANCE  # the bounding sphere spans about 84% of the picture
    return SIZE / 2 + f * q[:, 0] / q[:, 2], SIZE / 2 - f * q[:, 1] / q[:, 2], q[:, 2]


def rasterise(V, F, eye, R, radius):
    """Depth (inf = background) and view-space normal buffers by a z-buffer."""
    x, y, z = project(V, eye, R, radius)
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-300
    front = np.einsum("ij,ij->i", n, V[F[:, 0]] - eye) < 0
    depth = np.full((SIZE, SIZE), np.inf)
    normal = np.zeros((SIZE, SIZE, 3))
    nview = n @ R.T
    for f in np.flatnonzero(front):
        i = F[f]
        xs, ys, zs = x[i], y[i], z[i]
        x0, x1 = int(max(0, np.floor(xs.min()))), int(min(SIZE - 1, np.ceil(xs.max())))
        y0, y1 = int(max(0, np.floor(ys.min()))), int(min(SIZE - 1, np.ceil(ys.max())))
        if x1 < x0 or y1 < y0:
            continue
        gx, gy = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        d = (ys[1] - ys[2]) * (xs[0] - xs[2]) + (xs[2] - xs[1]) * (ys[0] - ys[2])
        if abs(d) < 1e-12:
            continue
        a = ((ys[1] - ys[2]) * (gx - xs[2]) + (xs[2] - xs[1]) * (gy - ys[2])) / d
        b = ((ys[2] - ys[0]) * (gx - xs[2]) + (xs[0] - xs[2]) * (gy - ys[2])) / d
        c = 1 - a - b
        inside = (a >= 0) & (b >= 0) & (c >= 0)
        zz = a * zs[0] + b * zs[1] + c * zs[2]
        win = depth[y0 : y1 + 1, x0 : x1 + 1]
        closer = inside & (zz < win)
        win[closer] = zz[closer]
        normal[y0 : y1 + 1, x0 : x1 + 1][closer] = nview[f]
    return depth, normal


def visible_segments(V, edges, eye, R, radius, depth, steps=12):
    """Pieces of each edge that pass the depth test, as 2-D pixel segments."""
    if len(edges) == 0:
        return []
    t = np.linspace(0, 1, steps + 1)
    P = (
        V[edges[:, 0]][:, None] * (1 - t[None, :, None])
        + V[edges[:, 1]][:, None] * t[None, :, None]
    )
    x, y, z = project(P.reshape(-1, 3), eye, R, radius)
    x, y, z = x.reshape(P.shape[:2]), y.reshape(P.shape[:2]), z.reshape(P.shape[:2])
    xi = np.clip(x.astype(int), 0, SIZE - 1)
    yi = np.clip(y.astype(int), 0, SIZE - 1)
    # visible when not behind the farthest surface around it
    # (the background counts as infinitely far)
    far = np.maximum.reduce(
        [
            depth[np.clip(yi + dy, 0, SIZE - 1), np.clip(xi + dx, 0, SIZE - 1)]
            for dy in (-1, 0, 1)
            for dx in (-1, 0, 1)
        ]
    )
    ok = z <= far * 1.01
    segs = []
    for k in range(len(edges)):
        for s in range(steps):
            if ok[k, s] and ok[k, s + 1]:
                segs.append([(x[k, s], y[k, s]), (x[k, s + 1], y[k, s + 1])])
    return segs


def toon(normal, depth):
    light = np.array([-0.4, 0.6, -0.7])
    light /= np.linalg.norm(light)
    d = np.clip(normal @ light, 0, 1)
    bands = np.select([d >= 0.7, d >= 0.35], [0.97, 0.85], 0.7)
    img = np.where(np.isinf(depth), 1.0, bands)
    return np.dstack([img * 0.98, img * 0.96, img])


def panel(ax, mesh, eye_dir, title, crease_angle=30.0, image_space=False):
    V, F = mesh
    eye, R, radius = camera(V, eye_dir)
    depth, normal = rasterise(V, F, eye, R, radius)
    ax.imshow(toon(normal, depth), extent=(0, SIZE, SIZE, 0), interpolation="nearest")
    if image_space:
        finite = np.where(np.isinf(depth), np.nan, depth)
        det = te.detect_edges(
            normal, depth / np.nanmax(finite), normal_threshold=1.2, depth_threshold=0.2
        )
        overlay = np.zeros((SIZE, SIZE, 4))
        overlay[det.mask] = (0.05, 0.05, 0.1, 1.0)
        ax.imshow(overlay, extent=(0, SIZE, SIZE, 0), interpolation="nearest")
    else:
        index = te.EdgeIndex(V, F, crease_angle=crease_angle)
        fe = index.features
        layers = [
            (fe.ridge, "#c0392b", "ridge"),
            (fe.valley, "#2e86c1", "valley"),
            (fe.boundary, "#27ae60", "boundary"),
            (index.silhouette(eye=eye), "black", "silhouette"),
        ]
        for edges, colour, label in layers:
            segs = visible_segments(V, edges, eye, R, radius, depth)
            ax.add_collection(
                LineCollection(segs, colors=colour, linewidths=1.0, label=label)
            )
        ax.legend(loc="lower left", fontsize=6, frameon=False, handlelength=1.2)
    ax.set_xlim(0, SIZE)
    ax.set_ylim(SIZE, 0)
    ax.set_title(title, fontsize=8)
    ax.axis("off")


def main():
    fig, axes = plt.subplots(1, 3, figsize=(7.5, 2.8), dpi=100, layout="constrained")
    part, teapot = fandisk(), tm.shapes.teapot()
    panel(axes[0], part, (1.0, 0.8, -1.4), "EdgeIndex: fandisk, crease_angle=30")
    panel(
        axes[1],
        teapot,
        (0.8, 0.9, 1.5),
        "EdgeIndex: teapot, crease_angle=60",
        crease_angle=60.0,
    )
    panel(
        axes[2], part, (1.0, 0.8, -1.4), "detect_edges: normal + depth", image_space=True
    )
    out = Path("edges.png")
    fig.savefig(out, dpi=100)
    print("wrote", out, out.stat().st_size // 1024, "KB")


if __name__ == "__main__":
    main()
