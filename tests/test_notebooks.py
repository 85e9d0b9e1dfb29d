"""The notebooks in notebooks/ run top to bottom in a real Jupyter kernel, so the examples cannot rot.

Each runs in a fresh kernel whose working directory is an empty temporary folder (so a notebook
that reads files next to itself, or from tests/, fails), with the environment variable CI set so
that it uses its small sizes. A cell that raises fails the test; so does a notebook that prints
to stderr (a warning) or leaves files behind in the working directory.
"""

from __future__ import annotations

import importlib.util
import json
import os
from pathlib import Path

import pytest

from conftest import need

NOTEBOOK_DIR = Path(__file__).resolve().parent.parent / "notebooks"
NOTEBOOKS = sorted(NOTEBOOK_DIR.glob("*.ipynb"))

# What each notebook must show besides text, and the optional libraries it needs.
SHOWS = {
    "quickstart.ipynb": "image/png",
    "papers.ipynb": "image/png",
    "accuracy_vs_time.ipynb": "image/png",
    "cross_validation.ipynb": None,
    "smoothing.ipynb": "image/png",
}
NEEDS = {
    "quickstart.ipynb": ["matplotlib", "PIL"],
    "papers.ipynb": ["matplotlib"],
    "accuracy_vs_time.ipynb": ["matplotlib"],
    "cross_validation.ipynb": ["trimesh", "pymeshlab", "skimage"],
    "smoothing.ipynb": ["matplotlib"],
}


# Notebooks that open a toonmesh.Viewer: with anywidget installed (always in CI) they show a
# live widget besides the still frame.
VIEWERS = {"quickstart.ipynb"}


def code_cells(path: Path) -> list:
    return [c for c in json.loads(path.read_text(encoding="utf-8"))["cells"] if c["cell_type"] == "code"]


def test_the_notebooks_a_newcomer_opens_first_are_there():
    assert set(SHOWS) <= {p.name for p in NOTEBOOKS}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_is_stored_without_outputs_and_reads_no_test_data(path):
    cells = code_cells(path)
    assert cells
    for cell in cells:
        assert cell["outputs"] == [] and cell["execution_count"] is None, "strip the outputs before committing"
    source = "\n".join("".join(c["source"]) for c in cells)
    for outside in ("tests/", "tests\\", "../", "..\\"):
        assert outside not in source, f"{path.name} reads {outside!r}: use toonmesh.data and toonmesh.shapes"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_runs_in_a_jupyter_kernel_from_any_folder(path, tmp_path, monkeypatch):
    for module in ["nbformat", "nbclient", "ipykernel", *NEEDS.get(path.name, [])]:
        need(module)
    import nbformat
    from nbclient import NotebookClient

    monkeypatch.chdir(tmp_path)
    notebook = nbformat.read(str(path), as_version=4)
    env = dict(os.environ, CI="true")  # the notebooks' small sizes
    env.pop("MPLBACKEND", None)  # the kernel's inline backend shows figures as images
    client = NotebookClient(notebook, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}})
    client.execute(env=env)  # raises CellExecutionError naming the cell that failed

    outputs = [o for c in notebook.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    stderr = "".join(o.get("text", "") for o in outputs if o.output_type == "stream" and o.name == "stderr")
    # matplotlib's own one-time notes on a fresh machine ("Matplotlib is building the font cache")
    warnings = [line for line in stderr.splitlines() if line.strip() and not line.startswith("Matplotlib ")]
    assert warnings == []
    shown = {mime for o in outputs for mime in o.get("data", {})}
    assert any(o.output_type == "stream" for o in outputs) or shown, "the notebook shows nothing"
    if SHOWS.get(path.name):
        assert SHOWS[path.name] in shown, f"{path.name} shows no {SHOWS[path.name]}"
    if path.name in VIEWERS and (importlib.util.find_spec("anywidget") or os.environ.get("CI", "").lower() == "true"):
        assert "application/vnd.jupyter.widget-view+json" in shown, f"{path.name} shows no viewer widget"
    assert sorted(p.name for p in tmp_path.iterdir()) == [], "the notebook left files in the working directory"
