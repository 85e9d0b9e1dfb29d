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


# Each argument against bad values of its kind: tests/test_bad_arguments.py. Here: arguments
# refused together, and messages that must say why.
@pytest.mark.parametrize(
    "kw, exc, match",
    [
        (dict(width=1_000_000), ValueError, "width.*limit"),
        (dict(width=12000, height=12000, supersample=2), ValueError, "supersample"),
        (dict(outputs=("outline",)), ValueError, "outputs.*outline.*needs outlines"),
        (dict(outputs=("lines",), outlines="image"), ValueError, "outputs.*lines.*mesh"),
    ],
)
def test_refusals_say_why(kw, exc, match):
    with pytest.raises(exc, match=match):
        render(**kw)


def test_forms_that_are_accepted():
    # a single light, a hex background, NumPy scalars, outputs=None (the default)
    a = render(lights=tm.Light.key(), background="#ffffff", width=np.int64(8), msaa=np.int32(1), outputs=None)
    b = render(lights=[tm.Light.key()], background=(1.0, 1.0, 1.0, 1.0))
    assert np.array_equal(a.color, b.color)
    assert render(background="#00000000").color[0, 0, 3] == 0


def test_near_and_far_are_checked_together():
    with pytest.raises(ValueError, match="far"):
        tm.Camera.look_at((0, 0, 5), near=2.0, far=1.0)


def test_the_core_refuses_bad_items_given_directly():
    r = _core.Renderer()
    mesh, normals, notes = r.add_mesh(V, F, "smooth")
    assert notes == []  # nothing to warn about
    assert normals == "smooth"
    frame = tm.RenderOptions(width=4, height=4)
    with pytest.raises(TypeError, match="meshes\\[0\\].material"):
        r.render([(mesh, {"model": "cel"}, None, None)], frame)
    with pytest.raises(TypeError, match="meshes\\[0\\]"):
        r.render([mesh], frame)
    with pytest.raises(ValueError, match="mesh"):
        r.render([(mesh + 99, None, None, None)], frame)
    with pytest.raises(ValueError, match="^meshes\\[0\\].up: "):
        r.render([(mesh, None, None, "w")], frame)
    with pytest.raises(ValueError, match="normals"):
        r.add_mesh(V, F, "wobbly")
    # the next call works
    images, (report,) = r.render([(mesh, None, None, None)], frame)
    assert images["color"].shape == (4, 4, 4) and report["width"] == 4 and report["up"] == "y"


def test_a_misspelt_option_is_refused_naming_it_with_a_hint():
    with pytest.raises(TypeError, match="widht: not a render option; did you mean 'width'"):
        render(widht=3)
    with pytest.raises(TypeError, match="colour: not a render option"):
        tm.Renderer().render(None, colour="#ffffff")


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
