"""Measured roundness profiles: CSV reading and the Fourier fit to :class:`Harmonics`.

Part of :mod:`runout.geometry.imperfections` (its module docstring gives the conventions).
"""

from __future__ import annotations

import csv
import math
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from runout.base.reading import InputFileError, read_bytes
from runout.geometry._harmonics import (
    TWO_PI,
    Harmonics,
    ImperfectionError,
    ProfileError,
    ProfileWarning,
    _two_orders,
)


# --------------------------------------------------------------------------------------------
# measured profiles
# --------------------------------------------------------------------------------------------
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
    if np.iscomplexobj(values):  # a cast would drop the imaginary part without a word
        raise ProfileError("", None, f"{name} must be real numbers, got complex values")
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
        # the shared reader: only a regular file (a FIFO found out without waiting for a
        # writer), a loop of links named, at most max_bytes + 1 bytes read
        raw = read_bytes(path, max_bytes, None, name)
    except InputFileError as exc:
        message = "is not a regular file" if "regular file" in exc.message else exc.message
        raise ProfileError(name, None, message) from None
    except OSError as exc:
        raise ProfileError(name, None, f"cannot read the file: {exc.strerror or exc}") from exc
    except UnicodeDecodeError as exc:
        raise ProfileError(
            name, None, f"is not UTF-8 text (byte {exc.start + 1} cannot be decoded)"
        ) from None
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
