"""Every combination of what a mesh draw reads and writes builds its pipeline and renders: the
mesh's colour (none, per vertex, a texture) x what the material needs of the vertex stage
(nothing, the anchors, the hatching field, both with Gouraud colours) x the targets the pass
writes (colour; colour with normal and depth or depth alone from the shading pass; normal and
depth or depth alone from the geometry pass), on Vulkan and GL; where a NumPy reference covers
the material, a small frame of each is held against it (every combination of the per-pixel
effects is held against their CPU references in Rust: src/render/effect_combinations_tests.rs).
The stages of each are written from one declaration per part (src/render/stage_part.rs,
src/render/graph/mesh_stages.rs)."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from render_reference import expected_color, light_dots, match_fraction, srgb_to_linear, view_positions

BACKENDS = ["vulkan", "gl"]
V, F = tm.shapes.icosphere(2)
TINT = np.array([153, 230, 76], dtype=np.uint8)

# alpha_cutoff: the geometry pass reads a coloured mesh only where its pixels may be cut
ALBEDO = {
    "none": lambda: tm.Mesh(V, F),
    "colour": lambda: tm.Mesh(V, F, vertex_colors=np.tile(TINT, (len(V), 1)), alpha_cutoff=0.5),
    "texture": lambda: tm.Mesh(V, F, uv=V[:, :2] * 0.5 + 0.5, texture=np.tile(TINT, (4, 4, 1)), alpha_cutoff=0.5),
}
NEEDS = {
    "nothing": tm.Material.bands(),
    "anchors": tm.Material.hatching(mode="triplanar"),
    "field": tm.Material.hatching(),
    "field, Gouraud": tm.Material.hatching(per_vertex=True),
    "a rim": tm.Material.bands(rim=tm.Rim()),
    "a rim, Gouraud": tm.Material.lambert(per_vertex=True, rim=tm.Rim(side="lit")),
}
# outputs, msaa, the pass that writes the geometry (None: none is written)
TARGETS = {
    "colour": (("color",), 1, None),
    "colour + normal and depth": (("color", "normal"), 1, "shade"),
    "colour + depth": (("color", "depth"), 1, "shade"),
    "normal and depth apart": (("color", "normal"), 4, "gbuffer"),
    "normal and depth alone": (("normal",), 1, "gbuffer"),
    "depth alone": (("depth",), 1, "gbuffer"),
}


# the materials whose every pixel the NumPy reference computes (render_reference.py), hard band
# borders; the hatching strokes are held against their CPU reference in Rust
REFERENCE = ("nothing", "a rim")
LIGHTS = [tm.Light.directional((0.4, -0.6, -1.0))]


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("albedo", list(ALBEDO))
@pytest.mark.parametrize("needs", REFERENCE)
def test_a_small_frame_of_each_combination_matches_the_cpu_reference(backend, albedo, needs):
    material = NEEDS[needs]
    res = tm.Renderer(backend).render(ALBEDO[albedo](), material=material, lights=LIGHTS, width=64, height=64,
                                      outputs=("color", "normal", "depth"), band_antialias=False)
    tint = srgb_to_linear(TINT / 255.0) if albedo != "none" else np.ones(3)
    want = expected_color(res, material, LIGHTS, albedo=tint)
    covered = np.isfinite(res.depth)
    # pixels within rounding of a band's or the rim's border may land on either side
    near = np.zeros_like(covered)
    for d in light_dots(res, LIGHTS):
        for t in material.thresholds:
            near |= np.abs(d - t) < 0.02
    if material.rim is not None:
        p = view_positions(res)
        v = -p / np.linalg.norm(p, axis=-1, keepdims=True)
        near |= np.abs(np.sum(res.normal * v, axis=-1) - material.rim.width) < 0.02
    mask = covered & ~near
    assert mask.sum() > 1000
    assert match_fraction(res, want, mask) > 0.99, (albedo, needs)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("albedo", list(ALBEDO))
@pytest.mark.parametrize("needs", list(NEEDS))
def test_every_combination_renders(backend, albedo, needs):
    r = tm.Renderer(backend)
    mesh = ALBEDO[albedo]()
    for name, (outputs, msaa, writer) in TARGETS.items():
        res = r.render(mesh, material=NEEDS[needs], width=24, height=24, outputs=outputs, msaa=msaa)
        where = f"{albedo}, {needs}, {name}"
        if writer == "gbuffer":
            assert "gbuffer" in res.passes, (where, res.passes)
        elif writer == "shade":
            assert "gbuffer" not in res.passes, (where, res.passes)
        if "color" in outputs:
            covered = (res.color != res.color[0, 0]).any(-1)  # the corner shows the background
            assert 100 < covered.sum() < 24 * 24, where
        if "depth" in outputs:
            assert 100 < np.isfinite(res.depth).sum() < 24 * 24, where
        if "normal" in outputs:
            n = res.normal[np.isfinite(res.normal).all(-1) & (np.abs(res.normal).sum(-1) > 0)]
            assert len(n) > 100 and np.allclose(np.linalg.norm(n, axis=-1), 1.0, atol=1e-3), where
