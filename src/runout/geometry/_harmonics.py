"""Fourier series of a part's radius (:class:`Harmonics`), single waves and spectral laws.

Part of :mod:`runout.geometry.imperfections` (its module docstring gives the conventions).
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.base.errors import GeometryError

TWO_PI = 2.0 * math.pi
#: Work (harmonics × angles) above which :meth:`Harmonics.evaluate` uses the Numba kernel.
KERNEL_THRESHOLD = 32_768

ElementPart = Literal["ball", "roller", "element"]
Part = Literal["inner", "outer", "ball", "roller", "element"]


class ImperfectionError(GeometryError):
    """An invalid imperfection description (a :class:`ValueError`).

    Parameters
    ----------
    key : str
        What is wrong, e.g. ``"harmonics.amplitudes"`` or ``"imperfections.pitch_errors"``.
    message : str
        Why.
    """


class ProfileError(ImperfectionError):
    """A measured profile that cannot be read or cannot give the requested harmonics.

    Parameters
    ----------
    file : str
        Path of the profile file as given (empty for in-memory profiles).
    line : int or None
        1-based line number in the file, when one line is at fault.
    message : str
        What is wrong.
    """

    def __init__(self, file: str, line: int | None, message: str) -> None:
        self.file = file
        self.line = line
        where = file if line is None else f"{file}:{line}"
        super().__init__(where or "profile", message)


class ProfileWarning(UserWarning):
    """The profile's sampling resolves the requested orders only poorly."""


# --------------------------------------------------------------------------------------------
# Harmonics
# --------------------------------------------------------------------------------------------
def _wrap_phase(phi: NDArray[np.float64]) -> NDArray[np.float64]:
    out = np.mod(phi, TWO_PI)
    out[out >= TWO_PI] = 0.0  # np.mod(-tiny, 2π) rounds up to 2π
    return out


#: Largest waviness order. A wave of 10^6 lobes is 3 µm long even on a 1 m raceway, shorter
#: than the contact ellipse of any loaded ball or roller, which filters it out.
MAX_ORDER = 1_000_000
#: Most rolling elements. The largest slewing bearings have a few hundred; every element is an
#: object of its own, so 10 000 keep a bearing's imperfections under a second to build.
MAX_ELEMENTS = 10_000


def _real_scalar(name: str, value: Any) -> Any:
    """``value`` unchanged unless complex, which is refused naming ``name`` (never cast)."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, numbers.Complex) and not isinstance(value, numbers.Real):
        raise ImperfectionError(
            name, f"must be a real number, got the complex {value!r} (never cast to real)"
        )
    return value


def _as_float_vector(name: str, values: ArrayLike) -> NDArray[np.float64]:
    if np.iscomplexobj(values):  # a cast would drop the imaginary part without a word
        raise ImperfectionError(name, "must be real numbers, got complex values (never cast)")
    try:
        arr = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise ImperfectionError(name, f"must be numbers, got {values!r}") from exc
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim != 1:
        raise ImperfectionError(name, f"must be one-dimensional, got shape {arr.shape}")
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ImperfectionError(name, f"must be finite, got {arr[i]!r} at position {i}")
    return arr


def _as_orders(name: str, values: ArrayLike) -> NDArray[np.int64]:
    arr = _as_float_vector(name, values)
    frac = arr != np.round(arr)
    if frac.any():
        i = int(np.flatnonzero(frac)[0])
        raise ImperfectionError(name, f"must be whole numbers, got {arr[i]!r} at position {i}")
    if (arr < 0).any():
        i = int(np.flatnonzero(arr < 0)[0])
        raise ImperfectionError(name, f"must be >= 0, got {int(arr[i])} at position {i}")
    if (arr > MAX_ORDER).any():  # as the case file's orders (case.limits.MAX_ORDER)
        raise ImperfectionError(
            name,
            f"order {int(arr.max())} is beyond {MAX_ORDER}: a wave that short is shorter than "
            "any contact",
        )
    return arr.astype(np.int64)


def _readonly(arr: NDArray[Any]) -> NDArray[Any]:
    arr = np.array(arr, copy=True)
    arr.setflags(write=False)
    return arr


@dataclass(frozen=True, init=False, eq=False)
class Harmonics:
    r"""A radius-deviation profile ``r(θ) = Σ a_k cos(k θ + φ_k)`` of one part.

    Parameters
    ----------
    orders : array_like of int
        Orders k ≥ 0 (waves per turn). Duplicates are merged by complex addition.
    amplitudes : array_like of float
        Zero-to-peak amplitudes a_k of the radius deviation [m]; negative values are turned
        positive with the phase advanced by π.
    phases : array_like of float, optional
        Phases φ_k [rad]; default 0. Stored wrapped to [0, 2π).

    Notes
    -----
    Terms of zero amplitude are dropped. The order-0 term ``a_0 cos φ_0`` is stored as
    ``|a_0 cos φ_0|`` with phase 0 or π (a size error has no phase). Equality compares the
    normalised arrays exactly. Instances are immutable (read-only arrays).
    """

    orders: NDArray[np.int64]
    amplitudes: NDArray[np.float64]
    phases: NDArray[np.float64]

    def __init__(
        self, orders: ArrayLike, amplitudes: ArrayLike, phases: ArrayLike | None = None
    ) -> None:
        k = _as_orders("harmonics.orders", orders)
        a = _as_float_vector("harmonics.amplitudes", amplitudes)
        if phases is None:
            p = np.zeros_like(a)
        else:
            p = _as_float_vector("harmonics.phases", phases)
        if not (k.size == a.size == p.size):
            raise ImperfectionError(
                "harmonics",
                f"orders, amplitudes and phases must have the same length, got "
                f"{k.size}, {a.size} and {p.size}",
            )
        k, a, p = _normalise(k, a, p)
        object.__setattr__(self, "orders", _readonly(k))
        object.__setattr__(self, "amplitudes", _readonly(a))
        object.__setattr__(self, "phases", _readonly(p))

    # --- construction -----------------------------------------------------------------------
    @classmethod
    def empty(cls) -> Harmonics:
        """No deviation at all."""
        return cls(np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0))

    @classmethod
    def from_complex(cls, orders: ArrayLike, coefficients: ArrayLike) -> Harmonics:
        """Build from complex coefficients ``c_k = a_k e^{iφ_k}`` (``r = Re Σ c_k e^{ikθ}``)."""
        c = np.asarray(coefficients, dtype=np.complex128).reshape(-1)
        if not np.isfinite(c).all():
            raise ImperfectionError("harmonics.coefficients", "must be finite")
        return cls(orders, np.abs(c), np.angle(c))

    def to_complex(self) -> tuple[NDArray[np.int64], NDArray[np.complex128]]:
        """Orders and complex coefficients ``c_k = a_k e^{iφ_k}``."""
        return self.orders.copy(), self.amplitudes * np.exp(1j * self.phases)

    # --- properties ---------------------------------------------------------------------------
    def __len__(self) -> int:
        return int(self.orders.size)

    @property
    def is_empty(self) -> bool:
        """True when there is no harmonic (the part is perfect)."""
        return self.orders.size == 0

    @property
    def max_order(self) -> int:
        """Highest order present (0 for an empty profile)."""
        return int(self.orders[-1]) if self.orders.size else 0

    @property
    def rms(self) -> float:
        """Root mean square of r(θ) over a turn [m], order 0 included: √(a₀² + Σ a_k²/2)."""
        a = self.amplitudes
        zero = self.orders == 0
        return float(math.sqrt(float(np.sum(a[zero] ** 2) + 0.5 * np.sum(a[~zero] ** 2))))

    # --- arithmetic ---------------------------------------------------------------------------
    def __add__(self, other: object) -> Harmonics:
        if not isinstance(other, Harmonics):
            return NotImplemented
        return Harmonics(
            np.concatenate([self.orders, other.orders]),
            np.concatenate([self.amplitudes, other.amplitudes]),
            np.concatenate([self.phases, other.phases]),
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Harmonics):
            return NotImplemented
        return (
            np.array_equal(self.orders, other.orders)
            and np.array_equal(self.amplitudes, other.amplitudes)
            and np.array_equal(self.phases, other.phases)
        )

    def __hash__(self) -> int:
        return hash((self.orders.tobytes(), self.amplitudes.tobytes(), self.phases.tobytes()))

    def __repr__(self) -> str:
        if self.orders.size <= 6:
            body = ", ".join(
                f"k={k}: {a:.4g} m @ {p:.4g} rad"
                for k, a, p in zip(self.orders, self.amplitudes, self.phases, strict=True)
            )
        else:
            body = (
                f"{self.orders.size} orders {self.orders[0]}..{self.orders[-1]}, "
                f"max amplitude {self.amplitudes.max():.4g} m"
            )
        return f"Harmonics({body})"

    def scaled(self, factor: float) -> Harmonics:
        """Every amplitude multiplied by ``factor`` (a negative factor shifts phases by π)."""
        if not math.isfinite(factor):
            raise ImperfectionError("harmonics.scale", f"must be finite, got {factor!r}")
        return Harmonics(self.orders, self.amplitudes * factor, self.phases)

    def shifted(self, angle: float) -> Harmonics:
        """The profile seen from a frame turned by ``-angle``: θ ↦ r(θ + angle).

        Phases become φ_k + k·angle. Example: a ring turned by ψ, evaluated at a fixed-frame
        angle θ, is ``h.shifted(-ψ).evaluate(θ)``.
        """
        return Harmonics(self.orders, self.amplitudes, self.phases + self.orders * angle)

    def mirrored(self) -> Harmonics:
        """θ ↦ r(-θ): converts a profile whose angle runs clockwise (phases negated)."""
        return Harmonics(self.orders, self.amplitudes, -self.phases)

    def band(self, kmin: int = 0, kmax: int | None = None) -> Harmonics:
        """Only the orders kmin ≤ k ≤ kmax (inclusive)."""
        keep = self.orders >= kmin
        if kmax is not None:
            keep &= self.orders <= kmax
        return Harmonics(self.orders[keep], self.amplitudes[keep], self.phases[keep])

    def derivative(self) -> Harmonics:
        """dr/dθ as harmonics: order k, amplitude k a_k, phase φ_k + π/2 (order 0 drops)."""
        return Harmonics(self.orders, self.amplitudes * self.orders, self.phases + 0.5 * math.pi)

    def diameter_deviation(self) -> Harmonics:
        r"""Diameter deviation along the contact line, ``r(θ) + r(θ + π)`` (seed 002 eq. 26).

        .. math:: w_b(\theta) = 2 \sum_{k\ \mathrm{even}} a_k \cos(k\theta + \varphi_k)

        Odd orders cancel; even orders (order 0 included) double. θ is the angle of the
        contact point in the element's own frame.
        """
        even = self.orders % 2 == 0
        return Harmonics(self.orders[even], 2.0 * self.amplitudes[even], self.phases[even])

    # --- evaluation ---------------------------------------------------------------------------
    def evaluate(self, theta: ArrayLike) -> NDArray[np.float64]:
        """r(θ) [m] at angles θ [rad] (any shape; the result has the same shape).

        Uses the Numba kernel :func:`runout.geometry._kernels.harmonic_sum` for large inputs and the
        NumPy expression otherwise; both agree to about 1e-16 Σ a_k.
        """
        t = np.asarray(theta, dtype=np.float64)
        flat = np.ascontiguousarray(t.reshape(-1))
        k = self.orders.astype(np.float64)
        if self.orders.size == 0:
            out = np.zeros(flat.size)
        elif flat.size * self.orders.size >= KERNEL_THRESHOLD:
            from runout.geometry._kernels import harmonic_sum

            out = harmonic_sum(
                flat,
                k,
                np.ascontiguousarray(self.amplitudes),
                np.ascontiguousarray(self.phases),
            )
        else:
            out = (
                self.amplitudes[:, None] * np.cos(k[:, None] * flat[None, :] + self.phases[:, None])
            ).sum(axis=0)
        return out.reshape(t.shape)

    def __call__(self, theta: ArrayLike) -> NDArray[np.float64]:
        """Same as :meth:`evaluate`."""
        return self.evaluate(theta)

    def peak_to_peak(self, samples: int | None = None) -> float:
        """max r − min r over a turn [m], found numerically.

        The profile is sampled on ``samples`` equally spaced angles (default
        ``max(512, 32 · max_order)``); the three highest local maxima and three lowest local
        minima are then polished by Newton's method on r'(θ) = 0 within their grid cell, so a
        single harmonic gives ``2 a_k`` to rounding error.
        """
        if self.is_empty or self.max_order == 0:
            return 0.0
        n = samples if samples is not None else max(512, 32 * self.max_order)
        if n < 8:
            raise ImperfectionError("peak_to_peak.samples", f"must be >= 8, got {n}")
        step = TWO_PI / n
        theta = np.arange(n) * step
        v = self.evaluate(theta)
        d1 = self.derivative()
        d2 = d1.derivative()
        extremes = []
        for sign in (1.0, -1.0):
            s = sign * v
            is_peak = (s >= np.roll(s, 1)) & (s >= np.roll(s, -1))
            idx = np.flatnonzero(is_peak)
            idx = idx[np.argsort(s[idx])[::-1][:3]]
            t = theta[idx]
            lo, hi = t - step, t + step
            for _ in range(20):
                curvature = d2.evaluate(t)
                ok = curvature * sign < 0.0
                if not ok.any():
                    break
                t_new = np.where(ok, t - d1.evaluate(t) / np.where(ok, curvature, 1.0), t)
                t_new = np.clip(t_new, lo, hi)
                if np.array_equal(t_new, t):
                    break
                t = t_new
            extremes.append(max(float(s.max()), float((sign * self.evaluate(t)).max())))
        return extremes[0] + extremes[1]


def _normalise(
    k: NDArray[np.int64], a: NDArray[np.float64], p: NDArray[np.float64]
) -> tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.float64]]:
    """Unique sorted orders, amplitudes ≥ 0, phases in [0, 2π), order 0 phase 0 or π."""
    a = a.copy()
    p = p.copy()
    zero = k == 0
    if zero.any():  # a size error: keep only the constant a cos φ
        a[zero] = a[zero] * np.cos(p[zero])
        p[zero] = 0.0
    uniq, inverse, counts = np.unique(k, return_inverse=True, return_counts=True)
    if uniq.size != k.size:
        c = np.zeros(uniq.size, dtype=np.complex128)
        np.add.at(c, inverse, a * np.exp(1j * p))
        a_new = np.abs(c)
        p_new = np.angle(c)
        # keep the exact input values of the orders that were not merged
        single = counts == 1
        position = np.empty(uniq.size, dtype=np.int64)
        position[inverse] = np.arange(k.size)
        a_new[single] = a[position[single]]
        p_new[single] = p[position[single]]
        k, a, p = uniq, a_new, p_new
    else:
        order = np.argsort(k, kind="stable")
        k, a, p = k[order], a[order], p[order]
    negative = a < 0
    a[negative] = -a[negative]
    p[negative] = p[negative] + math.pi
    p = _wrap_phase(p)
    keep = a != 0.0
    return k[keep], a[keep], p[keep]


def pack_harmonics(
    parts: Sequence[Harmonics],
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]]:
    """Pack several profiles for :func:`runout.geometry._kernels.harmonic_sum_rows`.

    Returns
    -------
    orders, amplitudes, phases : ndarray of float64, shape (K,)
        All harmonics one profile after the other (orders as float64).
    offsets : ndarray of int64, shape (len(parts) + 1,)
        Profile z owns entries ``offsets[z]:offsets[z+1]``.
    """
    sizes = np.array([len(h) for h in parts], dtype=np.int64)
    offsets = np.zeros(len(parts) + 1, dtype=np.int64)
    np.cumsum(sizes, out=offsets[1:])
    if len(parts):
        k = np.concatenate([h.orders for h in parts]).astype(np.float64)
        a = np.concatenate([h.amplitudes for h in parts]).astype(np.float64)
        p = np.concatenate([h.phases for h in parts]).astype(np.float64)
    else:
        k = a = p = np.zeros(0)
    return np.ascontiguousarray(k), np.ascontiguousarray(a), np.ascontiguousarray(p), offsets


# --------------------------------------------------------------------------------------------
# Builders
# --------------------------------------------------------------------------------------------
def single_harmonic(
    order: int,
    amplitude: float | None = None,
    phase: float = 0.0,
    peak_to_peak: float | None = None,
) -> Harmonics:
    """One harmonic ``a cos(k θ + φ)``.

    Parameters
    ----------
    order : int
        k ≥ 0. Order 0 is a size (radius) deviation and cannot be given peak-to-peak.
    amplitude : float, optional
        Zero-to-peak amplitude a [m] (a negative value flips the phase by π).
    phase : float
        φ [rad].
    peak_to_peak : float, optional
        Peak-to-peak value 2a [m], instead of ``amplitude``; it is halved.
    """
    if (amplitude is None) == (peak_to_peak is None):
        raise ImperfectionError(
            "waviness", "give exactly one of amplitude (zero-to-peak) and peak_to_peak"
        )
    order = _real_scalar("waviness.order", order)
    amplitude = _real_scalar("waviness.amplitude", amplitude)
    peak_to_peak = _real_scalar("waviness.peak_to_peak", peak_to_peak)
    phase = _real_scalar("waviness.phase", phase)
    if isinstance(order, bool) or not float(order).is_integer():
        raise ImperfectionError("waviness.order", f"must be a whole number, got {order!r}")
    if peak_to_peak is not None:
        if int(order) == 0:
            raise ImperfectionError(
                "waviness.peak_to_peak",
                "order 0 is a size error without peaks; give its amplitude instead",
            )
        if not (math.isfinite(peak_to_peak) and peak_to_peak >= 0.0):
            raise ImperfectionError(
                "waviness.peak_to_peak", f"must be a finite value >= 0, got {peak_to_peak!r}"
            )
        amplitude = 0.5 * peak_to_peak
    assert amplitude is not None
    if not math.isfinite(amplitude):
        raise ImperfectionError("waviness.amplitude", f"must be finite, got {amplitude!r}")
    if not math.isfinite(phase):
        raise ImperfectionError("waviness.phase", f"must be finite, got {phase!r}")
    return Harmonics([int(order)], [float(amplitude)], [float(phase)])


def _two_orders(key: str, orders: object) -> tuple[int, int]:
    """(k1, k2) from a pair of whole numbers, or an ImperfectionError naming ``key``."""
    message = f"must be two whole numbers [k1, k2], got {orders!r}"
    if isinstance(orders, str | bytes) or not isinstance(orders, Sequence | np.ndarray):
        raise ImperfectionError(key, message)
    values = list(orders)
    if len(values) != 2:
        raise ImperfectionError(key, message)
    out = []
    for v in values:
        if isinstance(v, bool):
            raise ImperfectionError(key, message)
        try:
            f = float(v)
        except (TypeError, ValueError) as exc:
            raise ImperfectionError(key, message) from exc
        if not (math.isfinite(f) and f.is_integer()):
            raise ImperfectionError(key, message)
        out.append(int(f))
    return out[0], out[1]


def _make_rng(seed: int | None, rng: np.random.Generator | None, what: str) -> np.random.Generator:
    if seed is not None and rng is not None:
        raise ImperfectionError(what, "give either seed or rng, not both")
    if rng is not None:
        if not isinstance(rng, np.random.Generator):
            raise ImperfectionError(what, f"rng must be a numpy.random.Generator, got {rng!r}")
        return rng
    if seed is None:
        raise ImperfectionError(
            what, 'phase="random" needs a seed (or an rng) so that results are reproducible'
        )
    return np.random.default_rng(seed)


def spectral_law(
    orders: tuple[int, int] | Sequence[int],
    amplitude: float,
    exponent: float,
    phase: float | str = "random",
    seed: int | None = None,
    rng: np.random.Generator | None = None,
) -> Harmonics:
    r"""A waviness spectrum ``a_k = amplitude · k^exponent`` for k1 ≤ k ≤ k2 (inclusive).

    Seed 002 eq. 45-47 use ``0.1 µm · k^-1.5`` on half-open ranges ``2 ≤ k < K``; the same
    spectrum here is ``orders=(2, K - 1)``, e.g. eq. 45 (inner ring) is
    ``spectral_law((2, 799), 0.1e-6, -1.5, seed=...)``.

    Parameters
    ----------
    orders : (int, int)
        First and last order (k1 ≥ 1, k2 ≥ k1), both included.
    amplitude : float
        Zero-to-peak amplitude at k = 1 [m] (≥ 0).
    exponent : float
        Power of k.
    phase : float or "random"
        One phase for every order [rad], or independent phases uniform in [0, 2π) drawn from
        the generator in increasing order of k.
    seed : int, optional
        Seed of ``numpy.random.default_rng`` (random phases only).
    rng : numpy.random.Generator, optional
        Generator to draw from instead of a seed (it advances by k2 − k1 + 1 draws).
    """
    k1, k2 = _two_orders("waviness_spectrum.orders", orders)
    if k1 < 1 or k2 < k1:
        raise ImperfectionError(
            "waviness_spectrum.orders",
            f"need 1 <= k1 <= k2 (order 0 is a size error, not a spectrum), got [{k1}, {k2}]",
        )
    if k2 > MAX_ORDER:  # before k2 - k1 + 1 orders are allocated
        raise ImperfectionError(
            "waviness_spectrum.orders",
            f"order {k2} is beyond {MAX_ORDER}: a wave that short is shorter than any contact "
            "and is filtered out by it",
        )
    amplitude = _real_scalar("waviness_spectrum.amplitude", amplitude)
    exponent = _real_scalar("waviness_spectrum.exponent", exponent)
    if not isinstance(phase, str):
        phase = _real_scalar("waviness_spectrum.phase", phase)
    if not (math.isfinite(amplitude) and amplitude >= 0.0):
        raise ImperfectionError(
            "waviness_spectrum.amplitude", f"must be a finite value >= 0, got {amplitude!r}"
        )
    if not math.isfinite(exponent):
        raise ImperfectionError("waviness_spectrum.exponent", f"must be finite, got {exponent!r}")
    k = np.arange(k1, k2 + 1, dtype=np.int64)
    a = amplitude * np.power(k.astype(np.float64), exponent)
    if not np.isfinite(a).all():
        raise ImperfectionError(
            "waviness_spectrum.exponent", "amplitude * k**exponent overflows for these orders"
        )
    if isinstance(phase, str):
        if phase != "random":
            raise ImperfectionError(
                "waviness_spectrum.phase", f'must be an angle or "random", got {phase!r}'
            )
        gen = _make_rng(seed, rng, "waviness_spectrum.seed")
        p = gen.uniform(0.0, TWO_PI, size=k.size)
    else:
        if seed is not None or rng is not None:
            raise ImperfectionError(
                "waviness_spectrum.seed", "a seed or rng only makes sense with phase='random'"
            )
        if not math.isfinite(phase):
            raise ImperfectionError("waviness_spectrum.phase", f"must be finite, got {phase!r}")
        p = np.full(k.size, float(phase))
    return Harmonics(k, a, p)
