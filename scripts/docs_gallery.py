"""MkDocs hook: the gallery, rendered while the site is built.

Each entry is a script in docs/gallery/ that writes its figures (PNG or SVG files) into the folder
it runs in. At build time every script listed under "Gallery" in mkdocs.yml's nav runs in a fresh
folder; its figures become files of the site (``gallery/<name>.png``) and a page
``gallery/<name>.md`` is written for it: the title and text from the script's docstring, the
figures, and the code. ``gallery/index.md`` shows every entry as a picture. A script that fails
or writes no figure stops the build.
"""

from __future__ import annotations

import ast
import concurrent.futures
import logging
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Dict, List, Tuple

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


def _run(script: Path) -> Tuple[str, float, Dict[str, bytes], str]:
    """Runs one script in a fresh folder; returns its figures by file name."""
    with tempfile.TemporaryDirectory(prefix=f"gallery-{script.stem}-") as tmp:
        env = dict(os.environ, MPLBACKEND="Agg")
        start = time.perf_counter()
        proc = subprocess.run([sys.executable, str(script)], cwd=tmp, env=env, capture_output=True,
                              text=True, timeout=TIMEOUT_S, stdin=subprocess.DEVNULL)
        took = time.perf_counter() - start
        if proc.returncode != 0:
            raise PluginError(f"gallery/{script.name} failed (exit {proc.returncode}):\n{proc.stdout}{proc.stderr}")
        figures = {p.name: p.read_bytes() for p in sorted(Path(tmp).iterdir()) if p.suffix in FIGURES}
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
    parts += [f"`python docs/gallery/{name}.py` writes " + ", ".join(f"`{f}`" for f in figures)
              + f" into the current folder ([{name}.py]({name}.py)):", ""]
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
        results = list(pool.map(lambda n: _run(docs / "gallery" / f"{n}.py"), names))
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
