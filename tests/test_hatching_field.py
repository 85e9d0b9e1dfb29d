"""Hatching along the form (the default `mode="field"`): strokes follow a cylinder's principal
directions, stay on the surface when the camera moves, and are the same bits every time. The
orientation measure reads the strokes back from the image (structure tensor of the ink) and
compares them with the projected axis and circumference; the triplanar mode's value is printed
beside it."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm

SIZE = 256
EYE = np.array([0.0, 1.2, 5.0])


def cylinder(around=96, rows=48, radius=0.5, height=2.0, capped=False):
    """A cylinder standing on the y axis, `rows` rows of quads split in two."""
    a = np.linspace(0, 2 * np.pi, around, endpoint=False)
    y = np.linspace(-height / 2, height / 2, rows + 1)
    V = np.array([[radius * np.cos(t), h, -radius * np.sin(t)] for h in y for t in a])
    F = []
    for r in range(rows):
        for k in range(around):
            i, j = r * around + k, r * around + (k + 1) % around
            F += [[i, j, j + around], [i, j + around, i + around]]
    if capped:
        for h, ring, flip in ((-height / 2, 0, True), (height / 2, rows * around, False)):
            c = len(V)
            V = np.vstack([V, [[0.0, h, 0.0]]])
            for k in range(around):
                i, j = ring + k, ring + (k + 1) % around
                F.append([c, j, i] if flip else [c, i, j])
    return V, np.array(F)


def camera(shift=0.0):
    offset = np.array([shift, 0.0, 0.0])
    return tm.Camera.orthographic(tuple(EYE + offset), target=tuple(offset), height=2.6)


def render(renderer, mesh, material, shift=0.0):
    return renderer.render(mesh, material=material, camera=camera(shift), width=SIZE, height=SIZE,
                           outputs=("color", "normal"))


def blur(a):
    k = np.array([1.0, 4.0, 6.0, 4.0, 1.0]) / 16
    for axis in (0, 1):
        a = np.apply_along_axis(lambda m: np.convolve(m, k, mode="same"), axis, a)
    return a


def principal_share(res, tolerance=15.0):
    """Share of stroke-edge pixels whose edge runs within `tolerance` degrees of the projected
    axis or circumference of the cylinder (standing on y)."""
    grey = res.color[..., :3].astype(float).mean(-1) / 255
    gx = np.zeros_like(grey)
    gy = np.zeros_like(grey)
    p = np.pad(grey, 1, mode="edge")
    gx = (p[:-2, 2:] + 2 * p[1:-1, 2:] + p[2:, 2:]) - (p[:-2, :-2] + 2 * p[1:-1, :-2] + p[2:, :-2])
    gy = (p[2:, :-2] + 2 * p[2:, 1:-1] + p[2:, 2:]) - (p[:-2, :-2] + 2 * p[:-2, 1:-1] + p[:-2, 2:])
    jxx, jxy, jyy = blur(gx * gx), blur(gx * gy), blur(gy * gy)
    # the gradient's dominant orientation (image x right, y down); strokes run across it
    theta = 0.5 * np.arctan2(2 * jxy, jxx - jyy) + np.pi / 2
    energy = jxx + jyy
    n = res.normal
    covered = res.color[..., 3] > 0
    # the view's basis: the axis (world y) and each pixel's circumference direction (axis x n)
    f = -EYE / np.linalg.norm(EYE)
    right = np.cross(f, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, f)
    axis = np.array([np.dot([0, 1, 0], right), np.dot([0, 1, 0], up), np.dot([0, 1, 0], -f)])
    around = np.cross(axis, n)
    # edges of ink strokes on the side wall, away from the silhouette and the rims
    edge = covered & (energy > 0.05 * energy[covered].max()) & (np.abs(n[..., 2]) > 0.35)
    edge &= np.abs((n * axis).sum(-1)) < 0.2
    screen = lambda d: np.arctan2(-d[..., 1], d[..., 0])  # noqa: E731  image y points down
    def off(a, b):
        d = np.abs(a - b) % np.pi
        return np.degrees(np.minimum(d, np.pi - d))
    best = np.minimum(off(theta, screen(np.broadcast_to(axis, n.shape))), off(theta, screen(around)))
    assert edge.sum() > 2000, f"only {edge.sum()} stroke-edge pixels"
    return float((best[edge] <= tolerance).mean())


@pytest.mark.parametrize("capped", [False, True])
def test_field_strokes_follow_a_standing_cylinders_principal_directions(capped):
    r = tm.Renderer()
    mesh = r.add_mesh(*cylinder(capped=capped))
    field = principal_share(render(r, mesh, tm.Material.hatching()))
    triplanar = principal_share(render(r, mesh, tm.Material.hatching(mode="triplanar")))
    print(f"\ncylinder (capped={capped}): strokes within 15 degrees of a principal direction: "
          f"field {field:.0%}, triplanar {triplanar:.0%}")
    assert field >= 0.70, (field, triplanar)
    assert field > triplanar + 0.2, (field, triplanar)


def test_field_hatching_is_the_same_bits_every_time():
    V, F = cylinder()
    a = tm.render(V, F, material=tm.Material.hatching(), camera=camera(), width=96, height=96).color
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    b = r.render(mesh, material=tm.Material.hatching(), camera=camera(), width=96, height=96).color
    c = r.render(mesh, material=tm.Material.hatching(), camera=camera(), width=96, height=96).color
    assert np.array_equal(a, b) and np.array_equal(b, c)
    assert (a[..., :3] < 100).any(), "some ink"


def test_field_strokes_move_with_the_surface():
    # the camera slides 7 pixels sideways: the image slides with it, strokes included (a pattern
    # anchored to the screen would stay put)
    r = tm.Renderer()
    mesh = r.add_mesh(*cylinder())
    pixel = 2.6 / SIZE
    a = render(r, mesh, tm.Material.hatching()).color[..., :3].astype(int)
    b = render(r, mesh, tm.Material.hatching(), shift=7 * pixel).color[..., :3].astype(int)
    moved = np.abs(a[:, 7:] - b[:, :-7]).mean()
    still = np.abs(a - b).mean()
    assert moved < 1.0, moved
    assert still > 5 * moved + 1.0, (still, moved)


def test_mode_is_checked_and_kept():
    assert tm.Material.hatching().hatch_style["mode"] == "field"
    m = tm.Material.hatching(mode="triplanar")
    assert m.hatch_style["mode"] == "triplanar"
    import pickle
    assert pickle.loads(pickle.dumps(m)).hatch_style["mode"] == "triplanar"
    with pytest.raises(ValueError, match="^mode"):
        tm.Material.hatching(mode="diagonal")
    with pytest.raises(TypeError, match="^mode"):
        tm.Material.hatching(mode=3)


def test_field_hatching_runs_no_pass_more_than_plain_bands():
    V, F = tm.shapes.icosphere(3)
    kw = dict(width=48, height=48, outlines="mesh")
    field = tm.render(V, F, material=tm.Material.hatching(), **kw)
    plain = tm.render(V, F, material=tm.Material.bands(), **kw)
    assert field.passes == plain.passes  # the field rides in the shade pass's own vertex stage
