r"""Rolling kinematics: cage, element spin and ball-pass frequencies.

Pure functions on SI values (frequencies in Hz, angles in rad), vectorised over NumPy arrays.
Pure rolling, no slip, elements equally spaced (seed 000 §2.1, seed 001 eq. 7-9, seed 002 §2.1).

With :math:`\gamma = D\cos\alpha / d_m`, inner-ring speed :math:`f_i` and outer-ring speed
:math:`f_o` (both signed, same sense positive):

.. math::

    f_c &= \tfrac12 f_i (1-\gamma) + \tfrac12 f_o (1+\gamma)        \\
    f_b &= \frac{d_m}{2D} (1-\gamma^2)\, |f_i - f_o|                   \\
    f_{BPI} &= Z |f_i - f_c|, \qquad f_{BPO} = Z |f_o - f_c|

How each paper writes them (all agree with the above):

* seed 000 (Tada): f_r rotating-ring speed, f_c cage, f_b ball rotation, f_i = Z|f_c - f_inner|
  (ball passes over a point of the inner ring), f_o = Z|f_r - f_c| for the rotating outer ring.
* seed 001 (Kim) eq. 7: Ω = ω/2 (1 - d/D cos α) is the cage (their d ball, D pitch);
  eq. 9: ω_b = ω D/(2d) (1 - d²/D² cos² α) the ball spin relative to the cage; eq. 8 places
  ball k at θ_k = Ω t + 2π(k-1)/Z.
* seed 002 (Anderon) eq. 5: ω_c = (r_c - r_b cos α)/(2 r_c) ω; eq. 4: ω_b = (r_c² - r_b² cos²α)
  /(2 r_b r_c) ω; eq. 7: θ_z = ω_c/ω θ + 2πz/Z. Its I, O, B orders (eq. 33, 37, 40) are
  Z(1+γ)/2 ± 1, nZ(1-γ)/2, 2n f_b/f ± f_c/f.
* seed 003 (Purohit) eq. 2.18-2.20: ω_cage = ω_in/2 (1 - d_b/d_m) + ω_out/2 (1 + d_b/d_m),
  ω_bp = N_b ω_cage for a stationary outer race (contact angle 0).
* seed 004 (Yu) eq. 3: γ₂ = α/2 (1 - 2D_w/(d_i+d_e)) is the cage angle. Its eq. 2 for the roller
  spin angle, ((d_i+d_e)² - 4D_w²)/((d_i+d_e)D_w) α, equals 4 (d_m/2D_w)(1-γ²) α as extracted:
  four times the pure-rolling value given here. We take it as an extraction error (a lost
  factor 4 in the denominator) and use the kinematically consistent spin; the roller-constraint
  model records this in its Notes.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from runout.geometry.bearing import Bearing, Operation

__all__ = [
    "Frequencies",
    "ball_pass_inner_frequency",
    "ball_pass_outer_frequency",
    "ball_spin_frequency",
    "bearing_frequencies",
    "cage_frequency",
    "pitch_ratio",
]


def pitch_ratio(
    ball_diameter: ArrayLike, pitch_diameter: ArrayLike, contact_angle: ArrayLike = 0.0
) -> Any:
    """γ = D cos α / d_m [-].

    Parameters
    ----------
    ball_diameter : array_like
        Element diameter D [m].
    pitch_diameter : array_like
        Pitch diameter d_m [m].
    contact_angle : array_like
        Contact angle α [rad].

    Returns
    -------
    ndarray or float
        γ [-], broadcast over the inputs.
    """
    return np.asarray(ball_diameter) * np.cos(contact_angle) / np.asarray(pitch_diameter)


def cage_frequency(
    inner_speed: ArrayLike,
    outer_speed: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    contact_angle: ArrayLike = 0.0,
) -> Any:
    """Cage (ball-set orbital) frequency f_c [Hz], signed like the ring speeds.

    .. math:: f_c = \\tfrac12 f_i (1-γ) + \\tfrac12 f_o (1+γ)

    Parameters
    ----------
    inner_speed, outer_speed : array_like
        Ring rotation frequencies [Hz], signed.
    ball_diameter, pitch_diameter : array_like
        D and d_m [m].
    contact_angle : array_like
        α [rad].

    Returns
    -------
    ndarray or float
        f_c [Hz], signed like the ring speeds.

    Notes
    -----
    Seed 003 eq. 2.18; seed 002 eq. 5; seed 001 eq. 7 (Purohit & Purohit 2006; the Anderon
    calculation model; Kim, Choi & Yoon).
    """
    g = pitch_ratio(ball_diameter, pitch_diameter, contact_angle)
    return 0.5 * np.asarray(inner_speed) * (1.0 - g) + 0.5 * np.asarray(outer_speed) * (1.0 + g)


def ball_spin_frequency(
    inner_speed: ArrayLike,
    outer_speed: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    contact_angle: ArrayLike = 0.0,
) -> Any:
    """Rotation frequency of an element about its own axis, seen from the cage, f_b [Hz] (>= 0).

    .. math:: f_b = \\frac{d_m}{2D}(1-γ^2)\\,|f_i - f_o|

    The sense is opposite to the inner ring's motion relative to the cage; only the magnitude
    is returned.

    Parameters
    ----------
    inner_speed, outer_speed : array_like
        Ring rotation frequencies [Hz], signed.
    ball_diameter, pitch_diameter : array_like
        D and d_m [m].
    contact_angle : array_like
        α [rad].

    Returns
    -------
    ndarray or float
        f_b [Hz] (>= 0).

    Notes
    -----
    Seed 002 eq. 4, seed 001 eq. 9 (the Anderon calculation model; Kim, Choi & Yoon).
    """
    g = pitch_ratio(ball_diameter, pitch_diameter, contact_angle)
    ratio = np.asarray(pitch_diameter) / (2.0 * np.asarray(ball_diameter))
    return ratio * (1.0 - g**2) * np.abs(np.asarray(inner_speed) - np.asarray(outer_speed))


def ball_pass_inner_frequency(
    n_elements: ArrayLike,
    inner_speed: ArrayLike,
    outer_speed: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    contact_angle: ArrayLike = 0.0,
) -> Any:
    """Rate at which elements pass a point of the inner raceway, Z |f_i - f_c| [Hz].

    Parameters
    ----------
    n_elements : array_like
        Number of elements Z [-].
    inner_speed, outer_speed : array_like
        Ring rotation frequencies [Hz], signed.
    ball_diameter, pitch_diameter : array_like
        D and d_m [m].
    contact_angle : array_like
        α [rad].

    Returns
    -------
    ndarray or float
        f_BPI [Hz] (>= 0).

    Notes
    -----
    Seed 002 eq. 49 (flaw pulse rate on the inner ring); Tada's f_i for a stationary inner ring
    (seed 000, Tada 2002).
    """
    fc = cage_frequency(inner_speed, outer_speed, ball_diameter, pitch_diameter, contact_angle)
    return np.asarray(n_elements) * np.abs(np.asarray(inner_speed) - fc)


def ball_pass_outer_frequency(
    n_elements: ArrayLike,
    inner_speed: ArrayLike,
    outer_speed: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    contact_angle: ArrayLike = 0.0,
) -> Any:
    """Rate at which elements pass a point of the outer raceway, Z |f_o - f_c| [Hz].

    Parameters
    ----------
    n_elements : array_like
        Number of elements Z [-].
    inner_speed, outer_speed : array_like
        Ring rotation frequencies [Hz], signed.
    ball_diameter, pitch_diameter : array_like
        D and d_m [m].
    contact_angle : array_like
        α [rad].

    Returns
    -------
    ndarray or float
        f_BPO [Hz] (>= 0).

    Notes
    -----
    Seed 002 eq. 53; seed 003 eq. 2.20 (ball passage frequency, stationary outer race)
    (the Anderon calculation model; Purohit & Purohit 2006).
    """
    fc = cage_frequency(inner_speed, outer_speed, ball_diameter, pitch_diameter, contact_angle)
    return np.asarray(n_elements) * np.abs(np.asarray(outer_speed) - fc)


@dataclass(frozen=True)
class Frequencies:
    """The characteristic frequencies of a bearing at one operating point [Hz].

    ``rotation`` is the speed of the rotating ring; every other frequency divided by it is an
    order (waves per revolution of the rotating ring), see :meth:`orders`.

    Attributes
    ----------
    rotation : float
        Speed of the rotating ring [Hz].
    cage : float
        Cage frequency f_c, seen from the stationary frame [Hz].
    ball_spin : float
        Element spin about its own axis relative to the cage f_b [Hz].
    ball_pass_inner, ball_pass_outer : float
        Ball-pass frequencies of the inner and outer raceways [Hz].
    """

    rotation: float
    cage: float
    ball_spin: float
    ball_pass_inner: float
    ball_pass_outer: float

    def to_dict(self) -> dict[str, float]:
        """Frequencies in Hz keyed as in the JSON contract (``frequencies_hz``).

        Returns
        -------
        dict of str to float
            Field name to frequency [Hz].
        """
        return asdict(self)

    def orders(self) -> dict[str, float]:
        """The same frequencies in orders of the rotating ring's speed [-].

        Returns
        -------
        dict of str to float
            Field name to order [-] (``rotation`` is 1).

        Raises
        ------
        ZeroDivisionError
            At zero speed.
        """
        if self.rotation == 0.0:
            raise ZeroDivisionError("orders are undefined at zero speed")
        return {k: v / self.rotation for k, v in asdict(self).items()}


def bearing_frequencies(
    bearing: Bearing, operation: Operation, contact_angle: float | None = None
) -> Frequencies:
    """Characteristic frequencies of ``bearing`` running as ``operation`` says.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing.
    operation : Operation
        Ring speeds [Hz].
    contact_angle : float or None
        Contact angle [rad]; default the bearing's nominal one (fixed or free contact angle).
        Pass the loaded contact angle from :mod:`runout.geometry.loading` for a preloaded bearing.

    Returns
    -------
    Frequencies
        Magnitudes in Hz (cage as seen from the stationary frame).
    """
    alpha = bearing.unloaded_contact_angle if contact_angle is None else contact_angle
    args = (
        operation.inner_speed,
        operation.outer_speed,
        bearing.element_diameter,
        bearing.pitch_diameter,
        alpha,
    )
    z = bearing.elements
    return Frequencies(
        rotation=abs(operation.speed),
        cage=float(abs(cage_frequency(*args))),
        ball_spin=float(ball_spin_frequency(*args)),
        ball_pass_inner=float(ball_pass_inner_frequency(z, *args)),
        ball_pass_outer=float(ball_pass_outer_frequency(z, *args)),
    )
