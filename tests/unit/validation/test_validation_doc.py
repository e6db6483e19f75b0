"""VALIDATION.md is what `runout reproduce` generates (so no number in it is typed by hand).

A full reproduce takes about 15 s on the 2-core machine, so the test runs every section in
full (no reduced run). Documents are compared as `runout reproduce --check` compares them
(:mod:`runout.validation.compare`): numbers within 1e-6 relative or one unit of their last
printed digit, a row's difference as far as its "ours" may move, error measures at rounding
level as bounds; the tests below show that another machine's last digits are not a stale
document and that a real change is.
"""

from __future__ import annotations

import dataclasses
import random
import re
from pathlib import Path

import pytest

from runout.validation import core
from runout.validation import reproduce as rp
from runout.validation.compare import _cells
from runout.validation.render import _table

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


def _row_line(row: rp.Row) -> str:
    return _table([row]).splitlines()[-1]


def _another_machine(doc: rp.Document, seed: int) -> str:
    """``doc`` as another machine could build it: every ours (and spread) moved by up to 1e-9
    of itself (far beyond round-off, far below CHECK_RTOL), an error measure below its
    rounding quantum anywhere below it; the verdicts as they are."""
    rng = random.Random(seed)
    moved = []
    for row in doc.rows:

        def move(x: float | None) -> float | None:
            return None if x is None else x * (1.0 + rng.uniform(-1e-9, 1e-9))

        value = move(row.value)
        assert value is not None
        quantum = core._quantum(row.check)
        if row.check.rule == "max" and 0.0 <= row.value < quantum:
            value = rng.uniform(0.0, quantum)
        moved.append(dataclasses.replace(row, value=value, low=move(row.low), high=move(row.high)))
    lines = doc.text.splitlines()
    rows = iter(moved)
    out = [_row_line(next(rows)) if _cells(line) else line for line in lines]
    assert next(rows, None) is None  # every row was replaced
    return "\n".join(out) + "\n"


@pytest.mark.parametrize("seed", [0, 1])
def test_another_machines_last_digits_are_not_stale(fresh: rp.Document, seed: int) -> None:
    other = _another_machine(fresh, seed)
    assert other != fresh.text
    assert rp.compare(other, fresh.text) == []
    assert rp.compare(fresh.text, other) == []


def test_a_last_printed_digit_of_ours_moved_is_not_stale() -> None:
    existing = (ROOT / "VALIDATION.md").read_text(encoding="utf-8")
    lines = existing.splitlines()
    moved = 0
    for i, line in enumerate(lines):
        cells = _cells(line)
        if cells is None or not re.fullmatch(r"-?\d+\.\d+", cells[3]):
            continue
        token = cells[3]
        decimals = len(token.split(".")[1])
        cells[3] = f"{float(token) + 10.0**-decimals:.{decimals}f}"
        lines[i] = "| " + " | ".join(cells) + " |"
        moved += 1
    assert moved > 100
    assert rp.compare("\n".join(lines), existing) == []


def _one_row(text: str, quantity: str) -> tuple[int, list[str]]:
    lines = text.splitlines()
    for i, line in enumerate(lines):
        cells = _cells(line)
        if cells is not None and cells[1] == quantity:
            return i, cells
    raise AssertionError(quantity)


def _with_cell(text: str, quantity: str, k: int, value: str) -> str:
    i, cells = _one_row(text, quantity)
    cells[k] = value
    lines = text.splitlines()
    lines[i] = "| " + " | ".join(cells) + " |"
    return "\n".join(lines)


@pytest.mark.parametrize(
    ("quantity", "cell", "value", "name"),
    [
        ("f_c [Hz]", 3, "50.089", "ours"),  # 50.087: two units of its last digit
        ("mean ball load, 20 N, Z = 7, α = 15° [N]", 4, "+0.00025", "difference"),
        ("mean ball load, 20 N, Z = 7, α = 15° [N]", 5, "❌ not reproduced (±0.0005)", "verdict"),
        ("mean ball load, 20 N, Z = 7, α = 15° [N]", 2, "11.05", "published"),  # 11.039
        ("largest relative error of 𝒦, 1 ≤ R_y/R_x ≤ 100", 3, "0.027536", "ours"),
        (
            "contact radius vs the exact solver with radii (r_b, r_b, ∞, ∞), relative",
            3,
            "5e-13",
            "ours",
        ),
        # +4.5e-06 = ours − 3.41198: beyond the 3.4e-6 (1e-6 of ours) ours may move
        ("I₇₋₁ (k = Z − 1 = 6)", 4, "+9.5e-06", "difference"),
    ],
)
def test_a_real_change_is_stale(quantity: str, cell: int, value: str, name: str) -> None:
    existing = (ROOT / "VALIDATION.md").read_text(encoding="utf-8")
    (problem,) = rp.compare(_with_cell(existing, quantity, cell, value), existing)
    assert f"fresh {name} {value!r}" in problem, problem


def test_a_difference_moves_as_far_as_ours_may() -> None:
    row = "| s | q | {pub} | {ours} | {diff} | ✅ agrees ({tol}) | — |"
    rel = row.format(pub="2.5", ours="2.5", diff="-5.14e-08 %", tol="±1 %")
    # the difference of two near-equal numbers: ours may move by 1e-6 of itself, 1e-4 %
    assert rp.compare(rel.replace("-5.14e-08", "-5.2e-08"), rel) == []
    assert rp.compare(rel.replace("-5.14e-08", "-3e-04"), rel) != []
    ratio = row.format(pub="19", ours="0.86928", diff="×0.04575", tol="±5 %")
    assert rp.compare(ratio.replace("0.04575", "0.04576"), ratio) == []
    assert rp.compare(ratio.replace("0.04575", "0.04578"), ratio) != []
    absolute = row.format(pub="0", ours="0", diff="0", tol="±0.001")
    # printed as 0 below 1e-4 of the tolerance: a number at that bound is the same
    assert rp.compare(absolute.replace("| 0 | ✅", "| +1e-07 | ✅"), absolute) == []
    assert rp.compare(absolute.replace("| 0 | ✅", "| +2e-06 | ✅"), absolute) != []
    bound = row.format(pub="—", ours="< 1e-11", diff="—", tol="≤ 1e-09")
    assert rp.compare(bound.replace("< 1e-11", "1e-11"), bound) == []
    assert rp.compare(bound.replace("< 1e-11", "2.5e-11"), bound) != []


def test_round_off_is_printed_as_a_bound_not_as_a_result() -> None:
    def ours(value: float, tol: float, rule: str = "max", published: float | None = None) -> str:
        check = rp.Check("s", "q", published, lambda: value, rule, tol)
        return check.evaluate().cells()[3 if published is None else 4]

    # one ulp or two of a relative error checked against 1e-13 print alike
    assert ours(2.220446049250313e-16, 1e-13) == ours(1.1102230246251565e-16, 1e-13) == "< 1e-13"
    assert ours(2.6044e-12, 1e-9) == ours(2.0615e-12, 1e-9) == "< 1e-11"
    assert ours(0.0, 1e-12) == "< 1e-12"
    assert ours(0.0339, 0.035) == "0.0339"  # a result, well above rounding
    assert ours(2.5 * (1 + 1e-13), 0.01, "rel", 2.5) == "0 %"
    assert ours(2.5 * (1 - 5.14e-10), 0.01, "rel", 2.5) == "-5.14e-08 %"


def test_checks_at_rounding_level_are_relative_errors() -> None:
    # ROUNDOFF is a relative round-off: a check with a tolerance below 1e-8 must measure a
    # relative error (or ratio), or its bound would be in some unit of its own
    tiny = [
        c
        for section in rp.SECTIONS
        for group in section.groups
        for c in group.checks()
        if c.rule == "max" and c.tol < 1e-8
    ]
    assert len(tiny) >= 5
    for c in tiny:
        assert "relative" in c.quantity, c.quantity


def test_merged_sections_replace_theirs_and_new_ones_go_before_the_index() -> None:
    from runout.validation.compare import merge_sections

    existing = "# V\n\nhead\n\n### A\n\na\n\n### B\n\nb\n\n### Example case files used above\n\ni\n"
    fresh = "# V\n\nhead\n\n### B\n\nb2\n\n### C\n\nc\n"
    merged = merge_sections(existing, fresh)
    assert merged == (
        "# V\n\nhead\n\n### A\n\na\n\n### B\n\nb2\n\n### C\n\nc\n\n"
        "### Example case files used above\n\ni\n"
    )
    assert merge_sections(existing, existing) == existing
