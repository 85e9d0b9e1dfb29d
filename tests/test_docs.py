"""The documentation site (``make docs``): it builds with warnings as errors, its gallery's scripts
run and leave their figures in the built site, every link between its pages resolves, the API
reference documents every public name, and a browser shows its pages without a broken image."""

from __future__ import annotations

import html
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


def _requests_from_the_web(page) -> List[str]:
    """Collects, as the page loads things, every request that leaves the disk (a site read
    offline must make none) and every request that fails."""
    seen: List[str] = []

    def request(r) -> None:
        if urlsplit(r.url).scheme not in ("file", "data", "about", "blob"):
            seen.append(r.url)

    page.on("request", request)
    page.on("requestfailed", lambda r: seen.append(f"{r.url} ({r.failure})"))
    return seen


def test_searching_plotter_from_file_lists_a_page_about_it(site, tmp_path):
    sync_api = need("playwright.sync_api")
    executable = chromium()
    assert (site / "search" / "search_index.js").is_file()  # the index as a script, for file:// pages
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            outside = _requests_from_the_web(page)
            page.goto((site / "index.html").as_uri())
            page.wait_for_load_state("load")
            box = page.locator(".md-search__input")
            assert box.is_visible()  # in the header, not behind an icon, at 1280 px
            header = page.locator(".md-header").bounding_box()
            where = box.bounding_box()
            assert header and where and where["y"] + where["height"] <= header["y"] + header["height"]
            box.click()
            box.type("plotter")
            items = page.locator(".md-search-result__item")
            items.first.wait_for(state="visible", timeout=20_000)
            shot = tmp_path / "search-plotter.png"
            page.screenshot(path=str(shot))
            visible = [item for item in items.all() if item.is_visible()]
            assert visible, "no search result is visible"
            meta = page.locator(".md-search-result__meta").inner_text()
            assert "matching" in meta and not meta.startswith("No"), meta
            links = page.eval_on_selector_all(".md-search-result__item > a", "links => links.map(a => a.href)")
            targets = {Path(unquote(urlsplit(link).path)) for link in links}
            assert targets and all(t.is_file() and site in t.parents for t in targets), links
            about = [t for t in targets if "plotter" in re.sub("<[^>]+>", " ", t.read_text()).lower()]
            assert about, targets
            # a guide's section whose heading says "plotter" is among the results, by its anchor
            every = page.eval_on_selector_all(".md-search-result a", "links => links.map(a => a.href)")
            found = {(Path(unquote(urlsplit(link).path)), urlsplit(link).fragment) for link in every}
            heading = re.compile(r'<h[1-6] id="([^"]+)"[^>]*>((?:(?!</h).)*plotter(?:(?!</h).)*)</h', re.I | re.S)
            guides = [site / f"{name}.html" for name in GUIDES]
            sections = {(t, m.group(1)) for t in guides for m in heading.finditer(t.read_text())}
            assert sections <= found, (sections - found, every)
            # the version, in the footer
            version = page.locator(".tm-version")
            version.scroll_into_view_if_needed()
            assert version.is_visible() and "toonmesh " in version.inner_text()
            # a notebook's page too (nbconvert's pages load widget managers and MathJax from the web)
            page.goto((site / "notebooks" / "quickstart.html").as_uri())
            page.wait_for_load_state("load")
            assert outside == [], outside
        finally:
            browser.close()
    assert shot.stat().st_size > 10_000
    print("screenshots:", shot)


def _pages(site: Path) -> List[Path]:
    return sorted(p for p in site.rglob("*.html"))


def test_every_page_shows_the_version_it_documents(site):
    import toonmesh

    version = toonmesh.__version__
    assert re.fullmatch(r"\d+\.\d+\.\d+\S*", version)
    pages = _pages(site)
    assert len(pages) > 40
    footer = re.compile(r'<div class="md-copyright__highlight tm-version">\s*toonmesh ([^\s<]+)')
    shown = {page.relative_to(site).as_posix(): footer.findall(page.read_text(encoding="utf-8")) for page in pages}
    assert {name: found for name, found in shown.items() if found != [version]} == {}


def test_the_changelog_is_a_page_of_the_nav_with_this_version(site):
    import toonmesh

    text = (site / "changelog.html").read_text(encoding="utf-8")
    words = re.sub("<[^>]+>", " ", text)
    assert f"[{toonmesh.__version__}]" in words  # the current release has its section
    entries = re.findall(r"<li>", text.split('class="md-content"', 1)[1])
    assert len(entries) >= 20, len(entries)
    # every heading of CHANGELOG.md is on the page, so the page is that file
    headings = re.findall(r"^#+ (.+)$", (ROOT / "CHANGELOG.md").read_text(), flags=re.M)
    assert headings and all(h in words for h in headings), headings
    # linked from the nav and from every page's footer
    index = (site / "index.html").read_text(encoding="utf-8")
    nav = index.split('class="md-nav md-nav--primary"', 1)[1]
    assert 'href="changelog.html"' in nav
    assert 'href="../changelog.html">Changelog' in (site / "gallery" / "index.html").read_text(encoding="utf-8")


def test_the_notebooks_are_pages_with_their_figures_and_their_ipynb_to_download(site):
    nbformat = need("nbformat")
    from PIL import Image
    import base64
    import io

    index = (site / "notebooks.html").read_text(encoding="utf-8")
    ran, with_figures = [], []
    for stored in sorted((ROOT / "notebooks").glob("*.ipynb")):
        name = stored.stem
        assert f'href="notebooks/{name}.html"' in index, name  # the notebooks page links to it
        html = (site / "notebooks" / f"{name}.html").read_text(encoding="utf-8")
        download = re.findall(r'<a href="([^"]+)" download class="md-button tm-download"', html)
        assert download == [f"{name}.ipynb"], download
        offered = site / "notebooks" / download[0]
        notebook = nbformat.read(str(offered), as_version=4)
        nbformat.validate(notebook)
        assert offered.read_bytes() == stored.read_bytes()  # the notebook as stored
        figures = []
        for data in re.findall(r'<img[^>]+src="data:image/png;base64,([^"]+)"', html):
            with Image.open(io.BytesIO(base64.b64decode(data))) as image:
                figures.append(image.size)
        if "Shown without its outputs" in html:  # a notebook the build does not run says so
            assert not figures and '<div class="jp-OutputArea-child' not in html, name
        else:
            ran.append(name)
            assert '<div class="jp-OutputArea-child' in html, name
        assert all(w >= 100 and h >= 100 for w, h in figures), (name, figures)
        if figures:
            with_figures.append(name)
        # a live widget cannot run offline: no widget state is kept, and its still frame is shown
        assert "application/vnd.jupyter.widget-state+json" not in html, name
    assert {"quickstart", "papers"} <= set(with_figures), with_figures
    log = (site / "build.log").read_text()
    assert sorted(re.findall(r"notebooks: (\w+)\.ipynb ran in", log)) == ran, log


def test_no_page_loads_a_script_or_a_style_from_the_web(site):
    tags = re.compile(r'<(?:script[^>]*\ssrc|link[^>]*\shref)="(?:https?:)?//[^"]*"')
    loaded = {page.relative_to(site).as_posix(): tags.findall(page.read_text(encoding="utf-8"))
              for page in _pages(site)}
    assert {name: found for name, found in loaded.items() if found} == {}


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


def test_the_guides_read_in_short_paragraphs_with_code_that_fits_the_page(site):
    """No paragraph of a guide or a measurement page runs over PARAGRAPH_WORDS words (a list
    without a blank line before it collapses into one), and at most 5% of their code lines run
    past CODE_COLUMNS characters (where a comment scrolls out of sight)."""
    metrics = _script("docs_metrics")
    figures = metrics.measure(site)
    print({key: figures[key] for key in ("code_lines", "wide_code_lines", "wide_by_page")})
    assert figures["long_paragraphs"] == [], figures["long_paragraphs"]
    assert figures["code_lines"] > 500
    assert figures["wide_code_lines"] <= 0.05 * figures["code_lines"], figures["wide_by_page"]


def test_a_user_finds_the_tasks_by_their_headings(site):
    """What a user comes to do is a heading of a guide, and the home page links to each."""
    headings: Dict[str, str] = {}
    for page in site.glob("*.html"):
        for _, text in re.findall(r"<h([1-3])[^>]*>(.*?)</h\1>", page.read_text(encoding="utf-8"), re.S):
            headings[html.unescape(re.sub(r"<[^>]+>", "", text)).replace("¶", "").strip()] = page.name
    home = (site / "index.html").read_text(encoding="utf-8")
    for task in ("Render your own file", "SVG for a pen plotter", "Use it in Jupyter", "Hatching and shadows"):
        assert task in headings, (task, sorted(headings))
        anchor = re.sub(r"[^a-z0-9 -]", "", task.lower()).replace(" ", "-")
        assert f'href="{headings[task]}#{anchor}"' in home, task


def test_the_home_page_and_a_gallery_page_show_every_picture_in_a_browser(site, tmp_path):
    sync_api = need("playwright.sync_api")
    executable = chromium()
    shots = []
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            for name in ("index.html", "api/rendering.html", "gallery/index.html", "gallery/still_life.html",
                         "gallery/papers.html"):
                page.goto((site / name).as_uri())
                page.wait_for_load_state("load")
                images = page.evaluate("Array.from(document.images).map(i => [i.src, i.complete, i.naturalWidth])")
                if name.startswith("api/"):
                    # an API page: its summary table and render's typed entry are on screen
                    assert page.locator(".tm-api-table table").first.is_visible(), name
                    assert page.locator("[id='toonmesh.render']").is_visible(), name
                else:
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
