r"""Geometric imperfections of a bearing's parts: waviness, size, pitch and slant errors.

Conventions
-----------
* SI inside: deviations in metres [m], angles in radians [rad]. No units library here; the
  case reader converts units before calling these functions.
* A part's radius deviation is a Fourier series in the part's own frame,

  .. math:: r(\theta) = \sum_k a_k \cos(k\theta + \varphi_k),

  with θ counter-clockwise from the part's +x axis. A ring's frame turns with the ring; a
  rolling element's frame turns with its spin. ``a_k`` is the **zero-to-peak amplitude of the
  radius deviation**; a ``peak_to_peak`` input is halved (single harmonics). After
  normalisation orders are unique and sorted, amplitudes are ≥ 0 (a negative amplitude becomes
  positive with the phase advanced by π) and phases lie in [0, 2π).
* Order 0 is a size error only: the order-0 term is the constant ``a_0 cos φ_0``, stored as
  ``|a_0 cos φ_0|`` with phase 0 or π. For a ball it is a *radius* deviation; the diameter
  changes by twice that.
* A ball or roller touches both raceways at opposite ends of a diameter, so the models need the
  **diameter deviation along the contact line**, ``w_b(θ) = r(θ) + r(θ + π)
  = 2 Σ_{k even} a_k cos(kθ + φ_k)`` (seed 002 eq. 26): odd orders cancel, even orders double
  (:meth:`Harmonics.diameter_deviation`).
* Rolling elements are numbered 1..Z in user-facing arguments (the ``element`` argument of
  :meth:`Imperfections.add`, the ``element`` key of case files and of :meth:`summary` rows) and
  indexed 0..Z-1 everywhere else (tuple positions, ``index`` arguments, arrays).
* ``pitch_errors[j]`` is the angular position error of element j relative to equal spacing
  [rad], positive counter-clockwise (ahead of its nominal place in the +θ sense).
* Randomness only through a :class:`numpy.random.Generator` passed in, or one created by
  ``numpy.random.default_rng(seed)`` from a given seed; never global state.

How the source papers write the same quantities
-----------------------------------------------
============================  ===============================================================
paper                         mapping onto :class:`Imperfections`
============================  ===============================================================
seed 002 eq. 23-25            ``W_ik, φ_ik`` → ``inner``; ``W_ok, φ_ok`` → ``outer``;
                              ``W_bzk, φ_bzk`` (ball radius) → ``elements[z]`` (z = 0..Z-1).
                              Eq. 23 includes order 1 (eccentricity), eq. 24 starts at 2, eq. 25
                              includes order 0 (radius relative to the set's mean); we allow
                              every order ≥ 0 on every part and leave it to the models.
seed 002 eq. 26               ``w_bz`` → ``element_diameter_deviation(z)`` (also adds
                              ``diameter_errors[z]``).
seed 002 eq. 34-35            ``W_s, φ_s`` → :class:`Slant` (term ``W_s cos(2θ - φ_s)``).
seed 001 eq. 11-12            ``a_rn, φ_rn`` → ``inner``; ``a_Rn, φ_Rn`` → ``outer`` (``r_0,
                              R_0`` are the nominal radii, not imperfections).
seed 001 eq. 13               ``d_k0 - d`` → ``diameter_errors[k-1]``; ``a_bkn, φ_bkn`` →
                              ``elements[k-1]`` (radius waviness); the second sum is the
                              radius at the opposite end of the diameter, see Notes.
seed 004 eq. 1, 4-7           ``ΔD_j`` → ``diameter_errors[j-1]``; ``C_rjm, φ_rjm`` →
                              ``elements[j-1]`` (the roller frame angle θ_rj + γ₁ of eq. 7 is
                              our element frame); ``Δd_i / 2`` → order 0 of ``inner`` and
                              ``C_im, φ_im`` → ``inner`` (θ_i - α of eq. 5 is the ring frame);
                              likewise ``Δd_e / 2`` and ``C_em`` → ``outer``.
seed 000 §2.1                 ``a_i, a_o, a_b`` are given peak-to-peak ("total amplitude") in
                              Tada's examples: use ``peak_to_peak=`` (halved). Tada measures
                              ball angles clockwise; :meth:`Harmonics.mirrored` converts a
                              clockwise profile.
============================  ===============================================================

Notes
-----
* Seed 001 eq. 13 as extracted reads ``Σ a cos(nω_b t + φ) + Σ a cos(nω_b t + π + φ)``; taken
  literally the two sums cancel for every n. The intended second term is the opposite point
  ``a cos(n(ω_b t + π) + φ)``, which is seed 002 eq. 26 and agrees with seed 001's abstract
  (ball form errors act through even orders only). We implement that reading.
* Seed 002 eq. 45-47 give the spectra on half-open ranges, e.g. ``2 ≤ k < 800``; our
  ``orders=(k1, k2)`` is inclusive on both ends, so eq. 45 is ``orders=(2, 799)`` (see
  :func:`anderon_608_example`).
* Seed 002 eq. 34 uses a radius ``r_o`` that is not defined anywhere in the extracted text (it
  comes from the missing Fig. 10). See :class:`Slant` for the reading we adopt.
"""

from __future__ import annotations

import csv
import math
import os
import stat
import warnings
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.errors import GeometryError

if TYPE_CHECKING:
    from runout.bearing import Bearing

__all__ = [
    "Harmonics",
    "ImperfectionError",
    "Imperfections",
    "ProfileError",
    "ProfileWarning",
    "Slant",
    "anderon_608_example",
    "from_profile",
    "pack_harmonics",
    "read_profile_csv",
    "single_harmonic",
    "slant_amplitude",
    "slant_angle",
    "spectral_law",
]

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


def _as_float_vector(name: str, values: ArrayLike) -> NDArray[np.float64]:
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
    if (arr > 2**31).any():
        raise ImperfectionError(name, f"order {int(arr.max())} is unreasonably large")
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

        Uses the Numba kernel :func:`runout._kernels.harmonic_sum` for large inputs and the
        NumPy expression otherwise; both agree to about 1e-16 Σ a_k.
        """
        t = np.asarray(theta, dtype=np.float64)
        flat = np.ascontiguousarray(t.reshape(-1))
        k = self.orders.astype(np.float64)
        if self.orders.size == 0:
            out = np.zeros(flat.size)
        elif flat.size * self.orders.size >= KERNEL_THRESHOLD:
            from runout._kernels import harmonic_sum

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
    """Pack several profiles for :func:`runout._kernels.harmonic_sum_rows`.

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


def _uniform_grid(
    theta: NDArray[np.float64], tolerance: float
) -> tuple[NDArray[np.int64], float] | None:
    """If the angles are a full turn sampled uniformly: (sort order, θ0); else None."""
    n = theta.size
    wrapped = np.mod(theta, TWO_PI)
    order = np.argsort(wrapped, kind="stable")
    s = wrapped[order]
    step = TWO_PI / n
    offsets = s - np.arange(n) * step
    # offsets are all ≈ θ0 (mod 2π) for a uniform grid; compare on the circle
    ref = offsets[0]
    dev = np.angle(np.exp(1j * (offsets - ref)))
    if np.max(np.abs(dev)) > tolerance * step:
        return None
    theta0 = float(ref + np.mean(dev))
    return order, theta0


def from_profile(
    angles: ArrayLike,
    deviations: ArrayLike,
    orders: tuple[int, int] | Sequence[int] | None = None,
    *,
    keep_mean: bool = False,
    method: Literal["auto", "fft", "lstsq"] = "auto",
    uniform_tolerance: float = 1e-3,
) -> Harmonics:
    r"""Harmonics of a measured roundness profile (seed 004 §3, seed 001 §4.1).

    Parameters
    ----------
    angles : array_like, shape (N,)
        Measuring angles [rad] in the part's frame, counter-clockwise, any order.
    deviations : array_like, shape (N,)
        Radius deviations [m] at those angles.
    orders : (int, int), optional
        Orders kept, ``k1 ≤ k ≤ k2`` inclusive, ``k1 ≥ 1``. Default for a uniform full-turn
        profile: every order below the Nyquist order N/2; required otherwise.
    keep_mean : bool
        Keep the mean radius deviation as order 0 (a size error). Default False: a roundness
        instrument's mean radius is arbitrary.
    method : {"auto", "fft", "lstsq"}
        ``"auto"`` uses the FFT when the angles are a full turn sampled uniformly (within
        ``uniform_tolerance`` of a step, after removing a closing sample at 360°), else linear
        least squares on ``[1, cos kθ, sin kθ]`` for the kept orders (the mean is always
        fitted, and dropped unless ``keep_mean``).
    uniform_tolerance : float
        Largest departure from the uniform grid still treated as uniform, as a fraction of the
        step (1e-3 accepts angles printed to a few decimals; the resulting amplitude error is
        below ``π · tolerance`` of the amplitude at the Nyquist order).

    Returns
    -------
    Harmonics

    Raises
    ------
    ProfileError
        Too few samples, non-finite values, orders at or above the Nyquist order of a uniform
        profile, or a least-squares problem with more unknowns than samples or without full
        rank.

    Warns
    -----
    ProfileWarning
        Irregular sampling whose largest gap exceeds half a wavelength of order k2, or an
        ill-conditioned fit (e.g. a short arc).

    Notes
    -----
    For samples θ_n = θ_0 + 2πn/N the DFT gives ``a_k e^{iφ_k} = (2/N) X_k e^{-ikθ_0}``
    (0 < k < N/2) and the mean ``X_0/N``. Orders outside [k1, k2] present in the data alias onto
    the kept ones in the least-squares case; filter first when that matters.
    """
    th = _profile_vector("angles", angles)
    dev = _profile_vector("deviations", deviations)
    if th.size != dev.size:
        raise ProfileError("", None, f"{th.size} angles but {dev.size} deviations")
    if th.size < 3:
        raise ProfileError("", None, f"need at least 3 samples, got {th.size}")
    if not (0.0 < uniform_tolerance < 0.5):
        raise ProfileError(
            "", None, f"uniform_tolerance must lie in (0, 0.5), got {uniform_tolerance}"
        )
    if method not in ("auto", "fft", "lstsq"):
        raise ProfileError("", None, f'method must be "auto", "fft" or "lstsq", got {method!r}')
    # a closing sample (the first angle repeated one turn later) carries no information
    span = th.max() - th.min()
    if th.size > 3 and abs(span - TWO_PI) <= uniform_tolerance * TWO_PI / (th.size - 1):
        last = int(np.argmax(th))
        th = np.delete(th, last)
        dev = np.delete(dev, last)
    n = th.size

    grid = _uniform_grid(th, uniform_tolerance) if method != "lstsq" else None
    if method == "fft" and grid is None:
        raise ProfileError(
            "", None, "method='fft' needs a full turn sampled at equal steps; use 'lstsq'"
        )
    k1, k2 = _profile_orders(orders, n if grid is not None else None)

    if grid is not None:
        if 2 * k2 >= n:
            raise ProfileError(
                "",
                None,
                f"{n} equally spaced samples resolve orders below {math.ceil(n / 2)} "
                f"(Nyquist); order {k2} was asked for: lower the highest order or sample finer",
            )
        idx, theta0 = grid
        spectrum = np.fft.rfft(dev[idx])
        k = np.arange(k1, k2 + 1)
        c = (2.0 / n) * spectrum[k] * np.exp(-1j * k * theta0)
        mean = float(spectrum[0].real / n)
    else:
        k, c, mean = _least_squares(th, dev, k1, k2)
    h = Harmonics.from_complex(k, c)
    if keep_mean:
        h = h + Harmonics([0], [mean])
    return h


def _profile_vector(name: str, values: ArrayLike) -> NDArray[np.float64]:
    try:
        arr = np.asarray(values, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError) as exc:
        raise ProfileError("", None, f"{name} must be numbers") from exc
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ProfileError("", None, f"{name}[{i}] is {arr[i]!r}; every value must be finite")
    return arr


def _profile_orders(
    orders: tuple[int, int] | Sequence[int] | None, n_uniform: int | None
) -> tuple[int, int]:
    if orders is None:
        if n_uniform is None:
            raise ProfileError(
                "", None, "irregular or partial sampling: give orders=(k1, k2) explicitly"
            )
        k2 = (n_uniform - 1) // 2
        if k2 < 1:
            raise ProfileError("", None, f"{n_uniform} samples resolve no order >= 1")
        return 1, k2
    try:
        k1, k2 = _two_orders("orders", orders)
    except ImperfectionError as exc:
        raise ProfileError("", None, f"orders {exc.message}") from None
    if k1 == 0:
        raise ProfileError(
            "", None, "orders start at 1; the mean (order 0) is controlled by keep_mean=True"
        )
    if k1 < 1 or k2 < k1:
        raise ProfileError("", None, f"orders need 1 <= k1 <= k2, got ({k1}, {k2})")
    return k1, k2


_LSTSQ_MAX_ELEMENTS = 40_000_000


def _least_squares(
    th: NDArray[np.float64], dev: NDArray[np.float64], k1: int, k2: int
) -> tuple[NDArray[np.int64], NDArray[np.complex128], float]:
    k = np.arange(k1, k2 + 1)
    unknowns = 1 + 2 * k.size
    n = th.size
    if n < unknowns:
        raise ProfileError(
            "",
            None,
            f"{n} samples cannot determine {unknowns} unknowns (mean + cos/sin of orders "
            f"{k1}..{k2}); need at least {unknowns} samples or fewer orders",
        )
    if n * unknowns > _LSTSQ_MAX_ELEMENTS:
        raise ProfileError(
            "",
            None,
            f"least-squares fit of {n} samples x {unknowns} unknowns is too large; resample "
            "the profile on a uniform full-turn grid (FFT) or ask for fewer orders",
        )
    s = np.sort(np.mod(th, TWO_PI))
    gaps = np.diff(np.concatenate([s, [s[0] + TWO_PI]]))
    arc = TWO_PI - float(gaps.max())
    inner_gap = float(np.sort(gaps)[-2]) if arc < 0.99 * TWO_PI else float(gaps.max())
    if inner_gap * k2 > math.pi:
        warnings.warn(
            f"the largest gap between profile samples ({math.degrees(inner_gap):.4g} deg) "
            f"exceeds half a wavelength of order {k2} ({180.0 / k2:.4g} deg): amplitudes near "
            f"that order are poorly determined",
            ProfileWarning,
            stacklevel=3,
        )
    phase = th[:, None] * k[None, :]
    design = np.empty((n, unknowns))
    design[:, 0] = 1.0
    design[:, 1::2] = np.cos(phase)
    design[:, 2::2] = np.sin(phase)
    sol, _, rank, sv = np.linalg.lstsq(design, dev, rcond=None)
    if rank < unknowns:
        raise ProfileError(
            "",
            None,
            f"the samples cannot separate orders {k1}..{k2} (rank {rank} of {unknowns}); the "
            "angles repeat or cover too little of a turn",
        )
    cond = float(sv[0] / sv[-1])
    if cond > 1e8:
        warnings.warn(
            f"ill-conditioned profile fit (condition number {cond:.3g}, arc covered "
            f"{math.degrees(arc):.4g} deg): the harmonics are not well determined",
            ProfileWarning,
            stacklevel=3,
        )
    # r = A cos kθ + B sin kθ = a cos(kθ + φ) with A = a cos φ, B = -a sin φ
    c = sol[1::2] - 1j * sol[2::2]
    return k, c, float(sol[0])


def read_profile_csv(
    path: str | Path,
    angle_unit: Literal["deg", "rad"] = "deg",
    deviation_scale: float = 1.0,
    *,
    delimiter: str | None = None,
    columns: tuple[int, int] = (0, 1),
    max_bytes: int | None = None,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Read a roundness profile: two columns, angle and radius deviation.

    Parameters
    ----------
    path : str or Path
        CSV file. Blank lines and lines starting with ``#`` are skipped; the first remaining
        line may be a header (it is skipped when its columns are not numbers).
    angle_unit : {"deg", "rad"}
        Unit of the angle column.
    deviation_scale : float
        Factor turning the deviation column into metres (1e-6 for µm, 1e-9 for nm).
    delimiter : str, optional
        Column separator; default: detected from the first data line (``,``, ``;``, tab,
        else whitespace).
    columns : (int, int)
        0-based column indices of angle and deviation.
    max_bytes : int, optional
        Largest file read [bytes]; only a regular file is opened when it is given (a device
        such as /dev/zero, or a FIFO, never ends).

    Returns
    -------
    angles : ndarray
        [rad].
    deviations : ndarray
        [m].

    Raises
    ------
    ProfileError
        Missing file, a row that is not two finite numbers (naming the file and line, never
        echoing the line: a profile may be any file), a file that is not UTF-8 text or is
        larger than ``max_bytes``, or no data at all.
    """
    name = str(path)
    if angle_unit not in ("deg", "rad"):
        raise ProfileError(name, None, f'angle_unit must be "deg" or "rad", got {angle_unit!r}')
    if not (math.isfinite(deviation_scale) and deviation_scale > 0.0):
        raise ProfileError(
            name, None, f"deviation_scale must be a positive number, got {deviation_scale!r}"
        )
    text = _read_text(Path(path), name, max_bytes)
    ia, idv = columns
    angles: list[float] = []
    devs: list[float] = []
    sep = delimiter
    first = True
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        if sep is None:
            sep = next((d for d in (",", ";", "\t") if d in line), " ")
        fields = _split(line, sep)
        try:
            a = float(fields[ia])
            d = float(fields[idv])
        except (ValueError, IndexError):
            if first:  # a header line
                first = False
                continue
            raise ProfileError(
                name,
                lineno,
                f"expected numbers in columns {ia + 1} and {idv + 1} separated by {_sep_name(sep)}",
            ) from None
        first = False
        if not (math.isfinite(a) and math.isfinite(d)):
            raise ProfileError(name, lineno, "non-finite value")
        angles.append(a)
        devs.append(d)
    if not angles:
        raise ProfileError(name, None, "no data rows")
    ang = np.array(angles)
    if angle_unit == "deg":
        ang = np.deg2rad(ang)
    return ang, np.array(devs) * deviation_scale


def _read_text(path: Path, name: str, max_bytes: int | None) -> str:
    """The file's text, reading no more than ``max_bytes`` and only from a regular file."""
    try:
        if max_bytes is None:
            return path.read_text(encoding="utf-8-sig")
        # O_NONBLOCK: opening a FIFO must not wait for a writer before it is found out
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as handle:
            if not stat.S_ISREG(os.fstat(handle.fileno()).st_mode):
                raise ProfileError(name, None, "is not a regular file")
            raw = handle.read(max_bytes + 1)
    except OSError as exc:
        raise ProfileError(name, None, f"cannot read the file: {exc.strerror or exc}") from exc
    except UnicodeDecodeError as exc:
        raise ProfileError(
            name, None, f"is not UTF-8 text (byte {exc.start + 1} cannot be decoded)"
        ) from None
    if len(raw) > max_bytes:
        raise ProfileError(name, None, f"is larger than {max_bytes} bytes")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ProfileError(
            name, None, f"is not UTF-8 text (byte {exc.start + 1} cannot be decoded)"
        ) from None


def _split(line: str, sep: str) -> list[str]:
    if sep == " ":
        return line.split()
    return [f.strip() for f in next(csv.reader([line], delimiter=sep))]


def _sep_name(sep: str) -> str:
    return {",": "commas", ";": "semicolons", "\t": "tabs", " ": "whitespace"}.get(sep, repr(sep))


# --------------------------------------------------------------------------------------------
# Slant
# --------------------------------------------------------------------------------------------
def slant_amplitude(angle: float, radius: float) -> float:
    r"""W_s from a slant angle β (seed 002 eq. 34): ``W_s = r (1 − cos β) / (2 cos β)`` [m].

    Evaluated as ``r sin²(β/2) / cos β`` (no cancellation for small β).
    """
    _check_radius(radius)
    if not (math.isfinite(angle) and 0.0 <= abs(angle) < 0.5 * math.pi):
        raise ImperfectionError("slant.angle", f"must lie in (-90, 90) deg, got {angle!r} rad")
    return radius * math.sin(0.5 * angle) ** 2 / math.cos(angle)


def slant_angle(amplitude: float, radius: float) -> float:
    """Inverse of :func:`slant_amplitude`: β = 2 asin √(W_s / (r + 2 W_s)) [rad] (≥ 0)."""
    _check_radius(radius)
    if not (math.isfinite(amplitude) and amplitude >= 0.0):
        raise ImperfectionError(
            "slant.amplitude", f"must be a finite value >= 0, got {amplitude!r}"
        )
    return 2.0 * math.asin(math.sqrt(amplitude / (radius + 2.0 * amplitude)))


def _check_radius(radius: float) -> None:
    if not (math.isfinite(radius) and radius > 0.0):
        raise ImperfectionError("slant.radius", f"must be a positive length, got {radius!r}")


@dataclass(frozen=True)
class Slant:
    r"""Slant of the inner raceway against the rotation axis (seed 002 eq. 34-35).

    It shakes the bearing twice per revolution of the inner ring; seed 002 adds the term
    ``W_s cos(2θ − φ_s)`` to the inner-ring displacement x_i (eq. 35, before the ``cos α`` of
    eq. 41), θ the inner-ring rotation angle.

    Parameters
    ----------
    amplitude : float
        W_s, zero-to-peak [m] (≥ 0); the displacement's peak-to-peak is 2 W_s.
    phase : float
        φ_s [rad]; note the minus sign in ``cos(2θ − φ_s)`` (seed 002's convention).

    Notes
    -----
    Eq. 34, ``W_s = r_o (1 − cos β) / (2 cos β)``, comes from the drawing of Fig. 10, which is
    missing from the extracted text, and ``r_o`` is not in the paper's symbol list. The formula
    is that of a circle of radius r_o tilted by β and cut by a plane normal to the axis (an
    ellipse with semi-axes r_o and r_o / cos β), the tilt direction turning with the inner ring.
    Since seed 002 measures the outer ring's radial displacement, r_o is most plausibly the
    radius of the outer ring surface that the pick-up touches; the bearing description knows
    only the outer raceway, so :meth:`from_bearing` uses the outer raceway radius
    ``d_o / 2`` unless ``radius`` is given (pass the outer ring's outside radius when known).
    Seed 002's own example gives W_s directly (eq. 44: 0.05 µm), which needs no radius.
    """

    amplitude: float
    phase: float = 0.0

    def __post_init__(self) -> None:
        if not (isinstance(self.amplitude, int | float) and math.isfinite(self.amplitude)):
            raise ImperfectionError("slant.amplitude", f"must be finite, got {self.amplitude!r}")
        if self.amplitude < 0.0:
            raise ImperfectionError(
                "slant.amplitude",
                f"must be >= 0 (for a negative W_s add π to the phase), got {self.amplitude!r}",
            )
        if not (isinstance(self.phase, int | float) and math.isfinite(self.phase)):
            raise ImperfectionError("slant.phase", f"must be finite, got {self.phase!r}")

    @classmethod
    def from_angle(cls, angle: float, radius: float | Bearing, phase: float = 0.0) -> Slant:
        """Slant of angle β [rad] seen at radius r_o (eq. 34).

        ``radius`` is r_o [m], or a bearing whose outer raceway radius ``d_o / 2`` is used (see
        the Notes of the class).
        """
        if isinstance(radius, int | float):
            return cls(slant_amplitude(angle, float(radius)), phase)
        return cls(slant_amplitude(angle, 0.5 * radius.outer_raceway_diameter), phase)

    @classmethod
    def from_bearing(
        cls,
        bearing: Bearing,
        *,
        amplitude: float | None = None,
        angle: float | None = None,
        phase: float = 0.0,
        radius: float | None = None,
    ) -> Slant:
        """Slant given by W_s or by β, converted with the bearing's geometry.

        Parameters
        ----------
        bearing : BallBearing or RollerBearing
            Supplies the default radius, ``bearing.outer_raceway_diameter / 2`` (see Notes of
            the class).
        amplitude, angle : float
            Exactly one: W_s [m] or β [rad].
        phase : float
            φ_s [rad].
        radius : float, optional
            The r_o of eq. 34 [m], overriding the default.
        """
        if (amplitude is None) == (angle is None):
            raise ImperfectionError("slant", "give exactly one of amplitude (W_s) and angle")
        if amplitude is not None:
            return cls(float(amplitude), phase)
        assert angle is not None
        r = 0.5 * bearing.outer_raceway_diameter if radius is None else radius
        return cls.from_angle(angle, r, phase)

    def angle(self, radius: float) -> float:
        """The slant angle β [rad] that gives this W_s at radius r [m]."""
        return slant_angle(self.amplitude, radius)

    @property
    def peak_to_peak(self) -> float:
        """2 W_s [m]."""
        return 2.0 * self.amplitude

    def displacement(self, theta: ArrayLike) -> NDArray[np.float64]:
        """``W_s cos(2θ − φ_s)`` [m] at inner-ring angles θ [rad] (seed 002 eq. 35)."""
        t = np.asarray(theta, dtype=np.float64)
        return self.amplitude * np.cos(2.0 * t - self.phase)

    def __add__(self, other: object) -> Slant:
        if not isinstance(other, Slant):
            return NotImplemented
        c = self.amplitude * np.exp(-1j * self.phase) + other.amplitude * np.exp(-1j * other.phase)
        return Slant(float(abs(c)), float(_wrap_phase(np.array([-np.angle(c)]))[0]))


# --------------------------------------------------------------------------------------------
# Imperfections of a whole bearing
# --------------------------------------------------------------------------------------------
def _element_vector(name: str, values: ArrayLike | None, n: int) -> NDArray[np.float64]:
    if values is None:
        return np.zeros(n)
    arr = _as_float_vector(f"imperfections.{name}", values)
    if arr.size != n:
        raise ImperfectionError(
            f"imperfections.{name}", f"needs one value per rolling element ({n}), got {arr.size}"
        )
    return arr


@dataclass(frozen=True, init=False, eq=False)
class Imperfections:
    """Every geometric imperfection of one bearing.

    Parameters
    ----------
    inner, outer : Harmonics
        Radius deviation of the inner and outer raceway in the ring's own frame [m].
    elements : sequence of Harmonics, or int
        Radius deviation of each rolling element (length Z), in the element's frame [m]; or
        the number of elements Z, all perfect.
    diameter_errors : array_like, shape (Z,)
        Diameter deviation of each element from the nominal diameter [m].
    pitch_errors : array_like, shape (Z,)
        Angular position error of each element relative to equal spacing [rad], positive
        counter-clockwise.
    slant : Slant, optional
        Inner-raceway slant (seed 002 eq. 34).

    Notes
    -----
    Z is taken from ``elements``, else from ``diameter_errors`` or ``pitch_errors``; missing
    per-element data default to perfect: ``Imperfections(elements=8, outer=...)`` is a bearing
    of 8 perfect elements with a wavy outer raceway. Without any of them Z is unknown and the
    constructor refuses. :class:`runout.Imperfections` (:mod:`runout.api`) is the builder
    that reads like the case file and takes Z from the bearing.
    Element *indices* are 0-based (tuple positions, ``index`` arguments); element *numbers*
    in :meth:`add` and :meth:`summary` are 1-based like the case file's ``element`` key.
    """

    inner: Harmonics
    outer: Harmonics
    elements: tuple[Harmonics, ...]
    diameter_errors: NDArray[np.float64]
    pitch_errors: NDArray[np.float64]
    slant: Slant | None

    def __init__(
        self,
        inner: Harmonics | None = None,
        outer: Harmonics | None = None,
        elements: Iterable[Harmonics] | int = (),
        diameter_errors: ArrayLike | None = None,
        pitch_errors: ArrayLike | None = None,
        slant: Slant | None = None,
    ) -> None:
        inner = Harmonics.empty() if inner is None else inner
        outer = Harmonics.empty() if outer is None else outer
        for name, h in (("inner", inner), ("outer", outer)):
            if not isinstance(h, Harmonics):
                raise ImperfectionError(
                    f"imperfections.{name}", f"must be Harmonics, got {type(h).__name__}"
                )
        if isinstance(elements, bool):
            raise ImperfectionError(
                "imperfections.elements",
                f"must be Z or one Harmonics per element, got {elements!r}",
            )
        if isinstance(elements, int | np.integer):
            if elements < 1:
                raise ImperfectionError(
                    "imperfections.elements", f"must be >= 1 (the number Z), got {elements}"
                )
            elements = (Harmonics.empty(),) * int(elements)
        elems = tuple(elements)
        for j, h in enumerate(elems):
            if not isinstance(h, Harmonics):
                raise ImperfectionError(
                    "imperfections.elements",
                    f"element {j + 1} must be Harmonics, got {type(h).__name__}",
                )
        if elems:
            n = len(elems)
        elif diameter_errors is not None:
            n = np.size(diameter_errors)
        elif pitch_errors is not None:
            n = np.size(pitch_errors)
        else:
            raise ImperfectionError(
                "imperfections.elements",
                "cannot tell the number of rolling elements: pass elements=Z (the number of "
                "balls or rollers), or use runout.Imperfections, which takes Z from the "
                "bearing",
            )
        if n < 1:
            raise ImperfectionError("imperfections.elements", "need at least one rolling element")
        if not elems:
            elems = (Harmonics.empty(),) * n
        if slant is not None and not isinstance(slant, Slant):
            raise ImperfectionError(
                "imperfections.slant", f"must be a Slant or None, got {type(slant).__name__}"
            )
        object.__setattr__(self, "inner", inner)
        object.__setattr__(self, "outer", outer)
        object.__setattr__(self, "elements", elems)
        object.__setattr__(
            self,
            "diameter_errors",
            _readonly(_element_vector("diameter_errors", diameter_errors, n)),
        )
        object.__setattr__(
            self, "pitch_errors", _readonly(_element_vector("pitch_errors", pitch_errors, n))
        )
        object.__setattr__(self, "slant", slant)

    @classmethod
    def perfect(cls, n_elements: int) -> Imperfections:
        """A bearing of ``n_elements`` perfect parts."""
        if isinstance(n_elements, bool) or not isinstance(n_elements, int | np.integer):
            raise ImperfectionError("n_elements", f"must be an integer, got {n_elements!r}")
        if n_elements < 1:
            raise ImperfectionError("n_elements", f"must be >= 1, got {n_elements}")
        return cls(elements=(Harmonics.empty(),) * int(n_elements))

    # --- queries ------------------------------------------------------------------------------
    @property
    def n_elements(self) -> int:
        """Z."""
        return len(self.elements)

    @property
    def is_perfect(self) -> bool:
        """True when nothing deviates."""
        return (
            self.inner.is_empty
            and self.outer.is_empty
            and all(h.is_empty for h in self.elements)
            and not self.diameter_errors.any()
            and not self.pitch_errors.any()
            and (self.slant is None or self.slant.amplitude == 0.0)
        )

    def element_diameter_deviation(self, index: int) -> Harmonics:
        """Diameter deviation of element ``index`` (0-based) along its contact line [m].

        ``diameter_errors[index]`` (order 0) plus ``r(θ) + r(θ + π)`` of its waviness (seed
        002 eq. 26); θ is the contact point's angle in the element's frame. An order-0 term in
        ``elements[index]`` (a radius error) adds twice its value.
        """
        if not -self.n_elements <= index < self.n_elements:
            raise IndexError(f"element index {index} out of range for {self.n_elements} elements")
        h = self.elements[index].diameter_deviation()
        d = float(self.diameter_errors[index])
        return h + Harmonics([0], [d]) if d != 0.0 else h

    def element_diameter_deviations(self) -> tuple[Harmonics, ...]:
        """:meth:`element_diameter_deviation` of every element."""
        return tuple(self.element_diameter_deviation(j) for j in range(self.n_elements))

    def evaluate_element_diameters(self, theta: ArrayLike) -> NDArray[np.float64]:
        """Diameter deviation of every element at its own angles [m], shape (Z, N).

        Parameters
        ----------
        theta : array_like, shape (Z, N) or (N,)
            Contact-point angle in each element's frame [rad]; a 1-D array is used for all.
        """
        from runout._kernels import harmonic_sum_rows

        t = np.asarray(theta, dtype=np.float64)
        if t.ndim == 1:
            t = np.broadcast_to(t, (self.n_elements, t.size))
        if t.ndim != 2 or t.shape[0] != self.n_elements:
            raise ImperfectionError(
                "theta", f"must have shape (Z, N) with Z = {self.n_elements}, got {t.shape}"
            )
        k, a, p, offsets = pack_harmonics(self.element_diameter_deviations())
        return harmonic_sum_rows(np.ascontiguousarray(t), k, a, p, offsets)

    # --- builders -----------------------------------------------------------------------------
    def _replace(self, **changes: Any) -> Imperfections:
        kwargs: dict[str, Any] = {
            "inner": self.inner,
            "outer": self.outer,
            "elements": self.elements,
            "diameter_errors": self.diameter_errors,
            "pitch_errors": self.pitch_errors,
            "slant": self.slant,
        }
        kwargs.update(changes)
        return Imperfections(**kwargs)

    def with_inner(self, harmonics: Harmonics) -> Imperfections:
        """Copy with the inner raceway replaced."""
        return self._replace(inner=harmonics)

    def with_outer(self, harmonics: Harmonics) -> Imperfections:
        """Copy with the outer raceway replaced."""
        return self._replace(outer=harmonics)

    def with_elements(self, elements: Sequence[Harmonics]) -> Imperfections:
        """Copy with every element's waviness replaced (length Z)."""
        if len(elements) != self.n_elements:
            raise ImperfectionError(
                "imperfections.elements",
                f"needs one profile per rolling element ({self.n_elements}), got {len(elements)}",
            )
        return self._replace(elements=tuple(elements))

    def with_diameter_errors(self, values: ArrayLike) -> Imperfections:
        """Copy with new element diameter errors [m], shape (Z,)."""
        return self._replace(diameter_errors=values)

    def with_pitch_errors(self, values: ArrayLike) -> Imperfections:
        """Copy with new element pitch errors [rad], shape (Z,)."""
        return self._replace(pitch_errors=values)

    def with_element_errors(
        self,
        diameter_errors: ArrayLike | None = None,
        pitch_errors: ArrayLike | None = None,
    ) -> Imperfections:
        """Copy with the given per-element errors replaced (None keeps the current ones)."""
        changes: dict[str, Any] = {}
        if diameter_errors is not None:
            changes["diameter_errors"] = diameter_errors
        if pitch_errors is not None:
            changes["pitch_errors"] = pitch_errors
        return self._replace(**changes)

    def with_slant(self, slant: Slant | None) -> Imperfections:
        """Copy with the slant replaced (None removes it)."""
        return self._replace(slant=slant)

    def element_phases_from_fixed_frame(self) -> Imperfections:
        r"""Copy with every element's waviness re-expressed from the fixed to the cage frame.

        Two body frames of rolling element j (0-based) are in use; both turn with the element's
        spin and differ only by where ψ = 0 points at t = 0 (ψ counter-clockwise in both):

        * **fixed** frame (seed 004, Yu et al. 2017, eq. 7: the roller frame is parallel to the
          bearing's): ψ = 0 along +x of the bearing;
        * **cage** frame (seed 001 eq. 13, seed 002 eq. 25-26, the product default): ψ = 0 along
          the outward radius through the element's centre, i.e. at the element's contact with
          the outer raceway, at t = 0.

        Element j's centre is at :math:`\beta_j = 2\pi j/Z + \epsilon_j` at t = 0
        (:math:`\epsilon_j` = ``pitch_errors[j]`` [rad]), so a material point at
        :math:`\psi_f` in the fixed frame is at :math:`\psi_c = \psi_f - \beta_j` in the cage
        frame, and

        .. math::
            a_k\cos(k\psi_f + \varphi^f_k) = a_k\cos(k\psi_c + \varphi^c_k),\qquad
            \varphi^c_k = \varphi^f_k + k\beta_j,

        i.e. ``elements[j].shifted(β_j)``. Amplitudes, order-0 (size) terms, raceways,
        diameter and pitch errors and the slant are unchanged; the inverse is
        ``shifted(-β_j)``.

        Returns
        -------
        Imperfections
            The same imperfections with element phases in the cage frame [rad].
        """
        z = self.n_elements
        beta = TWO_PI * np.arange(z) / z + self.pitch_errors
        return self._replace(
            elements=tuple(h.shifted(float(b)) for h, b in zip(self.elements, beta, strict=True))
        )

    def add(
        self,
        part: Part | str,
        harmonics: Harmonics,
        element: int | Sequence[int] | None = None,
    ) -> Imperfections:
        """Copy with ``harmonics`` added to a part's radius deviation.

        Parameters
        ----------
        part : {"inner", "outer", "ball", "roller", "element"}
            The part; the last three all mean the rolling elements.
        harmonics : Harmonics
            Radius deviation to add [m].
        element : int or sequence of int, optional
            Rolling elements only: 1-based element number(s) (as in the case file); None adds
            to every element.
        """
        if not isinstance(harmonics, Harmonics):
            raise ImperfectionError(
                "waviness", f"harmonics must be Harmonics, got {type(harmonics).__name__}"
            )
        if part in ("inner", "outer"):
            if element is not None:
                raise ImperfectionError(
                    "waviness.element", f"only balls or rollers take an element, not {part!r}"
                )
            return self._replace(**{part: getattr(self, part) + harmonics})
        if part not in ("ball", "roller", "element"):
            raise ImperfectionError(
                "waviness.part",
                f'must be "inner", "outer", "ball" or "roller", got {part!r}',
            )
        targets: list[int] = []
        if element is None:
            targets = list(range(self.n_elements))
        else:
            numbers = [element] if isinstance(element, int | np.integer) else list(element)
            for num in numbers:
                if isinstance(num, bool) or not isinstance(num, int | np.integer):
                    raise ImperfectionError(
                        "waviness.element", f"must be whole numbers, got {num!r}"
                    )
                if not 1 <= num <= self.n_elements:
                    raise ImperfectionError(
                        "waviness.element",
                        f"element numbers run from 1 to {self.n_elements}, got {num}",
                    )
                targets.append(int(num) - 1)
        elems = list(self.elements)
        for j in set(targets):
            elems[j] = elems[j] + harmonics
        return self._replace(elements=tuple(elems))

    # --- reports ------------------------------------------------------------------------------
    def summary(self) -> list[dict[str, Any]]:
        """One row per imperfection, for reports.

        Keys: ``part`` ("inner", "outer", "element", "slant"), ``element`` (1-based number or
        None), ``kind`` ("waviness", "diameter_error", "pitch_error", "slant"), ``order``,
        ``amplitude`` (zero-to-peak; for diameter and pitch errors the signed error),
        ``phase`` [rad] and ``unit`` ("m" or "rad"). Zero errors are omitted.
        """
        rows: list[dict[str, Any]] = []

        def wav(part: str, element: int | None, h: Harmonics) -> None:
            for k, a, p in zip(h.orders, h.amplitudes, h.phases, strict=True):
                rows.append(
                    {
                        "part": part,
                        "element": element,
                        "kind": "waviness",
                        "order": int(k),
                        "amplitude": float(a),
                        "phase": float(p),
                        "unit": "m",
                    }
                )

        wav("inner", None, self.inner)
        wav("outer", None, self.outer)
        for j, h in enumerate(self.elements):
            wav("element", j + 1, h)
        for kind, values, unit in (
            ("diameter_error", self.diameter_errors, "m"),
            ("pitch_error", self.pitch_errors, "rad"),
        ):
            for j, v in enumerate(values):
                if v != 0.0:
                    rows.append(
                        {
                            "part": "element",
                            "element": j + 1,
                            "kind": kind,
                            "order": 0,
                            "amplitude": float(v),
                            "phase": 0.0,
                            "unit": unit,
                        }
                    )
        if self.slant is not None and self.slant.amplitude != 0.0:
            rows.append(
                {
                    "part": "slant",
                    "element": None,
                    "kind": "slant",
                    "order": 2,
                    "amplitude": self.slant.amplitude,
                    "phase": self.slant.phase,
                    "unit": "m",
                }
            )
        return rows

    def __repr__(self) -> str:
        waved = sum(not h.is_empty for h in self.elements)
        return (
            f"Imperfections(Z={self.n_elements}, inner={self.inner!r}, outer={self.outer!r}, "
            f"elements with waviness={waved}, "
            f"max |diameter error|={np.abs(self.diameter_errors).max():.3g} m, "
            f"max |pitch error|={np.abs(self.pitch_errors).max():.3g} rad, slant={self.slant!r})"
        )


def anderon_608_example(
    seed: int | None = None,
    rng: np.random.Generator | None = None,
    ball_waviness: Literal["first", "all"] = "first",
) -> Imperfections:
    """The deviations of seed 002 §3.1 (eq. 43-47) for the 608 bearing of Tab. 1 (Z = 7).

    * eq. 43: inner-ring eccentricity W_i1 = 2.5 µm, phase 0;
    * eq. 44: slant W_s = 0.05 µm, phase 0;
    * eq. 45: inner W_ik = 0.1 µm / k^1.5, 2 ≤ k < 800 → orders (2, 799);
    * eq. 46: outer W_ok = 0.1 µm / k^1.5, 2 ≤ k < 1360 → orders (2, 1359);
    * eq. 47: ball W_b0k = 0.1 µm / k^1.5, 2 ≤ k < 287 → orders (2, 286);

    random phases uniform in [0, 2π), drawn in that order (inner, outer, then balls).

    Parameters
    ----------
    seed, rng
        Source of the random phases (exactly one).
    ball_waviness : {"first", "all"}
        Eq. 47 is written for ball z = 0 only (``W_b0k``); "first" follows that literally,
        "all" gives every ball the same law with its own random phases.
    """
    if ball_waviness not in ("first", "all"):
        raise ImperfectionError("ball_waviness", f'must be "first" or "all", got {ball_waviness!r}')
    gen = _make_rng(seed, rng, "seed")
    um = 1e-6
    inner = single_harmonic(1, 2.5 * um, 0.0) + spectral_law((2, 799), 0.1 * um, -1.5, rng=gen)
    outer = spectral_law((2, 1359), 0.1 * um, -1.5, rng=gen)
    n_balls = 1 if ball_waviness == "first" else 7
    balls = [spectral_law((2, 286), 0.1 * um, -1.5, rng=gen) for _ in range(n_balls)]
    balls += [Harmonics.empty()] * (7 - n_balls)
    return Imperfections(inner=inner, outer=outer, elements=balls, slant=Slant(0.05 * um, 0.0))
