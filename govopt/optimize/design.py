"""Whole-governor design: pendulum weight, spring (d, r, n, free length) and dash-pot.

Method (each step uses the statics and dynamics modules as evaluators):

1. For every pendulum mass on the catalogue's weight grid, the statics requirements (irregularity,
   ``k2_margin omega0^2 <= k^2 <= (1 - k2_margin) omega0^2`` at every configuration, a positive
   equilibrium speed, a spring in tension, a positive free length) are an interval of admissible
   stiffness, in closed form (:mod:`govopt.optimize.kappa`).
2. **Continuous bound**: for each mass, the spring is a geometric programme (cvxpy DGP, built once
   with parameters and re-solved, :class:`~govopt.optimize.spring_gp.SpringGP`): least mass with
   the stiffness in that interval, stress from the exact force ``F_n + 2 kappa (l_a - l_n)``,
   index, envelope, surge, turns and diameter bounds. The dynamics requirements are relaxed here,
   so the best of these is a true lower bound on any design. Where the spring's energy bound is
   attained by a spring meeting every row of the GP (the uncorrected stress and the stiffness
   band bind), that spring is the GP's optimum without a solve
   (:func:`govopt.optimize.gp_table.energy_optimum`); cvxpy solves the rest.
3. **Discrete design**: every catalogue wire, coil radius on its grid, turns on their step and
   mass on its grid is checked against the same constraints in closed form (vectorised, exhaustive),
   and the candidates are visited best first until one also admits a dash-pot with Hamabe's
   eq. (32) margin, no over-regulation and the settling limit for every load change. The dash-pot's
   feasible range is found on a log grid (it can be bounded on both sides: too little damping
   violates eq. 32, too much makes the slow roots a complex pair that overshoots).
4. The chosen design is re-evaluated with the full :func:`govopt.evaluate`, like the paper's
   closing check, and its constraints, margins and sensitivities are reported.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

import numpy as np

from .. import limits
from ..analysis import loadchange, statics
from ..analysis.over_regulation import OVER_TOL, over_regulates
from ..analysis.transient_cubic import hamabe_initial_conditions
from ..analysis.transient_events import analyse_many
from ..errors import DesignError, InfeasibleError
from ..limits import MAX_TRANSIENT_POINTS, design_size_error
from ..requirements import (
    SpringFigures,
    holds,
    requirement_rows,
    search_bound_rows,
    stress_row,
)
from ..spec import Design, Requirements, Spec, Speed
from ..springs import helical as hx
from ..units import G_STANDARD, SI_UNITS
from .kappa import Affine, KappaModel
from .margins import margins_to_ends, window_centre

#: Dash-pot grid, as multiples of the least damping that meets eq. (32) with its margin.
DASHPOT_FACTORS = np.geomspace(1.0, 200.0, 25)


def objective_unit(req: Requirements, gov) -> str:
    """The SI unit of the objective (:func:`objective_values`): kg for the masses, s for the
    settling time, the configuration's unit (rad or m) for the vibration's peak-to-peak."""
    return {"settling_time": "s", "vibration": SI_UNITS[gov.coordinate]}.get(req.objective, "kg")


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


def _steps(lo: float, hi: float, step: float) -> np.ndarray:
    if lo == hi:
        return np.array([lo])
    return np.arange(math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9) + 1) * step


def mass_grid(req: Requirements) -> np.ndarray:
    """The flying masses on the catalogue's weight step within the bounds (not zero: a lower
    bound within rounding of it is no flying mass)."""
    m = _steps(*req.flying_mass, req.mass_step)
    return m[m > 0]


def masses(req: Requirements) -> tuple[np.ndarray, np.ndarray]:
    """Every (flying mass, central load) pair on the weight-step grid, as two flat arrays."""
    m, c = np.meshgrid(mass_grid(req), _steps(*req.central_mass, req.mass_step), indexing="ij")
    return m.ravel(), c.ravel()


def k2_limits(spec: Spec, req: Requirements) -> tuple[float, float]:
    w0sq = spec.speed.omega_mean**2
    ceiling = (1.0 - req.k2_margin) * w0sq if spec.governor.resonance_ceiling else np.inf
    return req.k2_margin * w0sq, ceiling


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
    return km, *km.statics_interval(*k2_limits(spec, req), spec.speed.irregularity)


def _statics_feasible(spec: Spec, req: Requirements, cells: int = 1 << 16) -> bool:
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


def _windows(spec: Spec, req: Requirements, km: KappaModel, grid: Grid, rows, kappa) -> dict:
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


# ---------------------------------------------------------------------------------------------
# Springs: exhaustive discrete enumeration, checked in closed form
# ---------------------------------------------------------------------------------------------


def catalogue_axes(req: Requirements):
    """The catalogue's wire diameters, coil radii and turns within the bounds (1-D arrays);
    a bound with equal ends fixes the value, on the catalogue or not."""
    lo, hi = req.wire_diameter
    d = np.array([lo] if lo == hi else
                 [w for w in req.wire_diameters if lo - 1e-12 <= w <= hi + 1e-12])
    return d, _steps(*req.coil_radius, req.coil_radius_step), \
        _steps(*req.active_turns, req.turn_step)


def spring_catalogue(req: Requirements):
    """Every (d, r, n) the catalogue allows within the bounds, as flat arrays."""
    D, Rr, N = np.meshgrid(*catalogue_axes(req), indexing="ij")
    return D.ravel(), Rr.ravel(), N.ravel()


@dataclass(frozen=True)
class SpringCatalogue:
    """The springs a design may use (the spring plug's catalogue): each one's stiffness, mass
    and design fields (names of :class:`~govopt.spec.Design`), and ``check(cols, F_max, l0)``,
    the spring's own constraints for springs ``cols`` at largest force ``F_max`` and free length
    ``l0`` (arrays). ``gp``: the continuous bound (the spring GP) applies."""

    kappa: np.ndarray
    mass: np.ndarray
    fields: dict
    check: object
    gp: bool = True
    #: ``fatigue(cols, l0, swing)``: least fatigue safety of springs ``cols`` under peak-to-peak
    #: swings (candidates x dash-pots); None: no fatigue requirement
    fatigue: object = None

    @property
    def size(self) -> int:
        return int(self.kappa.size)


def helical_catalogue(spec: Spec, req: Requirements) -> SpringCatalogue:
    """Catalogue wire x coil-radius grid x turn step (helical springs; Wahl 1944)."""
    d, r, n = spring_catalogue(req)
    mat = spec.material
    kappa = hx.stiffness_r(d, r, n, mat.shear_modulus)
    harmonics, fatigue = (), None
    if mat.grade is not None:  # the wire grade's table (govopt.analysis.spring_engineering)
        from ..analysis import spring_engineering as se

        vib = se.screen_vibration(spec, req)
        harmonics = se.harmonics_hz(vib)
        if vib is not None:
            def fatigue(cc, l0, swing):
                return se.screen_fatigue(spec, d[cc], r[cc], n[cc], kappa[cc], l0, swing)
    return SpringCatalogue(
        kappa=kappa,
        mass=hx.wire_mass(d, r, n, mat.density),
        fields={"wire_diameter": d, "coil_radius": r, "active_turns": n},
        check=lambda cc, F, l0: spring_checks(spec, req, d[cc], r[cc], n[cc], F, l0,
                                              harmonics, kappa[cc]),
        fatigue=fatigue)


def leaf_catalogue(spec: Spec, req: Requirements) -> SpringCatalogue:
    """Stock flat sections within the bounds (``govopt/data/leaf_stock.csv``) at the type's
    leaf length: stiffness ``c E w t^3/(12 L^3)``, the leaf's constraint table (bending stress at
    the largest load, bow/length, t/w) (:mod:`govopt.springs.leaf`)."""
    from ..springs import leaf

    gov, mat = spec.governor, spec.material
    w, t = leaf.stock_sections()
    keep = ((w >= req.leaf_width[0] - 1e-12) & (w <= req.leaf_width[1] + 1e-12)
            & (t >= req.leaf_thickness[0] - 1e-12) & (t <= req.leaf_thickness[1] + 1e-12))
    w, t = w[keep], t[keep]
    span = float(np.max(gov.span(np.array([gov.x_inner, gov.x_outer]))))
    allowable = mat.allowable_bending_stress if mat.allowable_bending_stress else np.inf
    bow_ok = (gov.x_outer - gov.hinge_radius) / gov.leaf_length <= req.max_bow_ratio

    def check(cc, F, l0):
        return ((leaf.bending_stress(F, w[cc], t[cc], span, gov.leaf_ends) <= allowable) & bow_ok
                & gov.set_ok(l0))

    return SpringCatalogue(kappa=gov.leaf_stiffness(w, t, mat.elastic_modulus),
                           mass=leaf.mass(w, t, gov.leaf_length, mat.density),
                           fields={"leaf_width": w, "leaf_thickness": t}, check=check, gp=False)


#: the spring plug's catalogues by ``Governor.spring`` (a helical spring unless named here)
CATALOGUES = {"leaf": leaf_catalogue}


def catalogue(spec: Spec, req: Requirements) -> SpringCatalogue:
    return CATALOGUES.get(spec.governor.spring, helical_catalogue)(spec, req)


def spring_checks(spec: Spec, req: Requirements, d, r, n, F_max, l0, harmonics=(), kappa=None):
    """Spring constraints that do not depend on the governor's statics (arrays): the spring's
    requirement rows (:func:`govopt.requirements.requirement_rows`, group ``"spring"``: index,
    body length, outer diameter, surge); with a wire grade the spring engineering table
    (diameter-dependent allowables, the spring kind's own checks, surge clear of the forcing's
    ``harmonics`` in Hz) instead of the one stress; without one, the compression spring's
    geometric rows too (coil clash, buckling, free pitch:
    :func:`govopt.analysis.spring_engineering.geometry_rows`). ``kappa``: the springs'
    stiffness where the caller has it (N/m).

    Every row is elementwise, so the costly tables (geometry, engineering) are computed only
    for the springs that pass the cheap rows before them: the same answer for each spring, in
    a fraction of the time (the design screen checks millions of pairs)."""
    mat = spec.material
    ok = holds(requirement_rows(spec, req), SpringFigures(d, r, n, l0, mat))
    from ..analysis import spring_engineering as se

    if kappa is None:
        kappa = hx.stiffness_r(d, r, n, mat.shear_modulus)
    if mat.grade is None:  # the stress against the spec's allowable; coil clash and buckling
        ok = ok & holds([stress_row(mat)],
                        {"stress": hx.shear_stress_r(F_max, d, r, mat.stress_correction)})
        return _where(ok, lambda i: se.geometry_screen(spec, *_take(i, d, r, n, kappa, l0)))
    return _where(ok, lambda i: se.screen(spec, *_take(i, d, r, n, kappa, l0), harmonics))


def _take(i, *arrays):
    """Each of ``arrays`` at the indices ``i`` (a scalar as it is)."""
    return tuple(a[i] if np.ndim(a) else a for a in arrays)


def _where(ok, test):
    """``ok & test(all)`` with ``test`` (an elementwise screen of the indices it is given)
    computed only where ``ok`` holds."""
    ok = np.array(ok, dtype=bool)
    if ok.ndim == 0:
        return ok & np.asarray(test(slice(None)))
    i = np.flatnonzero(ok)
    ok[i] = test(i)
    return ok


def objective_values(req: Requirements, m, spring_mass, window=None, central=0.0):
    """The objective of candidates; ``window`` (from :func:`dashpot_window`) for the dynamic
    objectives."""
    if req.objective == "spring_mass":
        return spring_mass
    if req.objective == "settling_time":
        return window["settling"]
    if req.objective == "vibration":
        return window["vibration"]
    return m + central + spring_mass  # moving mass (flying + central + spring), the default


@dataclass(frozen=True)
class Candidate:
    m: float
    spring: dict  # the spring's design fields (wire_diameter ..., or leaf_width ...)
    kappa: float
    l0: float
    f: float
    objective: float
    settling: float
    f_lo: float
    f_hi: float
    central: float = 0.0


def spring_screen(spec: Spec, req: Requirements, km: KappaModel, lo, hi, cat: SpringCatalogue,
                  chunk: int = 1 << 18):
    """Every (mass row, catalogue spring) pair that passes the statics (``lo <= kappa <= hi``)
    and the spring checks, in row-major order: ``(rows, cols, l0, statics_feasible)``.

    The springs are sorted by stiffness once, so each mass's admissible springs are one
    slice (two binary searches, no masses x springs mask), and the checks run on chunks of at
    most ``chunk`` pairs: memory stays bounded whatever the catalogue. A chunk's arrays (2 MB
    each at 2**18 pairs) are reused by the allocator from one chunk to the next; at 2**20 pairs
    (8 MB) each came fresh from the kernel and its page faults cost a third of the design's
    time (spring_gravity-design: 11 M pairs, 1.7 s -> 1.3 s of CPU). The largest force over
    the configurations is ``max_j (kappa x_j + y_j)``, ``y_j`` being the same at every
    configuration for every spring type (``F = kappa (A_F - B_F l0)`` with constant
    ``B_F``), so it is ``y + kappa max_j x_j``, the same number in floating point (rounding is
    monotone); a type with varying ``B_F`` takes the maximum over configurations per chunk.
    """
    perm = np.argsort(cat.kappa, kind="stable")
    ks = cat.kappa[perm]
    bad = ~(lo <= hi)  # NaN-safe: the old mask admitted nothing there
    a = np.searchsorted(ks, lo, "left")
    b = np.where(bad, a, np.maximum(a, np.searchsorted(ks, hi, "right")))
    counts = b - a
    fx, fy = km.force.x, km.force.y
    uniform = bool(np.all(fy == fy[:, :1]))
    xmax = np.max(fx, axis=1) if uniform else None
    out_rows, out_cols, out_l0 = [np.zeros(0, np.intp)], [np.zeros(0, np.intp)], [np.zeros(0)]
    nz = np.nonzero(counts)[0]
    ends = np.cumsum(counts[nz])
    start = 0
    while start < nz.size:
        stop = max(int(np.searchsorted(ends, (ends[start - 1] if start else 0) + chunk,
                                       "right")), start + 1)
        R = nz[start:stop]
        cnt = counts[R]
        rr = np.repeat(R, cnt)
        pos = np.arange(rr.size) + np.repeat(a[R] - (np.cumsum(cnt) - cnt), cnt)
        cc, k = perm[pos], ks[pos]
        if uniform:
            F_max = xmax[rr] * k + fy[rr, 0]
        else:
            F_max = np.full(k.shape, -np.inf)
            for j in range(fx.shape[1]):
                np.maximum(F_max, fx[rr, j] * k + fy[rr, j], out=F_max)
        l0 = km.l0.x[rr, 0] + km.l0.y[rr, 0] / k
        ok = cat.check(cc, F_max, l0)
        rr, cc, l0 = rr[ok], cc[ok], l0[ok]
        # row-major, as a masses x springs mask would list them (each pair's key is unique)
        o = np.argsort(rr.astype(np.int64) * ks.size + cc)
        out_rows.append(rr[o])
        out_cols.append(cc[o])
        out_l0.append(l0[o])
        start = stop
    return (np.concatenate(out_rows), np.concatenate(out_cols), np.concatenate(out_l0),
            int(counts.sum()))


def _best_first(values, head: int):
    """The first ``head`` (or more, on ties) indices of ``argsort(values, kind="stable")``,
    in that order, without sorting everything."""
    if values.size <= head:
        return np.argsort(values, kind="stable")
    t = np.partition(values, head - 1)[head - 1]
    idx = np.nonzero(values <= t)[0]
    return idx[np.argsort(values[idx], kind="stable")]


def best_discrete(spec: Spec, req: Requirements, km: KappaModel, grid: Grid, lo, hi,
                  batch: int = 64, max_checked: int = 512, dynamics: bool = True
                  ) -> tuple[Candidate | None, dict]:
    """Exhaustive search over mass grid x catalogue springs; dynamics checked best first."""
    cat = catalogue(spec, req)
    kappa, smass = cat.kappa, cat.mass
    M = km.m.shape[0]
    rows, cols, l0, n_statics = spring_screen(spec, req, km, lo, hi, cat)
    per = 1 if km.reference is None else int(np.unique(km.reference).size)
    stats = {"gp": cat.gp, "springs": cat.size, "masses": int(M) // per,
             "combinations": cat.size * int(M),
             "statics_feasible": n_statics, "spring_feasible": int(rows.size)}
    m = km.m[rows, 0]
    if not dynamics:
        return None, stats
    if req.objective in ("settling_time", "vibration"):
        order = _surrogate_order(spec, req, km, grid, rows, kappa[cols])
        head = order[:max_checked]
    else:
        values = objective_values(req, m, smass[cols], central=km.central[rows, 0])
        head = _best_first(values, max_checked)[:max_checked]
        order = None
    best, checked, stopped = _visit(spec, req, km, grid, rows, cols, cat, m, l0, head, batch)
    if best is None and rows.size > max_checked and not stopped:
        # best-first found nothing: screen the dynamics on a (mass, stiffness) lattice and visit
        # only candidates in or next to cells where some dash-pot works
        keep = _lattice_screen(spec, req, km, grid, rows, kappa[cols], stats)
        if order is None:
            order = np.argsort(values, kind="stable")
        rest = order[max_checked:]
        rest = rest[keep[rest]]
        best, more, stopped = _visit(spec, req, km, grid, rows, cols, cat, m, l0, rest, batch)
        checked += more
    elif best is None and rows.size and not stopped:
        _lattice_screen(spec, req, km, grid, rows, kappa[cols], stats)  # for the diagnosis
    stats["dynamics_checked"] = checked
    if stopped:
        stats["dynamics_stopped_at_the_work_limit"] = True
    return best, stats


def _batches(size: int, batch: int):
    """Slices of ``range(size)`` of 1, 4, 16, ... then ``batch`` items: the first candidate
    best first is often feasible, and a small first batch checks it alone."""
    start, step = 0, 1
    while start < size:
        yield slice(start, min(start + step, size))
        start += step
        step = min(4 * step, batch)


def _visit(spec, req, km, grid, rows, cols, cat, m, l0, order, batch):
    """Check candidates in ``order`` in batches; the best feasible one (first batch with one
    feasible for the mass objectives, which are visited in objective order), the candidates
    checked, and whether the visit stopped at the running search's limit of work."""
    best, checked = None, 0
    for part in _batches(order.size, batch):
        sel = order[part]
        fat = None if cat.fatigue is None else (
            lambda swing, s=sel: cat.fatigue(cols[s], l0[s], swing))
        try:
            win = dashpot_window(spec, req, km, grid, rows[sel], cat.kappa[cols[sel]],
                                 fatigue=fat)
        except limits.WorkLimit:  # the best among those checked, with a note (design())
            return best, checked, True
        checked += sel.size
        if not np.any(win["feasible"]):
            continue
        obj = np.where(win["feasible"], objective_values(req, m[sel], cat.mass[cols[sel]], win,
                                                         km.central[rows[sel], 0]), np.inf)
        j = int(np.argmin(obj))
        i = sel[j]
        spring_fields = {k: float(v[cols[i]]) for k, v in cat.fields.items()}
        cand = Candidate(float(m[i]), spring_fields,
                         float(cat.kappa[cols[i]]), float(l0[i]), float(win["f"][j]), float(obj[j]),
                         float(win["settling"][j]), float(win["f_lo"][j]), float(win["f_hi"][j]),
                         float(km.central[rows[i], 0]))
        if best is None or cand.objective < best.objective:
            best = cand
        if req.objective in ("moving_mass", "spring_mass"):
            break
    return best, checked, False


def _cells(rows, kappa, width: float):
    """Group candidates by (mass row, cell of ``log kappa`` of the given width): the dynamics
    depend on the mass and the stiffness only. Returns each candidate's cell key, the distinct
    keys, and each cell's mass row and centre stiffness."""
    index = np.floor(np.log(kappa) / width).astype(np.int64)
    key = rows.astype(np.int64) * (1 << 40) + (index - index.min())
    uniq, first = np.unique(key, return_index=True)
    return key, uniq, rows[first], np.exp((index[first] + 0.5) * width)


def _lattice_screen(spec, req, km, grid, rows, kappa, stats, cells: int = 24):
    """Dynamics on a lattice of masses x ``cells`` log-spaced stiffness cells covering the
    candidates; returns a mask of candidates in or next to a cell with a feasible dash-pot, and
    records in ``stats["least"]`` how far each dynamic requirement can be pushed (for the
    diagnosis)."""
    width = max(float(np.ptp(np.log(kappa))) / cells, 1e-9)
    key, uniq, cell_rows, centre = _affordable_cells(spec, req, rows, kappa, width, LATTICE)
    if uniq is None:  # not within its share: every candidate stays, the visit counts them
        stats["lattice_cells"] = 0
        return np.ones(rows.size, bool)
    win = _windows(spec, req, km, grid, cell_rows, centre)
    stats["least"] = {k: float(np.min(v)) for k, v in win["least"].items()}
    good = set()
    for u in uniq[win["feasible"]]:
        good.update((u - 1, u, u + 1))
    stats["lattice_cells"] = int(uniq.size)
    stats["lattice_feasible"] = int(np.sum(win["feasible"]))
    return np.isin(key, list(good))


def _surrogate_order(spec, req, km, grid, rows, kappa):
    """Order candidates for the objectives that depend on the dash-pot (settling, vibration):
    the objective is evaluated once per (mass, stiffness to 5 %) cell, which is what it depends
    on, and every candidate takes its cell's value. The visit order is heuristic only within a
    cell; every candidate visited is checked exactly."""
    if rows.size == 0:
        return np.arange(0)
    key, uniq, cell_rows, centre = _affordable_cells(spec, req, rows, kappa, 0.05, SURROGATE)
    if uniq is None:  # not even a cell per mass within its share: lightest first
        return np.argsort(km.m[rows, 0], kind="stable")
    win = _windows(spec, req, km, grid, cell_rows, centre)
    score = np.where(win["feasible"], objective_values(req, None, None, win), np.inf)
    return np.argsort(score[np.searchsorted(uniq, key)], kind="stable")


#: the shares of the design's dynamics work (:data:`govopt.limits.MAX_DESIGN_DYNAMICS_SECONDS`)
#: the surrogate ordering the candidates and the lattice screening them may take at most
SURROGATE, LATTICE = 0.3, 0.3


def _affordable_cells(spec, req, rows, kappa, width: float, share: float):
    """:func:`_cells` at ``width``, widened (doubled) until their dash-pot windows take at most
    ``share`` of what the running search has left (:func:`govopt.limits.charge`); ``uniq``
    None where even a cell per mass row would not."""
    work = limits._WORK.get()
    budget = math.inf if work is None else share * work.left()
    each = window_seconds(spec, req)
    span = float(np.ptp(np.log(kappa))) if kappa.size else 0.0
    while True:
        key, uniq, cell_rows, centre = _cells(rows, kappa, width)
        if uniq.size * each <= budget:
            return key, uniq, cell_rows, centre
        if width > span:
            return key, None, cell_rows, centre
        width *= 2.0


# ---------------------------------------------------------------------------------------------
# Continuous bound (GP per mass) and the whole design
# ---------------------------------------------------------------------------------------------


def spring_mass_lower_bound(F, per_kappa, k_lo, k_hi, k_s, G, density):
    """Least wire mass of any helical spring with stiffness ``kappa`` in ``[k_lo, k_hi]`` (N/m)
    whose uncorrected stress at the force ``F + per_kappa kappa`` (N, N per N/m) is within
    ``k_s`` (Pa), with shear modulus ``G`` (Pa) and density (kg/m^3): the energy bound, kg.

    With Hamabe's Example 1 formulas, ``kappa = G d^4 / (64 r^3 n)`` and
    ``tau = 16 F r / (pi d^3)``, the energy stored at the force ``F``,
    ``U = F^2 / (2 kappa)``, is ``tau^2 V / (4 G)`` with ``V = pi^2 d^2 r n / 2`` the wire's
    volume. So ``tau <= k_s`` needs ``rho V >= 2 rho G F^2 / (kappa k_s^2)`` whatever ``d, r,
    n`` (Wahl's factor ``K >= 1`` and every other limit only add to it); ``F^2 / kappa`` is
    least at ``kappa = F / per_kappa`` within the band. Arrays broadcast; 0 where ``F <= 0``.

    A spring stressed to exactly ``k_s`` meets the bound (d = 10 mm, r = 50 mm, n = 5):

    >>> from govopt.springs import helical as hx
    >>> G, rho, F = 80e9, 7850.0, 500.0
    >>> kappa, tau = hx.stiffness_r(0.01, 0.05, 5, G), hx.shear_stress_r(F, 0.01, 0.05)
    >>> lb = spring_mass_lower_bound(F, 0.0, kappa, kappa, tau, G, rho)
    >>> bool(np.isclose(lb, hx.wire_mass(0.01, 0.05, 5, rho), rtol=1e-12))
    True
    """
    F, p = np.asarray(F, dtype=float), np.maximum(np.asarray(per_kappa, dtype=float), 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.clip(np.where(p > 0, F / p, np.inf), k_lo, k_hi)
        energy = (F + p * k) ** 2 / k
    return np.where(F > 0, 2.0 * density * G * energy / k_s**2, 0.0)


def gp_values(spec: Spec, req: Requirements, km: KappaModel, i: int, k_lo: float, k_hi: float,
              per: float) -> dict:
    """The spring GP's values for mass row ``i`` with the stiffness in ``[k_lo, k_hi]``: the
    exact force at the outermost configuration ``F = F_n + per kappa`` (a posynomial), the
    bounds and limits, and the body length within the band's largest free length; the allowable
    ``k_s`` is the caller's (a grade's rule or the spec's)."""
    mat = spec.material
    values = dict(kappa_min=k_lo, kappa_max=k_hi, F_max=float(km.force.y[i, -1]),
                  force_per_stiffness=per if per > 0 else None, G=mat.shear_modulus,
                  density=mat.density)
    # the requirement rows' GP limits; the body length at the band's largest free length
    ev = {"l0": float(km.l0.x[i, 0] + km.l0.y[i, 0] / k_hi)}
    values.update({row.gp.limit: row.limit(ev)
                   for row in (*requirement_rows(spec, req), *search_bound_rows(req))
                   if row.gp is not None})
    return values


def continuous_bound(spec: Spec, req: Requirements, km: KappaModel, lo, hi):
    """Least objective over masses with the spring sized by the GP (dynamics relaxed).

    Per mass the GP takes the stiffness band ``[lo, hi]``, the exact force at the outermost
    configuration ``F = F_n + 2 kappa (l_a - l_n)`` (a posynomial in d, r, n) and the body length
    limit at the band's largest free length, so it is a relaxation of the discrete search: its
    best value is a lower bound on every design, continuous or discrete.

    The masses are visited in the order of a lower bound of their objective (the flying and
    central masses plus :func:`spring_mass_lower_bound`), and the visit stops once that bound
    exceeds the best GP optimum found: the result is the one of solving every mass (the least
    objective, ties to the first mass), from a few solves of one shared GP. Where that bound is
    attained by a spring meeting every row of the GP's table
    (:func:`govopt.optimize.gp_table.energy_optimum`: the uncorrected stress and the stiffness
    band bind) that spring is the GP's optimum, certified without a solve (and without cvxpy).
    """
    from .gp_table import complete_values, energy_optimum

    mat = spec.material
    k_s, k_exp = mat.allowable_shear_stress, 0.0
    if mat.grade is not None:  # k_s d^-m above the grade's allowable over the wire bounds
        from ..analysis.spring_engineering import allowable_monomial

        k_s, k_exp = allowable_monomial(spec, *req.wire_diameter)
    gp = None
    rows = np.nonzero(lo <= hi)[0]
    k_lo, k_hi = np.maximum(lo[rows], 1e-9), np.minimum(hi[rows], 1e12)
    per_kappa = km.force.x[rows, -1]
    lower = spring_mass_lower_bound(km.force.y[rows, -1], per_kappa, k_lo, k_hi,
                                    k_s * req.wire_diameter[0] ** -k_exp, mat.shear_modulus,
                                    mat.density)
    if req.objective != "spring_mass":
        lower = lower + km.m[rows, 0] + km.central[rows, 0]
    best, best_key = None, (math.inf, -1)
    for j in np.argsort(lower, kind="stable"):
        if lower[j] > best_key[0] * (1.0 + 1e-7):  # the GP's optimum cannot be below its bound
            break
        i = int(rows[j])
        per = float(per_kappa[j])
        values = {**gp_values(spec, req, km, i, float(k_lo[j]), float(k_hi[j]), per),
                  "k_s": k_s}
        sol = energy_optimum(complete_values(values, "band"), mat.stress_correction, k_exp)
        if sol is None:  # not certified by the energy bound: the GP (cvxpy) decides
            if gp is None:
                from .spring_gp import cached_gp

                gp = cached_gp("mass", mat.stress_correction, "band", k_exp)
            sol = gp.solve(**values)
        if not sol.ok:
            continue
        m, c = float(km.m[i, 0]), float(km.central[i, 0])
        obj = sol.objective if req.objective == "spring_mass" else m + c + sol.objective
        if (obj, i) < best_key:
            best_key = (obj, i)
            best = {"objective": obj, f"{spec.governor.mass_key}_mass_kg": m,
                    **({"central_mass_kg": c} if c else {}), "wire_diameter_m": sol.d,
                    "coil_radius_m": sol.r, "active_turns": sol.n, "spring_mass_kg": sol.objective,
                    "stiffness_N_per_m": sol.stiffness, "shear_stress_Pa": sol.stress}
    return best


def validated(spec: Spec) -> Spec:
    """The spec with its design requirements filled in (:func:`requirements`), after the checks
    every search needs: grids of a size govopt allows, a ``[material]`` where a spring is to be
    chosen, a speed range. Raises :class:`~govopt.errors.InfeasibleError` naming the key."""
    req = requirements(spec)
    spec = replace(spec, requirements=req)  # the checks report the requirements designed to
    too_big = design_size_error(req, spec.analysis.points, spec.governor.spring_kind,
                                spec.governor.mass_key)
    if too_big:  # counted from bounds and steps before any grid is built (govopt.limits)
        raise InfeasibleError(f"{spec.path}: {too_big[0]}: {too_big[1]}")
    if spec.governor.spring is not None and spec.material is None:
        raise InfeasibleError(f"{spec.path}: material: missing: a design chooses the spring, "
                              "which needs its [material]")
    if spec.speed is None:
        raise InfeasibleError(f"{spec.path}: speed: missing: a design needs the speed range")
    return spec


def design(spec: Spec):
    """Find the best nominal design for the spec's requirements; see the module docstring.
    (:func:`govopt.optimize.search.design`, which ``govopt.design`` is, runs the robust search of
    :mod:`govopt.optimize.robust` instead where the requirements ask for a tolerance box.)

    Raises :class:`~govopt.errors.InfeasibleError` with a diagnosis when no design exists, and
    :class:`~govopt.errors.DesignError` naming the failed checks when the chosen design fails
    its final re-evaluation (never returns a design that fails a check).
    """
    spec = validated(spec)
    req = spec.requirements
    if req.robust:
        raise ValueError("a robust spec is designed by govopt.optimize.search.design (the "
                         "tolerance box's search), not the nominal search")
    work = limits.Work(limits.MAX_DESIGN_DYNAMICS_SECONDS)  # the dash-pot windows' work
    if spec.governor.spring is None:  # a dead-weight governor: masses only
        with limits.counting(work):
            cand, stats = dead_weight_search(spec, req)
        return _result(spec, req, cand, _with_work(stats, work), None)
    _check_grids(spec, req)
    grid, km, lo, hi, parts = statics_window(spec, req)
    if not np.any(lo <= hi):
        raise InfeasibleError(diagnose(spec, req, "statics", parts))
    with limits.counting(work):
        cand, stats = best_discrete(spec, req, km, grid, lo, hi)
    stats = _with_work(stats, work)
    if cand is None:
        stage = "spring" if stats["spring_feasible"] == 0 else "dynamics"
        raise InfeasibleError(diagnose(spec, req, stage, parts, stats))
    bound = continuous_bound(spec, req, km, lo, hi) \
        if req.objective in ("moving_mass", "spring_mass") and stats.pop("gp") else None
    return _result(spec, req, cand, stats, bound)


def _with_work(stats: dict, work) -> dict:
    """The search's stats with the dynamics' counted work (estimated CPU seconds)."""
    return {**stats, "dynamics_work_s": round(work.spent, 3)}


def result_of(spec: Spec, req: Requirements, cand: Candidate, stats: dict,
              bound: dict | None = None):
    """The chosen candidate re-evaluated and its optimiser's record (:func:`_result`), for the
    searches of other modules (:mod:`govopt.optimize.robust`)."""
    return _result(spec, req, cand, stats, bound)


def check_grids(spec: Spec, req: Requirements) -> None:
    """:func:`_check_grids`, for the searches of other modules."""
    _check_grids(spec, req)


def _result(spec: Spec, req: Requirements, cand: Candidate, stats: dict, bound: dict | None):
    """The chosen candidate re-evaluated by :func:`govopt.evaluate`, with the optimiser's
    record: objective, continuous bound and gap, search statistics, sensitivities."""
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
    gap = None if bound is None else (cand.objective - bound["objective"]) / bound["objective"]
    damping = gov.key_unit("damping")
    unit = objective_unit(req, gov)
    res.optimisation = {
        "status": "optimal",
        # the unit is in the value's key (JSON's rule) and, for writers, a field of its own
        "objective": {"name": req.objective, "unit": unit, f"value_{unit}": cand.objective},
        "design": {
            f"{gov.mass_key}_weight_N": cand.m * G_STANDARD, f"{gov.mass_key}_mass_kg": cand.m,
            **({"central_mass_kg": cand.central} if cand.central else {}),
            **{(k if k == "active_turns" else f"{k}_m"): v for k, v in cand.spring.items()},
            **({f"{gov.free_length_key}_m": cand.l0} if gov.spring is not None else {}),
            f"dashpot_{damping}": cand.f,
            f"dashpot_feasible_range_{damping}": [cand.f_lo, cand.f_hi],
            **dashpot_margins(cand),
        },
        "continuous_bound": None if bound is None else {
            (f"objective_{unit}" if k == "objective" else k): v for k, v in bound.items()},
        "gap": gap,
        "search": stats,
        "notes": ([] if spec.engine is not None and spec.load_changes else [
            "no [engine] or [[load_change]] in the spec: the dash-pot and the load-change "
            "requirements (eq. 32, over-regulation, settling) were not designed for"]) + ([
            f"the dynamics were checked for {stats.get('dynamics_checked')} candidates, "
            f"best first, then stopped at govopt's limit of work (~"
            f"{limits.MAX_DESIGN_DYNAMICS_SECONDS:g} s): the best among them, which a longer "
            "search might better (fewer load changes, or narrower bounds)"]
            if stats.get("dynamics_stopped_at_the_work_limit") else [])
        + bounds_notes(searched),
        "search_bounds": searched,
        "sensitivities": sensitivities(spec, req, None if bound is None
                                       else bound["objective"]),
    }
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
    catalogue's grid), ``"fixed"`` for equal ends, else None."""
    from ..spec_keys import bounds_table

    gov = spec.governor
    kind = gov.spring_kind
    given = (spec.data or {}).get("bounds") or {}
    table = bounds_table(gov, kind)
    rows = [(f"{gov.mass_key}_mass", gov.mass_key, "kg", req.flying_mass, mass_grid(req),
             cand.m)]
    if gov.central_load:
        rows.append(("central_mass", "central", "kg", req.central_mass,
                     _steps(*req.central_mass, req.mass_step), cand.central))
    if cand.spring and kind is not None and kind.helical:
        axes = dict(zip(("wire_diameter", "coil_radius", "active_turns"),
                        catalogue_axes(req), strict=True))
        rows += [(k.name, k.name, k.unit, getattr(req, k.name), axes[k.name],
                  cand.spring[k.name]) for k in kind.bounds]
    elif cand.spring and kind is not None:
        from ..springs import leaf

        w, t = leaf.stock_sections()
        keep = ((w >= req.leaf_width[0] - 1e-12) & (w <= req.leaf_width[1] + 1e-12)
                & (t >= req.leaf_thickness[0] - 1e-12) & (t <= req.leaf_thickness[1] + 1e-12))
        rows += [(k.name, k.name, k.unit, getattr(req, k.name), grid[keep],
                  cand.spring[k.name]) for k, grid in zip(kind.bounds, (w, t), strict=True)]
    if req.dashpot is not None and not math.isnan(cand.f):
        rows.append(("dashpot_f", "dashpot_f", gov.key_unit("damping"), req.dashpot,
                     np.array(req.dashpot), cand.f))
    out = []
    for name, key, unit, (lo, hi), grid, value in rows:
        first, last = _grid_ends(grid)
        tol = 1e-9 * max(abs(first), abs(last), 1e-300)
        at = ("fixed" if lo == hi else "lower" if value <= first + tol
              else "upper" if value >= last - tol else None)
        suffix = f"_{unit}" if unit else ""
        names = [n for n in table.key(key).names if n in given]
        out.append({"name": name, "key": names[0] if names else "/".join(table.key(key).names),
                    "unit": unit, f"low{suffix}": lo, f"high{suffix}": hi,
                    f"value{suffix}": value, "given": bool(names), "at": at})
    return out


def _shown(value: float, unit: str) -> str:
    """A bound's value as a person reads it: lengths in mm."""
    if unit == "m":
        return f"{value * 1e3:.4g} mm"
    return f"{value:.4g} {unit}".rstrip()


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
        if b["at"] in ("lower", "upper"):
            notes.append(f"at the {b['at']} search bound of {b['name']} "
                         f"({_shown(ends(b)[2], b['unit'])}): widen [bounds] {b['key']} to "
                         "search beyond it")
    return notes


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


def dashpot_margins(cand: Candidate) -> dict:
    """How far the chosen dash-pot may be set off before it leaves its feasible window
    (:func:`govopt.optimize.margins.margins_to_ends`), in per cent; empty without a dash-pot."""
    if not (cand.f > 0 and math.isfinite(cand.f_lo) and math.isfinite(cand.f_hi)):
        return {}
    down, up = margins_to_ends(cand.f, cand.f_lo, cand.f_hi)
    return {"dashpot_margin_to_lower_end_percent": 100.0 * down,
            "dashpot_margin_to_upper_end_percent": 100.0 * up}


def dead_weight_search(spec: Spec, req: Requirements) -> tuple[Candidate, dict]:
    """Least moving mass ``m + M`` of a dead-weight governor (Watt, Porter, Proell: textbook
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
    for part in _batches(rows.size, 64):
        sel, start = rows[part], part.start
        try:
            win = dashpot_window(spec, req, km, grid, sel, np.zeros(sel.size))
        except limits.WorkLimit:
            stats["dynamics_checked"] = int(start)
            stats["dynamics_stopped_at_the_work_limit"] = True
            raise InfeasibleError(_dynamics_conflict(spec, req, stats)) from None
        if np.any(win["feasible"]):
            j = int(np.argmax(win["feasible"]))
            i = sel[j]
            stats["dynamics_checked"] = int(start + j + 1)
            return Candidate(float(m[i]), {}, 0.0, 0.0, float(win["f"][j]),
                             float(m[i] + c[i]), float(win["settling"][j]),
                             float(win["f_lo"][j]), float(win["f_hi"][j]), float(c[i])), stats
    stats["dynamics_checked"] = int(rows.size)
    raise InfeasibleError(_dynamics_conflict(spec, req, stats))


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
    ok_parts, w2, rise, fall, k2, inertia = _dead_weight_statics(spec, req, grid, m, c)
    ok = np.logical_and.reduce(list(ok_parts.values()))
    stats = {"masses": int(m.size), "combinations": int(m.size),
             "statics_feasible": int(ok.sum()), "spring_feasible": int(ok.sum())}
    if not ok.any():
        raise InfeasibleError(_dead_weight_diagnosis(spec, req, ok_parts, rise, fall))
    zero = Affine(0.0 * w2, w2)

    km = KappaModel(spec, m[:, None], grid.alpha, zero, Affine(0.0 * k2, k2),
                    Affine(0.0 * w2, 0.0 * w2), Affine(0.0 * m[:, None], 0.0 * m[:, None]),
                    inertia, c[:, None])
    rows = np.nonzero(ok)[0]
    return grid, km, rows[np.argsort(m[rows] + c[rows], kind="stable")], m, c, stats


def _dead_weight_statics(spec: Spec, req: Requirements, grid: Grid, m, c):
    """The statics requirements of a dead-weight governor at every (ball, central) weight pair:
    ``({name: met}, omega^2, omega_rise^2, omega_fall^2, k^2, inertia)`` over the grid."""
    t = statics.terms(spec, grid.alpha, m[:, None], c[:, None])
    arrays = _dead_weight_arrays(spec, grid, m, c, t)
    return _dead_weight_parts(spec, req, *arrays[1:4]), *arrays


def _dead_weight_arrays(spec: Spec, grid: Grid, m, c, t):
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


def _dead_weight_parts(spec: Spec, req: Requirements, rise, fall, k2) -> dict:
    """Which (ball, central) weight pairs meet each statics requirement (``{name: met}``),
    from :func:`_dead_weight_arrays`."""
    sp = spec.speed
    k2_lo, k2_hi = k2_limits(spec, req)
    return {
        "equilibrium speed > 0": np.all(fall > 0, axis=1),
        "k^2 within its margins": np.all((k2 >= k2_lo) & (k2 <= k2_hi), axis=1),
        statics.BAND_INNER: statics.band_extremes(fall, rise)[0] >= sp.omega_inner,
        statics.BAND_OUTER: statics.band_extremes(fall, rise)[1] <= sp.omega_outer,
    }


#: weight pairs per block of the infeasibility diagnosis's wider searches
_DIAGNOSIS_BLOCK = 4096


def _same_terms(a, b) -> bool:
    """Whether two :class:`govopt.governors.base.Terms` hold the same numbers (NaN never
    equal: such terms are computed again)."""
    return all(np.array_equal(getattr(a, f.name), getattr(b, f.name)) for f in fields(a))


def _bisect(feasible, lo: float = 1.0, hi: float = 100.0, iters: int = 12) -> float | None:
    """Smallest factor ``x`` in ``[lo, hi]`` with ``feasible(x)``, by bisection in log space;
    None if even ``hi`` is not enough."""
    if not feasible(hi):
        return None
    for _ in range(iters):
        mid = math.sqrt(lo * hi)
        lo, hi = (lo, mid) if feasible(mid) else (mid, hi)
    return hi


def _dead_weight_diagnosis(spec: Spec, req: Requirements, parts: dict, rise, fall) -> str:
    """Which requirement no ball and central-load weight meets, and the requirements that bind:
    each relaxed in turn (the k^2 margin, the band's ends, the weight bounds), with the value
    that makes the search feasible."""
    sp = spec.speed
    failing = [k for k, v in parts.items() if not v.any()]
    head = (f"{spec.path}: infeasible: no {spec.governor.mass_key} and central-load weight in "
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

    def feasible(s, r):
        m, c = masses(r)
        keep = np.array_equal(m, own[0]) and np.array_equal(c, own[1])
        for lo in range(0, m.size, _DIAGNOSIS_BLOCK):
            mb, cb = m[lo:lo + _DIAGNOSIS_BLOCK], c[lo:lo + _DIAGNOSIS_BLOCK]
            t = statics.terms(s, grid.alpha, mb[:, None], cb[:, None])
            hit = memo.get(lo) if keep else None
            if hit is None or not _same_terms(hit[0], t):
                hit = t, _dead_weight_arrays(s, grid, mb, cb, t)[1:4]
                if keep:
                    memo[lo] = hit
            if np.logical_and.reduce(list(_dead_weight_parts(s, r, *hit[1]).values())).any():
                return True
        return False

    def band(inner, outer):
        return replace(spec, speed=Speed((inner + outer) / 2.0, 2.0 * (outer - inner)
                                         / (outer + inner), band=sp.band))

    rpm = 30.0 / math.pi
    moves = []
    central = central_move(spec, req, lambda r: feasible(spec, r))
    if central:
        moves.append(central)
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
        moves.append(f"the weight bounds widened x{x:.3g}")
    with np.errstate(invalid="ignore"):
        ratio = np.sqrt(rise[:, -1] / fall[:, 0])
    best = float(np.nanmin(np.where(np.isfinite(ratio), ratio, np.nan))) \
        if np.isfinite(ratio).any() else math.inf
    tail = ("; it becomes feasible if one of these moves: " + "; ".join(moves)) if moves else (
        f"; no single requirement within a factor of 100 makes it feasible (the narrowest "
        f"operating band the geometry and friction allow spans a speed ratio {best:.4g}, the "
        f"spec's range {sp.omega_outer / sp.omega_inner:.4g})")
    return head + tail


def central_move(spec: Spec, req: Requirements, feasible) -> str | None:
    """The central load's upper search bound that makes ``feasible(requirements)`` hold, as
    a diagnosis's move (``bounds.central_weight 0 .. 0 kg (the default: no central load) -> 0
    .. 21.6 kg``), or None: where the type has a central load and no central load up to 100
    times the flying mass's upper bound does it. The bound is raised from the spec's (from a
    hundredth of the flying mass's upper bound where it is 0) by bisection in log space."""
    gov = spec.governor
    if not gov.central_load:
        return None
    lo, hi = req.central_mass
    top = 100.0 * max(req.flying_mass[1], hi)
    base = hi if hi > 0 else req.flying_mass[1] / 100.0

    def widened(x):
        return replace(req, central_mass=(lo, base * x))

    x = _bisect(lambda x: feasible(widened(x)), lo=1.0, hi=top / base, iters=16)
    if x is None or (hi > 0 and x == 1.0):
        return None
    given = "central_weight" if "central_mass" not in ((spec.data or {}).get("bounds") or {}) \
        else "central_mass"
    default = "" if hi > 0 else " (the default: no central load)"
    return (f"bounds.{given} {lo:.4g} .. {hi:.4g} kg{default} -> {lo:.4g} .. "
            f"{base * x:.4g} kg")


def _check_grids(spec: Spec, req: Requirements) -> None:
    """Bounds that leave no point of a catalogue grid are a user's mistake: say which."""
    if mass_grid(req).size == 0:
        raise InfeasibleError(
            f"{spec.path}: bounds.pendulum_weight: no weight on the catalogue's weight_step grid "
            f"({req.mass_step * G_STANDARD:g} N) lies within the bounds")
    d, r, n = catalogue_axes(req)
    for values, key in ((d, "catalogue.wire_diameters within bounds.wire_diameter"),
                        (r, "bounds.coil_radius on the catalogue's coil_radius_step grid"),
                        (n, "bounds.active_turns on the catalogue's turn_step grid")):
        if values.size == 0:
            raise InfeasibleError(f"{spec.path}: {key}: no value lies within the bounds")


def _feasible(spec: Spec, req: Requirements, stage: str) -> bool:
    if stage == "statics":
        return _statics_feasible(spec, req)
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


def diagnose(spec: Spec, req: Requirements, stage: str, parts, stats=None) -> str:
    """Which requirements conflict, and how far each would have to move (a relaxation)."""
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
                   else [("irregularity", with_irr, "x", speed.irregularity)])
    if stage == "statics":
        lo_name = max(parts, key=lambda k: np.median(parts[k][0]))
        lo, hi = parts[lo_name]
        others = [k for k in parts if k != lo_name]
        weight = f"{spec.governor.mass_key} weight"
        if not np.any(lo <= hi) or not others:  # the requirement alone: no stiffness meets it
            head = (f"{spec.path}: infeasible: no spring stiffness meets the requirement "
                    f"'{lo_name}' by itself at any {weight} in the bounds")
        else:  # never "X conflicts with X"
            hi_name = min(others, key=lambda k: np.median(parts[k][1]))
            head = (f"{spec.path}: infeasible: the requirement '{lo_name}' needs a stiffer "
                    f"spring than '{hi_name}' allows at every {weight} in the bounds")
        cands = [*speed_moves, ("k2_margin", with_k2, "/", req.k2_margin),
                 (f"bounds.{spec.governor.mass_key}_weight", with_mass, "widen x", None)]
    elif stage == "spring" and stats["statics_feasible"] == 0:
        head = (f"{spec.path}: infeasible: no catalogue spring's stiffness falls in the window "
                "the statics allow (the speed band, k^2 margins, free length) at any "
                f"{spec.governor.mass_key} weight in the bounds")
        cands = [*speed_moves, ("k2_margin", with_k2, "/", req.k2_margin)]
    elif stage == "spring":
        head = (f"{spec.path}: infeasible: no spring in the catalogue and bounds meets the "
                f"allowable shear stress (with index, envelope and surge limits) at a stiffness "
                f"the statics allow ({stats['statics_feasible']} mass-spring combinations pass "
                f"the statics, none the spring checks)")
        cands = [("allowable_shear_stress", with_ks, "x", mat.allowable_shear_stress),
                 *speed_moves]
        if mat.allowable_shear_stress is None:  # a wire grade's allowables: not one number
            cands = cands[1:]
    else:
        return _dynamics_conflict(spec, req, stats)
    for name, make, how, value in cands:
        x = _relax(spec, req, stage, make)
        if x is None:
            continue
        if how == "x" and value is not None:
            moves.append(f"{name} {value:g} -> {value * x:.4g} (x{x:.3g})")
        elif how.startswith("rpm"):  # a band's end, shown as the spec's speeds are
            rpm = 30.0 / math.pi
            to = value / x if how == "rpm /" else value * x
            moves.append(f"{name} {value * rpm:.5g} rpm -> {to * rpm:.5g} rpm")
        elif how == "/" and value:
            moves.append(f"{name} {value:g} -> {value / x:.4g}")
        elif how == "widen x":
            moves.append(f"{name} widened x{x:.3g}")
    tail = ("; it becomes feasible if one of these moves: " + "; ".join(moves)) if moves \
        else "; no single requirement within a factor of 100 makes it feasible"
    return head + tail


def _dynamics_conflict(spec: Spec, req: Requirements, stats: dict) -> str:
    """Name the dynamic requirement that no admissible dash-pot meets, and how far it is."""
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
        return (f"{spec.path}: infeasible: with no [[load_change]] no dash-pot is designed, and "
                f"undamped, the forced vibration breaks {broken or 'the requirements'} on every "
                f"candidate {where}; add the load change (a dash-pot) or relax them")
    over = least.get("over_regulation", np.inf)
    if over > OVER_TOL:
        text = ("no admissible damping" if not np.isfinite(over) else
                f"the least over-regulation at any admissible damping is "
                f"{100 * over:.3g} % of the load change (scaled by the slowest mode's decay)")
        return (f"{spec.path}: infeasible: Hamabe's eq. (32) with margin {req.hurwitz_margin:g} "
                f"conflicts with 'no over-regulation' for the load changes: {text} {where}; "
                f"lower requirements.hurwitz_margin or the load change")
    settle = least.get("settling_time", np.inf)
    if req.max_settling_time is not None and settle > req.max_settling_time:
        return (f"{spec.path}: infeasible: requirements.max_settling_time "
                f"{req.max_settling_time:g} s conflicts with 'no over-regulation' and eq. (32): "
                + (f"the fastest admissible settling is {settle:.4g} s {where}"
                   if np.isfinite(settle) else
                   f"no admissible dash-pot's settling could be placed (a time grid of at "
                   f"most {MAX_TRANSIENT_POINTS} points, then the modes' envelope: the load "
                   f"change's modes are too far apart, as with a very large flywheel) {where}"))
    vib = least.get("vibration", np.inf)
    if req.max_vibration is not None and vib > req.max_vibration:
        return (f"{spec.path}: infeasible: requirements.max_vibration "
                f"{np.degrees(req.max_vibration):.4g} deg conflicts with the load-change "
                f"requirements: the least peak-to-peak bound at an admissible damping is "
                f"{np.degrees(vib):.4g} deg {where}")
    if stats.get("lattice_feasible", 0) and spec.material is not None \
            and spec.material.grade is not None:  # the lattice screens all but the spring's life
        return (f"{spec.path}: infeasible: requirements.min_fatigue_safety "
                f"{req.min_fatigue_safety or 1.0:g}: no candidate's spring reaches it under the "
                f"vibration at a damping the load changes admit ({stats['lattice_feasible']} "
                f"mass x stiffness cells meet the load-change requirements alone) {where}")
    return (f"{spec.path}: infeasible: the dynamic requirements are met only together on no "
            f"candidate {where}")


def sensitivities(spec: Spec, req: Requirements, base: float | None) -> list[dict]:
    """Finite-difference sensitivity of the continuous bound ``base`` to each requirement
    (+1 %): each perturbed bound re-solved exactly by :func:`continuous_bound`, which solves
    the shared GP only at the masses whose lower bound can beat the best (one or two)."""
    out = []
    speed, mat = spec.speed, spec.material

    def bound_of(s, r):
        _, km, lo, hi, _ = statics_window(s, r)
        b = continuous_bound(s, r, km, lo, hi)
        return None if b is None else b["objective"]

    if req.objective not in ("moving_mass", "spring_mass") or base is None:
        return out
    trials = [
        *([("allowable shear stress k_s", replace(spec, material=replace(
            mat, allowable_shear_stress=mat.allowable_shear_stress * 1.01)), req)]
          if mat.allowable_shear_stress is not None else []),  # a wire grade: per d
        ("irregularity", replace(spec, speed=replace(
            speed, irregularity=speed.irregularity * 1.01)), req),
        ("mean speed", replace(spec, speed=replace(speed, omega_mean=speed.omega_mean * 1.01)),
         req),
        ("k^2 margin", spec, replace(req, k2_margin=req.k2_margin * 1.01)),
    ]
    for name, s, r in trials:
        b = bound_of(s, r)
        if b is None:
            continue
        pct = 100.0 * (b / base - 1.0)
        out.append({"requirement": name, "change_percent": 1.0,
                    "objective_change_percent": pct,
                    "text": f"+1 % on {name} -> {pct:+.2f} % {req.objective.replace('_', ' ')}"})
    return out
