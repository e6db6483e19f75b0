"""Spindle case documents for the spindle tests (two bearings of Tada's size by default)."""

from __future__ import annotations

import copy
from typing import Any

from runout.case.model import Case, parse_case

TADA = {
    "elements": 8,
    "element_diameter": 1e-3,
    "pitch_diameter": 7e-3,
    "inner_conformity": 0.52,
    "outer_conformity": 0.53,
    "radial_clearance": 10e-6,
}


def spindle_document(
    waviness: list[dict[str, Any]] | None = None,
    *,
    arrangement: str = "DB",
    preload: dict[str, Any] | None = None,
    nose: float = -8e-3,
    positions: tuple[float, ...] = (0.0, 12e-3),
    bearings: list[dict[str, Any]] | None = None,
    operation: dict[str, Any] | None = None,
    samples: int = 512,
    revolutions: float = 8.0,
) -> dict[str, Any]:
    names = ["front", "rear", "third", "fourth", "b5", "b6", "b7", "b8", "b9"]
    rows = bearings or [dict(TADA) for _ in positions]
    return {
        "title": "spindle test",
        "spindle": {
            "arrangement": arrangement,
            "nose_position": nose,
            **(preload or {"preload": 20.0}),
        },
        "bearings": [
            {"name": names[i], "position": p, **copy.deepcopy(rows[i])}
            for i, p in enumerate(positions)
        ],
        "operation": {"speed": 90.0, **(operation or {})},
        "waviness": list(waviness or []),
        "analysis": {"model": "spindle", "samples": samples, "revolutions": revolutions},
    }


def spindle_case(*args: Any, **kwargs: Any) -> Case:
    return parse_case(spindle_document(*args, **kwargs), "<test>")
