"""What every ``runout`` command shares: the consoles, the argument types, one-line errors
and warnings (:func:`_guard`), loading a case with ``--model`` and ``--set``, JSON and table
printing.

Bad input ends with one clear line on stderr, ``error: FILE: key.path: problem``, and exit
status 2, never a traceback. Warnings raised while a command runs are collected and printed
as one ``warning:`` line after it. A failure that is not runout's own (a bug) is one
``error:`` line too, with exit status 70; ``RUNOUT_DEBUG=1`` shows its traceback. Tables
written to a pipe or a file are laid out for a fixed width (:data:`PIPE_WIDTH`).
"""

from __future__ import annotations

import errno
import functools
import json
import os
import sys
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Any, TypeVar

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from runout.base.errors import GeometryError, NumericalError, RunoutError
from runout.cli import compile_notice as _compile_notice

_out = Console()
_err = Console(stderr=True)

F = TypeVar("F", bound=Callable[..., Any])

CaseArg = Annotated[
    Path, typer.Argument(help="TOML case file (see docs/case-file.md).", show_default=False)
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]
ModelOpt = Annotated[
    str | None,
    typer.Option(
        "--model",
        metavar="NAME",
        help="Model id replacing the case's [analysis] model (e.g. linear).",
        show_default=False,
    ),
]
SetOpt = Annotated[
    list[str] | None,
    typer.Option(
        "--set",
        metavar="KEY=VALUE",
        help="Set one case key by its dotted path before validation (repeatable), e.g. "
        '--set operation.axial_load="30 N" --set analysis.samples=8192 --set '
        "waviness[1].order=9. VALUE is read as a TOML value; a bare word is a string.",
        show_default=False,
    ),
]


#: Width of tables written to a pipe or a file (not to a terminal).
PIPE_WIDTH = 200
#: Exit status of a failure that is a bug, not bad input (sysexits' EX_SOFTWARE).
EXIT_INTERNAL = 70


#: The command-line framework's own exits and usage errors. Typer (0.26 on) carries its own
#: copy of click, whose usage errors derive from ``TyperException``; click itself is not a
#: dependency and must not be imported.
_CLI_EXITS = (typer.Exit, typer.Abort, typer.exceptions.TyperException)


#: Warning categories that are about the case and reach the user as one ``warning:`` line.
_CASE_WARNINGS = (RuntimeWarning, UserWarning)


def _one_line(text: str) -> str:
    """``text`` on one line: control characters (a newline in a quoted TOML key) escaped."""
    return "".join(ch if ch.isprintable() else repr(ch)[1:-1] for ch in text)


def _fail(message: str, status: int = 2) -> None:
    # emoji=False: ":x:" in a value or a file's line is text, not an emoji
    _err.print(
        f"[bold red]error:[/] {escape(_one_line(message))}",
        highlight=False,
        soft_wrap=True,
        emoji=False,
    )
    raise typer.Exit(status)


def _warn(file: object, messages: list[str]) -> None:
    """One ``warning:`` line on stderr for all of ``messages`` (nothing when empty)."""
    unique = list(dict.fromkeys(m for m in messages if m))
    if not unique:
        return
    where = f"{file}: " if file is not None else ""
    text = "; ".join(unique[:5]) + (f" (and {len(unique) - 5} more)" if len(unique) > 5 else "")
    _err.print(
        f"[bold yellow]warning:[/] {escape(_one_line(where + text))}",
        highlight=False,
        soft_wrap=True,
        emoji=False,
    )


def _named(message: str, file: object) -> str:
    """``message`` starting with the case file, once."""
    if file is None or message.startswith(f"{file}:"):
        return message
    return f"{file}: {message}"


def _guard(fn: F) -> F:
    """One line on stderr for every failure: exit status 2 for runout's own errors.

    Errors raised by a model (a geometry check, a solver that lost contact) name the case
    file too; warnings are collected into one ``warning:`` line, printed after a command that
    succeeded (an error line stays the only line of a failure).
    """

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        file = kwargs.get("case_file")
        # a first run after installation compiles kernels for a few seconds: say so
        _compile_notice.watch(sys.stderr)
        try:
            return _guarded(fn, file, *args, **kwargs)
        finally:
            _compile_notice.stop()

    return wrapper  # type: ignore[return-value]


def _guarded(fn: Callable[..., Any], file: object, *args: Any, **kwargs: Any) -> Any:
    """The body of :func:`_guard`'s wrapper: ``fn`` run, its failures and warnings reported."""
    with warnings.catch_warnings(record=True) as caught:
        try:
            result = fn(*args, **kwargs)
        except RunoutError as exc:
            message = str(exc)
            if isinstance(exc, GeometryError | NumericalError):
                message = _named(message, file)
            _fail(message)
        except KeyboardInterrupt:
            _err.print("interrupted")
            raise typer.Exit(130) from None
        except _CLI_EXITS:
            raise
        except MemoryError:
            _fail(
                _named(
                    "ran out of memory; lower analysis.samples or the orders, or raise "
                    "[analysis] max_memory only if the machine has the memory",
                    file,
                )
            )
        except Exception as exc:
            if os.environ.get("RUNOUT_DEBUG"):
                raise
            if _output_lost(exc):  # stdout closed or its disk full: not runout's bug
                _fail(_named(f"cannot write the output ({exc})", file), 1)
            _fail(
                _named(
                    f"internal error ({type(exc).__name__}: {exc}); this is a bug in "
                    "runout, please report it with the case file (RUNOUT_DEBUG=1 shows "
                    "the traceback)",
                    file,
                ),
                EXIT_INTERNAL,
            )
    # what concerns the case (a profile, a line too close to another, an overflow), not
    # the deprecations and compiler notes of the libraries underneath
    _warn(file, [str(w.message) for w in caught if issubclass(w.category, _CASE_WARNINGS)])
    compiled = _compile_notice.finish()
    if compiled is not None:
        print(compiled, file=sys.stderr, flush=True)
    return result


def _load(case_file: Path, model: str | None = None, sets: list[str] | None = None) -> Any:
    """The case of ``case_file`` with ``--model`` and ``--set`` applied, validated as a file."""
    from runout.base.errors import CaseError
    from runout.case.model import load_case, parse_override

    overrides: dict[str, Any] = {}
    for text in sets or ():
        try:
            key, value = parse_override(text)
        except ValueError as exc:
            raise CaseError(str(case_file), "", f"--set: {exc}") from None
        if key in overrides:
            # the later one would silently replace the first
            raise CaseError(str(case_file), key, "given twice with --set")
        overrides[key] = value
    return load_case(case_file, model=model, overrides=overrides or None)


def _print_json(payload: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(payload, indent=2, allow_nan=False) + "\n")


def _rows_table(title: str, rows: list[tuple[str, str, str]]) -> Table:
    table = Table(title=title, title_justify="left", show_header=True, header_style="bold")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("unit")
    for name, value, unit in rows:
        table.add_row(escape(name), escape(value), escape(unit))
    return table


def _print_sections(sections: list[tuple[str, list[tuple[str, str, str]]]]) -> None:
    """Titled tables; a section whose rows have no value and no unit prints as a list."""
    for title, rows in sections:
        if rows and all(not value and not unit for _, value, unit in rows):
            _out.print(f"[bold]{escape(title)}[/]", soft_wrap=True)
            for text, _, _ in rows:
                _out.print(f"- {escape(text)}", highlight=False, soft_wrap=True, emoji=False)
        else:
            _out.print(_rows_table(title, rows))


def _output_lost(exc: Exception) -> bool:
    """Whether ``exc`` is the standard output failing (closed, or its disk full)."""
    if sys.stdout is None or getattr(sys.stdout, "closed", False):
        return True
    return isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EPIPE, errno.EBADF)
