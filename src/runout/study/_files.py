"""A study's output directory: atomic files, one writer, only runout's own directories.

Part of :mod:`runout.study.run` (its module docstring describes studies).
"""

from __future__ import annotations

import contextlib
import math
import os
import re
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, TextIO

from runout.base.reading import InputFileError, read_json
from runout.io import output_dir as _policy
from runout.study._chunks import ChunkTask
from runout.study._plan import FORMAT, RUNOUT_KEYS, StudyError

try:
    import fcntl
except ImportError:  # pragma: no cover - Windows: O_EXCL lock files instead of flock
    fcntl = None  # type: ignore[assignment]


# --------------------------------------------------------------------------------------------
# output directories: atomic files, one writer, only runout's own directories
# --------------------------------------------------------------------------------------------
#: The lock file of an output directory (holds the writer's PID; removed when it ends).
LOCK_NAME = ".lock"
#: Temporary files of :func:`write_atomic`: ``.<name>.<12 hex digits>.tmp``.
_TEMP = re.compile(r"^\..+\.[0-9a-f]{12}\.tmp$")
#: What ``runout sweep-dynamic`` writes into its ``--out`` (legacy directories have no marker).
_SWEEP_DYNAMIC = re.compile(r"^(points|sweep\.csv|trend\.png|spectra_.+\.png)$")


class OutputError(StudyError, _policy.OutputError):
    """An output directory that cannot be used: not a directory, unwritable, foreign, locked."""


def write_atomic(path: Path, write: Callable[[TextIO], Any]) -> Path:
    """Write ``path`` through a uniquely named temporary file in the same directory.

    :func:`runout.io.output_dir.write_atomic`, text mode: a reader, or a study resumed after
    a kill, sees the old file or the new one, never half of one; two writers never share a
    temporary name (``.<name>.<random>.tmp``, O_EXCL), and a leftover of a killed run is
    removed by the next run (:func:`_remove_leftovers`). A symbolic link at ``path`` is
    refused, never written through.

    Raises
    ------
    OutputError
        Naming ``path`` when it is a link or the file system refuses (read-only, full,
        permissions).
    """
    try:
        return _policy.write_atomic(path, write)  # type: ignore[arg-type]  # opened in text mode
    except _policy.OutputError as exc:
        raise OutputError(str(exc)) from None


def output_directory(out: Path | str, option: str = "--out") -> Path:
    """Check ``out`` can be an output directory and create it (with its parents).

    :func:`runout.io.output_dir.output_directory`: an empty string, an existing file, a
    system or home directory, or a directory that cannot be created or written is refused.

    Raises
    ------
    OutputError
        One line naming the path.
    """
    try:
        return _policy.output_directory(out, option)
    except _policy.OutputError as exc:
        raise OutputError(str(exc)) from None


def _own_lock_file(path: Path) -> bool:
    """Whether ``path`` looks like a lock file of ours: empty or one PID."""
    try:
        text = path.read_text(encoding="ascii").strip()
    except (OSError, ValueError):
        return False
    return text == "" or text.isdigit()


def _entries(directory: Path) -> list[Path]:
    """What ``directory`` holds besides our lock file and leftover temporary files."""
    return sorted(
        p
        for p in directory.iterdir()
        if not (p.name == LOCK_NAME and _own_lock_file(p)) and not _TEMP.match(p.name)
    )


def refuse_foreign(directory: Path, kind: str, force: bool, option: str = "--out") -> None:
    """Refuse a non-empty ``directory`` that is not a runout output of ``kind``.

    A study replaces its own files (chunks, manifest, summary, CSV, plots) in its output
    directory; pointed by mistake at a directory of the user's (or of another command) it
    would overwrite files that happen to share those names and mix its files with others.

    Parameters
    ----------
    directory : Path
        An existing directory.
    kind : {"study", "sweep-dynamic"}
        A study directory holds a ``manifest.json`` of format FORMAT; a sweep-dynamic
        directory holds only ``points/``, ``sweep.csv``, ``trend.png`` and ``spectra_*.png``.
    force : bool
        Write into the directory anyway (only the files runout writes are replaced).

    Raises
    ------
    OutputError
        Naming the directory and the first entry that is not runout's.
    StudyError
        A study directory whose manifest is corrupted (naming the file).
    """
    try:
        entries = _entries(directory)
    except OSError as exc:
        raise OutputError(f"{option} {directory}: cannot list ({exc.strerror or exc})") from None
    if not entries:
        return
    if force:
        if kind == "study":
            _refuse_collisions(directory, entries)
        return
    if kind == "study":
        manifest = directory / "manifest.json"
        if manifest.exists() or manifest.is_symlink():  # a link or a device is named too
            _read_manifest(manifest)  # a corrupted manifest is an error of its own
            return
        foreign: Path | None = entries[0]
    else:
        foreign = next((p for p in entries if not _SWEEP_DYNAMIC.match(p.name)), None)
    if foreign is None:
        return
    raise OutputError(
        f"{option} {directory}: not empty and not a runout {kind} output (it holds "
        f"{foreign.name!r}); choose an empty directory or pass --force to write into it"
    )


#: The names a study writes (and a fresh study deletes) in its output directory.
STUDY_NAMES = re.compile(
    r"^(manifest\.json|summary\.json|samples\.csv|samples_columns\.json|stiffness\.csv"
    r"|histograms\.png|sweep_.+\.png|chunks)$"
)


def _refuse_collisions(directory: Path, entries: list[Path]) -> None:
    """Refuse (even with ``--force``) a study over a file of the user's that it would replace.

    In a study's own directory (a ``manifest.json`` of a study, or one too damaged to read)
    every study name is the study's;
    elsewhere a study name is runout's only when the directory's list of runout's files
    (:data:`runout.io.output_dir.MARKER`) holds it.
    """
    manifest = directory / "manifest.json"
    if manifest.is_file() and not manifest.is_symlink():
        try:  # the bounded reader: a manifest is read back like every file of ours
            doc = read_json(manifest, [directory])
        except (OSError, ValueError, InputFileError):
            return  # a corrupted manifest of a study: --force starts it afresh
        if isinstance(doc, dict) and doc.get("format") == FORMAT:
            return
        chunks = directory / "chunks"
        if chunks.is_dir() and not chunks.is_symlink() and any(chunks.glob("chunk_*.json")):
            return  # a study's manifest damaged beside its chunks: --force starts afresh
    for p in entries:
        if STUDY_NAMES.match(p.name) and (
            p.is_symlink() or not _policy.owned(directory, p.name) or p.name == "chunks"
        ):
            raise OutputError(
                f"{p}: exists and was not written by runout; a study replaces only its own "
                "files, even with --force (move it away or choose an empty directory)"
            )


def _remove_leftovers(directory: Path) -> None:
    """Delete temporary files left by a killed writer (only names write_atomic makes)."""
    for folder in (directory, directory / "chunks", directory / "points"):
        if folder.is_dir():
            for p in folder.iterdir():
                if _TEMP.match(p.name):
                    p.unlink(missing_ok=True)


def _lock_holder(fd: int) -> str:
    try:
        text = os.pread(fd, 32, 0).decode("ascii", "replace").strip()
    except OSError:
        text = ""
    return text if text.isdigit() else "unknown"


def _pid_alive(pid: int) -> bool:  # pragma: no cover - only without fcntl (Windows)
    if pid <= 0:
        return False
    if sys.platform == "win32":
        import ctypes

        handle = ctypes.windll.kernel32.OpenProcess(0x1000, False, pid)  # type: ignore[attr-defined]
        if not handle:
            return False
        ctypes.windll.kernel32.CloseHandle(handle)  # type: ignore[attr-defined]
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


@contextlib.contextmanager
def output_lock(directory: Path) -> Iterator[Path]:
    """Hold the exclusive writer lock of ``directory`` (``directory/.lock``) while in the block.

    POSIX: ``flock`` on the lock file. The kernel releases it when the holder ends, even by
    SIGKILL, so a lock is never stale; the file holds the holder's PID for the message.
    Without ``fcntl`` (Windows) the file is created with O_EXCL and a lock whose PID is no
    longer running is taken over. The file is removed on the way out; a writer that opened
    it just before must then lock the file now at the path (checked with ``samestat``),
    otherwise two writers could hold locks on two different files.

    Raises
    ------
    OutputError
        ``"<dir>/.lock: another runout study is writing to <dir> (pid N)"``, or naming the
        lock file when it cannot be created (unwritable directory).
    """
    path = directory / LOCK_NAME
    busy = f"{path}: another runout study is writing to {directory} (pid {{}})"
    try:
        fd = _acquire(path, busy)
    except OSError as exc:
        raise OutputError(f"{path}: cannot create the lock file ({exc.strerror or exc})") from None
    try:
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
        yield path
    finally:
        with contextlib.suppress(OSError):
            path.unlink()
        os.close(fd)


def _acquire(path: Path, busy: str) -> int:
    if fcntl is None:  # pragma: no cover - Windows
        while True:
            try:
                return os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                holder = path.read_text(encoding="ascii", errors="replace").strip()
                if holder.isdigit() and _pid_alive(int(holder)):
                    raise OutputError(busy.format(holder)) from None
                path.unlink(missing_ok=True)  # stale: its writer is gone
    while True:
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = _lock_holder(fd)
            os.close(fd)
            raise OutputError(busy.format(holder)) from None
        except BaseException:
            os.close(fd)
            raise
        try:
            if os.path.samestat(os.fstat(fd), os.stat(path)):
                return fd
        except FileNotFoundError:
            pass
        os.close(fd)  # the holder removed that file on its way out: lock the new one


# ---------------------------------------------------------------- manifest and chunk checks
_RESUME_KEYS = ("format", "digest", "samples", "chunk_size", "chunks")


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def _manifest_problem(doc: Any) -> str | None:
    """What makes ``doc`` not a manifest.json of this version, or None."""
    if not isinstance(doc, dict):
        return f"a JSON {type(doc).__name__}, not an object"
    if doc.get("format") != FORMAT:
        return f"format is {doc.get('format')!r}, not {FORMAT!r}"
    if not isinstance(doc.get("digest"), str):
        return "no study digest"
    if doc.get("kind") not in ("montecarlo", "sweep"):
        return f"kind is {doc.get('kind')!r}"
    for key in ("samples", "chunk_size", "chunks"):
        if not _is_int(doc.get(key)) or doc[key] < 1:
            return f"{key} is {doc.get(key)!r}, not a positive integer"
    done = doc.get("done")
    if not isinstance(done, list) or not all(_is_int(k) and 0 <= k < doc["chunks"] for k in done):
        return f"done is not a list of chunk numbers below {doc['chunks']}"
    if len(set(done)) != len(done):
        return "done lists a chunk twice"
    if not isinstance(doc.get("complete"), bool):
        return "complete is not true or false"
    # absent in the manifests of sampling version 1 (before issue 31)
    if "sampling" in doc and (not _is_int(doc["sampling"]) or doc["sampling"] < 1):
        return f"sampling is {doc['sampling']!r}, not a positive integer"
    return None


def _read_manifest(path: Path) -> dict[str, Any]:
    """``path`` (a manifest.json) checked field by field.

    Raises
    ------
    StudyError
        Naming the file when it cannot be read or is not a manifest of this version: a
        truncated or hand-edited manifest must not become a traceback, nor a resume that
        trusts whatever it lists.
    """
    try:
        doc = read_json(path, [path.parent])
    except InputFileError as exc:
        problem = exc.message
    else:
        found = _manifest_problem(doc)
        if found is None:
            return dict(doc)
        problem = found
    raise StudyError(
        f"{path}: corrupted study manifest ({problem}); pass --force to start the study afresh "
        f"in {path.parent}"
    )


def _chunk_problem(chunk: Any, task: ChunkTask, digest: str) -> str | None:
    """What makes ``chunk`` not the result of ``task`` in the study ``digest``, or None.

    The digest comes first: a chunk swapped in from another study (or another version of
    this case) is well formed and would silently replace this study's samples. The rest is
    the structure _assemble and StudyResult rely on, so that a damaged file is recomputed
    instead of raising KeyError / TypeError half-way through the statistics.
    """
    if not isinstance(chunk, dict):
        return f"a JSON {type(chunk).__name__}, not an object"
    if chunk.get("digest") != digest:
        return "written by another study" if "digest" in chunk else "no study digest"
    for key, want in (("chunk", task.index), ("start", task.start), ("stop", task.stop)):
        if not _is_int(chunk.get(key)) or chunk[key] != want:
            return f"{key} is {chunk.get(key)!r}, expected {want}"
    n = task.stop - task.start
    model, values, runout = chunk.get("model"), chunk.get("values"), chunk.get("runout")
    if not isinstance(model, list) or len(model) != n or not all(isinstance(m, str) for m in model):
        return f"model is not a list of {n} names"
    if not isinstance(values, dict) or set(values) != {q.key for q in task.quantities}:
        return "values do not hold the study's quantities"
    for q in task.quantities:
        column = values[q.key]
        if not isinstance(column, list) or len(column) != n:
            return f"values of {q.key} are not a list of {n}"
        for v in column:
            ok = (
                isinstance(v, list) and len(v) == q.size and all(_is_number(x) for x in v)
                if q.size > 1
                else _is_number(v) or isinstance(v, str)
            )
            if not ok:
                return f"a value of {q.key} is {v!r}"
    if not isinstance(runout, dict) or not all(
        isinstance(runout.get(k), list)
        and len(runout[k]) == n
        and all(v is None or _is_number(v) for v in runout[k])
        for k in RUNOUT_KEYS
    ):
        return "runout is not a list of numbers per figure"
    lines = chunk.get("lines")
    if not isinstance(lines, dict):
        return "lines is not an object"
    for key, entry in lines.items():
        if (
            "|" not in key
            or not isinstance(entry, dict)
            or not _is_number(entry.get("frequency_hz"))
            or not isinstance(entry.get("pp_m"), list)
            or len(entry["pp_m"]) != n
            or not all(_is_number(v) for v in entry["pp_m"])
        ):
            return f"line {key!r} is damaged"
    errors = chunk.get("errors")
    if not isinstance(errors, dict) or not all(
        k.isdigit() and task.start <= int(k) < task.stop and isinstance(v, str)
        for k, v in errors.items()
    ):
        return "errors is not an object of sample numbers and messages"
    return _stiffness_problem(chunk, task)


#: The model whose points carry a stiffness (``runout.models.equilibrium.MODEL``; not imported:
#: checking a chunk must not load the model).
_EQUILIBRIUM = "equilibrium"
#: Keys of a point's ``radial_stiffness`` (:func:`runout.models.equilibrium.radial_stiffness`).
_RADIAL_KEYS = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m", "speed_rpm")


#: Keys of a point's ``bearing_damping`` (:func:`runout.models.equilibrium.bearing_damping`).
_DAMPING_KEYS = (
    "model",
    "coefficient_s",
    "cxx_n_s_per_m",
    "cxy_n_s_per_m",
    "cyx_n_s_per_m",
    "cyy_n_s_per_m",
    "czz_n_s_per_m",
)


def _damping_ok(damping: object) -> bool:
    """A point's ``bearing_damping``: absent (``{}``: none asked) or whole."""
    if damping == {}:
        return True
    return (
        isinstance(damping, dict)
        and set(damping) == set(_DAMPING_KEYS)
        and damping["model"] in ("kraemer", "proportional")
        and all(_is_number(damping[k]) for k in _DAMPING_KEYS[1:])
    )


def _stiffness_problem(chunk: dict[str, Any], task: ChunkTask) -> str | None:
    """What is wrong with the chunk's ``stiffness`` entries, or None.

    Every equilibrium point that ran must have one: a chunk written before studies kept the
    stiffness (no ``stiffness`` object) is recomputed rather than giving a stiffness.csv with
    points missing.
    """
    stiffness = chunk.get("stiffness", {})
    if not isinstance(stiffness, dict):
        return "stiffness is not an object"
    for k, entry in stiffness.items():
        radial = entry.get("radial_stiffness") if isinstance(entry, dict) else None
        if (
            not k.isdigit()
            or not task.start <= int(k) < task.stop
            or not isinstance(radial, dict)
            or set(radial) != set(_RADIAL_KEYS)
            or not all(_is_number(v) for v in radial.values())
            or not _is_number(entry.get("axial_stiffness_n_per_m"))
            or not _damping_ok(entry.get("bearing_damping", {}))
        ):
            return f"stiffness of sample {k!r} is damaged"
    for row, model in enumerate(chunk["model"]):
        i = str(task.start + row)
        if model == _EQUILIBRIUM and i not in chunk["errors"] and i not in stiffness:
            return f"sample {i} has no stiffness (written by an earlier version)"
    return None
