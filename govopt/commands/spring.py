"""`govopt spring`: the least-mass helical spring for a force and stiffness (an exact GP,
certified global), from options, a spring spec or both, with a wire grade's allowables and the
spring maker's checks (the work is :func:`govopt.spring_command.run`'s)."""

from pathlib import Path
from typing import Annotated

import typer

from . import common
from .common import JSON_HELP, ChecksFailed, echo, guarded

SPRING_SHORT = ("Least-mass helical spring for a force and stiffness (an exact GP, certified "
                "global).")
SPRING_HELP = ("Least-mass helical spring for a force and stiffness (an exact GP, certified "
               "global), from the options, a spring spec file or both (the options override "
               "the file); with --material the wire grade's allowables per diameter and the "
               "spring maker's checks.")

app = typer.Typer(add_completion=False)

Text = str | None
Number = float | None


def _o(name: str, help: str, metavar: str = "<str>"):
    return common.option(name, help=help, metavar=metavar)


@app.command("spring", help=SPRING_HELP, short_help=SPRING_SHORT)
@guarded
def spring(
        spec: Annotated[Path | None, typer.Argument(
            help="Spring spec file (TOML with units, a [spring] table of these options); the "
                 "options override it.", metavar="spec", show_default=False)] = None,
        force: Annotated[Text, _o("--force", "Largest working force, e.g. '606 kgf' "
                                  "(required, here or in the spec).")] = None,
        stiffness: Annotated[Text, _o("--stiffness", "Stiffness, e.g. '59.7 kgf/cm' (or from "
                                      "the stroke).")] = None,
        allowable_stress: Annotated[Text, _o("--allowable-stress", "Allowable shear stress k_s "
                                             "(required without --material; overrides its "
                                             "rule).")] = None,
        shear_modulus: Annotated[Text, _o("--shear-modulus", "Shear modulus G (required "
                                          "without --material).")] = None,
        density: Annotated[Text, _o("--density", "Wire density (default: the grade's, or 7850 "
                                    "kg/m^3).")] = None,
        correction: Annotated[Text, _o("--correction", "Stress correction: 'wahl', "
                                       "'bergstrasser' or 'none' (default: 'wahl'; with "
                                       "--material the rules' choice).")] = None,
        material: Annotated[Text, _o("--material", "Wire grade, e.g. 'EN10270-1 DH' "
                                     "(govopt/data/spring_materials.toml): allowables per wire "
                                     "diameter and the spring maker's checks.")] = None,
        tensile_strength: Annotated[Text, _o("--tensile-strength", "R_m of --material "
                                             "custom.")] = None,
        kind: Annotated[Text, _o("--kind", "Spring type: 'compression' (default) or "
                                 "'extension'.")] = None,
        rules: Annotated[Text, _o("--rules", "Allowables and fatigue: 'EN13906' (default) or "
                                  "'Shigley'.")] = None,
        index_min: Annotated[Number, _o("--index-min", "Least spring index D/d (default 4: "
                                        "EN 13906-1 scope and Shigley's preferred range).",
                                        "<float>")] = None,
        index_max: Annotated[Number, _o("--index-max", "Largest spring index D/d (default 12: "
                                        "Shigley's preferred range; EN 13906-1 allows 20).",
                                        "<float>")] = None,
        turns_min: Annotated[Number, _o("--turns-min", "Least active turns (default 3: fewer "
                                        "coil poorly and load unevenly).", "<float>")] = None,
        turns_max: Annotated[Number, _o("--turns-max", "Most active turns.", "<float>")] = None,
        min_force: Annotated[Text, _o("--min-force", "Least working force F1 (extension: the "
                                      "initial tension stays below it).")] = None,
        length_1: Annotated[Text, _o("--length-1", "Installed length L1 at --min-force "
                                     "(compression).")] = None,
        length_2: Annotated[Text, _o("--length-2", "Installed length L2 at --force: the coils "
                                     "stay clear there; free length L2 + F/R "
                                     "(compression).")] = None,
        stroke: Annotated[Text, _o("--stroke", "Working stroke H = L1 - L2: the stiffness "
                                   "(F - F1) / H.")] = None,
        fatigue_min_force: Annotated[Text, _o("--fatigue-min-force", "Least force of the "
                                              "fatigue load cycle (with "
                                              "--fatigue-max-force).")] = None,
        fatigue_max_force: Annotated[Text, _o("--fatigue-max-force", "Largest force of the "
                                              "fatigue load cycle.")] = None,
        min_fatigue_safety: Annotated[Number, _o("--min-fatigue-safety", "Required fatigue "
                                                 "safety (default 1).", "<float>")] = None,
        life: Annotated[Number, _o("--life", "Required life, cycles (default 1e7).",
                                   "<float>")] = None,
        peened: Annotated[bool | None, common.flag(
            "--peened/--no-peened", help="Shot-peened wire (fatigue; default: not peened).",
            show_default=False)] = None,
        ends: Annotated[Text, _o("--ends", "Compression spring ends (EN 13906-1; default "
                                 "closed_ground).")] = None,
        seating: Annotated[Text, _o("--seating", "Compression spring seating for buckling "
                                    "(default fixed-fixed).")] = None,
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
        json_out: Annotated[bool, common.flag("--json", help=JSON_HELP)] = False,
        xlsx: Annotated[Text, _o("--xlsx", "Write a workbook: the spring maker's sheet, the "
                                 "checks, the force-length table.", "<path>")] = None,
        plots: Annotated[Path | None, _o("--plots", "Write the plots (force-length; the fatigue "
                                         "diagram with a load cycle), PNG and SVG, into this "
                                         "folder.", "<path>")] = None,
        replace: Annotated[bool, common.flag("--replace", help="Replace output files that "
                                             "exist (--force is the spring's force here).")]
        = False,
) -> None:
    from ..spring_command import run

    options = {k: v for k, v in locals().items()
               if k not in ("spec", "json_out", "xlsx", "plots", "replace", "run")}
    out = run(spec, json_out=json_out, xlsx=xlsx, plots=plots, replace=replace, **options)
    echo(out.text)
    for path in out.written:
        echo(f"wrote {Path(path).absolute()}", err=json_out)
    if out.failed:  # as evaluate: the spring is reported, and exit code 1 says a check failed
        echo(f"{len(out.failed)} of {out.total} checks failed: {'; '.join(out.failed)}",
             err=True)
        raise ChecksFailed
