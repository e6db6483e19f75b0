"""The dynamic model's sweep (seed 003 Figs. 3-4): one run per number of balls and axial
preload, ``runout sweep-dynamic``, each point saved as it is computed so that an interrupted
sweep resumes where it stopped.

A sweep is a study of the dynamic model (:mod:`runout.models.dynamic`): it lives with the
studies, whose output directory, lock and atomic writes it uses.
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from runout.analysis.result_details import DynamicDetails
from runout.analysis.results import RunResult
from runout.analysis.spectrum import amplitude_spectrum, extract_lines
from runout.base.errors import GeometryError, RunoutError
from runout.case.model import parse_case
from runout.models import dynamic
from runout.report import plotting
from runout.study.run import (
    OutputError,
    StudyError,
    _dumps,
    _remove_leftovers,
    error_text,
    output_directory,
    output_lock,
    refuse_foreign,
    write_atomic,
)

__all__ = ["SweepPoint", "exact_number", "point_name", "sweep"]


# --------------------------------------------------------------------------------------------
# sweeps (seed 003 Figs. 3-4)
# --------------------------------------------------------------------------------------------
def _variant(case: Any, elements: int | None, preload: float | None) -> Any:
    """The case with another number of balls and/or axial preload.

    Built from the keys the case gives (not their defaults too): a bearing given by its
    catalogue angle stays given by it, not by the angle and a clearance of 0.
    """
    data = case.spec.model_dump(mode="python", exclude_unset=True, exclude_none=True)
    if elements is not None:
        data["bearing"]["elements"] = int(elements)
    if preload is not None:
        data.setdefault("operation", {})["axial_load"] = float(preload)
    data.setdefault("analysis", {})["model"] = dynamic.MODEL
    base = Path(case.path).parent if case.path and not case.path.startswith("<") else None
    return parse_case(data, f"{case.path} (elements={elements}, preload={preload} N)", base)


def _case_digest(case: Any) -> str:
    text = json.dumps(case.spec.model_dump(mode="json"), sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


@dataclass(frozen=True)
class SweepPoint:
    """One point of a sweep: inputs and the figures of its steady state.

    Attributes
    ----------
    elements : int
        Number of balls Z [-].
    preload_n : float
        Axial preload [N].
    contact_angle_deg : float
        Contact angle of the run [deg].
    ball_passage_hz : float
        Ball passage frequency [Hz].
    natural_frequencies_hz : list of float
        Linearised natural frequencies at the static start, ascending [Hz].
    radial_pp_m : float
        Radial runout p-p along the measuring direction [m].
    ball_passage_pp_m : float
        p-p of the ball-passage line along the measuring direction [m]; 0 below the
        solver's resolution.
    mean_displacement_m : list of float
        Mean x and y of the rotor [m].
    spectrum_hz : list of float
        Frequencies of the amplitude spectrum along the measuring direction, up to 8 times
        the ball passage frequency [Hz].
    spectrum_pp_m : list of float
        Its p-p at each frequency [m].
    lines : list of dict
        The largest fitted lines in x and y (of the 12 largest), as
        :meth:`runout.analysis.lines.Component.to_json` writes them.
    """

    elements: int
    preload_n: float
    contact_angle_deg: float
    ball_passage_hz: float
    natural_frequencies_hz: list[float]
    radial_pp_m: float
    ball_passage_pp_m: float
    mean_displacement_m: list[float]
    spectrum_hz: list[float]
    spectrum_pp_m: list[float]
    lines: list[dict[str, Any]]

    def to_json(self) -> dict[str, Any]:
        """Plain JSON.

        Returns
        -------
        dict
            Field name -> value (the file of a point in ``points/``, less the case digest).
        """
        return dict(self.__dict__)


def _point(case: Any, result: RunResult) -> SweepPoint:
    u = result.measuring_direction
    radial = u[0] * result.displacement[0] + u[1] * result.displacement[1]
    fs = 1.0 / (result.time[1] - result.time[0])
    spec = amplitude_spectrum(radial, sample_rate=fs)
    details = result.details
    if not isinstance(details, DynamicDetails):
        raise TypeError(f"a sweep point needs a dynamic result, got the {result.model} model's")
    fbp = details.ball_passage_hz
    radial_bp = float(extract_lines(result.time, radial, [fbp]).amplitude[0]) * 2.0
    if radial_bp <= details.solver_resolution_m:
        radial_bp = 0.0
    keep = spec.frequencies <= 8.0 * fbp
    return SweepPoint(
        elements=case.bearing.elements,
        preload_n=case.operation.axial_load,
        contact_angle_deg=math.degrees(result.contact_angle),
        ball_passage_hz=fbp,
        natural_frequencies_hz=list(details.natural_frequencies_hz),
        radial_pp_m=float(result.runout.radial_pp_m or 0.0),  # the dynamic model has a record
        ball_passage_pp_m=radial_bp,
        mean_displacement_m=result.mean_displacement()[:2],
        spectrum_hz=[float(f) for f in spec.frequencies[keep]],
        spectrum_pp_m=[float(2.0 * a) for a in spec.amplitude[keep]],
        lines=[c.to_json() for c in result.lines(top=12) if c.direction in ("x", "y")],
    )


def exact_number(value: float) -> str:
    """Shortest text of ``value`` that reads back as exactly ``value``.

    ``f"{value:g}"`` when it round-trips (``10``, ``0.5``: the names of earlier versions stay
    valid), ``repr`` otherwise (``10.0000001``). Two different values therefore never share a
    text: a point name made of 6 significant digits let two close preloads share one result.

    Parameters
    ----------
    value : float
        The number (a preload [N] in a point name).

    Returns
    -------
    str
        Its text; ``-0.0`` is written as ``0``.
    """
    value = float(value) + 0.0  # -0.0 and 0.0 are one preload
    short = f"{value:g}"
    return short if float(short) == value else repr(value)


def point_name(elements: int, preload: float) -> str:
    """Name of a sweep point (and of its file in ``points/``): ``Z<z>_P<preload>N``, exact.

    Parameters
    ----------
    elements : int
        Number of balls Z [-].
    preload : float
        Axial preload [N], written by :func:`exact_number`.

    Returns
    -------
    str
        E.g. ``Z9_P10N``.
    """
    return f"Z{int(elements)}_P{exact_number(preload)}N"


_POINT_FIELDS = frozenset(SweepPoint.__dataclass_fields__)


def _saved_point(doc: Any, elements: int, preload: float, digest: str) -> SweepPoint | str:
    """The point stored in ``doc`` if it is this case's point (elements, preload); else why not.

    Checked field by field: a damaged or hand-edited file must be recomputed, not raise
    AttributeError / TypeError here or in the plots, and a file of another point (renamed,
    or named by an older version) must not stand in for this one.
    """
    if not isinstance(doc, dict):
        return f"a JSON {type(doc).__name__}, not an object"
    if doc.get("case_digest") != digest:
        return "written for another case"
    if set(doc) != _POINT_FIELDS | {"case_digest"}:
        return "fields missing or unknown"
    if doc["elements"] != elements or doc["preload_n"] != preload:
        return f"the point Z{doc['elements']!r} P{doc['preload_n']!r} N"

    def number(v: Any) -> bool:
        return isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)

    scalars = ("contact_angle_deg", "ball_passage_hz", "radial_pp_m", "ball_passage_pp_m")
    arrays = ("natural_frequencies_hz", "mean_displacement_m", "spectrum_hz", "spectrum_pp_m")
    if not all(number(doc[k]) for k in scalars) or not all(
        isinstance(doc[k], list) and all(number(v) for v in doc[k]) for k in arrays
    ):
        return "a figure is not a number"
    if len(doc["mean_displacement_m"]) != 2 or len(doc["spectrum_hz"]) != len(doc["spectrum_pp_m"]):
        return "arrays of the wrong length"
    if not isinstance(doc["lines"], list) or not all(isinstance(x, dict) for x in doc["lines"]):
        return "lines is not a list of objects"
    return SweepPoint(**{k: v for k, v in doc.items() if k != "case_digest"})


def sweep(
    case: Any,
    elements: Sequence[int] = (),
    preloads: Sequence[float] = (),
    out: Path | str | None = None,
    *,
    progress: Callable[[int, int, str], None] | None = None,
    force: bool = False,
    notify: Callable[[str], None] | None = None,
) -> list[SweepPoint]:
    """Run the dynamic model over numbers of balls × axial preloads (seed 003 Figs. 3–4).

    Every point is the case with ``[bearing] elements`` and ``[operation] axial_load``
    replaced. With ``out``, each finished point is written at once (atomically) to
    ``out/points/<point_name>.json`` (with a digest of the case), and a rerun reuses the
    points already there for the same case: an interrupted sweep loses nothing. A saved point
    that is damaged, of another case or of another point is recomputed, and said through
    ``notify``. The panels (``spectra_elements_P<p>N.png``, ``spectra_preload_Z<z>.png``),
    ``trend.png`` and ``sweep.csv`` are written at the end. ``out`` is locked for the whole
    sweep (:func:`runout.study.run.output_lock`) and must be new, empty or a sweep's output.

    Parameters
    ----------
    case : Case
    elements : sequence of int
        Numbers of balls; empty = the case's.
    preloads : sequence of float
        Axial preloads [N]; empty = the case's.
    out : Path, str or None
        Output directory (an empty string is refused, not taken as the current directory).
    progress : callable or None
        Called as ``progress(done, total, text)`` after each point.
    force : bool
        Write into a non-empty ``out`` that is not a sweep-dynamic output.
    notify : callable or None
        Called with one-line notes (points recomputed); default: a logged warning.

    Returns
    -------
    list of SweepPoint
        In the order elements-major.

    Raises
    ------
    runout.study.run.OutputError
        ``out`` empty, a file, unwritable, not a sweep's output, or locked by another writer.
    runout.study.run.StudyError
        A point failed with an exception that is not a runout error (the points finished
        before it are kept).
    """
    zs = list(elements) or [case.bearing.elements]
    ps = list(preloads) or [case.operation.axial_load]
    for p in ps:
        if not (math.isfinite(p) and p >= 0.0):
            raise GeometryError("preload", f"must be >= 0 N, got {p!r}")
    if out is None:
        return _sweep_points(case, zs, ps, None, progress, notify)

    directory = output_directory(out)
    refuse_foreign(directory, "sweep-dynamic", force)
    with output_lock(directory):
        return _sweep_points(case, zs, ps, directory, progress, notify)


def _sweep_points(
    case: Any,
    zs: list[int],
    ps: list[float],
    out: Path | None,
    progress: Callable[[int, int, str], None] | None,
    notify: Callable[[str], None] | None,
) -> list[SweepPoint]:
    """The points of :func:`sweep`; ``out`` is checked and locked by the caller."""
    digest = _case_digest(case)
    points: list[SweepPoint] = []
    total = len(zs) * len(ps)
    redone: list[str] = []
    if out is not None:
        _remove_leftovers(out)
        try:
            (out / "points").mkdir(exist_ok=True)
        except OSError as exc:
            raise OutputError(f"{out / 'points'}: cannot create ({exc.strerror or exc})") from None
    for z in zs:
        for p in ps:
            p = float(p) + 0.0
            name = point_name(z, p)
            path = out / "points" / f"{name}.json" if out is not None else None
            point = None
            if path is not None and path.exists():
                try:
                    found = _saved_point(json.loads(path.read_text()), z, p, digest)
                except (OSError, ValueError):
                    found = "unreadable"
                if isinstance(found, SweepPoint):
                    point = found
                else:
                    redone.append(f"{path.name}: {found}")
            if point is None:
                variant = _variant(case, z, p)
                try:
                    point = _point(variant, dynamic.run(variant))
                except RunoutError:
                    raise  # names the case and the point already
                except Exception as exc:
                    raise StudyError(
                        f"{variant.path}: {error_text(exc)} (the points finished before it "
                        "are kept)"
                    ) from None
                if path is not None:
                    text = _dumps({**point.to_json(), "case_digest": digest})
                    write_atomic(path, functools.partial(_write_str, text))
            points.append(point)
            if progress is not None:
                progress(len(points), total, name)
    if redone:
        n = len(redone)
        shown = "; ".join(redone[:3]) + ("; ..." if n > 3 else "")
        message = (
            f"{out / 'points' if out is not None else 'points'}: recomputed {n} point"
            f"{'s' if n > 1 else ''} that could not be reused ({shown})"
        )
        if notify is not None:
            notify(message)
        else:
            import logging

            logging.getLogger(__name__).warning(message)
    if out is not None:
        try:
            _write_sweep(points, zs, ps, out, case.title)
        except OSError as exc:  # a plot: the CSV names its own file
            raise OutputError(f"{out}: cannot write ({exc.strerror or exc})") from None
    return points


def _write_str(text: str, fh: Any) -> None:
    fh.write(text)


def _write_sweep(
    points: list[SweepPoint], zs: list[int], ps: list[float], out: Path, title: str
) -> list[Path]:

    rows = [
        "elements,preload_n,contact_angle_deg,ball_passage_hz,natural_frequency_1_hz,"
        "natural_frequency_2_hz,radial_pp_m,ball_passage_pp_m,mean_x_m,mean_y_m\n"
    ]
    for pt in points:
        fn = [*pt.natural_frequencies_hz, 0.0, 0.0]
        # the preload exactly: two close preloads are two rows, not one value twice
        rows.append(
            f"{pt.elements},{exact_number(pt.preload_n)},{pt.contact_angle_deg:.6g},"
            f"{pt.ball_passage_hz:.8g},{fn[0]:.8g},{fn[1]:.8g},{pt.radial_pp_m:.6g},"
            f"{pt.ball_passage_pp_m:.6g},{pt.mean_displacement_m[0]:.6g},"
            f"{pt.mean_displacement_m[1]:.6g}\n"
        )
    written = [write_atomic(out / "sweep.csv", lambda fh: fh.writelines(rows))]
    written += plotting.plot_dynamic_sweep(points, zs, ps, out, title)
    return written
