"""The numba cache-directory probe: writable or not, and it leaves nothing behind."""

from __future__ import annotations

from pathlib import Path

from runout.base._numba_cache import _writable


def test_writable_directory_is_created_and_left_clean(tmp_path: Path) -> None:
    target = tmp_path / "a" / "b"
    assert _writable(target)
    assert target.is_dir() and not list(target.iterdir())


def test_a_file_in_the_way_is_not_writable(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert not _writable(blocker)
    assert not _writable(blocker / "below")
