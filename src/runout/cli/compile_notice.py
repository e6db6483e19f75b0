"""Say on stderr when a command compiles numerical kernels, so that a first run does not wait
without a word.

The kernels are Numba functions compiled for the machine's CPU on their first call and kept in
Numba's cache (``cache=True``): after an installation each model's first command compiles its
kernels once (a few seconds), every later one loads them. Numba announces a compilation with
its ``numba:compile`` event, which it raises only on a cache miss; a listener for it prints one
line when the first kernel starts compiling and, when the command succeeds, one line with what
was compiled and how long it took. ``runout warm`` compiles every model's kernels ahead.

Numba is imported only by the commands that need it (``runout frequencies`` does not), so
:func:`watch` does not import it: it registers the listener as soon as Numba has been imported,
through a finder on :data:`sys.meta_path` that removes itself after that one import.
"""

from __future__ import annotations

import importlib.util
import os
import sys
import time
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any, TextIO

__all__ = ["ENV", "finish", "stop", "topic_of", "wanted", "watch"]

#: The first message, printed once per process when a kernel starts compiling.
STARTING = (
    "runout: compiling numerical kernels for this machine ({what}); this happens once after "
    "installation, later runs load them from the cache (`runout warm` compiles them all ahead)"
)

#: Readable names of the modules whose kernels compile (the first matching fragment wins).
_TOPICS: tuple[tuple[str, str], ...] = (
    ("_roller", "roller_constraint model"),
    ("_equilibrium", "equilibrium model"),
    ("_dynamic", "dynamic model"),
    ("_spindle", "spindle model"),
    ("quasi_static_2d", "quasi_static_2d model"),
    ("quasi_static_3d", "quasi_static_3d model"),
    ("_quasi_static", "quasi-static contacts"),
    ("runout.study.", "study"),
    ("line_kernels", "spectral lines"),
    ("elliptic", "Hertz contact"),
    ("csvfmt", "output files"),
    ("geometry._kernels", "imperfections"),
)


class _State:
    """What this process has said and compiled (one command at a time)."""

    stream: TextIO | None = None
    registered = False
    announced = False
    depth = 0
    started = 0.0
    seconds = 0.0
    topics: dict[str, None] = {}  # noqa: RUF012 - an ordered set, reset by watch()


def topic_of(module: str) -> str:
    """A readable name for the kernels of ``module`` (``runout.models._roller_kernels`` →
    "roller_constraint model")."""
    for fragment, topic in _TOPICS:
        if fragment in module:
            return topic
    return module.removeprefix("runout.")


def _on_start(data: Any) -> None:
    module = getattr(getattr(data.get("dispatcher"), "py_func", None), "__module__", "") or ""
    if _State.depth == 0:
        _State.started = time.perf_counter()
    _State.depth += 1
    if not module.startswith("runout"):  # a library overload compiled for one of ours
        return
    topic = topic_of(module)
    _State.topics.setdefault(topic, None)
    if _State.stream is not None and not _State.announced:
        _State.announced = True
        try:
            print(STARTING.format(what=topic), file=_State.stream, flush=True)
        except (OSError, ValueError):  # the command's stderr is gone: nothing to tell
            pass


def _on_end() -> None:
    _State.depth = max(_State.depth - 1, 0)
    if _State.depth == 0:
        _State.seconds += time.perf_counter() - _State.started


def _register() -> None:
    """Listen to Numba's compile events (Numba is imported by now)."""
    if _State.registered:
        return
    from numba.core import event

    class _Listener(event.Listener):
        def on_start(self, ev: Any) -> None:
            _on_start(ev.data or {})

        def on_end(self, ev: Any) -> None:
            _on_end()

    event.register("numba:compile", _Listener())
    _State.registered = True


class _AfterNumba:
    """Registers the listener right after Numba's first import, then leaves ``sys.meta_path``.

    A finder by protocol (``find_spec``): ``importlib.abc`` costs milliseconds of every start.
    """

    def find_spec(
        self,
        fullname: str,
        path: Sequence[str] | None,
        target: ModuleType | None = None,
    ) -> Any:
        if fullname != "numba":
            return None
        if self in sys.meta_path:
            sys.meta_path.remove(self)
        spec = importlib.util.find_spec(fullname)
        if spec is None or spec.loader is None:
            return spec
        loader = spec.loader
        run: Callable[[ModuleType], None] = loader.exec_module

        def exec_module(module: ModuleType) -> None:
            run(module)
            _register()

        loader.exec_module = exec_module  # type: ignore[method-assign]
        return spec


#: ``RUNOUT_COMPILE_NOTICE=1`` prints the notices whatever stderr is, ``0`` never.
ENV = "RUNOUT_COMPILE_NOTICE"


def wanted(stream: TextIO) -> bool:
    """Whether to print the notices on ``stream``: to a person at a terminal, or when asked.

    A script that reads stderr (a test harness, a pipeline expecting one ``error:`` line) gets
    no progress lines unless ``RUNOUT_COMPILE_NOTICE=1``.

    Parameters
    ----------
    stream : text stream
        The command's standard error.

    Returns
    -------
    bool
    """
    setting = os.environ.get(ENV, "").strip()
    if setting in ("0", "1"):
        return setting == "1"
    isatty = getattr(stream, "isatty", None)
    try:
        return bool(isatty()) if callable(isatty) else False
    except (OSError, ValueError):
        return False


def watch(stream: TextIO) -> None:
    """Print to ``stream`` when this command compiles a kernel (once per process).

    Parameters
    ----------
    stream : text stream
        Where the notices go (the command's standard error); nothing is printed unless
        :func:`wanted` says so.
    """
    _State.stream = stream if wanted(stream) else None
    _State.seconds = 0.0
    _State.topics = {}
    if _State.registered:
        return
    if "numba" in sys.modules:
        _register()
    elif not any(isinstance(f, _AfterNumba) for f in sys.meta_path):
        sys.meta_path.insert(0, _AfterNumba())


def finish() -> str | None:
    """After a command that succeeded: the line saying what it compiled (None if nothing).

    Returns
    -------
    str or None
        E.g. "runout: compiled the kernels of the spindle model, spectral lines in 6.1 s; they
        are cached now".
    """
    if not _State.topics or _State.stream is None:
        return None
    what = ", ".join(_State.topics)
    line = f"runout: compiled the kernels of the {what} in {_State.seconds:.1f} s; cached now"
    _State.topics = {}
    _State.seconds = 0.0
    return line


def stop() -> None:
    """The command has ended: print nothing more (its stream may be closed by now)."""
    _State.stream = None
    _State.topics = {}
    _State.seconds = 0.0
