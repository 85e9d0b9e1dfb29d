"""toonmesh's pytest plugin: snapshot tests of renders and line drawings.

Installed with toonmesh (the ``pytest11`` entry point ``toonmesh.pytest_plugin``), so that every
test can ask for the ``toon_snapshot`` fixture; where the entry point is not installed (an
editable build made before it) load it with ``pytest -p toonmesh.pytest_plugin`` or
``pytest_plugins = ["toonmesh.pytest_plugin"]`` in the top ``conftest.py`` (a no-op where it is
installed: the entry point has the module's name); ``-p no:toonmesh.pytest_plugin`` turns it off.

::

    def test_bunny(toon_snapshot):
        toon_snapshot(toonmesh.render(*toonmesh.data.bunny(), width=256, height=256))

The reference is ``__snapshots__/test_bunny.png`` beside the test file. Without it the test
fails (it writes ``test_bunny.actual.png`` to look at); ``pytest --toon-update`` writes it.
A later run compares the render with it (:class:`toonmesh.testing.Snapshot` has the rules and
the tolerances; docs/testing.md a complete example).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, List

import pytest

from toonmesh.testing import Snapshot

#: The paths of the references written in this run, for the summary at its end.
_WRITTEN = pytest.StashKey[List[Path]]()


def pytest_addoption(parser: Any) -> None:
    """Adds ``--toon-update``: write missing references and refresh those that differ."""
    group = parser.getgroup("toonmesh", "toonmesh snapshots")
    group.addoption(
        "--toon-update",
        action="store_true",
        default=False,
        help="toon_snapshot: write missing reference images and drawings, and refresh those that differ",
    )


def pytest_configure(config: Any) -> None:
    """Starts the list of references this run writes."""
    config.stash[_WRITTEN] = []


def _test_name(node: Any) -> str:
    name = node.name
    cls = getattr(node, "cls", None)
    return f"{cls.__name__}.{name}" if cls is not None else name


@pytest.fixture
def toon_snapshot(request: Any) -> Snapshot:
    """A :class:`toonmesh.testing.Snapshot` of this test: ``toon_snapshot(render)`` compares a
    render (or an image array, or a line drawing) with ``__snapshots__/<test name>.png`` (or
    ``.svg``) beside the test file; ``pytest --toon-update`` writes the references."""
    directory = Path(str(request.node.path)).parent / "__snapshots__"
    return Snapshot(
        directory,
        _test_name(request.node),
        update=bool(request.config.getoption("toon_update")),
        written=request.config.stash[_WRITTEN],
    )


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int, config: Any) -> None:
    """Lists the references ``--toon-update`` wrote."""
    written = config.stash.get(_WRITTEN, [])
    if not written:
        return
    terminalreporter.section("toon snapshots")
    terminalreporter.write_line(f"wrote {len(written)} reference{'s' if len(written) != 1 else ''}:")
    for path in written:
        terminalreporter.write_line(f"  {path}")
