"""Every import of the package is a declared dependency, or an extra's behind a guard.

A plain ``pip install runout`` installs ``[project] dependencies`` and nothing else: a module
that imports a package only an extra (or a dependency's dependency) brings fails there. This
reads every module's imports from its source and checks each against pyproject.toml:

- an import at module level (or in a function without a guard) must come from a core
  dependency;
- an import of an extra's package must sit in a ``try`` that catches ``ImportError`` (the
  message then names the extra), or go through ``_optional("name")``.

The test that installs the built wheel into a fresh environment with no extras and runs every
command is ``tests/cli/test_reproduce_wheel.py``; this one names the offending file and line.
"""

from __future__ import annotations

import ast
import importlib.metadata as metadata
import re
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "src" / "runout"
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))


def _name(requirement: str) -> str:
    """The normalised distribution name of a requirement string (``"dask[x]>=1"`` → dask)."""
    match = re.match(r"\s*([A-Za-z0-9][A-Za-z0-9._-]*)", requirement)
    assert match is not None, requirement
    return re.sub(r"[-_.]+", "-", match.group(1)).lower()


CORE = {_name(r) for r in PYPROJECT["project"]["dependencies"]}
EXTRAS = {
    extra: {_name(r) for r in requirements}
    for extra, requirements in PYPROJECT["project"]["optional-dependencies"].items()
}
#: the import names each installed distribution provides (numba → numba, pillow → PIL, ...)
PROVIDERS = {
    module: {re.sub(r"[-_.]+", "-", d).lower() for d in dists}
    for module, dists in metadata.packages_distributions().items()
}


def _guarded(node: ast.AST, parents: dict[ast.AST, ast.AST]) -> bool:
    """Whether ``node`` lies in the body of a ``try`` one of whose handlers catches ImportError."""
    child, parent = node, parents.get(node)
    while parent is not None:
        if isinstance(parent, ast.Try) and child in parent.body:
            for handler in parent.handlers:
                names = ast.dump(handler.type) if handler.type is not None else "bare"
                if "ImportError" in names or "ModuleNotFoundError" in names:
                    return True
        child, parent = parent, parents.get(parent)
    return False


def _third_party_imports() -> list[tuple[str, int, str, bool]]:
    """(file, line, top-level module, guarded) of every import of a package not ours."""
    found = []
    for path in sorted(SRC.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        parents = {child: node for node in ast.walk(tree) for child in ast.iter_child_nodes(node)}
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                modules = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                modules = [node.module]
            else:
                continue
            for module in modules:
                top = module.split(".")[0]
                if top == "runout" or top in sys.stdlib_module_names:
                    continue
                rel = str(path.relative_to(ROOT))
                found.append((rel, node.lineno, top, _guarded(node, parents)))
    return found


def _optional_calls() -> list[tuple[str, int, str]]:
    """(file, line, module) of every ``_optional("module")`` call (the data extra's imports)."""
    found = []
    for path in sorted(SRC.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Name)
                and node.func.id == "_optional"
                and node.args
                and isinstance(node.args[0], ast.Constant)
                and isinstance(node.args[0].value, str)
            ):
                rel = str(path.relative_to(ROOT))
                found.append((rel, node.lineno, node.args[0].value.split(".")[0]))
    return found


def test_the_scan_sees_the_imports() -> None:
    # the checks below must be able to fail: they see the package's real imports
    tops = {top for _, _, top, _ in _third_party_imports()}
    assert {"numpy", "numba", "typer", "pydantic", "distributed"} <= tops
    assert {module for _, _, module in _optional_calls()} == {"pandas", "xarray"}


def test_every_unguarded_import_is_a_core_dependency() -> None:
    wrong = [
        f"{file}:{line}: {top} (from {sorted(PROVIDERS.get(top, {'?'}))}, not in dependencies)"
        for file, line, top, guarded in _third_party_imports()
        if not guarded and not PROVIDERS.get(top, set()) & CORE
    ]
    assert not wrong, "\n".join(wrong)


def test_every_guarded_import_is_declared_in_an_extra() -> None:
    declared = set().union(*EXTRAS.values()) | CORE
    wrong = [
        f"{file}:{line}: {top} is in no extra of pyproject.toml"
        for file, line, top, guarded in _third_party_imports()
        if guarded and not PROVIDERS.get(top, set()) & declared
    ]
    wrong += [
        f"{file}:{line}: _optional({module!r}) is in no extra of pyproject.toml"
        for file, line, module in _optional_calls()
        if not PROVIDERS.get(module, set()) & set().union(*EXTRAS.values())
    ]
    assert not wrong, "\n".join(wrong)


def test_click_is_not_imported() -> None:
    # typer carries its own copy of click (0.26 on); click is installed only by extras here,
    # so a plain install crashed with "No module named 'click'"
    assert "click" not in CORE
    assert not [row for row in _third_party_imports() if row[2] == "click"]
