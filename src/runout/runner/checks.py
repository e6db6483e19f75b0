"""Model-level validation: what ``runout check`` and every run do before any work.

:func:`runout.case.model.load_case` checks what a case file says on its own (schema, geometry that
cannot exist, sizes within the budget of :mod:`runout.case.limits`). :func:`validate` adds what
depends on the model and on the physics of the loaded bearing:

* the model's own input checks (its ``setup``: a ball bearing, a preload, a speed, a load that
  holds the rotor, a contact angle the fixed-angle model can keep, ...);
* the dynamic model's step plan against the budget (it needs the natural frequencies);
* Hertz validity of the most loaded element (:func:`runout.geometry.contact.ball_load_validity`):
  a contact that cannot be elastic is an error, one beyond the ISO 76 static limit a warning.

Errors are :class:`runout.base.errors.CaseError` naming the file and the key; warnings are returned
as one-line notes (``"operation.axial_load: ..."``) for the result's notes or ``runout check``'s
single ``warning:`` line. ``runout check`` calls it, and so does
:func:`runout.runner.run_model`, so a case ``check`` calls valid does not fail later on input.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from runout.base.errors import CaseError, GeometryError, NumericalError
from runout.geometry.bearing import BallBearing, RollerBearing

__all__ = ["as_case_error", "case_key", "validate"]

#: Keys the models' own checks use, and the case key each stands for.
_MODEL_KEYS = {
    "contact_angle": "bearing.contact_angle",
    "analysis": "analysis.samples",
    "alpha": "analysis.revolutions",
    "preload": "operation.axial_load",
    "imperfections.elements": "elements",
    "elements": "bearing.elements",
    "element_diameter": "bearing.element_diameter",
    "n_elements": "bearing.elements",
    "ball_diameter": "bearing.element_diameter",
    "roller_diameter": "bearing.element_diameter",
    "radial_clearance": "bearing.radial_clearance",
}


def case_key(case: Any, key: str) -> str:
    """The case key behind a model's key (``"inner raceway"`` -> ``"waviness[2].amplitude"``).

    The rigid roller model names parts (``"inner raceway"``, ``"roller 3"``): they map to the
    first waviness, spectrum or profile entry of that part.

    Parameters
    ----------
    case : Case
        The loaded case (its ``spec`` tables are searched for a part's entry).
    key : str
        Key of a model's check: a parameter name (``"contact_angle"``) or a part
        (``"inner raceway"``, ``"roller 3"``).

    Returns
    -------
    str
        The case key (``"bearing.contact_angle"``, ``"waviness[2].amplitude"``); ``key``
        itself when it names neither, ``"waviness"`` for a part with no entry.
    """
    if key in _MODEL_KEYS:
        return _MODEL_KEYS[key]
    part, element = None, None
    if key in ("inner raceway", "outer raceway"):
        part = key.split()[0]
    elif key.startswith(("roller ", "ball ")) and key.split()[-1].isdigit():
        part, element = "element", int(key.split()[-1])
    if part is None:
        return key
    spec = case.spec
    for table in ("waviness", "waviness_spectrum", "profile"):
        for i, entry in enumerate(getattr(spec, table), start=1):
            same = entry.part == part or (part == "element" and entry.part in ("ball", "roller"))
            if same and (element is None or entry.element in (None, element)):
                field = "file" if table == "profile" else "amplitude"
                if table != "profile" and entry.amplitude is None:
                    field = "peak_to_peak"
                return f"{table}[{i}].{field}"
    return "waviness"


def as_case_error(case: Any, exc: GeometryError) -> CaseError:
    """A model's :class:`GeometryError` as a :class:`CaseError` naming the case file.

    Parameters
    ----------
    case : Case
        The case the model ran on (its ``path`` and tables).
    exc : GeometryError
        The model's error; its key is mapped by :func:`case_key`.

    Returns
    -------
    CaseError
        The same message, naming the case file and the case key.
    """
    return CaseError(case.path, case_key(case, exc.key), exc.message)


def _element_loads(case: Any, model: str) -> list[tuple[str, float, str]]:
    """(key, load [N], words) of the most loaded element under each load of the case.

    Rough and on the safe side (a rigid-ring load distribution): Q = F_a / (Z sin α) for the
    axial load, Stribeck's 5 F_r / (Z cos α) for the radial load (with the unbalance force of
    the dynamic model), 4 M / (Z d_m sin α) for a moment.
    """
    from runout.geometry.loading import operating_contact_angle

    bearing, op = case.bearing, case.operation
    z = bearing.elements
    try:
        alpha, _ = operating_contact_angle(bearing, op)
    except (GeometryError, NumericalError):
        return []
    s, c = math.sin(alpha), math.cos(alpha)
    radial = op.radial_load
    radial_key = "operation.radial_load"
    dyn = getattr(case, "dynamics", None)
    if model == "dynamic" and dyn is not None and dyn.unbalance > 0.0:
        unbalance = dyn.unbalance * (2.0 * math.pi * op.inner_speed) ** 2
        if unbalance > radial:
            radial_key = "dynamics.unbalance"
        radial += unbalance
    loads = []
    if op.axial_load > 0.0 and s > 0.01:
        loads.append(("operation.axial_load", op.axial_load / (z * s)))
    if radial > 0.0:
        loads.append((radial_key, 5.0 * radial / (z * max(c, 0.01))))
    if op.moment_load > 0.0 and s > 0.01:
        moment = 4.0 * op.moment_load / (z * bearing.pitch_diameter * s)
        loads.append(("operation.moment_load", moment))
    if not loads:
        return []
    total = sum(q for _, q in loads)
    key = max(loads, key=lambda kq: kq[1])[0]
    word = "ball" if isinstance(bearing, BallBearing) else "roller"
    return [(key, total, f"the most loaded {word} carries about {total:.4g} N")]


def _interference_loads(case: Any) -> list[tuple[str, float, str]]:
    """(key, load [N], words) of balls larger than the room between the raceways."""
    bearing = case.bearing
    if not isinstance(bearing, BallBearing):
        return []
    from runout.geometry.contact import ball_race_contacts

    errors = np.asarray(case.imperfections.diameter_errors, dtype=np.float64)
    interference = errors - bearing.radial_clearance
    if not (interference > 0.0).any():
        return []
    kn = ball_race_contacts(bearing, 0.0).combined_stiffness
    j = int(np.argmax(interference))
    load = kn * float(interference[j]) ** 1.5
    return [
        (
            f"elements.diameter_errors[{j + 1}]",
            load,
            f"ball {j + 1} is {interference[j] * 1e6:.4g} um larger than the room between "
            f"the raceways, pressed in with about {load:.4g} N",
        )
    ]


def hertz_findings(case: Any, model: str) -> list[Any]:
    """Hertz validity findings of the most loaded element (and of oversized balls).

    Rough, safe-side element loads [N] from the case's axial, radial (with the dynamic model's
    unbalance force) and moment loads, judged by
    :func:`runout.geometry.contact.ball_load_validity` or
    :func:`runout.geometry.contact.roller_load_validity`.

    Parameters
    ----------
    case : Case
        The loaded case (bearing, operation, imperfections; spindle for the spindle model).
    model : str
        Model id (``"dynamic"`` adds the unbalance force, ``"spindle"`` checks each bearing
        of the spindle).

    Returns
    -------
    list of HertzFinding
        Warnings (beyond the ISO 76 static limit) and errors (no elastic contact); empty
        when every contact is valid or the contact angle cannot be found.
    """
    from runout.geometry.contact import ball_load_validity, roller_load_validity
    from runout.geometry.loading import operating_contact_angle

    bearing = case.bearing
    found: list[Any] = []
    if model == "spindle" and getattr(case, "spindle", None) is not None:
        return _spindle_findings(case)
    if isinstance(bearing, BallBearing):
        try:
            alpha, _ = operating_contact_angle(bearing, case.operation)
        except (GeometryError, NumericalError):
            return []
        for key, load, what in _element_loads(case, model):
            found += ball_load_validity(bearing, load, alpha, key, what)
        for key, load, what in _interference_loads(case):
            found += ball_load_validity(bearing, load, 0.0, key, what)
    elif isinstance(bearing, RollerBearing):
        for key, load, what in _element_loads(case, model):
            found += roller_load_validity(bearing, load, key, what)
    return found


def _spindle_findings(case: Any) -> list[Any]:
    """Hertz validity of each spindle bearing's most loaded ball at the shaft's static position
    under the preload and the loads (no imperfections)."""
    from runout.geometry.contact import ball_load_validity
    from runout.models import spindle

    try:
        st = spindle.setup(case.spindle, case.operation)
        q, _ = spindle.static_stiffness(st)
    except (GeometryError, NumericalError):
        return []  # the model's set-up names the key
    loads = spindle.ball_loads(st, q)
    found: list[Any] = []
    start = 0
    op = case.operation
    for index, (b, sb) in enumerate(zip(case.spindle.bearings, st.bearings, strict=True), 1):
        z = sb.kinematics.n_elements
        worst = float(loads[start : start + z].max())
        start += z
        if not isinstance(b.bearing, BallBearing):
            continue
        key = (
            "spindle.preload"
            if case.spindle.preload is not None
            else ("spindle.preload_displacement")
        )
        if op.radial_load > 0.0 or op.moment_load > 0.0 or op.axial_load > 0.0:
            key = f"bearings[{index}]"
        what = f"the most loaded ball of bearing {b.name} carries {worst:.4g} N"
        found += ball_load_validity(b.bearing, worst, sb.contact_angle, key, what)
    return found


def _model_setup(case: Any, model: str) -> None:
    """Run the model's own input checks (its set-up), without solving anything."""
    an, op = case.analysis, case.operation
    if model == "linear":
        from runout.geometry.loading import operating_contact_angle
        from runout.models import linear

        alpha, _ = operating_contact_angle(case.bearing, op)
        linear.rates(case.bearing, op, alpha)
        linear.variant_gains(alpha, an.linear_variant)
    elif model in ("quasi_static_2d", "quasi_static_3d"):
        import importlib

        from runout.models._quasi_static import time_grid

        module = importlib.import_module(f"runout.models.{model}")
        module.setup(case)
        time_grid(op.speed, an.revolutions, an.samples)
    elif model == "spindle" and getattr(case, "spindle", None) is not None:
        from runout.models import spindle
        from runout.models._quasi_static import time_grid

        spindle.setup(case.spindle, op)
        time_grid(op.speed, an.revolutions, an.samples)
    elif model == "roller_constraint":
        from runout.models import roller_constraint

        roller_constraint.geometry_from(case.bearing, case.imperfections, op)
        roller_constraint.rotation_angles(an.revolutions, 2)
    elif model == "equilibrium":
        from runout.models import equilibrium

        equilibrium.setup(case)
    elif model == "dynamic":
        from runout.case.limits import case_budget
        from runout.models import dynamic

        st = dynamic.setup(case)
        revs, spr, _ = dynamic._analysis_grid(case)
        q = dynamic.static_equilibrium(st, np.array([0.0]))[0]
        fn = dynamic.linearised_natural_frequencies(st, q)
        dyn = case.dynamics
        dynamic.plan_integration(
            st, op.speed, revs, spr, fn, time_step=dyn.time_step, limits=case_budget(case)
        )


def validate(case: Any, model: str | None = None, *, strict: bool = True) -> tuple[str, ...]:
    """Check a loaded case for ``model`` (default its ``[analysis] model``) before any work.

    Parameters
    ----------
    case : Case
        The loaded case.
    model : str or None
        Model id; default ``case.analysis.model``.
    strict : bool
        False when the case does not name its model: the default model's own refusals are
        then returned as a warning, not raised (the physics and the budget still are).

    Returns
    -------
    tuple of str
        Warnings, one line each, starting with the key (``"operation.axial_load: ..."``).

    Raises
    ------
    CaseError
        Naming the file and the key: a model set-up that refuses the case, a step plan
        beyond the budget, or a contact that cannot be elastic.
    """
    model = model or case.analysis.model
    notes: list[str] = []
    try:
        for finding in hertz_findings(case, model):
            if finding.severity == "error":
                raise CaseError(case.path, finding.key, finding.message)
            notes.append(f"{finding.key}: {finding.message}")
    except GeometryError as exc:
        raise as_case_error(case, exc) from None
    try:
        _model_setup(case, model)
    except GeometryError as exc:
        from runout.case.limits import LimitError

        if strict or isinstance(exc, LimitError):
            raise as_case_error(case, exc) from None
        notes.append(
            f"analysis.model: not given, and the default {model} model would refuse the case: "
            f"{case_key(case, exc.key)}: {exc.message}"
        )
    except NumericalError as exc:
        # the static start of the dynamic model did not converge: the run would fail there
        if strict:
            raise CaseError(case.path, "", f"the {model} model cannot start: {exc}") from None
        notes.append(f"analysis.model: the default {model} model cannot start: {exc}")
    return tuple(notes)
