"""`govopt spring`: the least-mass helical spring for a force and stiffness (an exact GP,
certified global), with a wire grade's allowables and the spring maker's checks."""

import json
import math
from typing import Annotated

import typer

from . import common
from .common import JSON_HELP, Command, echo, fail, guarded

SPRING_SHORT = ("Least-mass helical spring for a force and stiffness (an exact GP, certified "
                "global).")
SPRING_HELP = ("Least-mass helical spring for a force and stiffness (an exact GP, certified "
               "global); with --material the wire grade's allowables per diameter and the spring "
               "maker's checks (spring type, index and turn limits, fatigue load cycle).")

app = typer.Typer(add_completion=False)


def quantity(text: str | None, dimension: str, option: str, positive: bool = True):
    from ..units import UnitError, parse_quantity

    if text is None:
        return None
    try:
        value = parse_quantity(text, dimension)
    except UnitError as exc:
        fail(f"{option}: {exc}")
    if value < 0 or (positive and value == 0):
        fail(f"{option}: must be {'positive' if positive else 'zero or more'}, got {text!r}")
    return value


@app.command("spring", cls=Command, help=SPRING_HELP, short_help=SPRING_SHORT)
@guarded
def spring(
        force: Annotated[str, common.option(
            "--force", help="Largest working force, e.g. '606 kgf'.")],
        stiffness: Annotated[str, common.option(
            "--stiffness", help="Stiffness, e.g. '59.7 kgf/cm'.")],
        allowable_stress: Annotated[str | None, common.option(
            "--allowable-stress", help='Allowable shear stress k_s (required without --material; '
            'overrides its rule).')] = None,
        shear_modulus: Annotated[str | None, common.option(
            "--shear-modulus", help='Shear modulus G (required without --material).')] = None,
        density: Annotated[str | None, common.option(
            "--density", help="Wire density (default: the grade's, or 7850 kg/m^3).")] = None,
        correction: Annotated[str | None, common.option(
            "--correction", help="Stress correction: 'wahl', 'bergstrasser' or 'none' (default: "
            "'wahl'; with --material the rules' choice).")] = None,
        material: Annotated[str | None, common.option(
            "--material", help="Wire grade, e.g. 'EN10270-1 DH' "
            '(govopt/data/spring_materials.toml): allowables per wire diameter and the spring '
            "maker's checks.")] = None,
        tensile_strength: Annotated[str | None, common.option(
            "--tensile-strength", help='R_m of --material custom.')] = None,
        kind: Annotated[str, common.option(
            "--kind", help="Spring type: 'compression' or 'extension'.")] = 'compression',
        rules: Annotated[str, common.option(
            "--rules", help="Allowables and fatigue: 'EN13906' or 'Shigley'.")] = 'EN13906',
        index_min: Annotated[float, common.option(
            "--index-min", metavar='<float>', help='Least spring index D/d (EN 13906-1 scope and '
            "Shigley's preferred range: 4).")] = 4.0,
        index_max: Annotated[float, common.option(
            "--index-max", metavar='<float>', help="Largest spring index D/d (Shigley's "
            'preferred range: 12; EN 13906-1 allows 20).')] = 12.0,
        turns_min: Annotated[float, common.option(
            "--turns-min", metavar='<float>', help='Least active turns (3: fewer coil poorly and '
            'load unevenly).')] = 3.0,
        turns_max: Annotated[float | None, common.option(
            "--turns-max", metavar='<float>', help='Most active turns.')] = None,
        min_force: Annotated[str | None, common.option(
            "--min-force", help='Least working force (extension: the initial tension stays below '
            'it).')] = None,
        fatigue_min_force: Annotated[str | None, common.option(
            "--fatigue-min-force", help='Least force of the fatigue load cycle (with '
            '--fatigue-max-force).')] = None,
        fatigue_max_force: Annotated[str | None, common.option(
            "--fatigue-max-force", help='Largest force of the fatigue load cycle.')] = None,
        min_fatigue_safety: Annotated[float, common.option(
            "--min-fatigue-safety", metavar='<float>', help='Required fatigue safety.')] = 1.0,
        life: Annotated[float, common.option(
            "--life", metavar='<float>', help='Required life, cycles.')] = 10000000.0,
        peened: Annotated[bool, common.flag(
            "--peened/--no-peened", help='Shot-peened wire (fatigue).')] = False,
        ends: Annotated[str, common.option(
            "--ends", help='Compression spring ends (EN 13906-1).')] = 'closed_ground',
        seating: Annotated[str, common.option(
            "--seating", help='Compression spring seating for buckling.')] = 'fixed-fixed',
        max_outer_diameter: Annotated[str | None, common.option(
            "--max-outer-diameter", help="Envelope, e.g. '10 cm'.")] = None,
        max_body_length: Annotated[str | None, common.option(
            "--max-body-length", help='Close-wound body length limit.')] = None,
        min_surge_frequency: Annotated[str | None, common.option(
            "--min-surge-frequency", help="e.g. '40 Hz'.")] = None,
        min_wire_diameter: Annotated[str | None, common.option(
            "--min-wire-diameter", help="Thinnest wire, e.g. '2 mm'.")] = None,
        max_wire_diameter: Annotated[str | None, common.option(
            "--max-wire-diameter", help="Thickest wire, e.g. '6 mm'.")] = None,
        objective: Annotated[str, common.option(
            "--objective", help="What to minimise: 'mass' (all coils of wire), 'volume' ((n + "
            "end coils) D d^2, as the optimisation literature), 'solid length', 'outer diameter'."
            )] = 'mass',
        min_inside_diameter: Annotated[str | None, common.option(
            "--min-inside-diameter", help='Least inside diameter D - d (over a rod).')] = None,
        max_free_length: Annotated[str | None, common.option(
            "--max-free-length", help='Longest free length (compression: the least free length '
            'that keeps the coils clear at --force).')] = None,
        max_solid_length: Annotated[str | None, common.option(
            "--max-solid-length", help='Longest solid length (compression).')] = None,
        max_stiffness: Annotated[str | None, common.option(
            "--max-stiffness", help='Largest stiffness: --stiffness to this is accepted (a '
            'stiffness range instead of one value).')] = None,
        json_out: Annotated[bool, common.flag("--json", help=JSON_HELP)] = False,
) -> None:
    """Least-mass helical spring for a force and stiffness (an exact GP, certified global);
    with --material the wire grade's allowables per diameter and the spring maker's checks
    (spring type, index and turn limits, fatigue load cycle)."""
    from ..optimize.spring_sizing import size_spring
    from ..springs import helical, materials

    for option, value, allowed in (
            ("--correction", correction, (None, "wahl", "bergstrasser", "none")),
            ("--material", material, materials.GRADES),
            ("--kind", kind, ("compression", "extension")),
            ("--rules", rules, materials.METHODS), ("--ends", ends, tuple(helical.END_FORMS)),
            ("--seating", seating, tuple(helical.SEATING)),
            ("--objective", objective, SPRING_OBJECTIVES)):
        if value is not None and value not in allowed:
            fail(f"{option}: expected one of {', '.join(map(repr, allowed))}, got {value!r}")
    for option, value, what in (("--life", life, "a positive number of cycles"),
                                ("--min-fatigue-safety", min_fatigue_safety,
                                 "a positive safety factor"),
                                ("--index-min", index_min, "a positive spring index"),
                                ("--index-max", index_max, "a positive spring index"),
                                ("--turns-min", turns_min, "a positive number of turns"),
                                ("--turns-max", turns_max, "a positive number of turns")):
        if value is not None and not (math.isfinite(value) and value > 0.0):
            fail(f"{option}: expected {what}, got {value!r}")
    if material is not None and shear_modulus is None and not isinstance(
            materials.material(material, tensile_strength=1.0).G, float):
        fail(f"--shear-modulus: required with --material {material!r}, whose shear modulus "
              "varies with the wire diameter")
    if material is None:
        for option, value in (("--allowable-stress", allowable_stress),
                              ("--shear-modulus", shear_modulus)):
            if value is None:
                fail(f"{option}: required without --material")
    values = dict(
        k_s=quantity(allowable_stress, "stress", "--allowable-stress"),
        G=quantity(shear_modulus, "stress", "--shear-modulus"),
        density=quantity(density, "density", "--density") or (None if material else 7850.0),
        D_out_max=quantity(max_outer_diameter, "length", "--max-outer-diameter"),
        L_body_max=quantity(max_body_length, "length", "--max-body-length"),
        f_surge_min=quantity(min_surge_frequency, "frequency", "--min-surge-frequency"),
        d_min=quantity(min_wire_diameter, "length", "--min-wire-diameter"),
        d_max=quantity(max_wire_diameter, "length", "--max-wire-diameter"),
        Di_min=quantity(min_inside_diameter, "length", "--min-inside-diameter"),
        L0_max=quantity(max_free_length, "length", "--max-free-length"),
        Lc_max=quantity(max_solid_length, "length", "--max-solid-length"),
        **{k: v for k, v in (("n_min", turns_min), ("n_max", turns_max),
                             ("C_min", index_min), ("C_max", index_max)) if v is not None})
    F, k = quantity(force, "force", "--force"), quantity(stiffness, "stiffness", "--stiffness")
    cycle = None
    if (fatigue_min_force is None) != (fatigue_max_force is None):
        fail("--fatigue-min-force and --fatigue-max-force: give both (the load cycle)")
    if fatigue_min_force is not None:
        cycle = (quantity(fatigue_min_force, "force", "--fatigue-min-force", positive=False),
                 quantity(fatigue_max_force, "force", "--fatigue-max-force"))
        if cycle[0] > cycle[1]:
            fail(f"--fatigue-min-force: expected at most --fatigue-max-force "
                  f"({fatigue_max_force}), got {fatigue_min_force!r}")
    k_max = quantity(max_stiffness, "stiffness", "--max-stiffness")
    if k_max is not None and k_max < k:
        fail(f"--max-stiffness: expected at least --stiffness ({stiffness}), "
              f"got {max_stiffness!r}")
    F_min = quantity(min_force, "force", "--min-force", positive=False) or 0.0
    if F_min > F:
        fail(f"--min-force: expected at most --force ({force}), got {min_force!r}")
    try:
        sizing = size_spring(
            F, k, grade=material, kind=kind, rules=rules, correction=correction,
            tensile_strength=quantity(tensile_strength, "stress", "--tensile-strength"),
            F_min=F_min, fatigue=cycle,
            min_fatigue_safety=min_fatigue_safety, peened=peened, cycles=life, ends=ends,
            seating=seating, objective=objective,
            stiffness_max=k_max, **values)
    except ValueError as exc:
        fail(str(exc))
    sol = sizing.solution
    if not sol.ok:
        why = sizing.diagnosis
        fail("no spring meets these requirements" + (f": {why}" if why else ""))
    out = {"wire_diameter_m": sol.d, "coil_radius_m": sol.r, "active_turns": sol.n,
           "mass_kg": sol.mass, "end_coils": sol.end_coils,
           "active_mass_kg": sol.mass * sol.n / (sol.n + sol.end_coils),
           "stiffness_N_per_m": sol.stiffness, "shear_stress_Pa": sol.stress,
           "wahl_factor": sol.wahl_factor, "spring_index": sol.index,
           "surge_frequency_Hz": sol.surge_frequency, "sensitivities": sol.sensitivities,
           "objective": sol.objective_name, "objective_value": sol.objective,
           "active": sol.active, "global_optimum": sizing.certified,
           "lower_bound": sizing.lower_bound, "gap_to_bound": sizing.gap,
           "stress_correction": sol.correction,
           "duality_gap_log": sol.certificate.get("duality_gap_log")}
    if material is not None:
        out.update({"material": material, "kind": kind,
                    "free_length_m": sizing.free_length,
                    "initial_tension_N": sizing.initial_tension,
                    "checks": [c.to_dict() for c in sizing.checks], "notes": sizing.notes})
    if json_out:
        from ..jsonable import jsonable

        echo(json.dumps(jsonable(out), indent=2))
    else:
        _print_spring(sol, out, sizing, material, kind)
    failed = [c.name for c in sizing.checks if not c.passed] if material is not None else []
    if failed:  # as evaluate: the spring is reported, and exit code 1 says a check failed
        echo(f"{len(failed)} of {len(sizing.checks)} checks failed: {'; '.join(failed)}",
              err=True)
        raise SystemExit(1)


#: ``govopt spring --objective`` choices (:data:`govopt.optimize.spring_gp.OBJECTIVES`)
SPRING_OBJECTIVES = ("mass", "volume", "solid length", "outer diameter")

#: how each objective is printed (scale from SI, unit)
_OBJECTIVE_UNITS = {"mass": (1e3, "g"), "volume": (1e6, "cm^3"), "solid length": (1e3, "mm"),
                    "outer diameter": (1e3, "mm")}

#: SI units of the spring checks and the units they are printed in (scale, unit)
_CHECK_UNITS = {"Pa": (1e-6, "MPa"), "m": (1e3, "mm"), "N/m": (1e-3, "N/mm"), "N": (1.0, "N")}


def _verdict(check, sizing) -> str:
    """PASS or FAIL; a fatigue row past its data's life says so (strength held constant)."""
    from ..springs.checks import DATA_CYCLES

    verdict = "PASS" if check.passed else "FAIL"
    if "fatigue" in check.name and sizing.cycles > DATA_CYCLES:
        verdict += (f" (life {sizing.cycles:.3g} cycles is beyond the data's {DATA_CYCLES:.0e}:"
                    " extrapolated)")
    return verdict


def _print_spring(sol, out, sizing, material, kind) -> None:
    """The text report of `govopt spring`."""
    from ..springs.helical import correction_factor

    k_b = float(correction_factor(sol.index, "bergstrasser"))
    factor = {"none": "uncorrected stress", "wahl": f"Wahl K {sol.wahl_factor:.4f}",
              "bergstrasser": f"Bergstraesser k {k_b:.4f}"}[sol.correction]
    echo(f"d = {sol.d * 1e3:.4f} mm, D = {2e3 * sol.r:.4f} mm, n = {sol.n:.4f} active "
          f"+ {sol.end_coils:.3g} end coils, mass = {sol.mass * 1e3:.5g} g, stress = "
          f"{sol.stress / 1e6:.2f} MPa (index {sol.index:.2f}, {factor})")
    scale, unit = _OBJECTIVE_UNITS[sol.objective_name]
    if sol.objective_name != "mass":
        echo(f"least {sol.objective_name}: {sol.objective * scale:.6g} {unit}")
    if sizing.certified:
        claim = "global optimum certified"
    elif math.isfinite(sizing.gap):
        claim = (f"optimal within {100 * sizing.gap:.3g} % of a certified bound "
                 f"({sizing.lower_bound * scale:.5g} {unit})")
    else:
        claim = "no certified bound (the relaxation was not solved to optimality)"
    echo(f"{claim} (duality gap in log space {out['duality_gap_log']:.2g}); active in the "
          f"last GP: {', '.join(sol.active)}")
    for name, value in sol.sensitivities.items():
        if abs(value) > 1e-6:
            echo(f"  +1 % on {name} -> {value:+.3f} % {sol.objective_name}")
    if material is not None:
        extra = (f"free length {sizing.free_length * 1e3:.2f} mm (coils clear at the force)"
                 if kind == "compression" else
                 f"initial tension {sizing.initial_tension:.4g} N")
        echo(f"{kind} spring of {material}: {extra}; checks (value, limit, margin, source):")
        for c in sizing.checks:
            scale, unit = _CHECK_UNITS.get(c.unit, (1.0, c.unit))
            echo(f"  {c.name}: {c.value * scale:.6g} {c.sense} {c.limit * scale:.6g} {unit}, "
                  f"margin {100 * c.margin:+.2f} % {_verdict(c, sizing)} - {c.source}")
        for note in sizing.notes:
            echo(f"  note: {note}")


