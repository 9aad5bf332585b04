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

from ..springs import compression as hc
from ..springs import extension as he
from ..springs import helical as hx
from ..springs import materials as mt
from ..springs import tolerances as tl
from ..springs.assessment import Loads, Rules, Spring, extension_free_length, table
from .gp_table import DEFAULT_BOUNDS
from .record import CERTIFIED_GAP, Objective, Record
from .spring_gp import FREE_LENGTH_KEYS, cached_gp
from .spring_results import SpringSolution

KINDS = ("compression", "extension")


def end_coils(kind: str, mat=None, ends: str = "closed_ground") -> float:
    """Coils of wire beyond the ``n`` active ones, counted in the mass (EN 13906-1: the wire
    length ``pi D n_t`` counts ends and loops as coils).

    Compression: the end form's inactive coils (:func:`govopt.springs.compression.end_coils`: 2
    for closed ends, EN 13906-1 ``n_t = n + 2``). Extension (``ends``: its loops,
    :data:`govopt.springs.extension.HOOKS`; EN 13906-2:2013, active coils ``n = n_b + G/E``):
    the body's ``n_b = n - G/E`` coils plus the loops' coils of wire, i.e. ``2 h - G/E`` (``h``
    a loop's coils, 1 for a full loop; ``2 h`` without a grade, as ``E`` is then unknown)."""
    if kind == "compression":
        return hc.end_coils(ends)
    loops = 2.0 * he.HOOKS[ends].coils
    if mat is None:
        return loops
    return loops - float(mat.shear_modulus(1e-3) / mat.elastic_modulus(1e-3))


@dataclass
class Sizing:
    """The GP's spring as drawn (:class:`govopt.springs.assessment.Spring`) with its material,
    loads and rules, the spring kind's checks on it, and the certified lower bound on the
    objective."""

    solution: SpringSolution
    kind: str
    checks: list = field(default_factory=list)
    allowable_factor: float = 1.0
    notes: list[str] = field(default_factory=list)
    #: a certified lower bound on the GP's objective (the relaxation's optimum; nan: none)
    lower_bound: float = math.nan
    #: the required fatigue life (cycles)
    cycles: float = 1e7
    #: why no spring was found (the relaxed GP's diagnosis), empty when one was
    diagnosis: str = ""
    #: the spring as drawn, and what :func:`govopt.springs.assessment.assess` needs beside it
    spring: Spring | None = None
    mat: mt.Material | None = None
    loads: Loads | None = None
    rules: Rules | None = None
    #: the GP's objective's name (:data:`govopt.optimize.spring_results.OBJECTIVES`)
    objective: str = "mass"
    #: how the design was found (the GP; a catalogue's enumeration, :mod:`.spring_catalogue`)
    method: str = "geometric programme (cvxpy; exact: convex in the logarithms of d, D, n)"
    #: counts of a catalogue's enumeration (empty for the continuous GP)
    search: dict = field(default_factory=dict)
    #: per range of wires ``(lo, hi)`` (m; one, or one per range of constant moduli), the GP
    #: and its values that relax every row over every wire of the range (or the plain GP's):
    #: a catalogue's per-wire bounds (:mod:`govopt.optimize.spring_catalogue`)
    relaxation: list | None = None

    @property
    def value(self) -> float:
        """The objective of the spring as drawn (:func:`objective_value`): the GP's, evaluated
        with the exact formulas (the helix rise, the largest wire's solid length)."""
        if self.spring is None:
            return math.nan
        return float(objective_value(self.objective, self.spring, self.mat, self.loads.F2))

    @property
    def gap(self) -> float:
        """``value / lower_bound - 1``: how far from optimal the design can be at most."""
        return max(0.0, self.value / self.lower_bound - 1.0)

    @property
    def certified(self) -> bool:
        """The design is a proven global optimum (within 1e-6 of the certified bound)."""
        return bool(self.gap <= CERTIFIED_GAP)

    @property
    def passed(self) -> bool:
        return all(c.passed for c in self.checks)

    def record(self) -> Record:
        """The optimiser's record (:class:`govopt.optimize.record.Record`): the objective as
        asked (the energy per mass maximised: the reciprocal of the GP's, its sensitivities
        negated), the certified bound, the active limits and the GP's dual elasticities."""
        sol = self.solution
        name, unit, sense = OBJECTIVE_RECORD[self.objective]
        flip = sense == "maximise"
        value, bound = self.value, self.lower_bound
        if flip:
            value, bound = 1.0 / value, 1.0 / bound
        sens = {k: (-v if flip else v) for k, v in sol.sensitivities.items()
                if abs(v) > 1e-6}  # below: a limit that does not bind (the duals' rounding)
        # a discrete optimum's binding limits are its checks' (the relaxation's are the GP's)
        active = [c.name for c in self.checks if c.active] if self.search else sol.active
        status = sol.status if sol.ok else (sol.status or "infeasible")
        if sol.ok and not self.passed:  # a spring that fails a check is no optimum
            status = "checks failed"
        return Record(
            status=status,
            objective=Objective(name, unit, sense), value=value, bound=bound,
            active=list(active), sensitivities=sens,
            sensitivities_of=("the continuous relaxation (any wire, any coils)" if self.search
                              else "the last GP solved (the design's)"),
            method=self.method, solver=str(sol.certificate.get("solver", "")),
            solve_time_s=sol.solve_time, search=dict(self.search), notes=list(self.notes))


#: the objectives as the record states them: GP objective -> (name, SI unit, sense)
OBJECTIVE_RECORD = {"mass": ("mass", "kg", "minimise"),
                    "volume": ("volume (n + end coils) D d^2", "m^3", "minimise"),
                    "solid length": ("solid length", "m", "minimise"),
                    "outer diameter": ("outer diameter", "m", "minimise"),
                    "mass per energy": ("energy per mass", "J/kg", "maximise")}


def objective_value(name: str, spring: Spring, mat, F_max):
    """The GP objective ``name`` of a drawn spring (its fields may be arrays, broadcast),
    with the exact formulas: the mass over the wire's length with the helix rise
    (:func:`govopt.springs.helical.helix_wire_length`), the solid length of the end form with
    the largest wire diameter (EN 13906-1), the literature's volume ``n_t D d^2``, the outside
    diameter, the mass over the energy stored at ``F_max``, ``F_max^2 / (2 R)``."""
    d, D = np.asarray(spring.d, dtype=float), np.asarray(spring.D, dtype=float)
    G = mat.shear_modulus(d)
    if spring.kind == "compression":
        n, Q = spring.coils, spring.end_coils
        d_max = tl.max_wire_diameter(d, mat.grade)
        m = hc.pitch(spring.L0, d, n, n + Q, spring.form, d_max)
        wire = hx.helix_wire_length(D, n, m, Q, d)
    else:
        n = he.extension_active_coils(spring.coils, G, mat.elastic_modulus(d))
        Q = spring.coils + 2.0 * he.HOOKS[spring.form].coils - n
        wire = hx.helix_wire_length(D, 0.0, 0.0, n + Q, d)
    mass = mat.density * np.pi * d**2 / 4.0 * wire
    if name == "mass":
        return mass
    if name == "volume":
        return (n + Q) * D * d**2
    if name == "solid length":
        return hc.solid_length(tl.max_wire_diameter(d, mat.grade), n + Q, spring.form)
    if name == "outer diameter":
        return D + d
    if name == "mass per energy":
        return mass * 2.0 * hx.stiffness(d, D, n, G) / F_max**2
    raise ValueError(f"objective must be one of {tuple(OBJECTIVE_RECORD)}, got {name!r}")


def drawn(kind: str, mat, d, D, n, F_min: float, F_max: float, *, ends: str,
          L2: float | None = None, dynamic: bool = True) -> Spring:
    """The spring ``(d, D, n)`` (``n`` its active coils; arrays broadcast) as drawn (SI). A
    compression spring: ``n_t = n +`` its end form's inactive coils
    (:func:`govopt.springs.compression.end_coils`) and the least free length that keeps the coils
    clear at ``F_max``, ``L0 = L_n + F_max / R`` with EN 13906-1's least working length (the
    solid length with the largest wire diameter; ``S_a`` x1.5 dynamic), or with the installed
    length ``L2`` at ``F_max``, ``L0 = L2 + F_max / R``. An extension spring (``ends``: its
    loops): ``n_b = n - G/E`` body coils, the initial tension in the middle of Shigley's
    preferred range (eq. (10-40)) but at most the least force, the free length inside its
    loops (:func:`govopt.springs.assessment.extension_free_length`)."""
    G = mat.shear_modulus(d)
    if kind == "compression":
        R = hx.stiffness(d, D, n, G)
        Q = hc.end_coils(ends)
        d_max = tl.max_wire_diameter(d, mat.grade)
        Ln = hc.min_working_length(d, D, n, n + Q, ends, dynamic, ends.startswith("hot"), d_max)
        return Spring(kind, d, D, n, Q, (Ln if L2 is None else L2) + F_max / R, ends)
    n_b = n - G / mat.elastic_modulus(d)
    lo, hi = he.initial_tension_range(hx.spring_index(d, D))
    F0 = np.minimum(hx.force_at_stress(0.5 * (lo + hi), d, D), F_min)
    return Spring(kind, d, D, n_b, 0.0, extension_free_length(d, D, n_b, ends), ends, F0)


def size_spring(F_max: float, stiffness: float, *, grade: str | None = None,
                kind: str = "compression", k_s: float | None = None, G: float | None = None,
                density: float | None = None, tensile_strength: float | None = None,
                rules: str = "EN13906", correction: str | None = None, F_min: float = 0.0,
                fatigue: tuple[float, float] | None = None, min_fatigue_safety: float = 1.0,
                peened: bool = False, cycles: float = 1e7, ends: str | None = None,
                seating: str = "fixed-fixed", objective: str = "mass",
                stiffness_max: float | None = None, L2: float | None = None,
                **bounds) -> Sizing:
    """Size a spring (SI): see the module docstring. ``bounds``: the GP's optional limits
    (``n_min``, ``n_max``, ``C_min``, ``C_max``, ``D_out_max``, ``L_body_max``,
    ``f_surge_min``, ``d_min`` ...); with a grade the index defaults to EN 13906-1's 4..20.
    The space it is built into (the GP's envelope constraints): ``Di_min`` (the
    inside diameter over a rod), and for a compression spring ``L0_max`` (its least free
    length: coils clear at ``F_max``) and ``Lc_max`` (its solid length). With
    ``stiffness_max`` the stiffness may lie anywhere in ``stiffness .. stiffness_max`` (the GP's
    band mode). ``L2``: the installed (working) length at ``F_max`` of a compression spring; the
    coils stay clear there (GP row ``working length``) and the free length is ``L2 + F_max /
    R`` (the solid-length stress row of the GP then takes the least free length: a relaxation,
    checked exactly afterwards). ``ends``: a compression spring's end form
    (:data:`~govopt.springs.compression.END_FORMS`, default closed and ground), an extension
    spring's loops (:data:`~govopt.springs.extension.HOOKS`, default full loops). Any wire and
    coils: :func:`govopt.optimize.spring_catalogue.size_orderable_spring` takes them from a
    table of wires and a step of coils."""
    kw = dict(grade=grade, kind=kind, k_s=k_s, density=density,
              tensile_strength=tensile_strength, rules=rules, correction=correction,
              F_min=F_min, fatigue=fatigue, min_fatigue_safety=min_fatigue_safety,
              peened=peened, cycles=cycles, ends=ends, seating=seating, objective=objective,
              stiffness_max=stiffness_max, L2=L2)
    pieces = _moduli_pieces(grade, G, tensile_strength, density, bounds)
    if pieces is None:
        return _size(F_max, stiffness, G=G, **kw, **bounds)
    return _by_pieces(pieces, F_max, stiffness, G, kw, bounds)


def _moduli_pieces(grade, G, tensile_strength, density, bounds):
    """The grade's ranges of wire diameters (m) with constant moduli, each ``(lo, hi, G, E)``,
    where its shear modulus (not given) or its elastic modulus steps with the diameter (ASTM
    A228, Shigley Table 10-5); None where both are constant (one GP serves every wire)."""
    if grade is None:
        return None
    mat = mt.material(grade, tensile_strength=tensile_strength, G=G, density=density)
    stepped = [m for m in (mat.G, mat.E) if not isinstance(m, float)]
    if not stepped:
        return None
    lo = max(mat.d_min, bounds.get("d_min") or 0.0)
    hi = min(mat.d_max, bounds.get("d_max") or math.inf)
    cuts = sorted({u for m in stepped for u, _ in m if lo < u < hi})
    out, start = [], lo
    for end in [*cuts, hi]:
        if end >= start:
            mid = math.sqrt(start * end)  # in the row: the moduli of every wire of the piece
            out.append((start, end, float(mat.shear_modulus(mid)),
                        float(mat.elastic_modulus(mid))))
        start = end * (1.0 + 2e-9)  # the next row (a row holds its upper end)
    return out


def _by_pieces(pieces, F_max, stiffness, G, kw, bounds) -> Sizing:
    """:func:`size_spring` where the moduli step with the wire (:func:`_moduli_pieces`): each
    range of constant moduli sized on its own (its own GP, exact there), the best spring that
    passes its checks taken; the certified bound is the least of the pieces' bounds, and the
    relaxations of every piece bound a wire table's springs
    (:mod:`govopt.optimize.spring_catalogue`)."""
    mat = mt.material(kw["grade"], tensile_strength=kw["tensile_strength"], G=G,
                      density=kw["density"])
    done = []
    for lo, hi, G_i, E_i in pieces:
        piece = _size(F_max, stiffness, G=G_i, E=E_i, **kw,
                      **{**bounds, "d_min": lo, "d_max": hi})
        if piece.solution.ok and piece.spring is not None:  # the grade's own moduli
            piece.mat = mat
            piece.checks, _ = table(piece.spring, mat, piece.loads, piece.rules)
        done.append(piece)
    ok = [p for p in done if p.solution.ok and p.spring is not None]
    if not ok:
        return done[0]
    best = min(ok, key=lambda p: (not p.passed, p.value))
    bounds_ = [p.lower_bound if p.solution.ok else
               math.inf if p.solution.status == "infeasible" else math.nan for p in done]
    best.lower_bound = min(bounds_) if not any(math.isnan(b) for b in bounds_) else math.nan
    best.relaxation = [r for p in done if p.relaxation for r in p.relaxation]
    best.notes.append(f"the moduli step with the wire diameter ({mat.moduli_source}): each of "
                      f"the {len(pieces)} ranges of constant moduli sized on its own, the best "
                      "taken; the certified bound is the least of theirs")
    return best


def _size(F_max: float, stiffness: float, *, grade, kind, k_s, G, density, tensile_strength,
          rules, correction, F_min, fatigue, min_fatigue_safety, peened, cycles, ends, seating,
          objective, stiffness_max, L2, E=None, **bounds) -> Sizing:
    """:func:`size_spring` on a continuum of wires and coils (``E``: the elastic modulus over
    the grade's, a piece of :func:`_by_pieces`)."""
    if kind not in KINDS:
        raise ValueError(f"spring kind must be one of {KINDS}, got {kind!r}")
    ends = ends or ("closed_ground" if kind == "compression" else "full_loop")
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
        space["solid_coils"] = hc.end_coils(ends) + hc.END_FORMS[ends].extra
    else:  # coils touching: the helix's pitch d (the GP's pitch constraint)
        space.update(pitch_clear=1e-12, pitch_F=1e-12)
    relaxed = dict(space)  # the relaxation gives the bound; with L2 the design's GP restricts
    if L2 is not None:
        space.update(L2_solid=L2, clear_solid=1e-12, pitch_on=1.0, pitch_clear=1e-12,
                     pitch_L2=L2)
    mode, rate = "equality", {"kappa": stiffness}
    if stiffness_max is not None:
        if not stiffness <= stiffness_max:
            raise ValueError(f"stiffness range {stiffness!r} .. {stiffness_max!r} is empty")
        mode, rate = "band", {"kappa_min": stiffness, "kappa_max": stiffness_max}
    loads = Loads(F_min, F_max, None if fatigue is None else (min(fatigue), max(fatigue)))
    if grade is None:  # the allowable and modulus given: a stand-in wire (no R_m)
        mat = mt.given(G, density)
        correction = correction or "wahl"
        bounds = {"C_min": DEFAULT_BOUNDS["C_min"], "C_max": DEFAULT_BOUNDS["C_max"], **bounds}
    else:
        mat = mt.material(grade, tensile_strength=tensile_strength, G=G, E=E, density=density)
        correction = correction or hx.DEFAULT_CORRECTION[(rules, "static")]
        bounds = {"C_min": 4.0, "C_max": 20.0, **bounds}
    index = (bounds["C_min"], bounds["C_max"])
    rule = Rules(method=rules, allowable=k_s, correction=correction, peened=peened,
                 seating=seating, index=index, fatigue_safety=min_fatigue_safety, cycles=cycles)
    place = "compression" if kind == "compression" else "extension"
    G, density = mat.G, mat.density
    lo, hi = max(mat.d_min, bounds.get("d_min") or 0.0), min(mat.d_max, bounds.get("d_max")
                                                          or math.inf)
    # a grade with no least wire (custom: from 0): the window's logarithms need one above 0
    lo = lo if lo > 0.0 else min(hi, 1.0) * 1e-9
    state = {"window": (lo, hi)}

    Q = end_coils(kind, mat, ends)
    stable = math.inf
    if kind == "compression":  # the slenderness that cannot buckle
        stable = float(hc.critical_free_length(1.0, G, mat.elastic_modulus(math.sqrt(lo * hi)),
                                               hc.SEATING[seating]))

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
            dc = math.sqrt(state["window"][0] * state["window"][1])
            # the wire's tolerance at the window's centre (the table's row the wire settles in)
            extra["d_tol"] = max(float(tl.max_wire_diameter(dc, grade)) - dc, 1e-12)
            if kind == "compression" and grade is not None:  # the stress at solid length
                k_c, m_c = _monomial(mat, "solid", rules, None, *state["window"])
                extra.update(k_solid=k_c, s_over_D_max=stable)
            gp = cached_gp(objective, correction, mode, m, Q, slender is not None, m_c,
                           envelope, helix=True)
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
            if not refit or (m == 0.0 and m_c is None and grade is None) or np.allclose(
                    new, state["window"], rtol=1e-5, atol=0.0):  # nothing fitted to re-fit
                break
            state["window"] = new  # re-fit the allowable about this wire
        sizing = _checked(Sizing(sol, kind, mat=mat, loads=loads, rules=rule,
                                 objective=objective, cycles=cycles), ends, L2)
        sizing.allowable_factor = factor
        return sizing, min((_ratio(c) for c in sizing.checks
                            if (c.unit == "Pa" and c.sense == "<=") or "fatigue" in c.name),
                           default=math.inf)

    def relaxation(values, k, m, m_c) -> dict:
        """The fitted GP's values that make it a relaxation over every wire in ``[lo, hi]``:
        the monomial fits raised to lie above the rule over the grade's diameters
        (:func:`_domination`), the allowable at the rule's own (factor 1), and the largest
        wire's solid length with the least relative tolerance over them where a length limit
        reads it."""
        out = {"k_s": k * _domination(mat, place, rules, k_s, k, m, lo, hi)}
        if m_c is not None:
            out["k_solid"] = values["k_solid"] * _domination(mat, "solid", rules, None,
                                                             values["k_solid"], m_c, lo, hi)
        if set(space) & {"L0_max", "Lc_max", "L2"}:  # the solid length bounds these
            out["d_tol"] = min(values["d_tol"], _least_tolerance(grade, lo))
        return out

    def certified_bound(sizing) -> float:
        """The bound of the GP just solved (at the rule's own allowable), made valid for every
        wire (``relaxation``), the GP solved again where a value had to move (a step
        table's rows, an interpolated table's kinks); a concave rule's tangent already lies
        above."""
        gp, values, k, m, m_c = state["fit"]
        if not sizing.solution.ok:
            return math.nan
        moved = relaxation(values, k, m, m_c)
        if all(abs(x / values[key] - 1.0) <= 2e-6 for key, x in moved.items()):
            return dual_bound(sizing.solution)
        return dual_bound(gp.solve(**{**values, **moved}))

    def finish(sizing):
        """``sizing`` with the relaxation over every wire: the last fit's GP without the
        buckling slenderness' restriction, at the values of :func:`relaxation` and the
        relaxed space (a catalogue's per-wire bounds, :mod:`govopt.optimize.spring_catalogue`)."""
        if sizing.solution.ok:
            _, values, k, m, m_c = state["fit"]
            gp = cached_gp(objective, correction, mode, m, Q, False, m_c, envelope, helix=True)
            keep = {key: x for key, x in values.items()
                    if key not in FREE_LENGTH_KEYS or key in ("k_solid", "s_over_D_max",
                                                              "d_tol")}
            sizing.relaxation = [(lo, hi, gp, {**keep, **relaxed,
                                               **relaxation(values, k, m, m_c)})]
        return sizing

    if L2 is not None:  # there the design's GP restricts; its relaxation bounds: first
        loose, _ = attempt(1.0, relax=True)
        bound = certified_bound(loose)
        if not loose.solution.ok:  # nor can the restriction be met: the relaxation's diagnosis
            return loose
        if loose.passed:  # the relaxation's design passes: optimal
            loose.lower_bound = bound
            return finish(loose)
        state["window"] = (lo, hi)  # the design's GP fitted afresh, as without the relaxation
        # the force at solid length bounded by F + R (L2 - lam), safe where L_c >= lam: from
        # the relaxation's solid length (a design near it), else lam = 0 (every design)
        lam = 0.99 * _solid_length(loose)
        state["installed"] = {"L2_solid": L2 - lam}
        sizing, worst = attempt(1.0)
        if not sizing.solution.ok or _solid_length(sizing) < lam:
            state["installed"], state["window"] = {}, (lo, hi)
            sizing, worst = attempt(1.0)
    else:
        sizing, worst = attempt(1.0)
    if L2 is None:
        bound = certified_bound(sizing)  # the GP is a relaxation of the rows: a lower bound
    sizing = _stress_search(attempt, sizing, worst)
    if sizing.solution.ok and kind == "compression":
        sizing = _buckling_search(attempt, sizing, stable)
    if sizing.solution.ok and L2 is not None:
        sizing = _installed_search(attempt, sizing, state, L2, ends)
    sizing.lower_bound = bound
    return finish(sizing)


def _solid_length(sizing: Sizing) -> float:
    """The drawn spring's solid length with the largest wire diameter (EN 13906-1), m."""
    sp = sizing.spring
    return float(hc.solid_length(tl.max_wire_diameter(sp.d, sizing.mat.grade), sp.total_coils,
                                 sp.form))


def _least_tolerance(grade, lo: float) -> float:
    """The least wire tolerance of the grade's wires from ``lo`` (m) up: its tolerance table
    rises with the diameter (EN 10270), so the least is the thinnest wire's."""
    return max(float(tl.max_wire_diameter(lo, grade)) - lo, 1e-12)


def _checked(sizing: Sizing, ends: str, L2: float | None) -> Sizing:
    """``sizing`` with its spring drawn and the spring kind's table on it
    (:func:`govopt.springs.assessment.table`: the fatigue rows at the load cycle)."""
    sol = sizing.solution
    sp = drawn(sizing.kind, sizing.mat, sol.d, 2.0 * sol.r, sol.n, sizing.loads.F1,
               sizing.loads.F2, ends=ends, L2=L2)
    sizing.spring = Spring(sp.kind, *(float(x) for x in (sp.d, sp.D, sp.coils, sp.end_coils,
                                                         sp.L0)), sp.form, float(sp.F0))
    sizing.checks, _ = table(sizing.spring, sizing.mat, sizing.loads, sizing.rules)
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


def dual_bound(sol) -> float:
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
    design that passes, to 0.1 %; the GP without it stays the certified lower bound. Where no
    spring within the other limits is short enough not to buckle at all (``s = 1``
    infeasible), the least ``s`` the limits allow is found first (bisection on the GP's
    feasibility, to 0.1 %): a spring that may buckle but whose deflection stays below ``s_K``
    is searched from there."""
    if not _failed_buckling(sizing):
        return sizing
    factor = sizing.allowable_factor
    top = float(sizing.spring.L0 / sizing.spring.D / stable)  # the failing design's
    least, safe = 1.0, attempt(factor, 1.0)[0]
    if not safe.solution.ok:  # the least slenderness factor the other limits allow
        lo, hi = 1.0, top
        while hi / lo > 1.001:
            mid = math.sqrt(lo * hi)
            if attempt(factor, mid, refit=False)[0].solution.ok:
                hi = mid
            else:
                lo = mid
        least, safe = hi, attempt(factor, hi)[0]
    if not safe.solution.ok or _failed_buckling(safe):
        sizing.notes.append("no spring passes the buckling check within the other limits: "
                            "guide it (--seating) or allow a larger diameter")
        return sizing
    good, bad = least, top
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
        good = max(least, good * 0.998)
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
    solid = _solid_length

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


__all__ = ["KINDS", "OBJECTIVE_RECORD", "Sizing", "diagnose", "drawn", "dual_bound",
           "end_coils", "objective_value", "size_spring"]


def _ratio(check) -> float:
    """How far a check is from its limit as a ratio (>= 1 passes): ``limit/value`` for ``<=``,
    ``value/limit`` for ``>=``; a zero denominator is as far as it gets (inf)."""
    num, den = (check.limit, check.value) if check.sense == "<=" else (check.value, check.limit)
    return num / den if den else math.inf
