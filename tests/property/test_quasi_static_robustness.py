"""Robustness of the quasi-static models on random bearings and imperfections (hypothesis).

Heavy waviness on lightly preloaded bearings unloads balls, leaves a single ball loaded at the
warm start of an instant, or holds a 2-D shaft by two opposite balls only. Whatever the input,
a run ends with finite results or with a named error (contact loss or a singular system) that
gives the instant; never a NaN and never a stalled Newton iteration.
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from runout.api import Imperfections
from runout.base.errors import (
    CaseError,
    ContactLossError,
    ConvergenceError,
    NumericalError,
    RunoutError,
)
from runout.case.model import Case
from runout.geometry.bearing import BallBearing, Operation
from runout.runner import run_model

# Random short records put lines closer than 1/record length: the warning is right, and expected.
pytestmark = pytest.mark.filterwarnings("ignore::runout.analysis.spectrum.LineResolutionWarning")


@st.composite
def random_case(draw: st.DrawFn, model: str) -> dict[str, Any]:
    """Keyword arguments of BallBearing, Operation and the imperfections, and [analysis]."""
    z = draw(st.integers(5, 13))
    d = draw(st.floats(0.5e-3, 4e-3))
    waviness = [
        {
            "part": draw(st.sampled_from(["inner", "outer", "ball"])),
            "order": draw(st.integers(1, 3 * z)),
            "amplitude": 10.0 ** draw(st.floats(-9.0, -5.3)),
            "phase": draw(st.floats(0.0, 2 * math.pi)),
        }
        for _ in range(draw(st.integers(1, 4)))
    ]
    sigma = 10.0 ** draw(st.floats(-9.0, -6.5))
    errors = [draw(st.floats(-3.0, 3.0)) * sigma for _ in range(z)]
    return {
        "bearing": {
            "elements": z,
            "element_diameter": d,
            "pitch_diameter": d * draw(st.floats(3.5, 8.0)),
            "inner_conformity": draw(st.floats(0.505, 0.56)),
            "outer_conformity": draw(st.floats(0.505, 0.56)),
            "radial_clearance": draw(st.floats(0.0, 20e-6)),
        },
        "operation": {
            "rotating_ring": draw(st.sampled_from(["inner", "outer"])),
            "speed": draw(st.floats(1.0, 300.0)),
            "axial_load": 10.0 ** draw(st.floats(-0.5, 2.5)),
        },
        "waviness": waviness,
        "diameter_errors": errors,
        "analysis": {"model": model, "revolutions": draw(st.floats(1.0, 6.0)), "samples": 256},
    }


def _check(data: dict[str, Any]) -> None:
    try:
        bearing = BallBearing(**data["bearing"])
        waves = Imperfections(elements=bearing.elements)
        for entry in data["waviness"]:
            waves = waves.waviness(**entry)
        case = Case.from_inputs(
            bearing,
            Operation(**data["operation"]),
            waves.diameter_errors(data["diameter_errors"]),
            analysis=data["analysis"],
        )
    except RunoutError:  # impossible geometry etc.: the case checks say so, not the model
        return
    try:
        result = run_model(case)
    except CaseError:  # the model-level input checks (runout.runner.checks) name the key
        return
    except (ContactLossError, NumericalError) as exc:
        assert not isinstance(exc, ConvergenceError), f"{exc}\n{json.dumps(data)}"
        assert "instant" in str(exc)
        return
    assert np.all(np.isfinite(result.displacement))
    json.dumps(result.to_json(), allow_nan=False)


@settings(max_examples=40, deadline=None)
@given(data=random_case("quasi_static_3d"))
def test_quasi_static_3d_solves_or_names_the_instant(data: dict[str, Any]) -> None:
    _check(data)


@settings(max_examples=40, deadline=None)
@given(data=random_case("quasi_static_2d"))
def test_quasi_static_2d_solves_or_names_the_instant(data: dict[str, Any]) -> None:
    _check(data)
