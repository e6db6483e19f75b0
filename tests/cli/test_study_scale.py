"""Studies at scale through the real command line (issue 31): a lot of 10^6 bearings within
the default budget, memory that does not grow with Python objects per sample, and the change
of the Monte Carlo draws (sampling version 2) refused on resume instead of mixed.

Found in issue 31: 10^6 samples of seed 001 Table 9 were refused by the default budget
("would need about 2.09 GiB": 2 KiB kept per sample), every sample set up its own random
generator (2.7 s of a 10^5 study), and a study held its chunks and samples.csv's text whole.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from peak_memory import peak_rss
from runout.case.estimates import batched_sample_bytes
from runout.case.model import load_case

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed001_kim_table9.toml"
#: Peak memory of the command before any study array: Python, NumPy, numba, SciPy, pint,
#: pydantic, matplotlib and the compiled kernels (measured ~250 MB), with margin.
BASELINE = 400 * 2**20


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    exe = [sys.executable, "-m", "runout.cli", *args]
    return subprocess.run(exe, capture_output=True, text=True, check=False, timeout=300)


def lot(tmp_path: Path, samples: int, instants: int | None = None) -> Path:
    text = EXAMPLE.read_text().replace("samples = 1000\n", f"samples = {samples}\n", 1)
    if instants is not None:
        text = text.replace("revolutions = 8 ", "revolutions = 1 ", 1)
        text = text.replace("samples = 1024", f"samples = {instants}", 1)
    path = tmp_path / "lot.toml"
    path.write_text(text)
    return path


def test_a_million_bearings_are_within_the_default_budget(tmp_path: Path) -> None:
    path = lot(tmp_path, 1_000_000)
    assert load_case(path).study.samples == 1_000_000
    done = cli("check", str(path))
    assert done.returncode == 0, done.stderr


def test_memory_of_a_lot_grows_by_its_columns_not_by_objects_per_sample(
    tmp_path: Path,
) -> None:
    """10^5 bearings at 64 instants written to --out take at most twice their columns (8 bytes
    per sample and column of samples.csv: one column and a temporary of the statistics) more
    than 10^3 bearings do. Before: chunks of Python floats kept whole and samples.csv's text
    built at once, about 1.6 kB per sample here."""
    peaks, columns = {}, 0
    for samples in (1_000, 100_000):
        path = lot(tmp_path, samples, instants=64)
        out = tmp_path / f"o{samples}"
        cmd = [sys.executable, "-m", "runout.cli", "study", str(path), "--out", str(out)]
        peaks[samples] = peak_rss(cmd)
        with (out / "samples.csv").open() as fh:
            columns = len(fh.readline().split(","))
            assert sum(1 for _ in fh) == samples
        summary = json.loads((out / "summary.json").read_text())
        assert summary["samples"] == samples and summary["failed"] == 0
    growth = peaks[100_000] - peaks[1_000]
    assert growth <= 2 * 8 * columns * 99_000, (growth / 2**20, columns)
    # and within what the estimate counts for it
    assert peaks[100_000] <= BASELINE + 100_000 * batched_sample_bytes(load_case(path))


def test_a_run_of_the_earlier_sampling_is_not_resumed(tmp_path: Path) -> None:
    """A directory written before sampling version 2 (its manifest has no ``sampling``) holds
    other bearings for the same seed: --resume refuses it in one line, a fresh run replaces it."""
    path = lot(tmp_path, 40, instants=64)
    out = tmp_path / "o"
    assert cli("study", str(path), "--out", str(out)).returncode == 0
    manifest = json.loads((out / "manifest.json").read_text())
    del manifest["sampling"]  # as sampling version 1 wrote it
    manifest["complete"] = False
    (out / "manifest.json").write_text(json.dumps(manifest))
    done = cli("study", str(path), "--out", str(out), "--resume")
    assert done.returncode == 2, done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "earlier version of runout (sampling 1" in lines[0]
    assert "without --resume" in lines[0] and str(out / "manifest.json") in lines[0]
    again = cli("study", str(path), "--out", str(out))
    assert again.returncode == 0, again.stderr
    assert json.loads((out / "manifest.json").read_text())["sampling"] == 2
