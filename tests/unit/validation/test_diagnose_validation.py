"""The diagnosis checks: the documented recovery table, seed 002's reading, the nonlinear bias."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from runout.validation._diagnosis_checks import nonlinear_bias_rows, recovery_markdown, seed002_rows

ROOT = Path(__file__).resolve().parents[3]


def test_documented_recovery_table_is_what_the_code_gives():
    doc = (ROOT / "docs" / "models" / "diagnosis.md").read_text(encoding="utf-8")
    table = recovery_markdown(str(ROOT / "examples" / "seed002_608.toml"))
    assert table in doc


def test_recovery_error_grows_with_noise():
    rows = {
        (noise, rev): med
        for noise, rev, med, _ in _rows_from(
            recovery_markdown(str(ROOT / "examples" / "seed002_608.toml"))
        )
    }
    for rev in (5.0, 20.0, 80.0):
        assert rows[(0.01, rev)] < rows[(0.05, rev)] < rows[(0.2, rev)]
    for noise in (0.01, 0.05, 0.2):
        assert rows[(noise, 80.0)] < rows[(noise, 5.0)]


def _rows_from(table: str) -> list[tuple[float, float, float, float]]:
    out = []
    for line in table.splitlines()[2:]:
        cells = [c.strip().rstrip(" %") for c in line.strip("|").split("|")]
        out.append(tuple(float(c) for c in cells))
    return out  # type: ignore[return-value]


def test_seed002_rows_within_their_tolerance():
    rows = seed002_rows(str(ROOT / "examples" / "seed002_608.toml"))
    assert len(rows) == 11
    for quantity, published, ours, tolerance, _why in rows:
        assert abs(ours / published - 1.0) <= tolerance, quantity


def test_nonlinear_record_bias():
    rows = nonlinear_bias_rows(20e-9)
    alpha = math.radians(28.9)  # seed 000's bearing under 20 N (docs/models/linear.md)
    for quantity, _set, _got, bias, variant in rows:
        if variant == "force_balance":
            assert abs(bias) < 2e-3, quantity
        elif quantity.startswith("ball"):
            assert bias == pytest.approx(1.0 / math.cos(alpha) ** 2 - 1.0, abs=0.01), quantity
        else:
            assert bias == pytest.approx(1.0 / math.cos(alpha) - 1.0, abs=0.01), quantity
