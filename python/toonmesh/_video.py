"""Turntables as video: a GIF (Pillow) or an MP4 (H.264 through imageio-ffmpeg, which ships
its own ffmpeg), written from (K, H, W, 4) uint8 frames; for the viewer's ``turntable`` and the
command line's ``render -o turn.mp4 --views N``."""

from __future__ import annotations

import importlib
from typing import Any, Callable

import numpy as np

#: The video formats written, by file suffix.
VIDEO_SUFFIXES = (".gif", ".mp4")
#: Frames per second of a turntable video unless told.
DEFAULT_FPS = 24

Writer = Callable[[str, np.ndarray, int], None]

#: The frame rates a video may have.
FPS_RANGE = (1, 60)


def check_fps(fps: Any) -> int:
    """``fps``, an int in ``FPS_RANGE``, checked (TypeError or ValueError naming it)."""
    if isinstance(fps, (bool, np.bool_)) or not isinstance(fps, (int, np.integer)):
        raise TypeError(f"fps: expected an int, got {type(fps).__name__}")
    if not FPS_RANGE[0] <= fps <= FPS_RANGE[1]:
        raise ValueError(f"fps: must be in [{FPS_RANGE[0]}, {FPS_RANGE[1]}], got {fps}")
    return int(fps)


def _write_gif(path: str, frames: np.ndarray, fps: int) -> None:
    from PIL import Image

    images = [Image.fromarray(np.ascontiguousarray(f[..., :3])) for f in frames]
    images[0].save(path, save_all=True, append_images=images[1:], duration=round(1000 / fps), loop=0,
                   optimize=False, disposal=1)


def _write_mp4(path: str, frames: np.ndarray, fps: int) -> None:
    import imageio_ffmpeg  # type: ignore[import-untyped]

    height, width = frames.shape[1:3]
    gen = imageio_ffmpeg.write_frames(path, (width, height), fps=fps, codec="libx264", pix_fmt_in="rgb24",
                                      pix_fmt_out="yuv420p", macro_block_size=1, output_params=["-loglevel", "error"])
    gen.send(None)
    for f in frames:
        gen.send(np.ascontiguousarray(f[..., :3]).tobytes())
    gen.close()


#: Per suffix: its writer, and the module and package it needs.
_VIDEO = {".gif": (_write_gif, "PIL", "Pillow"), ".mp4": (_write_mp4, "imageio_ffmpeg", "imageio-ffmpeg")}


def video_writer(kind: str, who: str) -> Writer:
    """The writer ``(path, frames, fps)`` of a ``kind`` (".gif" or ".mp4") video, its library
    checked before any render; ``who`` (the caller, e.g. "turntable") names it in the error."""
    write, module, package = _VIDEO[kind]
    try:
        importlib.import_module(module)
    except ImportError:
        raise ImportError(f"{who}: writing {kind} needs {package} (pip install 'toonmesh[notebook]')") from None
    return write
