"""The envelope-diagnosis validation rows (VALIDATION.md) and their generator."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from runout.case.model import load_case
from runout.validation import envelope
from runout.validation._envelope_checks import defect_frequencies, defect_record, round_trip_rates

CASE = Path(__file__).resolve().parents[3] / "examples" / "cwru_6205_drive_end.toml"


def test_generator_impacts_at_the_defect_period():
    case = load_case(CASE)
    rec = defect_record(case, "outer", noise=0.0, slip=0.0, seed=1)
    a = rec.channels["a"]
    # each impact's first sample is its largest rise: count the rises above half the largest
    rising = np.flatnonzero((a[1:] > 0.5 * a.max()) & (a[:-1] <= 0.5 * a.max()))
    impacts = rising[np.diff(rising, prepend=-10_000) > 20]
    bpfo = defect_frequencies(case, 1797.0)["outer"]
    assert impacts.size == pytest.approx(bpfo * rec.duration, abs=1.5)


def test_rates_on_a_small_sample_hold_the_published_bounds():
    r = round_trip_rates(load_case(CASE), records=24, seed=3)
    assert r.false_alarm == 0.0
    assert r.named >= 0.85 and r.wrong <= 0.1


def test_rows_agree():
    rows = [c.evaluate() for c in envelope.checks()]
    assert len(rows) == 8
    assert all(r.verdict == "agrees" or "agree" in str(r.verdict).lower() for r in rows), rows
