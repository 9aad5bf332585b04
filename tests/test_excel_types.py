"""Every governor type's workbook: the generic Design sheet (live formulas in the masses and the
spring on the Model sheet's constants of the linkage at the range's ends) recalculated by
LibreOffice agrees with govopt's own values to 1e-9, for each bundled evaluate spec and each
type's optimised design."""

import tomllib
from pathlib import Path

import openpyxl
import pytest
from test_excel import RTOL, _csv_values, _formula_cells, _recalculate, needs_libreoffice

import govopt
from govopt.report import excel

SPECS = Path(__file__).resolve().parent.parent / "specs"
_ALL = {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted(SPECS.glob("*.toml"))}
#: evaluate specs of every type but the shaft (whose sheet test_excel.py checks cell by cell)
EVALUATE = [n for n, d in _ALL.items() if "design" in d and d["governor"]["type"] != "shaft"]
#: one design spec per type
DESIGN = [n for n, d in _ALL.items() if n.endswith("-design") and "design" not in d
          and d["governor"]["type"] != "shaft"]


@pytest.fixture(scope="module")
def results():
    out = {n: govopt.evaluate(govopt.load_spec(SPECS / f"{n}.toml")) for n in EVALUATE}
    out.update({n: govopt.design(govopt.load_spec(SPECS / f"{n}.toml")) for n in DESIGN})
    return out


@pytest.fixture(scope="module")
def written(results, tmp_path_factory):
    d = tmp_path_factory.mktemp("types")
    return {n: excel.write_workbook(r, d / f"{n}.xlsx") for n, r in results.items()}


@pytest.fixture(scope="module")
def opened(written):
    """name -> the written workbook as openpyxl reads it, loaded once (two tests read each)."""
    cache = {}

    def load(name):
        if name not in cache:
            cache[name] = openpyxl.load_workbook(written[name])
        return cache[name]

    return load


@pytest.fixture(scope="module")
def recalculated(written, tmp_path_factory):
    """name -> the Design sheet's values after LibreOffice recalculated the whole workbook
    (every workbook in one call), or None without soffice."""
    if needs_libreoffice.args[0]:  # no soffice: the written workbooks only
        return None
    d = tmp_path_factory.mktemp("types-lo")
    out = _recalculate(list(written.values()), d / "out", d / "profile",
                       sheet=("Design", excel.SHEETS.index("Design") + 1))
    return {n: _csv_values(out[p]) for n, p in written.items()}


def test_every_type_has_specs():
    types = {d["governor"]["type"] for d in _ALL.values()}
    assert {"shaft", "watt", "porter", "proell", "hartnell", "spring_loaded",
            "spring_gravity"} <= types
    assert {_ALL[n]["governor"]["type"] for n in DESIGN} >= {
        "watt", "porter", "proell", "hartnell", "spring_loaded", "spring_gravity",
        "traction_coil", "traction_leaf"}


@pytest.mark.parametrize("name", EVALUATE + DESIGN)
def test_design_sheet_is_live(opened, recalculated, name):
    """Every formula of the Design sheet has govopt's value beside it; after LibreOffice
    recalculates, each equals it to RTOL (1e-9)."""
    ws = opened(name)["Design"]
    cells = [c for c in _formula_cells(ws) if c.column == excel.VALUE]
    assert len(cells) >= 5  # masses, speeds at both ends, rpm (and the spring's figures)
    assert any("omega_inner" in (ws.cell(c.row, excel.NAME).value or "") for c in cells)
    if recalculated is None:
        pytest.skip("LibreOffice not available")
    values = recalculated[name]
    for c in cells:
        want = ws.cell(c.row, excel.GOVOPT).value
        got = values.get((c.row, c.column))
        assert isinstance(got, float | int), (c.coordinate, got)
        assert got == pytest.approx(want, rel=RTOL, abs=1e-12), ws.cell(c.row, excel.NAME).value


@pytest.mark.parametrize("name", DESIGN)
def test_designs_pass_every_check(results, name):
    """`govopt design` on each type's design spec returns a design that passes every check
    when re-evaluated from the spec (issue: one seam for every governor)."""
    res = results[name]
    assert res.optimisation["status"] == "optimal"
    spec = govopt.load_spec(SPECS / f"{name}.toml").with_design(res.design)
    again = govopt.evaluate(spec)
    failing = [c.name for c in again.checks if not c.passed]
    assert failing == []
    assert again.statics.omega[0] == pytest.approx(res.statics.omega[0], rel=1e-12)


@pytest.mark.parametrize("name", EVALUATE + DESIGN)
def test_workbook_reads_in_engineering_units(opened, results, name):
    """Every number a person reads on the Design, Characteristic and Checks sheets has a
    display format and an engineering unit (mm, MPa, N/mm, rpm, deg: no Pa, m, rad/s); the
    seam's constants on the Model sheet, labelled in words, its spring terms only where the type
    has a spring; every cell aligned at the top; the characteristic's chart draws the spec's
    required band and, where friction acts, the opening and closing speeds."""
    res = results[name]
    wb = opened(name)
    for ws in (wb["Design"], wb["Characteristic"], wb["Checks"]):
        for row in ws.iter_rows():
            for c in row:
                if isinstance(c.value, float):
                    assert c.number_format != "General", (ws.title, c.coordinate)
    design = wb["Design"]
    rows = range(2, design.max_row + 1)
    units = {design.cell(r, excel.UNIT).value for r in rows} - {None}
    assert not units & {"Pa", "m", "rad/s", "N/m", "rad"}, units
    assert "rpm" in units
    model = wb["Model"]
    symbols = {model.cell(r, 2).value for r in range(2, model.max_row + 1)}
    assert ("A_F_i" in symbols) == (res.spec.governor.spring is not None)
    assert {"cf_m_i", "lv_m_a"} <= symbols
    assert not {"cf_m_i", "lv_m_a"} & {design.cell(r, 2).value for r in rows}  # internals apart
    labels = {model.cell(r, 2).value: model.cell(r, 1).value for r in range(2, model.max_row)}
    assert labels["cf_m_i"].startswith("dead loads' pull per kg of")
    assert all(c.alignment.vertical == "top" for row in design.iter_rows(min_row=2) for c in row
               if c.value is not None)
    spec_units = {r[4] for r in wb["Spec"].iter_rows(min_row=3, values_only=True)} - {None, ""}
    assert not spec_units & {"Pa", "m", "rad/s", "N/m", "rad"}, spec_units
    head = [c.value for c in wb["Characteristic"][1]]
    assert not any(h and ("(m)" in h or "(Pa)" in h or "(rad)" in h) for h in head), head
    ((chart, _),) = excel.layout(excel.build_workbook(res)["Characteristic"]).charts
    friction = res.friction_speeds[0] is not None
    assert ("opening speed (rising against friction) (rpm)" in head) == friction
    assert len(chart.series) == (3 if res.spec.speed is not None else 1) + 2 * friction


@pytest.mark.parametrize("name", ["hartnell-design", "porter-design", "traction-leaf-design"])
def test_the_drawing_is_at_equal_scales(results, name):
    """The Summary's drawing of the governor is at equal scales across and up, so its balls are
    circles, as the PNG draws them: the chart's plot area is written as the axes' own rectangle
    (its layout the chart's, which openpyxl writes into the plot area), and its axes give as
    many mm per cm of that rectangle each way."""
    wb = excel.build_workbook(results[name])
    chart = next(c for c, _ in excel.layout(wb["Summary"]).charts
                 if c.title.tx.rich.p[0].r[0].t.startswith("Drawn to scale"))
    m = chart.layout.manualLayout
    assert m.layoutTarget == "inner" and chart.plot_area.layout is None  # written from layout
    across = (chart.x_axis.scaling.max - chart.x_axis.scaling.min) / (m.w * chart.width)
    up = (chart.y_axis.scaling.max - chart.y_axis.scaling.min) / (m.h * chart.height)
    assert across == pytest.approx(up, rel=1e-9)
