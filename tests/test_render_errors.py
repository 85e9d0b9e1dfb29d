"""Rendering: every argument is checked, with an exception that names it."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core


def _camera_bypassing_checks(**fields):
    """A camera with fields the Python constructors refuse, to test the core's own checks."""
    cam = tm.Camera.look_at(eye=(0, 0, 1))
    for k, v in fields.items():
        object.__setattr__(cam, k, v)
    return cam

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
        (dict(width=12000, height=12000, supersample=2), ValueError, "supersample"),
        (dict(width=2.5), TypeError, "width"),
        (dict(msaa=2), ValueError, "msaa"),
        (dict(supersample=0), ValueError, "supersample"),
        (dict(outputs=("colour",)), ValueError, "outputs"),
        (dict(outputs=()), ValueError, "outputs"),
        (dict(background=(1, 1)), ValueError, "background"),
        (dict(background=(2, 0, 0)), ValueError, "background"),
        (dict(ambient=(np.nan, 0, 0)), ValueError, "ambient"),
        (dict(material="bands"), TypeError, "material"),
        (dict(normals="bumpy"), ValueError, "normals"),
        (dict(transform=np.zeros((4, 4))), ValueError, "transform"),
        (dict(transform=np.eye(3)), ValueError, "transform"),
        (dict(transform=np.full((4, 4), np.inf)), ValueError, "transform"),
        (dict(camera=_camera_bypassing_checks(eye=(0.0, 0.0, 5.0), target=(0.0, 0.0, 5.0))), ValueError, "camera.target"),
        (dict(camera=tm.Camera.look_at((0, 0, 5), up=(0, 0, 1))), ValueError, "camera.up"),
        (dict(camera=tm.Camera.look_at((0, 0, 5), fov_y=0)), ValueError, "fov_y"),
        (dict(camera=tm.Camera.look_at((0, 0, 5), near=2.0, far=1.0)), ValueError, "camera.far"),
        (dict(camera=tm.Camera.orthographic((0, 0, 5), height=-1)), ValueError, "camera.height"),
        (dict(camera="front"), TypeError, "camera"),
        (dict(lights=[tm.Light.key()] * 9), ValueError, "lights"),
        (dict(lights=["sun"]), TypeError, "lights"),
        (dict(lights=[tm.Light("directional", direction=(0.0, 0.0, 0.0))]), ValueError, "lights\\[0\\].direction"),
        (dict(lights=[tm.Light("directional", direction=(np.nan, 0.0, 1.0))]), ValueError, "lights\\[0\\].direction"),
        (dict(lights=[tm.Light("point", position=(0.0, 0.0, 1.0), intensity=-1.0)]), ValueError, "intensity"),
        (dict(material=tm.Material.bands(thresholds=(0.5, 0.2), values=(0, 1, 2))), ValueError, "thresholds"),
        (dict(material=tm.Material.bands(values=(0, 1))), ValueError, "values"),
        (dict(material=tm.Material.thresholded_phong(t_h=2.0)), ValueError, "t_h"),
        (dict(material=tm.Material.phong(shininess=0)), ValueError, "shininess"),
        (dict(smooth_iterations=1.5), TypeError, "smooth_iterations"),
        (dict(backend="metal"), ValueError, "backend"),
    ],
)
def test_bad_arguments_raise_naming_the_argument(kw, exc, match):
    with pytest.raises(exc, match=match):
        render(**kw)


def test_constructors_check_their_arguments():
    with pytest.raises(ValueError, match="direction"):
        tm.Light.directional((0, 0, 0))
    with pytest.raises(ValueError, match="direction"):
        tm.Light.directional((np.nan, 0, 1))
    with pytest.raises(ValueError, match="space"):
        tm.Light.point((0, 0, 0), space="screen")
    with pytest.raises(ValueError, match="color"):
        tm.Material.bands("#12")
    with pytest.raises(ValueError, match="color"):
        tm.Material.lambert((1, -1, 0))
    with pytest.raises(ValueError, match="highlight"):
        tm.Material.thresholded_phong(highlight="phong")
    with pytest.raises(ValueError, match="table"):
        tm.Material.lut(np.ones((300,)))
    with pytest.raises(ValueError, match="eye"):
        tm.Camera.look_at((0, 0))


def test_the_core_refuses_bad_values_given_directly():
    r = _core.Renderer()
    mesh = r.add_mesh(V, F)
    with pytest.raises(ValueError, match="lights\\[0\\].direction"):
        r.render([(mesh, {}, None)], lights=[{"kind": "directional", "direction": (0, 0, 0)}])
    with pytest.raises(ValueError, match="model"):
        r.render([(mesh, {"model": "cel"}, None)])
    with pytest.raises(ValueError, match="mesh"):
        r.render([(mesh + 99, {}, None)])
    with pytest.raises(ValueError, match="normals"):
        r.add_mesh(V, F, "wobbly")


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
        with pytest.raises(ValueError, match=r"target: must differ from eye"):
            make(eye=(1, 2, 3), target=(1, 2, 3))
    assert tm.Camera.look_at(eye=(0, 0, 1)).target == (0.0, 0.0, 0.0)
