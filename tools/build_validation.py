"""Join the validation fragments (docs/_fragments/validation_*.md) into VALIDATION.md."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ORDER = ["kinematics", "contact", "spectrum", "linear", "roller"]


def build() -> str:
    """The full VALIDATION.md text."""
    head = (ROOT / "docs" / "_fragments" / "validation_head.md").read_text(encoding="utf-8")
    parts = [head.rstrip() + "\n"]
    fragments = sorted((ROOT / "docs" / "_fragments").glob("validation_*.md"))
    names = [p.stem.removeprefix("validation_") for p in fragments if p.stem != "validation_head"]
    names.sort(key=lambda n: (ORDER.index(n) if n in ORDER else len(ORDER), n))
    for name in names:
        text = (ROOT / "docs" / "_fragments" / f"validation_{name}.md").read_text(encoding="utf-8")
        parts.append("\n" + text.rstrip() + "\n")
    return "".join(parts)


if __name__ == "__main__":
    (ROOT / "VALIDATION.md").write_text(build(), encoding="utf-8")
