"""The discrete design search: the catalogue of springs a design may use (stock wires and
flat sections, coil radii and turns on their made steps), each spring's own constraints in
closed form, and the best-first screen of (mass, spring) pairs against the statics window, then
the dash-pot window (:mod:`govopt.optimize.windows`). This is where a design is rounded to what
can be bought or made.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import limits
from ..errors import InfeasibleError
from ..requirements import (
    SpringFigures,
    holds,
    requirement_rows,
    stress_row,
)
from ..spec import Requirements, Spec
from ..springs import helical as hx
from ..units import G_STANDARD
from .kappa import KappaModel
from .windows import Grid, batched_windows, dashpot_window, grid_steps, mass_grid, window_seconds


def catalogue_axes(req: Requirements):
    """The catalogue's wire diameters, coil radii and turns within the bounds (1-D arrays);
    a bound with equal ends fixes the value, on the catalogue or not."""
    lo, hi = req.wire_diameter
    d = np.array([lo] if lo == hi else
                 [w for w in req.wire_diameters if lo - 1e-12 <= w <= hi + 1e-12])
    return d, grid_steps(*req.coil_radius, req.coil_radius_step), \
        grid_steps(*req.active_turns, req.turn_step)


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
        from ..analysis import spring_screens as ss

        vib = ss.screen_vibration(spec, req)
        harmonics = se.harmonics_hz(vib)
        if vib is not None:
            def fatigue(cc, l0, swing):
                return ss.screen_fatigue(spec, d[cc], r[cc], n[cc], kappa[cc], l0, swing)
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
    from ..analysis import spring_screens as ss

    if kappa is None:
        kappa = hx.stiffness_r(d, r, n, mat.shear_modulus)
    if mat.grade is None:  # the stress against the spec's allowable; coil clash and buckling
        ok = ok & holds([stress_row(mat)],
                        {"stress": hx.shear_stress_r(F_max, d, r, mat.stress_correction)})
        return _where(ok, lambda i: ss.geometry_screen(spec, *_take(i, d, r, n, kappa, l0)))
    return _where(ok, lambda i: ss.screen(spec, *_take(i, d, r, n, kappa, l0), harmonics))


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


def objective_values(req: Requirements, m, spring_mass, window=None, central=0.0, *,
                     gov):
    """The objective of candidates; ``window`` (from :func:`dashpot_window`) for the dynamic
    objectives; ``gov`` the governor, whose :meth:`~govopt.governors.base.Governor.moving_mass`
    counts every moving mass."""
    if req.objective == "spring_mass":
        return spring_mass
    if req.objective == "settling_time":
        return window["settling"]
    if req.objective == "vibration":
        return window["vibration"]
    return gov.moving_mass(m, central, spring_mass)  # every moving mass, the default


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
        values = objective_values(req, m, smass[cols], central=km.central[rows, 0],
                                  gov=spec.governor)
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


def batches(size: int, batch: int):
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
    for part in batches(order.size, batch):
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
                                                         km.central[rows[sel], 0],
                                                         gov=spec.governor), np.inf)
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
    win = batched_windows(spec, req, km, grid, cell_rows, centre)
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
    win = batched_windows(spec, req, km, grid, cell_rows, centre)
    score = np.where(win["feasible"],
                     objective_values(req, None, None, win, gov=spec.governor), np.inf)
    return np.argsort(score[np.searchsorted(uniq, key)], kind="stable")


#: the shares of the design's dynamics work (:data:`govopt.limits.MAX_DESIGN_DYNAMICS_SECONDS`)
#: the surrogate ordering the candidates and the lattice screening them may take at most
SURROGATE, LATTICE = 0.3, 0.3


def _affordable_cells(spec, req, rows, kappa, width: float, share: float):
    """:func:`_cells` at ``width``, widened (doubled) until their dash-pot windows take at most
    ``share`` of what the running search has left (:func:`govopt.limits.charge`); ``uniq``
    None where even a cell per mass row would not."""
    work = limits.running()
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





def check_grids(spec: Spec, req: Requirements) -> None:
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
