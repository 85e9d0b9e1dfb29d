"""How readable the built documentation site is: ``python scripts/docs_metrics.py SITE``.

Reads the built site (``make docs`` writes it into site/) and prints, as JSON:

- ``long_paragraphs``: paragraphs of the guides (every page but the API reference and the
  gallery's) over ``PARAGRAPH_WORDS`` words, each as ``[page, words, first words]``;
- ``code_lines`` and ``wide_code_lines``: the lines of the guides' code blocks, and those wider
  than ``CODE_COLUMNS`` characters;
- ``api``: on the API reference pages, the namedtuple field aliases, raw Sphinx roles, memory
  addresses and command-line internals shown, the headings, and whether ``render``'s signature
  shows types.

``tests/test_docs.py`` holds the site to these limits.
"""

from __future__ import annotations

import json
import re
import sys
from html.parser import HTMLParser
from pathlib import Path
from typing import Dict, List, Tuple

#: a paragraph longer than this is a wall of text
PARAGRAPH_WORDS = 150
#: a code line wider than this scrolls its end (often its comment) out of sight
CODE_COLUMNS = 90

#: what an API page must not show: namedtuple field aliases, reStructuredText roles as text,
#: objects' memory addresses, and the command line's internals
API_NOISE = {
    "field_aliases": r"Alias for field number",
    "raw_roles": r":(?:class|func|meth|attr|data|mod|exc|obj|py:\w+):",
    "memory_addresses": r"\bat 0x[0-9a-fA-F]{6,}",
    "cli_internals": r"\b(?:cmd_render|cmd_\w+|DEFAULT_FPS|TYPE_CHECKING)\b",
}


class _Text(HTMLParser):
    """The text of the page's article: its paragraphs, code blocks' lines and headings."""

    def __init__(self) -> None:
        super().__init__()
        self.paragraphs: List[str] = []
        self.code: List[str] = []
        self.headings = 0
        self.text: List[str] = []
        self._in_article = 0
        self._p = 0
        self._pre = 0
        self._buf: List[str] = []
        self._pre_buf: List[str] = []
        self._skip = 0

    def handle_starttag(self, tag: str, attrs) -> None:
        if tag == "article":
            self._in_article += 1
        if not self._in_article:
            return
        if tag in ("script", "style"):
            self._skip += 1
        if tag == "p":
            self._p += 1
            self._buf = []
        elif tag == "pre":
            self._pre += 1
            self._pre_buf = []
        elif re.fullmatch(r"h[1-6]", tag):
            self.headings += 1

    def handle_endtag(self, tag: str) -> None:
        if tag == "article":
            self._in_article -= 1
        if not self._in_article:
            return
        if tag in ("script", "style"):
            self._skip -= 1
        if tag == "p" and self._p:
            self._p -= 1
            self.paragraphs.append(" ".join("".join(self._buf).split()))
        elif tag == "pre" and self._pre:
            self._pre -= 1
            self.code.extend("".join(self._pre_buf).rstrip("\n").split("\n"))

    def handle_data(self, data: str) -> None:
        if not self._in_article or self._skip:
            return
        self.text.append(data)
        if self._p:
            self._buf.append(data)
        if self._pre:
            self._pre_buf.append(data)


def _read(path: Path) -> _Text:
    parser = _Text()
    parser.feed(path.read_text(encoding="utf-8"))
    return parser


def _is_api(rel: str) -> bool:
    return rel == "api.html" or rel.startswith("api/")


def measure(site: Path) -> Dict[str, object]:
    """The figures above, for the site built into ``site``."""
    long_paragraphs: List[Tuple[str, int, str]] = []
    code_lines = 0
    wide: List[Tuple[str, int]] = []
    api: Dict[str, object] = {key: 0 for key in API_NOISE}
    api.update(headings=0, pages=0, render_signature_typed=False)
    for path in sorted(site.rglob("*.html")):
        rel = path.relative_to(site).as_posix()
        if rel == "404.html":
            continue
        page = _read(path)
        if _is_api(rel):
            text = "".join(page.text)
            api["pages"] = int(api["pages"]) + 1  # type: ignore[call-overload]
            api["headings"] = int(api["headings"]) + page.headings  # type: ignore[call-overload]
            for key, pattern in API_NOISE.items():
                api[key] = int(api[key]) + len(re.findall(pattern, text))  # type: ignore[call-overload]
            html = path.read_text(encoding="utf-8")
            heading = re.search(r'id="toonmesh\.render".*?</h\d>', html, re.S)
            if heading:
                signature = re.sub(r"<[^>]+>", "", html[heading.end():heading.end() + 6000])
                api["render_signature_typed"] = bool(re.search(r"\w+\s*:\s*\w", signature.split(")")[0]))
            continue
        if rel.startswith("gallery/"):
            continue
        for p in page.paragraphs:
            words = len(p.split())
            if words > PARAGRAPH_WORDS:
                long_paragraphs.append((rel, words, " ".join(p.split()[:8])))
        for line in page.code:
            code_lines += 1
            if len(line) > CODE_COLUMNS:
                wide.append((rel, len(line)))
    return {"long_paragraphs": long_paragraphs, "code_lines": code_lines, "wide_code_lines": len(wide),
            "wide_by_page": _count(p for p, _ in wide), "api": api}


def _count(items) -> Dict[str, int]:
    out: Dict[str, int] = {}
    for item in items:
        out[item] = out.get(item, 0) + 1
    return out


if __name__ == "__main__":
    figures = measure(Path(sys.argv[1] if len(sys.argv) > 1 else "site"))
    figures["long_paragraphs_count"] = len(figures["long_paragraphs"])  # type: ignore[arg-type]
    print(json.dumps(figures, indent=1))
