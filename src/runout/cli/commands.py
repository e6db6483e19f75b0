"""The ``runout`` command-line tool.

Bad input ends with one clear line on stderr, ``error: FILE: key.path: problem``, and exit
status 2, never a traceback. Warnings raised while a command runs (a poorly resolved profile,
a numerical overflow) are collected and printed as one ``warning:`` line after it, without the
source paths Python's warnings module would print. A failure that is not runout's own (a bug)
is one ``error:`` line too, with exit status 70; ``RUNOUT_DEBUG=1`` shows its traceback.

Output meant for scripts does not depend on the terminal: JSON is written as is, one-line
messages are never wrapped, and tables written to a pipe or a file are laid out for a fixed
width (:data:`PIPE_WIDTH`), whatever the terminal or ``COLUMNS``.
"""

from __future__ import annotations

import csv
import json
import math
import os
import re
import shutil
import sys
from contextlib import ExitStack, nullcontext
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer
from rich.markup import escape
from rich.table import Table

from runout import __version__
from runout.cli.catalogue import CatalogueOpt, use_catalogue
from runout.cli.common import (
    PIPE_WIDTH,
    CaseArg,
    JsonOpt,
    ModelOpt,
    SetOpt,
    _err,
    _fail,
    _guard,
    _load,
    _one_line,
    _out,
    _print_json,
    _print_sections,
    _rows_table,
    _warn,
)

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
    # Rich measures the terminal on stdin/stderr even when stdout is a pipe, and honours
    # COLUMNS: output read by scripts and tests would depend on where it ran.
    if not _out.is_terminal:
        _out.size = (PIPE_WIDTH, 25)


@app.command()
@_guard
def check(
    case_file: CaseArg,
    as_json: JsonOpt = False,
    model: ModelOpt = None,
    sets: SetOpt = None,
    catalogue: CatalogueOpt = None,
) -> None:
    """Validate a case file and print the derived geometry, contact constants and frequencies.

    Runs every check a run does (the model's input checks, the memory and time budget, Hertz
    validity), so a case called valid is not refused on input later; warnings go to one
    warning: line (--json: "warnings"). --model and --set check the case as run would run it.

    Example: runout check examples/seed001_kim_spindle.toml --json
    """
    from runout.base.errors import CaseError
    from runout.report.summary import bearing_source_sections, bearing_summary, model_use
    from runout.runner.checks import validate

    use_catalogue(catalogue)
    case = _load(case_file, model, sets)
    summary = bearing_summary(case.bearing, case.operation)
    use = model_use(case)
    named = "model" in case.spec.analysis.model_fields_set
    if use.refusals and named:
        # `check` calls a case valid only when the model it names will run it
        key, message = use.refusals[0]
        raise CaseError(str(case_file), key, message)
    # the model's own input checks, the budget and the Hertz validity, as `run` does them
    notes = list(validate(case, strict=named))
    sources = [s.to_json() for s in case.bearing_sources]
    if as_json:
        payload = {"title": case.title, "case": str(case_file), **summary.to_json()}
        payload["model_use"] = use.to_json()
        payload["warnings"] = notes
        if sources and case.spindle is None:
            payload["bearing_source"] = sources[0]
        elif sources:
            payload["bearing_sources"] = sources
        _print_json(payload)
        return
    _warn(case_file, notes)
    # soft_wrap: one line however long the path, so that "is valid" is never split
    _out.print(
        f"[bold]{escape(case.title or str(case_file))}[/]  ({escape(str(case_file))}) is valid.",
        soft_wrap=True,
    )
    # a designation: d, D, B and where each value comes from, before the derived geometry
    _print_sections(
        bearing_source_sections(
            sources[0] if len(sources) == 1 and case.spindle is None else sources or None
        )
    )
    catalogue_notes = [n for s in case.bearing_sources for n in s.notes]
    if catalogue_notes:
        _print_sections([("Catalogue notes", [(n, "", "") for n in catalogue_notes])])
    for title, rows in summary.sections():
        _out.print(_rows_table(title, rows))
    _out.print(_rows_table(f"As the {use.model} model uses it", use.rows()))
    if case.spindle is not None:  # one table per bearing: each has its own parts
        for b in case.spindle.bearings:
            if not b.imperfections.is_perfect:
                _out.print(_imperfection_table(b.imperfections, f"Imperfections: {b.name} bearing"))
    elif not case.imperfections.is_perfect:
        _out.print(_imperfection_table(case.imperfections))


def _imperfection_table(imperfections: Any, title: str = "Imperfections") -> Table:
    table = Table(title=escape(title), title_justify="left", header_style="bold")
    for col in ("part", "element", "order", "amplitude 0-p [nm]", "phase [deg]"):
        table.add_column(escape(col), justify="right" if col != "part" else "left")
    rows = imperfections.summary()
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
def frequencies(
    case_file: CaseArg, as_json: JsonOpt = False, catalogue: CatalogueOpt = None
) -> None:
    """Print cage, element-spin and element-pass frequencies in Hz and in orders.

    A roller bearing's JSON also has roller_pass_inner/roller_pass_outer (equal to
    ball_pass_inner/ball_pass_outer, which stay for every bearing).

    Example: runout frequencies examples/seed002_608.toml --json
    """
    from runout.analysis.results import frequencies_json
    from runout.case.model import load_case
    from runout.geometry.bearing import RollerBearing
    from runout.geometry.kinematics import bearing_frequencies
    from runout.report.summary import bearing_summary

    use_catalogue(catalogue)
    case = load_case(case_file)
    # (name, bearing, contact angle): a spindle's bearings each at the angle its model uses
    sets: list[tuple[str | None, Any, float]]
    if case.spindle is not None:
        from runout.models import spindle

        setups = spindle.setup(case.spindle, case.operation).bearings
        sets = [
            (b.name, b.bearing, s.contact_angle)
            for b, s in zip(case.spindle.bearings, setups, strict=True)
        ]
    else:
        sets = [(None, case.bearing, bearing_summary(case.bearing, case.operation).contact_angle)]

    def entry(bearing: Any, angle: float) -> dict[str, Any]:
        freqs = bearing_frequencies(bearing, case.operation, angle)
        element = "roller" if isinstance(bearing, RollerBearing) else "ball"
        return {
            "contact_angle_deg": math.degrees(angle),
            "frequencies_hz": frequencies_json(freqs.to_dict(), element),
            "orders": frequencies_json(freqs.orders(), element) if freqs.rotation > 0 else None,
        }

    if as_json:
        payload = {"title": case.title, "case": str(case_file), **entry(*sets[0][1:])}
        if case.spindle is not None:  # the first bearing above, as in runout run's output
            payload["bearings"] = [{"name": n, **entry(b, a)} for n, b, a in sets]
        _print_json(payload)
        return
    for name, bearing, angle in sets:
        _out.print(_frequency_table(case, case_file, name, bearing, angle))


def _frequency_table(
    case: Any, case_file: Path, name: str | None, bearing: Any, angle: float
) -> Table:
    from runout.geometry.bearing import RollerBearing
    from runout.geometry.kinematics import bearing_frequencies

    freqs = bearing_frequencies(bearing, case.operation, angle)
    element = "roller" if isinstance(bearing, RollerBearing) else "ball"
    which = "" if name is None else f", {name} bearing"
    table = Table(
        title=f"{case.title or case_file}: characteristic frequencies{which} "
        f"(contact angle {math.degrees(angle):.4g} deg, "
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
        "ball_spin": f"{element} spin about its axis, rel. cage (f_b)",
        "ball_pass_inner": f"{element} pass, inner raceway (BPFI)",
        "ball_pass_outer": f"{element} pass, outer raceway (BPFO)",
    }
    for key, value in freqs.to_dict().items():
        order = "-" if orders is None else f"{orders[key]:.6g}"
        table.add_row(labels[key], f"{value:.6g}", order)
    return table


@app.command()
@_guard
def run(
    case_file: CaseArg,
    as_json: JsonOpt = False,
    out: Annotated[
        str | None,
        typer.Option(
            "--out",
            help="Directory for plots and data files, with a copy of the case (case.toml): "
            "new, empty or runout's; files are written whole or not at all, never over a file "
            "runout did not write, never through a link.",
        ),
    ] = None,
    report: Annotated[
        bool,
        typer.Option(
            "--report", help="Also write a self-contained report.html (default --out out/<case>)."
        ),
    ] = False,
    force: Annotated[
        bool,
        typer.Option(
            "--force",
            help="Write into a non-empty --out that is not runout's, or over the results of "
            "another case (its case.toml differs); only runout's own files are replaced.",
        ),
    ] = False,
    model: ModelOpt = None,
    sets: SetOpt = None,
    history_revolutions: Annotated[
        float,
        typer.Option(
            "--history-revolutions",
            min=0.01,
            max=1e6,
            help="Revolutions of the rotating ring the time-history figure shows (the last ones).",
        ),
    ] = 3.0,
    catalogue: CatalogueOpt = None,
) -> None:
    r"""Run the model named in the case's \[analysis] table (or --model).

    \[analysis] bands adds band values, \[analysis] limit a PASS/FAIL verdict (docs/concepts.md).

    --model NAME runs another model on the same case; --set KEY=VALUE changes one case key
    (validated like the file). With either, --out's case.toml is the case as run.

    --out DIR refuses a DIR whose case.toml is another case, or a non-empty DIR that is not
    runout's, unless --force; even --force replaces only files runout wrote (docs/outputs.md).

    Example: runout run examples/seed000_tada_fig7.toml --out out/tada --report
    """
    with ExitStack() as stack:
        # the figures' processes (--out only) start first and import matplotlib while this one
        # reads the case and runs the model; a refused case or directory ends them unused
        writes = out is not None or report
        early, _EARLY_WORKERS[:] = _EARLY_WORKERS[:], []
        for unused in early[writes:]:  # started by main() for a command that writes nothing
            unused.close()
        workers = stack.enter_context(early[0] if early else _figure_workers()) if writes else None
        from runout.report.summary import result_sections
        from runout.runner import run_model

        use_catalogue(catalogue)
        case = _load(case_file, model, sets)
        if report and out is None:
            out = str(Path("out") / case_file.stem)
        case_text = _case_text(case_file, case, model, sets)
        # checked before the model runs: a refused directory costs nothing and is left untouched
        directory = None if out is None else _run_directory(out, case_file, force, case_text)
        result = run_model(case)  # with the case's [analysis] outputs (bands, verdict)
        if as_json:
            _print_json(result.to_json())
        else:
            _print_sections(result_sections(result))
        if directory is not None:
            written = _write_run(
                result, case, case_file, case_text, directory, report, history_revolutions,
                workers,
            )  # fmt: skip
            if not as_json:
                for path in written:
                    _out.print(f"wrote {escape(str(path))}")


#: The drawing processes :func:`main` started before the arguments were parsed (``run`` takes
#: them; at most one entry).
_EARLY_WORKERS: list[Any] = []


def _writes_files(args: list[str]) -> bool:
    """Whether ``args`` look like ``run ... --out DIR`` or ``run ... --report``: the drawing
    processes are then started before the arguments are parsed (a guess: a wrong one costs
    processes that end unused, never a file)."""
    if not args or args[0] != "run":
        return False
    return any(a in ("--out", "--report") or a.startswith("--out=") for a in args[1:])


def _figure_workers() -> Any:
    """Processes that draw the figures of ``run --out`` (:mod:`runout.report._figure_workers`)."""
    from runout.report._figure_workers import FigureWorkers, figure_processes

    return FigureWorkers(figure_processes(), _warm_figures)


def _warm_figures() -> None:
    """A drawing process's start: the plotting code is imported there, beside this process
    (which imports it only to write the files, once the model has run)."""
    from runout.report.run_files import warm_figures

    warm_figures()


def _write_run(
    result: Any,
    case: Any,
    case_file: Path,
    case_text: str,
    directory: Path,
    report: bool,
    history_revolutions: float,
    workers: Any = None,
) -> list[Path]:
    """Write the files of ``run --out``: all of them, or none (docs/outputs.md).

    The files are written into a staging directory inside ``directory`` and moved into place
    together once every one is written and none would replace a file runout did not write:
    a full disk or a refused name leaves ``directory`` as it was.
    """
    from runout.io.output_dir import staged
    from runout.report.run_files import write_result
    from runout.report.summary import bearing_summary

    with staged(directory) as stage:
        written = write_result(
            result, stage.path, history_revolutions=history_revolutions, workers=workers
        )
        # The inputs travel with the results, so a report can be rebuilt from the directory.
        summary = bearing_summary(case.bearing, case.operation)
        (stage.path / "summary.json").write_text(
            json.dumps({"title": case.title, **summary.to_json()}, indent=2, allow_nan=False) + "\n"
        )
        (stage.path / "case.toml").write_text(case_text, encoding="utf-8")
        written += [stage.path / "summary.json", stage.path / "case.toml"]
        written += _copy_profiles(case_file, case, directory, stage.path)
        written = [stage.final(p) for p in written]
    if report:
        from runout.io.output_dir import write_owned
        from runout.report.page import report_html

        text = report_html(directory)
        written.append(write_owned(directory, "report.html", lambda fh: fh.write(text)))
    return written


def _copy_profiles(case_file: Path, case: Any, directory: Path, stage: Path) -> list[Path]:
    """Copy the profile CSVs the case names by a relative path into ``stage`` (for ``--out``).

    DIR/case.toml names them relative to itself, as the case file did: without the copies
    ``runout run DIR/case.toml`` and ``runout report DIR`` could not read the case. A profile
    must lie inside the case file's directory (or a ``RUNOUT_PROFILE_DIRS`` directory, named
    by an absolute path, which the copy of the case reaches as it is). A profile that already
    is the file in ``directory`` (``--out`` is the case's directory) is not copied.
    """
    copied: list[Path] = []
    for entry in case.spec.profile:
        name = Path(entry.file)
        if name.is_absolute() or ".." in name.parts:
            continue  # read from where it is, by the same absolute name
        source, final = case_file.parent / name, directory / name
        if final.exists() and not final.is_symlink() and final.samefile(source):
            continue
        target = stage / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, target)
        copied.append(target)
    return copied


def _case_text(case_file: Path, case: Any, model: str | None, sets: list[str] | None) -> str:
    """Text of the case as run: the file itself, or with --model/--set the case rewritten."""
    if model is None and not sets:
        return case_file.read_text(encoding="utf-8")
    given = [f"--model {model}"] if model is not None else []
    given += [f"--set {text}" for text in sets or ()]
    header = f"# {case_file} run with {' '.join(given)}\n"
    return _one_line(header.rstrip("\n")) + "\n" + case.to_toml()


def _run_directory(out: str, case_file: Path, force: bool, case_text: str) -> Path:
    """The ``run --out`` directory, created; refused when its case.toml is another case.

    ``runout report DIR`` rebuilds the report from DIR/case.toml and the results next to it:
    results of one case beside the case file of another would make a wrong report, and the
    user's case.toml would be lost. Writing under another name would keep the file but still
    mix the two, so another case is refused (``--force`` replaces it). The same text again is
    a rerun of the same case and is rewritten in place.
    """
    from runout.io.output_dir import OutputError, claim, output_directory

    directory = output_directory(out)
    claim(directory, force=force)
    target = directory / "case.toml"
    if force or not (target.exists() or target.is_symlink()):
        return directory
    try:
        same = target.read_text(encoding="utf-8") == case_text
    except (OSError, ValueError):
        same = False
    if not same:
        raise OutputError(
            f"{target}: holds another case (the results in {directory} are not of "
            f"{case_file}); choose another --out or pass --force to replace them"
        )
    return directory


@app.command("report")
@_guard
def report_command(
    directory: Annotated[
        Path, typer.Argument(help="Directory written by `runout run CASE --out DIR`.")
    ],
    catalogue: CatalogueOpt = None,
) -> None:
    """Write DIR/report.html: one self-contained page with inputs, results and figures.

    DIR/report.html is replaced only when runout wrote it; a link there is refused.

    Example: runout report out/tada
    """
    from runout.io.output_dir import output_directory, write_owned
    from runout.report.page import report_html

    use_catalogue(catalogue)  # the case's designation, when a user catalogue gave it
    text = report_html(directory)  # refuses a directory that is not a run's or a study's
    output_directory(directory, option="report")
    path = write_owned(directory, "report.html", lambda fh: fh.write(text))
    _out.print(f"wrote {escape(str(path))}")


def _number_list(text: str | None, kind: type, name: str) -> list[Any]:
    if text is None or not text.strip():
        return []
    try:
        return [kind(part) for part in text.split(",") if part.strip()]
    except ValueError:
        raise typer.BadParameter(f"{name}: expected a comma-separated list, got {text!r}") from None


@app.command("sweep-dynamic")
@_guard
def sweep_dynamic(
    case_file: CaseArg,
    elements: Annotated[
        str | None, typer.Option("--elements", help="Numbers of balls, e.g. 5,7,8,10,12,15.")
    ] = None,
    preload: Annotated[
        str | None, typer.Option("--preload", help="Axial preloads [N], e.g. 10,30,50,100.")
    ] = None,
    out: Annotated[
        str, typer.Option("--out", help="Directory for the panels, sweep.csv and points/.")
    ] = "out/sweep-dynamic",
    as_json: JsonOpt = False,
    force: Annotated[
        bool,
        typer.Option("--force", help="Write into a non-empty --out that is not a sweep's."),
    ] = False,
) -> None:
    """Dynamic model (seed 003) over numbers of balls x preloads: Fig. 3/4-style spectra.

    Finished points are kept in OUT/points/ and reused by a rerun of the same case.

    OUT is locked while the sweep writes; a non-empty OUT that is not a sweep's needs --force.

    Example: runout sweep-dynamic examples/seed003_purohit.toml --elements 5,7,8,10,12,15
    --preload 10,30,50,100 --out out/purohit
    """
    from rich.progress import Progress

    from runout.case.model import load_case
    from runout.study.dynamic_sweep import exact_number, sweep

    case = load_case(case_file)
    zs = _number_list(elements, int, "--elements")
    ps = _number_list(preload, float, "--preload")
    # no bar off a terminal: a refused --out stays one line on stderr
    disable = as_json or not _err.is_terminal
    with Progress(console=_err, transient=True, disable=disable) as bar:
        task = bar.add_task("sweep", total=max(1, len(zs or [0]) * len(ps or [0])))

        def tick(done: int, total: int, name: str) -> None:
            bar.update(task, completed=done, total=total, description=name)

        points = sweep(case, zs, ps, out, progress=tick, force=force, notify=_note)
    if as_json:
        _print_json({"points": [p.to_json() for p in points]})
        return
    table = Table(title=f"{case.title or case_file}: dynamic sweep", header_style="bold")
    for col in ("balls", "preload [N]", "α_p [deg]", "BPF [Hz]", "f_n [Hz]", "BP line p-p [nm]"):
        table.add_column(escape(col), justify="right")
    for p in points:
        table.add_row(
            str(p.elements),
            exact_number(p.preload_n),
            f"{p.contact_angle_deg:.4g}",
            f"{p.ball_passage_hz:.5g}",
            "/".join(f"{f:.5g}" for f in p.natural_frequencies_hz),
            f"{p.ball_passage_pp_m * 1e9:.4g}",
        )
    _out.print(table)
    _out.print(f"wrote {escape(out)}/ (sweep.csv, trend.png, spectra_*.png, points/)")


def _note(message: str) -> None:
    """A one-line note on stderr: something the user should know that is not an error."""
    _err.print(f"note: {escape(message)}", highlight=False, soft_wrap=True)


@app.command("study")
@_guard
def study_command(
    case_file: CaseArg,
    as_json: JsonOpt = False,
    out: Annotated[
        str | None,
        typer.Option(
            "--out",
            help="Directory for chunk files, manifest, summary, samples.csv (with its units in "
            "samples_columns.json) and plots (new, empty or a study's; locked while the study "
            "writes).",
        ),
    ] = None,
    workers: Annotated[
        int, typer.Option("--workers", min=1, help="Local worker processes (1: in-process).")
    ] = 1,
    scheduler: Annotated[
        str | None,
        typer.Option(
            "--scheduler",
            help="Dask scheduler tcp://HOST:PORT (or 'local' for a local cluster); connecting "
            "waits at most RUNOUT_SCHEDULER_CONNECT_TIMEOUT (10 s), an answer "
            "RUNOUT_SCHEDULER_RESPONSE_TIMEOUT (30 s).",
        ),
    ] = None,
    resume: Annotated[
        bool, typer.Option("--resume", help="Continue an interrupted run recorded in --out.")
    ] = False,
    chunk_size: Annotated[
        int | None, typer.Option("--chunk-size", min=1, help="Samples per task and result file.")
    ] = None,
    force: Annotated[
        bool,
        typer.Option(
            "--force",
            help="Write into a non-empty --out that is not a study's; start afresh over a "
            "corrupted manifest or a different study.",
        ),
    ] = False,
    model: ModelOpt = None,
    sets: SetOpt = None,
    allocate: Annotated[
        str | None,
        typer.Option(
            "--allocate",
            metavar="KEY",
            help="Find the largest tolerance of this [study.vary] key (element_diameter_sigma, "
            "a normal std, a uniform high) for which the lot meets [analysis] limit with "
            "--target-yield (sets study.allocate; docs/studies.md).",
        ),
    ] = None,
    target_yield: Annotated[
        float | None,
        typer.Option(
            "--target-yield",
            metavar="Y",
            help="Fraction of the lot within the limit for --allocate, 0 < Y < 1 (sets "
            "study.target_yield).",
        ),
    ] = None,
    catalogue: CatalogueOpt = None,
) -> None:
    r"""Run the case's \[study]: Monte Carlo over drawn quantities or a sweep (docs/studies.md).

    A sample whose model fails is recorded with its error; the study goes on.

    Exit status: 0 if any sample succeeded (failures noted), 1 if all failed, 2 for bad input.

    Example: runout study examples/seed001_kim_table9.toml --json --workers 2
    """
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

    from runout.study.run import dask_executor, run_study

    if resume and out is None:
        _fail("--resume needs --out DIR (the directory of the interrupted run)")
    if scheduler is not None:  # a malformed address is refused before anything is read
        from runout.study.scheduler import scheduler_address

        scheduler_address(scheduler)
    use_catalogue(catalogue)
    case = _load_allocating(case_file, model, sets, allocate, target_yield)
    for source in case.bearing_sources:  # [bearing] designation: what was replaced or not applied
        for line in source.notes:
            _note(line)
    if case.study is None:
        _fail(f"{case_file}: study: the case has no [study] table (see docs/studies.md)")
    if case.study.kind == "arrangement":
        given = {
            "--workers": workers != 1,
            "--scheduler": scheduler is not None,
            "--resume": resume,
            "--chunk-size": chunk_size is not None,
        }
        for option, used in given.items():
            if used:
                _fail(f'{option} does not apply to [study] kind = "arrangement" (one process)')
        _arrangement(case, case_file, as_json, out, force)
        return
    executor = None
    if case.study.allocate is not None:
        if out is not None or resume:
            _fail(
                f"{case_file}: study.allocate: an allocation runs its studies in memory; "
                f"{'--out' if out is not None else '--resume'} applies to one study: run "
                "`runout study` with the allocated value to write its files"
            )
        from runout.study.allocate import allocate as allocate_tolerance

        if scheduler is not None:
            executor = dask_executor(None if scheduler == "local" else scheduler)
        with _err.status("allocating", spinner="dots") if _err.is_terminal else nullcontext():
            found = allocate_tolerance(
                case, executor=executor, workers=workers, chunk_size=chunk_size, notify=_note
            )
        summary = found.result.to_json()
        summary["allocated"] = found.to_json()
        if as_json:
            _print_json(summary)
        else:
            _print_allocation(summary, str(case.title or case_file))
        _study_failures(summary)
        return
    if scheduler is not None:
        executor = dask_executor(None if scheduler == "local" else scheduler)
    columns = (
        "[progress.description]{task.description}",
        BarColumn(),
        MofNCompleteColumn(),
        TimeRemainingColumn(),
    )
    with Progress(*columns, console=_err, transient=True, disable=not _err.is_terminal) as bar:
        task = bar.add_task("samples", total=None)

        def tick(done: int, total: int) -> None:
            bar.update(task, completed=done, total=total)

        result = run_study(
            case,
            executor=executor,
            workers=workers,
            out=out,
            resume=resume,
            progress=tick,
            chunk_size=chunk_size,
            force=force,
            notify=_note,
        )
    summary = result.to_json()
    if as_json:
        _print_json(summary)
    else:
        _print_study(summary, str(case.title or case_file), out)
    _study_failures(summary)


def _arrangement(case: Any, case_file: Path, as_json: bool, out: str | None, force: bool) -> None:
    """``runout study`` of ``[study] kind = "arrangement"``: the order of a lot's balls."""
    from runout.io.output_dir import claim, output_directory
    from runout.study.arrangement_study import run_arrangement

    directory = None
    if out is not None:  # refused before the search runs: a refusal costs nothing
        directory = output_directory(out)
        claim(directory, force=force)
    study = run_arrangement(case)
    doc = study.to_json()
    if as_json:
        _print_json(doc)
    else:
        _print_arrangement(doc, str(case.title or case_file))
    if directory is not None:
        written = _write_arrangement(study, case_file, directory)
        if not as_json:
            for path in written:
                _out.print(f"wrote {escape(str(path))}")


def _write_arrangement(study: Any, case_file: Path, directory: Path) -> list[Path]:
    """arrangement.json, arrangement.csv, random_orders.csv and case.toml, all or none."""
    from runout.io.output_dir import staged

    doc = study.to_json()
    with staged(directory) as stage:
        files = {
            "arrangement.json": json.dumps(doc, indent=2, allow_nan=False) + "\n",
            "arrangement.csv": "position,ball,lot_row,diameter_error_um\n"
            + "".join(
                f"{r['position']},{r['ball']},{r['lot_row']},{r['diameter_error_m'] * 1e6:.9g}\n"
                for r in study.positions
            ),
            "random_orders.csv": f"{doc['minimise']['quantity']}_{doc['minimise']['unit']}\n"
            + "".join(f"{v:.9g}\n" for v in study.random_values),
            "case.toml": case_file.read_text(encoding="utf-8"),
        }
        written = []
        for name, text in files.items():
            (stage.path / name).write_text(text, encoding="utf-8")
            written.append(stage.path / name)
        written = [stage.final(p) for p in written]
    return written


def _print_arrangement(doc: dict[str, Any], title: str) -> None:
    """The chosen order, its value predicted and computed, and the random assemblies."""
    from runout.base.display import format_length, length_unit

    goal, arr, rand, check = doc["minimise"], doc["arrangement"], doc["random"], doc["check"]
    what = {
        "lines": "sum of the line p-p",
        "line": f"p-p of the {goal['line']} line",
        "nrro_pp": "NRRO p-p",
        "band": f"Anderon band {goal['band']}",
    }[goal["quantity"]]
    values = [arr["predicted"], check["value"], rand["p5"], rand["p50"], rand["p95"]]
    if goal["unit"] == "m":
        unit = length_unit(values)

        def fmt(value: float) -> str:
            return format_length(value, unit)

    else:

        def fmt(value: float) -> str:
            return f"{value:.4g} Anderon"

    lot = doc["lot"]
    _out.print(
        f"{escape(title)}: {lot['elements']} of {lot['balls']} balls ({escape(lot['file'])}), "
        f"minimising the {what} ({arr['search']} search, {arr['evaluated']} orders)",
        highlight=False,
        soft_wrap=True,
    )
    _out.print(
        "order (position 1 first): " + escape(", ".join(arr["balls"])),
        highlight=False,
        soft_wrap=True,
    )
    table = Table(title_justify="left", header_style="bold")
    for col in ("line", "Hz", "predicted p-p", "model p-p"):
        table.add_column(col, justify="left" if col == "line" else "right")
    for line in arr["lines"]:
        table.add_row(
            escape(line["line"]),
            f"{line['frequency_hz']:.5g}",
            format_length(line["predicted_pp_m"], length_unit([line["predicted_pp_m"]])),
            format_length(line["model_pp_m"], length_unit([line["model_pp_m"]])),
        )
    _out.print(table)
    diff = check["relative_difference"]
    _out.print(
        f"{what}: predicted {fmt(arr['predicted'])}, model {doc['model']} {fmt(check['value'])}"
        + ("" if diff is None else f" ({100 * diff:+.2f} %)"),
        highlight=False,
        soft_wrap=True,
    )
    _out.print(
        f"{rand['orders']} random orders: p5 {fmt(rand['p5'])}, median {fmt(rand['p50'])}, "
        f"p95 {fmt(rand['p95'])}, mean {fmt(rand['mean'])}; "
        f"{100 * rand['fraction_as_good']:.3g} % as good as this order",
        highlight=False,
        soft_wrap=True,
    )
    for note in doc["notes"]:
        _out.print(f"note: {escape(note)}", highlight=False, soft_wrap=True)


def _load_allocating(
    case_file: Path,
    model: str | None,
    sets: list[str] | None,
    allocate: str | None,
    target_yield: float | None,
) -> Any:
    """The case with ``--allocate`` and ``--target-yield`` set as ``study.allocate`` and
    ``study.target_yield`` (a refusal of either names its option)."""
    from runout.base.errors import CaseError

    extra = list(sets or ())
    options = {}
    if allocate is not None:
        extra.append(f"study.allocate={json.dumps(allocate)}")
        options["study.allocate"] = "--allocate"
    if target_yield is not None:
        extra.append(f"study.target_yield={target_yield!r}")
        options["study.target_yield"] = "--target-yield"
    try:
        return _load(case_file, model, extra)
    except CaseError as exc:
        option = options.get(exc.key)
        if option is None or not exc.message.endswith("(given by --set)"):
            raise
        message = exc.message.removesuffix("(given by --set)") + f"(given by {option})"
        raise CaseError(exc.file, exc.key, message) from None


def _print_allocation(summary: dict[str, Any], title: str) -> None:
    """The study at the allocated tolerance, then the allocation in one paragraph."""
    from runout.base.display import format_length, length_unit

    found = summary["allocated"]
    key = found["key"]
    name = next(k for k in found if k not in ("key", "studies") and k.startswith(key))
    _print_study(summary, f"{title} at the allocated {key}", None)

    def value(v: float | None) -> str:
        if v is None:
            return "none"
        if name.endswith("_m"):
            return format_length(v, length_unit([v]))
        return f"{v:.6g}"

    limit = format_length(found["limit_m"], length_unit([found["limit_m"]]))
    low, high = found["ci"]
    _out.print(
        f"allocated: {key} = {value(found[name])}: {found['passed']} of {found['samples']} "
        f"bearings within {limit} on {found['quantity']} ({100 * found['yield']:.1f} %; "
        f"{100 * found['confidence']:.0f} % interval {100 * low:.1f}-{100 * high:.1f} %, "
        f"{found['method']}) for a target of {100 * found['target_yield']:.1f} %; the next "
        f"value tried, {value(found['next_' + name])}, misses it (resolution "
        f"{100 * found['rtol']:g} %, {len(found['studies'])} studies of the same "
        f"{found['samples']} bearings, seed {found['seed']})",
        soft_wrap=True,
        highlight=False,
    )
    for text in found["notes"]:
        _out.print(f"note: {escape(text)}", soft_wrap=True, highlight=False)


def _study_failures(summary: dict[str, Any]) -> None:
    """Say how many samples failed; exit 1 when all did (the statistics are empty)."""
    failed, total = summary["failed"], summary["samples"]
    if not failed:
        return
    word = "samples" if summary["kind"] == "montecarlo" else "points"
    first = summary["errors"][0]
    example = f"{word[:-1]} {first['sample']}: {first['error']}"
    if failed == total:
        _err.print(
            f"[bold red]error:[/] all {total} {word} failed ({escape(example)})",
            highlight=False,
            soft_wrap=True,
        )
        raise typer.Exit(1)
    _note(
        f"{failed} of {total} {word} failed and are left out of the statistics (first: {example})"
    )


def _print_study(summary: dict[str, Any], title: str, out: str | None) -> None:
    """The study's statistics in one length unit chosen over the figures shown."""
    from runout.base.display import format_length, length_unit

    comps = summary["components"][:20]
    stat_keys = ("mean", "std", "p5", "p50", "p95")
    shown = [stats[k] for stats in summary["runout"].values() for k in stat_keys]
    shown += [comp["pp_m"][k] for comp in comps for k in stat_keys]
    unit = length_unit(v for v in shown if v is not None)
    table = Table(
        title=f"{title}: {summary['kind']} of {summary['samples']} samples"
        f" ({summary['failed']} failed)",
        title_justify="left",
        header_style="bold",
    )
    columns = ("quantity", "Hz", *(f"{k} [{unit[0]}]" for k in stat_keys))
    for col in columns:
        table.add_column(escape(col), justify="left" if col == "quantity" else "right")

    def fmt(value: float | None) -> str:
        # None: no sample gave the figure (failed, or not a quantity of the model): not 0
        return "n/a" if value is None else format_length(value, unit).rsplit(" ", 1)[0]

    for name, stats in summary["runout"].items():
        table.add_row(escape(name), "", *(fmt(stats[k]) for k in stat_keys))
    for comp in comps:
        table.add_row(
            escape(f"{comp['direction']} {comp['label']}"[:70]),
            f"{comp['frequency_hz']:.5g}",
            *(fmt(comp["pp_m"][k]) for k in stat_keys),
        )
    _out.print(table)
    source = summary.get("bearing_sources", summary.get("bearing_source"))
    for entry in source if isinstance(source, list) else [source] if source else []:
        provenance = "; ".join(f"{k}: {v}" for k, v in entry["provenance"].items())
        _out.print(
            f"bearing {entry['designation']} from the {entry['catalogue']} catalogue "
            f"({provenance})",
            soft_wrap=True,
            highlight=False,
        )
    for grade in summary.get("ball_grades", []):  # the sigma a ball grade drew with
        sigma = format_length(grade["sigma_m"], length_unit([grade["sigma_m"]]))
        form = ""
        if "form_order" in grade:  # each ball's form drawn too ([elements] grade_form_order)
            bound = grade["form_amplitude_max_m"]
            form = (
                f", each ball's form {grade['form_order']} lobes up to "
                f"{format_length(bound, length_unit([bound]))} (0-peak)"
            )
        _out.print(
            f"ball grade {grade['grade']} ({grade['key']}): ball diameter sigma {sigma}{form} "
            f"({grade['source']})",
            soft_wrap=True,
            highlight=False,
        )
    lot = summary.get("yield")
    if lot is not None:
        limit = format_length(lot["limit_m"], length_unit([lot["limit_m"]]))
        if "class" in lot:  # K_ia of an ISO 492 tolerance class for the bore
            limit += f" (ISO 492 class {lot['class']}, bore {lot['bore_m'] * 1e3:g} mm)"
        if lot["fraction"] is None:
            _out.print(f"yield: no sample succeeded (limit {limit} on {lot['quantity']})")
        else:
            _out.print(
                f"yield: {lot['passed']} of {lot['samples']} bearings within {limit} on "
                f"{lot['quantity']} ({100 * lot['fraction']:.1f} %; "
                f"{100 * lot['confidence']:.0f} % interval {100 * lot['ci_low']:.1f}-"
                f"{100 * lot['ci_high']:.1f} %, {lot['method']})",
                soft_wrap=True,
                highlight=False,
            )
    for note in summary.get("notes", []):  # a streaming study: what it changes
        _out.print(f"note: {escape(note)}", soft_wrap=True, highlight=False)
    if out is not None:
        files = "manifest.json, chunks/, summary.json"
        if (Path(out) / "samples.csv").is_file():  # not written by streaming statistics
            files += ", samples.csv, samples_columns.json"
        if (Path(out) / "stiffness.csv").is_file():  # equilibrium: the stiffness of every point
            files += ", stiffness.csv"
            _out.print(_damping_line(Path(out) / "stiffness.csv"), soft_wrap=True, highlight=False)
        # the figures (histograms.png, sweep_*.png: a fresh run removed any earlier ones)
        figures = sorted(p.name for p in Path(out).glob("*.png") if _STUDY_FIGURE.match(p.name))
        files += "".join(f", {name}" for name in figures)
        _out.print(f"wrote {escape(out)}/ ({files})")


_STUDY_FIGURE = re.compile(r"histograms\.png|sweep_.+\.png")


def _damping_line(path: Path) -> str:
    """What ``stiffness.csv`` says of damping: its model(s) and β, or that it has none."""
    with path.open(newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    if not rows or "bearing_damping" not in rows[0]:
        return (
            "stiffness.csv: stiffness only, no damping columns ([analysis] bearing_damping = "
            '"none"; "kraemer" or "proportional" add cxx ... czz)'
        )
    models = sorted({(r["bearing_damping"], r["bearing_damping_coefficient_s"]) for r in rows})
    named = ", ".join(f'"{m}" (β = {float(b):.3g} s)' for m, b in models)
    kraemer = any(m == "kraemer" for m, _ in models)
    estimate = "; Krämer's estimate, not a measurement" if kraemer else ""
    return f"stiffness.csv: damping c = β k, every coefficient; bearing_damping = {named}{estimate}"


@app.command("reproduce")
@_guard
def reproduce_command(
    only: Annotated[
        str | None,
        typer.Option(
            "--only",
            help="Comma-separated sections (kinematics, contact, spectrum, linear, roller, "
            "dynamic, quasi_static, life, diagnosis, envelope, studies, defects, mcfadden_smith); "
            "default all. An existing document keeps its other sections.",
        ),
    ] = None,
    out: Annotated[
        Path,
        typer.Option(
            "--out",
            help="Where to write the document (never over a file runout reproduce did not "
            "write, never through a link).",
        ),
    ] = Path("VALIDATION.md"),
    check_only: Annotated[
        bool,
        typer.Option(
            "--check", help="Compare with the existing file instead of writing; exit 1 if stale."
        ),
    ] = False,
) -> None:
    """Run every reproducible table and figure of the seed papers and write VALIDATION.md.

    Example: runout reproduce --only kinematics,contact --check
    """
    from rich.progress import Progress

    from runout.validation import reproduce as rp

    sections = None if only is None else [s.strip() for s in only.split(",") if s.strip()]
    with Progress(console=_err, transient=True) as bar:
        task = bar.add_task("reproduce", total=len(sections or rp.section_keys()))

        def tick(title: str, done: int, total: int) -> None:
            bar.update(task, completed=done, total=total, description=title[:50])

        doc = rp.build(sections, progress=tick)
    if check_only:
        if not out.exists():
            _fail(f"{out} does not exist")
        existing = out.read_text(encoding="utf-8")
        if sections is not None:
            blocks = rp.split_sections(existing)
            fresh_blocks = rp.split_sections(doc.text)
            existing = "\n".join(blocks.get(t, "").rstrip() for t in fresh_blocks if t)
            fresh = "\n".join(b.rstrip() for t, b in fresh_blocks.items() if t)
        else:
            fresh = doc.text
        problems = rp.compare(fresh, existing)
        _out.print(doc.summary())
        if problems:
            _err.print(f"{escape(str(out))} is stale: {len(problems)} difference(s)")
            for p in problems[:20]:
                _err.print(escape(p), soft_wrap=True)
            raise typer.Exit(1)
        _out.print(f"{escape(str(out))} is up to date")
        return
    text = doc.text
    if out.is_symlink():
        _fail(f"{out}: a symbolic link; runout does not write through links (choose another --out)")
    if out.exists():
        existing = out.read_text(encoding="utf-8", errors="replace") if out.is_file() else ""
        if rp.GENERATED_MARK not in existing:
            _fail(
                f"{out}: exists and was not written by runout reproduce, which replaces only its "
                "own document (move it away or choose another --out)"
            )
        if sections is not None:  # the other sections stay as they are
            text = rp.merge_sections(existing, doc.text)
    out.write_text(text, encoding="utf-8")
    _out.print(doc.summary())
    _out.print(f"wrote {escape(str(out))}")


@app.command("warm")
@_guard
def warm_command() -> None:
    """Compile every model's kernels for this machine now, so that no later command waits.

    Each model's first command after an installation compiles its kernels (a few seconds,
    said on stderr); this runs one example of every model, and a study, to do it ahead.
    `make install` runs it. Example: runout warm
    """
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from runout.cli.warm import WARM_CASES, WarmError, warm

    with Progress(
        TextColumn("{task.description}"), BarColumn(), TimeElapsedColumn(), console=_err
    ) as bar:
        task = bar.add_task("compiling", total=len(WARM_CASES))

        def on_case(model: str, name: str, seconds: float | None) -> None:
            if seconds is None:
                bar.update(task, description=f"compiling the {model} kernels ({name})")
            else:
                bar.advance(task)

        try:
            times = warm(on_case=on_case)
        except WarmError as exc:
            bar.stop()
            _fail(str(exc), 1)
            return
        bar.update(task, description="compiled")
    for model, seconds in times:
        _out.print(f"compiled the {escape(model)} kernels ({seconds:.1f} s)", highlight=False)


# `runout diagnose` lives in its own module (the inverse of the linear model)
from runout.cli.diagnose import register as _register_diagnose  # noqa: E402

_register_diagnose(app)

# `runout catalogue`: the bearing catalogue behind [bearing] designation
from runout.cli.catalogue import register as _register_catalogue  # noqa: E402

_register_catalogue(app)


def main() -> None:
    """Console-script entry point.

    The command's exit status is final once it returns: the streams are flushed and the
    ``atexit`` handlers run (logging, Dask, temporary files), then the process ends without
    the interpreter's teardown of every module, which frees Numba's and LLVM's compiled code
    object by object (about 0.2 s of every command). Should a non-daemon thread still run, the
    interpreter exits the usual way and waits for it; ``python -m runout.cli`` (under a
    profiler, say) always does.
    """
    if _writes_files(sys.argv[1:]):
        # parsing the arguments takes 0.15-0.2 s (Typer, pydantic): the processes that draw
        # `run --out`'s figures import matplotlib meanwhile, so that they are ready when a quick
        # model's result is
        _EARLY_WORKERS.append(_figure_workers())
    try:
        app()
        code: object = 0
    except SystemExit as exc:
        code = exc.code
    finally:
        for unused in _EARLY_WORKERS:  # the command never ran (a usage error, --help)
            unused.close()
    _exit(code)


def _exit(code: object) -> NoReturn:
    """End the process with ``code`` as ``SystemExit`` would, without the interpreter's teardown."""
    import atexit
    import threading

    main = threading.main_thread()
    if any(t is not main and t.is_alive() and not t.daemon for t in threading.enumerate()):
        raise SystemExit(code)
    if code is None:
        status = 0
    elif isinstance(code, int):
        status = code
    else:  # SystemExit("message"): printed to stderr, status 1
        print(code, file=sys.stderr)
        status = 1
    for stream in (sys.stdout, sys.stderr):
        try:
            if stream is not None:  # None: started with the stream closed
                stream.flush()
        except (OSError, ValueError):  # a closed pipe or a full disk: the output is gone
            status = status or 1
    atexit._run_exitfuncs()
    os._exit(status)
