"""`govopt spring design|check`: the least-mass helical spring for a force and stiffness (an
exact GP, certified global; from a wire table with whole or half coils when a grade is given),
or a given spring checked; from options, a spring spec or both (the work is
:func:`govopt.spring_command.run`'s and :func:`~govopt.spring_command.check`'s). `govopt spring
SPEC ...` is `govopt spring design SPEC ...` (:func:`govopt.cli.main`)."""

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


def _design(name: str):
    """The option of ``[spring]``'s key ``name`` of a spring to design."""
    return _option(DESIGN.key(name), DESIGN)


def _check(name: str):
    """The option of ``[spring]``'s key ``name`` of a spring you have."""
    return _option(CHECK.key(name), CHECK)


JsonOut = Annotated[bool, common.flag("--json", help=JSON_HELP)]
Xlsx = Annotated[str | None, common.option(
    "--xlsx", metavar="<path>", help="Write a workbook: the spring maker's sheet, the checks, "
                                     "the force-length table.")]
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
        echo(f"wrote {Path(path).absolute()}", err=json_out)
    if out.failed:  # as evaluate: the spring is reported, and exit code 1 says a check failed
        echo(f"{len(out.failed)} of {out.total} checks failed: {'; '.join(out.failed)}",
             err=True)
        raise ChecksFailed


@app.command("design", help=DESIGN_HELP, short_help="Design a spring (default).")
@guarded
def design(
        spec: Annotated[Path | None, typer.Argument(
            help=rich_text("Spring spec file (TOML with units, a [spring] table of these "
                           "options with underscores); the options override it."),
            metavar="spec", show_default=False)] = None,
        force: _design("force") = None,
        stiffness: _design("stiffness") = None,
        max_stiffness: _design("max_stiffness") = None,
        allowable_stress: _design("allowable_stress") = None,
        shear_modulus: _design("shear_modulus") = None,
        density: _design("density") = None,
        tensile_strength: _design("tensile_strength") = None,
        correction: _design("correction") = None,
        material: _design("material") = None,
        kind: _design("kind") = None,
        rules: _design("rules") = None,
        ends: _design("ends") = None,
        seating: _design("seating") = None,
        objective: _design("objective") = None,
        index_min: _design("index_min") = None,
        index_max: _design("index_max") = None,
        turns_min: _design("turns_min") = None,
        turns_max: _design("turns_max") = None,
        min_force: _design("min_force") = None,
        fatigue_min_force: _design("fatigue_min_force") = None,
        fatigue_max_force: _design("fatigue_max_force") = None,
        min_fatigue_safety: _design("min_fatigue_safety") = None,
        life: _design("life") = None,
        peened: _design("peened") = None,
        max_outer_diameter: _design("max_outer_diameter") = None,
        max_body_length: _design("max_body_length") = None,
        min_surge_frequency: _design("min_surge_frequency") = None,
        min_wire_diameter: _design("min_wire_diameter") = None,
        max_wire_diameter: _design("max_wire_diameter") = None,
        min_inside_diameter: _design("min_inside_diameter") = None,
        max_free_length: _design("max_free_length") = None,
        max_solid_length: _design("max_solid_length") = None,
        length_1: _design("length_1") = None,
        length_2: _design("length_2") = None,
        stroke: _design("stroke") = None,
        wire_sizes: _design("wire_sizes") = None,
        coil_step: _design("coil_step") = None,
        loops: _design("loops") = None,
        name: _option(NAME, DESIGN) = None,
        json_out: JsonOut = False,
        output: Annotated[str | None, common.option(
            "-o", "--output", metavar="<path>",
            help="Write the designed spring as a spec for 'govopt spring check' (its "
                 "geometry, material, loads and rules).")] = None,
        xlsx: Xlsx = None,
        plots: Plots = None,
        replace: Replace = False,
) -> None:
    from ..spring_command import run

    options = {k: v for k, v in locals().items()
               if k not in ("spec", "json_out", "xlsx", "plots", "replace", "run", "output")}
    _finish(run(spec, json_out=json_out, xlsx=xlsx, plots=plots, output=output,
                replace=replace, **options), json_out)


@app.command("check", help=CHECK_HELP, short_help="Check a spring you have.")
@guarded
def check(
        spec: Annotated[Path | None, typer.Argument(
            help=rich_text("Spring spec file whose [spring] gives the spring (these options "
                           "with underscores); the options override it."), metavar="spec",
            show_default=False)] = None,
        wire_diameter: _check("wire_diameter") = None,
        mean_diameter: _check("mean_diameter") = None,
        outer_diameter: _check("outer_diameter") = None,
        active_coils: _check("active_coils") = None,
        total_coils: _check("total_coils") = None,
        free_length: _check("free_length") = None,
        initial_tension: _check("initial_tension") = None,
        tolerance_grade: _check("tolerance_grade") = None,
        kind: _check("kind") = None,
        material: _check("material") = None,
        tensile_strength: _check("tensile_strength") = None,
        shear_modulus: _check("shear_modulus") = None,
        allowable_stress: _check("allowable_stress") = None,
        density: _check("density") = None,
        correction: _check("correction") = None,
        rules: _check("rules") = None,
        ends: _check("ends") = None,
        seating: _check("seating") = None,
        force: _check("force") = None,
        min_force: _check("min_force") = None,
        length_1: _check("length_1") = None,
        length_2: _check("length_2") = None,
        fatigue_min_force: _check("fatigue_min_force") = None,
        fatigue_max_force: _check("fatigue_max_force") = None,
        min_fatigue_safety: _check("min_fatigue_safety") = None,
        life: _check("life") = None,
        peened: _check("peened") = None,
        index_min: _check("index_min") = None,
        index_max: _check("index_max") = None,
        loops: _check("loops") = None,
        name: _option(NAME, CHECK) = None,
        json_out: JsonOut = False,
        xlsx: Xlsx = None,
        plots: Plots = None,
        replace: Replace = False,
) -> None:
    from ..spring_command import check as run_check

    options = {k: v for k, v in locals().items()
               if k not in ("spec", "json_out", "xlsx", "plots", "replace", "run_check")}
    _finish(run_check(spec, json_out=json_out, xlsx=xlsx, plots=plots, replace=replace,
                      **options), json_out)
