"""The stage packages stay a DAG: few units at the top, no import cycle, old paths deprecated.

``make lint`` runs the layer contract itself (import-linter, ``[tool.importlinter]`` in
pyproject.toml: each package imports only those below it). These tests add what the contract
does not see: every import statement counts (inside functions and under ``TYPE_CHECKING``
too), so no cycle between modules hides behind a deferred import; the few places where a
lower module reaches an upper one at call time by name (``importlib.import_module``: the
result's conveniences and the deprecated paths) are exactly the listed ones; and the module
paths of the flat layout keep working for one release, with a DeprecationWarning.
"""

from __future__ import annotations

import ast
import importlib
import sys
import warnings
from collections import defaultdict
from pathlib import Path

import pytest

import runout

SRC = Path(__file__).resolve().parents[2] / "src"
PACKAGE = SRC / "runout"

#: Where a module reaches a module above it at call time, by name, and why.
BY_NAME = {
    # results are data: their figure, summary and files come from the report layer
    ("runout.analysis.results", "runout.report.plotting"),
    ("runout.analysis.results", "runout.report.summary"),
    ("runout.analysis.results", "runout.report.run_files"),
    # a linear result read back is the linear model's own result type
    ("runout.analysis.results", "runout.models.linear"),
    # the deprecated runout.models.run_model (moved to runout.runner), for one release
    ("runout.models", "runout.runner"),
}


def _modules() -> dict[str, Path]:
    out = {}
    for path in SRC.rglob("*.py"):
        name = ".".join(path.relative_to(SRC).with_suffix("").parts).removesuffix(".__init__")
        out[name] = path
    return out


def _edges(modules: dict[str, Path]) -> dict[str, set[str]]:
    """Module -> the runout modules it imports, every import statement counted."""
    edges: dict[str, set[str]] = defaultdict(set)
    for name, path in modules.items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                targets = [f"{node.module}.{a.name}" for a in node.names] + [node.module]
            elif isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                continue
            for target in targets:
                while target and target not in modules:
                    target = target.rpartition(".")[0]
                if target.startswith("runout") and target != name:
                    edges[name].add(target)
                    break
    return edges


def _cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(sorted(component))

    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 10_000))
    try:
        for v in list(edges):
            if v not in index:
                visit(v)
    finally:
        sys.setrecursionlimit(limit)
    return out


def test_at_most_16_units_under_the_package() -> None:
    units = [
        p.name
        for p in PACKAGE.iterdir()
        if (p.suffix == ".py" or (p.is_dir() and (p / "__init__.py").exists()))
    ]
    assert len(units) <= 16, sorted(units)


def test_no_import_cycle_between_modules() -> None:
    cycles = _cycles(_edges(_modules()))
    assert not cycles, cycles


def test_the_cycle_check_can_fail() -> None:
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _cycles({"a": {"b"}, "b": set()}) == []


def test_the_only_upward_calls_by_name_are_the_listed_ones() -> None:
    found = set()
    for name, path in _modules().items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and node.func.attr == "import_module"
                and node.args
                and isinstance(node.args[0], ast.Constant)
                and str(node.args[0].value).startswith("runout.")
                and name != "runout"  # the package face and its deprecated paths
            ):
                found.add((name, node.args[0].value))
    assert found == BY_NAME


@pytest.mark.parametrize("old", sorted(runout.MOVED_MODULES))
def test_the_flat_layout_paths_still_import_with_a_warning(old: str) -> None:
    sys.modules.pop(old, None)
    with pytest.warns(DeprecationWarning, match=old.replace(".", r"\.") + " is deprecated"):
        module = importlib.import_module(old)
    home = importlib.import_module(runout.MOVED_MODULES[old][0])
    public = [n for n in getattr(home, "__all__", dir(home)) if not n.startswith("_")]
    assert public
    for name in public:
        assert getattr(module, name) is getattr(home, name), (old, name)


def test_moved_names_reach_their_new_homes() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        from runout.results import RunResult as old_result  # type: ignore[import-not-found]
        from runout.results import apply_analysis  # type: ignore[import-not-found]

        from runout.analysis.results import RunResult
        from runout.report.run_files import write_result
        from runout.runner.analysis import apply_analysis as new_apply

        assert old_result is RunResult and apply_analysis is new_apply
        from runout.result_files import write_result as old_write  # type: ignore[import-not-found]

        assert old_write is write_result
    with pytest.warns(DeprecationWarning, match="run_model is deprecated"):
        import runout.models

        moved = runout.models.run_model
    from runout.runner import run_model

    assert moved is run_model
