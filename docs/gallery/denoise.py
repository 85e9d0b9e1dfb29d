"""Denoising that keeps creases: bilateral and guided filtering.

The fandisk model (tests/data/meshes/fandisk.obj, 12,946 faces) with
Gaussian noise of 0.4 mean edge lengths along its normals, before and after each smoother, all
with their defaults, rendered with mesh outlines (silhouettes and creases, Kang et al.). Top row:
clean, noisy, Taubin; bottom row: pymeshlab's two-step smoothing, bilateral, guided; each panel gives
its mean face-normal error to the clean model. The outlines show what each smoother leaves of
the creases. Needs trimesh and pymeshlab.
"""

from pathlib import Path

import numpy as np
import pymeshlab
import trimesh
from PIL import Image, ImageDraw

import toonmesh as tm
from toonmesh.bench import parts

ROOT = Path(__file__).resolve().parents[2]  # the repository: its test meshes
SIZE = 320


def two_step(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(V, F))
    ms.apply_coord_two_steps_smoothing()
    return ms.current_mesh().vertex_matrix()


def main() -> None:
    m = trimesh.load(ROOT / "tests" / "data" / "meshes" / "fandisk.obj", process=False, force="mesh")
    V, F = np.asarray(m.vertices, np.float64), np.asarray(m.faces, np.int64)
    N = parts.noisy(V, F, 0.4, seed=1)
    panels = {
        "clean": V,
        "noisy": N,
        "taubin": tm.smooth.taubin(N, F),
        "pymeshlab two-step": two_step(N, F),
        "bilateral": tm.smooth.bilateral(N, F),
        "guided": tm.smooth.guided(N, F),
    }
    camera = tm.Camera.fit((-0.6, 0.5, 1.0))
    light = [tm.Light.directional((0.5, -0.6, -1.0))]
    images = []
    for label, X in panels.items():
        img = tm.render(X, F, camera=camera, lights=light, outlines="mesh", width=SIZE, height=SIZE,
                        supersample=2).color
        pil = Image.fromarray(img)
        if label != "clean":
            label += f": {parts.normal_error(X, F, V):.1f} deg"
        ImageDraw.Draw(pil).text((8, 8), label, fill=(0, 0, 0, 255))
        images.append(np.asarray(pil))
    out = Path("denoise.png")
    grid = np.concatenate([np.concatenate(images[:3], axis=1), np.concatenate(images[3:], axis=1)], axis=0)
    Image.fromarray(grid).save(out, optimize=True)
    print("wrote", out)


if __name__ == "__main__":
    main()
