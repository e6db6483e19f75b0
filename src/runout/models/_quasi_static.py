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
* The contact point of ball j in its own frame is at :math:`\pm 2\pi f_b t` (spin relative to
  the cage, seed 000 §2.1, seed 001 eq. 9; the sign is :attr:`Kinematics.contact_rate`'s); the
  diameter deviation along the contact line is
  :meth:`runout.imperfections.Imperfections.evaluate_element_diameters` (seed 002 eq. 26).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.errors import GeometryError
from runout.imperfections import Harmonics, Imperfections
from runout.kinematics import bearing_frequencies
from runout.results import Component, Runout, RunResult
from runout.spectrum import extract_lines, separate_rro_nrro

__all__ = [
    "ContactDeviations",
    "Kinematics",
    "PredictedLine",
    "RunoutSplit",
    "contact_deviations",
    "fit_components",
    "predicted_lines",
    "runout_figures",
    "split_runout",
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

    @property
    def contact_rate(self) -> float:
        r"""Signed rate of the contact-point angle in each element's own frame [Hz].

        Rolling without slip, an element spins against the inner ring's motion relative to the
        cage (:mod:`runout.kinematics`): seen from the cage, its contact point then runs over
        its surface at :math:`+f_b` when the inner ring turns faster than the outer (ball inside
        a stationary outer race, spinning against its orbit) and at :math:`-f_b` when the outer
        ring is the faster (ball rolling on a stationary inner race, spinning with its orbit).
        Seed 002 eq. 6 is the first case; the linear model uses the same signed rate.
        """
        return self.spin if self.inner >= self.outer else -self.spin


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
    spin_angle = TWO_PI * kin.contact_rate * t
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


#: Ring harmonics (largest first, per ring) paired for seed 000 eq. 7 sum/difference lines.
MAX_PAIRED_HARMONICS = 24


def _largest(h: Harmonics, count: int) -> list[int]:
    keep = [(float(a), int(k)) for k, a in zip(h.orders, h.amplitudes, strict=True) if k > 0]
    keep = [ka for ka in keep if ka[0] > 0.0]
    keep.sort(reverse=True)
    return sorted(k for _, k in keep[:count])


def _pair_lines(imperfections: Imperfections, kin: Kinematics, axial: bool) -> list[PredictedLine]:
    r"""Second-order lines of two ring harmonics (seed 000 §2.2.2, eq. 7).

    The product of harmonic :math:`k_1` of part 1 (ring speed :math:`f_1`) and :math:`k_2` of
    part 2 carries :math:`L = k_1 \pm k_2` lobes turning at :math:`k_1 f_1 \pm k_2 f_2`; the
    ball set passes it to the radial direction when :math:`L + m = nZ` with m = ∓1 and to the
    axial direction when m = 0, at :math:`|(L + m) f_c - (k_1 f_1 \pm k_2 f_2)|`. For an inner
    waviness :math:`W_{ni}` and an outer :math:`W_{no}` with the outer ring rotating this is
    Tada's eq. 7, :math:`|W_{no} f_r \mp n f_i|` (f_i = Z f_c). Pairs of two harmonics of the
    same ring follow the same rule.
    """
    z = kin.n_elements
    parts = [
        ("inner", k, kin.inner) for k in _largest(imperfections.inner, MAX_PAIRED_HARMONICS)
    ] + [("outer", k, kin.outer) for k in _largest(imperfections.outer, MAX_PAIRED_HARMONICS)]
    out: list[PredictedLine] = []
    for a in range(len(parts)):
        for b in range(a + 1, len(parts)):
            (p1, k1, f1), (p2, k2, f2) = parts[a], parts[b]
            for sign in (1, -1):
                lobes = k1 + sign * k2
                turn = k1 * f1 + sign * k2 * f2
                if lobes < 0:
                    lobes, turn = -lobes, -turn
                op = "+" if sign == 1 else "-"
                for m in (-1, 0, 1):
                    if (m == 0 and not axial) or (lobes + m) % z or (lobes == 0 and m != 0):
                        continue
                    n = (lobes + m) // z
                    freq = abs((lobes + m) * kin.cage - turn)
                    rule = f"nZ{'+1' if m == -1 else '-1' if m == 1 else ''}"
                    label = (
                        f"{p1} {k1} {op} {p2} {k2} lobes (|W {op} W|={lobes}={rule}, n={n}, "
                        f"order 2, seed 000 eq. 7): |{lobes + m} f_c - ({k1} f_{p1[0]} {op} "
                        f"{k2} f_{p2[0]})|"
                    )
                    out.append(PredictedLine("axial" if m == 0 else "radial", freq, label))
    return out


def predicted_lines(
    imperfections: Imperfections,
    kin: Kinematics,
    *,
    axial: bool = True,
    second_order_pairs: bool = False,
) -> list[PredictedLine]:
    """Every line the single imperfections produce (first to third order), unmerged.

    With ``second_order_pairs`` the sum and difference lines of two ring harmonics (seed 000
    eq. 7, :func:`_pair_lines`) are added, for the :data:`MAX_PAIRED_HARMONICS` largest
    harmonics of each ring.
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
    if second_order_pairs:
        out += _pair_lines(imperfections, kin, axial)
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
            comps.append(Component.fitted(name, f, rotation_hz, amp, ph, label))
    if comps:
        # drop lines at the solver's round-off floor (predicted but absent)
        floor = FLOOR * max(c.pp_m for c in comps)
        comps = [c for c in comps if c.pp_m > floor]
    comps.sort(key=lambda c: -c.pp_m)
    return tuple(comps)


#: Lines "explain" a record when the rms of what they leave is at most this fraction of the
#: rms of the radial motion; RRO/NRRO then come from the lines (no averaging bias).
LINE_RESIDUAL_MAX = 1e-3


@dataclass(frozen=True)
class RunoutSplit:
    """Runout figures and how RRO/NRRO were separated.

    Attributes
    ----------
    runout : Runout
    method : {"lines", "synchronous_average", "none"}
    residual : float
        rms of the radial motion the fitted lines leave, over the rms of the radial motion
        about its mean [-] (nan-free: 0 for a motionless record; 1 when no line was fitted).
    """

    runout: Runout
    method: str
    residual: float


def split_runout(
    time: NDArray[np.float64],
    displacement: NDArray[np.float64],
    direction: NDArray[np.float64],
    lines: list[PredictedLine],
    rotation_hz: float,
    synchronous: tuple[NDArray[np.float64], int] | None,
) -> RunoutSplit:
    """RRO/NRRO from the labelled lines when they explain the record, else by averaging.

    The radial lines are fitted to the radial signal (:func:`runout.spectrum.extract_lines`).
    When the relative residual is at most :data:`LINE_RESIDUAL_MAX`, RRO p-p is the p-p over
    one revolution of the sum of the integer-order lines and NRRO p-p the p-p over the record
    of the sum of the others: exact, whereas a synchronous average over N revolutions keeps a
    fraction of order 1/(N·dist(order, ℤ)) of every non-integer line (seed 001's cage line
    would show up as RRO). Otherwise the synchronous average is used (:func:`runout_figures`)
    and the residual is reported.
    """
    radial = direction[0] * displacement[0] + direction[1] * displacement[1]
    base = runout_figures(displacement, direction, synchronous)
    n = time.size
    duration = n * (time[1] - time[0])
    merged = _merge(lines, "radial", 0.5 / duration, 0.5 * n / duration * 0.999, 0.05 / duration)
    centred = radial - radial.mean()
    scale = float(np.sqrt(np.mean(centred**2)))
    if scale == 0.0:
        return RunoutSplit(base, "lines", 0.0)
    if not merged:
        return RunoutSplit(base, "synchronous_average" if synchronous else "none", 1.0)
    freqs = np.array([f for f, _ in merged])
    fit = extract_lines(time, radial, freqs)
    residual = float(fit.residual_rms) / scale
    if residual > LINE_RESIDUAL_MAX:
        return RunoutSplit(base, "synchronous_average" if synchronous else "none", residual)
    orders = freqs / rotation_hz
    rep = np.abs(orders - np.round(orders)) < 1e-9
    rro = nrro = 0.0
    if rep.any():
        spr = max(2048, int(16 * np.abs(orders[rep]).max()))
        tr = np.arange(spr) / (spr * rotation_hz)
        wr = 2.0 * math.pi * np.outer(freqs[rep], tr)
        rro = float(np.ptp((fit.amplitude[rep, None] * np.cos(wr + fit.phase[rep, None])).sum(0)))
    if (~rep).any():
        wn = 2.0 * math.pi * np.outer(freqs[~rep], time)
        nrro = float(
            np.ptp((fit.amplitude[~rep, None] * np.cos(wn + fit.phase[~rep, None])).sum(0))
        )
    out = Runout(base.radial_pp_m, base.axial_pp_m, rro, nrro)
    return RunoutSplit(out, "lines", residual)


def runout_note(split: RunoutSplit, synchronous: bool) -> str:
    """Readable note on how RRO/NRRO were obtained."""
    if split.method == "lines":
        return (
            "RRO/NRRO from the labelled lines (integer orders = RRO); they explain the radial "
            f"motion to {100 * split.residual:.2g} % rms"
        )
    if synchronous:
        return (
            "RRO/NRRO by synchronous averaging: the labelled lines leave "
            f"{100 * split.residual:.3g} % rms of the radial motion unexplained (non-integer "
            "lines bias the average by about 1/(revolutions x distance to an integer order))"
        )
    return "record shorter than 2 revolutions: RRO/NRRO not separated (reported 0)"


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


def measuring_direction(operation: Any) -> NDArray[np.float64]:
    """Unit vector of the radial measuring direction: the radial load's, else +x."""
    if operation.radial_load > 0.0:
        angle = operation.radial_load_angle
        return np.array([math.cos(angle), math.sin(angle)])
    return np.array([1.0, 0.0])


def animation_writer(result: RunResult) -> Callable[[Path], list[Path]]:
    """Writer of ``bearing.gif`` (orbit and balls; :func:`runout.plotting.animate_bearing`)."""

    def write(directory: Path) -> list[Path]:
        from runout import plotting

        return [plotting.animate_bearing(result, directory / "bearing.gif")]

    return write


def run_quasi_static(
    case: Any,
    setup: Any,
    solve: Callable[[Any, NDArray[np.float64], Any], tuple[NDArray[np.float64], Any]],
    *,
    model: str,
    planar: bool,
    description: str,
    extras: dict[str, Any],
) -> RunResult:
    """The run flow shared by the quasi-static models (seeds 000 and 001).

    Solve on the analysis grid, fit the predicted lines, split RRO/NRRO (from the lines, or a
    synchronous grid of whole revolutions, solved again when it differs from the analysis
    grid), and assemble the result with its notes and the GIF writer.

    Parameters
    ----------
    case : Case
        The validated case.
    setup : object
        The model's prepared constants (with ``kinematics``, ``contact_angle``).
    solve : callable
        ``solve(case, time, setup) -> (displacement (3, n) [m], unloaded-ball counts)``.
    model : str
        Model id.
    planar : bool
        True for the 2-D model: no axial lines or direction.
    description : str
        What the displacement is, for the notes.
    extras : dict
        Model-specific JSON entries placed before the shared ones.
    """
    an, op = case.analysis, case.operation
    t = time_grid(op.speed, an.revolutions, an.samples)
    disp, unloaded = solve(case, t, setup)
    u = measuring_direction(op)
    grid = synchronous_grid(op.speed, an.revolutions, an.samples)
    sync = None
    if grid is not None:
        ts, spr = grid
        ds = disp if np.array_equal(ts, t) else solve(case, ts, setup)[0]
        sync = (u[0] * ds[0] + u[1] * ds[1], spr)
    lines = predicted_lines(
        case.imperfections, setup.kinematics, axial=not planar, second_order_pairs=True
    )
    directions = ("x", "y") if planar else ("x", "y", "z")
    comps = fit_components(t, disp, lines, op.speed, directions=directions)
    split = split_runout(t, disp, u, lines, op.speed, sync)
    notes = (
        unloaded_note(unloaded, setup.kinematics.n_elements),
        description,
        runout_note(split, grid is not None),
    )
    result = RunResult(
        model=model,
        title=case.title,
        frequencies=bearing_frequencies(case.bearing, op, setup.contact_angle),
        contact_angle=setup.contact_angle,
        time=t,
        displacement=disp,
        components=comps,
        runout=split.runout,
        measuring_direction=u,
        extras={
            **extras,
            "unloaded_balls_max": int(unloaded.max()),
            "n_elements": setup.kinematics.n_elements,
            "rro_method": split.method,
            "line_fit_residual": split.residual,
        },
        notes=notes,
    )
    return replace(result, writers=(animation_writer(result),))
