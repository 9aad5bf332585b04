"""The Summary sheet: the design record's first page, printed on one landscape page.

What the design is and who wrote it (name, description, governor type, spec file, the command,
govopt's version, the date), the verdict, the chosen design in the units of a drawing (the
masses, the spring as its maker specifies it, the dash-pot; the speeds, with friction where it
acts), the failing, binding and tightest checks with their margins, what the spring's
tolerances do to the speeds, and two charts: the characteristic against the required band (and
the friction band) and the governor drawn to scale at its innermost, normal and outermost
configurations (:meth:`govopt.governors.base.Governor.drawing`; the drawing's data on the Model
sheet, the characteristic's on its own sheet).
"""

from __future__ import annotations

import datetime as _dt
import math
from typing import TYPE_CHECKING

import numpy as np
from openpyxl.chart import Reference, Series
from openpyxl.chart.layout import Layout, ManualLayout
from openpyxl.chart.legend import LegendEntry
from openpyxl.styles import Font, PatternFill

from ...verdict import shown
from ..text import check_name, made_lines, margin_words, verdict, watched
from .book import (
    BODY_PT,
    BOLD,
    COLOURS,
    FONT,
    ITALIC,
    TITLE,
    WRAP,
    Sheet,
    add_series,
    axis_range,
    fit_rows,
    page_room,
    scatter,
    sig_format,
    unit_label,
)

if TYPE_CHECKING:
    from ...result import Result

#: The left block (label, value, unit, a note across D-F), a gap, the right block (a check's
#: name, value, unit, margin and result; the charts above and below it).
WIDTHS = {1: 25, 2: 10, 3: 8, 4: 7, 5: 7, 6: 7, 7: 1, 8: 24, 9: 10, 10: 8, 11: 14, 12: 9}
LEFT, RIGHT, RIGHT_COL = 6, 8, "H"
#: The characteristic's and the drawing's size on the page (cm): the right block's width.
CHART, DRAWING = (12.6, 5.6), (12.6, 7.6)
_VERDICT_FILL = {True: PatternFill("solid", fgColor="C6EFCE"),
                 False: PatternFill("solid", fgColor="FFC7CE")}
_VERDICT_FONT = {True: Font(name=FONT, size=BODY_PT, bold=True, color="006100"),
                 False: Font(name=FONT, size=BODY_PT, bold=True, color="9C0006")}


def design_rows(res: Result) -> list[tuple[str, object, str, str]]:
    """The chosen design as a drawing gives it: ``(label, SI value or text, SI unit, note)``,
    a section's title with the unit ``"section"``: the flying masses and the central load, the
    spring (the maker's numbers where govopt has the maker's sheet, else the section the spec
    gives), the dash-pot; then the speeds and the objective (the result's figures)."""
    gov, sd, ds = res.spec.governor, res.spring, res.design
    figures = {f.name: f for f in res.figures()}
    rows: list[tuple[str, object, str, str]] = []
    rows.append((f"{gov.mass_name} weight (each)", sd.m * 9.80665, "N",
                 f"mass {sd.m:.4g} kg"))
    if sd.central:
        rows.append(("central load weight", sd.central * 9.80665, "N",
                     f"mass {sd.central:.4g} kg"))
    rep = res.spring_report
    if rep is not None:
        sh = rep.sheet
        key = gov.free_length_key.replace("_", " ")
        rows += [(f"Spring ({sh.kind})", None, "section", ""),
                 ("material", f"{sh.grade} ({sh.material_standard})", "", ""),
                 ("wire diameter d", sh.d, "m", ""),
                 ("mean coil diameter D", sh.D, "m",
                  f"outside {1e3 * (sh.D + sh.d):.2f} mm, inside {1e3 * (sh.D - sh.d):.2f} mm"),
                 ("active coils n", sh.n, "",
                  f"{'total coils n_t' if sh.kind == 'compression' else 'body coils n_b'} "
                  f"{sh.coils:.4g}; {sh.ends}"),
                 ("free length L0", sh.L0, "m",
                  f"the model's {key} l0 = {1e3 * sd.l0:.2f} mm (Spring sheet)"),
                 ("rate R", sh.R, "N/m", "")]
        if sh.kind != "compression":
            rows.append(("initial tension F0", sh.F0, "N", ""))
    elif gov.spring is not None:
        rows.append((f"Spring ({gov.spring})", None, "section", ""))
        for k in gov.spring_kind.section:  # the section the spec gives
            value = getattr(ds, k.name, None)
            if value is not None:
                rows.append((k.name.replace("_", " "), value, "m" if k.kind == "length" else "",
                             ""))
        for name in ("spring stiffness", gov.free_length_key.replace("_", " ")):
            if name in figures:
                f = figures[name]
                rows.append((name, f.value, f.unit, ""))
    if ds is not None and ds.dashpot is not None:
        f = figures["dash-pot"]
        rows.append(("dash-pot f", f.value, f.unit, f.note))
    for name, f in figures.items():
        if (f.group == "speed" and name != "mean speed") or name.startswith("objective"):
            rows.append((name, f.value, f.unit, f.note if name.startswith("objective") else ""))
    return rows


def build_summary(sheet: Sheet, res: Result, *, command: str, characteristic: Sheet,
                  drawing: tuple | None) -> None:
    """The Summary sheet (see the module's text): on the left what the design is and who wrote
    it, the verdict, the design and what the tolerances do; on the right the characteristic,
    the checks to watch and the governor drawn. ``characteristic``: the Characteristic sheet
    (the chart's data); ``drawing``: ``(sheet, series)`` of the drawing's data on the Model
    sheet (:func:`drawing_data`), or None."""
    from ... import __version__

    spec, ws = res.spec, sheet.ws
    sheet.set_widths(WIDTHS)
    sheet.print_cols = max(WIDTHS)
    kind = "design" if res.optimisation else res.kind
    sheet.title(1, f"govopt {kind}: {spec.name}", font=TITLE)
    description = next((e.written for e in spec.entries if e.key == "description"), "")
    row = 2
    sheet.paragraph(row, "; ".join(t for t in (description, spec.governor.title) if t), 1, LEFT,
                    font=ITALIC)
    row += 1
    now = _dt.datetime.now(_dt.UTC).replace(microsecond=0).isoformat()
    for label, value in (("command", command), ("govopt", f"{__version__}, {now} UTC")):
        sheet.put(row, 1, label).font = BOLD
        sheet.paragraph(row, value, 2, LEFT, font=None)
        row += 1
    line = verdict(res)
    passed = line.startswith("PASS")
    sheet.paragraph(row, line, 1, LEFT, font=_VERDICT_FONT[passed])
    ws.cell(row, 1).fill = _VERDICT_FILL[passed]
    for text in made_lines(res):  # the yield beside the verdict
        row += 1
        sheet.paragraph(row, text.strip(), 1, LEFT, font=None)
    row = _design(sheet, row + 1, res)
    _tolerances(sheet, row + 1, res)
    fit_rows(sheet)  # the rows' heights: the right column's charts sit by them
    _, end = sheet.chart(_characteristic_chart(res, characteristic), f"{RIGHT_COL}1")
    last = _checks(sheet, end + 2, res)
    fit_rows(sheet)
    if drawing is not None:  # as tall as the page has room for (one page), 4 cm at least
        height = max(4.0, min(DRAWING[1], page_room(sheet, 1, last + 1) - 0.3))
        sheet.chart(_drawing_chart(res, *drawing, height=height), f"{RIGHT_COL}{last + 2}")
    ws.freeze_panes = None


def _design(sheet: Sheet, row: int, res: Result) -> int:
    """The chosen design's table; returns the next free row."""
    sheet.title(row, "Chosen design" if res.optimisation else "Design", font=BOLD)
    sheet.header(row + 1, ["quantity", "value", "unit", "note", "", ""])
    first, row = row, row + 2
    for label, value, unit, note in design_rows(res):
        if unit == "section":
            sheet.put(row, 1, label).font = BOLD
            row += 1
            continue
        sheet.put(row, 1, label)
        if isinstance(value, str):
            sheet.paragraph(row, value, 2, LEFT, font=None)
        else:
            v, u = shown(value, unit)
            sheet.put(row, 2, v, sig_format(v) if isinstance(v, float) else None)
            sheet.put(row, 3, unit_label(u) if unit else "")
            if note:
                sheet.paragraph(row, note, 4, LEFT, font=None)
        row += 1
    sheet.keep_table(first, row - 1)
    return row


def _checks(sheet: Sheet, row: int, res: Result) -> int:
    """The failing, binding and tightest checks (the text's ``Checks to watch``) in the right
    block; returns its last row."""
    shown_checks = watched(res)
    more = len(res.checks) - len(shown_checks)
    sheet.title(row, "Checks to watch" + (f": failing, binding, tightest ({more} more pass)"
                                          if more else ""), col=RIGHT, font=BOLD)
    sheet.header(row + 1, ["check", "value", "unit", "margin", "result"], col=RIGHT)
    first, row = row, row + 2
    for c in shown_checks:
        value, unit = shown(c.value, c.unit)
        sheet.put(row, RIGHT, check_name(c, res)).alignment = WRAP
        sheet.put(row, RIGHT + 1, value, sig_format(value) if isinstance(value, float) else None)
        sheet.put(row, RIGHT + 2, unit_label(unit))
        sheet.put(row, RIGHT + 3, margin_words(c))
        result = ("PASS, binding" if c.active else "PASS") if c.passed else "FAIL"
        sheet.put(row, RIGHT + 4, result).font = _VERDICT_FONT[c.passed]
        row += 1
    sheet.keep_table(first, row - 1)
    return row - 1


def _tolerances(sheet: Sheet, row: int, res: Result) -> int:
    """What the spring's tolerances do to the speeds (the spring report's worst-case spread),
    where govopt has the maker's sheet."""
    rep = res.spring_report
    if rep is None:
        return row
    sp = rep.to_dict()["tolerance_spread"]
    grade = rep.sheet.tolerance_grade
    rpm = 30.0 / math.pi
    (a, b), (c, d) = sp["omega_inner_range_rad_s"], sp["omega_outer_range_rad_s"]
    sheet.paragraph(row, f"Spring tolerances (EN 15800 grade {grade}, worst case): speed at "
                         f"the inner end {a * rpm:.5g} .. {b * rpm:.5g} rpm, at the outer end "
                         f"{c * rpm:.5g} .. {d * rpm:.5g} rpm (rate "
                         f"{sp['stiffness_range_N_per_m'][0] / 1e3:.5g} .. "
                         f"{sp['stiffness_range_N_per_m'][1] / 1e3:.5g} N/mm, free length "
                         f"+- {sp['free_length_tolerance_m'] * 1e3:.3g} mm)", 1, LEFT, font=None)
    return row + 1


def _characteristic_chart(res: Result, char: Sheet):
    """Speed (rpm) against configuration from the Characteristic sheet's columns, the friction
    band's speeds dashed, the required band from its chart data."""
    from .characteristic import band_column, columns, speed_range

    ws = char.ws
    cols = columns(res)
    n = len(res.statics.alpha)
    chart = scatter(f"Characteristic ({res.method.named('characteristic').cite})",
                    cols[0][0], "speed (rpm)", *CHART)
    add_series(chart, ws, 1, 3, 1, n + 1, colour=0, title="speed")
    if res.friction_speeds[0] is not None:
        add_series(chart, ws, 1, 4, 1, n + 1, colour=3, dash=True, width=1.25, title="opening")
        add_series(chart, ws, 1, 5, 1, n + 1, colour=4, dash=True, width=1.25, title="closing")
    if res.spec.speed is not None:
        col = band_column(res)
        for k in (1, 2):
            add_series(chart, ws, col, col + k, 2, 4, colour=1, dash=True,
                       title="required band" if k == 1 else "required band (outer)")
        chart.legend.legendEntry.append(LegendEntry(idx=len(chart.series) - 1, delete=True))
    chart.x_axis.scaling.min, chart.x_axis.scaling.max = axis_range(cols[0][1])
    chart.y_axis.scaling.min, chart.y_axis.scaling.max = speed_range(res)
    return chart


def drawing_data(sheet: Sheet, res: Result, col: int) -> list | None:
    """The governor drawn at its innermost, normal and outermost configurations, as chart
    data in columns from ``col`` of ``sheet`` (x and y in mm, a blank row between polylines):
    per configuration its bars, sleeve, spring and balls (each ball a polygon of its radius)
    and its fulcrums; the frame once. Returns ``[(label, colour, style, first row, last row,
    x column), ...]`` for :func:`_drawing_chart`, or None where the type draws nothing."""
    gov, sd = res.spec.governor, res.spring
    configurations = (("innermost", gov.x_inner, 0, True), ("normal", gov.x_normal, 5, False),
                      ("outermost", gov.x_outer, 1, True))
    drawings = [gov.drawing(x, sd) for _, x, _, _ in configurations]
    if drawings[1] is None:
        return None
    sheet.title(1, "The governor drawing (chart data, mm)", col=col, font=BOLD)
    out, c = [], col
    circle = np.linspace(0.0, 2.0 * np.pi, 25)
    for (label, x, colour, dash), d in zip(configurations, drawings, strict=True):
        groups = {"lines": [], "spring": [], "pivots": []}
        for part in d.parts:
            pts = np.asarray(part.points, dtype=float) * 1e3
            if part.kind == "mass" or (part.kind == "frame" and len(pts) == 1):
                r = part.size * 1e3
                poly = np.column_stack([pts[0, 0] + r * np.cos(circle),
                                        pts[0, 1] + r * np.sin(circle)])
                groups["lines" if part.kind == "mass" else "frame"] = \
                    groups.get("lines" if part.kind == "mass" else "frame", []) + [poly]
            elif part.kind == "pivot":
                groups["pivots"].append(pts)
            elif part.kind == "spring":
                groups["spring"].append(pts)
            elif part.kind == "frame":
                groups.setdefault("frame", []).append(pts)
            else:
                groups["lines"].append(pts)
        xs, unit = gov.shown(x)
        name = f"{label}: {gov.coordinate_name} {float(xs):.4g} {unit}"
        for group, polys in groups.items():
            if group == "frame" and label != "normal" or not polys:
                continue
            sheet.put(2, c, f"{name}: {group}")
            sheet.put(3, c, "x (mm)")
            sheet.put(3, c + 1, "y (mm)")
            r = 4
            for poly in polys:
                for px_, py_ in poly:
                    sheet.put(r, c, float(px_), "0.0")
                    sheet.put(r, c + 1, float(py_), "0.0")
                    r += 1
                r += 1  # a blank row: a gap in the line
            out.append((name if group == "lines" else f"{label} {group}", colour, dash, group,
                        3, r - 2, c))
            sheet.set_widths({c: 10, c + 1: 10, c + 2: 2})
            c += 3
    return out


def _drawing_chart(res: Result, sheet: Sheet, series: list, height: float = DRAWING[1]):
    """The drawing as a scatter chart on equal scales (the plot area's place fixed, so that a
    millimetre across is a millimetre up): each configuration's bars, balls and sleeve as one
    line in its colour (innermost and outermost dashed), its spring thin, its fulcrums as
    triangles; the frame grey; the title names the colours."""
    ws = sheet.ws
    chart = scatter("Drawn to scale: innermost (blue), normal (grey), outermost (red)",
                    *res.spec.governor.drawing(
        res.spec.governor.x_normal, res.spring).axes, DRAWING[0], height)
    chart.x_axis.majorGridlines = None
    chart.y_axis.majorGridlines = None
    xs, ys = [], []
    for name, colour, dash, group, head, last, c in series:
        for col, bucket in ((c, xs), (c + 1, ys)):
            bucket += [cell.value for (r, cc), cell in sheet.cells.items()
                       if cc == col and head < r <= last and isinstance(cell.value, float)]
        x_ref = Reference(ws, min_col=c, min_row=head + 1, max_row=last)
        y_ref = Reference(ws, min_col=c + 1, min_row=head + 1, max_row=last)
        s = Series(y_ref, x_ref, title=name)
        s.smooth = False
        hexcolour = "A6A6A6" if group == "frame" else COLOURS[colour]
        line = s.graphicalProperties.line
        if group == "pivots":
            s.marker.symbol, s.marker.size = "triangle", 6
            s.marker.graphicalProperties.solidFill = hexcolour
            s.marker.graphicalProperties.line.solidFill = hexcolour
            line.noFill = True
        else:
            s.marker.symbol = "none"
            line.solidFill = hexcolour
            line.width = int((0.75 if group == "spring" else 2.5 if group == "frame" else 1.5)
                             * 12700)
            if dash or group == "spring":
                line.dashStyle = "sysDot" if group == "spring" else "dash"
        chart.series.append(s)

    chart.display_blanks = "gap"
    chart.legend = None  # the title names the configurations' colours
    # the axes' share of the chart, fixed: room for the title's two lines above (1.2 cm) and
    # the tick labels and axis title below (1.1 cm)
    plot_w, top = 0.78, 1.2 / height
    plot_h = 1.0 - top - 1.1 / height
    # "inner": the share is the axes' rectangle itself, not one that also holds the tick
    # labels and axis titles; set on the chart (openpyxl writes the chart's layout into its
    # plot area, over one set on the plot area: the balls were drawn as ellipses)
    chart.layout = Layout(manualLayout=ManualLayout(
        layoutTarget="inner", xMode="edge", yMode="edge", x=0.17, y=top, w=plot_w, h=plot_h))
    width_cm, height_cm = plot_w * DRAWING[0], plot_h * height
    (x0, x1), (y0, y1) = (min(xs), max(xs)), (min(ys), max(ys))
    per_cm = max((x1 - x0) / width_cm, (y1 - y0) / height_cm) * 1.02  # mm a cm, both axes
    while True:  # each axis from a whole tick, as many mm a cm on both, the drawing inside
        step = nice(per_cm * 1.5)  # a tick every 1.5 cm or so
        ends = [(math.floor((0.5 * (lo + hi) - 0.5 * per_cm * cm) / step) * step, cm)
                for lo, hi, cm in ((x0, x1, width_cm), (y0, y1, height_cm))]  # centred
        if all(start + per_cm * cm >= hi for (start, cm), hi in zip(ends, (x1, y1),
                                                                      strict=True)):
            break
        per_cm *= 1.03
    for axis, (start, cm) in zip((chart.x_axis, chart.y_axis), ends, strict=True):
        axis.scaling.min, axis.scaling.max = start, start + per_cm * cm
        axis.majorUnit = step
    chart.x_axis.number_format = chart.y_axis.number_format = "0"
    return chart


def nice(x: float) -> float:
    """The least of 1, 2, 2.5, 5 times a power of ten at least ``x`` (> 0).

    >>> nice(0.7), nice(13.0), nice(2.2)
    (1.0, 20.0, 2.5)
    """
    power = 10.0 ** math.floor(math.log10(x))
    return next(f * power for f in (1.0, 2.0, 2.5, 5.0, 10.0) if f * power >= x * (1 - 1e-12))
