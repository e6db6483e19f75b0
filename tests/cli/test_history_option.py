"""`runout run --history-revolutions N` chooses how many revolutions the history figure shows
(issue 17: "the history shows a few revolutions (selectable)")."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from runout.cli.commands import app
from runout.report import plotting

runner = CliRunner()
CASE = Path(__file__).resolve().parents[2] / "examples" / "seed000_tada_fig7.toml"


def test_the_option_reaches_the_history_figure(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    # recorded in a file: the figures are drawn by processes forked from this one
    seen = tmp_path / "seen.txt"
    drawn = plotting.plot_time_history

    def recording(result: Any, ax: Any = None, revolutions: float = 3.0) -> Any:
        with seen.open("a") as fh:
            fh.write(f"{revolutions!r}\n")
        return drawn(result, ax, revolutions=revolutions)

    monkeypatch.setattr(plotting, "plot_time_history", recording)
    out = tmp_path / "tada"
    result = runner.invoke(
        app, ["run", str(CASE), "--out", str(out), "--history-revolutions", "10"]
    )
    assert result.exit_code == 0, result.stderr
    assert seen.read_text().split() == ["10.0"]
    assert (out / "history.png").stat().st_size > 10_000


@pytest.mark.parametrize("value", ["0", "-1", "1e9"])
def test_a_history_length_out_of_range_is_refused(value: str, tmp_path: Path) -> None:
    result = runner.invoke(
        app, ["run", str(CASE), "--out", str(tmp_path / "x"), "--history-revolutions", value]
    )
    assert result.exit_code == 2
    assert "--history-revolutions" in result.stderr
