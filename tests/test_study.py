"""Trade studies (govopt.study): sweeps and samplers, rows equal to govopt.evaluate's, the
SQLite store killed and resumed, pool and Dask backends, exports, Pareto fronts, tolerances."""

import math
import os
import signal
import sqlite3
import time
from pathlib import Path

import hostile
import numpy as np
import pandas as pd
import pytest

from govopt import evaluate, load_spec
from govopt.bulk import result_row, row_figures
from govopt.stats import wilson
from govopt.study import (
    Store,
    StudyError,
    Sweep,
    Tolerance,
    export,
    load_study,
    outcome,
    pareto_front,
    run_study,
    summary_text,
    tolerance_summary,
)
from govopt.study.summary import check_columns

SPECS = Path(__file__).resolve().parent.parent / "specs"
STUDY = SPECS / "studies" / "hamabe-study.toml"
HARTNELL = SPECS / "textbook-ex4-hartnell.toml"
RTOL = 1e-12


def _same(a, b) -> bool:
    if isinstance(a, str) or isinstance(b, str) or a is None or b is None:
        return a == b or ((a is None or a != a) and (b is None or b != b))
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return a == b if math.isinf(a) or math.isinf(b) else abs(a - b) <= RTOL * max(abs(a), abs(b))


# ---------------------------------------------------------------------------------------------
# sweeps and points


def _written(sweep: Sweep) -> list:
    """A sweep's values as the spec file writes them."""
    return [sweep.toml(v) for v in sweep.take(np.arange(len(sweep)))]


def test_sweep_forms():
    """Values are kept as numbers in the unit written (a list of texts only where they are not
    numbers in one unit), and written back for the parser as the file writes them."""
    r = Sweep.parse("design.pendulum_weight", "6 kgf:12 kgf:4")
    assert (r.unit, r.num, list(r.take(np.arange(4)))) == ("kgf", 4, [6.0, 8.0, 10.0, 12.0])
    assert _written(r) == ["6 kgf", "8 kgf", "10 kgf", "12 kgf"]
    mixed = Sweep.parse("design.wire_diameter", "1 cm:20 mm:3")  # STOP in START's unit
    assert _written(mixed) == ["1 cm", "1.5 cm", "2 cm"]
    assert _written(Sweep.parse("speed.irregularity", "0.08:0.12:3")) == [0.08, 0.1, 0.12]
    turns = Sweep.parse("design.active_turns", "6:10:3")
    assert turns.integer and _written(turns) == [6, 8, 10]
    listed = Sweep.parse("design.pendulum_weight", "12,10,8 kgf")
    assert (listed.values, listed.unit, listed.text) == ((12.0, 10.0, 8.0), "kgf", False)
    assert Sweep.parse("analysis.geometry", "exact,series").values == ("exact", "series")
    assert Sweep.parse("analysis.geometry", "exact,series").text
    assert Sweep.parse("k", "1 cm, 2 kg").text  # not one unit: each read by the parser
    assert _written(Sweep.parse("k", {"start": "1 cm", "stop": "2 cm", "num": 2})) == [
        "1 cm", "2 cm"]
    assert len(Sweep.parse("k", "1 cm:2 cm")) == 0  # a range for the samplers
    for bad in ("1 cm:2 kg:3", "1:2:0", "1:2:x", "1,,2", "1:2:3:4", "nan:1:3"):
        with pytest.raises(StudyError):
            Sweep.parse("k", bad)


def _wide(tmp_path) -> Path:
    """textbook-ex4-hartnell with a 200-300 rpm band. The studies below sweep its design over
    weights and free lengths whose operating bands the book's 240-256.8 rpm refuses: the band
    is a requirement of every path, and the book's own rounded spring (3.572 kgf/cm)
    spans 0.002 % more than it."""
    text = HARTNELL.read_text(encoding="utf-8")
    for old, new in (('inner = "240 rpm"', 'inner = "200 rpm"'),
                     ('outer = "256.8 rpm"', 'outer = "300 rpm"')):
        assert old in text
        text = text.replace(old, new)
    path = tmp_path / "wide.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _study(tmp_path, table: str, spec: Path = HARTNELL) -> Path:
    path = tmp_path / "study.toml"
    path.write_text(spec.read_text(encoding="utf-8") + "\n" + table, encoding="utf-8")
    return path


def test_grid_zip_and_samplers(tmp_path):
    path = _study(tmp_path, "")
    sweeps = ["design.ball_weight=1.8 kgf:2.2 kgf:3", "speed.outer=250 rpm,260 rpm"]
    grid = load_study(path, sweeps=sweeps).points()
    assert len(grid) == 6 and grid[1] == {"design.ball_weight": "1.8 kgf",
                                         "speed.outer": "260 rpm"}
    with pytest.raises(StudyError, match="same number of values"):
        load_study(path, sweeps=sweeps, combine="zip").points()
    ranges = ["design.ball_weight=1.8 kgf:2.2 kgf", "design.free_length=15 cm:16 cm"]
    lhs = load_study(path, sweeps=ranges, combine="lhs", samples=50, seed=4).points()
    again = load_study(path, sweeps=ranges, combine="lhs", samples=50, seed=4).points()
    assert lhs == again and len(lhs) == 50
    # a Latin hypercube: each of the 50 equal strata of each key holds exactly one sample
    w = np.array([float(p["design.ball_weight"].split()[0]) for p in lhs])
    strata = np.floor((w - 1.8) / 0.4 * 50).astype(int)
    assert sorted(strata) == list(range(50))
    sob = load_study(path, sweeps=ranges, combine="sobol", samples=16).points()
    assert len({p["design.free_length"] for p in sob}) == 16


def test_bad_points_are_rows_not_crashes(tmp_path):
    """A value the spec parser refuses, one out of range and one that leaves no equilibrium
    are error rows with the reason; the good points are evaluated; nothing is dropped."""
    path = _study(tmp_path, "", _wide(tmp_path))
    study = load_study(path, sweeps=["design.free_length=15.41 cm,-1 cm,2 kg,15.5 cm,8 cm"])
    report = run_study(study, tmp_path / "s.db")
    assert (report.total, report.done) == (5, 5)
    with Store(tmp_path / "s.db") as store:
        t = store.table()
    assert list(t["point"]) == [0, 1, 2, 3, 4]
    assert list(t["status"]) == ["pass", "error", "error", "pass", "error"]
    # the inputs as written, in the row of a point the parser refused too
    assert list(t["design_free_length"]) == ["15.41 cm", "-1 cm", "2 kg", "15.5 cm", "8 cm"]
    assert "design.free_length" in t["message"][1] and "positive" in t["message"][1]
    assert "length" in t["message"][2]
    assert "no equilibrium speed at ball radius = 0.075 m" in t["message"][4]


def test_outcome_all_failed_exits_nonzero(tmp_path):
    """A study whose every point failed exits non-zero with one line naming the most common
    reason: 1 when points ran and failed a check, 2 when none could be evaluated; some failures
    exit 0 and are counted."""
    case_a = SPECS / "hamabe-a.toml"  # irregularity 0.123 (the paper's case a)

    def run(spec, sweep, name):
        study = load_study(spec, sweeps=[sweep])
        with Store(tmp_path / name) as store:
            return outcome(store, run_study(study, store.path))

    assert run(case_a, "speed.irregularity=0.1,0.11", "fail.db") == (
        1, "all 2 points failed: most common reason (2 of 2): fails: irregularity")
    code, line = run(case_a, "speed.irregularity=0.11,0.13", "some.db")  # 0.123 <= 0.13 passes
    assert (code, line) == (0, "1 of 2 points failed: most common reason (1 of 1): fails: "
                               "irregularity")
    spec = _study(tmp_path, "")
    code, line = run(spec, "design.free_length=-1 cm,-2 cm,8 cm", "error.db")
    # the convention of exit 2: 'error: FILE: ...', the file named once
    assert code == 2 and line.startswith(f"error: {spec}: all 3 points failed (none could be "
                                         "evaluated): most common reason (1 of 3): "
                                         "design.free_length: ")
    assert line.count(str(spec)) == 1 and "\n" not in line
    code, line = run(_study(tmp_path, "", _wide(tmp_path)), "design.free_length=15.41 cm,15.5 cm",
                     "pass.db")
    assert (code, line) == (0, "")


# ---------------------------------------------------------------------------------------------
# the paper's Example 1


def test_example1_study_reproduces_evaluate(tmp_path):
    """specs/studies/hamabe-study.toml: each row is `govopt evaluate` of the case's own spec
    (a, b, c, d, d'), every figure and check to 1e-12."""
    study = load_study(STUDY)
    assert [p["design.pendulum_weight"] for p in study.points()] == [
        "12 kgf", "10 kgf", "8 kgf", "6 kgf", "6 kgf"]
    run_study(study, tmp_path / "h.db")
    with Store(tmp_path / "h.db") as store:
        table = store.table()
        names = _database_names(store, load_spec(SPECS / "hamabe-a.toml"))
    for i, case in enumerate(["a", "b", "c", "d", "d-prime"]):
        ref = result_row(evaluate(load_spec(SPECS / f"hamabe-{case}.toml")))
        row = table.iloc[i].to_dict()
        wrong = {k: (v, row.get(names[k])) for k, v in ref.items()
                 if not _same(v, row.get(names[k]))}
        assert not wrong, (case, wrong)
    # inputs as written (12 kgf); the flying mass in SI (12 kg)
    assert table["design_pendulum_weight"][0] == 12.0
    assert table["pendulum_mass"][0] == pytest.approx(12.0, rel=1e-15)
    # the spring stiffnesses of the paper's table (kgf/cm from d, r, n): 64.2, 50.4, 38.9,
    # 21.95, 29.3 (model doc, Example 1)
    paper = np.array([64.2, 50.4, 38.9, 21.95, 29.3]) * 9.80665 / 0.01
    assert np.allclose(table["stiffness"], paper, rtol=0.003)


def _database_names(store, spec) -> dict[str, str]:
    """Each column of a bulk row (:func:`govopt.bulk.result_row`) -> its column in the
    study's database (the declared figure's name; a check's value, margin and verdict)."""
    figures = {k: f.name for k, f in row_figures(spec).items()}
    names = {(r, label): n for n, r, label in store.conn.execute(
        "SELECT name, role, label FROM columns")}
    out = {"objective": "objective", "objective_value": "objective_value", "status": "status",
           "message": "message"}
    for key, name in figures.items():
        out[key] = names.get(("figure", name)) or names.get(("design", name), name)
    for (role, label), name in names.items():
        if role.startswith("check "):
            out[f"{role.split()[1]}: {label}"] = name
    return out


# ---------------------------------------------------------------------------------------------
# the store: kill, resume, integrity


@pytest.fixture(scope="module")
def cli():
    """``cli(*args)``: ``govopt ARGS`` in a process of its own, forked from one interpreter
    that loaded govopt once (tests/forkcli.py), a ``Popen``-like handle."""
    from forkcli import Server

    with Server() as server:
        yield server.start


def _rows(db: Path) -> int:
    """Rows committed in a study database (0 if it or its table does not exist yet); read-only,
    so that looking never creates the file."""
    try:
        conn = sqlite3.connect(f"file:{db}?mode=ro", uri=True, timeout=5)
    except sqlite3.Error:
        return 0
    try:
        return conn.execute("SELECT COUNT(*) FROM points").fetchone()[0]
    except sqlite3.Error:
        return 0
    finally:
        conn.close()


def test_sigkill_and_resume_give_the_uninterrupted_table(tmp_path, cli):
    """A study killed with SIGKILL at several moments (before its first commit, and after
    about a quarter, a half and three quarters of its rows) and resumed each time ends with the
    table of one uninterrupted run; the database passes PRAGMA integrity_check after every
    kill and never holds a partial chunk."""
    sweep = "design.ball_weight=1.5 kgf:2.5 kgf:2400"
    spec = _wide(tmp_path)
    args = ["study", spec, "--sweep", sweep, "--chunk", "100", "--skip", "classic"]
    ref_db = tmp_path / "ref.db"
    run_study(load_study(spec, sweeps=[sweep], skip="classic"), ref_db, chunk=100)
    with Store(ref_db) as store:
        reference = store.table()
    db = tmp_path / "killed.db"
    kills = 0
    for target in (0, 600, 1200, 1800):
        proc = cli(*args, "--db", db, "--resume")
        deadline = time.monotonic() + 60
        while proc.poll() is None and _rows(db) < target and time.monotonic() < deadline:
            time.sleep(0.01)
        if proc.poll() is None:
            os.kill(proc.pid, signal.SIGKILL)
            kills += 1
        proc.communicate()
        if db.exists():
            with sqlite3.connect(db) as conn:
                assert conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
        n = _rows(db)
        assert n % 100 == 0 or n == 2400  # whole chunks only
    assert kills >= 3
    proc = cli(*args, "--db", db, "--resume")
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 0, err
    with Store(db) as store:
        assert store.integrity() == "ok"
        pd.testing.assert_frame_equal(store.table(), reference)


def test_sigterm_ends_a_study_with_the_summary_sigint_prints(tmp_path, cli):
    """SIGTERM stops a study as Ctrl-C does: the blocks done kept, the summary on stdout and
    how to resume on stderr, the same lines; exit 128 + the signal (130, 143)."""
    spec = _wide(tmp_path)
    said = {}
    for sig in (signal.SIGINT, signal.SIGTERM):
        db = tmp_path / f"{sig.name}.db"
        proc = cli("study", spec, "--sweep", "design.ball_weight=1.5 kgf:2.5 kgf:100000",
                   "--chunk", "100", "--skip", "classic", "--db", db)
        deadline = time.monotonic() + 60
        while proc.poll() is None and _rows(db) < 200 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert proc.poll() is None, "the study ended before the signal"
        os.kill(proc.pid, sig)
        out, err = proc.communicate(timeout=120)
        assert proc.returncode == 128 + sig, err
        n = _rows(db)
        assert f"points: {n} of 100000 done" in out, out
        assert err == f"interrupted: {n} of 100000 points are in {db}; run again with --resume " \
                      "to finish\n"
        said[sig] = out.splitlines()[0]
    assert said[signal.SIGINT] == said[signal.SIGTERM]


def test_resume_skips_done_points_and_refuses_other_studies(tmp_path):
    path = _study(tmp_path, "")
    db = tmp_path / "r.db"
    first = load_study(path, sweeps=["design.ball_weight=1.8 kgf:2.2 kgf:5"])
    run_study(first, db, chunk=2)
    with pytest.raises(StudyError, match="--resume"):
        run_study(first, db)
    again = run_study(first, db, resume=True)
    assert (again.skipped, again.done) == (5, 0)
    other = load_study(path, sweeps=["design.ball_weight=1.8 kgf:2.2 kgf:7"])
    with pytest.raises(StudyError, match="another study"):
        run_study(other, db, resume=True)
    fresh = run_study(other, db, fresh=True)
    assert fresh.done == 7


# ---------------------------------------------------------------------------------------------
# backends


def test_dask_and_process_pool_give_the_same_table(tmp_path):
    """Design mode (the Porter of porter-design, whose design search takes ~0.1 s) over four
    speed ranges, two of them infeasible (a Porter's speed ratio is its geometry's; the third
    needs more central load than the bounds allow): a 2-process pool and a 2-worker Dask
    LocalCluster give identical tables."""
    pytest.importorskip("dask.distributed")
    from dask.distributed import Client, LocalCluster

    spec = SPECS / "porter-design.toml"
    sweeps = ["speed.inner=180 rpm,190 rpm,200 rpm,190 rpm",
              "speed.outer=212.2 rpm,224 rpm,235.8 rpm,200 rpm"]
    run_study(load_study(spec, sweeps=sweeps, combine="zip"), tmp_path / "pool.db", workers=2)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                      dashboard_address=None) as cluster, Client(cluster):
        run_study(load_study(spec, sweeps=sweeps, combine="zip"), tmp_path / "dask.db",
                  dask=cluster.scheduler_address)
    with Store(tmp_path / "pool.db") as a, Store(tmp_path / "dask.db") as b:
        ta, tb = a.table(), b.table()
    pd.testing.assert_frame_equal(ta, tb)
    assert list(ta["status"]) == ["optimal", "optimal", "infeasible", "infeasible"]
    assert "infeasible" in ta["message"][3]
    assert ta["objective"][0] == "moving_mass"
    # a design-mode row is the design's own evaluation, with the optimiser's objective
    from govopt import design

    res = design(load_spec(spec))  # point 1 is the spec's own 190-224 rpm
    value = res.optimisation["value"]
    assert ta["objective_value"][1] == value
    assert ta["moving_mass"][1] == pytest.approx(value, rel=1e-12)
    with Store(tmp_path / "pool.db", create=False) as store:
        units = store.columns().set_index("name")
    assert units.at["objective_value", "unit"] == "kg"


# ---------------------------------------------------------------------------------------------
# results


def test_pareto_front_against_brute_force():
    rng = np.random.default_rng(7)
    n = 300
    frame = pd.DataFrame({"a": rng.random(n), "b": rng.random(n), "c": rng.random(n),
                          "status": rng.choice(["pass", "fail"], n, p=[0.8, 0.2])})
    frame.loc[5, ["a", "b", "c"]] = frame.loc[4, ["a", "b", "c"]].to_numpy()  # a tie
    for objectives, signs in ((["a", "b"], [1, 1]), (["a", "max:b", "c"], [1, -1, 1])):
        F = np.column_stack([s * frame[o.removeprefix("max:")] for o, s in
                             zip(objectives, signs, strict=True)])
        ok = (frame["status"] == "pass").to_numpy()
        expect = np.zeros(n, bool)
        for i in np.nonzero(ok)[0]:
            dominated = ok & np.all(F <= F[i], axis=1) & np.any(F < F[i], axis=1)
            expect[i] = not dominated.any()
        got = pareto_front(frame, objectives)
        ties = np.nonzero(expect & ~got)[0]  # of equal rows only the first is kept
        assert all(np.any(np.all(F[got] == F[i], axis=1)) for i in ties)
        assert not np.any(got & ~expect)


def test_wilson_interval():
    # closed forms: k = 0 gives [0, z^2 / (n + z^2)]; k = n mirrors it
    z2 = 1.959963984540054**2
    assert wilson(0, 10) == pytest.approx((0.0, z2 / (10 + z2)), abs=1e-15)
    lo, hi = wilson(10, 10)
    assert (lo, hi) == pytest.approx((10 / (10 + z2), 1.0), abs=1e-15)
    lo, hi = wilson(50, 100)  # symmetric about 1/2
    assert lo + hi == pytest.approx(1.0, abs=1e-15)


def test_tolerance_study(tmp_path):
    """Wire diameter +-1 % (3 sigma) around Hamabe case c's spring: the stiffness G d^4 /
    (64 r^3 n) scatters as 4 dd/d, so its relative standard deviation is 4 x 1/3 % = 1.33 %
    (to first order; 400 samples pin it to ~4 %); the probability of each requirement has a
    Wilson interval; the speed range's spread is reported."""
    spec = SPECS / "hamabe-c.toml"
    study = load_study(spec, tolerances=["design.wire_diameter=±1%"], samples=400,
                       skip="vibration,classic")
    run_study(study, tmp_path / "t.db")
    with Store(tmp_path / "t.db") as store:
        table = store.table()
        text = summary_text(store)
        checks = {k: c["passed"] for k, c in check_columns(store).items()}
        units = store.columns().set_index("name")
    k = table["stiffness"].to_numpy()
    assert np.std(k) / np.mean(k) == pytest.approx(4 / 300, rel=0.1)
    d = table["design_wire_diameter"].to_numpy()  # drawn in SI, read in the spec's cm
    assert np.mean(d) == pytest.approx(0.015, rel=1e-3)
    assert (units.at["design_wire_diameter", "unit"],
            units.at["design_wire_diameter", "shown_unit"]) == ("m", "cm")
    s = tolerance_summary(table, checks)
    shear = s["checks"]["shear stress"]
    p = float(table[checks["shear stress"]].fillna(False).mean())
    assert shear["probability"] == p and shear["ci95"][0] <= p <= shear["ci95"][1]
    assert 0 < s["spread"]["omega_inner"]["std"] < 0.05 * s["spread"]["omega_inner"]["mean"]
    assert "tolerance study, 400 samples" in text
    with pytest.raises(StudyError, match="±X%"):
        Tolerance.parse("k", "1%")
    # the tolerance model of a made governor: case c's steel names no wire grade (its wire is
    # taken exact) and its spring pulls (an extension spring's free length is by agreement with
    # the maker): the coil diameter alone
    grade = load_study(spec, tolerances=["grade=2"], samples=4)
    assert {t.key for t in grade.tolerances} == {"design.coil_radius"}


@pytest.mark.parametrize("band", hostile.BAD_BANDS)
def test_a_band_that_makes_a_part_impossible_is_refused(tmp_path, band):
    """A tolerance band whose end the spec refuses (a wire's diameter or a weight at or below
    zero) is refused where it is given, one line naming the key, before any point runs: no
    sample is an impossible part counted as a failure."""
    from clirun import invoke

    options, words = hostile.BAD_BANDS[band]
    r = invoke(["study", "run", SPECS / "hamabe-c.toml", *options, "--db", tmp_path / "t.db"])
    assert r.exit_code == 2 and r.stderr.count("\n") == 1, r.output
    assert r.stderr.startswith(f"error: {SPECS / 'hamabe-c.toml'}: study: {words}"), r.stderr
    assert "give a narrower band" in r.stderr and not (tmp_path / "t.db").exists()


def test_exports_and_no_clobber(tmp_path):
    """CSV and Parquet in the spec's units with the unit in each heading (speeds in rpm,
    lengths in cm, forces in kgf: Hamabe's), the workbook's Data sheet the database's own
    columns; an existing file is replaced only when asked."""
    from govopt.report.study_workbook import write_workbook

    study = load_study(STUDY)
    run_study(study, tmp_path / "h.db")
    with Store(tmp_path / "h.db") as store:
        table = store.table()
        for name in ("t.csv", "t.parquet"):
            export(store, tmp_path / name)
        write_workbook(store, tmp_path / "t.xlsx", plots=False)
        with pytest.raises(Exception, match="already exists"):
            export(store, tmp_path / "t.csv")
        export(store, tmp_path / "t.csv", overwrite=True)
    csv = pd.read_csv(tmp_path / "t.csv")
    parquet = pd.read_parquet(tmp_path / "t.parquet")
    data = pd.read_excel(tmp_path / "t.xlsx", sheet_name="Data")
    assert list(data.columns) == [c for c in table.columns if c != "pareto"]
    for other in (csv, parquet, data):
        assert np.allclose(other["margin_irregularity"], table["margin_irregularity"],
                           rtol=1e-11)
    for other in (csv, parquet):
        assert "omega_inner [rpm]" in other and "omega_inner_rad_s" not in other
        assert np.allclose(other["omega_inner [rpm]"], table["omega_inner"] * 30 / math.pi,
                           rtol=1e-11)
        assert np.allclose(other["free_half_length [cm]"], table["free_half_length"] * 100,
                           rtol=1e-11)
        assert np.allclose(other["max_spring_force [kgf]"],
                           table["max_spring_force"] / 9.80665, rtol=1e-11)
        assert list(other["design_pendulum_weight [kgf]"]) == [12, 10, 8, 6, 6]
        assert list(other["pareto"]) == list(table["pareto"])
    import pyarrow.parquet as pq

    field = pq.read_schema(tmp_path / "t.parquet").field("omega_inner [rpm]")
    assert field.metadata[b"si_unit"] == b"rad/s" and field.metadata[b"unit"] == b"rpm"


def test_cli_study_show_export(tmp_path, monkeypatch):
    from clirun import invoke

    monkeypatch.chdir(tmp_path)

    def cli(*args):
        return invoke(args)

    wide = _wide(tmp_path)
    r = cli("study", wide, "--sweep", "design.ball_weight=1.9 kgf:2.1 kgf:3", "--sweep",
            "design.free_length=15 cm,16 cm", "--pareto", "moving_mass,max:k2_margin",
            "--db", "s.db", "--out", "s.csv", "--plot", "plots")
    assert r.exit_code == 0, r.output
    assert "points: 6 of 6 done" in r.stdout and "Pareto front" in r.stdout
    # like evaluate and design, a study says where it wrote, the path as given
    assert "wrote s.csv" in r.stdout.splitlines()
    assert f"wrote {Path('plots') / 'pareto.png'}" in r.stdout.splitlines()
    assert {p.name for p in (tmp_path / "plots").iterdir()} >= {
        "sweep-design.ball_weight.png", "sweep-design.free_length.svg", "pareto.png"}
    again = cli("study", wide, "--sweep", "design.ball_weight=2 kgf", "--db", "s.db")
    assert again.exit_code == 2 and "holds another study" in again.output  # not --resume
    show = cli("study", "show", "s.db")
    assert show.exit_code == 0 and "status:" in show.stdout
    out = cli("study", "export", "s.db", "--out", "s.csv")
    assert out.exit_code == 2 and "already exists" in out.output
    assert len(pd.read_csv(tmp_path / "s.csv")) == 6
    with Store(tmp_path / "s.db") as store:
        assert store.meta("total") == 6


def test_cli_study_exit_codes(tmp_path, monkeypatch):
    """`govopt study`: the table is written and summarised whatever failed; every point failing
    a check exits 1 with one line on stderr naming the most common reason, every point an error
    exits 2 (an 'error:' line), some failures exit 0 with their count on stderr."""
    from clirun import invoke

    monkeypatch.chdir(tmp_path)
    case_a = SPECS / "hamabe-a.toml"
    failed = invoke(["study", str(case_a), "--sweep", "speed.irregularity=0.1,0.11",
                     "--db", "f.db"])
    assert failed.exit_code == 1, failed.output
    assert "status: fail 2" in failed.stdout
    assert failed.stderr == ("all 2 points failed: most common reason (2 of 2): fails: "
                             "irregularity\n")
    errors = invoke(["study", str(case_a), "--sweep", "design.pendulum_weight=-1 kgf,-2 kgf",
                     "--db", "e.db"])
    assert errors.exit_code == 2, errors.output
    assert "status: error 2" in errors.stdout
    assert errors.stderr.startswith(f"error: {case_a}: all 2 points failed (none could be "
                                    "evaluated): most common reason (1 of 2): "
                                    "design.pendulum_weight: ")
    assert errors.stderr.count("\n") == 1
    some = invoke(["study", str(case_a), "--sweep", "speed.irregularity=0.11,0.13",
                   "--db", "s.db"])
    assert some.exit_code == 0, some.output
    assert some.stderr == "1 of 2 points failed: most common reason (1 of 1): fails: irregularity\n"


# ------------------------------------------------------------------------------------------
# plots a reader does not misread


def test_zipped_study_is_one_plot_and_pareto_says_minimise(tmp_path):
    """Zipped keys move together: one sweep plot against the first, the others named on its
    axis; the Pareto axes say 'minimise' (not '(min)', which reads as minutes)."""
    from govopt.report.study_plots import plot_study

    study = load_study(SPECS / "hamabe-a.toml", sweeps=[
        "design.pendulum_weight=10 kgf:12 kgf:3", "design.wire_diameter=1.6 cm:1.8 cm:3"],
        combine="zip", pareto=["moving_mass", "settling_time"])
    run_study(study, tmp_path / "z.db")
    with Store(tmp_path / "z.db") as store:
        files = {p.name for p in plot_study(store, tmp_path / "plots")}
    assert files == {"sweep-design.pendulum_weight.png", "sweep-design.pendulum_weight.svg",
                     "pareto.png", "pareto.svg"}
    svg = (tmp_path / "plots" / "sweep-design.pendulum_weight.svg").read_text()
    assert "in step with it: design.wire_diameter" in svg
    pareto = (tmp_path / "plots" / "pareto.svg").read_text()
    assert "(minimise)" in pareto and "(min)" not in pareto


def test_tolerance_plot_marks_the_limit_and_failing_samples(tmp_path):
    """The irregularity's histogram carries its requirement; the failing samples of a margin
    are red, not the passing ones' green."""
    from govopt.report.study_plots import check_limit, plot_study

    study = load_study(SPECS / "hamabe-c.toml", tolerances=["grade=2",
                                                             "design.wire_diameter=±3%"],
                       samples=60)
    run_study(study, tmp_path / "t.db")
    with Store(tmp_path / "t.db") as store:
        frame = store.table()
        plot_study(store, tmp_path / "plots", formats=("svg",))  # read below
    spec = load_spec(SPECS / "hamabe-c.toml")
    assert check_limit(frame, "value_irregularity", "margin_irregularity") == pytest.approx(
        spec.speed.irregularity, rel=1e-9)
    svg = (tmp_path / "plots" / "tolerance.svg").read_text()
    assert f"required &lt;= {spec.speed.irregularity:.4g}" in svg
    assert (frame["margin_irregularity"] < 0).any()  # some fail
    assert "fill: #d62728" in svg  # their bars red (C3), beside the passing ones' green
    assert "speed at the inner end [rpm]" in svg  # in the spec's unit


def _inner_speed_spread(spec, folder, samples):
    """`govopt study show`'s text of a +-1 % pendulum tolerance study of ``spec``, its line of
    the inner speed's spread, that line's mean and the mean of the stored column (rad/s)."""
    run_study(load_study(spec, tolerances=["design.pendulum_weight=±1%"], samples=samples),
              folder / "t.db")
    with Store(folder / "t.db") as store:
        text = summary_text(store)
        frame = store.table()
    line = next(x for x in text.splitlines() if x.strip().startswith("omega_inner")).strip()
    return (text, line, float(line.split("mean ")[1].split()[0]), frame["omega_inner"].mean())


def test_study_show_gives_speeds_in_rpm_and_inputs_as_drawn(tmp_path):
    """`govopt study show`: the tolerance spread of the speeds in rpm (the spec's and the
    plot's unit), not rad/s, every number of the line with its unit."""
    text, line, mean, stored = _inner_speed_spread(SPECS / "hamabe-c.toml", tmp_path, 20)
    assert line.startswith("omega_inner: mean ") and line.count(" rpm") == 3, line
    assert mean == pytest.approx(stored * 30 / math.pi, rel=1e-5)
    assert "rad/s" not in text.split("tolerance study", 1)[1]


def test_study_show_gives_speeds_in_the_specs_own_unit(tmp_path):
    """A spec that states its speeds in rad/s gets its spread in rad/s (the spec's unit)."""
    text = (SPECS / "hamabe-c.toml").read_text(encoding="utf-8")
    spec = tmp_path / "rad.toml"
    mean = load_spec(SPECS / "hamabe-c.toml").speed.omega_mean
    speed = text[text.index("[speed]"):].split("\n\n", 1)[0]
    new = "\n".join(f'mean = "{mean:.17g} rad/s"' if line.startswith("mean") else line
                    for line in speed.splitlines())
    assert new != speed
    spec.write_text(text.replace(speed, new), encoding="utf-8")
    _, line, value, stored = _inner_speed_spread(spec, tmp_path, 8)
    assert line.startswith("omega_inner: mean ") and line.count(" rad/s") == 3, line
    assert value == pytest.approx(stored, rel=1e-5)


# ---------------------------------------------------------------------------------------------
# databases that must not lose anything


def test_db_never_replaces_the_spec_nor_a_foreign_file(tmp_path, monkeypatch):
    """`--db SPEC --force` refuses (the spec is kept byte for byte); so does --db on a file that
    is not a govopt study database; an empty file is never written by `export` (read-only)."""
    from clirun import invoke

    monkeypatch.chdir(tmp_path)
    spec = tmp_path / "s.toml"
    spec.write_bytes(HARTNELL.read_bytes())
    sweep = "design.ball_weight=1.9 kgf,2 kgf"
    r = invoke(["study", "run", spec, "--sweep", sweep, "--db", spec, "--force"])
    assert r.exit_code == 2 and r.stderr.count("\n") == 1, r.output
    assert "it is the spec" in r.stderr
    assert spec.read_bytes() == HARTNELL.read_bytes()
    other = tmp_path / "notes.db"
    conn = sqlite3.connect(other)
    conn.execute("CREATE TABLE notes (x)")
    conn.commit()
    conn.close()
    before = other.read_bytes()
    for force in ((), ("--force",)):
        r = invoke(["study", "run", spec, "--sweep", sweep, "--db", other, *force])
        assert r.exit_code == 2 and "not a govopt study database" in r.stderr, r.output
    assert other.read_bytes() == before
    empty = tmp_path / "empty.db"
    empty.touch()
    r = invoke(["study", "export", empty, "--out", "x.csv"])
    assert r.exit_code == 2 and "not a govopt study database" in r.stderr, r.output
    assert empty.stat().st_size == 0 and not (tmp_path / "x.csv").exists()


def test_damaged_database_is_one_line(tmp_path, monkeypatch):
    """Garbage past the first page: run --resume, show and export answer one line naming the
    file (exit 2); --force starts afresh."""
    from clirun import invoke

    monkeypatch.chdir(tmp_path)
    spec = _wide(tmp_path)  # every swept weight keeps its band: the runs pass (exit 0)
    sweep = "design.ball_weight=1.8 kgf:2.2 kgf:300"
    assert invoke(["study", "run", spec, "--sweep", sweep, "--db", "d.db",
                   "--skip", "dynamics,vibration,classic"]).exit_code == 0
    with open(tmp_path / "d.db", "r+b") as fh:
        assert fh.seek(0, 2) > 8192
        fh.seek(4096)
        fh.write(os.urandom(4096))
    for args in (["study", "run", spec, "--sweep", sweep, "--db", "d.db", "--resume"],
                 ["study", "show", "d.db"], ["study", "export", "d.db", "--out", "d.csv"]):
        r = invoke(args)
        assert r.exit_code == 2, r.output
        assert r.stderr.startswith("error: d.db: the study database is damaged"), r.stderr
        assert r.stderr.count("\n") == 1
    r = invoke(["study", "run", spec, "--sweep", sweep, "--db", "d.db", "--force",
                "--skip", "dynamics,vibration,classic"])
    assert r.exit_code == 0 and "points: 300 of 300 done" in r.stdout, r.output


def test_db_and_dask_options_are_checked_first(tmp_path, monkeypatch):
    from clirun import invoke

    monkeypatch.chdir(tmp_path)
    base = ["study", "run", HARTNELL, "--sweep", "design.ball_weight=1.9 kgf,2 kgf"]
    cases = {("--db", "no/such/x.db"): "folder no/such does not exist",
             ("--db", ""): "--db: expected a database file name",
             ("--db", str(tmp_path)): "not a regular file",
             ("--dask", "garbage"): "--dask: expected 'local' or a scheduler address",
             ("--dask", "tcp://host:99999"): "--dask: expected"}
    for args, expected in cases.items():
        r = invoke([*base, *args])
        assert r.exit_code == 2 and expected in r.stderr, (args, r.output)
        assert r.stderr.count("\n") == 1
    assert not list(tmp_path.iterdir())  # nothing written


def test_show_opens_read_only(tmp_path):
    """`study show` needs no write: a database whose file and folder are read-only is shown
    (and the file is not modified)."""
    from clirun import invoke

    db = tmp_path / "ro" / "s.db"
    db.parent.mkdir()
    run_study(load_study(HARTNELL, sweeps=["design.ball_weight=1.9 kgf,2 kgf"]), db)
    before = db.read_bytes()
    db.chmod(0o444)
    db.parent.chmod(0o555)
    try:
        r = invoke(["study", "show", db])
    finally:
        db.parent.chmod(0o755)
    assert r.exit_code == 0 and "points: 2 of 2 done" in r.stdout, r.output
    assert db.read_bytes() == before


def _start(cli, spec, db, sweep, *extra):
    return cli("study", "run", spec, "--db", db, "--sweep", sweep, "--chunk", "5",
               "--skip", "dynamics,vibration,classic", *extra)


def test_two_studies_on_one_database(tmp_path, cli):
    """Two processes started at once: of two *different* studies one is refused (one line
    naming the database and that it holds another study) and the database holds only the
    other's rows; two runs of the *same* study cooperate: every point once."""
    db = tmp_path / "c.db"
    a = _start(cli, HARTNELL, db, "design.ball_weight=1.8 kgf:2.2 kgf:120")
    b = _start(cli, HARTNELL, db, "design.ball_weight=1.8 kgf:2.2 kgf:70")
    (_, err_a), (_, err_b) = a.communicate(timeout=300), b.communicate(timeout=300)
    codes = sorted([a.returncode, b.returncode])
    assert codes[0] in (0, 1) and codes[1] == 2, (err_a, err_b)
    refused = err_a if a.returncode == 2 else err_b
    assert refused.startswith(f"error: {db}: the database holds another study"), refused
    assert refused.count("\n") == 1
    ran = 120 if a.returncode != 2 else 70
    with Store(db, create=False) as store:
        assert store.count() == ran == store.meta("total")
        assert store.integrity() == "ok"
    same = tmp_path / "same.db"
    sweep = "design.ball_weight=1.8 kgf:2.2 kgf:200"
    a = _start(cli, HARTNELL, same, sweep, "--resume")
    b = _start(cli, HARTNELL, same, sweep, "--resume")
    for p in (a, b):
        out, err = p.communicate(timeout=300)
        assert p.returncode in (0, 1) and "points: 200 of 200 done" in out, err
    with Store(same, create=False) as store:
        assert store.count() == 200
        assert sorted(store.table()["point"]) == list(range(200))


def test_sweep_and_tolerance_errors_name_the_key_and_spec(tmp_path):
    with pytest.raises(StudyError, match=r"^.*hartnell.toml: study: sweep design.ball_weight: "
                                         r"cannot read '9\*\*9\*\*9 kgf'"):
        load_study(HARTNELL, sweeps=["design.ball_weight=9**9**9 kgf:3 kgf:3"])
    with pytest.raises(StudyError, match=r"hartnell.toml: study: tolerance design.bogus: the "
                                         "spec has no numeric value there"):
        load_study(HARTNELL, tolerances=["design.bogus=+-1%"], samples=4)
    assert not (tmp_path / "t.db").exists()


def test_a_point_is_never_held_twice(tmp_path):
    """A grid whose list holds a value twice, a zip whose values repeat in step and a key swept
    twice are refused when the study is defined (one line naming the sweep): each point of a
    study is one row, its number the database's key."""
    spec = SPECS / "hamabe-a.toml"
    with pytest.raises(StudyError, match=r"sweep design.pendulum_weight: '12 kgf' is listed "
                                         "twice"):
        load_study(spec, sweeps=["design.pendulum_weight=12 kgf,10 kgf,12 kgf",
                                 "speed.irregularity=0.12,0.11"])
    with pytest.raises(StudyError, match="points 0 and 2 are the same"):
        load_study(spec, sweeps=["design.pendulum_weight=12 kgf,10 kgf,12 kgf",
                                 "speed.irregularity=0.12,0.11,0.12"], combine="zip")
    with pytest.raises(StudyError, match="--sweep: design.pendulum_weight is given twice"):
        load_study(spec, sweeps=["design.pendulum_weight=12 kgf,10 kgf",
                                 "design.pendulum_weight=8 kgf"])
    # the same value in step with different others: two points
    assert load_study(STUDY).count() == 5
