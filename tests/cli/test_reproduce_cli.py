"""`runout reproduce`: writes the document, --check detects a stale one (exit 1)."""

from __future__ import annotations

from pathlib import Path

from typer.testing import CliRunner

from runout.cli.commands import app

runner = CliRunner()


def test_reproduce_writes_and_checks(tmp_path: Path) -> None:
    out = tmp_path / "V.md"
    res = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert "checks:" in res.output and "agree" in res.output
    text = out.read_text(encoding="utf-8")
    assert "### Kinematics" in text and "| 3.41198 |" in text
    ok = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(out), "--check"])
    assert ok.exit_code == 0, ok.output
    # another CPU: ours in its last printed digit (a value at a rounding boundary)
    out.write_text(text.replace("| 3.41198 | 3.41198 |", "| 3.41198 | 3.41199 |"), "utf-8")
    moved = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(out), "--check"])
    assert moved.exit_code == 0, moved.output
    out.write_text(text.replace("| 3.41198 | 3.41198 |", "| 3.41198 | 3.41298 |"), "utf-8")
    stale = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(out), "--check"])
    assert stale.exit_code == 1


def test_reproduce_unknown_section_is_a_clean_error(tmp_path: Path) -> None:
    res = runner.invoke(app, ["reproduce", "--only", "nope", "--out", str(tmp_path / "V.md")])
    assert res.exit_code == 2


def test_only_help_names_every_section() -> None:
    from runout.validation import section_keys

    # the --only help is written by hand: it must name every section a user can pick
    shown = runner.invoke(app, ["reproduce", "--help"], terminal_width=200)
    assert shown.exit_code == 0
    for key in section_keys():
        assert key in shown.output, key


def test_reproduce_never_overwrites_a_file_it_did_not_write(tmp_path: Path) -> None:
    out = tmp_path / "VALIDATION.md"
    out.write_text("my own notes\n", encoding="utf-8")
    res = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(out)])
    assert res.exit_code == 2, res.output
    assert len(res.output.strip().splitlines()) == 1, res.output
    assert str(out) in res.output and "not written by runout" in res.output
    assert out.read_text(encoding="utf-8") == "my own notes\n"


def test_reproduce_does_not_write_through_a_link(tmp_path: Path) -> None:
    target = tmp_path / "elsewhere.md"
    target.write_text("kept\n", encoding="utf-8")
    link = tmp_path / "V.md"
    link.symlink_to(target)
    res = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(link)])
    assert res.exit_code == 2, res.output
    assert "link" in res.output
    assert target.read_text(encoding="utf-8") == "kept\n"


def test_only_some_sections_replace_those_sections_of_the_document(tmp_path: Path) -> None:
    # the project's own document: rewriting one section leaves the others as they were, and
    # a section that has not changed comes back identical
    shipped = Path(__file__).resolve().parents[2] / "VALIDATION.md"
    out = tmp_path / "VALIDATION.md"
    text = shipped.read_text(encoding="utf-8")
    out.write_text(text, encoding="utf-8")
    res = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(out)])
    assert res.exit_code == 0, res.output
    after = out.read_text(encoding="utf-8")
    assert after.count("### ") == text.count("### ")
    assert after.index("### Dynamic model") > after.index("### Kinematics")
    ok = runner.invoke(app, ["reproduce", "--only", "kinematics", "--out", str(out), "--check"])
    assert ok.exit_code == 0, ok.output
    from runout.validation.compare import compare

    assert compare(after, text) == []  # the same document, to the check's tolerance
