"""The README and "Which model when" list every model this version provides (issue 29, item 7c).

Both failed before the fix: the README's model table left out ``spindle`` and the page said
"six models" and listed a shaft on two bearings among what no model represents.
"""

from __future__ import annotations

import re
from pathlib import Path

from runout.models import MODEL_MODULES

ROOT = Path(__file__).resolve().parents[2]
NUMBER_WORDS = {5: "Five", 6: "Six", 7: "Seven", 8: "Eight", 9: "Nine", 10: "Ten"}


def _table_models(text: str) -> set[str]:
    """Model ids in the first column of the markdown tables of ``text``."""
    return set(re.findall(r"^\| `([a-z_0-9]+)`", text, flags=re.MULTILINE))


def test_readme_model_table_names_every_model() -> None:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert set(MODEL_MODULES) <= _table_models(text)


def test_which_model_page_names_and_counts_every_model() -> None:
    text = (ROOT / "docs" / "which-model.md").read_text(encoding="utf-8")
    assert set(MODEL_MODULES) <= _table_models(text)
    assert f"{NUMBER_WORDS[len(MODEL_MODULES)]} models read the same case file" in text
    none = text.split("## What none of them represents", 1)[1]
    # the spindle model carries a shaft on two or more bearings
    assert "shaft carried by two bearings" not in none
