"""Write the API reference pages (docs/api/*.md) and their nav from the stage packages.

``python docs_hooks/api_pages.py`` rewrites ``docs/api/`` (one page per package, listing its
public modules, one page per public module; the validation package on one page) and the
``API reference`` part of mkdocs.yml, in the packages' order bottom to top. Run it after
adding or moving a module; ``tests/docs/test_site.py`` fails while a public module has no
page in the nav.
"""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src" / "runout"
API = ROOT / "docs" / "api"

#: The stage packages bottom to top, and what each holds (the nav's section titles).
PACKAGES = [
    ("base", "Base (errors, units, display, glossary)"),
    ("geometry", "Geometry and physics of one bearing"),
    ("catalogue", "The bearing catalogue"),
    ("case", "Case files"),
    ("analysis", "Spectra, lines and results"),
    ("models", "Models"),
    ("runner", "Running a case"),
    ("io", "Result files"),
    ("diagnose", "Diagnosis"),
    ("api", "The Python face"),
    ("examples", "The Python face"),
    ("report", "Reports, summaries and figures"),
    ("study", "Studies"),
    ("validation", "Validation against the papers"),
]
#: Tools of the project, not API (the generators of docs pages).
NOT_API = {"runout.case.schema_doc", "runout.validation.reproduce"}


def summary(path: Path) -> str:
    """The first sentence line of a module's docstring."""
    doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8"))) or ""
    first = doc.strip().splitlines()[0] if doc.strip() else ""
    # Sphinx roles read as plain code in a Markdown list (:class:`X` -> `X`)
    return re.sub(r":\w+:`~?([^`]+)`", r"`\1`", first).replace("``", "`")


def public_modules(package: str) -> list[tuple[str, Path]]:
    """(dotted name, path) of the package itself and its public modules."""
    single = SRC / f"{package}.py"
    if single.exists():
        return [(f"runout.{package}", single)]
    base = SRC / package
    out = [(f"runout.{package}", base / "__init__.py")]
    for path in sorted(base.glob("*.py")):
        if path.stem.startswith("_"):
            continue
        name = f"runout.{package}.{path.stem}"
        if name not in NOT_API:
            out.append((name, path))
    return out


def write_pages() -> list[tuple[str, list[tuple[str, str]]]]:
    """Write every page; return the nav sections: (title, [(label, file)])."""
    for old in API.glob("*.md"):
        old.unlink()
    sections: dict[str, list[tuple[str, str]]] = {}
    index = [
        "# API reference",
        "",
        "Generated from the docstrings (numpydoc: units in brackets, the source equation",
        "cited). The packages are stages, bottom to top: each imports only those above it in",
        "this list ([architecture](../architecture.md)).",
        "",
    ]
    for package, title in PACKAGES:
        modules = public_modules(package)
        entries = sections.setdefault(title, [])
        if package == "validation":
            body = [f"# `runout.{package}`", "", f"::: runout.{package}", ""]
            body += [f"::: {name}\n" for name, _ in modules[1:]]
            (API / f"runout.{package}.md").write_text("\n".join(body), encoding="utf-8")
            entries.append((f"runout.{package}", f"api/runout.{package}.md"))
            index += [f"## {title}", "", f"- [`runout.{package}`](runout.{package}.md)", ""]
            continue
        if title not in [line.removeprefix("## ") for line in index]:
            index += [f"## {title}", ""]
        for i, (name, path) in enumerate(modules):
            is_package = path.name == "__init__.py"
            options = "\n    options:\n      members: false\n" if is_package and i == 0 else "\n"
            if is_package and len(modules) > 1:
                listed = "\n".join(f"- [`{n}`]({n}.md): {summary(p)}" for n, p in modules[1:])
                text = f"# `{name}`\n\n::: {name}{options}\n## Modules\n\n{listed}\n"
            else:
                text = f"# `{name}`\n\n::: {name}{options}"
            (API / f"{name}.md").write_text(text, encoding="utf-8")
            entries.append((name, f"api/{name}.md"))
            index.append(f"- [`{name}`]({name}.md): {summary(path)}")
        index.append("")
    (API / "index.md").write_text("\n".join(index).rstrip() + "\n", encoding="utf-8")
    return list(sections.items())


def write_nav(sections: list[tuple[str, list[tuple[str, str]]]]) -> None:
    """Replace the ``API reference`` block of mkdocs.yml."""
    config = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    lines = ["  - API reference:", "      - api/index.md"]
    for title, entries in sections:
        lines.append(f"      - {title}:")
        lines += [f"          - {label}: {file}" for label, file in entries]
    block = "\n".join(lines) + "\n"
    new, count = re.subn(r"  - API reference:\n(?:      .*\n)+", block, config)
    if count != 1:
        sys.exit("mkdocs.yml: no single 'API reference' block in the nav")
    (ROOT / "mkdocs.yml").write_text(new, encoding="utf-8")


if __name__ == "__main__":
    write_nav(write_pages())
