"""One meaning per case key, and what each model does with it.

Every case key has one physical meaning, unit, sign and frame, whichever model runs. A model
*honours* a key (it changes the result), *refuses* it (exit 2, naming the key and the models
that honour it) or does *not apply* it (the run goes on and says so in the JSON ``notes`` and
in the readable summary). This table is the single source: ``enforce`` applies it before
every run, ``runout check`` prints it for the case's model, ``docs/conventions.md`` is
generated from it (``conventions_page``), and the tests change one key at a time to check
that every cell is what the code does.

The frame shared by every model (Harris, *Rolling Bearing Analysis*, for the geometry):

* loads act on the shaft (the inner ring) along their direction: a radial load along
  ``radial_load_direction`` (default -y), an axial load along +z, a moment about its vector;
* displacements are the inner ring's centre relative to the outer ring's (the shaft in the
  housing), whichever ring turns; x, y from the rings concentric, z from the rings axially
  centred (groove centres in one plane), growing along the axial load on the shaft;
* angles are counter-clockwise from +x; phases are those of cos(kθ + φ) in the part's own
  frame (element waviness: ``[elements] phase_frame``);
* t = 0 at the start of the reported record.

Each model's documentation maps its paper's own frame onto this one.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

from runout.base.errors import CaseError
from runout.case.model import MODEL_IDS

if TYPE_CHECKING:
    from runout.case.model import Case, CaseSpec

__all__ = [
    "KEYS",
    "MODELS",
    "Applicability",
    "KeyConvention",
    "applicability",
    "conventions_page",
    "enforce",
    "honouring_models",
]

Status = Literal["honoured", "refused", "not_applicable"]

#: Model ids in the order of the matrix columns.
MODELS = MODEL_IDS
_SHORT = {
    "linear": "linear",
    "quasi_static_2d": "qs 2-D",
    "quasi_static_3d": "qs 3-D",
    "equilibrium": "equil.",
    "dynamic": "dynamic",
    "roller_constraint": "roller",
    "spindle": "spindle",
}
H: Status = "honoured"
R: Status = "refused"
N: Status = "not_applicable"


@dataclass(frozen=True)
class KeyConvention:
    """One case key (or one kind of imperfection entry): meaning and per-model treatment.

    Attributes
    ----------
    key : str
        Case-file key path (``operation.radial_load``) or entry kind (``waviness (rings)``).
    meaning : str
        Physical meaning, sign and frame.
    unit : str
        SI unit of the value (``-`` for none).
    statuses : tuple of str
        ``honoured`` / ``refused`` / ``not_applicable`` per model, in :data:`MODELS` order.
    why : dict
        Model id -> why it refuses or does not apply the key (said in the error or note).
    present : callable
        ``present(spec) -> list of key paths`` the case sets (explicitly and not to the
        default); empty when the case does not use the key.
    honoured_when : dict
        Model id -> ``condition(spec)``: cases in which a key the model otherwise does not
        apply does change its result (e.g. conformities set the clearance of a nominal angle).
    """

    key: str
    meaning: str
    unit: str
    statuses: tuple[Status, ...]
    why: dict[str, str] = field(default_factory=dict)
    present: Callable[[CaseSpec], list[str]] = field(default=lambda spec: [], repr=False)
    honoured_when: dict[str, Callable[[CaseSpec], bool]] = field(default_factory=dict, repr=False)

    def status(self, model: str, spec: CaseSpec | None = None) -> Status:
        """What ``model`` does with this key (in ``spec``, when a condition applies).

        Parameters
        ----------
        model : str
            Model id, one of :data:`MODELS`.
        spec : CaseSpec or None
            The validated case-file tables, for the conditions of :attr:`honoured_when`; None:
            the model's column of the table.

        Returns
        -------
        {"honoured", "refused", "not_applicable"}
        """
        condition = self.honoured_when.get(model)
        if spec is not None and condition is not None and condition(spec):
            return "honoured"
        return self.statuses[MODELS.index(model)]


# --------------------------------------------------------------------------------------------
# what a case sets
# --------------------------------------------------------------------------------------------
def _table_key(table: str, name: str) -> Any:
    """``present`` for ``[table] name``: set explicitly and different from the default."""

    def present(spec: CaseSpec) -> list[str]:
        sections: list[tuple[str, Any]]
        if table == "bearing" and spec.bearings:  # a spindle: every [[bearings]] entry
            sections = [(f"bearings[{i}]", b) for i, b in enumerate(spec.bearings, start=1)]
        elif table == "elements":  # [elements], or a spindle's [elements.<name>]
            sections = list(spec.element_tables)
        else:
            sections = [(table, getattr(spec, table, None))]
        found = []
        for prefix, section in sections:
            if section is None or name not in section.model_fields_set:
                continue
            value = getattr(section, name)
            default = type(section).model_fields[name].default
            if value is None or value == default:
                continue
            found.append(f"{prefix}.{name}")
        return found

    return present


def _damping_keys(spec: CaseSpec) -> list[str]:
    """``present`` for the bearing damping: set to a model other than "none"."""
    if spec.analysis.bearing_damping in (None, "none"):
        return []
    return ["analysis.bearing_damping"]


#: Why a run does not apply ``[elements] grade`` (its note).
_GRADE_IN_A_RUN = (
    "one bearing has one set of balls, and the grade gives only their scatter: a run draws no "
    "ball sizes (elements.diameter_errors are used as given); a Monte Carlo study draws them "
    "with [study.vary] ball_grade, and each ball's form when grade_form_order names its "
    "lobes. A run applies no form from the grade either (one ball's form is not a scatter: "
    'give it as [[waviness]] part = "ball")'
)


def _grade_keys(spec: CaseSpec) -> list[str]:
    """``present`` of ``[elements] grade`` and ``grade_sigma_divisor``."""
    return [
        f"{prefix}.{name}"
        for prefix, table in spec.element_tables
        for name in ("grade", "grade_sigma_divisor", "grade_form_order")
        if getattr(table, name) is not None
    ]


def _table(table: str) -> Any:
    def present(spec: CaseSpec) -> list[str]:
        return [table] if getattr(spec, table, None) is not None else []

    return present


def _entries(parts: tuple[str, ...], *, coherent_only: bool = False) -> Any:
    """``present`` for imperfection entries of ``parts`` in the three imperfection tables."""

    def present(spec: CaseSpec) -> list[str]:
        found = []
        for table in ("waviness", "waviness_spectrum", "profile"):
            for i, entry in enumerate(getattr(spec, table), start=1):
                if entry.part not in parts:
                    continue
                if coherent_only and (
                    entry.element is not None or getattr(entry, "phase", None) == "random"
                ):
                    continue
                if _zero_amplitude(entry):
                    continue
                found.append(f"{table}[{i}]")
        return found

    return present


def _zero_amplitude(entry: Any) -> bool:
    amplitude = getattr(entry, "amplitude", None)
    peak = getattr(entry, "peak_to_peak", None)
    if amplitude is None and peak is None:
        return False  # a profile: its deviations are read from a file
    return not (amplitude or peak)


def _element_list(name: str) -> Any:
    def present(spec: CaseSpec) -> list[str]:
        return [
            f"{key}.{name}"
            for key, table in spec.element_tables
            if (values := getattr(table, name)) and any(v != 0.0 for v in values)
        ]

    return present


def _entry_list(table: str) -> Any:
    def present(spec: CaseSpec) -> list[str]:
        return [f"{table}[{i}]" for i in range(1, len(getattr(spec, table)) + 1)]

    return present


def _signal_keys(spec: CaseSpec) -> list[str]:
    return ["analysis.signal"] if spec.analysis.signal == "acceleration" else []


def _spindle_tables(spec: CaseSpec) -> list[str]:
    return ["spindle", "bearings"] if spec.bearings else []


def _bearing_type_roller(spec: CaseSpec) -> list[str]:
    if spec.bearings:  # a spindle: every bearing
        return [
            f"bearings[{i}].type"
            for i, b in enumerate(spec.bearings, start=1)
            if b.type == "cylindrical_roller"
        ]
    return ["bearing.type"] if spec.lead_bearing.type == "cylindrical_roller" else []


def _analysis_range(spec: CaseSpec) -> list[str]:
    given = spec.analysis.model_fields_set & {"revolutions", "samples"}
    return [f"analysis.{name}" for name in sorted(given)]


def _position_preload(spec: CaseSpec) -> list[str]:
    # a spindle's [spindle] preload_displacement is its own key; only the case's own
    # operation.preload is this one there
    if spec.preload_kind != "position":
        return []
    if spec.spindle is not None and "preload" not in spec.operation.model_fields_set:
        return []
    return ["operation.preload"]


def _axial_limit(spec: CaseSpec) -> list[str]:
    a = spec.analysis
    return ["analysis.limit_on"] if a.limit is not None and a.limit_on == "axial_pp" else []


# --------------------------------------------------------------------------------------------
# the table
# --------------------------------------------------------------------------------------------
_NOT_SOLVED = "the equilibrium model solves the nominal (perfect) bearing at one instant"
_NO_LINES = "it solves one static instant: there are no lines to form bands from"
_TWO_D = "it is planar"
_RIGID = "the rigid constraint model has no contact elasticity"
_ANGLE_FROM_CLEARANCE = (
    "it derives the contact angles from the clearance and the loads; a catalogue (free) angle "
    "is bearing.nominal_contact_angle"
)
_NO_TILT = "it has no tilt degree of freedom"
_TILT_HELD = "it always holds the ring's tilt at 0 (it has no tilt degree of freedom)"
_SPRING_ONLY = "it solves the rings' axial position under a constant axial force (a spring)"
_SLANT = "it has no raceway slant (seed 002 eq. 34 is a linear-model term)"
_RING_KINEMATICS = "the rigid constraint model turns one ring and holds the other still"


def _option_of(
    model: str, key: str, meaning: str, unit: str, why: str, present: Any
) -> KeyConvention:
    """A key only ``model`` honours; the others run without it and say so."""
    statuses: tuple[Status, ...] = tuple(H if m == model else N for m in MODELS)
    return KeyConvention(
        key,
        meaning,
        unit,
        statuses,
        {m: why for m in MODELS if m != model},
        present,
    )


KEYS: tuple[KeyConvention, ...] = (
    KeyConvention(
        'bearing.type = "cylindrical_roller"',
        "Cylindrical roller bearing: line contacts, contact angle 0, clearance from the "
        "raceway diameters.",
        "-",
        (H, R, R, R, R, H, R),
        {
            "quasi_static_2d": "it is a ball-bearing model (seed 001)",
            "quasi_static_3d": "it is a ball-bearing model (seed 000)",
            "equilibrium": "it is a ball-bearing model (Jones-Harris)",
            "dynamic": "it is a ball-bearing model (seed 003)",
            "spindle": "it is a ball-bearing model (seed 000 for each bearing)",
        },
        _bearing_type_roller,
    ),
    KeyConvention(
        "bearing.radial_clearance",
        "ISO radial internal clearance = Harris's diametral play P_d = d_o - d_i - 2D; the "
        "radial play of one ball is P_d / 2. Sets the free contact angle "
        "α⁰ = arccos(1 - P_d / 2A).",
        "m",
        (H, H, H, H, H, H, H),
        {},
        _table_key("bearing", "radial_clearance"),
    ),
    KeyConvention(
        "bearing.nominal_contact_angle",
        "Nominal (free, catalogue) contact angle α⁰ of an unloaded bearing pushed axially; "
        "fixes the clearance P_d = 2A(1 - cos α⁰). With radial_clearance both must agree.",
        "rad",
        (H, H, H, H, H, H, H),
        {},
        _table_key("bearing", "nominal_contact_angle"),
    ),
    KeyConvention(
        "bearing.contact_angle",
        "Operating contact angle held fixed whatever the load (seed 000); omitted, the models "
        "derive it from the clearance and the axial load.",
        "rad",
        (H, H, H, R, R, N, H),
        {
            "equilibrium": _ANGLE_FROM_CLEARANCE,
            "dynamic": _ANGLE_FROM_CLEARANCE,
            "roller_constraint": "it takes a ball bearing in its radial plane (contact angle 0)",
        },
        _table_key("bearing", "contact_angle"),
    ),
    KeyConvention(
        "bearing.inner_conformity, outer_conformity (or groove radii)",
        "Groove radius over ball diameter f = r / D (> 0.5); with the clearance they set the "
        "free contact angle, and the Hertz contact.",
        "-",
        (H, H, H, H, H, N, H),
        {
            "roller_constraint": "it takes the balls as circles on the groove-bottom diameters; "
            "they count only through the clearance of a bearing.nominal_contact_angle"
        },
        lambda spec: [
            path
            for name in (
                "inner_conformity",
                "outer_conformity",
                "inner_groove_radius",
                "outer_groove_radius",
            )
            for path in _table_key("bearing", name)(spec)
        ],
        {"roller_constraint": lambda spec: spec.lead_bearing.nominal_contact_angle is not None},
    ),
    KeyConvention(
        "bearing.dynamic_load_rating",
        "Basic dynamic load rating C of the bearing (catalogue, ISO 281): with it the "
        "equilibrium model reports the ISO/TS 16281 reference rating life L10r (JSON life), "
        "the spindle model each bearing's (JSON bearings[].life).",
        "N",
        (N, N, N, H, N, N, H),
        {
            m: "the ISO/TS 16281 reference rating life is computed from the equilibrium and "
            "spindle models' ball loads only"
            for m in MODELS
            if m not in ("equilibrium", "spindle")
        },
        _table_key("bearing", "dynamic_load_rating"),
    ),
    KeyConvention(
        "bearing.fatigue_load_limit, lubrication, analysis.reliability",
        "Inputs of the modified reference rating life L_nmr = a_1 a_ISO L10r (ISO 281): fatigue "
        "load limit C_u, viscosity ratio (or operating viscosity), contamination factor, "
        "reliability.",
        "N, -, m^2/s, %",
        (N, N, N, H, N, N, H),
        {
            m: "the modified life multiplies the ISO/TS 16281 reference rating life, which is "
            "computed from the equilibrium and spindle models' ball loads only"
            for m in MODELS
            if m not in ("equilibrium", "spindle")
        },
        lambda spec: (
            _table_key("bearing", "fatigue_load_limit")(spec)
            + _table("lubrication")(spec)
            + _table_key("analysis", "reliability")(spec)
        ),
    ),
    KeyConvention(
        "material.youngs_modulus, poisson_ratio",
        "Elastic constants of rings and elements (Hertz contact stiffness).",
        "Pa, -",
        (N, H, H, H, H, N, H),
        {
            "linear": "its gains do not depend on the contact stiffness (seed 002 eq. 13); the "
            "material enters only the loaded contact angle",
            "roller_constraint": _RIGID,
        },
        lambda spec: (
            _table_key("material", "youngs_modulus")(spec)
            + _table_key("material", "poisson_ratio")(spec)
        ),
    ),
    KeyConvention(
        "material.density",
        "Density of the rolling elements (centrifugal force, gyroscopic moment).",
        "kg/m^3",
        (N, N, N, H, N, N, N),
        {
            "linear": "it has no inertia",
            "quasi_static_2d": "it is quasi-static without ball inertia",
            "quasi_static_3d": "it is quasi-static without ball inertia",
            "dynamic": "its inertia is the rotor mass of [dynamics]; ball inertia is neglected",
            "roller_constraint": "it is a rigid, quasi-static model",
        },
        _table_key("material", "density"),
    ),
    KeyConvention(
        "operation.rotating_ring",
        "Ring whose revolutions define orders (waves per revolution) and RRO.",
        "-",
        (H, H, H, H, H, H, H),
        {},
        _table_key("operation", "rotating_ring"),
    ),
    KeyConvention(
        "operation.other_ring_speed",
        "Speed of the other ring, signed relative to speed (both rings turning).",
        "Hz",
        (H, H, H, H, H, R, H),
        {"roller_constraint": _RING_KINEMATICS},
        _table_key("operation", "other_ring_speed"),
    ),
    KeyConvention(
        "operation.axial_load",
        "Axial load on the shaft along +z; the preload force, of the kind operation.preload names.",
        "N",
        (H, H, H, H, H, N, H),
        {"roller_constraint": "a cylindrical roller bearing carries no axial load"},
        _table_key("operation", "axial_load"),
    ),
    KeyConvention(
        'operation.preload = "position"',
        'What holds the rings axially. "spring" (default): a constant axial force '
        "(axial_load; the constant-pressure preload of seeds 000 and 001), the shaft free to "
        'move axially under the other loads. "position": the rings held at the axial offset '
        "axial_load sets alone (perfect bearing, no radial load), whatever the other loads. "
        "A spindle's kind is its [spindle] key (preload: spring, preload_displacement: "
        "position); [dynamics] axial_dof = true / false of older case files reads as spring / "
        "position.",
        "-",
        (N, N, R, R, H, N, N),
        {
            "linear": "its radial gains are the same for both kinds (the axial and radial "
            "motions of a uniform bearing decouple to first order)",
            "quasi_static_2d": "it is planar: both kinds move the shaft alike while every "
            "ball stays loaded, and it refuses a radial load that unloads balls",
            "quasi_static_3d": _SPRING_ONLY + " (seed 000)",
            "equilibrium": _SPRING_ONLY,
            "roller_constraint": "a cylindrical roller bearing carries no axial load",
            "spindle": "its preload kind is its [spindle] key (preload: spring, "
            "preload_displacement: position), which a contradicting operation.preload is "
            "refused against",
        },
        _position_preload,
    ),
    KeyConvention(
        "operation.radial_load",
        "Radial load on the shaft along radial_load_direction; the radial measuring direction.",
        "N",
        (N, H, H, H, H, N, H),
        {
            "linear": "its gains do not depend on the load; the load only sets the measuring "
            "direction",
            "roller_constraint": "the rigid model does not depend on the size of the measuring "
            "load, only on its direction",
        },
        _table_key("operation", "radial_load"),
    ),
    KeyConvention(
        "operation.radial_load_direction",
        "Direction of the radial load on the shaft, counter-clockwise from +x; default -y.",
        "rad",
        (H, H, H, H, H, H, H),
        {},
        _table_key("operation", "radial_load_direction"),
    ),
    KeyConvention(
        "operation.moment_load",
        "Tilting moment on the shaft (inner ring).",
        "N m",
        (R, R, R, H, R, R, H),
        {m: _NO_TILT for m in MODELS if m not in ("equilibrium", "spindle")},
        _table_key("operation", "moment_load"),
    ),
    KeyConvention(
        "operation.moment_load_direction",
        "Direction of the moment vector, counter-clockwise from +x.",
        "rad",
        (N, N, N, H, N, N, H),
        {m: _NO_TILT for m in MODELS if m not in ("equilibrium", "spindle")},
        _table_key("operation", "moment_load_direction"),
    ),
    KeyConvention(
        'waviness, waviness_spectrum, profile: part = "inner" / "outer"',
        "Radius deviation of a raceway, zero-to-peak, a cos(kθ + φ) in the ring's own frame; "
        "inner: material added positive; outer: radius larger positive.",
        "m, rad",
        (H, H, H, N, H, H, H),
        {"equilibrium": _NOT_SOLVED},
        _entries(("inner", "outer")),
    ),
    KeyConvention(
        'waviness, waviness_spectrum, profile: part = "ball" / "roller"',
        "Radius deviation of an element in its own frame (phase_frame); enters as the "
        "diameter deviation along the contact line (seed 002 eq. 26).",
        "m, rad",
        (H, H, H, N, H, H, H),
        {"equilibrium": _NOT_SOLVED},
        _entries(("ball", "roller")),
    ),
    KeyConvention(
        "slant",
        "Inner-raceway slant (seed 002 eq. 34): a two-per-revolution axial tilt of the groove.",
        "m or rad",
        (H, R, R, N, R, R, R),
        {
            "quasi_static_2d": _SLANT,
            "quasi_static_3d": _SLANT,
            "dynamic": _SLANT,
            "roller_constraint": _SLANT,
            "equilibrium": _NOT_SOLVED,
            "spindle": "a slant is not given per bearing ([slant] has no bearing = key)",
        },
        _table("slant"),
    ),
    KeyConvention(
        "elements.diameter_errors",
        "Size error of each element's diameter (order 0 of its deviation).",
        "m",
        (H, H, H, N, H, H, H),
        {"equilibrium": _NOT_SOLVED},
        _element_list("diameter_errors"),
    ),
    KeyConvention(
        "elements.pitch_errors",
        "Angular position error of each element in the cage, counter-clockwise.",
        "rad",
        (H, H, H, N, H, H, H),
        {"equilibrium": _NOT_SOLVED},
        _element_list("pitch_errors"),
    ),
    KeyConvention(
        "elements.phase_frame",
        "Frame of element waviness phases: cage (0 along the outward radius at t = 0) or fixed "
        "(0 along +x for every element, seed 004 eq. 7).",
        "-",
        (H, H, H, N, H, H, H),
        {"equilibrium": _NOT_SOLVED},
        _table_key("elements", "phase_frame"),
    ),
    KeyConvention(
        "elements.grade, grade_sigma_divisor, grade_form_order",
        "ISO 3290-1 grade of the balls (G3 to G200) and the number of standard deviations its "
        "lot diameter variation V_DWL is taken as (default 6): a Monte Carlo draws the balls' "
        "diameters with sigma = V_DWL / divisor ([study.vary] ball_grade), and with "
        "grade_form_order each ball's form harmonic up to the grade's bound.",
        "-",
        (N, N, N, N, N, N, N),
        {m: _GRADE_IN_A_RUN for m in MODELS},
        _grade_keys,
    ),
    KeyConvention(
        "analysis.revolutions, samples",
        "Length of the record in revolutions of the rotating ring, and its number of instants.",
        "-",
        (H, H, H, N, H, H, H),
        {"equilibrium": "it solves one static instant"},
        _analysis_range,
    ),
    _option_of(
        "linear",
        "analysis.linear_variant",
        "Contact model of the linear model: radial spring (seed 002) or force balance.",
        "-",
        "it is a linear-model option",
        _table_key("analysis", "linear_variant"),
    ),
    _option_of(
        "equilibrium",
        "analysis.race_control",
        "Raceway resisting the gyroscopic moment (Jones-Harris).",
        "-",
        "it is an equilibrium-model option",
        _table_key("analysis", "race_control"),
    ),
    _option_of(
        "equilibrium",
        "analysis.moment_arm",
        "Arm of the balls' axial forces in the moment equations: radius of the inner groove "
        "curvature centres (Harris) or the pitch radius (ISO/TS 16281).",
        "-",
        "it is an equilibrium-model option",
        _table_key("analysis", "moment_arm"),
    ),
    _option_of(
        "equilibrium",
        "analysis.bearing_damping, bearing_damping_coefficient",
        "Damping of the bearing coefficients, c = β k for every coefficient: Krämer's estimate "
        "(β = 0.79e-5 s; Dynamics of Rotors and Foundations, 1993) or the user's β.",
        "s",
        "it gives no bearing coefficients (the equilibrium model's stiffness is what is damped)",
        _damping_keys,
    ),
    KeyConvention(
        "analysis.ring_tilt",
        "The inner ring's tilts in the equilibrium model: \"free\" (default; the balls' moment "
        'balances moment_load) or "held" at 0, the balls\' moment then a reaction (JSON '
        "reaction_moment_n_m); held with a moment_load is refused.",
        "-",
        (R, R, R, H, R, R, R),
        {
            "linear": _NO_TILT,
            "quasi_static_2d": _TWO_D + ": " + _NO_TILT,
            "quasi_static_3d": _TILT_HELD,
            "dynamic": _TILT_HELD,
            "roller_constraint": _TWO_D + ": " + _NO_TILT,
            "spindle": "the tilt of its shaft follows from the bearing set and the shaft, not "
            "from this key",
        },
        _table_key("analysis", "ring_tilt"),
    ),
    KeyConvention(
        "analysis.bands",
        'Band values from the lines along the measuring direction: "iso15242" (rms velocity '
        "in the ISO 15242-1 bands, edges scaled from 1800 rpm to the speed; JSON iso15242) or "
        '"anderon" (Anderon bands in orders; the linear model always gives them, from x).',
        "-",
        (H, H, H, R, H, H, H),
        {"equilibrium": _NO_LINES},
        _table_key("analysis", "bands"),
    ),
    KeyConvention(
        "analysis.limit_bore",
        "Bore d of the bearing, which selects the K_ia row of an ISO 492 tolerance class limit "
        '(limit = "P4"; ISO 492:2014, 2.5 mm < d <= 120 mm).',
        "m",
        (H, H, H, R, H, H, H),
        {"equilibrium": _NOT_SOLVED + ": it gives no runout to compare"},
        _table_key("analysis", "limit_bore"),
    ),
    KeyConvention(
        'analysis.limit_on = "axial_pp"',
        "A spec limit on the axial runout p-p.",
        "-",
        (R, R, H, R, R, R, H),
        {
            "linear": "it gives the radial displacement only",
            "quasi_static_2d": _TWO_D,
            "equilibrium": _NOT_SOLVED,
            "dynamic": 'its rotor is held axially with operation.preload = "position"',
            "roller_constraint": _TWO_D,
        },
        _axial_limit,
        {"dynamic": lambda spec: spec.preload_kind == "spring"},
    ),
    KeyConvention(
        "analysis.limit",
        "Spec limit on analysis.limit_on (default the radial p-p): a length [m], or a velocity "
        "[m/s] for an ISO 15242 band; run: JSON verdict (pass: value <= limit), study: JSON "
        "yield with a Clopper-Pearson 95 % interval.",
        "m or m/s",
        (H, H, H, R, H, H, H),
        {"equilibrium": _NOT_SOLVED + ": it gives no runout to compare"},
        _table_key("analysis", "limit"),
    ),
    KeyConvention(
        "spindle, bearings",
        "A rigid shaft on two or more [[bearings]] (each a [bearing] with name and axial "
        "position): arrangement (DB, DF, DT), spring or position preload, and the nose position "
        "where the runout is reported; imperfection tables name their bearing.",
        "m, N",
        (R, R, R, R, R, R, H),
        {
            m: "it runs one bearing: a case with [[bearings]] is refused when it is read "
            '(analysis.model), and runs in model = "spindle"'
            for m in MODELS
            if m != "spindle"
        },
        _spindle_tables,
    ),
    KeyConvention(
        "defect",
        "Localized defect (spall) of width along the rolling direction and depth on the outer "
        "or inner raceway (at angle, ring frame) or on a ball (element): the contact approach "
        "of a ball over it drops by the depth its centre can reach.",
        "m, rad",
        (R, R, R, R, H, R, R),
        {
            m: "it has no impacts: a spall is a short, local loss of contact that only the "
            "time integration of the dynamic model resolves"
            for m in MODELS
            if m != "dynamic"
        },
        _entry_list("defect"),
    ),
    KeyConvention(
        "analysis.signal, sensor",
        'signal = "acceleration": the housing acceleration along the measuring direction, the '
        "bearing's force on the outer ring through one resonance of the housing ([sensor] "
        "resonance, damping_ratio, sample_rate, noise) or several ([[sensor.modes]], their "
        "accelerations added), and its envelope spectrum.",
        "Hz, -",
        (R, R, R, R, H, R, R),
        {
            m: "it computes no contact force history to make an acceleration from"
            for m in MODELS
            if m != "dynamic"
        },
        _signal_keys,
    ),
    _option_of(
        "dynamic",
        "dynamics",
        "Rotor mass, damping, unbalance and integration settings.",
        "kg, N s/m, kg m, s",
        "it has no rotor dynamics",
        _table("dynamics"),
    ),
)


def honouring_models(convention: KeyConvention) -> list[str]:
    """Models that honour a key.

    Parameters
    ----------
    convention : KeyConvention
        One row of :data:`KEYS`.

    Returns
    -------
    list of str
        Model ids whose column says ``honoured``, in :data:`MODELS` order.
    """
    return [m for m in MODELS if convention.status(m) == "honoured"]


# --------------------------------------------------------------------------------------------
# applying it to a case
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Applicability:
    """What one model does with one case.

    Attributes
    ----------
    model : str
        Model id.
    uses : list of (key path, status)
        Every key the case sets, with the model's treatment.
    refusals : list of (key path, message)
        Keys the model refuses (the first one ends a run with exit 2).
    notes : list of str
        Keys the model does not apply, and how it reads some combinations; these go into the
        JSON ``notes`` and the readable summary.
    """

    model: str
    uses: list[tuple[str, Status]]
    refusals: list[tuple[str, str]]
    notes: list[str]


def _rows(spec: CaseSpec) -> Iterator[tuple[KeyConvention, str]]:
    for convention in KEYS:
        for path in convention.present(spec):
            yield convention, path


def applicability(spec: CaseSpec, model: str) -> Applicability:
    """Apply the table to a validated case specification for ``model``.

    Parameters
    ----------
    spec : CaseSpec
        The validated case-file tables.
    model : str
        Model id.

    Returns
    -------
    Applicability
        Every key the case sets with its status, the refusals and the notes.
    """
    uses: list[tuple[str, Status]] = []
    refusals: list[tuple[str, str]] = []
    notes: list[str] = []
    for convention, path in _rows(spec):
        status = convention.status(model, spec)
        uses.append((path, status))
        why = convention.why.get(model, "")
        if status == "refused":
            others = ", ".join(f'"{m}"' for m in honouring_models(convention))
            refusals.append(
                (path, f"not honoured by the {model} model: {why}; model = {others} honours it")
            )
        elif status == "not_applicable":
            notes.append(f"{path}: not applied by the {model} model ({why})")
    notes += _combination_notes(spec, model)
    return Applicability(model, uses, refusals, notes)


def _combination_notes(spec: CaseSpec, model: str) -> list[str]:
    """Readings of key combinations a user should be told about."""
    out: list[str] = []
    b = spec.lead_bearing
    if (
        model in ("linear", "quasi_static_3d")  # 2-D: the clearance also sets δ_0
        and b.contact_angle is not None
        and (b.radial_clearance > 0.0 or b.nominal_contact_angle is not None)
    ):
        key = (
            "bearing.nominal_contact_angle"
            if b.nominal_contact_angle is not None
            else "bearing.radial_clearance"
        )
        out.append(
            f"{key}: not used by the {model} model here: the contact angle is held at "
            f"bearing.contact_angle = {math.degrees(b.contact_angle):.6g} deg, and the "
            "clearance enters only through the contact angle"
        )
    op = spec.operation
    if (
        model != "roller_constraint"
        and "radial_load_direction" in op.model_fields_set
        and op.radial_load == 0.0
    ):
        out.append(
            "operation.radial_load_direction: not applied by the "
            f"{model} model without a radial load (the measuring direction is then x)"
        )
    fixed_frame = any(t.phase_frame == "fixed" for _, t in spec.element_tables)
    if model != "equilibrium" and not fixed_frame:
        for path in _entries(("ball", "roller"), coherent_only=True)(spec):
            out.append(
                f"{path}: no element given, so every element carries this deviation with the "
                "same phase in its own frame (a coherent worst case); give element = j for one "
                'element, or a waviness_spectrum with phase = "random" for independent elements'
            )
    return out


def enforce(case: Case, model: str | None = None) -> tuple[str, ...]:
    """Refuse what ``model`` (default the case's) refuses; return the notes it must carry.

    Parameters
    ----------
    case : Case
        The case; one built in code (no ``spec``) is not checked.
    model : str or None
        Model id; None: the case's ``[analysis] model``.

    Returns
    -------
    tuple of str
        The notes the result must carry (keys not applied, combinations read one way).

    Raises
    ------
    CaseError
        Naming the case file, the refused key and the models that honour it.
    """
    spec = getattr(case, "spec", None)
    if spec is None:  # built in code, not from a case file: nothing to compare with
        return ()
    found = applicability(spec, model or case.analysis.model)
    if found.refusals:
        key, message = found.refusals[0]
        raise CaseError(case.path, key, message)
    return tuple(found.notes)


# --------------------------------------------------------------------------------------------
# the documentation page
# --------------------------------------------------------------------------------------------
_SYMBOL = {"honoured": "✓", "refused": "✗ refused", "not_applicable": "– note"}


def conventions_page() -> str:
    """Markdown of ``docs/conventions.md``: the frame, then the key × model matrix.

    Returns
    -------
    str
        The page's Markdown: the frame, the key × model matrix, each key's meaning and unit,
        and the combinations read one way.
    """
    doc = (__doc__ or "").split("\n\n", 1)[1].strip()
    lines = [
        "# Conventions: one meaning per key, in every model",
        "",
        "Generated from `runout.case.conventions` by `python -m runout.case.conventions`; do not "
        "edit by hand. A test runs every cell of the matrix.",
        "",
        doc,
        "",
        "## Key × model matrix",
        "",
        "✓ honoured (changes the result); ✗ refused (exit 2, the message names the key and the "
        "models that honour it); – not applied (the run goes on; the JSON `notes` and the "
        "readable summary name the key).",
        "",
        "| key | unit | " + " | ".join(_SHORT[m] for m in MODELS) + " |",
        "|---|---|" + "---|" * len(MODELS),
    ]
    for c in KEYS:
        cells = " | ".join(_SYMBOL[c.status(m)] for m in MODELS)
        lines.append(f"| `{c.key}` | {c.unit} | {cells} |")
    lines += ["", "## Meaning of each key", ""]
    for c in KEYS:
        lines.append(f"- **`{c.key}`** [{c.unit}]: {c.meaning}")
        for m in MODELS:
            if c.status(m) != "honoured":
                verb = "refuses" if c.status(m) == "refused" else "does not apply it"
                lines.append(f"  - `{m}` {verb}: {c.why.get(m, '')}.")
    lines += [
        "",
        "## Combinations the models read in one way",
        "",
        "- `contact_angle` with `radial_clearance` (or `nominal_contact_angle`) in `linear` and "
        "`quasi_static_3d`: the angle is held, and the clearance, which enters these models "
        "only through the contact angle, is not used (a note says so). In `quasi_static_2d` the "
        "clearance still sets the preload approach δ_0.",
        "- Conformities (or groove radii) with `nominal_contact_angle` in `roller_constraint`: "
        "they set the clearance P_d = 2A(1 - cos α⁰), so they are honoured there.",
        "- `radial_load_direction` without a radial load: the measuring direction is x in every "
        "model but `roller_constraint` (whose measuring load always has a direction); a note "
        "says so.",
        "- Element waviness without `element` (and not a random-phase spectrum): every element "
        "carries the deviation with the same phase in its own frame, a coherent worst case (a "
        "note says so).",
        "- A radially loaded bearing without axial preload has radial play P_d/2 per ball in "
        "`dynamic`, and in `equilibrium` once at least 3 balls carry the load (its ring is free "
        "to tilt and to move axially); `quasi_static_2d` and `quasi_static_3d` need an axial "
        "preload and refuse the case, naming those two.",
        "",
    ]
    return "\n".join(lines)


if __name__ == "__main__":
    import sys

    sys.stdout.write(conventions_page())
