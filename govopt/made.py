"""Made governors: the yield of a design built to its tolerances, beside the verdict.

A governor is made to the tolerances the spec states (the tolerance model,
:mod:`govopt.analysis.tolerance`: its spring to an EN 15800 grade with the wire after EN 10270,
its masses and dash-pot as ``[requirements]`` spread them) and set by the fitter where the spec
has one (``requirements.adjusting_nut``, ``dashpot_valve``: a governor that fails as made is
tried at the fitter's settings, least change first, and holds if one of them makes every
requirement hold). Its **yield** is the probability that a made governor meets every
requirement (every check but the search bounds'): estimated from :data:`SAMPLES` governors
drawn from the model's scatter at the points of a Latin hypercube (McKay, Beckman and Conover
1979, :func:`govopt.stats.unit_cube`), seeded by ``requirements.robust_seed`` (default 0) - the
same points as ``govopt study run --tolerance grade=N --samples N --seed S`` draws - through the
vectorised evaluator (:func:`govopt.bulk.evaluate_many`), with its 95 % Wilson interval
(:func:`govopt.stats.wilson`; conservative for a Latin hypercube, whose estimate varies less than
independent draws') and the requirement that fails most often. Beside it, the worst case of the
speeds over the tolerance box (:func:`govopt.analysis.tolerance.speed_band`, exact) and the
required band.

The work is counted at its estimated cost (:func:`row_seconds`): a spec whose evaluations are
dear (a forced vibration, friction strokes, design by design) gets fewer samples, at most
:data:`govopt.limits.MAX_YIELD_SECONDS` of them, and the record says how many.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from . import limits
from .analysis import tolerance as tm
from .requirements import PASS_TOL
from .stats import unit_cube, wilson

#: governors sampled for the yield beside the verdict (fewer where each costs more:
#: :func:`sample_count`); its 95 % interval is then +-3.5 % at a yield of 80 %. Where the spec
#: asks for a yield (``requirements.min_yield``), ``requirements.robust_samples`` (default
#: 2000), as the design search certifies it
SAMPLES = 500
#: the fewest samples the yield is given from (past the limit of work: none, and a note)
MIN_SAMPLES = 50
#: the torque slope's levels in a sample (the slope is a spec value, not a design column: each
#: level is one bulk evaluation)
TORQUE_LEVELS = 11
#: the failing samples are adjusted by the fitter in this many groups of settings, least change
#: first (a sample fixed by a small change is not tried at the others)
ADJUSTMENT_GROUPS = 3
#: the least yield where the spec asks for none (``requirements.min_yield``): a spring
#: governor's verdict is PASS where the 95 % Wilson lower bound of its made-and-set yield is at
#: least this (``requirements.verdict = "made"``, the default)
DEFAULT_MIN_YIELD = 0.95
#: the EN 15800 quality grade a spring is made to where the spec states none (neither a wire
#: grade's ``tolerance_grade`` nor ``robust_spring_grade``): grade 2, the standard's middle
#: grade (grade 1 is the finest and dearest)
DEFAULT_GRADE = 2
#: the search bounds' rows (limits of the catalogue search, not requirements of a made part)
BOUND_NAMES = ("mass >= min", "mass <= max", "wire diameter >= min", "wire diameter <= max",
               "coil radius >= min", "coil radius <= max", "active turns >= min",
               "active turns <= max", "leaf width", "leaf thickness")


# ---------------------------------------------------------------------------------------------
# Whose verdict: the made governor's
# ---------------------------------------------------------------------------------------------

def judged_as_made(spec) -> bool:
    """Whether ``spec``'s verdict is the made governor's: a helical spring of a material (its
    EN 15800 tolerances follow from its section) and ``requirements.verdict = "made"`` (the
    default; ``"nominal"`` or ``--nominal``: the nominal design's checks alone)."""
    req, mat = spec.requirements, spec.material
    return (tm.kind(spec) is not None and mat is not None and mat.shear_modulus is not None
            and spec.verdict == "made" and (req is None or req.verdict == "made"))


def made_requirements(spec):
    """The requirements a made governor of ``spec`` is judged by: the spec's, with the made
    verdict's defaults where it states none (:func:`judged_as_made`): the spring made to EN
    15800 grade :data:`DEFAULT_GRADE`, the yield at least :data:`DEFAULT_MIN_YIELD`. The
    spec's own requirements where its verdict is nominal (None without any)."""
    from .inputs import Requirements

    req = spec.requirements
    if not judged_as_made(spec):
        return req
    req = Requirements() if req is None else req
    changes = {}
    if tm.spring_grade(spec, req) is None:
        changes["robust_spring_grade"] = DEFAULT_GRADE
    if req.min_yield is None:  # not asked: as many samples as the work allows
        changes["min_yield"] = DEFAULT_MIN_YIELD
        afford = int(limits.MAX_MONTE_CARLO_SECONDS / 2 / row_seconds(spec))
        changes["robust_samples"] = max(min(req.robust_samples, afford), MIN_SAMPLES)
    return replace(req, **changes) if changes else req


def as_made(spec):
    """``spec`` with :func:`made_requirements` (what ``govopt design`` designs for); a spec
    that asks for a design over its tolerance box already (``robust_*``, ``min_yield``:
    :mod:`govopt.optimize.robust`) as it is (a design every check holds for over the whole box
    has a yield of 1)."""
    if spec.requirements is not None and spec.requirements.robust:
        return spec
    req = made_requirements(spec)
    return spec if req is spec.requirements else replace(spec, requirements=req)


def fitter_sets(spec) -> tuple:
    """The settings the fitter makes on each made governor of ``spec``
    (:meth:`govopt.governors.base.Governor.adjustments`), none where
    ``requirements.fitter = "none"``."""
    req = spec.requirements
    if req is not None and req.fitter == "none":
        return ()
    return spec.governor.adjustments()


def set_by_the_fitter(spec, rows: dict, cols: dict, i: int = 0) -> dict:
    """The made governors ``rows`` (design columns) as the fitter sets them
    (:func:`fitter_sets`): each setting brings the equilibrium speed at its end of the range to
    the speed of design ``i`` of ``cols`` there. The speed squared is affine in the spring's
    free length (virtual work, ``omega^2 = (kappa (A - B l0) + C_f) / (J'/2 - C_i)``,
    :meth:`govopt.governors.base.Terms.omega_squared`), so the setting is the closed form
    ``l0 = (A + (C_f - omega*^2 (J'/2 - C_i)) / kappa) / B`` at that end."""
    from .analysis import statics
    from .evaluator import springs_of

    out = dict(rows)
    for adj in fitter_sets(spec):
        if adj.field != "free_half_length":
            continue
        x = statics.configurations(spec)
        end = x[:1] if adj.end == "inner" else x[-1:]
        one = {k: np.asarray(v, dtype=float)[i:i + 1] for k, v in cols.items()}
        kappa0, l00 = springs_of(spec, one)
        t0 = statics.terms(spec, end, one["flying_mass"][:, None],
                           np.nan_to_num(one["central_mass"])[:, None])
        target = t0.omega_squared(kappa0[:, None], l00[:, None])
        kappa, _ = springs_of(spec, out)
        t = statics.terms(spec, end, out["flying_mass"][:, None],
                          np.nan_to_num(out["central_mass"])[:, None])
        with np.errstate(all="ignore"):
            l0 = (t.A + (t.cf - target * t.lever) / kappa[:, None]) / t.B
        out["free_half_length"] = np.broadcast_to(l0, (len(kappa), 1))[:, 0].copy()
    return out


# ---------------------------------------------------------------------------------------------
# Which rows of a bulk frame hold
# ---------------------------------------------------------------------------------------------

class Evaluated:
    """Made governors evaluated, as arrays (no pandas frame: :func:`evaluate_arrays`): the
    requirements' ``names`` (every check but the search bounds'), their relative ``margins``
    (rows x names, as :func:`check_margins` reads a bulk frame), the rows that are ``error``
    (impossible designs) and the evaluator's per-row ``figures`` (SI)."""

    def __init__(self, names: list[str], margins: np.ndarray, error: np.ndarray,
                 figures: dict):
        self.names, self.margins, self.error, self.figures = names, margins, error, figures

    def __len__(self) -> int:
        return len(self.error)

    def take(self, rows) -> Evaluated:
        """Some of the rows (an index array or a mask)."""
        return Evaluated(self.names, self.margins[rows], self.error[rows],
                         {k: np.asarray(v)[rows] for k, v in self.figures.items()})

    @staticmethod
    def concat(parts: list[Evaluated]) -> Evaluated:
        """The rows of ``parts`` in order (a requirement a part lacks does not apply there)."""
        names = list(dict.fromkeys(n for p in parts for n in p.names))
        margins = np.concatenate([np.column_stack(
            [p.margins[:, p.names.index(n)] if n in p.names else np.full(len(p), np.inf)
             for n in names]) if names else np.zeros((len(p), 0)) for p in parts])
        keys = [k for k in parts[0].figures if all(k in p.figures for p in parts)]
        return Evaluated(names, margins, np.concatenate([p.error for p in parts]),
                         {k: np.concatenate([np.asarray(p.figures[k]) for p in parts])
                          for k in keys})


def evaluated(spec, cols: dict, vibration: bool = True) -> Evaluated:
    """The designs ``cols`` through the one evaluator (:func:`govopt.evaluator.core`, the
    classic measures left out), as :class:`Evaluated`."""
    from .evaluator import DESIGN_FIELDS, core

    n = len(cols["flying_mass"])
    cols = {f: np.asarray(cols[f], dtype=float) if f in cols else np.full(n, np.nan)
            for f in DESIGN_FIELDS}
    ev = core(spec, cols, vibration=vibration, classic=False)
    error = ev.impossible
    names = [c for c in ev.table.names if not any(b in c for b in BOUND_NAMES)]
    out = np.empty((ev.n, len(names)))
    columns = ev.table.columns()
    for j, name in enumerate(names):
        c = columns[name]
        m, p = c.margin, c.passed
        m = np.where(~p & ~(m < PASS_TOL), -np.inf, np.where(p, np.maximum(m, PASS_TOL), m))
        out[:, j] = np.where(error, -np.inf, np.where(c.applies, m, np.inf))
    return Evaluated(names, out, error, ev.figures)


def requirement_checks(frame) -> list[str]:
    """The checks of a bulk frame a made governor must meet (all but the search bounds')."""
    if isinstance(frame, Evaluated):  # arrays: no pandas on the yield's path
        return list(frame.names)
    from .bulk import check_names

    return [c for c in check_names(frame.columns) if not any(b in c for b in BOUND_NAMES)]


def check_margins(frame) -> np.ndarray:
    """The requirements' relative margins (rows x :func:`requirement_checks`): -inf on an error
    row and where a check fails by its own verdict at a margin >= 0 (so a row holds exactly
    where every entry is >= :data:`govopt.requirements.PASS_TOL`), +inf where a check does not
    apply."""
    if isinstance(frame, Evaluated):
        return frame.margins
    from .bulk import margin_column, passed_column

    names = requirement_checks(frame)
    out = np.empty((len(frame), len(names)))
    error = (frame["status"] == "error").to_numpy(dtype=bool)
    for j, c in enumerate(names):
        m = frame[margin_column(c)].to_numpy(dtype=float)
        p = frame[passed_column(c)].to_numpy(dtype=float, na_value=np.nan)  # 1, 0, NaN: n/a
        m = np.where((p == 0) & ~(m < PASS_TOL), -np.inf,
                     np.where(p == 1, np.maximum(m, PASS_TOL), m))  # its verdict rules
        m = np.where(np.isnan(p), np.inf, m)
        out[:, j] = np.where(error, -np.inf, m)
    return out


def holds(frame) -> np.ndarray:
    """Rows where every requirement holds (a check that does not apply holds; an error row
    does not)."""
    error = _error(frame)
    return ~error & np.all(check_margins(frame) >= PASS_TOL, axis=1)


def _error(frame) -> np.ndarray:
    """The rows of a bulk frame (or :class:`Evaluated`) that are impossible designs."""
    if isinstance(frame, Evaluated):
        return frame.error
    return (frame["status"] == "error").to_numpy(dtype=bool)


def failing(frame) -> dict[str, int]:
    """Per requirement, in how many rows of ``frame`` it fails (an error row: ``"no
    equilibrium or impossible design"``), most first."""
    if len(frame) == 0:
        return {}
    bad = check_margins(frame) < PASS_TOL
    error = _error(frame)
    counts = {c: int(k) for c, k in zip(requirement_checks(frame), bad[~error].sum(axis=0),
                                         strict=True) if k}
    if error.any():
        counts["impossible design (no equilibrium, or a figure not finite)"] = int(error.sum())
    return dict(sorted(counts.items(), key=lambda kv: -kv[1]))


# ---------------------------------------------------------------------------------------------
# Work
# ---------------------------------------------------------------------------------------------

def row_seconds(spec, vibration: bool = True) -> float:
    """Estimated CPU seconds of one design's evaluation in a bulk frame of ``spec``
    (:func:`govopt.limits.evaluation_seconds`): the parts that run design by design where the
    evaluator runs them (:func:`govopt.evaluator.core`; ``vibration``: the forced vibration is
    asked for)."""
    from .analysis import statics
    from .evaluator import overridden

    gov = spec.governor
    leaf = gov.spring is not None and overridden(gov, "spring_checks")
    wire = gov.spring is not None and not leaf and (
        spec.material is not None and getattr(spec.material, "grade", None) is not None)
    vib = (vibration or leaf or wire) and overridden(gov, "vibration")
    friction = 0
    if spec.engine is not None and spec.load_changes:
        to = np.array([lc.alpha_to for lc in spec.load_changes])
        friction = int(np.count_nonzero(np.asarray(gov.friction(to)) > 0))
    return limits.evaluation_seconds(statics.configurations(spec).size, vibration=vib,
                                     spring_checks=leaf, wire_checks=wire,
                                     friction_runs=friction)


def sample_count(spec, req=None) -> int:
    """How many governors the yield samples: :data:`SAMPLES` (``requirements.robust_samples``
    where the spec asks for a yield), fewer where they would cost more than
    :data:`govopt.limits.MAX_YIELD_SECONDS` (half of
    :data:`govopt.limits.MAX_MONTE_CARLO_SECONDS` where it asks for a yield) at
    :func:`row_seconds` each; 0 where fewer than :data:`MIN_SAMPLES` fit."""
    req = made_requirements(spec) if req is None else req
    asked = req is not None and req.min_yield is not None
    n, budget = ((req.robust_samples, limits.MAX_MONTE_CARLO_SECONDS / 2) if asked
                 else (SAMPLES, limits.MAX_YIELD_SECONDS))
    n = min(n, int(budget / row_seconds(spec)))
    return n if n >= MIN_SAMPLES else 0


def _by_torque_level(spec, cols: dict, torque, vibration: bool):
    """The rows of design columns ``cols`` grouped by their relative torque-slope change
    ``torque`` (None: the spec's), the running work charged first: per level, the spec at that
    slope, its rows' columns and their indices."""
    n = len(cols["flying_mass"])
    torque = np.zeros(n) if torque is None else np.asarray(torque, dtype=float)
    limits.charge(n * row_seconds(spec, vibration), n)
    for level in np.unique(torque):
        sel = np.nonzero(torque == level)[0]
        s = spec if level == 0 else replace(spec, engine=replace(
            spec.engine, torque_slope=spec.engine.torque_slope * (1.0 + level)))
        yield s, {k: np.asarray(v, dtype=float)[sel] for k, v in cols.items()}, sel


def evaluate_at(spec, cols: dict, torque=None, vibration: bool = True):
    """The bulk frame of design columns ``cols``, each row at its relative torque-slope change
    ``torque`` (a few levels, one evaluation each; None: the spec's), rows in order; the running
    :class:`govopt.limits.Work` (:func:`govopt.limits.counting`) is charged first."""
    import pandas as pd

    from .bulk import evaluate_many

    frames, index = [], []
    for s, part, sel in _by_torque_level(spec, cols, torque, vibration):
        frames.append(evaluate_many(s, part, vibration=vibration, classic=False))
        index.append(sel)
    frame = pd.concat(frames, ignore_index=True)
    return frame.iloc[np.argsort(np.concatenate(index), kind="stable")].reset_index(drop=True)


def evaluate_arrays(spec, cols: dict, torque=None, vibration: bool = True) -> Evaluated:
    """:func:`evaluate_at` as arrays (:class:`Evaluated`, no pandas frame): the rows in
    order, the running work charged first."""
    parts, index = [], []
    for s, part, sel in _by_torque_level(spec, cols, torque, vibration):
        parts.append(evaluated(s, part, vibration))
        index.append(sel)
    return Evaluated.concat(parts).take(np.argsort(np.concatenate(index), kind="stable"))


# ---------------------------------------------------------------------------------------------
# Samples of made governors
# ---------------------------------------------------------------------------------------------

def draw(cols: dict, bx: tm.Box, n: int, seed: int, i: int = 0):
    """``n`` governors made from design ``i`` of ``cols`` within its box ``bx``: design columns
    and each one's relative torque-slope change (at :data:`TORQUE_LEVELS` levels), at the
    points of a seeded Latin hypercube (:func:`govopt.stats.unit_cube`) through the model's
    scatter (:func:`govopt.analysis.tolerance.offsets`)."""
    dims = bx.dims()
    z = tm.offsets(unit_cube("lhs", n, len(dims), seed)) if dims else np.zeros((n, 0))
    rows = tm.at(cols, bx, z[:, :len(bx.active())], i)
    torque = np.zeros(n)
    if bx.torque > 0:
        levels = np.linspace(-1.0, 1.0, TORQUE_LEVELS)
        torque = bx.torque * levels[np.abs(z[:, -1:] - levels).argmin(axis=1)]
    return rows, torque


def fit(spec, rows: dict, torque, ok: np.ndarray, nut: float, valve: float,
        vibration: bool = True, evaluate=None, frame=None):
    """The fitter's adjustment of the made governors ``rows`` that fail (``~ok``): each tried at
    the settings of the adjusting nut (``+-nut``, m) and the dash-pot valve (``+-valve``) in
    :data:`ADJUSTMENT_GROUPS` groups, least change first, holding if some setting makes every
    requirement hold. Returns ``(ok, adjusted, not tried)``: the governors that hold after it,
    how many the fitter's setting made hold, and how many failing ones were not tried at every
    setting because the running work reached its limit (they count as failing). With
    ``frame`` (the governors' evaluated rows) also that frame with each adjusted governor's row
    as set (the first setting, least change first, at which it holds). ``evaluate(rows,
    torque)``: the evaluation (default :func:`evaluate_at`)."""
    if evaluate is None:
        def evaluate(r, t):
            return evaluate_at(spec, r, t, vibration)
    ok = ok.copy()
    nuts, valves = (x[1:] for x in tm.fitter_settings(nut, valve))
    adjusted, stopped, set_rows = 0, 0, {}
    torque = np.zeros(len(ok)) if torque is None else np.asarray(torque)
    for part in [p for p in np.array_split(np.arange(nuts.size), ADJUSTMENT_GROUPS) if p.size]:
        bad = np.nonzero(~ok)[0]
        if bad.size == 0:
            break
        rep = {k: np.repeat(v[bad], part.size) for k, v in rows.items()}
        rep["free_half_length"] = rep["free_half_length"] + np.tile(nuts[part], bad.size)
        rep["dashpot"] = rep["dashpot"] * np.tile(valves[part], bad.size)
        try:
            got = evaluate(rep, np.repeat(torque[bad], part.size))
        except limits.WorkLimit:
            stopped = int(bad.size)
            break
        good = holds(got).reshape(bad.size, part.size)
        fixed = good.any(axis=1)
        if frame is not None:
            first = np.argmax(good, axis=1)
            for i in np.nonzero(fixed)[0]:
                set_rows[int(bad[i])] = got.iloc[[i * part.size + int(first[i])]]
        ok[bad] = fixed
        adjusted += int(fixed.sum())
    if frame is None:
        return ok, adjusted, stopped
    if set_rows:  # the adjusted governors' rows as set
        import pandas as pd

        idx = sorted(set_rows)
        new = pd.concat([set_rows[i] for i in idx], ignore_index=True)
        new.index = idx
        frame = pd.concat([frame.drop(index=idx), new]).sort_index()
    return ok, adjusted, stopped, frame


def resolved_columns(spec, res) -> dict:
    """The design columns of a result's design (:func:`govopt.bulk.design_arrays`) with the
    spring's free length as evaluated: a made spring's free length is a number (where the design
    leaves it out, the one that holds the normal configuration at the mean speed)."""
    from .bulk import design_arrays

    cols = design_arrays(spec.with_design(res.design), [res.design])
    if spec.governor.spring is not None and not np.isfinite(cols["free_half_length"][0]):
        cols["free_half_length"] = np.array([float(res.spring.l0)])
    return cols


def fitter_of(req) -> tuple[float, float]:
    """The fitter's ranges the requirements declare: ``(adjusting nut (m), dash-pot valve)``."""
    return (0.0, 0.0) if req is None else (req.adjusting_nut, req.dashpot_valve)


def made_yield(spec, cols: dict, bx: tm.Box, n: int, seed: int,
               fitter: tuple[float, float] = (0.0, 0.0), blocks=None, give_up=None) -> dict:
    """The yield of design 0 of ``cols`` made within ``bx``: ``n`` governors (:func:`draw`),
    evaluated and, where the spec has a fitter, adjusted (:func:`fit`): the probability that
    every requirement holds with its 95 % Wilson interval, the requirements that fail (as made)
    and the sampled speeds' range. A sample the fitter could not try at every setting within the
    running work's limit counts as failing (then the probability is a lower bound, and a note
    says so).

    ``blocks``: the samples are evaluated in blocks of these sizes (the last repeated; None: at
    once), and after each block ``give_up(failures, samples so far)`` may stop them (the record
    then says how many were evaluated, ``samples``, of ``of``)."""
    rows, torque = draw(cols, bx, n, seed)
    rows = set_by_the_fitter(spec, rows, cols)
    nut = fitter[0] if spec.governor.spring is not None else 0.0
    frames, oks, adjusted, stopped, start, b = [], [], 0, 0, 0, 0
    while start < n:
        size = n if not blocks else blocks[min(b, len(blocks) - 1)]
        sel = np.arange(start, min(n, start + size))
        start, b = int(sel[-1]) + 1, b + 1
        part = {k: v[sel] for k, v in rows.items()}
        frame = evaluate_arrays(spec, part, torque[sel])
        ok = holds(frame)
        if nut > 0 or fitter[1] > 0:
            ok, a, s_ = fit(spec, part, torque[sel], ok, nut, fitter[1],
                            evaluate=lambda r, t: evaluate_arrays(spec, r, t))
            adjusted, stopped = adjusted + a, stopped + s_
        frames.append(frame)
        oks.append(ok)
        if give_up is not None and give_up(int(sum((~o).sum() for o in oks)), start):
            break
    frame, ok = Evaluated.concat(frames), np.concatenate(oks)
    done, k = len(ok), int(ok.sum())
    lo, hi = wilson(k, done)
    fails = failing(frame.take(np.nonzero(~ok)[0]))
    out = {"probability": k / done, "ci95": [lo, hi], "holds": k, "samples": done, "of": n,
           "seed": seed, "sampler": "Latin hypercube", "distribution": tm.DISTRIBUTION,
           "adjusted_by_the_fitter": adjusted, "failing": fails,
           "most_failing": next(iter(fails), None)}
    for end in ("inner", "outer"):
        w = np.asarray(frame.figures[f"omega_{end}_rad_s"], dtype=float)
        w = w[np.isfinite(w) & ~frame.error]
        out[f"sampled_{end}_rad_s"] = [float(w.min()), float(w.max())] if w.size else None
    if stopped:
        out["note"] = (f"the fitter's adjustment stopped at govopt's limit of work: {stopped} "
                       "failing samples were not tried at every setting and count as failing, "
                       "so the probability is a lower bound")
    return out


def record(spec, cols: dict, bx: tm.Box, n: int, seed: int, fitter=(0.0, 0.0),
           min_yield: float | None = None, certified: bool = False,
           spreads: tuple[float, float] = (0.0, 0.0), sampled: dict | None = None) -> dict:
    """The made governors' record of design 0 of ``cols``: the tolerances (``spreads``: the
    masses' and the dash-pot's fractions), the yield (:func:`made_yield`, or ``sampled`` where
    it was found already; 1 without samples where the worst case over the box holds,
    ``certified``) and the worst-case speed band beside the required one, SI."""
    nut, valve = fitter
    masses, dashpot = spreads
    tol = {"spring_grade": bx.grade, "wire_standard": tm.wire_standard(spec)
           if bx.grade is not None else None,
           "half_widths": bx.half_widths(spec), "masses_fraction": masses,
           "dashpot_fraction": dashpot, "torque_slope_fraction": bx.torque,
           "adjusting_nut_m": nut, "dashpot_valve_fraction": valve,
           "distribution": tm.DISTRIBUTION, "notes": list(bx.notes),
           "set_by_the_fitter": [f"{a.what}, bringing the speed at the {a.end} end to the "
                                 f"design's ({a.cite})" for a in fitter_sets(spec)]}
    band = tm.speed_band(spec, cols, bx)  # as made (before any fitter's setting)
    sp = spec.speed
    band["required_rad_s"] = [sp.omega_inner, sp.omega_outer] if sp is not None and sp.band \
        else None
    band["as_made"] = True
    if certified:
        y = {"probability": 1.0, "ci95": [1.0, 1.0], "holds": None, "samples": 0, "seed": seed,
             "certified": "every requirement holds over the whole box (worst case)",
             "failing": {}, "most_failing": None}
    elif n == 0:
        y = {"probability": None, "ci95": None, "samples": 0, "seed": seed, "failing": {},
             "most_failing": None,
             "note": f"each governor's evaluation costs ~{row_seconds(spec) * 1e3:.2g} ms "
                     f"here: fewer than {MIN_SAMPLES} fit govopt's limit of "
                     f"{limits.MAX_YIELD_SECONDS:g} s for the yield"}
    elif sampled is not None:
        y = sampled | {"certified": None}
    else:
        with limits.counting(limits.Work(limits.MAX_MONTE_CARLO_SECONDS)):
            y = made_yield(spec, cols, bx, n, seed, fitter) | {"certified": None}
    if min_yield is not None:
        y["required"] = min_yield
        y["meets_required"] = None if y["ci95"] is None else bool(y["ci95"][0] >= min_yield)
    return {"tolerances": tol, "yield": y, "speed_band": band}


def stated_record(spec, res) -> dict | None:
    """The made governors' record of a result (:func:`record`) for the tolerances its spec
    states (:func:`govopt.analysis.tolerance.states_tolerances`), else None."""
    req = made_requirements(spec)
    if not tm.states_tolerances(spec, req):
        return None
    cols = resolved_columns(spec, res)
    bx = tm.stated(spec, cols, req).known()
    if not bx.dims():
        return None
    seed = 0 if req is None else req.robust_seed
    return record(spec, cols, bx, sample_count(spec, req), seed, fitter_of(req),
                  None if req is None else req.min_yield, spreads=spreads_of(req))


def spreads_of(req) -> tuple[float, float]:
    """The masses' and the dash-pot's spreads the requirements state (fractions)."""
    return (0.0, 0.0) if req is None else (req.robust_masses, req.robust_dashpot)


def _required(res):
    """``res`` whose made record (a robust design's) states the required yield where the
    verdict is the made governor's (:func:`made_requirements`)."""
    y = res.made["yield"]
    if y.get("required") is not None or not judged_as_made(res.spec):
        return res
    need = made_requirements(res.spec).min_yield
    y = {**y, "required": need,
         "meets_required": None if y["ci95"] is None else bool(y["ci95"][0] >= need)}
    return replace(res, made={**res.made, "yield": y})


def with_yield(res):
    """``res`` with its made governors' record (``Result.made``: the yield beside the verdict),
    where its spec states tolerances and the record is not there yet."""
    if res.made is not None:
        return _required(res)
    made = stated_record(res.spec, res)
    return res if made is None else replace(res, made=made)


__all__ = ["BOUND_NAMES", "SAMPLES", "check_margins", "draw", "evaluate_at", "failing", "fit",
           "holds", "made_yield", "record", "requirement_checks", "row_seconds",
           "sample_count", "stated_record", "with_yield"]
