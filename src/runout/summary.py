"""What `runout check` and `runout frequencies` report: derived geometry, contacts, frequencies.

One function, :func:`bearing_summary`, gathers the derived quantities of a bearing at an
operating point; its result renders as JSON (SI values, unit in the key) or as tables.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from runout.bearing import BallBearing, Bearing, Operation, RollerBearing
from runout.contact import BallContacts, RollerContacts, ball_race_contacts, roller_race_contacts
from runout.kinematics import Frequencies, bearing_frequencies
from runout.loading import AxialLoading, axial_loading, axial_loading_fixed_angle
from runout.results import ROLLER_ALIASES, frequencies_json

__all__ = ["BearingSummary", "ModelUse", "bearing_summary", "model_use", "operating_contact_angle"]

Rows = list[tuple[str, str, str]]


def operating_contact_angle(
    bearing: Bearing, operation: Operation
) -> tuple[float, AxialLoading | None]:
    """Contact angle the bearing runs at, and the axial-load solution behind it.

    A fixed ``contact_angle`` in the bearing description wins; otherwise a ball bearing under an
    axial load runs at the loaded contact angle (Harris's load-angle relation,
    :func:`runout.loading.axial_loading`), and without axial load at the free contact angle.
    Roller bearings run at 0.

    Returns
    -------
    contact_angle : float
        [rad]
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


@dataclass(frozen=True)
class BearingSummary:
    """Derived geometry, Hertz contacts and frequencies of one bearing at one operating point."""

    bearing: Bearing
    operation: Operation
    contact_angle: float
    frequencies: Frequencies
    contacts: BallContacts | RollerContacts | None
    loading: AxialLoading | None

    # ------------------------------------------------------------------------ JSON
    def to_json(self) -> dict[str, Any]:
        """Plain-JSON dictionary; SI values with the unit in the key name."""
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
        """Titled rows (quantity, value, unit) for the readable output."""
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
}


@dataclass(frozen=True)
class ModelUse:
    """What one model will take from a case: effective inputs and each key's treatment.

    Attributes
    ----------
    model : str
    contact_angle : float
        Effective contact angle [rad] (see :data:`_ANGLE_SOURCE` for how the model gets it).
    radial_clearance : float
        Diametral play P_d [m].
    preload_approach : float or None
        Elastic approach of a ball along its contact line under the axial preload [m].
    keys : list of (key path, status)
    notes : list of str
    refusals : list of (key path, message)
    """

    model: str
    contact_angle: float
    radial_clearance: float
    preload_approach: float | None
    keys: list[tuple[str, str]]
    notes: list[str]
    refusals: list[tuple[str, str]]

    def to_json(self) -> dict[str, Any]:
        """JSON entry ``model_use`` of ``runout check --json``."""
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
        """Readable rows for ``runout check``."""
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
    case : runout.case.Case
        A validated case (read from a file: the key table needs its ``spec``).
    model : str, optional
        Model id.
    """
    from runout.conventions import applicability

    model = model or case.analysis.model
    bearing, op = case.bearing, case.operation
    alpha, loading = operating_contact_angle(bearing, op)
    if model == "roller_constraint":
        alpha = 0.0
    approach = None
    if loading is not None and model not in ("roller_constraint", "linear"):
        approach = loading.total_approach
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
