"""The windows a design search works in: for each pendulum (and central) mass, the interval of
spring stiffness the statics requirements admit (:mod:`govopt.optimize.kappa`), and for each
candidate the range of dash-pot settings the load-change requirements admit (Hamabe's eq. (32),
no over-regulation, settling, vibration); the statics of dead-weight governors at every weight
pair. The searches of :mod:`govopt.optimize.design` and :mod:`govopt.optimize.robust` read them;
:mod:`govopt.optimize.diagnosis` re-runs them with a requirement relaxed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import limits
from ..analysis import loadchange, statics
from ..analysis.over_regulation import OVER_TOL, over_regulates
from ..analysis.transient_cubic import hamabe_initial_conditions
from ..analysis.transient_events import analyse_many
from ..spec import Requirements, Spec
from .kappa import KappaModel
from .margins import window_centre

#: Dash-pot grid, as multiples of the least damping that meets eq. (32) with its margin.
DASHPOT_FACTORS = np.geomspace(1.0, 200.0, 25)


@dataclass(frozen=True)
class Grid:
    """The analysis configurations, with the indices of the ones the requirements refer to."""

    alpha: np.ndarray
    inner: int
    outer: int
    load_changes: tuple[tuple[int, int], ...]

    @classmethod
    def build(cls, spec: Spec) -> Grid:
        alpha = statics.configurations(spec)
        extra = [a for lc in spec.load_changes for a in (lc.alpha_from, lc.alpha_to)]
        alpha = np.unique(np.concatenate([alpha, extra]))
        idx = [(int(np.searchsorted(alpha, lc.alpha_from)),
                int(np.searchsorted(alpha, lc.alpha_to))) for lc in spec.load_changes]
        return cls(alpha, 0, len(alpha) - 1, tuple(idx))


def requirements(spec: Spec) -> Requirements:
    return spec.requirements or Requirements()


def grid_steps(lo: float, hi: float, step: float) -> np.ndarray:
    if lo == hi:
        return np.array([lo])
    return np.arange(math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9) + 1) * step


def mass_grid(req: Requirements) -> np.ndarray:
    """The flying masses on the catalogue's weight step within the bounds (not zero: a lower
    bound within rounding of it is no flying mass)."""
    m = grid_steps(*req.flying_mass, req.mass_step)
    return m[m > 0]


def masses(req: Requirements) -> tuple[np.ndarray, np.ndarray]:
    """Every (flying mass, central load) pair on the weight-step grid, as two flat arrays."""
    m, c = np.meshgrid(mass_grid(req), grid_steps(*req.central_mass, req.mass_step), indexing="ij")
    return m.ravel(), c.ravel()


def k2_limits(spec: Spec, req: Requirements) -> tuple[float, float]:
    """``k^2``'s limits ``(low, high)``, 1/s^2: the type's rule on the spec's ``k2_margin``
    (:meth:`~govopt.governors.base.Governor.k2_rule`; no ceiling: ``inf``)."""
    w0sq = spec.speed.omega_mean**2
    margin, ceiling = spec.governor.k2_rule(req.k2_margin)
    return margin * w0sq, (1.0 - margin) * w0sq if ceiling else np.inf


#: reference speeds across a stated band at which the normal configuration may be held
BAND_REFERENCES = 9


#: the finer scan where none of the coarse reference speeds admits a spring (a leaf without set
#: holds the band only with its normal configuration in a narrow window of speeds)
BAND_REFERENCES_FINE = 65


def reference_speeds(spec: Spec, count: int = BAND_REFERENCES) -> np.ndarray | None:
    """The speeds (rad/s) at which the design search holds the normal configuration: the mean
    speed only (Hamabe, Example 1: ``[speed] mean/irregularity``), or, where the spec states a
    band ``[speed] inner/outer``, :data:`BAND_REFERENCES` speeds across it, the mean first: the
    band is the requirement, where in it the normal configuration runs is a design choice (the
    free length), and holding it at the mean can rule out every spring (a leaf without set)."""
    sp = spec.speed
    if not sp.band:
        return None
    w = np.linspace(sp.omega_inner, sp.omega_outer, count)
    mid = count // 2
    return np.concatenate([[sp.omega_mean], w[:mid], w[mid + 1:]])


def statics_window(spec: Spec, req: Requirements):
    """Configurations, the kappa-affine model over the weight grid (times the reference speeds
    of :func:`reference_speeds`) and the admissible stiffness interval per row:
    ``(grid, km, lo, hi, parts)`` (see :meth:`KappaModel.statics_interval`)."""
    grid = Grid.build(spec)
    m, c = masses(req)
    for count in (BAND_REFERENCES, BAND_REFERENCES_FINE):
        km, lo, hi, parts = _window_rows(spec, req, grid, m, c, count)
        if km.reference is None or np.any(lo <= hi):
            break
    return grid, km, lo, hi, parts


def _window_rows(spec: Spec, req: Requirements, grid: Grid, m, c, count: int):
    """:func:`statics_window`'s model and intervals for the weight pairs ``m, c`` at ``count``
    reference speeds: ``(km, lo, hi, parts)``, each row on its own."""
    refs = reference_speeds(spec, count) if spec.governor.spring is not None else None
    if refs is not None:  # rows mass-major, the mean speed first (ties keep it)
        m, c, refs = np.repeat(m, refs.size), np.repeat(c, refs.size), np.tile(refs, m.size)
    km = KappaModel.build(spec, m, grid.alpha, c[:, None], refs)
    return km, *km.statics_interval(*k2_limits(spec, req), spec.speed.irregularity,
                                    least=least_range(spec, req))


def least_range(spec: Spec, req: Requirements) -> float:
    """The least range of speed's share of the band
    (:meth:`~govopt.governors.base.Governor.range_rule`; 0 without a band or where none is
    required)."""
    return spec.governor.range_rule(req.min_range) if spec.speed.band else 0.0


def statics_feasible(spec: Spec, req: Requirements, cells: int = 1 << 16) -> bool:
    """Whether :func:`statics_window` admits a stiffness at some weight pair, computed in blocks
    of weight pairs of at most ``cells`` (row, configuration) cells and stopping at the first
    block that does: a diagnosis widening the weight bounds a hundredfold held all their rows
    (weights x reference speeds x configurations) at once (+0.3 GB)."""
    grid = Grid.build(spec)
    m, c = masses(req)
    for count in (BAND_REFERENCES, BAND_REFERENCES_FINE):
        block = max(1, cells // (count * grid.alpha.size))
        for i in range(0, m.size, block):
            km, lo, hi, _ = _window_rows(spec, req, grid, m[i:i + block], c[i:i + block], count)
            if np.any(lo <= hi):
                return True
        if spec.governor.spring is None or reference_speeds(spec, count) is None:
            return False
    return False


# ---------------------------------------------------------------------------------------------
# Dynamics of candidates (vectorised over candidates and dash-pot values)
# ---------------------------------------------------------------------------------------------


def load_change_problem(spec: Spec, km: KappaModel, grid: Grid, rows, kappa):
    """Coefficients ``a0, a2, a3`` and initial state of every load change for candidates
    (mass row ``rows``, stiffness ``kappa``): Hamabe eqs. (27)-(28) and Part III's initial
    conditions, as :func:`govopt.analysis.loadchange.load_change_model` builds them for one
    design. Shapes: (candidates, load changes)."""
    eng = spec.engine
    m = km.m[rows, 0][:, None]
    kappa = np.asarray(kappa)[:, None]
    i1 = np.array([i for i, _ in grid.load_changes])
    i0 = np.array([j for _, j in grid.load_changes])
    inertia = km.inertia[rows][:, i0]
    w2 = km.omega2.x[rows] * kappa + km.omega2.y[rows]
    k2 = km.k2.x[rows] * kappa + km.k2.y[rows]
    omega0 = np.sqrt(np.maximum(w2[:, i0], 0.0))
    omega1 = np.sqrt(np.maximum(w2[:, i1], 0.0)) * (1.0 + eng.insensibility)
    alpha0 = grid.alpha[i0]
    R = -eng.torque_slope * spec.governor.travel_slope(alpha0) / eng.flywheel_inertia
    a0 = inertia + 0.0 * alpha0
    a2 = inertia * k2[:, i0] / 3.0
    a3 = 2.0 * omega0 * loadchange.speed_lever(spec, alpha0, m, km.central[rows]) * R
    xi0 = (grid.alpha[i1] - alpha0) + 0.0 * a0
    x = hamabe_initial_conditions(a0, a2, a3, R, xi0, omega1 - omega0)
    return a0, a2, a3, x


def dashpot_window(spec: Spec, req: Requirements, km: KappaModel, grid: Grid, rows, kappa,
                   factors=DASHPOT_FACTORS, fatigue=None):
    """For each candidate: the dash-pot values on a log grid that meet eq. (32) with its margin,
    give no over-regulation, settle within the limit for every load change and keep the
    vibration bound within its limit; and the best of them (fastest settling, or least
    vibration for that objective; for the mass objectives, which do not depend on it, the
    centre of its admissible window on a log scale,
    :func:`~govopt.optimize.margins.window_centre`). ``fatigue(swing)``: the candidates' least
    spring fatigue safety under peak-to-peak swings (candidates x dash-pots; the vibration
    bound is used, so it errs safe), kept at ``requirements.min_fatigue_safety`` (default 1).
    Returns a dict of arrays over candidates."""
    n = len(rows)
    limits.charge(n * window_seconds(spec, req), n)  # the running search's work, if counted
    nan = np.full(n, np.nan)
    if spec.engine is None or not spec.load_changes:  # no dash-pot is designed
        ok, vib = np.ones(n, bool), nan
        if spec.engine is not None and (req.max_vibration is not None or fatigue is not None
                                        or req.objective == "vibration"):
            # the vibration without a dash-pot, as govopt evaluate finds it
            vib = 2.0 * vibration_bound(spec, km, grid, rows, kappa, np.zeros((n, 1)))[:, 0]
            if req.max_vibration is not None:
                ok &= vib <= req.max_vibration
            if fatigue is not None:
                ok &= fatigue(vib[:, None])[:, 0] >= (req.min_fatigue_safety or 1.0)
        return {"feasible": ok, "f": nan, "settling": nan, "f_lo": nan, "f_hi": nan,
                "vibration": vib, "least": {}}
    a0, a2, a3, (x0, x1, x2) = load_change_problem(spec, km, grid, rows, kappa)
    # least f meeting 9 a1 a2 >= (1 + margin) a0 a3 for all load changes (eq. 32, a1 = f/3)
    with np.errstate(divide="ignore", invalid="ignore"):
        f_min = np.max((1.0 + req.hurwitz_margin) * a0 * a3 / (3.0 * a2), axis=1)
    f_min = np.where(np.all(a2 > 0, axis=1), f_min, np.inf)
    f = f_min[:, None] * factors[None, :]  # (n, F)
    if req.dashpot is not None:
        f = np.clip(f, *req.dashpot)
    s = analyse_many(a0[:, None, :], np.where(np.isfinite(f), f, 1.0)[:, :, None] / 3.0,
                        a2[:, None, :], a3[:, None, :], x0[:, None, :], x1[:, None, :],
                        x2[:, None, :], band=spec.analysis.settling_band)
    # over-regulation at any t >= 0, by the one rule (over_regulation.over_regulates); its measure
    # relative to the load change for the diagnosis
    no_over = np.all(s.stable & ~over_regulates(s.over_regulation_scaled, x0[:, None, :]),
                     axis=2)
    over = np.max(np.where(s.stable, np.nan_to_num(s.over_regulation_scaled, nan=np.inf)
                           / np.abs(x0[:, None, :]), np.inf), axis=2)
    over = np.where(no_over, 0.0, np.maximum(over, np.nextafter(OVER_TOL, 1.0)))
    hurwitz = np.all(s.stable & (s.hurwitz_margin >= req.hurwitz_margin * (1 - 1e-12)), axis=2)
    hurwitz &= np.isfinite(f)
    settle = np.max(np.where(s.stable, s.settling_time, np.inf), axis=2)
    ok = hurwitz & no_over
    # the least each requirement can be brought to, given the ones before it (for diagnoses)
    least = {"over_regulation": np.min(np.where(hurwitz, over, np.inf), axis=1),
             "settling_time": np.min(np.where(ok, settle, np.inf), axis=1)}
    if req.max_settling_time is not None:
        ok = ok & (settle <= req.max_settling_time)
    vib = np.full(f.shape, np.nan)
    if req.max_vibration is not None or req.objective == "vibration" or fatigue is not None:
        vib = 2.0 * vibration_bound(spec, km, grid, rows, kappa, f)
        least["vibration"] = np.min(np.where(ok, vib, np.inf), axis=1)
        if req.max_vibration is not None:
            ok = ok & (vib <= req.max_vibration)
    if fatigue is not None:  # the spring's life under the vibration
        ok = ok & (fatigue(vib) >= (req.min_fatigue_safety or 1.0))
    # the best admissible dash-pot: an infinite score (settling not decided within the time
    # grid's limit, limits.MAX_TRANSIENT_POINTS: a huge flywheel) ranks after every finite one
    # but before every inadmissible one, so the pick is always an admissible dash-pot
    score = np.where(ok, vib if req.objective == "vibration" else settle, np.inf)
    best = np.argmin(np.where(ok, np.minimum(score, np.finfo(float).max), np.inf), axis=1)
    if req.objective in ("moving_mass", "spring_mass"):  # indifferent to the dash-pot: margin
        best = window_centre(f, ok)
    idx = np.arange(n)
    feasible = np.any(ok, axis=1)
    f_ok = np.where(ok, f, np.nan)
    with np.errstate(all="ignore"):
        return {"feasible": feasible, "f": np.where(feasible, f[idx, best], np.nan),
                "least": least,
                "settling": np.where(feasible, settle[idx, best], np.inf),
                "vibration": np.where(feasible, vib[idx, best], np.inf),
                "f_lo": np.nanmin(np.where(feasible[:, None], f_ok, np.inf), axis=1),
                "f_hi": np.nanmax(np.where(feasible[:, None], f_ok, -np.inf), axis=1)}


def window_seconds(spec: Spec, req: Requirements) -> float:
    """Estimated CPU seconds of one candidate's :func:`dashpot_window`
    (:data:`govopt.limits.WINDOW_SECONDS_PER_LOAD_CHANGE` a load change, and the vibration
    bound's harmonics where a requirement reads it); a small floor without load changes."""
    changes = len(spec.load_changes) if spec.engine is not None else 0
    vibration = spec.engine is not None and (req.max_vibration is not None
                                             or req.objective == "vibration")
    return (limits.WINDOW_SECONDS_PER_LOAD_CHANGE * max(changes, 0.05)
            + (limits.WINDOW_SECONDS_PER_HARMONIC * spec.analysis.harmonics
               if vibration else 0.0))


#: candidates a single dash-pot window takes at once at one load change (its transients' arrays
#: grow with candidates x dash-pot settings x load changes: at most ~10^5 transients at once)
WINDOW_ROWS = 4096


def batched_windows(spec: Spec, req: Requirements, km: KappaModel, grid: Grid, rows, kappa) -> dict:
    """:func:`dashpot_window` of many candidates, in blocks of at most :data:`WINDOW_ROWS`
    over the load changes (memory bounded): the arrays of the blocks joined."""
    block = max(1, WINDOW_ROWS // max(len(spec.load_changes), 1))
    parts = [dashpot_window(spec, req, km, grid, rows[i:i + block], kappa[i:i + block])
             for i in range(0, len(rows), block)] or [
        dashpot_window(spec, req, km, grid, rows, kappa)]
    out = {k: np.concatenate([p[k] for p in parts]) for k in parts[0] if k != "least"}
    out["least"] = {k: np.concatenate([p["least"][k] for p in parts])
                    for k in parts[0]["least"]}
    return out


def vibration_bound(spec: Spec, km: KappaModel, grid: Grid, rows, kappa, f):
    """Sum of the harmonic amplitudes at the normal configuration (Hamabe Part II, with the
    dash-pot): an upper bound of half the peak-to-peak vibration, for candidates x dash-pots."""
    from ..governors.shaft.vibration import peak_amplitude_bound

    i_n = int(np.argmin(np.abs(grid.alpha - spec.governor.alpha_normal)))
    k2 = (km.k2.x[rows, i_n] * np.asarray(kappa) + km.k2.y[rows, i_n])[:, None]
    inertia = km.inertia[rows, i_n][:, None]
    m = km.m[rows, 0][:, None]
    return peak_amplitude_bound(spec, spec.governor.alpha_normal, k2, inertia, m, dashpot=f)





def dead_weight_statics(spec: Spec, req: Requirements, grid: Grid, m, c):
    """The statics requirements of a dead-weight governor at every (ball, central) weight pair:
    ``({name: met}, omega^2, omega_rise^2, omega_fall^2, k^2, inertia)`` over the grid."""
    t = statics.terms(spec, grid.alpha, m[:, None], c[:, None])
    arrays = dead_weight_arrays(spec, grid, m, c, t)
    return dead_weight_parts(spec, req, *arrays[1:4]), *arrays


def dead_weight_arrays(spec: Spec, grid: Grid, m, c, t):
    """``(omega^2, omega_rise^2, omega_fall^2, k^2, inertia)`` of a dead-weight governor at
    every (ball, central) weight pair, from its generalised forces ``t`` there
    (:func:`govopt.analysis.statics.terms`); the speed band enters only through ``t``."""
    gov = spec.governor
    fr = gov.friction(grid.alpha)
    with np.errstate(divide="ignore", invalid="ignore"):
        w2, rise, fall = (t.omega_squared(0.0, 0.0, s * fr) for s in (0.0, 1.0, -1.0))
        inertia = gov.inertia(grid.alpha, m[:, None], c[:, None]) + 0.0 * w2
        k2 = t.stiffness(0.0, 0.0, w2) / inertia
    return w2, rise, fall, k2, inertia


def dead_weight_parts(spec: Spec, req: Requirements, rise, fall, k2) -> dict:
    """Which (ball, central) weight pairs meet each statics requirement (``{name: met}``),
    from :func:`dead_weight_arrays`."""
    sp = spec.speed
    k2_lo, k2_hi = k2_limits(spec, req)
    out = {
        "equilibrium speed > 0": np.all(fall > 0, axis=1),
        "k^2 within its margins": np.all((k2 >= k2_lo) & (k2 <= k2_hi), axis=1),
        statics.BAND_INNER: statics.band_extremes(fall, rise)[0] >= sp.omega_inner,
        statics.BAND_OUTER: statics.band_extremes(fall, rise)[1] <= sp.omega_outer,
    }
    least = least_range(spec, req)
    if least > 0:  # asked for: the range of speed without friction, the mean of the two bands
        from ..requirements import RANGE_OF_SPEED

        with np.errstate(invalid="ignore"):
            w = np.sqrt((rise + fall) / 2.0)
        out[RANGE_OF_SPEED] = w[:, -1] - w[:, 0] >= least * (sp.omega_outer - sp.omega_inner)
    return out


def central_load_intervals(spec: Spec, req: Requirements, grid: Grid, m) -> tuple:
    """The central loads ``c`` at which each flying mass ``m`` (an array) meets every statics
    requirement of :func:`dead_weight_parts`, as an interval ``(lo, hi)`` per mass (``lo > hi``:
    none), in closed form, for a type whose forces are affine in the central load
    (:attr:`Governor.central_load_affine`). With the lever ``jp - ci`` free of ``c``, the
    speeds squared ``(cf -+ F) / (jp - ci)`` (textbook 3.4(b)) and ``I k^2`` and ``I`` (Hamabe
    eqs. 18-20) are affine in ``c``, so each requirement at each configuration is ``a + b c >=
    0``: a half-line. Read from :func:`dead_weight_arrays` at ``c = 0`` and ``c = 1`` kg."""
    sp = spec.speed
    k2_lo, k2_hi = k2_limits(spec, req)
    at = []
    for c in (0.0, 1.0):
        cc = np.full(np.shape(m), c)
        _, rise, fall, k2, inertia = dead_weight_arrays(
            spec, grid, m, cc, statics.terms(spec, grid.alpha, m[:, None], cc[:, None]))
        with np.errstate(invalid="ignore"):
            forms = [fall, k2 * inertia - k2_lo * inertia]
            if np.isfinite(k2_hi):
                forms.append(k2_hi * inertia - k2 * inertia)
            if sp.omega_inner > 0:
                forms.append(fall - sp.omega_inner**2)
            forms.append(sp.omega_outer**2 - rise)
        at.append(forms)
    lo, hi = np.full(np.size(m), -np.inf), np.full(np.size(m), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for a, a1 in zip(*at, strict=True):
            b = a1 - a
            root = -a / b
            lo = np.maximum(lo, np.max(np.where(b > 0, root, -np.inf), axis=1))
            hi = np.minimum(hi, np.min(np.where(b < 0, root, np.inf), axis=1))
            never = np.any((b == 0) & ~(a >= 0) | ~np.isfinite(a) | ~np.isfinite(b), axis=1)
            lo = np.where(never, np.inf, lo)
    return lo, hi
