"""Hostile inputs through the real command line, under memory and time limits.

Every file of ``tests/hostile/`` is a case file from an adversarial review (about 820 inputs;
14 ended in tracebacks, 9 hung or exhausted memory, some printed NaN with exit 0). Its header
says what it did and what must happen now::

    # hostile: what the review found
    # run: check run              commands to run (run is `run --json`)
    # expect: 2 analysis.samples  exit 2, one stderr line "error: FILE: analysis.samples: ..."
    # expect: 0                   exit 0, finite JSON (run) or "is valid" (check)
    # expect: 2 -                 exit 2, one line naming the file (no key: a file-level error)
    # setup: fifo fifo.csv        a file the test makes (fifo, symlink, sparse, random, text)
    # env: RUNOUT_MAX_TIME=15 s   environment of the commands
    # warning: operation.axial_load   a warning naming that key (check's line, run's notes)
    # not-in-stderr: root:        text that must never be printed (file contents)

Each command is a subprocess of the installed package (``python -m runout.cli``) with its
address space limited to :data:`MEMORY_LIMIT` (``RLIMIT_AS``) and a :data:`TIMEOUT`: a hang or
an allocation beyond the budget fails the test instead of the machine. The commands run two
at a time (the machine has two cores) once per session; each test then checks one result.
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

CORPUS = Path(__file__).resolve().parents[1] / "hostile"
#: Address space of one command [bytes]: the default memory budget (2 GiB of arrays) and
#: Python, NumPy and numba besides.
MEMORY_LIMIT = 3 * 2**30
#: Seconds one command may take (the default time budget is 2 min of estimated computing;
#: the corpus's long runs lower it with RUNOUT_MAX_TIME).
TIMEOUT = 120.0


@dataclass(frozen=True)
class Spec:
    """The header of one corpus file."""

    path: Path
    commands: tuple[str, ...]
    status: int
    key: str | None
    env: dict[str, str]
    setup: tuple[str, ...]
    warning: str | None
    hidden: tuple[str, ...]


def _parse(path: Path) -> Spec:
    meta: dict[str, list[str]] = {}
    for line in path.read_text(encoding="utf-8-sig").splitlines():
        match = re.match(r"#\s*([a-z-]+):\s*(.*)$", line)
        if match:
            meta.setdefault(match.group(1), []).append(match.group(2).strip())
    expect = meta["expect"][0].split(maxsplit=1)
    env = dict(item.split("=", 1) for item in meta.get("env", []))
    return Spec(
        path=path,
        commands=tuple(meta.get("run", ["check"])[0].split()),
        status=int(expect[0]),
        key=None if len(expect) == 1 or expect[1] == "-" else expect[1],
        env=env,
        setup=tuple(meta.get("setup", [])),
        warning=(meta.get("warning") or [None])[0],
        hidden=tuple(meta.get("not-in-stderr", [])),
    )


SPECS = {p.stem: _parse(p) for p in sorted(CORPUS.glob("*.toml"))}
CASES = [(name, cmd) for name, spec in SPECS.items() for cmd in spec.commands]


def _make(directory: Path, directive: str) -> None:
    """Create the special file a corpus entry needs (not stored in the repository)."""
    kind, name, *rest = directive.split()
    target = directory / name
    if kind == "fifo":
        os.mkfifo(target)
    elif kind == "symlink":
        target.symlink_to(rest[0])
    elif kind == "sparse":  # a huge file that takes no disk space
        with target.open("wb") as handle:
            handle.truncate(int(rest[0]))
    elif kind == "random":
        target.write_bytes(os.urandom(int(rest[0])))
    elif kind == "text":  # a profile whose second row carries the given word
        rows = [f"{10 * k},{rest[0] if k == 1 else 0.1 * k}" for k in range(36)]
        target.write_text("angle,deviation\n" + "\n".join(rows) + "\n", encoding="utf-8")
    else:  # pragma: no cover - a typo in the corpus
        raise ValueError(directive)


def _limit() -> None:  # pragma: no cover - runs in the child
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def _command(path: Path, command: str, env: dict[str, str]) -> dict[str, Any]:
    args = [sys.executable, "-m", "runout.cli", command, path.name]
    if command == "run":
        args.append("--json")
    try:
        done = subprocess.run(
            args,
            capture_output=True,
            text=True,
            timeout=TIMEOUT,
            preexec_fn=_limit,
            env=env,
            cwd=path.parent,
        )
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "stdout": "", "stderr": ""}
    return {"status": done.returncode, "stdout": done.stdout, "stderr": done.stderr}


@pytest.fixture(scope="session")
def results(tmp_path_factory: pytest.TempPathFactory) -> dict[tuple[str, str], dict[str, Any]]:
    directory = tmp_path_factory.mktemp("hostile")
    for spec in SPECS.values():
        shutil.copy(spec.path, directory / spec.path.name)
        for directive in spec.setup:
            _make(directory, directive)
    jobs = {}
    with ThreadPoolExecutor(max_workers=2) as pool:
        for name, command in CASES:
            spec = SPECS[name]
            env = {**os.environ, "PYTHONWARNINGS": "", **spec.env}
            env.pop("RUNOUT_DEBUG", None)
            jobs[(name, command)] = pool.submit(_command, directory / spec.path.name, command, env)
        return {case: job.result() for case, job in jobs.items()}


def _finite(value: Any) -> bool:
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(_finite(v) for v in value.values())
    if isinstance(value, list):
        return all(_finite(v) for v in value)
    return True


def _reject_constant(name: str) -> Any:
    raise AssertionError(f"JSON output contains {name}")


@pytest.mark.parametrize(("name", "command"), CASES, ids=[f"{n}-{c}" for n, c in CASES])
def test_hostile_input(results: dict[tuple[str, str], dict[str, Any]], name: str, command: str):
    spec = SPECS[name]
    got = results[(name, command)]
    stderr = got["stderr"]
    assert got["status"] != "timeout", f"{name}: `runout {command}` did not end in {TIMEOUT} s"
    assert "Traceback" not in stderr, stderr[-2000:]
    for text in spec.hidden:
        assert text not in stderr + got["stdout"], f"{name}: printed {text!r}"
    lines = stderr.splitlines()
    if spec.status == 2:
        assert got["status"] == 2, (got["status"], stderr[-2000:], got["stdout"][-500:])
        assert len(lines) == 1, f"{name}: stderr is not one line:\n{stderr}"
        assert lines[0].startswith(f"error: {spec.path.name}: "), lines[0]
        if spec.key is not None:
            assert lines[0].startswith(f"error: {spec.path.name}: {spec.key}"), lines[0]
        return
    assert got["status"] == 0, (got["status"], stderr[-2000:])
    assert all(line.startswith("warning: ") for line in lines), stderr
    assert len(lines) <= 1, stderr
    if command == "run":
        payload = json.loads(got["stdout"], parse_constant=_reject_constant)
        assert _finite(payload), f"{name}: non-finite number in the JSON output"
        if spec.warning is not None:
            assert any(n.startswith(spec.warning) for n in payload["notes"]), payload["notes"]
    else:
        assert "is valid" in got["stdout"]
        if spec.warning is not None:
            assert lines and spec.warning in lines[0], stderr


def test_the_corpus_covers_every_kind_of_finding() -> None:
    # unbounded work, tracebacks, accepted nonsense and messages each have entries
    assert len(SPECS) >= 40
    assert sum(spec.status == 0 for spec in SPECS.values()) >= 4
    assert {"run", "check"} <= {c for _, c in CASES}


# --------------------------------------------------------------------------------------------
# environments rather than case files
# --------------------------------------------------------------------------------------------
def test_a_read_only_install_with_an_unwritable_home_still_runs(tmp_path: Path) -> None:
    # numba refused to define its cached kernels ("cannot cache function ...: no locator
    # available") when neither the package's __pycache__ nor the home cache is writable. As
    # root nothing is read-only, so the package is copied with a *file* where every
    # __pycache__ directory would go, and HOME lies under a file.
    import runout

    install = tmp_path / "site"
    shutil.copytree(
        Path(runout.__file__).parent,
        install / "runout",
        ignore=shutil.ignore_patterns("__pycache__"),
    )
    for directory in [install / "runout", *(install / "runout").rglob("*")]:
        if directory.is_dir():
            (directory / "__pycache__").write_text("not a directory\n")
    blocker = tmp_path / "home-is-a-file"
    blocker.write_text("")
    env = {
        **os.environ,
        "PYTHONPATH": str(install),
        "PYTHONDONTWRITEBYTECODE": "1",
        "HOME": str(blocker / "home"),
        "XDG_CACHE_HOME": str(blocker / "cache"),
        "TMPDIR": str(tmp_path / "tmp"),
    }
    env.pop("NUMBA_CACHE_DIR", None)
    (tmp_path / "tmp").mkdir()
    case = Path(__file__).resolve().parents[2] / "examples" / "seed002_608.toml"
    done = subprocess.run(
        [sys.executable, "-m", "runout.cli", "run", str(case), "--json"],
        capture_output=True,
        text=True,
        timeout=600,
        env=env,
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert "Traceback" not in done.stderr
    assert json.loads(done.stdout)["model"] == "linear"


def test_output_for_scripts_does_not_depend_on_the_terminal_or_the_path(tmp_path: Path) -> None:
    # From a clone at a longer path, rich wrapped the title line at 80 columns and split
    # "is valid" (tests/cli/test_commands.py::test_check_accepts_every_example failed); a
    # narrow COLUMNS did the same to tables that tests read.
    deep = tmp_path.joinpath(*(["a-rather-long-directory-name-for-a-clone"] * 4))
    deep.mkdir(parents=True)
    examples = Path(__file__).resolve().parents[2] / "examples"
    case = deep / "seed003_purohit_clearance.toml"
    shutil.copy(examples / case.name, case)
    outputs = {}
    for columns in ("40", "300"):
        env = {**os.environ, "COLUMNS": columns}
        for command in ("check", "frequencies"):
            done = subprocess.run(
                [sys.executable, "-m", "runout.cli", command, str(case)],
                capture_output=True,
                text=True,
                timeout=300,
                env=env,
            )
            assert done.returncode == 0, done.stderr
            outputs[(command, columns)] = done.stdout
    assert outputs[("check", "40")] == outputs[("check", "300")]
    assert outputs[("frequencies", "40")] == outputs[("frequencies", "300")]
    first = outputs[("check", "40")].splitlines()[0]
    assert first.endswith("is valid.") and str(case) in first


def test_tables_read_by_tests_do_not_depend_on_columns_in_process(tmp_path: Path) -> None:
    # The tests that read tables (test_commands: "is valid", the frequency orders;
    # test_one_language: the equilibrium's "not applied" notes; test_run_linear: the
    # attribution table) ran under CliRunner, whose output rich laid out for COLUMNS or the
    # terminal on stdin: the same command gave other text in another terminal.
    from typer.testing import CliRunner

    from runout.cli.commands import app

    runner = CliRunner()
    examples = Path(__file__).resolve().parents[2] / "examples"
    for name, command in (
        ("seed001_kim_equilibrium.toml", "run"),
        ("seed002_608.toml", "frequencies"),
        ("seed002_608.toml", "check"),
    ):
        texts = {
            columns: runner.invoke(
                app, [command, str(examples / name)], env={"COLUMNS": columns}
            ).stdout
            for columns in ("30", "500")
        }
        assert texts["30"] == texts["500"], (name, command)
