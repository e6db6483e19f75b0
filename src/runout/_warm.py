"""Warm numba's cache: compile every kernel a command can need, once, at install.

``python -m runout._warm EXAMPLES_DIR`` (run by ``make install``) runs one case per model, as a
user would, so that the first command after installation does not wait 10-30 s for the kernels
of its model to compile.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

__all__ = ["WARM_CASES", "warm"]


#: One case per model (and the Monte Carlo study): running each once compiles every kernel a
#: command can need into numba's cache. Paths relative to the repository's ``examples/``.
WARM_CASES: tuple[tuple[str, str], ...] = (
    ("run", "seed000_tada_fig7.toml"),  # quasi_static_3d
    ("run", "seed001_kim_spindle.toml"),  # quasi_static_2d
    ("run", "seed001_kim_equilibrium.toml"),  # equilibrium
    ("run", "seed002_608.toml"),  # linear
    ("run", "seed003_purohit.toml"),  # dynamic
    ("run", "seed004_nu209.toml"),  # roller_constraint
    ("run", "spindle_hdd.toml"),  # spindle
    ("study", "seed001_kim_table9.toml"),  # Monte Carlo (batched kernels)
)


def warm(examples: Path, out: Path | None = None) -> list[tuple[str, float]]:
    """Compile every kernel into numba's cache by running one case per model, as a user would.

    The kernels are compiled on first use (``cache=True``), which costs 10-30 s for a model
    on a busy 2-core machine: ``make install`` calls this once so that the first command a
    user runs starts from a warm cache. Each case runs in its own process with ``--out`` (the
    output writers have kernels too) into a temporary directory.

    Parameters
    ----------
    examples : Path
        The directory holding the cases of :data:`WARM_CASES`.
    out : Path or None
        Where the outputs go; default a temporary directory, removed afterwards.

    Returns
    -------
    list of (str, float)
        Each case and its wall time [s].
    """
    import shutil
    import subprocess
    import tempfile
    import time

    script = Path(sys.executable).with_name("runout")
    command = [str(script)] if script.exists() else [sys.executable, "-m", "runout.cli"]
    env = dict(os.environ, MPLBACKEND=os.environ.get("MPLBACKEND", "Agg"))
    base = Path(tempfile.mkdtemp(prefix="runout-warm-")) if out is None else out
    times: list[tuple[str, float]] = []
    try:
        for verb, name in WARM_CASES:
            t0 = time.perf_counter()
            subprocess.run(
                [*command, verb, str(examples / name), "--out", str(base / Path(name).stem)],
                check=True,
                stdout=subprocess.DEVNULL,
                env=env,
            )
            times.append((f"{verb} {name}", time.perf_counter() - t0))
    finally:
        if out is None:
            shutil.rmtree(base, ignore_errors=True)
    return times


if __name__ == "__main__":  # python -m runout._warm EXAMPLES_DIR
    where = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("examples")
    for what, seconds in warm(where):
        print(f"compiled the kernels of {what} ({seconds:.1f} s)")
