"""Compile every model's kernels into Numba's cache ahead of use: ``runout warm``.

The kernels are compiled for the machine's CPU on first use and cached (``cache=True``); the
first command of each model after an installation pays a few seconds for it (and says so on
stderr). ``runout warm`` (run by ``make install``) runs one example case per model, and one
study, as a user would, so that every later command starts from a warm cache. The cases are
the example files shipped inside the package, so an installed wheel warms itself.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

__all__ = ["WARM_CASES", "WarmError", "warm"]


#: One case per model (and the Monte Carlo study): running each once, with ``--out`` (the
#: output writers have kernels too), compiles every kernel a command can need.
WARM_CASES: tuple[tuple[str, str, str], ...] = (
    ("run", "seed002_608.toml", "linear"),
    ("run", "seed000_tada_fig7.toml", "quasi_static_3d"),
    ("run", "seed001_kim_spindle.toml", "quasi_static_2d"),
    ("run", "seed001_kim_equilibrium.toml", "equilibrium"),
    ("run", "seed003_purohit.toml", "dynamic"),
    ("run", "seed004_nu209.toml", "roller_constraint"),
    ("run", "spindle_hdd.toml", "spindle"),
    ("study", "seed001_kim_table9.toml", "Monte Carlo study"),
)

#: The longest one case may take (a loaded 2-core machine compiles a model in under a minute).
CASE_TIMEOUT_S = 600.0


class WarmError(RuntimeError):
    """A warm-up case failed: its command and the last line it printed on stderr."""


def warm(
    examples: Path | None = None,
    on_case: Callable[[str, str, float | None], None] | None = None,
) -> list[tuple[str, float]]:
    """Compile every kernel into Numba's cache by running one case per model.

    Each case runs in its own process (``python -m runout.cli``, ``--out`` into a temporary
    directory that is removed afterwards), as a user's command would.

    Parameters
    ----------
    examples : Path, optional
        The directory holding the cases of :data:`WARM_CASES`; default the example files
        shipped with the package.
    on_case : callable, optional
        Called as ``on_case(model, file, None)`` before each case and ``on_case(model, file,
        seconds)`` after it (a progress display).

    Returns
    -------
    list of (str, float)
        Each model and its wall time [s].

    Raises
    ------
    WarmError
        When a case fails or runs past :data:`CASE_TIMEOUT_S`.
    """
    if examples is None:
        from runout.validation.cases import examples_dir

        examples = examples_dir()
    env = dict(os.environ, MPLBACKEND=os.environ.get("MPLBACKEND", "Agg"))
    times: list[tuple[str, float]] = []
    with tempfile.TemporaryDirectory(prefix="runout-warm-") as base:
        for verb, name, model in WARM_CASES:
            if on_case is not None:
                on_case(model, name, None)
            command = [sys.executable, "-m", "runout.cli", verb, str(examples / name)]
            command += ["--out", str(Path(base) / Path(name).stem)]
            t0 = time.perf_counter()
            try:
                proc = subprocess.run(
                    command,
                    stdout=subprocess.DEVNULL,
                    stderr=subprocess.PIPE,
                    text=True,
                    env=env,
                    timeout=CASE_TIMEOUT_S,
                    check=False,
                )
            except subprocess.TimeoutExpired:
                raise WarmError(
                    f"{verb} {name} ran past {CASE_TIMEOUT_S:.0f} s while warming the "
                    f"{model} kernels"
                ) from None
            if proc.returncode != 0:
                lines = [line for line in proc.stderr.splitlines() if line.strip()]
                last = lines[-1] if lines else f"exit status {proc.returncode}"
                raise WarmError(f"warming the {model} kernels failed ({verb} {name}): {last}")
            seconds = time.perf_counter() - t0
            times.append((model, seconds))
            if on_case is not None:
                on_case(model, name, seconds)
    return times
