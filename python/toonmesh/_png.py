"""PNG files of 8-bit images for the snapshot tests (:mod:`toonmesh.testing`), written and read
with the standard library and NumPy alone, so that comparing renders needs no imaging library.

The writer stores each row with PNG's "Sub" filter (each byte less the byte of the pixel to its
left), deflated at level 9: the same image gives the same bytes everywhere. The reader undoes
all five filters (the four that look left or up vectorised across a row; "Average" and "Paeth",
which chain along the row, pixel by pixel, or through Pillow when it is installed), for 8-bit
grey, grey with alpha, RGB and RGBA images, not interlaced: what toonmesh and most tools write.
"""

from __future__ import annotations

import struct
import zlib
import numpy as np

_SIGNATURE = b"\x89PNG\r\n\x1a\n"
#: PNG colour type by channel count, and back.
_COLOR_TYPE = {1: 0, 2: 4, 3: 2, 4: 6}
_CHANNELS = {v: k for k, v in _COLOR_TYPE.items()}


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
    4 RGBA). Raises ValueError naming ``name`` for a file that is not such a PNG."""
    if data[:8] != _SIGNATURE:
        raise ValueError(f"{name}: not a PNG file")
    pos, idat, header = 8, [], None
    while pos + 8 <= len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if header is None:
        raise ValueError(f"{name}: a PNG file without its header")
    w, h, depth, color_type, _, _, interlace = header
    if depth != 8 or color_type not in _CHANNELS or interlace:
        return _decode_with_pillow(data, name, "an 8-bit grey, RGB or RGBA image, not interlaced")
    c = _CHANNELS[color_type]
    raw = np.frombuffer(zlib.decompress(b"".join(idat)), np.uint8)
    if raw.size != h * (1 + w * c):
        raise ValueError(f"{name}: a PNG file whose pixel data does not fill its {w}x{h} image")
    rows = raw.reshape(h, 1 + w * c)
    kinds = rows[:, 0]
    if np.any(kinds > 4):
        raise ValueError(f"{name}: a PNG file with an unknown row filter")
    if np.any(kinds >= 3):
        try:
            return _decode_with_pillow(data, name, "")
        except ImportError:
            pass  # the slow way below
    return _unfilter(rows[:, 1:].reshape(h, w, c), kinds)


def _unfilter(rows: np.ndarray, kinds: np.ndarray) -> np.ndarray:
    h, w, c = rows.shape
    out = np.zeros((h, w, c), np.uint8)
    above = np.zeros((w, c), np.uint8)
    for y in range(h):
        row, kind = rows[y], kinds[y]
        if kind == 0:
            cur = row.copy()
        elif kind == 1:
            cur = np.cumsum(row, axis=0, dtype=np.uint8)
        elif kind == 2:
            cur = row + above
        else:
            cur = _chained(row, above, kind)
        out[y] = cur
        above = cur
    return out


def _chained(row: np.ndarray, above: np.ndarray, kind: int) -> np.ndarray:
    """One row under the Average (3) or Paeth (4) filter, pixel by pixel."""
    w, _ = row.shape
    r, b = row.astype(np.int32), above.astype(np.int32)
    out = np.zeros_like(r)
    left = np.zeros(row.shape[1], np.int32)
    upper_left = np.zeros(row.shape[1], np.int32)
    for x in range(w):
        up = b[x]
        if kind == 3:
            pred = (left + up) // 2
        else:
            p = left + up - upper_left
            pa, pb, pc = np.abs(p - left), np.abs(p - up), np.abs(p - upper_left)
            pred = np.where((pa <= pb) & (pa <= pc), left, np.where(pb <= pc, up, upper_left))
        out[x] = (r[x] + pred) & 0xFF
        left, upper_left = out[x], up
    return out.astype(np.uint8)


def _decode_with_pillow(data: bytes, name: str, needs: str) -> np.ndarray:
    try:
        import io

        from PIL import Image
    except ImportError:
        if not needs:
            raise
        raise ValueError(f"{name}: reading this PNG needs Pillow (pip install pillow); without it, "
                         f"{needs}") from None
    with Image.open(io.BytesIO(data)) as im:
        pixels = np.asarray(im if im.mode in ("L", "LA", "RGB", "RGBA") else im.convert("RGBA"), dtype=np.uint8)
    return pixels[:, :, None] if pixels.ndim == 2 else pixels
