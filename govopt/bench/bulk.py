"""The bulk evaluation's speed: ``evaluate_many`` (the vectorised evaluate-mode path) against
per-design loops, on designs of Hamabe's case a scattered (the pendulum weight +-20 %, the
spring's turns +-10 %), in CPU seconds (``time.process_time``, medians): the machine is shared,
and wall time measures the neighbours. ``govopt bench`` reports it beside its targets;
``benchmarks/bench_study.py`` beside the study's own figures.
"""

from __future__ import annotations

import time

import numpy as np

from .suites import SPECS


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
    from govopt.analysis import characteristic as chs
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
        ch = chs.characteristic(s, sd)
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
