"""Ball grades (ISO 3290-1) and tolerance classes of radial bearings (ISO 492) as data.

``[elements] grade`` and ``[study.vary] ball_grade`` name an ISO 3290-1 grade of steel balls
(``"G5"``); ``[analysis] limit`` may name an ISO 492 tolerance class (``"P4"``) whose radial
runout of the assembled bearing inner ring K_ia, for the bearing's bore, is the spec limit.
Every value is the standard's tabulated one in micrometres, stored as written and returned
in SI.

Sources
-------
* ISO 3290-1:2014, Rolling bearings - Balls - Part 1: Steel balls: the table of form and
  surface roughness tolerances (V_DWs, t_Dw, Ra) and the table of sorting tolerances and
  gauges (V_DWL, gauge interval I_G), grades G3 to G200. Grade G80 of older editions and of
  ABMA/ISO 3290 tables is not in the 2014 table and is not listed here.
* ISO 492:2014, Rolling bearings - Radial bearings - Geometrical product specifications
  (GPS) and tolerance values: the inner ring tables of the Normal class and classes 6, 5, 4
  and 2 (P6, P5, P4, P2 in maker's notation), column K_ia (radial runout of the assembled
  bearing inner ring), bores 2.5 mm < d <= 120 mm.

The ISO 3290-1 values were checked against two ball makers' reproductions of its tables. Every
K_ia value up to 80 mm and the Normal, P6, P5 and P2 values from 80 to 120 mm were checked
against bearing makers' reproductions; the P4 value from 80 to 120 mm was written down by two
engineers independently from makers' tables (they agree) and is not yet compared with a
reproduction (docs/studies.md says so).
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass

__all__ = [
    "BALL_GRADES",
    "DEFAULT_GRADE_SIGMA_DIVISOR",
    "ISO_492_SOURCE",
    "ISO_3290_SOURCE",
    "KIA_BORE_EDGES_MM",
    "KIA_UM",
    "TOLERANCE_CLASSES",
    "BallGrade",
    "ClassLimit",
    "StandardsError",
    "ball_grade",
    "class_limit",
    "grade_form_amplitude",
    "grade_sigma",
    "is_class_name",
]

#: Citation of the ball grade values.
ISO_3290_SOURCE = (
    "ISO 3290-1:2014 (steel balls), tables of form and surface roughness tolerances and of "
    "sorting tolerances and gauges"
)
#: Citation of the K_ia values.
ISO_492_SOURCE = (
    "ISO 492:2014 (radial bearings), inner ring tolerance table of the class, K_ia (radial "
    "runout of the assembled bearing inner ring)"
)

#: Lot diameter variation V_DWL taken as this many standard deviations of the balls' diameters
#: (the range of a lot of normal diameters within +-3 sigma: a lot that meets its grade has
#: 99.7 % of its balls within V_DWL). Overridable: ``[elements] grade_sigma_divisor``.
DEFAULT_GRADE_SIGMA_DIVISOR = 6.0


class StandardsError(ValueError):
    """A grade or class that is not tabulated, or a bore outside the table."""


@dataclass(frozen=True)
class BallGrade:
    """The ISO 3290-1 tolerances of one grade of steel balls, all in SI [m].

    Attributes
    ----------
    name : str
        ``"G3"`` ... ``"G200"``.
    diameter_variation : float
        V_DWs: largest minus smallest single diameter of one ball [m].
    spherical_form : float
        t_Dw: deviation from spherical form (roundness) of one ball [m].
    roughness : float
        Ra: arithmetical mean surface roughness [m].
    lot_diameter_variation : float
        V_DWL: mean diameter of the largest ball minus that of the smallest ball of a lot [m].
    gauge_interval : float
        I_G: step of the ball gauges (the lot mean diameter's deviation from nominal) [m].
    """

    name: str
    diameter_variation: float
    spherical_form: float
    roughness: float
    lot_diameter_variation: float
    gauge_interval: float


def _grade(name: str, vdws: float, tdw: float, ra: float, vdwl: float, ig: float) -> BallGrade:
    um = 1e-6
    return BallGrade(name, vdws * um, tdw * um, ra * um, vdwl * um, ig * um)


#: ISO 3290-1:2014 grades of steel balls, values in um as tabulated: V_DWs, t_Dw, Ra, V_DWL, I_G.
BALL_GRADES: dict[str, BallGrade] = {
    g.name: g
    for g in (
        _grade("G3", 0.08, 0.08, 0.010, 0.13, 0.5),
        _grade("G5", 0.13, 0.13, 0.014, 0.25, 1.0),
        _grade("G10", 0.25, 0.25, 0.020, 0.5, 1.0),
        _grade("G16", 0.4, 0.4, 0.025, 0.8, 2.0),
        _grade("G20", 0.5, 0.5, 0.032, 1.0, 2.0),
        _grade("G24", 0.6, 0.6, 0.040, 1.2, 2.0),
        _grade("G28", 0.7, 0.7, 0.050, 1.4, 2.0),
        _grade("G40", 1.0, 1.0, 0.060, 2.0, 4.0),
        _grade("G60", 1.5, 1.5, 0.080, 3.0, 6.0),
        _grade("G100", 2.5, 2.5, 0.100, 5.0, 10.0),
        _grade("G200", 5.0, 5.0, 0.150, 10.0, 15.0),
    )
}

#: ISO 492 tolerance classes of radial bearings, loosest first.
TOLERANCE_CLASSES = ("Normal", "P6", "P5", "P4", "P2")
#: Bore ranges of :data:`KIA_UM` [mm]: range i is edges[i] < d <= edges[i + 1].
KIA_BORE_EDGES_MM = (2.5, 10.0, 18.0, 30.0, 50.0, 80.0, 120.0)
#: K_ia [um] per class and bore range (ISO 492:2014, inner ring tables).
KIA_UM: dict[str, tuple[float, ...]] = {
    "Normal": (10.0, 10.0, 13.0, 15.0, 20.0, 25.0),
    "P6": (6.0, 7.0, 8.0, 10.0, 10.0, 13.0),
    "P5": (4.0, 4.0, 4.0, 5.0, 5.0, 6.0),
    "P4": (2.5, 2.5, 3.0, 4.0, 4.0, 5.0),
    "P2": (1.5, 1.5, 2.5, 2.5, 2.5, 2.5),
}


def _close(name: str, known: list[str]) -> str:
    hint = difflib.get_close_matches(name, known, n=3, cutoff=0.5)
    return f"; did you mean {' or '.join(repr(h) for h in hint)}?" if hint else ""


def ball_grade(name: str) -> BallGrade:
    """The ISO 3290-1 grade ``name`` (``"G5"``; ``"g5"`` and ``"5"`` are read as ``"G5"``).

    Parameters
    ----------
    name : str
        The grade as a case writes it.

    Returns
    -------
    BallGrade
        Its tabulated values [m].

    Raises
    ------
    StandardsError
        A grade that is not in the table, with the close matches.
    """
    text = str(name).strip()
    key = text.upper() if text[:1] in ("g", "G") else f"G{text}"
    if key in BALL_GRADES:
        return BALL_GRADES[key]
    raise StandardsError(
        f"unknown ball grade {text!r} (ISO 3290-1:2014 grades: {', '.join(BALL_GRADES)})"
        + _close(key, list(BALL_GRADES))
    )


def grade_sigma(grade: BallGrade, divisor: float = DEFAULT_GRADE_SIGMA_DIVISOR) -> float:
    """Standard deviation of the balls' diameters of a lot of grade ``grade`` [m].

    Parameters
    ----------
    grade : BallGrade
        The grade.
    divisor : float
        V_DWL taken as ``divisor`` standard deviations [-] (default 6: the lot's range as
        +-3 sigma of normal diameters).

    Returns
    -------
    float
        ``V_DWL / divisor`` [m].

    Notes
    -----
    ISO 3290-1:2014 defines V_DWL as the mean diameter of the largest ball minus that of the
    smallest ball of a lot; the models draw each ball's diameter error from N(0, sigma^2).
    """
    return grade.lot_diameter_variation / divisor


def grade_form_amplitude(grade: BallGrade, order: int) -> float:
    """Largest zero-to-peak amplitude of a ball's form harmonic of ``order`` lobes that the
    grade allows [m].

    Parameters
    ----------
    grade : BallGrade
        The grade.
    order : int
        Lobes k >= 2 of the harmonic r(θ) = R + a cos(kθ + φ) on a great circle of the ball.

    Returns
    -------
    float
        ``t_Dw / 2`` for odd k; ``min(t_Dw / 2, V_DWs / 4)`` for even k [m].

    Notes
    -----
    ISO 3290-1:2014 bounds a ball's form by its deviation from spherical form t_Dw (the
    radial distance between the circumscribed and inscribed spheres, 2a for one harmonic) and
    its single diameter variation V_DWs. The diameter through θ is 2R + a (cos kθ + cos k(θ +
    π)): it varies by 4a for even k and not at all for odd k (a ball of constant width), so
    only even orders are bounded by V_DWs as well. The grade gives no lobe order; the case
    names it (``[elements] grade_form_order``).
    """
    if order < 2:
        raise StandardsError(f"a ball's form order must be >= 2, got {order}")
    bound = 0.5 * grade.spherical_form
    if order % 2 == 0:
        bound = min(bound, 0.25 * grade.diameter_variation)
    return bound


def is_class_name(text: str) -> bool:
    """Whether ``text`` reads as a tolerance class name rather than a length.

    Parameters
    ----------
    text : str
        An ``[analysis] limit`` as written.

    Returns
    -------
    bool
        True when it does not start with a digit, a sign or a decimal point (``"P4"``,
        ``"Normal"``, ``"P3"``; a class the table lacks is refused later, by name).
    """
    stripped = text.strip()
    return bool(stripped) and not (stripped[0].isdigit() or stripped[0] in "+-.")


@dataclass(frozen=True)
class ClassLimit:
    """The K_ia limit of an ISO 492 class for one bore.

    Attributes
    ----------
    tolerance_class : str
        ``"Normal"``, ``"P6"``, ``"P5"``, ``"P4"`` or ``"P2"``.
    bore : float
        The bearing's bore d [m].
    limit : float
        K_ia [m].
    source : str
        The citation with the bore range: ``"ISO 492:2014 ... P4, 18 mm < d <= 30 mm"``.
    """

    tolerance_class: str
    bore: float
    limit: float
    source: str


def class_limit(name: str, bore: float) -> ClassLimit:
    """K_ia of the ISO 492 class ``name`` for a bearing of bore ``bore`` [m].

    Parameters
    ----------
    name : str
        Class name (:data:`TOLERANCE_CLASSES`; case as tabulated, ``"p4"`` is read as
        ``"P4"``).
    bore : float
        Bore d [m].

    Returns
    -------
    ClassLimit

    Raises
    ------
    StandardsError
        An unknown class (with close matches; "P0" is told to write "Normal"), or a bore
        outside 2.5 mm < d <= 120 mm.
    """
    text = str(name).strip()
    canonical = {c.lower(): c for c in TOLERANCE_CLASSES}
    key = canonical.get(text.lower())
    if key is None:
        if text.upper() in ("P0", "PN", "CLASS 0", "ABEC1", "ABEC 1"):
            raise StandardsError(f'{text!r} is the ISO 492 Normal class: write "Normal"')
        raise StandardsError(
            f"unknown tolerance class {text!r} (ISO 492 classes: {', '.join(TOLERANCE_CLASSES)})"
            + _close(text, list(TOLERANCE_CLASSES))
        )
    # to 1 nm: a bore given as "18 mm" is 0.018 m, whose 1e3 multiple is 18.000000000000004
    # and would fall into the next range
    d_mm = round(bore * 1e3, 6)
    edges = KIA_BORE_EDGES_MM
    if not edges[0] < d_mm <= edges[-1]:
        raise StandardsError(
            f"bore {d_mm:.6g} mm is outside the K_ia table of this version "
            f"({edges[0]:g} mm < d <= {edges[-1]:g} mm): give a numeric limit instead"
        )
    i = next(k for k in range(len(edges) - 1) if d_mm <= edges[k + 1])
    return ClassLimit(
        key,
        bore,
        KIA_UM[key][i] * 1e-6,
        f"{ISO_492_SOURCE}, class {key}, {edges[i]:g} mm < d <= {edges[i + 1]:g} mm",
    )
