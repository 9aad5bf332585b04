"""A study's workbook (``govopt study export --out STUDY.xlsx``): a record a person prints.

Sheets, in order:

* **Summary**: what was swept and how, the points done and their statuses, the best feasible
  points in the spec's units, the Pareto front or the tolerance probabilities, who wrote it,
  then the plots (:func:`govopt.report.study_plots.study_figures`), each on a page of its own;
* **Table**: the points in the spec's units, each heading naming its unit, the columns a
  person asked for first (the point, the swept inputs, the status, the objective, the margins
  of the constraints that bind), then the other figures and checks, the message last; printed
  landscape at 9 pt, the heading row and the inputs repeated on every page, every column as
  wide as its longest value (nothing cut). A study of more than :data:`MAX_TABLE_ROWS` points
  prints its best feasible points;
* **Data**: every row and column as the database holds them (SI; inputs as written), for
  analysis;
* **Columns**: each column's unit, the unit the Table gives it in, and what it is.

Written with openpyxl's public API in write-only mode (a million-point Data sheet is streamed,
never held), atomically (:func:`govopt.report.files.atomic_write`).
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import numpy as np
import pandas as pd

from ..study.store import BATCH

#: characters of the columns repeated on every page of the Table at most (the point and
#: the inputs; the point alone beyond)
TITLE_WIDTH = 40
#: the page setup's paper size code of A4 (ECMA-376 Part 1, 18.3.1.63; openpyxl's
#: ``Worksheet.PAPERSIZE_A4``)
A4 = 9
#: rows of the printable Table at most (the Data sheet holds every row)
MAX_TABLE_ROWS = 2000
#: the Table's font size (pt): at least 8 when printed, as the sheet prints at 100 %
FONT_SIZE = 9
#: significant digits of a number in the Table (the Data sheet keeps every digit)
DIGITS = 5
#: the room for a plot on an A4 page in portrait, inches: each plot is scaled to fit a page
PAGE = (6.0, 10.0)


def _cell(sheet, value, *, bold=False, size=FONT_SIZE, wrap=False, fill=None, fmt=None):
    from openpyxl.cell import WriteOnlyCell
    from openpyxl.styles import Alignment, Font, PatternFill

    cell = WriteOnlyCell(sheet, value=value)
    cell.font = Font(size=size, bold=bold)
    if wrap:
        cell.alignment = Alignment(wrap_text=True, vertical="top")
    if fill:
        cell.fill = PatternFill("solid", fgColor=fill)
    if fmt:
        cell.number_format = fmt
    return cell


def _plain(v):
    """A value as a cell takes it: Python numbers, texts, None for NaN or NA."""
    if v is None or v is pd.NA:
        return None
    if isinstance(v, np.generic):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return None if math.isnan(v) else str(v)
    return v


def _rounded(v):
    v = _plain(v)
    if isinstance(v, float) and v != 0:
        return float(f"{v:.{DIGITS}g}")
    return v


def _width(values, heading: str, cap: int = 40) -> float:
    """A column's width (characters) for its longest shown value and heading word."""
    longest = max((len(str(v)) for v in values if v is not None), default=0)
    word = max((len(w) for w in heading.split()), default=0)
    return min(max(longest + 2, word + 2, 6), cap)


def _describe_sweep(s: dict) -> str:
    from ..study.quantities import number_text

    unit = f" {s['unit']}" if s.get("unit") else ""
    if s.get("start") is not None:
        span = f"{number_text(s['start'])} to {number_text(s['stop'])}{unit}"
        return f"{span}, {s['num']} values" if s.get("num") else f"{span}, sampled"
    values = [str(v) if s.get("text") else number_text(v) for v in s["values"]]
    shown = ", ".join(values[:12]) + (f", ... ({len(values)} values)" if len(values) > 12
                                      else "")
    return shown + ("" if s.get("text") else unit)


def _describe_tolerance(t: dict) -> str:
    band = f"±{t['half'] * 100:g} %" if t["relative"] else f"±{t['half']:g} {t['unit']}".strip()
    how = ("normal, the band is 3 standard deviations" if t["distribution"] == "normal"
           else "uniform within the band")
    return f"{band} ({how})"


def summary_rows(store) -> list[tuple[str, str]]:
    """The Summary's lines: ``(what, value)``."""
    from ..study.summary import check_columns, pareto_points, tolerance_summary, with_unit

    study = store.study()
    total = store.meta("total") or 0
    n = store.count()
    how = {"grid": "every combination (grid)", "zip": "the values taken in step (zip)",
           "lhs": f"Latin hypercube, {study.get('samples')} samples, seed {study.get('seed')}",
           "sobol": f"scrambled Sobol', {study.get('samples')} samples, seed "
                    f"{study.get('seed')}"}[study.get("combine", "grid")]
    rows = [("spec", str(study.get("spec_path"))),
            ("mode", "each point's design evaluated" if study.get("mode") == "evaluate"
             else "a design found for each point"),
            ("points", f"{n} of {total} done; {how}" if not study.get("tolerances") else
             f"{n} of {total} done; manufacturing tolerances sampled (Latin hypercube, seed "
             f"{study.get('seed')})")]
    for s in study.get("sweeps", []):
        rows.append((f"swept: {s['key']}", _describe_sweep(s)))
    for t in study.get("tolerances", []):
        rows.append((f"tolerance: {t['key']}", _describe_tolerance(t)))
    counts = store.conn.execute("SELECT status, COUNT(*) FROM points GROUP BY status ORDER BY "
                                "COUNT(*) DESC, MIN(point)").fetchall()
    rows.append(("status", ", ".join(f"{k} {v}" for k, v in counts) or "no point done yet"))
    info = store.columns().set_index("name")
    if "objective_value" in info.index:
        best = store.conn.execute(
            "SELECT point, objective, objective_value FROM points WHERE status IN ('pass', "
            "'optimal') AND objective_value IS NOT NULL ORDER BY objective_value, point "
            "LIMIT 1").fetchone()
        if best is not None:
            unit, factor = info.at["objective_value", "shown_unit"], info.at[
                "objective_value", "shown_factor"]
            rows.append(("best feasible point", f"point {best[0]}: {best[1].replace('_', ' ')} "
                                                f"{with_unit(best[2] / factor, unit)}"))
        else:
            rows.append(("best feasible point", "none: no point passed"))
    if study.get("pareto"):
        front = pareto_points(store)
        rows.append((f"Pareto front ({', '.join(study['pareto'])})",
                     f"{len(front)} point{'s' if len(front) != 1 else ''}: "
                     + ", ".join(str(int(i)) for i in front[:30])
                     + (", ..." if len(front) > 30 else "")))
    if study.get("tolerances"):
        checks = {k: c["passed"] for k, c in check_columns(store).items() if "passed" in c}
        s = tolerance_summary(store.batches(["status", *checks.values()]), checks)
        a = s["all_requirements"]
        rows.append(("all requirements hold", f"probability {a['probability']:.4f} (95 %: "
                                              f"{a['ci95'][0]:.4f}-{a['ci95'][1]:.4f})"))
        for name, c in s["checks"].items():
            if c["probability"] < 1.0:
                rows.append((f"  {name}", f"probability {c['probability']:.4f} (95 %: "
                                          f"{c['ci95'][0]:.4f}-{c['ci95'][1]:.4f})"))
    from ..study.store import FORMAT_VERSION

    versions = ", ".join(store.meta("govopt_versions") or [])
    rows += [("written by", f"govopt {versions}; database {store.path} (format "
                            f"{FORMAT_VERSION})"),
             ("sheets", "Table: the points in the spec's units; Data: every row and column "
                        "in SI (inputs as written); Columns: the units and what each column "
                        "is")]
    return rows


def table_order(store) -> list[str]:
    """The Table's columns, those a person asked for first: the point, the inputs, the
    status, the objective's value, the binding constraints' margins; then the figures, the
    checks and the message."""
    from ..study.summary import check_columns
    from .study_plots import constraints, least_margins

    info = store.columns()
    role = dict(zip(info["name"], info["role"], strict=True))
    checks = {k: c for k, c in check_columns(store).items() if "margin" in c}
    binding = constraints(least_margins(store.batches(
        ["status", *(c["margin"] for c in checks.values())]), checks))
    first = ["point", *store.names("input"), "status",
             *(["objective_value"] if "objective_value" in role else []),
             *(checks[c]["margin"] for c in binding)]
    rest = [n for n in info["name"] if n not in first and n not in ("message", "objective")]
    return [*first, *rest, "message"]


def _table_rows(store, order: list[str]) -> pd.DataFrame:
    """The Table's rows: every point, or the best feasible ones of a large study."""
    n = store.count()
    if n <= MAX_TABLE_ROWS:
        parts = list(store.batches(order))
        return pd.concat(parts, ignore_index=True) if parts else pd.DataFrame(columns=order)
    by = "objective_value" if "objective_value" in order else "point"
    return store.frame(store.conn.execute(
        f"SELECT {', '.join(chr(34) + c + chr(34) for c in order)} FROM points ORDER BY "
        f"status NOT IN ('pass', 'optimal'), {by} IS NULL, {by}, point LIMIT {MAX_TABLE_ROWS}"))


def _lines(text: str, width: float) -> int:
    """Lines a wrapped text takes in a column ``width`` characters wide (words kept whole)."""
    import textwrap

    return max(1, len(textwrap.wrap(str(text), max(1, int(width) - 1))))


#: the height of one line of :data:`FONT_SIZE` text, points
LINE = FONT_SIZE * 1.4
#: the Summary's columns (characters of the default font): 72 fit an A4 page at 100 % in
#: Excel (Calibri) and LibreOffice (which may draw Calibri wider, as DejaVu Sans)
SUMMARY_WIDTHS = (24, 48)


def _summary(book, store, figures) -> None:
    from openpyxl.drawing.image import Image
    from openpyxl.worksheet.pagebreak import Break

    sheet = book.create_sheet("Summary")
    sheet.column_dimensions["A"].width, sheet.column_dimensions["B"].width = SUMMARY_WIDTHS
    sheet.page_setup.orientation = "portrait"
    sheet.page_setup.paperSize = A4
    sheet.page_setup.scale = 100
    _margins(sheet)
    name = store.study().get("name", "?")
    sheet.append([_cell(sheet, f"Trade study {name!r}", bold=True, size=14)])
    sheet.append([])
    row = 2
    for what, value in summary_rows(store):
        row += 1
        lines = max(_lines(what, SUMMARY_WIDTHS[0]), _lines(value, SUMMARY_WIDTHS[1]))
        sheet.row_dimensions[row].height = lines * LINE
        sheet.append([_cell(sheet, what, bold=not what.startswith(" "), wrap=True),
                      _cell(sheet, value, wrap=True)])
    dpi = 96.0  # pixels an inch in the drawing's anchor (openpyxl: EMU = px * 9525)
    for title, fig in figures:
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=150)
        buf.seek(0)
        image = Image(buf)
        w, h = fig.get_size_inches()
        scale = min(1.0, PAGE[0] / w, (PAGE[1] - 0.5) / h)  # one page each, nothing cut
        image.width, image.height = w * scale * dpi, h * scale * dpi
        sheet.row_breaks.append(Break(id=row))  # the plot starts a page
        sheet.append([_cell(sheet, f"plot: {title}", bold=True)])
        row += 1
        sheet.add_image(image, f"A{row + 1}")
        taken = math.ceil(image.height * 72.0 / dpi / 15.0) + 1  # rows of 15 pt
        for _ in range(taken):
            sheet.append([])
        row += taken


def _margins(sheet) -> None:
    """Half-inch margins (the footer within them)."""
    sheet.page_margins.left = sheet.page_margins.right = 0.5
    sheet.page_margins.top = sheet.page_margins.bottom = 0.6
    sheet.page_margins.footer = 0.3


def _table(book, store, order: list[str]) -> None:
    from openpyxl.utils import get_column_letter

    from ..study.summary import heading

    info = store.columns().set_index("name")
    frame = _table_rows(store, order)
    sheet = book.create_sheet("Table")
    objective = store.conn.execute("SELECT objective FROM points WHERE objective IS NOT NULL "
                                   "LIMIT 1").fetchone() if "objective" in info.index else None
    headings, columns = [], []
    for c in order:
        unit = info.at[c, "shown_unit"] if c in info.index else ""
        label = c.replace("_", " ")
        if c == "objective_value" and objective is not None:
            label = f"{objective[0].replace('_', ' ')} (objective)"
        headings.append(heading(label, unit))
        v = frame[c] if c in frame else pd.Series([None] * len(frame))
        if c in info.index and info.at[c, "type"] == "REAL":
            v = v.to_numpy(dtype=float) / float(info.at[c, "shown_factor"])
        columns.append([_rounded(x) for x in v])
    widths = []
    for j, (h, values) in enumerate(zip(headings, columns, strict=True), 1):
        cap = 60 if order[j - 1] == "message" else 24
        widths.append(_width(values, h, cap))
        sheet.column_dimensions[get_column_letter(j)].width = widths[-1]
    inputs = 1 + len(store.names("input"))
    repeated = inputs if sum(widths[:inputs]) <= TITLE_WIDTH else 1  # the point, the inputs
    sheet.page_setup.orientation = "landscape"
    sheet.page_setup.paperSize = A4
    sheet.page_setup.scale = 100
    _margins(sheet)
    sheet.print_title_rows = "1:1"
    sheet.print_title_cols = f"A:{get_column_letter(repeated)}"
    sheet.freeze_panes = f"{get_column_letter(inputs + 1)}2"
    sheet.row_dimensions[1].height = max(_lines(h, w) for h, w in zip(headings, widths,
                                                                       strict=True)) * LINE
    sheet.print_options.gridLines = True
    sheet.oddFooter.center.text = "&A, page &P of &N"
    sheet.append([_cell(sheet, h, bold=True, wrap=True, fill="DDDDDD") for h in headings])
    wrap_at = order.index("message")
    for i in range(len(frame)):
        sheet.row_dimensions[i + 2].height = _lines(columns[wrap_at][i] or "",
                                                    widths[wrap_at]) * LINE
        sheet.append([_cell(sheet, columns[j][i], wrap=j == wrap_at, fmt="General")
                      for j in range(len(order))])
    if len(frame) < store.count():
        sheet.append([_cell(sheet, f"the {len(frame)} best feasible points of {store.count()}; "
                                   "every point is on the Data sheet", bold=True)])


def _data(book, store, batch: int) -> None:
    from openpyxl.utils import get_column_letter

    names = store.names()
    sheet = book.create_sheet("Data")
    for j, name in enumerate(names, 1):
        sheet.column_dimensions[get_column_letter(j)].width = max(10, min(len(name) + 2, 40))
    sheet.freeze_panes = "B2"
    sheet.page_setup.orientation = "landscape"
    sheet.print_title_rows = "1:1"
    sheet.append(names)
    for part in store.batches(names, batch=batch):
        for row in part.astype(object).itertuples(index=False, name=None):
            sheet.append([_plain(v) for v in row])


def _columns(book, store) -> None:
    from openpyxl.utils import get_column_letter

    info = store.columns()
    sheet = book.create_sheet("Columns")
    heads = ["name", "type", "unit (Data)", "role", "label", "about", "unit (Table)",
             "Table value = Data value / factor"]
    rows = [[_plain(v) for v in r] for r in info.itertuples(index=False, name=None)]
    widths = [_width([r[j] for r in rows], h, 30 if j == 5 else 24)
              for j, h in enumerate(heads)]
    for j, w in enumerate(widths, 1):
        sheet.column_dimensions[get_column_letter(j)].width = w
    sheet.page_setup.orientation = "landscape"
    sheet.page_setup.paperSize = A4
    sheet.page_setup.scale = 100
    _margins(sheet)
    sheet.print_title_rows = "1:1"
    sheet.print_options.gridLines = True
    for i, r in enumerate([heads, *rows], 1):
        sheet.row_dimensions[i].height = max(_lines(v, w) for v, w in zip(r, widths,
                                                                          strict=True)) * LINE
        sheet.append([_cell(sheet, v, wrap=True, bold=i == 1, fill="DDDDDD" if i == 1 else None)
                      for v in r])


def write_workbook(store, path: str | Path, *, overwrite: bool | None = None,
                   batch: int = BATCH, plots: bool = True) -> Path:
    """Write the study's workbook (see the module's docstring) to ``path``, atomically;
    ``plots``: with the plots on the Summary sheet."""
    from openpyxl import Workbook

    from ..errors import GovoptError
    from .files import atomic_write

    path = Path(path)
    if path.suffix.lower() != ".xlsx":
        raise GovoptError(f"{path}: expected an .xlsx file")
    figures = []
    if plots and store.count():
        from .study_plots import study_figures

        figures = study_figures(store)
    order = table_order(store)

    def write(tmp: Path) -> None:
        book = Workbook(write_only=True)
        _summary(book, store, figures)
        _table(book, store, order)
        _data(book, store, batch)
        _columns(book, store)
        book.save(tmp)

    return atomic_write(path, write, overwrite=overwrite, what="study workbook")
