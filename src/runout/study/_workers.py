"""The study's worker processes: started once per study, kept for every chunk of it.

:func:`init_worker` sets Numba single-threaded, loads the study code (what unpickling a chunk
needs: :mod:`runout.study._chunks`) and the kernels from their cache before the first chunk
arrives, and ties the worker to the life of its parent (:func:`die_with_parent`).
"""

from __future__ import annotations

import atexit
import contextlib
import os
import sys
from typing import Any

import numpy as np

import runout.study._chunks  # noqa: F401 - what unpickling a chunk needs, loaded before the first
from runout.base._lifetime import die_with_parent
from runout.study._kernels import project_rows, solve_batch

__all__ = ["die_with_parent", "init_worker", "spawn_context", "warm_kernels", "worker_threads"]


# --------------------------------------------------------------------------------------------
# pool workers
# --------------------------------------------------------------------------------------------
def spawn_context() -> Any:
    """The start method of study workers: ``spawn``.

    Numba's threading layers are not fork-safe once used: workers start clean interpreters.
    """
    import multiprocessing

    return multiprocessing.get_context("spawn")


def worker_threads(workers: int, cores: int | None = None) -> int:
    """Numba threads of each of ``workers`` pool processes: its share of the cores, at least 1.

    ``workers x threads`` never exceeds the cores (no oversubscription: two processes whose
    thread teams share one core wait for each other at every chunk's end), and a machine with
    more cores than workers still uses them all.

    Parameters
    ----------
    workers : int
        Worker processes of the pool.
    cores : int, optional
        Cores of the machine (default: :func:`os.cpu_count`).
    """
    cores = cores or os.cpu_count() or 1
    import numba

    limit = int(getattr(numba.config, "NUMBA_NUM_THREADS", cores))
    return max(1, min(limit, cores // max(1, workers)))


def init_worker(parent: int | None = None, threads: int = 1) -> None:  # pragma: no cover
    """Set up a pool worker once for all its chunks (runs in the worker).

    One Numba thread team of ``threads`` (:func:`worker_threads`: the process's share of the
    cores) and no threads for long records, tied to the life of ``parent``, and the study
    code and its kernels loaded now, while the parent plans the study, instead of in the first
    chunk.
    """
    import numba

    from runout.base._threads import use_threads

    limit = int(getattr(numba.config, "NUMBA_NUM_THREADS", threads))
    numba.set_num_threads(max(1, min(threads, limit)))
    use_threads(False)  # nor two threads per long record: the workers are the parallelism
    if parent is not None:
        die_with_parent(parent)
    warm_kernels()
    # A worker holds nothing to clean up once multiprocessing has flushed its queues (it does
    # before the interpreter exits): skip the interpreter's teardown of Numba and LLVM, which
    # a study would otherwise wait for at its end.
    atexit.register(_exit_now)


def _exit_now() -> None:  # pragma: no cover - runs in workers, at exit
    with contextlib.suppress(Exception):
        sys.stdout.flush()
        sys.stderr.flush()
    os._exit(0)


def warm_kernels() -> None:
    """Import the study code and load the batched kernels (from Numba's cache) on tiny inputs."""
    theta = np.array([[0.0, 2.0, 4.0]])
    solve_batch(np.full((1, 3), 1e-6), np.zeros((1, 3)), theta, 1e10, 1e-6, 5, False)
    project_rows(np.zeros((1, 2)), np.zeros((1, 2)))
