r"""``[study] kind = "arrangement"``: the order of a measured lot's balls, from a case file.

The case gives the bearing (Z = ``elements``), its operation and ``[analysis]``; ``[study]
lot`` names the CSV of the measured balls (:mod:`runout.study.arrangement_lot`), ``minimise``
what to make smallest. The search (:func:`runout.study.arrangement.optimise_arrangement`)
uses the closed form of seed 001 linearised about the preloaded state (Y.-C. Kim, S.-K. Choi,
K.-C. Yoon, "Vibration analysis of ball bearings with ball geometric imperfections", eq. 10
and 16-17; :mod:`runout.study.arrangement`): every line is a circular whirl whose phasor is a
sum over positions, so any arrangement's lines cost a few multiplications. From the phasors:

* ``lines``: the sum of the p-p of the f_c and k f_b ± f_c lines (the Σ column of seed 001
  Tables 4-8);
* ``line``: one of them;
* ``nrro_pp``: the p-p of their sum along the measuring direction on the case's time grid
  (every such line is non-repeatable);
* ``band``: an Anderon band of those lines (seed 002 eq. 1 and 42).

The chosen order is then run by the case's model with those balls in those positions, and the
same quantity read from the model's record (the lines fitted at their exact frequencies, the
model's own NRRO p-p): the JSON gives the predicted value beside the model's. The baseline is
``random_orders`` random assemblies (Z balls of the lot, in random order): their percentiles
and the fraction of them as good as the chosen order.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.base.errors import CaseError
from runout.case.limits import profile_roots
from runout.case.model import Case, parse_case
from runout.study.arrangement import Objective, line_phasors, optimise_arrangement
from runout.study.arrangement_lot import BallLot, read_lot

__all__ = ["ArrangementStudy", "run_arrangement"]

#: Rows of arrangements whose waveform is built at once by the NRRO objective (memory bound).
_BLOCK = 2048


@dataclass(frozen=True)
class _Lines:
    """The lines the lot's balls make: labels, signed angular frequencies [rad/s]."""

    labels: tuple[str, ...]
    frequencies_hz: NDArray[np.float64]
    angular: NDArray[np.float64]


def _lines(orders: NDArray[np.int64], cage_hz: float, spin_hz: float) -> _Lines:
    labels = ("fc", *(f"{k}fb+fc" for k in orders), *(f"{k}fb-fc" for k in orders))
    wc, wb = 2.0 * math.pi * cage_hz, 2.0 * math.pi * spin_hz
    angular = np.concatenate([[wc], orders * wb + wc, -(orders * wb - wc)])
    return _Lines(labels, np.abs(angular) / (2.0 * math.pi), angular)


class _NrroObjective:
    """p-p along ``direction`` of the lines' sum on the time grid ``t`` (all non-repeatable)."""

    def __init__(self, lines: _Lines, t: NDArray[np.float64], direction: NDArray[np.float64]):
        self.waves = np.exp(1j * np.outer(lines.angular, t))  # (L, n)
        self.weight = complex(direction[0], -direction[1])  # Re(conj(u) q) = u . (x, y)
        # a waveform of n instants per arrangement instead of one sum
        self.cost = t.size / 8.0
        # turning every ball by one position turns the whirl pattern against the direction
        self.rotation_invariant = False

    def __call__(self, phasors: NDArray[np.complex128]) -> NDArray[np.float64]:
        flat = phasors.reshape(-1, phasors.shape[-1])
        out = np.empty(flat.shape[0])
        for start in range(0, flat.shape[0], _BLOCK):
            wave = (self.weight * (flat[start : start + _BLOCK] @ self.waves)).real
            out[start : start + _BLOCK] = np.ptp(wave, axis=-1)
        return out.reshape(phasors.shape[:-1])


class _BandObjective:
    """Anderon value of one band of the lines (seed 002 eq. 1 and 42)."""

    def __init__(self, lines: _Lines, rotation_hz: float, band: str):
        self.orders = lines.frequencies_hz / rotation_hz
        self.band = band

    def __call__(self, phasors: NDArray[np.complex128]) -> NDArray[np.float64]:
        from runout.analysis.spectrum import anderon_bands_from_lines

        # a circular whirl of phasor B is a line of 0-p amplitude |B| along any direction
        return np.asarray(anderon_bands_from_lines(self.orders, np.abs(phasors))[self.band])


def _line_objective(index: int) -> Objective:
    def one(phasors: NDArray[np.complex128]) -> NDArray[np.float64]:
        return np.asarray(2.0 * np.abs(phasors[..., index]))

    return one


@dataclass(frozen=True)
class ArrangementStudy:
    """The chosen order of a lot's balls, its predicted and computed value, the baseline.

    Attributes
    ----------
    document : dict
        The JSON object of ``runout study --json`` (:meth:`to_json`).
    positions : list of dict
        The ball at each position (name, lot row, diameter error [m]), position 1 first.
    random_values : ndarray
        The quantity of every random assembly [m, or Anderon for a band].
    """

    document: dict[str, Any]
    positions: list[dict[str, Any]]
    random_values: NDArray[np.float64]

    def to_json(self) -> dict[str, Any]:
        """The JSON object (docs/studies.md, "Ball arrangement").

        Returns
        -------
        dict
            ``kind``, ``lot``, ``minimise``, ``arrangement``, ``check``, ``random``, ``notes``.
        """
        return self.document


def _refuse_other_inputs(case: Case) -> None:
    """The lot gives the balls; anything else imperfect is outside the closed form."""
    spec, path = case.spec, case.path
    if case.spindle is not None:
        raise CaseError(path, "study.kind", '"arrangement" orders the balls of one bearing')
    if case.analysis.model != "quasi_static_2d":
        raise CaseError(
            path,
            "analysis.model",
            'kind = "arrangement" runs the 2-D quasi-static model (seed 001) its closed form '
            f'linearises: write model = "quasi_static_2d" (got "{case.analysis.model}")',
        )
    if spec.elements is not None and getattr(spec.elements, "diameter_errors", None):
        raise CaseError(
            path, "elements.diameter_errors", "the lot gives the balls' diameter errors: remove it"
        )
    for i, entry in enumerate(spec.waviness, start=1):
        what = (
            "the lot gives the balls' waviness"
            if entry.part == "ball"
            else (
                "an arrangement study orders the lot's balls on otherwise perfect rings; the "
                "closed form does not count ring waviness"
            )
        )
        raise CaseError(path, f"waviness[{i}]", f"{what}: remove it")
    others = (
        ("waviness_spectrum", spec.waviness_spectrum),
        ("profile", spec.profile),
        ("slant", spec.slant),
        ("elements.pitch_errors", getattr(spec.elements, "pitch_errors", None)),
    )
    for key, value in others:
        if value:
            raise CaseError(
                path,
                key,
                "an arrangement study orders the lot's balls on otherwise perfect parts (the "
                "closed form counts only the balls): remove it",
            )


def _variant(case: Case, lot: BallLot, balls: tuple[int, ...]) -> Case:
    """The case with the lot's ``balls`` at positions 1..Z (every order of the lot)."""
    # the keys the file gives, no defaults written back: a default set explicitly would be
    # reported by the model as a key it does not apply
    data = case.spec.model_dump(exclude_unset=True, exclude_none=True)
    data.pop("study", None)
    data["elements"] = {"diameter_errors": [float(lot.diameter_errors[b]) for b in balls]}
    data["waviness"] = [
        {
            "part": "ball",
            "element": position,
            "order": int(order),
            "amplitude": float(lot.amplitudes[b, c]),
            "phase": float(lot.phases[b, c]),
        }
        for position, b in enumerate(balls, start=1)
        for c, order in enumerate(lot.orders)
        if lot.amplitudes[b, c] > 0.0
    ]
    return parse_case(data, case.path, Path(case.path).parent)


def _stats(values: NDArray[np.float64], chosen: float) -> dict[str, Any]:
    pct = np.percentile(values, [5.0, 50.0, 95.0])
    # as good within the round-off of the closed form: 1e-9 relative
    as_good = int(np.count_nonzero(values <= chosen * (1.0 + 1e-9) + 1e-30))
    return {
        "orders": int(values.size),
        "mean": float(values.mean()),
        "std": float(values.std(ddof=1)) if values.size > 1 else 0.0,
        "min": float(values.min()),
        "p5": float(pct[0]),
        "p50": float(pct[1]),
        "p95": float(pct[2]),
        "max": float(values.max()),
        "fraction_as_good": as_good / values.size,
        "improvement": float(values.mean() / chosen) if chosen > 0.0 else None,
    }


def run_arrangement(case: Case) -> ArrangementStudy:
    """Run the case's ``[study] kind = "arrangement"`` (module docstring).

    Parameters
    ----------
    case : Case
        A ball-bearing case with ``[study] kind = "arrangement"``, ``model =
        "quasi_static_2d"`` and no imperfection of its own.

    Returns
    -------
    ArrangementStudy
        The chosen order, its predicted value, the model's value and the random baseline.

    Raises
    ------
    CaseError
        A case the closed form does not describe (another model, other imperfections), a
        lot smaller than Z, a ``line`` of an order the lot does not give.
    InputFileError
        The lot file (:func:`runout.study.arrangement_lot.read_lot`).

    Notes
    -----
    Seed 001 (Kim, Choi, Yoon, "Vibration analysis of ball bearings with ball geometric
    imperfections") eq. 10 and 16-17, linearised; Tables 5-8 are its arrangements.
    """
    from runout.analysis.spectrum import anderon_bands_from_lines, extract_lines
    from runout.models import quasi_static_2d as qs2
    from runout.models._quasi_static import measuring_direction, time_grid
    from runout.runner import run_model

    study = case.study
    assert study is not None and study.kind == "arrangement" and study.lot is not None
    _refuse_other_inputs(case)
    base = Path(case.path).parent
    lot_path = Path(study.lot) if Path(study.lot).is_absolute() else base / study.lot
    lot = read_lot(lot_path, profile_roots(base), study.lot)
    z = int(case.bearing.elements)
    if lot.size < z:
        raise CaseError(
            case.path,
            "study.lot",
            f"{study.lot} holds {lot.size} balls; the bearing takes elements = {z}",
        )
    notes: list[str] = []
    odd = [int(k) for k in lot.orders[~lot.even]]
    if odd:
        notes.append(
            f"waviness orders {odd} of the balls leave the diameter along the contact line "
            "unchanged (seed 002 eq. 26): the search does not count them; the model's check "
            "runs with them"
        )
    if case.operation.radial_load > 0.0:
        notes.append(
            "the closed form assumes every ball equally loaded (axial preload only); with the "
            "radial load the model's value below is the one to trust"
        )
    form, orders = lot.form()
    st = qs2.setup(case)
    kin = st.kinematics
    lines = _lines(orders, float(kin.cage), float(kin.spin))
    an, op = case.analysis, case.operation
    t = time_grid(op.speed, an.revolutions, an.samples)
    direction = measuring_direction(op)
    objective: Objective | None
    unit = "m"
    if study.arrangement_goal == "lines":
        objective = None
    elif study.arrangement_goal == "line":
        assert study.line is not None
        if study.line not in lines.labels:
            raise CaseError(
                case.path,
                "study.line",
                f'"{study.line}": the lot gives no such line (its lines: '
                f"{', '.join(lines.labels)})",
            )
        objective = _line_objective(lines.labels.index(study.line))
    elif study.arrangement_goal == "nrro_pp":
        objective = _NrroObjective(lines, t, direction)
    else:
        from runout.analysis.spectrum import ANDERON_BANDS

        assert study.band is not None
        band = ANDERON_BANDS.bands[ANDERON_BANDS.names.index(study.band)]
        line_orders = lines.frequencies_hz / float(op.speed)
        if not np.any(band.contains(line_orders)):
            shown = ", ".join(f"{o:.3g}" for o in line_orders)
            raise CaseError(
                case.path,
                "study.band",
                f'"{study.band}" holds none of the lot\'s lines (they lie at orders {shown}): '
                "every order would give 0; choose the band they fall in",
            )
        objective = _BandObjective(lines, float(op.speed), study.band)
        unit = "Anderon"
    rng = np.random.default_rng(study.seed)
    found = optimise_arrangement(
        lot.diameter_errors,
        z,
        form=form,
        orders=orders,
        rng=rng,
        random_trials=study.arrangement_trials,
        objective=objective,
    )
    balls = found.balls
    p = np.exp(2j * np.pi * np.arange(z) / z)
    phasors = line_phasors(lot.diameter_errors[list(balls)], form[list(balls)], p)
    predicted = float(found.objective)
    # the model on the case with these balls in these positions
    result = run_model(_variant(case, lot, balls))
    radial = direction[0] * result.displacement[0] + direction[1] * result.displacement[1]
    fit = extract_lines(result.time, radial, lines.frequencies_hz)
    model_pp = 2.0 * np.asarray(fit.amplitude)
    if study.arrangement_goal == "lines":
        computed = float(model_pp.sum())
    elif study.arrangement_goal == "line":
        computed = float(model_pp[lines.labels.index(str(study.line))])
    elif study.arrangement_goal == "nrro_pp":
        nrro = result.runout.nrro_pp_m
        if nrro is None:  # pragma: no cover - the 2-D model separates NRRO for every case
            raise CaseError(case.path, "study.minimise", "the model gives no NRRO p-p here")
        computed = float(nrro)
    else:
        computed = float(
            anderon_bands_from_lines(lines.frequencies_hz / op.speed, 0.5 * model_pp)[
                str(study.band)
            ]
        )
    random_values = np.asarray(found.random_objectives, dtype=np.float64)
    positions = [
        {
            "position": i,
            "ball": lot.names[b],
            "lot_row": b + 1,
            "diameter_error_m": float(lot.diameter_errors[b]),
        }
        for i, b in enumerate(balls, start=1)
    ]
    if computed and abs(computed - predicted) > 0.1 * abs(computed):
        notes.append(
            f"the model's value differs from the closed form's by more than 10 % "
            f"({100 * (computed - predicted) / computed:+.1f} %): at this level the terms the "
            "linear law leaves out (products of the lines, unequal ball loads) matter; the "
            "model's value is the one to trust"
        )
    notes += [n for n in result.notes if n]
    document: dict[str, Any] = {
        "kind": "arrangement",
        "model": case.analysis.model,
        "lot": {
            "file": study.lot,
            "balls": lot.size,
            "elements": z,
            "waviness_orders": [int(k) for k in lot.orders],
        },
        "minimise": {
            "quantity": study.arrangement_goal,
            "line": study.line,
            "band": study.band,
            "unit": unit,
        },
        "arrangement": {
            "balls": [lot.names[b] for b in balls],
            "lot_rows": [b + 1 for b in balls],
            "positions": positions,
            "search": "exact" if found.exact else "local",
            "evaluated": int(found.evaluated),
            "predicted": predicted,
            "lines": [
                {
                    "line": label,
                    "frequency_hz": float(f),
                    "predicted_pp_m": float(2.0 * abs(b)),
                    "model_pp_m": float(m),
                }
                for label, f, b, m in zip(
                    lines.labels, lines.frequencies_hz, phasors, model_pp, strict=True
                )
            ],
        },
        "check": {
            "model": case.analysis.model,
            "value": computed,
            "relative_difference": (computed - predicted) / computed if computed else None,
        },
        "random": _stats(random_values, predicted),
        "notes": notes,
    }
    return ArrangementStudy(document, positions, random_values)
