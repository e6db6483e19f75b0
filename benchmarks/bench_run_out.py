"""``runout run CASE --out DIR`` against ``runout run CASE --json`` on the examples (issue 31).

Writing a run's files (tables, figures, the animation, a model's own files) must cost at
most as much again as the run itself: ``--out`` within 2x the ``--json`` wall time of the same
case. One example per model; each command is a fresh interpreter (start-up included), warm
Numba and file caches (one untimed run of each first), the two commands run in turn so that
load from other jobs falls on both, best of several runs. The 2^20-instant case is
``bench_cli.bench_cli_run_out_vs_json_2e20``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _harness import BenchResult

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
#: The console script a user runs (its fast exit), beside this interpreter; else the module.
_SCRIPT = Path(sys.executable).with_name("runout")
RUNOUT = [str(_SCRIPT)] if _SCRIPT.is_file() else [sys.executable, "-m", "runout.cli"]
REPEAT = 3


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env.setdefault("MPLBACKEND", "Agg")
    # timed as installed: pip compiles runout's bytecode, and the untimed first run writes it
    # here (an environment with PYTHONDONTWRITEBYTECODE would compile every module each run)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def _wall(cmd: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(
        cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=_env()
    )
    return time.perf_counter() - t0


def out_vs_json(case: Path, repeat: int = REPEAT) -> tuple[float, float]:
    """Best wall times [s] of ``run CASE --out DIR`` and ``run CASE --json``, run in turn."""
    best_out = best_json = float("inf")
    with tempfile.TemporaryDirectory(prefix="runout-bench-") as tmp:
        for k in range(repeat + 1):  # the first round warms the caches
            as_json = _wall([*RUNOUT, "run", str(case), "--json"])
            with_out = _wall([*RUNOUT, "run", str(case), "--out", str(Path(tmp) / "out")])
            if k:
                best_json = min(best_json, as_json)
                best_out = min(best_out, with_out)
    return best_out, best_json


def _bench(example: str, model: str) -> BenchResult:
    with_out, as_json = out_vs_json(EXAMPLES / f"{example}.toml")
    return BenchResult(
        name=f"cli: run --out vs --json, {example} ({model})",
        ours_s=with_out,
        reference_s=as_json,
        reference="runout run --json (same case)",
        target="--out within 2x the --json time",
        met=with_out <= 2.0 * as_json,
    )


def bench_run_out_linear() -> BenchResult:
    """seed002_608: the linear model's three extra figures, no compiled code."""
    return _bench("seed002_608", "linear")


def bench_run_out_quasi_static_3d() -> BenchResult:
    """seed000_tada_fig7: the standard figures and the animation."""
    return _bench("seed000_tada_fig7", "quasi_static_3d")


def bench_run_out_quasi_static_2d() -> BenchResult:
    """seed001_kim_spindle: the standard figures and the animation."""
    return _bench("seed001_kim_spindle", "quasi_static_2d")


def bench_run_out_equilibrium() -> BenchResult:
    """seed001_kim_equilibrium: the ball table, the stiffness and one figure."""
    return _bench("seed001_kim_equilibrium", "equilibrium")


def bench_run_out_dynamic() -> BenchResult:
    """seed003_purohit: the standard figures, the spectrum table and figure."""
    return _bench("seed003_purohit", "dynamic")


def bench_run_out_roller_constraint() -> BenchResult:
    """seed004_nu209: the contact table, the order sweep (123 solves) and three figures."""
    return _bench("seed004_nu209", "roller_constraint")


def bench_run_out_spindle() -> BenchResult:
    """spindle_hdd: the standard figures of a two-bearing spindle."""
    return _bench("spindle_hdd", "spindle")
