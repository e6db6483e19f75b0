"""runout.base.reading: the bounds refuse nothing runout writes and everything beyond them."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.base.reading import (
    MAX_JSON_DEPTH,
    MAX_JSON_INT_DIGITS,
    InputFileError,
    check_shape,
    parse_json,
    read_bytes,
)

#: JSON documents as runout writes them: finite numbers, bounded integers, shallow nesting.
documents = st.recursive(
    st.none()
    | st.booleans()
    | st.integers(-(10**20), 10**20)
    | st.floats(allow_nan=False, allow_infinity=False)
    | st.text(max_size=20),
    lambda children: (
        st.lists(children, max_size=5) | st.dictionaries(st.text(max_size=10), children, max_size=5)
    ),
    max_leaves=40,
)


@settings(max_examples=200, deadline=None)
@given(doc=documents)
def test_a_document_within_the_bounds_reads_as_json_reads_it(doc: object) -> None:
    text = json.dumps(doc)
    assert parse_json(text, "f.json") == json.loads(text)


@settings(max_examples=50, deadline=None)
@given(depth=st.integers(MAX_JSON_DEPTH + 1, 20 * MAX_JSON_DEPTH), kind=st.sampled_from("[{"))
def test_nesting_beyond_the_bound_is_refused_naming_the_file(depth: int, kind: str) -> None:
    text = "[" * depth + "]" * depth if kind == "[" else '{"a":' * depth + "1" + "}" * depth
    with pytest.raises(InputFileError, match="nested deeper") as info:
        parse_json(text, "f.json")
    assert info.value.file == "f.json"


@given(digits=st.integers(MAX_JSON_INT_DIGITS + 1, 10_000))
@settings(max_examples=20, deadline=None)
def test_an_integer_beyond_the_bound_is_refused(digits: int) -> None:
    with pytest.raises(InputFileError, match="integer of"):
        parse_json('{"a": [' + "7" * digits + "]}", "f.json")


@pytest.mark.parametrize("constant", ["NaN", "Infinity", "-Infinity"])
def test_a_number_that_is_not_finite_is_refused_naming_its_key(constant: str) -> None:
    with pytest.raises(InputFileError) as info:
        parse_json('{"runout": {"radial_pp_m": ' + constant + "}}", "r.json")
    assert info.value.key == "runout.radial_pp_m"
    assert not math.isfinite(float(constant))


def test_the_first_value_of_another_shape_is_named() -> None:
    shape = {"components": [{"pp_m": "number"}], "runout": {"radial_pp_m": "number"}}
    with pytest.raises(InputFileError) as info:
        check_shape({"components": [{"pp_m": 1.0}, "x", 3]}, shape, "r.json")
    assert info.value.key == "components[1]"
    check_shape({"components": None, "runout": {"radial_pp_m": None}, "new": "free"}, shape, "r")


def test_a_link_out_of_the_directory_and_a_loop_are_refused(tmp_path: Path) -> None:
    inside = tmp_path / "dir"
    inside.mkdir()
    (tmp_path / "secret").write_text("secret")
    (inside / "out.json").symlink_to(tmp_path / "secret")
    (inside / "loop.json").symlink_to("loop.json")
    (inside / "ok.json").write_text("{}")
    (inside / "link.json").symlink_to("ok.json")
    with pytest.raises(InputFileError, match="outside"):
        read_bytes(inside / "out.json", 100, [inside])
    with pytest.raises(InputFileError, match="loop"):
        read_bytes(inside / "loop.json", 100, [inside])
    assert read_bytes(inside / "link.json", 100, [inside]) == b"{}"  # a link inside is fine
    with pytest.raises(InputFileError, match="larger than"):
        read_bytes(inside / "ok.json", 1, [inside])


def test_null_in_an_array_of_objects_is_refused_naming_it() -> None:
    """A run directory's result.json with ``"components": [null, ...]`` crashed `runout report`
    (found by tests/property/test_reading_fuzz.py); a null number stays allowed."""
    shape = {"components": [{"pp_m": "number"}], "values": ["number"]}
    check_shape({"components": [{"pp_m": None}], "values": [1.0, None]}, shape, "result.json")
    with pytest.raises(InputFileError) as info:
        check_shape({"components": [{"pp_m": 1.0}, None]}, shape, "result.json")
    assert "components[1]" in str(info.value) and "found null" in str(info.value)
