r"""Integration of the dynamic model (seed 003 §3): Newmark-β with Newton–Raphson, step and
block planning within the budget, and the transient detection.

Part of :mod:`runout.models.dynamic` (which documents the model and re-exports these names).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.spectrum import amplitude_spectrum
from runout.base.errors import ConvergenceError, GeometryError, NumericalError
from runout.models._dynamic_kernels import (
    BLOWUP,
    FORCE_RTOL,  # noqa: F401 - re-exported with the kernels (docs, tests)
    NOT_CONVERGED,
    NOT_FINITE,
    OK,
    _contact,  # noqa: F401
    _deviations,  # noqa: F401
    newmark_kernel,
)
from runout.models._dynamic_setup import (
    MAX_ITER,
    DynamicSetup,
    contact_forces,
    external_force,
    linearised_natural_frequencies,
    static_equilibrium,
)

#: Default number of Newmark steps per period of the highest linearised natural frequency.
STEPS_PER_PERIOD = 200
#: Transient is over when the free vibration is below this fraction of the response p-p.
SETTLE_TOL = 1e-3
#: Most steps a single run may take (transient + analysis) before giving up.
MAX_STEPS = 50_000_000
#: Longest block of the transient search [revolutions of the rotating ring].
MAX_BLOCK_REVOLUTIONS = 200

_CAUSES = {
    NOT_CONVERGED: "Newton-Raphson iteration of the Newmark step did not converge",
    BLOWUP: "the rotor left the bearing (displacement beyond half the groove-centre distance A)",
    NOT_FINITE: "non-finite displacement (numerical blow-up)",
}


# --------------------------------------------------------------------------------------------
# integration with transient detection
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Integration:
    """Steady-state record of one dynamic run.

    Attributes
    ----------
    time : ndarray, shape (n,)
        Instants of the analysis window [s], ``k / (speed · samples_per_rev)``: t = 0 is the
        first recorded instant, the end of the transient, and the time of the equations of
        motion (ball angles, unbalance phase), which the transient reached from the static
        start at t = -transient.
    displacement : ndarray, shape (3, n)
        x, y and z − (preloaded position) of the rotor [m].
    samples_per_rev : int
        Output samples per revolution of the rotating ring.
    time_step : float
        Newmark step h [s].
    transient : float
        Length of the transient before t = 0, the first recorded instant [s] (a whole number
        of revolutions of the rotating ring).
    settled : str
        How the transient ended: "decayed", "stationary" (free vibration stopped decaying) or
        "limit" (not settled before the step budget).
    natural_frequencies : ndarray
        Linearised natural frequencies at the static equilibrium [Hz].
    static_position : ndarray, shape (3,)
        Static equilibrium at t = 0 (the geometry of the record's start) [m].
    min_loaded : int
        Fewest loaded balls at any step.
    steps : int
        Newmark steps taken.
    iterations : int
        Newton iterations taken.
    """

    time: NDArray[np.float64]
    displacement: NDArray[np.float64]
    samples_per_rev: int
    time_step: float
    transient: float
    settled: str
    natural_frequencies: NDArray[np.float64]
    static_position: NDArray[np.float64]
    min_loaded: int
    steps: int
    iterations: int
    free_vibration: list[float] = field(default_factory=list)


def _raise(status: int, step: int, t: float) -> None:
    cause = _CAUSES.get(status, f"kernel status {status}")
    if status == NOT_CONVERGED:
        raise ConvergenceError(cause, step, t)
    raise NumericalError(cause, step, t)


def _band_amplitude(
    block: NDArray[np.float64], dt: float, f_lo: float, f_hi: float
) -> tuple[float, float]:
    """Largest Hann-spectrum amplitude of x, y (, z) in [f_lo, f_hi], and the block's p-p."""
    spec = amplitude_spectrum(block, sample_rate=1.0 / dt)
    sel = (spec.frequencies >= f_lo) & (spec.frequencies <= f_hi)
    amp = float(spec.amplitude[:, sel].max()) if sel.any() else 0.0
    return amp, float(np.max(np.ptp(block, axis=1)))


def choose_step(
    st: DynamicSetup, f_natural: float, dt_out: float, time_step: float | None
) -> tuple[float, int]:
    """Newmark step h [s] and output stride (h · stride = dt_out).

    Default: at least :data:`STEPS_PER_PERIOD` steps per period of ``f_natural`` (phase
    error of the average-acceleration scheme ≈ (ωh)²/12 ≈ 8e-5 per period) and a whole
    number of steps per output interval. The stride may be astronomically large (a tiny
    step or speed): :func:`plan_integration` checks the work it implies before anything is
    allocated.
    """
    if time_step is not None:
        if not (time_step > 0.0 and math.isfinite(time_step)):
            raise GeometryError("dynamics.time_step", f"must be > 0, got {time_step!r}")
        target = time_step
    else:
        target = 1.0 / (STEPS_PER_PERIOD * max(f_natural, 1e-12))
    stride = max(1, math.ceil(dt_out / target * (1 - 1e-12)))
    return dt_out / stride, stride


def _largest_divisor_at_most(n: int, bound: int) -> int:
    """Largest divisor of ``n`` (>= 1) not above ``bound`` (>= 1), in O(sqrt n) steps."""
    best = 1
    i = 1
    while i * i <= n:
        if n % i == 0:
            for d in (i, n // i):
                if best < d <= bound:
                    best = d
        i += 1
    return best


@dataclass(frozen=True)
class IntegrationPlan:
    """Step, strides and block sizes of one dynamic run, fixed before any array exists.

    Attributes
    ----------
    time_step : float
        Newmark step h [s].
    stride : int
        Steps per output instant.
    steps_per_rev : int
        Steps per revolution of the rotating ring.
    window_steps : int
        Steps of the analysis window (``revolutions`` revolutions).
    rev_block, block_steps : int
        Revolutions and steps of one block of the transient search.
    det_stride : int
        Steps per recorded instant of a transient block (a divisor of ``block_steps``).
    record : int
        Output instants of the analysis window.
    f_lo, f_hi : float
        Lowest positive and highest linearised natural frequency [Hz].
    transient_steps : int
        Most steps the transient search may take (each is integrated twice).
    """

    time_step: float
    stride: int
    steps_per_rev: int
    window_steps: int
    rev_block: int
    block_steps: int
    det_stride: int
    record: int
    f_lo: float
    f_hi: float
    transient_steps: int


def _cost_per_step(st: DynamicSetup) -> float:
    """Estimated seconds of one Newmark step (contacts x harmonics, Newton iterations)."""
    from runout.case.limits import COST_DYNAMIC_ELEMENT, COST_DYNAMIC_HARMONIC

    z = st.n_elements
    rings = st.harmonics[0].size + st.harmonics[3].size
    balls = st.harmonics[6].size
    return z * COST_DYNAMIC_ELEMENT + (z * rings + balls) * COST_DYNAMIC_HARMONIC


def plan_integration(
    st: DynamicSetup,
    speed: float,
    revolutions: int,
    samples_per_rev: int,
    natural: NDArray[np.float64],
    *,
    time_step: float | None = None,
    max_steps: int = MAX_STEPS,
    limits: Any = None,
) -> IntegrationPlan:
    """Step, strides and transient allowance of a run, refused when beyond the budget.

    The analysis window and one block of the transient search (integrated twice) are the
    least a run does; their time and memory are estimated from the step count and compared
    with ``limits`` (:func:`runout.case.limits.budget`) before anything is allocated. The steps
    left in the time budget (at most ``max_steps`` in all) bound the transient search.

    Raises
    ------
    runout.case.limits.LimitError
        Naming the key that makes the run too large (``dynamics.time_step``,
        ``operation.speed``, ``dynamics.mass`` or ``analysis.revolutions``).
    GeometryError
        No contact stiffness at the static position.
    """
    from runout.case.limits import LimitError, budget, format_bytes, format_seconds

    limits = budget() if limits is None else limits
    f_hi = float(natural.max()) if natural.size else 0.0
    if not (math.isfinite(f_hi) and f_hi > 0.0):
        raise GeometryError(
            "operation.radial_load",
            "the rotor has no contact stiffness at its static position (no ball is loaded): "
            "give a radial load or an axial preload",
        )
    positive = natural[natural > 0.0]
    f_lo = float(positive.min()) if positive.size else f_hi
    if f_lo * MAX_BLOCK_REVOLUTIONS < speed:
        # a transient block is at most 200 revolutions: a free vibration slower than that
        # cannot be seen decaying, and its record would hold less than one sample
        raise GeometryError(
            "dynamics.mass",
            f"the rotor's lowest natural frequency ({f_lo:.3g} Hz, from the mass "
            f"{st.mass:.4g} kg on the contact stiffness) is below 1/{MAX_BLOCK_REVOLUTIONS} of "
            f"the speed ({speed:.4g} Hz): its free vibration outlasts "
            f"{MAX_BLOCK_REVOLUTIONS} revolutions and no steady state can be found",
        )
    dt_out = 1.0 / (speed * samples_per_rev)
    h, stride = choose_step(st, f_hi, dt_out, time_step)
    steps_per_rev = stride * samples_per_rev
    # a block spans >= 20 natural periods and, with damping, >= ln 2 linear decay times 2m/c
    # (the free vibration halves per block at least), but at most 200 revolutions
    decay = math.log(2.0) * 2.0 * st.mass / st.damping if st.damping > 0.0 else math.inf
    rev_block = max(1, math.ceil(20.0 / max(f_lo, 1e-12) * speed))
    rev_block = min(MAX_BLOCK_REVOLUTIONS, max(rev_block, math.ceil(min(decay, 1e9) * speed)))
    window_steps = revolutions * steps_per_rev
    block_steps = rev_block * steps_per_rev
    det_points = block_steps / max(1.0, math.floor(1.0 / (8.0 * f_hi * h)))
    record = revolutions * samples_per_rev
    least = window_steps + 2 * block_steps
    per_step = _cost_per_step(st)
    seconds = least * per_step
    memory = 8.0 * 3 * (8 * record + 6 * det_points) + 16.0 * record * 64
    duration = revolutions / speed
    what = (
        f"{revolutions} revolutions at {speed:.4g} Hz = {duration:.4g} s of motion, and a "
        f"transient block of {rev_block} revolutions, in steps of {h:.3g} s: "
        f"{least:.3g} Newmark steps"
    )
    # the key to change: the one that makes the steps many
    undamped = math.ceil(min(decay, 1e9) * speed) >= rev_block > 1
    if time_step is not None:
        key = "dynamics.time_step"
    elif duration > 60.0:
        key = "operation.speed"
    elif h < 1e-8:
        key = "dynamics.mass"
        what += f" (natural frequency {f_hi:.3g} Hz)"
    elif 2 * block_steps > window_steps and undamped:
        # little or no damping: the transient blocks last as long as the free vibration does
        key = "dynamics.damping"
    else:
        key = "analysis.revolutions"
    if not memory <= limits.memory:
        raise LimitError(
            key,
            f"the dynamic run would need about {format_bytes(memory)} of memory ({what}); "
            f"change {key} {limits.raise_hint('memory')}",
        )
    if not (seconds <= limits.time and least <= max_steps):
        raise LimitError(
            key,
            f"the dynamic run would take about {format_seconds(seconds)} ({what}); change "
            f"{key} {limits.raise_hint('time')}",
        )
    # the transient search is integrated twice: half of what is left of the budget
    left = min(max_steps, int(limits.time / per_step)) - window_steps
    transient_steps = max(block_steps, left // 2)
    fine = max(1, math.floor(1.0 / (8.0 * f_hi * h)))
    det_stride = _largest_divisor_at_most(block_steps, fine)
    return IntegrationPlan(
        time_step=h,
        stride=stride,
        steps_per_rev=steps_per_rev,
        window_steps=window_steps,
        rev_block=rev_block,
        block_steps=block_steps,
        det_stride=det_stride,
        record=record,
        f_lo=f_lo,
        f_hi=f_hi,
        transient_steps=transient_steps,
    )


class _Stepper:
    """Newmark integration state and counters, advanced block by block by :func:`integrate`."""

    def __init__(self, st: DynamicSetup, par: NDArray[np.float64], h: float) -> None:
        self.st, self.par, self.h = st, par, h
        self.state = np.zeros(9)
        self.t = 0.0
        self.steps = self.iterations = 0
        self.min_loaded = st.n_elements

    def start_static(self, t: float, q: NDArray[np.float64]) -> None:
        """Start at rest at ``q`` at time ``t``, acceleration from the equation of motion."""
        st = self.st
        self.t = t
        self.state = np.zeros(9)
        self.state[:3] = q
        f0, _ = contact_forces(st, np.array([t]), q[None])
        self.state[6 : 6 + st.ndof] = (external_force(st, np.array([t]))[0] - f0[0])[
            : st.ndof
        ] / st.mass

    def advance(self, n_steps: int, stride: int, out: NDArray[np.float64]) -> None:
        """``n_steps`` steps, recording every ``stride``-th state into ``out``."""
        st = self.st
        status, bad, it, ml = newmark_kernel(
            n_steps, stride, self.t, self.state, self.par, st.theta0, st.harmonics, st.ndof,
            MAX_ITER, out, st.spalls, st.slip,
        )  # fmt: skip
        if status != OK:
            _raise(int(status), self.steps + int(bad), self.t + (int(bad) + 1) * self.h)
        self.t += n_steps * self.h
        self.steps += n_steps
        self.iterations += int(it)
        self.min_loaded = min(self.min_loaded, int(ml))


def integrate(
    st: DynamicSetup,
    speed: float,
    revolutions: int,
    samples_per_rev: int,
    *,
    time_step: float | None = None,
    progress: Callable[[float], None] | None = None,
    max_steps: int = MAX_STEPS,
    limits: Any = None,
) -> Integration:
    """Integrate from the static equilibrium, detect the end of the transient, record.

    Blocks of whole revolutions (at least 20 periods of the lowest natural frequency) are
    integrated one after the other. After each block the largest Hann-spectrum amplitude
    within ±15 % of the natural frequencies (the free vibration) is compared with the block's
    p-p: the transient is over when it is below :data:`SETTLE_TOL` of the p-p ("decayed"), or
    when it has stopped decaying ("stationary": the largest amplitude of the last three blocks
    is above half that of the three before, whereas a block lasts at least ln 2 linear decay
    times 2m/c, so a free vibration would have dropped eightfold; a forced line in the band, a
    resonance or an undamped system keeps it, and the analysis then includes it).
    The transient found this way is then integrated again, from the static equilibrium at
    t = -transient, and ``revolutions`` whole revolutions are recorded from t = 0: the returned
    ``time`` starts at 0 where the bearing's geometry (ball angles θ_j(t), ring angles,
    unbalance phase Ωt) is the one every other model has at its t = 0 (the product's time
    origin), and ``transient`` is the length of the transient before it. The transient is
    integrated twice; it is usually short against the record.

    Parameters
    ----------
    st : DynamicSetup
    speed : float
        Rotating ring speed [Hz] (> 0).
    revolutions : int
        Revolutions in the analysis window (>= 1).
    samples_per_rev : int
        Output samples per revolution.
    time_step : float or None
        Newmark step [s]; default automatic (:func:`choose_step`).
    progress : callable or None
        Called with the fraction done (0..1) after each block.
    max_steps : int
        Step budget of the whole run (transient search twice and the window).
    limits : runout.case.limits.Budget or None
        Memory and time budget (default :func:`runout.case.limits.budget`); the plan is refused
        before any array is allocated when it exceeds it, and what is left of the time bounds
        the transient search.

    Raises
    ------
    ConvergenceError, NumericalError
        Naming the step and time of the failure.
    runout.case.limits.LimitError
        A window or a transient block beyond the budget (:func:`plan_integration`).
    """
    q_static = static_equilibrium(st, np.array([0.0]))[0]
    fn = linearised_natural_frequencies(st, q_static)
    plan = plan_integration(
        st,
        speed,
        revolutions,
        samples_per_rev,
        fn,
        time_step=time_step,
        max_steps=max_steps,
        limits=limits,
    )
    f_lo, f_hi = plan.f_lo, plan.f_hi
    dt_out = 1.0 / (speed * samples_per_rev)
    h, stride, steps_per_rev = plan.time_step, plan.stride, plan.steps_per_rev
    par = st.params(h)
    run = _Stepper(st, par, h)
    run.start_static(0.0, q_static)
    history: list[float] = []
    settled = "limit"
    budget = plan.transient_steps
    block_steps = plan.block_steps
    # the transient blocks are recorded finely enough to see the free vibration
    det_stride = plan.det_stride
    dt_det = det_stride * h
    est_blocks = 4
    while run.steps + block_steps <= max(budget, block_steps):
        out = np.zeros((block_steps // det_stride, 3))
        run.advance(block_steps, det_stride, out)
        amp, pp = _band_amplitude(out[:, : st.ndof].T, dt_det, 0.85 * f_lo, 1.15 * f_hi)
        history.append(amp)
        floor = 1e-9 * st.reference_approach
        if amp <= SETTLE_TOL * max(pp, floor) or amp <= floor:
            settled = "decayed"
            break
        # a transient at least halves per block (block sizing above): when the largest of the
        # last three blocks is still above half the largest of the three before, what is left
        # in the band is part of the steady response (a forced line, a resonance, c = 0)
        if len(history) >= 6 and max(history[-3:]) >= 0.5 * max(history[-6:-3]):
            settled = "stationary"
            break
        est_blocks = max(est_blocks, len(history) + 2)
        if progress is not None:
            progress(0.5 * len(history) / est_blocks)
        if run.steps + block_steps > budget:
            break
    transient = run.t
    # One time origin for every model: the bearing's geometry (ball angles, ring angles,
    # unbalance) at the reported t = 0 is the one every other model has at its t = 0. The
    # search above has measured how long the transient lasts; integrate it again from the
    # static equilibrium at t = -transient, so that the record starts at t = 0 exactly.
    if transient > 0.0:
        run.start_static(-transient, static_equilibrium(st, np.array([-transient]))[0])
        for _ in range(len(history)):
            run.advance(block_steps, det_stride, np.zeros((block_steps // det_stride, 3)))
        run.t = 0.0  # exactly, not the rounded sum of the steps
    n_out = revolutions * samples_per_rev
    # the record starts at t = 0: row 0 is the state there, row k the state k output
    # intervals later; the kernel records after each ``stride`` steps, so it fills rows
    # 1..n_out and the last row (the start of the next revolution) is dropped: the window is
    # [0, revolutions / speed)
    out = np.zeros((n_out + 1, 3))
    out[0] = run.state[:3]
    # record in chunks of whole revolutions so that progress can be shown
    chunk_rev = max(1, revolutions // 10)
    done = 0
    while done < revolutions:
        nrev = min(chunk_rev, revolutions - done)
        view = out[1 + done * samples_per_rev : 1 + (done + nrev) * samples_per_rev]
        run.advance(nrev * steps_per_rev, stride, view)
        done += nrev
        if progress is not None:
            progress(0.5 + 0.5 * done / revolutions)
    out = out[:n_out]
    if not np.all(np.isfinite(out)):
        raise NumericalError("non-finite displacement in the analysis window")
    time = np.arange(n_out, dtype=np.float64) * dt_out  # t = 0 after the transient
    return Integration(
        time=time,
        displacement=np.ascontiguousarray(out.T),
        samples_per_rev=samples_per_rev,
        time_step=h,
        transient=transient,
        settled=settled,
        natural_frequencies=fn,
        static_position=q_static,
        min_loaded=run.min_loaded,
        steps=run.steps,
        iterations=run.iterations,
        free_vibration=history,
    )
