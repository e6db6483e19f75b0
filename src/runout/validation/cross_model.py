"""Cross-check of two models: ``linear`` (force-balance variant) against ``quasi_static_3d``.

Tada's force balance (seed 000: S. Tada, "Three-dimensional analysis of non-repeatable runout
(NRRO) in ball bearings", Koyo Engineering Journal, 2002) linearised about the preloaded state
is the linear model's ``force_balance`` variant, so at 1 nm the two must agree to the
linearisation error.
"""

from __future__ import annotations

import functools
import math
from typing import TYPE_CHECKING, Any

from runout.validation.cases import load, uses
from runout.validation.core import Check, bind

if TYPE_CHECKING:
    from runout.case.model import Case

__all__ = ["INTRO", "checks", "cross_case", "cross_gap", "cross_lines"]


def cross_case(ring: str, model: str) -> Case:
    """Tada's standard bearing with 1 nm of inner, outer and ball waviness, for ``model``.

    The bearing and operation of ``examples/seed000_tada_table2.toml`` with an inner 9-lobe,
    an outer 7-lobe and a ball-3 2-lobe waviness of 1 nm; 40 revolutions of 8192 samples.

    Parameters
    ----------
    ring : {"inner", "outer"}
        The rotating ring.
    model : {"linear", "quasi_static_3d"}
        The model; ``linear`` runs its ``force_balance`` variant.

    Returns
    -------
    Case
        The validated case.
    """
    from runout.case.model import parse_case

    wav = [
        {"part": "inner", "order": 9, "amplitude": 1e-9, "phase": math.radians(20)},
        {"part": "outer", "order": 7, "amplitude": 1e-9, "phase": math.radians(50)},
        {"part": "ball", "order": 2, "amplitude": 1e-9, "element": 3},
    ]
    case = load("seed000_tada_table2.toml")
    data = case.spec.model_dump(exclude_none=True)
    data["operation"]["rotating_ring"] = ring
    data["waviness"] = wav
    data["analysis"] = {"model": model, "revolutions": 40, "samples": 8192}
    if model == "linear":
        data["analysis"]["linear_variant"] = "force_balance"
    return parse_case(data, "cross-check")


@functools.cache
def cross_lines(ring: str, model: str) -> dict[tuple[str, float], float]:
    """The radial lines of :func:`cross_case` run by ``model``.

    Parameters
    ----------
    ring : {"inner", "outer"}
        The rotating ring.
    model : {"linear", "quasi_static_3d"}
        The model.

    Returns
    -------
    dict
        (direction "x" or "y", frequency [Hz] rounded to 1 mHz) → p-p [m], lines above
        0.01 nm only.
    """
    from runout.models import linear, quasi_static_3d

    module: Any = {"linear": linear, "quasi_static_3d": quasi_static_3d}[model]
    result = module.run(cross_case(ring, model))
    return {
        (c.direction, round(c.frequency_hz, 3)): c.pp_m
        for c in result.components
        if c.direction in ("x", "y") and c.pp_m > 1e-11
    }


def cross_gap(ring: str) -> float:
    """Largest relative gap of the radial lines of the two models, ``ring`` rotating.

    Parameters
    ----------
    ring : {"inner", "outer"}
        The rotating ring.

    Returns
    -------
    float
        max |quasi_static_3d / linear - 1| over the linear model's lines [-]; infinite when a
        line is missing from the nonlinear model or the linear model has fewer than six.
    """
    lin, qs = cross_lines(ring, "linear"), cross_lines(ring, "quasi_static_3d")
    if len(lin) < 6:
        return math.inf
    return max(abs(qs[k] / v - 1.0) if k in qs else math.inf for k, v in lin.items())


def checks() -> list[Check]:
    """The cross-model table.

    Returns
    -------
    list of Check
        The largest relative gap of the radial lines (:func:`cross_gap`), inner and outer ring
        rotating, against the linearisation error.

    Notes
    -----
    Tada's force balance (seed 000) linearised about the preloaded state is the linear
    model's ``force_balance`` variant: a check against theory, not against a printed number.
    """
    name = uses("seed000_tada_table2.toml", "seed 000 Table 1 bearing, Table 2 and conclusion 1")
    return [
        Check(
            "linear (force balance) vs quasi_static_3d, 1 nm",
            f"largest relative gap of the radial lines, {ring} ring rotating",
            None,
            bind(lambda ring: cross_gap(ring), ring),
            "max",
            2e-3,
            expected="the linearisation error",
            case=name,
        )
        for ring in ("inner", "outer")
    ]


INTRO = """\
Tada's standard bearing (`examples/seed000_tada_table2.toml`: Z = 8, D = 1 mm, d_m = 7 mm,
P_d = 10 µm, 20 N) with 1 nm of inner 9-lobe, outer 7-lobe and ball-3 2-lobe waviness; test
`tests/reference/test_cross_linear_vs_quasi_static.py`. Tada's force balance linearised about
the preloaded state is the linear model's `force_balance` variant, so the two models must agree
to the linearisation error."""
