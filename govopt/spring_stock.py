"""`govopt spring --catalogue FILE.csv`: the lightest spring of a maker's catalogue that meets
the requirements, each spring checked with the rows `govopt spring check` reads
(:func:`govopt.springs.assessment.assess`), as spring users pick a stock spring (ODOP:Spring
ships stock catalogues).

The catalogue is a CSV file of compression springs, one a row. Its first row names the columns,
each with its unit in brackets where it has one (``d (mm)``, ``rate (lbf/in)``), in any order:

==============  ===============================================================================
``part_number`` the maker's part number (text)
``d``           the wire diameter
``D`` or ``OD`` the mean coil diameter, or the outside diameter ``D + d``
``L0``          the free length
``n``           the active coils
``ends``        the end form (``closed_ground``, ``closed``, ``open``, ``open_ground`` ...);
                the total coils are ``n`` and the end form's inactive coils (EN 13906-1)
``material``    the wire grade (a grade of govopt's data, e.g. ``EN10270-1 SH``)
``rate``        the maker's rate (optional): the rate checked is ``G d^4 / (8 D^3 n)`` of the
                grade's ``G``; a maker's rate more than 2 % from it is named in a note
==============  ===============================================================================

A spring meets the requirements when every check passes at the working forces (the design's
rules: stresses, coil clash, buckling, index range ...), it fits the space given (outside and
inside diameter, free and solid length, wire and coil bounds) and its rate is the stiffness:
within ``stiffness .. max_stiffness`` when a range is given, else the stiffness lies in the
rate band EN 15800 allows the spring as made (its tolerance grade: ``rate least .. rate
largest``). Every spring of the file is checked: the lightest that passes is the catalogue's
optimum (its own bound). ``--catalogue sample`` reads the catalogue bundled with govopt
(``govopt/data/spring_catalogue_sample.csv``: made up, to show the format, no maker's).
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from .errors import GovoptError

#: the bundled catalogue's name (``--catalogue sample``)
SAMPLE = "sample"
#: column -> (dimension of :data:`govopt.units.SI_UNITS`, or "text"; meaning)
COLUMNS = {"part_number": ("text", "the maker's part number"),
           "d": ("length", "wire diameter"),
           "D": ("length", "mean coil diameter"),
           "OD": ("length", "outside diameter"),
           "L0": ("length", "free length"),
           "n": ("dimensionless", "active coils"),
           "ends": ("text", "end form"),
           "material": ("text", "wire grade"),
           "rate": ("stiffness", "the maker's rate")}
REQUIRED = ("part_number", "d", "L0", "n", "ends", "material")
#: a maker's rate this far from the grade's ``G d^4 / (8 D^3 n)`` is named in a note
RATE_NOTE = 0.02


@dataclass(frozen=True)
class StockSpring:
    """One row of a catalogue: the part number, the spring as drawn (SI), its grade, the
    maker's rate (N/m, None when not given) and its row in the file (1: the first spring)."""

    part: str
    spring: object
    grade: str
    rate: float | None
    row: int


def path_of(name: str) -> Path:
    """The file of ``--catalogue``: the bundled sample for :data:`SAMPLE`, else the path."""
    if name == SAMPLE:
        return Path(str(resources.files("govopt").joinpath(
            "data/spring_catalogue_sample.csv")))
    return Path(name)


def _header(where: str, text: str) -> tuple[str, str]:
    """A column's name and unit from its header, ``"d (mm)"`` -> ``("d", "mm")``."""
    m = re.fullmatch(r"\s*([A-Za-z_0-9]+)\s*(?:[(\[]\s*([^)\]]*?)\s*[)\]])?\s*", text)
    if m is None or m.group(1) not in COLUMNS:
        raise GovoptError(f"{where}: column {text.strip()!r}: expected one of "
                          f"{', '.join(COLUMNS)} (with its unit in brackets: 'd (mm)')")
    name, unit = m.group(1), m.group(2) or ""
    dim = COLUMNS[name][0]
    if dim not in ("text", "dimensionless") and not unit:
        raise GovoptError(f"{where}: column {name!r}: expected its unit in brackets, e.g. "
                          f"'{name} ({'N/mm' if dim == 'stiffness' else 'mm'})'")
    return name, unit


def read(name: str) -> list[StockSpring]:
    """The catalogue ``name`` (module docstring); a bad file, column or value is a
    :class:`GovoptError` naming the file, the row and the column (exit code 2)."""
    from .springs import compression as hc
    from .springs import materials as mt
    from .springs.assessment import Spring
    from .units import UnitError, parse_quantity

    path = path_of(name)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError, ValueError) as exc:  # ValueError: a NUL in the name
        raise GovoptError(f"--catalogue: cannot read {path}: "
                          f"{getattr(exc, 'strerror', None) or exc}") from None
    try:
        rows = list(csv.reader(text.splitlines()))
    except csv.Error as exc:
        raise GovoptError(f"{path}: expected CSV text: {exc}") from None
    rows = [r for r in rows if any(c.strip() for c in r) and not r[0].lstrip().startswith("#")]
    if not rows:
        raise GovoptError(f"{path}: expected a header row and springs, got an empty file")
    columns = [_header(f"{path}: row 1", c) for c in rows[0]]
    names = [c for c, _ in columns]
    missing = [c for c in REQUIRED if c not in names]
    if ("D" in names) == ("OD" in names):
        missing.append("D or OD (one of them)")
    if missing or len(set(names)) != len(names):
        raise GovoptError(f"{path}: row 1: expected the columns {', '.join(REQUIRED)} and D or "
                          f"OD, each once; missing or repeated: "
                          f"{', '.join(missing) or 'a repeated column'}")
    out = []
    for i, row in enumerate(rows[1:], start=1):
        where = f"{path}: spring {i}"
        if len(row) != len(columns):
            raise GovoptError(f"{where}: expected {len(columns)} values, got {len(row)}")
        v: dict = {}
        for (col, unit), cell in zip(columns, row, strict=True):
            cell = cell.strip()
            dim = COLUMNS[col][0]
            if dim == "text":
                v[col] = cell
                continue
            if not cell and col == "rate":
                v[col] = None
                continue
            try:
                v[col] = parse_quantity(f"{cell} {unit}".strip() if dim != "dimensionless"
                                        else float(cell), dim)
            except (UnitError, ValueError) as exc:
                raise GovoptError(f"{where}: {col}: expected a number, got {cell!r} "
                                  f"({exc})") from None
            if not v[col] > 0:
                raise GovoptError(f"{where}: {col}: expected above 0, got {cell!r}")
        if v["material"] not in mt.materials():
            raise GovoptError(f"{where}: material: expected one of "
                              f"{', '.join(mt.materials())}, got {v['material']!r}")
        if v["ends"] not in hc.END_FORMS:
            raise GovoptError(f"{where}: ends: expected one of {', '.join(hc.END_FORMS)}, got "
                              f"{v['ends']!r}")
        d = v["d"]
        D = v["D"] if "D" in v else v["OD"] - d
        if not D > d:
            raise GovoptError(f"{where}: expected a coil wider than the wire ({d * 1e3:.6g} mm)")
        spring = Spring("compression", d, D, v["n"], hc.end_coils(v["ends"]), v["L0"], v["ends"])
        out.append(StockSpring(v["part_number"], spring, v["material"], v.get("rate"), i))
    if not out:
        raise GovoptError(f"{path}: expected springs below the header row, got none")
    return out


def _space(v: dict, sp, mat) -> list[str]:
    """The space and bounds of the requirements the spring ``sp`` does not meet (names)."""
    from .springs import compression as hc
    from .springs import tolerances as tl
    from .verdict import holds

    d, D, n = sp.d, sp.D, sp.coils
    Lc = float(hc.solid_length(tl.max_wire_diameter(d, mat.grade), sp.total_coils, sp.form))
    limits = (("max_outer_diameter", D + d, "<="), ("min_inside_diameter", D - d, ">="),
              ("max_free_length", sp.L0, "<="), ("max_solid_length", Lc, "<="),
              ("min_wire_diameter", d, ">="), ("max_wire_diameter", d, "<="),
              ("turns_min", n, ">="), ("turns_max", n, "<="),
              ("max_body_length", (n + 1.0) * d, "<="))
    return [key for key, value, sense in limits
            if v.get(key) is not None and not holds(value, v[key], sense)]


def pick(stock: list[StockSpring], v: dict, rules, loads, material: str | None):
    """The lightest spring of ``stock`` meeting the requirements ``v`` (the design's values,
    SI) with ``rules`` at ``loads`` (module docstring): ``(spring, its assessment, counts,
    notes)``; a :class:`GovoptError` naming the closest miss when none does."""
    from .springs import materials as mt
    from .springs.assessment import assess

    counts = {"catalogue springs": len(stock), "of the grade": 0, "with the rate": 0,
              "passing every check": 0}
    best, near = None, None
    for item in stock:
        if material is not None and item.grade != material:
            continue
        counts["of the grade"] += 1
        mat = mt.material(item.grade, G=v.get("shear_modulus"), density=v.get("density"))
        a = assess(item.spring, mat, loads, rules)
        R = a.value("rate")
        lo, hi = v["stiffness"], v.get("max_stiffness")
        if hi is None:
            lo, hi = a.value("rate least"), a.value("rate largest")
            fits = lo * (1 - 1e-9) <= v["stiffness"] <= hi * (1 + 1e-9)
        else:
            fits = lo * (1 - 1e-9) <= R <= hi * (1 + 1e-9)
        if not fits:
            continue
        counts["with the rate"] += 1
        unmet = a.failed + _space(v, item.spring, mat)
        mass = a.value("mass")
        if unmet:
            if near is None or len(unmet) < len(near[1]):
                near = (item, unmet)
            continue
        counts["passing every check"] += 1
        if best is None or mass < best[2]:
            best = (item, a, mass)
    if best is None:
        why = (f"{counts['catalogue springs']} springs, {counts['of the grade']} of the grade, "
               f"{counts['with the rate']} with the rate")
        if near is not None:
            why += f"; the closest, part {near[0].part}, fails {', '.join(near[1])}"
        raise GovoptError(f"no spring of the catalogue meets these requirements ({why})")
    item, a, _ = best
    notes = [f"part {item.part} (spring {item.row} of the catalogue)"]
    R = a.value("rate")
    if item.rate is not None and abs(item.rate / R - 1.0) > RATE_NOTE:
        notes.append(f"the catalogue's rate {item.rate * 1e-3:.4g} N/mm differs from G d^4 / "
                     f"(8 D^3 n) = {R * 1e-3:.4g} N/mm of the grade's G by "
                     f"{100 * (item.rate / R - 1):+.3g} % (the checks read the latter)")
    return item, a, counts, notes


def record(a, counts: dict, source: str, notes: list[str]):
    """The optimiser's record of a catalogue's pick: every spring checked, so the lightest
    that passes is the catalogue's optimum, its own bound."""
    from .optimize.record import Objective, Record

    mass = a.value("mass")
    return Record(status="optimal", objective=Objective("mass", "kg"), value=mass, bound=mass,
                  active=[c.name for c in a.checks if c.active],
                  method=f"every spring of the catalogue {source} checked (exhaustive: the "
                         "lightest that passes is the catalogue's optimum)",
                  search=dict(counts), notes=list(notes))


__all__ = ["COLUMNS", "SAMPLE", "StockSpring", "path_of", "pick", "read", "record"]
