"""Rendering: every shading model against a NumPy reference, on Vulkan and on GL."""

from __future__ import annotations

import numpy as np
import pytest
from render_reference import expected_color, light_dots, match_fraction, need

import toonmesh as tm
from toonmesh import _core
from toonmesh.testing import assert_images_close

BACKENDS = ["vulkan", "gl"]
# Pixels whose L.n lies this close to a threshold may fall on either side of it through f32
# rounding of interpolated normals; they are left out of the band and threshold comparisons.
EDGE_MARGIN = 1e-4


@pytest.fixture(scope="module", params=BACKENDS)
def renderer(request):
    return tm.Renderer(request.param)


@pytest.fixture(scope="module")
def sphere():
    V, F = _core.icosphere(4, 0.0, 0)
    return V, F


@pytest.fixture(scope="module")
def bumpy():
    V, F = _core.icosphere(4, 0.04, 7)
    return V, F


LIGHTS = [
    tm.Light.key(),
    tm.Light.point((3.0, 1.5, 2.0), color=(1.0, 0.8, 0.6), intensity=0.4),
]

MATERIALS = {
    "lambert": tm.Material.lambert("#d08040"),
    "phong": tm.Material.phong("#4080d0", shininess=24.0),
    "thresholded_phong_blinn": tm.Material.thresholded_phong("#40a060", t_h=0.1, t_s=0.9),
    "thresholded_phong_paper": tm.Material.thresholded_phong("#a04060", t_h=-0.2, t_s=0.2, highlight="paper"),
    "bands": tm.Material.bands("#e08830"),
    "bands_custom": tm.Material.bands((0.3, 0.5, 0.9), thresholds=(-0.3, 0.4), values=(0.1, 0.5, 1.0)),
    "lut_kang": tm.Material.lut(),
    "lut_rgb": tm.Material.lut(np.linspace([0.1, 0.0, 0.3], [1.0, 0.9, 0.2], 16), color=(1, 1, 1)),
}


def _thresholds(m: tm.Material):
    if m.model == "bands":
        return list(m.thresholds)
    if m.model == "thresholded_phong":
        return [m.t_h]
    if m.model == "lut":
        n = len(m.table) if m.table is not None else 256
        return list(np.arange(1, n) / n)
    return []


@pytest.mark.parametrize("name", list(MATERIALS))
def test_each_model_matches_numpy_reference(renderer, bumpy, name):
    m = MATERIALS[name]
    # hard band borders: the formulas themselves (the blended borders are held against the
    # CPU reference in the Rust GPU tests, and against supersampling in test_band_antialias.py)
    res = renderer.render(tm.Mesh(*bumpy), material=m, lights=LIGHTS, width=200, height=150,
                          outputs=("color", "normal", "depth"), band_antialias=False)
    covered = np.isfinite(res.depth)
    assert covered.sum() > 5000
    mask = covered.copy()
    for d in light_dots(res, LIGHTS):
        for t in _thresholds(m):
            mask &= np.abs(d - t) > EDGE_MARGIN
    assert mask.sum() > 0.9 * covered.sum()
    frac = match_fraction(res, expected_color(res, m, LIGHTS), mask)
    assert frac >= 0.995, f"{name} on {renderer.backend}: {frac:.4f} of covered pixels match"


@pytest.mark.parametrize("backend", BACKENDS)
def test_per_vertex_shading_colours_vertices(backend):
    # Flat normals under an orthographic camera and parallel light: every vertex of a face gets
    # the face's colour, so the interpolated colour equals the reference of the face normal.
    V, F = _core.icosphere(2, 0.0, 0)
    lights = [tm.Light.directional((0.3, -0.6, -1.0))]
    m = tm.Material.thresholded_phong(t_h=0.3, t_s=0.5, highlight="paper", per_vertex=True)
    res = tm.render(
        tm.Mesh(V, F, normals="flat"),
        material=m,
        lights=lights,
        camera=tm.Camera.orthographic((0, 0, 5), height=2.5),
        width=120,
        height=120,
        outputs=("color", "normal", "depth"),
        backend=backend,
    )
    covered = np.isfinite(res.depth)
    assert match_fraction(res, expected_color(res, m, lights), covered) >= 0.995
    # and it differs from per-pixel shading of a smooth sphere somewhere (the Gouraud look)
    smooth = tm.render(V, F, material=m, lights=lights, camera=tm.Camera.orthographic((0, 0, 5), height=2.5), width=120, height=120, backend=backend)
    assert (smooth.color != res.color).any()


def test_vulkan_and_gl_agree(bumpy):
    images = []
    for backend in BACKENDS:
        res = tm.render(*bumpy, material=tm.Material.bands(), lights=LIGHTS, width=257, height=181, outputs=("color", "depth"), backend=backend)
        images.append(res)
    a, b = images
    # no pixel more than 1 level apart but for 0.2% of them (docs/testing.md has the sizes)
    assert_images_close(a, b, levels=1, share=0.002)
    assert np.array_equal(np.isfinite(a.depth), np.isfinite(b.depth)) or (np.isfinite(a.depth) != np.isfinite(b.depth)).mean() < 0.005
    both = np.isfinite(a.depth) & np.isfinite(b.depth)
    np.testing.assert_allclose(a.depth[both], b.depth[both], rtol=1e-4)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("size", [(301, 199), (1, 1), (2, 3), (65, 1)])
def test_odd_sizes(backend, sphere, size):
    w, h = size
    res = tm.render(*sphere, width=w, height=h, outputs=("color", "normal", "depth"), backend=backend)
    assert res.color.shape == (h, w, 4) and res.color.dtype == np.uint8
    assert res.normal.shape == (h, w, 3) and res.normal.dtype == np.float32
    assert res.depth.shape == (h, w) and res.depth.dtype == np.float32
    assert (res.width, res.height) == (w, h)
    if w > 100:
        # the sphere is centred: the middle pixel is covered, the corners are background
        assert np.isfinite(res.depth[h // 2, w // 2]) and np.isinf(res.depth[0, 0])
        assert tuple(res.color[0, 0]) == (255, 255, 255, 255)
        # depth at the centre is the distance to the sphere's front along the view axis
        eye_dist = -res.view_matrix[2, 3]
        assert abs(res.depth[h // 2, w // 2] - (eye_dist - 1.0)) < 0.01
        assert res.normal[h // 2, w // 2, 2] > 0.99


def test_top_left_origin_and_normals_in_view_space(sphere):
    # a light from above (in camera space) lights the top of the sphere: top rows are brighter
    res = tm.render(*sphere, material=tm.Material.lambert((1, 1, 1)), lights=[tm.Light.directional((0, -1, 0), space="camera")],
                    camera=tm.Camera.look_at((0, 0, 4)), width=64, height=64, outputs=("color", "normal"))
    assert res.color[16, 32, 0] > res.color[48, 32, 0]
    assert res.normal[12, 32, 1] > 0.5 and res.normal[52, 32, 1] < -0.5   # +y up
    assert res.normal[32, 52, 0] > 0.5                                      # +x right


def test_passes_list_only_what_runs(sphere):
    assert tm.render(*sphere, width=32, height=32).passes == ["shade", "readback_color"]
    full = tm.render(*sphere, width=32, height=32, outputs=("color", "normal", "depth"))
    assert full.passes == ["shade", "readback_color", "readback_normal_depth"]
    fuller = tm.render(*sphere, width=32, height=32, outputs=("color", "normal", "depth"), msaa=4, supersample=2)
    assert fuller.passes == ["shade", "gbuffer", "downsample", "readback_color", "readback_normal_depth"]
    assert tm.render(*sphere, width=32, height=32, outputs="depth").passes == ["gbuffer", "readback_depth"]
    assert tm.render(*sphere, width=32, height=32, supersample=3).passes == ["shade", "downsample", "readback_color"]
    assert "frame" in fuller.timings and all(t >= 0 for t in fuller.timings.values())
    if fuller.timing_source == "gpu":
        assert {"shade", "gbuffer", "downsample"} <= set(fuller.timings)


def test_only_requested_outputs_are_returned(sphere):
    res = tm.render(*sphere, width=16, height=16, outputs=("normal",))
    assert res.color is None and res.depth is None and res.normal is not None
    with pytest.raises(ValueError, match="color"):
        res.save("never-written.png")


@pytest.mark.parametrize("backend", BACKENDS)
def test_hard_scenes_render(backend, sphere):
    # camera inside the mesh: every pixel sees the inside, normals turned toward the camera
    inside = tm.render(*sphere, camera=tm.Camera.look_at((0, 0, 0), (0, 0, -1), fov_y=60), width=40, height=30,
                       outputs=("color", "normal", "depth"), backend=backend)
    assert np.isfinite(inside.depth).all()
    assert (inside.normal[..., 2] > 0).all()
    # the mesh behind the camera: nothing covered
    behind = tm.render(*sphere, camera=tm.Camera.look_at((0, 0, 5), (0, 0, 10)), width=40, height=30, outputs=("color", "depth"),
                       backend=backend, background=(0, 0, 0, 0))
    assert np.isinf(behind.depth).all() and (behind.color == 0).all()
    # an empty scene is the background
    empty = tm.render(None, width=7, height=5, background=(0.2, 0.4, 0.6), outputs=("color", "depth", "normal"), backend=backend)
    assert (empty.color == [51, 102, 153, 255]).all()
    assert np.isinf(empty.depth).all() and (empty.normal == 0).all()
    assert tm.render([], width=3, height=3, backend=backend).passes == ["shade", "readback_color"]


def test_several_meshes_with_own_materials_and_transforms(sphere):
    V, F = sphere
    shift = np.eye(4)
    shift[0, 3] = 3.0
    red, blue = tm.Material.bands((1, 0, 0)), tm.Material.bands((0, 0, 1))
    res = tm.render([tm.Mesh(V, F, material=red), tm.Mesh(V, F, material=blue, transform=shift)],
                    camera=tm.Camera.fit((0, 0, 1)), lights=[tm.Light.directional((0, 0, -1))], width=200, height=100)
    left, right = res.color[50, 71], res.color[50, 129]
    assert left[0] > 200 and left[2] == 0
    assert right[2] > 200 and right[0] == 0


def test_mirrored_transform_keeps_normals_outward(sphere):
    V, F = sphere
    mirror = np.diag([-1.0, 1.0, 1.0, 1.0])
    a = tm.render(V, F, width=48, height=48, outputs="normal", camera=tm.Camera.look_at((0, 0, 4)))
    b = tm.render(V, F, transform=mirror, width=48, height=48, outputs="normal", camera=tm.Camera.look_at((0, 0, 4)))
    covered = np.linalg.norm(a.normal, axis=-1) > 0
    assert (a.normal[covered][:, 2] > 0).mean() > 0.99 and (b.normal[covered][:, 2] > 0).mean() > 0.99


def test_msaa_and_supersampling_smooth_edges_only(bumpy):
    kw = dict(width=96, height=96, material=tm.Material.bands())
    plain = tm.render(*bumpy, **kw).color.astype(int)
    for knob in (dict(msaa=4), dict(supersample=2)):
        aa = tm.render(*bumpy, **kw, **knob).color.astype(int)
        same = np.all(np.abs(aa - plain) <= 1, axis=-1)
        assert 0.6 < same.mean() < 1.0, knob
        assert len(np.unique(aa.reshape(-1, 4), axis=0)) > len(np.unique(plain.reshape(-1, 4), axis=0))


def test_inputs_are_not_modified_and_dtypes_accepted(sphere):
    V, F = sphere
    V32, F32 = V.astype(np.float32), F.astype(np.int32)
    V_copy, F_copy = V32.copy(), F32.copy()
    a = tm.render(V32, F32, width=32, height=32, smooth_iterations=2).color
    b = tm.render(np.asfortranarray(V), F.astype(np.uint32), width=32, height=32, smooth_iterations=2).color
    assert np.array_equal(V32, V_copy) and np.array_equal(F32, F_copy)
    assert np.abs(a.astype(int) - b.astype(int)).max() <= 1


def test_trimesh_input(sphere):
    trimesh = need("trimesh")
    m = trimesh.Trimesh(*sphere, process=False)
    assert np.array_equal(tm.render(m, width=32, height=32).color, tm.render(*sphere, width=32, height=32).color)


def _neighbour_mean(V, F, n):
    e = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    e = np.unique(np.sort(e, axis=1), axis=0)
    nbrs = [[] for _ in range(len(V))]
    for a, b in e:
        nbrs[a].append(b)
        nbrs[b].append(a)
    X = V.copy()
    for _ in range(n):
        X = np.array([X[nb].mean(axis=0) if nb else X[i] for i, nb in enumerate(nbrs)])
    return X


def test_smooth_iterations_smooth_first(bumpy):
    V, F = bumpy
    kw = dict(width=96, height=96, outputs=("color", "depth"), camera=tm.Camera.look_at((0, 0, 3.5)))
    a = tm.render(V, F, smooth_iterations=3, **kw)
    b = tm.render(_neighbour_mean(V, F, 3), F, **kw)
    both = np.isfinite(a.depth) & np.isfinite(b.depth)
    assert both.sum() > 0.99 * np.isfinite(b.depth).sum()
    np.testing.assert_allclose(a.depth[both], b.depth[both], rtol=1e-4)
    assert (np.abs(a.color.astype(int) - b.color.astype(int)) <= 1).all(axis=-1).mean() > 0.995
    with pytest.raises(ValueError, match="smooth_iterations"):
        tm.render(V, F, smooth_iterations=-1)


def test_result_png_pil_and_repr(tmp_path, sphere):
    Image = need("PIL.Image")
    res = tm.render(*sphere, width=33, height=21)
    path = tmp_path / "out.png"
    res.save(path)
    assert np.array_equal(np.asarray(Image.open(path).convert("RGBA")), res.color)
    assert res._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    assert np.array_equal(np.asarray(res.to_pil()), res.color)
    assert "33x21" in repr(res)


def test_gpu_info_names_adapter_and_backend():
    for backend in BACKENDS:
        info = tm.gpu_info(backend)
        assert info["backend"] == backend and info["name"]
        assert info["max_texture_size"] >= 2048 and 4 in info["msaa_samples"]
    assert tm.gpu_info()["backend"] in BACKENDS


def test_renderer_keeps_meshes_for_many_views(sphere):
    r = tm.Renderer()
    h = r.add_mesh(*sphere)
    frames = [r.render(h, camera=tm.Camera.fit((np.sin(a), 0.3, np.cos(a))), width=48, height=48).color for a in np.linspace(0, 3, 4)]
    assert r._engine.mesh_count == 1
    # the same view twice gives the same image
    again = r.render(h, camera=tm.Camera.fit((np.sin(0.0), 0.3, np.cos(0.0))), width=48, height=48).color
    assert np.array_equal(frames[0], again)
    other = tm.Renderer()
    with pytest.raises(ValueError, match="another Renderer"):
        other.render(h)
    r.remove_mesh(h)
    assert r._engine.mesh_count == 0
    with pytest.raises(ValueError, match="mesh"):
        r.render(h)
