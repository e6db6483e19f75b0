"""First run of each model on an empty Numba cache against the same command on a warm cache.

The kernels are compiled on first use and kept in Numba's on-disk cache (``cache=True``): the
first command of a model after an installation (or after its kernels changed) pays their
compilation. Target (the issue "the first run of each model must not wait for the
compiler"): that first run within 4x of the same command run again right after.

For each model, one command as a user types it (the installed ``runout`` script next to this
interpreter, a subprocess each time): ``runout run <example> --json`` per model and
``runout study`` for the Monte Carlo study. Ours: the wall time of the first run with
``NUMBA_CACHE_DIR`` pointing at a fresh, empty directory. Reference: the same command run
again, best of :data:`WARM_RUNS` (the cache now warm). Both in the same run of this module,
so that a loaded machine slows both. About 45 s in all on the 2-core machine.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _harness import BenchResult

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
#: Warm runs after the first; the best counts.
WARM_RUNS = 2
#: The first run may take this many times the warm one.
LIMIT = 4.0


def _command() -> list[str]:
    """The installed ``runout`` script next to this interpreter (else ``python -m``)."""
    script = Path(sys.executable).with_name("runout")
    return [str(script)] if script.exists() else [sys.executable, "-m", "runout.cli"]


def _wall(cmd: list[str], env: dict[str, str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    return time.perf_counter() - t0


def _first_and_warm(verb: str, example: str, model: str) -> BenchResult:
    """The first run on an empty cache and the best warm run of ``runout VERB EXAMPLE``."""
    cmd = [*_command(), verb, str(EXAMPLES / example)] + (["--json"] if verb == "run" else [])
    cache = tempfile.mkdtemp(prefix="runout-bench-numba-")
    env = dict(os.environ, NUMBA_CACHE_DIR=cache, MPLBACKEND="Agg")
    try:
        first = _wall(cmd, env)
        warm = min(_wall(cmd, env) for _ in range(WARM_RUNS))
    finally:
        shutil.rmtree(cache, ignore_errors=True)
    print(f"  {verb} {example}: first {first:.2f} s, warm {warm:.2f} s ({first / warm:.2f}x)")
    shown = f"runout {verb} {Path(example).stem}" + (" --json" if verb == "run" else "")
    return BenchResult(
        name=f"first run, {model}: {shown}",
        ours_s=first,
        reference_s=warm,
        reference=f"same command, warm cache (best of {WARM_RUNS})",
        target=f"first run within {LIMIT:g}x the warm run",
        met=first <= LIMIT * warm,
    )


def bench_first_run_linear() -> BenchResult:
    """Seed 002's 608 (the linear model)."""
    return _first_and_warm("run", "seed002_608.toml", "linear")


def bench_first_run_quasi_static_3d() -> BenchResult:
    """Seed 000's Fig. 7 case (quasi_static_3d)."""
    return _first_and_warm("run", "seed000_tada_fig7.toml", "quasi_static_3d")


def bench_first_run_quasi_static_2d() -> BenchResult:
    """Seed 001's spindle bearing (quasi_static_2d)."""
    return _first_and_warm("run", "seed001_kim_spindle.toml", "quasi_static_2d")


def bench_first_run_equilibrium() -> BenchResult:
    """Seed 001's equilibrium at speed (equilibrium)."""
    return _first_and_warm("run", "seed001_kim_equilibrium.toml", "equilibrium")


def bench_first_run_dynamic() -> BenchResult:
    """Seed 003's rotor-bearing system (dynamic)."""
    return _first_and_warm("run", "seed003_purohit.toml", "dynamic")


def bench_first_run_roller_constraint() -> BenchResult:
    """Seed 004's NU209 (roller_constraint)."""
    return _first_and_warm("run", "seed004_nu209.toml", "roller_constraint")


def bench_first_run_spindle() -> BenchResult:
    """The two-bearing HDD spindle (spindle)."""
    return _first_and_warm("run", "spindle_hdd.toml", "spindle")


def bench_first_run_study() -> BenchResult:
    """Seed 001's Table 9 Monte Carlo (the study's batched kernels)."""
    return _first_and_warm("study", "seed001_kim_table9.toml", "Monte Carlo study")
