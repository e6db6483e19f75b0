"""Typed inputs of the spindle model: the bearings on the shaft, their positions, the preload.

A spindle case (``[spindle]`` + ``[[bearings]]``) is read as one single-bearing case per
bearing (its ``[[bearings]]`` entry as ``[bearing]``, the imperfection tables that name it,
``[elements.<name>]``, the shared ``[material]`` and ``[operation]``), each validated exactly as
a case file with one bearing; errors name the spindle case's own keys.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from runout.base.errors import CaseError
from runout.geometry.bearing import Bearing
from runout.geometry.imperfections import Imperfections

if TYPE_CHECKING:
    from runout.case.model import Case, CaseSpec, ProfileData

__all__ = ["SpindleBearing", "SpindleLayout", "build_layout"]

Arrangement = Literal["DB", "DF", "DT"]
_TABLES = ("waviness", "waviness_spectrum", "profile")


@dataclass(frozen=True)
class SpindleBearing:
    """One bearing of a spindle.

    Attributes
    ----------
    name : str
    position : float
        Axial coordinate of its ball-set plane along the shaft [m].
    bearing : BallBearing or RollerBearing
        (the spindle model refuses roller bearings: runout.case.conventions)
    imperfections : Imperfections
        Its waviness, size and pitch errors.
    """

    name: str
    position: float
    bearing: Bearing
    imperfections: Imperfections


@dataclass(frozen=True)
class SpindleLayout:
    """The shaft's bearings and preload (the ``[spindle]`` table).

    Attributes
    ----------
    bearings : tuple of SpindleBearing
        Two or more, in the case file's order.
    arrangement : {"DB", "DF", "DT"}
        Back-to-back, face-to-face or tandem.
    preload : float or None
        Constant-pressure (spring) preload [N].
    preload_displacement : float or None
        Position preload: axial overlap of the two groups [m].
    nose_position : float
        Axial coordinate where the runout is reported [m].
    """

    bearings: tuple[SpindleBearing, ...]
    arrangement: Arrangement
    preload: float | None
    preload_displacement: float | None
    nose_position: float


def _remap(key: str, name: str, index: int, entries: dict[str, list[int]]) -> str:
    """A key of a bearing's own case as the spindle case's key."""
    if key.startswith("bearing."):
        return f"bearings[{index}]." + key[len("bearing.") :]
    if key.startswith("elements"):
        return f"elements.{name}" + key[len("elements") :]
    match = re.match(r"(waviness_spectrum|waviness|profile)\[(\d+)\](.*)", key)
    if match:
        table, k, rest = match.group(1), int(match.group(2)), match.group(3)
        own = entries[table]
        if 1 <= k <= len(own):
            return f"{table}[{own[k - 1]}]{rest}"
    return key


def bearing_document(document: dict[str, Any], name: str) -> tuple[dict[str, Any], dict[str, Any]]:
    """A bearing's single-bearing case document, and the indices of its entries per table."""
    entry = next(b for b in document["bearings"] if b["name"] == name)
    own: dict[str, Any] = {
        "title": document.get("title", ""),
        "bearing": {k: v for k, v in entry.items() if k not in ("name", "position")},
    }
    for table in ("material", "operation"):
        if table in document:
            own[table] = document[table]
    entries: dict[str, list[int]] = {}
    for table in _TABLES:
        rows = document.get(table, [])
        entries[table] = [i for i, row in enumerate(rows, start=1) if row.get("bearing") == name]
        picked = [{k: v for k, v in row.items() if k != "bearing"} for row in rows]
        chosen = [picked[i - 1] for i in entries[table]]
        if chosen:
            own[table] = chosen
    elements = document.get("elements") or {}
    if name in elements:
        own["elements"] = elements[name]
    analysis = {
        k: v
        for k, v in document.get("analysis", {}).items()
        if k in ("revolutions", "samples", "max_memory", "max_time")
    }
    own["analysis"] = {**analysis, "model": "quasi_static_3d"}
    return own, entries


def build_layout(
    spec: CaseSpec,
    path: str,
    base_dir: Path | None,
    profile_data: ProfileData | None,
) -> tuple[SpindleLayout, list[Case]]:
    """The spindle of a validated spindle case, and each bearing's own case.

    Raises
    ------
    CaseError
        Naming the spindle case's key (``bearings[2].pitch_diameter``, ``waviness[3].order``).
    """
    from runout.case.model import parse_case

    document = spec.model_dump(mode="python", exclude_unset=True, exclude_none=True)
    assert spec.spindle is not None  # checked by the schema
    bearings: list[SpindleBearing] = []
    cases: list[Case] = []
    for index, b in enumerate(spec.bearings, start=1):
        own, entries = bearing_document(document, b.name)
        try:
            case = parse_case(own, path, base_dir, profile_data=profile_data)
        except CaseError as exc:
            raise CaseError(path, _remap(exc.key, b.name, index, entries), exc.message) from None
        bearings.append(SpindleBearing(b.name, b.position, case.bearing, case.imperfections))
        cases.append(case)
    layout = SpindleLayout(
        bearings=tuple(bearings),
        arrangement=spec.spindle.arrangement,
        preload=spec.spindle.preload,
        preload_displacement=spec.spindle.preload_displacement,
        nose_position=spec.spindle.nose_position,
    )
    return layout, cases
