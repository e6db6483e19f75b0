"""A result's JSON reads back into a RunResult that writes the same JSON, byte for byte.

The documents are the stored ``runout run --json`` outputs of every example
(``tests/data/examples_json``, checked against the CLI by ``tests/cli/test_examples_json.py``).
Byte for byte holds on any machine: nothing is computed, the stored floats are read and written
back (``repr`` round-trips a float exactly).
"""

from __future__ import annotations

import gzip
import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from runout.analysis.result_details import (
    DETAILS_BY_MODEL,
    DynamicDetails,
    EquilibriumDetails,
    Iso15242,
    QuasiStaticDetails,
    RollerDetails,
    Verdict,
)
from runout.analysis.results import RunResult, _radians_exactly
from runout.models.linear import LinearResult

ROOT = Path(__file__).resolve().parents[3]
STORED = sorted((ROOT / "tests" / "data" / "examples_json").glob("*.json.gz"))


def _dumps(doc: dict) -> bytes:
    """What ``runout run --json`` prints for ``doc``."""
    return (json.dumps(doc, indent=2, allow_nan=False) + "\n").encode()


def test_every_example_is_read_back() -> None:
    assert len(STORED) == len(list((ROOT / "examples").glob("*.toml")))


@pytest.mark.parametrize("path", STORED, ids=[p.name.removesuffix(".json.gz") for p in STORED])
def test_from_json_to_json_is_byte_identical(path: Path) -> None:
    stored = gzip.decompress(path.read_bytes())
    doc = json.loads(stored)
    result = RunResult.from_json(doc)
    assert _dumps(result.to_json()) == stored
    # the model's entries are typed, of the model's class
    assert isinstance(result.details, DETAILS_BY_MODEL[doc["model"]])
    assert result.time.size == 0  # no record was given: the mean is the JSON's
    assert result.mean_displacement() == doc["mean_displacement_m"]


def test_typed_fields_of_each_model() -> None:
    docs = {
        p.name.removesuffix(".json.gz"): json.loads(gzip.decompress(p.read_bytes())) for p in STORED
    }
    qs = RunResult.from_json(docs["seed001_kim_table4"]).details
    assert isinstance(qs, QuasiStaticDetails) and qs.planar
    assert qs.approach_m == docs["seed001_kim_table4"]["initial_approach_m"]
    q3 = RunResult.from_json(docs["seed000_tada_fig7"]).details
    assert isinstance(q3, QuasiStaticDetails) and not q3.planar
    assert q3.approach_m == docs["seed000_tada_fig7"]["preload_approach_m"]
    eq = RunResult.from_json(docs["seed001_kim_equilibrium"]).details
    assert isinstance(eq, EquilibriumDetails)
    assert (
        eq.radial_stiffness.kxx_n_per_m
        == docs["seed001_kim_equilibrium"]["radial_stiffness"]["kxx_n_per_m"]
    )
    assert eq.stiffness_matrix.dofs[0] == "axial"
    dyn = RunResult.from_json(docs["seed003_purohit_clearance"]).details
    assert isinstance(dyn, DynamicDetails)
    assert (
        list(dyn.natural_frequencies_hz)
        == docs["seed003_purohit_clearance"]["natural_frequencies_hz"]
    )
    assert dyn.sample_rate_hz is None  # not in the JSON
    roller = RunResult.from_json(docs["seed004_nu209"])
    assert isinstance(roller.details, RollerDetails)
    assert roller.details.iso492.quantity in ("Kia", "Kea")
    assert roller.details.solution is None
    assert roller.element == "roller"  # the roller_pass_* aliases name it
    linear = RunResult.from_json(docs["seed002_608"])
    assert isinstance(linear, LinearResult) and linear.spectral_lines is not None
    assert linear.variant == docs["seed002_608"]["linear_variant"]


def test_linear_lines_rebuilt_from_the_components() -> None:
    doc = json.loads(
        gzip.decompress((ROOT / "tests/data/examples_json/seed002_608.json.gz").read_bytes())
    )
    result = RunResult.from_json(doc)
    assert isinstance(result, LinearResult) and result.spectral_lines is not None
    lines = result.spectral_lines
    # every x component comes back as the amplitude and phase of its order's line
    for c in doc["components"]:
        k = int(np.searchsorted(lines.order, c["order"]))
        assert lines.order[k] == c["order"]
        phasor = lines.x_complex[k] if c["direction"] == "x" else lines.y_complex[k]
        assert abs(phasor) * 2.0 == pytest.approx(c["pp_m"], rel=1e-12)
        assert math.remainder(float(np.angle(phasor)) - c["phase_rad"], 2 * math.pi) == (
            pytest.approx(0.0, abs=1e-9)
        )


def test_analysis_outputs_read_back() -> None:
    doc = json.loads(
        gzip.decompress((ROOT / "tests/data/examples_json/seed004_nu209.json.gz").read_bytes())
    )
    iso = {
        "unit": "um/s",
        "speed_rpm": 1800.0,
        "direction": "measuring",
        "measuring_direction": [0.6, -0.8],
        "bands": {
            "L": {"low_hz": 50.0, "high_hz": 300.0, "rms_um_per_s": 1.5},
            "M": {"low_hz": 300.0, "high_hz": 1800.0, "rms_um_per_s": 0.25},
            "H": {"low_hz": 1800.0, "high_hz": 10000.0, "rms_um_per_s": 0.0},
        },
    }
    verdict = {"quantity": "iso15242.L", "limit_um_per_s": 2.0, "value_um_per_s": 1.5, "pass": True}
    notes = doc.pop("notes")
    doc.update(iso15242=iso, verdict=verdict, notes=notes)
    result = RunResult.from_json(doc)
    assert result.iso15242 == Iso15242.from_json(iso)
    assert result.verdict == Verdict(
        quantity="iso15242.L", limit=2.0, value=1.5, passed=True, unit="um/s"
    )
    # the measuring direction is the one the bands state
    assert list(result.measuring_direction) == [0.6, -0.8]
    assert list(result.to_json()) == list(doc)
    assert _dumps(result.to_json()) == _dumps(doc)
    metres = {"quantity": "radial_pp", "limit_m": 1e-6, "value_m": 2e-6, "pass": False}
    assert Verdict.from_json(metres).to_json() == metres
    assert list(Verdict.from_json(metres).to_json()) == list(metres)


def test_a_record_is_taken_and_checked() -> None:
    doc = json.loads(gzip.decompress(STORED[0].read_bytes()))
    t = np.linspace(0.0, 1.0, 5)
    disp = np.zeros((3, 5))
    result = RunResult.from_json(doc, time=t, displacement=disp)
    assert result.time.size == 5 and result.displacement.shape == (3, 5)
    with pytest.raises(ValueError, match="both"):
        RunResult.from_json(doc, time=t)
    with pytest.raises(ValueError, match="shape"):
        RunResult.from_json(doc, time=t, displacement=np.zeros((3, 4)))


@given(st.floats(-720.0, 720.0, allow_nan=False))
def test_contact_angle_degrees_read_back_exactly(degrees: float) -> None:
    doc = json.loads(gzip.decompress(STORED[0].read_bytes()))
    doc["contact_angle_deg"] = degrees
    result = RunResult.from_json(doc)
    assert result.to_json()["contact_angle_deg"] == degrees
    # the angle in radians is the nearest: within an ulp or two of the value
    assert result.contact_angle == pytest.approx(math.radians(degrees), rel=1e-15, abs=1e-300)
    probe = _radians_exactly(29.0)  # no float has exactly 29 deg: math.radians's is taken
    assert probe == math.radians(29.0)


def test_no_untyped_bag_or_closures_remain() -> None:
    import dataclasses

    names = {f.name for f in dataclasses.fields(RunResult)}
    assert "extras" not in names and "writers" not in names
    assert {"details", "iso15242", "verdict"} <= names
