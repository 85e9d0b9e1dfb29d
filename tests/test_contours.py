"""Smooth contours and suggestive contours (tm.edges.contours, tm.edges.suggestive_contours):
closed forms on the sphere and torus, scans' noise, scale, seams, hard cases and arguments."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from test_curvature import _torus


def _length(lines):
    return float(sum(np.linalg.norm(np.diff(l, axis=0), axis=1).sum() for l in lines))


def test_sphere_contour_is_one_closed_circle():
    V, F = tm.shapes.icosphere(5)
    eye = np.array([0.0, 0.0, 4.0])
    lines = tm.edges.contours(V, F, eye=eye)
    assert len(lines) == 1
    line = lines[0]
    np.testing.assert_array_equal(line[0], line[-1])
    # on the unit sphere the rim seen from eye is p . eye = 1 (chords sit slightly inside)
    assert np.abs(line @ eye - 1).max() < 0.01
    assert abs(_length(lines) - 2 * np.pi * np.sqrt(1 - 1 / 16)) < 0.01
    ortho = tm.edges.contours(V, F, direction=(0, 0, -1))
    assert len(ortho) == 1 and np.abs(ortho[0][:, 2]).max() < 0.01


def test_noisy_sphere_contour_does_not_shatter():
    V, F = tm.shapes.icosphere(5, noise=0.003, seed=0)
    eye = (0.0, 0.0, 4.0)
    lines = tm.edges.contours(V, F, eye=eye)
    faces_rule = tm.edges.chains(tm.edges.silhouette(V, F, eye=eye))
    rim = 2 * np.pi * np.sqrt(1 - 1 / 16)
    assert len(lines) <= 20 < len(faces_rule)
    assert _length(lines) < 1.6 * rim < _length([V[c] for c in faces_rule])


def test_scale_and_offset_move_the_lines_with_the_mesh():
    V, F = tm.shapes.icosphere(4, noise=0.01, seed=1)
    eye = np.array([0.3, 0.2, 3.0])
    ref = tm.edges.contours(V, F, eye=eye)
    for s, offset in [(1e-3, 0.0), (1e4, 5e3), (1.0, -1e5)]:
        lines = tm.edges.contours(V * s + offset, F, eye=eye * s + offset)
        assert [len(l) for l in lines] == [len(l) for l in ref]
        for a, b in zip(lines, ref):
            np.testing.assert_allclose((a - offset) / s, b, atol=1e-6)


def test_weld_joins_lines_across_seams():
    V, F = tm.shapes.icosphere(4)
    # split the sphere along x = 0: faces on the right side get their own copies of the vertices
    right = V[F].mean(axis=1)[:, 0] > 0
    used = np.unique(F[right])
    copy = np.full(len(V), -1)
    copy[used] = len(V) + np.arange(len(used))
    split_V = np.concatenate([V, V[used]])
    split_F = F.copy()
    split_F[right] = copy[F[right]]
    eye = (0.0, 0.0, 4.0)
    assert len(tm.edges.contours(split_V, split_F, eye=eye)) >= 2
    welded = tm.edges.contours(split_V, split_F, eye=eye, weld=True)
    assert len(welded) == 1 and np.array_equal(welded[0][0], welded[0][-1])


def test_no_suggestive_contours_on_convex_shapes():
    V, F = tm.shapes.icosphere(5)
    for scale in ([1, 1, 1], [2.0, 1.0, 0.6]):
        for eye in [(0, 0, 4.0), (3.0, 1.0, 2.0)]:
            assert tm.edges.suggestive_contours(V * scale, F, eye=eye, threshold=0.0) == []


def _torus_radial(P, eye, R, r):
    """The exact radial curvature of the torus at points P (on or next to it), seen from eye,
    and n . v."""
    u = np.arctan2(P[:, 1], P[:, 0])
    w = np.arctan2(P[:, 2], np.hypot(P[:, 0], P[:, 1]) - R)
    n = np.stack([np.cos(w) * np.cos(u), np.cos(w) * np.sin(u), np.sin(w)], -1)
    tube = np.stack([-np.sin(w) * np.cos(u), -np.sin(w) * np.sin(u), np.cos(w)], -1)
    ring = np.stack([-np.sin(u), np.cos(u), 0 * u], -1)
    view = eye - P
    view /= np.linalg.norm(view, axis=1)[:, None]
    a, b = np.einsum("ij,ij->i", view, tube), np.einsum("ij,ij->i", view, ring)
    kr = (a * a / r + b * b * np.cos(w) / (R + r * np.cos(w))) / (a * a + b * b)
    return kr, np.einsum("ij,ij->i", n, view)


@pytest.mark.parametrize("eye", [(0.0, -4.0, 2.5), (2.5, -2.5, 1.5), (0.5, -3.0, 4.0)])
def test_torus_suggestive_contours_lie_where_radial_curvature_is_zero(eye):
    R, r = 1.0, 0.3
    V, F, _, _ = _torus(R, r)
    eye = np.array(eye)
    lines = tm.edges.suggestive_contours(V, F, eye=eye, threshold=0.0)
    assert lines, "the inner half of a torus seen from beside and above has suggestive contours"
    P = np.concatenate(lines)
    kr, ndotv = _torus_radial(P, eye, R, r)
    assert np.median(np.abs(kr)) * r < 0.005 and np.abs(kr).max() * r < 0.05
    # only where the surface faces the viewer (n . v interpolated over the faces is cut at 0)
    assert np.all(ndotv > -0.01)
    # a higher threshold keeps part of them
    total = _length(lines)
    assert _length(tm.edges.suggestive_contours(V, F, eye=eye, threshold=0.01)) < total
    # and the same, in other units
    scaled = tm.edges.suggestive_contours(V * 250.0, F, eye=eye * 250.0, threshold=0.0)
    assert abs(_length(scaled) / 250.0 - total) < 1e-6 * total


def _mean_edge(V, F):
    return float(np.linalg.norm(V[F] - V[np.roll(F, 1, axis=1)], axis=2).mean())


def test_a_scan_draws_its_shape_not_its_noise():
    from toonmesh.data import bunny

    V, F = bunny()
    eye = V.mean(0) + np.array([0.3, 0.1, 1.0]) * 2.5 * np.ptp(V, 0).max()
    raw = tm.edges.suggestive_contours(V, F, eye=eye, weld=True, smoothing=0.0)
    default = tm.edges.suggestive_contours(V, F, eye=eye, weld=True)
    assert len(default) * 5 < len(raw), (len(default), len(raw))
    lengths = lambda lines: np.array([_length([l]) for l in lines])  # noqa: E731
    assert np.median(lengths(default)) > 2 * np.median(lengths(raw))
    # the default width is 2 mean edges, at most 1% of the diagonal: the bunny's is 1.7 edges
    cap = 0.01 * np.linalg.norm(np.ptp(V, 0)) / _mean_edge(V, F)
    assert 1.0 < cap < 2.0
    explicit = tm.edges.suggestive_contours(V, F, eye=eye, weld=True, smoothing=min(2.0, cap))
    # (the mean edge summed in another order: equal to rounding)
    assert len(explicit) == len(default)
    assert all(np.allclose(a, b, atol=1e-9) for a, b in zip(explicit, default))
    # and it does not depend on units
    scaled = tm.edges.suggestive_contours(V * 1e3, F, eye=eye * 1e3, weld=True)
    assert len(scaled) == len(default)
    assert abs(_length(scaled) / 1e3 - _length(default)) < 1e-6 * _length(default)


def test_a_coarse_mesh_keeps_its_features():
    from conftest import load_mesh

    V, F = load_mesh("cow")
    cap = 0.01 * np.linalg.norm(np.ptp(V, 0)) / _mean_edge(V, F)
    assert cap < 1.0  # the cow's edges are 1.7% of its diagonal
    eye = V.mean(0) + np.array([0.9, 0.3, 1.0]) * 2.5 * np.ptp(V, 0).max()
    default = tm.edges.suggestive_contours(V, F, eye=eye, weld=True)
    at_cap = tm.edges.suggestive_contours(V, F, eye=eye, weld=True, smoothing=cap)
    wide = tm.edges.suggestive_contours(V, F, eye=eye, weld=True, smoothing=2.0)
    assert len(default) == len(at_cap)
    assert _length(default) > 2 * _length(wide)


def test_hard_cases():
    V = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [0, 0, 1], [0, -1, 0]], float)
    F = np.array([[0, 1, 2], [0, 1, 3], [0, 1, 4], [0, 1, 5], [0, 0, 3], [3, 4, 5]])
    for fn in (tm.edges.contours, tm.edges.suggestive_contours):
        for lines in (fn(V, F, eye=(0.5, 0.5, 3)), fn(V, F, direction=(1, 1, 1))):
            assert all(np.all(np.isfinite(l)) and l.shape[1] == 3 for l in lines)
    # an eye on a vertex (no direction toward it there)
    assert all(np.all(np.isfinite(l)) for l in tm.edges.contours(V, F, eye=V[3]))
    with pytest.raises(ValueError, match="vertices"):  # as everywhere, an empty mesh is refused
        tm.edges.contours(np.zeros((0, 3)), np.zeros((0, 3), int), eye=(0, 0, 1))


def test_arguments_are_checked():
    V, F = tm.shapes.icosphere(2)
    with pytest.raises(ValueError, match="eye, direction"):
        tm.edges.contours(V, F)
    with pytest.raises(ValueError, match="threshold"):
        tm.edges.suggestive_contours(V, F, eye=(0, 0, 3), threshold=-1)
    with pytest.raises(ValueError, match="threshold"):
        tm.edges.suggestive_contours(V, F, eye=(0, 0, 3), threshold=float("nan"))
    with pytest.raises(TypeError, match="weld"):
        tm.edges.contours(V, F, eye=(0, 0, 3), weld="yes")
    with pytest.raises(IndexError, match="faces"):
        tm.edges.contours(V, F + 100, eye=(0, 0, 3))


def test_an_edge_index_gives_the_same_lines_for_many_views():
    V, F, _, _ = _torus(n_u=120, n_v=40)
    index = tm.edges.EdgeIndex(V, F, weld=True)
    for eye in [(0.0, -4.0, 2.5), (2.5, -2.5, 1.5), (0.5, -3.0, 4.0)]:
        for mine, theirs in [
            (index.contours(eye=eye), tm.edges.contours(V, F, eye=eye, weld=True)),
            (index.suggestive_contours(eye=eye, threshold=0.0),
             tm.edges.suggestive_contours(V, F, eye=eye, threshold=0.0, weld=True)),
        ]:
            assert len(mine) == len(theirs) > 0
            for a, b in zip(mine, theirs):
                np.testing.assert_array_equal(a, b)
