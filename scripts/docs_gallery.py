"""MkDocs hook: the gallery, rendered while the site is built.

Each entry is a script in docs/gallery/ that writes its figures (PNG or SVG files) into the folder
it runs in. At build time every script listed under "Gallery" in mkdocs.yml's nav runs in a fresh
folder; its figures become files of the site (``gallery/<name>.png``) and a page
``gallery/<name>.md`` is written for it: the title and text from the script's docstring, the
figures, the code and a button to download the script. ``gallery/index.md`` shows every entry as
a picture. A script that fails or writes no figure stops the build.

A script runs as a pip user would run it after downloading it: alone in an empty folder, with
``python -I`` (neither PYTHONPATH nor the script's folder on the import path), an environment
naming no path of the repository, and the toonmesh package this build imports as its only
addition to the interpreter's site-packages. Before it runs, :func:`offences` reads it (AST) and
refuses imports of private modules (``toonmesh._*``, ``toonmesh.bench``) and paths that reach
outside the folder it runs in.
"""

from __future__ import annotations

import ast
import concurrent.futures
import importlib.util
import logging
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Dict, Iterator, List, Tuple

from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File, Files

log = logging.getLogger("mkdocs.hooks.gallery")

FIGURES = (".png", ".svg")
#: a script that takes longer than this stops the build
TIMEOUT_S = 600


def _entries(config) -> List[str]:
    """The scripts' names in the order the nav lists their pages under the gallery."""
    names: List[str] = []

    def walk(items):
        for item in items or []:
            value = list(item.values())[0] if isinstance(item, dict) else item
            if isinstance(value, list):
                walk(value)
            elif isinstance(value, str) and value.startswith("gallery/") and value != "gallery/index.md":
                names.append(value[len("gallery/"):-len(".md")])

    walk(config["nav"])
    return names


#: modules of the package that a pip user's scripts must not import: the benchmark's helpers
PRIVATE = ("toonmesh.bench",)


def _private(module: str) -> bool:
    """Whether ``module`` is toonmesh's own and not public: ``toonmesh._*`` at any depth, or
    one of :data:`PRIVATE` and what lies below it."""
    parts = module.split(".")
    if parts[0] != "toonmesh":
        return False
    return any(p.startswith("_") for p in parts[1:]) or any(module == m or module.startswith(m + ".")
                                                           for m in PRIVATE)


def _outside(text: str) -> bool:
    """Whether a string names a path outside the folder a script runs in: absolute, from the
    home folder, or through a parent (``..``)."""
    parts = text.replace("\\", "/").split("/")
    return text.startswith(("/", "~")) or ".." in parts


def offences(source: str) -> Iterator[str]:
    """What keeps a gallery script from running as downloaded, one line each ("line N: ...").

    Imports of ``toonmesh._*`` or ``toonmesh.bench``; ``__file__`` (where the script lies is
    not where it runs: data comes from ``toonmesh.data`` and ``toonmesh.shapes``); and string
    constants outside the docstring that name absolute paths, the home folder or a parent
    folder. Reading ``source`` only: nothing runs.
    """
    tree = ast.parse(source)
    docstring = tree.body[0].value if tree.body and isinstance(tree.body[0], ast.Expr) else None
    for node in ast.walk(tree):
        line = getattr(node, "lineno", 0)
        if isinstance(node, ast.Import):
            modules = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            modules = [node.module] + [f"{node.module}.{alias.name}" for alias in node.names]
        else:
            modules = []
        for module in modules:
            if _private(module):
                yield (f"line {line}: imports {module}, which is not public API (a pip user's scripts "
                       "use toonmesh's public modules only)")
                break
        if isinstance(node, ast.Name) and node.id == "__file__":
            yield (f"line {line}: uses __file__; a downloaded script runs elsewhere (data comes from "
                   "toonmesh.data and toonmesh.shapes, files are written into the current folder)")
        if (isinstance(node, ast.Constant) and isinstance(node.value, str) and node is not docstring
                and _outside(node.value)):
            yield f"line {line}: names the path {node.value!r}, outside the folder the script runs in"


def _package() -> Path:
    """The folder of the toonmesh package this build imports (the one under test)."""
    spec = importlib.util.find_spec("toonmesh")
    if spec is None or not spec.submodule_search_locations:
        raise PluginError("the gallery needs toonmesh importable (make build, or PYTHONPATH=python)")
    return Path(list(spec.submodule_search_locations)[0]).resolve()


def _environment(site: Path, repository: Path) -> Dict[str, str]:
    """The environment a script runs in: the build's, less Python's own variables and every path
    in the repository (the interpreter's environment, a virtual one inside the repository say,
    stays: it is the pip user's); child interpreters (pytest, say) find toonmesh in ``site``."""
    inside, interpreter = str(repository.resolve()), str(Path(sys.prefix).resolve())

    def keep(path: str) -> bool:
        return not path.startswith(inside) or path.startswith(interpreter)

    env = {}
    for key, value in os.environ.items():
        if key.startswith("PYTHON"):
            continue
        kept = os.pathsep.join(p for p in value.split(os.pathsep) if keep(p))
        if kept or not value:
            env[key] = kept
    env.update(MPLBACKEND="Agg", PYTHONPATH=str(site), PYTHONNOUSERSITE="1")
    return env


# ``python -I`` ignores PYTHONPATH: toonmesh is put first on the path as an installed package
# would be, and the script runs as ``__main__`` from its downloaded copy
_START = ("import runpy, sys; sys.path.insert(0, sys.argv[1]); sys.argv = sys.argv[2:]; "
          "runpy.run_path(sys.argv[0], run_name='__main__')")


def _run(script: Path, repository: Path) -> Tuple[str, float, Dict[str, bytes], str]:
    """Runs one script as a pip user would (see the module's docstring); returns its name, its
    time in seconds, its figures by file name and what it printed."""
    found = list(offences(script.read_text()))
    if found:
        raise PluginError(f"gallery/{script.name} would not run as downloaded: " + "; ".join(found))
    with tempfile.TemporaryDirectory(prefix=f"gallery-{script.stem}-") as tmp:
        site, download, work = (Path(tmp) / d for d in ("site", "download", "work"))
        for folder in (site, download, work):
            folder.mkdir()
        (site / "toonmesh").symlink_to(_package(), target_is_directory=True)
        copy = download / script.name
        shutil.copyfile(script, copy)
        start = time.perf_counter()
        proc = subprocess.run([sys.executable, "-I", "-c", _START, str(site), str(copy)], cwd=work,
                              env=_environment(site, repository), capture_output=True, text=True,
                              timeout=TIMEOUT_S, stdin=subprocess.DEVNULL)
        took = time.perf_counter() - start
        if proc.returncode != 0:
            raise PluginError(f"gallery/{script.name} failed in an empty folder (exit {proc.returncode}):\n"
                              f"{proc.stdout}{proc.stderr}")
        figures = {p.name: p.read_bytes() for p in sorted(work.iterdir()) if p.suffix in FIGURES}
        if not figures:
            raise PluginError(f"gallery/{script.name} wrote no figure (a .png or .svg file in the folder it runs in)")
        return script.stem, took, figures, proc.stdout


def _split(source: str) -> Tuple[str, str, str]:
    """The script's title (docstring's first line), its text (the rest) and the code after it."""
    tree = ast.parse(source)
    doc = ast.get_docstring(tree)
    if not doc:
        raise PluginError("a gallery script needs a docstring: its title, then what it shows")
    title, _, text = doc.partition("\n")
    code = "\n".join(source.splitlines()[tree.body[0].end_lineno:]).strip("\n")
    return title.strip().rstrip("."), text.strip(), code


def _page(name: str, source: str, figures: Dict[str, bytes], output: str) -> str:
    title, text, code = _split(source)
    parts = [f"# {title}", "", text, ""]
    for fig in figures:
        parts += [f"![{title}]({fig})", ""]
    parts += [f'[Download {name}.py]({name}.py){{ .md-button download="{name}.py" }}', ""]
    parts += [f"`python {name}.py` writes " + ", ".join(f"`{f}`" for f in figures)
              + " into the folder it runs in:", ""]
    parts += ["```python", code, "```", ""]
    if output.strip():
        parts += ["It prints:", "", "```text", output.rstrip(), "```", ""]
    return "\n".join(parts)


def on_files(files: Files, config) -> Files:
    docs = Path(config["docs_dir"])
    names = _entries(config)
    listed = {p.stem for p in (docs / "gallery").glob("*.py")}
    if set(names) != listed:
        raise PluginError(f"gallery scripts and the nav's gallery pages differ: scripts {sorted(listed)}, "
                          f"nav {sorted(names)}")
    jobs = int(os.environ.get("TOONMESH_GALLERY_JOBS", "2"))
    start = time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(lambda n: _run(docs / "gallery" / f"{n}.py", docs.resolve().parent), names))
    cards = ["# Gallery", "",
             "Each picture is drawn by a short script when this site is built; click one for its code.",
             "", '<div class="tm-gallery" markdown>', ""]
    for name, took, figures, output in results:
        source = (docs / "gallery" / f"{name}.py").read_text()
        for fig, data in figures.items():
            files.append(File.generated(config, f"gallery/{fig}", content=data))
        files.append(File.generated(config, f"gallery/{name}.md", content=_page(name, source, figures, output)))
        title = _split(source)[0]
        cards.append(f"[![{title}]({next(iter(figures))})<span>{title}</span>]({name}.md)")
        log.info("gallery: %s.py ran in %.1f s (%s)", name, took, ", ".join(figures))
    cards += ["", "</div>", ""]
    files.append(File.generated(config, "gallery/index.md", content="\n".join(cards)))
    log.info("gallery: %d scripts in %.1f s", len(results), time.perf_counter() - start)
    return files
