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

        Example: runout diagnose examples/seed002_608.toml --record run.csv --out out/diag
        """
        from runout.base.errors import CaseError
        from runout.diagnose.fit import diagnose

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
