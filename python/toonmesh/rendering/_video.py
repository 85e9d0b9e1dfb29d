"""Turntables as video: a GIF (Pillow), an MP4 (H.264) or a WebM (VP9), the last two through
imageio-ffmpeg, which ships its own ffmpeg; written from (K, H, W, 4) or (K, H, W, 3) uint8
frames, with a progress bar (tqdm) where there are many; for :meth:`RenderStack.save`, the
viewer's ``turntable`` and the command line's ``render -o turn.mp4 --views N``."""

from __future__ import annotations

import importlib
import os
from typing import Any, Callable, Iterable

import numpy as np

from toonmesh.arguments._checks import flag

#: The video formats written, by file suffix.
VIDEO_SUFFIXES = (".gif", ".mp4", ".webm")
#: Frames per second of a turntable video unless told.
DEFAULT_FPS = 24
#: How long a turntable video lasts unless told (seconds, all the way round).
DEFAULT_SECONDS = 4.0
#: The frame rates a video may have.
FPS_RANGE = (1, 60)
#: From this many frames on, writing shows a progress bar (where tqdm is installed).
PROGRESS_FROM = 8

Writer = Callable[[str, Iterable[np.ndarray], int, int, int], None]


def check_fps(fps: Any) -> int:
    """``fps``, an int in ``FPS_RANGE``, checked (TypeError or ValueError naming it)."""
    if isinstance(fps, (bool, np.bool_)) or not isinstance(fps, (int, np.integer)):
        raise TypeError(f"fps: expected an int, got {type(fps).__name__}")
    if not FPS_RANGE[0] <= fps <= FPS_RANGE[1]:
        raise ValueError(f"fps: must be in [{FPS_RANGE[0]}, {FPS_RANGE[1]}], got {fps}")
    return int(fps)


def _rgb(frame: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(frame[..., :3])


def _write_gif(path: str, frames: Iterable[np.ndarray], fps: int, width: int, height: int) -> None:
    from PIL import Image

    images = [Image.fromarray(_rgb(f)) for f in frames]
    images[0].save(path, save_all=True, append_images=images[1:], duration=round(1000 / fps), loop=0,
                   optimize=False, disposal=1)


def _ffmpeg(codec: str, extra: Iterable[str]) -> Writer:
    def write(path: str, frames: Iterable[np.ndarray], fps: int, width: int, height: int) -> None:
        import imageio_ffmpeg  # type: ignore[import-untyped]

        gen = imageio_ffmpeg.write_frames(path, (width, height), fps=fps, codec=codec, pix_fmt_in="rgb24",
                                          pix_fmt_out="yuv420p", macro_block_size=1,
                                          output_params=["-loglevel", "error", *extra])
        gen.send(None)
        for f in frames:
            gen.send(_rgb(f).tobytes())
        gen.close()

    return write


#: Per suffix: its writer, the module and package it needs, and whether its width and height
#: must be even (4:2:0 chroma).
_VIDEO = {
    ".gif": (_write_gif, "PIL", "Pillow", False),
    ".mp4": (_ffmpeg("libx264", []), "imageio_ffmpeg", "imageio-ffmpeg", True),
    # constant quality (-crf with no bit rate cap), as libvpx-vp9 wants for it
    ".webm": (_ffmpeg("libvpx-vp9", ["-crf", "32", "-b:v", "0"]), "imageio_ffmpeg", "imageio-ffmpeg", True),
}


def video_kind(path: Any, who: str = "path") -> str:
    """The suffix of a video file name ``path`` (a str or os.PathLike), checked; ``who`` names
    it in errors."""
    target = os.fspath(path) if isinstance(path, (str, os.PathLike)) else None
    if not isinstance(target, str):
        raise TypeError(f"{who}: expected a str or os.PathLike, got {type(path).__name__}")
    kind = os.path.splitext(target)[1].lower()
    if kind not in VIDEO_SUFFIXES:
        raise ValueError(f"{who}: expected a {', '.join(VIDEO_SUFFIXES)} file name, got {target!r}")
    return kind


def check_video_size(kind: str, width: int, height: int, who: str) -> None:
    """Refuses an odd width or height for a format that needs them even (ValueError naming
    ``who``)."""
    if _VIDEO[kind][3] and (width % 2 or height % 2):
        raise ValueError(f"{who}: a {kind} video needs an even width and height, got {width}x{height}")


def video_writer(kind: str, who: str) -> Writer:
    """The writer ``(path, frames, fps, width, height)`` of a ``kind`` video (a suffix of
    ``VIDEO_SUFFIXES``), its library checked before any render; ``who`` (the caller, e.g.
    "turntable") names it in the error."""
    write, module, package, _ = _VIDEO[kind]
    try:
        importlib.import_module(module)
    except ImportError:
        raise ImportError(f"{who}: writing {kind} needs {package} (pip install 'toonmesh[notebook]')") from None
    return write


def _with_progress(frames: np.ndarray, progress: bool, what: str) -> Iterable[np.ndarray]:
    if not progress or len(frames) < PROGRESS_FROM:
        return frames
    try:
        from tqdm.auto import tqdm
    except ImportError:  # no bar without tqdm
        return frames
    return tqdm(frames, desc=what, unit="frame", leave=False)


def save_video(path: Any, frames: Any, fps: int = DEFAULT_FPS, progress: bool = True, who: str = "path") -> str:
    """Writes ``frames`` ((K, H, W, 3|4) uint8) to the video file ``path`` (.gif, .mp4, .webm) at
    ``fps`` frames per second, with a progress bar when ``progress`` and there are many frames.
    Returns the path written, as a string. Errors name ``who`` (the path's argument)."""
    kind = video_kind(path, who)
    fps = check_fps(fps)
    progress = flag("progress", progress)
    frames = np.asarray(frames)
    if frames.dtype != np.uint8 or frames.ndim != 4 or frames.shape[-1] not in (3, 4) or len(frames) == 0:
        raise ValueError(f"frames: expected (K, H, W, 3|4) uint8 with K >= 1, got {frames.shape} {frames.dtype}")
    height, width = frames.shape[1:3]
    check_video_size(kind, width, height, who)
    write = video_writer(kind, who)
    target = os.fspath(path)
    write(target, _with_progress(frames, progress, f"writing {os.path.basename(target)}"), fps, width, height)
    return target
