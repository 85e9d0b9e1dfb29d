"""Batch rendering on a Dask cluster gives the sequential images, and what users send to workers
(materials, cameras, lights) survives pickling."""

from __future__ import annotations

import os
import pickle

import numpy as np
import pytest

import toonmesh as tm
from conftest import MESHES, need
from toonmesh.batch import render_file, render_files


def _scene_objects():
    return dict(
        material=tm.Material.thresholded_phong("#3c8af0", t_h=0.1, highlight="paper", per_vertex=True),
        camera=tm.Camera.look_at((0.4, 0.3, 2.5), (0.0, 0.1, 0.0), up=(0, 1, 0), fov_y=30),
        lights=[tm.Light.directional((-1, -1, -1), color="#ffeedd", intensity=0.8),
                tm.Light.point((0, 2, 1), intensity=0.4, space="camera")],
    )


@pytest.mark.parametrize("material", [
    tm.Material.bands("#f08a3c", thresholds=(0.3, 0.6), values=(0.2, 0.6, 1.0)),
    tm.Material.lut(np.linspace(0.2, 1.0, 8)),
    tm.Material.phong(shininess=12),
    tm.Material.lambert("#888888"),
])
def test_materials_cameras_and_lights_pickle_and_render_the_same(material):
    V, F = tm.shapes.icosphere(3, noise=0.05, seed=2)
    objects = dict(_scene_objects(), material=material)
    for cam in (objects["camera"], tm.Camera.fit((0, 1, 1), up=(0, 0, 1), orthographic=True),
                tm.Camera.orthographic((0, 0, 3), height=2.5)):
        sent = pickle.loads(pickle.dumps(dict(objects, camera=cam), protocol=pickle.HIGHEST_PROTOCOL))
        before = tm.render(V, F, width=48, height=40, **dict(objects, camera=cam)).color
        after = tm.render(V, F, width=48, height=40, **sent).color
        assert np.array_equal(before, after)


@pytest.fixture(scope="module")
def cluster_client():
    """A local cluster of 2 worker processes, one thread each (what render_files starts itself
    when no client is given), shared by the tests below."""
    need("dask.distributed")
    from dask.distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    yield client
    client.close()
    cluster.close()


def test_cluster_renders_the_sequential_images(tmp_path, cluster_client):
    need("trimesh")
    paths = [str(MESHES / f"{name}.obj") for name in ("spot", "fandisk", "suzanne")]
    options = dict(views=3, width=64, height=48, up="y", **_scene_objects())
    options.pop("camera")  # a turntable: one fit camera per view
    sequential = [row for p in paths for row in render_file(p, str(tmp_path / "seq"), **options)]
    rows = render_files(paths, str(tmp_path / "dask"), client=cluster_client, **options)
    assert [(r["mesh"], r["view"]) for r in rows] == [(p, k) for p in paths for k in range(3)]
    assert len({r["worker"] for r in rows}) >= 1 and all(r["render_s"] > 0 for r in rows)
    for a, b in zip(sequential, rows):
        assert os.path.basename(a["path"]) == os.path.basename(b["path"])
        with open(a["path"], "rb") as fa, open(b["path"], "rb") as fb:
            assert fa.read() == fb.read(), b["path"]  # the same image bits
    assert len(os.listdir(tmp_path / "dask")) == 9


def test_cluster_writes_npz_for_float_outputs_and_reports_errors(tmp_path, cluster_client):
    need("trimesh")
    rows = render_files([str(MESHES / "spot.obj")], str(tmp_path), client=cluster_client, width=32, height=24,
                        outputs=("color", "depth"), smooth_iterations=2, smooth_method="taubin")
    assert [os.path.basename(r["path"]) for r in rows] == ["spot.npz"]
    with np.load(rows[0]["path"]) as z:
        assert z["depth"].shape == (24, 32) and z["color"].shape == (24, 32, 4)
    with pytest.raises(FileNotFoundError, match="nothere.obj"):
        render_files([str(tmp_path / "nothere.obj")], str(tmp_path), client=cluster_client)
    with pytest.raises(ValueError, match="same images"):
        render_files([str(MESHES / "spot.obj"), str(tmp_path / "spot.obj")], str(tmp_path), client=cluster_client)
