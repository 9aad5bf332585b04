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


METHOD_WIDTHS = {1: 22, 2: 22, 3: 44, 4: 32}


def build_method(sheet: Sheet, res: Result) -> None:
    """The type's method (its declaration, :meth:`Governor.method`): a small table a topic of
    its equations with their sources, the fidelity settings that apply with their values, the
    spring's free length in words, how the workbook is made, and last the bibliography (the
    method's and the checks' sources: the one table that may run onto another page)."""
    from ...governors.base import TOPICS

    method = res.method
    sheet.set_widths(METHOD_WIDTHS)
    sheet.print_cols = 4
    sheet.title(1, f"Method: {method.title}")
    sheet.put(2, 1, "What govopt computes for this governor, and from which source: the "
                    "type's own declaration, beside its physics.").font = ITALIC
    row = 4
    for topic, heading in TOPICS.items():
        equations = method.of(topic)
        if not equations:
            continue
        sheet.title(row, heading, font=BOLD)
        sheet.header(row + 1, ["what", "", "equation", "source (fidelity settings)"])
        first, row = row, row + 2
        for e in equations:
            sheet.paragraph(row, e.what, 1, 2, font=None)
            sheet.put(row, 3, e.formula).alignment = WRAP
            settings = f" ({', '.join(e.settings)})" if e.settings else ""
            sheet.put(row, 4, e.cite + settings).alignment = WRAP
            row += 1
        sheet.keep_table(first, row - 1)
        row += 1
    sheet.title(row, "Fidelity settings that apply to this governor", font=BOLD)
    sheet.header(row + 1, ["setting", "what it chooses", "value in this spec", ""])
    first, row = row, row + 2
    for s in method.settings:
        sheet.put(row, 1, s.key)
        sheet.put(row, 2, s.meaning).alignment = WRAP
        sheet.put(row, 3, str(s.value).lower() if isinstance(s.value, bool) else s.value,
                  sig_format(s.value))
        row += 1
    sheet.keep_table(first, row - 1)
    row += 1
    if method.free_length:
        sheet.title(row, "The spring's free length in this model", font=BOLD)
        sheet.paragraph(row + 1, method.free_length, 1, 4, font=None)
        sheet.keep(row, row + 1)
        row += 3
    sheet.title(row, "This workbook", font=BOLD)
    first, row = row, row + 1
    for label, text in _WORKBOOK_NOTES:
        sheet.put(row, 1, label).font = ITALIC
        sheet.paragraph(row, text, 2, 4, font=None)
        row += 1
    sheet.keep_table(first, row - 1, header=first)
    row += 1
    keys = method.sources(tuple(c.source for c in res.checks))
    sheet.title(row, "Sources (of the method and of the checks)", font=BOLD)
    sheet.header(row + 1, ["key", "citation", "", "used for"])
    first, row = row, row + 2
    for key in keys:
        ref = reference(key)
        sheet.put(row, 1, key)
        sheet.paragraph(row, ref.citation, 2, 3, font=None)
        sheet.put(row, 4, ref.use).alignment = WRAP
        row += 1
    sheet.keep_table(first, row - 1)


#: How the workbook is made, for its reader (on the Method sheet).
_WORKBOOK_NOTES = (
    ("sheets", "Summary (the answer: verdict, design, the checks to watch, the characteristic, "
               "the governor drawn), Design (live formulas), Checks, Optimisation (for a "
               "design), Characteristic, Spring "
               "(where the governor has one), Dynamics, Spec (the inputs), Method (this sheet), "
               "Model (the model's internals). docs/how-to/read-the-workbook.md tells more."),
    ("units", "Engineering units where a person reads (mm, N/mm, MPa, rpm, deg), each column or "
              "row with its unit; the Design sheet's formulas work in SI (m, kg, s, N, Pa, "
              "rad) on its defined names, the SI cells right of its printed page."),
    ("live", "The Design sheet's blue cells are formulas on its yellow inputs: edit an input "
             "and they follow; every other number is govopt's value when the workbook was "
             "written. A reader that does not recalculate (pandas, a previewer) finds govopt's "
             "value of each formula in the Design sheet's 'govopt value' column."),
    ("words", "yes/no for booleans; 'never' for a time that never comes (a response that never "
              "reaches or never settles at its new equilibrium); 'not decided' for a settling "
              "time beyond what the solver's time grid resolves; 'unbounded' for an unstable "
              "excursion; a blank cell is not defined."),
    ("printing", "A4 at a fixed scale (text never under 8 pt), landscape where wide; page "
                 "breaks keep a table with its title and header and a chart with its rows; a "
                 "table that runs onto another page repeats its title and header; chart data "
                 "beside a sheet's printed columns are not printed; every page names the "
                 "design at its top and gives 'page x of y' at its foot."),
)
