"""Hypothesis: tampered result directories, study chunks and records end cleanly.

The companion of :mod:`test_case_fuzz` for the files runout reads back. A run directory's
``result.json`` and ``summary.json`` (``runout report``), a study's chunk files and manifest
(``runout study --resume``) and a measured record (``runout diagnose``) are tampered with: a
value replaced by one of another kind, a number that is not finite, a huge integer, deep
nesting, bytes cut or flipped, blank lines, odd header names, a fast tachometer. Every command
must end with exit status 0 or 2, one ``error:`` line naming a file of the directory (or the
record), no traceback, within a bounded time.
"""

from __future__ import annotations

import json
import math
import shutil
import time
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from cases import KIM_TOML
from runout.cli.commands import app

ROOT = Path(__file__).resolve().parents[2]
runner = CliRunner()
#: Seconds one tampered example may take (a report of the seed 002 run takes about one).
BOUND_S = 30.0

#: Values put in place of one value of a JSON document (``"@..."`` are written raw).
HOSTILE_VALUES = st.one_of(
    st.sampled_from(
        [
            "a string",
            "",
            [],
            {},
            [1, "x", None],
            {"a": 1},
            True,
            None,
            -1,
            0,
            1e308,
            -1e-308,
            "@NaN",
            "@Infinity",
            "@-Infinity",
            "@" + "9" * 5000,
            "@" + "[" * 3000 + "]" * 3000,
        ]
    ),
    st.integers(),
    st.floats(allow_nan=False, allow_infinity=False),
    st.text(max_size=30),
)


def _paths(doc: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every path to a value of ``doc`` (the first 5 items of each array)."""
    out = [prefix]
    if isinstance(doc, dict):
        for key, value in doc.items():
            out += _paths(value, (*prefix, key))
    elif isinstance(doc, list):
        for i, value in enumerate(doc[:5]):
            out += _paths(value, (*prefix, i))
    return out


def _replaced(doc: Any, path: tuple[Any, ...], value: Any) -> str:
    """``doc`` as JSON text with the value at ``path`` replaced (raw text for ``"@..."``)."""
    marker = "@@REPLACED@@"
    if not path:
        doc = marker
    else:
        target = doc
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = marker
    raw = value[1:] if isinstance(value, str) and value.startswith("@") else json.dumps(value)
    return json.dumps(doc).replace(json.dumps(marker), raw, 1)


@st.composite
def tampered_json(draw: st.DrawFn, original: str) -> str:
    """``original`` (a JSON text) with one value replaced, cut short, or bytes changed."""
    how = draw(st.sampled_from(["replace", "replace", "replace", "cut", "flip"]))
    if how == "cut":
        return original[: draw(st.integers(0, len(original) - 1))]
    if how == "flip":
        at = draw(st.integers(0, len(original) - 1))
        return (
            original[:at]
            + draw(st.sampled_from(["{", "]", '"', "\\", "\x00", "é"]))
            + original[at + 1 :]
        )
    doc = json.loads(original)
    path = draw(st.sampled_from(_paths(doc)))
    return _replaced(doc, path, draw(HOSTILE_VALUES))


def _check(result: Any, names: tuple[str, ...], elapsed: float) -> None:
    """Exit 0 or 2, one error line naming one of ``names``, no traceback, bounded time."""
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(
        result.exception
    )
    assert result.exit_code in (0, 2), (result.exit_code, result.stderr[-2000:])
    assert "Traceback" not in result.stderr + result.stdout
    lines = result.stderr.splitlines()
    if result.exit_code == 2:
        assert len(lines) == 1, f"not one line:\n{result.stderr}"
        assert lines[0].startswith(tuple(f"error: {n}" for n in names)), lines[0]
    else:
        assert not any(line.startswith("error:") for line in lines), result.stderr
    assert elapsed < BOUND_S, f"one example took {elapsed:.1f} s"


# --------------------------------------------------------------------------------------------
# a run directory: runout report
# --------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def run_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("fuzz-run") / "run"
    done = runner.invoke(
        app, ["run", str(ROOT / "examples" / "seed002_608.toml"), "--out", str(out)]
    )
    assert done.exit_code == 0, done.stderr
    return out


RUN_FILES = ("result.json", "summary.json")


@settings(
    max_examples=100, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(data=st.data(), name=st.sampled_from(RUN_FILES))
def test_tampered_run_directory_reports_or_is_refused(
    run_dir: Path, tmp_path_factory: pytest.TempPathFactory, data: st.DataObject, name: str
) -> None:
    directory = tmp_path_factory.mktemp("tampered") / "run"
    shutil.copytree(run_dir, directory)
    original = (run_dir / name).read_text(encoding="utf-8")
    (directory / name).write_text(data.draw(tampered_json(original)), encoding="utf-8")
    start = time.perf_counter()
    result = runner.invoke(app, ["report", str(directory)])
    _check(result, (f"{directory}/",), time.perf_counter() - start)


# --------------------------------------------------------------------------------------------
# a study directory: runout study --resume
# --------------------------------------------------------------------------------------------
STUDY_CASE = (
    'title = "fuzz resume"\n'
    + KIM_TOML
    + """[analysis]
model = "quasi_static_2d"
revolutions = 4
samples = 256
[study]
kind = "montecarlo"
samples = 4
seed = 3
chunk_size = 2
[study.vary]
element_diameter_sigma = "0.1 um"
"""
)


@pytest.fixture(scope="module")
def study_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("fuzz-study")
    (root / "case.toml").write_text(STUDY_CASE, encoding="utf-8")
    done = runner.invoke(app, ["study", str(root / "case.toml"), "--out", str(root / "out")])
    assert done.exit_code == 0, done.stderr
    return root


@settings(
    max_examples=30, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(data=st.data(), name=st.sampled_from(["chunks/chunk_00001.json", "manifest.json"]))
def test_tampered_study_resumes_or_is_refused(
    study_dir: Path, tmp_path_factory: pytest.TempPathFactory, data: st.DataObject, name: str
) -> None:
    # in place, in the study's own directory (a chunk's digest holds its case's directory)
    out = study_dir / "out"
    kept = (out / name).read_text(encoding="utf-8")
    try:
        (out / name).write_text(data.draw(tampered_json(kept)), encoding="utf-8")
        start = time.perf_counter()
        result = runner.invoke(
            app, ["study", str(study_dir / "case.toml"), "--out", str(out), "--resume"]
        )
        # a file of the directory, or the directory (a manifest of another study), or the
        # manifest of an earlier sampling version ("--resume: DIR/manifest.json: ...")
        prefixes = (f"{out}/", f"--resume: {out} ", f"--resume: {out}/manifest.json: ")
        _check(result, prefixes, time.perf_counter() - start)
    finally:
        (out / name).write_text(kept, encoding="utf-8")


def test_a_chunk_with_a_figure_its_model_does_not_give_resumes(study_dir: Path) -> None:
    """Found by the fuzz above: a chunk whose planar samples carry an axial p-p (one number
    among the lot's NaN) crashed the histograms ("Too many bins", exit 70). The samples without
    a value are not binned, and the panel says how many."""
    out = study_dir / "out"
    name = "chunks/chunk_00001.json"
    kept = (out / name).read_text(encoding="utf-8")
    try:
        doc = json.loads(kept)
        doc["runout"]["axial_pp_m"] = [281474976710656.0, None]
        (out / name).write_text(json.dumps(doc), encoding="utf-8")
        start = time.perf_counter()
        result = runner.invoke(
            app, ["study", str(study_dir / "case.toml"), "--out", str(out), "--resume"]
        )
        _check(result, (f"{out}/",), time.perf_counter() - start)
        assert result.exit_code == 0
    finally:
        (out / name).write_text(kept, encoding="utf-8")


# --------------------------------------------------------------------------------------------
# a measured record: runout diagnose
# --------------------------------------------------------------------------------------------
def _record_lines(rate: float | None) -> list[str]:
    fs = 4000.0
    rows = []
    for k in range(1000):
        t = k / fs
        row = f"{t!r},{1e-7 * math.sin(60 * math.pi * t)!r},{1e-7 * math.cos(60 * math.pi * t)!r}"
        rows.append(row + (f",{rate * t!r}" if rate is not None else ""))
    return rows


@st.composite
def records(draw: st.DrawFn) -> str:
    rate = draw(st.one_of(st.none(), st.sampled_from([30.0, 1e3, 1e6, 1e11, 1e300, -5.0])))
    names = ["time_s", "x_m", "y_m"] + (["rev"] if rate is not None else [])
    if draw(st.booleans()):
        at = draw(st.integers(0, len(names) - 1))
        names[at] = draw(
            st.one_of(
                st.text(max_size=40),
                st.sampled_from(["x [um]", "t [ms]", "x [parsec]", "rev [2]", "root:x:0:0", "x_m"]),
            )
        )
    lines = [",".join(names), *_record_lines(rate)]
    for _ in range(draw(st.integers(0, 3))):
        at = draw(st.integers(0, len(lines) - 1))
        lines[at] = draw(
            st.one_of(
                st.just(""),
                st.text(max_size=50),
                st.sampled_from(["nan,0,0", "1e400,1,1", ",,", "A" * 5000 + ",0,0"]),
            )
        )
    blank = "\n" * draw(st.integers(0, 2))
    return blank + "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def record_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fuzz-record")


@settings(max_examples=100, deadline=None)
@given(text=records())
def test_tampered_records_diagnose_or_are_refused(record_dir: Path, text: str) -> None:
    path = record_dir / "record.csv"
    path.write_text(text, encoding="utf-8")
    case = ROOT / "examples" / "seed002_608.toml"
    start = time.perf_counter()
    result = runner.invoke(app, ["diagnose", str(case), "--record", str(path), "--json"])
    # the record, or the case when the record's content contradicts it (its speed)
    _check(result, (f"{path}: ", f"{case}: "), time.perf_counter() - start)


@pytest.mark.parametrize(
    ("key", "value"), [("element_diameter_m", 1e308), ("pitch_diameter_m", -0.015)]
)
def test_summary_with_an_impossible_bearing_size_is_refused(
    run_dir: Path, tmp_path: Path, key: str, value: float
) -> None:
    # found by the fuzz test above in CI: 1e308 m shown in mm overflowed to infinity (exit 70)
    directory = tmp_path / "run"
    shutil.copytree(run_dir, directory)
    summary = json.loads((directory / "summary.json").read_text(encoding="utf-8"))
    summary["bearing"][key] = value
    (directory / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
    result = runner.invoke(app, ["report", str(directory)])
    assert result.exit_code == 2, result.stderr
    (line,) = result.stderr.strip().splitlines()
    assert f"bearing.{key}" in line and "summary.json" in line
