"""Studies that cannot lose or mix data, through the real command line.

Each test here reproduces one finding of the data-safety issue: the output lock, the per-chunk
study digest checked on resume, corrupted manifests and chunks, what ``--out`` may point to,
``run --out`` and an existing ``case.toml``, failed samples, workers outliving a killed parent
and sweep-dynamic point names. Concurrency and SIGKILL go through subprocesses (each bounded by
a timeout, every process started here is reaped or killed by its id); the rest goes through
typer's CliRunner on ``runout.cli.commands:app``.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from cases import KIM_TOML
from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
CASE = (
    """
title = "safety test"
"""
    + KIM_TOML
    + """[analysis]
model = "quasi_static_2d"
revolutions = 4
samples = 256
[study]
kind = "montecarlo"
samples = {samples}
seed = {seed}
chunk_size = {chunk}
[study.vary]
element_diameter_sigma = "0.1 um"
"operation.axial_load" = {{ distribution = "normal", std = "2 N" }}
"""
)

runner = CliRunner()
WORKERS_2 = ("--workers", "2", "--out")


def write_case(
    directory: Path, samples: int = 6, chunk: int = 2, seed: int = 3, name: str = "case.toml"
) -> Path:
    path = directory / name
    path.write_text(CASE.format(samples=samples, chunk=chunk, seed=seed), encoding="utf-8")
    return path


def dynamic_case(directory: Path) -> Path:
    """The seed 003 rotor, shortened to 4 revolutions of 512 samples (about a second a point)."""
    text = (ROOT / "examples" / "seed003_purohit.toml").read_text(encoding="utf-8")
    text = text.replace("revolutions = 50", "revolutions = 4").replace(
        "samples = 8192", "samples = 512"
    )
    path = directory / "dyn.toml"
    path.write_text(text, encoding="utf-8")
    return path


def invoke(*args: str) -> Any:
    return runner.invoke(app, list(args))


def tree(directory: Path) -> dict[str, bytes]:
    return {
        str(p.relative_to(directory)): p.read_bytes()
        for p in sorted(directory.rglob("*"))
        if p.is_file()
    }


def one_line_error(result: Any, code: int = 2) -> str:
    """The stderr of a refused command: exit ``code``, one line, no traceback."""
    assert result.exit_code == code, (result.exit_code, result.stdout, result.stderr)
    assert isinstance(result.exception, SystemExit), repr(result.exception)
    err = result.stderr
    assert "Traceback" not in err and len(err.splitlines()) == 1, err  # no blank line either
    return err.strip()


def popen(*args: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "runout.cli", *args],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )


@pytest.fixture
def procs() -> Iterator[list[subprocess.Popen[str]]]:
    """Processes started by a test: killed by their id and reaped if the test did not."""
    started: list[subprocess.Popen[str]] = []
    yield started
    for proc in started:
        if proc.poll() is None:
            proc.kill()
        proc.wait(timeout=30)
        if proc.stderr is not None:
            proc.stderr.close()


def wait_for(condition: Any, timeout: float, what: str) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return
        time.sleep(0.02)
    raise AssertionError(f"timed out waiting for {what}")


# ------------------------------------------------------------------ lock
def test_second_writer_is_refused_while_the_first_runs(
    tmp_path: Path, procs: list[subprocess.Popen[str]]
) -> None:
    case = write_case(tmp_path, samples=120, chunk=4)
    shared, fresh = tmp_path / "shared", tmp_path / "fresh"
    first = popen("study", str(case), "--out", str(shared))
    procs.append(first)
    manifest = shared / "manifest.json"

    def started() -> bool:
        try:
            return len(json.loads(manifest.read_text())["done"]) >= 1
        except (OSError, ValueError, KeyError):
            return False

    wait_for(started, 60, "the first study to write a chunk")
    assert first.poll() is None, "the first study ended before the second could start"
    second = subprocess.run(
        [sys.executable, "-m", "runout.cli", "study", str(case), "--out", str(shared)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert second.returncode == 2, second.stderr
    err = second.stderr
    assert "Traceback" not in err and len(err.splitlines()) == 1, err
    assert f"another runout study is writing to {shared} (pid {first.pid})" in err
    _, first_err = first.communicate(timeout=120)
    assert first.returncode == 0, first_err
    # the first study's files are exactly those of a run that was never disturbed
    assert invoke("study", str(case), "--out", str(fresh)).exit_code == 0
    assert tree(shared) == tree(fresh)


def test_three_writers_at_once_never_crash_or_mix(
    tmp_path: Path, procs: list[subprocess.Popen[str]]
) -> None:
    case = write_case(tmp_path, samples=40, chunk=2)
    shared, fresh = tmp_path / "shared", tmp_path / "fresh"
    started = [popen("study", str(case), "--out", str(shared)) for _ in range(3)]
    procs.extend(started)
    errs = [p.communicate(timeout=120)[1] for p in started]
    codes = [p.returncode for p in started]
    assert set(codes) <= {0, 2} and 0 in codes, (codes, errs)
    for code, err in zip(codes, errs, strict=True):
        assert "Traceback" not in err, err
        if code == 2:
            assert "another runout study is writing to" in err, err
    assert invoke("study", str(case), "--out", str(fresh)).exit_code == 0
    assert tree(shared) == tree(fresh)


def test_sweep_dynamic_refuses_a_locked_directory(tmp_path: Path) -> None:
    from runout.study.run import output_lock

    out = tmp_path / "sweep"
    out.mkdir()
    with output_lock(out):
        err = one_line_error(
            invoke("sweep-dynamic", str(dynamic_case(tmp_path)), "--out", str(out))
        )
    assert f"another runout study is writing to {out} (pid {os.getpid()})" in err
    assert not (out / "points").exists()


# ------------------------------------------------------------------ digests and resume
def test_swapped_chunk_from_another_study_is_recomputed(tmp_path: Path) -> None:
    mine, other, fresh = tmp_path / "mine", tmp_path / "other", tmp_path / "fresh"
    case = write_case(tmp_path)
    assert invoke("study", str(case), "--out", str(mine)).exit_code == 0
    assert invoke("study", str(case), "--out", str(fresh)).exit_code == 0
    other_case = write_case(tmp_path, seed=4, name="other.toml")
    assert invoke("study", str(other_case), "--out", str(other)).exit_code == 0
    shutil.copy(other / "chunks" / "chunk_00001.json", mine / "chunks" / "chunk_00001.json")
    result = invoke("study", str(case), "--out", str(mine), "--resume", "--json")
    assert result.exit_code == 0, result.stderr
    assert "recomputing 1 chunk" in result.stderr and "chunk_00001.json" in result.stderr
    assert tree(mine) == tree(fresh)
    chunk = json.loads((mine / "chunks" / "chunk_00000.json").read_text())
    assert chunk["digest"] == json.loads((mine / "manifest.json").read_text())["digest"]


def test_resume_takes_the_chunks_the_manifest_has_not_listed_yet(tmp_path: Path) -> None:
    """The manifest is rewritten at most once a second: after a kill it may lag the chunk
    files; a resume takes every valid chunk on disk, recomputes none, and ends the same."""
    out, fresh = tmp_path / "out", tmp_path / "fresh"
    case = write_case(tmp_path)
    assert invoke("study", str(case), "--out", str(out)).exit_code == 0
    assert invoke("study", str(case), "--out", str(fresh)).exit_code == 0
    manifest = _manifest(out)
    (out / "manifest.json").write_text(json.dumps({**manifest, "done": [0], "complete": False}))
    (out / "summary.json").unlink()
    stamps = {p.name: p.stat().st_mtime_ns for p in (out / "chunks").iterdir()}
    result = invoke("study", str(case), "--out", str(out), "--resume")
    assert result.exit_code == 0, (result.stderr, result.exception)
    assert "recomputing" not in result.stderr
    assert {p.name: p.stat().st_mtime_ns for p in (out / "chunks").iterdir()} == stamps
    assert tree(out) == tree(fresh)


def test_a_chunk_size_chosen_from_the_cost_gives_the_same_numbers(tmp_path: Path) -> None:
    """Without ``chunk_size`` the study chooses it from the estimated cost of a sample (at
    least four chunks per thread or worker here); its numbers are those of any chunk size, and
    a resume with another worker count continues with the size the run chose."""
    from runout.case import estimates
    from runout.case.model import load_case

    given = write_case(tmp_path, samples=48, chunk=5, name="given.toml")
    text = given.read_text().replace("chunk_size = 5\n", "")
    chosen = tmp_path / "chosen.toml"
    chosen.write_text(text)
    assert invoke("study", str(given), "--out", str(tmp_path / "a")).exit_code == 0
    result = invoke("study", str(chosen), "--out", str(tmp_path / "b"))
    assert result.exit_code == 0, (result.stderr, result.exception)
    size = _manifest(tmp_path / "b")["chunk_size"]
    threads = estimates.study_threads() if estimates.batched_study(load_case(chosen)) else 1
    assert size == estimates.study_chunk_size(load_case(chosen), threads)
    assert 1 <= size <= -(-48 // (estimates.CHUNKS_PER_WORKER * threads))
    summary = "summary.json"
    assert (tmp_path / "a" / summary).read_bytes() == (tmp_path / "b" / summary).read_bytes()
    manifest = _manifest(tmp_path / "b")
    (tmp_path / "b" / "manifest.json").write_text(
        json.dumps({**manifest, "done": [0], "complete": False})
    )
    for extra in sorted((tmp_path / "b" / "chunks").iterdir())[1:]:
        extra.unlink()
    again = invoke("study", str(chosen), "--out", str(tmp_path / "b"), "--resume", "--workers", "2")
    assert again.exit_code == 0, (again.stderr, again.exception)
    assert _manifest(tmp_path / "b")["chunk_size"] == size
    assert (tmp_path / "a" / summary).read_bytes() == (tmp_path / "b" / summary).read_bytes()


def test_chosen_chunk_sizes_follow_the_cost_within_their_bounds() -> None:
    """About CHUNK_SECONDS of estimated work per chunk, CHUNKS_PER_WORKER chunks per worker
    at least, MAX_CHOSEN_CHUNK samples at most: each bound binds in one of these cases."""
    import tomllib

    from runout.case import estimates
    from runout.case.model import parse_case

    def case(samples: int, instants: int, batched: bool = False) -> Any:
        text = CASE.format(samples=samples, chunk=1, seed=1).replace("chunk_size = 1\n", "")
        if batched:  # the ball sizes alone: the batched Monte Carlo (microseconds a bearing)
            text = text.replace(text[text.index('"operation.axial_load"') :], "")
        text = text.replace("samples = 256", f"samples = {instants}")
        budget = 'max_time = "1000 h"\n'  # estimated, never run
        text = text.replace("revolutions = 4\n", "revolutions = 4\n" + budget)
        return parse_case(tomllib.loads(text), "case.toml")

    def expected(c: Any, workers: int) -> tuple[int, int, int]:
        per = estimates.study_point_seconds(c)
        points = estimates.study_points(c)
        return (
            math.ceil(estimates.CHUNK_SECONDS / per),
            math.ceil(points / (estimates.CHUNKS_PER_WORKER * workers)),
            estimates.MAX_CHOSEN_CHUNK,
        )

    for samples, instants, batched, workers, binding in (
        (40, 4096, False, 2, 1),  # few samples: four chunks per worker
        (100_000, 16, True, 1, 2),  # cheap samples: the largest chunk
        (100_000, 256, False, 1, 0),  # costly samples: a quarter second of work
    ):
        c = case(samples, instants, batched)
        assert estimates.batched_study(c) == batched
        bounds = expected(c, workers)
        assert estimates.study_chunk_size(c, workers) == min(bounds) == bounds[binding], bounds
    assert estimates.study_chunk_size(case(40, 4096), 16) == 1


def test_manifest_is_not_rewritten_after_every_chunk(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Rewriting the growing list of done chunks after each chunk is quadratic in the number
    of chunks: written at the start, at most once a second, and at the end."""
    import runout.study.run as study_run

    writes: list[str] = []
    real = study_run._write_text

    def counting(path: Path, text: str) -> Path:
        writes.append(path.name)
        return real(path, text)

    monkeypatch.setattr(study_run, "_write_text", counting)
    monkeypatch.setattr(study_run, "MANIFEST_INTERVAL_S", 3600.0)
    case = write_case(tmp_path, samples=40, chunk=1)
    result = invoke("study", str(case), "--out", str(tmp_path / "out"))
    assert result.exit_code == 0, (result.stderr, result.exception)
    assert writes.count("manifest.json") == 2  # the start and the end
    manifest = _manifest(tmp_path / "out")
    assert manifest["done"] == list(range(40)) and manifest["complete"] is True


@pytest.mark.parametrize(
    "content",
    [
        '{"chunk": 1, "start": 2, "st',  # truncated
        "[1, 2]",  # not an object
        '{"chunk": 1, "start": 2, "stop": 4, "runout": 5}',  # wrong types
        "",  # empty file
    ],
    ids=["truncated", "list", "wrong-types", "empty"],
)
def test_corrupt_chunk_is_recomputed_and_said(tmp_path: Path, content: str) -> None:
    out, fresh = tmp_path / "out", tmp_path / "fresh"
    case = write_case(tmp_path)
    assert invoke("study", str(case), "--out", str(out)).exit_code == 0
    assert invoke("study", str(case), "--out", str(fresh)).exit_code == 0
    (out / "chunks" / "chunk_00001.json").write_text(content)
    result = invoke("study", str(case), "--out", str(out), "--resume")
    assert result.exit_code == 0, (result.stderr, result.exception)
    assert "recomputing 1 chunk" in result.stderr
    assert tree(out) == tree(fresh)


def _manifest(out: Path) -> dict[str, Any]:
    return dict(json.loads((out / "manifest.json").read_text()))


@pytest.mark.parametrize(
    "corrupt",
    [
        lambda m: json.dumps(m)[:40],  # truncated JSON
        lambda m: "[]",
        lambda m: json.dumps({**m, "done": 5}),
        lambda m: json.dumps({**m, "done": ["x"]}),
        lambda m: json.dumps({**m, "done": [99]}),
        lambda m: json.dumps({**m, "chunks": "three"}),
        lambda m: json.dumps({k: v for k, v in m.items() if k != "digest"}),
    ],
    ids=["truncated", "list", "done-int", "done-str", "done-range", "chunks-str", "no-digest"],
)
def test_corrupt_manifest_is_one_line_or_recomputed_with_force(
    tmp_path: Path, corrupt: Any
) -> None:
    out, fresh = tmp_path / "out", tmp_path / "fresh"
    case = write_case(tmp_path)
    assert invoke("study", str(case), "--out", str(out)).exit_code == 0
    assert invoke("study", str(case), "--out", str(fresh)).exit_code == 0
    (out / "manifest.json").write_text(corrupt(_manifest(out)))
    for extra in (["--resume"], []):
        err = one_line_error(invoke("study", str(case), "--out", str(out), *extra))
        assert str(out / "manifest.json") in err and "--force" in err
    result = invoke("study", str(case), "--out", str(out), "--resume", "--force")
    assert result.exit_code == 0, (result.stderr, result.exception)
    assert "manifest.json" in result.stderr  # says it started afresh
    assert tree(out) == tree(fresh)


# ------------------------------------------------------------------ what --out may be
def test_empty_out_is_refused_and_touches_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    case = write_case(tmp_path)
    dyn = dynamic_case(tmp_path)
    work = tmp_path / "work"
    (work / "chunks").mkdir(parents=True)
    (work / "chunks" / "chunk_00099.json").write_text("mine")
    monkeypatch.chdir(work)
    for args in (
        ["study", str(case), "--out", ""],
        ["sweep-dynamic", str(dyn), "--out", ""],
        ["run", str(case), "--out", ""],
        ["study", str(case), "--out", "  "],
    ):
        err = one_line_error(invoke(*args))
        assert "--out" in err and "empty" in err, err
    assert sorted(p.name for p in work.rglob("*")) == ["chunk_00099.json", "chunks"]


def _targets(tmp_path: Path) -> list[Path]:
    a_file = tmp_path / "a_file"
    a_file.write_text("user data")
    targets = [a_file, Path("/dev/null"), a_file / "sub"]
    if os.geteuid() != 0:  # root writes anywhere: a read-only directory stops only others
        locked = tmp_path / "locked"
        locked.mkdir()
        locked.chmod(0o555)
        targets += [locked / "sub", locked]
    if Path("/proc").is_dir():
        targets.append(Path("/proc/runout-test-out"))
    return targets


@pytest.mark.parametrize("command", ["study", "sweep-dynamic", "run"])
def test_out_that_is_not_a_writable_directory_is_one_line(tmp_path: Path, command: str) -> None:
    case = dynamic_case(tmp_path) if command == "sweep-dynamic" else write_case(tmp_path)
    try:
        for target in _targets(tmp_path):
            err = one_line_error(invoke(command, str(case), "--out", str(target)))
            assert str(target) in err, err
        assert (tmp_path / "a_file").read_text() == "user data"
    finally:
        if (tmp_path / "locked").exists():
            (tmp_path / "locked").chmod(0o755)


@pytest.mark.parametrize("command", ["study", "sweep-dynamic"])
def test_unwritable_directory_is_one_line_even_for_root(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, command: str
) -> None:
    # root writes into a read-only directory: make the file system refuse the way it refuses
    # everyone else, at the first file the command creates there
    case = dynamic_case(tmp_path) if command == "sweep-dynamic" else write_case(tmp_path)
    target = tmp_path / "readonly"
    target.mkdir()
    real_open = os.open

    def refusing_open(path: Any, flags: int, *args: Any, **kwargs: Any) -> int:
        if str(path).startswith(str(target)) and flags & os.O_CREAT:
            raise PermissionError(13, "Permission denied", str(path))
        return real_open(path, flags, *args, **kwargs)

    monkeypatch.setattr(os, "open", refusing_open)
    err = one_line_error(invoke(command, str(case), "--out", str(target)))
    assert f"{target / '.lock'}: cannot create the lock file (Permission denied)" in err


def test_foreign_directory_is_refused_unless_force(tmp_path: Path) -> None:
    case = write_case(tmp_path)
    foreign = tmp_path / "mine"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("my notes")
    (foreign / "summary.json").write_text("my summary")
    err = one_line_error(invoke("study", str(case), "--out", str(foreign)))
    assert str(foreign) in err and "--force" in err
    assert sorted(p.name for p in foreign.iterdir()) == ["notes.txt", "summary.json"]
    assert (foreign / "summary.json").read_text() == "my summary"
    # even --force never replaces a file of the user's that shares a study's name (issue 30)
    err = one_line_error(invoke("study", str(case), "--out", str(foreign), "--force"))
    assert str(foreign / "summary.json") in err
    assert (foreign / "summary.json").read_text() == "my summary"
    (foreign / "summary.json").rename(tmp_path / "my_summary.json")
    result = invoke("study", str(case), "--out", str(foreign), "--force")
    assert result.exit_code == 0, result.stderr
    assert (foreign / "notes.txt").read_text() == "my notes"  # --force replaces only our files
    # a study's own directory is reused without --force (a new run replaces the old one)
    assert invoke("study", str(case), "--out", str(foreign)).exit_code == 0
    # an output of another kind is foreign too
    sweep_dir = tmp_path / "sweep"
    (sweep_dir / "points").mkdir(parents=True)
    (sweep_dir / "sweep.csv").write_text("elements\n")
    one_line_error(invoke("study", str(case), "--out", str(sweep_dir)))
    err = one_line_error(
        invoke("sweep-dynamic", str(dynamic_case(tmp_path)), "--out", str(foreign))
    )
    assert str(foreign) in err and "--force" in err


def test_run_never_overwrites_another_case_toml(tmp_path: Path) -> None:
    case = write_case(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    (out / "case.toml").write_text("# the user's other case\n")
    # a directory of the user's (issue 30: not runout's, so refused before case.toml is read)
    err = one_line_error(invoke("run", str(case), "--out", str(out)))
    assert str(out) in err and "--force" in err
    # even --force never replaces a case.toml runout did not write
    err = one_line_error(invoke("run", str(case), "--out", str(out), "--force"))
    assert str(out / "case.toml") in err
    assert (out / "case.toml").read_text() == "# the user's other case\n"
    assert sorted(p.name for p in out.iterdir()) == ["case.toml"]  # nothing else written
    # runout's own directory: the same case again is rewritten in place
    own = tmp_path / "own"
    assert invoke("run", str(case), "--out", str(own)).exit_code == 0
    assert invoke("run", str(case), "--out", str(own)).exit_code == 0
    # its case.toml now another case: refused, --force replaces runout's files
    (own / "case.toml").write_text("# stale\n")
    err = one_line_error(invoke("run", str(case), "--out", str(own)))
    assert str(own / "case.toml") in err and "--force" in err
    result = invoke("run", str(case), "--out", str(own), "--force")
    assert result.exit_code == 0, result.stderr
    assert (own / "case.toml").read_text() == case.read_text()


# ------------------------------------------------------------------ failures
def _failing_run_model(monkeypatch: pytest.MonkeyPatch, fails: Any) -> None:
    import runout.runner

    real = runout.runner.run_model

    def run_model(case: Any) -> Any:
        if fails(case):
            raise ValueError("bad point, on purpose")
        return real(case)

    monkeypatch.setattr(runout.runner, "run_model", run_model)


def test_one_failed_sample_is_recorded_and_the_study_continues(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    case = write_case(tmp_path)
    seen: list[float] = []

    def third(c: Any) -> bool:
        seen.append(c.operation.axial_load)
        return len(seen) == 3  # the third sample evaluated (sample 2)

    _failing_run_model(monkeypatch, third)
    out = tmp_path / "out"
    result = invoke("study", str(case), "--out", str(out), "--json")
    assert result.exit_code == 0, (result.stderr, result.exception)
    payload = json.loads(result.stdout)
    assert payload["samples"] == 6 and payload["failed"] == 1
    assert payload["errors"] == [{"sample": 2, "error": "ValueError: bad point, on purpose"}]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["failed"] == 1 and summary["errors"] == payload["errors"]
    assert "1 of 6 samples failed" in result.stderr
    # readable output says it too
    seen.clear()
    result = invoke("study", str(case))
    assert result.exit_code == 0 and "1 of 6 samples failed" in result.stderr


def test_all_failed_exits_1(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _failing_run_model(monkeypatch, lambda c: True)
    out = tmp_path / "out"
    result = invoke("study", str(write_case(tmp_path)), "--json", "--out", str(out))
    assert result.exit_code == 1, (result.stderr, result.exception)
    assert json.loads(result.stdout)["failed"] == 6
    assert "all 6 samples failed" in result.stderr and "Traceback" not in result.stderr
    assert json.loads((out / "summary.json").read_text())["failed"] == 6  # still written


def test_files_are_identical_for_any_worker_count(tmp_path: Path) -> None:
    case = write_case(tmp_path, samples=8, chunk=2)
    one, two = tmp_path / "one", tmp_path / "two"
    assert invoke("study", str(case), "--out", str(one)).exit_code == 0
    done = subprocess.run(
        [sys.executable, "-m", "runout.cli", "study", str(case), *WORKERS_2, str(two)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    assert tree(one) == tree(two)


def test_keyboard_interrupt_still_stops(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import runout.runner

    def interrupted(case: Any) -> Any:
        raise KeyboardInterrupt

    monkeypatch.setattr(runout.runner, "run_model", interrupted)
    result = invoke("study", str(write_case(tmp_path)), "--out", str(tmp_path / "out"))
    assert result.exit_code == 130 and "interrupted" in result.stderr
    assert not (tmp_path / "out" / ".lock").exists()  # released on the way out


# ------------------------------------------------------------------ workers and their parent
def _children(pid: int) -> set[int]:
    found = set()
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            fields = stat.rsplit(")", 1)[1].split()
            if int(fields[1]) == pid:
                found.add(int(entry.name))
    return found


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state not in ("Z", "X")  # a zombie has exited: only its parent's record is left


@pytest.mark.skipif(
    not Path("/proc/self/stat").exists(),
    reason="reads worker PIDs from /proc (Linux); the watchdog fallback is tested apart",
)
def test_workers_die_with_a_killed_parent(
    tmp_path: Path, procs: list[subprocess.Popen[str]]
) -> None:
    case = write_case(tmp_path, samples=4000, chunk=4)
    # stderr to /dev/null: orphaned workers would hold a pipe open after their parent is gone
    parent = subprocess.Popen(
        [sys.executable, "-m", "runout.cli", "study", str(case), *WORKERS_2, str(tmp_path / "out")],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    procs.append(parent)  # type: ignore[arg-type]
    workers: set[int] = set()

    def two_workers_busy() -> bool:
        nonlocal workers
        assert parent.poll() is None, "the study ended before it could be killed"
        workers = _children(parent.pid)
        done = tmp_path / "out" / "chunks" / "chunk_00001.json"
        return len(workers) >= 2 and done.exists()

    wait_for(two_workers_busy, 90, "two workers to finish a chunk")
    try:
        os.kill(parent.pid, signal.SIGKILL)
        parent.wait(timeout=30)
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline and any(_alive(p) for p in workers):
            time.sleep(0.05)
        survivors = [p for p in workers if _alive(p)]
        assert not survivors, f"workers {survivors} outlived their killed parent"
    finally:
        for pid in workers:  # only the processes this test started
            if _alive(pid):
                os.kill(pid, signal.SIGKILL)


# ------------------------------------------------------------------ sweep-dynamic points
def test_sweep_dynamic_close_preloads_do_not_share_a_result(tmp_path: Path) -> None:
    out = tmp_path / "sweep"
    dyn = dynamic_case(tmp_path)
    result = invoke(
        "sweep-dynamic", str(dyn), "--preload", "10.0000001,10.0000002", "--out", str(out), "--json"
    )
    assert result.exit_code == 0, (result.stderr, result.exception)
    points = json.loads(result.stdout)["points"]
    assert [p["preload_n"] for p in points] == [10.0000001, 10.0000002]
    assert len(list((out / "points").glob("*.json"))) == 2
    # a rerun reuses each point as it was, and a corrupt one is recomputed (and said)
    files = sorted((out / "points").glob("*.json"))
    files[0].write_text("[1, 2]")
    again = invoke(
        "sweep-dynamic", str(dyn), "--preload", "10.0000001,10.0000002", "--out", str(out), "--json"
    )
    assert again.exit_code == 0, (again.stderr, again.exception)
    assert json.loads(again.stdout)["points"] == points
    assert "recomputed 1 point" in again.stderr


def test_sweep_dynamic_point_failure_is_one_line_and_keeps_finished_points(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import runout.models.dynamic as dynamic

    real = dynamic.run

    def run(case: Any, progress: Any = None) -> Any:
        if case.operation.axial_load == 20.0:
            raise ValueError("bad point, on purpose")
        return real(case, progress)

    monkeypatch.setattr(dynamic, "run", run)
    out = tmp_path / "sweep"
    args = ["sweep-dynamic", str(dynamic_case(tmp_path)), "--preload", "10,20", "--out", str(out)]
    err = one_line_error(invoke(*args))
    assert "preload=20.0 N" in err and "ValueError: bad point, on purpose" in err
    assert [p.name for p in (out / "points").iterdir()] == ["Z9_P10N.json"]
    assert not (out / ".lock").exists()
