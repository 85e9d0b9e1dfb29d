"""Shadows (Kang, Kim and Yoon's shadow z-buffer): the shadow output held against a CPU ray cast
of the same scene (a box on a plane, a torus over a plane, a sphere shadowing itself), no
acne on lit surfaces, tight contact shadows, shadowed pixels in the lowest band, the plan, and
the settings' checks."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from scipy import ndimage

import toonmesh as tm
from toonmesh.bench.effects import SHADOW_SCENES, iou, plane, shadow_against_truth

BACKENDS = ["vulkan", "gl"]


SCENES = SHADOW_SCENES


def shadow_and_truth(name, size, backend="vulkan", shadows=True):
    return shadow_against_truth(name, size, shadows, backend)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("name", list(SCENES))
def test_shadowed_pixels_match_a_ray_cast(name, backend):
    res, truth = shadow_and_truth(name, 192, backend)
    assert res.passes[:2] == ["shadow_map", "shade"] and "shadow" in res.passes
    shadowed, true = res.shadow < 0.5, truth < 0.5
    assert true.sum() > 500, "the scene should have shadows"
    assert iou(shadowed, true) >= 0.97, f"IoU {iou(shadowed, true):.4f}"


@pytest.mark.parametrize("flt", ["none", "pcf"])
def test_both_filters_hold_at_the_default_size(flt):
    res, truth = shadow_and_truth("box on a plane", 192, shadows=tm.Shadows(filter=flt))
    assert iou(res.shadow < 0.5, truth < 0.5) >= 0.97
    soft = ((res.shadow > 0.02) & (res.shadow < 0.98)).sum()
    # PCF gives fractions along shadow edges; one nearest test gives none
    assert (soft > 0) == (flt == "pcf")


@pytest.mark.parametrize("backend", BACKENDS)
def test_no_acne_on_lit_surfaces(backend):
    r = tm.Renderer(backend=backend)
    for direction in [(0.0, -1.0, 0.0), (0.3, -1.0, 0.2), (1.0, -0.35, 0.0)]:  # up to 70 degrees
        res = r.render(
            tm.Mesh(*plane(2.0)),
            lights=[tm.Light.directional(direction, shadows=True)],
            camera=tm.Camera.fit((0.3, 1.0, 0.6)),
            width=256, height=256, outputs=("shadow",),
        )
        assert res.shadow.min() == 1.0, f"{(res.shadow < 1).sum()} shadowed pixels on a lit plane, light {direction}"


def test_contact_shadows_have_no_gap_at_1024():
    res, truth = shadow_and_truth("box on a plane", 1024)
    shadowed, true = res.shadow < 0.5, truth < 0.5
    # every pixel where the two disagree lies within 2 pixels of both answers' shadow edges:
    # no lit gap between the box and its shadow wider than that
    to_shadow = ndimage.distance_transform_edt(~shadowed)
    to_true = ndimage.distance_transform_edt(~true)
    assert to_shadow[true].max() <= 2.0, f"a truly shadowed pixel {to_shadow[true].max():.1f} px from any shadow"
    assert to_true[shadowed].max() <= 2.0


def test_shadowed_pixels_take_the_lowest_band():
    (V, F), direction, eye = SCENES["box on a plane"]
    light = tm.Light.directional(direction, shadows=tm.Shadows(filter="none"))
    res = tm.render(V, F, lights=[light], camera=tm.Camera.fit(eye), width=160, height=160,
                    outputs=("color", "shadow"), material=tm.Material.bands(), ambient=(0.1, 0.1, 0.1))
    in_shadow = res.color[res.shadow == 0][:, :3]
    colours, counts = np.unique(in_shadow, axis=0, return_counts=True)
    lowest = colours[counts.argmax()]
    # the plane's shadow and the box's faces turned from the light share the lowest band
    assert counts.max() >= 0.97 * len(in_shadow), f"{len(colours)} colours in shadow"
    lit = res.color[res.shadow == 1][:, :3]
    assert (lit != lowest).any(axis=1).mean() > 0.5
    # without shadows the same pixels of the plane are lit
    plain = tm.render(V, F, lights=[tm.Light.directional(direction)], camera=tm.Camera.fit(eye),
                      width=160, height=160, material=tm.Material.bands(), ambient=(0.1, 0.1, 0.1))
    assert (plain.color[res.shadow == 0][:, :3] != lowest).any(axis=1).mean() > 0.3


def test_the_plan_runs_shadow_passes_only_when_asked():
    V, F = tm.shapes.icosphere(1)
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    casting = [tm.Light.directional((0, -1, 0), shadows=True)]
    assert r.render(mesh, width=32, height=32).passes == ["shade", "readback_color"]
    assert r.render(mesh, lights=casting, width=32, height=32).passes == ["shadow_map", "shade", "readback_color"]
    assert r.render(mesh, lights=casting, width=32, height=32, outputs=("depth",)).passes == ["gbuffer", "readback_depth"]
    assert r.render(mesh, lights=casting, width=32, height=32, outputs=("shadow",)).passes == [
        "shadow_map", "gbuffer", "shadow", "readback_shadow"]
    # an empty scene casts nothing
    assert r.render([], lights=casting, width=8, height=8).passes == ["shade", "readback_color"]


def test_views_in_flight_give_the_same_shadows():
    (V, F), direction, _ = SCENES["torus over a plane"]
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    lights = [tm.Light.directional(direction, shadows=True)]
    cams = [tm.Camera.fit((np.cos(a), 1.0, np.sin(a))) for a in np.linspace(0, 3, 4)]
    stack = r.render_many(mesh, cams, lights=lights, width=64, height=64, outputs=("color", "shadow"))
    for i, cam in enumerate(cams):
        alone = r.render(mesh, camera=cam, lights=lights, width=64, height=64, outputs=("color", "shadow"))
        assert np.array_equal(stack.shadow[i], alone.shadow) and np.array_equal(stack.color[i], alone.color)


@pytest.mark.parametrize(
    "make, exc, match",
    [
        (lambda: tm.Shadows(size=1000), ValueError, "^size: must be a power of two"),
        (lambda: tm.Shadows(size=32), ValueError, "^size"),
        (lambda: tm.Shadows(size=2.0**11), TypeError, "^size"),
        (lambda: tm.Shadows(bias=-1.0), ValueError, "^bias: must be finite and >= 0"),
        (lambda: tm.Shadows(bias=float("nan")), ValueError, "^bias"),
        (lambda: tm.Shadows(filter="soft"), ValueError, "^filter: must be 'none' or 'pcf'"),
        (lambda: tm.Light.directional((0, -1, 0), shadows="yes"), TypeError, "^shadows: expected True, False or a toonmesh.Shadows"),
        (lambda: tm.Light.directional((0, -1, 0), shadows=1), TypeError, "^shadows"),
    ],
)
def test_bad_settings_name_the_argument(make, exc, match):
    with pytest.raises(exc, match=match):
        make()


def test_scene_level_errors():
    V, F = tm.shapes.icosphere(1)
    two = [tm.Light.directional((0, -1, 0), shadows=True), tm.Light.directional((1, -1, 0), shadows=True)]
    with pytest.raises(ValueError, match="^lights: one light may cast shadows"):
        tm.render(V, F, lights=two, width=8, height=8)
    with pytest.raises(ValueError, match="^outputs: 'shadow' needs a light that casts shadows"):
        tm.render(V, F, width=8, height=8, outputs=("shadow",))


def test_settings_pickle_and_print():
    s = tm.Shadows(size=1024, bias=0.5, filter="none")
    light = tm.Light.directional((1, -2, 0.5), shadows=s)
    assert light.shadows == s and (s.size, s.bias, s.filter) == (1024, 0.5, "none")
    assert pickle.loads(pickle.dumps(light)) == light and pickle.loads(pickle.dumps(s)) == s
    assert "Shadows(size=1024" in repr(light)
    assert tm.Light.directional((1, -2, 0.5), shadows=True).shadows == tm.Shadows()
    assert tm.Light.directional((1, -2, 0.5)).shadows is None
    assert hash(light) == hash(pickle.loads(pickle.dumps(light)))


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_lighter_shadow_takes_its_share_of_the_light(backend):
    """Shadows(strength=s) leaves 1 - s of the light in the map's shadows (the shadow output
    is mix(1, visibility, s) of the full shadow's, the CPU rule) and none on surfaces facing
    away; the colour there lies between the full shadow's and no shadow's."""
    (V, F), direction, eye = SCENES["box on a plane"]
    r = tm.Renderer(backend=backend)
    mesh = r.add_mesh(V, F)

    def frame(strength):
        light = tm.Light.directional(direction, shadows=tm.Shadows(strength=strength))
        return r.render(mesh, lights=[light], camera=tm.Camera.fit(eye), width=128, height=128,
                        outputs=("color", "shadow"), material=tm.Material.lambert(), band_antialias=False)

    full, half = frame(1.0), frame(0.5)
    away = full.shadow == 0  # facing away, or fully shadowed by the map
    mapped = (full.shadow > 0) & (full.shadow < 1)
    expected = 1.0 - 0.5 * (1.0 - full.shadow)
    in_map = (full.shadow < 1) & (half.shadow < 1)
    np.testing.assert_allclose(half.shadow[mapped], expected[mapped], atol=1e-5)
    # a fully shadowed pixel of the map keeps half the light; one facing away none
    assert set(np.unique(half.shadow[away & in_map])) <= {0.0, 0.5}
    assert (half.shadow[away] == 0.5).sum() > 100
    none = r.render(mesh, lights=[tm.Light.directional(direction)], camera=tm.Camera.fit(eye), width=128,
                    height=128, outputs=("color",), material=tm.Material.lambert(), band_antialias=False)
    shade = half.shadow == 0.5
    grey = lambda res: res.color[shade][:, :3].astype(int).sum(axis=1)  # noqa: E731
    assert (grey(full) < grey(half)).all() and (grey(half) <= grey(none)).all()
    assert grey(half).mean() < grey(none).mean() - 20  # equal only where the light grazes
    assert tm.Shadows(strength=0.5) != tm.Shadows() and pickle.loads(pickle.dumps(tm.Shadows(strength=0.5))).strength == 0.5
    with pytest.raises(ValueError, match="^strength: must be in \\[0, 1\\]"):
        tm.Shadows(strength=1.5)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_masked_textures_cut_outs_are_cut_out_of_its_shadow(backend):
    check_cut_out_shadows(backend)


def check_cut_out_shadows(backend):
    # a square leaf above a floor, textured with a 4x4 checker of opaque and clear texels
    # (alpha cutoff 0.5): its shadow on the floor is the checker, not a square
    leaf_v, leaf_f = plane(1.0, y=1.0)
    checker = (np.indices((4, 4)).sum(axis=0) % 2).astype(np.uint8)
    texture = np.zeros((4, 4, 4), np.uint8)
    texture[..., :3] = 200
    texture[..., 3] = checker * 255
    uv = (leaf_v[:, [0, 2]] + 1.0) / 2.0
    light = [tm.Light.directional((0.0, -1.0, 0.0), shadows=tm.Shadows(filter="none"))]
    camera = tm.Camera.orthographic((0.0, 5.0, 0.001), target=(0.0, 0.0, 0.0), height=2.0)
    kw = dict(lights=light, camera=camera, width=64, height=64, outputs=("shadow", "depth"), backend=backend)
    r = tm.Renderer(backend)
    for cutoff in (None, 0.5):
        leaf = tm.Mesh(leaf_v, leaf_f, uv=uv, texture=texture, alpha_cutoff=cutoff)
        floor = tm.Mesh(*plane(2.0))
        res = r.render([floor, leaf], **{k: v for k, v in kw.items() if k != "backend"})
        on_floor = res.depth > 4.5  # the floor (5 below the camera), where the leaf is cut away
        shadowed = res.shadow < 0.5
        if cutoff is None:
            # an opaque leaf: it covers the floor, which is all in its shadow where it shows
            assert on_floor.sum() == 0 or shadowed[on_floor].mean() > 0.99
        else:
            # the floor shows through the clear texels and is lit there: the light passes too
            assert on_floor.sum() > 64 * 64 * 0.4, on_floor.sum()
            lit = (~shadowed) & on_floor
            assert lit.sum() / on_floor.sum() > 0.95, (lit.sum(), on_floor.sum())
