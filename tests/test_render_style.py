"""Cross-hatching and dithering (Borquez and Yepez): shading variants that add no pass. Held
against the CPU rules they follow (how many stroke layers a tone gets; the Bayer thresholds),
with strokes of about constant width on screen, deterministic bits, and the settings' checks."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.bench.effects import shimmer

BACKENDS = ["vulkan", "gl"]

# A square facing +z, seen head-on by an orthographic camera that it fills.
SQUARE_V = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]]) * 4
SQUARE_F = np.array([[0, 1, 2], [0, 2, 3]])
HEAD_ON = tm.Camera.orthographic((0.0, 0.0, 10.0), target=(0.0, 0.0, 0.0), height=4.0)


def light_at(d):
    """A light making L.n = d on the square."""
    return tm.Light.directional((-np.sqrt(1 - d * d), 0.0, -d))


def square(material, d, backend="vulkan", size=96, camera=HEAD_ON):
    r = tm.Renderer(backend=backend)
    return r.render(tm.Mesh(SQUARE_V, SQUARE_F, material=material), camera=camera, lights=[light_at(d)],
                    width=size, height=size, ambient=(0.0, 0.0, 0.0))


def ink_share(color, paper=255):
    """Mean ink coverage of an image of ink (0.1 grey) strokes on white paper."""
    grey = color[..., :3].astype(float).mean(-1)
    return float(((paper - grey) / (paper - 26)).clip(0, 1).mean())


def layers(tone):
    """The shader's rule: layer k of 4 shows below tone 1 - k / 5."""
    return sum(tone < 1 - k / 5 for k in range(1, 5))


@pytest.mark.parametrize("backend", BACKENDS)
def test_stroke_layers_follow_the_band_tone(backend):
    # the paper's bands: L.n 0.95 -> 1.0, 0.8 -> 0.9, 0.6 -> 0.7, 0.3 -> 0.2, 0.1 -> 0
    cases = [(0.95, 1.0), (0.8, 0.9), (0.6, 0.7), (0.3, 0.2), (0.1, 0.0)]
    shares = []
    for d, tone in cases:
        res = square(tm.Material.hatching(), d, backend)
        share = ink_share(res.color)
        if layers(tone) == 0:
            assert share == 0.0, f"L.n {d}: ink on paper that should be blank"
        else:
            assert share > 0.05, f"L.n {d}: {layers(tone)} layers but no ink"
        shares.append(share)
    # more layers, more ink; one layer of strokes 1.25 px wide every 6 px covers about a fifth
    assert all(a < b for a, b in zip(shares[1:], shares[2:])), shares
    assert 0.1 < shares[2] < 0.45, shares


def test_strokes_keep_their_width_on_screen_near_and_far():
    shares = []
    for distance in [6.0, 11.0, 23.0, 47.0]:
        cam = tm.Camera.look_at((0.0, 0.0, distance), (0.0, 0.0, 0.0), fov_y=20.0)
        res = square(tm.Material.hatching(), 0.6, camera=cam, size=128)
        covered = res.color[..., 3] > 0
        inside = covered[32:96, 32:96].all()
        assert inside, "the square should fill the middle of the view"
        shares.append(ink_share(res.color[32:96, 32:96]))
    # the object-space pattern switches octaves to keep ~6 px spacing: ink share stays put
    # while the square shrinks 8 times on screen
    assert max(shares) < 1.6 * min(shares), shares


def test_hatching_is_deterministic_and_adds_no_pass():
    V, F = tm.shapes.icosphere(3)
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    a = r.render(mesh, material=tm.Material.hatching(), width=96, height=96)
    b = r.render(mesh, material=tm.Material.hatching(), width=96, height=96)
    assert np.array_equal(a.color, b.color)
    assert a.passes == ["shade", "readback_color"]
    lit = [tm.Light.directional((0.3, -1.0, -0.5), shadows=True)]
    both = r.render(mesh, material=tm.Material.hatching(dither="bayer4"), lights=lit, width=64, height=64)
    assert both.passes == ["shadow_map", "shade", "readback_color"]


def test_backends_agree_on_hatching():
    V, F = tm.shapes.icosphere(3)
    a, b = (tm.render(V, F, material=tm.Material.hatching(), width=96, height=96, backend=k).color for k in BACKENDS)
    assert np.abs(a.astype(int) - b.astype(int)).mean() < 2.0


def bayer(n):
    m = np.zeros((1, 1), int)
    while m.shape[0] < n:
        m = np.block([[4 * m, 4 * m + 2], [4 * m + 3, 4 * m + 1]])
    return (m + 0.5) / (n * n)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("n, pattern", [(2, "bayer2"), (4, "bayer4"), (8, "bayer8")])
def test_screen_dither_follows_the_bayer_matrix(backend, n, pattern):
    amount, below = 0.2, 0.04  # L.n 0.04 under the 0.7 threshold: up a band where t >= 0.7
    mat = tm.Material.bands(color=(1.0, 1.0, 1.0), dither=tm.Dither(pattern, amount=amount))
    res = square(mat, 0.7 - below, backend, size=64)
    up = res.color[..., 0] > 240  # band 0.9 against band 0.7
    t = np.tile(bayer(n), (64 // n, 64 // n))
    expected = t >= 0.5 + below / amount
    assert 0 < expected.mean() < 1
    assert np.array_equal(up, expected), f"{(up != expected).sum()} pixels differ"


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_turned_dither_turns_the_matrix(backend):
    # at 90 degrees counter-clockwise as seen, pixel (x, y) reads the cell (-(y + 1), x) (its centre
    # turned), so the rows of the matrix become its columns
    amount, below, n = 0.2, 0.04, 4
    mat = tm.Material.bands(color=(1.0, 1.0, 1.0), dither=tm.Dither("bayer4", amount=amount, angle=90))
    up = square(mat, 0.7 - below, backend, size=64).color[..., 0] > 240
    y, x = np.mgrid[0:64, 0:64]
    expected = bayer(n)[x % n, (-(y + 1)) % n] >= 0.5 + below / amount
    assert np.array_equal(up, expected), f"{(up != expected).sum()} pixels differ"
    plain = tm.Material.bands(color=(1.0, 1.0, 1.0), dither=tm.Dither("bayer4", amount=amount))
    assert not np.array_equal(up, square(plain, 0.7 - below, backend, size=64).color[..., 0] > 240)


def test_blue_noise_dithers_without_a_grid():
    mat = tm.Material.bands(color=(1.0, 1.0, 1.0), dither=tm.Dither("blue", amount=0.2))
    up = square(mat, 0.66, size=64).color[..., 0] > 240
    # the R2 thresholds: a share near 1 - 0.7 of pixels go up a band
    assert abs(up.mean() - 0.3) < 0.03
    # and no 2x2, 4x4 or 8x8 period
    for n in (2, 4, 8):
        assert not np.array_equal(up, np.roll(up, n, axis=1))


def test_object_space_dither_shimmers_less_on_a_turntable():
    # the share of surface points whose decision changes between frames 1 degree apart
    for pattern in ("bayer4", "blue"):
        screen, obj = shimmer("screen", pattern, size=96), shimmer("object", pattern, size=96)
        assert obj < 0.6 * screen, (pattern, screen, obj)


@pytest.mark.parametrize(
    "make, exc, match",
    [
        (lambda: tm.Dither("bayer3"), ValueError, "^pattern: must be 'bayer2', 'bayer4', 'bayer8' or 'blue'"),
        (lambda: tm.Dither(space="world"), ValueError, "^space: must be 'screen' or 'object'"),
        (lambda: tm.Dither(amount=3.0), ValueError, "^amount"),
        (lambda: tm.Dither(scale=0.5), ValueError, "^scale"),
        (lambda: tm.Material.bands(dither=3), TypeError, "^dither: expected a pattern name or a toonmesh.Dither"),
        (lambda: tm.Material.bands(dither="noise"), ValueError, "^dither: must be"),
        (lambda: tm.Material.bands(dither="bayer4", per_vertex=True), ValueError, "^dither: needs per-pixel"),
        (lambda: tm.Material.hatching(spacing=1.0), ValueError, "^spacing"),
        (lambda: tm.Material.hatching(width=0.0), ValueError, "^width"),
        (lambda: tm.Material.hatching(width=7.0), ValueError, "^width"),
        (lambda: tm.Material.hatching(ink=(0, 0, 300)), ValueError, "^ink"),
    ],
)
def test_bad_settings_name_the_argument(make, exc, match):
    with pytest.raises(exc, match=match):
        make()


def test_settings_pickle_and_read_back():
    d = tm.Dither("blue", space="object", amount=0.3, scale=2.0)
    assert (d.pattern, d.space, d.amount, d.scale) == ("blue", "object", 0.3, 2.0)
    assert pickle.loads(pickle.dumps(d)) == d
    m = tm.Material.hatching(ink="#203040", spacing=8.0, width=2.0, dither=d)
    assert pickle.loads(pickle.dumps(m)) == m and m.dither == d
    assert m.hatch_style["spacing"] == 8.0 and m.model == "bands"
    assert tm.Material.bands().hatch_style is None and tm.Material.bands().dither is None
    assert tm.Material.lut(dither="bayer8").dither == tm.Dither("bayer8")
