"""The ``runout diagnose`` command (registered on the app by :func:`register`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.markup import escape
from rich.table import Table

from runout.cli.common import CaseArg, JsonOpt, _fail, _guard, _load, _out, _print_json

__all__ = ["register"]


def _table(diagnosis: Any) -> list[Any]:
    """Readable tables of a diagnosis (estimates, unattributed lines, what is not seen)."""
    from runout.base.display import format_length

    unit = "m" if diagnosis.quantity == "displacement" else "m/s"
    out: list[Any] = []
    est = Table(
        title=f"Estimated deviations (linear model, {diagnosis.variant}); explained fraction "
        f"{diagnosis.explained_fraction:.4f}",
        title_justify="left",
        header_style="bold",
    )
    for name in (
        "part",
        "lobes",
        "amplitude",
        "± 1σ",
        "phase [deg]",
        "± 1σ [deg]",
        "line [Hz]",
        "whirl",
    ):
        est.add_column(escape(name), justify="right" if name not in ("part", "whirl") else "left")
    est.add_column("share", justify="right")
    for e in diagnosis.estimates:
        who = e.part if e.element is None else f"{e.part} {e.element}"
        if e.note.startswith(("ball set", "roller set")):
            who += " set"
        est.add_row(
            escape(who),
            escape(" | ".join(str(k) for k in e.lobes)),
            escape(format_length(e.amplitude_m)),
            escape(format_length(e.uncertainty_m)),
            # a phase a hair below 2 pi is 0: print 0.0, not 360.0
            f"{round(e.phase_rad * 57.29577951308232, 1) % 360.0:.1f}",
            f"{e.phase_uncertainty_rad * 57.29577951308232:.2g}",
            f"{e.frequency_hz:.6g}",
            e.whirl,
            f"{e.share:.3f}",
        )
    if not diagnosis.estimates:
        est.add_row("none detected", "", "", "", "", "", "", "", "")
    out.append(est)
    if diagnosis.unattributed:
        un = Table(
            title="Unattributed lines (no bearing deviation of the model explains them)",
            title_justify="left",
            header_style="bold",
        )
        for name in ("frequency [Hz]", "order", f"p-p [{unit}]", "channel", "kinematic match"):
            un.add_column(escape(name))
        for u in diagnosis.unattributed:
            un.add_row(
                f"{u.frequency_hz:.6g}",
                f"{u.order:.5g}",
                f"{u.pp:.4g}",
                u.channel,
                escape(u.kinematic_match or "none"),
            )
        out.append(un)
    return out


def _parse_band(text: str) -> tuple[float, float]:
    """``LO,HI`` [Hz] of --band, or exit 2 naming the option."""
    import math

    parts = text.split(",")
    try:
        if len(parts) != 2:
            raise ValueError
        lo, hi = float(parts[0]), float(parts[1])
    except ValueError:
        _fail(f"--band must be two frequencies in Hz as LO,HI (e.g. 2000,4000), got {text!r}")
        raise  # unreachable: _fail exits
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo < hi):
        _fail(f"--band must satisfy 0 <= LO < HI (finite, in Hz), got {text!r}")
    return lo, hi


def _envelope_tables(result: Any) -> list[Any]:
    """Readable tables of an envelope diagnosis: the parts ranked, the largest peaks."""
    ranked = Table(
        title=f"Defect evidence (squared envelope spectrum, band {result.band_hz[0]:.6g}-"
        f"{result.band_hz[1]:.6g} Hz, {result.band_source}); verdict: {result.verdict}",
        title_justify="left",
        header_style="bold",
    )
    for name in (
        "part",
        "defect freq. [Hz]",
        "order",
        "assessment",
        "score [dB]",
        "harmonics found",
        "sidebands found",
        "SNR of 1x",
    ):
        ranked.add_column(
            escape(name), justify="left" if name in ("part", "assessment") else "right"
        )
    for d in result.defects:
        first = next((e for e in d.lines if e.harmonic == 1 and e.sideband == 0), None)
        ranked.add_row(
            d.part,
            f"{d.frequency_hz:.6g}",
            f"{d.order:.5g}",
            d.assessment,
            f"{d.score:.1f}",
            ", ".join(map(str, d.harmonics_found)) or "none",
            str(sum(1 for e in d.lines if e.sideband != 0 and e.found)),
            "—" if first is None else f"{first.snr:.3g}",
        )
    peaks = Table(
        title="Largest envelope-spectrum peaks", title_justify="left", header_style="bold"
    )
    for name in ("frequency [Hz]", "amplitude [(m/s^2)^2]", "SNR", "label"):
        peaks.add_column(escape(name), justify="left" if name == "label" else "right")
    for p in result.peaks:
        peaks.add_row(
            f"{p.frequency_hz:.6g}", f"{p.amplitude:.4g}", f"{p.snr:.3g}", escape(p.label or "—")
        )
    return [ranked, peaks]


def _envelope(
    case_file: Path,
    record: Path,
    quantity: str,
    variant: str | None,
    max_lobes: int | None,
    band: str | None,
    slip_tolerance: float,
    as_json: bool,
    out: str | None,
    force: bool,
) -> None:
    """``runout diagnose --envelope``: read, diagnose, print and write."""
    from runout.diagnose.envelope import diagnose_envelope

    for given, option in (
        (quantity != "displacement", "--quantity"),
        (variant is not None, "--variant"),
        (max_lobes is not None, "--max-lobes"),
    ):
        if given:
            _fail(
                f"{option} is read by the line fit, not by --envelope (an acceleration "
                "record): drop one of them"
            )
    pass_band = None if band is None else _parse_band(band)
    case = _load(case_file)
    directory = None
    if out is not None:
        from runout.io.output_dir import claim, output_directory

        directory = output_directory(out)
        claim(directory, force=force)
    result = diagnose_envelope(case, record, band=pass_band, slip_tolerance=slip_tolerance)
    if as_json:
        _print_json(result.to_json())
    else:
        for table in _envelope_tables(result):
            _out.print(table)
        if result.notes:
            _out.print("[bold]Notes[/]", soft_wrap=True)
            for text in result.notes:
                _out.print(f"- {escape(text)}", highlight=False, soft_wrap=True, emoji=False)
    if directory is not None:
        from runout.io.output_dir import staged
        from runout.report._envelope import write_envelope

        with staged(directory) as stage:
            written = [stage.final(p) for p in write_envelope(result, stage.path)]
        if not as_json:
            for path in written:
                _out.print(f"wrote {escape(str(path))}")


def register(app: typer.Typer) -> None:
    """Add ``diagnose`` to ``app`` (the ``runout`` command line)."""

    @app.command("diagnose")
    @_guard
    def diagnose_command(
        case_file: CaseArg,
        record: Annotated[
            Path,
            typer.Option(
                "--record",
                help="CSV record: time_s and x_m and/or y_m (units in brackets: 'x \\[um]'), "
                "optional tachometer column rev.",
                show_default=False,
            ),
        ],
        quantity: Annotated[
            str,
            typer.Option(
                "--quantity",
                help="What x/y hold: displacement or velocity (Anderon-meter records).",
            ),
        ] = "displacement",
        variant: Annotated[
            str | None,
            typer.Option(
                "--variant",
                help="Linear-model variant to invert: radial_spring or force_balance "
                "(default: the case's \\[analysis] linear_variant).",
                show_default=False,
            ),
        ] = None,
        max_lobes: Annotated[
            int | None,
            typer.Option(
                "--max-lobes",
                min=1,
                help="Largest lobe count searched (default: every line below the Nyquist "
                "frequency, at most 240 lines).",
                show_default=False,
            ),
        ] = None,
        gain_uncertainty: Annotated[
            float,
            typer.Option(
                "--gain-uncertainty",
                min=0.0,
                max=0.5,
                help="Relative standard uncertainty of the sensor's calibration (gain), "
                "included in every amplitude and phase uncertainty and in the detection: "
                "0.01 = 1 %, a probe calibration certificate's usual sensitivity tolerance.",
            ),
        ] = 0.01,
        envelope: Annotated[
            bool,
            typer.Option(
                "--envelope",
                help="Envelope diagnosis of an acceleration record (column a_m_per_s2, or "
                "a \\[m/s^2], a \\[g]): which localized defect (outer race, inner race, ball, "
                "cage) its squared-envelope spectrum shows.",
            ),
        ] = False,
        band: Annotated[
            str | None,
            typer.Option(
                "--band",
                help="With --envelope: the pass band LO,HI in Hz (default: the fast "
                "kurtogram's most impulsive band).",
                show_default=False,
            ),
        ] = None,
        slip_tolerance: Annotated[
            float,
            typer.Option(
                "--slip-tolerance",
                min=0.0,
                max=0.1,
                help="With --envelope: relative tolerance of the defect frequencies "
                "(rolling elements slip 1-2 %; 0.02 = 2 %).",
            ),
        ] = 0.02,
        as_json: JsonOpt = False,
        out: Annotated[
            str | None,
            typer.Option(
                "--out",
                help="Directory for report.html, diagnosis.json, the estimated case file "
                "(estimated.toml, runs with `runout run`) and the figures: new, empty or "
                "runout's; files are written whole or not at all, never over a file runout "
                "did not write, never through a link.",
                show_default=False,
            ),
        ] = None,
        force: Annotated[
            bool,
            typer.Option(
                "--force",
                help="Write into a non-empty --out that is not runout's (only runout's own "
                "files are replaced).",
            ),
        ] = False,
    ) -> None:
        r"""Estimate which part deviations produced a measured runout or vibration record.

        CASE gives the bearing and the operation; its imperfection tables are ignored. The
        record is fitted on the lines of the bearing's kinematics and the linear model is
        inverted; what the record cannot tell apart is reported, not guessed
        (docs/models/diagnosis.md). The record's speed is read from its own lines: a record
        whose lines give a speed more than 2 % from the case's (or the tachometer's) is
        refused, a slow drift is tracked. Uncertainties include the noise, the sensor gain
        (--gain-uncertainty) and the speed tracking.

        With --envelope the record is an acceleration (column a_m_per_s2, a [m/s^2] or
        a [g]) and the diagnosis reads its squared-envelope spectrum for the bearing's
        defect frequencies (BPFO, BPFI, ball, cage) within the slip tolerance: the parts
        ranked with their evidence (harmonics, sidebands, SNR) and a plain verdict.

        Example: runout diagnose examples/seed002_608.toml --record run.csv --out out/diag
        """
        from runout.base.errors import CaseError
        from runout.diagnose.fit import diagnose

        if envelope:
            _envelope(
                case_file,
                record,
                quantity,
                variant,
                max_lobes,
                band,
                slip_tolerance,
                as_json,
                out,
                force,
            )
            return
        if band is not None:
            _fail("--band is read by the envelope diagnosis: add --envelope")
        if quantity not in ("displacement", "velocity"):
            _fail(f'--quantity must be "displacement" or "velocity", got {quantity!r}')
        if variant is not None and variant not in ("radial_spring", "force_balance"):
            raise CaseError(
                str(case_file),
                "analysis.linear_variant",
                f'--variant must be "radial_spring" or "force_balance", got {variant!r}',
            )
        case = _load(case_file)
        directory = None
        if out is not None:  # checked before the fit: a refused directory costs nothing
            from runout.io.output_dir import claim, output_directory

            directory = output_directory(out)
            claim(directory, force=force)
        result = diagnose(
            case,
            record,
            quantity=quantity,  # type: ignore[arg-type]
            variant=variant,
            max_lobes=max_lobes,
            gain_uncertainty=gain_uncertainty,
        )
        if as_json:
            _print_json(result.to_json())
        else:
            for table in _table(result):
                _out.print(table)
            remarks = [
                f"{e.part} {' | '.join(map(str, e.lobes))} lobes at {e.frequency_hz:.6g} Hz: "
                f"{e.note}"
                for e in result.estimates
                if e.note
            ]
            for title, items in (
                ("About the estimates", tuple(remarks)),
                ("Not observable with this record", result.not_observable),
                ("Notes", result.notes),
            ):
                if not items:
                    continue
                _out.print(f"[bold]{escape(title)}[/]", soft_wrap=True)
                for text in items:
                    _out.print(f"- {escape(text)}", highlight=False, soft_wrap=True, emoji=False)
        if directory is not None:
            from runout.io.output_dir import staged
            from runout.report._diagnosis import write_diagnosis

            # all the files or none, never over a file runout did not write (docs/outputs.md)
            with staged(directory) as stage:
                written = [stage.final(p) for p in write_diagnosis(result, stage.path)]
            if not as_json:
                for path in written:
                    _out.print(f"wrote {escape(str(path))}")
