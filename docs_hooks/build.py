"""Build the documentation site strictly and check it: ``python docs_hooks/build.py SITE_DIR``.

``make docs`` regenerates the generated pages (case-file reference, conventions) first and then
calls this; the test suite calls :func:`build` directly. The validation and benchmark pages are
copies of VALIDATION.md and BENCHMARKS.md made here (they are not committed under ``docs/``).
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

from site_check import check_site  # noqa: E402

#: Pages copied from the repository's top level into the site's sources.
COPIED = {"VALIDATION.md": "validation.md", "BENCHMARKS.md": "benchmarks.md"}


def build(site_dir: Path) -> list[str]:
    """Build the site into ``site_dir`` with ``mkdocs build --strict``; return the check's findings.

    Raises
    ------
    RuntimeError
        When mkdocs fails (its output is in the message).
    """
    for source, target in COPIED.items():
        shutil.copyfile(ROOT / source, ROOT / "docs" / target)
    command = [sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(site_dir)]
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise RuntimeError(f"mkdocs build failed:\n{done.stdout}\n{done.stderr}")
    return check_site(site_dir)


if __name__ == "__main__":
    site = Path(sys.argv[1]).resolve()
    found = build(site)
    print("\n".join(found) or f"documentation: {site / 'index.html'} (site check clean)")
    raise SystemExit(1 if found else 0)
