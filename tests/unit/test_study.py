"""Studies (runout.study): seeding, batched kernel, chunking independence, sweeps, errors."""

from __future__ import annotations

import copy
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout import study as st_mod
from runout._study_kernels import project_rows, solve_batch, solve_batch_reference
from runout.case import Case, parse_case
from runout.errors import CaseError
from runout.models import quasi_static_2d as qs2
from runout.spectrum import extract_lines
from runout.study import line_label, run_study, sample_rng, statistics

KIM = {
    "bearing": {
        "type": "ball",
        "elements": 10,
        "element_diameter": "1.5875 mm",
        "pitch_diameter": "9.1 mm",
        "inner_conformity": 0.529,
        "outer_conformity": 0.535,
        "radial_clearance": "5 um",
    },
    "operation": {"rotating_ring": "inner", "speed": "7200 rpm", "axial_load": "60.68 N"},
    "analysis": {"model": "quasi_static_2d", "revolutions": 4, "samples": 256},
}


def kim(study: dict[str, Any], **extra: Any) -> Case:
    data = copy.deepcopy(KIM)
    data.update(extra)
    data["study"] = study
    return parse_case(data, "kim.toml")


def mc(samples: int = 12, seed: int = 5, **vary: Any) -> Case:
    return kim(
        {
            "kind": "montecarlo",
            "samples": samples,
            "seed": seed,
            "vary": vary or {"element_diameter_sigma": "0.1 um"},
        }
    )


def assert_same(a: st_mod.StudyResult, b: st_mod.StudyResult) -> None:
    assert a.samples == b.samples and a.model == b.model and a.values == b.values
    for k in st_mod.RUNOUT_KEYS:
        np.testing.assert_array_equal(a.runout[k], b.runout[k])
    assert a.lines.keys() == b.lines.keys()
    for key in a.lines:
        assert a.lines[key][0] == b.lines[key][0]
        np.testing.assert_array_equal(a.lines[key][1], b.lines[key][1])


# ------------------------------------------------------------------ seeding
def test_sample_rng_is_the_spawned_child() -> None:
    children = np.random.SeedSequence(42).spawn(6)
    for i in (0, 3, 5):
        a = sample_rng(42, i).standard_normal(4)
        b = np.random.default_rng(children[i]).standard_normal(4)
        np.testing.assert_array_equal(a, b)
    assert not np.array_equal(sample_rng(42, 0).random(3), sample_rng(42, 1).random(3))


# ------------------------------------------------------------------ kernels
def test_batched_kernel_matches_numpy_reference_and_model() -> None:
    case = mc()
    base = parse_case({**KIM, "elements": {"diameter_errors": [0.0] * 10}}, "k.toml")
    st_ = qs2.setup(base)
    t = np.arange(64) * (4 / 120.0) / 64
    c, theta = qs2.approaches(base, st_, t)
    offsets = 0.5 * np.random.default_rng(1).normal(0, 1e-7, (3, 10))
    q, unloaded, status, _ = solve_batch(c, offsets, theta, st_.stiffness, st_.initial_approach)
    ref = solve_batch_reference(c, offsets, theta, st_.stiffness, st_.initial_approach)
    assert np.all(status == 0) and unloaded.max() == 0
    np.testing.assert_allclose(q, ref, rtol=0, atol=1e-9 * st_.initial_approach)
    # and the per-bearing public solver of the model, bearing by bearing
    for m in range(3):
        variant = parse_case(
            {**KIM, "elements": {"diameter_errors": list(2.0 * offsets[m])}}, "k.toml"
        )
        disp, _ = qs2.solve(variant, t)
        np.testing.assert_allclose(q[m].T, disp[:2], rtol=0, atol=1e-9 * st_.initial_approach)
    serial = solve_batch(c, offsets, theta, st_.stiffness, st_.initial_approach, parallel=False)
    np.testing.assert_array_equal(serial[0], q)
    del case


def test_project_rows_is_the_least_squares_fit() -> None:
    rng = np.random.default_rng(2)
    t = np.arange(300) * 1e-3
    freqs = np.array([7.3, 41.0, 112.5])
    x = rng.normal(size=(5, 300))
    coef = project_rows(x, st_mod._line_projector(t, freqs))
    fit = extract_lines(t, x, freqs, axis=-1)
    np.testing.assert_allclose(np.hypot(coef[:, 1:4], coef[:, 4:]), fit.amplitude, rtol=1e-9)
    # fixed summation order: one row alone gives the same bits as inside a batch
    alone = project_rows(x[2:3], st_mod._line_projector(t, freqs))
    np.testing.assert_array_equal(alone[0], coef[2])


def test_batched_path_equals_per_bearing_model_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    case = mc(samples=4)
    fast = run_study(case)
    monkeypatch.setattr(st_mod, "_batched", lambda task: False)
    slow = run_study(case)
    for k in st_mod.RUNOUT_KEYS:
        np.testing.assert_allclose(fast.runout[k], slow.runout[k], rtol=1e-7, atol=1e-15)
    key = "x|ball size error: f_c"
    assert key in fast.lines and key in slow.lines
    np.testing.assert_allclose(fast.lines[key][1], slow.lines[key][1], rtol=1e-7)


def test_radial_load_is_not_dropped_by_the_batched_path() -> None:
    # The batched kernel has no external force; a loaded 2-D case must take the model's path.
    loaded = copy.deepcopy(KIM)
    loaded["operation"]["radial_load"] = "5 N"
    loaded["study"] = {
        "kind": "montecarlo",
        "samples": 2,
        "seed": 5,
        "vary": {"element_diameter_sigma": "0.1 um"},
    }
    with_load = run_study(parse_case(loaded, "kim.toml"))
    without = run_study(mc(samples=2))
    # Same ball sizes, but the load stiffens the loaded side: the runout changes (by ~4e-5
    # here), far beyond the solver's 1e-12 agreement between identical runs.
    a, b = with_load.runout["radial_pp_m"], without.runout["radial_pp_m"]
    assert np.max(np.abs(a - b) / b) > 1e-6


# ------------------------------------------------------------------ reproducibility
def test_numbers_do_not_depend_on_chunking_or_workers() -> None:
    case = mc(samples=23)
    one = run_study(case)
    assert_same(one, run_study(case, chunk_size=4))
    with ThreadPoolExecutor(max_workers=2) as pool:
        assert_same(one, run_study(case, executor=pool, chunk_size=5))
    assert_same(one, run_study(case, workers=2, chunk_size=6))  # process pool


def test_generic_monte_carlo_draws_and_reproducibility() -> None:
    case = kim(
        {
            "kind": "montecarlo",
            "samples": 6,
            "seed": 9,
            "chunk_size": 4,
            "vary": {
                "operation.axial_load": {"distribution": "normal", "std": "5 N"},
                "bearing.radial_clearance": {
                    "distribution": "uniform",
                    "low": "4 um",
                    "high": "6 um",
                },
                "elements.diameter_errors": {
                    "distribution": "sample",
                    "values": ["-0.1 um", "0 um", "0.1 um"],
                },
            },
        }
    )
    a = run_study(case)
    assert a.samples == 6 and not a.errors
    loads = np.array(a.values["operation.axial_load"])
    assert np.all(np.abs(loads - 60.68) < 6 * 5.0) and np.unique(loads).size == 6
    clear = np.array(a.values["bearing.radial_clearance"])
    assert np.all((clear >= 4e-6) & (clear <= 6e-6))
    sizes = np.array(a.values["elements.diameter_errors"])
    assert sizes.shape == (6, 10) and set(np.round(sizes.ravel() * 1e7)) <= {-1.0, 0.0, 1.0}
    assert_same(a, run_study(case, chunk_size=1))


# ------------------------------------------------------------------ sweeps
def test_sweep_grid_over_quantities_and_models() -> None:
    case = kim(
        {
            "kind": "sweep",
            "models": ["quasi_static_2d", "quasi_static_3d"],
            "vary": {"operation.axial_load": {"start": "30 N", "stop": "90 N", "num": 3}},
        },
        elements={"diameter_errors": ["0.1 um", 0, 0, 0, 0, 0, 0, 0, 0, 0]},
    )
    res = run_study(case)
    assert res.samples == 6 and not res.errors
    assert res.model == ["quasi_static_2d"] * 3 + ["quasi_static_3d"] * 3
    np.testing.assert_allclose(res.values["operation.axial_load"], [30.0, 60.0, 90.0] * 2)
    # one 0.1 um oversize ball: f_c line ≈ 4Δ/Z = 40 nm whatever the preload (linear theory)
    fc = res.lines["x|ball size error: f_c"][1]
    np.testing.assert_allclose(fc[:3], 40e-9, rtol=0.02)
    js = res.to_json()
    assert len(js["points"]) == 6 and js["points"][0]["values"]["operation.axial_load"] == 30.0


def test_sweep_step_and_integer_keys() -> None:
    case = kim({"kind": "sweep", "vary": {"bearing.elements": {"start": 8, "stop": 12, "step": 2}}})
    quantities = st_mod.plan_quantities(case)
    assert quantities[0].values == (8, 10, 12)


# ------------------------------------------------------------------ statistics
@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0.0, 1e-6), min_size=2, max_size=60), st.integers(1, 30))
def test_statistics_are_ordered_and_consistent(values: list[float], bins: int) -> None:
    s = statistics(values, bins)
    eps = 1e-18
    assert s["min"] - eps <= s["p5"] <= s["p50"] + eps <= s["p95"] + 2 * eps <= s["max"] + 3 * eps
    assert s["min"] - eps <= s["mean"] <= s["max"] + eps
    assert s["two_sigma"] == 2.0 * s["std"]
    assert sum(s["histogram"]["counts"]) == len(values)
    assert len(s["histogram"]["edges"]) == bins + 1


def test_line_label_merges_element_numbers() -> None:
    label = "ball 1 size error: f_c; ball 2 size error: f_c; pitch errors: f_c"
    assert line_label(label) == "ball size error: f_c; pitch errors: f_c"
    assert line_label(line_label(label)) == line_label(label)


# ------------------------------------------------------------------ case validation
@pytest.mark.parametrize(
    ("study", "where", "text"),
    [
        ({"kind": "montecarlo", "vary": {"element_diameter_sigm": "1 um"}}, "vary", "did you mean"),
        (
            {"kind": "montecarlo", "vary": {"operation.axial_lod": {"distribution": "uniform"}}},
            "study.vary.operation.axial_lod",
            "did you mean 'operation.axial_load'",
        ),
        (
            {"kind": "montecarlo", "vary": {"operation.axial_load": {"distribution": "normal"}}},
            "study.vary.operation.axial_load.std",
            "required",
        ),
        (
            {
                "kind": "montecarlo",
                "vary": {"operation.axial_load": {"distribution": "normal", "sd": 1}},
            },
            "study.vary.operation.axial_load.sd",
            "did you mean 'std'",
        ),
        (
            {"kind": "sweep", "vary": {"operation.axial_load": {"start": 1, "stop": 2}}},
            "study.vary.operation.axial_load.num",
            "exactly one of num or step",
        ),
        (
            {"kind": "sweep", "samples": 3, "vary": {"operation.speed": {"values": [1]}}},
            "study.samples",
            "montecarlo",
        ),
        ({"kind": "montecarlo", "vary": {}}, "study.vary", "at least one"),
        (
            {"kind": "sweep", "vary": {"waviness.amplitude": {"values": [1]}}},
            "study.vary.waviness.amplitude",
            "waviness[1].amplitude",
        ),
    ],
)
def test_study_table_errors_name_the_key(study: dict[str, Any], where: str, text: str) -> None:
    with pytest.raises(CaseError) as err:
        kim(study)
    assert where in str(err.value) and text in str(err.value)


def test_drawn_values_are_checked_where_they_go() -> None:
    case = kim(
        {
            "kind": "montecarlo",
            "vary": {"operation.axial_load": {"distribution": "uniform", "low": "1 m", "high": 2}},
        }
    )
    with pytest.raises(CaseError, match=r"study\.vary\.operation\.axial_load\.low.*force"):
        st_mod.plan_quantities(case)
    case = kim(
        {"kind": "sweep", "vary": {"waviness[2].amplitude": {"values": ["1 nm"]}}},
    )
    with pytest.raises(CaseError, match="has 0"):
        st_mod.plan_quantities(case)


def test_resume_refuses_a_different_study(tmp_path: Any) -> None:
    run_study(mc(samples=3), out=tmp_path, plots=False)
    with pytest.raises(st_mod.StudyError, match="different"):
        run_study(mc(samples=3, seed=6), out=tmp_path, resume=True)
