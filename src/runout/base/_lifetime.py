"""A helper process's life tied to its parent's: :func:`die_with_parent`.

Used by the study's pool workers (:mod:`runout.study._workers`) and by the processes that draw
a run's figures (:mod:`runout.report._figure_workers`).
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
import time

__all__ = ["die_with_parent"]


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
