"""`runout run --out` draws its figures in processes started beside the model (issue 31).

The files are those the command would write by itself (the same names, the same bytes); a
figure that fails is the command's error (one line, the internal-error status, no files
moved into DIR); a drawing process that dies is an error naming the figures not written,
never a hang.
"""

from __future__ import annotations

import os
import pickle
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from runout.case.model import load_case
from runout.cli.commands import app
from runout.cli.common import EXIT_INTERNAL
from runout.report import plotting
from runout.report.run_files import write_result
from runout.runner import run_model

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


@pytest.mark.parametrize("example", ["seed001_kim_spindle", "seed002_608", "seed004_nu209"])
def test_the_files_are_those_drawn_in_the_command(example: str, tmp_path: Path) -> None:
    case = EXAMPLES / f"{example}.toml"
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(case), "--out", str(out)])
    assert result.exit_code == 0, result.stderr
    here = tmp_path / "here"
    written = write_result(run_model(load_case(case)), here)  # drawn in this process
    assert len(written) == len({p.name for p in written})
    names = sorted(p.name for p in written)
    assert sorted(
        p.name
        for p in out.iterdir()
        if p.name not in ("case.toml", "summary.json") and not p.name.startswith(".")
    ) == (names)
    # the order of the listing is that of write_result's
    listed = [line.rsplit("/", 1)[-1] for line in result.stdout.split() if "/" in line]
    assert [n for n in listed if n in names] == [p.name for p in written]
    for name in names:
        assert (out / name).read_bytes() == (here / name).read_bytes(), name


def test_a_figure_that_fails_fails_the_command(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    def broken(*args: Any, **kwargs: Any) -> Any:
        raise ValueError("the orbit cannot be drawn")

    # inherited by the drawing processes, which are forked from this one
    monkeypatch.setattr(plotting, "plot_orbit", broken)
    out = tmp_path / "out"
    result = runner.invoke(
        app, ["run", str(EXAMPLES / "seed001_kim_spindle.toml"), "--out", str(out)]
    )
    assert result.exit_code == EXIT_INTERNAL, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1
    assert "ValueError: the orbit cannot be drawn" in lines[0]
    assert not [p for p in out.iterdir() if p.suffix in (".png", ".gif", ".csv", ".json")]


def test_a_drawing_process_that_dies_is_an_error_not_a_hang(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    def dies(*args: Any, **kwargs: Any) -> Any:
        os._exit(9)  # as if killed (out of memory)

    monkeypatch.setattr(plotting, "plot_orbit", dies)
    out = tmp_path / "out"
    result = runner.invoke(
        app, ["run", str(EXAMPLES / "seed001_kim_spindle.toml"), "--out", str(out)]
    )
    assert result.exit_code == EXIT_INTERNAL, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1
    assert "orbit.png" in lines[0] and "ended early" in lines[0]
    assert not (out / "history.png").exists()


def test_spawned_processes_draw_the_same_files(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Where processes are not forked (macOS, Windows) each is spawned and warms itself."""
    from runout.report._figure_workers import FigureWorkers
    from runout.report.run_files import warm_figures

    result = run_model(load_case(EXAMPLES / "seed001_kim_spindle.toml"))
    monkeypatch.setattr("sys.platform", "darwin")
    with FigureWorkers(2, warm_figures) as workers:
        spawned = write_result(result, tmp_path / "spawned", workers=workers)
    monkeypatch.undo()
    here = write_result(result, tmp_path / "here")
    assert [p.name for p in spawned] == [p.name for p in here]
    for a, b in zip(spawned, here, strict=True):
        assert a.read_bytes() == b.read_bytes(), a.name


@pytest.mark.skipif(not hasattr(os, "nice"), reason="niceness is a Unix process attribute")
def test_the_drawing_processes_yield_to_the_command(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """The model and the order sweep go first on busy cores: the figures draw at a lower
    priority (the figure drawn from the sweep is not left waiting at the end)."""
    from runout.report._figure_workers import FIGURE_NICENESS

    seen = tmp_path / "niceness"
    drawn = plotting.plot_orbit

    def recording(*args: Any, **kwargs: Any) -> Any:
        seen.write_text(str(os.nice(0)))  # os.nice(0) reads the process's niceness
        return drawn(*args, **kwargs)

    monkeypatch.setattr(plotting, "plot_orbit", recording)
    out = tmp_path / "out"
    result = runner.invoke(
        app, ["run", str(EXAMPLES / "seed001_kim_spindle.toml"), "--out", str(out)]
    )
    assert result.exit_code == 0, result.stderr
    assert (out / "orbit.png").is_file()
    # at most 19, the lowest priority: a command already that nice draws at 19
    assert int(seen.read_text()) == min(19, os.nice(0) + FIGURE_NICENESS)
    assert FIGURE_NICENESS > 0


def test_the_drawing_processes_need_not_import_the_solver(tmp_path: Path) -> None:
    """What the drawing processes receive for the rigid model (the result, its figures' data,
    the order sweep) unpickles without the compiled solver: importing Numba there cost each
    process 0.2 s of CPU while the sweep ran (issue 31)."""
    received: list[bytes] = []

    class Recording:
        """Stands in for FigureWorkers: keeps what would travel, draws here."""

        def draw(self, draw: Any, result: Any, directory: Path, jobs: Any, later: Any) -> Any:
            jobs = [*jobs, *later()]
            received.append(pickle.dumps((draw, result, jobs), protocol=pickle.HIGHEST_PROTOCOL))
            return {name: draw(result, directory, name, extra) for name, extra in jobs}

    result = run_model(load_case(EXAMPLES / "seed004_nu209.toml"))
    written = write_result(result, tmp_path / "out", workers=Recording())  # type: ignore[arg-type]
    assert {"displacement.png", "contact_pattern.png", "order_sweep.png"} <= {
        p.name for p in written
    }
    (tmp_path / "payload.pickle").write_bytes(received[0])
    check = (
        "import pickle, sys; import runout.report.run_files; "
        "before = set(sys.modules); "
        f"pickle.loads(open({str(tmp_path / 'payload.pickle')!r}, 'rb').read()); "
        "print(sorted(m for m in set(sys.modules) - before "
        "if m.split('.')[0] == 'numba' or m.startswith('runout.models')))"
    )
    done = subprocess.run(
        [sys.executable, "-c", check], capture_output=True, text=True, timeout=120, check=True
    )
    assert done.stdout.strip() == "[]"
