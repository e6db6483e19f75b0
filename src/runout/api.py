"""Running runout from Python: the same cases, checks and models as the case file.

:func:`run` is the one entry point from code. It builds the document a case file with the
same tables would hold, validates it exactly as :func:`runout.case.model.load_case` validates a file
(the same keys, units, messages and budget checks) and runs it with
:func:`runout.runner.run_model`, which is what ``runout run`` does with a file. A case built
in code is a :class:`runout.case.model.Case` like any other:
:meth:`~runout.case.model.Case.to_toml` writes it as a case file that ``runout run`` gives the
same results for.

:class:`Imperfections` here is a *builder* that reads like the case file's imperfection tables
(``[[waviness]]``, ``[[waviness_spectrum]]``, ``[[profile]]``, ``[slant]``, ``[elements]``):
the same keys, units and meanings. It records the tables; the bearing turns them into
harmonics when the case is built. The resolved harmonics the models use are
:class:`runout.geometry.imperfections.BearingImperfections` (``case.imperfections``), the
physics class: build one directly only to work with the harmonics themselves.

Examples
--------
>>> import runout
>>> bearing = runout.BallBearing(elements=8, element_diameter=1e-3, pitch_diameter=7e-3,
...                              radial_clearance=10e-6)
>>> operation = runout.Operation(rotating_ring="outer", speed=90.0, axial_load=20.0)
>>> waves = runout.Imperfections(elements=8).waviness("inner", order=9, peak_to_peak="20 nm")
>>> result = runout.run("quasi_static_3d", bearing=bearing, operation=operation,
...                     imperfections=waves, revolutions=20, samples=2048)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.analysis.result_details import EquilibriumDetails
from runout.analysis.results import RunResult
from runout.base.errors import CaseError
from runout.case.builder import Imperfections, build_case, split_options
from runout.case.model import Case, parse_case
from runout.geometry.bearing import BallBearing, Operation, RollerBearing
from runout.runner import run_model

__all__ = [
    "ROSS_MAJOR_VERSIONS",
    "BearingCoefficients",
    "Imperfections",
    "bearing_coefficients",
    "build_case",
    "run",
]

#: ROSS major versions :meth:`BearingCoefficients.to_ross_kwargs` knows the speed axis of.
ROSS_MAJOR_VERSIONS = (2, 3)
#: Stiffness names of :class:`BearingCoefficients` [N/m] (stiffness.csv's columns).
_K_NAMES = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m", "kzz_n_per_m")
#: Damping names [N s/m], in the order of :data:`_K_NAMES`.
_C_NAMES = ("cxx_n_s_per_m", "cxy_n_s_per_m", "cyx_n_s_per_m", "cyy_n_s_per_m", "czz_n_s_per_m")


def run(
    model: str,
    *,
    bearing: BallBearing | RollerBearing,
    operation: Operation,
    imperfections: Imperfections | None = None,
    title: str = "",
    tables: Mapping[str, Any] | None = None,
    **options: Any,
) -> RunResult:
    """Run one model on a bearing: the Python form of ``runout run CASE``.

    Builds the case a case file with these tables would give
    (:meth:`runout.case.model.Case.from_inputs`, with every check of a case file and of the memory
    and time budget) and runs it with :func:`runout.runner.run_model`, as the command line does.

    Parameters
    ----------
    model : str
        Model id: "linear", "quasi_static_2d", "quasi_static_3d", "equilibrium", "dynamic"
        or "roller_constraint" (``[analysis] model``).
    bearing : BallBearing or RollerBearing
        Geometry and material.
    operation : Operation
        Speeds and loads.
    imperfections : Imperfections, optional
        The builder of the imperfection tables; default a perfect bearing.
    title : str
        Shown in outputs.
    tables : mapping, optional
        The case file's other tables by name, as the file gives them: ``{"lubrication":
        {"viscosity_ratio": 1.5, "contamination_factor": 0.5}, "bearing":
        {"fatigue_load_limit": "0.6 kN"}}`` for the modified life, ``{"sensor": {...},
        "defect": [{...}]}`` for a spall's acceleration signal; a key the other arguments
        give too is refused.
    **options
        The ``[analysis]`` keys (revolutions, samples, bands, limit, limit_on,
        linear_variant, race_control, ring_tilt, bearing_damping, bearing_damping_coefficient,
        max_memory, max_time) and the ``[dynamics]`` keys
        (mass, damping, unbalance, time_step, axial_dof, contact_law) by the same names: SI
        numbers or strings with units.

    Returns
    -------
    RunResult

    Raises
    ------
    CaseError
        An unknown option, or a value the case file would refuse (the same message, naming
        the key, with ``<python>`` for the file).
    """
    analysis, dynamics = split_options(options)
    case = build_case(
        bearing,
        operation,
        imperfections,
        title=title,
        analysis={"model": model, **analysis},
        dynamics=dynamics or None,
        tables=tables,
    )
    result: RunResult = run_model(case)
    return result


@dataclass(frozen=True)
class BearingCoefficients:
    """A bearing's linear coefficients over the speed of its rotating ring: a rotor code's input.

    Each entry is the ``runout run --json`` result of the equilibrium model at that speed:
    ``radial_stiffness`` (the radial block, tilts held), K_aa of ``stiffness_matrix`` and
    ``bearing_damping`` (c = β k; zero with ``damping_model = "none"``). Rows as in a sweep's
    ``stiffness.csv``.

    Attributes
    ----------
    speed_hz : ndarray
        Speed of the rotating ring [Hz], one per row.
    kxx_n_per_m, kxy_n_per_m, kyx_n_per_m, kyy_n_per_m : ndarray
        Radial block ∂F_x/∂x, ∂F_x/∂y, ∂F_y/∂x, ∂F_y/∂y of the restoring force [N/m].
    kzz_n_per_m : ndarray
        Axial stiffness K_aa [N/m].
    cxx_n_s_per_m, cxy_n_s_per_m, cyx_n_s_per_m, cyy_n_s_per_m, czz_n_s_per_m : ndarray
        Damping, β times the stiffness of the same name [N s/m]; zero for ``"none"``.
    damping_model : {"none", "kraemer", "proportional"}
        ``[analysis] bearing_damping`` of the case.
    damping_coefficient_s : float
        β [s] (0 for ``"none"``).
    """

    speed_hz: NDArray[np.float64]
    kxx_n_per_m: NDArray[np.float64]
    kxy_n_per_m: NDArray[np.float64]
    kyx_n_per_m: NDArray[np.float64]
    kyy_n_per_m: NDArray[np.float64]
    kzz_n_per_m: NDArray[np.float64]
    cxx_n_s_per_m: NDArray[np.float64]
    cxy_n_s_per_m: NDArray[np.float64]
    cyx_n_s_per_m: NDArray[np.float64]
    cyy_n_s_per_m: NDArray[np.float64]
    czz_n_s_per_m: NDArray[np.float64]
    damping_model: str
    damping_coefficient_s: float

    @property
    def speed_rpm(self) -> NDArray[np.float64]:
        """Speed of the rotating ring [rev/min]."""
        return 60.0 * self.speed_hz

    @property
    def frequency_rad_per_s(self) -> NDArray[np.float64]:
        """Speed of the rotating ring as an angular frequency [rad/s]: a rotor code's speed."""
        return 2.0 * math.pi * self.speed_hz

    def to_ross_kwargs(self, ross_version: str) -> dict[str, Any]:
        """Keyword arguments of ``ross.BearingElement`` with the speed on its rotor-speed axis.

        ROSS 3 renamed the axes of a bearing's coefficient table: ``speed=`` is the rotor speed
        (what ROSS 2 called ``frequency=``) and ``frequency=`` the whirl frequency. This gives
        the rotor speed [rad/s] under the name the given version reads it by. ROSS itself is
        not imported (it is not a dependency of runout).

        Parameters
        ----------
        ross_version : str
            ``ross.__version__`` (major 2 or 3, :data:`ROSS_MAJOR_VERSIONS`).

        Returns
        -------
        dict
            ``kxx``, ``kxy``, ``kyx``, ``kyy``, ``kzz`` [N/m], ``cxx`` ... ``czz`` [N s/m]
            (zeros with ``damping_model = "none"``: ROSS needs a ``cxx``) as float arrays,
            and ``speed`` (ROSS 3) or ``frequency`` (ROSS 2): the rotor speed [rad/s]. Add
            ``n=`` (the node) and pass them: ``ross.BearingElement(n=0, **kwargs)``.

        Raises
        ------
        ValueError
            A version whose major is not 2 or 3.
        """
        head = str(ross_version).split(".", 1)[0]
        major = int(head) if head.isdigit() else None
        if major not in ROSS_MAJOR_VERSIONS:
            raise ValueError(
                f"ROSS {ross_version!r}: runout knows the speed axis of ROSS 2 (frequency=) and "
                "ROSS 3 (speed=); read the bearing element's documentation for this version"
            )
        kwargs: dict[str, Any] = {
            name.split("_", 1)[0]: np.array(getattr(self, name), dtype=np.float64)
            for name in _K_NAMES + _C_NAMES
        }
        kwargs["speed" if major >= 3 else "frequency"] = self.frequency_rad_per_s
        return kwargs


def bearing_coefficients(case: Case, speeds_hz: ArrayLike) -> BearingCoefficients:
    """The bearing's coefficients at each speed: the equilibrium model run once per speed.

    The Python form of a sweep of ``operation.speed`` (``stiffness.csv``): the case with its
    ``[operation] speed`` replaced by each value, validated as a case file and run by
    :func:`runout.runner.run_model`, as ``runout run`` does.

    Parameters
    ----------
    case : Case
        A case of the equilibrium model (``[analysis] model = "equilibrium"``), its damping
        from ``[analysis] bearing_damping``.
    speeds_hz : array_like
        Speeds of the rotating ring [Hz], one or more, finite and >= 0.

    Returns
    -------
    BearingCoefficients
        One row per speed, in the order given.

    Raises
    ------
    CaseError
        A case of another model (key ``analysis.model``), no speed or a speed that is not a
        finite number >= 0 (key ``operation.speed``), or what the case file would refuse at
        that speed.

    Notes
    -----
    Stiffness: the Jones–Harris equilibrium (seed 001 §2.1; Kim, Choi & Yoon). Damping:
    c = β k (E. Krämer, *Dynamics of Rotors and Foundations*, Springer, 1993;
    :mod:`runout.geometry.bearing_damping`).
    """
    if case.analysis.model != "equilibrium":
        raise CaseError(
            case.path,
            "analysis.model",
            f'bearing coefficients come from the equilibrium model, not "{case.analysis.model}"',
        )
    speeds = np.atleast_1d(np.asarray(speeds_hz, dtype=np.float64))
    if speeds.ndim != 1 or speeds.size == 0 or not np.all(np.isfinite(speeds) & (speeds >= 0)):
        raise CaseError(case.path, "operation.speed", "needs one or more finite speeds >= 0 [Hz]")
    document = case.to_document()
    document.pop("study", None)
    base = Path(case.path).parent if case.path and not case.path.startswith("<") else None
    rows: list[EquilibriumDetails] = []
    for speed in speeds:
        document.setdefault("operation", {})["speed"] = float(speed)
        point = parse_case(document, case.path, base, profile_data=case.profile_data)
        details = run_model(point).details
        assert isinstance(details, EquilibriumDetails)
        rows.append(details)
    damping = [d.bearing_damping for d in rows]
    columns: dict[str, NDArray[np.float64]] = {}
    for k_name, c_name in zip(_K_NAMES, _C_NAMES, strict=True):
        if k_name == "kzz_n_per_m":
            columns[k_name] = np.array([d.stiffness_matrix.matrix[0][0] for d in rows])
        else:
            columns[k_name] = np.array([getattr(d.radial_stiffness, k_name) for d in rows])
        columns[c_name] = np.array([0.0 if c is None else getattr(c, c_name) for c in damping])
    first = damping[0]
    return BearingCoefficients(
        speed_hz=speeds.copy(),
        damping_model="none" if first is None else first.model,
        damping_coefficient_s=0.0 if first is None else first.coefficient_s,
        **columns,
    )
