"""Intersection lines (toonmesh.edges.intersections, intersection_lines): held exactly against
the all-pairs reference, against the analytic curves of two crossing cylinders, and on the hard
cases (coplanar, touching, degenerate, far away, tiny)."""

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core
from toonmesh.edges import intersection_lines, intersections


def reference(meshes, self_intersections=False):
    """Every pair of triangles compared (no hierarchy), with the same triangle rule."""
    from toonmesh.edges import _mesh_list

    return _core._intersections(_mesh_list(meshes), self_intersections, True)


def rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.diag(r))


def moved(mesh, matrix=np.eye(3), offset=(0.0, 0.0, 0.0)):
    V, F = mesh
    return V @ np.asarray(matrix).T + offset, F


def soup(rng, n, size=0.5):
    centres = rng.uniform(-1, 1, (n, 1, 3))
    V = (centres + rng.uniform(-size, size, (n, 3, 3))).reshape(-1, 3)
    return V, np.arange(3 * n).reshape(n, 3)


def tube(sections=96, length=3.0, rings=6):
    """An open tube of radius 1 about the y axis, from -length to length."""
    V, F = tm.shapes.lathe(np.stack([np.ones(rings + 1), np.linspace(-length, length, rings + 1)], axis=1), sections)
    return V, F


def box(lo, hi):
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    V = np.array([[(hi if (k >> a) & 1 else lo)[a] for a in range(3)] for k in range(8)])
    F = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                  [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]])
    return V, F


def pin_and_plate():
    """A closed pin (a 24-sided cylinder, tilted, off-centre) through a plate 0.2 thick."""
    pin = tm.shapes.lathe([(0, -2), (0.3, -2), (0.3, 2), (0, 2)], 24)
    c, s = np.cos(0.2), np.sin(0.2)
    pin = moved(pin, [[c, -s, 0], [s, c, 0], [0, 0, 1]], (0.13, 0.0, -0.07))
    return [pin, box((-1.5, -0.1, -1.2), (1.4, 0.1, 1.3))]


def as_set(segments, decimals=None):
    s = np.asarray(segments)
    if decimals is not None:
        s = np.round(s, decimals)
    return {tuple(sorted(map(tuple, seg.tolist()))) for seg in s}


def test_the_hierarchy_finds_exactly_what_all_pairs_find():
    rng = np.random.default_rng(5)
    soups = [soup(rng, 300) for _ in range(3)]
    got = intersections(soups, self_intersections=True)
    assert len(got) > 500
    np.testing.assert_array_equal(got, reference(soups, self_intersections=True))
    # closed meshes turned, scaled and moved at random, float32 among them
    shapes = [tm.shapes.icosphere(3), tm.shapes.torus(segments=40, tube_segments=20), tm.shapes.uv_sphere(30, 20)]
    scene = [moved(m, rotation(rng) * rng.uniform(0.6, 1.2), rng.uniform(-0.4, 0.4, 3)) for m in shapes]
    scene[1] = (scene[1][0].astype(np.float32), scene[1][1])
    got = intersections(scene)
    assert len(got) > 300
    np.testing.assert_array_equal(got, reference(scene))
    assert got.dtype == np.float64 and got.shape[1:] == (2, 3)


def test_a_mesh_with_itself_is_two_meshes_joined():
    a = tm.shapes.icosphere(3)
    b = moved(tm.shapes.icosphere(3), offset=(0.6, 0.1, 0.05))
    joined = (np.concatenate([a[0], b[0]]), np.concatenate([a[1], b[1] + len(a[0])]))
    apart = intersections([a, b])
    assert len(apart) > 50
    assert len(intersections([joined])) == 0
    np.testing.assert_array_equal(intersections([joined], self_intersections=True), apart)


def test_crossing_cylinders_follow_the_analytic_curves():
    along_y = tube()
    along_x = moved(along_y, [[0, 1, 0], [-1, 0, 0], [0, 0, 1]])
    segments = intersections([along_x, along_y])
    # the curves: two ellipses (cos t, +-cos t, sin t), where y^2 + z^2 = 1 and x^2 + z^2 = 1
    t = np.linspace(0, 2 * np.pi, 4000, endpoint=False)
    curve = np.concatenate([np.stack([np.cos(t), s * np.cos(t), np.sin(t)], axis=1) for s in (1, -1)])
    ends = segments.reshape(-1, 3)
    nearest = np.sqrt(((ends[:, None, :] - curve[None, :, :]) ** 2).sum(axis=2)).min(axis=1)
    assert nearest.max() < 0.01
    # their length, by the trapezoid rule (exact to rounding for a smooth periodic integrand)
    analytic = 2 * np.mean(np.sqrt(2 * np.sin(t) ** 2 + np.cos(t) ** 2)) * 2 * np.pi
    length = np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1).sum()
    assert 0.97 < length / analytic < 1.03, (length, analytic)
    # joined into closed loops, even where an edge of one tube crosses an edge of the other (at
    # every section on the ellipse x = -y: the two tubes have their edges at the same angles)
    lines = intersection_lines([along_x, along_y])
    assert len(lines) <= 4 and all((line[0] == line[-1]).all() for line in lines)
    assert sum(len(line) - 1 for line in lines) == len(segments)
    assert np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1).min() > 1e-6


def test_a_pin_through_a_plate_gives_two_closed_loops():
    scene = pin_and_plate()
    lines = intersection_lines(scene)
    segments = intersections(scene)
    assert len(lines) == 2
    assert sum(len(line) - 1 for line in lines) == len(segments)
    for line in lines:
        assert line.shape[1] == 3 and line.dtype == np.float64
        np.testing.assert_array_equal(line[0], line[-1])
        # on one face of the plate, around the pin
        assert np.abs(np.abs(line[:, 1]) - 0.1).max() < 1e-15
    assert sorted(np.sign(line[0, 1]) for line in lines) == [-1, 1]


@pytest.mark.parametrize("scale, offset", [(1e-3, 0.0), (1.0, 1e6), (1e-3, 1e3)])
def test_far_away_and_tiny_scenes_give_the_same_lines(scale, offset):
    scene = pin_and_plate()
    want = intersections(scene)
    far = [moved(m, np.eye(3) * scale, offset) for m in scene]
    got = intersections(far)
    assert np.isfinite(got).all() and got.shape == want.shape
    np.testing.assert_allclose((got - offset) / scale, want, atol=1e-6)
    lines = intersection_lines(far)
    assert len(lines) == 2 and all((line[0] == line[-1]).all() for line in lines)


def test_coplanar_touching_and_degenerate_faces_give_no_lines():
    flat = (np.array([[0, 0, 0], [2, 0, 0], [0, 2, 0.0]]), np.array([[0, 1, 2]]))
    over = (np.array([[0.5, 0.5, 0], [3, 0.5, 0], [0.5, 3, 0.0]]), np.array([[0, 2, 1]]))
    for offset in (0.0, 1e6):
        assert intersections([moved(flat, offset=offset), moved(over, offset=offset)]).shape == (0, 2, 3)
    # resting on each other, a face on a face; the same mesh twice
    lower, upper = box((0, 0, 0), (1, 1, 1)), box((0.2, 0.3, 1), (0.7, 0.8, 1.5))
    assert len(intersections([lower, upper])) == 0
    sphere = tm.shapes.icosphere(2)
    assert len(intersections([sphere, sphere])) == 0
    # faces without area (a repeated index, collinear corners) add nothing to a crossing
    V, F = moved(tm.shapes.icosphere(2), offset=(0.5, 0, 0))
    V = np.concatenate([V, [[0.5, -2, 0], [0.5, 0, 0], [0.5, 2, 0]]])
    F_bad = np.concatenate([F, [[0, 0, 5], [len(V) - 3, len(V) - 2, len(V) - 1]]])
    got = intersections([sphere, (V, F_bad)], self_intersections=True)
    np.testing.assert_array_equal(got, intersections([sphere, (V, F)], self_intersections=True))
    assert len(got) > 20 and np.isfinite(got).all()


def test_an_edge_lying_in_the_other_surface_is_given_once():
    # a UV sphere's equator lies in the floor z = 0 (its poles on the y axis: turn it)
    V, F = tm.shapes.uv_sphere(16, 8)
    sphere = moved((V, F), [[1, 0, 0], [0, 0, -1], [0, 1, 0]])
    floor = (np.array([[-3, -3, 0], [3, -3, 0], [3, 3, 0], [-3, 3, 0.0]]), np.array([[0, 1, 2], [0, 2, 3]]))
    segments = intersections([sphere, floor])
    lines = intersection_lines([sphere, floor])
    assert len(lines) == 1 and (lines[0][0] == lines[0][-1]).all()
    assert np.abs(segments[..., 2]).max() < 1e-15
    # the 16 equator edges, once each, cut where the floor's diagonal crosses them
    length = np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1).sum()
    assert length == pytest.approx(32 * np.sin(np.pi / 16), rel=1e-12)


def test_fewer_than_two_meshes_and_bad_input():
    sphere = tm.shapes.icosphere(1)
    for meshes in ([], [sphere]):
        got = intersections(meshes)
        assert got.shape == (0, 2, 3) and got.dtype == np.float64
        assert intersection_lines(meshes) == []
    with pytest.raises(TypeError, match=r"^meshes: expected a list"):
        intersections(sphere[0])
    with pytest.raises(TypeError, match=r"^meshes\[1\]: faces: required"):
        intersections([sphere, sphere[0]])
    bad = sphere[0].copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"^meshes\[2\]\.vertices: "):
        intersections([sphere, sphere, (bad, sphere[1])])
    with pytest.raises(IndexError, match=r"^meshes\[1\]\.faces: "):
        intersections([sphere, (sphere[0], sphere[1] + 1)])
    with pytest.raises(TypeError, match=r"^meshes\[0\]\.faces: "):
        intersection_lines([(sphere[0], sphere[1].astype(float)), sphere])
    with pytest.raises(TypeError, match=r"^self_intersections: "):
        intersections([sphere, sphere], self_intersections="yes")
    # nothing modified in place
    V = sphere[0].copy()
    intersections([sphere, moved(sphere, offset=(0.5, 0, 0))])
    np.testing.assert_array_equal(V, sphere[0])
