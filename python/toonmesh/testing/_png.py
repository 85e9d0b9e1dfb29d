"""PNG files of 8-bit images for the snapshot tests (:mod:`toonmesh.testing`).

Read by the core's PNG codec (the Rust ``image`` crate, which also encodes renders:
``RenderResult.png_bytes``): every filter, bit depth and colour type it reads. Written here, with
the standard library and NumPy, because a snapshot's bytes must stay as they are: each row stored
with PNG's "Sub" filter (each byte less the byte of the pixel to its left), deflated by zlib at
level 9, so that the same image gives the same bytes everywhere. The core's encoder chooses a
filter per row and deflates with its own compressor: other bytes for the same pixels (on the
tests' two snapshots: neither byte-identical, 25% larger), so it would rewrite every reference
file a project has committed.
"""

from __future__ import annotations

import struct
import zlib

import numpy as np

from toonmesh import _core

_SIGNATURE = b"\x89PNG\r\n\x1a\n"
#: PNG colour type by channel count.
_COLOR_TYPE = {1: 0, 2: 4, 3: 2, 4: 6}


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def encode(image: np.ndarray) -> bytes:
    """PNG file bytes of an (H, W) or (H, W, C) uint8 image, C in 1..4 (grey, grey and alpha,
    RGB, RGBA)."""
    pixels = np.ascontiguousarray(image, dtype=np.uint8)
    if pixels.ndim == 2:
        pixels = pixels[:, :, None]
    h, w, c = pixels.shape
    # Sub filter: each byte less the byte one pixel to its left (mod 256)
    filtered = pixels.copy()
    filtered[:, 1:] -= pixels[:, :-1]
    rows = np.concatenate([np.ones((h, 1), np.uint8), filtered.reshape(h, w * c)], axis=1)
    header = struct.pack(">IIBBBBB", w, h, 8, _COLOR_TYPE[c], 0, 0, 0)
    return (_SIGNATURE + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(rows.tobytes(), 9))
            + _chunk(b"IEND", b""))


def decode(data: bytes, name: str = "image") -> np.ndarray:
    """The (H, W, C) uint8 pixels of PNG file bytes (C: 1 grey, 2 grey and alpha, 3 RGB,
    4 RGBA; 16-bit and palette files as 8-bit), by the core's codec. Raises ValueError naming
    ``name`` for a file that is not a readable PNG."""
    if bytes(data[:8]) != _SIGNATURE:
        raise ValueError(f"{name}: not a PNG file")
    try:
        return _core.decode_png(bytes(data))  # type: ignore[no-any-return]
    except ValueError as exc:
        reason = str(exc).split(": ", 1)[-1]  # the core names its argument, data
        raise ValueError(f"{name}: {reason}") from None
