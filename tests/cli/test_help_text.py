"""Help texts show what their docstrings say: rich markup must not eat ``[analysis]``.

Found by a new user: ``runout run --help`` read "Run the model named in the case's  table."
because the help is rendered as rich markup, where ``[analysis]`` is a style tag.
"""

from __future__ import annotations

import re

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

COMMANDS = [c for c in app.registered_commands if c.callback is not None]


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: c.name or c.callback.__name__)
def test_bracketed_table_names_survive_in_help(command) -> None:  # type: ignore[no-untyped-def]
    name = command.name or command.callback.__name__.replace("_", "-")
    doc = command.callback.__doc__ or ""
    wanted = set(re.findall(r"\\?\[([a-z_.]+)\]", doc))
    result = CliRunner().invoke(app, [name, "--help"], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    for table in wanted:
        assert f"[{table}]" in result.output, (name, table)
    assert "case's  table" not in result.output
