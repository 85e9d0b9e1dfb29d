"""How far each function stays correct as coordinates and image values grow or shrink: the
limits stated in the hard-case table (docs/hard-cases.md), held by tests."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import edges as te

V, F = tm.shapes.icosphere(2, noise=0.05, seed=1)

SMOOTHERS = {
    "uniform": lambda X: tm.smooth.laplacian(X, F),
    "cotangent": lambda X: tm.smooth.laplacian(X, F, weights="cotangent"),
    "distance": lambda X: tm.smooth.laplacian(X, F, weights="distance"),
    "taubin": lambda X: tm.smooth.taubin(X, F),
    "hc": lambda X: tm.smooth.hc(X, F),
    "implicit-cotangent": lambda X: tm.smooth.implicit(X, F, weights="cotangent"),
    "volume constraint": lambda X: tm.smooth.laplacian(X, F, volume_constraint=True),
    "pymeshlab": lambda X: tm.smooth.laplacian(X, F, preset="pymeshlab"),
    "trimesh implicit": lambda X: tm.smooth.implicit(X, F, preset="trimesh"),
}

# From subnormal coordinates to float64's largest: squared lengths alone would overflow above
# about 1e154 and the volume's sums above about 1e77 (and underflow below their inverses).
SCALES = [1e-300, 1e-200, 1e-160, 1e-100, 1e-60, 1e60, 1e100, 1e160, 1e200, 1e300, 1e307]


@pytest.mark.parametrize("name", sorted(SMOOTHERS))
@pytest.mark.parametrize("scale", SCALES)
def test_smoothing_gives_the_same_result_at_every_scale(name, scale):
    smooth = SMOOTHERS[name]
    ref = smooth(V)
    out = smooth(V * scale)
    assert np.isfinite(out).all()
    assert np.abs(out / scale - ref).max() <= 1e-12 * np.abs(ref).max()


def test_subnormal_coordinates_are_smoothed_to_their_precision():
    # 1e-310 keeps about 35 of a float64's 53 bits.
    for name, smooth in SMOOTHERS.items():
        out = smooth(V * 1e-310)
        assert np.isfinite(out).all()
        assert np.abs(out / 1e-310 - smooth(V)).max() <= 1e-8, name


@pytest.mark.parametrize("offset", [1e6, 1e10, 1e300])
def test_offsets_cost_only_the_precision_of_the_coordinates(offset):
    # Far from the origin a float64 resolves eps * offset; the mesh keeps its size (the offset
    # divided by 1e6), so the result is good to about 1e-10 of the diagonal, even with the
    # volume constraint (whose sums are taken about the vertices' mean, not the origin).
    size = offset / 1e6
    for name, smooth in SMOOTHERS.items():
        if name in ("pymeshlab", "trimesh implicit"):
            continue  # the peers' own rules are stated about the origin
        ref = smooth(V)
        out = (smooth(V * size + offset) - offset) / size
        assert np.abs(out - ref).max() <= 1e-8, name


def test_a_mesh_smaller_than_the_resolution_at_its_offset_stays_finite():
    # At 1e100 a mesh of size 1 is below float64's resolution: every vertex is the same point.
    out = tm.smooth.laplacian(V + 1e100, F, weights="cotangent")
    assert np.isfinite(out).all() and np.all(out == 1e100)


def test_results_beyond_the_dtype_are_refused_naming_the_cause():
    # Taubin's inflate step amplifies the lowest frequencies by up to about 1e-3 per iteration.
    with pytest.raises(ValueError, match="^iterations: the smoothed positions grew past the largest float32"):
        tm.smooth.taubin((V * 1e30).astype(np.float32), F, iterations=40_000)
    # Pure inflation of a mesh at 99% of float64's largest value pushes its peaks past it.
    big = V / np.abs(V).max() * (0.99 * np.finfo(np.float64).max)
    with pytest.raises(ValueError, match="^vertices: the smoothed positions overflow float64"):
        tm.smooth.taubin(big, F, lamb=0.0, mu=-1.0, iterations=3)


def test_float32_needs_no_rescaling_anywhere_in_its_range():
    V32 = V.astype(np.float32)
    for scale in (1e-40, 1e-30, 1e30, 1e37):
        for name in ("uniform", "cotangent", "distance", "volume constraint"):
            out = SMOOTHERS[name]((V32 * np.float32(scale)).astype(np.float32))
            assert out.dtype == np.float32 and np.isfinite(out).all()
            tol = 1e-2 if scale < 1e-37 else 1e-5  # subnormal float32 keeps few bits
            assert np.abs(out / np.float32(scale) - SMOOTHERS[name](V32)).max() <= tol, (name, scale)


@pytest.mark.parametrize("scale", [1e-305, 1e-300, 1e-160, 1e-100, 1e100, 1e160, 1e300, 1e307])
def test_outlines_are_the_same_at_every_scale(scale):
    ref = te.feature_edges(V, F, crease_angle=10.0)
    fe = te.feature_edges(V * scale, F, crease_angle=10.0)
    assert np.array_equal(fe.crease, ref.crease) and len(fe.degenerate_faces) == 0
    assert np.allclose(fe.crease_angles, ref.crease_angles, atol=1e-9)
    eye = np.array([0.3, 0.2, 5.0])
    assert np.array_equal(te.silhouette(V * scale, F, eye=eye * scale), te.silhouette(V, F, eye=eye))
    index = te.EdgeIndex(V * scale, F)
    assert np.array_equal(index.silhouette(direction=(0.1, 0.0, -1.0)), te.silhouette(V, F, direction=(0.1, 0.0, -1.0)))


@pytest.mark.parametrize("dtype, scales", [
    (np.float64, [1e-300, 1e-160, 1e160, 1e300, 4e307]),
    (np.float32, [1e-30, 1e-20, 1e20, 1e30, 8e37]),
])
def test_sobel_is_accurate_up_to_a_quarter_of_the_largest_value(dtype, scales):
    img = np.random.default_rng(0).random((16, 16))
    tiny = np.finfo(dtype).tiny
    for f in (te.sobel, te.sobel_h, te.sobel_v):
        ref = f(img.astype(dtype)).astype(np.float64)
        for s in scales:
            out = f((img * s).astype(dtype))
            assert np.isfinite(out).all(), (f.__name__, s)
            # Below the smallest normal number the image itself keeps fewer bits.
            tol = 1e-5 if dtype == np.float32 else 1e-13
            if s * 1e-2 < tiny * 1e8:
                tol = 1e-3
            assert np.abs(out.astype(np.float64) / s - ref).max() <= tol * np.abs(ref).max(), (f.__name__, s)


def test_sobel_beyond_a_quarter_of_the_largest_value_overflows():
    # The [1, 2, 1] sums of values above max / 4 do not fit: inf or NaN, as in scikit-image.
    img = np.full((4, 4), np.finfo(np.float32).max, dtype=np.float32)
    assert not np.isfinite(te.sobel_v(img)).all()


def test_detect_edges_at_large_depths():
    depth = 1.0 + np.random.default_rng(1).random((12, 12))
    ref = te.detect_edges(depth=depth, depth_threshold=0.5)
    for s in (1e-300, 1e300):
        d = te.detect_edges(depth=depth * s, depth_threshold=0.5 * s)
        assert np.isfinite(d.depth_gradient).all() and np.array_equal(d.mask, ref.mask)
