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
from PIL import Image

import toonmesh as tm
from toonmesh.batch import render_files
from toonmesh.figures import panels

if __name__ == "__main__":
    os.makedirs("meshes", exist_ok=True)
    paths = []
    for seed in range(3):
        V, F = tm.shapes.icosphere(4, noise=0.1, seed=seed)
        paths.append(f"meshes/blob{seed}.ply")
        trimesh.Trimesh(V, F, process=False).export(paths[-1])

    with (
        LocalCluster(n_workers=2, threads_per_worker=1) as cluster,
        Client(cluster) as client,
    ):
        rows = render_files(
            paths,
            "frames",
            views=4,
            client=client,
            up="y",
            width=160,
            height=160,
            material=tm.Material.thresholded_phong("#3c8af0"),
            outlines="mesh",
        )
    print(len(rows), "images, on workers", sorted({row["worker"] for row in rows}))
    ordered = sorted(
        rows, key=lambda row: (paths.index(row["mesh"]), row["path"])
    )  # one row a mesh
    images = [np.asarray(Image.open(row["path"])) for row in ordered]
    labels = [os.path.basename(row["path"]) for row in ordered]
    Image.fromarray(panels(images, labels, columns=4)).save("batch.png")
