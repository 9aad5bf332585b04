"""The spring as its maker reads it: the governor's Spring sheet, and ``govopt spring``'s
workbook.

The governor's Spring sheet (only where the governor has a spring) opens with what the model's
spring numbers are on the spring (its free length in the type's form, coils active and total,
in words: :func:`lengths_in_words`), then the force against length at the maker's working
points with its chart, the maker's sheet, the material, the loads and the tolerance spread
(govopt's record, :meth:`govopt.analysis.spring_record.SpringReport.record`) and the spring
engineering checks; a spring without a maker's sheet (a leaf, a spring given by its rate) shows
its figures and its force over the range. ``govopt spring --xlsx`` writes the same conventions:
a Summary (command, version, date, verdict, the answer with the objective and its certified
bound to enough digits to show the gap), the maker's sheet, the checks, the force-length table
and the Spec sheet of the governor's workbook (every input with its declared meaning,
:func:`govopt.report.excel.record.inputs_table`).
"""

from __future__ import annotations

import datetime as _dt
import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from ...springs.sheet import SECTION, record_rows
from .book import (
    BOLD,
    TITLE,
    WRAP,
    Sheet,
    add_series,
    finish,
    new_workbook,
    save,
    scalar,
    scatter,
    unit_label,
)

if TYPE_CHECKING:
    from ...result import Result

#: How the spring's sheets show an SI unit: (unit, factor, number format): millimetres, N/mm,
#: MPa, rpm, degrees.
ENGINEERING = {
    "m": ("mm", 1e3, "0.000"), "Pa": ("MPa", 1e-6, "0.00"), "N/m": ("N/mm", 1e-3, "0.000"),
    "rad/s": ("rpm", 30.0 / math.pi, "0.00"), "rad": ("deg", 180.0 / math.pi, "0.000"),
    "N": ("N", 1.0, "#,##0.0"), "Hz": ("Hz", 1.0, "0.00"), "kg": ("kg", 1.0, "0.0000"),
    "kg/m^3": ("kg/m^3", 1.0, "#,##0"), "rpm": ("rpm", 1.0, "0.00"), "s": ("s", 1.0, "0.000"),
}
#: The sheet's columns: quantity, value, unit, then the checks' sense .. source.
WIDTHS = {1: 32, 2: 13, 3: 8, 4: 11, 5: 7, 6: 9, 7: 7, 8: 34}
#: The force-length chart's size (cm), beside its table.
CHART = (13.0, 8.0)


def engineering(value: Any, unit: str) -> tuple[Any, str, str]:
    """``(value, unit, number format)`` of an SI value as the spring's sheets show it
    (:data:`ENGINEERING`); a value with another unit, or no number, as it is ("General")."""
    if unit not in ENGINEERING:
        fractional = isinstance(value, float) and math.isfinite(value) and value % 1 != 0
        return value, unit, "0.000" if fractional and not unit else "General"
    seen, factor, number = ENGINEERING[unit]
    if isinstance(value, bool) or not isinstance(value, int | float | np.number):
        return value, seen, "General"
    return float(value) * factor, seen, number


def _record_rows(record: Mapping):
    """``(label, value, SI unit, depth)`` rows of a record (:func:`govopt.springs.sheet.
    record_rows`), a section's title with the value ``SECTION``; lists as one line of text in
    the unit the sheet shows."""
    for depth, label, value, unit in record_rows(record):
        if isinstance(value, list | tuple):
            seen = [engineering(v, unit) for v in value]
            yield label, "; ".join(f"{v:.6g}" if isinstance(v, float) else str(v)
                                   for v, _, _ in seen), engineering(0.0, unit)[1], depth
        else:
            yield label, value if value is SECTION else scalar(value), unit, depth


def force_length_points(sheet) -> list[tuple[str, float, float]]:
    """The maker's working points ``(name, length m, force N)`` of a
    :class:`govopt.springs.sheet.SpringSheet`: the free length (with the initial tension of an
    extension spring), the two working points and a compression spring's solid length; a point
    the one before it repeats is left out."""
    if sheet.kind == "compression":
        points = [("free length L0", sheet.L0, 0.0), ("working point 1", sheet.L1, sheet.F1),
                  ("working point 2", sheet.L2, sheet.F2)]
        if sheet.solid_length is not None:
            Lc = sheet.solid_length
            points.append(("solid length Lc", Lc, sheet.R * (sheet.L0 - Lc)))
    else:
        points = [("free length L0 (initial tension F0)", sheet.L0, sheet.F0),
                  ("working point 1", sheet.L1, sheet.F1),
                  ("working point 2", sheet.L2, sheet.F2)]
    out: list[tuple[str, float, float]] = []
    for name, L, F in points:
        if out and math.isclose(out[-1][1], L, rel_tol=1e-12) and \
                math.isclose(out[-1][2], F, rel_tol=1e-12, abs_tol=1e-12):
            continue
        out.append((name, float(L), float(F)))
    return out


def write_force_length(sheet: Sheet, row: int, points, title: str, chart_col: str = "E",
                       shown=None) -> int:
    """The force-length table at ``row`` (point, length, force; in mm and N, or in the units
    ``shown`` gives: ``shown(value, SI unit) -> (value, unit)``) and its chart beside it;
    returns the next free row."""
    ws = sheet.ws
    if shown is None:
        def shown(value, unit):
            return (value * 1e3, "mm") if unit == "m" else (value, unit)
    lu, fu = shown(0.0, "m")[1], shown(0.0, "N")[1]
    sheet.title(row, title, font=BOLD)
    sheet.header(row + 1, ["point", f"length L ({lu})", f"force F ({fu})"])
    for i, (name, L, F) in enumerate(points, start=row + 2):
        sheet.put(i, 1, name)
        sheet.put(i, 2, shown(L, "m")[0], "0.000")
        sheet.put(i, 3, shown(F, "N")[0], "#,##0.0")
    last = row + 1 + len(points)
    chart = scatter("force against length", f"length L ({lu})", f"force F ({fu})", *CHART)
    add_series(chart, ws, 2, 3, row + 1, last, colour=0, marker="circle", title="spring")
    chart.legend = None
    _, end = sheet.chart(chart, f"{chart_col}{row}")
    sheet.keep_table(row, last)
    sheet.keep(row, end)
    return max(last, end) + 2


def lengths_in_words(res: Result) -> str:
    """What the model's spring numbers are on the spring itself: the free length in the type's
    form (its method's words) against the maker's free length, and the active coils against the
    total or body coils; the numbers from the result's spring record."""
    gov, sd, rep = res.spec.governor, res.spring, res.spring_report
    sh = rep.sheet
    key = gov.free_length_key.replace("_", " ")
    factor = gov.spring_length_factor
    mm = 1e3
    out = [f"The model's {res.method.free_length}."]
    if sh.kind == "compression":
        out.append(f"The maker's free length L0 = {sh.L0 * mm:.2f} mm is the model's {key} "
                   f"l0 = {sd.l0 * mm:.2f} mm" + (f" times {factor:g}" if factor != 1 else "")
                   + f". Total coils n_t = {sh.coils:.2f}: the {sd.n:.2f} active coils n and "
                   f"{sh.coils - sd.n:.2f} inactive end coils (EN 13906-1).")
    else:
        Lv = factor * sd.l0
        opens = Lv + sh.F0 / sd.kappa
        out.append(f"Here l0 = {sd.l0 * mm:.2f} mm, so the attachments are L_v = "
                   f"{Lv * mm:.2f} mm apart where the linear law F = kappa (L - L_v) gives no "
                   f"force. The spring itself, closed, is L0 = {sh.L0 * mm:.2f} mm long inside "
                   f"its loops; under its initial tension F0 = {sh.F0:.4g} N it begins to open "
                   f"at L_v + F0/kappa = {opens * mm:.2f} mm between the attachments. Active "
                   f"coils n = {sh.n:.3f} = body coils n_b {sh.coils:.3f} + G/E "
                   f"{sh.n - sh.coils:.3f} (the loops' flexibility, Shigley 10-11).")
    return " ".join(out)


def _record(sheet: Sheet, row: int, record: Mapping) -> int:
    """A record's rows (quantity, value, unit; a long text across the value columns); its
    top-level sections kept whole where they fit; returns the next free row."""
    sheet.header(row, ["quantity", "value", "unit"])
    head = row
    row += 1
    tops = []
    for label, value, unit, depth in _record_rows(record):
        label = "  " * depth + label
        if value is SECTION:
            sheet.title(row, label, font=BOLD)
            if depth == 0:
                tops.append(row)
        elif isinstance(value, str) and len(value) > WIDTHS[2]:
            sheet.put(row, 1, label)
            sheet.paragraph(row, value, 2, 8, font=None)
        else:
            value, unit, number = engineering(value, unit)
            sheet.put(row, 1, label)
            sheet.put(row, 2, "not given" if value is None else value, number)
            sheet.put(row, 3, "" if value is None else unit)
        row += 1
    for first, end in zip(tops, [*tops[1:], row], strict=True):
        sheet.keep_table(first, end - 1, header=head, top=head)
    return row + 1


def _checks(sheet: Sheet, row: int, checks, title: str) -> int:
    """The spring engineering checks' table (check .. source); returns the next free row."""
    sheet.title(row, title, font=BOLD)
    if not checks:
        return row + 2
    sheet.header(row + 1, ["check", "value", "unit", "limit", "sense", "margin", "result",
                           "source"])
    r = row + 1
    for c in checks:
        r += 1
        (value, unit, number), (limit, _, _) = (engineering(v, c.unit)
                                                for v in (c.value, c.limit))
        number = number if c.unit else "0.000"
        for col, v, f in ((1, c.name, None), (2, value, number), (3, unit_label(unit), None),
                          (4, limit, number), (5, c.sense, None), (6, c.margin, "0.00%"),
                          (7, "PASS" if c.passed else "FAIL", None), (8, c.source, None)):
            sheet.put(r, col, v, f)
        sheet.ws.cell(r, 8).alignment = WRAP
    sheet.keep_table(row, r)
    return r + 2


def build_spring(sheet: Sheet, res: Result) -> None:
    """The governor's Spring sheet (see the module's text)."""
    gov = res.spec.governor
    sheet.set_widths(WIDTHS)
    sheet.print_cols = len(WIDTHS)
    sheet.ws.freeze_panes = "A2"
    rep = res.spring_report
    kind = f"{gov.spring} spring" if gov.spring_kind.helical else gov.spring
    sheet.title(1, f"Spring: the governor's {kind}, as its maker reads it")
    if rep is None:
        _spring_figures(sheet, res)
        return
    sheet.paragraph(2, lengths_in_words(res), 1, 8, font=None)
    row = write_force_length(sheet, 4, force_length_points(rep.sheet),
                             "Force against length at the maker's working points")
    sheet.title(row, "Specification for the spring maker, material, loads and tolerances",
                font=BOLD)
    row = _record(sheet, row + 1, rep.record())
    graded = res.spec.material.grade is not None
    checks = [c for c in res.checks if graded and c.group == "spring"]
    _checks(sheet, row, checks, "Spring engineering checks" + (
        "" if checks else ": none (they need a material.grade)"))


def _spring_figures(sheet: Sheet, res: Result) -> None:
    """A spring without a maker's sheet (a leaf; a spring given by its rate): its figures, what
    its free length is, and its force over the range."""
    gov, st = res.spec.governor, res.statics
    sheet.paragraph(2, f"The model's {res.method.free_length}.", 1, 8, font=None)
    sheet.header(4, ["quantity", "value", "unit"])
    row = 5
    for f in res.figures():
        if f.group != "spring":
            continue
        value, unit, number = engineering(f.value, f.unit)
        sheet.put(row, 1, f.name)
        sheet.put(row, 2, value, number)
        sheet.put(row, 3, unit)
        row += 1
    sheet.keep_table(4, row - 1, header=4)
    row += 1
    xs, xu = gov.shown(st.alpha)
    sheet.title(row, "The spring's force over the range", font=BOLD)
    sheet.header(row + 1, [f"{gov.coordinate_name} ({xu})", "force F (N)"])
    for i, (x, F) in enumerate(zip(xs, st.spring_force, strict=True), start=row + 2):
        sheet.put(i, 1, float(x), "0.000")
        sheet.put(i, 2, float(F), "#,##0.0")
    last = row + 1 + len(xs)
    chart = scatter("the spring's force over the range", f"{gov.coordinate_name} ({xu})",
                    "force F (N)", *CHART)
    add_series(chart, sheet.ws, 1, 2, row + 1, last, colour=0)
    chart.legend = None
    sheet.chart(chart, f"E{row}")
    sheet.keep_table(row, last)


# --------------------------------------------------------------------------------------------
# govopt spring --xlsx


def spring_workbook(outcome, path, *, rows, sheet, points, replace: bool = True,
                    command: str = ""):
    """``govopt spring``'s workbook (see the module's text), saved atomically (an existing
    file replaced only with ``replace``): ``rows`` the answer's ``(label, SI value or text, SI
    unit)`` (:func:`govopt.report.spring_outputs.workbook_rows`), shown in the units the input
    was written in (``outcome.shown``); ``sheet`` the maker's sheet or None; ``points`` the
    force-length points ``(name, length m, force N)`` of the spring's assessment; the inputs
    (``outcome.entries``, from ``outcome.spec`` or the options) on the Spec sheet."""
    from ... import __version__
    from .book import command_line
    from .record import inputs_table

    checks_, optimum, shown = outcome.checks, outcome.record, outcome.shown
    wb = new_workbook()
    header = f"govopt spring: {outcome.name}"
    summary = Sheet(wb.create_sheet("Summary"))
    summary.set_widths({1: 36, 2: 18, 3: 10, 4: 44})
    summary.print_cols = 4
    summary.title(1, header, font=TITLE)
    now = _dt.datetime.now(_dt.UTC).replace(microsecond=0).isoformat()
    record = [("command", command or command_line("govopt spring (Python API)")),
              ("govopt version", __version__), ("written (UTC)", now)]
    row = 3
    for label, value in record:
        summary.put(row, 1, label).font = BOLD
        summary.paragraph(row, value, 2, 4, font=None)
        row += 1
    failed = [c.name for c in checks_ if not c.passed]
    verdict = (f"FAIL: {len(failed)} of {len(checks_)} checks fail: " + "; ".join(failed)
               if failed else f"PASS: all {len(checks_)} checks pass" if checks_
               else "no spring engineering checks (they need a wire grade, --material)")
    row += 1
    summary.paragraph(row, verdict, 1, 4, font=BOLD)
    row += 2
    summary.header(row, ["quantity", "value", "unit", "note"])
    head = row
    for label, value, unit in rows:
        row += 1
        if unit == "section":
            summary.title(row, label, font=BOLD)
            continue
        if isinstance(value, float) and not math.isfinite(value):
            value = "not bounded" if math.isinf(value) else "none"
        if label.startswith(("objective", "certified")) and isinstance(value, float):
            value, unit = shown(value, unit)
            summary.put(row, 1, label)
            summary.put(row, 2, value, "0.00000000000E+00")  # 12 digits: the gap shows
            summary.put(row, 3, unit)
            continue
        if isinstance(value, int | float) and not isinstance(value, bool):
            number = "0.00" if unit == "%" else engineering(value, unit)[2]
            value, unit = shown(value, unit)  # the units the input was written in
            summary.put(row, 1, label)
            summary.put(row, 2, value, number)
            summary.put(row, 3, unit)
        else:
            summary.put(row, 1, label)
            summary.paragraph(row, str(value), 2, 4, font=None)
    gap = math.nan if optimum is None else optimum.gap
    if math.isfinite(gap):
        row += 1
        summary.put(row, 1, "gap to the certified bound")
        summary.put(row, 2, gap, "0.00E+00")
        summary.paragraph(row, "(objective - bound) / bound, a fraction: how far the answer is "
                               "from the best any spring could do", 4, 4, font=None)
    summary.keep_table(head, row, header=head)
    if sheet is not None:
        row += 2
        summary.paragraph(row, "Specification for the spring maker (EN 15800 grade 2) on the "
                               "Spring sheet; the checks on the Checks sheet; force against "
                               "length on the Force-length sheet; the inputs, each with "
                               "its meaning, on the Spec sheet.", 1, 4)
        spring = Sheet(wb.create_sheet("Spring"))
        spring.set_widths(WIDTHS)
        spring.print_cols = 3
        spring.title(1, f"{outcome.name}: specification for the spring maker")
        _record(spring, 3, sheet.figures())
    checks = Sheet(wb.create_sheet("Checks"))
    checks.set_widths(WIDTHS)
    checks.print_cols = len(WIDTHS)
    checks.ws.freeze_panes = "A2"
    _checks(checks, 1, checks_, "Spring checks" + (
        "" if checks_ else ": none (they need a wire grade, --material)"))
    fl = Sheet(wb.create_sheet("Force-length"))
    fl.set_widths({1: 34, 2: 14, 3: 14, 4: 4})
    write_force_length(fl, 1, points, f"{outcome.name}: force against length", shown=shown)
    inputs = Sheet(wb.create_sheet("Spec"))
    inputs_table(inputs, f"Spec: the inputs of {outcome.name}", outcome.entries, outcome.spec,
                 show=shown)
    for s in (summary, *([spring] if sheet is not None else []), checks, fl, inputs):
        finish(s, header, f"govopt {__version__}")
    summary.ws.sheet_view.tabSelected = True
    wb.properties.creator = f"govopt {__version__}"
    wb.properties.title = header
    return save(wb, path, overwrite=replace)
