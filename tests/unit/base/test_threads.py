"""Long records on two threads (issue 16): the spectral kernels' halves give the same result
to the bit, the quasi-static solves' halves agree with one pass to the solver's tolerance,
and no result depends on whether the threads ran (a study's worker thread runs them in turn)."""

from __future__ import annotations

import threading
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import numpy as np
import pytest

from runout import examples
from runout.analysis import _line_kernels as line_kernels
from runout.base import _threads as _threads
from runout.geometry import loading
from runout.models import _quasi_static as qsm
from runout.models import quasi_static_2d as qs2
from runout.models import quasi_static_3d as qs3


def _in_worker(fn: Any) -> Any:
    """fn() on a thread that is not the main one (the spans then run one after the other)."""
    with ThreadPoolExecutor(1) as pool:
        return pool.submit(fn).result()


def test_halves_cover_the_record_and_cut_on_the_alignment() -> None:
    assert _threads.halves(100, 1000) == ((0, 100),)
    spans = _threads.halves(5000, 1000, 256)
    assert spans[0][0] == 0 and spans[-1][1] == 5000 and spans[0][1] == spans[1][0]
    assert spans[0][1] % 256 == 0


def test_spans_run_on_two_threads_only_from_the_main_thread() -> None:
    seen: list[str] = []
    lock = threading.Lock()

    def work(first: int, last: int) -> int:
        with lock:
            seen.append(threading.current_thread().name)
        return last - first

    assert _threads.in_spans(work, ((0, 3), (3, 10))) == [3, 7]
    if _threads.parallel_allowed():
        assert all(name.startswith("runout-span") for name in seen)
    seen.clear()
    assert _in_worker(lambda: _threads.in_spans(work, ((0, 3), (3, 10)))) == [3, 7]
    assert all(not name.startswith("runout-span") for name in seen)


def test_projection_and_synthesis_halves_are_identical_to_the_bit() -> None:
    rng = np.random.default_rng(3)
    n = line_kernels._PARALLEL_MIN * 2 + 77  # two halves, the last block short
    x = np.ascontiguousarray(rng.normal(size=(2, n)))
    dt = 1e-4
    omega = 2 * np.pi * rng.uniform(1.0, 4000.0, 9)
    c2, s2 = line_kernels._project_uniform_kernel(x, dt, omega)
    c1, s1 = _in_worker(lambda: line_kernels._project_uniform_kernel(x, dt, omega))
    assert np.array_equal(c1, c2) and np.array_equal(s1, s2)
    a, b = rng.normal(size=(2, 9)), rng.normal(size=(2, 9))
    const = np.array([0.1, -0.2])
    y2 = line_kernels._synthesize_uniform_kernel(const, a, b, dt, omega, n)
    y1 = _in_worker(lambda: line_kernels._synthesize_uniform_kernel(const, a, b, dt, omega, n))
    assert np.array_equal(y1, y2)
    # and both still match the NumPy references
    tau = np.arange(n) * dt
    c_ref, _ = line_kernels._project_numpy(x, tau, omega)
    np.testing.assert_allclose(c2, c_ref, rtol=1e-9, atol=1e-9 * np.abs(c_ref).max())


@pytest.mark.parametrize("module", [qs3, qs2])
def test_a_long_solve_in_halves_agrees_with_one_pass(
    monkeypatch: pytest.MonkeyPatch, module: Any
) -> None:
    case = examples.tada().case()
    st = module.setup(case)
    t = qsm.time_grid(case.operation.speed, 20.0, qsm.SPLIT_MIN + 1000)
    halves, _ = module.solve(case, t, st)
    in_turn, _ = _in_worker(lambda: module.solve(case, t, st))
    assert np.array_equal(halves, in_turn)  # threads or not: the same record
    monkeypatch.setattr(qsm, "SPLIT_MIN", 1 << 40)
    one_pass, _ = module.solve(case, t, st)
    scale = float(np.abs(one_pass[:2]).max())
    # the second half starts from rest: its first instants agree to the Newton tolerance
    assert np.abs(halves - one_pass).max() <= 1e-11 * scale  # the kernels' RTOL


def test_a_failure_in_the_second_half_names_its_instant_in_the_record() -> None:
    calls: list[tuple[int, int]] = []

    def kernel(*args: Any) -> tuple[int, int]:
        first, last = args[-2], args[-1]
        calls.append((first, last))
        return (3, last - 5) if first > 0 else (0, -1)

    n = qsm.SPLIT_MIN + 10
    assert qsm.solve_in_halves(kernel, (), n) == (3, n - 5)
    cut = _threads.halves(n, qsm.SPLIT_MIN, qsm.ANCHOR)[0][1]
    assert sorted(calls) == [(0, cut), (cut, n)]


def test_the_axial_load_solution_is_reused_and_errors_are_not_kept() -> None:
    bearing = examples.tada_bearing()
    first = loading.axial_loading(bearing, 20.0)
    assert loading.axial_loading(bearing, 20.0) is first
    assert loading.axial_loading(bearing, 21.0).contact_angle > first.contact_angle
    with pytest.raises(loading.GeometryError):
        loading.axial_loading(bearing, -1.0)


def test_a_process_can_forbid_the_threads(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(_threads, "_enabled", True)
    _threads.use_threads(False)
    assert not _threads.parallel_allowed()
    seen: list[str] = []
    _threads.in_spans(lambda a, b: seen.append(threading.current_thread().name), ((0, 1), (1, 2)))
    assert seen == [threading.current_thread().name] * 2
    _threads.use_threads(True)
