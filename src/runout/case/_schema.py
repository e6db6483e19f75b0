"""The case file's schema: one pydantic model per table, units read at the edge, and
the messages of its validation errors.

Part of :mod:`runout.case.model` (its module docstring describes case files).
"""

from __future__ import annotations

import difflib
import math
import re
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    field_validator,
    model_validator,
)

from runout.base.units import UnitError, to_si
from runout.case.limits import MAX_BINS, MAX_ELEMENTS, MAX_ENTRIES, MAX_ORDER
from runout.case.standards import (
    StandardsError,
    ball_grade,
    class_limit,
    is_class_name,
)
from runout.geometry.bearing_damping import MAX_DAMPING_COEFFICIENT_S
from runout.geometry.life import MAX_DYNAMIC_LOAD_RATING, RELIABILITY_FACTORS

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
    "spindle",
)
#: Most bearings on one spindle shaft (``[[bearings]]``): bounded before anything is built.
MAX_BEARINGS = 8


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
KinematicViscosity = Annotated[float, _quantity("kinematic_viscosity")]
MemoryQ = Annotated[float, _quantity("memory")]
Frequency = Annotated[float, _quantity("frequency")]


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

    designation: str | None = Field(
        None,
        description=(
            'Catalogue designation ("6204", "7014C", "NU209", "6205-2RS JEM SKF"): alone a '
            "whole bearing (type and geometry from the catalogue, `runout catalogue` lists "
            "it); a key given beside it replaces the catalogue's value, with a note."
        ),
    )
    type: Literal["ball", "cylindrical_roller"] = Field(
        "ball", description='"ball" (deep-groove or angular-contact) or "cylindrical_roller".'
    )
    elements: int = Field(
        description="Number of balls or rollers Z (3 to 10 000); required without designation."
    )
    element_diameter: Length = Field(
        description="Ball or roller diameter [m]; required without designation."
    )
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
    dynamic_load_rating: Force | None = Field(
        None,
        description=(
            "Basic dynamic load rating C [N] (catalogue, ISO 281): with it the equilibrium "
            "model reports the ISO/TS 16281 reference rating life L10r (JSON life), the spindle "
            "model each such bearing's (JSON bearings[].life)."
        ),
    )

    fatigue_load_limit: Force | None = Field(
        None,
        description=(
            "Fatigue load limit C_u [N] (catalogue, ISO 281): with [lubrication] "
            "contamination_factor and viscosity_ratio (or operating_viscosity), the "
            "equilibrium model reports the modified reference rating life L_nmr = a_1 a_ISO "
            "L10r (JSON life.lnmr_mrev)."
        ),
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

    @field_validator("dynamic_load_rating", "fatigue_load_limit")
    @classmethod
    def _rating(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 < value <= MAX_DYNAMIC_LOAD_RATING:
            raise ValueError(
                f"must be > 0 and at most {MAX_DYNAMIC_LOAD_RATING:.0e} N (the largest slewing "
                f"bearings are rated at a few tens of MN), got {value!r} N"
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


class SpindleBearingSpec(BearingSpec):
    """``[[bearings]]``: one bearing of a spindle, every ``[bearing]`` key plus its name and
    axial position."""

    name: str = Field(
        description="Name the imperfection tables use (bearing = ...) and the outputs show."
    )
    position: Length = Field(
        description="Axial coordinate of the bearing's ball-set plane along the shaft [m]; two "
        "bearings lie at least half the sum of their ball diameters apart (their rings are at "
        "least as wide as their balls)."
    )

    @field_validator("name")
    @classmethod
    def _name(cls, value: str) -> str:
        if not re.fullmatch(r"[A-Za-z0-9_-]{1,32}", value):
            raise ValueError(f"must be 1 to 32 letters, digits, '_' or '-', got {_Short(value)!r}")
        return value


class SpindleSpec(_Table):
    """``[spindle]``: a rigid shaft on the ``[[bearings]]`` (model = "spindle")."""

    arrangement: Literal["DB", "DF", "DT"] = Field(
        "DB",
        description=(
            'Directions of the contact angles: "DB" back-to-back (pressure centres outside the '
            'bearings), "DF" face-to-face (inside), "DT" tandem (all take thrust along +z).'
        ),
    )
    preload: Force | None = Field(
        None,
        description=(
            "Constant-pressure (spring) preload [N]: the rear group's outer rings slide "
            "axially on a spring of this force (DT: an axial force on the shaft)."
        ),
    )
    preload_displacement: Length | None = Field(
        None,
        description=(
            "Position (rigid) preload [m]: the axial overlap of the two groups' bearings, "
            "shared half and half at the reference position (DB and DF only)."
        ),
    )
    nose_position: Length = Field(
        0.0, description="Axial coordinate where the runout is reported (disk hub, tool) [m]."
    )

    @model_validator(mode="after")
    def _one_preload(self) -> SpindleSpec:
        if (self.preload is None) == (self.preload_displacement is None):
            raise _KeyedError("preload", "give exactly one of preload or preload_displacement")
        value = self.preload if self.preload is not None else self.preload_displacement
        key = "preload" if self.preload is not None else "preload_displacement"
        if value is not None and not value > 0.0:
            raise _KeyedError(key, f"must be > 0, got {value!r}")
        if self.preload_displacement is not None and self.arrangement == "DT":
            raise _KeyedError(
                "preload_displacement",
                'a tandem (DT) set has no opposed bearing to press against: give preload = "... '
                'N" (an axial force on the shaft), or arrangement = "DB" or "DF"',
            )
        return self


class MaterialSpec(_Table):
    """``[material]``: elastic and inertial properties (default: bearing steel)."""

    youngs_modulus: Pressure = Field(208e9, description="Young's modulus [Pa].")
    poisson_ratio: Plain = Field(0.3, description="Poisson's ratio [-].")
    density: Density = Field(7850.0, description="Density [kg/m^3].")


#: Smallest nonzero speed of a case [Hz] (one revolution in about 11.6 days).
MIN_SPEED_HZ = 1e-6


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
    axial_load: Force = Field(
        0.0,
        description="Axial load on the shaft along +z [N]; with preload it is the preload force.",
    )
    preload: Literal["spring", "position"] = Field(
        "spring",
        description=(
            'What holds the rings axially. "spring": a constant axial force (the '
            "constant-pressure preload of seeds 000 and 001); the shaft moves axially under "
            'the other loads. "position": the rings are held at the axial offset the axial '
            "load sets alone (no radial load, perfect bearing), whatever the other loads."
        ),
    )
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
        if 0.0 < value < MIN_SPEED_HZ:
            # a record of even one revolution would last longer than float64 time can hold
            # with any resolution (and than any bearing runs): not a speed, a typing slip
            raise ValueError(
                f"must be 0 (at rest) or at least {MIN_SPEED_HZ:g} Hz, got {value!r} Hz"
            )
        return value


#: Largest viscosity ratio κ read [-]: ISO 281 takes anything above 4 as 4; beyond 1000 the
#: number is a typing slip, not a lubricant.
MAX_VISCOSITY_RATIO_READ = 1000.0
#: Largest kinematic viscosity read [m²/s] (10^6 mm²/s: bitumen, not a bearing lubricant).
MAX_KINEMATIC_VISCOSITY = 1.0


class LubricationSpec(_Table):
    """``[lubrication]``: the inputs of ISO 281's life modification factor a_ISO."""

    viscosity_ratio: Plain | None = Field(
        None,
        description=(
            "Viscosity ratio κ = ν/ν_1 [-] at the operating temperature (ISO 281), > 0; above "
            "4 it is taken as 4, below 0.1 there is no a_ISO (a note says so). Or give "
            "operating_viscosity."
        ),
    )
    operating_viscosity: KinematicViscosity | None = Field(
        None,
        description=(
            "Kinematic viscosity ν of the lubricant at the operating temperature [m²/s] (e.g. "
            '"20 mm^2/s" or "20 cSt"): κ = ν/ν_1, ν_1 = rated_viscosity or ISO 281\'s from '
            "the speed and pitch diameter. Not with viscosity_ratio."
        ),
    )
    rated_viscosity: KinematicViscosity | None = Field(
        None,
        description=(
            "Rated (reference) viscosity ν_1 [m²/s], only with operating_viscosity; default "
            "ISO 281's ν_1 at the relative ring speed and pitch diameter."
        ),
    )
    contamination_factor: Plain | None = Field(
        None,
        description=(
            "Contamination factor e_C [-], 0 (severe) to 1 (extreme cleanliness), ISO 281's tables."
        ),
    )

    @field_validator("viscosity_ratio")
    @classmethod
    def _ratio(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 < value <= MAX_VISCOSITY_RATIO_READ:
            raise ValueError(
                f"must be > 0 and at most {MAX_VISCOSITY_RATIO_READ:g}, got {_Short(value)!r}"
            )
        return value

    @field_validator("operating_viscosity", "rated_viscosity")
    @classmethod
    def _viscosity(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 < value <= MAX_KINEMATIC_VISCOSITY:
            raise ValueError(
                f"must be > 0 and at most {MAX_KINEMATIC_VISCOSITY:g} m^2/s, got "
                f"{_Short(value)!r} m^2/s"
            )
        return value

    @field_validator("contamination_factor")
    @classmethod
    def _contamination(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 <= value <= 1.0:
            raise ValueError(f"must lie in [0, 1], got {_Short(value)!r}")
        return value

    @model_validator(mode="after")
    def _one_viscosity(self) -> LubricationSpec:
        if self.viscosity_ratio is not None and self.operating_viscosity is not None:
            raise _KeyedError(
                "operating_viscosity",
                "give viscosity_ratio or operating_viscosity, not both",
            )
        if self.rated_viscosity is not None and self.operating_viscosity is None:
            raise _KeyedError(
                "rated_viscosity",
                "only with operating_viscosity (κ = operating_viscosity / rated_viscosity)",
            )
        return self


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
    bearing: str | None = Field(
        None, description="Name of the [[bearings]] entry (spindle cases only; required there)."
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


class DefectSpec(_Table):
    """``[[defect]]``: one localized defect (a spall) on a raceway or a ball (model dynamic)."""

    part: Literal["outer", "inner", "ball"] = Field(
        description='"outer" or "inner" raceway, or a "ball" (its element).'
    )
    width: Length = Field(
        description="Length of the spall along the rolling direction [m] (> 0; the bearing "
        "bounds it: below a tenth of the raceway's or ball's circumference)."
    )
    depth: Length = Field(
        description="Depth of the spall [m] (> 0, below the ball radius); a ball of diameter D "
        "drops at most D/2 - sqrt(D^2/4 - width^2/4) into it."
    )
    angle: AngleQ | None = Field(
        None,
        description="Ring defects: angle of the spall's centre on the ring [rad], "
        "counter-clockwise from +x at t = 0 (the frame of radial_load_direction); default 0.",
    )
    element: int | None = Field(
        None,
        ge=1,
        description="Ball defects: the ball (1-based, as [[waviness]] element); the spall "
        "faces the outer raceway at t = 0.",
    )

    @field_validator("width", "depth")
    @classmethod
    def _positive(cls, value: float) -> float:
        if not value > 0.0:
            raise ValueError(f"must be > 0, got {value!r} m")
        return value

    @model_validator(mode="after")
    def _where(self) -> DefectSpec:
        if self.part == "ball":
            if self.element is None:
                raise _KeyedError("element", 'required for part = "ball": which ball (1-based)')
            if self.angle is not None:
                raise _KeyedError(
                    "angle",
                    "only applies to ring defects; a ball defect faces the outer raceway at t = 0",
                )
        elif self.element is not None:
            raise _KeyedError("element", f'only applies to part = "ball", not "{self.part}"')
        return self


#: Most housing modes of one sensor (``[[sensor.modes]]``): bounded before anything is built.
MAX_SENSOR_MODES = 16


def _positive_hz(value: float) -> float:
    if not value > 0.0:
        raise ValueError(f"must be > 0, got {value!r} Hz")
    return value


def _damping_ratio(value: float) -> float:
    if not 0.0 < value < 1.0:
        raise ValueError(f"must be between 0 and 1 (exclusive), got {value!r}")
    return value


class SensorModeSpec(_Table):
    """``[[sensor.modes]]`` entry: one mode of the housing; the sensor reads the sum of the
    modes' accelerations."""

    resonance: Frequency = Field(description="Natural frequency of the mode [Hz] (> 0).")
    damping_ratio: Plain = Field(description="Damping ratio of the mode [-], 0 < zeta < 1.")
    modal_mass: Mass = Field(
        description="Modal mass of the mode as the bearing's force and the sensor see it [kg]: "
        "its mass over the product of its shape at the bearing and at the sensor, negative "
        "where the shape has opposite signs there (never 0)."
    )

    @field_validator("resonance")
    @classmethod
    def _resonance(cls, value: float) -> float:
        return _positive_hz(value)

    @field_validator("damping_ratio")
    @classmethod
    def _ratio(cls, value: float) -> float:
        return _damping_ratio(value)

    @field_validator("modal_mass")
    @classmethod
    def _mass(cls, value: float) -> float:
        if value == 0.0:
            raise ValueError("must not be 0 (a mode of no mass has no finite response)")
        return value


class SensorSpec(_Table):
    """``[sensor]``: the accelerometer on the housing (``[analysis] signal = "acceleration"``)."""

    resonance: Frequency | None = Field(
        None,
        description="Natural frequency of the housing mode the impacts ring [Hz] (> 0); "
        "required unless modes are given.",
    )
    damping_ratio: Plain | None = Field(
        None,
        description="Damping ratio of that mode [-], 0 < zeta < 1; required unless modes are "
        "given.",
    )
    modes: list[SensorModeSpec] | None = Field(
        None,
        description="Several modes of the housing instead of one ([[sensor.modes]] tables, "
        f"1 to {MAX_SENSOR_MODES}, each with resonance, damping_ratio and modal_mass): the "
        "sensor reads the sum of their accelerations; not with resonance, damping_ratio or "
        "modal_mass beside them.",
    )
    sample_rate: Frequency = Field(
        description="Sample rate of the signal [Hz], above twice the (highest) resonance."
    )
    duration: Time | None = Field(
        None,
        description="Length of the signal [s]; default the analysis window (revolutions / speed).",
    )
    modal_mass: Mass | None = Field(
        None,
        description="Modal mass of the housing mode [kg]; default the [dynamics] mass.",
    )
    noise: Plain = Field(
        0.0, description="Rms of the added Gaussian noise over the signal's rms [-] (>= 0)."
    )
    seed: int = Field(
        0, ge=0, description="Seed of the noise's, the slip's and the speed fluctuation's draws."
    )
    slip: Plain = Field(
        0.0,
        description="Random slip of the rolling elements, 0 to 0.05: the relative standard "
        "deviation of the cage's speed, drawn anew each ball passage (each impact period "
        "jitters by about as much; 0.01-0.02 is typical).",
    )
    speed_fluctuation: Plain | None = Field(
        None,
        description="Random slow fluctuation of the shaft speed, 0 to 0.1: the rms of its "
        "relative deviation from the [operation] speed over the signal (the mean stays the "
        "speed); a sum of 8 sinusoids of random frequencies up to a tenth of the shaft speed and "
        "random phases, drawn from seed. The impacts and the rev column follow the fluctuating "
        "shaft angle; default none (a constant speed).",
    )
    band: tuple[Frequency, Frequency] | None = Field(
        None,
        description='Pass band of the run\'s envelope spectrum [Hz], [low, high] (e.g. ["2 kHz", '
        '"4 kHz"]), 0 <= low < high <= half the sample rate; default the band the fast '
        "kurtogram finds most impulsive.",
        strict=False,
    )

    @field_validator("resonance", "sample_rate")
    @classmethod
    def _positive_rate(cls, value: float | None) -> float | None:
        return None if value is None else _positive_hz(value)

    @field_validator("damping_ratio")
    @classmethod
    def _ratio(cls, value: float | None) -> float | None:
        return None if value is None else _damping_ratio(value)

    @field_validator("modes")
    @classmethod
    def _modes(cls, value: list[SensorModeSpec] | None) -> list[SensorModeSpec] | None:
        if value is not None and not 1 <= len(value) <= MAX_SENSOR_MODES:
            raise ValueError(f"must hold 1 to {MAX_SENSOR_MODES} modes, got {len(value)}")
        return value

    @field_validator("noise")
    @classmethod
    def _noise(cls, value: float) -> float:
        if not 0.0 <= value <= 100.0:
            raise ValueError(f"must be from 0 to 100 (times the signal's rms), got {value!r}")
        return value

    @field_validator("slip")
    @classmethod
    def _slip(cls, value: float) -> float:
        if not 0.0 <= value <= 0.05:
            raise ValueError(f"must be from 0 to 0.05 (0.02 = 2 %), got {value!r}")
        return value

    @field_validator("speed_fluctuation")
    @classmethod
    def _fluctuation(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 <= value <= 0.1:
            raise ValueError(f"must be from 0 to 0.1 (0.01 = 1 % rms), got {value!r}")
        return value

    @field_validator("duration", "modal_mass")
    @classmethod
    def _positive(cls, value: float | None) -> float | None:
        if value is not None and not value > 0.0:
            raise ValueError(f"must be > 0, got {value!r}")
        return value

    def housing_modes(self) -> list[tuple[float, float, float | None]]:
        """The housing's modes: (resonance [Hz], damping ratio [-], modal mass [kg] or None
        for the [dynamics] mass), from ``modes`` or from the single mode's keys."""
        if self.modes is not None:
            return [(m.resonance, m.damping_ratio, m.modal_mass) for m in self.modes]
        assert self.resonance is not None and self.damping_ratio is not None  # _nyquist
        return [(self.resonance, self.damping_ratio, self.modal_mass)]

    @model_validator(mode="after")
    def _nyquist(self) -> SensorSpec:
        if self.modes is not None:
            for key in ("resonance", "damping_ratio", "modal_mass"):
                if getattr(self, key) is not None:
                    raise _KeyedError(
                        key,
                        "not beside modes: give it in each [[sensor.modes]] entry (or drop "
                        "modes for a single mode)",
                    )
        else:
            for key in ("resonance", "damping_ratio"):
                if getattr(self, key) is None:
                    raise _KeyedError(
                        key, "required (the housing mode), unless [[sensor.modes]] are given"
                    )
        top = max(f for f, _, _ in self.housing_modes())
        if self.sample_rate <= 2.0 * top:
            which = "resonance" if self.modes is None else "highest resonance"
            raise _KeyedError(
                "sample_rate",
                f"must be above twice the {which} ({2.0 * top:.6g} Hz), got "
                f"{self.sample_rate:.6g} Hz",
            )
        if self.band is not None:
            low, high = self.band
            half = 0.5 * self.sample_rate
            if not (0.0 <= low < high <= half):
                raise _KeyedError(
                    "band",
                    f"must be [low, high] with 0 <= low < high <= {half:.6g} Hz (half the "
                    f"sample rate), got [{low:.6g}, {high:.6g}] Hz",
                )
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
    bearing: str | None = Field(
        None, description="Name of the [[bearings]] entry (spindle cases only; required there)."
    )

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
    bearing: str | None = Field(
        None, description="Name of the [[bearings]] entry (spindle cases only; required there)."
    )

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
    grade: str | None = Field(
        None,
        description=(
            'ISO 3290-1 grade of the balls (e.g. "G5"; G3 to G200): a run draws no ball sizes '
            "and says so in notes; a Monte Carlo draws them with [study.vary] ball_grade "
            "(sigma = V_DWL / grade_sigma_divisor); docs/studies.md."
        ),
    )
    grade_sigma_divisor: float | None = Field(
        None,
        gt=0.0,
        le=1e3,
        description=(
            "The lot diameter variation V_DWL of a ball grade taken as this many standard "
            "deviations of the balls' diameters (default 6: +-3 sigma)."
        ),
    )
    grade_form_order: int | None = Field(
        None,
        ge=2,
        description=(
            "Lobes of the balls' form error drawn from the grade: a Monte Carlo's ball_grade "
            "(or element_diameter_sigma on a graded bearing) also gives each ball one harmonic "
            "of this order, amplitude uniform from 0 to the grade's bound (t_Dw / 2; even "
            "orders also V_DWs / 4) and a uniform phase; default: no form drawn."
        ),
    )

    @field_validator("grade_form_order")
    @classmethod
    def _bounded_form_order(cls, value: int | None) -> int | None:
        if value is not None:
            _order_at_most(value)
        return value

    @field_validator("grade")
    @classmethod
    def _known_grade(cls, value: str | None) -> str | None:
        if value is None:
            return value
        try:
            return ball_grade(value).name
        except StandardsError as exc:
            raise ValueError(str(exc)) from None


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
        "spindle",
    ] = Field(
        "quasi_static_3d", description="Model id (docs/conventions.md: which keys each honours)."
    )
    revolutions: float = Field(
        20.0,
        ge=1e-6,
        le=1e9,
        description=(
            "Revolutions of the rotating ring, 10^-6 to 10^9 (a shorter record holds no motion "
            "the models resolve; beyond, the ring angle's round-off exceeds a microradian)."
        ),
    )
    samples: int = Field(4096, ge=16, description="Number of instants.")
    # None when unset (read as "displacement"): a study's digest hashes the defaults
    signal: Literal["displacement", "acceleration"] | None = Field(
        None,
        description='"displacement" (default) or "acceleration": also the housing acceleration '
        'measured by [sensor] (model = "dynamic"; run --out writes signal.csv, the JSON an '
        "envelope block).",
    )
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
    ring_tilt: Literal["free", "held"] | None = Field(
        None,
        description=(
            'model = "equilibrium" only: "free" (default): the inner ring tilts until the '
            'balls\' moment balances moment_load; "held": its tilts are held at 0 (as the 3-DOF '
            "models hold them), the balls' moment on it is a reaction (JSON "
            "reaction_moment_n_m); refused with a moment_load."
        ),
    )
    # reliability and moment_arm: None when unset (read as 90 and "curvature_centres"), so that
    # a study's digest, which hashes the defaults, stays that of earlier versions
    reliability: Plain | None = Field(
        None,
        description=(
            "Reliability of the modified reference rating life [%] (default 90): "
            + ", ".join(f"{p:g}" for p in RELIABILITY_FACTORS)
            + " (ISO 281's a_1 table; 90: a_1 = 1)."
        ),
    )
    moment_arm: Literal["curvature_centres", "pitch_radius"] | None = Field(
        None,
        description=(
            "model = \"equilibrium\" only: arm of the balls' axial forces in the inner ring's "
            'moment equations: "curvature_centres" (default; the radius of the inner groove '
            'curvature centres, Harris) or "pitch_radius" (d_m/2, as ISO/TS 16281 writes its '
            "moment equilibrium; a given moment_load then loads the balls slightly more)."
        ),
    )
    # None when unset (read as "none"): a study's digest hashes the defaults, and a new
    # default would change every digest (earlier output directories would not resume)
    bearing_damping: Literal["none", "kraemer", "proportional"] | None = Field(
        None,
        description=(
            'model = "equilibrium" only: damping of the bearing coefficients, c = β k for every '
            'coefficient (JSON bearing_damping, stiffness.csv columns cxx_n_s_per_m ...): "none" '
            '(default: stiffness only, no damping written), "kraemer" (β = 0.79e-5 s, the '
            "geometric mean of Krämer's (0.25 ... 2.5) × 10^-5 s for rolling bearings, Dynamics "
            'of Rotors and Foundations, 1993: an estimate, not a measurement) or "proportional" '
            "(the user's β, bearing_damping_coefficient)."
        ),
    )
    bearing_damping_coefficient: Time | None = Field(
        None,
        description=(
            'β of bearing_damping = "proportional" [s] (e.g. "2e-5 s"): c = β k, from 0 to '
            "1e-3 s (40 times Krämer's upper end; above it a bearing would be critically damped "
            "at a few hundred Hz)."
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
            '(e.g. "50 um/s") for a band, or an ISO 492 tolerance class ("Normal", "P6", "P5", '
            '"P4", "P2": its K_ia for the bore limit_bore; limit_on then defaults to "rro_pp"). '
            "run: JSON verdict (pass: value <= limit); study: JSON yield with a "
            "Clopper-Pearson 95 % interval."
        ),
    )
    limit_on: LimitQuantity = Field(
        "radial_pp",
        description=(
            'Quantity the limit applies to: "radial_pp", "rro_pp", "nrro_pp", "axial_pp" '
            '(runout p-p [m]) or "iso15242.L", "iso15242.M", "iso15242.H" (band rms, needs '
            'bands = "iso15242"; run only). Default "radial_pp", "rro_pp" with a tolerance class.'
        ),
    )
    limit_bore: Length | None = Field(
        None,
        description=(
            "Bore d of the bearing [m] (2.5 mm < d <= 120 mm), which selects the K_ia row of a "
            "tolerance class limit (ISO 492:2014); default with [bearing] designation: its "
            "catalogue bore (with a note)."
        ),
    )

    @field_validator("reliability")
    @classmethod
    def _reliability_row(cls, value: float | None) -> float | None:
        if value is not None and value not in RELIABILITY_FACTORS:
            rows = ", ".join(f"{p:g}" for p in RELIABILITY_FACTORS)
            raise ValueError(
                f"must be one of {rows} (%; ISO 281's a_1 table), got {_Short(value)!r}"
            )
        return value

    @model_validator(mode="before")
    @classmethod
    def _class_quantity(cls, value: object) -> object:
        # K_ia is the repeatable runout of the rotating inner ring: the default quantity of a
        # class limit (an explicit limit_on is kept and checked below)
        if (
            isinstance(value, dict)
            and isinstance(value.get("limit"), str)
            and is_class_name(value["limit"])
            and "limit_on" not in value
        ):
            return {**value, "limit_on": "rro_pp"}
        return value

    @property
    def tolerance_class(self) -> str | None:
        """The ISO 492 class ``limit`` names, or None for a numeric limit (or none)."""
        if isinstance(self.limit, str) and is_class_name(self.limit):
            return self.limit
        return None

    @field_validator("bearing_damping_coefficient")
    @classmethod
    def _bounded_damping_coefficient(cls, value: float | None) -> float | None:
        if value is not None and not 0.0 <= value <= MAX_DAMPING_COEFFICIENT_S:
            raise ValueError(f"must be from 0 to {MAX_DAMPING_COEFFICIENT_S:g} s, got {value!r} s")
        return value

    @model_validator(mode="after")
    def _check_damping(self) -> AnalysisSpec:
        given = self.bearing_damping_coefficient is not None
        if self.bearing_damping == "proportional" and not given:
            raise _KeyedError(
                "bearing_damping",
                '"proportional" needs analysis.bearing_damping_coefficient (β [s], e.g. "2e-5 s")',
            )
        if given and self.bearing_damping != "proportional":
            raise _KeyedError(
                "bearing_damping_coefficient",
                'only applies to bearing_damping = "proportional" (got '
                f'bearing_damping = "{self.bearing_damping or "none"}")',
            )
        return self

    @model_validator(mode="after")
    def _check_limit(self) -> AnalysisSpec:
        if self.limit is None:
            # a case re-serialised with its defaults (study variants) names the default
            if self.limit_on != "radial_pp":
                raise _KeyedError("limit_on", "needs analysis.limit (the spec limit)")
            if self.limit_bore is not None:
                raise _KeyedError("limit_bore", 'needs a tolerance class limit (e.g. "P4")')
            return self
        if self.tolerance_class is not None:
            analysis_limit(self)  # raises _KeyedError("limit" or "limit_bore", ...)
            return self
        if self.limit_bore is not None:
            raise _KeyedError(
                "limit_bore", 'only applies to a tolerance class limit (e.g. limit = "P4")'
            )
        limit_si(self.limit, self.limit_on)  # raises _KeyedError("limit", ...)
        if is_band_quantity(self.limit_on) and self.bands != "iso15242":
            raise _KeyedError(
                "limit_on", f'"{self.limit_on}" is a band: it needs bands = "iso15242"'
            )
        return self


def analysis_limit(analysis: AnalysisSpec) -> tuple[float, dict[str, Any] | None]:
    """The spec limit of ``[analysis]`` in SI and, for a tolerance class, what it is.

    Parameters
    ----------
    analysis : AnalysisSpec
        A table with a ``limit``.

    Returns
    -------
    tuple
        The limit ([m] for a runout p-p, [m/s] for a band) and None, or for an ISO 492 class
        K_ia [m] and ``{"class", "bore_m", "source"}`` (the verdict's and yield's keys).

    Raises
    ------
    _KeyedError
        ``limit``: an unknown class (close matches), a class on a quantity other than the
        radial runout; ``limit_bore``: missing, or outside the table.
    """
    assert analysis.limit is not None
    name = analysis.tolerance_class
    if name is None:
        return limit_si(analysis.limit, analysis.limit_on), None
    if analysis.limit_on not in ("rro_pp", "radial_pp"):
        raise _KeyedError(
            "limit_on",
            f'"{analysis.limit_on}": an ISO 492 class limits K_ia, the radial runout of the '
            'inner ring: limit_on = "rro_pp" (its default) or "radial_pp"',
        )
    try:
        class_limit(name, 0.025)  # the class name first: its error names limit
    except StandardsError as exc:
        raise _KeyedError("limit", str(exc)) from None
    if analysis.limit_bore is None:
        raise _KeyedError(
            "limit_bore",
            f'required with limit = "{name}": the bearing\'s bore d (e.g. limit_bore = '
            '"25 mm"), which selects the K_ia row of ISO 492',
        )
    try:
        found = class_limit(name, analysis.limit_bore)
    except StandardsError as exc:
        raise _KeyedError("limit_bore", str(exc)) from None
    return found.limit, {
        "class": found.tolerance_class,
        "bore_m": found.bore,
        "source": found.source,
    }


class DynamicsSpec(_Table):
    """``[dynamics]``: rotor for model = "dynamic"."""

    mass: Mass = Field(description="Rotor mass carried by the bearing [kg].")
    damping: Damping = Field(0.0, description="Viscous damping [N s/m] (>= 0).")
    unbalance: Unbalance = Field(0.0, description="Unbalance m e [kg m] (>= 0).")
    time_step: Time | None = Field(None, description="Integration step [s]; default automatic.")
    axial_dof: bool | None = Field(
        None,
        description=(
            'Kept for older case files: true is [operation] preload = "spring", false is '
            'preload = "position" (the run says so); write preload instead.'
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


#: ``[study.vary]`` shorthands (Monte Carlo): key -> what it draws. A spindle names the
#: bearing after a dot, as its ``[elements.<name>]`` tables do: ``element_diameter_sigma.front``.
STUDY_SHORTHANDS = {
    "element_diameter_sigma": (
        "standard deviation [m] of a normal error added to every element's diameter error"
    ),
    "ball_grade": (
        'ISO 3290-1 grade of the balls (e.g. "G5"): element_diameter_sigma = V_DWL / '
        "grade_sigma_divisor ([elements], default 6)"
    ),
}
#: A spindle bearing's per-element key: ``elements.<name>.diameter_errors`` (or pitch_errors).
_BEARING_ELEMENTS_KEY = re.compile(
    r"elements\.([A-Za-z0-9_-]{1,32})\.(diameter_errors|pitch_errors)"
)


def split_shorthand(key: str) -> tuple[str, str | None] | None:
    """``(shorthand, bearing name or None)`` of a ``[study.vary]`` shorthand key, else None.

    ``"element_diameter_sigma"`` gives ``("element_diameter_sigma", None)``;
    ``"element_diameter_sigma.front"`` (a spindle's bearing ``front``) gives
    ``("element_diameter_sigma", "front")``.
    """
    base, dot, name = key.partition(".")
    if base not in STUDY_SHORTHANDS:
        return None
    if not dot:
        return base, None
    return (base, name) if re.fullmatch(r"[A-Za-z0-9_-]{1,32}", name) else None


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

    A spindle bearing's element key ``elements.<name>.diameter_errors`` gives the table
    ``"elements.<name>"`` (the bearing's name is checked against the case by the study plan).

    Raises
    ------
    ValueError
        With a did-you-mean hint when the table or the key does not exist.
    """

    bearing = _BEARING_ELEMENTS_KEY.fullmatch(key)
    if bearing is not None:
        # a spindle bearing's [elements.<name>] key: the table carries the bearing's name
        return f"elements.{bearing.group(1)}", None, bearing.group(2)
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


#: ``[study] minimise`` of ``kind = "arrangement"``: what the chosen order makes smallest.
ARRANGEMENT_OBJECTIVES = ("lines", "line", "nrro_pp", "band")
#: ``[study] line``: the f_c line or a k f_b +- f_c line of an even order k (seed 001 Tables 4-8).
_ARRANGEMENT_LINE = re.compile(r"fc|([1-9][0-9]{0,2})fb([+-])fc")
#: ``[study]`` keys that only ``kind = "arrangement"`` reads.
ARRANGEMENT_KEYS = ("lot", "minimise", "line", "band", "random_orders")
#: Random assemblies an arrangement is compared with when ``random_orders`` is not given.
DEFAULT_RANDOM_ORDERS = 4000


class StudySpec(_Table):
    """``[study]``: for ``runout study`` (Monte Carlo, sweeps, or a ball arrangement)."""

    kind: Literal["montecarlo", "sweep", "arrangement"] = Field(
        description='"montecarlo", "sweep" or "arrangement" (the order of a lot\'s balls).'
    )
    samples: int = Field(100, ge=1, description="Number of Monte Carlo samples (bearings).")
    seed: int = Field(
        0, ge=0, description="Root seed: sample i draws from SeedSequence(seed, spawn_key=(i,))."
    )
    chunk_size: int | None = Field(
        None,
        ge=1,
        description=(
            "Samples per task and per result file (--out, --resume). Default: chosen from the "
            "estimated cost of a sample, about a quarter second of work per chunk, at least four "
            "chunks per worker or thread, at most 2048 samples; the numbers do not depend "
            "on it."
        ),
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
    statistics: Literal["auto", "exact", "streaming"] = Field(
        "auto",
        description=(
            'Monte Carlo statistics: "exact" (every sample\'s figures kept in memory: exact '
            'percentiles, samples.csv), "streaming" (memory independent of samples: exact '
            'mean, std, min and max, percentiles within a relative 1e-4) or "auto" (exact when '
            "the columns fit the memory budget, streaming otherwise; said in notes)."
        ),
    )
    allocate: str | None = Field(
        None,
        description=(
            "Tolerance allocation: the [study.vary] key whose tolerance runout study finds "
            "(element_diameter_sigma, a normal std or a uniform high): the largest value for "
            "which the lot meets analysis.limit with target_yield (docs/studies.md)."
        ),
    )
    target_yield: float | None = Field(
        None,
        gt=0.0,
        lt=1.0,
        description=(
            "Tolerance allocation: fraction of the lot within analysis.limit (0 < y < 1); "
            "with allocate."
        ),
    )
    vary: dict[str, VarySpec | RawQuantity] = Field(
        default_factory=dict,
        description=(
            'Quantities to vary: "table.key" = {distribution = ...} (Monte Carlo) or '
            "{values = [...]} or {start, stop, num or step} (sweep); shorthand "
            'element_diameter_sigma = "0.1 um" (a spindle: "element_diameter_sigma.<bearing>") '
            'or ball_grade = "G5" (ISO 3290-1; a spindle: "ball_grade.<bearing>"). '
            "Keys of each entry: docs/studies.md."
        ),
    )

    lot: str | None = Field(
        None,
        description=(
            "Arrangement: CSV file of the measured balls of the lot, one row per ball (columns "
            "diameter_error_um, waviness_<k>_amplitude_um, waviness_<k>_phase_deg; "
            "docs/studies.md), relative to the case file."
        ),
    )
    # None rather than the defaults in the schema: a Monte Carlo or a sweep dumped with
    # exclude_none and parsed again must not carry keys only an arrangement reads
    minimise: Literal["lines", "line", "nrro_pp", "band"] | None = Field(
        None,
        description=(
            'Arrangement: what the chosen order makes smallest: "lines" (the default: sum of '
            'the p-p of the f_c and k f_b +- f_c lines), "line" (one of them: line = ...), '
            '"nrro_pp" (NRRO p-p along the measuring direction) or "band" (an Anderon band: '
            "band = ...)."
        ),
    )
    line: str | None = Field(
        None,
        description=(
            'Arrangement, minimise = "line": "fc" or "<k>fb+fc" / "<k>fb-fc" with k an even '
            'order of the lot\'s waviness (e.g. "2fb+fc").'
        ),
    )
    band: Literal["U", "R", "L", "M", "H"] | None = Field(
        None, description='Arrangement, minimise = "band": the Anderon band (U, R, L, M, H).'
    )
    random_orders: int | None = Field(
        None,
        ge=1,
        le=1_000_000,
        description=(
            "Arrangement: random assemblies (Z balls of the lot in random order) the chosen "
            f"order is compared with (default {DEFAULT_RANDOM_ORDERS})."
        ),
    )

    @property
    def arrangement_goal(self) -> Literal["lines", "line", "nrro_pp", "band"]:
        """``minimise`` of an arrangement, its default ("lines") where the case names none."""
        return self.minimise or "lines"

    @property
    def arrangement_trials(self) -> int:
        """``random_orders`` of an arrangement, its default where the case names none."""
        return self.random_orders or DEFAULT_RANDOM_ORDERS

    @field_validator("line")
    @classmethod
    def _line_name(cls, value: str | None) -> str | None:
        if value is None:
            return value
        match = _ARRANGEMENT_LINE.fullmatch(value)
        if match is None or (match.group(1) is not None and int(match.group(1)) % 2):
            raise ValueError(
                f'expected "fc" or "<k>fb+fc" / "<k>fb-fc" with an even order k, got {value!r}'
            )
        return value

    @field_validator("vary", mode="before")
    @classmethod
    def _bearing_shorthands(cls, value: object) -> object:
        # element_diameter_sigma = { front = "0.1 um" } (or the unquoted dotted key
        # element_diameter_sigma.front = ..., which TOML reads as that table): one
        # "element_diameter_sigma.<bearing>" entry per bearing
        if not isinstance(value, dict):
            return value
        out: dict[object, object] = {}
        for key, entry in value.items():
            if (
                key in STUDY_SHORTHANDS
                and isinstance(entry, dict)
                and entry
                and not set(entry) & set(_VARY_KEYS)
            ):
                for name, sub in entry.items():
                    if f"{key}.{name}" in value:
                        raise _KeyedError(
                            f"{key}.{name}", "given twice (as a key and in the table); keep one"
                        )
                    out[f"{key}.{name}"] = sub
            else:
                out[key] = entry
        return out

    @model_validator(mode="after")
    def _check_vary(self) -> StudySpec:
        if self.kind == "arrangement":
            return self._check_arrangement()
        for name in ARRANGEMENT_KEYS:
            if name in self.model_fields_set:
                raise _KeyedError(name, 'only applies to kind = "arrangement"')
        if not self.vary:
            raise _KeyedError("vary", "name at least one quantity to vary")
        if self.kind == "sweep" and "samples" in self.model_fields_set:
            raise _KeyedError("samples", 'only applies to kind = "montecarlo"')
        if self.kind == "sweep" and self.statistics == "streaming":
            raise _KeyedError(
                "statistics", 'only applies to kind = "montecarlo" (a sweep lists every point)'
            )
        if self.kind == "montecarlo" and self.models is not None and len(self.models) != 1:
            raise _KeyedError("models", "a Monte Carlo study runs one model")
        if self.models is not None and not self.models:
            raise _KeyedError("models", "name at least one model")
        for key, entry in self.vary.items():
            where = f"vary.{key}"
            if split_shorthand(key) is not None:
                if self.kind != "montecarlo":
                    raise _KeyedError(where, 'shorthands apply to kind = "montecarlo" only')
                if split_shorthand(key)[0] == "ball_grade":  # type: ignore[index]
                    if not isinstance(entry, str):
                        raise _KeyedError(
                            where, f'must be a grade (e.g. "G5"), got {_Short(entry)!r}'
                        )
                    try:
                        ball_grade(entry)
                    except StandardsError as exc:
                        raise _KeyedError(where, str(exc)) from None
                    continue
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
        _check_allocation(self)
        return self

    def _check_arrangement(self) -> StudySpec:
        # the lot's balls are the study's input: nothing is drawn or swept, nothing chunked
        for name in ("vary", "samples", "chunk_size", "bins", "models", "statistics"):
            if name in self.model_fields_set:
                raise _KeyedError(
                    name, 'does not apply to kind = "arrangement" (the balls come from lot)'
                )
        if self.lot is None:
            raise _KeyedError("lot", 'required for kind = "arrangement": the CSV of the balls')
        goal = self.arrangement_goal
        if goal == "line" and self.line is None:
            raise _KeyedError("line", 'required for minimise = "line" (e.g. "fc" or "2fb+fc")')
        if goal == "band" and self.band is None:
            raise _KeyedError("band", 'required for minimise = "band" (e.g. "H")')
        if self.line is not None and goal != "line":
            raise _KeyedError("line", 'only applies to minimise = "line"')
        if self.band is not None and goal != "band":
            raise _KeyedError("band", 'only applies to minimise = "band"')
        return self


def _check_allocation(study: StudySpec) -> None:
    """``allocate`` names a drawn quantity with a tolerance; ``target_yield`` goes with it."""
    if study.allocate is None:
        if study.target_yield is not None:
            raise _KeyedError("target_yield", "needs allocate (the [study.vary] key to allocate)")
        return
    if study.kind != "montecarlo":
        raise _KeyedError("allocate", 'applies to kind = "montecarlo" (a lot of drawn bearings)')
    if study.target_yield is None:
        raise _KeyedError(
            "target_yield", "required with allocate: the fraction of the lot within the limit"
        )
    if study.allocate not in study.vary:
        keys = ", ".join(sorted(study.vary))
        raise _KeyedError(
            "allocate", f"'{study.allocate}' is not a [study.vary] key (the case varies: {keys})"
        )
    entry = study.vary[study.allocate]
    shorthand = split_shorthand(study.allocate)
    if shorthand is not None and shorthand[0] == "ball_grade":
        raise _KeyedError(
            "allocate",
            f"'{study.allocate}' is a ball grade: a grade is a table row, not a tolerance to "
            "allocate; allocate element_diameter_sigma (the grade's sigma is V_DWL / 6) and read "
            "the grade off docs/studies.md",
        )
    if isinstance(entry, VarySpec) and entry.distribution == "sample":
        raise _KeyedError(
            "allocate",
            f"'{study.allocate}' is drawn from measured values (distribution = \"sample\"): it "
            'has no tolerance to allocate; give it as distribution = "normal" (std) or '
            '"uniform" (high)',
        )


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
    bearing: BearingSpec | None = Field(
        None, description="The bearing (required, except in a spindle case: [[bearings]])."
    )
    spindle: SpindleSpec | None = None
    bearings: list[SpindleBearingSpec] = Field(default_factory=list)
    material: MaterialSpec = Field(default_factory=MaterialSpec)
    operation: OperationSpec = Field(default_factory=OperationSpec)
    waviness: list[WavinessSpec] = Field(default_factory=list)
    waviness_spectrum: list[WavinessSpectrumSpec] = Field(default_factory=list)
    profile: list[ProfileSpec] = Field(default_factory=list)
    defect: list[DefectSpec] = Field(default_factory=list)
    sensor: SensorSpec | None = None
    slant: SlantSpec | None = None
    elements: ElementsSpec | dict[str, ElementsSpec] | None = None
    analysis: AnalysisSpec = Field(default_factory=AnalysisSpec)
    lubrication: LubricationSpec | None = None
    dynamics: DynamicsSpec | None = None
    study: StudySpec | None = None

    @property
    def lead_bearing(self) -> BearingSpec:
        """``[bearing]``, or the first ``[[bearings]]`` entry of a spindle case."""
        if self.bearing is not None:
            return self.bearing
        return self.bearings[0]

    @property
    def preload_kind(self) -> Literal["spring", "position"]:
        """The preload the case runs with: ``"spring"`` or ``"position"``.

        ``[operation] preload`` when the case names it; else, in a spindle case, the kind of
        its ``[spindle]`` table (``preload`` is a spring, ``preload_displacement`` a position);
        else, in a dynamic case, the older ``[dynamics] axial_dof`` (true: spring, false:
        position), so that an older case file keeps its result; else ``"spring"``.
        """
        if "preload" in self.operation.model_fields_set:
            return self.operation.preload
        if self.spindle is not None:
            return "spring" if self.spindle.preload is not None else "position"
        dof = self.dynamics.axial_dof if self.dynamics is not None else None
        if dof is not None and self.analysis.model == "dynamic":
            return "spring" if dof else "position"
        return "spring"

    @property
    def element_tables(self) -> list[tuple[str, ElementsSpec]]:
        """(key, table) of ``[elements]``, or of each ``[elements.<name>]`` of a spindle."""
        if self.elements is None:
            return []
        if isinstance(self.elements, ElementsSpec):
            return [("elements", self.elements)]
        return [(f"elements.{name}", table) for name, table in self.elements.items()]

    @field_validator("bearings", mode="before")
    @classmethod
    def _few_bearings(cls, value: object) -> object:
        # empty: a single-bearing case (a document dumped with its defaults has bearings = [])
        if isinstance(value, list) and value and not 2 <= len(value) <= MAX_BEARINGS:
            raise ValueError(
                f"has {len(value)} entries: a spindle has 2 to {MAX_BEARINGS} bearings "
                "(one bearing: give [bearing] instead)"
            )
        return value

    @field_validator("elements", mode="before")
    @classmethod
    def _elements_table(cls, value: object) -> object:
        # [elements] (one bearing) or [elements.<name>] per spindle bearing: the second form
        # is told apart by its sub-tables, so each form reports its own errors
        if isinstance(value, dict) and value and all(isinstance(v, dict) for v in value.values()):
            tables = {}
            for name, table in value.items():
                try:
                    tables[name] = ElementsSpec.model_validate(table)
                except ValidationError as exc:  # named by its bearing: elements.<name>.key
                    raise _KeyedError(*_error_path(exc, str(name))) from None
            return tables
        if isinstance(value, dict):
            return ElementsSpec.model_validate(value)
        return value

    @model_validator(mode="after")
    def _sensor_with_signal(self) -> CaseSpec:
        # the sensor is read only for an acceleration signal, and that signal needs one
        acceleration = self.analysis.signal == "acceleration"
        if acceleration and self.sensor is None:
            raise _KeyedError(
                "analysis.signal",
                '"acceleration" needs a [sensor] table (resonance, damping_ratio, sample_rate)',
            )
        if self.sensor is not None and not acceleration:
            raise _KeyedError(
                "sensor",
                'is read only with [analysis] signal = "acceleration": add that key or remove '
                "the table",
            )
        return self

    @model_validator(mode="after")
    def _one_preload_kind(self) -> CaseSpec:
        # two keys naming two kinds are refused, never resolved one way: each reads as the
        # other would give another result
        if "preload" not in self.operation.model_fields_set:
            return self
        kind = self.operation.preload
        dof = self.dynamics.axial_dof if self.dynamics is not None else None
        if dof is not None and dof != (kind == "spring"):
            raise _KeyedError(
                "dynamics.axial_dof",
                f'{str(dof).lower()} contradicts operation.preload = "{kind}" (axial_dof = '
                'true is preload = "spring", false is "position"): remove axial_dof',
            )
        if self.spindle is not None:
            own = "spring" if self.spindle.preload is not None else "position"
            if kind != own:
                raise _KeyedError(
                    "operation.preload",
                    f'"{kind}" contradicts the [spindle] table, whose preload is a {own}: a '
                    'spindle\'s preload kind is its [spindle] key, preload = "... N" (spring) or '
                    'preload_displacement = "... um" (position); remove operation.preload',
                )
        return self

    @model_validator(mode="after")
    def _one_bearing_table(self) -> CaseSpec:
        if self.bearings:
            _check_spindle_tables(self)
            return self
        if self.bearing is None:
            raise _KeyedError("bearing", "required key is missing")
        if self.spindle is not None:
            raise _KeyedError(
                "spindle", "needs the spindle's bearings as [[bearings]] tables (two or more)"
            )
        if isinstance(self.elements, dict):
            raise _KeyedError(
                "elements", "[elements.<name>] tables name [[bearings]] entries: give [elements]"
            )
        for table in ("waviness", "waviness_spectrum", "profile"):
            for i, entry in enumerate(getattr(self, table), start=1):
                if entry.bearing is not None:
                    raise _KeyedError(
                        (table, i - 1, "bearing"),
                        "names a [[bearings]] entry of a spindle case; this case has one "
                        "[bearing]: remove the key",
                    )
        if self.analysis.model == "spindle":
            raise _KeyedError(
                "analysis.model",
                'model = "spindle" needs a [spindle] table and two or more [[bearings]] '
                "(each a [bearing] with name and position)",
            )
        return self

    @field_validator("waviness", "waviness_spectrum", "profile", "defect", mode="before")
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


def _check_spindle_tables(spec: CaseSpec) -> None:
    """The tables of a spindle case agree: one bearing table kind, names, model."""
    if spec.bearing is not None:
        raise _KeyedError(
            "bearing",
            "a case has either one [bearing] or a spindle's [[bearings]], not both: move this "
            "bearing into a [[bearings]] entry (with name and position)",
        )
    if spec.spindle is None:
        raise _KeyedError(
            "spindle",
            "required with [[bearings]]: arrangement, preload (or preload_displacement) and "
            "nose_position",
        )
    names = [b.name for b in spec.bearings]
    for i, name in enumerate(names, start=1):
        if name in names[: i - 1]:
            raise _KeyedError(("bearings", i - 1, "name"), f'"{name}" is used twice')
    if spec.analysis.model != "spindle":
        raise _KeyedError(
            "analysis.model",
            f'"{spec.analysis.model}" runs one bearing; a case with [[bearings]] runs in '
            'model = "spindle" (or give one [bearing] for the other models)',
        )
    for table in ("waviness", "waviness_spectrum", "profile"):
        for i, entry in enumerate(getattr(spec, table), start=1):
            if entry.bearing is None:
                raise _KeyedError(
                    (table, i - 1, "bearing"),
                    f'required with [[bearings]]: write bearing = "<name>" (one of '
                    f"{', '.join(names)})",
                )
            if entry.bearing not in names:
                raise _KeyedError(
                    (table, i - 1, "bearing"),
                    f'"{entry.bearing}" is not a [[bearings]] name ({", ".join(names)})',
                )
    if isinstance(spec.elements, ElementsSpec):
        raise _KeyedError(
            "elements",
            "with [[bearings]], per-bearing tables: write [elements.<name>] (one of "
            f"{', '.join(names)})",
        )
    for name in spec.elements or {}:
        if name not in names:
            raise _KeyedError(
                f"elements.{name}", f'"{name}" is not a [[bearings]] name ({", ".join(names)})'
            )


class _KeyedError(ValueError):
    """A model-validator error that belongs to one key of the table."""

    def __init__(self, key: str | tuple[str | int, ...], message: str) -> None:
        # a key inside an array of tables is given as its path: ("waviness", 2, "bearing")
        self.key = key
        super().__init__(f"{_format_loc(key) if isinstance(key, tuple) else key}: {message}")


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
            path = exc.key if isinstance(exc.key, tuple) else (exc.key,)
            return _format_loc((*loc, *path)), str(exc).split(": ", 1)[1]
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
    if kind == "less_than":
        return _format_loc(loc), f"must be < {ctx.get('lt')}, got {given!r}"
    if kind == "finite_number":
        return _format_loc(loc), f"must be a finite number, got {given!r}"
    if kind in ("recursion_loop",):
        return _format_loc(loc), "is nested too deeply"
    return _format_loc(loc), error["msg"]


def _error_path(exc: ValidationError, prefix: str) -> tuple[tuple[str | int, ...], str]:
    """(key path under ``prefix``, message) of the first error of a nested table's validation."""
    errors = sorted(exc.errors(), key=lambda e: 0 if e["type"] == "extra_forbidden" else 1)
    first = errors[0]
    _, message = _describe(first)
    path: tuple[str | int, ...] = (prefix, *first["loc"])
    inner = (first.get("ctx") or {}).get("error")
    if first["type"] == "value_error" and isinstance(inner, _KeyedError):
        path += inner.key if isinstance(inner.key, tuple) else (inner.key,)
    return path, message


def first_validation_error(exc: ValidationError) -> tuple[str, str]:
    """(key path, message) of the error a user should see first in a pydantic failure."""
    errors = exc.errors()
    # A union of an angle and "random" reports both branches; report the most specific one.
    # A misspelt key also makes the right one "missing": report the misspelling first.
    rank = {"extra_forbidden": 0}
    errors.sort(key=lambda e: rank.get(e["type"], 1))
    return _describe(errors[0])


def _field_kind(table: str, name: str) -> str | None:
    """Unit kind (:data:`runout.base.units.KINDS`) of a case key, None when it is not a quantity."""
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
