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

from typing import Any

from runout.analysis.results import RunResult
from runout.case.builder import Imperfections, build_case, split_options
from runout.geometry.bearing import BallBearing, Operation, RollerBearing
from runout.runner import run_model

__all__ = ["Imperfections", "build_case", "run"]


def run(
    model: str,
    *,
    bearing: BallBearing | RollerBearing,
    operation: Operation,
    imperfections: Imperfections | None = None,
    title: str = "",
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
    **options
        The ``[analysis]`` keys (revolutions, samples, bands, limit, limit_on,
        linear_variant, race_control, ring_tilt, max_memory, max_time) and the ``[dynamics]`` keys
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
    )
    result: RunResult = run_model(case)
    return result
