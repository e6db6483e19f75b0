"""Shared test cases (importable from any test: pytest puts tests/ on the path)."""

from __future__ import annotations

from typing import Any

from runout.case import Case, parse_case

#: Kim's spindle bearing (seed 001 Table 1) at 7200 rpm under its fitted 60.68 N, as TOML.
KIM_TOML = """\
[bearing]
type = "ball"
elements = 10
element_diameter = "1.5875 mm"
pitch_diameter = "9.1 mm"
inner_conformity = 0.529
outer_conformity = 0.535
radial_clearance = "5 um"
[operation]
speed = "7200 rpm"
axial_load = "60.68 N"
"""


#: The same bearing and operating point as tables (case-file keys and strings with units).
KIM_BEARING: dict[str, Any] = {
    "type": "ball",
    "elements": 10,
    "element_diameter": "1.5875 mm",
    "pitch_diameter": "9.1 mm",
    "inner_conformity": 0.529,
    "outer_conformity": 0.535,
    "radial_clearance": "5 um",
}
KIM_OPERATION: dict[str, Any] = {
    "rotating_ring": "inner",
    "speed": "7200 rpm",
    "axial_load": "60.68 N",
}


#: Tada's standard HDD bearing (seed 000 Table 1) with 10 um clearance, as a [bearing] table.
TADA_BEARING: dict[str, Any] = {
    "type": "ball",
    "elements": 8,
    "element_diameter": 1e-3,
    "pitch_diameter": 7e-3,
    "inner_conformity": 0.52,
    "outer_conformity": 0.53,
    "radial_clearance": 10e-6,
}


# The rotor of seed 003 Table 2 (8 balls by default) for the dynamic-model tests.
def dynamic_case(
    *,
    elements: int = 8,
    clearance: float = 0.2e-6,
    axial: float = 0.0,
    radial: float = 6.0,
    speed: float = 5000.0 / 60.0,
    waviness: list[dict[str, Any]] | None = None,
    dynamics: dict[str, Any] | None = None,
    revolutions: float = 4,
    samples: int = 1024,
    load_direction: float | None = None,
) -> Case:
    """The seed 003 Table 2 rotor (SI inputs; ``load_direction`` [rad] from +x, default -y)."""
    bearing: dict[str, Any] = {
        "type": "ball",
        "elements": elements,
        "element_diameter": 7.96e-3,
        "pitch_diameter": 54e-3,
        "inner_groove_radius": 4.08e-3,
        "outer_groove_radius": 4.61e-3,
        "radial_clearance": clearance,
    }
    return parse_case(
        {
            "title": "test rotor",
            "bearing": bearing,
            "operation": {
                "speed": speed,
                "radial_load": radial,
                "axial_load": axial,
                **({} if load_direction is None else {"radial_load_direction": load_direction}),
            },
            "waviness": waviness or [],
            "dynamics": {"mass": 0.6, "damping": 200.0, **(dynamics or {})},
            "analysis": {"model": "dynamic", "revolutions": revolutions, "samples": samples},
        }
    )


WAVY = [
    {"part": "inner", "order": 7, "amplitude": 20e-9, "phase": 0.3},
    {"part": "outer", "order": 9, "amplitude": 15e-9},
    {"part": "ball", "order": 2, "amplitude": 10e-9, "element": 2},
]
