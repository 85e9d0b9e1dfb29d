"""Glass: meshes with opacity below 1 (``Material(opacity=)``, or their colour's alpha with
``alpha_blend``, glTF's BLEND, MTL ``d``/``Tr``), composited exactly and in any item order by
depth peeling over the opaque frame and its ink.

Colours are compared in linear light: each square's shaded colour is measured by drawing it
alone and opaque, and the composite is the over operator on those, farthest first. The peeling
itself is held against its CPU twin in the Rust tests (src/render/passes/glass/gpu_tests.rs)."""

from __future__ import annotations

import base64
import json
import os

import numpy as np
import pytest

import toonmesh as tm

BACKENDS = ["vulkan", "gl"]
S = 48
SQUARE_F = np.array([[0, 1, 2], [0, 2, 3]])
HEAD_ON = dict(
    camera=tm.Camera.orthographic((0.0, 0.0, 10.0), target=(0.0, 0.0, 0.0), height=2.0),
    lights=[tm.Light.directional((0.0, 0.0, -1.0))],
    width=S,
    height=S,
)
RED, GREEN, BLUE = (0.9, 0.15, 0.1), (0.1, 0.8, 0.2), (0.1, 0.2, 0.9)


def square(half, z):
    return np.array([[-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]])


def decode(codes):
    c = np.asarray(codes, dtype=np.float64) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def encode(linear):
    c = np.clip(linear, 0.0, 1.0)
    return np.round(255.0 * np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055))


def rgb(result):
    return result.color[..., :3].astype(np.int32)


def layers(opacity=(1.0, 0.4, 0.5)):
    """Opaque red under green under blue (opacities in that order), red filling the view."""
    return [
        tm.Mesh(square(2.0, 0.0), SQUARE_F, material=tm.Material.lambert(RED, opacity=opacity[0])),
        tm.Mesh(square(0.6, 0.5), SQUARE_F, material=tm.Material.lambert(GREEN, opacity=opacity[1])),
        tm.Mesh(square(0.4, 1.0), SQUARE_F, material=tm.Material.lambert(BLUE, opacity=opacity[2])),
    ]


@pytest.mark.parametrize("backend", BACKENDS)
def test_blue_over_green_over_red_is_exact_over_compositing_in_any_order(backend):
    r = tm.Renderer(backend=backend)
    opaque = [decode(rgb(r.render(m, **HEAD_ON))) for m in layers((1.0, 1.0, 1.0))]
    exact = 0.5 * opaque[2] + 0.5 * (0.4 * opaque[1] + 0.6 * opaque[0])
    centre = (slice(S // 2 - 6, S // 2 + 6),) * 2  # inside all three squares
    items = layers()
    images = []
    for order in ([0, 1, 2], [2, 1, 0], [1, 0, 2]):
        res = r.render([items[i] for i in order], **HEAD_ON)
        assert res.passes.count("glass_peel") == 4 and "glass_composite" in res.passes
        images.append(rgb(res))
    want = encode(exact[centre])
    for img in images:
        assert np.abs(img[centre] - want).max() <= 6
        assert np.abs(img - images[0]).max() <= 1
    # the glass shows: the centre is neither the red alone nor the blue alone
    assert np.abs(images[0][centre] - rgb(r.render(items[0], **HEAD_ON))[centre]).max() > 40
    assert np.abs(images[0][centre] - encode(opaque[2][centre])).max() > 40


@pytest.mark.parametrize("backend", BACKENDS)
def test_opaque_scenes_run_no_glass_pass_and_keep_their_image(backend):
    r = tm.Renderer(backend=backend)
    plain = [tm.Mesh(square(2.0, 0.0), SQUARE_F, material=tm.Material.lambert(RED)),
             tm.Mesh(square(0.4, 1.0), SQUARE_F, material=tm.Material.lambert(BLUE))]
    explicit = layers((1.0, 1.0, 1.0))
    a = r.render(plain, **HEAD_ON)
    b = r.render([explicit[0], explicit[2]], **HEAD_ON)
    assert a.passes == b.passes == ["shade", "readback_color"]
    assert np.array_equal(a.color, b.color)
    # fewer layers than glass surfaces: the farthest is dropped
    one = r.render(layers(), glass_layers=1, **HEAD_ON)
    assert one.passes.count("glass_peel") == 1
    four = r.render(layers(), **HEAD_ON)
    assert np.abs(rgb(one) - rgb(four)).max() > 10


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("visibility", ["exact", "depth"])
def test_ink_behind_glass_stays_dark(backend, visibility):
    r = tm.Renderer(backend=backend)
    box = tm.Mesh(*_box(), material=tm.Material.lambert((0.9, 0.9, 0.9)), normals="flat")
    pane = tm.Mesh(square(3.0, 2.0), SQUARE_F, material=tm.Material.lambert((0.5, 0.5, 0.5), opacity=0.3))
    view = dict(camera=tm.Camera.look_at((2.0, 1.5, 4.0), target=(0.0, 0.0, 0.0)), width=128, height=128,
                outlines=tm.Outlines("mesh", visibility=visibility))
    bare = r.render(box, outputs=("color", "outline"), **view)
    ink = bare.outline > 0.5
    assert ink.sum() > 200
    behind = r.render([box, pane], **view)
    dark = rgb(behind).max(axis=-1) < 128
    assert dark[ink].mean() >= 0.8
    # the pane covers the box: the surface around the ink is lightened, not left as it was
    assert np.abs(rgb(behind) - rgb(bare))[~ink].max() > 20


def _box():
    V = np.array([[x, y, z] for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)])
    F = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                  [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    return V, F


def opacity_of(path_or_mesh, backend):
    """The opacity a file's (or Mesh's) square reads as: the composite's change between a
    black and a white background, in linear light, at the centre."""
    r = tm.Renderer(backend=backend)
    view = dict(camera=tm.Camera.orthographic((0.0, 0.0, 10.0), target=(0.0, 0.0, 0.0), height=2.0),
                width=S, height=S)
    if isinstance(path_or_mesh, str):
        path_or_mesh = tm.load(path_or_mesh)
    c = {}
    for bg in (0.0, 1.0):
        res = r.render(path_or_mesh, background=(bg, bg, bg), **view)
        c[bg] = decode(rgb(res))[S // 2 - 4: S // 2 + 4, S // 2 - 4: S // 2 + 4]
    return 1.0 - float(np.mean(c[1.0] - c[0.0]))


def _gltf(path, alpha_mode, alpha):
    V = square(1.5, 0.0).astype(np.float32)
    idx = SQUARE_F.astype(np.uint16).ravel()
    blob = V.tobytes() + idx.tobytes()
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"alphaMode": alpha_mode,
                       "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.8, alpha]}}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": V.nbytes},
                        {"buffer": 0, "byteOffset": V.nbytes, "byteLength": idx.nbytes}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": V.min(axis=0).tolist(), "max": V.max(axis=0).tolist()},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }
    with open(path, "w") as f:
        json.dump(doc, f)
    return path


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_gltf_blend_material_reads_as_its_alpha(tmp_path, backend):
    blend = _gltf(os.path.join(tmp_path, "blend.gltf"), "BLEND", 0.5)
    assert abs(opacity_of(blend, backend) - 0.5) < 0.02
    opaque = _gltf(os.path.join(tmp_path, "opaque.gltf"), "OPAQUE", 0.5)
    assert abs(opacity_of(opaque, backend) - 1.0) < 0.01


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("line,alpha", [("d 0.5", 0.5), ("Tr 0.25", 0.75)])
def test_an_mtl_dissolve_reads_as_opacity(tmp_path, backend, line, alpha):
    with open(os.path.join(tmp_path, "m.mtl"), "w") as f:
        f.write(f"newmtl m\nKd 0.2 0.4 0.8\n{line}\n")
    obj = os.path.join(tmp_path, "m.obj")
    with open(obj, "w") as f:
        f.write("mtllib m.mtl\nv -1.5 -1.5 0\nv 1.5 -1.5 0\nv 1.5 1.5 0\nv -1.5 1.5 0\n"
                "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")
    assert abs(opacity_of(obj, backend) - alpha) < 0.02


@pytest.mark.parametrize("backend", BACKENDS)
def test_alpha_blend_multiplies_the_opacity_by_the_colour_alpha(backend):
    colors = np.tile([0.2, 0.4, 0.8, 0.5], (4, 1))
    mesh = lambda blend, opacity: tm.Mesh(square(1.5, 0.0), SQUARE_F, vertex_colors=colors, alpha_blend=blend,
                                          material=tm.Material.bands(opacity=opacity))
    assert abs(opacity_of(mesh(True, 1.0), backend) - 0.5) < 0.02
    assert abs(opacity_of(mesh(True, 0.5), backend) - 0.25) < 0.02
    assert abs(opacity_of(mesh(False, 1.0), backend) - 1.0) < 0.01
    assert abs(opacity_of(mesh(False, 0.6), backend) - 0.6) < 0.02


def test_bad_opacity_and_alpha_blend_are_refused():
    with pytest.raises(ValueError, match="opacity"):
        tm.Material.lambert(opacity=1.5)
    with pytest.raises(TypeError, match="opacity"):
        tm.Material.bands(opacity="half")
    with pytest.raises(TypeError, match="alpha_blend"):
        tm.Renderer().add_mesh(square(1.0, 0.0), SQUARE_F, vertex_colors=np.ones((4, 4)), alpha_blend="yes")
    with pytest.raises(ValueError, match="glass_layers"):
        tm.RenderOptions(glass_layers=0)
    assert tm.Material.lambert(opacity=0.25).opacity == 0.25
    assert tm.Material.lambert().opacity == 1.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_glass_over_multisampled_and_supersampled_frames(backend):
    r = tm.Renderer(backend=backend)
    centre = (slice(S // 2 - 6, S // 2 + 6),) * 2
    single = r.render(layers(), outputs=("color", "depth"), **HEAD_ON)
    for more in (dict(msaa=4), dict(supersample=2)):
        res = r.render(layers(), outputs=("color", "depth"), **HEAD_ON, **more)
        assert "gbuffer" in res.passes and res.passes.count("glass_peel") == 4
        assert np.abs(rgb(res)[centre] - rgb(single)[centre]).max() <= 1
    # the depth output holds the opaque surface only: the red square at z = 0, 10 from the eye
    assert np.allclose(single.depth[centre], 10.0, atol=1e-4)


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_glass_own_ink_is_drawn_over_it(backend):
    r = tm.Renderer(backend=backend)
    box = tm.Mesh(*_box(), material=tm.Material.lambert((0.9, 0.9, 0.9), opacity=0.8), normals="flat")
    view = dict(camera=tm.Camera.look_at((2.0, 1.5, 4.0), target=(0.0, 0.0, 0.0)), width=128, height=128,
                outlines=tm.Outlines("mesh"), outputs=("color", "outline"))
    res = r.render(box, **view)
    assert res.passes.index("glass_lines") > res.passes.index("glass_composite") > res.passes.index("lines")
    opaque = r.render(tm.Mesh(*_box(), material=tm.Material.lambert((0.9, 0.9, 0.9)), normals="flat"), **view)
    # the back edges too: glass hides no line
    assert (res.outline > 0.5).sum() > 1.2 * (opaque.outline > 0.5).sum()
    # its silhouette and creases are dark where fully inked, not lightened by the glass they lie on
    ink = res.outline > 0.99
    assert ink.sum() > 200
    assert (rgb(res).max(axis=-1) < 100)[ink].mean() >= 0.95
