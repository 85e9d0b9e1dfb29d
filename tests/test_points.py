"""Point clouds drawn as toon splats (tm.Points): normals from each point's neighbours, splats
that cover the surface they sample, image-space ink at their silhouette, on both backends."""

import numpy as np
import pytest

import toonmesh as tm

BACKENDS = ["vulkan", "gl"]
SIZE = 256


def _sphere_points(n=40000, seed=0):
    v = np.random.default_rng(seed).normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _front(**kw):
    return dict(width=SIZE, height=SIZE, camera=tm.Camera.fit((0.0, 0.0, 1.0)), **kw)


def _disc(depth):
    """The pixels something was drawn on."""
    return np.isfinite(depth)


def _outer_ring(mask):
    """The pixels of `mask` with a neighbour outside it (its silhouette)."""
    inner = mask.copy()
    for axis in (0, 1):
        for step in (1, -1):
            inner &= np.roll(mask, step, axis=axis)
    return mask & ~inner


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_sphere_of_points_looks_like_the_sphere(backend):
    points = tm.Points(_sphere_points())
    r = tm.render(points, backend=backend, outlines="mesh", outputs=("color", "depth"), **_front())
    V, F = tm.shapes.icosphere(5)
    ref = tm.render(V, F, backend=backend, outputs=("depth",), **_front())
    got, disc = _disc(r.depth), _disc(ref.depth)
    assert (got & disc).sum() / (got | disc).sum() >= 0.9
    # >= 60% of the silhouette inked: an inked pixel (darker than without outlines) within 2
    # pixels of each silhouette pixel
    plain = tm.render(points, backend=backend, outputs=("color",), **_front())
    lum = [x.color[..., :3].astype(int).sum(axis=-1) for x in (r, plain)]
    dark = lum[0] < lum[1] - 60
    near = dark.copy()
    for dy in range(-2, 3):
        for dx in range(-2, 3):
            near |= np.roll(np.roll(dark, dy, axis=0), dx, axis=1)
    ring = _outer_ring(disc)
    assert near[ring].mean() >= 0.6
    # the ink stays at the silhouette: the inside is clean
    yy, xx = np.mgrid[:SIZE, :SIZE]
    c = np.argwhere(disc).mean(axis=0)
    radius = np.sqrt(disc.sum() / np.pi)
    inside = (yy - c[0]) ** 2 + (xx - c[1]) ** 2 < (0.85 * radius) ** 2
    assert dark[inside].mean() < 0.01
    # >= 3 toon tones, each covering >= 2% of the disc
    colours, counts = np.unique(r.color[inside & ~dark][:, :3], axis=0, return_counts=True)
    assert (counts >= 0.02 * inside.sum()).sum() >= 3, colours[counts >= 0.02 * inside.sum()]


@pytest.mark.parametrize("backend", BACKENDS)
def test_scale_free(backend):
    unit = _sphere_points(20000, seed=1)
    frames = [
        tm.render(tm.Points(unit * s), backend=backend, outlines="image", outputs=("color", "depth"),
                  **_front())
        for s in (0.005, 5000.0)
    ]
    a, b = (_disc(f.depth) for f in frames)
    assert (a & b).sum() / (a | b).sum() > 0.99
    diff = np.abs(frames[0].color.astype(int) - frames[1].color.astype(int))
    assert (diff.max(axis=-1) > 8).mean() < 0.01


def test_mesh_and_points_in_one_scene_keep_their_own_ink():
    V, F = tm.shapes.icosphere(3)
    ball = tm.Mesh(V * 0.5, F)
    shift = np.eye(4)
    shift[0, 3] = 1.5  # the cloud beside the ball, by its transform
    cloud = tm.Points(_sphere_points(5000) * 0.5, transform=shift)
    r = tm.render([ball, cloud], outlines="mesh", outputs=("color", "lines", "depth"), **_front())
    # the mesh keeps its mesh-space lines; the cloud's ink is image-space, so it adds no lines
    assert "lines" in r.passes and "edges" in r.passes
    alone = tm.render(ball, outlines="mesh", outputs=("lines",), **_front())
    assert "edges" not in alone.passes
    assert len(r.lines) > 0
    drawn = np.isfinite(r.depth)
    assert drawn[:, : SIZE // 2].any() and drawn[:, SIZE // 2:].any()  # both, side by side
    cloud_only = tm.render(cloud, outlines="mesh", outputs=("color", "lines"), **_front())
    assert len(cloud_only.lines) == 0


def test_normals_are_radial_outward_and_finite_on_hard_cases():
    p = _sphere_points(3000)
    n = tm.points.normals(p)
    assert n.dtype == p.dtype and n.shape == p.shape
    assert (np.einsum("ij,ij->i", n, p) > 0.98).all()
    assert tm.points.normals(p.astype(np.float32), k=16).dtype == np.float32
    line = np.outer(np.arange(30.0), [1.0, 2.0, 0.0])
    for cloud in (line, np.ones((40, 3)), np.zeros((1, 3)), np.eye(3), line[:2]):
        got = tm.points.normals(cloud)
        assert np.isfinite(got).all() and np.allclose(np.linalg.norm(got, axis=1), 1.0)
    # the same bits whatever the thread count
    before = tm.get_num_threads()
    try:
        tm.set_num_threads(1)
        one = tm.points.normals(p)
    finally:
        tm.set_num_threads(before)
    assert np.array_equal(one, n)


def test_hard_clouds_render():
    for cloud in (np.zeros((1, 3)), np.ones((50, 3)), np.outer(np.arange(30.0), [1.0, 2.0, 0.0])):
        r = tm.render(tm.Points(cloud), outlines="both", outputs=("color", "depth"), width=64, height=64)
        assert np.isfinite(r.depth).any()


def test_colours_normals_and_radius_given():
    p = _sphere_points(4000)
    red = np.tile([255, 0, 0], (len(p), 1)).astype(np.uint8)
    r = tm.render(tm.Points(p, normals=p * 3.0, colors=red, radius=0.1), outputs=("color",), **_front())
    drawn = r.color[SIZE // 2 - 20:SIZE // 2 + 20, SIZE // 2 - 20:SIZE // 2 + 20, :3].astype(int)
    assert (drawn[..., 0] > drawn[..., 1] + 60).all()  # the points' colour shows, under white
    renderer = tm.Renderer()
    handle = renderer.add_points(tm.Points(p))
    views = renderer.render_many(tm.Mesh(handle), [tm.Camera.fit((0, 0, 1)), tm.Camera.fit((1, 0, 0))],
                                 width=64, height=64, outputs=("depth",))
    assert all(np.isfinite(v.depth).mean() > 0.3 for v in views)
    renderer.remove_mesh(handle)


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="k"):
        tm.points.normals(np.zeros((5, 3)), k=2)
    with pytest.raises(TypeError, match="k"):
        tm.points.normals(np.zeros((5, 3)), k=3.5)
    with pytest.raises(ValueError, match="positions"):
        tm.points.normals(np.zeros((5, 2)))
    with pytest.raises(ValueError, match="positions"):
        tm.points.normals(np.full((5, 3), np.nan))
    with pytest.raises(TypeError, match="points"):
        tm.Renderer().add_points(np.zeros((5, 3)))
    with pytest.raises(ValueError, match="radius"):
        tm.Points(np.zeros((5, 3)), radius=-1.0)
    with pytest.raises(TypeError, match=r"meshes\[0\]"):
        tm.Renderer().render([object()])


@pytest.mark.parametrize("backend", BACKENDS)
def test_eye_dome_lighting_runs_only_when_asked_for_and_darkens_depth_steps(backend):
    cloud = tm.Points(_sphere_points(20000))
    off = tm.render(cloud, backend=backend, outputs=("color",), **_front())
    assert "eye_dome" not in off.passes
    on = tm.render(cloud, backend=backend, outputs=("color",), eye_dome=tm.EyeDome(strength=2.0), **_front())
    assert "eye_dome" in on.passes
    a, b = (x.color[..., :3].astype(int) for x in (on, off))
    assert (a <= b + 1).all()  # it only darkens
    assert (a.sum(axis=-1) < b.sum(axis=-1) - 30).sum() > 200  # toward the silhouette, most
    assert tm.EyeDome().strength > 0 and tm.EyeDome(radius=3).radius == 3
    with pytest.raises(ValueError, match="radius"):
        tm.EyeDome(radius=-1)


def test_a_cloud_alone_runs_no_mesh_line_steps_and_with_a_mesh_they_run():
    """Simulate only what the scene calls for: splats have no mesh-space lines, so a cloud
    alone under outlines="mesh" runs the image-space edges only; a mesh beside it brings the
    line steps back."""
    points = tm.Points(_sphere_points(2000))
    alone = tm.render(points, outlines="mesh", width=64, height=64).passes
    assert "edges" in alone and not {"silhouettes", "visible_lines", "lines"} & set(alone), alone
    V, F = tm.shapes.icosphere(2)
    beside = tm.render([points, tm.Mesh(V + 3.0, F)], outlines="mesh", width=64, height=64).passes
    assert {"silhouettes", "lines", "edges"} <= set(beside), beside
    # the 'lines' output of a cloud alone: no line, not an error
    assert tm.render(points, outlines="mesh", width=64, height=64, outputs=("color", "lines")).lines == []


def test_colour_alpha_is_said_not_drawn_and_a_material_opacity_makes_a_cloud_see_through():
    """A point colour's alpha does not cut splats away (they stay, opaque, with a warning that
    says so); the material's opacity is what makes a cloud glass."""
    P = _sphere_points(4000)
    rgba = np.zeros((len(P), 4))
    rgba[:, 0], rgba[:, 3] = 1.0, 0.3
    with pytest.warns(UserWarning, match="alpha channel is not drawn"):
        cloud = tm.Points(P, colors=rgba)
    r = tm.render(cloud, width=64, height=64, camera=tm.Camera.fit((0.0, 0.0, 1.0)))
    centre = r.color[32, 32, :3].astype(int)
    assert centre[0] > 150 and centre[1] < 30 and centre[2] < 30, centre  # red, drawn whole
    glass = tm.render(tm.Points(P, material=tm.Material.bands("#ff0000", opacity=0.4)), width=64, height=64,
                      camera=tm.Camera.fit((0.0, 0.0, 1.0)), background="#0000ff")
    mixed = glass.color[32, 32, :3].astype(int)
    assert "glass_composite" in glass.passes and mixed[0] > 100 and mixed[2] > 50, mixed  # red over blue
