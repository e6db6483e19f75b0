"""Griffe extension: turn the reStructuredText left in runout's numpydoc docstrings into Markdown.

The docstrings are written for numpydoc (Sphinx roles such as ``:func:`x```, ``:math:`x```,
``.. math::`` blocks and simple ``====`` tables). mkdocstrings renders docstrings as Markdown,
so without this extension the API reference shows the roles as raw text and the tables as
broken paragraphs. The conversion happens at documentation build time only; the source stays
numpydoc, which ``help()`` and IDEs read.
"""

from __future__ import annotations

import re
from typing import Any

import griffe

#: ``:role:`target``` for the roles the code uses; ``~`` keeps only the last dotted name.
_ROLE = re.compile(r":(?:py:)?(func|class|meth|attr|mod|data|obj|exc|const):`(~?)([^`]+)`")
_MATH_ROLE = re.compile(r":math:`([^`]+)`")
_TABLE_BORDER = re.compile(r"^(\s*)(=+)((?: +=+)+)\s*$")


def _role(match: re.Match[str]) -> str:
    short, target = match.group(2), match.group(3).strip()
    if short:
        target = target.rsplit(".", 1)[-1]
    call = "()" if match.group(1) in ("func", "meth") and not target.endswith(")") else ""
    return f"`{target}{call}`"


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip(" "))


def _math_blocks(lines: list[str]) -> list[str]:
    """``.. math::`` directives (argument on the same line or indented body) → ``$$`` blocks."""
    out: list[str] = []
    i = 0
    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        if not stripped.startswith(".. math::"):
            out.append(line)
            i += 1
            continue
        base = _indent(line)
        body: list[str] = []
        inline = stripped[len(".. math::") :].strip()
        if inline:
            body.append(inline)
        i += 1
        while i < len(lines) and (not lines[i].strip() or _indent(lines[i]) > base):
            body.append(lines[i].strip())
            i += 1
        while body and not body[-1]:
            body.pop()
        while body and not body[0]:
            body.pop(0)
        # Markdown continues a list item's blocks at 4 spaces; the docstrings indent bullets'
        # continuation lines by 2, so round up or the block would fall out of the item.
        pad = " " * (4 * -(-base // 4))
        out.append("")
        out.append(pad + "$$")
        out.extend(pad + b for b in body if b)
        out.append(pad + "$$")
        out.append("")
    return out


def _cells(line: str, spans: list[tuple[int, int]]) -> list[str]:
    cells = []
    for k, (start, end) in enumerate(spans):
        stop = len(line) if k == len(spans) - 1 else end
        cells.append(line[start:stop].strip())
    return cells


def _rows(segment: list[str], spans: list[tuple[int, int]]) -> list[list[str]]:
    rows: list[list[str]] = []
    for line in segment:
        cells = _cells(line, spans)
        if rows and not cells[0]:  # a wrapped cell continues the row above
            rows[-1] = [(a + " " + b).strip() for a, b in zip(rows[-1], cells, strict=True)]
        else:
            rows.append(cells)
    return rows


def _segment(lines: list[str], start: int) -> int | None:
    """Index of the next border line from ``start`` on, before any blank line; else None."""
    j = start
    while j < len(lines) and lines[j].strip():
        if _TABLE_BORDER.match(lines[j]):
            return j
        j += 1
    return None


def _tables(lines: list[str]) -> list[str]:
    """reST simple tables (``====  ====`` borders, optional header) → Markdown pipe tables.

    A row whose first cell is empty continues the row above (how the docstrings wrap long
    cells).
    """
    out: list[str] = []
    i = 0
    while i < len(lines):
        border = _TABLE_BORDER.match(lines[i])
        second = _segment(lines, i + 1) if border else None
        if border is None or second is None:
            out.append(lines[i])
            i += 1
            continue
        spans = [(m.start(), m.end()) for m in re.finditer(r"=+", lines[i])]
        third = _segment(lines, second + 1)
        if third is not None:  # border, header, border, body, border
            header = [" ".join(c) for c in zip(*_rows(lines[i + 1 : second], spans), strict=True)]
            body = _rows(lines[second + 1 : third], spans)
            i = third + 1
        else:  # border, body, border
            header = [""] * len(spans)
            body = _rows(lines[i + 1 : second], spans)
            i = second + 1
        pad = border.group(1)

        def row(cells: list[str], pad: str = pad) -> str:
            return pad + "| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |"

        out.extend(["", row(header), pad + "|" + "---|" * len(spans)])
        out.extend(row(r) for r in body)
        out.append("")
    return out


def rst_to_markdown(text: str) -> str:
    """Convert the reST constructs runout's docstrings use into Markdown (see module doc)."""
    lines = _tables(_math_blocks(text.splitlines()))
    text = "\n".join(lines)
    text = _MATH_ROLE.sub(lambda m: "\\(" + m.group(1) + "\\)", text)
    return _ROLE.sub(_role, text)


class RstToMarkdown(griffe.Extension):
    """Rewrite every docstring of the loaded package once it is loaded."""

    def on_package(self, *, pkg: griffe.Module, **kwargs: Any) -> None:
        self._walk(pkg, set())

    def _walk(self, obj: Any, seen: set[str]) -> None:
        if obj.path in seen:
            return
        seen.add(obj.path)
        if obj.docstring is not None:
            obj.docstring.value = rst_to_markdown(obj.docstring.value)
        for member in obj.members.values():
            if not member.is_alias:
                self._walk(member, seen)
