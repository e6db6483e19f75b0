"""Every example's ``runout run --json`` output is unchanged, to the last digits a machine moves.

The stored outputs in ``tests/data/examples_json`` were written by its ``regenerate.py`` on one
machine; a refactor must leave them as they are, and a change of results must rewrite them on
purpose. Another CPU (numba compiles for the host) or other library versions move the last
digits of a float: the comparison is ``tests/golden.py``'s (its docstring states the policy),
and ``tests/unit/test_golden.py`` shows it accepts such moves and refuses a real change.
"""

from __future__ import annotations

import gzip
import json
import sys
from pathlib import Path

import pytest

import golden

ROOT = Path(__file__).resolve().parents[2]
STORED = ROOT / "tests" / "data" / "examples_json"
sys.path.insert(0, str(STORED))
from regenerate import example_json  # noqa: E402

CASES = sorted((ROOT / "examples").glob("*.toml"))


def test_every_example_has_a_stored_output() -> None:
    stored = sorted(p.name.removesuffix(".json.gz") for p in STORED.glob("*.json.gz"))
    assert stored == [case.stem for case in CASES]


@pytest.mark.parametrize("case", CASES, ids=[c.stem for c in CASES])
def test_example_json_is_unchanged(case: Path) -> None:
    new = json.loads(example_json(case))
    old = json.loads(gzip.decompress((STORED / f"{case.stem}.json.gz").read_bytes()))
    golden.assert_same(new, old, f"{case.name}: --json")
