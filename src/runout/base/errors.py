"""Exceptions raised by runout.

Every error a user can cause or meet carries enough context to act on it: a case-file error
names the file and the key path, a geometry error names the quantity, a numerical error names
the instant and the cause. The command-line tool turns them into one line on stderr and exit
status 2, never a traceback.
"""

from __future__ import annotations


class RunoutError(Exception):
    """Base class of every error runout raises on purpose."""


class GeometryError(RunoutError, ValueError):
    """An impossible or inconsistent bearing description.

    Parameters
    ----------
    key : str
        Name of the offending quantity, e.g. ``"element_diameter"``.
    message : str
        What is wrong, in words a bearing engineer understands.
    """

    def __init__(self, key: str, message: str) -> None:
        self.key = key
        self.message = message
        super().__init__(f"{key}: {message}")


class FileKeyError(RunoutError):
    """What is wrong with one file, and where in it: ``"<file>: <key>: <message>"``.

    Parameters
    ----------
    file : str
        The file as the user gave it or sees it.
    key : str
        Dotted key path inside the file; empty for file-level errors.
    message : str
        What is wrong.
    hint : str, optional
        Appended to the message (e.g. where the docs describe the key).
    """

    def __init__(self, file: str, key: str, message: str, hint: str = "") -> None:
        self.file = file
        self.key = key
        self.message = message
        where = f"{file}: {key}" if key else file
        super().__init__(f"{where}: {message}{hint}")


class CaseError(FileKeyError):
    """A case file that cannot be read or is invalid.

    Parameters
    ----------
    file : str
        Path of the case file as the user gave it.
    key : str
        Dotted key path inside the file (``"bearing.elements"``); empty for file-level errors.
    message : str
        What is wrong.
    """

    def __init__(self, file: str, key: str, message: str) -> None:
        super().__init__(file, key, message, _doc_hint(key))


_DOCUMENTED_TABLES = (
    "bearing",
    "material",
    "operation",
    "waviness",
    "waviness_spectrum",
    "profile",
    "slant",
    "elements",
    "analysis",
    "dynamics",
    "study",
)


def _doc_hint(key: str) -> str:
    """Pointer to the case-file reference section of the table that ``key`` belongs to."""
    table = key.split(".", 1)[0].split("[", 1)[0]
    if table not in _DOCUMENTED_TABLES:
        return ""
    return f" (see docs/case-file.md#{table})"


class ArgumentTypeError(CaseError, TypeError):
    """A Python argument of the wrong type (a bearing that is not one): a :class:`CaseError`
    naming the argument as its key, and a :class:`TypeError` as Python code expects."""


class ModelNotAvailableError(RunoutError):
    """The case asks for a model this version does not provide."""


class NumericalError(RunoutError):
    """A solver failed: lost contact, no convergence, singular system.

    Parameters
    ----------
    cause : str
        What went wrong.
    instant : int or None
        Index of the time instant (or rotation angle) where it happened.
    time : float or None
        Time [s] or angle [rad] of that instant, when known.
    key : str or None
        The case key that decides whether the solver can succeed (``"spindle.preload"``),
        when one does; the message starts with it.
    hint : str or None
        What to change, at the end of the message.
    """

    def __init__(
        self,
        cause: str,
        instant: int | None = None,
        time: float | None = None,
        key: str | None = None,
        hint: str | None = None,
    ) -> None:
        self.cause = cause
        self.instant = instant
        self.time = time
        self.key = key
        where = ""
        if instant is not None:
            where = f" at instant {instant}"
            if time is not None:
                where += f" (t = {time:.6g})"
        end = f"; {hint}" if hint else ""
        super().__init__(f"{key + ': ' if key else ''}{cause}{where}{end}")


class ConvergenceError(NumericalError):
    """An iterative solver did not converge."""


class ContactLossError(NumericalError):
    """Too few elements carry load to hold the ring."""
