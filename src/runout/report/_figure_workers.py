"""Processes that draw a run's figures beside the command that runs the model (``run --out``).

matplotlib costs a run's files about 0.4 s to import and each figure 0.1-0.3 s to lay out,
draw and encode; ``runout run --json`` pays none of it. :class:`FigureWorkers` starts its
processes before the model runs: they import matplotlib while it runs, then take the
figures from one queue (each process the next figure when it is free) while the command
writes the tables. The command itself never imports matplotlib.

Bounded and visible: each process dies with the command (:func:`die_with_parent`); a figure
that raises is re-raised by :meth:`FigureWorkers.draw` (the command's error, as if drawn in
the command); a process that dies or says nothing for :data:`SILENCE_S` seconds is an error
naming the figures not written. Processes write only the files their figures name.
"""

from __future__ import annotations

import contextlib
import gc
import multiprocessing
import os
import pickle
import sys
import threading
import traceback
from collections.abc import Callable, Sequence
from multiprocessing.connection import Connection, wait
from pathlib import Path
from typing import Any

__all__ = ["SILENCE_S", "FigureError", "FigureWorkers", "figure_processes"]

#: Niceness added to the drawing processes: the command's own work (the model, the rigid model's
#: order sweep on its threads) goes first on a machine whose cores are all busy, so that the
#: figure drawn from the sweep is not left waiting at the end; the figures take the time left.
FIGURE_NICENESS = 5

#: Longest wait [s] for any word from the drawing processes before the figures still missing
#: are an error (a figure of a 2^20-instant record takes well under a second).
SILENCE_S = 300.0

#: A figure job: the file name and what it needs beyond the run's result (or None); those
#: returned by ``later`` travel on the job queue and must be small (the order sweep's table).
Job = tuple[str, Any]
#: Draws one figure: (result, directory, name, extra) -> the file written.
Draw = Callable[[Any, Path, str, Any], Path]


#: A queued job whose data came with the result (:meth:`FigureWorkers.draw`).
_IN_PAYLOAD = "in the payload"


class FigureError(RuntimeError):
    """A drawing process died or went silent before its figures were written."""


def figure_processes(cores: int | None = None) -> int:
    """Drawing processes for a machine of ``cores`` cores: 2, or 1 on a single core.

    Two processes draw the figures in about half the time of one on two cores; more would
    each pay matplotlib's import for a handful of figures.
    """
    cores = cores or os.cpu_count() or 1
    return 2 if cores >= 2 else 1


class FigureWorkers:
    """Processes, started now, that import matplotlib and then draw figures (:meth:`draw`).

    Parameters
    ----------
    processes : int
        Number of processes (:func:`figure_processes`).
    warm : callable
        Run by each process at its start (imports matplotlib and the plotting code).

    Notes
    -----
    On Linux the processes are forked (they share the command's imports; the command has
    started no thread yet): the first imports matplotlib and forks the others; elsewhere
    they are spawned and each imports its own.
    """

    def __init__(self, processes: int, warm: Callable[[], None]) -> None:
        # fork on Linux only: macOS's system libraries are not safe to use in a forked child
        forks = sys.platform.startswith("linux")
        context: Any = multiprocessing.get_context("fork" if forks else "spawn")
        for stream in (sys.stdout, sys.stderr):  # nothing buffered is copied into a fork
            with contextlib.suppress(Exception):
                stream.flush()
        self._jobs = context.SimpleQueue()
        pipes = [context.Pipe() for _ in range(max(1, processes))]
        self._conns: list[Connection] = [ours for ours, _ in pipes]
        self._procs: list[Any] = []
        self._closed = False
        self._finished = False
        # where processes fork, one imports matplotlib and then forks the others (which share
        # its imports: 0.4 s of CPU each saved); elsewhere each process imports its own
        groups = [[theirs for _, theirs in pipes]] if forks else [[theirs] for _, theirs in pipes]
        for group in groups:
            proc = context.Process(
                target=_serve,
                args=(group, self._jobs, os.getpid(), warm),
                name="runout-figures",
                daemon=True,
            )
            proc.start()
            self._procs.append(proc)
        for _, theirs in pipes:
            theirs.close()

    def draw(
        self,
        draw: Draw,
        result: Any,
        directory: Path,
        jobs: Sequence[Job],
        later: Callable[[], Sequence[Job]] | None = None,
    ) -> dict[str, Path]:
        """Draw ``jobs`` (and those ``later`` returns, once it returns) in the processes.

        Parameters
        ----------
        draw : callable
            ``draw(result, directory, name, extra)`` draws one figure and returns its file.
            A module-level function: the processes receive it by reference.
        result : RunResult
            The run's result, sent once to each process.
        directory : Path
            Where the figures go.
        jobs : sequence of (str, object)
            File name and extra data of each figure.
        later : callable, optional
            Called (in this process) once ``jobs`` are queued: more jobs, whose data this
            process computes meanwhile (the rigid model's order sweep).

        Returns
        -------
        dict
            File name -> path written.

        Raises
        ------
        Exception
            The first figure's error, as raised in its process; :class:`FigureError` when a
            process dies or is silent for :data:`SILENCE_S` seconds.
        """
        # the data travels once to each process with the result; the queue carries names
        # only (a pipe holds 64 KiB: a large job would block this process on a dead queue)
        first = {name: extra for name, extra in jobs}
        payload = pickle.dumps((draw, result, directory, first), protocol=pickle.HIGHEST_PROTOCOL)
        # sent on a thread: a process reads it once matplotlib is imported, and meanwhile
        # this one writes the tables (a record of 2^20 instants is 33 MB)
        sending = threading.Thread(
            target=self._send, args=(payload,), name="runout-figures-send", daemon=True
        )
        sending.start()
        queued = list(jobs)
        for name, _ in queued:
            self._jobs.put((name, _IN_PAYLOAD))
        if later is not None:
            extra = list(later())
            for job in extra:
                self._jobs.put(job)
            queued += extra
        for _ in self._conns:
            self._jobs.put(None)  # each process ends after the last job
        done = self._collect([name for name, _ in queued])
        sending.join()
        self._finished = True
        return done

    def _send(self, payload: bytes) -> None:
        for conn in self._conns:
            with contextlib.suppress(OSError):  # a process that died: _collect says so
                conn.send_bytes(payload)

    def _collect(self, names: list[str]) -> dict[str, Path]:
        done: dict[str, Path] = {}
        # a pipe ends when its process does (forked processes are not this one's children)
        live = set(self._conns)
        while len(done) < len(names):
            ready = wait(list(live), timeout=SILENCE_S)
            if not ready:
                raise FigureError(f"no figure drawn for {SILENCE_S:.0f} s: {_missing(names, done)}")
            for conn in ready:
                assert isinstance(conn, Connection)
                try:
                    message = conn.recv()
                except (EOFError, OSError):
                    live.discard(conn)
                    if len(done) < len(names) and not live:
                        raise FigureError(
                            f"the figure processes ended early: {_missing(names, done)}"
                        ) from None
                    continue
                if message[0] == "error":
                    _, name, error, text = message
                    error.add_note(f"while drawing {name} (in a figure process):\n{text}")
                    raise error
                _, name, path = message
                done[name] = path
        return done

    def close(self) -> None:
        """End the processes and release their pipes.

        After :meth:`draw` returned, the processes are waited for (they end once the queue
        is empty); otherwise (an error, the command interrupted) they are killed now.
        """
        if self._closed:
            return
        self._closed = True
        for proc in self._procs:
            if self._finished:  # every figure is written: the processes are ending
                proc.join(timeout=5.0)
            if proc.is_alive():
                proc.kill()
        for proc in self._procs:
            proc.join(timeout=5.0)
        for conn in self._conns:
            conn.close()
        self._jobs.close()

    def __enter__(self) -> FigureWorkers:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _missing(names: list[str], done: dict[str, Path]) -> str:
    return ", ".join(n for n in names if n not in done) or "none"


def _serve(
    conns: list[Connection], jobs: Any, parent: int, warm: Callable[[], None]
) -> None:  # pragma: no cover - runs in the processes
    """A drawing process: warm up, fork one process per further pipe, draw, end.

    Each process receives the result on its own pipe, takes figures from ``jobs`` until it
    finds None, and answers on its pipe. This one waits for those it forked before ending.
    """
    from runout.base._lifetime import die_with_parent

    die_with_parent(parent)
    nice = getattr(os, "nice", None)  # Unix only: elsewhere the figures draw at the command's
    if nice is not None:
        with contextlib.suppress(OSError):
            nice(FIGURE_NICENESS)
    with contextlib.suppress(Exception):
        # only a head start: what fails here fails again in the first figure, which is
        # reported as that figure's error
        warm()
    # the heap that matplotlib's import built stays shared with the forked processes: the
    # collector, untouched by it, copies none of its pages
    gc.freeze()
    forked = []
    for k in range(1, len(conns)):
        pid = os.fork()
        if pid == 0:  # the k-th process: its own pipe only (so that its end is seen)
            for j, conn in enumerate(conns):
                if j != k:
                    conn.close()
            die_with_parent(os.getppid())
            os._exit(_draw_jobs(conns[k], jobs))
        forked.append(pid)
        conns[k].close()
    code = _draw_jobs(conns[0], jobs)
    for pid in forked:
        with contextlib.suppress(OSError):
            os.waitpid(pid, 0)
    # no interpreter teardown (and no flush of stdio buffers copied by the fork)
    os._exit(code)


def _draw_jobs(conn: Connection, jobs: Any) -> int:  # pragma: no cover - in the processes
    """Receive the result on ``conn`` and draw the jobs of ``jobs`` until None: exit code."""
    code = 0
    try:
        draw, result, directory, first = pickle.loads(conn.recv_bytes())
        while (job := jobs.get()) is not None:
            name, extra = job
            if isinstance(extra, str) and extra == _IN_PAYLOAD:
                extra = first[name]
            try:
                path = draw(result, directory, name, extra)
            except BaseException as exc:  # the command's error: sent back, not printed
                conn.send(("error", name, _sendable(exc), traceback.format_exc()))
                break
            conn.send(("ok", name, path))
    except (EOFError, OSError, KeyboardInterrupt):
        code = 1  # the command is gone or ending
    finally:
        with contextlib.suppress(Exception):
            conn.close()
    return code


def _sendable(exc: BaseException) -> BaseException:
    """``exc`` if it survives pickling, else a RuntimeError saying what it was."""
    try:
        return pickle.loads(pickle.dumps(exc))
    except Exception:
        return RuntimeError(f"{type(exc).__name__}: {exc}")
