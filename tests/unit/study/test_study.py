"""Studies (runout.study.run): seeding, batched kernel, chunking independence, sweeps, errors."""

from __future__ import annotations

import json
import math
import os
import signal
import subprocess
import sys
import textwrap
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cases import KIM_TOML, kim_case
from runout.analysis.spectrum import extract_lines
from runout.base.errors import CaseError
from runout.case.model import Case
from runout.models import quasi_static_2d as qs2
from runout.study import _chunks as chunks_mod
from runout.study import _files as files_mod
from runout.study import run as st_mod
from runout.study._kernels import project_rows, solve_batch, solve_batch_reference
from runout.study.dynamic_sweep import exact_number, point_name
from runout.study.run import (
    OutputError,
    StudyError,
    error_text,
    line_label,
    load_study,
    output_directory,
    output_lock,
    refuse_foreign,
    run_study,
    sample_rng,
    statistics,
    write_atomic,
)


def kim(study: dict[str, Any], **extra: Any) -> Case:
    return kim_case(study=study, **extra)


def mc(samples: int = 12, seed: int = 5, **vary: Any) -> Case:
    return kim(
        {
            "kind": "montecarlo",
            "samples": samples,
            "seed": seed,
            "vary": vary or {"element_diameter_sigma": "0.1 um"},
        }
    )


def assert_same(a: st_mod.StudyResult, b: st_mod.StudyResult) -> None:
    assert a.samples == b.samples and a.model == b.model and a.values.keys() == b.values.keys()
    for key in a.values:
        np.testing.assert_array_equal(a.values[key], b.values[key])
    assert a.errors == b.errors
    for k in st_mod.RUNOUT_KEYS:
        np.testing.assert_array_equal(a.runout[k], b.runout[k])
    assert a.lines.keys() == b.lines.keys()
    for key in a.lines:
        assert a.lines[key][0] == b.lines[key][0]
        np.testing.assert_array_equal(a.lines[key][1], b.lines[key][1])


# ------------------------------------------------------------------ seeding
def test_sample_rng_is_the_spawned_child() -> None:
    children = np.random.SeedSequence(42).spawn(6)
    for i in (0, 3, 5):
        a = sample_rng(42, i).standard_normal(4)
        b = np.random.default_rng(children[i]).standard_normal(4)
        np.testing.assert_array_equal(a, b)
    assert not np.array_equal(sample_rng(42, 0).random(3), sample_rng(42, 1).random(3))


# ------------------------------------------------------------------ kernels
def test_batched_kernel_matches_numpy_reference_and_model() -> None:
    case = mc()
    base = kim_case(diameter_errors=[0.0] * 10)
    st_ = qs2.setup(base)
    t = np.arange(64) * (4 / 120.0) / 64
    c, theta = qs2.approaches(base, st_, t)
    offsets = 0.5 * np.random.default_rng(1).normal(0, 1e-7, (3, 10))
    q, unloaded, status, _ = solve_batch(c, offsets, theta, st_.stiffness, st_.initial_approach)
    ref = solve_batch_reference(c, offsets, theta, st_.stiffness, st_.initial_approach)
    assert np.all(status == 0) and unloaded.max() == 0
    np.testing.assert_allclose(q, ref, rtol=0, atol=1e-9 * st_.initial_approach)
    # and the per-bearing public solver of the model, bearing by bearing
    for m in range(3):
        variant = kim_case(diameter_errors=2.0 * offsets[m])
        disp, _ = qs2.solve(variant, t)
        np.testing.assert_allclose(q[m].T, disp[:2], rtol=0, atol=1e-9 * st_.initial_approach)
    serial = solve_batch(c, offsets, theta, st_.stiffness, st_.initial_approach, parallel=False)
    np.testing.assert_array_equal(serial[0], q)
    del case


def test_project_rows_is_the_least_squares_fit() -> None:
    rng = np.random.default_rng(2)
    t = np.arange(300) * 1e-3
    freqs = np.array([7.3, 41.0, 112.5])
    x = rng.normal(size=(5, 300))
    coef = project_rows(x, chunks_mod._line_projector(t, freqs))
    fit = extract_lines(t, x, freqs, axis=-1)
    np.testing.assert_allclose(np.hypot(coef[:, 1:4], coef[:, 4:]), fit.amplitude, rtol=1e-9)
    # fixed summation order: one row alone gives the same bits as inside a batch
    alone = project_rows(x[2:3], chunks_mod._line_projector(t, freqs))
    np.testing.assert_array_equal(alone[0], coef[2])


def test_batched_path_equals_per_bearing_model_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    case = mc(samples=4)
    fast = run_study(case)
    monkeypatch.setattr(chunks_mod, "_batched", lambda task: False)
    slow = run_study(case)
    for k in st_mod.RUNOUT_KEYS:
        np.testing.assert_allclose(fast.runout[k], slow.runout[k], rtol=1e-7, atol=1e-15)
    key = "x|ball size error: f_c"
    assert key in fast.lines and key in slow.lines
    np.testing.assert_allclose(fast.lines[key][1], slow.lines[key][1], rtol=1e-7)


def test_radial_load_is_not_dropped_by_the_batched_path() -> None:
    # The batched kernel has no external force; a loaded 2-D case must take the model's path.
    loaded = kim_case(
        radial_load=5.0,
        study={
            "kind": "montecarlo",
            "samples": 2,
            "seed": 5,
            "vary": {"element_diameter_sigma": "0.1 um"},
        },
    )
    with_load = run_study(loaded)
    without = run_study(mc(samples=2))
    # Same ball sizes, but the load stiffens the loaded side: the runout changes (by ~4e-5
    # here), far beyond the solver's 1e-12 agreement between identical runs.
    a, b = with_load.runout["radial_pp_m"], without.runout["radial_pp_m"]
    assert np.max(np.abs(a - b) / b) > 1e-6


# ------------------------------------------------------------------ reproducibility
def test_numbers_do_not_depend_on_chunking_or_workers() -> None:
    case = mc(samples=23)
    one = run_study(case)
    assert_same(one, run_study(case, chunk_size=4))
    with ThreadPoolExecutor(max_workers=2) as pool:
        assert_same(one, run_study(case, executor=pool, chunk_size=5))
    assert_same(one, run_study(case, workers=2, chunk_size=6))  # process pool


def test_generic_monte_carlo_draws_and_reproducibility() -> None:
    case = kim(
        {
            "kind": "montecarlo",
            "samples": 6,
            "seed": 9,
            "chunk_size": 4,
            "vary": {
                "operation.axial_load": {"distribution": "normal", "std": "5 N"},
                "bearing.radial_clearance": {
                    "distribution": "uniform",
                    "low": "4 um",
                    "high": "6 um",
                },
                "elements.diameter_errors": {
                    "distribution": "sample",
                    "values": ["-0.1 um", "0 um", "0.1 um"],
                },
            },
        }
    )
    a = run_study(case)
    assert a.samples == 6 and not a.errors
    loads = np.array(a.values["operation.axial_load"])
    assert np.all(np.abs(loads - 60.68) < 6 * 5.0) and np.unique(loads).size == 6
    clear = np.array(a.values["bearing.radial_clearance"])
    assert np.all((clear >= 4e-6) & (clear <= 6e-6))
    sizes = np.array(a.values["elements.diameter_errors"])
    assert sizes.shape == (6, 10) and set(np.round(sizes.ravel() * 1e7)) <= {-1.0, 0.0, 1.0}
    assert_same(a, run_study(case, chunk_size=1))


# ------------------------------------------------------------------ sweeps
def test_sweep_grid_over_quantities_and_models() -> None:
    case = kim(
        {
            "kind": "sweep",
            "models": ["quasi_static_2d", "quasi_static_3d"],
            "vary": {"operation.axial_load": {"start": "30 N", "stop": "90 N", "num": 3}},
        },
        diameter_errors=["0.1 um", 0, 0, 0, 0, 0, 0, 0, 0, 0],
    )
    res = run_study(case)
    assert res.samples == 6 and not res.errors
    assert res.model == ["quasi_static_2d"] * 3 + ["quasi_static_3d"] * 3
    np.testing.assert_allclose(res.values["operation.axial_load"], [30.0, 60.0, 90.0] * 2)
    # one 0.1 um oversize ball: f_c line ≈ 4Δ/Z = 40 nm whatever the preload (linear theory)
    fc = res.lines["x|ball size error: f_c"][1]
    np.testing.assert_allclose(fc[:3], 40e-9, rtol=0.02)
    js = res.to_json()
    assert len(js["points"]) == 6 and js["points"][0]["values"]["operation.axial_load"] == 30.0


def test_sweep_step_and_integer_keys() -> None:
    case = kim({"kind": "sweep", "vary": {"bearing.elements": {"start": 8, "stop": 12, "step": 2}}})
    quantities = st_mod.plan_quantities(case)
    assert quantities[0].values == (8, 10, 12)


# ------------------------------------------------------------------ statistics
@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0.0, 1e-6), min_size=2, max_size=60), st.integers(1, 30))
def test_statistics_are_ordered_and_consistent(values: list[float], bins: int) -> None:
    s = statistics(values, bins)
    eps = 1e-18
    assert s["min"] - eps <= s["p5"] <= s["p50"] + eps <= s["p95"] + 2 * eps <= s["max"] + 3 * eps
    assert s["min"] - eps <= s["mean"] <= s["max"] + eps
    assert s["two_sigma"] == 2.0 * s["std"]
    assert sum(s["histogram"]["counts"]) == len(values)
    assert len(s["histogram"]["edges"]) == bins + 1


def test_line_label_merges_element_numbers() -> None:
    label = "ball 1 size error: f_c; ball 2 size error: f_c; pitch errors: f_c"
    assert line_label(label) == "ball size error: f_c; pitch errors: f_c"
    assert line_label(line_label(label)) == line_label(label)


# ------------------------------------------------------------------ case validation
@pytest.mark.parametrize(
    ("study", "where", "text"),
    [
        ({"kind": "montecarlo", "vary": {"element_diameter_sigm": "1 um"}}, "vary", "did you mean"),
        (
            {"kind": "montecarlo", "vary": {"operation.axial_lod": {"distribution": "uniform"}}},
            "study.vary.operation.axial_lod",
            "did you mean 'operation.axial_load'",
        ),
        (
            {"kind": "montecarlo", "vary": {"operation.axial_load": {"distribution": "normal"}}},
            "study.vary.operation.axial_load.std",
            "required",
        ),
        (
            {
                "kind": "montecarlo",
                "vary": {"operation.axial_load": {"distribution": "normal", "sd": 1}},
            },
            "study.vary.operation.axial_load.sd",
            "did you mean 'std'",
        ),
        (
            {"kind": "sweep", "vary": {"operation.axial_load": {"start": 1, "stop": 2}}},
            "study.vary.operation.axial_load.num",
            "exactly one of num or step",
        ),
        (
            {"kind": "sweep", "samples": 3, "vary": {"operation.speed": {"values": [1]}}},
            "study.samples",
            "montecarlo",
        ),
        ({"kind": "montecarlo", "vary": {}}, "study.vary", "at least one"),
        (
            {"kind": "sweep", "vary": {"waviness.amplitude": {"values": [1]}}},
            "study.vary.waviness.amplitude",
            "waviness[1].amplitude",
        ),
    ],
)
def test_study_table_errors_name_the_key(study: dict[str, Any], where: str, text: str) -> None:
    with pytest.raises(CaseError) as err:
        kim(study)
    assert where in str(err.value) and text in str(err.value)


def test_drawn_values_are_checked_where_they_go() -> None:
    case = kim(
        {
            "kind": "montecarlo",
            "vary": {"operation.axial_load": {"distribution": "uniform", "low": "1 m", "high": 2}},
        }
    )
    with pytest.raises(CaseError, match=r"study\.vary\.operation\.axial_load\.low.*force"):
        st_mod.plan_quantities(case)
    case = kim(
        {"kind": "sweep", "vary": {"waviness[2].amplitude": {"values": ["1 nm"]}}},
    )
    with pytest.raises(CaseError, match="has 0"):
        st_mod.plan_quantities(case)


def test_resume_refuses_a_different_study(tmp_path: Any) -> None:
    run_study(mc(samples=3), out=tmp_path, plots=False)
    with pytest.raises(st_mod.StudyError, match="different"):
        run_study(mc(samples=3, seed=6), out=tmp_path, resume=True)


# ==================================================================== data safety
# Atomic files, the output lock, manifest and chunk checks, the parent watchdog of pool
# workers, exact sweep-dynamic point names, failure records (the command-line side is in
# tests/cli/test_study_safety.py).


def chunked(samples: int = 4, seed: int = 5, chunk: int = 2) -> Case:
    return kim(
        {
            "kind": "montecarlo",
            "samples": samples,
            "seed": seed,
            "chunk_size": chunk,
            "vary": {"element_diameter_sigma": "0.1 um"},
        }
    )


# ------------------------------------------------------------------ atomic files
def test_write_atomic_leaves_no_temporary_and_keeps_the_old_file_on_failure(
    tmp_path: Path,
) -> None:
    target = tmp_path / "a.json"
    write_atomic(target, lambda fh: fh.write("one\n"))
    assert target.read_text() == "one\n" and os.listdir(tmp_path) == ["a.json"]

    def broken(fh: Any) -> None:
        fh.write("half")
        raise RuntimeError("disk on fire")

    with pytest.raises(RuntimeError):
        write_atomic(target, broken)
    assert target.read_text() == "one\n" and os.listdir(tmp_path) == ["a.json"]
    # the umask decides the mode, as for any file the user writes (mkstemp would give 0o600)
    umask = os.umask(0)
    os.umask(umask)
    assert target.stat().st_mode & 0o777 == 0o666 & ~umask


def test_write_atomic_names_are_unique(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[str] = []
    replace = os.replace

    def spy(src: Any, dst: Any) -> None:
        seen.append(Path(src).name)
        replace(src, dst)

    monkeypatch.setattr(os, "replace", spy)
    for _ in range(5):
        write_atomic(tmp_path / "m.json", lambda fh: fh.write("x"))
    assert len(set(seen)) == 5
    assert all(files_mod._TEMP.match(name) and name.startswith(".m.json.") for name in seen)


def test_write_atomic_failure_is_an_output_error_naming_the_file(tmp_path: Path) -> None:
    with pytest.raises(OutputError, match=r"nowhere/a\.json: cannot write"):
        write_atomic(tmp_path / "nowhere" / "a.json", lambda fh: fh.write("x"))


# ------------------------------------------------------------------ output directories
def test_output_directory_refuses_empty_and_files(tmp_path: Path) -> None:
    with pytest.raises(OutputError, match="empty path"):
        output_directory("")
    with pytest.raises(OutputError, match="empty path"):
        run_study(chunked(), out="")
    (tmp_path / "f").write_text("x")
    with pytest.raises(OutputError, match="exists and is not a directory"):
        output_directory(tmp_path / "f")
    with pytest.raises(OutputError, match="cannot create the directory"):
        output_directory(tmp_path / "f" / "sub")
    made = output_directory(str(tmp_path / "a" / "b"))
    assert made.is_dir()


def test_refuse_foreign_accepts_only_runout_outputs(tmp_path: Path) -> None:
    d = tmp_path / "d"
    d.mkdir()
    refuse_foreign(d, "study", force=False)  # empty
    (d / ".lock").write_text("123\n")  # a lock file (of a killed run) is ours
    (d / ".manifest.json.0123456789ab.tmp").write_text("{")  # a leftover temporary too
    refuse_foreign(d, "study", force=False)
    (d / "points").mkdir()
    (d / "sweep.csv").write_text("")
    (d / "spectra_preload_Z9.png").write_text("")
    refuse_foreign(d, "sweep-dynamic", force=False)
    with pytest.raises(OutputError, match=r"not a runout study output .*'points'.*--force"):
        refuse_foreign(d, "study", force=False)
    (d / "notes.txt").write_text("mine")
    with pytest.raises(OutputError, match=r"'notes\.txt'"):
        refuse_foreign(d, "sweep-dynamic", force=False)
    refuse_foreign(d, "sweep-dynamic", force=True)


# ------------------------------------------------------------------ lock
def test_output_lock_is_exclusive_released_and_removed(tmp_path: Path) -> None:
    with output_lock(tmp_path) as path:
        assert path.read_text().strip() == str(os.getpid())
        with pytest.raises(OutputError) as err:
            with output_lock(tmp_path):
                pass  # pragma: no cover
        assert str(err.value) == (
            f"{path}: another runout study is writing to {tmp_path} (pid {os.getpid()})"
        )
    assert not path.exists()
    with output_lock(tmp_path):  # free again
        pass


def test_a_lock_file_left_by_a_killed_writer_is_not_a_lock(tmp_path: Path) -> None:
    (tmp_path / ".lock").write_text("999999999\n")  # a PID that does not run
    with output_lock(tmp_path) as path:
        assert path.read_text().strip() == str(os.getpid())


def test_run_study_holds_the_lock_while_it_writes(tmp_path: Path) -> None:
    with output_lock(tmp_path):
        with pytest.raises(OutputError, match="another runout study is writing"):
            run_study(chunked(), out=tmp_path, plots=False)
    assert os.listdir(tmp_path) == []


# ------------------------------------------------------------------ manifest and chunks
def test_manifest_checks(tmp_path: Path) -> None:
    run_study(chunked(), out=tmp_path, plots=False)
    good = json.loads((tmp_path / "manifest.json").read_text())
    assert files_mod._manifest_problem(good) is None
    bad = {
        "format": "other/1",
        "digest": 5,
        "kind": "grid",
        "samples": True,
        "chunk_size": 0,
        "chunks": 1.5,
        "done": [0, 0],
        "complete": "yes",
    }
    for key, value in bad.items():
        assert files_mod._manifest_problem({**good, key: value}) is not None, key
    (tmp_path / "manifest.json").write_bytes(b"\xff\xfe")
    with pytest.raises(StudyError, match=r"manifest\.json: corrupted study manifest"):
        files_mod._read_manifest(tmp_path / "manifest.json")


def test_chunks_carry_the_digest_and_are_checked(tmp_path: Path) -> None:
    case = chunked()
    run_study(case, out=tmp_path, plots=False)
    plan = st_mod._plan(case, None)
    chunk = json.loads((tmp_path / "chunks" / "chunk_00001.json").read_text())
    assert chunk["digest"] == plan.digest
    task = plan.tasks[1]
    assert files_mod._chunk_problem(chunk, task, plan.digest) is None
    assert files_mod._chunk_problem(chunk, plan.tasks[0], plan.digest) == "chunk is 1, expected 0"
    assert files_mod._chunk_problem(chunk, task, "0" * 64) == "written by another study"
    no_digest = {k: v for k, v in chunk.items() if k != "digest"}
    assert files_mod._chunk_problem(no_digest, task, plan.digest) == "no study digest"
    damaged = [
        ("model", ["quasi_static_2d"]),
        ("values", {}),
        ("runout", {"radial_pp_m": [1.0, 2.0]}),
        ("lines", {"x|f_c": {"frequency_hz": 1.0, "pp_m": [1.0]}}),
        ("errors", {"7": "outside the chunk"}),
    ]
    for key, value in damaged:
        assert files_mod._chunk_problem({**chunk, key: value}, task, plan.digest), key
    # load_study reads the directory back, and says which file is not this study's
    assert load_study(tmp_path, case).samples == 4
    (tmp_path / "chunks" / "chunk_00001.json").write_text("[]")
    with pytest.raises(StudyError, match=r"chunk_00001\.json: a JSON list"):
        load_study(tmp_path, case)
    with pytest.raises(StudyError, match="different case or study"):
        load_study(tmp_path, chunked(seed=6))


def test_resume_recomputes_a_bad_chunk_and_notifies(tmp_path: Path) -> None:
    case = chunked()
    first = run_study(case, out=tmp_path, plots=False)
    (tmp_path / "chunks" / "chunk_00000.json").write_text('{"truncated')
    notes: list[str] = []
    again = run_study(case, out=tmp_path, plots=False, resume=True, notify=notes.append)
    assert len(notes) == 1 and "recomputing 1 chunk" in notes[0] and "not valid JSON" in notes[0]
    assert again.to_json() == first.to_json()


def test_a_killed_writers_temporaries_are_removed(tmp_path: Path) -> None:
    case = chunked()
    run_study(case, out=tmp_path, plots=False)
    left = tmp_path / "chunks" / ".chunk_00000.json.0123456789ab.tmp"
    left.write_text("{")
    run_study(case, out=tmp_path, plots=False, resume=True)
    assert not left.exists()


# ------------------------------------------------------------------ failures
def test_error_text_is_one_bounded_line() -> None:
    assert error_text(ValueError("bad\n  point")) == "ValueError: bad point"
    long = error_text(RuntimeError("x" * 1000))
    assert len(long) == st_mod.ERROR_CHARS and long.endswith("...")


def test_failed_samples_are_listed_bounded(monkeypatch: pytest.MonkeyPatch) -> None:
    import runout.runner

    def fail(case: Any) -> Any:
        raise ZeroDivisionError("no")

    monkeypatch.setattr(runout.runner, "run_model", fail)
    monkeypatch.setattr(chunks_mod, "_batched", lambda task: False)
    res = run_study(chunked(samples=25, chunk=10))
    assert len(res.errors) == 25
    listed = res.summary()["errors"]
    assert len(listed) == st_mod.ERRORS_SHOWN
    assert listed[0] == {"sample": 0, "error": "ZeroDivisionError: no"}
    assert res.to_json()["failed"] == 25 and res.to_json()["errors"] == listed


def test_batched_failure_falls_back_to_per_bearing_records(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def broken(*args: Any) -> None:
        raise MemoryError("batch too large")

    monkeypatch.setattr(chunks_mod, "_evaluate_batched", broken)
    res = run_study(chunked(samples=3))
    assert not res.errors and all(math.isfinite(v) for v in res.runout["radial_pp_m"])


# ------------------------------------------------------------------ workers and their parent
@pytest.mark.skipif(
    sys.platform == "win32", reason="SIGKILL (the orphaned-worker case) does not exist on Windows"
)
def test_watchdog_alone_ends_a_worker_whose_parent_was_killed(tmp_path: Path) -> None:
    # The portable line of defence without prctl: the worker's thread watching its parent.
    script = tmp_path / "parent.py"
    script.write_text(
        textwrap.dedent(
            """
            import multiprocessing, os, time
            from concurrent.futures import ProcessPoolExecutor
            from runout.study.run import die_with_parent

            if __name__ == "__main__":
                pool = ProcessPoolExecutor(
                    1,
                    mp_context=multiprocessing.get_context("spawn"),
                    initializer=die_with_parent,
                    initargs=(os.getpid(), False),
                )
                pool.submit(time.sleep, 0.0).result()
                print(*pool._processes, flush=True)
                time.sleep(600)
            """
        )
    )
    parent = subprocess.Popen(
        [sys.executable, str(script)], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True
    )
    worker = 0
    try:
        assert parent.stdout is not None
        worker = int(parent.stdout.readline().split()[0])
        os.kill(parent.pid, signal.SIGKILL)
        parent.wait(timeout=30)
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline and _alive(worker):
            time.sleep(0.05)
        assert not _alive(worker), "the worker outlived its killed parent"
    finally:
        if parent.poll() is None:
            parent.kill()
            parent.wait(timeout=30)
        if parent.stdout is not None:
            parent.stdout.close()
        if worker and _alive(worker):
            os.kill(worker, signal.SIGKILL)


def _alive(pid: int) -> bool:
    stat = Path(f"/proc/{pid}/stat")
    if stat.parent.parent.is_dir() and Path("/proc/self/stat").exists():
        try:
            return stat.read_text().rsplit(")", 1)[1].split()[0] not in ("Z", "X")
        except OSError:
            return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True


# ------------------------------------------------------------------ sweep-dynamic names
def test_point_names_keep_the_old_short_form_when_it_is_exact() -> None:
    assert point_name(6, 0.0) == "Z6_P0N" and point_name(9, 5) == "Z9_P5N"
    assert point_name(9, -0.0) == "Z9_P0N"
    assert point_name(9, 10.0000001) == "Z9_P10.0000001N"
    assert point_name(9, 10.0000001) != point_name(9, 10.0000002)


@settings(max_examples=300, deadline=None)
@given(
    st.floats(0.0, 1e6, allow_nan=False, allow_infinity=False),
    st.floats(0.0, 1e6, allow_nan=False, allow_infinity=False),
)
def test_point_names_are_exact_and_unique(a: float, b: float) -> None:
    assert float(exact_number(a)) == a
    assert (exact_number(a) == exact_number(b)) == (a == b)


def test_the_digest_covers_the_bytes_of_profile_files(tmp_path: Path) -> None:
    # A remeasured profile is another case: its chunks must not pass for the old ones.
    from runout.case.model import load_case

    def profile(amplitude_um: float) -> None:
        rows = [f"{a},{amplitude_um * math.cos(math.radians(a) * 5)}" for a in range(0, 360, 2)]
        (tmp_path / "outer.csv").write_text("angle_deg,deviation_um\n" + "\n".join(rows))

    case_toml = tmp_path / "case.toml"
    case_toml.write_text(
        KIM_TOML
        + """[[profile]]
part = "outer"
file = "outer.csv"
orders = [2, 20]
[study]
kind = "montecarlo"
samples = 2
[study.vary]
element_diameter_sigma = "0.1 um"
"""
    )
    profile(0.2)
    first = st_mod._plan(load_case(case_toml), None).digest
    assert st_mod._plan(load_case(case_toml), None).digest == first
    profile(0.3)
    assert st_mod._plan(load_case(case_toml), None).digest != first
