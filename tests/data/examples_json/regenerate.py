"""Rewrite the stored ``runout run --json`` output of every example case file.

Run only when a change of results is intended and explained in the commit:
``.venv/bin/python tests/data/examples_json/regenerate.py``. The test
``tests/cli/test_examples_json.py`` compares each example's JSON with these files, exactly up to
the last digits another machine moves (``tests/golden.py``), so that a refactor cannot change a
number unnoticed.
"""

from __future__ import annotations

import gzip
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parents[2] / "examples"


def example_json(case: Path) -> bytes:
    """The standard output of ``runout run CASE --json``."""
    done = subprocess.run(
        [sys.executable, "-m", "runout.cli", "run", str(case), "--json"],
        capture_output=True,
        check=True,
    )
    return done.stdout


def main() -> None:
    for case in sorted(EXAMPLES.glob("*.toml")):
        target = HERE / f"{case.stem}.json.gz"
        # mtime=0: the same output gives the same file
        target.write_bytes(gzip.compress(example_json(case), mtime=0))
        print(target.name)


if __name__ == "__main__":
    main()
