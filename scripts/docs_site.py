"""MkDocs hook: the site's version, and the notebooks as pages.

- The version in every page's footer (docs/overrides/partials/copyright.html) is
  ``toonmesh.__version__``, read while the site is built, so it is never typed again.
- Each notebook of notebooks/ becomes a page ``notebooks/<name>.html`` with the notebook as
  stored (without outputs) beside it to download. The notebooks run here, as the test suite runs
  them (a fresh kernel in an empty folder), so that their figures are made at build time; a cell
  that fails stops the build. mkdocs-jupyter then renders the executed copies. A live widget
  cannot work on a page read offline, so no widget state is kept: a widget's output shows its
  still picture (the viewer keeps its frame as a PNG for this). The notebooks in NOT_RUN are
  shown without outputs, and their page says why.
"""

from __future__ import annotations

import concurrent.futures
import logging
import os
import shutil
import tempfile
import time
from pathlib import Path
from typing import Dict, Optional

import nbformat
from mkdocs.exceptions import PluginError
from mkdocs.plugins import event_priority
from mkdocs.structure.files import File, Files
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

import toonmesh

log = logging.getLogger("mkdocs.hooks.site")

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = ROOT / "notebooks"
#: notebooks shown without running them, and why (said on their page)
NOT_RUN = {
    "accuracy_vs_time.ipynb": "it runs the benchmarks, which takes over a minute even at its small "
                              "sizes (the gallery's accuracy example draws the same curves)",
}
#: a notebook that takes longer than this stops the build
TIMEOUT_S = 600

_executed: Optional[tempfile.TemporaryDirectory] = None


def on_config(config):
    config.extra["toonmesh_version"] = toonmesh.__version__
    return config


def _execute(path: Path, out: Path) -> float:
    """Runs one notebook in a fresh kernel whose working folder is empty; writes it, with its
    outputs, to ``out``; returns the seconds it took."""
    notebook = nbformat.read(str(path), as_version=4)
    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix=f"notebook-{path.stem}-") as cwd:
        client = NotebookClient(notebook, timeout=TIMEOUT_S, kernel_name="python3", store_widget_state=False,
                                resources={"metadata": {"path": cwd}})
        env = dict(os.environ)
        env.pop("MPLBACKEND", None)  # the kernel's inline backend shows figures as images
        try:
            client.execute(env=env)
        except CellExecutionError as error:
            raise PluginError(f"notebooks/{path.name} failed:\n{error}") from None
    nbformat.write(notebook, str(out))
    return time.perf_counter() - start


@event_priority(100)  # before mkdocs-jupyter's on_files, which turns .ipynb files into pages
def on_files(files: Files, config) -> Files:
    global _executed
    _executed = tempfile.TemporaryDirectory(prefix="notebooks-")
    folder = Path(_executed.name) / "notebooks"
    folder.mkdir()
    paths = sorted(NOTEBOOKS.glob("*.ipynb"))
    start = time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        took: Dict[str, "concurrent.futures.Future[float]"] = {
            p.name: pool.submit(_execute, p, folder / p.name) for p in paths if p.name not in NOT_RUN}
    for path in paths:
        if path.name in NOT_RUN:
            shutil.copyfile(path, folder / path.name)
        else:
            log.info("notebooks: %s ran in %.1f s", path.name, took[path.name].result())
        files.append(File(f"notebooks/{path.name}", src_dir=_executed.name, dest_dir=config["site_dir"],
                          use_directory_urls=config["use_directory_urls"]))
    log.info("notebooks: %d run in %.1f s", len(took), time.perf_counter() - start)
    return files


def on_page_context(context, page, config, nav):
    if getattr(page, "nb_url", None):
        name = Path(page.file.abs_src_path).name
        # mkdocs-jupyter links the download from the site's root ("/notebooks/x.ipynb"), which a
        # site read from disk cannot follow; the notebook is copied beside its page
        page.nb_url = name
        page.nb_not_run = NOT_RUN.get(name)
    return context


def on_post_build(config):
    # the notebooks to download are the stored ones, without outputs
    for path in NOTEBOOKS.glob("*.ipynb"):
        shutil.copyfile(path, Path(config["site_dir"]) / "notebooks" / path.name)
    if _executed is not None:
        _executed.cleanup()
