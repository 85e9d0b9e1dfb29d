"""Rendering: every argument is checked, with an exception that names it."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core

V, F = _core.icosphere(1, 0.0, 0)


def render(**kw):
    kw.setdefault("width", 8)
    kw.setdefault("height", 8)
    v = kw.pop("V", V)
    f = kw.pop("F", F)
    return tm.render(v, f, **kw)


@pytest.mark.parametrize(
    "kw, exc, match",
    [
        (dict(V=V[:, :2]), ValueError, "vertices"),
        (dict(V=V.astype(np.int64)), TypeError, "vertices"),
        (dict(V=np.where(np.arange(len(V))[:, None] == 3, np.nan, V)), ValueError, "vertices.*finite"),
        (dict(V=np.zeros((0, 3))), ValueError, "vertices"),
        (dict(F=F[:, :2]), ValueError, "faces"),
        (dict(F=F.astype(np.float32)), TypeError, "faces"),
        (dict(F=F + len(V)), IndexError, "faces"),
        (dict(F=F - 1), IndexError, "faces"),
        (dict(width=0), ValueError, "width"),
        (dict(height=-3), ValueError, "height"),
        (dict(width=1_000_000), ValueError, "width.*limit"),
        (dict(width=2**63), ValueError, "width"),
        (dict(width=12000, height=12000, supersample=2), ValueError, "supersample"),
        (dict(width=2.5), TypeError, "width.*integer.*float"),
        (dict(width=None), TypeError, "width.*integer"),
        (dict(width="64"), TypeError, "width.*integer.*str"),
        (dict(width=True), TypeError, "width.*integer.*bool"),
        (dict(msaa=4.0), TypeError, "msaa.*integer.*float"),
        (dict(msaa=2), ValueError, "msaa"),
        (dict(supersample=0), ValueError, "supersample"),
        (dict(outputs=("colour",)), ValueError, "outputs"),
        (dict(outputs=()), ValueError, "outputs"),
        (dict(outputs=5), TypeError, "outputs"),
        (dict(outputs=("color", 3)), TypeError, "outputs"),
        (dict(outputs=("outline",)), ValueError, "outputs.*outline.*needs outlines"),
        (dict(outputs=("lines",), outlines="image"), ValueError, "outputs.*lines.*mesh"),
        (dict(background=(1, 1)), ValueError, "background"),
        (dict(background=(2, 0, 0)), ValueError, "background"),
        (dict(background="white"), ValueError, "background"),
        (dict(background=(np.nan, 0, 0)), ValueError, "background"),
        (dict(ambient=(np.nan, 0, 0)), ValueError, "ambient"),
        (dict(ambient=(255, 255, 255)), ValueError, "ambient.*255"),
        (dict(material="bands"), TypeError, "material"),
        (dict(normals="bumpy"), ValueError, "normals"),
        (dict(transform=np.zeros((4, 4))), ValueError, "transform"),
        (dict(transform=np.eye(3)), ValueError, "transform"),
        (dict(transform=np.full((4, 4), np.inf)), ValueError, "transform"),
        (dict(camera="front"), TypeError, "camera"),
        (dict(lights=[tm.Light.key()] * 9), ValueError, "lights"),
        (dict(lights=["sun"]), TypeError, "lights\\[0\\]"),
        (dict(lights="sun"), TypeError, "lights"),
        (dict(outlines="ink"), ValueError, "outlines"),
        (dict(outlines=1), TypeError, "outlines"),
        (dict(smooth_iterations=1.5), TypeError, "smooth_iterations"),
        (dict(backend="metal"), ValueError, "backend"),
    ],
)
def test_bad_arguments_raise_naming_the_argument(kw, exc, match):
    with pytest.raises(exc, match=match):
        render(**kw)


def test_forms_that_are_accepted():
    # a single light, a hex background, NumPy scalars, outputs=None (the default)
    a = render(lights=tm.Light.key(), background="#ffffff", width=np.int64(8), msaa=np.int32(1), outputs=None)
    b = render(lights=[tm.Light.key()], background=(1.0, 1.0, 1.0, 1.0))
    assert np.array_equal(a.color, b.color)
    assert render(background="#00000000").color[0, 0, 3] == 0


@pytest.mark.parametrize(
    "make, match, exc",
    [
        (lambda: tm.Light.directional((0, 0, 0)), "direction", ValueError),
        (lambda: tm.Light.directional((np.nan, 0, 1)), "direction", ValueError),
        (lambda: tm.Light.directional((0, 0)), "direction", ValueError),
        (lambda: tm.Light.point((0, 0, 0), space="screen"), "space", ValueError),
        (lambda: tm.Light.point((0, 0, 1), intensity=-1.0), "intensity", ValueError),
        (lambda: tm.Light.point((0, 0, 1), intensity=True), "intensity", TypeError),
        (lambda: tm.Material.bands("#12"), "color", ValueError),
        (lambda: tm.Material.bands((255, 128, 0)), "color.*255", ValueError),
        (lambda: tm.Material.lambert((1, -1, 0)), "color", ValueError),
        (lambda: tm.Material.lambert(per_vertex="no"), "per_vertex.*bool", TypeError),
        (lambda: tm.Material.lambert(per_vertex=1), "per_vertex.*bool", TypeError),
        (lambda: tm.Material.thresholded_phong(highlight="phong"), "highlight", ValueError),
        (lambda: tm.Material.thresholded_phong(t_h=2.0), "t_h", ValueError),
        (lambda: tm.Material.thresholded_phong(t_h=np.nan), "t_h", ValueError),
        (lambda: tm.Material.thresholded_phong(t_h="0.5"), "t_h.*number", TypeError),
        (lambda: tm.Material.phong(shininess=0), "shininess", ValueError),
        (lambda: tm.Material.bands(thresholds=(0.5, 0.2), values=(0, 1, 2)), "thresholds", ValueError),
        (lambda: tm.Material.bands(values=(0, 1)), "values", ValueError),
        (lambda: tm.Material.bands(thresholds="0.5"), "thresholds", TypeError),
        (lambda: tm.Material.lut(np.ones((300,))), "table", ValueError),
        (lambda: tm.Material.lut([[1, 2]]), "table", ValueError),
        (lambda: tm.Camera.look_at((0, 0)), "eye", ValueError),
        (lambda: tm.Camera.look_at((0, 0, 5), up=(0, 0, 1)), "up.*parallel", ValueError),
        (lambda: tm.Camera.look_at((0, 0, 5), fov_y=0), "fov_y", ValueError),
        (lambda: tm.Camera.look_at((0, 0, 5), near=2.0, far=1.0), "far", ValueError),
        (lambda: tm.Camera.orthographic((0, 0, 5), height=-1), "height", ValueError),
        (lambda: tm.Camera.fit(margin=np.nan), "margin", ValueError),
        (lambda: tm.Camera.fit(orthographic="yes"), "orthographic", TypeError),
        (lambda: tm.Outlines("ink"), "kind", ValueError),
        (lambda: tm.Outlines(width=0), "width", ValueError),
        (lambda: tm.Outlines(width=np.nan), "width", ValueError),
        (lambda: tm.Outlines(silhouette=tm.LineStyle(width=-1)), "width", ValueError),
        (lambda: tm.Outlines(crease="thick"), "crease", ValueError),
        (lambda: tm.Outlines(crease=3), "crease", TypeError),
        (lambda: tm.Outlines(crease_angle=200), "crease_angle", ValueError),
        (lambda: tm.Outlines(crease_angle=None, weld="no"), "weld.*bool", TypeError),
        (lambda: tm.Outlines(depth_threshold=np.nan), "depth_threshold", ValueError),
        (lambda: tm.Outlines(normal_threshold=-1), "normal_threshold", ValueError),
        (lambda: tm.Outlines(depth_offset=np.inf), "depth_offset", ValueError),
        (lambda: tm.LineStyle(color=(2, 0, 0)), "color", ValueError),
    ],
)
def test_constructors_check_their_arguments(make, match, exc):
    with pytest.raises(exc, match=match):
        make()


def test_the_core_refuses_bad_items_given_directly():
    r = _core.Renderer()
    mesh = r.add_mesh(V, F)
    frame = dict(width=4, height=4, msaa=1, supersample=1)
    with pytest.raises(TypeError, match="meshes\\[0\\].material"):
        r.render([(mesh, {"model": "cel"}, None)], **frame)
    with pytest.raises(TypeError, match="meshes\\[0\\]"):
        r.render([mesh], **frame)
    with pytest.raises(ValueError, match="mesh"):
        r.render([(mesh + 99, None, None)], **frame)
    with pytest.raises(ValueError, match="normals"):
        r.add_mesh(V, F, "wobbly")
    # the next call works
    assert r.render([(mesh, None, None)], **frame)["color"].shape == (4, 4, 4)


def test_missing_gpu_raises_gpu_unavailable_with_instructions():
    env = dict(os.environ, TOONMESH_BACKEND="vulkan", VK_ICD_FILENAMES="/nonexistent.json", VK_DRIVER_FILES="/nonexistent.json")
    code = (
        "import toonmesh as tm\n"
        "try:\n    tm.gpu_info()\nexcept tm.GpuUnavailableError as e:\n    print('UNAVAILABLE', e)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120)
    assert "UNAVAILABLE" in out.stdout, out.stdout + out.stderr
    assert "mesa-vulkan-drivers" in out.stdout and "TOONMESH_BACKEND" in out.stdout


def test_environment_variable_picks_the_backend():
    env = dict(os.environ, TOONMESH_BACKEND="gl")
    out = subprocess.run([sys.executable, "-c", "import toonmesh as tm; print(tm.gpu_info()['backend'])"],
                         env=env, capture_output=True, text=True, timeout=120)
    assert out.stdout.strip() == "gl", out.stderr
    env["TOONMESH_BACKEND"] = "nope"
    out = subprocess.run([sys.executable, "-c", "import toonmesh as tm; tm.gpu_info()"], env=env, capture_output=True, text=True, timeout=120)
    assert "TOONMESH_BACKEND" in out.stderr


def test_a_camera_looking_at_its_own_eye_is_refused_when_made():
    for make in (tm.Camera.look_at, tm.Camera.orthographic):
        with pytest.raises(ValueError, match=r"target: must differ from .*eye"):
            make(eye=(1, 2, 3), target=(1, 2, 3))
    assert tm.Camera.look_at(eye=(0, 0, 1)).target == (0.0, 0.0, 0.0)
