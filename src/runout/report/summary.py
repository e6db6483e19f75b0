"""Readable summaries: what `runout check`, `runout frequencies` and `runout run` print.

:func:`bearing_summary` gathers the derived quantities of a bearing at an operating point; its
result renders as JSON (SI values, unit in the key) or as tables. :func:`result_sections` gives
the tables of a run result (:class:`runout.analysis.results.RunResult`, also one read back from its
JSON).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from runout.analysis.result_details import (
    DynamicDetails,
    EquilibriumDetails,
    LinearDetails,
    RollerDetails,
    SpindleDetails,
    Verdict,
)
from runout.analysis.results import ROLLER_ALIASES, RunResult, frequencies_json
from runout.geometry.bearing import BallBearing, Bearing, Operation, RollerBearing
from runout.geometry.contact import (
    BallContacts,
    RollerContacts,
    ball_race_contacts,
    roller_race_contacts,
)
from runout.geometry.kinematics import Frequencies, bearing_frequencies
from runout.geometry.life import RatingLife
from runout.geometry.loading import AxialLoading, operating_contact_angle

__all__ = [
    "BearingSummary",
    "ModelUse",
    "bearing_summary",
    "model_use",
    "operating_contact_angle",
    "result_sections",
    "verdict_line",
]

Rows = list[tuple[str, str, str]]


@dataclass(frozen=True)
class BearingSummary:
    """Derived geometry, Hertz contacts and frequencies of one bearing at one operating point.

    Made by :func:`bearing_summary`.

    Attributes
    ----------
    bearing : BallBearing or RollerBearing
        The bearing.
    operation : Operation
        Its operating point (speed, rotating ring, loads).
    contact_angle : float
        Contact angle the bearing runs at [rad]
        (:func:`runout.geometry.loading.operating_contact_angle`).
    frequencies : Frequencies
        Characteristic frequencies at that angle [Hz].
    contacts : BallContacts or RollerContacts or None
        Hertz point contacts of a ball bearing at that angle, or the line contacts of a roller
        bearing with a roller length; None for a roller bearing without one.
    loading : AxialLoading or None
        The static axial-load solution, when one was computed.
    """

    bearing: Bearing
    operation: Operation
    contact_angle: float
    frequencies: Frequencies
    contacts: BallContacts | RollerContacts | None
    loading: AxialLoading | None

    # ------------------------------------------------------------------------ JSON
    def to_json(self) -> dict[str, Any]:
        """Plain-JSON dictionary; SI values with the unit in the key name.

        Returns
        -------
        dict
            ``bearing``, ``derived``, ``contact`` (when there are contacts), ``axial_loading``
            (when computed), ``contact_angle_deg``, ``frequencies_hz`` and ``orders`` (None at
            zero speed).
        """
        b = self.bearing
        out: dict[str, Any] = {"bearing": _bearing_json(b), "derived": _derived_json(b)}
        if isinstance(self.contacts, BallContacts):
            c = self.contacts
            out["contact"] = {
                "contact_angle_deg": math.degrees(c.contact_angle),
                "inner": _point_json(c.inner),
                "outer": _point_json(c.outer),
                "combined_stiffness_n_per_m1_5": c.combined_stiffness,
            }
        elif isinstance(self.contacts, RollerContacts):
            out["contact"] = {
                "combined_stiffness_n_per_m10_9": self.contacts.combined_stiffness,
            }
        if self.loading is not None:
            ld = self.loading
            out["axial_loading"] = {
                "axial_load_n": ld.axial_load,
                "contact_angle_deg": math.degrees(ld.contact_angle),
                "ball_load_n": ld.ball_load,
                "inner_approach_m": ld.inner_approach,
                "outer_approach_m": ld.outer_approach,
                "axial_displacement_m": ld.axial_displacement,
            }
        out["contact_angle_deg"] = math.degrees(self.contact_angle)
        element = self.element
        out["frequencies_hz"] = frequencies_json(self.frequencies.to_dict(), element)
        out["orders"] = (
            frequencies_json(self.frequencies.orders(), element)
            if self.frequencies.rotation > 0
            else None
        )
        return out

    @property
    def element(self) -> str:
        """``"roller"`` or ``"ball"``: the name of the passage frequencies."""
        return "roller" if isinstance(self.bearing, RollerBearing) else "ball"

    # ------------------------------------------------------------------------ tables
    def sections(self) -> list[tuple[str, Rows]]:
        """Titled rows (quantity, value, unit) for the readable output.

        Returns
        -------
        list of (title, rows)
            Geometry, contacts, axial loading (when computed) and frequencies; rows are
            (quantity, value, unit) strings.
        """
        b = self.bearing
        geometry: Rows = [
            ("type", b.kind, ""),
            ("elements Z", str(b.elements), ""),
            ("element diameter D", f"{b.element_diameter * 1e3:.6g}", "mm"),
            ("pitch diameter d_m", f"{b.pitch_diameter * 1e3:.6g}", "mm"),
            ("inner raceway diameter d_i", f"{b.inner_raceway_diameter * 1e3:.6g}", "mm"),
            ("outer raceway diameter d_o", f"{b.outer_raceway_diameter * 1e3:.6g}", "mm"),
            ("radial clearance P_d (diametral)", f"{b.radial_clearance * 1e6:.6g}", "um"),
        ]
        if isinstance(b, BallBearing):
            geometry += [
                (
                    "inner / outer conformity f_i / f_o",
                    f"{b.inner_conformity:.4g} / {b.outer_conformity:.4g}",
                    "",
                ),
                (
                    "groove radii r_i / r_o",
                    f"{b.inner_groove_radius * 1e3:.6g} / {b.outer_groove_radius * 1e3:.6g}",
                    "mm",
                ),
                ("total curvature B = f_i + f_o - 1", f"{b.total_curvature:.6g}", ""),
                ("groove-centre distance A = B D", f"{b.curvature_distance * 1e6:.6g}", "um"),
                ("free contact angle α⁰", f"{math.degrees(b.free_contact_angle):.4f}", "deg"),
                ("free end play 2 A sin α⁰", f"{b.free_end_play * 1e6:.6g}", "um"),
            ]
        sections: list[tuple[str, Rows]] = [("Geometry", geometry)]
        if isinstance(self.contacts, BallContacts):
            c = self.contacts
            rows: Rows = [("at contact angle", f"{math.degrees(c.contact_angle):.4f}", "deg")]
            for name, pc in (("inner", c.inner), ("outer", c.outer)):
                rows += [
                    (f"{name}: curvature sum Σρ", f"{pc.curvature_sum * 1e-3:.6g}", "1/mm"),
                    (f"{name}: curvature difference F(ρ)", f"{pc.curvature_difference:.6g}", ""),
                    (f"{name}: ellipticity a/b", f"{pc.ellipticity:.6g}", ""),
                    (f"{name}: K (Q = K δ^1.5)", f"{pc.stiffness:.6g}", "N/m^1.5"),
                ]
            rows.append(("combined K_n (seed 000 eq. 4)", f"{c.combined_stiffness:.6g}", "N/m^1.5"))
            sections.append(("Hertz contacts", rows))
        elif isinstance(self.contacts, RollerContacts):
            sections.append(
                (
                    "Line contacts (Palmgren)",
                    [
                        (
                            "combined K_n (Q = K_n δ^(10/9))",
                            f"{self.contacts.combined_stiffness:.6g}",
                            "N/m^(10/9)",
                        )
                    ],
                )
            )
        if self.loading is not None:
            ld = self.loading
            sections.append(
                (
                    f"Axial load {ld.axial_load:.6g} N (static, "
                    + (
                        "at the fixed contact angle)"
                        if isinstance(b, BallBearing) and b.contact_angle is not None
                        else "Harris load-angle relation)"
                    ),
                    [
                        ("loaded contact angle α", f"{math.degrees(ld.contact_angle):.4f}", "deg"),
                        ("ball load Q", f"{ld.ball_load:.6g}", "N"),
                        ("approach inner δ_i", f"{ld.inner_approach * 1e6:.5g}", "um"),
                        ("approach outer δ_o", f"{ld.outer_approach * 1e6:.5g}", "um"),
                        ("axial displacement", f"{ld.axial_displacement * 1e6:.5g}", "um"),
                    ],
                )
            )
        f = self.frequencies
        orders = f.orders() if f.rotation > 0 else None
        freq_rows: Rows = []
        for key, value in f.to_dict().items():
            order = "" if orders is None else f"   ({orders[key]:.6g} /rev)"
            # a roller bearing's passages are named for rollers (JSON: both names)
            name = ROLLER_ALIASES.get(key, key) if self.element == "roller" else key
            freq_rows.append((name, f"{value:.6g}{order}", "Hz"))
        sections.append(
            (
                f"Frequencies ({self.operation.rotating_ring} ring rotating, contact angle "
                f"{math.degrees(self.contact_angle):.4f} deg)",
                freq_rows,
            )
        )
        return sections


def _bearing_json(b: Bearing) -> dict[str, Any]:
    common = {
        "type": b.kind,
        "elements": b.elements,
        "element_diameter_m": b.element_diameter,
        "pitch_diameter_m": b.pitch_diameter,
        "radial_clearance_m": b.radial_clearance,
    }
    if isinstance(b, BallBearing):
        common.update(
            inner_conformity=b.inner_conformity,
            outer_conformity=b.outer_conformity,
            contact_angle_deg=None if b.contact_angle is None else math.degrees(b.contact_angle),
        )
    else:
        common.update(roller_length_m=b.roller_length)
    m = b.material
    common["material"] = {
        "youngs_modulus_pa": m.youngs_modulus,
        "poisson_ratio": m.poisson_ratio,
        "density_kg_per_m3": m.density,
    }
    return common


def _derived_json(b: Bearing) -> dict[str, Any]:
    out: dict[str, Any] = {
        "inner_raceway_diameter_m": b.inner_raceway_diameter,
        "outer_raceway_diameter_m": b.outer_raceway_diameter,
    }
    if isinstance(b, BallBearing):
        out.update(
            inner_groove_radius_m=b.inner_groove_radius,
            outer_groove_radius_m=b.outer_groove_radius,
            total_curvature=b.total_curvature,
            curvature_distance_m=b.curvature_distance,
            free_contact_angle_deg=math.degrees(b.free_contact_angle),
            free_end_play_m=b.free_end_play,
        )
    return out


def _point_json(pc: Any) -> dict[str, float]:
    return {
        "curvature_sum_per_m": pc.curvature_sum,
        "curvature_difference": pc.curvature_difference,
        "ellipticity": pc.ellipticity,
        "stiffness_n_per_m1_5": pc.stiffness,
    }


def bearing_summary(bearing: Bearing, operation: Operation) -> BearingSummary:
    """Gather the derived geometry, contacts and frequencies of ``bearing`` at ``operation``.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
    operation : Operation

    Returns
    -------
    BearingSummary
    """
    alpha, loading = operating_contact_angle(bearing, operation)
    contacts: BallContacts | RollerContacts | None
    if isinstance(bearing, BallBearing):
        contacts = ball_race_contacts(bearing, alpha)
    elif bearing.roller_length is not None:
        contacts = roller_race_contacts(bearing)
    else:
        contacts = None
    return BearingSummary(
        bearing=bearing,
        operation=operation,
        contact_angle=alpha,
        frequencies=bearing_frequencies(bearing, operation, alpha),
        contacts=contacts,
        loading=loading,
    )


#: How each model arrives at its contact angle (for ``runout check``).
_ANGLE_SOURCE = {
    "linear": "held at bearing.contact_angle, else the static axial-load angle",
    "quasi_static_2d": "held at bearing.contact_angle, else the static axial-load angle",
    "quasi_static_3d": "held at bearing.contact_angle, else the static axial-load angle",
    "equilibrium": "solved per ball at speed (static axial-load angle shown)",
    "dynamic": "from the clearance and the axial preload (static axial-load angle shown)",
    "roller_constraint": "0 (rigid model in the radial plane)",
    "spindle": "per bearing: held at its contact_angle, else its loaded angle at the preload "
    "it carries (the first bearing's shown)",
}


@dataclass(frozen=True)
class ModelUse:
    """What one model will take from a case: effective inputs and each key's treatment.

    Attributes
    ----------
    model : str
        Model id.
    contact_angle : float
        Effective contact angle [rad] (see :data:`_ANGLE_SOURCE` for how the model gets it).
    radial_clearance : float
        Diametral play P_d [m].
    preload_approach : float or None
        Elastic approach of a ball along its contact line under the axial preload [m].
    keys : list of (key path, status)
        Each case key with how the model treats it (``"honoured"``, ``"refused"``,
        ``"not_applicable"``).
    notes : list of str
        Sentences on keys and key combinations.
    refusals : list of (key path, message)
        The keys the model refuses, with why.
    """

    model: str
    contact_angle: float
    radial_clearance: float
    preload_approach: float | None
    keys: list[tuple[str, str]]
    notes: list[str]
    refusals: list[tuple[str, str]]

    def to_json(self) -> dict[str, Any]:
        """JSON entry ``model_use`` of ``runout check --json``.

        Returns
        -------
        dict
            Plain-JSON dictionary; SI values with the unit in the key name.
        """
        return {
            "model": self.model,
            "contact_angle_deg": math.degrees(self.contact_angle),
            "contact_angle_from": _ANGLE_SOURCE[self.model],
            "radial_clearance_m": self.radial_clearance,
            "radial_play_per_ball_m": 0.5 * self.radial_clearance,
            "preload_approach_m": self.preload_approach,
            "keys": [{"key": k, "status": s} for k, s in self.keys],
            "notes": list(self.notes),
            "refusals": [{"key": k, "message": m} for k, m in self.refusals],
        }

    def rows(self) -> Rows:
        """Readable rows for ``runout check``.

        Returns
        -------
        list of (quantity, value, unit)
            Effective inputs, then each key's treatment, the notes and the refusals.
        """
        rows: Rows = [
            ("contact angle", f"{math.degrees(self.contact_angle):.4f}", "deg"),
            ("  how", _ANGLE_SOURCE[self.model], ""),
            ("radial clearance P_d (diametral)", f"{self.radial_clearance * 1e6:.6g}", "um"),
            ("radial play per ball P_d/2", f"{0.5 * self.radial_clearance * 1e6:.6g}", "um"),
        ]
        if self.preload_approach is not None:
            rows.append(
                ("preload approach (along the contact)", f"{self.preload_approach * 1e6:.5g}", "um")
            )
        words = {"honoured": "honoured", "refused": "REFUSED", "not_applicable": "not applied"}
        rows += [(key, words[status], "") for key, status in self.keys]
        # the not-applied keys are listed above; the other notes read key combinations
        rows += [("note: " + n, "", "") for n in self.notes if ": not applied by the" not in n]
        rows += [(f"{key}: {message}", "", "") for key, message in self.refusals]
        return rows


def model_use(case: Any, model: str | None = None) -> ModelUse:
    """What ``model`` (default the case's ``[analysis] model``) takes from ``case``.

    Parameters
    ----------
    case : runout.case.model.Case
        A validated case (read from a file: the key table needs its ``spec``).
    model : str, optional
        Model id.

    Returns
    -------
    ModelUse
        The effective contact angle, clearance and preload approach, and each key's treatment
        (no keys for a case not read from a file).
    """
    from runout.case.conventions import applicability

    model = model or case.analysis.model
    bearing, op = case.bearing, case.operation
    alpha, loading = operating_contact_angle(bearing, op)
    if model == "roller_constraint":
        alpha = 0.0
    approach = None
    if loading is not None and model not in ("roller_constraint", "linear"):
        approach = loading.total_approach
    if model == "spindle" and getattr(case, "spindle", None) is not None:
        from runout.base.errors import GeometryError
        from runout.models import spindle

        try:  # the first bearing at the preload it carries (the spindle's own set-up)
            lead = spindle.setup(case.spindle, op).bearings[0]
            alpha, approach = lead.contact_angle, lead.approach
        except GeometryError:
            pass  # the run names the key; the check shows the case as read
    found = applicability(case.spec, model) if getattr(case, "spec", None) is not None else None
    return ModelUse(
        model=model,
        contact_angle=alpha,
        radial_clearance=bearing.radial_clearance,
        preload_approach=approach,
        keys=[(k, s) for k, s in found.uses] if found else [],
        notes=list(found.notes) if found else [],
        refusals=list(found.refusals) if found else [],
    )


# --------------------------------------------------------------------------------------------
# the readable tables of a run result (`runout run`)
# --------------------------------------------------------------------------------------------
def result_sections(result: RunResult) -> list[tuple[str, Rows]]:
    """Readable tables of a run: runout figures, the largest lines, band values, verdict, notes.

    Lengths are shown in one unit per table, chosen over the figures it shows
    (:func:`runout.base.display.length_unit`); figures below
    :meth:`~runout.analysis.results.RunResult.resolution_m` print as 0, and a note states the
    resolution once. A section whose rows carry no value and no unit (the notes, the verdict)
    is a list of sentences. The equilibrium model (one instant) shows its ring displacements,
    stiffness and balls instead; the linear model adds its Anderon comparison and the
    frequency attribution table.

    Parameters
    ----------
    result : RunResult
        A model's result, or one read back (:meth:`~runout.analysis.results.RunResult.from_json`).

    Returns
    -------
    list of (title, rows)
        Rows are (quantity, value, unit).
    """
    details = result.details
    if isinstance(details, EquilibriumDetails):
        return _equilibrium_sections(result, details)
    sections = _run_sections(result)
    if isinstance(details, LinearDetails):
        sections += _linear_sections(result, details)
    if isinstance(details, SpindleDetails):
        sections.insert(1, ("Spindle: the shaft and its bearings", _spindle_rows(details)))
    return sections


def _spindle_rows(details: SpindleDetails) -> Rows:
    """Tilt, each bearing's runout at its plane and the nose stiffness of a spindle run."""
    from runout.base.display import length_unit

    unit = length_unit(b.runout.radial_pp_m or 0.0 for b in details.bearings)
    tilt = details.tilt_pp_rad
    rows: Rows = [
        (
            "arrangement, nose position",
            f"{details.arrangement}, {details.nose_position_m * 1e3:.6g}",
            "mm",
        ),
        ("tilt p-p (θx, θy)", f"{tilt[0]:.4g}, {tilt[1]:.4g}", "rad"),
    ]
    for b in details.bearings:
        rows.append(
            (
                f"{b.name} at {b.position_m * 1e3:.6g} mm: radial / axial p-p",
                f"{_length_number(b.runout.radial_pp_m, unit, None)} / "
                f"{_length_number(b.runout.axial_pp_m, unit, None)}",
                unit[0],
            )
        )
        rows.append(
            (
                f"{b.name}: contact angle, preload, pressure centre",
                f"{b.contact_angle_deg:.4g} deg, {b.preload_n:.4g} N, "
                f"{b.pressure_centre_m * 1e3:.4g} mm",
                "",
            )
        )
        if b.life is not None:
            life = b.life
            hours = "" if life.l10r_hours is None else f" ({life.l10r_hours:.6g} h)"
            rows.append(
                (
                    f"{b.name}: reference rating life L10r (ISO/TS 16281)",
                    f"{_life_figure(life.l10r_mrev)}{hours}",
                    "10⁶ rev",
                )
            )
            if life.lnmr_mrev is not None and life.a_iso is not None:
                rows.append(
                    (
                        f"{b.name}: modified life L_nmr (a_1 {life.a1:.4g}, a_ISO "
                        f"{life.a_iso:.4g})",
                        _life_figure(life.lnmr_mrev),
                        "10⁶ rev",
                    )
                )
    k = details.stiffness_matrix.matrix
    tool = details.tool_point_stiffness_n_per_m
    rows.append(
        (
            "tool-point stiffness k_x, k_y, k_z (at the nose, shaft free to tilt: 1/C_ii)",
            ", ".join(f"{v * 1e-6:.4g}" for v in tool),
            "N/µm",
        )
    )
    held = f"{k[0][0] * 1e-6:.4g}, {k[1][1] * 1e-6:.4g}, {k[2][2] * 1e-6:.4g}"
    rows.append(("5×5 matrix diagonal K_xx, K_yy, K_zz (at the nose, tilt held)", held, "N/µm"))
    rows.append(
        (
            "5×5 matrix diagonal K_θxθx, K_θyθy (translation held)",
            f"{k[3][3]:.4g}, {k[4][4]:.4g}",
            "N m/rad",
        )
    )
    return rows


#: The axial p-p of a model without an axial degree of freedom.
NOT_AXIAL = "n/a (no axial freedom)"


def _run_sections(result: RunResult) -> list[tuple[str, Rows]]:
    """The tables every model with a record shows (:func:`result_sections`)."""
    from runout.base.display import length_unit

    r = result.runout
    resolution = result.resolution_m()
    zeroed: list[float] = []  # figures shown as 0 for being below the resolution

    def show(value: float | None, unit: tuple[str, float], absent: str = "n/a") -> str:
        if value is None:  # not a figure of this model (Runout): n/a, never 0
            return absent
        if resolution is not None and 0.0 < abs(value) < resolution:
            zeroed.append(value)
        return _length_number(value, unit, resolution)

    details = result.details
    label = "radial p-p (measuring direction)"
    if isinstance(details, RollerDetails):  # the rigid model: Kia or Kea
        label += f" = {details.iso492.quantity} (ISO 492)"
    figures: list[tuple[str, list[float | None]]] = [(label, [r.radial_pp_m])]
    if isinstance(details, RollerDetails):  # it moves freely across the load
        figures.append(("radial p-p across the load", [details.horizontal_pp_m]))
    figures += [
        ("axial p-p", [r.axial_pp_m]),
        ("RRO p-p", [r.rro_pp_m]),
        ("NRRO p-p", [r.nrro_pp_m]),
    ]
    # the p-p figures share one unit; the mean position (play, approaches: often far
    # larger) has its own, so that a nm-size runout is not shown as 0.01 um
    unit = length_unit(v for _, values in figures for v in values if v is not None)
    rows: Rows = [
        (
            name,
            ", ".join(show(v, unit, NOT_AXIAL if name == "axial p-p" else "n/a") for v in values),
            unit[0] if None not in values else "",
        )
        for name, values in figures
    ]
    if result.time.size or result.record_mean is not None:
        mean = result.mean_displacement()
        mean_unit = length_unit(mean)
        rows.append(
            (
                "mean shaft position rel. outer ring (" + ", ".join("xyz"[: len(mean)]) + ")",
                ", ".join(show(v, mean_unit) for v in mean),
                mean_unit[0],
            )
        )
    if isinstance(details, DynamicDetails):  # the one model that runs either preload kind
        rows.append(
            (
                "preload",
                "spring preload (constant axial force, z free)"
                if details.axial_dof
                else "position preload (rings held at their preloaded axial offset)",
                "",
            )
        )
    sections: list[tuple[str, Rows]] = [
        (
            f"{result.title or result.model}: runout ({result.model} model, contact angle "
            f"{math.degrees(result.contact_angle):.4g} deg)",
            rows,
        )
    ]
    top = result.lines(top=15)
    line_unit = length_unit(c.pp_m for c in top)
    line_rows: Rows = [
        (
            f"{c.direction}  {c.label}",
            f"{show(c.pp_m, line_unit)} {line_unit[0]} at {c.frequency_hz:.5g} Hz",
            f"order {c.order:.5g}",
        )
        for c in top
    ]
    if line_rows:
        sections.append(("Largest lines (peak-to-peak)", line_rows))
    iso = result.iso15242
    if iso is not None:
        sections.append(
            (
                "ISO 15242-1 velocity bands (rms along the measuring direction"
                + ("" if iso.direction == "measuring" else f" {iso.direction}")
                + f", {_plain(iso.speed_rpm, 6)} rpm)",
                [
                    (
                        f"{name}  {_plain(b.low_hz, 4)}-{_plain(b.high_hz, 4)} Hz",
                        _plain(b.rms_um_per_s, 4),
                        iso.unit,
                    )
                    for name, b in iso.bands.items()
                ],
            )
        )
    if result.anderon is not None:
        sections.append(
            (
                "Anderon band values",
                [(band, _plain(value, 4), "Anderon") for band, value in result.anderon.items()],
            )
        )
    if result.verdict is not None:
        sections.append(("Spec limit", [(verdict_line(result.verdict), "", "")]))
    sections += bearing_source_sections(result.bearing_source)
    notes = list(result.notes)
    if zeroed and resolution is not None:
        from runout.base.display import resolution_note

        notes.insert(0, resolution_note(resolution, unit))
    if notes:
        sections.append(("Notes", [(note, "", "") for note in notes]))
    return sections


_ANGLE_KEYS = ("nominal_contact_angle", "contact_angle")
_PLAIN_KEYS = ("elements", "inner_conformity", "outer_conformity")
_DIMENSIONS = ("bore_diameter_m", "outside_diameter_m", "width_m")


def _source_value(key: str, value: float) -> tuple[str, str]:
    if key == "dynamic_load_rating":
        return f"{value / 1e3:.6g}", "kN"
    if key in _ANGLE_KEYS:
        return f"{math.degrees(value):.6g}", "deg"
    if key in _PLAIN_KEYS:
        return f"{value:.6g}", ""
    return f"{value * 1e3:.6g}", "mm"


def bearing_source_sections(
    source: dict[str, Any] | list[dict[str, Any]] | None,
) -> list[tuple[str, Rows]]:
    """Readable tables of a ``bearing_source`` (one per bearing from the catalogue).

    Parameters
    ----------
    source : dict, list of dict, or None
        The JSON ``bearing_source`` object, or a spindle's ``bearing_sources`` list
        (:meth:`runout.case.designation.BearingSource.to_json`).

    Returns
    -------
    list of (title, rows)
        Per bearing, a table (quantity, value, unit) of d, D, B and the values the catalogue
        sets (a value the case replaces shown beside the catalogue's), then the list of where
        they come from, one line per source.
    """
    if source is None:
        return []
    documents = [source] if isinstance(source, dict) else list(source)
    sections: list[tuple[str, Rows]] = []
    for doc in documents:
        if not all(k in doc for k in ("designation", *_DIMENSIONS)):
            continue  # an edited result.json: nothing to show, not an error
        provenance = doc.get("provenance", {})
        given = doc.get("given_in_case", {})
        requested = doc.get("requested", doc["designation"])
        title = doc["designation"]
        if requested != title:
            title = f"{requested} (catalogue row {doc['designation']})"
        name = f", {doc['name']} bearing" if doc.get("name") else ""
        rows: Rows = [
            ("bore d", f"{doc['bore_diameter_m'] * 1e3:.6g}", "mm"),
            ("outside diameter D", f"{doc['outside_diameter_m'] * 1e3:.6g}", "mm"),
            ("width B", f"{doc['width_m'] * 1e3:.6g}", "mm"),
        ]
        for key, value in doc.get("values", {}).items():
            shown, unit = _source_value(key, float(value))
            if key in given:
                shown = f"{_source_value(key, float(given[key]))[0]} (catalogue {shown})"
            rows.append((key, shown, unit))
        sections.append((f"Bearing {title} from the catalogue{name}", rows))
        by_source: dict[str, list[str]] = {}
        for key, text in provenance.items():
            by_source.setdefault(str(text), []).append("d, D, B" if key == "dimensions" else key)
        lines = [(f"{', '.join(keys)}: {text}", "", "") for text, keys in by_source.items()]
        sections.append((f"Where the values of {doc['designation']} come from", lines))
    return sections


def _linear_sections(result: RunResult, details: LinearDetails) -> list[tuple[str, Rows]]:
    """The linear model's Anderon comparison (exact lines vs DFT) and attribution table."""
    from runout.geometry.attribution import attribution_table_rows
    from runout.models.linear import LinearResult

    sections: list[tuple[str, Rows]] = []
    lines = result.spectral_lines if isinstance(result, LinearResult) else None
    if lines is not None and len(lines):
        assert isinstance(result, LinearResult)
        comp = result.anderon_comparison()
        sections.append(
            (
                "Anderon: exact lines vs six-revolution DFT (as seed 002)",
                [
                    (
                        band,
                        f"{v['lines']:.4g} (lines) / {v['dft']:.4g} (DFT)",
                        f"{100 * v['relative_difference']:+.1f} %",
                    )
                    for band, v in comp.items()
                ],
            )
        )
    if details.attribution:
        sections.append(
            ("Frequency attribution", attribution_table_rows(list(details.attribution)))
        )
    return sections


def _tilt_rows(q: tuple[float, ...], details: EquilibriumDetails) -> Rows:
    """The ring's tilts, or, held at 0, the restraint's reaction moment."""
    if details.ring_tilt == "held":
        m = details.reaction_moment_n_m
        return [
            ("tilt θ_x, θ_y", "0 (held)", "mrad"),
            ("reaction moment M_x (restraint on the ring)", f"{m[0]:.6g}", "N m"),
            ("reaction moment M_y (restraint on the ring)", f"{m[1]:.6g}", "N m"),
        ]
    return [("tilt θ_x", f"{q[3] * 1e3:.6g}", "mrad"), ("tilt θ_y", f"{q[4] * 1e3:.6g}", "mrad")]


def _equilibrium_sections(result: RunResult, details: EquilibriumDetails) -> list[tuple[str, Rows]]:
    """Ring displacements, stiffness diagonal, per-ball angles and loads (one instant)."""
    q = details.ring_displacement.as_tuple()
    k = details.stiffness_matrix.matrix
    sections: list[tuple[str, Rows]] = [
        (
            f"{result.title or result.model}: Jones-Harris equilibrium "
            f"({details.race_control} race control, tilt {details.ring_tilt})",
            [
                ("axial displacement δ_a", f"{q[0] * 1e6:.6g}", "µm"),
                ("radial displacement δ_x", f"{q[1] * 1e6:.6g}", "µm"),
                ("radial displacement δ_y", f"{q[2] * 1e6:.6g}", "µm"),
                *_tilt_rows(q, details),
                ("axial stiffness K_aa", f"{k[0][0] * 1e-6:.6g}", "N/µm"),
                ("radial stiffness K_xx", f"{k[1][1] * 1e-6:.6g}", "N/µm"),
                ("radial stiffness K_yy", f"{k[2][2] * 1e-6:.6g}", "N/µm"),
                ("tilt stiffness K_θxθx", f"{k[3][3]:.6g}", "N m/rad"),
                ("tilt stiffness K_θyθy", f"{k[4][4]:.6g}", "N m/rad"),
            ],
        )
    ]
    rows: Rows = []
    for r in details.balls:
        rows.append(
            (
                f"ball {r['ball']:d} at {r['azimuth_deg']:.4g} deg",
                f"α_i {r['inner_contact_angle_deg']:.4f} / α_o "
                f"{r['outer_contact_angle_deg']:.4f} deg",
                f"Q_i {r['inner_load_n']:.5g} / Q_o {r['outer_load_n']:.5g} N; "
                f"δ_i {r['inner_approach_m'] * 1e6:.5g} / δ_o "
                f"{r['outer_approach_m'] * 1e6:.5g} µm",
            )
        )
    sections.append(("Balls (contact angles, loads, approaches)", rows))
    if details.life is not None:
        sections.append(("Reference rating life (ISO/TS 16281)", _life_rows(details.life)))
    if result.notes:
        sections.append(("Notes", [(n, "", "") for n in result.notes]))
    return sections


def _life_figure(value: float | None) -> str:
    """A life to 6 figures; ``n/a`` beyond the floating-point range or none."""
    return "n/a" if value is None else f"{value:.6g}"


def _life_rows(life: RatingLife) -> Rows:
    """L10r, the rings' lives and the loads they come from (``n/a``: beyond range or none)."""
    figure = _life_figure

    rows: Rows = [
        ("L10r", figure(life.l10r_mrev), "10⁶ rev"),
        (
            "L10r of the inner / outer ring",
            f"{figure(life.l10r_inner_mrev)} / {figure(life.l10r_outer_mrev)}",
            "10⁶ rev",
        ),
    ]
    if life.l10r_hours is not None:
        rows.append(("L10r at this speed", f"{life.l10r_hours:.6g}", "h"))
    rows += [
        (
            "equivalent ball load Q_ei / Q_ee",
            f"{life.equivalent_inner_load_n:.6g} / {life.equivalent_outer_load_n:.6g}",
            "N",
        ),
        (
            "contact ratings Q_ci / Q_ce",
            f"{life.inner_contact_rating_n:.6g} / {life.outer_contact_rating_n:.6g}",
            "N",
        ),
        ("dynamic load rating C", f"{life.dynamic_load_rating_n:.6g}", "N"),
        ("equivalent reference load P_ref", figure(life.equivalent_reference_load_n), "N"),
        ("nominal contact angle of the rating", f"{life.nominal_contact_angle_deg:.6g}", "deg"),
    ]
    if life.a_iso is not None and life.lnmr_mrev is not None:
        rows += [
            ("modified life L_nmr = a_1 a_ISO L10r", figure(life.lnmr_mrev), "10⁶ rev"),
            (
                "a_1 / a_ISO",
                f"{life.a1:.4g} ({life.reliability_percent:g} %) / {life.a_iso:.4g}",
                "-",
            ),
            (
                "κ / e_C / C_u",
                f"{life.viscosity_ratio:.4g} / {life.contamination_factor:.4g} / "
                f"{life.fatigue_load_limit_n:.6g}",
                "- / - / N",
            ),
        ]
        if life.lnmr_hours is not None:
            rows.append(("L_nmr at this speed", f"{life.lnmr_hours:.6g}", "h"))
    return rows


def _length_number(value: float | None, unit: tuple[str, float], resolution: float | None) -> str:
    """The number of :func:`runout.base.display.format_length`, without the unit; ``n/a``
    for None (a figure the model does not have, never shown as 0)."""
    from runout.base.display import format_length

    if value is None:
        return "n/a"
    return format_length(value, unit, resolution_m=resolution).rsplit(" ", 1)[0]


def _plain(value: float, digits: int) -> str:
    from runout.base.display import format_number

    return format_number(value, digits)


def verdict_line(verdict: Verdict) -> str:
    """The PASS/FAIL sentence of a verdict (``PASS: radial_pp = 1.2 um within the limit 2 um``).

    Parameters
    ----------
    verdict : Verdict
        A verdict (:func:`runout.analysis.results.verdict_of`, or ``Verdict.from_json``).

    Returns
    -------
    str
        ``PASS`` or ``FAIL``, the quantity, its value and the limit.
    """
    from runout.base.display import format_length, length_unit

    word = "PASS" if verdict.passed else "FAIL"
    relation = "within" if verdict.passed else "exceeds"
    if verdict.unit == "m":
        unit = length_unit([verdict.value, verdict.limit])
        value = format_length(verdict.value, unit)
        limit = format_length(verdict.limit, unit)
    else:
        value = f"{_plain(verdict.value, 4)} um/s"
        limit = f"{_plain(verdict.limit, 4)} um/s"
    text = f"{word}: {verdict.quantity} = {value} {relation} the limit {limit}"
    if verdict.tolerance_class is not None:  # K_ia of an ISO 492 class for the bore
        bore = f"{float(verdict.tolerance_class['bore_m']) * 1e3:g} mm"
        text += f" (K_ia of ISO 492 class {verdict.tolerance_class['class']}, bore {bore})"
    return text
