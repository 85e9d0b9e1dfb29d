"""Line drawings and SVG: contours and suggestive contours.

Line drawings by the renderer of the raw Stanford
bunny, the cow (``toonmesh.data``) and the teapot (``toonmesh.shapes``), with Kang et al.'s face-edge silhouettes (``contours="faces"``), the
default (smooth contours between creases) and the default plus suggestive contours (in blue),
hidden lines removed; each panel's title counts its strokes. The SVG is the bunny's last panel as
``RenderResult.save_svg`` writes it. Needs matplotlib (``pip install matplotlib``).
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import toonmesh as tm  # noqa: E402
from toonmesh.data import bunny, cow  # noqa: E402

SIZE = 360
BLUE = (0.18, 0.37, 0.66)
# white paper: one band, so only the ink shows
PAPER = tm.Material.bands("#ffffff", thresholds=(2.0,), values=(1.0, 1.0))
SETTINGS = [
    ("contours='faces' (Kang et al.)", dict(contours="faces")),
    ("default: smooth contours", dict()),
    ("+ suggestive=True", dict(suggestive=tm.LineStyle(color=BLUE, width=1.2))),
]


def panel(r, mesh, camera, kw):
    """The drawing as an RGB image (ink over white) and its strokes by kind."""
    res = r.render(
        mesh,
        camera=camera,
        width=SIZE,
        height=SIZE,
        outlines=tm.Outlines("mesh", **kw),
        material=PAPER,
        outputs=("color", "lines"),
    )
    kinds = {k: sum(1 for x in res.line_kinds if x == k) for k in set(res.line_kinds)}
    return res, kinds


def main():
    rows = [
        (bunny(), (0.35, 0.3, 1.0), "the raw Stanford bunny"),
        (tm.shapes.teapot(12), (0.25, 0.5, 1.0), "the teapot"),
        (cow(), (0.9, 0.3, 1.0), "the cow"),
    ]
    fig, axes = plt.subplots(
        len(rows), len(SETTINGS), figsize=(7.8, 7.8), dpi=100, layout="constrained"
    )
    r = tm.Renderer()
    for ((V, F), eye, label), ax_row in zip(rows, axes):
        mesh = r.add_mesh(V, F)
        camera = tm.Camera.fit(eye)
        for (title, kw), ax in zip(SETTINGS, ax_row):
            res, kinds = panel(r, mesh, camera, kw)
            ax.imshow(res.color[..., :3])
            counts = ", ".join(f"{n} {k}" for k, n in sorted(kinds.items()))
            ax.set_title(f"{label}: {title}\n{counts}", fontsize=6)
            ax.axis("off")
            if label == rows[0][2] and kw.get("suggestive"):
                res.save_svg("contours.svg")
        r.remove_mesh(mesh)
    out = Path("contours.png")
    fig.savefig(out, dpi=100)
    print("wrote", out, out.stat().st_size // 1024, "KB")


if __name__ == "__main__":
    main()
