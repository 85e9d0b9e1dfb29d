"""The viewer, as a still.

``tm.Viewer`` is the live view in Jupyter: drag to orbit, wheel to zoom. Its methods do what the
pointer does, so a script can drive it too: here it starts on the bunny, orbits, zooms, switches
the material to hatching, and prints the ``tm.render`` call that reproduces the last frame. The
strip shows the frames it drew.
"""

from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny
from toonmesh.figures import panels

V, F = bunny()
v = tm.Viewer(V, F, outlines="mesh", width=256, height=256)
frames = [v.frame]
v.orbit(120, -20)  # as a drag of 120 pixels right, 20 up
frames.append(v.frame)
v.zoom(1.6)
frames.append(v.frame)
v.material = tm.Material.hatching()  # every setting re-renders when set
frames.append(v.frame)
print(v.code())
labels = ["start", "orbit(120, -20)", "zoom(1.6)", "material = hatching"]
Image.fromarray(panels(frames, labels)).save("viewer_frames.png", optimize=True)
