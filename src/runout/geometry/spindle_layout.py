"""Typed inputs of the spindle model: the bearings on the shaft, their positions, the preload.

A spindle case (``[spindle]`` + ``[[bearings]]``) is read into this layout by
:func:`runout.case.model.build_layout`, one single-bearing case per bearing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from runout.base.errors import GeometryError
from runout.geometry.bearing import Bearing, _as_real
from runout.geometry.imperfections import BearingImperfections

__all__ = ["Arrangement", "SpindleBearing", "SpindleLayout"]

Arrangement = Literal["DB", "DF", "DT"]


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
    imperfections : BearingImperfections
        Its waviness, size and pitch errors.
    """

    name: str
    position: float
    bearing: Bearing
    imperfections: BearingImperfections


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

    def __post_init__(self) -> None:
        check_spacing(self.bearings)


def check_spacing(bearings: tuple[SpindleBearing, ...] | list[SpindleBearing]) -> None:
    """Every two bearings at least half their two ball diameters apart along the shaft.

    Parameters
    ----------
    bearings : sequence of SpindleBearing
        The bearings with their positions [m] (``bearings[i].position``).

    Raises
    ------
    GeometryError
        A position that is not a finite real number, or two bearings closer than
        ``(D_i + D_j) / 2``, naming ``bearings[j].position`` (1-based, the later one).

    Notes
    -----
    A bearing's rings are at least as wide as its balls, so the ball-set planes of two bearings
    side by side lie at least ``(D_i + D_j) / 2`` apart (D the ball diameters). The rigid
    shaft's tilt stiffness grows with the square of the span: a span of a nanometre, once
    accepted, gave a tilt stiffness of nothing while a span of 0 was refused.
    """
    positions: list[float] = []
    for index, b in enumerate(bearings, start=1):
        value = _as_real(f"bearings[{index}].position", b.position)
        if not (isinstance(value, float) and math.isfinite(value)):
            raise GeometryError(
                f"bearings[{index}].position", f"must be a finite length [m], got {value!r}"
            )
        positions.append(value)
    for j in range(1, len(bearings)):
        for i in range(j):
            least = 0.5 * (
                bearings[i].bearing.element_diameter + bearings[j].bearing.element_diameter
            )
            gap = abs(positions[j] - positions[i])
            if gap < least:
                raise GeometryError(
                    f"bearings[{j + 1}].position",
                    f"{gap * 1e3:.6g} mm from bearings[{i + 1}] ({bearings[i].name}); the "
                    "ball-set planes of two bearings lie at least half the sum of their ball "
                    f"diameters apart, here {least * 1e3:.6g} mm (a bearing's rings are at "
                    "least as wide as its balls)",
                )
