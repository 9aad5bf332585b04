"""Speed against error: one point (time per evaluation, error) per method and setting over a
fixed suite with the hard cases, errors against high-precision references, and the Pareto front
of each analysis.

* :func:`speed_vs_error`: one point (time per evaluation, error) per method and setting over a
  fixed suite with the hard cases, errors against high-precision references:

=============  ==============================================================================
  statics        exact linkage (eq. 2) vs the paper's series (eq. 3); reference: the linkage
                 and centrifugal terms in mpmath (50 digits; the valve-gear reactions, which
                 both share, in binary64)
  transient      eq. (28): govopt's solver (single and batched) vs Hamabe's Cardano roots and
                 partial fractions (eqs. 38-41), ``numpy.roots`` with partial fractions,
                 ``solve_ivp`` (RK45, Radau, LSODA at several tolerances), python-control's
                 ``initial_response`` (if installed) and ``scipy.signal.lsim``; cases with
                 distinct, double, triple and nearly triple roots, on the Hurwitz boundary, a
                 stiff spread, light damping and Hamabe's Example 3; reference: ``exp(A t) x0``
                 in mpmath (50 digits) for the float coefficients
  load change    the linear model (eq. 28) vs the nonlinear equations (DOP853 at several
                 tolerances) for a small and a large load change; reference: the nonlinear
                 equations at rtol 1e-12 (binary64 integration, not mpmath)
  vibration      the harmonic series against the number of harmonics, Hamabe's case a and a
                 near-resonance (k^2 = 0.98 omega0^2, undamped); reference: 1024 harmonics
                 (their truncation bound is reported)
  friction       the closed form (expm strokes, brentq ends, eqs. 42-46) vs event-driven
                 ``solve_ivp`` at several tolerances; reference: every stroke re-solved in
                 mpmath (40 digits, expm and findroot) along the same phase sequence
  optimiser      ``design()`` on coarser catalogue grids vs its gap to the exhaustive optimum
                 of the full grid; the GP's continuous bound and its gap below that optimum
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np

from ..examples import SPECS  # the bundled specs

#: The settings govopt uses unless a spec's use case picks others: (analysis, method, setting)
DEFAULTS = {
    ("statics", "exact geometry (eq. 2)", "binary64"),
    ("transient", "govopt transient", "single"),
    ("load change, large", "linear eq. 28 (govopt)", "exact solver"),
    ("load change, small", "linear eq. 28 (govopt)", "exact solver"),
    ("vibration", "harmonic series", "N = 12"),
    ("friction", "closed form (govopt)", "expm + brentq"),
    ("optimiser", "design() exhaustive", "full catalogue"),
}


@dataclass
class Point:
    """One method at one setting: time per evaluation (s, CPU) and error (relative, worst
    over the suite's cases; ``inf`` where it fails)."""

    analysis: str
    method: str
    setting: str
    time_s: float
    error: float
    worst_case: str = ""
    note: str = ""
    pareto: bool = False
    default: bool = False


def cpu_per_call(fn, min_time: float = 0.02, repeats: int = 3) -> float:
    """Least CPU time per call of ``fn()`` over ``repeats`` runs of at least ``min_time``."""
    best = math.inf
    for _ in range(repeats):
        n, t0 = 0, time.process_time()
        while True:
            fn()
            n += 1
            dt = time.process_time() - t0
            if dt >= min_time:
                break
        best = min(best, dt / n)
    return best


def _rel(err, scale) -> float:
    err = np.asarray(err, dtype=float)
    if not np.all(np.isfinite(err)):
        return math.inf
    return float(np.max(np.abs(err)) / scale)


# ---------------------------------------------------------------------------------------------
# Transient (eq. 28)
# ---------------------------------------------------------------------------------------------


def _from_roots(r1, r2, r3):
    """``(a0, a1, a2, a3)`` of ``(s - r1)(s - r2)(s - r3)`` in Hamabe's form (a0 = 1)."""
    s1 = r1 + r2 + r3
    s2 = r1 * r2 + r1 * r3 + r2 * r3
    s3 = r1 * r2 * r3
    return 1.0, float(np.real(-s1) / 3.0), float(np.real(s2) / 3.0), float(np.real(-s3))


def transient_cases():
    """The suite of eq. (28): name -> (coefficients, initial state, times)."""
    from ..analysis import loadchange, statics
    from ..spec import load_spec

    x0 = (-1.0, 0.0, 2.0)
    cases = {
        "distinct real": (_from_roots(-1.0, -3.0, -7.0), x0, 8.0),
        "double root": (_from_roots(-2.0, -2.0, -5.0), x0, 5.0),
        "triple root": (_from_roots(-3.0, -3.0, -3.0), x0, 4.0),
        "near-triple (1e-6)": (_from_roots(-3.0 * (1 - 1e-6), -3.0, -3.0 * (1 + 1e-6)), x0,
                               4.0),
        "Hurwitz boundary": (_from_roots(2j, -2j, -1.0), x0, 12.0),
        "stiff spread (5e3)": (_from_roots(-0.2, -1.0, -1000.0), x0, 25.0),
        "light damping": (_from_roots(-0.02 + 5j, -0.02 - 5j, -1.0), x0, 30.0),
    }
    spec = load_spec(SPECS / "hamabe-a.toml")
    sd = statics.spring_design(spec, spec.design)
    a, x, _ = loadchange.coefficients(spec, sd, spec.load_changes[0], spec.design.dashpot)
    cases["Hamabe Example 3"] = (a, x, 3.0)
    return {k: (tuple(map(float, a)), tuple(map(float, x)), np.linspace(0.0, T, 61))
            for k, (a, x, T) in cases.items()}


def _companion(a):
    a0, a1, a2, a3 = a
    return np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-a3 / a0, -3 * a2 / a0, -3 * a1 / a0]])


def transient_reference(a, x0, t, dps: int = 50) -> np.ndarray:
    """``xi(t) = [exp(A t) x0]_0`` in mpmath for the float coefficients ``a`` (any roots)."""
    import mpmath as mp

    with mp.workdps(dps):
        a0, a1, a2, a3 = (mp.mpf(v) for v in a)
        A = mp.matrix([[0, 1, 0], [0, 0, 1], [-a3 / a0, -3 * a2 / a0, -3 * a1 / a0]])
        X = mp.matrix([mp.mpf(v) for v in x0])
        return np.array([float((mp.expm(A * mp.mpf(float(s))) * X)[0]) for s in t])


def _partial_fractions(r, x0, t):
    """``xi(t) = sum_k c_k exp(r_k t)`` with ``c_k`` by partial fractions (Hamabe eqs. 38, 40):
    divides by the root differences. ``r`` (n, 3) complex, ``x0`` (n, 3)."""
    x, xd, xdd = (np.asarray(x0)[:, j][:, None] for j in range(3))
    t = np.atleast_2d(t)  # (1, m) shared or (n, m) per design
    out = 0.0
    with np.errstate(all="ignore"):
        for k in range(3):
            rk, rj, rl = r[:, k][:, None], r[:, (k + 1) % 3][:, None], r[:, (k + 2) % 3][:, None]
            c = (xdd - (rj + rl) * xd + rj * rl * x) / ((rk - rj) * (rk - rl))
            out = out + c * np.exp(rk * t)
    return np.real(out)


def cardano_roots(a):
    """Roots of ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3`` by Cardano's formula (Hamabe eqs. 39, 41),
    vectorised; ``a`` is (4, n)."""
    a0, a1, a2, a3 = (np.asarray(v, dtype=float) for v in a)
    b, c, d = a1 / a0, a2 / a0, a3 / a0
    p, q = 3.0 * (c - b * b), d - 3.0 * b * c + 2.0 * b**3  # s = y - b: y^3 + p y + q = 0
    sq = np.sqrt((q / 2) ** 2 + (p / 3) ** 3 + 0j)
    u = (-q / 2 + sq) ** (1.0 / 3.0)
    with np.errstate(all="ignore"):
        v = np.where(u != 0, -p / (3.0 * np.where(u != 0, u, 1.0)), (-q + 0j) ** (1.0 / 3.0))
    w = np.exp(2j * np.pi / 3)
    return np.stack([u + v, u * w + v / w, u / w + v * w], axis=1) - b[:, None]


def transient_suite(quick: bool = False) -> list[Point]:
    """Every eq. (28) method on every case: worst relative error over the cases (max over t of
    ``|xi - xi_ref| / max |xi_ref|``) and the mean CPU time per case."""
    from scipy.integrate import solve_ivp
    from scipy.signal import lsim

    from ..analysis.transient import transient

    cases = transient_cases()
    refs = {k: transient_reference(a, x, t) for k, (a, x, t) in cases.items()}
    names = list(cases)

    def run_single(label, fn, setting="single", note=""):
        errs, times = {}, []
        for k, (a, x, t) in cases.items():
            try:
                y = fn(a, x, t)
                errs[k] = _rel(np.asarray(y) - refs[k], np.max(np.abs(refs[k])))
            except Exception:  # a method that fails on a case: infinite error
                errs[k] = math.inf
            times.append(cpu_per_call(lambda a=a, x=x, t=t: _try(fn, a, x, t),
                                       0.005 if quick else 0.01, 2 if quick else 3))
        worst = max(errs, key=lambda k: errs[k])
        return Point("transient", label, setting, float(np.mean(times)), errs[worst], worst,
                     note)

    points = [run_single("govopt transient", lambda a, x, t: transient(*a, *x, t))]
    reps = 25 if quick else 125
    A = np.array([cases[k][0] for k in names] * reps).T
    X = np.array([cases[k][1] for k in names] * reps).T
    tt = np.linspace(0.0, 1.0, 61)  # a common grid in units of each case's horizon
    T = np.array([cases[k][2][-1] for k in names] * reps)

    def batched(method):
        if method == "govopt":
            return _govopt_batched(A, X, T, tt)
        r = cardano_roots(A)
        return _partial_fractions(r, X.T, T[:, None] * tt)

    for method, label in (("govopt", "govopt transient"),
                          ("cardano", "Cardano + partial fractions (eqs. 38-41)")):
        y = batched(method)
        errs = {}
        for i, k in enumerate(names):
            errs[k] = _rel(y[i] - refs[k], np.max(np.abs(refs[k])))
        worst = max(errs, key=lambda k: errs[k])
        per = cpu_per_call(lambda m=method: batched(m), 0.02 if quick else 0.05) / A.shape[1]
        points.append(Point("transient", label, f"batched x{A.shape[1]}", per, errs[worst],
                            worst))

    def roots_pf(a, x, t):
        r = np.roots([a[0], 3 * a[1], 3 * a[2], a[3]]).astype(complex)
        return _partial_fractions(r[None, :], np.array([x]), t)[0]

    points.append(run_single("numpy.roots + partial fractions", roots_pf))

    def ivp(method, rtol):
        def fn(a, x, t):
            M = _companion(a)
            kw = {"jac": lambda _t, _y: M} if method in ("Radau", "LSODA") else {}
            sol = solve_ivp(lambda _, y: M @ y, (t[0], t[-1]), x, method=method, t_eval=t,
                            rtol=rtol, atol=rtol * 1e-3, **kw)
            return sol.y[0] if sol.success else np.full(t.shape, np.inf)
        return fn

    tols = (1e-3, 1e-6) if quick else (1e-3, 1e-6, 1e-9)
    for method in ("RK45", "Radau", "LSODA"):
        for rtol in tols:
            points.append(run_single(f"solve_ivp {method}", ivp(method, rtol), f"rtol={rtol:g}"))

    def lsim_fn(a, x, t):
        M = _companion(a)
        return lsim((M, np.zeros((3, 1)), np.array([[1.0, 0.0, 0.0]]), np.zeros((1, 1))),
                    np.zeros(t.size), t, X0=np.asarray(x))[1]

    points.append(run_single("scipy.signal.lsim", lsim_fn))
    try:
        import control
    except ImportError:
        control = None
    if control is not None:
        def ctrl(a, x, t):
            sys_ = control.ss(_companion(a), np.zeros((3, 1)), [[1.0, 0.0, 0.0]], [[0.0]])
            return np.ravel(control.initial_response(sys_, T=t, X0=np.asarray(x)).outputs)

        points.append(run_single("python-control initial_response", ctrl))
    return points


def _try(fn, *args):
    try:
        fn(*args)
    except Exception:
        pass


def _govopt_batched(A, X, T, tt):
    """govopt's vectorised transient of designs with different horizons: each on its own
    grid ``tt * T`` (time scaled: eq. 28 with ``t = T s`` has coefficients ``a_j T^-j``)."""
    from ..analysis.transient import transient

    a0, a1, a2, a3 = A
    x, xd, xdd = X
    # xi(T s) solves a0 y''' + 3 a1 T y'' + 3 a2 T^2 y' + a3 T^3 y = 0 with y' = T xi' ...
    return transient(a0, a1 * T, a2 * T**2, a3 * T**3, x, xd * T, xdd * T**2, tt)


# ---------------------------------------------------------------------------------------------
# Statics: exact vs series geometry
# ---------------------------------------------------------------------------------------------


def statics_reference(spec, alpha) -> np.ndarray:
    """Equilibrium speeds (rad/s) of the spec's design with the exact linkage (eq. 2) and the
    centrifugal moment (eq. 1) in mpmath, 50 digits; the valve-gear reactions ``cf, ci``
    (shared by both geometries) in binary64; the free length from equilibrium at the normal
    configuration as :func:`govopt.analysis.statics.free_half_length`."""
    import mpmath as mp

    from ..analysis import statics

    g, ds = spec.governor, spec.design
    ex = spec.with_analysis(geometry="exact")
    sd = statics.spring_design(ex, ds)
    with mp.workdps(50):
        a, b, rho, m, kappa = (mp.mpf(float(v)) for v in (g.a, g.b, g.rho, sd.m, sd.kappa))

        def parts(x):
            t = statics.terms(ex, np.array([x]), sd.m, sd.central)
            s = mp.sin(mp.mpf(float(x)))
            A = 2 * a * b * s
            ell = mp.sqrt(a**2 + b**2 - 2 * a * b * mp.cos(mp.mpf(float(x))))
            return A, A / ell, m * a * rho * s, mp.mpf(float(t.cf[0])), mp.mpf(float(t.ci[0]))

        if ds.free_half_length is not None:
            l0 = mp.mpf(float(ds.free_half_length))
        else:
            A, B, jp, cf, ci = parts(g.x_normal)
            Q = mp.mpf(float(spec.speed.omega_mean)) ** 2 * (jp - ci) - cf
            l0 = (A - Q / kappa) / B
        out = []
        for x in alpha:
            A, B, jp, cf, ci = parts(x)
            out.append(float(mp.sqrt((kappa * (A - B * l0) + cf) / (jp - ci))))
    return np.array(out)


def statics_suite(quick: bool = False) -> list[Point]:
    """Hamabe's cases a and c: the characteristic ``omega(alpha)`` with each geometry."""
    from ..analysis import characteristic as chs
    from ..analysis import statics
    from ..spec import load_spec

    points = []
    for geometry, label in (("exact", "exact geometry (eq. 2)"),
                            ("series", "series geometry (eq. 3)")):
        errs, times = {}, []
        for case in ("a", "c"):
            spec = load_spec(SPECS / f"hamabe-{case}.toml").with_analysis(geometry=geometry)

            def run(spec=spec):
                return chs.characteristic(spec, statics.spring_design(spec, spec.design))

            ch = run()
            ref = statics_reference(spec, ch.alpha)
            errs[f"hamabe-{case}"] = _rel(ch.omega - ref, 1.0) / float(np.min(ref))
            times.append(cpu_per_call(run, 0.01 if quick else 0.03))
        worst = max(errs, key=lambda k: errs[k])
        points.append(Point("statics", label, "binary64", float(np.mean(times)), errs[worst],
                            worst, "equilibrium speed over the range"))
    return points


# ---------------------------------------------------------------------------------------------
# Load change: linear model vs the nonlinear equations
# ---------------------------------------------------------------------------------------------


def load_change_suite(quick: bool = False) -> list[Point]:
    """Hamabe's case a: its load change ("large") and one twentieth of it ("small"), each
    its own analysis (a Pareto front per load change). Error: the largest ``|xi - xi_ref|``
    relative to ``|xi0|``."""
    from ..analysis import loadchange, nonlinear, statics
    from ..analysis.friction import linear_response
    from ..spec import LoadChange, load_spec

    spec = load_spec(SPECS / "hamabe-a.toml")
    sd = statics.spring_design(spec, spec.design)
    lc = spec.load_changes[0]
    small = LoadChange("small", lc.alpha_to + (lc.alpha_from - lc.alpha_to) / 20, lc.alpha_to)
    tols = (1e-4, 1e-7) if quick else (1e-4, 1e-6, 1e-8, 1e-10)
    points = []
    for name, change in (("large", lc), ("small", small)):
        ref = nonlinear.nonlinear_load_change(spec, sd, change, rtol=1e-12, atol=1e-15)
        m, t = ref.model, ref.t
        scale = abs(m.xi0)
        lin = linear_response(m.I, m.f, m.k2, m.C, m.R, m.xi0, m.eta0, t)[:, 0]
        per = cpu_per_call(lambda c=change: loadchange.analyse(spec, sd, c, spec.design.dashpot),
                            0.02 if quick else 0.05)
        points.append(Point(f"load change, {name}", "linear eq. 28 (govopt)", "exact solver",
                            per, _rel(lin - ref.xi, scale), f"hamabe-a {name}",
                            "model error: linearisation (xi^2, xi eta, eta^2 dropped)"))
        for rtol in tols:
            def run(rtol=rtol, c=change, t=t):
                return nonlinear.nonlinear_load_change(spec, sd, c, t, rtol=rtol,
                                                       atol=rtol * 1e-3)
            y = run()
            per = cpu_per_call(run, 0.0, 1 if quick else 2)
            points.append(Point(f"load change, {name}", "nonlinear DOP853", f"rtol={rtol:g}",
                                per, _rel(y.xi - ref.xi, scale), f"hamabe-a {name}"))
    return points


# ---------------------------------------------------------------------------------------------
# Vibration against the number of harmonics
# ---------------------------------------------------------------------------------------------


def vibration_suite(quick: bool = False) -> list[Point]:
    """Peak-to-peak vibration of Hamabe's case a (with its dash-pot) and near resonance
    (``k^2 = 0.98 omega0^2``, undamped) with N harmonics, against 1024 harmonics."""
    from ..analysis import statics
    from ..governors.shaft import vibration
    from ..spec import load_spec

    spec = load_spec(SPECS / "hamabe-a.toml")
    sd = statics.spring_design(spec, spec.design)
    a0 = spec.governor.alpha_normal
    w0 = spec.speed.omega_mean
    cases = {"hamabe-a": {}, "near resonance": {"k2": 0.98 * w0**2, "dashpot": None}}
    ref = {k: vibration.vibration(spec, sd, a0, n_harmonics=1024, **kw)
           for k, kw in cases.items()}
    orders = (1, 2, 4, 8, 12, 16, 32, 64) if quick else (1, 2, 4, 8, 12, 16, 24, 32, 48, 64,
                                                          96, 128, 256)
    points = []
    for N in orders:
        errs, times = {}, []
        for k, kw in cases.items():
            def run(kw=kw, N=N):
                return vibration.vibration(spec, sd, a0, n_harmonics=N, **kw)
            r = run()
            errs[k] = abs(r.peak_to_peak_rad / ref[k].peak_to_peak_rad - 1.0)
            times.append(cpu_per_call(run, 0.01 if quick else 0.03))
        worst = max(errs, key=lambda k: errs[k])
        points.append(Point("vibration", "harmonic series", f"N = {N}", float(np.mean(times)),
                            errs[worst], worst, "peak-to-peak"))
    bound = max(r.truncation_error_rad / r.peak_to_peak_rad for r in ref.values())
    for p in points:
        p.note = f"peak-to-peak; reference's own truncation bound {bound:.1e}"
    return points


# ---------------------------------------------------------------------------------------------
# Friction: closed form vs event-driven integration
# ---------------------------------------------------------------------------------------------


def _friction_case():
    """Hamabe's case d with the paper's fidelity, fulcrum friction 22.6 kgf cm, no dash-pot
    (his Example 4): a few strokes to rest."""
    from ..analysis.loadchange import load_change_model
    from ..spec import load_spec

    spec = load_spec(SPECS / "hamabe-d.toml").with_analysis(
        geometry="series", reaction_speed="mean", reaction_slope=False)
    spec = spec.with_design(replace(spec.design, dashpot=0.0,
                                    friction_moment=22.6 * 9.80665 * 0.01))
    m = load_change_model(spec)
    return m.I, m.f, m.k2, m.C, m.R, m.M0, m.xi0, m.eta0


def _event_driven(I, f, k2, C, R, M0, xi0, eta0, t_end, strokes, method, rtol):
    """Stroke ends ``[(t, xi)]`` by ``solve_ivp`` with an event at ``xi' = 0`` per stroke and
    the same stick law as :func:`govopt.analysis.friction.friction_transient`."""
    from scipy.integrate import solve_ivp

    xi, v, eta, t, ends = xi0, 0.0, eta0, 0.0, []
    while t < t_end and len(ends) < strokes:
        n = C * eta - I * k2 * xi
        if v == 0.0 and abs(n) <= M0 * (1 + 1e-12):
            if xi == 0.0:
                break
            n_b = -math.copysign(M0, xi)
            tb = t + max(0.0, (n - n_b) / (C * R * xi))
            if tb >= t_end:
                break
            t, eta = tb, (n_b + I * k2 * xi) / C
            s = -1 if xi > 0 else 1
        else:
            s = (1 if v > 0 else -1) if v != 0.0 else (1 if n > 0 else -1)

        def rhs(_, y, s=s):
            return (y[1], (C * y[2] - I * k2 * y[0] - f * y[1] - s * M0) / I, -R * y[0])

        def stop(_, y):
            return y[1]

        stop.terminal, stop.direction = True, -s
        sol = solve_ivp(rhs, (0.0, t_end - t), (xi, v, eta), method=method, rtol=rtol,
                        atol=rtol * 1e-3 * abs(xi0), events=stop)
        if not sol.t_events[0].size:
            break
        xi, _, eta = sol.y_events[0][0]
        v, t = 0.0, t + float(sol.t_events[0][0])
        ends.append((t, float(xi)))
    return ends


def friction_reference(res, dps: int = 40):
    """Stroke ends ``[(t, xi)]`` of a :class:`~govopt.analysis.friction.FrictionResult`
    re-solved in mpmath along its phase sequence: each stroke ``z(tau) = expm(M tau) z0`` with
    its end ``xi'(tau) = 0`` by ``findroot`` from the binary64 end, each stick in closed form."""
    import mpmath as mp

    I, f, k2, C, R, M0 = (res.I, res.f, res.k2, res.C, res.R, res.M0)
    with mp.workdps(dps):
        I, f, k2, C, R, M0 = (mp.mpf(v) for v in (I, f, k2, C, R, M0))
        xi, eta, t = mp.mpf(res.xi0), mp.mpf(res.eta0), mp.mpf(0)
        v = mp.mpf(res.xi_dot0)
        out = []
        for ph in res.phases:
            if not ph.complete:
                break
            if ph.kind == "stick":
                n_b = -mp.sign(xi) * M0
                n = C * eta - I * k2 * xi
                t = t + max(mp.mpf(0), (n - n_b) / (C * R * xi))
                eta = (n_b + I * k2 * xi) / C
                continue
            s = ph.direction
            M = mp.matrix([[0, 1, 0, 0], [-k2, -f / I, C / I, -s * M0 / I],
                           [-R, 0, 0, 0], [0, 0, 0, 0]])
            z0 = mp.matrix([xi, v, eta, 1])

            def vel(tau, M=M, z0=z0):
                return (mp.expm(M * tau) * z0)[1]

            tau = mp.findroot(vel, mp.mpf(ph.duration), solver="secant")
            z = mp.expm(M * tau) * z0
            xi, v, eta, t = z[0], mp.mpf(0), z[2], t + tau
            out.append((float(t), float(xi)))
    return out


def friction_suite(quick: bool = False) -> list[Point]:
    """Stroke ends (time and position) of Hamabe's Example 4 by each method; error: the
    largest ``|xi_end - ref|`` relative to ``|xi0|`` over the strokes."""
    from ..analysis.friction import friction_transient

    args = _friction_case()
    strokes = 6
    res = friction_transient(*args, max_strokes=strokes)
    t_end = res.t_horizon
    ref = friction_reference(res)
    scale = abs(args[6])

    def err(ends):
        if len(ends) < len(ref):
            return math.inf
        return max(abs(e[1] - r[1]) for e, r in zip(ends, ref, strict=False)) / scale

    def closed():
        r = friction_transient(*args, max_strokes=strokes)
        return [(p.t_end, p.xi_end) for p in r.phases if p.kind == "slide" and p.complete]

    points = [Point("friction", "closed form (govopt)", "expm + brentq", cpu_per_call(closed),
                    err(closed()), "hamabe-d Example 4", f"{len(ref)} strokes")]
    tols = (1e-4, 1e-8) if quick else (1e-4, 1e-6, 1e-8, 1e-10)
    for method in ("RK45", "DOP853", "Radau"):
        for rtol in tols:
            def run(method=method, rtol=rtol):
                return _event_driven(*args, t_end, len(ref), method, rtol)
            points.append(Point("friction", f"event-driven solve_ivp {method}",
                                f"rtol={rtol:g}", cpu_per_call(run, 0.0, 1 if quick else 2),
                                err(run()), "hamabe-d Example 4", f"{len(ref)} strokes"))
    return points


# ---------------------------------------------------------------------------------------------
# Optimiser: time against the gap to the exhaustive optimum
# ---------------------------------------------------------------------------------------------


def optimiser_suite(quick: bool = False) -> list[Point]:
    """``design()`` of specs/hamabe-design.toml on coarser grids (coil radius, turns, weight
    steps x k), and the continuous GP bound, against the exhaustive optimum of the full grid."""
    from ..optimize import design as dz
    from ..spec import load_spec

    spec = load_spec(SPECS / "hamabe-design.toml")
    req = dz.requirements(spec)

    def value(res):
        return res.optimisation["value"]

    best = value(dz.design(spec))
    points = []
    factors = (1, 2, 4) if quick else (1, 2, 3, 4, 6)
    for k in factors:
        s = replace(spec, requirements=replace(req, coil_radius_step=req.coil_radius_step * k,
                                               turn_step=req.turn_step * k,
                                               mass_step=req.mass_step * k))
        try:
            obj = value(dz.design(s))
        except Exception:
            obj = math.inf
        per = cpu_per_call(lambda s=s: _try(dz.design, s), 0.0, 2 if quick else 3)
        label = "full catalogue" if k == 1 else f"grids x{k}"
        points.append(Point("optimiser", "design() exhaustive", label, per,
                            obj / best - 1.0, "hamabe-design",
                            "gap to the exhaustive optimum of the full grid"))
    grid, km, lo, hi, _ = dz.statics_window(spec, req)
    bound = dz.continuous_bound(spec, req, km, lo, hi)["objective"]
    per = cpu_per_call(lambda: dz.continuous_bound(spec, req, km, lo, hi), 0.02)
    points.append(Point("optimiser", "continuous bound (GP)", "pruned masses", per,
                        1.0 - bound / best, "hamabe-design",
                        "a lower bound: its gap below the discrete optimum"))
    return points


# ---------------------------------------------------------------------------------------------
# The textbook and traction types: each type's shortcuts against its exact model, and the
# solve-for's tolerance, on a hard case of each type
# ---------------------------------------------------------------------------------------------

def type_cases() -> dict:
    """Every type's hard case (:attr:`Governor.bench_case`: a bundled spec or a spec's data,
    the values that make it hard, the fidelity key of its shortcuts and their settings, the
    exact model's first), with the input the solve rows find (default the flying mass)."""
    from ..governors import REGISTRY, governor_class

    out = {}
    for name in REGISTRY:
        cls = governor_class(name)
        source, changes, key, settings, *unknown = cls.bench_case
        out[name] = (source, changes, key, settings,
                     unknown[0] if unknown else f"design.{cls.mass_key}_weight")
    return out


def type_case(name: str, setting: str | None = None):
    """The hard case of type ``name`` (:func:`type_cases`) at its fidelity ``setting``."""
    from ..spec import load_spec, parse_spec, with_values

    source, changes, key, _, _ = type_cases()[name]
    spec = parse_spec(source) if isinstance(source, dict) else load_spec(SPECS / f"{source}.toml")
    changes = {**changes, **({key: setting} if setting is not None and key else {})}
    return with_values(spec, changes) if changes else spec


def types_suite(quick: bool = False, types=None) -> list[Point]:
    """Every type's hard case: its characteristic at each fidelity setting against the exact
    model (the Watt's exact model against the book's closed form in mpmath), and ``govopt
    solve``'s Brent tolerance finding one input for a speed 3 % below the outermost one's,
    against the root at the tightest tolerance (4 eps). ``types``: the types to run (default
    all of :func:`type_cases`)."""
    from .. import questions
    from ..analysis import statics

    points = []
    for name, (_, _, key, settings, unknown) in type_cases().items():
        if types is not None and name not in types:
            continue
        exact = type_case(name, settings[0])
        x = statics.configurations(exact)

        def speeds(spec, x=x):
            sd = statics.spring_design(spec)
            return np.sqrt(statics.omega_squared(spec, x, sd.m, sd.kappa, sd.l0, sd.central))

        closed = exact.governor.bench_reference(exact, x)  # the book's own, in mpmath
        ref = speeds(exact) if closed is None else closed
        for setting in settings:
            spec = type_case(name, setting)
            err = _rel(speeds(spec) - ref, 1.0) / float(np.min(ref))
            what = "the book's closed form in mpmath" if closed is not None else \
                "the exact model" if setting != settings[0] else "the exact model itself"
            points.append(Point(f"{name}: statics", f"characteristic ({key or 'exact'})",
                                setting, cpu_per_call(lambda s=spec: speeds(s), 0.005 if quick
                                                      else 0.02), err, name,
                                f"speed over the hard case's range against {what}"))
        outer = questions.Point("outer", "outer")
        target = 0.97 * questions.figure(exact, "speed", outer)
        best = questions.solve(exact, unknown, "speed", target, outer,
                               rtol=4 * np.finfo(float).eps).value
        for rtol in (1e-6, 1e-12) if quick else (1e-3, 1e-6, 1e-9, 1e-12):
            t0 = time.process_time()
            found = questions.solve(exact, unknown, "speed", target, outer, rtol=rtol)
            points.append(Point(f"{name}: solve", f"solve {unknown} (Brent)", f"rtol {rtol:g}",
                                time.process_time() - t0, abs(found.value - best) / abs(best),
                                name, f"{found.evaluations} evaluations; the root at 4 eps "
                                      "is the reference"))
    return points


SUITES = {"statics": statics_suite, "transient": transient_suite,
          "load change": load_change_suite, "vibration": vibration_suite,
          "friction": friction_suite, "optimiser": optimiser_suite, "types": types_suite}


def pareto(points: list[Point]) -> None:
    """Mark each analysis's Pareto front: no other point of it is as fast and as accurate,
    and strictly better in one (times within ``noise``, 2 %, count as equal); a method that
    fails (infinite error) is on no front."""
    noise = 1.02
    for p in points:
        same = [q for q in points if q.analysis == p.analysis and q is not p]
        p.pareto = math.isfinite(p.error) and not any(
            q.time_s <= p.time_s * noise and q.error <= p.error
            and (q.time_s < p.time_s / noise or q.error < p.error) for q in same)
        p.default = (p.analysis, p.method, p.setting) in DEFAULTS or (
            p.analysis.endswith(": statics") and p.worst_case and p.setting == type_cases()[
                p.worst_case][3][0]) or (p.analysis.endswith(": solve")
                                         and p.setting == "rtol 1e-12")


def speed_vs_error(quick: bool = False, analyses=None, log=None) -> list[Point]:
    """Run the suites (all, or those named in ``analyses``) and mark the Pareto fronts."""
    points = []
    for name, suite in SUITES.items():
        if analyses and name not in analyses:
            continue
        t0 = time.perf_counter()
        points += suite(quick)
        if log:
            log(f"{name}: {time.perf_counter() - t0:.1f} s")
    pareto(points)
    return points
