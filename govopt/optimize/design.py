"""Whole-governor design: pendulum weight, spring (d, r, n, free length) and dash-pot.

Method (each step uses the statics and dynamics modules as evaluators):

1. For every pendulum mass on the catalogue's weight grid, the statics requirements (irregularity,
   ``k2_margin omega0^2 <= k^2 <= (1 - k2_margin) omega0^2`` at every configuration, a positive
   equilibrium speed, a spring in tension, a positive free length) are an interval of admissible
   stiffness, in closed form (:mod:`govopt.optimize.kappa`, :mod:`govopt.optimize.windows`).
2. **Continuous bound**: for each mass, the spring is a geometric programme (cvxpy DGP, built once
   with parameters and re-solved, :class:`~govopt.optimize.spring_gp.SpringGP`): least mass with
   the stiffness in that interval, stress from the exact force ``F_n + 2 kappa (l_a - l_n)``,
   index, envelope, surge, turns and diameter bounds. The dynamics requirements are relaxed here,
   so the best of these is a true lower bound on any design. Where the spring's energy bound is
   attained by a spring meeting every row of the GP (the uncorrected stress and the stiffness
   band bind), that spring is the GP's optimum without a solve
   (:func:`govopt.optimize.gp_table.energy_optimum`); cvxpy solves the rest
   (:mod:`govopt.optimize.design_bound`).
3. **Discrete design**: every catalogue wire, coil radius on its grid, turns on their step and
   mass on its grid is checked against the same constraints in closed form (vectorised, exhaustive),
   and the candidates are visited best first until one also admits a dash-pot with Hamabe's
   eq. (32) margin, no over-regulation and the settling limit for every load change. The dash-pot's
   feasible range is found on a log grid (it can be bounded on both sides: too little damping
   violates eq. 32, too much makes the slow roots a complex pair that overshoots)
   (:mod:`govopt.optimize.catalogue_search`, :mod:`govopt.optimize.windows`).
4. The chosen design is re-evaluated with the full :func:`govopt.evaluate`, like the paper's
   closing check, and its constraints, margins and sensitivities are reported. Where no design
   exists, :mod:`govopt.optimize.diagnosis` names the requirements or bounds that conflict.
"""


from __future__ import annotations

import math
import time
from dataclasses import replace

import numpy as np

from .. import limits
from ..errors import DesignError, InfeasibleError
from ..limits import design_size_error
from ..spec import Design, Requirements, Spec
from ..units import G_STANDARD, SI_UNITS
from .catalogue_search import (
    Candidate,
    batches,
    best_discrete,
    catalogue,
    catalogue_axes,
    check_grids,
    objective_values,
    spring_screen,
)
from .design_bound import continuous_bound, gp_values, sensitivities
from .diagnosis import dead_weight_diagnosis, diagnose, dynamics_conflict, unverified
from .kappa import Affine, KappaModel
from .margins import margins_to_ends
from .record import Objective, Record
from .windows import (
    Grid,
    dashpot_window,
    dead_weight_statics,
    grid_steps,
    mass_grid,
    masses,
    requirements,
    statics_window,
)

#: the search's face: its entry points, and the steps of the search that the robust search
#: (:mod:`govopt.optimize.robust`) composes and the benchmarks time, from the modules that hold
#: them (:mod:`~govopt.optimize.windows`, :mod:`~govopt.optimize.catalogue_search`,
#: :mod:`~govopt.optimize.design_bound`, :mod:`~govopt.optimize.diagnosis`)
__all__ = ["Candidate", "best_discrete", "catalogue", "check_grids", "continuous_bound",
           "dashpot_window", "dead_weight_candidates", "design", "diagnose", "gp_values",
           "objective_unit", "objective_values", "requirements", "result_of", "spring_screen",
           "statics_window", "validated"]


def objective_unit(req: Requirements, gov) -> str:
    """The SI unit of the objective (:func:`objective_values`): kg for the masses, s for the
    settling time, the configuration's unit (rad or m) for the vibration's peak-to-peak."""
    return {"settling_time": "s", "vibration": SI_UNITS[gov.coordinate]}.get(req.objective, "kg")




def objective_of(req: Requirements, gov) -> Objective:
    """The design's objective for the record: name, SI unit and, for the moving mass, what it
    counts (:meth:`~govopt.governors.base.Governor.moving_mass_words`)."""
    return Objective(req.objective, objective_unit(req, gov), counts=(
        gov.moving_mass_words() if req.objective == "moving_mass" else ""))


def validated(spec: Spec) -> Spec:
    """The spec with its design requirements filled in (:func:`requirements`), after the checks
    every search needs: grids of a size govopt allows, a ``[material]`` where a spring is to be
    chosen, a speed range. Raises :class:`~govopt.errors.InfeasibleError` naming the key."""
    req = requirements(spec)
    spec = replace(spec, requirements=req)  # the checks report the requirements designed to
    too_big = design_size_error(req, spec.analysis.points, spec.governor.spring_kind,
                                spec.governor.mass_key)
    if too_big:  # counted from bounds and steps before any grid is built (govopt.limits)
        raise InfeasibleError(too_big[1], file=spec.path, key=too_big[0])
    if spec.governor.spring is not None and spec.material is None:
        raise InfeasibleError("missing: a design chooses the spring, which needs its [material]",
                              file=spec.path, key="material")
    if spec.speed is None:
        raise InfeasibleError("missing: a design needs the speed range", file=spec.path,
                              key="speed")
    return spec


def design(spec: Spec):
    """Find the best nominal design for the spec's requirements; see the module docstring.
    (:func:`govopt.optimize.search.design`, which ``govopt.design`` is, runs the robust search of
    :mod:`govopt.optimize.robust` instead where the requirements ask for a tolerance box.)

    Raises :class:`~govopt.errors.InfeasibleError` with a diagnosis when no design exists, and
    :class:`~govopt.errors.DesignError` naming the failed checks when the chosen design fails
    its final re-evaluation (never returns a design that fails a check).
    """
    start = time.perf_counter()
    spec = validated(spec)
    req = spec.requirements
    if req.robust:
        raise ValueError("a robust spec is designed by govopt.optimize.search.design (the "
                         "tolerance box's search), not the nominal search")
    work = limits.Work(limits.MAX_DESIGN_DYNAMICS_SECONDS)  # the dash-pot windows' work
    if spec.governor.spring is None:  # a dead-weight governor: masses only
        with limits.counting(work):
            cand, stats = dead_weight_search(spec, req)
        return result_of(spec, req, cand, _with_work(stats, work), None,
                         time.perf_counter() - start)
    check_grids(spec, req)
    grid, km, lo, hi, parts = statics_window(spec, req)
    if not np.any(lo <= hi):
        raise diagnose(spec, req, "statics", parts)
    with limits.counting(work):
        cand, stats = best_discrete(spec, req, km, grid, lo, hi)
    stats = _with_work(stats, work)
    if cand is None:
        stage = "spring" if stats["spring_feasible"] == 0 else "dynamics"
        raise diagnose(spec, req, stage, parts, stats)
    bound = continuous_bound(spec, req, km, lo, hi) \
        if req.objective in ("moving_mass", "spring_mass") and stats.pop("gp") else None
    return result_of(spec, req, cand, stats, bound, time.perf_counter() - start)



def _with_work(stats: dict, work) -> dict:
    """The search's stats with the dynamics' counted work (estimated CPU seconds)."""
    return {**stats, "dynamics_work_s": round(work.spent, 3)}


def result_of(spec: Spec, req: Requirements, cand: Candidate, stats: dict, bound: dict | None,
              seconds: float = math.nan):
    """The chosen candidate re-evaluated by :func:`govopt.evaluate`, with the optimiser's
    record (:class:`~govopt.optimize.record.Record`, as JSON): objective, continuous bound and
    gap, search statistics, sensitivities; ``seconds``: the search's wall time."""
    from ..evaluator import evaluate

    gov = spec.governor
    chosen = Design(flying_mass=cand.m, **cand.spring, free_half_length=cand.l0,
                    central_mass=cand.central or None,
                    dashpot=None if math.isnan(cand.f) else cand.f)
    res = evaluate(spec.with_design(chosen))
    failed = [c for c in res.checks if not c.passed]
    if failed:  # the closing check decides: a design that fails it is no design
        raise DesignError(unverified(spec, cand, failed))
    res.kind = "design"
    searched = search_bounds(spec, req, cand)
    damping = gov.key_unit("damping")
    record = Record(
        status="optimal", objective=objective_of(req, gov),
        value=cand.objective, bound=math.nan if bound is None else bound["objective"],
        active=[f"{b['name']} at its {b['at']} search bound" if b["held"] == "bound" else
                f"{b['name']} at the catalogue's {b['at']} step within its bounds "
                f"([catalogue] {b['step_key']})" for b in searched
                if b["at"] in ("lower", "upper")],
        sensitivities=sensitivities(spec, req, None if bound is None else bound["objective"]),
        sensitivities_of=("the continuous bound (the spring GP at each mass), re-solved with "
                          "each limit +1 % (a finite difference)"),
        method=("exhaustive enumeration of the " + ("catalogue's masses and springs, best first"
                if gov.spring is not None else "weight pairs, least first")
                + ", each with its dash-pot window" + ("; the bound: the spring GP at each mass"
                                                       if bound is not None else "")),
        solver="enumeration", solve_time_s=seconds, search=stats,
        notes=([] if spec.engine is not None and spec.load_changes else [
            "no [engine] or [[load_change]] in the spec: the dash-pot and the load-change "
            "requirements (eq. 32, over-regulation, settling) were not designed for"]) + ([
            f"the dynamics were checked for {stats.get('dynamics_checked')} candidates, "
            f"best first, then stopped at govopt's limit of work (~"
            f"{limits.MAX_DESIGN_DYNAMICS_SECONDS:g} s): the best among them, which a longer "
            "search might better (fewer load changes, or narrower bounds)"]
            if stats.get("dynamics_stopped_at_the_work_limit") else [])
        + bounds_notes(searched))
    record.sections = {
        "design": {
            f"{gov.mass_key}_weight_N": cand.m * G_STANDARD, f"{gov.mass_key}_mass_kg": cand.m,
            **({"central_mass_kg": cand.central} if cand.central else {}),
            **{(k if k == "active_turns" else f"{k}_m"): v for k, v in cand.spring.items()},
            **({f"{gov.free_length_key}_m": cand.l0} if gov.spring is not None else {}),
            f"dashpot_{damping}": cand.f,
            f"dashpot_feasible_range_{damping}": [cand.f_lo, cand.f_hi],
            **dashpot_margins(cand),
        },
        # the continuous bound's own design (its objective is the record's bound)
        "bound_design": None if bound is None else {
            k: v for k, v in bound.items() if k != "objective"},
        "search_bounds": searched,
    }
    res.optimisation = record.to_dict()
    return res


def _grid_ends(values) -> tuple[float, float]:
    values = np.asarray(values, dtype=float)
    return (float(values.min()), float(values.max())) if values.size else (math.nan, math.nan)


def search_bounds(spec: Spec, req: Requirements, cand: Candidate) -> list[dict]:
    """The bounds the search searched (``[bounds]``, defaults included) and where the chosen
    design lies in them, one dict each: the variable's ``name`` (``ball_mass``,
    ``wire_diameter``, ...), its ``key`` in ``[bounds]``, its SI ``unit``, ``low_<unit>``,
    ``high_<unit>`` and ``value_<unit>`` (``low``, ``high``, ``value`` when dimensionless),
    ``given`` (the spec states it) and ``at``: ``"lower"`` or ``"upper"`` where the design
    takes the least or the largest value the search could give it within the bound (the
    catalogue's grid), ``"fixed"`` for equal ends, else None; ``held``: what holds it there,
    ``"bound"`` (the grid reaches the bound) or ``"catalogue"`` (the grid's last step inside
    the bound falls short of it: the ``[catalogue]`` key ``step_key`` decides); ``bound_text``,
    ``step_text``: the bound and that key as the spec writes them (its own units; the default's
    text where it gives none)."""
    from ..spec_keys import bounds_table, catalogue_table

    gov = spec.governor
    kind = gov.spring_kind
    data = spec.data or {}
    given = data.get("bounds") or {}
    table = bounds_table(gov, kind)
    rows = [(f"{gov.mass_key}_mass", gov.mass_key, "kg", req.flying_mass, mass_grid(req),
             cand.m, "weight_step")]
    if gov.central_load:
        rows.append(("central_mass", "central", "kg", req.central_mass,
                     grid_steps(*req.central_mass, req.mass_step), cand.central, "weight_step"))
    if cand.spring and kind is not None and kind.helical:
        axes = dict(zip(("wire_diameter", "coil_radius", "active_turns"),
                        catalogue_axes(req), strict=True))
        steps = {"wire_diameter": "wire_diameters", "coil_radius": "coil_radius_step",
                 "active_turns": "turn_step"}
        rows += [(k.name, k.name, k.unit, getattr(req, k.name), axes[k.name],
                  cand.spring[k.name], steps.get(k.name)) for k in kind.bounds]
    elif cand.spring and kind is not None:
        from ..springs import leaf

        w, t = leaf.stock_sections()
        keep = ((w >= req.leaf_width[0] - 1e-12) & (w <= req.leaf_width[1] + 1e-12)
                & (t >= req.leaf_thickness[0] - 1e-12) & (t <= req.leaf_thickness[1] + 1e-12))
        rows += [(k.name, k.name, k.unit, getattr(req, k.name), grid[keep],
                  cand.spring[k.name], "leaf_sections")
                 for k, grid in zip(kind.bounds, (w, t), strict=True)]
    if req.dashpot is not None and not math.isnan(cand.f):
        rows.append(("dashpot_f", "dashpot_f", gov.key_unit("damping"), req.dashpot,
                     np.array(req.dashpot), cand.f, None))
    catalogue = catalogue_table(kind)
    written = data.get("catalogue") or {}
    out = []
    for name, key, unit, (lo, hi), grid, value, step in rows:
        first, last = _grid_ends(grid)
        tol = 1e-9 * max(abs(first), abs(last), 1e-300)
        at = ("fixed" if lo == hi else "lower" if value <= first + tol
              else "upper" if value >= last - tol else None)
        end = first if at == "lower" else last
        bound = lo if at == "lower" else hi
        held = None if at not in ("lower", "upper") else (
            "catalogue" if step and abs(end - bound) > 1e-6 * max(abs(bound), abs(end))
            else "bound")
        suffix = f"_{unit}" if unit else ""
        names = [n for n in table.key(key).names if n in given]
        entry = {"name": name, "key": names[0] if names else "/".join(table.key(key).names),
                 "unit": unit, f"low{suffix}": lo, f"high{suffix}": hi,
                 f"value{suffix}": value, "given": bool(names), "at": at, "held": held}
        if held:
            side = 0 if at == "lower" else 1
            entry["bound_text"] = str(given[names[0]][side]) if names else _shown(bound, unit)
        if held == "catalogue":
            decl = catalogue.key(step)
            entry["step_key"] = step
            entry["step_text"] = (str(written[step]) if step in written else
                                  decl.default_text or str(decl.default))
        out.append(entry)
    return out


def _shown(value: float, unit: str) -> str:
    """A bound's value as a person reads it: lengths in mm."""
    if unit == "m":
        return f"{value * 1e3:.4g} mm"
    return f"{value:.4g} {unit}".rstrip()


def _as_written(value: float, unit: str, text: str) -> str:
    """``value`` (SI ``unit``) in the unit of ``text``, a quantity as the spec writes it
    (``"0.25 lbf"``; a mass searched under a weight's bound as its weight), else
    :func:`_shown`."""
    from ..units import registry

    written = str(text).lstrip("+-0123456789.eE ").strip()
    if not written or not unit:
        return _shown(value, unit)
    ureg = registry()
    for magnitude, si in ((value, unit), (value * G_STANDARD, "N")):
        try:
            return f"{ureg.Quantity(magnitude, si).to(written).magnitude:.4g} {written}"
        except Exception:  # noqa: BLE001 - another dimension: the next reading, else SI
            continue
    return _shown(value, unit)


def bounds_notes(searched: list[dict]) -> list[str]:
    """The report's lines on the bounds searched (:func:`search_bounds`): every bound, its
    default marked, and each variable the design takes at a search bound."""
    def ends(b):
        s = f"_{b['unit']}" if b["unit"] else ""
        return b[f"low{s}"], b[f"high{s}"], b[f"value{s}"]

    parts = []
    for b in searched:
        lo, hi, _ = ends(b)
        span = (_shown(lo, b["unit"]) if b["at"] == "fixed" else
                f"{_shown(lo, b['unit'])} .. {_shown(hi, b['unit'])}")
        how = [w for w, on in (("default", not b["given"]), ("fixed", b["at"] == "fixed"))
               if on]
        parts.append(f"{b['name']} {span}" + (f" ({', '.join(how)})" if how else ""))
    notes = ["search bounds ([bounds]): " + ", ".join(parts)]
    for b in searched:
        if b["at"] not in ("lower", "upper"):
            continue
        value = _as_written(ends(b)[2], b["unit"], b.get("bound_text", ""))
        if b.get("held") == "catalogue":
            least, beyond = ("least", "below") if b["at"] == "lower" else ("largest", "above")
            notes.append(f"at the {least} {b['name']} the catalogue gives within the bounds "
                         f"({value}; [bounds] {b['key']} {b['at']} end {b['bound_text']}): "
                         f"the catalogue's step holds it, not the bound ([catalogue] "
                         f"{b['step_key']} = {b['step_text']}); a finer {b['step_key']} "
                         f"searches {beyond} it")
        else:
            notes.append(f"at the {b['at']} search bound of {b['name']} ({value}; [bounds] "
                         f"{b['key']} {b['at']} end {b['bound_text']}): widen [bounds] "
                         f"{b['key']} to search beyond it")
    return notes

def dashpot_margins(cand: Candidate) -> dict:
    """How far the chosen dash-pot may be set off before it leaves its feasible window
    (:func:`govopt.optimize.margins.margins_to_ends`), in per cent; empty without a dash-pot."""
    if not (cand.f > 0 and math.isfinite(cand.f_lo) and math.isfinite(cand.f_hi)):
        return {}
    down, up = margins_to_ends(cand.f, cand.f_lo, cand.f_hi)
    return {"dashpot_margin_to_lower_end_percent": 100.0 * down,
            "dashpot_margin_to_upper_end_percent": 100.0 * up}


def dead_weight_search(spec: Spec, req: Requirements) -> tuple[Candidate, dict]:
    """Least moving mass (every ball and the central load: :meth:`Governor.moving_mass`) of a
    dead-weight governor (Watt, Porter, Proell: textbook
    3.4), exhaustive over the ball and central-load weights on the catalogue's weight step.

    At each (m, M) the characteristic is exact (virtual work on the seam); with a friction band
    the sleeve rises at ``omega_rise`` and falls at ``omega_fall`` (section 3.4(b), "Friction at
    the sleeve"), so the requirement is that the whole operating band lies in the spec's range:
    the least ``omega_fall`` over the range ``>= omega_inner`` and the largest ``omega_rise``
    ``<= omega_outer`` (:func:`govopt.analysis.statics.band_extremes`), with
    ``k^2`` within its margins (a rising characteristic) everywhere. The geometry fixes the
    ratio of the band's ends; the masses set its level (``M/m``) and, against friction, its
    width. With an engine and load changes the dash-pot is designed as for spring governors.
    """
    grid, km, rows, m, c, stats = dead_weight_candidates(spec, req)
    gov = spec.governor
    for part in batches(rows.size, 64):
        sel, start = rows[part], part.start
        try:
            win = dashpot_window(spec, req, km, grid, sel, np.zeros(sel.size))
        except limits.WorkLimit:
            stats["dynamics_checked"] = int(start)
            stats["dynamics_stopped_at_the_work_limit"] = True
            raise dynamics_conflict(spec, req, stats) from None
        if np.any(win["feasible"]):
            j = int(np.argmax(win["feasible"]))
            i = sel[j]
            stats["dynamics_checked"] = int(start + j + 1)
            return Candidate(float(m[i]), {}, 0.0, 0.0, float(win["f"][j]),
                             float(gov.moving_mass(m[i], c[i], 0.0)), float(win["settling"][j]),
                             float(win["f_lo"][j]), float(win["f_hi"][j]), float(c[i])), stats
    stats["dynamics_checked"] = int(rows.size)
    raise dynamics_conflict(spec, req, stats)


def dead_weight_candidates(spec: Spec, req: Requirements):
    """The (ball, central) weight pairs of a dead-weight governor that meet the statics
    requirements (:func:`dead_weight_search`), least moving mass first: ``(grid, km, rows, m,
    c, stats)``, ``km`` the kappa-free model :func:`dashpot_window` takes (rows of ``m``, ``c``).
    Raises :class:`InfeasibleError` with the diagnosis when none does."""
    gov = spec.governor
    grid = Grid.build(spec)
    m, c = masses(req)
    if m.size == 0:
        raise InfeasibleError(f"{spec.path}: bounds.{gov.mass_key}_weight: no weight on the "
                              "catalogue's weight_step grid lies within the bounds")
    ok_parts, w2, rise, fall, k2, inertia = dead_weight_statics(spec, req, grid, m, c)
    ok = np.logical_and.reduce(list(ok_parts.values()))
    stats = {"masses": int(m.size), "combinations": int(m.size),
             "statics_feasible": int(ok.sum()), "spring_feasible": int(ok.sum())}
    if not ok.any():
        raise dead_weight_diagnosis(spec, req, ok_parts, rise, fall)
    zero = Affine(0.0 * w2, w2)

    km = KappaModel(spec, m[:, None], grid.alpha, zero, Affine(0.0 * k2, k2),
                    Affine(0.0 * w2, 0.0 * w2), Affine(0.0 * m[:, None], 0.0 * m[:, None]),
                    inertia, c[:, None])
    rows = np.nonzero(ok)[0]
    return grid, km, rows[np.argsort(gov.moving_mass(m[rows], c[rows], 0.0), kind="stable")], \
        m, c, stats
