"""toonmesh.figures.panels: labelled panels in rows, the inputs untouched, bad input named."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import need
from toonmesh.figures import LABEL_SIZE, panels


def _cells(n, colours=((240, 138, 60), (60, 138, 240), (120, 200, 120))):
    return [np.full((40, 120, 4), (*colours[k % len(colours)], 255), np.uint8) for k in range(n)]


def test_panels_lay_the_images_out_in_rows_with_a_white_filled_last_row():
    need("PIL")
    cells = _cells(5)
    before = [c.copy() for c in cells]
    figure = panels(cells, [""] * 5, columns=3)
    assert figure.shape == (80, 360, 3) and figure.dtype == np.uint8
    for k, cell in enumerate(cells):
        r, c = divmod(k, 3)
        np.testing.assert_array_equal(figure[40 * r:40 * (r + 1), 120 * c:120 * (c + 1)], cell[..., :3])
    assert (figure[40:, 240:] == 255).all()  # the sixth place: white
    assert all((a == b).all() for a, b in zip(cells, before))
    assert panels(cells[:2], ["", ""]).shape == (40, 240, 3)  # one row by default


def test_a_label_is_dark_text_on_a_white_box_at_the_panels_top_left():
    need("PIL")
    plain, labelled = (panels(_cells(1), [t]) for t in ("", "Rim(side='lit')"))
    corner = labelled[: LABEL_SIZE + 8, :100]
    assert (corner == 255).all(axis=2).sum() > 100  # the box
    assert (corner.max(axis=2) < 80).sum() > 20  # the ink of the text
    np.testing.assert_array_equal(labelled[30:], plain[30:])  # below the label, the panel as it was


@pytest.mark.parametrize("images, labels, columns, error, words", [
    ([], [], None, ValueError, "images: expected at least one"),
    ([np.zeros((4, 4, 3), np.float32)], [""], None, TypeError, "images[0]: expected dtype uint8"),
    ([[0, 1]], [""], None, TypeError, "images[0]: expected a NumPy array"),
    ([np.zeros((4, 4), np.uint8)], [""], None, ValueError, "images[0]: expected an (H, W, 3)"),
    ([np.zeros((4, 4, 3), np.uint8), np.zeros((4, 5, 3), np.uint8)], ["", ""], None, ValueError, "images[1]"),
    ([np.zeros((4, 4, 3), np.uint8)], ["a", "b"], None, ValueError, "labels: expected one str per image"),
    ([np.zeros((4, 4, 3), np.uint8)], "a", None, ValueError, "labels: expected one str per image"),
    ([np.zeros((4, 4, 3), np.uint8)], [3], None, TypeError, "labels[0]: expected a str"),
    ([np.zeros((4, 4, 3), np.uint8)], [""], 0, ValueError, "columns: expected 1 or more"),
    ([np.zeros((4, 4, 3), np.uint8)], [""], 1.5, TypeError, "columns: expected an int"),
])
def test_bad_input_is_named(images, labels, columns, error, words):
    need("PIL")
    with pytest.raises(error) as caught:
        panels(images, labels, columns)
    assert words in str(caught.value)
