"""docs/python.md is a test: its Python blocks and its ``runout`` commands run, in order.

The blocks run in one namespace in a temporary directory with the Agg backend, as a reader
pasting them one after the other would; the ``$ runout ...`` lines of its console blocks run
through the command line on the files the blocks wrote. Every ``runout.NAME`` the guide uses
must be documented on an API reference page.
"""

from __future__ import annotations

import importlib
import json
import re
import shlex
from pathlib import Path
from types import ModuleType
from typing import Any

import matplotlib
import pytest
from typer.testing import CliRunner

import runout
from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "docs" / "python.md"
FENCE = re.compile(r"^```(\w+)\n(.*?)^```", re.MULTILINE | re.DOTALL)


def _blocks(language: str) -> list[str]:
    return [
        body for lang, body in FENCE.findall(GUIDE.read_text(encoding="utf-8")) if lang == language
    ]


def test_the_guide_has_python_blocks_and_commands() -> None:
    assert len(_blocks("python")) >= 8
    assert any("$ runout run" in block for block in _blocks("console"))


def test_every_python_block_runs_in_order(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    namespace: dict[str, Any] = {"__name__": "__guide__"}
    for i, block in enumerate(_blocks("python"), start=1):
        try:
            exec(compile(block, f"docs/python.md block {i}", "exec"), namespace)
        except Exception as exc:  # the failing block, not only the line
            raise AssertionError(f"block {i} failed:\n{block}") from exc
    import matplotlib.pyplot as plt

    plt.close("all")
    printed = capsys.readouterr().out
    assert "radial runout p-p" in printed and "nm at 30 N" in printed
    assert "analysis.samples: must be >= 16" in printed  # the error block printed the error
    # the two runs' lines in one table keep their units (issue 29: pd.concat dropped them)
    lines = namespace["lines"]
    assert lines.attrs["units"]["pp_m"] == "m" and lines.attrs["units"]["frequency_hz"] == "Hz"
    assert set(lines["model"]) == {"quasi_static_3d", "quasi_static_2d"}
    assert (tmp_path / "lines.png").stat().st_size > 0
    assert (tmp_path / "spindle.toml").is_file()

    # the console block: the saved case runs to the JSON of the Python run
    runner = CliRunner()
    commands = [
        line[2:]
        for block in _blocks("console")
        for line in block.splitlines()
        if line.startswith("$ runout ")
    ]
    assert commands
    for command in commands:
        args = shlex.split(command)[1:]
        result = runner.invoke(app, args)
        assert result.exit_code == 0, (command, result.stderr)
    first = runner.invoke(app, ["run", "spindle.toml", "--json"])
    assert json.dumps(json.loads(first.stdout)) == json.dumps(namespace["qs3"].to_json())
    second = runner.invoke(app, ["run", "spindle.toml", "--model", "quasi_static_2d", "--json"])
    assert json.loads(second.stdout)["components"] == namespace["qs2"].to_json()["components"]


def test_every_public_name_the_guide_uses_is_in_the_api_reference() -> None:
    text = "\n".join(_blocks("python")) + GUIDE.read_text(encoding="utf-8")
    names = set(re.findall(r"(?<![\w.])runout\.([A-Za-z_]\w*)", text))
    assert {"run", "Imperfections", "Case", "load_case", "BallBearing", "Operation"} <= names
    for name in sorted(names):
        obj = getattr(runout, name, None)
        if obj is None or isinstance(obj, ModuleType):
            module = f"runout.{name}"  # a module: runout.models, runout.report.plotting
        else:
            module = obj.__module__
        page = ROOT / "docs" / "api" / f"{module}.md"
        assert page.is_file(), f"runout.{name} ({module}) has no API reference page"
        assert f"::: {module}" in page.read_text(encoding="utf-8")
        if obj is not None and not isinstance(obj, ModuleType):
            # rendered on that page: public there (in its __all__ when it has one)
            home = importlib.import_module(module)
            assert getattr(home, name) is obj
            assert name in getattr(home, "__all__", [name]), f"{name} not in {module}.__all__"
    # the methods the guide calls are documented on their classes
    from runout.analysis.results import RunResult

    for method in ("to_dataframe", "plot", "to_json"):
        assert getattr(RunResult, method).__doc__
    for method in ("from_inputs", "to_toml", "save"):
        assert getattr(runout.Case, method).__doc__
