"""The console script ends without the interpreter's teardown (issue 16: about 0.2 s of every
command freed Numba's and LLVM's code object by object) and keeps what a normal exit gives:
the exit status, every byte of stdout and stderr, and the files a command wrote."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "examples" / "seed000_tada_fig7.toml"
SCRIPT = Path(sys.executable).with_name("runout")


def _runout(*args: str) -> subprocess.CompletedProcess[str]:
    command = [str(SCRIPT)] if SCRIPT.exists() else [sys.executable, "-m", "runout.cli"]
    return subprocess.run([*command, *args], capture_output=True, text=True, timeout=300)


def test_a_run_prints_all_its_json_and_exits_0(tmp_path: Path) -> None:
    done = _runout("run", str(CASE), "--json", "--out", str(tmp_path / "tada"))
    assert done.returncode == 0, done.stderr
    printed = json.loads(done.stdout)  # the whole document, flushed before the exit
    written = json.loads((tmp_path / "tada" / "result.json").read_text(encoding="utf-8"))
    assert printed == written
    assert (tmp_path / "tada" / "history.csv").stat().st_size > 100_000


def test_a_refused_case_exits_2_with_its_message(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text(CASE.read_text(encoding="utf-8").replace("elements = 8", "elements = 2"))
    done = _runout("check", str(bad))
    assert done.returncode == 2
    assert "bad.toml: bearing.elements" in done.stderr


def test_the_fast_exit_keeps_a_message_exit_and_a_status() -> None:
    code = (
        "import runout.cli.commands as c, sys\n"
        "c.app = lambda: (_ for _ in ()).throw(SystemExit('stopped: reason'))\n"
        "c.main()\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 1
    assert "stopped: reason" in done.stderr
    code = "import runout.cli.commands as c\nc.app = lambda: print('out') or exit(3)\nc.main()\n"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert (done.returncode, done.stdout) == (3, "out\n")


def test_the_drawing_processes_started_early_end_with_a_refused_run(tmp_path: Path) -> None:
    # `runout run ... --out` starts its drawing processes before the arguments are parsed; a
    # refused case, a usage error or --help ends them unused: the command returns (a process
    # left behind would hold the captured streams open), writes nothing and says why
    bad = tmp_path / "bad.toml"
    bad.write_text(CASE.read_text(encoding="utf-8").replace("elements = 8", "elements = 2"))
    out = tmp_path / "out"
    done = _runout("run", str(bad), "--out", str(out))
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and "bad.toml: bearing.elements" in done.stderr
    assert not out.exists()
    done = _runout("run", "--out", str(out), "--help")
    assert done.returncode == 0 and "--out" in done.stdout
    done = _runout("run", str(CASE), "--out", str(out), "--no-such-option")
    assert done.returncode == 2 and not out.exists()


def test_which_commands_start_drawing_early() -> None:
    from runout.cli.commands import _writes_files

    assert _writes_files(["run", "case.toml", "--out", "dir"])
    assert _writes_files(["run", "case.toml", "--out=dir"])
    assert _writes_files(["run", "case.toml", "--report"])
    assert not _writes_files(["run", "case.toml", "--json"])
    assert not _writes_files(["study", "case.toml", "--out", "dir"])
    assert not _writes_files([])
