"""Running a validated case: the model it names, its input checks, its ``[analysis]`` outputs.

:func:`run_model` is what ``runout run``, the Python :func:`runout.run` and every study sample
call: one meaning per key first (:mod:`runout.case.conventions`), the model's input checks
and budget (:mod:`runout.runner.checks`), the model (:mod:`runout.models`), then the bands
and verdict the case asks for (:mod:`runout.runner.analysis`).
"""

from __future__ import annotations

import dataclasses
import importlib

from runout.analysis.results import RunResult
from runout.base.errors import GeometryError, ModelNotAvailableError
from runout.case.conventions import enforce
from runout.case.model import Case
from runout.models import MODEL_MODULES, available_models
from runout.runner.analysis import apply_analysis
from runout.runner.checks import as_case_error, validate

__all__ = ["run_model"]


def run_model(case: Case) -> RunResult:
    """Run the model named in ``case.analysis.model``.

    The case is first checked against :mod:`runout.case.conventions`: a key the model refuses ends
    the run with a :class:`runout.base.errors.CaseError`; the keys it does not apply are added to
    the result's notes.

    Parameters
    ----------
    case : Case
        A loaded case (:func:`runout.case.model.load_case`); SI values inside.

    Returns
    -------
    RunResult
        The model's result with the case's ``[analysis]`` outputs (bands, verdict) and the
        notes of the checks and conventions.

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
    # One meaning per key: refuse what this model cannot honour, note what it does not apply.
    notes = enforce(case, model)
    # the model's set-up, the budget and the physics, as `runout check` runs them
    warnings = validate(case, model)
    module = importlib.import_module(MODEL_MODULES[model])
    try:
        result = module.run(case)
    except GeometryError as exc:  # an input check inside the model: name the file and key
        raise as_case_error(case, exc) from None
    # [bearing] designation: where the values come from, and each catalogue value replaced
    catalogue_notes = tuple(n for source in case.bearing_sources for n in source.notes)
    if notes or warnings or catalogue_notes:
        result = dataclasses.replace(
            result, notes=(*result.notes, *catalogue_notes, *warnings, *notes)
        )
    if case.bearing_sources:
        result = dataclasses.replace(result, bearing_source=case.bearing_source())
    # the case's [analysis] outputs beyond the model: bands, verdict, passage names
    return apply_analysis(result, case)
