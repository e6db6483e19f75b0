"""The spindle column of the key × model matrix (runout.case.conventions) is what the model does.

As tests/unit/case/test_conventions_matrix.py for the single-bearing models: a spindle base case
and the same case with one key changed; an honoured key changes the result, a refused key
ends with a CaseError naming it and the models that honour it, a key not applied leaves a
note naming it. Keys of [bearing] are changed in every [[bearings]] entry, imperfections are
given to the front bearing.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from convention_cells import assert_cell
from runout.base.errors import CaseError
from runout.case.conventions import KEYS
from runout.case.model import parse_case
from spindle_cases import spindle_document

Data = dict[str, Any]


def _base() -> Data:
    return spindle_document(
        [
            {"bearing": "front", "part": "inner", "order": 9, "amplitude": 5e-9, "phase": 0.3},
            {"bearing": "rear", "part": "ball", "order": 2, "amplitude": 5e-9, "element": 1},
            {"bearing": "front", "part": "ball", "order": 2, "amplitude": 4e-9, "element": 2},
        ],
        samples=1024,
        revolutions=4,
    )


def _bearings(key: str, value: Any) -> Callable[[Data], None]:
    def change(data: Data) -> None:
        for b in data["bearings"]:
            b[key] = value

    return change


def _set(path: str, value: Any) -> Callable[[Data], None]:
    table, key = path.split(".")

    def change(data: Data) -> None:
        data.setdefault(table, {})[key] = value

    return change


def _front_elements(key: str, value: Any) -> Callable[[Data], None]:
    def change(data: Data) -> None:
        data.setdefault("elements", {}).setdefault("front", {})[key] = value

    return change


def _add(entry: Data) -> Callable[[Data], None]:
    def change(data: Data) -> None:
        data["waviness"].append(entry)

    return change


def _roller(data: Data) -> None:
    data["bearings"][1] = {
        "name": "rear",
        "position": 12e-3,
        "type": "cylindrical_roller",
        "elements": 14,
        "element_diameter": 10e-3,
        "inner_raceway_diameter": 54.991e-3,
        "outer_raceway_diameter": 75.032e-3,
    }
    data["waviness"] = [w for w in data["waviness"] if w["bearing"] == "front"]


def _nominal(data: Data) -> None:
    for b in data["bearings"]:
        del b["radial_clearance"]
        b["nominal_contact_angle"] = 0.4


def _load_first(data: Data) -> None:
    data["operation"]["radial_load"] = 2.0
    data["operation"]["radial_load_direction"] = -1.0


def _moment_first(data: Data) -> None:
    data["operation"]["moment_load"] = 0.01
    data["operation"]["moment_load_direction"] = 1.0


def _axial_limit(data: Data) -> None:
    data["analysis"]["limit"] = "1 um"
    data["analysis"]["limit_on"] = "axial_pp"


def _load_base(data: Data) -> None:
    data["operation"]["radial_load"] = 2.0


def _moment_base(data: Data) -> None:
    data["operation"]["moment_load"] = 0.01


def _position_base(data: Data) -> None:
    # a spindle's kind is its [spindle] key: operation.preload agreeing with it is not applied
    del data["spindle"]["preload"]
    data["spindle"]["preload_displacement"] = 2e-6


def _none(data: Data) -> None:
    return None


def _life_modification(data: Data) -> None:
    # the modified life multiplies each rated bearing's L10r
    for b in data["bearings"]:
        b["fatigue_load_limit"] = 200.0
    data["lubrication"] = {"viscosity_ratio": 1.5, "contamination_factor": 0.5}
    data["analysis"]["reliability"] = 99.0


def _class_limit(data: Data) -> None:
    # a P4 limit at a bore of 8 mm (K_ia 2.5 um); the change moves the bore to 40 mm (4 um)
    data["analysis"]["limit"] = "P4"
    data["analysis"]["limit_bore"] = "8 mm"


def _acceleration(data: dict[str, Any]) -> None:
    data["analysis"]["signal"] = "acceleration"
    data["sensor"] = {"resonance": 3000.0, "damping_ratio": 0.05, "sample_rate": 12000.0}


#: key -> (patch of the base, the change of the key alone)
CHANGES: dict[str, tuple[Callable[[Data], None], Callable[[Data], None]]] = {
    'bearing.type = "cylindrical_roller"': (_none, _roller),
    "bearing.radial_clearance": (_none, _bearings("radial_clearance", 14e-6)),
    "bearing.nominal_contact_angle": (_none, _nominal),
    "bearing.contact_angle": (_none, _bearings("contact_angle", 0.35)),
    "bearing.inner_conformity, outer_conformity (or groove radii)": (
        _none,
        _bearings("inner_conformity", 0.515),
    ),
    "bearing.dynamic_load_rating": (_none, _bearings("dynamic_load_rating", 5000.0)),
    "bearing.fatigue_load_limit, lubrication, analysis.reliability": (
        _bearings("dynamic_load_rating", 5000.0),
        _life_modification,
    ),
    "material.youngs_modulus, poisson_ratio": (_none, _set("material.youngs_modulus", 2e11)),
    "material.density": (_none, _set("material.density", 7000.0)),
    "operation.rotating_ring": (_none, _set("operation.rotating_ring", "outer")),
    "operation.other_ring_speed": (_none, _set("operation.other_ring_speed", 3.0)),
    "operation.axial_load": (_none, _set("operation.axial_load", 5.0)),
    'operation.preload = "position"': (_position_base, _set("operation.preload", "position")),
    "operation.radial_load": (_none, _set("operation.radial_load", 2.0)),
    "operation.radial_load_direction": (_load_base, _set("operation.radial_load_direction", -1.0)),
    "operation.moment_load": (_none, _set("operation.moment_load", 0.01)),
    "operation.moment_load_direction": (
        _moment_base,
        _set("operation.moment_load_direction", 1.0),
    ),
    'waviness, waviness_spectrum, profile: part = "inner" / "outer"': (
        _none,
        _add({"bearing": "rear", "part": "outer", "order": 7, "amplitude": 3e-9}),
    ),
    'waviness, waviness_spectrum, profile: part = "ball" / "roller"': (
        _none,
        _add({"bearing": "front", "part": "ball", "order": 2, "amplitude": 3e-9, "element": 3}),
    ),
    "slant": (_none, lambda d: d.__setitem__("slant", {"amplitude": 5e-8})),
    "elements.diameter_errors": (_none, _front_elements("diameter_errors", [1e-7] + [0.0] * 7)),
    "elements.pitch_errors": (_none, _front_elements("pitch_errors", [0.0, 0.01] + [0.0] * 6)),
    "elements.phase_frame": (_none, _front_elements("phase_frame", "fixed")),
    "analysis.revolutions, samples": (_none, _set("analysis.revolutions", 3)),
    "analysis.linear_variant": (_none, _set("analysis.linear_variant", "force_balance")),
    "analysis.race_control": (_none, _set("analysis.race_control", "inner")),
    "analysis.moment_arm": (_none, _set("analysis.moment_arm", "pitch_radius")),
    "analysis.bearing_damping, bearing_damping_coefficient": (
        _none,
        _set("analysis.bearing_damping", "kraemer"),
    ),
    "analysis.ring_tilt": (_none, _set("analysis.ring_tilt", "held")),
    "dynamics": (_none, lambda d: d.__setitem__("dynamics", {"mass": 0.03, "damping": 20.0})),
    "defect": (
        _none,
        lambda d: d.setdefault("defect", []).append(
            {"part": "outer", "width": 5e-4, "depth": 2e-5}
        ),
    ),
    "analysis.signal, sensor": (_none, _acceleration),
    "analysis.bands": (_none, _set("analysis.bands", "iso15242")),
    'analysis.limit_on = "axial_pp"': (_none, _axial_limit),
    "analysis.limit": (_none, _set("analysis.limit", "1 um")),
    "elements.grade, grade_sigma_divisor, grade_form_order": (
        _none,
        _front_elements("grade", "G5"),
    ),
    "analysis.limit_bore": (_class_limit, _set("analysis.limit_bore", "40 mm")),
    "spindle, bearings": (_none, _set("spindle.nose_position", -20e-3)),
}


def test_every_key_has_a_change() -> None:
    assert set(CHANGES) == {c.key for c in KEYS}


@pytest.mark.parametrize("key", [c.key for c in KEYS])
def test_spindle_cell_is_what_the_model_does(key: str) -> None:
    convention = next(c for c in KEYS if c.key == key)
    patch, change = CHANGES[key]
    base = _base()
    patch(base)
    assert_cell(convention, "spindle", base, change)


@pytest.mark.parametrize("model", ["linear", "quasi_static_3d", "dynamic"])
def test_other_models_refuse_a_spindle_case(model: str) -> None:
    data = _base()
    data["analysis"]["model"] = model
    with pytest.raises(CaseError) as info:
        parse_case(data, "matrix.toml")
    assert "analysis.model" in str(info.value)
    assert '"spindle"' in str(info.value)
