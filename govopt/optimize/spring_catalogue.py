"""A spring that can be ordered: the wire from a table of sizes, the coils on a step (half
turns), the best one certified by a bounded enumeration against the GP's bound.

:func:`govopt.optimize.spring_sizing.size_spring` first solves the continuous problem; its
relaxation over every wire (``Sizing.relaxation``: the GP whose rows each lie on or beyond the
exact ones for every wire of the grade, :func:`~govopt.optimize.spring_sizing.size_spring`)
then bounds each wire from below. With the wire fixed, that GP's optimum is convex in the
logarithm of the wire's diameter (a partial minimisation of a problem convex in the logarithms
of its variables, Boyd and Vandenberghe, *Convex Optimization*, 3.2.5), so walking the table
outwards from the continuous optimum, each direction stops at the first wire whose bound
exceeds the best spring found: no wire beyond it can do better.

Each wire that is not pruned is enumerated exactly: every wound coil count on the step (a
compression spring's active coils, an extension spring's body coils) between the counts the
index range allows, the mean diameter that gives the stiffness (at a stiffness range's two
ends: every objective is monotone in ``D`` at fixed wire and coils), the spring drawn as the
continuous design's is (:func:`~govopt.optimize.spring_sizing.drawn`) and held against every
row of the spring's table (:func:`govopt.springs.checks.evaluate`, the fatigue rows at the
load cycle) and the problem's limits. The best spring is the exact optimum of the discrete
problem: its own value is the certified bound (gap 0), and the record says how many wires and
springs the proof examined and how far the continuous optimum lies below.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from ..limits import MAX_SPRINGS
from ..springs import checks as ck
from ..springs import compression as hc
from ..springs import helical as hx
from ..springs import tolerances as tl
from ..springs.assessment import Spring, table, table_keywords
from ..verdict import holds
from .spring_sizing import Sizing, drawn, dual_bound, objective_value, size_spring

__all__ = ["catalogue_sizing", "size_orderable_spring"]


def _interval(lo: float, hi: float, step: float) -> np.ndarray:
    """The multiples of ``step`` in ``[lo, hi]`` (rounding allowed at the ends)."""
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi < lo:
        return np.zeros(0)
    k0, k1 = math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9)
    if k1 - k0 + 1 > MAX_SPRINGS:
        raise ValueError(f"{k1 - k0 + 1} coil counts on the step {step} for one wire: more than "
                         f"{MAX_SPRINGS}")
    return np.arange(max(k0, 1), k1 + 1, dtype=float) * step


def _candidates(s: Sizing, w: float, step: float, limits: dict, ends: str, L2):
    """Every spring of wire ``w`` with the wound coils on ``step`` (module docstring), as a
    drawn :class:`Spring` of arrays, and its active coils."""
    mat, kind = s.mat, s.kind
    G, E = float(mat.shear_modulus(w)), float(mat.elastic_modulus(w))
    extra = 0.0 if kind == "compression" else G / E  # active = wound + G/E (the loops)
    k_lo, k_hi = limits["kappa_min"], limits["kappa_max"]
    C_lo, C_hi = s.rules.index
    # the index range bounds the active coils through the stiffness: n = G d / (8 R C^3)
    n_lo = max(limits.get("n_min") or 0.0, G * w / (8.0 * k_hi * C_hi**3))
    n_hi = min(limits.get("n_max") or math.inf, G * w / (8.0 * k_lo * C_lo**3))
    wound = _interval(n_lo - extra, n_hi - extra, step)
    n = wound + extra
    D = [(G * w**4 / (8.0 * k * n)) ** (1.0 / 3.0) for k in sorted({k_lo, k_hi})]
    n, D = np.concatenate([n] * len(D)), np.concatenate(D)
    return drawn(kind, mat, np.full(n.shape, w), D, n, s.loads.F1, s.loads.F2, ends=ends,
                 L2=L2), n


def _feasible(s: Sizing, sp: Spring, n: np.ndarray, limits: dict,
              spared: frozenset = frozenset()) -> np.ndarray:
    """Where the springs ``sp`` (arrays) meet every row of the spring's table that the
    material can give (:func:`govopt.springs.assessment.table`'s) and the problem's limits,
    each with the checks' own tolerance (:func:`govopt.verdict.holds`: a row holds at
    equality); the rows named in ``spared`` are not required (:func:`catalogue_sizing`: only
    when no spring passes them)."""
    d, D = sp.d, sp.D
    ok = np.ones(np.shape(n), dtype=bool)
    kw = table_keywords(sp, s.mat, s.loads, s.rules)
    rows = [(name, v, lim) for name, (v, lim) in ck.evaluate(s.kind, **kw).items()
            if "fatigue" not in name]
    if s.loads.cycle is not None:
        kw.update(F1=min(s.loads.cycle), F2=max(s.loads.cycle))
        rows += [(name, v, lim) for name, (v, lim) in ck.evaluate(s.kind, **kw).items()
                 if "fatigue" in name]
    senses = {r.name: r.sense for r in ck.TABLES[s.kind] + ck.COMMON}
    for name, v, lim in rows:
        if np.all(np.isnan(lim)) or name in spared:  # a grade's row, no grade: not checked
            continue
        ok &= holds(v, lim, senses[name])
    G = s.mat.shear_modulus(d)
    f_e = hx.surge_frequency(d, D, n, G, s.mat.density)
    space = [("D_out_max", D + d, "<="), ("L_body_max", (n + 1.0) * d, "<="),
             ("f_surge_min", f_e, ">="), ("Di_min", D - d, ">="), ("L0_max", sp.L0, "<=")]
    if s.kind == "compression":
        space.append(("Lc_max", hc.solid_length(tl.max_wire_diameter(d, s.mat.grade),
                                                 sp.total_coils, sp.form), "<="))
    for key, value, sense in space:
        if limits.get(key) is not None:
            ok &= holds(value, limits[key], sense)
    return ok


def _pieces(s: Sizing, wires: list[float]) -> list[tuple[list[float], object, dict]]:
    """The table's wires split by the relaxations' pieces (``Sizing.relaxation``: one per
    range of wires with constant moduli), each piece's wires ordered outwards from its
    relaxation's own optimum (the least of its per-wire bounds, convex in log d)."""
    out = []
    for lo, hi, gp, values in s.relaxation:
        mine = [w for w in wires if lo * (1 - 1e-9) <= w <= hi * (1 + 1e-9)]
        if not mine:
            continue
        sol = gp.solve(**{**values, "d_min": max(lo, mine[0]), "d_max": min(hi, mine[-1])})
        centre = float(sol.d) if sol.ok else mine[0]
        split = int(np.searchsorted(mine, centre))
        out += [(side, gp, values) for side in (mine[split:], mine[:split][::-1])]
    return out


def catalogue_sizing(s: Sizing, wires: Sequence[float], step: float, limits: dict, *,
                     ends: str, L2: float | None, source: str) -> Sizing:
    """The best spring with a wire of ``wires`` (m) and its wound coils on ``step`` (module
    docstring), from the continuous sizing ``s``; ``limits``: the stiffness (``kappa_min``,
    ``kappa_max``, equal for one stiffness) and the GP's bounds and space (``n_min``,
    ``D_out_max``, ``Di_min``, ``L0_max`` ...); ``source``: where the sizes come from (the
    record's notes). Every row is required; only where no spring of the table passes a row
    the continuous design fails too (an extension spring's initial tension without a least
    force, say) is the best spring that passes the others returned, failing it (its checks
    say so, exit code 1)."""
    lo, hi = limits.get("d_min") or 0.0, limits.get("d_max") or math.inf
    lo, hi = max(lo, s.mat.d_min), min(hi, s.mat.d_max)
    table_wires = sorted({float(w) for w in wires if lo * (1 - 1e-9) <= w <= hi * (1 + 1e-9)})
    stats = {"wires in range": len(table_wires), "wires enumerated": 0,
             "wires pruned by their bound": 0, "springs examined": 0}
    pieces = _pieces(s, table_wires)

    def search(spared: frozenset):
        best: tuple[float, Spring, int] | None = None
        bounds: dict[float, float] = {}

        def bound_of(w: float, gp, values) -> float:
            if w not in bounds:
                sol = gp.solve(**{**values, "d_min": w, "d_max": w})
                bounds[w] = (math.inf if sol.status == "infeasible" else
                             dual_bound(sol) if sol.ok else -math.inf)
            return bounds[w]

        for side, gp, values in pieces:  # outwards from each piece's relaxation optimum
            for w in side:
                b = bound_of(w, gp, values)
                if best is not None and b > best[0] * (1.0 + 1e-9):
                    stats["wires pruned by their bound"] += len(side) - side.index(w)
                    break  # convex in log d: every wire beyond is bounded higher still
                if math.isinf(b) and b > 0:
                    continue  # no spring at all with this wire
                sp, n = _candidates(s, w, step, limits, ends, L2)
                stats["wires enumerated"] += 1
                stats["springs examined"] += int(np.size(n))
                if not np.size(n):
                    continue
                ok = _feasible(s, sp, n, limits, spared)
                if not ok.any():
                    continue
                value = np.asarray(objective_value(s.objective, sp, s.mat, s.loads.F2),
                                   dtype=float)
                i = int(np.argmin(np.where(ok, value, np.inf)))
                if best is None or value[i] < best[0]:
                    best = (float(value[i]), sp, i)
        return best

    best = search(frozenset())
    unmet = frozenset(c.name for c in s.checks if not c.passed)
    if best is None and unmet:  # nothing passes every row: the best failing only those
        best = search(unmet)
    if best is None:
        why = (f"no spring with a wire of the table ({len(table_wires)} sizes between "
               f"{lo * 1e3:.4g} and {hi * 1e3:.4g} mm; {source.split(':')[0]}) and coils on "
               f"the step {step:g} meets every requirement; the continuous optimum has d = "
               f"{s.spring.d * 1e3:.4g} mm, n = {s.spring.coils:.4g} (--wire-sizes continuous), "
               "or try a finer --coil-step")
        sol = replace(s.solution, status="infeasible")
        return Sizing(sol, s.kind, diagnosis=why, mat=s.mat, loads=s.loads, rules=s.rules,
                      objective=s.objective)
    _, sp, i = best
    spring = Spring(sp.kind, *(float(np.asarray(x)[i]) if np.ndim(x) else float(x)
                               for x in (sp.d, sp.D, sp.coils, sp.end_coils, sp.L0)),
                    sp.form, float(np.asarray(sp.F0)[i]) if np.ndim(sp.F0) else float(sp.F0))
    checks, _ = table(spring, s.mat, s.loads, s.rules)
    out = Sizing(s.solution, s.kind, checks, mat=s.mat, loads=s.loads, rules=s.rules,
                 objective=s.objective, cycles=s.cycles, spring=spring,
                 method=(f"bounded enumeration of the wire table and the coils on the step "
                         f"{step:g}, each wire bounded by the continuous GP with that wire"),
                 search=stats)
    out.lower_bound = out.value  # exact by enumeration: the optimum is its own bound
    out.notes.append(f"wire sizes: {source}")
    failing = [c.name for c in checks if not c.passed]
    if failing:  # no optimum: the bound is the continuous relaxation's, of a passing spring
        out.lower_bound = s.lower_bound
        out.notes.append("no spring of the wire table and the coils on the step passes "
                         + ", ".join(failing) + " (nor does the continuous design): this is "
                         "the lightest that passes the other checks")
    if math.isfinite(s.lower_bound):  # the price of ordering: against the certified bound
        price = (out.value / s.lower_bound - 1 if s.objective != "mass per energy"
                 else s.lower_bound / out.value - 1)
        out.notes.append(f"a spring of any wire and coils cannot do better than the "
                         f"continuous relaxation's certified bound; this orderable spring is "
                         f"within {100 * price:.3g} % of it")
    return out


def size_orderable_spring(F_max: float, stiffness: float, *, wires: Sequence[float],
                          coil_step: float = 0.5, wire_source: str = "", **kw) -> Sizing:
    """The best spring with a wire of ``wires`` (m) and its coils on ``coil_step``
    (:func:`catalogue_sizing`) for the problem of
    :func:`govopt.optimize.spring_sizing.size_spring` (``kw``: its keywords);
    ``wire_source``: where the table comes from."""
    sizing = size_spring(F_max, stiffness, **kw)
    if not sizing.solution.ok:
        return sizing
    bounds = {k: v for k, v in kw.items() if k in (
        "n_min", "n_max", "C_min", "C_max", "D_out_max", "L_body_max", "f_surge_min", "d_min",
        "d_max", "Di_min", "L0_max", "Lc_max")}
    limits = {**bounds, "kappa_min": stiffness,
              "kappa_max": kw.get("stiffness_max") or stiffness}
    return catalogue_sizing(sizing, wires, coil_step, limits, ends=sizing.spring.form,
                            L2=kw.get("L2"), source=wire_source)
