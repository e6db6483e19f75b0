"""Seed 000: S. Tada, "Three-dimensional analysis of non-repeatable runout (NRRO) in ball
bearings", Koyo Engineering Journal (2002) — Table 2, conclusions 1 and 3, §3.2 / Fig. 6.

Computed with the 3-D quasi-static model (``runout.models.quasi_static_3d``) from the example
case files ``seed000_tada_table2.toml`` and ``seed000_tada_fig6.toml``. The published cells of
Fig. 6 are :data:`TADA_FIG6`.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from runout.validation.cases import uses, variant
from runout.validation.core import Check, bind

if TYPE_CHECKING:
    from runout.case.model import Case

__all__ = [
    "INTRO",
    "TADA_CONCLUSION3_AMPLITUDES",
    "TADA_FIG6",
    "TADA_PP",
    "checks",
    "tada_case",
    "tada_frequencies",
    "tada_line_pp",
    "tada_second_order_lines",
]

#: The waviness peak-to-peak of Table 2 and the unit of Fig. 6's relative amplitudes [m].
TADA_PP = 20e-9


def tada_case(
    waviness: list[dict[str, Any]],
    *,
    z: int | None = None,
    axial: float | None = None,
    clearance: float | None = None,
    revolutions: float | None = None,
    samples: int | None = None,
    elements: dict[str, Any] | None = None,
    name: str = "seed000_tada_table2.toml",
) -> Case:
    """The example ``name`` with ``waviness`` (peak-to-peak, as the paper) and changes.

    Parameters
    ----------
    waviness : list of dict
        The case file's ``[[waviness]]`` entries (SI values) replacing the example's.
    z, axial, clearance : optional
        Number of balls, axial preload [N], radial clearance P_d [m].
    revolutions, samples : optional
        The record: revolutions of the rotating ring and instants.
    elements : dict, optional
        The case file's ``[elements]`` table (per-ball size and pitch errors).
    name : str
        The example case file changed.

    Returns
    -------
    Case
        The changed example, validated as a case file.
    """

    def mutate(data: dict[str, Any]) -> None:
        data["waviness"] = waviness
        if z is not None:
            data["bearing"]["elements"] = z
        if axial is not None:
            data["operation"]["axial_load"] = axial
        if clearance is not None:
            data["bearing"]["radial_clearance"] = clearance
        if revolutions is not None:
            data["analysis"]["revolutions"] = revolutions
        if samples is not None:
            data["analysis"]["samples"] = samples
        if elements is not None:
            data["elements"] = elements

    return variant(name, mutate)


def tada_frequencies(case: Case) -> dict[str, float]:
    """f_c, f_b, f_r and Tada's f_i = Z f_c, f_o = Z (f_r − f_c) [Hz] at the loaded angle.

    Parameters
    ----------
    case : Case
        A case of the 3-D quasi-static model (its loaded contact angle is that model's).

    Returns
    -------
    dict of str to float
        ``f_c``, ``f_b``, ``f_r``, ``f_i`` and ``f_o`` [Hz].
    """
    from runout.geometry.kinematics import ball_spin_frequency, cage_frequency
    from runout.models import quasi_static_3d as qs3

    alpha = qs3.setup(case).contact_angle
    b, fr = case.bearing, case.operation.speed
    fc = float(cage_frequency(0.0, fr, b.element_diameter, b.pitch_diameter, alpha))
    fb = float(ball_spin_frequency(0.0, fr, b.element_diameter, b.pitch_diameter, alpha))
    z = b.elements
    return {"f_c": fc, "f_b": fb, "f_r": fr, "f_i": z * fc, "f_o": z * (fr - fc)}


def tada_line_pp(case: Case, freqs: Sequence[float], disp: np.ndarray | None = None) -> np.ndarray:
    """p-p [m] of each frequency in x, y, z, fitted jointly: shape (3, len(freqs)).

    ``disp`` is the displacement (3, samples) [m] on ``qs3.time_grid_of(case)`` when already
    solved; otherwise the case is solved here.

    Parameters
    ----------
    case : Case
        A case of the 3-D quasi-static model.
    freqs : sequence of float
        Frequencies of the lines [Hz].
    disp : ndarray, shape (3, samples), optional
        The solved displacement [m].

    Returns
    -------
    ndarray, shape (3, len(freqs))
        p-p of each line in x, y and z [m].
    """
    from runout.analysis.spectrum import extract_lines
    from runout.models import quasi_static_3d as qs3

    t = qs3.time_grid_of(case)
    if disp is None:
        disp, _ = qs3.solve(case, t)
    return 2.0 * extract_lines(t, disp, np.asarray(freqs), axis=-1).amplitude


def _tada_table2_row(part: str, lobes: int, n: int, direction: str) -> tuple[float, float]:
    """(main line p-p / waviness p-p, largest other-direction line / main line)."""
    if part == "ball":
        case = tada_case([{"part": "ball", "element": 1, "order": lobes, "peak_to_peak": TADA_PP}])
        f = tada_frequencies(case)
        pp = tada_line_pp(
            case, [lobes * f["f_b"] - f["f_c"], lobes * f["f_b"] + f["f_c"], lobes * f["f_b"]]
        )
        radial = max(pp[0, 0], pp[0, 1])
        axial = pp[2, 2]
        other = max(pp[0, 2], pp[1, 2]) / radial + max(pp[2, 0], pp[2, 1]) / axial
        return min(radial, axial) / TADA_PP, float(other)
    case = tada_case([{"part": part, "order": lobes, "peak_to_peak": TADA_PP, "phase": 0.3}])
    f = tada_frequencies(case)
    shift = 0 if (part == "inner" or direction == "z") else (1 if lobes % 8 == 1 else -1)
    freq = n * f["f_i" if part == "inner" else "f_o"] + shift * f["f_r"]
    pp = tada_line_pp(case, [freq])[:, 0]
    if direction == "xy":
        main = float(np.hypot(pp[0], pp[1]) / math.sqrt(2.0))
        return main / TADA_PP, float(pp[2] / main)
    return float(pp[2] / TADA_PP), float(max(pp[0], pp[1]) / pp[2])


@functools.cache
def _tada_table2_all() -> dict[str, tuple[float, float]]:
    out = {}
    for n in (1, 2):
        for part in ("inner", "outer"):
            for s, d in ((-1, "xy"), (0, "z"), (1, "xy")):
                out[f"{part} {n * 8 + s}"] = _tada_table2_row(part, n * 8 + s, n, d)
        out[f"ball {2 * n}"] = _tada_table2_row("ball", 2 * n, n, "")
    return out


def _tada_conclusion1() -> float:
    from runout.models import quasi_static_3d as qs3

    worst = 0.0
    for axial in (10.0, 20.0, 50.0):
        for z in (6, 8, 12):
            for clearance in (5e-6, 20e-6):
                for part, sign in (("inner", 1), ("outer", -1)):
                    lobes = z + sign
                    wav = [{"part": part, "order": lobes, "peak_to_peak": TADA_PP, "phase": 1.0}]
                    case = tada_case(
                        wav, z=z, axial=axial, clearance=clearance, revolutions=16, samples=1024
                    )
                    kin = qs3.setup(case).kinematics
                    f_ring = kin.inner if part == "inner" else kin.outer
                    freq = abs((lobes - sign) * kin.cage - lobes * f_ring)
                    pp = tada_line_pp(case, [freq])[:, 0]
                    worst = max(worst, abs(pp[0] / TADA_PP - 1), abs(pp[1] / TADA_PP - 1))
    return worst


TADA_CONCLUSION3_AMPLITUDES = (20e-9, 40e-9)


def tada_second_order_lines(z: int, lobes: int, direction: str) -> tuple[int, list[float]]:
    """Seed 000 conclusion 3: the second-order line of one outer waviness at two amplitudes.

    Returns the multiple of Z at which it falls, (2 lobes ± 1 or 2 lobes), and its p-p [m]
    for :data:`TADA_CONCLUSION3_AMPLITUDES` (x for ``direction="xy"``, z for ``"z"``).

    Parameters
    ----------
    z : int
        Number of balls Z [-].
    lobes : int
        Lobes of the outer-ring waviness [-].
    direction : {"xy", "z"}
        The radial (read in x) or the axial line.

    Returns
    -------
    multiple : int
        The multiple m of the cage frequency in the line's frequency |m f_c − 2 lobes f_o|
        (2 lobes ± 1 radially, 2 lobes axially).
    lines : list of float
        Its p-p at each amplitude of :data:`TADA_CONCLUSION3_AMPLITUDES` [m].

    Notes
    -----
    Seed 000 conclusion 3 (with Fig. 3): the second-order line grows with the square of the
    waviness amplitude.
    """
    from runout.models import quasi_static_3d as qs3

    lines = []
    multiple = 0
    for a in TADA_CONCLUSION3_AMPLITUDES:
        case = tada_case(
            [{"part": "outer", "order": lobes, "peak_to_peak": a}],
            z=z,
            revolutions=32,
            samples=2048,
        )
        kin = qs3.setup(case).kinematics
        lk = 2 * lobes
        m = 0 if direction == "z" else (-1 if (lk - 1) % z == 0 else 1)
        multiple = lk + m
        freq = abs(multiple * kin.cage - lk * kin.outer)
        pp = tada_line_pp(case, [freq])[:, 0]
        lines.append(float(pp[2] if direction == "z" else pp[0]))
    return multiple, lines


def _tada_conclusion3(z: int, lobes: int, direction: str) -> float:
    """Exponent of the second-order line's growth with the waviness amplitude (2 expected)."""
    _, lines = tada_second_order_lines(z, lobes, direction)
    amps = TADA_CONCLUSION3_AMPLITUDES
    return math.log(lines[1] / lines[0]) / math.log(amps[1] / amps[0])


#: §3.2 / Fig. 6: (a₇, ϑ₇ [°], a₉, ϑ₉ [°], printed inclination φ [°], Tada clockwise); the
#: amplitudes are peak-to-peak in units of :data:`TADA_PP`.
TADA_FIG6 = [
    (0.25, 0, 0.25, 0, 0),
    (0.25, 0, 0.5, 30, 135),
    (0.25, 0, 0.75, 60, 90),
    (0.25, 0, 1.0, 90, 45),
    (0.5, 30, 0.25, 0, 75),
    (0.5, 30, 0.5, 30, 30),
    (0.5, 30, 0.75, 60, 165),
    (0.5, 30, 1.0, 90, 120),
    (1.0, 90, 0.25, 0, 45),
    (1.0, 90, 0.5, 30, 0),
    (1.0, 90, 0.75, 60, 135),
    (1.0, 90, 1.0, 90, 90),
]


@functools.cache
def _tada_fig6_cell(i: int) -> tuple[float, float, float]:
    """(major-axis error, minor-axis error (relative to the 20 nm unit), inclination [deg])."""
    from runout.analysis.spectrum import extract_lines
    from runout.models import quasi_static_3d as qs3

    a7, t7, a9, t9, _ = TADA_FIG6[i]
    wav = [
        {"part": "inner", "order": 7, "peak_to_peak": a7 * TADA_PP, "phase": math.radians(7 * t7)},
        {"part": "inner", "order": 9, "peak_to_peak": a9 * TADA_PP, "phase": math.radians(9 * t9)},
    ]
    case = tada_case(wav, name="seed000_tada_fig6.toml")
    t = qs3.time_grid_of(case)
    disp, _ = qs3.solve(case, t)
    fit = extract_lines(t, disp[:2], np.array([tada_frequencies(case)["f_i"]]), axis=-1)
    amp, ph = fit.amplitude[:, 0], fit.phase[:, 0]
    m = np.array([[a * math.cos(p), -a * math.sin(p)] for a, p in zip(amp, ph, strict=True)])
    u, sv, _ = np.linalg.svd(m)
    major = abs(2 * sv[0] / ((a7 + a9) * TADA_PP) - 1)
    minor = abs(2 * sv[1] - abs(a7 - a9) * TADA_PP) / TADA_PP
    incl = (-math.degrees(math.atan2(u[1, 0], u[0, 0]))) % 180.0
    return float(major), float(minor), incl


def _angle_to(printed: float, value: float) -> float:
    """``value`` unwrapped (mod 180°) to the branch nearest ``printed``."""
    return printed + ((value - printed + 90.0) % 180.0 - 90.0)


def checks() -> list[Check]:
    """The Tada table.

    Returns
    -------
    list of Check
        The direction of each line of Table 2, conclusion 1 (first-order line = waviness
        p-p), the growth exponent of conclusion 3, and the inclination and axes of the
        ellipses of Fig. 6.

    Notes
    -----
    Seed 000 Table 2, conclusions 1 and 3 (Fig. 3) and §3.2 / Fig. 6 (:data:`TADA_FIG6`).
    """
    name = uses("seed000_tada_table2.toml", "seed 000 Table 1 bearing, Table 2 and conclusion 1")
    fig6 = uses("seed000_tada_fig6.toml", "seed 000 §3.2 / Fig. 6 ellipses (12 cells)")
    out: list[Check] = []
    labels = {-1: "nZ−1", 0: "nZ", 1: "nZ+1"}
    for n in (1, 2):
        for part in ("inner", "outer"):
            for s in (-1, 0, 1):
                key = f"{part} {n * 8 + s}"
                where = "z" if s == 0 else "x, y"
                out.append(
                    Check(
                        f"Seed 000 Table 2, {part} {labels[s]} (n = {n}, {n * 8 + s} lobes)",
                        f"line in {where} only: other direction / line",
                        None,
                        bind(lambda key: _tada_table2_all()[key][1], key),
                        "max",
                        1e-3,
                        expected=f"{where} only",
                        case=name,
                    )
                )
        key = f"ball {2 * n}"
        out.append(
            Check(
                f"Seed 000 Table 2, ball 2n (n = {n})",
                "x, y at 2n f_b ± f_c and z at 2n f_b only: other direction / line (sum)",
                None,
                bind(lambda key: _tada_table2_all()[key][1], key),
                "max",
                2e-3,
                expected="no cross-talk",
                case=name,
            )
        )
    out.append(
        Check(
            "Seed 000 conclusion 1",
            "radial first-order line of nZ±1 waviness / waviness p-p − 1, largest over F_a "
            "10/20/50 N, Z 6/8/12, P_d 5/20 µm, inner and outer",
            None,
            _tada_conclusion1,
            "max",
            1e-6,
            expected="0 (line = waviness p-p)",
            reason="exact: each ball's approach stays at the preload approach, so the Hertz "
            "exponent never acts",
            case=name,
        )
    )
    for z, lobes, d in ((9, 5, "xy"), (9, 4, "xy"), (8, 4, "z")):
        out.append(
            Check(
                "Seed 000 conclusion 3 / Fig. 3",
                f"growth exponent of the second-order line, Z = {z}, outer {lobes} lobes "
                f"({'radial' if d == 'xy' else 'axial'}), 20 → 40 nm",
                2.0,
                bind(lambda z, lobes, d: _tada_conclusion3(z, lobes, d), z, lobes, d),
                "abs",
                0.01,
                case=name,
            )
        )
    for i, (a7, t7, a9, t9, printed) in enumerate(TADA_FIG6):
        out.append(
            Check(
                f"Seed 000 Fig. 6, a₇ = {a7}, ϑ₇ = {t7}°, a₉ = {a9}, ϑ₉ = {t9}°",
                "major-axis inclination φ [°]",
                float(printed),
                bind(lambda i, printed: _angle_to(printed, _tada_fig6_cell(i)[2]), i, printed),
                "abs",
                1e-3,
                reason="eq. 8 was lost in extraction; reconstructed as φ = ((Z+1)·ϑ(Z+1) − "
                "(Z−1)·ϑ(Z−1))/2 (mod 180°)"
                if i == 0
                else "—",
                case=fig6,
            )
        )
    out.append(
        Check(
            "Seed 000 §3.2 / Fig. 6, 12 cells",
            "ellipse axes: largest error of major = sum, minor = difference (relative)",
            None,
            lambda: max(max(_tada_fig6_cell(i)[:2]) for i in range(len(TADA_FIG6))),
            "max",
            1e-6,
            expected="0",
            case=fig6,
        )
    )
    return out


INTRO = """\
Outer ring rotating at 5400 rpm, constant-pressure preload 20 N, d_m = 7 mm, D = 1 mm, Z = 8,
E = 208 GPa, ν = 0.3, P_d = 10 µm. **The paper gives no groove conformities; we use 0.52
(inner) / 0.53 (outer).** Inputs are peak-to-peak as in the paper (20 nm). Tada's eq. 1
(waviness functions) is missing from the extraction; we derive it from the kinematics (module
docstring). Line amplitudes are fitted at the predicted frequencies
(`runout.analysis.spectrum.extract_lines`, no leakage). Tests:
`tests/reference/test_seed000_tada.py`."""
