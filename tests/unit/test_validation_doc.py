"""VALIDATION.md is the join of its fragments (so it cannot drift from them)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_validation_md_is_built_from_fragments() -> None:
    spec = importlib.util.spec_from_file_location(
        "build_validation", ROOT / "tools" / "build_validation.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    # Rebuild with: python tools/build_validation.py
    assert (ROOT / "VALIDATION.md").read_text(encoding="utf-8") == module.build()
