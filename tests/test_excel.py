"""The Excel workbook: structure, text safety, atomic write, and live formulas recalculated by
LibreOffice headless and compared with govopt's own numbers (the shaft governor's Design sheet,
cell by cell; every other type's in test_excel_types.py; the record's pages in
test_workbook_record.py)."""

from __future__ import annotations

import csv
import dataclasses
import functools
import math
import os
import re
import shutil
import stat
import subprocess
import tomllib
from pathlib import Path

import numpy as np
import openpyxl
import pytest

import govopt
from govopt.errors import GovoptError
from govopt.report import excel
from govopt.report.excel.book import ROW_PT, Sheet, paginate, unit_label
from govopt.verdict import SHOWN, Check

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"
#: The bundled shaft-governor specs with a given design to evaluate (the shaft's Design sheet has
#: its own named geometry cells; every other type's sheet is tested in test_excel_types.py).
BUNDLED = sorted(p.stem for p in SPECS.glob("*.toml")
                 if "design" in (d := tomllib.loads(p.read_text(encoding="utf-8")))
                 and d["governor"]["type"] == "shaft")
SOFFICE = shutil.which("soffice") or shutil.which("libreoffice")
needs_libreoffice = pytest.mark.skipif(SOFFICE is None, reason="LibreOffice (soffice) not on PATH")

#: Workbooks recalculated by LibreOffice (about a second each): the paper's cases a, c, d' and
#: the other fidelity branches (the rest of the bundled specs differ only in numbers).
RECALCULATED = ("hamabe-a", "hamabe-c", "hamabe-d-prime", "alt")

#: Relative tolerance between LibreOffice's recalculation and govopt.
RTOL = 1e-9

#: Forces LibreOffice to recalculate every formula on load, whatever cached values say.
_RECALC_ALWAYS = """<?xml version="1.0" encoding="UTF-8"?>
<oor:items xmlns:oor="http://openoffice.org/2001/registry"
 xmlns:xs="http://www.w3.org/2001/XMLSchema" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
<item oor:path="/org.openoffice.Office.Calc/Formula/Load"><prop oor:name="OOXMLRecalcMode" \
oor:op="fuse"><value>0</value></prop></item>
<item oor:path="/org.openoffice.Office.Calc/Formula/Load"><prop oor:name="ODFRecalcMode" \
oor:op="fuse"><value>0</value></prop></item>
</oor:items>
"""


# ------------------------------------------------------------------------------------------
# helpers


def _alt_spec():
    """hamabe-a with the other fidelity branches (series geometry, reaction at the mean speed,
    Wahl correction), a fixed free length and inertia, and neither dash-pot nor engine."""
    data = tomllib.loads((SPECS / "hamabe-a.toml").read_text())
    data["name"] = "hamabe-a-alt"
    data["analysis"] = {"geometry": "series", "reaction_speed": "mean"}
    data["material"]["stress_correction"] = "wahl"
    design = data["design"]
    del design["dashpot_a1"]
    design["free_half_length"] = "130 mm"
    design["pendulum_inertia"] = "0.19 kg*m^2"
    del data["engine"], data["load_change"]
    return govopt.parse_spec(data, "hamabe-a-alt.toml")


def _expected(res) -> dict[str, float]:
    """govopt's own value of every named formula cell of the Design sheet."""
    st, sd, sp = res.statics, res.spring, res.spring_properties
    mat, speed = res.spec.material, res.spec.speed
    out = {
        "pendulum_mass": sd.m, "stiffness": sd.kappa, "spring_index": sp["spring_index"],
        "wahl_factor": sp["wahl_factor"], "max_shear_stress": res.max_stress,
        "stress_utilisation": res.max_stress / mat.allowable_shear_stress,
        "spring_mass": sp["mass_kg"], "surge_frequency": sp["surge_frequency_Hz"],
        "body_length": sp["body_length_m"], "irregularity": res.irregularity,
        "irregularity_utilisation": res.irregularity / speed.irregularity,
    }
    for tag, i in (("inner", 0), ("outer", -1)):
        out[f"half_length_{tag}"] = st.extra["half length l"][0][i]
        out[f"spring_force_{tag}"] = st.spring_force[i]
        out[f"shear_stress_{tag}"] = st.stress[i]
        out[f"spring_moment_{tag}"] = st.M_f[i]
        out[f"omega_{tag}"] = st.omega[i]
        out[f"rpm_{tag}"] = st.omega[i] * 30.0 / math.pi
    if res.design.flying_inertia is None:
        out["pendulum_inertia"] = sd.inertia
    return {k: float(v) for k, v in out.items()}


def _factor(design, row: int) -> float:
    """The factor from the Design sheet's SI value of ``row`` to the value shown beside it
    (govopt.verdict.SHOWN by the row's SI unit; 1 where it is shown in SI)."""
    label = design.cell(row, excel.SI_UNIT).value
    return next((f for unit, (_, f) in SHOWN.items() if unit_label(unit) == label), 1.0)


def _named_cells(wb) -> dict[str, tuple[str, str]]:
    out = {}
    for name, dn in wb.defined_names.items():
        (sheet, ref), = list(dn.destinations)
        out[name] = (sheet, ref.replace("$", ""))
    return out


@functools.cache
def _read(path: Path, data_only: bool = False):
    """``openpyxl.load_workbook(path, data_only=data_only)`` once per file and mode: several
    tests read the same workbook (the fixtures' and LibreOffice's), none changes it."""
    return openpyxl.load_workbook(path, data_only=data_only)


def _formula_cells(ws):
    return [c for row in ws.iter_rows() for c in row if c.data_type == "f"]


def _recalculate(files: list[Path], outdir: Path, profile: Path,
                 sheet: str | None = None, pdf: bool = False) -> dict[Path, Path]:
    """Convert ``files`` with LibreOffice headless (one process), recalculating every formula
    on load: xlsx -> xlsx, or with ``sheet`` (``(name, number)``: a sheet's name and its place
    in the workbook, from 1) that sheet's recalculated
    values alone as CSV (``<stem>-<sheet>.csv``, read by :func:`_csv_values`; LibreOffice
    writes no workbook, a third of the time), or with ``pdf`` the workbooks as printed
    (``<stem>.pdf``); returns {input: output}."""
    (profile / "user").mkdir(parents=True, exist_ok=True)
    (profile / "user" / "registrymodifications.xcu").write_text(_RECALC_ALWAYS)
    if pdf:
        target, out = "pdf", {f: outdir / f"{f.stem}.pdf" for f in files}
    elif sheet is None:
        target, out = "xlsx:Calc MS Excel 2007 XML", {f: outdir / f.name for f in files}
    else:  # UTF-8, values not as shown (all 15 digits LibreOffice keeps), the sheet's number
        target = ("csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,false,"
                  f"{sheet[1]}")
        out = {f: outdir / f"{f.stem}-{sheet[0]}.csv" for f in files}
    cmd = [SOFFICE, f"-env:UserInstallation={profile.as_uri()}", "--headless", "--norestore",
           "--nologo", "--convert-to", target, "--outdir", str(outdir), *map(str, files)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=240,
                          env={**os.environ, "SAL_USE_VCLPLUGIN": "svp"})
    missing = [str(f) for f, o in out.items() if not o.exists()]
    assert not missing, f"LibreOffice did not convert {missing}:\n{proc.stdout}\n{proc.stderr}"
    return out


def _csv_values(path: Path) -> dict[tuple[int, int], float | str]:
    """{(row, column): value} of a sheet LibreOffice wrote as CSV (:func:`_recalculate` with
    ``sheet``), 1-based like openpyxl's cells; a number as a float, anything else (an error such
    as Err:502 or #REF!, a text) as its text."""
    with path.open(encoding="utf-8", newline="") as f:
        rows = list(csv.reader(f))
    number = re.compile(r"-?\d+(\.\d*)?([eE][-+]?\d+)?")
    return {(r, c): float(v) if number.fullmatch(v) else v
            for r, row in enumerate(rows, start=1) for c, v in enumerate(row, start=1) if v}


def _rel(got: float, want: float) -> float:
    return abs(got - want) / abs(want) if want != 0 else abs(got)


# ------------------------------------------------------------------------------------------
# fixtures


@pytest.fixture(scope="module")
def results():
    out = {name: govopt.evaluate(govopt.load_spec(SPECS / f"{name}.toml")) for name in BUNDLED}
    out["alt"] = govopt.evaluate(_alt_spec())
    return out


@pytest.fixture(scope="module")
def workbooks(results, tmp_path_factory):
    d = tmp_path_factory.mktemp("xlsx")
    return {name: excel.write_workbook(res, d / f"{name}.xlsx") for name, res in results.items()}


def _fake_dynamics(res):
    """``res`` with its own dynamics (a real load change and the forced vibration) and, beside
    them, an unstable copy of the load change (complex roots, every figure infinite), a key no
    table declares, and an optimiser's record and checks."""
    real = res.dynamics["load_changes"][0]
    unstable = {**real, "name": "unstable copy", "stable": np.bool_(False), "kind": "complex",
                "roots_per_s": [[0.75, 4.0], [0.75, -4.0], [-7.25, 0.0]],
                "over_regulation_rad": float("inf"), "over_regulates": True,
                "first_arrival_time_s": float("inf"), "settling_time_s": float("inf")}
    return dataclasses.replace(
        res,
        dynamics={**res.dynamics, "load_changes": [real, unstable],
                  "free_response": {"t_s": [0.0, 1.0], "xi_rad": [0.05, 0.01]}},
        optimisation={
            "status": "optimal", "objective": {"name": "moving_mass", "unit": "kg",
                                               "sense": "minimise"},
            "value": 2.5, "bound": 2.4,
            "bound_design": {"wire_diameter_m": 0.0161, "shear_stress_Pa": 3.9e8},
            "gap": 2.5 / 2.4 - 1, "notes": ["a note from the optimiser"],
            "search": {"springs": 3, "combinations": 1574370},
            "design": {"wire_diameter_m": 0.0165, "coil_radius_m": 0.058, "active_turns": 7.5,
                       "dashpot_N_m_s_per_rad": 4.04,
                       "dashpot_feasible_range_N_m_s_per_rad": [0.229, float("inf")]},
            "sensitivities": {"allowable shear stress k_s": -0.33},
        },
        kind="optimisation",
        # an optimiser's checks: a tighter stress limit and k^2 margin than the spec's own
        checks=[
            Check("shear stress", res.max_stress, 0.9 * res.spec.material.allowable_shear_stress,
                  "<="),
            Check("irregularity", res.irregularity, res.spec.speed.irregularity, "<="),
            Check("k^2 < omega0^2 (no resonance)", float(np.max(res.k2)),
                  0.95 * res.spec.speed.omega_mean**2, "<="),
            Check("pendulum mass >= min", res.spring.m, res.spring.m, ">="),
        ],
    )


@pytest.fixture(scope="module")
def recalculated(results, workbooks, tmp_path_factory):
    """All the workbooks, an edited one and two special ones, recalculated in one LibreOffice
    run. Returns {key: (written path, LibreOffice output path)}."""
    d = tmp_path_factory.mktemp("lo")
    files = {name: workbooks[name] for name in RECALCULATED}
    # the design edited in the workbook: wire diameter 17 mm -> 16 mm
    wb = openpyxl.load_workbook(workbooks["hamabe-a"])
    sheet, ref = _named_cells(wb)["wire_diameter"]
    shown = wb[sheet].cell(wb[sheet][ref].row, excel.VALUE)  # the input, in mm
    assert shown.value == pytest.approx(17.0)
    shown.value = 16.0
    files["edited"] = d / "hamabe-a-d16.xlsx"
    wb.save(files["edited"])
    files["text"] = excel.write_workbook(_text_result(d), d / "text.xlsx")
    files["dynamics"] = excel.write_workbook(_fake_dynamics(results["hamabe-a"]),
                                             d / "dynamics.xlsx")
    out = _recalculate(list(files.values()), d / "out", d / "profile")
    return {k: (f, out[f]) for k, f in files.items()}


def _text_result(d: Path):
    text = (SPECS / "hamabe-a.toml").read_text()
    text = text.replace('name = "hamabe-a"', 'name = "=SUM(2,3)"', 1)
    text = text.replace('description = "Hamabe Example 1, case a: W = 12 kgf, irregularity '
                        '0.12"', 'description = "=1+1"', 1)
    path = d / "formula-like.toml"
    path.write_text(text)
    spec = govopt.load_spec(path)
    assert (spec.name, spec.entries[1].written) == ("=SUM(2,3)", "=1+1")
    return govopt.evaluate(spec)


# ------------------------------------------------------------------------------------------
# structure (openpyxl only)


@pytest.mark.parametrize("name", [*BUNDLED, "alt"])
def test_sheets_charts_and_names(workbooks, results, name):
    res = results[name]
    wb = _read(workbooks[name])
    # a shaft has a spring; an evaluation has no optimiser's record
    assert tuple(wb.sheetnames) == excel.sheets(res) == tuple(
        s for s in excel.SHEETS if s != "Optimisation")
    built = excel.build_workbook(res)
    charts = {ws.title: len(excel.layout(ws).charts) for ws in built.worksheets}
    assert charts["Characteristic"] == 1 and charts["Dynamics"] >= 1  # k^2 against omega0^2
    assert charts["Summary"] == 2  # the characteristic and the governor drawn
    for title in ("Design", "Checks", "Characteristic", "Model"):
        assert wb[title].freeze_panes, title

    names = _named_cells(wb)
    inputs = {"wire_diameter", "coil_radius", "turns", "free_half_length", "pendulum_weight",
              "std_gravity", "dashpot", "friction_moment", "shear_modulus", "allowable_stress",
              "density", "link_a", "link_rho", "link_b", "alpha_inner", "alpha_normal",
              "alpha_outer", "omega_mean", "irregularity_required", "reaction_cf_inner",
              "reaction_ci_inner", "reaction_cf_outer", "reaction_ci_outer"}
    if res.design.flying_inertia is not None:
        inputs.add("pendulum_inertia")
    formulas = set(_expected(res))
    assert set(names) == inputs | formulas
    design = wb["Design"]
    for n in inputs:  # the name is the SI cell converting the yellow input beside it
        sheet, ref = names[n]
        assert sheet == "Design"
        cell = design[ref]
        shown = design.cell(cell.row, excel.VALUE)
        assert cell.column == excel.SI and cell.data_type == "f", n
        assert cell.value.startswith(f"={shown.coordinate}"), n
        assert shown.data_type == "n", n
        assert shown.fill.fgColor.rgb.endswith("FFF2CC"), n
    expected = _expected(res)
    for n in formulas:  # a formula beside govopt's own value, in the unit shown
        cell = design[names[n][1]]
        assert cell.data_type == "f" and cell.value.startswith("="), n
        govopt_value = design.cell(cell.row, excel.GOVOPT).value
        assert govopt_value == pytest.approx(expected[n] * _factor(design, cell.row),
                                             rel=1e-15), n
    sd = res.spring
    for n, v, unit in (("wire_diameter", sd.d, "mm"), ("coil_radius", sd.r, "mm"),
                       ("turns", sd.n, "-"), ("free_half_length", sd.l0, "mm"),
                       ("pendulum_weight", sd.m * 9.80665, "N")):
        row = design[names[n][1]].row
        assert design.cell(row, excel.UNIT).value == unit
        assert design.cell(row, excel.VALUE).value == pytest.approx(
            v * _factor(design, row), rel=1e-15)
    dashpot = design.cell(design[names["dashpot"][1]].row, excel.VALUE)
    assert (dashpot.value is None) == (res.design.dashpot is None)
    # a person reads engineering units: no Pa, m or rad/s in the value column's units
    units = {design.cell(r, excel.UNIT).value for r in range(2, design.max_row + 1)}
    assert not units & {"Pa", "m", "rad/s", "N/m", "rad"}, units
    assert {"MPa", "mm", "rpm"} <= units

    checks = wb["Checks"]
    rules = [r for cf in checks.conditional_formatting for r in cf.rules]
    assert len(rules) >= 2
    assert [checks.cell(i + 2, 1).value for i in range(len(res.checks))] == \
        [c.name for c in res.checks]
    # the checks are govopt's numbers (a reader that does not recalculate sees them all)
    assert not _formula_cells(checks)
    for i, c in enumerate(res.checks, start=2):
        assert checks.cell(i, 7).value == ("PASS" if c.passed else "FAIL")
        assert checks.cell(i, 6).value == pytest.approx(c.margin, rel=1e-15)
        assert checks.cell(i, 9).value == c.source

    method = [[c.value for c in r] for r in wb["Method"].iter_rows()]
    cited = {r[3] for r in method if isinstance(r[3], str)}
    dynamic = ("Hamabe eq. 28", "Hamabe eq. 32", "Hamabe eqs. 13-22")
    for where in ("Hamabe eq. 1", "Hamabe eq. 12", "Hamabe eqs. 18-20", *dynamic):
        # the load change and the forced vibration only with the engine's data
        assert any(c.startswith(where) for c in cited) == (
            where not in dynamic or res.spec.engine is not None), where
    settings = {r[0]: r[3] for r in method if isinstance(r[0], str) and r[0].startswith(
        ("analysis.", "material."))}
    assert settings["analysis.geometry"] == res.spec.analysis.geometry
    assert settings["material.stress_correction"] == res.spec.material.stress_correction
    keys = {r[0] for r in method}
    assert {"hamabe", "wahl", "en15800"} <= keys
    assert any(r[0] == "hamabe" and "Disturbing Actions of a Shaft Governor" in str(r[1])
               for r in method)

    spec_rows = list(wb["Spec"].iter_rows(min_row=3, max_row=len(res.spec.entries) + 2,
                                          values_only=True))
    assert [(r[0], r[2]) for r in spec_rows] == [(e.key, e.written) for e in res.spec.entries]

    text = [c.value for r in wb["Dynamics"].iter_rows() for c in r if isinstance(c.value, str)]
    if not res.dynamics:
        note = next(t for t in text if t.startswith("Dynamics were not run"))
        assert ("no [engine]" in note) == (res.spec.engine is None)


def test_characteristic_table_matches_result(workbooks, results):
    res = results["hamabe-a"]
    ws = _read(workbooks["hamabe-a"])["Characteristic"]
    head = [c.value for c in ws[1]]
    assert head[:4] == ["alpha (deg)", "omega (rad/s)", "speed (rpm)", "M_z (N m)"]
    col = {h: i for i, h in enumerate(head)}
    rows = list(ws.iter_rows(min_row=2, values_only=True))
    assert len(rows) == len(res.statics.alpha)
    st = res.statics
    # openpyxl writes numbers with 16 significant digits ("%.16g")
    for head, want in (("omega (rad/s)", st.omega), ("shear stress tau (MPa)", st.stress / 1e6),
                       ("k^2 (1/s^2)", res.k2), ("M_r0 (N m)", st.M_r0),
                       ("alpha (deg)", np.degrees(st.alpha))):
        np.testing.assert_allclose([r[col[head]] for r in rows], want, rtol=1e-15, atol=0)
    np.testing.assert_allclose([r[col["speed (rpm)"]] for r in rows], st.omega * 30 / math.pi,
                               rtol=1e-15)


def test_formula_like_text_stays_text(tmp_path):
    path = excel.write_workbook(_text_result(tmp_path), tmp_path / "t.xlsx")
    wb = openpyxl.load_workbook(path)
    spec = {r[0].value: r[2] for r in wb["Spec"].iter_rows(min_row=3) if r[0].value}
    for key, text in (("name", "=SUM(2,3)"), ("description", "=1+1")):
        assert spec[key].value == text and spec[key].data_type == "s"
    title = wb["Summary"]["A1"]
    assert title.value == "govopt evaluation: =SUM(2,3)" and title.data_type == "s"
    assert wb["Method"]["A1"].data_type == "s"


def _table_below(ws, title: str) -> list[list]:
    """The rows (header first) of the table titled ``title`` in column A, up to a blank row;
    its notes (text in column A alone) left out; the printed columns only (a chart's data
    beside them are not the table's)."""
    last = openpyxl.utils.column_index_from_string(
        re.search(r":\$?([A-Z]+)", ws.print_area).group(1))
    rows = [[c.value for c in r] for r in ws.iter_rows(max_col=last)]
    i = next(k for k, r in enumerate(rows) if r[0] == title)
    out = []
    for r in rows[i + 1:]:
        if all(v is None for v in r):
            break
        if any(v is not None for v in r[1:]):
            out.append(r)
    return out


def _title_text(title) -> str:
    return "".join(r.t for p in title.tx.rich.p for r in (p.r or []))


def test_dynamics_and_optimisation_are_tables(tmp_path, results):
    """The Dynamics sheet and the Checks sheet's optimisation block are tables
    with named columns and units (they were a raw dump of dicts: JSON keys as headers, roots as
    Python complex text, 'stable' as 1, 'inf'): roots in real and imaginary columns, words for
    booleans and infinities, charts with unit-bearing axis titles and distinct colours. (This
    test replaces the one that asserted the old dump's cells.)"""
    res = _fake_dynamics(results["hamabe-a"])
    real, unstable = res.dynamics["load_changes"]
    built = excel.build_workbook(res)
    charts = [c for c, _ in excel.layout(built["Dynamics"]).charts]
    # the two load changes' responses, the forced vibration over one revolution, k^2 (last)
    assert len(charts) == 4
    for chart in charts:
        for axis in (chart.x_axis, chart.y_axis):
            assert re.search(r"\(.+\)$", _title_text(axis.title)), _title_text(axis.title)
            assert axis.tickLblPos == "low"  # the labels off the curve when an axis crosses it
    k2 = charts[-1].series
    colours = [s.graphicalProperties.line.solidFill.srgbClr for s in k2]
    assert len(colours) == 2 and colours[0] != colours[1]  # k^2 and omega0^2 told apart

    wb = openpyxl.load_workbook(excel.write_workbook(res, tmp_path / "d.xlsx"))
    dyn = wb["Dynamics"]
    lc = _table_below(dyn, "Load changes (Hamabe eq. 28, eq. 32; Vyshnegradsky 1877)")
    assert lc[0][:4] == ["quantity", "unit", "unloading", "unstable copy"]
    row = {r[0]: r[1:4] for r in lc[1:]}
    assert row["stable"] == ["", "yes", "no"] or row["stable"] == [None, "yes", "no"]
    assert row["over-regulates (any t >= 0)"][1:] == ["no", "yes"]
    assert row["over-regulation (past the new equilibrium)"] == ["deg", 0.0, "unbounded"]
    assert row["first arrival at the new equilibrium"] == ["s", "never", "never"]  # aperiodic
    assert row["settling time (2 % band)"][0] == "s"
    assert row["settling time (2 % band)"][1] == pytest.approx(real["settling_time_s"],
                                                              rel=1e-15)
    assert row["settling time (2 % band)"][2] == "never"
    assert row["alpha after (new equilibrium)"][1] == pytest.approx(real["alpha_to_deg"])
    assert row["Hurwitz margin 9 a1 a2 / (a0 a3) - 1 (Hamabe eq. 32)"][1] == pytest.approx(
        real["hurwitz_margin"], rel=1e-15)

    roots = _table_below(dyn, "Roots of the load-change cubic (Hamabe eq. 28): xi ~ exp(s t)")
    assert roots[0] == ["load change", "root", "real part (1/s)", "imaginary part (1/s)",
                        "time constant -1/Re (s)", "period 2 pi / |Im| (s)", *roots[0][6:]]
    # openpyxl writes numbers with 16 significant digits ("%.16g")
    assert [r[:2] for r in roots[1:]] == [["unloading", k] for k in (1, 2, 3)] + [
        ["unstable copy", k] for k in (1, 2, 3)]
    np.testing.assert_allclose([r[2:4] for r in roots[1:]], [
        *real["roots_per_s"], [0.75, 4.0], [0.75, -4.0], [-7.25, 0.0]], rtol=1e-15, atol=0)
    growing = roots[4]
    assert growing[4] == pytest.approx(-1 / 0.75) and growing[5] == pytest.approx(math.pi / 2)
    assert roots[1][5] is None  # a real root has no period

    vib = _table_below(dyn, "Forced vibration (Hamabe eqs. 13-22, eq. 23)")
    v = {r[0]: r[1:3] for r in vib[1:]}
    assert v["peak-to-peak swing"] == ["deg", pytest.approx(
        math.degrees(res.dynamics["vibration"]["peak_to_peak_rad"]), rel=1e-14)]
    assert v["resonance"][1] == "no"

    other = _table_below(dyn, "Other dynamics results (as recorded)")
    assert other[1][:3] == ["free response", None, '{"t_s": [0.0, 1.0], "xi_rad": [0.05, 0.01]}']

    texts = [c.value for r in dyn.iter_rows() for c in r if isinstance(c.value, str)]
    assert not [t for t in texts if t in ("inf", "-inf", "nan", "True", "False")
                or re.fullmatch(r"\(?[-+0-9.e]+[-+][0-9.e]+j\)?", t)]
    for r in dyn.iter_rows():
        for c in r:
            assert not isinstance(c.value, bool), c.coordinate  # words, not 1/0 or TRUE

    checks = wb["Optimisation"]  # the optimiser's record on a sheet of its own
    opt = {r[0]: r[1:3] for r in _table_below(checks, "Optimisation (govopt design)")[1:]}
    assert opt["objective: moving mass"] == ["kg", 2.5]
    assert opt["continuous bound (GP relaxation)"] == ["kg", 2.4]
    assert opt["gap to the bound"] == ["%", pytest.approx(100 * (2.5 / 2.4 - 1))]
    assert opt["combinations searched"][1] == 1574370
    chosen = {r[0]: r[1:3] for r in _table_below(checks, "Chosen design")[1:]}
    assert chosen["wire diameter"] == ["mm", pytest.approx(16.5)]
    assert chosen["dashpot feasible range to"] == ["N m s/rad", "no upper end found"]
    sens = _table_below(checks, "Sensitivities: +1 % on a requirement")
    assert sens[0][:3] == ["requirement", "change (%)", "objective change (%)"]
    assert sens[1][:3] == ["allowable shear stress k_s", 1.0, -0.33]
    cells = [c for r in checks.iter_rows() for c in r if c.value is not None]
    assert "constraints" not in {c.value for c in cells}
    # no '###' and no cut-off labels: every column is wider than what it shows
    width = {k: d.width for k, d in checks.column_dimensions.items()}
    for c in cells:
        if isinstance(c.value, float):
            assert width[c.column_letter] >= len(f"{c.value:.5g}") + 2, c.coordinate
    labels = [r[0] for r in _table_below(checks, "Optimisation (govopt design)")]
    assert width["A"] >= max(len(s) for s in labels)


@pytest.mark.parametrize("name", ["hamabe-a", "alt"])
def test_every_sheet_has_a_print_setup(workbooks, results, name):
    """Every sheet prints at a fixed scale of at least 80 % where it has a chart, 73 % where it
    has none (its text never under 8 pt: the smallest font times the scale), landscape where
    wide, within a print area that holds its charts (the record's sheets; the others' print
    area a blank row below their cells, until asked for), the design named at the top of every
    page and "page x of y" at the foot; the rows repeated on each page are the header of the
    table that runs onto another page (the Spring sheet's record: its header row), none where
    no table does (Checks)."""
    wb = _read(workbooks[name])
    built = excel.build_workbook(results[name])
    for ws in wb.worksheets:
        ps, sheet = ws.page_setup, excel.layout(built[ws.title])
        assert not ws.sheet_properties.pageSetUpPr.fitToPage, ws.title
        least = excel.book.MIN_SCALE if sheet.charts else 73
        assert least <= ps.scale <= 100, ws.title
        assert ws.oddHeader.left.text == f"govopt evaluation: {results[name].spec.name}"
        assert ws.oddFooter.center.text == "&A, page &P of &N"
        if ws.title in excel.PRINTED:
            assert ws.print_area.startswith(f"'{ws.title}'!$A$1:"), ws.title
        else:
            last = int(re.search(r"(\d+)$", sheet.area).group(1))
            assert re.fullmatch(rf"'{ws.title}'!\$A\${last + 2}:\$[A-Z]+\${last + 2}",
                                ws.print_area), (ws.title, ws.print_area)
    titles = {ws.title: ws.print_title_rows for ws in wb.worksheets}
    assert len(wb["Checks"].row_breaks.brk) == 0 and titles["Checks"] is None
    assert wb["Design"].page_setup.orientation == "landscape"  # seven columns with notes
    # every chart lies inside its sheet's print area (as asked for); no cell prints under 8 pt
    for ws in built.worksheets:
        sheet = excel.layout(ws)
        assert excel.printed_font(sheet) >= 8.0, ws.title
        cols, rows = re.search(r"([A-Z]+)(\d+)$", sheet.area).groups()
        for chart, anchor in sheet.charts:
            c, r = excel.extent(sheet, anchor, chart.width, chart.height)
            assert c <= openpyxl.utils.column_index_from_string(cols) and r <= int(rows)


def test_formulas_sit_beside_govopts_values(workbooks, results):
    """The workbook is written through openpyxl's public API, which stores a formula without
    a cached result: a reader that does not recalculate (pandas, a previewer) reads govopt's
    value of each live formula in the Design sheet's 'govopt value' column beside it, and
    every other sheet holds govopt's numbers, not formulas."""
    import pandas as pd

    res = results["hamabe-a"]
    path = workbooks["hamabe-a"]
    wf = _read(path)
    names = {ref: n for n, (sheet, ref) in _named_cells(wf).items() if sheet == "Design"}
    expected = _expected(res)
    n = 0
    for c in _formula_cells(wf["Design"]):
        if c.column != excel.VALUE:
            continue
        name = names.get(wf["Design"].cell(c.row, excel.SI).coordinate)
        beside = wf["Design"].cell(c.row, excel.GOVOPT).value
        if name in expected:
            assert beside == pytest.approx(expected[name] * _factor(wf["Design"], c.row),
                                           rel=1e-15), name
            n += 1
    assert n == len(expected)
    for ws in wf.worksheets:
        if ws.title not in ("Design", "Model"):
            assert not _formula_cells(ws), ws.title
    design = pd.read_excel(path, sheet_name="Design", header=0)
    row = design.index[design["defined name"] == "stiffness"][0]
    assert design.loc[row, "govopt value"] == pytest.approx(res.spring.kappa / 1e3, rel=1e-15)


def test_cli_writes_workbook(tmp_path):
    from clirun import invoke


    out = tmp_path / "cli.xlsx"
    run = invoke(["evaluate", str(SPECS / "hamabe-b.toml"), "--xlsx", str(out)])
    assert run.exit_code == 0, run.output
    assert tuple(openpyxl.load_workbook(out).sheetnames) == tuple(
        s for s in excel.SHEETS if s != "Optimisation")
    assert os.listdir(tmp_path) == ["cli.xlsx"]
    command = openpyxl.load_workbook(out)["Summary"]["B3"].value  # the record says who wrote it
    assert "hamabe-b.toml" in command and str(out) in command


# ------------------------------------------------------------------------------------------
# atomic write


@pytest.mark.parametrize("existing", [False, True])
def test_atomic_write_builder_failure(tmp_path, results, monkeypatch, existing):
    target = tmp_path / "w.xlsx"
    if existing:
        target.write_bytes(b"previous")

    def boom(*args, **kwargs):
        raise RuntimeError("builder failed midway")

    monkeypatch.setattr(excel, "build_checks", boom)
    with pytest.raises(RuntimeError, match="midway"):
        excel.write_workbook(results["hamabe-a"], target)
    assert os.listdir(tmp_path) == (["w.xlsx"] if existing else [])
    if existing:
        assert target.read_bytes() == b"previous"


@pytest.mark.parametrize("existing", [False, True])
def test_atomic_write_save_failure(tmp_path, results, monkeypatch, existing):
    target = tmp_path / "w.xlsx"
    if existing:
        target.write_bytes(b"previous")

    def partial_save(self, filename):
        Path(filename).write_bytes(b"PK\x03\x04 partial")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(openpyxl.Workbook, "save", partial_save)
    with pytest.raises(GovoptError, match="cannot write workbook"):
        excel.write_workbook(results["hamabe-a"], target)
    assert os.listdir(tmp_path) == (["w.xlsx"] if existing else [])
    if existing:
        assert target.read_bytes() == b"previous"


def test_atomic_write_replaces_and_reports_bad_directory(tmp_path, results):
    target = tmp_path / "w.xlsx"
    target.write_bytes(b"previous")
    target.chmod(0o640)
    assert excel.write_workbook(results["hamabe-a"], str(target)) == target
    assert openpyxl.load_workbook(target).sheetnames[0] == "Summary"
    assert os.listdir(tmp_path) == ["w.xlsx"]
    assert stat.S_IMODE(target.stat().st_mode) == 0o640  # the replaced file's permissions
    umask = os.umask(0o022)
    os.umask(umask)
    fresh = excel.write_workbook(results["hamabe-a"], tmp_path / "new.xlsx")
    assert stat.S_IMODE(fresh.stat().st_mode) == 0o666 & ~umask  # not mkstemp's 0600
    with pytest.raises(GovoptError, match="cannot write workbook"):
        excel.write_workbook(results["hamabe-a"], tmp_path / "missing" / "w.xlsx")


# ------------------------------------------------------------------------------------------
# recalculation by a real spreadsheet engine


def _compare_all_formulas(written: Path, recalculated: Path, res, *,
                          check_reldiff=True) -> float:
    """Compare every formula cell of the Design sheet (the workbook's only live cells) as
    LibreOffice recalculated it with govopt; returns the worst relative difference."""
    wf = _read(written)
    wv = _read(recalculated, data_only=True)
    expected = _expected(res)
    names = {ref: n for n, (sheet, ref) in _named_cells(wf).items() if sheet == "Design"}
    worst, compared, total = 0.0, 0, 0
    design = wf["Design"]
    for c in _formula_cells(design):
        total += 1
        got = wv["Design"][c.coordinate].value
        assert isinstance(got, float | int) and not isinstance(got, bool), (c.coordinate, got)
        name = names.get(design.cell(c.row, excel.SI).coordinate)
        if c.column == excel.SI and name not in expected:  # an input, converted to SI
            shown = wv["Design"].cell(c.row, excel.VALUE).value or 0.0
            assert got == pytest.approx(shown / _factor(design, c.row), rel=1e-14), name
            compared += 1
        elif c.column in (excel.SI, excel.VALUE):  # a named formula, in SI and shown
            want = expected[name] * (_factor(design, c.row) if c.column == excel.VALUE else 1)
            worst = max(worst, _rel(got, want))
            assert got == pytest.approx(want, rel=RTOL, abs=0), name
            compared += 1
        elif c.column == excel.RELDIFF:  # relative difference to govopt's value beside it
            if check_reldiff:
                assert abs(got) <= RTOL, c.coordinate
            compared += 1
    assert compared == total and total > 0
    return worst


@pytest.mark.libreoffice
@needs_libreoffice
@pytest.mark.parametrize("name", RECALCULATED)
def test_libreoffice_recalculation_matches_govopt(recalculated, results, name):
    written, out = recalculated[name]
    worst = _compare_all_formulas(written, out, results[name])
    print(f"{name}: worst relative difference LibreOffice vs govopt {worst:.2e}")


@pytest.mark.libreoffice
@needs_libreoffice
def test_libreoffice_recalculates_edited_input(recalculated, results):
    """An edited input (the wire diameter) moves every live formula to govopt's numbers for the
    edited design, the stress and irregularity utilisations (the live checks) with them."""
    res = results["hamabe-a"]
    written, out = recalculated["edited"]
    # govopt for the changed design, with the workbook's free half length (an input cell)
    design = dataclasses.replace(res.spec.design, wire_diameter=0.016,
                                 free_half_length=res.spring.l0)
    new = govopt.evaluate(res.spec, design)
    assert new.spring.kappa < 0.8 * res.spring.kappa
    worst = _compare_all_formulas(written, out, new, check_reldiff=False)
    print(f"edited: worst relative difference LibreOffice vs govopt {worst:.2e}")
    wv = _read(out, data_only=True)
    names = _named_cells(wv)

    def value(n):
        sheet, ref = names[n]
        return wv[sheet][ref].value

    assert value("stiffness") == pytest.approx(new.spring.kappa, rel=RTOL)
    assert value("max_shear_stress") == pytest.approx(new.max_stress, rel=RTOL)
    assert value("irregularity") == pytest.approx(new.irregularity, rel=RTOL)
    stress, irregularity = new.check("shear stress"), new.check("irregularity")
    assert value("stress_utilisation") == pytest.approx(stress.value / stress.limit, rel=RTOL)
    assert value("irregularity_utilisation") == pytest.approx(
        irregularity.value / irregularity.limit, rel=RTOL)
    assert (value("stress_utilisation") <= 1) == stress.passed


@pytest.mark.libreoffice
@needs_libreoffice
def test_libreoffice_keeps_formula_like_text(recalculated):
    written, out = recalculated["text"]
    for path in (written, out):
        wb = _read(path)
        spec = {r[0].value: r[2] for r in wb["Spec"].iter_rows(min_row=3) if r[0].value}
        assert spec["description"].value == "=1+1" and spec["description"].data_type == "s"
        assert spec["name"].value == "=SUM(2,3)" and spec["name"].data_type == "s"
    values = _read(out, data_only=True)["Spec"]
    assert [r[2] for r in values.iter_rows(min_row=3, max_row=4, values_only=True)] == \
        ["=SUM(2,3)", "=1+1"]


@pytest.mark.libreoffice
@needs_libreoffice
def test_libreoffice_dynamics_and_optimiser_checks(recalculated, results):
    res = _fake_dynamics(results["hamabe-a"])
    written, out = recalculated["dynamics"]
    wb = _read(out, data_only=True)
    assert tuple(wb.sheetnames) == excel.SHEETS
    cells = [c.value for r in wb["Dynamics"].iter_rows() for c in r if c.value is not None]
    # the Hurwitz margin under its name in the load changes' table, with LibreOffice's words
    # intact
    assert {"Hurwitz margin 9 a1 a2 / (a0 a3) - 1 (Hamabe eq. 32)", "never",
            "unbounded"} <= set(cells)
    worst = _compare_all_formulas(written, out, res)
    # the optimiser's checks as govopt decided them: its own limits, numbers not links
    assert [r[6] for r in wb["Checks"].iter_rows(min_row=2, max_row=5, values_only=True)] == \
        ["FAIL", "FAIL", "PASS", "PASS"]
    assert wb["Checks"]["E2"].value == pytest.approx(  # a check without a unit: as it is
        0.9 * res.spec.material.allowable_shear_stress, rel=1e-12)
    assert wb["Checks"]["H5"].value == "yes"
    print(f"dynamics: worst relative difference LibreOffice vs govopt {worst:.2e}")


def test_spring_sheet_reads_in_engineering_units(tmp_path):
    """The Spring sheet (the spring maker's): lengths in mm, rate in N/mm, stresses in MPa,
    each number with a display format (not 0.236953566747573 m or 345207690.444161 Pa)."""
    res = govopt.evaluate(govopt.load_spec(SPECS / "hamabe-a.toml"))
    wb = openpyxl.load_workbook(excel.write_workbook(res, tmp_path / "s.xlsx"))
    rows = {str(r[0].value).strip(): r for r in wb["Spring"].iter_rows() if r[0].value}
    sheet = res.spring_report.to_dict()["sheet"]
    for label, key, unit, factor in (("free length", "free_length_m", "mm", 1e3),
                                     ("rate", "rate_N_per_m", "N/mm", 1e-3),
                                     ("wire diameter", "wire_diameter_m", "mm", 1e3)):
        value, shown_unit = rows[label][1], rows[label][2]
        assert shown_unit.value == unit
        assert value.value == pytest.approx(sheet[key] * factor, rel=1e-12)
        assert value.number_format != "General"
    units = {r[2].value for r in rows.values() if r[2].value}
    assert not units & {"m", "Pa", "N/m", "rad/s"}, units


def test_page_breaks_keep_blocks_together():
    """Printing: a break never splits a kept block that fits on a page (it moves up
    to the block's first row); a block longer than a page is split; the repeated first row is
    counted on every page after the first."""
    from govopt.report.excel.book import PAGE_FILL

    sheet = Sheet(openpyxl.Workbook().active)
    for r in range(1, 121):
        sheet.put(r, 1, r)
    height = 50 * ROW_PT * 96 / 72 / PAGE_FILL  # 50 default rows a page
    sheet.keep(40, 70)  # 31 rows: would straddle the first page's end (row 50)
    paginate(sheet, 120, height)
    breaks = [b.id for b in sheet.ws.row_breaks.brk]
    assert breaks[0] == 39  # the block starts the second page
    assert breaks[1] == 39 + 50  # no table repeats its header: 50 rows
    sheet.keep_table(91, 95)  # a table from row 91: its title and header repeat after it
    sheet.ws.row_breaks.brk = []
    paginate(sheet, 120, height)
    # 48 rows under its title and header
    assert [b.id for b in sheet.ws.row_breaks.brk][:2] == [39, 39 + 48]
    other = Sheet(openpyxl.Workbook().active)
    other.keep(10, 80)  # longer than a page: split where the page ends
    paginate(other, 120, height)
    assert [b.id for b in other.ws.row_breaks.brk][0] == 50


def test_characteristic_chart_shares_its_page(results):
    """The characteristic's chart is printed with the table's last rows, never alone under the
    repeated header: the page break (if any) falls at least five rows above the chart."""
    for name in ("hamabe-a", "hamabe-b"):
        wb = excel.build_workbook(results[name])
        ws = wb["Characteristic"]
        n = len(results[name].statics.alpha)
        ((chart, anchor),) = excel.layout(ws).charts
        assert anchor == f"B{n + 3}"  # under the table
        assert all(b.id <= n + 1 - 5 for b in ws.row_breaks.brk), [b.id for b in ws.row_breaks.brk]
