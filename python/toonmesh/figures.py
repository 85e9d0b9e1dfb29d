"""Figures that compare renders: labelled panels side by side, as the gallery draws them.

Needs Pillow 10.1 or later to draw the text (``pip install pillow``, or ``'toonmesh[io]'``).
"""

from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

__all__ = ["panels"]

#: the labels' text height in pixels, and the white box's margin round it
LABEL_SIZE = 13
_MARGIN = (3, 2)
_AT = (6, 4)


def _image(k: int, value: object) -> np.ndarray:
    if not isinstance(value, np.ndarray):
        raise TypeError(f"images[{k}]: expected a NumPy array, got {type(value).__name__}")
    if value.dtype != np.uint8:
        raise TypeError(f"images[{k}]: expected dtype uint8 (as RenderResult.color), got {value.dtype}")
    if value.ndim != 3 or value.shape[2] not in (3, 4) or 0 in value.shape:
        raise ValueError(f"images[{k}]: expected an (H, W, 3) or (H, W, 4) image, got shape {value.shape}")
    return value[..., :3]


def panels(images: Sequence[np.ndarray], labels: Sequence[str], columns: Optional[int] = None) -> np.ndarray:
    """The images in rows of ``columns``, each with its label at its top left, as one image.

    Args:
        images: sequence of (H, W, 3) or (H, W, 4) uint8 arrays, all of one H and W. The
            panels, in reading order (``RenderResult.color`` is one); alpha is dropped.
        labels: sequence of str, one per image. What each panel shows, drawn in black on a
            white box at its top left (``LABEL_SIZE`` pixels high; "" for none).
        columns: int >= 1, default None. Panels per row; None puts them all in one row. A last
            row that is not full is filled with white.

    Returns:
        (rows * H, columns * W, 3) uint8 array, RGB; the inputs are not modified.

    Raises:
        TypeError: an image that is not a uint8 array, a label that is not a str or a
            ``columns`` that is not an int.
        ValueError: no images, images of other shapes or sizes, not one label per image, or
            ``columns`` below 1.
        ImportError: Pillow is not installed.
    """
    try:
        from PIL import Image, ImageDraw, ImageFont
    except ImportError:
        raise ImportError("toonmesh.figures.panels needs Pillow: pip install pillow (or 'toonmesh[io]')") from None
    cells = [_image(k, image) for k, image in enumerate(images)]
    if not cells:
        raise ValueError("images: expected at least one image")
    shape = cells[0].shape
    for k, cell in enumerate(cells):
        if cell.shape != shape:
            raise ValueError(f"images[{k}]: every panel must be {shape[1]}x{shape[0]} like images[0], "
                             f"got {cell.shape[1]}x{cell.shape[0]}")
    texts = list(labels) if not isinstance(labels, str) else None
    if texts is None or len(texts) != len(cells):
        raise ValueError(f"labels: expected one str per image ({len(cells)}), got {labels!r}")
    for k, text in enumerate(texts):
        if not isinstance(text, str):
            raise TypeError(f"labels[{k}]: expected a str, got {type(text).__name__}")
    if columns is None:
        columns = len(cells)
    if isinstance(columns, bool) or not isinstance(columns, (int, np.integer)):
        raise TypeError(f"columns: expected an int or None, got {type(columns).__name__}")
    if columns < 1:
        raise ValueError(f"columns: expected 1 or more, got {columns}")
    font = ImageFont.load_default(size=LABEL_SIZE)
    drawn = []
    for cell, text in zip(cells, texts):
        pil = Image.fromarray(np.ascontiguousarray(cell))
        if text:
            draw = ImageDraw.Draw(pil)
            left, top, right, bottom = draw.textbbox(_AT, text, font=font)
            mx, my = _MARGIN
            draw.rectangle((left - mx, top - my, right + mx, bottom + my), fill="white")
            draw.text(_AT, text, font=font, fill="black")
        drawn.append(np.asarray(pil))
    rows = -(-len(drawn) // columns)
    drawn += [np.full(shape, 255, np.uint8)] * (rows * columns - len(drawn))
    return np.concatenate([np.concatenate(drawn[r * columns:(r + 1) * columns], axis=1) for r in range(rows)])
