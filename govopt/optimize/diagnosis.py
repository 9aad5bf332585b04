"""Why a design search found nothing: which requirements, inputs or bounds conflict, and how
far each would have to move (bisection on a relaxed copy of the spec) for a design to exist,
each move in the spec's keys and the units it wrote them in (the friction lowered to a value
that works, a band's end, a bound); why a chosen design failed its closing evaluation; and what
change makes a failing evaluation pass (:func:`evaluation_moves`).
"""

from __future__ import annotations

import math
import re
from dataclasses import fields, replace

import numpy as np

from .. import limits
from ..analysis import statics
from ..analysis.over_regulation import OVER_TOL
from ..errors import InfeasibleError
from ..limits import MAX_TRANSIENT_POINTS
from ..spec import Requirements, Spec, Speed, with_values
from ..units import SI_UNITS, to_unit
from .catalogue_search import Candidate, best_discrete
from .windows import (
    Grid,
    central_load_intervals,
    dead_weight_arrays,
    dead_weight_parts,
    dead_weight_statics,
    grid_steps,
    mass_grid,
    masses,
    statics_feasible,
    statics_window,
)

#: weight pairs per block of the infeasibility diagnosis's wider searches
_DIAGNOSIS_BLOCK = 4096


def _same_terms(a, b) -> bool:
    """Whether two :class:`govopt.governors.base.Terms` hold the same numbers (NaN never
    equal: such terms are computed again)."""
    return all(np.array_equal(getattr(a, f.name), getattr(b, f.name)) for f in fields(a))


def _written_unit(spec: Spec, key: str) -> str | None:
    """The unit the spec wrote ``key`` in (``"kgf"`` of ``"8 kgf"``), or None (not written,
    or a bare number)."""
    entry = next((e for e in spec.entries if e.key == key), None)
    if entry is None or not isinstance(entry.written, str):
        return None
    m = re.fullmatch(r"\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*(\S.*?)\s*", entry.written)
    return m[1] if m else None


def as_written(spec: Spec, key: str, si: float, dimension: str, down: bool = False,
               up: bool = False) -> str:
    """``si`` (SI) in the unit the spec wrote ``key`` in, to 4 significant digits (``2.309
    kgf``; rounded down with ``down``, up with ``up``, so that a value moved far enough still
    is), else in SI."""
    unit = _written_unit(spec, key)
    value = si
    if unit is not None:
        try:
            value = to_unit(si, dimension, unit)
        except (ValueError, TypeError, AttributeError):  # a unit pint reads only in context
            unit = None
    if unit is None:
        unit = SI_UNITS[dimension]
    if (down or up) and value > 0:
        step = 10.0 ** (math.floor(math.log10(value)) - 3)
        value = (math.floor if down else math.ceil)(value / step) * step
    return f"{value:.4g} {unit}"


def friction_move(spec: Spec, feasible) -> str | None:
    """The spec's friction (its type's :attr:`~govopt.governors.base.Governor.friction_key`)
    lowered to a value at which ``feasible(variant spec)`` holds, as a move in the spec's key
    and unit (``governor.sleeve_friction 8 kgf -> 2.309 kgf``): bisection between the spec's
    value and a thousandth of it; None where the spec has no friction or even that is not
    enough (friction is then not the cause)."""
    gov = spec.governor
    key, dimension = gov.friction_key, gov.friction_dimension
    entry = next((e for e in spec.entries if e.key == key), None) if key else None
    if entry is None or not isinstance(entry.si, float) or entry.si <= 0 or spec.data is None:
        return None
    now, unit = entry.si, SI_UNITS[dimension]
    x = _bisect(lambda x: feasible(with_values(spec, {key: f"{now / x!r} {unit}"})),
                hi=1000.0, iters=14)
    if x is None:
        return None
    return (f"{key} {as_written(spec, key, now, dimension)} -> "
            f"{as_written(spec, key, now / x, dimension, down=True)}")


def range_moves(spec: Spec, feasible) -> list[str]:
    """The governor's range narrowed at either end (its type's
    :attr:`~govopt.governors.base.Governor.range_keys`) to where ``feasible(variant spec)``
    holds, as moves in the spec's keys and units (``governor.radius_outer 25 cm -> 23.1 cm``):
    bisection on the share of the range kept, down to a twentieth; none where the type
    declares no range keys or the spec does not write them."""
    from ..errors import GovoptError

    gov = spec.governor
    if gov.range_keys is None or spec.data is None:
        return []
    ends = [next((e for e in spec.entries if e.key == k), None) for k in gov.range_keys]
    if any(e is None or not isinstance(e.si, float) for e in ends):
        return []
    (k_in, lo), (k_out, hi) = [(e.key, e.si) for e in ends]
    unit = SI_UNITS[gov.range_dimension]

    def ok(key: str, value: float) -> bool:
        try:
            return feasible(with_values(spec, {key: f"{value!r} {unit}"}))
        except GovoptError:  # a configuration the type refuses (its normal outside)
            return False

    moves = []
    for key, now, to in ((k_out, hi, lambda x: lo + (hi - lo) / x),
                         (k_in, lo, lambda x: hi - (hi - lo) / x)):
        x = _bisect(lambda x, key=key, to=to: ok(key, to(x)), hi=20.0, iters=12)
        if x is not None:
            shown = as_written(spec, key, to(x), gov.range_dimension, down=key == k_out,
                               up=key == k_in)
            moves.append(f"{key} {as_written(spec, key, now, gov.range_dimension)} -> {shown}")
    return moves


def bounds_move(spec: Spec, req: Requirements, x: float, central: bool) -> str:
    """The weight bounds widened ``x`` times each way (low / x, high * x), as a move in the
    spec's keys: ``bounds.ball_weight 2 .. 10 kgf -> 0.79 .. 25.3 kgf`` (and the central
    load's with ``central``). A bound on a weight is shown in kgf (m kg weighs m kgf), on a
    mass in kg."""
    written = (spec.data or {}).get("bounds") or {}
    out = []
    for base, (lo, hi), on in ((spec.governor.mass_key, req.flying_mass, True),
                               ("central", req.central_mass, central)):
        if not on:
            continue
        name = f"{base}_mass" if f"{base}_mass" in written else f"{base}_weight"
        unit = "kg" if name.endswith("_mass") else "kgf"
        out.append(f"bounds.{name} {lo:.4g} .. {hi:.4g} {unit} -> {lo / x:.4g} .. "
                   f"{hi * x:.4g} {unit}")
    return " and ".join(out)


def _bisect(feasible, lo: float = 1.0, hi: float = 100.0, iters: int = 12) -> float | None:
    """Smallest factor ``x`` in ``[lo, hi]`` with ``feasible(x)``, by bisection in log space;
    None if even ``hi`` is not enough."""
    if not feasible(hi):
        return None
    for _ in range(iters):
        mid = math.sqrt(lo * hi)
        lo, hi = (lo, mid) if feasible(mid) else (mid, hi)
    return hi


def dead_weight_diagnosis(spec: Spec, req: Requirements, parts: dict, rise, fall
                          ) -> InfeasibleError:
    """Which requirement no ball and central-load weight meets, and the requirements that bind:
    each relaxed in turn (the k^2 margin, the band's ends, the weight bounds), with the value
    that makes the search feasible."""
    sp = spec.speed
    failing = [k for k, v in parts.items() if not v.any()]
    head = (f"infeasible: no {spec.governor.mass_key} and central-load weight in "
            f"the bounds meets " + (", ".join(f"'{k}'" for k in failing) if failing else
                                    "all the statics requirements together"))
    grid = Grid.build(spec)
    # the bisections below move a margin or the band, which leave the weights' generalised
    # forces as they are (the band moves the mean speed, which a governor's forces may use):
    # the spec's own weights' arrays are computed again only where the forces differ. Wider
    # weight bounds are taken a block of weights at a time (each row is its own weight pair),
    # up to the first feasible one.
    own = masses(req)
    memo: dict = {}

    def grid_of(s):  # another governor (its friction or its range): its own grid
        return grid if s.governor is spec.governor else Grid.build(s)

    def meets_in(s, r):
        g = grid_of(s)
        return lambda m, c: np.logical_and.reduce(
            list(dead_weight_statics(s, r, g, m, c)[0].values()))

    def feasible(s, r):
        if spec.governor.central_load_affine:  # each ball's central loads in closed form
            least = _least_central(s, r, mass_grid(r), grid_steps(*r.central_mass,
                                                                   r.mass_step), meets_in(s, r))
            if least is not ...:
                return least is not None
        m, c = masses(r)
        own_gov = s.governor is spec.governor  # else another friction or range: its arrays
        keep = np.array_equal(m, own[0]) and np.array_equal(c, own[1]) and own_gov
        g = grid_of(s)
        for lo in range(0, m.size, _DIAGNOSIS_BLOCK):
            mb, cb = m[lo:lo + _DIAGNOSIS_BLOCK], c[lo:lo + _DIAGNOSIS_BLOCK]
            t = statics.terms(s, g.alpha, mb[:, None], cb[:, None])
            hit = memo.get(lo) if keep else None
            if hit is None or not _same_terms(hit[0], t):
                hit = t, dead_weight_arrays(s, g, mb, cb, t)[1:4]
                if keep:
                    memo[lo] = hit
            if np.logical_and.reduce(list(dead_weight_parts(s, r, *hit[1]).values())).any():
                return True
        return False

    def band(inner, outer):
        return replace(spec, speed=Speed((inner + outer) / 2.0, 2.0 * (outer - inner)
                                         / (outer + inner), band=sp.band))

    rpm = 30.0 / math.pi
    moves = []
    central = central_move(spec, req, meets_in(spec, req))
    if central:
        moves.append(central)
    friction = friction_move(spec, lambda s: feasible(s, req))
    if friction:  # the cause named: the friction band is wider than the speed band leaves
        key = spec.governor.friction_key
        head += (f": the friction ({key}) spreads the opening and closing speeds wider than "
                 "speed.inner .. speed.outer leaves room for")
        moves.insert(0, friction)
    x = _bisect(lambda x: feasible(spec, replace(req, k2_margin=req.k2_margin / x)))
    if x is not None and req.k2_margin:
        moves.append(f"requirements.k2_margin {req.k2_margin:g} -> {req.k2_margin / x:.4g}")
    x = _bisect(lambda x: feasible(band(sp.omega_inner / x, sp.omega_outer), req))
    if x is not None:
        moves.append(f"speed.inner {sp.omega_inner * rpm:.5g} rpm -> "
                     f"{sp.omega_inner / x * rpm:.5g} rpm")
    x = _bisect(lambda x: feasible(band(sp.omega_inner, sp.omega_outer * x), req))
    if x is not None:
        moves.append(f"speed.outer {sp.omega_outer * rpm:.5g} rpm -> "
                     f"{sp.omega_outer * x * rpm:.5g} rpm")
    x = _bisect(lambda x: feasible(spec, replace(
        req, flying_mass=(req.flying_mass[0] / x, req.flying_mass[1] * x),
        central_mass=(req.central_mass[0] / x, req.central_mass[1] * x))), hi=4.0)
    if x is not None:
        moves.append(bounds_move(spec, req, x, central=spec.governor.central_load))
    moves += range_moves(spec, lambda s: feasible(s, req))  # the geometry: a narrower range
    with np.errstate(invalid="ignore"):
        ratio = np.sqrt(rise[:, -1] / fall[:, 0])
    best = float(np.nanmin(np.where(np.isfinite(ratio), ratio, np.nan))) \
        if np.isfinite(ratio).any() else math.inf
    return InfeasibleError(head, file=spec.path, moves=moves, otherwise=(
        f"{InfeasibleError.NO_MOVE} (the narrowest operating band the geometry and friction "
        f"allow spans a speed ratio {best:.4g}, the spec's range "
        f"{sp.omega_outer / sp.omega_inner:.4g})"))


def central_move(spec: Spec, req: Requirements, meets) -> str | None:
    """The central load's upper search bound that makes the search feasible, as a diagnosis's
    move (``bounds.central_weight 0 .. 0 kgf (the default: no central load) -> 0 .. 21.6
    kgf``; the bound on ``central_mass`` in kg), or None: where the type has a central load
    and no central load up to 100 times the flying mass's upper bound does it. ``meets(m, c)``
    says which (flying, central) mass pairs meet every statics requirement.

    The bound is raised from the spec's (from a hundredth of the flying mass's upper bound
    where it is 0) by bisection in log space. A pair meets the requirements whatever the bounds,
    and a higher bound only adds central loads on the same weight-step lattice, so the search
    is feasible exactly when the bound reaches the least central load of a pair that meets
    them: that load is found once (the lattice ascending, a block of pairs at a time, up to the
    first that holds one) and the bisection tests the bound against it."""
    gov = spec.governor
    if not gov.central_load:
        return None
    lo, hi = req.central_mass
    top = 100.0 * max(req.flying_mass[1], hi)
    base = hi if hi > 0 else req.flying_mass[1] / 100.0
    m, loads = mass_grid(req), grid_steps(lo, top, req.mass_step)
    least = _least_central(spec, req, m, loads, meets) if gov.central_load_affine else ...
    if least is ...:  # the lattice ascending, a block of pairs at a time
        least = None
        per = max(1, _DIAGNOSIS_BLOCK // max(1, m.size))
        for j in range(0, loads.size, per):
            mm, cc = np.meshgrid(m, loads[j:j + per], indexing="ij")
            hit = meets(mm.ravel(), cc.ravel()).reshape(mm.shape).any(axis=0)
            if hit.any():
                least = loads[j + int(np.argmax(hit))]
                break
    if least is None:
        return None

    def reaches(x):  # the widened bound's lattice holds the least load that meets them
        grid = grid_steps(lo, base * x, req.mass_step)
        return grid.size > 0 and grid[-1] >= least

    x = _bisect(reaches, lo=1.0, hi=top / base, iters=16)
    if x is None or (hi > 0 and x == 1.0):
        return None
    given = "central_weight" if "central_mass" not in ((spec.data or {}).get("bounds") or {}) \
        else "central_mass"
    unit = "kgf" if given == "central_weight" else "kg"  # a weight of m kg is m kgf
    default = "" if hi > 0 else " (the default: no central load)"
    return (f"bounds.{given} {lo:.4g} .. {hi:.4g} {unit}{default} -> {lo:.4g} .. "
            f"{base * x:.4g} {unit}")


#: lattice loads tried at the lower end of each flying mass's closed-form interval
_CENTRAL_TRIES = 3


def _least_central(spec: Spec, req: Requirements, m, loads, meets):
    """The least central load of the lattice ``loads`` at which some flying mass of ``m``
    meets every statics requirement (``meets(m, c)``), or None: each mass's interval of
    central loads in closed form (:func:`govopt.optimize.windows.central_load_intervals`,
    widened by rounding), the first lattice loads in it tried with ``meets`` itself, which
    decides. ``...`` where the two disagree (every load tried fails in an interval that holds
    more): the caller scans the lattice instead."""
    lo, hi = central_load_intervals(spec, req, Grid.build(spec), m)
    pad = 1e-9 * (np.abs(lo) + np.abs(hi) + req.mass_step)
    with np.errstate(invalid="ignore"):
        first = np.searchsorted(loads, np.where(np.isfinite(lo), lo - pad, -np.inf))
        end = np.searchsorted(loads, np.where(np.isfinite(hi), hi + pad, np.inf), side="right")
    rows = np.nonzero(end > first)[0]
    if not rows.size:
        return None
    j = first[rows, None] + np.arange(_CENTRAL_TRIES)
    tried = j < end[rows, None]
    jj = np.minimum(j, loads.size - 1)
    hit = meets(np.repeat(m[rows], _CENTRAL_TRIES), loads[jj].ravel()).reshape(j.shape) & tried
    if np.any(~hit.any(axis=1) & (end[rows] - first[rows] > _CENTRAL_TRIES)):
        return ...
    return float(np.min(loads[jj][hit])) if hit.any() else None


def _feasible(spec: Spec, req: Requirements, stage: str) -> bool:
    if stage == "statics":
        return statics_feasible(spec, req)
    grid, km, lo, hi, _ = statics_window(spec, req)
    if not np.any(lo <= hi):
        return False
    cand, stats = best_discrete(spec, req, km, grid, lo, hi, dynamics=stage == "dynamics",
                                max_checked=512)
    return stats["spring_feasible"] > 0 if stage == "spring" else cand is not None


def _relax(spec: Spec, req: Requirements, stage: str, make, lo=1.0, hi=100.0, iters=12):
    """Smallest factor ``x`` in ``[lo, hi]`` with ``make(x) = (spec, req)`` feasible, by
    bisection in log space; None if even ``hi`` is not enough."""
    return _bisect(lambda x: _feasible(*make(x), stage), lo, hi, iters)


def diagnose(spec: Spec, req: Requirements, stage: str, parts, stats=None) -> InfeasibleError:
    """Which requirements conflict, and how far each would have to move (a relaxation), as the
    error to raise (its ``moves``: the relaxations)."""
    speed, mat = spec.speed, spec.material
    moves = []

    def with_irr(x):
        return replace(spec, speed=replace(speed, irregularity=speed.irregularity * x)), req

    def with_ks(x):
        return replace(spec, material=replace(mat, allowable_shear_stress=mat
                                              .allowable_shear_stress * x)), req

    def with_k2(x):
        return spec, replace(req, k2_margin=req.k2_margin / x)

    def with_hurwitz(x):
        return spec, replace(req, hurwitz_margin=req.hurwitz_margin / x)

    def with_mass(x):
        return spec, replace(req, flying_mass=(req.flying_mass[0] / x,
                                                 req.flying_mass[1] * x))

    def with_band(inner, outer):  # a band stated [speed] inner/outer, re-derived as the parser
        return replace(spec, speed=Speed((inner + outer) / 2.0, 2.0 * (outer - inner)
                                         / (outer + inner), band=True)), req

    def with_inner(x):
        return with_band(speed.omega_inner / x, speed.omega_outer)

    def with_outer(x):
        return with_band(speed.omega_inner, speed.omega_outer * x)

    # the speed requirement as the spec states it: the band's ends, or the irregularity
    speed_moves = ([("speed.inner", with_inner, "rpm /", speed.omega_inner),
                    ("speed.outer", with_outer, "rpm x", speed.omega_outer)] if speed.band
                   else [("speed.irregularity", with_irr, "x", speed.irregularity)])
    if stage == "statics":
        lo_name = max(parts, key=lambda k: np.median(parts[k][0]))
        lo, hi = parts[lo_name]
        others = [k for k in parts if k != lo_name]
        weight = f"{spec.governor.mass_key} weight"
        if not np.any(lo <= hi) or not others:  # the requirement alone: no stiffness meets it
            head = (f"infeasible: no spring stiffness meets the requirement "
                    f"'{lo_name}' by itself at any {weight} in the bounds")
        else:  # never "X conflicts with X"
            hi_name = min(others, key=lambda k: np.median(parts[k][1]))
            head = (f"infeasible: the requirement '{lo_name}' needs a stiffer "
                    f"spring than '{hi_name}' allows at every {weight} in the bounds")
        cands = [*speed_moves, ("requirements.k2_margin", with_k2, "/", req.k2_margin),
                 ("bounds", with_mass, "widen x", None)]
    elif stage == "spring" and stats["statics_feasible"] == 0:
        head = (f"infeasible: no catalogue spring's stiffness falls in the window "
                "the statics allow (the speed band, k^2 margins, free length) at any "
                f"{spec.governor.mass_key} weight in the bounds")
        cands = [*speed_moves, ("requirements.k2_margin", with_k2, "/", req.k2_margin)]
    elif stage == "spring":
        head = (f"infeasible: no spring in the catalogue and bounds meets the "
                f"allowable shear stress (with index, envelope and surge limits) at a stiffness "
                f"the statics allow ({stats['statics_feasible']} mass-spring combinations pass "
                f"the statics, none the spring checks)")
        cands = [("material.allowable_shear_stress", with_ks, "stress x",
                  mat.allowable_shear_stress), *speed_moves]
        if mat.allowable_shear_stress is None:  # a wire grade's allowables: not one number
            cands = cands[1:]
    else:
        return dynamics_conflict(spec, req, stats)
    friction = friction_move(spec, lambda s: _feasible(s, req, stage))
    if friction:
        moves.append(friction)
        head += f"; with less friction ({spec.governor.friction_key}) a design exists"
    for name, make, how, value in cands:
        x = _relax(spec, req, stage, make)
        if x is None:
            continue
        if how == "stress x" and value is not None:  # as the spec wrote it (MPa, kgf/cm^2)
            moves.append(f"{name} {as_written(spec, name, value, 'stress')} -> "
                         f"{as_written(spec, name, value * x, 'stress')} (x{x:.3g})")
        elif how == "x" and value is not None:
            moves.append(f"{name} {value:g} -> {value * x:.4g} (x{x:.3g})")
        elif how.startswith("rpm"):  # a band's end, shown as the spec's speeds are
            rpm = 30.0 / math.pi
            to = value / x if how == "rpm /" else value * x
            moves.append(f"{name} {value * rpm:.5g} rpm -> {to * rpm:.5g} rpm")
        elif how == "/" and value:
            moves.append(f"{name} {value:g} -> {value / x:.4g}")
        elif how == "widen x":
            moves.append(bounds_move(spec, req, x, central=False))
    return InfeasibleError(head, file=spec.path, moves=moves)


def dynamics_conflict(spec: Spec, req: Requirements, stats: dict) -> InfeasibleError:
    """Name the dynamic requirement that no admissible dash-pot meets, and how far it is."""
    return InfeasibleError(_dynamics_reason(spec, req, stats), file=spec.path)


def _dynamics_reason(spec: Spec, req: Requirements, stats: dict) -> str:
    """:func:`dynamics_conflict`'s reason, in words."""
    least = stats.get("least", {})
    where = (f"({stats.get('spring_feasible', 'all')} candidates pass the statics "
             f"and spring checks; {stats['dynamics_checked']} checked best first"
             + (f", stopped at govopt's limit of work (~{limits.MAX_DESIGN_DYNAMICS_SECONDS:g} s)"
                if stats.get("dynamics_stopped_at_the_work_limit") else "")
             + f", {stats.get('lattice_cells', 0)} mass x stiffness cells screened)")
    if spec.engine is None or not spec.load_changes:  # no dash-pot to design: the vibration
        broken = " and ".join(name for name, on in (
            ("requirements.max_vibration", req.max_vibration is not None),
            ("the spring's fatigue safety (requirements.min_fatigue_safety)",
             spec.material is not None and spec.material.grade is not None)) if on)
        return (f"infeasible: with no [[load_change]] no dash-pot is designed, and "
                f"undamped, the forced vibration breaks {broken or 'the requirements'} on every "
                f"candidate {where}; add the load change (a dash-pot) or relax them")
    over = least.get("over_regulation", np.inf)
    if over > OVER_TOL:
        text = ("no admissible damping" if not np.isfinite(over) else
                f"the least over-regulation at any admissible damping is "
                f"{100 * over:.3g} % of the load change (scaled by the slowest mode's decay)")
        return (f"infeasible: Hamabe's eq. (32) with margin {req.hurwitz_margin:g} "
                f"conflicts with 'no over-regulation' for the load changes: {text} {where}; "
                f"lower requirements.hurwitz_margin or the load change")
    settle = least.get("settling_time", np.inf)
    if req.max_settling_time is not None and settle > req.max_settling_time:
        return (f"infeasible: requirements.max_settling_time "
                f"{req.max_settling_time:g} s conflicts with 'no over-regulation' and eq. (32): "
                + (f"the fastest admissible settling is {settle:.4g} s {where}"
                   if np.isfinite(settle) else
                   f"no admissible dash-pot's settling could be placed (a time grid of at "
                   f"most {MAX_TRANSIENT_POINTS} points, then the modes' envelope: the load "
                   f"change's modes are too far apart, as with a very large flywheel) {where}"))
    vib = least.get("vibration", np.inf)
    if req.max_vibration is not None and vib > req.max_vibration:
        return (f"infeasible: requirements.max_vibration "
                f"{np.degrees(req.max_vibration):.4g} deg conflicts with the load-change "
                f"requirements: the least peak-to-peak bound at an admissible damping is "
                f"{np.degrees(vib):.4g} deg {where}")
    if stats.get("lattice_feasible", 0) and spec.material is not None \
            and spec.material.grade is not None:  # the lattice screens all but the spring's life
        return (f"infeasible: requirements.min_fatigue_safety "
                f"{req.min_fatigue_safety or 1.0:g}: no candidate's spring reaches it under the "
                f"vibration at a damping the load changes admit ({stats['lattice_feasible']} "
                f"mass x stiffness cells meet the load-change requirements alone) {where}")
    return (f"infeasible: the dynamic requirements are met only together on no "
            f"candidate {where}")


def unverified(spec: Spec, cand: Candidate, failed) -> str:
    """The diagnosis of a chosen design that fails its final evaluation (``failed``: the
    :class:`~govopt.verdict.Check` objects that fail). The verdict is the evaluator's
    (:mod:`govopt.evaluator`); the search held the same requirement rows on its own model (the
    statics affine in the spring rate at fixed masses, on the catalogue's grid), so a miss is a
    design on the edge of a requirement, by the rounding between the two: name it, its value,
    its limit and its margin, and what to change."""
    gov = spec.governor
    spring = "".join(f", {k} = {v:.6g}" for k, v in cand.spring.items())
    names = ", ".join(c.name for c in failed)
    return (f"{spec.path}: the chosen design ({gov.mass_key} {cand.m:.6g} kg{spring}, dash-pot "
            f"{cand.f:.6g} SI) fails its final verification by govopt evaluate: "
            + "; ".join(f"{c.name}: {c.value:.6g} {c.unit}, required {c.sense} {c.limit:.6g} "
                        f"(margin {c.margin:.3g})" for c in failed)
            + f". The search's screen passed it on its own model, so it lies on the edge of "
            f"{names}: no design is returned; ask for a little more margin on {names} (or a "
            "finer catalogue step) and search again")


#: The most evaluations :func:`evaluation_moves` spends on a failing design (each a few ms to
#: a tenth of a second; a count, not a time, so that the advice is the same on any machine):
#: its moves are then those found so far, the friction's and the speeds' first.
EVALUATION_BUDGET = 200
#: The factors a design value is scanned over, each way (up to x2 and /2), before bisection.
_SCAN = 1.05 ** np.arange(1, 16)


def evaluation_moves(spec: Spec) -> list[str]:
    """What makes a failing evaluation pass: each change of one input of ``spec`` (its
    friction lowered, a band's end or the irregularity moved, a design value raised or
    lowered) at which every check of :func:`govopt.evaluator.evaluate` passes, the nearest
    found, in the spec's keys and units (``governor.sleeve_friction 8 kgf -> 3.156 kgf``,
    ``design.central_weight 33.75 kgf -> 36.4 kgf``). A design value is scanned up and down
    to twice and half its value, then bisected; at most :data:`EVALUATION_BUDGET`
    evaluations."""
    from ..errors import GovoptError
    from ..evaluator import core, design_columns, evaluate

    spent = [0]

    def statics_checks(variant: Spec) -> list | None:  # the checks before the dynamics
        ev = core(variant, design_columns([variant.design]), dynamics=False, vibration=False,
                  classic=False)
        return None if ev.error[0] is not None else ev.table.checks(0)

    def full(variant: Spec) -> bool:
        return all(c.passed for c in evaluate(variant).checks)

    # where every failing check is one the statics hold, a move is sought on them (fast) and
    # the value found is then held against the whole evaluation
    base = statics_checks(spec) if spec.design is not None else None
    failing = {c.name for c in evaluate(spec).checks if not c.passed}
    quick = base is not None and failing <= {c.name for c in base}

    def passes(values: dict | Spec, final: bool = False) -> bool:
        if spent[0] >= EVALUATION_BUDGET and not final:
            return False
        spent[0] += 1
        try:
            variant = values if isinstance(values, Spec) else with_values(spec, values)
            if quick and not final:
                checks = statics_checks(variant)
                return checks is not None and all(c.passed for c in checks)
            return full(variant)
        except GovoptError:  # no equilibrium, a value out of range: not this way
            return False

    def at(key: str, si: float, dimension: str) -> dict:
        return {key: f"{float(si)!r} {SI_UNITS[dimension]}"}

    if spec.data is None:
        return []
    found = []  # (key, as written now, the new value as the spec would write it)
    friction = friction_move(spec, passes)
    if friction:
        key, change = friction.split(" ", 1)
        found.append((key, *change.split(" -> ")))
    sp, rpm = spec.speed, 30.0 / math.pi
    if sp is not None and sp.band:
        for key, now, sign in (("speed.inner", sp.omega_inner, -1), ("speed.outer",
                                                                      sp.omega_outer, 1)):
            x = _bisect(lambda x, key=key, now=now, sign=sign: passes(
                {key: f"{float(now * x ** sign * rpm)!r} rpm"}), hi=2.0, iters=10)
            if x is not None:
                found.append((key, f"{now * rpm:.5g} rpm", f"{now * x ** sign * rpm:.5g} rpm"))
    elif sp is not None:
        x = _bisect(lambda x: passes({"speed.irregularity": float(sp.irregularity * x)}),
                    hi=min(100.0, limits.MAX_IRREGULARITY / sp.irregularity), iters=10)
        if x is not None:
            found.append(("speed.irregularity", f"{sp.irregularity:g}",
                          float(f"{sp.irregularity * x:.4g}")))
    for entry in spec.entries:
        if not entry.key.startswith("design.") or not isinstance(entry.si, float) \
                or entry.si <= 0 or not entry.unit:
            continue
        dimension = next((d for d, u in SI_UNITS.items() if u == entry.unit), None)
        if dimension is None:
            continue
        key, now = entry.key, entry.si
        best = None
        for sign in (1, -1):  # up, then down: the nearer of the two
            prev = 1.0
            for f in _SCAN:
                if passes(at(key, now * f ** sign, dimension)):
                    x = _bisect(lambda x, s=sign, key=key, now=now, d=dimension: passes(
                        at(key, now * x ** s, d)), lo=prev, hi=f, iters=6)
                    if x is not None and (best is None or x < best[0]):
                        best = (x, sign)
                    break
                prev = f
        if best is not None:
            x, sign = best
            found.append((key, as_written(spec, key, now, dimension),
                          as_written(spec, key, now * x ** sign, dimension)))
    # each move as shown (rounded as written) holds against the whole evaluation
    moves = [f"{key} {old} -> {new}" for key, old, new in found
             if passes({key: new}, final=True)]
    return moves
