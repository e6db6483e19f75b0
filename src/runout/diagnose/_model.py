"""The linear model turned into observation equations for :func:`runout.diagnose.fit`.

Every deviation the linear model (seed 002 eq. 33-40) maps to a line is an *unknown*: a ring
harmonic of k = nZ ± 1 lobes (and the eccentricity), the even harmonics and the size error of
each element, the slant. The forward model is linear in their complex coefficients, so the
gains are read from :func:`runout.models.linear.closed_form_terms` itself (a unit deviation at
phase 0 and at phase π/2 gives the gain and whether the term carries the coefficient or its
conjugate): the inverse uses exactly the forward model's signs, frames and variants.

An *equation* is one complex number the record gives: with both x and y, the forward and the
backward whirl of a line, C₊ = (X + iY)/2 and C₋ = conj(X − iY)/2, are separate equations; with
one channel, the line's phasor X (or Y) is one equation carrying both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from runout.geometry.imperfections import BearingImperfections, Harmonics, Slant
from runout.models.linear import Rates, closed_form_terms

__all__ = ["Contribution", "Equation", "Unknown", "equations", "unknown_gains"]

PART_NAMES = ("inner", "outer", "ball", "slant")
#: Signed orders within this (relative) are one term.
_SAME = 1e-9


@dataclass(frozen=True)
class Unknown:
    """One deviation coefficient: part, lobes, element (0-based, -1 for rings); ``real`` for a
    size error (no phase)."""

    part: int
    lobes: int
    element: int
    real: bool = False


@dataclass(frozen=True)
class Contribution:
    """``gain × coefficient`` (``conj`` of the coefficient when ``conj``) in one equation."""

    unknown: Unknown
    gain: complex
    conj: bool


@dataclass
class Equation:
    """One complex observation: the sum of its contributions at signed order ``omega``.

    ``omega`` is the signed order (forward > 0) for two-channel equations; for one channel it
    is the (positive) order of the line and the contributions of both whirls are folded in.
    """

    omega: float
    contributions: list[Contribution] = field(default_factory=list)
    #: Largest distance [Hz] to another line fitted as one with it (closer than the record
    #: resolves); 0 for a resolved line.
    spread_hz: float = 0.0


def _ring_orders(z: int, k_max: int) -> list[int]:
    ks = {1}
    n = 1
    while n * z - 1 <= k_max:
        ks.update(k for k in (n * z - 1, n * z + 1) if k <= k_max)
        n += 1
    return sorted(ks)


def unknown_gains(
    z: int,
    r: Rates,
    contact_angle: float,
    variant: str,
    ring_lobes: int,
    ball_lobes: int,
    slant: bool,
) -> list[tuple[float, Contribution]]:
    """(signed order, contribution) of every term of every unknown.

    Parameters
    ----------
    z : int
        Number of elements.
    r : Rates
        Ring, cage and spin rates.
    contact_angle : float
        α [rad].
    variant : str
        Linear-model variant.
    ring_lobes, ball_lobes : int
        Largest lobe counts of the rings and the elements.
    slant : bool
        Include the inner-raceway slant.
    """
    ks = _ring_orders(z, ring_lobes)
    ms = list(range(2, ball_lobes + 1, 2))
    out: list[tuple[float, Contribution]] = []

    def build(phase: float, with_size: bool) -> BearingImperfections:
        ring = Harmonics(ks, np.ones(len(ks)), np.full(len(ks), phase))
        if with_size:
            elements = [Harmonics([0], [1.0]) for _ in range(z)]
            return BearingImperfections(elements=elements)
        el = [Harmonics(ms, np.ones(len(ms)), np.full(len(ms), phase)) for _ in range(z)]
        return BearingImperfections(
            inner=ring,
            outer=ring,
            elements=el,
            slant=Slant(1.0, phase) if slant else None,
        )

    t0 = closed_form_terms(build(0.0, False), r, contact_angle, variant)
    t1 = closed_form_terms(build(0.5 * math.pi, False), r, contact_angle, variant)
    for j in range(len(t0)):
        part, lobes = int(t0.part[j]), int(t0.lobes[j])
        element = int(t0.element[j])
        c0, c1 = complex(t0.coefficient[j]), complex(t1.coefficient[j])
        # phase π/2 multiplies a coefficient by i, its conjugate by -i
        conj = abs(c1 + 1j * c0) < abs(c1 - 1j * c0)
        lob = 2 if part == 3 else lobes
        out.append((float(t0.omega[j]), Contribution(Unknown(part, lob, element), c0, conj)))
    ts = closed_form_terms(build(0.0, True), r, contact_angle, variant)
    for j in range(len(ts)):
        u = Unknown(2, 0, int(ts.element[j]), real=True)
        out.append((float(ts.omega[j]), Contribution(u, complex(ts.coefficient[j]), False)))
    return out


def equations(terms: list[tuple[float, Contribution]], channels: tuple[str, ...]) -> list[Equation]:
    """Group the terms into the equations the record's channels give (see module doc)."""
    two = len(channels) == 2
    eqs: list[Equation] = []
    keyed = sorted(
        (((om if two else abs(om)), om, c) for om, c in terms if abs(om) > 1e-12),
        key=lambda t: t[0],
    )
    for key, om, c in keyed:
        if not eqs or abs(key - eqs[-1].omega) > _SAME * max(1.0, abs(key)):
            eqs.append(Equation(key))
        if two or om > 0.0:
            contrib = c
        else:  # one channel: a backward term enters the line's phasor conjugated
            contrib = Contribution(c.unknown, c.gain.conjugate(), not c.conj)
        if not two and channels[0] == "y":
            # Y = -i (C+ - conj C-): forward terms x -i, backward (already conjugated) x +i
            contrib = Contribution(
                contrib.unknown, contrib.gain * (-1j if om > 0.0 else 1j), contrib.conj
            )
        eqs[-1].contributions.append(contrib)
    return eqs


def static_unknowns(terms: list[tuple[float, Contribution]]) -> list[Unknown]:
    """Unknowns whose every term is static (order 0): an offset the record's mean removes."""
    moving = {c.unknown for om, c in terms if abs(om) > 1e-12}
    return sorted(
        {c.unknown for om, c in terms if abs(om) <= 1e-12} - moving,
        key=lambda u: (u.part, u.lobes, u.element),
    )


def solve_min_norm(
    eqs: list[Equation], values: NDArray[np.complex128], sigma: NDArray[np.float64]
) -> dict[Unknown, complex]:
    """Weighted least squares, minimum norm, over the unknowns of ``eqs``.

    The record fixes only the combinations the equations see; of all deviations that give the
    observed lines the smallest (sum of squared coefficients) is returned: the limit of a
    Tikhonov-regularised fit as the regularisation vanishes.
    """
    unknowns: dict[Unknown, int] = {}
    for e in eqs:
        for c in e.contributions:
            if c.unknown not in unknowns:
                unknowns[c.unknown] = len(unknowns)
    cols: dict[Unknown, int] = {}
    n_cols = 0
    for u in unknowns:
        cols[u] = n_cols
        n_cols += 1 if u.real else 2
    a = np.zeros((2 * len(eqs), n_cols))
    b = np.zeros(2 * len(eqs))
    for i, (e, v, s) in enumerate(zip(eqs, values, sigma, strict=True)):
        w = 1.0 / s
        b[2 * i], b[2 * i + 1] = v.real * w, v.imag * w
        for c in e.contributions:
            j = cols[c.unknown]
            qr, qi = c.gain.real * w, c.gain.imag * w
            if c.unknown.real:
                a[2 * i, j] += qr
                a[2 * i + 1, j] += qi
            elif not c.conj:
                a[2 * i, j] += qr
                a[2 * i, j + 1] -= qi
                a[2 * i + 1, j] += qi
                a[2 * i + 1, j + 1] += qr
            else:
                a[2 * i, j] += qr
                a[2 * i, j + 1] += qi
                a[2 * i + 1, j] += qi
                a[2 * i + 1, j + 1] -= qr
    if n_cols == 0:
        return {}
    x, *_ = np.linalg.lstsq(a, b, rcond=1e-10)
    out: dict[Unknown, complex] = {}
    for u, j in cols.items():
        out[u] = complex(x[j]) if u.real else complex(x[j], x[j + 1])
    return out
