"""Estimates of a bearing's internal geometry from its boundary dimensions.

A catalogue row gives the ISO 15 boundary dimensions (bore d, outside diameter D, width B) and,
where a publication gives them, the internal dimensions. The cells a row leaves empty are
estimated here by named rules; every estimated value says so in its provenance
(:mod:`runout.catalogue`), and the rules' errors against the rows whose internal values are
published are stated in docs/designation.md and checked by the tests.

Rules (lengths in [m], angles in [rad]):

``pitch_mean``
    d_m = (d + D) / 2: the rolling elements sit halfway across the ring section.
``ball_section``
    D_w = 0.3 (D - d): the ball fills 60 % of the radial section height (D - d) / 2.
``roller_section``
    D_w = 0.25 (D - d): the roller fills half the section height; raceways
    d_i = d_m - D_w, d_e = d_m + D_w (zero clearance).
``conrad_fill``
    Z = 1 + floor(phi / (2 asin(D_w / d_m))), phi = 200 deg: the balls of a deep-groove
    (Conrad) assembly are put in through the crescent left by displacing the inner ring, so
    Z - 1 ball pitches fit inside the fill angle phi (Harris & Kotzalas, *Essential Concepts
    of Bearing Technology*, 5th ed., 2007, ch. 2, the Conrad assembly). phi is chosen so that
    the rule gives the published counts of the 608, 6203 and 6205 rows.
``cage_pitch``
    Z = floor(pi / asin(p / d_m)): as many elements as fit round the pitch circle at a centre
    distance p; p = 1.2 D_w for the balls of an angular-contact bearing (one shoulder relieved,
    the cage bars 0.2 D_w), p = 1.4 D_w for the rollers of a cylindrical roller bearing (chosen
    so that the rule gives the 14 rollers of the published NU209).
``typical_conformity``
    f_i = 0.52, f_o = 0.53: groove radius over ball diameter typical of deep-groove and
    angular-contact bearings (Harris & Kotzalas, 2007, ch. 2).
"""

from __future__ import annotations

import math

__all__ = [
    "BALL_SECTION_FACTOR",
    "CONRAD_FILL_ANGLE",
    "INNER_CONFORMITY",
    "OUTER_CONFORMITY",
    "RULES",
    "estimate",
]

#: Ball diameter over (D - d) of the ``ball_section`` rule [-].
BALL_SECTION_FACTOR = 0.3
#: Roller diameter over (D - d) of the ``roller_section`` rule [-].
ROLLER_SECTION_FACTOR = 0.25
#: Fill angle of a Conrad assembly in the ``conrad_fill`` rule [rad].
CONRAD_FILL_ANGLE = math.radians(200.0)
#: Ball centre distance over ball diameter in an angular-contact bearing (``cage_pitch``) [-].
ANGULAR_PITCH_FACTOR = 1.2
#: Roller centre distance over roller diameter in a cylindrical roller bearing [-].
ROLLER_PITCH_FACTOR = 1.4
#: Typical groove conformities (``typical_conformity``) [-].
INNER_CONFORMITY = 0.52
OUTER_CONFORMITY = 0.53

#: Each rule's one-line statement, as the provenance and ``runout catalogue`` show it.
RULES = {
    "pitch_mean": "estimate (rule pitch_mean: d_m = (d + D)/2)",
    "ball_section": "estimate (rule ball_section: D_w = 0.3 (D - d))",
    "roller_section": "estimate (rule roller_section: D_w = 0.25 (D - d))",
    "roller_raceways": "estimate (rule roller_section: d_i = d_m - D_w, d_e = d_m + D_w)",
    "conrad_fill": "estimate (rule conrad_fill: Z = 1 + floor(200 deg / (2 asin(D_w/d_m))))",
    "cage_pitch_ball": "estimate (rule cage_pitch: Z = floor(pi / asin(1.2 D_w/d_m)))",
    "cage_pitch_roller": "estimate (rule cage_pitch: Z = floor(pi / asin(1.4 D_w/d_m)))",
    "typical_conformity": "estimate (rule typical_conformity: f_i = 0.52, f_o = 0.53)",
}


def _rounded(length: float) -> float:
    """A length to the picometre (0.012, not 0.011999999999999999) [m]."""
    return round(length, 12)


def _fit_count(pitch_angle: float, span: float) -> int:
    # a hair of tolerance: a count that fits exactly is not lost to round-off
    return math.floor(span / pitch_angle * (1.0 + 1e-12))


def estimate(
    kind: str, bore: float, outside: float, given: dict[str, float]
) -> dict[str, tuple[float, str]]:
    """Estimated internal geometry for the keys a row leaves empty.

    Parameters
    ----------
    kind : {"deep_groove", "angular_contact", "cylindrical_roller"}
        The bearing's kind.
    bore, outside : float
        Bore d and outside diameter D [m].
    given : dict of str to float
        The row's published values by case key (SI); the rules use them where given (a
        published ball diameter sets the count).

    Returns
    -------
    dict of str to (float, str)
        Case key -> (SI value, the rule's statement) for each key not in ``given``.
    """
    out: dict[str, tuple[float, str]] = {}
    if kind == "cylindrical_roller":
        d_w = given.get("element_diameter")
        if d_w is None:
            d_w = _rounded(ROLLER_SECTION_FACTOR * (outside - bore))
            out["element_diameter"] = (d_w, RULES["roller_section"])
        if "inner_raceway_diameter" in given and "outer_raceway_diameter" in given:
            pitch = 0.5 * (given["inner_raceway_diameter"] + given["outer_raceway_diameter"])
        else:
            pitch = 0.5 * (bore + outside)
            inner = given.get("inner_raceway_diameter", _rounded(pitch - d_w))
            outer = given.get("outer_raceway_diameter", _rounded(pitch + d_w))
            # zero clearance to the last bit: never a negative one by round-off
            while outer - inner - 2.0 * d_w < 0.0 and "outer_raceway_diameter" not in given:
                outer = math.nextafter(outer, math.inf)
            while outer - inner - 2.0 * d_w < 0.0:
                inner = math.nextafter(inner, -math.inf)
            for key, value in (
                ("inner_raceway_diameter", inner),
                ("outer_raceway_diameter", outer),
            ):
                if key not in given:
                    out[key] = (value, RULES["roller_raceways"])
        if "elements" not in given:
            angle = 2.0 * math.asin(min(1.0, ROLLER_PITCH_FACTOR * d_w / pitch))
            out["elements"] = (float(_fit_count(angle, 2.0 * math.pi)), RULES["cage_pitch_roller"])
        return out
    ball_pitch = given.get("pitch_diameter")
    if ball_pitch is None:
        ball_pitch = _rounded(0.5 * (bore + outside))
        out["pitch_diameter"] = (ball_pitch, RULES["pitch_mean"])
    pitch = ball_pitch
    ball = given.get("element_diameter")
    if ball is None:
        ball = _rounded(BALL_SECTION_FACTOR * (outside - bore))
        out["element_diameter"] = (ball, RULES["ball_section"])
    d_w = ball
    if "elements" not in given:
        if kind == "deep_groove":
            angle = 2.0 * math.asin(min(1.0, d_w / pitch))
            count = 1 + _fit_count(angle, CONRAD_FILL_ANGLE)
            out["elements"] = (float(count), RULES["conrad_fill"])
        else:
            angle = 2.0 * math.asin(min(1.0, ANGULAR_PITCH_FACTOR * d_w / pitch))
            out["elements"] = (float(_fit_count(angle, 2.0 * math.pi)), RULES["cage_pitch_ball"])
    for key, value in (
        ("inner_conformity", INNER_CONFORMITY),
        ("outer_conformity", OUTER_CONFORMITY),
    ):
        if key not in given:
            out[key] = (value, RULES["typical_conformity"])
    return out
