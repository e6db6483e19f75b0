"""Shared test cases (importable from any test: pytest puts tests/ on the path).

Physics inputs come from :mod:`runout.examples`; the case-file forms here (``KIM_TOML`` and
the tables) are for the tests whose subject is the case file: the command line, the
conventions and the studies.
"""

from __future__ import annotations

import dataclasses
from typing import Any

from runout import examples
from runout.api import Imperfections
from runout.case.model import Case

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


def kim_case(
    *,
    study: dict[str, Any] | None = None,
    diameter_errors: Any = None,
    radial_load: float = 0.0,
    revolutions: float = 4,
    samples: int = 256,
) -> Case:
    """Kim's spindle bearing at its operating point, quasi_static_2d, short record.

    ``diameter_errors`` [m] (Z = 10 values), default perfect balls; ``study`` a [study] table.
    """
    example = examples.kim(radial_load=radial_load, oversize=None)
    imperfections = None
    if diameter_errors is not None:
        imperfections = Imperfections(elements=10).diameter_errors(diameter_errors)
    return Case.from_inputs(
        example.bearing,
        example.operation,
        imperfections,
        analysis={"model": "quasi_static_2d", "revolutions": revolutions, "samples": samples},
        study=study,
    )


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
    """The seed 003 Table 2 rotor (SI inputs; ``load_direction`` [rad] from +x, default -y).

    ``waviness`` entries are the keyword arguments of
    :meth:`runout.api.Imperfections.waviness` (``part``, ``order``, ``amplitude``, ...).
    """
    rotor = examples.purohit(
        elements=elements,
        radial_clearance=clearance,
        speed=speed,
        radial_load=radial,
        axial_load=axial,
        radial_load_direction=load_direction,
    )
    waves = Imperfections(elements=elements)
    for entry in waviness or []:
        waves = waves.waviness(**entry)
    # the rotor's kind (seed 003: position); an axial_dof of these helpers' callers names the
    # kind, as it did before the preload key (true: spring, false: position)
    dynamics = dict(dynamics or {})
    operation = rotor.operation
    if "axial_dof" in dynamics:
        kind = "spring" if dynamics.pop("axial_dof") else "position"
        operation = dataclasses.replace(operation, preload=kind)
    return Case.from_inputs(
        rotor.bearing,
        operation,
        waves,
        title="test rotor",
        analysis={"model": "dynamic", "revolutions": revolutions, "samples": samples},
        dynamics={"mass": 0.6, "damping": 200.0, **dynamics},
    )


WAVY = [
    {"part": "inner", "order": 7, "amplitude": 20e-9, "phase": 0.3},
    {"part": "outer", "order": 9, "amplitude": 15e-9},
    {"part": "ball", "order": 2, "amplitude": 10e-9, "element": 2},
]


def typed_case(
    bearing: Any,
    operation: Any,
    waviness: list[dict[str, Any]] | None = None,
    **analysis: Any,
) -> Case:
    """A case from typed inputs: ``waviness`` entries are the keyword arguments of
    :meth:`runout.api.Imperfections.waviness` (``part``, ``order``, ``amplitude`` or
    ``peak_to_peak``, ``phase``, ``element``), ``analysis`` the ``[analysis]`` keys."""
    imperfections = None
    if waviness:
        imperfections = Imperfections(elements=bearing.elements)
        for entry in waviness:
            imperfections = imperfections.waviness(**entry)
    return Case.from_inputs(bearing, operation, imperfections, analysis=analysis)


def run_case_text(path: Any, text: str, *args: str) -> Any:
    """Write ``text`` as the case file ``path`` and run ``runout run path *args`` in-process.

    Returns the click ``Result`` (``exit_code``, ``stdout``, ``stderr``).
    """
    from typer.testing import CliRunner

    from runout.cli.commands import app

    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(app, ["run", str(path), *args])


def run_json(result: Any) -> dict[str, Any]:
    """The JSON a successful ``runout run --json`` printed (asserting it succeeded)."""
    import json

    assert result.exit_code == 0, result.stderr
    out: dict[str, Any] = json.loads(result.stdout)
    return out


#: The MASTA reference bearing of ISO/TS 16281's open code (Z = 7, D_w 11.5 mm) with every input
#: of the modified rating life, as a case file: :data:`MODIFIED_LIFE_KEYS` fill it.
MODIFIED_LIFE_CASE = """\
title = "modified life"
[bearing]
type = "ball"
elements = 7
element_diameter = "11.5 mm"
pitch_diameter = "43.5 mm"
inner_conformity = 0.52
outer_conformity = 0.53
radial_clearance = "10 um"
dynamic_load_rating = "23.4 kN"
{limit}
[material]
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[operation]
rotating_ring = "inner"
speed = "{speed}"
axial_load = "500 N"
radial_load = "1500 N"
{lubrication}
[analysis]
model = "{model}"
{reliability}
"""

#: The keys of :data:`MODIFIED_LIFE_CASE`: C_u, [lubrication], the equilibrium model, 99 %.
MODIFIED_LIFE_KEYS = {
    "limit": 'fatigue_load_limit = "0.6 kN"',
    "speed": "3000 rpm",
    "lubrication": "[lubrication]\nviscosity_ratio = 1.5\ncontamination_factor = 0.5",
    "model": "equilibrium",
    "reliability": "reliability = 99",
}
