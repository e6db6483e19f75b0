"""Damping of a rolling bearing for a rotordynamics model: stiffness-proportional estimates.

A rolling bearing's damping is not given by its geometry: it comes from the lubricant film,
the fits and the housing, and is measured, not computed. What rotordynamics practice uses when
no measurement exists is a damping proportional to the bearing's stiffness, c = β k, with β
from experience. :func:`proportional_damping` applies it to every coefficient of a stiffness
block; :data:`KRAEMER_COEFFICIENT_S` is the default β of ``[analysis] bearing_damping =
"kraemer"``.

Notes
-----
E. Krämer, *Dynamics of Rotors and Foundations*, Springer, 1993: for rolling-element bearings
the damping coefficient is about (0.25 ... 2.5) × 10⁻⁵ s times the stiffness (an engineering
estimate over a decade, not a measurement of any one bearing).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Krämer's range of β = c / k for rolling-element bearings [s] (Dynamics of Rotors and
#: Foundations, 1993).
KRAEMER_RANGE_S = (0.25e-5, 2.5e-5)
#: β of ``bearing_damping = "kraemer"`` [s]: the geometric mean of Krämer's range, rounded
#: (the range spans a decade, so the middle on a log scale is a factor 3.2 from either end).
KRAEMER_COEFFICIENT_S = 0.79e-5
#: Largest β a case may give [s]: 40 times Krämer's upper end. A β above it would make a
#: bearing critically damped at a few hundred Hz: not a rolling bearing.
MAX_DAMPING_COEFFICIENT_S = 1e-3
#: ``[analysis] bearing_damping`` values: no damping, Krämer's estimate, the user's β.
BEARING_DAMPING_MODELS = ("none", "kraemer", "proportional")


def damping_coefficient(model: str, coefficient_s: float | None) -> float:
    """β of a damping model [s]: c = β k.

    Parameters
    ----------
    model : {"none", "kraemer", "proportional"}
        ``[analysis] bearing_damping``.
    coefficient_s : float or None
        ``[analysis] bearing_damping_coefficient`` [s]; needed (and only read) for
        ``"proportional"``.

    Returns
    -------
    float
        0 for ``"none"``, :data:`KRAEMER_COEFFICIENT_S` for ``"kraemer"``, ``coefficient_s``
        for ``"proportional"`` [s].

    Raises
    ------
    ValueError
        An unknown model, or ``"proportional"`` without a finite β in [0,
        :data:`MAX_DAMPING_COEFFICIENT_S`].
    """
    if model == "none":
        return 0.0
    if model == "kraemer":
        return KRAEMER_COEFFICIENT_S
    if model == "proportional":
        if coefficient_s is None or not (
            math.isfinite(coefficient_s) and 0.0 <= coefficient_s <= MAX_DAMPING_COEFFICIENT_S
        ):
            raise ValueError(
                f"proportional damping needs a coefficient from 0 to "
                f"{MAX_DAMPING_COEFFICIENT_S:g} s, got {coefficient_s!r}"
            )
        return float(coefficient_s)
    raise ValueError(f"unknown bearing damping model {model!r}: one of {BEARING_DAMPING_MODELS}")


def proportional_damping(stiffness: ArrayLike, coefficient_s: float) -> NDArray[np.float64]:
    r"""Stiffness-proportional damping of a bearing: every coefficient c_ij = β k_ij [N s/m].

    .. math:: c_{ij} = \beta \, k_{ij}

    The cross terms are damped in the same proportion as the direct ones, so the damping
    matrix has the stiffness matrix's symmetry and sign pattern.

    Parameters
    ----------
    stiffness : array_like
        Stiffness coefficients [N/m] (any shape; a 2×2 radial block, the axial K_aa, a table
        over speed).
    coefficient_s : float
        β [s], finite and >= 0.

    Returns
    -------
    ndarray
        The damping coefficients [N s/m], the shape of ``stiffness``.

    Notes
    -----
    E. Krämer, *Dynamics of Rotors and Foundations*, Springer, 1993: rolling-element bearing
    damping c ≈ (0.25 ... 2.5) × 10⁻⁵ s · k. An estimate for a rotor model when no measured
    damping exists; it does not come from the bearing's geometry.
    """
    if not (math.isfinite(coefficient_s) and coefficient_s >= 0.0):
        raise ValueError(f"the damping coefficient must be finite and >= 0, got {coefficient_s}")
    return coefficient_s * np.asarray(stiffness, dtype=np.float64)
