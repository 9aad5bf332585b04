"""Speed of bulk evaluation and trade studies, as ratios against baselines timed in the same run.

* ``evaluate_many`` (the vectorised evaluate-mode path) for ``--points`` designs of Hamabe's case
  a (the pendulum weight and the spring's turns scattered), statics and k^2 only, then (a tenth
  of them) with the load-change transient (eq. 28: roots, Hurwitz margin, over-regulation and
  settling located exactly by ``transient.analyse_many``), against per-design loops timed on a
  subsample: ``govopt.evaluate`` itself, and a bare loop of the same statics and k^2
  (``statics.spring_design``, ``characteristic``, ``restoring_k2``);
* a whole evaluate-mode study of ``--points`` points (points, parsing, evaluation, typed rows,
  SQLite) against ``evaluate_many`` alone on the same points: the study's and the database's
  overhead per row, and the database's alone (``Store.add`` of the rows);
* a design-mode study (the spring-loaded governor of ``spring_loaded-design`` over ``--designs``
  upper speeds) with 1 and 2 worker processes;
* the peak memory (maximum resident set size, ``os.wait4``) and time of each command of a
  ``--memory-points`` study (10^6 by default, the documented limit; 0 skips it), each in a
  process of its own: ``study run`` (with its summary), ``study show``, ``study export`` to CSV
  and to Parquet, ``study export --plot``; for this tree and for a baseline (``--baseline-ref``,
  default ``main``: its files taken with ``git archive`` into a temporary folder, so the
  implementation the study replaced is measured as it was), one command after the other, in
  the same run, with the ratios (points per second, peak memory) of this tree to it.

Run:  python benchmarks/bench_study.py [--points 100000] [--baseline 200] [--designs 24]
      [--memory-points 1000000] [--baseline-ref main]
:func:`run` returns the numbers as a dict. Never used as timed assertions in the tests.
The bulk rates are CPU time (``time.process_time``, medians of ``--repeats``): the machine is
shared, and wall time measures the neighbours.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

import numpy as np

from govopt.bench.bulk import bulk_bench

SPECS = Path(__file__).resolve().parent.parent / "specs"


def study_bench(points: int = 100_000) -> dict:
    """A whole evaluate-mode study (statics and k^2: points, parsing, evaluation, typed rows,
    SQLite) against ``evaluate_many`` on the same points, and the database's own cost per row
    (``Store.add`` of the rows, one transaction per 1024)."""
    from govopt.bulk import evaluate_many
    from govopt.study import Store, load_study, run_chunk, run_study

    sweep = f"design.pendulum_weight=10 kgf:14 kgf:{points}"
    study = load_study(SPECS / "hamabe-a.toml", sweeps=[sweep],
                       skip="dynamics,vibration,classic")
    masses = np.linspace(10.0, 14.0, points)
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        run_study(study, Path(tmp) / "bench.db")
        study_s = time.perf_counter() - t0
        t0 = time.perf_counter()
        evaluate_many(study.base(), {"flying_mass": masses}, dynamics=False, vibration=False,
                      classic=False)
        bulk_s = time.perf_counter() - t0
        text = json.dumps(study.definition(), sort_keys=True)
        blocks = [run_chunk(text, np.arange(s, min(s + 1024, points)))
                  for s in range(0, points, 1024)]
        with Store(Path(tmp) / "bench2.db") as store:
            store.claim(study.definition(), points)
            store.start()
            t0 = time.perf_counter()
            for rows in blocks:
                store.add(rows)
            insert_s = time.perf_counter() - t0
        size = (Path(tmp) / "bench2.db").stat().st_size
    return {
        "points": points, "study_s": study_s, "evaluate_many_s": bulk_s,
        "study_points_per_s": points / study_s,
        "study_overhead_per_row_us": 1e6 * (study_s - bulk_s) / points,
        "sqlite_insert_per_row_us": 1e6 * insert_s / points,
        "database_bytes_per_row": size / points,
        "database_share_of_study": insert_s / study_s,
    }


def design_bench(designs: int = 24) -> dict:
    """A design-mode study: the spring-loaded governor of ``spring_loaded-design`` (balls and
    ball springs, ~0.1-3 s a design) for ``designs`` upper speeds from 330 to 350 rpm, designs
    per second on 1 and 2 worker processes (the same table)."""
    from govopt.study import Store, load_study, run_study
    from govopt.study.rows import clear_caches

    sweeps = [f"speed.outer=330 rpm:350 rpm:{designs}"]
    out = {"spec": "spring_loaded-design", "designs": designs}
    tables = []
    with tempfile.TemporaryDirectory() as tmp:
        # warm up (imports, the solver's compiled problems) on another speed, outside the timing
        run_study(load_study(SPECS / "spring_loaded-design.toml",
                             sweeps=["speed.outer=345.5 rpm"]), Path(tmp) / "warm.db")
        for workers in (1, 2):
            clear_caches()  # no spec parsed ahead for the timed run
            study = load_study(SPECS / "spring_loaded-design.toml", sweeps=sweeps)
            t0 = time.perf_counter()
            run_study(study, Path(tmp) / f"d{workers}.db", workers=workers)
            out[f"designs_per_s_{workers}_workers"] = designs / (time.perf_counter() - t0)
            with Store(Path(tmp) / f"d{workers}.db") as store:
                tables.append(store.table())
    out["speedup_2_workers"] = out["designs_per_s_2_workers"] / out["designs_per_s_1_workers"]
    out["same_table"] = bool(tables[0].equals(tables[1]))
    out["statuses"] = tables[0]["status"].value_counts().to_dict()
    return out


def _peak(args: list[str], cwd: str, tree: Path) -> dict:
    """Run ``python -m govopt.cli ARGS`` with govopt from ``tree`` in a process of its own: its
    peak resident memory (MB), wall and CPU seconds, exit status."""
    import os
    import subprocess
    import sys

    env = {**os.environ, "PYTHONPATH": str(tree)}
    t0 = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "govopt.cli", *args], cwd=cwd, env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    return {"peak_rss_MB": usage.ru_maxrss / 1024.0, "wall_s": time.perf_counter() - t0,
            "cpu_s": usage.ru_utime + usage.ru_stime, "exit": os.waitstatus_to_exitcode(status)}


def baseline_tree(ref: str, folder: Path) -> Path:
    """The files of ``ref`` (a commit of this repository) in ``folder`` (``git archive``)."""
    import io
    import subprocess
    import tarfile

    root = Path(__file__).resolve().parent.parent
    tar = subprocess.run(["git", "-C", str(root), "archive", ref, "govopt"], check=True,
                         capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(tar)) as archive:
        archive.extractall(folder, filter="data")
    return folder


def _commands(points: int, spec: str) -> dict[str, list[str]]:
    return {
        "study_run": ["study", "run", spec, "--sweep",
                      f"design.pendulum_weight=10 kgf:14 kgf:{points}",
                      "--skip", "dynamics,vibration,classic", "--db", "s.db"],
        "study_show": ["study", "show", "s.db"],
        "export_csv": ["study", "export", "s.db", "--out", "t.csv"],
        "export_parquet": ["study", "export", "s.db", "--out", "t.parquet"],
        "export_plot": ["study", "export", "s.db", "--out", "u.csv", "--plot", "p"],
    }


def memory_bench(points: int = 1_000_000, baseline_ref: str | None = "main") -> dict:
    """Peak memory and time of a ``points``-point evaluate-mode study (case a's pendulum weight
    swept, statics and k^2) through the command line: run, show, export (CSV, Parquet), plots;
    for this tree and, in the same run, the ``baseline_ref`` tree, with this tree's ratios to
    it."""
    spec = str(SPECS / "hamabe-a.toml")
    here = SPECS.parent.parent
    out: dict = {"points": points}
    with tempfile.TemporaryDirectory() as tmp:
        trees = {"this": here}
        if baseline_ref:
            trees["baseline"] = baseline_tree(baseline_ref, Path(tmp) / "baseline")
            out["baseline_ref"] = baseline_ref
        for name, tree in trees.items():
            work = Path(tmp) / f"work-{name}"
            work.mkdir()
            runs = {cmd: _peak(args, str(work), tree) for cmd, args in
                    _commands(points, spec).items()}
            run = runs["study_run"]
            run["points_per_s_wall"] = points / run["wall_s"]
            run["points_per_s_cpu"] = points / run["cpu_s"]
            runs["database_MB"] = (work / "s.db").stat().st_size / 2**20
            runs["largest_peak_rss_MB"] = max(v["peak_rss_MB"] for v in runs.values()
                                              if isinstance(v, dict))
            out[name] = runs
    if "baseline" in out:
        a, b = out["this"], out["baseline"]
        out["ratios_this_to_baseline"] = {
            "points_per_s_cpu": a["study_run"]["points_per_s_cpu"]
            / b["study_run"]["points_per_s_cpu"],
            "points_per_s_wall": a["study_run"]["points_per_s_wall"]
            / b["study_run"]["points_per_s_wall"],
            **{f"peak_rss_{k}": a[k]["peak_rss_MB"] / b[k]["peak_rss_MB"]
               for k in _commands(1, spec)},
            "database_size": a["database_MB"] / b["database_MB"]}
    return out


def run(points: int = 100_000, baseline: int = 200, designs: int = 24, repeats: int = 3,
        memory_points: int = 1_000_000, baseline_ref: str | None = "main") -> dict:
    out = {"bulk": bulk_bench(points, baseline, repeats), "study": study_bench(points),
           "design": design_bench(designs)}
    if memory_points:
        out["memory"] = memory_bench(memory_points, baseline_ref)
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--baseline", type=int, default=200)
    ap.add_argument("--designs", type=int, default=24)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--memory-points", type=int, default=1_000_000)
    ap.add_argument("--baseline-ref", default="main",
                    help="the commit whose study commands are measured beside this tree's "
                         "('' for none)")
    ap.add_argument("--only-memory", action="store_true",
                    help="measure the commands' memory and time only")
    args = ap.parse_args()
    if args.only_memory:
        result = memory_bench(args.memory_points, args.baseline_ref or None)
    else:
        result = run(args.points, args.baseline, args.designs, args.repeats,
                     args.memory_points, args.baseline_ref or None)
    print(json.dumps(result, indent=2))
