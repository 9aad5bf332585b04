"""The load-change analysis of one design or many at once: first arrival, over-regulation and
settling of the transient of eq. (28), as a :class:`TransientSummary` (:func:`analyse_many`).

Hamabe, *Disturbing Actions of a Shaft Governor*, Part III, eqs. (28), (32), (37).  Event
analysis (over-regulation, first arrival, settling) is exact root finding on the analytic
response (:mod:`govopt.analysis.transient`): :func:`analyse_many` brackets the events on a grid
evaluated by :func:`grid_values` (the plain modal sum where the roots are well separated and
every mode decays: bracketing only, every reported figure is located on the Newton form) and
refines them by a vectorised bracketed Newton iteration.  Over-regulation is decided for all
``t >= 0`` (:mod:`govopt.analysis.over_regulation`); settling past the grid is
:mod:`govopt.analysis.settling`'s.

Inputs that are not finite, or ``a0 = 0``, raise ValueError naming the argument.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..limits import MAX_TRANSIENT_POINTS
from .over_regulation import Tail
from .settling import PER_PERIOD, envelope_settling, extrapolate_settling
from .transient import BLOCK, Response, local_max, modal_amplitudes, refine, refine_peaks
from .transient_cubic import classify_roots, hurwitz_margin, is_stable, pair_separations

__all__ = ["TransientSummary", "analyse_many", "grid_values", "over_regulation_many"]

_EFOLDS = 12.0  # default horizon: ln(1/band) + this many e-folds of the slowest mode


@dataclass(frozen=True)
class TransientSummary:
    """Load-change response of designs (Hamabe, Disturbing Actions of a Shaft Governor, III):
    arrays of the broadcast shape of :func:`analyse_many`'s inputs (``roots`` has a trailing
    axis of 3; one design: 0-d arrays).

    ``over_regulation`` is the largest excursion of ``xi`` past 0 on the side opposite to ``xi0``
    over all ``t >= 0`` (same units as ``xi``; 0.0 if it never crosses) -- the pendulum passing its
    new equilibrium.  It may be exponentially small (a crossing late in the tail; it underflows to 0
    past ~1e-300): decide with :func:`~govopt.analysis.over_regulation.over_regulates` on
    ``over_regulation_scaled``, the same excursion measured against the slowest mode's decay (see
    :class:`~govopt.analysis.over_regulation.Tail`), nan where undecided (conservatively:
    over-regulates). ``first_arrival_time`` is the first ``t > 0`` with ``xi = 0`` (inf if none).
    ``settling_time`` is the smallest ``T`` with ``|xi(t)| <= band * |xi0|`` for all ``t >= T``
    (``|xi0|`` replaced by ``max |xi|`` if ``xi0 = 0``); inf for an unstable design, or when a
    stable design has not settled within ``horizon`` (``|xi| <= band |xi0| / 4`` over its last
    quarter; then ``truncated`` is True: *not decided*, not 'never').  Where the event grid is cut
    at ``max_points`` before the response settles (a lightly damped pendulum under a huge flywheel)
    settling is found past it from the modes' envelope
    (:func:`~govopt.analysis.settling.envelope_settling`) and may exceed ``horizon``.  The horizon
    reaches every zero of ``xi`` and the largest far-side excursion
    (:class:`~govopt.analysis.over_regulation.Tail`).  For unstable designs ``over_regulation`` and
    the other events are those within ``horizon`` (the decision still covers all t).
    """

    roots: np.ndarray
    kind: np.ndarray
    stable: np.ndarray
    hurwitz_margin: np.ndarray
    over_regulation: np.ndarray
    first_arrival_time: np.ndarray
    settling_time: np.ndarray
    horizon: np.ndarray
    over_regulation_scaled: np.ndarray | None = None
    truncated: np.ndarray | None = None
    #: the time of the largest far-side excursion (an exact zero of ``xi'``; 0 if none)
    over_regulation_time: np.ndarray | None = None


def _exact_max(resp, t, xd, v, sign, clip, amp, lmax=None):
    """Exact maximum over t > 0 of v = sign * xi per row: the grid maximum, raised to the exact
    peaks of the lobes that the grid may have clipped (within ``clip * amp`` of it).  For v = |xi|
    pass sign = None (its interior local maxima are extrema of xi).  Returns the maxima and their
    times.  With a sign, grid maxima at or below zero are refined too where the slope allows the
    lobe to reach zero between the neighbouring grid points (a far-side lobe that the grid clipped,
    e.g. near a tangency).  ``lmax``: :func:`~govopt.analysis.transient.local_max` of v, if
    already known."""
    rows = np.arange(v.shape[0])
    kmax = np.argmax(v, axis=1)
    vmax = v[rows, kmax]
    r, k = local_max(v) if lmax is None else lmax
    vk = v[r, k]
    with np.errstate(invalid="ignore", over="ignore"):  # +-inf values of a growing design
        cand = (vk > 0) & (vk >= vmax[r] - clip * amp[r])
        if sign is not None:
            reach = (np.maximum(np.maximum(np.abs(xd[r, k - 1]), np.abs(xd[r, k])),
                                np.abs(xd[r, k + 1])) * (t[r, k + 1] - t[r, k - 1]))
            cand |= (vk <= 0) & (vk + reach >= 0)
    r, k = r[cand], k[cand]
    out = np.maximum(vmax, 0.0)
    tout = np.where(vmax > 0, t[rows, kmax], 0.0)
    grid = vmax > 0
    if r.size:
        r, k, te, xe = refine_peaks(resp, t, xd, r, k)
        val = np.abs(xe) if sign is None else sign[r] * xe
        order = np.lexsort((-val, r))  # per row, largest first
        r, te, val = r[order], te[order], val[order]
        first = np.unique(r, return_index=True)[1]
        r, te, val = r[first], te[first], val[first]
        up = val > out[r]
        out[r[up]], tout[r[up]] = val[up], te[up]
        grid &= ~np.isin(rows, r[up])
    g = np.nonzero(grid)[0]
    if g.size:  # a maximum read off the grid (e.g. its last point): its Newton-form value
        xg = resp.subset(g)(tout[g, None], nder=0)[:, 0, 0]
        vg = np.abs(xg) if sign is None else sign[g] * xg
        out[g], tout[g] = np.maximum(vg, 0.0), np.where(vg > 0, tout[g], 0.0)
    return out, tout


def _events_on_grid(resp, t, y, s0, band, d0, stable, per_period):
    """First arrival, over-regulation (and its time) and settling for designs sharing a grid
    width.

    resp: Response (order >= 2) for n designs; t (n, M) increasing per row, t[:, 0] = 0;
    y = grid_values(resp, t) (xi, xi'); the band is band * |d0| (or band * max |xi| where
    d0 = 0).  Events
    are bracketed on the grid; lobes the grid may have clipped (grid peaks close to zero, to the
    maximum, or to the band) are refined to their exact extremum first, then every event time
    is refined by bracketed Newton.
    """
    n, M = t.shape
    rows = np.arange(n)
    xi, xd = y[:, 0], y[:, 1]
    ax = np.abs(xi)
    amp = ax.max(axis=1)
    clip = 1.5 * (1.0 - math.cos(math.pi / per_period))  # grid's worst clipping of a lobe
    scale = np.abs(d0)
    z = np.nonzero(scale == 0)[0]
    if z.size:
        scale[z] = _exact_max(resp.subset(z), t[z], xd[z], ax[z], None, clip, amp[z])[0]
    b = band * scale
    v = -s0[:, None] * xi  # > 0 past the new equilibrium
    lr, lk = local_max(v)
    # --- first arrival: v from < 0 to >= 0 on the grid, or a clipped lobe reaching 0 earlier
    j = np.full(n, M)
    pos = np.nonzero(np.fmax.reduce(v, axis=1) > 0)[0]  # only rows reaching the far side cross
    if pos.size:
        w = v[pos]
        nxt = np.concatenate([w[:, 2:], w[:, -1:]], axis=1)  # runs of exact 0 (underflow) do
        cross = (w[:, :-1] < 0) & ((w[:, 1:] > 0) | ((w[:, 1:] == 0) & (nxt > 0)))  # not cross
        j[pos] = np.where(cross.any(axis=1), np.argmax(cross, axis=1), M)
    has = j < M
    lo = np.where(has, t[rows, np.minimum(j, M - 2)], np.nan)
    hi = np.where(has, t[rows, np.minimum(j + 1, M - 1)], np.nan)
    vk = v[lr, lk]
    near = (vk < 0) & (vk >= -0.02 * amp[lr]) & (lk < j[lr])
    r, k = lr[near], lk[near]
    if r.size:
        r, k, te, xe = refine_peaks(resp, t, xd, r, k)
        hit = -s0[r] * xe >= 0
        r, k, te = r[hit], k[hit], te[hit]
        first = np.unique(r, return_index=True)[1]  # earliest lobe per row (sorted by k)
        r, k, te = r[first], k[first], te[first]
        lo[r], hi[r], has[r] = t[r, k - 1], te, True
    arrival = np.full(n, np.inf)
    idx = np.nonzero(has)[0]
    if idx.size:
        arrival[idx] = refine(resp.subset(idx), 0, 0.0, lo[idx], hi[idx])
    # --- over-regulation: grid maximum, and the exact peaks of the lobes that may hold it
    over, t_over = _exact_max(resp, t, xd, v, -s0, clip, amp, (lr, lk))
    # --- settling: last time |xi| = b
    above = ax > b[:, None]
    anyab = above.any(axis=1)
    last = np.where(anyab, M - 1 - np.argmax(above[:, ::-1], axis=1), -1)
    settling = np.where(stable, 0.0, np.inf)
    settling[anyab & (last == M - 1)] = np.inf
    ok = stable & (last < M - 1)
    lo = t[rows, np.maximum(last, 0)]
    hi = t[rows, np.minimum(last + 1, M - 1)]
    sgn = np.sign(xi[rows, np.maximum(last, 0)])
    todo = ok & anyab
    # lobes after the last grid point above the band whose exact peak may still exceed it
    r, k = local_max(ax)
    late = (k > last[r]) & (ax[r, k] >= 0.9 * b[r]) & ok[r]
    r, k = r[late], k[late]
    if r.size:
        r, k, te, xe = refine_peaks(resp, t, xd, r, k)
        hit = np.abs(xe) > b[r]
        r, k, te, xe = r[hit], k[hit], te[hit], xe[hit]
        lastlobe = r.size - 1 - np.unique(r[::-1], return_index=True)[1]  # latest per row
        r, k, te, xe = r[lastlobe], k[lastlobe], te[lastlobe], xe[lastlobe]
        lo[r], hi[r], sgn[r], todo[r] = te, t[r, k + 1], np.sign(xe), True
    idx = np.nonzero(todo)[0]
    if idx.size:
        settling[idx] = refine(resp.subset(idx), 0, sgn[idx] * b[idx], lo[idx], hi[idx])
    return arrival, over, t_over, settling, b


#: Smallest relative root separation at which :func:`grid_values` sums the modes directly.
_MODAL_SEP = 1e-2


def grid_values(resp, t):
    """``xi`` and ``xi'`` (n, 2, T) at the event-search grid ``t`` (n, T): values that only
    bracket events and pick the lobes to refine -- every reported figure is located on the
    Newton form (:func:`~govopt.analysis.transient.refine`, :func:`_exact_max`).

    Where every mode decays and the roots are well separated (relative separation >= ``_MODAL_SEP``)
    the modal sum ``sum c_k exp(l_k t)`` (:func:`~govopt.analysis.transient.modal_amplitudes`) is
    used: a few exponentials per point instead of the divided differences, and no overflow (all
    ``exp(l t) <= 1``).  Its error is the amplitudes' rounding, of order ``eps / _MODAL_SEP**2 ~
    2e-12`` of the trajectory's scale (two root differences in the denominator;
    tests/test_transient.py measures below 1e-11 at the threshold, 1e-14 on typical designs), so a
    grid sign can differ from the Newton form's only where ``|xi|`` is that close to 0 (a lobe
    grazing zero at a grid point; the figure found is then rounding either way).  Other rows use the
    Newton form, bit for bit.

    Parameters
    ----------
    resp : Response [-]
        Prepared responses (:meth:`govopt.analysis.transient.Response.build`), one per row.
    t : ndarray [s]
        Grid times, shape (n, T) (or broadcastable to it).

    Returns
    -------
    ndarray [rad, rad/s]
        Shape (n, 2, T): ``xi`` and ``xi'`` (m, m/s for a length coordinate).

    References
    ----------
    [hamabe] Part III, eq. (28) and the constants of eqs. (38), (40) (the modal sum).

    Examples
    --------
    At ``t = 0`` the grid gives back the initial state (Example 3, case a, paper's
    coefficients, kgf-cm-s).

    >>> from govopt.analysis.transient import Response
    >>> resp, _ = Response.build(1.76, 24, 211.2, 840, -0.128, 0.0, 18.716, order=2)
    >>> y = grid_values(resp, np.array([[0.0, 0.5]]))
    >>> [round(float(v), 4) for v in y[0, :, 0]], round(float(y[0, 0, 1]), 4)
    ([-0.128, 0.0], -0.037)
    """
    n, T = resp.n, t.shape[-1]
    t = np.broadcast_to(t, (n, T))
    l = resp.roots
    with np.errstate(all="ignore"):
        c = modal_amplitudes(l, resp.d)
        modal = (np.isfinite(c).all(axis=1) & (l.real.max(axis=1) < 0)
                 & (pair_separations(l).min(axis=1) >= _MODAL_SEP))
    out = np.empty((n, 2, T))
    rest = np.nonzero(~modal)[0]
    if rest.size:
        out[rest] = resp.subset(rest)(t[rest], nder=1)
    cplx = (l.imag != 0).any(axis=1)
    step = max(1, BLOCK // max(T, 1))
    for rows in (np.nonzero(modal & ~cplx)[0], np.nonzero(modal & cplx)[0]):
        for s in range(0, rows.size, step):
            r = rows[s : s + step]
            tt, lr, cr = t[r], l[r], c[r]
            xi, xd, e = np.zeros(tt.shape), np.zeros(tt.shape), np.empty(tt.shape)
            if not cplx[r[0]]:  # three real modes
                lr, cr = lr.real, cr.real
                for k in range(3):
                    np.exp(np.multiply(lr[:, k, None], tt, out=e), out=e)
                    e *= cr[:, k, None]
                    xi += e
                    e *= lr[:, k, None]
                    xd += e
            else:  # a real mode and a conjugate pair: c_r e^{rt} + 2 Re(c_p e^{pt})
                k = np.arange(r.size)
                ir, ip = np.argmin(np.abs(lr.imag), axis=1), np.argmax(lr.imag, axis=1)
                rr, c_r = lr[k, ir].real[:, None], cr[k, ir].real[:, None]
                p, cp = lr[k, ip][:, None], cr[k, ip][:, None]
                cpp = cp * p
                np.exp(np.multiply(rr, tt, out=e), out=e)
                e *= c_r
                xi += e
                e *= rr
                xd += e
                ep = np.exp(np.multiply(p.real, tt, out=e))
                ep *= 2.0
                q = np.multiply(p.imag, tt, out=e)
                for f, a, b in ((np.cos, cp.real, cpp.real), (np.sin, -cp.imag, -cpp.imag)):
                    w = f(q)
                    w *= ep
                    xi += a * w
                    xd += b * w
            out[r, 0], out[r, 1] = xi, xd
    return out


def _modal_windows(roots, d, ok, H, per_period):
    """Where the response is, to 1e-12 relative, its slowest mode(s) alone: per design
    (grid_end, uniform_end, extrapolate), from the modal amplitudes (used only where the roots
    are well separated, relative separation >= 1e-3, so that the amplitudes are accurate).

    After ``T_w`` every faster mode is below 1e-12 of the slowest group.  If the slowest group
    is a complex pair, the response is then a pure damped sinusoid: the first arrival and the
    largest over-swing lie within ``T_w`` plus a few periods, and the settling crossing can be
    extrapolated from one exact extremum (heights fall by exp(-sigma pi / q) per half period);
    so the grid stops there (extrapolate = True).  If it is a real root, oscillation needs
    resolving only until ``T_w``.  Elsewhere the whole horizon is resolved.
    """
    l = roots
    well = ok & (pair_separations(l).min(axis=1) >= 1e-3)
    with np.errstate(all="ignore"):
        amp = np.abs(modal_amplitudes(l, d))
        sig = -l.real
        smin = sig.min(axis=1)
        slow = sig == smin[:, None]
        a_slow = np.where(slow, amp, 0.0).sum(axis=1)
        well &= np.isfinite(amp).all(axis=1) & (a_slow > 0) & (smin > 0)
        tk = np.log(amp / (1e-12 * a_slow[:, None])) / (sig - smin[:, None])
        t_w = np.where(slow | ~(tk > 0), 0.0, tk).max(axis=1)
    q = np.abs(l.imag).max(axis=1)
    osc = q > 0
    pair_slow = well & (slow.sum(axis=1) == 2)
    period = 2.0 * np.pi / np.where(osc, q, 1.0)
    window = np.minimum(H, t_w + 4.0 * period)
    grid_end = np.where(pair_slow, window, H)
    uni_end = np.where(osc, np.where(well, window, H), 0.0)
    return grid_end, uni_end, pair_slow


def analyse_many(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, band=0.02, horizon=None,
                 n_log=160, per_period=PER_PERIOD, max_points=MAX_TRANSIENT_POINTS):
    """The load-change response of one design or many at once (the one transient analysis:
    :func:`govopt.evaluate` calls it with one design, the design search with many).

    Hamabe, Disturbing Actions of a Shaft Governor, Part III, eqs. (28), (32), (37).  Each design
    gets its own grid: ``n_log`` log-spaced times from 1e-3 of its fastest time constant to its
    horizon, plus, if it oscillates, uniform times at ``per_period`` points per period (at most
    ``max_points``) over the part of the horizon where oscillation can still create events (where
    the roots are well separated, only until every faster mode is below 1e-12 of the slowest; a
    slowest damped pair's settling crossing is then extrapolated exactly from one extremum -- see
    :func:`_modal_windows`).  Designs are processed in batches of equal grid width.  The first zero
    of ``xi``, the largest opposite-side excursion (at a zero of ``xi'``) and the last band crossing
    are bracketed and refined by a vectorised bracketed Newton iteration on the analytic response
    (exact to rounding). Over-regulation is decided for all ``t >= 0``
    (:class:`~govopt.analysis.over_regulation.Tail`,
    :func:`~govopt.analysis.over_regulation.over_regulates`): the default horizon is ``(ln(1/band) +
    12)/decay`` (decay = slowest rate) for a stable design and a few slow periods (at most e^20
    growth) for an unstable one, extended to the window the dominant modes call for (the dominance
    time, and until no later far-side excursion can be larger than the one found), and doubled for
    the designs whose tail is not yet well inside the band; a stable design not settled within it is
    reported inf (``truncated``).  Where the uniform grid is cut at ``max_points`` before settling,
    settling comes from the modes' envelope (:func:`~govopt.analysis.settling.envelope_settling`).
    Returns a :class:`TransientSummary`; raises ValueError for non-finite inputs or ``a0 = 0`` (nan
    events only where the roots themselves overflow).

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28) (``a_i`` in kg m^2 s^-i in SI; any consistent set, the
        paper's is kgf-cm-s), broadcast against each other and the initial state.
    xi0 : float or array [rad]
        Initial deviation from the new equilibrium (m for a length coordinate).
    xi_dot0 : float or array [rad/s]
        Initial velocity (0 for a sudden load change).
    xi_ddot0 : float or array [rad/s^2]
        Initial acceleration
        (:func:`~govopt.analysis.transient_cubic.hamabe_initial_conditions`).
    band : float [-]
        Settling band, relative to ``|xi0|``.
    horizon : float or array [s], optional
        Time up to which events are sought (default: from the roots, see above).
    n_log : int [-]
        Log-spaced grid points (dimensionless count).
    per_period : int [-]
        Uniform grid points per period of the fastest oscillation.
    max_points : int [-]
        Cap on a design's uniform grid.

    Returns
    -------
    TransientSummary [-]
        Roots [1/s], kind, stability, Hurwitz margin [-], over-regulation [rad], first arrival,
        settling and horizon [s], per design.

    References
    ----------
    [hamabe] Part III, eqs. (28), (32), (37); [hurwitz].

    Examples
    --------
    Example 3, case a (the paper's coefficients, kgf-cm-s) with its dash-pot a1 = 24 and with
    a1 = 15: three real roots, then a complex pair; neither over-regulates, as the paper finds.

    >>> s = analyse_many(1.76, [24, 15], 211.2, 840, -0.128, 0.0, 18.716)
    >>> s.kind.tolist(), s.over_regulation.tolist(), s.first_arrival_time.tolist()
    (['real', 'complex'], [0.0, 0.0], [inf, inf])

    A hand-checkable lightly damped case: roots -50 and -0.1 +- 1i
    (``(s + 50)(s^2 + 0.2 s + 1.01)``) from rest at ``xi0 = 1``: the fast mode is spent at
    once, so the far-side peak is about ``exp(-0.1 pi)`` = 0.7304 near t = pi (the damping and
    the fast mode shift both slightly).

    >>> s = analyse_many(1.0, 50.2 / 3, 11.01 / 3, 50.5, 1.0, 0.0, 0.0)
    >>> round(float(s.over_regulation), 4), round(float(s.over_regulation_time), 3)
    (0.7303, 3.162)
    """
    if not band > 0:
        raise ValueError("band must be positive")
    resp, shape = Response.build(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, order=2)
    c = resp.c
    n = resp.n
    roots = resp.roots
    d = resp.d
    valid = np.isfinite(roots).all(axis=-1) & np.isfinite(d[:, :4]).all(axis=-1)
    stable = is_stable(*c) & valid
    margin = hurwitz_margin(*c)
    kind = classify_roots(roots, 1e-6)
    rr = np.where(valid[:, None], roots, -1.0)
    if horizon is None:
        H = _default_horizon(rr, band, stable)
    else:
        H = np.broadcast_to(np.asarray(horizon, float), shape).reshape(-1).copy()
        if not np.all(H > 0):
            raise ValueError("horizon must be positive")
    lam_max, _, _, omega = _time_scales(rr)
    osc = omega > 0
    dt = np.where(osc, 2.0 * np.pi / np.where(osc, omega, 1.0) / per_period, 0.0)
    # side the response starts on (sign of the first non-zero initial derivative)
    s0 = np.zeros(n)
    for k in range(d.shape[1] - 1, -1, -1):
        s0 = np.where(d[:, k] != 0, np.sign(d[:, k]), s0)
    arrival, over, t_over, settling = (np.full(n, np.nan) for _ in range(4))
    unresolved = np.zeros(n, bool)
    vi = np.nonzero(valid)[0]
    pos = np.full(n, -1)
    pos[vi] = np.arange(vi.size)
    late = Tail(resp.subset(vi), s0[vi])
    if horizon is None:
        H[vi] = np.maximum(H[vi], late.need)
    u_log = np.linspace(0.0, 1.0, n_log)
    todo = vi
    for attempt in range(8):
        g_end, u_end, extrap = _modal_windows(rr[todo], d[todo], stable[todo], H[todo],
                                              per_period)
        n_uni = np.where(osc[todo], np.ceil(np.minimum(u_end / np.where(osc[todo], dt[todo],
                                                                         1.0), max_points)), 0)
        truncated = n_uni >= max_points
        u_end = np.where(osc[todo], np.minimum(u_end, n_uni * dt[todo]), 0.0)
        g_end = np.where(truncated, np.minimum(g_end, u_end), g_end)
        H[todo] = np.where(truncated & ~extrap, g_end, H[todo])
        # batches of equal grid width: uniform parts rounded up to a power of two
        width = np.where(n_uni > 0, 2 ** np.ceil(np.log2(np.maximum(n_uni, 1))), 0)
        redo, H_redo = [], []
        for wd in np.unique(width).astype(np.int64):
            sel = np.nonzero(width == wd)[0]
            per = max(1, (1 << 22) // (n_log + 1 + wd))
            for s in range(0, sel.size, per):
                loc = sel[s : s + per]
                idx = todo[loc]
                Ge, Ue = g_end[loc, None], u_end[loc, None]
                t0 = np.minimum(1e-3 / lam_max[idx, None], 1e-3 * Ge)
                tl = t0 * (Ge / t0) ** u_log[None, :]
                if wd:  # merge the uniform part into the (increasing) log-spaced one
                    tu = Ue * np.linspace(0.0, 1.0, wd + 1)[None, :]
                    t = np.sort(np.concatenate([tl, tu], axis=1), axis=1)
                else:
                    t = np.concatenate([np.zeros((idx.size, 1)), tl], axis=1)
                sub = resp.subset(idx)
                y = grid_values(sub, t)
                a_, o_, to_, st_, b = _events_on_grid(sub, t, y, s0[idx], band, d[idx, 0],
                                                      stable[idx], per_period)
                ex = extrap[loc]
                settled = _tail_ok(t, y[:, 0], b)
                tail = settled | ex
                st_ = np.where(stable[idx] & ~tail, np.inf, st_)  # not settled in horizon
                if ex.any():
                    e = np.nonzero(ex)[0]
                    st_[e] = extrapolate_settling(sub.subset(e), t[e], y[e], b[e], st_[e])
                # grid cut at max_points before settling: the modes' envelope decides
                cut = truncated[loc] & stable[idx] & ~settled
                if cut.any():
                    e = np.nonzero(cut)[0]
                    env = envelope_settling(sub.subset(e), b[e], per_period, max_points)
                    st_[e] = np.where(np.isnan(env), np.inf, env)
                    unresolved[idx[e]] = np.isnan(env)
                arrival[idx], over[idx], t_over[idx], settling[idx] = a_, o_, to_, st_
                if horizon is None:
                    # longer: to settle (doubling), or until no later far-side excursion can
                    # exceed the one found (Tail.wanted)
                    want = np.where(stable[idx] & ~tail & ~truncated[loc], 2.0 * H[idx], 0.0)
                    w_over = late.wanted(pos[idx], o_)
                    want = np.maximum(want, np.where(ex | truncated[loc], 0.0, w_over))
                    more = want > H[idx] * (1.0 + 1e-9)
                    redo.append(idx[more])
                    H_redo.append(want[more])
        todo = np.concatenate(redo) if redo else np.zeros(0, np.int64)
        if todo.size == 0 or attempt == 6:
            break
        H[todo] = np.concatenate(H_redo)
    scaled = np.full(n, np.nan)
    scaled[vi] = late.scaled(np.arange(vi.size), over[vi], t_over[vi], H[vi])

    def rs(a):
        return a.reshape(shape + a.shape[1:])

    return TransientSummary(
        roots=rs(roots), kind=rs(kind), stable=rs(stable), hurwitz_margin=rs(margin),
        over_regulation=rs(over), first_arrival_time=rs(arrival), settling_time=rs(settling),
        horizon=rs(H), over_regulation_scaled=rs(scaled),
        truncated=rs(unresolved | (stable & np.isinf(settling))), over_regulation_time=rs(t_over),
    )


def _time_scales(roots):
    """(lam_max, lam_min, decay, omega) per row of roots (..., 3): finite, positive scales."""
    mag = np.abs(roots)
    lam_max = mag.max(axis=-1)
    nz = np.where(mag > 0, mag, np.inf).min(axis=-1)
    lam_max = np.where(lam_max > 0, lam_max, 1.0)
    lam_min = np.where(np.isfinite(nz), nz, lam_max)
    decay = -roots.real.max(axis=-1)  # > 0 iff every mode decays
    omega = np.abs(roots.imag).max(axis=-1)
    return lam_max, lam_min, decay, omega


def _default_horizon(roots, band, stable):
    """A time after which a stable response is far inside the band (vectorised over rows)."""
    lam_max, lam_min, decay, omega = _time_scales(roots)
    with np.errstate(divide="ignore"):
        settle = (math.log(1.0 / band) + _EFOLDS) / np.where(decay > 0, decay, np.nan)
    grow = np.maximum(roots.real.max(axis=-1), 0.0)
    with np.errstate(divide="ignore"):
        unstable = np.minimum(40.0 * 2.0 * np.pi / lam_min, 20.0 / np.where(grow > 0, grow, 0.0))
    h = np.where(stable & np.isfinite(settle), settle, unstable)
    return np.where(np.isfinite(h) & (h > 0), h, 40.0 * 2.0 * np.pi / lam_min)


def _tail_ok(t, xi, b):
    """Whether a stable response is well inside the band over the last quarter of its grid
    (rows of t, xi; b per row): then the horizon is long enough for settling."""
    tail = t >= 0.75 * t[..., -1:]
    return np.max(np.where(tail, np.abs(xi), 0.0), axis=-1) <= 0.25 * b


def over_regulation_many(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, horizon=None):
    """Over-regulation of many designs at once (see :func:`analyse_many`); 0.0 if none.

    Hamabe, Disturbing Actions of a Shaft Governor, Part III: the largest excursion of ``xi``
    past the new equilibrium, on the side opposite to ``xi0``, over all ``t >= 0``.  It may be
    exponentially small: decide over-regulation with
    :func:`~govopt.analysis.over_regulation.over_regulates` on
    ``analyse_many(...).over_regulation_scaled``.

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28) (``a_i`` in kg m^2 s^-i in SI; any consistent set, the
        paper's is kgf-cm-s), broadcast against each other and the initial state.
    xi0 : float or array [rad]
        Initial deviation from the new equilibrium (m for a length coordinate).
    xi_dot0 : float or array [rad/s]
        Initial velocity (0 for a sudden load change).
    xi_ddot0 : float or array [rad/s^2]
        Initial acceleration
        (:func:`~govopt.analysis.transient_cubic.hamabe_initial_conditions`).
    horizon : float or array [s], optional
        As :func:`analyse_many`'s.

    Returns
    -------
    ndarray [rad]
        The largest far-side excursion (m for a length coordinate), 0.0 if none.

    References
    ----------
    [hamabe] Part III, the definition of over-regulation.

    Examples
    --------
    Example 3, case a (paper's coefficients, none, as the paper finds) beside the lightly damped
    case of :func:`analyse_many` (the far-side peak about ``exp(-0.1 pi)``):

    >>> o = over_regulation_many([1.76, 1.0], [24, 50.2 / 3], [211.2, 11.01 / 3], [840, 50.5],
    ...                          [-0.128, 1.0], 0.0, [18.716, 0.0])
    >>> [round(float(v), 4) for v in o]
    [0.0, 0.7303]
    """
    return analyse_many(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, horizon=horizon).over_regulation
