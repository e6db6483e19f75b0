"""VALIDATION.md is what `runout reproduce` generates (so no number in it is typed by hand).

A full reproduce takes about 15 s on the 2-core machine, so the test runs every section in
full (no reduced run). Numbers are compared as `runout reproduce --check` compares them: within
1e-6 relative or one unit of their last printed digit.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from runout.validation import reproduce as rp

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="module")
def fresh() -> rp.Document:
    return rp.build()


def test_validation_md_equals_a_fresh_reproduce(fresh: rp.Document) -> None:
    # Regenerate with: runout reproduce
    existing = (ROOT / "VALIDATION.md").read_text(encoding="utf-8")
    problems = rp.compare(fresh.text, existing)
    assert not problems, "\n".join(problems[:10])


def test_every_section_has_rows_and_every_row_a_verdict(fresh: rp.Document) -> None:
    counts = fresh.counts()
    assert sum(counts.values()) == len(fresh.rows) > 150
    for key in rp.section_keys():
        assert f"### {next(s.title for s in rp.SECTIONS if s.key == key)}" in fresh.text


def test_every_example_used_by_a_check_exists() -> None:
    rp.build(["kinematics"])  # registers its examples
    for name in rp.EXAMPLE_USES:
        assert (ROOT / "examples" / name).is_file(), name


def test_compare_tolerates_last_digit_but_not_a_real_change() -> None:
    base = "| a | 1.2345 | +0.5 % | ✅ |"
    assert rp.compare(base, "| a | 1.2346 | +0.5 % | ✅ |") == []
    assert rp.compare(base, "| a | 1.2355 | +0.5 % | ✅ |") != []
    assert rp.compare(base, "| a | 1.2345 | +0.5 % | ❌ |") != []


def test_verdict_rules() -> None:
    agree = rp.Check("s", "q", 10.0, lambda: 10.2, "rel", 0.03).evaluate()
    gap = rp.Check("s", "q", 10.0, lambda: 11.0, "rel", 0.03).evaluate()
    spread = rp.Check(
        "s", "q", 10.0, lambda: (11.0, 9.0, 12.0), "rel", 0.03, spread_from_ours=True
    ).evaluate()
    outside = rp.Check(
        "s", "q", 10.0, lambda: (11.0, 10.5, 12.0), "rel", 0.03, spread_from_ours=True
    ).evaluate()
    assert (agree.verdict, gap.verdict, spread.verdict, outside.verdict) == (
        rp.AGREE,
        rp.NOT,
        rp.SPREAD,
        rp.NOT,
    )
    assert rp.Check("s", "q", None, lambda: 1e-9, "max", 1e-6).evaluate().verdict == rp.AGREE
    assert rp.Check("s", "q", None, lambda: 0.5, "min", 1.0).evaluate().verdict == rp.NOT
