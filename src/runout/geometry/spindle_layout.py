"""Typed inputs of the spindle model: the bearings on the shaft, their positions, the preload.

A spindle case (``[spindle]`` + ``[[bearings]]``) is read into this layout by
:func:`runout.case.model.build_layout`, one single-bearing case per bearing.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from runout.geometry.bearing import Bearing
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
