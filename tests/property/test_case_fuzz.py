"""Hypothesis: any corruption of a valid case is refused with a CaseError naming the key."""

from __future__ import annotations

import tomllib

from hypothesis import given, settings
from hypothesis import strategies as st

from runout.case import parse_case
from runout.errors import CaseError

BASE = tomllib.loads(
    """
[bearing]
type = "ball"
elements = 7
element_diameter = "3.9688 mm"
pitch_diameter = "15 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "10 um"
[operation]
rotating_ring = "inner"
speed = "1800 rpm"
axial_load = "20 N"
"""
)

LENGTH_KEYS = ["element_diameter", "pitch_diameter", "radial_clearance"]

bad_lengths = st.one_of(
    st.floats(max_value=-1e-9, allow_nan=False, allow_infinity=False),
    st.sampled_from(["3 kg", "12 N", "fast", "10 rpm", "", "mm", "1e400 m"]),
    st.booleans(),
    st.lists(st.integers(), max_size=2),
)


@settings(max_examples=60, deadline=None)
@given(key=st.sampled_from(LENGTH_KEYS), value=bad_lengths)
def test_corrupt_length_is_refused_naming_the_key(key: str, value: object) -> None:
    data = {**BASE, "bearing": {**BASE["bearing"], key: value}}
    try:
        parse_case(data, "fuzz.toml")
    except CaseError as exc:
        assert exc.file == "fuzz.toml"
        assert exc.key.startswith("bearing."), exc
        assert exc.message
    else:
        raise AssertionError(f"bearing.{key} = {value!r} was accepted")


@settings(max_examples=60, deadline=None)
@given(
    elements=st.one_of(st.integers(max_value=2), st.floats(allow_nan=False), st.text(max_size=3))
)
def test_bad_number_of_elements_is_refused(elements: object) -> None:
    data = {**BASE, "bearing": {**BASE["bearing"], "elements": elements}}
    try:
        parse_case(data, "fuzz.toml")
    except CaseError as exc:
        assert exc.key == "bearing.elements", exc
    else:
        raise AssertionError(f"elements = {elements!r} was accepted")


@settings(max_examples=40, deadline=None)
@given(key=st.text(alphabet="abcdefghijklmnopqrstuvwxyz_", min_size=1, max_size=12))
def test_unknown_keys_are_refused(key: str) -> None:
    if key in BASE["bearing"] or key in {
        "type",
        "contact_angle",
        "inner_groove_radius",
        "outer_groove_radius",
        "inner_raceway_diameter",
        "outer_raceway_diameter",
        "roller_length",
    }:
        return
    data = {**BASE, "bearing": {**BASE["bearing"], key: 1.0}}
    try:
        parse_case(data, "fuzz.toml")
    except CaseError as exc:
        assert exc.key == f"bearing.{key}"
        assert exc.message.startswith("unknown key")
    else:
        raise AssertionError(f"unknown key {key!r} was accepted")
