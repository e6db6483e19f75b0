"""The inputs section of the report (:mod:`runout.report.page`): the inputs as the model used them.

A case may set keys a model does not apply (the run says so in its notes, and the conventions
table knows which model honours which key). The report shows an input only when the model
used it, with how it used it (held fixed, derived from the clearance and the load, ...), and
lists the ignored keys by name, so that nothing the model ignored reads as if it counted.
"""

from __future__ import annotations

import math
import re
from typing import Any

from runout.base.errors import RunoutError
from runout.report._html import (
    common_unit,
    details,
    esc,
    fmt_number,
    length,
    num,
    table,
)

__all__ = ["inputs_section", "speed_words", "unused_keys"]

_NOT_USED = re.compile(r"^([a-z_]+(?:\.[a-z_]+)?(?:\[\d+\])?): not (?:used|applied)")


def speed_words(result: dict[str, Any], case: Any) -> str:
    """E.g. "inner ring at 1800 rpm", from the rotating ring's frequency [Hz] of the run."""
    ring = (
        case.operation.rotating_ring
        if case is not None
        else result.get("rotating_ring", "rotating")
    )
    rot = num((result.get("frequencies_hz") or {}).get("rotation"))
    if rot is None:
        return ""
    return f"{ring} ring at {fmt_number(rot * 60.0, 5)} rpm"


def unused_keys(result: dict[str, Any], case: Any) -> set[str]:
    """Case keys the model did not apply (from the run's notes and the conventions table)."""
    notes = list(result.get("notes") or [])
    model = result.get("model")
    if case is not None and model:
        from runout.case.conventions import applicability

        try:
            notes += applicability(case.spec, str(model)).notes
        except (RunoutError, ValueError, KeyError):
            pass  # a model id this runout does not know: the run's own notes still count
    found = set()
    for note in notes:
        match = _NOT_USED.match(str(note))
        if match:
            found.add(match.group(1))
    return found


# --------------------------------------------------------------------------------------------
# inputs as the model used them
# --------------------------------------------------------------------------------------------
def inputs_section(result: dict[str, Any], summary: dict[str, Any], case: Any) -> list[str]:
    """HTML of the inputs the model used (with how), the ignored keys, and derived geometry.

    Parameters
    ----------
    result, summary : dict
        ``result.json`` and ``summary.json`` of the run.
    case : Case or None
        The case loaded from the directory's ``case.toml`` (None: the operating inputs are
        left out, the geometry comes from ``summary.json``).
    """
    model = str(result.get("model") or "")
    unused = unused_keys(result, case)
    bearing = summary.get("bearing") or {}
    roller_type = bearing.get("type") == "cylindrical_roller"
    mm = ("mm", 1e3)
    rows: list[list[str]] = []

    def row(name: str, value: str, how: str = "") -> None:
        rows.append([esc(name), esc(value), esc(how)])

    element = "roller" if roller_type else "ball"
    z = bearing.get("elements")
    if z is not None:
        row("rolling elements Z", f"{z} {element}s")
    for key, name in (
        ("element_diameter_m", f"{element} diameter D"),
        ("pitch_diameter_m", "pitch diameter d_m"),
    ):
        if num(bearing.get(key)) is not None:
            row(name, length(bearing[key], mm, digits=6))
    fixed_angle = case is not None and getattr(case.bearing, "contact_angle", None) is not None
    clearance_unused = (
        "bearing.radial_clearance" in unused
        or "bearing.nominal_contact_angle" in unused
        or (fixed_angle and model in ("linear", "quasi_static_3d"))
    )
    clearance = num(result.get("radial_clearance_m"))
    if clearance is None:
        clearance = num(bearing.get("radial_clearance_m"))
    if clearance is not None and not clearance_unused:
        how = "from the raceway diameters" if roller_type else "diametral play P_d"
        if model == "dynamic":
            how = f"radial play P_d/2 = {length(clearance / 2, common_unit([clearance]))}"
        row("radial clearance P_d", length(clearance, common_unit([clearance]), digits=6), how)
    if not roller_type and model != "roller_constraint":
        fi, fo = num(bearing.get("inner_conformity")), num(bearing.get("outer_conformity"))
        if fi is not None and fo is not None:
            row("conformity f_i / f_o", f"{fi:.4g} / {fo:.4g}", "groove radius / D")
    angle = num(result.get("contact_angle_deg"))
    if angle is not None and model != "roller_constraint" and not roller_type:
        if fixed_angle:
            how = "held fixed (bearing.contact_angle)"
        elif model == "equilibrium":
            how = "mean over the balls; each ball's inner and outer angle below"
        elif model == "spindle":
            how = "the first bearing's, at the preload it carries (each bearing's: spindle table)"
        elif case is not None and case.operation.axial_load <= 0.0:
            # without an axial load the models take the free contact angle (clearance taken up
            # axially): at the groove bottoms only when that angle is 0
            how = (
                "no axial load: the balls touch at the groove bottoms"
                if abs(angle) < 1e-9
                else "no axial load: the free contact angle of the clearance"
            )
        else:
            how = "from the clearance and the axial load"
        row("operating contact angle", f"{angle:.4g} deg", how)
    layout = getattr(case, "spindle", None) if model == "spindle" else None
    if layout is not None:
        names = {"DB": "back-to-back", "DF": "face-to-face", "DT": "tandem"}
        row("arrangement", layout.arrangement, names.get(layout.arrangement, ""))
        if layout.preload is not None:
            how = (
                "constant-pressure (spring) preload on the shaft (tandem)"
                if layout.arrangement == "DT"
                else "constant-pressure (spring) preload, on the -z group's outer rings"
            )
            row("preload", f"{fmt_number(layout.preload, 5)} N", how)
        if layout.preload_displacement is not None:
            overlap = length(layout.preload_displacement, ("um", 1e6))
            row("preload", overlap, "position (rigid) preload: axial overlap, outer rings fixed")
        row("nose position", length(layout.nose_position, mm), "where the runout is reported")
    for key, how in (
        ("preload_approach_m", "elastic approach of the preload, per ball"),
        ("initial_approach_m", "initial (preload) approach δ_0"),
    ):
        value = num(result.get(key))
        if value is not None:
            row("preload approach", length(value), how)
    if case is not None:
        op = case.operation
        speed = speed_words(result, case)
        if speed:
            row("speed", speed)
        if op.other_ring_speed:
            row("other ring speed", f"{fmt_number(op.other_ring_speed * 60.0, 5)} rpm")
        direction = math.degrees(op.radial_load_direction)
        if op.radial_load > 0.0 and "operation.radial_load" not in unused:
            row("radial load", f"{fmt_number(op.radial_load, 5)} N", f"along {direction:.4g} deg")
        elif model in ("linear", "roller_constraint") or op.radial_load > 0.0:
            row("measuring direction", f"{direction:.4g} deg", "direction of the radial load")
        if op.axial_load > 0.0 and "operation.axial_load" not in unused:
            row("axial load", f"{fmt_number(op.axial_load, 5)} N", _preload_words(op, model))
        if op.moment_load > 0.0 and "operation.moment_load" not in unused:
            row("moment load", f"{fmt_number(op.moment_load, 5)} N m")
        material = getattr(case.bearing, "material", None)
        if material is not None and model not in ("linear", "roller_constraint"):
            row(
                "material E / ν",
                f"{material.youngs_modulus / 1e9:.4g} GPa / {material.poisson_ratio:.3g}",
            )
        if material is not None and model == "equilibrium":
            row("element density", f"{material.density:.5g} kg/m³")
        dyn = case.spec.dynamics if model == "dynamic" else None
        if dyn is not None:
            row("rotor mass", f"{dyn.mass:.4g} kg")
            row("damping", f"{dyn.damping:.4g} N s/m")
            if dyn.unbalance > 0.0:
                row("unbalance", f"{dyn.unbalance * 1e6:.4g} g mm")
        rows += [[esc("imperfection"), esc(text), ""] for text in _imperfections(case, unused)]
    parts = ["<h2>Inputs as the model used them</h2>", table(["input", "value", "how"], rows)]
    if unused:
        parts.append(
            "<p class='muted'>Given but not used by this model (see Notes): "
            + esc(", ".join(sorted(unused)))
            + "</p>"
        )
    parts += _geometry_details(result, summary, clearance_unused)
    return parts


def _imperfections(case: Any, unused: set[str]) -> list[str]:
    """Short lines for the case's imperfections; harmonics of one part and size share a line."""
    spec = case.spec

    def on(entry: Any) -> str:  # which bearing of a spindle the entry is on
        name = getattr(entry, "bearing", None)
        return f" (bearing {name})" if name else ""

    groups: dict[tuple[str, str], list[str]] = {}
    for i, entry in enumerate(spec.waviness, start=1):
        if f"waviness[{i}]" in unused:
            continue
        who = entry.part if entry.element is None else f"{entry.part} {entry.element}"
        who += on(entry)
        if entry.amplitude is not None:
            size = f"{length(entry.amplitude)} (0-p)"
        elif entry.peak_to_peak is not None:
            size = f"{length(entry.peak_to_peak)} (p-p)"
        else:
            size = "—"
        groups.setdefault((who, size), []).append(str(entry.order))
    out = [
        f"{who}: {', '.join(orders)} lobes, {size}{' each' if len(orders) > 1 else ''}"
        for (who, size), orders in groups.items()
    ]
    for i, entry in enumerate(spec.waviness_spectrum, start=1):
        if f"waviness_spectrum[{i}]" not in unused:
            out.append(
                f"{entry.part}{on(entry)}: spectrum of orders {entry.orders[0]}–{entry.orders[1]}"
            )
    for i, entry in enumerate(spec.profile, start=1):
        if f"profile[{i}]" not in unused:
            out.append(f"{entry.part}{on(entry)}: measured profile")
    for key, elements in spec.element_tables:
        where = f" (bearing {key.split('.', 1)[1]})" if "." in key else ""
        if elements.diameter_errors and any(elements.diameter_errors):
            n = len(elements.diameter_errors)
            out.append(f"element diameter errors{where} ({n} values)")
        if elements.pitch_errors and any(elements.pitch_errors):
            out.append(f"element pitch errors{where} ({len(elements.pitch_errors)} values)")
    if len(out) > 8:
        out = [*out[:8], f"… and {len(out) - 8} more (case file below)"]
    return out


def _kv_rows(data: dict[str, Any], skip: tuple[str, ...] = ()) -> list[list[str]]:
    """Rows (name, value) of a flat JSON object whose keys carry their SI unit as a suffix."""
    rows = []
    for key, value in data.items():
        if key in skip or isinstance(value, dict | list):
            continue
        number = num(value)
        # longest suffixes first: "_per_m" and "_n_per_m1_5" also end like "_m" or "_5"
        if key.endswith("_n_per_m1_5") and number is not None:
            rows.append([esc(key[:-11].replace("_", " ")), esc(f"{_power10(number)} N/m^1.5")])
        elif key.endswith("_per_m") and number is not None:
            rows.append([esc(key[:-6].replace("_", " ")), esc(f"{number * 1e-3:.5g} 1/mm")])
        elif key.endswith("_m") and number is not None:
            rows.append([esc(key[:-2].replace("_", " ")), esc(length(number, digits=6))])
        elif key.endswith("_deg") and number is not None:
            rows.append([esc(key[:-4].replace("_", " ")), esc(f"{number:.5g} deg")])
        elif key.endswith("_n") and number is not None:
            rows.append([esc(key[:-2].replace("_", " ")), esc(f"{number:.5g} N")])
        elif value is not None:
            rows.append([esc(key.replace("_", " ")), esc(fmt_number(value))])
    return rows


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def _power10(value: float) -> str:
    """A large or small number as "3.049 × 10¹⁰" (never "3.049e+10")."""
    if value == 0.0 or 1e-3 <= abs(value) < 1e6:
        return fmt_number(value, 5)
    exponent = math.floor(math.log10(abs(value)))
    mantissa = value / 10.0**exponent
    return f"{mantissa:.4g} × 10{str(exponent).translate(_SUPERSCRIPT)}"


def _geometry_details(
    result: dict[str, Any], summary: dict[str, Any], clearance_unused: bool
) -> list[str]:
    """Derived geometry, contact constants and frequencies, collapsed."""
    blocks = []
    derived = dict(summary.get("derived") or {})
    if clearance_unused:
        # these follow from the clearance, which the model did not use
        for key in ("free_contact_angle_deg", "free_end_play_m"):
            derived.pop(key, None)
    if derived:
        blocks.append("<h3>Derived geometry</h3>" + table(["quantity", "value"], _kv_rows(derived)))
    contact = summary.get("contact") or {}
    rows = []
    for side in ("inner", "outer"):
        if isinstance(contact.get(side), dict):
            rows += [[esc(f"{side} {r[0]}"), r[1]] for r in _kv_rows(contact[side])]
    rows += _kv_rows(contact, skip=("contact_angle_deg",))
    if rows:
        blocks.append("<h3>Hertz contact</h3>" + table(["quantity", "value"], rows))
    freqs = result.get("frequencies_hz") or summary.get("frequencies_hz") or {}
    if freqs:
        roller = (summary.get("bearing") or {}).get("type") == "cylindrical_roller"
        rotation = num(freqs.get("rotation")) or 0.0
        rows = [
            [
                esc(_frequency_name(name, roller)),
                esc(fmt_number(num(hz), 6)),
                esc(fmt_number((float(hz) / rotation) if rotation and num(hz) else None, 6)),
            ]
            for name, hz in freqs.items()
        ]
        blocks.append(
            "<h3>Characteristic frequencies</h3>"
            + table(["frequency", "Hz", "order"], rows, numeric=(1, 2))
        )
    if not blocks:
        return []
    return [details("Derived geometry, contact and characteristic frequencies", "".join(blocks))]


def _frequency_name(name: str, roller: bool) -> str:
    element = "roller" if roller else "ball"
    names = {
        "rotation": "rotating ring f_r",
        "cage": "cage f_c",
        "ball_spin": f"{element} spin",
        "ball_pass_inner": f"{element} pass, inner ring (BPFI)",
        "ball_pass_outer": f"{element} pass, outer ring (BPFO)",
    }
    return names.get(name, name.replace("_", " "))


def _preload_words(op: Any, model: str) -> str:
    """How the axial load holds the rings: the case's preload kind, in words."""
    if model == "spindle":  # its kind is its [spindle] key, shown with the spindle's inputs
        return "on the shaft, along +z"
    if op.preload == "position":
        return "on the shaft, along +z; position preload (rings held at its axial offset)"
    return "on the shaft, along +z; spring preload (constant force)"
