"""Studies on workers (runout.study._pool): arrays shipped to workers, fused kernel, chunk fill."""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cases import kim_case
from runout.analysis.decompose import RESIDUAL_REL
from runout.case.model import Case
from runout.models import quasi_static_2d as qs2
from runout.study import _chunks as chunks_mod
from runout.study import _pool as pool_mod
from runout.study import _result as result_mod
from runout.study import _workers as workers_mod
from runout.study import run as st_mod
from runout.study._kernels import _contacts, solve_batch, solve_batch_reference
from runout.study.run import run_study


def mc(samples: int, seed: int = 7, chunk: int = 250) -> Case:
    return kim_case(
        study={
            "kind": "montecarlo",
            "samples": samples,
            "seed": seed,
            "chunk_size": chunk,
            "vary": {"element_diameter_sigma": "0.1 um"},
        }
    )


def chunks_equal(a: st_mod.StudyResult, b: st_mod.StudyResult) -> None:
    """Byte-identical results: same floats, same keys, same order, same errors."""
    assert a.model == b.model and a.values.keys() == b.values.keys() and a.errors == b.errors
    for key in a.values:
        assert np.asarray(a.values[key]).tobytes() == np.asarray(b.values[key]).tobytes()
    for k in st_mod.RUNOUT_KEYS:
        assert a.runout[k].tobytes() == b.runout[k].tobytes()
    assert list(a.lines) == list(b.lines)
    for key in a.lines:
        assert a.lines[key][0] == b.lines[key][0]
        assert a.lines[key][1].tobytes() == b.lines[key][1].tobytes()


# ------------------------------------------------------------------ fused kernel
def _shared(case: Case) -> tuple[Any, np.ndarray, np.ndarray]:
    base = kim_case(diameter_errors=[0.0] * 10)
    setup = qs2.setup(base)
    t = np.arange(48) * (4 / 120.0) / 48
    c, theta = qs2.approaches(base, setup, t)
    del case
    return setup, c, theta


@settings(max_examples=40, deadline=None)
@given(
    q0=st.floats(-3e-6, 3e-6),
    q1=st.floats(-3e-6, 3e-6),
    instant=st.integers(0, 47),
    spread=st.floats(0.0, 2e-6),
)
def test_contacts_is_the_force_stiffness_and_energy_of_the_model(
    q0: float, q1: float, instant: int, spread: float
) -> None:
    setup, c, theta = _shared(mc(2))
    ci = c[instant] + spread * np.sin(np.arange(10) * 1.7)
    cth, sth = np.cos(theta[instant]), np.sin(theta[instant])
    k = setup.stiffness
    f0, f1, h00, h01, h11, load, e = _contacts(ci, cth, sth, k, q0, q1)
    # NumPy reference (seed 001 eq. 14, 16-17): loads, their resultant and its Jacobian
    d = 2.0 * ci + q0 * cth + q1 * sth
    on = d > 0.0
    p = k * d[on] ** 1.5
    # sums of terms of both signs: compared on the scale of their terms
    scale = float(p.sum())
    np.testing.assert_allclose([f0, f1], [p @ cth[on], p @ sth[on]], rtol=0, atol=1e-12 * scale)
    kk = 1.5 * k * np.sqrt(d[on])
    hess = [kk @ (cth[on] ** 2), kk @ (cth[on] * sth[on]), kk @ (sth[on] ** 2)]
    np.testing.assert_allclose([h00, h01, h11], hess, rtol=0, atol=1e-12 * float(kk.sum()))
    assert math.isclose(load, float(p.sum()), rel_tol=1e-12)
    # the line search's energy: the model's own potential, to the bit
    assert e == qs2.hertz_potential(ci, cth, sth, k, q0, q1, np.zeros(2))
    np.testing.assert_allclose(e, k / 2.5 * np.sum(d[on] ** 2.5), rtol=1e-12)


def test_fused_kernel_still_matches_the_reference_newton() -> None:
    setup, c, theta = _shared(mc(2))
    offsets = 0.5 * np.random.default_rng(3).normal(0, 2e-7, (4, 10))
    q, _, status, _ = solve_batch(c, offsets, theta, setup.stiffness, setup.initial_approach)
    ref = solve_batch_reference(c, offsets, theta, setup.stiffness, setup.initial_approach)
    assert np.all(status == 0)
    np.testing.assert_allclose(q, ref, rtol=0, atol=1e-9 * setup.initial_approach)


# ------------------------------------------------------------------ arrays shipped to workers
def test_chunks_with_shipped_arrays_equal_chunks_that_set_up_the_case() -> None:
    plan = st_mod._plan(mc(30, chunk=8), None)
    shipped = chunks_mod._with_batch(plan.tasks)
    assert all(t.batch is not None for t in shipped)
    chunks_mod._BASES.clear()  # the worker's own set-up, from the case document
    for bare, task in zip(plan.tasks, shipped, strict=True):
        assert bare.batch is None
        assert chunks_mod.chunk_json(st_mod.evaluate_chunk(bare)) == chunks_mod.chunk_json(
            st_mod.evaluate_chunk(task)
        )


def test_byte_identical_for_any_worker_count_chunking_and_executor() -> None:
    from concurrent.futures import ThreadPoolExecutor

    one = run_study(mc(41, chunk=250))
    chunks_equal(one, run_study(mc(41, chunk=7)))
    chunks_equal(one, run_study(mc(41, chunk=10), workers=2))  # process pool, arrays shipped
    with ThreadPoolExecutor(max_workers=3) as threads:  # nogil kernels side by side
        chunks_equal(one, run_study(mc(41, chunk=5), executor=threads))


def test_byte_identical_with_thread_teams_in_the_workers(monkeypatch: pytest.MonkeyPatch) -> None:
    """Workers whose Numba team has two threads (a machine with twice the cores) run the
    parallel kernel in each chunk: the same bytes as one thread in this process."""
    one = run_study(mc(29, chunk=250))
    monkeypatch.setattr(st_mod, "worker_threads", lambda workers: 2)
    chunks_equal(one, run_study(mc(29, chunk=6), workers=2))


def test_a_case_whose_set_up_fails_is_left_to_the_workers(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def broken(task: Any) -> Any:
        raise MemoryError("no room")

    plan = st_mod._plan(mc(4, chunk=2), None)
    monkeypatch.setattr(chunks_mod, "_batch_base", broken)
    assert chunks_mod._with_batch(plan.tasks) == plan.tasks  # the per-bearing path records it


# ------------------------------------------------------------------ column-wise chunk fill
def _per_row_reference(
    task: st_mod.ChunkTask, b: pool_mod.BatchArrays, rows: pool_mod.RowResults
) -> dict[str, Any]:
    """The chunk as the former row-by-row loop built it (chunks_mod._add_lines per bearing)."""
    chunk = chunks_mod._empty_chunk(task)
    for row in range(task.stop - task.start):
        if rows.status[row] != 0:
            chunk["errors"][str(task.start + row)] = "failed"
            for k in st_mod.RUNOUT_KEYS:
                chunk["runout"][k].append(None)
            continue
        # the planar model has no axial freedom: its axial p-p is None, not 0
        figures = (rows.radial[row], None, rows.rro[row], rows.nrro[row])
        for k, v in zip(st_mod.RUNOUT_KEYS, figures, strict=True):
            chunk["runout"][k].append(None if v is None else float(v))
        chunks_mod._add_lines(
            chunk,
            row,
            (
                (name, float(b.frequencies[j]), b.labels[j], float(rows.pp[row, axis, j]))
                for axis, name in enumerate(("x", "y"))
                for j in range(b.frequencies.size)
            ),
        )
    return chunk


@pytest.mark.parametrize("failed", [(), (0, 3), (1,), (0, 1, 2, 3, 4)])
def test_column_fill_equals_the_row_by_row_records(
    monkeypatch: pytest.MonkeyPatch, failed: tuple[int, ...]
) -> None:
    task = chunks_mod._with_batch(st_mod._plan(mc(5, chunk=5), None).tasks)[0]
    b = task.batch
    assert b is not None
    # two lines whose labels differ only by element numbers: one entry, the larger p-p
    freqs = np.array([b.frequencies[0], 1.37 * b.frequencies[0]])
    b = dataclasses.replace(
        b,
        frequencies=freqs,
        labels=("ball 1 size error: f_c", "ball 2 size error: f_c"),
        projector=pool_mod.line_projector(b.time, freqs),
    )
    task = dataclasses.replace(task, batch=b)
    seen: list[pool_mod.RowResults] = []

    def failing(batch: Any, errors: Any, parallel: bool) -> pool_mod.RowResults:
        rows = pool_mod.evaluate_rows(batch, errors, parallel)
        status = rows.status.copy()
        status[list(failed)] = 1
        instant = np.where(status != 0, 3, -1)
        seen.append(dataclasses.replace(rows, status=status, instant=instant))
        return seen[-1]

    monkeypatch.setattr(chunks_mod, "evaluate_rows", failing)
    chunk = st_mod.evaluate_chunk(task)
    ref = _per_row_reference(task, b, seen[0])
    # the chunk's file (lists, None for a failed bearing) is the row-by-row record
    written = chunks_mod.chunk_json(chunk)
    assert written["runout"] == ref["runout"]
    assert written["lines"] == ref["lines"] and list(chunk["lines"]) == list(ref["lines"])
    assert sorted(chunk["errors"]) == sorted(ref["errors"])
    assert all("ContactLossError" in v for v in chunk["errors"].values())


def test_warm_kernels_loads_without_error() -> None:
    workers_mod.warm_kernels()
    assert (
        st_mod._init_worker is workers_mod.init_worker
        and st_mod._context is workers_mod.spawn_context
    )


# ------------------------------------------------------------------ RRO/NRRO split
def _split_eager(
    b: pool_mod.BatchArrays, q: np.ndarray, coef: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The split with every waveform built, zero or not (the former code, as a reference)."""
    t, x = b.time, q[:, :, 0]
    n_b, m, speed = x.shape[0], b.frequencies.size, b.rotation_hz
    w = 2.0 * np.pi * np.outer(b.frequencies, t)
    basis = np.concatenate([np.ones((1, t.size)), np.cos(w), np.sin(w)])
    fitted = np.einsum("bk,kn->bn", coef, basis, optimize=False)
    one_rev = np.linspace(0.0, 1.0 / speed, 4097)[:-1]
    rro_rev, rro_rec = np.zeros((n_b, one_rev.size)), np.zeros_like(x)
    rep = np.abs(b.frequencies / speed - np.round(b.frequencies / speed)) < 1e-9
    if rep.any():
        a_c, a_s = coef[:, 1 : 1 + m][:, rep], coef[:, 1 + m :][:, rep]
        for tt, out in ((one_rev, rro_rev), (t, rro_rec)):
            wr = 2.0 * np.pi * np.outer(b.frequencies[rep], tt)
            out += np.einsum("bk,kn->bn", a_c, np.cos(wr), optimize=False)
            out += np.einsum("bk,kn->bn", a_s, np.sin(wr), optimize=False)
    residual = x - fitted
    n_rev = math.floor(t.size * (t[1] - t[0]) * speed + 1e-9)
    spr = round(1.0 / (speed * (t[1] - t[0])))
    if b.synchronous and n_rev >= 2:
        blocks = residual[:, : n_rev * spr].reshape(n_b, n_rev, spr)
        avg = blocks.mean(axis=1)
        se = blocks.std(axis=1, ddof=1) / math.sqrt(n_rev)
        uncertainty = np.sqrt(np.mean(se**2, axis=1))
        avg = avg - avg.mean(axis=1, keepdims=True)
        level = np.sqrt(np.mean(avg**2, axis=1))
        keep = (level > 3.0 * uncertainty) & (level > RESIDUAL_REL * np.std(x, axis=1))
        if keep.any():
            phase = np.rint((t - t[0]) * speed * spr).astype(np.int64) % spr
            idx = (np.arange(one_rev.size) * spr // one_rev.size) % spr
            rro_rec = rro_rec + np.where(keep[:, None], avg[:, phase], 0.0)
            rro_rev = rro_rev + np.where(keep[:, None], avg[:, idx], 0.0)
    covers = t.size * (t[1] - t[0]) * speed >= 1.0 - 1e-9
    return np.ptp(rro_rec if covers else rro_rev, axis=1), np.ptp(x - rro_rec, axis=1)


@pytest.mark.parametrize("synchronous", [False, True])
@pytest.mark.parametrize("orders", [(), (2.0,), (2.0, 3.41), (3.41,)])
@pytest.mark.parametrize("revolutions", [4, 0.5])
def test_split_rows_equals_the_eager_split(
    synchronous: bool, orders: tuple[float, ...], revolutions: float
) -> None:
    speed, spr = 50.0, 64
    t = np.arange(int(revolutions * spr)) / (speed * spr)
    freqs = np.array(orders) * speed
    rng = np.random.default_rng(11)
    n_b = 6
    x = rng.normal(0.0, 1e-9, (n_b, t.size))
    for f in freqs:
        x += rng.normal(0.0, 1e-7, (n_b, 1)) * np.cos(2 * np.pi * f * t + rng.uniform(0, 6))
    x[::2] += 3e-8 * np.sin(2 * np.pi * 7 * speed * t)  # something synchronous, in half
    q = np.stack([x, np.zeros_like(x)], axis=-1)
    b = pool_mod.BatchArrays(
        time=t,
        c=np.zeros((t.size, 3)),
        theta=np.zeros((t.size, 3)),
        frequencies=freqs,
        labels=tuple(f"line {k}" for k in range(freqs.size)),
        projector=pool_mod.line_projector(t, freqs),
        synchronous=synchronous,
        z=3,
        rotation_hz=speed,
        stiffness=1.0,
        d_ref=1.0,
        max_iter=1,
    )
    coef = x @ b.projector.T
    rro, nrro = pool_mod.split_rows(b, q, coef)
    ref_rro, ref_nrro = _split_eager(b, q, coef)
    assert rro.tobytes() == ref_rro.tobytes() and nrro.tobytes() == ref_nrro.tobytes()


# ------------------------------------------------------------------ samples.csv
@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(allow_nan=True, allow_infinity=True, width=64), max_size=20))
def test_csv_cells_column_by_column_are_the_cells(values: list[float]) -> None:
    columns = [
        np.array(values, dtype=np.float64),
        np.arange(len(values)),
        np.array([*values, "inner", 3], dtype=object),
    ]
    for col in columns:
        assert result_mod._cells(col) == [result_mod._cell(v) for v in col]


def test_in_process_chunks_run_on_threads_only_when_batched_and_several() -> None:
    import numba

    many = chunks_mod._with_batch(st_mod._plan(mc(30, chunk=8), None).tasks)
    assert chunks_mod._threads(many) == min(4, numba.config.NUMBA_NUM_THREADS)
    assert chunks_mod._threads(many[:1]) == 1  # one chunk: the kernel's own threads
    assert chunks_mod._threads(st_mod._plan(mc(30, chunk=8), None).tasks) == 1  # no arrays
