"""The glossary: one name per quantity, in one table that renders docs/glossary.md.

The case-file keys, the Python constructor arguments and attributes, the JSON keys and the
docs use the names of :data:`TERMS`. ``python -m runout.base.glossary > docs/glossary.md``
writes the page; a test fails when the committed page differs, when a ``[bearing]``,
``[operation]`` or ``[material]`` key or a field of :class:`runout.geometry.bearing.BallBearing`,
:class:`~runout.geometry.bearing.RollerBearing`, :class:`~runout.geometry.bearing.Operation` or
:class:`~runout.geometry.bearing.Material` is missing from it, or when a name's unit differs
between the case file, the Python docstring and the glossary.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass

__all__ = ["TERMS", "Term", "glossary_markdown", "names", "term"]


@dataclass(frozen=True)
class Term:
    """One row of the glossary.

    Attributes
    ----------
    names : tuple of str
        The names the row defines (two for an inner/outer pair), as written in case files,
        Python and JSON; for a concept with no key (``order``), the word used in the docs.
    symbol : str
        Symbol in Harris's notation (or the usual one), ``"–"`` when there is none.
    unit : str
        SI unit of the value (``"–"``: a pure number, a count or a text value).
    meaning : str
        What the quantity is.
    key : bool
        True when the names are keys or identifiers (rendered as code); False for a concept
        named in words.
    """

    names: tuple[str, ...]
    symbol: str
    unit: str
    meaning: str
    key: bool = True


TERMS: tuple[Term, ...] = (
    # ------------------------------------------------------------------ [bearing]
    Term(
        ("type",),
        "–",
        "–",
        '"ball" (deep-groove or angular-contact) or "cylindrical_roller": in Python the class, '
        "BallBearing or RollerBearing",
    ),
    Term(
        ("designation",),
        "–",
        "–",
        'a bearing\'s catalogue designation ("6204", "7014C", "NU209"): alone a whole '
        "bearing description from runout's catalogue (ISO 15 boundary dimensions, internal "
        "geometry published or estimated by a named rule); keys given beside it override",
    ),
    Term(
        ("elements",),
        "Z",
        "–",
        "number of balls or rollers (Python's former `n_elements` is deprecated)",
    ),
    Term(
        ("element_diameter",),
        "D, D_w",
        "m",
        "diameter of a rolling element (former `ball_diameter`, `roller_diameter` deprecated)",
    ),
    Term(("pitch_diameter",), "d_m", "m", "diameter of the circle through the element centres"),
    Term(
        ("inner_conformity", "outer_conformity"),
        "f_i, f_o",
        "–",
        "groove radius / ball diameter",
    ),
    Term(
        ("inner_groove_radius", "outer_groove_radius"),
        "r_i, r_o",
        "m",
        "groove (cross-section) radii",
    ),
    Term(
        ("inner_raceway_diameter", "outer_raceway_diameter"),
        "d_i, d_o",
        "m",
        "groove-bottom (ball) or raceway (roller) diameters",
    ),
    Term(("roller_length",), "l", "m", "effective length of a cylindrical roller"),
    Term(
        ("radial_clearance",),
        "P_d",
        "m",
        "ISO radial internal clearance = diametral play",
    ),
    Term(("total_curvature",), "B", "–", "f_i + f_o − 1"),
    Term(
        ("curvature_distance",),
        "A",
        "m",
        "B D, distance between groove curvature centres",
    ),
    Term(
        ("nominal_contact_angle", "free_contact_angle"),
        "α⁰",
        "rad",
        "contact angle of the unloaded bearing, arccos(1 − P_d / 2A): the case key and "
        "`BallBearing(nominal_contact_angle=)` set it (as the clearance); the bearing's "
        "`nominal_contact_angle` and `free_contact_angle` report it",
    ),
    Term(
        ("contact_angle",),
        "α",
        "rad",
        "angle between the contact line and the radial plane",
    ),
    Term(
        ("dynamic_load_rating",),
        "C",
        "N",
        "basic dynamic load rating of the bearing (catalogue, ISO 281): the load it carries for "
        "10⁶ revolutions at 90 % survival; sets the contact ratings of the reference life",
    ),
    Term(
        ("fatigue_load_limit", "fatigue_load_limit_n"),
        "C_u",
        "N",
        "fatigue load limit of the bearing (catalogue, ISO 281): the load below which the "
        "raceways do not fatigue; enters a_ISO",
    ),
    # ------------------------------------------------------------------ [material]
    Term(
        ("material",),
        "–",
        "–",
        "the [material] table; in Python a Material, the `material` of a bearing",
    ),
    Term(("youngs_modulus",), "E", "Pa", "Young's modulus of rings and rolling elements"),
    Term(("poisson_ratio",), "ν", "–", "Poisson's ratio of rings and rolling elements"),
    Term(("density",), "ρ", "kg/m³", "density of the rolling elements"),
    # ------------------------------------------------------------------ [operation]
    Term(
        ("rotating_ring",),
        "–",
        "–",
        '"inner" or "outer": the ring whose revolutions define orders',
    ),
    Term(("speed",), "f_r", "Hz", "rotation frequency of the rotating ring (rev/s)"),
    Term(
        ("other_ring_speed",),
        "–",
        "Hz",
        "rotation frequency of the other ring, signed relative to `speed`",
    ),
    Term(("axial_load",), "F_a", "N", "axial load on the shaft; the preload force"),
    Term(
        ("preload",),
        "–",
        "–",
        '"spring": constant axial force (shaft free axially); "position": rings held at the '
        "axial offset of the axial load alone",
    ),
    Term(("radial_load",), "F_r", "N", "radial load on the shaft"),
    Term(
        ("radial_load_direction",),
        "–",
        "rad",
        "direction of the radial load, counter-clockwise from +x (default −y)",
    ),
    Term(("moment_load",), "M", "N m", "tilting moment on the inner ring"),
    Term(
        ("moment_load_direction",),
        "–",
        "rad",
        "direction of the moment vector, counter-clockwise from +x",
    ),
    # ------------------------------------------------------------------ frequencies
    Term(("cage",), "f_c", "Hz", "ball-set orbital frequency"),
    Term(
        ("ball_spin",),
        "f_b",
        "Hz",
        "element rotation about its own axis, seen from the cage",
    ),
    Term(
        ("ball_pass_inner", "ball_pass_outer"),
        "BPFI, BPFO",
        "Hz",
        "rate of elements passing a point of a raceway",
    ),
    Term(
        ("roller_pass_inner", "roller_pass_outer"),
        "BPFI, BPFO",
        "Hz",
        "the same, under the roller names (roller bearings' JSON: aliases)",
    ),
    Term(
        ("order",),
        "–",
        "–",
        "frequency / speed: waves per revolution of the rotating ring",
        key=False,
    ),
    # ------------------------------------------------------------------ imperfections, outputs
    Term(("amplitude",), "a_k", "m", "zero-to-peak radius deviation of harmonic k"),
    Term(
        ("peak_to_peak", "pp"),
        "–",
        "m",
        "2 × amplitude; every output displacement is p-p",
    ),
    Term(
        ("RRO / NRRO",),
        "–",
        "m",
        "repeatable (synchronous with the rotating ring) / non-repeatable runout",
        key=False,
    ),
    Term(
        ("top_source",),
        "–",
        "–",
        "label of a line's largest source (RunResult.to_dataframe)",
    ),
    Term(
        ("Anderon",),
        "–",
        "µin/rad/√octave",
        "band value of the displacement density dx/dθ",
        key=False,
    ),
    Term(
        ("iso15242",),
        "L, M, H",
        "µm/s",
        "rms radial velocity per ISO 15242-1 band, edges scaled to the speed",
    ),
    Term(
        ("verdict",),
        "–",
        "–",
        "a run's figure against `[analysis] limit`: pass when value ≤ limit",
    ),
    Term(
        ("yield",),
        "–",
        "–",
        "fraction of a Monte Carlo lot within the limit, Clopper–Pearson 95 % interval",
    ),
    Term(
        ("allocate", "target_yield", "allocated"),
        "–",
        "–",
        "`[study]` keys of a tolerance allocation: the `[study.vary]` key whose tolerance is "
        "found, the lot's target yield; JSON `allocated`: the largest tolerance whose "
        "estimated yield meets it, with its interval",
    ),
    # ------------------------------------------------------------------ ring tilt
    Term(
        ("ring_tilt",),
        "–",
        "–",
        '`[analysis]` key and JSON entry of the equilibrium model: "free" (the balls\' '
        'moment balances moment_load) or "held" (θ_x = θ_y = 0 imposed)',
    ),
    Term(
        ("held_dofs",),
        "–",
        "–",
        "equilibrium: the degrees of freedom held at 0 instead of solved (tilt_x, tilt_y "
        "when ring_tilt is held); `stiffness_matrix` stays over all five",
    ),
    Term(
        ("reaction_moment_n_m",),
        "M_x, M_y",
        "N m",
        "equilibrium with the tilt held: the moment the restraint exerts on the inner ring to "
        "hold it untilted, in the sense of moment_load (0 when the tilt is free)",
    ),
    Term(
        ("solver_resolution_m",),
        "–",
        "m",
        "the resolution the model states for its record: below it a figure is numerical "
        "noise, not a result (printed as 0); the line fit's floor of an iterative model, a "
        "round-off bound of a closed-form one",
    ),
    # ------------------------------------------------------------------ stiffness
    Term(
        ("stiffness_matrix",),
        "K",
        "N/m, N/rad, N m/m, N m/rad",
        "5×5 tangent stiffness of the equilibrium model over axial, x, y, tilt_x, tilt_y; of "
        "the spindle at the nose over x, y, z, tilt_x, tilt_y (each entry holds the other "
        "coordinates: K_xx with the tilt held)",
    ),
    Term(
        ("tool_point_stiffness_n_per_m",),
        "1/C_xx, 1/C_yy, 1/C_zz",
        "N/m",
        "spindle: stiffness at the tool (the nose) with the shaft free to tilt, 1/C_ii of the "
        "compliance C = K⁻¹ of `stiffness_matrix`",
    ),
    Term(
        ("radial_stiffness",),
        "k_xx, k_xy, k_yx, k_yy",
        "N/m",
        "radial 2×2 block of `stiffness_matrix`, tilts held (`kxx_n_per_m` ...): the "
        "stiffness of a linear bearing element",
    ),
    Term(
        ("bearing_damping",),
        "c_xx, c_xy, c_yx, c_yy, c_zz",
        "N s/m",
        "equilibrium model with [analysis] bearing_damping: damping of the bearing coefficients, "
        "c = β k for each (`cxx_n_s_per_m` ...; stiffness.csv's damping columns); its `model` "
        "and β (`coefficient_s`): Krämer's estimate or the user's, not a measurement",
    ),
    Term(
        ("bearing_damping_coefficient",),
        "β",
        "s",
        "ratio of a bearing's damping to its stiffness, c = β k; Krämer (Dynamics of Rotors and "
        "Foundations, 1993) gives (0.25 ... 2.5) × 10⁻⁵ s for rolling bearings",
    ),
    Term(
        ("life",),
        "–",
        "–",
        "equilibrium model, with `dynamic_load_rating`: the ISO/TS 16281 basic reference rating "
        "life and the loads it comes from (`l10r_mrev` ...)",
    ),
    Term(
        ("l10r_mrev", "l10r_inner_mrev", "l10r_outer_mrev"),
        "L10r, L10ri, L10re",
        "10⁶ rev",
        "basic reference rating life (ISO/TS 16281) of the bearing and of each ring, in "
        "millions of revolutions of one ring relative to the other; L10r = (L10ri^−e + "
        "L10re^−e)^(−1/e), e = 10/9",
    ),
    Term(
        ("equivalent_inner_load_n", "equivalent_outer_load_n"),
        "Q_ei, Q_ee",
        "N",
        "dynamic equivalent rolling-element load of a raceway: the cubic mean of the ball loads "
        "on the ring turning relative to the load, the 10/3-power mean on the other",
    ),
    Term(
        ("inner_contact_rating_n", "outer_contact_rating_n"),
        "Q_ci, Q_ce",
        "N",
        "rolling-element load of the basic dynamic load rating of a raceway contact "
        "(from C and the geometry, ISO/TS 16281)",
    ),
    Term(
        ("equivalent_reference_load_n",),
        "P_ref",
        "N",
        "dynamic equivalent reference load C L10r^(−1/3): the ISO 281 load of the same life",
    ),
    Term(
        ("lnmr_mrev", "lnmr_hours"),
        "L_nmr",
        "10⁶ rev",
        "modified reference rating life a_1 a_ISO L10r (ISO 281's factors on the ISO/TS 16281 "
        "life), also in hours at the run's speed",
    ),
    Term(
        ("a_iso",),
        "a_ISO",
        "–",
        "life modification factor of ISO 281 (lubrication, contamination, fatigue load limit) "
        "at P_ref, 0.1 to 50",
    ),
    Term(
        ("a1", "reliability_percent"),
        "a_1",
        "–",
        "ISO 281's life modification factor for reliability (1 at 90 %) and the reliability "
        "it is for [%]",
    ),
    Term(
        ("kzz_n_per_m",),
        "K_aa",
        "N/m",
        "axial stiffness in stiffness.csv: the first diagonal entry of `stiffness_matrix`",
    ),
)


def names() -> dict[str, Term]:
    """Every name of :data:`TERMS` -> its row (a name appears once).

    Returns
    -------
    dict of str to Term
        Each name of every row, mapped to that row.

    Raises
    ------
    ValueError
        A name in two rows.
    """
    found: dict[str, Term] = {}
    for t in TERMS:
        for name in t.names:
            if name in found:
                raise ValueError(f"glossary: {name!r} is defined twice")
            found[name] = t
    return found


def term(name: str) -> Term:
    """The glossary row of ``name``.

    Parameters
    ----------
    name : str
        A name as used in the API, case files and JSON output.

    Returns
    -------
    Term
        Its row (symbol, SI unit, meaning).

    Raises
    ------
    KeyError
        ``name`` is not in the glossary.
    """
    return names()[name]


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def glossary_markdown() -> str:
    """The Markdown of docs/glossary.md.

    Returns
    -------
    str
        The whole page, a table of every row, ending in a newline.
    """
    lines = [
        "# Glossary",
        "",
        "Generated from `runout.base.glossary` by `python -m runout.base.glossary`; do not edit "
        "by hand.",
        "",
        "One name per quantity, everywhere: in the Python API, the case files, the JSON output and",
        "the docs. SI inside; units appear only in case files, the command line and reports.",
        "",
        "| name | symbol (Harris) | unit (SI) | meaning |",
        "|---|---|---|---|",
    ]
    for t in TERMS:
        shown = ", ".join(f"`{n}`" if t.key else n for n in t.names)
        lines.append(f"| {shown} | {_cell(t.symbol)} | {_cell(t.unit)} | {_cell(t.meaning)} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(glossary_markdown())
