"""The Excel workbook: structure, text safety, atomic write, and live formulas recalculated by
LibreOffice headless and compared with govopt's own numbers."""

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
from govopt.verdict import SHOWN, Check

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "govopt" / "specs"
#: The bundled shaft-governor specs with a given design to evaluate (the shaft's Design sheet has
#: its own named geometry cells; every other type's sheet is tested in test_excel_types.py).
def _in_checks(value: float, check: Check) -> float:
    """A check's value or limit as the Checks sheet shows it (MPa, mm, deg: the units people
    read; the same product the sheet's formula takes)."""
    from govopt.report import sections

    return sections.shown(value, check.unit, only=excel.SHOWN_IN_CHECKS)[0]


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
    label = design.cell(row, excel._SI_UNIT).value
    return next((f for unit, (_, f) in SHOWN.items() if excel._unit_label(unit) == label), 1.0)


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
    on load: xlsx -> xlsx, or with ``sheet`` (one of excel.SHEETS) that sheet's recalculated
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
                  f"{excel.SHEETS.index(sheet) + 1}")
        out = {f: outdir / f"{f.stem}-{sheet}.csv" for f in files}
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
                                               "value_kg": 2.5},
            "continuous_bound": {"objective_kg": 2.4, "wire_diameter_m": 0.0161,
                                 "shear_stress_Pa": 3.9e8},
            "gap": 2.5 / 2.4 - 1, "notes": ["a note from the optimiser"],
            "search": {"springs": 3, "combinations": 1574370},
            "design": {"wire_diameter_m": 0.0165, "coil_radius_m": 0.058, "active_turns": 7.5,
                       "dashpot_N_m_s_per_rad": 4.04,
                       "dashpot_feasible_range_N_m_s_per_rad": [0.229, float("inf")]},
            "sensitivities": [{"requirement": "allowable shear stress k_s", "change_percent": 1.0,
                               "objective_change_percent": -0.33, "text": "..."}],
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
    shown = wb[sheet].cell(wb[sheet][ref].row, excel._VALUE)  # the input, in mm
    assert shown.value == pytest.approx(17.0)
    shown.value = 16.0
    files["edited"] = d / "hamabe-a-d16.xlsx"
    wb.save(files["edited"])
    files["text"] = excel.write_workbook(_text_result(d), d / "text.xlsx")
    files["dynamics"] = excel.write_workbook(_fake_dynamics(results["hamabe-a"]),
                                             d / "dynamics.xlsx")
    # cached results twice govopt's: LibreOffice must recompute every formula, not show these
    wb = excel.build_workbook(results["hamabe-a"])
    wb._govopt_cached = {k: 2.0 * v if isinstance(v, float) and v else 7.0
                         for k, v in wb._govopt_cached.items()}
    files["poisoned"] = d / "poisoned.xlsx"
    excel._atomic_save(wb, files["poisoned"])
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
    assert tuple(wb.sheetnames) == excel.SHEETS
    for ws in wb.worksheets:
        assert ws.freeze_panes, ws.title
    assert len(wb["Characteristic"]._charts) == 1
    assert len(wb["Dynamics"]._charts) >= 1  # k^2 against omega0^2

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
        shown = design.cell(cell.row, excel._VALUE)
        assert cell.column == excel._SI and cell.data_type == "f", n
        assert cell.value.startswith(f"={shown.coordinate}"), n
        assert shown.data_type == "n", n
        assert shown.fill.fgColor.rgb.endswith("FFF2CC"), n
    for n in formulas:
        cell = design[names[n][1]]
        assert cell.data_type == "f" and cell.value.startswith("="), n
    sd = res.spring
    for n, v, unit in (("wire_diameter", sd.d, "mm"), ("coil_radius", sd.r, "mm"),
                       ("turns", sd.n, "-"), ("free_half_length", sd.l0, "mm"),
                       ("pendulum_weight", sd.m * 9.80665, "N")):
        row = design[names[n][1]].row
        assert design.cell(row, excel._UNIT).value == unit
        assert design.cell(row, excel._VALUE).value == pytest.approx(
            v * _factor(design, row), rel=1e-15)
    dashpot = design.cell(design[names["dashpot"][1]].row, excel._VALUE)
    assert (dashpot.value is None) == (res.design.dashpot is None)
    # a person reads engineering units: no Pa, m or rad/s in the value column's units
    units = {design.cell(r, excel._UNIT).value for r in range(2, design.max_row + 1)}
    assert not units & {"Pa", "m", "rad/s", "N/m", "rad"}, units
    assert {"MPa", "mm", "rpm"} <= units

    # every formula cell carries govopt's value as its cached result (issue 13, item 2: was
    # empty; test_formula_cells_carry_govopts_values checks the values): the recalculation
    # tests below make LibreOffice recompute, and the poisoned cache proves that it does
    values = _read(workbooks[name], data_only=True)
    for ws in wb.worksheets:
        for c in _formula_cells(ws):
            if c.column == 8 and ws.title == "Checks":
                continue  # 'binding': an empty text when not binding
            assert values[ws.title][c.coordinate].value is not None, (ws.title, c.coordinate)

    checks = wb["Checks"]
    rules = [r for cf in checks.conditional_formatting for r in cf.rules]
    assert len(rules) >= 2
    assert [checks.cell(i + 2, 1).value for i in range(len(res.checks))] == \
        [c.name for c in res.checks]

    notes = {r[0]: r[1] for r in wb["Notes"].iter_rows(values_only=True) if r[0]}
    assert notes["govopt version"] == govopt.__version__
    assert notes["analysis.geometry"] == res.spec.analysis.geometry
    assert notes["material.stress_correction"] == res.spec.material.stress_correction
    assert {"Hamabe eq. 1", "Hamabe eq. 12", "Hamabe eqs. 18-20", "Hamabe eq. 28",
            "Hamabe eq. 32", "Hamabe eqs. 16-23", "Wahl 1944"} <= set(notes)

    spec_rows = list(wb["Spec"].iter_rows(min_row=2, max_row=len(res.spec.entries) + 1,
                                          values_only=True))
    assert [(r[0], r[1]) for r in spec_rows] == [(e.key, e.written) for e in res.spec.entries]

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
    spec = {r[0].value: r[1] for r in wb["Spec"].iter_rows(min_row=2) if r[0].value}
    for key, text in (("name", "=SUM(2,3)"), ("description", "=1+1")):
        assert spec[key].value == text and spec[key].data_type == "s"
    notes = {r[0].value: r[1] for r in wb["Notes"].iter_rows() if r[0].value}
    assert notes["spec name"].value == "=SUM(2,3)" and notes["spec name"].data_type == "s"
    assert wb["Notes"]["A1"].data_type == "s"


def _table_below(ws, title: str) -> list[list]:
    """The rows (header first) of the table titled ``title`` in column A, up to a blank row;
    its notes (text in column A alone) left out; the printed columns A-L only."""
    rows = [[c.value for c in r] for r in ws.iter_rows(max_col=12)]
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
    """Issue 13, item 2: the Dynamics sheet and the Checks sheet's optimisation block are tables
    with named columns and units (they were a raw dump of dicts: JSON keys as headers, roots as
    Python complex text, 'stable' as 1, 'inf'): roots in real and imaginary columns, words for
    booleans and infinities, charts with unit-bearing axis titles and distinct colours. (This
    test replaces the one that asserted the old dump's cells.)"""
    res = _fake_dynamics(results["hamabe-a"])
    real, unstable = res.dynamics["load_changes"]
    built = excel.build_workbook(res)
    charts = built["Dynamics"]._charts
    # k^2, the two load changes' responses and the forced vibration over one revolution
    assert len(charts) == 4
    for chart in charts:
        for axis in (chart.x_axis, chart.y_axis):
            assert re.search(r"\(.+\)$", _title_text(axis.title)), _title_text(axis.title)
            assert axis.tickLblPos == "low"  # the labels off the curve when an axis crosses it
    k2 = charts[0].series
    colours = [s.graphicalProperties.line.solidFill.srgbClr for s in k2]
    assert len(colours) == 2 and colours[0] != colours[1]  # k^2 and omega0^2 told apart

    wb = openpyxl.load_workbook(excel.write_workbook(res, tmp_path / "d.xlsx"))
    dyn = wb["Dynamics"]
    lc = _table_below(dyn, "Load changes (Hamabe Part III, eq. 28; Hurwitz eq. 32)")
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
    assert row["Hurwitz margin 9 a1 a2 / (a0 a3) - 1 (eq. 32)"][1] == pytest.approx(
        real["hurwitz_margin"], rel=1e-15)

    roots = _table_below(dyn, "Roots of eq. 28: xi ~ exp(s t)")
    assert roots[0] == ["load change", "root", "real part (1/s)", "imaginary part (1/s)",
                        "time constant -1/Re (s)", "period 2 pi/|Im| (s)", *roots[0][6:]]
    # openpyxl writes numbers with 16 significant digits ("%.16g")
    assert [r[:2] for r in roots[1:]] == [["unloading", k] for k in (1, 2, 3)] + [
        ["unstable copy", k] for k in (1, 2, 3)]
    np.testing.assert_allclose([r[2:4] for r in roots[1:]], [
        *real["roots_per_s"], [0.75, 4.0], [0.75, -4.0], [-7.25, 0.0]], rtol=1e-15, atol=0)
    growing = roots[4]
    assert growing[4] == pytest.approx(-1 / 0.75) and growing[5] == pytest.approx(math.pi / 2)
    assert roots[1][5] is None  # a real root has no period

    vib = _table_below(dyn, "Forced vibration under the valve gear (Hamabe Part II, eqs. 16-23)")
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

    checks = wb["Checks"]
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
        if isinstance(c.value, float) and c.row > len(res.checks) + 1:
            assert width[c.column_letter] >= len(f"{c.value:.5g}") + 2, c.coordinate
    labels = [r[0] for r in _table_below(checks, "Optimisation (govopt design)")]
    assert width["A"] >= max(len(s) for s in labels)


@pytest.mark.parametrize("name", ["hamabe-a", "alt"])
def test_every_sheet_has_a_print_setup(workbooks, results, name):
    """Issue 13, item 2: every sheet prints to the page width (as many pages down as needed),
    landscape where wide, within a print area that holds its charts; issue 23: the rows repeated
    on each page are the header of the table that runs onto another page (the Spring sheet's
    list: its title and header, rows 1-2), the sheet's title where no table does and row 1 is a
    title, none where row 1 is the header of a table that ends on the first page (Checks)."""
    wb = _read(workbooks[name])
    for ws in wb.worksheets:
        ps = ws.page_setup
        assert ws.sheet_properties.pageSetUpPr.fitToPage, ws.title
        assert (ps.fitToWidth, ps.fitToHeight) == (1, 0), ws.title
    titles = {ws.title: ws.print_title_rows for ws in wb.worksheets}
    assert titles["Spring"] == "$1:$2" and titles["Characteristic"] == "$1:$1"
    assert titles["Dynamics"] == titles["Notes"] == "$1:$1"  # a title row, no table's header
    assert len(wb["Checks"].row_breaks.brk) == 0 and titles["Checks"] is None
    for ws in wb.worksheets:
        assert ws.print_area.startswith(f"'{ws.title}'!$A$1:"), ws.title
    assert wb["Design"].page_setup.orientation == "landscape"  # eight columns with notes
    assert wb["Spec"].page_setup.orientation == "portrait"  # four columns
    # every chart lies inside its sheet's print area
    built = excel.build_workbook(results[name])
    for ws in built.worksheets:
        cols, rows = re.search(r"\$([A-Z]+)\$(\d+)$", ws.print_area).groups()
        for chart in ws._charts:
            c, r = excel._extent(ws, chart.anchor, chart.width, chart.height)
            assert c <= openpyxl.utils.column_index_from_string(cols) and r <= int(rows)


def test_formula_cells_carry_govopts_values(workbooks, results):
    """Issue 13, item 2: readers that do not recalculate (pandas, previewers) see govopt's value
    of every formula: it is stored as the formula's cached result."""
    import pandas as pd

    res = results["hamabe-a"]
    path = workbooks["hamabe-a"]
    wf = _read(path)
    wv = _read(path, data_only=True)
    names = {ref: n for n, (sheet, ref) in _named_cells(wf).items() if sheet == "Design"}
    expected = _expected(res)
    n = 0
    for c in _formula_cells(wf["Design"]):
        got = wv["Design"][c.coordinate].value
        name = names.get(wf["Design"].cell(c.row, excel._SI).coordinate)
        if c.column == excel._SI and name in expected:
            assert got == expected[name], name  # exactly
        elif c.column == excel._SI:  # an input's SI value
            shown = wv["Design"].cell(c.row, excel._VALUE).value or 0.0  # blank: 0
            assert got == pytest.approx(shown / _factor(wf["Design"], c.row), rel=1e-15), name
        elif c.column == excel._VALUE:  # the formula's value as shown
            assert got == expected[name] * _factor(wf["Design"], c.row), name
        else:  # the relative difference to govopt's value beside it
            assert got == 0.0
        n += 1
    for c in _formula_cells(wf["Checks"]):
        check = res.checks[c.row - 2]
        want = {2: _in_checks(check.value, check), 4: _in_checks(check.limit, check),
                6: check.margin, 7: "PASS" if check.passed else "FAIL",
                8: "yes" if check.active else None}
        assert wv["Checks"][c.coordinate].value == want[c.column], (check.name, c.column)
        n += 1
    assert n > 40
    design = pd.read_excel(path, sheet_name="Design", header=0)
    row = design.index[design["defined name"] == "stiffness"][0]
    assert design.loc[row, "value (SI)"] == pytest.approx(res.spring.kappa, rel=1e-15)


def test_cli_writes_workbook(tmp_path):
    from clirun import invoke


    out = tmp_path / "cli.xlsx"
    run = invoke(["evaluate", str(SPECS / "hamabe-b.toml"), "--xlsx", str(out)])
    assert run.exit_code == 0, run.output
    assert tuple(openpyxl.load_workbook(out).sheetnames) == excel.SHEETS
    assert os.listdir(tmp_path) == ["cli.xlsx"]


# ------------------------------------------------------------------------------------------
# atomic write


@pytest.mark.parametrize("existing", [False, True])
def test_atomic_write_builder_failure(tmp_path, results, monkeypatch, existing):
    target = tmp_path / "w.xlsx"
    if existing:
        target.write_bytes(b"previous")

    def boom(*args, **kwargs):
        raise RuntimeError("builder failed midway")

    monkeypatch.setattr(excel, "_build_checks", boom)
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
    assert openpyxl.load_workbook(target).sheetnames[0] == "Spec"
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


def _compare_all_formulas(written: Path, recalculated: Path, res, *, design_only=False,
                          check_reldiff=True) -> float:
    """Compare every formula cell's recalculated value with govopt; returns the worst
    relative difference."""
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
        name = names.get(design.cell(c.row, excel._SI).coordinate)
        if c.column == excel._SI and name not in expected:  # an input, converted to SI
            shown = wv["Design"].cell(c.row, excel._VALUE).value or 0.0
            assert got == pytest.approx(shown / _factor(design, c.row), rel=1e-14), name
            compared += 1
        elif c.column in (excel._SI, excel._VALUE):  # a named formula, in SI and shown
            want = expected[name] * (_factor(design, c.row) if c.column == excel._VALUE else 1)
            worst = max(worst, _rel(got, want))
            assert got == pytest.approx(want, rel=RTOL, abs=0), name
            compared += 1
        elif c.column == excel._RELDIFF:  # relative difference to govopt's value beside it
            if check_reldiff:
                assert abs(got) <= RTOL, c.coordinate
            compared += 1
    if not design_only:
        checks = wf["Checks"]
        for c in _formula_cells(checks):
            total += 1
            check = res.checks[c.row - 2]
            got = wv["Checks"][c.coordinate].value
            want = {2: _in_checks(check.value, check), 4: _in_checks(check.limit, check),
                    6: check.margin, 7: "PASS" if check.passed else "FAIL",
                    8: "yes" if check.active else None}[c.column]
            if isinstance(want, float):
                worst = max(worst, _rel(got, want))
                assert got == pytest.approx(want, rel=RTOL, abs=1e-12), (check.name, c.column)
            else:
                assert got == want, (check.name, c.column)
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
    res = results["hamabe-a"]
    written, out = recalculated["edited"]
    # govopt for the changed design, with the workbook's free half length (an input cell)
    design = dataclasses.replace(res.spec.design, wire_diameter=0.016,
                                 free_half_length=res.spring.l0)
    new = govopt.evaluate(res.spec, design)
    assert new.spring.kappa < 0.8 * res.spring.kappa
    worst = _compare_all_formulas(written, out, new, design_only=True, check_reldiff=False)
    print(f"edited: worst relative difference LibreOffice vs govopt {worst:.2e}")
    wv = _read(out, data_only=True)
    names = _named_cells(wv)

    def value(n):
        sheet, ref = names[n]
        return wv[sheet][ref].value

    assert value("stiffness") == pytest.approx(new.spring.kappa, rel=RTOL)
    assert value("max_shear_stress") == pytest.approx(new.max_stress, rel=RTOL)
    assert value("irregularity") == pytest.approx(new.irregularity, rel=RTOL)
    # the live checks follow the edit too
    checks = wv["Checks"]
    for i, c in enumerate(new.checks, start=2):
        if c.name in ("shear stress", "irregularity"):
            assert checks.cell(i, 6).value == pytest.approx(c.margin, rel=RTOL, abs=1e-12)
            assert checks.cell(i, 7).value == ("PASS" if c.passed else "FAIL")


@pytest.mark.libreoffice
@needs_libreoffice
def test_libreoffice_keeps_formula_like_text(recalculated):
    written, out = recalculated["text"]
    for path in (written, out):
        wb = _read(path)
        spec = {r[0].value: r[1] for r in wb["Spec"].iter_rows(min_row=2) if r[0].value}
        assert spec["description"].value == "=1+1" and spec["description"].data_type == "s"
        assert spec["name"].value == "=SUM(2,3)" and spec["name"].data_type == "s"
    values = _read(out, data_only=True)["Spec"]
    assert [r[1] for r in values.iter_rows(min_row=2, max_row=3, values_only=True)] == \
        ["=SUM(2,3)", "=1+1"]


@pytest.mark.libreoffice
@needs_libreoffice
def test_libreoffice_dynamics_and_optimiser_checks(recalculated, results):
    res = _fake_dynamics(results["hamabe-a"])
    written, out = recalculated["dynamics"]
    wb = _read(out, data_only=True)
    assert tuple(wb.sheetnames) == excel.SHEETS
    cells = [c.value for r in wb["Dynamics"].iter_rows() for c in r if c.value is not None]
    # the Hurwitz margin under its name in the load changes' table (was the JSON key
    # 'hurwitz_margin' of the raw dump, issue 13 item 2), with LibreOffice's words intact
    assert {"Hurwitz margin 9 a1 a2 / (a0 a3) - 1 (eq. 32)", "never", "unbounded"} <= set(cells)
    # a check limit that is not the spec's own is written as a number, not linked to the input
    checks = _read(written)["Checks"]
    assert checks["B2"].value == "=max_shear_stress" and checks["D2"].data_type == "n"
    assert checks["D4"].data_type == "n"
    worst = _compare_all_formulas(written, out, res)
    assert [r[6] for r in wb["Checks"].iter_rows(min_row=2, max_row=5, values_only=True)] == \
        ["FAIL", "FAIL", "PASS", "PASS"]
    assert wb["Checks"]["H5"].value == "yes"
    print(f"dynamics: worst relative difference LibreOffice vs govopt {worst:.2e}")


@pytest.mark.libreoffice
@needs_libreoffice
def test_libreoffice_recomputes_cached_values(recalculated, results):
    """The cached results written with the formulas are readers' convenience, never the numbers
    the recalculation tests compare: written twice govopt's value (7 for a zero or a word),
    LibreOffice's recalculation still gives govopt's."""
    written, out = recalculated["poisoned"]
    cached = _read(written, data_only=True)
    sheet, ref = _named_cells(cached)["stiffness"]
    assert cached[sheet][ref].value == 2 * results["hamabe-a"].spring.kappa  # poisoned
    worst = _compare_all_formulas(written, out, results["hamabe-a"])
    print(f"poisoned: worst relative difference LibreOffice vs govopt {worst:.2e}")


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
    """Printing (issue 23): a break never splits a kept block that fits on a page (it moves up
    to the block's first row); a block longer than a page is split; the repeated first row is
    counted on every page after the first."""
    ws = openpyxl.Workbook().active
    for r in range(1, 121):
        ws.cell(r, 1, r)
    height = 50 * excel._ROW_PT * 96 / 72 / excel._PAGE_FILL  # 50 default rows a page
    excel._keep(ws, 40, 70)  # 31 rows: would straddle the first page's end (row 50)
    excel._paginate(ws, 120, height)
    breaks = [b.id for b in ws.row_breaks.brk]
    assert breaks[0] == 39  # the block starts the second page
    assert breaks[1] == 39 + 49  # 49 rows under the repeated first row
    ws2 = openpyxl.Workbook().active
    excel._keep(ws2, 10, 80)  # longer than a page: split where the page ends
    excel._paginate(ws2, 120, height)
    assert [b.id for b in ws2.row_breaks.brk][0] == 50


def test_characteristic_chart_shares_its_page(results):
    """The characteristic's chart is printed with the table's last rows, never alone under the
    repeated header: the page break (if any) falls at least five rows above the chart."""
    for name in ("hamabe-a", "hamabe-b"):
        wb = excel.build_workbook(results[name])
        ws = wb["Characteristic"]
        n = len(results[name].statics.alpha)
        (chart,) = ws._charts
        assert chart.anchor == f"B{n + 3}"  # under the table
        assert all(b.id <= n + 1 - 5 for b in ws.row_breaks.brk), [b.id for b in ws.row_breaks.brk]
