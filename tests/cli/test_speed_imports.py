"""The light commands stay light: what `--help`, `frequencies` and `check` leave unimported.

A behaviour test, not a timing test: each command runs in a fresh interpreter, and the
heavy libraries a command does not need must not be in ``sys.modules`` afterwards (scipy.signal
cost ~1 s, scipy.optimize ~0.15 s, scipy.special ~0.1 s, dask ~0.1 s through pint, matplotlib
~0.5 s).
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

_PROBE = """
import json, sys
sys.argv = ["runout", *json.loads(sys.argv[1])]
from runout.cli.commands import app  # main() would end the process before the probe prints
try:
    app()
except SystemExit as exc:
    code = exc.code
else:
    code = 0
print("\\nMODULES " + json.dumps([code, sorted(m for m in sys.modules)]))
"""

NEVER = (
    "scipy.signal",
    "scipy.special",
    "scipy.optimize",
    "dask",
    "matplotlib",
    "PIL",
    "threadpoolctl",
)


def _modules(*args: str) -> set[str]:
    proc = subprocess.run(
        [sys.executable, "-c", _PROBE, json.dumps(list(args))],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    last = proc.stdout.rsplit("\nMODULES ", 1)[-1]
    code, modules = json.loads(last)
    assert code in (0, None), proc.stderr
    return set(modules)


@pytest.mark.parametrize("command", ["frequencies", "check"])
@pytest.mark.parametrize("case", ["seed000_tada_fig7.toml", "seed004_nu209.toml"])
def test_light_commands_import_no_heavy_library(command: str, case: str) -> None:
    loaded = _modules(command, str(EXAMPLES / case))
    assert not [m for m in NEVER if m in loaded]


def test_frequencies_of_a_roller_bearing_needs_no_scipy_subpackage() -> None:
    # no contact angle to solve for: neither the elliptic integrals nor a root finder (pint
    # imports the bare scipy package to look for it, a few milliseconds)
    loaded = _modules("frequencies", str(EXAMPLES / "seed004_nu209.toml"))
    assert not [m for m in ("scipy.special", "scipy.linalg", "scipy.optimize") if m in loaded]


def test_help_imports_neither_scipy_nor_numba_nor_pint() -> None:
    loaded = _modules("--help")
    assert not [m for m in (*NEVER, "scipy", "numba", "pint", "pydantic") if m in loaded]


@pytest.mark.parametrize("case", ["seed000_tada_fig7.toml", "seed004_nu209.toml"])
def test_frequencies_compile_nothing(case: str) -> None:
    """``frequencies`` solves the loaded contact angle (Hertz, elliptic integrals) in NumPy:
    numba (~0.2 s to import, and it pulls scipy.linalg) is for the models."""
    loaded = _modules("frequencies", str(EXAMPLES / case))
    assert "numba" not in loaded and "runout.geometry._elliptic_kernel" not in loaded


def test_run_out_of_the_linear_model_imports_no_numba(tmp_path: Path) -> None:
    """The linear model compiles nothing, and neither do its files: ``run --out`` of a linear
    case must not import numba (~0.3 s) nor load the roller or CSV kernels (~0.5 s from the
    cache) to write a record a few hundred thousand values long (issue 31: ``--out`` within
    2x ``--json``)."""
    loaded = _modules("run", str(EXAMPLES / "seed002_608.toml"), "--out", str(tmp_path / "o"))
    assert (tmp_path / "o" / "history.csv").is_file()
    assert "numba" not in loaded
    assert "runout.models._roller_kernels" not in loaded


def test_run_json_imports_no_plotting_library() -> None:
    """Only ``--out`` loads matplotlib and Pillow (~0.4 s): ``--json`` never does."""
    loaded = _modules("run", str(EXAMPLES / "seed002_608.toml"), "--json")
    assert "matplotlib" not in loaded and "PIL" not in loaded
