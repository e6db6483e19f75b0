"""The built wheel works installed on its own: a plain install, every command, no extras.

The wheel is built from a copy of the source tree (offline: ``pip wheel --no-build-isolation
--no-index``) and installed with pip into a fresh virtual environment (``python -m venv``) as a
user's ``pip install runout`` would, console script included. Offline, its dependencies cannot
be downloaded: they are borrowed from the project's environment, but only those the wheel
declares (``Requires-Dist`` without an extra, and theirs, markers evaluated), each installed
distribution's own files linked into one directory that a ``.pth`` line puts on the path. So a
module the package imports without declaring it (click, once: typer stopped depending on it)
is missing there as it would be on a user's machine. ``pip check`` then checks the
environment, and ``runout --version``, ``check``, ``frequencies``, ``run`` and a small
``study`` of the examples run with the fresh environment's script, from another working
directory; ``runout reproduce --check`` compares VALIDATION.md. The tests assert that the
installed package, and its example files, are the ones imported.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import zipfile
from email.parser import Parser
from importlib import metadata
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
SHIPPED = ROOT / "src" / "runout" / "examples" / "data"
SYNC = "cp examples/*.toml src/runout/examples/data/"


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
        assert same, f"src/runout/examples/data/{name} is stale: {SYNC}"


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
    shipped = {Path(n).name for n in names if n.startswith("runout/examples/data/")}
    assert {p.name for p in EXAMPLES.glob("*.toml")} <= shipped, "the wheel lacks case files"
    assert "runout/catalogue/bearings.csv" in names, "the wheel lacks the bearing catalogue"
    venv = tmp_path_factory.mktemp("venv")
    _run([sys.executable, "-m", "venv", "--without-pip", str(venv)], dist)
    python = venv / ("Scripts/python.exe" if os.name == "nt" else "bin/python")
    purelib = "import sysconfig; print(sysconfig.get_paths()['purelib'])"
    target = Path(_run([str(python), "-c", purelib], dist).strip())
    borrowed = tmp_path_factory.mktemp("declared")
    for entry in _declared_closure(wheel):
        (borrowed / entry.name).symlink_to(entry, target_is_directory=entry.is_dir())
    (target / "_declared_dependencies.pth").write_text(f"{borrowed}\n", encoding="utf-8")
    _run(
        [*pip, "--python", str(python), "install", "--no-deps", "--no-index", "-q", str(wheel)],
        dist,
    )
    return python


def _requirements(text: str) -> list[Requirement]:
    """The requirements of a METADATA text that a plain install (no extra) brings."""
    found = []
    for line in Parser().parsestr(text).get_all("Requires-Dist") or []:
        req = Requirement(line)
        if req.marker is None or req.marker.evaluate({"extra": ""}):
            found.append(req)
    return found


def _declared_closure(wheel: Path) -> list[Path]:
    """The top-level entries in site-packages of every distribution a plain install brings.

    From the wheel's own METADATA, transitively through the installed distributions' metadata
    (a requirement's extras are followed: ``dask[distributed]`` brings distributed's).
    """
    with zipfile.ZipFile(wheel) as zf:
        (meta,) = [n for n in zf.namelist() if n.endswith(".dist-info/METADATA")]
        todo = _requirements(zf.read(meta).decode())
    seen: set[str] = set()
    entries: set[Path] = set()
    while todo:
        req = todo.pop()
        name = canonicalize_name(req.name)
        if name in seen:
            continue
        seen.add(name)
        dist = metadata.distribution(req.name)
        assert req.specifier.contains(dist.version, prereleases=True), (req, dist.version)
        base = Path(str(dist.locate_file("")))
        for file in dist.files or []:
            top = file.parts[0]
            if top != ".." and not top.endswith(".pth") and top != "__pycache__":
                entries.add(base / top)
        for line in dist.requires or []:
            dep = Requirement(line)
            extras = [{"extra": e} for e in req.extras] or [{"extra": ""}]
            if dep.marker is None or any(dep.marker.evaluate(e) for e in extras):
                todo.append(dep)
    return sorted(e for e in entries if e.exists())


def _env() -> dict[str, str]:
    """The environment for the installed script: no PYTHONPATH into the checkout."""
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}


def test_plain_install_has_no_undeclared_dependency(installed: Path, tmp_path: Path) -> None:
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check", "--python", str(installed)]
    assert "No broken requirements" in _run([*pip, "check"], tmp_path, _env())
    visible = _run([*pip, "list", "--format=freeze"], tmp_path, _env())
    names = {canonicalize_name(line.split("==")[0]) for line in visible.split()}
    # what only the extras bring is not there (click came with them and hid a crash)
    assert "runout" in names and "numba" in names
    assert not names & {"click", "dask", "pandas", "pytest", "mkdocs", "xarray"}, names


def test_every_command_runs_from_a_plain_install(installed: Path, tmp_path: Path) -> None:
    runout = installed.with_name("runout.exe" if os.name == "nt" else "runout")
    version = _run([str(runout), "--version"], tmp_path, _env())
    assert version.split() == ["runout", metadata.version("runout")]
    case = EXAMPLES / "seed002_608.toml"
    assert "is valid" in _run([str(runout), "check", str(case)], tmp_path, _env())
    assert "cage" in _run([str(runout), "frequencies", str(case)], tmp_path, _env())
    # the 3-D quasi-static model's Newton solve is a compiled kernel (the linear model has none)
    compiled = EXAMPLES / "seed000_tada_fig7.toml"
    first = subprocess.run(
        [str(runout), "run", str(compiled), "--json"],
        cwd=tmp_path,
        env={**_env(), "RUNOUT_COMPILE_NOTICE": "1"},  # stderr is a pipe here, not a terminal
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert first.returncode == 0, first.stderr
    assert json.loads(first.stdout)["model"] == "quasi_static_3d"
    assert (
        json.loads(_run([str(runout), "run", str(case), "--json"], tmp_path, _env()))["model"]
        == "linear"
    )
    # a fresh installation compiles its kernels once, and says so on stderr
    assert "compiling" in first.stderr, first.stderr
    study = EXAMPLES / "seed001_kim_table9.toml"
    small = ["--set", "study.samples=8"]
    doc = json.loads(_run([str(runout), "study", str(study), *small, "--json"], tmp_path, _env()))
    assert doc["samples"] == 8
    assert "runout" in _run([str(runout), "--help"], tmp_path, _env())
    # [bearing] designation reads the catalogue the wheel ships
    cwru = EXAMPLES / "cwru_6205_drive_end.toml"
    assert "Case Western" in _run([str(runout), "check", str(cwru)], tmp_path, _env())
    listing = _run([str(runout), "catalogue", "NU2"], tmp_path, _env())
    assert "NU209" in listing


def test_installed_wheel_reproduces_validation_md(installed: Path, tmp_path: Path) -> None:
    env = _env()
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
