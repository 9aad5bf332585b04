"""Hamabe's load-change equation (28) and its characteristic cubic (29): the coefficients and
initial state of a load change, the stability test, the discriminant, and the roots with their
kind (real, complex, repeated).

Hamabe, *Disturbing Actions of a Shaft Governor*, Part III.  After a sudden load change the
pendulum's deviation ``xi`` from its new equilibrium obeys eq. (28)::

    a0 xi''' + 3 a1 xi'' + 3 a2 xi' + a3 xi = 0,
    a0 = I,  3 a1 = f (dash-pot),  3 a2 = I k^2,  a3 = 2 R omega0 a m rho sin(alpha0),

with characteristic cubic (29) ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3 = 0``.  Everything here is
pure and vectorised: coefficients broadcast against each other over any leading shape.

Hamabe's root formulas (39), (41) are the trigonometric / Cardano solutions, which break down at
and near repeated roots, exactly where a well-damped governor is tuned; :func:`cubic_roots`
replaces them with the companion matrix's eigenvalues, polished, backward stable.  The response
built on these roots is :mod:`govopt.analysis.transient`.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "as_floats",
    "classify",
    "classify_roots",
    "cubic_roots",
    "discriminant",
    "hamabe_coefficients",
    "hamabe_initial_conditions",
    "hurwitz_margin",
    "is_stable",
    "pair_separations",
    "roots_of_rows",
]


def as_floats(*xs):
    """The arguments as float arrays broadcast against each other."""
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
    I, f, k2, R, omega0, a, m, rho, alpha0 = as_floats(I, f, k2, R, omega0, a, m, rho, alpha0)
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
    a0, a2, a3, R, xi0, eta0 = as_floats(a0, a2, a3, R, xi0, eta0)
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
    a0, a1, a2, a3 = as_floats(a0, a1, a2, a3)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 9.0 * a1 * a2 / (a0 * a3) - 1.0


def is_stable(a0, a1, a2, a3):
    """Asymptotic stability of eq. (28): all coefficients of one sign and ``9 a1 a2 > a0 a3``.

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (32) (Hurwitz).  The products are
    compared directly, so no division is involved.  The boundary (margin exactly 0: an undamped
    oscillation) is *not* stable.
    """
    a0, a1, a2, a3 = as_floats(a0, a1, a2, a3)
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
    a0, a1, a2, a3 = as_floats(a0, a1, a2, a3)
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


def roots_of_rows(c, polish):
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

    Returns a complex array of shape ``broadcast(a0, a1, a2, a3).shape + (3,)``, each triple sorted
    by real part, then imaginary part (a conjugate pair is exactly conjugate, a real root has
    imaginary part exactly 0).  Method: eigenvalues of the balanced companion matrix (one stacked
    LAPACK call), then up to ``polish`` Newton steps on the cubic itself, each accepted only if it
    lowers the residual, and the polished triple kept only if its Vieta coefficients match the cubic
    at least as well.  This handles stiff spreads (roots 1e-5 .. 1e5) with small relative error in
    every root; roots of a cluster of multiplicity m are, unavoidably, only accurate to about
    ``eps**(1/m)``, but the triple stays backward stable, which is all that
    :func:`govopt.analysis.transient.transient` needs.  Rows with ``a0 = 0`` or non-finite
    coefficients give nan. (Hamabe, Disturbing Actions of a Shaft Governor, eq. (29); his (39), (41)
    are replaced.)

    >>> r = cubic_roots(1.0, 2.0, 3.0, 4.0)   # (s + 1)^2 (s + 4): the double root to 1e-8
    >>> bool(np.allclose(np.sort_complex(r), [-4.0, -1.0, -1.0], rtol=0.0, atol=1e-7))
    True
    """
    a0, a1, a2, a3 = as_floats(a0, a1, a2, a3)
    shape = a0.shape
    c = np.stack([x.reshape(-1) for x in (a0, a1, a2, a3)])
    r = roots_of_rows(c, polish)
    r = np.sort(r, axis=-1)  # numpy orders complex lexicographically: real, then imag
    return r.reshape(shape + (3,))


def pair_separations(r):
    """Relative separations |ri - rj| / max(|ri|, |rj|) of the pairs (12, 13, 23), (..., 3)."""
    pairs = ((0, 1), (0, 2), (1, 2))
    seps = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for i, j in pairs:
            d = np.abs(r[..., i] - r[..., j])
            s = np.maximum(np.abs(r[..., i]), np.abs(r[..., j]))
            seps.append(np.where(d == 0, 0.0, d / s))
    return np.stack(seps, axis=-1)


def classify_roots(r, rtol):
    seps = pair_separations(r)
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
    kind = classify_roots(r, rtol)
    return str(kind) if kind.ndim == 0 else kind
