"""`govopt spring` (design) and `govopt spring check`: a helical spring sized on its own, or
checked as it is, from options, a spring spec file or both (options override the file). Plain
Python values in, a report out; the command line only parses (:mod:`govopt.commands.spring`).

A spring spec is TOML with units as a governor spec (``error: FILE: KEY: expected ...``, exit
code 2): a ``name``, a ``description`` and a ``[spring]`` table whose keys are the command's
options with underscores (``force = "500 N"``, ``max_outer_diameter = "40 mm"``, ``turns_min =
3``, ``peened = true``). ``problem = "sandgren-1990"`` states Sandgren's mixed-discrete spring
(:func:`govopt.optimize.spring_literature.solve_sandgren`) with its data as keys. A spec whose
``[spring]`` gives a spring's geometry (``wire_diameter``, ``mean_diameter`` ...) is checked
(`govopt spring check SPEC`), and `govopt spring -o SPEC` writes one of the designed spring.
Every key, and so every option, is declared once in :mod:`govopt.spring_keys` (meaning, unit,
default, range) and read by its declaration (:func:`merged`); the options' help, the reference
``docs/reference/spring-spec.md``, the templates and the JSON Schema are generated from it.

The design's problem statements beyond a force and a stiffness:

- installed lengths and working stroke: ``length_2`` (``L2``, the length at ``force``),
  ``length_1`` (``L1`` at ``min_force``) and ``stroke`` (``H = L1 - L2``); two of them, or the
  stroke with the forces, give the stiffness ``(F2 - F1) / H``. At ``L2`` the coils stay clear
  (EN 13906-1: ``L2 >= L_n = L_c + S_a``, a GP row) and the free length is ``L2 + F2 / R``;
- free-length and solid-length limits, inside diameter over a rod, outside diameter in a bore,
  a stiffness range, a least surge frequency and wire-diameter bounds: GP rows
  (:mod:`govopt.optimize.spring_gp`);
- objectives: mass (all coils of wire, the helix rise included), solid length, outside
  diameter, the literature's volume ``(n + end coils) D d^2`` and the stored energy per mass
  ``F^2 / (2 R m)`` (its reciprocal minimised, a posynomial);
- a spring that can be ordered: ``wire_sizes`` (``"preferred"``: the grade's standard's
  diameters, :func:`govopt.springs.materials.wire_sizes`; a list; ``"continuous"``) and
  ``coil_step`` (coils on 0.25, 0.5 or 1): the best such spring by a bounded enumeration
  (:mod:`govopt.optimize.spring_catalogue`); the grade's table by default when a grade is
  given.

Either way the spring is reported from :func:`govopt.springs.assessment.assess` (the same rows
for a designed and a checked spring), in the units the input was written in
(:func:`govopt.report.spring_report.shown_units`), with the optimiser's record where something
was optimised (:class:`govopt.optimize.record.Record`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import GovoptError
from .reader import Reader, read_spec_data
from .spring_keys import (
    CHECK,
    DESCRIPTION,
    DESIGN,
    FORMS,
    GEOMETRY,
    NAME,
    OBJECTIVES,
    SANDGREN,
    defaults,
    form,
    top_table,
)

#: where a person finds the keys of each form of ``[spring]`` (errors on an unknown key)
GUIDE = "docs/reference/spring-spec.md under"


@dataclass
class Outcome:
    """What `govopt spring` prints (its text, its JSON), the checks the verdict reads (exit
    code 1 when one fails), the spring's assessment and the optimiser's record (None for a
    check), the problem's values (SI, defaults applied), the units shown, the files written,
    and the inputs read (:class:`govopt.reader.Entry` s, each with its declared meaning) with
    the spec file they came from (None: the options alone)."""

    name: str
    command: str
    assessment: Any
    record: Any
    checks: list
    shown: Any
    values: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    text: str = ""
    data: dict = field(default_factory=dict)
    sizing: Any = None
    written: list = field(default_factory=list)
    entries: list = field(default_factory=list)
    spec: str | None = None

    @property
    def failed(self) -> list[str]:
        return [c.name for c in self.checks if not c.passed]

    @property
    def total(self) -> int:
        return len(self.checks)


class _Where:
    """Where each value came from: ``--option`` or ``FILE: spring.key`` (error messages)."""

    def __init__(self, file: str | None, from_file: set[str], command: str = "spring"):
        self.file, self.from_file, self.command = file, from_file, command

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
            raise GovoptError(f"{option}: required{also} (see 'govopt {self.command} --help')")
        raise GovoptError(f"{self.file}: spring.{key}: required (or {option}){also}")


def _option_reader(options: dict, entries: list):
    """The options given, read as a spec table: errors name the option (``--force: ...``)."""
    class Options(Reader):
        def key(self, name: str) -> str:
            return "--" + name.replace("_", "-")

    return Options("", _listed(options), "", entries)


def _listed(table: dict) -> dict:
    """``wire_sizes`` written as one text, ``"2.5 mm, 2.8 mm, 3 mm"`` (an option's, or a
    spec's), as the list it is (a word of its choices stays a word)."""
    value = table.get("wire_sizes")
    if isinstance(value, str):
        words = value.strip()
        items = [x.strip() for x in words.split(",") if x.strip()]
        choices = DESIGN.key("wire_sizes").options()
        table["wire_sizes"] = words if words in choices or not items else items
    return table


def merged(spec: str | Path | None, options: dict, command: str = "design"
           ) -> tuple[dict, _Where, str | None, str, list]:
    """The spec's values overridden by the options given (not None), each read by its
    declaration (:mod:`govopt.spring_keys`) through :class:`govopt.reader.Reader` (units,
    types, ranges; unknown keys with a did-you-mean), in SI; the :class:`_Where` naming each
    value's origin, the literature problem, the name and the entries read (for the units
    shown)."""
    entries: list = []
    given = {k: v for k, v in options.items() if v is not None}
    opts, sp, problem, name = _option_reader(given, entries), None, None, ""
    if "name" in given:
        name = opts.read(NAME)
        del given["name"]
    shape = command  # the form of [spring] read: "design", "check" or a problem's name
    if spec is not None:
        data = read_spec_data(spec)
        if command == "design" and isinstance(data.get("spring"), dict):
            shape = form(data["spring"])  # a problem's; a spring's geometry is refused below
    table = FORMS[shape][0]
    if spec is not None:
        top = Reader(str(spec), data, "", entries, top_table(table.meaning))
        top.guide = f"{GUIDE} {shape}:"
        written = top.read(NAME) or Path(spec).stem
        name = name or written  # --name over the spec's
        top.read(DESCRIPTION)
        if not top.has("spring"):
            top.fail("spring", "missing (required: a [spring] table)")
        sp = top.sub("spring", declared=table)
        top.finish()
        if command == "design" and shape == "check":
            geometry = next(k.name for k in GEOMETRY if sp.has(k.name))
            sp.fail(geometry, f"a spring's geometry: check it with 'govopt spring check {spec}' "
                              "(a design spec states forces and limits)")
        _listed(sp.table)
        if table is SANDGREN:
            problem = sp.read(SANDGREN.key("problem"))
        _another_forms_key(sp, shape)
        sp.used.update(table.names)  # read below, where no option overrides it
        sp.finish()
    keys = [k for k in table.keys if k.name != "problem"]
    from_file = set() if sp is None else {k.name for k in keys if sp.has(k.name)} - set(given)
    where = _Where(None if spec is None else str(spec), from_file,
                   "spring check" if command == "check" else "spring")
    for key in given:
        if key not in table.names:
            where.fail(key, f"not a value of the problem {problem!r} of {spec} (its values: "
                            f"{', '.join(sorted(k.name for k in keys))})")
    values = {}
    for key in keys:
        rd = opts if key.name in given else sp if key.name in from_file else None
        if rd is not None:
            values[key.name] = rd.read(key, required=False)
    if isinstance(values.get("wire_sizes"), tuple):
        values["wire_sizes"] = tuple(sorted(values["wire_sizes"]))
    return values, where, problem, name, entries


def _another_forms_key(sp: Reader, shape: str) -> None:
    """A key of another form of ``[spring]`` than ``shape`` (:data:`govopt.spring_keys.FORMS`:
    ``stiffness`` in a spring to check) named as such, not as an unknown key."""
    def what(name: str) -> str:
        spring, command = FORMS[name]
        also = f', with problem = "{name}"' if spring is SANDGREN else ""
        return f"{spring.meaning.split(':')[0]} ({command}{also})"

    for key in map(str, sp.table):
        other = next((n for n, (spring, _) in FORMS.items() if key in spring.names), None)
        if key not in FORMS[shape][0].names and other is not None:
            sp.fail(key, f"not a key of {what(shape)}; it is one of {what(other)}")


def _outputs(xlsx, plots, output, stem: str, replace: bool, inputs) -> None:
    """Every file of the run planned and checked against the others and the input before
    anything is computed or written (:func:`govopt.report.spring_outputs.check_outputs`)."""
    from .report import spring_outputs as so

    so.check_outputs(xlsx, plots, stem, replace=replace, inputs=inputs, output=output)


def _write(out: Outcome, xlsx, plots, output, stem: str, replace: bool, spec=None) -> Outcome:
    from .report import spring_outputs as so

    if output is not None:
        out.written.append(so.write_check_spec(out, output, replace=replace,
                                               drawing=_drawing(out)))
    if xlsx is not None:
        from .report.excel.book import command_line

        command = command_line(f"govopt spring {out.command} {spec or ''} --xlsx {xlsx} "
                               "(through the Python API)")
        out.written.append(so.write_workbook(out, xlsx, replace=replace, command=command))
    if plots is not None:
        out.written += so.write_plots(out, plots, stem, replace=replace)
    return out


def _drawing(out: Outcome) -> tuple[int, tuple[int, int, int]] | None:
    """How a designed spring's lengths are written (:func:`govopt.report.spring_outputs.
    drawn_length`): the fewest significant digits, from 4 (a drawing's), and the rounding of
    the wire, the mean diameter and the free length (nearest first, then up and down) at
    which the spring read back fails no check the design
    passes; None (every digit) for a checked spring, which is written as it was given."""
    from dataclasses import replace
    from itertools import product

    from .report.spring_outputs import drawn_length
    from .springs.assessment import table

    if out.command != "design":
        return None
    a, sp = out.assessment, out.assessment.spring
    failed = set(a.failed)
    for digits in range(4, 16):
        for ways in product((0, 1, -1), repeat=3):
            d, D, L0 = (drawn_length(out.shown, x, digits, w)[1]
                        for x, w in zip((sp.d, sp.D, sp.L0), ways, strict=True))
            rows, _ = table(replace(sp, d=d, D=D, L0=L0), a.mat, a.loads, a.rules)
            if {c.name for c in rows if not c.passed} <= failed:
                return digits, ways
    return None


def run(spec: str | Path | None = None, *, json_out: bool = False, xlsx=None, plots=None,
        output=None, replace: bool = False, **options) -> Outcome:
    """`govopt spring [SPEC] [options]` (module docstring): the sized spring's report (text or
    JSON) and its failed checks; with ``xlsx`` a workbook, with ``plots`` a folder of plots
    (:mod:`govopt.report.spring_outputs`), with ``output`` a spec of the spring for `govopt
    spring check`, all planned and checked before the run and written after it (existing files
    only with ``replace``). Raises :class:`GovoptError` (exit code 2) on bad input or when no
    spring meets the requirements: nothing is written then."""
    values, where, problem, name, entries = merged(spec, options)
    stem = Path(spec).stem if spec is not None else "spring"
    if (xlsx is not None or plots is not None or output is not None) and problem:
        raise GovoptError(f"--xlsx, --plots, -o: not for the literature problem {problem!r} "
                          "(its answer is the printed one)")
    if problem == "sandgren-1990":
        return _render(_sandgren(values, where, name or stem), json_out)
    from .report.files import overwrite_option

    with overwrite_option("--replace"):  # this command's --force is the spring's force
        _outputs(xlsx, plots, output, stem, replace, [] if spec is None else [spec])
        out = _design({**defaults(DESIGN), **values}, where, name, entries)
        out.spec = where.file
        _render(out, json_out)
        return _write(out, xlsx, plots, output, stem, replace, spec)


def check(spec: str | Path | None = None, *, json_out: bool = False, xlsx=None, plots=None,
          replace: bool = False, **options) -> Outcome:
    """`govopt spring check [SPEC] [options]`: a given spring's report (module docstring),
    the same as a designed spring's without the optimiser's record; files as :func:`run`."""
    values, where, _, name, entries = merged(spec, options, "check")
    stem = Path(spec).stem if spec is not None else "spring"
    from .report.files import overwrite_option

    with overwrite_option("--replace"):
        _outputs(xlsx, plots, None, stem, replace, [] if spec is None else [spec])
        out = _check({**defaults(CHECK), **values}, where, name, entries)
        out.spec = where.file
        _render(out, json_out)
        return _write(out, xlsx, plots, None, stem, replace, spec)


def _render(out: Outcome, json_out: bool) -> Outcome:
    from .report import spring_report as sr

    out.data = sr.to_json(out)
    if json_out:
        import json

        out.text = json.dumps(out.data, indent=2)
    else:
        out.text = sr.to_text(out)
    return out


# ---------------------------------------------------------------------------- shared rules


def _require(v: dict, where: _Where, *keys) -> None:
    for key in keys:
        if v.get(key) is None:
            where.missing(key)


#: option pairs whose least must not exceed their largest (a range)
PAIRS = (("index_min", "index_max", ""), ("turns_min", "turns_max", ""),
         ("min_wire_diameter", "max_wire_diameter", "m"), ("stiffness", "max_stiffness", "N/m"))


def _pairs(v: dict, where: _Where) -> None:
    """An inverted range is an error naming both ends (not an infeasible spring)."""
    for lo, hi, unit in PAIRS:
        a, b = v.get(lo), v.get(hi)
        if a is not None and b is not None and a > b:
            u = f" {unit}" if unit else ""
            raise GovoptError(f"{where(lo)} {a:.6g}{u} and {where(hi)} {b:.6g}{u}: the least "
                              f"is above the largest (expected {lo} <= {hi})")


def _material_rules(v: dict, where: _Where) -> None:
    """What a wire grade must come with, and what needs one: the tensile strength of
    ``custom`` only, a load cycle's fatigue only with a grade's data; without a grade, the
    allowable and the modulus."""
    material = v.get("material")
    if v.get("tensile_strength") is not None and material != "custom":
        where.fail("tensile_strength", "applies to --material custom only (a grade's R_m is its "
                   "standard's), got " + (f"material {material!r}" if material
                                          else "no --material"))
    if material == "custom" and v.get("tensile_strength") is None:
        where.missing("tensile_strength", " with material 'custom'")
    cycle = [k for k in ("fatigue_min_force", "fatigue_max_force") if v.get(k) is not None]
    if cycle and material is None:
        where.fail(cycle[0], "a load cycle's fatigue needs a wire grade's fatigue data: give "
                             "--material (e.g. 'EN10270-1 DH')")
    if len(cycle) == 1:
        raise GovoptError(f"{where('fatigue_min_force')} and {where('fatigue_max_force')}: "
                          "give both (the load cycle)")
    if cycle and v["fatigue_min_force"] > v["fatigue_max_force"]:
        where.fail("fatigue_min_force", f"expected at most {where('fatigue_max_force')}, "
                                        f"got {v['fatigue_min_force']:.6g} N")
    if material is None and v.get("catalogue") is None:  # a catalogue's rows name theirs
        _require(v, where, "allowable_stress", "shear_modulus")


def _rules(v: dict):
    """The standard's choices; the load dynamic (S_a x1.5) as ``load`` says, else where a
    load cycle is given."""
    from .springs.assessment import Rules

    load = v.get("load") or ("dynamic" if v.get("fatigue_max_force") is not None else "static")
    return Rules(method=v["rules"], allowable=v.get("allowable_stress"),
                 correction=v.get("correction") or (
                     None if v.get("material") or v.get("catalogue") else "wahl"),
                 peened=v["peened"], seating=v["seating"],
                 index=(v["index_min"], v["index_max"]),
                 fatigue_safety=v["min_fatigue_safety"], cycles=v["life"],
                 dynamic=load == "dynamic", tolerance_grade=v.get("tolerance_grade", 2))


def _material(v: dict):
    from .springs import materials

    if v.get("material") is None:
        return materials.given(v["shear_modulus"], v.get("density") or 7850.0,
                               v.get("elastic_modulus"))
    return materials.material(v["material"], tensile_strength=v.get("tensile_strength"),
                              G=v.get("shear_modulus"), E=v.get("elastic_modulus"),
                              density=v.get("density"))


def _outcome(name, command, assessment, record, entries, v, notes=(), sizing=None) -> Outcome:
    """The outcome of a designed or checked spring; a spring without a name (options alone)
    named by what it is, in the units of the input."""
    from .report.spring_report import shown_units

    shown = shown_units(entries)
    if not name:
        sp = assessment.spring
        grade = f", {v['material']}" if v.get("material") else ""
        if command == "design":
            name = (f"{sp.kind} spring for {shown.text(v['force'], 'N', 4)} at "
                    f"{shown.text(v['stiffness'], 'N/m', 4)}{grade}")
        else:
            name = (f"{sp.kind} spring d {shown.text(sp.d, 'm', 4)}, D "
                    f"{shown.text(sp.D, 'm', 4)}, n {assessment.value('active coils'):.4g}"
                    f"{grade}")
    return Outcome(name, command, assessment, record, list(assessment.checks), shown, v,
                   [*notes, *assessment.notes], sizing=sizing, entries=list(entries))


# ---------------------------------------------------------------------------- design


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


def _catalogue(v: dict, where: _Where):
    """The wire sizes to order from (m) and their source, or None for any wire: the grade's
    table by default when a grade is given (:func:`govopt.springs.materials.wire_sizes`)."""
    from .springs import materials

    sizes = v.get("wire_sizes") or ("preferred" if v.get("material") else "continuous")
    if sizes == "continuous":
        if v.get("coil_step") is not None:
            where.fail("coil_step", "a step of coils needs wire sizes to order from "
                                    "(--wire-sizes preferred or a list)")
        return None, ""
    if sizes == "preferred":
        return materials.wire_sizes(v.get("material"))
    return sizes, "the wire diameters given (" + where("wire_sizes") + ")"


def _design(v: dict, where: _Where, name: str, entries) -> Outcome:
    from .optimize.spring_catalogue import size_orderable_spring
    from .optimize.spring_sizing import size_spring
    from .springs.assessment import assess

    _require(v, where, "force")
    _lengths(v, where)
    if v.get("stiffness") is None:
        where.missing("stiffness", " (or the stroke: length_1 and length_2, or stroke, with "
                                   "the forces)")
    _pairs(v, where)
    _material_rules(v, where)
    F, F_min = v["force"], v.get("min_force") or 0.0
    if F_min > F:
        where.fail("min_force", f"expected at most the force ({F:.6g} N), got {F_min:.6g} N")
    if v.get("length_2") is not None and v["kind"] != "compression":
        where.fail("length_2", "installed lengths are for compression springs")
    if v.get("loops") is not None and v["kind"] != "extension":
        where.fail("loops", "loops are an extension spring's (--kind extension); a compression "
                            "spring has --ends")
    if v["objective"] == "solid length" and v["kind"] != "compression":
        where.fail("objective", "a compression spring's (an extension spring is close-wound: "
                                "its body is solid; minimise its mass or outer diameter)")
    if v.get("ends") is not None and v["kind"] != "compression":
        where.fail("ends", "end forms are a compression spring's; an extension spring has "
                           "--loops")
    if v.get("catalogue") is not None:
        return _from_catalogue(v, where, name, entries)
    wires, source = _catalogue(v, where)
    material = v.get("material")
    cycle = None
    if v.get("fatigue_min_force") is not None:
        cycle = (v["fatigue_min_force"], v["fatigue_max_force"])
    density = v.get("density") or (None if material else 7850.0)
    bounds = dict(
        k_s=v.get("allowable_stress"), G=v.get("shear_modulus"), density=density,
        D_out_max=v.get("max_outer_diameter"), L_body_max=v.get("max_body_length"),
        f_surge_min=v.get("min_surge_frequency"), d_min=v.get("min_wire_diameter"),
        d_max=v.get("max_wire_diameter"), Di_min=v.get("min_inside_diameter"),
        L0_max=v.get("max_free_length"), Lc_max=v.get("max_solid_length"),
        n_min=v["turns_min"], C_min=v["index_min"], C_max=v["index_max"],
        **({"n_max": v["turns_max"]} if v.get("turns_max") is not None else {}))
    order = {} if wires is None else dict(wires=wires, coil_step=v.get("coil_step") or 0.5,
                                          wire_source=source)
    try:
        sizing = (size_orderable_spring if order else size_spring)(
            F, v["stiffness"], grade=material, kind=v["kind"], rules=v["rules"],
            correction=v.get("correction"), tensile_strength=v.get("tensile_strength"),
            F_min=F_min, fatigue=cycle, min_fatigue_safety=v["min_fatigue_safety"],
            peened=v["peened"], cycles=v["life"], ends=v.get("ends") or v.get("loops"),
            seating=v["seating"], objective=OBJECTIVES[v["objective"]],
            stiffness_max=v.get("max_stiffness"), L2=v.get("length_2"), **order, **bounds)
    except ValueError as exc:
        raise GovoptError(str(exc)) from None
    if not sizing.solution.ok or sizing.spring is None:
        why = sizing.diagnosis
        raise GovoptError("no spring meets these requirements" + (f": {why}" if why else ""))
    a = assess(sizing.spring, sizing.mat, sizing.loads, sizing.rules)
    return _outcome(name, "design", a, sizing.record(), entries, v, sizing=sizing)


def _from_catalogue(v: dict, where: _Where, name: str, entries) -> Outcome:
    """The lightest spring of a maker's catalogue meeting the requirements
    (:mod:`govopt.spring_stock`): the same report as a designed spring's."""
    from . import spring_stock as stock
    from .springs.assessment import Loads

    for key in ("length_1", "length_2", "wire_sizes", "coil_step"):
        if v.get(key) is not None:
            where.fail(key, "not with a catalogue (its springs are picked at the forces and "
                            "the stiffness)")
    if v["kind"] != "compression":
        where.fail("catalogue", "a catalogue of compression springs (not --kind extension)")
    file = v["catalogue"]
    if where("catalogue") != "--catalogue" and file != stock.SAMPLE:
        file = str(Path(where.file).parent / file)  # a spec's file: beside the spec
    cycle = None
    if v.get("fatigue_min_force") is not None:
        cycle = (v["fatigue_min_force"], v["fatigue_max_force"])
    loads = Loads(v.get("min_force") or 0.0, v["force"], cycle)
    item, a, counts, notes = stock.pick(stock.read(file), v, _rules(v), loads,
                                        v.get("material"))
    source = Path(file).name if file != stock.SAMPLE else "sample (made up, no maker's)"
    return _outcome(name or f"part {item.part} of the catalogue {source}", "design", a,
                    stock.record(a, counts, source, notes), entries, v)


# ---------------------------------------------------------------------------- check


def _check(v: dict, where: _Where, name: str, entries) -> Outcome:
    """A given spring (module docstring): its geometry, material, loads and rules read and
    checked for consistency, then assessed."""
    from .springs import compression as hc
    from .springs import extension as he
    from .springs import helical as hx
    from .springs import tolerances as tl
    from .springs.assessment import Loads, Spring, assess, extension_free_length

    _require(v, where, "wire_diameter")
    _pairs(v, where)
    _material_rules(v, where)
    d = v["wire_diameter"]
    given = [k for k in ("mean_diameter", "outer_diameter") if v.get(k) is not None]
    if len(given) != 1:
        raise GovoptError(f"{where('mean_diameter')} or {where('outer_diameter')}: give one"
                          + (" (got both)" if given else " (the coil's diameter)"))
    D = v["mean_diameter"] if given[0] == "mean_diameter" else v["outer_diameter"] - d
    if not D > d:
        where.fail(given[0], f"expected a coil wider than the wire ({d * 1e3:.6g} mm), got a "
                             f"mean diameter of {D * 1e3:.6g} mm")
    mat, kind = _material(v), v["kind"]
    G, E = float(mat.shear_modulus(d)), float(mat.elastic_modulus(d))
    notes = []
    if kind == "compression":
        for key in ("loops", "initial_tension"):
            if v.get(key) is not None:
                where.fail(key, "an extension spring's (--kind extension)")
        _require(v, where, "active_coils", "free_length")
        n, ends = v["active_coils"], v.get("ends") or "closed_ground"
        total, inactive = v.get("total_coils"), hc.end_coils(ends)
        if total is not None and (total < n or (total == n and inactive > 0)):
            where.fail("total_coils", f"expected {'more than' if inactive > 0 else 'at least'} "
                                      f"the active coils ({n:g}) with {ends} ends, got "
                                      f"{total:g}")
        end_coils = inactive if total is None else total - n
        spring = Spring(kind, d, D, n, end_coils, v["free_length"], ends)
        Lc = float(hc.solid_length(tl.max_wire_diameter(d, mat.grade), n + end_coils, ends))
        if v["free_length"] < Lc:
            where.fail("free_length", f"expected at least the solid length L_c = "
                                      f"{Lc * 1e3:.6g} mm ({n + end_coils:g} coils of "
                                      f"{ends} ends, EN 13906-1), got "
                                      f"{v['free_length'] * 1e3:.6g} mm")
        R = float(hx.stiffness(d, D, n, G))
    else:
        if v.get("ends") is not None:
            where.fail("ends", "a compression spring's; an extension spring has --loops")
        loops = v.get("loops") or "full_loop"
        if v.get("total_coils") is not None:  # an extension spring's body coils
            n_b = v["total_coils"]
            n = n_b + G / E
            if v.get("active_coils") is not None and not math.isclose(
                    v["active_coils"], n, rel_tol=1e-9):
                where.fail("total_coils", f"an extension spring's body coils n_b, whose active "
                                          f"coils are n_b + G/E = {n:.6g} (Shigley section "
                                          f"10-11), not {where('active_coils')} "
                                          f"{v['active_coils']:g}: give one of them")
        else:
            _require(v, where, "active_coils")
            n_b = v["active_coils"] - G / E
            n = v["active_coils"]
        if not n_b > 0.0:
            where.fail("active_coils", f"expected more than G/E = {G / E:.4g} (the body's "
                                       f"coils n_b = n - G/E), got {n:g}")
        R = float(hx.stiffness(d, D, n, G))
        body = float(he.extension_body_length(d, n_b))
        if v.get("free_length") is not None and v["free_length"] < body:
            where.fail("free_length", f"expected at least the close-wound body (n_b + 1) d = "
                                      f"{body * 1e3:.6g} mm, got {v['free_length'] * 1e3:.6g} mm")
        F0 = v.get("initial_tension")
        if F0 is None:  # at most the least force (0 N where none is given)
            least = v.get("min_force")
            least = least if least is not None else (
                math.inf if v.get("length_1") is not None else 0.0)
            lo, hi = he.initial_tension_range(D / d)
            middle = float(hx.force_at_stress(0.5 * (lo + hi), d, D))
            F0 = min(middle, least)
            notes.append(f"initial tension not given: {F0:.4g} N, "
                         + ("the middle of Shigley's preferred range (eq. (10-40))"
                            if F0 == middle else
                            f"the least working force (the middle of Shigley's preferred range "
                            f"(eq. (10-40)), {middle:.4g} N, is above it)"))
        L0 = v.get("free_length") or float(extension_free_length(d, D, n_b, loops))
        spring = Spring(kind, d, D, n_b, 0.0, L0, loops, F0)
    F1, F2 = _forces(v, where, spring, R)
    cycle = None
    if v.get("fatigue_min_force") is not None:
        cycle = (v["fatigue_min_force"], v["fatigue_max_force"])
    a = assess(spring, mat, Loads(F1, F2, cycle), _rules(v))
    return _outcome(name, "check", a, None, entries, v, notes)


def _forces(v: dict, where: _Where, spring, R: float) -> tuple[float, float]:
    """The working forces ``F1 <= F2``: given, or from the working lengths and the rate."""
    sign = 1.0 if spring.kind == "compression" else -1.0
    F0 = spring.F0

    def at(length):
        return (F0 if sign < 0 else 0.0) + R * sign * (spring.L0 - length)

    out = []
    for force, length in (("min_force", "length_1"), ("force", "length_2")):
        if v.get(force) is not None and v.get(length) is not None:
            raise GovoptError(f"{where(force)} and {where(length)}: give one (the other "
                              "follows from the rate)")
        L = v.get(length)
        if L is not None and sign < 0 and L < spring.L0:
            where.fail(length, f"expected at least the free length ({spring.L0 * 1e3:.6g} mm: "
                               f"an extension spring is close-wound below it), got "
                               f"{L * 1e3:.6g} mm")
        if L is not None and sign > 0 and L > spring.L0:
            where.fail(length, f"expected at most the free length ({spring.L0 * 1e3:.6g} mm: "
                               f"beyond it the spring would pull), got {L * 1e3:.6g} mm")
        out.append(v.get(force) if L is None else at(L))
    F1, F2 = out
    if F2 is None:
        where.missing("force", " (or the working length: length_2)")
    if not F2 > 0.0:  # as a force of 0 N is refused
        where.fail("length_2", f"expected a length under load, got the free length "
                               f"({spring.L0 * 1e3:.6g} mm: no working force)")
    F1 = 0.0 if F1 is None else F1
    if not F1 <= F2:
        where.fail("min_force" if v.get("min_force") is not None else "length_1",
                   f"expected at most the force at L2 ({F2:.6g} N), got {F1:.6g} N")
    return F1, F2


# ---------------------------------------------------------------------------- Sandgren


def _sandgren(raw: dict, where: _Where, name: str) -> Outcome:
    """Sandgren's (1990) mixed-discrete spring with the spec's data (SI in ``raw``; inch, lbf,
    psi inside, as the problem is stated): the exact optimum by enumeration, reported as every
    spring (its own constraints g1..g8 the checks); an infeasible variant gets the conflicting
    data keys from its continuous relaxation's diagnosis."""
    from .optimize import spring_literature as sl
    from .springs import materials
    from .springs.assessment import Loads, Rules, Spring, assess

    inch, lbf = 0.0254, 4.4482216152605
    scale = {"length": inch, "force": lbf, "stress": lbf / inch**2}
    p = dict(sl.SANDGREN)
    for key, q in raw.items():  # SI (read by merged) -> the problem's units
        p[sl.SANDGREN_DATA[key]] = q / scale[SANDGREN.key(key).kind]
    if not p["F_load"] < p["F_max"]:
        where.fail("min_force", "expected below the force")
    best = sl.solve_sandgren(p)
    if not math.isfinite(best.objective):
        raise GovoptError(sl.sandgren_diagnosis(p, where))
    record = sl.sandgren_record(p, best)
    d, D, N = best.d * inch, best.D * inch, best.N
    L0 = sl.sandgren_free_length(p, best) * inch
    spring = Spring("compression", d, D, float(N), 2.0, L0, "closed_ground")
    mat = materials.given(p["G"] * lbf / inch**2, 7850.0)
    loads = Loads(p["F_load"] * lbf, p["F_max"] * lbf)
    a = assess(spring, mat, loads, Rules(allowable=p["S"] * lbf / inch**2, correction="wahl",
                                         index=(3.0, math.inf)))
    from .report.spring_report import IMPERIAL, METRIC, Shown

    shown = Shown({**METRIC, **IMPERIAL, "m": ("in", inch), "N": ("lbf", lbf),
                   "Pa": ("psi", lbf / inch**2), "N/m": ("lbf/in", lbf / inch)})
    notes = ["the figures with a steel wire's density, 7850 kg/m^3 (the problem states none)"]
    return Outcome(name, "sandgren-1990", a, record, sl.sandgren_checks(p, best), shown, raw,
                   notes)


__all__ = ["Outcome", "check", "merged", "run"]
