"""`govopt study run|export|show`: batch trade studies, one row per point in an SQLite
database; export, plot and summarise it. `govopt study SPEC ...` is `govopt study run SPEC ...`
(:func:`govopt.cli.main`)."""

import contextlib
from pathlib import Path
from typing import Annotated

import typer

from . import common
from .common import FORCE_HELP, ChecksFailed, State, echo, fail, guarded, rich_text

STUDY_SHORT = ("Batch trade studies: sweep a spec's inputs, one row per point in an SQLite "
               "database; export, plot and summarise it.")
STUDY_HELP = STUDY_SHORT + " `govopt study SPEC ...` is `govopt study run SPEC ...`."
RUN_HELP = "Run a trade study: the spec at every point of the sweeps (or tolerance samples)."
EXPORT_HELP = "Export a study's table from its database (CSV, Parquet or xlsx)."
SHOW_HELP = ("Summarise a study: progress, status counts, the best points in the spec's units, "
             "Pareto front, tolerances.")

app = typer.Typer(name="study", add_completion=False, help=STUDY_HELP, short_help=STUDY_SHORT,
                  invoke_without_command=True)


@app.callback()
def study(ctx: typer.Context) -> None:
    if ctx.invoked_subcommand is None:  # `govopt study`: its help, exit code 2 (nothing ran)
        echo(ctx.get_help())
        raise SystemExit(2)


@app.command("run", help=RUN_HELP, short_help=RUN_HELP)
@guarded
def study_run(
        spec: Annotated[Path, typer.Argument(
            metavar="spec", show_default=False,
            help=rich_text("Spec file; its [study] table, if any, is the study's default."))],
        sweep: Annotated[list[str] | None, common.option(
            "--sweep", help="KEY=START:STOP:NUM (with units: 'design.pendulum_weight=6 kgf:12 "
            "kgf:4') or KEY=v1,v2,...; repeat for more keys.")] = None,
        grid: Annotated[bool, common.flag("--grid", help="Every combination (default).")]
        = False,
        zip_: Annotated[bool, common.flag("--zip", help="The sweeps' values taken in step.")]
        = False,
        lhs: Annotated[int | None, common.option(
            "--lhs", metavar="<int>", help="N Latin-hypercube samples.")] = None,
        sobol: Annotated[int | None, common.option(
            "--sobol", metavar="<int>", help="N scrambled Sobol' samples.")] = None,
        seed: Annotated[int | None, common.option(
            "--seed", metavar="<int>", help="Seed of the samplers.")] = None,
        mode: Annotated[str | None, common.option(
            "--mode", help="'evaluate' the spec's design at each point, or 'design' one "
            "(default: evaluate if the spec has a [design]).")] = None,
        tolerance: Annotated[list[str] | None, common.option(
            "--tolerance", help="KEY=±X% (or '±X unit', 'uniform ±X%'; grade=1|2|3 for EN "
            "15800): sample manufacturing scatter around the spec's design.")] = None,
        samples: Annotated[int | None, common.option(
            "--samples", metavar="<int>", help="Samples of a tolerance study (1000).")] = None,
        pareto: Annotated[str | None, common.option(
            "--pareto", help="Two or three objectives for a Pareto front, e.g. "
            "'moving_mass,settling_time' (or column names; 'max:' to maximise).")] = None,
        skip: Annotated[str | None, common.option(
            "--skip", help="Analyses to leave out in evaluate mode: dynamics, vibration, "
            "classic.")] = None,
        db: Annotated[str | None, common.option(
            "--db", metavar="<path>",
            help="The study's SQLite database (default: <spec>.study.db here).")] = None,
        out: Annotated[str | None, common.option(
            "--out", metavar="<path>", help="Export the table: .csv, .parquet or .xlsx.")]
        = None,
        workers: Annotated[int, common.option(
            "--workers", metavar="<int>", help="Processes (a pool; Dask workers).")] = 1,
        dask: Annotated[str | None, common.option(
            "--dask", help="'local' (a LocalCluster of --workers processes) or a scheduler "
            "tcp://HOST:PORT.")] = None,
        resume: Annotated[bool, common.flag(
            "--resume/--no-resume", help="Skip the points already in --db.")] = False,
        plot: Annotated[Path | None, common.option(
            "--plot", "--plots", metavar="<path>",
            help="Write the study's plots (PNG and SVG) into this folder.")] = None,
        chunk: Annotated[int | None, common.option(
            "--chunk", metavar="<int>", help="Points per chunk and database transaction "
            "(default 1024 evaluate, 1 design).")] = None,
        force: Annotated[bool, common.flag("--force", help=FORCE_HELP)] = False) -> None:
    """Run a trade study: the spec at every point of the sweeps (or tolerance samples)."""
    from ..report.files import check_output
    from ..study import load_study, outcome, run_study
    from ..study.sampling import check_seed

    chosen = [name for name, on in (("grid", grid), ("zip", zip_), ("lhs", lhs is not None),
                                    ("sobol", sobol is not None)) if on]
    if len(chosen) > 1:
        fail(f"choose one of --grid, --zip, --lhs, --sobol (got {', '.join(chosen)})")
    for name, value in (("--lhs", lhs), ("--sobol", sobol), ("--samples", samples),
                        ("--workers", workers), ("--chunk", chunk)):
        if value is not None and value < 1:
            fail(f"{name}: expected a whole number >= 1, got {value}")
    if seed is not None:
        check_seed(seed, "--seed")
    study = load_study(spec, sweeps=sweep or (), tolerances=tolerance or (),
                       combine=chosen[0] if chosen else None,
                       samples=lhs if lhs is not None else sobol if sobol is not None else samples,
                       seed=seed, mode=mode, skip=skip, pareto=pareto)
    db = Path(f"{spec.stem}.study.db") if db is None else db
    if out is not None:
        check_output(out, overwrite=force, inputs=[spec], databases=[db], what="study table")
    if plot is not None:
        from ..report.study_plots import check_plot_folder

        check_plot_folder(plot)
    bar = progress_bar()
    try:
        with sigterm_stops():
            report = run_study(study, db, workers=workers, dask=dask, resume=resume,
                               fresh=force and not resume, chunk=chunk, progress=bar)
    finally:
        if bar is not None:
            bar.close()
    for note in report.notes:
        echo(f"note: {note}", err=True)
    study_outputs(db, out, plot, force)
    code, line = _outcome(db, report, outcome)
    if line:
        echo(line, err=True)
    if code:
        raise ChecksFailed if code == 1 else SystemExit(
            State.terminated if report.interrupted and State.terminated else code)


@contextlib.contextmanager
def sigterm_stops():
    """Within this block, SIGTERM stops a study as Ctrl-C does (the blocks done are kept, the
    summary and how to resume are printed), exiting 128 + SIGTERM; only where the process's
    SIGTERM is govopt's own (the console script's), never a host's."""
    import signal

    from ..cli import on_sigterm

    if signal.getsignal(signal.SIGTERM) is not on_sigterm:
        yield
        return

    def stop(signum, frame):
        signal.signal(signal.SIGTERM, signal.SIG_IGN)  # a second one while stopping: ignored
        State.terminated = 128 + signum
        raise KeyboardInterrupt

    signal.signal(signal.SIGTERM, stop)
    try:
        yield
    finally:
        if signal.getsignal(signal.SIGTERM) is stop:
            signal.signal(signal.SIGTERM, on_sigterm)


def _outcome(db, report, outcome):
    """0; 1 every point failed; 2 none ran; 130 interrupted (:func:`govopt.study.outcome`)."""
    from ..study import Store

    with Store(db, create=False) as store:
        return outcome(store, report)


def study_outputs(db: Path, out: Path | None, plot: Path | None, force: bool) -> None:
    """The summary, and the table and plots where asked for."""
    from ..study import Store, summary_text

    with Store(db, create=False) as store:
        echo(summary_text(store))
        write_outputs(store, out, plot, force)


def write_outputs(store, out, plot, force: bool) -> None:
    """The table (CSV, Parquet, or the workbook) and the plots of the study in ``store``."""
    if out is not None:
        if Path(out).suffix.lower() == ".xlsx":
            from ..report.study_workbook import write_workbook

            written = write_workbook(store, out, overwrite=force)
        else:
            from ..study import export

            written = export(store, out, overwrite=force)
        echo(f"wrote {written}")
    if plot is not None:
        from ..report.study_plots import plot_study

        for path in plot_study(store, plot, overwrite=force):
            echo(f"wrote {path}")


def progress_bar():
    """A rich progress bar on stderr (points done, failures, ETA) when it is a terminal: a
    callable ``(done, failures, total)`` with ``close()``; else None."""
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    console = Console(stderr=True)
    if not console.is_terminal:
        return None
    bar = Progress(TextColumn("study"), BarColumn(), MofNCompleteColumn(),
                   TextColumn("failures {task.fields[failures]}"), TimeElapsedColumn(),
                   TextColumn("ETA"), TimeRemainingColumn(), console=console, transient=True)

    class Bar:
        task = None

        def __call__(self, done: int, failures: int, total: int) -> None:
            if self.task is None:
                bar.start()
                self.task = bar.add_task("study", total=total, completed=done, failures=failures)
            bar.update(self.task, completed=done, failures=failures)

        def close(self) -> None:
            bar.stop()

    return Bar()


@app.command("export", help=EXPORT_HELP, short_help=EXPORT_HELP)
@guarded
def study_export(
        db: Annotated[Path, typer.Argument(metavar="db", show_default=False,
                                           help="The study's database.")],
        out: Annotated[str, common.option(
            "--out", metavar="<path>", help="A .csv, .parquet or .xlsx file.")],
        plot: Annotated[Path | None, common.option(
            "--plot", "--plots", metavar="<path>", help="Also write the plots into this folder.")]
        = None,
        force: Annotated[bool, common.flag("--force", help=FORCE_HELP)] = False) -> None:
    """Export a study's table from its database (CSV, Parquet or xlsx)."""
    from ..report.files import check_output
    from ..study import Store

    check_output(out, overwrite=force, databases=[db], what="study table")
    with Store(db, create=False) as store:
        write_outputs(store, out, plot, force)


@app.command("show", help=SHOW_HELP, short_help=SHOW_HELP)
@guarded
def study_show(db: Annotated[Path, typer.Argument(metavar="db", show_default=False,
                                                  help="The study's database.")]) -> None:
    """Summarise a study: progress, status counts, best points, Pareto front, tolerances."""
    from ..study import Store, summary_text

    with Store(db, create=False) as store:
        echo(summary_text(store))
