"""Speed vs error of the vectorised load-change transient (Hamabe's eq. 28).

Evaluates ``govopt.analysis.transient.transient`` for many random stable designs at once and
compares it with a per-design ``scipy.integrate.solve_ivp`` baseline timed in the same run on a
subsample (time per design extrapolated), reporting for each the worst error against a
high-precision reference (mpmath, 40 digits: exact modal solution of the float coefficients).

Run:  python benchmarks/bench_transient.py [--designs 100000] [--baseline 200] [--times 200]
A later ``govopt bench`` command can call :func:`run`, which returns the numbers as a dict.
"""

from __future__ import annotations

import argparse
import time

import mpmath as mp
import numpy as np
from scipy.integrate import solve_ivp

from govopt.analysis.transient import transient
from govopt.analysis.transient_events import analyse_many

#: solve_ivp baselines: label -> keyword arguments
BASELINES = {
    "solve_ivp RK45 rtol=1e-6": dict(method="RK45", rtol=1e-6, atol=1e-9),
    "solve_ivp DOP853 rtol=1e-10": dict(method="DOP853", rtol=1e-10, atol=1e-13),
}


def random_designs(n, seed=0):
    """Random stable Hamabe-like designs (kgf-cm-s): a0 = I, 3 a2 = I k^2, a3/a0 from the
    linkage, a1 from a Hurwitz margin (32) between 0.05 and 20; a load change xi0 < 0 with
    xi'(0) = 0 and xi''(0) from a speed error (all as in Example 3 of the model doc)."""
    rng = np.random.default_rng(seed)
    a0 = rng.uniform(0.5, 2.0, n)
    k2 = rng.uniform(50.0, 600.0, n)
    a3 = a0 * rng.uniform(300.0, 600.0, n)
    a2 = a0 * k2 / 3.0
    margin = 10 ** rng.uniform(np.log10(0.05), np.log10(20.0), n)
    a1 = a0 * a3 / (9.0 * a2) * (1.0 + margin)
    xi0 = rng.uniform(-0.2, -0.05, n)
    xi_ddot0 = rng.uniform(-40.0, 60.0, n)
    return (a0, a1, a2, a3), (xi0, np.zeros(n), xi_ddot0)


def reference(coeffs, x0, t, dps=40):
    """xi(t) for one design in mpmath: modal solution with the exact roots of the float
    coefficients (random designs have distinct roots; a near-double pair falls back to the
    matrix exponential)."""
    with mp.workdps(dps):
        a0, a1, a2, a3 = (mp.mpf(float(c)) for c in coeffs)
        X = [mp.mpf(float(v)) for v in x0]
        r = mp.polyroots([a0, 3 * a1, 3 * a2, a3], maxsteps=200, extraprec=2 * dps)
        sep = min(abs(r[i] - r[j]) / max(abs(r[i]), abs(r[j])) for i, j in ((0, 1), (0, 2), (1, 2)))
        if sep < mp.mpf(10) ** (-dps // 4):
            A = mp.matrix([[0, 1, 0], [0, 0, 1], [-a3 / a0, -3 * a2 / a0, -3 * a1 / a0]])
            return np.array([float((mp.expm(A * mp.mpf(float(tt))) * mp.matrix(X))[0])
                             for tt in t])
        V = mp.matrix([[1, 1, 1], list(r), [v**2 for v in r]])
        c = mp.lu_solve(V, mp.matrix(X))
        return np.array([float(mp.re(sum(c[k] * mp.exp(r[k] * mp.mpf(float(tt)))
                                         for k in range(3)))) for tt in t])


def _baseline(coeffs, x0, t, **kw):
    a0, a1, a2, a3 = (float(c) for c in coeffs)
    A = np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-a3 / a0, -3 * a2 / a0, -3 * a1 / a0]])
    if kw.get("method") in ("Radau", "BDF", "LSODA"):
        kw = dict(kw, jac=A)
    sol = solve_ivp(lambda _t, x: A @ x, (t[0], t[-1]), np.asarray(x0, float), t_eval=t, **kw)
    return sol.y[0]


def run(n_designs=100_000, n_baseline=200, n_times=200, t_end=3.0, n_events=2000, seed=0,
        verbose=False):
    """Benchmark; returns a dict of timings (seconds) and worst relative errors.

    Errors are max |xi - xi_ref| / max |xi_ref| over each design's time grid, worst over the
    ``n_baseline`` subsample.  ``n_events`` designs are also run through ``analyse_many``
    (over-regulation, first arrival, settling: exact event times), timed per design.
    """
    coeffs, x0 = random_designs(n_designs, seed)
    t = np.linspace(0.0, t_end, n_times)
    sub = np.linspace(0, n_designs - 1, min(n_baseline, n_designs)).astype(int)

    transient(*(c[:10] for c in coeffs), *(v[:10] for v in x0), t)  # warm-up
    t0 = time.perf_counter()
    xi = transient(*coeffs, *x0, t)
    t_vec = time.perf_counter() - t0

    def design(i):
        return tuple(float(c[i]) for c in coeffs), tuple(float(v[i]) for v in x0)

    t0 = time.perf_counter()
    refs = {int(i): reference(*design(i), t) for i in sub}
    t_ref = time.perf_counter() - t0

    def worst(values):
        return max(float(np.max(np.abs(values[k] - refs[i])) / np.max(np.abs(refs[i])))
                   for k, i in enumerate(sub))

    out = dict(
        n_designs=n_designs, n_times=n_times, n_baseline=int(sub.size),
        vectorised_total_s=t_vec, vectorised_per_design_s=t_vec / n_designs,
        vectorised_max_rel_error=worst([xi[i] for i in sub]),
        reference_per_design_s=t_ref / sub.size, baselines={},
    )
    for label, kw in BASELINES.items():
        t0 = time.perf_counter()
        ys = [_baseline(*design(i), t, **kw) for i in sub]
        per = (time.perf_counter() - t0) / sub.size
        out["baselines"][label] = dict(
            per_design_s=per, extrapolated_total_s=per * n_designs,
            speed_ratio=per / out["vectorised_per_design_s"], max_rel_error=worst(ys),
        )
    if n_events:
        m = min(n_events, n_designs)
        t0 = time.perf_counter()
        s = analyse_many(*(c[:m] for c in coeffs), *(v[:m] for v in x0))
        t_ev = time.perf_counter() - t0
        out.update(events_n=m, events_per_design_s=t_ev / m,
                   events_over_regulating=float(np.mean(s.over_regulation > 0)))
    if verbose:
        print(report(out))
    return out


def report(r):
    lines = [
        f"load-change transient, {r['n_designs']} random stable designs x {r['n_times']} times",
        f"  vectorised (govopt)   : {r['vectorised_total_s']:.2f} s total, "
        f"{r['vectorised_per_design_s'] * 1e6:.2f} us/design, "
        f"max rel error {r['vectorised_max_rel_error']:.1e}",
    ]
    for label, b in r["baselines"].items():
        lines.append(
            f"  {label:<27s}: {b['per_design_s'] * 1e3:.2f} ms/design "
            f"(x{r['n_designs']} = {b['extrapolated_total_s']:.0f} s), "
            f"speed ratio {b['speed_ratio']:.0f}x, max rel error {b['max_rel_error']:.1e}")
    lines.append(f"  errors vs mpmath (40 digits) on a subsample of {r['n_baseline']} designs; "
                 f"reference {r['reference_per_design_s'] * 1e3:.0f} ms/design")
    if "events_n" in r:
        lines.append(f"  analyse_many (exact events) on {r['events_n']} designs: "
                     f"{r['events_per_design_s'] * 1e6:.0f} us/design, "
                     f"{100 * r['events_over_regulating']:.0f} % over-regulate")
    return "\n".join(lines)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--designs", type=int, default=100_000)
    p.add_argument("--baseline", type=int, default=200)
    p.add_argument("--times", type=int, default=200)
    p.add_argument("--events", type=int, default=2000)
    p.add_argument("--seed", type=int, default=0)
    a = p.parse_args(argv)
    run(a.designs, a.baseline, a.times, n_events=a.events, seed=a.seed, verbose=True)


if __name__ == "__main__":
    main()
