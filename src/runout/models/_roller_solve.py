r"""The stable position of the rigid constraint model (seed 004 §5, done as an optimisation).

Split out of :mod:`runout.models.roller_constraint` (which documents the model and re-exports
these names): :func:`solve` runs the compiled active-set walk
(:mod:`runout.models._roller_kernels`) at every rotation angle; the support-function gaps,
the closed forms and ellipse positions of seed 004's validation, and the order sweep are here.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numba
import numpy as np
from numpy.typing import NDArray

from runout.base.errors import ConvergenceError, GeometryError, NumericalError
from runout.geometry.imperfections import Harmonics, single_harmonic
from runout.models._roller_kernels import (
    _FAR_CONTACT,
    _NO_STABLE,
    _NO_STRADDLE,
    _NO_VERTEX,
    _SETTLE_FAIL,
    SETTLE_EACH,
    SETTLE_GIVEN,
    SETTLE_ONCE,
    _solve_all,
    _solve_pairs,
    deviations,
    gap,
    support,
    work_arrays,
)
from runout.models._roller_setup import (
    ConstraintGeometry,
    _bodies,
    _check_convex,
    _pack,
    _turns,
    absolute_spin_ratio,
    cage_ratio,
    elements_to_fixed_frame,
)

FloatArray = NDArray[np.float64]
TWO_PI = 2.0 * math.pi

#: Rollers closer than this to the loaded ring are reported as touching [m].
TOL_TOUCH = 1e-11


_STATUS_TEXT = {
    _NO_STRADDLE: "no roller on one side of the load line (too few rollers near the load zone)",
    _NO_VERTEX: "the two-contact Newton solve did not converge",
    _NO_STABLE: (
        "no stable position: every two-roller contact either interferes with another roller "
        "or does not straddle the load (rollers jam: is there radial clearance?)"
    ),
    _SETTLE_FAIL: "a roller could not be settled onto the fixed raceway (Newton did not converge)",
    _FAR_CONTACT: (
        "a roller more than 90 deg from the load zone touches the loaded ring: the clearance is "
        "too small for the part errors (the rigid measuring model does not apply)"
    ),
}


@dataclass(frozen=True, eq=False)
class Solution:
    """Stable positions of the loaded ring over a set of rotation angles.

    Attributes
    ----------
    geometry : ConstraintGeometry
        The model input.
    alpha : ndarray, shape (n,)
        Rotation angles of the turning ring [rad].
    centre : ndarray, shape (n, 2)
        Centre of the loaded (turning) ring relative to the fixed ring's centre [m].
    pair : ndarray of int, shape (n, 2)
        The two rollers (0-based) whose contacts hold the ring.
    multipliers : ndarray, shape (n, 2)
        Their KKT multipliers (contact forces per unit measuring load) [-].
    gaps : ndarray, shape (n, Z)
        Gap between every roller and the loaded ring at the stable position [m].
    roller_centres : ndarray, shape (n, Z, 2)
        Roller centres after settling on the fixed ring [m].
    """

    geometry: ConstraintGeometry
    alpha: FloatArray
    centre: FloatArray
    pair: NDArray[np.int64]
    multipliers: FloatArray
    gaps: FloatArray
    roller_centres: FloatArray

    @property
    def radial(self) -> FloatArray:
        """Displacement along the load direction u [m]."""
        return np.asarray(self.centre @ self.geometry.load_direction)

    @property
    def horizontal(self) -> FloatArray:
        """Displacement perpendicular to the load, along u rotated +90° [m]."""
        u = self.geometry.load_direction
        return np.asarray(self.centre @ np.array([-u[1], u[0]]))

    @property
    def touching(self) -> NDArray[np.bool_]:
        """Rollers within :data:`TOL_TOUCH` of the loaded ring, shape (n, Z)."""
        return np.asarray(self.gaps <= TOL_TOUCH)

    @property
    def runout(self) -> float:
        """max - min of :attr:`radial` [m]."""
        return float(np.ptp(self.radial))


def solve(geo: ConstraintGeometry, alpha: Sequence[float] | FloatArray) -> Solution:
    """Stable position of the loaded ring at each rotation angle.

    Parameters
    ----------
    geo : ConstraintGeometry
        Bearing, imperfections, turning ring and load direction.
    alpha : array_like, shape (n,)
        Rotation angles of the turning ring [rad], in the order they are visited (each solve
        starts from the previous position).

    Returns
    -------
    Solution

    Raises
    ------
    NumericalError
        No admissible stable position (e.g. rollers jam without clearance); the message names
        the rotation angle and the cause.
    ConvergenceError
        A Newton solve did not converge.
    """
    return _solve_one(geo, _angles(alpha))


def solve_many(
    geometries: Sequence[ConstraintGeometry], alpha: Sequence[float] | FloatArray
) -> list[Solution]:
    """:func:`solve` for several geometries over the same angles, on parallel threads.

    The compiled solver releases the GIL, so the independent solves run on up to
    :func:`numba.get_num_threads` threads; each solution is the one :func:`solve` gives
    (bit for bit, whatever the number of threads).

    Parameters
    ----------
    geometries : sequence of ConstraintGeometry
    alpha : array_like, shape (n,)
        Rotation angles of the turning ring [rad], shared by every solve.

    Returns
    -------
    list of Solution
        In the order of ``geometries``.

    Raises
    ------
    NumericalError, ConvergenceError
        As :func:`solve`, for the first geometry that fails.
    """
    al = _angles(alpha)
    geos = list(geometries)
    threads = min(len(geos), max(1, numba.get_num_threads()))
    if threads <= 1:
        return [_solve_one(g, al) for g in geos]
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=threads) as pool:
        return list(pool.map(lambda g: _solve_one(g, al), geos))


def _angles(alpha: Sequence[float] | FloatArray) -> FloatArray:
    al = np.ascontiguousarray(np.asarray(alpha, dtype=np.float64).reshape(-1))
    if not np.all(np.isfinite(al)):
        raise GeometryError("alpha", "rotation angles must be finite")
    return al


def _solve_one(geo: ConstraintGeometry, al: FloatArray) -> Solution:
    """:func:`solve` on checked angles."""
    settled = np.empty((al.size, geo.n_elements))
    radii = np.empty((al.size, geo.n_elements, 3))
    out = _walk(geo, al, settled, SETTLE_EACH, radii, False, False, True)
    out_c, out_pair, out_lam, out_gap, out_rc = out
    return Solution(geo, al, out_c, out_pair, out_lam, out_gap, out_rc)


def _walk(
    geo: ConstraintGeometry,
    al: FloatArray,
    settled: FloatArray,
    settle: int,
    radii: FloatArray,
    radii_given: bool,
    warm: bool,
    exact: bool,
) -> tuple[FloatArray, NDArray[np.int64], FloatArray, FloatArray, FloatArray]:
    """The compiled walk over the checked angles ``al``: centres, pairs, multipliers, gaps and
    roller centres (:class:`Solution`'s arrays).

    ``settled`` (n, Z) receives the settled radius [m] of every roller near the contact side,
    or gives it (``settle``, ``_roller_kernels.SETTLE_EACH`` ...: with ``SETTLE_GIVEN`` the
    radii of a bearing whose fixed ring and rollers are those of ``geo``, over the same
    angles); ``radii`` (n, Z, 3) receives the rollers' directions, or gives them with
    ``radii_given`` (``_roller_kernels._solve_all``); ``warm`` starts the Newton solves from
    the solutions nearby (the same stops: the same solutions to round-off); without
    ``exact`` the gaps not computed by the search are NaN (a caller that wants only the
    centres).
    """
    z = geo.n_elements
    bodies = _pack(geo)
    beta0 = geo.element_positions
    u = geo.load_direction
    c0 = 0.5 * max(geo.radial_clearance, 0.0) * u
    inner_turns, outer_turns = _turns(geo)
    n = al.size
    out_c = np.zeros((n, 2))
    out_pair = np.zeros((n, 2), dtype=np.int64)
    out_lam = np.zeros((n, 2))
    out_gap = np.zeros((n, z))
    out_rc = np.zeros((n, z, 2))
    out_status = np.zeros(n, dtype=np.int64)
    mode = 0 if geo.rotating_ring == "inner" else 1
    ux, uy = float(u[0]), float(u[1])
    cx, cy = float(c0[0]), float(c0[1])
    dev = deviations(bodies)
    work = work_arrays(z)
    out = (out_c, out_pair, out_lam, out_gap)
    kinematics = (cage_ratio(geo), absolute_spin_ratio(geo), inner_turns, outer_turns)
    beta = np.ascontiguousarray(beta0)
    start = 0
    for _ in range(n + 1):  # each pass solves at least one angle
        start, cx, cy = _solve_all(
            al, start, mode, bodies, beta, *kinematics, ux, uy, cx, cy, *out, out_rc,
            out_status, dev, *work, settled, settle, radii, radii_given, warm, exact,
        )  # fmt: skip
        if start >= n:
            break
        # an angle the active-set walk could not place: every pair of candidates (compiled
        # only in a run that needs it), then on with the next angle
        cx, cy = _solve_pairs(
            start, mode, bodies, cx, cy, ux, uy, *out, out_status, dev, *work, warm, exact
        )
        start += 1
    bad = np.flatnonzero(out_status)
    if bad.size:
        i = int(bad[0])
        code = int(out_status[i])
        cls = ConvergenceError if code in (_NO_VERTEX, _SETTLE_FAIL) else NumericalError
        raise cls(
            f"roller_constraint: {_STATUS_TEXT.get(code, 'unknown failure')} at rotation angle "
            f"{math.degrees(al[i]):.6g} deg",
            instant=i,
            time=float(al[i]),
        )
    return out_c, out_pair, out_lam, out_gap, out_rc


# --------------------------------------------------------------------------------------------
# thin wrappers of the kernels (tests, verification)
# --------------------------------------------------------------------------------------------
def support_function(
    radius: float, harmonics: Harmonics, psi: float, turned: float = 0.0
) -> tuple[float, float, float]:
    """Support function of the profile ``radius + harmonics(θ - turned)`` in direction ψ.

    Returns
    -------
    h, dh_dpsi, radius_of_curvature : float
        :math:`h(\\psi) = \\max_\\theta \\rho(\\theta)\\cos(\\theta-\\psi)` [m], its derivative
        [m/rad] and the radius of curvature of the profile at the support point [m].
    """
    return support(0, _bodies([radius], [harmonics]), float(turned), float(psi))


def _pair(
    ra: float, ha: Harmonics, rb: float, hb: Harmonics, turned_a: float, turned_b: float,
    centre_b: Sequence[float], inside: bool,
) -> tuple[float, float]:  # fmt: skip
    bodies = _bodies([ra, rb], [ha, hb])
    dx, dy = float(centre_b[0]), float(centre_b[1])
    g, psi, _ = gap(0, float(turned_a), 1, float(turned_b), dx, dy, bodies, inside)
    return g, psi


def _cold(n: int) -> FloatArray:
    """Support points of ``n`` bodies to start from: δ = 0 (see ``_roller_kernels._support``)."""
    warm = np.zeros((n, 3))
    warm[:, 1] = 1.0
    return warm


def pair_gap(
    radius_a: float,
    harmonics_a: Harmonics,
    radius_b: float,
    harmonics_b: Harmonics,
    centre_b: Sequence[float],
    turned_a: float = 0.0,
    turned_b: float = 0.0,
) -> tuple[float, float]:
    """Signed closest distance between two separate convex profiles (eq. 13-16, exact).

    Body A is centred at the origin, body B at ``centre_b``; each profile is
    ``radius + harmonics(θ - turned)``. Returns the gap [m] (negative: interference depth)
    and the direction ψ of the contact normal from A towards B [rad].
    """
    return _pair(radius_a, harmonics_a, radius_b, harmonics_b, turned_a, turned_b, centre_b, False)


def inside_gap(
    radius_e: float,
    harmonics_e: Harmonics,
    radius_b: float,
    harmonics_b: Harmonics,
    centre_b: Sequence[float],
    turned_e: float = 0.0,
    turned_b: float = 0.0,
) -> tuple[float, float]:
    """Signed distance from profile B (centre ``centre_b``) to the enclosing profile E (eq. 8-11).

    Returns the gap [m] (negative: B sticks out of E) and the normal direction ψ [rad].
    """
    return _pair(radius_e, harmonics_e, radius_b, harmonics_b, turned_e, turned_b, centre_b, True)


# --------------------------------------------------------------------------------------------
# verification cases of seed 004 §6
# --------------------------------------------------------------------------------------------
def _straddling_pair(beta: FloatArray, w: FloatArray) -> tuple[int, int]:
    phi = np.arctan2(
        w[0] * np.sin(beta) - w[1] * np.cos(beta), w[0] * np.cos(beta) + w[1] * np.sin(beta)
    )
    left = np.flatnonzero(phi <= 0)
    right = np.flatnonzero(phi > 0)
    return int(left[np.argmax(phi[left])]), int(right[np.argmin(phi[right])])


def analytic_circular(
    inner_diameter: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: FloatArray,
) -> FloatArray:
    """Inner-ring centre for perfect circular parts, seed 004 eq. 17, in closed form [m].

    The two rollers either side of the bottom sit at radius (d_e - D_w)/2; the ring centre is
    the intersection, on the bearing's side, of the two circles of radius (d_i + D_w)/2 about
    them (the paper solves eq. 17 by Newton-Raphson; the intersection is explicit).

    Returns
    -------
    ndarray, shape (n, 2)
    """
    al = np.asarray(alpha, dtype=np.float64).reshape(-1)
    dm = 0.5 * (inner_diameter + outer_diameter)
    gam2 = 0.5 * al * (1.0 - roller_diameter / dm)
    s = 0.5 * (outer_diameter - roller_diameter)
    rho = 0.5 * (inner_diameter + roller_diameter)
    out = np.empty((al.size, 2))
    w = np.array([0.0, -1.0])
    base = 2.0 * np.pi * np.arange(n_elements) / n_elements
    for i, g in enumerate(gam2):
        beta = base + g
        ja, jb = _straddling_pair(beta, w)
        pa = s * np.array([math.cos(beta[ja]), math.sin(beta[ja])])
        pb = s * np.array([math.cos(beta[jb]), math.sin(beta[jb])])
        mid = 0.5 * (pa + pb)
        half = 0.5 * float(np.linalg.norm(pb - pa))
        t = (pb - pa) / (2.0 * half)
        normal = np.array([-t[1], t[0]])
        if normal @ mid > 0:  # towards the bearing centre
            normal = -normal
        out[i] = mid + math.sqrt(rho * rho - half * half) * normal
    return out


def ellipse_harmonics(semi_major: float, semi_minor: float, n: int = 64) -> tuple[float, Harmonics]:
    """Mean radius and Fourier harmonics of the ellipse of seed 004 eq. 20-21 in its ring frame.

    The paper's polar radius :math:`ab/\\sqrt{(a\\cos\\theta)^2 + (b\\sin\\theta)^2}` has the
    major axis along the ring's y axis. Its coefficients fall by about ((a-b)/(a+b)) per
    order, so ``n`` samples give it to rounding error.
    """
    a, b = semi_major, semi_minor
    theta = 2.0 * np.pi * np.arange(n) / n
    r = a * b / np.sqrt((a * np.cos(theta)) ** 2 + (b * np.sin(theta)) ** 2)
    c = np.fft.rfft(r) / n
    mean = float(c[0].real)
    orders = np.arange(1, n // 2)
    coef = 2.0 * c[1 : n // 2]
    keep = np.abs(coef) > 1e-24
    return mean, Harmonics.from_complex(orders[keep], coef[keep])


def _roller_pair_positions(
    inner_diameter: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: float,
) -> tuple[FloatArray, FloatArray]:
    dm = 0.5 * (inner_diameter + outer_diameter)
    beta = 2.0 * np.pi * np.arange(n_elements) / n_elements + 0.5 * alpha * (
        1.0 - roller_diameter / dm
    )
    ja, jb = _straddling_pair(beta, np.array([0.0, -1.0]))
    s = 0.5 * (outer_diameter - roller_diameter)
    pa = s * np.array([math.cos(beta[ja]), math.sin(beta[ja])])
    pb = s * np.array([math.cos(beta[jb]), math.sin(beta[jb])])
    return pa, pb


def _newton2(fun: Any, x0: FloatArray, what: str) -> FloatArray:
    x = np.array(x0, dtype=np.float64)
    for _ in range(60):
        f, jac = fun(x)
        dx = np.linalg.solve(jac, -f)
        x = x + dx
        if np.linalg.norm(dx) <= 1e-16:
            return x
    if np.linalg.norm(dx) <= 1e-14:
        return x
    raise ConvergenceError(f"{what}: Newton-Raphson did not converge")


def ellipse_position_paper(
    semi_major: float,
    semi_minor: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: float,
    inner_diameter: float | None = None,
) -> FloatArray:
    """Ring centre from seed 004 eq. 18-21: radius of the ellipse along the line of centres.

    ``inner_diameter`` only sets the cage ratio of eq. 3 (default 2 × semi-major).
    """
    a, b = semi_major, semi_minor
    d_i = 2.0 * a if inner_diameter is None else inner_diameter
    pa, pb = _roller_pair_positions(d_i, outer_diameter, roller_diameter, n_elements, alpha)
    rr = 0.5 * roller_diameter

    def polar(t: float) -> tuple[float, float]:
        x = t - alpha
        q = (a * math.cos(x)) ** 2 + (b * math.sin(x)) ** 2
        r = a * b / math.sqrt(q)
        dq = (b * b - a * a) * math.sin(2 * x)
        return r, -0.5 * r * dq / q

    def fun(c: FloatArray) -> tuple[FloatArray, FloatArray]:
        f = np.empty(2)
        jac = np.empty((2, 2))
        for i, pj in enumerate((pa, pb)):
            d = pj - c
            dist = float(np.linalg.norm(d))
            theta = math.atan2(-d[1], -d[0]) + math.pi  # direction from ring centre to roller
            r, dr = polar(theta)
            f[i] = dist - r - rr
            # d dist/dc = -d/|d|; d theta/dc = (d_y, -d_x)/|d|^2 ... chain rule
            dtheta = np.array([d[1], -d[0]]) / dist**2
            jac[i] = -d / dist - dr * dtheta
        return f, jac

    c0 = np.array([0.0, -0.5 * (outer_diameter - 2 * a - 2 * roller_diameter) / 2.0])
    return _newton2(fun, c0, "ellipse eq. 18-21")


def ellipse_position_exact(
    semi_major: float,
    semi_minor: float,
    outer_diameter: float,
    roller_diameter: float,
    n_elements: int,
    alpha: float,
    inner_diameter: float | None = None,
) -> FloatArray:
    """Ring centre for the elliptic inner raceway with the exact closest distance.

    Each roller centre lies at distance D_w/2 from the ellipse (on its parallel curve); the
    closest ellipse point is found on the parametric ellipse (b cos t, a sin t), turned by α,
    by Newton's method on (q(t) - P)·q'(t) = 0, independently of the support-function code.
    """
    a, b = semi_major, semi_minor
    d_i = 2.0 * a if inner_diameter is None else inner_diameter
    pa, pb = _roller_pair_positions(d_i, outer_diameter, roller_diameter, n_elements, alpha)
    rr = 0.5 * roller_diameter
    ca, sa = math.cos(alpha), math.sin(alpha)
    rot = np.array([[ca, -sa], [sa, ca]])

    def closest(c: FloatArray, pj: FloatArray) -> tuple[float, FloatArray]:
        loc = rot.T @ (pj - c)  # roller centre in the ring frame
        t = math.atan2(loc[1] / a, loc[0] / b)
        for _ in range(60):
            q = np.array([b * math.cos(t), a * math.sin(t)])
            q1 = np.array([-b * math.sin(t), a * math.cos(t)])
            q2 = -q
            f = (q - loc) @ q1
            fp = q1 @ q1 + (q - loc) @ q2
            dt = f / fp
            t -= dt
            if abs(dt) < 1e-16:
                break
        q = np.array([b * math.cos(t), a * math.sin(t)])
        v = loc - q
        dist = float(np.linalg.norm(v))
        return dist, rot @ (v / dist)

    def fun(c: FloatArray) -> tuple[FloatArray, FloatArray]:
        f = np.empty(2)
        jac = np.empty((2, 2))
        for i, pj in enumerate((pa, pb)):
            dist, nrm = closest(c, pj)
            f[i] = dist - rr
            jac[i] = -nrm
        return f, jac

    c0 = np.array([0.0, -0.5 * (outer_diameter - 2 * a - 2 * roller_diameter) / 2.0])
    return _newton2(fun, c0, "exact ellipse contact")


@dataclass(frozen=True, eq=False)
class OrderSweep:
    """Runout against the harmonic order of one part's roundness error.

    Attributes
    ----------
    orders : ndarray of int, shape (m,)
        Harmonic orders swept.
    parts : tuple of str
        Parts ("inner", "outer", "roller"); "roller" puts the harmonic on every roller.
    amplitude : float
        Zero-to-peak amplitude used for every run [m].
    runout : ndarray, shape (len(parts), m)
        Radial runout p-p along the load [m], perfect-bearing runout included; where
        ``solved`` is false the entry is 0 and means nothing (no stable position).
    solved : ndarray of bool, shape (len(parts), m)
        Whether the bearing with that harmonic has a stable position at every angle: a
        harmonic as large as the clearance can jam the rollers (:func:`order_sweep`).
    baseline : float
        Runout of the same bearing with perfect parts (roller passage alone) [m].
    n_elements : int
        Z, to read the table against multiples of the roller number.
    """

    orders: NDArray[np.int64]
    parts: tuple[str, ...]
    amplitude: float
    runout: FloatArray
    solved: NDArray[np.bool_]
    baseline: float
    n_elements: int

    def rows(self) -> list[dict[str, float | int | None]]:
        """One row per order: ``order``, ``order_over_z`` and ``<part>_pp_m`` for each part
        (None where that harmonic jams the rollers or makes its part non-convex: no runout to
        state)."""
        out: list[dict[str, float | int | None]] = []
        for i, kk in enumerate(self.orders):
            row: dict[str, float | int | None] = {
                "order": int(kk),
                "order_over_z": float(kk) / self.n_elements,
            }
            for j, part in enumerate(self.parts):
                row[f"{part}_pp_m"] = float(self.runout[j, i]) if self.solved[j, i] else None
            out.append(row)
        return out


def order_sweep(
    geo: ConstraintGeometry,
    alpha: FloatArray,
    orders: Sequence[int] | None = None,
    amplitude: float = 1e-6,
    parts: Sequence[str] = ("inner", "outer", "roller"),
) -> OrderSweep:
    """Runout for a single harmonic of each order on each part in turn (others perfect).

    Parameters
    ----------
    geo : ConstraintGeometry
        The bearing; its own imperfections are discarded (the sweep starts from perfect parts,
        keeping the roller size and pitch errors out as well).
    alpha : ndarray
        Rotation angles [rad].
    orders : sequence of int, optional
        Default 2 … 3Z.
    amplitude : float
        Zero-to-peak amplitude of the harmonic [m].
    parts : sequence of {"inner", "outer", "roller"}
        A "roller" harmonic is the same on every roller in its cage frame (phase 0 at its outer
        contact at α = 0), like a ``[[waviness]] part = "roller"`` entry of a case.

    Returns
    -------
    OrderSweep
        A harmonic under which the rollers have no stable position at some angle (an
        amplitude comparable with the clearance jams them), or which makes its part
        non-convex (amplitude x order^2 comparable with the radius: outside the rigid model,
        as a run's ``geometry_from`` refuses), is marked unsolved (:attr:`OrderSweep.solved`)
        rather than failing the sweep: the sweep is an aid to read the run's bearing, whose
        own solution stands.

    Raises
    ------
    NumericalError, ConvergenceError
        When the perfect bearing itself has no stable position.

    Notes
    -----
    Each entry is the runout :func:`solve` gives for that geometry alone, to round-off: the
    solves share the perfect bearing's settled rollers where they are the same, settle alike
    rollers once per angle, start their Newton solves warm and compute no gaps (where a part's
    convexity margin is below :data:`EXACT_MARGIN`, close to flat, only the last: a warm start
    can reach another stationary point of a gap there)
    (``_roller_kernels`` module docstring). Model: Yu et al., "Prediction method for the
    radial runout of inner ring in cylindrical roller bearings", Math. Probl. Eng., 2017
    (seed 004), eq. 1-16 and §5.
    """
    z = geo.n_elements
    ks = np.arange(2, 3 * z + 1) if orders is None else np.asarray(orders, dtype=np.int64)
    perfect = geo.replace(
        inner=Harmonics.empty(),
        outer=Harmonics.empty(),
        elements=(Harmonics.empty(),) * z,
        element_radii=np.full(z, 0.5 * geo.element_diameter),
        pitch_errors=np.zeros(z),
    )
    loaded = "inner" if geo.rotating_ring == "inner" else "outer"
    geos: list[ConstraintGeometry] = []
    settles: list[int] = []
    for part in parts:
        for kk in ks:
            h = single_harmonic(int(kk), amplitude)
            if part == "inner":
                g = perfect.replace(inner=h)
            elif part == "outer":
                g = perfect.replace(outer=h)
            elif part in ("roller", "element", "ball"):
                g = perfect.replace(
                    elements=elements_to_fixed_frame((h,) * z, perfect.element_positions)
                )
            else:
                raise GeometryError("order_sweep.parts", f"unknown part {part!r}")
            geos.append(g)
            # the fixed ring and the rollers of a harmonic on the loaded ring are the perfect
            # bearing's: so are the settled rollers; a roller harmonic is the same on every
            # roller in its cage frame, and the fixed ring is round: every roller settles at
            # the same radius at a given angle (module docstring of _roller_kernels)
            if part == loaded:
                settles.append(SETTLE_GIVEN)
            elif part in ("roller", "element", "ball"):
                settles.append(SETTLE_ONCE)
            else:
                settles.append(SETTLE_EACH)
    al = _angles(alpha)
    settled = np.empty((al.size, z))
    # the perfect bearing first: its failure is the bearing's (raised), its settled rollers
    # are those of every geometry whose harmonic is on the loaded ring, its rollers'
    # directions those of every geometry
    radii = np.empty((al.size, z, 3))
    walk = _walk(perfect, al, settled, SETTLE_EACH, radii, False, True, False)
    baseline = _runout(perfect, walk[0])
    runouts = _runouts_or_none(geos, settles, al, settled, radii)
    solved = np.array([r is not None for r in runouts]).reshape(len(parts), ks.size)
    table = np.array([0.0 if r is None else r for r in runouts]).reshape(len(parts), ks.size)
    return OrderSweep(ks, tuple(parts), amplitude, table, solved, baseline, z)


def _runout(geo: ConstraintGeometry, centre: FloatArray) -> float:
    """:attr:`Solution.runout` of the centres ``centre`` (n, 2) [m]."""
    return float(np.ptp(np.asarray(centre @ geo.load_direction)))


#: Least convexity margin of the parts (:func:`_roller_setup._convexity_margin`) from which
#: the order sweep takes its shortcuts (warm Newton starts, alike rollers settled once); below
#: it a geometry is walked as a run's solve walks it (cold, every roller settled on its own).
EXACT_MARGIN = 0.5


def _runouts_or_none(
    geometries: Sequence[ConstraintGeometry],
    settles: Sequence[int],
    al: FloatArray,
    settled: FloatArray,
    radii: FloatArray,
) -> list[float | None]:
    """Runout [m] of each geometry over the checked angles ``al``, None for one without a
    stable position at some angle; on parallel threads (the compiled walk releases the GIL).
    ``radii``: the rollers' directions of the perfect bearing (:func:`_walk`), the same in all.

    ``settles`` says how each geometry's rollers settle (``_roller_kernels.SETTLE_EACH`` ...);
    ``SETTLE_GIVEN`` takes them from ``settled`` (those of a bearing with the same fixed ring
    and rollers, :func:`_walk`). Only the centres are wanted: the Newton solves start warm and
    the gaps the search did not need are not computed.
    """

    def one(i: int) -> float | None:
        g = geometries[i]
        try:
            # a part the harmonic makes non-convex is outside the rigid model (geometry_from
            # refuses it in a run): its support functions have several stationary points
            margin = _check_convex(g)
        except GeometryError:
            return None
        own = settled if settles[i] == SETTLE_GIVEN else np.empty_like(settled)
        settle = settles[i]
        warm = True
        if margin < EXACT_MARGIN:
            # a part close to flat somewhere: a contact's Newton solve started from the normal
            # of the angle before can reach another stationary point of its gap, and alike
            # rollers settled once differ from each settled on its own by more than round-off
            # (random runs found a warm walk that jammed where the cold one did not, at margin
            # 0.12, and a roller harmonic 1.4e-11 m off at 0.10): the run's own walk
            warm = False
            settle = SETTLE_EACH if settle == SETTLE_ONCE else settle
        try:
            return _runout(g, _walk(g, al, own, settle, radii, True, warm, False)[0])
        except NumericalError:  # ConvergenceError included: jammed or unsettled
            return None

    threads = min(len(geometries), max(1, numba.get_num_threads()))
    if threads <= 1:
        return [one(i) for i in range(len(geometries))]
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=threads) as pool:
        return list(pool.map(one, range(len(geometries))))
