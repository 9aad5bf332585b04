"""Robust design: every check holds over a tolerance box, after the fitter's adjustment.

``[requirements]`` may ask that the design hold for parts made anywhere within their tolerances:

- the spring, per ``robust_spring_grade`` (EN 15800 quality grade 1-3): the mean coil diameter
  ``+-A_D`` (EN 15800 Table 1), the free length ``+-A_L0`` of a compression spring (EN 15800;
  an extension spring's by agreement with the maker, so not included, as on the spring sheet)
  and the wire diameter per its EN 10270 standard (none for a material without a wire grade) -
  the tolerances of the spring sheet (:mod:`govopt.springs.tolerances`,
  :func:`govopt.springs.sheet.compression_sheet`);
- the dash-pot setting ``+-robust_dashpot`` (a fraction), the flying and central masses
  ``+-robust_masses`` and the engine's torque slope ``+-robust_torque_slope``;

and may name what the fitter adjusts on assembly: ``adjusting_nut``, the spring's free length
(its initial extension) by a nut, within ``+-adjusting_nut`` (m); ``dashpot_valve``, the dash-pot
valve, within ``+-dashpot_valve`` of the design's setting (a fraction; the setting's tolerance
``robust_dashpot`` applies on top).

Method. The nominal search's candidates (statics screen and spring checks,
:func:`govopt.optimize.design.spring_screen`, or a dead-weight governor's weight pairs,
:func:`govopt.optimize.design.dead_weight_candidates`; dash-pot in the centre of its window,
:func:`govopt.optimize.design.dashpot_window`) are visited in objective order, and each one that
is feasible at nominal values is evaluated at every corner of its tolerance box by the bulk
evaluator (:func:`govopt.bulk.evaluate_many`, vectorised over candidates x corners). With an
adjusting nut or valve, a point of the box holds if some setting on a grid over their ranges
makes every check hold (the fitter sets them for the parts at hand). A candidate that holds at
every corner is then taken over the whole box (:func:`worst_case`): every edge of the box is
probed at its quarter points; a check whose margin is monotone along every edge in every
tolerance has its worst case at a corner, and one that is not (the irregularity in the flying
mass, for one) is minimised over the tolerances it is not monotone in by a bounded quasi-Newton
search (L-BFGS-B) from its worst probed point - the inner maximisation of its violation. The
first candidate that holds over its box is the robust optimum (the least objective among the
catalogue's candidates that do; at most :data:`MAX_CHECKED` candidates feasible at nominal
values are checked, then the diagnosis names the check that fails most often, at a corner or
inside the box). It is then verified by a seeded Monte-Carlo sample, uniform within the box
(every part anywhere within its tolerance), through the same evaluator: the probability that
every check holds, with its 95 % Wilson interval (:func:`govopt.stats.wilson`), and the checks
that fail in the sample.

The checks of the search bounds (``pendulum mass >= min`` ...) are not requirements on a made
part and are left out of the worst case.

Work. Every evaluation is counted at its estimated cost (:func:`row_seconds`,
:func:`govopt.limits.evaluation_seconds`: a forced vibration, a leaf's checks or friction
strokes design by design cost ten to a hundred times the vectorised rest), against
:data:`govopt.limits.MAX_ROBUST_SEARCH_SECONDS` for the search and
:data:`govopt.limits.MAX_MONTE_CARLO_SECONDS` for the verification: a spec whose first
candidate's box or whose samples alone exceed them is refused before anything runs
(:func:`work_errors`), a search that reaches its limit stops with a diagnosis, and a
verification that reaches it stops adjusting the failing samples (the probability is then a
lower bound, and says so).
"""

from __future__ import annotations

import itertools
import math
import time
from dataclasses import replace

import numpy as np

from .. import limits
from .. import made as mk
from ..analysis import tolerance as tm
from ..analysis.tolerance import Box
from ..errors import InfeasibleError
from ..made import (  # noqa: F401 (BOUND_NAMES: the search bounds, for its readers)
    ADJUSTMENT_GROUPS,
    BOUND_NAMES,
    TORQUE_LEVELS,
    check_margins,
    holds,
)
from ..requirements import PASS_TOL
from ..spec import Design, Requirements, Spec
from ..stats import wilson
from . import design as dz

#: the checks a made governor must meet (all but the search bounds')
robust_checks = mk.requirement_checks

#: the fitter's settings of the adjusting nut and of the dash-pot valve tried over each one's
#: range (odd: the nominal setting included)
NUT_SETTINGS = 9
#: batches of candidates evaluated at their corners, and the most checked before giving up
BATCHES = (8, 64, 256)
MAX_CHECKED = 1024
#: the yield's samples of a candidate (``requirements.min_yield``) are evaluated in blocks of
#: these sizes (the last repeated), and the candidate is dropped after a block where its yield
#: cannot reach the requirement (:func:`yield_search`)
YIELD_BLOCKS = (16, 48, 192, 448)


def nominal_requirements(req: Requirements) -> Requirements:
    """The requirements without the tolerance box (the nominal design's)."""
    return replace(req, robust_spring_grade=None, robust_dashpot=0.0, robust_masses=0.0,
                   robust_torque_slope=0.0, adjusting_nut=0.0, dashpot_valve=0.0,
                   min_yield=None)


def box_notes(spec: Spec, req: Requirements) -> list[str]:
    """What the tolerance box leaves out, in words (:func:`govopt.analysis.tolerance.notes`)."""
    return tm.notes(spec, tm.spring_grade(spec, req))


def candidate_box(spec: Spec, req: Requirements, cols: dict) -> Box:
    """The tolerance box of candidates given as design columns ``cols`` (arrays): the tolerance
    model's (:func:`govopt.analysis.tolerance.stated`)."""
    grade = tm.spring_grade(spec, req)
    if grade is not None and tm.kind(spec) is None:
        raise InfeasibleError(f"{spec.path}: requirements.robust_spring_grade: EN 15800 "
                              "tolerances are for helical springs")
    return tm.stated(spec, cols, req)


WorkLimit, Work, counting = limits.WorkLimit, limits.Work, limits.counting


def _vibration(spec: Spec, req: Requirements) -> bool:
    """Whether the robust evaluations solve the forced vibration (a limit or objective on it,
    or a wire grade's fatigue)."""
    return req.max_vibration is not None or req.objective == "vibration" or (
        spec.material is not None and spec.material.grade is not None)


def row_seconds(spec: Spec, req: Requirements) -> float:
    """Estimated CPU seconds of one robust evaluation of a design of ``spec``
    (:func:`govopt.made.row_seconds`, the forced vibration where :func:`_vibration` asks it)."""
    return mk.row_seconds(spec, _vibration(spec, req))


def _dimensions_at_most(spec: Spec, req: Requirements) -> int:
    """How many quantities a candidate's box tolerances at most (:func:`candidate_box`)."""
    k = 0
    if tm.spring_grade(spec, req) is not None and tm.kind(spec) is not None:
        k += 1 + (tm.wire_standard(spec) is not None) + (tm.kind(spec) == "compression")
    if req.robust_dashpot > 0:
        k += 1
    if req.robust_masses > 0:
        k += 1 + bool(req.central_mass[1] > 0)
    return k + (req.robust_torque_slope > 0)


def work_errors(spec: Spec, req: Requirements):
    """The robust design's work past govopt's limits before anything runs, as ``(key,
    message)``, else None: the Monte-Carlo's samples alone beyond half of
    :data:`govopt.limits.MAX_MONTE_CARLO_SECONDS` (the rest is the fitter's adjustment of the
    samples that fail), or the first batch of candidates at their corners and one candidate's
    edges (:func:`worst_case`) at every fitter's setting beyond
    :data:`govopt.limits.MAX_ROBUST_SEARCH_SECONDS`."""
    row = row_seconds(spec, req)
    each = f"each evaluation ~{row * 1e3:.2g} ms here"
    samples = int(limits.MAX_MONTE_CARLO_SECONDS / 2 / row)
    if req.robust_samples > samples:
        return ("requirements.robust_samples",
                f"at most {samples} samples for this spec ({each}: govopt's limit of "
                f"{limits.MAX_MONTE_CARLO_SECONDS / 2:g} s for the sample), got "
                f"{req.robust_samples}")
    k, settings = _dimensions_at_most(spec, req), nut_settings(req)[0].size
    rows = (BATCHES[0] * 2**k + k * 2 ** max(k - 1, 0) * len(EDGE_POINTS) + 1) * settings
    if rows * row > limits.MAX_ROBUST_SEARCH_SECONDS:
        fitter = (f" at each of the fitter's {settings} settings (adjusting_nut, "
                  "dashpot_valve)" if settings > 1 else "")
        return ("requirements",
                f"the tolerance box of {k} quantities ({2**k} corners){fitter} takes "
                f"~{rows * row:.0f} s to check the first candidates ({each}), past govopt's "
                f"limit of {limits.MAX_ROBUST_SEARCH_SECONDS:g} s: tolerance fewer quantities "
                "(robust_*)" + (" or adjust fewer" if settings > 1 else ""))
    return None


def _evaluate(spec: Spec, req: Requirements, cols: dict, torque: np.ndarray):
    """Bulk evaluation of design columns, each row at its relative torque-slope change
    ``torque`` (:func:`govopt.made.evaluate_at`; the running :class:`Work` is charged first)."""
    return mk.evaluate_at(spec, cols, torque, _vibration(spec, req))


def nut_settings(req: Requirements):
    """The fitter's settings tried: ``(nut, valve)``, the nut's free-length change (m) and the
    valve's factor on the dash-pot, least change first
    (:func:`govopt.analysis.tolerance.fitter_settings`)."""
    return tm.fitter_settings(req.adjusting_nut, req.dashpot_valve, NUT_SETTINGS)


def corners(spec: Spec, req: Requirements, cols: dict, box: Box, arrays: bool = False):
    """Every corner of each candidate's box, each at every nut setting: the evaluated frame (or,
    with ``arrays``, the :class:`govopt.made.Evaluated` arrays, no pandas) and its candidate,
    corner and nut indices (flat arrays), and the corners' sign table."""
    names = box.active()
    dims = names + (["torque_slope"] if box.torque > 0 else [])
    signs = np.array(list(itertools.product((-1.0, 1.0), repeat=len(dims))),
                     dtype=float).reshape(2 ** len(dims), len(dims))  # one, empty, without any
    nut, valve = nut_settings(req)
    n = len(cols["flying_mass"])
    cand, corner, k = (a.ravel() for a in np.meshgrid(np.arange(n), np.arange(len(signs)),
                                                         np.arange(nut.size), indexing="ij"))
    rows = {f: v[cand].copy() for f, v in cols.items()}
    for j, name in enumerate(names):
        rows[name] = rows[name] + signs[corner, j] * box.fields[name][cand]
    rows["free_half_length"] = rows["free_half_length"] + nut[k]
    rows["dashpot"] = rows["dashpot"] * valve[k]
    torque = signs[corner, -1] * box.torque if box.torque > 0 else np.zeros(cand.size)
    frame = (mk.evaluate_arrays(spec, rows, torque, _vibration(spec, req)) if arrays
             else _evaluate(spec, req, rows, torque))
    return frame, cand, corner, k, signs, dims


def corner_verdict(frame, n: int, n_corners: int, n_nut: int):
    """Per candidate: whether every corner holds at some nut setting, and per corner the first
    (least) setting index that holds (-1: none)."""
    ok = holds(frame).reshape(n, n_corners, n_nut)
    first = np.where(ok.any(axis=2), np.argmax(ok, axis=2), -1)
    return np.all(first >= 0, axis=1), first


def _design_columns(cat, rows, cols, l0, km, f) -> dict:
    c = km.central[rows, 0]
    out = {"flying_mass": km.m[rows, 0], "free_half_length": l0, "dashpot": f,
           "central_mass": np.where(c > 0, c, np.nan)}
    out.update({k: v[cols] for k, v in cat.fields.items()})
    return out


def supported(spec: Spec, req: Requirements) -> None:
    """Raise a one-line :class:`InfeasibleError` for a robust design the search cannot make:
    a dynamic objective, or a tolerance the governor does not have."""
    gov = spec.governor
    if req.objective not in ("moving_mass", "spring_mass"):
        what = req.objective.replace("_", " ")
        raise InfeasibleError(
            f"{spec.path}: requirements.objective: a robust design (robust_* keys) minimises "
            f"the moving or spring mass, not the {what} (it moves with the dash-pot setting "
            "the box varies): minimise a mass and bound the "
            f"{what} by requirements.max_{req.objective}")
    if gov.spring is None and req.robust_spring_grade is not None:
        raise _no_spring(spec, "robust_spring_grade")
    if gov.spring is not None and not gov.spring_kind.helical and \
            req.robust_spring_grade is not None:
        raise InfeasibleError(
            f"{spec.path}: requirements.robust_spring_grade: EN 15800 tolerances are for "
            "helical springs, not a leaf spring: tolerance the masses and the dash-pot instead")
    if req.robust_dashpot > 0 and (spec.engine is None or not spec.load_changes):
        raise _no_dashpot(spec, "robust_dashpot")
    fitter_supported(spec, req)
    if req.min_yield is not None:
        if not tm.states_tolerances(spec, req):
            raise InfeasibleError(
                f"{spec.path}: requirements.min_yield: the spec states no tolerance to make the "
                "governor to: name the spring's wire grade (material.grade, made to its "
                "tolerance_grade) or robust_spring_grade, or spread the masses or the dash-pot "
                "(robust_masses, robust_dashpot)")
        n = req.robust_samples
        if yield_allowance(n, req.min_yield) < 0:
            need = next(k for k in itertools.count(n) if wilson(k, k)[0] >= req.min_yield)
            raise InfeasibleError(
                f"{spec.path}: requirements.robust_samples: {n} samples cannot show a yield "
                f"of {req.min_yield:g} at 95 % confidence (even all {n} holding, its Wilson "
                f"lower bound is {wilson(n, n)[0]:.4g}): at least {need}")
    too_much = work_errors(spec, req)
    if too_much:  # counted before anything runs
        raise InfeasibleError(f"{spec.path}: {too_much[0]}: {too_much[1]}")


def fitter_supported(spec: Spec, req: Requirements) -> None:
    """Raise a one-line :class:`InfeasibleError` for a fitter's range the governor cannot have:
    an adjusting nut without a spring, a dash-pot valve without a dash-pot."""
    gov = spec.governor
    if gov.spring is None and req.adjusting_nut > 0:
        raise _no_spring(spec, "adjusting_nut")
    if req.dashpot_valve > 0 and (spec.engine is None or not spec.load_changes):
        raise _no_dashpot(spec, "dashpot_valve")


def _no_spring(spec: Spec, key: str) -> InfeasibleError:
    """``requirements.KEY`` tolerances a spring that a dead-weight governor does not have."""
    return InfeasibleError(
        f"{spec.path}: requirements.{key}: a {spec.governor.type_name} governor has no spring "
        "(dead weight): tolerance its masses (robust_masses) and dash-pot instead")


def _no_dashpot(spec: Spec, key: str) -> InfeasibleError:
    """``requirements.KEY`` tolerances a dash-pot that is not designed without a load change."""
    return InfeasibleError(f"{spec.path}: requirements.{key}: no dash-pot is designed without "
                           "[engine] and [[load_change]]: drop the key or add them")


def yield_allowance(n: int, min_yield: float) -> int:
    """The most of ``n`` sampled governors that may fail while the yield's 95 % Wilson lower
    bound stays at least ``min_yield`` (:func:`govopt.stats.wilson`); -1 where even none
    failing is not enough.

    >>> yield_allowance(2000, 0.99), yield_allowance(500, 0.99), yield_allowance(300, 0.99)
    (11, 0, -1)
    """
    f = -1
    while f + 1 <= n and wilson(n - (f + 1), n)[0] >= min_yield:
        f += 1
    return f


def _slices(order):
    """``(first, order[first:first + size])`` in the batch sizes of :data:`BATCHES` (the last
    size repeated)."""
    start, b = 0, 0
    while start < order.size:
        size = BATCHES[min(b, len(BATCHES) - 1)]
        yield start, order[start:start + size]
        start, b = start + size, b + 1


def spring_batches(spec: Spec, req: Requirements):
    """A spring governor's candidates feasible at nominal values, in objective order, in
    batches (:data:`BATCHES`): ``(design columns, candidates)``, the statics screen and spring
    checks of the nominal search (:func:`govopt.optimize.design.spring_screen`) with the dash-pot
    in its window (:func:`govopt.optimize.design.dashpot_window`)."""
    dz.check_grids(spec, req)
    grid, km, lo, hi, parts = dz.statics_window(spec, req)
    if not np.any(lo <= hi):
        raise dz.diagnose(spec, req, "statics", parts)
    cat = dz.catalogue(spec, req)
    rows, cols, l0, _ = dz.spring_screen(spec, req, km, lo, hi, cat)
    values = dz.objective_values(req, km.m[rows, 0], cat.mass[cols],
                                 central=km.central[rows, 0], gov=spec.governor)
    order = np.argsort(values, kind="stable")
    for first, sel in _slices(order):
        fat = None if cat.fatigue is None else (
            lambda swing, s=sel: cat.fatigue(cols[s], l0[s], swing))
        win = dz.dashpot_window(spec, req, km, grid, rows[sel], cat.kappa[cols[sel]],
                                fatigue=fat)
        good = np.nonzero(win["feasible"])[0]
        s = sel[good]
        cands = [dz.Candidate(float(km.m[rows[i], 0]),
                              {k: float(v[cols[i]]) for k, v in cat.fields.items()},
                              float(cat.kappa[cols[i]]), float(l0[i]), float(win["f"][g]),
                              float(values[i]), float(win["settling"][g]),
                              float(win["f_lo"][g]), float(win["f_hi"][g]),
                              float(km.central[rows[i], 0])) for i, g in zip(s, good, strict=True)]
        visited = [int(first + g + 1) for g in good]
        yield _design_columns(cat, rows[s], cols[s], l0[s], km, win["f"][good]), cands, visited


def dead_weight_batches(spec: Spec, req: Requirements):
    """A dead-weight governor's (ball, central) weight pairs feasible at nominal values, least
    moving mass first, in batches, as :func:`spring_batches` gives them
    (:func:`govopt.optimize.design.dead_weight_candidates`, the dash-pot in its window)."""
    grid, km, rows, m, c, _ = dz.dead_weight_candidates(spec, req)
    for first, sel in _slices(rows):
        win = dz.dashpot_window(spec, req, km, grid, sel, np.zeros(sel.size))
        good = np.nonzero(win["feasible"])[0]
        s = sel[good]
        cands = [dz.Candidate(float(m[i]), {}, 0.0, 0.0, float(win["f"][g]), float(m[i] + c[i]),
                              float(win["settling"][g]), float(win["f_lo"][g]),
                              float(win["f_hi"][g]), float(c[i]))
                 for i, g in zip(s, good, strict=True)]
        visited = [int(first + g + 1) for g in good]
        yield ({"flying_mass": m[s], "central_mass": np.where(c[s] > 0, c[s], np.nan),
                "free_half_length": np.full(s.size, np.nan), "dashpot": win["f"][good]},
               cands, visited)


def robust_search(spec: Spec, req: Requirements):
    """The least-objective candidate that holds every check over its tolerance box (corners
    first, then the whole box, :func:`worst_case`): ``(Candidate, stats, worst case)``; raises
    :class:`InfeasibleError` when none does."""
    stats = {"nominal_feasible_checked": 0, "corner_evaluations": 0,
             "inner_maximisations": 0, "rejected_inside_the_box": 0}
    failing: dict[tuple[str, str], int] = {}
    work = Work(limits.MAX_ROBUST_SEARCH_SECONDS)
    try:
        with counting(work):
            found = _search(spec, req, stats, failing)
    except WorkLimit:
        found = None
        stats["stopped_at_the_work_limit"] = True
    stats["evaluations"], stats["work_s"] = work.items, round(work.spent, 3)
    if found is not None:
        return found
    if req.min_yield is not None:
        raise InfeasibleError(yield_diagnosis(spec, req, stats, failing))
    worst = sorted(failing.items(), key=lambda kv: -kv[1])[:2]
    which = "; ".join(f"'{k}' fails {where} for {v}" for (k, where), v in worst) or (
        "at some corner no setting of the fitter's makes every check hold at once"
        if stats["corner_evaluations"] else "none is within the EN 15800 / EN 10270 tables")
    stopped = stats.get("stopped_at_the_work_limit")
    raise InfeasibleError(
        f"{spec.path}: infeasible: requirements.robust_*: no candidate holds every check over "
        f"its tolerance box ({stats['nominal_feasible_checked']} candidates feasible at nominal "
        "values checked best first, "
        + (f"stopped at govopt's limit of work (~{limits.MAX_ROBUST_SEARCH_SECONDS:g} s)"
           if stopped else f"at most {MAX_CHECKED}")
        + f": {which}); narrow the tolerances, "
        + ("add requirements.adjusting_nut, " if spec.governor.spring is not None
           and not stopped else "")
        + "or widen the bounds (or the speed range)")


def _candidates(spec: Spec, req: Requirements, stats: dict):
    """The searches' batches of candidates feasible at nominal values, in objective order, at
    most :data:`MAX_CHECKED` of them (counted in ``stats``): ``(design columns, candidates,
    candidates visited, their tolerance box)``."""
    batches = spring_batches if spec.governor.spring is not None else dead_weight_batches
    for dcols, cands, visited in batches(spec, req):
        if stats["nominal_feasible_checked"] >= MAX_CHECKED:
            break
        if not cands:
            continue
        if spec.engine is None or not spec.load_changes:
            dcols["dashpot"] = np.full(len(cands), np.nan)
        stats["nominal_feasible_checked"] += len(cands)
        yield dcols, cands, visited, candidate_box(spec, req, dcols)


def _search(spec: Spec, req: Requirements, stats: dict, failing: dict):
    """:func:`robust_search`'s loop: the candidate found with its stats and worst case, else
    None (``stats`` and ``failing`` filled in)."""
    if req.min_yield is not None:
        return _yield_search(spec, req, stats, failing)
    for dcols, cands, visited, box in _candidates(spec, req, stats):
        n = len(cands)
        finite = box.finite()
        if not finite.any():  # outside the tolerance tables: not certifiable
            continue
        frame, *_, signs, _ = corners(spec, req, {k: v[finite] for k, v in dcols.items()},
                                      Box({k: v[finite] for k, v in box.fields.items()},
                                          box.torque))
        stats["corner_evaluations"] += len(frame)
        n_nut = nut_settings(req)[0].size
        ok_f, _ = corner_verdict(frame, int(finite.sum()), len(signs), n_nut)
        for name, count in failures(frame, int(finite.sum()), len(signs), n_nut).items():
            failing[(name, "at a corner")] = failing.get((name, "at a corner"), 0) + count
        ok = np.zeros(n, bool)
        ok[finite] = ok_f
        for j in np.nonzero(ok)[0]:  # in objective order: the whole box, not only its corners
            wc = worst_case(spec, req, {k: v[j:j + 1] for k, v in dcols.items()},
                            Box({k: v[j:j + 1] for k, v in box.fields.items()}, box.torque),
                            stop_on_failure=True)
            stats["inner_maximisations"] += int(bool(wc["not_monotone"]))
            if not wc["holds"]:
                stats["rejected_inside_the_box"] += 1
                for name in failures(wc["frame"], len(wc["frame"]), 1, 1):
                    key = (name, "inside the box")
                    failing[key] = failing.get(key, 0) + 1
                continue
            stats["candidates_visited"] = visited[j]
            return cands[j], stats, wc
    return None


def _yield_search(spec: Spec, req: Requirements, stats: dict, failing: dict):
    """The search for a yield (``requirements.min_yield``): the candidates feasible at nominal
    values, in objective order, each made ``robust_samples`` times within its box
    (:func:`govopt.made.made_yield`, the same samples as its reported yield) in blocks
    (:data:`YIELD_BLOCKS`). A candidate is dropped after a block where its yield cannot reach
    the requirement: more failures than the whole sample may have
    (:func:`yield_allowance`), or so many that even the Wilson interval of its failure rate so
    far lies wholly above ``1 - min_yield``. A candidate whose first block holds is tried over
    its whole box first (its corners, then :func:`worst_case`): holding there, its yield is 1,
    certified without samples. The first that is certified, or whose whole sample shows the
    yield at 95 % confidence, is chosen: ``(Candidate, stats, worst case or None)``, the yield
    in ``stats["_yield"]``; None when none is (``failing``: the requirements failing in the
    samples; ``stats["_best"]``: the best candidate seen)."""
    n, seed, fitter = req.robust_samples, req.robust_seed, mk.fitter_of(req)
    allowance = yield_allowance(n, req.min_yield)
    stats.update(candidates_sampled=0, dropped_early=0, certified_by_the_worst_case=0)

    def give_up(fails: int, done: int) -> bool:
        return fails > allowance or (done < n and wilson(fails, done)[0] > 1.0 - req.min_yield)

    for dcols, cands, visited, box in _candidates(spec, req, stats):
        for j in np.nonzero(box.finite())[0]:  # outside the tolerance tables: not made
            cols, bx = {k: v[j:j + 1] for k, v in dcols.items()}, box.take(slice(j, j + 1))
            stats["candidates_sampled"] += 1
            first = mk.made_yield(spec, cols, bx, n, seed, fitter, blocks=YIELD_BLOCKS[:1],
                                  give_up=lambda fails, done: True)
            if first["holds"] == first["samples"] and _holds_at_corners(spec, req, cols, bx):
                wc = worst_case(spec, req, cols, bx, stop_on_failure=True)
                if wc["holds"]:
                    stats["certified_by_the_worst_case"] += 1
                    stats["candidates_visited"] = visited[j]
                    return cands[j], stats, wc
            y = first if give_up(first["samples"] - first["holds"], first["samples"]) else \
                mk.made_yield(spec, cols, bx, n, seed, fitter, blocks=YIELD_BLOCKS,
                              give_up=give_up)
            for name, count in y["failing"].items():
                failing[(name, "in the samples")] = failing.get(
                    (name, "in the samples"), 0) + count
            best = stats.get("_best")
            if best is None or y["probability"] > best[0]["probability"]:
                stats["_best"] = (y, cands[j], cols, bx)
            if y["samples"] == n and y["ci95"][0] >= req.min_yield:
                stats["candidates_visited"] = visited[j]
                stats["_yield"] = y
                return cands[j], stats, None
            stats["dropped_early"] += int(y["samples"] < n)
    return None


def _holds_at_corners(spec: Spec, req: Requirements, cols: dict, bx: Box) -> bool:
    """Whether one candidate holds every check at every corner of its box (at some setting of
    the fitter's)."""
    frame, *_, signs, _ = corners(spec, req, cols, bx, arrays=True)
    ok, _ = corner_verdict(frame, 1, len(signs), nut_settings(req)[0].size)
    return bool(ok[0])


def yield_diagnosis(spec: Spec, req: Requirements, stats: dict, failing: dict) -> str:
    """Why no candidate reaches ``requirements.min_yield``: the best yield seen and where, the
    requirements failing most often in the samples, and the tolerance that spreads the best
    candidate's speeds most (:func:`govopt.analysis.tolerance.speed_band_each`) against the
    required band."""
    checked = stats["nominal_feasible_checked"]
    stopped = stats.get("stopped_at_the_work_limit")
    head = (f"{spec.path}: infeasible: requirements.min_yield: no candidate's yield reaches "
            f"{100 * req.min_yield:g} % at 95 % confidence ({checked} candidates feasible at "
            "nominal values, sampled best first"
            + (f", stopped after {stats.get('evaluations', 0)} evaluations: the work govopt "
               f"allows a search, {limits.MAX_ROBUST_SEARCH_SECONDS:g} s of evaluations at "
               "their estimated cost" if stopped else "") + ")")
    best = stats.get("_best")
    if best is None:
        return head + ": none is within the EN 15800 / EN 10270 tables; widen the bounds"
    y, cand, cols, bx = best
    gov, rpm = spec.governor, 30.0 / math.pi
    spring = ", ".join(f"{k.replace('_', ' ')} {v * 1e3:.4g} mm" if k != "active_turns"
                       else f"{v:g} active turns" for k, v in cand.spring.items())
    worst = list(y["failing"].items())[:2]  # the best candidate's own, of its own samples
    text = (f"{head}: the best, {gov.mass_name} mass {cand.m:.4g} kg"
            + (f" with {spring}" if spring else "")
            + f", holds in {y['holds']} of its {y['samples']} samples "
            f"({100 * y['probability']:.3g} %); most often failing there: "
            + ", ".join(f"'{k}' (in {v} samples)" for k, v in worst))
    each = tm.speed_band_each(spec, cols, bx)
    sp = spec.speed
    outside = {k: v for k, v in each.items()  # a tolerance whose band leaves the required one
               if sp is not None and sp.band and (v[0] < sp.omega_inner or v[1] > sp.omega_outer)}
    if outside:
        name, (lo, hi) = max(outside.items(), key=lambda kv: kv[1][1] - kv[1][0])
        half = bx.fields[name][0]
        shown = f"+-{half * 1e3:.3g} mm" if name in ("wire_diameter", "coil_radius",
                                                      "free_half_length") else f"+-{half:.3g}"
        text += (f"; its {name.replace('_', ' ').replace('free half length', 'free length')} "
                 f"tolerance alone ({shown}, {tm.SOURCES[name]}) spreads its speed band over "
                 f"{lo * rpm:.4g}-{hi * rpm:.4g} rpm against the required "
                 f"{spec.speed.omega_inner * rpm:.4g}-{spec.speed.omega_outer * rpm:.4g} rpm")
    return text + ('; let the fitter set the spring (requirements.fitter = "sets"), '
                   if gov.spring is not None and not mk.fitter_sets(spec) else "; ") + (
        "make to a finer grade, lower min_yield, or widen the speed band or the bounds")


def failures(frame, n: int, n_corners: int, n_nut: int) -> dict:
    """Per robust check, on how many of ``n`` candidates it fails at some corner whatever the
    nut's setting (for the diagnosis)."""
    bad = check_margins(frame) < PASS_TOL
    count = bad.reshape(n, n_corners, n_nut, -1).all(axis=2).any(axis=1).sum(axis=0)
    return {c: int(k) for c, k in zip(robust_checks(frame), count, strict=True) if k}


def monte_carlo(spec: Spec, req: Requirements, design: Design) -> dict:
    """Seeded Monte-Carlo verification of one design: every toleranced value uniform within its
    box (``requirements.robust_samples`` samples, ``robust_seed``), the nut set by the fitter as
    at the corners; the probability that every check holds with its 95 % Wilson interval."""
    from ..bulk import design_arrays

    base = {k: v[:1] for k, v in design_arrays(spec.with_design(design), [design]).items()}
    box = candidate_box(spec, req, base)
    rng = np.random.default_rng(req.robust_seed)
    n = req.robust_samples
    rows = {k: np.repeat(v, n) for k, v in base.items()}
    for name in box.active():
        rows[name] = rows[name] + box.fields[name][0] * rng.uniform(-1.0, 1.0, n)
    torque = np.zeros(n)
    if box.torque > 0:
        levels = np.linspace(-box.torque, box.torque, TORQUE_LEVELS)
        torque = levels[rng.integers(0, TORQUE_LEVELS, n)]
    work = Work(limits.MAX_MONTE_CARLO_SECONDS)
    with counting(work):  # the samples (within half the limit: work_errors)
        frame = _evaluate(spec, req, rows, torque)
    with counting(work):  # the fitter adjusts the failing ones, least change first; those
        # not tried at every setting within the limit count as failing
        ok, adjusted, stopped = mk.fit(spec, rows, torque, holds(frame), req.adjusting_nut,
                                       req.dashpot_valve, _vibration(spec, req))
    k = int(ok.sum())
    lo, hi = wilson(k, n)
    # the checks that fail in the sample before any adjustment (a failure inside a box whose
    # corners hold: the check is not monotone in a tolerance)
    failing = failures(frame.iloc[np.nonzero(~ok)[0]], int((~ok).sum()), 1, 1) if k < n else {}
    out = {"samples": n, "seed": req.robust_seed, "distribution": "uniform within the box",
           "holds": k, "adjusted_by_the_fitter": adjusted, "probability": k / n,
           "failing_checks": failing,
           "ci95": [lo, hi], "evaluations": work.items, "work_s": round(work.spent, 3)}
    if stopped:
        out["note"] = (f"the fitter's adjustment stopped at govopt's limit of work (~"
                       f"{limits.MAX_MONTE_CARLO_SECONDS:g} s): {stopped} failing samples were "
                       "not tried at every setting and count as failing, so the probability is "
                       "a lower bound (fewer robust_samples, or fewer fitter's settings)")
    return out


def robust_design(spec: Spec):
    """The robust design of the spec (see the module docstring): the chosen design re-evaluated
    by :func:`govopt.evaluate` with, in ``optimisation["robust"]``, the box, the worst case of
    each check beside its nominal value, the adjusting nut's range and nominal setting, the
    Monte-Carlo verification and the cost against the nominal optimum."""
    req = dz.requirements(spec)
    supported(spec, req)
    nominal_req = nominal_requirements(req)
    t0 = time.perf_counter()
    nominal = dz.design(replace(spec, requirements=nominal_req))
    t_nominal = time.perf_counter() - t0
    t0 = time.perf_counter()
    cand, stats, wc = robust_search(spec, req)
    picked = stats.pop("_yield", None)
    stats.pop("_best", None)
    res = dz.result_of(spec, req, cand, stats, None)
    record = robust_record(spec, req, cand, res.checks, wc)
    if req.min_yield is None:  # the worst case, verified by a uniform sample of the box
        record["monte_carlo"] = monte_carlo(spec, req, design_of(spec, cand))
        if record["monte_carlo"].get("note"):
            res.optimisation["notes"] = [*res.optimisation.get("notes", []),
                                         record["monte_carlo"]["note"]]
    res.made = made_record(spec, req, res, picked)
    t_robust = time.perf_counter() - t0
    unit = res.optimisation["objective"]["unit"]
    v_nom = nominal.optimisation["value"]
    record["cost"] = {f"nominal_objective_{unit}": v_nom,
                      f"robust_objective_{unit}": cand.objective,
                      "increase_percent": 100.0 * (cand.objective / v_nom - 1.0),
                      "nominal_design": nominal.optimisation["design"]}
    record["time_s"] = {"nominal_design": t_nominal, "robust_search_and_verification": t_robust}
    res.optimisation["robust"] = record
    return res


def made_record(spec: Spec, req: Requirements, res, picked: dict | None) -> dict:
    """The made governors' record of the chosen design (:func:`govopt.made.record`): its yield
    as the search found it (``picked``, sampled), else 1, certified by the worst case over its
    box."""
    cols = mk.resolved_columns(spec, res)
    bx = candidate_box(spec, req, cols).known()
    return mk.record(spec, cols, bx, req.robust_samples if picked else 0, req.robust_seed,
                     mk.fitter_of(req), req.min_yield, certified=picked is None,
                     spreads=mk.spreads_of(req), sampled=picked)


def design_of(spec: Spec, cand) -> Design:
    """The candidate as a :class:`~govopt.spec.Design`."""
    return Design(flying_mass=cand.m, **cand.spring, free_half_length=cand.l0,
                  central_mass=cand.central or None,
                  dashpot=None if math.isnan(cand.f) else cand.f)


def robust_record(spec: Spec, req: Requirements, cand, checks=(), wc=None) -> dict:
    """The box of the chosen design, the worst case of each check over it (:func:`worst_case`,
    ``wc`` if already found) beside the nominal value (SI; unit, limit and sense from the
    evaluated ``checks``), where it lies and how it was found, and the fitter's settings: the
    range the box needs and the setting for nominal parts."""
    from ..bulk import design_arrays, margin_column, passed_column, value_column

    d = design_of(spec, cand)
    cols = {k: v[:1] for k, v in design_arrays(spec.with_design(d), [d]).items()}
    box = candidate_box(spec, req, cols)
    if wc is None:
        # a design for a yield need not hold over the whole box: its edges show where it fails
        wc = worst_case(spec, req, cols, box, inner=req.min_yield is None)
    at, dims, pts = wc["frame"], wc["dims"], wc["points"]
    nut, valve = nut_settings(req)
    nominal = at.iloc[:1]  # nominal parts, at the fitter's setting for them
    evaluated = {c.name: c for c in checks}
    checks = []
    for j, name in enumerate(robust_checks(at)):
        m = wc["margins"][:, j]
        if not np.any(m < np.inf):  # applies nowhere
            continue
        c = evaluated.get(name)
        w = worst_row(m, at[value_column(name)].to_numpy(dtype=float), wc["found_by"],
                      c.sense if c else "")
        passed = at[passed_column(name)]
        checks.append({"check": name, "unit": c.unit if c else "",
                       "sense": c.sense if c else "", "limit": c.limit if c else math.nan,
                       "nominal": float(nominal[value_column(name)].iloc[0]),
                       "worst_case": float(at[value_column(name)].iloc[w]),
                       "worst_margin": float(at[margin_column(name)].iloc[w]),
                       # in half-widths of each tolerance: -1 and +1 are the box's faces
                       "worst_at": {dims[j]: float(pts[w, j]) for j in range(len(dims))},
                       "found_by": wc["found_by"][w],
                       "not_monotone_in": wc["not_monotone"].get(name, []),
                       "holds": bool((passed.isna() | (passed == True)).all())})  # noqa: E712
    used = wc["setting"]
    band = speed_band(spec, at)
    corner = np.array([f == "corner" for f in wc["found_by"]])
    damping = spec.governor.key_unit("damping")
    halves = {f"{k}_m" if k in ("wire_diameter", "coil_radius", "free_half_length")
              else f"{spec.governor.mass_key}_mass_kg" if k == "flying_mass"
              else f"{k}_kg" if k.endswith("mass") else f"{k}_{damping}": float(v[0])
              for k, v in box.fields.items() if v[0] > 0}
    s0 = int(wc["setting"][0])
    return {
        "tolerances": {"spring_grade": req.robust_spring_grade,
                       "dashpot_fraction": req.robust_dashpot,
                       "masses_fraction": req.robust_masses,
                       "torque_slope_fraction": req.robust_torque_slope,
                       "half_widths": halves, "notes": box_notes(spec, req)},
        "corners": 2 ** len(dims), "points_evaluated": len(at),
        "holds_at_every_corner": bool(np.all(wc["margins"][corner] >= PASS_TOL)),
        "holds_over_the_box": bool(wc["holds"]),
        "speed_band": band,
        "checks": checks,
        "adjusting_nut": None if req.adjusting_nut <= 0 else {
            "range_m": [-req.adjusting_nut, req.adjusting_nut],
            "needed_range_m": [float(nut[used].min()), float(nut[used].max())],
            "nominal_setting_m": float(nut[s0]),
            f"{spec.governor.free_length_key}_at_nominal_setting_m":
                float(cols["free_half_length"][0] + nut[s0])},
        "dashpot_valve": None if req.dashpot_valve <= 0 else {
            f"range_{damping}": [cand.f * (1 - req.dashpot_valve),
                                 cand.f * (1 + req.dashpot_valve)],
            f"needed_range_{damping}": [float(cand.f * valve[used].min()),
                                        float(cand.f * valve[used].max())],
            f"nominal_setting_{damping}": float(cand.f * valve[s0])},
    }


def worst_row(margin, value, found_by, sense: str) -> int:
    """The row of the least margin; among rows tied with it (to 1e-12: a margin that is a ratio
    of forces is the same at every coil diameter) a corner first, then the worst value in the
    check's sense."""
    m = np.asarray(margin, dtype=float)
    tied = np.nonzero(m <= m.min() + 1e-12 * max(1.0, abs(float(m.min()))))[0] \
        if np.isfinite(m.min()) else np.array([int(np.argmin(m))])
    sign = -1.0 if sense == "<=" else 1.0
    key = [(found_by[i] != "corner", sign * np.nan_to_num(value[i]), i) for i in tied]
    return int(min(key)[2])


def speed_band(spec: Spec, frame) -> dict:
    """The equilibrium speed over the configurations (Hamabe eq. 12 by virtual work,
    :func:`govopt.analysis.statics.omega_squared`): its least and largest over the designs of
    ``frame`` (the points of the box evaluated, each at the fitter's setting): the speed band
    the tolerances give, rad/s, against the configuration (the type's unit)."""
    from ..analysis import statics

    x = statics.configurations(spec)
    gov = spec.governor
    keys = (("m", f"{gov.mass_key}_mass_kg"), ("kappa", "stiffness_N_per_m"),
            ("l0", f"{gov.free_length_key}_m"), ("central", "central_mass_kg"))
    # a dead-weight governor's frame has no spring columns: no spring
    col = {k: (frame[c].to_numpy(dtype=float) if c in frame else np.zeros(len(frame)))[:, None]
           for k, c in keys}
    with np.errstate(invalid="ignore"):
        w = np.sqrt(statics.omega_squared(spec, x[None, :], col["m"], col["kappa"], col["l0"],
                                          np.nan_to_num(col["central"])))
    unit = "rad" if spec.governor.coordinate == "angle" else "m"
    return {f"configuration_{unit}": x.tolist(), "lowest_rad_s": np.nanmin(w, axis=0).tolist(),
            "highest_rad_s": np.nanmax(w, axis=0).tolist()}


# ---------------------------------------------------------------------------------------------
# The worst case over the box: corners where a check is monotone, an inner maximisation where not
# ---------------------------------------------------------------------------------------------

#: the points probed along each edge of the box, in half-widths (the ends are its corners)
EDGE_POINTS = (-1.0, -0.5, 0.0, 0.5, 1.0)
#: a check's margin that turns back along an edge by more than this is not monotone there
#: (below it: the evaluator's rounding)
MONOTONE_TOL = 1e-9
#: the inner maximisation (:func:`inner_minimum`): its step of the finite-difference gradient
#: (half-widths) and its iterations
INNER_STEP = 1e-4
INNER_ITERATIONS = 12


def dimensions(box: Box) -> list[str]:
    """The box's toleranced quantities (design columns, then ``torque_slope``)."""
    return box.active() + (["torque_slope"] if box.torque > 0 else [])


def at_points(spec: Spec, req: Requirements, cols: dict, box: Box, points):
    """One design (columns of length 1) made at ``points`` of its box (P x dims, each in
    half-widths, -1 .. 1) and set by the fitter: at each point the first setting of
    :func:`nut_settings` (least change first) at which every robust check holds, else the one
    with the largest least margin (the point fails whatever the fitter does). Returns the
    evaluated frame (P rows, each at its setting), its :func:`check_margins` and the settings'
    indices."""
    points = np.atleast_2d(np.asarray(points, dtype=float))
    names = box.active()
    nut, valve = nut_settings(req)
    p, s = (a.ravel() for a in np.meshgrid(np.arange(len(points)), np.arange(nut.size),
                                           indexing="ij"))
    rows = {f: np.repeat(v[:1], p.size) for f, v in cols.items()}
    for j, name in enumerate(names):
        rows[name] = rows[name] + points[p, j] * box.fields[name][0]
    rows["free_half_length"] = rows["free_half_length"] + nut[s]
    rows["dashpot"] = rows["dashpot"] * valve[s]
    torque = points[p, -1] * box.torque if box.torque > 0 else np.zeros(p.size)
    frame = _evaluate(spec, req, rows, torque)
    margins = check_margins(frame)
    if nut.size == 1:
        return frame, margins, np.zeros(len(points), int)
    least = margins.min(axis=1, initial=np.inf).reshape(len(points), nut.size)
    ok = least >= PASS_TOL
    use = np.where(ok.any(axis=1), np.argmax(ok, axis=1), np.argmax(least, axis=1))
    pick = np.arange(len(points)) * nut.size + use
    return frame.iloc[pick].reset_index(drop=True), margins[pick], use


def edges(k: int) -> tuple[np.ndarray, np.ndarray]:
    """Every edge of a k-dimensional box of half-widths, probed at :data:`EDGE_POINTS`:
    ``(points, dim)``, points (edges x len(EDGE_POINTS) x k) and the dimension each edge runs
    along."""
    out, dim = [], []
    t = np.asarray(EDGE_POINTS)
    for j in range(k):
        for rest in itertools.product((-1.0, 1.0), repeat=k - 1):
            p = np.repeat(np.insert(np.array(rest), j, 0.0)[None, :], t.size, axis=0)
            p[:, j] = t
            out.append(p)
            dim.append(j)
    return np.array(out).reshape(-1, t.size, k), np.array(dim, dtype=int)


def monotone(values, tol: float = MONOTONE_TOL) -> np.ndarray:
    """Whether each row of ``values`` (along an edge) is monotone, either way, within ``tol``;
    a row with a NaN (the check does not apply there) counts as monotone.

    >>> monotone(np.array([[0, 1, 2.0], [2, 1, 0.0], [1, 0, 1.0], [0, 0, 0.0]])).tolist()
    [True, True, False, True]
    """
    d = np.diff(np.asarray(values, dtype=float), axis=1)
    with np.errstate(invalid="ignore"):
        up, down = np.all(~(d < -tol), axis=1), np.all(~(d > tol), axis=1)
    return up | down


class Failed(Exception):
    """Raised by a search's function to stop it at the first failing point."""


def inner_minimum(fun, start, step: float = INNER_STEP, iterations: int = INNER_ITERATIONS):
    """A least of ``fun`` over the box ``[-1, 1]^q`` near ``start`` by a bounded quasi-Newton
    search (L-BFGS-B, scipy.optimize.minimize); ``fun(points)`` evaluates P x q points at once
    and returns their values (the forward-difference gradient is one call: the point and its q
    neighbours, stepped inwards at a bound; +-inf, a check that does not apply or an error, is
    clipped to +-1e3). Returns the point found and its value."""
    from scipy.optimize import minimize

    def value_and_gradient(t):
        h = np.where(t + step <= 1.0, step, -step)
        v = np.asarray(fun(np.vstack([t, t + np.diag(h)])), dtype=float)
        v = np.clip(np.nan_to_num(v, posinf=1e3, neginf=-1e3), -1e3, 1e3)
        return float(v[0]), (v[1:] - v[0]) / h

    r = minimize(value_and_gradient, np.clip(np.asarray(start, dtype=float), -1.0, 1.0),
                 jac=True, method="L-BFGS-B", bounds=[(-1.0, 1.0)] * len(start),
                 options={"maxiter": iterations})
    return r.x, float(r.fun)


def worst_case(spec: Spec, req: Requirements, cols: dict, box: Box,
               stop_on_failure: bool = False, inner: bool = True) -> dict:
    """The worst case of one design (columns of length 1) over its box, after the fitter's
    adjustment.

    The box is probed along every edge (:func:`edges`, the corners included). A check whose
    margin is monotone along every edge in every tolerance has its worst case at a corner. A
    check that is not monotone in some tolerances is minimised over those (an inner
    maximisation of its violation, :func:`inner_minimum`), from its worst probed point, the
    tolerances it is monotone in held at that point's faces. ``stop_on_failure``: return at the
    first point where a check fails (a search's candidate is then rejected); not ``inner``: the
    edges only (a design for a yield, which fails somewhere in its box: where, on its edges).

    Returns ``dims``; every evaluated ``points`` (half-widths; the first, 0, nominal parts) with
    its ``frame`` row (at the fitter's setting), ``margins`` (:func:`check_margins`),
    ``setting`` index and ``found_by`` ("nominal", "corner", "edge", "inner maximisation");
    per check the tolerances it is not monotone in (``not_monotone``); and ``holds``: every
    robust check holds at every point."""
    import pandas as pd

    dims = dimensions(box)
    k = len(dims)
    grid, along = edges(k) if k else (np.zeros((0, len(EDGE_POINTS), 0)), np.zeros(0, int))
    flat = np.vstack([np.zeros((1, k)), grid.reshape(grid.shape[0] * grid.shape[1], k)])
    # (nominal parts first)
    frame, margins, setting = at_points(spec, req, cols, box, flat)
    corner = np.all(np.abs(flat[1:]) == 1.0, axis=1)
    seen = {"points": [flat], "frame": [frame], "margins": [margins], "setting": [setting],
            "found_by": ["nominal"] + ["corner" if c else "edge" for c in corner]}
    flat, margins = flat[1:], margins[1:]  # the edges

    def result(ok: bool) -> dict:
        return {"dims": dims, "points": np.vstack(seen["points"]),
                "frame": pd.concat(seen["frame"], ignore_index=True),
                "margins": np.vstack(seen["margins"]),
                "setting": np.concatenate(seen["setting"]), "found_by": seen["found_by"],
                "not_monotone": not_monotone, "holds": ok}

    not_monotone: dict[str, list[str]] = {}
    ok = bool(np.all(seen["margins"][0] >= PASS_TOL))  # nominal parts and the edges
    if k == 0 or (stop_on_failure and not ok) or not inner:
        return result(ok)
    names = robust_checks(frame)
    for c, name in enumerate(names):
        bad = ~monotone(np.where(np.isfinite(margins[:, c]), margins[:, c],
                                 np.nan).reshape(grid.shape[:2]))
        if not bad.any():
            continue
        free = sorted(set(along[bad].tolist()))
        not_monotone[name] = [dims[j] for j in free]
        base = flat[int(np.argmin(margins[:, c]))].copy()

        def fun(sub, c=c, base=base, free=free):
            pts = np.repeat(base[None, :], len(sub), axis=0)
            pts[:, free] = sub
            f, m, s = at_points(spec, req, cols, box, pts)
            for key, v in (("points", pts), ("frame", f), ("margins", m), ("setting", s)):
                seen[key].append(v)
            seen["found_by"] += ["inner maximisation"] * len(pts)
            if stop_on_failure and np.any(m < PASS_TOL):
                raise Failed
            return m[:, c]

        try:
            inner_minimum(fun, base[free])
        except Failed:
            return result(False)
    return result(bool(np.all(np.vstack(seen["margins"]) >= PASS_TOL)))
