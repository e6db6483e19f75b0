"""MkDocs hooks: serve KaTeX from the site itself.

The documentation renders its mathematics with KaTeX. Readers may have no access to a CDN
(the project's own machines have none), so the site carries its own copy: the pinned KaTeX
release is fetched once from the npm registry with ``npm pack`` into ``out/katex/`` (not
committed) and copied into ``assets/katex/`` of every build.
"""

from __future__ import annotations

import shutil
import subprocess
import tarfile
from pathlib import Path
from typing import Any

KATEX_VERSION = "0.16.22"
ROOT = Path(__file__).resolve().parents[1]
CACHE = ROOT / "out" / "katex" / KATEX_VERSION
#: What the pages load (see ``extra_javascript``/``extra_css`` in mkdocs.yml) and its fonts.
ASSETS = ("katex.min.js", "katex.min.css", "fonts")


def katex_dist() -> Path:
    """The unpacked ``dist`` folder of the pinned KaTeX release, fetched on first use."""
    dist = CACHE / "package" / "dist"
    if (dist / "katex.min.js").is_file():
        return dist
    CACHE.mkdir(parents=True, exist_ok=True)
    spec = f"katex@{KATEX_VERSION}"
    try:
        subprocess.run(
            ["npm", "pack", spec, "--silent", "--pack-destination", str(CACHE)],
            check=True,
            capture_output=True,
            timeout=300,
        )
    except (OSError, subprocess.SubprocessError) as error:
        raise RuntimeError(
            f"the documentation needs KaTeX {KATEX_VERSION} to render its mathematics and "
            f"`npm pack {spec}` failed ({error}); install Node.js/npm or put the package's "
            f"files in {dist}"
        ) from error
    with tarfile.open(CACHE / f"katex-{KATEX_VERSION}.tgz") as archive:
        archive.extractall(CACHE, filter="data")
    return dist


def on_post_build(config: Any, **kwargs: Any) -> None:
    """Copy KaTeX's script, style sheet and fonts into ``assets/katex``."""
    dist = katex_dist()
    target = Path(config["site_dir"]) / "assets" / "katex"
    for name in ASSETS:
        source, dest = dist / name, target / name
        dest.parent.mkdir(parents=True, exist_ok=True)
        if source.is_dir():
            shutil.copytree(source, dest, dirs_exist_ok=True)
        else:
            shutil.copy2(source, dest)
