"""Typed model-specific parts of a run result, and the ``[analysis]`` outputs added to it.

Each model fills :attr:`runout.analysis.results.RunResult.details` with one of the frozen
dataclasses here (:data:`ModelDetails`); :meth:`to_json` gives the model's own entries of the
JSON contract (keys and order as documented per model in docs/models/) and :meth:`from_json`
reads them back from a ``result.json``. :class:`Iso15242` and :class:`Verdict` are what
:func:`runout.runner.analysis.apply_analysis` adds for ``[analysis] bands = "iso15242"`` and
``[analysis] limit``.

Some details also hold in-memory data of the run that the JSON does not carry (the rigid
model's contact solution, the dynamic model's sample rate): these are excluded from
comparison and JSON, and are None in a result read back from a file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal, Protocol, TypeAlias

import numpy as np
from numpy.typing import NDArray

from runout.geometry.life import RatingLife

if TYPE_CHECKING:
    from runout.analysis.lines import Runout


class RollerSolution(Protocol):
    """What a result carries of the rigid model's contact solution (the model's ``Solution``,
    :mod:`runout.models.roller_constraint`, defined above this layer): the stable position at
    every rotation angle, which the run's files and figures read."""

    @property
    def alpha(self) -> NDArray[np.float64]:
        """Rotation angles of the turning ring [rad], shape (n,)."""
        ...

    @property
    def centre(self) -> NDArray[np.float64]:
        """Centre of the loaded ring relative to the fixed ring's [m], shape (n, 2)."""
        ...

    @property
    def pair(self) -> NDArray[np.int64]:
        """The two rollers (0-based) whose contacts hold the ring, shape (n, 2)."""
        ...

    @property
    def multipliers(self) -> NDArray[np.float64]:
        """Their contact forces per unit measuring load [-], shape (n, 2)."""
        ...

    @property
    def gaps(self) -> NDArray[np.float64]:
        """Gap of every roller at the stable position [m], shape (n, Z)."""
        ...


__all__ = [
    "DETAILS_BY_MODEL",
    "DynamicDetails",
    "EquilibriumDetails",
    "HeldRollers",
    "Iso492",
    "Iso15242",
    "Iso15242Band",
    "LinearDetails",
    "ModelDetails",
    "QuasiStaticDetails",
    "RadialStiffness",
    "RingDisplacement",
    "RollerDetails",
    "SpindleBearingResult",
    "SpindleDetails",
    "StiffnessMatrix",
    "Verdict",
    "details_from_json",
    "tool_point_stiffness",
]

#: One row of a table of the JSON contract (attribution rows, the per-ball table).
Row: TypeAlias = dict[str, Any]


# --------------------------------------------------------------------------------------------
# linear model (seed 002)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LinearDetails:
    """What the linear model adds to its result.

    Attributes
    ----------
    attribution : tuple of dict
        Frequency attribution table of the bearing
        (:func:`runout.geometry.attribution.attribution_rows`: part, factor, lobes, formula,
        order [-], frequency_hz [Hz]).
    linear_variant : {"radial_spring", "force_balance"}
        Contact model of the closed form.
    explained_fraction : float
        Share of the record's x, y variance the listed lines explain [-].
    """

    attribution: tuple[Row, ...]
    linear_variant: str
    explained_fraction: float

    def to_json(self) -> dict[str, Any]:
        """The linear model's JSON entries.

        Returns
        -------
        dict
            ``attribution`` (rows), ``linear_variant`` and ``explained_fraction`` [-].
        """
        return {
            "attribution": [dict(row) for row in self.attribution],
            "linear_variant": self.linear_variant,
            "explained_fraction": self.explained_fraction,
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> LinearDetails:
        """Read the entries of :meth:`to_json` from a result's JSON object.

        Parameters
        ----------
        doc : dict
            A result's JSON object (with the entries of :meth:`to_json`).

        Returns
        -------
        LinearDetails
        """
        return cls(
            attribution=tuple(dict(row) for row in doc["attribution"]),
            linear_variant=str(doc["linear_variant"]),
            explained_fraction=float(doc["explained_fraction"]),
        )


# --------------------------------------------------------------------------------------------
# quasi-static models (seeds 000, 001)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class QuasiStaticDetails:
    """What the quasi-static models (2-D and 3-D) add to their result.

    Attributes
    ----------
    planar : bool
        True for ``quasi_static_2d`` (its approach is the initial one under the radial load),
        False for ``quasi_static_3d`` (the approach under the axial preload).
    approach_m : float
        Reference elastic approach [m]: ``initial_approach_m`` (2-D) or
        ``preload_approach_m`` (3-D) in the JSON.
    unloaded_balls_max : int
        Largest number of balls out of contact at one instant.
    n_elements : int
        Number of balls.
    explained_fraction : float
        Share of the record's variance the fitted lines explain [-].
    """

    planar: bool
    approach_m: float
    unloaded_balls_max: int
    n_elements: int
    explained_fraction: float

    @property
    def approach_key(self) -> str:
        """JSON key of :attr:`approach_m`."""
        return "initial_approach_m" if self.planar else "preload_approach_m"

    def to_json(self) -> dict[str, Any]:
        """The quasi-static model's JSON entries.

        Returns
        -------
        dict
            The approach [m] under :attr:`approach_key`, ``unloaded_balls_max``, ``n_elements``
            and ``explained_fraction`` [-].
        """
        return {
            self.approach_key: self.approach_m,
            "unloaded_balls_max": self.unloaded_balls_max,
            "n_elements": self.n_elements,
            "explained_fraction": self.explained_fraction,
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any], *, planar: bool) -> QuasiStaticDetails:
        """Read the entries of :meth:`to_json` (``planar``: the 2-D model's).

        Parameters
        ----------
        doc : dict
            A result's JSON object (with the entries of :meth:`to_json`).
        planar : bool
            True for the 2-D model (``initial_approach_m``), False for the 3-D one
            (``preload_approach_m``).

        Returns
        -------
        QuasiStaticDetails
        """
        key = "initial_approach_m" if planar else "preload_approach_m"
        return cls(
            planar=planar,
            approach_m=float(doc[key]),
            unloaded_balls_max=int(doc["unloaded_balls_max"]),
            n_elements=int(doc["n_elements"]),
            explained_fraction=float(doc["explained_fraction"]),
        )


# --------------------------------------------------------------------------------------------
# Jones-Harris equilibrium (seed 001 §2.1)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class RingDisplacement:
    """Displacement of the inner ring relative to the outer ring at equilibrium.

    Attributes
    ----------
    axial_m, x_m, y_m : float
        Axial (from the contact on one groove flank) and radial displacements [m].
    tilt_x_rad, tilt_y_rad : float
        Tilts about x and y [rad].
    """

    axial_m: float
    x_m: float
    y_m: float
    tilt_x_rad: float
    tilt_y_rad: float

    def to_json(self) -> dict[str, float]:
        """JSON ``ring_displacement``.

        Returns
        -------
        dict of str to float
            The displacements [m] and tilts [rad] by name.
        """
        return {
            "axial_m": self.axial_m,
            "x_m": self.x_m,
            "y_m": self.y_m,
            "tilt_x_rad": self.tilt_x_rad,
            "tilt_y_rad": self.tilt_y_rad,
        }

    def as_tuple(self) -> tuple[float, float, float, float, float]:
        """(axial, x, y, tilt_x, tilt_y) [m, m, m, rad, rad]: the solver's order.

        Returns
        -------
        tuple of float
            Axial, x, y displacements [m] and tilts about x, y [rad].
        """
        return (self.axial_m, self.x_m, self.y_m, self.tilt_x_rad, self.tilt_y_rad)


@dataclass(frozen=True)
class StiffnessMatrix:
    """The 5 x 5 bearing stiffness at equilibrium.

    Attributes
    ----------
    dofs : tuple of str
        Degrees of freedom, rows and columns: axial, x, y, tilt_x, tilt_y.
    units : str
        Units of the entries (rows F_a, F_x, F_y [N], M_x, M_y [N m]; columns per m or per rad).
    matrix : tuple of tuple of float
        The entries [N/m, N/rad, N m/m, N m/rad].
    """

    dofs: tuple[str, ...]
    units: str
    matrix: tuple[tuple[float, ...], ...]

    def to_json(self) -> dict[str, Any]:
        """JSON ``stiffness_matrix``.

        Returns
        -------
        dict
            ``dofs``, ``units`` and ``matrix`` (a list of rows) [N/m, N/rad, N m/m, N m/rad].
        """
        return {
            "dofs": list(self.dofs),
            "units": self.units,
            "matrix": [list(row) for row in self.matrix],
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> StiffnessMatrix:
        """Read :meth:`to_json` back.

        Parameters
        ----------
        doc : dict
            The JSON ``stiffness_matrix`` object.

        Returns
        -------
        StiffnessMatrix
        """
        return cls(
            dofs=tuple(str(d) for d in doc["dofs"]),
            units=str(doc["units"]),
            matrix=tuple(tuple(float(v) for v in row) for row in doc["matrix"]),
        )


@dataclass(frozen=True)
class RadialStiffness:
    """Radial 2 x 2 block of the bearing stiffness.

    As :func:`runout.models.equilibrium.radial_stiffness` gives it.

    Attributes
    ----------
    kxx_n_per_m, kxy_n_per_m, kyx_n_per_m, kyy_n_per_m : float
        Entries [N/m].
    speed_rpm : float
        Speed of the rotating ring [rev/min].
    """

    kxx_n_per_m: float
    kxy_n_per_m: float
    kyx_n_per_m: float
    kyy_n_per_m: float
    speed_rpm: float

    def to_json(self) -> dict[str, float]:
        """JSON ``radial_stiffness``.

        Returns
        -------
        dict of str to float
            The four entries [N/m] and ``speed_rpm`` [rev/min].
        """
        return {
            "kxx_n_per_m": self.kxx_n_per_m,
            "kxy_n_per_m": self.kxy_n_per_m,
            "kyx_n_per_m": self.kyx_n_per_m,
            "kyy_n_per_m": self.kyy_n_per_m,
            "speed_rpm": self.speed_rpm,
        }


@dataclass(frozen=True)
class BearingDamping:
    """Damping of the bearing coefficients at the operating point: c = β k.

    As :func:`runout.models.equilibrium.bearing_damping` gives it, from the reported stiffness
    (``radial_stiffness`` and the axial K_aa) and ``[analysis] bearing_damping``.

    Attributes
    ----------
    model : {"kraemer", "proportional"}
        The damping model (``[analysis] bearing_damping``).
    coefficient_s : float
        β [s].
    cxx_n_s_per_m, cxy_n_s_per_m, cyx_n_s_per_m, cyy_n_s_per_m : float
        β times the radial block kxx, kxy, kyx, kyy [N s/m].
    czz_n_s_per_m : float
        β times the axial stiffness K_aa [N s/m].
    """

    model: str
    coefficient_s: float
    cxx_n_s_per_m: float
    cxy_n_s_per_m: float
    cyx_n_s_per_m: float
    cyy_n_s_per_m: float
    czz_n_s_per_m: float

    def to_json(self) -> dict[str, Any]:
        """JSON ``bearing_damping``.

        Returns
        -------
        dict
            ``model``, ``coefficient_s`` [s] and the five coefficients [N s/m].
        """
        return {
            "model": self.model,
            "coefficient_s": self.coefficient_s,
            "cxx_n_s_per_m": self.cxx_n_s_per_m,
            "cxy_n_s_per_m": self.cxy_n_s_per_m,
            "cyx_n_s_per_m": self.cyx_n_s_per_m,
            "cyy_n_s_per_m": self.cyy_n_s_per_m,
            "czz_n_s_per_m": self.czz_n_s_per_m,
        }


@dataclass(frozen=True)
class EquilibriumDetails:
    """What the Jones-Harris equilibrium model adds to its result.

    Attributes
    ----------
    race_control : {"outer", "inner", "none"}
        Raceway control hypothesis.
    ring_displacement : RingDisplacement
        Ring displacements and tilts [m, rad].
    stiffness_matrix : StiffnessMatrix
        5 x 5 stiffness.
    radial_stiffness : RadialStiffness
        Its radial block [N/m].
    inner_contact_angle_deg, outer_contact_angle_deg : tuple of float
        Contact angle of each ball [deg].
    balls : tuple of dict
        Per-ball table (SI values, unit in the key; ``ball`` 1-based).
    newton_iterations : int
        Newton iterations of the ring solve.
    ring_tilt : {"free", "held"}
        The inner ring's tilts free, or held at 0 (``[analysis] ring_tilt``).
    held_dofs : tuple of str
        Degrees of freedom held at 0 instead of solved (``("tilt_x", "tilt_y")`` when the
        tilt is held, else empty); the stiffness matrix is over all five either way.
    reaction_moment_n_m : tuple of float
        (M_x, M_y) [N m]: the moment the tilt restraint exerts on the inner ring to hold it
        untilted, in the sense of ``moment_load`` (the moment load that would hold a free
        ring at zero tilt); (0, 0) when the tilt is free.
    life : RatingLife or None
        ISO/TS 16281 reference rating life and its parts (JSON ``life``; lives in 10^6
        revolutions, loads [N]); None without ``[bearing] dynamic_load_rating``.
    bearing_damping : BearingDamping or None
        Damping of the coefficients (JSON ``bearing_damping``); None with ``[analysis]
        bearing_damping = "none"`` (the default: stiffness only).
    """

    race_control: str
    ring_displacement: RingDisplacement
    stiffness_matrix: StiffnessMatrix
    radial_stiffness: RadialStiffness
    inner_contact_angle_deg: tuple[float, ...]
    outer_contact_angle_deg: tuple[float, ...]
    balls: tuple[Row, ...]
    newton_iterations: int
    ring_tilt: str = "free"
    held_dofs: tuple[str, ...] = ()
    reaction_moment_n_m: tuple[float, float] = (0.0, 0.0)
    life: RatingLife | None = None
    bearing_damping: BearingDamping | None = None

    def to_json(self) -> dict[str, Any]:
        """The equilibrium model's JSON entries.

        Returns
        -------
        dict
            Race control, ring tilt (free or held), ring displacement [m, rad], held degrees of
            freedom, reaction moment [N m], stiffness matrices, contact angles [deg], per-ball
            table, Newton iterations, with a dynamic load rating ``life`` and, with damping
            asked, ``bearing_damping``.
        """
        out = {
            "race_control": self.race_control,
            "ring_tilt": self.ring_tilt,
            "ring_displacement": self.ring_displacement.to_json(),
            "held_dofs": list(self.held_dofs),
            "reaction_moment_n_m": list(self.reaction_moment_n_m),
            "stiffness_matrix": self.stiffness_matrix.to_json(),
            "radial_stiffness": self.radial_stiffness.to_json(),
            "inner_contact_angle_deg": list(self.inner_contact_angle_deg),
            "outer_contact_angle_deg": list(self.outer_contact_angle_deg),
            "balls": [dict(row) for row in self.balls],
            "newton_iterations": self.newton_iterations,
        }
        if self.life is not None:
            out["life"] = self.life.to_json()
        if self.bearing_damping is not None:
            out["bearing_damping"] = self.bearing_damping.to_json()
        return out

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> EquilibriumDetails:
        """Read the entries of :meth:`to_json` from a result's JSON object.

        Parameters
        ----------
        doc : dict
            A result's JSON object (with the entries of :meth:`to_json`).

        Returns
        -------
        EquilibriumDetails
        """
        moment = doc.get("reaction_moment_n_m", (0.0, 0.0))
        return cls(
            race_control=str(doc["race_control"]),
            ring_displacement=RingDisplacement(**doc["ring_displacement"]),
            stiffness_matrix=StiffnessMatrix.from_json(doc["stiffness_matrix"]),
            radial_stiffness=RadialStiffness(**doc["radial_stiffness"]),
            inner_contact_angle_deg=tuple(float(v) for v in doc["inner_contact_angle_deg"]),
            outer_contact_angle_deg=tuple(float(v) for v in doc["outer_contact_angle_deg"]),
            balls=tuple(dict(row) for row in doc["balls"]),
            newton_iterations=int(doc["newton_iterations"]),
            # results written before ring_tilt existed: the ring was free to tilt
            ring_tilt=str(doc.get("ring_tilt", "free")),
            held_dofs=tuple(str(d) for d in doc.get("held_dofs", ())),
            reaction_moment_n_m=(float(moment[0]), float(moment[1])),
            # results written before the life existed, or without a rating: none
            life=None if doc.get("life") is None else RatingLife.from_json(doc["life"]),
            # results without damping asked (or written before it existed): none
            bearing_damping=(
                None
                if doc.get("bearing_damping") is None
                else BearingDamping(**doc["bearing_damping"])
            ),
        )


# --------------------------------------------------------------------------------------------
# dynamic model (seed 003)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class DynamicDetails:
    """What the dynamic model adds to its result.

    Attributes
    ----------
    natural_frequencies_hz : tuple of float
        Linearised natural frequencies at the static start, ascending [Hz].
    ball_passage_hz : float
        Ball passage frequency [Hz].
    time_step_s : float
        Newmark step [s].
    transient_s : float
        Length of the transient before the record [s].
    transient_end : str
        How the transient ended (``"settled"``, ``"stationary"``, ``"limit"``).
    static_displacement_m : tuple of float
        Static position the integration started from [m].
    contact_law : str
        Contact law of the balls.
    contact_stiffness_n_per_m1_5 : float
        Hertz constant [N/m^1.5].
    preload_contact_angle_deg : float
        Contact angle under the preload [deg].
    axial_dof : bool
        True when the rotor moves axially (3 degrees of freedom).
    min_loaded_balls : int
        Fewest balls in contact at one instant.
    solver_resolution_m : float
        Smallest p-p the solver resolves [m].
    explained_fraction : float
        Share of the record's variance the fitted lines explain [-].
    mean_axial_displacement_m : float or None
        Mean axial displacement from the preloaded position [m] (with ``axial_dof`` only).
    sample_rate_hz : float or None
        Samples per second of the record [Hz] (not in the JSON; None when read back: the
        record's spacing is used).
    """

    natural_frequencies_hz: tuple[float, ...]
    ball_passage_hz: float
    time_step_s: float
    transient_s: float
    transient_end: str
    static_displacement_m: tuple[float, ...]
    contact_law: str
    contact_stiffness_n_per_m1_5: float
    preload_contact_angle_deg: float
    axial_dof: bool
    min_loaded_balls: int
    solver_resolution_m: float
    explained_fraction: float
    mean_axial_displacement_m: float | None = None
    sample_rate_hz: float | None = field(default=None, compare=False, repr=False)

    def to_json(self) -> dict[str, Any]:
        """The dynamic model's JSON entries.

        Returns
        -------
        dict
            The fields by name (SI values, unit in the key), ``preload`` (``"spring"`` with
            the axial degree of freedom, else ``"position"``); ``mean_axial_displacement_m``
            [m] only when set, ``sample_rate_hz`` never.
        """
        out: dict[str, Any] = {
            "natural_frequencies_hz": list(self.natural_frequencies_hz),
            "ball_passage_hz": self.ball_passage_hz,
            "time_step_s": self.time_step_s,
            "transient_s": self.transient_s,
            "transient_end": self.transient_end,
            "static_displacement_m": list(self.static_displacement_m),
            "contact_law": self.contact_law,
            "contact_stiffness_n_per_m1_5": self.contact_stiffness_n_per_m1_5,
            "preload_contact_angle_deg": self.preload_contact_angle_deg,
            "axial_dof": self.axial_dof,
            # the case's preload kind: a spring frees z, a position holds it
            "preload": "spring" if self.axial_dof else "position",
            "min_loaded_balls": self.min_loaded_balls,
            "solver_resolution_m": self.solver_resolution_m,
            "explained_fraction": self.explained_fraction,
        }
        if self.mean_axial_displacement_m is not None:
            out["mean_axial_displacement_m"] = self.mean_axial_displacement_m
        return out

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> DynamicDetails:
        """Read the entries of :meth:`to_json` from a result's JSON object.

        Parameters
        ----------
        doc : dict
            A result's JSON object (with the entries of :meth:`to_json`).

        Returns
        -------
        DynamicDetails
        """
        mean_axial = doc.get("mean_axial_displacement_m")
        return cls(
            natural_frequencies_hz=tuple(float(v) for v in doc["natural_frequencies_hz"]),
            ball_passage_hz=float(doc["ball_passage_hz"]),
            time_step_s=float(doc["time_step_s"]),
            transient_s=float(doc["transient_s"]),
            transient_end=str(doc["transient_end"]),
            static_displacement_m=tuple(float(v) for v in doc["static_displacement_m"]),
            contact_law=str(doc["contact_law"]),
            contact_stiffness_n_per_m1_5=float(doc["contact_stiffness_n_per_m1_5"]),
            preload_contact_angle_deg=float(doc["preload_contact_angle_deg"]),
            axial_dof=bool(doc["axial_dof"]),
            min_loaded_balls=int(doc["min_loaded_balls"]),
            solver_resolution_m=float(doc["solver_resolution_m"]),
            explained_fraction=float(doc["explained_fraction"]),
            mean_axial_displacement_m=None if mean_axial is None else float(mean_axial),
        )


# --------------------------------------------------------------------------------------------
# rigid constraint model (seed 004)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class HeldRollers:
    """Which rollers held the ring over the record.

    Attributes
    ----------
    rollers_touched : tuple of int
        Rollers (1-based) in contact at some angle.
    pairs : tuple of (int, int)
        Distinct pairs of rollers holding the ring (1-based).
    pair_counts : tuple of int
        Angles at which each pair held it.
    max_touching : int
        Most rollers touching at one angle.
    fraction_three_or_more : float
        Share of the angles with three or more rollers touching [-].
    """

    rollers_touched: tuple[int, ...]
    pairs: tuple[tuple[int, int], ...]
    pair_counts: tuple[int, ...]
    max_touching: int
    fraction_three_or_more: float

    def to_json(self) -> dict[str, Any]:
        """JSON ``contacts``.

        Returns
        -------
        dict
            JSON ``contacts``: the fields by name (lists for the tuples).
        """
        return {
            "rollers_touched": list(self.rollers_touched),
            "pairs": [list(p) for p in self.pairs],
            "pair_counts": list(self.pair_counts),
            "max_touching": self.max_touching,
            "fraction_three_or_more": self.fraction_three_or_more,
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> HeldRollers:
        """Read :meth:`to_json` back.

        Parameters
        ----------
        doc : dict
            The JSON ``contacts`` object.

        Returns
        -------
        HeldRollers
        """
        return cls(
            rollers_touched=tuple(int(j) for j in doc["rollers_touched"]),
            pairs=tuple((int(a), int(b)) for a, b in doc["pairs"]),
            pair_counts=tuple(int(c) for c in doc["pair_counts"]),
            max_touching=int(doc["max_touching"]),
            fraction_three_or_more=float(doc["fraction_three_or_more"]),
        )


@dataclass(frozen=True)
class Iso492:
    """The ISO 492 name of the rigid model's radial runout.

    Attributes
    ----------
    quantity : {"Kia", "Kea"}
        Radial runout of the assembled bearing's inner (Kia) or outer (Kea) ring.
    radial_runout_m : float
        Its value [m].
    """

    quantity: str
    radial_runout_m: float

    def to_json(self) -> dict[str, Any]:
        """JSON ``iso492``.

        Returns
        -------
        dict
            ``quantity`` and ``radial_runout_m`` [m].
        """
        return {"quantity": self.quantity, "radial_runout_m": self.radial_runout_m}


@dataclass(frozen=True)
class RollerDetails:
    """What the rigid constraint model (``roller_constraint``) adds to its result.

    Attributes
    ----------
    horizontal_pp_m : float
        Peak-to-peak across the measuring load [m].
    explained_fraction : float
        Share of the record's variance the fitted lines explain [-].
    contacts : HeldRollers
        Which rollers held the ring.
    rotating_ring : {"inner", "outer"}
        The turning (and loaded) ring.
    radial_clearance_m : float
        Diametral clearance [m].
    iso492 : Iso492
        ISO 492 name and value of the radial runout.
    solution : RollerSolution or None
        The contact solution at every angle (not in the JSON: it writes ``contacts.csv``,
        ``order_sweep.csv`` and the model's figures); None when read back.
    """

    horizontal_pp_m: float
    explained_fraction: float
    contacts: HeldRollers
    rotating_ring: str
    radial_clearance_m: float
    iso492: Iso492
    solution: RollerSolution | None = field(default=None, compare=False, repr=False)

    def to_json(self) -> dict[str, Any]:
        """The rigid model's JSON entries.

        Returns
        -------
        dict
            ``horizontal_pp_m`` [m], ``explained_fraction`` [-], ``contacts``, ``rotating_ring``,
            ``radial_clearance_m`` [m] and ``iso492`` (not the solution).
        """
        return {
            "horizontal_pp_m": self.horizontal_pp_m,
            "explained_fraction": self.explained_fraction,
            "contacts": self.contacts.to_json(),
            "rotating_ring": self.rotating_ring,
            "radial_clearance_m": self.radial_clearance_m,
            "iso492": self.iso492.to_json(),
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> RollerDetails:
        """Read the entries of :meth:`to_json` from a result's JSON object.

        Parameters
        ----------
        doc : dict
            A result's JSON object (with the entries of :meth:`to_json`).
            ``solution`` is None.

        Returns
        -------
        RollerDetails
        """
        return cls(
            horizontal_pp_m=float(doc["horizontal_pp_m"]),
            explained_fraction=float(doc["explained_fraction"]),
            contacts=HeldRollers.from_json(doc["contacts"]),
            rotating_ring=str(doc["rotating_ring"]),
            radial_clearance_m=float(doc["radial_clearance_m"]),
            iso492=Iso492(str(doc["iso492"]["quantity"]), float(doc["iso492"]["radial_runout_m"])),
        )


#: The details of any model.
# --------------------------------------------------------------------------------------------
# spindle (a rigid shaft on several bearings)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SpindleBearingResult:
    """One bearing of a spindle run (a row of the JSON ``bearings``).

    Attributes
    ----------
    name : str
        The bearing's name in the case.
    position_m : float
        Axial coordinate of its ball-set plane [m].
    contact_angle_deg : float
        Its contact angle [deg].
    thrust : {"+z", "-z"}
        Direction of the axial load on the shaft it carries (the arrangement).
    preload_n : float
        Preload it carries [N].
    preload_approach_m : float
        Elastic approach along the contact line under that preload [m].
    pressure_centre_m : float
        Axial coordinate where its contact lines cross the axis [m].
    runout : Runout
        The shaft's runout at its plane (relative to the housing) [m].
    mean_displacement_m : tuple of float
        Mean (x, y, z) of the shaft at its plane [m].
    life : RatingLife or None
        Its ISO/TS 16281 reference rating life from its ball loads at the static position
        (JSON ``life``, only with its ``dynamic_load_rating``).
    """

    name: str
    position_m: float
    contact_angle_deg: float
    thrust: str
    preload_n: float
    preload_approach_m: float
    pressure_centre_m: float
    runout: Runout
    mean_displacement_m: tuple[float, float, float]
    life: RatingLife | None = None

    def to_json(self) -> dict[str, Any]:
        """JSON row of ``bearings``.

        Returns
        -------
        dict
            The fields by name (SI values, unit in the key; ``runout`` [m] as an object).
        """
        return {
            "name": self.name,
            "position_m": self.position_m,
            "contact_angle_deg": self.contact_angle_deg,
            "thrust": self.thrust,
            "preload_n": self.preload_n,
            "preload_approach_m": self.preload_approach_m,
            "pressure_centre_m": self.pressure_centre_m,
            "runout": self.runout.to_json(),
            "mean_displacement_m": list(self.mean_displacement_m),
        } | ({} if self.life is None else {"life": self.life.to_json()})

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> SpindleBearingResult:
        """Read :meth:`to_json` back.

        Parameters
        ----------
        doc : dict
            One row of the JSON ``bearings``.

        Returns
        -------
        SpindleBearingResult
        """
        from runout.analysis.lines import Runout

        x, y, z = (float(v) for v in doc["mean_displacement_m"])
        return cls(
            name=str(doc["name"]),
            position_m=float(doc["position_m"]),
            contact_angle_deg=float(doc["contact_angle_deg"]),
            thrust=str(doc["thrust"]),
            preload_n=float(doc["preload_n"]),
            preload_approach_m=float(doc["preload_approach_m"]),
            pressure_centre_m=float(doc["pressure_centre_m"]),
            runout=Runout(**{k: float(v) for k, v in doc["runout"].items()}),
            mean_displacement_m=(x, y, z),
            # rows written before the spindle's life, or without a rating: none
            life=None if doc.get("life") is None else RatingLife.from_json(doc["life"]),
        )


def tool_point_stiffness(
    matrix: tuple[tuple[float, ...], ...] | NDArray[np.float64],
) -> tuple[float, float, float]:
    r"""1/C_ii of the translations of a 5×5 stiffness at a point (x, y, z, θx, θy) [N/m].

    Parameters
    ----------
    matrix : array_like, shape (5, 5)
        Stiffness at the point: rows F_x, F_y, F_z [N], M_x, M_y [N m]; columns per m or per
        rad.

    Returns
    -------
    tuple of float
        :math:`1/C_{xx}, 1/C_{yy}, 1/C_{zz}` with :math:`C = K^{-1}` [N/m]: the stiffness
        along each translation with the other coordinates free (0 where K is singular along
        it: a coordinate nothing holds).

    Notes
    -----
    The compliance is solved from K (``numpy.linalg.solve`` against the unit vectors), not
    read from K's diagonal: :math:`1/C_{ii} \le K_{ii}`, equal only where coordinate i does
    not couple to the others.
    """
    k = np.asarray(matrix, dtype=np.float64)
    try:
        compliance = np.linalg.solve(k, np.eye(k.shape[0])[:, :3])
    except np.linalg.LinAlgError:
        return (0.0, 0.0, 0.0)
    diag = np.diag(compliance[:3, :3])
    out = [float(1.0 / c) if c > 0.0 and math.isfinite(c) else 0.0 for c in diag]
    return out[0], out[1], out[2]


@dataclass(frozen=True)
class SpindleDetails:
    """What the spindle model adds to its result (the nose's record is the result's own).

    Attributes
    ----------
    arrangement : {"DB", "DF", "DT"}
        Back-to-back, face-to-face or tandem.
    nose_position_m : float
        Axial coordinate of the reported runout [m].
    tilt_pp_rad : tuple of float
        Peak-to-peak of the shaft's tilts θx, θy [rad].
    static_position : tuple of float
        The shaft's position without imperfections (x, y, z [m], θx, θy [rad]) at the axial
        origin, from its preload reference.
    bearings : tuple of SpindleBearingResult
        Each bearing's figures at its own plane.
    stiffness_matrix : StiffnessMatrix
        5×5 stiffness of the shaft at the nose (x, y, z, tilt_x, tilt_y) [N/m, N/rad, N m/m,
        N m/rad]: its diagonal is a stiffness with every other coordinate held (a translation
        of the nose with the tilt held), not the stiffness at the tool
        (:attr:`tool_point_stiffness_n_per_m`).
    unloaded_balls_max : int
        Largest number of balls (all bearings) out of contact at one instant.
    n_elements : int
        Balls of all bearings.
    explained_fraction : float
        Share of the nose record's variance the fitted lines explain [-].
    """

    arrangement: str
    nose_position_m: float
    tilt_pp_rad: tuple[float, float]
    static_position: tuple[float, ...]
    bearings: tuple[SpindleBearingResult, ...]
    stiffness_matrix: StiffnessMatrix
    unloaded_balls_max: int
    n_elements: int
    explained_fraction: float

    @property
    def tool_point_stiffness_n_per_m(self) -> tuple[float, float, float]:
        r"""Stiffness at the tool (the nose) along x, y, z with the shaft free to tilt [N/m].

        :math:`k_i = 1 / C_{ii}` with :math:`C = K^{-1}` the nose compliance (the inverse of
        :attr:`stiffness_matrix`): the force at the nose along i over the displacement it
        gives there, every other coordinate (the tilts included) settling where the bearings
        put it. What a machine-tool designer calls the spindle's static stiffness at the tool;
        the diagonal :math:`K_{ii}` holds the tilt and is larger (much larger for an
        overhung nose).

        Returns
        -------
        tuple of float
            k_x, k_y, k_z [N/m].
        """
        return tool_point_stiffness(self.stiffness_matrix.matrix)

    def to_json(self) -> dict[str, Any]:
        """The spindle model's JSON entries.

        Returns
        -------
        dict
            The fields by name (SI values, unit in the key); ``tilt_pp_rad`` [rad] and
            ``tool_point_stiffness_n_per_m`` [N/m] as ``x``, ``y`` (``z``) objects,
            ``bearings`` as rows.
        """
        kx, ky, kz = self.tool_point_stiffness_n_per_m
        return {
            "arrangement": self.arrangement,
            "nose_position_m": self.nose_position_m,
            "tilt_pp_rad": {"x": self.tilt_pp_rad[0], "y": self.tilt_pp_rad[1]},
            "static_position": list(self.static_position),
            "bearings": [b.to_json() for b in self.bearings],
            "stiffness_matrix": self.stiffness_matrix.to_json(),
            "tool_point_stiffness_n_per_m": {"x": kx, "y": ky, "z": kz},
            "unloaded_balls_max": self.unloaded_balls_max,
            "n_elements": self.n_elements,
            "explained_fraction": self.explained_fraction,
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> SpindleDetails:
        """Read :meth:`to_json` back.

        Parameters
        ----------
        doc : dict
            A result's JSON object (with the entries of :meth:`to_json`).

        Returns
        -------
        SpindleDetails
        """
        tilt = doc["tilt_pp_rad"]
        return cls(
            arrangement=str(doc["arrangement"]),
            nose_position_m=float(doc["nose_position_m"]),
            tilt_pp_rad=(float(tilt["x"]), float(tilt["y"])),
            static_position=tuple(float(v) for v in doc["static_position"]),
            bearings=tuple(SpindleBearingResult.from_json(b) for b in doc["bearings"]),
            stiffness_matrix=StiffnessMatrix.from_json(doc["stiffness_matrix"]),
            unloaded_balls_max=int(doc["unloaded_balls_max"]),
            n_elements=int(doc["n_elements"]),
            explained_fraction=float(doc["explained_fraction"]),
        )


ModelDetails: TypeAlias = (
    LinearDetails
    | QuasiStaticDetails
    | EquilibriumDetails
    | DynamicDetails
    | RollerDetails
    | SpindleDetails
)


def details_from_json(model: str, doc: dict[str, Any]) -> ModelDetails | None:
    """The details of ``model`` read from a result's JSON object (None for an unknown model).

    Parameters
    ----------
    model : str
        Model id (the JSON's ``model``).
    doc : dict
        The result's JSON object.

    Returns
    -------
    ModelDetails or None
        The model's details class (:data:`DETAILS_BY_MODEL`) read from ``doc``.
    """
    if model == "linear":
        return LinearDetails.from_json(doc)
    if model in ("quasi_static_2d", "quasi_static_3d"):
        return QuasiStaticDetails.from_json(doc, planar=model == "quasi_static_2d")
    if model == "equilibrium":
        return EquilibriumDetails.from_json(doc)
    if model == "dynamic":
        return DynamicDetails.from_json(doc)
    if model == "roller_constraint":
        return RollerDetails.from_json(doc)
    if model == "spindle":
        return SpindleDetails.from_json(doc)
    return None


#: Model id -> its details class.
DETAILS_BY_MODEL: dict[str, type[ModelDetails]] = {
    "linear": LinearDetails,
    "quasi_static_2d": QuasiStaticDetails,
    "quasi_static_3d": QuasiStaticDetails,
    "equilibrium": EquilibriumDetails,
    "dynamic": DynamicDetails,
    "roller_constraint": RollerDetails,
    "spindle": SpindleDetails,
}


# --------------------------------------------------------------------------------------------
# [analysis] outputs
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Iso15242Band:
    """One ISO 15242-1 band.

    Attributes
    ----------
    low_hz, high_hz : float
        Band edges [Hz].
    rms_um_per_s : float
        RMS velocity in the band [um/s].
    """

    low_hz: float
    high_hz: float
    rms_um_per_s: float

    def to_json(self) -> dict[str, float]:
        """JSON band object.

        Returns
        -------
        dict of str to float
            ``low_hz``, ``high_hz`` [Hz] and ``rms_um_per_s`` [um/s].
        """
        return {"low_hz": self.low_hz, "high_hz": self.high_hz, "rms_um_per_s": self.rms_um_per_s}


@dataclass(frozen=True)
class Iso15242:
    """RMS velocity per ISO 15242-1 band, from the lines along the measuring direction.

    Attributes
    ----------
    unit : str
        Unit of the band values (``"um/s"``).
    speed_rpm : float
        Speed of the rotating ring [rev/min] (the band edges scale with it).
    direction : {"x", "y", "measuring"}
        Measuring direction by name, ``"measuring"`` when along no axis.
    measuring_direction : tuple of float
        Unit vector of the measuring direction (x, y) [-].
    bands : dict
        Band name (L, M, H) -> :class:`Iso15242Band`.
    """

    unit: str
    speed_rpm: float
    direction: str
    measuring_direction: tuple[float, float]
    bands: dict[str, Iso15242Band]

    def to_json(self) -> dict[str, Any]:
        """JSON ``iso15242``.

        Returns
        -------
        dict
            ``unit``, ``speed_rpm`` [rev/min], ``direction``, ``measuring_direction`` [-] and
            ``bands`` (name -> band object).
        """
        return {
            "unit": self.unit,
            "speed_rpm": self.speed_rpm,
            "direction": self.direction,
            "measuring_direction": list(self.measuring_direction),
            "bands": {name: band.to_json() for name, band in self.bands.items()},
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> Iso15242:
        """Read :meth:`to_json` back.

        Parameters
        ----------
        doc : dict
            The JSON ``iso15242`` object.

        Returns
        -------
        Iso15242
        """
        u = doc["measuring_direction"]
        return cls(
            unit=str(doc["unit"]),
            speed_rpm=float(doc["speed_rpm"]),
            direction=str(doc["direction"]),
            measuring_direction=(float(u[0]), float(u[1])),
            bands={
                str(name): Iso15242Band(
                    float(b["low_hz"]), float(b["high_hz"]), float(b["rms_um_per_s"])
                )
                for name, b in doc["bands"].items()
            },
        )


@dataclass(frozen=True)
class Verdict:
    """A runout figure or band value against the case's ``[analysis] limit``.

    Attributes
    ----------
    quantity : str
        ``radial_pp``, ``rro_pp``, ``nrro_pp``, ``axial_pp`` or ``iso15242.<band>``.
    limit : float
        The limit [m] for a p-p, [um/s] for a band.
    value : float
        The result's value, same unit.
    passed : bool
        True when ``value <= limit``.
    unit : {"m", "um/s"}
        Unit of ``limit`` and ``value`` (JSON ``limit_m`` / ``limit_um_per_s``).
    tolerance_class : dict or None
        For an ISO 492 tolerance class limit: ``{"class", "bore_m", "source"}`` (JSON keys
        of the same names); None for a numeric limit.
    """

    quantity: str
    limit: float
    value: float
    passed: bool
    unit: Literal["m", "um/s"] = "m"
    tolerance_class: dict[str, Any] | None = None

    def to_json(self) -> dict[str, Any]:
        """JSON ``verdict``.

        Returns
        -------
        dict
            ``quantity``, ``limit_m`` and ``value_m`` [m] (``limit_um_per_s`` and
            ``value_um_per_s`` [um/s] for a band) and ``pass``; for a tolerance class also
            ``class``, ``bore_m`` and ``source`` (ISO 492:2014 and the bore range).
        """
        suffix = "m" if self.unit == "m" else "um_per_s"
        return {
            "quantity": self.quantity,
            f"limit_{suffix}": self.limit,
            f"value_{suffix}": self.value,
            "pass": self.passed,
            **(self.tolerance_class or {}),
        }

    @classmethod
    def from_json(cls, doc: dict[str, Any]) -> Verdict:
        """Read :meth:`to_json` back.

        Parameters
        ----------
        doc : dict
            The JSON ``verdict`` object (its keys give the unit).

        Returns
        -------
        Verdict
        """
        if "limit_m" in doc:
            grade: dict[str, Any] = {k: doc[k] for k in ("class", "bore_m", "source") if k in doc}
            return cls(
                str(doc["quantity"]),
                float(doc["limit_m"]),
                float(doc["value_m"]),
                bool(doc["pass"]),
                "m",
                grade or None,
            )
        return cls(
            str(doc["quantity"]),
            float(doc["limit_um_per_s"]),
            float(doc["value_um_per_s"]),
            bool(doc["pass"]),
            "um/s",
        )


def __getattr__(name: str) -> object:
    """``RollerContacts`` (renamed :class:`HeldRollers`: one name, one class), for one release;
    :class:`runout.geometry.contact.RollerContacts` is the Hertz contacts of a roller bearing."""
    if name == "RollerContacts":
        import warnings

        warnings.warn(
            "runout.analysis.result_details.RollerContacts is deprecated: it is HeldRollers",
            DeprecationWarning,
            stacklevel=2,
        )
        return HeldRollers
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
