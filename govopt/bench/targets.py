"""The speed targets beside what was measured: ``design()`` in process, whole-process times of
the commands against ``python -c pass`` timed in the same run, the peak memory of a design over
48 million combinations and the bulk evaluation (:mod:`govopt.bench.bulk`).
"""

from __future__ import annotations

import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from .bulk import bulk_bench
from .suites import SPECS, cpu_per_call

#: The speed targets (docs/decisions.md, imports on demand): name -> (limit, unit, what is measured)
TARGETS = {
    "design() in process": (0.1, "s CPU", "median CPU of design(), bundled hamabe-design"),
    "govopt --help": (0.3, "s CPU", "whole process, median user + system time"),
    "govopt evaluate": (0.5, "s CPU", "whole process, median user + system (bundled hamabe-a)"),
    "govopt design": (0.6, "s CPU", "whole process, median user + system (hamabe-design)"),
    "peak RSS, 48 M combinations": (1024.0, "MB", "design() in a child process"),
    "evaluate_many, statics + k^2": (1e5, "designs/s", "CPU, hamabe-a designs scattered",
                                     ">="),
    "evaluate_many, + load change": (3e4, "designs/s", "CPU, the same with the transient",
                                     ">="),
}


def design_in_process(repeats: int = 7) -> dict:
    """Median CPU of ``design()`` on the bundled spec (after one warm-up), its stages, and a
    check that its bound (pruned masses, certified by the energy bound where it is attained)
    equals the GP solved by cvxpy at every mass."""
    from ..optimize import design as dz
    from ..optimize.spring_gp import cached_gp
    from ..spec import load_spec

    spec = load_spec(SPECS / "hamabe-design.toml")
    dz.design(spec)
    times = []
    for _ in range(repeats):
        t0 = time.process_time()
        dz.design(spec)
        times.append(time.process_time() - t0)
    req = dz.requirements(spec)
    grid, km, lo, hi, _ = dz.statics_window(spec, req)
    stages = {
        "statics window": cpu_per_call(lambda: dz.statics_window(spec, req)),
        "spring screen": cpu_per_call(lambda: dz.best_discrete(spec, req, km, grid, lo, hi,
                                                                dynamics=False)),
        "discrete search with dynamics": cpu_per_call(
            lambda: dz.best_discrete(spec, req, km, grid, lo, hi)),
        "continuous bound": cpu_per_call(lambda: dz.continuous_bound(spec, req, km, lo, hi)),
    }
    pruned = dz.continuous_bound(spec, req, km, lo, hi)["objective"]
    gp = cached_gp("mass", spec.material.stress_correction, "band")
    every = []
    mat = spec.material
    t0 = time.process_time()
    for i in np.nonzero(lo <= hi)[0]:
        k_hi = float(min(hi[i], 1e12))
        per = float(km.force.x[i, -1])
        sol = gp.solve(**dz.gp_values(spec, req, km, i, float(max(lo[i], 1e-9)), k_hi, per),
                       k_s=mat.allowable_shear_stress)
        if sol.ok:
            every.append(float(km.m[i, 0] + km.central[i, 0]) + sol.objective)
    t_every = time.process_time() - t0
    return {"median_cpu_s": statistics.median(times), "runs": times, "stages_cpu_s": stages,
            "bound_pruned": pruned, "bound_every_mass": min(every),
            "bound_every_mass_cpu_s": t_every, "masses": len(every)}


def _child_times(args, repeats, env=None):
    """Median wall and CPU (children's user + system) of running ``args`` ``repeats`` times."""
    walls, cpus = [], []
    for _ in range(repeats):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False,
                       cwd=tempfile.gettempdir(), env=env)
        walls.append(time.perf_counter() - t0)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    return statistics.median(walls), statistics.median(cpus)


def process_times(repeats: int = 5) -> dict:
    """Whole-process times of the commands, with ``python -c pass`` as the baseline."""
    py = [sys.executable]
    cli = py + ["-m", "govopt.cli"]
    runs = {
        "python -c pass": py + ["-c", "pass"],
        "govopt --help": cli + ["--help"],
        "govopt evaluate": cli + ["evaluate"],
        "govopt design": cli + ["design", str(SPECS / "hamabe-design.toml")],
    }
    out = {}
    for name, args in runs.items():
        wall, cpu = _child_times(args, repeats)
        out[name] = {"wall_s": wall, "cpu_s": cpu}
    return out


def big_catalogue_spec(folder: Path) -> Path:
    """specs/hamabe-design.toml with every catalogue step refined: 193 weights x 249066
    springs = 48.1 million mass-spring combinations."""
    text = (SPECS / "hamabe-design.toml").read_text()
    for old, new in (('turn_step = 0.5', 'turn_step = 0.125'),
                     ('coil_radius_step = "1 mm"', 'coil_radius_step = "0.5 mm"'),
                     ('weight_step = "0.25 kgf"', 'weight_step = "0.0625 kgf"')):
        if old not in text:
            raise ValueError(f"hamabe-design.toml no longer has {old!r}")
        text = text.replace(old, new)
    path = folder / "hamabe-48M.toml"
    path.write_text(text)
    return path


def peak_memory() -> dict:
    """Peak RSS (MB) of a child process that designs the 48 M-combination catalogue."""
    code = ("import resource, sys, time, json\n"
            "from govopt import load_spec, design\n"
            "t = time.process_time()\n"
            "r = design(load_spec(sys.argv[1]))\n"
            "print(json.dumps({'search': r.optimisation['search'], 'cpu_s': "
            "time.process_time() - t, 'rss_MB': resource.getrusage(resource.RUSAGE_SELF)"
            ".ru_maxrss / 1024}))\n")
    with tempfile.TemporaryDirectory() as tmp:
        path = big_catalogue_spec(Path(tmp))
        p = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True,
                           text=True, cwd=tmp, check=False)
    if p.returncode != 0:
        return {"error": p.stderr.strip().splitlines()[-1:]}
    return json.loads(p.stdout.strip().splitlines()[-1])


def targets(quick: bool = False, log=None) -> list[dict]:
    """Every speed target beside what was measured (rows for :func:`write_report`)."""
    rows = []

    def add(name, value, extra=""):
        limit, unit, what, *sense = TARGETS[name]
        sense = sense[0] if sense else "<="
        rows.append({"target": name, "limit": limit, "unit": unit, "measured": value,
                     "sense": sense, "met": bool(value <= limit if sense == "<=" else
                                                 value >= limit),
                     "what": what, "note": extra})

    d = design_in_process(3 if quick else 7)
    rel = abs(d["bound_pruned"] / d["bound_every_mass"] - 1.0)
    add("design() in process", d["median_cpu_s"],
        f"its bound {d['bound_pruned']:.12g} (pruned masses, energy-certified) = the GP solved "
        f"at all {d['masses']} masses {d['bound_every_mass']:.12g} to {rel:.1e} "
        f"({d['bound_every_mass_cpu_s']:.2f} s CPU)")
    if log:
        log("design() in process measured")
    pt = process_times(3 if quick else 5)
    base = pt["python -c pass"]
    load = os.getloadavg()[0]
    for name in ("govopt --help", "govopt evaluate", "govopt design"):
        add(name, pt[name]["cpu_s"], f"wall {pt[name]['wall_s']:.2f} s at load average "
            f"{load:.1f} (on an idle machine wall ~ CPU); python -c pass {base['cpu_s']:.2f} s "
            f"CPU, {base['wall_s']:.2f} s wall")
    if log:
        log("whole-process times measured")
    mem = peak_memory()
    if "rss_MB" in mem:
        add("peak RSS, 48 M combinations", mem["rss_MB"],
            f"{mem['search']['combinations']:,} combinations, "
            f"{mem['search']['spring_feasible']:,} spring-feasible, {mem['cpu_s']:.1f} s CPU")
    if log:
        log("peak memory measured")
    b = bulk_bench(20_000 if quick else 100_000, 50 if quick else 200, 3)
    loop = f"a loop of govopt.evaluate: {b['evaluate_loop_points_per_s']:.3g} designs/s"
    add("evaluate_many, statics + k^2", b["statics_k2_vectorised_points_per_s"],
        f"{b['points']:,} designs; {b['statics_k2_speedup_vs_evaluate_loop']:.0f} x {loop}")
    add("evaluate_many, + load change", b["with_transient_vectorised_points_per_s"],
        f"{b['with_transient_points']:,} designs; "
        f"{b['with_transient_speedup_vs_evaluate_loop']:.0f} x {loop}")
    if log:
        log("bulk evaluation measured")
    return rows
