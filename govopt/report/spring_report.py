"""The text and JSON of `govopt spring` (a designed spring, a checked one, a literature
problem): one shape for all, read from the spring's assessment
(:func:`govopt.springs.assessment.assess`), its checks and, where something was optimised,
the optimiser's record (:class:`govopt.optimize.record.Record`). Formats only: nothing is
computed here but the units a person reads.

The JSON is SI, each key naming its unit (govopt's rule), with the same keys whatever the path
(:data:`JSON_KEYS`; a figure that does not apply is ``null``, ``optimisation`` is ``null``
where nothing was optimised). The text speaks the units the input was written in
(:class:`Shown`: a spring given in inches and pounds-force is reported in in, lbf, psi,
lbf/in, lb).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..jsonable import jsonable
from ..verdict import Figure

#: the top-level keys of every `govopt spring` JSON, in order
JSON_KEYS = ("name", "command", "spring", "material", "lengths_and_energy", "dynamics",
             "fatigue", "tolerances", "working_points", "checks", "optimisation", "notes")

#: SI unit -> (shown unit, SI per shown unit) when the input gives no other
METRIC = {"m": ("mm", 1e-3), "Pa": ("MPa", 1e6), "N/m": ("N/mm", 1e3), "N": ("N", 1.0),
          "kg": ("g", 1e-3), "J": ("J", 1.0), "Hz": ("Hz", 1.0), "rad": ("deg", math.pi / 180),
          "kg/m^3": ("kg/m^3", 1.0), "m^3": ("cm^3", 1e-6), "J/kg": ("J/kg", 1.0),
          "%": ("%", 1.0), "cycles": ("cycles", 1.0), "": ("", 1.0)}
#: the units of a spring given in inches (the length) and pounds-force (the force)
IMPERIAL = {"kg": ("lb", 0.45359237), "J": ("in*lbf", 0.0254 * 4.4482216152605),
            "kg/m^3": ("lb/in^3", 0.45359237 / 0.0254**3), "m^3": ("in^3", 0.0254**3)}
_WRITTEN = re.compile(r"\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s+(\S.*?)\s*$")


@dataclass(frozen=True)
class Shown:
    """SI unit -> (the unit a person reads, SI per that unit)."""

    table: dict = field(default_factory=lambda: dict(METRIC))

    def __call__(self, value, si: str):
        """``(value, unit)`` in the shown unit (text and numbers other than floats as
        they are)."""
        unit, per = self.table.get(si, (si, 1.0))
        if value is None or isinstance(value, bool | str | tuple | list):
            return value, unit
        return value / per, unit

    def text(self, value, si: str, digits: int = 5) -> str:
        """``"12.5 mm"``: the value in its shown unit."""
        v, unit = self(value, si)
        if isinstance(v, float) and math.isinf(v):
            return "infinite"
        if isinstance(v, float):
            v = f"{v:.{digits}g}"
        return f"{v} {unit}".rstrip()


def shown_units(entries) -> Shown:
    """The units the input was written in (:class:`govopt.reader.Entry` s, in reading order):
    the first length's and force's units (a stress's own, else MPa or psi), and from them the
    stiffness (force/length), mass, energy and volume (lb, in*lbf, in^3 where the length is in
    inches or feet)."""
    from ..units import parse_quantity

    first: dict[str, str] = {}
    dims = {"m": "length", "N": "force", "Pa": "stress", "N/m": "stiffness"}
    for e in entries:
        match = _WRITTEN.match(str(e.written))
        if e.unit in dims and e.unit not in first and match:
            first[e.unit] = match[1]
    table = dict(METRIC)

    def use(si: str, unit: str) -> None:
        try:
            table[si] = (unit, parse_quantity(f"1 {unit}", dims[si]))
        except ValueError:  # a unit the parser reads only with a number before it
            pass

    if "m" not in first and "/" in first.get("N/m", ""):  # a length from a stiffness: lbf/in
        first["m"] = first["N/m"].split("/")[-1]
    for si in ("m", "N", "Pa", "N/m"):
        if si in first:
            use(si, first[si])
    length, force = table["m"][0], table["N"][0]
    if "N/m" not in first and (length, force) != ("mm", "N"):
        use("N/m", f"{force}/{length}")
    imperial = length in ("in", "inch", "inches", "ft", "foot", "feet")
    if imperial:
        table.update(IMPERIAL)
        if "Pa" not in first:
            use("Pa", "psi")
    return Shown(table)


def _value(f: Figure):
    """A figure's value for JSON: numbers (nan as null, inf with its flag), words as they are."""
    return f.value


def section_json(section: dict) -> dict:
    """A section of figures as JSON: each figure under its key (its unit in the key)."""
    return {f.key: _value(f) for f in section.values()}


def to_json(out) -> dict:
    """The JSON of an outcome of `govopt spring` (:data:`JSON_KEYS`, SI)."""
    a = out.assessment
    data = {"name": out.name, "command": out.command}
    for name, section in a.sections.items():
        data[name.replace(" ", "_")] = section_json(section)
    data["working_points"] = [section_json(p) for p in a.points]
    data["checks"] = [c.to_dict() for c in out.checks]
    data["optimisation"] = None if out.record is None else out.record.to_dict()
    data["notes"] = list(out.notes)
    return jsonable({k: data[k] for k in JSON_KEYS})


def _rows(section: dict, shown: Shown, skip=()) -> list[str]:
    """``name (symbol)  value unit`` of every figure that applies (nan left out)."""
    out = []
    for key, f in section.items():
        if key in skip or (isinstance(f.value, float) and math.isnan(f.value)):
            continue
        label = f.name + (f" {f.symbol}" if f.symbol else "")
        note = f"  ({f.note})" if f.note else ""
        out.append(f"  {label:<40} {shown.text(f.value, f.unit)}{note}")
    return out


def _points(a, shown: Shown) -> list[str]:
    """The working points as a table: length, deflection, force, stresses (uncorrected tau
    and corrected tau_k, EN 13906-1)."""
    cols = ("length", "deflection", "force", "stress", "corrected stress")
    heads = ("length", "deflection", "force", "stress tau", "tau_k = k tau")
    units = [shown(0.0, a.points[0][c].unit)[1] for c in cols]
    lines = [f"  {'working point':<26}" + "".join(f"{c:>14}" for c in heads),
             f"  {'':<26}" + "".join(f"{u:>14}" for u in units)]
    for p in a.points:
        cells = "".join(f"{'-':>14}" if math.isnan(p[c].value) else
                        f"{shown(p[c].value, p[c].unit)[0]:>14.5g}" for c in cols)
        lines.append(f"  {p['point'].value:<26}{cells}")
    lines.append(f"  {a.points[0]['corrected stress'].source}")
    return lines


def verdict(check) -> str:
    return "PASS" if check.passed else "FAIL"


def _num(x: float) -> str:
    return "infinite" if math.isinf(x) else f"{x:.6g}"


def check_lines(out, shown: Shown) -> list[str]:
    """One line per check: value, sense, limit (shown units), margin, verdict, source."""
    lines = []
    for c in out.checks:
        (v, unit), (lim, _) = shown(c.value, c.unit), shown(c.limit, c.unit)
        lines.append(f"  {c.name}: {_num(v)} {c.sense} {_num(lim)}{' ' + unit if unit else ''}"
                     f", margin {100 * c.margin:+.2f} % {verdict(c)} - {c.source}")
    return lines


def record_lines(record, shown: Shown) -> list[str]:
    """The optimiser's record: the objective and claim, the bound, the active limits and the
    sensitivities (elasticities, per cent per per cent)."""
    obj = record.objective
    word = "least" if obj.sense == "minimise" else "most"
    bound = shown.text(record.bound, obj.unit, 6) if math.isfinite(record.bound) else "none"
    lines = [f"Optimisation: {word} {obj.name} {shown.text(record.value, obj.unit, 6)}, "
             f"{record.claim(bound)}",
             f"  method: {record.method}; solver {record.solver or '-'}"
             + (f", {record.solve_time_s:.3g} s" if math.isfinite(record.solve_time_s) else ""),
             f"  certified {'lower' if obj.sense == 'minimise' else 'upper'} bound: {bound}; "
             f"active: {', '.join(record.active) or 'none'}"]
    if record.search:
        lines.append("  search: " + ", ".join(f"{k} {v}" for k, v in record.search.items()))
    if record.sensitivities:
        lines.append(f"  sensitivities of {record.sensitivities_of} (d ln {obj.name} / d ln "
                     "limit: per cent per +1 % on the limit):")
        lines += [f"    +1 % on {k} -> {v:+.3f} % {obj.name}"
                  for k, v in record.sensitivities.items()]
    lines += [f"  note: {n}" for n in record.notes]
    return lines


def to_text(out) -> str:
    """The text report: the spring, its working points, what it does, the optimiser's record
    (where one), the checks, the fatigue cycle, the tolerances, the notes."""
    a, shown = out.assessment, out.shown
    sp = a.sections["spring"]
    what = {"design": "designed", "check": "checked"}.get(out.command, out.command)
    lines = [f"{out.name} ({what} {sp['kind'].value} spring)",
             f"  wire: {a.mat.grade}" + (f" ({a.mat.standard})" if a.mat.standard else "")]
    lines += _rows(sp, shown, skip=("kind",))
    lines += _rows(a.sections["lengths and energy"], shown)
    lines += _rows(a.sections["dynamics"], shown)
    lines.append("")
    lines += _points(a, shown)
    if out.record is not None:
        lines += ["", *record_lines(out.record, shown)]
    lines += ["", f"Checks ({len(out.checks)}; value, limit, margin, source):",
              *check_lines(out, shown)]
    if a.loads.cycle is not None:
        lines += ["", "Fatigue load cycle:", *_rows(a.sections["fatigue"], shown)]
    lines += ["", f"Tolerances (EN 15800 grade {a.rules.tolerance_grade}) and what they do:",
              *_rows(a.sections["tolerances"], shown, skip=("quality grade",))]
    lines += [f"note: {n}" for n in out.notes]
    return "\n".join(lines)
