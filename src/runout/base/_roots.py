"""A bracketing scalar root finder without importing scipy.optimize.

:func:`brentq` is Brent's method as SciPy's ``scipy.optimize.brentq`` runs it (the same steps
in the same floating-point operations, so the same iterates and root to the bit; tested
against SciPy in ``tests/unit/base/test_roots.py``). It exists because importing scipy.optimize
costs ~0.1-0.2 s, and `runout frequencies` and `runout check` need one root (the contact angle
under an axial load) and nothing else from it.

Reference: R. P. Brent, *Algorithms for Minimization without Derivatives*, Prentice-Hall,
1973, ch. 4.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal, overload

__all__ = ["RootResults", "brentq"]

#: SciPy's smallest accepted relative tolerance, 4 machine epsilons.
_RTOL_MIN = 4.0 * 2.220446049250313e-16


@dataclass(frozen=True)
class RootResults:
    """What :func:`brentq` did (the fields of SciPy's ``RootResults`` that runout reads).

    Attributes
    ----------
    root : float
        The estimate of the root.
    iterations : int
        Iterations run.
    function_calls : int
        Evaluations of ``f``.
    converged : bool
        True when the bracket shrank below the tolerance (or ``f`` hit 0 exactly).
    flag : str
        ``"converged"`` or ``"convergence error"``.
    """

    root: float
    iterations: int
    function_calls: int
    converged: bool
    flag: str


def _call(f: Callable[[float], float], x: float) -> float:
    value = float(f(x))
    if math.isnan(value):
        raise ValueError(f"the function value at x={x} is NaN; solver cannot continue")
    return value


def _div(num: float, den: float) -> float:
    """``num / den`` as SciPy's C code computes it (IEEE 754): ±inf or nan, never an exception.

    Products of tiny function values underflow to 0 (f ~ 1e-117 squared); C then divides by
    zero into an infinite or undefined step, which the step test rejects (bisection).
    """
    if den != 0.0:
        return num / den
    if num == 0.0 or math.isnan(num):
        return math.nan
    return math.copysign(math.inf, num) * math.copysign(1.0, den)


@overload
def brentq(
    f: Callable[[float], float],
    a: float,
    b: float,
    xtol: float = ...,
    rtol: float = ...,
    maxiter: int = ...,
    full_output: Literal[False] = ...,
) -> float: ...


@overload
def brentq(
    f: Callable[[float], float],
    a: float,
    b: float,
    xtol: float = ...,
    rtol: float = ...,
    maxiter: int = ...,
    *,
    full_output: Literal[True],
) -> tuple[float, RootResults]: ...


def brentq(
    f: Callable[[float], float],
    a: float,
    b: float,
    xtol: float = 2e-12,
    rtol: float = _RTOL_MIN,
    maxiter: int = 100,
    full_output: bool = False,
) -> float | tuple[float, RootResults]:
    """Root of ``f`` in the bracket ``[a, b]`` by Brent's method (as ``scipy.optimize.brentq``).

    Parameters
    ----------
    f : callable
        Continuous scalar function, ``f(a)`` and ``f(b)`` of opposite signs.
    a, b : float
        The bracket.
    xtol, rtol : float
        The root is found within ``xtol + rtol * |x|`` (``xtol > 0``, ``rtol >= 4 eps``).
    maxiter : int
        Most iterations (>= 0).
    full_output : bool
        Also return a :class:`RootResults`.

    Returns
    -------
    float or (float, RootResults)

    Raises
    ------
    ValueError
        ``f(a)`` and ``f(b)`` of the same sign, a NaN value of ``f``, or bad tolerances.
    RuntimeError
        No convergence within ``maxiter`` iterations (as SciPy's default ``disp=True``).
    """
    if not xtol > 0:
        raise ValueError(f"xtol too small ({xtol:g} <= 0)")
    if rtol < _RTOL_MIN:
        raise ValueError(f"rtol too small ({rtol:g} < {_RTOL_MIN:g})")
    if maxiter < 0:
        raise ValueError("maxiter must be >= 0")
    xpre, xcur = float(a), float(b)
    xblk = fblk = spre = scur = 0.0
    fpre = _call(f, xpre)
    fcur = _call(f, xcur)
    calls = 2
    iterations = 0

    def done(x: float, converged: bool) -> float | tuple[float, RootResults]:
        if not converged:
            raise RuntimeError(f"Failed to converge after {maxiter} iterations, value is {x}.")
        if full_output:
            return x, RootResults(x, iterations, calls, True, "converged")
        return x

    if fpre == 0.0:
        return done(xpre, True)
    if fcur == 0.0:
        return done(xcur, True)
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise ValueError("f(a) and f(b) must have different signs")
    for _ in range(maxiter):
        iterations += 1
        if fpre != 0.0 and fcur != 0.0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk = xpre
            fblk = fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2.0  # the tolerance is 2 delta
        sbis = (xblk - xcur) / 2.0
        if fcur == 0.0 or abs(sbis) < delta:
            return done(xcur, True)
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # interpolate (secant)
                stry = _div(-fcur * (xcur - xpre), fcur - fpre)
            else:  # extrapolate (inverse quadratic)
                dpre = _div(fpre - fcur, xpre - xcur)
                dblk = _div(fblk - fcur, xblk - xcur)
                stry = _div(-fcur * (fblk * dblk - fpre * dpre), dblk * dpre * (fblk - fpre))
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
                spre = scur  # a good short step
                scur = stry
            else:
                spre = scur = sbis  # bisect
        else:
            spre = scur = sbis  # bisect
        xpre = xcur
        fpre = fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = _call(f, xcur)
        calls += 1
    return done(xcur, False)
