"""Checks of the built documentation site that a reader would otherwise find by eye.

Used by ``make docs`` (after the build) and by ``tests/docs/test_site.py``:

* no raw Sphinx roles (``:func:`x```) and no reST table borders in the pages;
* no raw TeX (``e^{…}``, ``S_{k}``, ``\\frac``) outside the math that KaTeX renders and outside
  code;
* every relative link and resource resolves to a file inside the site, and no page points to
  files a user of the project does not have (the papers' folder, design notes);
* the KaTeX copy the pages load is in the site.
"""

from __future__ import annotations

import re
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

RAW_ROLE = re.compile(
    r":(?:py:)?(?:func|class|meth|attr|mod|data|obj|exc|const|math|ref):(?:`|<code>)"
)
RAW_TEX = re.compile(r"\^\{|_\{|\\(?:frac|sum|alpha|beta|gamma|delta|theta|varphi|phi|sqrt|cdot)\b")
RST_TABLE = re.compile(r"={3,}[ \t]+={3,}")
OUTSIDE = re.compile(r"\.\./shared|DESIGN\.md|seeds/[0-9]{3}_")
#: Text inside these is not prose: code, scripts, and the mathematics KaTeX renders.
SKIP_TAGS = {"code", "pre", "script", "style", "kbd", "samp", "textarea"}


class _Page(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.stack: list[tuple[str, bool]] = []
        self.text: list[str] = []
        self.links: list[str] = []

    def _skipping(self) -> bool:
        return any(skip for _, skip in self.stack)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        for key in ("href", "src"):
            if values.get(key):
                self.links.append(str(values[key]))
        if tag in {"br", "img", "hr", "meta", "link", "input", "source", "col", "wbr"}:
            return
        classes = (values.get("class") or "").split()
        self.stack.append((tag, tag in SKIP_TAGS or "arithmatex" in classes))

    def handle_endtag(self, tag: str) -> None:
        for k in range(len(self.stack) - 1, -1, -1):
            if self.stack[k][0] == tag:
                del self.stack[k:]
                return

    def handle_data(self, data: str) -> None:
        if not self._skipping():
            self.text.append(data)


def check_page(site: Path, page: Path) -> list[str]:
    """Problems found in one built HTML page (empty when it is clean)."""
    raw = page.read_text(encoding="utf-8")
    name = page.relative_to(site).as_posix()
    problems: list[str] = []
    parser = _Page()
    parser.feed(raw)
    prose = "".join(parser.text)
    for pattern, what in ((RAW_TEX, "raw TeX outside mathematics"), (RST_TABLE, "reST table")):
        for match in pattern.finditer(prose):
            context = prose[max(0, match.start() - 40) : match.end() + 40].replace("\n", " ")
            problems.append(f"{name}: {what}: …{context}…")
    for match in RAW_ROLE.finditer(raw):
        problems.append(f"{name}: raw Sphinx role: {raw[match.start() : match.end() + 40]!r}")
    for match in OUTSIDE.finditer(prose):
        context = prose[max(0, match.start() - 40) : match.end() + 40].replace("\n", " ")
        problems.append(f"{name}: points outside the project: …{context}…")
    for link in parser.links:
        parts = urlsplit(link)
        if parts.scheme in ("http", "https", "mailto", "data"):
            continue
        if parts.scheme or (link.startswith("/") and name != "404.html"):
            problems.append(f"{name}: link outside the site: {link}")
            continue
        if not parts.path or name == "404.html":
            continue  # an anchor on the same page; the 404 page links from the site's root
        target = (page.parent / unquote(parts.path)).resolve()
        if not target.is_relative_to(site.resolve()):
            problems.append(f"{name}: link leaves the site: {link}")
        elif not (target.is_file() or (target / "index.html").is_file()):
            problems.append(f"{name}: broken link: {link}")
    return problems


def check_site(site: Path) -> list[str]:
    """Problems found in every page of the built site at ``site``."""
    problems: list[str] = []
    for asset in ("assets/katex/katex.min.js", "assets/katex/katex.min.css"):
        if not (site / asset).is_file():
            problems.append(f"missing {asset}: the mathematics would not render")
    for page in sorted(site.rglob("*.html")):
        problems.extend(check_page(site, page))
    return problems


if __name__ == "__main__":
    found = check_site(Path(sys.argv[1]))
    print("\n".join(found) or "site check: clean")
    raise SystemExit(1 if found else 0)
