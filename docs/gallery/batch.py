"""Batch rendering on a Dask cluster.

``toonmesh.batch.render_files`` renders many mesh files and views on a Dask cluster, one task a
mesh: here three noisy blobs, four views each, on a local cluster of two worker processes, put
together as a contact sheet (one row a mesh). Pointed at a remote scheduler
(``Client("tcp://scheduler:8786")``) it runs the same way across machines. Needs Dask and trimesh (``pip install 'toonmesh[batch]'``).
"""

import os

import numpy as np
import trimesh
from dask.distributed import Client, LocalCluster
from PIL import Image, ImageDraw, ImageFont

import toonmesh as tm
from toonmesh.batch import render_files

def label(image: np.ndarray, text: str) -> np.ndarray:
    """``image`` (H, W, 3 or 4) uint8 with ``text`` on a white box at its top left."""
    pil = Image.fromarray(image)
    draw = ImageDraw.Draw(pil)
    font = ImageFont.load_default(size=13)
    box = draw.textbbox((6, 4), text, font=font)
    draw.rectangle((box[0] - 3, box[1] - 2, box[2] + 3, box[3] + 2), fill="white")
    draw.text((6, 4), text, font=font, fill="black")
    return np.asarray(pil)


if __name__ == "__main__":
    os.makedirs("meshes", exist_ok=True)
    paths = []
    for seed in range(3):
        V, F = tm.shapes.icosphere(4, noise=0.1, seed=seed)
        paths.append(f"meshes/blob{seed}.ply")
        trimesh.Trimesh(V, F, process=False).export(paths[-1])

    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        rows = render_files(paths, "frames", views=4, client=client, up="y", width=160, height=160,
                            material=tm.Material.thresholded_phong("#3c8af0"), outlines="mesh")
    print(len(rows), "images, on workers", sorted({row["worker"] for row in rows}))
    sheet = [[label(np.asarray(Image.open(row["path"])), os.path.basename(row["path"])) for row in rows
              if row["mesh"] == path] for path in paths]
    Image.fromarray(np.concatenate([np.concatenate(r, axis=1) for r in sheet], axis=0)).save("batch.png")
