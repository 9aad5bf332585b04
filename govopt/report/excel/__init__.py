"""The workbook of one design: a record a person prints and reads, the answer first.

:func:`write_workbook` writes one ``.xlsx`` per :class:`~govopt.result.Result` (openpyxl's public
API; the sheets' conventions, :mod:`govopt.report.excel.book`):

* **Summary** - one printed page: what the design is, who wrote it (command, version, date),
  the verdict, the chosen design in drawing units, the checks to watch, what the spring's
  tolerances do to the speeds, the characteristic with its band and the governor drawn
  (:mod:`.summary`);
* **Design** - the design's inputs as yellow cells with defined names and the derived
  quantities as live formulas beside govopt's values (:mod:`.design`);
* **Checks** - every check with value, limit, margin, verdict and source; **Optimisation** -
  the optimiser's record, for a design (:mod:`.checks`);
* **Characteristic** - the equilibrium over the range, the friction band's speeds, the chart
  (:mod:`.characteristic`);
* **Spring** - where the governor has one: the spring as its maker reads it (:mod:`.spring`);
* **Dynamics** - k^2 and the declared dynamics tables (:mod:`.dynamics`);
* **Spec** - the inputs with what each means; **Method** - the type's own equations, sources
  and fidelity settings; **Model** - the model's internals (:mod:`.record`).

The printed record is the sheets of :data:`PRINTED` (Summary, Design, Checks, Method); the
others keep their page set up but print only when a reader sets their print range.

Every heading that cites a source reads the governor type's method
(:meth:`govopt.governors.base.Governor.method`); no sheet holds a type's method text. The writer
formats only: every number comes from the result or from govopt's own functions. The file is
written atomically (:func:`govopt.report.excel.book.save`).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from openpyxl import Workbook

from .book import (
    BODY_PT,
    Sheet,
    command_line,
    extent,
    finish,
    layout,
    new_workbook,
    paginate,
    print_titles,
    printed_font,
    save,
    tables,
)
from .characteristic import build_characteristic
from .checks import SHOWN_IN_CHECKS, build_checks, build_optimisation
from .design import (
    GOVOPT,
    NAME,
    NOTE,
    RELDIFF,
    SI,
    SI_UNIT,
    UNIT,
    VALUE,
    FormulaSheet,
    build_design,
    model_constants,
)
from .dynamics import build_dynamics
from .record import build_method, build_spec
from .spring import ENGINEERING, build_spring, engineering
from .summary import build_summary, drawing_data

if TYPE_CHECKING:
    from ...result import Result

__all__ = ["ENGINEERING", "GOVOPT", "NAME", "NOTE", "PRINTED", "RELDIFF", "SHEETS",
           "SHOWN_IN_CHECKS", "SI", "SI_UNIT", "UNIT", "VALUE", "build_workbook", "engineering",
           "extent", "layout",
           "paginate", "print_titles", "printed_font", "sheets", "tables", "write_workbook"]

#: The Summary's body text (pt): 8 pt printed at the least scale, so that its page holds the
#: answer whole.
SUMMARY_PT = 10.0
#: Every sheet a design's workbook can have, in order (``Spring`` only where the governor has
#: a spring: :func:`sheets`).
SHEETS = ("Summary", "Design", "Checks", "Optimisation", "Characteristic", "Spring",
          "Dynamics", "Spec", "Method", "Model")
#: The sheets a printed record holds, what a colleague reads and signs: the answer, the design
#: with its formulas, the checks, the method and its sources. The others are there on screen
#: and print only when asked (:attr:`~govopt.report.excel.book.Sheet.printed`).
PRINTED = ("Summary", "Design", "Checks", "Method")


def sheets(result: Result) -> tuple[str, ...]:
    """The sheets of ``result``'s workbook, in order: ``Optimisation`` only for a design
    (``govopt design``), ``Spring`` only where the governor has a spring."""
    return tuple(s for s in SHEETS
                 if (s != "Spring" or result.spec.governor.spring is not None)
                 and (s != "Optimisation" or result.optimisation))


def write_workbook(result: Result, path: str | os.PathLike, *, command: str | None = None
                   ) -> Path:
    """Write the workbook of ``result`` to ``path`` atomically and return the path.
    ``command``: the command that wrote it, for the Summary's record (default: govopt's command
    line where the process is the ``govopt`` command, else a note of the library call).

    The workbook is built in memory, saved to a temporary file in the same directory and
    renamed over ``path``; on any error the temporary file is removed and an existing ``path``
    is left untouched. An unwritable path raises :class:`~govopt.errors.GovoptError`.
    """
    path = Path(path)
    kind = "design" if result.optimisation else result.kind
    wb = build_workbook(result, command=command or command_line(
        f"{kind} of {result.spec.path}, written to {path} by govopt.report.excel."
        "write_workbook (Python)"))
    return save(wb, path)


def build_workbook(result: Result, *, command: str = "") -> Workbook:
    """The workbook of ``result`` in memory (see the module docstring for the sheets)."""
    from ... import __version__

    res = result
    wb = new_workbook()
    made = {name: Sheet(wb.create_sheet(name), one_page=name == "Summary",
                        body_pt=SUMMARY_PT if name == "Summary" else BODY_PT,
                        printed=name in PRINTED)
            for name in sheets(res)}
    model = FormulaSheet(wb, made["Model"])
    build_design(wb, made["Design"], model, res)
    if not model.titles:  # the type wrote its own sheet: the seam's constants as values
        model_constants(model, res, named=False)
    model.close()
    build_checks(made["Checks"], res)
    if "Optimisation" in made:
        build_optimisation(made["Optimisation"], res)
    build_characteristic(made["Characteristic"], res)
    if "Spring" in made:
        build_spring(made["Spring"], res)
    build_dynamics(made["Dynamics"], res)
    build_spec(made["Spec"], res)
    build_method(made["Method"], res)
    drawing = drawing_data(made["Model"], res, col=SI_UNIT + 2)
    build_summary(made["Summary"], res, command=command or "(not recorded)",
                  characteristic=made["Characteristic"],
                  drawing=None if drawing is None else (made["Model"], drawing))
    kind = "design" if res.optimisation else res.kind
    header = f"govopt {kind}: {res.spec.name}"
    for sheet in made.values():
        finish(sheet, header, f"govopt {__version__}")
    wb.active = wb.worksheets.index(made["Summary"].ws)
    for ws in wb.worksheets:
        ws.sheet_view.tabSelected = ws is made["Summary"].ws
    wb.properties.creator = f"govopt {__version__}"
    wb.properties.title = header
    return wb
