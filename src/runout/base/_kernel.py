"""The one way the package compiles a kernel: :func:`kernel`, ``numba.njit`` with its options.

Every kernel is cached on disk (``cache=True``: compiled once per installation and CPU) and
built without the C-callable wrapper numba otherwise adds for first-class function use
(``no_cfunc_wrapper=True``: no kernel is passed as a function object; the wrapper is
first-run compilation time for nothing, some 1 ms per array argument).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Literal, TypeVar

import numba

if TYPE_CHECKING:
    from numba.core.dispatcher import Dispatcher

__all__ = ["kernel"]

_F = TypeVar("_F", bound=Callable[..., object])


def kernel(
    *,
    nogil: bool = False,
    parallel: bool = False,
    inline: Literal["never", "always"] = "never",
) -> Callable[[_F], Dispatcher[_F]]:
    """Decorator: compile the function with ``numba.njit`` and the package's options.

    Parameters
    ----------
    nogil : bool
        Release the GIL while the kernel runs (kernels run on parallel threads).
    parallel : bool
        Numba's automatic parallelisation (``prange``).
    inline : {"never", "always"}
        Inline into compiled callers at Numba IR level (a helper with one caller).

    Returns
    -------
    callable
        The decorator, which returns numba's dispatcher of the function.
    """
    options: dict[str, object] = {
        "cache": True,
        "no_cfunc_wrapper": True,
        "nogil": nogil,
        "parallel": parallel,
        "inline": inline,
    }
    # no_cfunc_wrapper is a numba option its type stubs leave out
    decorator: Callable[[_F], Dispatcher[_F]] = numba.njit(**options)  # type: ignore[call-overload]
    return decorator
