"""`govopt spring`: a helical spring sized on its own, from options, a spring spec file or both
(options override the file). Plain Python values in, a report out; the command line only
parses (:mod:`govopt.cli`).

A spring spec is TOML with units as a governor spec (``error: FILE: KEY: expected ...``, exit
code 2): a ``name``, a ``description`` and a ``[spring]`` table whose keys are the command's
options with underscores (``force = "500 N"``, ``max_outer_diameter = "40 mm"``, ``turns_min =
3``, ``peened = true``). ``problem = "sandgren-1990"`` states Sandgren's mixed-discrete spring
(:func:`govopt.optimize.spring_literature.solve_sandgren`) with its data as keys.

The problem statements beyond a force and a stiffness:

- installed lengths and working stroke: ``length_2`` (``L2``, the length at ``force``),
  ``length_1`` (``L1`` at ``min_force``) and ``stroke`` (``H = L1 - L2``); two of them, or the
  stroke with the forces, give the stiffness ``(F2 - F1) / H``. At ``L2`` the coils stay clear
  (EN 13906-1: ``L2 >= L_n = L_c + S_a``, a GP row) and the free length is ``L2 + F2 / R``;
- free-length and solid-length limits, inside diameter over a rod, outside diameter in a bore,
  a stiffness range, a least surge frequency and wire-diameter bounds: GP rows
  (:mod:`govopt.optimize.spring_gp`);
- objectives: mass (all coils of wire), solid length, outside diameter, the literature's
  volume ``(n + end coils) D d^2`` and the stored energy per mass ``F^2 / (2 R m)`` (its
  reciprocal minimised, a posynomial).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import GovoptError
from .reader import Reader, read_spec_data

#: option -> (kind, detail): ``quantity`` (its dimension), ``number`` (what it must be: a
#: positive finite number), ``choice`` (None: the allowed values are looked up), ``flag``,
#: ``text``. The spec's ``[spring]`` keys are these names.
OPTIONS: dict[str, tuple[str, Any]] = {
    "force": ("quantity", "force"), "stiffness": ("quantity", "stiffness"),
    "max_stiffness": ("quantity", "stiffness"),
    "allowable_stress": ("quantity", "stress"), "shear_modulus": ("quantity", "stress"),
    "density": ("quantity", "density"), "tensile_strength": ("quantity", "stress"),
    "correction": ("choice", ("wahl", "bergstrasser", "none")), "material": ("choice", None),
    "kind": ("choice", ("compression", "extension")), "rules": ("choice", None),
    "ends": ("choice", None), "seating": ("choice", None), "objective": ("choice", None),
    "index_min": ("number", "a positive spring index"),
    "index_max": ("number", "a positive spring index"),
    "turns_min": ("number", "a positive number of turns"),
    "turns_max": ("number", "a positive number of turns"),
    "min_force": ("quantity", "force"), "fatigue_min_force": ("quantity", "force"),
    "fatigue_max_force": ("quantity", "force"),
    "min_fatigue_safety": ("number", "a positive safety factor"),
    "life": ("number", "a positive number of cycles"), "peened": ("flag", None),
    "max_outer_diameter": ("quantity", "length"), "max_body_length": ("quantity", "length"),
    "min_surge_frequency": ("quantity", "frequency"),
    "min_wire_diameter": ("quantity", "length"), "max_wire_diameter": ("quantity", "length"),
    "min_inside_diameter": ("quantity", "length"), "max_free_length": ("quantity", "length"),
    "max_solid_length": ("quantity", "length"), "length_1": ("quantity", "length"),
    "length_2": ("quantity", "length"), "stroke": ("quantity", "length"),
}
#: the spec-only keys of Sandgren's problem (``problem = "sandgren-1990"``)
SANDGREN_KEYS = {"force": "force", "min_force": "force", "allowable_stress": "stress",
                 "shear_modulus": "stress", "max_free_length": "length",
                 "min_wire_diameter": "length", "max_outer_diameter": "length",
                 "max_preload_deflection": "length", "min_working_deflection": "length"}
PROBLEMS = ("sandgren-1990",)

#: defaults of the options (applied after the spec and the options are merged)
DEFAULTS = {"kind": "compression", "rules": "EN13906", "index_min": 4.0, "index_max": 12.0,
            "turns_min": 3.0, "min_fatigue_safety": 1.0, "life": 1e7, "peened": False,
            "ends": "closed_ground", "seating": "fixed-fixed", "objective": "mass"}

#: ``govopt spring --objective`` choices and the GP objective each minimises
OBJECTIVES = {"mass": "mass", "volume": "volume", "solid length": "solid length",
              "outer diameter": "outer diameter", "energy per mass": "mass per energy"}
#: how each objective is printed (scale from SI, unit)
OBJECTIVE_UNITS = {"mass": (1e3, "g"), "volume": (1e6, "cm^3"), "solid length": (1e3, "mm"),
                   "outer diameter": (1e3, "mm"), "mass per energy": (1.0, "kg/J")}
#: SI units of the spring checks and the units they are printed in (scale, unit)
CHECK_UNITS = {"Pa": (1e-6, "MPa"), "m": (1e3, "mm"), "N/m": (1e-3, "N/mm"), "N": (1.0, "N")}


@dataclass
class Outcome:
    """What `govopt spring` prints, and the checks that failed (exit code 1 when any)."""

    text: str
    data: dict
    failed: list[str] = field(default_factory=list)
    total: int = 0
    sizing: Any = None
    #: the problem's values (SI, defaults applied), its name and the optimality claim
    values: dict = field(default_factory=dict)
    name: str = "spring"
    claim: str = ""
    #: the files written (--xlsx, --plots)
    written: list = field(default_factory=list)


class _Where:
    """Where each value came from: ``--option`` or ``FILE: spring.key`` (error messages)."""

    def __init__(self, file: str | None, from_file: set[str]):
        self.file, self.from_file = file, from_file

    def __call__(self, key: str) -> str:
        if key in self.from_file:
            return f"{self.file}: spring.{key}"
        return "--" + key.replace("_", "-")

    def fail(self, key: str, message: str):
        raise GovoptError(f"{self(key)}: {message}")

    def missing(self, key: str, also: str = "") -> None:
        """A required value given nowhere: named in the spec when there is one."""
        option = "--" + key.replace("_", "-")
        if self.file is None:  # as the parser's own errors: where to look
            raise GovoptError(f"{option}: required{also} (see 'govopt spring --help')")
        raise GovoptError(f"{self.file}: spring.{key}: required (or {option}){also}")


def _option_reader(options: dict, entries: list):
    """The options given, read as a spec table: errors name the option (``--force: ...``)."""
    class Options(Reader):
        def key(self, name: str) -> str:
            return "--" + name.replace("_", "-")

    return Options("", options, "", entries)


def _read(rd, key: str, problem: str | None):
    """One value through :class:`govopt.reader.Reader` (units, types, ranges; errors ``FILE:
    spring.KEY: ...`` or ``--key: ...``), in SI."""
    if problem:  # the literature problem's data: positive quantities
        return rd.quantity(key, SANDGREN_KEYS[key], required=False)
    kind, detail = OPTIONS[key]
    if kind == "quantity":  # the lower forces of a cycle may be zero
        return rd.quantity(key, detail, required=False,
                           nonnegative=key in ("min_force", "fatigue_min_force"))
    if kind == "number":
        return rd.number(key, required=False)
    if kind == "flag":
        return rd.boolean(key, None)
    return rd.choice(key, _choices(key), None)


def _choices(key: str):
    from .springs import helical, materials

    return {"material": materials.GRADES, "rules": materials.METHODS,
            "ends": tuple(helical.END_FORMS), "seating": tuple(helical.SEATING),
            "objective": tuple(OBJECTIVES)}.get(key) or OPTIONS[key][1]


def _lengths(v: dict, where: _Where) -> None:
    """Installed lengths and stroke (module docstring): the stiffness they give, checked
    against a given one; ``L1`` from ``L2`` and ``H`` (and the other way)."""
    L1, L2, H = v.get("length_1"), v.get("length_2"), v.get("stroke")
    if L1 is not None and L2 is not None:
        if not L1 > L2:
            where.fail("length_1", f"expected longer than the installed length at the force "
                                   f"({where('length_2')}), got {L1 * 1e3:.6g} mm")
        if H is not None and not math.isclose(H, L1 - L2, rel_tol=1e-9):
            where.fail("stroke", f"expected {where('length_1')} - {where('length_2')} = "
                                 f"{(L1 - L2) * 1e3:.6g} mm (or give two of the three), got "
                                 f"{H * 1e3:.6g} mm")
        H = v["stroke"] = L1 - L2
    elif L1 is not None and H is not None:
        v["length_2"] = L1 - H
        if not v["length_2"] > 0.0:
            where.fail("stroke", f"expected shorter than {where('length_1')}")
    elif L1 is not None:
        where.fail("length_1", f"give {where('length_2')} or {where('stroke')} with it")
    if H is None:
        return
    F1 = v.get("min_force") or 0.0
    rate = (v["force"] - F1) / H
    if not rate > 0.0:
        where.fail("min_force", "expected below the force (the stroke compresses the spring)")
    if v.get("stiffness") is not None and not math.isclose(v["stiffness"], rate, rel_tol=1e-6):
        where.fail("stiffness", f"contradicts the forces and the stroke, which give "
                                f"{rate * 1e-3:.6g} N/mm (give one of them)")
    v["stiffness"] = rate


def merged(spec: str | Path | None, options: dict) -> tuple[dict, _Where, str | None, str]:
    """The spec's values overridden by the options given (not None), read through the
    governor spec's :class:`govopt.reader.Reader` (unknown keys with a did-you-mean, units,
    types), in SI; the :class:`_Where` naming each value's origin, the literature problem and
    the name."""
    entries: list = []
    given = {k: v for k, v in options.items() if v is not None}
    opts, sp, problem, name = _option_reader(given, entries), None, None, "spring"
    if spec is not None:
        top = Reader(str(spec), read_spec_data(spec), "", entries)
        name = top.text("name") or Path(spec).stem
        top.text("description")
        if not top.has("spring"):
            top.fail("spring", "missing (required: a [spring] table)")
        sp = top.sub("spring")
        top.finish()
        problem = sp.choice("problem", PROBLEMS, None)
        for key in SANDGREN_KEYS if problem else OPTIONS:
            sp.raw(key, False)  # the keys allowed here
        sp.finish()
    allowed = SANDGREN_KEYS if problem else OPTIONS
    from_file = set() if sp is None else {k for k in allowed if sp.has(k)} - set(given)
    where = _Where(None if spec is None else str(spec), from_file)
    for key in given:
        if key not in allowed:
            where.fail(key, f"not a value of the problem {problem!r} of {spec} (its "
                            f"values: {', '.join(sorted(SANDGREN_KEYS))})")
    values = {}
    for key in allowed:
        rd = opts if key in given else sp if key in from_file else None
        if rd is not None:
            values[key] = _read(rd, key, problem)
    return values, where, problem, name


def run(spec: str | Path | None = None, *, json_out: bool = False, xlsx=None, plots=None,
        replace: bool = False, **options) -> Outcome:
    """`govopt spring [SPEC] [options]` (module docstring): the sized spring's report (text or
    JSON) and its failed checks; with ``xlsx`` a workbook (the spring maker's sheet, the
    checks, the force-length table) and with ``plots`` a folder of plots
    (:mod:`govopt.report.spring_outputs`), checked before the run and written after it (existing
    files only with ``replace``). Raises :class:`GovoptError` (exit code 2) on bad input or
    when no spring meets the requirements: nothing is written then."""
    values, where, problem, name = merged(spec, options)
    stem = Path(spec).stem if spec is not None else "spring"
    if (xlsx is not None or plots is not None) and problem:
        raise GovoptError(f"--xlsx, --plots: not for the literature problem {problem!r} "
                          "(its answer is the printed one)")
    if problem == "sandgren-1990":
        return _sandgren(values, where, json_out)
    if xlsx is None and plots is None:
        return _size({**DEFAULTS, **values}, where, name, json_out)
    from .report import spring_outputs as so
    from .report.files import overwrite_option

    with overwrite_option("--replace"):  # this command's --force is the spring's force
        so.check_outputs(xlsx, plots, stem, replace=replace,
                         inputs=[] if spec is None else [spec])
        out = _size({**DEFAULTS, **values}, where, name, json_out)
        if xlsx is not None:
            from .report.excel.book import command_line

            command = command_line(f"govopt spring {spec or ''} --xlsx {xlsx} (through the "
                                   "Python API)")
            out.written.append(so.write_workbook(out, xlsx, replace=replace, command=command))
        if plots is not None:
            out.written += so.write_plots(out, plots, stem, replace=replace)
    return out


def _require(v: dict, where: _Where, *keys) -> None:
    for key in keys:
        if v.get(key) is None:
            where.missing(key)


def _size(v: dict, where: _Where, name: str, json_out: bool) -> Outcome:
    from .optimize.spring_sizing import size_spring
    from .springs import materials

    _require(v, where, "force")
    _lengths(v, where)
    if v.get("stiffness") is None:
        where.missing("stiffness", " (or the stroke: length_1 and length_2, or stroke, with "
                                   "the forces)")
    material = v.get("material")
    if material is not None and v.get("shear_modulus") is None and not isinstance(
            materials.material(material, tensile_strength=1.0).G, float):
        where.missing("shear_modulus", f" with material {material!r}, whose shear modulus "
                                       "varies with the wire diameter")
    if material is None:
        _require(v, where, "allowable_stress", "shear_modulus")
    cycle = None
    if (v.get("fatigue_min_force") is None) != (v.get("fatigue_max_force") is None):
        raise GovoptError(f"{where('fatigue_min_force')} and {where('fatigue_max_force')}: "
                          "give both (the load cycle)")
    if v.get("fatigue_min_force") is not None:
        cycle = (v["fatigue_min_force"], v["fatigue_max_force"])
        if cycle[0] > cycle[1]:
            where.fail("fatigue_min_force", f"expected at most {where('fatigue_max_force')}, "
                                            f"got {cycle[0]:.6g} N")
    k, k_max = v["stiffness"], v.get("max_stiffness")
    if k_max is not None and k_max < k:
        where.fail("max_stiffness", f"expected at least the stiffness ({k * 1e-3:.6g} N/mm), "
                                    f"got {k_max * 1e-3:.6g} N/mm")
    F, F_min = v["force"], v.get("min_force") or 0.0
    if F_min > F:
        where.fail("min_force", f"expected at most the force ({F:.6g} N), got {F_min:.6g} N")
    if v.get("length_2") is not None and v["kind"] != "compression":
        where.fail("length_2", "installed lengths are for compression springs")
    density = v.get("density") or (None if material else 7850.0)
    bounds = dict(
        k_s=v.get("allowable_stress"), G=v.get("shear_modulus"), density=density,
        D_out_max=v.get("max_outer_diameter"), L_body_max=v.get("max_body_length"),
        f_surge_min=v.get("min_surge_frequency"), d_min=v.get("min_wire_diameter"),
        d_max=v.get("max_wire_diameter"), Di_min=v.get("min_inside_diameter"),
        L0_max=v.get("max_free_length"), Lc_max=v.get("max_solid_length"),
        n_min=v["turns_min"], C_min=v["index_min"], C_max=v["index_max"],
        **({"n_max": v["turns_max"]} if v.get("turns_max") is not None else {}))
    try:
        sizing = size_spring(
            F, k, grade=material, kind=v["kind"], rules=v["rules"],
            correction=v.get("correction"), tensile_strength=v.get("tensile_strength"),
            F_min=F_min, fatigue=cycle, min_fatigue_safety=v["min_fatigue_safety"],
            peened=v["peened"], cycles=v["life"], ends=v["ends"], seating=v["seating"],
            objective=OBJECTIVES[v["objective"]], stiffness_max=k_max, L2=v.get("length_2"),
            **bounds)
    except ValueError as exc:
        raise GovoptError(str(exc)) from None
    sol = sizing.solution
    if not sol.ok:
        why = sizing.diagnosis
        raise GovoptError("no spring meets these requirements" + (f": {why}" if why else ""))
    data = _data(sizing, v, name)
    text = None if json_out else _text(sizing, data, v)
    if json_out:
        import json

        from .jsonable import jsonable

        text = json.dumps(jsonable(data), indent=2)
    failed = [c.name for c in sizing.checks if not c.passed] if material is not None else []
    return Outcome(text, data, failed, len(sizing.checks), sizing, v, name,
                   claim(sizing, bound_text(sizing, v)))


def _data(sizing, v: dict, name: str) -> dict:
    """The JSON of a sized spring: SI, each key's unit in its name."""
    sol = sizing.solution
    out = {"name": name, "wire_diameter_m": sol.d, "coil_radius_m": sol.r,
           "active_turns": sol.n, "mass_kg": sol.mass, "end_coils": sol.end_coils,
           "active_mass_kg": sol.mass * sol.n / (sol.n + sol.end_coils),
           "stiffness_N_per_m": sol.stiffness, "shear_stress_Pa": sol.stress,
           "wahl_factor": sol.wahl_factor, "spring_index": sol.index,
           "surge_frequency_Hz": sol.surge_frequency, "sensitivities": sol.sensitivities,
           "objective": v["objective"], "objective_value": _shown(sol.objective, v),
           "active": sol.active, "global_optimum": sizing.certified,
           # a bound on the objective as asked: the energy per mass's is an upper one
           ("upper_bound" if v["objective"] == "energy per mass" else "lower_bound"):
               _shown(sizing.lower_bound, v), "gap_to_bound": sizing.gap,
           "stress_correction": sol.correction,
           "duality_gap_log": sol.certificate.get("duality_gap_log"),
           "stored_energy_J": v["force"]**2 / (2.0 * sol.stiffness)}
    out["energy_per_mass_J_per_kg"] = out["stored_energy_J"] / sol.mass
    out["free_length_m"] = sizing.free_length  # spring_sizing.lengths: one computation
    if sizing.kind == "compression":
        out["solid_length_m"] = sizing.solid_length
    if v.get("length_2") is not None:
        # the stroke as given, else the spring's from F1 to F2 (L2 and a stiffness given)
        H = v.get("stroke") or (v["force"] - (v.get("min_force") or 0.0)) / sol.stiffness
        out.update(installed_length_2_m=v["length_2"], stroke_m=H,
                   installed_length_1_m=v["length_2"] + H)
    if v.get("material") is not None:
        out.update({"material": v["material"], "kind": v["kind"],
                    "initial_tension_N": sizing.initial_tension,
                    "checks": [c.to_dict() for c in sizing.checks], "notes": sizing.notes})
        life = body_life(sizing, v)
        if life is not None:  # inf: at least the data's life (JSON null with a flag)
            out["fatigue_life_cycles"] = life
    return out


def _shown(value: float, v: dict) -> float:
    """The objective as asked: the energy per mass is the reciprocal of what the GP minimises
    (J/kg); the others as minimised (SI)."""
    return 1.0 / value if v["objective"] == "energy per mass" else value


#: the body's fatigue row (:mod:`govopt.springs.checks`)
BODY_FATIGUE = "body fatigue safety factor"


def body_life(sizing, v: dict) -> float | None:
    """The estimated life (cycles) of the body under the fatigue load cycle
    (:func:`govopt.springs.fatigue.finite_life`: Basquin's line from ``0.9 S_su`` at 1e3
    cycles to the data's endurance at 1e7, read at the row's safety): ``inf`` when it passes
    at the data's life, nan below 1e3 cycles; None without a fatigue row."""
    from .springs import fatigue, materials
    from .springs.checks import DATA_CYCLES

    row = next((c for c in sizing.checks if c.name == BODY_FATIGUE), None)
    if row is None:
        return None
    mat = materials.material(v["material"], tensile_strength=v.get("tensile_strength"),
                             G=v.get("shear_modulus"), density=v.get("density"))
    Sse, Ssu = fatigue.reversed_endurance(mat, sizing.solution.d, v["rules"], v["peened"])
    return float(fatigue.finite_life(row.value, Sse, Ssu, DATA_CYCLES))


def _verdict(check, sizing, life=None) -> str:
    """PASS or FAIL; a fatigue row past its data's life says so (strength held constant), and
    the body's row below 1 (the stress above the data's endurance) its estimated finite
    life."""
    from .springs.checks import DATA_CYCLES

    verdict = "PASS" if check.passed else "FAIL"
    if "fatigue" in check.name and sizing.cycles > DATA_CYCLES:
        verdict += (f" (life {sizing.cycles:.3g} cycles is beyond the data's {DATA_CYCLES:.0e}:"
                    " extrapolated)")
    if check.name == BODY_FATIGUE and life is not None and check.value < 1.0:
        if math.isnan(life):
            verdict += " (estimated life below 1e3 cycles: quasi-static, no S-N estimate)"
        elif math.isfinite(life):
            enough = "enough for" if life >= sizing.cycles else "short of"
            verdict += (f" at the data's {DATA_CYCLES:.0e} cycles; estimated finite life "
                        f"{life:.3g} cycles, {enough} the required {sizing.cycles:.3g} (Basquin "
                        "line 0.9 S_su at 1e3 to the endurance at 1e7, Shigley 9th ed. §6-7)")
    return verdict


def bound_text(sizing, v: dict) -> str:
    """The certified bound in the objective's unit (the energy per mass: an upper bound)."""
    if v["objective"] == "energy per mass":
        return f"{1.0 / sizing.lower_bound:.5g} J/kg"
    scale, unit = OBJECTIVE_UNITS[OBJECTIVES[v["objective"]]]
    return f"{sizing.lower_bound * scale:.5g} {unit}"


def claim(sizing, bound: str) -> str:
    """What the optimiser can say of its design: a certified global optimum, or optimal within
    X % of a certified lower bound (``bound``: that bound as text), or no bound."""
    if sizing.certified:
        return "global optimum certified"
    if math.isfinite(sizing.gap):
        return f"optimal within {100 * sizing.gap:.3g} % of a certified bound ({bound})"
    return "no certified bound (the relaxation was not solved to optimality)"


def _text(sizing, data: dict, v: dict) -> str:
    """The text report: the spring first, then the certificate, sensitivities, checks."""
    from .springs.helical import correction_factor

    sol, lines = sizing.solution, []
    k_b = float(correction_factor(sol.index, "bergstrasser"))
    factor = {"none": "uncorrected stress", "wahl": f"Wahl K {sol.wahl_factor:.4f}",
              "bergstrasser": f"Bergstraesser k {k_b:.4f}"}[sol.correction]
    lines.append(f"d = {sol.d * 1e3:.4f} mm, D = {2e3 * sol.r:.4f} mm, n = {sol.n:.4f} active "
                 f"+ {sol.end_coils:.3g} end coils, mass = {sol.mass * 1e3:.5g} g, stress = "
                 f"{sol.stress / 1e6:.2f} MPa (index {sol.index:.2f}, {factor})")
    if v.get("length_2") is not None:
        lines.append(f"free length {data['free_length_m'] * 1e3:.2f} mm, installed "
                     f"L1 = {data['installed_length_1_m'] * 1e3:.2f} mm at "
                     f"{v.get('min_force') or 0.0:.4g} N, L2 = {v['length_2'] * 1e3:.2f} mm at "
                     f"{v['force']:.4g} N (stroke {data['stroke_m'] * 1e3:.2f} mm), stiffness "
                     f"{sol.stiffness * 1e-3:.4f} N/mm")
    objective, bound = v["objective"], bound_text(sizing, v)
    if objective == "energy per mass":
        lines.append(f"most stored energy per mass: {data['objective_value']:.6g} J/kg "
                     f"({data['stored_energy_J']:.4g} J at {v['force']:.4g} N)")
    else:
        scale, unit = OBJECTIVE_UNITS[OBJECTIVES[objective]]
        if objective != "mass":
            lines.append(f"least {objective}: {sol.objective * scale:.6g} {unit}")
    lines.append(f"{claim(sizing, bound)} (duality gap in log space "
                 f"{data['duality_gap_log']:.2g}); active in the last GP: "
                 f"{', '.join(sol.active)}")
    for name, value in sol.sensitivities.items():
        if abs(value) > 1e-6:
            lines.append(f"  +1 % on {name} -> {value:+.3f} % {sol.objective_name}")
    material, kind = v.get("material"), v["kind"]
    if material is not None:
        extra = (f"free length {sizing.free_length * 1e3:.2f} mm"
                 + (" (coils clear at the force)" if v.get("length_2") is None else "")
                 if kind == "compression" else
                 f"initial tension {sizing.initial_tension:.4g} N")
        lines.append(f"{kind} spring of {material}: {extra}; checks (value, limit, margin, "
                     "source):")
        life = data.get("fatigue_life_cycles")
        for c in sizing.checks:
            scale, unit = CHECK_UNITS.get(c.unit, (1.0, c.unit))
            lines.append(f"  {c.name}: {c.value * scale:.6g} {c.sense} {c.limit * scale:.6g} "
                         f"{unit}, margin {100 * c.margin:+.2f} % "
                         f"{_verdict(c, sizing, life)} - {c.source}")
        lines.extend(f"  note: {note}" for note in sizing.notes)
    return "\n".join(lines)


def _sandgren(raw: dict, where: _Where, json_out: bool) -> Outcome:
    """Sandgren's (1990) mixed-discrete spring with the spec's data (SI in ``raw``; inch, lbf,
    psi inside, as the problem is stated): the exact optimum by enumeration."""
    from .optimize.spring_literature import SANDGREN, solve_sandgren

    inch, lbf = 0.0254, 4.4482216152605
    scale = {"length": inch, "force": lbf, "stress": lbf / inch**2}
    names = {"force": "F_max", "min_force": "F_load", "allowable_stress": "S",
             "shear_modulus": "G", "max_free_length": "l_max", "min_wire_diameter": "d_min",
             "max_outer_diameter": "D_max", "max_preload_deflection": "delta_pm",
             "min_working_deflection": "delta_w"}
    p = dict(SANDGREN)
    for key, q in raw.items():  # SI (read by merged) -> the problem's units
        p[names[key]] = q / scale[SANDGREN_KEYS[key]]
    if not p["F_load"] < p["F_max"]:
        where.fail("min_force", "expected below the force")
    best = solve_sandgren(p)
    if not math.isfinite(best.objective):
        raise GovoptError("no spring meets these requirements: no wire of Sandgren's table "
                          "and whole number of coils satisfies g1..g8")
    data = {"problem": "sandgren-1990", "active_turns": best.N,
            "mean_coil_diameter_m": best.D * inch, "wire_diameter_m": best.d * inch,
            "objective": "volume pi^2 D d^2 (N + 2) / 4",
            "objective_value_in3": best.objective, "pairs_examined": best.checked,
            "global_optimum": True}
    if json_out:
        import json

        return Outcome(json.dumps(data, indent=2), data)
    text = (f"Sandgren (1990) mixed-discrete spring: N = {best.N} coils, D = {best.D:.5f} in, "
            f"d = {best.d} in (table), volume pi^2 D d^2 (N + 2) / 4 = {best.objective:.6g} in^3"
            f"\nglobal optimum certified by exhaustive bounded enumeration "
            f"({best.checked} wire/coil pairs examined, every one that could beat it)")
    return Outcome(text, data)


__all__ = ["DEFAULTS", "OBJECTIVES", "OPTIONS", "Outcome", "merged", "run"]
