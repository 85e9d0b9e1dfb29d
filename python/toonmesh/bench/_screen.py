"""What a view shows on screen, read from screenshots (Playwright's ``locator.screenshot()``), for
the viewer's browser benchmark and tests: its covered and ink pixels against the exact frame of
the same view, and a screenshot taken while a drag goes on."""

from __future__ import annotations

import io
from importlib import resources
from typing import Any, Tuple

import numpy as np


def script(name: str) -> str:
    """One of the benchmark's browser scripts beside this module (``viewer_browser_*.js``)."""
    return resources.files(__package__).joinpath(name).read_text(encoding="utf-8")


def pixels(png: bytes) -> np.ndarray:
    """A screenshot (PNG bytes) as (H, W, 3) int16."""
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(np.int16)


def background(exact: np.ndarray) -> np.ndarray:
    """The empty view's colour: the commonest along ``exact``'s edges (a screenshot may take in
    a border's row)."""
    edges = np.concatenate([exact[0], exact[-1], exact[:, 0], exact[:, -1]])[:, :3].astype(np.int16)
    colours, counts = np.unique(edges, axis=0, return_counts=True)
    return colours[counts.argmax()]


def covered(picture: np.ndarray, bg: np.ndarray) -> int:
    """The pixels of ``picture`` that differ from ``bg`` (an RGB colour) by more than 24 levels in
    a channel: the model, not the empty view."""
    return int((np.abs(picture[..., :3].astype(np.int16) - bg[:3].astype(np.int16)).max(-1) > 24).sum())


def ink(picture: np.ndarray) -> int:
    """The dark pixels of ``picture`` (every channel below 100): the ink (the default bands stay
    lighter)."""
    return int((picture[..., :3].max(-1) < 100).sum())


def shares(shot: np.ndarray, exact: np.ndarray) -> Tuple[float, float]:
    """What a screenshot of a view shows against the exact frame of the same view: its covered
    pixels and its ink pixels, each as a share of the exact frame's."""
    bg = background(exact)
    return covered(shot, bg) / max(covered(exact, bg), 1), ink(shot) / max(ink(exact), 1)


def centre(locator: Any) -> Tuple[float, float]:
    """The middle of ``locator``'s box on the page, in CSS pixels."""
    box = locator.bounding_box()
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def press_and_move(page: Any, x: float, y: float, steps: int, dx: float, dy: float = 0.0, pause_ms: int = 30) -> None:
    """The start of a drag as a hand makes it: the mouse pressed at (x, y), then moved ``steps``
    times by (dx, dy), ``pause_ms`` after each move, so that the page sees every move. The
    button stays down: ``page.mouse.up()`` ends the drag (a screenshot may come first)."""
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, steps + 1):
        page.mouse.move(x + dx * i, y + dy * i)
        page.wait_for_timeout(pause_ms)


def screenshot_mid_drag(page: Any, locator: Any, target: str, x: float, y: float, index: int = 0) -> bytes:
    """A screenshot of ``locator`` while a drag goes on: with the mouse held down at (x, y) on
    the element that ``target`` (a CSS selector; its ``index``-th match) selects, the page moves
    the pointer a pixel right and back every 40 ms until the screenshot is taken
    (``viewer_browser_hold.js``), so that the view never settles however long the screenshot
    takes, and ends where it was."""
    page.evaluate(script("viewer_browser_hold.js"), [target, index, x, y])
    try:
        return locator.screenshot()
    finally:
        page.evaluate("window.__hold.stop()")
