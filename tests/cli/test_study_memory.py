"""The memory estimate of a batched Monte Carlo bounds what the study really holds.

Found in review: a ball-size Monte Carlo of 250 bearings at 2^17 instants was estimated at
35 MB and peaked at 1.5 GB (5.4 GB at 2^19, accepted by ``runout check`` under the 2 GiB
default), because every chunk held all its records at once. The study is run through the real
command line and its peak memory measured by a fresh parent process.
"""

from __future__ import annotations

import sys
from pathlib import Path

from peak_memory import peak_rss
from runout.case.estimates import estimate_run, estimate_study
from runout.case.model import load_case

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed001_kim_table9.toml"
#: Peak memory of the command before any study array: Python, NumPy, numba, SciPy, pint,
#: pydantic and the compiled kernels (measured ~250 MB), with margin.
BASELINE = 400 * 2**20


def test_batched_monte_carlo_stays_within_its_estimate(tmp_path: Path) -> None:
    text = EXAMPLE.read_text()
    text = text.replace("samples = 1000\n", "samples = 250\n", 1)
    text = text.replace("[analysis]\n", '[analysis]\nmax_memory = "8 GiB"\n', 1)
    text = text.replace("revolutions = ", "revolutions = 1024 # ", 1)
    text = text.replace("samples = 1024", "samples = 131072", 1)
    case_path = tmp_path / "lot.toml"
    case_path.write_text(text)
    case = load_case(case_path)
    assert case.analysis.samples == 131072 and case.study.samples == 250
    estimate = estimate_study(case, estimate_run(case, case.analysis.model))
    peak = peak_rss(
        [sys.executable, "-m", "runout.cli", "study", str(case_path), "--out", str(tmp_path / "o")]
    )
    assert peak <= BASELINE + estimate.memory, (peak / 2**20, estimate.memory / 2**20)


def test_worker_processes_are_checked_against_the_budget(tmp_path: Path) -> None:
    """Each worker holds the shared arrays: a budget that fits the study in this process but
    not in two workers refuses ``--workers 2`` before any work, naming the remedy."""
    from typer.testing import CliRunner

    from runout.case.estimates import STUDY_BYTES_PER_RUN, batched_memory, study_points
    from runout.cli.commands import app

    text = EXAMPLE.read_text().replace("samples = 1024", "samples = 131072", 1)
    case_path = tmp_path / "lot.toml"
    case_path.write_text(text)
    case = load_case(case_path)
    runs = study_points(case) * STUDY_BYTES_PER_RUN
    here = max(
        estimate_study(case, estimate_run(case, case.analysis.model)).memory,
        batched_memory(case) + runs,
    )
    two = batched_memory(case, workers=2) + runs
    assert two > 1.5 * here
    limit = f"{int((here + two) / 2 / 2**20)} MiB"
    result = CliRunner().invoke(
        app,
        ["study", str(case_path), "--workers", "2", "--json"],
        env={"RUNOUT_MAX_MEMORY": limit},
    )
    assert result.exit_code == 2, result.output
    assert "worker processes would need about" in result.stderr
    assert str(case_path) in result.stderr
