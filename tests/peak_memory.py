"""Peak resident memory of a command, for the memory tests of the command line."""

from __future__ import annotations

import subprocess
import sys


def peak_rss(cmd: list[str]) -> float:
    """Peak resident memory of one command [B] (ru_maxrss of its own fresh parent, in KiB)."""
    probe = (
        "import resource, subprocess, sys; "
        "subprocess.run(sys.argv[1:], check=True, capture_output=True); "
        "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)"
    )
    done = subprocess.run(
        [sys.executable, "-c", probe, *cmd], check=True, capture_output=True, text=True
    )
    return 1024.0 * float(done.stdout.strip())
