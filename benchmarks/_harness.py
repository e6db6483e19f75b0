"""Tiny benchmark harness: best-of-N wall time of ours and of a naive reference, same run."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class BenchResult:
    """One benchmark: our time, the naive reference's time, and the target in words."""

    name: str
    ours_s: float
    reference_s: float
    reference: str
    target: str
    met: bool
    #: Unit of ``ours_s`` and ``reference_s``: "s" for times (the default) or "B/instant" for
    #: memory benchmarks, whose two fields then hold bytes per instant.
    unit: str = "s"

    @property
    def ratio(self) -> float:
        """How many times faster we are than the reference."""
        return self.reference_s / self.ours_s if self.ours_s > 0 else float("inf")


def best_time(fn: Callable[[], object], repeat: int = 5, number: int = 1) -> float:
    """Best wall time of ``number`` calls of ``fn`` over ``repeat`` trials [s per call]."""
    fn()  # warm up (JIT compilation, caches)
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        best = min(best, (time.perf_counter() - t0) / number)
    return best
