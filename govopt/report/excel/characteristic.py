"""The Characteristic sheet: the equilibrium over the configuration range in the units people read
(deg or mm, rpm, MPa; omega in rad/s, the paper's), the speeds the governor opens and closes at
where friction acts, and the chart of speed against configuration with the spec's required band
(its data right of the printed columns)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ..sections import shown
from .book import BOLD, Sheet, add_series, axis_range, fmt, scatter, unit_label

if TYPE_CHECKING:
    from ...result import Result

#: The characteristic chart's size (cm).
CHART = (22.0, 11.0)


def columns(res: Result) -> list[tuple[str, np.ndarray, str]]:
    """The sheet's columns: (header with unit, values as shown, shown unit); the speed in rpm
    is the third, the friction speeds (where friction acts) the fourth and fifth."""
    st, gov = res.statics, res.spec.governor
    xs, xu = gov.shown(st.alpha)
    q = "N*m" if gov.coordinate == "angle" else "N"  # the generalised force's unit
    rise, fall = res.friction_speeds
    raw: list[tuple[str, Any, str]] = [("speed", st.omega, "rad/s")]
    if rise is not None:
        raw += [("opening speed (rising against friction)", rise, "rad/s"),
                ("closing speed (falling against friction)", fall, "rad/s")]
    raw += [(name, v, q) for name, v in zip(gov.force_names, (st.M_z, st.M_f, st.M_r0),
                                            strict=True)]
    if gov.spring is not None:
        raw.append(("spring force F", st.spring_force, "N"))
        if np.isfinite(st.stress).any():  # a spring given by its rate alone has no stress
            raw.append(("shear stress tau", st.stress, "Pa"))
    raw += [(name, values, unit) for name, (values, unit) in st.extra.items()]
    if res.k2 is not None:
        raw.append(("k^2", res.k2, "rad^2/s^2"))
    cols = [(f"{gov.coordinate_name} ({xu})", np.asarray(xs, dtype=float), xu),
            ("omega (rad/s)", np.asarray(st.omega, dtype=float), "rad/s")]
    for name, values, unit in raw:
        v, u = shown(np.asarray(values, dtype=float), unit)
        cols.append((f"{name} ({unit_label(u)})", v, u))
    return cols


def speed_range(res: Result) -> tuple[float, float]:
    """The speed axis's ends (rpm): round values just outside the speeds drawn (the
    characteristic, the friction band's, the required band)."""
    speeds = [res.statics.omega]
    speeds += [s for s in res.friction_speeds if s is not None]
    if res.spec.speed is not None:
        speeds.append(np.array([res.spec.speed.omega_inner, res.spec.speed.omega_outer]))
    rpm = np.concatenate([np.asarray(s, dtype=float).ravel() for s in speeds]) * 30 / math.pi
    lo, hi = float(np.min(rpm)), float(np.max(rpm))
    pad = 0.05 * (hi - lo) if hi > lo else 1.0
    return axis_range([lo - pad, hi + pad])


def band_column(res: Result) -> int:
    """The first column of the required band's chart data: right of the printed table and
    of the chart under it (cm, at the narrowest a column prints)."""
    return max(len(columns(res)), 2 + int(CHART[0] / 2.54 * 96 / 60)) + 2


def build_characteristic(sheet: Sheet, res: Result) -> None:
    """The table, then its chart under it: speed (rpm) against the configuration, the friction
    band's opening and closing speeds dashed, the spec's required band; printed, the chart
    shares its page with the table's last rows, never alone under a repeated header."""
    ws, spec = sheet.ws, res.spec
    cols = columns(res)
    sheet.header(1, [c[0] for c in cols])
    ws.freeze_panes = "B2"
    n = len(res.statics.alpha)
    for j, (_, values, unit) in enumerate(cols, start=1):
        for i in range(n):
            sheet.put(i + 2, j, values[i], fmt(unit))
    sheet.set_widths({j: 9 for j in range(1, len(cols) + 1)})
    xu = cols[0][2]
    chart = scatter(f"Characteristic ({res.method.named('characteristic').cite}): speed "
                    "against configuration", cols[0][0], "speed (rpm)", *CHART)
    add_series(chart, ws, 1, 3, 1, n + 1, colour=0)
    if res.friction_speeds[0] is not None:
        add_series(chart, ws, 1, 4, 1, n + 1, colour=3, dash=True, width=1.25)
        add_series(chart, ws, 1, 5, 1, n + 1, colour=4, dash=True, width=1.25)
    sheet.print_cols = len(cols)
    if spec.speed is not None:  # the required band: two dashed lines, data right of the table
        col = band_column(res)
        sheet.title(1, "required band (chart data)", col=col, font=BOLD)
        band = ((spec.speed.omega_inner, "required inner speed (rpm)"),
                (spec.speed.omega_outer, "required outer speed (rpm)"))
        sheet.put(2, col, cols[0][0])
        for k, (_, label) in enumerate(band, start=1):
            sheet.put(2, col + k, label)
        xs = cols[0][1]
        for i, x in enumerate((float(xs[0]), float(xs[-1])), start=3):
            sheet.put(i, col, x, fmt(xu))
            for k, (w, _) in enumerate(band, start=1):
                sheet.put(i, col + k, w * 30.0 / math.pi, fmt("rpm"))
        for k in (1, 2):
            add_series(chart, ws, col, col + k, 2, 4, colour=1, dash=True)
    elif res.friction_speeds[0] is None:
        chart.legend = None  # one curve: the axis titles name it
    chart.x_axis.scaling.min, chart.x_axis.scaling.max = axis_range(cols[0][1])
    chart.y_axis.scaling.min, chart.y_axis.scaling.max = speed_range(res)
    anchor = f"B{n + 3}"
    _, end = sheet.chart(chart, anchor)  # below the table
    sheet.keep_table(1, n + 1, header=1)
    sheet.keep(max(2, n + 1 - 5), end)  # the chart with the table's last rows
