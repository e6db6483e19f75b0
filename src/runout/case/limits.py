"""Limits as policy: how much memory and time a case may ask for, checked before any work.

Every size a case file can set (orders, numbers of harmonics, samples, revolutions, time steps,
study samples, sweep points, file sizes) is bounded here, in one place. A bound is either
*fixed* (a case file or a quantity string longer than any a person types, an order beyond any
a contact can feel) or *derived*: the memory and the time a run would take are estimated from
the case before anything is allocated, and a case whose estimate exceeds the budget is refused
with one line that says the estimate and the key to change.

The budget
----------
``max_memory`` (default :data:`DEFAULT_MAX_MEMORY`, 2 GiB of the large arrays) and
``max_time`` (default :data:`DEFAULT_MAX_TIME`, 2 min of estimated computing) come, first
found first used, from

1. the case's own ``[analysis] max_memory = "8 GiB"`` and ``max_time = "1 h"``;
2. the environment variables ``RUNOUT_MAX_MEMORY`` and ``RUNOUT_MAX_TIME`` (same syntax);
3. the defaults.

A budget above the machine's physical memory is refused. The estimates are deliberately
simple (measured costs per instant, contact and harmonic on a 2-core x86-64 machine; see the
``COST_*`` constants) and meant to be right within a factor of a few: they separate a run of
minutes from one of days, not seconds from seconds.

Profiles (``[[profile]] file``) must be regular files no larger than :func:`max_profile_bytes`
and lie inside the case file's directory; ``RUNOUT_PROFILE_DIRS`` (directories separated by
``os.pathsep``) names further directories profiles may be read from. A measured record
(``runout diagnose --record``) may be no larger than :func:`max_record_bytes`.

The files runout reads back (a run or study directory, a record) have fixed bounds of their
own, below this layer so that every reader shares them: :mod:`runout.base.reading`
(``MAX_JSON_BYTES``, ``MAX_JSON_VALUES``, ``MAX_JSON_DEPTH``, ``MAX_JSON_INT_DIGITS``,
``MAX_FIGURE_BYTES``).
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from runout.base.errors import GeometryError

# the physical bounds live with the harmonics (the constructors in code check them too)
from runout.geometry._harmonics import MAX_ELEMENTS as MAX_ELEMENTS
from runout.geometry._harmonics import MAX_ORDER as MAX_ORDER

__all__ = [
    "DEFAULT_MAX_MEMORY",
    "DEFAULT_MAX_TIME",
    "ENV_MAX_MEMORY",
    "ENV_MAX_TIME",
    "ENV_PROFILE_DIRS",
    "MAX_CASE_FILE_BYTES",
    "MAX_ELEMENTS",
    "MAX_ENTRIES",
    "MAX_ORDER",
    "MAX_TOML_DEPTH",
    "Budget",
    "LimitError",
    "ResourceEstimate",
    "budget",
    "check",
    "format_bytes",
    "format_seconds",
    "harmonics_memory",
    "max_profile_bytes",
    "max_profile_points",
    "max_record_bytes",
    "profile_allowed",
]

KiB = 1024
MiB = 1024 * KiB
GiB = 1024 * MiB

#: Default budget of the large arrays of one run or study [bytes].
DEFAULT_MAX_MEMORY = 2 * GiB
#: Default budget of estimated computing time of one run or study [s].
DEFAULT_MAX_TIME = 120.0
ENV_MAX_MEMORY = "RUNOUT_MAX_MEMORY"
ENV_MAX_TIME = "RUNOUT_MAX_TIME"
ENV_PROFILE_DIRS = "RUNOUT_PROFILE_DIRS"

#: Largest case file read [bytes]: a case is text a person writes; 4 MiB holds ~100 000 lines.
MAX_CASE_FILE_BYTES = 4 * MiB
#: Deepest nesting of TOML tables and arrays in a case file (the schema needs 4).
MAX_TOML_DEPTH = 32
#: Largest number of histogram bins of a Monte Carlo summary.
MAX_BINS = 10_000
#: Most entries of an array table ([[waviness]], [[waviness_spectrum]], [[profile]]).
MAX_ENTRIES = 1000

# --- measured costs (2-core x86-64, numba kernels compiled) ---------------------------------
#: Seconds per instant × contact × harmonic of the quasi-static solves (deviations + Newton).
COST_QUASI_STATIC = 6e-9
#: Seconds per instant × spectral line of the line fit and the RRO/NRRO split.
COST_LINE_FIT = 2e-8
#: Seconds per instant × spectral line of the linear model's synthesis.
COST_LINEAR = 2e-9
#: Seconds per instant × element × harmonic of the rigid roller constraint (vertex search).
COST_ROLLER = 3e-7
#: Seconds per Newmark step and element of the dynamic model (contact forces, Newton).
COST_DYNAMIC_ELEMENT = 1e-7
#: Seconds per Newmark step × contact × harmonic of the dynamic model (the deviations).
COST_DYNAMIC_HARMONIC = 1.5e-8
#: Seconds of fixed cost of one run (set-up, result assembly).
COST_RUN = 5e-3
#: Bytes per instant of a quasi-static run at its peak: the record (time, the (3, n)
#: displacement: 32 B, the unloaded-ball counts: 2 B; the deviations are evaluated in the
#: kernel, without (n, Z) arrays) and the decomposition's arrays (the residual, the window and
#: the spectrum of one direction, ~56 B). Measured: 90 B by tracemalloc, 97 B of RSS growth
#: at 2^22 instants (Fig. 7 case of seed 000); doubled.
BYTES_QUASI_STATIC = 192.0
#: Bytes per instant and fitted line of the line fit (3 directions x 16 B per block of 256
#: instants: 0.19 B measured), doubled.
BYTES_LINE_INSTANT = 0.5
#: Largest angle the quasi-static models evaluate, 2π x revolutions x the highest order x the
#: balls' spin ratio d_m / (2 D) (a ball's harmonics turn with its spin) [rad]:
#: a double holds an angle of 1e9 rad to 1e-7 rad, so beyond it the phases of the record, not
#: the bearing, set the smallest lines (a perfect bearing over 1e9 revolutions shows 1e-13 m
#: of round-off runout).
MAX_PHASE_ANGLE = 1e9
#: Bytes per stored harmonic (orders, amplitudes, phases and the temporaries of normalising,
#: packing and per-element copies).
BYTES_PER_HARMONIC = 160
#: Bytes per profile byte while a profile file is read (lines, floats, arrays).
BYTES_PER_PROFILE_BYTE = 24
#: Memory of a diagnosis per byte of its record CSV: the parsed columns, the displacement and
#: residual arrays of the fit and their temporaries (measured: 226 MiB of peak memory for a
#: 39 MB file of 10^6 rows of x and y).
RECORD_BYTES_PER_FILE_BYTE = 6.0


class LimitError(GeometryError):
    """A case that would need more memory or time than the budget, or a size beyond a bound.

    Parameters
    ----------
    key : str
        The case key to change (``"analysis.samples"``).
    message : str
        The estimate and what to change, ending with how to raise the budget when it applies.
    """


@dataclass(frozen=True)
class Budget:
    """Memory [B] and time [s] one run (or one study) may use, and where they came from.

    Attributes
    ----------
    memory : float
        Memory budget of the large arrays [B].
    time : float
        Budget of estimated computing time [s].
    memory_from, time_from : str
        Where each came from: ``"default"``, ``"analysis.max_memory"`` /
        ``"analysis.max_time"`` (the case) or the environment variable's name.
    """

    memory: float = float(DEFAULT_MAX_MEMORY)
    time: float = DEFAULT_MAX_TIME
    memory_from: str = "default"
    time_from: str = "default"

    def raise_hint(self, what: str) -> str:
        """How to raise the budget of ``what`` ("memory" or "time").

        Parameters
        ----------
        what : {"memory", "time"}
            The budget exceeded.

        Returns
        -------
        str
            The end of a refusal's message: the limit [B or s], where it came from, and the case key
            and environment variable that raise it.
        """
        if what == "memory":
            return (
                f"or raise the limit ({format_bytes(self.memory)}, {self.memory_from}) with "
                f'[analysis] max_memory = "8 GiB" or {ENV_MAX_MEMORY}'
            )
        return (
            f"or raise the limit ({format_seconds(self.time)}, {self.time_from}) with "
            f'[analysis] max_time = "1 h" or {ENV_MAX_TIME}'
        )


@dataclass(frozen=True)
class ResourceEstimate:
    """What one run or study is expected to need.

    Attributes
    ----------
    memory : float
        Peak size of the large arrays [B].
    seconds : float
        Computing time [s].
    memory_key, time_key : str
        Case key that sizes each the most (the one to change).
    memory_what, time_what : str
        The sizes behind each figure, in words ("16384 instants x 7 balls").
    """

    memory: float
    seconds: float
    memory_key: str
    time_key: str
    memory_what: str
    time_what: str


def physical_memory() -> float | None:
    """Installed memory of this machine [B], None when the system does not say.

    Returns
    -------
    float or None
        Page size times physical pages [B].
    """
    try:
        return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, OSError, ValueError):
        return None


def _from_env(name: str, kind: str, environ: Mapping[str, str]) -> float | None:
    from runout.base.units import UnitError, to_si

    text = environ.get(name)
    if text is None or not text.strip():
        return None
    try:
        value = to_si(text.strip(), kind)
    except UnitError as exc:
        raise LimitError(name, f"environment variable: {exc}") from None
    if not value > 0.0:
        raise LimitError(name, f"environment variable: must be > 0, got {text!r}")
    return value


def budget(
    max_memory: float | None = None,
    max_time: float | None = None,
    environ: Mapping[str, str] | None = None,
) -> Budget:
    """The budget of one run: the case's own keys, else the environment, else the defaults.

    Parameters
    ----------
    max_memory : float or None
        ``[analysis] max_memory`` [B].
    max_time : float or None
        ``[analysis] max_time`` [s].
    environ : mapping, optional
        Environment (default ``os.environ``).

    Returns
    -------
    Budget
        Memory [B] and time [s], each with where it came from.

    Raises
    ------
    LimitError
        An environment variable that is not a positive amount, or a memory budget above the
        machine's physical memory.
    """
    env = os.environ if environ is None else environ
    memory, memory_from = float(DEFAULT_MAX_MEMORY), "default"
    seconds, time_from = DEFAULT_MAX_TIME, "default"
    env_memory = _from_env(ENV_MAX_MEMORY, "memory", env)
    env_time = _from_env(ENV_MAX_TIME, "time", env)
    if max_memory is not None:
        memory, memory_from = max_memory, "analysis.max_memory"
    elif env_memory is not None:
        memory, memory_from = env_memory, ENV_MAX_MEMORY
    if max_time is not None:
        seconds, time_from = max_time, "analysis.max_time"
    elif env_time is not None:
        seconds, time_from = env_time, ENV_MAX_TIME
    installed = physical_memory()
    if installed is not None and memory > installed:
        key = "analysis.max_memory" if memory_from == "analysis.max_memory" else memory_from
        raise LimitError(
            key,
            f"{format_bytes(memory)} is more than this machine's memory "
            f"({format_bytes(installed)})",
        )
    return Budget(memory, seconds, memory_from, time_from)


def case_budget(case_or_spec: Any) -> Budget:
    """:func:`budget` of a case (or its validated spec) from its ``[analysis]`` keys.

    Parameters
    ----------
    case_or_spec : Case or CaseSpec
        A case, or its validated case-file tables (``[analysis] max_memory`` [B] and
        ``max_time`` [s]).

    Returns
    -------
    Budget
    """
    spec = getattr(case_or_spec, "spec", case_or_spec)
    analysis = getattr(spec, "analysis", None)
    return budget(
        getattr(analysis, "max_memory", None),
        getattr(analysis, "max_time", None),
    )


def check(estimate: ResourceEstimate, limits: Budget) -> None:
    """Refuse an estimate beyond the budget, naming the key to change.

    Parameters
    ----------
    estimate : ResourceEstimate
        Memory [B] and time [s] a run or study is expected to need.
    limits : Budget
        The budget [B, s].

    Raises
    ------
    LimitError
        Memory first (it fails hard), then time.
    """
    if not estimate.memory <= limits.memory:
        raise LimitError(
            estimate.memory_key,
            f"would need about {format_bytes(estimate.memory)} of memory "
            f"({estimate.memory_what}); lower {estimate.memory_key} "
            f"{limits.raise_hint('memory')}",
        )
    if not estimate.seconds <= limits.time:
        raise LimitError(
            estimate.time_key,
            f"would take about {format_seconds(estimate.seconds)} ({estimate.time_what}); "
            f"lower {estimate.time_key} {limits.raise_hint('time')}",
        )


def format_bytes(n: float) -> str:
    """``1.5 GiB``-style size of ``n`` bytes.

    Parameters
    ----------
    n : float
        A size [B] (inf: "an unbounded amount").

    Returns
    -------
    str
        Three significant digits in the largest binary unit not above it (B, KiB, ... EiB).
    """
    if not math.isfinite(n):
        return "an unbounded amount"
    for unit, size in (("EiB", 1024.0**6), ("PiB", 1024.0**5), ("TiB", 1024.0**4)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    for unit, size in (("GiB", GiB), ("MiB", MiB), ("KiB", KiB)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.0f} B"


def format_seconds(s: float) -> str:
    """``2.5 h``-style duration of ``s`` seconds.

    Parameters
    ----------
    s : float
        A duration [s] (inf: "forever").

    Returns
    -------
    str
        Three significant digits in the largest unit not above it (s, min, h, days, years).
    """
    if not math.isfinite(s):
        return "forever"
    year = 365.25 * 86400.0
    for unit, size in (("years", year), ("days", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if s >= size:
            return f"{s / size:.3g} {unit}"
    return f"{s:.3g} s"


# --------------------------------------------------------------------------------------------
# fixed bounds and file sizes
# --------------------------------------------------------------------------------------------
def harmonics_memory(count: float) -> float:
    """Memory of ``count`` harmonics while they are built and packed [B].

    Parameters
    ----------
    count : float
        Number of harmonics [-].

    Returns
    -------
    float
        ``count`` times :data:`BYTES_PER_HARMONIC` [B].
    """
    return float(count) * BYTES_PER_HARMONIC


def max_profile_bytes(limits: Budget) -> int:
    """Largest profile file read within the memory budget [B].

    Parameters
    ----------
    limits : Budget
        The budget; its memory [B] is divided by :data:`BYTES_PER_PROFILE_BYTE`.

    Returns
    -------
    int
        Largest profile file size [B].
    """
    return int(limits.memory // BYTES_PER_PROFILE_BYTE)


#: Bytes of a CSV row of a profile (``"359.75,0.0123\\n"`` and longer): a profile given as
#: arrays is held to the points of the largest profile file, since saving the case writes it as
#: one.
PROFILE_ROW_BYTES = 16


def max_profile_points(limits: Budget) -> int:
    """Most points of a profile given as arrays (Python API) within the memory budget.

    Parameters
    ----------
    limits : Budget
        The budget; :func:`max_profile_bytes` divided by :data:`PROFILE_ROW_BYTES`.

    Returns
    -------
    int
        Largest number of angles (and of deviations) [-].
    """
    return max_profile_bytes(limits) // PROFILE_ROW_BYTES


def max_record_bytes(limits: Budget) -> int:
    """Largest measured-record CSV ``runout diagnose`` reads within the memory budget [B].

    Parameters
    ----------
    limits : Budget
        The budget; its memory [B] is divided by :data:`RECORD_BYTES_PER_FILE_BYTE`.

    Returns
    -------
    int
        Largest record file size [B].
    """
    return int(limits.memory // RECORD_BYTES_PER_FILE_BYTE)


def profile_roots(base_dir: Path, environ: Mapping[str, str] | None = None) -> list[Path]:
    """Directories a case's profiles may come from: the case's own and ``RUNOUT_PROFILE_DIRS``.

    Parameters
    ----------
    base_dir : Path
        The case file's directory.
    environ : mapping, optional
        Environment (default ``os.environ``), read for :data:`ENV_PROFILE_DIRS`.

    Returns
    -------
    list of Path
        ``base_dir`` and each directory of the variable, resolved (``~`` expanded).
    """
    env = os.environ if environ is None else environ
    roots = [base_dir.resolve()]
    for part in env.get(ENV_PROFILE_DIRS, "").split(os.pathsep):
        if part.strip():
            try:
                roots.append(Path(part.strip()).expanduser().resolve())
            except (OSError, RuntimeError):  # a loop of links names no directory
                continue
    return roots


def profile_allowed(path: Path, base_dir: Path, environ: Mapping[str, str] | None = None) -> bool:
    """True when ``path`` (resolved, symbolic links followed) lies under an allowed directory.

    Parameters
    ----------
    path : Path
        A profile file named by a case.
    base_dir : Path
        The case file's directory.
    environ : mapping, optional
        Environment (default ``os.environ``), read for :data:`ENV_PROFILE_DIRS`.

    Returns
    -------
    bool
    """
    try:
        resolved = path.resolve()
    except (OSError, RuntimeError):  # a loop of links (RuntimeError up to Python 3.12)
        return False
    return any(resolved.is_relative_to(root) for root in profile_roots(base_dir, environ))


def __getattr__(name: str) -> object:
    """``Estimate`` (renamed :class:`ResourceEstimate`: one name, one class; a diagnosis'
    :class:`runout.diagnose.Estimate` is a part deviation), for one release."""
    if name == "Estimate":
        import warnings

        warnings.warn(
            "runout.case.limits.Estimate is deprecated: it is ResourceEstimate",
            DeprecationWarning,
            stacklevel=2,
        )
        return ResourceEstimate
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
