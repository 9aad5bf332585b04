"""A study's database as other tools read it: one typed column per input, figure and check, the
units in ``columns``, a ``format_version``; resumed only by a govopt that computes it alike;
never a ``-wal``/``-shm`` file left; every way it cannot be used said in one line."""

import math
import re
import shutil
import sqlite3
import subprocess
from pathlib import Path

import hostile
import numpy as np
import pandas as pd
import pytest

import govopt
from govopt.study import FORMAT_VERSION, Store, load_study, run_study

SPECS = Path(__file__).resolve().parent.parent / "specs"
STUDY = SPECS / "studies" / "hamabe-study.toml"
CASE_A = SPECS / "hamabe-a.toml"


@pytest.fixture(scope="module")
def hamabe_db(tmp_path_factory) -> Path:
    """Hamabe's Example 1 as a study (five cases, zipped), in a database."""
    db = tmp_path_factory.mktemp("h") / "h.db"
    run_study(load_study(STUDY), db)
    return db


def _journal_files(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(("-wal", "-shm",
                                                                        "-journal")))


# ---------------------------------------------------------------------------------------------
# a table other tools read


def test_sqlite3_and_pandas_read_named_columns(hamabe_db):
    """The acceptance queries: the sqlite3 shell selects a figure by its name, pandas reads
    the table with named, typed columns."""
    if shutil.which("sqlite3"):
        out = subprocess.run(["sqlite3", hamabe_db, "select irregularity from points where "
                              "status = 'pass' limit 3"], capture_output=True, text=True,
                             check=True).stdout.split()
    else:  # the same query through Python's sqlite3
        with sqlite3.connect(f"file:{hamabe_db}?mode=ro", uri=True) as con:
            out = [str(v) for (v,) in con.execute(
                "select irregularity from points where status = 'pass' limit 3")]
    con = sqlite3.connect(f"file:{hamabe_db}?mode=ro", uri=True)
    try:
        frame = pd.read_sql("select * from points", con)
        columns = pd.read_sql("select * from columns", con).set_index("name")
        types = dict(con.execute("select name, type from pragma_table_info('points')")
                     .fetchall())
    finally:
        con.close()
    passing = frame.loc[frame["status"] == "pass", "irregularity"]
    assert [float(v) for v in out] == pytest.approx(list(passing[:3]), rel=1e-12)
    assert len(frame) == 5 and frame["point"].tolist() == [0, 1, 2, 3, 4]
    assert {"status", "message", "design_pendulum_weight", "omega_inner", "stiffness",
            "margin_irregularity", "passed_irregularity", "value_shear_stress",
            "objective_value"} <= set(frame.columns)
    assert frame["omega_inner"].dtype == float and frame["design_active_turns"].dtype == int
    assert types["omega_inner"] == "REAL" and types["passed_irregularity"] == "INTEGER"
    assert types["status"] == "TEXT" and types["stability"] == "TEXT"
    assert set(frame["passed_irregularity"].dropna()) <= {0, 1}
    # every column of points is described, in order, and only those
    assert list(columns.index) == list(frame.columns)
    # units: SI for figures, as written for inputs; the spec's own for reading
    assert columns.loc["omega_inner", ["unit", "shown_unit"]].tolist() == ["rad/s", "rpm"]
    assert columns.at["omega_inner", "shown_factor"] == pytest.approx(math.pi / 30, rel=1e-15)
    assert columns.loc["design_pendulum_weight", ["unit", "role", "label"]].tolist() == [
        "kgf", "input", "design.pendulum_weight"]
    assert columns.loc["stiffness", ["unit", "shown_unit"]].tolist() == ["N/m", "kgf/cm"]
    assert columns.at["stiffness", "shown_factor"] == pytest.approx(980.665, rel=1e-15)
    assert columns.loc["value_shear_stress", ["unit", "shown_unit"]].tolist() == [
        "Pa", "kgf/cm^2"]
    assert columns.loc["margin_irregularity", ["role", "label"]].tolist() == [
        "check margin", "irregularity"]


def test_a_design_figure_is_read_in_the_unit_the_spec_writes_its_key_in(tmp_path):
    """A spec whose lengths are in cm but whose wire diameter is in mm reads its study's wire
    diameter in mm (the key's own unit), its coil radius in cm; ``study show`` alike."""
    spec = tmp_path / "a.toml"
    text = CASE_A.read_text()
    assert 'wire_diameter = "1.7 cm"' in text
    spec.write_text(text.replace('wire_diameter = "1.7 cm"', 'wire_diameter = "17 mm"'))
    db = tmp_path / "a.db"
    run_study(load_study(spec, sweeps=["design.pendulum_weight=11 kgf,12 kgf"],
                         skip="dynamics,vibration,classic"), db)
    with Store(db, create=False) as store:
        columns = store.columns().set_index("name")
        table = store.table()
    assert columns.loc["wire_diameter", ["unit", "shown_unit"]].tolist() == ["m", "mm"]
    assert columns.at["wire_diameter", "shown_factor"] == pytest.approx(1e-3, rel=1e-15)
    assert columns.loc["coil_radius", ["unit", "shown_unit"]].tolist() == ["m", "cm"]
    assert table["wire_diameter"].tolist() == pytest.approx([0.017, 0.017], rel=1e-12)


def test_meta_holds_the_format_the_version_and_the_study(hamabe_db):
    con = sqlite3.connect(f"file:{hamabe_db}?mode=ro", uri=True)
    try:
        meta = dict(con.execute("select key, value from meta").fetchall())
        user_version = con.execute("pragma user_version").fetchone()[0]
        app = con.execute("pragma application_id").fetchone()[0]
    finally:
        con.close()
    assert meta["format_version"] == str(FORMAT_VERSION) == str(user_version)
    assert app == 0x676F766F
    assert meta["govopt_version"] == f'"{govopt.__version__}"'
    assert '"keys"' in meta["study"] and meta["total"] == "5"


def test_every_row_figure_is_declared():
    """Each column a row of any bundled spec's design has is declared (its name and unit), so
    the database never takes a figure's unit from its name."""
    from govopt import load_spec
    from govopt.bulk import evaluate_rows, row_figures

    checked = 0
    for path in sorted(SPECS.glob("*.toml")):
        spec = load_spec(path)
        if spec.design is None:
            continue
        frame, units = evaluate_rows(spec, [spec.design])
        declared = row_figures(spec)
        figures = [c for c in frame.columns if not c.startswith(("value: ", "margin: ",
                                                                  "passed: "))
                   and c not in ("objective", "objective_value", "status", "message")]
        assert set(figures) <= set(declared), (path.name, set(figures) - set(declared))
        assert set(units) == {c.split(": ", 1)[1] for c in frame.columns
                              if c.startswith("margin: ")}
        checked += 1
    assert checked >= 10


# ---------------------------------------------------------------------------------------------
# format and version


def _cli(*args, cwd=None):
    from clirun import invoke

    return invoke([str(a) for a in args], cwd=cwd)


def _one_line_error(r, *words) -> str:
    assert r.exit_code == 2, r.output
    assert r.stderr.count("\n") == 1 and r.stderr.startswith("error: "), r.stderr
    for w in words:
        assert w in r.stderr, r.stderr
    return r.stderr


def test_another_format_is_refused_in_one_line(tmp_path):
    """A database of a newer format, and govopt 0.1.0's (every point's figures in one blob,
    no format recorded), are refused by run --resume, show and export with one line naming the
    formats; --force starts afresh."""
    sweep = "speed.irregularity=0.12,0.13"
    newer = tmp_path / "newer.db"
    run_study(load_study(CASE_A, sweeps=[sweep]), newer)
    with Store(newer) as store:
        store.set_meta({"format_version": FORMAT_VERSION + 1})
    old = tmp_path / "old.db"
    con = sqlite3.connect(old)
    con.executescript(
        "CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);"
        "CREATE TABLE layouts (id TEXT PRIMARY KEY, columns TEXT NOT NULL);"
        "CREATE TABLE points (hash TEXT PRIMARY KEY, idx INTEGER NOT NULL, status TEXT NOT "
        "NULL, message TEXT, layout TEXT NOT NULL, numbers BLOB NOT NULL, texts TEXT NOT NULL);"
        "INSERT INTO meta VALUES ('govopt_version', '\"0.1.0\"');")
    con.close()
    for db, found in ((newer, f"format {FORMAT_VERSION + 1}, a newer govopt's"),
                      (old, "format 1, an older govopt's")):
        for args in (["study", "run", CASE_A, "--sweep", sweep, "--db", db, "--resume"],
                     ["study", "show", db], ["study", "export", db, "--out", tmp_path / "x.csv"]):
            _one_line_error(_cli(*args), str(db), found, f"reads format {FORMAT_VERSION}")
        r = _cli("study", "run", CASE_A, "--sweep", sweep, "--db", db, "--force")
        assert r.exit_code in (0, 1), r.output
        with Store(db, create=False) as store:
            assert store.count() == 2 and store.format_version() == FORMAT_VERSION
    assert not (tmp_path / "x.csv").exists()
    assert _journal_files(tmp_path) == []


def test_resume_under_another_version_checks_the_results(tmp_path, monkeypatch):
    """A database written by another govopt version is resumed only if this version computes
    its stored points alike: said in one note, no point stored twice; where they differ it is
    refused with one line naming the point and the column."""
    sweep = "design.pendulum_weight=10 kgf:12 kgf:6"
    db = tmp_path / "v.db"
    run_study(load_study(CASE_A, sweeps=[sweep]), db, chunk=2)
    with sqlite3.connect(db) as con:  # a run killed after two blocks
        con.execute("DELETE FROM points WHERE point >= 4")
    monkeypatch.setattr(govopt, "__version__", "9.9.9")
    r = _cli("study", "run", CASE_A, "--sweep", sweep, "--db", db, "--resume")
    assert r.exit_code in (0, 1), r.output
    notes = [line for line in r.stderr.splitlines() if line.startswith("note: ")]
    assert notes == [f"note: {db}: written by govopt 0.1.0; its first 3 points recomputed by "
                     "govopt 9.9.9 agree: resumed"]
    assert "points: 6 of 6 done" in r.stdout
    with Store(db, create=False) as store:
        assert store.count() == 6 and store.meta("govopt_versions") == ["0.1.0", "9.9.9"]
    with sqlite3.connect(db) as con:  # a version whose results differ
        con.execute("DELETE FROM points WHERE point >= 4")
        con.execute("UPDATE points SET irregularity = irregularity * 1.01 WHERE point = 0")
        con.execute("UPDATE meta SET value = '[\"0.1.0\"]' WHERE key = 'govopt_versions'")
    err = _one_line_error(_cli("study", "run", CASE_A, "--sweep", sweep, "--db", db,
                               "--resume"), "written by govopt 0.1.0, whose results differ "
                                            "from govopt 9.9.9's (point 0, irregularity:")
    assert "--force" in err and "np.float64" not in err  # numbers as a person reads them
    assert re.search(r"irregularity: [0-9.]+ stored, [0-9.]+ now", err), err
    with Store(db, create=False) as store:
        assert store.count() == 4
    assert _journal_files(tmp_path) == []


# ---------------------------------------------------------------------------------------------
# files left and one-line errors


def test_no_journal_file_is_left(tmp_path, hamabe_db):
    """After a run (its summary and exports read read-only), show, export and a refused run,
    the folder holds the database alone."""
    db = tmp_path / "s.db"
    r = _cli("study", "run", CASE_A, "--sweep", "speed.irregularity=0.12,0.13", "--db", db,
             "--out", tmp_path / "s.csv", "--plot", tmp_path / "p")
    assert r.exit_code == 0, r.output
    assert _journal_files(tmp_path) == []
    assert _cli("study", "show", db).exit_code == 0
    assert _cli("study", "export", db, "--out", tmp_path / "s.parquet").exit_code == 0
    _one_line_error(_cli("study", "run", CASE_A, "--sweep", "speed.irregularity=0.1", "--db",
                         db), "holds another study")
    assert _journal_files(tmp_path) == []
    copy = tmp_path / "copy.db"
    shutil.copy(hamabe_db, copy)
    assert _cli("study", "show", copy).exit_code == 0
    assert _journal_files(tmp_path) == []


def test_a_truncated_database_is_damaged_and_force_replaces_it(tmp_path):
    """A database cut short is called damaged with advice that works: --force starts it
    afresh (govopt knows its own database by its header)."""
    sweep = "design.pendulum_weight=10 kgf:12 kgf:400"
    db = tmp_path / "t.db"
    run_study(load_study(CASE_A, sweeps=[sweep], skip="dynamics,vibration,classic"), db)
    size = db.stat().st_size
    with open(db, "r+b") as fh:
        fh.truncate(size // 2)
    for args in (["study", "run", CASE_A, "--sweep", sweep, "--db", db, "--resume",
                  "--skip", "dynamics,vibration,classic"], ["study", "show", db]):
        err = _one_line_error(_cli(*args), "the study database is damaged")
        assert "run the study again with --force" in err
    r = _cli("study", "run", CASE_A, "--sweep", sweep, "--db", db, "--force",
             "--skip", "dynamics,vibration,classic")
    assert r.exit_code in (0, 1) and "points: 400 of 400 done" in r.stdout, r.output
    assert _journal_files(tmp_path) == []


@pytest.mark.parametrize("damage", hostile.DAMAGES)
def test_a_damaged_database_is_named_damaged(tmp_path, damage):
    """A database whose structure or totals are not what govopt wrote (a table gone, a row the
    study did not write, a total or a unit's factor edited) is called damaged, with what is
    wrong, by show, export and --resume (exit 2, one line): nothing is shown or counted from
    it, nothing exported; --force starts the study afresh."""
    sql, words = hostile.DAMAGES[damage]
    db = tmp_path / "d.db"
    hostile.damaged_study_db(sql, db)
    for args in (["study", "show", db], ["study", "export", db, "--out", tmp_path / "d.csv"],
                 ["study", "run", STUDY, "--db", db, "--resume", "--skip", "vibration,classic"]):
        _one_line_error(_cli(*args), f"{db}: the study database is damaged: ", words,
                        "run the study again with --force")
    assert not (tmp_path / "d.csv").exists()
    if damage == "no columns table":  # govopt's own header: --force may replace it
        r = _cli("study", "run", STUDY, "--db", db, "--force", "--skip", "vibration,classic")
        assert r.exit_code == 0 and "points: 5 of 5 done" in r.stdout, r.output


def test_a_database_that_cannot_be_read_is_one_line(tmp_path, hamabe_db, monkeypatch):
    """show and export of a database this process may not read: one line naming it (the
    permission said), exit 2, not a traceback."""
    from govopt.study import store as store_module

    copy = tmp_path / "p.db"
    shutil.copy(hamabe_db, copy)

    def denied(path, *args, **kwargs):
        if Path(path) == copy:
            raise PermissionError(13, "Permission denied", str(path))
        return open(path, *args, **kwargs)

    monkeypatch.setattr(store_module, "open", denied, raising=False)
    _one_line_error(_cli("study", "show", copy), str(copy), "cannot read the study database "
                                                           "(permission denied)")
    monkeypatch.undo()
    import os

    if os.geteuid() == 0:  # root reads every file: the rest needs an ordinary user
        return
    copy.chmod(0)
    try:
        _one_line_error(_cli("study", "show", copy), str(copy), "permission denied")
    finally:
        copy.chmod(0o644)


def test_the_database_is_named_as_such(tmp_path, hamabe_db):
    """An export over the database itself names it the study database, not the spec."""
    copy = tmp_path / "d.db"
    shutil.copy(hamabe_db, copy)
    err = _one_line_error(_cli("study", "export", copy, "--out", copy, "--force"),
                          "it is the same file as the study database")
    assert "spec" not in err


@pytest.mark.parametrize("args, words", [
    (["--seed", "-1", "--lhs", "4"], ["--seed: expected a whole number from 0 to 2^64 - 1, "
                                      "got -1"]),
    (["--samples", "0"], ["--samples: expected a whole number >= 1, got 0"]),
    (["--lhs", "0"], ["--lhs: expected a whole number >= 1, got 0"]),
    (["--sweep", "design.pendulum_weight=1 kgf"], ["--sweep: design.pendulum_weight is given "
                                                   "twice"]),
])
def test_options_are_refused_naming_themselves(tmp_path, args, words):
    sweep = ["--sweep", "design.pendulum_weight=10 kgf:12 kgf"] if "--samples" not in args \
        else ["--tolerance", "design.pendulum_weight=±1%"]
    err = _one_line_error(_cli("study", "run", CASE_A, *sweep, *args, "--db", tmp_path / "x.db"),
                          *words)
    assert "--lhs" not in err or "--lhs" in args
    assert not (tmp_path / "x.db").exists()


@pytest.mark.parametrize("table, words", [
    ("seed = -1", "study.seed: expected a whole number >= 0, got -1"),
    ("seed = 1.5", "study.seed: expected a whole number >= 0, got 1.5"),
    ("samples = 0", "study.samples: expected a whole number >= 1, got 0"),
])
def test_study_table_values_are_refused_naming_the_key(tmp_path, table, words):
    spec = tmp_path / "s.toml"
    spec.write_text(CASE_A.read_text(encoding="utf-8") + f"\n[study]\n{table}\ncombine = "
                    '"lhs"\n[study.sweep]\n"design.pendulum_weight" = "10 kgf:12 kgf"\n',
                    encoding="utf-8")
    _one_line_error(_cli("study", "run", spec, "--db", tmp_path / "x.db"), str(spec), words)


def test_progress_is_told_from_the_start(tmp_path):
    """``progress`` hears of the study before its first block and after each."""
    heard = []
    run_study(load_study(CASE_A, sweeps=["design.pendulum_weight=10 kgf:12 kgf:25"],
                         skip="dynamics,vibration,classic"), tmp_path / "p.db", chunk=10,
              progress=lambda done, failures, total: heard.append((done, total)))
    assert heard == [(0, 25), (10, 25), (20, 25), (25, 25)]


# ---------------------------------------------------------------------------------------------
# tolerance studies on every bundled spec with a spring


def _helical_design(path: Path) -> bool:
    import tomllib

    design = tomllib.loads(path.read_text(encoding="utf-8")).get("design", {})
    return "wire_diameter" in design and "coil_radius" in design


@pytest.mark.parametrize("name", sorted(p.stem for p in SPECS.glob("*.toml")))
def test_grade_tolerance_plot_on_every_bundled_spec(tmp_path, name):
    """`study SPEC --tolerance grade=2 --plot` on each bundled spec: a spec whose design has a
    helical spring gets its plot (whatever the samples' spread); another is refused in one
    line saying what the grade needs."""
    path = SPECS / f"{name}.toml"
    r = _cli("study", path, "--tolerance", "grade=2", "--samples", "30", "--db",
             tmp_path / "t.db", "--plot", tmp_path / "p")
    if _helical_design(path):
        assert r.exit_code in (0, 1), r.output
        assert (tmp_path / "p" / "tolerance.png").exists()
    else:
        _one_line_error(r, "tolerance grade: needs a helical spring in [design]")


def test_grade_tolerance_plot_of_a_designed_hartnell(tmp_path):
    """The Hartnell govopt designs, toleranced to grade 2: margins that hardly vary (the
    bounds' rows) are drawn, not refused as 'too many bins'."""
    spec = tmp_path / "h.toml"
    r = _cli("design", SPECS / "hartnell-design.toml", "-o", spec)
    assert r.exit_code == 0, r.output
    r = _cli("study", spec, "--tolerance", "grade=2", "--samples", "200", "--db",
             tmp_path / "t.db", "--plot", tmp_path / "p")
    assert r.exit_code in (0, 1), r.output
    assert (tmp_path / "p" / "tolerance.svg").exists()


def test_histograms_of_degenerate_samples():
    """All equal, equal to rounding, a few distinct values, NaN and nothing: each counted."""
    from govopt.report.study_plots import histograms

    cases = {"equal": [2.0] * 5, "rounding": [1e6, 1e6 + 1e-9, 1e6], "few": [1.0, 2.0, 1.0],
             "nan": [np.nan, 3.0, np.nan], "none": [np.nan] * 3, "negative": [-1.0, -1.0]}
    n = max(map(len, cases.values()))
    frame = pd.DataFrame({k: v + [np.nan] * (n - len(v)) for k, v in cases.items()})
    frame["status"] = "pass"
    hists = histograms(lambda: [frame], {k: (k, 1.0, k == "negative") for k in cases})
    for k, v in cases.items():
        edges, counts, negative = hists[k]
        finite = np.isfinite(v).sum()
        assert counts.sum() + negative.sum() == finite, k
        assert np.all(np.diff(edges) > 0), k
    assert hists["none"][0].size == 0
    assert hists["negative"][2].sum() == 2


# ---------------------------------------------------------------------------------------------
# the workbook


def test_workbook_prints_a_summary_then_the_table(tmp_path, hamabe_db):
    """Summary first (what was swept, the counts, the best point, the plots), then the Table
    in the spec's units (units in the headings, landscape, the heading row repeated, the
    inputs first, fonts of 8 pt or more), the Data sheet the database's own columns."""
    from openpyxl import load_workbook

    from govopt.report.study_workbook import write_workbook

    with Store(hamabe_db, create=False) as store:
        path = write_workbook(store, tmp_path / "s.xlsx")
        table = store.table()
    book = load_workbook(path)
    assert book.sheetnames == ["Summary", "Table", "Data", "Columns"]
    summary = {r[0]: r[1] for r in book["Summary"].iter_rows(values_only=True) if r and r[0]}
    assert summary["swept: design.pendulum_weight"] == "12, 10, 8, 6, 6 kgf"
    assert summary["status"] == "fail 3, pass 2"
    assert summary["best feasible point"] == "point 2: moving mass 12.18 kg"
    import zipfile

    with zipfile.ZipFile(path) as z:  # the sweep and the Pareto front, drawn on the Summary
        assert len([n for n in z.namelist() if n.startswith("xl/media/")]) == 2
        assert len([n for n in z.namelist() if n.startswith("xl/drawings/drawing")]) == 1
    sheet = book["Table"]
    head = [c.value for c in sheet[1]]
    assert head[:7] == ["point", "design pendulum weight [kgf]", "speed irregularity",
                        "design wire diameter [cm]", "design active turns",
                        "design dashpot a1 [kgf*cm*s/rad]", "status"]
    assert head[7] == "moving mass (objective) [kg]" and head[-1] == "message"
    assert "omega inner [rpm]" in head and "stiffness [kgf/cm]" in head
    assert sheet.page_setup.orientation == "landscape" and sheet.print_title_rows == "$1:$1"
    inner = head.index("omega inner [rpm]") + 1
    assert sheet.cell(2, inner).value == pytest.approx(table["omega_inner"][0] * 30 / math.pi,
                                                       rel=1e-4)
    sizes = {c.font.sz for row in sheet.iter_rows() for c in row if c.value is not None}
    assert min(sizes) >= 8
    for col in range(1, len(head) + 1):  # every value as wide as its column (nothing cut)
        letter = sheet.cell(1, col).column_letter
        width = sheet.column_dimensions[letter].width
        longest = max(len(str(sheet.cell(r, col).value or "")) for r in range(2, 7))
        assert width >= min(longest, 60), (head[col - 1], width, longest)
    data = pd.read_excel(path, sheet_name="Data")
    assert list(data.columns) == [c for c in table.columns if c != "pareto"]
    assert np.allclose(data["omega_inner"], table["omega_inner"], rtol=1e-15)
