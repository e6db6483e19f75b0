r"""Reference rating life L10r of a ball bearing from its load distribution (ISO/TS 16281:2008).

ISO/TS 16281:2008 computes the basic reference rating life of a bearing from the loads of its
rolling elements (a load distribution such as the equilibrium model's) instead of ISO 281's
equivalent bearing load: each raceway contact has a basic dynamic load rating, each raceway an
equivalent rolling-element load, each ring a life, and the two lives combine into the
bearing's. The equation numbers below are those the open implementation of the TS
(github.com/minzhun/ISO16281, ``BallBearing.py``) gives its functions; its test suite
(``Test_BallBearing.py``) quotes MASTA's L10r for seven load cases, which
``tests/reference/test_iso_ts_16281_life.py`` reproduces through ``runout run``.

Contact ratings (TS eq. 19-24, radial ball bearing of i rows). With the nominal contact angle
α, :math:`\gamma = D\cos\alpha/d_m`, the conformities :math:`f_i, f_e` and
:math:`\Gamma = ((1-\gamma)/(1+\gamma))^{1.72}\,(f_i(2f_e-1)/(f_e(2f_i-1)))^{0.41}`, the
rolling-element load for the basic dynamic load rating of the inner and the outer ring
contact follows from the bearing's basic dynamic load rating C:

.. math::
    Q_{ci} = \frac{C}{0.407\,Z\,(i\cos\alpha)^{0.7}}
             \big[1 + (1.044\,\Gamma)^{10/3}\big]^{0.3},\qquad
    Q_{ce} = \frac{C}{0.389\,Z\,(i\cos\alpha)^{0.7}}
             \big[1 + (1.044\,\Gamma)^{-10/3}\big]^{0.3}.

(0.407 and 0.389 are Lundberg and Palmgren's ratios of the radial load to Z times the cubic
and the 10/3-power mean ball load of a radially loaded bearing with half its balls loaded.)

Equivalent rolling-element loads (TS eq. 25-28). A raceway point of the ring that turns
relative to the load meets every ball load (cubic mean, the ball-contact life exponent 3); a
point of the ring that stands still under the load keeps its own, and the ring's survival
combines its points with the Weibull exponent e = 10/9 (the 3e = 10/3-power mean):

.. math::
    Q_{e,\mathrm{rot}} = \Big(\frac1Z\sum_j Q_j^3\Big)^{1/3},\qquad
    Q_{e,\mathrm{fix}} = \Big(\frac1Z\sum_j Q_j^{10/3}\Big)^{3/10}.

Lives (TS eq. 29), in millions of revolutions of one ring relative to the other:

.. math::
    L_{10ri} = (Q_{ci}/Q_{ei})^3,\quad L_{10re} = (Q_{ce}/Q_{ee})^3,\quad
    L_{10r} = \big(L_{10ri}^{-e} + L_{10re}^{-e}\big)^{-1/e},\ e = 10/9,

and the dynamic equivalent reference load :math:`P_{ref} = C\,L_{10r}^{-1/3}`.

Notes
-----
* α is the *nominal* contact angle of the rating (ISO 281): 0 for a deep-groove bearing whose
  angle comes from its play only, the catalogue angle of an angular-contact bearing. The
  operating contact angles enter only through the ball loads. MASTA's deep-groove cases with
  10 µm play are rated at α = 0: the free contact angle of that play (7.6°) would raise the
  lives by 1.9 %.
* The TS's ball loads come from a static load distribution. A caller at speed passes each
  ring its own contact loads (the outer ones carry the balls' centrifugal force): that is an
  extension of the TS, which the caller states.
* Not covered: contacts truncated by the groove shoulders, and thrust bearings (nominal
  α > 45°, whose TS formulas differ).

Modified reference rating life (ISO/TS 16281:2008 with ISO 281:2007's factors):
:math:`L_{nmr} = a_1\,a_{ISO}\,L_{10r}` (:func:`modified_reference_life`). a_1 is ISO 281's
reliability factor (:data:`RELIABILITY_FACTORS`, 90 to 99.95 %); a_ISO is ISO 281's life
modification factor of a radial ball bearing (:func:`life_modification_factor`) from the
viscosity ratio κ, the contamination factor e_C, the fatigue load limit C_u and, for the TS,
the dynamic equivalent reference load P_ref (the load that gives L10r through ISO 281's
:math:`L_{10} = (C/P)^3`):

.. math::
    a_{ISO} = 0.1\Big[1 - \big(2.5671 - c_1\,\kappa^{-c_2}\big)^{0.83}
              \Big(\frac{e_C C_u}{P_{ref}}\Big)^{1/3}\Big]^{-9.3},\quad
    (c_1, c_2) = \begin{cases}
        (2.2649, 0.054381) & 0.1 \le \kappa < 0.4\\
        (1.9987, 0.19087) & 0.4 \le \kappa < 1\\
        (1.9987, 0.071739) & 1 \le \kappa \le 4,
    \end{cases}

capped at 50; ISO 281 takes κ > 4 as 4 and gives no a_ISO below κ = 0.1. The constants are
those two open implementations of ISO 281:2007 use (one of them misprints 0.19087 as
0.019087). The rated viscosity, when κ is formed from the operating viscosity ν, is ISO 281's
:math:`\nu_1 = 45000\,n^{-0.83} D_{pw}^{-0.5}` for n < 1000 r/min and
:math:`4500\,n^{-0.5} D_{pw}^{-0.5}` above [mm²/s, n in r/min, D_pw in mm]
(:func:`rated_viscosity`).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from runout.base.errors import GeometryError

__all__ = [
    "A_ISO_CAP",
    "ISO281_BM_BALL",
    "ISO281_FC_BALL",
    "LIFE_EXPONENT",
    "MAX_DYNAMIC_LOAD_RATING",
    "MAX_RADIAL_CONTACT_ANGLE",
    "MAX_VISCOSITY_RATIO",
    "METHOD",
    "MIN_VISCOSITY_RATIO",
    "RELIABILITY_FACTORS",
    "WEIBULL_EXPONENT",
    "RatingLife",
    "basic_dynamic_load_rating",
    "contact_load_ratings",
    "equivalent_element_loads",
    "life_modification_factor",
    "modified_reference_life",
    "rated_viscosity",
    "reference_rating_life",
    "reliability_factor",
]

#: Life exponent of a ball (point) contact, L = (Q_c / Q_e)^3 [-].
LIFE_EXPONENT = 3.0
#: Weibull slope e of ball bearings; the rings' lives combine as (L_i^-e + L_e^-e)^(-1/e) [-].
WEIBULL_EXPONENT = 10.0 / 9.0
#: Largest ``dynamic_load_rating`` read [N]: the largest slewing bearings are rated at a few
#: tens of MN.
MAX_DYNAMIC_LOAD_RATING = 1e9
#: Largest nominal contact angle of a radial ball bearing (ISO 281) [rad]; beyond it the TS
#: rates a thrust ball bearing with other formulas.
MAX_RADIAL_CONTACT_ANGLE = math.radians(45.0)
#: Largest life modification factor a_ISO (ISO 281:2007) [-].
A_ISO_CAP = 50.0
#: Smallest viscosity ratio κ for which ISO 281:2007 gives a_ISO [-].
MIN_VISCOSITY_RATIO = 0.1
#: Viscosity ratio beyond which ISO 281:2007 takes κ = 4 [-].
MAX_VISCOSITY_RATIO = 4.0
#: ISO 281:2007's life modification factor for reliability a_1 by reliability [%] (its
#: table; 90 % is the basic rating life's).
RELIABILITY_FACTORS: dict[float, float] = {
    90.0: 1.0,
    95.0: 0.64,
    96.0: 0.55,
    97.0: 0.47,
    98.0: 0.37,
    99.0: 0.25,
    99.2: 0.22,
    99.4: 0.19,
    99.6: 0.16,
    99.8: 0.12,
    99.9: 0.093,
    99.92: 0.087,
    99.94: 0.08,
    99.95: 0.077,
}
# a_ISO constants of a radial ball bearing (module docstring): upper κ of the range, c_1, c_2
_A_ISO_RANGES = ((0.4, 2.2649, 0.054381), (1.0, 1.9987, 0.19087), (math.inf, 1.9987, 0.071739))
#: The method, as the JSON ``life.method`` names it.
METHOD = "ISO/TS 16281:2008 basic reference rating life (radial ball bearing, eq. 19-29)"


#: ISO 281:2007 Table 2, the factor f_c of single-row radial (deep groove) and angular contact
#: ball bearings against D_w cos(alpha) / D_pw = 0.01, 0.02, ..., 0.40 [-].
ISO281_FC_BALL = (
    29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
    56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,
    59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,
    55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4,
)  # fmt: skip
#: ISO 281:2007's b_m of radial deep-groove and angular-contact ball bearings [-].
ISO281_BM_BALL = 1.3


def basic_dynamic_load_rating(
    elements: int,
    element_diameter: float,
    pitch_diameter: float,
    nominal_contact_angle: float = 0.0,
    rows: int = 1,
) -> float:
    r"""ISO 281:2007's basic dynamic radial load rating C_r of a radial ball bearing.

    Parameters
    ----------
    elements : int
        Balls per row Z.
    element_diameter : float
        Ball diameter D_w [m].
    pitch_diameter : float
        Pitch diameter D_pw [m].
    nominal_contact_angle : float
        Nominal contact angle alpha [rad]: 0 for a deep-groove bearing.
    rows : int
        Rows of balls i.

    Returns
    -------
    float
        C_r [N].

    Raises
    ------
    GeometryError
        ``element_diameter``: D_w cos(alpha) / D_pw outside Table 2's 0.01 ... 0.40.

    Notes
    -----
    ISO 281:2007, Rolling bearings -- Dynamic load ratings and rating life, eq. (2) of
    section 6.1.1 (lengths in mm, C_r in N):

    .. math::
        C_r = b_m f_c (i\cos\alpha)^{0.7} Z^{2/3} D_w^{1.8}\quad(D_w \le 25.4\ \mathrm{mm}),
        \qquad C_r = 3.647\, b_m f_c (i\cos\alpha)^{0.7} Z^{2/3} D_w^{1.4}\quad(D_w > 25.4),

    with b_m = 1.3 (Table 1, radial deep-groove and angular-contact ball bearings) and f_c
    from Table 2 (the column of single-row radial and of angular-contact groove ball
    bearings), interpolated linearly in D_w cos(alpha) / D_pw (the standard's own rule).
    The f_c values of :data:`ISO281_FC_BALL` were checked against two independent public
    implementations of the table (a Python deep-groove design script and a JavaScript
    load-rating calculator), which agree with each other entry by entry; the rating
    reproduces the catalogue values of makers within a few per cent where the internal
    geometry is the maker's (docs/designation.md).
    """
    d_w = element_diameter * 1e3
    ratio = d_w * math.cos(nominal_contact_angle) / (pitch_diameter * 1e3)
    if not 0.01 <= ratio <= 0.40:
        raise GeometryError(
            "element_diameter",
            f"D_w cos(alpha) / D_pw = {ratio:.4g} is outside ISO 281's f_c table (0.01 to 0.4)",
        )
    position = ratio / 0.01 - 1.0
    low = min(int(position), len(ISO281_FC_BALL) - 2)
    f_c = ISO281_FC_BALL[low] + (position - low) * (ISO281_FC_BALL[low + 1] - ISO281_FC_BALL[low])
    common = ISO281_BM_BALL * f_c * (rows * math.cos(nominal_contact_angle)) ** 0.7
    common *= elements ** (2.0 / 3.0)
    if d_w <= 25.4:
        return common * d_w**1.8
    return 3.647 * common * d_w**1.4


def contact_load_ratings(
    elements: int,
    element_diameter: float,
    pitch_diameter: float,
    inner_conformity: float,
    outer_conformity: float,
    nominal_contact_angle: float,
    dynamic_load_rating: float,
    rows: int = 1,
) -> tuple[float, float]:
    r"""Rolling-element loads of the basic dynamic load ratings of the two raceway contacts.

    Parameters
    ----------
    elements : int
        Number of balls per row Z [-].
    element_diameter : float
        Ball diameter D [m].
    pitch_diameter : float
        Pitch diameter d_m [m].
    inner_conformity, outer_conformity : float
        Groove radius over ball diameter f_i, f_e [-] (> 0.5).
    nominal_contact_angle : float
        Nominal contact angle α of the rating [rad], in [0, 45°].
    dynamic_load_rating : float
        Basic dynamic (radial) load rating C of the bearing [N].
    rows : int
        Number of rows i [-].

    Returns
    -------
    q_ci, q_ce : float
        Q_ci and Q_ce [N] (module docstring).

    Raises
    ------
    GeometryError
        A nominal contact angle beyond 45° (a thrust bearing) or a rating that is not a
        positive finite number.

    Notes
    -----
    ISO/TS 16281:2008 eq. 19-24 (radial ball bearing), as numbered by the open implementation
    github.com/minzhun/ISO16281; Lundberg and Palmgren's 0.407 and 0.389.
    """
    if not 0.0 <= nominal_contact_angle <= MAX_RADIAL_CONTACT_ANGLE:
        raise GeometryError(
            "bearing.nominal_contact_angle",
            f"{math.degrees(nominal_contact_angle):.6g} deg: the reference rating life is "
            "computed for radial ball bearings (nominal contact angle 0 to 45 deg)",
        )
    if not (math.isfinite(dynamic_load_rating) and dynamic_load_rating > 0.0):
        raise GeometryError(
            "bearing.dynamic_load_rating",
            f"must be a positive finite number, got {dynamic_load_rating!r}",
        )
    gamma = element_diameter * math.cos(nominal_contact_angle) / pitch_diameter
    f_i, f_e = inner_conformity, outer_conformity
    ratio = ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * (
        f_i * (2.0 * f_e - 1.0) / (f_e * (2.0 * f_i - 1.0))
    ) ** 0.41
    base = dynamic_load_rating / (elements * (rows * math.cos(nominal_contact_angle)) ** 0.7)
    q_ci = base / 0.407 * (1.0 + (1.044 * ratio) ** (10.0 / 3.0)) ** 0.3
    q_ce = base / 0.389 * (1.0 + (1.044 * ratio) ** (-10.0 / 3.0)) ** 0.3
    return q_ci, q_ce


def _power_mean(loads: np.ndarray, power: float) -> float:
    """(mean of Q^p)^(1/p) [N], scaled by the largest load so that no power overflows."""
    top = float(loads.max(initial=0.0))
    if top == 0.0:
        return 0.0
    return top * float(np.mean((loads / top) ** power)) ** (1.0 / power)


def equivalent_element_loads(
    inner_loads: ArrayLike,
    outer_loads: ArrayLike,
    rotating_ring: Literal["inner", "outer"] = "inner",
) -> tuple[float, float]:
    """Dynamic equivalent rolling-element loads of the inner and the outer raceway [N].

    Parameters
    ----------
    inner_loads, outer_loads : array_like, shape (Z,)
        Contact load of every ball on the inner and on the outer raceway [N] (0 for a ball
        without load; every ball of the row counts in the means).
    rotating_ring : {"inner", "outer"}
        The ring that turns relative to the load: its raceway takes the cubic mean, the other
        the 10/3-power mean.

    Returns
    -------
    q_ei, q_ee : float
        Q_ei and Q_ee [N].

    Raises
    ------
    GeometryError
        Loads that are negative, not finite, or not one per ball on each ring.

    Notes
    -----
    ISO/TS 16281:2008 eq. 25-28 (numbering of github.com/minzhun/ISO16281).
    """
    q_i = np.asarray(inner_loads, dtype=float)
    q_e = np.asarray(outer_loads, dtype=float)
    if q_i.ndim != 1 or q_i.shape != q_e.shape or q_i.size == 0:
        raise GeometryError("loads", "need one inner and one outer load per ball")
    for name, q in (("inner_load", q_i), ("outer_load", q_e)):
        if not (np.all(np.isfinite(q)) and np.all(q >= 0.0)):
            raise GeometryError(name, "ball loads must be finite and >= 0")
    if rotating_ring not in ("inner", "outer"):
        raise GeometryError(
            "operation.rotating_ring", f'must be "inner" or "outer", got {rotating_ring!r}'
        )
    turning = LIFE_EXPONENT
    standing = LIFE_EXPONENT * WEIBULL_EXPONENT
    p_i, p_e = (turning, standing) if rotating_ring == "inner" else (standing, turning)
    return _power_mean(q_i, p_i), _power_mean(q_e, p_e)


def _log_life(rating: float, load: float) -> float | None:
    """ln of (Q_c / Q_e)^3 [ln 10^6 rev]; None for an unloaded raceway (unbounded life)."""
    if load == 0.0:
        return None
    return LIFE_EXPONENT * (math.log(rating) - math.log(load))


def _exp(log_value: float | None) -> float | None:
    """exp(log_value), None beyond the floating-point range or for None."""
    if log_value is None or log_value > 700.0:
        return None
    return math.exp(log_value)


@dataclass(frozen=True)
class RatingLife:
    """The reference rating life of a ball bearing and the quantities it is made of.

    Attributes
    ----------
    l10r_mrev : float or None
        Basic reference rating life L10r [10^6 revolutions of one ring relative to the
        other]; None when it exceeds the floating-point range (a bearing all but unloaded).
    l10r_inner_mrev, l10r_outer_mrev : float or None
        The inner and the outer ring's lives [10^6 rev]; None for a raceway without load or
        beyond the floating-point range.
    equivalent_inner_load_n, equivalent_outer_load_n : float
        Dynamic equivalent rolling-element loads Q_ei, Q_ee [N].
    inner_contact_rating_n, outer_contact_rating_n : float
        Rolling-element loads of the basic dynamic load ratings Q_ci, Q_ce [N].
    dynamic_load_rating_n : float
        The bearing's basic dynamic load rating C [N].
    equivalent_reference_load_n : float or None
        Dynamic equivalent reference load P_ref = C L10r^(-1/3) [N] (None with L10r).
    nominal_contact_angle_deg : float
        Nominal contact angle α of the rating [deg].
    rotating_ring : {"inner", "outer"}
        The ring taken as turning relative to the load.
    l10r_hours : float or None
        L10r in hours at the run's relative ring speed [h]; None at rest.
    method : str
        The standard and equations (:data:`METHOD`).
    reliability_percent, a1 : float or None
        Reliability of the modified life [%] and ISO 281's factor a_1 for it [-].
    viscosity_ratio : float or None
        The viscosity ratio κ a_ISO was evaluated at (κ > 4 taken as 4) [-].
    contamination_factor : float or None
        e_C [-].
    fatigue_load_limit_n : float or None
        C_u [N].
    a_iso : float or None
        ISO 281's life modification factor a_ISO [-] (at P_ref).
    lnmr_mrev, lnmr_hours : float or None
        Modified reference rating life L_nmr = a_1 a_ISO L10r [10^6 rev] and in hours [h].
        All of these are None when the modified life is not asked for or cannot be formed
        (the notes say why).
    """

    l10r_mrev: float | None
    l10r_inner_mrev: float | None
    l10r_outer_mrev: float | None
    equivalent_inner_load_n: float
    equivalent_outer_load_n: float
    inner_contact_rating_n: float
    outer_contact_rating_n: float
    dynamic_load_rating_n: float
    equivalent_reference_load_n: float | None
    nominal_contact_angle_deg: float
    rotating_ring: str
    l10r_hours: float | None = None
    method: str = METHOD
    reliability_percent: float | None = None
    a1: float | None = None
    viscosity_ratio: float | None = None
    contamination_factor: float | None = None
    fatigue_load_limit_n: float | None = None
    a_iso: float | None = None
    lnmr_mrev: float | None = None
    lnmr_hours: float | None = None

    def to_json(self) -> dict[str, Any]:
        """JSON ``life``.

        Returns
        -------
        dict
            Every attribute under its own name (SI, unit in the key; lives in 10^6 rev).
        """
        return {
            "l10r_mrev": self.l10r_mrev,
            "l10r_inner_mrev": self.l10r_inner_mrev,
            "l10r_outer_mrev": self.l10r_outer_mrev,
            "equivalent_inner_load_n": self.equivalent_inner_load_n,
            "equivalent_outer_load_n": self.equivalent_outer_load_n,
            "inner_contact_rating_n": self.inner_contact_rating_n,
            "outer_contact_rating_n": self.outer_contact_rating_n,
            "dynamic_load_rating_n": self.dynamic_load_rating_n,
            "equivalent_reference_load_n": self.equivalent_reference_load_n,
            "nominal_contact_angle_deg": self.nominal_contact_angle_deg,
            "rotating_ring": self.rotating_ring,
            "l10r_hours": self.l10r_hours,
            "method": self.method,
            "reliability_percent": self.reliability_percent,
            "a1": self.a1,
            "viscosity_ratio": self.viscosity_ratio,
            "contamination_factor": self.contamination_factor,
            "fatigue_load_limit_n": self.fatigue_load_limit_n,
            "a_iso": self.a_iso,
            "lnmr_mrev": self.lnmr_mrev,
            "lnmr_hours": self.lnmr_hours,
        }

    @classmethod
    def from_json(cls, doc: Mapping[str, Any]) -> RatingLife:
        """Read :meth:`to_json` back.

        Parameters
        ----------
        doc : mapping
            The JSON ``life`` object.

        Returns
        -------
        RatingLife
        """

        def number(key: str) -> float | None:
            value = doc.get(key)
            return None if value is None else float(value)

        return cls(
            l10r_mrev=number("l10r_mrev"),
            l10r_inner_mrev=number("l10r_inner_mrev"),
            l10r_outer_mrev=number("l10r_outer_mrev"),
            equivalent_inner_load_n=float(doc["equivalent_inner_load_n"]),
            equivalent_outer_load_n=float(doc["equivalent_outer_load_n"]),
            inner_contact_rating_n=float(doc["inner_contact_rating_n"]),
            outer_contact_rating_n=float(doc["outer_contact_rating_n"]),
            dynamic_load_rating_n=float(doc["dynamic_load_rating_n"]),
            equivalent_reference_load_n=number("equivalent_reference_load_n"),
            nominal_contact_angle_deg=float(doc["nominal_contact_angle_deg"]),
            rotating_ring=str(doc["rotating_ring"]),
            l10r_hours=number("l10r_hours"),
            method=str(doc.get("method", METHOD)),
            # results written before the modified life existed: none
            reliability_percent=number("reliability_percent"),
            a1=number("a1"),
            viscosity_ratio=number("viscosity_ratio"),
            contamination_factor=number("contamination_factor"),
            fatigue_load_limit_n=number("fatigue_load_limit_n"),
            a_iso=number("a_iso"),
            lnmr_mrev=number("lnmr_mrev"),
            lnmr_hours=number("lnmr_hours"),
        )


def reference_rating_life(
    *,
    elements: int,
    element_diameter: float,
    pitch_diameter: float,
    inner_conformity: float,
    outer_conformity: float,
    nominal_contact_angle: float,
    dynamic_load_rating: float,
    inner_loads: ArrayLike,
    outer_loads: ArrayLike,
    rotating_ring: Literal["inner", "outer"] = "inner",
    relative_speed: float = 0.0,
) -> RatingLife:
    r"""ISO/TS 16281 basic reference rating life L10r of a single-row radial ball bearing.

    Parameters
    ----------
    elements : int
        Number of balls Z [-].
    element_diameter : float
        Ball diameter D [m].
    pitch_diameter : float
        Pitch diameter d_m [m].
    inner_conformity, outer_conformity : float
        f_i, f_e [-].
    nominal_contact_angle : float
        Nominal contact angle α of the rating [rad] (0 for a deep-groove bearing).
    dynamic_load_rating : float
        Basic dynamic load rating C [N].
    inner_loads, outer_loads : array_like, shape (Z,)
        Contact loads of every ball on the inner and the outer raceway [N].
    rotating_ring : {"inner", "outer"}
        The ring that turns relative to the load.
    relative_speed : float
        Speed of one ring relative to the other [Hz], for ``l10r_hours``; 0: none.

    Returns
    -------
    RatingLife
        L10r and the ring lives [10^6 rev], the equivalent loads and contact ratings [N].

    Raises
    ------
    GeometryError
        No ball load on either raceway, negative or non-finite loads, a rating that is not
        a positive finite number, or a nominal contact angle beyond 45°.

    Notes
    -----
    ISO/TS 16281:2008 eq. 19-29 (numbering of the open implementation
    github.com/minzhun/ISO16281); the module docstring gives the formulas.
    """
    q_ci, q_ce = contact_load_ratings(
        elements,
        element_diameter,
        pitch_diameter,
        inner_conformity,
        outer_conformity,
        nominal_contact_angle,
        dynamic_load_rating,
    )
    q_ei, q_ee = equivalent_element_loads(inner_loads, outer_loads, rotating_ring)
    if q_ei == 0.0 and q_ee == 0.0:
        raise GeometryError("loads", "no ball carries load: the bearing has no finite life")
    log_i = _log_life(q_ci, q_ei)
    log_e = _log_life(q_ce, q_ee)
    # L^-e summed in logarithms: a lightly loaded ring's L^-e underflows long before L does;
    # an unloaded raceway (unbounded life) adds nothing
    e = WEIBULL_EXPONENT
    logs = np.array([-e * v for v in (log_i, log_e) if v is not None])
    log_life = -float(np.logaddexp.reduce(logs)) / e
    life = _exp(log_life)
    p_ref = None if life is None else dynamic_load_rating * math.exp(-log_life / LIFE_EXPONENT)
    hours = None
    if life is not None and relative_speed != 0.0:
        hours = life * 1e6 / (abs(relative_speed) * 3600.0)
    return RatingLife(
        l10r_mrev=life,
        l10r_inner_mrev=_exp(log_i),
        l10r_outer_mrev=_exp(log_e),
        equivalent_inner_load_n=q_ei,
        equivalent_outer_load_n=q_ee,
        inner_contact_rating_n=q_ci,
        outer_contact_rating_n=q_ce,
        dynamic_load_rating_n=float(dynamic_load_rating),
        equivalent_reference_load_n=p_ref,
        nominal_contact_angle_deg=math.degrees(nominal_contact_angle),
        rotating_ring=rotating_ring,
        l10r_hours=hours,
    )


def reliability_factor(reliability_percent: float) -> float:
    """ISO 281:2007's life modification factor for reliability a_1.

    Parameters
    ----------
    reliability_percent : float
        Reliability [%]: one of the table's values, 90 to 99.95.

    Returns
    -------
    float
        a_1 [-] (1 at 90 %).

    Raises
    ------
    GeometryError
        A reliability that is not in the table (ISO 281 gives no values between its rows).

    Notes
    -----
    ISO 281:2007, the table of a_1 (:data:`RELIABILITY_FACTORS`).
    """
    for percent, factor in RELIABILITY_FACTORS.items():
        if reliability_percent == percent:
            return factor
    rows = ", ".join(f"{p:g}" for p in RELIABILITY_FACTORS)
    raise GeometryError(
        "analysis.reliability",
        f"{reliability_percent!r} %: ISO 281 gives a_1 for {rows} % only",
    )


def life_modification_factor(
    viscosity_ratio: float,
    contamination_factor: float,
    fatigue_load_limit: float,
    load: float,
) -> float:
    r"""ISO 281:2007 life modification factor a_ISO of a radial ball bearing.

    Parameters
    ----------
    viscosity_ratio : float
        κ = ν/ν_1 [-], >= 0.1; above 4 it is taken as 4.
    contamination_factor : float
        e_C [-], 0 to 1.
    fatigue_load_limit : float
        C_u [N], >= 0.
    load : float
        Dynamic equivalent load P [N] (P_ref for ISO/TS 16281), > 0.

    Returns
    -------
    float
        a_ISO [-], from 0.1 (e_C C_u / P = 0) up to :data:`A_ISO_CAP` (50); increasing in κ
        (up to 4), e_C and C_u, decreasing in P.

    Raises
    ------
    GeometryError
        κ below 0.1 (outside ISO 281's a_ISO), e_C outside [0, 1], a negative C_u or a load
        that is not positive; any input not finite.

    Notes
    -----
    ISO 281:2007, a_ISO of radial ball bearings, its three κ ranges (module docstring). The
    bracket reaches 0 at a finite e_C C_u / P, beyond which a_ISO would be unbounded: the cap
    holds it at 50 there.
    """
    for key, value in (
        ("viscosity_ratio", viscosity_ratio),
        ("contamination_factor", contamination_factor),
        ("fatigue_load_limit", fatigue_load_limit),
        ("load", load),
    ):
        if not math.isfinite(value):
            raise GeometryError(key, f"must be finite, got {value!r}")
    if viscosity_ratio < MIN_VISCOSITY_RATIO:
        raise GeometryError(
            "lubrication.viscosity_ratio",
            f"{viscosity_ratio:.6g}: ISO 281 gives no a_ISO below κ = {MIN_VISCOSITY_RATIO:g}",
        )
    if not 0.0 <= contamination_factor <= 1.0:
        raise GeometryError(
            "lubrication.contamination_factor", f"must lie in [0, 1], got {contamination_factor!r}"
        )
    if fatigue_load_limit < 0.0:
        raise GeometryError(
            "bearing.fatigue_load_limit", f"must be >= 0, got {fatigue_load_limit!r}"
        )
    if not load > 0.0:
        raise GeometryError("load", f"must be > 0, got {load!r}")
    kappa = min(viscosity_ratio, MAX_VISCOSITY_RATIO)
    c1, c2 = next((c1, c2) for top, c1, c2 in _A_ISO_RANGES if kappa < top)
    ratio = contamination_factor * fatigue_load_limit / load
    bracket = 1.0 - (2.5671 - c1 * kappa**-c2) ** 0.83 * ratio ** (1.0 / 3.0)
    # 0.1 bracket^-9.3 >= 50 where bracket <= (500)^(-1/9.3); below it (or <= 0) the cap
    if bracket <= (A_ISO_CAP / 0.1) ** (-1.0 / 9.3):
        return A_ISO_CAP
    return 0.1 * bracket**-9.3


def rated_viscosity(relative_speed: float, pitch_diameter: float) -> float:
    r"""ISO 281:2007's rated (reference) kinematic viscosity ν_1 of the lubricant.

    Parameters
    ----------
    relative_speed : float
        Speed of one ring relative to the other [Hz] (its size is used), > 0.
    pitch_diameter : float
        D_pw [m], > 0.

    Returns
    -------
    float
        ν_1 [m²/s].

    Raises
    ------
    GeometryError
        At rest (ν_1 is defined for a turning bearing).

    Notes
    -----
    ISO 281:2007: :math:`\nu_1 = 45000\,n^{-0.83} D_{pw}^{-0.5}` for n < 1000 r/min,
    :math:`4500\,n^{-0.5} D_{pw}^{-0.5}` from 1000 r/min [mm²/s; n in r/min, D_pw in mm].
    """
    rpm = 60.0 * abs(relative_speed)
    if not (math.isfinite(rpm) and rpm > 0.0):
        raise GeometryError(
            "lubrication.operating_viscosity",
            "the rated viscosity ν_1 needs a turning bearing (operation.speed > 0); give "
            "lubrication.viscosity_ratio instead",
        )
    d_mm = pitch_diameter * 1e3
    nu1_mm2_s = (
        45000.0 * rpm**-0.83 * d_mm**-0.5 if rpm < 1000.0 else 4500.0 * rpm**-0.5 * d_mm**-0.5
    )
    return nu1_mm2_s * 1e-6


def modified_reference_life(
    life: RatingLife,
    *,
    reliability_percent: float = 90.0,
    viscosity_ratio: float | None = None,
    contamination_factor: float | None = None,
    fatigue_load_limit: float | None = None,
) -> tuple[RatingLife, list[str]]:
    """The life with ISO 281's a_1 and a_ISO applied: L_nmr = a_1 a_ISO L10r.

    Parameters
    ----------
    life : RatingLife
        The reference rating life (:func:`reference_rating_life`).
    reliability_percent : float
        Reliability [%] (a row of :data:`RELIABILITY_FACTORS`).
    viscosity_ratio, contamination_factor, fatigue_load_limit : float or None
        κ [-], e_C [-], C_u [N]; all three are needed for a_ISO.

    Returns
    -------
    life : RatingLife
        ``life`` with the modified-life fields filled (a_ISO and L_nmr None when an input is
        missing, κ < 0.1 or L10r is beyond the floating-point range).
    notes : list of str
        What was assumed or why there is no L_nmr.

    Notes
    -----
    ISO/TS 16281:2008 with ISO 281:2007: a_ISO is evaluated at the dynamic equivalent
    reference load P_ref = C L10r^(-1/3).
    """
    a1 = reliability_factor(reliability_percent)
    out = dataclasses.replace(life, reliability_percent=reliability_percent, a1=a1)
    given = {
        "lubrication.viscosity_ratio (or operating_viscosity)": viscosity_ratio,
        "lubrication.contamination_factor": contamination_factor,
        "bearing.fatigue_load_limit": fatigue_load_limit,
    }
    missing = [key for key, value in given.items() if value is None]
    if missing:
        if len(missing) == len(given):
            return out, []
        return out, ["life: no modified life L_nmr: a_ISO needs " + ", ".join(missing) + " as well"]
    assert viscosity_ratio is not None
    assert contamination_factor is not None
    assert fatigue_load_limit is not None
    out = dataclasses.replace(
        out, contamination_factor=contamination_factor, fatigue_load_limit_n=fatigue_load_limit
    )
    if viscosity_ratio < MIN_VISCOSITY_RATIO:
        return dataclasses.replace(out, viscosity_ratio=viscosity_ratio), [
            f"life: no modified life L_nmr: the viscosity ratio κ = {viscosity_ratio:.4g} is "
            f"below {MIN_VISCOSITY_RATIO:g}, where ISO 281 gives no a_ISO (the lubricant film "
            "does not separate the surfaces)"
        ]
    p_ref = life.equivalent_reference_load_n
    if p_ref is None or life.l10r_mrev is None:
        return dataclasses.replace(out, viscosity_ratio=viscosity_ratio), [
            "life: no modified life L_nmr: L10r is beyond the floating-point range"
        ]
    notes = []
    kappa = viscosity_ratio
    if kappa > MAX_VISCOSITY_RATIO:
        notes.append(
            f"life: viscosity ratio κ = {kappa:.4g} taken as {MAX_VISCOSITY_RATIO:g} in a_ISO, "
            "as ISO 281 prescribes"
        )
        kappa = MAX_VISCOSITY_RATIO
    a_iso = life_modification_factor(kappa, contamination_factor, fatigue_load_limit, p_ref)
    if a_iso == A_ISO_CAP:
        notes.append(f"life: a_ISO reached ISO 281's cap {A_ISO_CAP:g}")
    lnmr = a1 * a_iso * life.l10r_mrev
    hours = None if life.l10r_hours is None else a1 * a_iso * life.l10r_hours
    notes.append(
        f"life: modified reference rating life L_nmr = a_1 a_ISO L10r (ISO 281:2007 factors, "
        f"a_ISO of a radial ball bearing at P_ref = {p_ref:.6g} N): a_1 = {a1:g} "
        f"({reliability_percent:g} % reliability), a_ISO = {a_iso:.4g}"
    )
    return (
        dataclasses.replace(
            out, viscosity_ratio=kappa, a_iso=a_iso, lnmr_mrev=lnmr, lnmr_hours=hours
        ),
        notes,
    )
