"""End-to-end benchmarks of the command-line tool: what a user waits for, start-up included.

Each command runs as a subprocess (a fresh interpreter, warm Numba cache and warm file
cache: every command is run once before timing), best wall time of several runs.

* ``runout frequencies`` against a bare ``python -c "import numpy"``: the floor of any
  Python tool built on NumPy (target: within 6×).
* ``runout --help`` against the same floor.
* ``runout run --out DIR`` against ``runout run --json`` on a 2^20-instant quasi_static_3d
  case (seed 000's Fig. 7 case at 1,048,576 instants): writing the data files, plots and the
  animation must cost at most as much again as the run itself (target: within 2×).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _harness import BenchResult

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "seed000_tada_fig7.toml"
#: The console script a user runs (its fast exit), beside this interpreter; else the module.
_SCRIPT = Path(sys.executable).with_name("runout")
RUNOUT = [str(_SCRIPT)] if _SCRIPT.is_file() else [sys.executable, "-m", "runout.cli"]
BIG_SAMPLES = 1 << 20


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env.setdefault("MPLBACKEND", "Agg")
    # timed as installed: pip compiles runout's bytecode, and the untimed first run writes it
    # here (an environment with PYTHONDONTWRITEBYTECODE would compile every module each run)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def _wall(cmd: list[str], repeat: int, cwd: Path | None = None) -> float:
    """Best wall time of ``repeat`` runs of ``cmd`` after one untimed run [s]."""
    best = float("inf")
    for k in range(repeat + 1):
        t0 = time.perf_counter()
        subprocess.run(
            cmd,
            check=True,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            env=_env(),
            cwd=cwd,
        )
        if k:  # the first run warms the caches
            best = min(best, time.perf_counter() - t0)
    return best


def _numpy_floor(repeat: int) -> float:
    return _wall([sys.executable, "-c", "import numpy"], repeat)


def _entry_point() -> list[str]:
    """The installed ``runout`` script next to this interpreter (else ``python -m``)."""
    script = Path(sys.executable).with_name("runout")
    return [str(script)] if script.exists() else RUNOUT


def bench_cli_frequencies_vs_bare_numpy() -> BenchResult:
    """Warm `runout frequencies` of seed 000's case vs `python -c "import numpy"`."""
    ours = _wall([*_entry_point(), "frequencies", str(EXAMPLE)], repeat=7)
    floor = _numpy_floor(repeat=7)
    return BenchResult(
        name="cli: runout frequencies (warm)",
        ours_s=ours,
        reference_s=floor,
        reference='python -c "import numpy"',
        target="within 6x a bare NumPy import",
        met=ours <= 6.0 * floor,
    )


def bench_cli_help_vs_bare_numpy() -> BenchResult:
    """`runout --help` start-up vs `python -c "import numpy"`."""
    ours = _wall([*_entry_point(), "--help"], repeat=7)
    floor = _numpy_floor(repeat=7)
    return BenchResult(
        name="cli: runout --help",
        ours_s=ours,
        reference_s=floor,
        reference='python -c "import numpy"',
        target="within 3x a bare NumPy import",
        met=ours <= 3.0 * floor,
    )


def _big_case(directory: Path) -> Path:
    """Seed 000's Fig. 7 case at 2^20 instants (budget raised for it)."""
    text = EXAMPLE.read_text()
    text, count = re.subn(
        r"(?m)^samples\s*=\s*\d+.*$",
        f'samples = {BIG_SAMPLES}\nmax_memory = "8 GiB"\nmax_time = "10 min"',
        text,
    )
    if count != 1:
        raise RuntimeError(f"{EXAMPLE} has no single 'samples =' line to change")
    path = directory / "big.toml"
    path.write_text(text)
    return path


def bench_cli_run_out_vs_json_2e20() -> BenchResult:
    """`runout run --out DIR` vs `runout run --json`, quasi_static_3d at 2^20 instants."""
    with tempfile.TemporaryDirectory(prefix="runout-bench-") as tmp:
        case = _big_case(Path(tmp))
        out = Path(tmp) / "out"
        # run in turn, so that load from other jobs falls on both commands
        as_json = with_out = float("inf")
        for _ in range(3):
            as_json = min(as_json, _wall([*_entry_point(), "run", str(case), "--json"], 1))
            with_out = min(
                with_out, _wall([*_entry_point(), "run", str(case), "--out", str(out)], 1)
            )
    return BenchResult(
        name="cli: run --out vs --json, 2^20 instants",
        ours_s=with_out,
        reference_s=as_json,
        reference="runout run --json (same case)",
        target="--out within 2x the --json time",
        met=with_out <= 2.0 * as_json,
    )
