"""A ``runout run --out DIR`` directory reads back into a result that summarises, plots and
writes like the one the model returned."""

from __future__ import annotations

import io
import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.base.errors import RunoutError
from runout.case.model import load_case
from runout.cli.commands import app
from runout.io.output_dir import MARKER
from runout.io.result_files import read_result
from runout.report import plotting
from runout.runner import run_model

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
runner = CliRunner()

#: One example per model (each runs in about a second).
CASES = [
    ("seed001_kim_table4", ()),
    ("seed000_tada_fig7", ('analysis.bands="iso15242"', 'analysis.limit="0.1 nm"')),
    ("seed002_608", ()),
    ("seed001_kim_equilibrium", ()),
    ("seed003_purohit_clearance", ()),
    ("seed004_nu209", ()),
]


def _png(fig: object) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=60)  # type: ignore[attr-defined]
    plotting.pyplot().close(fig)
    return buf.getvalue()


@pytest.mark.parametrize(("name", "sets"), CASES, ids=[c[0] for c in CASES])
def test_read_back_run_directory(name: str, sets: tuple[str, ...], tmp_path: Path) -> None:
    out = tmp_path / "run"
    args = ["run", str(EXAMPLES / f"{name}.toml"), "--out", str(out)]
    for text in sets:
        args += ["--set", text]
    done = runner.invoke(app, args)
    assert done.exit_code == 0, done.stderr
    read = read_result(out)
    # the JSON the run wrote, byte for byte
    import json

    text = json.dumps(read.to_json(), indent=2, allow_nan=False) + "\n"
    assert text == (out / "result.json").read_text()
    # the tables of the model's own result
    case = load_case(out / "case.toml")
    original = run_model(case)
    assert read.summary_sections() == original.summary_sections()
    np.testing.assert_array_equal(read.measuring_direction, original.measuring_direction)
    if sets:
        assert read.iso15242 is not None and read.verdict is not None
        assert read.verdict.passed is False
    # written again: the same data files (history.csv holds what it was read from)
    again = tmp_path / "again"
    written = {p.name for p in read.write(again)}
    for same in ("result.json", "history.csv", "lines.csv"):
        assert (again / same).read_bytes() == (out / same).read_bytes(), same
    model_only = {"contacts.csv", "order_sweep.csv", "order_sweep.png", "displacement.png"}
    model_only.add("contact_pattern.png")
    # the CLI adds the case, its summary and the list of runout's files (docs/outputs.md)
    expected = {p.name for p in out.iterdir()} - {"case.toml", "summary.json", MARKER}
    if name == "seed004_nu209":  # the contact solution is not stored: its files are not
        expected -= model_only
    assert written == expected
    if read.time.size < 2:
        return
    # the figures: the lines figure is drawn from the lines alone, the same image
    assert _png(plotting.plot_result(read, "lines")) == _png(plotting.plot_result(original))
    for kind in ("history", "orbit", "spectrum"):
        fig = plotting.plot_result(read, kind)
        ref = plotting.plot_result(original, kind)
        assert [a.get_title() for a in fig.axes] == [a.get_title() for a in ref.axes] or (
            kind == "history"  # the window may start one sample apart (12-digit times)
        )
        assert [a.get_ylabel() for a in fig.axes] == [a.get_ylabel() for a in ref.axes]
        for a, b in zip(fig.axes, ref.axes, strict=True):
            np.testing.assert_allclose(a.get_ylim(), b.get_ylim(), rtol=1e-6)
        plotting.pyplot().close(fig)
        plotting.pyplot().close(ref)


def test_report_rebuilt_without_rerunning(tmp_path: Path) -> None:
    out = tmp_path / "run"
    done = runner.invoke(
        app, ["run", str(EXAMPLES / "seed001_kim_table4.toml"), "--out", str(out), "--report"]
    )
    assert done.exit_code == 0, done.stderr
    first = (out / "report.html").read_text(encoding="utf-8")
    (out / "report.html").unlink()
    done = runner.invoke(app, ["report", str(out)])
    assert done.exit_code == 0, done.stderr
    assert (out / "report.html").read_text(encoding="utf-8") == first


def test_read_result_needs_the_record(tmp_path: Path) -> None:
    out = tmp_path / "run"
    done = runner.invoke(app, ["run", str(EXAMPLES / "seed001_kim_table4.toml"), "--out", str(out)])
    assert done.exit_code == 0, done.stderr
    (out / "history.csv").unlink()
    with pytest.raises(RunoutError, match=r"history\.csv"):
        read_result(out)


def test_read_result_refuses_an_unknown_measuring_direction(tmp_path: Path) -> None:
    out = tmp_path / "run"
    done = runner.invoke(app, ["run", str(EXAMPLES / "seed001_kim_table4.toml"), "--out", str(out)])
    assert done.exit_code == 0, done.stderr
    (out / "case.toml").unlink()
    with pytest.raises(RunoutError, match="measuring direction"):
        read_result(out)


def test_report_refuses_a_negative_solver_resolution(tmp_path: Path) -> None:
    """Found by the reading fuzz test: ``solver_resolution_m = -1`` in an edited result.json
    passed the shape check (a number) and crashed the report (internal error, exit 70)."""
    out = tmp_path / "run"
    done = runner.invoke(app, ["run", str(EXAMPLES / "seed002_608.toml"), "--out", str(out)])
    assert done.exit_code == 0, done.stderr
    doc = json.loads((out / "result.json").read_text(encoding="utf-8"))
    doc["solver_resolution_m"] = -1
    (out / "result.json").write_text(json.dumps(doc), encoding="utf-8")
    done = runner.invoke(app, ["report", str(out)])
    assert done.exit_code == 2, done.stderr
    (line,) = done.stderr.strip().splitlines()
    assert "result.json: solver_resolution_m: expected a finite number >= 0, found -1" in line
