"""Where runout may write: one policy for the output directories of every command.

``runout run``, ``diagnose``, ``report``, ``study`` and ``sweep-dynamic`` write only

* into a directory that is new, empty, or runout's own: it holds :data:`MARKER` (the names of
  the files runout wrote there), or it is an output of an earlier version, recognised by its
  files (a study's ``manifest.json``; a run's ``result.json`` beside its ``case.toml``);
  another non-empty directory is refused unless ``--force`` (:func:`claim`);
* never over a file runout did not write, even with ``--force`` (:func:`check_target`);
* never through a symbolic link named like an output file, nor into a linked subdirectory;
* never into ``/``, a system directory or a home directory itself (:func:`system_directory`);
* each file through a temporary name in the same directory, renamed over the target
  (:func:`write_atomic`); the files of one command are written into a private staging
  directory and renamed into place together once all are written (:func:`staged`), so a
  full disk or an interrupt leaves the directory as it was, never a truncated file.

Every refusal is an :class:`OutputError`: one line naming the directory or file and what to do.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import secrets
import shutil
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import IO, Any

from runout.base.errors import RunoutError

__all__ = [
    "MARKER",
    "OutputError",
    "check_target",
    "claim",
    "output_directory",
    "owned",
    "record",
    "staged",
    "system_directory",
    "write_atomic",
    "write_owned",
]

#: The file listing what runout wrote into a directory (JSON: format, files).
MARKER = ".runout-files.json"
#: ``format`` of :data:`MARKER`.
MARKER_FORMAT = "runout-files/1"
#: Temporary files of :func:`write_atomic`: ``.<name>.<12 hex digits>.tmp``.
TEMP_NAME = re.compile(r"^\..+\.[0-9a-f]{12}\.tmp$")
#: Staging directories of :func:`staged`: ``.runout-<random>.tmp``.
STAGE_NAME = re.compile(r"^\.runout-[A-Za-z0-9_]+\.tmp$")

#: System trees: refused with everything under them.
_SYSTEM_TREES = ("/bin", "/boot", "/dev", "/etc", "/lib", "/lib32", "/lib64", "/libx32",
                 "/proc", "/sbin", "/sys", "/usr")  # fmt: skip
#: Directories refused themselves (their subdirectories are fine: /tmp/x, /home/me/out).
_SYSTEM_ROOTS = ("/", "/home", "/root", "/var", "/tmp", "/opt", "/srv", "/mnt", "/media", "/run")

#: What earlier versions wrote, by the file that identifies the directory (no marker then).
_LEGACY = {
    # a study: its manifest, chunks, tables, plots, and the report runout report adds
    "manifest.json": re.compile(
        r"^(manifest\.json|summary\.json|samples\.csv|samples_columns\.json|stiffness\.csv"
        r"|histograms\.png|sweep_.+\.png|report\.html|chunks(/chunk_\d+\.json)?)$"
    ),
    # a run: result.json beside case.toml, the tables, figures and model files it writes
    "result.json": re.compile(
        r"^(result\.json|history\.csv|lines\.csv|summary\.json|case\.toml|report\.html"
        r"|balls\.csv|stiffness\.csv|spectrum\.csv|contacts\.csv|order_sweep\.csv"
        r"|[a-z0-9_]+\.png|bearing\.gif)$"
    ),
}


class OutputError(RunoutError):
    """An output directory or file runout must not or cannot write (one line naming it)."""


def system_directory(path: Path) -> bool:
    """Whether ``path`` (resolved) is ``/``, a system directory or a home directory itself.

    Parameters
    ----------
    path : Path
        A directory.

    Returns
    -------
    bool
        True for ``/``, anything under ``/usr``, ``/etc``, ``/bin``, ``/sbin``, ``/lib*``,
        ``/boot``, ``/dev``, ``/proc``, ``/sys``, and for ``/home``, ``/root``, ``/var``,
        ``/tmp``, ``/opt``, ``/srv``, ``/mnt``, ``/media``, ``/run`` and the user's home
        directory themselves (not their subdirectories).
    """
    if os.name == "nt":  # pragma: no cover - no such tree on Windows
        return False
    real = os.path.realpath(path)
    if any(real == top or real.startswith(top + "/") for top in _SYSTEM_TREES):
        return True
    roots = {os.path.realpath(p) for p in _SYSTEM_ROOTS}
    with contextlib.suppress(RuntimeError, KeyError):
        roots.add(os.path.realpath(Path.home()))
    return real in roots


def output_directory(out: Path | str, option: str = "--out") -> Path:
    """Check ``out`` can be an output directory and create it (with its parents).

    Parameters
    ----------
    out : path or str
        As the user gave it. An empty string is refused: ``Path("")`` is the current
        directory, and writing there by accident would mix files with the user's.
    option : str
        Name of the option in messages.

    Returns
    -------
    Path
        ``out``, an existing directory.

    Raises
    ------
    OutputError
        One line naming the path: empty, an existing file (``/dev/null`` too), a system
        directory, or a directory that cannot be created or written.
    """
    if isinstance(out, str) and not out.strip():
        raise OutputError(f"{option}: empty path; give a directory (use {option} . for this one)")
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise OutputError(f"{option} {path}: exists and is not a directory")
    if system_directory(path):
        raise OutputError(
            f"{option} {path}: a system or home directory; choose a new directory for the output"
        )
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(
            f"{option} {path}: cannot create the directory ({exc.strerror or exc})"
        ) from None
    writable(path, option)
    return path


def writable(directory: Path, option: str = "--out") -> None:
    """Refuse ``directory`` when the file system will not let runout create files in it.

    Parameters
    ----------
    directory : Path
        An existing directory.
    option : str
        Name of the option in messages.

    Raises
    ------
    OutputError
        Naming the directory (read-only file system, no permission).
    """
    if not os.access(directory, os.W_OK | os.X_OK):
        raise OutputError(
            f"{option} {directory}: cannot write into the directory (read-only or no "
            "permission); choose a writable directory"
        )


def _read_marker(directory: Path) -> set[str] | None:
    """The names :data:`MARKER` lists, or None (no marker, a link, or not a marker)."""
    path = directory / MARKER
    if path.is_symlink() or not path.is_file():
        return None
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    files = doc.get("files") if isinstance(doc, dict) else None
    if (
        not isinstance(doc, dict)
        or doc.get("format") != MARKER_FORMAT
        or not isinstance(files, list)
    ):
        return None
    return {f for f in files if isinstance(f, str)}


def _json_object(path: Path) -> dict[str, Any] | None:
    """The JSON object of ``path`` (a plain file, not a link), or None."""
    if path.is_symlink() or not path.is_file():
        return None
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return doc if isinstance(doc, dict) else None


def _legacy_kind(directory: Path) -> re.Pattern[str] | None:
    """The names an earlier version wrote into ``directory``, when it is recognised as one.

    A study's ``manifest.json`` states its format (``runout-study/N``; a manifest damaged
    beyond reading is the study's own problem, reported by the study); a run's
    ``result.json`` is an object naming its model, beside ``case.toml``.
    """
    manifest = directory / "manifest.json"
    if manifest.is_file() and not manifest.is_symlink():
        doc = _json_object(manifest)
        if doc is None or str(doc.get("format", "")).startswith("runout-study/"):
            return _LEGACY["manifest.json"]
    case = directory / "case.toml"
    if case.is_file() and not case.is_symlink():
        doc = _json_object(directory / "result.json")
        if doc is not None and "model" in doc:
            return _LEGACY["result.json"]
    return None


def owned(directory: Path, name: str) -> bool:
    """Whether runout wrote ``directory / name``.

    Parameters
    ----------
    directory : Path
        The output directory.
    name : str
        Relative, ``/``-separated name of a file in it.

    Returns
    -------
    bool
        Listed in the directory's :data:`MARKER`; in a directory an earlier version wrote (no
        marker), a name of the files that version wrote there.
    """
    names = _read_marker(directory)
    if names is not None:
        return name in names
    legacy = _legacy_kind(directory)
    return legacy is not None and legacy.match(name) is not None


def is_ours(directory: Path) -> bool:
    """Whether ``directory`` is runout's.

    Parameters
    ----------
    directory : Path
        An existing directory.

    Returns
    -------
    bool
        It holds :data:`MARKER`, or the files of an earlier version's run or study.
    """
    return _read_marker(directory) is not None or _legacy_kind(directory) is not None


def _entries(directory: Path) -> list[str]:
    """Names in ``directory`` besides runout's marker, lock, temporary and staging files."""
    return sorted(
        p.name
        for p in directory.iterdir()
        if p.name not in (MARKER, ".lock")
        and not TEMP_NAME.match(p.name)
        and not STAGE_NAME.match(p.name)
    )


def claim(directory: Path, *, force: bool, option: str = "--out") -> None:
    """Refuse a non-empty ``directory`` that is not runout's, unless ``force``.

    Parameters
    ----------
    directory : Path
        An existing directory (:func:`output_directory`).
    force : bool
        Write into it anyway; even then only files runout wrote are replaced
        (:func:`check_target`).
    option : str
        Name of the option in messages.

    Raises
    ------
    OutputError
        Naming the directory and its first entry.
    """
    if force or is_ours(directory):
        return
    try:
        entries = _entries(directory)
    except OSError as exc:
        raise OutputError(f"{option} {directory}: cannot list ({exc.strerror or exc})") from None
    if entries:
        raise OutputError(
            f"{option} {directory}: not empty and not a runout output (it holds "
            f"{entries[0]!r}); choose an empty directory or pass --force to write beside "
            "those files"
        )


def check_target(directory: Path, name: str) -> Path:
    """``directory / name``, checked: no link on the way, not a file of the user's.

    Parameters
    ----------
    directory : Path
        The output directory.
    name : str
        Relative, ``/``-separated name of the file runout is about to write.

    Returns
    -------
    Path
        The target.

    Raises
    ------
    OutputError
        The target or a directory between it and ``directory`` is a symbolic link or not a
        directory, or the target exists and runout did not write it.
    """
    target = directory / name
    parent = directory
    for part in Path(name).parts[:-1]:
        parent = parent / part
        if parent.is_symlink() or (parent.exists() and not parent.is_dir()):
            raise OutputError(
                f"{parent}: a link or a file where runout writes a directory; remove it or "
                "choose another directory"
            )
    if target.is_symlink():
        raise OutputError(
            f"{target}: a symbolic link; runout does not write through links (remove it or "
            "choose another directory)"
        )
    if target.exists() and (target.is_dir() or not owned(directory, name)):
        raise OutputError(
            f"{target}: exists and was not written by runout; runout replaces only its own "
            "files, even with --force (move it away or choose another directory)"
        )
    return target


def record(directory: Path, names: list[str]) -> None:
    """Add ``names`` to the directory's :data:`MARKER` (written atomically).

    Parameters
    ----------
    directory : Path
        The output directory.
    names : list of str
        Relative, ``/``-separated names of the files runout writes there.

    Raises
    ------
    OutputError
        The marker cannot be written.
    """
    known = _read_marker(directory) or set()
    doc = {"format": MARKER_FORMAT, "files": sorted(known | set(names))}
    text = json.dumps(doc, indent=1) + "\n"
    write_atomic(directory / MARKER, lambda fh: fh.write(text))


def write_atomic(path: Path, write: Callable[[IO[Any]], Any], *, binary: bool = False) -> Path:
    """Write ``path`` through a uniquely named temporary file in the same directory.

    ``os.replace`` within one directory is atomic: a reader sees the old file or the new one,
    never half of one; a full disk or an interrupt leaves the old file and no temporary
    (removed on the way out; one a killed process leaves is recognised by :data:`TEMP_NAME`).
    The temporary is created with O_EXCL (never through a link, never another writer's) and
    mode 0o666 minus the umask, like any file the user writes.

    Parameters
    ----------
    path : Path
        The file to write; a symbolic link there is refused (replacing it would drop the
        user's link, writing through it would write outside the directory).
    write : callable
        Called with the open temporary file (text, UTF-8, no newline translation; or binary).
    binary : bool
        Open the temporary in binary mode.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    OutputError
        Naming ``path``: a link, or the file system refuses (read-only, full, permissions).
    """
    if path.is_symlink():
        raise OutputError(
            f"{path}: a symbolic link; runout does not write through links (remove it or "
            "choose another directory)"
        )
    try:
        for _ in range(100):
            tmp = path.with_name(f".{path.name}.{secrets.token_hex(6)}.tmp")
            try:
                fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                continue
            break
        else:  # pragma: no cover - 100 collisions of 48 random bits
            raise FileExistsError(f"no free temporary name next to {path}")
        try:
            handle = (
                os.fdopen(fd, "wb") if binary else os.fdopen(fd, "w", encoding="utf-8", newline="")
            )
            with handle as fh:
                write(fh)
            os.replace(tmp, path)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
    except OSError as exc:
        raise OutputError(f"{path}: cannot write ({exc.strerror or exc})") from None
    return path


def write_owned(
    directory: Path, name: str, write: Callable[[IO[Any]], Any], *, binary: bool = False
) -> Path:
    """Write one file ``directory / name`` under the policy: checked, listed, atomic.

    Parameters
    ----------
    directory : Path
        The output directory (existing).
    name : str
        The file's name in it.
    write : callable
        Called with the open temporary file (:func:`write_atomic`).
    binary : bool
        Open it in binary mode.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    OutputError
        The target is refused (:func:`check_target`) or cannot be written.
    """
    target = check_target(directory, name)
    record(directory, [name])
    return write_atomic(target, write, binary=binary)


@contextlib.contextmanager
def staged(directory: Path, option: str = "--out") -> Iterator[Staging]:
    """A private staging directory inside ``directory``, moved into place on success.

    The command writes its files into ``staging.path`` (any writer, any number of files,
    subdirectories too). When the block ends normally every file is checked
    (:func:`check_target`) before any is moved, then each is renamed over its target and
    :data:`MARKER` lists them; a refusal or a failure leaves ``directory`` as it was and
    removes the staging directory.

    Parameters
    ----------
    directory : Path
        The output directory (existing, checked by :func:`output_directory`).
    option : str
        Name of the option in messages.

    Yields
    ------
    Staging
        Write into its ``path``; its ``written`` lists the final files after the block.

    Raises
    ------
    OutputError
        ``directory`` cannot be written, a file runout wrote cannot be written (disk full:
        naming it), or a target is refused.
    """
    try:
        path = Path(tempfile.mkdtemp(prefix=".runout-", suffix=".tmp", dir=directory))
    except OSError as exc:
        raise OutputError(
            f"{option} {directory}: cannot write into the directory ({exc.strerror or exc}); "
            "choose a writable directory"
        ) from None
    stage = Staging(directory, path)
    try:
        try:
            yield stage
        except OSError as exc:  # a writer failed (disk full): nothing reached the directory
            name = stage.final(exc.filename) if _inside(exc.filename, path) else directory
            raise OutputError(f"{name}: cannot write ({exc.strerror or exc})") from None
        stage.commit()
    finally:
        shutil.rmtree(path, ignore_errors=True)


def _inside(filename: Any, directory: Path) -> bool:
    """Whether ``filename`` (an OSError's, maybe None) names a path inside ``directory``."""
    if not isinstance(filename, str | os.PathLike):
        return False
    return Path(os.fspath(filename)).is_relative_to(directory)


class Staging:
    """The staging directory of :func:`staged`: write into :attr:`path`, read :attr:`final`.

    Parameters
    ----------
    directory : Path
        The output directory.
    path : Path
        The staging directory inside it (created by :func:`staged`).
    """

    def __init__(self, directory: Path, path: Path) -> None:
        self.directory = directory
        self.path = path
        self.written: list[Path] = []

    def final(self, staged_path: Path) -> Path:
        """Where a file written at ``staged_path`` ends.

        Parameters
        ----------
        staged_path : Path
            A file written under :attr:`path`.

        Returns
        -------
        Path
            The same name in the output directory.
        """
        return self.directory / Path(staged_path).relative_to(self.path)

    def commit(self) -> list[Path]:
        """Check every staged file's target, then move them all; record them in the marker.

        Returns
        -------
        list of Path
            The files now in the output directory.

        Raises
        ------
        OutputError
            A target is refused (nothing moved) or cannot be written.
        """
        names = sorted(
            p.relative_to(self.path).as_posix()
            for p in self.path.rglob("*")
            if p.is_file() and not p.is_symlink()
        )
        for name in names:
            check_target(self.directory, name)
        # listed first: a file moved in is never left unlisted (and so not replaceable)
        record(self.directory, names)
        try:
            for name in names:
                target = self.directory / name
                target.parent.mkdir(parents=True, exist_ok=True)
                os.replace(self.path / name, target)
        except OSError as exc:
            raise OutputError(
                f"{exc.filename or self.directory}: cannot write ({exc.strerror or exc})"
            ) from None
        self.written = [self.directory / name for name in names]
        return self.written
