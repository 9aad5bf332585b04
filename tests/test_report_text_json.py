"""What an engineer sees: the text report (items 3: every value with its unit, the same
unit for the same quantity, margins in words, "never", the objective's unit, colour on a
terminal and plain text when piped) and the JSON (no section twice, infinities as null
with a flag, units in the keys). The workbook's tables, print setup and cached values are tested
in test_excel.py."""

from __future__ import annotations

import dataclasses
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import govopt
from govopt.jsonable import jsonable
from govopt.made import with_yield
from govopt.report import sections
from govopt.report.text import check_name, format_result, format_summary
from govopt.result import Check

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"
ANSI = re.compile(r"\x1b\[")


def _strict(text: str):
    """JSON as the standard has it: no NaN or Infinity tokens."""
    def bad(token):
        raise AssertionError(f"non-standard JSON token {token}")
    return json.loads(text, parse_constant=bad)


def _cli(*args, cwd, **kw):
    return subprocess.run([sys.executable, "-m", "govopt.cli", *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=120,
                          env={**os.environ, "NO_COLOR": "", "TERM": "xterm"}, **kw)


@pytest.fixture(scope="module")
def shaft():
    return govopt.evaluate(govopt.load_spec(SPECS / "hamabe-a.toml"))


@pytest.fixture(scope="module")
def porter():
    return govopt.evaluate(govopt.load_spec(SPECS / "porter-engine.toml"))


@pytest.fixture(scope="module")
def designed():
    return govopt.design(govopt.load_spec(SPECS / "hamabe-design.toml"))


def _rows(text: str, title: str) -> list[list[str]]:
    """The rows of the plain-text table under ``title`` (columns split on 2+ spaces), up to a
    blank line or its notes (indented two spaces; the rows start in the first column)."""
    lines = text.splitlines()
    i = lines.index(title)
    out = []
    for line in lines[i + 1:]:
        if not line.strip() or line.startswith("  "):
            break
        if set(line.strip()) <= {"-"}:
            continue
        out.append(re.split(r"\s{2,}", line.strip()))
    return out


# ------------------------------------------------------------------------------------------
# text


def test_piped_report_is_plain_text(tmp_path, shaft):
    """`govopt evaluate | ...`: plain ASCII, no escape codes, the same text as the API's."""
    run = _cli("evaluate", SPECS / "hamabe-a.toml", "--full", cwd=tmp_path)
    assert run.returncode == 1, run.stderr  # case a fails its irregularity: exit 1
    assert not ANSI.search(run.stdout)
    assert not re.search("[\u2500-\u257f]", run.stdout)  # ASCII rules, no box drawing
    # the CLI attaches the made governors' yield (the new default "made" verdict,
    # govopt.made.with_yield), which govopt.evaluate leaves to the caller
    assert run.stdout.strip() == format_result(with_yield(shaft), colour=False).strip()
    assert "Checks" in run.stdout.splitlines()


@pytest.mark.skipif(os.name != "posix", reason="needs a pseudo-terminal")
def test_terminal_report_is_coloured(tmp_path):
    """On a terminal the report is a coloured rich table: PASS in green (ANSI 32)."""
    import pty

    main, child = pty.openpty()
    env = {k: v for k, v in os.environ.items() if k != "NO_COLOR"}
    proc = subprocess.Popen([sys.executable, "-m", "govopt.cli", "evaluate",
                             str(SPECS / "hamabe-a.toml")], cwd=tmp_path, stdout=child,
                            stderr=subprocess.PIPE, env={**env, "TERM": "xterm",
                                                         "COLUMNS": "200"})
    os.close(child)
    chunks = []
    while True:
        try:
            data = os.read(main, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
    assert proc.wait(timeout=120) == 1, proc.stderr.read()  # case a fails a check: exit 1
    os.close(main)
    out = b"".join(chunks).decode()
    assert ANSI.search(out)
    assert re.search(r"\x1b\[[0-9;]*32m[^\x1b]*PASS", out)  # green PASS


@pytest.mark.parametrize("cell", ["a\tb", "a\rb", "a\x1b[31mb"])
def test_control_codes_in_cells_are_shown_as_escapes(cell):
    """A tab, carriage return or escape code in a cell is printed as its escape (``\\t``)."""
    from govopt.report.text import TextReport

    report = TextReport(False)
    report.table(["a", "b"], [["1", cell], [cell, "2"]], right=(0,))
    plain = report.text()
    assert repr(cell)[1:-1] in plain and cell not in plain


def test_a_spec_never_sends_the_terminal_an_escape_code(tmp_path):
    """A spec whose file name (or any string it carries) holds an escape sequence: on a
    terminal the report shows it as text (``\\x1b[31m``), never as a colour change."""
    odd = tmp_path / "a\x1b[31mred.toml"
    odd.write_text((SPECS / "hamabe-a.toml").read_text())
    res = govopt.evaluate(govopt.load_spec(odd))
    for colour in (True, False):
        text = format_result(res, colour=colour)
        assert "\x1b[31m" not in text
        assert "a\\x1b[31mred.toml" in text


def test_settling_not_decided_is_not_never(shaft):
    """A stable response whose settling the solver could not place (its time grid cut, the
    envelope unresolved: ``settling_not_decided``) reads "not decided", never "never"."""
    import copy

    res = copy.copy(shaft)
    res.dynamics = copy.deepcopy(shaft.dynamics)
    lc = res.dynamics["load_changes"][0]
    assert lc["stable"] and math.isfinite(lc["settling_time_s"])
    lc.update(settling_time_s=math.inf, settling_not_decided=True)
    table = sections.load_changes(res)[0]
    row = next(r for r in table.rows if str(r[0]).startswith("settling time"))
    assert row[2] == "not decided"
    assert any("'not decided'" in n for n in table.notes)
    assert not any("'never'" in n and "settling" in n for n in table.notes)


def test_every_value_has_its_unit_and_margins_read_as_margins(designed):
    """The checks table: a unit on every row (``-`` for a ratio), angles in degrees, lengths in
    mm, stresses in MPa (one unit per quantity: the summary's and the tables' units), margins
    in words; "never" for a time that never comes, the objective with its unit."""
    text = format_result(designed, colour=False)
    assert "inf" not in re.findall(r"[a-z]+", text)  # "never" / "unbounded", not "inf s"
    checks = _rows(text, "Checks")
    assert checks[0] == ["check", "value", "limit", "unit", "margin", "result"]
    by = {r[0]: r for r in checks[1:]}
    assert len(by) == len(designed.checks)
    for c in designed.checks:
        name, value, limit, unit, margin, result = by[check_name(c, designed)]
        shown, want_unit = sections.shown(c.value, c.unit)
        assert unit == (want_unit.replace("*", " ") or "-")
        assert float(value) == pytest.approx(shown, rel=1e-5, abs=1e-12)
        assert re.fullmatch(r"[\d,.]+ % spare|(over|short) by [\d,.]+ %", margin), margin
        assert result.startswith("PASS" if c.passed else "FAIL")
        want_margin = abs(100 * c.margin)
        assert float(re.search(r"[\d,.]+", margin)[0].replace(",", "")) == pytest.approx(
            want_margin, abs=0.006 if want_margin < 1000 else 0.51)
    # the same quantity in the same unit wherever it appears (was radians in the checks and
    # degrees in the load change's line)
    assert by["no over-regulation: unloading"][3] == "deg"
    lc = {r[0]: r for r in _rows(text, "Load changes (Hamabe eq. 28, eq. 32; Vyshnegradsky "
                                       "1877)")}
    assert lc["over-regulation (past the new equilibrium)"][1] == "deg"
    assert by["shear stress"][3] == "MPa"
    summary = {r[0]: r for r in _rows(text, "Design")}
    assert summary["max shear stress"][2] == "MPa"
    assert by["shear stress"][1] == f"{designed.max_stress / 1e6:.6g}"
    k2_check = check_name(designed.check("k^2 > 0 (stability)"), designed)
    assert by[k2_check][3] == "1/s^2" == lc["k^2 at the new equilibrium"][1]
    assert by["body length within free length"][3] == "mm" == summary["wire diameter"][2]
    # every summary row has a unit column; the first arrival never comes: "never", not "inf s"
    assert all(len(r) >= 3 and r[2] for r in summary.values())
    assert lc["first arrival at the new equilibrium"][1:] == ["s", "never"]
    # the objective with its unit
    opt = {r[0]: r for r in _rows(text, "Optimisation (govopt design)")}
    value = designed.optimisation["value"]
    counts = designed.optimisation["objective"]["counts"]  # what the moving mass counts
    assert opt[f"objective: moving mass ({counts})"][1:] == ["kg", f"{value:.5g}"]


def test_length_coordinate_in_mm_everywhere(porter):
    """A ball governor (the configuration is a length): the load change, its check and the
    characteristic in millimetres."""
    text = format_result(porter, colour=False)
    # the Porter's load change cites its own sources (the third-order model, Hurwitz), not
    # the shaft governor's paper
    lc = {r[0]: r for r in _rows(text, "Load changes (Vyshnegradsky 1877; Hurwitz 1895)")}
    assert lc["ball radius after (new equilibrium)"][1:] == ["mm", "230"]
    checks = {r[0]: r for r in _rows(text, "Checks")}
    assert checks["no over-regulation: load thrown off"][3] == "mm"
    assert checks["characteristic rises (stable)"][3] == "rad/s per mm"
    head = text.splitlines()[text.splitlines().index(
        "Characteristic (textbook 3.4(b) eq. (i), 3.3)") + 2]
    assert head.split()[0] == "(mm)"


# ------------------------------------------------------------------------------------------
# JSON


def test_json_infinities_are_null_with_a_flag():
    """Hamabe's case a returns aperiodically: its first arrival never comes. The JSON is strict
    (no Infinity token): null with ``<key>_infinite``."""
    from clirun import invoke

    run = invoke(["evaluate", str(SPECS / "hamabe-a.toml"), "--json"])
    assert run.exit_code == 1, run.output  # case a fails its irregularity: exit 1
    lc = _strict(run.stdout)["load_changes"][0]
    assert lc["first_arrival_time_s"] is None and lc["first_arrival_time_s_infinite"] == "+inf"
    assert isinstance(lc["settling_time_s"], float) and "settling_time_s_infinite" not in lc
    # a check whose value is unbounded (an unstable load change) and a range open at one end
    c = Check("no over-regulation: x", math.inf, 0.0, "<=", "rad", scale=0.1)
    d = _strict(json.dumps(c.to_dict()))
    assert (d["value"], d["value_infinite"], d["margin"], d["margin_infinite"]) == \
        (None, "+inf", None, "-inf")
    assert jsonable({"range_m": [0.5, -math.inf]}) == {"range_m": [0.5, None],
                                                       "range_m_infinite": [None, "-inf"]}
    assert jsonable({"x_s": math.nan}) == {"x_s": None}  # NaN: not defined, no flag


def test_json_keys_carry_units_by_the_coordinate(porter, shaft):
    """Every load-change key names its unit, the configuration's by the seam (rad for the
    shaft's angle, m for the Porter's ball radius); eq. 28's coefficients and the classic
    effort, power and friction band with theirs."""
    p, s = (r.to_dict() for r in (porter, shaft))
    lc = p["load_changes"][0]
    assert {"over_regulation_m", "over_regulation_scaled_m"} <= set(lc)
    assert set(lc["initial_state"]) == {"xi_m", "xi_dot_m_s", "xi_ddot_m_s2"}
    assert set(lc["response"]) == {"t_s", "xi_m"}
    assert set(lc["coefficients"]) == {"a0_kg", "a1_N_s_per_m", "a2_N_per_m", "a3_N_per_m_s"}
    assert not [k for k in lc if k.endswith("_rad")]
    # a0 = I in kg: the Porter's generalised inertia at the new equilibrium
    from govopt.analysis import statics

    inertia = float(statics.inertia(porter.spec, porter.spring, lc["radius_to_m"]))
    assert lc["coefficients"]["a0_kg"] == pytest.approx(inertia, rel=1e-12)
    assert lc["radius_to_m"] == pytest.approx(0.23)  # the seam's json_coordinate
    assert set(s["load_changes"][0]["coefficients"]) == {
        "a0_kg_m2", "a1_N_m_s_per_rad", "a2_N_m_per_rad", "a3_N_m_per_rad_s"}
    assert "over_regulation_rad" in s["load_changes"][0]
    assert {"effort_N", "power_J", "friction_band_N"} <= set(p["classic"])
    assert {"effort_N_m", "power_J", "friction_band_N_m"} <= set(s["classic"])
    assert not {"effort", "power", "effort_unit", "power_unit"} & set(p["classic"])


def test_json_writes_each_section_once(designed):
    """The design's checks are its constraints: one list, once (was also 'constraints'); the
    objective and the continuous bound with the objective's unit in their keys."""
    d = designed.to_dict()
    lists = [k for k, v in d.items() if isinstance(v, list) and v and isinstance(v[0], dict)
             and {"name", "limit", "sense"} <= set(v[0])]
    assert lists == ["checks"] and "constraints" not in d
    o = d["optimisation"]  # the optimiser's record: the value and its unit, fields of their own
    assert o["objective"]["unit"] == "kg" and "value" not in o["objective"]
    # The default verdict is now "made": the made (robust) search proves no continuous bound,
    # and says so; the continuous bound is the nominal search's, checked on the nominal verdict.
    assert o["bound"] is None and o["claim"].startswith("no certified bound")
    spec = govopt.load_spec(SPECS / "hamabe-design.toml")
    n = govopt.design(dataclasses.replace(spec, verdict="nominal")).to_dict()["optimisation"]
    assert n["objective"]["unit"] == "kg" and n["value"] >= n["bound"]


# ------------------------------------------------------------------------------------------
# the answer first


@pytest.mark.parametrize("which", ["shaft", "designed", "porter"])
def test_the_answer_comes_first_and_fits_a_screen(request, which):
    """The default report opens with the verdict (all checks pass, or which fail with their
    margins), then the design, and fits a screen; every failing and binding check is among
    the checks it shows."""
    res = request.getfixturevalue(which)
    text = format_summary(res, colour=False)
    lines = text.splitlines()
    assert len(lines) <= 70, len(lines)
    verdict = lines[lines.index("Verdict") + 1]
    failed = [c for c in res.checks if not c.passed]
    assert verdict.startswith("FAIL" if failed else "PASS"), verdict
    for c in failed:
        assert check_name(c, res) in verdict
    assert lines.index("Verdict") < lines.index("Design")
    assert not any(x.startswith("Characteristic (") for x in lines)  # on request only
    shown = {r[0] for r in _rows(text, next(x for x in lines if x.startswith("Checks to watch")))}
    for c in res.checks:
        if not c.passed or c.active:
            assert check_name(c, res) in shown
    assert "--full" in lines[-1]


def test_the_k2_margin_says_what_its_limit_is(designed):
    """'k^2 > 0' held to a margin (limit k2_margin omega0^2 > 0) is named by that margin, not
    shown as '> 0' beside a limit of 31.58."""
    c = designed.check("k^2 > 0 (stability)")
    assert c.limit > 0
    name = check_name(c, designed)
    assert "> 0" not in name
    ratio = float(re.search(r">= ([\d.]+) omega0\^2", name)[1])
    assert ratio == pytest.approx(c.limit / designed.omega_reference ** 2, rel=1e-2)


def test_no_empty_rows_and_no_unit_after_a_word(designed):
    """A properties table shows no row whose values are all blank (no dash-pot without an
    engine), and 'none modelled' is never followed by a unit."""
    import copy

    res = copy.copy(designed)
    res.optimisation = copy.deepcopy(designed.optimisation)
    key = next(k for k in res.optimisation["design"] if k.startswith("dashpot_N"))
    res.optimisation["design"][key] = None
    text = format_result(res, colour=False)
    rows = _rows(text, "Chosen design")
    assert rows and all(len(r) == 3 for r in rows), rows
    assert not any(r[0] == "dashpot" for r in rows)
    assert "none modelled Hz" not in text
