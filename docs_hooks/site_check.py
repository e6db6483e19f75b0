"""Checks of the built documentation site that a reader would otherwise find by eye.

Used by ``make docs`` (after the build) and by ``tests/docs/test_site.py``:

* no raw Sphinx roles (``:func:`x```) and no reST table borders in the pages;
* no raw TeX (``e^{…}``, ``S_{k}``, ``\\frac``) outside the math that KaTeX renders and outside
  code;
* every relative link and resource resolves to a file inside the site, and no page points to
  files a user of the project does not have (the papers' folder, design notes);
* the KaTeX copy the pages load is in the site.

:func:`check_theory_source` reads a theory page's markdown itself for what the built page hides:
an equation written as plain text (it renders, but as ``W_ij(t) = Σ_k ...`` with underscores)
and a list without a blank line before it (Python-Markdown folds it into the paragraph above).
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
#: A list item (``*``, ``-``, ``+`` or ``1.``) at the start of a line.
LIST_ITEM = re.compile(r"^ {0,3}(?:[*+-]|\d+[.)])\s+\S")
#: An equation as plain text: a subscripted or Greek symbol (optionally with arguments) set
#: equal to, or compared with, something; or a sum, root, integral or partial derivative sign.
PLAIN_EQUATION = re.compile(
    r"(?<![\w\\])(?:[A-Za-zα-ωΑ-Ω]+_\w+|[α-ωΑ-ΩΣ]\w*)(?:\([^)]*\))?\s*[=≈≤≥]\s*[^\s=]"
    r"|[Σ∑√∫∂]"
)
#: Inline code, inline mathematics and link targets: not prose to check.
NOT_PROSE = re.compile(r"`[^`]*`|\$\$.*?\$\$|\$[^$]*\$|\]\([^)]*\)")

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


def check_theory_source(text: str, name: str) -> list[str]:
    """Plain-text equations and collapsed lists in one theory page's markdown source.

    Parameters
    ----------
    text : str
        The page's markdown.
    name : str
        The page's name in the messages.

    Returns
    -------
    list of str
        ``"name:line: what: text"`` for each finding (empty when the page is clean).
    """
    problems: list[str] = []
    previous = ""
    fenced = display = False
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped.startswith(("```", "~~~")):
            fenced = not fenced
        elif fenced:
            pass
        elif display or (stripped.startswith("$$") and stripped.count("$$") == 1):
            # a display block: from a line opening $$ to the line that closes it
            display = not (display and "$$" in stripped)
        else:
            if (
                LIST_ITEM.match(line)
                and previous.strip()
                and not LIST_ITEM.match(previous)
                and not previous.startswith((" ", "\t", "#", "|"))
            ):
                problems.append(f"{name}:{number}: list without a blank line before it")
            prose = NOT_PROSE.sub("", line)
            match = PLAIN_EQUATION.search(prose)
            if match:
                problems.append(f"{name}:{number}: plain-text mathematics: {prose.strip()[:72]}")
        previous = line
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
