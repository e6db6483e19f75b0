"""One module per model id; :func:`run_model` dispatches a validated case to it.

Each model lives in ``runout/models/<id>.py`` and exposes ``run(case) -> RunResult``. A case
that names a model this version does not provide gets a
:class:`runout.base.errors.ModelNotAvailableError` saying so, never a partial answer.
"""

from __future__ import annotations

import dataclasses
import importlib
import importlib.util
import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.base.errors import ModelNotAvailableError

__all__ = ["MODEL_MODULES", "available_models", "measuring_direction", "run_model"]

#: model id -> module that implements it (``run(case) -> RunResult``)
MODEL_MODULES: dict[str, str] = {
    "linear": "runout.models.linear",
    "quasi_static_2d": "runout.models.quasi_static_2d",
    "quasi_static_3d": "runout.models.quasi_static_3d",
    "equilibrium": "runout.models.equilibrium",
    "dynamic": "runout.models.dynamic",
    "roller_constraint": "runout.models.roller_constraint",
    "spindle": "runout.models.spindle",
}


def available_models() -> list[str]:
    """Model ids this installation provides."""
    return sorted(
        model
        for model, module in MODEL_MODULES.items()
        if importlib.util.find_spec(module) is not None
    )


def measuring_direction(case: Any, model: str | None = None) -> NDArray[np.float64]:
    """Unit vector (x, y) of the radial measuring direction ``model`` uses on ``case``.

    The direction of the radial load on the shaft (``operation.radial_load_direction``) when
    there is one, else +x; the rigid constraint model always measures along the load
    direction (it assumes a light measuring load when none is given); the equilibrium model
    (one instant) along +x.

    Parameters
    ----------
    case : runout.case.model.Case
        A validated case.
    model : str, optional
        Model id; default the case's ``[analysis] model``.
    """
    model = model or case.analysis.model
    op = case.operation
    if model == "roller_constraint" or (model != "equilibrium" and op.radial_load > 0.0):
        angle = op.radial_load_direction
        return np.array([math.cos(angle), math.sin(angle)])
    return np.array([1.0, 0.0])


def run_model(case: Any) -> Any:
    """Run the model named in ``case.analysis.model``.

    The case is first checked against :mod:`runout.case.conventions`: a key the model refuses ends
    the run with a :class:`runout.base.errors.CaseError`; the keys it does not apply are added to
    the result's notes.

    Raises
    ------
    ModelNotAvailableError
        If that model is not part of this version.
    CaseError
        If the case sets a key the model refuses, fails the model's input checks, exceeds the
        budget of :mod:`runout.case.limits` or loads a contact beyond Hertz theory
        (:func:`runout.runner.checks.validate`); its warnings join the result's notes.
    """
    model = case.analysis.model
    if model not in available_models():
        available = ", ".join(available_models()) or "none yet"
        raise ModelNotAvailableError(
            f"{case.path}: analysis.model: model '{model}' is not available in this version "
            f"(available: {available}); `runout check` and `runout frequencies` work for any case"
        )
    from runout.base.errors import GeometryError
    from runout.case.conventions import enforce
    from runout.runner.checks import as_case_error, validate

    # One meaning per key: refuse what this model cannot honour, note what it does not apply.
    notes = enforce(case, model)
    # the model's set-up, the budget and the physics, as `runout check` runs them
    warnings = validate(case, model)
    module = importlib.import_module(MODEL_MODULES[model])
    try:
        result = module.run(case)
    except GeometryError as exc:  # an input check inside the model: name the file and key
        raise as_case_error(case, exc) from None
    if notes or warnings:
        result = dataclasses.replace(result, notes=(*result.notes, *warnings, *notes))
    # the case's [analysis] outputs beyond the model: bands, verdict, passage names
    from runout.analysis.results import apply_analysis

    return apply_analysis(result, case)
