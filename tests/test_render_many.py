"""Many views in flight: the same bits as rendering each view alone, stacked arrays, and a
stream of renders that allocates nothing new."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh import _core
from toonmesh.testing import assert_drawings_close, assert_images_close

from conftest import need

BACKENDS = ["vulkan", "gl"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_render_many_gives_the_bits_of_each_view_alone(backend):
    V, F = _core.icosphere(3, 0.04, 4)
    r = tm.Renderer(backend)
    mesh = r.add_mesh(V, F)
    cams = [tm.Camera.fit((np.sin(a), 0.3, np.cos(a))) for a in np.linspace(0, 2 * np.pi, 7, endpoint=False)]
    kw = dict(width=64, height=48, outputs=("color", "depth", "outline", "lines"), outlines="both")
    stack = r.render_many(mesh, cams, **kw)
    assert len(stack) == 7 and stack.color.shape == (7, 48, 64, 4) and stack.depth.shape == (7, 48, 64)
    assert stack.normal is None
    for i, cam in enumerate(cams):
        alone = r.render(mesh, camera=cam, **kw)
        assert_images_close(stack[i], alone, levels=0, share=0.0)
        assert_images_close(stack.color[i], alone, levels=0, share=0.0)
        assert np.array_equal(stack[i].depth, alone.depth, equal_nan=True)
        assert np.array_equal(stack[i].outline, alone.outline)
        assert_drawings_close(stack[i], alone, pixels=0.0, share=0.0)
        assert np.array_equal(stack[i].view_matrix, alone.view_matrix)
    assert not np.array_equal(stack.color[0], stack.color[1])


def test_render_many_checks_its_cameras():
    r = tm.Renderer()
    V, F = _core.icosphere(1, 0.0, 0)
    mesh = r.add_mesh(V, F)
    with pytest.raises(TypeError, match="cameras\\[1\\]"):
        r.render_many(mesh, [tm.Camera.fit(), "front"])
    with pytest.raises(TypeError, match="cameras"):
        r.render_many(mesh, 5)
    assert len(r.render_many(mesh, [], width=8, height=8)) == 0


def test_a_stack_of_views_saves_itself_as_a_video_in_each_format(tmp_path, capsys):
    Image = need("PIL.Image")
    imageio_ffmpeg = need("imageio_ffmpeg")
    V, F = _core.icosphere(3, 0.04, 4)
    r = tm.Renderer()
    mesh = r.add_mesh(V, F)
    cams = [tm.Camera.fit(turn=t) for t in range(0, 360, 36)]
    stack = r.render_many(mesh, cams, width=64, height=48)
    gif = stack.save(tmp_path / "turn.gif", fps=10)
    assert gif == str(tmp_path / "turn.gif")
    assert "writing turn.gif" in capsys.readouterr().err  # ten frames: a progress bar
    with Image.open(gif) as im:
        assert im.n_frames == 10 and im.size == (64, 48) and abs(im.info["duration"] - 100) <= 10
        im.seek(3)  # frame k is view k (GIF's palette rounds the colours)
        assert np.abs(np.asarray(im.convert("RGB")).astype(int) - stack.color[3, ..., :3]).mean() < 4.0
    for suffix in (".mp4", ".webm"):
        path = stack.save(tmp_path / f"turn{suffix}", fps=5, progress=False)
        assert imageio_ffmpeg.count_frames_and_secs(path) == (10, 2.0), suffix
        reader = imageio_ffmpeg.read_frames(path)
        next(reader)  # its metadata, then the frames
        first = np.frombuffer(next(reader), np.uint8)
        reader.close()
        assert np.abs(first.reshape(48, 64, 3).astype(int) - stack.color[0, ..., :3]).mean() < 6.0, suffix
    assert "writing" not in capsys.readouterr().err
    with pytest.raises(ValueError, match="path: expected a .gif, .mp4, .webm"):
        stack.save(tmp_path / "turn.avi")
    with pytest.raises(ValueError, match="fps"):
        stack.save(tmp_path / "turn.gif", fps=0)
    odd = r.render_many(mesh, cams[:2], width=33, height=48)
    with pytest.raises(ValueError, match="path: a .webm video needs an even width and height, got 33x48"):
        odd.save(tmp_path / "odd.webm")
    depth_only = r.render_many(mesh, cams[:2], width=32, height=32, outputs=("depth",))
    with pytest.raises(ValueError, match="colour"):
        depth_only.save(tmp_path / "depth.gif")
    assert not any((tmp_path / n).exists() for n in ("turn.avi", "odd.webm", "depth.gif"))
