"""Excel workbook of one design: inputs, live spring formulas, characteristic, checks, notes.

:func:`write_workbook` writes one ``.xlsx`` per :class:`~govopt.result.Result` (openpyxl):

* **Spec** — every spec input as written (always a text cell) and in SI.
* **Design** — the design and the constants the formulas need as yellow *input* cells with
  workbook-level defined names (``wire_diameter``, ``coil_radius``, ``turns`` ...), and the
  derived quantities (stiffness, index, Wahl factor, spring force and stress at the ends of the
  range, utilisation, spring mass, surge frequency, equilibrium speeds and irregularity) as live
  Excel formulas on those names, each next to govopt's own value.
* **Characteristic** — the table over the configuration with a chart of speed against it.
* **Dynamics** — ``k^2`` against ``omega0^2`` (chart), and the declared dynamics tables of
  :mod:`govopt.report.sections` (load changes, roots in real and imaginary columns, the forced
  vibration and its harmonics, responses charted), or why there are none.
* **Checks** — every check with value, limit, margin and PASS/FAIL (conditional formatting), the
  binding checks, and the optimiser's record as tables (objective with its unit, search,
  chosen design, continuous bound, sensitivities) when present.
* **Notes** — method, fidelity, version, date and the sources' equation numbers.

The writer formats only; every number comes from the result or from govopt's own functions
(the valve-gear reaction constants). Words replace what is not a number: ``yes``/``no`` for
booleans, ``never`` for a time that never comes, ``not decided`` for a settling time
the solver could not place, ``unbounded`` for an unstable excursion.

Every sheet prints: A4, fit to the page width, landscape where wide, a print area, the sheet's
name and page in the footer, page breaks that keep tables whole where they fit, and at the top of
each page a table runs on to the table's own title and header (:func:`print_titles`). Every
formula cell carries govopt's own value as its cached result (written into the saved file), so
readers that do not recalculate (pandas, previewers) see the numbers; Excel and LibreOffice
recalculate on opening. The file is written atomically: a temporary file in the target's
directory, renamed over the target only when complete.
"""

from __future__ import annotations

import datetime as _dt
import math
import os
import re
import zipfile
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from openpyxl import Workbook
from openpyxl.cell.cell import ILLEGAL_CHARACTERS_RE
from openpyxl.chart import Reference, ScatterChart, Series
from openpyxl.formatting.rule import FormulaRule
from openpyxl.styles import Alignment, Font, PatternFill
from openpyxl.utils import column_index_from_string, get_column_letter
from openpyxl.workbook.defined_name import DefinedName
from openpyxl.worksheet.page import PageMargins
from openpyxl.worksheet.pagebreak import Break
from openpyxl.worksheet.worksheet import Worksheet

from ..analysis import statics
from ..springs.sheet import SECTION, record_rows
from ..units import G_STANDARD
from ..verdict import ACTIVE_TOL, SHOWN
from . import sections
from .files import atomic_write

if TYPE_CHECKING:
    from ..result import Result

__all__ = ["SHEETS", "build_workbook", "write_workbook"]

#: Sheet names, in workbook order.
SHEETS = ("Spec", "Design", "Characteristic", "Dynamics", "Checks", "Spring", "Notes")

_BOLD = Font(bold=True)
_TITLE = Font(bold=True, size=13)
_HEADER_FILL = PatternFill("solid", fgColor="D9D9D9")
_INPUT_FILL = PatternFill("solid", fgColor="FFF2CC")
_FORMULA_FILL = PatternFill("solid", fgColor="DDEBF7")
_PASS_FILL = PatternFill("solid", fgColor="C6EFCE", bgColor="C6EFCE")
_FAIL_FILL = PatternFill("solid", fgColor="FFC7CE", bgColor="FFC7CE")
_PASS_FONT = Font(color="006100")
_FAIL_FONT = Font(color="9C0006")
_WRAP = Alignment(wrap_text=True, vertical="top", horizontal="left")
_ITALIC = Font(italic=True)
_HEADER_ALIGN = Alignment(wrap_text=True, vertical="center")
_RIGHT = Alignment(horizontal="right")
_LEFT_WRAP = Alignment(horizontal="left", wrap_text=True)

#: Display formats by SI unit (the stored values keep full precision).
_FORMATS = {
    "m": "0.000000", "N": "#,##0.000", "Pa": "#,##0", "N/m": "#,##0.00", "kg": "0.000000",
    "kg*m^2": "0.000000", "rad": "0.000000", "rad/s": "0.000000", "rpm": "0.0000",
    "N*m": "0.000000", "Hz": "0.000", "": "0.000000", "kg/m^3": "#,##0.00",
    "m/s^2": "0.00000", "N*m*s/rad": "0.000000", "deg": "0.0000", "rad^2/s^2": "0.000",
    "s": "0.0000", "N*m/rad": "#,##0.000", "MPa": "#,##0.00", "mm": "0.000",
    "N/mm": "#,##0.000", "1/s^2": "0.000",
}
_GENERAL_FORMAT = "0.000000"
_RELDIFF_FORMAT = "0.0E+00"

#: Characters that make a spreadsheet treat typed text as something else (formula, number...).
_FORMULA_LEAD = ("=", "+", "-", "@")

#: Equation sources for the Notes sheet.
SOURCES = (
    ("Hamabe eq. 1", "centrifugal moment about the fulcrum, M_z = omega^2 m a rho sin(alpha)"),
    ("Hamabe eq. 2", "spring half length l = sqrt(a^2 + b^2 - 2 a b cos(alpha)), force "
                     "F = 2 kappa (l - l0), moment M_f = F a b sin(alpha) / l (exact geometry)"),
    ("Hamabe eq. 3", "the paper's first-order series for M_f (geometry = 'series')"),
    ("Hamabe eq. 11", "mean reaction of the valve gear M_r0 = C_f + omega^2 C_i"),
    ("Hamabe eq. 12", "equilibrium M_f - M_z + M_r0 = 0: the characteristic curve"),
    ("Hamabe eqs. 18-20", "restoring stiffness k^2 = (dM_f/dalpha - omega^2 m a rho "
                          "cos(alpha) [+ dM_r0/dalpha]) / I"),
    ("Hamabe eqs. 16-23", "forced vibration of the pendulum by the engine's speed "
                          "fluctuation: harmonics (eqs. 20-22), dash-pot (eq. 23)"),
    ("Hamabe eq. 28", "load change of governor and engine: a0 xi''' + 3 a1 xi'' + 3 a2 xi' "
                      "+ a3 xi = 0 (from eqs. 24-27)"),
    ("Hamabe eq. 32", "Hurwitz stability of eq. 28: 9 a1 a2 > a0 a3 (margin 9 a1 a2 / (a0 a3) "
                      "- 1)"),
    ("Hamabe Example 1", "spring design: kappa = G d^4 / (64 r^3 n), tau = 16 F r / (pi d^3), "
                         "free half length from equilibrium at the normal configuration"),
    ("Hamabe Part I", "irregularity delta = (omega_a - omega_i) / omega0, omega0 the mean speed"),
    ("Wahl 1944", "A. M. Wahl, Mechanical Springs: index C = 2 r / d, stress factor "
                  "K = (4C - 1)/(4C - 4) + 0.615/C (eq. 2-12), surge frequency (ch. 25)"),
)


# --------------------------------------------------------------------------------------------
# public API


def write_workbook(result: Result, path: str | os.PathLike) -> Path:
    """Write the workbook of ``result`` to ``path`` atomically and return the path.

    The workbook is built in memory, saved to a temporary file in the same directory and
    renamed over ``path``; on any error the temporary file is removed and an existing ``path``
    is left untouched. An unwritable path raises :class:`~govopt.errors.GovoptError`.
    """
    path = Path(path)
    wb = build_workbook(result)
    _atomic_save(wb, path)
    return path


def build_workbook(result: Result) -> Workbook:
    """The workbook of ``result`` in memory (see the module docstring for the sheets)."""
    wb = Workbook()
    wb.remove(wb.active)
    wb._govopt_cached = {}  # (sheet, cell) -> govopt's value of the formula (_formula)
    sheets = {name: wb.create_sheet(name) for name in SHEETS}
    _build_spec(sheets["Spec"], result)
    _build_design(wb, sheets["Design"], result)
    _build_characteristic(sheets["Characteristic"], result)
    _build_dynamics(sheets["Dynamics"], result)
    _build_checks(sheets["Checks"], result)
    _build_spring(sheets["Spring"], result)
    _build_notes(sheets["Notes"], result)
    wb.active = sheets["Design"]
    for ws in wb.worksheets:
        ws.sheet_view.tabSelected = ws is sheets["Design"]
        _align_top(ws)
        fit_rows(ws)
        print_setup(ws)
    from .. import __version__

    wb.properties.creator = f"govopt {__version__}"
    wb.properties.title = f"govopt {result.kind}: {result.spec.name}"
    return wb


# --------------------------------------------------------------------------------------------
# atomic write


def _atomic_save(wb: Workbook, path: Path) -> None:
    """Save ``wb`` to ``path`` through the one atomic writer of every output
    (:func:`govopt.report.files.atomic_write`: temporary file, rename, mode 0666 minus umask or
    the replaced file's, errors as one-line :class:`~govopt.errors.GovoptError`); text
    properties (the title holds the spec's name) made XML-safe first."""
    props = wb.properties
    for key in ("title", "subject", "description", "creator", "keywords", "category"):
        if isinstance(getattr(props, key), str):
            setattr(props, key, _xml_safe(getattr(props, key)))
    cached = getattr(wb, "_govopt_cached", None) or {}

    def save(tmp):
        wb.save(tmp)
        _store_cached_values(Path(tmp), cached)

    atomic_write(path, save, what="workbook")


# --------------------------------------------------------------------------------------------
# cell helpers


def _scalar(value: Any) -> Any:
    """A value a cell can hold: finite numbers stay numbers; NaN/inf, complex and anything else
    become text (an xlsx cannot store NaN)."""
    if value is None:
        return None
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, int | np.integer):
        return int(value)
    if isinstance(value, float | np.floating):
        x = float(value)
        return x if math.isfinite(x) else ("nan" if math.isnan(x) else ("inf" if x > 0 else "-inf"))
    if isinstance(value, complex | np.complexfloating):
        z = complex(value)
        return f"{z.real:.10g}{z.imag:+.10g}j"
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return _scalar(value.item())
    return str(value)


def _xml_safe(text: str) -> str:
    """``text`` with the control characters an xlsx (XML 1.0) cannot hold written as ``\\xNN``
    (a spec's name may contain them)."""
    return ILLEGAL_CHARACTERS_RE.sub(lambda m: f"\\x{ord(m[0]):02x}", text)


def _set(cell, value, number_format: str | None = None):
    """Write ``value``; text is always stored as text, never as a formula, and control
    characters an xlsx cannot hold are written visibly as ``\\xNN``."""
    value = _scalar(value)
    if isinstance(value, str):
        value = _xml_safe(value)
    cell.value = value
    if isinstance(value, str):
        cell.data_type = "s"
        if value.startswith(_FORMULA_LEAD):
            cell.quotePrefix = True  # so re-typing in Excel/Calc keeps it text too
    elif number_format and isinstance(value, int | float) and not isinstance(value, bool):
        cell.number_format = number_format
    return cell


def _formula(cell, formula: str, number_format: str | None = None, cached: Any = None):
    """A formula cell; ``cached``: govopt's value of it, stored as the formula's cached result
    when the workbook is saved (:func:`_store_cached_values`), so that readers that do not
    recalculate see the number."""
    cell.value = formula if formula.startswith("=") else "=" + formula
    cell.data_type = "f"
    if number_format:
        cell.number_format = number_format
    cache = getattr(cell.parent.parent, "_govopt_cached", None)
    if cache is not None and cached is not None:
        cache[(cell.parent.title, cell.coordinate)] = cached
    return cell


def _header(ws: Worksheet, row: int, headers: Iterable[str], col: int = 1) -> None:
    for j, h in enumerate(headers):
        c = _set(ws.cell(row, col + j), h)
        c.font, c.fill = _BOLD, _HEADER_FILL
        c.alignment = _HEADER_ALIGN


def _title(ws: Worksheet, row: int, text: str, col: int = 1, font: Font = _TITLE) -> None:
    _set(ws.cell(row, col), text).font = font


def _written(ws: Worksheet):
    """The cells written so far (``iter_rows`` would create every empty cell of the range)."""
    return ws._cells.values()


def _widths(ws: Worksheet, fixed: Mapping[int, float] | None = None, low=8.0, high=60.0):
    """Column widths from the text in each column (formulas and numbers count as 14)."""
    width: dict[int, float] = {}
    for c in _written(ws):
        if c.value is None:
            continue
        n = 14 if c.data_type in ("n", "f") else len(str(c.value)) + 2
        width[c.column] = max(width.get(c.column, low), min(n, high))
    for col, w in {**width, **(fixed or {})}.items():
        ws.column_dimensions[get_column_letter(col)].width = w


def _unit_label(unit: str) -> str:
    return unit.replace("*", " ") if unit else "-"


def shown_unit(unit: str) -> str:
    """The engineering unit an SI unit is shown in (:data:`govopt.verdict.SHOWN`)."""
    return SHOWN.get(unit, (unit, 1.0))[0]


def _fmt(unit: str) -> str:
    return _FORMATS.get(unit, _GENERAL_FORMAT)


def _scatter(title: str, x_title: str, y_title: str, width=18.0, height=9.0) -> ScatterChart:
    chart = ScatterChart()
    chart.title, chart.style = _xml_safe(title), 13
    chart.x_axis.title, chart.y_axis.title = _xml_safe(x_title), _xml_safe(y_title)
    chart.x_axis.delete = chart.y_axis.delete = False  # newer Excel hides axes otherwise
    # tick labels at the low end of each axis: off the curve when an axis crosses mid-plot
    chart.x_axis.tickLblPos = chart.y_axis.tickLblPos = "low"
    chart.x_axis.number_format = chart.y_axis.number_format = "General"  # not the cells' 0.0000
    chart.x_axis.majorGridlines = None
    chart.width, chart.height = width, height
    chart.legend.position = "b"
    return chart


#: Distinct series colours (blue, red, green, orange, purple): one per curve of a chart.
_COLOURS = ("1F77B4", "D62728", "2CA02C", "FF7F0E", "9467BD")


def _add_series(chart: ScatterChart, ws: Worksheet, x_col: int, y_col: int, header_row: int,
                last_row: int, colour: int | None = None, dash: bool = False) -> None:
    xs = Reference(ws, min_col=x_col, min_row=header_row + 1, max_row=last_row)
    ys = Reference(ws, min_col=y_col, min_row=header_row, max_row=last_row)
    s = Series(ys, xs, title_from_data=True)
    s.marker.symbol = "none"
    s.smooth = False
    line = s.graphicalProperties.line
    line.solidFill = _COLOURS[(len(chart.series) if colour is None else colour) % len(_COLOURS)]
    line.width = 22225  # 1.75 pt in EMU
    if dash:
        line.dashStyle = "dash"
    chart.series.append(s)


# --------------------------------------------------------------------------------------------
# Spec


def _build_spec(ws: Worksheet, res: Result) -> None:
    spec = res.spec
    _header(ws, 1, ["key", "value as written", "value as read", "unit"])
    ws.freeze_panes = "A2"
    for i, e in enumerate(spec.entries, start=2):
        _set(ws.cell(i, 1), e.key)
        _set(ws.cell(i, 2), e.written)  # always text: a spec string is never a formula
        value, unit = sections.shown(e.si, e.unit)  # as read, in the units people read
        _set(ws.cell(i, 3), value, _sig_format(value) or "General")
        _set(ws.cell(i, 4), _unit_label(unit) if e.unit else "")
    _keep_table(ws, 1, len(spec.entries) + 1, header=1)
    row = len(spec.entries) + 3
    _set(ws.cell(row, 1), "spec file")
    _set(ws.cell(row, 2), str(spec.path))
    _widths(ws, {1: 36, 2: 40, 3: 22, 4: 12})


# --------------------------------------------------------------------------------------------
# Design: input cells with defined names and live formulas


_DESIGN_HEADERS = ["quantity", "symbol", "value", "unit", "govopt value", "rel. difference",
                   "formula / source", "defined name", "value (SI)", "SI unit"]
#: The Design sheet's columns: a person reads and edits the value in engineering units
#: (:data:`govopt.verdict.SHOWN`: mm, MPa, N/mm, rpm, deg); the defined names are the SI cells
#: beside it (converted from the input, or the live formula in SI), which every formula uses.
_VALUE, _UNIT, _GOVOPT, _RELDIFF, _NOTE, _NAME, _SI, _SI_UNIT = 3, 4, 5, 6, 7, 8, 9, 10
#: The Design sheet's widths (characters) and the characters of a line of text across the
#: printed columns A .. formula / source (about 1.1 per width unit).
_DESIGN_WIDTHS = {1: 44, 2: 12, _VALUE: 16, _UNIT: 10, _GOVOPT: 16, _RELDIFF: 11, _NOTE: 60,
                  _NAME: 24, _SI: 18, _SI_UNIT: 10}
_TEXT_LINE = int(1.1 * sum(w for j, w in _DESIGN_WIDTHS.items() if j <= _NOTE)) - 4

#: Defined names must not look like a cell reference (A1 or R1C1) or clash with a function.
_NAME_OK = re.compile(r"^[a-z][a-z_]*$")


class _DesignSheet:
    def __init__(self, wb: Workbook, ws: Worksheet):
        self.wb, self.ws, self.row = wb, ws, 1
        self.titles: list[int] = []  # the sections' title rows (kept with their rows)
        _header(ws, 1, _DESIGN_HEADERS)
        ws.freeze_panes = "A2"
        self.row = 2

    def _name(self, name: str) -> None:
        if not _NAME_OK.match(name) or name in self.wb.defined_names:
            raise ValueError(f"bad or repeated defined name {name!r}")
        ref = f"'{self.ws.title}'!${get_column_letter(_SI)}${self.row}"
        self.wb.defined_names[name] = DefinedName(name, attr_text=ref)
        _set(self.ws.cell(self.row, _NAME), name)

    def section(self, text: str) -> None:
        self.row += 1 if self.row > 2 else 0
        _title(self.ws, self.row, text, font=_BOLD)
        self.titles.append(self.row)
        self.row += 1

    def _label(self, label, symbol, unit, note):
        ws = self.ws
        _set(ws.cell(self.row, 1), label)
        _set(ws.cell(self.row, 2), symbol)
        _set(ws.cell(self.row, _UNIT), _unit_label(shown_unit(unit)))
        _set(ws.cell(self.row, _SI_UNIT), _unit_label(unit))
        if note:
            _set(ws.cell(self.row, _NOTE), note)

    def input(self, name, label, symbol, value, unit, note="", number_format=None) -> None:
        """A yellow input in engineering units, and its defined name: the SI cell converting
        it (``value`` in SI; blank for None)."""
        self._label(label, symbol, unit, note)
        r, factor = self.row, SHOWN.get(unit, (unit, 1.0))[1]
        c = self.ws.cell(r, _VALUE)
        if value is None:
            c.value = None
        else:
            _set(c, float(value) * factor, number_format or _fmt(shown_unit(unit)))
        c.fill = _INPUT_FILL
        ref = f"{get_column_letter(_VALUE)}{r}"
        _formula(self.ws.cell(r, _SI), f"={ref}" if factor == 1.0 else f"={ref}/{factor!r}",
                 number_format or _fmt(unit), 0.0 if value is None else float(value))
        self._name(name)
        self.row += 1

    def formula(self, name, label, symbol, formula, unit, govopt_value, note="") -> None:
        """A live formula in SI on the defined names (blue, named), shown in engineering units
        beside govopt's value and their relative difference."""
        ws, r = self.ws, self.row
        self._label(label, symbol, unit, note)
        shown, factor = SHOWN.get(unit, (unit, 1.0))
        _formula(ws.cell(r, _SI), formula, _fmt(unit), govopt_value).fill = _FORMULA_FILL
        si = f"{get_column_letter(_SI)}{r}"
        seen = None if govopt_value is None else govopt_value * factor
        _formula(ws.cell(r, _VALUE), f"={si}" if factor == 1.0 else f"={si}*{factor!r}",
                 _fmt(shown), seen).fill = _FORMULA_FILL
        _set(ws.cell(r, _GOVOPT), seen, _fmt(shown))
        v, g = f"{get_column_letter(_VALUE)}{r}", f"{get_column_letter(_GOVOPT)}{r}"
        _formula(ws.cell(r, _RELDIFF), f"=IF({g}=0,ABS({v}),ABS({v}/{g}-1))", _RELDIFF_FORMAT,
                 0.0)
        self._name(name)
        self.row += 1

    def helical_spring(self, sd, props) -> None:
        """A helical spring's live stiffness, index and Wahl factor on the named wire diameter,
        coil radius, turns and shear modulus (one definition for every type's sheet)."""
        self.formula("stiffness", "spring stiffness (whole spring)", "kappa",
                     "=shear_modulus*wire_diameter^4/(64*coil_radius^3*turns)", "N/m", sd.kappa,
                     "kappa = G d^4 / (64 r^3 n) (Wahl 1944; Hamabe Ex. 1)")
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
                     "delta = (omega_a - omega_i) / omega0, omega0 the mean speed (Hamabe Part I)")
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
        """An explanation in italics across the printed columns (quantity .. formula /
        source), wrapped."""
        c = _set(self.ws.cell(self.row, 1), text)
        c.font = _ITALIC
        c.alignment = _WRAP
        self.ws.merge_cells(start_row=self.row, start_column=1, end_row=self.row,
                            end_column=_NOTE)
        self.ws.row_dimensions[self.row].height = 15.0 * math.ceil(len(text) / _TEXT_LINE)
        self.row += 1


def _build_design(wb: Workbook, ws: Worksheet, res: Result) -> None:
    s = _DesignSheet(wb, ws)
    if not res.spec.governor.excel_design(s, res):  # a type may write its own live sheet
        _generic_design(s, res)
    s.row += 1
    s.text("Yellow cells are inputs, in the units beside them (mm, N/mm, MPa, rpm, deg); blue "
           "cells are formulas. The formulas work in SI on the defined names (column "
           f"{get_column_letter(_NAME)}): each is the SI cell of column "
           f"{get_column_letter(_SI)}, converted from the input or shown in column "
           f"{get_column_letter(_VALUE)} in the unit beside it. 'govopt value' is govopt's result "
           "when the workbook was written; 'rel. difference' compares the two, so it shows how "
           "far an edited design has moved.")
    s.text("The characteristic table, k^2 and dynamics on the other sheets are govopt values "
           "and do not follow edits here; re-run govopt for them.")
    for first, end in zip(s.titles, [*s.titles[1:], s.row + 1], strict=True):
        _keep_table(ws, first, end - 2, header=1)  # printed: a section whole, or its ends kept
    _keep_table(ws, 1, s.row - 1, header=1)  # the sheet's one table, under the header row
    _widths(ws, _DESIGN_WIDTHS)
    for (c,) in ws.iter_rows(min_row=2, min_col=_NOTE, max_col=_NOTE):
        if isinstance(c.value, str) and len(c.value) > 60:
            c.alignment = _WRAP  # the page's width ends here: a long source wraps


def _seam_constants(res: Result, x: float) -> dict[str, float]:
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


def _seam_meanings(q: str, mass: str) -> dict[str, tuple[str, str]]:
    """What each constant of :func:`_seam_constants` is, in words, and its SI unit (``q``: the
    generalised force's, N m or N), for the Design sheet's labels: ``omega^2 = (kappa (A - B
    l0) + cf + m cf_m + M cf_c) / (lv + m lv_m + M lv_c)``, ``F = kappa (A_F - B_F l0)``."""
    return {
        "A": ("spring's pull per N/m of rate", f"{q}/(N/m)"),
        "B": ("spring's pull per N/m of rate and m of free length", f"{q}/N"),
        "A_F": ("spring's stretch term (force per N/m of rate)", "m"),
        "B_F": ("spring's free-length factor (a pure number)", ""),
        "cf": ("dead loads' pull without the weights (links, valve gear)", q),
        "cf_m": (f"dead loads' pull per kg of {mass}", f"{q}/kg"),
        "cf_c": ("dead loads' pull per kg of central load", f"{q}/kg"),
        "lv": ("centrifugal pull per omega^2 without the weights", f"{q}*s^2"),
        "lv_m": (f"centrifugal pull per omega^2 and kg of {mass}", f"{q}*s^2/kg"),
        "lv_c": ("centrifugal pull per omega^2 and kg of central load", f"{q}*s^2/kg"),
    }


def _generic_design(s: _DesignSheet, res: Result) -> None:
    """The Design sheet of any governor type on the seam's constants at the range's ends."""
    spec, sd, ds, props = res.spec, res.spring, res.design, res.spring_properties
    gov, sp, mat, st = spec.governor, spec.speed, spec.material, res.statics
    mk = gov.mass_key
    helical = bool(props)
    s.section("Inputs (yellow, in the units beside them): edit them and the formulas below "
              "follow")
    s.input(f"{mk}_weight", f"{mk} weight (each)", "w", sd.m * G_STANDARD, "N",
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
                    "design.spring_stiffness")
        s.input("free_length", f"spring free length ({gov.free_length_key})", "l0", sd.l0, "m",
                f"design.{gov.free_length_key}" if ds.free_half_length is not None else
                "govopt: equilibrium at the normal configuration at the mean speed")
    if sp is not None:
        s.input("omega_mean", "mean speed", "omega0", sp.omega_mean, "rad/s", "speed.mean")
        s.input("irregularity_required", "required irregularity (at most)", "delta0",
                sp.irregularity, "", "speed.irregularity")
    ends = (("inner", 0, "i"), ("outer", -1, "a"))
    s.section(f"The seam at the ends of the range ({gov.title}; constants from govopt, "
              "generalised forces per unit of the masses)")
    q = "N*m" if gov.coordinate == "angle" else "N"  # the generalised force's unit
    meaning = _seam_meanings(q, mk)
    s.text("omega^2 = (kappa (A - B l0) + cf + m cf_m + M cf_c) / (lv + m lv_m + M lv_c) and "
           "F = kappa (A_F - B_F l0): the equilibrium by virtual work, split by what it is "
           "linear in (the spring's rate kappa and free length l0, the weights' masses m and "
           "M); 'pull' is the generalised force along the coordinate "
           f"({'N m about the angle' if gov.coordinate == 'angle' else 'N along the length'})."
           " These constants depend on the linkage alone; govopt wrote them at the inner (_i) "
           "and outer (_a) end of the range.")
    spring_terms = ("A", "B", "A_F", "B_F")
    for tag, i, sym in ends:
        for key, value in _seam_constants(res, st.alpha[i]).items():
            if gov.spring is None and key in spring_terms:
                continue  # no spring: its terms are zero and no formula reads them
            what, unit = meaning[key]
            s.input(f"{key.lower()}_{tag}", f"{what}, {tag} end", f"{key}_{sym}", value, unit,
                    "govopt.analysis.statics.terms (the seam)",
                    _sig_format(sections.shown(value, unit)[0]))
    s.section("Derived quantities (blue, live formulas) next to govopt's values as written")
    s.formula(f"{mk}_mass", f"{mk} mass", "m", f"={mk}_weight/std_gravity", "kg", sd.m,
              "m = w / g_n")
    s.formula("central_mass", "central load's mass", "M", "=central_weight/std_gravity", "kg",
              sd.central or 0.0, "M = W / g_n")
    if helical:
        s.helical_spring(sd, props)
        factor = s.stress_factor(mat.stress_correction, props["spring_index"])
    for tag, i, sym in ends:
        if gov.spring is None:
            break
        s.formula(f"spring_force_{tag}", f"spring force at {gov.coordinate_name}_{sym}",
                  f"F_{sym}", f"=stiffness*(a_f_{tag}-b_f_{tag}*free_length)", "N",
                  st.spring_force[i], "F = kappa (A_F - B_F l0)")
        if helical:
            s.formula(f"shear_stress_{tag}", f"shear stress at {gov.coordinate_name}_{sym}",
                      f"tau_{sym}", f"=16*ABS(spring_force_{tag})*coil_radius/"
                      f"(PI()*wire_diameter^3)" + factor, "Pa",
                      st.stress[i], "tau = 16 |F| r / (pi d^3)" + (" x K" if factor else ""))
    for tag, i, sym in ends:
        spring_q = (f"stiffness*(a_{tag}-b_{tag}*free_length)+" if gov.spring is not None
                    else "")
        w = (f"=SQRT(({spring_q}cf_{tag}+{mk}_mass*cf_m_{tag}+central_mass*cf_c_{tag})/"
             f"(lv_{tag}+{mk}_mass*lv_m_{tag}+central_mass*lv_c_{tag}))")
        s.formula(f"omega_{tag}", f"equilibrium speed at {gov.coordinate_name}_{sym}",
                  f"omega_{sym}", w, "rad/s", st.omega[i],
                  "omega^2 = (kappa (A - B l0) + cf) / (jp - ci): virtual work on the seam")
        s.formula(f"rpm_{tag}", f"equilibrium speed at {gov.coordinate_name}_{sym}", f"N_{sym}",
                  f"=omega_{tag}*30/PI()", "rpm", st.omega[i] * 30.0 / math.pi,
                  "N = 30 omega / pi")
    if sp is not None:
        s.irregularity(res)


# --------------------------------------------------------------------------------------------
# Characteristic


def _build_characteristic(ws: Worksheet, res: Result) -> None:
    """The characteristic in the units people read (deg or mm, rpm, MPa; omega in rad/s, the
    paper's), and its chart under it with the spec's required speed band: printed, the chart
    shares its page with the table's last rows (:func:`_paginate`), never alone under a
    repeated header."""
    st, gov, spec = res.statics, res.spec.governor, res.spec
    xs, xu = gov.shown(st.alpha)  # the configuration as people read it (deg or mm)
    q = "N*m" if gov.coordinate == "angle" else "N"  # the generalised force's unit
    raw: list[tuple[str, Any, str]] = [
        ("omega", st.omega, "rad/s/"),  # rad/s as the paper writes it (rpm beside it)
        ("speed", st.omega, "rad/s"),
        *((name, v, q) for name, v in zip(gov.force_names, (st.M_z, st.M_f, st.M_r0),
                                          strict=True)),
    ]
    if gov.spring is not None:
        raw.append(("spring force F", st.spring_force, "N"))
        if np.isfinite(st.stress).any():  # a spring given by its rate alone has no stress
            raw.append(("shear stress tau", st.stress, "Pa"))
    raw += [(name, values, unit) for name, (values, unit) in st.extra.items()]
    if res.k2 is not None:
        raw.append(("k^2", res.k2, "rad^2/s^2"))
    cols = [(f"{gov.coordinate_name} ({xu})", np.asarray(xs, dtype=float), xu)]
    for name, values, unit in raw:
        if unit == "rad/s/":
            cols.append((f"{name} (rad/s)", np.asarray(values, dtype=float), "rad/s"))
            continue
        v, u = sections.shown(np.asarray(values, dtype=float), unit)
        cols.append((f"{name} ({_unit_label(u)})", v, u))
    _header(ws, 1, [c[0] for c in cols])
    ws.freeze_panes = "B2"
    n = len(st.alpha)
    for j, (_, values, unit) in enumerate(cols, start=1):
        for i in range(n):
            _set(ws.cell(i + 2, j), values[i], _fmt(unit))
    _widths(ws, {j: 13 for j in range(1, len(cols) + 1)})
    rpm = 3  # the speed column
    chart = _scatter("Characteristic (equilibrium by virtual work; Hamabe eq. 12): speed "
                     "against configuration", f"{gov.coordinate_name} ({xu})", "speed (rpm)",
                     width=24.0, height=11.0)
    _add_series(chart, ws, 1, rpm, 1, n + 1, colour=0)
    if spec.speed is not None:  # the required band: two dashed lines, data right of the table
        col = len(cols) + 2
        _title(ws, 1, "required band (chart data)", col=col, font=_BOLD)
        band = ((spec.speed.omega_inner, "required inner speed (rpm)"),
                (spec.speed.omega_outer, "required outer speed (rpm)"))
        _set(ws.cell(2, col), f"{gov.coordinate_name} ({xu})")
        for k, (_, label) in enumerate(band, start=1):
            _set(ws.cell(2, col + k), label)
        for i, x in enumerate((float(xs[0]), float(xs[-1])), start=3):
            _set(ws.cell(i, col), x, _fmt(xu))
            for k, (w, _) in enumerate(band, start=1):
                _set(ws.cell(i, col + k), w * 30.0 / math.pi, _fmt("rpm"))
        for k in (1, 2):
            _add_series(chart, ws, col, col + k, 2, 4, colour=1, dash=True)
        ws._govopt_print_cols = len(cols)
    else:
        chart.legend = None  # one curve: the axis titles name it
    chart.x_axis.scaling.min, chart.x_axis.scaling.max = _axis_range(xs)
    anchor = f"B{n + 3}"
    ws.add_chart(chart, anchor)  # below the table
    _keep_table(ws, 1, n + 1, header=1)
    _keep(ws, max(2, n + 1 - 5), _extent(ws, anchor, 24.0, 11.0)[1])  # with the last rows


# --------------------------------------------------------------------------------------------
# Dynamics


def _build_dynamics(ws: Worksheet, res: Result) -> None:
    """k^2 over the range with its chart, then the declared dynamics tables
    (:func:`govopt.report.sections.dynamics`): load changes, roots with real and imaginary
    parts, the forced vibration and its harmonics, with named columns and units; the responses'
    data sit to the right of the printed area, their charts inside it."""
    spec, st, gov = res.spec, res.statics, res.spec.governor
    w0sq = res.omega_reference**2
    _title(ws, 1, "Dynamics (Hamabe Parts II and III)")
    ws.freeze_panes = "A2"
    widths = {1: 46, 2: 13, **{j: 14 for j in range(3, 15)}}
    for j, w in widths.items():
        ws.column_dimensions[get_column_letter(j)].width = w
    row = 3
    if res.k2 is not None:
        xs, xu = gov.shown(st.alpha)
        _title(ws, row, "Restoring stiffness k^2 over the range against omega0^2 "
                        "(Hamabe eqs. 18-20: stable for 0 < k^2 < omega0^2)", font=_BOLD)
        head = row + 1
        _header(ws, head, [f"{gov.coordinate_name} ({xu})", "k^2 (rad^2/s^2)",
                           "omega0^2 (rad^2/s^2)", "k^2 / omega0^2"])
        for i in range(len(st.alpha)):
            r = head + 1 + i
            _set(ws.cell(r, 1), float(xs[i]), _fmt(xu))
            _set(ws.cell(r, 2), res.k2[i], _fmt("rad^2/s^2"))
            _set(ws.cell(r, 3), w0sq, _fmt("rad^2/s^2"))
            _set(ws.cell(r, 4), res.k2[i] / w0sq, "0.0000")
        last = head + len(st.alpha)
        chart = _scatter("k^2 against omega0^2 (stable below omega0^2, above 0)",
                         f"{gov.coordinate_name} ({xu})", "k^2 (rad^2/s^2)")
        _add_series(chart, ws, 1, 2, head, last, colour=0)
        _add_series(chart, ws, 1, 3, head, last, colour=1, dash=True)
        chart.y_axis.scaling.min = min(0.0, float(np.min(res.k2)))
        chart.x_axis.scaling.min, chart.x_axis.scaling.max = _axis_range(xs)
        ws.add_chart(chart, f"F{head}")
        _keep_table(ws, row, last)
        _keep(ws, row, _extent(ws, f"F{head}", 18.0, 9.0)[1])  # the chart beside the table
        row = max(last + 2, head + 20)
    dyn = res.dynamics or {}
    if not dyn:
        why = ("the spec has no [engine] data (flywheel inertia, torque slope), which the "
               "load-change and vibration analyses need" if spec.engine is None else
               "this result carries none (statics only); the spec has engine data, so run "
               "the dynamics analysis to fill this part")
        _set(ws.cell(row, 1), f"Dynamics were not run: {why}.").font = _ITALIC
        return
    tables = sections.dynamics(res)
    for table in (t for t in tables if not t.series):
        row = _write_table(ws, row, table)
    series = [t for t in tables if t.series]
    if series:
        # the data right of the printed area (the charts show them), two columns each
        data_col = _extent(ws, "F1", _CHART_SIZE[0], 1.0)[0] + 2
        _set(ws.cell(row, 1), f"Responses: the charts below; their data are in columns "
             f"{get_column_letter(data_col)} onwards (not printed).").font = _ITALIC
        row += 1
        for k, table in enumerate(series):
            col = data_col + 3 * k
            _title(ws, 2, table.title, col=col, font=_BOLD)
            head, last = _write_rows(ws, 3, table, col)
            chart = _scatter(table.chart.title, table.headers[table.chart.x],
                             table.headers[table.chart.ys[0]])
            for n, j in enumerate(table.chart.ys):
                _add_series(chart, ws, col + table.chart.x, col + j, head, last, colour=n)
            chart.legend = None  # one curve: the axis titles name it
            anchor = f"{'A' if k % 2 == 0 else 'F'}{row}"
            ws.add_chart(chart, anchor)
            _keep(ws, row - (k == 0), _extent(ws, anchor, *_CHART_SIZE)[1])
            if k % 2 == 1 or k == len(series) - 1:
                row = _extent(ws, anchor, *_CHART_SIZE)[1] + 2
            for j in (0, 1):
                ws.column_dimensions[get_column_letter(col + j)].width = 16
        ws._govopt_print_cols = data_col - 2


def _sig_format(value: Any) -> str | None:
    """A number format showing ``value`` to 5 significant digits (the cell keeps every digit):
    whole numbers with thousands separators, very large or small numbers in E notation."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    if isinstance(value, int):
        return "#,##0"
    a = abs(value)
    if a == 0:
        return "0"
    if a >= 1e6 or a < 1e-4:
        return "0.0000E+00"
    return "0." + "0" * max(1, 4 - math.floor(math.log10(a))) if a < 1e4 else "#,##0.0"


def _write_rows(ws: Worksheet, row: int, table: sections.Table, col: int = 1) -> tuple[int, int]:
    """The header and rows of a declared table at ``(row, col)``; returns (header row, last
    row). Numbers stay numbers (5 significant digits shown), words are text."""
    _header(ws, row, table.headers, col)
    for i, values in enumerate(table.rows, start=1):
        for j, v in enumerate(values):
            c = _set(ws.cell(row + i, col + j), v, _sig_format(v))
            if isinstance(v, str) and j >= (2 if table.properties else 1):
                width = ws.column_dimensions[get_column_letter(col + j)].width or 8.43
                # a word sits right like the numbers; a longer text wraps in its cell
                c.alignment = _RIGHT if len(v) < width else _WRAP
    return row, row + len(table.rows)


def _write_table(ws: Worksheet, row: int, table: sections.Table, col: int = 1) -> int:
    """A declared table with its title and notes; returns the next free row."""
    _title(ws, row, table.title, col=col, font=_BOLD)
    _, last = _write_rows(ws, row + 1, table, col)
    for k, note in enumerate(table.notes, start=1):
        _set(ws.cell(last + k, col), note).font = _ITALIC
    _keep_table(ws, row, last + len(table.notes))
    return last + len(table.notes) + 2


# --------------------------------------------------------------------------------------------
# Checks


def _live_checks(res: Result) -> dict[str, tuple[str | None, str | None]]:
    """Checks whose value and limit can follow the Design sheet's formulas: name -> (value
    formula, limit formula), each only where it is the very quantity govopt checked."""
    def same(a: float, b: float) -> bool:
        return math.isclose(a, b, rel_tol=1e-12, abs_tol=0.0)

    spec, out = res.spec, {}
    for c in res.checks:
        if c.name == "shear stress":
            pair = ("=max_shear_stress" if same(c.value, res.max_stress) else None,
                    "=allowable_stress" if same(c.limit, spec.material.allowable_shear_stress)
                    else None)
        elif c.name == "irregularity":
            pair = ("=irregularity" if same(c.value, res.irregularity) else None,
                    "=irregularity_required" if same(c.limit, spec.speed.irregularity)
                    else None)
        else:
            continue
        out[c.name] = pair
    return out


def _build_checks(ws: Worksheet, res: Result) -> None:
    """Every check with value, limit, margin and PASS/FAIL; the stress and irregularity live on
    the Design sheet's names. Configurations, lengths and slopes in the units people read (deg
    or mm: :data:`govopt.report.sections.SHOWN`; the margin is the same in any unit), words for
    a value that is not finite; then the optimiser's record as declared tables."""
    headers = ["check", "value", "sense", "limit", "unit", "margin", "result",
               "binding (active)", "govopt margin", "source"]
    _header(ws, 1, headers)
    ws.freeze_panes = "B2"
    row = 2
    live = _live_checks(res)
    for c in res.checks:
        value, unit = sections.shown(c.value, c.unit, only=SHOWN_IN_CHECKS)
        limit, _ = sections.shown(c.limit, c.unit, only=SHOWN_IN_CHECKS)
        factor = sections.SHOWN[c.unit][1] if unit != c.unit else 1.0
        fmt = _fmt(unit) if unit else _GENERAL_FORMAT
        finite = math.isfinite(c.value) and math.isfinite(c.limit)
        _set(ws.cell(row, 1), c.name)
        value_f, limit_f = (None if f is None or factor == 1.0 else f"=({f[1:]})*{factor!r}"
                            for f in live.get(c.name, (None, None)))
        value_f = value_f or live.get(c.name, (None, None))[0]
        limit_f = limit_f or live.get(c.name, (None, None))[1]
        if value_f and finite:
            _formula(ws.cell(row, 2), value_f, fmt, value)
        else:
            _set(ws.cell(row, 2), sections.cell(value), fmt)
        _set(ws.cell(row, 3), c.sense)
        if limit_f and finite:
            _formula(ws.cell(row, 4), limit_f, fmt, limit)
        else:
            _set(ws.cell(row, 4), sections.cell(limit), fmt)
        _set(ws.cell(row, 5), _unit_label(unit))
        diff = f"(D{row}-B{row})" if c.sense == "<=" else f"(B{row}-D{row})"
        if unit != c.unit:  # shown in another unit: the check's own scale, converted
            scale = repr(float((c.scale or (abs(c.limit) if c.limit != 0 else 1.0)) * factor))
        elif c.scale:
            scale = repr(float(c.scale))
        else:
            scale = f"IF(D{row}=0,1,ABS(D{row}))"
        verdict = ("PASS" if c.passed else "FAIL", "yes" if c.active else "")
        if not finite:  # a word in B or D: govopt's margin and verdict, no formula
            _set(ws.cell(row, 6), sections.cell(c.margin), "0.00%")
            _set(ws.cell(row, 7), verdict[0])
            _set(ws.cell(row, 8), verdict[1])
        else:
            _formula(ws.cell(row, 6), f"={diff}/{scale}", "0.00%", c.margin)
            if c.verdict is None:
                _formula(ws.cell(row, 7), f'=IF(F{row}>=-1E-9,"PASS","FAIL")', None, verdict[0])
                _formula(ws.cell(row, 8),
                         f'=IF(AND(F{row}>=-1E-9,F{row}<{ACTIVE_TOL!r}),"yes","")', None,
                         verdict[1])
            else:  # decided by govopt (over-regulation: transient.over_regulates, all t >= 0)
                _set(ws.cell(row, 7), verdict[0])
                _set(ws.cell(row, 8), verdict[1])
        _set(ws.cell(row, 9), sections.cell(c.margin), "0.00%")
        _set(ws.cell(row, 10), c.source).alignment = _WRAP
        row += 1
    last = row - 1
    _keep_table(ws, 1, last + 4, header=1)  # with the binding and failed lines under it
    if res.checks:
        green = FormulaRule(formula=["$G2=\"PASS\""], fill=_PASS_FILL, font=_PASS_FONT)
        red = FormulaRule(formula=["$G2=\"FAIL\""], fill=_FAIL_FILL, font=_FAIL_FONT)
        for rng in (f"F2:G{last}", f"A2:A{last}"):
            ws.conditional_formatting.add(rng, green)
            ws.conditional_formatting.add(rng, red)
    row += 1
    active = [c.name for c in res.checks if c.active]
    _set(ws.cell(row, 1), "binding (active) checks").font = _BOLD
    _set(ws.cell(row, 2), ", ".join(active) if active else "none "
         f"(a satisfied check is binding when its margin is below {ACTIVE_TOL:g})")
    row += 1
    failed = [c.name for c in res.checks if not c.passed]
    _set(ws.cell(row, 1), "failed checks").font = _BOLD
    _set(ws.cell(row, 2), ", ".join(failed) if failed else "none")
    row += 1
    _set(ws.cell(row, 1), "margin: the distance to the limit as a share of the limit (of the "
         "check's scale where the limit is 0); the same in any unit.").font = _ITALIC
    row += 2
    tables = sections.optimisation(res)
    if not tables:
        _title(ws, row, "Optimisation", font=_BOLD)
        _set(ws.cell(row + 1, 1), "No optimisation in this result: it evaluates a given design "
             "(no binding constraints or sensitivities to report).").font = _ITALIC
    for table in tables:
        row = _write_table(ws, row, table)
    labels = [len(str(r[0])) for t in tables for r in t.rows] + [len(c.name) for c in res.checks]
    _widths(ws, {1: max([34, *labels]) + 2, 2: 18, 3: 14, 4: 18, 5: 13, 6: 11, 7: 9, 8: 10,
                 9: 13, 10: 60})


# --------------------------------------------------------------------------------------------
# Spring


def _allowable_note(res: Result) -> str:
    """Where the allowable shear stress on the Design sheet comes from."""
    if res.spec.material.allowable_shear_stress is not None:
        return "material.allowable_shear_stress"
    return (f"material.grade {res.spec.material.grade}: the standard's rule at the design's "
            "wire diameter (not live in d; see the Spring sheet)")



#: How the Spring sheet (the one a spring maker reads) shows an SI unit: (unit, factor, number
#: format): millimetres, N/mm, MPa, rpm, degrees.
ENGINEERING = {
    "m": ("mm", 1e3, "0.000"), "Pa": ("MPa", 1e-6, "0.00"), "N/m": ("N/mm", 1e-3, "0.000"),
    "rad/s": ("rpm", 30.0 / math.pi, "0.00"), "rad": ("deg", 180.0 / math.pi, "0.000"),
    "N": ("N", 1.0, "#,##0.0"), "Hz": ("Hz", 1.0, "0.00"), "kg": ("kg", 1.0, "0.0000"),
    "kg/m^3": ("kg/m^3", 1.0, "#,##0"), "rpm": ("rpm", 1.0, "0.00"), "s": ("s", 1.0, "0.000"),
}


def engineering(value: Any, unit: str) -> tuple[Any, str, str]:
    """``(value, unit, number format)`` of an SI value as the Spring sheet shows it
    (:data:`ENGINEERING`); a value with another unit, or no number, as it is ("General")."""
    if unit not in ENGINEERING:
        fractional = isinstance(value, float) and math.isfinite(value) and value % 1 != 0
        return value, unit, "0.000" if fractional and not unit else "General"
    shown, factor, fmt = ENGINEERING[unit]
    if isinstance(value, bool) or not isinstance(value, int | float | np.number):
        return value, shown, "General"
    return float(value) * factor, shown, fmt


def _record_rows(record: Mapping):
    """``(label, value, SI unit)`` rows of a record (:func:`govopt.springs.sheet.record_rows`:
    the units are the figures' fields), a section's title with the value ``SECTION``, indented
    by depth; lists as one line of text in the unit the sheet shows."""
    for depth, label, value, unit in record_rows(record):
        label = "  " * depth + label
        if isinstance(value, list | tuple):
            shown = [engineering(v, unit) for v in value]
            yield label, ", ".join(f"{v:.6g}" if isinstance(v, float) else str(v)
                                   for v, _, _ in shown), engineering(0.0, unit)[1]
        else:
            yield label, value if value is SECTION else _scalar(value), unit


def _build_spring(ws: Worksheet, res: Result) -> None:
    """The spring maker's sheet, the material at the wire diameter, the static and fatigue
    loads, the tolerance spread of the governed speed range, and the spring engineering checks
    with value, limit, margin and source (govopt values; no formulas)."""
    _title(ws, 1, "Spring: specification for the spring maker and spring engineering")
    ws.freeze_panes = "A2"
    rep = res.spring_report
    if rep is None:
        _set(ws.cell(3, 1), "No wire spring in this design (a dead-weight governor, a leaf, or "
             "a spring given by its stiffness only).").font = _ITALIC
        ws.column_dimensions["A"].width = 90  # printed: the title and the line whole
        return
    _header(ws, 2, ["quantity", "value", "unit"])
    row = 3
    tops = []  # the top-level sections' title rows: printed whole where they fit on a page
    for label, value, unit in _record_rows(rep.record()):
        if value is SECTION:
            _title(ws, row, label, font=_BOLD)
            _keep(ws, row, row + 3)
            if not label.startswith(" "):
                tops.append(row)
        else:  # engineering units, each number with its display format
            value, unit, fmt = engineering(value, unit)
            _set(ws.cell(row, 1), label)
            _set(ws.cell(row, 2), "not given" if value is None else value, fmt)
            ws.cell(row, 2).alignment = _LEFT_WRAP
            _set(ws.cell(row, 3), "" if value is None else unit)
        row += 1
    for first, end in zip(tops, [*tops[1:], row], strict=True):
        _keep_table(ws, first, end - 1, header=2)
    _keep_table(ws, 1, row - 1, header=2)  # the sheet's list, under the header row
    row += 1
    first_check = row
    graded = res.spec.material.grade is not None
    rows = [c for c in res.checks if graded and c.group == "spring"]
    _title(ws, row, "Spring engineering checks" + ("" if rows else ": none (they need a "
                                                    "material.grade)"), font=_BOLD)
    row += 1
    if rows:
        _header(ws, row, ["check", "value", "sense", "limit", "unit", "margin", "result",
                          "source"])
        for c in rows:
            row += 1
            (value, unit, fmt), (limit, _, _) = (engineering(v, c.unit)
                                                 for v in (c.value, c.limit))
            fmt = fmt if c.unit else "0.000"
            for col, v, f in ((1, c.name, None), (2, value, fmt), (3, c.sense, None),
                              (4, limit, fmt), (5, _unit_label(unit), None),
                              (6, c.margin, "0.00%"), (7, "PASS" if c.passed else "FAIL", None),
                              (8, c.source, None)):
                _set(ws.cell(row, col), v, f)
    _keep_table(ws, row - len(rows) - 1 - bool(rows), row)
    # printed with the list's last rows: a page after the list would repeat the list's header
    _keep(ws, tops[-1] if row - tops[-1] <= 30 else first_check - 4, row)
    _widths(ws, {1: 40, 2: 40, 3: 14, 4: 18, 5: 10, 6: 11, 7: 9, 8: 80})


# --------------------------------------------------------------------------------------------
# print setup and cached values

#: Charts' size (cm): wide enough to read, two side by side on a landscape page.
_CHART_SIZE = (18.0, 9.0)
#: Check units the Checks sheet shows as people read them (a live stress is the Design sheet's
#: name in Pa times 1E-6: MPa).
SHOWN_IN_CHECKS = tuple(SHOWN)  # every unit a person reads otherwise: rpm, mm, MPa, deg
#: Printable width of an A4 page in portrait, in screen pixels (96 per inch, 1.5 cm margins).
_PORTRAIT_PX = 680


def _px(width: float | None) -> int:
    """Screen pixels of a column of ``width`` characters (Excel's rule, 7 px per character)."""
    return int((width or 8.43) * 7 + 5)


def _extent(ws: Worksheet, anchor: str, width_cm: float, height_cm: float) -> tuple[int, int]:
    """The last column and row a chart of this size anchored at ``anchor`` covers."""
    col, row = column_index_from_string(re.match(r"[A-Z]+", anchor)[0]), int(
        re.search(r"\d+", anchor)[0])
    px = width_cm / 2.54 * 96
    while px > 0:
        px -= _px(ws.column_dimensions[get_column_letter(col)].width)
        col += 1
    px = height_cm / 2.54 * 96
    while px > 0:
        px -= (ws.row_dimensions[row].height or _ROW_PT) * 96 / 72
        row += 1
    return col - 1, row - 1


def _align_top(ws: Worksheet) -> None:
    """Every cell aligned at the top of its row: a label beside a wrapped text (a long source,
    a note) reads as that text's row, not the next one's."""
    top: dict[tuple, Alignment] = {}  # one object per alignment: openpyxl finds it by identity
    for c in _written(ws):
        a = c.alignment
        if a.vertical is None:
            key = (a.horizontal, a.wrap_text, a.indent)
            if key not in top:
                top[key] = Alignment(horizontal=a.horizontal, vertical="top",
                                     wrap_text=a.wrap_text, indent=a.indent)
            c.alignment = top[key]


def fit_rows(ws: Worksheet) -> None:
    """Row heights for wrapped text (headers, notes): openpyxl stores none and a reader that
    does not fit rows on opening would draw wrapped lines over the next row. Lines are
    estimated from the column's width (about 1.1 characters of text per width unit)."""
    need: dict[int, int] = {}
    merged = {r.start_cell.coordinate for r in ws.merged_cells.ranges}  # sized where merged
    for c in _written(ws):
        if not (isinstance(c.value, str) and c.alignment.wrap_text) or c.data_type == "f" \
                or c.coordinate in merged:
            continue
        per_line = max(1.0, 1.1 * (ws.column_dimensions[c.column_letter].width or 8.43) - 1)
        lines = sum(max(1, math.ceil(len(part) / per_line)) for part in c.value.split("\n"))
        need[c.row] = max(need.get(c.row, 1), lines)
    for r, lines in need.items():
        if lines > 1:
            ws.row_dimensions[r].height = max(ws.row_dimensions[r].height or 0, 15.0 * lines)


def _axis_range(x) -> tuple[float, float]:
    """Round axis ends just outside the data (the chart then starts where the data do)."""
    lo, hi = float(np.min(x)), float(np.max(x))
    step = 10 ** math.floor(math.log10(hi - lo)) if hi > lo else 1.0
    return math.floor(lo / step) * step, math.ceil(hi / step) * step


def print_setup(ws: Worksheet) -> None:
    """Print every sheet readably: A4, fit to the page width (as many pages down as needed),
    landscape where the content is wider than a portrait page, page breaks that keep tables
    together (:func:`_paginate`), the header of a table that runs on repeated on each page
    (:func:`print_titles`), a print area covering the cells and charts (not the charts' data
    placed to the right), the sheet's name and page number in the footer."""
    cols = getattr(ws, "_govopt_print_cols", None) or ws.max_column
    rows = ws.max_row if cols == ws.max_column else max(
        (c.row for c in _written(ws) if c.column <= cols and c.value is not None),
        default=1)
    for chart in ws._charts:
        c, r = _extent(ws, chart.anchor, chart.width, chart.height)
        cols, rows = max(cols, c), max(rows, r)
    width = sum(_px(ws.column_dimensions[get_column_letter(j)].width) for j in range(1, cols + 1))
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.orientation = "landscape" if width > 1.25 * _PORTRAIT_PX else "portrait"
    ws.page_setup.fitToWidth, ws.page_setup.fitToHeight = 1, 0
    ws.sheet_properties.pageSetUpPr.fitToPage = True
    ws.page_margins = PageMargins(left=0.5, right=0.5, top=0.6, bottom=0.6, header=0.3,
                                  footer=0.3)
    ws.print_options.gridLines = False
    ws.print_area = f"A1:{get_column_letter(cols)}{rows}"
    ws.oddFooter.center.text = "&A, page &P of &N"
    page_w, page_h = _PAGE_PX[ws.page_setup.orientation]
    _paginate(ws, rows, page_h / min(1.0, page_w / max(_SPREADSHEET_WIDTH * width, 1)))
    repeat = print_titles(ws)
    if repeat is not None:
        ws.print_title_rows = f"{repeat[0]}:{repeat[1]}"


def print_titles(ws: Worksheet) -> tuple[int, int] | None:
    """The rows to repeat at the top of each printed page (one range per sheet): the title and
    header of the table that runs onto another page (the layout lets one table a sheet do so,
    the last or the one whose end shares its page with what follows; a spreadsheet repeats
    the rows only on the pages after the one they first appear on), else the sheet's title row
    where row 1 is a title and not a table's header, else none (each page then starts with a
    table's own title and header)."""
    breaks = [b.id for b in ws.row_breaks.brk]
    spanning = {t.repeat for t in tables(ws) if t.spans(breaks)}
    if spanning:
        return min(spanning)
    if not any(1 in (t.title, t.header) for t in tables(ws)):
        return (1, 1)
    return None


#: The printable width and height of an A4 page (px at 96 dpi) inside the margins of
#: :func:`print_setup` (0.5 in left and right, 0.6 in top and bottom), by orientation.
_PAGE_PX = {"portrait": (21.0 / 2.54 * 96 - 96, 29.7 / 2.54 * 96 - 115.2),
            "landscape": (29.7 / 2.54 * 96 - 96, 21.0 / 2.54 * 96 - 115.2)}
#: The share of a page's height :func:`_paginate` fills (room for the renderer's rounding).
_PAGE_FILL = 0.96
#: A row's height where none is set (pt), and the printed width of the columns against
#: :func:`_px`'s, as LibreOffice lays out the sheets (measured on its PDF: a default row 12.75
#: pt, columns about 1.1 times Excel's 7 px per character).
_ROW_PT, _SPREADSHEET_WIDTH = 12.75, 1.1


def _keep(ws: Worksheet, first: int, last: int) -> None:
    """Rows ``first`` .. ``last`` print on one page where they fit on one (a table's title with
    its header and first rows, a table's last rows with the chart under it)."""
    if not hasattr(ws, "_govopt_keep"):
        ws._govopt_keep = []
    ws._govopt_keep.append((first, last))


def _keep_table(ws: Worksheet, title: int, last: int, rows: int = 3,
                header: int | None = None) -> None:
    """A table from its title row to ``last``: whole on a page where it fits on one; else its
    title and header never end a page and its last ``rows`` rows never start one alone.
    ``header``: its column-header row (default the row under the title; the sheet's header row
    for a section of a sheet-wide table, the title itself for a section with none). The table
    is registered for :func:`print_setup`, which repeats the header of the table that runs
    onto another page at the top of each page it continues on."""
    header = title + 1 if header is None else header
    if not hasattr(ws, "_govopt_tables"):
        ws._govopt_tables = []
    ws._govopt_tables.append(PrintedTable(title, header, last))
    if last - title <= 30:
        _keep(ws, title, last)
    else:
        _keep(ws, title, max(title, header) + 1 + rows)
        _keep(ws, last - rows, last)


@dataclass(frozen=True)
class PrintedTable:
    """A table of a sheet as printed: its title row, its column-header row and its last row.
    ``header < title`` for a section of a sheet-wide table whose header heads the sheet."""

    title: int
    header: int
    last: int

    @property
    def repeat(self) -> tuple[int, int]:
        """The rows printed above the table's rows on a page it continues on: its title and
        header, or the sheet's rows down to the shared header (a section's)."""
        return (self.title, self.header) if self.header >= self.title else (1, self.header)

    def spans(self, breaks: Iterable[int]) -> bool:
        """Whether a page break (after row ``b``) falls between its header and its last row."""
        first = max(self.title, self.header)
        return any(first <= b < self.last for b in breaks)


def tables(ws: Worksheet) -> list[PrintedTable]:
    """The tables of a sheet built by :func:`build_workbook`, as registered for printing."""
    return list(getattr(ws, "_govopt_tables", []))


def _paginate(ws: Worksheet, last: int, height: float) -> None:
    """Manual page breaks so that no kept block (:func:`_keep`) is split where it fits on a
    page: rows are laid out by their heights on pages ``height`` px tall (the page's height at
    the print scale), the repeated rows on every page after the first (counted as the tallest
    range :func:`print_titles` may choose: a table's title and header, or row 1)."""
    keep = sorted(getattr(ws, "_govopt_keep", []))
    if not keep:
        return

    def px(r: int) -> float:
        return (ws.row_dimensions[r].height or _ROW_PT) * 96 / 72

    room = height * _PAGE_FILL
    title = max((sum(px(k) for k in range(a, b + 1)) for a, b in
                 {t.repeat for t in tables(ws)} | {(1, 1)}), default=0.0)
    used, start = 0.0, 1
    r = 1
    while r <= last:
        h = px(r)
        if used + h <= room or r == start:
            used += h
            r += 1
            continue
        # row r starts a new page: move the break up to the start of a block it would split
        brk = r
        for first, end in keep:
            if first < brk <= end and first > start and \
                    sum(px(k) for k in range(first, end + 1)) + title <= room:
                brk = first
        ws.row_breaks.append(Break(id=brk - 1))
        start, r, used = brk, brk, title


_CELL = re.compile(rb'<c r="([A-Z]+[0-9]+)"([^>]*)><f>(.*?)</f><v\s*/>\s*</c>', re.S)


def _cached_xml(sheet: bytes, values: Mapping[str, Any]) -> bytes:
    """``sheet`` (a worksheet part) with ``values[ref]`` as the cached result of each formula
    cell ``ref``: ``<v>number</v>``, or ``t="str"`` for text (SpreadsheetML, ECMA-376 Part 1,
    18.3.1.4 c and 18.18.11 ST_CellType)."""
    from xml.sax.saxutils import escape

    def fill(m: re.Match) -> bytes:
        ref, attrs, f = m[1].decode(), m[2], m[3]
        v = values.get(ref)
        if isinstance(v, bool) or v is None:
            return m[0]
        if isinstance(v, str):
            return (b'<c r="' + m[1] + b'"' + attrs + b' t="str"><f>' + f + b"</f><v>"
                    + escape(v).encode() + b"</v></c>")
        if not math.isfinite(v):
            return m[0]
        return b'<c r="' + m[1] + b'"' + attrs + b"><f>" + f + b"</f><v>" + \
            repr(float(v)).encode() + b"</v></c>"

    return _CELL.sub(fill, sheet)


def _store_cached_values(path: Path, cached: Mapping[tuple[str, str], Any]) -> None:
    """Rewrite the saved workbook at ``path`` with govopt's value of every formula cell as its
    cached result. openpyxl writes formulas without results, so pandas, previewers and other
    readers that do not recalculate would see empty cells; Excel and LibreOffice still
    recalculate on opening (openpyxl sets ``fullCalcOnLoad``)."""
    from xml.sax.saxutils import unescape

    if not cached:
        return
    with zipfile.ZipFile(path) as z:
        parts = [(info, z.read(info.filename)) for info in z.infolist()]
    files = dict((i.filename, data) for i, data in parts)
    rels = {}  # relationship id -> part name
    for m in re.finditer(rb"<Relationship\b[^>]*>", files["xl/_rels/workbook.xml.rels"]):
        rid, target = (re.search(p, m[0])[1] for p in (rb'Id="([^"]+)"', rb'Target="([^"]+)"'))
        rels[rid] = target.decode().lstrip("/")
    by_title: dict[str, dict[str, Any]] = {}
    for (title, ref), v in cached.items():
        by_title.setdefault(title, {})[ref] = v
    for m in re.finditer(rb"<sheet\b[^>]*>", files["xl/workbook.xml"]):
        name = re.search(rb'name="([^"]*)"', m[0])[1].decode()
        rid = re.search(rb'r:id="([^"]+)"', m[0])[1]
        target = rels[rid]
        part = target if target.startswith("xl/") else f"xl/{target}"
        values = by_title.get(unescape(name, {"&quot;": '"', "&apos;": "'"}))
        if values:
            files[part] = _cached_xml(files[part], values)
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for info, _ in parts:
            z.writestr(info, files[info.filename])


# --------------------------------------------------------------------------------------------
# Notes


def _build_notes(ws: Worksheet, res: Result) -> None:
    from .. import __version__

    spec, an, mat = res.spec, res.spec.analysis, res.spec.material
    now = _dt.datetime.now(_dt.UTC).replace(microsecond=0).isoformat()
    rows: list[tuple[str, Any]] = [
        ("govopt version", __version__),
        ("written (UTC)", now),
        ("result kind", res.kind),
        ("spec file", str(spec.path)),
        ("spec name", spec.name),
        ("governor type", spec.governor_type),
        ("", None),
        ("Method", None),
        ("statics", "Characteristic from the equilibrium M_f - M_z + M_r0 = 0 (Hamabe eq. 12) "
                    "at each configuration alpha, with M_z (eq. 1), M_f (eq. 2 or 3) and the "
                    "valve gear's mean reaction M_r0 (eq. 11)."),
        ("spring", "Stiffness G d^4 / (64 r^3 n) and stress 16 F r / (pi d^3) (Hamabe Ex. 1), "
                   "optionally times Wahl's factor (Wahl 1944); mass and surge frequency of "
                   "the active coils."),
        ("stability", "Restoring stiffness k^2 (Hamabe eqs. 18-20), required 0 < k^2 < "
                      "omega0^2."),
        ("dynamics", "Load change (eq. 28, stability by Hurwitz eq. 32) and forced vibration "
                     "(eqs. 16-23) when the spec has engine data: "
                     + ("included" if res.dynamics else "not in this result")),
        ("", None),
        ("Fidelity", None),
        ("analysis.geometry", an.geometry),
        ("analysis.reaction_speed", an.reaction_speed),
        ("analysis.reaction_slope", str(an.reaction_slope).lower()),
        ("analysis.valve_table", an.valve_table),
        ("analysis.points", an.points),
        ("analysis.harmonics", an.harmonics),
        ("analysis.settling_band", an.settling_band),
        ("material.stress_correction", mat.stress_correction if mat else "no spring material"),
        ("", None),
        ("Sources", None),
        *SOURCES,
        ("", None),
        ("Workbook", None),
        ("units", "Engineering units where a person reads (mm, N/mm, MPa, rpm, deg), each "
                  "column or row with its unit; the Design sheet's formulas work in SI (m, "
                  "kg, s, N, Pa, rad) on its defined names, the SI cells at its right."),
        ("Design sheet", "Yellow input cells, in the units beside them, feed the workbook "
                         "names (wire_diameter, coil_radius, turns, free_half_length, "
                         "pendulum_weight, ...: the SI cells converting them); blue cells are "
                         "live formulas on the names, each shown beside govopt's own value."),
        ("not live", "Characteristic, k^2, dynamics and checks other than stress and "
                     "irregularity are govopt's values when the workbook was written."),
        ("cached values", "Every formula cell also stores govopt's value as its cached "
                          "result, so readers that do not recalculate (pandas, previewers) "
                          "show numbers; Excel and LibreOffice recalculate on opening."),
        ("words", "yes/no for booleans; 'never' for a time that never comes (a response "
                  "that never reaches or never settles at its new equilibrium); 'not "
                  "decided' for a settling time beyond what the solver's time grid resolves; "
                  "'unbounded' for an unstable excursion; a blank cell is not defined."),
        ("printing", "Each sheet prints to the page width (landscape where wide); page "
                     "breaks keep a table with its title and header, its last rows, and a "
                     "chart with its rows; a table that runs onto another page has its title "
                     "and header repeated at the top of it; response data beside the Dynamics "
                     "charts are not printed."),
    ]
    _title(ws, 1, f"govopt {res.kind}: {spec.name}")
    ws.freeze_panes = "A2"
    titles = []
    for i, (key, value) in enumerate(rows, start=3):
        c = _set(ws.cell(i, 1), key)
        if value is None and key:
            c.font = _BOLD
            titles.append(i)
        if value is not None:
            _set(ws.cell(i, 2), value, "General").alignment = _WRAP
    for first, end in zip(titles, [*titles[1:], len(rows) + 4], strict=True):
        _keep_table(ws, first, end - 2, header=first)  # printed: a section whole where it fits
    _widths(ws, {1: 28, 2: 110})
