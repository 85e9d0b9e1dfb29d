"""The documentation site (``make docs``): it builds with warnings as errors, its gallery's scripts
run and leave their figures in the built site, every link between its pages resolves, the API
reference documents every public name, and a browser shows its pages without a broken image."""

from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path
from typing import Dict, List, Set, Tuple
from urllib.parse import unquote, urlsplit

import pytest

from conftest import chromium, need

ROOT = Path(__file__).resolve().parent.parent
GUIDES = ("smoothing", "lines", "rendering", "effects", "colour", "files", "viewer", "cli", "batch", "testing",
          "notebooks")


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """The site, built once for this module with ``mkdocs build --strict`` into a fresh folder."""
    need("mkdocs")
    need("mkdocstrings")
    out = tmp_path_factory.mktemp("site")
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    proc = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-f", str(ROOT / "mkdocs.yml"),
                           "-d", str(out)], cwd=ROOT, env=env, capture_output=True, text=True, timeout=1200,
                          stdin=subprocess.DEVNULL)
    log = proc.stdout + proc.stderr
    assert proc.returncode == 0, log
    warnings = [line for line in log.splitlines() if line.startswith(("WARNING", "ERROR"))]
    assert warnings == [], log
    (out / "build.log").write_text(log)
    return out


def test_the_site_has_the_guides_the_measurements_and_the_api_reference(site):
    for page in ("index", "install", *GUIDES, "accuracy", "benchmarks", "hard-cases", "api", "internals",
                 "development"):
        assert (site / f"{page}.html").is_file(), page
    text = (site / "smoothing.html").read_text()
    assert "Feature-preserving smoothing" in text and "volume_constraint" in text
    # the README's sections shown on the site come from the README itself
    assert "rustup" in (site / "install.html").read_text()
    assert "bunny()" in re.sub("<[^>]+>", "", (site / "index.html").read_text())


def test_every_gallery_script_ran_and_left_its_figures_in_the_built_site(site):
    scripts = sorted(p.stem for p in (ROOT / "docs" / "gallery").glob("*.py"))
    assert len(scripts) >= 10
    figures = sorted(p.name for p in (site / "gallery").iterdir() if p.suffix in (".png", ".svg"))
    assert len(figures) >= len(scripts) >= 10, figures
    index = (site / "gallery" / "index.html").read_text()
    for name in scripts:
        page = (site / "gallery" / f"{name}.html").read_text()
        assert f'href="{name}.html"' in index, name
        shown = re.findall(r'<img[^>]*src="([^"]+\.(?:png|svg))"', page)
        assert shown and all((site / "gallery" / src).stat().st_size > 1000 for src in shown), (name, shown)
        assert "<code" in page and re.search(r"(from|import) toonmesh", re.sub("<[^>]+>", "", page)), name
    log = (site / "build.log").read_text()
    assert len(re.findall(r"gallery: \w+\.py ran in", log)) == len(scripts), log


class _Links(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.links: List[str] = []
        self.ids: Set[str] = set()

    def handle_starttag(self, tag: str, attrs: List[Tuple[str, "str | None"]]) -> None:
        a = dict(attrs)
        if a.get("id"):
            self.ids.add(a["id"] or "")
        for key in ("href", "src"):
            if a.get(key):
                self.links.append(a[key] or "")


def _parse(path: Path) -> _Links:
    parser = _Links()
    parser.feed(path.read_text(encoding="utf-8"))
    return parser


def test_every_internal_link_of_the_built_site_resolves(site):
    pages: Dict[Path, _Links] = {p: _parse(p) for p in site.rglob("*.html") if p.name != "404.html"}
    broken = []
    checked = 0
    for page, parsed in pages.items():
        for link in parsed.links:
            parts = urlsplit(link)
            if parts.scheme or link.startswith("//") or link.startswith("mailto:"):
                continue
            target = (page.parent / unquote(parts.path)).resolve() if parts.path else page
            if parts.path.endswith("/"):
                target = target / "index.html"
            checked += 1
            if not target.exists():
                broken.append(f"{page.relative_to(site)}: {link}")
            elif parts.fragment and target.suffix == ".html":
                ids = pages[target].ids if target in pages else _parse(target).ids
                if parts.fragment not in ids:
                    broken.append(f"{page.relative_to(site)}: {link} (no such anchor)")
    assert checked > 500
    assert broken == [], broken


def test_the_api_reference_documents_every_public_function_class_and_method(site):
    need("griffe")
    spec = importlib.util.spec_from_file_location("docs_api", ROOT / "scripts" / "docs_api.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert module.undocumented(ROOT / "python") == []
    api = (site / "api.html").read_text()
    for name in ("render", "Renderer", "Material", "Camera", "Light", "RenderResult", "Viewer", "smooth.laplacian",
                 "edges.feature_edges", "testing.assert_images_close", "batch.render_files"):
        assert f'id="toonmesh.{name}"' in api, name
    assert "band_antialias" in api  # the render keywords (RenderKeywords), from the core's docstring


def test_the_home_page_and_a_gallery_page_show_every_picture_in_a_browser(site, tmp_path):
    sync_api = need("playwright.sync_api")
    executable = chromium()
    shots = []
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            for name in ("index.html", "gallery/index.html", "gallery/papers.html"):
                page.goto((site / name).as_uri())
                page.wait_for_load_state("load")
                images = page.evaluate("Array.from(document.images).map(i => [i.src, i.complete, i.naturalWidth])")
                assert len(images) >= 1, name
                broken = [src for src, complete, width in images if not complete or width == 0]
                assert broken == [], (name, broken)
                shot = tmp_path / (name.replace("/", "-").replace(".html", ".png"))
                page.screenshot(path=str(shot), full_page=True)
                shots.append(shot)
        finally:
            browser.close()
    assert all(s.stat().st_size > 10_000 for s in shots)
    print("screenshots:", *shots)


def _gallery_hook():
    """scripts/docs_gallery.py, the hook that runs the gallery, as a module."""
    need("mkdocs")
    spec = importlib.util.spec_from_file_location("docs_gallery", ROOT / "scripts" / "docs_gallery.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_gallery_scripts_import_public_modules_only_and_reach_no_file_outside_their_folder():
    hook = _gallery_hook()
    for script in sorted((ROOT / "docs" / "gallery").glob("*.py")):
        assert list(hook.offences(script.read_text())) == [], script.name
    bad = ('"""A script."""\nimport toonmesh._core\nfrom toonmesh.bench.lines import slab\n'
           'from toonmesh import _files\nfrom toonmesh.files._load import read_mesh\n'
           'ROOT = __file__\nopen("../../tests/data/meshes/cow.obj")\nopen("/etc/hostname")\n'
           'from toonmesh.data import bunny\nimport toonmesh.shapes\n')
    found = list(hook.offences(bad))
    assert [f.split(":")[0] for f in found] == [f"line {n}" for n in range(2, 9)], found
    assert "toonmesh._core" in found[0] and "toonmesh.bench.lines" in found[1] and "toonmesh._files" in found[2]
    assert "__file__" in found[4] and "'../../tests/data/meshes/cow.obj'" in found[5] and "'/etc/hostname'" in found[6]
    # a path in the docstring is text (a link to another page), not a file the script reads
    assert list(hook.offences('"""See [the accuracy page](../accuracy.md)."""\nimport toonmesh\n')) == []


def test_a_gallery_script_runs_alone_in_an_empty_folder_as_a_pip_user_runs_it(tmp_path):
    """The hook names the script and the offence, refuses before running what it can read, and
    runs the rest in an empty folder with ``python -I``: neither the repository's files, nor a
    module beside the script, nor PYTHONPATH reach it; toonmesh is the one this build imports."""
    from mkdocs.exceptions import PluginError

    hook = _gallery_hook()
    folder = tmp_path / "gallery"
    folder.mkdir()
    private = folder / "private.py"
    private.write_text('"""Private."""\nfrom toonmesh.bench import parts\n')
    with pytest.raises(PluginError, match=r"gallery/private\.py would not run as downloaded: line 2: imports "
                                          r"toonmesh\.bench"):
        hook._run(private, ROOT)
    relative = folder / "relative.py"  # no path a reader can see: the empty folder stops it
    relative.write_text('"""Relative."""\nopen("tests/data/meshes/cow.obj").read()\n')
    with pytest.raises(PluginError, match=r"(?s)gallery/relative\.py failed in an empty folder.*FileNotFoundError"):
        hook._run(relative, ROOT)
    (folder / "helper.py").write_text("X = 1\n")
    beside = folder / "beside.py"
    beside.write_text('"""Beside."""\nimport helper\n')
    with pytest.raises(PluginError, match=r"(?s)gallery/beside\.py failed.*No module named 'helper'"):
        hook._run(beside, ROOT)
    report = folder / "report.py"
    report.write_text('"""Report."""\nimport json, os, sys\nimport numpy as np\nimport toonmesh\n'
                      'print(json.dumps({"here": os.listdir("."), "flags": sys.flags.isolated, '
                      '"toonmesh": os.path.realpath(toonmesh.__file__), "environ": dict(os.environ)}))\n'
                      'open("figure.svg", "w").write("<svg xmlns=\'http://www.w3.org/2000/svg\'/>")\n')
    name, took, figures, output = hook._run(report, ROOT)
    seen = __import__("json").loads(output)
    assert name == "report" and list(figures) == ["figure.svg"] and took > 0
    assert seen["here"] == [] and seen["flags"] == 1
    assert seen["toonmesh"] == str((hook._package() / "__init__.py").resolve())
    inside = [k for k, v in seen["environ"].items() if str(ROOT) in v and str(Path(sys.prefix).resolve()) not in v]
    assert inside == [], inside


def test_each_gallery_page_offers_its_script_to_download(site):
    for script in sorted((ROOT / "docs" / "gallery").glob("*.py")):
        page = (site / "gallery" / f"{script.stem}.html").read_text()
        assert re.search(rf'<a [^>]*download="{script.stem}\.py"[^>]*>|<a [^>]*href="{script.stem}\.py"[^>]*download',
                         page), script.name
        assert (site / "gallery" / script.name).read_bytes() == script.read_bytes(), script.name
