"""The viewer, as a still.

``tm.Viewer`` is the live view in Jupyter: drag to orbit, wheel to zoom. Its methods do what the
pointer does, so a script can drive it too: here it starts on the bunny, orbits, zooms, switches
the material to hatching, and prints the ``tm.render`` call that reproduces the last frame. The
strip shows the frames it drew.
"""

import numpy as np
from PIL import Image, ImageDraw, ImageFont

import toonmesh as tm
from toonmesh.data import bunny

def label(image: np.ndarray, text: str) -> np.ndarray:
    """``image`` (H, W, 3 or 4) uint8 with ``text`` on a white box at its top left."""
    pil = Image.fromarray(image)
    draw = ImageDraw.Draw(pil)
    font = ImageFont.load_default(size=13)
    box = draw.textbbox((6, 4), text, font=font)
    draw.rectangle((box[0] - 3, box[1] - 2, box[2] + 3, box[3] + 2), fill="white")
    draw.text((6, 4), text, font=font, fill="black")
    return np.asarray(pil)


V, F = bunny()
v = tm.Viewer(V, F, outlines="mesh", width=256, height=256)
frames = [label(v.frame, "start")]
v.orbit(120, -20)                          # as a drag of 120 pixels right, 20 up
frames.append(label(v.frame, "orbit(120, -20)"))
v.zoom(1.6)
frames.append(label(v.frame, "zoom(1.6)"))
v.material = tm.Material.hatching()        # every setting re-renders when set
frames.append(label(v.frame, "material = hatching"))
print(v.code())
Image.fromarray(np.concatenate(frames, axis=1)).save("viewer_frames.png", optimize=True)
