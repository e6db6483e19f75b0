"""Hostile output directories through the real command line: runout writes only what is its own.

Every file of ``tests/hostile/outputs/`` is a case file from the review of what ``--out`` (and
``runout report DIR``) may write: through symbolic links, over the user's files, into ``/``.
Its header says what it did and what must happen now; the lines run in order::

    # hostile: what the review found
    # setup: file NAME TEXT          a file of the user's (NAME relative to the test directory)
    # setup: dir NAME                a directory
    # setup: symlink NAME TARGET     a symbolic link
    # setup: record NAME             a measured record for diagnose (synthetic, of the case)
    # before: ARGS                   a command that must succeed (CASE: this file)
    # env: NAME=VALUE                environment of the commands (a relative path made absolute)
    # run: ARGS                      the command under test
    # expect: 2 TEXT                 exit 2, one stderr line "error: ..." containing TEXT
    # expect: 0                      exit 0
    # unchanged: NAMES               files (or links) whose bytes (or target) must not change
    # absent: NAMES                  files that must not be written

Each command is a subprocess (``python -m runout.cli``) in the test's own directory. After the
command no temporary or staging file of runout's may be left anywhere in that directory.

The full disk and the read-only directory are environments rather than case files: they are
made in-process (typer's CliRunner), by a file system call that fails as the kernel would.
"""

from __future__ import annotations

import errno
import io
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

from runout.cli.commands import app

CORPUS = Path(__file__).resolve().parents[1] / "hostile" / "outputs"
ENTRIES = sorted(CORPUS.glob("*.toml"))
TIMEOUT = 300.0
#: What runout leaves only while it writes: ``.<name>.<hex>.tmp`` and ``.runout-*.tmp``.
LEFTOVER = re.compile(r"^\..+\.tmp$")


def _directives(path: Path) -> list[tuple[str, str]]:
    found = []
    for line in path.read_text(encoding="utf-8").splitlines():
        match = re.match(r"#\s*([a-z]+):\s*(.*)$", line)
        if match:
            found.append((match.group(1), match.group(2).strip()))
    return found


def _setup(directory: Path, case: Path, text: str) -> None:
    kind, name, *rest = text.split(maxsplit=2)
    target = directory / name
    target.parent.mkdir(parents=True, exist_ok=True)
    if kind == "file":
        target.write_text(" ".join(rest) + "\n", encoding="utf-8")
    elif kind == "dir":
        target.mkdir(exist_ok=True)
    elif kind == "symlink":
        if target.exists() or target.is_symlink():
            target.unlink()
        target.symlink_to(rest[0])
    elif kind == "record":
        from runout.case.model import load_case
        from runout.validation._diagnosis_checks import done_when_truth, synthetic_record

        rec, _, _ = synthetic_record(
            load_case(case), done_when_truth(7), samples=8000, sample_rate=4000.0, seed=1
        )
        rows = np.column_stack([rec.time, rec.channels["x"] * 1e6, rec.channels["y"] * 1e6])
        lines = ["t [s],x [um],y [um]"] + [",".join(repr(float(v)) for v in r) for r in rows]
        target.write_text("\n".join(lines) + "\n", encoding="utf-8")
    else:  # pragma: no cover - a typo in the corpus
        raise ValueError(text)


def _state(path: Path) -> Any:
    if path.is_symlink():
        return ("link", os.readlink(path))
    return ("file", path.read_bytes()) if path.is_file() else None


def _command(directory: Path, args: str, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    argv = [a.replace("CASE", "case.toml") if a == "CASE" else a for a in args.split()]
    return subprocess.run(
        [sys.executable, "-m", "runout.cli", *argv],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        env=env,
        cwd=directory,
    )


@pytest.mark.parametrize("entry", ENTRIES, ids=[p.stem for p in ENTRIES])
def test_hostile_output(entry: Path, tmp_path: Path) -> None:
    case = tmp_path / "case.toml"
    shutil.copy(entry, case)
    env = {**os.environ, "PYTHONWARNINGS": ""}
    env.pop("RUNOUT_DEBUG", None)
    directives = _directives(entry)
    for kind, text in directives:  # the setup, in order, then the command under test
        if kind == "setup":
            _setup(tmp_path, case, text)
        elif kind == "env":
            key, value = text.split("=", 1)
            env[key] = value if value.startswith("/") else str(tmp_path / value)
        elif kind == "before":
            before = _command(tmp_path, text, env)
            assert before.returncode == 0, (text, before.stderr[-2000:])
    given = {kind: text for kind, text in directives if kind in ("run", "expect", "unchanged")}
    watched = {name: _state(tmp_path / name) for name in given.get("unchanged", "").split()}
    done = _command(tmp_path, given["run"], env)
    expect = given["expect"]
    status, _, message = expect.partition(" ")
    assert "Traceback" not in done.stderr, done.stderr[-2000:]
    assert done.returncode == int(status), (done.returncode, done.stderr[-2000:])
    if int(status) == 2:
        lines = done.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("error: "), done.stderr
        assert message in lines[0], lines[0]
    for name, state in watched.items():
        assert _state(tmp_path / name) == state, f"{name} changed"
    for kind, text in directives:
        if kind == "absent":
            for name in text.split():
                assert not (tmp_path / name).exists(), f"{name} was written"
    leftovers = [p for p in tmp_path.rglob(".*") if LEFTOVER.match(p.name)]
    assert not leftovers, leftovers


def test_the_corpus_has_refusals_and_successes() -> None:
    statuses = [text.split()[0] for e in ENTRIES for k, text in _directives(e) if k == "expect"]
    assert len(statuses) == len(ENTRIES) >= 10
    assert statuses.count("0") >= 2 and statuses.count("2") >= 8


# --------------------------------------------------------------------------------------------
# environments rather than case files
# --------------------------------------------------------------------------------------------
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed002_608.toml"
runner = CliRunner()


def _refuse_writes_under(directory: Path, code: int, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every call that would create or write a file or directory under ``directory`` fails
    with ``code``, as a read-only file system (EROFS) or a full disk (ENOSPC) makes it."""
    root = str(directory.resolve())
    strerror = os.strerror(code)

    def under(path: Any) -> bool:
        try:
            return os.path.realpath(os.fspath(path)).startswith(root)
        except TypeError:  # a file descriptor
            return False

    real_open, real_os_open, real_mkdir = io.open, os.open, os.mkdir

    def fake_open(file: Any, mode: str = "r", *args: Any, **kwargs: Any) -> Any:
        if any(c in mode for c in "wax+") and under(file):
            raise OSError(code, strerror, os.fspath(file))
        return real_open(file, mode, *args, **kwargs)

    def fake_os_open(path: Any, flags: int, *args: Any, **kwargs: Any) -> int:
        if flags & (os.O_WRONLY | os.O_RDWR | os.O_CREAT) and under(path):
            raise OSError(code, strerror, os.fspath(path))
        return real_os_open(path, flags, *args, **kwargs)

    def fake_mkdir(path: Any, *args: Any, **kwargs: Any) -> None:
        if under(path) and os.path.realpath(os.fspath(path)) != root:
            raise OSError(code, strerror, os.fspath(path))
        return real_mkdir(path, *args, **kwargs)

    monkeypatch.setattr(io, "open", fake_open)
    monkeypatch.setattr("builtins.open", fake_open)
    monkeypatch.setattr(os, "open", fake_os_open)
    monkeypatch.setattr(os, "mkdir", fake_mkdir)
    if code == errno.EROFS:
        real_access = os.access
        monkeypatch.setattr(
            os, "access", lambda p, m, **k: not (under(p) and m & os.W_OK) and real_access(p, m)
        )


def test_report_into_a_read_only_directory_is_a_named_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # `runout report DIR` on a read-only DIR ended with exit 70 ("internal error ... bug")
    out = tmp_path / "out"
    assert runner.invoke(app, ["run", str(EXAMPLE), "--out", str(out)]).exit_code == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    _refuse_writes_under(out, errno.EROFS, monkeypatch)
    result = runner.invoke(app, ["report", str(out)])
    monkeypatch.undo()
    assert result.exit_code == 2, (result.exit_code, result.stderr)
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and str(out) in lines[0], result.stderr
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before


def test_a_full_disk_leaves_no_truncated_figure(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # a full disk while the figures were saved left a truncated PNG under its final name
    import matplotlib.figure

    out = tmp_path / "out"
    real_savefig = matplotlib.figure.Figure.savefig

    def savefig_disk_full(self: Any, fname: Any, *args: Any, **kwargs: Any) -> None:
        target = fname if hasattr(fname, "write") else open(fname, "wb")
        target.write(b"\x89PNG\r\n\x1a\n half a figure")  # what fitted on the disk
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), getattr(fname, "name", fname))

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", savefig_disk_full)
    result = runner.invoke(app, ["run", str(EXAMPLE), "--out", str(out)])
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", real_savefig)
    assert result.exit_code == 2, (result.exit_code, result.stderr)
    assert len(result.stderr.splitlines()) == 1 and "No space left" in result.stderr
    # nothing half-written under a final name: the directory holds what it held (nothing)
    assert sorted(p.name for p in out.iterdir()) == [], sorted(out.iterdir())


def test_a_full_disk_leaves_no_truncated_study_histograms(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the finding: a study on a full disk left a truncated histograms.png
    import matplotlib.figure

    case = tmp_path / "case.toml"
    shutil.copy(CORPUS / "study_forced_deletes_users_summary.toml", case)
    out = tmp_path / "out"

    def savefig_disk_full(self: Any, fname: Any, *args: Any, **kwargs: Any) -> None:
        target = fname if hasattr(fname, "write") else open(fname, "wb")
        target.write(b"\x89PNG\r\n\x1a\n half a figure")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), getattr(fname, "name", fname))

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", savefig_disk_full)
    result = runner.invoke(app, ["study", str(case), "--out", str(out)])
    monkeypatch.undo()
    assert result.exit_code == 2, (result.exit_code, result.stderr, result.exception)
    assert len(result.stderr.splitlines()) == 1 and "histograms.png" in result.stderr
    assert not (out / "histograms.png").exists()
    assert not [p for p in out.rglob(".*") if LEFTOVER.match(p.name)]
