"""What the figure scripts (``docs/*_figure.py``) share: where the repository and its test meshes
are, the smoothed bunny most of them draw, and how a figure is written. The scripts run from the
repository root (``python docs/<name>_figure.py``), which puts this folder on the import path.
"""

from pathlib import Path
from typing import Tuple

import numpy as np
from PIL import Image

import toonmesh as tm
from toonmesh.data import bunny

ROOT = Path(__file__).resolve().parent.parent
#: The test meshes (spot, the cow, fandisk, the raw Stanford bunny, ...).
MESHES = ROOT / "tests" / "data" / "meshes"


def smoothed_bunny() -> Tuple[np.ndarray, np.ndarray]:
    """The shipped bunny after five steps of Al-Rousan et al.'s Laplacian smoothing
    (``preset="paper"``), which take the scan's noise out of the bands."""
    V, F = bunny()
    return tm.smooth.laplacian(V, F, iterations=5, preset="paper"), F


def save(name: str, image: np.ndarray) -> None:
    """Writes ``image`` (an (H, W, 4) uint8 array) as the PNG ``docs/<name>``, and says so."""
    out = ROOT / "docs" / name
    Image.fromarray(image).save(out, optimize=True)
    print("wrote", out)
