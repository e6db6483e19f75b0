"""Benchmark of the diagnosis (issue 19): a 10^6-sample x/y record of the 608 diagnosed.

Ours: :func:`runout.diagnose.fit` on a record (20 kHz, 50 s, 1500 revolutions) of inner, outer and
ball waviness with 2 % noise and a mains line: 240 candidate lines fitted jointly in x and y,
the residual searched, the linear model inverted, the estimates run forward again. Reference:
one NumPy FFT of both channels, the least any spectral reading of the record costs. Second
benchmark: reading the same record from a CSV file (checks included).
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np

from _harness import BenchResult, best_time
from runout.case.model import load_case
from runout.diagnose._record import read_record
from runout.diagnose.fit import diagnose
from runout.validation._diagnosis_checks import done_when_truth, recovery_errors, synthetic_record

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = 1_000_000


def _record():  # type: ignore[no-untyped-def]
    case = load_case(ROOT / "examples" / "seed002_608.toml")
    truth = done_when_truth(7)
    rec, _, _ = synthetic_record(case, truth, sample_rate=20000.0, samples=SAMPLES, seed=3)
    return case, truth, rec


def bench_diagnose_1e6_samples() -> BenchResult:
    case, truth, rec = _record()
    d = diagnose(case, rec)
    worst = max(recovery_errors(d, truth).values())
    if not (worst < 0.02 and d.explained_fraction > 0.95):
        raise AssertionError(f"diagnosis wrong: worst error {worst}, {d.explained_fraction}")
    ours = best_time(lambda: diagnose(case, rec), repeat=3)
    x, y = rec.channels["x"], rec.channels["y"]
    ref = best_time(lambda: (np.fft.rfft(x), np.fft.rfft(y)), repeat=3)
    return BenchResult(
        name="diagnose 10^6-sample x/y record (608)",
        ours_s=ours,
        reference_s=ref,
        reference="NumPy FFT of x and y",
        target="< 2 s",
        met=ours < 2.0,
    )


def bench_diagnose_read_csv_1e6_rows() -> BenchResult:
    _, _, rec = _record()
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "record.csv"
        data = np.column_stack([rec.time, rec.channels["x"], rec.channels["y"]])
        np.savetxt(path, data, delimiter=",", header="time_s,x_m,y_m", comments="", fmt="%.9g")
        ours = best_time(lambda: read_record(path), repeat=3)
        ref = best_time(lambda: np.loadtxt(path, delimiter=",", skiprows=1), repeat=1)
    return BenchResult(
        name="read a 10^6-row record CSV (checked)",
        ours_s=ours,
        reference_s=ref,
        reference="np.loadtxt of the file",
        target="< 1.5 s",
        met=ours < 1.5,
    )
