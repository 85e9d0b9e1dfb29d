"""A JupyterLab server for browser runs of the viewer (its browser test and benchmark): token-less,
on a free port, with a notebook of given cells, and the user's own Jupyter settings, kernels and
workspaces left out (the kernel is this Python)."""

from __future__ import annotations

import contextlib
import json
import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path
from typing import Iterator, Sequence


def write_notebook(path: Path, cells: Sequence[str]) -> None:
    """A notebook of code ``cells`` (not run) at ``path``."""
    code = [{"cell_type": "code", "metadata": {}, "source": s, "outputs": [], "execution_count": None} for s in cells]
    nb = {
        "cells": code,
        "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}},
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    path.write_text(json.dumps(nb), encoding="utf-8")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@contextlib.contextmanager
def jupyter_lab(home: Path) -> Iterator[str]:
    """A JupyterLab server serving ``home / "work"`` (its settings under ``home``); yields its URL."""
    work = home / "work"
    work.mkdir(exist_ok=True)
    port = _free_port()
    env = dict(os.environ, JUPYTER_CONFIG_DIR=str(home / "config"), JUPYTER_DATA_DIR=str(home / "data"),
               JUPYTER_RUNTIME_DIR=str(home / "runtime"), JUPYTERLAB_WORKSPACES_DIR=str(home / "workspaces"),
               JUPYTER_PLATFORM_DIRS="1")
    log = open(home / "server.log", "wb")
    server = subprocess.Popen(
        [sys.executable, "-m", "jupyterlab", "--no-browser", "--ip=127.0.0.1", f"--port={port}",
         "--ServerApp.token=", "--ServerApp.password=", "--ServerApp.disable_check_xsrf=True",
         f"--ServerApp.root_dir={work}", "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
         "--allow-root"],
        cwd=work, env=env, stdout=log, stderr=subprocess.STDOUT,
    )
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 30
        while True:
            try:
                urllib.request.urlopen(f"{url}/api/status", timeout=1).read()
                break
            except OSError:
                if server.poll() is not None or time.monotonic() > deadline:
                    log.close()
                    raise RuntimeError("jupyter lab did not start:\n" + (home / "server.log").read_text(errors="replace"))
                time.sleep(0.25)
        yield url
    finally:
        server.terminate()
        try:
            server.wait(timeout=10)
        except subprocess.TimeoutExpired:
            server.kill()
        log.close()


def open_notebook(page, url: str, name: str):  # type: ignore[no-untyped-def]
    """Opens notebook ``name`` in JupyterLab at ``url`` on a Playwright ``page`` once its kernel is
    idle; returns the locator of its cells."""
    page.goto(f"{url}/lab/tree/{name}")
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=30_000)
    page.get_by_text("| Idle").wait_for(timeout=30_000)  # the status bar: "Python 3 (ipykernel) | Idle"
    return page.locator(".jp-Notebook .jp-Cell")
