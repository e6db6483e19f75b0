"""Case files: TOML in, validated frozen dataclasses out.

A case file describes one bearing, how it runs, what is wrong with its parts and which analysis
to run (docs/case-file.md, generated from the schema below, and docs/conventions.md). A
number is SI; a string carries its unit and is parsed by :mod:`runout.units`.

Every problem is reported as a :class:`runout.errors.CaseError` that names the file, the key
path (``bearing.elements``, ``waviness[2].order``; array entries are counted from 1) and what is
wrong. Unknown keys are errors with a did-you-mean hint.
"""

from __future__ import annotations

import difflib
import math
import re
import stat
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    field_validator,
    model_validator,
)

from runout.bearing import BallBearing, Bearing, Material, Operation, RollerBearing
from runout.errors import CaseError, GeometryError
from runout.imperfections import (
    Harmonics,
    Imperfections,
    ProfileError,
    Slant,
    from_profile,
    read_profile_csv,
    single_harmonic,
    spectral_law,
)
from runout.limits import (
    BYTES_PER_PROFILE_BYTE,
    ENV_PROFILE_DIRS,
    MAX_BINS,
    MAX_CASE_FILE_BYTES,
    MAX_ELEMENTS,
    MAX_ENTRIES,
    MAX_ORDER,
    MAX_TOML_DEPTH,
    Budget,
    Estimate,
    LimitError,
    case_budget,
    estimate_run,
    estimate_study,
    format_bytes,
    harmonics_memory,
    max_profile_bytes,
    profile_allowed,
)
from runout.limits import check as check_estimate
from runout.units import UnitError, to_si

__all__ = [
    "MAX_CONFORMITY",
    "MODEL_IDS",
    "Analysis",
    "Case",
    "CaseSpec",
    "apply_overrides",
    "first_validation_error",
    "load_case",
    "parse_case",
    "parse_override",
    "read_case_data",
]

TWO_PI = 2.0 * math.pi
#: Largest groove conformity f = r / D: a groove radius of a whole ball diameter is no longer
#: a groove (deep-groove and angular-contact bearings have f = 0.505-0.6).
MAX_CONFORMITY = 1.0

MODEL_IDS = (
    "linear",
    "quasi_static_2d",
    "quasi_static_3d",
    "equilibrium",
    "dynamic",
    "roller_constraint",
)


def _quantity(kind: str) -> BeforeValidator:
    def convert(value: object) -> float:
        try:
            return to_si(value, kind)
        except UnitError as exc:
            raise ValueError(str(exc)) from None

    convert.kind = kind  # type: ignore[attr-defined]  # read by _field_kind (sweep ranges)
    return BeforeValidator(convert)


Length = Annotated[float, _quantity("length")]
Force = Annotated[float, _quantity("force")]
Pressure = Annotated[float, _quantity("pressure")]
Density = Annotated[float, _quantity("density")]
Mass = Annotated[float, _quantity("mass")]
Time = Annotated[float, _quantity("time")]
Damping = Annotated[float, _quantity("damping")]
AngleQ = Annotated[float, _quantity("angle")]
Speed = Annotated[float, _quantity("speed")]
Unbalance = Annotated[float, _quantity("mass_length")]
Plain = Annotated[float, _quantity("dimensionless")]
MomentQ = Annotated[float, _quantity("moment")]
MemoryQ = Annotated[float, _quantity("memory")]


def _order_at_most(value: int, what: str = "order") -> None:
    if value > MAX_ORDER:
        raise ValueError(
            f"{what} {value} exceeds the largest supported order {MAX_ORDER} (a wave of 10^6 "
            "lobes is shorter than any contact ellipse, which filters it out)"
        )


class _Table(BaseModel):
    # allow_inf_nan=False: TOML has inf and nan literals, and inf passes every "> 0" check
    model_config = ConfigDict(extra="forbid", frozen=True, strict=True, allow_inf_nan=False)


class BearingSpec(_Table):
    """``[bearing]``: the geometry of the bearing."""

    type: Literal["ball", "cylindrical_roller"] = Field(
        "ball", description='"ball" (deep-groove or angular-contact) or "cylindrical_roller".'
    )
    elements: int = Field(description="Number of balls or rollers Z (3 to 10 000).")
    element_diameter: Length = Field(description="Ball or roller diameter [m].")
    pitch_diameter: Length | None = Field(
        None, description="Pitch diameter d_m [m] (ball bearings; rollers derive it)."
    )
    inner_conformity: Plain | None = Field(
        None, description="Inner groove radius / ball diameter f_i (> 0.5). Default 0.52."
    )
    outer_conformity: Plain | None = Field(
        None, description="Outer groove radius / ball diameter f_o (> 0.5). Default 0.53."
    )
    inner_groove_radius: Length | None = Field(
        None, description="Inner groove radius [m], instead of inner_conformity."
    )
    outer_groove_radius: Length | None = Field(
        None, description="Outer groove radius [m], instead of outer_conformity."
    )
    radial_clearance: Length = Field(
        0.0, description="ISO radial internal clearance = Harris diametral play P_d [m]."
    )
    contact_angle: AngleQ | None = Field(
        None,
        description=(
            "Operating contact angle held fixed [rad] (seed 000); omitted: derived from the "
            "clearance and the axial load. Not the catalogue angle: see nominal_contact_angle."
        ),
    )
    nominal_contact_angle: AngleQ | None = Field(
        None,
        description=(
            "Nominal (free, catalogue) contact angle α⁰ [rad]: sets the clearance "
            "P_d = 2A(1 - cos α⁰), A = (f_i + f_o - 1) D. With radial_clearance, both must agree."
        ),
    )
    inner_raceway_diameter: Length | None = Field(
        None, description="Inner raceway diameter d_i [m] (cylindrical roller bearings)."
    )
    outer_raceway_diameter: Length | None = Field(
        None, description="Outer raceway diameter d_e [m] (cylindrical roller bearings)."
    )
    roller_length: Length | None = Field(
        None, description="Effective roller length [m] (cylindrical roller bearings)."
    )

    @field_validator("elements", mode="before")
    @classmethod
    def _elements(cls, value: object) -> object:
        if isinstance(value, bool) or not isinstance(value, int) or value < 3:
            raise ValueError(f"must be an integer >= 3, got {_Short(value)!r}")
        if value > MAX_ELEMENTS:
            raise ValueError(
                f"must be at most {MAX_ELEMENTS} (the largest slewing bearings have a few "
                f"hundred), got {value}"
            )
        return value

    @model_validator(mode="after")
    def _by_type(self) -> BearingSpec:
        ball_only = (
            "pitch_diameter",
            "inner_conformity",
            "outer_conformity",
            "inner_groove_radius",
            "outer_groove_radius",
            "contact_angle",
            "nominal_contact_angle",
        )
        roller_only = ("inner_raceway_diameter", "outer_raceway_diameter", "roller_length")
        if self.type == "ball":
            if self.pitch_diameter is None:
                raise _KeyedError("pitch_diameter", "required for a ball bearing")
            for key in roller_only:
                if getattr(self, key) is not None:
                    raise _KeyedError(key, 'only applies to type = "cylindrical_roller"')
            for side in ("inner", "outer"):
                if (
                    getattr(self, f"{side}_conformity") is not None
                    and getattr(self, f"{side}_groove_radius") is not None
                ):
                    raise _KeyedError(
                        f"{side}_groove_radius",
                        f"give {side}_conformity or {side}_groove_radius, not both",
                    )
        else:
            for key in ("inner_raceway_diameter", "outer_raceway_diameter"):
                if getattr(self, key) is None:
                    raise _KeyedError(key, "required for a cylindrical roller bearing")
            for key in ball_only:
                if getattr(self, key) is not None:
                    raise _KeyedError(key, 'only applies to type = "ball"')
            if self.radial_clearance != 0.0:
                raise _KeyedError(
                    "radial_clearance",
                    "a cylindrical roller bearing's clearance follows from its raceway "
                    "diameters (d_e - d_i - 2 D_w); give those instead",
                )
        return self


class MaterialSpec(_Table):
    """``[material]``: elastic and inertial properties (default: bearing steel)."""

    youngs_modulus: Pressure = Field(208e9, description="Young's modulus [Pa].")
    poisson_ratio: Plain = Field(0.3, description="Poisson's ratio [-].")
    density: Density = Field(7850.0, description="Density [kg/m^3].")


class OperationSpec(_Table):
    """``[operation]``: which ring turns, how fast, and the loads."""

    rotating_ring: Literal["inner", "outer"] = Field(
        "inner", description="Ring whose revolutions define orders."
    )
    speed: Speed = Field(
        0.0,
        description=(
            "Speed of the rotating ring [Hz] (e.g. '1800 rpm'), >= 0: the sense of rotation is "
            "not a sign; rotating_ring names the ring and other_ring_speed is signed relative "
            "to it."
        ),
    )
    other_ring_speed: Speed = Field(
        0.0, description="Speed of the other ring [Hz], signed relative to speed."
    )
    axial_load: Force = Field(0.0, description="Axial load or constant-pressure preload [N].")
    radial_load: Force = Field(0.0, description="Radial load [N].")
    radial_load_direction: AngleQ = Field(
        -math.pi / 2, description="Direction of the radial load from +x [rad]; default -y."
    )
    moment_load: MomentQ = Field(
        0.0, description='Tilting moment on the inner ring [N m] (model = "equilibrium").'
    )
    moment_load_direction: AngleQ = Field(
        0.0, description="Direction of the moment vector from +x [rad]; default +x."
    )

    @field_validator("axial_load", "radial_load", "moment_load")
    @classmethod
    def _non_negative(cls, value: float) -> float:
        if value < 0.0:
            raise ValueError(f"must be >= 0, got {value!r} N")
        return value

    @field_validator("speed")
    @classmethod
    def _unsigned_speed(cls, value: float) -> float:
        # One meaning of a speed in every model: its size. The sense of rotation is set by
        # rotating_ring (and the sign of other_ring_speed relative to it), never by a sign
        # here, which two models used to drop and the others refused.
        if value < 0.0:
            raise ValueError(
                f"must be >= 0, got {value!r} Hz: the sense of rotation is not a sign of the "
                "speed; name the turning ring with rotating_ring (other_ring_speed is signed "
                "relative to it)"
            )
        return value


Part = Literal["inner", "outer", "ball", "roller"]


class WavinessSpec(_Table):
    """``[[waviness]]``: one harmonic of one part's radius deviation."""

    part: Part = Field(description='"inner", "outer", "ball" or "roller".')
    order: int = Field(ge=0, description="Number of lobes (waves per circumference).")
    amplitude: Length | None = Field(None, description="Zero-to-peak radius deviation [m].")
    peak_to_peak: Length | None = Field(None, description="Peak-to-peak radius deviation [m].")
    phase: AngleQ = Field(0.0, description="Phase φ of a cos(kθ + φ) [rad].")
    element: int | None = Field(
        None, ge=1, description="Ball/roller number (1-based); omitted: every element."
    )

    @field_validator("order")
    @classmethod
    def _bounded_order(cls, value: int) -> int:
        _order_at_most(value)
        return value

    @model_validator(mode="after")
    def _one_amplitude(self) -> WavinessSpec:
        _check_amplitude(self.amplitude, self.peak_to_peak)
        _check_element(self.part, self.element)
        return self


class WavinessSpectrumSpec(_Table):
    """``[[waviness_spectrum]]``: amplitude(k) = amplitude * k**exponent for k in orders."""

    part: Part = Field(description='"inner", "outer", "ball" or "roller".')
    orders: tuple[int, int] = Field(description="First and last order, inclusive.", strict=False)
    amplitude: Length | None = Field(None, description="Zero-to-peak amplitude at k = 1 [m].")
    peak_to_peak: Length | None = Field(None, description="Peak-to-peak amplitude at k = 1 [m].")
    exponent: float = Field(0.0, description="Spectral slope: amplitude ~ k**exponent.")
    phase: AngleQ | Literal["random"] = Field(
        "random", description='"random" (seeded) or one angle for every order.'
    )
    seed: int | None = Field(
        None,
        ge=0,
        description='Seed of the random phases (phase = "random" only; default 0, reproducible).',
    )
    element: int | None = Field(None, ge=1, description="Ball/roller number (1-based).")

    @field_validator("phase", mode="before")
    @classmethod
    def _phase(cls, value: object) -> object:
        if value == "random":
            return value
        try:
            return to_si(value, "angle")
        except UnitError as exc:
            raise ValueError(f'{exc}; expected an angle or "random"') from None

    @model_validator(mode="after")
    def _check(self) -> WavinessSpectrumSpec:
        first, last = self.orders
        if first < 0 or last < first:
            raise _KeyedError(
                "orders", f"must be [first, last] with 0 <= first <= last, got {list(self.orders)}"
            )
        try:
            _order_at_most(last, "last order")
        except ValueError as exc:
            raise _KeyedError("orders", str(exc)) from None
        if first == 0 and self.exponent < 0:
            raise _KeyedError("orders", "order 0 with a negative exponent is infinite")
        if self.seed is not None and self.phase != "random":
            raise _KeyedError(
                "seed", 'only applies to phase = "random" (a fixed phase draws nothing)'
            )
        _check_amplitude(self.amplitude, self.peak_to_peak)
        _check_element(self.part, self.element)
        return self


class ProfileSpec(_Table):
    """``[[profile]]``: a measured roundness profile (CSV of angle, deviation)."""

    part: Part = Field(description='"inner", "outer", "ball" or "roller".')
    file: str = Field(
        description=(
            "CSV path, relative to the case file; a regular file inside the case file's "
            "directory (or one named by RUNOUT_PROFILE_DIRS), within the memory budget."
        )
    )
    angle_unit: Literal["deg", "rad"] = Field("deg", description="Unit of the angle column.")
    deviation_unit: str = Field("um", description="Unit of the deviation column (e.g. 'um').")
    orders: tuple[int, int] = Field(description="Orders kept [first, last].", strict=False)
    element: int | None = Field(None, ge=1, description="Ball/roller number (1-based).")

    @model_validator(mode="after")
    def _check(self) -> ProfileSpec:
        first, last = self.orders
        if first < 0 or last < first:
            raise _KeyedError(
                "orders", f"must be [first, last] with 0 <= first <= last, got {list(self.orders)}"
            )
        try:
            _order_at_most(last, "last order")
        except ValueError as exc:
            raise _KeyedError("orders", str(exc)) from None
        try:
            to_si(f"1 {self.deviation_unit}", "length")
        except UnitError:
            raise _KeyedError(
                "deviation_unit", f'"{self.deviation_unit}" is not a length unit'
            ) from None
        _check_element(self.part, self.element)
        return self


class SlantSpec(_Table):
    """``[slant]``: inner-raceway slant (seed 002 eq. 34)."""

    part: Literal["inner"] = Field("inner", description="Only the inner raceway.")
    amplitude: Length | None = Field(None, description="W_s [m], amplitude of the 2/rev term.")
    angle: AngleQ | None = Field(None, description="Slant angle β [rad], instead of amplitude.")
    phase: AngleQ = Field(0.0, description="Phase φ_s [rad].")

    @model_validator(mode="after")
    def _one(self) -> SlantSpec:
        if (self.amplitude is None) == (self.angle is None):
            raise _KeyedError("amplitude", "give exactly one of amplitude or angle")
        value = self.amplitude if self.amplitude is not None else self.angle
        if value is not None and value < 0:
            raise _KeyedError(
                "amplitude" if self.amplitude is not None else "angle", "must be >= 0"
            )
        return self


class ElementsSpec(_Table):
    """``[elements]``: per-element size and position errors (length Z each)."""

    diameter_errors: list[Length] | None = Field(
        None, description="Deviation of each element's diameter [m]."
    )
    pitch_errors: list[AngleQ] | None = Field(
        None, description="Angular position error of each element [rad]."
    )
    phase_frame: Literal["cage", "fixed"] = Field(
        "cage",
        description=(
            'Frame of the phases of element waviness: "cage" (angle 0 along the outward '
            'radius through the element\'s centre at t = 0; seeds 001, 002) or "fixed" '
            "(angle 0 along +x of the bearing for every element; seed 004 eq. 7)."
        ),
    )


RawQuantity = int | float | str

#: Quantities a spec limit applies to (``[analysis] limit_on``).
LIMIT_QUANTITIES = (
    "radial_pp",
    "rro_pp",
    "nrro_pp",
    "axial_pp",
    "iso15242.L",
    "iso15242.M",
    "iso15242.H",
)
LimitQuantity = Literal[
    "radial_pp", "rro_pp", "nrro_pp", "axial_pp", "iso15242.L", "iso15242.M", "iso15242.H"
]


def is_band_quantity(quantity: str) -> bool:
    """True for an ISO 15242 band (a velocity), False for a runout p-p (a length)."""
    return quantity.startswith("iso15242.")


def limit_si(value: RawQuantity, quantity: str) -> float:
    """A spec limit in SI: [m] for a runout p-p, [m/s] for a band.

    A number is SI (metres, or metres per second for a band), as every case-file number;
    a string carries its unit. The dimension must match ``quantity``.

    Raises
    ------
    _KeyedError
        Key ``limit``: a value of the wrong dimension, not finite or not positive.
    """
    band = is_band_quantity(quantity)
    try:
        result = to_si(value, "velocity" if band else "length")
    except UnitError as exc:
        what = 'a velocity (e.g. "50 um/s")' if band else 'a length (e.g. "0.5 um")'
        raise _KeyedError("limit", f'limit_on = "{quantity}" needs {what}: {exc}') from None
    if not result > 0.0:
        raise _KeyedError("limit", f"must be > 0, got {_Short(value)!r}")
    return result


class AnalysisSpec(_Table):
    """``[analysis]``: which model and how long."""

    model: Literal[
        "linear",
        "quasi_static_2d",
        "quasi_static_3d",
        "equilibrium",
        "dynamic",
        "roller_constraint",
    ] = Field(
        "quasi_static_3d", description="Model id (docs/conventions.md: which keys each honours)."
    )
    revolutions: float = Field(20.0, gt=0, description="Revolutions of the rotating ring.")
    samples: int = Field(4096, ge=16, description="Number of instants.")
    max_memory: MemoryQ | None = Field(
        None,
        description=(
            'Memory budget of a run or study [bytes] (e.g. "8 GiB"); default RUNOUT_MAX_MEMORY, '
            "else 2 GiB. A case whose estimate exceeds it is refused before any work."
        ),
    )
    max_time: Time | None = Field(
        None,
        description=(
            'Time budget of a run or study [s] (e.g. "1 h"); default RUNOUT_MAX_TIME, else '
            "2 min of estimated computing. A case whose estimate exceeds it is refused."
        ),
    )
    linear_variant: Literal["radial_spring", "force_balance"] = Field(
        "radial_spring",
        description=(
            'model = "linear" only: "radial_spring" (seed 002 eq. 13, gain cos α) or '
            '"force_balance" (rings 1:1, element deviations 1/cos α).'
        ),
    )
    race_control: Literal["outer", "inner", "none"] = Field(
        "outer",
        description=(
            'model = "equilibrium" only: raceway that resists the gyroscopic moment by '
            'friction ("outer": λ_o = 2, λ_i = 0; "inner": λ_i = 2, λ_o = 0; "none": no '
            "gyroscopic moment in the ball balance; seed 001 eq. 3-4)."
        ),
    )
    bands: Literal["anderon", "iso15242"] | None = Field(
        None,
        description=(
            'Band values from the lines: "iso15242" (rms velocity [um/s] in the ISO 15242-1 '
            "bands L, M, H, edges scaled from 1800 rpm to the speed; JSON iso15242) or "
            '"anderon" (Anderon bands in orders; JSON anderon). Along the measuring direction; '
            "the linear model always gives anderon (x, seed 002). Refused by a model without "
            "lines (equilibrium); docs/concepts.md."
        ),
    )
    limit: RawQuantity | None = Field(
        None,
        description=(
            'Spec limit on limit_on: a length (e.g. "0.5 um") for a runout p-p, a velocity '
            '(e.g. "50 um/s") for a band. run: JSON verdict (pass: value <= limit); study: '
            "JSON yield with a Clopper-Pearson 95 % interval."
        ),
    )
    limit_on: LimitQuantity = Field(
        "radial_pp",
        description=(
            'Quantity the limit applies to: "radial_pp", "rro_pp", "nrro_pp", "axial_pp" '
            '(runout p-p [m]) or "iso15242.L", "iso15242.M", "iso15242.H" (band rms, needs '
            'bands = "iso15242"; run only).'
        ),
    )

    @model_validator(mode="after")
    def _check_limit(self) -> AnalysisSpec:
        if self.limit is None:
            # a case re-serialised with its defaults (study variants) names the default
            if self.limit_on != "radial_pp":
                raise _KeyedError("limit_on", "needs analysis.limit (the spec limit)")
            return self
        limit_si(self.limit, self.limit_on)  # raises _KeyedError("limit", ...)
        if is_band_quantity(self.limit_on) and self.bands != "iso15242":
            raise _KeyedError(
                "limit_on", f'"{self.limit_on}" is a band: it needs bands = "iso15242"'
            )
        return self


class DynamicsSpec(_Table):
    """``[dynamics]``: rotor for model = "dynamic"."""

    mass: Mass = Field(description="Rotor mass carried by the bearing [kg].")
    damping: Damping = Field(0.0, description="Viscous damping [N s/m] (>= 0).")
    unbalance: Unbalance = Field(0.0, description="Unbalance m e [kg m] (>= 0).")
    time_step: Time | None = Field(None, description="Integration step [s]; default automatic.")
    axial_dof: bool = Field(
        False,
        description=(
            "Also integrate the axial motion of the rotor under a constant axial force "
            "(spring preload); false holds it at the preloaded position (seed 003)."
        ),
    )
    contact_law: Literal["exact", "delta_star_table"] = Field(
        "exact",
        description=(
            'Contact constant K_n: "exact" Hertz solution or "delta_star_table" '
            "(δ* interpolated in seed 003 Table 1)."
        ),
    )

    @field_validator("mass")
    @classmethod
    def _positive_mass(cls, value: float) -> float:
        if value <= 0:
            raise ValueError(f"must be > 0, got {value!r} kg")
        return value

    @field_validator("damping", "unbalance")
    @classmethod
    def _non_negative(cls, value: float) -> float:
        # a negative damping feeds energy in: the run ended in "the rotor left the bearing"
        if value < 0:
            raise ValueError(f"must be >= 0, got {value!r}")
        return value

    @field_validator("time_step")
    @classmethod
    def _positive_step(cls, value: float | None) -> float | None:
        if value is not None and not value > 0:
            raise ValueError(f"must be > 0, got {value!r} s")
        return value


class VarySpec(_Table):
    """``[study.vary]`` entry: how one case quantity is drawn (Monte Carlo) or swept.

    The key is the quantity's path in the case file, quoted: ``"operation.axial_load"``,
    ``"bearing.radial_clearance"``, ``"waviness[1].phase"``, ``"elements.diameter_errors"``
    (an array key: every element drawn independently). Values carry units like the key they
    replace.
    """

    distribution: Literal["normal", "uniform", "sample"] | None = Field(
        None,
        description=(
            'Monte Carlo: "normal" (mean, std), "uniform" (low, high) or "sample" (draw with '
            "replacement from the measured values)."
        ),
    )
    mean: RawQuantity | None = Field(
        None, description="Normal: mean; default the case's own value (0 if it has none)."
    )
    std: RawQuantity | None = Field(None, description="Normal: standard deviation (>= 0).")
    low: RawQuantity | None = Field(None, description="Uniform: lower bound.")
    high: RawQuantity | None = Field(None, description="Uniform: upper bound.")
    values: list[RawQuantity] | None = Field(
        None, description='"sample": the measured values; sweep: the list of values.'
    )
    start: RawQuantity | None = Field(None, description="Sweep: first value of a range.")
    stop: RawQuantity | None = Field(None, description="Sweep: last value of a range.")
    num: int | None = Field(None, ge=2, description="Sweep: number of values of a range.")
    step: RawQuantity | None = Field(None, description="Sweep: step of a range (or num).")


#: ``[study.vary]`` shorthands (Monte Carlo): key -> what it draws.
STUDY_SHORTHANDS = {
    "element_diameter_sigma": (
        "standard deviation [m] of a normal error added to every element's diameter error"
    ),
}
_MC_KEYS = {
    "normal": ("mean", "std"),
    "uniform": ("low", "high"),
    "sample": ("values",),
}
_SWEEP_KEYS = ("values", "start", "stop", "num", "step")
_VARY_KEYS = ("distribution", "mean", "std", "low", "high", *_SWEEP_KEYS)


def study_paths() -> dict[str, list[str]]:
    """Tables of a case file and their keys that a study may vary (for checks and hints)."""
    out: dict[str, list[str]] = {}
    for name, info in CaseSpec.model_fields.items():
        table = _table_type(info.annotation)
        if table is None or table is StudySpec:
            continue
        out[name] = list(table.model_fields)
    return out


def _array_tables() -> set[str]:
    return {
        name
        for name, info in CaseSpec.model_fields.items()
        if "list[" in str(info.annotation) and _table_type(info.annotation) is not None
    }


def parse_vary_key(key: str) -> tuple[str, int | None, str]:
    """Split a ``[study.vary]`` key into (table, 1-based index or None, field); check names.

    Raises
    ------
    ValueError
        With a did-you-mean hint when the table or the key does not exist.
    """
    import re

    match = re.fullmatch(r"([a-z_]+)(?:\[(\d+)\])?\.([a-z_]+)", key)
    tables = study_paths()
    if match is None:
        known = [f"{t}.{f}" for t, fields in tables.items() for f in fields]
        hint = difflib.get_close_matches(key, [*known, *STUDY_SHORTHANDS], n=1, cutoff=0.6)
        suffix = f"; did you mean '{hint[0]}'?" if hint else ""
        raise ValueError(
            "not a quantity of the case: expected 'table.key' or 'table[i].key' (e.g. "
            f"'operation.axial_load') or one of {sorted(STUDY_SHORTHANDS)}{suffix}"
        )
    table, index, name = match.group(1), match.group(2), match.group(3)
    if table not in tables:
        hint = difflib.get_close_matches(table, list(tables), n=1, cutoff=0.6)
        suffix = f"; did you mean '{hint[0]}'?" if hint else ""
        raise ValueError(f"the case has no table '{table}'{suffix}")
    if name not in tables[table]:
        hint = difflib.get_close_matches(name, tables[table], n=1, cutoff=0.6)
        suffix = f"; did you mean '{table}.{hint[0]}'?" if hint else ""
        raise ValueError(f"'{table}' has no key '{name}'{suffix}")
    arrays = _array_tables()
    if table in arrays and index is None:
        raise ValueError(f"'{table}' is an array of tables: name one, e.g. '{table}[1].{name}'")
    if table not in arrays and index is not None:
        raise ValueError(f"'{table}' is a single table: write '{table}.{name}'")
    position = int(index) if index is not None else None
    if position is not None and position < 1:
        raise ValueError("array entries are counted from 1")
    return table, position, name


class StudySpec(_Table):
    """``[study]``: for ``runout study`` (Monte Carlo over drawn quantities, or sweeps)."""

    kind: Literal["montecarlo", "sweep"] = Field(description='"montecarlo" or "sweep".')
    samples: int = Field(100, ge=1, description="Number of Monte Carlo samples (bearings).")
    seed: int = Field(
        0, ge=0, description="Root seed: sample i draws from SeedSequence(seed, spawn_key=(i,))."
    )
    chunk_size: int = Field(
        250, ge=1, description="Samples per task and per result file (--out, --resume)."
    )
    models: (
        list[
            Literal[
                "linear",
                "quasi_static_2d",
                "quasi_static_3d",
                "equilibrium",
                "dynamic",
                "roller_constraint",
            ]
        ]
        | None
    ) = Field(
        None,
        description=(
            "Model ids to run (sweeps: one or several; Monte Carlo: one); default analysis.model."
        ),
    )
    bins: int = Field(
        20, ge=1, le=MAX_BINS, description="Histogram bins of the Monte Carlo summary."
    )
    vary: dict[str, VarySpec | RawQuantity] = Field(
        default_factory=dict,
        description=(
            'Quantities to vary: "table.key" = {distribution = ...} (Monte Carlo) or '
            "{values = [...]} or {start, stop, num or step} (sweep); shorthand "
            'element_diameter_sigma = "0.1 um". Keys of each entry: docs/studies.md.'
        ),
    )

    @model_validator(mode="after")
    def _check_vary(self) -> StudySpec:
        if not self.vary:
            raise _KeyedError("vary", "name at least one quantity to vary")
        if self.kind == "sweep" and "samples" in self.model_fields_set:
            raise _KeyedError("samples", 'only applies to kind = "montecarlo"')
        if self.kind == "montecarlo" and self.models is not None and len(self.models) != 1:
            raise _KeyedError("models", "a Monte Carlo study runs one model")
        if self.models is not None and not self.models:
            raise _KeyedError("models", "name at least one model")
        for key, entry in self.vary.items():
            where = f"vary.{key}"
            if key in STUDY_SHORTHANDS:
                if self.kind != "montecarlo":
                    raise _KeyedError(where, 'shorthands apply to kind = "montecarlo" only')
                if isinstance(entry, VarySpec):
                    raise _KeyedError(where, 'must be a length (e.g. "0.1 um"), not a table')
                try:
                    value = to_si(entry, "length")
                except UnitError as exc:
                    raise _KeyedError(where, str(exc)) from None
                if not value >= 0.0:
                    raise _KeyedError(where, f"must be >= 0, got {entry!r}")
                continue
            try:
                parse_vary_key(key)
            except ValueError as exc:
                raise _KeyedError(where, str(exc)) from None
            if not isinstance(entry, VarySpec):
                raise _KeyedError(
                    where,
                    "must be a table: {distribution = ...} (Monte Carlo) or {values = [...]} "
                    "(sweep)",
                )
            given = {k for k in _VARY_KEYS if getattr(entry, k) is not None}
            if self.kind == "montecarlo":
                _check_distribution(where, entry, given)
            else:
                _check_sweep(where, entry, given)
        return self


def _check_distribution(where: str, entry: VarySpec, given: set[str]) -> None:
    if entry.distribution is None:
        raise _KeyedError(f"{where}.distribution", 'required: "normal", "uniform" or "sample"')
    allowed = {"distribution", *_MC_KEYS[entry.distribution]}
    for extra in sorted(given - allowed):
        raise _KeyedError(
            f"{where}.{extra}", f'does not apply to distribution = "{entry.distribution}"'
        )
    required = {"normal": ("std",), "uniform": ("low", "high"), "sample": ("values",)}
    for name in required[entry.distribution]:
        if name not in given:
            raise _KeyedError(
                f"{where}.{name}", f'required for distribution = "{entry.distribution}"'
            )
    if entry.values is not None and not entry.values:
        raise _KeyedError(f"{where}.values", "needs at least one value")


def _check_sweep(where: str, entry: VarySpec, given: set[str]) -> None:
    for extra in sorted(given - set(_SWEEP_KEYS)):
        raise _KeyedError(f"{where}.{extra}", 'only applies to kind = "montecarlo"')
    if "values" in given:
        if given != {"values"}:
            other = sorted(given - {"values"})[0]
            raise _KeyedError(f"{where}.{other}", "give values or a range, not both")
        if not entry.values:
            raise _KeyedError(f"{where}.values", "needs at least one value")
        return
    for name in ("start", "stop"):
        if name not in given:
            raise _KeyedError(f"{where}.{name}", "required: give values = [...] or a range")
    if ("num" in given) == ("step" in given):
        raise _KeyedError(f"{where}.num", "give exactly one of num or step")


class CaseSpec(_Table):
    """The whole case file."""

    title: str = Field("", description="Free text shown in outputs.")
    bearing: BearingSpec
    material: MaterialSpec = Field(default_factory=MaterialSpec)
    operation: OperationSpec = Field(default_factory=OperationSpec)
    waviness: list[WavinessSpec] = Field(default_factory=list)
    waviness_spectrum: list[WavinessSpectrumSpec] = Field(default_factory=list)
    profile: list[ProfileSpec] = Field(default_factory=list)
    slant: SlantSpec | None = None
    elements: ElementsSpec | None = None
    analysis: AnalysisSpec = Field(default_factory=AnalysisSpec)
    dynamics: DynamicsSpec | None = None
    study: StudySpec | None = None

    @field_validator("waviness", "waviness_spectrum", "profile", mode="before")
    @classmethod
    def _few_entries(cls, value: object) -> object:
        # each entry is added to the parts one at a time (quadratic in the number of entries):
        # many harmonics belong in one spectrum or profile, not in thousands of entries
        if isinstance(value, list) and len(value) > MAX_ENTRIES:
            raise ValueError(
                f"has {len(value)} entries, at most {MAX_ENTRIES}: give many orders as one "
                "[[waviness_spectrum]] or [[profile]]"
            )
        return value


class _KeyedError(ValueError):
    """A model-validator error that belongs to one key of the table."""

    def __init__(self, key: str, message: str) -> None:
        self.key = key
        super().__init__(f"{key}: {message}")


def _check_amplitude(amplitude: float | None, peak_to_peak: float | None) -> None:
    if (amplitude is None) == (peak_to_peak is None):
        raise _KeyedError("amplitude", "give exactly one of amplitude or peak_to_peak")
    value = amplitude if amplitude is not None else peak_to_peak
    if value is not None and value < 0:
        raise _KeyedError("amplitude" if amplitude is not None else "peak_to_peak", "must be >= 0")


def _check_element(part: str, element: int | None) -> None:
    if element is not None and part in ("inner", "outer"):
        raise _KeyedError("element", f'only applies to balls or rollers, not part = "{part}"')


# --------------------------------------------------------------------------------------------
# error formatting
# --------------------------------------------------------------------------------------------
def _fields_at(loc: tuple[int | str, ...]) -> list[str]:
    """Field names of the table at ``loc`` (for did-you-mean hints)."""
    model: Any = CaseSpec
    for part in loc:
        if isinstance(part, int):
            continue
        info = getattr(model, "model_fields", {}).get(part)
        if info is None:
            break
        annotation = info.annotation
        model = _table_type(annotation)
        if model is None:
            return []
    return list(getattr(model, "model_fields", {}).keys())


def _table_type(annotation: Any) -> Any:
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()):
        found = _table_type(arg)
        if found is not None:
            return found
    return None


def _format_loc(loc: tuple[int | str, ...]) -> str:
    text = ""
    for part in loc:
        if isinstance(part, int):
            text += f"[{part + 1}]"
        elif (
            part.startswith("function-") or part in ("literal['random']", "VarySpec") or "[" in part
        ):
            continue
        else:
            text += f".{part}" if text else part
    return text


#: Longest echo of a value in an error message: the line stays one readable line.
_ECHO_CHARS = 60


class _Short:
    """A value whose repr is cut to :data:`_ECHO_CHARS` characters."""

    def __init__(self, value: object) -> None:
        self.value = value

    def __repr__(self) -> str:
        text = repr(self.value)
        return text if len(text) <= _ECHO_CHARS else text[: _ECHO_CHARS - 3] + "..."


def _describe(error: Any) -> tuple[str, str]:
    loc = tuple(error["loc"])
    kind = error["type"]
    given = _Short(error.get("input"))
    ctx = error.get("ctx") or {}
    if kind == "extra_forbidden":
        key = str(loc[-1])
        hint = difflib.get_close_matches(key, _fields_at(loc[:-1]), n=1, cutoff=0.6)
        suffix = f"; did you mean '{hint[0]}'?" if hint else ""
        return _format_loc(loc), f"unknown key{suffix}"
    if kind == "missing":
        return _format_loc(loc), "required key is missing"
    if kind == "value_error":
        exc = ctx.get("error")
        if isinstance(exc, _KeyedError):
            return _format_loc((*loc, exc.key)), str(exc).split(": ", 1)[1]
        return _format_loc(loc), str(exc) if exc is not None else error["msg"]
    if kind == "literal_error":
        return _format_loc(loc), f"must be one of {ctx.get('expected')}, got {given!r}"
    if kind in ("int_type", "int_from_float", "int_parsing"):
        return _format_loc(loc), f"must be an integer, got {given!r}"
    if kind in ("float_type", "float_parsing"):
        return _format_loc(loc), f"must be a number, got {given!r}"
    if kind in ("string_type",):
        return _format_loc(loc), f"must be a string, got {given!r}"
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        return _format_loc(loc), f"must be a table, got {given!r}"
    if kind in ("list_type", "tuple_type"):
        return _format_loc(loc), f"must be an array, got {given!r}"
    if kind == "too_short" or kind == "too_long":
        return _format_loc(loc), f"has the wrong number of entries: {error['msg'].lower()}"
    if kind == "greater_than_equal":
        return _format_loc(loc), f"must be >= {ctx.get('ge')}, got {given!r}"
    if kind == "greater_than":
        return _format_loc(loc), f"must be > {ctx.get('gt')}, got {given!r}"
    if kind == "less_than_equal":
        return _format_loc(loc), f"must be <= {ctx.get('le')}, got {given!r}"
    if kind == "finite_number":
        return _format_loc(loc), f"must be a finite number, got {given!r}"
    if kind in ("recursion_loop",):
        return _format_loc(loc), "is nested too deeply"
    return _format_loc(loc), error["msg"]


def first_validation_error(exc: ValidationError) -> tuple[str, str]:
    """(key path, message) of the error a user should see first in a pydantic failure."""
    errors = exc.errors()
    # A union of an angle and "random" reports both branches; report the most specific one.
    # A misspelt key also makes the right one "missing": report the misspelling first.
    rank = {"extra_forbidden": 0}
    errors.sort(key=lambda e: rank.get(e["type"], 1))
    return _describe(errors[0])


# --------------------------------------------------------------------------------------------
# building the domain objects
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Analysis:
    """What to compute: model id, revolutions of the rotating ring, number of instants."""

    model: str = "quasi_static_3d"
    revolutions: float = 20.0
    samples: int = 4096
    linear_variant: str = "radial_spring"
    race_control: str = "outer"
    bands: str | None = None
    limit: float | None = None
    limit_on: str = "radial_pp"


#: Measured profiles held in memory: file name in ``[[profile]] file`` -> (angles [rad],
#: deviations [m]), read instead of a file (profiles given to the Python API as arrays).
ProfileData = Mapping[str, tuple[np.ndarray, np.ndarray]]


@dataclass(frozen=True)
class Case:
    """A validated case: every quantity SI, ready for the models.

    Build one from a case file with :func:`load_case`, or in code with
    :meth:`Case.from_inputs` (or let :func:`runout.run` build and run it); do not call the
    constructor yourself: ``spec``, the validated case-file document, is what the models and
    :meth:`to_toml` read.

    Attributes
    ----------
    path : str
        The case file as given, or ``"<python>"`` for a case built in code.
    title : str
    bearing : BallBearing or RollerBearing
    operation : Operation
    imperfections : runout.imperfections.Imperfections
        The resolved harmonics of every part (what the models use).
    analysis : Analysis
    spec : CaseSpec
        The validated case-file document.
    profile_data : mapping
        Measured profiles given as arrays: ``[[profile]] file`` name -> (angles [rad],
        deviations [m]); empty for a case read from a file.
    """

    path: str
    title: str
    bearing: Bearing
    operation: Operation
    imperfections: Imperfections
    analysis: Analysis
    spec: CaseSpec = field(repr=False)
    profile_data: ProfileData = field(default_factory=dict, repr=False, compare=False)

    @property
    def dynamics(self) -> DynamicsSpec | None:
        """The ``[dynamics]`` table, if any."""
        return self.spec.dynamics

    @property
    def study(self) -> StudySpec | None:
        """The ``[study]`` table, if any."""
        return self.spec.study

    @classmethod
    def from_inputs(
        cls,
        bearing: Bearing,
        operation: Operation | None = None,
        imperfections: Any = None,
        *,
        title: str = "",
        analysis: Mapping[str, Any] | None = None,
        dynamics: Mapping[str, Any] | None = None,
        study: Mapping[str, Any] | None = None,
        base_dir: str | Path | None = None,
    ) -> Case:
        """The case a case file with these tables would give, validated the same way.

        Parameters
        ----------
        bearing : BallBearing or RollerBearing
            Geometry and material (``[bearing]``, ``[material]``).
        operation : Operation, optional
            ``[operation]``; default a bearing at rest without load.
        imperfections : runout.Imperfections, optional
            The builder of ``[[waviness]]``, ``[[waviness_spectrum]]``, ``[[profile]]``,
            ``[slant]`` and ``[elements]`` (:class:`runout.api.Imperfections`); default none.
        title : str
        analysis, dynamics, study : mapping, optional
            The ``[analysis]``, ``[dynamics]`` and ``[study]`` keys, by their case-file names:
            SI numbers or strings with units.
        base_dir : str or Path, optional
            Directory that ``[[profile]]`` files are read from; default the working directory.

        Raises
        ------
        CaseError
            Naming ``<python>`` and the case key, with the message a case file would give.
        """
        from runout.api import build_case

        return build_case(
            bearing,
            operation,
            imperfections,
            title=title,
            analysis=analysis,
            dynamics=dynamics,
            study=study,
            base_dir=base_dir,
        )

    def to_document(self) -> dict[str, Any]:
        """The case-file document (tables of SI numbers) that gives this case again."""
        return self.spec.model_dump(mode="python", exclude_unset=True, exclude_none=True)

    def to_toml(self) -> str:
        """The case as case-file text (SI numbers), for ``runout run`` or :func:`load_case`.

        Keys given at their defaults are written only when they were given; ``[[profile]]``
        files are named as in the case and read relative to the saved file.

        Raises
        ------
        CaseError
            A profile given as arrays has no file to name: use :meth:`save`, which writes it.
        """
        if self.profile_data:
            name = next(iter(self.profile_data))
            raise CaseError(
                self.path,
                _profile_key(self.spec, name),
                "was given as arrays and has no file; Case.save(path) writes the case with "
                "its profiles as CSV files next to it",
            )
        return self._toml()

    def _toml(self, files: dict[str, str] | None = None) -> str:
        import tomli_w

        # tables in the order of the case-file reference, and every entry of an array of
        # tables as its own [[table]] (tomli_w would write short ones inline)
        document = self.to_document()
        for entry in document.get("profile", []):  # profiles saved under other names
            entry["file"] = (files or {}).get(entry.get("file", ""), entry.get("file"))
        chunks = []
        top = {k: v for k, v in document.items() if not isinstance(v, dict | list)}
        if top:
            chunks.append(tomli_w.dumps(top))
        for name in CaseSpec.model_fields:
            value = document.get(name)
            if isinstance(value, dict):
                chunks.append(tomli_w.dumps({name: value}))
            elif isinstance(value, list):
                chunks.extend(f"[[{name}]]\n" + tomli_w.dumps(entry) for entry in value)
        return "\n".join(chunk.strip("\n") + "\n" for chunk in chunks)

    def save(self, path: str | Path) -> Path:
        """Write :meth:`to_toml` to ``path``, and profiles given as arrays as CSV beside it.

        Each profile's CSV is named after the case file (``<stem>.<part>_profile_<k>.csv``), so
        that cases saved into one directory do not share a profile file.

        Returns
        -------
        Path
            The case file written.
        """
        target = Path(path)
        # named after the case file: two cases saved in one directory keep their own profiles
        files = {name: f"{target.stem}.{name}" for name in self.profile_data}
        for name, (angles, deviations) in self.profile_data.items():
            rows = "".join(
                f"{float(a)!r},{float(d)!r}\n" for a, d in zip(angles, deviations, strict=True)
            )
            (target.parent / files[name]).write_text(
                "# angle, radius deviation (units: the case file's [[profile]] entry)\n" + rows,
                encoding="utf-8",
            )
        target.write_text(self._toml(files), encoding="utf-8")
        return target


def _profile_key(spec: CaseSpec, name: str) -> str:
    for i, p in enumerate(spec.profile, start=1):
        if p.file == name:
            return f"profile[{i}].file"
    return "profile"


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
    b = spec.bearing
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
        Estimate(memory, 0.0, key, key, f"{total} harmonics", f"{total} harmonics"), limits
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


def _check_element_errors(bearing: Bearing, imp: Imperfections) -> None:
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
) -> Imperfections:
    z = bearing.elements
    limits = case_budget(spec) if limits is None else limits
    _check_harmonics_budget(spec, z, limits)
    imp = Imperfections.perfect(z)

    def target(part: str) -> str:
        return "element" if part in ("ball", "roller") else part

    def check(key: str, part: str, element: int | None) -> None:
        if not _element_part_ok(bearing, part):
            raise _CaseKeyError(
                f"{key}.part", f'"{part}" does not match bearing.type = "{spec.bearing.type}"'
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
    if spec.elements is not None:
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


def _depth(value: object, limit: int) -> int:
    """Nesting depth of tables and arrays, counted up to ``limit + 1`` (no recursion)."""
    stack: list[tuple[object, int]] = [(value, 0)]
    deepest = 0
    while stack:
        node, depth = stack.pop()
        deepest = max(deepest, depth)
        if deepest > limit:
            return deepest
        if isinstance(node, dict):
            stack.extend((v, depth + 1) for v in node.values())
        elif isinstance(node, list):
            stack.extend((v, depth + 1) for v in node)
    return deepest


def _field_kind(table: str, name: str) -> str | None:
    """Unit kind (:data:`runout.units.KINDS`) of a case key, None when it is not a quantity."""
    model = (
        _table_type(CaseSpec.model_fields[table].annotation)
        if table in CaseSpec.model_fields
        else None
    )
    info = getattr(model, "model_fields", {}).get(name)
    for meta in getattr(info, "metadata", ()):
        kind = getattr(getattr(meta, "func", None), "kind", None)
        if kind is not None:
            return str(kind)
    return None


def sweep_count(spec: CaseSpec, key: str, entry: VarySpec | RawQuantity) -> int:
    """Number of values of one ``[study.vary]`` sweep entry, computed without listing them.

    ``num`` is the count; a range by ``step`` has ``floor((stop - start) / step) + 1`` values,
    with start, stop and step read in the unit kind of the key they sweep.

    Raises
    ------
    CaseError
        Not here: unreadable values are left to the study, which names them; 1 is returned.
    """
    if not isinstance(entry, VarySpec):
        return 1
    if entry.values is not None:
        return max(1, len(entry.values))
    if entry.num is not None:
        return int(entry.num)
    if entry.step is None or entry.start is None or entry.stop is None:
        return 1
    try:
        table, _, name = parse_vary_key(key)
        kind = _field_kind(table, name) or "dimensionless"
        start, stop = to_si(entry.start, kind), to_si(entry.stop, kind)
        step = to_si(entry.step, kind)
    except (UnitError, ValueError, KeyError):
        return 1
    if step == 0.0 or (stop - start) * step < 0.0:
        return 1
    count = math.floor((stop - start) / step + 1e-9) + 1
    return max(1, count) if math.isfinite(count) else 2**62


def _check_limits(case: Case) -> None:
    """Refuse a case whose run (or study) would exceed the budget, before any work."""
    limits = case_budget(case)
    per_run = estimate_run(case, case.analysis.model)
    if case.study is not None:
        models = list(case.study.models) if case.study.models else [case.analysis.model]
        per_run = max((estimate_run(case, m) for m in models), key=lambda e: (e.seconds, e.memory))
        check_estimate(estimate_study(case, per_run), limits)
    check_estimate(per_run, limits)


def parse_case(
    data: dict[str, Any],
    path: str = "<case>",
    base_dir: Path | None = None,
    *,
    profile_data: ProfileData | None = None,
) -> Case:
    """Validate a parsed TOML document and build the domain objects.

    Parameters
    ----------
    data : dict
        The TOML document as a dictionary.
    path : str
        File name used in error messages.
    base_dir : Path or None
        Directory that relative file references (profiles) are resolved against, and the only
        one profiles may come from (with those of RUNOUT_PROFILE_DIRS).
    profile_data : mapping, optional
        Profiles given as arrays: ``[[profile]] file`` name -> (angles, deviations) in the
        units of the entry, used instead of reading that file.

    Raises
    ------
    CaseError
        Naming ``path``, the key path and the problem; also for a case whose estimated memory
        or time exceeds the budget (:mod:`runout.limits`).
    """
    if _depth(data, MAX_TOML_DEPTH) > MAX_TOML_DEPTH:
        raise CaseError(path, "", f"tables and arrays are nested deeper than {MAX_TOML_DEPTH}")
    try:
        spec = CaseSpec.model_validate(data)
    except ValidationError as exc:
        key, message = first_validation_error(exc)
        raise CaseError(path, key, message) from None
    try:
        limits = case_budget(spec)
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    try:
        bearing = _build_bearing(spec)
    except GeometryError as exc:
        raise CaseError(path, _GEOMETRY_KEYS.get(exc.key, exc.key), exc.message) from None
    try:
        operation = Operation(
            rotating_ring=spec.operation.rotating_ring,
            speed=spec.operation.speed,
            other_ring_speed=spec.operation.other_ring_speed,
            axial_load=spec.operation.axial_load,
            radial_load=spec.operation.radial_load,
            radial_load_direction=spec.operation.radial_load_direction,
            moment_load=spec.operation.moment_load,
            moment_load_direction=spec.operation.moment_load_direction,
        )
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    try:
        imperfections = _build_imperfections(
            spec, bearing, base_dir or Path.cwd(), limits, profile_data
        )
    except _CaseKeyError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    except ValueError as exc:
        raise CaseError(path, "", str(exc)) from None
    analysis = Analysis(
        model=spec.analysis.model,
        revolutions=spec.analysis.revolutions,
        samples=spec.analysis.samples,
        linear_variant=spec.analysis.linear_variant,
        race_control=spec.analysis.race_control,
        bands=spec.analysis.bands,
        limit=(
            None
            if spec.analysis.limit is None
            else limit_si(spec.analysis.limit, spec.analysis.limit_on)
        ),
        limit_on=spec.analysis.limit_on,
    )
    case = Case(
        path=path,
        title=spec.title,
        bearing=bearing,
        operation=operation,
        imperfections=imperfections,
        analysis=analysis,
        spec=spec,
        profile_data=dict(profile_data or {}),
    )
    try:
        _check_limits(case)
    except GeometryError as exc:
        raise CaseError(path, exc.key, exc.message) from None
    return case


def load_case(
    path: str | Path,
    *,
    model: str | None = None,
    overrides: Mapping[str, Any] | None = None,
) -> Case:
    """Read and validate a TOML case file.

    Only a regular file of at most :data:`runout.limits.MAX_CASE_FILE_BYTES` is read (a FIFO
    or /dev/zero is refused before it is opened for reading); a UTF-8 byte-order mark is
    allowed.

    Parameters
    ----------
    path : str or Path
        The case file.
    model : str, optional
        Model id replacing ``[analysis] model`` (``runout run --model``).
    overrides : mapping, optional
        Case keys by dotted path (``"operation.axial_load"``, ``"waviness[2].order"``,
        ``"title"``) -> value as the file would give it (SI number or string with unit),
        replacing or adding that key before validation (``runout run --set``).

    Returns
    -------
    Case

    Raises
    ------
    CaseError
        If the file cannot be read, is not TOML, or is invalid (with the overrides), naming
        the file and the key.
    """
    name = str(path)
    data = read_case_data(path)
    changes = dict(overrides or {})
    if model is not None:
        if "analysis.model" in changes:  # one would silently replace the other
            raise CaseError(name, "analysis.model", "given both as --model and with --set")
        study = data.get("study")
        if isinstance(study, dict) and "models" in study and "study.models" not in changes:
            # a study's models list decides which models run: --model would be ignored
            raise CaseError(
                name,
                "study.models",
                f"the study runs the models it lists; write --set study.models='[\"{model}\"]' "
                "instead of --model",
            )
        changes["analysis.model"] = model
    if not changes:
        return parse_case(data, name, Path(path).parent)
    try:
        apply_overrides(data, changes, name)
        return parse_case(data, name, Path(path).parent)
    except CaseError as exc:
        given = next((k for k in changes if exc.key == k or exc.key.startswith(f"{k}[")), None)
        if given is None:
            raise
        how = "--model" if given == "analysis.model" and model is not None else "--set"
        raise CaseError(name, exc.key, f"{exc.message} (given by {how})") from None


def read_case_data(path: str | Path) -> dict[str, Any]:
    """The TOML document of a case file, read within the size limit, not yet validated.

    Raises
    ------
    CaseError
        If the file cannot be read or is not TOML.
    """
    p = Path(path)
    name = str(path)
    try:
        info = p.stat()
    except FileNotFoundError:
        raise CaseError(name, "", "no such file") from None
    except OSError as exc:
        raise CaseError(name, "", f"cannot be read ({exc.strerror or exc})") from None
    if stat.S_ISDIR(info.st_mode):
        raise CaseError(name, "", "is a directory, not a case file")
    if not stat.S_ISREG(info.st_mode):
        raise CaseError(name, "", "is not a regular file (a device or FIFO is not a case file)")
    if info.st_size > MAX_CASE_FILE_BYTES:
        raise CaseError(
            name,
            "",
            f"is {format_bytes(info.st_size)}; a case file is at most "
            f"{format_bytes(MAX_CASE_FILE_BYTES)} (put measured data in [[profile]] files)",
        )
    try:
        with p.open("rb") as handle:
            raw = handle.read(MAX_CASE_FILE_BYTES + 1)
    except OSError as exc:
        raise CaseError(name, "", f"cannot be read ({exc.strerror or exc})") from None
    if len(raw) > MAX_CASE_FILE_BYTES:
        raise CaseError(name, "", f"is larger than {format_bytes(MAX_CASE_FILE_BYTES)}")
    try:
        # utf-8-sig: editors on Windows start files with a byte-order mark
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise CaseError(
            name, "", f"is not UTF-8 text (byte {exc.start + 1} cannot be decoded)"
        ) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(name, "", f"is not valid TOML: {exc}") from None
    except RecursionError:
        raise CaseError(
            name, "", f"is not valid TOML: nested deeper than {MAX_TOML_DEPTH} levels"
        ) from None


def parse_override(text: str) -> tuple[str, Any]:
    """``KEY=VALUE`` of ``--set`` as (dotted key, value).

    The value is read as a TOML value (``8192``, ``"30 N"``, ``[1, 2]``, ``true``); a bare
    word that is not one (``30 N`` without quotes, ``outer``) is taken as a string.

    Raises
    ------
    ValueError
        Without ``=`` or without a key.
    """
    key, sep, value = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise ValueError(f"expected KEY=VALUE (e.g. operation.axial_load='30 N'), got {text!r}")
    value = value.strip()
    try:
        parsed = tomllib.loads(f"v = {value}")
        if set(parsed) == {"v"}:
            return key, parsed["v"]
    except tomllib.TOMLDecodeError:
        pass
    return key, value


_OVERRIDE_KEY = re.compile(r"([a-z_]+)(?:\[(\d+)\])?(?:\.([a-z_]+))?")


def apply_overrides(data: dict[str, Any], overrides: Mapping[str, Any], path: str) -> None:
    """Set case keys by dotted path in a TOML document, in place, before it is validated.

    ``title``, ``table.key`` or ``table[i].key`` (entries counted from 1); a table the
    document lacks is created. A key the case does not have is left to the validation, which
    names it with a did-you-mean hint.

    Raises
    ------
    CaseError
        A path that is not a case key's shape, or an array entry the document does not have.
    """
    for key, value in overrides.items():
        match = _OVERRIDE_KEY.fullmatch(key)
        if match is None:
            raise CaseError(
                path,
                _one_line(key),
                "not a case key: expected 'title', 'table.key' or 'table[i].key' (e.g. "
                "operation.axial_load or waviness[1].order)",
            )
        table, index, name = match.group(1), match.group(2), match.group(3)
        if name is None:
            if index is not None or (table in CaseSpec.model_fields and table != "title"):
                raise CaseError(path, key, "name a key of the table, e.g. 'operation.speed'")
            data[table] = value
            continue
        if index is None:
            section = data.setdefault(table, {})
            if not isinstance(section, dict):
                raise CaseError(
                    path, table, "is an array of tables: name one, e.g. " + table + "[1]"
                )
            section[name] = value
            continue
        entries = data.get(table, [])
        position = int(index)
        if not isinstance(entries, list) or not 1 <= position <= len(entries):
            count = len(entries) if isinstance(entries, list) else 0
            raise CaseError(
                path,
                f"{table}[{position}]",
                f"the case has {count} [[{table}]] entries (counted from 1)",
            )
        entry = entries[position - 1]
        if not isinstance(entry, dict):  # a malformed file: `waviness = [1, 2]`
            raise CaseError(path, f"{table}[{position}]", "is not a table; fix the file first")
        entry[name] = value


def _one_line(text: str) -> str:
    return "".join(ch if ch.isprintable() else repr(ch)[1:-1] for ch in text)
