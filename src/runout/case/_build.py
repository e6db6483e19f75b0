"""From a validated case document to the domain objects: the bearing, its imperfections
(waviness, spectra, profiles, slant, element errors) and the budget checks.

Part of :mod:`runout.case.model` (its module docstring describes case files).
"""

from __future__ import annotations

import math
import stat
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from runout.base.errors import GeometryError
from runout.base.reading import MISSING, InputFileError, resolve_inside
from runout.base.units import to_si
from runout.case._schema import (
    MAX_CONFORMITY,
    TWO_PI,
    BearingSpec,
    CaseSpec,
    ElementsSpec,
    ProfileSpec,
)
from runout.case.limits import (
    BYTES_PER_PROFILE_BYTE,
    ENV_PROFILE_DIRS,
    PROFILE_ROW_BYTES,
    Budget,
    LimitError,
    ResourceEstimate,
    case_budget,
    format_bytes,
    harmonics_memory,
    max_profile_bytes,
    max_profile_points,
    profile_allowed,
)
from runout.case.limits import check as check_estimate
from runout.geometry.bearing import BallBearing, Bearing, Material, RollerBearing
from runout.geometry.imperfections import (
    BearingImperfections,
    Harmonics,
    ProfileError,
    Slant,
    from_profile,
    read_profile_csv,
    single_harmonic,
    spectral_law,
)

#: Measured profiles held in memory: file name in ``[[profile]] file`` -> (angles [rad],
#: deviations [m]), read instead of a file (profiles given to the Python API as arrays).
ProfileData = Mapping[str, tuple[np.ndarray, np.ndarray]]

_GEOMETRY_KEYS = {
    "elements": "bearing.elements",
    "element_diameter": "bearing.element_diameter",
    "pitch_diameter": "bearing.pitch_diameter",
    "inner_conformity": "bearing.inner_conformity",
    "outer_conformity": "bearing.outer_conformity",
    "radial_clearance": "bearing.radial_clearance",
    "contact_angle": "bearing.contact_angle",
    "bearing.nominal_contact_angle": "bearing.nominal_contact_angle",
    "bearing.radial_clearance": "bearing.radial_clearance",
    "inner_raceway_diameter": "bearing.inner_raceway_diameter",
    "outer_raceway_diameter": "bearing.outer_raceway_diameter",
    "roller_length": "bearing.roller_length",
    "material.youngs_modulus": "material.youngs_modulus",
    "material.poisson_ratio": "material.poisson_ratio",
    "material.density": "material.density",
}


def _build_bearing(spec: CaseSpec) -> Bearing:
    b = spec.lead_bearing
    material = Material(
        youngs_modulus=spec.material.youngs_modulus,
        poisson_ratio=spec.material.poisson_ratio,
        density=spec.material.density,
    )
    if b.type == "cylindrical_roller":
        assert b.inner_raceway_diameter is not None and b.outer_raceway_diameter is not None
        return RollerBearing(
            elements=b.elements,
            element_diameter=b.element_diameter,
            inner_raceway_diameter=b.inner_raceway_diameter,
            outer_raceway_diameter=b.outer_raceway_diameter,
            roller_length=b.roller_length,
            material=material,
        )
    assert b.pitch_diameter is not None
    if not b.element_diameter > 0.0 and (
        b.inner_groove_radius is not None or b.outer_groove_radius is not None
    ):  # groove radii are read as conformities r / D below
        raise GeometryError(
            "bearing.element_diameter",
            f"must be a positive finite number, got {b.element_diameter!r}",
        )
    f_i = b.inner_conformity
    if b.inner_groove_radius is not None:
        f_i = b.inner_groove_radius / b.element_diameter
    f_o = b.outer_conformity
    if b.outer_groove_radius is not None:
        f_o = b.outer_groove_radius / b.element_diameter
    f_i = 0.52 if f_i is None else f_i
    f_o = 0.53 if f_o is None else f_o
    for side, f in (("inner", f_i), ("outer", f_o)):
        if f >= MAX_CONFORMITY:
            given = (
                f"{side}_groove_radius"
                if getattr(b, f"{side}_groove_radius") is not None
                else f"{side}_conformity"
            )
            raise GeometryError(
                f"bearing.{given}",
                f"conformity f = {f:.6g} is not below {MAX_CONFORMITY:g}: a groove radius of a "
                "whole ball diameter or more is no groove (deep-groove and angular-contact "
                "bearings have f = 0.505-0.6)",
            )
    clearance = b.radial_clearance
    if b.nominal_contact_angle is not None:
        clearance = _clearance_of_nominal_angle(
            b, f_i, f_o, "radial_clearance" in b.model_fields_set
        )
    return BallBearing(
        elements=b.elements,
        element_diameter=b.element_diameter,
        pitch_diameter=b.pitch_diameter,
        inner_conformity=f_i,
        outer_conformity=f_o,
        radial_clearance=clearance,
        contact_angle=b.contact_angle,
        material=material,
        dynamic_load_rating=b.dynamic_load_rating,
    )


def _clearance_of_nominal_angle(b: BearingSpec, f_i: float, f_o: float, given: bool) -> float:
    """Diametral play of a nominal (free) contact angle, P_d = 2A(1 - cos α⁰) (Harris) [m]."""
    alpha0 = b.nominal_contact_angle
    assert alpha0 is not None
    if not 0.0 <= alpha0 < 0.5 * math.pi:
        raise GeometryError(
            "bearing.nominal_contact_angle",
            f"must lie in [0, 90) deg, got {math.degrees(alpha0):.6g} deg",
        )
    a = (f_i + f_o - 1.0) * b.element_diameter
    clearance = 2.0 * a * (1.0 - math.cos(alpha0))
    if given and abs(b.radial_clearance - clearance) > max(1e-9, 1e-3 * clearance):
        raise GeometryError(
            "bearing.radial_clearance",
            f"{b.radial_clearance * 1e6:.6g} um disagrees with nominal_contact_angle = "
            f"{math.degrees(alpha0):.6g} deg, which sets P_d = 2A(1 - cos a0) = "
            f"{clearance * 1e6:.6g} um; give one of the two",
        )
    return clearance


def _element_part_ok(bearing: Bearing, part: str) -> bool:
    return not (
        (part == "ball" and isinstance(bearing, RollerBearing))
        or (part == "roller" and isinstance(bearing, BallBearing))
    )


def harmonic_counts(spec: CaseSpec, z: int) -> list[tuple[str, int]]:
    """(key, number of harmonics it creates) of every waviness entry, before any is built.

    An element entry without an element number counts once per element (it is copied onto
    each); the key is the one to change (``"waviness_spectrum[2].orders"``).
    """
    counts: list[tuple[str, int]] = []
    tables: list[tuple[str, list[Any]]] = [
        ("waviness", list(spec.waviness)),
        ("waviness_spectrum", list(spec.waviness_spectrum)),
        ("profile", list(spec.profile)),
    ]
    for table, entries in tables:
        for i, entry in enumerate(entries, start=1):
            per = 1 if table == "waviness" else entry.orders[1] - entry.orders[0] + 1
            # an element entry without an element number is copied onto every element
            copies = z if entry.part in ("ball", "roller") and entry.element is None else 1
            key = f"{table}[{i}].order" if table == "waviness" else f"{table}[{i}].orders"
            counts.append((key, per * copies))
    return counts


def _check_harmonics_budget(spec: CaseSpec, z: int, limits: Budget) -> None:
    """Refuse, before building any, more harmonics than the memory budget holds."""
    counts = harmonic_counts(spec, z)
    total = sum(n for _, n in counts)
    if not counts:
        return
    key = max(counts, key=lambda c: c[1])[0]
    memory = harmonics_memory(total)
    check_estimate(
        ResourceEstimate(memory, 0.0, key, key, f"{total} harmonics", f"{total} harmonics"), limits
    )


def _radius_bound(bearing: Bearing, part: str) -> tuple[float, str]:
    """Radius [m] a part's radius deviation must stay below, and the part in words."""
    if part in ("ball", "roller"):
        return 0.5 * bearing.element_diameter, f"the {part} radius"
    if part == "inner":
        return 0.5 * bearing.inner_raceway_diameter, "the inner raceway radius"
    return 0.5 * bearing.outer_raceway_diameter, "the outer raceway radius"


def _check_amplitude_exists(key: str, part: str, harmonics: Harmonics, bearing: Bearing) -> None:
    """A radius deviation whose peaks reach the part's own radius describes no real part."""
    peak = float(np.sum(harmonics.amplitudes)) if len(harmonics) else 0.0
    radius, words = _radius_bound(bearing, part)
    if peak >= radius:
        raise _CaseKeyError(
            key,
            f"the deviation reaches {peak * 1e3:.6g} mm, not less than {words} "
            f"{radius * 1e3:.6g} mm: no such part can exist",
        )


def _check_element_errors(bearing: Bearing, imp: BearingImperfections) -> None:
    """Diameter and pitch errors of elements that could not be assembled.

    * a diameter D + Δd_j <= 0 is no element;
    * a ball smaller than the others by more than 2A - P_d has more play than the groove
      depth it sits in (the radial_clearance rule for the whole set, per ball);
    * neighbouring elements, with their pitch and diameter errors, must not overlap on the
      pitch circle (and must stay in their order).
    Too large a ball (interference) is judged by the Hertz checks of the models.
    """
    d = bearing.element_diameter
    errors = np.asarray(imp.diameter_errors, dtype=np.float64)
    word = "ball" if isinstance(bearing, BallBearing) else "roller"
    for j, err in enumerate(errors):
        key = f"elements.diameter_errors[{j + 1}]"
        if d + err <= 0.0:
            raise _CaseKeyError(
                key,
                f"{err * 1e3:.6g} mm on a {d * 1e3:.6g} mm {word} leaves a diameter of "
                f"{(d + err) * 1e3:.6g} mm: no such {word} exists",
            )
        if isinstance(bearing, BallBearing):
            play = bearing.radial_clearance - err
            limit = 2.0 * bearing.curvature_distance
            if play >= limit:
                raise _CaseKeyError(
                    key,
                    f"a ball {-err * 1e6:.6g} um smaller than nominal has a diametral play of "
                    f"{play * 1e6:.6g} um, beyond twice the groove-centre distance "
                    f"2A = {limit * 1e6:.6g} um: it would leave the grooves",
                )
    pitch = np.asarray(imp.pitch_errors, dtype=np.float64)
    if not (pitch.any() or errors.any()):
        return
    z = errors.size
    radius = 0.5 * bearing.pitch_diameter
    for j in range(z):
        nxt = (j + 1) % z
        gap_angle = TWO_PI / z + pitch[nxt] - pitch[j]
        key = "elements.pitch_errors" if pitch.any() else "elements.diameter_errors"
        key += f"[{nxt + 1}]"
        if not 0.0 < gap_angle < math.pi:
            raise _CaseKeyError(
                key,
                f"the pitch errors put {word} {nxt + 1} {math.degrees(gap_angle):.4g} deg from "
                f"{word} {j + 1}: the {word}s would pass through each other",
            )
        spacing = 2.0 * radius * math.sin(0.5 * gap_angle)
        needed = 0.5 * (2.0 * d + errors[j] + errors[nxt])
        if spacing < needed:
            raise _CaseKeyError(
                key,
                f"{word}s {j + 1} and {nxt + 1} overlap on the pitch circle (centre spacing "
                f"{spacing * 1e3:.6g} mm < {needed * 1e3:.6g} mm)",
            )


def _read_profile(
    p: ProfileSpec, key: str, base_dir: Path, limits: Budget, data: ProfileData | None = None
) -> Harmonics:
    """Harmonics of a ``[[profile]]`` entry, read within the budget and the case's directory.

    Only a regular file inside the case file's directory (or a directory named by
    RUNOUT_PROFILE_DIRS) is opened: /dev/zero, a FIFO or ../../etc/passwd never are. Errors name
    the file and the line, never echo its contents. A profile given as arrays (``data``, in
    the units of its entry) is taken as read.
    """
    if data is not None and p.file in data:
        angles, deviations = data[p.file]
        most = max_profile_points(limits)
        for name, values in (("angles", angles), ("deviations", deviations)):
            count = int(np.size(values)) if isinstance(values, np.ndarray) else len(values)
            if count > most:  # before the arrays are copied and fitted
                raise LimitError(
                    f"{key}.{name}",
                    f"has {count} points; reading it would need about "
                    f"{format_bytes(count * PROFILE_ROW_BYTES * BYTES_PER_PROFILE_BYTE)} of "
                    f"memory (profiles up to {most} points); resample the profile "
                    f"{limits.raise_hint('memory')}",
                )
            if np.iscomplexobj(values):
                raise _CaseKeyError(
                    f"{key}.{name}", "must be real numbers, got complex values (never cast to real)"
                )
        try:
            # the conversions of read_profile_csv, so that saving it as CSV changes nothing
            ang = np.array(angles, dtype=np.float64)
            if p.angle_unit == "deg":
                ang = np.deg2rad(ang)
            devs = np.array(deviations, dtype=np.float64) * to_si(f"1 {p.deviation_unit}", "length")
            return from_profile(ang, devs, orders=p.orders)
        except ProfileError as exc:
            field_name = "orders" if "order" in exc.message else "file"
            raise _CaseKeyError(f"{key}.{field_name}", exc.message) from None
        except (GeometryError, ValueError) as exc:
            raise _CaseKeyError(f"{key}.file", str(exc)) from None
    path = base_dir / p.file
    try:
        # a loop of links is named here (resolving it raised RuntimeError, exit 70)
        resolve_inside(path, None, p.file)
    except InputFileError as exc:
        if exc.message != MISSING:
            raise _CaseKeyError(f"{key}.file", f'"{p.file}" {exc.message}') from None
    if not profile_allowed(path, base_dir):
        raise _CaseKeyError(
            f"{key}.file",
            f'"{p.file}" lies outside the case file\'s directory; copy the profile next to the '
            f"case, or name its directory in {ENV_PROFILE_DIRS}",
        )
    try:
        info = path.stat()
    except FileNotFoundError:
        raise _CaseKeyError(f"{key}.file", f'"{p.file}": no such file') from None
    except OSError as exc:
        raise _CaseKeyError(
            f"{key}.file", f'"{p.file}" cannot be read ({exc.strerror or exc})'
        ) from None
    if not stat.S_ISREG(info.st_mode):
        raise _CaseKeyError(
            f"{key}.file",
            f'"{p.file}" is not a regular file (a device, FIFO or directory is not a profile)',
        )
    largest = max_profile_bytes(limits)
    if info.st_size > largest:
        raise LimitError(
            f"{key}.file",
            f'"{p.file}" is {format_bytes(info.st_size)}; reading it would need about '
            f"{format_bytes(info.st_size * BYTES_PER_PROFILE_BYTE)} of memory (profiles up to "
            f"{format_bytes(largest)}); resample the profile {limits.raise_hint('memory')}",
        )
    try:
        angles, deviations = read_profile_csv(
            path,
            angle_unit=p.angle_unit,
            deviation_scale=to_si(f"1 {p.deviation_unit}", "length"),
            max_bytes=largest,
        )
        harmonics = from_profile(angles, deviations, orders=p.orders)
    except ProfileError as exc:
        message = exc.message
        field_name = "orders" if "order" in message and exc.line is None else "file"
        where = f'"{p.file}"' if exc.line is None else f'"{p.file}" line {exc.line}'
        raise _CaseKeyError(f"{key}.{field_name}", f"{where}: {message}") from None
    except (OSError, ValueError) as exc:
        raise _CaseKeyError(f"{key}.file", f'"{p.file}": {exc}') from None
    return harmonics


def _build_imperfections(
    spec: CaseSpec,
    bearing: Bearing,
    base_dir: Path,
    limits: Budget | None = None,
    profile_data: ProfileData | None = None,
) -> BearingImperfections:
    z = bearing.elements
    limits = case_budget(spec) if limits is None else limits
    _check_harmonics_budget(spec, z, limits)
    imp = BearingImperfections.perfect(z)

    def target(part: str) -> str:
        return "element" if part in ("ball", "roller") else part

    def check(key: str, part: str, element: int | None) -> None:
        if not _element_part_ok(bearing, part):
            raise _CaseKeyError(
                f"{key}.part", f'"{part}" does not match bearing.type = "{spec.lead_bearing.type}"'
            )
        if element is not None and element > z:
            raise _CaseKeyError(f"{key}.element", f"must be <= {z} (the number of elements)")

    def keyed(key: str, exc: GeometryError) -> _CaseKeyError:
        # the builders name the table without its index ("waviness.order"): add it
        field_name = exc.key.rsplit(".", 1)[-1] if "." in exc.key else ""
        return _CaseKeyError(f"{key}.{field_name}" if field_name else key, exc.message)

    for i, w in enumerate(spec.waviness, start=1):
        key = f"waviness[{i}]"
        check(key, w.part, w.element)
        amplitude = w.amplitude if w.amplitude is not None else 0.5 * (w.peak_to_peak or 0.0)
        if w.order == 0 and w.part in ("inner", "outer"):
            raise _CaseKeyError(
                f"{key}.order", "order 0 of a raceway is a size change; use the raceway diameter"
            )
        try:
            harmonics = single_harmonic(w.order, amplitude, w.phase)
        except GeometryError as exc:
            raise keyed(key, exc) from None
        amp_key = f"{key}.amplitude" if w.amplitude is not None else f"{key}.peak_to_peak"
        _check_amplitude_exists(amp_key, w.part, harmonics, bearing)
        imp = imp.add(target(w.part), harmonics, element=w.element)
    for i, s in enumerate(spec.waviness_spectrum, start=1):
        key = f"waviness_spectrum[{i}]"
        check(key, s.part, s.element)
        amplitude = s.amplitude if s.amplitude is not None else 0.5 * (s.peak_to_peak or 0.0)
        amp_key = f"{key}.amplitude" if s.amplitude is not None else f"{key}.peak_to_peak"
        phase: float | str = s.phase
        seed = (0 if s.seed is None else s.seed) if phase == "random" else None
        harmonics_list: list[Harmonics]
        try:
            if s.element is None and s.part in ("ball", "roller") and phase == "random":
                # Every element gets its own random phases, drawn from one seeded generator.
                rng = np.random.default_rng(seed)
                harmonics_list = [
                    spectral_law(s.orders, amplitude, s.exponent, phase="random", rng=rng)
                    for _ in range(z)
                ]
                _check_amplitude_exists(amp_key, s.part, harmonics_list[0], bearing)
                for j, h in enumerate(harmonics_list, start=1):
                    imp = imp.add("element", h, element=j)
                continue
            harmonics = spectral_law(s.orders, amplitude, s.exponent, phase=phase, seed=seed)
        except GeometryError as exc:
            raise keyed(key, exc) from None
        _check_amplitude_exists(amp_key, s.part, harmonics, bearing)
        imp = imp.add(target(s.part), harmonics, element=s.element)
    for i, p in enumerate(spec.profile, start=1):
        key = f"profile[{i}]"
        check(key, p.part, p.element)
        harmonics = _read_profile(p, key, base_dir, limits, profile_data)
        _check_amplitude_exists(f"{key}.file", p.part, harmonics, bearing)
        imp = imp.add(target(p.part), harmonics, element=p.element)
    if spec.slant is not None:
        if not isinstance(bearing, BallBearing):
            raise _CaseKeyError("slant", "applies to ball bearings only")
        try:
            if spec.slant.amplitude is not None:
                slant = Slant(amplitude=spec.slant.amplitude, phase=spec.slant.phase)
            else:
                assert spec.slant.angle is not None
                slant = Slant.from_angle(spec.slant.angle, bearing, phase=spec.slant.phase)
        except GeometryError as exc:
            raise keyed("slant", exc) from None
        if not slant.amplitude < 0.5 * bearing.inner_raceway_diameter:
            raise _CaseKeyError(
                "slant.amplitude" if spec.slant.amplitude is not None else "slant.angle",
                f"a slant of {slant.amplitude * 1e3:.6g} mm is not less than the inner raceway "
                f"radius {0.5e3 * bearing.inner_raceway_diameter:.6g} mm",
            )
        imp = imp.with_slant(slant)
    if isinstance(spec.elements, ElementsSpec):
        for name in ("diameter_errors", "pitch_errors"):
            values = getattr(spec.elements, name)
            if values is None:
                continue
            if len(values) != z:
                raise _CaseKeyError(
                    f"elements.{name}", f"has {len(values)} entries; the bearing has {z} elements"
                )
            imp = imp.with_element_errors(**{name: values})
        _check_element_errors(bearing, imp)
        if spec.elements.phase_frame == "fixed":
            imp = imp.element_phases_from_fixed_frame()
    return imp


class _CaseKeyError(Exception):
    def __init__(self, key: str, message: str) -> None:
        self.key = key
        self.message = message
        super().__init__(f"{key}: {message}")
