"""The example case files shipped in the package are the repository's ``examples/``.

``examples/*.toml`` (what the README and docs point to) and ``runout/examples/data/*.toml``
(package data: what an installed runout validates and reproduces with) are the same files.
Editing one alone once gave the seed 003 examples a position preload in ``examples/`` while
the package's copies, which VALIDATION.md is reproduced from, kept the old default.
"""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def test_the_package_ships_the_examples_byte_for_byte() -> None:
    repo = {p.name: p.read_bytes() for p in sorted((ROOT / "examples").glob("*.toml"))}
    data = ROOT / "src" / "runout" / "examples" / "data"
    shipped = {p.name: p.read_bytes() for p in sorted(data.glob("*.toml"))}
    assert sorted(shipped) == sorted(repo)
    differ = [name for name in repo if shipped[name] != repo[name]]
    assert differ == [], f"examples/ and runout/examples/data/ differ: {differ}"
