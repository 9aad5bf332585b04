"""Text report of a :class:`~govopt.result.Result` (formats only, no physics).

Every value is printed with its unit, and the same quantity always in the same unit: angles in
degrees, lengths in millimetres, stresses in MPa, k^2 in 1/s^2 (:data:`sections.SHOWN`), the
checks included. Margins read as margins ("1.86 % spare", "over by 3.2 %"), a time that never
comes is "never", the objective carries its unit. The dynamics and the optimiser's record are
the declared sections of :mod:`govopt.report.sections`, the same tables as the workbook's.

On a terminal the tables are coloured (rich: PASS green, FAIL red, binding yellow); piped or
redirected, the report is plain ASCII text with no escape codes (``NO_COLOR`` is honoured).
"""

from __future__ import annotations

import io
import math
import os
import shutil
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from ..limits import printable
from ..verdict import ACTIVE_TOL, Check, Figure
from . import sections as sec

if TYPE_CHECKING:  # the result imports this module (Result.summary): no import back
    from ..result import Result

RPM = 30.0 / math.pi


def colour_default() -> bool:
    """Colour when standard output is a terminal, ``NO_COLOR`` is unset and ``TERM`` is not
    ``dumb``."""
    return (sys.stdout.isatty() and "NO_COLOR" not in os.environ
            and os.environ.get("TERM") != "dumb")


def _num(value, fmt: str = ".5g") -> str:
    """A table cell as text: a number in ``fmt`` (whole numbers as integers), a word as is,
    blank for None."""
    v = sec.cell(value)
    if v is None:
        return ""
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return format(v, fmt)
    return str(v)


def _plain(text: str) -> bool:
    """Whether rich would print ``text`` unchanged: printable but for line breaks (rich drops
    control codes and expands tabs)."""
    return text.replace("\n", "").isprintable()


class TextReport:
    """Collects the report: tables through rich, coloured on a terminal, plain text without
    colour when not. ``plain``: None for not ``colour`` (a line of printable text written as
    is); False renders every line through rich as well."""

    def __init__(self, colour: bool, plain: bool | None = None):
        self.colour = colour
        self.plain = not colour if plain is None else plain
        self.buf = io.StringIO()
        self._console = None

    @property
    def console(self):
        """A rich console writing to the report, made on first use."""
        if self._console is None:
            from rich import box
            from rich.console import Console

            colour = self.colour
            width = shutil.get_terminal_size((120, 24)).columns if colour else 400
            self._console = Console(file=self.buf, force_terminal=colour, no_color=not colour,
                                    color_system="standard" if colour else None, width=width,
                                    markup=False, highlight=False, emoji=False)
            # a rule under the header only: Unicode on a terminal, ASCII when piped
            self.box = box.SIMPLE_HEAD if colour else box.Box(
                "    \n    \n -- \n    \n    \n    \n    \n    \n", ascii=True)
        return self._console

    def line(self, text: str = "", style: str | None = None) -> None:
        text = printable(text)  # a spec's strings never reach a terminal as escape codes
        if self.plain and _plain(text):
            self.buf.write(text + "\n")
            return
        self.console.print(text, style=style if self.colour else None, soft_wrap=True)

    def title(self, text: str) -> None:
        self.line("")
        self.line(text, "bold cyan")

    def table(self, headers, rows, *, right=(), show_header=True, styles=None) -> None:
        """``rows`` of strings; ``right``: indices of right-justified columns; ``styles``: a
        style per row (or None)."""
        headers, rows = [printable(h) for h in headers], [[printable(c) for c in r] for r in rows]
        from rich.table import Table
        from rich.text import Text

        console = self.console
        t = Table(box=self.box, show_header=show_header, show_edge=False, pad_edge=False,
                  padding=(0, 1), header_style="bold" if self.colour else "")
        for j, h in enumerate(headers):
            t.add_column(h, justify="right" if j in right else "left",
                         no_wrap=j < len(headers) - 1)
        for i, r in enumerate(rows):
            style = (styles[i] if styles else None) if self.colour else None
            t.add_row(*(Text(c) for c in r), style=style)
        console.print(t)

    def section(self, table: sec.Table) -> None:
        """A declared table (:mod:`govopt.report.sections`); series are left to the sheets."""
        if table.series:
            return
        self.title(table.title)
        if table.properties:
            head = table.headers
            self.table(head, [[str(r[0]), str(r[1] or "-"), *(_num(v) for v in r[2:])]
                              for r in table.rows
                              if any(sec.cell(v) is not None for v in r[2:])],  # no empty rows
                       right=range(2, len(head)), show_header=head[2:] != ["value"])
        else:
            self.table(table.headers, [[_num(v) for v in r] for r in table.rows],
                       right=range(1, len(table.headers)))
        for note in table.notes:
            self.line(f"  {note}", "dim")

    def text(self) -> str:
        text = self.buf.getvalue()
        if not self.colour:
            text = "\n".join(line.rstrip() for line in text.splitlines())
        return text.rstrip("\n")


def margin_words(c: Check) -> str:
    """A check's margin in words: "1.86 % spare", "over by 3.2 %" (a ``<=`` check),
    "short by 3.2 %" (a ``>=`` check); a non-finite margin is "unbounded"."""
    m = 100.0 * c.margin
    if not math.isfinite(m):
        return "unbounded" if m > 0 else ("over" if c.sense == "<=" else "short") + " unbounded"
    size = f"{abs(m):.2f} %" if abs(m) < 1000 else f"{abs(m):,.0f} %"
    if c.margin >= 0 or c.passed:
        return f"{size} spare"
    return ("over by " if c.sense == "<=" else "short by ") + size


def check_name(c: Check, res: Result) -> str:
    """The check's name as the report shows it, saying what its limit is where the name does
    not: ``"k^2 > 0 (stability)"`` held to a margin (the spec's ``k2_margin * omega0^2``) reads
    ``"k^2 >= 0.05 omega0^2 (stability margin)"``."""
    if c.name == "k^2 > 0 (stability)" and c.limit > 0:
        return f"k^2 >= {c.limit / res.omega_reference ** 2:.3g} omega0^2 (stability margin)"
    return c.name


def _check_rows(checks, res: Result) -> tuple[list[list[str]], list[str]]:
    rows, styles = [], []
    for c in checks:
        value, unit = sec.shown(c.value, c.unit)
        limit, _ = sec.shown(c.limit, c.unit)
        result = ("PASS (binding)" if c.active else "PASS") if c.passed else "FAIL"
        rows.append([check_name(c, res), _num(value, ".6g"), f"{c.sense} {_num(limit, '.6g')}",
                     unit.replace("*", " ") or "-", margin_words(c), result])
        styles.append("red bold" if not c.passed else ("yellow" if c.active else "green"))
    return rows, styles


_CHECK_HEADERS = ["check", "value", "limit", "unit", "margin", "result"]


def _checks(out: TextReport, res: Result) -> None:
    rows, styles = _check_rows(res.checks, res)
    out.title("Checks")
    out.table(_CHECK_HEADERS, rows, right=(1, 2, 4), styles=styles)
    out.line("  margin: the distance to the limit as a share of the limit (of the check's scale "
             f"where the limit is 0); binding: satisfied with less than {100 * ACTIVE_TOL:g} % "
             "to spare.", "dim")


#: Checks shown in the answer besides the failing and binding ones: the tightest few.
WATCH_TIGHTEST = 3


def watched(res: Result) -> list[Check]:
    """The checks the answer shows: every failing and binding check and the
    :data:`WATCH_TIGHTEST` tightest of the rest (all of them where there are few), in the
    result's order."""
    if len(res.checks) <= 2 * WATCH_TIGHTEST + 2:
        return list(res.checks)
    must = [c for c in res.checks if not c.passed or c.active]
    rest = sorted((c for c in res.checks if c.passed and not c.active),
                  key=lambda c: c.margin)[:WATCH_TIGHTEST]
    keep = {id(c) for c in (*must, *rest)}
    return [c for c in res.checks if id(c) in keep]


def verdict(res: Result) -> str:
    """One line: all checks pass, or which fail (with their margins); where the verdict is the
    made governor's (:attr:`Result.verdict_of`), "PASS as made" or "FAIL as made" with the
    made-and-set yield against ``min_yield``, what fails most often and what to change."""
    from ..made_words import meets

    failed = [c for c in res.checks if not c.passed]
    n = len(res.checks)
    if not failed:
        binding = [check_name(c, res) for c in res.checks if c.active]
        tail = f"; binding: {'; '.join(binding)}" if binding else ""
        ok = meets(res.made)
        if ok is None:
            req, spring = res.spec.requirements, res.spec.governor.spring
            asked = (" at nominal (--nominal)" if res.spec.verdict == "nominal" and spring
                     else " at nominal (requirements.verdict = \"nominal\")" if
                     req is not None and req.verdict == "nominal" and spring else "")
            return f"PASS{asked}: all {n} checks pass" + tail
        if ok:
            return f"PASS as made: {yield_line(res)}; all {n} checks pass at nominal" + tail
        return (f"FAIL as made: {yield_line(res)}; all {n} checks pass at nominal; "
                + made_advice(res))
    return (f"FAIL: {len(failed)} of {n} checks fail: "
            + "; ".join(f"{check_name(c, res)} ({margin_words(c)})" for c in failed))


def made_lines(res: Result) -> list[str]:
    """The yield beside the verdict (where the spec states tolerances: ``Result.made``): the
    share of made governors that pass with its interval and the requirement failing most often,
    the worst-case speed band beside the required one, and what they were made to."""
    from ..made_words import meets, sampled_words

    made = res.made
    if not made:
        return []
    nominal = "PASS" if all(c.passed for c in res.checks) else "FAIL"
    said = nominal == "PASS" and meets(made) is not None  # the verdict's line says the yield
    band, tol = made["speed_band"], made["tolerances"]

    def rpm(pair) -> str:
        return f"{pair[0] * RPM:.4g}-{pair[1] * RPM:.4g} rpm"

    st = res.statics
    besides = (f"the required {rpm(band['required_rad_s'])}" if band.get("required_rad_s")
               else f"nominal {rpm((float(np.min(st.omega)), float(np.max(st.omega))))}")
    made_to = [f"EN 15800 grade {tol['spring_grade']}" + (
        f", wire to {tol['wire_standard']}" if tol.get("wire_standard") else "")
        if tol.get("spring_grade") is not None else ""]
    made_to += [f"{what} +-{100 * f:g} %" for what, f in (
        ("masses", tol.get("masses_fraction", 0.0)), ("dash-pot", tol.get("dashpot_fraction", 0.0)),
        ("torque slope", tol.get("torque_slope_fraction", 0.0))) if f]
    if tol.get("adjusting_nut_m"):
        made_to.append(f"set by the fitter's nut +-{tol['adjusting_nut_m'] * 1e3:.3g} mm")
    if tol.get("dashpot_valve_fraction"):
        made_to.append(f"dash-pot valve set +-{100 * tol['dashpot_valve_fraction']:g} %")
    made_as = " as made (before the fitter's setting)" if tol.get("adjusting_nut_m") or \
        tol.get("set_by_the_fitter") else ""
    made_to += [f"set by the fitter: {s}" for s in tol.get("set_by_the_fitter") or ()]
    return [*([] if said else [f"{nominal} at nominal; {yield_line(res)}"]),
            f"  worst-case speeds {rpm(band['band_rad_s'])}{made_as} beside {besides}",
            "  made to " + ", ".join(m for m in made_to if m) + f"; {sampled_words(made)}"]


def made_advice(res: Result) -> str:
    """What the fitter or the designer can change where the made governors fall short of
    ``min_yield``."""
    req = res.spec.requirements
    fitter = ("let the fitter set the spring (requirements.fitter = \"sets\")"
              if req is not None and req.fitter == "none" and res.spec.governor.adjustments()
              else "")
    return "; ".join(x for x in (
        fitter, "design for the made governor (govopt design: only designs whose made yield "
                "meets min_yield)",
        "or make to a finer grade (requirements.robust_spring_grade = 1), widen the speed "
        "band, or lower requirements.min_yield") if x)


def yield_line(res: Result) -> str:
    """The yield in words (:func:`govopt.made.yield_words`), the checks named as the report
    names them."""
    from ..made_words import yield_words

    shown = {c.name: check_name(c, res) for c in res.checks}
    return yield_words(res.made, lambda n: shown.get(n, n))


def band_spring_note(spec) -> str:
    """What the spring found for the band is (:func:`govopt.spec.band_spring`)."""
    found, gov = spec.band_spring, spec.governor
    return (f"no spring given: the one that floats the governor between speed.inner and "
            f"speed.outer has the rate {found['stiffness'] / 1e3:.5g} N/mm and the "
            f"{gov.free_length_key.replace('_', ' ')} {found['free_length'] * 1e3:.5g} mm, the "
            f"initial force {found['force_inner']:.5g} N at the innermost configuration "
            f"({found['force_outer']:.5g} N at the outermost); evaluated with it")


def _warnings(res: Result) -> list[str]:
    """The notes a reader should not miss: the spring found for the band, the optimiser's and
    the spring sheet's."""
    notes = [str(n) for n in (res.optimisation or {}).get("notes") or []]
    found = getattr(res.spec, "band_spring", None)
    if found:
        notes.insert(0, band_spring_note(res.spec))
    if res.spring_report is not None:
        d = res.spring_report.to_dict()
        notes += [*d["tolerance_spread"]["notes"], *d["notes"]]
    if res.made:
        notes += [*res.made["tolerances"]["notes"], *(
            [res.made["yield"]["note"]] if res.made["yield"].get("note") else [])]
    return list(dict.fromkeys(notes))


#: The report's sections by name (``govopt evaluate --section NAME``), in the full report's
#: order; ``summary`` is the answer (verdict, design, the checks to watch, notes).
SECTIONS = ("summary", "design", "checks", "characteristic", "dynamics", "vibration",
            "optimisation", "spring")


def _summary_section(out: TextReport, res: Result, every_check: bool = False) -> None:
    """The answer: the verdict, the design, the checks to watch (none where ``every_check``:
    the whole Checks table follows) and the notes."""
    line = verdict(res)
    out.title("Verdict")
    out.line(line, "green bold" if line.startswith("PASS") else "red bold")
    for text in made_lines(res):
        out.line(text)
    _design_section(out, res)
    shown = [] if every_check else watched(res)
    if shown:
        rows, styles = _check_rows(shown, res)
        more = len(res.checks) - len(shown)
        out.title("Checks to watch" + (f" (failing, binding and the {WATCH_TIGHTEST} tightest; "
                                       f"{more} more pass: --section checks)" if more else ""))
        out.table(_CHECK_HEADERS, rows, right=(1, 2, 4), styles=styles)
    notes = _warnings(res)
    if notes:
        out.title("Notes")
        for note in notes:
            out.line(f"  - {note}")


def figure_text(value, unit: str) -> tuple[str, str]:
    """A figure's value and unit as the reports show them (:func:`govopt.verdict.shown`: mm,
    MPa, N/mm, rpm, deg), 5 significant digits: ``("139.4", "rpm")``; a word as it is."""
    v, u = sec.shown(value, unit)
    if isinstance(v, str):
        return v, u.replace("*", " ") or "-"
    return _num(v), u.replace("*", " ") or "-"


def _summary(res: Result) -> list[list[str]]:
    """Rows ``[quantity, value, unit, note]`` of the design's figures
    (:meth:`~govopt.result.Result.figures`), each in the unit a person reads."""
    rows = []
    for f in res.figures():
        value, unit = figure_text(f.value, f.unit)
        note = "; ".join(x for x in (f.note, f.source) if x)
        if f.symbol and f.symbol not in note:
            note = f"{f.symbol}" + (f"; {note}" if note else "")
        rows.append([f.name, value, unit, note])
    return rows


def _design_section(out: TextReport, res: Result) -> None:
    out.title("Design")
    out.table(["", "", "", ""], _summary(res), right=(1,), show_header=False)


def _characteristic(out: TextReport, res: Result) -> None:
    st, gov = res.statics, res.spec.governor
    q = "N m" if gov.coordinate == "angle" else "N"
    xs, xunit = gov.shown(st.alpha)
    rise, fall = res.friction_speeds
    friction = [] if rise is None else [("opening\n(rpm)", rise * RPM, ".2f"),
                                        ("closing\n(rpm)", fall * RPM, ".2f")]
    cols = [(f"{gov.coordinate_name}\n({xunit})", xs, ".3f"), ("omega\n(rad/s)", st.omega, ".4f"),
            ("speed\n(rpm)", st.omega * RPM, ".2f"), *friction,
            *((f"{n}\n({q})", v, ".3f") for n, v in zip(gov.force_names,
                                                        (st.M_z, st.M_f, st.M_r0), strict=True))]
    if gov.spring is not None:
        cols.append(("spring force\n(N)", st.spring_force, ".1f"))
        if np.isfinite(st.stress).any():  # a spring given by its rate alone has no stress
            cols.append(("shear stress\n(MPa)", st.stress / 1e6, ".1f"))
    if res.k2 is not None:
        cols.append(("k^2\n(1/s^2)", res.k2, ".1f"))
    out.title(res.method.heading("statics", "Characteristic"))
    out.table([c[0] for c in cols],
              [[format(float(c[1][i]), c[2]) for c in cols] for i in range(len(st.alpha))],
              right=range(len(cols)))


def _tables(out: TextReport, tables) -> None:
    for table in tables:
        out.section(table)


def _spring_section(out: TextReport, res: Result) -> None:
    for line in format_spring(res):
        out.line(line)


_WRITERS = {
    "summary": _summary_section,
    "characteristic": _characteristic,
    "design": _design_section,
    "dynamics": lambda out, res: _tables(out, sec.load_changes(res) + sec.restoring(res)),
    "vibration": lambda out, res: _tables(out, sec.vibration(res)),
    "optimisation": lambda out, res: _tables(out, sec.optimisation(res)),
    "checks": _checks,
    "spring": _spring_section,
}


def format_result(res: Result, colour: bool | None = None,
                  sections: Sequence[str] | None = None) -> str:
    """The report, the answer first: its head (spec, governor, fidelity), then ``sections``
    (names of :data:`SECTIONS`, in that order; None: all of them, the full report). The
    ``summary`` alone (:func:`format_summary`) fits a screen. ``colour``: None for
    :func:`colour_default` (a terminal)."""
    out = TextReport(colour_default() if colour is None else colour)
    spec = res.spec
    cited = {k for e in res.method.equations for k in e.settings}  # the settings that choose
    fid = [f"{s.key.split('.')[-1]}={s.value}" for s in res.method.settings if s.key in cited]
    out.line(f"govopt {res.kind}: {spec.name}  ({spec.path})  [{spec.governor.title}]", "bold")
    out.line("fidelity: " + (", ".join(fid) or "none to choose"))
    wanted = SECTIONS if sections is None else sections
    unknown = [s for s in wanted if s not in _WRITERS]
    if unknown:
        raise ValueError(f"unknown report section(s) {unknown}; expected {SECTIONS}")
    for name in SECTIONS:
        if name == "summary" and name in wanted:
            _summary_section(out, res, every_check="checks" in wanted)
        elif name in wanted and not (name == "design" and "summary" in wanted):
            _WRITERS[name](out, res)
    if sections is not None and list(wanted) == ["summary"]:
        out.line("")
        out.line("More: --full, or --section NAME (" + ", ".join(SECTIONS[1:]) + ").", "dim")
    return out.text()


def format_summary(res: Result, colour: bool | None = None) -> str:
    """The answer first, to fit a screen: the verdict, the design in engineering units, the
    failing, binding and tightest checks, and the notes (``govopt evaluate``'s default)."""
    return format_result(res, colour, ["summary"])


def format_spring(res: Result) -> list[str]:
    """The spring maker's sheet, the spring's loads, fatigue and tolerance spread, and the
    sources of the spring engineering checks (the checks themselves are rows of the
    Checks table, shown once); nothing without a wire spring."""
    rep = res.spring_report
    if rep is None:
        return []
    loads, sp = rep.loads, rep.to_dict()["tolerance_spread"]
    value = {k: f.value for k, f in loads.items() if isinstance(f, Figure)}  # in their units:
    out = ["", "Spring specification (to send to a spring maker)", rep.sheet.to_text(),
           f"  static loads        F = {value['force min']:.5g} .. {value['force max']:.5g} "
           f"N over the range"]  # forces in N, frequencies in Hz (the figures' units)
    fat = loads["fatigue"]
    if fat is None:
        out.append("  fatigue             no periodic forcing modelled: fatigue not checked")
    else:
        swing, unit = sec.shown(fat["peak to peak"].value, fat["peak to peak"].unit)
        out.append(f"  fatigue load cycle  swing {float(swing):.4g} {unit} peak-to-peak at the "
                   f"normal configuration ({fat['forcing']})")
        if "force min" in fat:
            mpa = {k: sec.shown(fat[k].value, fat[k].unit)[0] for k in (
                "corrected stress min", "corrected stress max", "mean stress",
                "alternating stress")}
            out.append(f"                      F = {fat['force min'].value:.5g} .. "
                       f"{fat['force max'].value:.5g} N; corrected stress "
                       f"{mpa['corrected stress min']:.4g} .. "
                       f"{mpa['corrected stress max']:.4g} MPa (mean "
                       f"{mpa['mean stress']:.4g}, alternating "
                       f"{mpa['alternating stress']:.4g} MPa)")
    harm = ", ".join(f"{f:.4g}" for f in value["excitation harmonics"])
    out.append(f"  surge               {value['surge frequency']:.4g} Hz; excitation "
               f"harmonics present: {f'{harm} Hz' if harm else 'none modelled'}")
    rpm = [f"{a * 30.0 / math.pi:.2f} .. {b * 30.0 / math.pi:.2f}" for a, b in (
        sp["omega_inner_range_rad_s"], sp["omega_outer_range_rad_s"])]
    out.append(f"  tolerance spread    rate {sp['stiffness_range_N_per_m'][0]:.6g} .. "
               f"{sp['stiffness_range_N_per_m'][1]:.6g} N/m (wire +- "
               f"{sp['wire_diameter_tolerance_m'] * 1e3:.3g} mm, coil +- "
               f"{sp['coil_diameter_tolerance_m'] * 1e3:.3g} mm, free length +- "
               f"{sp['free_length_tolerance_m'] * 1e3:.3g} mm): speed at the inner end "
               f"{rpm[0]} rpm, at the outer end {rpm[1]} rpm")
    out += [f"  note: {n}" for n in [*sp["notes"], *rep.notes]]
    graded = res.spec.material is not None and res.spec.material.grade is not None
    rows = [c for c in res.checks if graded and c.group == "spring"]
    if rows:  # their values, limits and margins are the Checks table's rows
        out += ["", "Spring engineering checks: sources (values and margins under Checks)"]
        out += [f"  {c.name}: {c.source}" for c in rows]
    return out


def format_html(res: Result) -> str:
    """The answer as HTML for a notebook (``Result._repr_html_``): the verdict, the design's
    figures and every check, each number in the unit a person reads (the same rows as
    :func:`format_summary`'s, from the checks' and figures' fields)."""
    from html import escape

    def table(headers, rows, styles=None):
        head = "".join(f"<th>{escape(h)}</th>" for h in headers)
        body = "".join(
            f"<tr{'' if not styles or not styles[i] else f' style={chr(34)}{styles[i]}{chr(34)}'}>"
            + "".join(f"<td>{escape(str(c))}</td>" for c in r) + "</tr>"
            for i, r in enumerate(rows))
        return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"

    line = verdict(res)
    colour = {"red bold": "color:#9c0006", "yellow": "color:#9c6500",
              "green": "color:#006100"}
    rows, styles = _check_rows(res.checks, res)
    return (f"<div><p><b>govopt {escape(res.kind)}: {escape(str(res.spec.name))}</b> "
            f"[{escape(res.spec.governor.title)}]</p>"
            f"<p style=\"{'color:#006100' if line.startswith('PASS') else 'color:#9c0006'}\">"
            f"<b>{escape(line)}</b></p><p><b>Design</b></p>"
            + table(["quantity", "value", "unit", "note"], _summary(res))
            + "<p><b>Checks</b></p>"
            + table(_CHECK_HEADERS, rows, [colour.get(s, "") for s in styles]) + "</div>")
