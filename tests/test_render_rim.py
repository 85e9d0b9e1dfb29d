"""The rim light (`tm.Rim` on any material): a band along the silhouette where n.v < width, on
both sides or only the lit or shadowed one, added as light or painted over; in every shading
model, on coloured and textured meshes, with no extra pass. Its pixels are held against the CPU
reference in Rust (`render::effects::rim::gpu_tests`); here, what a user sees."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm

V, F = tm.shapes.icosphere(4)
# orthographic, so that n.v is the view-space normal's z
SIZE = dict(width=96, height=96, camera=tm.Camera.orthographic((0.0, 0.0, 5.0), height=2.4))
LIGHT = [tm.Light.directional((0.0, 0.0, -1.0))]  # from the viewer: the whole disc is lit


def _render(material, **kw):
    return tm.render(V, F, material=material, lights=LIGHT, outputs=("color", "normal", "depth"), **SIZE, **kw)


def _rim_mask(r, width):
    """Pixels well inside the rim (n.v < width) and well outside it."""
    covered = np.isfinite(r.depth)
    return covered & (r.normal[..., 2] < width - 0.08), covered & (r.normal[..., 2] > width + 0.08)


@pytest.mark.parametrize("make", [tm.Material.lambert, tm.Material.phong, tm.Material.bands,
                                  tm.Material.thresholded_phong, tm.Material.hatching,
                                  lambda **kw: tm.Material.lut([0.3, 0.7, 1.0], **kw)],
                         ids=["lambert", "phong", "bands", "thresholded_phong", "hatching", "lut"])
def test_a_rim_brightens_the_silhouette_band_only_in_every_model(make):
    plain = _render(make())
    rim = _render(make(rim=tm.Rim(width=0.35, strength=1.0)))
    inside, outside = _rim_mask(rim, 0.35)
    assert inside.sum() > 200 and outside.sum() > 1000
    gain = rim.color[..., :3].astype(int) - plain.color[..., :3].astype(int)
    white = (plain.color[..., :3] >= 250).all(axis=2)  # nothing to add (hatching's paper)
    assert (gain[inside] >= 0).all()
    assert ((gain.sum(axis=2) > 30) | white)[inside].mean() > 0.97
    assert (gain[outside] == 0).all()
    assert rim.passes == plain.passes  # no pass of its own


def test_mix_paints_the_rims_colour_and_the_sides_split_it():
    blue = _render(tm.Material.bands("#ffffff", rim=tm.Rim("#0000ff", width=0.4, strength=1.0, blend="mix")))
    inside, _ = _rim_mask(blue, 0.4)
    px = blue.color[inside][:, :3].astype(int)
    assert (px[:, 2] > 200).mean() > 0.97 and (px[:, 0] < 20).mean() > 0.97
    # a light from the right: the lit side's rim is on the right, the shadowed side's on the left
    side_light = [tm.Light.directional((-1.0, 0.0, -0.2))]
    cols = np.arange(96)
    for side, right in (("lit", True), ("shadowed", False)):
        m = tm.Material.lambert("#202020", rim=tm.Rim(width=0.4, strength=1.0, side=side))
        r = tm.render(V, F, material=m, lights=side_light, outputs=("color", "depth"), **SIZE)
        bright = (r.color[..., :3].astype(int).sum(axis=2) > 500) & np.isfinite(r.depth)
        xs = np.broadcast_to(cols, bright.shape)[bright]
        assert len(xs) > 50
        assert (np.median(xs) > 48) == right, (side, np.median(xs))


def test_a_rim_on_gouraud_coloured_and_textured_meshes():
    rim = tm.Rim(width=0.4, strength=1.0, color="#ff0000", blend="mix")
    colours = np.tile(np.array([40, 200, 40], np.uint8), (len(V), 1))
    uv = V[:, :2] * 0.5 + 0.5
    meshes = [tm.Mesh(V, F, vertex_colors=colours), tm.Mesh(V, F, uv=uv, texture=np.tile(colours[:1], (4, 4, 1)))]
    for mesh in meshes:
        for per_vertex in (False, True):
            r = tm.render(mesh, material=tm.Material.bands(rim=rim, per_vertex=per_vertex), lights=LIGHT,
                          outputs=("color", "normal", "depth"), **SIZE)
            inside, outside = _rim_mask(r, 0.4)
            red = r.color[..., 0].astype(int) - r.color[..., 1].astype(int)
            assert (red[inside] > 150).mean() > 0.95, per_vertex
            assert (red[outside] < 0).mean() > 0.95, per_vertex  # the green surface keeps its colour


def test_rim_settings_describe_themselves():
    rim = tm.Rim("#ffeecc", width=0.2, softness=0.1, side="lit")
    assert eval(repr(rim), {"Rim": tm.Rim}) == rim
    m = tm.Material.bands(rim=rim)
    assert m.rim == rim and m.replace(rim=None).rim is None
    assert tm.Material.hatching().rim is None
    with pytest.raises(ValueError, match="^width: must be in \\[0, 1\\]"):
        tm.Rim(width=1.5)
    with pytest.raises(TypeError, match="^rim: expected a toonmesh.Rim"):
        tm.Material.bands(rim="#ffffff")
