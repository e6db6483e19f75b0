"""Every public function and class of the package has a numpydoc docstring.

In the manner of python-control's ``docstrings_test.py``: for each public module (no leading
underscore in its dotted path; the command-line package is not an API), every public
function and method documents each of its parameters in a ``Parameters`` section and what it
gives back in a ``Returns`` (or ``Yields``) section unless it returns None; every public class
has a ``Parameters`` or ``Attributes`` section when it takes arguments or has fields.
Properties are exempt (a one-line description is their numpydoc form), and so are dunder
methods. A parameter's unit goes in brackets on its description line (``[m]``).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[2] / "src" / "runout"
NOT_API = ("cli",)


def _public_modules() -> list[Path]:
    out = []
    for path in sorted(SRC.rglob("*.py")):
        parts = path.relative_to(SRC).with_suffix("").parts
        if parts[0] in NOT_API or parts[-1] == "__main__":
            continue
        if any(p.startswith("_") and p != "__init__" for p in parts):
            continue
        out.append(path)
    return out


def _section(doc: str, name: str) -> str | None:
    """The text of numpydoc section ``name`` (None when absent)."""
    match = re.search(
        rf"^\s*{name}\n\s*-{{3,}}\n(.*?)(?=^\s*\w[\w ]*\n\s*-{{3,}}\n|\Z)", doc, re.M | re.S
    )
    return match.group(1) if match else None


def _documented(section: str) -> set[str]:
    """Parameter names a Parameters section describes (``a, b : float`` names both)."""
    names: set[str] = set()
    for line in section.splitlines():
        if line.strip() and not line.startswith((" " * 8, "\t\t")) and ":" in line:
            head = line.split(" : ")[0] if " : " in line else line.split(":")[0]
            names |= {n.strip().lstrip("*") for n in head.split(",")}
        elif line.strip() and not line.startswith(" " * 8):
            names |= {n.strip().lstrip("*") for n in line.strip().split(",")}
    return names


def _is_property(fn: ast.FunctionDef) -> bool:
    return any(
        (isinstance(d, ast.Name) and d.id in ("property", "cached_property", "overload"))
        or (isinstance(d, ast.Attribute) and d.attr in ("setter", "cached_property", "overload"))
        for d in fn.decorator_list
    )


def _returns_value(fn: ast.FunctionDef) -> bool:
    if fn.returns is not None:
        return ast.unparse(fn.returns) not in ("None", "NoReturn")
    return any(isinstance(n, ast.Return) and n.value is not None for n in ast.walk(fn))


def _function_problems(fn: ast.FunctionDef, where: str, method: bool) -> list[str]:
    doc = ast.get_docstring(fn) or ""
    if not doc:
        return [f"{where}: no docstring"]
    problems = []
    args = [a.arg for a in (*fn.args.posonlyargs, *fn.args.args, *fn.args.kwonlyargs)]
    if method and args and args[0] in ("self", "cls"):
        args = args[1:]
    if fn.args.vararg is not None:
        args.append(fn.args.vararg.arg)
    if fn.args.kwarg is not None:
        args.append(fn.args.kwarg.arg)
    if args:
        section = _section(doc, "Parameters")
        if section is None:
            problems.append(f"{where}: no Parameters section ({', '.join(args)})")
        else:
            missing = [a for a in args if a not in _documented(section)]
            if missing:
                problems.append(f"{where}: Parameters lacks {', '.join(missing)}")
    if _returns_value(fn) and _section(doc, "Returns") is None and _section(doc, "Yields") is None:
        problems.append(f"{where}: no Returns section")
    return problems


def _class_problems(cls: ast.ClassDef, where: str) -> list[str]:
    doc = ast.get_docstring(cls) or ""
    if not doc:
        return [f"{where}: no docstring"]
    fields = [
        n
        for n in cls.body
        if isinstance(n, ast.AnnAssign)
        and isinstance(n.target, ast.Name)
        and not n.target.id.startswith("_")
        and "ClassVar" not in ast.unparse(n.annotation)
    ]
    init = next(
        (n for n in cls.body if isinstance(n, ast.FunctionDef) and n.name == "__init__"), None
    )
    takes = bool(fields) or (init is not None and len(init.args.args) > 1)
    is_protocol = any(ast.unparse(b).endswith("Protocol") for b in cls.bases)
    has = _section(doc, "Parameters") is not None or _section(doc, "Attributes") is not None
    if takes and not has and not is_protocol:
        return [f"{where}: no Parameters or Attributes section"]
    return []


def _problems(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    module = ".".join(path.relative_to(SRC.parent).with_suffix("").parts).removesuffix(".__init__")
    problems: list[str] = []
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            problems += _function_problems(node, f"{module}.{node.name}", method=False)
        elif isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            problems += _class_problems(node, f"{module}.{node.name}")
            for item in node.body:
                if (
                    isinstance(item, ast.FunctionDef)
                    and not item.name.startswith("_")
                    and not _is_property(item)
                ):
                    where = f"{module}.{node.name}.{item.name}"
                    problems += _function_problems(item, where, method=True)
    return problems


MODULES = _public_modules()


def test_the_check_sees_the_public_modules() -> None:
    names = {p.relative_to(SRC).as_posix() for p in MODULES}
    assert {"geometry/bearing.py", "analysis/results.py", "models/linear.py"} <= names
    assert not any(n.startswith("cli/") or "/_" in n.removesuffix("/__init__.py") for n in names)


def test_the_check_can_fail() -> None:
    bare = ast.parse("def f(x, y):\n    '''Sum.'''\n    return x + y\n").body[0]
    assert isinstance(bare, ast.FunctionDef)
    assert len(_function_problems(bare, "f", method=False)) == 2
    good = ast.parse(
        "def f(x, y):\n    '''Sum.\n\n    Parameters\n    ----------\n    x, y : float\n"
        "        Lengths [m].\n\n    Returns\n    -------\n    float\n    '''\n    return x + y\n"
    ).body[0]
    assert isinstance(good, ast.FunctionDef)
    assert _function_problems(good, "f", method=False) == []


@pytest.mark.parametrize("path", MODULES, ids=[p.relative_to(SRC).as_posix() for p in MODULES])
def test_public_functions_and_classes_have_numpydoc_sections(path: Path) -> None:
    problems = _problems(path)
    assert not problems, "\n".join(problems)
