"""Files others wrote.

The corpus of the tests (``tests/data/corpus``): mesh files from trimesh's own test suite, many
of them deliberately odd (comments, negative indices, no indices, nested nodes, a concave
polygon, a binary PLY, mixed-case suffixes), each drawn with the defaults, side by side and
named (point clouds and line files among them); the files refused (empty ones, a face of 2
corners) are listed below the pictures with their one-line reasons, as ``tm.load`` (or the
render) gives them. Needs trimesh (and, for 3MF,
networkx and lxml: ``pip install 'toonmesh[io]'``).
"""

import warnings
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

import toonmesh as tm

ROOT = Path(__file__).resolve().parents[2]  # the repository: its test files
TILE, COLUMNS = 150, 6
BESIDE = (".bin", ".mtl", ".md", ".png", ".jpg")


def main() -> None:
    files = sorted(p for p in (ROOT / "tests/data/corpus").rglob("*") if p.is_file() and not p.name.endswith(BESIDE))
    tiles, refused = [], []
    for path in files:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # each file's warnings are the tests' business
            try:
                tm.load(str(path))
                image = Image.fromarray(tm.render(str(path), width=TILE, height=TILE, supersample=2).color)
            except (ValueError, ImportError) as exc:
                refused.append(str(exc).replace(str(path.parent) + "/", ""))
                continue
            image = image.convert("RGB")
        ImageDraw.Draw(image).text((4, TILE - 14), path.name[:24], fill=(0, 0, 0))
        tiles.append(np.asarray(image))
    rows = -(-len(tiles) // COLUMNS)
    blank = np.full((TILE, TILE, 3), 255, np.uint8)
    tiles += [blank] * (rows * COLUMNS - len(tiles))
    grid = np.concatenate([np.concatenate(tiles[r * COLUMNS:(r + 1) * COLUMNS], axis=1) for r in range(rows)])
    notes = Image.new("RGB", (grid.shape[1], 16 * len(refused) + 8), "white")
    draw = ImageDraw.Draw(notes)
    for k, line in enumerate(refused):
        draw.text((6, 4 + 16 * k), "refused: " + line[:120], fill=(90, 30, 30))
    figure = np.concatenate([grid, np.asarray(notes)], axis=0)
    Image.fromarray(figure).save("corpus.png", optimize=True)


if __name__ == "__main__":
    main()
