"""Hostile inputs through the public Python API: the budgets and key-named errors of a case file.

The review found the Python API bypassing what the case file enforces: profile arrays of
5 x 10^7 points ended in a raw MemoryError, ``diameter_errors`` with 10^7 entries ran for
minutes before its length check, complex deviations were cast to real without a word, five
misuses (a bearing that is not one, ...) raised errors that named no key, and ``np.float32``
values were refused as "not a positive finite number". Each reproducer runs in a subprocess
under the memory limit and the timeout of the command-line corpus
(``tests/cli/test_hostile_inputs.py``), so that a regression fails the test, not the machine.
"""

from __future__ import annotations

import json
import math
import resource
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import runout
from runout.base.errors import CaseError, GeometryError
from runout.case.builder import Imperfections, build_case

#: Address space of one reproducer [bytes], as the command-line corpus.
MEMORY_LIMIT = 3 * 2**30
#: Seconds one reproducer may take; the refusals are checked to take far less.
TIMEOUT = 120.0

PRELUDE = """
import json, numpy as np, runout
from runout.base.errors import CaseError, GeometryError
from runout.case.builder import Imperfections, build_case
bearing = runout.BallBearing(elements=8, element_diameter=1e-3, pitch_diameter=7e-3,
                             radial_clearance=10e-6)
operation = runout.Operation(rotating_ring="outer", speed=90.0, axial_load=20.0)

def report(fn):
    try:
        fn()
    except (CaseError, GeometryError) as exc:
        print(json.dumps({"error": type(exc).__name__, "key": exc.key, "text": str(exc),
                          "type_error": isinstance(exc, TypeError)}))
    else:
        print(json.dumps({"error": None}))
"""


def _limit() -> None:  # pragma: no cover - runs in the child
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def _api(body: str) -> tuple[dict[str, object], float]:
    """Run ``body`` after :data:`PRELUDE` in a limited subprocess: its report and seconds."""
    start = time.monotonic()
    done = subprocess.run(
        [sys.executable, "-c", PRELUDE + textwrap.dedent(body)],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        preexec_fn=_limit,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.splitlines()[-1]), time.monotonic() - start


def test_profile_arrays_beyond_the_budget_are_refused_naming_the_key() -> None:
    got, _ = _api(
        """
        n = 50_000_000
        angles = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
        report(lambda: runout.run(
            "linear", bearing=bearing, operation=operation,
            imperfections=Imperfections(elements=8).profile(
                "inner", orders=(2, 30), angles=angles, deviations=np.zeros(n))))
        """
    )
    assert got["error"] == "CaseError", got
    assert got["key"] in ("profile[1].angles", "profile[1].deviations"), got
    assert "points" in str(got["text"]) and "resample" in str(got["text"])


def test_a_larger_memory_budget_admits_a_larger_profile() -> None:
    # the same budget as a case file: [analysis] max_memory raises it
    angles = np.linspace(0.0, 2 * np.pi, 6_000_000, endpoint=False)
    imperfections = Imperfections(elements=8).profile(
        "inner", orders=(2, 30), angles=angles, deviations=1e-8 * np.cos(9 * angles)
    )
    bearing = runout.BallBearing(elements=8, element_diameter=1e-3, pitch_diameter=7e-3)
    with pytest.raises(CaseError) as refused:
        build_case(bearing, imperfections=imperfections, analysis={"model": "linear"})
    assert refused.value.key == "profile[1].angles"
    case = build_case(
        bearing, imperfections=imperfections, analysis={"model": "linear", "max_memory": "4 GiB"}
    )
    amplitude = case.imperfections.inner.amplitudes[list(case.imperfections.inner.orders).index(9)]
    assert math.isclose(amplitude, 1e-8, rel_tol=1e-9)


@pytest.mark.parametrize("method", ["diameter_errors", "pitch_errors"])
@pytest.mark.parametrize("elements", ["", "elements=8"])
@pytest.mark.parametrize("values", ["[0.0] * 10_000_000", "np.zeros(10_000_000)"])
def test_ten_million_element_errors_are_refused_at_once(
    method: str, elements: str, values: str
) -> None:
    got, took = _api(f"report(lambda: Imperfections({elements}).{method}({values}))")
    assert got["error"] == "CaseError" and got["key"] == f"elements.{method}", got
    assert "10000000 entries" in str(got["text"])
    assert took < 20.0  # was minutes: every entry converted before the length was looked at


@pytest.mark.parametrize(
    ("call", "key"),
    [
        (
            "Imperfections(elements=8).profile('inner', orders=(2, 30), angles=theta, "
            "deviations=1e-8 * np.exp(3j * theta))",
            "profile[1].deviations",
        ),
        (
            "Imperfections(elements=8).profile('inner', orders=(2, 30), angles=theta + 0j, "
            "deviations=np.zeros(360))",
            "profile[1].angles",
        ),
        (
            "Imperfections(elements=8).diameter_errors(np.zeros(8, complex))",
            "elements.diameter_errors",
        ),
        ("Imperfections(elements=8).pitch_errors([0.0] * 7 + [1e-3j])", "elements.pitch_errors"),
        (
            "Imperfections().waviness('inner', order=9, amplitude=1e-8 + 0j)",
            "waviness[1].amplitude",
        ),
        (
            "runout.BallBearing(elements=8, element_diameter=1e-3 + 0j, pitch_diameter=7e-3)",
            "element_diameter",
        ),
        ("runout.Operation(speed=np.complex128(90.0))", "operation.speed"),
        ("runout.Material(youngs_modulus=np.complex64(2e11))", "material.youngs_modulus"),
    ],
)
def test_complex_input_is_refused_naming_the_key_never_cast(call: str, key: str) -> None:
    got, _ = _api(
        f"theta = np.linspace(0.0, 2 * np.pi, 360, endpoint=False)\nreport(lambda: {call})"
    )
    assert got["error"] in ("CaseError", "GeometryError") and got["key"] == key, got


def test_from_profile_refuses_complex_deviations() -> None:
    from runout.geometry.imperfections import ProfileError, from_profile

    theta = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
    with pytest.raises(ProfileError, match="deviations must be real numbers"):
        from_profile(theta, 1e-8 * np.exp(3j * theta), orders=(2, 10))


@pytest.mark.parametrize(
    ("call", "key"),
    [
        ("runout.run('linear', bearing='608', operation=operation)", "bearing"),
        ("runout.run('linear', bearing=bearing, operation={'speed': 90.0})", "operation"),
        (
            "runout.run('linear', bearing=bearing, operation=operation, imperfections=[1])",
            "imperfections",
        ),
        (
            "runout.case.model.Case.from_inputs(bearing, operation, imperfections=3)",
            "imperfections",
        ),
        ("Imperfections(elements=8, waviness=3)", "waviness"),
    ],
)
def test_api_misuses_name_the_argument_and_stay_type_errors(call: str, key: str) -> None:
    got, _ = _api(f"import runout.case.model\nreport(lambda: {call})")
    assert got["error"] == "ArgumentTypeError" and got["key"] == key, got
    assert got["type_error"], "code that caught TypeError still does"


_NUMPY_KINDS = [np.float64, np.float32, np.longdouble, lambda v: np.array(v)]


@settings(max_examples=30, deadline=None)
@given(
    kind=st.sampled_from(_NUMPY_KINDS),
    diameter=st.floats(0.5e-3, 1.5e-3),
    clearance=st.floats(0.0, 20e-6),
    speed=st.floats(1.0, 500.0),
)
def test_numpy_scalars_are_the_numbers_they_hold(
    kind: object, diameter: float, clearance: float, speed: float
) -> None:
    convert = kind  # np.float32(...) etc.; the Python float of it is the value it holds
    d, c, s = convert(diameter), convert(clearance), convert(speed)  # type: ignore[operator]
    numpy_bearing = runout.BallBearing(
        elements=np.int64(8), element_diameter=d, pitch_diameter=convert(7e-3), radial_clearance=c
    )  # type: ignore[operator]
    python_bearing = runout.BallBearing(
        elements=8,
        element_diameter=float(d),
        pitch_diameter=float(convert(7e-3)),
        radial_clearance=float(c),
    )  # type: ignore[operator]
    assert numpy_bearing == python_bearing
    assert type(numpy_bearing.element_diameter) is float and type(numpy_bearing.elements) is int
    operation = runout.Operation(speed=s, axial_load=convert(20.0))  # type: ignore[operator]
    assert operation == runout.Operation(speed=float(s), axial_load=float(convert(20.0)))  # type: ignore[operator]


def test_numpy_scalars_run_as_python_numbers() -> None:
    bearing = runout.BallBearing(
        elements=np.int64(8), element_diameter=np.float32(1e-3), pitch_diameter=np.array(7e-3)
    )
    operation = runout.Operation(rotating_ring="outer", speed=np.float32(90.0), axial_load=20)
    waves = Imperfections(elements=np.array(8)).waviness(
        "inner", order=np.int64(9), amplitude=np.float32(1e-8)
    )
    got = runout.run(
        "linear", bearing=bearing, operation=operation, imperfections=waves, samples=np.int64(2048)
    )
    same = runout.run(
        "linear",
        bearing=runout.BallBearing(
            elements=8, element_diameter=float(np.float32(1e-3)), pitch_diameter=7e-3
        ),
        operation=runout.Operation(rotating_ring="outer", speed=90.0, axial_load=20.0),
        imperfections=Imperfections(elements=8).waviness(
            "inner", order=9, amplitude=float(np.float32(1e-8))
        ),
        samples=2048,
    )
    assert math.isclose(got.runout.radial_pp_m, same.runout.radial_pp_m, rel_tol=1e-12)
    assert got.runout.radial_pp_m > 0.0


def test_a_spindle_layout_refuses_bearings_closer_than_their_rings_allow() -> None:
    from runout.geometry.imperfections import BearingImperfections
    from runout.geometry.spindle_layout import SpindleBearing, SpindleLayout

    ball = runout.BallBearing(elements=8, element_diameter=1e-3, pitch_diameter=7e-3)
    perfect = BearingImperfections.perfect(8)

    def layout(rear: float) -> SpindleLayout:
        return SpindleLayout(
            bearings=(
                SpindleBearing("front", 0.0, ball, perfect),
                SpindleBearing("rear", rear, ball, perfect),
            ),
            arrangement="DT",
            preload=20.0,
            preload_displacement=None,
            nose_position=0.0,
        )

    for span in (0.0, 1e-9, 0.999e-3):
        with pytest.raises(GeometryError) as refused:
            layout(span)
        assert refused.value.key == "bearings[2].position"
    assert layout(1e-3).bearings[1].position == 1e-3
    assert layout(np.float32(0.012)).bearings[1].position == float(np.float32(0.012))


@pytest.mark.parametrize(
    ("call", "key"),
    [
        ("BearingImperfections.perfect(10**9)", "n_elements"),
        ("spectral_law((1, 10**9), 1e-9, -1.0, phase=0.0)", "waviness_spectrum.orders"),
        # a harmonic built directly: orders bounded as the case file's (2**31 was accepted)
        ("single_harmonic(2**30, 1e-9, 0.0)", "harmonics.orders"),
        ("single_harmonic(9, 1e-9 + 1j, 0.0)", "waviness.amplitude"),
        ("spectral_law((2, 30), 1e-9, -1.0, phase=1j)", "waviness_spectrum.phase"),
        (
            "BearingImperfections.perfect(8).with_element_errors("
            "diameter_errors=np.zeros(8, complex))",
            "imperfections.diameter_errors",
        ),
    ],
)
def test_the_harmonics_constructors_bound_sizes_and_refuse_complex(call: str, key: str) -> None:
    # 10^9 elements or orders were allocated (MemoryError), complex element errors cast to real
    got, took = _api(
        "from runout.geometry.imperfections import BearingImperfections, single_harmonic, "
        f"spectral_law\nreport(lambda: {call})"
    )
    assert got["error"] == "ImperfectionError" and got["key"] == key, got
    assert took < 30.0


def test_a_bearing_built_in_python_has_the_case_files_bound_on_its_elements() -> None:
    # the geometry class had no cap (the case file's is 10,000): 10**6 balls were accepted
    with pytest.raises(GeometryError) as refused:
        runout.BallBearing(elements=10**6, element_diameter=1e-6, pitch_diameter=1.0)
    assert refused.value.key == "elements" and "at most 10000" in str(refused.value)
