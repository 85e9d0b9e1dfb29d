"""Principal curvature (tm.edges.curvature) against closed forms (sphere, cylinder, torus,
ellipsoid), its scale and orientation rules, hard cases, and libigl and pymeshlab on real
meshes."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.testing import curvature_vs_libigl

from conftest import load_mesh, need


def _grid_surface(point, n_u, n_v, closed_v=True):
    """A (u, v) grid mesh of point(U, V) with u periodic (and v periodic when closed_v), and
    the grid's U, V per vertex."""
    u = np.linspace(0, 2 * np.pi, n_u, endpoint=False)
    v = np.linspace(0, 2 * np.pi, n_v, endpoint=False) if closed_v else np.linspace(0.0, 1.0, n_v)
    U, W = np.meshgrid(u, v, indexing="ij")
    V = point(U, W).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n_u), np.arange(n_v if closed_v else n_v - 1), indexing="ij")
    i, j = i.ravel(), j.ravel()

    def at(a, b):
        return (a % n_u) * n_v + (b % n_v)

    a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
    F = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    return V, F, U.ravel(), W.ravel()


def _torus(R=1.0, r=0.3, n_u=240, n_v=80):
    def point(U, W):
        return np.stack([(R + r * np.cos(W)) * np.cos(U), (R + r * np.cos(W)) * np.sin(U), r * np.sin(W)], -1)

    return _grid_surface(point, n_u, n_v)


def _cylinder(r=0.5, h=2.0, n_u=128, n_v=40):
    def point(U, W):
        return np.stack([r * np.cos(U), r * np.sin(U), h * W], -1)

    return _grid_surface(point, n_u, n_v, closed_v=False)


def _median_rel(a, b):
    return float(np.median(np.abs(a - b) / np.abs(b)))


def test_sphere_is_one_over_radius():
    V, F = tm.shapes.icosphere(5)
    for radius in (0.01, 1.0, 300.0):
        c = tm.edges.curvature(V * radius, F)
        assert _median_rel(c.k1, 1 / radius) < 0.02
        assert _median_rel(c.k2, 1 / radius) < 0.02
        assert np.all(c.k1 >= c.k2)
        np.testing.assert_allclose(c.mean, 1 / radius, rtol=0.02)
        np.testing.assert_allclose(c.gaussian, 1 / radius**2, rtol=0.04)


def test_torus_values_and_directions():
    R, r = 1.0, 0.3
    V, F, U, W = _torus(R, r)
    c = tm.edges.curvature(V, F)
    around_tube = np.full(len(V), 1 / r)  # the small circle's curvature
    along_ring = np.cos(W) / (R + r * np.cos(W))  # the large circle's normal curvature
    assert _median_rel(c.k1, np.maximum(around_tube, along_ring)) < 0.03
    big = np.abs(along_ring) > 0.2  # away from the circles where the second value crosses 0
    assert _median_rel(c.k2[big], np.minimum(around_tube, along_ring)[big]) < 0.03
    # d1 (the larger curvature, around the tube) is the small circle's tangent, d2 the large one's
    tube_tangent = np.stack([-np.sin(W) * np.cos(U), -np.sin(W) * np.sin(U), np.cos(W)], -1)
    ring_tangent = np.stack([-np.sin(U), np.cos(U), np.zeros_like(U)], -1)
    assert np.median(np.abs(np.einsum("ij,ij->i", c.d1, tube_tangent))) > 0.99
    assert np.median(np.abs(np.einsum("ij,ij->i", c.d2, ring_tangent))) > 0.99
    np.testing.assert_allclose(np.cross(c.d1, c.d2), c.normals, atol=1e-9)
    # outward normals
    centre_line = np.stack([R * np.cos(U), R * np.sin(U), np.zeros_like(U)], -1)
    assert np.all(np.einsum("ij,ij->i", c.normals, V - centre_line) > 0)


def test_cylinder_interior_and_boundary():
    r = 0.5
    V, F, U, W = _cylinder(r)
    c = tm.edges.curvature(V, F)
    interior = (W > 0.1) & (W < 0.9)
    assert _median_rel(c.k1[interior], 1 / r) < 0.02
    assert np.median(np.abs(c.k2[interior])) < 0.02 / r
    assert np.median(np.abs(c.d2[interior, 2])) > 0.99  # the straight direction is the axis
    assert np.all(np.isfinite(c.k1)) and np.all(np.isfinite(c.d1))  # boundary rows too
    # the radial curvature along a view 45 degrees from the axis (orthographic)
    direction = np.array([1.0, 0.0, 1.0])
    to_viewer = -direction / np.linalg.norm(direction)
    u, w = c.d1 @ to_viewer, c.d2 @ to_viewer
    kr = (c.k1 * u * u + c.k2 * w * w) / (u * u + w * w)
    s2 = np.sin(U) ** 2
    expected = (1 / r) * s2 / (1 + s2)
    assert np.median(np.abs(kr - expected)[interior]) < 0.02 / r


def test_ellipsoid_mean_and_gaussian():
    a, b, cc = 1.0, 0.7, 0.5
    V, F = tm.shapes.icosphere(6)
    V = V * [a, b, cc]
    curv = tm.edges.curvature(V, F)
    x, y, z = V.T
    q = x**2 / a**4 + y**2 / b**4 + z**2 / cc**4
    gaussian = 1 / (a * b * cc) ** 2 / q**2
    mean = (x**2 + y**2 + z**2 - a**2 - b**2 - cc**2) / (2 * (a * b * cc) ** 2 * q**1.5)
    assert _median_rel(curv.gaussian, gaussian) < 0.03
    assert _median_rel(curv.mean, np.abs(mean)) < 0.03


def test_scale_offset_orientation_and_dtype():
    V, F, _, _ = _torus(n_u=60, n_v=24)
    ref = tm.edges.curvature(V, F)
    # offsets up to 1e6 times the size: the input itself keeps about 1e-10 of an edge there
    for s, offset in [(1e-4, 0.0), (1e4, 0.0), (1.0, 1e6), (3e-6, -2.0)]:
        c = tm.edges.curvature(V * s + offset, F)
        np.testing.assert_allclose(c.k1 * s, ref.k1, rtol=1e-6, atol=1e-6 * np.abs(ref.k1).max())
        np.testing.assert_allclose(c.derivatives * s * s, ref.derivatives, atol=1e-5 * np.abs(ref.derivatives).max())
    flipped = tm.edges.curvature(V, F[:, ::-1])
    np.testing.assert_allclose(flipped.k1, -ref.k2, atol=1e-9)
    np.testing.assert_allclose(flipped.normals, -ref.normals, atol=1e-12)
    single = tm.edges.curvature(V.astype(np.float32), F.astype(np.int32))
    assert single.k1.dtype == np.float64
    np.testing.assert_allclose(single.k1, ref.k1, rtol=1e-3, atol=1e-3 * np.abs(ref.k1).max())


def test_smoothing_measures_the_shape_under_noise_at_any_scale():
    a, b, cc = 1.0, 0.7, 0.5
    V, F = tm.shapes.icosphere(6)
    noisy, _ = tm.shapes.icosphere(6, noise=0.004, seed=2)
    x, y, z = (V * [a, b, cc]).T
    q = x**2 / a**4 + y**2 / b**4 + z**2 / cc**4
    mean = (x**2 + y**2 + z**2 - a**2 - b**2 - cc**2) / (2 * (a * b * cc) ** 2 * q**1.5)
    noisy = noisy * [a, b, cc]
    raw = tm.edges.curvature(noisy, F)
    smooth = tm.edges.curvature(noisy, F, smoothing=2.0)
    # the one-ring estimate follows the noise; at 2 mean edges the ellipsoid comes back
    assert _median_rel(raw.mean, np.abs(mean)) > 0.5
    assert _median_rel(smooth.mean, np.abs(mean)) < 0.15
    assert np.mean(raw.k1 * raw.k2 < 0) > 0.2 and np.mean(smooth.k1 * smooth.k2 < 0) < 0.01
    # the width is in mean edge lengths: the same answer in other units
    for s in (1e-3, 1e3):
        c = tm.edges.curvature(noisy * s + 5e3 * s, F, smoothing=2.0)
        np.testing.assert_allclose(c.k1 * s, smooth.k1, rtol=1e-6, atol=1e-6 * np.abs(smooth.k1).max())
    # a clean mesh keeps its values
    clean = tm.edges.curvature(V * [a, b, cc], F, smoothing=2.0)
    assert _median_rel(clean.mean, np.abs(mean)) < 0.03
    assert np.all(np.isfinite(smooth.derivatives))


def test_convex_shapes_have_no_negative_curvature_to_speak_of():
    V, F = tm.shapes.icosphere(4)
    c = tm.edges.curvature(V * [2.0, 1.0, 0.6], F)
    assert np.all(c.k2 > 0)


def test_hard_cases_are_finite():
    V = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [0, 0, 1], [0, -1, 0], [9, 9, 9]], float)
    F = np.array([[0, 1, 2], [0, 1, 3], [0, 1, 4], [0, 1, 5], [0, 0, 3], [3, 4, 5]])  # collinear, fan of 4 (non-manifold), repeated index
    c = tm.edges.curvature(V, F)
    for arr in (c.k1, c.k2, c.d1, c.d2, c.normals, c.derivatives):
        assert np.all(np.isfinite(arr))
    assert c.k1[6] == 0 and c.k2[6] == 0  # a vertex in no face
    np.testing.assert_allclose(np.linalg.norm(c.d1, axis=1), 1.0)
    # a single point mesh, and every face degenerate
    c = tm.edges.curvature(np.zeros((3, 3)), np.array([[0, 1, 2]]))
    assert np.all(c.k1 == 0) and np.all(np.isfinite(c.d1))


def test_inputs_are_checked_and_left_alone():
    V, F = tm.shapes.icosphere(2)
    before = V.copy()
    tm.edges.curvature(V, F)
    np.testing.assert_array_equal(V, before)
    with pytest.raises(IndexError, match="faces"):
        tm.edges.curvature(V, F + len(V))
    with pytest.raises(ValueError, match="vertices"):
        tm.edges.curvature(V[:, :2], F)
    bad = V.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match="vertices"):
        tm.edges.curvature(bad, F)


def test_trimesh_input():
    trimesh = need("trimesh")
    V, F = tm.shapes.icosphere(3)
    c = tm.edges.curvature(trimesh.Trimesh(V, F, process=False))
    np.testing.assert_array_equal(c.k1, tm.edges.curvature(V, F).k1)


@pytest.mark.parametrize("name", ["spot", "stanford-bunny", "rocker-arm"])
def test_agrees_with_libigl(name):
    V, F = load_mesh(name)
    agree = curvature_vs_libigl(V, F)  # libigl's quadric fit over 2 rings
    assert agree.mean_correlation > 0.9
    assert agree.k1_correlation > 0.9
    # same sign convention: where both are clearly curved, they agree on the sign
    assert agree.sign_agreement > 0.95


@pytest.mark.parametrize("name", ["spot", "stanford-bunny", "rocker-arm"])
def test_agrees_with_pymeshlab(name):
    pymeshlab = need("pymeshlab")
    V, F = load_mesh(name)
    c = tm.edges.curvature(V, F)
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(V, F))
    # method 3: pseudo-inverse quadric fitting; the quality it writes: the mean curvature
    ms.compute_curvature_principal_directions_per_vertex(method=3, curvcolormethod=0)
    H = ms.current_mesh().vertex_scalar_array()
    ok = np.isfinite(H)
    assert ok.mean() > 0.99
    assert np.corrcoef(c.mean[ok], H[ok])[0, 1] > 0.9
    assert 0.85 < np.median(H[ok] / c.mean[ok]) < 1.2  # same sign convention and scale
