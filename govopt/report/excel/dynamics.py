"""The Dynamics sheet: k^2 over the range against omega0^2 (table, chart under it), then the
declared dynamics tables of :mod:`govopt.report.sections` (load changes, roots with real and
imaginary parts, the forced vibration and its harmonics), each headed with the type's own
method, and the responses' charts (their data right of the printed columns); or why there are
none."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from openpyxl.utils import get_column_letter

from .. import sections
from .book import BOLD, ITALIC, Sheet, add_series, axis_range, fmt, scatter

if TYPE_CHECKING:
    from ...result import Result

#: Charts' size (cm): one to a row, inside a landscape page's width.
CHART = (18.0, 9.0)
#: The printed columns' widths: labels, units, a value column per load change.
WIDTHS = {1: 40, 2: 10, **{j: 12 for j in range(3, 9)}}


def build_dynamics(sheet: Sheet, res: Result) -> None:
    """The declared tables and the responses' charts, then k^2 over the range (last: a table
    that runs onto another page repeats its header, and only the sheet's last may)."""
    ws, spec = sheet.ws, res.spec
    sheet.title(1, res.method.heading("load change", "Dynamics")
                if res.dynamics else "Dynamics")
    ws.freeze_panes = "A2"
    sheet.set_widths(WIDTHS)
    sheet.print_cols = len(WIDTHS)
    row = 3
    dyn = res.dynamics or {}
    if not dyn:
        why = ("the spec has no [engine] data (flywheel inertia, torque slope), which the "
               "load-change and vibration analyses need" if spec.engine is None else
               "this result carries none (statics only); the spec has engine data, so run "
               "the dynamics analysis to fill this part")
        sheet.paragraph(row, f"Dynamics were not run: {why}.", 1, 4)
        row += 2
    tables = sections.dynamics(res) if dyn else []
    for table in (t for t in tables if not t.series):
        row = sheet.write_table(row, table)
    series = [t for t in tables if t.series]
    if series:
        data_col = len(WIDTHS) + 2  # the data right of the printed columns, two each
        sheet.put(row, 1, f"Responses: the charts below; their data are in columns "
                          f"{get_column_letter(data_col)} onwards (not printed).").font = ITALIC
        row += 1
        for k, table in enumerate(series):
            col = data_col + 3 * k
            sheet.title(2, table.title, col=col, font=BOLD)
            head, last = sheet.write_rows(3, table, col)
            chart = scatter(table.chart.title, table.headers[table.chart.x],
                            table.headers[table.chart.ys[0]], *CHART)
            for n, j in enumerate(table.chart.ys):
                add_series(chart, ws, col + table.chart.x, col + j, head, last, colour=n)
            chart.legend = None  # one curve: the axis titles name it
            _, end = sheet.chart(chart, f"A{row}")
            sheet.keep(row - (k == 0), end)
            row = end + 2
            sheet.set_widths({col: 16, col + 1: 16})
    if res.k2 is not None:
        _k2(sheet, row, res)


def _k2(sheet: Sheet, row: int, res: Result) -> None:
    """k^2 over the range against omega0^2 (the type's restoring stiffness), its chart under
    the table's last rows."""
    ws, st, gov = sheet.ws, res.statics, res.spec.governor
    w0sq = res.omega_reference**2
    xs, xu = gov.shown(st.alpha)
    ceiling = gov.k2_rule(getattr(res.spec.requirements, "k2_margin", None))[1]
    k2 = res.method.named("k2")
    sheet.title(row, f"Restoring stiffness k^2 over the range ({k2.cite}): stable for "
                     + ("0 < k^2 < omega0^2" if ceiling else "k^2 > 0"), font=BOLD)
    head = row + 1
    sheet.header(head, [f"{gov.coordinate_name} ({xu})", "k^2 (1/s^2)", "omega0^2 (1/s^2)",
                        "k^2 / omega0^2"])
    for i in range(len(st.alpha)):
        r = head + 1 + i
        sheet.put(r, 1, float(xs[i]), fmt(xu))
        sheet.put(r, 2, res.k2[i], fmt("rad^2/s^2"))
        sheet.put(r, 3, w0sq, fmt("rad^2/s^2"))
        sheet.put(r, 4, res.k2[i] / w0sq, "0.0000")
    last = head + len(st.alpha)
    chart = scatter("k^2 against omega0^2" + (" (stable below omega0^2, above 0)"
                                              if ceiling else " (stable above 0)"),
                    f"{gov.coordinate_name} ({xu})", "k^2 (1/s^2)", *CHART)
    add_series(chart, ws, 1, 2, head, last, colour=0)
    if ceiling:
        add_series(chart, ws, 1, 3, head, last, colour=1, dash=True)
    chart.y_axis.scaling.min = min(0.0, float(np.min(res.k2)))
    chart.x_axis.scaling.min, chart.x_axis.scaling.max = axis_range(xs)
    sheet.keep_table(row, last)
    _, end = sheet.chart(chart, f"A{last + 2}")
    sheet.keep(last - 4, end)  # the chart with the table's last rows
