"""`govopt spring design|check`: the least-mass helical spring for a force and stiffness (an
exact GP, certified global; from a wire table with whole or half coils when a grade is given),
or a given spring checked; from options, a spring spec or both (the work is
:func:`govopt.spring_command.run`'s and :func:`~govopt.spring_command.check`'s). `govopt spring
SPEC ...` is `govopt spring design SPEC ...` (:func:`govopt.cli.main`).

The options are the keys of the form of ``[spring]`` each command reads, declared once in
:mod:`govopt.spring_keys`: :func:`keyed` gives a command one option per key (``--max-outer-
diameter`` for ``max_outer_diameter``), in declared order, with the key's value type and help
(:func:`govopt.spec_docs.option_help`), through the command's signature (:mod:`inspect`), which
typer reads; the command's own parameters (the spec, the outputs) are written in it."""

import inspect
from pathlib import Path
from typing import Annotated

import typer

from ..keys import Key, Table
from ..spec_docs import option_help
from ..spring_keys import CHECK, DESIGN, NAME
from . import common
from .common import JSON_HELP, ChecksFailed, echo, guarded, rich_text

SPRING_SHORT = ("Least-mass helical spring for a force and stiffness (an exact GP, certified "
                "global), or check one you have.")
SPRING_HELP = (SPRING_SHORT + " `govopt spring SPEC ...` is `govopt spring design SPEC ...`.")
DESIGN_HELP = ("Least-mass helical spring for a force and stiffness (an exact GP, certified "
               "global), from the options, a spring spec file or both (the options override "
               "the file); with --material the wire grade's allowables per diameter, the "
               "spring maker's checks, and a wire from the grade's standard's table with the "
               "coils on half turns (--wire-sizes, --coil-step).")
CHECK_HELP = ("Check a helical spring you have: its wire, coil diameter, coils and free length "
              "with its material and working forces or lengths; the same report as a designed "
              "spring's (rate, forces and stresses at each length and at solid, EN 13906-1's "
              "checks, buckling, surge, fatigue and life, EN 15800 tolerances), in the units "
              "the input is written in; exit code 1 when a check fails.")
app = typer.Typer(name="spring", add_completion=False, help=SPRING_HELP,
                  short_help=SPRING_SHORT, invoke_without_command=True)


def _option(key: Key, table: Table):
    """The option of a spring spec's key (``--max-outer-diameter`` for ``max_outer_diameter``),
    its value's type and its help (meaning, unit, default) from the declaration
    (:func:`govopt.spec_docs.option_help`)."""
    option, help_text = "--" + key.name.replace("_", "-"), option_help(key, table)
    if key.kind == "flag":
        return Annotated[bool | None, common.flag(f"{option}/--no-{option[2:]}", help=help_text,
                                                  show_default=False)]
    whole = key.kind == "choice" and isinstance(key.choices, tuple) and all(
        isinstance(c, int) for c in key.choices)  # the EN 15800 grade
    kind = int if whole or key.kind == "count" else float if key.kind == "number" else str
    return Annotated[kind | None, common.option(option, help=help_text,
                                                metavar=f"<{kind.__name__}>")]


def keyed(table: Table):
    """A command whose options are ``table``'s keys and ``--name`` (each None where not given),
    after its first parameter (the spec) and before its own others; the function takes them as
    ``**options``."""
    def decorate(command):
        spec, *own, rest = inspect.signature(command).parameters.values()
        assert rest.kind is inspect.Parameter.VAR_KEYWORD, command
        keys = [inspect.Parameter(k.name, inspect.Parameter.KEYWORD_ONLY, default=None,
                                  annotation=_option(k, table)) for k in (*table.keys, NAME)]
        params = [spec, *(p.replace(kind=inspect.Parameter.KEYWORD_ONLY) for p in own)]
        command.__signature__ = inspect.Signature([params[0], *keys, *params[1:]])
        command.__annotations__ = {p.name: p.annotation for p in (*params, *keys)}
        return command

    return decorate


JsonOut = Annotated[bool, common.flag("--json", help=JSON_HELP)]
Xlsx = Annotated[str | None, common.option(
    "--xlsx", metavar="<path>", help="Write a workbook: the spring maker's sheet, the checks, "
                                     "the force-length table, the inputs.")]
Plots = Annotated[Path | None, common.option(
    "--plots", metavar="<path>", help="Write the plots (force-length; the fatigue diagram with "
                                      "a load cycle), PNG and SVG, into this folder.")]
Replace = Annotated[bool, common.flag("--replace", help="Replace output files that exist "
                                      "(--force is the spring's force here).")]


@app.callback()
def spring(ctx: typer.Context) -> None:
    if ctx.invoked_subcommand is None:  # `govopt spring`: its help, exit code 2 (nothing ran)
        echo(ctx.get_help())
        raise SystemExit(2)


def _finish(out, json_out: bool) -> None:
    echo(out.text)
    for path in out.written:
        echo(f"wrote {path}", err=json_out)
    if out.failed:  # as evaluate: the spring is reported, and exit code 1 says a check failed
        echo(f"{len(out.failed)} of {out.total} checks failed: {'; '.join(out.failed)}",
             err=True)
        raise ChecksFailed


@app.command("design", help=DESIGN_HELP, short_help="Design a spring (default).")
@guarded
@keyed(DESIGN)
def design(
        spec: Annotated[Path | None, typer.Argument(
            help=rich_text("Spring spec file (TOML with units, a [spring] table of these "
                           "options with underscores); the options override it."),
            metavar="spec", show_default=False)] = None,
        json_out: JsonOut = False,
        output: Annotated[str | None, common.option(
            "-o", "--output", metavar="<path>",
            help="Write the designed spring as a spec for 'govopt spring check' (its "
                 "geometry, its lengths as a drawing gives them: 4 significant digits, more "
                 "only where a check would fail; material, loads and rules).")] = None,
        xlsx: Xlsx = None,
        plots: Plots = None,
        replace: Replace = False,
        **options,
) -> None:
    from ..report.files import removed_on_error
    from ..spring_command import run

    with removed_on_error():  # a refused run leaves no empty plots folder
        out = run(spec, json_out=json_out, xlsx=xlsx, plots=plots, output=output,
                  replace=replace, **options)
    _finish(out, json_out)


@app.command("check", help=CHECK_HELP, short_help="Check a spring you have.")
@guarded
@keyed(CHECK)
def check(
        spec: Annotated[Path | None, typer.Argument(
            help=rich_text("Spring spec file whose [spring] gives the spring (these options "
                           "with underscores); the options override it."), metavar="spec",
            show_default=False)] = None,
        json_out: JsonOut = False,
        xlsx: Xlsx = None,
        plots: Plots = None,
        replace: Replace = False,
        **options,
) -> None:
    from ..report.files import removed_on_error
    from ..spring_command import check as run_check

    with removed_on_error():  # a refused run leaves no empty plots folder
        out = run_check(spec, json_out=json_out, xlsx=xlsx, plots=plots, replace=replace,
                        **options)
    _finish(out, json_out)
