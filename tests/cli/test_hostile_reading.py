"""Hostile files runout reads back, through the real command line, under memory and time limits.

The companion of :mod:`test_hostile_inputs` (hostile case files) for what runout reads that
someone may have tampered with: a run directory (``runout report``), a study directory
(``runout study --resume``), a measured record (``runout diagnose``) and a case's profile
files. Every file of ``tests/hostile/reading/`` is one finding of a review; its header says
what it did, what the test builds and what must happen now::

    # hostile: what the review found
    # run: report                 report | resume | diagnose | check
    # base: run                   run (a run directory, run/), study (case.toml and out/),
    #                             record (case.toml and record.csv), profile (case.toml)
    # setup: symlink case.toml /etc/passwd     what is done to the base (see _tamper)
    # expect: 2 case.toml         exit 2, one stderr line "error: DIR/case.toml: ..."
    # expect: 2 result.json runout    ... "error: run/result.json: runout..."
    # expect: 0                   exit 0, no error line
    # stderr: recomputing 1 chunk text stderr must hold
    # not-in-stderr: root:        text that must never be printed (another file's contents)
    # not-in-page: root:x:        text the written report.html must not hold

The file of an error line is named as the command names it: ``run/`` for a report, ``out/``
for a study's files, nothing for the case and the record.
"""

from __future__ import annotations

import json
import math
import os
import re
import resource
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from cases import KIM_TOML

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "hostile" / "reading"
#: Address space of one command [bytes] (as for the hostile case files).
MEMORY_LIMIT = 3 * 2**30
#: Seconds one command may take.
TIMEOUT = 120.0
#: Where each kind of command names the files it reads.
PREFIX = {"report": "run/", "resume": "out/", "diagnose": "", "check": ""}

STUDY_CASE = (
    'title = "hostile resume"\n'
    + KIM_TOML
    + """[analysis]
model = "quasi_static_2d"
revolutions = 4
samples = 256
[study]
kind = "montecarlo"
samples = 6
seed = 3
chunk_size = 2
[study.vary]
element_diameter_sigma = "0.1 um"
"""
)

PROFILE_CASE = """[bearing]
type = "ball"
elements = 7
element_diameter = "3.9688 mm"
pitch_diameter = "15 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "10 um"
[operation]
rotating_ring = "inner"
speed = "1800 rpm"
axial_load = "20 N"
[[profile]]
part = "inner"
file = "loop_a.csv"
orders = [1, 5]
"""


@dataclass(frozen=True)
class Spec:
    """The header of one corpus file."""

    path: Path
    command: str
    base: str
    setup: tuple[str, ...]
    status: int
    file: str | None
    key: str | None
    stderr: tuple[str, ...]
    hidden: tuple[str, ...]
    hidden_in_page: tuple[str, ...]


def _parse(path: Path) -> Spec:
    meta: dict[str, list[str]] = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        match = re.match(r"#\s*([a-z-]+):\s*(.*)$", line)
        if match:
            meta.setdefault(match.group(1), []).append(match.group(2).strip())
    expect = meta["expect"][0].split(maxsplit=2)
    return Spec(
        path=path,
        command=meta["run"][0],
        base=meta["base"][0],
        setup=tuple(meta.get("setup", [])),
        status=int(expect[0]),
        file=expect[1] if len(expect) > 1 else None,
        key=expect[2] if len(expect) > 2 else None,
        stderr=tuple(meta.get("stderr", [])),
        hidden=tuple(meta.get("not-in-stderr", [])),
        hidden_in_page=tuple(meta.get("not-in-page", [])),
    )


SPECS = {p.stem: _parse(p) for p in sorted(CORPUS.glob("*.hostile"))}


def _limit() -> None:  # pragma: no cover - runs in the child
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def _cli(cwd: Path, *args: str) -> dict[str, Any]:
    env = {**os.environ, "PYTHONWARNINGS": ""}
    env.pop("RUNOUT_DEBUG", None)
    try:
        done = subprocess.run(
            [sys.executable, "-m", "runout.cli", *args],
            capture_output=True,
            text=True,
            timeout=TIMEOUT,
            preexec_fn=_limit,
            env=env,
            cwd=cwd,
        )
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "stdout": "", "stderr": ""}
    return {"status": done.returncode, "stdout": done.stdout, "stderr": done.stderr}


def _record_text(rate_rev_per_s: float | None = None) -> str:
    """A record of 2000 samples at 4 kHz: a 30 Hz whirl of 0.1 um (the case turns at 30 Hz)."""
    fs = 4000.0
    header = "time_s,x_m,y_m" + (",rev" if rate_rev_per_s is not None else "")
    rows = []
    for k in range(2000):
        t = k / fs
        row = f"{t!r},{1e-7 * math.sin(60 * math.pi * t)!r},{1e-7 * math.cos(60 * math.pi * t)!r}"
        if rate_rev_per_s is not None:
            row += f",{rate_rev_per_s * t!r}"
        rows.append(row)
    return header + "\n" + "\n".join(rows) + "\n"


def _set(doc: Any, key: str, value: Any) -> None:
    *head, last = key.split(".")
    for part in head:
        doc = doc[part]
    doc[last] = value


def _tamper(directory: Path, directive: str) -> None:
    """Apply one ``# setup:`` line to an entry's directory."""
    kind, name, *rest = directive.split(maxsplit=2 if directive.startswith("replace") else -1)
    if kind == "replace":  # replace FILE KEY JSON (NaN allowed)
        key, value = rest[0].split(maxsplit=1)
        rest = [key, value]
    target = directory / name
    if kind == "symlink":
        target.unlink(missing_ok=True)
        target.symlink_to(rest[0])
    elif kind == "fifo":
        target.unlink(missing_ok=True)
        os.mkfifo(target)
    elif kind == "sparse":
        with target.open("wb") as handle:
            handle.truncate(int(rest[0]))
    elif kind == "text":
        target.write_text(" ".join(rest) + "\n", encoding="utf-8")
    elif kind == "nested":
        depth = int(rest[0])
        target.write_text('{"model": "linear", "a": ' + "[" * depth + "]" * depth + "}")
    elif kind == "array":
        target.write_text('{"model": "linear", "a": [' + ",".join(["0"] * int(rest[0])) + "]}")
    elif kind == "replace":
        doc = json.loads(target.read_text(encoding="utf-8"))
        _set(doc, rest[0], json.loads(rest[1]))
        target.write_text(json.dumps(doc), encoding="utf-8")
    elif kind == "bigint":
        doc = json.loads(target.read_text(encoding="utf-8"))
        _set(doc, rest[0], "@BIG@")
        text = json.dumps(doc).replace('"@BIG@"', "9" * int(rest[1]))
        target.write_text(text, encoding="utf-8")
    elif kind == "blank":
        target.write_text("\n" * int(rest[0]) + target.read_text(encoding="utf-8"))
    elif kind == "header":
        lines = target.read_text(encoding="utf-8").splitlines(keepends=True)
        target.write_text(rest[0] + "\n" + "".join(lines[1:]), encoding="utf-8")
    elif kind == "field":  # the first field of line 5 replaced by a long word
        lines = target.read_text(encoding="utf-8").splitlines(keepends=True)
        lines[4] = "A" * int(rest[0]) + lines[4][lines[4].index(",") :]
        target.write_text("".join(lines), encoding="utf-8")
    elif kind == "tacho":
        target.write_text(_record_text(float(rest[0])), encoding="utf-8")
    else:  # pragma: no cover - a typo in the corpus
        raise ValueError(directive)


def _command(spec: Spec, directory: Path) -> list[str]:
    if spec.command == "report":
        return ["report", "run"]
    if spec.command == "resume":
        return ["study", "case.toml", "--out", "out", "--resume"]
    if spec.command == "diagnose":
        return ["diagnose", "case.toml", "--record", "record.csv", "--json"]
    return ["check", "case.toml"]


def _build(spec: Spec, directory: Path, run_dir: Path) -> None:
    directory.mkdir()
    if spec.base == "run":
        shutil.copytree(run_dir, directory / "run", symlinks=True)
    elif spec.base == "study":
        (directory / "case.toml").write_text(STUDY_CASE, encoding="utf-8")
        done = _cli(directory, "study", "case.toml", "--out", "out")
        assert done["status"] == 0, done["stderr"]
    elif spec.base == "record":
        shutil.copy(ROOT / "examples" / "seed002_608.toml", directory / "case.toml")
        (directory / "record.csv").write_text(_record_text(), encoding="utf-8")
    elif spec.base == "profile":
        (directory / "case.toml").write_text(PROFILE_CASE, encoding="utf-8")
    else:  # pragma: no cover - a typo in the corpus
        raise ValueError(spec.base)
    # a setup line names the file as the error line does, without the prefix
    where = directory / PREFIX[spec.command]
    for directive in spec.setup:
        _tamper(where, directive)


@pytest.fixture(scope="session")
def outcomes(tmp_path_factory: pytest.TempPathFactory) -> dict[str, dict[str, Any]]:
    root = tmp_path_factory.mktemp("hostile-reading")
    made = _cli(root, "run", str(ROOT / "examples" / "seed002_608.toml"), "--out", "base-run")
    assert made["status"] == 0, made["stderr"]

    def one(name: str) -> dict[str, Any]:
        spec = SPECS[name]
        directory = root / name
        _build(spec, directory, root / "base-run")
        got = _cli(directory, *_command(spec, directory))
        page = directory / "run" / "report.html"
        got["page"] = page.read_text(encoding="utf-8") if page.is_file() else ""
        return got

    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = {name: pool.submit(one, name) for name in SPECS}
        return {name: job.result() for name, job in jobs.items()}


@pytest.mark.parametrize("name", list(SPECS))
def test_hostile_file(outcomes: dict[str, dict[str, Any]], name: str) -> None:
    spec = SPECS[name]
    got = outcomes[name]
    stderr = got["stderr"]
    assert got["status"] != "timeout", f"{name}: did not end in {TIMEOUT} s"
    assert "Traceback" not in stderr, stderr[-2000:]
    for text in spec.hidden:
        assert text not in stderr + got["stdout"], f"{name}: printed {text!r}"
    for text in spec.hidden_in_page:
        assert text not in got["page"], f"{name}: the page holds {text!r}"
    for text in spec.stderr:
        assert text in stderr, f"{name}: stderr lacks {text!r}:\n{stderr}"
    if spec.status == 2:
        assert got["status"] == 2, (got["status"], stderr[-2000:])
        lines = stderr.splitlines()
        assert len(lines) == 1, f"{name}: stderr is not one line:\n{stderr}"
        where = f"error: {PREFIX[spec.command]}{spec.file}: "
        if spec.key is not None:
            where += spec.key
        assert lines[0].startswith(where), lines[0]
        return
    assert got["status"] == 0, (got["status"], stderr[-2000:])
    assert not any(line.startswith("error:") for line in stderr.splitlines()), stderr


def test_the_corpus_covers_every_reader() -> None:
    assert {s.command for s in SPECS.values()} == {"report", "resume", "diagnose", "check"}
    assert sum(s.status == 0 for s in SPECS.values()) >= 3
