"""The ``runout`` command-line tool.

Bad input ends with one clear line on stderr and exit status 2, never a traceback.
"""

from __future__ import annotations

import functools
import json
import math
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Any, TypeVar

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from runout import __version__
from runout.errors import RunoutError

app = typer.Typer(
    name="runout",
    help=(
        "Runout (RRO/NRRO) and vibration of rolling bearings from the geometry of their parts.\n\n"
        "Example: runout check examples/seed002_608.toml"
    ),
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)
_out = Console()
_err = Console(stderr=True)

F = TypeVar("F", bound=Callable[..., Any])

CaseArg = Annotated[
    Path, typer.Argument(help="TOML case file (see docs/case-file.md).", show_default=False)
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]


def _fail(message: str) -> None:
    _err.print(f"[bold red]error:[/] {escape(message)}", highlight=False, soft_wrap=True)
    raise typer.Exit(2)


def _guard(fn: F) -> F:
    """Turn runout's own errors into one line on stderr and exit status 2."""

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return fn(*args, **kwargs)
        except RunoutError as exc:
            _fail(str(exc))
        except KeyboardInterrupt:
            _err.print("interrupted")
            raise typer.Exit(130) from None

    return wrapper  # type: ignore[return-value]


def _print_json(payload: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(payload, indent=2, allow_nan=False) + "\n")


def _rows_table(title: str, rows: list[tuple[str, str, str]]) -> Table:
    table = Table(title=title, title_justify="left", show_header=True, header_style="bold")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("unit")
    for name, value, unit in rows:
        table.add_row(escape(name), escape(value), escape(unit))
    return table


def _version_callback(value: bool) -> None:
    if value:
        _out.print(f"runout {__version__}")
        raise typer.Exit()


@app.callback()
def _main(
    version: Annotated[
        bool,
        typer.Option("--version", callback=_version_callback, is_eager=True, help="Print version."),
    ] = False,
) -> None:
    """Runout (RRO/NRRO) and vibration of rolling bearings from the geometry of their parts."""


@app.command()
@_guard
def check(case_file: CaseArg, as_json: JsonOpt = False) -> None:
    """Validate a case file and print the derived geometry, contact constants and frequencies.

    Example: runout check examples/seed001_kim_spindle.toml --json
    """
    from runout.case import load_case
    from runout.summary import bearing_summary

    case = load_case(case_file)
    summary = bearing_summary(case.bearing, case.operation)
    if as_json:
        _print_json({"title": case.title, "case": str(case_file), **summary.to_json()})
        return
    _out.print(
        f"[bold]{escape(case.title or str(case_file))}[/]  ({escape(str(case_file))}) is valid."
    )
    for title, rows in summary.sections():
        _out.print(_rows_table(title, rows))
    if not case.imperfections.is_perfect:
        _out.print(_imperfection_table(case))


def _imperfection_table(case: Any) -> Table:
    table = Table(title="Imperfections", title_justify="left", header_style="bold")
    for col in ("part", "element", "order", "amplitude 0-p [nm]", "phase [deg]"):
        table.add_column(escape(col), justify="right" if col != "part" else "left")
    rows = case.imperfections.summary()
    for row in rows[:40]:
        element = row.get("element")
        table.add_row(
            str(row["part"]),
            "all" if element is None else str(element),
            str(row["order"]),
            f"{row['amplitude'] * 1e9:.4g}",
            f"{math.degrees(row['phase']):.4g}",
        )
    if len(rows) > 40:
        table.caption = f"... and {len(rows) - 40} more harmonics"
    return table


@app.command()
@_guard
def frequencies(case_file: CaseArg, as_json: JsonOpt = False) -> None:
    """Print cage, ball-spin and ball-pass frequencies in Hz and in orders.

    Example: runout frequencies examples/seed002_608.toml --json
    """
    from runout.case import load_case
    from runout.summary import bearing_summary

    case = load_case(case_file)
    summary = bearing_summary(case.bearing, case.operation)
    freqs = summary.frequencies
    if as_json:
        _print_json(
            {
                "title": case.title,
                "case": str(case_file),
                "contact_angle_deg": math.degrees(summary.contact_angle),
                "frequencies_hz": freqs.to_dict(),
                "orders": freqs.orders() if freqs.rotation > 0 else None,
            }
        )
        return
    table = Table(
        title=f"{case.title or case_file}: characteristic frequencies "
        f"(contact angle {math.degrees(summary.contact_angle):.4g} deg, "
        f"{case.operation.rotating_ring} ring rotating)",
        title_justify="left",
        header_style="bold",
    )
    table.add_column("frequency")
    table.add_column("Hz", justify="right")
    table.add_column("order (per rev)", justify="right")
    orders = freqs.orders() if freqs.rotation > 0 else None
    labels = {
        "rotation": "rotating ring",
        "cage": "cage (f_c)",
        "ball_spin": "element spin about its axis, rel. cage (f_b)",
        "ball_pass_inner": "element pass, inner raceway (BPFI)",
        "ball_pass_outer": "element pass, outer raceway (BPFO)",
    }
    for key, value in freqs.to_dict().items():
        order = "-" if orders is None else f"{orders[key]:.6g}"
        table.add_row(labels[key], f"{value:.6g}", order)
    _out.print(table)


@app.command()
@_guard
def run(
    case_file: CaseArg,
    as_json: JsonOpt = False,
    out: Annotated[
        Path | None, typer.Option("--out", help="Directory for plots and data files.")
    ] = None,
    report: Annotated[
        bool,
        typer.Option(
            "--report", help="Also write a self-contained report.html (default --out out/<case>)."
        ),
    ] = False,
) -> None:
    """Run the model named in the case's [analysis] table.

    Example: runout run examples/seed000_tada_fig7.toml --out out/tada --report
    """
    from runout.case import load_case
    from runout.models import run_model
    from runout.summary import bearing_summary

    case = load_case(case_file)
    result = run_model(case)
    if as_json:
        _print_json(result.to_json())
    else:
        for title, rows in result.summary_sections():
            _out.print(_rows_table(title, rows))
    if report and out is None:
        out = Path("out") / case_file.stem
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        written = result.write(out)
        # The inputs travel with the results, so a report can be rebuilt from the directory.
        summary = bearing_summary(case.bearing, case.operation)
        (out / "summary.json").write_text(
            json.dumps({"title": case.title, **summary.to_json()}, indent=2, allow_nan=False) + "\n"
        )
        (out / "case.toml").write_text(case_file.read_text(encoding="utf-8"), encoding="utf-8")
        written += [out / "summary.json", out / "case.toml"]
        if report:
            from runout.report import build_report

            written.append(build_report(out))
        if not as_json:
            for path in written:
                _out.print(f"wrote {escape(str(path))}")


@app.command("report")
@_guard
def report_command(
    directory: Annotated[
        Path, typer.Argument(help="Directory written by `runout run CASE --out DIR`.")
    ],
) -> None:
    """Write DIR/report.html: one self-contained page with inputs, results and figures.

    Example: runout report out/tada
    """
    from runout.report import build_report

    path = build_report(directory)
    _out.print(f"wrote {escape(str(path))}")


def main() -> None:
    """Console-script entry point."""
    app()


if __name__ == "__main__":
    main()
