"""Draws docs/contours.png: line drawings of the raw Stanford bunny, spot and the cow with face-edge
silhouettes (toonmesh.edges.silhouette), smooth contours (toonmesh.edges.contours) and
suggestive contours (toonmesh.edges.suggestive_contours), hidden lines removed with the small
z-buffer of docs/edges_figure.py. Needs matplotlib and trimesh. Run from the repository root:
``python docs/contours_figure.py``.
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from edges_figure import ROOT, SIZE, camera, plt, project, rasterise, trimesh  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

from toonmesh import edges as te  # noqa: E402


def visible_polyline_segments(lines, eye, R, radius, depth, step_px=0.5):
    """2-D pixel segments of the parts of 3-D polylines that pass the depth test, sampled about
    every half pixel."""
    segs = []
    for line in lines:
        x, y, z = project(line, eye, R, radius)
        for k in range(len(line) - 1):
            n = max(1, int(np.hypot(x[k + 1] - x[k], y[k + 1] - y[k]) / step_px))
            t = np.linspace(0, 1, n + 1)
            xs, ys, zs = x[k] + t * (x[k + 1] - x[k]), y[k] + t * (y[k + 1] - y[k]), z[k] + t * (z[k + 1] - z[k])
            xi, yi = np.clip(xs.astype(int), 0, SIZE - 1), np.clip(ys.astype(int), 0, SIZE - 1)
            far = np.maximum.reduce(
                [depth[np.clip(yi + dy, 0, SIZE - 1), np.clip(xi + dx, 0, SIZE - 1)] for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
            )
            ok = zs <= far * 1.005
            segs += [[(xs[i], ys[i]), (xs[i + 1], ys[i + 1])] for i in range(n) if ok[i] and ok[i + 1]]
    return segs


def draw(ax, segs, colour, title):
    ax.add_collection(LineCollection(segs, colors=colour, linewidths=0.8))
    ax.set_xlim(0, SIZE)
    ax.set_ylim(SIZE, 0)
    ax.set_title(title, fontsize=7)
    ax.axis("off")


def row(axes, name, eye_dir, up=(0.0, 1.0, 0.0), threshold=0.01):
    mesh = trimesh.load(ROOT / "tests" / "data" / "meshes" / name, process=False, force="mesh")
    V, F = np.asarray(mesh.vertices, float), np.asarray(mesh.faces)
    eye, R, radius = camera(V, eye_dir, up=up)
    depth, _ = rasterise(V, F, eye, R, radius)
    faces_rule = [V[c] for c in te.chains(te.silhouette(V, F, eye=eye, weld=True))]
    smooth = te.contours(V, F, eye=eye, weld=True)
    suggestive = te.suggestive_contours(V, F, eye=eye, weld=True, threshold=threshold)
    short = lambda lines: sum(np.linalg.norm(np.diff(l, axis=0), axis=1).sum() < 0.02 * radius for l in lines)  # noqa: E731
    draw(axes[0], visible_polyline_segments(faces_rule, eye, R, radius, depth), "black",
         f"silhouette(): {len(faces_rule)} chains, {short(faces_rule)} tiny")
    draw(axes[1], visible_polyline_segments(smooth, eye, R, radius, depth), "black",
         f"contours(): {len(smooth)} chains, {short(smooth)} tiny")
    draw(axes[2], visible_polyline_segments(smooth, eye, R, radius, depth), "black", "")
    draw(axes[2], visible_polyline_segments(suggestive, eye, R, radius, depth), "#2e5fa8",
         f"+ suggestive_contours(threshold={threshold:g}): {len(suggestive)}")


def main():
    fig, axes = plt.subplots(3, 3, figsize=(7.5, 7.8), dpi=100, layout="constrained")
    # the raw scan's curvature is noisy: only the strongest suggestive contours
    row(axes[0], "stanford-bunny.obj", (0.3, 0.1, 1.0), threshold=0.3)
    row(axes[1], "spot.obj", (1.0, 0.35, 0.9))
    row(axes[2], "cow.obj", (0.9, 0.3, 1.0))
    out = ROOT / "docs" / "contours.png"
    fig.savefig(out, dpi=100)
    print(out.relative_to(ROOT), out.stat().st_size // 1024, "KB")


if __name__ == "__main__":
    main()
