"""Benchmarks, each reported as a ratio against a baseline measured in the same run.

Run with ``govopt bench``. Never used as timed assertions in the tests.
"""

from __future__ import annotations

import time
from pathlib import Path


def design_bench(spec_path: str | Path) -> dict:
    """One full design of the bundled spec, split into its stages, against one evaluation."""
    from ..evaluation import evaluate
    from ..optimize import design as dz
    from ..spec import load_spec

    spec = load_spec(spec_path)
    t0 = time.perf_counter()
    res = dz.design(spec)
    total = time.perf_counter() - t0
    t0 = time.perf_counter()
    evaluate(spec.with_design(res.design))
    one_eval = time.perf_counter() - t0
    req = dz.requirements(spec)
    t0 = time.perf_counter()
    grid, km, lo, hi, _ = dz.statics_window(spec, req)
    _, stats = dz.best_discrete(spec, req, km, grid, lo, hi, dynamics=False)
    screen = time.perf_counter() - t0
    return {"design_s": total, "evaluate_s": one_eval, "design_over_evaluate": total / one_eval,
            "statics_and_spring_screen_s": screen, "combinations": stats["combinations"],
            "screen_per_combination_s": screen / stats["combinations"],
            "screen_vs_evaluate_per_design": one_eval / (screen / stats["combinations"])}


def gp_bench(n: int = 30) -> dict:
    """Re-solving the parameterised spring GP vs building it afresh (same n problems)."""
    from ..optimize.spring_gp import benchmark_resolve

    return benchmark_resolve(n=n)


def transient_bench(n_designs: int = 100_000, n_baseline: int = 100) -> dict | None:
    """Vectorised transient for many designs vs per-design solve_ivp (benchmarks/ script)."""
    path = Path(__file__).resolve().parents[2] / "benchmarks" / "bench_transient.py"
    if not path.exists():
        return None
    import importlib.util

    mod_spec = importlib.util.spec_from_file_location("bench_transient", path)
    mod = importlib.util.module_from_spec(mod_spec)
    mod_spec.loader.exec_module(mod)
    return mod.run(n_designs=n_designs, n_baseline=n_baseline)
