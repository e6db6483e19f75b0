"""One module per model id (the physics); :func:`runout.runner.run_model` dispatches a validated
case to it.

Each model lives in ``runout/models/<id>.py`` and exposes ``run(case) -> RunResult``. A case
that names a model this version does not provide gets a
:class:`runout.base.errors.ModelNotAvailableError` saying so, never a partial answer.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = ["MODEL_MODULES", "available_models", "measuring_direction"]

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
    """Model ids this installation provides.

    Returns
    -------
    list of str
        The ids of :data:`MODEL_MODULES` whose module can be imported, sorted.
    """
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

    Returns
    -------
    ndarray, shape (2,)
        Unit vector (x, y) of the measuring direction [-].
    """
    model = model or case.analysis.model
    op = case.operation
    if model == "roller_constraint" or (model != "equilibrium" and op.radial_load > 0.0):
        angle = op.radial_load_direction
        return np.array([math.cos(angle), math.sin(angle)])
    return np.array([1.0, 0.0])


def __getattr__(name: str) -> Any:
    """``runout.models.run_model`` (moved to :func:`runout.runner.run_model`), for one release."""
    if name == "run_model":
        import warnings

        warnings.warn(
            "runout.models.run_model is deprecated; import it from runout.runner",
            DeprecationWarning,
            stacklevel=2,
        )
        # the orchestration is a layer above the models: found by name, once, for the old path
        return importlib.import_module("runout.runner").run_model
    raise AttributeError(f"module 'runout.models' has no attribute {name!r}")
