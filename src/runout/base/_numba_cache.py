"""Where numba keeps its compiled kernels, when the installed package cannot.

The kernels are compiled with ``cache=True``: numba writes them next to the sources
(``__pycache__``) or into the user's cache directory. A read-only installation with an
unwritable (or missing) home directory offers neither, and numba then refuses to define the
kernels at all (``RuntimeError: cannot cache function ...: no locator available``): every
command would fail. :func:`ensure_numba_cache` runs before any kernel module is imported and,
in that case only, points ``NUMBA_CACHE_DIR`` to a private directory under the system's
temporary directory (compiled kernels are then cached there, per user).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

__all__ = ["ensure_numba_cache"]


def _writable(directory: Path) -> bool:
    """True when a file can be created in ``directory`` (created if missing)."""
    # a probe file of our own rather than tempfile, whose import costs ~10 ms of every start
    probe = directory / f".runout-probe-{os.getpid()}-{id(directory)}"
    try:
        directory.mkdir(parents=True, exist_ok=True)
        os.close(os.open(probe, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o600))
        os.unlink(probe)
    except OSError:
        return False
    return True


def _user_cache() -> Path:
    """numba's user-wide cache directory (``$XDG_CACHE_HOME/numba`` or ``~/.cache/numba``)."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "numba"


def ensure_numba_cache() -> str | None:
    """Give numba a writable cache directory when neither of its own is writable.

    Returns
    -------
    str or None
        The directory set as ``NUMBA_CACHE_DIR``, or None when nothing had to change (the
        variable is set already, or the package or user cache directory is writable).
    """
    if os.environ.get("NUMBA_CACHE_DIR"):
        return None
    package = Path(__file__).resolve().parent
    if _writable(package / "__pycache__") or _writable(_user_cache()):
        return None
    import tempfile  # only here: a read-only installation without a user cache

    uid = os.getuid() if hasattr(os, "getuid") else "user"
    fallback = Path(tempfile.gettempdir()) / f"runout-numba-cache-{uid}"
    if not _writable(fallback):
        fallback = Path(tempfile.mkdtemp(prefix="runout-numba-cache-"))
    os.environ["NUMBA_CACHE_DIR"] = str(fallback)
    config = sys.modules.get("numba.core.config")
    if config is not None:  # numba already imported: its configuration was read at import
        config.CACHE_DIR = str(fallback)  # type: ignore[attr-defined]
    return str(fallback)
