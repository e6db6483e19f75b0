"""Bearing, material and operating-condition descriptions (SI, frozen dataclasses).

Geometry follows Harris, *Rolling Bearing Analysis*: the pitch diameter ``d_m`` is the mean of
the raceway (groove-bottom) diameters, and the radial clearance ``P_d`` is the diametral play
(ISO radial internal clearance), so that ``d_o - d_i - 2 D = P_d`` for a ball bearing.

Symbols used by the five source papers map onto these names as follows.

============================  =========  =========  =========  ==========  ==========
quantity                      seed 000   seed 001   seed 002   seed 003    seed 004
============================  =========  =========  =========  ==========  ==========
``elements``                  Z          Z          Z          N_b         Z
``element_diameter`` [m]      2 r_b      d          d_b, 2r_b  d_b, 2r_b   D_w
``pitch_diameter`` [m]        —          D          d_c, 2r_c  d_m, 2r_m   (d_i+d_e)/2
``inner_conformity``          —          f_i        —          r_gi / d_b  —
``radial_clearance`` [m]      —          P_d        —          γ (see §)   d_e-d_i-2D_w
``contact_angle`` [rad]       α          α          α          α_p         0
============================  =========  =========  =========  ==========  ==========

§ seed 003 calls γ the "internal radial clearance" and makes the contact close when the radial
approach exceeds γ; we read that γ as the radial play P_d / 2 (the dynamic model documents it).
"""

from __future__ import annotations

import functools
import inspect
import math
import numbers
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal, TypeVar

import numpy as np

from runout.base.errors import GeometryError
from runout.geometry._harmonics import MAX_ELEMENTS
from runout.geometry.life import MAX_DYNAMIC_LOAD_RATING

__all__ = ["BallBearing", "Bearing", "Material", "Operation", "RollerBearing"]

RingName = Literal["inner", "outer"]
PreloadKind = Literal["spring", "position"]

#: Largest ring speed read [Hz] (6e7 rpm, a hundred times the fastest bearings): far beyond it
#: the centrifugal and unbalance forces overflow (1e300 rpm did in the dynamic model).
MAX_SPEED = 1e6

_T = TypeVar("_T")


def _deprecated_names(renamed: dict[str, str]) -> Callable[[type[_T]], type[_T]]:
    """Accept a class's former argument and attribute names for one release, with a warning.

    The names of :class:`BallBearing`, :class:`RollerBearing` and :class:`Operation` equal the
    case-file keys (``elements``, ``element_diameter``, ``radial_load_direction``, ...); the
    names of runout 0.1 (``n_elements``, ``ball_diameter``, ``roller_diameter``,
    ``radial_load_angle``, ``moment_load_angle``) still work as keyword arguments and
    attributes and raise a :class:`DeprecationWarning` naming the new one.
    """

    def decorate(cls: type[_T]) -> type[_T]:
        init = cls.__init__

        @functools.wraps(init)
        def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
            for old, new in renamed.items():
                if old in kwargs:
                    if new in kwargs:
                        raise TypeError(f"{cls.__name__}() got both {new}= and its old name {old}=")
                    warnings.warn(
                        f"{cls.__name__}({old}=...) is deprecated: write {new}= (the case-file "
                        "key); the old name goes in the next release",
                        DeprecationWarning,
                        stacklevel=2,
                    )
                    kwargs[new] = kwargs.pop(old)
            init(self, *args, **kwargs)

        cls.__init__ = __init__  # type: ignore[method-assign]
        for old, new in renamed.items():

            def getter(self: Any, _old: str = old, _new: str = new) -> Any:
                warnings.warn(
                    f"{type(self).__name__}.{_old} is deprecated: read .{_new} (the case-file "
                    "key); the old name goes in the next release",
                    DeprecationWarning,
                    stacklevel=2,
                )
                return getattr(self, _new)

            setattr(cls, old, property(getter, doc=f"Deprecated name of :attr:`{new}`."))
        return cls

    return decorate


def _alternative_inputs(cls: type[_T]) -> type[_T]:
    """Accept a ball bearing's alternative case-file keys as keyword arguments.

    As in a ``[bearing]`` table, ``inner_groove_radius`` / ``outer_groove_radius`` [m] may be
    given instead of the conformities (f = r / D) and ``nominal_contact_angle`` [rad], the
    free (catalogue) contact angle α⁰, instead of the clearance: P_d = 2A(1 - cos α⁰),
    A = (f_i + f_o - 1) D (Harris, *Rolling Bearing Analysis*). Giving both a key and its
    alternative is refused, as the case file refuses it (a clearance that agrees with the
    angle to 0.1 % is accepted, as there).
    """
    init = cls.__init__
    signature = inspect.signature(init)

    @functools.wraps(init)
    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        alternatives = {
            key: kwargs.pop(key)
            for key in ("inner_groove_radius", "outer_groove_radius", "nominal_contact_angle")
            if key in kwargs
        }
        if not alternatives:
            init(self, *args, **kwargs)
            return
        bound = signature.bind_partial(self, *args, **kwargs)
        given = dict(bound.arguments)
        given.pop("self", None)
        diameter = given.get("element_diameter", given.get("ball_diameter"))
        if diameter is not None:
            _positive("element_diameter", diameter)
        for side in ("inner", "outer"):
            key = f"{side}_groove_radius"
            if key not in alternatives:
                continue
            if f"{side}_conformity" in given:
                raise GeometryError(key, f"give {side}_conformity or {key}, not both")
            radius = alternatives[key]
            _positive(key, radius)
            if diameter is None:
                raise GeometryError(key, "needs element_diameter to give the conformity r / D")
            given[f"{side}_conformity"] = radius / diameter
        if "nominal_contact_angle" in alternatives:
            value = alternatives["nominal_contact_angle"]
            if isinstance(value, bool) or not isinstance(value, numbers.Real):
                raise GeometryError(
                    "nominal_contact_angle", f"must be a number [rad], got {value!r}"
                )
            alpha0 = float(value)
            if not 0.0 <= alpha0 < 0.5 * math.pi:
                raise GeometryError(
                    "nominal_contact_angle",
                    f"must lie in [0, 90) deg, got {math.degrees(alpha0):.6g} deg",
                )
            if diameter is None:
                raise GeometryError(
                    "nominal_contact_angle", "needs element_diameter to give the clearance"
                )
            f_i = given.get("inner_conformity", signature.parameters["inner_conformity"].default)
            f_o = given.get("outer_conformity", signature.parameters["outer_conformity"].default)
            clearance = 2.0 * (f_i + f_o - 1.0) * diameter * (1.0 - math.cos(alpha0))
            stated = given.get("radial_clearance")
            if stated is not None and abs(stated - clearance) > max(1e-9, 1e-3 * clearance):
                raise GeometryError(
                    "radial_clearance",
                    f"{stated * 1e6:.6g} um disagrees with nominal_contact_angle = "
                    f"{math.degrees(alpha0):.6g} deg, which sets P_d = 2A(1 - cos a0) = "
                    f"{clearance * 1e6:.6g} um; give one of the two",
                )
            given["radial_clearance"] = clearance
        init(self, **given)

    cls.__init__ = __init__  # type: ignore[method-assign]
    return cls


def _check_elements(bearing: Any) -> None:
    """``bearing.elements`` an integer >= 3 (numpy integers too, stored as ``int``)."""
    z = bearing.elements
    if isinstance(z, np.ndarray) and z.ndim == 0:  # a 0-d array is the number it holds
        z = z[()]
    if isinstance(z, bool | np.bool_) or not isinstance(z, numbers.Integral):
        raise GeometryError("elements", f"must be an integer, got {z!r}")
    count = int(z)
    object.__setattr__(bearing, "elements", count)
    if count < 3:
        raise GeometryError("elements", f"must be an integer >= 3, got {count}")
    if count > MAX_ELEMENTS:  # as the case file's bearing.elements (case.limits.MAX_ELEMENTS)
        raise GeometryError(
            "elements",
            f"must be at most {MAX_ELEMENTS} (the largest slewing bearings have a few "
            f"hundred), got {count}",
        )


def _as_real(name: str, value: Any) -> Any:
    """``value`` as a Python float when it is a real number of any kind; complex refused.

    NumPy scalars (``np.float32(1e-3)``, ``np.int64(8)``) and 0-d arrays are the numbers a
    computation hands over and are taken as Python numbers are. A complex value is refused,
    naming ``name``: casting it would silently drop its imaginary part. Anything else (None,
    bool, a string) is returned unchanged for the caller's own check.
    """
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, bool | np.bool_ | str) or value is None:
        return value
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, numbers.Complex):
        raise GeometryError(
            name, f"must be a real number, got the complex {value!r} (never cast to real)"
        )
    return value


def _real_fields(obj: Any, names: tuple[str, ...], prefix: str = "") -> None:
    """Store ``obj``'s numeric fields ``names`` as Python floats (:func:`_as_real`)."""
    for name in names:
        object.__setattr__(obj, name, _as_real(prefix + name, getattr(obj, name)))


def _positive(name: str, value: float) -> None:
    value = _as_real(name, value)
    if not (isinstance(value, int | float) and math.isfinite(value) and value > 0.0):
        raise GeometryError(name, f"must be a positive finite number, got {value!r}")


@dataclass(frozen=True)
class Material:
    """Elastic and inertial properties of the rings and the rolling elements.

    Parameters
    ----------
    youngs_modulus : float
        Young's modulus E [Pa]. Default 208 GPa (bearing steel, seed 000 Table 1).
    poisson_ratio : float
        Poisson's ratio ν [-]. Default 0.3.
    density : float
        Density ρ [kg/m^3]. Default 7850.
    """

    youngs_modulus: float = 208e9
    poisson_ratio: float = 0.3
    density: float = 7850.0

    def __post_init__(self) -> None:
        _real_fields(self, ("youngs_modulus", "poisson_ratio", "density"), "material.")
        _positive("material.youngs_modulus", self.youngs_modulus)
        _positive("material.density", self.density)
        if not (-1.0 < self.poisson_ratio < 0.5):
            raise GeometryError(
                "material.poisson_ratio", f"must lie in (-1, 0.5), got {self.poisson_ratio!r}"
            )

    @property
    def effective_modulus(self) -> float:
        """Harris's E' = 2 / ((1-ν₁²)/E₁ + (1-ν₂²)/E₂) for two bodies of this material [Pa]."""
        return self.youngs_modulus / (1.0 - self.poisson_ratio**2)


@_alternative_inputs
@_deprecated_names({"n_elements": "elements", "ball_diameter": "element_diameter"})
@dataclass(frozen=True)
class BallBearing:
    """A deep-groove or angular-contact ball bearing.

    Parameters
    ----------
    elements : int
        Number of balls Z (>= 3).
    element_diameter : float
        Ball diameter D [m].
    pitch_diameter : float
        Pitch diameter d_m [m], mean of the groove-bottom diameters.
    inner_conformity : float
        Inner groove radius over ball diameter, f_i = r_i / D (> 0.5).
    outer_conformity : float
        Outer groove radius over ball diameter, f_o = r_o / D (> 0.5).
    radial_clearance : float
        ISO radial internal clearance = Harris's diametral play P_d [m] (>= 0).
    contact_angle : float or None
        Fixed contact angle [rad]. ``None`` derives it from the clearance (free contact angle)
        or from clearance and axial load (see :mod:`runout.geometry.loading`).
    material : Material
        Material of rings and balls.
    dynamic_load_rating : float or None
        Basic dynamic load rating C [N] (catalogue, ISO 281); with it the equilibrium model
        reports the ISO/TS 16281 reference rating life (:mod:`runout.geometry.life`).

    Notes
    -----
    As in a case file's ``[bearing]`` table, keyword arguments ``inner_groove_radius`` and
    ``outer_groove_radius`` [m] may replace the conformities and ``nominal_contact_angle``
    [rad], the free (catalogue) contact angle α⁰, may replace the clearance:
    P_d = 2A(1 - cos α⁰), A = (f_i + f_o - 1) D (Harris). The bearing stores the conformities
    and the clearance; the same names read back as properties.
    """

    elements: int
    element_diameter: float
    pitch_diameter: float
    inner_conformity: float = 0.52
    outer_conformity: float = 0.53
    radial_clearance: float = 0.0
    contact_angle: float | None = None
    material: Material = field(default_factory=Material)
    dynamic_load_rating: float | None = None

    kind = "ball"

    if TYPE_CHECKING:  # the signature `_alternative_inputs` gives at run time, for type checkers

        def __init__(
            self,
            elements: int,
            element_diameter: float,
            pitch_diameter: float,
            inner_conformity: float = 0.52,
            outer_conformity: float = 0.53,
            radial_clearance: float = 0.0,
            contact_angle: float | None = None,
            material: Material = ...,
            dynamic_load_rating: float | None = None,
            *,
            inner_groove_radius: float = ...,
            outer_groove_radius: float = ...,
            nominal_contact_angle: float = ...,
        ) -> None: ...

    def __post_init__(self) -> None:
        _check_elements(self)
        _real_fields(
            self,
            (
                "element_diameter",
                "pitch_diameter",
                "inner_conformity",
                "outer_conformity",
                "radial_clearance",
                "contact_angle",
                "dynamic_load_rating",
            ),
        )
        _positive("element_diameter", self.element_diameter)
        _positive("pitch_diameter", self.pitch_diameter)
        if self.dynamic_load_rating is not None:
            _positive("dynamic_load_rating", self.dynamic_load_rating)
            if self.dynamic_load_rating > MAX_DYNAMIC_LOAD_RATING:
                raise GeometryError(
                    "dynamic_load_rating",
                    f"must be at most {MAX_DYNAMIC_LOAD_RATING:.0e} N (the largest slewing "
                    f"bearings are rated at a few tens of MN), got {self.dynamic_load_rating!r}",
                )
        if self.element_diameter >= self.pitch_diameter:
            raise GeometryError(
                "element_diameter",
                f"{self.element_diameter * 1e3:.6g} mm is not smaller than the pitch diameter "
                f"{self.pitch_diameter * 1e3:.6g} mm",
            )
        chord = self.pitch_diameter * math.sin(math.pi / self.elements)
        if self.element_diameter >= chord:
            raise GeometryError(
                "elements",
                f"{self.elements} balls of {self.element_diameter * 1e3:.6g} mm overlap on a "
                f"{self.pitch_diameter * 1e3:.6g} mm pitch circle (centre spacing "
                f"{chord * 1e3:.6g} mm); at most "
                f"{_max_elements(self.element_diameter, self.pitch_diameter)} fit",
            )
        for name in ("inner_conformity", "outer_conformity"):
            value = getattr(self, name)
            if not (isinstance(value, int | float) and math.isfinite(value) and value > 0.5):
                raise GeometryError(
                    name,
                    f"must be > 0.5 (groove radius larger than the ball radius), got {value!r}",
                )
        if not (math.isfinite(self.radial_clearance) and self.radial_clearance >= 0.0):
            raise GeometryError(
                "radial_clearance",
                f"must be >= 0 (no negative clearance), got {self.radial_clearance!r}",
            )
        if self.radial_clearance >= 2.0 * self.curvature_distance:
            raise GeometryError(
                "radial_clearance",
                f"{self.radial_clearance * 1e6:.6g} um exceeds twice the groove-centre distance "
                f"A = {self.curvature_distance * 1e6:.6g} um: the balls would leave the grooves",
            )
        if self.contact_angle is not None and not (0.0 <= self.contact_angle < math.pi / 2):
            raise GeometryError(
                "contact_angle",
                f"must lie in [0, 90) deg, got {math.degrees(self.contact_angle):.6g} deg",
            )

    # --- derived geometry -------------------------------------------------------------
    @property
    def inner_groove_radius(self) -> float:
        """r_i = f_i D [m]."""
        return self.inner_conformity * self.element_diameter

    @property
    def outer_groove_radius(self) -> float:
        """r_o = f_o D [m]."""
        return self.outer_conformity * self.element_diameter

    @property
    def total_curvature(self) -> float:
        """Harris's total conformity ratio B = f_i + f_o - 1 [-] (seed 003 eq. 2.22: A / d_b)."""
        return self.inner_conformity + self.outer_conformity - 1.0

    @property
    def curvature_distance(self) -> float:
        """A = r_i + r_o - D between the groove curvature centres [m] (seed 003 eq. 2.22)."""
        return self.total_curvature * self.element_diameter

    @property
    def inner_raceway_diameter(self) -> float:
        """Groove-bottom diameter of the inner raceway d_i = d_m - D - P_d/2 [m]."""
        return self.pitch_diameter - self.element_diameter - 0.5 * self.radial_clearance

    @property
    def outer_raceway_diameter(self) -> float:
        """Groove-bottom diameter of the outer raceway d_o = d_m + D + P_d/2 [m]."""
        return self.pitch_diameter + self.element_diameter + 0.5 * self.radial_clearance

    @property
    def free_contact_angle(self) -> float:
        """α⁰ = arccos(1 - P_d / (2A)) [rad] (Harris, free contact angle)."""
        return math.acos(1.0 - self.radial_clearance / (2.0 * self.curvature_distance))

    @property
    def free_end_play(self) -> float:
        """Axial play P_e = 2 A sin α⁰ [m] (Harris)."""
        return 2.0 * self.curvature_distance * math.sin(self.free_contact_angle)

    @property
    def nominal_contact_angle(self) -> float:
        """Nominal (free, catalogue) contact angle α⁰ [rad]: the case key of that name.

        The angle of the unloaded bearing pushed axially, set by the clearance (equal to
        :attr:`free_contact_angle`); a fixed ``contact_angle`` does not change it.
        """
        return self.free_contact_angle

    @property
    def unloaded_contact_angle(self) -> float:
        """The fixed contact angle when given, else the free contact angle α⁰ [rad].

        The angle the kinematics and the contact formulas take when no other is given.
        """
        return self.free_contact_angle if self.contact_angle is None else self.contact_angle


def _max_elements(diameter: float, pitch_diameter: float) -> int:
    """Largest number of elements of this diameter that fit on the pitch circle."""
    return math.floor(math.pi / math.asin(min(1.0, diameter / pitch_diameter)) - 1e-12)


@_deprecated_names({"n_elements": "elements", "roller_diameter": "element_diameter"})
@dataclass(frozen=True)
class RollerBearing:
    """A cylindrical roller bearing (line contact, contact angle 0).

    Parameters
    ----------
    elements : int
        Number of rollers Z (>= 3).
    element_diameter : float
        Roller diameter D_w [m].
    inner_raceway_diameter : float
        Inner raceway diameter d_i [m].
    outer_raceway_diameter : float
        Outer raceway diameter d_e [m].
    roller_length : float or None
        Effective roller length l [m]; needed only for line-contact stiffness.
    material : Material
        Material of rings and rollers.
    """

    elements: int
    element_diameter: float
    inner_raceway_diameter: float
    outer_raceway_diameter: float
    roller_length: float | None = None
    material: Material = field(default_factory=Material)

    kind = "cylindrical_roller"
    contact_angle = 0.0

    def __post_init__(self) -> None:
        _check_elements(self)
        _real_fields(
            self,
            (
                "element_diameter",
                "inner_raceway_diameter",
                "outer_raceway_diameter",
                "roller_length",
            ),
        )
        _positive("element_diameter", self.element_diameter)
        _positive("inner_raceway_diameter", self.inner_raceway_diameter)
        _positive("outer_raceway_diameter", self.outer_raceway_diameter)
        if self.roller_length is not None:
            _positive("roller_length", self.roller_length)
        if self.radial_clearance < 0.0:
            raise GeometryError(
                "outer_raceway_diameter",
                f"d_e - d_i - 2 D_w = {self.radial_clearance * 1e6:.6g} um: negative clearance "
                "(rollers do not fit between the raceways)",
            )
        chord = self.pitch_diameter * math.sin(math.pi / self.elements)
        if self.element_diameter >= chord:
            raise GeometryError(
                "elements",
                f"{self.elements} rollers of {self.element_diameter * 1e3:.6g} mm overlap on a "
                f"{self.pitch_diameter * 1e3:.6g} mm pitch circle; at most "
                f"{_max_elements(self.element_diameter, self.pitch_diameter)} fit",
            )

    @property
    def pitch_diameter(self) -> float:
        """d_m = (d_i + d_e) / 2 [m]."""
        return 0.5 * (self.inner_raceway_diameter + self.outer_raceway_diameter)

    @property
    def radial_clearance(self) -> float:
        """Diametral play P_d = d_e - d_i - 2 D_w [m]."""
        return (
            self.outer_raceway_diameter - self.inner_raceway_diameter - 2.0 * self.element_diameter
        )

    @property
    def nominal_contact_angle(self) -> float:
        """Always 0 for a cylindrical roller bearing [rad]."""
        return 0.0

    @property
    def unloaded_contact_angle(self) -> float:
        """Always 0 for a cylindrical roller bearing [rad]."""
        return 0.0


Bearing = BallBearing | RollerBearing


@_deprecated_names(
    {"radial_load_angle": "radial_load_direction", "moment_load_angle": "moment_load_direction"}
)
@dataclass(frozen=True)
class Operation:
    """How the bearing runs and what loads it.

    Parameters
    ----------
    rotating_ring : {"inner", "outer"}
        The ring whose revolutions define orders (waves per revolution).
    speed : float
        Rotation frequency of the rotating ring [Hz] (revolutions per second).
    other_ring_speed : float
        Rotation frequency of the other ring [Hz], signed relative to ``speed``; 0 for the
        usual case of one stationary ring.
    axial_load : float
        Axial load on the shaft along +z [N] (>= 0); with ``preload`` the preload force.
    preload : {"spring", "position"}
        What holds the rings axially: ``"spring"`` a constant axial force (the
        constant-pressure preload of Tada 2002, seed 000, and Kim et al., seed 001), the shaft
        free to move axially under the other loads; ``"position"`` the rings held at the axial
        offset ``axial_load`` sets alone (perfect bearing, no radial load).
    radial_load : float
        Radial load magnitude [N] (>= 0).
    radial_load_direction : float
        Direction of the radial load, counter-clockwise from +x [rad]. Default -π/2 (along -y).
    moment_load : float
        Magnitude of a tilting moment on the inner ring [N m] (>= 0); only the
        ``equilibrium`` model uses it.
    moment_load_direction : float
        Direction of the moment vector in the x-y plane, counter-clockwise from +x [rad].
    """

    rotating_ring: RingName = "inner"
    speed: float = 0.0
    other_ring_speed: float = 0.0
    axial_load: float = 0.0
    preload: PreloadKind = "spring"
    radial_load: float = 0.0
    radial_load_direction: float = -math.pi / 2
    moment_load: float = 0.0
    moment_load_direction: float = 0.0

    def __post_init__(self) -> None:
        if self.rotating_ring not in ("inner", "outer"):
            raise GeometryError(
                "operation.rotating_ring", f'must be "inner" or "outer", got {self.rotating_ring!r}'
            )
        if self.preload not in ("spring", "position"):
            raise GeometryError(
                "operation.preload", f'must be "spring" or "position", got {self.preload!r}'
            )
        units = {
            "speed": "Hz, revolutions per second",
            "other_ring_speed": "Hz, revolutions per second",
            "radial_load_direction": "rad",
            "moment_load_direction": "rad",
            "axial_load": "N",
            "radial_load": "N",
            "moment_load": "N m",
        }
        _real_fields(self, tuple(units), "operation.")
        for name, unit in units.items():
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise GeometryError(
                    f"operation.{name}",
                    f"must be a number in SI units [{unit}], got {value!r} (a string with a "
                    "unit is read in case files and by runout.load_case, not here)",
                )
        for name in ("speed", "other_ring_speed", "radial_load_direction", "moment_load_direction"):
            if not math.isfinite(getattr(self, name)):
                raise GeometryError(f"operation.{name}", "must be finite")
        for name in ("speed", "other_ring_speed"):
            value = getattr(self, name)
            if abs(value) > MAX_SPEED:  # squared into centrifugal and unbalance forces
                raise GeometryError(
                    f"operation.{name}",
                    f"{value * 60:.4g} rpm is beyond any rolling bearing (at most "
                    f"{MAX_SPEED * 60:.0e} rpm)",
                )
        for name in ("axial_load", "radial_load", "moment_load"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0.0):
                raise GeometryError(f"operation.{name}", f"must be >= 0, got {value!r}")

    @property
    def inner_speed(self) -> float:
        """Rotation frequency of the inner ring [Hz]."""
        return self.speed if self.rotating_ring == "inner" else self.other_ring_speed

    @property
    def outer_speed(self) -> float:
        """Rotation frequency of the outer ring [Hz]."""
        return self.speed if self.rotating_ring == "outer" else self.other_ring_speed
