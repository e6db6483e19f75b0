"""The committed case-file reference is the one the schema generates."""

from __future__ import annotations

from pathlib import Path

from runout.case.schema_doc import case_file_reference

DOC = Path(__file__).resolve().parents[3] / "docs" / "case-file.md"


def test_case_file_reference_is_current() -> None:
    # Regenerate with: python -m runout.case.schema_doc > docs/case-file.md
    assert DOC.read_text(encoding="utf-8") == case_file_reference()


def test_every_table_documents_every_key() -> None:
    text = case_file_reference()
    for key in ("element_diameter", "radial_clearance", "peak_to_peak", "exponent", "revolutions"):
        assert f"| `{key}` |" in text
