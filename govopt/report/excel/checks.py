"""The Checks sheet: every check with its value, limit, margin, verdict and source, in the units
people read (deg or mm, MPa, rpm: :data:`SHOWN_IN_CHECKS`; the margin is the same in any unit),
words for a value that is not finite, PASS/FAIL coloured; the binding and failed checks. The
Optimisation sheet: the optimiser's record as declared tables
(:func:`govopt.report.sections.optimisation`).

Every number here is govopt's (no formulas: a reader that does not recalculate sees them all);
the stress and the irregularity follow an edited design live on the Design sheet
(``stress_utilisation``, ``irregularity_utilisation``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from openpyxl.formatting.rule import FormulaRule

from ...verdict import ACTIVE_TOL, SHOWN
from .. import sections
from .book import (
    BOLD,
    FAIL_FILL,
    FAIL_FONT,
    GENERAL_FORMAT,
    PASS_FILL,
    PASS_FONT,
    WRAP,
    Sheet,
    fmt,
    unit_label,
)

if TYPE_CHECKING:
    from ...result import Result

#: Check units the sheet shows as people read them: every unit :data:`SHOWN` converts.
SHOWN_IN_CHECKS = tuple(SHOWN)
HEADERS = ["check", "value", "unit", "sense", "limit", "margin", "result", "binding (active)",
           "source"]
#: The widths: a declared table under the checks (quantity, unit, value) reads in A-C.
WIDTHS = {1: 32, 2: 12, 3: 12, 4: 6, 5: 12, 6: 9, 7: 7, 8: 8, 9: 42}


def build_checks(sheet: Sheet, res: Result) -> None:
    """The checks' table, the binding and failed lines and the optimiser's tables."""
    ws = sheet.ws
    labels = [len(c.name) for c in res.checks]
    sheet.set_widths({**WIDTHS, 1: min(38, max([WIDTHS[1] - 2, *labels]) + 2)})
    sheet.header(1, HEADERS)
    ws.freeze_panes = "B2"
    row = 2
    for c in res.checks:
        value, unit = sections.shown(c.value, c.unit, only=SHOWN_IN_CHECKS)
        limit, _ = sections.shown(c.limit, c.unit, only=SHOWN_IN_CHECKS)
        number = fmt(unit) if unit else GENERAL_FORMAT
        sheet.put(row, 1, c.name)
        sheet.put(row, 2, sections.cell(value), number)
        sheet.put(row, 3, unit_label(unit))
        sheet.put(row, 4, c.sense)
        sheet.put(row, 5, sections.cell(limit), number)
        sheet.put(row, 6, sections.cell(c.margin), "0.00%")
        sheet.put(row, 7, "PASS" if c.passed else "FAIL")
        sheet.put(row, 8, "yes" if c.active else "")
        sheet.put(row, 9, c.source).alignment = WRAP
        row += 1
    last = row - 1
    sheet.print_cols = len(HEADERS)
    # with the binding and failed lines under it, and three checks at least beside them
    sheet.keep_table(1, last + 4, rows=3 + 4, header=1)
    if res.checks:
        green = FormulaRule(formula=['$G2="PASS"'], fill=PASS_FILL, font=PASS_FONT)
        red = FormulaRule(formula=['$G2="FAIL"'], fill=FAIL_FILL, font=FAIL_FONT)
        for rng in (f"F2:G{last}", f"A2:A{last}"):
            ws.conditional_formatting.add(rng, green)
            ws.conditional_formatting.add(rng, red)
    row += 1
    active = [c.name for c in res.checks if c.active]
    sheet.put(row, 1, "binding (active) checks").font = BOLD
    sheet.put(row, 2, ", ".join(active) if active else "none "
              f"(a satisfied check is binding when its margin is below {ACTIVE_TOL:g})")
    row += 1
    failed = [c.name for c in res.checks if not c.passed]
    sheet.put(row, 1, "failed checks").font = BOLD
    sheet.put(row, 2, ", ".join(failed) if failed else "none")
    row += 1
    sheet.paragraph(row, "margin: the distance to the limit as a share of the limit (of the "
                         "check's scale where the limit is 0); the same in any unit.", 1, 9)


def build_optimisation(sheet: Sheet, res: Result) -> None:
    """The optimiser's record (``govopt design``) as declared tables: status, objective and
    bound, the search, the chosen design, the bound's design, a robust design's tolerance box
    and worst cases, the sensitivities (on a sheet of its own: a table that runs onto another
    page repeats its header there, and a sheet repeats one)."""
    sheet.set_widths(WIDTHS)
    sheet.print_cols = len(HEADERS)
    sheet.title(1, "Optimisation: the design search's record")
    row = 3
    for table in sections.optimisation(res):
        row = sheet.write_table(row, table)

