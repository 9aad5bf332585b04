"""Trade studies in bounded memory (issue 21): a large range sweep's values made as they are
taken (the same points and the same study key as written out), the database read, exported,
summarised and plotted a batch at a time with the whole table's results."""

import itertools
import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from govopt import study as st
from govopt.study import Store, export, load_study, pareto_front, run_study, summary_text

SPECS = Path(__file__).resolve().parent.parent / "govopt" / "specs"


def _written_out(study: st.Study) -> st.Study:
    """The study with every range's values written out (as govopt stored them before)."""
    return st.replace(study, sweeps=tuple(
        st.replace(s, values=s.at(np.linspace(0.0, 1.0, len(s.values))))
        if isinstance(s.values, st.RangeValues) else s for s in study.sweeps))


@pytest.mark.parametrize("sweeps, combine", [
    (["design.pendulum_weight=10 kgf:14 kgf:23", "design.active_turns=6:9:3"], "grid"),
    (["design.active_turns=6:9:4", "speed.irregularity=0.1:0.12:17"], "grid"),
    (["speed.irregularity=0.1:0.12:19", "design.wire_diameter=1.6 cm:1.8 cm:19"], "zip"),
])
def test_range_values_are_the_written_out_values(monkeypatch, sweeps, combine):
    """A range of more than LAZY_VALUES values (here 8) is kept as its ends and count: the
    same values, points in the same order (the last key fastest), spans and study key as the
    values written out, and a definition that reads back as the same study."""
    monkeypatch.setattr(st, "LAZY_VALUES", 8)
    study = load_study(SPECS / "hamabe-a.toml", sweeps=sweeps, combine=combine)
    assert any(isinstance(s.values, st.RangeValues) for s in study.sweeps)
    eager = _written_out(study)
    for lazy, full in zip(study.sweeps, eager.sweeps, strict=True):
        assert lazy.values == full.values and list(lazy.values) == list(full.values)
        assert lazy.values[-1] == full.values[-1] and lazy.values[2:5] == full.values[2:5]
    columns = [s.values for s in eager.sweeps]
    rows = itertools.product(*columns) if combine == "grid" else zip(*columns, strict=True)
    points = [dict(zip(study.keys, r, strict=True)) for r in rows]
    assert list(study.iter_points()) == points
    assert study.spans() == st._spans(points)
    assert st.study_digest(study.definition()) == st.study_digest(eager.definition())
    again = st.Study.from_definition(json.loads(json.dumps(study.definition())))
    assert list(again.iter_points()) == points


def test_a_million_point_sweep_is_not_held():
    """A 10^6-point range is its ends and count: the study's definition (stored in the database
    and sent to every worker) stays a few kB, not the ~20 MB of its values."""
    study = load_study(SPECS / "hamabe-a.toml",
                       sweeps=["design.pendulum_weight=10 kgf:14 kgf:1000000"])
    values = study.sweeps[0].values
    assert isinstance(values, st.RangeValues) and len(values) == 1_000_000
    assert len(json.dumps(study.definition())) < 20_000
    assert values[0] == "10 kgf" and values[-1] == "14 kgf"
    assert values[500_000] == f"{10 + 4 * np.linspace(0, 1, 1_000_000)[500_000]:.15g} kgf"


def test_a_database_of_written_out_values_is_resumed(tmp_path, monkeypatch):
    """A database whose study was stored with its range written out (before RangeValues)
    belongs to the same study: --resume continues it, nothing refused or run twice."""
    spec = SPECS / "hamabe-a.toml"
    sweeps = ["design.pendulum_weight=10 kgf:14 kgf:12"]
    old = load_study(spec, sweeps=sweeps, skip="dynamics,vibration,classic")
    assert not isinstance(old.sweeps[0].values, st.RangeValues)
    run_study(old, tmp_path / "s.db", chunk=4)
    monkeypatch.setattr(st, "LAZY_VALUES", 5)
    new = load_study(spec, sweeps=sweeps, skip="dynamics,vibration,classic")
    assert isinstance(new.sweeps[0].values, st.RangeValues)
    report = run_study(new, tmp_path / "s.db", resume=True)
    assert (report.skipped, report.done) == (12, 0)


@pytest.fixture(scope="module")
def grid_db(tmp_path_factory):
    """A 13 x 3 grid with a Pareto front of three points, in a database."""
    db = tmp_path_factory.mktemp("grid") / "g.db"
    study = load_study(SPECS / "hamabe-a.toml", sweeps=[
        "design.pendulum_weight=8 kgf:14 kgf:13", "design.wire_diameter=1.5,1.6,1.7 cm"],
        pareto=["moving_mass", "max:k2_margin"], skip="vibration,classic")
    run_study(study, db)
    return db


def test_batches_pareto_and_exports_equal_the_whole_table(grid_db, tmp_path):
    """Read 5 rows at a time: the batches make the whole table, the front found batch by batch
    is the whole table's, and the exports written by batches are those of one batch."""
    with Store(grid_db, create=False) as store:
        table = store.table()
        assert table["pareto"].sum() >= 2  # a front worth finding batch by batch
        parts = list(store.batches(batch=5))
        assert len(parts) == 8 and all(len(p) <= 5 for p in parts)
        pd.testing.assert_frame_equal(pd.concat(parts, ignore_index=True),
                                      table.drop(columns="pareto"))
        assert list(store.pareto(batch=5)) == list(table.loc[table["pareto"], "point"])
        assert list(store.pareto(batch=5)) == list(table.loc[pareto_front(
            table, ["moving_mass", "max:k2_margin"]), "point"])
        for ext in ("csv", "parquet", "xlsx"):
            export(store, tmp_path / f"small.{ext}", batch=5)
            export(store, tmp_path / f"whole.{ext}", batch=1000)
    assert (tmp_path / "small.csv").read_bytes() == (tmp_path / "whole.csv").read_bytes()
    csv = pd.read_csv(tmp_path / "small.csv")
    assert list(csv.columns) == list(table.columns)
    assert list(csv["pareto"]) == list(table["pareto"])
    pd.testing.assert_frame_equal(pd.read_parquet(tmp_path / "small.parquet"),
                                  pd.read_parquet(tmp_path / "whole.parquet"))
    pd.testing.assert_frame_equal(pd.read_excel(tmp_path / "small.xlsx"),
                                  pd.read_excel(tmp_path / "whole.xlsx"))


def test_export_of_a_column_of_numbers_then_texts(tmp_path):
    """A swept key written as numbers in the first batch and as text further on is text
    throughout the Parquet file (a file's column has one type), not a failed export."""
    study = load_study(SPECS / "hamabe-a.toml", sweeps=['design.active_turns=8,7,"6"'],
                       skip="dynamics,vibration,classic")
    run_study(study, tmp_path / "m.db")
    with Store(tmp_path / "m.db", create=False) as store:
        export(store, tmp_path / "m.parquet", batch=2)
        export(store, tmp_path / "m.xlsx", batch=2)
    frame = pd.read_parquet(tmp_path / "m.parquet")
    assert list(frame["design.active_turns"]) == ["8", "7", '"6"']
    assert list(pd.read_excel(tmp_path / "m.xlsx")["design.active_turns"].astype(str)) == [
        "8", "7", '"6"']


def test_plots_of_a_large_study_draw_every_kth_point(grid_db, tmp_path):
    """Beyond max_points rows the sweep plots draw one point in k (said on the plot) and the
    Pareto front whole; the constraints drawn are chosen over every row."""
    from govopt.report.study_plots import plot_study

    with Store(grid_db, create=False) as store:  # the SVGs, read below (PNGs: test_study.py)
        files = {p.name for p in plot_study(store, tmp_path / "p", max_points=10,
                                            formats=("svg",))}
        front = len(store.pareto())
        plot_study(store, tmp_path / "all", formats=("svg",))
    assert "pareto.svg" in files and "sweep-design.pendulum_weight.svg" in files
    sweep = (tmp_path / "p" / "sweep-design.pendulum_weight.svg").read_text()
    assert "one point in 4 drawn" in sweep
    pareto = (tmp_path / "p" / "pareto.svg").read_text()
    assert "off it one point in 4 drawn" in pareto and f"{front} of " in pareto
    whole = (tmp_path / "all" / "sweep-design.pendulum_weight.svg").read_text()
    assert "drawn" not in whole
    # the same constraints (their titles) whether every point is drawn or one in four
    titles = [t for t in whole.split("<!-- ")[1:] if "(margin &lt; 0: fails)" in t[:200]]
    assert titles and all(t.split(" -->")[0] in sweep for t in titles)


def test_summary_is_the_whole_tables(grid_db):
    """`study show` reads a batch at a time: its status counts and best point are the
    whole table's."""
    with Store(grid_db, create=False) as store:
        table = store.table()
        text = summary_text(store)
    counts = table["status"].value_counts()
    assert "status: " + ", ".join(f"{k} {v}" for k, v in counts.items()) in text
    ok = table["status"].isin(["pass", "optimal"]) & table["objective_value"].notna()
    best = table.loc[ok].sort_values("objective_value", kind="stable").iloc[0]
    assert f"{best['objective_value']:.6g} at point {int(best['point'])} " in text


def test_plots_of_a_study_whose_every_point_is_an_error(tmp_path):
    """No row has an objective or a check: the plots are drawn (empty), not a KeyError."""
    from govopt.report.study_plots import plot_study

    study = load_study(SPECS / "hamabe-a.toml", sweeps=["design.pendulum_weight=-1,-2 kgf"],
                       pareto=["moving_mass", "settling_time"])
    run_study(study, tmp_path / "e.db")
    with Store(tmp_path / "e.db", create=False) as store:
        assert set(store.table()["status"]) == {"error"}
        files = {p.name for p in plot_study(store, tmp_path / "p")}
    assert files == {"sweep-design.pendulum_weight.png", "sweep-design.pendulum_weight.svg",
                     "pareto.png", "pareto.svg"}
