"""The wheel (``make wheel``, which ``make test`` runs): an abi3 wheel, tagged manylinux, that
installs into a fresh virtual environment with no Rust toolchain on the PATH and runs the README's
ten-line example there."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path
from typing import Dict, Tuple

import pytest

import toonmesh

ROOT = Path(__file__).resolve().parent.parent
WHEELS = ROOT / "target" / "wheels"


def _wheel() -> Path:
    """The wheel of this build: there, and holding the extension this test suite imports."""
    wheels = sorted(WHEELS.glob("toonmesh-*.whl"))
    core = Path(toonmesh._core.__file__).read_bytes()
    problem = None
    if len(wheels) != 1:
        problem = f"{len(wheels)} wheels in {WHEELS} (make wheel builds one)"
    else:
        with zipfile.ZipFile(wheels[0]) as z:
            if z.read(f"toonmesh/{Path(toonmesh._core.__file__).name}") != core:
                problem = f"{wheels[0].name} holds another build of the extension than this one (make wheel)"
    if problem:
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail(problem)
        pytest.skip(problem)
    return wheels[0]


def test_the_wheel_is_abi3_and_manylinux():
    name = _wheel().name
    assert re.fullmatch(r"toonmesh-[\w.]+-cp39-abi3-manylinux_2_\d+_x86_64\.whl", name), name


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Tuple[Path, Dict[str, str]]:
    """A fresh virtual environment with the wheel (and its dependencies) alone installed, and the
    environment to run it in: its own PATH with the system's tools and no Rust toolchain."""
    wheel = _wheel()
    where = tmp_path_factory.mktemp("installed")
    venv = where / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    # a PATH with the fresh environment and the system's tools, and no cargo or rustc
    path = os.pathsep.join([str(venv / "bin"), "/usr/local/bin", "/usr/bin", "/bin"])
    env = {k: v for k, v in os.environ.items() if not k.startswith(("CARGO", "RUSTUP", "PYTHON", "VIRTUAL_ENV"))}
    env.update(PATH=path, PIP_QUIET="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", str(wheel)], env=env, check=True,
                   cwd=where, timeout=600)
    return venv, env


def test_the_wheel_installs_and_renders_without_rust(tmp_path, installed):
    venv, env = installed
    for tool in ("cargo", "rustc", "maturin"):
        assert subprocess.run(["sh", "-c", f"command -v {tool}"], env=env).returncode != 0, tool
    readme = (ROOT / "README.md").read_text()
    example = re.search(r"\[start:example\] -->\n```python\n(.*?)```", readme, flags=re.S).group(1)
    (tmp_path / "example.py").write_text("import toonmesh\nprint(toonmesh.__file__)\n" + example)
    run = subprocess.run([str(venv / "bin" / "python"), "example.py"], env=env, cwd=tmp_path, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    where = run.stdout.splitlines()[0]
    assert where.startswith(str(venv)), where  # the wheel's toonmesh, not the repository's
    assert "shade" in run.stdout, run.stdout  # print(r.passes)
    assert (tmp_path / "bunny.png").stat().st_size > 10_000


def test_the_wheel_holds_the_viewers_browser_files():
    """The viewer's .js, .css and .html files travel in the wheel beside its modules (the widget
    and the standalone page read them at run time)."""
    from toonmesh.viewer import _assets

    folder = Path(_assets.__file__).parent
    files = {p.name for p in folder.iterdir() if p.suffix in (".js", ".css", ".html")}
    assert set(_assets.WIDGET) | set(_assets.PAGE) <= files, files  # every file the lists name exists
    with zipfile.ZipFile(_wheel()) as z:
        shipped = {Path(n).name for n in z.namelist() if n.startswith("toonmesh/viewer/")}
    assert files <= shipped, sorted(files - shipped)


@pytest.mark.parametrize("script", ["still_life.py", "plotter.py"])
def test_a_gallery_script_runs_as_downloaded_where_only_the_wheel_is_installed(tmp_path, installed, script):
    """The gallery's illustrations need numpy and the wheel alone: each runs from a copy in an
    empty folder (``python -I``: not even the folder of the copy on the import path) and writes
    its figure there. The build runs every gallery script the same way (scripts/docs_gallery.py)."""
    venv, env = installed
    (tmp_path / "download").mkdir()
    copy = tmp_path / "download" / script
    copy.write_bytes((ROOT / "docs" / "gallery" / script).read_bytes())
    work = tmp_path / "work"
    work.mkdir()
    run = subprocess.run([str(venv / "bin" / "python"), "-I", str(copy)], env=env, cwd=work, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    figures = [p for p in work.iterdir() if p.suffix in (".png", ".svg")]
    assert figures and all(p.stat().st_size > 10_000 for p in figures), figures
