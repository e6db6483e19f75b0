"""The bearings of the source papers as typed inputs, ready to run or to vary.

Each ``*_bearing`` function returns the :class:`runout.BallBearing` or
:class:`runout.RollerBearing` of one paper, and each case function (:func:`tada`, :func:`kim`,
:func:`anderon_608`, :func:`purohit`, :func:`nu209`) returns an :class:`Example`: that bearing
with the paper's operating point, imperfections and analysis. With their defaults they equal the
example case files ``examples/seed000_tada_fig7.toml``, ``seed001_kim_spindle.toml``,
``seed002_608.toml``, ``seed003_purohit.toml`` and ``seed004_nu209.toml`` number for number
(``runout run`` on the file and :meth:`Example.run` print the same results); keyword arguments
change what studies and tests vary (number of elements, clearance, loads, speed).

Lengths, loads and speeds are SI numbers (m, N, Hz) or strings with units (``"10 um"``,
``"5400 rpm"``) read as a case file reads them, so that a default such as ``"10 um"`` is the
very number the case file gives.

The papers (full references in the documentation's list of sources):

- seed 000: S. Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
  bearings", Koyo Engineering Journal 161E, 2002, Table 1 and Fig. 7;
- seed 001: Y.-C. Kim, S.-K. Choi, K.-C. Yoon, "Vibration analysis of ball bearings with ball
  geometric imperfections" (KIMM / FAG Hanwha, no year printed), Tables 1, 2 and 4;
- seed 002: "Anderon vibration" (an instrument maker's calculation model, no author or year
  printed), Tab. 1 and eq. 43-47;
- seed 003: R.K. Purohit, K. Purohit, "Dynamic analysis of ball bearings with effect of preload
  and number of balls", International Journal of Applied Mechanics and Engineering 11(1), 2006,
  Table 2 and Fig. 3;
- seed 004: Y. Yu, G. Chen, J. Li, Y. Xue, B. Pang, "Prediction method for the radial runout of
  inner ring in cylindrical roller bearings", Mathematical Problems in Engineering 2017,
  Table 1 and Fig. 9.

Examples
--------
>>> from runout import examples
>>> result = examples.kim(elements=12).run(revolutions=4, samples=1024)
>>> case = examples.tada(radial_clearance="5 um").case()
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from runout.api import Imperfections, build_case
from runout.base.units import to_si
from runout.geometry.bearing import BallBearing, Material, Operation, RollerBearing

if TYPE_CHECKING:
    from runout.analysis.results import RunResult
    from runout.case.model import Case

__all__ = [
    "Example",
    "anderon_608",
    "bearing_608",
    "kim",
    "kim_bearing",
    "nu209",
    "nu209_bearing",
    "purohit",
    "purohit_bearing",
    "tada",
    "tada_bearing",
]

#: A number in SI units or a string with its unit (``"10 um"``), as in a case file.
Quantity = float | str


def _si(value: Quantity, kind: str) -> float:
    # through the case file's parser: "10 um" is 9.999999999999999e-06 there, not 1e-05
    return to_si(value, kind)


@dataclass(frozen=True)
class Example:
    """A bearing of a source paper with its operating point, imperfections and analysis.

    Attributes
    ----------
    title : str
        Shown in outputs (the example case file's title).
    bearing : BallBearing or RollerBearing
        Geometry and material.
    operation : Operation
        Speeds and loads.
    imperfections : runout.api.Imperfections or None
        The builder of the imperfection tables; None for a perfect bearing.
    analysis : mapping
        The ``[analysis]`` keys (``model``, ``revolutions``, ``samples``, ...), by their
        case-file names.
    dynamics : mapping or None
        The ``[dynamics]`` keys (``mass``, ``damping``, ...) of the ``dynamic`` model.

    Notes
    -----
    ``dataclasses.replace(example, imperfections=None)`` gives the same example with perfect
    parts; :meth:`with_analysis` changes analysis keys.
    """

    title: str
    bearing: BallBearing | RollerBearing
    operation: Operation
    imperfections: Imperfections | None = None
    analysis: Mapping[str, Any] = field(default_factory=dict)
    dynamics: Mapping[str, Any] | None = None

    def __post_init__(self) -> None:
        # read-only copies: an example shared between tests cannot be changed by one of them
        object.__setattr__(self, "analysis", MappingProxyType(dict(self.analysis)))
        if self.dynamics is not None:
            object.__setattr__(self, "dynamics", MappingProxyType(dict(self.dynamics)))

    def with_analysis(self, **keys: Any) -> Example:
        """The same example with these ``[analysis]`` keys changed (e.g. ``samples=1024``).

        Parameters
        ----------
        **keys
            ``[analysis]`` keys, by their case-file names, that replace or add to the
            example's (``model``, ``revolutions``, ``samples``, ...).

        Returns
        -------
        Example
            A new example; this one is unchanged.
        """
        return dataclasses.replace(self, analysis={**self.analysis, **keys})

    def case(self, **analysis: Any) -> Case:
        """The validated case (:meth:`runout.case.model.Case.from_inputs`), checked as a file is.

        Parameters
        ----------
        **analysis
            ``[analysis]`` keys that replace the example's (``model``, ``revolutions``, ...).

        Returns
        -------
        runout.case.model.Case
            The validated case, as a case file of the same content would give it.
        """
        return build_case(
            self.bearing,
            self.operation,
            self.imperfections,
            title=self.title,
            analysis={**self.analysis, **analysis},
            dynamics=self.dynamics,
        )

    def run(self, **options: Any) -> RunResult:
        """Run the example (:func:`runout.run`), as ``runout run`` runs its case file.

        Parameters
        ----------
        **options
            ``[analysis]`` keys (``model``, ``revolutions``, ``samples``, ...) and
            ``[dynamics]`` keys that replace the example's.

        Returns
        -------
        runout.analysis.results.RunResult
            The result of the example's model.
        """
        from runout.api import run

        merged = {**self.analysis, **(self.dynamics or {}), **options}
        model = merged.pop("model")
        return run(
            model,
            bearing=self.bearing,
            operation=self.operation,
            imperfections=self.imperfections,
            title=self.title,
            **merged,
        )


# --------------------------------------------------------------------------------------------
# seed 000: Tada's standard HDD spindle bearing
# --------------------------------------------------------------------------------------------
def tada_bearing(
    *,
    elements: int = 8,
    radial_clearance: Quantity = "10 um",
    contact_angle: Quantity | None = None,
) -> BallBearing:
    """The standard HDD spindle bearing of seed 000 (Tada 2002, Table 1).

    Eight 1 mm balls on a 7 mm pitch circle, steel of 208 GPa and ν = 0.3. The paper gives no
    groove conformities: f_i = 0.52 and f_o = 0.53 are assumed.

    Parameters
    ----------
    elements : int
        Number of balls Z [-].
    radial_clearance : float or str
        Diametral play P_d [m] (default 10 um).
    contact_angle : float or str, optional
        Fixed contact angle [rad]; default free (set by clearance and preload).

    Returns
    -------
    BallBearing
        The bearing of Table 1 with these changes.
    """
    return BallBearing(
        elements=elements,
        element_diameter=_si("1 mm", "length"),
        pitch_diameter=_si("7 mm", "length"),
        inner_conformity=0.52,
        outer_conformity=0.53,
        radial_clearance=_si(radial_clearance, "length"),
        contact_angle=None if contact_angle is None else _si(contact_angle, "angle"),
        material=Material(youngs_modulus=_si("208 GPa", "pressure"), poisson_ratio=0.3),
    )


def tada(
    *,
    elements: int = 8,
    radial_clearance: Quantity = "10 um",
    speed: Quantity = "5400 rpm",
    axial_load: Quantity = "20 N",
    peak_to_peak: Quantity = "20 nm",
) -> Example:
    """Tada's bearing with the waviness of Fig. 7 (``examples/seed000_tada_fig7.toml``).

    The outer ring turns at 5400 rpm under a 20 N constant-pressure preload; both rings carry
    Z - 1, Z and Z + 1 lobes (7, 8 and 9 for the default Z = 8) of 20 nm peak to peak, as the
    paper gives them. Model ``quasi_static_3d``, 72 revolutions (0.8 s at 5400 rpm), 4096
    samples.

    Parameters
    ----------
    elements : int
        Number of balls Z [-]; the lobe numbers follow it.
    radial_clearance : float or str
        Diametral play P_d [m].
    speed : float or str
        Outer-ring speed [Hz].
    axial_load : float or str
        Preload [N].
    peak_to_peak : float or str
        Peak-to-peak height of each waviness [m].

    Returns
    -------
    Example
        The case of ``examples/seed000_tada_fig7.toml`` with these changes.
    """
    waves = Imperfections(elements=elements)
    for part in ("inner", "outer"):
        for order in (elements - 1, elements, elements + 1):
            waves = waves.waviness(part, order, peak_to_peak=peak_to_peak)
    return Example(
        title="Tada standard model (seed 000 Table 1), Fig. 7 wavinesses",
        bearing=tada_bearing(elements=elements, radial_clearance=radial_clearance),
        operation=Operation(
            rotating_ring="outer",
            speed=_si(speed, "speed"),
            axial_load=_si(axial_load, "force"),
        ),
        imperfections=waves,
        analysis={"model": "quasi_static_3d", "revolutions": 72, "samples": 4096},
    )


# --------------------------------------------------------------------------------------------
# seed 001: Kim's HDD spindle-motor bearing
# --------------------------------------------------------------------------------------------
def kim_bearing(*, elements: int = 10, radial_clearance: Quantity = "5 um") -> BallBearing:
    """The HDD spindle-motor bearing of seed 001 (Kim, Choi, Yoon, Table 1).

    Balls of 1.5875 mm on a 9.1 mm pitch circle, conformities 0.529 and 0.535, 5 um clearance.

    Parameters
    ----------
    elements : int
        Number of balls Z [-] (Table 2 varies it).
    radial_clearance : float or str
        Diametral play P_d [m].

    Returns
    -------
    BallBearing
        The bearing of Table 1 with these changes.
    """
    return BallBearing(
        elements=elements,
        element_diameter=_si("1.5875 mm", "length"),
        pitch_diameter=_si("9.1 mm", "length"),
        inner_conformity=0.529,
        outer_conformity=0.535,
        radial_clearance=_si(radial_clearance, "length"),
    )


def kim(
    *,
    elements: int = 10,
    radial_clearance: Quantity = "5 um",
    speed: Quantity = "7200 rpm",
    axial_load: Quantity = "60.68 N",
    radial_load: Quantity = 0.0,
    oversize: Quantity | None = "0.1 um",
) -> Example:
    """Kim's bearing with ball 1 oversize (``examples/seed001_kim_spindle.toml``).

    The inner ring turns at 7200 rpm. The paper does not print the axial preload: 60.68 N is
    the load that reproduces its Table 2 contact angle of 18.73 deg at Z = 10. Ball 1 is
    0.1 um oversize (Table 4, the size part only). Model ``quasi_static_2d``, 20 revolutions,
    4096 samples.

    Parameters
    ----------
    elements : int
        Number of balls Z [-].
    radial_clearance : float or str
        Diametral play P_d [m].
    speed : float or str
        Inner-ring speed [Hz].
    axial_load : float or str
        Axial preload [N].
    radial_load : float or str
        Radial load along -y [N] (none in the paper).
    oversize : float or str or None
        Diameter error of ball 1 [m]; None for perfect balls.

    Returns
    -------
    Example
        The case of ``examples/seed001_kim_spindle.toml`` with these changes.
    """
    errors: list[Quantity] = [0] * elements
    imperfections = None
    title = "Kim spindle bearing (seed 001 Table 1), perfect balls"
    if oversize is not None:
        errors[0] = oversize
        imperfections = Imperfections(elements=elements).diameter_errors(errors)
        size = oversize if isinstance(oversize, str) else f"{oversize * 1e6:.6g} um"
        title = f"Kim spindle bearing (seed 001 Table 1), ball 1 oversize by {size}"
    return Example(
        title=title,
        bearing=kim_bearing(elements=elements, radial_clearance=radial_clearance),
        operation=Operation(
            rotating_ring="inner",
            speed=_si(speed, "speed"),
            axial_load=_si(axial_load, "force"),
            radial_load=_si(radial_load, "force"),
        ),
        imperfections=imperfections,
        analysis={"model": "quasi_static_2d", "revolutions": 20, "samples": 4096},
    )


# --------------------------------------------------------------------------------------------
# seed 002: the 608 of the Anderon model
# --------------------------------------------------------------------------------------------
def bearing_608(*, contact_angle: Quantity | None = "10 deg") -> BallBearing:
    """The 608 deep-groove ball bearing of seed 002 ("Anderon vibration", Tab. 1).

    Seven balls of 3.9688 mm on a 15 mm pitch circle at a 10 deg contact angle. The paper gives
    no conformities: the typical deep-groove 0.52 and 0.53 are assumed.

    Parameters
    ----------
    contact_angle : float or str or None
        Fixed contact angle [rad]; None for the free angle of a bearing without clearance.

    Returns
    -------
    BallBearing
        The 608 of Tab. 1.
    """
    return BallBearing(
        elements=7,
        element_diameter=_si("3.9688 mm", "length"),
        pitch_diameter=_si("15 mm", "length"),
        inner_conformity=0.52,
        outer_conformity=0.53,
        contact_angle=None if contact_angle is None else _si(contact_angle, "angle"),
    )


def anderon_608(*, speed: Quantity = "1800 rpm", axial_load: Quantity = "20 N") -> Example:
    """The 608 with the imperfections of eq. 43-47 (``examples/seed002_608.toml``).

    Inner-ring eccentricity of 2.5 um (eq. 43), an inner-raceway slant of 0.05 um (eq. 44),
    waviness spectra 0.1 um k^-1.5 on the inner raceway (2 <= k < 800, eq. 45), the outer
    raceway (2 <= k < 1360, eq. 46) and ball 1 (2 <= k < 287, eq. 47), with seeded random
    phases, and a 0.1 um size error of ball 1 (B_A0 of Fig. 17; eq. 47 starts at k = 2, the
    value is our reading). Inner ring at the Anderon meter's 1800 rpm under 20 N axial. Model
    ``linear``, 6 revolutions of 4096 samples each.

    Parameters
    ----------
    speed : float or str
        Inner-ring speed [Hz].
    axial_load : float or str
        Axial load [N].

    Returns
    -------
    Example
        The case of ``examples/seed002_608.toml`` with these changes.
    """
    imperfections = (
        Imperfections(elements=7)
        .waviness("inner", 1, amplitude="2.5 um", phase="0 deg")
        .slant(amplitude="0.05 um", phase="0 deg")
        .spectrum("inner", (2, 799), amplitude="0.1 um", exponent=-1.5, phase="random", seed=1)
        .spectrum("outer", (2, 1359), amplitude="0.1 um", exponent=-1.5, phase="random", seed=2)
        .waviness("ball", 0, amplitude="0.1 um", element=1)
        .spectrum(
            "ball", (2, 286), amplitude="0.1 um", exponent=-1.5, phase="random", seed=3, element=1
        )
    )
    return Example(
        title="608 (seed 002 Tab. 1) with the waviness of eq. 43-47",
        bearing=bearing_608(),
        operation=Operation(
            rotating_ring="inner",
            speed=_si(speed, "speed"),
            axial_load=_si(axial_load, "force"),
        ),
        imperfections=imperfections,
        analysis={"model": "linear", "revolutions": 6, "samples": 24576},
    )


# --------------------------------------------------------------------------------------------
# seed 003: Purohit's rotor-bearing system
# --------------------------------------------------------------------------------------------
def purohit_bearing(*, elements: int = 9, radial_clearance: Quantity = "0.2 um") -> BallBearing:
    """The ball bearing of the rotor of seed 003 (Purohit & Purohit 2006, Table 2).

    Balls of 7.96 mm on a 54 mm pitch circle, groove radii 4.08 mm (inner) and 4.61 mm (outer).
    The paper's "internal radial clearance" γ = 0.1 um is the play at which a contact closes,
    half the diametral play: P_d = 0.2 um. Its ring radii (23 mm, 46 mm) do not match its pitch
    radius (27 mm); the ball and pitch sizes are used.

    Parameters
    ----------
    elements : int
        Number of balls Z [-] (the paper varies it).
    radial_clearance : float or str
        Diametral play P_d [m].

    Returns
    -------
    BallBearing
        The bearing of Table 2 with these changes.
    """
    diameter = _si("7.96 mm", "length")
    return BallBearing(
        elements=elements,
        element_diameter=diameter,
        pitch_diameter=_si("54 mm", "length"),
        # the groove radii as conformities f = r / D, as the case file's keys are read
        inner_conformity=_si("4.08 mm", "length") / diameter,
        outer_conformity=_si("4.61 mm", "length") / diameter,
        radial_clearance=_si(radial_clearance, "length"),
    )


def purohit(
    *,
    elements: int = 9,
    radial_clearance: Quantity = "0.2 um",
    speed: Quantity = "5000 rpm",
    radial_load: Quantity = "6 N",
    axial_load: Quantity = "10 N",
    radial_load_direction: Quantity | None = None,
) -> Example:
    """Purohit's rotor-bearing system with the preload of Fig. 3 (``seed003_purohit.toml``).

    A 0.6 kg rotor with 200 N s/m damping; inner ring at 5000 rpm, 6 N radial load along -y
    and 10 N axial preload, a position preload (the paper's rotor moves in x, y only). Model
    ``dynamic``, 50 revolutions, 8192 samples.

    Parameters
    ----------
    elements : int
        Number of balls Z [-].
    radial_clearance : float or str
        Diametral play P_d [m].
    speed : float or str
        Inner-ring speed [Hz].
    radial_load : float or str
        Radial load [N].
    axial_load : float or str
        Axial preload [N].
    radial_load_direction : float or str, optional
        Direction of the radial load from +x [rad]; default -y.

    Returns
    -------
    Example
        The case of ``examples/seed003_purohit.toml`` with these changes.
    """
    direction = {}
    if radial_load_direction is not None:
        direction["radial_load_direction"] = _si(radial_load_direction, "angle")
    return Example(
        title="Purohit rotor-bearing system (seed 003 Table 2)",
        bearing=purohit_bearing(elements=elements, radial_clearance=radial_clearance),
        operation=Operation(
            rotating_ring="inner",
            speed=_si(speed, "speed"),
            radial_load=_si(radial_load, "force"),
            axial_load=_si(axial_load, "force"),
            preload="position",  # seed 003's rotor moves in x, y only
            **direction,
        ),
        analysis={"model": "dynamic", "revolutions": 50, "samples": 8192},
        dynamics={"mass": "0.6 kg", "damping": "200 N*s/m"},
    )


# --------------------------------------------------------------------------------------------
# seed 004: the NU209 of Yu et al.
# --------------------------------------------------------------------------------------------
def nu209_bearing() -> RollerBearing:
    """The NU209 cylindrical roller bearing of seed 004 (Yu et al. 2017, Table 1).

    Fourteen 10 mm rollers between raceways of 54.991 mm and 75.032 mm.

    Returns
    -------
    RollerBearing
        The NU209 of Table 1.
    """
    return RollerBearing(
        elements=14,
        element_diameter=_si("10 mm", "length"),
        inner_raceway_diameter=_si("54.991 mm", "length"),
        outer_raceway_diameter=_si("75.032 mm", "length"),
    )


def nu209(
    *,
    amplitude: Quantity = "1 um",
    order: int = 10,
    speed: Quantity = "1 rpm",
    radial_load: Quantity = "10 N",
) -> Example:
    """The NU209 with the inner-raceway roundness error of Fig. 9 (``seed004_nu209.toml``).

    A 1 um, 10-lobe waviness of the inner raceway; the inner ring turns slowly (1 rpm, as a
    runout measurement does) under a light 10 N measuring load along -y. Model
    ``roller_constraint``, 1.5 revolutions (540 deg), 2161 samples.

    Parameters
    ----------
    amplitude : float or str
        Zero-to-peak amplitude of the inner-raceway waviness [m].
    order : int
        Its number of lobes [-].
    speed : float or str
        Inner-ring speed [Hz].
    radial_load : float or str
        Measuring load [N].

    Returns
    -------
    Example
        The case of ``examples/seed004_nu209.toml`` with these changes.
    """
    size = amplitude if isinstance(amplitude, str) else f"{amplitude * 1e6:.6g} um"
    return Example(
        title=f"NU209 (seed 004 Table 1), inner raceway {size} at {order} lobes (Fig. 9)",
        bearing=nu209_bearing(),
        operation=Operation(
            rotating_ring="inner",
            speed=_si(speed, "speed"),
            radial_load=_si(radial_load, "force"),
        ),
        imperfections=Imperfections(elements=14).waviness("inner", order, amplitude=amplitude),
        analysis={"model": "roller_constraint", "revolutions": 1.5, "samples": 2161},
    )
