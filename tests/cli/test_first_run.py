"""The first run after an installation says on stderr that it compiles; ``runout warm`` ahead.

Numba compiles a model's kernels on their first call and caches them: with an empty cache
(``NUMBA_CACHE_DIR`` pointing to a new directory) the first command prints one line when it
starts compiling and one with what it compiled; the same command again prints neither.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from runout.cli.warm import WARM_CASES

ROOT = Path(__file__).resolve().parents[2]
RUNOUT = [sys.executable, "-m", "runout.cli"]


def _runout(args: list[str], cache: Path, notice: str = "1") -> subprocess.CompletedProcess[str]:
    # stderr is a pipe here, not a terminal: RUNOUT_COMPILE_NOTICE=1 asks for the notices a
    # person at a terminal gets
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), MPLBACKEND="Agg")
    env["RUNOUT_COMPILE_NOTICE"] = notice
    return subprocess.run(
        [*RUNOUT, *args], capture_output=True, text=True, env=env, timeout=600, check=False
    )


def test_first_run_says_it_compiles_and_the_second_does_not(tmp_path: Path) -> None:
    # the 3-D quasi-static model's Newton solve is a compiled kernel (the linear model has none)
    case = str(ROOT / "examples" / "seed000_tada_fig7.toml")
    first = _runout(["run", case, "--json"], tmp_path / "cache")
    assert first.returncode == 0, first.stderr
    lines = first.stderr.splitlines()
    assert len(lines) == 2, first.stderr
    assert lines[0].startswith("runout: compiling numerical kernels for this machine")
    assert "once after installation" in lines[0] and "runout warm" in lines[0]
    assert lines[1].startswith("runout: compiled the kernels of the ") and " s; " in lines[1]
    second = _runout(["run", case, "--json"], tmp_path / "cache")
    assert second.returncode == 0 and second.stderr == "", second.stderr
    # the notice is on stderr only: standard output is the same JSON
    assert json.loads(first.stdout) == json.loads(second.stdout)


def test_a_script_reading_stderr_gets_no_progress_lines(tmp_path: Path) -> None:
    # not a terminal, not asked for: an error or warning stays the only line a script reads
    case = str(ROOT / "examples" / "seed000_tada_fig7.toml")
    done = _runout(["run", case, "--json"], tmp_path / "cache", notice="")
    assert done.returncode == 0 and done.stderr == "", done.stderr


def test_commands_that_compile_nothing_say_nothing(tmp_path: Path) -> None:
    case = str(ROOT / "examples" / "seed002_608.toml")
    done = _runout(["frequencies", case], tmp_path / "cache")
    assert done.returncode == 0 and done.stderr == "", done.stderr


def test_warm_lists_every_model() -> None:
    # the suite runs after `make install`, which warmed the cache: this is the quick path
    done = subprocess.run(
        [*RUNOUT, "warm"],
        capture_output=True,
        text=True,
        env=dict(os.environ, MPLBACKEND="Agg"),
        timeout=900,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    for _, _, model in WARM_CASES:
        assert f"compiled the {model} kernels (" in done.stdout
