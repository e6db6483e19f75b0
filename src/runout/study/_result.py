"""A study's results: statistics, yield and the column-wise :class:`StudyResult`.

Part of :mod:`runout.study.run` (its module docstring describes studies).
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TextIO

import numpy as np
from numpy.typing import NDArray

from runout.io.study_columns import COLUMNS_FILE, element_column, identifier, line_column
from runout.io.study_columns import FORMAT as COLUMNS_FORMAT
from runout.study._chunks import ERRORS_SHOWN
from runout.study._files import write_atomic
from runout.study._plan import RUNOUT_KEYS, Quantity, StudyError
from runout.study._stream import QUANTILE_RELATIVE_ERROR, StreamStatistics


# --------------------------------------------------------------------------------------------
# statistics
# --------------------------------------------------------------------------------------------
def statistics(values: ArrayLikeF, bins: int = 20) -> dict[str, Any]:
    """Mean, std (ddof 1), 2σ, 5/50/95 % percentiles, min, max and histogram of ``values``.

    Non-finite entries (failed samples) are left out.
    """
    v = np.asarray(values, dtype=np.float64)
    v = v[np.isfinite(v)]
    if v.size == 0:
        nan = float("nan")
        return {
            "mean": nan,
            "std": nan,
            "two_sigma": nan,
            "p5": nan,
            "p50": nan,
            "p95": nan,
            "min": nan,
            "max": nan,
            "histogram": {"edges": [], "counts": []},
        }
    std = float(np.std(v, ddof=1)) if v.size > 1 else 0.0
    p5, p50, p95 = (float(x) for x in np.percentile(v, [5.0, 50.0, 95.0]))
    # values equal to round-off (a line no swept quantity changes, e.g. a spindle's in-phase
    # translation) cannot be cut into finite-size bins: one bin holds them
    spread = float(v.max() - v.min())
    scale = float(np.abs(v).max())
    equal = 0.0 < spread <= 1e-10 * scale
    if spread == 0.0:
        # all equal: numpy's own ±0.5 around them, widened where 0.5 is below the values'
        # resolution (above ~1e14 it cannot make finite bins; a tampered chunk can hold that)
        half = max(0.5, 1e-10 * scale)
        counts, edges = np.histogram(v, bins=bins, range=(v[0] - half, v[0] + half))
    else:
        counts, edges = np.histogram(v, bins=1 if equal else bins)
    return {
        "mean": float(np.mean(v)),
        "std": std,
        "two_sigma": 2.0 * std,
        "p5": p5,
        "p50": p50,
        "p95": p95,
        "min": float(v.min()),
        "max": float(v.max()),
        "histogram": {"edges": [float(e) for e in edges], "counts": [int(c) for c in counts]},
    }


ArrayLikeF = Sequence[float] | NDArray[np.float64]
_CONTRACT = ("mean", "std", "p5", "p50", "p95")
#: Stiffness columns of stiffness.csv and :meth:`StudyResult.to_dataframe` [N/m].
_STIFFNESS_COLUMNS = ("kxx_n_per_m", "kxy_n_per_m", "kyx_n_per_m", "kyy_n_per_m", "kzz_n_per_m")
#: Damping columns of stiffness.csv and :meth:`StudyResult.to_dataframe` [N s/m], when a
#: point has damping (``[analysis] bearing_damping``): the run JSON's ``bearing_damping``.
_DAMPING_COLUMNS = (
    "cxx_n_s_per_m",
    "cxy_n_s_per_m",
    "cyx_n_s_per_m",
    "cyy_n_s_per_m",
    "czz_n_s_per_m",
)
#: Runout columns of :meth:`StudyResult.to_dataframe`, in this order.
_FRAME_RUNOUT = ("radial_pp_m", "rro_pp_m", "nrro_pp_m", "axial_pp_m")
#: Rows of samples.csv turned into text at a time (the file is written block by block).
CSV_BLOCK = 8192
#: Confidence of the interval of a lot's yield [-].
YIELD_CONFIDENCE = 0.95


# --------------------------------------------------------------------------------------------
# result
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class StudyResult:
    """All samples (or points) of a study, column-wise.

    Attributes
    ----------
    kind : {"montecarlo", "sweep"}
    title : str
    seed : int
    quantities : tuple of Quantity
    model : list of str, length N
        Model of each sample.
    values : dict
        Quantity key -> the N values: a Monte Carlo's as a float64 array, shape (N,) or
        (N, size) for a per-element key [SI]; a sweep's as a list (SI floats, or the literal
        strings of a text key).
    runout : dict
        RUNOUT_KEYS -> ndarray (N,) [m]; NaN for failed samples.
    lines : dict
        ``"direction|label"`` -> (frequency [Hz], ndarray (N,) of p-p [m]).
    errors : dict
        Sample index -> message, for samples whose model failed.
    bins : int
        Histogram bins.
    limit : (str, float) or None
        ``[analysis] limit_on`` and ``limit`` [m] when the case gives a spec limit: the
        Monte Carlo JSON gets ``yield``, a sweep's points get ``pass``.
    stiffness : dict
        Sample index -> ``{"radial_stiffness": {...}, "axial_stiffness_n_per_m": K_aa}`` for
        every equilibrium sample that ran (the run JSON's ``radial_stiffness`` [N/m, rpm] and
        the axial diagonal of its ``stiffness_matrix`` [N/m]); written as ``stiffness.csv``.
    limit_class : dict or None
        ``{"class", "bore_m", "source"}`` when the limit is an ISO 492 tolerance class's K_ia
        (the ``yield`` object carries them).
    bearing_source : dict or list or None
        Where the base case's bearing comes from when it names a ``designation``: the run
        JSON's ``bearing_source`` object (a spindle: a list, one per catalogue bearing).
    """

    kind: str
    title: str
    seed: int
    quantities: tuple[Quantity, ...]
    model: list[str]
    values: dict[str, list[Any]]
    runout: dict[str, NDArray[np.float64]]
    lines: dict[str, tuple[float, NDArray[np.float64]]]
    errors: dict[int, str]
    bins: int = 20
    limit: tuple[str, float] | None = None
    stiffness: dict[int, dict[str, Any]] = field(default_factory=dict)
    limit_class: dict[str, Any] | None = None
    bearing_source: Any = None

    @property
    def samples(self) -> int:
        """Number of samples (or sweep points × models)."""
        return len(self.model)

    @property
    def failed(self) -> int:
        """Number of samples whose model failed."""
        return len(self.errors)

    def line_table(self) -> list[tuple[str, float, str, NDArray[np.float64]]]:
        """(direction, frequency [Hz], label, p-p per sample [m]), largest mean first."""
        rows = [
            (key.split("|", 1)[0], f, key.split("|", 1)[1], pp)
            for key, (f, pp) in self.lines.items()
        ]
        ok = np.isfinite(self.runout["radial_pp_m"])
        rows.sort(key=lambda r: (-float(np.mean(r[3][ok])) if ok.any() else 0.0, r[0], r[1]))
        return rows

    def summary(self) -> dict[str, Any]:
        """Full statistics (JSON-ready): runout and lines with histograms (Monte Carlo)."""
        ok = np.isfinite(self.runout["radial_pp_m"])
        runout = {k: statistics(self.runout[k], self.bins) for k in RUNOUT_KEYS}
        comps = [
            {
                "direction": d,
                "frequency_hz": f,
                "label": label,
                "pp_m": statistics(pp[ok], self.bins),
            }
            for d, f, label, pp in self.line_table()
        ]
        return self._summary_document(sorted(set(self.model)), runout, comps)

    def _summary_document(
        self, models: list[str], runout: dict[str, Any], comps: list[dict[str, Any]]
    ) -> dict[str, Any]:
        """The summary's keys around its statistics (both kinds of result)."""
        return {
            "title": self.title,
            "kind": self.kind,
            "seed": self.seed,
            "models": models,
            "samples": self.samples,
            "failed": self.failed,
            "errors": self.error_list(),
            "quantities": [q.key for q in self.quantities],
            "runout": runout,
            "components": comps,
            **self._grade_keys(),
            **self._source_keys(),
        }

    def _source_keys(self) -> dict[str, Any]:
        """``bearing_source`` (a catalogue bearing's provenance; a spindle's list:
        ``bearing_sources``), as in the run JSON."""
        if self.bearing_source is None:
            return {}
        if isinstance(self.bearing_source, list):
            return {"bearing_sources": self.bearing_source}
        return {"bearing_source": self.bearing_source}

    def _grade_keys(self) -> dict[str, Any]:
        """``ball_grades`` (the grade and sigma of each ball-size draw of a graded bearing)
        and ``notes`` (an explicit sigma winning over a grade), when the study has them."""
        grades = [dict(q.grade) for q in self.quantities if q.grade is not None]
        if not grades:
            return {}
        notes = [g["note"] for g in grades if "note" in g]
        return {"ball_grades": grades, **({"notes": notes} if notes else {})}

    def error_list(self, limit: int = ERRORS_SHOWN) -> list[dict[str, Any]]:
        """The first ``limit`` failed samples as ``{"sample": i, "error": "Type: message"}``.

        Bounded: a study where every one of 10^5 samples fails must not write 10^5 messages
        into summary.json; ``failed`` gives the count, ``points`` (sweeps) every error.
        """
        return [{"sample": i, "error": self.errors[i]} for i in sorted(self.errors)[:limit]]

    def to_json(self) -> dict[str, Any]:
        """The ``runout study --json`` object (the documented JSON contract, docs/studies.md).

        Monte Carlo: ``samples``, ``failed``, ``errors`` (the first ERRORS_SHOWN failed samples
        with their error), ``runout`` and ``components`` with each p-p as {mean, std, p5, p50,
        p95}. Sweep: the same statistics over the points, plus ``points`` (values, model,
        runout and components of each point).
        """
        full = self.summary()

        def trim(stats: dict[str, Any]) -> dict[str, float | None]:
            return {k: _finite(stats[k]) for k in _CONTRACT}

        out: dict[str, Any] = {
            "title": self.title,
            "kind": self.kind,
            "models": full["models"],
            "seed": self.seed,
            "samples": self.samples,
            "failed": self.failed,
            "errors": full["errors"],
            "runout": {k: trim(v) for k, v in full["runout"].items()},
            "components": [
                {
                    **{k: c[k] for k in ("direction", "frequency_hz", "label")},
                    "pp_m": trim(c["pp_m"]),
                }
                for c in full["components"]
            ],
        }
        if self.kind == "sweep":
            out["points"] = self.points()
        elif self.limit is not None:
            out["yield"] = self.lot_yield()
        return out | self._grade_keys() | self._source_keys() | self._streaming_keys()

    def _streaming_keys(self) -> dict[str, Any]:
        """Keys a streaming study adds to its JSON (none here: exact statistics)."""
        return {}

    def lot_yield(self, confidence: float = YIELD_CONFIDENCE) -> dict[str, Any]:
        """The ``yield`` JSON object: fraction of the lot within the limit, with its interval.

        Over the samples whose model succeeded (failed samples are neither passes nor
        failures). A sample passes when its figure is at most the limit. The interval is the
        exact binomial (Clopper-Pearson) one: ``ci_low`` = B(α/2; k, n-k+1) and ``ci_high`` =
        B(1-α/2; k+1, n-k) with B the beta quantile, α = 1 - ``confidence``; 0 when no sample
        passed and 1 when all did. ``fraction`` and the interval are null with no sample.
        """
        if self.limit is None:
            raise ValueError("the study has no spec limit")
        quantity, limit = self.limit
        n, k = self._passed(quantity, limit)
        low: float | None = None
        high: float | None = None
        if n:
            from scipy.stats import beta

            alpha = 1.0 - confidence
            low = 0.0 if k == 0 else float(beta.ppf(alpha / 2.0, k, n - k + 1))
            high = 1.0 if k == n else float(beta.ppf(1.0 - alpha / 2.0, k + 1, n - k))
        return {
            "quantity": quantity,
            "limit_m": limit,
            **(self.limit_class or {}),
            "passed": k,
            "samples": n,
            "fraction": k / n if n else None,
            "ci_low": low,
            "ci_high": high,
            "confidence": confidence,
            "method": "Clopper-Pearson",
        }

    def _passed(self, quantity: str, limit: float) -> tuple[int, int]:
        """Samples with the figure ``quantity`` and, of them, those within ``limit``."""
        values = self.runout[f"{quantity}_m"]
        ok = values[np.isfinite(values)]
        return int(ok.size), int(np.sum(ok <= limit))

    def points(self) -> list[dict[str, Any]]:
        """Per-sample records: values, model, runout and non-zero lines."""
        rows = []
        table = self.line_table()
        for i in range(self.samples):
            rows.append(
                {
                    "sample": i,
                    "model": self.model[i],
                    "values": {k: v[i] for k, v in self.values.items()},
                    "runout": {k: _finite(float(self.runout[k][i])) for k in RUNOUT_KEYS},
                    "components": [
                        {"direction": d, "frequency_hz": f, "label": label, "pp_m": float(pp[i])}
                        for d, f, label, pp in table
                        if pp[i] > 0.0
                    ],
                    "error": self.errors.get(i),
                }
            )
            if i in self.stiffness:
                rows[-1]["radial_stiffness"] = dict(self.stiffness[i]["radial_stiffness"])
                rows[-1]["axial_stiffness_n_per_m"] = self.stiffness[i]["axial_stiffness_n_per_m"]
                if "bearing_damping" in self.stiffness[i]:
                    rows[-1]["bearing_damping"] = dict(self.stiffness[i]["bearing_damping"])
            if self.limit is not None:
                value = float(self.runout[f"{self.limit[0]}_m"][i])
                rows[-1]["pass"] = bool(value <= self.limit[1]) if math.isfinite(value) else None
        return rows

    # ------------------------------------------------------------ data
    def to_dataframe(self) -> Any:
        """One row per sample (Monte Carlo) or point (sweep) as a :class:`pandas.DataFrame`.

        Columns: ``sample`` (index), ``model``, one column per varied quantity named by its
        ``[study.vary]`` key (the case key, e.g. ``operation.speed``; SI values, a list per
        row for a per-element key), the runout figures ``radial_pp_m``, ``rro_pp_m``,
        ``nrro_pp_m``, ``axial_pp_m`` [m] (NaN for a failed sample), one p-p column [m] per
        line (``"<direction>_<label>_pp_m"`` as a plain identifier, e.g.
        ``x_ball_size_error_f_c_pp_m``, as in ``samples.csv``; 0 where the line is below the
        model's reporting floor; :meth:`column_descriptions` gives each one's frequency and
        label), ``pass`` when the case gives a spec limit,
        for a study of the equilibrium model ``kxx_n_per_m``, ``kxy_n_per_m``,
        ``kyx_n_per_m``, ``kyy_n_per_m`` and ``kzz_n_per_m`` [N/m] (as in ``stiffness.csv``;
        NaN for a point of another model or a failed one), with damping asked
        (``[analysis] bearing_damping``) ``cxx_n_s_per_m`` ... ``czz_n_s_per_m`` [N s/m] too,
        and ``error`` (the failure's
        ``"Type: message"``, empty when the sample ran).
        ``df.attrs`` holds ``units``, ``kind``, ``title`` and ``seed``.

        Returns
        -------
        pandas.DataFrame

        Raises
        ------
        ImportError
            pandas is not installed (``pip install "runout[data]"``).
        """
        from runout.analysis.results import _optional

        pd = _optional("pandas")
        n = self.samples
        data: dict[str, Any] = {"sample": np.arange(n), "model": list(self.model)}
        units: dict[str, str] = {"sample": "-", "model": "-"}
        for q in self.quantities:
            values = self.values[q.key]
            if isinstance(values, np.ndarray):  # a Monte Carlo's drawn column
                data[q.key] = values.tolist() if q.size > 1 else values
            else:
                data[q.key] = [list(v) for v in values] if q.size > 1 else list(values)
            units[q.key] = _si_unit(q)
        for k in _FRAME_RUNOUT:
            data[k] = np.asarray(self.runout[k], dtype=np.float64)
            units[k] = "m"
        names = self.line_columns()
        for d, _f, label, pp in self.line_table():
            name = names[f"{d}|{label}"]  # as in samples.csv
            data[name] = np.asarray(pp, dtype=np.float64)
            units[name] = "m"
        if self.limit is not None:
            figure = np.asarray(self.runout[f"{self.limit[0]}_m"], dtype=np.float64)
            data["pass"] = [bool(v <= self.limit[1]) if math.isfinite(v) else None for v in figure]
            units["pass"] = "-"
        if self.stiffness:  # equilibrium points: the columns of stiffness.csv, NaN elsewhere
            table = dict(self.stiffness_columns())
            for name in _STIFFNESS_COLUMNS:
                values = table[name]
                column = np.full(n, np.nan)
                column[sorted(self.stiffness)] = values
                data[name] = column
                units[name] = "N/m"
            for name in _DAMPING_COLUMNS if self.damped else ():
                column = np.full(n, np.nan)
                column[sorted(self.stiffness)] = table[name]
                data[name] = column
                units[name] = "N s/m"
        data["error"] = [self.errors.get(i, "") for i in range(n)]
        units["error"] = "-"
        df = pd.DataFrame(data)
        df.attrs.update({"units": units, "kind": self.kind, "title": self.title, "seed": self.seed})
        if self.limit is not None:
            df.attrs["limit"] = {"quantity": self.limit[0], "limit_m": self.limit[1]}
        return df

    def plot(self, kind: str | None = None, quantity: str | None = None, top: int = 4) -> Any:
        """One figure of the study (matplotlib, through :mod:`runout.report.plotting`).

        Parameters
        ----------
        kind : {"histograms", "sweep"}, optional
            ``"histograms"`` (Monte Carlo) or ``"sweep"``; by default the study's own kind.
        quantity : str, optional
            Sweep: the swept key on the horizontal axis (needed when several are swept).
        top : int
            Number of lines drawn.

        Returns
        -------
        matplotlib.figure.Figure
        """
        from runout.report.plotting import plot_study_kind

        if kind is None:
            kind = "histograms" if self.kind == "montecarlo" else "sweep"
        return plot_study_kind(self, kind, quantity=quantity, top=top)

    # ------------------------------------------------------------ files
    def write(self, directory: Path, plots: bool = True) -> list[Path]:
        """Write ``summary.json``, ``samples.csv``, ``samples_columns.json`` and plots into
        ``directory``.

        ``samples.csv`` has one row per sample, no units row, and plain identifiers as column
        names (:meth:`columns`); ``samples_columns.json`` gives every column's SI unit and
        what it is (:meth:`column_descriptions`).
        """
        directory.mkdir(parents=True, exist_ok=True)
        written = [self._write_summary(directory)]
        written.append(self._write_csv(directory / "samples.csv"))
        written.append(self._write_columns(directory / COLUMNS_FILE))
        if self.stiffness:
            written.append(self._write_stiffness(directory / "stiffness.csv"))
        if plots:
            from runout.report.plotting import plot_study

            if self.limit is None:
                written += plot_study(self, directory)
            else:
                # the spec limit as a line on the histogram of its quantity
                written += plot_study(
                    self, directory, limit_quantity=f"{self.limit[0]}_m", limit_m=self.limit[1]
                )
        return written

    def _write_summary(self, directory: Path, summary: dict[str, Any] | None = None) -> Path:
        """``summary.json`` of ``summary`` (default :meth:`summary`, NaN written as null)."""
        if summary is None:
            summary = _nan_to_none(self.summary())  # every sample failed: no statistics
        if self.limit is not None and self.kind == "montecarlo":
            summary = {**summary, "yield": self.lot_yield()}
        return _write_text(directory / "summary.json", _dumps(summary, indent=2))

    def columns(self) -> list[tuple[str, NDArray[Any]]]:
        """Flat table of ``samples.csv``: (column name, values per sample).

        Every name is a plain identifier (:mod:`runout.io.study_columns`); the units and what
        each column is are in :meth:`column_descriptions`.
        """
        return [(name, values) for name, values, _, _ in self._column_table()]

    def column_descriptions(self) -> dict[str, Any]:
        """The ``samples_columns.json`` document: the unit and meaning of every column.

        Returns
        -------
        dict
            ``format``; ``units``: column -> SI unit (``"-"`` for a count, text or index),
            every column of ``samples.csv`` in its order; ``columns``: column -> ``{"key"}``
            (a varied case key, ``"element"`` too for one element of a per-element draw) or
            ``{"direction", "frequency_hz", "label"}`` (a line).
        """
        table = self._column_table()
        return {
            "format": COLUMNS_FORMAT,
            "units": {name: unit for name, _, unit, _ in table},
            "columns": {name: info for name, _, _, info in table if info},
        }

    def _column_table(self) -> list[tuple[str, NDArray[Any], str, dict[str, Any]]]:
        """(name, values, unit, description) of every column of ``samples.csv``."""
        cols: list[tuple[str, NDArray[Any], str, dict[str, Any]]] = [
            ("sample", np.arange(self.samples), "-", {}),
            ("model", np.array(self.model, dtype=object), "-", {}),
        ]
        for q in self.quantities:
            vals = self.values[q.key]
            unit = _si_unit(q)
            if q.size > 1:
                arr = np.array(vals, dtype=np.float64).reshape(self.samples, q.size)
                table, _, name = q.path
                bearing = table.partition(".")[2] or None
                cols += [
                    (
                        element_column(name, bearing, j + 1, q.size),
                        arr[:, j],
                        unit,
                        {"key": q.key, "element": j + 1},
                    )
                    for j in range(q.size)
                ]
            else:
                # a Monte Carlo's drawn column is float64 already; a sweep's may hold text
                column = vals if isinstance(vals, np.ndarray) else np.array(vals, dtype=object)
                cols.append((identifier(q.key), column, unit, {"key": q.key}))
        cols += [(k, self.runout[k], "m", {}) for k in RUNOUT_KEYS]
        names = self.line_columns()
        for d, f, label, pp in self.line_table():
            info = {"direction": d, "frequency_hz": f, "label": label}
            cols.append((names[f"{d}|{label}"], pp, "m", info))
        return cols

    def line_columns(self) -> dict[str, str]:
        """Column name of every line (``"direction|label"`` -> name), unique and stable.

        Names come from the direction and label (:func:`runout.io.study_columns.line_column`);
        two labels that give one name are numbered in the order of their keys, which does not
        depend on the samples' values.
        """
        return line_column_names(self.lines)

    def stiffness_columns(self) -> list[tuple[str, list[Any]]]:
        """The table of ``stiffness.csv``: one row per equilibrium point that ran.

        Columns: ``sample``, the varied values by case key [SI] (``key[j]`` per element of a
        per-element key), ``speed_rpm`` [rev/min], ``frequency_rad_per_s`` (the speed as the
        rotor's angular frequency [rad/s], what rotordynamics codes index bearing
        coefficients by), ``kxx_n_per_m``, ``kxy_n_per_m``, ``kyx_n_per_m``, ``kyy_n_per_m``
        (the radial block, tilts held) and ``kzz_n_per_m`` (the axial stiffness K_aa) [N/m].
        With damping asked at any point (``[analysis] bearing_damping``, :attr:`damped`), then
        ``bearing_damping`` (the point's damping model: ``"kraemer"``, ``"proportional"``, or
        ``"none"`` with zero damping), ``bearing_damping_coefficient_s`` (β [s]) and
        ``cxx_n_s_per_m``, ``cxy_n_s_per_m``, ``cyx_n_s_per_m``, ``cyy_n_s_per_m``,
        ``czz_n_s_per_m`` (c = β k [N s/m]); without, no damping columns.
        A point whose model failed has no row (its error is in the points and summary).
        """
        rows = sorted(self.stiffness)
        cols: list[tuple[str, list[Any]]] = [("sample", rows)]
        for q in self.quantities:
            vals = self.values[q.key]
            if q.size > 1:
                cols += [(f"{q.key}[{j + 1}]", [vals[i][j] for i in rows]) for j in range(q.size)]
            else:
                cols.append((q.key, [vals[i] for i in rows]))
        radial = [self.stiffness[i]["radial_stiffness"] for i in rows]
        cols.append(("speed_rpm", [r["speed_rpm"] for r in radial]))
        cols.append(
            ("frequency_rad_per_s", [r["speed_rpm"] * 2.0 * math.pi / 60.0 for r in radial])
        )
        for k in _STIFFNESS_COLUMNS[:4]:
            cols.append((k, [r[k] for r in radial]))
        cols.append(("kzz_n_per_m", [self.stiffness[i]["axial_stiffness_n_per_m"] for i in rows]))
        if self.damped:
            # a point without damping in a table that has some: model "none", zero damping
            none = {"model": "none", "coefficient_s": 0.0, **dict.fromkeys(_DAMPING_COLUMNS, 0.0)}
            damping = [self.stiffness[i].get("bearing_damping", none) for i in rows]
            cols.append(("bearing_damping", [d["model"] for d in damping]))
            cols.append(("bearing_damping_coefficient_s", [d["coefficient_s"] for d in damping]))
            cols += [(k, [d[k] for d in damping]) for k in _DAMPING_COLUMNS]
        return cols

    @property
    def damped(self) -> bool:
        """True when a point has bearing damping (``[analysis] bearing_damping``)."""
        return any("bearing_damping" in entry for entry in self.stiffness.values())

    def _write_stiffness(self, path: Path) -> Path:
        cols = self.stiffness_columns()

        def rows(fh: TextIO) -> None:
            writer = csv.writer(fh, lineterminator="\n")
            writer.writerow([name for name, _ in cols])
            writer.writerows(zip(*([_cell(v) for v in col] for _, col in cols), strict=True))

        return write_atomic(path, rows)

    def _write_columns(self, path: Path) -> Path:
        # not sorted: "units" lists the columns in the order of samples.csv
        text = json.dumps(self.column_descriptions(), indent=2, allow_nan=False) + "\n"
        return _write_text(path, text)

    def _write_csv(self, path: Path) -> Path:
        cols = self.columns()

        def rows(fh: TextIO) -> None:
            writer = csv.writer(fh, lineterminator="\n")
            writer.writerow([name for name, _ in cols])
            # CSV_BLOCK rows at a time, column by column (no per-cell dispatch): the text of
            # 10^6 samples is never in memory at once
            for start in range(0, self.samples, CSV_BLOCK):
                block = slice(start, start + CSV_BLOCK)
                cells = [_cells(col[block]) for _, col in cols]
                writer.writerows(zip(*cells, strict=True))

        return write_atomic(path, rows)


def line_column_names(keys: Iterable[str]) -> dict[str, str]:
    """Column name of every line key (``"direction|label"`` -> name), unique and stable.

    Names come from the direction and label (:func:`runout.io.study_columns.line_column`);
    two labels that give one name are numbered in the order of their keys, which does not
    depend on the samples' values.
    """
    names: dict[str, str] = {}
    taken = set(RUNOUT_KEYS) | {"sample", "model"}
    for key in sorted(keys):
        direction, _, label = key.partition("|")
        base = line_column(direction, label)
        name, n = base, 1
        while name in taken:
            n += 1
            name = f"{base}_{n}"
        taken.add(name)
        names[key] = name
    return names


#: What a streaming study answers where per-sample values are asked for.
PER_SAMPLE_REFUSAL = (
    'a streaming study (statistics = "streaming") keeps no per-sample values; run it with '
    '[study] statistics = "exact" for {what}'
)


@dataclass(frozen=True)
class StreamedStudyResult(StudyResult):
    """A Monte Carlo reduced by streaming statistics: no per-sample column in memory.

    The per-sample attributes of :class:`StudyResult` (``model``, ``values``, ``runout``,
    ``lines``, ``stiffness``) are empty; ``errors`` holds the first
    :data:`runout.study._chunks.ERRORS_SHOWN` failed samples only. Count, mean, std, min and max
    are exact (the same bits for any chunking, worker count and scheduler); the percentiles and
    histograms come from a quantile sketch of relative accuracy ``quantile_relative_error``
    (:mod:`runout.study._stream`). Methods that need per-sample values (``points``,
    ``to_dataframe``, ``columns``, ``plot``) raise :class:`StudyError` saying to use
    ``statistics = "exact"``.

    Attributes
    ----------
    sample_count : int
        Number of samples.
    failed_count : int
        Samples whose model failed.
    models_run : tuple of str
        Models of the samples.
    runout_statistics : dict
        RUNOUT_KEYS -> :class:`StreamStatistics` [m].
    line_statistics : dict
        ``"direction|label"`` -> (frequency [Hz], :class:`StreamStatistics` of its p-p [m]
        over the samples that ran, 0 where the line is below the reporting floor).
    passed : int
        Samples within the spec limit (with ``limit``).
    notes : tuple of str
        What the streaming statistics change (JSON ``notes`` and the readable summary).
    """

    sample_count: int = 0
    failed_count: int = 0
    models_run: tuple[str, ...] = ()
    runout_statistics: dict[str, StreamStatistics] = field(default_factory=dict)
    line_statistics: dict[str, tuple[float, StreamStatistics]] = field(default_factory=dict)
    passed: int = 0
    notes: tuple[str, ...] = ()

    @property
    def samples(self) -> int:
        """Number of samples."""
        return self.sample_count

    @property
    def failed(self) -> int:
        """Number of samples whose model failed."""
        return self.failed_count

    def _line_order(self) -> list[tuple[str, float, str, StreamStatistics]]:
        rows = [
            (key.split("|", 1)[0], f, key.split("|", 1)[1], stats)
            for key, (f, stats) in self.line_statistics.items()
        ]
        ran = self.runout_statistics["radial_pp_m"].count > 0
        rows.sort(key=lambda r: (-r[3].mean() if ran else 0.0, r[0], r[1]))
        return rows

    def line_table(self) -> list[tuple[str, float, str, NDArray[np.float64]]]:
        """Refused: the lines' per-sample p-p are not kept."""
        raise StudyError(PER_SAMPLE_REFUSAL.format(what="the per-sample line p-p"))

    def summary(self) -> dict[str, Any]:
        """Full statistics (JSON-ready), as :meth:`StudyResult.summary`, plus ``statistics``,
        ``quantile_relative_error`` and ``notes``."""
        runout = {k: self.runout_statistics[k].summary(self.bins) for k in RUNOUT_KEYS}
        comps = [
            {"direction": d, "frequency_hz": f, "label": label, "pp_m": stats.summary(self.bins)}
            for d, f, label, stats in self._line_order()
        ]
        summary = self._summary_document(sorted(self.models_run), runout, comps)
        return {**summary, **self._streaming_keys()}

    def _streaming_keys(self) -> dict[str, Any]:
        return {
            "statistics": "streaming",
            "quantile_relative_error": QUANTILE_RELATIVE_ERROR,
            "notes": [*self._grade_keys().get("notes", []), *self.notes],
        }

    def _passed(self, quantity: str, limit: float) -> tuple[int, int]:
        return self.runout_statistics[f"{quantity}_m"].count, self.passed

    def points(self) -> list[dict[str, Any]]:
        """Refused: the per-sample records are not kept."""
        raise StudyError(PER_SAMPLE_REFUSAL.format(what="per-sample records"))

    def to_dataframe(self) -> Any:
        """Refused: the per-sample values are not kept."""
        raise StudyError(PER_SAMPLE_REFUSAL.format(what="a table of the samples"))

    def plot(self, kind: str | None = None, quantity: str | None = None, top: int = 4) -> Any:
        """Refused: the figures are drawn from the per-sample values."""
        raise StudyError(PER_SAMPLE_REFUSAL.format(what="its figures"))

    def columns(self) -> list[tuple[str, NDArray[Any]]]:
        """Refused: the per-sample values are not kept."""
        raise StudyError(PER_SAMPLE_REFUSAL.format(what="the columns of samples.csv"))

    def column_descriptions(self) -> dict[str, Any]:
        """Refused: the columns of samples.csv are not written."""
        raise StudyError(PER_SAMPLE_REFUSAL.format(what="the columns of samples.csv"))

    def write(self, directory: Path, plots: bool = True) -> list[Path]:
        """Write ``summary.json`` and, with ``plots``, ``histograms.png`` drawn from the
        summary's bins (:func:`runout.report.plotting.streamed_histograms`); a study with
        ``--out`` writes ``samples.csv`` and ``samples_columns.json`` from its chunk files
        (:func:`runout.study.run.run_study`)."""
        directory.mkdir(parents=True, exist_ok=True)
        summary = _nan_to_none(self.summary())  # the file's and the figure's, computed once
        written = [self._write_summary(directory, summary)]
        if plots and self.kind == "montecarlo":
            from runout.report._plot_style import _save
            from runout.report.plotting import streamed_histograms

            quantity = None if self.limit is None else f"{self.limit[0]}_m"
            limit_m = None if self.limit is None else self.limit[1]
            figure = streamed_histograms(summary, limit_quantity=quantity, limit_m=limit_m)
            written.append(_save(figure, directory / "histograms.png", dpi=110))
        return written


def _si_unit(q: Quantity) -> str:
    """SI unit of a varied quantity's values (``"-"`` for a count, a ratio or a text)."""
    from runout.base.units import KINDS
    from runout.report.plotting import _key_unit_kind  # the case schema's kind of the key

    table, index, name = q.path
    # a spindle bearing's [elements.<name>] has the [elements] table's keys
    kind = _key_unit_kind((table.partition(".")[0], index, name))
    return (KINDS[kind][1] if kind is not None else "") or "-"


def _cell(value: Any) -> str:
    if isinstance(value, float | np.floating):
        return repr(float(value)) if math.isfinite(value) else ""
    return str(value)


def _cells(column: NDArray[Any]) -> list[str]:
    """:func:`_cell` of every entry of ``column``, the same text."""
    if column.dtype.kind == "f":
        return [repr(v) if math.isfinite(v) else "" for v in column.tolist()]
    if column.dtype.kind in "iu":
        return [str(v) for v in column.tolist()]
    return [_cell(v) for v in column]


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def _nan_to_none(obj: Any) -> Any:
    """``obj`` with every non-finite float replaced by None (JSON has no NaN)."""
    if isinstance(obj, float):
        return _finite(obj)
    if isinstance(obj, dict):
        return {k: _nan_to_none(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_nan_to_none(v) for v in obj]
    return obj


def _dumps(obj: Any, indent: int | None = None) -> str:
    return json.dumps(obj, indent=indent, sort_keys=True, allow_nan=False) + "\n"


def _write_text(path: Path, text: str) -> Path:
    return write_atomic(path, lambda fh: fh.write(text))
