"""Load change of the shaft governor: the cubic, its stability and a robust transient.

Hamabe, *Disturbing Actions of a Shaft Governor*, Part III.  After a sudden load change the
pendulum's deviation ``xi`` from its new equilibrium obeys eq. (28)::

    a0 xi''' + 3 a1 xi'' + 3 a2 xi' + a3 xi = 0,
    a0 = I,  3 a1 = f (dash-pot),  3 a2 = I k^2,  a3 = 2 R omega0 a m rho sin(alpha0),

with characteristic cubic (29) ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3 = 0``.

Everything here is pure and vectorised: coefficients and initial conditions broadcast against
each other over any leading shape (many designs at once); a 1-D array of times ``t`` is
appended as the last axis of the result.

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

Event analysis (over-regulation, first arrival, settling) is exact root finding on the analytic
response: :func:`analyse_many` (vectorised bracketed Newton over one or many designs) brackets
the events on a grid evaluated by
:func:`_grid_values` (the plain modal sum where the roots are well separated and every mode
decays: bracketing only, every reported figure is located on the Newton form).
Over-regulation is decided for all ``t >= 0``, not within
a horizon: the response is a sum of three exponential modes, so after a dominance time the sign
of ``xi`` is that of the slowest mode(s), and only the window before it needs root finding
(:class:`_Tail` has the proof; :func:`over_regulates` with :data:`OVER_TOL` is the one decision
that the evaluator, the design search and the Excel sheet all use).

Inputs that are not finite, or ``a0 = 0``, raise ValueError naming the argument.  Values whose
exponentials overflow binary64 (a growing design at late times) are computed scaled by the
largest real part and returned as ``+-inf`` with their true sign, never nan.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..limits import MAX_TRANSIENT_POINTS

__all__ = [
    "TransientSummary",
    "analyse_many",
    "classify",
    "cubic_roots",
    "discriminant",
    "hamabe_coefficients",
    "hamabe_initial_conditions",
    "hurwitz_margin",
    "is_stable",
    "over_regulation_many",
    "transient",
    "transient_derivatives",
]

_EPS = float(np.finfo(float).eps)
_BLOCK = 1 << 15  # elements per evaluation block (keeps temporaries in cache)
_SERIES_TERMS = 20  # Taylor terms of the 3-node divided difference (|h| <= 2/3: error < 1e-20)
_PER_PERIOD = 24  # event-search grid points per period of the fastest oscillation
_EFOLDS = 12.0  # default horizon: ln(1/band) + this many e-folds of the slowest mode


def _floats(*xs):
    return np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in xs))


# --------------------------------------------------------------------------------------------
# Coefficients, initial conditions, stability
# --------------------------------------------------------------------------------------------


def hamabe_coefficients(I, f, k2, R, omega0, a, m, rho, alpha0):
    """Coefficients ``(a0, a1, a2, a3)`` of Hamabe's eq. (28) from the design quantities.

    ``a0 = I``, ``3 a1 = f``, ``3 a2 = I k^2``, ``a3 = 2 R omega0 a m rho sin(alpha0)``
    (Hamabe, Disturbing Actions of a Shaft Governor, eqs. (27)-(28)).  Any consistent units.

    >>> m = 12 / 981
    >>> [round(float(c), 2) for c in hamabe_coefficients(144 * m, 72, 360, 300 / 43, 25.1, 18,
    ...                                                      m, 12, np.radians(64 + 40 / 60))]
    [1.76, 24.0, 211.38, 836.39]
    """
    I, f, k2, R, omega0, a, m, rho, alpha0 = _floats(I, f, k2, R, omega0, a, m, rho, alpha0)
    return I, f / 3.0, I * k2 / 3.0, 2.0 * R * omega0 * a * m * rho * np.sin(alpha0)


def hamabe_initial_conditions(a0, a2, a3, R, xi0, eta0):
    """Initial state ``(xi(0), xi'(0), xi''(0))`` for a sudden load change (Hamabe, Part III).

    ``xi(0) = alpha1 - alpha0``, ``xi'(0) = 0`` and ``a0 xi''(0) = (a3 / R) eta0 - 3 a2 xi(0)``
    with ``eta0 = omega1' - omega0`` the speed error (Hamabe, Disturbing Actions of a Shaft
    Governor, the relations preceding eq. (38)).

    >>> x = hamabe_initial_conditions(1.76, 211.2, 840.0, 300 / 43, -0.128, -0.4)
    >>> [round(float(v), 3) for v in x]
    [-0.128, 0.0, 18.716]
    """
    a0, a2, a3, R, xi0, eta0 = _floats(a0, a2, a3, R, xi0, eta0)
    xi_ddot0 = ((a3 / R) * eta0 - 3.0 * a2 * xi0) / a0
    return xi0, np.zeros_like(xi0), xi_ddot0


def hurwitz_margin(a0, a1, a2, a3):
    """Hurwitz margin ``9 a1 a2 / (a0 a3) - 1`` of the cubic (29).

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (32): with all coefficients positive the
    governor is stable iff ``9 a1 a2 > a0 a3``, i.e. iff this margin is positive.  ``a3 = 0``
    gives ``+-inf`` (or nan for ``a1 a2 = 0``), without a warning.

    >>> round(float(hurwitz_margin(1.76, 24, 211.2, 840)), 4)   # Example 3, case a
    29.8571
    """
    a0, a1, a2, a3 = _floats(a0, a1, a2, a3)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 9.0 * a1 * a2 / (a0 * a3) - 1.0


def is_stable(a0, a1, a2, a3):
    """Asymptotic stability of eq. (28): all coefficients of one sign and ``9 a1 a2 > a0 a3``.

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (32) (Hurwitz).  The products are
    compared directly, so no division is involved.  The boundary (margin exactly 0: an undamped
    oscillation) is *not* stable.
    """
    a0, a1, a2, a3 = _floats(a0, a1, a2, a3)
    sgn = np.sign(a0)
    b1, b2, b3 = sgn * a1, sgn * a2, sgn * a3
    return (sgn != 0) & (b1 > 0) & (b2 > 0) & (b3 > 0) & (9.0 * b1 * b2 > np.abs(a0) * b3)


def discriminant(a0, a1, a2, a3):
    """Hamabe's discriminant ``G^2 + 4 H^3`` of the cubic (29), eq. (37).

    With ``y = a0 s + a1`` (eq. 33) the cubic becomes ``y^3 + 3 H y + G = 0`` with
    ``H = a0 a2 - a1^2`` and ``G = a0^2 a3 - 3 a0 a1 a2 + 2 a1^3`` (eq. 34).  Eq. (37): a pair of
    complex roots iff ``G^2 + 4 H^3 > 0``; three distinct real roots iff ``< 0``; a repeated root
    iff ``= 0``.  The classical discriminant of (29) is ``-27 (G^2 + 4 H^3) / a0^2``.

    Evaluated from the coefficients this suffers cancellation near repeated roots; use
    :func:`classify` for a decision with a stated tolerance.

    >>> float(discriminant(1.0, 1.0, 1.0, 1.0))   # triple root s = -1
    0.0
    """
    a0, a1, a2, a3 = _floats(a0, a1, a2, a3)
    H = a0 * a2 - a1 * a1
    G = a0 * a0 * a3 - 3.0 * a0 * a1 * a2 + 2.0 * a1**3
    return G * G + 4.0 * H**3


# --------------------------------------------------------------------------------------------
# Roots
# --------------------------------------------------------------------------------------------


def _poly(c, s):
    return ((c[0] * s + 3.0 * c[1]) * s + 3.0 * c[2]) * s + c[3]


def _dpoly(c, s):
    return (3.0 * c[0] * s + 6.0 * c[1]) * s + 3.0 * c[2]


def _vieta_error(c, r):
    """Componentwise relative backward error of a root triple (rows of r) against the cubic."""
    r1, r2, r3 = r[:, 0], r[:, 1], r[:, 2]
    a0, a1, a2, a3 = c
    tiny = np.finfo(float).tiny
    e1 = np.abs(r1 + r2 + r3 + 3.0 * a1 / a0) / (np.abs(r1) + np.abs(r2) + np.abs(r3) + tiny)
    p12, p13, p23 = r1 * r2, r1 * r3, r2 * r3
    e2 = np.abs(p12 + p13 + p23 - 3.0 * a2 / a0) / (np.abs(p12) + np.abs(p13) + np.abs(p23) + tiny)
    p = p12 * r3
    e3 = np.abs(p + a3 / a0) / (np.abs(p) + np.abs(a3 / a0) + tiny)
    return np.maximum(np.maximum(e1, e2), e3)


def _roots_flat(c, polish):
    """Roots of the rows of c = (a0, a1, a2, a3) (each shape (n,)), unsorted, (n, 3) complex."""
    n = c.shape[1]
    out = np.full((n, 3), np.nan + 0j)
    with np.errstate(all="ignore"):
        m2, m1, m0 = -3.0 * c[1] / c[0], -3.0 * c[2] / c[0], -c[3] / c[0]
    ok = np.isfinite(m2) & np.isfinite(m1) & np.isfinite(m0)
    if not ok.any():
        return out
    cc = c[:, ok]
    M = np.zeros((cc.shape[1], 3, 3))
    M[:, 0, 0], M[:, 0, 1], M[:, 0, 2] = m2[ok], m1[ok], m0[ok]
    M[:, 1, 0] = 1.0
    M[:, 2, 1] = 1.0
    r0 = np.linalg.eigvals(M).astype(complex)  # balanced QR: backward stable
    r = r0.copy()
    cb = cc[:, :, None]
    with np.errstate(all="ignore"):
        for _ in range(polish):
            p = _poly(cb, r)
            step = p / _dpoly(cb, r)
            new = r - step
            better = np.isfinite(new) & (np.abs(_poly(cb, new)) < np.abs(p))
            r = np.where(better, new, r)
        # keep the polished triple only where it is also the better factorisation (guards
        # against two polished roots of a close pair collapsing onto one).
        keep = _vieta_error(cc, r) <= _vieta_error(cc, r0)
    r = np.where(keep[:, None], r, r0)
    # real coefficients: one real root and a conjugate pair, or three real roots
    order = np.argsort(r.imag, axis=1)
    r = np.take_along_axis(r, order, axis=1)
    pair = r[:, 2].imag > 0
    r[:, 1] = np.where(pair, r[:, 1].real + 0j, r[:, 1])
    r[:, 0] = np.where(pair, np.conj(r[:, 2]), r[:, 0])
    out[ok] = r
    return out


def cubic_roots(a0, a1, a2, a3, *, polish=3):
    """Roots of Hamabe's characteristic cubic (29) ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3``.

    Returns a complex array of shape ``broadcast(a0, a1, a2, a3).shape + (3,)``, each triple
    sorted by real part, then imaginary part (a conjugate pair is exactly conjugate, a real root
    has imaginary part exactly 0).  Method: eigenvalues of the balanced companion matrix (one
    stacked LAPACK call), then up to ``polish`` Newton steps on the cubic itself, each accepted
    only if it lowers the residual, and the polished triple kept only if its Vieta coefficients
    match the cubic at least as well.  This handles stiff spreads (roots 1e-5 .. 1e5) with small
    relative error in every root; roots of a cluster of multiplicity m are, unavoidably, only
    accurate to about ``eps**(1/m)``, but the triple stays backward stable, which is all that
    :func:`transient` needs.  Rows with ``a0 = 0`` or non-finite coefficients give nan.
    (Hamabe, Disturbing Actions of a Shaft Governor, eq. (29); his (39), (41) are replaced.)

    >>> r = cubic_roots(1.0, 2.0, 3.0, 4.0)   # (s + 1)^2 (s + 4): the double root to 1e-8
    >>> bool(np.allclose(np.sort_complex(r), [-4.0, -1.0, -1.0], rtol=0.0, atol=1e-7))
    True
    """
    a0, a1, a2, a3 = _floats(a0, a1, a2, a3)
    shape = a0.shape
    c = np.stack([x.reshape(-1) for x in (a0, a1, a2, a3)])
    r = _roots_flat(c, polish)
    r = np.sort(r, axis=-1)  # numpy orders complex lexicographically: real, then imag
    return r.reshape(shape + (3,))


def _pair_separations(r):
    """Relative separations |ri - rj| / max(|ri|, |rj|) of the pairs (12, 13, 23), (..., 3)."""
    pairs = ((0, 1), (0, 2), (1, 2))
    seps = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for i, j in pairs:
            d = np.abs(r[..., i] - r[..., j])
            s = np.maximum(np.abs(r[..., i]), np.abs(r[..., j]))
            seps.append(np.where(d == 0, 0.0, d / s))
    return np.stack(seps, axis=-1)


def _classify_roots(r, rtol):
    seps = _pair_separations(r)
    repeated = (seps.min(axis=-1) <= rtol) | (seps.max(axis=-1) <= rtol ** (2.0 / 3.0))
    cplx = np.abs(r.imag).max(axis=-1) > 0
    bad = ~np.isfinite(r).all(axis=-1)
    kind = np.where(repeated, "repeated", np.where(cplx, "complex", "real"))
    return np.where(bad, "invalid", kind)


def classify(a0, a1, a2, a3, rtol=1e-6):
    """Kind of the roots of the cubic (29): ``"real"``, ``"complex"`` or ``"repeated"``.

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (37): the sign of ``G^2 + 4 H^3`` (see
    :func:`discriminant`) separates three distinct real roots (< 0) from one real root and a
    complex pair (> 0); zero means a repeated root.  Deciding "zero" needs a tolerance: the
    roots are called repeated when they can be made to coincide by a relative perturbation of
    the coefficients of about ``rtol**2``, i.e. when two roots agree to ``rtol`` relative, or
    all three to ``rtol**(2/3)`` (a double root splits like the square root of a coefficient
    perturbation, a triple root like the cube root).  The default ``rtol = 1e-6`` sits well
    above the rounding noise of an exactly repeated root (``sqrt(eps)``, ``eps**(1/3)``).  Outside
    the tolerance the discriminant's sign is read from the (accurate) roots, equivalent to (37)
    but free of its cancellation.  Returns a str for scalar input, else an array of str;
    ``"invalid"`` for rows with ``a0 = 0`` or non-finite coefficients.

    >>> classify(1.76, 24, 211.2, 840), classify(1.76, 15, 211.2, 840), classify(1, 1, 1, 1)
    ('real', 'complex', 'repeated')
    """
    r = cubic_roots(a0, a1, a2, a3)
    kind = _classify_roots(r, rtol)
    return str(kind) if kind.ndim == 0 else kind


# --------------------------------------------------------------------------------------------
# Divided differences of exp, and the response
# --------------------------------------------------------------------------------------------


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
    of s -> exp(s t); derivative orders j > 0 use all six (see _Response).

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


class _Response:
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
        arrs = _floats(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0)
        _check_inputs(arrs)
        shape = arrs[0].shape
        flat = np.stack([x.reshape(-1) for x in arrs])
        roots = np.sort(_roots_flat(flat[:4], 3), axis=-1)
        return cls(flat[:4], flat[4:], roots, order), shape

    @property
    def n(self):
        return self.roots.shape[0]

    def subset(self, idx):
        new = object.__new__(_Response)
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
        step = max(1, _BLOCK // max(T, 1))
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
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.ndim != 1:
        raise ValueError("t must be a 1-D array of times")
    if order < 0:
        raise ValueError("order must be >= 0")
    resp, shape = _Response.build(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, order)
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

    >>> xi = transient(1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, [0.0, 1.0])   # triple root s = -1
    >>> np.allclose(xi, [1.0, 2.5 * np.exp(-1.0)])
    True
    >>> x = transient(1.0, -10.0, 100.0, 10.0, -0.128, 0.0, 18.7, [47.23, 47.5])  # growing
    >>> bool(1.28e307 < x[0] < 1.29e307 and x[1] == -np.inf)
    True
    """
    return transient_derivatives(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, t, order=0)[0]


# --------------------------------------------------------------------------------------------
# Over-regulation for all t >= 0: the late-time sign from the dominant mode(s)
# --------------------------------------------------------------------------------------------

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
    :attr:`TransientSummary.over_regulation_scaled` (or the array of
    :attr:`TransientSummary`): ``-s0 xi(t) exp(-rho t)`` (``s0`` the side the response starts
    on, ``rho`` the largest real part of the roots) at the largest far-side excursion, or its
    upper limit as ``t -> inf`` if larger (with three real roots: its exact supremum over
    ``t >= 0``); positive exactly when ``xi`` crosses zero (:class:`_Tail`).  Scaling by the
    slowest mode keeps a crossing late in the tail visible: its plain amount is exponentially
    small (it may even underflow), which is why the decision is not made on
    :attr:`~TransientSummary.over_regulation` itself.  True
    where ``over_regulation_scaled > OVER_TOL |xi0|``, and where it is nan (not decided, e.g.
    a grid truncated before the dominance time): conservative.  ``xi0`` in rad.

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


class _Tail:
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


# --------------------------------------------------------------------------------------------
# The analysis of one design or many at once
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class TransientSummary:
    """Load-change response of designs (Hamabe, Disturbing Actions of a Shaft Governor, III):
    arrays of the broadcast shape of :func:`analyse_many`'s inputs (``roots`` has a trailing
    axis of 3; one design: 0-d arrays).

    ``over_regulation`` is the largest excursion of ``xi`` past 0 on the side opposite to
    ``xi0`` over all ``t >= 0`` (same units as ``xi``; 0.0 if it never crosses) -- the pendulum
    passing its new equilibrium.  It may be exponentially small (a crossing late in the tail;
    it underflows to 0 past ~1e-300): decide with :func:`over_regulates` on
    ``over_regulation_scaled``, the same excursion measured against the slowest mode's decay
    (see :class:`_Tail`), nan where undecided (conservatively: over-regulates).
    ``first_arrival_time`` is the first ``t > 0`` with ``xi = 0`` (inf if none).
    ``settling_time`` is the smallest ``T`` with ``|xi(t)| <= band * |xi0|`` for all ``t >= T``
    (``|xi0|`` replaced by ``max |xi|`` if ``xi0 = 0``); inf for an unstable design, or when a
    stable design has not settled within ``horizon`` (``|xi| <= band |xi0| / 4`` over its last
    quarter; then ``truncated`` is True: *not decided*, not 'never').  Where the event grid is
    cut at ``max_points`` before the response settles (a lightly damped pendulum under a huge
    flywheel) settling is found past it from the modes' envelope (:func:`_envelope_settling`)
    and may exceed ``horizon``.  The horizon reaches every zero of ``xi`` and the largest far-side
    excursion (:class:`_Tail`).  For unstable designs
    ``over_regulation`` and the other events are those within ``horizon`` (the decision still
    covers all t).
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


def _refine(resp, j, target, lo, hi, iters=100):
    """Vectorised safeguarded Newton (Numerical Recipes' rtsafe) for resp_j(t) = target on the
    brackets [lo, hi], one per row of resp (which needs order >= j + 1: the derivative drives
    Newton).  A Newton step is taken only if it stays inside the bracket and at least halves
    the step before last; otherwise the bracket is bisected.  Rows stop when the step is at
    rounding level (|dt| <= 4 eps t) or the residual is exactly zero.
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


def _local_max(v):
    """Interior grid local maxima of the rows of v (>= left neighbour, > right neighbour), as
    index arrays (rows, columns) in row-major order."""
    with np.errstate(invalid="ignore"):
        r, k = np.nonzero((v[:, 1:-1] >= v[:, :-2]) & (v[:, 1:-1] > v[:, 2:]))
    return r, k + 1


def _refine_peaks(resp, t, xd, r, k):
    """Exact extrema next to grid points (r, k) (zeros of xi' in [t_k-1, t_k] or [t_k, t_k+1]).

    Returns the rows, grid indices, times and xi values of those with a bracket.
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
    te = _refine(sub, 1, 0.0, lo, hi)
    return r, k, te, sub(te[:, None], nder=0)[:, 0, 0]


def _exact_max(resp, t, xd, v, sign, clip, amp, lmax=None):
    """Exact maximum over t > 0 of v = sign * xi per row: the grid maximum, raised to the exact
    peaks of the lobes that the grid may have clipped (within ``clip * amp`` of it).  For
    v = |xi| pass sign = None (its interior local maxima are extrema of xi).  Returns the
    maxima and their times.  With a sign, grid maxima at or below zero are refined too where
    the slope allows the lobe to reach zero between the neighbouring grid points (a far-side
    lobe that the grid clipped, e.g. near a tangency).  ``lmax``: :func:`_local_max` of v, if
    already known."""
    rows = np.arange(v.shape[0])
    kmax = np.argmax(v, axis=1)
    vmax = v[rows, kmax]
    r, k = _local_max(v) if lmax is None else lmax
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
        r, k, te, xe = _refine_peaks(resp, t, xd, r, k)
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

    resp: _Response (order >= 2) for n designs; t (n, M) increasing per row, t[:, 0] = 0;
    y = _grid_values(resp, t) (xi, xi'); the band is band * |d0| (or band * max |xi| where
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
    lr, lk = _local_max(v)
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
        r, k, te, xe = _refine_peaks(resp, t, xd, r, k)
        hit = -s0[r] * xe >= 0
        r, k, te = r[hit], k[hit], te[hit]
        first = np.unique(r, return_index=True)[1]  # earliest lobe per row (sorted by k)
        r, k, te = r[first], k[first], te[first]
        lo[r], hi[r], has[r] = t[r, k - 1], te, True
    arrival = np.full(n, np.inf)
    idx = np.nonzero(has)[0]
    if idx.size:
        arrival[idx] = _refine(resp.subset(idx), 0, 0.0, lo[idx], hi[idx])
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
    r, k = _local_max(ax)
    late = (k > last[r]) & (ax[r, k] >= 0.9 * b[r]) & ok[r]
    r, k = r[late], k[late]
    if r.size:
        r, k, te, xe = _refine_peaks(resp, t, xd, r, k)
        hit = np.abs(xe) > b[r]
        r, k, te, xe = r[hit], k[hit], te[hit], xe[hit]
        lastlobe = r.size - 1 - np.unique(r[::-1], return_index=True)[1]  # latest per row
        r, k, te, xe = r[lastlobe], k[lastlobe], te[lastlobe], xe[lastlobe]
        lo[r], hi[r], sgn[r], todo[r] = te, t[r, k + 1], np.sign(xe), True
    idx = np.nonzero(todo)[0]
    if idx.size:
        settling[idx] = _refine(resp.subset(idx), 0, sgn[idx] * b[idx], lo[idx], hi[idx])
    return arrival, over, t_over, settling, b


def _modal_amplitudes(l, d):
    """Modal amplitudes ``c_k`` of ``xi(t) = sum_k c_k exp(l_k t)`` for distinct roots ``l``
    (n, 3) and initial state ``d`` (n, >= 3): ``c_k = ((A - l_i)(A - l_j) x0)_0 / ((l_k - l_i)
    (l_k - l_j))`` (partial fractions of eq. (28); Hamabe's constants (38), (40) restated).
    Complex (n, 3); inf or nan where roots coincide (callers test separation first)."""
    c = np.empty(l.shape, complex)
    for k, (i, j) in enumerate(((1, 2), (0, 2), (0, 1))):
        li, lj, lk = l[:, i], l[:, j], l[:, k]
        c[:, k] = (d[:, 2] - (li + lj) * d[:, 1] + li * lj * d[:, 0]) / ((lk - li) * (lk - lj))
    return c


#: Smallest relative root separation at which :func:`_grid_values` sums the modes directly.
_MODAL_SEP = 1e-2


def _grid_values(resp, t):
    """``xi`` and ``xi'`` (n, 2, T) at the event-search grid ``t`` (n, T): values that only
    bracket events and pick the lobes to refine -- every reported figure is located on the
    Newton form (:func:`_refine`, :func:`_exact_max`).

    Where every mode decays and the roots are well separated (relative separation >=
    ``_MODAL_SEP``) the modal sum ``sum c_k exp(l_k t)`` (:func:`_modal_amplitudes`) is used: a
    few exponentials per point instead of the divided differences, and no overflow (all
    ``exp(l t) <= 1``).  Its error is the amplitudes' rounding, of order
    ``eps / _MODAL_SEP**2 ~ 2e-12`` of the trajectory's scale (two root differences in the
    denominator; tests/test_transient.py measures below 1e-11 at the threshold, 1e-14 on
    typical designs), so a grid sign can differ from the Newton form's only where ``|xi|`` is
    that close to 0 (a lobe grazing zero at a grid point; the figure found is then rounding
    either way).  Other rows use the Newton form, bit for bit.
    """
    n, T = resp.n, t.shape[-1]
    t = np.broadcast_to(t, (n, T))
    l = resp.roots
    with np.errstate(all="ignore"):
        c = _modal_amplitudes(l, resp.d)
        modal = (np.isfinite(c).all(axis=1) & (l.real.max(axis=1) < 0)
                 & (_pair_separations(l).min(axis=1) >= _MODAL_SEP))
    out = np.empty((n, 2, T))
    rest = np.nonzero(~modal)[0]
    if rest.size:
        out[rest] = resp.subset(rest)(t[rest], nder=1)
    cplx = (l.imag != 0).any(axis=1)
    step = max(1, _BLOCK // max(T, 1))
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
    well = ok & (_pair_separations(l).min(axis=1) >= 1e-3)
    with np.errstate(all="ignore"):
        amp = np.abs(_modal_amplitudes(l, d))
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
                 n_log=160, per_period=_PER_PERIOD, max_points=MAX_TRANSIENT_POINTS):
    """The load-change response of one design or many at once (the one transient analysis:
    :func:`govopt.evaluate` calls it with one design, the design search with many).

    Hamabe, Disturbing Actions of a Shaft Governor, Part III, eqs. (28), (32), (37).  Each design
    gets its own grid: ``n_log`` log-spaced times from 1e-3 of its fastest time constant to its
    horizon, plus, if it oscillates, uniform times at ``per_period`` points per period (at most
    ``max_points``) over the part of the horizon where oscillation can still create events
    (where the roots are well separated, only until every faster mode is below 1e-12 of the
    slowest; a slowest damped pair's settling crossing is then extrapolated exactly from one
    extremum -- see :func:`_modal_windows`).  Designs are processed in batches of equal grid
    width.  The first zero of ``xi``, the largest opposite-side excursion (at a zero of
    ``xi'``) and the last band crossing are bracketed and refined by a vectorised bracketed
    Newton iteration on the analytic response (exact to rounding).
    Over-regulation is decided for all ``t >= 0`` (:class:`_Tail`, :func:`over_regulates`): the
    default horizon is ``(ln(1/band) + 12)/decay`` (decay = slowest rate) for a stable design
    and a few slow periods (at most e^20 growth) for an unstable one, extended to the window the
    dominant modes call for (the dominance time, and until no later far-side excursion can be
    larger than the one found), and doubled for the designs whose tail is not yet well inside
    the band; a stable design not settled within it is reported inf (``truncated``).  Where the
    uniform grid is cut at ``max_points`` before settling, settling comes from the modes'
    envelope (:func:`_envelope_settling`).  Returns a :class:`TransientSummary`; raises
    ValueError for non-finite inputs or ``a0 = 0`` (nan events only where the roots themselves
    overflow).
    """
    if not band > 0:
        raise ValueError("band must be positive")
    resp, shape = _Response.build(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, order=2)
    c = resp.c
    n = resp.n
    roots = resp.roots
    d = resp.d
    valid = np.isfinite(roots).all(axis=-1) & np.isfinite(d[:, :4]).all(axis=-1)
    stable = is_stable(*c) & valid
    margin = hurwitz_margin(*c)
    kind = _classify_roots(roots, 1e-6)
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
    late = _Tail(resp.subset(vi), s0[vi])
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
                y = _grid_values(sub, t)
                a_, o_, to_, st_, b = _events_on_grid(sub, t, y, s0[idx], band, d[idx, 0],
                                                      stable[idx], per_period)
                ex = extrap[loc]
                settled = _tail_ok(t, y[:, 0], b)
                tail = settled | ex
                st_ = np.where(stable[idx] & ~tail, np.inf, st_)  # not settled in horizon
                if ex.any():
                    e = np.nonzero(ex)[0]
                    st_[e] = _extrapolate_settling(sub.subset(e), t[e], y[e], b[e], st_[e])
                # grid cut at max_points before settling: the modes' envelope decides
                cut = truncated[loc] & stable[idx] & ~settled
                if cut.any():
                    e = np.nonzero(cut)[0]
                    env = _envelope_settling(sub.subset(e), b[e], per_period, max_points)
                    st_[e] = np.where(np.isnan(env), np.inf, env)
                    unresolved[idx[e]] = np.isnan(env)
                arrival[idx], over[idx], t_over[idx], settling[idx] = a_, o_, to_, st_
                if horizon is None:
                    # longer: to settle (doubling), or until no later far-side excursion can
                    # exceed the one found (_Tail.wanted)
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


def _extrapolate_settling(resp, t, y, b, settled):
    """Settling of designs whose grid ends once only their slowest damped pair is left (see
    :func:`_modal_windows`): from the last exact extremum ``t_e`` in the window, the extrema
    are ``t_e + k pi/q`` with heights falling by ``exp(-sigma pi/q)`` each; the last one above
    the band and the next bracket the crossing, refined on the analytic response.  Rows whose
    last extremum is already inside the band keep ``settled`` (found within the window)."""
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
    te = _refine(sub, 1, 0.0, t[idx, j[idx]], t[idx, j[idx] + 1])
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
    out[idx] = _refine(sub, 0, np.sign(vk) * b[idx], tk, tk + half)
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
    r, k = _local_max(ax)
    late = (k > last[r]) & (ax[r, k] >= 0.9 * b[r])
    if late.any():
        r, k, te, xe = _refine_peaks(resp, t, xd, r[late], k[late])
        hit = np.abs(xe) > b[r]
        r, k, te, xe = r[hit], k[hit], te[hit], xe[hit]
        lastlobe = r.size - 1 - np.unique(r[::-1], return_index=True)[1]  # latest per row
        r, k, te, xe = r[lastlobe], k[lastlobe], te[lastlobe], xe[lastlobe]
        lo[r], hi[r], sgn[r], last[r] = te, t[r, k + 1], np.sign(xe), k
    out = np.full(n, np.nan)
    ok = np.nonzero((last >= 0) & (last < M - 1))[0]
    if ok.size:
        out[ok] = _refine(resp.subset(ok), 0, sgn[ok] * b[ok], lo[ok], hi[ok])
    return out


def _envelope_settling(resp, b, per_period=_PER_PERIOD, max_points=MAX_TRANSIENT_POINTS):
    """Settling time (last ``|xi| = b``) of stable designs with a real root ``r`` and a damped
    pair ``p`` whose event grid is cut at ``max_points`` (a pendulum's 0.3 s swing under a huge
    flywheel's 1e5 s decay), without a grid over the whole transient.

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (28): ``xi = c_r e^{r t} +
    2 Re(c_p e^{p t})`` (:func:`_modal_amplitudes`), so ``|xi(t)| <= E(t) = |c_r| e^{r t} +
    2 |c_p| e^{Re(p) t}``, a decreasing envelope.  Past ``T_E`` with ``E(T_E) = b`` (bisected,
    ``b`` lowered by 1e-9 to cover the amplitudes' rounding) ``xi`` stays in the band, so the
    last exit lies before it; it is searched on a grid of ``per_period`` points per period of
    the pair over the last 2, 4, 8, ... periods before ``T_E`` until one is above ``b`` (the
    envelope changes little over a period, so usually the first window holds it), then located
    on the analytic response (:func:`_last_exit`).  ``b`` in the units of ``xi``, per design.
    Returns seconds, nan where not resolved (roots not well separated -- relative separation
    below 1e-3, where the amplitudes lose accuracy -- or a window of ``max_points`` points).

    >>> resp, _ = _Response.build(1.0, 2e-5 / 3 + 1e-8 / 3, (100.0 + 2e-5 * 1e-8) / 3,
    ...                           100.0 * 1e-8, -0.1, 0.0, 0.0, order=2)
    >>> round(float(_envelope_settling(resp, np.array([0.002]))[0]), 1)  # ln(50) / 1e-8
    391202300.5
    """
    n = resp.n
    out = np.full(n, np.nan)
    l = resp.roots
    with np.errstate(all="ignore"):
        c = _modal_amplitudes(l, resp.d)
        ok = ((l.imag != 0).any(axis=1) & (l.real.max(axis=1) < 0) & np.isfinite(c).all(axis=1)
              & (_pair_separations(l).min(axis=1) >= 1e-3))
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


def over_regulation_many(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, horizon=None):
    """Over-regulation of many designs at once (see :func:`analyse_many`); 0.0 if none.

    Hamabe, Disturbing Actions of a Shaft Governor, Part III: the largest excursion of ``xi``
    past the new equilibrium, on the side opposite to ``xi0``, over all ``t >= 0``.  It may be
    exponentially small: decide over-regulation with :func:`over_regulates` on
    ``analyse_many(...).over_regulation_scaled``.
    """
    return analyse_many(a0, a1, a2, a3, xi0, xi_dot0, xi_ddot0, horizon=horizon).over_regulation
