"""The conventions every govopt workbook follows, in one place: cells, fonts, tables, charts and
the printed page. A design's workbook (:mod:`govopt.report.excel`), ``govopt spring``'s and a
study's export build their sheets with these helpers (openpyxl's public API only).

A :class:`Sheet` wraps an openpyxl worksheet and remembers what the printed page needs (the
cells written, the charts and their extents, the blocks to keep on one page, the tables whose
header repeats); :func:`finish` then aligns, sizes and prints the sheet:

* **text**: the workbook's body font is 11 pt (the default), headings 13 pt, nothing smaller;
  long text wraps in its column (its row made tall enough) or across merged columns
  (:meth:`Sheet.paragraph`), so nothing is cut by a cell's edge;
* **numbers**: each with a display format for its unit (:data:`FORMATS`), the stored value
  keeping every digit; a word where a number is not finite;
* **printing**: A4, portrait where the printed columns fit, else landscape, at a fixed scale
  of at least :func:`least_scale` (so no text prints under 8 pt: :func:`printed_font`), the
  columns chosen so that the page's width holds them; page breaks that keep a table with its
  title and header and its last rows (:func:`paginate`); a table that runs onto another page
  repeats its title and header (:func:`print_titles`); a header naming the document on every
  page and the footer ``<sheet>, page x of y``.

A workbook is saved through :func:`save` (:func:`govopt.report.files.atomic_write`: a
temporary file renamed into place, nothing half-written).
"""

from __future__ import annotations

import math
import re
import weakref
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from openpyxl import Workbook
from openpyxl.cell.cell import ILLEGAL_CHARACTERS_RE
from openpyxl.chart import Reference, ScatterChart, Series
from openpyxl.chart.text import RichText, Text
from openpyxl.chart.title import Title
from openpyxl.drawing.text import (
    CharacterProperties,
    Paragraph,
    ParagraphProperties,
    RegularTextRun,
)
from openpyxl.styles import Alignment, Font, PatternFill
from openpyxl.utils import column_index_from_string, get_column_letter
from openpyxl.worksheet.page import PageMargins
from openpyxl.worksheet.pagebreak import Break
from openpyxl.worksheet.worksheet import Worksheet

from ...verdict import SHOWN

__all__ = ["BOLD", "FORMATS", "HEADER_FILL", "INPUT_FILL", "ITALIC", "MIN_SCALE", "TITLE",
           "PrintedTable", "Sheet", "add_series", "extent", "finish", "fmt", "layout",
           "paginate", "print_titles", "printed_font", "save", "scatter", "sig_format",
           "tables", "unit_label"]

#: The body text's size (pt; openpyxl's and Excel's default), the headings', and the smallest
#: scale a sheet with a chart prints at: charts' text is 10 pt, so 80 % prints it at 8 pt.
BODY_PT, TITLE_PT, MIN_SCALE = 11.0, 13.0, 80
#: The smallest printed text (pt): a sheet without charts prints at the least scale that keeps
#: its smallest cell font at this size (:func:`least_scale`: 73 % for 11 pt).
PRINTED_PT = 8.0
#: The body font (openpyxl's default, named on every font: a cell's font without a name falls
#: back to the renderer's serif).
FONT = "Calibri"
BOLD = Font(name=FONT, size=BODY_PT, bold=True)
TITLE = Font(name=FONT, bold=True, size=TITLE_PT)
ITALIC = Font(name=FONT, size=BODY_PT, italic=True)
HEADER_FILL = PatternFill("solid", fgColor="D9D9D9")
INPUT_FILL = PatternFill("solid", fgColor="FFF2CC")
FORMULA_FILL = PatternFill("solid", fgColor="DDEBF7")
PASS_FILL = PatternFill("solid", fgColor="C6EFCE", bgColor="C6EFCE")
FAIL_FILL = PatternFill("solid", fgColor="FFC7CE", bgColor="FFC7CE")
PASS_FONT = Font(name=FONT, size=BODY_PT, color="006100")
FAIL_FONT = Font(name=FONT, size=BODY_PT, color="9C0006")
WRAP = Alignment(wrap_text=True, vertical="top", horizontal="left")
HEADER_ALIGN = Alignment(wrap_text=True, vertical="center")
RIGHT = Alignment(horizontal="right")

#: Display formats by unit (the stored values keep full precision).
FORMATS = {
    "m": "0.000000", "N": "#,##0.000", "Pa": "#,##0", "N/m": "#,##0.00", "kg": "0.000000",
    "kg*m^2": "0.000000", "rad": "0.000000", "rad/s": "0.000000", "rpm": "0.0000",
    "N*m": "0.000000", "Hz": "0.000", "": "0.000000", "kg/m^3": "#,##0.00",
    "m/s^2": "0.00000", "N*m*s/rad": "0.000000", "deg": "0.0000", "rad^2/s^2": "0.000",
    "s": "0.0000", "N*m/rad": "#,##0.000", "MPa": "#,##0.00", "mm": "0.000",
    "N/mm": "#,##0.000", "1/s^2": "0.000", "N*s/m": "0.0000",
}
GENERAL_FORMAT = "0.000000"
#: Characters that make a spreadsheet treat typed text as something else (formula, number...).
_FORMULA_LEAD = ("=", "+", "-", "@")
#: Distinct series colours (blue, red, green, orange, purple, grey): one per curve of a chart.
COLOURS = ("1F77B4", "D62728", "2CA02C", "FF7F0E", "9467BD", "7F7F7F")


def scalar(value: Any) -> Any:
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
        return scalar(value.item())
    return str(value)


def xml_safe(text: str) -> str:
    """``text`` with the control characters an xlsx (XML 1.0) cannot hold written as ``\\xNN``
    (a spec's name may contain them)."""
    return ILLEGAL_CHARACTERS_RE.sub(lambda m: f"\\x{ord(m[0]):02x}", text)


def unit_label(unit: str) -> str:
    """A unit as a person writes it (``N m`` for ``N*m``); ``-`` for none."""
    return unit.replace("*", " ") if unit else "-"


def shown_unit(unit: str) -> str:
    """The engineering unit an SI unit is shown in (:data:`govopt.verdict.SHOWN`)."""
    return SHOWN.get(unit, (unit, 1.0))[0]


def fmt(unit: str) -> str:
    """The display format of a number in ``unit``."""
    return FORMATS.get(unit, GENERAL_FORMAT)


def sig_format(value: Any) -> str | None:
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


# --------------------------------------------------------------------------------------------
# a sheet and what its printed page needs


#: Each worksheet's :class:`Sheet` (what was written on it, for printing and for the tests).
_LAYOUTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


@dataclass(frozen=True)
class PrintedTable:
    """A table of a sheet as printed: its title row, its column-header row and its last row.
    ``header < title`` for a section of a sheet-wide table whose header heads the sheet."""

    title: int
    header: int
    last: int
    #: a section's: the first row repeated above it (the shared header's title, or row 1)
    top: int = 1

    @property
    def repeat(self) -> tuple[int, int]:
        """The rows printed above the table's rows on a page it continues on: its title and
        header, or (a section's) the rows from ``top`` down to the shared header."""
        return (self.title, self.header) if self.header >= self.title else (self.top,
                                                                            self.header)

    def spans(self, breaks: Iterable[int]) -> bool:
        """Whether a page break (after row ``b``) falls between its header and its last row (a
        section's: between the shared header above it and its last row)."""
        first = self.header if self.header < self.title else max(self.title, self.header)
        return any(first <= b < self.last for b in breaks)


@dataclass
class Sheet:
    """A worksheet being written and what its printed page needs: the cells written, the
    charts with their size (cm), the blocks kept on one page, the tables registered for
    repeated headers, the last printed column (None: every column written) and the scale
    it prints at (set by :func:`finish`)."""

    ws: Worksheet
    cells: dict = field(default_factory=dict)
    charts: list = field(default_factory=list)
    keeps: list = field(default_factory=list)
    tables: list = field(default_factory=list)
    print_cols: int | None = None
    scale: int = 100
    #: a sheet laid out as one page (the Summary): no page breaks of its own, printed at the
    #: least scale (:data:`MIN_SCALE`), so that as much as can fits
    one_page: bool = False
    #: the body text's size on this sheet (pt): the Summary's 10 pt prints at 8 pt at
    #: :data:`MIN_SCALE`; its fonts are scaled to it when the sheet is finished
    body_pt: float = BODY_PT
    #: whether the sheet is in the printed record; one that is not keeps its page set up but
    #: an empty print range (LibreOffice and Excel print none of it), until a reader sets its
    #: range to :attr:`area` and asks for it
    printed: bool = True
    #: the range the sheet prints when asked (``A1:H70``; set by :func:`finish`)
    area: str = ""

    def __post_init__(self):
        _LAYOUTS[self.ws] = self

    # -- cells --------------------------------------------------------------------------------

    def put(self, row: int, col: int, value, number_format: str | None = None):
        """Write ``value`` (:func:`scalar`); text is always stored as text, never as a
        formula, and control characters an xlsx cannot hold are written visibly as
        ``\\xNN``."""
        cell = self.ws.cell(row, col)
        value = scalar(value)
        if isinstance(value, str):
            value = xml_safe(value)
        cell.value = value
        if isinstance(value, str):
            cell.data_type = "s"
            if value.startswith(_FORMULA_LEAD):
                cell.quotePrefix = True  # so re-typing in Excel/Calc keeps it text too
        elif number_format and isinstance(value, int | float) and not isinstance(value, bool):
            cell.number_format = number_format
        self.cells[(row, col)] = cell
        return cell

    def formula(self, row: int, col: int, formula: str, number_format: str | None = None):
        """A formula cell (the spreadsheet computes it on opening)."""
        cell = self.ws.cell(row, col)
        cell.value = formula if formula.startswith("=") else "=" + formula
        cell.data_type = "f"
        if number_format:
            cell.number_format = number_format
        self.cells[(row, col)] = cell
        return cell

    def header(self, row: int, headers: Iterable[str], col: int = 1) -> None:
        """A table's column headers: bold on grey, wrapped."""
        for j, h in enumerate(headers):
            c = self.put(row, col + j, h)
            c.font, c.fill, c.alignment = BOLD, HEADER_FILL, HEADER_ALIGN

    def title(self, row: int, text: str, col: int = 1, font: Font = TITLE):
        """A title or a section's heading."""
        c = self.put(row, col, text)
        c.font = font
        return c

    def paragraph(self, row: int, text: str, first: int = 1, last: int = 4,
                  font: Font | None = ITALIC) -> None:
        """``text`` across columns ``first`` .. ``last`` (merged), wrapped, its row as tall as
        its lines need."""
        c = self.put(row, first, text)
        if font is not None:
            c.font = font
        c.alignment = WRAP
        if last > first:
            self.ws.merge_cells(start_row=row, start_column=first, end_row=row, end_column=last)
        width = sum(self.width(j) for j in range(first, last + 1))
        self.ws.row_dimensions[row].height = self.line_pt * _lines(text, self.chars(width))

    @property
    def line_pt(self) -> float:
        """A line of body text's height (pt): :data:`ROW_PT` at 11 pt."""
        return ROW_PT * self.body_pt / BODY_PT

    def chars(self, width: float) -> float:
        """``width`` (of a column, in the body font's width units) in 11 pt characters: a
        smaller body font fits more."""
        return width * BODY_PT / self.body_pt

    def width(self, col: int) -> float:
        """Column ``col``'s width (characters; the default where none is set)."""
        return self.ws.column_dimensions[get_column_letter(col)].width or 8.43

    def widths(self, fixed: Mapping[int, float] | None = None, low=8.0, high=60.0) -> None:
        """Column widths from the text in each column (numbers count as 14), ``fixed`` where
        given."""
        width: dict[int, float] = {}
        for c in self.cells.values():
            if c.value is None:
                continue
            n = 14 if c.data_type in ("n", "f") else len(str(c.value)) + 2
            width[c.column] = max(width.get(c.column, low), min(n, high))
        for col, w in {**width, **(fixed or {})}.items():
            self.ws.column_dimensions[get_column_letter(col)].width = w

    def set_widths(self, widths: Mapping[int, float]) -> None:
        """Column widths (characters) as given."""
        for col, w in widths.items():
            self.ws.column_dimensions[get_column_letter(col)].width = w

    # -- charts and printing ------------------------------------------------------------------

    def chart(self, chart: ScatterChart, anchor: str) -> tuple[int, int]:
        """Place ``chart`` at ``anchor``; returns the last column and row it covers."""
        self.ws.add_chart(chart, anchor)
        self.charts.append((chart, anchor))
        return extent(self, anchor, chart.width, chart.height)

    def keep(self, first: int, last: int) -> None:
        """Rows ``first`` .. ``last`` print on one page where they fit on one (a table's title
        with its header and first rows, a table's last rows with the chart under it)."""
        self.keeps.append((first, last))

    def keep_table(self, title: int, last: int, rows: int = 3, header: int | None = None,
                   top: int = 1, whole: bool = True) -> None:
        """A table from its title row to ``last``: whole on a page where it fits on one (with
        ``whole``; without, a long table fills the page it starts on); else its title and
        header never end a page and its last ``rows`` rows never start one alone.
        ``header``: its column-header row (default the row under the title; a shared header
        row above it for a section of a longer table, whose rows from ``top`` repeat above the
        section where it continues; the title itself for a section with none)."""
        header = title + 1 if header is None else header
        self.tables.append(PrintedTable(title, header, last, top))
        if whole or last - title <= 2 * rows + 2:
            self.keep(title, last)
        if last - title > 2 * rows + 2:
            self.keep(title, max(title, header) + 1 + rows)
            self.keep(last - rows, last)

    def write_rows(self, row: int, table, col: int = 1) -> tuple[int, int]:
        """The header and rows of a declared table (:class:`govopt.report.sections.Table`) at
        ``(row, col)``; returns (header row, last row). Numbers stay numbers (5 significant
        digits shown), words are text (a long one wraps)."""
        self.header(row, table.headers, col)
        for i, values in enumerate(table.rows, start=1):
            for j, v in enumerate(values):
                c = self.put(row + i, col + j, v, sig_format(v))
                if isinstance(v, str) and j >= (2 if table.properties else 1):
                    c.alignment = RIGHT if len(v) < self.width(col + j) else WRAP
                elif isinstance(v, str) and len(v) >= self.width(col + j):
                    c.alignment = WRAP
        return row, row + len(table.rows)

    def write_table(self, row: int, table, col: int = 1) -> int:
        """A declared table with its title and notes (each note a wrapped paragraph across the
        table's columns); returns the next free row."""
        self.title(row, table.title, col=col, font=BOLD)
        _, last = self.write_rows(row + 1, table, col)
        for k, note in enumerate(table.notes, start=1):
            self.paragraph(last + k, note, col, col + max(len(table.headers) - 1, 3))
        self.keep_table(row, last + len(table.notes))
        return last + len(table.notes) + 2


def layout(ws: Worksheet) -> Sheet:
    """The :class:`Sheet` a worksheet was written through."""
    return _LAYOUTS[ws]


def tables(ws: Worksheet) -> list[PrintedTable]:
    """The tables of a sheet, as registered for printing."""
    return list(_LAYOUTS[ws].tables) if ws in _LAYOUTS else []


def _lines(text: str, width: float) -> int:
    """The lines ``text`` wraps to in ``width`` characters of column: a width unit holds about
    1.15 characters of text (measured on LibreOffice's PDF with its fallback font, DejaVu Sans;
    Excel's Calibri holds more, so the estimate errs tall rather than cut)."""
    per_line = max(1.0, 1.15 * width - 1.0)
    return sum(max(1, math.ceil(len(part) / per_line)) for part in str(text).split("\n"))


def chart_title(text: str, size: float = 11.0) -> Title:
    """A chart's title in bold ``size`` pt (a spreadsheet's default is larger)."""
    bold = CharacterProperties(sz=int(100 * size), b=True)
    para = Paragraph(pPr=ParagraphProperties(defRPr=bold),
                     r=[RegularTextRun(rPr=bold, t=xml_safe(text))])
    return Title(tx=Text(rich=RichText(p=[para])), overlay=False)


def scatter(title: str, x_title: str, y_title: str, width=18.0, height=9.0) -> ScatterChart:
    """A scatter chart with its title in 11 pt (:func:`chart_title`), axis titles, tick labels
    at the axes' low ends and the legend below; ``width`` x ``height`` cm."""
    chart = ScatterChart()
    chart.title, chart.style = chart_title(title), 13
    chart.x_axis.title, chart.y_axis.title = xml_safe(x_title), xml_safe(y_title)
    chart.x_axis.delete = chart.y_axis.delete = False  # newer Excel hides axes otherwise
    # tick labels at the low end of each axis: off the curve when an axis crosses mid-plot
    chart.x_axis.tickLblPos = chart.y_axis.tickLblPos = "low"
    chart.x_axis.number_format = chart.y_axis.number_format = "General"  # not the cells' 0.0000
    chart.x_axis.majorGridlines = None
    chart.width, chart.height = width, height
    chart.legend.position = "b"
    return chart


def add_series(chart: ScatterChart, ws: Worksheet, x_col: int, y_col: int, header_row: int,
               last_row: int, colour: int | None = None, dash: bool = False,
               marker: str | None = None, width: float = 1.75, title: str | None = None):
    """A line (or, with ``marker`` and ``width`` 0, points) from the columns ``x_col``,
    ``y_col`` of ``ws`` below ``header_row`` (the y column's header its name, or ``title``)."""
    xs = Reference(ws, min_col=x_col, min_row=header_row + 1, max_row=last_row)
    if title is None:
        ys = Reference(ws, min_col=y_col, min_row=header_row, max_row=last_row)
        s = Series(ys, xs, title_from_data=True)
    else:
        ys = Reference(ws, min_col=y_col, min_row=header_row + 1, max_row=last_row)
        s = Series(ys, xs, title=xml_safe(title))
    colour_hex = COLOURS[(len(chart.series) if colour is None else colour) % len(COLOURS)]
    s.marker.symbol = marker or "none"
    if marker:
        s.marker.size = 7
        s.marker.graphicalProperties.solidFill = colour_hex
        s.marker.graphicalProperties.line.solidFill = colour_hex
    s.smooth = False
    line = s.graphicalProperties.line
    if width > 0:
        line.solidFill = colour_hex
        line.width = int(width * 12700)  # pt in EMU
        if dash:
            line.dashStyle = "dash"
    else:
        line.noFill = True
    chart.series.append(s)
    return s


def axis_range(x) -> tuple[float, float]:
    """Round axis ends just outside the data (the chart then starts where the data do)."""
    lo, hi = float(np.min(x)), float(np.max(x))
    step = 10 ** math.floor(math.log10(hi - lo)) if hi > lo else 1.0
    return math.floor(lo / step) * step, math.ceil(hi / step) * step


# --------------------------------------------------------------------------------------------
# the printed page

#: The printable width and height of an A4 page (px at 96 dpi) inside the margins of
#: :func:`print_setup` (0.5 in left and right, 0.6 in top and bottom), by orientation.
PAGE_PX = {"portrait": (21.0 / 2.54 * 96 - 96, 29.7 / 2.54 * 96 - 115.2),
           "landscape": (29.7 / 2.54 * 96 - 96, 21.0 / 2.54 * 96 - 115.2)}
#: The share of a page's height :func:`paginate` fills (room for the renderer's rounding).
PAGE_FILL = 0.96
#: A row's height where none is set (pt), and the printed width of the columns against
#: :func:`px`'s, at their widest: LibreOffice without Calibri (or its metric twin Carlito)
#: sizes the columns by its fallback font, DejaVu Sans (measured on its PDF: a row of 11 pt
#: text 15 pt tall, a column 1.31 times Excel's 7 px per character).
ROW_PT, SPREADSHEET_WIDTH = 15.0, 1.35


def px(width: float | None) -> int:
    """Screen pixels of a column of ``width`` characters (Excel's rule, 7 px per character)."""
    return int((width or 8.43) * 7 + 5)


def extent(sheet: Sheet, anchor: str, width_cm: float, height_cm: float) -> tuple[int, int]:
    """The last column and row a chart of this size anchored at ``anchor`` covers."""
    ws = sheet.ws
    col = column_index_from_string(re.match(r"[A-Z]+", anchor)[0])
    row = int(re.search(r"\d+", anchor)[0])
    left = width_cm / 2.54 * 96
    while left > 0:
        left -= px(ws.column_dimensions[get_column_letter(col)].width)
        col += 1
    left = height_cm / 2.54 * 96
    while left > 0:
        left -= (ws.row_dimensions[row].height or sheet.line_pt) * 96 / 72
        row += 1
    return col - 1, row - 1


def page_room(sheet: Sheet, first: int, last: int) -> float:
    """What a one-page sheet's landscape page has left (cm) below rows ``first`` .. ``last``
    (their heights as set), at :data:`MIN_SCALE`."""
    ws = sheet.ws
    used = sum((ws.row_dimensions[r].height or sheet.line_pt) * 96 / 72
               for r in range(first, last + 1))
    room = PAGE_PX["landscape"][1] * PAGE_FILL * 100.0 / MIN_SCALE - used
    return room / 96 * 2.54


def printed_font(sheet: Sheet) -> float:
    """The smallest font size (pt) a sheet's cells print at: the smallest cell font times the
    print scale (the body's 11 pt where a cell sets no size)."""
    sizes = [c.font.sz or BODY_PT for c in sheet.cells.values() if c.value is not None]
    return min(sizes, default=BODY_PT) * sheet.scale / 100.0


def least_scale(sheet: Sheet) -> int:
    """The least scale (%) a sheet prints at with no text under :data:`PRINTED_PT`:
    :data:`MIN_SCALE` where it has a chart (10 pt text), else what its smallest cell font
    allows (73 % for the body's 11 pt)."""
    if sheet.charts:
        return MIN_SCALE
    sizes = [c.font.sz or BODY_PT for c in sheet.cells.values() if c.value is not None]
    return min(100, math.ceil(100 * PRINTED_PT / min(sizes, default=BODY_PT)))


def finish(sheet: Sheet, header: str, right: str = "") -> None:
    """Make a written sheet print readably: every cell aligned at the top, rows tall enough
    for their wrapped text, the page set up (:func:`print_setup`) with ``header`` (left) and
    ``right`` at the top of every page."""
    _align_top(sheet)
    _body_size(sheet)
    fit_rows(sheet)
    print_setup(sheet, header, right)


def _body_size(sheet: Sheet) -> None:
    """Every cell's font scaled to the sheet's body size (:attr:`Sheet.body_pt`), where it is
    not the workbook's; one font object per style."""
    if sheet.body_pt == BODY_PT:
        return
    made: dict[tuple, Font] = {}
    for c in sheet.cells.values():
        f = c.font
        size = round((f.sz or BODY_PT) * sheet.body_pt / BODY_PT, 1)
        key = (f.name, size, f.b, f.i, f.color.rgb if f.color is not None else None)
        if key not in made:
            made[key] = Font(name=f.name or FONT, size=size, bold=f.b, italic=f.i,
                             color=f.color)
        c.font = made[key]


def _align_top(sheet: Sheet) -> None:
    """Every cell aligned at the top of its row: a label beside a wrapped text (a long source,
    a note) reads as that text's row, not the next one's."""
    top: dict[tuple, Alignment] = {}  # one object per alignment
    for c in sheet.cells.values():
        a = c.alignment
        if a.vertical is None:
            key = (a.horizontal, a.wrap_text, a.indent)
            if key not in top:
                top[key] = Alignment(horizontal=a.horizontal, vertical="top",
                                     wrap_text=a.wrap_text, indent=a.indent)
            c.alignment = top[key]


def fit_rows(sheet: Sheet) -> None:
    """Row heights for wrapped text (headers, notes): openpyxl stores none and a reader that
    does not fit rows on opening would draw wrapped lines over the next row; a text cell too
    long for its column is made to wrap."""
    need: dict[int, int] = {}
    ws = sheet.ws
    merged = {r.start_cell.coordinate for r in ws.merged_cells.ranges}  # sized where merged
    printed = sheet.print_cols or ws.max_column  # chart data beside the page: as written
    for c in sheet.cells.values():
        if not isinstance(c.value, str) or c.data_type == "f" or c.coordinate in merged \
                or c.column > printed:
            continue
        width = sheet.width(c.column)
        if not c.alignment.wrap_text:
            if len(c.value) < width - 1 or _free_right(sheet, c):
                continue
            c.alignment = Alignment(horizontal=c.alignment.horizontal, vertical="top",
                                    wrap_text=True)
        need[c.row] = max(need.get(c.row, 1), _lines(c.value, sheet.chars(width)))
    for r, lines in need.items():
        if lines > 1:
            ws.row_dimensions[r].height = max(ws.row_dimensions[r].height or 0,
                                              sheet.line_pt * lines)


def _free_right(sheet: Sheet, cell) -> bool:
    """Whether a text may run on into the empty printed cells to its right (a section's
    title): every cell it would cover is empty and inside the printed columns."""
    need = len(cell.value) - sheet.width(cell.column) + 1
    col = cell.column
    last = sheet.print_cols or sheet.ws.max_column
    while need > 0:
        col += 1
        if col > last or (cell.row, col) in sheet.cells:
            return False
        need -= sheet.width(col)
    return True


def print_setup(sheet: Sheet, header: str = "", right: str = "") -> None:
    """Print the sheet readably: A4, portrait where its printed columns fit the page, else
    landscape; a fixed scale, at most 100 % and at least :func:`least_scale`, fitting the
    printed width (so no text prints under 8 pt); page breaks that keep tables together
    (:func:`paginate`), the header of a table that runs on repeated on each page
    (:func:`print_titles`), a print area covering the cells and charts (not a chart's data
    placed to the right; an empty one for a sheet outside the printed record), ``header`` and
    ``right`` at the top of every page and the sheet's name and ``page x of y`` at the foot."""
    ws = sheet.ws
    cols, rows = print_extent(sheet)
    width = SPREADSHEET_WIDTH * sum(px(ws.column_dimensions[get_column_letter(j)].width)
                                    for j in range(1, cols + 1))
    portrait = PAGE_PX["portrait"][0] / width
    orientation = "portrait" if portrait >= 0.95 and not sheet.one_page else "landscape"
    page_w, page_h = PAGE_PX[orientation]
    least = least_scale(sheet)
    sheet.scale = least if sheet.one_page else max(least, min(100, int(100 * page_w / width)))
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.orientation = orientation
    ws.page_setup.scale = sheet.scale
    ws.sheet_properties.pageSetUpPr.fitToPage = False
    ws.page_margins = PageMargins(left=0.5, right=0.5, top=0.6, bottom=0.6, header=0.3,
                                  footer=0.3)
    ws.print_options.gridLines = False
    sheet.area = f"A1:{get_column_letter(cols)}{rows}"
    # a sheet outside the record: a blank row below its rows, across its printed columns (a
    # reader of the print range finds them), whose page is not printed
    ws.print_area = sheet.area if sheet.printed else \
        f"A{rows + 2}:{get_column_letter(cols)}{rows + 2}"
    if header:  # '&' starts a header's code: doubled, it is the character
        ws.oddHeader.left.text = xml_safe(header).replace("&", "&&")
    if right:
        ws.oddHeader.right.text = xml_safe(right).replace("&", "&&")
    ws.oddFooter.center.text = "&A, page &P of &N"
    if not sheet.one_page:
        paginate(sheet, rows, page_h * 100.0 / sheet.scale)
    repeat = print_titles(sheet)
    if repeat is not None:
        ws.print_title_rows = f"{repeat[0]}:{repeat[1]}"


def print_extent(sheet: Sheet) -> tuple[int, int]:
    """The last column and row a sheet prints: its printed columns' cells and its charts (not
    a chart's data placed to the right)."""
    cols = sheet.print_cols or sheet.ws.max_column
    rows = max((r for (r, c), cell in sheet.cells.items() if c <= cols and cell.value is not None),
               default=1)
    for chart, anchor in sheet.charts:
        c, r = extent(sheet, anchor, chart.width, chart.height)
        cols, rows = max(cols, c), max(rows, r)
    return cols, rows


def print_titles(sheet: Sheet) -> tuple[int, int] | None:
    """The rows to repeat at the top of each printed page (one range per sheet): the title and
    header of the table that runs onto another page (the layout lets one table a sheet do so,
    the last or the one whose end shares its page with what follows; a spreadsheet repeats
    the rows only on the pages after the one they first appear on), else none (each page then
    starts with a table's own title and header, and the page header names the document)."""
    breaks = [b.id for b in sheet.ws.row_breaks.brk]
    spanning = {t.repeat for t in sheet.tables if t.spans(breaks)}
    return min(spanning) if spanning else None


def paginate(sheet: Sheet, last: int, height: float) -> None:
    """Manual page breaks so that no kept block (:meth:`Sheet.keep`) is split where it fits on
    a page: rows are laid out by their heights on pages ``height`` px tall (the page's height
    at the print scale), the repeated rows on every page after the first (counted as the
    tallest range :func:`print_titles` may choose)."""
    keep = sorted(sheet.keeps)
    if not keep:
        return
    ws = sheet.ws

    def row_px(r: int) -> float:
        return (ws.row_dimensions[r].height or ROW_PT) * 96 / 72

    room = height * PAGE_FILL
    title = max((sum(row_px(k) for k in range(a, b + 1)) for a, b in
                 {t.repeat for t in sheet.tables}), default=0.0)
    used, start = 0.0, 1
    r = 1
    while r <= last:
        h = row_px(r)
        if used + h <= room or r == start:
            used += h
            r += 1
            continue
        # row r starts a new page: move the break up to the start of a block it would split
        brk = r
        for first, end in keep:
            if first < brk <= end and first > start and \
                    sum(row_px(k) for k in range(first, end + 1)) + title <= room:
                brk = first
        ws.row_breaks.append(Break(id=brk - 1))
        start, r, used = brk, brk, title


def new_workbook() -> Workbook:
    """An empty workbook (no default sheet)."""
    wb = Workbook()
    wb.remove(wb.active)
    return wb


def save(wb: Workbook, path: str | Path, *, overwrite: bool | None = None,
         what: str = "workbook") -> Path:
    """Save ``wb`` to ``path`` through the one atomic writer of every output
    (:func:`govopt.report.files.atomic_write`: temporary file, rename, mode 0666 minus umask or
    the replaced file's, errors as one-line :class:`~govopt.errors.GovoptError`; ``overwrite``:
    its policy); text properties made XML-safe first."""
    from ..files import atomic_write

    props = wb.properties
    for key in ("title", "subject", "description", "creator", "keywords", "category"):
        if isinstance(getattr(props, key), str):
            setattr(props, key, xml_safe(getattr(props, key)))
    return atomic_write(Path(path), wb.save, overwrite=overwrite, what=what)


def command_line(default: str) -> str:
    """The command writing a workbook, for its record: govopt's own command line where this
    process is the ``govopt`` command (its arguments, quoted as a shell would need), else
    ``default`` (a library call says what it was)."""
    import shlex
    import sys

    argv = list(sys.argv)
    program = Path(argv[0]) if argv else Path()
    if program.name == "govopt" or (program.name == "__main__.py"
                                    and program.parent.name == "govopt"):
        return shlex.join(["govopt", *argv[1:]])
    return default
