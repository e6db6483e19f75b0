"""Kinematics: bearing frequencies against published tables and the seeds' closed forms.

Sources: the CWRU bearing data centre's table of the 6205-2RS JEM fault frequencies (9 balls,
0.3126 in, pitch 1.537 in, 0°); seed 002 (Anderon vibration) eq. 48–59 for the 608; seed 001
(Y.-C. Kim, S.-K. Choi, K.-C. Yoon, "Vibration analysis of ball bearings with ball geometric
imperfections") §5.1; seed 003 (R.K. Purohit, K. Purohit, "Dynamic analysis of ball bearings
with effect of preload and number of balls", 2006) eq. 2.20; seed 004 (Y. Yu et al.,
"Prediction method for the radial runout of inner ring in cylindrical roller bearings", 2017)
eq. 3.
"""

from __future__ import annotations

import functools
import math

from runout.examples import nu209_bearing
from runout.validation.cases import load, uses
from runout.validation.core import Check

__all__ = [
    "CWRU_6205",
    "KIM_FREQUENCIES_HZ",
    "SEED002_ORDERS",
    "checks",
    "cwru_orders",
    "orders_608",
]

INCH = 25.4e-3

#: CWRU bearing data centre, drive-end bearing 6205-2RS JEM: fault frequencies in multiples of
#: the shaft speed (9 balls, D = 0.3126 in, d_m = 1.537 in, α = 0).
CWRU_6205 = {
    "ball_pass_inner": 5.4152,
    "ball_pass_outer": 3.5848,
    "cage": 0.39828,
    "ball_spin": 2.357,
}

#: Seed 002 ("Anderon vibration"), the 608 of Tab. 1, orders of the rotating inner ring:
#: eq. 48 (I_{7-1}), eq. 50 (inner flaw rate), eq. 51 (O_7), eq. 52 (O_14), eq. 55 (B_A0),
#: eq. 56 (B_B1), eq. 57 (B_A1), eq. 59 (2 ω_b/ω).
SEED002_ORDERS = {
    "I_6": 3.41198,
    "inner_flaw": 4.41198,
    "O_7": 2.58802,
    "O_14": 5.17603,
    "B_A0": 0.369716,
    "B_B1": 3.15316,
    "B_A1": 3.89259,
    "ball_flaw": 3.52287,
}

#: Seed 001 (Kim, Choi, Yoon) §5.1: f_c and f_b [Hz] of the Table 1 bearing at 7200 rpm,
#: α = 18.73° (rounded by the paper).
KIM_FREQUENCIES_HZ = {"cage": 50.0, "ball_spin": 335.0}


@functools.cache
def cwru_orders() -> dict[str, float]:
    """Our orders of the CWRU 6205 (inner ring turning at 1 Hz).

    Returns
    -------
    dict of str to float
        Frequency name (``cage``, ``ball_spin``, ``ball_pass_inner``, ...) -> order [-].

    Notes
    -----
    Compared with the CWRU bearing data centre's table of the 6205-2RS JEM
    (:data:`CWRU_6205`).
    """
    from runout import BallBearing, Operation
    from runout.geometry.kinematics import bearing_frequencies

    bearing = BallBearing(9, 0.3126 * INCH, 1.537 * INCH, contact_angle=0.0)
    return dict(bearing_frequencies(bearing, Operation("inner", speed=1.0)).orders())


@functools.cache
def orders_608() -> dict[str, float]:
    """Our orders of the 608 of ``examples/seed002_608.toml`` (inner ring turning at 1 Hz).

    Returns
    -------
    dict of str to float
        Frequency name (``cage``, ``ball_spin``, ``ball_pass_inner``, ...) -> order [-].

    Notes
    -----
    Compared with seed 002 eq. 48-59 (:data:`SEED002_ORDERS`).
    """
    from runout import Operation
    from runout.geometry.kinematics import bearing_frequencies

    case = load("seed002_608.toml")
    return dict(bearing_frequencies(case.bearing, Operation("inner", speed=1.0)).orders())


def _kim_freq(which: str) -> float:
    from runout.geometry.kinematics import bearing_frequencies

    case = load("seed001_kim_spindle.toml")
    f = bearing_frequencies(case.bearing, case.operation, math.radians(18.73))
    return float(f.cage if which == "cage" else f.ball_spin)


def _seed003_bpf_error() -> float:
    from runout import Operation
    from runout.geometry.kinematics import bearing_frequencies

    case = load("seed003_purohit.toml")
    b = case.bearing
    f = bearing_frequencies(b, Operation("inner", speed=case.operation.speed), 0.0)
    expected = 0.5 * b.elements * case.operation.speed * (1 - b.element_diameter / b.pitch_diameter)
    return abs(float(f.ball_pass_outer) / expected - 1.0)


def _seed004_cage_error() -> float:
    from runout import Operation
    from runout.geometry.kinematics import bearing_frequencies

    b = nu209_bearing()
    f = bearing_frequencies(b, Operation("inner", speed=1.0))
    d_i, d_e = b.inner_raceway_diameter, b.outer_raceway_diameter
    expected = 0.5 * (1 - 2 * b.element_diameter / (d_i + d_e))
    return abs(float(f.cage) / expected - 1.0)


def checks() -> list[Check]:
    """The kinematics table.

    Returns
    -------
    list of Check
        Orders of the CWRU 6205 and of seed 002's 608, seed 001's f_c and f_b, and two closed
        forms checked against theory.

    Notes
    -----
    The CWRU 6205-2RS JEM table; seed 002 eq. 48-59; seed 001 §5.1; seed 003 eq. 2.20;
    seed 004 eq. 3.
    """
    cw = "CWRU 6205-2RS JEM (9 balls, 0.3126 in, 1.537 in, 0°)"
    s002 = uses("seed002_608.toml", "seed 002 Tab. 1, eq. 43–47, eq. 48–59, Fig. 12")
    s001 = uses("seed001_kim_spindle.toml", "seed 001 Table 1 bearing, §5.1 frequencies")
    o = orders_608
    return [
        Check(
            cw,
            "BPFI [orders]",
            CWRU_6205["ball_pass_inner"],
            lambda: cwru_orders()["ball_pass_inner"],
            "abs",
            5e-5,
        ),
        Check(
            "″",
            "BPFO",
            CWRU_6205["ball_pass_outer"],
            lambda: cwru_orders()["ball_pass_outer"],
            "abs",
            5e-5,
        ),
        Check(
            "″",
            "FTF (cage)",
            CWRU_6205["cage"],
            lambda: cwru_orders()["cage"],
            "rel",
            1e-4,
            reason="the table's last digit: 0.5 (1 − 0.3126/1.537) = 0.398308; checked at "
            "1e-4 relative",
        ),
        Check(
            "″",
            "ball spin",
            CWRU_6205["ball_spin"],
            lambda: cwru_orders()["ball_spin"],
            "abs",
            5e-4,
            reason="printed to 4 figures",
        ),
        Check(
            "Seed 002 eq. 48 (608)",
            "I₇₋₁ (k = Z − 1 = 6)",
            SEED002_ORDERS["I_6"],
            lambda: o()["ball_pass_inner"] - 1,
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 50",
            "inner flaw rate",
            SEED002_ORDERS["inner_flaw"],
            lambda: o()["ball_pass_inner"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 51",
            "O_7",
            SEED002_ORDERS["O_7"],
            lambda: o()["ball_pass_outer"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 52",
            "O_14",
            SEED002_ORDERS["O_14"],
            lambda: 2 * o()["ball_pass_outer"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 55",
            "B_A0 (cage)",
            SEED002_ORDERS["B_A0"],
            lambda: o()["cage"],
            "abs",
            1e-6,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 56",
            "B_B1",
            SEED002_ORDERS["B_B1"],
            lambda: 2 * o()["ball_spin"] - o()["cage"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 57",
            "B_A1",
            SEED002_ORDERS["B_A1"],
            lambda: 2 * o()["ball_spin"] + o()["cage"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 002 eq. 59",
            "2 ω_b/ω",
            SEED002_ORDERS["ball_flaw"],
            lambda: 2 * o()["ball_spin"],
            "abs",
            1e-5,
            case=s002,
            digits=6,
        ),
        Check(
            "Seed 001 §5.1 (Table 1, 7200 rpm, α = 18.73°)",
            "f_c [Hz]",
            KIM_FREQUENCIES_HZ["cage"],
            lambda: _kim_freq("cage"),
            "abs",
            0.5,
            reason="the paper rounds to 50 Hz",
            case=s001,
        ),
        Check(
            "″",
            "f_b [Hz]",
            KIM_FREQUENCIES_HZ["ball_spin"],
            lambda: _kim_freq("spin"),
            "abs",
            0.5,
            reason="the paper rounds to 335 Hz",
            case=s001,
        ),
        Check(
            "Seed 003 eq. 2.20 (theory)",
            "BPF vs (Z/2) f_i (1 − D/d_m), relative error",
            None,
            _seed003_bpf_error,
            "max",
            1e-12,
            expected="0",
            case=uses("seed003_purohit.toml", "seed 003 Table 2 rotor, Figs. 3–4 (dynamic)"),
        ),
        Check(
            "Seed 004 eq. 3 (theory)",
            "cage ratio vs ½ (1 − 2D_w/(d_i + d_e)), relative error",
            None,
            _seed004_cage_error,
            "max",
            1e-12,
            expected="0",
            case=uses("seed004_nu209.toml", "seed 004 Table 1 NU209, Fig. 9"),
        ),
    ]


# ---------------------------------------------------------------------------------------------
