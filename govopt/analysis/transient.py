"""The load-change transient of eq. (28), exact for any roots: the response ``xi(t)``, its
derivatives, the modes' amplitudes, and root finding on the response.

Hamabe, *Disturbing Actions of a Shaft Governor*, Part III, eq. (28) (the cubic, its roots and
its stability: :mod:`govopt.analysis.transient_cubic`).  Coefficients and initial conditions
broadcast against each other over any leading shape (many designs at once); a 1-D array of
times ``t`` is appended as the last axis of the result.

Why not Hamabe's closed forms.  His constants, eqs. (38) and (40), divide by differences of the
roots, and his root formulas (39), (41) are the trigonometric / Cardano solutions; all of them
break down at and near repeated roots, which is exactly where a well-damped governor is tuned.
Instead the response is ``xi(t) = [exp(A t) x0]_0`` for the companion matrix ``A`` of (28) and
the state ``x0 = (xi, xi', xi'')(0)``, and ``exp(A t)`` is written in Newton (Opitz / Putzer)
form, valid for *any* eigenvalues ``l1, l2, l3`` including repeated ones::

    exp(A t) = f[l1] I + f[l1,l2] (A - l1 I) + f[l1,l2,l3] (A - l1 I)(A - l2 I),

where ``f[...]`` are divided differences of ``s -> exp(s t)``.  They are computed without any
division by a small difference of nodes: two-node differences as ``exp(mid) sinh(h)/h``, and
three-node differences from a Taylor series about the centroid when the nodes are within unit
distance (in ``z = l t``), otherwise by the usual recurrence divided by the *largest* node
distance (>= 1), which cannot amplify rounding.  The only inputs from the roots are the roots
themselves, so the result is as accurate as the roots are *backward* stable (their Vieta
coefficients match the cubic's), not as accurate as they are forward accurate -- which is what
makes the method insensitive to (near-)repeated roots.  Derivatives ``xi^(j)`` differentiate
the same Newton form in ``t`` (Leibniz rule for divided differences of ``s^j exp(s t)``), so
they too start from the exact initial state rather than from the fast-mode-dominated
``A^j x0``.  The nodes are ordered per design with the farthest pair first and last (the one
with the larger real part first).

Events on the response (a zero, an extremum, a band crossing) are located by :func:`refine`,
a vectorised bracketed Newton iteration on the analytic response (exact to rounding).

Inputs that are not finite, or ``a0 = 0``, raise ValueError naming the argument.  Values whose
exponentials overflow binary64 (a growing design at late times) are computed scaled by the
largest real part and returned as ``+-inf`` with their true sign, never nan.
"""

from __future__ import annotations

import numpy as np

from .transient_cubic import as_floats, roots_of_rows

__all__ = [
    "BLOCK",
    "Response",
    "local_max",
    "modal_amplitudes",
    "refine",
    "refine_peaks",
    "transient",
    "transient_derivatives",
]

_EPS = float(np.finfo(float).eps)
BLOCK = 1 << 15  # elements per evaluation block (keeps temporaries in cache)
_SERIES_TERMS = 20  # Taylor terms of the 3-node divided difference (|h| <= 2/3: error < 1e-20)


def _sinhc(h):
    """sinh(h)/h for complex h, exact at 0."""
    with np.errstate(all="ignore"):
        out = np.sinh(h) / h
    small = np.abs(h) < 1e-3
    if small.any():
        h2 = h[small] ** 2
        out[small] = 1.0 + h2 / 6.0 * (1.0 + h2 / 20.0 * (1.0 + h2 / 42.0))
    return out


def _tdd1(la, lb, t, close):
    """``t * exp[la t, lb t]`` at the masked entries (nodes closer than 1 in ``z = l t``).

    ``exp((za+zb)/2) sinh(h)/h`` with ``h = (zb-za)/2``: no cancellation, exact at ``h = 0``.
    la, lb are per-row nodes (n,), t and close are (n, T).
    """
    rows = np.nonzero(close)[0]
    tc = t[close]
    za, zb = la[rows] * tc, lb[rows] * tc
    h = 0.5 * (zb - za)
    return tc * np.exp(za + h) * _sinhc(h)


def _dd2_series(z1, z2, z3):
    """exp[z1, z2, z3] for nodes within unit distance: Taylor series about the centroid.

    exp[z1,z2,z3] = exp(c) sum_m H_m(h1,h2,h3)/(m+2)!, with h_i = z_i - c and H_m the complete
    homogeneous symmetric polynomials (divided differences of z^(m+2)); with sum h_i = 0 they
    obey H_m = -e2 H_{m-2} + e3 H_{m-3}.  |h_i| <= 2/3, so 20 terms reach 1e-20.
    """
    c = (z1 + z2 + z3) / 3.0
    h1, h2, h3 = z1 - c, z2 - c, z3 - c
    e2 = h1 * h2 + h1 * h3 + h2 * h3
    e3 = h1 * h2 * h3
    hm3 = np.zeros_like(c)
    hm2 = np.zeros_like(c)
    hm1 = np.ones_like(c)  # H_0
    total = 0.5 * hm1
    fact = 2.0
    for m in range(1, _SERIES_TERMS):
        hm = -e2 * hm2 + e3 * hm3
        fact *= m + 2
        total = total + hm / fact
        hm3, hm2, hm1 = hm2, hm1, hm
    return np.exp(c) * total


def _eval_block(nodes, C, t):
    """Newton-form response.  nodes (n,3) (l1, l2, l3), ordered so that (l1, l3) is the farthest
    pair; C (n,J,6); t (n or 1, T).  Real or complex arrays (real roots stay real).

    Returns (n, J, T): sum_k Re(C[..., k] * F_k) with F = (exp(z1), t exp[z1,z2],
    t^2 exp[z1,z2,z3], exp(z2), t exp[z2,z3], exp(z3)), z_i = l_i t, the divided differences
    of s -> exp(s t); derivative orders j > 0 use all six (see Response).

    First differences: ``(exp(zb) - exp(za)) / (zb - za)`` where the nodes are 1 or more apart
    (in z), ``exp(mid) sinh(h)/h`` where closer.  Second difference: since |z3 - z1| is the
    largest node distance, ``(exp[z2,z3] - exp[z1,z2]) / (z3 - z1)`` is used only where that
    distance is >= 1 (it cannot amplify rounding), and the centroid series where all three nodes
    are within distance 1.  No division by a small node difference occurs anywhere.
    """
    n = nodes.shape[0]
    t = np.broadcast_to(t, (n, t.shape[-1]))
    l1, l2, l3 = nodes[:, 0], nodes[:, 1], nodes[:, 2]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        if np.iscomplexobj(nodes):
            # one real node and a conjugate pair: exp(l t) = exp(Re l t)(cos qt + i sgn sin qt)
            q = np.abs(nodes.imag).max(axis=1)
            qt = q[:, None] * t
            cq, sq = np.cos(qt), np.sin(qt)
            es = []
            for lk in (l1, l2, l3):
                ex = np.exp(lk.real[:, None] * t)
                sg = np.sign(lk.imag)[:, None]
                e = np.empty(t.shape, complex)
                e.real = ex * cq
                e.imag = (ex * sq) * sg
                real = sg[:, 0] == 0
                if real.any():
                    e.real[real] = ex[real]
                es.append(e)
            e1, e2, e3 = es
        else:
            e1, e2, e3 = (np.exp(lk[:, None] * t) for lk in (l1, l2, l3))
        f1 = (e2 - e1) * (1.0 / (l2 - l1))[:, None]  # t exp[z1, z2]
        g23 = (e3 - e2) * (1.0 / (l3 - l2))[:, None]  # t exp[z2, z3]
        at = np.abs(t)
        close = np.abs(l2 - l1)[:, None] * at < 1.0
        if close.any():
            f1[close] = _tdd1(l1, l2, t, close)
        close = np.abs(l3 - l2)[:, None] * at < 1.0
        if close.any():
            g23[close] = _tdd1(l2, l3, t, close)
        f2 = (g23 - f1) * (1.0 / (l3 - l1))[:, None]  # t^2 exp[z1, z2, z3]
        close = np.abs(l3 - l1)[:, None] * at < 1.0
        if close.any():
            rows = np.nonzero(close)[0]
            tc = t[close]
            f2[close] = tc * tc * _dd2_series(l1[rows] * tc, l2[rows] * tc, l3[rows] * tc)
        out = None
        nterms = 3 if C.shape[1] == 1 else 6  # xi alone needs only e1, f1, f2
        for k, F in enumerate((e1, f1, f2, e2, g23, e3)[:nterms]):
            Ck = C[:, :, k, None]
            if np.iscomplexobj(F):
                term = Ck.real * F.real[:, None, :] - Ck.imag * F.imag[:, None, :]
            else:
                term = Ck * F[:, None, :]
            out = term if out is None else out + term
    return out


def _node_order(roots):
    """Per-row permutation of the roots into Newton nodes (l1, l2, l3): the farthest pair first
    and last, the one with the larger real part (slower or growing mode) first."""
    r = roots
    dist = np.stack(
        [np.abs(r[:, 0] - r[:, 1]), np.abs(r[:, 0] - r[:, 2]), np.abs(r[:, 1] - r[:, 2])], -1
    )
    pairs = np.array([[0, 2, 1], [0, 1, 2], [1, 0, 2]])  # (i, middle, k) for pairs 01, 02, 12
    far = np.argmax(np.where(np.isfinite(dist), dist, -1.0), axis=1)
    i, j, k = pairs[far].T
    rows = np.arange(r.shape[0])
    swap = r[rows, k].real > r[rows, i].real
    first = np.where(swap, k, i)
    last = np.where(swap, i, k)
    return np.stack([first, j, last], axis=1)


_ARG_NAMES = ("a0", "a1", "a2", "a3", "xi0", "xi_dot0", "xi_ddot0")


def _check_inputs(arrs):
    """ValueError naming the first argument of eq. (28) that is not finite, or a0 = 0."""
    for name, x in zip(_ARG_NAMES, arrs, strict=True):
        bad = ~np.isfinite(x)
        if bad.any():
            where = "" if x.ndim == 0 else f" at index {tuple(int(i) for i in np.argwhere(bad)[0])}"
            raise ValueError(f"{name} is not finite ({float(x[bad][0])!r}{where})")
    if np.any(arrs[0] == 0):
        where = "" if arrs[0].ndim == 0 else \
            f" (at index {tuple(int(i) for i in np.argwhere(arrs[0] == 0)[0])})"
        raise ValueError(f"a0 must be non-zero{where}")


class Response:
    """Prepared analytic response of many designs (flattened), evaluable at any times."""

    def __init__(self, c, d, roots, order):
        # c: (4, n) coefficients, d: (3, n) initial state, roots: (n, 3) sorted ascending
        self.c = c
        self.roots = roots
        self.order = order
        self.nodes = np.take_along_axis(roots, _node_order(roots), axis=1)
        a0, a1, a2, a3 = c
        ds = [d[0], d[1], d[2]]
        with np.errstate(all="ignore"):
            for k in range(3, order + 3):
                ds.append(-(3.0 * a1 * ds[k - 1] + 3.0 * a2 * ds[k - 2] + a3 * ds[k - 3]) / a0)
        self.d = np.stack(ds, axis=-1)  # (n, order+3): xi^(k)(0), for signs and scales only
        l1, l2, l3 = self.nodes[:, 0], self.nodes[:, 1], self.nodes[:, 2]
        with np.errstate(all="ignore"):
            # Newton coefficients of the initial state: x0, (A - l1) x0, (A - l1)(A - l2) x0
            C0 = d[0].astype(complex)
            C1 = d[1] - l1 * d[0]
            C2 = d[2] - (l1 + l2) * d[1] + (l1 * l2) * d[0]
            # complete homogeneous symmetric polynomials h_m of (l1), (l1,l2), (l1,l2,l3),
            # m = -2 .. order (index m + 2): divided differences of s^m (Leibniz rule below)
            zero, one = np.zeros_like(l1), np.ones_like(l1)
            h1, h2, h3 = [zero, zero, one], [zero, zero, one], [zero, zero, one]
            for _ in range(order):
                h1.append(l1 * h1[-1])
                h2.append(l2 * h2[-1] + h1[-1])
                h3.append(l3 * h3[-1] + h2[-1])
            # xi^(j)(t) = Re sum_k C_{k-1} sum_{m<=k} (s^j)[l1..lm] exp[lm..lk](t)   (Leibniz),
            # so derivatives come from the exact initial state, not from a fast-mode-dominated
            # A^j x0.  Terms ordered as F = (e1, f1, f2, e2, g23, e3), see _eval_block.
            K = np.empty((self.n, order + 1, 6), complex)
            for j in range(order + 1):
                K[:, j, 0] = C0 * h1[j + 2]
                K[:, j, 1] = C1 * h1[j + 2]
                K[:, j, 2] = C2 * h1[j + 2]
                K[:, j, 3] = C1 * h2[j + 1]
                K[:, j, 4] = C2 * h2[j + 1]
                K[:, j, 5] = C2 * h3[j]
        self.C = K
        self._split()

    def _split(self):
        # rows whose nodes are all real are evaluated in real arithmetic (about 3x faster)
        real = (self.nodes.imag == 0).all(axis=1)
        self._groups = (
            (np.nonzero(real)[0], self.nodes.real, self.C.real),
            (np.nonzero(~real)[0], self.nodes, self.C),
        )

    @classmethod
    def build(cls, a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, order):
        arrs = as_floats(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0)
        _check_inputs(arrs)
        shape = arrs[0].shape
        flat = np.stack([x.reshape(-1) for x in arrs])
        roots = np.sort(roots_of_rows(flat[:4], 3), axis=-1)
        return cls(flat[:4], flat[4:], roots, order), shape

    @property
    def n(self):
        return self.roots.shape[0]

    def subset(self, idx):
        new = object.__new__(Response)
        new.c, new.roots, new.order = self.c[:, idx], self.roots[idx], self.order
        new.nodes, new.d, new.C = self.nodes[idx], self.d[idx], self.C[idx]
        new._split()
        return new

    def __call__(self, t, nder=None, shift=None):
        """Values (n, J, T) of xi, xi', ... up to ``nder`` (default: the prepared order);
        t is 1-D (common times) or (n, T) (per-design times).

        With ``shift`` (per design, real) the values are ``xi^(j)(t) exp(-shift t)``: the same
        Newton form with the nodes shifted by ``-shift`` (divided differences of ``exp(s t)``
        are shift-covariant: ``exp[l1..lk](t) = exp(shift t) exp[l1-shift..lk-shift](t)``).
        Without it, values whose exponentials overflow (a growing design at late times) are
        evaluated scaled by the largest real part and returned as +-inf with their true sign
        (or the true value, where it is representable), never nan.
        """
        t = np.asarray(t, dtype=float)
        common = t.ndim == 1
        T = t.shape[-1]
        J = self.order + 1 if nder is None else nder + 1
        out = np.empty((self.n, J, T))
        step = max(1, BLOCK // max(T, 1))
        for rows, nodes, C in self._groups:
            for s in range(0, rows.size, step):
                r = rows[s : s + step]
                tb = t[None, :] if common else t[r]
                nb = nodes[r]
                if shift is not None:
                    out[r] = _eval_block(nb - shift[r, None], C[r, :J], tb)
                    continue
                vals = _eval_block(nb, C[r, :J], tb)
                bad = ~np.isfinite(vals)
                if bad.any():
                    rho = nb.real.max(axis=1)
                    sc = _eval_block(nb - rho[:, None], C[r, :J], tb)
                    lt = np.broadcast_to(rho[:, None] * tb, (r.size, T))[:, None, :]
                    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
                        big = np.sign(sc) * np.exp(np.log(np.abs(sc)) + lt)
                    vals = np.where(bad, np.where(sc == 0, 0.0, big), vals)
                out[r] = vals
        return out


def transient_derivatives(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, t, order=2):
    """Response of eq. (28) and its derivatives: a tuple ``(xi, xi', ..., xi^(order))``.

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (28) with initial state
    ``(xi0, xi_dot0, xi_ddot0)``.  Each array has shape ``broadcast(inputs).shape + (len(t),)``.
    ``xi^(j)(t) = [exp(A t) A^j x0]_0``: the derivatives use the same robust Newton form with the
    initial derivative sequence ``xi^(k)(0)`` continued by the recurrence of (28), so they are
    exact derivatives of the returned ``xi`` (not finite differences).  ``order`` may be any
    integer >= 0 (3 gives ``xi'''`` for checking the ODE).

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28) (``a_i`` in kg m^2 s^-i in SI; any consistent set, the
        paper's is kgf-cm-s), see :func:`govopt.analysis.transient_cubic.hamabe_coefficients`.
    xi0 : float or array [rad]
        Initial deviation from the new equilibrium.
    xi_dot0 : float or array [rad/s]
        Initial angular velocity of the pendulum (0 for a sudden load change).
    xi_ddot0 : float or array [rad/s^2]
        Initial angular acceleration (see
        :func:`govopt.analysis.transient_cubic.hamabe_initial_conditions`).
    t : array [s]
        Times, 1-D.
    order : int [-]
        Highest derivative returned (dimensionless count).

    Returns
    -------
    tuple of ndarray [rad/s^j]
        ``xi^(j)(t)`` for ``j = 0 .. order``.

    References
    ----------
    [hamabe] Part III, eq. (28); the Newton-form solution is govopt's own (module docstring).

    Examples
    --------
    A triple root s = -1 with ``x0 = (1, 0, 0)``: ``xi = e^-t (1 + t + t^2/2)``, so by hand
    ``xi(1) = 2.5/e`` and ``xi'(1) = -0.5/e``.

    >>> xi, xd = transient_derivatives(1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, [1.0], order=1)
    >>> round(float(xi[0]), 6), round(float(xd[0]), 6)
    (0.919699, -0.18394)
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.ndim != 1:
        raise ValueError("t must be a 1-D array of times")
    if order < 0:
        raise ValueError("order must be >= 0")
    resp, shape = Response.build(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, order)
    vals = resp(t)
    return tuple(vals[:, j, :].reshape(shape + (t.size,)) for j in range(order + 1))


def transient(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, t):
    """Deviation ``xi(t)`` after a load change: the solution of Hamabe's eq. (28).

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (28)
    ``a0 xi''' + 3 a1 xi'' + 3 a2 xi' + a3 xi = 0`` with ``xi(0) = xi0``, ``xi'(0) = xi_dot0``,
    ``xi''(0) = xi_ddot0``.  Coefficients and initial values broadcast over any leading shape;
    ``t`` (1-D) becomes the last axis.  Valid for distinct, repeated and nearly repeated roots
    alike (see the module docstring); unstable designs give the growing solution, ``+-inf`` with
    its sign where it overflows binary64 (never nan).  Non-finite inputs or ``a0 = 0`` raise
    ValueError naming the argument.  Replaces Hamabe's closed forms (30)-(31) with (38)-(41).

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28) (``a_i`` in kg m^2 s^-i in SI; any consistent set, the
        paper's is kgf-cm-s), see :func:`govopt.analysis.transient_cubic.hamabe_coefficients`.
    xi0 : float or array [rad]
        Initial deviation from the new equilibrium.
    xi_dot0 : float or array [rad/s]
        Initial angular velocity of the pendulum (0 for a sudden load change).
    xi_ddot0 : float or array [rad/s^2]
        Initial angular acceleration (see
        :func:`govopt.analysis.transient_cubic.hamabe_initial_conditions`).
    t : array [s]
        Times, 1-D.

    Returns
    -------
    ndarray [rad]
        ``xi(t)``, shape ``broadcast(inputs).shape + (len(t),)``.

    References
    ----------
    [hamabe] Part III, eq. (28).

    Examples
    --------
    Example 3, case a (a0 = 1.76, a1 = 24, a2 = 211.2, a3 = 840, xi0 = -0.128 rad, eta0 = -0.4
    rad/s, so ``xi''(0)`` = 18.716): the paper's curve ``0.0318 e^-29.1t - 0.0814 e^-1.7t -
    0.0784 e^-10t`` gives -0.0353 at 0.5 s and -0.0149 at 1 s: its slow root -1.7 comes from a
    slide-rule G 3 % off (see :func:`govopt.analysis.transient_cubic.cubic_roots`; the exact
    -1.61 decays more slowly). Neither crosses zero: no over-regulation, as the paper finds.

    >>> xi = transient(1.76, 24, 211.2, 840, -0.128, 0.0, 18.716, [0.5, 1.0])
    >>> [round(float(v), 4) for v in xi]
    [-0.037, -0.0163]

    A triple root (hand-checkable: ``e^-t (1 + t + t^2/2)``), and a growing design:

    >>> xi = transient(1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, [0.0, 1.0])   # triple root s = -1
    >>> np.allclose(xi, [1.0, 2.5 * np.exp(-1.0)])
    True
    >>> x = transient(1.0, -10.0, 100.0, 10.0, -0.128, 0.0, 18.7, [47.23, 47.5])  # growing
    >>> bool(1.28e307 < x[0] < 1.29e307 and x[1] == -np.inf)
    True
    """
    return transient_derivatives(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, t, order=0)[0]


def modal_amplitudes(l, d):
    """Modal amplitudes ``c_k`` of ``xi(t) = sum_k c_k exp(l_k t)`` for distinct roots ``l``
    (n, 3) and initial state ``d`` (n, >= 3): ``c_k = ((A - l_i)(A - l_j) x0)_0 / ((l_k - l_i)
    (l_k - l_j))`` (partial fractions of eq. (28); Hamabe's constants (38), (40) restated).
    Complex (n, 3); inf or nan where roots coincide (callers test separation first).

    Parameters
    ----------
    l : ndarray [1/s]
        Distinct roots of the cubic (29), shape (n, 3).
    d : ndarray [rad/s^k]
        Initial derivatives ``xi^(k)(0)``, k = 0, 1, 2, ..., shape (n, >= 3).

    Returns
    -------
    ndarray [rad]
        Complex amplitudes, shape (n, 3), in the order of ``l``.

    References
    ----------
    [hamabe] Part III, eqs. (38), (40) (the constants of the real and complex cases).

    Examples
    --------
    Example 3, case a: the paper prints 0.0318 (at -29.1), -0.0784 (at -10) and -0.0814 (at
    -1.7); ours solve the exact cubic, whose roots differ from the paper's slide-rule ones.

    >>> from govopt.analysis.transient_cubic import cubic_roots
    >>> l = cubic_roots(1.76, 24, 211.2, 840)[None, :]
    >>> c = modal_amplitudes(l, np.array([[-0.128, 0.0, 18.716]]))[0]
    >>> [round(float(v.real), 4) for v in c]
    [0.032, -0.0784, -0.0816]
    """
    c = np.empty(l.shape, complex)
    for k, (i, j) in enumerate(((1, 2), (0, 2), (0, 1))):
        li, lj, lk = l[:, i], l[:, j], l[:, k]
        c[:, k] = (d[:, 2] - (li + lj) * d[:, 1] + li * lj * d[:, 0]) / ((lk - li) * (lk - lj))
    return c


def refine(resp, j, target, lo, hi, iters=100):
    """Vectorised safeguarded Newton (Numerical Recipes' rtsafe) for resp_j(t) = target on the
    brackets [lo, hi], one per row of resp (which needs order >= j + 1: the derivative drives
    Newton).  A Newton step is taken only if it stays inside the bracket and at least halves
    the step before last; otherwise the bracket is bisected.  Rows stop when the step is at
    rounding level (|dt| <= 4 eps t) or the residual is exactly zero.

    Parameters
    ----------
    resp : Response [-]
        Prepared responses (see :meth:`Response.build`), one per row.
    j : int [-]
        Derivative order whose value is sought (0: ``xi``, 1: ``xi'``).
    target : float or array [rad/s^j]
        Value sought, per row or common.
    lo, hi : ndarray [s]
        Brackets, one per row.
    iters : int [-]
        Iterations at most (dimensionless count).

    Returns
    -------
    ndarray [s]
        The times found.

    References
    ----------
    Numerical Recipes' ``rtsafe`` on the response of [hamabe] eq. (28) (govopt's own use).

    Examples
    --------
    ``a0 = 1, a2 = 1/3, a1 = a3 = 0`` with ``x0 = (0, 1, 0)`` is ``xi = sin t``: its zero in
    [2, 4] is pi.

    >>> resp, _ = Response.build(1.0, 0.0, 1 / 3, 0.0, 0.0, 1.0, 0.0, order=2)
    >>> round(float(refine(resp, 0, 0.0, np.array([2.0]), np.array([4.0]))[0]), 12)
    3.14159265359
    """
    target = np.broadcast_to(np.asarray(target, float), lo.shape)
    lo, hi = lo.astype(float).copy(), hi.astype(float).copy()

    def ev(rows, x):
        sub = resp if rows.size == resp.n else resp.subset(rows)
        v = sub(x[:, None], nder=j + 1)[:, :, 0]
        return v[:, j] - target[rows], v[:, j + 1]

    act = np.arange(lo.size)
    flo = ev(act, lo)[0]
    x = 0.5 * (lo + hi)
    dx = hi - lo
    dxold = dx.copy()
    for _ in range(iters):
        xa = x[act]
        fx, dfx = ev(act, xa)
        same = np.sign(fx) == np.sign(flo[act])
        la = np.where(same, xa, lo[act])
        ha = np.where(same, hi[act], xa)
        flo[act] = np.where(same, fx, flo[act])
        lo[act], hi[act] = la, ha
        with np.errstate(all="ignore"):
            step = fx / dfx
        newton = xa - step
        tol = 4 * _EPS * np.abs(xa)
        # converged: Newton step at rounding level, residual exactly 0, or bracket exhausted
        done = (fx == 0) | (np.abs(step) <= tol) | (ha - la <= tol)
        ok = (np.isfinite(newton) & (newton > la) & (newton < ha)
              & (np.abs(2.0 * fx) < np.abs(dxold[act] * dfx)))
        dxold[act] = dx[act]
        xn = np.where(ok, newton, 0.5 * (la + ha))
        dx[act] = xn - xa
        x[act] = np.where(done, np.where(np.isfinite(newton) & (np.abs(step) <= tol), newton, xa),
                          xn)
        act = act[~done]
        if act.size == 0:
            break
    return x


def local_max(v):
    """Interior grid local maxima of the rows of v (>= left neighbour, > right neighbour), as
    index arrays (rows, columns) in row-major order.

    A grid helper of govopt's own for the events of [hamabe] eq. (28) (peaks of ``|xi|``).

    Parameters
    ----------
    v : ndarray [-]
        Values on a grid, shape (n, M), any unit.

    Returns
    -------
    tuple of ndarray [-]
        Row and column indices of the maxima.

    Examples
    --------
    A plateau counts at its right end:

    >>> r, k = local_max(np.array([[0, 2, 1, 3, 3, 0.0]]))
    >>> r.tolist(), k.tolist()
    ([0, 0], [1, 4])
    """
    with np.errstate(invalid="ignore"):
        r, k = np.nonzero((v[:, 1:-1] >= v[:, :-2]) & (v[:, 1:-1] > v[:, 2:]))
    return r, k + 1


def refine_peaks(resp, t, xd, r, k):
    """Exact extrema next to grid points (r, k) (zeros of xi' in [t_k-1, t_k] or [t_k, t_k+1]).

    Returns the rows, grid indices, times and xi values of those with a bracket.

    govopt's own event location on the response of [hamabe] eq. (28).

    Parameters
    ----------
    resp : Response [-]
        Prepared responses (see :meth:`Response.build`), one per row.
    t : ndarray [s]
        Grid times, shape (n, M).
    xd : ndarray [rad/s]
        ``xi'`` on the grid, shape (n, M).
    r, k : ndarray [-]
        Rows and grid indices of candidate peaks (e.g. from :func:`local_max`).

    Returns
    -------
    tuple of ndarray [-, -, s, rad]
        Rows, grid indices, times and ``xi`` values of the extrema found.

    Examples
    --------
    ``xi = sin t`` (see :func:`refine`) on a grid of 0.5 s: the peak at pi/2, value 1.

    >>> resp, _ = Response.build(1.0, 0.0, 1 / 3, 0.0, 0.0, 1.0, 0.0, order=2)
    >>> t = np.linspace(0.0, 3.0, 7)[None, :]
    >>> y = resp(t, nder=1)
    >>> r, k, te, xe = refine_peaks(resp, t, y[:, 1], *local_max(y[:, 0]))
    >>> round(float(te[0]), 10), round(float(xe[0]), 10)
    (1.5707963268, 1.0)
    """
    left = np.sign(xd[r, k - 1]) != np.sign(xd[r, k])
    right = np.sign(xd[r, k]) != np.sign(xd[r, k + 1])
    ok = left | right
    r, k, left = r[ok], k[ok], left[ok]
    if r.size == 0:
        z = np.zeros(0)
        return r, k, z, z
    lo = np.where(left, t[r, k - 1], t[r, k])
    hi = np.where(left, t[r, k], t[r, k + 1])
    sub = resp.subset(r)
    te = refine(sub, 1, 0.0, lo, hi)
    return r, k, te, sub(te[:, None], nder=0)[:, 0, 0]
