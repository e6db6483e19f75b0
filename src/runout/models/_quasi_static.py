r"""Pieces shared by the quasi-static models (seed 000 and seed 001): time grid, contact
deviations, predicted spectral lines and their labels, runout figures.

Conventions (both models)
-------------------------
* Angles counter-clockwise from +x [rad] (Tada measures ball angles clockwise; only the sense
  of the orbits changes, not a frequency or an amplitude).
* Ball j (0-based) sits at :math:`\theta_j = 2\pi f_c t + 2\pi j/Z + \epsilon_j` with the signed
  cage frequency :math:`f_c` and the pitch error :math:`\epsilon_j` (seed 000 §2.1, seed 001
  eq. 8).
* A ring turning at :math:`f_r` [Hz] shows its raceway point :math:`\theta - 2\pi f_r t` (ring
  frame) at the fixed-frame angle θ.
* The contact point of ball j in its own frame is at :math:`2\pi f_b t` (spin relative to the
  cage, seed 000 §2.1, seed 001 eq. 9); the diameter deviation along the contact line is
  :meth:`runout.imperfections.Imperfections.evaluate_element_diameters` (seed 002 eq. 26).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from runout.errors import GeometryError
from runout.imperfections import Harmonics, Imperfections
from runout.results import Component, Runout
from runout.spectrum import extract_lines, separate_rro_nrro

__all__ = [
    "ContactDeviations",
    "Kinematics",
    "PredictedLine",
    "contact_deviations",
    "fit_components",
    "predicted_lines",
    "runout_figures",
    "synchronous_grid",
    "time_grid",
]

TWO_PI = 2.0 * math.pi
#: Highest nonlinear order j of Tada's Table 3 for which lines are predicted and fitted.
MAX_LINE_ORDER = 3
#: Components below this fraction of the largest one are dropped from the output.
FLOOR = 1e-7


@dataclass(frozen=True)
class Kinematics:
    """Signed frequencies [Hz] the quasi-static models need.

    Attributes
    ----------
    inner, outer : float
        Ring speeds [Hz], signed (rotating ring positive).
    cage : float
        Signed cage frequency f_c [Hz].
    spin : float
        Ball spin relative to the cage f_b [Hz] (>= 0).
    rotating_ring : {"inner", "outer"}
    n_elements : int
        Z.
    """

    inner: float
    outer: float
    cage: float
    spin: float
    rotating_ring: str
    n_elements: int

    @property
    def rotation(self) -> float:
        """Speed of the rotating ring [Hz]."""
        return self.inner if self.rotating_ring == "inner" else self.outer


def time_grid(speed: float, revolutions: float, samples: int) -> NDArray[np.float64]:
    """``samples`` equally spaced instants over ``revolutions`` turns of the rotating ring [s]."""
    if not (math.isfinite(speed) and speed > 0.0):
        raise GeometryError("operation.speed", f"must be > 0 for a runout analysis, got {speed!r}")
    if not (revolutions > 0.0 and samples >= 16):
        raise GeometryError("analysis", "needs revolutions > 0 and samples >= 16")
    duration = revolutions / speed
    return np.arange(samples, dtype=np.float64) * (duration / samples)


def synchronous_grid(
    speed: float, revolutions: float, samples: int
) -> tuple[NDArray[np.float64], int] | None:
    """A grid with an integer number (>= 2) of revolutions and of samples per revolution.

    Returns ``(time, samples_per_rev)``, or None when the record is shorter than two
    revolutions (then no RRO/NRRO split is possible).
    """
    n_rev = math.floor(revolutions + 1e-9)
    if n_rev < 2:
        return None
    spr = max(16, math.ceil(samples / n_rev))
    t = np.arange(n_rev * spr, dtype=np.float64) / (spr * speed)
    return t, spr


@dataclass(frozen=True)
class ContactDeviations:
    """Deviations seen at each ball's contacts, arrays of shape (n, Z) [m] or [rad].

    Attributes
    ----------
    theta : ndarray
        Ball angular positions θ_j(t) [rad].
    inner : ndarray
        Inner raceway radius deviation at the ball, positive = material added [m].
    outer : ndarray
        Outer raceway radius deviation at the ball, positive = radius larger (material
        removed) [m].
    ball : ndarray
        Ball diameter deviation along the contact line, size errors included [m].
    """

    theta: NDArray[np.float64]
    inner: NDArray[np.float64]
    outer: NDArray[np.float64]
    ball: NDArray[np.float64]


def contact_deviations(
    imperfections: Imperfections, kin: Kinematics, time: NDArray[np.float64]
) -> ContactDeviations:
    """Evaluate the raceway and ball deviations at every ball contact and instant.

    Parameters
    ----------
    imperfections : Imperfections
        Waviness, size and pitch errors (Z elements).
    kin : Kinematics
        Signed ring, cage and spin frequencies [Hz].
    time : ndarray, shape (n,)
        Instants [s].

    Returns
    -------
    ContactDeviations
    """
    z = kin.n_elements
    t = np.asarray(time, dtype=np.float64)
    theta = (
        TWO_PI * kin.cage * t[:, None]
        + TWO_PI * np.arange(z)[None, :] / z
        + np.asarray(imperfections.pitch_errors, dtype=np.float64)[None, :]
    )
    w_in = imperfections.inner.evaluate(theta - TWO_PI * kin.inner * t[:, None])
    w_out = imperfections.outer.evaluate(theta - TWO_PI * kin.outer * t[:, None])
    spin_angle = TWO_PI * kin.spin * t
    w_ball = np.ascontiguousarray(imperfections.evaluate_element_diameters(spin_angle).T)
    return ContactDeviations(theta=theta, inner=w_in, outer=w_out, ball=w_ball)


# --------------------------------------------------------------------------------------------
# predicted lines (Tada Table 2 / 3)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PredictedLine:
    """A line the imperfections should produce: direction set, frequency [Hz], label."""

    directions: str  # "radial" | "axial"
    frequency_hz: float
    label: str


def _ring_lines(part: str, lobes: int, kin: Kinematics, axial: bool) -> list[PredictedLine]:
    """Lines of a single ring harmonic of ``lobes`` waves up to order MAX_LINE_ORDER.

    The l-th power of the harmonic carries l·k lobes; the ball set filters it to the radial
    direction when l·k = nZ ± 1 and to the axial direction when l·k = nZ (seed 000 Tables 2-3,
    eq. 6). The frequency is :math:`|(lk + m) f_c - lk f_{ring}|` with m = -1, 0, +1.
    """
    z = kin.n_elements
    f_ring = kin.inner if part == "inner" else kin.outer
    other = kin.outer if part == "inner" else kin.inner
    sym = "f_i" if part == "inner" else "f_o"
    out: list[PredictedLine] = []
    for order in range(1, MAX_LINE_ORDER + 1):
        lk = order * lobes
        for m in (-1, 0, 1):
            if m == 0 and not axial:
                continue
            if (lk + m) % z:
                continue
            n = (lk + m) // z
            freq = abs((lk + m) * kin.cage - lk * f_ring)
            if order == 1:
                rule = f"nZ{'+1' if m == -1 else '-1' if m == 1 else ''}"
            else:
                rule = f"{order}·{lobes}=nZ{'+1' if m == -1 else '-1' if m == 1 else ''}"
            if f_ring == 0.0:
                formula = f"n {sym}"
            elif other == 0.0 and m != 0:
                formula = f"n {sym} {'+' if m == -1 else '-'} f_r"
            elif other == 0.0:
                formula = f"n {sym}"
            else:
                formula = f"|(lk{m:+d}) f_c - lk f_ring|, l={order}"
            kind = "" if order == 1 else f", order {order}"
            label = f"{part} {lobes} lobes ({rule}, n={n}{kind}): {formula}"
            out.append(PredictedLine("axial" if m == 0 else "radial", freq, label))
    return out


def _element_lines(index: int, h: Harmonics, kin: Kinematics, axial: bool) -> list[PredictedLine]:
    """Lines of ball ``index``'s diameter deviation (seed 000 Table 2, ball rows)."""
    out: list[PredictedLine] = []
    fc, fb = abs(kin.cage), kin.spin
    for k, a in zip(h.orders, h.amplitudes, strict=True):
        if a == 0.0:
            continue
        k = int(k)
        if k == 0:
            out.append(PredictedLine("radial", fc, f"ball {index + 1} size error: f_c"))
            continue
        for order in range(1, MAX_LINE_ORDER + 1):
            kk = order * k
            kind = "" if order == 1 else f", order {order}"
            out.append(
                PredictedLine(
                    "radial", kk * fb + fc, f"ball {index + 1} {k} lobes (2n{kind}): 2n f_b + f_c"
                )
            )
            out.append(
                PredictedLine(
                    "radial",
                    abs(kk * fb - fc),
                    f"ball {index + 1} {k} lobes (2n{kind}): 2n f_b - f_c",
                )
            )
            if axial:
                out.append(
                    PredictedLine(
                        "axial", kk * fb, f"ball {index + 1} {k} lobes (2n{kind}): 2n f_b"
                    )
                )
    return out


def predicted_lines(
    imperfections: Imperfections, kin: Kinematics, *, axial: bool = True
) -> list[PredictedLine]:
    """Every line the single imperfections produce (first to third order), unmerged.

    Notes
    -----
    Sum and difference lines of two ring wavinesses (seed 000 eq. 7) are not predicted; they
    stay in the time history and in the runout figures but are not fitted as components.
    """
    out: list[PredictedLine] = []
    for part, h in (("inner", imperfections.inner), ("outer", imperfections.outer)):
        for k in h.orders:
            if int(k) > 0:
                out += _ring_lines(part, int(k), kin, axial)
    for j in range(kin.n_elements):
        out += _element_lines(j, imperfections.element_diameter_deviation(j), kin, axial)
    if np.any(np.asarray(imperfections.pitch_errors) != 0.0):
        out.append(PredictedLine("radial", abs(kin.cage), "pitch errors: f_c"))
    return out


def _merge(
    lines: list[PredictedLine], kind: str, f_min: float, f_max: float, tol: float
) -> list[tuple[float, str]]:
    chosen = sorted(
        (ln for ln in lines if ln.directions == kind and f_min < ln.frequency_hz < f_max),
        key=lambda ln: ln.frequency_hz,
    )
    merged: list[tuple[float, list[str]]] = []
    for ln in chosen:
        if merged and ln.frequency_hz - merged[-1][0] <= tol:
            if ln.label not in merged[-1][1]:
                merged[-1][1].append(ln.label)
        else:
            merged.append((ln.frequency_hz, [ln.label]))
    return [(f, "; ".join(labels)) for f, labels in merged]


def fit_components(
    time: NDArray[np.float64],
    displacement: NDArray[np.float64],
    lines: list[PredictedLine],
    rotation_hz: float,
    *,
    directions: tuple[str, ...] = ("x", "y", "z"),
) -> tuple[Component, ...]:
    """Fit the predicted lines in each direction (leakage-free least squares).

    Radial lines are fitted in x and y, axial lines in z (:func:`runout.spectrum.extract_lines`).
    Lines closer than a twentieth of the record's resolution are merged (labels joined); lines
    below ``FLOOR`` times the largest are dropped.

    Returns
    -------
    tuple of Component
        Largest first; p-p = 2 × fitted amplitude.
    """
    n = time.size
    duration = n * (time[1] - time[0])
    f_max = 0.5 * n / duration * 0.999
    f_min = 0.5 / duration
    tol = 0.05 / duration
    comps: list[Component] = []
    for axis, name in enumerate(("x", "y", "z")):
        if name not in directions:
            continue
        kind = "axial" if name == "z" else "radial"
        merged = _merge(lines, kind, f_min, f_max, tol)
        if not merged:
            continue
        freqs = np.array([f for f, _ in merged])
        fit = extract_lines(time, displacement[axis], freqs)
        for (f, label), amp, ph in zip(merged, fit.amplitude, fit.phase, strict=True):
            order = f / rotation_hz
            comps.append(
                Component(
                    direction=name,
                    frequency_hz=float(f),
                    order=float(order),
                    pp_m=float(2.0 * amp),
                    label=label,
                    phase_rad=float(ph),
                    repeatable=bool(abs(order - round(order)) < 1e-9),
                )
            )
    if comps:
        # drop lines at the solver's round-off floor (predicted but absent)
        floor = FLOOR * max(c.pp_m for c in comps)
        comps = [c for c in comps if c.pp_m > floor]
    comps.sort(key=lambda c: -c.pp_m)
    return tuple(comps)


def runout_figures(
    displacement: NDArray[np.float64],
    direction: NDArray[np.float64],
    synchronous: tuple[NDArray[np.float64], int] | None,
) -> Runout:
    """Runout p-p figures [m].

    Parameters
    ----------
    displacement : ndarray, shape (3, n)
        x, y, z history [m].
    direction : ndarray, shape (2,)
        Unit radial measuring direction.
    synchronous : (radial signal, samples_per_rev) or None
        Radial signal on a grid with an integer number of revolutions; RRO is its synchronous
        average, NRRO the rest (:func:`runout.spectrum.separate_rro_nrro`). None → RRO = radial
        p-p and NRRO = 0 are not claimed: both are reported as 0.
    """
    radial = direction[0] * displacement[0] + direction[1] * displacement[1]
    rro = nrro = 0.0
    if synchronous is not None:
        sep = separate_rro_nrro(synchronous[0], synchronous[1])
        rro, nrro = float(sep.rro_pp), float(sep.nrro_pp)
    return Runout(
        radial_pp_m=float(np.ptp(radial)),
        axial_pp_m=float(np.ptp(displacement[2])),
        rro_pp_m=rro,
        nrro_pp_m=nrro,
    )


def unloaded_note(unloaded: NDArray[np.int64], n_elements: int) -> str:
    """Readable note on balls that lost contact (count per instant)."""
    worst = int(unloaded.max()) if unloaded.size else 0
    if worst == 0:
        return f"all {n_elements} balls stayed loaded at every instant"
    instants = int(np.count_nonzero(unloaded))
    return (
        f"balls lost contact (no load) at {instants} of {unloaded.size} instants, "
        f"at most {worst} of {n_elements} at once"
    )


SolveFn = Callable[[NDArray[np.float64]], tuple[NDArray[np.float64], NDArray[np.int64]]]
