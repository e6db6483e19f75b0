"""The ``[analysis]`` outputs a run adds to a model's result: band values (Anderon, ISO 15242-1)
and the verdict against a limit, computed from the result's lines.

Seed 002 gives the Anderon bands (eq. 1 and eq. 42, the velocity density of the radial
displacement); ISO 15242-1 the L, M, H bands of rms velocity. :func:`apply_analysis` is what
:func:`runout.runner.run_model` calls after the model.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from runout.analysis.result_details import Iso15242, Iso15242Band, Verdict
from runout.analysis.results import RunResult
from runout.case.model import Case

__all__ = ["anderon_json", "apply_analysis", "iso15242_of", "measured_lines", "verdict_of"]


# -------------------------------------------------------------------------------------------
# the [analysis] outputs computed from a model's result
# -------------------------------------------------------------------------------------------
def measured_lines(result: RunResult) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Radial lines along the measuring direction: frequencies [Hz], 0-p amplitudes [m].

    The x and y lines of one frequency are combined as phasors,
    ``|u_x X + u_y Y|`` with ``X = (pp_x / 2) exp(i φ_x)``: the line a probe along the
    measuring direction ``u`` would see. Axial (z) lines are left out.

    Parameters
    ----------
    result : RunResult
        A model's result: its ``components`` (``pp_m`` [m], ``phase_rad`` [rad],
        ``frequency_hz`` [Hz]) and ``measuring_direction`` (unit vector [-]).

    Returns
    -------
    frequencies : ndarray
        Line frequencies [Hz].
    amplitudes : ndarray
        Zero-to-peak amplitudes along the measuring direction [m].
    """
    u = result.measuring_direction
    phasors: dict[float, complex] = {}
    for c in result.components:
        if c.direction not in ("x", "y"):
            continue
        weight = float(u[0] if c.direction == "x" else u[1])
        phasor = 0.5 * c.pp_m * complex(math.cos(c.phase_rad), math.sin(c.phase_rad))
        phasors[c.frequency_hz] = phasors.get(c.frequency_hz, 0j) + weight * phasor
    freqs = np.array(list(phasors), dtype=np.float64)
    amps = np.array([abs(p) for p in phasors.values()], dtype=np.float64)
    return freqs, amps


def _direction_name(u: NDArray[np.float64]) -> str:
    """``"x"`` or ``"y"`` for a measuring direction along an axis, else ``"measuring"``."""
    # a direction given as an angle (-90 deg) leaves cos/sin round-off on the other axis
    if abs(u[1]) < 1e-12:
        return "x"
    if abs(u[0]) < 1e-12:
        return "y"
    return "measuring"


def iso15242_of(result: RunResult) -> Iso15242:
    """RMS velocity per ISO 15242-1 band from the lines (JSON ``iso15242``).

    Bands L, M, H with the edges of 1800 rpm scaled to the rotating ring's speed
    (:func:`runout.analysis.spectrum.iso15242_band_set`), from the radial lines along the measuring
    direction (:func:`measured_lines`).

    Parameters
    ----------
    result : RunResult
        A model's result with a rotating ring (``frequencies.rotation`` [Hz] > 0).

    Returns
    -------
    Iso15242
        Band edges [Hz] and rms velocity per band [um/s], the speed [rpm] and the measuring
        direction.
    """
    from runout.analysis.spectrum import iso15242_band_set, iso15242_bands_from_lines

    rotation = float(result.frequencies.rotation)
    bands = iso15242_band_set(rotation)
    freqs, amps = measured_lines(result)
    values = iso15242_bands_from_lines(freqs, amps, bands).as_dict()
    u = result.measuring_direction
    return Iso15242(
        unit="um/s",
        speed_rpm=rotation * 60.0,
        direction=_direction_name(u),
        measuring_direction=(float(u[0]), float(u[1])),
        bands={b.name[0]: Iso15242Band(b.low, b.high, values[b.name]) for b in bands.bands},
    )


def anderon_json(result: RunResult) -> dict[str, float]:
    """Anderon band values from the lines along the measuring direction, in orders.

    Parameters
    ----------
    result : RunResult
        A model's result with a rotating ring (``frequencies.rotation`` [Hz] > 0).

    Returns
    -------
    dict of str to float
        Band name -> Anderon value [Anderon] (seed 002 eq. 1 and 42).

    Notes
    -----
    Seed 002 (Anderon calculation model) eq. 1 and 42, via
    :func:`runout.analysis.spectrum.anderon_bands_from_lines`.
    """
    from runout.analysis.spectrum import anderon_bands_from_lines

    freqs, amps = measured_lines(result)
    orders = freqs / float(result.frequencies.rotation)
    return anderon_bands_from_lines(orders, amps).as_dict()


def verdict_of(result: RunResult, limit: float, quantity: str) -> Verdict:
    """``quantity`` of ``result`` against ``limit`` (JSON ``verdict``).

    Parameters
    ----------
    result : RunResult
        The result judged (its ``runout`` figures [m] or ``iso15242`` bands [um/s]).
    limit : float
        [m] for a runout p-p, [m/s] for a band (``iso15242.L`` ...).
    quantity : str
        ``radial_pp``, ``rro_pp``, ``nrro_pp``, ``axial_pp`` or ``iso15242.<band>``.

    Returns
    -------
    Verdict
        Limit and value in [m] for a runout p-p, in [um/s] for a band (the limit converted
        from [m/s]), and whether the value is within the limit.

    Raises
    ------
    ValueError
        A band quantity for a result without ISO 15242 band values.
    """
    if quantity.startswith("iso15242."):
        if result.iso15242 is None:
            raise ValueError(f"{quantity}: the result has no ISO 15242 band values")
        value = float(result.iso15242.bands[quantity.split(".", 1)[1]].rms_um_per_s)
        limit_um = limit * 1e6
        return Verdict(quantity, limit_um, value, bool(value <= limit_um), "um/s")
    figure = getattr(result.runout, f"{quantity}_m")
    if figure is None:  # the case conventions refuse such a limit first
        raise ValueError(f"{quantity}: the {result.model} model does not compute it")
    value_m = float(figure)
    return Verdict(quantity, limit, value_m, bool(value_m <= limit), "m")


def apply_analysis(result: RunResult, case: Case) -> RunResult:
    """``result`` with what the case's ``[analysis]`` asks beyond the model: bands, verdict.

    ``bands = "iso15242"`` adds the ``iso15242`` JSON, ``bands = "anderon"`` the Anderon
    values from the lines (the linear model keeps its own, from its exact x lines as seed 002
    measured), ``limit`` the ``verdict``; the bearing's element type names the passage
    frequencies. Idempotent: applying it twice gives the same result.

    Parameters
    ----------
    result : RunResult
        The model's result.
    case : Case
        The case run; its ``[analysis]`` table (``bands``, ``limit`` [m] or [m/s],
        ``limit_on``) and its bearing.

    Returns
    -------
    RunResult
        A copy with ``iso15242``, ``anderon``, ``verdict`` and ``element`` set.

    Raises
    ------
    CaseError
        A model without a record (one instant) given bands or a limit, or a zero speed with
        bands (band edges scale with the speed).
    """
    from runout.base.errors import CaseError
    from runout.geometry.bearing import RollerBearing

    analysis = case.analysis
    bands = getattr(analysis, "bands", None)
    limit = getattr(analysis, "limit", None)
    limit_on = getattr(analysis, "limit_on", "radial_pp")
    element = "roller" if isinstance(case.bearing, RollerBearing) else "ball"
    iso15242 = result.iso15242
    verdict = result.verdict
    anderon = result.anderon
    if (bands is not None or limit is not None) and result.time.size < 2:
        key = "analysis.bands" if bands is not None else "analysis.limit"
        raise CaseError(
            case.path, key, f"the {result.model} model gives no record (one instant): no lines"
        )
    if bands is not None and not result.frequencies.rotation > 0.0:
        raise CaseError(case.path, "analysis.bands", "band edges need a rotating ring (speed > 0)")
    if bands == "iso15242":
        iso15242 = iso15242_of(result)
    elif bands == "anderon" and result.model != "linear":
        anderon = anderon_json(result)
    if limit is not None:
        probe = replace(result, iso15242=iso15242)
        verdict = verdict_of(probe, float(limit), limit_on)
        tolerance_class = getattr(analysis, "limit_class", None)
        if tolerance_class is not None:  # an ISO 492 class: its name, bore and source
            verdict = replace(verdict, tolerance_class=dict(tolerance_class))
        if verdict.passed:
            _refuse_unseen_pass(probe, case.path, limit_on)
    return replace(result, iso15242=iso15242, verdict=verdict, anderon=anderon, element=element)


def _refuse_unseen_pass(result: RunResult, path: str, quantity: str) -> None:
    """Refuse a PASS the record cannot support: predicted lines it does not resolve.

    A line above the Nyquist frequency or below 1/T is left out of the fit (the notes say
    which): the figures and bands are then lower bounds, enough to fail a limit but not to
    pass it. A band also needs the record to reach the band's upper edge.
    """
    from runout.analysis.decompose import NOT_FITTED, NOT_FITTED_NYQUIST
    from runout.base.errors import CaseError

    unseen = [n for n in result.notes if NOT_FITTED in n]
    if quantity.startswith("iso15242.") and result.time.size >= 2 and result.iso15242 is not None:
        band = result.iso15242.bands[quantity.split(".", 1)[1]]
        nyquist = 0.5 / float(result.time[1] - result.time[0])
        if band.high_hz > nyquist:
            unseen.append(f"the band reaches {band.high_hz:.6g} Hz, the record {nyquist:.6g} Hz")
    if not unseen:
        return
    high = any(NOT_FITTED_NYQUIST in n or "the band reaches" in n for n in unseen)
    key = "analysis.samples" if high else "analysis.revolutions"
    what = "more samples" if high else "more revolutions"
    raise CaseError(
        path,
        key,
        f"the record does not resolve every predicted line ({unseen[0]}), so {quantity} "
        f"within the limit cannot be shown (it could only fail); give {what}",
    )
