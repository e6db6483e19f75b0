"""Every cell of the key × model matrix (runout.case.conventions) is what the code does.

For each key and model, a base case of that model and the same case with only that key changed
are run: an honoured key changes the result, a refused key ends with a CaseError naming it and
the models that honour it, a key the model does not apply leaves a note naming it.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cases import TADA_BEARING
from convention_cells import assert_cell
from runout.case.conventions import KEYS, MODELS, conventions_page

DOC = Path(__file__).resolve().parents[3] / "docs" / "conventions.md"

Data = dict[str, Any]


def _base(model: str) -> Data:
    data: Data = {
        "title": "matrix",
        "bearing": dict(TADA_BEARING),
        "operation": {"speed": 90.0, "axial_load": 20.0},
        "waviness": [
            {"part": "inner", "order": 9, "amplitude": 5e-9, "phase": 0.3},
            {"part": "ball", "order": 2, "amplitude": 5e-9, "element": 1},
            {"part": "ball", "order": 2, "amplitude": 4e-9, "element": 2, "phase": 0.7},
        ],
        "analysis": {"model": model, "revolutions": 4, "samples": 1024},
    }
    if model == "dynamic":
        data["dynamics"] = {"mass": 0.02, "damping": 20.0}
    return data


def _set(path: str, value: Any) -> Callable[[Data], None]:
    table, key = path.split(".")

    def change(data: Data) -> None:
        data.setdefault(table, {})[key] = value

    return change


def _add(table: str, entry: Data) -> Callable[[Data], None]:
    def change(data: Data) -> None:
        data.setdefault(table, []).append(entry)

    return change


def _roller(data: Data) -> None:
    data["bearing"] = {
        "type": "cylindrical_roller",
        "elements": 14,
        "element_diameter": 10e-3,
        "inner_raceway_diameter": 54.991e-3,
        "outer_raceway_diameter": 75.032e-3,
    }
    data["waviness"] = [w for w in data["waviness"] if w["part"] != "ball"]


def _nominal(data: Data) -> None:
    del data["bearing"]["radial_clearance"]
    data["bearing"]["nominal_contact_angle"] = 0.4


def _radial_load(data: Data) -> None:
    data["operation"]["radial_load"] = 2.0


def _no_patch(data: Data, model: str) -> None:
    return None


def _load_unless_it_is_refused(data: Data, model: str) -> None:
    data["operation"]["radial_load"] = 2.0


def _moment_for_equilibrium(data: Data, model: str) -> None:
    if model == "equilibrium":
        data["operation"]["moment_load"] = 0.01


def _radial_load_for_equilibrium(data: Data, model: str) -> None:
    # under an axial load alone the free ring does not tilt: holding it would change nothing
    if model == "equilibrium":
        data["operation"]["radial_load"] = 2.0


def _rated_for_equilibrium(data: Data, model: str) -> None:
    # the modified life multiplies L10r: no rating, no life to modify
    if model == "equilibrium":
        data["bearing"]["dynamic_load_rating"] = 5000.0


def _life_modification(data: Data) -> None:
    data["bearing"]["fatigue_load_limit"] = 200.0
    data["lubrication"] = {"viscosity_ratio": 1.5, "contamination_factor": 0.5}
    data["analysis"]["reliability"] = 99.0


def _moment_load_for_equilibrium(data: Data, model: str) -> None:
    # without a moment load the balls' moments sum to 0 whatever their arm
    if model == "equilibrium":
        data["operation"]["moment_load"] = 0.05


def _held_axially(data: Data, model: str) -> None:
    # the dynamic column's cell: its rotor held axially (with the default spring preload it
    # moves axially and honours the key, condition honoured_when)
    if model == "dynamic":
        data["operation"]["preload"] = "position"


def _axial_limit(data: Data) -> None:
    data["analysis"]["limit"] = "1 um"
    data["analysis"]["limit_on"] = "axial_pp"


def _acceleration(data: Data) -> None:
    data["analysis"]["signal"] = "acceleration"
    data["sensor"] = {
        "resonance": 3000.0, "damping_ratio": 0.05, "sample_rate": 12000.0, "duration": 0.05,
    }  # fmt: skip


def _class_limit(data: Data, model: str) -> None:
    # a P4 limit at a bore of 8 mm (K_ia 2.5 um); the change moves the bore to 40 mm (4 um)
    data["analysis"]["limit"] = "P4"
    data["analysis"]["limit_bore"] = "8 mm"


#: key -> (patch of the base for this key, the change of the key alone)
CHANGES: dict[str, tuple[Callable[[Data, str], None], Callable[[Data], None]]] = {
    'bearing.type = "cylindrical_roller"': (_no_patch, _roller),
    "bearing.radial_clearance": (_no_patch, _set("bearing.radial_clearance", 14e-6)),
    "bearing.nominal_contact_angle": (_no_patch, _nominal),
    "bearing.contact_angle": (_no_patch, _set("bearing.contact_angle", 0.35)),
    "bearing.inner_conformity, outer_conformity (or groove radii)": (
        _no_patch,
        _set("bearing.inner_conformity", 0.515),
    ),
    "bearing.dynamic_load_rating": (_no_patch, _set("bearing.dynamic_load_rating", 5000.0)),
    "bearing.fatigue_load_limit, lubrication, analysis.reliability": (
        _rated_for_equilibrium,
        _life_modification,
    ),
    "material.youngs_modulus, poisson_ratio": (_no_patch, _set("material.youngs_modulus", 2e11)),
    "material.density": (_no_patch, _set("material.density", 7000.0)),
    "operation.rotating_ring": (_no_patch, _set("operation.rotating_ring", "outer")),
    "operation.other_ring_speed": (_no_patch, _set("operation.other_ring_speed", 3.0)),
    "operation.axial_load": (_no_patch, _set("operation.axial_load", 25.0)),
    'operation.preload = "position"': (_no_patch, _set("operation.preload", "position")),
    "operation.radial_load": (_no_patch, _radial_load),
    "operation.radial_load_direction": (
        _load_unless_it_is_refused,
        _set("operation.radial_load_direction", -1.0),
    ),
    "operation.moment_load": (_no_patch, _set("operation.moment_load", 0.01)),
    "operation.moment_load_direction": (
        _moment_for_equilibrium,
        _set("operation.moment_load_direction", 1.0),
    ),
    'waviness, waviness_spectrum, profile: part = "inner" / "outer"': (
        _no_patch,
        _add("waviness", {"part": "outer", "order": 7, "amplitude": 3e-9}),
    ),
    'waviness, waviness_spectrum, profile: part = "ball" / "roller"': (
        _no_patch,
        _add("waviness", {"part": "ball", "order": 2, "amplitude": 3e-9, "element": 3}),
    ),
    "slant": (_no_patch, lambda d: d.__setitem__("slant", {"amplitude": 5e-8})),
    "elements.diameter_errors": (
        _no_patch,
        _set("elements.diameter_errors", [1e-7] + [0.0] * 7),
    ),
    "elements.pitch_errors": (_no_patch, _set("elements.pitch_errors", [0.0, 0.01] + [0.0] * 6)),
    "elements.phase_frame": (_no_patch, _set("elements.phase_frame", "fixed")),
    "analysis.revolutions, samples": (_no_patch, _set("analysis.revolutions", 3)),
    "analysis.linear_variant": (_no_patch, _set("analysis.linear_variant", "force_balance")),
    "analysis.race_control": (_no_patch, _set("analysis.race_control", "inner")),
    "analysis.moment_arm": (
        _moment_load_for_equilibrium,
        _set("analysis.moment_arm", "pitch_radius"),
    ),
    "analysis.bearing_damping, bearing_damping_coefficient": (
        _no_patch,
        _set("analysis.bearing_damping", "kraemer"),
    ),
    "analysis.ring_tilt": (_radial_load_for_equilibrium, _set("analysis.ring_tilt", "held")),
    "dynamics": (
        _no_patch,
        lambda d: d.__setitem__("dynamics", {"mass": 0.03, "damping": 20.0}),
    ),
    "defect": (
        _no_patch,
        _add("defect", {"part": "outer", "width": 5e-4, "depth": 2e-5, "angle": -1.5}),
    ),
    "analysis.signal, sensor": (_no_patch, _acceleration),
    "analysis.bands": (_no_patch, _set("analysis.bands", "iso15242")),
    'analysis.limit_on = "axial_pp"': (_held_axially, _axial_limit),
    "analysis.limit": (_no_patch, _set("analysis.limit", "1 um")),
    "elements.grade, grade_sigma_divisor, grade_form_order": (
        _no_patch,
        _set("elements.grade", "G5"),
    ),
    "analysis.limit_bore": (_class_limit, _set("analysis.limit_bore", "40 mm")),
    # run on a spindle case: tests/unit/case/test_spindle_conventions.py
    "spindle, bearings": (_no_patch, lambda d: None),
}


def test_every_key_has_a_change() -> None:
    assert set(CHANGES) == {c.key for c in KEYS}
    assert all(len(c.statuses) == len(MODELS) for c in KEYS)


# the spindle column needs a spindle case: tests/unit/case/test_spindle_conventions.py
CELLS = [
    (c.key, m) for c in KEYS for m in MODELS if m != "spindle" and c.key != "spindle, bearings"
]


@pytest.mark.parametrize(("key", "model"), CELLS, ids=[f"{m}|{k}" for k, m in CELLS])
def test_matrix_cell_is_what_the_model_does(key: str, model: str) -> None:
    convention = next(c for c in KEYS if c.key == key)
    patch, change = CHANGES[key]
    base = _base(model)
    patch(base, model)
    assert_cell(convention, model, base, change)


def test_conventions_page_is_current() -> None:
    # Regenerate with: python -m runout.case.conventions > docs/conventions.md
    assert DOC.read_text(encoding="utf-8") == conventions_page()
