"""A helical spring sized on its own (``govopt spring``): the spring GP, then the spring maker's
checks of a wire grade.

Without a grade this is :func:`govopt.optimize.spring_gp.size_helical_spring` (least mass at a
stiffness and largest force, certified global). With a grade (:mod:`govopt.springs.materials`)
the allowable static stress is the standard's rule ``fraction R_m(d)`` (EN 13906-1/-2 or
Shigley); the GP takes it as a monomial ``k d^-m``, the rule's tangent in log-log at the
centre of a window of wire diameters about the solution,
re-fitted until the wire settles at the window's centre (the tangent of the rule there). The
certified lower bound is that GP's, or where the tangent does not lie above the rule over all
the grade's wires (a step table's rows) the same GP with the fit raised until it does. Then
the spring kind's own table
(:mod:`govopt.springs.checks`) is evaluated on the GP's spring: a compression spring gets the
least free length that keeps the coils clear at the largest force (EN 13906-1: ``L0 = L_c +
S_a + F_max / R``), ``n_t = n + 2`` (closed ends); an extension spring ``n_b = n - G/E`` and the
initial tension in the middle of Shigley's preferred range (at most the least force). A fatigue
load cycle ``F_lo .. F_hi`` adds the fatigue rows. When a stress row fails (an extension
spring's hooks, which the GP does not model, or the fatigue safety), the body's allowable is
lowered in proportion and the GP re-solved (a heuristic outer loop: the result passes the
stress and fatigue rows, its optimality certificate is that of the last GP only).

>>> s = size_spring(1000.0, 20e3, grade="EN10270-1 DH", kind="compression", n_max=30)
>>> stress = {c.name: c for c in s.checks if c.unit == "Pa"}
>>> s.solution.status, all(c.passed for c in stress.values())
('optimal', True)
>>> c = stress["shear stress at solid length"]  # binds: 0.56 R_m(d) (EN 13906-1)
>>> round(c.value / c.limit, 3), s.certified
(1.0, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..springs import checks as ck
from ..springs import helical as hx
from ..springs import materials as mt
from .spring_gp import SpringSolution, cached_gp

KINDS = ("compression", "extension")
#: Inactive coils of a compression spring: one closed end coil each side, ``n_t = n + 2``
#: (EN 13906-1:2013, total coils for cold-coiled springs with closed ends; Shigley Table 10-1).
COMPRESSION_END_COILS = 2.0


def end_coils(kind: str, mat=None) -> float:
    """Coils of wire beyond the ``n`` active ones, counted in the mass (EN 13906-1: the wire
    length ``pi D n_t`` counts ends and hooks as coils).

    Compression: :data:`COMPRESSION_END_COILS`. Extension (EN 13906-2:2013, active coils
    ``n = n_b + G/E``): the body's ``n_b = n - G/E`` coils plus two hooks or loops of one coil
    each, i.e. ``2 - G/E`` (``2`` without a grade, as ``E`` is then unknown)."""
    if kind == "compression":
        return COMPRESSION_END_COILS
    if mat is None:
        return 2.0
    return 2.0 - float(mat.shear_modulus(1e-3) / mat.elastic_modulus(1e-3))


@dataclass
class Sizing:
    """The GP's spring and, with a grade, the spring engineering checks on it."""

    solution: SpringSolution
    kind: str
    checks: list = field(default_factory=list)
    free_length: float = math.nan
    initial_tension: float = math.nan
    allowable_factor: float = 1.0
    notes: list[str] = field(default_factory=list)
    #: a certified lower bound on the objective (the relaxation's GP optimum; nan: none)
    lower_bound: float = math.nan
    #: the required fatigue life (cycles)
    cycles: float = 1e7
    #: why no spring was found (the relaxed GP's diagnosis), empty when one was
    diagnosis: str = ""
    #: a compression spring's solid length ``L_c`` and least working length ``L_n = L_c +
    #: S_a`` (m, EN 13906-1; nan for extension), set with the free length by :func:`lengths`
    solid_length: float = math.nan
    least_length: float = math.nan

    @property
    def gap(self) -> float:
        """``objective / lower_bound - 1``: how far from optimal the design can be at most."""
        return self.solution.objective / self.lower_bound - 1.0

    @property
    def certified(self) -> bool:
        """The design is a proven global optimum (within 1e-6 of the certified bound)."""
        return bool(self.gap <= 1e-6)

    @property
    def passed(self) -> bool:
        return all(c.passed for c in self.checks)


def _kw(kind, mat, d, D, n, F_min, F_max, *, rules, allowable, correction, peened, cycles,
        index, ends, seating, L2=None):
    """The library's keywords for one spring (free length, coils and initial tension as the
    module docstring says; with the installed length ``L2`` at ``F_max`` the free length is
    ``L2 + F_max / R``)."""
    kw = dict(mat=mat, d=d, D=D, F1=F_min, F2=F_max, method=rules, allowable=allowable,
              correction=correction, peened=peened, cycles=cycles, index_min=index[0],
              index_max=index[1])
    if kind == "compression":
        R = float(hx.stiffness(d, D, n, mat.shear_modulus(d)))
        n_t = n + 2.0
        L0 = (float(hx.min_working_length(d, D, n, n_t, ends, dynamic=True)) if L2 is None
              else L2) + F_max / R
        kw.update(n=n, n_t=n_t, L0=L0, ends=ends, seating=seating)
    else:
        lo, hi = hx.initial_tension_range(hx.spring_index(d, D))
        F0 = float(min(hx.force_at_stress(0.5 * (lo + hi), d, D), F_min))
        kw.update(n_body=n - float(mat.shear_modulus(d) / mat.elastic_modulus(d)), F0=F0)
    return kw


def size_spring(F_max: float, stiffness: float, *, grade: str | None = None,
                kind: str = "compression", k_s: float | None = None, G: float | None = None,
                density: float | None = None, tensile_strength: float | None = None,
                rules: str = "EN13906", correction: str | None = None, F_min: float = 0.0,
                fatigue: tuple[float, float] | None = None, min_fatigue_safety: float = 1.0,
                peened: bool = False, cycles: float = 1e7, ends: str = "closed_ground",
                seating: str = "fixed-fixed", objective: str = "mass",
                stiffness_max: float | None = None, L2: float | None = None,
                **bounds) -> Sizing:
    """Size a spring (SI): see the module docstring. ``bounds``: the GP's optional limits
    (``n_min``, ``n_max``, ``C_min``, ``C_max``, ``D_out_max``, ``L_body_max``,
    ``f_surge_min``, ``d_min`` ...); with a grade the index defaults to EN 13906-1's 4..20.
    The space it is built into (GP constraints, :meth:`SpringGP._envelope`): ``Di_min`` (the
    inside diameter over a rod), and for a compression spring ``L0_max`` (its least free
    length: coils clear at ``F_max``) and ``Lc_max`` (its solid length). With
    ``stiffness_max`` the stiffness may lie anywhere in ``stiffness .. stiffness_max`` (the GP's
    band mode). ``L2``: the installed (working) length at ``F_max`` of a compression spring; the
    coils stay clear there (GP row ``working length``) and the free length is ``L2 + F_max /
    R`` (the solid-length stress row of the GP then takes the least free length: a relaxation,
    checked exactly afterwards)."""
    if kind not in KINDS:
        raise ValueError(f"spring kind must be one of {KINDS}, got {kind!r}")
    space = {k: bounds.pop(k) for k in ("Di_min", "L0_max", "Lc_max")
             if bounds.get(k) is not None}
    for k in ("Di_min", "L0_max", "Lc_max"):
        bounds.pop(k, None)
    if kind == "extension" and (set(space) - {"Di_min"} or L2 is not None):
        raise ValueError("free, solid and installed length limits are for compression springs")
    if L2 is not None:
        space.update(L2=L2, Ln_max=L2, clear=1e-12)
    envelope = kind if space else None
    if kind == "compression":
        space["solid_coils"] = end_coils(kind) + hx.END_FORMS[ends][0]
    relaxed = dict(space)  # the relaxation gives the bound; with L2 the design's GP restricts
    if L2 is not None:
        space.update(L2_solid=L2, clear_solid=1e-12, pitch_on=1.0)
    mode, rate = "equality", {"kappa": stiffness}
    if stiffness_max is not None:
        if not stiffness <= stiffness_max:
            raise ValueError(f"stiffness range {stiffness!r} .. {stiffness_max!r} is empty")
        mode, rate = "band", {"kappa_min": stiffness, "kappa_max": stiffness_max}
    if grade is None:
        correction = correction or "wahl"
        gp = cached_gp(objective, correction, mode, 0.0, end_coils(kind), envelope=envelope)
        sol = gp.solve(certify=True, **rate, F_max=F_max, k_s=k_s, G=G, density=density,
                       **space, **bounds)
        why = "" if sol.ok else sol.status if sol.status != "infeasible" else diagnose(
            gp, **rate, F_max=F_max, k_s=k_s, G=G, density=density, **space, **bounds)
        return lengths(Sizing(sol, kind, lower_bound=_bound(sol), diagnosis=why), F_max, ends,
                       L2)
    mat = mt.material(grade, tensile_strength=tensile_strength, G=G, density=density)
    if not isinstance(mat.G, float):
        raise ValueError(f"grade {grade!r}: the shear modulus varies with the wire diameter "
                         f"({mat.moduli_source}): give it")
    correction = correction or hx.DEFAULT_CORRECTION[(rules, "static")]
    bounds = {"C_min": 4.0, "C_max": 20.0, **bounds}
    index = (bounds["C_min"], bounds["C_max"])
    place = "compression" if kind == "compression" else "extension"
    G, density = mat.G, mat.density
    lo, hi = max(mat.d_min, bounds.get("d_min") or 0.0), min(mat.d_max, bounds.get("d_max")
                                                          or math.inf)
    state = {"window": (lo, hi)}

    Q = end_coils(kind, mat)
    if kind == "compression":  # the slenderness that cannot buckle
        stable = float(hx.critical_free_length(1.0, G, mat.elastic_modulus(math.sqrt(lo * hi)),
                                               hx.SEATING[seating]))

    def attempt(factor, slender=None, refit=True, relax=False):
        """The GP at ``factor`` times the rule, re-fitted until the wire settles (with
        ``slender``: free length <= ``slender`` times the longest that cannot buckle; without
        ``refit`` one solve with the current fit, the same compiled GP); the checks and the
        worst ratio of a stress or fatigue row (< 1: it fails)."""
        base = relaxed if relax else {**space, **state.get("installed", {})}
        extra = dict(base) if slender is None else {**base,
                                                    "L0_over_D_max": slender * stable}
        for _ in range(60):
            k, m = _monomial(mat, place, rules, k_s, *state["window"])
            m_c = None
            if kind == "compression":  # the stress at solid length, a constraint too
                k_c, m_c = _monomial(mat, "solid", rules, None, *state["window"])
                extra.update(k_solid=k_c, s_over_D_max=stable)
            gp = cached_gp(objective, correction, mode, m, Q, slender is not None, m_c,
                            envelope)
            values = dict(**rate, F_max=F_max, k_s=k * factor, G=G, density=density,
                          **{**bounds, "d_min": lo, "d_max": hi}, **extra)
            sol = gp.solve(**values)
            state["fit"] = (gp, values, k, m, m_c)
            if not sol.ok:
                text = diagnose(gp, **values) if sol.status == "infeasible" else sol.status
                if factor < 1.0:
                    text += (f" (with the allowable lowered to {factor:.3g} of the rule's for "
                             "the fatigue or hook rows)")
                return Sizing(sol, kind, diagnosis=text), 0.0
            new = (max(lo, sol.d / 1.25), min(hi, sol.d * 1.25))
            if not refit or np.allclose(new, state["window"], rtol=1e-5, atol=0.0):
                break
            state["window"] = new  # re-fit the allowable about this wire
        sizing = _checked(sol, kind, mat, F_min, F_max, fatigue, rules=rules, k_s=k_s,
                          correction=correction, peened=peened, cycles=cycles, index=index,
                          ends=ends, seating=seating, need=min_fatigue_safety, L2=L2)
        sizing.allowable_factor = factor
        return sizing, min((_ratio(c) for c in sizing.checks
                            if (c.unit == "Pa" and c.sense == "<=") or "fatigue" in c.name),
                           default=math.inf)

    def certified_bound(sizing) -> float:
        """The bound of the GP just solved (at the rule's own allowable), made valid for every
        wire: the monomial fit raised to lie above the rule over the grade's diameters
        (:func:`_domination`), the GP solved again with it when it had to rise (a step table's
        rows, an interpolated table's kinks); a concave rule's tangent already lies above."""
        gp, values, k, m, m_c = state["fit"]
        if not sizing.solution.ok:
            return math.nan
        raised = {"k_s": _domination(mat, place, rules, k_s, k, m, lo, hi)}
        if m_c is not None:
            raised["k_solid"] = _domination(mat, "solid", rules, None, values["k_solid"], m_c,
                                            lo, hi)
        if all(f <= 1.0 + 2e-6 for f in raised.values()):
            return _bound(sizing.solution)
        relaxed_sol = gp.solve(**{**values, **{key: values[key] * f
                                               for key, f in raised.items()}})
        return _bound(relaxed_sol)

    if L2 is not None:  # there the design's GP restricts; its relaxation bounds: first
        loose, _ = attempt(1.0, relax=True)
        bound = certified_bound(loose)
        if not loose.solution.ok:  # nor can the restriction be met: the relaxation's diagnosis
            return loose
        if loose.passed:  # the relaxation's design passes: optimal
            loose.lower_bound, loose.cycles = bound, cycles
            return lengths(loose, F_max, ends, L2)
        state["window"] = (lo, hi)  # the design's GP fitted afresh, as without the relaxation
    sizing, worst = attempt(1.0)
    if L2 is None:
        bound = certified_bound(sizing)  # the GP is a relaxation of the rows: a lower bound
    sizing = _stress_search(attempt, sizing, worst)
    if sizing.solution.ok and kind == "compression":
        sizing = _buckling_search(attempt, sizing, stable)
    if sizing.solution.ok and L2 is not None:
        sizing = _installed_search(attempt, sizing, state, L2, ends)
    sizing.lower_bound, sizing.cycles = bound, cycles
    return lengths(sizing, F_max, ends, L2)


def lengths(sizing: Sizing, F_max: float, ends: str, L2: float | None = None) -> Sizing:
    """The sized spring's lengths, computed once for every output (text, JSON, workbook and
    force-length plot read them). A compression spring: its solid length ``L_c``
    (:func:`govopt.springs.helical.solid_length`, EN 13906-1 by the end form), least working
    length ``L_n = L_c + S_a`` (EN 13906-1, dynamic) and, where the checks did not set it (no
    grade), its free length ``L2 + F_max / R`` or ``L_n + F_max / R`` as :func:`_kw`. An
    extension spring: the free length of its ``n + end coils - 2`` body coils (EN 13906-2,
    :func:`govopt.springs.helical.extension_free_length`). Lengths in m, ``F_max`` in N."""
    sol = sizing.solution
    if not sol.ok:
        return sizing
    d, D, n, n_t = sol.d, 2.0 * sol.r, sol.n, sol.n + sol.end_coils
    if sizing.kind == "compression":
        sizing.solid_length = float(hx.solid_length(d, n_t, ends))
        sizing.least_length = float(hx.min_working_length(d, D, n, n_t, ends, dynamic=True))
        if not math.isfinite(sizing.free_length):
            sizing.free_length = (sizing.least_length if L2 is None else L2) \
                + F_max / sol.stiffness
    elif not math.isfinite(sizing.free_length):
        sizing.free_length = float(hx.extension_free_length(d, D, n_t - 2.0))
    return sizing


def diagnose(gp, **values) -> str:
    """Which limits of the GP ``gp`` must move, and by what factor (:meth:`SpringGP.diagnose`);
    when no limit moved by up to 1e6 helps (an absurd value, e.g. 1e308 turns), again with
    factors up to 1e300 (the GP is solved in logarithms)."""
    why = gp.diagnose(**values)
    if not why.conflicting and not why.relaxations:
        wide = gp.diagnose(max_factor=1e300, **values)
        if wide.conflicting or wide.relaxations:
            return wide.summary()
    return why.summary()


def _bound(sol) -> float:
    """The solver's dual objective: a lower bound on the GP's optimum (nan unless optimal)."""
    return float(sol.certificate.get("objective_lower_bound", math.nan))


def _failed_buckling(sizing) -> bool:
    return any(c.name == "deflection / buckling deflection" and not c.passed
               for c in sizing.checks)


def _buckling_search(attempt, sizing, stable):
    """Buckling (EN 13906-1, 9.14) as a constraint. Its limit is not a posynomial, but a free
    length below the slenderness that cannot buckle (``L0 <= stable D``) is; a free length of
    ``s`` times that may still pass (the deflection stays below ``s_K``). Bisection on ``s``
    from 1 (safe when feasible) to the unconstrained design's slenderness finds the least-mass
    design that passes, to 0.1 %; the GP without it stays the certified lower bound."""
    if not _failed_buckling(sizing):
        return sizing
    factor = sizing.allowable_factor
    safe, _ = attempt(factor, 1.0)
    if not safe.solution.ok or _failed_buckling(safe):
        sizing.notes.append("no spring passes the buckling check within the other limits: "
                            "guide it (--seating) or allow a larger diameter")
        return sizing
    sol = sizing.solution
    good, bad = 1.0, float(sizing.free_length / (2.0 * sol.r) / stable)
    while bad / good > 1.001:  # one compiled GP: the allowable's fit is frozen meanwhile
        mid = math.sqrt(good * bad)
        trial, _ = attempt(factor, mid, refit=False)
        if trial.solution.ok and not _failed_buckling(trial):
            good = mid
        else:
            bad = mid
    for _ in range(20):  # the fit re-centred on the design found; back off if that buckles
        trial, _ = attempt(factor, good)
        if trial.solution.ok and not _failed_buckling(trial) and trial.passed >= safe.passed:
            safe = trial
            break
        good = max(1.0, good * 0.998)
    safe.allowable_factor = factor
    safe.notes = sizing.notes + [
        f"buckling binds: the free length is held to {good:.4g} times the slenderness that "
        "cannot buckle (EN 13906-1, 9.14), found by bisection to 0.1 %"]
    return safe


def _installed_search(attempt, sizing, state, L2, ends):
    """The installed length's stress at solid length, tightened. The GP bounds the force at
    solid length ``F_max + R (L2 - L_c)`` by ``F_max + R (L2 - lam)`` (``L2_solid = L2 - lam``,
    a monomial), which is safe for every spring with ``L_c >= lam``; ``lam = 0`` (the first
    design) always is. Bisection on ``lam = theta L_c`` of the design found keeps the lightest
    design whose solid length is at least its ``lam`` and that passes every check, to 0.1 %;
    the bound stays the relaxation's (:func:`size_spring`)."""
    def solid(s):
        sol = s.solution
        return float(hx.solid_length(sol.d, sol.n + sol.end_coils, ends))

    factor, best, notes = sizing.allowable_factor, sizing, list(sizing.notes)
    lo, hi = 0.0, 1.0
    while hi - lo > 1e-3:  # one compiled GP: the allowable's fit is frozen meanwhile
        mid = 0.5 * (lo + hi)
        lam = mid * solid(best)
        state["installed"] = {"L2_solid": L2 - lam}
        trial, _ = attempt(factor, refit=False)
        if trial.solution.ok and solid(trial) >= lam and trial.passed and \
                trial.solution.objective <= best.solution.objective:
            lo, best = mid, trial
        else:
            hi = mid
    if best is not sizing:
        best.allowable_factor = factor
        best.notes = notes + [
            f"the force at solid length is bounded by F + R (L2 - {lo:.3g} L_c) (a posynomial "
            "restriction of F + R (L2 - L_c)), found by bisection to 0.1 %"]
    return best


def _stress_search(attempt, sizing, worst):
    """The body's allowable lowered until the hooks' and fatigue rows pass (module docstring)."""
    if not sizing.solution.ok or worst >= 1.0:
        return sizing
    bad, good = 1.0, None  # the largest factor that passes, by steps down then bisection
    factor = 1.0
    for _ in range(30):
        factor *= float(np.clip(worst, 0.5, 0.99))
        trial, worst = attempt(factor)
        if not trial.solution.ok:
            return trial
        if worst >= 1.0:
            good, sizing = factor, trial
            break
        bad = factor
    if good is None:
        return sizing
    for _ in range(12):  # one compiled GP: the allowable's fit is frozen meanwhile
        mid = math.sqrt(good * bad)
        trial, worst = attempt(mid, refit=False)
        if trial.solution.ok and worst >= 1.0:
            good = mid
        else:
            bad = mid
    for _ in range(20):  # the fit re-centred on the design found; back off if a row fails
        trial, worst = attempt(good)
        if trial.solution.ok and worst >= 1.0:
            sizing = trial
            break
        good *= 0.998
    sizing.notes.append(f"the body's allowable was lowered to {good:.4g} of the rule's so that "
                        "the hooks' static stresses and the fatigue rows pass too (heuristic "
                        "outer search; the certified bound is the relaxation's)")
    return sizing


def _domination(mat, place, rules, k_s, k, m, lo, hi) -> float:
    """How far ``k d^-m`` must rise to lie on or above the rule's allowable at every wire in
    ``[lo, hi]`` (m): the largest ``allowable d^m / k`` at 513 log-spaced wires and the
    table's nodes (a step table's row ends, where a row's ``allowable d^m`` peaks), at least 1
    (an explicit ``k_s``: 1)."""
    if k_s is not None:
        return 1.0
    d = np.geomspace(lo, hi, 513)
    nodes = mat.rm_nodes
    d = np.union1d(d, nodes[(nodes > lo) & (nodes < hi)])
    allow = mt.allowable_static_stress(mat, d, place, rules)
    ok = np.isfinite(allow)
    return max(1.0, float(np.max(allow[ok] * d[ok] ** m) / k)) if np.any(ok) else 1.0


def _monomial(mat, place, rules, k_s, lo, hi):
    """``(k, m)``: the rule's allowable as ``k d^-m``, tangent in log-log at the window's
    geometric centre (:meth:`~govopt.springs.materials.Material.strength_exponent`: a step
    table's trend) and shaved by 1e-6 (an explicit ``k_s``: m = 0). Once the wire settles at
    the centre, the GP's stress limit is the rule's at that wire."""
    if k_s is not None:
        return float(k_s), 0.0
    dc = math.sqrt(lo * hi)
    m = mat.strength_exponent(dc)  # the rule is a fraction of R_m: R_m's exponent
    a = float(mt.allowable_static_stress(mat, dc, place, rules))
    return float(a * dc**m * (1.0 - 1e-6)), m


def _checked(sol, kind, mat, F_min, F_max, fatigue, *, rules, k_s, correction, peened,
             cycles, index, ends, seating, need, L2=None) -> Sizing:
    """The spring kind's table on the GP's spring, with the fatigue rows for the cycle."""
    d, D, n = sol.d, 2.0 * sol.r, sol.n
    kw = _kw(kind, mat, d, D, n, F_min, F_max, rules=rules, allowable=k_s,
             correction=correction, peened=peened, cycles=cycles, index=index, ends=ends,
             seating=seating, L2=L2)
    rows = [c for c in ck.checks(kind, fatigue_safety=need, **kw) if "fatigue" not in c.name]
    if fatigue is not None:
        kw.update(F1=min(fatigue), F2=max(fatigue))
        rows += [c for c in ck.checks(kind, fatigue_safety=need, **kw) if "fatigue" in c.name]
    return Sizing(sol, kind, rows, free_length=float(ck.prepare(kind, **kw)["L0"]),
                  initial_tension=float(kw.get("F0", math.nan)))


__all__ = ["KINDS", "Sizing", "diagnose", "end_coils", "lengths", "size_spring"]


def _ratio(check) -> float:
    """How far a check is from its limit as a ratio (>= 1 passes): ``limit/value`` for ``<=``,
    ``value/limit`` for ``>=``; a zero denominator is as far as it gets (inf)."""
    num, den = (check.limit, check.value) if check.sense == "<=" else (check.value, check.limit)
    return num / den if den else math.inf
