"""Back-face culling where it cannot change the image: a closed, consistently wound mesh whose
bounding sphere lies wholly beyond the near plane is drawn without its inner sides. Each case
renders the mesh twice, as it is and with one extra face that repeats a vertex (zero area, so
it draws nothing, but the mesh no longer encloses a solid, so nothing is culled), and requires
the same images and the right ``culled`` report."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from conftest import load_mesh

BACKENDS = ["vulkan", "gl"]
OUTPUTS = ("color", "depth", "normal")


def opened(F: np.ndarray) -> np.ndarray:
    """The faces plus one that repeats a vertex: the same picture, but no enclosed solid."""
    return np.vstack([F, [[F[0, 0], F[0, 1], F[0, 0]]]])


def flipped(F: np.ndarray) -> np.ndarray:
    return F[:, ::-1].copy()


def two_shells(F_inner_flipped: bool = False):
    V, F = tm.shapes.torus()
    W, G = tm.shapes.icosphere(3)
    G = flipped(G) if F_inner_flipped else G
    return np.vstack([V, 0.5 * W + [1.6, 0.0, 0.0]]), np.vstack([F, G + len(V)])


MIRROR = np.diag([-1.0, 1.0, 1.0, 1.0])
LOWERED = np.array([[2.0, 0.0, 0.0, -1.0], [0.0, 2.0, 0.0, -1.0], [0.0, 0.0, 1.0, -0.5], [0.0, 0.0, 0.0, 1.0]])
TILT = np.array([[0.8, 0.0, 0.6, 0.2], [0.0, 1.5, 0.0, -0.1], [-0.6, 0.0, 0.8, 0.0], [0.0, 0.0, 0.0, 1.0]])

# name: (vertices, faces, transform, culled when seen from outside)
MESHES = {
    "icosphere": (*tm.shapes.icosphere(4), None, True),
    "torus": (*tm.shapes.torus(segments=40, tube_segments=24), None, True),
    "pawn": (*tm.shapes.pawn(), None, True),
    "wound inside out": (tm.shapes.icosphere(4)[0], flipped(tm.shapes.icosphere(4)[1]), None, True),
    "mirrored": (*tm.shapes.torus(), MIRROR, True),
    "stretched and turned": (*tm.shapes.pawn(), TILT, True),
    "two shells": (*two_shells(), None, True),
    "one shell inside out": (*two_shells(True), None, False),
    "open grid": (*tm.shapes.grid(16), LOWERED, False),
}

# Files: spot is split along its texture seams (closed only once positions are merged), fandisk
# is a CAD part, the bunny has holes. Centred on the origin with a diagonal of 2, as the
# cameras expect.
for _name, _culled in [("spot", True), ("fandisk", True), ("stanford-bunny", False)]:
    _V, _F = load_mesh(_name)
    _V = (_V - (_V.min(0) + _V.max(0)) / 2) / (np.linalg.norm(_V.max(0) - _V.min(0)) / 2)
    MESHES[_name] = (_V, _F, None, _culled)

CAMERAS = {
    "outside": tm.Camera.look_at((0.4, 1.2, 4.0), fov_y=40),
    "orthographic": tm.Camera.orthographic((2.0, 3.0, 3.0), height=3.0),
    "inside": tm.Camera.look_at((0.05, 0.1, 0.0), target=(0.0, 0.0, -1.0), fov_y=80, near=0.01),
    "near plane cuts": tm.Camera.look_at((0.0, 0.0, 1.6), fov_y=50, near=1.0),
}


def pair(backend, name, camera, material=None, lights=None, outputs=OUTPUTS, size=96):
    V, F, transform, _ = MESHES[name]
    kw = dict(camera=camera, width=size, height=size, outputs=outputs, material=material, transform=transform)
    if lights is not None:
        kw["lights"] = lights
    r = tm.Renderer(backend=backend)
    closed = r.render(tm.Mesh(V, F), **kw)
    open_ = r.render(tm.Mesh(V, opened(F)), **kw)
    return closed, open_


def assert_same(a, b, outputs=OUTPUTS):
    for out in outputs:
        x, y = getattr(a, out), getattr(b, out)
        differ = ~np.isclose(x.astype(np.float64), y.astype(np.float64), rtol=0, atol=0, equal_nan=True)
        if differ.ndim == 3:
            differ = differ.any(axis=-1)
        # ties between coincident depths may go either way: at most one pixel in 2000
        assert differ.mean() <= 5e-4, f"{out}: {differ.sum()} pixels differ"


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("camera", list(CAMERAS))
@pytest.mark.parametrize("name", list(MESHES))
def test_culling_never_changes_the_image(backend, name, camera):
    closed, open_ = pair(backend, name, CAMERAS[camera])
    assert open_.culled == [False]
    outside = camera in ("outside", "orthographic")
    assert closed.culled == [MESHES[name][3] and outside]
    drawn = (closed.depth < np.inf).mean()
    assert drawn > 0.02, "the mesh should be in view"
    assert_same(closed, open_)


@pytest.mark.parametrize("backend", BACKENDS)
def test_culled_meshes_cast_the_same_shadows(backend):
    lights = [tm.Light.directional((0.3, -1.0, -0.4), shadows=True)]
    camera = tm.Camera.look_at((0.5, 2.5, 4.0), fov_y=45)
    closed, open_ = pair(backend, "two shells", camera, lights=lights, outputs=("color", "shadow"), size=128)
    assert closed.passes[0] == "shadow_map" and closed.culled == [True]
    assert (closed.shadow < 0.5).sum() > 50, "the scene should have shadows"
    assert_same(closed, open_, ("color", "shadow"))


@pytest.mark.parametrize("backend", BACKENDS)
def test_styled_materials_are_the_same_culled(backend):
    camera = CAMERAS["outside"]
    for material in [
        tm.Material.bands(dither=tm.Dither("bayer4", space="object")),
        tm.Material.hatching(),
        tm.Material.thresholded_phong(per_vertex=True),
    ]:
        closed, open_ = pair(backend, "torus", camera, material=material, outputs=("color",))
        assert closed.culled == [True]
        assert_same(closed, open_, ("color",))


def test_each_mesh_of_a_scene_is_decided_alone():
    V, F = tm.shapes.icosphere(3)
    near = np.eye(4)
    near[:3, 3] = (0.0, 0.0, 2.2)  # straddles the near plane of a camera at z = 3
    far = np.eye(4)
    far[:3, 3] = (0.0, 0.0, -2.0)
    res = tm.render(
        [tm.Mesh(V, F, transform=far), tm.Mesh(V, F, transform=near), tm.Mesh(*tm.shapes.grid(4))],
        camera=tm.Camera.look_at((0.0, 0.0, 3.0), target=(0.0, 0.0, 0.0), fov_y=60, near=0.5),
        width=32, height=32,
    )
    assert res.culled == [True, False, False]


def test_render_many_reports_culling_per_view():
    V, F = tm.shapes.icosphere(3)
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    cams = [tm.Camera.look_at((0.0, 0.0, 3.0)), tm.Camera.look_at((0.0, 0.0, 0.2), target=(0, 0, -1), near=0.01)]
    stack = r.render_many(mesh, cameras=cams, width=24, height=24)
    assert [v.culled for v in stack] == [[True], [False]]
