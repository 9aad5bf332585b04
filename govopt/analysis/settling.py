"""Settling of a load change past the event grid: from the slowest damped pair's decrement
once only it is left (:func:`extrapolate_settling`), and from the modes' envelope where the grid
is cut before the response settles (:func:`envelope_settling`, a lightly damped pendulum under
a huge flywheel).

Hamabe, *Disturbing Actions of a Shaft Governor*, Part III, eq. (28).  Settling is the last
time ``|xi| = b`` (the band); each is located on the analytic response
(:func:`govopt.analysis.transient.refine`).
"""

from __future__ import annotations

import numpy as np

from ..limits import MAX_TRANSIENT_POINTS
from .transient import local_max, modal_amplitudes, refine, refine_peaks
from .transient_cubic import pair_separations

__all__ = ["PER_PERIOD", "envelope_settling", "extrapolate_settling"]

_EPS = float(np.finfo(float).eps)
PER_PERIOD = 24  # event-search grid points per period of the fastest oscillation


def extrapolate_settling(resp, t, y, b, settled):
    """Settling of designs whose grid ends once only their slowest damped pair is left (see
    :func:`govopt.analysis.transient_events.analyse_many`'s modal windows): from the last exact
    extremum ``t_e`` in the window, the extrema are ``t_e + k pi/q`` with heights falling by
    ``exp(-sigma pi/q)`` each; the last one above the band and the next bracket the crossing,
    refined on the analytic response.  Rows whose
    last extremum is already inside the band keep ``settled`` (found within the window).

    Parameters
    ----------
    resp : Response [-]
        Prepared responses (:meth:`govopt.analysis.transient.Response.build`), one per row.
    t : ndarray [s]
        The window's grid, shape (n, M).
    y : ndarray [rad, rad/s]
        ``xi`` and ``xi'`` on the grid, shape (n, 2, M)
        (:func:`~govopt.analysis.transient_events.grid_values`).
    b : ndarray [rad]
        The band, per design (m for a length coordinate).
    settled : ndarray [s]
        Settling times found within the window (nan where none).

    Returns
    -------
    ndarray [s]
        Settling times.

    References
    ----------
    [hamabe] Part III, eq. (28) (a damped pair's extrema fall by a constant ratio); the
    extrapolation is govopt's own.

    Examples
    --------
    Roots -50 and -0.1 +- 1i from rest at ``xi0 = 1``, band 0.02, the grid cut at 10 s: the
    settling found past it, 38.246 s, agrees with a brute-force scan of 600 001 points over
    60 s (38.246), and with ``ln(50) / 0.1`` = 39.1 less part of a half period, by hand.

    >>> from govopt.analysis.transient import Response
    >>> from govopt.analysis.transient_events import grid_values
    >>> resp, _ = Response.build(1.0, 50.2 / 3, 11.01 / 3, 50.5, 1.0, 0.0, 0.0, order=2)
    >>> t = np.linspace(0.0, 10.0, 241)[None, :]
    >>> st = extrapolate_settling(resp, t, grid_values(resp, t), np.array([0.02]),
    ...                           np.array([np.nan]))
    >>> round(float(st[0]), 3)
    38.246
    """
    n, M = t.shape
    rows = np.arange(n)
    xd = y[:, 1]
    sd = np.sign(xd)
    ch = (sd[:, :-1] * sd[:, 1:]) < 0
    has = ch.any(axis=1)
    j = M - 2 - np.argmax(ch[:, ::-1], axis=1)
    out = settled.copy()
    idx = np.nonzero(has)[0]
    if idx.size == 0:
        return out
    sub = resp.subset(idx)
    te = refine(sub, 1, 0.0, t[idx, j[idx]], t[idx, j[idx] + 1])
    xe = sub(te[:, None], nder=0)[:, 0, 0]
    up = np.abs(xe) > b[idx]
    idx, te, xe, sub = idx[up], te[up], xe[up], sub.subset(np.nonzero(up)[0])
    if idx.size == 0:
        return out
    lam = sub.roots[np.arange(idx.size), np.argmax(sub.roots.real, axis=1)]
    half = np.pi / np.abs(lam.imag)
    step = -lam.real * half  # log-decrement per half period
    k = np.floor(np.log(np.abs(xe) / b[idx]) / step)
    for _ in range(3):  # make sure the k-th extremum is above the band (rounding at the edge)
        tk = te + k * half
        vk = sub(tk[:, None], nder=0)[:, 0, 0]
        k = np.where((np.abs(vk) <= b[idx]) & (k > 0), k - 1, k)
    tk = te + k * half
    vk = sub(tk[:, None], nder=0)[:, 0, 0]
    out[idx] = refine(sub, 0, np.sign(vk) * b[idx], tk, tk + half)
    del rows
    return out


def _last_exit(resp, t, y, b):
    """Last time ``|xi| = b`` on the window grids ``t`` (n, M) with values ``y`` (n, 2, M):
    bracketed at the last grid point above ``b``, or at the exact peak of a later lobe the grid
    clipped (grid peak >= 0.9 b), and refined on the Newton form; nan where nothing in the
    window is above ``b`` or its last point still is (the caller widens the window)."""
    n, M = t.shape
    rows = np.arange(n)
    xi, xd = y[:, 0], y[:, 1]
    ax = np.abs(xi)
    above = ax > b[:, None]
    last = np.where(above.any(axis=1), M - 1 - np.argmax(above[:, ::-1], axis=1), -1)
    j = np.maximum(last, 0)
    lo, hi = t[rows, j], t[rows, np.minimum(j + 1, M - 1)]
    sgn = np.sign(xi[rows, j])
    r, k = local_max(ax)
    late = (k > last[r]) & (ax[r, k] >= 0.9 * b[r])
    if late.any():
        r, k, te, xe = refine_peaks(resp, t, xd, r[late], k[late])
        hit = np.abs(xe) > b[r]
        r, k, te, xe = r[hit], k[hit], te[hit], xe[hit]
        lastlobe = r.size - 1 - np.unique(r[::-1], return_index=True)[1]  # latest per row
        r, k, te, xe = r[lastlobe], k[lastlobe], te[lastlobe], xe[lastlobe]
        lo[r], hi[r], sgn[r], last[r] = te, t[r, k + 1], np.sign(xe), k
    out = np.full(n, np.nan)
    ok = np.nonzero((last >= 0) & (last < M - 1))[0]
    if ok.size:
        out[ok] = refine(resp.subset(ok), 0, sgn[ok] * b[ok], lo[ok], hi[ok])
    return out


def envelope_settling(resp, b, per_period=PER_PERIOD, max_points=MAX_TRANSIENT_POINTS):
    """Settling time (last ``|xi| = b``) of stable designs with a real root ``r`` and a damped
    pair ``p`` whose event grid is cut at ``max_points`` (a pendulum's 0.3 s swing under a huge
    flywheel's 1e5 s decay), without a grid over the whole transient.

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (28): ``xi = c_r e^{r t} +
    2 Re(c_p e^{p t})`` (:func:`modal_amplitudes`), so ``|xi(t)| <= E(t) = |c_r| e^{r t} +
    2 |c_p| e^{Re(p) t}``, a decreasing envelope.  Past ``T_E`` with ``E(T_E) = b`` (bisected,
    ``b`` lowered by 1e-9 to cover the amplitudes' rounding) ``xi`` stays in the band, so the
    last exit lies before it; it is searched on a grid of ``per_period`` points per period of
    the pair over the last 2, 4, 8, ... periods before ``T_E`` until one is above ``b`` (the
    envelope changes little over a period, so usually the first window holds it), then located
    on the analytic response (:func:`_last_exit`).  ``b`` in the units of ``xi``, per design.
    Returns seconds, nan where not resolved (roots not well separated -- relative separation
    below 1e-3, where the amplitudes lose accuracy -- or a window of ``max_points`` points).

    Parameters
    ----------
    resp : Response [-]
        Prepared responses (:meth:`govopt.analysis.transient.Response.build`), one per row.
    b : ndarray [rad]
        The band, per design (m for a length coordinate).
    per_period : int [-]
        Grid points per period of the pair (dimensionless count).
    max_points : int [-]
        Largest window searched (dimensionless count).

    Returns
    -------
    ndarray [s]
        Settling times, nan where not resolved.

    References
    ----------
    [hamabe] Part III, eq. (28); the envelope bound is govopt's own.

    Examples
    --------
    A pendulum of period ``2 pi / 10`` s on a mode decaying at 1e-8 1/s, from ``xi0 = -0.1``,
    band 0.002: the slow mode alone sets it, ``ln(0.1 / 0.002) / 1e-8`` s, by hand.

    >>> from govopt.analysis.transient import Response
    >>> resp, _ = Response.build(1.0, 2e-5 / 3 + 1e-8 / 3, (100.0 + 2e-5 * 1e-8) / 3,
    ...                           100.0 * 1e-8, -0.1, 0.0, 0.0, order=2)
    >>> round(float(envelope_settling(resp, np.array([0.002]))[0]), 1)  # ln(50) / 1e-8
    391202300.5
    """
    n = resp.n
    out = np.full(n, np.nan)
    l = resp.roots
    with np.errstate(all="ignore"):
        c = modal_amplitudes(l, resp.d)
        ok = ((l.imag != 0).any(axis=1) & (l.real.max(axis=1) < 0) & np.isfinite(c).all(axis=1)
              & (pair_separations(l).min(axis=1) >= 1e-3))
    idx = np.nonzero(ok)[0]
    if idx.size == 0:
        return out
    l, c, b = l[idx], c[idx], np.asarray(b, float)[idx]
    k = np.arange(idx.size)
    ir, ip = np.argmin(np.abs(l.imag), axis=1), np.argmax(l.imag, axis=1)
    amp = np.stack([np.abs(c[k, ir].real), 2.0 * np.abs(c[k, ip])], axis=1)
    sig = -np.stack([l[k, ir].real, l[k, ip].real], axis=1)
    target = b * (1.0 - 1e-9)
    with np.errstate(divide="ignore"):  # each term is below target / 2 after its hi
        hi = np.maximum(np.log(2.0 * amp / target[:, None]) / sig, 0.0).max(axis=1)
    lo = np.zeros_like(hi)
    for _ in range(200):  # E decreasing: E(lo) > target >= E(hi)
        mid = 0.5 * (lo + hi)
        up = (amp * np.exp(-sig * mid[:, None])).sum(axis=1) > target
        lo, hi = np.where(up, mid, lo), np.where(up, hi, mid)
        if np.all(hi - lo <= 4 * _EPS * hi):
            break
    period = 2.0 * np.pi / l[k, ip].imag
    todo, periods = k, 2
    while todo.size and periods * per_period <= max_points:
        m = periods * per_period + 1
        t0 = np.maximum(hi[todo] - periods * period[todo], 0.0)
        t = t0[:, None] + (hi[todo] - t0)[:, None] * np.linspace(0.0, 1.0, m)[None, :]
        sub = resp.subset(idx[todo])
        st = _last_exit(sub, t, sub(t, nder=1), b[todo])
        out[idx[todo]] = np.where(np.isnan(st) & (t0 == 0.0), 0.0, st)  # never above b
        todo = todo[np.isnan(st) & (t0 > 0.0)]
        periods *= 2
    return out
