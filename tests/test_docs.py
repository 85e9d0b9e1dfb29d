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
    for page in ("index", "install", *GUIDES, "accuracy", "benchmarks", "hard-cases", "api/index", "internals",
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


def _script(name: str):
    spec = importlib.util.spec_from_file_location(name, ROOT / "scripts" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


API_PAGES = ("index", "rendering", "settings", "lines", "smoothing", "files", "viewer", "testing")


def test_the_api_reference_documents_every_public_function_class_and_method(site):
    need("griffe")
    assert _script("docs_api").undocumented(ROOT / "python") == []
    pages = {name: (site / "api" / f"{name}.html").read_text() for name in API_PAGES}
    api = "".join(pages.values())
    for name in ("render", "Renderer", "Material", "Camera", "Light", "RenderResult", "Viewer", "smooth.laplacian",
                 "edges.feature_edges", "testing.assert_images_close", "batch.render_files", "Renderer.render_many",
                 "Material.bands", "load", "shapes.torus", "data.bunny", "ViewerClosedError"):
        assert api.count(f'id="toonmesh.{name}"') == 1, name
    # each area's page opens with a table of its entries, linked; the index lists every page's
    for name in API_PAGES[1:]:
        table = pages[name].split("<table>")[1].split("</table>")[0]
        assert table.count('href="#toonmesh.') >= 2, name
        assert f'href="{name}.html#toonmesh.' in pages["index"], name

    # no noise: namedtuple field aliases, raw roles, memory addresses, command-line internals
    figures = _script("docs_metrics").measure(site)["api"]
    assert figures["pages"] == len(API_PAGES), figures
    assert {k: figures[k] for k in ("field_aliases", "raw_roles", "memory_addresses", "cli_internals")} == {
        "field_aliases": 0, "raw_roles": 0, "memory_addresses": 0, "cli_internals": 0}, figures
    assert figures["render_signature_typed"], figures
    # the roles became links: render's docstring names Mesh and load, linked to their entries
    rendering = pages["rendering"]
    entry = rendering.split('id="toonmesh.render"')[1].split('id="toonmesh.Renderer"')[0]
    assert 'href="#toonmesh.Mesh"' in entry and 'href="files.html#toonmesh.load"' in entry
    # the settings classes' signatures are their stub's, typed, not (*args, **kwargs)
    settings = re.sub(r"<[^>]+>", "", pages["settings"])
    assert "*args" not in settings and "**kwargs" not in settings
    assert re.search(r"bands\(\s*color:\s*Optional\[Color\]", settings), settings[:2000]

    # the render keywords: a table of every keyword (type, default, meaning), from the core's
    # description, linked from render's entry and from Renderer.render and render_many
    import toonmesh

    keywords = rendering.split('id="render-keywords"')[1]
    for field in toonmesh.RenderOptions.describe()["fields"]:
        assert f'id="render-keywords.{field["name"]}"' in keywords, field["name"]
    assert "<code>Material.bands()</code>" in keywords and "<code>512</code>" in keywords
    assert 'href="#render-keywords"' in entry
    for method in ("render", "render_many"):
        part = rendering.split(f'id="toonmesh.Renderer.{method}"')[1][:6000]
        assert 'href="#render-keywords"' in part, method


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
