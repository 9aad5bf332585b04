"""The record sheets: Spec (the input as a table of quantities with what each means, as written
and in the units people read), Method (the governor type's own equations and sources, the
fidelity settings that apply, the bibliography of the method and the checks, how to read the
workbook) and Model (the model's internals, labelled for a reader: the linkage's constants the
Design sheet's formulas read, and the governor drawing's chart data)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...references import reference
from ..sections import shown
from .book import BOLD, ITALIC, WRAP, Sheet, sig_format, unit_label

if TYPE_CHECKING:
    from ...result import Result

SPEC_HEADERS = ["quantity (spec key)", "what it means", "as written", "value", "unit"]
SPEC_WIDTHS = {1: 28, 2: 44, 3: 22, 4: 13, 5: 9}


def build_spec(sheet: Sheet, res: Result) -> None:
    """Every input of the governor's spec (:func:`inputs_table`)."""
    spec = res.spec
    inputs_table(sheet, f"Spec: the inputs of {spec.name}", spec.entries, str(spec.path))


def inputs_table(sheet: Sheet, title: str, entries, path: str | None, show=shown) -> None:
    """Every input: its key, its meaning (the key's declaration, where the reader has it), the
    text as written (always text: a spec string is never a formula) and the value read, in the
    units people read (``show``: SI value and unit to the value and unit shown); then the spec
    file (``path``; None: the options alone)."""
    sheet.set_widths(SPEC_WIDTHS)
    sheet.title(1, title)
    sheet.header(2, SPEC_HEADERS)
    sheet.ws.freeze_panes = "A3"
    row = 3
    for e in entries:
        sheet.put(row, 1, e.key)
        sheet.put(row, 2, getattr(e, "meaning", "") or "").alignment = WRAP
        sheet.put(row, 3, e.written).alignment = WRAP
        value, unit = show(e.si, e.unit)  # as read, in the units people read
        if value != e.written:  # a word as read is the word as written
            sheet.put(row, 4, value, sig_format(value) or "General")
        sheet.put(row, 5, unit_label(unit) if e.unit else "")
        row += 1
    sheet.keep_table(1, row - 1)
    sheet.put(row + 1, 1, "spec file").font = BOLD
    sheet.paragraph(row + 1, path or "none (the command's options alone)", 2, 5, font=None)
    sheet.print_cols = len(SPEC_HEADERS)


#: The Method sheet's columns: as wide as a landscape page holds at the least scale, so that
#: its text wraps to few lines.
METHOD_WIDTHS = {1: 26, 2: 28, 3: 50, 4: 42}


def build_method(sheet: Sheet, res: Result) -> None:
    """The type's method (its declaration, :meth:`Governor.method`): one table of its
    equations with their sources, a section a topic, the fidelity settings that apply with
    their values, the spring's free length in words, the bibliography (the method's and the
    checks' sources, each with what this record uses it for: :meth:`Method.uses`), and last how
    the workbook is made. Printed in the record, so written to fill its pages: a table may run
    onto another page (its header repeated), no blank row between a table's sections."""
    from ...governors.base import TOPICS

    method = res.method
    sheet.set_widths(METHOD_WIDTHS)
    sheet.print_cols = 4
    sheet.title(1, f"Method: {method.title}")
    sheet.put(2, 1, "What govopt computes for this governor, and from which source: the "
                    "type's own declaration, beside its physics.").font = ITALIC
    sheet.header(3, ["what", "", "equation", "source (fidelity settings)"])
    row = 4
    for topic, heading in TOPICS.items():
        equations = method.of(topic)
        if not equations:
            continue
        sheet.title(row, heading, font=BOLD)
        sheet.keep(row, row + 1)  # a topic's heading never alone at a page's foot
        row += 1
        for e in equations:
            sheet.paragraph(row, e.what, 1, 2, font=None)
            sheet.put(row, 3, e.formula).alignment = WRAP
            settings = f" ({', '.join(e.settings)})" if e.settings else ""
            sheet.put(row, 4, e.cite + settings).alignment = WRAP
            row += 1
    # the equations: one table, the sheet's title and its header repeated where it runs on
    sheet.keep_table(1, row - 1, header=3, whole=False)
    row += 1
    sheet.title(row, "Fidelity settings that apply to this governor", font=BOLD)
    sheet.header(row + 1, ["setting", "what it chooses", "", "value in this spec"])
    first, row = row, row + 2
    for s in method.settings:
        sheet.put(row, 1, s.key)
        sheet.paragraph(row, s.meaning, 2, 3, font=None)
        sheet.put(row, 4, str(s.value).lower() if isinstance(s.value, bool) else s.value,
                  sig_format(s.value))
        row += 1
    sheet.keep_table(first, row - 1)
    row += 1
    if method.free_length:
        sheet.title(row, "The spring's free length in this model", font=BOLD)
        sheet.paragraph(row + 1, method.free_length, 1, 4, font=None)
        sheet.keep(row, row + 1)
        row += 3
    uses = res.method.uses(tuple((c.name, c.source) for c in res.checks))
    sheet.title(row, "Sources (of the method and of the checks)", font=BOLD)
    sheet.header(row + 1, ["key", "citation", "", "used in this record for"])
    first, row = row, row + 2
    for key, use in uses.items():
        sheet.put(row, 1, key)
        sheet.paragraph(row, reference(key).citation, 2, 3, font=None)
        sheet.put(row, 4, use).alignment = WRAP
        row += 1
    sheet.keep_table(first, row - 1)
    row += 1
    sheet.title(row, "This workbook", font=BOLD)
    first, row = row, row + 1
    for label, text in _WORKBOOK_NOTES:
        sheet.put(row, 1, label).font = ITALIC
        sheet.paragraph(row, text, 2, 4, font=None)
        row += 1
    sheet.keep_table(first, row - 1, header=first)


#: How the workbook is made, for its reader (on the Method sheet).
_WORKBOOK_NOTES = (
    ("units", "Engineering units where a person reads (mm, N/mm, MPa, rpm, deg); the Design "
              "sheet's formulas work in SI on its defined names, right of its printed page."),
    ("live", "The Design sheet's blue cells are formulas on its yellow inputs; every other "
             "number is govopt's value when the workbook was written (beside each formula, "
             "in 'govopt value', for a reader that does not recalculate)."),
    ("words", "yes/no for booleans; 'never' for a time that never comes; 'not decided' for a "
              "settling time beyond the solver's time grid; 'unbounded' for an unstable "
              "excursion; a blank cell is not defined."),
    ("printing", "The record is Summary, Design, Checks and Method. The other sheets have an "
                 "empty print range: to print one, set its range (LibreOffice: Format > Print "
                 "Ranges > Edit, entire sheet; Excel: Page Layout > Print Area > Clear). Text "
                 "never under 8 pt; a table that runs onto another page repeats its header."),
)
