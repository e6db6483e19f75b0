r"""Hertz contact between rolling elements and raceways (point and line contact).

Everything is SI: lengths [m], curvatures [1/m], loads [N], moduli and pressures [Pa].
A *contact stiffness* is the constant of the load-deflection law :math:`Q = K\,\delta^{n}`
with :math:`n = 3/2` for point contact [N/m^1.5] and :math:`n = 10/9` for line contact
[N/m^(10/9)]; :math:`\delta` is the *approach* (mutual elastic deflection of the two bodies).

Point contact (balls)
---------------------
Geometry enters through the curvature sum :math:`\Sigma\rho` and the curvature difference
:math:`F(\rho)` (seed 003 eq. 2.6-2.9, after Harris). The ellipticity :math:`\kappa = a/b` of the
contact ellipse solves the classical transcendental equation (Harris, *Rolling Bearing
Analysis*, ch. 6)

.. math::

    F(\rho) = \frac{(\kappa^2+1)\,\mathcal{E}(m) - 2\,\mathcal{K}(m)}{(\kappa^2-1)\,\mathcal{E}(m)},
    \qquad m = 1 - \kappa^{-2},

where :math:`\mathcal{K}, \mathcal{E}` are the complete elliptic integrals of the first and
second kind of *parameter* :math:`m` (SciPy's convention; the modulus is :math:`\sqrt{m}`). With
Harris's effective modulus :math:`E' = 2/[(1-\nu_I^2)/E_I + (1-\nu_{II}^2)/E_{II}]` and
:math:`\Lambda = 3Q/(E'\Sigma\rho)`:

.. math::

    a = a^*\Lambda^{1/3},\quad b = b^*\Lambda^{1/3},\quad
    \delta = \delta^*\Lambda^{2/3}\,\frac{\Sigma\rho}{2},\quad
    p_{max} = \frac{3Q}{2\pi a b},

    a^* = \Big(\frac{2\kappa^2\mathcal{E}}{\pi}\Big)^{1/3},\quad
    b^* = \Big(\frac{2\mathcal{E}}{\pi\kappa}\Big)^{1/3},\quad
    \delta^* = \frac{2\mathcal{K}}{\pi}\Big(\frac{\pi}{2\kappa^2\mathcal{E}}\Big)^{1/3}.

Solving :math:`\delta(Q)` for :math:`Q` gives the stiffness

.. math:: K = \frac{2\sqrt2}{3}\,E'\,(\Sigma\rho)^{-1/2}\,(\delta^*)^{-3/2}.

Line contact (cylindrical rollers)
----------------------------------
Palmgren's empirical law as quoted by Harris, made dimensionally homogeneous so that it can be
used with other materials (see :func:`line_contact_approach`).

Seed 002 (Anderon) treats a ball pressed on a flat; :func:`ball_flat_contact_radius` and
:func:`ball_flat_cap_force` reproduce its eq. 9-10 and explain how they relate to Hertz.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.base.errors import ConvergenceError, GeometryError
from runout.geometry._elliptic import complete_elliptic
from runout.geometry.bearing import BallBearing, Material, RollerBearing

__all__ = [
    "HARRIS_DELTA_STAR_TABLE",
    "HARRIS_STEEL_APPROACH_CONSTANT",
    "ISO76_BALL_PRESSURE",
    "ISO76_ROLLER_PRESSURE",
    "PALMGREN_LINE_CONSTANT",
    "PLASTIC_PRESSURE",
    "BallContacts",
    "HertzFinding",
    "HertzIntegrals",
    "LineContact",
    "PointContact",
    "RollerContacts",
    "ball_flat_cap_displacement",
    "ball_flat_cap_force",
    "ball_flat_contact_radius",
    "ball_load_validity",
    "ball_race_contacts",
    "ball_race_curvature",
    "combined_stiffness",
    "curvature_difference_from_ratio",
    "curvature_from_radii",
    "delta_star_from_table",
    "dimensionless_factors",
    "ellipticity",
    "hamrock_brewe",
    "harris_steel_approach",
    "hertz_point_stiffness",
    "line_contact_approach",
    "line_contact_load",
    "point_contact",
    "radius_ratio",
    "roller_load_validity",
    "roller_race_contacts",
    "stiffness_from_delta_star_table",
]

FloatArray = NDArray[np.float64]
RaceName = Literal["inner", "outer"]

# Below this elliptic parameter m the closed forms lose digits to cancellation; use series.
_SMALL_M = 1e-3
# Maclaurin coefficients (in m) of F(rho)(m) and of D(m) = (K - E) / (m pi/2), exact rationals
# obtained from the hypergeometric series of K and E.
_F_SERIES = (0.0, 3 / 8, 3 / 16, 111 / 1024, 141 / 2048, 1533 / 32768)
_D_SERIES = (1 / 2, 3 / 16, 15 / 128, 175 / 2048, 2205 / 32768, 14553 / 262144)


def _poly(coeffs: tuple[float, ...], x: FloatArray) -> FloatArray:
    out = np.zeros_like(x)
    for c in reversed(coeffs):
        out = out * x + c
    return out


def _as_float_array(value: ArrayLike, name: str) -> FloatArray:
    arr = np.asarray(value, dtype=np.float64)
    if np.any(np.isnan(arr)):
        raise GeometryError(name, "contains NaN")
    return arr


# --------------------------------------------------------------------------------------------
# Curvature sum and difference
# --------------------------------------------------------------------------------------------
def curvature_from_radii(
    r_i1: ArrayLike, r_i2: ArrayLike, r_ii1: ArrayLike, r_ii2: ArrayLike
) -> tuple[FloatArray, FloatArray]:
    r"""Curvature sum and difference of two bodies from their principal radii.

    Seed 003 eq. 2.6-2.7 (Harris). Body I and body II touch at one point; index 1 is the
    principal plane containing the rolling direction, index 2 the transverse plane (the two
    bodies' principal planes are assumed to coincide, as in a bearing).

    .. math::

        \Sigma\rho = \frac1{r_{I1}} + \frac1{r_{I2}} + \frac1{r_{II1}} + \frac1{r_{II2}},\qquad
        F(\rho) = \frac{|(\rho_{I1}-\rho_{I2}) + (\rho_{II1}-\rho_{II2})|}{\Sigma\rho}

    Parameters
    ----------
    r_i1, r_i2, r_ii1, r_ii2 : array_like
        Principal radii [m]: positive for a convex surface, negative for a concave one,
        ``numpy.inf`` for a flat direction.

    Returns
    -------
    curvature_sum : ndarray
        :math:`\Sigma\rho` [1/m].
    curvature_difference : ndarray
        :math:`F(\rho)` in [0, 1) [-].

    Raises
    ------
    GeometryError
        If a radius is zero or NaN, if the relative curvature in either plane is negative
        (the concave body is tighter than the convex one, i.e. they do not touch at a point),
        or if it is zero in one plane (line contact: use :class:`LineContact`).

    Notes
    -----
    Harris writes :math:`F(\rho)` without the absolute value and labels the planes so that it
    is positive; taking the magnitude makes the result independent of the labelling.
    """
    radii = [_as_float_array(r, n) for r, n in zip((r_i1, r_i2, r_ii1, r_ii2), _RADII, strict=True)]
    for r, n in zip(radii, _RADII, strict=True):
        if np.any(r == 0.0):
            raise GeometryError(n, "a principal radius of curvature cannot be zero")
    rho = [1.0 / r for r in radii]
    plane1 = rho[0] + rho[2]
    plane2 = rho[1] + rho[3]
    if np.any(plane1 < 0.0) or np.any(plane2 < 0.0):
        raise GeometryError(
            "curvature", "negative relative curvature: the concave surface is tighter than the ball"
        )
    total = plane1 + plane2
    if np.any(plane1 == 0.0) or np.any(plane2 == 0.0):
        raise GeometryError(
            "curvature", "zero relative curvature in one plane: this is a line contact"
        )
    return total, np.abs(plane1 - plane2) / total


_RADII = ("r_i1", "r_i2", "r_ii1", "r_ii2")


def ball_race_curvature(
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    conformity: ArrayLike,
    contact_angle: ArrayLike = 0.0,
    race: RaceName = "inner",
) -> tuple[FloatArray, FloatArray]:
    r"""Curvature sum and difference of a ball on its inner or outer groove.

    Seed 003 eq. 2.8 (inner) and 2.9 (outer), written with Harris's
    :math:`\gamma = D\cos\alpha/d_m`, which also covers a non-zero contact angle:

    .. math::

        \Sigma\rho_i &= \frac1D\Big(4 - \frac1{f_i} + \frac{2\gamma}{1-\gamma}\Big), &
        F(\rho)_i &= \frac{1/f_i + 2\gamma/(1-\gamma)}{4 - 1/f_i + 2\gamma/(1-\gamma)} \\
        \Sigma\rho_o &= \frac1D\Big(4 - \frac1{f_o} - \frac{2\gamma}{1+\gamma}\Big), &
        F(\rho)_o &= \frac{1/f_o - 2\gamma/(1+\gamma)}{4 - 1/f_o - 2\gamma/(1+\gamma)}

    Parameters
    ----------
    ball_diameter : array_like
        D [m].
    pitch_diameter : array_like
        d_m [m].
    conformity : array_like
        Groove radius over ball diameter f = r/D (> 0.5) [-].
    contact_angle : array_like
        α [rad].
    race : {"inner", "outer"}
        Which raceway.

    Returns
    -------
    curvature_sum : ndarray
        Σρ [1/m].
    curvature_difference : ndarray
        F(ρ) [-].

    Notes
    -----
    Seed 003 eq. 2.8 gives the radius of the inner raceway in the rolling plane as d_i/2, the
    groove-bottom radius; that is the α = 0 case of Harris's :math:`(d_m - D\cos\alpha)/
    (2\cos\alpha)`, which is what γ encodes. (The extracted eq. 2.8 also lost its fraction
    bars: "2_D'" stands for 2/D.)
    """
    d = _as_float_array(ball_diameter, "ball_diameter")
    f = _as_float_array(conformity, "conformity")
    if np.any(d <= 0.0):
        raise GeometryError("ball_diameter", "must be positive")
    if np.any(f <= 0.5):
        raise GeometryError("conformity", "must be > 0.5 (groove radius larger than the ball's)")
    g = d * np.cos(contact_angle) / _as_float_array(pitch_diameter, "pitch_diameter")
    if np.any(g >= 1.0) or np.any(g < 0.0):
        raise GeometryError("pitch_diameter", "D cos(alpha) / d_m must lie in [0, 1)")
    if race == "inner":
        ring = 2.0 * g / (1.0 - g)
    elif race == "outer":
        ring = -2.0 * g / (1.0 + g)
    else:
        raise GeometryError("race", f'must be "inner" or "outer", got {race!r}')
    denom = 4.0 - 1.0 / f + ring
    return denom / d, (1.0 / f + ring) / denom


# --------------------------------------------------------------------------------------------
# Ellipticity and the elliptic integrals
# --------------------------------------------------------------------------------------------
class HertzIntegrals(NamedTuple):
    """Ellipticity κ = a/b [-] and the complete elliptic integrals K(m), E(m), m = 1 - 1/κ².

    Attributes
    ----------
    ellipticity : ndarray
        κ = a/b (>= 1) [-].
    first_kind : ndarray
        Complete elliptic integral of the first kind K(m) [-].
    second_kind : ndarray
        Complete elliptic integral of the second kind E(m) [-].
    """

    ellipticity: FloatArray
    first_kind: FloatArray
    second_kind: FloatArray


def _integrals(x: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray]:
    """p = 1 - m, m, K(m), E(m) and D(m) = (K - E)/m at x = ln(1 - m) = -2 ln κ (x <= 0)."""
    p = np.exp(x)  # p = 1 - m = 1/κ², precise even when m -> 1
    m = -np.expm1(x)
    k, e = complete_elliptic(p, m)  # by the AGM; scipy.special costs ~0.1 s of start-up
    small = m < _SMALL_M
    if np.any(small):
        with np.errstate(divide="ignore", invalid="ignore"):
            d = np.where(small, 0.5 * np.pi * _poly(_D_SERIES, m), (k - e) / m)
    else:
        d = (k - e) / m
    return p, m, k, e, d


def _residual(
    x: FloatArray, log_q: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """Residual ln(1 - F(x)) - ln(1 - F_target), its slope d/dx, and K, E at x."""
    p, m, k, e, d = _integrals(x)
    q = 2.0 * p * d / e  # 1 - F, precise for slender contacts
    small = m < _SMALL_M
    with np.errstate(divide="ignore", invalid="ignore"):
        if np.any(small):
            # near the circle take F from its series, so that ln(1 - F) keeps relative digits
            f_series = _poly(_F_SERIES, m)
            log_q_x = np.where(small, np.log1p(-f_series), np.log(q))
            f_over_m = np.where(small, _poly(_F_SERIES[1:], m), (1.0 - q) / m)
        else:
            log_q_x = np.log(q)
            f_over_m = (1.0 - q) / m
    slope = 1.0 - f_over_m * e / (2.0 * d) - p * d / (2.0 * e)
    return log_q_x - log_q, slope, k, e


def _newton(
    log_q: FloatArray, x0: FloatArray, rtol: float, max_iter: int
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Safeguarded vectorised Newton for x = -2 ln κ; returns x, K, E."""
    lo = np.minimum(8.0 / 3.0 * log_q, 0.0)
    hi = log_q.copy()
    # below |ln(1 - F)| = 1e-100 the caller's series guess is already exact to round-off
    done = log_q > -1e-100
    x = np.clip(x0, lo, hi)
    for _ in range(max_iter):
        resid, slope, _, _ = _residual(x, log_q)
        # keep the bracket: the residual increases with x
        lo = np.where(resid < 0.0, np.maximum(lo, x), lo)
        hi = np.where(resid > 0.0, np.minimum(hi, x), hi)
        x_new = x - resid / slope
        outside = (x_new < lo) | (x_new > hi) | ~np.isfinite(x_new)
        x_new = np.where(outside, 0.5 * (lo + hi), x_new)
        converged = np.abs(x_new - x) <= rtol * np.abs(x)
        x = np.where(done, x, x_new)
        done = done | converged | (resid == 0.0)
        if np.all(done):
            break
    else:
        bad = log_q[~done]
        raise ConvergenceError(
            f"Hertz ellipticity did not converge for F(rho) = {-np.expm1(bad[:3])}"
        )
    _, _, k, e, _ = _integrals(x)
    return x, k, e


@lru_cache(maxsize=1)
def _starting_table() -> tuple[FloatArray, FloatArray]:
    """x = -2 ln κ tabulated against u = -ln(1 - F) on [0, 37], for Newton's first guess."""
    u = np.concatenate([[0.0], np.geomspace(1e-4, 4.0, 240), np.linspace(4.0, 37.0, 166)[1:]])
    kappa0 = 1.0339 * radius_ratio(-np.expm1(-u)) ** 0.636  # Hamrock & Brewe's fit
    x, _, _ = _newton(-u, -2.0 * np.log(kappa0), 1e-10, 60)
    return u, x


def ellipticity(
    curvature_difference: ArrayLike, *, rtol: float = 1e-8, max_iter: int = 40
) -> HertzIntegrals:
    r"""Solve Hertz's equation for the ellipticity κ = a/b, vectorised.

    Harris, *Rolling Bearing Analysis*, ch. 6 (the relation between F(ρ) and κ; seed 003
    calls F(ρ) the curvature difference, eq. 2.7):

    .. math::

        F(\rho) = \frac{(\kappa^2+1)\mathcal{E}(m) - 2\mathcal{K}(m)}{(\kappa^2-1)\mathcal{E}(m)},
        \qquad m = 1-\kappa^{-2}.

    Parameters
    ----------
    curvature_difference : array_like
        F(ρ) in [0, 1) [-].
    rtol : float
        Newton stops once a step changes ln κ by less than ``rtol`` relative; convergence is
        quadratic, so the error left is of order ``rtol**2``, i.e. round-off.
    max_iter : int
        Newton iterations allowed.

    Returns
    -------
    HertzIntegrals
        κ (>= 1), :math:`\mathcal{K}(m)` and :math:`\mathcal{E}(m)`, arrays shaped like the
        input.

    Raises
    ------
    GeometryError
        If F(ρ) is outside [0, 1) (F = 1 is a line contact).
    ConvergenceError
        If the iteration does not converge (not observed for any F in [0, 1)).

    Notes
    -----
    The unknown is :math:`x = \ln(1-m) = -2\ln\kappa` and the residual
    :math:`\ln(1-F(x)) - \ln(1-F_{target})`, with :math:`1 - F = 2(1-m)(\mathcal{K}
    - \mathcal{E})/(m\mathcal{E})` evaluated directly so that slender contacts keep their
    digits. Written this way the equation is monotone and concave with slope between 3/8
    (κ → 1) and 1 (κ → ∞), and the root is bracketed by :math:`[\tfrac83\ln(1-F),
    \ln(1-F)]`; Newton is kept inside the bracket (bisection otherwise). The first guess
    is interpolated in a small table of exact solutions, so two or three steps reach
    round-off. :math:`\mathcal{K}` and :math:`\mathcal{E}` come from
    :func:`runout.geometry._elliptic.complete_elliptic` (arithmetic-geometric mean, within a few ulp
    of SciPy's ``ellipkm1(1 - m)`` and ``ellipe(m)``), given 1 - m so that it keeps its
    digits near m = 1; below m = 1e-3 short Maclaurin series replace the closed forms,
    which lose digits to cancellation there.
    """
    f_target = _as_float_array(curvature_difference, "curvature_difference")
    if np.any(f_target < 0.0) or np.any(f_target >= 1.0):
        raise GeometryError(
            "curvature_difference", "F(rho) must lie in [0, 1); F = 1 is a line contact"
        )
    log_q = np.log1p(-f_target)  # ln(1 - F) <= 0
    u_tab, x_tab = _starting_table()
    x0 = np.interp(-log_q, u_tab, x_tab)
    # near the circle invert the series F = 3m/8 + 3m²/16 + 111m³/1024 instead
    f0 = np.minimum(f_target, u_tab[1])
    m0 = f0 * (8.0 / 3.0 + f0 * (-32.0 / 9.0 + 4.0 * f0))
    x0 = np.where(f_target < u_tab[1], np.log1p(-m0), x0)
    x, k, e = _newton(log_q, x0, rtol, max_iter)
    return HertzIntegrals(np.exp(-0.5 * x), k, e)


def dimensionless_factors(
    curvature_difference: ArrayLike,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    r"""Harris's dimensionless contact factors a*, b*, δ* for a curvature difference F(ρ).

    .. math::

        a^* = \Big(\frac{2\kappa^2\mathcal{E}}{\pi}\Big)^{1/3},\quad
        b^* = \Big(\frac{2\mathcal{E}}{\pi\kappa}\Big)^{1/3},\quad
        \delta^* = \frac{2\mathcal{K}}{\pi}\Big(\frac{\pi}{2\kappa^2\mathcal{E}}\Big)^{1/3}

    All three equal 1 for a circular contact.

    Parameters
    ----------
    curvature_difference : array_like
        F(ρ) [-].

    Returns
    -------
    a_star, b_star, delta_star : ndarray
        [-].

    Notes
    -----
    Harris, *Rolling Bearing Analysis*, ch. 6; δ* is the quantity tabulated in seed 003
    (Purohit & Purohit 2006) Table 1.
    """
    return _factors(ellipticity(curvature_difference))


def _factors(h: HertzIntegrals) -> tuple[FloatArray, FloatArray, FloatArray]:
    kappa, k, e = h
    inv_k2 = kappa**-2.0
    a_star = np.cbrt(2.0 * e / (np.pi * inv_k2))
    b_star = np.cbrt(2.0 * e / (np.pi * kappa))
    delta_star = (2.0 * k / np.pi) * np.cbrt(np.pi * inv_k2 / (2.0 * e))
    return a_star, b_star, delta_star


def hertz_point_stiffness(
    curvature_sum: ArrayLike, curvature_difference: ArrayLike, effective_modulus: ArrayLike
) -> FloatArray:
    r"""Load-deflection constant K of a Hertz point contact, Q = K δ^1.5 [N/m^1.5].

    .. math:: K = \frac{2\sqrt2}{3}\,E'\,(\Sigma\rho)^{-1/2}\,(\delta^*)^{-3/2}

    Obtained by solving Harris's :math:`\delta = \delta^*[3Q/(E'\Sigma\rho)]^{2/3}\Sigma\rho/2`
    for Q.

    Parameters
    ----------
    curvature_sum : array_like
        Σρ [1/m].
    curvature_difference : array_like
        F(ρ) [-].
    effective_modulus : array_like
        Harris's E' [Pa] (``Material.effective_modulus`` for two bodies of one material).

    Returns
    -------
    ndarray
        K [N/m^1.5].

    Notes
    -----
    It is seed 003 (Purohit & Purohit 2006) eq. 2.12-2.13 for any material (see
    :func:`harris_steel_approach` for the steel-only numbers); Harris, *Rolling Bearing
    Analysis*, ch. 6.
    """
    s = _positive_array(curvature_sum, "curvature_sum")
    ep = _positive_array(effective_modulus, "effective_modulus")
    _, _, ds = dimensionless_factors(curvature_difference)
    return _stiffness(s, ep, ds)


def _stiffness(
    curvature_sum: FloatArray, modulus: FloatArray, delta_star: FloatArray
) -> FloatArray:
    return 2.0 * math.sqrt(2.0) / 3.0 * modulus / (np.sqrt(curvature_sum) * delta_star**1.5)


def _positive_array(value: ArrayLike, name: str) -> FloatArray:
    arr = _as_float_array(value, name)
    if np.any(~(arr > 0.0)) or np.any(~np.isfinite(arr)):
        raise GeometryError(name, "must be positive and finite")
    return arr


def _check_load(load: ArrayLike, name: str = "load") -> FloatArray:
    arr = _as_float_array(load, name)
    if np.any(arr < 0.0) or np.any(~np.isfinite(arr)):
        raise GeometryError(name, "must be a finite non-negative force [N]")
    return arr


# --------------------------------------------------------------------------------------------
# Point contact result
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PointContact:
    r"""One Hertz point contact (a ball on a raceway), solved exactly.

    Attributes
    ----------
    curvature_sum : float
        Σρ [1/m].
    curvature_difference : float
        F(ρ) [-].
    effective_modulus : float
        E' [Pa].
    ellipticity : float
        κ = a/b [-].
    first_kind, second_kind : float
        Complete elliptic integrals :math:`\mathcal{K}(m)`, :math:`\mathcal{E}(m)`,
        m = 1 - 1/κ² [-].
    a_star, b_star, delta_star : float
        Harris's dimensionless factors [-].
    stiffness : float
        K in Q = K δ^1.5 [N/m^1.5].
    """

    curvature_sum: float
    curvature_difference: float
    effective_modulus: float
    ellipticity: float
    first_kind: float
    second_kind: float
    a_star: float
    b_star: float
    delta_star: float
    stiffness: float

    @classmethod
    def from_radii(
        cls, r_i1: float, r_i2: float, r_ii1: float, r_ii2: float, effective_modulus: float
    ) -> PointContact:
        """Contact of two bodies from their principal radii [m] (:func:`curvature_from_radii`).

        Parameters
        ----------
        r_i1, r_i2, r_ii1, r_ii2 : float
            Principal radii of body I and body II [m]: positive convex, negative concave,
            ``numpy.inf`` flat; index 1 is the rolling plane, 2 the transverse plane.
        effective_modulus : float
            Harris's E' [Pa].

        Returns
        -------
        PointContact
            The contact solved by :func:`point_contact`.
        """
        s, f = curvature_from_radii(r_i1, r_i2, r_ii1, r_ii2)
        return point_contact(float(s), float(f), effective_modulus)

    def _scale(self, load: ArrayLike) -> FloatArray:
        """Λ^(1/3) = (3Q / (E' Σρ))^(1/3) [m]."""
        q = _check_load(load)
        return np.cbrt(3.0 * q / (self.effective_modulus * self.curvature_sum))

    def approach(self, load: ArrayLike) -> FloatArray:
        """Elastic approach δ = (Q/K)^(2/3) [m] for a normal load Q [N] (>= 0).

        Parameters
        ----------
        load : array_like
            Normal contact load Q [N] (>= 0).

        Returns
        -------
        ndarray
            Approach δ [m].
        """
        return (_check_load(load) / self.stiffness) ** (2.0 / 3.0)

    def load(self, approach: ArrayLike) -> FloatArray:
        """Normal load Q = K [δ]₊^1.5 [N]; a negative approach (a gap) carries no load.

        Parameters
        ----------
        approach : array_like
            Approach δ [m]; negative for a gap.

        Returns
        -------
        ndarray
            Normal load Q [N].
        """
        d = _as_float_array(approach, "approach")
        return self.stiffness * np.maximum(d, 0.0) ** 1.5

    def semi_axes(self, load: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """Semi-major a and semi-minor b axes of the contact ellipse [m].

        Parameters
        ----------
        load : array_like
            Normal contact load Q [N] (>= 0).

        Returns
        -------
        a, b : ndarray
            Semi-major and semi-minor axes [m].
        """
        lam = self._scale(load)
        return self.a_star * lam, self.b_star * lam

    def max_pressure(self, load: ArrayLike) -> FloatArray:
        """Maximum Hertz pressure 3Q / (2π a b) [Pa] (0 at zero load).

        Parameters
        ----------
        load : array_like
            Normal contact load Q [N] (>= 0).

        Returns
        -------
        ndarray
            Maximum pressure p_max [Pa].
        """
        q = _check_load(load)
        a, b = self.semi_axes(q)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(q > 0.0, 1.5 * q / (np.pi * a * b), 0.0)


def point_contact(
    curvature_sum: float, curvature_difference: float, effective_modulus: float
) -> PointContact:
    """Solve one Hertz point contact exactly (see the module docstring for the formulas).

    Parameters
    ----------
    curvature_sum : float
        Σρ [1/m] (> 0).
    curvature_difference : float
        F(ρ) in [0, 1) [-].
    effective_modulus : float
        Harris's E' [Pa].

    Returns
    -------
    PointContact
        κ [-], the elliptic integrals K(m), E(m) [-], a*, b*, δ* [-] and the stiffness
        K [N/m^1.5].

    Notes
    -----
    Harris, *Rolling Bearing Analysis*, ch. 6; the stiffness is seed 003 (Purohit & Purohit
    2006) eq. 2.12-2.13 for any material (:func:`hertz_point_stiffness`).
    """
    h = ellipticity(curvature_difference)
    kappa, k, e = h
    a_s, b_s, d_s = _factors(h)
    s = _positive_array(curvature_sum, "curvature_sum")
    ep = _positive_array(effective_modulus, "effective_modulus")
    stiffness = _stiffness(s, ep, d_s)
    return PointContact(
        curvature_sum=float(curvature_sum),
        curvature_difference=float(curvature_difference),
        effective_modulus=float(effective_modulus),
        ellipticity=float(kappa),
        first_kind=float(k),
        second_kind=float(e),
        a_star=float(a_s),
        b_star=float(b_s),
        delta_star=float(d_s),
        stiffness=float(stiffness),
    )


def combined_stiffness(k_inner: ArrayLike, k_outer: ArrayLike, exponent: float = 1.5) -> FloatArray:
    r"""Stiffness of two contacts in series (ball-inner and ball-outer), Q = K_n δ^n.

    The two approaches add under the same load, :math:`\delta = (Q/K_i)^{1/n} + (Q/K_o)^{1/n}`,
    hence

    .. math::

        K_n = \Big[\Big(\frac1{K_i}\Big)^{1/n} + \Big(\frac1{K_o}\Big)^{1/n}\Big]^{-n}
            = \frac{K_i K_o}{\big(K_i^{1/n} + K_o^{1/n}\big)^{n}}.

    Use n = 10/9 for line contacts.

    Parameters
    ----------
    k_inner, k_outer : array_like
        Stiffnesses of the two contacts [N/m^n] (> 0).
    exponent : float
        Load-deflection exponent n.

    Returns
    -------
    ndarray
        K_n [N/m^n].

    Notes
    -----
    With n = 3/2 this is seed 001 eq. 15 (first form), seed 000 eq. 4 (second form,
    :math:`K_iK_o/[K_i^{2/3}+K_o^{2/3}]^{1.5}`) and seed 003 eq. 2.14 (first form with the
    exponent written 1/n): multiplying the bracket of the first form by
    :math:`(K_iK_o)^{1/n}` turns it into the second, so the three are one expression
    (Kim, Choi & Yoon; Tada 2002; Purohit & Purohit 2006).
    """
    ki = _positive_array(k_inner, "k_inner")
    ko = _positive_array(k_outer, "k_outer")
    inv_n = 1.0 / exponent
    return (ki**-inv_n + ko**-inv_n) ** (-exponent)


@dataclass(frozen=True)
class BallContacts:
    """Both contacts of one ball at a given contact angle.

    Attributes
    ----------
    contact_angle : float
        α [rad].
    inner, outer : PointContact
        Ball-inner and ball-outer raceway contacts.
    combined_stiffness : float
        K_n of the two in series [N/m^1.5] (see :func:`combined_stiffness`).
    """

    contact_angle: float
    inner: PointContact
    outer: PointContact
    combined_stiffness: float

    def approach(self, load: ArrayLike) -> FloatArray:
        """Total approach δ_i + δ_o = (Q/K_n)^(2/3) of the two raceways [m].

        Parameters
        ----------
        load : array_like
            Ball load Q [N] (>= 0).

        Returns
        -------
        ndarray
            Total approach δ_i + δ_o [m].
        """
        return (_check_load(load) / self.combined_stiffness) ** (2.0 / 3.0)

    def load(self, approach: ArrayLike) -> FloatArray:
        """Ball load K_n [δ]₊^1.5 [N] for a total approach δ [m].

        Parameters
        ----------
        approach : array_like
            Total approach δ of the two raceways [m]; negative for a gap.

        Returns
        -------
        ndarray
            Ball load Q [N].
        """
        d = _as_float_array(approach, "approach")
        return self.combined_stiffness * np.maximum(d, 0.0) ** 1.5


def ball_race_contacts(bearing: BallBearing, contact_angle: float | None = None) -> BallContacts:
    """Exact Hertz contacts of a ball with both raceways of ``bearing``.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and material (E' = ``bearing.material.effective_modulus``).
    contact_angle : float or None
        α [rad]; default ``bearing.unloaded_contact_angle``.

    Returns
    -------
    BallContacts
        Inner and outer :class:`PointContact` and the series stiffness K_n (seed 000 eq. 4,
        seed 001 eq. 15, seed 003 eq. 2.14).
    """
    alpha = bearing.unloaded_contact_angle if contact_angle is None else float(contact_angle)
    if not (math.isfinite(alpha) and 0.0 <= alpha < 0.5 * math.pi):
        raise GeometryError("contact_angle", f"must lie in [0, 90) deg, got {alpha!r} rad")
    ep = bearing.material.effective_modulus
    contacts = []
    races: tuple[tuple[RaceName, float], ...] = (
        ("inner", bearing.inner_conformity),
        ("outer", bearing.outer_conformity),
    )
    for race, f in races:
        s, fr = ball_race_curvature(
            bearing.element_diameter, bearing.pitch_diameter, f, alpha, race
        )
        contacts.append(point_contact(float(s), float(fr), ep))
    inner, outer = contacts
    kn = float(combined_stiffness(inner.stiffness, outer.stiffness))
    return BallContacts(alpha, inner, outer, kn)


# --------------------------------------------------------------------------------------------
# Approximations and tables (cross-checks)
# --------------------------------------------------------------------------------------------
def radius_ratio(curvature_difference: ArrayLike) -> FloatArray:
    r"""Ratio R_y/R_x >= 1 of the effective radii for a curvature difference F(ρ).

    With :math:`1/R_x` and :math:`1/R_y` the relative curvatures of the two principal planes,
    :math:`F = (1/R_x - 1/R_y)/(1/R_x + 1/R_y)`, so :math:`R_y/R_x = (1+F)/(1-F)`.

    Parameters
    ----------
    curvature_difference : array_like
        F(ρ) in [0, 1) [-].

    Returns
    -------
    ndarray
        Radius ratio R_y/R_x [-].
    """
    f = _as_float_array(curvature_difference, "curvature_difference")
    return (1.0 + f) / (1.0 - f)


def curvature_difference_from_ratio(ratio: ArrayLike) -> FloatArray:
    """F(ρ) = (r - 1)/(r + 1) for a radius ratio r = R_y/R_x >= 1 (inverse of radius_ratio).

    Parameters
    ----------
    ratio : array_like
        Radius ratio r = R_y/R_x (>= 1) [-].

    Returns
    -------
    ndarray
        Curvature difference F(ρ) [-].
    """
    r = _as_float_array(ratio, "ratio")
    return (r - 1.0) / (r + 1.0)


def hamrock_brewe(ratio: ArrayLike) -> HertzIntegrals:
    r"""Hamrock & Brewe's curve fits of κ, :math:`\mathcal{K}`, :math:`\mathcal{E}`.

    For :math:`r = R_y/R_x \ge 1` (Hamrock & Brewe 1983, J. Lubr. Technol. 105; quoted in
    Harris ch. 6):

    .. math::

        \kappa \approx 1.0339\,r^{0.636},\quad
        \mathcal{E} \approx 1.0003 + 0.5968/r,\quad
        \mathcal{K} \approx 1.5277 + 0.6023\ln r

    Their stated accuracy is a few per cent; used here only as a cross-check and as the
    starting point of :func:`ellipticity`.

    Parameters
    ----------
    ratio : array_like
        Radius ratio r = R_y/R_x (>= 1) [-].

    Returns
    -------
    HertzIntegrals
        Approximate κ, :math:`\mathcal{K}` and :math:`\mathcal{E}` [-].
    """
    r = _as_float_array(ratio, "ratio")
    return HertzIntegrals(1.0339 * r**0.636, 1.5277 + 0.6023 * np.log(r), 1.0003 + 0.5968 / r)


#: Seed 003 Table 1 (after Harris 1991): curvature difference F(ρ) -> δ*. The extracted row
#: "0.995112 -> 3176" lost its leading "0."; it is restored as 0.3176 (the exact δ* there is
#: 0.3176).
HARRIS_DELTA_STAR_TABLE: tuple[tuple[float, float], ...] = (
    (0.0, 1.0),
    (0.1075, 0.997),
    (0.3204, 0.9761),
    (0.4795, 0.9429),
    (0.5916, 0.9077),
    (0.6716, 0.8733),
    (0.7332, 0.8394),
    (0.7948, 0.7961),
    (0.83595, 0.7602),
    (0.87366, 0.7169),
    (0.90999, 0.6636),
    (0.93657, 0.6112),
    (0.95738, 0.5551),
    (0.97290, 0.4960),
    (0.983797, 0.4352),
    (0.990902, 0.3745),
    (0.995112, 0.3176),
    (0.997300, 0.2705),
    (0.9981847, 0.2427),
    (0.9989156, 0.2106),
    (0.9994785, 0.17167),
    (0.9998527, 0.11995),
    (1.0, 0.0),
)


def delta_star_from_table(curvature_difference: ArrayLike) -> FloatArray:
    r"""δ* interpolated in seed 003 Table 1 (Harris's tabulation).

    Interpolation is linear in :math:`(\ln(1-F), \ln\delta^*)` between the tabulated rows
    (linear in F between 0 and the first non-zero row), which follows the logarithmic
    behaviour of δ* as F → 1 far better than plain linear interpolation in F.

    Parameters
    ----------
    curvature_difference : array_like
        F(ρ) in [0, 0.9998527] (the last finite row) [-].

    Returns
    -------
    ndarray
        δ* [-].

    Raises
    ------
    GeometryError
        Outside the table's range; the last row (F = 1, δ* = 0) is the line-contact limit and
        cannot be interpolated towards.

    Notes
    -----
    Seed 003 (Purohit & Purohit 2006) Table 1, after Harris (1991); see
    :data:`HARRIS_DELTA_STAR_TABLE` for the restored row.
    """
    f = _as_float_array(curvature_difference, "curvature_difference")
    table = np.array(HARRIS_DELTA_STAR_TABLE[:-1])
    if np.any(f < 0.0) or np.any(f > table[-1, 0]):
        raise GeometryError(
            "curvature_difference", f"outside the table's range [0, {table[-1, 0]}]"
        )
    x_tab = np.log1p(-table[:, 0])
    y_tab = np.log(table[:, 1])
    # np.interp needs increasing abscissae: -ln(1-F) increases with F
    return np.exp(np.interp(-np.log1p(-f), -x_tab, y_tab))


def stiffness_from_delta_star_table(
    curvature_sum: ArrayLike, curvature_difference: ArrayLike, effective_modulus: ArrayLike
) -> FloatArray:
    r"""Point-contact stiffness with δ* taken from seed 003 Table 1 instead of solved.

    Same formula as :func:`hertz_point_stiffness`,
    :math:`K = \tfrac{2\sqrt2}{3}E'(\Sigma\rho)^{-1/2}(\delta^*)^{-3/2}` (seed 003 eq. 2.12-2.13
    generalised to any E'), with δ* from :func:`delta_star_from_table`.

    Parameters
    ----------
    curvature_sum : array_like
        Σρ [1/m].
    curvature_difference : array_like
        F(ρ) [-], within the table's range (0 to 0.9998527).
    effective_modulus : array_like
        Harris's E' [Pa].

    Returns
    -------
    ndarray
        K [N/m^1.5].

    Notes
    -----
    Seed 003 (Purohit & Purohit 2006) eq. 2.12-2.13 and Table 1.
    """
    s = _positive_array(curvature_sum, "curvature_sum")
    ep = _positive_array(effective_modulus, "effective_modulus")
    return _stiffness(s, ep, delta_star_from_table(curvature_difference))


#: Coefficient c of seed 003 eq. 2.10, δ = c δ* Q^(2/3) (Σρ)^(1/3), in SI (δ [m], Q [N],
#: Σρ [1/m]). It equals (3/E')^(2/3)/2 with E' = 207.5 GPa / (1 - 0.3²) (Harris's steel).
HARRIS_STEEL_APPROACH_CONSTANT = 2.787e-8


def harris_steel_approach(
    load: ArrayLike, curvature_sum: ArrayLike, delta_star: ArrayLike
) -> FloatArray:
    r"""Approach of a steel-on-steel point contact by seed 003 eq. 2.10 [m].

    .. math:: \delta = 2.787\times10^{-8}\;\delta^*\,Q^{2/3}\,(\Sigma\rho)^{1/3}

    with Q [N], Σρ [1/m], δ [m]. Harris prints the same law with the coefficient 2.79e-4 for
    δ in mm and Σρ in 1/mm; that coefficient carries the unit mm^(4/3) N^(-2/3), and
    1 mm^(4/3) = 10⁻⁴ m^(4/3), so the SI coefficient is 2.79e-8: seed 003's 2.787e-8 is the
    SI form (its exponent is not garbled).

    Parameters
    ----------
    load : array_like
        Q [N].
    curvature_sum : array_like
        Σρ [1/m].
    delta_star : array_like
        δ* [-] (from :func:`dimensionless_factors` or :func:`delta_star_from_table`).

    Returns
    -------
    ndarray
        Approach δ [m].

    Notes
    -----
    The coefficient is :math:`(3/E')^{2/3}/2` for E = 207.5 GPa, ν = 0.3 — Harris's steel —
    so this is the general Hertz approach specialised to steel. The inverse printed in seed
    003 is inconsistent with it: eq. 2.11 gives :math:`Q = 3.587\times10^{7}(\Sigma\rho)^{1/2}
    (\delta^*)^{-3/2}\delta^{3/2}` and eq. 2.12-2.13 the same constant with
    :math:`(\Sigma\rho)^{-1/2}` and unit "N/mm". Inverting eq. 2.10 gives
    :math:`(2.787\times10^{-8})^{-3/2} = 2.149\times10^{11}` N/m^1.5 with
    :math:`(\Sigma\rho)^{-1/2}`; 3.587e7 is merely 1/2.787e-8 (the exponent 3/2 was not
    applied), and the sign of the Σρ exponent in eq. 2.11 is wrong. This module uses the
    consistent inverse, :func:`hertz_point_stiffness`.
    """
    q = _check_load(load)
    return (
        HARRIS_STEEL_APPROACH_CONSTANT
        * _as_float_array(delta_star, "delta_star")
        * q ** (2.0 / 3.0)
        * np.cbrt(_positive_array(curvature_sum, "curvature_sum"))
    )


# --------------------------------------------------------------------------------------------
# Ball pressed on a flat (seed 002)
# --------------------------------------------------------------------------------------------
def ball_flat_contact_radius(
    load: ArrayLike, ball_radius: float, material: Material | None = None
) -> FloatArray:
    r"""Radius of the contact circle of a ball pressed on a flat of the same material [m].

    Seed 002 eq. 9:

    .. math:: r = \Big(\frac{3(1-\nu^2)\,r_b\,f}{2E}\Big)^{1/3}

    Parameters
    ----------
    load : array_like
        Contact force f [N].
    ball_radius : float
        :math:`r_b` [m].
    material : Material or None
        E and ν; default steel (``Material()``).

    Returns
    -------
    ndarray
        Contact radius r [m].

    Notes
    -----
    Seed 002 (Anderon calculation model) eq. 9. This is exactly Hertz's circle for a sphere
    of radius :math:`r_b` on a half-space of the same material (:math:`a^3 = 3 f R / (4E^*)`,
    :math:`1/E^* = 2(1-\nu^2)/E`), i.e. the exact point-contact solution with radii
    :math:`(r_b, r_b, \infty, \infty)`.
    """
    mat = Material() if material is None else material
    _positive_array(ball_radius, "ball_radius")
    q = _check_load(load)
    return np.cbrt(
        3.0 * (1.0 - mat.poisson_ratio**2) * ball_radius * q / (2.0 * mat.youngs_modulus)
    )


def ball_flat_cap_force(
    displacement: ArrayLike, ball_radius: float, material: Material | None = None
) -> FloatArray:
    r"""Seed 002 eq. 10: force of a ball on a flat as a function of the "contact displacement".

    .. math:: f(x) = \frac{2E\,[x(2r_b - x)]^{3/2}}{3(1-\nu^2)\,r_b}

    Parameters
    ----------
    displacement : array_like
        x [m], 0 <= x <= r_b.
    ball_radius : float
        :math:`r_b` [m].
    material : Material or None
        E and ν; default steel.

    Returns
    -------
    ndarray
        f [N].

    Notes
    -----
    Eq. 10 is not a Hertz load-deflection law. It takes the Hertz contact radius of eq. 9 and
    reads x as the height of the spherical cap that a *rigid* ball would cut off with a plane
    at that radius, :math:`r^2 = x(2r_b - x)`, then solves eq. 9 for f. For small x this gives
    :math:`x \approx r^2/(2r_b)`, whereas Hertz's approach of the two elastic bodies is
    :math:`\delta = r^2/r_b`: for small x eq. 10 predicts **half** the Hertz deflection at
    the same force, so its force at displacement x equals the Hertz force at approach 2x
    (a stiffness constant :math:`2^{3/2}` times Hertz's). Seed 002's worked example (a 2 mm
    steel ball at 11.039 N, "about 19 um" read off its Fig. 6) is not reproduced: eq. 10 gives
    0.87 um and Hertz 1.74 um with E = 208 GPa; 19 um from eq. 10 needs E about 100 times
    smaller, which points to a unit slip in the figure.
    """
    mat = Material() if material is None else material
    _positive_array(ball_radius, "ball_radius")
    x = _as_float_array(displacement, "displacement")
    if np.any(x < 0.0) or np.any(x > ball_radius):
        raise GeometryError("displacement", "must lie in [0, r_b] for the cap formula")
    return (
        2.0
        * mat.youngs_modulus
        * (x * (2.0 * ball_radius - x)) ** 1.5
        / (3.0 * (1.0 - mat.poisson_ratio**2) * ball_radius)
    )


def ball_flat_cap_displacement(
    load: ArrayLike, ball_radius: float, material: Material | None = None
) -> FloatArray:
    """Inverse of :func:`ball_flat_cap_force` (the small root, x <= r_b) [m].

    x = r_b - sqrt(r_b² - r²) with r from :func:`ball_flat_contact_radius` (seed 002 eq. 9).

    Parameters
    ----------
    load : array_like
        Contact force f [N].
    ball_radius : float
        :math:`r_b` [m].
    material : Material or None
        E and ν; default steel.

    Returns
    -------
    ndarray
        Contact displacement x [m], 0 <= x <= r_b.

    Notes
    -----
    Seed 002 eq. 9-10; see :func:`ball_flat_cap_force` for how x relates to the Hertz
    approach.
    """
    r = ball_flat_contact_radius(load, ball_radius, material)
    if np.any(r > ball_radius):
        raise GeometryError("load", "contact radius exceeds the ball radius")
    return r**2 / (ball_radius + np.sqrt(ball_radius**2 - r**2))


# --------------------------------------------------------------------------------------------
# Line contact (cylindrical rollers)
# --------------------------------------------------------------------------------------------
#: Palmgren's steel roller-raceway law δ = 3.84e-5 Q^0.9 / l^0.8 (δ, l in mm, Q in N), here in
#: SI: 3.84e-5 mm · (1e-3 m/mm) / (1e3 mm/m)^0.8 = 1.5287e-10 (δ, l in m).
PALMGREN_LINE_CONSTANT = 3.84e-5 * 1e-3 / 1e3**0.8
# Harris's steel, for which Palmgren's constant holds: E = 207.5 GPa, ν = 0.3.
_STEEL_EFFECTIVE_MODULUS = 207.5e9 / (1.0 - 0.3**2)
_LINE_EXP = 0.9


def line_contact_approach(
    load: ArrayLike, length: ArrayLike, effective_modulus: float = _STEEL_EFFECTIVE_MODULUS
) -> FloatArray:
    r"""Approach of one roller-raceway line contact, Palmgren's law [m].

    Harris (*Rolling Bearing Analysis*, ch. 6, after Palmgren) for steel:
    :math:`\delta = 3.84\times10^{-5}\,Q^{0.9}/l^{0.8}` with δ, l in mm and Q in N, i.e.
    :math:`\delta = 1.5287\times10^{-10}\,Q^{0.9}l^{-0.8}` in SI. Written dimensionally
    homogeneous,

    .. math:: \delta = c_0\,\Big(\frac{Q}{E' l}\Big)^{0.9} l^{0.1},

    with the dimensionless :math:`c_0 = 1.5287\times10^{-10}\,E_{steel}'^{\,0.9}`. Because the
    exponents of Q and l satisfy 0.9 - 0.8 = 0.1, this is the only form consistent with
    dimensions in which δ depends on Q, l and the elastic constants alone (the roller radius
    does not appear in Palmgren's fit); in Hertz's theory the elastic constants enter only
    through Q/E', so other materials follow by :math:`\delta \propto E'^{-0.9}`.

    Parameters
    ----------
    load : array_like
        Q [N] (>= 0).
    length : array_like
        Effective contact length l [m].
    effective_modulus : float
        Harris's E' [Pa]; default steel (E = 207.5 GPa, ν = 0.3, Harris's values).

    Returns
    -------
    ndarray
        δ [m].

    Notes
    -----
    Empirical, for steel rollers with a straight profile under moderate loads (Palmgren's
    tests); it ignores roller diameter, crowning and edge stresses. The exponent 0.9 (not 1)
    is Palmgren's fit to measured approaches.
    """
    q = _check_load(load)
    ln = _positive_array(length, "length")
    scale = (_STEEL_EFFECTIVE_MODULUS / effective_modulus) ** _LINE_EXP
    return scale * PALMGREN_LINE_CONSTANT * q**_LINE_EXP / ln**0.8


def line_contact_load(
    approach: ArrayLike, length: ArrayLike, effective_modulus: float = _STEEL_EFFECTIVE_MODULUS
) -> FloatArray:
    """Inverse of :func:`line_contact_approach`: Q = K [δ]₊^(10/9) [N].

    Parameters
    ----------
    approach : array_like
        δ [m]; negative for a gap (no load).
    length : array_like
        Effective contact length l [m].
    effective_modulus : float
        Harris's E' [Pa]; default steel (E = 207.5 GPa, ν = 0.3, Harris's values).

    Returns
    -------
    ndarray
        Q [N].

    Notes
    -----
    Palmgren's law as quoted by Harris (*Rolling Bearing Analysis*, ch. 6), inverted.
    """
    d = _as_float_array(approach, "approach")
    ln = _positive_array(length, "length")
    scale = (_STEEL_EFFECTIVE_MODULUS / effective_modulus) ** _LINE_EXP
    return (np.maximum(d, 0.0) * ln**0.8 / (scale * PALMGREN_LINE_CONSTANT)) ** (1.0 / _LINE_EXP)


@dataclass(frozen=True)
class LineContact:
    r"""One roller-raceway line contact.

    Attributes
    ----------
    length : float
        Effective contact length l [m].
    effective_modulus : float
        E' [Pa].
    curvature_sum : float
        Σρ in the rolling plane [1/m] (used only for the Hertz half-width and pressure).
    stiffness : float
        K in Q = K δ^(10/9) [N/m^(10/9)], from Palmgren's law.
    """

    length: float
    effective_modulus: float
    curvature_sum: float
    stiffness: float

    def approach(self, load: ArrayLike) -> FloatArray:
        """Palmgren approach δ [m] for a roller load Q [N].

        Parameters
        ----------
        load : array_like
            Roller load Q [N] (>= 0).

        Returns
        -------
        ndarray
            Approach δ [m] (:func:`line_contact_approach`).
        """
        return line_contact_approach(load, self.length, self.effective_modulus)

    def load(self, approach: ArrayLike) -> FloatArray:
        """Roller load Q [N] for an approach δ [m] (0 for a gap).

        Parameters
        ----------
        approach : array_like
            Approach δ [m]; negative for a gap.

        Returns
        -------
        ndarray
            Roller load Q [N] (:func:`line_contact_load`).
        """
        return line_contact_load(approach, self.length, self.effective_modulus)

    def semi_width(self, load: ArrayLike) -> FloatArray:
        r"""Hertz half-width :math:`b = [8Q/(\pi l E'\Sigma\rho)]^{1/2}` [m] (Harris ch. 6).

        Parameters
        ----------
        load : array_like
            Roller load Q [N] (>= 0).

        Returns
        -------
        ndarray
            Half-width b of the contact band [m].
        """
        q = _check_load(load)
        return np.sqrt(
            8.0 * q / (np.pi * self.length * self.effective_modulus * self.curvature_sum)
        )

    def max_pressure(self, load: ArrayLike) -> FloatArray:
        """Hertz maximum pressure 2Q / (π b l) [Pa] (0 at zero load).

        Parameters
        ----------
        load : array_like
            Roller load Q [N] (>= 0).

        Returns
        -------
        ndarray
            Maximum pressure p_max [Pa].
        """
        q = _check_load(load)
        b = self.semi_width(q)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(q > 0.0, 2.0 * q / (np.pi * b * self.length), 0.0)


@dataclass(frozen=True)
class RollerContacts:
    """Both line contacts of a cylindrical roller.

    Attributes
    ----------
    inner, outer : LineContact
        Roller-inner and roller-outer contacts.
    combined_stiffness : float
        K_n for the two in series with n = 10/9 [N/m^(10/9)]; with Palmgren's law the two
        contacts have the same stiffness, so K_n = K / 2^(10/9).
    """

    inner: LineContact
    outer: LineContact
    combined_stiffness: float

    def approach(self, load: ArrayLike) -> FloatArray:
        """Combined approach δ_i + δ_o [m] for a roller load Q [N].

        Parameters
        ----------
        load : array_like
            Roller load Q [N] (>= 0).

        Returns
        -------
        ndarray
            Combined approach δ_i + δ_o [m].
        """
        return self.inner.approach(load) + self.outer.approach(load)

    def load(self, approach: ArrayLike) -> FloatArray:
        """Roller load Q [N] for a combined approach δ_i + δ_o [m].

        Parameters
        ----------
        approach : array_like
            Combined approach δ_i + δ_o [m]; negative for a gap.

        Returns
        -------
        ndarray
            Roller load Q [N].
        """
        d = _as_float_array(approach, "approach")
        return self.combined_stiffness * np.maximum(d, 0.0) ** (1.0 / _LINE_EXP)


def roller_race_contacts(bearing: RollerBearing) -> RollerContacts:
    """Line contacts of a roller with both raceways of a cylindrical roller bearing.

    Parameters
    ----------
    bearing : RollerBearing
        Needs ``roller_length``; E' = ``bearing.material.effective_modulus``.

    Returns
    -------
    RollerContacts
    """
    if bearing.roller_length is None:
        raise GeometryError("roller_length", "is needed for the line-contact stiffness")
    length = bearing.roller_length
    ep = bearing.material.effective_modulus
    scale = (_STEEL_EFFECTIVE_MODULUS / ep) ** _LINE_EXP
    k = (length**0.8 / (scale * PALMGREN_LINE_CONSTANT)) ** (1.0 / _LINE_EXP)
    d = bearing.element_diameter
    inner = LineContact(length, ep, 2.0 / d + 2.0 / bearing.inner_raceway_diameter, k)
    outer = LineContact(length, ep, 2.0 / d - 2.0 / bearing.outer_raceway_diameter, k)
    kn = float(combined_stiffness(k, k, exponent=1.0 / _LINE_EXP))
    return RollerContacts(inner, outer, kn)


# --------------------------------------------------------------------------------------------
# Validity of the Hertz solution
# --------------------------------------------------------------------------------------------
#: ISO 76 reference contact pressure of ball bearings [Pa]: at the centre of the most loaded
#: contact it leaves a permanent deformation of 1e-4 of the ball diameter.
ISO76_BALL_PRESSURE = 4.2e9
#: ISO 76 reference contact pressure of roller bearings [Pa].
ISO76_ROLLER_PRESSURE = 4.0e9
#: Maximum pressure whose mean (2/3 of it) exceeds the hardness of hardened bearing steel
#: (about 8 GPa, 60+ HRC) [Pa]: the contact is fully plastic, no elastic model applies.
PLASTIC_PRESSURE = 12.0e9


_RANK = {"warning": 0, "error": 1}


@dataclass(frozen=True)
class HertzFinding:
    """A Hertz contact outside the theory's validity.

    Attributes
    ----------
    severity : {"warning", "error"}
        ``"error"``: the contact cannot be elastic (ellipse as long as the element, mean
        pressure above the steel's hardness); ``"warning"``: beyond the ISO 76 static limit,
        permanent dents, the elastic results are optimistic.
    key : str
        Case key of the load that causes it.
    message : str
        What and how much, in one line.
    """

    severity: Literal["warning", "error"]
    key: str
    message: str


def _judge(
    key: str,
    what: str,
    pressure: float,
    half_size: float,
    element: float,
    reference: float,
    size_word: str,
) -> list[HertzFinding]:
    """The findings of one contact: half-size of the contact vs the element, pressure."""
    stated = (
        f"{what}: Hertz pressure {pressure / 1e9:.3g} GPa, contact {size_word} "
        f"{2e3 * half_size:.3g} mm on a {element * 1e3:.4g} mm element"
    )
    if not 2.0 * half_size < element:
        return [
            HertzFinding(
                "error",
                key,
                f"{stated}: the contact would be as large as the element itself, far outside "
                "Hertz theory (no such elastic contact exists)",
            )
        ]
    if not pressure < PLASTIC_PRESSURE:
        return [
            HertzFinding(
                "error",
                key,
                f"{stated}: the mean pressure exceeds the hardness of bearing steel "
                f"(maximum above {PLASTIC_PRESSURE / 1e9:.3g} GPa): a fully plastic contact, "
                "not an elastic one",
            )
        ]
    if pressure > reference:
        return [
            HertzFinding(
                "warning",
                key,
                f"{stated}: above the {reference / 1e9:.3g} GPa static limit of ISO 76 "
                "(permanent dents); the elastic results are optimistic",
            )
        ]
    return []


def ball_load_validity(
    bearing: BallBearing, load: float, contact_angle: float, key: str, what: str
) -> list[HertzFinding]:
    """Hertz validity of a ball loaded with ``load`` [N] at ``contact_angle`` [rad].

    Checks both raceway contacts: the semi-major axis a of the contact ellipse against the
    ball (2a >= D is no Hertz contact), and the maximum pressure against the hardness of the
    steel (error) and the ISO 76 static limit (warning).

    Parameters
    ----------
    bearing : BallBearing
        Geometry and material.
    load : float
        Normal ball load Q [N].
    contact_angle : float
        α [rad].
    key : str
        Case key of the load, for the findings.
    what : str
        The load in words (``"the most loaded ball, about 3.2e4 N"``).

    Returns
    -------
    list of HertzFinding
        The most severe finding of the two raceways (empty when the contact is valid or the
        load is not a finite positive force).
    """
    if not (math.isfinite(load) and load > 0.0):
        return []
    contacts = ball_race_contacts(bearing, contact_angle)
    worst: list[HertzFinding] = []
    for race, pc in (("inner", contacts.inner), ("outer", contacts.outer)):
        a, _ = pc.semi_axes(load)
        found = _judge(
            key,
            f"{what} ({race} raceway)",
            float(pc.max_pressure(load)),
            float(a),
            bearing.element_diameter,
            ISO76_BALL_PRESSURE,
            "ellipse length",
        )
        if found and (not worst or _RANK[found[0].severity] > _RANK[worst[0].severity]):
            worst = found
    return worst


def roller_load_validity(
    bearing: RollerBearing, load: float, key: str, what: str
) -> list[HertzFinding]:
    """Hertz validity of a roller loaded with ``load`` [N] (needs ``roller_length``).

    The line contact's width 2b against the roller diameter, and its maximum pressure against
    the steel's hardness (error) and the ISO 76 static limit of roller bearings (warning).

    Parameters
    ----------
    bearing : RollerBearing
        Geometry and material; without ``roller_length`` nothing is checked.
    load : float
        Roller load Q [N].
    key : str
        Case key of the load, for the findings.
    what : str
        The load in words.

    Returns
    -------
    list of HertzFinding
        The most severe finding of the two raceways (empty when the contact is valid, the
        roller length is unknown or the load is not a finite positive force).
    """
    if bearing.roller_length is None or not (math.isfinite(load) and load > 0.0):
        return []
    contacts = roller_race_contacts(bearing)
    worst: list[HertzFinding] = []
    for race, lc in (("inner", contacts.inner), ("outer", contacts.outer)):
        found = _judge(
            key,
            f"{what} ({race} raceway)",
            float(lc.max_pressure(load)),
            float(lc.semi_width(load)),
            bearing.element_diameter,
            ISO76_ROLLER_PRESSURE,
            "width",
        )
        if found and (not worst or _RANK[found[0].severity] > _RANK[worst[0].severity]):
            worst = found
    return worst
