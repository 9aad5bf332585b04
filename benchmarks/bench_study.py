"""Speed of bulk evaluation and trade studies, as ratios against baselines timed in the same run.

* ``evaluate_many`` (the vectorised evaluate-mode path) for ``--points`` designs of Hamabe's case
  a (the pendulum weight and the spring's turns scattered), statics and k^2 only, then (a tenth
  of them) with the load-change transient (eq. 28: roots, Hurwitz margin, over-regulation and
  settling located exactly by ``transient.analyse_many``), against per-design loops timed on a
  subsample: ``govopt.evaluate`` itself, and a bare loop of the same statics and k^2
  (``statics.spring_design``, ``characteristic``, ``restoring_k2``);
* a whole evaluate-mode study of ``--points`` points (point list, hashes, SQLite) against
  ``evaluate_many`` alone on the same points: the study's and the database's overhead per row,
  and the database's alone (``Store.add`` of the rows, JSON included);
* a design-mode study (the spring-loaded governor of ``spring_loaded-design`` over ``--designs``
  upper speeds) with 1 and 2 worker processes;
* the peak memory (maximum resident set size, ``os.wait4``) of each command of a
  ``--memory-points`` study (10^6 by default, the documented limit; 0 skips it), each in a
  process of its own: ``study run`` (with its summary), ``study show``, ``study export`` to CSV
  and to Parquet, ``study export --plot``; with the run's points per second (wall and CPU).

Run:  python benchmarks/bench_study.py [--points 100000] [--baseline 200] [--designs 24]
      [--memory-points 1000000]
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

SPECS = Path(__file__).resolve().parent.parent / "govopt" / "specs"


def _designs(spec, n: int, seed: int = 0) -> dict:
    rng = np.random.default_rng(seed)
    return {"flying_mass": spec.design.flying_mass * rng.uniform(0.8, 1.2, n),
            "active_turns": spec.design.active_turns * rng.uniform(0.9, 1.1, n)}


def _loop(fn, items) -> float:
    t0 = time.process_time()
    for it in items:
        fn(it)
    return (time.process_time() - t0) / len(items)


def _cpu(fn, repeats: int) -> float:
    """Median CPU seconds of ``fn()`` over ``repeats`` calls."""
    times = []
    for _ in range(repeats):
        t0 = time.process_time()
        fn()
        times.append(time.process_time() - t0)
    return float(np.median(times))


def bulk_bench(points: int = 100_000, baseline: int = 200, repeats: int = 3) -> dict:
    """evaluate_many against per-design loops (CPU seconds per design, designs per second)."""
    from govopt import evaluate, load_spec
    from govopt.analysis import statics
    from govopt.bulk import evaluate_many
    from govopt.spec import Design

    spec = load_spec(SPECS / "hamabe-a.toml")
    cols = _designs(spec, points)
    designs = [Design(**{**spec.design.__dict__, "flying_mass": float(m),
                         "active_turns": float(n)})
               for m, n in zip(cols["flying_mass"][:baseline], cols["active_turns"][:baseline],
                               strict=True)]
    evaluate_many(spec, {k: v[:64] for k, v in cols.items()})  # warm caches and imports

    def bare(d):
        s = spec.with_design(d)
        sd = statics.spring_design(s, d)
        ch = statics.characteristic(s, sd)
        statics.restoring_k2(s, ch.alpha, sd, ch.omega**2)

    per_bare = _loop(bare, designs)
    per_evaluate = _loop(lambda d: evaluate(spec.with_design(d)), designs)
    frame = evaluate_many(spec, cols, dynamics=False, vibration=False, classic=False)
    statics_s = _cpu(lambda: evaluate_many(spec, cols, dynamics=False, vibration=False,
                                           classic=False), repeats)
    n_dyn = max(1, points // 10)
    sub = {k: v[:n_dyn] for k, v in cols.items()}
    dynamics_s = _cpu(lambda: evaluate_many(spec, sub, vibration=False, classic=False), repeats)
    return {
        "spec": "hamabe-a (pendulum weight +-20 %, turns +-10 %)",
        "points": points, "passed": int((frame["status"] == "pass").sum()),
        "statics_k2_vectorised_points_per_s": points / statics_s,
        "statics_k2_bare_loop_points_per_s": 1.0 / per_bare,
        "evaluate_loop_points_per_s": 1.0 / per_evaluate,
        "statics_k2_speedup_vs_bare_loop": per_bare * points / statics_s,
        "statics_k2_speedup_vs_evaluate_loop": per_evaluate * points / statics_s,
        "with_transient_points": n_dyn,
        "with_transient_vectorised_points_per_s": n_dyn / dynamics_s,
        "with_transient_speedup_vs_evaluate_loop": per_evaluate * n_dyn / dynamics_s,
        "baseline_designs": baseline, "timing": f"CPU, median of {repeats}",
    }


def study_bench(points: int = 100_000) -> dict:
    """A whole evaluate-mode study (statics and k^2: point list, hashes, parsing, evaluation,
    encoding, SQLite) against ``evaluate_many`` on the same points, and the database's own cost
    per row (encoding the rows and inserting them, one transaction per 1024)."""
    from govopt.bulk import evaluate_many
    from govopt.study import Store, encode, load_study, run_study

    sweep = f"design.pendulum_weight=10 kgf:14 kgf:{points}"
    study = load_study(SPECS / "hamabe-a.toml", sweeps=[sweep],
                       skip="dynamics,vibration,classic")
    masses = np.linspace(10.0, 14.0, points)
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        run_study(study, Path(tmp) / "bench.db")
        study_s = time.perf_counter() - t0
        t0 = time.perf_counter()
        frame = evaluate_many(study.base(), {"flying_mass": masses}, dynamics=False,
                              vibration=False, classic=False)
        bulk_s = time.perf_counter() - t0
        hashes = [f"{i:064x}" for i in range(points)]
        t0 = time.perf_counter()
        chunks = [encode(frame.iloc[s:s + 1024], hashes[s:s + 1024],
                         list(range(s, min(s + 1024, points))))
                  for s in range(0, points, 1024)]
        encode_s = time.perf_counter() - t0
        with Store(Path(tmp) / "bench2.db") as store:
            t0 = time.perf_counter()
            for c in chunks:
                store.add(c)
            insert_s = time.perf_counter() - t0
            size = (Path(tmp) / "bench2.db").stat().st_size + (
                Path(tmp) / "bench2.db-wal").stat().st_size
    return {
        "points": points, "study_s": study_s, "evaluate_many_s": bulk_s,
        "study_points_per_s": points / study_s,
        "study_overhead_per_row_us": 1e6 * (study_s - bulk_s) / points,
        "encode_per_row_us": 1e6 * encode_s / points,
        "sqlite_insert_per_row_us": 1e6 * insert_s / points,
        "database_bytes_per_row": size / points,
        "database_share_of_study": (encode_s + insert_s) / study_s,
    }


def design_bench(designs: int = 24) -> dict:
    """A design-mode study: the spring-loaded governor of ``spring_loaded-design`` (balls and
    ball springs, ~0.1-3 s a design) for ``designs`` upper speeds from 330 to 350 rpm, designs
    per second on 1 and 2 worker processes (the same table)."""
    from govopt import study as st
    from govopt.study import Store, load_study, run_study

    sweeps = [f"speed.outer=330 rpm:350 rpm:{designs}"]
    out = {"spec": "spring_loaded-design", "designs": designs}
    tables = []
    with tempfile.TemporaryDirectory() as tmp:
        # warm up (imports, the solver's compiled problems) on another speed, outside the timing
        run_study(load_study(SPECS / "spring_loaded-design.toml",
                             sweeps=["speed.outer=345.5 rpm"]), Path(tmp) / "warm.db")
        for workers in (1, 2):
            st._VARIANTS.clear()  # no spec parsed ahead for the timed run
            st._LINEAR.clear()
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


def _peak(args: list[str], cwd: str) -> dict:
    """Run ``python -m govopt.cli ARGS`` in a process of its own: its peak resident memory
    (MB), wall and CPU seconds, exit status."""
    import os
    import subprocess
    import sys

    env = {**os.environ, "PYTHONPATH": str(SPECS.parent.parent)}
    t0 = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "govopt.cli", *args], cwd=cwd, env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return {"peak_rss_MB": usage.ru_maxrss / 1024.0, "wall_s": time.perf_counter() - t0,
            "cpu_s": usage.ru_utime + usage.ru_stime, "exit": proc.returncode}


def memory_bench(points: int = 1_000_000) -> dict:
    """Peak memory of a ``points``-point evaluate-mode study (case a's pendulum weight swept,
    statics and k^2) through the command line: run, show, export (CSV, Parquet), plots."""
    spec = str(SPECS / "hamabe-a.toml")
    out: dict = {"points": points}
    with tempfile.TemporaryDirectory() as tmp:
        out["study_run"] = _peak(["study", "run", spec, "--sweep",
                                  f"design.pendulum_weight=10 kgf:14 kgf:{points}",
                                  "--skip", "dynamics,vibration,classic", "--db", "s.db"], tmp)
        run = out["study_run"]
        run["points_per_s_wall"] = points / run["wall_s"]
        run["points_per_s_cpu"] = points / run["cpu_s"]
        out["study_show"] = _peak(["study", "show", "s.db"], tmp)
        out["export_csv"] = _peak(["study", "export", "s.db", "--out", "t.csv"], tmp)
        out["export_parquet"] = _peak(["study", "export", "s.db", "--out", "t.parquet"], tmp)
        out["export_plot"] = _peak(["study", "export", "s.db", "--out", "u.csv", "--plot", "p"],
                                   tmp)
    out["largest_peak_rss_MB"] = max(v["peak_rss_MB"] for v in out.values()
                                     if isinstance(v, dict))
    return out


def run(points: int = 100_000, baseline: int = 200, designs: int = 24, repeats: int = 3,
        memory_points: int = 1_000_000) -> dict:
    out = {"bulk": bulk_bench(points, baseline, repeats), "study": study_bench(points),
           "design": design_bench(designs)}
    if memory_points:
        out["memory"] = memory_bench(memory_points)
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--baseline", type=int, default=200)
    ap.add_argument("--designs", type=int, default=24)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--memory-points", type=int, default=1_000_000)
    args = ap.parse_args()
    print(json.dumps(run(args.points, args.baseline, args.designs, args.repeats,
                         args.memory_points), indent=2))
