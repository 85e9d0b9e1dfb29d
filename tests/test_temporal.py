"""toonmesh.testing.temporal_popping: ink carried with its surface from frame to frame, and what
pops. A real turntable holds its lines (they move with the surface), the same ink left where it
was does not, ink moved past the radius pops, points the next frame cannot see are not counted,
and the benchmark prints the figure."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.bench._freestyle import CLIP_MARGIN, blender_camera, write_obj
from toonmesh.bench.temporal import turntable
from toonmesh.data import bunny
from toonmesh.testing import POPPING_PIXELS, temporal_popping

SIZE = 256


@pytest.fixture(scope="module")
def frames():
    V, F = bunny()
    return list(tm.Renderer().render_many(tm.Mesh(V, F), turntable(V, 3), width=SIZE, height=SIZE,
                                           outlines=tm.Outlines("mesh"), outputs=("outline", "depth")))


def as_tuple(frame, ink=None, depth=None):
    return (frame.outline if ink is None else ink, frame.depth if depth is None else depth,
            frame.view_matrix, frame.projection)


def test_a_turntable_keeps_its_lines_where_its_surface_went(frames):
    p = temporal_popping(frames)
    assert p.counted.shape == (3,) and (p.counted > 0.5 * (frames[0].outline >= 0.5).sum()).all()
    assert p.share < 0.002 and p.appearing < 0.01, p



def test_reprojection_is_exact_where_the_lines_cannot_change():
    # the camera turns about its own eye: every line stays on its surface, but the image slides
    # by about 25 pixels, so only ink carried through depth and cameras finds itself
    V, F = bunny()
    eye = np.asarray(turntable(V, 0)[0].eye)
    centre = 0.5 * (V.min(axis=0) + V.max(axis=0))
    a = np.radians(4.0)
    rot = np.array([[np.cos(a), 0.0, np.sin(a)], [0.0, 1.0, 0.0], [-np.sin(a), 0.0, np.cos(a)]])
    cams = [tm.Camera.look_at(tuple(eye), target=tuple(eye + m @ (centre - eye)), up=(0, 1, 0), fov_y=40)
            for m in (np.eye(3), rot)]
    pan = tm.Renderer().render_many(tm.Mesh(V, F), cams, width=SIZE, height=SIZE, outlines=tm.Outlines("mesh"),
                                    outputs=("outline", "depth"))
    assert temporal_popping(pan).share < 0.002
    assert temporal_popping([pan[0], as_tuple(pan[1], ink=pan[0].outline)]).share > 0.5


def test_a_still_camera_pops_nothing_and_ink_moved_past_the_radius_pops(frames):
    f = frames[0]
    still = temporal_popping([f, f])
    assert still.share == 0 and still.popped.tolist() == [0] and still.counted[0] > 100
    ink = f.outline >= 0.5
    ink[:4], ink[-4:], ink[:, :4], ink[:, -4:] = False, False, False, False  # the bunny touches the edges
    for shift, popped in ((1, False), (int(POPPING_PIXELS) + 2, True)):
        moved = np.zeros_like(ink)
        moved[:-shift, :-shift] = ink[shift:, shift:]
        p = temporal_popping([as_tuple(f, ink=ink), as_tuple(f, ink=moved)])
        # ink on a line along the shift may still find itself: most of it pops, not all
        assert (p.share > 0.5) if popped else (p.share == 0), (shift, p)


def test_points_the_next_frame_does_not_see_are_not_counted(frames):
    f = frames[0]
    # a surface in front of everything the first frame drew: nothing of it is seen
    covered = np.where(np.isfinite(f.depth), 0.5 * f.depth, f.depth)
    p = temporal_popping([as_tuple(f), as_tuple(f, ink=np.zeros_like(f.outline), depth=covered)])
    assert p.counted[0] < 0.02 * (f.outline >= 0.5).sum() and p.share <= 1.0
    # the same, with the ink gone but the surface seen: every counted pixel pops
    gone = temporal_popping([as_tuple(f), as_tuple(f, ink=np.zeros_like(f.outline))])
    assert gone.share == 1.0 and gone.counted[0] > 100
    # where it popped: every place is an ink pixel of the frame it leaves
    rows, cols = gone.where[0].T
    assert len(rows) == gone.popped[0] and (f.outline[rows, cols] >= 0.5).all()


def test_bad_frames_are_named(frames):
    f = frames[0]
    with pytest.raises(ValueError, match=r"frames: need at least 2"):
        temporal_popping([f])
    with pytest.raises(TypeError, match=r"frames\[1\]: expected a toonmesh.RenderResult"):
        temporal_popping([f, "frame"])
    no_outline = tm.render(tm.Mesh(*bunny()), width=32, height=32, outputs=("depth",))
    with pytest.raises(ValueError, match=r"frames\[0\]: has no 'outline' image"):
        temporal_popping([no_outline, f])
    nan = f.depth.copy()
    nan[0, 0] = np.nan
    with pytest.raises(ValueError, match=r"frames\[1\]: depth has NaN"):
        temporal_popping([f, as_tuple(f, depth=nan)])
    with pytest.raises(ValueError, match=r"frames\[1\]: ink and depth must be \(H, W\) images of one shape"):
        temporal_popping([f, as_tuple(f, ink=f.outline[:10])])
    with pytest.raises(ValueError, match=r"pixels: must be a finite number in \[0, 64\]"):
        temporal_popping(frames, pixels=-1)
    with pytest.raises(ValueError, match=r"ink: must be a finite number in \(0, 1\]"):
        temporal_popping(frames, ink=0)
    assert np.isfinite(f.outline).all()  # never modified: the frames are used above unchanged


def test_the_benchmark_prints_the_figure():
    # without Blender on PATH: its peer is optional, and the test must not need it
    path = os.pathsep.join(d for d in os.environ.get("PATH", "").split(os.pathsep)
                           if not os.path.exists(os.path.join(d, "blender")))
    r = subprocess.run([sys.executable, "-m", "toonmesh.bench", "temporal", "--quick"], capture_output=True,
                       text=True, timeout=600, env=dict(os.environ, PATH=path))
    assert r.returncode == 0, r.stderr
    rows = {line.split("|")[1].strip(): line for line in r.stdout.splitlines() if line.startswith("| mesh")}
    assert set(rows) == {"mesh lines", "mesh lines + suggestive", "mesh lines + suggestive, each view alone"}, r.stdout
    assert "Popping per 1-degree step" in r.stdout and "%" in rows["mesh lines"]
    assert "| Freestyle: not installed" in r.stdout, r.stdout


def test_freestyle_camera_puts_a_point_where_toonmesh_does():
    # Blender's camera looks down its local -z, +y up; with the sensor fit vertical its frame's
    # half height at unit distance is tan(fov_y / 2) and its half width that times the aspect
    V, F = bunny()
    camera = tm.Camera.look_at((0.3, 0.2, 0.4), target=(0, 0.1, 0), fov_y=40, near=0.1, far=3.0)
    r = tm.render(tm.Mesh(V, F), width=96, height=64, camera=camera, outputs=("depth",))
    blender = blender_camera(r.view_matrix, r.projection)
    to_world = np.array(blender["matrix"])
    assert np.allclose(to_world[:3, :3].T @ to_world[:3, :3], np.eye(3)) and np.isclose(np.linalg.det(to_world), 1)
    assert np.isclose(blender["fov_y"], 40.0)
    assert np.allclose(blender["clip"], [0.1 * CLIP_MARGIN[0], 3.0 * CLIP_MARGIN[1]])
    points = np.concatenate([V[::997], np.ones((len(V[::997]), 1))], axis=1)
    seen = points @ np.linalg.inv(to_world).T
    half = np.tan(np.radians(blender["fov_y"]) / 2)
    theirs = np.stack([seen[:, 0] / -seen[:, 2] / (half * 96 / 64), seen[:, 1] / -seen[:, 2] / half], axis=1)
    clip = points @ (r.projection @ r.view_matrix).T
    ours = clip[:, :2] / clip[:, 3:4]
    assert np.abs(ours).max() > 0.3 and np.allclose(theirs, ours, atol=1e-9)


def test_freestyle_gets_the_mesh_exactly(tmp_path):
    V, F = bunny()
    write_obj(str(tmp_path / "mesh.obj"), V, F)
    lines = (tmp_path / "mesh.obj").read_text().splitlines()
    read_v = np.array([[float(x) for x in ln.split()[1:]] for ln in lines if ln.startswith("v ")])
    read_f = np.array([[int(x) - 1 for x in ln.split()[1:]] for ln in lines if ln.startswith("f ")])
    assert np.array_equal(read_v.astype(V.dtype), V) and np.array_equal(read_f, F)
