"""Every example's ``runout run --json`` output is unchanged, byte for byte.

The stored outputs in ``tests/data/examples_json`` were written by its ``regenerate.py``; a
refactor must leave them as they are, and a change of results must rewrite them on purpose.
"""

from __future__ import annotations

import gzip
import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
STORED = ROOT / "tests" / "data" / "examples_json"
sys.path.insert(0, str(STORED))
from regenerate import example_json  # noqa: E402

CASES = sorted((ROOT / "examples").glob("*.toml"))


def _first_difference(new: object, old: object, path: str = "$") -> str:
    """The first JSON path where two documents differ, for a readable failure."""
    if type(new) is not type(old):
        return f"{path}: {type(old).__name__} became {type(new).__name__}"
    if isinstance(new, dict) and isinstance(old, dict):
        if list(new) != list(old):
            return f"{path}: keys {list(old)} became {list(new)}"
        for key in new:
            if new[key] != old[key]:
                return _first_difference(new[key], old[key], f"{path}.{key}")
    if isinstance(new, list) and isinstance(old, list):
        if len(new) != len(old):
            return f"{path}: length {len(old)} became {len(new)}"
        for i, (a, b) in enumerate(zip(new, old, strict=True)):
            if a != b:
                return _first_difference(a, b, f"{path}[{i}]")
    return f"{path}: {old!r} became {new!r}"


def test_every_example_has_a_stored_output() -> None:
    stored = sorted(p.name.removesuffix(".json.gz") for p in STORED.glob("*.json.gz"))
    assert stored == [case.stem for case in CASES]


@pytest.mark.parametrize("case", CASES, ids=[c.stem for c in CASES])
def test_example_json_is_unchanged(case: Path) -> None:
    new = example_json(case)
    old = gzip.decompress((STORED / f"{case.stem}.json.gz").read_bytes())
    if new != old:
        pytest.fail(
            f"{case.name}: --json changed at {_first_difference(json.loads(new), json.loads(old))}"
        )
