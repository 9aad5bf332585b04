"""Trade studies in bounded memory: a range's values made as they are taken (the same points
as its values written out), the database read, exported, summarised and plotted a batch at a
time with the whole table's results."""

import itertools
import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from govopt.study import (
    Store,
    Study,
    export,
    load_study,
    pareto_front,
    pareto_points,
    run_study,
    summary_text,
)

SPECS = Path(__file__).resolve().parent.parent / "specs"


@pytest.mark.parametrize("sweeps, combine", [
    (["design.pendulum_weight=10 kgf:14 kgf:23", "design.active_turns=6:9:4"], "grid"),
    (["design.active_turns=6:9:4", "speed.irregularity=0.1:0.12:17"], "grid"),
    (["speed.irregularity=0.1:0.12:19", "design.wire_diameter=1.6 cm:1.8 cm:19"], "zip"),
])
def test_points_are_made_from_their_numbers(sweeps, combine):
    """A block of points is made from the definition and the points' numbers alone: the
    same values as the ranges written out (np.linspace) combined as a product (the last key
    fastest) or in step, and a definition that reads back as the same study."""
    study = load_study(SPECS / "hamabe-a.toml", sweeps=sweeps, combine=combine)
    columns = [[s.toml(v) for v in s.at(np.linspace(0.0, 1.0, len(s)))] for s in study.sweeps]
    rows = itertools.product(*columns) if combine == "grid" else zip(*columns, strict=True)
    points = [dict(zip(study.keys, r, strict=True)) for r in rows]
    assert study.points() == points
    block = np.array([3, 1, len(points) - 1])
    values = study.values(block)
    assert [{k: study.toml(k, values[k][j]) for k in study.keys} for j in range(3)] == [
        points[i] for i in block]
    again = Study.from_definition(json.loads(json.dumps(study.definition())))
    assert again.points() == points


def test_a_million_point_sweep_is_not_held():
    """A 10^6-point range is its ends and count: the study's definition (stored in the database
    and sent to every worker) stays a few kB, not the ~20 MB of its values."""
    study = load_study(SPECS / "hamabe-a.toml",
                       sweeps=["design.pendulum_weight=10 kgf:14 kgf:1000000"])
    s = study.sweeps[0]
    assert len(s) == 1_000_000 and s.values == ()
    assert len(json.dumps(study.definition())) < 20_000
    assert [s.toml(v) for v in s.take([0, 999_999])] == ["10 kgf", "14 kgf"]
    assert s.take([500_000])[0] == 10 + 4 * np.linspace(0, 1, 1_000_000)[500_000]


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
        front = list(pareto_points(store, batch=5))
        assert front == list(table.loc[table["pareto"], "point"])
        assert front == list(table.loc[pareto_front(
            table, ["moving_mass", "max:k2_margin"]), "point"])
        from govopt.report.study_workbook import write_workbook

        for ext in ("csv", "parquet"):
            export(store, tmp_path / f"small.{ext}", batch=5)
            export(store, tmp_path / f"whole.{ext}", batch=1000)
        write_workbook(store, tmp_path / "small.xlsx", batch=5, plots=False)
        write_workbook(store, tmp_path / "whole.xlsx", batch=1000, plots=False)
    assert (tmp_path / "small.csv").read_bytes() == (tmp_path / "whole.csv").read_bytes()
    csv = pd.read_csv(tmp_path / "small.csv")
    assert [c.split(" [")[0] for c in csv.columns] == list(table.columns)
    assert list(csv["pareto"]) == list(table["pareto"])
    pd.testing.assert_frame_equal(pd.read_parquet(tmp_path / "small.parquet"),
                                  pd.read_parquet(tmp_path / "whole.parquet"))
    for sheet in ("Table", "Data"):
        pd.testing.assert_frame_equal(pd.read_excel(tmp_path / "small.xlsx", sheet_name=sheet),
                                      pd.read_excel(tmp_path / "whole.xlsx", sheet_name=sheet))


def test_export_of_a_column_of_numbers_then_texts(tmp_path):
    """A swept key written as numbers and as a text is a column of texts as written (its
    type is the sweep's, not the first batch's): the database, Parquet and the workbook
    agree."""
    from govopt.report.study_workbook import write_workbook

    study = load_study(SPECS / "hamabe-a.toml", sweeps=['design.active_turns=8,7,"6"'],
                       skip="dynamics,vibration,classic")
    run_study(study, tmp_path / "m.db")
    with Store(tmp_path / "m.db", create=False) as store:
        export(store, tmp_path / "m.parquet", batch=2)
        write_workbook(store, tmp_path / "m.xlsx", batch=2, plots=False)
        assert list(store.table()["design_active_turns"]) == ["8", "7", '"6"']
    frame = pd.read_parquet(tmp_path / "m.parquet")
    assert list(frame["design_active_turns"]) == ["8", "7", '"6"']
    data = pd.read_excel(tmp_path / "m.xlsx", sheet_name="Data")
    assert list(data["design_active_turns"].astype(str)) == ["8", "7", '"6"']


def test_plots_of_a_large_study_draw_every_kth_point(grid_db, tmp_path):
    """Beyond max_points rows the sweep plots draw one point in k (said on the plot) and the
    Pareto front whole; the constraints drawn are chosen over every row."""
    from govopt.report.study_plots import plot_study

    with Store(grid_db, create=False) as store:  # the SVGs, read below (PNGs: test_study.py)
        files = {p.name for p in plot_study(store, tmp_path / "p", max_points=10,
                                            formats=("svg",))}
        front = len(pareto_points(store))
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
    best = table.loc[ok].sort_values("objective_value", kind="stable")
    first = best.iloc[0]
    assert (f"best feasible point: {int(first['point'])}, moving mass "
            f"{first['objective_value']:.4g} kg ({len(best)} feasible)") in text
    rows = text.split("in the spec's units:\n", 1)[1].splitlines()[1:6]
    assert [int(r.split()[0]) for r in rows] == list(best["point"][:5])


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
