"""The study's worker processes: started once per study, kept for every chunk of it.

:func:`init_worker` sets Numba single-threaded, loads the study code (what unpickling a chunk
needs: :mod:`runout.study._chunks`) and the kernels from their cache before the first chunk
arrives, and ties the worker to the life of its parent (:func:`die_with_parent`).
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
import threading
import time
from typing import Any

import numpy as np

import runout.study._chunks  # noqa: F401 - what unpickling a chunk needs, loaded before the first
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


#: ``prctl`` option of Linux: signal sent to this process when its parent ends.
PR_SET_PDEATHSIG = 1


def die_with_parent(parent: int, kernel: bool = True) -> None:  # pragma: no cover - workers
    """End this process as soon as process ``parent`` ends, however it ends.

    A pool worker waits on its task queue, whose write end it holds itself, so it never sees
    its parent go: a SIGKILLed ``runout study --workers N`` would leave N orphans finishing
    their chunks and then waiting forever. On Linux ``prctl(PR_SET_PDEATHSIG, SIGKILL)`` has
    the kernel kill the worker with its parent. Everywhere, and as a second line on Linux
    (where the signal follows the parent *thread*, not process), a daemon thread waits on the
    parent's sentinel (:func:`multiprocessing.parent_process`; polls ``os.getppid()`` when
    there is none) and ends the process.

    Parameters
    ----------
    parent : int
        PID of the parent (the process that submits the chunks).
    kernel : bool
        Use ``prctl`` where available; False tests the portable watchdog alone.
    """
    if kernel and sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() != parent:  # the parent was gone before the line above took effect
        os._exit(1)
    watch = threading.Thread(
        target=_watch_parent, args=(parent,), name="runout-parent-watch", daemon=True
    )
    watch.start()


def _watch_parent(parent: int) -> None:  # pragma: no cover - runs in workers
    import multiprocessing
    from multiprocessing.connection import wait

    proc = multiprocessing.parent_process()
    if proc is not None and proc.sentinel is not None:
        while proc.is_alive():
            wait([proc.sentinel], timeout=60.0)
    else:
        while os.getppid() == parent:
            time.sleep(0.5)
    os._exit(1)  # no cleanup: the parent that would collect our results is gone
