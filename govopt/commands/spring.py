"""`govopt spring design|check`: the least-mass helical spring for a force and stiffness (an
exact GP, certified global; from a wire table with whole or half coils when a grade is given),
or a given spring checked; from options, a spring spec or both (the work is
:func:`govopt.spring_command.run`'s and :func:`~govopt.spring_command.check`'s). `govopt spring
SPEC ...` is `govopt spring design SPEC ...` (:func:`govopt.cli.main`)."""

from pathlib import Path
from typing import Annotated

import typer

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
WIRE_SIZES_HELP = ("Wires to order from: 'preferred' (the grade's standard's diameters, "
                   "listed with their source in govopt's data/wire_sizes.toml: EN 10270-1's "
                   "nominal sizes, ASTM A228's; other grades the ISO 3 R20 series govopt "
                   "design uses), a list ('2.5 mm, 2.8 mm, 3 mm') or 'continuous' (any wire "
                   "and coils). Default: 'preferred' with --material, else 'continuous'.")

app = typer.Typer(name="spring", add_completion=False, help=SPRING_HELP,
                  short_help=SPRING_SHORT, invoke_without_command=True)

Text = str | None
Number = float | None


def _o(name: str, help: str, metavar: str = "<str>"):
    return common.option(name, help=help, metavar=metavar)


# the options design and check share, declared once
Material = Annotated[Text, _o("--material", "Wire grade, e.g. 'EN10270-1 DH' "
                              "(govopt/data/spring_materials.toml): allowables per wire "
                              "diameter and the spring maker's checks.")]
TensileStrength = Annotated[Text, _o("--tensile-strength", "R_m of --material custom.")]
ShearModulus = Annotated[Text, _o("--shear-modulus", "Shear modulus G (required without "
                                  "--material).")]
AllowableStress = Annotated[Text, _o("--allowable-stress", "Allowable shear stress k_s "
                                     "(required without --material; overrides its rule).")]
Density = Annotated[Text, _o("--density", "Wire density (default: the grade's, or 7850 "
                             "kg/m^3).")]
Correction = Annotated[Text, _o("--correction", "Static stress correction: 'wahl', "
                                "'bergstrasser' or 'none' (default: 'wahl'; with --material "
                                "the rules' choice).")]
Kind = Annotated[Text, _o("--kind", "Spring type: 'compression' (default) or 'extension'.")]
Rules = Annotated[Text, _o("--rules", "Allowables and fatigue: 'EN13906' (default) or "
                           "'Shigley'.")]
MinForce = Annotated[Text, _o("--min-force", "Least working force F1 (extension: the initial "
                              "tension stays below it).")]
Length1 = Annotated[Text, _o("--length-1", "Working (installed) length L1 at --min-force "
                             "(compression).")]
FatigueMin = Annotated[Text, _o("--fatigue-min-force", "Least force of the fatigue load cycle "
                                "(with --fatigue-max-force and --material).")]
FatigueMax = Annotated[Text, _o("--fatigue-max-force", "Largest force of the fatigue load "
                                "cycle.")]
FatigueSafety = Annotated[Number, _o("--min-fatigue-safety", "Required fatigue safety "
                                     "(default 1).", "<float>")]
Life = Annotated[Number, _o("--life", "Required life, cycles (default 1e7).", "<float>")]
Peened = Annotated[bool | None, common.flag(
    "--peened/--no-peened", help="Shot-peened wire (fatigue; default: not peened).",
    show_default=False)]
Ends = Annotated[Text, _o("--ends", "Compression spring ends: closed_ground (default), "
                          "closed, open, open_ground (EN 13906-1 and Shigley's solid "
                          "lengths).")]
Loops = Annotated[Text, _o("--loops", "Extension spring loops: full_loop (default), "
                           "half_loop, side_loop, english_loop (EN 13906-2).")]
Seating = Annotated[Text, _o("--seating", "Compression spring seating for buckling (default "
                             "fixed-fixed).")]
Name = Annotated[Text, _o("--name", "The spring's name (reports, plot titles; default: the "
                          "spec's, or what the spring is).")]
JsonOut = Annotated[bool, common.flag("--json", help=JSON_HELP)]
Xlsx = Annotated[Text, _o("--xlsx", "Write a workbook: the spring maker's sheet, the checks, "
                          "the force-length table.", "<path>")]
Plots = Annotated[Path | None, _o("--plots", "Write the plots (force-length; the fatigue "
                                  "diagram with a load cycle), PNG and SVG, into this folder.",
                                  "<path>")]
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
                           "options); the options override it."), metavar="spec",
            show_default=False)] = None,
        force: Annotated[Text, _o("--force", "Largest working force, e.g. '606 kgf' "
                                  "(required, here or in the spec).")] = None,
        stiffness: Annotated[Text, _o("--stiffness", "Stiffness, e.g. '59.7 kgf/cm' (or from "
                                      "the stroke).")] = None,
        allowable_stress: AllowableStress = None,
        shear_modulus: ShearModulus = None,
        density: Density = None,
        correction: Correction = None,
        material: Material = None,
        tensile_strength: TensileStrength = None,
        kind: Kind = None,
        rules: Rules = None,
        index_min: Annotated[Number, _o("--index-min", "Least spring index D/d (default 4: "
                                        "EN 13906-1 scope and Shigley's preferred range).",
                                        "<float>")] = None,
        index_max: Annotated[Number, _o("--index-max", "Largest spring index D/d (default 12: "
                                        "Shigley's preferred range; EN 13906-1 allows 20).",
                                        "<float>")] = None,
        turns_min: Annotated[Number, _o("--turns-min", "Least active turns (default 3: fewer "
                                        "coil poorly and load unevenly).", "<float>")] = None,
        turns_max: Annotated[Number, _o("--turns-max", "Most active turns.", "<float>")] = None,
        min_force: MinForce = None,
        length_1: Length1 = None,
        length_2: Annotated[Text, _o("--length-2", "Installed length L2 at --force: the coils "
                                     "stay clear there; free length L2 + F/R "
                                     "(compression).")] = None,
        stroke: Annotated[Text, _o("--stroke", "Working stroke H = L1 - L2: the stiffness "
                                   "(F - F1) / H.")] = None,
        fatigue_min_force: FatigueMin = None,
        fatigue_max_force: FatigueMax = None,
        min_fatigue_safety: FatigueSafety = None,
        life: Life = None,
        peened: Peened = None,
        ends: Ends = None,
        loops: Loops = None,
        seating: Seating = None,
        max_outer_diameter: Annotated[Text, _o("--max-outer-diameter", "Outside diameter in a "
                                               "bore (envelope), e.g. '10 cm'.")] = None,
        max_body_length: Annotated[Text, _o("--max-body-length", "Close-wound body length "
                                            "limit.")] = None,
        min_surge_frequency: Annotated[Text, _o("--min-surge-frequency", "e.g. '40 Hz'.")]
        = None,
        min_wire_diameter: Annotated[Text, _o("--min-wire-diameter", "Thinnest wire, e.g. "
                                              "'2 mm'.")] = None,
        max_wire_diameter: Annotated[Text, _o("--max-wire-diameter", "Thickest wire, e.g. "
                                              "'6 mm'.")] = None,
        max_stiffness: Annotated[Text, _o("--max-stiffness", "Largest stiffness: --stiffness "
                                          "to this is accepted (a stiffness range instead of "
                                          "one value).")] = None,
        min_inside_diameter: Annotated[Text, _o("--min-inside-diameter", "Least inside "
                                                "diameter D - d (over a rod).")] = None,
        max_free_length: Annotated[Text, _o("--max-free-length", "Longest free length "
                                            "(compression: the least free length that keeps "
                                            "the coils clear at --force).")] = None,
        max_solid_length: Annotated[Text, _o("--max-solid-length", "Longest solid length "
                                             "(compression).")] = None,
        objective: Annotated[Text, _o("--objective", "What to minimise: 'mass' (default; all "
                                      "coils of wire), 'volume' ((n + end coils) D d^2, as the "
                                      "optimisation literature), 'solid length', 'outer "
                                      "diameter', or 'energy per mass' (the most stored energy "
                                      "per mass).")] = None,
        wire_sizes: Annotated[Text, _o("--wire-sizes", WIRE_SIZES_HELP)] = None,
        coil_step: Annotated[Number, _o("--coil-step", "Active coils (extension: body coils) "
                                        "on this step with a wire table: 0.5 (default), 0.25 "
                                        "or 1.", "<float>")] = None,
        name: Name = None,
        json_out: JsonOut = False,
        output: Annotated[Text, common.option(
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
        wire_diameter: Annotated[Text, _o("--wire-diameter", "Wire diameter d, e.g. '2.8 mm' "
                                          "(required).")] = None,
        mean_diameter: Annotated[Text, _o("--mean-diameter", "Mean coil diameter D (or "
                                          "--outer-diameter).")] = None,
        outer_diameter: Annotated[Text, _o("--outer-diameter", "Outside diameter D + d.")]
        = None,
        active_coils: Annotated[Number, _o("--active-coils", "Active coils n (extension: or "
                                           "--total-coils, the body's).", "<float>")] = None,
        total_coils: Annotated[Number, _o("--total-coils", "Total coils n_t (default: n + the "
                                          "end form's inactive coils); an extension spring's "
                                          "body coils.", "<float>")] = None,
        free_length: Annotated[Text, _o("--free-length", "Free length L0 (required for a "
                                        "compression spring; an extension spring's inside its "
                                        "loops, default from them).")] = None,
        ends: Ends = None,
        loops: Loops = None,
        initial_tension: Annotated[Text, _o("--initial-tension", "Extension spring's initial "
                                            "tension F0.")] = None,
        kind: Kind = None,
        material: Material = None,
        tensile_strength: TensileStrength = None,
        shear_modulus: ShearModulus = None,
        allowable_stress: AllowableStress = None,
        density: Density = None,
        correction: Correction = None,
        rules: Rules = None,
        force: Annotated[Text, _o("--force", "Largest working force F2 (or --length-2).")]
        = None,
        min_force: MinForce = None,
        length_1: Length1 = None,
        length_2: Annotated[Text, _o("--length-2", "Working length L2 (F2 from the rate).")]
        = None,
        fatigue_min_force: FatigueMin = None,
        fatigue_max_force: FatigueMax = None,
        min_fatigue_safety: FatigueSafety = None,
        life: Life = None,
        peened: Peened = None,
        seating: Seating = None,
        index_min: Annotated[Number, _o("--index-min", "Least spring index (default 4).",
                                        "<float>")] = None,
        index_max: Annotated[Number, _o("--index-max", "Largest spring index (default 20, "
                                        "EN 13906-1).", "<float>")] = None,
        tolerance_grade: Annotated[Number, _o("--tolerance-grade", "EN 15800 quality grade "
                                              "1, 2 (default) or 3.", "<int>")] = None,
        name: Name = None,
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
