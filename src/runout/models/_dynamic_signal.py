r"""Localized defects and the accelerometer signal of the dynamic model.

Part of :mod:`runout.models.dynamic`. A ``[[defect]]`` entry is a spall: the approach δ_j of a
ball whose contact point lies over it drops by the depth its centre can reach
(:func:`runout.models._dynamic_kernels.spall_drop`), so the ball unloads as it enters and is
loaded again, abruptly, as it leaves: an impact on the rotor and on the outer ring at each
passage. A spall on the stationary ring sits at a fixed angle and sees the load zone's load;
one on the rotating ring turns with it and passes through the load zone once a revolution; a
ball's meets the outer and the inner raceway once a spin revolution each, wherever the cage
carries the ball.

``[analysis] signal = "acceleration"`` integrates the steady state again with a step that
divides the sensor's sampling interval, records the bearing's force on the outer ring along the
measuring direction at every step and passes it through the housing's modes
(:mod:`runout.analysis.sensor`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from runout.analysis.sensor import (
    AccelerationSignal,
    HousingMode,
    envelope_block,
    housing_acceleration,
    min_samples,
    sample,
)
from runout.base.errors import GeometryError
from runout.models._dynamic_integration import MAX_STEPS, Integration, _cost_per_step, _Stepper
from runout.models._dynamic_kernels import S_ARC, S_BALL, S_DEPTH, S_RADIUS, S_RATE, S_WIDTH
from runout.models._dynamic_setup import (
    TWO_PI,
    DynamicSetup,
    contact_forces,
    static_equilibrium,
)

__all__ = [
    "FLUCTUATION_BANDWIDTH",
    "FLUCTUATION_TERMS",
    "SPALL_STEPS",
    "acceleration_signal",
    "spall_entry_time",
    "speed_profile",
]

#: Fewest Newmark steps over the entry of a ball into a spall (from its edge to the depth the
#: ball reaches): the step is refined to give at least these.
SPALL_STEPS = 10
#: Steps integrated and converted to force at once while recording the signal.
_CHUNK = 1 << 15


def spall_entry_time(st: DynamicSetup) -> float | None:
    """Shortest time a ball takes to enter a spall, edge to full drop [s] (None: no spall).

    The contact point runs over a raceway at the speed of the cage relative to that ring,
    over a ball at its spin relative to the cage; it reaches the full drop d of a ball of
    radius r at :math:`e = \\sqrt{2rd - d^2}` from the edge (:func:`spall_drop`), at most the
    half width.

    Parameters
    ----------
    st : DynamicSetup
        With its ``spalls``.

    Returns
    -------
    float or None
        [s]; None without spalls (or a spall that does not move: speed 0).
    """
    times = []
    wc = TWO_PI * st.kinematics.cage
    for row in st.spalls:
        rate = abs(row[S_RATE]) if row[S_BALL] else abs(wc - row[S_RATE])
        speed = rate * row[S_ARC]
        if speed <= 0.0:
            continue
        r, d, w = row[S_RADIUS], row[S_DEPTH], row[S_WIDTH]
        reach = math.sqrt(max(2.0 * r * d - d * d, 0.0))
        times.append(min(reach, 0.5 * w) / speed)
    return min(times) if times else None


def _slip_knots(st: DynamicSetup, transient: float, duration: float, sensor: Any) -> Any:
    r"""The cage's slip angle at the start of each ball passage from -transient [rad].

    The cage turns at :math:`\omega_c(1 + s\,n_k)` over the k-th interval of one ball
    passage, :math:`T = 1/(Z|f_c|)` (a ball passes a point of the outer ring), :math:`n_k`
    standard normal (seeded by ``[sensor] seed``): its slip angle grows by
    :math:`\omega_c T s\,n_k` over each interval, and each impact period on the outer ring
    jitters by a relative standard deviation s.
    """
    if st.harmonics[0].size + st.harmonics[3].size + st.harmonics[6].size:
        raise GeometryError(
            "sensor.slip",
            "random slip is modelled for a bearing without waviness or ball size errors (their "
            "rotating phasors do not slip): remove sensor.slip or the imperfections",
        )
    wc = TWO_PI * st.kinematics.cage
    period = 1.0 / (st.n_elements * abs(st.kinematics.cage))
    count = math.ceil((transient + duration) / period) + 3
    rng = np.random.default_rng((sensor.seed, 1))  # a stream of its own: the noise's is kept
    steps = wc * period * sensor.slip * rng.standard_normal(count)
    values = np.concatenate([[0.0], np.cumsum(steps)])
    return np.concatenate([[-transient - period, period], values])


#: Sinusoids of the speed fluctuation, and its bandwidth over the shaft speed.
FLUCTUATION_TERMS = 8
FLUCTUATION_BANDWIDTH = 0.1


def speed_profile(
    fluctuation: float, shaft_hz: float, duration: float, seed: int, count: int
) -> NDArray[np.float64]:
    r"""Relative deviation of the shaft speed from its mean at ``count`` instants over the record.

    Parameters
    ----------
    fluctuation : float
        Rms of the deviation over the record, ε [-] (``[sensor] speed_fluctuation``).
    shaft_hz : float
        Mean shaft speed f_r [Hz].
    duration : float
        The record's length [s]; the instants are ``duration * i / count``.
    seed : int
        ``[sensor] seed`` (a stream of its own: the noise's and the slip's are kept).
    count : int
        Number of instants.

    Returns
    -------
    ndarray
        u(t) with Ω(t) = Ω̄ (1 + u(t)): zero mean and rms ε over the record.

    Notes
    -----
    :math:`u(t) = c\,\sum_{k=1}^{8} \cos(2\pi f_k t + \phi_k) - \bar u`, with :math:`f_k`
    uniform in [0.01, 0.1] f_r (a slow variation: ten shaft revolutions or more a cycle) and
    :math:`\phi_k` uniform, scaled to rms ε: a band-limited random speed variation as simulated
    bearing signals use it (R. B. Randall and J. Antoni, "Rolling element bearing diagnostics —
    A tutorial", MSSP 25, 2011, sec. 2: speed fluctuations smear the defect lines; order
    tracking removes them).
    """
    rng = np.random.default_rng((seed, 2))
    freqs = shaft_hz * FLUCTUATION_BANDWIDTH * rng.uniform(0.1, 1.0, FLUCTUATION_TERMS)
    phases = rng.uniform(0.0, TWO_PI, FLUCTUATION_TERMS)
    t = duration * np.arange(count, dtype=np.float64) / count
    u = np.cos(TWO_PI * freqs[None, :] * t[:, None] + phases[None, :]).sum(axis=1)
    u -= u.mean()
    rms = float(np.sqrt(np.mean(u * u)))
    out: NDArray[np.float64] = fluctuation * u / rms if rms > 0.0 else np.zeros(count)
    return out


def _warp(
    force: NDArray[np.float64], h: float, fluctuation: float, shaft_hz: float, seed: int
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The force at a fluctuating speed, and the shaft's revolutions at each step / speed.

    Integrated at the constant mean speed, the force at nominal time τ is the one at the
    shaft angle Ω̄ τ; at a fluctuating speed that angle is reached at t with
    τ(t) = ∫_0^t (1 + u) dt: F_fluct(t) = F(τ(t)), linear between steps.
    """
    n = force.size
    u = speed_profile(fluctuation, shaft_hz, n * h, seed, n)
    rate = 1.0 + u
    tau = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * h)])
    grid = h * np.arange(n, dtype=np.float64)
    warped = np.interp(tau, grid, force)
    return warped, tau


def _mode_text(mode: HousingMode) -> str:
    return (
        f"resonance {mode.resonance_hz:.6g} Hz, damping ratio {mode.damping_ratio:.3g}, modal "
        f"mass {mode.modal_mass_kg:.4g} kg"
    )


def acceleration_signal(
    case: Any,
    st: DynamicSetup,
    integ: Integration,
    direction: NDArray[np.float64],
    limits: Any,
) -> tuple[AccelerationSignal, list[str]]:
    """The housing acceleration of a dynamic run (``[analysis] signal = "acceleration"``).

    The steady state is integrated again from the static equilibrium at ``-transient`` (the
    transient the run found), with the run's step shortened to divide the sensor's sampling
    interval; the contact force :math:`\\sum_j Q_j n_j` (the force of the balls on the outer
    ring) along ``direction`` at every step drives :func:`housing_acceleration`, sampled by
    :func:`sample`; then the noise.

    Parameters
    ----------
    case : Case
        Its ``[sensor]`` table and operation.
    st : DynamicSetup
        The model's setup.
    integ : Integration
        The run's integration (step, transient).
    direction : ndarray, shape (2,)
        Measuring direction (unit vector in x, y).
    limits : runout.case.limits.Budget
        The run's budget: the signal's steps are bounded by it.

    Returns
    -------
    AccelerationSignal
    list of str
        Notes (the sensor model, the step).

    Raises
    ------
    GeometryError
        A signal too short for the envelope analysis or beyond the budget (naming
        ``sensor.duration`` or ``sensor.sample_rate``).
    """
    from runout.case.limits import LimitError, format_bytes, format_seconds
    from runout.geometry.kinematics import bearing_frequencies

    sensor = case.spec.sensor
    op = case.operation
    fs = float(sensor.sample_rate)
    speed = float(op.speed)
    duration = (
        float(sensor.duration) if sensor.duration is not None else integ.time[-1] + integ.time[1]
    )
    n_out = round(duration * fs)
    if n_out < min_samples():
        raise GeometryError(
            "sensor.duration",
            f"{duration:.4g} s at {fs:.6g} Hz is {n_out} samples: the envelope analysis needs "
            f"at least {min_samples()}",
        )
    factor = max(1, math.ceil(1.0 / (fs * integ.time_step) - 1e-9))
    h = 1.0 / (fs * factor)
    steps = n_out * factor + round(integ.transient / h)
    seconds = steps * _cost_per_step(st) * 2.0  # and the forces of every step
    key = "sensor.duration" if sensor.duration is not None else "analysis.revolutions"
    # the force at every step, the filtered copy and the resampling's: about 4 arrays
    memory = 4.0 * 8.0 * n_out * factor + _CHUNK * (24.0 + 8.0 * 8 * st.n_elements)
    if memory > limits.memory:
        raise LimitError(
            key,
            f"the acceleration signal would need about {format_bytes(memory)} of memory "
            f"({n_out} samples of {factor} Newmark steps each); shorten it with {key} "
            f"{limits.raise_hint('memory')}",
        )
    if steps > MAX_STEPS or seconds > limits.time:
        raise LimitError(
            key,
            f"the acceleration signal would take {steps:.3g} Newmark steps of {h:.3g} s (about "
            f"{format_seconds(seconds)}); shorten it with {key} {limits.raise_hint('time')}",
        )
    slip_notes = ""
    if sensor.slip > 0.0:
        st = st.replace(slip=_slip_knots(st, integ.transient, duration, sensor))
        slip_notes = (
            f"; random slip {sensor.slip:.3g}: the cage's speed varies by that relative standard "
            "deviation, drawn anew each ball passage (each impact period jitters by about as "
            "much; the balls and their spin follow the cage)"
        )
    run = _Stepper(st, st.params(h), h)
    t0 = -integ.transient
    run.start_static(t0, static_equilibrium(st, np.array([t0]))[0])
    left = round(integ.transient / h)
    while left > 0:  # the transient again, with this step (not recorded)
        n = min(left, _CHUNK)
        run.advance(n, n, np.zeros((1, 3)))
        left -= n
    run.t = 0.0
    n_fine = n_out * factor
    force = np.empty(n_fine)
    q0 = run.state[:3].copy()
    force[0] = contact_forces(st, np.array([0.0]), q0[None])[0][0, :2] @ direction
    done = 1
    while done < n_fine:
        n = min(_CHUNK, n_fine - done)
        out = np.zeros((n, 3))
        run.advance(n, 1, out)
        t = (done + np.arange(n)) * h
        f, _ = contact_forces(st, t, out)
        force[done : done + n] = f[:, :2] @ direction
        done += n
    # a single mode without modal_mass takes the [dynamics] mass (noted)
    modes = tuple(
        HousingMode(float(f), float(z), float(m) if m is not None else st.mass)
        for f, z, m in sensor.housing_modes()
    )
    fluctuation = float(sensor.speed_fluctuation or 0.0)
    nominal_time = None
    if fluctuation > 0.0:
        # the housing rings at its own resonance: the force is warped, not the acceleration
        force, nominal_time = _warp(force, h, fluctuation, abs(speed), int(sensor.seed))
    fine = housing_acceleration(
        force,
        h,
        [m.resonance_hz for m in modes],
        [m.damping_ratio for m in modes],
        [m.modal_mass_kg for m in modes],
    )
    acc = sample(fine, factor)[:n_out]
    rms = float(np.sqrt(np.mean(acc**2)))
    if sensor.noise > 0.0:
        rng = np.random.default_rng(sensor.seed)
        acc = acc + sensor.noise * rms * rng.standard_normal(acc.size)
    time = np.arange(n_out, dtype=np.float64) / fs
    freqs = bearing_frequencies(case.bearing, op, st.contact_angle)
    rotating = op.rotating_ring
    fundamentals = {
        "outer": freqs.ball_pass_outer,
        "inner": freqs.ball_pass_inner,
        "ball": 2.0 * freqs.ball_spin,
        "cage": abs(freqs.cage),
    }
    # the rotating ring's defect passes the load zone once a revolution, a ball's once a cage
    # revolution, the stationary ring's never (Randall and Antoni 2011, Table 1)
    sidebands: dict[str, float | None] = {
        "outer": freqs.rotation if rotating == "outer" else None,
        "inner": freqs.rotation if rotating == "inner" else None,
        "ball": abs(freqs.cage),
        "cage": None,
    }
    band = None if sensor.band is None else (float(sensor.band[0]), float(sensor.band[1]))
    rev = speed * (time if nominal_time is None else nominal_time[::factor][:n_out])
    # a fluctuating speed: the run knows its shaft angle, the envelope is read in orders
    tracked = None if nominal_time is None else abs(rev)
    envelope = envelope_block(acc, fs, fundamentals, sidebands, freqs.rotation, band, tracked)
    signal = AccelerationSignal(
        time=time,
        acceleration=acc,
        rev=rev,
        sample_rate_hz=fs,
        modes=modes,
        noise=float(sensor.noise),
        seed=int(sensor.seed),
        slip=float(sensor.slip),
        speed_fluctuation=fluctuation,
        envelope=envelope,
    )
    if len(modes) == 1:
        housing = (
            "one housing mode, H(s) = s^2 / (M (s^2 + 2 zeta wn s + wn^2)), "
            + _mode_text(modes[0])
            + (
                " (the [dynamics] mass: [sensor] modal_mass not given)"
                if sensor.modal_mass is None
                else ""
            )
        )
    else:
        housing = (
            f"{len(modes)} housing modes whose accelerations add, H(s) = sum of "
            "s^2 / (M_k (s^2 + 2 zeta_k w_k s + w_k^2)): " + "; ".join(_mode_text(m) for m in modes)
        )
    notes = [
        "acceleration signal: the bearing's force on the outer ring along the measuring "
        f"direction through {housing}; sampled at {fs:.6g} Hz after an anti-aliasing filter, "
        f"{n_out} samples "
        f"({duration:.4g} s), Newmark step {h * 1e6:.4g} us ({factor} per sample); Gaussian "
        f"noise {sensor.noise:.3g} x the signal rms (seed {sensor.seed})"
        + (
            slip_notes
            or "; no slip of the rolling elements"
            + ("" if fluctuation > 0.0 else " (the defect lines are exact)")
        )
        + (
            f"; the shaft speed fluctuates by {fluctuation:.3g} rms about {abs(speed) * 60:.6g} "
            f"rpm (a sum of {FLUCTUATION_TERMS} random sinusoids below "
            f"{FLUCTUATION_BANDWIDTH * abs(speed):.3g} Hz, seed {sensor.seed}): the constant-speed "
            "force is resampled at the fluctuating shaft angle (its inertial effects neglected) "
            "and the rev column follows it; the defect lines in Hz spread by about as much"
            if fluctuation > 0.0
            else "; a constant shaft speed"
        ),
        f"envelope band {envelope['band_hz'][0]:.6g}-{envelope['band_hz'][1]:.6g} Hz "
        + ("chosen by the fast kurtogram" if band is None else "given by [sensor] band")
        + f" (spectral kurtosis {envelope['spectral_kurtosis']:.3g})"
        + (
            "; the signal order-tracked first with the run's shaft angle (the rev column): "
            "its lines read at their orders times the mean speed"
            if tracked is not None
            else ""
        ),
    ]
    return signal, notes
