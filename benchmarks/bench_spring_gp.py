"""Re-solving the parameterised spring GP against building it afresh, in the same run.

:class:`govopt.optimize.spring_gp.SpringGP` is built once with cvxpy parameters (DPP), so a
re-solve with new values skips the compilation; this measures what that saves: the mean time of
a re-solve and of a fresh build-and-solve over the same problems, their ratio, and the largest
relative difference between the two sets of optima (they must agree).

Run:  python benchmarks/bench_spring_gp.py [--n 50] [--json]
A benchmark, not a test: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import json
import time

from govopt.optimize.spring_gp import SpringGP

#: Hamabe case a in SI (kgf/cm units converted with 1 kgf = 9.80665 N), spring steel density.
EXAMPLE = {
    "kappa": 59.7 * 9.80665 * 100.0,
    "F_max": 606.0 * 9.80665,
    "k_s": 4000.0 * 9.80665e4,
    "G": 850000.0 * 9.80665e4,
    "density": 7850.0,
    "r_max": 0.08,
    "D_out_max": 0.2,
    "n_min": 3.0,
}


def benchmark_resolve(n: int = 50, **values) -> dict[str, float]:
    """Mean wall time of a DPP re-solve vs building and solving a fresh problem.

    Both loops solve the same ``n`` specifications (``k_s`` swept over +-20 %); ``values``
    override the built-in example (Hamabe case a in SI with Wahl's factor). Returns
    ``resolve_s``, ``build_s`` (per solve), ``first_solve_s`` (compile + solve), ``ratio``
    (``build_s / resolve_s``) and ``max_rel_diff`` between the two sets of optima.
    """
    base = {**EXAMPLE, **values}
    specs = [{**base, "k_s": base["k_s"] * (0.8 + 0.4 * i / max(n - 1, 1))} for i in range(n)]
    t0 = time.perf_counter()
    gp = SpringGP()
    gp.solve(**base)
    first = time.perf_counter() - t0
    t0 = time.perf_counter()
    re = [gp.solve(**s).objective for s in specs]
    resolve = (time.perf_counter() - t0) / n
    t0 = time.perf_counter()
    fresh = [SpringGP().solve(**s).objective for s in specs]
    build = (time.perf_counter() - t0) / n
    diff = max(abs(a / b - 1.0) for a, b in zip(re, fresh, strict=True))
    return {"n": n, "resolve_s": resolve, "build_s": build, "first_solve_s": first,
            "ratio": build / resolve, "max_rel_diff": diff}


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=50, help="problems solved each way")
    p.add_argument("--json", action="store_true", help="print the measurements as JSON")
    a = p.parse_args(argv)
    out = benchmark_resolve(n=a.n)
    if a.json:
        print(json.dumps(out, indent=2))
        return
    print(f"spring GP, {out['n']} problems: re-solve {1e3 * out['resolve_s']:.2f} ms, fresh "
          f"build and solve {1e3 * out['build_s']:.2f} ms (x{out['ratio']:.1f}); first solve "
          f"{1e3 * out['first_solve_s']:.1f} ms; optima agree to {out['max_rel_diff']:.1e}")


if __name__ == "__main__":
    main()
