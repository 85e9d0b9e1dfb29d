"""Colour on the mesh: vertex and face colours, uv and a texture, and what a trimesh brings.

The albedo (colour times texture sample, in linear light) multiplies the material's colour, so
on a square lit head-on the render divided by a white render (in linear light) is the albedo:
held against NumPy references of the colour rules, against trimesh's ``uv_to_color`` for the
texture's axes, and, for every shading model, against a material whose colour is multiplied
instead. The sampling rule itself (filters, wraps, mip levels) is held against its CPU twin on
both backends in the Rust tests (src/render/albedo_gpu_tests.rs)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import toonmesh as tm
from conftest import need

BACKENDS = ["vulkan", "gl"]
S = 48  # image size

# A square facing +z seen head-on by an orthographic camera that it fills exactly, lit head-on.
SQUARE_V = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]])
SQUARE_F = np.array([[0, 1, 2], [0, 2, 3]])
SQUARE_UV = (SQUARE_V[:, :2] + 1.0) / 2.0
HEAD_ON = dict(
    camera=tm.Camera.orthographic((0.0, 0.0, 10.0), target=(0.0, 0.0, 0.0), height=2.0),
    lights=[tm.Light.directional((0.0, 0.0, -1.0))],
    ambient=(0.0, 0.0, 0.0),
    material=tm.Material.lambert(color=(1.0, 1.0, 1.0)),
    width=S,
    height=S,
)


def decode(codes):
    c = np.asarray(codes, dtype=np.float64) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def encode(linear):
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


def pixel_xy(n=S):
    """World (x, y) of each pixel centre on the square, (n, n, 2)."""
    t = (np.arange(n) + 0.5) / n
    x, y = np.meshgrid(-1.0 + 2.0 * t, 1.0 - 2.0 * t)
    return np.stack([x, y], -1)


def rendered(backend, mesh, **kw):
    return tm.Renderer(backend).render(mesh, **{**HEAD_ON, **kw})


def with_albedo(white, albedo_linear):
    """The 8-bit colour of a white render's pixels times a linear albedo."""
    return np.round(255 * encode(decode(white[..., :3]) * albedo_linear)).astype(int)


def grid(n=9):
    """The square as an n x n grid of vertices (many triangles to interpolate across)."""
    t = np.linspace(-1.0, 1.0, n)
    x, y = np.meshgrid(t, t)
    V = np.stack([x.ravel(), y.ravel(), np.zeros(n * n)], -1)
    i = np.arange(n - 1)
    a = (i[:, None] * n + i[None, :]).ravel()
    F = np.concatenate([np.stack([a, a + 1, a + n + 1], -1), np.stack([a, a + n + 1, a + n], -1)])
    return V, F


def linear_field(xy):
    """A linear-light colour that is linear in the position, so interpolation keeps it exact."""
    x, y = xy[..., 0], xy[..., 1]
    return np.stack([0.1 + 0.4 * (x + 1), 0.05 + 0.45 * (y + 1), np.full_like(x, 0.5)], -1)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("per_vertex", [False, True])
def test_vertex_colours_are_decoded_then_interpolated_in_linear_light(backend, per_vertex):
    V, F = grid()
    colors = encode(linear_field(V[:, :2]))  # sRGB floats whose linear values are linear in x, y
    material = tm.Material.lambert(color=(1.0, 1.0, 1.0), per_vertex=per_vertex)
    white = rendered(backend, tm.Mesh(V, F), material=material).color
    got = rendered(backend, tm.Mesh(V, F, vertex_colors=colors), material=material).color
    want = with_albedo(white, linear_field(pixel_xy()))
    assert np.abs(got[..., :3].astype(int) - want).max() <= 2
    # uint8 codes with alpha read the same as floats
    codes = np.concatenate([np.round(colors * 255), np.full((len(V), 1), 255)], 1).astype(np.uint8)
    again = rendered(backend, tm.Mesh(V, F, vertex_colors=codes), material=material).color
    assert np.abs(again.astype(int) - got.astype(int)).max() <= 2


# a 2 x 2 checker of four colours: red, green (top row), blue, yellow (bottom row)
CHECKER = np.array([[[230, 20, 20], [20, 200, 40]], [[30, 40, 220], [240, 220, 30]]], np.uint8)


def checker_agreement(color, white, uv):
    """Share of pixels (away from the cell borders) whose colour is the one trimesh's
    uv_to_color reads at that pixel's uv."""
    trimesh = need("trimesh")
    from PIL import Image

    want_codes = trimesh.visual.uv_to_color(uv.reshape(-1, 2), Image.fromarray(CHECKER))[:, :3]
    want = with_albedo(white, decode(want_codes.reshape(S, S, 3)))
    away = np.all(np.abs(pixel_xy()) > 2.5 / S, -1)  # not within a pixel or so of u, v = 0.5
    ok = np.all(np.abs(color[..., :3].astype(int) - want) <= 2, -1)
    return float(ok[away].mean())


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_checker_texture_renders_as_trimesh_uv_to_color_says_and_a_flipped_axis_is_caught(backend):
    white = rendered(backend, tm.Mesh(SQUARE_V, SQUARE_F)).color
    color = rendered(backend, tm.Mesh(SQUARE_V, SQUARE_F, uv=SQUARE_UV, texture=CHECKER, texture_filter="nearest")).color
    uv = (pixel_xy() + 1.0) / 2.0
    assert checker_agreement(color, white, uv) > 0.99
    flipped_v = np.stack([uv[..., 0], 1.0 - uv[..., 1]], -1)
    flipped_u = np.stack([1.0 - uv[..., 0], uv[..., 1]], -1)
    assert checker_agreement(color, white, flipped_v) < 0.05
    assert checker_agreement(color, white, flipped_u) < 0.05
    # the top-left quarter is the image's top-left texel
    assert color[S // 4, S // 4, 0] > 150 and color[S // 4, S // 4, 2] < 100


@pytest.mark.parametrize("backend", BACKENDS)
def test_texture_wrap_modes_repeat_clamp_and_mirror_outside_the_unit_square(backend):
    uv = SQUARE_UV * 3.0 - 1.0  # [-1, 2]: a whole texture beyond each side
    colors = {}
    for wrap in ("repeat", "clamp", "mirror"):
        mesh = tm.Mesh(SQUARE_V, SQUARE_F, uv=uv, texture=CHECKER, texture_filter="nearest", texture_wrap=wrap)
        colors[wrap] = rendered(backend, mesh).color[..., :3].astype(int)

    def at(wrap, u, v):
        """The colour where the square reads (u, v)."""
        x, y = (u + 1.0) / 1.5 - 1.0, (v + 1.0) / 1.5 - 1.0
        return colors[wrap][int((1.0 - y) / 2.0 * S), int((x + 1.0) / 2.0 * S)]

    red = lambda c: c[0] > 150 and c[1] < 100
    green = lambda c: c[1] > 150 and c[0] < 100
    # in the top row of texels (v = 0.75), one texel left of the image (u = -0.3) and two (-0.8)
    assert green(at("repeat", -0.3, 0.75)) and red(at("repeat", -0.8, 0.75))
    assert red(at("clamp", -0.3, 0.75)) and red(at("clamp", -0.8, 0.75))
    assert red(at("mirror", -0.3, 0.75)) and green(at("mirror", -0.8, 0.75))
    # inside the image all three read the same
    inside = slice(S // 3 + 2, 2 * S // 3 - 2)
    assert np.array_equal(colors["repeat"][inside, inside], colors["mirror"][inside, inside])
    assert np.array_equal(colors["clamp"][inside, inside], colors["mirror"][inside, inside])


@pytest.mark.parametrize("backend", BACKENDS)
def test_alpha_cutoff_cuts_where_alpha_is_below_it(backend):
    rgba = np.concatenate([CHECKER, np.full((2, 2, 1), 255, np.uint8)], -1)
    rgba[0, 1, 3] = 40  # the top-right texel nearly transparent
    kw = dict(outputs=("color", "depth"), background=(0.0, 0.0, 0.0))
    mesh = lambda **c: tm.Mesh(SQUARE_V, SQUARE_F, uv=SQUARE_UV, texture=rgba, texture_filter="nearest", **c)
    kept = rendered(backend, mesh(), **kw)
    cut = rendered(backend, mesh(alpha_cutoff=0.5), **kw)
    tr, tl = (S // 4, 3 * S // 4), (S // 4, S // 4)
    assert kept.color[tr][1] > 150 and np.isfinite(kept.depth[tr])
    assert tuple(cut.color[tr][:3]) == (0, 0, 0) and np.isinf(cut.depth[tr])  # background, no surface
    assert np.array_equal(cut.color[tl], kept.color[tl])
    # where the geometry has a pass of its own (multisampled colour), it is cut there too
    ms = rendered(backend, mesh(alpha_cutoff=0.5), msaa=4, **kw)
    assert "gbuffer" in ms.passes and np.isinf(ms.depth[tr]) and np.isfinite(ms.depth[tl])
    # a vertex colour's alpha counts too
    alpha = np.array([[1, 1, 1, 0.2]] * 4)
    gone = rendered(backend, tm.Mesh(SQUARE_V, SQUARE_F, vertex_colors=alpha, alpha_cutoff=0.5), **kw)
    assert np.isinf(gone.depth).all()


@pytest.mark.parametrize("normals", ["smooth", "flat", "auto"])
def test_face_colours_are_flat_per_face_for_every_normal_mode(normals):
    V, F = tm.shapes.icosphere(2)
    rng = np.random.default_rng(3)
    fc = rng.integers(0, 256, (len(F), 3)).astype(np.uint8)
    r = tm.Renderer("vulkan")
    kw = dict(width=64, height=64, material=tm.Material.lambert(color=(1.0, 1.0, 1.0)), ambient=(0, 0, 0),
              outputs=("color", "depth"))
    plain = r.render(tm.Mesh(V, F, normals=normals), **kw)
    white = plain.color
    got = r.render(tm.Mesh(V, F, normals=normals, face_colors=fc), **kw).color
    lit = (decode(white[..., :3]).min(-1) > 0.15) & np.isfinite(plain.depth)
    albedo = decode(got[..., :3])[lit] / decode(white[..., :3])[lit]
    # every lit pixel's albedo is one face's colour (no blend between faces)
    d = np.abs(albedo[:, None, :] - decode(fc)[None]).max(-1).min(-1)
    assert (d < 0.04).mean() > 0.98 and lit.sum() > 500


MODELS = [
    lambda c, pv: tm.Material.lambert(c, per_vertex=pv),
    lambda c, pv: tm.Material.phong(c, per_vertex=pv),
    lambda c, pv: tm.Material.thresholded_phong(c, per_vertex=pv),
    lambda c, pv: tm.Material.bands(c, per_vertex=pv),
    lambda c, pv: tm.Material.bands(c, dither="bayer4"),
    lambda c, pv: tm.Material.hatching(c, mode="triplanar"),
    lambda c, pv: tm.Material.lut(None, c, per_vertex=pv),
]


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("colour", ["vertex", "face", "texture"])
def test_hatching_along_the_form_takes_a_meshs_colour_and_texture(backend, colour):
    # a mesh of one colour hatched along the form renders as the plain mesh whose material has
    # the product colour: the albedo tints the paper, the strokes stay where they were (face
    # colours give every corner its own vertex, and the field follows them there)
    V, F = tm.shapes.icosphere(3)
    base, tint = np.array([0.9, 0.7, 0.5]), np.array([153, 230, 76], dtype=np.uint8)
    product = tuple(float(x) for x in encode(decode(base * 255) * decode(tint)))
    coloured = {
        "vertex": lambda: tm.Mesh(V, F, vertex_colors=np.tile(tint, (len(V), 1))),
        "face": lambda: tm.Mesh(V, F, face_colors=np.tile(tint, (len(F), 1))),
        "texture": lambda: tm.Mesh(V, F, uv=np.full((len(V), 2), 0.5), texture=np.tile(tint, (4, 4, 1))),
    }[colour]()
    r = tm.Renderer(backend)
    kw = dict(width=96, height=96, lights=[tm.Light.key(), tm.Light.point((2.0, 1.0, 3.0))])
    tinted = r.render(coloured, material=tm.Material.hatching(tuple(base)), **kw)
    plain = r.render(tm.Mesh(V, F), material=tm.Material.hatching(product), **kw)
    diff = np.abs(tinted.color.astype(int) - plain.color.astype(int)).max(-1)
    assert (diff > 2).mean() <= 0.001, f"{(diff > 2).sum()} pixels"
    # the device decodes a texture's sRGB itself and may round it the other way (as it does
    # under triplanar hatching): one code at most
    assert np.median(diff) <= (1 if colour == "texture" else 0)
    assert (plain.color[..., :3] < 60).any(), "some ink"
    assert tinted.passes == plain.passes


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_uniform_albedo_multiplies_the_materials_colour_in_every_model(backend):
    V, F = tm.shapes.icosphere(3)
    base, tint = np.array([0.9, 0.7, 0.5]), np.array([0.6, 0.9, 0.3])
    product = tuple(float(x) for x in encode(decode(base * 255) * decode(tint * 255)))
    r = tm.Renderer(backend)
    for i, model in enumerate(MODELS):
        for per_vertex in (False, True):
            kw = dict(width=64, height=64, lights=[tm.Light.key(), tm.Light.point((2.0, 1.0, 3.0))])
            tinted = r.render(tm.Mesh(V, F, vertex_colors=np.tile(tint, (len(V), 1))), material=model(tuple(base), per_vertex), **kw)
            plain = r.render(tm.Mesh(V, F), material=model(product, per_vertex), **kw)
            diff = np.abs(tinted.color.astype(int) - plain.color.astype(int)).max(-1)
            # the same within rounding; a hatching tone right at a layer's threshold may round
            # to the other side (two pixels of 4096)
            assert (diff > 2).mean() <= 0.001, f"model {i}, per_vertex={per_vertex}: {(diff > 2).sum()} pixels"
            assert np.median(diff) == 0
            assert tinted.passes == plain.passes  # a coloured mesh costs no pass


def test_a_trimesh_brings_its_colours_and_texture():
    trimesh = need("trimesh")
    from PIL import Image

    V, F = grid(5)
    rng = np.random.default_rng(0)
    vc = rng.integers(0, 256, (len(V), 4)).astype(np.uint8)
    vc[:, 3] = 255
    fc = rng.integers(0, 256, (len(F), 4)).astype(np.uint8)
    fc[:, 3] = 255
    r = tm.Renderer("vulkan")
    same = lambda a, b: np.array_equal(r.render(a, **HEAD_ON).color, r.render(b, **HEAD_ON).color)
    assert same(tm.Mesh(trimesh.Trimesh(V, F, vertex_colors=vc, process=False)), tm.Mesh(V, F, vertex_colors=vc))
    assert same(tm.Mesh(trimesh.Trimesh(V, F, face_colors=fc, process=False)), tm.Mesh(V, F, face_colors=fc))
    uv = (V[:, :2] + 1) / 2
    textured = trimesh.Trimesh(V, F, visual=trimesh.visual.TextureVisuals(uv=uv, image=Image.fromarray(CHECKER)), process=False)
    assert same(tm.Mesh(textured), tm.Mesh(V, F, uv=uv, texture=CHECKER))
    # tm.render and Renderer.add_mesh take it too
    assert np.array_equal(tm.render(textured, **HEAD_ON).color, r.render(tm.Mesh(V, F, uv=uv, texture=CHECKER), **HEAD_ON).color)
    handle = r.add_mesh(textured)
    assert np.array_equal(r.render(handle, **HEAD_ON).color, r.render(tm.Mesh(V, F, uv=uv, texture=CHECKER), **HEAD_ON).color)
    # uv without a material of the file's (an OBJ with vt lines only: trimesh makes a grey
    # placeholder image) brings nothing; an OBJ material's Kd without an image is the colour
    bare = trimesh.Trimesh(V, F, visual=trimesh.visual.TextureVisuals(uv=uv), process=False)
    assert tm.Mesh(bare).colors == {} and same(tm.Mesh(bare), tm.Mesh(V, F))
    kd = trimesh.visual.material.SimpleMaterial(diffuse=[200, 30, 30, 255])
    red = trimesh.Trimesh(V, F, visual=trimesh.visual.TextureVisuals(uv=uv, material=kd), process=False)
    assert same(tm.Mesh(red), tm.Mesh(V, F, vertex_colors=np.tile([200, 30, 30], (len(V), 1)).astype(np.uint8)))
    # a glTF material: its base colour factor (linear light) multiplies the texture
    pbr = trimesh.visual.material.PBRMaterial(baseColorTexture=Image.fromarray(CHECKER), baseColorFactor=[128, 255, 255, 255])
    half_red = trimesh.Trimesh(V, F, visual=trimesh.visual.TextureVisuals(uv=uv, material=pbr), process=False)
    a = decode(r.render(tm.Mesh(half_red), **HEAD_ON).color[..., :3])
    b = decode(r.render(tm.Mesh(V, F, uv=uv, texture=CHECKER), **HEAD_ON).color[..., :3])
    bright = b[..., 0] > 0.3
    assert np.allclose(a[..., 0][bright] / b[..., 0][bright], 128 / 255, atol=0.02)
    assert np.allclose(a[..., 1:], b[..., 1:], atol=0.01)


def test_what_is_given_but_not_drawn_is_named_in_a_warning():
    trimesh = need("trimesh")
    V, F = grid(3)
    with pytest.warns(UserWarning, match="texture_filter: not used"):
        tm.Mesh(V, F, texture_filter="nearest")
    with pytest.warns(UserWarning, match="alpha_cutoff: not used"):
        tm.Renderer("vulkan").add_mesh(V, F, alpha_cutoff=0.5)
    coloured = trimesh.Trimesh(V, F, vertex_colors=np.full((len(V), 4), 200, np.uint8), process=False)
    with pytest.warns(UserWarning, match="vertex_colors are not used"):
        tm.Mesh(coloured, face_colors=np.zeros((len(F), 3)))
    pbr = trimesh.visual.material.PBRMaterial(baseColorFactor=[255, 255, 255, 255], normalTexture=np.zeros((2, 2, 3), np.uint8))
    normal_mapped = trimesh.Trimesh(V, F, visual=trimesh.visual.TextureVisuals(uv=V[:, :2], material=pbr), process=False)
    with pytest.warns(UserWarning, match="normalTexture is not drawn"):
        tm.Mesh(normal_mapped)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        tm.Mesh(V, F, uv=V[:, :2], texture=CHECKER, texture_wrap="mirror", alpha_cutoff=0.1)
        tm.Mesh(coloured)


def test_colour_inputs_are_not_modified_and_read_only_arrays_are_taken():
    V, F = grid(3)
    arrays = dict(vertex_colors=np.linspace(0, 1, len(V) * 3).reshape(-1, 3), uv=V[:, :2].copy(), texture=CHECKER.copy())
    copies = {k: v.copy() for k, v in arrays.items()}
    for a in arrays.values():
        a.setflags(write=False)
    tm.render(tm.Mesh(V, F, **arrays), **HEAD_ON)
    for k in arrays:
        assert np.array_equal(arrays[k], copies[k]), k


def test_a_pil_image_is_a_texture():
    need("trimesh")
    from PIL import Image

    V, F = grid(3)
    uv = (V[:, :2] + 1) / 2
    a = tm.render(tm.Mesh(V, F, uv=uv, texture=Image.fromarray(CHECKER)), **HEAD_ON).color
    b = tm.render(tm.Mesh(V, F, uv=uv, texture=CHECKER), **HEAD_ON).color
    assert np.array_equal(a, b)


def test_a_textured_file_renders_with_its_texture_in_batch_renders(tmp_path):
    trimesh = need("trimesh")
    from PIL import Image

    from toonmesh import batch

    V, F = grid(5)
    uv = (V[:, :2] + 1) / 2
    pbr = trimesh.visual.material.PBRMaterial(baseColorTexture=Image.fromarray(CHECKER), baseColorFactor=[255] * 4)
    visual = trimesh.visual.TextureVisuals(uv=uv, material=pbr)
    path = str(tmp_path / "checker.glb")
    trimesh.Trimesh(V, F, visual=visual, process=False).export(path)
    out = str(tmp_path / "out.png")
    batch.render_views(path, [out], camera=HEAD_ON["camera"], lights=HEAD_ON["lights"], width=S, height=S,
                       material=HEAD_ON["material"], ambient=(0.0, 0.0, 0.0))
    image = np.asarray(Image.open(out))[..., :3].astype(int)
    direct = tm.render(tm.Mesh(V, F, uv=uv, texture=CHECKER), **HEAD_ON).color[..., :3].astype(int)
    assert np.abs(image - direct).max() <= 2  # the file's texture, the right way up


def test_own_colours_show_the_same_however_the_meshes_are_given():
    V, F = tm.shapes.icosphere(2)
    colours = np.tile(np.array([40, 90, 220], np.uint8), (len(V), 1))
    mine = tm.Mesh(V, F, vertex_colors=colours)
    kw = dict(width=48, height=48)
    given = tm.render([mine], **kw).color
    white = tm.render([tm.Mesh(V, F, vertex_colors=colours, material=tm.Material.bands("#ffffff"))], **kw).color
    np.testing.assert_array_equal(given, white)  # the colours as they are, not times the default orange
    assert mine.material is None  # the caller's mesh is left as it was
    tinted = tm.render([mine], material=tm.Material.bands("#ff8000"), **kw).color
    assert np.abs(tinted.astype(int) - given.astype(int)).max() > 40  # a given material multiplies them
