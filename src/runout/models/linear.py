r"""Linear model of the outer-ring radial displacement (seed 002, "Anderon vibration").

The rings and rolling elements are rigid except at their contacts, which are linearised about
the mean load (seed 002 eq. 12). The radial force balance of the measured ring then gives its
centre displacement as a weighted sum of the deviations met by each element (eq. 21-22):

.. math::

    u(\theta) = x + i y = \frac{2 g}{Z} \sum_{z=0}^{Z-1} w_z(\theta)\, e^{i\theta_z}, \qquad
    w_z = w_i(\theta_z - \psi_i) - w_o(\theta_z - \psi_o) + w_{bz}(\theta_b)

with θ the angle of the rotating ring, θ_z the angle of element z (eq. 7), ψ_i, ψ_o the ring
angles, θ_b the contact-point angle in the element's frame (eq. 6) and w_bz the element's
diameter deviation along the contact line (eq. 26). ``g`` is ``cos α`` in the paper's
radial-spring variant (eq. 13, 21) and differs per part in the force-balance variant (see
:func:`variant_gains`).

Two routes give the same waveform:

* :func:`closed_form_terms` / :func:`spectral_lines`: each ring harmonic k, split into two
  complex exponentials, survives the sum over equally spaced elements only when ``k ± 1 ≡ 0
  (mod Z)`` (eq. 32-37); element harmonics keep a phase factor per element (eq. 38-40). The
  result is an exact list of lines ``C e^{iΩθ}`` with Ω of either sign (forward and backward
  whirl), merged into real lines of x and y at |Ω|.
* :func:`direct_sum` evaluates eq. 28 literally, element by element.

Notes
-----
Departures from seed 002 and choices it leaves open (the theory page docs/models/linear.md
derives them):

* **Outer-raceway sign.** :mod:`runout.geometry.imperfections` stores *radius* deviations. A larger
  outer-raceway radius moves the outer ring towards the element, so it enters with a minus
  sign (as in seed 000 eq. 2, ``(W_i - W_o) cos α``). Seed 002 eq. 27 adds w_o; its w_o is the
  deviation measured into the material. The lines are identical up to a phase of π; seed 002's
  example has random phases.
* **Slant in y.** Seed 002 eq. 35 gives only x. We take y as the reading of the same mechanism
  by a probe turned 90° about the axis: the two-per-revolution pattern turns with the inner
  ring, so that probe sees it a quarter turn later, ``y = −W_s cos(2ψ_i − φ_s)``. The slant is
  scaled like the other inner-ring terms (``cos α`` in the radial-spring variant, 1 in the
  force-balance one). A stationary inner ring gives a constant (static) offset.
* **Rotating outer ring.** The same sum with ψ_o = θ, ψ_i = 0 and the cage and spin rates of
  :mod:`runout.geometry.kinematics`. The contact-point angle on an element turns at the signed rate
  ``f_b sign(f_i − f_o)``; seed 002 (inner ring rotating) has the positive sense.
* **Pitch errors.** Eq. 19-20 need equally spaced elements. With pitch errors the direct sum
  solves the full 2 × 2 balance at each instant, ``(Z/2) u + (1/2) P ū = R`` with
  ``P = Σ e^{2iθ_z}``; the lines use the exact element sums ``Σ e^{imθ_z}`` but neglect the
  ``P`` coupling (first order in the pitch errors); the result's notes say so.
* Orders are waves per revolution of the rotating ring; frequencies are ``order × |speed|``.
* **Frame.** Seed 002 gives the outer ring's centre relative to the inner ring's. The result is
  reported as the shaft (inner ring) relative to the outer ring, as by every runout model:
  :data:`SHAFT_FRAME` turns the sign of every term (each line's phase moves by π; amplitudes,
  bands and orders are unchanged).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.analysis.decompose import exact_shares, split_runout
from runout.analysis.lines import Component, Source
from runout.analysis.result_details import LinearDetails
from runout.analysis.results import RunResult
from runout.analysis.spectrum import (
    ANDERON_BANDS,
    MICROINCH,
    BandSet,
    BandValues,
    _synthesize_uniform_kernel,
    anderon_bands_from_lines,
    anderon_bands_from_waveform,
)
from runout.base.errors import GeometryError
from runout.geometry.attribution import attribution_rows, ball_size_line, ball_waviness_line
from runout.geometry.bearing import Bearing, Operation
from runout.geometry.imperfections import BearingImperfections, Harmonics
from runout.geometry.kinematics import Frequencies, bearing_frequencies, pitch_ratio

__all__ = [
    "VARIANTS",
    "LinearResult",
    "Rates",
    "SpectralLines",
    "Terms",
    "closed_form_terms",
    "direct_sum",
    "linear_result",
    "rates",
    "run",
    "solve",
    "spectral_lines",
    "synthesize",
    "variant_gains",
]

Variant = Literal["radial_spring", "force_balance"]
VARIANTS: tuple[str, ...] = ("radial_spring", "force_balance")
TWO_PI = 2.0 * math.pi
#: Lines whose |Ω| agree to this relative tolerance are one line.
_MERGE_RTOL = 1e-12
#: An order within this of an integer is synchronous with the rotating ring (RRO).
_INTEGER_TOL = 1e-9

PART_CODES = ("inner", "outer", "ball", "slant")


# --------------------------------------------------------------------------------------------
# kinematics and gains
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Rates:
    """Angular rates in orders (per radian of the rotating ring), signed [-].

    Attributes
    ----------
    inner, outer : float
        Ring rates ν_i, ν_o (1 for the rotating ring).
    cage : float
        ν_c, seed 002 eq. 7 coefficient for the inner ring rotating.
    spin : float
        ν_b, rate of the contact-point angle in the element's frame (eq. 6 coefficient).
    rotation_hz : float
        |speed| of the rotating ring [Hz]; order × rotation_hz = frequency.
    """

    inner: float
    outer: float
    cage: float
    spin: float
    rotation_hz: float


#: Seed 002 writes the outer ring's displacement relative to the inner ring; runout reports the
#: shaft (inner ring) relative to the outer ring, the same motion with the opposite sign.
SHAFT_FRAME = -1.0


def rates(bearing: Bearing, operation: Operation, contact_angle: float) -> Rates:
    r"""Rates of rings, cage and element spin in orders of the rotating ring.

    .. math::

        \nu_c = \tfrac12 \nu_i (1-\gamma) + \tfrac12 \nu_o (1+\gamma), \qquad
        \nu_b = \frac{d_m}{2D}(1-\gamma^2)(\nu_i - \nu_o)

    with γ = D cos α / d_m (seed 002 eq. 4-7 for ν_i = 1, ν_o = 0).

    Parameters
    ----------
    bearing : Bearing
        Geometry (element and pitch diameters [m]).
    operation : Operation
        Ring speeds [Hz]; the rotating ring's speed must not be zero.
    contact_angle : float
        α [rad].

    Returns
    -------
    Rates
        ν_i, ν_o, ν_c, ν_b [-] (orders, signed) and the rotating ring's speed [Hz].

    Raises
    ------
    GeometryError
        When the rotating ring's speed is zero.

    Notes
    -----
    "Anderon vibration" (seed 002, the instrument maker's calculation model), eq. 4-7,
    generalised to either ring rotating.
    """
    speed = abs(operation.speed)
    if speed == 0.0:
        raise GeometryError("operation.speed", "the linear model needs a rotating ring (speed > 0)")
    ni = operation.inner_speed / speed
    no = operation.outer_speed / speed
    g = float(pitch_ratio(bearing.element_diameter, bearing.pitch_diameter, contact_angle))
    nc = 0.5 * ni * (1.0 - g) + 0.5 * no * (1.0 + g)
    nb = bearing.pitch_diameter / (2.0 * bearing.element_diameter) * (1.0 - g * g) * (ni - no)
    return Rates(ni, no, nc, nb, speed)


def variant_gains(contact_angle: float, variant: str = "radial_spring") -> tuple[float, float]:
    r"""Gains from a deviation to the ring displacement: (rings and slant, elements) [-].

    * ``"radial_spring"`` (seed 002 eq. 13, 21): every deviation is taken along the contact
      line and the contact acts as a radial spring: both gains are ``cos α``.
    * ``"force_balance"`` (seed 000 eq. 2 and 5 linearised, outer ring free axially under a
      constant preload): a ring's radial deviation w_r interferes by ``w_r cos α`` along the
      contact line and the radial balance divides by ``cos α``, so rings pass 1:1; an element's
      diameter deviation lies on the contact line and passes as ``1 / cos α``.

    Parameters
    ----------
    contact_angle : float
        α [rad].
    variant : {"radial_spring", "force_balance"}, optional
        Contact model; default ``"radial_spring"``.

    Returns
    -------
    g_ring, g_element : float
        Gain of the ring (and slant) deviations and of the element diameter deviations [-].

    Raises
    ------
    GeometryError
        An unknown variant, or ``"force_balance"`` at a contact angle of 90°.

    Notes
    -----
    ``"radial_spring"``: "Anderon vibration" (seed 002, the instrument maker's calculation model),
    eq. 13 and 21. ``"force_balance"``: Tada, "Three-dimensional analysis of non-repeatable
    runout (NRRO) in ball bearings", Koyo Engineering Journal (2002), eq. 2 and 5 (seed 000),
    linearised.
    """
    c = math.cos(contact_angle)
    if variant == "radial_spring":
        return c, c
    if variant == "force_balance":
        if c <= 1e-6:
            raise GeometryError(
                "analysis.linear_variant",
                "force_balance needs a contact angle below 90 deg",
            )
        return 1.0, 1.0 / c
    raise GeometryError(
        "analysis.linear_variant", f'must be "radial_spring" or "force_balance", got {variant!r}'
    )


# --------------------------------------------------------------------------------------------
# closed form: complex exponential terms
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class Terms:
    """Complex exponential terms ``u(θ) = Σ_j C_j e^{iΩ_j θ}`` of u = x + i y.

    Attributes
    ----------
    omega : ndarray
        Ω_j, signed orders [-].
    coefficient : ndarray of complex
        C_j [m].
    part : ndarray of int
        Index into :data:`PART_CODES` (inner, outer, ball, slant).
    lobes : ndarray of int
        Order of the source harmonic (slant: 2; element size error: 0).
    kind : ndarray of int
        Which exponential: 0 = ``e^{+ik...}`` (k+1 ≡ 0 mod Z for rings; for balls the line at
        2n f_b + f_c, seed 002's "A"), 1 = ``e^{-ik...}`` (k-1 ≡ 0; for balls the line at
        |2n f_b - f_c|, "B"), 2 = element size error, 3 = slant. A ball's kind names the
        frequency, not the exponential: with the outer ring turning, ν_b < 0 and
        ``e^{i(ν_c + mν_b)θ}`` sits at |2n f_b - f_c| (kind 1).
    element : ndarray of int
        0-based element for ball terms, -1 otherwise.
    """

    omega: NDArray[np.float64]
    coefficient: NDArray[np.complex128]
    part: NDArray[np.int64]
    lobes: NDArray[np.int64]
    kind: NDArray[np.int64]
    element: NDArray[np.int64]

    def __len__(self) -> int:
        return int(self.omega.size)

    def evaluate(self, theta: ArrayLike) -> NDArray[np.complex128]:
        """u(θ) [m] by NumPy broadcasting (the reference for :func:`synthesize`).

        Parameters
        ----------
        theta : array_like
            Angles of the rotating ring [rad] (flattened).

        Returns
        -------
        ndarray of complex
            u = x + i y at each angle [m].
        """
        t = np.asarray(theta, dtype=np.float64).reshape(-1)
        out = np.zeros(t.size, dtype=np.complex128)
        step = max(1, 2_000_000 // max(1, self.omega.size))
        for s in range(0, t.size, step):
            tb = t[s : s + step]
            out[s : s + step] = (
                self.coefficient[:, None] * np.exp(1j * self.omega[:, None] * tb[None, :])
            ).sum(axis=0)
        return out


def _element_sums(
    multipliers: NDArray[np.int64], beta: NDArray[np.float64], equal: bool
) -> NDArray[np.complex128]:
    """S_m = Σ_z e^{i m β_z} for each multiplier m (exact 0 or Z when equally spaced)."""
    z = beta.size
    if equal:
        return np.where(multipliers % z == 0, float(z), 0.0).astype(np.complex128)
    sums: NDArray[np.complex128] = np.exp(
        1j * np.multiply.outer(multipliers.astype(np.float64), beta)
    ).sum(axis=1)
    return sums


def _ring_terms(
    h: Harmonics,
    sign: float,
    nu_ring: float,
    r: Rates,
    gain: float,
    beta: NDArray[np.float64],
    equal: bool,
    part: int,
) -> list[NDArray[Any]]:
    """Terms of one ring's harmonics (seed 002 eq. 32-33 for the inner, 36-37 for the outer)."""
    z = beta.size
    k = h.orders
    a = h.amplitudes * np.exp(1j * h.phases)
    # u = (g/Z) Σ_z [A e^{i(k+1)θ_z - ikψ} + conj(A) e^{-i(k-1)θ_z + ikψ}]
    s1 = _element_sums(k + 1, beta, equal)
    s2 = _element_sums(-(k - 1), beta, equal)
    kf = k.astype(np.float64)
    om1 = (kf + 1.0) * r.cage - kf * nu_ring
    om2 = -(kf - 1.0) * r.cage + kf * nu_ring
    c1 = sign * gain / z * a * s1
    c2 = sign * gain / z * np.conj(a) * s2
    keep1 = np.abs(s1) > 1e-12 * z
    keep2 = np.abs(s2) > 1e-12 * z
    n1, n2 = int(keep1.sum()), int(keep2.sum())
    return [
        np.concatenate([om1[keep1], om2[keep2]]),
        np.concatenate([c1[keep1], c2[keep2]]),
        np.full(n1 + n2, part),
        np.concatenate([k[keep1], k[keep2]]),
        np.concatenate([np.zeros(n1, np.int64), np.ones(n2, np.int64)]),
        np.full(n1 + n2, -1),
    ]


def closed_form_terms(
    imperfections: BearingImperfections,
    r: Rates,
    contact_angle: float,
    variant: str = "radial_spring",
) -> Terms:
    r"""Exact complex exponential terms of u = x + i y (seed 002 eq. 33, 35, 37, 39-40).

    Ring harmonic k of complex amplitude :math:`A = a e^{i\varphi}` (ring rate ν) gives

    .. math::

        \frac{g\,S_{k+1}}{Z} A\, e^{i((k+1)\nu_c - k\nu)\theta} +
        \frac{g\,S_{-(k-1)}}{Z} \bar A\, e^{i(-(k-1)\nu_c + k\nu)\theta},
        \qquad S_m = \sum_z e^{i m \beta_z}

    (S_m = Z when m ≡ 0 mod Z, else 0, for equally spaced elements β_z = 2πz/Z); the outer ring
    with a minus sign. Element z's diameter harmonic of even order m,
    :math:`B = d e^{i\varphi}`, gives
    ``(g_b/Z) e^{iβ_z} (B e^{i(ν_c + mν_b)θ} + B̄ e^{i(ν_c − mν_b)θ})`` (eq. 39: B_An, B_Bn);
    its size error (order 0, value D_z) gives ``(2 g_b/Z) D_z e^{iβ_z} e^{iν_cθ}`` (eq. 40).

    Parameters
    ----------
    imperfections : BearingImperfections
        Deviations of the parts [m] (Z ≥ 3 elements).
    r : Rates
        From :func:`rates`.
    contact_angle : float
        α [rad].
    variant : {"radial_spring", "force_balance"}
        See :func:`variant_gains`.

    Returns
    -------
    Terms
        Signed orders Ω_j [-] and coefficients C_j [m] of u = x + i y, with their sources.

    Raises
    ------
    GeometryError
        Fewer than 3 elements, or an invalid variant.

    Notes
    -----
    "Anderon vibration" (seed 002, the instrument maker's calculation model), eq. 32-40.
    """
    z = imperfections.n_elements
    if z < 3:
        raise GeometryError(
            "bearing.elements", f"the linear model needs at least 3 elements (eq. 19-20), got {z}"
        )
    g_ring, g_ball = (SHAFT_FRAME * g for g in variant_gains(contact_angle, variant))
    beta = TWO_PI * np.arange(z) / z + imperfections.pitch_errors
    equal = not bool(np.any(imperfections.pitch_errors))
    parts = [
        _ring_terms(imperfections.inner, 1.0, r.inner, r, g_ring, beta, equal, 0),
        _ring_terms(imperfections.outer, -1.0, r.outer, r, g_ring, beta, equal, 1),
    ]
    # elements (eq. 38-40)
    om, co, lo, ki, el = [], [], [], [], []
    for j, h in enumerate(imperfections.element_diameter_deviations()):
        if h.is_empty:
            continue
        m = h.orders
        b = h.amplitudes * np.exp(1j * h.phases)
        e = np.exp(1j * beta[j])
        zero = m == 0
        pos = ~zero
        mf = m[pos].astype(np.float64)
        om += [np.array([r.cage] * int(zero.sum())), r.cage + mf * r.spin, r.cage - mf * r.spin]
        co += [
            2.0 * g_ball / z * b[zero].real * e,
            g_ball / z * b[pos] * e,
            g_ball / z * np.conj(b[pos]) * e,
        ]
        lo += [m[zero], m[pos], m[pos]]
        npos = int(pos.sum())
        # kind 0 is the line at 2n f_b + f_c: ν_c + mν_b when spin and cage turn the same way
        same_sense = r.spin * r.cage >= 0.0
        plus, minus = np.zeros(npos, np.int64), np.ones(npos, np.int64)
        ki += [np.full(int(zero.sum()), 2), *((plus, minus) if same_sense else (minus, plus))]
        el += [np.full(int(zero.sum()) + 2 * npos, j)]
    if om:
        omega = np.concatenate(om)
        parts.append(
            [
                omega,
                np.concatenate(co).astype(np.complex128),
                np.full(omega.size, 2),
                np.concatenate(lo),
                np.concatenate(ki),
                np.concatenate(el),
            ]
        )
    s = imperfections.slant
    if s is not None and s.amplitude > 0.0:
        # x = g W cos(2ψ_i − φ), y = −x: (1 − i) g W/2 (e^{-iφ} e^{2iν_iθ} + e^{iφ} e^{-2iν_iθ})
        half = (1.0 - 1.0j) * 0.5 * g_ring * s.amplitude
        parts.append(
            [
                np.array([2.0 * r.inner, -2.0 * r.inner]),
                np.array([half * np.exp(-1j * s.phase), half * np.exp(1j * s.phase)]),
                np.array([3, 3]),
                np.array([2, 2]),
                np.array([3, 3]),
                np.array([-1, -1]),
            ]
        )
    cols = [np.concatenate([p[i] for p in parts]) for i in range(6)]
    return Terms(
        omega=cols[0].astype(np.float64),
        coefficient=cols[1].astype(np.complex128),
        part=cols[2].astype(np.int64),
        lobes=cols[3].astype(np.int64),
        kind=cols[4].astype(np.int64),
        element=cols[5].astype(np.int64),
    )


# --------------------------------------------------------------------------------------------
# real lines
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LineSource:
    r"""One source's part of a line: its x and y phasors [m].

    :math:`x = \mathrm{Re}(X e^{i\omega\theta})`, likewise y.

    Attributes
    ----------
    source : Source
        What produces this part of the line.
    x, y : complex
        Phasors X, Y of this source's part of x and y [m].
    """

    source: Source
    x: complex
    y: complex


def _term_source(
    part: int, lobes: int, kind: int, element: int, z: int, inner_rotating: bool
) -> Source:
    """The structured source of one term (seed 002's symbol where it has one)."""
    if part == 3:
        return Source("slant", None, None, "2 per rev of the inner ring (eq. 35)", "2 f_i")
    if part == 2:
        # the shared table names ball lines alike in every model (seed 002 eq. 39-40)
        if kind == 2:
            return Source("ball", element + 1, 0, *ball_size_line())
        return Source(
            "ball", element + 1, lobes, *ball_waviness_line(lobes, 1 if kind == 0 else -1)
        )
    name = "inner" if part == 0 else "outer"
    ring = "i" if part == 0 else "o"
    k = lobes
    if k == 1 and kind == 1:
        return Source(name, None, 1, "eccentricity (eq. 33)", f"f_{ring}")
    if kind == 0:
        n, pm, formula = (k + 1) // z, "-", f"|{k + 1} f_c - {k} f_{ring}|"
    else:
        n, pm, formula = (k - 1) // z, "+", f"|{k} f_{ring} - {k - 1} f_c|"
    if (k + (1 if kind == 0 else -1)) % z == 0 and n >= 1:
        sym = (f" I_(nZ{pm}1)" if part == 0 else " O_nZ") if inner_rotating else ""
        return Source(name, None, k, f"nZ{pm}1, n={n}{sym} (eq. 33/37)", formula)
    return Source(name, None, k, "k ± 1 ≠ nZ (unequal spacing)", formula)


@dataclass(frozen=True, eq=False)
class SpectralLines:
    r"""Lines of the ring-centre displacement, one per distinct frequency.

    At order ω ≥ 0, ``u = C₊ e^{iωθ} + C₋ e^{−iωθ}`` (C₋ = 0 at ω = 0), so

    .. math::

        x = |X| \cos(\omega\theta + \arg X),\ X = C_+ + \bar C_-; \qquad
        y = |Y| \cos(\omega\theta + \arg Y),\ Y = -i (C_+ - \bar C_-).

    |C₊| is the forward (with the rotating ring) and |C₋| the backward whirl radius; the orbit
    is an ellipse of semi-axes |C₊| + |C₋| and ||C₊| − |C₋|| (seed 000 §3.2).

    Attributes
    ----------
    order : ndarray
        ω [-], ascending, ≥ 0.
    c_plus, c_minus : ndarray of complex
        C₊, C₋ [m].
    labels : tuple of str
        Source(s): part, lobe count and formula.
    rotation_hz : float
        Rotating-ring speed [Hz].
    sources : tuple of tuples of LineSource
        Per line, each source with its own x and y phasors (they add up to X, Y): the exact
        shares of a line several sources produce.
    """

    order: NDArray[np.float64]
    c_plus: NDArray[np.complex128]
    c_minus: NDArray[np.complex128]
    labels: tuple[str, ...]
    rotation_hz: float
    sources: tuple[tuple[LineSource, ...], ...] = ()

    def __len__(self) -> int:
        return int(self.order.size)

    @property
    def frequency_hz(self) -> NDArray[np.float64]:
        """Frequencies [Hz]."""
        return self.order * self.rotation_hz

    @property
    def x_complex(self) -> NDArray[np.complex128]:
        """X = C₊ + conj(C₋) [m]."""
        return self.c_plus + np.conj(self.c_minus)

    @property
    def y_complex(self) -> NDArray[np.complex128]:
        """Y = −i (C₊ − conj(C₋)) [m]."""
        return -1j * (self.c_plus - np.conj(self.c_minus))

    @property
    def x_amplitude(self) -> NDArray[np.float64]:
        """Zero-to-peak amplitude of x [m]."""
        return np.abs(self.x_complex)

    @property
    def y_amplitude(self) -> NDArray[np.float64]:
        """Zero-to-peak amplitude of y [m]."""
        return np.abs(self.y_complex)

    @property
    def x_phase(self) -> NDArray[np.float64]:
        """Phase of x = A cos(ωθ + φ) [rad]."""
        return np.angle(self.x_complex)

    @property
    def y_phase(self) -> NDArray[np.float64]:
        """Phase of y [rad]."""
        return np.angle(self.y_complex)

    @property
    def forward(self) -> NDArray[np.float64]:
        """Forward-whirl radius |C₊| [m]."""
        return np.abs(self.c_plus)

    @property
    def backward(self) -> NDArray[np.float64]:
        """Backward-whirl radius |C₋| [m]."""
        return np.abs(self.c_minus)

    @property
    def ellipse_major(self) -> NDArray[np.float64]:
        """Semi-major axis of the orbit, |C₊| + |C₋| [m]."""
        return self.forward + self.backward

    @property
    def ellipse_minor(self) -> NDArray[np.float64]:
        """Semi-minor axis of the orbit, ||C₊| − |C₋|| [m]."""
        return np.abs(self.forward - self.backward)

    @property
    def repeatable(self) -> NDArray[np.bool_]:
        """True for lines at integer orders (synchronous with the rotating ring): RRO."""
        return np.abs(self.order - np.round(self.order)) <= _INTEGER_TOL

    def along(self, direction: ArrayLike) -> NDArray[np.complex128]:
        """Complex amplitude of the displacement along unit vector ``(cos a, sin a)`` [m].

        Parameters
        ----------
        direction : array_like, shape (2,)
            Unit vector (cos a, sin a) of the direction [-].

        Returns
        -------
        ndarray of complex
            Phasor of each line along ``direction`` [m].
        """
        d = np.asarray(direction, dtype=np.float64)
        along: NDArray[np.complex128] = d[0] * self.x_complex + d[1] * self.y_complex
        return along

    def select(self, mask: ArrayLike) -> SpectralLines:
        """The lines where ``mask`` is true.

        Parameters
        ----------
        mask : array_like of bool
            One flag per line.

        Returns
        -------
        SpectralLines
            The selected lines, with their labels and sources.
        """
        m = np.asarray(mask, dtype=bool)
        return SpectralLines(
            self.order[m],
            self.c_plus[m],
            self.c_minus[m],
            tuple(lab for lab, keep in zip(self.labels, m, strict=True) if keep),
            self.rotation_hz,
            tuple(src for src, keep in zip(self.sources, m, strict=True) if keep)
            if self.sources
            else (),
        )

    def derivative(self) -> SpectralLines:
        """Lines of the displacement density du/dθ [m/rad] (seed 002 eq. 42).

        Returns
        -------
        SpectralLines
            The same orders with C₊, C₋ multiplied by ±iω [m/rad].

        Notes
        -----
        "Anderon vibration" (seed 002, the instrument maker's calculation model), eq. 42.
        """
        return SpectralLines(
            self.order,
            1j * self.order * self.c_plus,
            -1j * self.order * self.c_minus,
            self.labels,
            self.rotation_hz,
            tuple(
                tuple(LineSource(ls.source, 1j * w * ls.x, 1j * w * ls.y) for ls in line_sources)
                for w, line_sources in zip(self.order, self.sources, strict=True)
            )
            if self.sources
            else (),
        )

    def evaluate(self, theta: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """x(θ), y(θ) [m] by NumPy broadcasting (reference for :func:`synthesize`).

        Parameters
        ----------
        theta : array_like
            Angles of the rotating ring [rad] (flattened).

        Returns
        -------
        x, y : ndarray
            Displacements at each angle [m].
        """
        t = np.asarray(theta, dtype=np.float64).reshape(-1)
        x = np.zeros(t.size)
        y = np.zeros(t.size)
        step = max(1, 2_000_000 // max(1, self.order.size))
        for s in range(0, t.size, step):
            ph = self.order[:, None] * t[None, s : s + step]
            xc, yc = self.x_complex[:, None], self.y_complex[:, None]
            x[s : s + step] = (np.abs(xc) * np.cos(ph + np.angle(xc))).sum(axis=0)
            y[s : s + step] = (np.abs(yc) * np.cos(ph + np.angle(yc))).sum(axis=0)
        return x, y


def _term_label(part: int, lobes: int, kind: int, z: int, inner_rotating: bool) -> str:
    """Human label of one term: part, lobe count and formula (paper symbol if it has one)."""
    name = PART_CODES[part]
    if part == 3:
        return "inner slant: 2 per rev of the inner ring (eq. 35)"
    if part == 2:
        if kind == 2:
            sym = "B_A0 = f_c/f" if inner_rotating else "f_c/f"
            return f"ball size error (order 0): {sym} (eq. 40)"
        n = lobes // 2
        sym = f"B_{'A' if kind == 0 else 'B'}{n} = " if inner_rotating else ""
        _, formula = ball_waviness_line(lobes, 1 if kind == 0 else -1)
        return f"ball waviness {lobes} lobes: {sym}{formula} (eq. 39)"
    ring = "i" if part == 0 else "o"
    k = lobes
    if kind == 0:
        n, pm = (k + 1) // z, "-"
        formula = f"|{k + 1} f_c - {k} f_{ring}|/f"
    else:
        n, pm = (k - 1) // z, "+"
        formula = f"|{k} f_{ring} - {k - 1} f_c|/f"
    if k == 1 and kind == 1:
        return f"{name} eccentricity (1 lobe): f_{ring}/f (eq. 33)"
    if inner_rotating and (k + (1 if kind == 0 else -1)) % z == 0 and n >= 1:
        sym = f"I_(nZ{pm}1)" if part == 0 else "O_nZ"
        return f"{name} waviness {k} lobes (n={n}, nZ{pm}1): {sym} = {formula} (eq. 33/37)"
    return f"{name} waviness {k} lobes: {formula}"


def spectral_lines(terms: Terms, rotation_hz: float, z: int, inner_rotating: bool) -> SpectralLines:
    """Merge terms into real lines at |Ω| (terms within 1e-12 relative are one frequency).

    Parameters
    ----------
    terms : Terms
        From :func:`closed_form_terms`.
    rotation_hz : float
        Rotating-ring speed [Hz].
    z : int
        Number of elements (for the n of nZ ± 1 in labels).
    inner_rotating : bool
        Use seed 002's symbols (I, O, B_A, B_B) in labels.

    Returns
    -------
    SpectralLines
        One line per distinct |Ω| [-], ascending, with C₊, C₋ [m], labels and each source's
        own phasors [m].
    """
    w = np.abs(terms.omega)
    order = np.argsort(w, kind="stable")
    ws = w[order]
    if ws.size == 0:
        empty_c = np.zeros(0, dtype=np.complex128)
        return SpectralLines(np.zeros(0), empty_c, empty_c.copy(), (), rotation_hz)
    new = np.ones(ws.size, dtype=bool)
    new[1:] = np.diff(ws) > _MERGE_RTOL * np.maximum(1.0, ws[1:])
    group = np.cumsum(new) - 1
    n_lines = int(group[-1]) + 1
    grp = np.empty(ws.size, dtype=np.int64)
    grp[order] = group
    freq = np.zeros(n_lines)
    np.maximum.at(freq, grp, w)
    c = terms.coefficient
    is_zero = freq[grp] == 0.0
    plus = (terms.omega > 0) | is_zero
    cp = np.zeros(n_lines, dtype=np.complex128)
    cm = np.zeros(n_lines, dtype=np.complex128)
    np.add.at(cp, grp[plus], c[plus])
    np.add.at(cm, grp[~plus], c[~plus])
    labels: list[list[str]] = [[] for _ in range(n_lines)]
    balls: dict[tuple[int, str], list[int]] = {}
    for j in order:
        lab = _term_label(
            int(terms.part[j]), int(terms.lobes[j]), int(terms.kind[j]), z, inner_rotating
        )
        g = int(grp[j])
        if terms.part[j] == 2:
            balls.setdefault((g, lab), []).append(int(terms.element[j]) + 1)
        elif lab not in labels[g]:
            labels[g].append(lab)
    for (g, lab), elems in balls.items():
        which = "all balls" if len(elems) == z else "ball " + ",".join(map(str, sorted(elems)))
        labels[g].append(f"{lab} [{which}]")
    # each source's own phasors (terms of one source at one line add up)
    parts: list[dict[Source, list[complex]]] = [{} for _ in range(n_lines)]
    for j in order:
        src = _term_source(
            int(terms.part[j]),
            int(terms.lobes[j]),
            int(terms.kind[j]),
            int(terms.element[j]),
            z,
            inner_rotating,
        )
        cj = complex(c[j])
        xj, yj = (cj, -1j * cj) if plus[j] else (cj.conjugate(), 1j * cj.conjugate())
        acc = parts[int(grp[j])].setdefault(src, [0j, 0j])
        acc[0] += xj
        acc[1] += yj
    sources = tuple(
        tuple(LineSource(src, xy[0], xy[1]) for src, xy in line.items()) for line in parts
    )
    return SpectralLines(
        freq, cp, cm, tuple("; ".join(lab) for lab in labels), rotation_hz, sources
    )


# --------------------------------------------------------------------------------------------
# waveforms
# --------------------------------------------------------------------------------------------
def synthesize(
    lines: SpectralLines, revolutions: float, samples: int
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """x(θ), y(θ) from the lines on θ = 2π · revolutions · n / samples.

    Blocks of 256 samples as matrix products with one table of phasors
    (:mod:`runout.analysis._line_kernels`); agrees with :meth:`SpectralLines.evaluate` to about
    1e-13 of the largest amplitude.

    Parameters
    ----------
    lines : SpectralLines
        Lines to synthesise (orders [-], phasors [m] or [m/rad]).
    revolutions : float
        Length of the record in revolutions of the rotating ring [-].
    samples : int
        Number of samples over the record.

    Returns
    -------
    theta : ndarray
        Angles of the rotating ring [rad].
    x, y : ndarray
        Displacements [m].
    """
    dtheta = TWO_PI * revolutions / samples
    theta = np.arange(samples, dtype=np.float64) * dtheta
    xc, yc = lines.x_complex, lines.y_complex
    a = np.ascontiguousarray(np.stack([xc.real, yc.real]))
    b = np.ascontiguousarray(np.stack([-xc.imag, -yc.imag]))
    out = _synthesize_uniform_kernel(
        np.zeros(2), a, b, dtheta, np.ascontiguousarray(lines.order), samples
    )
    out = np.asarray(out, dtype=np.float64)
    return theta, out[0], out[1]


def solve(r: NDArray[np.complex128], p: NDArray[np.complex128], z: int) -> NDArray[np.complex128]:
    r"""Solve the radial balance ``(Z/2) u + (1/2) P ū = R`` for u (eq. 18 with eq. 19-20 kept).

    .. math:: u = \frac{R - P\bar R / Z}{Z/2 - |P|^2 / (2Z)}

    With equally spaced elements P = 0 and u = 2R/Z (eq. 21-22).

    Parameters
    ----------
    r : ndarray of complex
        ``R = Σ_z w_z exp(iθ_z)``, the elements' deviations summed as phasors [m].
    p : ndarray of complex
        ``P = Σ_z exp(2iθ_z)`` [-] (0 for equally spaced elements).
    z : int
        Number of elements Z.

    Returns
    -------
    ndarray of complex
        u = x + i y [m].

    Notes
    -----
    "Anderon vibration" (seed 002, the instrument maker's calculation model), eq. 18-22.
    """
    q = 0.5 * z
    return (r - p * np.conj(r) / (2.0 * q)) / (q - np.abs(p) ** 2 / (4.0 * q))


def direct_sum(
    imperfections: BearingImperfections,
    r: Rates,
    contact_angle: float,
    theta: ArrayLike,
    variant: str = "radial_spring",
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    r"""x(θ), y(θ) by summing over the elements at each instant (seed 002 eq. 28, 22).

    Each element's deviation ``w_z = g (w_i(θ_z − ψ_i) − w_o(θ_z − ψ_o)) + g_b w_bz(ν_b θ)``
    is evaluated from the part profiles, ``R = Σ_z w_z e^{iθ_z}`` and u from :func:`solve`.
    The slant adds ``g W_s cos(2ψ_i − φ_s) (1 − i)``.

    Parameters
    ----------
    imperfections : BearingImperfections
        Deviations [m].
    r : Rates
        From :func:`rates`.
    contact_angle : float
        α [rad].
    theta : array_like
        Angles of the rotating ring [rad].
    variant : str
        See :func:`variant_gains`.

    Returns
    -------
    x, y : ndarray
        Displacements at each angle [m].

    Raises
    ------
    GeometryError
        Fewer than 3 elements, or an invalid variant.

    Notes
    -----
    "Anderon vibration" (seed 002, the instrument maker's calculation model), eq. 22 and 28
    (eq. 18 with unequal spacing, :func:`solve`).
    """
    z = imperfections.n_elements
    if z < 3:
        raise GeometryError(
            "bearing.elements", f"the linear model needs at least 3 elements (eq. 19-20), got {z}"
        )
    g_ring, g_ball = (SHAFT_FRAME * g for g in variant_gains(contact_angle, variant))
    t = np.asarray(theta, dtype=np.float64).reshape(-1)
    beta = TWO_PI * np.arange(z) / z + imperfections.pitch_errors
    rr = np.zeros(t.size, dtype=np.complex128)
    pp = np.zeros(t.size, dtype=np.complex128)
    spin = r.spin * t
    for j in range(z):
        tz = r.cage * t + beta[j]
        w = g_ring * (
            imperfections.inner.evaluate(tz - r.inner * t)
            - imperfections.outer.evaluate(tz - r.outer * t)
        )
        w = w + g_ball * imperfections.element_diameter_deviation(j).evaluate(spin)
        e = np.exp(1j * tz)
        rr += w * e
        pp += e * e
    if not np.any(imperfections.pitch_errors):
        pp[:] = 0.0
    u = solve(rr, pp, z)
    s = imperfections.slant
    if s is not None and s.amplitude > 0.0:
        u = u + g_ring * s.amplitude * np.cos(2.0 * r.inner * t - s.phase) * (1.0 - 1.0j)
    return u.real.copy(), u.imag.copy()


# --------------------------------------------------------------------------------------------
# the model's result
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LinearResult(RunResult):
    """:class:`RunResult` of the linear model, with its exact lines and Anderon analysis.

    Attributes
    ----------
    spectral_lines : SpectralLines or None
        The closed-form lines (DC offset included at order 0).
    rates : Rates or None
        Angular rates used.
    theta : ndarray
        Angle of the rotating ring at each instant [rad].

    The variant and the attribution table are in :attr:`details`
    (:class:`~runout.analysis.result_details.LinearDetails`).
    """

    spectral_lines: SpectralLines | None = None
    rates: Rates | None = None
    theta: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))

    @property
    def variant(self) -> str:
        """``"radial_spring"`` or ``"force_balance"``."""
        d = self.details
        return d.linear_variant if isinstance(d, LinearDetails) else "radial_spring"

    @property
    def attribution(self) -> list[dict[str, Any]]:
        """Frequency attribution table of the bearing (:mod:`runout.geometry.attribution`)."""
        d = self.details
        return [dict(row) for row in d.attribution] if isinstance(d, LinearDetails) else []

    def _lines(self) -> SpectralLines:
        if self.spectral_lines is None:
            raise ValueError("this result carries no spectral lines")
        return self.spectral_lines

    def density_lines(self) -> SpectralLines:
        """Lines of the displacement density v = du/dθ [m/rad] (eq. 42).

        Returns
        -------
        SpectralLines
            Orders [-] and phasors [m/rad] (:meth:`SpectralLines.derivative`).
        """
        return self._lines().derivative()

    def anderon_lines(self, direction: str = "x", bands: BandSet = ANDERON_BANDS) -> BandValues:
        """Anderon band values from the exact lines (no leakage), eq. 1 and 42.

        Parameters
        ----------
        direction : {"x", "y"}
            Displacement component (seed 002 measures x).
        bands : BandSet
            Bands in orders.

        Returns
        -------
        BandValues
            ``values`` in Anderon, ``rms`` in µin/rad.

        Notes
        -----
        "Anderon vibration" (seed 002, the instrument maker's calculation model), eq. 1 and 42.
        """
        lines = self._lines()
        amp = lines.x_amplitude if direction == "x" else lines.y_amplitude
        keep = lines.order > 0
        return anderon_bands_from_lines(lines.order[keep], amp[keep], bands)

    def density_waveform(
        self, revolutions: int = 6, samples_per_rev: int | None = None, direction: str = "x"
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """v = dx/dθ [m/rad] sampled over whole revolutions (seed 002 Fig. 11, 14).

        Parameters
        ----------
        revolutions : int
            Whole revolutions of the rotating ring (seed 002: 6).
        samples_per_rev : int, optional
            Default: the smallest power of two above 2.5 × the highest line order (≥ 256).
        direction : {"x", "y"}
            Displacement component (seed 002 measures x).

        Returns
        -------
        theta, v : ndarray
            Angles of the rotating ring [rad] and the displacement density [m/rad].
        """
        lines = self._lines().derivative()
        if samples_per_rev is None:
            top = float(lines.order.max()) if len(lines) else 1.0
            samples_per_rev = max(256, 1 << math.ceil(math.log2(2.5 * top + 1.0)))
        if revolutions < 2 or samples_per_rev < 8:
            raise ValueError("need at least 2 revolutions and 8 samples per revolution")
        theta, x, y = synthesize(lines, revolutions, revolutions * samples_per_rev)
        return theta, (x if direction == "x" else y)

    def anderon_dft(
        self,
        revolutions: int = 6,
        samples_per_rev: int | None = None,
        bands: BandSet = ANDERON_BANDS,
        window: str | None = None,
        direction: str = "x",
    ) -> BandValues:
        """Anderon band values from a DFT of ``revolutions`` of the density waveform.

        This is what seed 002 did (six revolutions, rectangular window): lines that are not
        multiples of 1/revolutions leak into neighbouring bins and bands.

        Parameters
        ----------
        revolutions : int
            Whole revolutions of the rotating ring in the record (seed 002: 6).
        samples_per_rev : int, optional
            Samples per revolution; default as :meth:`density_waveform`.
        bands : BandSet
            Bands in orders.
        window : str or None
            ``None`` (rectangular, as seed 002) or a window name such as ``"hann"``.
        direction : {"x", "y"}
            Displacement component.

        Returns
        -------
        BandValues
            ``values`` in Anderon, ``rms`` in µin/rad.

        Notes
        -----
        "Anderon vibration" (seed 002, the instrument maker's calculation model), eq. 1
        and 42, Fig. 12.
        """
        _, v = self.density_waveform(revolutions, samples_per_rev, direction)
        spr = v.size // revolutions
        return anderon_bands_from_waveform(v, spr, bands, window=window, density=True)

    def anderon_comparison(
        self, revolutions: int = 6, bands: BandSet = ANDERON_BANDS
    ) -> dict[str, dict[str, float]]:
        """Band values from exact lines and from a DFT, and their relative difference.

        Parameters
        ----------
        revolutions : int
            Whole revolutions of the DFT record (seed 002: 6).
        bands : BandSet
            Bands in orders.

        Returns
        -------
        dict
            ``{band: {"lines": V, "dft": V, "relative_difference": (dft − lines)/lines}}``
            (the difference is 0 when the lines value is 0).
        """
        a = self.anderon_lines(bands=bands).as_dict()
        b = self.anderon_dft(revolutions, bands=bands).as_dict()
        return {
            k: {
                "lines": a[k],
                "dft": b[k],
                "relative_difference": (b[k] - a[k]) / a[k] if a[k] > 0 else 0.0,
            }
            for k in a
        }

    def line_anderon_spectrum(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Orders and rms displacement density of each x line [µin/rad] (Fig. 12 axes).

        Returns
        -------
        order : ndarray
            Line orders [-] (> 0).
        rms : ndarray
            rms of dx/dθ of each line [µin/rad].
        """
        lines = self._lines()
        keep = lines.order > 0
        rms = lines.order[keep] * lines.x_amplitude[keep] / math.sqrt(2.0) / MICROINCH
        return lines.order[keep], rms


def linear_result(result: RunResult) -> LinearResult:
    r"""A :class:`LinearResult` of a linear run read back from its JSON
    (:meth:`runout.analysis.results.RunResult.from_json`): its lines rebuilt from the components.

    Each order's x and y phasors X, Y give :math:`C_+ = (X + iY)/2` and
    :math:`\bar C_- = (X - iY)/2` (:class:`SpectralLines`); the DC line (order 0) and the
    lines the output leaves out as cancelled (below 1e-12 of the largest) are not in the
    JSON, and neither enters the Anderon values (a density has no DC).

    Parameters
    ----------
    result : RunResult
        A result of the linear model read back from JSON (components with pp [m] and
        phase [rad]).

    Returns
    -------
    LinearResult
        The same result with its spectral lines (orders [-], phasors [m]) and the angle of the
        rotating ring at each instant [rad].
    """
    by_order: dict[float, list[complex]] = {}
    for c in result.components:
        if c.direction not in ("x", "y"):
            continue
        phasor = 0.5 * c.pp_m * complex(math.cos(c.phase_rad), math.sin(c.phase_rad))
        pair = by_order.setdefault(c.order, [0j, 0j])
        pair[0 if c.direction == "x" else 1] += phasor
    orders = sorted(by_order)
    x = np.array([by_order[o][0] for o in orders], dtype=np.complex128)
    y = np.array([by_order[o][1] for o in orders], dtype=np.complex128)
    labels = tuple(next((c.label for c in result.components if c.order == o), "") for o in orders)
    lines = SpectralLines(
        np.array(orders, dtype=np.float64),
        0.5 * (x + 1j * y),
        np.conj(0.5 * (x - 1j * y)),
        labels,
        float(result.frequencies.rotation),
    )
    rotation = float(result.frequencies.rotation)
    theta = TWO_PI * rotation * result.time if rotation > 0 else np.zeros_like(result.time)
    fields = {f.name: getattr(result, f.name) for f in dataclasses.fields(RunResult)}
    return LinearResult(**fields, spectral_lines=lines, theta=theta)


def _components(lines: SpectralLines) -> tuple[Component, ...]:
    out: list[Component] = []
    rep = lines.repeatable
    top = float(max(lines.x_amplitude.max(initial=0.0), lines.y_amplitude.max(initial=0.0)))
    for i in range(len(lines)):
        if lines.order[i] == 0.0:
            continue
        for name, cval in (("x", lines.x_complex[i]), ("y", lines.y_complex[i])):
            amp = abs(cval)
            if amp <= 1e-12 * top:  # a cancelled line (round-off of the element sums)
                continue
            own = [(ls.source, ls.x if name == "x" else ls.y) for ls in lines.sources[i]]
            out.append(
                replace(
                    Component.from_sources(
                        name,
                        float(lines.frequency_hz[i]),
                        lines.rotation_hz,
                        amp,
                        float(np.angle(cval)),
                        exact_shares(own, complex(cval)),
                    ),
                    order=float(lines.order[i]),
                    repeatable=bool(rep[i]),
                )
            )

    out.sort(key=lambda c: -c.pp_m)
    return tuple(out)


def _measuring_direction(operation: Operation) -> NDArray[np.float64]:
    if operation.radial_load > 0.0:
        a = operation.radial_load_direction
        return np.array([math.cos(a), math.sin(a)])
    return np.array([1.0, 0.0])


def run(case: Any) -> LinearResult:
    """Run the linear model on a validated case (``[analysis] model = "linear"``).

    Parameters
    ----------
    case : runout.case.model.Case
        Bearing, operation, imperfections; ``analysis.revolutions`` and ``analysis.samples``
        set the waveform window and ``analysis.linear_variant`` the contact model.

    Returns
    -------
    LinearResult
        Waveform over the window, labelled lines (p-p), runout figures (RRO = integer orders,
        NRRO = the rest, p-p along the measuring direction over the window), Anderon bands from
        the exact lines, and the attribution table (JSON key ``attribution``).
    """
    from runout.geometry.loading import operating_contact_angle

    bearing, operation, imp = case.bearing, case.operation, case.imperfections
    variant = getattr(case.analysis, "linear_variant", "radial_spring")
    alpha, _ = operating_contact_angle(bearing, operation)
    rt = rates(bearing, operation, alpha)
    terms = closed_form_terms(imp, rt, alpha, variant)
    inner_rot = operation.rotating_ring == "inner" and operation.other_ring_speed == 0.0
    lines = spectral_lines(terms, rt.rotation_hz, imp.n_elements, inner_rot)
    revolutions = float(case.analysis.revolutions)
    samples = int(case.analysis.samples)
    pitch = bool(np.any(imp.pitch_errors))
    notes: list[str] = []
    if pitch:
        theta = TWO_PI * revolutions * np.arange(samples) / samples
        x, y = direct_sum(imp, rt, alpha, theta, variant)
        notes.append(
            "pitch errors: the waveform solves the full radial balance; the listed lines "
            "neglect the stiffness modulation by unequal spacing (first order in the errors)"
        )
    else:
        theta, x, y = synthesize(lines, revolutions, samples)
    direction = _measuring_direction(operation)
    time = theta / (TWO_PI * rt.rotation_hz)
    displacement = np.stack([x, y, np.zeros_like(x)])
    components = _components(lines)
    residual = np.zeros_like(displacement)
    if pitch:  # the lines neglect the unequal-spacing coupling: what they leave
        _, xl, yl = synthesize(lines, revolutions, samples)
        residual[0], residual[1] = x - xl, y - yl
    turning = imp.inner if operation.rotating_ring == "inner" else imp.outer
    synchronous = (
        bool(np.any(turning.amplitudes > 0.0))
        or (imp.slant is not None and operation.rotating_ring == "inner")
        or (operation.inner_speed != 0.0 and operation.outer_speed != 0.0)
    )
    split = split_runout(
        time,
        displacement,
        direction,
        components,
        rt.rotation_hz,
        residual,
        synchronous=synchronous,
        axial=False,  # a radial model: no axial degree of freedom
    )
    notes += split.notes
    variance = float(np.sum(np.var(displacement[:2], axis=1)))
    explained = 1.0 - float(np.sum(np.var(residual[:2], axis=1))) / variance if variance else 1.0
    freqs: Frequencies = bearing_frequencies(bearing, operation, alpha)
    attribution = attribution_rows(
        ball_diameter=bearing.element_diameter,
        pitch_diameter=bearing.pitch_diameter,
        contact_angle=alpha,
        n_elements=bearing.elements,
        rotating_ring=operation.rotating_ring,
        speed_hz=rt.rotation_hz,
    )
    anderon = anderon_bands_from_lines(
        lines.order[lines.order > 0], lines.x_amplitude[lines.order > 0]
    ).as_dict()
    if variant == "force_balance":
        notes.append("force-balance variant: rings pass 1:1, element deviations x 1/cos(alpha)")
    if operation.other_ring_speed != 0.0:
        notes.append("both rings rotate: orders are per revolution of the rotating ring")
    return LinearResult(
        model="linear",
        title=case.title,
        frequencies=freqs,
        contact_angle=alpha,
        time=time,
        displacement=displacement,
        components=components,
        runout=split.runout,
        measuring_direction=direction,
        anderon=anderon,
        details=LinearDetails(
            attribution=tuple(attribution),
            linear_variant=variant,
            explained_fraction=explained,
        ),
        notes=tuple(notes),
        spectral_lines=lines,
        rates=rt,
        theta=theta,
    )
