"""Files read back safely: regular files inside their directory, bounded in size and shape.

Only regular files, only inside a directory, never more than a bound, JSON only of a bounded
size, depth and shape.

Every file runout reads back (a run directory's ``result.json``, ``summary.json``,
``case.toml`` and figures for ``runout report``; a study's manifest and chunks for ``runout
study --resume``; a measured record for ``runout diagnose``; a case's ``[[profile]]`` files)
goes through :func:`open_regular`. A directory someone else can write to may hold a link to
``/etc/passwd``, a FIFO that blocks for ever, ``/dev/zero`` that never ends, a link loop, or a
JSON document built to exhaust memory or recursion. Each of them ends in one
:class:`InputFileError` naming the file (and the key inside it when known), which the command
line prints as one line with exit status 2.

The bounds (documented in the troubleshooting page, with their values):

- :data:`MAX_JSON_BYTES`: the largest JSON file read; at most that many bytes plus one are
  ever read, so ``/dev/zero`` or a growing file costs no more;
- :data:`MAX_JSON_VALUES`: the most values (numbers, strings, containers) one JSON document
  holds, counted on the text before it is parsed (separators ``,`` and ``:``), which bounds
  every array's length and the memory of the parsed document;
- :data:`MAX_JSON_DEPTH`: the deepest nesting of arrays and objects (runout writes 6);
- :data:`MAX_JSON_INT_DIGITS`: the most digits of one JSON integer (runout writes counts,
  indices and seeds, at most 20 digits; Python's own bound of 4300 digits would end in a
  ``ValueError`` that names no file);
- :data:`MAX_FIGURE_BYTES`: the largest figure embedded in a report.

Numbers that are not finite (``NaN``, ``Infinity``) are refused naming their key: runout
never writes them (its JSON is written with ``allow_nan=False``), so one is an edited file.
"""

from __future__ import annotations

import json
import math
import os
import stat
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any, BinaryIO

from runout.base.errors import FileKeyError

__all__ = [
    "MAX_FIGURE_BYTES",
    "MAX_JSON_BYTES",
    "MAX_JSON_DEPTH",
    "MAX_JSON_INT_DIGITS",
    "MAX_JSON_VALUES",
    "MISSING",
    "InputFileError",
    "check_shape",
    "open_regular",
    "parse_json",
    "read_bytes",
    "read_json",
    "read_text",
    "resolve_inside",
]

_MiB = 1024 * 1024

#: Largest JSON file read back [B]: a run's result.json is about 1 MB (a spectrum of ten
#: thousand lines with their sources, ~20 MB).
MAX_JSON_BYTES = 64 * _MiB
#: Most values in one JSON document (counted by its separators before parsing): about
#: 250 MB of parsed Python objects at most.
MAX_JSON_VALUES = 4_000_000
#: Deepest nesting of JSON arrays and objects (runout writes at most 6 levels).
MAX_JSON_DEPTH = 64
#: Most digits of a JSON integer (runout writes counts, indices and seeds: at most 20).
MAX_JSON_INT_DIGITS = 100
#: Largest figure embedded in a report [B] (runout's figures are below 1 MB).
MAX_FIGURE_BYTES = 32 * _MiB


#: The message of a file that does not exist.
MISSING = "cannot be read (no such file)"


class InputFileError(FileKeyError, ValueError):
    """A file that cannot be read back safely or is not what runout writes.

    Parameters
    ----------
    file : str
        The file as it is shown to the user.
    key : str
        Dotted path of the value inside the file (``"runout.radial_pp_m"``), or ``""`` for
        the whole file.
    message : str
        What is wrong.
    """

    def __init__(self, file: str, key: str, message: str) -> None:
        super().__init__(file, key, message)


def resolve_inside(path: Path, roots: Sequence[Path] | None, name: str | None = None) -> Path:
    """The real path of ``path`` (every link followed), checked to lie under one of ``roots``.

    Parameters
    ----------
    path : Path
        The file named.
    roots : sequence of Path or None
        Directories the file must lie in once its links are followed; None: anywhere (a file
        the user named on the command line).
    name : str, optional
        The file as shown in messages (default ``str(path)``).

    Returns
    -------
    Path
        The resolved path.

    Raises
    ------
    InputFileError
        A missing file, a link loop, or a real path outside every root.
    """
    shown = str(path) if name is None else name
    try:
        real = Path(path).resolve(strict=True)
    except FileNotFoundError:
        raise InputFileError(shown, "", MISSING) from None
    except RuntimeError:  # Python 3.11: "Symlink loop from ..."
        raise InputFileError(shown, "", "is a loop of symbolic links") from None
    except OSError as exc:
        if exc.errno == getattr(os, "ELOOP", -1):
            raise InputFileError(shown, "", "is a loop of symbolic links") from None
        raise InputFileError(shown, "", f"cannot be read ({exc.strerror or exc})") from None
    if roots is not None:
        real_roots = []
        for root in roots:
            try:
                real_roots.append(Path(root).resolve(strict=True))
            except (OSError, RuntimeError):
                continue
        if not any(real.is_relative_to(root) for root in real_roots):
            where = " or ".join(str(r) for r in roots)
            raise InputFileError(
                shown,
                "",
                f"leads outside {where} (a symbolic link out of the directory); runout reads "
                "only the files inside it",
            )
    return real


def open_regular(
    path: Path, roots: Sequence[Path] | None = None, name: str | None = None
) -> BinaryIO:
    """Open a regular file for reading in binary mode, never following a link out of ``roots``.

    The real path is checked by :func:`resolve_inside`, then opened with ``O_NOFOLLOW`` (a
    link swapped in after the check is refused) and ``O_NONBLOCK`` (a FIFO does not block the
    open); anything but a regular file (a device, a FIFO, a directory, a socket) is refused on
    the open descriptor.

    Parameters
    ----------
    path : Path
        The file.
    roots : sequence of Path or None
        Directories the file must lie in (see :func:`resolve_inside`).
    name : str, optional
        The file as shown in messages.

    Returns
    -------
    BinaryIO
        The open file (the caller closes it).

    Raises
    ------
    InputFileError
        The file is missing, outside the roots, a loop, not a regular file or unreadable.
    """
    shown = str(path) if name is None else name
    real = resolve_inside(path, roots, shown)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOFOLLOW", 0)
    try:
        fd = os.open(real, flags | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        if exc.errno == getattr(os, "ELOOP", -1):
            raise InputFileError(shown, "", "became a symbolic link while it was read") from None
        raise InputFileError(shown, "", f"cannot be read ({exc.strerror or exc})") from None
    try:
        mode = os.fstat(fd).st_mode
    except OSError as exc:  # pragma: no cover - fstat of an open descriptor
        os.close(fd)
        raise InputFileError(shown, "", f"cannot be read ({exc.strerror or exc})") from None
    if not stat.S_ISREG(mode):
        os.close(fd)
        kind = "a directory" if stat.S_ISDIR(mode) else "a device, FIFO or socket"
        raise InputFileError(shown, "", f"is not a regular file ({kind})")
    return os.fdopen(fd, "rb")


def read_bytes(
    path: Path, max_bytes: int, roots: Sequence[Path] | None = None, name: str | None = None
) -> bytes:
    """The bytes of a regular file no larger than ``max_bytes`` (at most ``max_bytes + 1`` read).

    Parameters
    ----------
    path : Path
        The file.
    max_bytes : int
        Largest size accepted [B].
    roots : sequence of Path or None
        Directories the file must lie in (see :func:`resolve_inside`).
    name : str, optional
        The file as shown in messages.

    Returns
    -------
    bytes

    Raises
    ------
    InputFileError
        See :func:`open_regular`; or the file is larger than ``max_bytes``.
    """
    shown = str(path) if name is None else name
    with open_regular(path, roots, shown) as handle:
        try:
            data = handle.read(max_bytes + 1)
        except OSError as exc:
            raise InputFileError(shown, "", f"cannot be read ({exc.strerror or exc})") from None
    if len(data) > max_bytes:
        raise InputFileError(shown, "", f"is larger than {_size(max_bytes)}, the most runout reads")
    return data


def read_text(
    path: Path, max_bytes: int, roots: Sequence[Path] | None = None, name: str | None = None
) -> str:
    """The UTF-8 text (a leading byte-order mark dropped) of :func:`read_bytes`.

    Parameters
    ----------
    path : Path
        The file.
    max_bytes : int
        Largest file read [B].
    roots : sequence of Path or None
        Directories the file must lie in (see :func:`resolve_inside`).
    name : str, optional
        The file as shown in messages.

    Returns
    -------
    str
        The file's text.

    Raises
    ------
    InputFileError
        See :func:`read_bytes`; or the bytes are not UTF-8.
    """
    shown = str(path) if name is None else name
    data = read_bytes(path, max_bytes, roots, shown)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputFileError(
            shown, "", f"is not UTF-8 text (byte {exc.start + 1} cannot be decoded)"
        ) from None


def read_json(
    path: Path,
    roots: Sequence[Path] | None = None,
    name: str | None = None,
    *,
    max_bytes: int = MAX_JSON_BYTES,
    shape: Any = None,
) -> Any:
    """A JSON document read within the bounds of this module, its numbers finite.

    Parameters
    ----------
    path : Path
        The file.
    roots : sequence of Path or None
        Directories the file must lie in (see :func:`resolve_inside`).
    name : str, optional
        The file as shown in messages.
    max_bytes : int
        Largest file read [B] (default :data:`MAX_JSON_BYTES`).
    shape : optional
        A shape the document must have (see :func:`check_shape`).

    Returns
    -------
    Any
        The decoded document.

    Raises
    ------
    InputFileError
        See :func:`read_text`; not JSON; beyond :data:`MAX_JSON_VALUES`,
        :data:`MAX_JSON_DEPTH` or :data:`MAX_JSON_INT_DIGITS`; a number that is not finite;
        a value of another shape (naming its key).
    """
    shown = str(path) if name is None else name
    text = read_text(path, max_bytes, roots, shown)
    return parse_json(text, shown, shape=shape)


def parse_json(text: str, name: str, *, shape: Any = None) -> Any:
    """``text`` decoded as JSON within the bounds of this module (see :func:`read_json`).

    Parameters
    ----------
    text : str
        The document.
    name : str
        The file as shown in messages.
    shape : optional
        A shape the document must have (see :func:`check_shape`).

    Returns
    -------
    Any
    """
    # every value but the first follows a "," or a ":" (in a string they only overcount)
    separators = text.count(",") + text.count(":")
    if separators >= MAX_JSON_VALUES:
        raise InputFileError(
            name, "", f"holds more than {MAX_JSON_VALUES} values, the most runout reads"
        )

    def bounded_int(digits: str) -> int:
        if len(digits.lstrip("-")) > MAX_JSON_INT_DIGITS:
            raise _TooLong(len(digits.lstrip("-")))
        return int(digits)

    try:
        doc = json.loads(text, parse_int=bounded_int)
    except _TooLong as exc:
        raise InputFileError(
            name,
            "",
            f"holds an integer of {exc.digits} digits (at most {MAX_JSON_INT_DIGITS} are read)",
        ) from None
    except RecursionError:
        raise InputFileError(
            name, "", f"is nested deeper than {MAX_JSON_DEPTH} levels of arrays and objects"
        ) from None
    except ValueError as exc:  # JSONDecodeError
        raise InputFileError(name, "", f"is not valid JSON ({_first_line(str(exc))})") from None
    _check_values(doc, name)
    if shape is not None:
        check_shape(doc, shape, name)
    return doc


class _TooLong(ValueError):
    def __init__(self, digits: int) -> None:
        self.digits = digits
        super().__init__(digits)


def _first_line(text: str) -> str:
    return text.splitlines()[0][:200] if text else text


def _check_values(doc: Any, name: str) -> None:
    """Depth within :data:`MAX_JSON_DEPTH` and every number finite (iteratively: no recursion)."""
    stack: list[tuple[Any, str, int]] = [(doc, "", 0)]
    while stack:
        value, key, depth = stack.pop()
        if isinstance(value, float):
            if not math.isfinite(value):
                raise InputFileError(
                    name, key or "(the document)", f"{value!r} is not a finite number"
                )
        elif isinstance(value, dict | list):
            if depth >= MAX_JSON_DEPTH:
                raise InputFileError(name, key, f"is nested deeper than {MAX_JSON_DEPTH} levels")
            items = value.items() if isinstance(value, dict) else enumerate(value)
            for k, v in items:
                if isinstance(v, dict | list | float):
                    stack.append((v, _join(key, k), depth + 1))


def _join(key: str, item: object) -> str:
    if isinstance(item, int):
        return f"{key}[{item}]"
    text = _shown_key(str(item))
    return f"{key}.{text}" if key else text


def _shown_key(key: str) -> str:
    """A key of the file as it is shown: printable, at most 60 characters."""
    text = "".join(ch if ch.isprintable() else "?" for ch in key)
    return text if len(text) <= 60 else text[:57] + "..."


#: Largest part size a reader accepts [m] (shape ``"length"``): the largest slewing bearings
#: are a few metres across; a kilometre is an edited file.
MAX_READ_LENGTH_M = 1e3

#: A shape: one of these names, a tuple of them (any of), a list of one shape (every item),
#: or a dict of key to shape (an object whose listed keys, when present, have those shapes;
#: other keys are free). ``null`` is accepted wherever a value may be missing.
SHAPE_TYPES: Mapping[str, Callable[[Any], bool]] = {
    "object": lambda v: isinstance(v, dict),
    "list": lambda v: isinstance(v, list),
    "number": lambda v: isinstance(v, int | float) and not isinstance(v, bool),
    # a size or resolution: the readers' arithmetic takes it as one
    "nonnegative": lambda v: (
        isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v) and v >= 0
    ),
    # a part's size [m]: shown at the bearing's scale (mm), so bounded as any bearing is
    "length": lambda v: (
        isinstance(v, int | float)
        and not isinstance(v, bool)
        and math.isfinite(v)
        and 0 <= v <= MAX_READ_LENGTH_M
    ),
    "string": lambda v: isinstance(v, str),
    "bool": lambda v: isinstance(v, bool),
    "scalar": lambda v: isinstance(v, str | int | float | bool),
    "any": lambda v: True,
}

_WORDS = {
    "object": "an object",
    "list": "an array",
    "number": "a number",
    "nonnegative": "a finite number >= 0",
    "length": "a length from 0 to 1000 m",
    "string": "a string",
    "bool": "true or false",
    "scalar": "a number or a string",
}


def check_shape(doc: Any, shape: Any, name: str, key: str = "") -> None:
    """Check that ``doc`` has ``shape`` (see :data:`SHAPE_TYPES`).

    ``null`` passes for a value (an absent or undefined number, string or object), but not as
    an element of an array of objects: the files written hold none there, and a reader would
    take it for an object.

    Parameters
    ----------
    doc : Any
        A decoded JSON value.
    shape : str, tuple, list or dict
        The shape.
    name : str
        The file as shown in messages.
    key : str
        Path of ``doc`` in the file.

    Raises
    ------
    InputFileError
        Naming the first value of another shape and what was expected.
    """
    stack: list[tuple[Any, Any, str]] = [(doc, shape, key)]
    while stack:
        value, want, where = stack.pop()
        if value is None:
            continue
        if isinstance(want, dict):
            if not isinstance(value, dict):
                raise _mismatch(name, where, value, "an object")
            # pushed in reverse: the first value of another shape is the one named
            for k, sub in reversed(want.items()):
                if k in value:
                    stack.append((value[k], sub, _join(where, k)))
        elif isinstance(want, list):
            if not isinstance(value, list):
                raise _mismatch(name, where, value, "an array")
            if isinstance(want[0], dict):
                for i, item in enumerate(value):
                    if item is None:
                        raise _mismatch(name, f"{where}[{i}]", item, "an object")
            stack.extend(
                (value[i], want[0], f"{where}[{i}]") for i in range(len(value) - 1, -1, -1)
            )
        else:
            options = want if isinstance(want, tuple) else (want,)
            if not any(SHAPE_TYPES[o](value) for o in options):
                raise _mismatch(name, where, value, " or ".join(_WORDS[o] for o in options))


def _mismatch(name: str, key: str, value: Any, expected: str) -> InputFileError:
    kinds = {dict: "an object", list: "an array", str: "a string", bool: "true or false"}
    found = "null" if value is None else kinds.get(type(value), "a number")
    if found == "a number":  # its value says what is wrong with it (e.g. -1 for a size)
        found = _shown_key(repr(value))
    return InputFileError(
        name, key or "(the document)", f"expected {expected}, found {found} (an edited file?)"
    )


def _size(n: int) -> str:
    return f"{n / _MiB:g} MiB" if n >= _MiB else f"{n} bytes"
