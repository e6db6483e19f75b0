r"""Which part, lobe count and formula produces which frequency (seed 002 Tab. 3, seed 000 Tab. 2).

Pure functions of the geometry: given the element and pitch diameters, the contact angle, the
number of elements and which ring rotates, list every factor with the frequency it produces in
orders (waves per revolution of the rotating ring) and in hertz. These are the first-order
(linear) frequencies; the nonlinear models add combinations.

With γ = D cos α / d_m, ring rates ν_i, ν_o (1 for the rotating ring, 0 for the other), cage
ν_c = ν_i (1 − γ)/2 + ν_o (1 + γ)/2 and element spin (relative to the cage)
ν_b = d_m/(2D) (1 − γ²) (one sign for either ring rotating):

=========================  ===========================  ====================================
factor                     inner ring rotating          outer ring rotating
=========================  ===========================  ====================================
inner eccentricity         1                            0 (static offset)
inner slant                2 (eq. 35)                   0 (static offset)
inner waviness nZ ± 1      nZ (1 + γ)/2 ± 1 (eq. 33)    nZ (1 + γ)/2
inner flaw                 Z (1 + γ)/2 (eq. 49)         Z (1 + γ)/2
outer eccentricity         0 (static offset)            1
outer waviness nZ ± 1      nZ (1 − γ)/2 (eq. 37)        nZ (1 − γ)/2 ± 1
outer flaw                 Z (1 − γ)/2 (eq. 53)         Z (1 − γ)/2
ball diameter error        (1 − γ)/2 (eq. 40, 55)       (1 + γ)/2
ball waviness 2n           2n ν_b ± (1 − γ)/2 (eq. 39)  2n ν_b ± (1 + γ)/2
ball flaw                  2 ν_b (eq. 58)               2 ν_b
=========================  ===========================  ====================================

Notes
-----
Seed 002 Tab. 3 lists the outer-ring waviness as "nZ ± 1" producing ``nZ (1 − γ)/2``: both
lobe counts give the same frequency (eq. 37). Seed 000 Tab. 2 (outer ring rotating) writes the
same results as ``n f_i`` (inner, stationary) and ``n f_o ± f_r`` (outer, rotating), with f_i,
f_o the ball-pass frequencies; the rows here agree with it.
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["attribution_rows", "attribution_table_rows", "ball_size_line", "ball_waviness_line"]


def ball_waviness_line(lobes: int, sign: int, harmonic: int = 1) -> tuple[str, str]:
    """Term and formula of the line of an element's ``lobes`` at ``harmonic`` × lobes f_b ± f_c.

    Every model labels the ball-waviness lines through this one function, so that a line has
    the same name in every model and its sign follows the frequency it sits at.

    Parameters
    ----------
    lobes : int
        2n, the lobe count of the element's diameter deviation (≥ 1) [-].
    sign : {1, -1}
        +1 for the line at ``harmonic·lobes·f_b + f_c``, -1 for ``|harmonic·lobes·f_b - f_c|``,
        with f_b (element spin relative to the cage) and f_c (cage) both taken ≥ 0 [-].
    harmonic : int
        l, the power of the harmonic (1: the first-order line of seed 002 eq. 39) [-].

    Returns
    -------
    term, formula : str
        ``"2n f_b + f_c"`` (with ``", order l"`` for l > 1) and the frequency with the lobe
        count written out, e.g. ``"4 f_b - f_c"``.

    Notes
    -----
    Seed 002 (Anderon model) eq. 39 writes the two lines as 2n ν_b ± ν_c for the inner ring
    rotating; with the outer ring rotating the element spins the other way relative to the
    cage, so the same exponential lands on the other line. The sign here is the frequency's,
    never the exponential's.
    """
    if sign not in (1, -1):
        raise ValueError(f"sign must be +1 or -1, got {sign!r}")
    if lobes < 1 or harmonic < 1:
        raise ValueError(f"need lobes >= 1 and harmonic >= 1, got {lobes}, {harmonic}")
    pm = "+" if sign > 0 else "-"
    suffix = "" if harmonic == 1 else f", order {harmonic}"
    return f"2n f_b {pm} f_c{suffix}", f"{harmonic * lobes} f_b {pm} f_c"


def ball_size_line() -> tuple[str, str]:
    """Term and formula of the line of an element's size error: the cage frequency.

    Returns
    -------
    term, formula : str
        ``("f_c", "f_c")``.

    Notes
    -----
    Seed 002 (Anderon model) eq. 40 (B_A0): a larger element turns with the cage.
    """
    return "f_c", "f_c"


def attribution_rows(
    ball_diameter: float,
    pitch_diameter: float,
    contact_angle: float,
    n_elements: int,
    rotating_ring: str = "inner",
    speed_hz: float = 1.0,
    n_max: int = 2,
) -> list[dict[str, Any]]:
    """Rows {part, factor, lobes, formula, order, frequency_hz} for one bearing.

    Parameters
    ----------
    ball_diameter, pitch_diameter : float
        D and d_m [m].
    contact_angle : float
        α [rad].
    n_elements : int
        Z (≥ 3) [-].
    rotating_ring : {"inner", "outer"}
        Which ring turns (the other is stationary).
    speed_hz : float
        Speed of the rotating ring [Hz] (≥ 0); frequencies are order × speed.
    n_max : int
        Harmonics n = 1..n_max listed for the nZ ± 1 and 2n rows [-].

    Returns
    -------
    list of dict
        ``lobes`` is a string ("1", "nZ-1 = 6", "2n = 4", "-"); ``order`` ≥ 0 (per revolution
        of the rotating ring) [-]; ``frequency_hz`` is order × ``speed_hz`` [Hz].

    Notes
    -----
    The rows follow seed 002 Tab. 3 (Anderon model, with the equation numbers quoted in each
    row's ``formula``) and agree with seed 000 Tab. 2 (Tada) for the outer ring rotating; see
    the module docstring.
    """
    if rotating_ring not in ("inner", "outer"):
        raise ValueError(f'rotating_ring must be "inner" or "outer", got {rotating_ring!r}')
    if not (ball_diameter > 0 and pitch_diameter > ball_diameter):
        raise ValueError("need 0 < ball_diameter < pitch_diameter")
    if int(n_elements) < 3:
        raise ValueError(f"need at least 3 elements, got {n_elements}")
    if not (math.isfinite(speed_hz) and speed_hz >= 0):
        raise ValueError(f"speed_hz must be finite and >= 0, got {speed_hz!r}")
    if n_max < 1:
        raise ValueError(f"n_max must be >= 1, got {n_max}")
    z = int(n_elements)
    g = ball_diameter * math.cos(contact_angle) / pitch_diameter
    inner = rotating_ring == "inner"
    nu_c = (1 - g) / 2 if inner else (1 + g) / 2
    nu_b = pitch_diameter / (2 * ball_diameter) * (1 - g * g)
    cage = "(1-γ)/2" if inner else "(1+γ)/2"
    rows: list[dict[str, Any]] = []

    def add(part: str, factor: str, lobes: str, formula: str, order: float) -> None:
        rows.append(
            {
                "part": part,
                "factor": factor,
                "lobes": lobes,
                "formula": formula,
                "order": abs(order),
                "frequency_hz": abs(order) * speed_hz,
            }
        )

    # inner ring
    if inner:
        add("inner", "eccentricity", "1", "1", 1.0)
        add("inner", "slant", "-", "2 (eq. 35)", 2.0)
    else:
        add("inner", "eccentricity", "1", "0: stationary ring, static offset", 0.0)
        add("inner", "slant", "-", "0: stationary ring, static offset", 0.0)
    for n in range(1, n_max + 1):
        for s in (-1, 1):
            lobes = f"nZ{'+' if s > 0 else '-'}1 = {n * z + s} (n={n})"
            if inner:
                order = n * z * (1 + g) / 2 + s
                formula = f"nZ(1+γ)/2 {'+' if s > 0 else '-'} 1 (eq. 33)"
            else:
                order = n * z * (1 + g) / 2
                formula = "nZ(1+γ)/2 (n × inner ball-pass)"
            add("inner", "waviness", lobes, formula, order)
    add("inner", "flaw", "-", "Z(1+γ)/2 (eq. 49)", z * (1 + g) / 2)
    # outer ring
    if inner:
        add("outer", "eccentricity", "1", "0: stationary ring, static offset", 0.0)
    else:
        add("outer", "eccentricity", "1", "1", 1.0)
    for n in range(1, n_max + 1):
        for s in (-1, 1):
            lobes = f"nZ{'+' if s > 0 else '-'}1 = {n * z + s} (n={n})"
            if inner:
                order = n * z * (1 - g) / 2
                formula = "nZ(1-γ)/2 (eq. 37)"
            else:
                order = n * z * (1 - g) / 2 + s
                formula = f"nZ(1-γ)/2 {'+' if s > 0 else '-'} 1"
            add("outer", "waviness", lobes, formula, order)
    add("outer", "flaw", "-", "Z(1-γ)/2 (eq. 53)", z * (1 - g) / 2)
    # balls
    add("ball", "diameter error", "0", f"{cage} (eq. 40, 55)", nu_c)
    spin = "(d_m/2D)(1-γ²)"
    for n in range(1, n_max + 1):
        for s in (-1, 1):
            term, _ = ball_waviness_line(2 * n, s)
            add(
                "ball",
                "waviness",
                f"2n = {2 * n} (n={n})",
                f"{term}: 2n{spin} {'+' if s > 0 else '-'} {cage} (eq. 39)",
                2 * n * nu_b + s * nu_c,
            )
    add("ball", "flaw", "-", f"2{spin} (eq. 58)", 2 * nu_b)
    return rows


def attribution_table_rows(rows: list[dict[str, Any]]) -> list[tuple[str, str, str]]:
    """Three-column text rows (what, order, Hz) of :func:`attribution_rows` for tables.

    Parameters
    ----------
    rows : list of dict
        Rows as returned by :func:`attribution_rows` (``order`` [-], ``frequency_hz`` [Hz]).

    Returns
    -------
    list of tuple of str
        ``(what, "order ...", "... Hz")`` for each row, numbers to six significant digits.
    """
    return [
        (
            f"{r['part']} {r['factor']} [{r['lobes']}]: {r['formula']}",
            f"order {r['order']:.6g}",
            f"{r['frequency_hz']:.6g} Hz",
        )
        for r in rows
    ]
