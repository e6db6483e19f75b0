"""Lengths at the input's scale: unit choice and formatting (runout.base.display)."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from runout.base.display import format_length, length_unit, resolution_note

# A printed number: optional sign, digits, optional decimals; nothing else.
_NUMBER = re.compile(r"^-?\d+(\.\d+)? (nm|um|mm|m)$")

finite_lengths = st.floats(min_value=-1e4, max_value=1e4, allow_nan=False, allow_infinity=False)
# Lengths for which some unit (nm to m) reads below 1000: under 999.9 m.
unit_range_lengths = st.floats(min_value=-999.9, max_value=999.9, allow_nan=False)


@pytest.mark.parametrize(
    ("values", "expected"),
    [
        ([3.124e-7], ("nm", 1e9)),
        ([5e-10, 3.1e-7], ("nm", 1e9)),
        ([2.5e-6, 3e-9], ("um", 1e6)),
        ([2.5e-3], ("mm", 1e3)),
        ([1.5], ("m", 1.0)),
        ([], ("nm", 1e9)),
        ([0.0, -0.0], ("nm", 1e9)),
        ([math.nan, 2e-6, math.inf], ("um", 1e6)),
        ([-4e-6], ("um", 1e6)),
        # 999.97 nm would print as "1000 nm": shown in um instead.
        ([9.9997e-7], ("um", 1e6)),
    ],
)
def test_length_unit_choice(values: list[float], expected: tuple[str, float]) -> None:
    assert length_unit(values) == expected


@pytest.mark.parametrize(
    ("value", "unit", "resolution", "expected"),
    [
        (3.124e-7, None, None, "312.4 nm"),
        (3.124e-7, ("um", 1e6), None, "0.3124 um"),
        (3e-7, None, None, "300 nm"),
        (5e-19, ("nm", 1e9), 1e-12, "0 nm"),
        (-5e-19, ("nm", 1e9), 1e-12, "0 nm"),
        (2e-12, ("nm", 1e9), 1e-12, "0.002 nm"),
        (-1.23456e-6, None, None, "-1.235 um"),
        (1234567.0, ("m", 1.0), None, "1235000 m"),
    ],
)
def test_format_length_examples(
    value: float, unit: tuple[str, float] | None, resolution: float | None, expected: str
) -> None:
    assert format_length(value, unit, resolution_m=resolution) == expected


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_format_length_refuses_non_finite(bad: float) -> None:
    with pytest.raises(ValueError, match="non-finite"):
        format_length(bad)


def test_format_length_refuses_bad_resolution() -> None:
    with pytest.raises(ValueError, match="resolution_m"):
        format_length(1e-9, resolution_m=math.nan)


def test_resolution_note() -> None:
    assert resolution_note(1e-12, ("nm", 1e9)) == (
        "values below the solver's resolution (0.001 nm) print as 0"
    )
    with pytest.raises(ValueError):
        resolution_note(0.0, ("nm", 1e9))


@given(st.lists(unit_range_lengths, min_size=1, max_size=8))
def test_chosen_unit_reads_between_a_tenth_and_a_thousand(values: list[float]) -> None:
    name, scale = length_unit(values)
    largest = max(abs(v) for v in values)
    reading = largest * scale
    assert reading < 1000.0
    if largest >= 1e-10:
        # The smallest unit is nm: a largest value under 0.1 nm cannot read 0.1 or more.
        assert reading >= 0.1
    if largest >= 1e-9 and name != "nm":
        assert reading >= 0.999


@given(
    st.lists(finite_lengths, min_size=1, max_size=8),
    st.one_of(st.none(), st.floats(min_value=0.0, max_value=1e-6)),
    st.integers(min_value=1, max_value=8),
)
def test_format_length_prints_plain_numbers(
    values: list[float], resolution: float | None, digits: int
) -> None:
    unit = length_unit(values)
    for value in values:
        text = format_length(value, unit, resolution_m=resolution, digits=digits)
        assert _NUMBER.match(text), text
        assert "e" not in text.split()[0]
        assert "nan" not in text and "inf" not in text
        if resolution is not None and abs(value) < resolution:
            assert text == f"0 {unit[0]}"
        # The printed number is the value within rounding to `digits` significant digits
        # (or to the decimal cap of digits + 2 decimals).
        shown = float(text.split()[0])
        reading = value * unit[1]
        if resolution is None or abs(value) >= resolution:
            tolerance = max(abs(reading) * 10.0 ** (1 - digits), 10.0 ** -(digits + 2))
            assert abs(shown - reading) <= tolerance, (text, reading)


@given(finite_lengths)
def test_own_unit_never_shows_a_thousand(value: float) -> None:
    text = format_length(value)
    assert abs(float(text.split()[0])) < 1000.0 or abs(value) >= 1000.0


def test_a_tiny_resolution_is_stated_as_a_bound_not_as_noise_digits() -> None:
    from runout.base.display import format_resolution

    note = resolution_note(5.2e-16, ("nm", 1e9))
    assert note == "values below the solver's resolution (under 0.001 nm) print as 0"
    assert format_resolution(5.2e-10) == "0.52 nm"
    assert format_resolution(7.3e-16) == "under 0.001 nm"
    with pytest.raises(ValueError):
        format_resolution(0.0)


def test_an_array_is_read_in_one_pass_like_the_same_values_in_a_list() -> None:
    import numpy as np

    rng = np.random.default_rng(4)
    for scale in (1e-10, 3e-8, 2e-5, 0.4):
        values = rng.normal(size=(3, 500)) * scale
        assert length_unit(values) == length_unit(values.ravel().tolist())
    values = np.array([np.nan, 2.5e-6, -np.inf, -7e-7])
    assert length_unit(values) == length_unit([2.5e-6, -7e-7]) == ("um", 1e6)
    assert length_unit(np.array([])) == ("nm", 1e9)
