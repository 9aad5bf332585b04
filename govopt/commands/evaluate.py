"""`govopt evaluate` and `govopt design`: a spec's design evaluated, or the best design for its
requirements, reported as text or JSON and written where asked (-o, --xlsx, --plots)."""

import json
from pathlib import Path
from typing import Annotated

import typer

from ..examples import SPECS
from .common import FORCE_HELP, JSON_HELP, ChecksFailed, echo, fail, flag, guarded, option

DEFAULT_EVALUATE = SPECS / "hamabe-a.toml"
DEFAULT_DESIGN = SPECS / "hamabe-design.toml"

EVALUATE_HELP = ("Evaluate the spec's design (default: the bundled Hamabe case a). Exit code 0: "
                 "every check passed; 1: some check failed; 2: bad input.")
EVALUATE_SHORT = "Evaluate the spec's design (default: the bundled Hamabe case a)."
DESIGN_HELP = ("Find the best design for the spec's requirements (default: bundled "
               "hamabe-design). Files are written only where asked (-o, --xlsx, --plots), as by "
               "evaluate.")
DESIGN_SHORT = "Find the best design for the spec's requirements (default: bundled hamabe-design)."

Spec = Annotated[Path | None, typer.Argument(help="Spec file (TOML with units).",
                                             metavar="spec", show_default=False)]
Json = Annotated[bool, flag("--json", help=JSON_HELP)]
Xlsx = Annotated[str | None, typer.Option("--xlsx", metavar="<path>",
                                          help="Write an Excel design sheet.")]
Force = Annotated[bool, flag("--force", help=FORCE_HELP)]
Plots = Annotated[Path | None, typer.Option(
    "--plots", metavar="<path>", help="Write the plots (PNG and SVG) into this folder.")]
Full = Annotated[bool, flag("--full", help="Print the whole report (the default is the answer: "
                                      "verdict, design, the checks to watch, notes).")]
Section = Annotated[list[str] | None, typer.Option(
    "--section", metavar="<str>",
    help="Print these sections of the report (repeat, or comma-separated): summary, "
         "characteristic, design, dynamics, vibration, optimisation, checks, spring.")]
Change = Annotated[str | None, option(
    "--speed-change", help="The speed change of the effort and power: a fraction c (e.g. 0.01) "
    "at the normal configuration, or 'range': the governor's own, from its lowest to its "
    "highest speed (default: the spec's [analysis] speed_change, else 0.01).")]

evaluate_app = typer.Typer(add_completion=False)
design_app = typer.Typer(add_completion=False)


Nominal = Annotated[bool, flag(
    "--nominal", help="The nominal design's verdict alone: its checks, not the governors made "
    "to the tolerances and set by the fitter (as requirements.verdict = \"nominal\").")]


def _load(spec: Path | None, default: Path, nominal: bool = False, **analysis):
    """The spec with the command's ``[analysis]`` options set as if written in it (re-read:
    ``design -o`` writes them into the design's spec, which then reproduces the report);
    ``nominal``: its verdict the nominal design's (``--nominal``)."""
    import dataclasses

    from ..spec import load_spec, with_values
    from ..spec_keys import analysis_table

    s = load_spec(spec or default)
    changes = {f"analysis.{k}": v for k, v in analysis.items() if v is not None}
    own = analysis_table(s.governor).names
    for key in (k for k, v in analysis.items() if v is not None and k not in own):
        fail(f"--{key.replace('_', '-')}: the {s.governor.type_name} governor has no "
             f"[analysis] {key} (docs/reference/spec.md)")
    s = with_values(s, changes) if changes else s
    return dataclasses.replace(s, verdict="nominal") if nominal else s


@evaluate_app.command("evaluate", help=EVALUATE_HELP, short_help=EVALUATE_SHORT)
@guarded
def evaluate(spec: Spec = None,
             geometry: Annotated[str | None, typer.Option(
                 "--geometry", metavar="<str>",
                 help="The shaft governor's linkage geometry: 'exact' (default) or "
                      "'series' (Hamabe eq. 3).")]
             = None,
             json_out: Json = False, xlsx: Xlsx = None, force: Force = False,
             plots: Plots = None, full: Full = False, section: Section = None,
             speed_change: Change = None, nominal: Nominal = False) -> None:
    from ..evaluator import evaluate as run

    if geometry is not None and geometry not in ("exact", "series"):
        fail(f"--geometry: expected 'exact' or 'series', got {geometry!r}")
    change = _speed_change(speed_change)
    run_and_report(lambda: run(_load(spec, DEFAULT_EVALUATE, nominal, geometry=geometry,
                                     speed_change=change)), json_out,
                   spec or DEFAULT_EVALUATE, xlsx=xlsx, force=force, plots=plots,
                   sections=_sections(full, section), advise=True)


@design_app.command("design", help=DESIGN_HELP, short_help=DESIGN_SHORT)
@guarded
def design(spec: Spec = None, json_out: Json = False,
           output: Annotated[str | None, typer.Option(
               "-o", "--output", metavar="<path>", help="Write the design as a spec file.")]
           = None,
           xlsx: Xlsx = None, force: Force = False, plots: Plots = None, full: Full = False,
           section: Section = None, speed_change: Change = None,
           nominal: Nominal = False) -> None:
    from ..optimize.search import design as run

    change = _speed_change(speed_change)
    run_and_report(lambda: run(_load(spec, DEFAULT_DESIGN, nominal, speed_change=change)),
                   json_out,
                   spec or DEFAULT_DESIGN,
                   xlsx=xlsx, output=output, force=force, plots=plots,
                   sections=_sections(full, section))


def _speed_change(text: str | None) -> float | str | None:
    """``--speed-change``: 'range' or a fraction in (0, 1), read by the rule of the spec's
    ``[analysis] speed_change`` (:func:`govopt.spec.read_speed_change`)."""
    if text is None:
        return None
    from ..reader import Reader
    from ..spec import read_speed_change

    return read_speed_change(Reader("", {"--speed-change": _toml_value(text)}, "", []),
                             "--speed-change")


def _toml_value(text: str):
    """An option's text as the value it would be in a spec (``2`` an integer, ``1e-300`` a
    float, ``nan`` a float), else the text itself: an option and its spec key are read alike."""
    import tomllib

    if "\n" not in text and "\r" not in text:
        try:
            return tomllib.loads(f"value = {text}")["value"]
        except tomllib.TOMLDecodeError:
            pass
    return text.strip()


def _sections(full: bool, section: list[str] | None) -> list[str] | None:
    """The report's sections: the answer (``summary``) by default, all with ``--full``, the
    named ones with ``--section`` (names checked: a wrong one is exit 2)."""
    from ..report.text import SECTIONS

    if full and section:
        fail("--full and --section: choose one (--full prints every section)")
    if full:
        return None
    names = [n.strip() for s in section or () for n in s.split(",") if n.strip()]
    for name in names:
        if name not in SECTIONS:
            import difflib

            close = difflib.get_close_matches(name, SECTIONS, n=1)
            fail(f"--section: expected one of {', '.join(SECTIONS)}, got {name!r}"
                 + (f" (did you mean {close[0]!r}?)" if close else ""))
    return names or ["summary"]


def run_and_report(compute, json_out: bool, spec: Path, xlsx: str | None = None,
                   output: str | None = None, force: bool = False, plots: Path | None = None,
                   sections: list[str] | None = None, advise: bool = False) -> None:
    """Check the outputs, compute a Result, write the requested files, print it and say what
    was written where (on stderr with ``--json``); a user's error (GovoptError) exits 2 and a
    result with failed checks 1, through :func:`~govopt.commands.common.guarded`. With
    ``--json`` a search that finds no design prints its diagnosis as one JSON object before
    exiting 2; ``advise``: a result with failed checks is told what change makes it pass
    (:func:`govopt.optimize.diagnosis.evaluation_moves`; in the JSON, ``diagnosis``)."""
    from ..report.files import removed_on_error

    with removed_on_error():  # a refused run leaves no empty plots folder
        _run_and_report(compute, json_out, spec, xlsx, output, force, plots, sections, advise)


def _run_and_report(compute, json_out: bool, spec: Path, xlsx: str | None = None,
                    output: str | None = None, force: bool = False, plots: Path | None = None,
                    sections: list[str] | None = None, advise: bool = False) -> None:
    from ..report.files import check_planned, drawn_design, overwrite_policy, write_design_spec
    from ..report.text import format_result

    outputs = [(p, what) for p, what in ((output, "design spec"), (xlsx, "workbook"))
               if p is not None]  # before the run: fail in a second, not after it
    check_planned(outputs, overwrite=force, inputs=[spec])
    if plots is not None:  # the folder, and no plot replaced without --force
        from ..report.plot_files import check_plot_dir, write_plots

        check_plot_dir(plots, spec.stem, overwrite=force, inputs=[spec],
                       others=[p for p, _ in outputs])
    from ..errors import DesignError, InfeasibleError
    from ..made import with_yield

    try:
        res = compute()
    except (InfeasibleError, DesignError) as exc:  # no design: the diagnosis, as JSON too
        if json_out:
            echo(json.dumps(exc.to_dict(), indent=2))
        raise
    if output is not None:  # rounded as drawn, and evaluated again: the report is its
        text, res, _ = drawn_design(res)
        write_design_spec(res, output, overwrite=force, text=text)
    res = with_yield(res)  # governors made to the spec's tolerances: the yield
    if xlsx is not None:
        from ..report.excel import write_workbook

        with overwrite_policy(force):
            write_workbook(res, xlsx)
    drawn = [] if plots is None else write_plots(res, plots, stem=spec.stem, overwrite=force)
    moves = None
    if advise and not all(c.passed for c in res.checks):
        from ..optimize.diagnosis import evaluation_moves

        moves = evaluation_moves(res.spec)
    if json_out:
        out = res.to_dict()
        if moves is not None:
            out["diagnosis"] = {"failed": [c.name for c in res.checks if not c.passed],
                                "moves": moves}
        echo(json.dumps(out, indent=2))
    else:
        echo(format_result(res, sections=sections))
    for path in (output, xlsx, *drawn):
        if path is not None:
            echo(f"wrote {path}", err=json_out)
    exit_on_failed_checks(res, json_out, moves)


def exit_on_failed_checks(res, json_out: bool, moves: list[str] | None = None) -> None:
    """Exit code 1 (after the report) when any of the result's checks failed, saying (on
    stderr) which, and ``moves``: the changes that each make it pass; or when the made
    governors' yield falls short of ``min_yield`` where the verdict is theirs
    (:attr:`govopt.result.Result.passed`)."""
    failed = [c.name for c in res.checks if not c.passed]
    if failed:
        if not json_out:
            echo(f"{len(failed)} of {len(res.checks)} checks failed: {'; '.join(failed)}",
                 err=True)
            if moves is not None:
                echo("it passes if one of these moves: " + "; ".join(moves) if moves else
                     "no single change of its friction, speeds or a design value (within x2) "
                     "makes it pass", err=True)
        raise ChecksFailed
    if not res.passed:
        if not json_out:
            from ..report.text import yield_line

            echo(f"FAIL as made: {yield_line(res)}", err=True)
        raise ChecksFailed
