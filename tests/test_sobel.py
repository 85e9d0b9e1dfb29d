"""Sobel filters cross-validated against scikit-image and OpenCV; the paper's edge rule."""


import numpy as np
import pytest

from toonmesh import edges as te
from toonmesh.testing import sobel_vs_skimage


from conftest import need  # noqa: E402  (skips on a user machine without the peer, fails in CI)


def images():
    rng = np.random.default_rng(42)
    step = np.zeros((17, 23))
    step[:, 11:] = 1.0
    diag = np.fromfunction(lambda r, c: (r + c > 20).astype(float), (19, 21))
    yield "random", rng.random((31, 47))
    yield "random-big-range", rng.normal(size=(20, 20)) * 3
    yield "step", step
    yield "step-rows", step.T.copy()
    yield "diagonal", diag
    yield "constant", np.full((9, 13), 0.375)
    yield "1xN", rng.random((1, 37))
    yield "Nx1", rng.random((29, 1))
    yield "1x1", np.array([[0.5]])
    yield "2x2", rng.random((2, 2))
    yield "3x3", rng.random((3, 3))


def as_dtype(img, dtype):
    if dtype == np.uint8:
        lo, hi = img.min(), img.max()
        return np.round((img - lo) / (hi - lo if hi > lo else 1) * 255).astype(np.uint8)
    return img.astype(dtype)


def agrees_with_skimage(img, mask=None, which="sobel"):
    """The same dtype as scikit-image's result, and the same numbers within 1e-6."""
    d = sobel_vs_skimage(img, mask, which=which)
    return d.dtype == d.peer_dtype and d.largest <= 1e-6


@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.uint8])
@pytest.mark.parametrize("which", ["sobel", "sobel_h", "sobel_v"])
def test_matches_skimage(dtype, which):
    for name, img in images():
        assert agrees_with_skimage(as_dtype(img, dtype), which=which), name


@pytest.mark.parametrize("dtype", [np.float16, np.int16, np.uint16, np.int32, bool])
def test_other_dtypes_follow_skimage(dtype):
    rng = np.random.default_rng(3)
    if dtype is bool:
        img = rng.random((15, 16)) > 0.5
    elif dtype is np.float16:
        img = rng.random((15, 16)).astype(dtype)
    else:
        info = np.iinfo(dtype)
        img = rng.integers(max(info.min, -30000), min(info.max, 30000), size=(15, 16)).astype(dtype)
    assert agrees_with_skimage(img)


def test_mask_matches_skimage():
    rng = np.random.default_rng(7)
    img = rng.random((40, 50)).astype(np.float32)
    mask = np.zeros((40, 50), dtype=bool)
    mask[5:30, 3:45] = True
    mask[10, 10] = False
    for which in ("sobel", "sobel_h", "sobel_v"):
        assert agrees_with_skimage(img, mask, which)
    assert agrees_with_skimage(img, np.ones_like(mask))


def test_channels_are_filtered_separately():
    img = np.random.default_rng(1).random((20, 30, 3)).astype(np.float32)
    ours = te.sobel(img)
    assert ours.shape == img.shape and ours.dtype == np.float32
    assert agrees_with_skimage(img)  # each channel against scikit-image's filter of it


def test_large_float32_image():
    img = np.random.default_rng(5).random((517, 1031)).astype(np.float32)
    assert agrees_with_skimage(img)
    assert agrees_with_skimage(np.asfortranarray(img)[::2, ::3])


@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.uint8])
def test_opencv_convention_matches_cv2(dtype):
    cv2 = need("cv2")
    for name, img in images():
        img = as_dtype(img, dtype)
        ddepth = cv2.CV_32F if dtype == np.float32 else cv2.CV_64F
        src = img if dtype != np.uint8 else img
        gx = cv2.Sobel(src, ddepth, 1, 0, ksize=3)
        gy = cv2.Sobel(src, ddepth, 0, 1, ksize=3)
        tol = 1e-6 * max(1.0, float(np.abs(img).max()))
        assert np.max(np.abs(te.sobel_v(img, convention="opencv") - gx)) <= tol, name
        assert np.max(np.abs(te.sobel_h(img, convention="opencv") - gy)) <= tol, name
        assert np.max(np.abs(te.sobel(img, convention="opencv") - cv2.magnitude(gx, gy))) <= tol, name


def test_opencv_skimage_equivalent_call():
    """The benchmark's cv2 baseline is the same numbers as skimage (and so as ours)."""
    cv2 = need("cv2")
    img = np.random.default_rng(11).random((64, 80)).astype(np.float32)
    gx = cv2.Sobel(img, cv2.CV_32F, 1, 0, ksize=3, scale=0.25, borderType=cv2.BORDER_REFLECT)
    gy = cv2.Sobel(img, cv2.CV_32F, 0, 1, ksize=3, scale=0.25, borderType=cv2.BORDER_REFLECT)
    assert np.max(np.abs(te.sobel(img) - cv2.magnitude(gx, gy) / np.sqrt(2))) <= 1e-6


def test_sobel_bad_input():
    with pytest.raises(ValueError, match="image"):
        te.sobel(np.zeros((2, 3, 4, 5)))
    with pytest.raises(ValueError, match="image"):
        te.sobel(np.zeros((0, 3)))
    with pytest.raises(TypeError, match="image"):
        te.sobel(np.zeros((3, 3), dtype=complex))
    with pytest.raises(ValueError, match="convention"):
        te.sobel(np.zeros((3, 3)), convention="matlab")
    with pytest.raises(ValueError, match="mask"):
        te.sobel(np.zeros((3, 3)), mask=np.ones((2, 2)))
    img = np.random.default_rng(0).random((8, 8))
    before = img.copy()
    te.sobel(img, mask=img > 0.5)
    assert np.array_equal(img, before)


# ---------------------------------------------------------------------------------------------
# the paper's rule


def paper_oracle(buf):
    """max over channels of max(|Gx|, |Gy|), reflect border, by explicit correlation."""
    sx = np.array([[1, 0, -1], [2, 0, -2], [1, 0, -1]], dtype=np.float64)
    buf = buf if buf.ndim == 3 else buf[..., None]
    p = np.pad(buf.astype(np.float64), ((1, 1), (1, 1), (0, 0)), mode="symmetric")
    h, w = buf.shape[:2]
    gx = sum(sx[i, j] * p[i : i + h, j : j + w] for i in range(3) for j in range(3))
    gy = sum(sx.T[i, j] * p[i : i + h, j : j + w] for i in range(3) for j in range(3))
    return np.maximum(np.abs(gx), np.abs(gy)).max(axis=2)


def test_detect_edges_rule():
    rng = np.random.default_rng(2)
    normal = rng.normal(size=(24, 32, 3)).astype(np.float32)
    normal /= np.linalg.norm(normal, axis=2, keepdims=True)
    depth = rng.random((24, 32))
    det = te.detect_edges(normal, depth, normal_threshold=2.0, depth_threshold=1.5)
    assert det.normal_gradient.dtype == np.float32 and det.depth_gradient.dtype == np.float64
    assert np.allclose(det.normal_gradient, paper_oracle(normal), atol=1e-5)
    assert np.allclose(det.depth_gradient, paper_oracle(depth), atol=1e-12)
    assert np.array_equal(det.mask, (paper_oracle(normal) > 2.0) | (paper_oracle(depth) > 1.5))
    mask, gn, gd = te.detect_edges(depth=depth, depth_threshold=1.5)
    assert gn is None and np.array_equal(mask, paper_oracle(depth) > 1.5)


def test_detect_edges_background():
    depth = np.full((10, 12), np.inf)
    depth[3:7, 4:9] = 2.0
    depth[4, 5] = 2.01
    depth[0, 0] = np.nan
    det = te.detect_edges(depth=depth, depth_threshold=0.1)
    g = det.depth_gradient
    assert np.all(g[0:2, :] == 0) and g[5, 7] == 0  # deep background and flat interior
    assert np.isinf(g[3, 4]) and np.isinf(g[2, 6]) and np.isinf(g[6, 9])  # the outline
    assert det.mask[3, 4] and not det.mask[0, 0]
    assert g[4, 6] == pytest.approx(0.02)  # a real depth step inside the object
    with pytest.raises(ValueError, match="normal"):
        te.detect_edges()
    with pytest.raises(ValueError, match="depth"):
        te.detect_edges(np.zeros((4, 4, 3)), np.zeros((5, 4)))
