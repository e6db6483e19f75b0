"""Long records on both cores: independent spans of a record on two threads.

The compiled kernels that walk a record instant by instant release the GIL (``nogil``), so
two threads fill two spans of one record at once. Work is split only where the spans are
independent (the result does not depend on how it is split: each block of the spectral
kernels restarts from exact values; the quasi-static solves start the second half from rest,
see :func:`runout.models._quasi_static.solve_in_halves`), so a result never depends on the
machine's number of cores. Threads are used from the main thread only, and not in a study's
pool workers (:func:`use_threads`): a study's workers already keep the cores busy and run the
spans one after the other.
"""

from __future__ import annotations

import contextlib
import functools
import os
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any, TypeVar

__all__ = ["halves", "in_spans", "one_blas_thread", "parallel_allowed", "use_threads"]

T = TypeVar("T")

_enabled = True


def use_threads(enabled: bool) -> None:
    """Allow or forbid the spans' threads in this process (a study's pool workers forbid them)."""
    global _enabled
    _enabled = bool(enabled)


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def parallel_allowed() -> bool:
    """True in the main thread of a process allowed two cores or more, threads not forbidden."""
    return _enabled and threading.current_thread() is threading.main_thread() and _cores() >= 2


def halves(n: int, minimum: int, align: int = 1) -> tuple[tuple[int, int], ...]:
    """``[0, n)`` whole below ``minimum``, else cut in two at a multiple of ``align``."""
    if n < max(minimum, 2 * align):
        return ((0, n),)
    cut = (n // 2) // align * align
    return ((0, cut), (cut, n))


def in_spans(work: Callable[[int, int], T], spans: tuple[tuple[int, int], ...]) -> list[T]:
    """``work(first, last)`` for each span, in order; on two threads where allowed."""
    if len(spans) > 1 and parallel_allowed():
        with ThreadPoolExecutor(len(spans), thread_name_prefix="runout-span") as pool:
            return list(pool.map(lambda span: work(*span), spans))
    return [work(*span) for span in spans]


@functools.lru_cache(maxsize=1)
def _blas_controller() -> Any:
    """threadpoolctl's controller of the BLAS libraries loaded (NumPy's and SciPy's)."""
    import scipy.linalg  # noqa: F401  (loads SciPy's BLAS, so that the controller sees it)

    try:
        from threadpoolctl import ThreadpoolController
    except ImportError:  # a dependency; without it the BLAS keeps its default threads
        return None
    return ThreadpoolController()


def one_blas_thread() -> contextlib.AbstractContextManager[Any]:
    """Run the enclosed BLAS/LAPACK calls on one thread.

    The line fit's dense algebra is small (a symmetric eigenvalue problem and a Cholesky of
    ``2 m + 1`` unknowns, ~5 ms on one core for 200 lines) and its record-sized products are
    split over the cores by :func:`in_spans` already: a threaded BLAS gains nothing, and when
    the cores are busy with other work its threads wait for each other, which measured
    0.36-2.3 s instead of 65 ms for a 200-line fit on a shared 2-core machine.
    """
    controller = _blas_controller()
    if controller is None:
        return contextlib.nullcontext()
    return controller.limit(limits=1, user_api="blas")
