"""`runout study`: JSON contract, interrupted run + --resume (byte for byte), Dask cluster."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from cases import KIM_TOML
from runout.case.model import load_case
from runout.study.run import run_study

ROOT = Path(__file__).resolve().parents[2]
CASE = (
    """
title = "study test"
"""
    + KIM_TOML
    + """[analysis]
model = "quasi_static_2d"
revolutions = 4
samples = 256
[study]
kind = "montecarlo"
samples = {samples}
seed = 3
chunk_size = {chunk}
[study.vary]
element_diameter_sigma = "0.1 um"
"operation.axial_load" = {{ distribution = "normal", std = "2 N" }}
"""
)


def write_case(tmp_path: Path, samples: int, chunk: int) -> Path:
    path = tmp_path / "case.toml"
    path.write_text(CASE.format(samples=samples, chunk=chunk), encoding="utf-8")
    return path


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    exe = [sys.executable, "-m", "runout.cli", *args]
    return subprocess.run(exe, capture_output=True, text=True, check=False, timeout=120)


def tree(directory: Path) -> dict[str, bytes]:
    return {
        str(p.relative_to(directory)): p.read_bytes()
        for p in sorted(directory.rglob("*"))
        if p.is_file()
    }


def test_study_json_contract(tmp_path: Path) -> None:
    done = cli("study", str(write_case(tmp_path, 5, 2)), "--json")
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert out["samples"] == 5 and out["failed"] == 0
    stats = {"mean", "std", "p5", "p50", "p95"}
    assert set(out["runout"]) == {"radial_pp_m", "axial_pp_m", "rro_pp_m", "nrro_pp_m"}
    assert all(set(v) == stats for v in out["runout"].values())
    comp = out["components"][0]
    assert {"direction", "frequency_hz", "label", "pp_m"} <= set(comp)
    assert set(comp["pp_m"]) == stats and comp["direction"] in ("x", "y")
    assert comp["pp_m"]["p5"] <= comp["pp_m"]["p50"] <= comp["pp_m"]["p95"]


def test_study_help_and_errors(tmp_path: Path) -> None:
    done = cli("study", "--help")
    assert done.returncode == 0 and "Example:" in done.stdout
    plain = tmp_path / "plain.toml"
    plain.write_text(CASE.split("[study]")[0], encoding="utf-8")
    done = cli("study", str(plain))
    assert done.returncode == 2 and "[study]" in done.stderr and "Traceback" not in done.stderr
    done = cli("study", str(write_case(tmp_path, 5, 2)), "--resume")
    assert done.returncode == 2 and "--out" in done.stderr


def test_killed_run_resumes_to_identical_files(tmp_path: Path) -> None:
    case = write_case(tmp_path, 120, 4)  # 30 chunks on the per-bearing path
    fresh, killed = tmp_path / "fresh", tmp_path / "killed"
    done = cli("study", str(case), "--out", str(fresh))
    # the "wrote" line names the figures too (it listed the tables alone)
    assert "summary.json, samples.csv, samples_columns.json, histograms.png)" in done.stdout
    assert done.returncode == 0, done.stderr
    proc = subprocess.Popen(
        [sys.executable, "-m", "runout.cli", "study", str(case), "--out", str(killed)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    manifest = killed / "manifest.json"
    deadline = time.monotonic() + 60
    written = 0
    while time.monotonic() < deadline and proc.poll() is None:
        try:
            written = len(json.loads(manifest.read_text())["done"])
        except (OSError, ValueError, KeyError):
            written = 0
        if written >= 3:
            break
        time.sleep(0.02)
    assert proc.poll() is None, "the run ended before it could be interrupted"
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    state = json.loads(manifest.read_text())
    assert not state["complete"] and 3 <= len(state["done"]) < 30
    # the killed writer's lock file stays, with its PID, but locks nothing: flock died with it
    assert (killed / ".lock").read_text().strip() == str(proc.pid)
    done = cli("study", str(case), "--out", str(killed), "--resume")
    assert done.returncode == 0, done.stderr
    a, b = tree(fresh), tree(killed)
    assert a.keys() == b.keys()
    for name in a:
        assert a[name] == b[name], name


@pytest.fixture(scope="module")
def cluster():  # type: ignore[no-untyped-def]
    # `make test` installs the dask extra: a missing distributed is a failure, not a skip.
    import dask
    import distributed

    # Dask trims malloc aggressively by default (MALLOC_TRIM_THRESHOLD_=65536), which makes
    # NumPy temporaries slow; restore a large threshold in the workers' environment.
    with dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": 2**28}):
        with distributed.LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=False,
            host="127.0.0.1",
            protocol="tcp",
            dashboard_address=None,
        ) as lc:
            yield lc


def test_dask_local_cluster_same_numbers(cluster, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    import distributed

    case = load_case(write_case(tmp_path, 12, 3))
    local = run_study(case)
    with distributed.Client(cluster) as client:
        remote = run_study(case, executor=client.get_executor())
    for k, v in local.runout.items():
        np.testing.assert_array_equal(v, remote.runout[k])
    for key, (f, pp) in local.lines.items():
        assert remote.lines[key][0] == f
        np.testing.assert_array_equal(pp, remote.lines[key][1])
    # and the command line, through --scheduler tcp://...
    done = cli(
        "study",
        str(write_case(tmp_path, 12, 3)),
        "--json",
        "--scheduler",
        cluster.scheduler_address,
    )
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert out["runout"]["radial_pp_m"]["mean"] == local.to_json()["runout"]["radial_pp_m"]["mean"]


def test_dask_scatters_the_shared_arrays_and_gives_the_same_bytes(  # type: ignore[no-untyped-def]
    cluster, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A batched ball-size Monte Carlo on Dask: the shared arrays are scattered to the workers
    once (chunks carry none), and the numbers are the in-process ones for any chunk size."""
    import distributed

    from runout.study import run as st_mod

    text = CASE.format(samples=17, chunk=250)
    text = text.replace('"operation.axial_load" = { distribution = "normal", std = "2 N" }\n', "")
    assert "operation.axial_load" not in text
    path = tmp_path / "balls.toml"
    path.write_text(text, encoding="utf-8")
    local = run_study(load_case(path))
    shipped: list[bool] = []
    evaluate = st_mod.evaluate_chunk

    def spy(task):  # type: ignore[no-untyped-def]
        shipped.append(task.batch is not None)
        return evaluate(task)

    scattered: list[bool] = []
    scatter = st_mod._scattered

    def watch(pool, tasks):  # type: ignore[no-untyped-def]
        submit = scatter(pool, tasks)
        scattered.append(submit is not None)
        return submit

    monkeypatch.setattr(st_mod, "evaluate_chunk", spy)  # in the cluster's threads too
    monkeypatch.setattr(st_mod, "_scattered", watch)
    with distributed.Client(cluster) as client:
        remote = run_study(load_case(path), executor=client.get_executor(), chunk_size=4)
    assert scattered == [True]  # sent once, by reference
    assert len(shipped) == 5 and all(shipped)  # every chunk found them on its worker
    for k, v in local.runout.items():
        assert v.tobytes() == remote.runout[k].tobytes()
    assert local.values["element_diameter_sigma"].tobytes() == (
        remote.values["element_diameter_sigma"].tobytes()
    )
    for key, (f, pp) in local.lines.items():
        assert remote.lines[key][0] == f and pp.tobytes() == remote.lines[key][1].tobytes()
