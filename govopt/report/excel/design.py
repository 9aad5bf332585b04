"""The Design sheet: the design's inputs as yellow cells with workbook-level defined names
(``wire_diameter``, ``coil_radius``, ``turns`` ...) and the quantities derived from them (the
spring's stiffness, index and stresses, the masses, the equilibrium speeds at the ends of the
range, the irregularity) as live formulas, each beside govopt's own value; and the Model sheet's
constants those formulas read (the linkage's generalised forces at the ends of the range,
labelled for a reader).

A person reads and edits the value in engineering units (:data:`govopt.verdict.SHOWN`: mm,
MPa, N/mm, rpm, deg); each defined name is the SI cell beside it (converted from the input, or
the live formula in SI), which every formula uses. The defined names and SI cells sit right of
the printed columns. A governor type may write its own live sheet
(:meth:`govopt.governors.base.Governor.excel_design`, the shaft governor's); every other type
gets the generic sheet on the seam (:func:`generic_design`).
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING

import numpy as np
from openpyxl import Workbook
from openpyxl.utils import get_column_letter
from openpyxl.workbook.defined_name import DefinedName

from ...analysis import statics
from ...units import G_STANDARD
from ...verdict import SHOWN
from ..sections import shown
from .book import (
    BOLD,
    FORMULA_FILL,
    INPUT_FILL,
    WRAP,
    Sheet,
    fmt,
    shown_unit,
    sig_format,
    unit_label,
)

if TYPE_CHECKING:
    from ...result import Result

HEADERS = ["quantity", "symbol", "value", "unit", "govopt value", "rel. difference",
           "formula / source", "defined name", "value (SI)", "SI unit"]
#: The columns: label, symbol, the value a person reads and edits, its unit, govopt's value,
#: their relative difference, the formula or source (the printed columns end here), then the
#: defined name, the SI cell the formulas use and its unit.
VALUE, UNIT, GOVOPT, RELDIFF, NOTE, NAME, SI, SI_UNIT = 3, 4, 5, 6, 7, 8, 9, 10
WIDTHS = {1: 34, 2: 9, VALUE: 13, UNIT: 8, GOVOPT: 13, RELDIFF: 10, NOTE: 36, NAME: 24,
          SI: 16, SI_UNIT: 11}
RELDIFF_FORMAT = "0.0E+00"
#: Defined names must not look like a cell reference (A1 or R1C1) or clash with a function.
_NAME_OK = re.compile(r"^[a-z][a-z_]*$")


class FormulaSheet:
    """A sheet of named inputs and live formulas (the Design sheet, the Model sheet's
    constants): :meth:`input`, :meth:`formula`, :meth:`section`, :meth:`text`; a governor type's
    own sheet (:meth:`Governor.excel_design`) writes through these."""

    def __init__(self, wb: Workbook, sheet: Sheet, model: FormulaSheet | None = None):
        self.wb, self.sheet, self.ws = wb, sheet, sheet.ws
        self.model = model  # where the generic sheet writes the linkage's constants
        self.titles: list[int] = []  # the sections' title rows (kept with their rows)
        sheet.set_widths(WIDTHS)
        sheet.header(1, HEADERS)
        sheet.print_cols = NOTE
        self.ws.freeze_panes = "A2"
        self.row = 2

    def _name(self, name: str) -> None:
        if not _NAME_OK.match(name) or name in self.wb.defined_names:
            raise ValueError(f"bad or repeated defined name {name!r}")
        ref = f"'{self.ws.title}'!${get_column_letter(SI)}${self.row}"
        self.wb.defined_names[name] = DefinedName(name, attr_text=ref)
        self.sheet.put(self.row, NAME, name)

    def section(self, text: str) -> None:
        """A section's title (bold)."""
        self.row += 1 if self.row > 2 else 0
        self.sheet.title(self.row, text, font=BOLD)
        self.titles.append(self.row)
        self.row += 1

    def _label(self, label, symbol, unit, note):
        s = self.sheet
        s.put(self.row, 1, label)
        s.put(self.row, 2, symbol)
        s.put(self.row, UNIT, unit_label(shown_unit(unit)))
        s.put(self.row, SI_UNIT, unit_label(unit))
        if note:
            s.put(self.row, NOTE, note).alignment = WRAP

    def input(self, name, label, symbol, value, unit, note="", number_format=None) -> None:
        """A yellow input in engineering units, and its defined name: the SI cell converting
        it (``value`` in SI; blank for None)."""
        self._label(label, symbol, unit, note)
        r, factor = self.row, SHOWN.get(unit, (unit, 1.0))[1]
        c = self.ws.cell(r, VALUE)
        if value is None:
            c.value = None
        else:
            self.sheet.put(r, VALUE, float(value) * factor, number_format or fmt(shown_unit(unit)))
        c.fill = INPUT_FILL
        ref = f"{get_column_letter(VALUE)}{r}"
        self.sheet.formula(r, SI, f"={ref}" if factor == 1.0 else f"={ref}/{factor!r}",
                           number_format or fmt(unit))
        self._name(name)
        self.row += 1

    def formula(self, name, label, symbol, formula, unit, govopt_value, note="") -> None:
        """A live formula in SI on the defined names (blue, named), shown in engineering units
        beside govopt's value and their relative difference."""
        s, r = self.sheet, self.row
        self._label(label, symbol, unit, note)
        seen_unit, factor = SHOWN.get(unit, (unit, 1.0))
        s.formula(r, SI, formula, fmt(unit)).fill = FORMULA_FILL
        si = f"{get_column_letter(SI)}{r}"
        s.formula(r, VALUE, f"={si}" if factor == 1.0 else f"={si}*{factor!r}",
                  fmt(seen_unit)).fill = FORMULA_FILL
        seen = None if govopt_value is None else govopt_value * factor
        s.put(r, GOVOPT, seen, fmt(seen_unit))
        v, g = f"{get_column_letter(VALUE)}{r}", f"{get_column_letter(GOVOPT)}{r}"
        s.formula(r, RELDIFF, f"=IF({g}=0,ABS({v}),ABS({v}/{g}-1))", RELDIFF_FORMAT)
        self._name(name)
        self.row += 1

    def value(self, label, symbol, value, unit, note="") -> None:
        """govopt's value of a quantity the sheet does not compute (no name, no formula)."""
        self._label(label, symbol, unit, note)
        seen, seen_unit = shown(value, unit)
        self.sheet.put(self.row, GOVOPT, seen, sig_format(seen) or fmt(seen_unit))
        self.row += 1

    def helical_spring(self, sd, props) -> None:
        """A helical spring's live stiffness, index and Wahl factor on the named wire diameter,
        coil radius, turns and shear modulus (one definition for every type's sheet)."""
        self.formula("stiffness", "spring stiffness (whole spring)", "kappa",
                     "=shear_modulus*wire_diameter^4/(64*coil_radius^3*turns)", "N/m", sd.kappa,
                     "kappa = G d^4 / (64 r^3 n) (Wahl 1944)")
        self.formula("spring_index", "spring index", "C", "=2*coil_radius/wire_diameter", "",
                     props["spring_index"], "C = 2 r / d (Wahl 1944)")
        self.formula("wahl_factor", "Wahl stress factor", "K",
                     "=(4*spring_index-1)/(4*spring_index-4)+0.615/spring_index", "",
                     props["wahl_factor"], "K = (4C - 1)/(4C - 4) + 0.615/C (Wahl 1944, eq. 2-12)")

    def irregularity(self, res: Result) -> None:
        """The irregularity and its utilisation from the named ``omega_inner``, ``omega_outer``
        (one definition for every governor type; the same as the result's)."""
        sp = res.spec.speed
        self.formula("irregularity", "irregularity", "delta",
                     "=(omega_outer-omega_inner)/omega_mean", "", res.irregularity,
                     "delta = (omega_a - omega_i) / omega0 ("
                     f"{res.method.named('irregularity').cite})")
        self.formula("irregularity_utilisation", "irregularity utilisation", "delta/delta0",
                     "=irregularity/irregularity_required", "", res.irregularity / sp.irregularity,
                     "<= 1 required")

    def stress_factor(self, correction: str, index: float) -> str:
        """The stress formula's factor for ``material.stress_correction``: ``*wahl_factor``
        (its row is the sheet's), ``*bergstrasser_factor`` (its row written here: EN 13906-1's
        k, Shigley eq. (10-5) K_B) or none."""
        if correction == "bergstrasser":
            self.formula("bergstrasser_factor", "Bergstraesser stress factor", "k",
                         "=(spring_index+0.5)/(spring_index-0.75)", "",
                         (index + 0.5) / (index - 0.75),
                         "k = (C + 0.5)/(C - 0.75) (EN 13906-1; Shigley eq. 10-5)")
            return "*bergstrasser_factor"
        return "*wahl_factor" if correction == "wahl" else ""

    def text(self, text: str) -> None:
        """An explanation in italics across the printed columns, wrapped."""
        self.sheet.paragraph(self.row, text, 1, NOTE)
        self.row += 1

    def close(self) -> None:
        """The printed blocks: each section under the sheet's header (repeated on every page),
        filling the page it starts on, its title never alone at a page's foot nor its last rows
        alone at a page's head."""
        for first, end in zip(self.titles, [*self.titles[1:], self.row + 1], strict=True):
            self.sheet.keep_table(first, end - 2, header=1, whole=False)
        self.sheet.keep_table(1, self.row - 1, header=1)


def build_design(wb: Workbook, design: Sheet, model: FormulaSheet, res: Result) -> None:
    """The Design sheet: the type's own live sheet or the generic one, the friction speeds
    where friction acts, and what the colours mean."""
    s = FormulaSheet(wb, design, model)
    if not res.spec.governor.excel_design(s, res):  # a type may write its own live sheet
        generic_design(s, res)
    rise, fall = res.friction_speeds
    if rise is not None:
        band = res.method.named("band")
        s.section("With friction: the speeds the governor moves at (govopt's values)")
        (low, at_low), (high, at_high) = res.band_extremes
        s.value("lowest closing speed", "omega_fall", low, "rad/s",
                f"falling against friction, at {at_low}: the band's lowest speed"
                + (f" ({band.cite})" if band else ""))
        s.value("highest opening speed", "omega_rise", high, "rad/s",
                f"rising against friction, at {at_high}: the band's highest speed")
    s.row += 1
    s.text("Yellow cells are inputs, in the units beside them (mm, N/mm, MPa, rpm, deg); blue "
           "cells are formulas. The formulas work in SI on the defined names (column "
           f"{get_column_letter(NAME)}, right of the printed page): each is the SI cell of "
           f"column {get_column_letter(SI)}, converted from the input or shown in column "
           f"{get_column_letter(VALUE)} in the unit beside it. 'govopt value' is govopt's "
           "result when the workbook was written (what a reader that does not recalculate "
           "sees); 'rel. difference' compares the two, so it shows how far an edited design "
           "has moved.")
    s.text("The characteristic table, k^2, dynamics and checks on the other sheets are govopt's "
           "values and do not follow edits here; re-run govopt for them.")
    s.close()


def seam_constants(res: Result, x: float) -> dict[str, float]:
    """The seam at ``x`` split by the masses it is affine in (Lagrange: every generalised force is
    linear in the flying and central masses), so the sheet can write the equilibrium live in
    the design's masses and spring: ``omega^2 = (kappa (A - B l0) + cf0 + m cfm + M cfc) /
    (lv0 + m lvm + M lvc)``."""
    spec = res.spec
    t0, tm, tc = (statics.terms(spec, x, m, c) for m, c in ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0)))
    A_F, B_F = spec.governor.spring_force_coefficients(np.asarray(x, dtype=float))
    out = {"A": t0.A, "B": t0.B, "A_F": A_F, "B_F": B_F,
           "cf": t0.cf, "cf_m": tm.cf - t0.cf, "cf_c": tc.cf - t0.cf,
           "lv": t0.lever, "lv_m": tm.lever - t0.lever, "lv_c": tc.lever - t0.lever}
    return {k: float(v) for k, v in out.items()}


def seam_meanings(q: str, mass: str) -> dict[str, tuple[str, str]]:
    """What each constant of :func:`seam_constants` is, in words, and its SI unit (``q``: the
    generalised force's, N m or N): ``omega^2 = (kappa (A - B l0) + cf + m cf_m + M cf_c) /
    (lv + m lv_m + M lv_c)``, ``F = kappa (A_F - B_F l0)``."""
    return {
        "A": ("spring's pull per N/m of rate", f"{q}/(N/m)"),
        "B": ("spring's pull per N/m of rate and m of free length", f"{q}/N"),
        "A_F": ("spring's stretch term (force per N/m of rate)", "m"),
        "B_F": ("spring's free-length factor (a pure number)", ""),
        "cf": ("dead loads' pull without the weights (links, fixed springs)", q),
        "cf_m": (f"dead loads' pull per kg of {mass}", f"{q}/kg"),
        "cf_c": ("dead loads' pull per kg of central load", f"{q}/kg"),
        "lv": ("centrifugal pull per omega^2 without the weights", f"{q}*s^2"),
        "lv_m": (f"centrifugal pull per omega^2 and kg of {mass}", f"{q}*s^2/kg"),
        "lv_c": ("centrifugal pull per omega^2 and kg of central load", f"{q}*s^2/kg"),
    }


def _allowable_note(res: Result) -> str:
    """Where the allowable shear stress on the Design sheet comes from."""
    if res.spec.material.allowable_shear_stress is not None:
        return "material.allowable_shear_stress"
    return (f"material.grade {res.spec.material.grade}: the standard's rule at the design's "
            "wire diameter (not live in d; see the Spring sheet)")


def model_constants(model: FormulaSheet, res: Result, named: bool = True) -> None:
    """The Model sheet's constants: the linkage's generalised forces at the ends of the range,
    split by what they are linear in, with their meaning in words; named inputs the generic
    Design sheet's formulas read, or (``named`` False: a type wrote its own Design sheet)
    govopt's values for reference."""
    gov, st = res.spec.governor, res.statics
    q = "N*m" if gov.coordinate == "angle" else "N"  # the generalised force's unit
    meaning = seam_meanings(q, gov.mass_key)
    model.section(f"The linkage's constants at the ends of the range ({gov.title})")
    model.text("omega^2 = (kappa (A - B l0) + cf + m cf_m + M cf_c) / (lv + m lv_m + M lv_c) "
               "and F = kappa (A_F - B_F l0): the equilibrium by virtual work, split by what it "
               "is linear in (the spring's rate kappa and free length l0, the weights' masses m "
               "and M); 'pull' is the generalised force along the coordinate "
               f"({'N m about the angle' if gov.coordinate == 'angle' else 'N along the length'})."
               " These constants depend on the linkage alone; govopt wrote them at the inner "
               "(_i) and outer (_a) end of the range"
               + (", and the Design sheet's equilibrium speeds read them." if named else
                  " (the Design sheet computes from the type's own equations)."))
    spring_terms = ("A", "B", "A_F", "B_F")
    for tag, i, sym in (("inner", 0, "i"), ("outer", -1, "a")):
        for key, value in seam_constants(res, st.alpha[i]).items():
            if gov.spring is None and key in spring_terms:
                continue  # no spring: its terms are zero and no formula reads them
            what, unit = meaning[key]
            if named:
                model.input(f"{key.lower()}_{tag}", f"{what}, {tag} end", f"{key}_{sym}", value,
                            unit, "govopt.analysis.statics.terms",
                            sig_format(shown(value, unit)[0]))
            else:
                model.value(f"{what}, {tag} end", f"{key}_{sym}", value, unit,
                            "govopt.analysis.statics.terms")


def generic_design(s: FormulaSheet, res: Result) -> None:
    """The Design sheet of any governor type: its inputs, and the masses, spring, forces,
    stresses and equilibrium speeds at the range's ends as live formulas on the Model sheet's
    constants of the linkage."""
    spec, sd, ds, props = res.spec, res.spring, res.design, res.spring_properties
    gov, sp, mat, st = spec.governor, spec.speed, spec.material, res.statics
    mk = gov.mass_key
    helical = bool(props)
    s.section("Inputs (yellow, in the units beside them): edit them and the formulas below "
              "follow")
    s.input(f"{mk}_weight", f"{gov.mass_name} weight (each)", "w", sd.m * G_STANDARD, "N",
            f"design.{mk}_weight (or mass x standard gravity)")
    s.input("std_gravity", "standard gravity", "g_n", G_STANDARD, "m/s^2",
            "CGPM 1901; converts weights to masses")
    s.input("central_weight", "central (sleeve) load", "W", (sd.central or 0.0) * G_STANDARD,
            "N", "design.central_weight" if ds.central_mass is not None else "none: 0")
    if gov.spring is not None:
        if helical:
            s.input("wire_diameter", "wire diameter", "d", sd.d, "m", "design.wire_diameter")
            s.input("coil_radius", "mean coil radius", "r", sd.r, "m", "design.coil_radius")
            s.input("turns", "active turns", "n", sd.n, "", "design.active_turns")
            s.input("shear_modulus", "shear modulus", "G", mat.shear_modulus, "Pa",
                    "material.shear_modulus")
            s.input("allowable_stress", "allowable shear stress", "k_s",
                    res.allowable_shear_stress, "Pa", _allowable_note(res))
            s.input("density", "density of the wire", "rho_w", mat.density, "kg/m^3",
                    "material.density")
        else:
            s.input("stiffness", "spring stiffness", "kappa", sd.kappa, "N/m",
                    "design.spring_stiffness (or the leaf's section)")
        s.input("free_length", f"spring's {gov.free_length_key.replace('_', ' ')}", "l0", sd.l0,
                "m", f"design.{gov.free_length_key}" if ds.free_half_length is not None else
                "govopt: equilibrium at the normal configuration at the mean speed")
    if sp is not None:
        s.input("omega_mean", "mean speed", "omega0", sp.omega_mean, "rad/s", "speed.mean")
        s.input("irregularity_required", "required irregularity (at most)", "delta0",
                sp.irregularity, "", "speed.irregularity")
    model_constants(s.model, res)
    s.section("Derived quantities (blue, live formulas) next to govopt's values as written")
    s.formula(f"{mk}_mass", f"{gov.mass_name} mass", "m", f"={mk}_weight/std_gravity", "kg",
              sd.m, "m = w / g_n")
    s.formula("central_mass", "central load's mass", "M", "=central_weight/std_gravity", "kg",
              sd.central or 0.0, "M = W / g_n")
    if helical:
        s.helical_spring(sd, props)
        factor = s.stress_factor(mat.stress_correction, props["spring_index"])
    spring_force = res.method.named("spring force")
    for tag, i, sym in (("inner", 0, "i"), ("outer", -1, "a")):
        if gov.spring is None:
            break
        s.formula(f"spring_force_{tag}", f"spring force at {gov.coordinate_name}_{sym}",
                  f"F_{sym}", f"=stiffness*(a_f_{tag}-b_f_{tag}*free_length)", "N",
                  st.spring_force[i], "F = kappa (A_F - B_F l0)"
                  + (f" ({spring_force.cite})" if spring_force else ""))
        if helical:
            s.formula(f"shear_stress_{tag}", f"shear stress at {gov.coordinate_name}_{sym}",
                      f"tau_{sym}", f"=16*ABS(spring_force_{tag})*coil_radius/"
                      f"(PI()*wire_diameter^3)" + factor, "Pa",
                      st.stress[i], "tau = 16 |F| r / (pi d^3)" + (" x K" if factor else ""))
    characteristic = res.method.named("characteristic")
    for tag, i, sym in (("inner", 0, "i"), ("outer", -1, "a")):
        spring_q = (f"stiffness*(a_{tag}-b_{tag}*free_length)+" if gov.spring is not None
                    else "")
        w = (f"=SQRT(({spring_q}cf_{tag}+{mk}_mass*cf_m_{tag}+central_mass*cf_c_{tag})/"
             f"(lv_{tag}+{mk}_mass*lv_m_{tag}+central_mass*lv_c_{tag}))")
        s.formula(f"omega_{tag}", f"equilibrium speed at {gov.coordinate_name}_{sym}",
                  f"omega_{sym}", w, "rad/s", st.omega[i],
                  f"the equilibrium ({characteristic.cite}) on the Model sheet's constants")
        s.formula(f"rpm_{tag}", f"equilibrium speed at {gov.coordinate_name}_{sym}", f"N_{sym}",
                  f"=omega_{tag}*30/PI()", "rpm", st.omega[i] * 30.0 / math.pi,
                  "N = 30 omega / pi")
    if sp is not None:
        s.irregularity(res)
