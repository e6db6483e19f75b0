"""`runout reproduce` works from an installed wheel, not only from a source checkout.

The example case files the validation computes from ship inside the package
(``runout/_examples_data``, copies of ``examples/*.toml``). The wheel is built from a copy of
the source tree (offline: ``pip wheel --no-build-isolation --no-index``) and installed into a
fresh virtual environment (``python -m venv``; offline, its dependencies -- numpy, scipy,
numba, ... -- are borrowed from the project's environment through a ``.pth`` line, which does
not carry the checkout's editable install); ``runout reproduce --check`` runs with the fresh
environment's interpreter, from another working directory, against the repository's
VALIDATION.md. The test asserts that the installed package, and its example files, are the
ones imported.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
SHIPPED = ROOT / "src" / "runout" / "_examples_data"
SYNC = "cp examples/*.toml src/runout/_examples_data/"


def _run(args: list[str], cwd: Path, env: dict[str, str] | None = None) -> str:
    proc = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, f"{args}\n{proc.stdout}\n{proc.stderr}"
    return proc.stdout


def test_shipped_case_files_equal_the_examples_directory() -> None:
    # examples/ is what users read and run; the package carries the same bytes
    ours = sorted(p.name for p in EXAMPLES.glob("*.toml"))
    shipped = sorted(p.name for p in SHIPPED.glob("*.toml"))
    assert ours, "no example case files"
    assert shipped == ours, f"the shipped case files differ from examples/: {SYNC}"
    for name in ours:
        same = (SHIPPED / name).read_bytes() == (EXAMPLES / name).read_bytes()
        assert same, f"src/runout/_examples_data/{name} is stale: {SYNC}"


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The wheel built from a copy of the tree, installed into a fresh venv: its interpreter."""
    source = tmp_path_factory.mktemp("source")
    # a copy: the build writes build/ and *.egg-info next to the sources
    ignore = shutil.ignore_patterns("__pycache__", "*.egg-info", "*.pyc")
    shutil.copytree(ROOT / "src", source / "src", ignore=ignore)
    for name in ("pyproject.toml", "README.md"):
        shutil.copy2(ROOT / name, source / name)
    dist = tmp_path_factory.mktemp("dist")
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check", "--no-cache-dir"]
    _run(
        [
            *pip,
            "wheel",
            "--no-deps",
            "--no-build-isolation",
            "--no-index",
            "-q",
            "-w",
            str(dist),
            str(source),
        ],
        source,
    )
    (wheel,) = dist.glob("runout-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    shipped = {Path(n).name for n in names if n.startswith("runout/_examples_data/")}
    assert {p.name for p in EXAMPLES.glob("*.toml")} <= shipped, "the wheel lacks case files"
    venv = tmp_path_factory.mktemp("venv")
    _run([sys.executable, "-m", "venv", "--without-pip", str(venv)], dist)
    python = venv / ("Scripts/python.exe" if os.name == "nt" else "bin/python")
    purelib = "import sysconfig; print(sysconfig.get_paths()['purelib'])"
    target = Path(_run([str(python), "-c", purelib], dist).strip())
    ours = Path(_run([sys.executable, "-c", purelib], dist).strip())
    # the dependencies only: a path added by a .pth line does not process that directory's
    # own .pth files, so the checkout's editable install of runout stays out
    (target / "_dependencies.pth").write_text(f"{ours}\n", encoding="utf-8")
    _run(
        [*pip, "install", "--no-deps", "--no-index", "-q", "--target", str(target), str(wheel)],
        dist,
    )
    return python


def test_installed_wheel_reproduces_validation_md(installed: Path, tmp_path: Path) -> None:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    where = _run(
        [
            str(installed),
            "-c",
            "import runout; from runout.validation.cases import examples_dir; "
            "print(runout.__file__); print(examples_dir())",
        ],
        tmp_path,
        env,
    ).splitlines()
    # the installed package and its own example files, not the checkout's src/ or examples/
    venv = installed.parents[1]
    assert Path(where[0]).is_relative_to(venv), where
    assert Path(where[1]).is_relative_to(venv), where
    out = _run(
        [
            str(installed),
            "-m",
            "runout.cli",
            "reproduce",
            "--check",
            "--out",
            str(ROOT / "VALIDATION.md"),
        ],
        tmp_path,
        env,
    )
    assert "is up to date" in out
