"""Properties over random meshes and images (hypothesis).

Meshes mix clean parts (a noisy icosphere or grid, or random triangles) with the hard parts real
data has: holes, faces that repeat an index, collinear faces, duplicated vertices (seams),
non-manifold fins and vertices no face uses. The properties:

- finite input gives finite output (or a documented exception) from every smoothing method and
  every outline function;
- smoothing commutes with rotations, translations and uniform scaling, to the dtype's precision
  relative to the bounding-box diagonal;
- feature edges are invariant under the same motions, away from the crease threshold;
- silhouettes are invariant under a joint motion of mesh and eye, away from edge-on faces;
- Sobel is linear (sobel_h, sobel_v) and its magnitude positively homogeneous;
- a render is unchanged (colour and outline coverage, to rounding) when mesh, camera and lights
  move and scale together.

CI runs a bounded, derandomized number of examples (the "ci" profile in conftest.py);
``TOONMESH_LONG_TESTS=1`` runs many more.
"""

from __future__ import annotations

import os

import numpy as np
import pytest

try:
    from hypothesis import assume, given
    from hypothesis import strategies as st
    from hypothesis.extra.numpy import arrays
except ImportError:
    if os.environ.get("CI", "").lower() == "true":
        raise
    pytest.skip("hypothesis is not installed", allow_module_level=True)

import toonmesh as tm
from toonmesh import edges as te

# ------------------------------------------------------------------------------------------------
# Random meshes


@st.composite
def meshes(draw):
    """(V float64, F int64) with some of the hard parts real meshes have."""
    seed = draw(st.integers(0, 2**32 - 1))
    rng = np.random.default_rng(seed)
    base = draw(st.sampled_from(["sphere", "grid", "triangles"]))
    if base == "sphere":
        V, F = tm.shapes.icosphere(1, noise=0.15, seed=seed)
    elif base == "grid":
        V, F = tm.shapes.grid(draw(st.integers(2, 7)), noise=0.2, seed=seed)
    else:
        n = draw(st.integers(3, 24))
        V = rng.uniform(-1, 1, (n, 3))
        F = rng.integers(0, n, (draw(st.integers(1, 30)), 3))
    V, F = V.copy(), F.copy()
    if draw(st.booleans()):  # holes
        keep = rng.random(len(F)) > 0.25
        F = F[keep] if keep.any() else F[:1]
    if draw(st.booleans()):  # a face that repeats an index
        F = np.vstack([F, [[F[0, 0], F[0, 0], F[0, 1]]]])
    if draw(st.booleans()):  # a collinear face
        a, b = F[0, 0], F[0, 1]
        V = np.vstack([V, (V[a] + V[b]) / 2])
        F = np.vstack([F, [[a, b, len(V) - 1]]])
    if draw(st.booleans()):  # a seam: one vertex stored twice, some faces use the copy
        i = F[-1, 2]
        V = np.vstack([V, V[i]])
        F[-1, 2] = len(V) - 1
    if draw(st.booleans()):  # a non-manifold fin on an edge
        a, b = F[0, 1], F[0, 2]
        V = np.vstack([V, V[a] + [0.1, -0.2, 0.5]])
        F = np.vstack([F, [[a, b, len(V) - 1]]])
    if draw(st.booleans()):  # a vertex no face uses
        V = np.vstack([V, [[3.0, -2.0, 1.0]]])
    return V, F.astype(np.int64)


@st.composite
def motions(draw, scale=True):
    """(R, t, s): a proper rotation, a translation of up to 10 diagonals, a scale in [1e-3, 1e3]."""
    q = np.array(draw(st.lists(st.floats(-1, 1), min_size=4, max_size=4)))
    assume(np.linalg.norm(q) > 0.1)
    a, b, c, d = q / np.linalg.norm(q)
    R = np.array(
        [
            [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
            [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
            [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d],
        ]
    )
    t = np.array(draw(st.lists(st.floats(-10, 10), min_size=3, max_size=3)))
    s = 10.0 ** draw(st.floats(-3, 3)) if scale else 1.0
    return R, t, s


def moved(X, motion, diag):
    R, t, s = motion
    return (X @ R.T) * s + t * diag * s


def diagonal(V):
    return float(np.linalg.norm(V.max(0) - V.min(0)))


def relative_areas(V, F):
    """|cross| / longest edge squared per face (0 when all corners coincide)."""
    p = V[F]
    e = [p[:, 2] - p[:, 1], p[:, 0] - p[:, 2], p[:, 1] - p[:, 0]]
    longest = np.max([np.einsum("ij,ij->i", x, x) for x in e], axis=0)
    cross = np.linalg.norm(np.cross(e[0], e[1]), axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(longest > 0, cross / longest, 0.0)


def well_conditioned(V, F):
    """No face near the degenerate threshold (relative area 1e-12), where rounding decides."""
    r = relative_areas(V, F)
    return not np.any((r > 1e-14) & (r < 1e-10))


def cotangent_rows_clear_of_zero(V, F):
    """A vertex whose clamped cotangent weights all vanish falls back to uniform weights: a jump.
    True when no vertex's largest edge weight is within 1e-7 of zero."""
    p = V[F]
    e = [p[:, 2] - p[:, 1], p[:, 0] - p[:, 2], p[:, 1] - p[:, 0]]
    longest = np.max([np.einsum("ij,ij->i", x, x) for x in e], axis=0)
    twice_area = np.maximum(np.linalg.norm(np.cross(e[0], e[1]), axis=1), 1e-4 * longest)
    weights = {}
    for k in range(3):
        with np.errstate(invalid="ignore", divide="ignore"):
            cot = np.where(longest > 0, -np.einsum("ij,ij->i", e[(k + 1) % 3], e[(k + 2) % 3]) / twice_area, 0.0)
        a, b = F[:, (k + 1) % 3], F[:, (k + 2) % 3]
        for i, j, c in zip(a, b, cot):
            if i != j:
                key = (min(i, j), max(i, j))
                weights[key] = weights.get(key, 0.0) + c
    best = {}
    for (i, j), w in weights.items():
        best[i] = max(best.get(i, -np.inf), w)
        best[j] = max(best.get(j, -np.inf), w)
    return all(abs(w) > 1e-7 for w in best.values())


def volume_clear_of_threshold(V, F, dtype):
    """The volume constraint is skipped on meshes that enclose (almost) no volume, or whose
    faces' vector area does not vanish (open ones): jumps at 1e-12 diagonal^3 and at 1e3 eps of
    the total area. True when the mesh is far from both."""
    c = V.mean(0)
    a, b, d = (V[F[:, k]] - c for k in range(3))
    vol = abs(np.einsum("ij,ij->i", a, np.cross(b, d)).sum() / 6)
    ref = 1e-12 * diagonal(V) ** 3
    n = np.cross(b - a, d - a)
    openness = np.linalg.norm(n.sum(0)) / max(np.linalg.norm(n, axis=1).sum(), 1e-300)
    closed = 1e3 * np.finfo(dtype).eps
    return not (ref / 100 < vol < ref * 100) and not (closed / 30 < openness < closed * 30)


# ------------------------------------------------------------------------------------------------
# Smoothing


SMOOTHERS = {
    "laplacian": tm.smooth.laplacian,
    "taubin": tm.smooth.taubin,
    "hc": tm.smooth.hc,
    "implicit": tm.smooth.implicit,
}


@st.composite
def smoothing_options(draw):
    method = draw(st.sampled_from(sorted(SMOOTHERS)))
    boundaries = ["fixed", "free"] if method == "implicit" else ["fixed", "free", "slide"]
    kw = dict(
        weights=draw(st.sampled_from(["uniform", "cotangent", "distance"])),
        boundary=draw(st.sampled_from(boundaries)),
        iterations=draw(st.integers(1, 3 if method == "implicit" else 8)),
    )
    if method in ("laplacian", "implicit"):
        kw["volume_constraint"] = draw(st.booleans())
    if method == "implicit":
        kw["tol"] = 1e-13
    if draw(st.booleans()):
        kw["pinned"] = [0]
    return method, kw


def smooth(method, X, F, kw):
    try:
        return SMOOTHERS[method](X, F, **kw)
    except tm.ConvergenceError:
        assume(False)  # documented: the solve may not reach a tolerance this tight


@given(meshes(), smoothing_options(), st.sampled_from([np.float64, np.float32]))
def test_smoothing_finite_input_gives_finite_output(mesh, options, dtype):
    V, F = mesh
    method, kw = options
    out = smooth(method, V.astype(dtype), F, kw)
    assert out.dtype == dtype and out.shape == V.shape
    assert np.isfinite(out).all()


@given(meshes(), smoothing_options(), motions(), st.sampled_from([np.float64, np.float32]))
def test_smoothing_commutes_with_rigid_motion_and_scale(mesh, options, motion, dtype):
    V, F = mesh
    method, kw = options
    if kw["weights"] == "cotangent":
        assume(cotangent_rows_clear_of_zero(V, F))
    if kw.get("volume_constraint"):
        assume(volume_clear_of_threshold(V, F, dtype))
    d = diagonal(V)
    X = V.astype(dtype).astype(np.float64)  # the positions both runs start from
    Y = moved(X, motion, d)
    out = smooth(method, X.astype(dtype), F, kw).astype(np.float64)
    out_moved = smooth(method, Y.astype(dtype), F, kw).astype(np.float64)
    expected = moved(out, motion, d)
    # Rounding grows with the coordinates' magnitude, which the translation raises.
    magnitude = max(np.abs(Y).max() / diagonal(Y), 1.0)
    tol = (1e-9 if dtype == np.float64 else 1e-3) * magnitude
    err = np.abs(out_moved - expected).max() / diagonal(Y)
    assert err <= tol, f"{method} {kw}: {err:.2e} > {tol:.2e}"


# ------------------------------------------------------------------------------------------------
# Outlines


@given(meshes(), st.floats(0, 180), st.booleans())
def test_outlines_finite_input_gives_finite_output(mesh, angle, weld):
    V, F = mesh
    fe = te.feature_edges(V, F, crease_angle=angle, weld=weld)
    assert np.all((fe.crease_angles > angle) & (fe.crease_angles <= 180))
    for e in (fe.boundary, fe.crease, fe.nonmanifold):
        assert e.dtype == np.int64 and e.shape[1:] == (2,) and np.all(e[:, 0] < e[:, 1])
    index = te.EdgeIndex(V, F, crease_angle=angle, weld=weld)
    assert np.isfinite(index.face_normals).all()
    for view in (dict(eye=(0.3, 2.0, 4.0)), dict(direction=(0.0, -1.0, 0.2))):
        sil = index.silhouette(**view)
        assert np.array_equal(sil, te.silhouette(V, F, weld=weld, **view))
        lines = index.outlines(**view)
        segs = te.segments(V, lines)
        assert segs.shape == (len(lines), 2, 3) and np.isfinite(segs).all()
        assert sum(len(c) - 1 for c in te.chains(lines)) == len(lines)


@given(meshes(), st.booleans(), st.sampled_from([np.float64, np.float32]))
def test_curvature_and_contours_finite_input_gives_finite_output(mesh, weld, dtype):
    V, F = mesh
    V = V.astype(dtype)
    c = te.curvature(V, F)
    for a in (c.k1, c.k2, c.d1, c.d2, c.normals, c.derivatives):
        assert a.dtype == np.float64 and np.isfinite(a).all()
    assert np.all(c.k1 >= c.k2)
    np.testing.assert_allclose(np.linalg.norm(c.d1, axis=1), 1.0, rtol=1e-9)
    index = te.EdgeIndex(V, F, weld=weld)
    for view in (dict(eye=(0.3, 2.0, 4.0)), dict(direction=(0.0, -1.0, 0.2))):
        for lines in (index.contours(**view), index.suggestive_contours(threshold=0.0, **view)):
            assert all(l.ndim == 2 and l.shape[1] == 3 and len(l) >= 2 and np.isfinite(l).all() for l in lines)
        assert [len(l) for l in index.contours(**view)] == [len(l) for l in te.contours(V, F, weld=weld, **view)]


@given(meshes(), motions(), st.floats(1, 179))
def test_feature_edges_invariant_under_rigid_motion_and_scale(mesh, motion, angle):
    V, F = mesh
    assume(well_conditioned(V, F))
    every = te.feature_edges(V, F, crease_angle=0.0)
    # No dihedral angle near the threshold, and no fold near 180 degrees (where convexity is
    # the sign of a vanishing cross product).
    assume(np.all(np.abs(every.crease_angles - angle) > 1e-6))
    assume(np.all(every.crease_angles < 180 - 1e-6))
    Y = moved(V, motion, diagonal(V))
    a, b = te.feature_edges(V, F, crease_angle=angle), te.feature_edges(Y, F, crease_angle=angle)
    for name in ("boundary", "crease", "nonmanifold", "degenerate_faces", "crease_convex"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert np.allclose(a.crease_angles, b.crease_angles, atol=1e-7)


@given(meshes(), motions(), st.lists(st.floats(-3, 3), min_size=3, max_size=3), st.booleans())
def test_silhouettes_invariant_under_joint_motion_of_mesh_and_eye(mesh, motion, eye, orthographic):
    V, F = mesh
    assume(well_conditioned(V, F))
    d = diagonal(V)
    eye = np.array(eye) * d + V.mean(0) + [0.0, 0.0, 2.5 * d]
    # Skip views where some face is nearly edge-on: there rounding decides its side.
    p = V[F]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    norm = np.linalg.norm(n, axis=1)
    defined = relative_areas(V, F) > 1e-12
    v = (np.array([0.1, -0.3, -1.0]) if orthographic else p[:, 0] - eye)
    v = np.broadcast_to(v, p[:, 0].shape)
    with np.errstate(invalid="ignore", divide="ignore"):
        cos = np.einsum("ij,ij->i", n, v) / (norm * np.linalg.norm(v, axis=1))
    assume(np.all(np.abs(cos[defined]) > 1e-7))
    R, t, s = motion
    Y = moved(V, motion, d)
    if orthographic:
        a = te.silhouette(V, F, direction=(0.1, -0.3, -1.0))
        b = te.silhouette(Y, F, direction=R @ np.array([0.1, -0.3, -1.0]))
    else:
        a = te.silhouette(V, F, eye=eye)
        b = te.silhouette(Y, F, eye=moved(eye[None], motion, d)[0])
    assert np.array_equal(a, b)


# ------------------------------------------------------------------------------------------------
# Sobel


def images(dtype):
    shapes = st.tuples(st.integers(1, 12), st.integers(1, 12))
    return shapes.flatmap(lambda s: st.tuples(*(arrays(dtype, s, elements=st.floats(-1e3, 1e3, width=32)) for _ in range(2))))


# Factors of 0 or of magnitude 1e-3 to 100 (smaller ones would underflow float32 images).
FACTORS = st.one_of(st.just(0.0), st.floats(1e-3, 100), st.floats(-100, -1e-3))


@given(
    st.sampled_from([np.float64, np.float32]).flatmap(images),
    FACTORS,
    FACTORS,
    st.sampled_from(["skimage", "opencv"]),
)
def test_sobel_is_linear(pair, a, b, convention):
    x, y = pair
    eps = float(np.finfo(x.dtype).eps)
    combo = (a * x.astype(np.float64) + b * y.astype(np.float64)).astype(x.dtype)
    scale = abs(a) * float(np.abs(x).max()) + abs(b) * float(np.abs(y).max()) + float(np.finfo(x.dtype).tiny)
    for f in (te.sobel_h, te.sobel_v):
        lhs = f(combo, convention=convention).astype(np.float64)
        rhs = a * f(x, convention=convention).astype(np.float64) + b * f(y, convention=convention).astype(np.float64)
        assert np.abs(lhs - rhs).max() <= 64 * eps * scale, f.__name__
    g = te.sobel(x, convention=convention).astype(np.float64)
    assert np.isfinite(g).all() and (g >= 0).all()
    ga = te.sobel((a * x.astype(np.float64)).astype(x.dtype), convention=convention).astype(np.float64)
    assert np.abs(ga - abs(a) * g).max() <= 64 * eps * scale


# ------------------------------------------------------------------------------------------------
# Shapes


@given(st.integers(0, 4), st.floats(0, 1), st.integers(0, 2**64 - 1))
def test_icosphere_is_a_closed_unit_sphere_within_its_noise(s, noise, seed):
    V, F = tm.shapes.icosphere(s, noise=noise, seed=seed)
    assert V.shape == (10 * 4**s + 2, 3) and F.shape == (20 * 4**s, 3)
    r = np.linalg.norm(V, axis=1)
    assert np.isfinite(V).all() and np.all(np.abs(r - 1) <= noise * (1 + 1e-12) + 1e-12)
    assert len(te.feature_edges(V, F).boundary) == 0


@given(st.integers(2, 40), st.floats(0, 10), st.integers(0, 2**64 - 1))
def test_grid_is_an_open_square(n, noise, seed):
    V, F = tm.shapes.grid(n, noise=noise, seed=seed)
    assert V.shape == (n * n, 3) and F.shape == (2 * (n - 1) ** 2, 3)
    assert np.isfinite(V).all() and np.all(np.abs(V[:, 2]) <= noise)
    assert len(te.feature_edges(V, F).boundary) == 4 * (n - 1)


# ------------------------------------------------------------------------------------------------
# Rendering


RENDERER = tm.Renderer()
RENDER_SIZE = dict(width=48, height=48)
UNIT = st.lists(st.floats(-1, 1), min_size=3, max_size=3).map(np.array).filter(lambda v: np.linalg.norm(v) > 0.2)


@st.composite
def scenes(draw):
    """A mesh, a camera looking at it from 1 to 2 diagonals away (eye, target, up; the mesh fills
    10% to 90% of the image), a world-space light (directional or point) and a toon material."""
    seed = draw(st.integers(0, 2**32 - 1))
    if draw(st.booleans()):
        V, F = tm.shapes.icosphere(2, noise=0.1, seed=seed)
    else:
        V, F = tm.shapes.grid(draw(st.integers(3, 9)), noise=0.2, seed=seed)
    d = diagonal(V)
    center = V.mean(0)
    view = draw(UNIT)
    view = view / np.linalg.norm(view)
    eye = center + view * d * draw(st.floats(1.0, 2.0))
    target = center + draw(UNIT) * 0.1 * d
    up = draw(UNIT)
    assume(np.linalg.norm(np.cross(up / np.linalg.norm(up), eye - target) / np.linalg.norm(eye - target)) > 0.3)
    if draw(st.booleans()):
        light = ("directional", draw(UNIT))
    else:  # outside the mesh, on the camera's side
        light = ("point", center + (view + draw(UNIT) * 0.5) * 2.0 * d)
    if draw(st.booleans()):
        material = tm.Material.thresholded_phong(
            (0.9, 0.5, 0.2), t_h=draw(st.floats(-0.3, 0.5)), highlight=draw(st.sampled_from(["blinn", "paper"])),
            per_vertex=draw(st.booleans()),
        )
    else:
        material = tm.Material.bands((0.2, 0.6, 0.9), per_vertex=draw(st.booleans()))
    return V, F, eye, target, up, light, material


def render_scene(V, F, eye, target, up, light, material, transform=None):
    kind, where = light
    lit = tm.Light.directional(where) if kind == "directional" else tm.Light.point(where)
    camera = tm.Camera.look_at(eye, target, up=up)
    return RENDERER.render(
        tm.Mesh(V, F, transform=transform), material=material, camera=camera, lights=[lit],
        outputs=("color", "outline"), outlines="mesh", **RENDER_SIZE,
    )


# Both images come from the same view-space scene up to float64 rounding, so a pixel differs
# only where that rounding moves a triangle's edge or a shading threshold (t_h, a band) across
# its centre. Measured on lavapipe over 2000 examples: at most 1 pixel of 2304 (0.04%) differs by
# more than 8/255, and the outline coverage by at most 5e-5 of itself. The bounds leave room for
# GPUs that rasterize with fewer sub-pixel bits.
MAX_DIFFERING_PIXELS = 0.005
MAX_OUTLINE_CHANGE = 0.01


@given(scenes(), motions(), st.booleans())
def test_render_agrees_with_its_scene_moved_with_the_camera(scene, motion, via_transform):
    """A rigid motion and uniform scale (1e-3 to 1e3) of mesh, camera and light together leaves
    the image unchanged: the mesh moved (its vertices, or by its transform), the camera's eye and
    target moved and its up turned, a directional light turned, a point light moved."""
    V, F, eye, target, up, (kind, where), material = scene
    R, t, s = motion
    d = diagonal(V)

    def move(p):
        return moved(np.asarray(p, np.float64)[None], motion, d)[0]

    a = render_scene(V, F, eye, target, up, (kind, where), material)
    light = (kind, R @ where if kind == "directional" else move(where))
    if via_transform:
        M = np.eye(4)
        M[:3, :3] = s * R
        M[:3, 3] = move(np.zeros(3))
        b = render_scene(V, F, move(eye), move(target), R @ up, light, material, transform=M)
    else:
        b = render_scene(moved(V, motion, d), F, move(eye), move(target), R @ up, light, material)
    differ = np.abs(a.color.astype(int) - b.color.astype(int)).max(axis=2) > 8
    assert differ.mean() <= MAX_DIFFERING_PIXELS, f"{differ.mean():.2%} of the pixels differ"
    ink_a, ink_b = float(a.outline.mean()), float(b.outline.mean())
    assert ink_a > 0, "the outlines are drawn"
    assert abs(ink_a - ink_b) <= MAX_OUTLINE_CHANGE * ink_a, f"outline coverage {ink_a:.4f} != {ink_b:.4f}"


# ------------------------------------------------------------------------------------------------
# Feature-preserving smoothing (normal filtering)


@st.composite
def normal_filter_options(draw):
    kw = dict(iterations=draw(st.integers(0, 6)), vertex_iterations=draw(st.integers(1, 6)))
    if draw(st.booleans()):
        kw["sigma_r"] = draw(st.floats(0.05, 1.0))
    if draw(st.booleans()):
        kw["pinned"] = [0]
    return draw(st.sampled_from(["bilateral", "guided"])), kw


@given(meshes(), normal_filter_options(), st.sampled_from([np.float64, np.float32]))
def test_normal_filtering_finite_input_gives_finite_output(mesh, options, dtype):
    V, F = mesh
    method, kw = options
    out = getattr(tm.smooth, method)(V.astype(dtype), F, **kw)
    assert out.dtype == dtype and out.shape == V.shape
    assert np.isfinite(out).all()
