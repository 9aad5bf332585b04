"""`govopt at` and `govopt solve`: the textbook's questions from one spec - the answers at the
points a problem names, and any one input found for one figure's target
(:mod:`govopt.questions`)."""

import json
from pathlib import Path
from typing import Annotated

import typer

from .common import JSON_HELP, echo, flag, guarded, option

AT_HELP = ("Answers at the points a problem names: speeds (frictionless, rising, falling), "
           "insensitiveness, controlling, spring and sleeve forces, effort, power and the "
           "forces in the arms, links and pivots. Exit code 0; 2: bad input.")
AT_SHORT = "Speeds, forces, effort and power at the configurations a problem names."
SOLVE_HELP = ("Find one input of the spec (--unknown) at which one figure meets its target "
              "(--target), by bracketed root-finding; an error when no value in the bracket "
              "meets it. Exit code 0; 2: bad input or no root.")
SOLVE_SHORT = "Find the spec input at which a figure meets its target (any unknown)."

Spec = Annotated[Path, typer.Argument(help="Spec file (TOML with units).", metavar="spec",
                                      show_default=False)]
Json = Annotated[bool, flag("--json", help=JSON_HELP)]
POINT_HELP = ("A point: NAME=VALUE with NAME one of the type's coordinates (a ball governor's "
              "radius, angle, height, joint_radius, lift), e.g. 'angle=30 deg', or inner, "
              "normal, outer.")

at_app = typer.Typer(add_completion=False)
solve_app = typer.Typer(add_completion=False)

@at_app.command("at", help=AT_HELP, short_help=AT_SHORT)
@guarded
def at(spec: Spec, points: Annotated[list[str], option("--at", help=POINT_HELP + " Repeat for "
                                                                   "more points.")],
       json_out: Json = False) -> None:
    import numpy as np

    from .. import questions
    from ..analysis.points import FIGURES, unit
    from ..spec import load_spec
    from ..units import SI_UNITS
    from ..verdict import json_key

    s = load_spec(spec)
    gov = s.governor
    pts = [questions.parse_point(gov, p) for p in points]
    out = questions.answers(s, pts)
    rows = [(c.name, SI_UNITS[c.dimension], out["coordinates"][c.name])
            for c in gov.coordinates()]
    rows += [(name.replace("_", " "), unit(gov, kind), out["figures"][name])
             for name, (kind, _) in FIGURES.items()]
    rows += [(name, "N", values) for name, values in out["links"].items()]
    if json_out:
        listed = []
        for i, p in enumerate(pts):
            item = {"at": p.text, gov.json_coordinate("x", out["x"][i])[0]:
                    gov.json_coordinate("x", out["x"][i])[1]}
            for name, u, values in rows:
                v = float(values[i])
                item[json_key(name, u)] = v if np.isfinite(v) else None
            item["stable"] = bool(out["stable"][i])
            listed.append(item)
        echo(json.dumps({"spec": s.name, "speed_change": s.analysis.speed_change,
                         "points": listed}, indent=2))
        return
    change = s.analysis.speed_change
    echo(f"{s.name}: answers at {len(pts)} point{'s' * (len(pts) > 1)} (effort and power "
         + ("to the outermost configuration's speed)" if change == "range"
            else f"for a {100 * change:g} % speed change)"))
    width = max(12, *(len(p.text) + 2 for p in pts))
    echo(f"{'':<22}{'':<6}" + "".join(f"{p.text:>{width}}" for p in pts))
    for name, u, values in rows:
        cells = [questions.shown(float(v), u) for v in values]
        echo(f"{name:<22}{cells[0][1]:<6}" + "".join(
            f"{v:>{width}.5g}" if np.isfinite(v) else f"{'-':>{width}}" for v, _ in cells))
    echo(f"{'stable':<22}{'':<6}" + "".join(f"{('yes' if v else 'no'):>{width}}"
                                            for v in out["stable"]))


@solve_app.command("solve", help=SOLVE_HELP, short_help=SOLVE_SHORT)
@guarded
def solve(spec: Spec,
          unknown: Annotated[str, option("--unknown", help="The input to find, by its dotted "
                                         "key: governor.extension, design.ball_weight, "
                                         "governor.sleeve_friction, design.free_length ...")],
          target: Annotated[str, option("--target", help="FIGURE=VALUE: a figure at the point "
                                        "(speed, speed_rising, speed_falling, insensitiveness, "
                                        "controlling_force, spring_force, sleeve_force, effort, "
                                        "power, a link force: arm_tension ...) or over the "
                                        "range (range), e.g. 'speed=160 rpm'.")],
          point: Annotated[str | None, option("--at", help=POINT_HELP)] = None,
          between: Annotated[tuple[str, str] | None, option(
              "--between", metavar="<low> <high>", help="The values of the unknown to search "
              "between, e.g. --between '1 cm' '20 cm' (default: a factor of 8 either side of "
              "its value in the spec).")] = None,
          json_out: Json = False) -> None:
    from .. import questions
    from ..errors import GovoptError
    from ..spec import load_spec
    from ..units import parse_quantity

    s = load_spec(spec)
    pt = None if point is None else questions.parse_point(s.governor, point)
    name, sep, value = (p.strip() for p in target.partition("="))
    figures = questions.figure_names(s.governor)
    if not sep or name not in figures:
        raise GovoptError(f"--target {target!r}: expected FIGURE=VALUE with FIGURE one of "
                          f"{', '.join(figures)}")
    fu = questions.figure_unit(s.governor, name)
    dimension = questions.dimension_of(fu)
    try:
        goal = parse_quantity(value, dimension)
    except ValueError as exc:
        raise GovoptError(f"--target {target!r}: {exc}") from None
    unit, _ = questions.key_unit(s, unknown)
    bracket = None
    if between is not None:
        dim = questions.dimension_of(unit)
        try:
            bracket = tuple(parse_quantity(b, dim) for b in between)
        except ValueError as exc:
            raise GovoptError(f"--between: {exc}") from None
    found = questions.solve(s, unknown, name, goal, pt, bracket)
    where = f" at {pt.text}" if pt is not None else ""
    if json_out:
        echo(json.dumps({"spec": s.name, "unknown": unknown, "value": found.value,
                         "unit": found.unit, "target": {"figure": name, "at": point,
                                                        "value": goal},
                         "achieved": found.achieved, "bracket": list(found.bracket),
                         "evaluations": found.evaluations, "sign_changes": found.roots},
                        indent=2))
        return
    shown, u = questions.shown(found.value, found.unit)
    echo(f"{unknown} = {shown:.6g} {u}".rstrip())
    achieved, au = questions.shown(found.achieved, fu)
    echo(f"  {name}{where}: {achieved:.6g} {au} (target {value}); {found.evaluations} "
         f"evaluations over {questions.shown(found.bracket[0], found.unit)[0]:.4g} .. "
         f"{questions.shown(found.bracket[1], found.unit)[0]:.4g} {u}".rstrip())
    if found.roots > 1:
        echo(f"  note: the figure meets its target {found.roots} times in the bracket; this "
             "is the first (narrow it with --between for another)")
