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
  :meth:`BearingImperfections.add`, the ``element`` key of case files and of :meth:`summary`
  rows) and indexed 0..Z-1 everywhere else (tuple positions, ``index`` arguments, arrays).
* ``pitch_errors[j]`` is the angular position error of element j relative to equal spacing
  [rad], positive counter-clockwise (ahead of its nominal place in the +θ sense).
* Randomness only through a :class:`numpy.random.Generator` passed in, or one created by
  ``numpy.random.default_rng(seed)`` from a given seed; never global state.

How the source papers write the same quantities
-----------------------------------------------
============================  ===============================================================
paper                         mapping onto :class:`BearingImperfections`
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

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.geometry._harmonics import (
    MAX_ELEMENTS,
    TWO_PI,
    Harmonics,
    ImperfectionError,
    Part,
    _as_float_vector,
    _make_rng,
    _readonly,
    _wrap_phase,
    pack_harmonics,
    single_harmonic,
    spectral_law,
)
from runout.geometry._harmonics import ProfileError as ProfileError
from runout.geometry._harmonics import ProfileWarning as ProfileWarning
from runout.geometry._profiles import from_profile as from_profile
from runout.geometry._profiles import read_profile_csv as read_profile_csv

if TYPE_CHECKING:
    from runout.geometry.bearing import Bearing

__all__ = [
    "BearingImperfections",
    "Harmonics",
    "ImperfectionError",
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


# --------------------------------------------------------------------------------------------
# Slant
# --------------------------------------------------------------------------------------------
def slant_amplitude(angle: float, radius: float) -> float:
    r"""W_s from a slant angle β (seed 002 eq. 34): ``W_s = r (1 − cos β) / (2 cos β)`` [m].

    Evaluated as ``r sin²(β/2) / cos β`` (no cancellation for small β).

    Parameters
    ----------
    angle : float
        Slant angle β [rad], |β| < π/2.
    radius : float
        Radius r_o at which the slant is seen [m] (> 0); see the Notes of :class:`Slant`.

    Returns
    -------
    float
        W_s, zero-to-peak [m] (≥ 0).

    Notes
    -----
    Seed 002 (Anderon calculation model) eq. 34.
    """
    _check_radius(radius)
    if not (math.isfinite(angle) and 0.0 <= abs(angle) < 0.5 * math.pi):
        raise ImperfectionError("slant.angle", f"must lie in (-90, 90) deg, got {angle!r} rad")
    return radius * math.sin(0.5 * angle) ** 2 / math.cos(angle)


def slant_angle(amplitude: float, radius: float) -> float:
    """Inverse of :func:`slant_amplitude`: β = 2 asin √(W_s / (r + 2 W_s)) [rad] (≥ 0).

    Parameters
    ----------
    amplitude : float
        W_s, zero-to-peak [m] (≥ 0).
    radius : float
        Radius r_o at which the slant is seen [m] (> 0).

    Returns
    -------
    float
        Slant angle β [rad] (≥ 0).

    Notes
    -----
    Seed 002 (Anderon calculation model) eq. 34, solved for β.
    """
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

        Parameters
        ----------
        angle : float
            Slant angle β [rad], |β| < π/2.
        radius : float or BallBearing or RollerBearing
            r_o [m], or a bearing supplying ``outer_raceway_diameter / 2``.
        phase : float
            φ_s [rad].

        Returns
        -------
        Slant
            The slant with W_s from :func:`slant_amplitude` [m].
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

        Returns
        -------
        Slant
            The slant, amplitude W_s [m] and phase φ_s [rad].

        Raises
        ------
        ImperfectionError
            Unless exactly one of ``amplitude`` and ``angle`` is given.
        """
        if (amplitude is None) == (angle is None):
            raise ImperfectionError("slant", "give exactly one of amplitude (W_s) and angle")
        if amplitude is not None:
            return cls(float(amplitude), phase)
        assert angle is not None
        r = 0.5 * bearing.outer_raceway_diameter if radius is None else radius
        return cls.from_angle(angle, r, phase)

    def angle(self, radius: float) -> float:
        """The slant angle β [rad] that gives this W_s at radius r [m].

        Parameters
        ----------
        radius : float
            Radius r at which the slant is seen [m] (> 0).

        Returns
        -------
        float
            β [rad] (≥ 0), by :func:`slant_angle`.
        """
        return slant_angle(self.amplitude, radius)

    @property
    def peak_to_peak(self) -> float:
        """2 W_s [m]."""
        return 2.0 * self.amplitude

    def displacement(self, theta: ArrayLike) -> NDArray[np.float64]:
        """``W_s cos(2θ − φ_s)`` [m] at inner-ring angles θ [rad] (seed 002 eq. 35).

        Parameters
        ----------
        theta : array_like
            Inner-ring rotation angle θ [rad].

        Returns
        -------
        ndarray
            Slant displacement [m], shaped like ``theta``.

        Notes
        -----
        Seed 002 (Anderon calculation model) eq. 35.
        """
        t = np.asarray(theta, dtype=np.float64)
        return self.amplitude * np.cos(2.0 * t - self.phase)

    def __add__(self, other: object) -> Slant:
        if not isinstance(other, Slant):
            return NotImplemented
        c = self.amplitude * np.exp(-1j * self.phase) + other.amplitude * np.exp(-1j * other.phase)
        return Slant(float(abs(c)), float(_wrap_phase(np.array([-np.angle(c)]))[0]))


# --------------------------------------------------------------------------------------------
# BearingImperfections of a whole bearing
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
class BearingImperfections:
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
    per-element data default to perfect: ``BearingImperfections(elements=8, outer=...)`` is a
    bearing of 8 perfect elements with a wavy outer raceway. Without any of them Z is unknown
    and the constructor refuses. :class:`runout.Imperfections` (:mod:`runout.api`) is the builder
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
    def perfect(cls, n_elements: int) -> BearingImperfections:
        """A bearing of ``n_elements`` perfect parts.

        Parameters
        ----------
        n_elements : int
            Number of rolling elements Z (≥ 1) [-].

        Returns
        -------
        BearingImperfections
            Every deviation zero.
        """
        if isinstance(n_elements, bool) or not isinstance(n_elements, int | np.integer):
            raise ImperfectionError("n_elements", f"must be an integer, got {n_elements!r}")
        if n_elements < 1:
            raise ImperfectionError("n_elements", f"must be >= 1, got {n_elements}")
        if n_elements > MAX_ELEMENTS:  # before one object per element is made
            raise ImperfectionError(
                "n_elements", f"must be at most {MAX_ELEMENTS}, got {n_elements}"
            )
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

        Parameters
        ----------
        index : int
            0-based element index (negative counts from the end).

        Returns
        -------
        Harmonics
            Diameter deviation w_b(θ) [m], even orders only plus the order-0 size error.

        Raises
        ------
        IndexError
            If ``index`` is out of range.

        Notes
        -----
        Seed 002 (Anderon calculation model) eq. 26.
        """
        if not -self.n_elements <= index < self.n_elements:
            raise IndexError(f"element index {index} out of range for {self.n_elements} elements")
        h = self.elements[index].diameter_deviation()
        d = float(self.diameter_errors[index])
        return h + Harmonics([0], [d]) if d != 0.0 else h

    def element_diameter_deviations(self) -> tuple[Harmonics, ...]:
        """:meth:`element_diameter_deviation` of every element.

        Returns
        -------
        tuple of Harmonics
            Diameter deviation of each element [m], length Z.
        """
        return tuple(self.element_diameter_deviation(j) for j in range(self.n_elements))

    def evaluate_element_diameters(self, theta: ArrayLike) -> NDArray[np.float64]:
        """Diameter deviation of every element at its own angles [m], shape (Z, N).

        Parameters
        ----------
        theta : array_like, shape (Z, N) or (N,)
            Contact-point angle in each element's frame [rad]; a 1-D array is used for all.

        Returns
        -------
        ndarray, shape (Z, N)
            Diameter deviation of each element at its angles [m].
        """
        from runout.geometry._kernels import harmonic_sum_rows

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
    def _replace(self, **changes: Any) -> BearingImperfections:
        kwargs: dict[str, Any] = {
            "inner": self.inner,
            "outer": self.outer,
            "elements": self.elements,
            "diameter_errors": self.diameter_errors,
            "pitch_errors": self.pitch_errors,
            "slant": self.slant,
        }
        kwargs.update(changes)
        return BearingImperfections(**kwargs)

    def with_inner(self, harmonics: Harmonics) -> BearingImperfections:
        """Copy with the inner raceway replaced.

        Parameters
        ----------
        harmonics : Harmonics
            New radius deviation of the inner raceway [m].

        Returns
        -------
        BearingImperfections
            The copy.
        """
        return self._replace(inner=harmonics)

    def with_outer(self, harmonics: Harmonics) -> BearingImperfections:
        """Copy with the outer raceway replaced.

        Parameters
        ----------
        harmonics : Harmonics
            New radius deviation of the outer raceway [m].

        Returns
        -------
        BearingImperfections
            The copy.
        """
        return self._replace(outer=harmonics)

    def with_elements(self, elements: Sequence[Harmonics]) -> BearingImperfections:
        """Copy with every element's waviness replaced (length Z).

        Parameters
        ----------
        elements : sequence of Harmonics
            New radius deviation of each element [m], length Z.

        Returns
        -------
        BearingImperfections
            The copy.
        """
        if len(elements) != self.n_elements:
            raise ImperfectionError(
                "imperfections.elements",
                f"needs one profile per rolling element ({self.n_elements}), got {len(elements)}",
            )
        return self._replace(elements=tuple(elements))

    def with_diameter_errors(self, values: ArrayLike) -> BearingImperfections:
        """Copy with new element diameter errors [m], shape (Z,).

        Parameters
        ----------
        values : array_like, shape (Z,)
            Diameter deviation of each element from the nominal diameter [m].

        Returns
        -------
        BearingImperfections
            The copy.
        """
        return self._replace(diameter_errors=values)

    def with_pitch_errors(self, values: ArrayLike) -> BearingImperfections:
        """Copy with new element pitch errors [rad], shape (Z,).

        Parameters
        ----------
        values : array_like, shape (Z,)
            Angular position error of each element [rad], positive counter-clockwise.

        Returns
        -------
        BearingImperfections
            The copy.
        """
        return self._replace(pitch_errors=values)

    def with_element_errors(
        self,
        diameter_errors: ArrayLike | None = None,
        pitch_errors: ArrayLike | None = None,
    ) -> BearingImperfections:
        """Copy with the given per-element errors replaced (None keeps the current ones).

        Parameters
        ----------
        diameter_errors : array_like, shape (Z,), optional
            Diameter deviation of each element [m].
        pitch_errors : array_like, shape (Z,), optional
            Angular position error of each element [rad].

        Returns
        -------
        BearingImperfections
            The copy.
        """
        changes: dict[str, Any] = {}
        if diameter_errors is not None:
            changes["diameter_errors"] = diameter_errors
        if pitch_errors is not None:
            changes["pitch_errors"] = pitch_errors
        return self._replace(**changes)

    def with_slant(self, slant: Slant | None) -> BearingImperfections:
        """Copy with the slant replaced (None removes it).

        Parameters
        ----------
        slant : Slant or None
            New inner-raceway slant (amplitude [m], phase [rad]).

        Returns
        -------
        BearingImperfections
            The copy.
        """
        return self._replace(slant=slant)

    def element_phases_from_fixed_frame(self) -> BearingImperfections:
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
        BearingImperfections
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
    ) -> BearingImperfections:
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

        Returns
        -------
        BearingImperfections
            The copy.
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

        Returns
        -------
        list of dict
            The rows, keyed as above; ``amplitude`` in the row's ``unit`` ([m] or [rad]).
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
            f"BearingImperfections(Z={self.n_elements}, inner={self.inner!r}, "
            f"outer={self.outer!r}, "
            f"elements with waviness={waved}, "
            f"max |diameter error|={np.abs(self.diameter_errors).max():.3g} m, "
            f"max |pitch error|={np.abs(self.pitch_errors).max():.3g} rad, slant={self.slant!r})"
        )


def anderon_608_example(
    seed: int | None = None,
    rng: np.random.Generator | None = None,
    ball_waviness: Literal["first", "all"] = "first",
) -> BearingImperfections:
    """The deviations of seed 002 §3.1 (eq. 43-47) for the 608 bearing of Tab. 1 (Z = 7).

    * eq. 43: inner-ring eccentricity W_i1 = 2.5 µm, phase 0;
    * eq. 44: slant W_s = 0.05 µm, phase 0;
    * eq. 45: inner W_ik = 0.1 µm / k^1.5, 2 ≤ k < 800 → orders (2, 799);
    * eq. 46: outer W_ok = 0.1 µm / k^1.5, 2 ≤ k < 1360 → orders (2, 1359);
    * eq. 47: ball W_b0k = 0.1 µm / k^1.5, 2 ≤ k < 287 → orders (2, 286);

    random phases uniform in [0, 2π), drawn in that order (inner, outer, then balls).

    Parameters
    ----------
    seed : int, optional
        Seed of a new :func:`numpy.random.default_rng` for the random phases.
    rng : numpy.random.Generator, optional
        Generator of the random phases (exactly one of ``seed`` and ``rng``).
    ball_waviness : {"first", "all"}
        Eq. 47 is written for ball z = 0 only (``W_b0k``); "first" follows that literally,
        "all" gives every ball the same law with its own random phases.

    Returns
    -------
    BearingImperfections
        Seven balls; amplitudes [m], phases [rad].
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
    return BearingImperfections(
        inner=inner, outer=outer, elements=balls, slant=Slant(0.05 * um, 0.0)
    )


def __getattr__(name: str) -> object:
    """``Imperfections`` (renamed :class:`BearingImperfections`: one name, one class), for one
    release; ``runout.Imperfections`` is the builder of the case file's tables."""
    if name == "Imperfections":
        import warnings

        warnings.warn(
            "runout.geometry.imperfections.Imperfections is deprecated: it is "
            "BearingImperfections (runout.Imperfections is the builder of the case tables)",
            DeprecationWarning,
            stacklevel=2,
        )
        return BearingImperfections
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
