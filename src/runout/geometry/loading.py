r"""Static ball bearing under a centred pure axial load: contact angle, ball load, deflections.

Every ball carries the same load Q when the axial load :math:`F_a` is centred and there is no
radial load, speed effects (centrifugal force, gyroscopic moment) are neglected and the rings
are rigid apart from the Hertz contacts. With the distance between the groove curvature
centres :math:`A = BD` (:math:`B = f_i + f_o - 1`) and the free contact angle
:math:`\alpha^0 = \arccos(1 - P_d/2A)`, the radial distance between those centres stays
:math:`A\cos\alpha^0` while their axial distance grows; the loaded contact angle α therefore
sets the total elastic approach

.. math:: \delta_n = A\Big(\frac{\cos\alpha^0}{\cos\alpha} - 1\Big),

and the force balance :math:`F_a = Z Q \sin\alpha` with :math:`Q = K_n\delta_n^{3/2}` gives
Harris's load-angle relation for a thrust-loaded ball bearing (*Rolling Bearing Analysis*;
seed 003 eq. 2.21-2.22 is the same relation for the preload :math:`P_l`, see Notes)

.. math::

    F_a = Z\,K_n(\alpha)\,(BD)^{3/2}\Big(\frac{\cos\alpha^0}{\cos\alpha} - 1\Big)^{3/2}\sin\alpha.

The series stiffness :math:`K_n` of the ball-inner and ball-outer contacts (seed 000 eq. 4,
seed 001 eq. 15, seed 003 eq. 2.14) depends on α through the curvature sums
(γ = D cos α / d_m); it is evaluated at the loaded α here. Harris's textbook shortcut freezes
it at :math:`\alpha^0`; that variant is available with ``stiffness="free"``.

Notes
-----
Seed 003 eq. 2.21 prints :math:`P_l = mK[Bd_b(1/\cos\alpha_p - 1)]^{3/2}\sin\alpha_p`: it
is the zero-clearance case (:math:`\cos\alpha^0 = 1`) of the relation above, and its leading
factor m can only be the number of balls (its nomenclature uses m for the rotor mass, which
would make the equation dimensionally wrong).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Literal

from runout.base.errors import ConvergenceError, GeometryError
from runout.geometry.bearing import BallBearing, Bearing, Operation, RollerBearing
from runout.geometry.contact import BallContacts, ball_race_contacts

__all__ = [
    "AxialLoading",
    "axial_load_for_contact_angle",
    "axial_loading",
    "axial_loading_fixed_angle",
    "operating_contact_angle",
]

StiffnessMode = Literal["at_angle", "free"]

# Upper end of the bracket for α: just below 90 deg, where the load tends to infinity.
_ALPHA_MAX = 0.5 * math.pi * (1.0 - 1e-9)


@dataclass(frozen=True)
class AxialLoading:
    """Result of a static pure-axial-load analysis of a ball bearing.

    Attributes
    ----------
    axial_load : float
        F_a [N].
    free_contact_angle : float
        α⁰ [rad], the angle at which the balls first touch both grooves.
    contact_angle : float
        Loaded contact angle α [rad].
    ball_load : float
        Normal load per ball Q = F_a / (Z sin α) [N].
    inner_approach, outer_approach : float
        Hertz approaches δ_i, δ_o of the ball-inner and ball-outer contacts [m].
    total_approach : float
        δ_n = δ_i + δ_o [m] (equal to A (cos α⁰ / cos α - 1)).
    axial_displacement : float
        Relative axial displacement of the rings from first contact,
        (A + δ_n) sin α - A sin α⁰ [m].
    contacts : BallContacts
        The two Hertz contacts (at α, or at α⁰ for ``stiffness="free"``) and K_n.
    """

    axial_load: float
    free_contact_angle: float
    contact_angle: float
    ball_load: float
    inner_approach: float
    outer_approach: float
    total_approach: float
    axial_displacement: float
    contacts: BallContacts

    @property
    def combined_stiffness(self) -> float:
        """K_n used in the solution [N/m^1.5]."""
        return self.contacts.combined_stiffness


def _check_axial_load(axial_load: float) -> float:
    value = float(axial_load)
    if not (math.isfinite(value) and value >= 0.0):
        raise GeometryError("axial_load", f"must be a finite force >= 0 N, got {axial_load!r}")
    return value


def _free_angle(bearing: BallBearing, free_contact_angle: float | None) -> float:
    alpha0 = bearing.free_contact_angle if free_contact_angle is None else float(free_contact_angle)
    if not (math.isfinite(alpha0) and 0.0 <= alpha0 < 0.5 * math.pi):
        raise GeometryError("free_contact_angle", f"must lie in [0, 90) deg, got {alpha0!r} rad")
    return alpha0


def axial_load_for_contact_angle(
    bearing: BallBearing,
    contact_angle: float,
    *,
    stiffness: StiffnessMode = "at_angle",
    free_contact_angle: float | None = None,
) -> float:
    r"""Axial load F_a [N] that brings the contact angle to ``contact_angle`` (explicit).

    Harris's load-angle relation (see the module docstring; seed 003 eq. 2.21):

    .. math::

        F_a = Z\,K_n\,(BD)^{3/2}\Big(\frac{\cos\alpha^0}{\cos\alpha} - 1\Big)^{3/2}\sin\alpha

    Parameters
    ----------
    bearing : BallBearing
        Geometry and material.
    contact_angle : float
        Loaded contact angle α [rad], α⁰ <= α < π/2.
    stiffness : {"at_angle", "free"}
        Evaluate K_n at α (default) or freeze it at α⁰ (Harris's shortcut).
    free_contact_angle : float or None
        α⁰ [rad]; default ``bearing.free_contact_angle`` (from the radial clearance).

    Returns
    -------
    float
        F_a [N].

    Notes
    -----
    Harris, *Rolling Bearing Analysis* (thrust-loaded ball bearing); seed 003 (Purohit &
    Purohit 2006) eq. 2.21 is its zero-clearance case (see the module Notes).
    """
    alpha0 = _free_angle(bearing, free_contact_angle)
    alpha = float(contact_angle)
    if not (math.isfinite(alpha) and alpha0 <= alpha < 0.5 * math.pi):
        raise GeometryError(
            "contact_angle",
            f"must lie in [{math.degrees(alpha0):.6g}, 90) deg (free contact angle to 90), "
            f"got {math.degrees(alpha):.6g} deg",
        )
    kn = _kn(bearing, alpha if stiffness == "at_angle" else alpha0, stiffness)
    return _load_at(bearing, alpha, alpha0, kn)


def _kn(bearing: BallBearing, alpha: float, stiffness: str) -> float:
    if stiffness not in ("at_angle", "free"):
        raise GeometryError("stiffness", f'must be "at_angle" or "free", got {stiffness!r}')
    return ball_race_contacts(bearing, alpha).combined_stiffness


def _load_at(bearing: BallBearing, alpha: float, alpha0: float, kn: float) -> float:
    a = bearing.curvature_distance
    stretch = max(math.cos(alpha0) / math.cos(alpha) - 1.0, 0.0)
    return bearing.elements * kn * (a * stretch) ** 1.5 * math.sin(alpha)


def axial_loading(
    bearing: BallBearing,
    axial_load: float,
    *,
    stiffness: StiffnessMode = "at_angle",
    free_contact_angle: float | None = None,
    xtol: float = 1e-14,
) -> AxialLoading:
    r"""Contact angle, ball load and deflections of a ball bearing under a pure axial load.

    Solves Harris's load-angle relation (module docstring; seed 003 eq. 2.21-2.22) for the
    loaded contact angle α with a bracketed root finder (Brent) on
    :math:`[\alpha^0, 90^\circ)`, then

    .. math::

        Q = \frac{F_a}{Z\sin\alpha},\quad \delta_i = (Q/K_i)^{2/3},\quad
        \delta_o = (Q/K_o)^{2/3},\quad
        \delta_a = (BD + \delta_n)\sin\alpha - BD\sin\alpha^0 .

    Parameters
    ----------
    bearing : BallBearing
        Geometry (Z, D, d_m, f_i, f_o, P_d) and material. A fixed ``bearing.contact_angle``
        is ignored here: the angle is what this function computes (see
        :func:`axial_loading_fixed_angle` for the fixed-angle model of seed 000).
    axial_load : float
        Centred axial load F_a [N] (>= 0).
    stiffness : {"at_angle", "free"}
        ``"at_angle"`` (default) evaluates the contact stiffnesses at the loaded angle α, so
        the curvature sums follow γ = D cos α / d_m; ``"free"`` freezes them at α⁰ (Harris's
        simplification).
    free_contact_angle : float or None
        α⁰ [rad]; default ``bearing.free_contact_angle`` (0 for zero clearance).
    xtol : float
        Absolute tolerance on α [rad].

    Returns
    -------
    AxialLoading

    Raises
    ------
    GeometryError
        For a negative or non-finite load, or an invalid α⁰.
    ConvergenceError
        If the root finder fails.

    Notes
    -----
    Speed effects are neglected (no centrifugal force or gyroscopic moment, unlike seed 001's
    Jones-Harris analysis), so inner and outer contact angles are equal. Zero load returns
    α = α⁰ with zero deflections.
    """
    fa = _check_axial_load(axial_load)
    alpha0 = _free_angle(bearing, free_contact_angle)
    if stiffness not in ("at_angle", "free"):
        raise GeometryError("stiffness", f'must be "at_angle" or "free", got {stiffness!r}')
    return _axial_loading(bearing, fa, alpha0, stiffness, xtol)


# a run asks for the same operating point several times (input checks, model set-up, summary);
# the bearing is a frozen dataclass and the result immutable, so the solution is kept
@functools.lru_cache(maxsize=64)
def _axial_loading(
    bearing: BallBearing, fa: float, alpha0: float, stiffness: StiffnessMode, xtol: float
) -> AxialLoading:
    if fa == 0.0:
        contacts = ball_race_contacts(bearing, alpha0)
        return AxialLoading(0.0, alpha0, alpha0, 0.0, 0.0, 0.0, 0.0, 0.0, contacts)

    free_contacts = ball_race_contacts(bearing, alpha0) if stiffness == "free" else None

    def residual(alpha: float) -> float:
        if free_contacts is not None:
            kn = free_contacts.combined_stiffness
        else:
            kn = ball_race_contacts(bearing, alpha).combined_stiffness
        return _load_at(bearing, alpha, alpha0, kn) / fa - 1.0

    if not residual(_ALPHA_MAX) >= 0.0:  # no angle short of 90 degrees carries it
        kn = (free_contacts or ball_race_contacts(bearing, _ALPHA_MAX)).combined_stiffness
        raise GeometryError(
            "operation.axial_load",
            f"{fa:.4g} N is more than the {_load_at(bearing, _ALPHA_MAX, alpha0, kn):.4g} N "
            "the balls carry at a contact angle of 90 deg (the Hertz contacts would be "
            "crushed long before)",
        )
    try:
        from runout.base._roots import brentq  # SciPy's Brent steps without scipy.optimize's import

        alpha, info = brentq(
            residual, alpha0, _ALPHA_MAX, xtol=xtol, rtol=8.9e-16, full_output=True
        )
    except ValueError as exc:  # no sign change: excluded above, but be explicit
        raise ConvergenceError(f"axial load-angle relation has no root: {exc}") from exc
    if not info.converged:
        raise ConvergenceError(f"axial load-angle relation did not converge: {info.flag}")
    contacts = free_contacts if free_contacts is not None else ball_race_contacts(bearing, alpha)
    return _result(bearing, fa, alpha0, float(alpha), contacts)


def _result(
    bearing: BallBearing, fa: float, alpha0: float, alpha: float, contacts: BallContacts
) -> AxialLoading:
    q = fa / (bearing.elements * math.sin(alpha))
    d_i = (q / contacts.inner.stiffness) ** (2.0 / 3.0)
    d_o = (q / contacts.outer.stiffness) ** (2.0 / 3.0)
    a = bearing.curvature_distance
    d_n = d_i + d_o
    d_a = (a + d_n) * math.sin(alpha) - a * math.sin(alpha0)
    return AxialLoading(fa, alpha0, alpha, q, d_i, d_o, d_n, d_a, contacts)


def axial_loading_fixed_angle(
    bearing: BallBearing, axial_load: float, contact_angle: float | None = None
) -> AxialLoading:
    r"""Ball load and deflections under a pure axial load at a *fixed* contact angle.

    Seed 000 (Tada) fixes the contact angle during an analysis; with x = y = 0 its force
    balance (eq. 5, z row) reduces to :math:`F_a = Z K_n \delta_n^{3/2}\sin\alpha`, i.e.
    :math:`Q = F_a/(Z\sin\alpha)` and :math:`\delta_n = (Q/K_n)^{2/3}`. The axial
    displacement is the one that produces :math:`\delta_n` along the contact normal,
    :math:`\delta_n/\sin\alpha`.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and material.
    axial_load : float
        F_a [N] (>= 0).
    contact_angle : float or None
        α [rad] (> 0 when F_a > 0); default ``bearing.unloaded_contact_angle``.

    Returns
    -------
    AxialLoading
        ``free_contact_angle`` and ``contact_angle`` both hold the fixed α.

    Notes
    -----
    Seed 000 (Tada 2002) eq. 5, z row, with x = y = 0; K_n is seed 000 eq. 4.
    """
    fa = _check_axial_load(axial_load)
    alpha = bearing.unloaded_contact_angle if contact_angle is None else float(contact_angle)
    contacts = ball_race_contacts(bearing, alpha)
    if fa == 0.0:
        return AxialLoading(0.0, alpha, alpha, 0.0, 0.0, 0.0, 0.0, 0.0, contacts)
    if alpha <= 0.0:
        raise GeometryError(
            "contact_angle", "a zero contact angle cannot carry an axial load when it is fixed"
        )
    q = fa / (bearing.elements * math.sin(alpha))
    d_i = (q / contacts.inner.stiffness) ** (2.0 / 3.0)
    d_o = (q / contacts.outer.stiffness) ** (2.0 / 3.0)
    d_n = d_i + d_o
    return AxialLoading(fa, alpha, alpha, q, d_i, d_o, d_n, d_n / math.sin(alpha), contacts)


def operating_contact_angle(
    bearing: Bearing, operation: Operation
) -> tuple[float, AxialLoading | None]:
    """Contact angle the bearing runs at, and the axial-load solution behind it.

    A fixed ``contact_angle`` in the bearing description wins; otherwise a ball bearing under an
    axial load runs at the loaded contact angle (Harris's load-angle relation,
    :func:`runout.geometry.loading.axial_loading`), and without axial load at the free contact
    angle. Roller bearings run at 0.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing.
    operation : Operation
        Its operating condition (``axial_load`` [N]).

    Returns
    -------
    contact_angle : float
        Operating contact angle α [rad].
    loading : AxialLoading or None
        The static axial-load solution when one was computed.
    """
    if isinstance(bearing, RollerBearing):
        return 0.0, None
    if operation.axial_load > 0.0:
        if bearing.contact_angle is not None:
            # A fixed angle (seed 000's model) carries the load at that angle.
            fixed = axial_loading_fixed_angle(bearing, operation.axial_load)
            return bearing.contact_angle, fixed
        loading = axial_loading(bearing, operation.axial_load)
        return loading.contact_angle, loading
    return bearing.unloaded_contact_angle, None
