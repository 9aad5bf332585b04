"""Command-line interface: parses arguments, calls the API, prints. No physics here.

The standard library's argparse parses (docs/decisions.md, imports on demand): typer builds
every parameter through pydantic, ~0.1 s of CPU before any command ran. A command's own imports
come when it runs; rich only where the reports and the study's progress bar draw with it.
"""

from __future__ import annotations

import argparse
import functools
import json
import os
import re
import signal
import sys
import warnings
from pathlib import Path

from .errors import GovoptError
from .examples import SPECS
from .limits import printable, shorten_values

DEFAULT_EVALUATE = SPECS / "hamabe-a.toml"
DEFAULT_DESIGN = SPECS / "hamabe-design.toml"

_DEBUG = False  # set by main from --debug / GOVOPT_DEBUG
_ANSI = re.compile(r"\033\[[;?0-9]*[a-zA-Z]")  # an escape sequence, stripped when not a terminal


def _echo(text: str, err: bool = False) -> None:
    """Print a line to stdout (stderr with ``err``), flushed; escape sequences are kept only
    on a terminal (as click's ``echo`` did: a spec's name may carry them)."""
    stream = sys.stderr if err else sys.stdout
    if not stream.isatty():
        text = _ANSI.sub("", text)
    print(text, file=stream, flush=True)


def _fail(message: str) -> None:
    """A user's error: one line ``error: ...`` on stderr, exit code 2."""
    _echo(f"error: {printable(shorten_values(message))}", err=True)
    raise SystemExit(2)


def _internal(exc: BaseException) -> None:
    """One line for an unexpected exception: a bug, to be reported; exit code 3."""
    text = " ".join(str(exc).split())
    text = text if len(text) <= 200 else text[:197] + "..."
    _echo(f"internal error: {type(exc).__name__}: {printable(text)} -- this is a bug in "
          "govopt, please report it (run with --debug to see the traceback)", err=True)


class _ChecksFailed(Exception):
    """The command ran and printed its result, and some of the design's checks failed."""


def _guarded(command):
    """Run a command so that it never shows a traceback: a user's error (GovoptError) is one
    line and exit 2, anything unexpected one line, "please report" and exit 3 (``--debug``
    re-raises); a result whose checks fail exits 1. Warnings are held and shown one line each
    only if the command ran to its end (exit 0 or 1)."""

    @functools.wraps(command)
    def run(*args, **kwargs):
        debug, out, failed = _DEBUG, None, False
        with warnings.catch_warnings(record=not debug) as caught:
            try:
                out = command(*args, **kwargs)
            except _ChecksFailed:
                failed = True
            except BrokenPipeError:
                raise
            except GovoptError as exc:
                _fail(str(exc))
            except Exception as exc:
                if debug:
                    raise
                _internal(exc)
                raise SystemExit(3) from None
        for message in dict.fromkeys(str(w.message) for w in caught or ()):
            _echo(f"warning: {printable(message)}", err=True)
        if failed:
            raise SystemExit(1)
        return out

    return run


def _load(spec: Path | None, default: Path, **analysis):
    from .spec import load_spec

    s = load_spec(spec or default)
    changes = {k: v for k, v in analysis.items() if v is not None}
    return s.with_analysis(**changes) if changes else s


@_guarded
def evaluate(*, spec, geometry, json_out, xlsx, force, plots, full, section) -> None:
    """Evaluate the spec's design (default: the bundled Hamabe case a). Exit code 0: every
    check passed; 1: some check failed; 2: bad input."""
    from .evaluation import evaluate as run

    if geometry is not None and geometry not in ("exact", "series"):
        _fail(f"--geometry: expected 'exact' or 'series', got {geometry!r}")
    _run_and_report(lambda: run(_load(spec, DEFAULT_EVALUATE, geometry=geometry)), json_out,
                    spec or DEFAULT_EVALUATE, xlsx=xlsx, force=force, plots=plots,
                    sections=_sections(full, section))


@_guarded
def design(*, spec, json_out, output, xlsx, force, plots, full, section) -> None:
    """Find the best design for the spec's requirements (default: bundled hamabe-design).
    Files are written only where asked (-o, --xlsx, --plots), as by evaluate."""
    from .optimize.search import design as run

    _run_and_report(lambda: run(_load(spec, DEFAULT_DESIGN)), json_out, spec or DEFAULT_DESIGN,
                    xlsx=xlsx, output=output, force=force, plots=plots,
                    sections=_sections(full, section))


def _sections(full: bool, section: list[str] | None) -> list[str] | None:
    """The report's sections: the answer (``summary``) by default, all with ``--full``, the
    named ones with ``--section`` (names checked: a wrong one is exit 2)."""
    from .report.text import SECTIONS

    if full and section:
        _fail("--full and --section: choose one (--full prints every section)")
    if full:
        return None
    names = [n.strip() for s in section or () for n in s.split(",") if n.strip()]
    for name in names:
        if name not in SECTIONS:
            import difflib

            close = difflib.get_close_matches(name, SECTIONS, n=1)
            _fail(f"--section: expected one of {', '.join(SECTIONS)}, got {name!r}"
                  + (f" (did you mean {close[0]!r}?)" if close else ""))
    return names or ["summary"]


def _run_and_report(compute, json_out: bool, spec: Path, xlsx: Path | None = None,
                    output: Path | None = None, force: bool = False, plots: Path | None = None,
                    sections: list[str] | None = None) -> None:
    """Check the outputs, compute a Result, write the requested files, print it and say what
    was written where (on stderr with ``--json``); a user's error (GovoptError) exits 2 and a
    result with failed checks 1, through :func:`_guarded`."""
    from .report.files import check_output, drawn_design, overwrite_policy, write_design_spec
    from .report.text import format_result

    outputs = [(p, what, force)
               for p, what in ((output, "design spec"), (xlsx, "workbook")) if p is not None]
    for p, what, overwrite in outputs:  # before the run: fail in a second, not after it
        check_output(p, overwrite=overwrite, inputs=[spec], what=what,
                     others=[q for q, _, _ in outputs if q is not p])
    if plots is not None:  # the folder, and no plot replaced without --force
        from .report.plot_files import check_plot_dir, write_plots

        check_plot_dir(plots, spec.stem, overwrite=force, inputs=[spec],
                       others=[p for p, _, _ in outputs])
    res = compute()
    if output is not None:  # rounded as drawn, and evaluated again: the report is its
        text, res, _ = drawn_design(res)
        write_design_spec(res, output, overwrite=force, text=text)
    if xlsx is not None:
        from .report.excel import write_workbook

        with overwrite_policy(force):
            write_workbook(res, xlsx)
    drawn = [] if plots is None else write_plots(res, plots, stem=spec.stem, overwrite=force)
    _echo(json.dumps(res.to_dict(), indent=2) if json_out else format_result(res,
                                                                              sections=sections))
    for path in (output, xlsx, *drawn):
        if path is not None:
            _echo(f"wrote {Path(path).absolute()}", err=json_out)
    _exit_on_failed_checks(res, json_out)


def _exit_on_failed_checks(res, json_out: bool) -> None:
    """Exit code 1 (after the report) when any of the result's checks failed."""
    failed = [c.name for c in res.checks if not c.passed]
    if failed:
        if not json_out:
            _echo(f"{len(failed)} of {len(res.checks)} checks failed: {'; '.join(failed)}",
                  err=True)
        raise _ChecksFailed


def _q(text: str | None, dimension: str, option: str, positive: bool = True):
    from .units import UnitError, parse_quantity

    if text is None:
        return None
    try:
        value = parse_quantity(text, dimension)
    except UnitError as exc:
        _fail(f"{option}: {exc}")
    if value < 0 or (positive and value == 0):
        _fail(f"{option}: must be {'positive' if positive else 'zero or more'}, got {text!r}")
    return value


@_guarded
def spring(*, spec, json_out, xlsx, plots, replace, **options) -> None:
    """Least-mass helical spring for a force and stiffness (an exact GP, certified global),
    from the options, a spring spec file or both (the options override the file); with
    --material the wire grade's allowables per diameter and the spring maker's checks."""
    from .spring_command import run

    out = run(spec, json_out=json_out, xlsx=xlsx, plots=plots, replace=replace, **options)
    _echo(out.text)
    for path in out.written:
        _echo(f"wrote {Path(path).absolute()}", err=json_out)
    if out.failed:  # as evaluate: the spring is reported, and exit code 1 says a check failed
        _echo(f"{len(out.failed)} of {out.total} checks failed: {'; '.join(out.failed)}",
              err=True)
        raise _ChecksFailed


@_guarded
def bench(*, quick, out, targets, force) -> None:
    """Speed against error of every analysis (one point per method and setting, errors
    against high-precision references) and the speed targets beside what was measured."""
    from .report import bench as b

    if out is not None:  # before the benchmark: fail in a second, not after it
        b.check_report(out, overwrite=force)

    def log(message: str) -> None:
        _echo(f"  {message}", err=True)

    rows = b.targets(quick, log=log) if targets else None
    points = b.speed_vs_error(quick, log=log)
    _echo(b.summary(points, rows))
    if out is not None:
        for path in b.write_report(points, out, rows, overwrite=force):
            _echo(f"wrote {Path(path).absolute()}")


@_guarded
def study_run(*, spec, sweep, grid, zip_, lhs, sobol, seed, mode, tolerance, samples, pareto,
              skip, db, out, workers, dask, resume, plot, chunk, force) -> None:
    """Run a trade study: the spec at every point of the sweeps (or tolerance samples)."""
    from .report.files import check_output
    from .study import load_study, outcome, run_study

    chosen = [name for name, on in (("grid", grid), ("zip", zip_), ("lhs", lhs is not None),
                                    ("sobol", sobol is not None)) if on]
    if len(chosen) > 1:
        _fail(f"choose one of --grid, --zip, --lhs, --sobol (got {', '.join(chosen)})")
    if workers < 1 or (chunk is not None and chunk < 1):
        _fail("--workers and --chunk must be at least 1")
    study = load_study(spec, sweeps=sweep or (), tolerances=tolerance or (),
                       combine=chosen[0] if chosen else None,
                       samples=lhs if lhs is not None else sobol if sobol is not None else samples,
                       seed=seed, mode=mode, skip=skip, pareto=pareto)
    db = Path(f"{spec.stem}.study.db") if db is None else db
    if out is not None:
        check_output(out, overwrite=force, inputs=[spec, db], what="study table")
    if plot is not None:
        from .report.study_plots import check_plot_folder

        check_plot_folder(plot)
    bar = _progress_bar()
    try:
        report = run_study(study, db, workers=workers, dask=dask, resume=resume,
                           fresh=force and not resume, chunk=chunk, progress=bar)
    finally:
        if bar is not None:
            bar.close()
    _study_outputs(db, out, plot, force)
    code, line = outcome(db, report)  # 0; 1 every point failed; 2 none ran; 130 interrupted
    if line:
        _echo(line, err=True)
    if code:
        raise _ChecksFailed if code == 1 else SystemExit(code)


def _study_outputs(db: Path, out: Path | None, plot: Path | None, force: bool) -> None:
    from .study import Store, export, summary_text

    with Store(db, create=False) as store:
        _echo(summary_text(store))
        if out is not None:
            _echo(f"wrote {Path(export(store, out, overwrite=force)).absolute()}")
        if plot is not None:
            from .report.study_plots import plot_study

            for path in plot_study(store, plot, overwrite=force):
                _echo(f"wrote {Path(path).absolute()}")


def _progress_bar():
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


@_guarded
def study_export(*, db, out, plot, force) -> None:
    """Export a study's table from its database (CSV, Parquet or xlsx)."""
    from .report.files import check_output
    from .study import Store, export

    check_output(out, overwrite=force, inputs=[db], what="study table")
    with Store(db, create=False) as store:
        _echo(f"wrote {Path(export(store, out, overwrite=force)).absolute()}")
        if plot is not None:
            from .report.study_plots import plot_study

            for path in plot_study(store, plot, overwrite=force):
                _echo(f"wrote {Path(path).absolute()}")


@_guarded
def study_show(*, db) -> None:
    """Summarise a study: progress, status counts, best point, Pareto front, tolerances."""
    from .study import Store, summary_text

    with Store(db, create=False) as store:
        _echo(summary_text(store))


@_guarded
def examples_command() -> None:
    """List the bundled example specs.

    `govopt init NAME` copies one to start from."""
    from .examples import description, examples

    found = examples()
    width = max(map(len, found))
    for name, path in found.items():
        _echo(f"{name:<{width}}  {description(path)}")


@_guarded
def init_command(*, name, output, force) -> None:
    """Copy a bundled example spec here, to start from.

    E.g. `govopt init hamabe-a` writes hamabe-a.toml in the current folder."""
    import tomllib

    from .examples import example
    from .report.files import atomic_write, check_output, names_folder, output_folder

    source = example(name)
    target = Path(output) if output is not None else Path(source.name)
    if names_folder(output):  # 'DIR/new/': a folder, made if only its parent exists
        target = output_folder(target, "the spec") / source.name
    elif target.is_dir():
        target = target / source.name
    check_output(target, overwrite=force, inputs=[source], what="spec")
    data = source.read_bytes()
    atomic_write(target, lambda tmp: tmp.write_bytes(data), overwrite=force, what="spec")
    table = tomllib.loads(data.decode("utf-8"))
    command = ("study" if "study" in table else "spring" if "spring" in table and
               "governor" not in table else "evaluate" if "design" in table else "design")
    _echo(f"wrote {target.absolute()} (the bundled {source.stem}); edit it, then: "
          f"govopt {command} {target}")


# ------------------------------------------------------------------------------------------
# the parser


class _Parser(argparse.ArgumentParser):
    """argparse with govopt's conventions: a bad command line is one line ``error: ...`` and
    exit code 2 (as every user's error), and an option's value is the next word whatever it
    starts with (``--min-force -1e3N`` is a value, as click read it, not an unknown option);
    no abbreviated options (``--geo`` is not ``--geometry``); a command names the words it does
    not know itself (its help is where to look)."""

    command = False  # a command's own parser (set by _command)

    def __init__(self, *args, allow_abbrev: bool = False, **kw):
        super().__init__(*args, allow_abbrev=allow_abbrev, **kw)

    def error(self, message: str) -> None:
        _fail(f"{message} (see '{self.prog} --help')")

    def parse_known_args(self, args=None, namespace=None):
        takes = {s for a in self._actions if a.nargs is None for s in a.option_strings}
        words, out = list(sys.argv[1:] if args is None else args), []
        while words:
            word = words.pop(0)
            if word == "--":
                out += [word, *words]
                break
            glued = word in takes and words and words[0].startswith("-")
            out.append(f"{word}={words.pop(0)}" if glued else word)
        namespace, extras = super().parse_known_args(out, namespace)
        if extras and self.command:
            self.error(f"unrecognized arguments: {' '.join(extras)}")
        return namespace, extras


def _typed(text: str) -> str:
    """An output file's path as typed: text, not a Path, so that a trailing '/' (a folder,
    which a Path drops) reaches the output checks (:func:`govopt.report.files.check_output`)."""
    return text


#: the metavar of each option's type, as `govopt X --help` shows it (`--xlsx <path>`)
_METAVAR = {str: "<str>", Path: "<path>", _typed: "<path>", int: "<int>", float: "<float>"}
_FORCE_HELP = "Replace output files that exist (regular files only, never the spec)."
_JSON_HELP = "Print a JSON object in SI units."


def _option(p, *names, help: str, type=str, default=None, **kw) -> None:
    """An option that takes a value; its default, if any, is shown after its help."""
    help = help.replace("%", "%%") + ("" if default is None else " (default: %(default)s)")
    help += " (required)" if kw.get("required") else ""
    p.add_argument(*names, type=type, default=default, metavar=_METAVAR[type], help=help, **kw)


def _flag(p, *names, help: str, switch: bool | None = None, **kw) -> None:
    """A flag (``--json``); with ``switch`` its ``--no-`` twin too, ``switch`` the default."""
    if switch is None:
        p.add_argument(*names, action="store_true", help=help, **kw)
    else:
        default = names[0] if switch else "--no-" + names[0][2:]
        p.add_argument(*names, action=argparse.BooleanOptionalAction, default=switch,
                       help=f"{help} (default: {default})", **kw)


def _command(group, name: str, run, short: str) -> _Parser:
    """A (sub)command ``name`` running ``run``: ``short`` in its group's list, the function's
    docstring atop its own help."""
    p = group.add_parser(name, help=short, description=" ".join(run.__doc__.split()))
    p.set_defaults(_run=run)
    p.command = True
    return p


def _spec_outputs(p, output: bool) -> None:
    """The spec argument and the outputs of `evaluate` (``output``: `design`'s ``-o``)."""
    p.add_argument("spec", nargs="?", type=Path, metavar="spec",
                   help="Spec file (TOML with units).")
    if not output:
        _option(p, "--geometry", help="Linkage geometry: 'exact' (default) or 'series' (the "
                                      "paper's eq. 3).")
    _flag(p, "--json", dest="json_out", help=_JSON_HELP)
    if output:
        _option(p, "-o", "--output", type=_typed, help="Write the design as a spec file.")
    _option(p, "--xlsx", type=_typed, help="Write an Excel design sheet.")
    _flag(p, "--force", help=_FORCE_HELP)
    _option(p, "--plots", type=Path, help="Write the plots (PNG and SVG) into this folder.")
    _flag(p, "--full", help="Print the whole report (the default is the answer: verdict, "
                            "design, the checks to watch, notes).")
    _option(p, "--section", action="append",
            help="Print these sections of the report (repeat, or comma-separated): summary, "
                 "characteristic, design, dynamics, vibration, optimisation, checks, spring.")


def _study_parser(group) -> None:
    """`govopt study run|export|show`."""
    study = group.add_parser(
        "study", help="Batch trade studies: sweep a spec's inputs, one row per point in an "
                      "SQLite database; export, plot and summarise it.",
        description="Batch trade studies: sweep a spec's inputs, one row per point in an "
                    "SQLite database; export, plot and summarise it. `govopt study SPEC ...` "
                    "is `govopt study run SPEC ...`.")
    sub = study.add_subparsers(dest="_study", metavar="COMMAND", title="commands")
    study.set_defaults(_help=study)
    p = _command(sub, "run", study_run, "Run a trade study: the spec at every point of the "
                                        "sweeps (or tolerance samples).")
    p.add_argument("spec", type=Path, metavar="spec",
                   help="Spec file; its [study] table, if any, is the study's default.")
    _option(p, "--sweep", action="append",
            help="KEY=START:STOP:NUM (with units: 'design.pendulum_weight=6 kgf:12 kgf:4') or "
                 "KEY=v1,v2,...; repeat for more keys.")
    _flag(p, "--grid", help="Every combination (default).")
    _flag(p, "--zip", dest="zip_", help="The sweeps' values taken in step.")
    _option(p, "--lhs", type=int, help="N Latin-hypercube samples.")
    _option(p, "--sobol", type=int, help="N scrambled Sobol' samples.")
    _option(p, "--seed", type=int, help="Seed of the samplers.")
    _option(p, "--mode", help="'evaluate' the spec's design at each point, or 'design' one "
                              "(default: evaluate if the spec has a [design]).")
    _option(p, "--tolerance", action="append",
            help="KEY=±X% (or '±X unit', 'uniform ±X%'; grade=1|2|3 for EN 15800): sample "
                 "manufacturing scatter around the spec's design.")
    _option(p, "--samples", type=int, help="Samples of a tolerance study (1000).")
    _option(p, "--pareto", help="Two or three objectives for a Pareto front, e.g. "
                                "'moving_mass,settling_time' (or column names; 'max:' to "
                                "maximise).")
    _option(p, "--skip", help="Analyses to leave out in evaluate mode: dynamics, vibration, "
                              "classic.")
    _option(p, "--db", type=_typed,
            help="The study's SQLite database (default: <spec>.study.db here).")
    _option(p, "--out", type=_typed, help="Export the table: .csv, .parquet or .xlsx.")
    _option(p, "--workers", type=int, default=1, help="Processes (a pool; Dask workers).")
    _option(p, "--dask", help="'local' (a LocalCluster of --workers processes) or a scheduler "
                              "tcp://HOST:PORT.")
    _flag(p, "--resume", switch=False, help="Skip the points already in --db.")
    _option(p, "--plot", "--plots", type=Path,
            help="Write the study's plots (PNG and SVG) into this folder.")
    _option(p, "--chunk", type=int, help="Points per chunk and database transaction (default "
                                         "1024 evaluate, 1 design).")
    _flag(p, "--force", help=_FORCE_HELP)
    p = _command(sub, "export", study_export,
                 "Export a study's table from its database (CSV, Parquet or xlsx).")
    p.add_argument("db", type=Path, metavar="db", help="The study's database.")
    _option(p, "--out", type=_typed, required=True, help="A .csv, .parquet or .xlsx file.")
    _option(p, "--plot", "--plots", type=Path, help="Also write the plots into this folder.")
    _flag(p, "--force", help=_FORCE_HELP)
    p = _command(sub, "show", study_show, "Summarise a study: progress, status counts, best "
                                          "point, Pareto front, tolerances.")
    p.add_argument("db", type=Path, metavar="db", help="The study's database.")


def _spring_parser(group) -> None:
    p = _command(group, "spring", spring, "Least-mass helical spring for a force and stiffness "
                                          "(an exact GP, certified global).")
    p.add_argument("spec", nargs="?", type=Path, metavar="spec",
                   help="Spring spec file (TOML with units, a [spring] table of these "
                        "options); the options override it.")
    _option(p, "--force", help="Largest working force, e.g. '606 kgf' (required, here or in "
                               "the spec).")
    _option(p, "--stiffness", help="Stiffness, e.g. '59.7 kgf/cm' (or from the stroke).")
    _option(p, "--allowable-stress", help="Allowable shear stress k_s (required without "
                                          "--material; overrides its rule).")
    _option(p, "--shear-modulus", help="Shear modulus G (required without --material).")
    _option(p, "--density", help="Wire density (default: the grade's, or 7850 kg/m^3).")
    _option(p, "--correction", help="Stress correction: 'wahl', 'bergstrasser' or 'none' "
                                    "(default: 'wahl'; with --material the rules' choice).")
    _option(p, "--material", help="Wire grade, e.g. 'EN10270-1 DH' "
                                  "(govopt/data/spring_materials.toml): allowables per wire "
                                  "diameter and the spring maker's checks.")
    _option(p, "--tensile-strength", help="R_m of --material custom.")
    _option(p, "--kind", help="Spring type: 'compression' (default) or 'extension'.")
    _option(p, "--rules", help="Allowables and fatigue: 'EN13906' (default) or 'Shigley'.")
    _option(p, "--index-min", type=float,
            help="Least spring index D/d (default 4: EN 13906-1 scope and Shigley's preferred "
                 "range).")
    _option(p, "--index-max", type=float,
            help="Largest spring index D/d (default 12: Shigley's preferred range; EN 13906-1 "
                 "allows 20).")
    _option(p, "--turns-min", type=float,
            help="Least active turns (default 3: fewer coil poorly and load unevenly).")
    _option(p, "--turns-max", type=float, help="Most active turns.")
    _option(p, "--min-force", help="Least working force F1 (extension: the initial tension "
                                   "stays below it).")
    _option(p, "--length-1", help="Installed length L1 at --min-force (compression).")
    _option(p, "--length-2", help="Installed length L2 at --force: the coils stay clear there; "
                                  "free length L2 + F/R (compression).")
    _option(p, "--stroke", help="Working stroke H = L1 - L2: the stiffness (F - F1) / H.")
    _option(p, "--fatigue-min-force", help="Least force of the fatigue load cycle (with "
                                           "--fatigue-max-force).")
    _option(p, "--fatigue-max-force", help="Largest force of the fatigue load cycle.")
    _option(p, "--min-fatigue-safety", type=float, help="Required fatigue safety (default 1).")
    _option(p, "--life", type=float, help="Required life, cycles (default 1e7).")
    p.add_argument("--peened", action=argparse.BooleanOptionalAction, default=None,
                   help="Shot-peened wire (fatigue; default: not peened).")
    _option(p, "--ends", help="Compression spring ends (EN 13906-1; default closed_ground).")
    _option(p, "--seating", help="Compression spring seating for buckling (default "
                                 "fixed-fixed).")
    _option(p, "--max-outer-diameter", help="Outside diameter in a bore (envelope), e.g. "
                                            "'10 cm'.")
    _option(p, "--max-body-length", help="Close-wound body length limit.")
    _option(p, "--min-surge-frequency", help="e.g. '40 Hz'.")
    _option(p, "--min-wire-diameter", help="Thinnest wire, e.g. '2 mm'.")
    _option(p, "--max-wire-diameter", help="Thickest wire, e.g. '6 mm'.")
    _option(p, "--max-stiffness", help="Largest stiffness: --stiffness to this is accepted "
                                       "(a stiffness range instead of one value).")
    _option(p, "--min-inside-diameter", help="Least inside diameter D - d (over a rod).")
    _option(p, "--max-free-length", help="Longest free length (compression: the least free "
                                         "length that keeps the coils clear at --force).")
    _option(p, "--max-solid-length", help="Longest solid length (compression).")
    _option(p, "--objective",
            help="What to minimise: 'mass' (default; all coils of wire), 'volume' ((n + end "
                 "coils) D d^2, as the optimisation literature), 'solid length', 'outer "
                 "diameter', or 'energy per mass' (the most stored energy per mass).")
    _flag(p, "--json", dest="json_out", help=_JSON_HELP)
    _option(p, "--xlsx", type=_typed, help="Write a workbook: the spring maker's sheet, the "
                                           "checks, the force-length table.")
    _option(p, "--plots", type=Path, help="Write the plots (force-length; the fatigue diagram "
                                          "with a load cycle), PNG and SVG, into this folder.")
    _flag(p, "--replace", help="Replace output files that exist (--force is the spring's "
                               "force here).")


@functools.cache
def parser() -> _Parser:
    """govopt's command line: its commands, their options and help."""
    from . import __version__

    root = _Parser(prog="govopt",
                   description="Design and evaluate speed governors and their springs: Hamabe's "
                               "shaft governor, the textbook's Watt, Porter, Proell, Hartnell, "
                               "spring-loaded and spring-and-gravity governors, and the "
                               "traction-engine coil- and flat-spring governors "
                               "(`govopt examples` lists a spec of each).")
    root.add_argument("--debug", action="store_true", dest="_debug",
                      help="Show the traceback of an unexpected error, and warnings as they "
                           "come. [env var: GOVOPT_DEBUG]")
    root.add_argument("--version", action="version", version=f"govopt {__version__}",
                      help="Print govopt's version and exit.")
    group = root.add_subparsers(dest="_command", metavar="COMMAND", title="commands")
    root.set_defaults(_help=root)
    _spec_outputs(_command(group, "evaluate", evaluate, "Evaluate the spec's design (default: "
                                                        "the bundled Hamabe case a)."),
                  output=False)
    p = _command(group, "design", design, "Find the best design for the spec's requirements "
                                          "(default: bundled hamabe-design).")
    _spec_outputs(p, output=True)
    _spring_parser(group)
    p = _command(group, "bench", bench, "Speed against error of every analysis and the speed "
                                        "targets beside what was measured.")
    _flag(p, "--quick", switch=False, help="A smaller suite and fewer repeats (under a minute).")
    _option(p, "--out", type=Path, help="Folder for speed-vs-error.md, .csv and .png (made "
                                        "if only its parent exists).")
    _flag(p, "--force", help=_FORCE_HELP)
    _flag(p, "--targets", switch=True, help="Also measure the speed targets.")
    _command(group, "examples", examples_command, "List the bundled example specs.")
    p = _command(group, "init", init_command, "Copy a bundled example spec here, to start "
                                              "from.")
    p.add_argument("name", metavar="name", help="A bundled example (see `govopt examples`).")
    _option(p, "-o", "--output", type=_typed, help="Where to write it (default: NAME.toml "
                                                   "here; a folder: NAME.toml in it).")
    _flag(p, "--force", help=_FORCE_HELP)
    _study_parser(group)
    return root


def _debug_env() -> bool:
    """GOVOPT_DEBUG as a flag (as click read it: 1/true/yes/on, 0/false/no/off or empty)."""
    value = os.environ.get("GOVOPT_DEBUG", "").strip().lower()
    if value in ("", "0", "false", "f", "no", "n", "off"):
        return False
    if value in ("1", "true", "t", "yes", "y", "on"):
        return True
    _fail(f"GOVOPT_DEBUG: expected 1 or 0 (true/false, yes/no, on/off), got {value!r}")


def _run(argv: list[str]) -> None:
    """Parse ``argv`` and run its command (`govopt study SPEC` is `govopt study run SPEC`)."""
    global _DEBUG
    _DEBUG = False
    at = next((i for i, a in enumerate(argv) if not a.startswith("-")), len(argv))
    if argv[at:at + 1] == ["study"] and argv[at + 1:at + 2] not in (
            [], ["run"], ["export"], ["show"], ["-h"], ["--help"]):
        argv = [*argv[:at + 1], "run", *argv[at + 1:]]
    args = vars(parser().parse_args(argv))
    _DEBUG = args["_debug"] or _debug_env()
    if "_run" not in args:  # no command: the help, and exit code 2 (nothing was run)
        args["_help"].print_help()
        raise SystemExit(2)
    args.pop("_run")(**{k: v for k, v in args.items() if not k.startswith("_")})


def _on_sigterm(signum, frame) -> None:
    """SIGTERM unwinds like an exception, so every ``finally`` runs (temporary files are
    removed); a second SIGTERM during that clean-up is ignored."""
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    raise SystemExit(128 + signum)


def main(argv: list[str] | None = None) -> None:
    """Console-script entry point (``argv``: the words after ``govopt``, default
    ``sys.argv[1:]``): never a traceback unless ``--debug``. Run as the console script it owns
    the process's SIGTERM; called with ``argv`` (tests, embedding) it leaves it alone."""
    # One BLAS thread unless told otherwise (before numpy loads): govopt's matrices are small,
    # and OpenBLAS's pool costs ~0.05 s of CPU to start and spins idle after each call (issue
    # 14: a third of `govopt evaluate`'s CPU); studies run processes in parallel anyway.
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    if argv is None:
        signal.signal(signal.SIGTERM, _on_sigterm)
    argv = sys.argv[1:] if argv is None else [str(a) for a in argv]
    try:
        _run(argv)
    except KeyboardInterrupt:
        sys.exit(130)
    except BrokenPipeError:  # `govopt evaluate | head`: quiet, stdout is gone
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(1)
    except Exception as exc:  # outside a command (the commands are _guarded)
        if _DEBUG or "--debug" in argv:
            raise
        _internal(exc)
        sys.exit(3)


if __name__ == "__main__":
    main()
