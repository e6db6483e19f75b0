"""Results as data: RunResult.to_dataframe / to_xarray / plot, StudyResult.to_dataframe / plot."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np
import pytest

from cases import KIM_TOML
from runout import examples
from runout.analysis.results import RunResult
from runout.case.model import load_case, parse_case
from runout.runner import run_model
from runout.study.run import Quantity, StudyResult, run_study

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
LINE_COLUMNS = [
    "direction",
    "frequency_hz",
    "order",
    "pp_m",
    "phase_rad",
    "repeatable",
    "label",
    "top_source",
]


@pytest.fixture(scope="module")
def tada() -> RunResult:
    """A 3-D result: axial motion, a line with two sources."""
    return run_model(load_case(EXAMPLES / "seed000_tada_fig6.toml"))


@pytest.fixture(scope="module")
def linear() -> RunResult:
    """Many lines in x and y, repeatable and not."""
    return run_model(examples.anderon_608().case())


def test_dataframe_has_one_row_per_line_largest_first(linear: RunResult) -> None:
    df = linear.to_dataframe()
    assert list(df.columns) == LINE_COLUMNS
    assert len(df) == len(linear.components) > 100
    assert list(df["pp_m"]) == sorted(df["pp_m"], reverse=True)
    expected = linear.to_json()["components"]  # the JSON contract's order and values
    for name in ("direction", "frequency_hz", "order", "pp_m", "phase_rad", "repeatable", "label"):
        assert list(df[name]) == [c[name] for c in expected], name
    assert df["repeatable"].any() and not df["repeatable"].all()
    assert set(df["direction"]) == {"x", "y"}
    assert df.attrs["units"]["pp_m"] == "m" and df.attrs["units"]["frequency_hz"] == "Hz"
    assert df.attrs["units"]["phase_rad"] == "rad"
    assert df.attrs["model"] == "linear" and df.attrs["title"] == linear.title


def test_top_source_is_the_largest_sources_label(tada: RunResult) -> None:
    df = tada.to_dataframe()
    shared = [c for c in tada.lines() if len(c.sources) > 1]
    assert shared, "the fixture must have a line with several sources"
    for row, c in zip(df.itertuples(), tada.lines(), strict=True):
        assert row.top_source == c.sources[0].label()
    # the short label counts the other sources; top_source names only the largest
    row = df.iloc[tada.lines().index(shared[0])]
    assert row["label"].endswith(f"+{len(shared[0].sources) - 1} more")
    assert row["top_source"] != row["label"] and row["label"].startswith(row["top_source"])


def test_dataframe_of_a_result_without_lines_keeps_its_columns() -> None:
    result = run_model(load_case(EXAMPLES / "seed001_kim_equilibrium.toml"))
    df = result.to_dataframe()
    assert list(df.columns) == LINE_COLUMNS and len(df) == 0
    assert df.attrs["model"] == "equilibrium"


def test_xarray_history_with_coordinates_and_units(tada: RunResult) -> None:
    da = tada.to_xarray()
    assert da.dims == ("direction", "time")
    assert list(da["direction"].values) == ["x", "y", "z"]
    np.testing.assert_array_equal(da["time"].values, tada.time)
    np.testing.assert_array_equal(da.sel(direction="z").values, tada.z)
    np.testing.assert_array_equal(da.values, tada.displacement)
    assert tada.axial_motion  # z is part of this record
    assert da.attrs["units"] == "m" and da["time"].attrs["units"] == "s"
    assert da.attrs["model"] == "quasi_static_3d" and da.attrs["title"] == tada.title
    assert da.attrs["measuring_direction"] == [float(v) for v in tada.measuring_direction]


@pytest.mark.parametrize("module", ["pandas", "xarray"])
def test_missing_extra_names_the_install_command(
    tada: RunResult, module: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(sys.modules, module, None)  # import of it raises ImportError
    method = tada.to_dataframe if module == "pandas" else tada.to_xarray
    with pytest.raises(ImportError, match=r'pip install "runout\[data\]"'):
        method()


def test_plot_kinds_return_axes_with_units(tada: RunResult) -> None:
    import matplotlib.pyplot as plt

    for kind, ylabel in (
        ("lines", "peak-to-peak ["),
        ("history", "displacement about mean ["),
        ("orbit", "y about mean ["),
        ("spectrum", "peak-to-peak ["),
    ):
        ax = tada.plot(kind=kind)
        assert ax.get_ylabel().startswith(ylabel), kind
        assert ax.get_xlabel().endswith("]"), kind
        plt.close(ax.figure)
    fig, ax = plt.subplots()
    assert tada.plot("orbit", ax=ax) is ax  # draws into the caller's axes
    plt.close(fig)
    with pytest.raises(ValueError, match="'lines', 'history', 'orbit', 'spectrum'"):
        tada.plot(kind="bode")


def test_plot_of_one_instant_says_why() -> None:
    result = run_model(load_case(EXAMPLES / "seed001_kim_equilibrium.toml"))
    with pytest.raises(ValueError, match="equilibrium model gives one instant"):
        result.plot("history")


SWEEP = (
    'title = "sweep to frame"\n'
    + KIM_TOML
    + '[elements]\ndiameter_errors = ["0.1 um", 0, 0, 0, 0, 0, 0, 0, 0, 0]\n'
    + '[analysis]\nmodel = "quasi_static_2d"\nrevolutions = 4\nsamples = 256\n'
    + '[study]\nkind = "sweep"\n[study.vary]\n'
    + '"operation.axial_load" = { values = ["40 N", "60 N", "80 N"] }\n'
)


@pytest.fixture(scope="module")
def sweep() -> StudyResult:
    import tomllib

    return run_study(parse_case(tomllib.loads(SWEEP), "sweep.toml", EXAMPLES))


def test_study_dataframe_one_row_per_point(sweep: StudyResult) -> None:
    df = sweep.to_dataframe()
    head = ["sample", "model", "operation.axial_load"]
    runout = ["radial_pp_m", "rro_pp_m", "nrro_pp_m", "axial_pp_m"]
    assert list(df.columns[:7]) == head + runout
    assert list(df.columns[-1:]) == ["error"]
    assert len(df) == 3
    assert list(df["operation.axial_load"]) == [40.0, 60.0, 80.0]  # SI: N
    assert list(df["model"]) == ["quasi_static_2d"] * 3
    for k in runout:
        np.testing.assert_array_equal(df[k].to_numpy(), sweep.runout[k])
    assert df["radial_pp_m"].min() > 0.0
    lines = [c for c in df.columns if c.endswith("_pp_m") and c not in runout]
    assert len(lines) == len(sweep.lines) > 0
    assert all(re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", c) for c in lines)
    described = sweep.column_descriptions()["columns"]
    by_line = {(described[c]["direction"], described[c]["label"]): c for c in lines}
    points = sweep.points()
    for i, point in enumerate(points):  # every non-zero line of a point, at its p-p
        for c in point["components"]:
            name = by_line[(c["direction"], c["label"])]
            assert described[name]["frequency_hz"] == c["frequency_hz"]
            assert df.loc[i, name] == c["pp_m"]
    assert list(df["error"]) == ["", "", ""]
    assert df.attrs["kind"] == "sweep" and df.attrs["units"]["radial_pp_m"] == "m"
    assert df.attrs["units"]["operation.axial_load"] == "N"


def test_study_dataframe_keeps_errors_lists_and_the_limit() -> None:
    q_load = Quantity("operation.axial_load", ("operation", None, "axial_load"), 1, "sweep")
    q_d = Quantity("elements.diameter_errors", ("elements", None, "diameter_errors"), 2, "normal")
    result = StudyResult(
        kind="montecarlo",
        title="hand-made",
        seed=1,
        quantities=(q_load, q_d),
        model=["quasi_static_2d"] * 2,
        values={
            "operation.axial_load": [40.0, 50.0],
            "elements.diameter_errors": [[1e-7, -1e-7], [2e-7, 0.0]],
        },
        runout={
            "radial_pp_m": np.array([3e-8, np.nan]),
            "rro_pp_m": np.array([1e-8, np.nan]),
            "nrro_pp_m": np.array([2e-8, np.nan]),
            "axial_pp_m": np.array([0.0, np.nan]),
        },
        lines={"x|ball size error: f_c": (50.0, np.array([2e-8, 0.0]))},
        errors={1: "ContactLossError: too few balls loaded"},
        limit=("radial_pp", 2.5e-8),
    )
    df = result.to_dataframe()
    assert df.loc[0, "elements.diameter_errors"] == [1e-7, -1e-7]
    assert df.loc[1, "error"] == "ContactLossError: too few balls loaded"
    assert df.loc[0, "error"] == ""
    assert np.isnan(df.loc[1, "radial_pp_m"])
    assert list(df["pass"]) == [False, None]  # 3e-8 > 2.5e-8; a failed sample is neither
    assert list(df["x_ball_size_error_f_c_pp_m"]) == [2e-8, 0.0]
    assert df.attrs["limit"] == {"quantity": "radial_pp", "limit_m": 2.5e-8}
    assert df.attrs["units"]["elements.diameter_errors"] == "m"


def test_study_plot(sweep: StudyResult) -> None:
    import matplotlib.pyplot as plt

    fig = sweep.plot()
    xlabels = [ax.get_xlabel() for ax in fig.axes]
    assert xlabels and all(label.startswith("axial load [") for label in xlabels)
    assert all(ax.get_ylabel().startswith("peak-to-peak [") for ax in fig.axes)
    plt.close(fig)
    assert sweep.plot(quantity="operation.axial_load") is not None
    plt.close("all")
    with pytest.raises(ValueError, match="draws kind='sweep'"):
        sweep.plot(kind="histograms")
    with pytest.raises(ValueError, match="not a drawn swept key"):
        sweep.plot(quantity="operation.speed")


def test_lines_dataframe_keeps_units_and_names_each_run(tada: RunResult, linear: RunResult) -> None:
    from runout.analysis.results import lines_dataframe

    both = lines_dataframe([tada, linear], key="model")
    assert both.attrs["units"]["pp_m"] == "m" and both.attrs["units"]["model"] == "-"
    assert set(both.attrs["runs"]) == {tada.model, linear.model}
    assert len(both) == len(tada.to_dataframe()) + len(linear.to_dataframe())
    assert (both["model"] == tada.model).sum() == len(tada.to_dataframe())
    with pytest.raises(ValueError, match="same model"):
        lines_dataframe([linear, linear])
    with pytest.raises(ValueError, match="already"):
        lines_dataframe({"a": linear}, key="pp_m")
    named = lines_dataframe({"a": linear, "b": linear})
    assert set(named["run"]) == {"a", "b"}
