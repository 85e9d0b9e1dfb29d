"""The demo: the papers' pipeline.

What ``python -m toonmesh demo`` (``make demo``) draws: the Stanford bunny smoothed five times
(Al-Rousan et al.), shaded with the thresholded Phong model, with mesh-space outlines (Kang et
al.), on a ground plane.
"""

from toonmesh.cli import main

main(["demo", "--out", "demo.png"])
