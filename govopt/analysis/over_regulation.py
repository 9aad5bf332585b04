"""Over-regulation of a load change for all ``t >= 0``, not within a horizon: what the
dominant mode(s) decide, how long a window the root finding needs, and the one decision
:func:`over_regulates` that the evaluator, the design search and the Excel sheet all use.

Hamabe, *Disturbing Actions of a Shaft Governor*, Part III: over-regulation is the pendulum
passing its new equilibrium.  The response of eq. (28) is a sum of three exponential modes, so
after a dominance time the sign of ``xi`` is that of the slowest mode(s), and only the window
before it needs root finding (:class:`Tail` has the proof).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["OVER_TOL", "Tail", "over_regulates"]

_EPS = float(np.finfo(float).eps)

#: Tolerance of the over-regulation decision, relative to ``|xi0|``: a far-side excursion, or a
#: dominant-mode coefficient, measured against the slowest mode's decay (see
#: :func:`over_regulates`) at or below ``OVER_TOL |xi0|`` counts as none.  It is the solver's
#: rounding level: the response is guaranteed to 1e-9 of the trajectory's scale in the hardest
#: cases (near-repeated and stiff roots, checked against mpmath at 50 digits in the tests), so
#: an excursion below that cannot be told from rounding.
OVER_TOL = 1e-9


def over_regulates(over_regulation_scaled, xi0):
    """The one decision "does this load change over-regulate, at any ``t >= 0``?".

    Hamabe, Disturbing Actions of a Shaft Governor, Part III: over-regulation is the pendulum
    passing its new equilibrium, ``xi(t)`` changing sign.  ``over_regulation_scaled`` (rad) is
    :attr:`~govopt.analysis.transient_events.TransientSummary.over_regulation_scaled` (or the array
    of :func:`~govopt.analysis.transient_events.analyse_many`): ``-s0 xi(t) exp(-rho t)`` (``s0``
    the side the response starts on, ``rho`` the largest real part of the roots) at the largest
    far-side excursion, or its upper limit as ``t -> inf`` if larger (with three real roots: its
    exact supremum over ``t >= 0``); positive exactly when ``xi`` crosses zero (:class:`Tail`).
    Scaling by the slowest mode keeps a crossing late in the tail visible: its plain amount is
    exponentially small (it may even underflow), which is why the decision is not made on
    :attr:`~govopt.analysis.transient_events.TransientSummary.over_regulation` itself.  True where
    ``over_regulation_scaled > OVER_TOL |xi0|``, and where it is nan (not decided, e.g. a grid
    truncated before the dominance time): conservative.  ``xi0`` in rad.

    Parameters
    ----------
    over_regulation_scaled : float or array [rad]
        The scaled far-side excursion (see above); nan where undecided.
    xi0 : float or array [rad]
        Initial deviation from the new equilibrium, ``alpha1 - alpha0``.

    Returns
    -------
    bool or ndarray of bool [-]
        True where the load change over-regulates (or is undecided).

    References
    ----------
    [hamabe] Part III, the definition of over-regulation; the tolerance is govopt's own.

    Examples
    --------
    Example 3's unloading (xi0 = -0.128 rad): the tolerance is ``1e-9 * 0.128`` = 1.28e-10 rad,
    so an excursion of 2e-10 rad counts, 0 does not; undecided counts (conservative).

    >>> over_regulates(float("nan"), -0.128)
    True
    >>> over_regulates(0.0, -0.128), over_regulates(2e-10, -0.128), over_regulates(1e-6, -0.128)
    (False, True, True)
    """
    d = np.asarray(over_regulation_scaled, dtype=float)
    out = ~(d <= OVER_TOL * np.abs(np.asarray(xi0, dtype=float)))
    return bool(out) if out.ndim == 0 else out


def _dominance_time(a, b, w, g, c):
    """Smallest ``T >= 0`` with ``(a + b min(t, w)) exp(-g t) <= c`` for every ``t >= T``
    (arrays; ``a, b >= 0``, ``w`` in ``(0, inf]``, ``g > 0``, ``c > 0``).

    The left side is increasing then decreasing in ``t`` (its log-derivative
    ``b / (a + b t) - g`` falls, and is ``-g`` past ``w``), peaking at
    ``t_pk = clip(1/g - a/b, 0, w)``: T is 0 if the peak is at most ``c``, else its crossing of
    ``c`` on the falling side, bracketed by the explicit bounds ``ln((a + b w)/c)/g`` and
    ``max(ln(2a/c), 2 ln(4b/(e g c)))/g`` (from ``t exp(-g t/2) <= 2/(e g)``) and bisected.
    The upper end of the final bracket is returned, so T is never too small.

    >>> round(float(_dominance_time(2.0, 0.0, np.inf, 1.0, 1.0)), 12)   # 2 e^-t <= 1: ln 2
    0.69314718056
    """
    a, b, w, g, c = np.broadcast_arrays(*(np.asarray(v, float) for v in (a, b, w, g, c)))

    def logphi(t):
        return np.log(a + b * np.minimum(t, w)) - g * t

    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        lc = np.log(c)
        tpk = np.where(b > 0, np.clip(1.0 / g - a / np.where(b > 0, b, 1.0), 0.0, w), 0.0)
        hi1 = np.log((a + b * w) / c) / g
        hi2 = np.maximum(np.log(2.0 * a / c), 2.0 * np.log(4.0 * b / (math.e * g * c))) / g
        hi = np.fmax(np.fmin(hi1, hi2), tpk)
        lo = tpk.copy()
        need = logphi(tpk) > lc
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            above = logphi(mid) > lc
            lo = np.where(above, mid, lo)
            hi = np.where(above, hi, mid)
            if not np.any(need & (hi - lo > 4 * _EPS * hi)):
                break
    return np.where(need, hi, 0.0)


def _newton_real(y, l1, l2):
    """Newton coefficients ``(K1, K2)`` of a state ``y = (y, y', y'')`` on real nodes
    ``(l1, l2, .)``: ``K1 = y' - l1 y``, ``K2 = y'' - (l1 + l2) y' + l1 l2 y``."""
    return y[1] - l1 * y[0], y[2] - (l1 + l2) * y[1] + l1 * l2 * y[0]


class Tail:
    """Over-regulation for all ``t >= 0``: what the dominant mode(s) decide, and how long a
    window the root finding needs (Hamabe, Disturbing Actions of a Shaft Governor, eq. (28)).

    Let ``rho`` be the largest real part of the roots and ``s0`` the side the response starts
    on.  ``u(t) = xi(t) exp(-rho t)`` has the sign of ``xi``, so ``xi`` over-regulates iff
    ``-s0 u > 0`` somewhere; ``over_regulation_scaled`` is the larger of ``-s0 u`` at the
    largest far-side excursion found and the part the modes decide below, clipped at 0.  It is
    compared with ``OVER_TOL |xi0|`` (:func:`over_regulates`): ``u`` does not decay, so its
    rounding stays at the level of the initial state for all ``t``.

    **Three real roots** ``l1 >= l2 >= l3`` (repeated or not).  In Newton form on the nodes
    ``(l1, l2, l3)``, ``u = y + K1 g[0, m2] + K2 g[0, m2, m3]`` with ``m_k = l_k - l1 <= 0`` and
    ``g[...]`` the divided differences of ``s -> exp(s t)``, so
    ``u'(t) = exp(m2 t) (K1 + K2 psi(t))``, ``psi(t) = (1 - exp(-(l2 - l3) t))/(l2 - l3)``
    (``= t`` for ``l2 = l3``).  ``psi`` is increasing, so ``u'`` changes sign at most once, at
    ``t_c`` with ``psi(t_c) = -K1/K2``: ``u`` is monotone on ``[0, t_c]`` and on
    ``[t_c, inf)``, and ``sup (-s0 u) = max(-s0 u(0), -s0 u(t_c), -s0 u(inf))`` exactly, with
    ``u(inf) = N1 / ((l1 - l2)(l1 - l3))``, ``N1 = ((A - l2)(A - l3) x0)_0 = xi'' - (l2 + l3)
    xi' + l2 l3 xi`` (the slowest mode's coefficient; ``+-inf`` with the sign of ``N1`` for a
    repeated slowest root).  No search is needed for the decision.  The same holds for
    ``xi' exp(-rho t)`` (state ``(xi', xi'', xi''')``), so every zero of ``xi`` and ``xi'``
    lies before the last sign change of these two, which is bracketed here (doubling from
    ``t_c``): a window reaching it holds every event, and the largest far-side excursion.

    **A real root r and a pair rho_p +- i q.**  Exactly ``xi = c_r e^{r t} + P(t)`` with
    ``c_r = N_r / |r - p|^2``, ``N_r = xi'' - 2 rho_p xi' + |p|^2 xi`` and the pair part
    ``P = e^{rho_p t} (P0 cos q t + (B/q) sin q t)``, ``P0 = xi0 - c_r``,
    ``B = xi'(0) - r c_r - rho_p P0``, of amplitude ``Amp = hypot(P0, B/q)``, so
    ``|P(t)| <= e^{rho_p t} (|P0| + |B| min(t, 1/q))``.

    * ``rho_p > r`` (the pair is slowest): ``-s0 u -> -s0 Amp cos(q t - theta)``, whose upper
      limit is ``Amp``: the response crosses zero for ever unless the pair part vanishes
      (``Amp <= OVER_TOL |xi0|`` through :func:`over_regulates`).  After
      ``T_A = ln(2 |c_r| / Amp) / (rho_p - r)`` the real mode is below half the pair's
      amplitude, so a far-side lobe lies in ``[T_A, T_A + 2 pi / q]``; far-side values never
      exceed ``U(t) = Amp e^{rho_p t} - s0 c_r e^{r t}``, which bounds how far to search for the
      largest one.
    * ``r > rho_p`` (the real root is slowest): for ``t >= T*`` with
      ``(|P0| + |B| min(t, 1/q)) e^{-(r - rho_p) t} <= |c_r|`` (:func:`_dominance_time`)
      ``|P(t)| <= |c_r e^{r t}|``, so ``xi`` has the sign of ``c_r``: no zero after ``T*``.
      If ``-s0 c_r > 0`` it over-regulates (it ends on the far side); otherwise the root
      finding on ``[0, T*]`` decides.
    * ``r = rho_p`` exactly: ``u = c_r + Amp cos(q t - theta)`` is periodic, its upper limit
      ``-s0 c_r + Amp`` is its supremum, and one period holds the largest excursion.
    """

    def __init__(self, resp, s0):
        n = resp.n
        l = resp.roots
        d = resp.d
        self.s0 = s0
        self.xi0 = d[:, 0]
        self.cap = np.full(n, np.inf)
        self.rho = l.real.max(axis=1)
        self.kind = np.where((l.imag != 0).any(axis=1), 1, 0)
        self.lim = np.zeros(n)  # -s0 * limit contribution (already a lower bound of the sup)
        self.sup = np.zeros(n)  # analytic sup of -s0 u (three real roots)
        self.need = np.zeros(n)  # window the events need (structural)
        self.undecided_after = np.zeros(n)  # B rows: a window shorter than T* is unsure
        self.pair = {}
        with np.errstate(all="ignore"):
            self._real(resp, np.nonzero(self.kind == 0)[0], s0)
            self._complex(resp, np.nonzero(self.kind == 1)[0], s0, l, d)

    # -- three real roots ---------------------------------------------------------------------
    def _real(self, resp, idx, s0):
        if idx.size == 0:
            return
        sub = resp.subset(idx)
        l = sub.roots.real
        l1, l2, l3 = l[:, 2], l[:, 1], l[:, 0]
        s = s0[idx]
        last = np.zeros(idx.size)
        for j in (0, 1):  # xi and xi'
            y = [sub.d[:, j + k] for k in range(3)]
            u0 = y[0]
            k1, k2 = _newton_real(y, l1, l2)
            n1 = y[2] - (l2 + l3) * y[1] + l2 * l3 * y[0]
            m2, m3, dl = l1 - l2, l1 - l3, l2 - l3
            uinf = n1 / (m2 * m3)
            # N1 = 0 with a repeated slowest root: the next term's limit (u = y + K1 g[0, m3])
            alt = np.where(m3 > 0, u0 + k1 / np.where(m3 > 0, m3, 1.0),
                           np.where(k1 != 0, np.sign(k1) * np.inf, u0))
            uinf = np.where(np.isnan(uinf), np.where(m2 * m3 == 0, alt, 0.0), uinf)
            yc = -k1 / k2
            ok = (k2 != 0) & (yc > 0) & ((dl == 0) | (dl * yc < 1.0))
            dl1 = np.where(dl > 0, dl, 1.0)
            tc = np.where(dl > 0, -np.log1p(-np.where(ok, dl * yc, 0.0)) / dl1, yc)
            tc = np.where(ok & np.isfinite(tc) & (tc > 0), tc, 0.0)
            uc = sub(tc[:, None], nder=j, shift=l1)[:, j, 0]
            if j == 0:
                self.sup[idx] = np.maximum(0.0, np.fmax(np.fmax(-s * u0, -s * uc), -s * uinf))
                self.lim[idx] = -s * uinf
            # last sign change of u: after t_c only if u(t_c) and u(inf) have opposite signs
            sinf = np.sign(uinf)
            start = np.where(tc > 0, tc, 0.0)
            ustart = np.where(tc > 0, uc, u0)
            todo = (sinf != 0) & (ustart != 0) & (np.sign(ustart) != sinf)
            tend = np.where(tc > 0, tc, 0.0)
            tau = 1.0 / np.maximum(np.abs(l).max(axis=1), 1e-300)
            k = np.nonzero(todo)[0]
            for _ in range(200):
                if k.size == 0:
                    break
                tau[k] *= 2.0
                tt = start[k] + tau[k]
                uu = sub.subset(k)(tt[:, None], nder=j, shift=l1[k])[:, j, 0]
                done = np.sign(uu) == sinf[k]
                tend[k[done]] = tt[done]
                k = k[~done]
            last = np.maximum(last, tend)
        self.need[idx] = 1.05 * last

    # -- a real root and a complex pair -------------------------------------------------------
    def _complex(self, resp, idx, s0, l, d):
        if idx.size == 0:
            return
        rows = l[idx]
        ip = np.argmax(rows.imag, axis=1)
        ir = np.argmin(np.abs(rows.imag), axis=1)
        k = np.arange(idx.size)
        p, r = rows[k, ip], rows[k, ir].real
        rp, q = p.real, p.imag
        x, x1, x2 = d[idx, 0], d[idx, 1], d[idx, 2]
        s = s0[idx]
        cr = (x2 - 2.0 * rp * x1 + (rp * rp + q * q) * x) / ((r - rp) ** 2 + q * q)
        P0 = x - cr
        B = x1 - r * cr - rp * P0
        amp = np.hypot(P0, B / q)
        period = 2.0 * np.pi / q
        stable = self.rho[idx] < 0
        sig = -rp
        A = (rp > r) | (cr == 0)
        Bk = (r > rp) & ~A  # the rest (equal real parts) is C
        kind = np.where(A, 1, np.where(Bk, 2, 3))
        self.kind[idx] = kind
        m = -s * cr
        # A: the pair is slowest
        tA = np.where(2 * np.abs(cr) > amp, np.log(2 * np.abs(cr) / amp) / (rp - r), 0.0)
        tA = np.where(np.isfinite(tA) & (amp > 0), tA, 0.0)
        # largest far-side lobes near the peak of U(t) = Amp e^{rho_p t} - |c_r| e^{r t}
        tm = np.log(np.abs(cr) * np.abs(r) / (amp * sig)) / (rp - r)
        tm = np.where(stable & (m < 0) & np.isfinite(tm) & (tm > 0), tm, 0.0)
        needA = np.maximum(tA, tm) + 2.0 * period
        # B: the real root is slowest
        tstar = _dominance_time(np.abs(P0), np.abs(B), 1.0 / q, r - rp, np.abs(cr))
        # C: equal real parts
        self.lim[idx] = np.where(A, amp, np.where(Bk, m, m + amp))
        need = np.where(A, needA, np.where(Bk, 1.05 * tstar, 1.05 * period))
        # keep growing responses representable (e^600); beyond that the window is unsure
        cap = np.where(self.rho[idx] > 0, 600.0 / np.maximum(self.rho[idx], 1e-300), np.inf)
        cap = np.where(stable, (np.log(np.abs(cr) + amp + np.abs(x)) + 700.0) / sig, cap)
        self.cap[idx] = cap
        self.need[idx] = np.minimum(need, cap)
        self.undecided_after[idx] = np.where(Bk, 1.05 * tstar, 0.0)
        self.pair = dict(idx=idx, A=A, Bk=Bk, amp=amp, m=m, cr=cr, r=r, sig=sig, tstar=tstar,
                         stable=stable)

    def wanted(self, rows, v):
        """Window needed given the largest far-side excursion ``v`` found so far (``rows``
        index designs): past it no far-side value can exceed ``v`` (A: ``U(t) <= v``; B ending
        on the far side: ``2 |c_r| e^{r t} <= v`` after ``T*``).  0 where nothing more is
        needed (three real roots and C: the structural window already holds every event)."""
        out = np.zeros(rows.size)
        pr = self.pair
        if not pr or pr["idx"].size == 0:
            return out
        pos = np.minimum(np.searchsorted(pr["idx"], rows), pr["idx"].size - 1)
        mine = (pr["idx"][pos] == rows) & (v > 0)
        if not mine.any():
            return out
        pos, vv = pos[mine], v[mine]
        A, Bk, amp, m, cr, r, sig, tstar, stable = (
            pr[key][pos] for key in ("A", "Bk", "amp", "m", "cr", "r", "sig", "tstar", "stable"))
        with np.errstate(all="ignore"):
            wA = np.log((amp + np.maximum(m, 0.0)) / vv) / sig
            wB = np.where(m > 0, np.maximum(tstar, np.log(2.0 * np.abs(cr) / vv) / -r), 0.0)
            w = np.where(A, wA, np.where(Bk, wB, 0.0))
        w = np.where(stable & np.isfinite(w), np.minimum(w, self.cap[rows[mine]]), 0.0)
        out[mine] = np.maximum(w, 0.0)
        return out

    def scaled(self, rows, over, t_over, H):
        """``over_regulation_scaled`` of designs ``rows``: the larger of the analytic part and
        the largest far-side excursion found (at ``t_over``) times ``exp(-rho t_over)``; nan
        (not decided) where the window ``H`` ended before the dominance time ``T*`` with
        nothing above the tolerance found."""
        with np.errstate(all="ignore"):
            found = np.where(over > 0, np.exp(np.log(over) - self.rho[rows] * t_over), 0.0)
        out = np.fmax(np.fmax(np.maximum(self.lim[rows], 0.0), self.sup[rows]), found)
        short = H < self.undecided_after[rows] * (1 - 1e-12)
        return np.where(short & ~over_regulates(out, self.xi0[rows]), np.nan, out)
