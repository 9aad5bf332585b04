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
    """The arguments as float arrays broadcast against each other.

    govopt's own helper (no source): every function of the load-change cubic
    ([hamabe] eqs. (28)-(29)) is vectorised through it.

    Parameters
    ----------
    *xs : float or array [-]
        Numbers in any unit; the unit of each is kept.

    Returns
    -------
    list of ndarray [-]
        One float array per argument, all of the broadcast shape.

    Examples
    --------
    >>> [x.tolist() for x in as_floats(1, [2, 3])]
    [[1.0, 1.0], [2.0, 3.0]]
    """
    return np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in xs))


# --------------------------------------------------------------------------------------------
# Coefficients, initial conditions, stability
# --------------------------------------------------------------------------------------------


def hamabe_coefficients(I, f, k2, R, omega0, a, m, rho, alpha0):
    """Coefficients ``(a0, a1, a2, a3)`` of Hamabe's eq. (28) from the design quantities.

    ``a0 = I``, ``3 a1 = f``, ``3 a2 = I k^2``, ``a3 = 2 R omega0 a m rho sin(alpha0)``
    (Hamabe, Disturbing Actions of a Shaft Governor, eqs. (27)-(28)).  Any consistent units.

    Parameters
    ----------
    I : float or array [kg m^2]
        Moment of inertia of the pendulum about its fulcrum.
    f : float or array [N m s/rad]
        Dash-pot coefficient (moment per angular velocity of the pendulum, eq. (23)).
    k2 : float or array [1/s^2]
        Square of the pendulum's natural angular frequency, ``k^2`` (Part II).
    R : float or array [1/s^2]
        ``-(dT/dalpha) / I_fw``, the engine's torque slope over the flywheel's inertia (eq. 27).
    omega0 : float or array [rad/s]
        Shaft speed at the new equilibrium.
    a : float or array [m]
        Distance from the shaft to the pendulum's fulcrum.
    m : float or array [kg]
        Mass of the pendulum.
    rho : float or array [m]
        Distance from the fulcrum to the pendulum's centre of mass.
    alpha0 : float or array [rad]
        Pendulum angle at the new equilibrium.

    Returns
    -------
    tuple of ndarray [kg m^2, kg m^2/s, kg m^2/s^2, kg m^2/s^3]
        ``(a0, a1, a2, a3)``.

    References
    ----------
    [hamabe] Part III, eqs. (27)-(28).

    Examples
    --------
    Example 3, case a (W = 12 kgf, rho = 12 cm, k^2 = 360, a dash-pot f = 72 kgf cm s, in the
    paper's kgf-cm-s units with g = 981 cm/s^2): the paper prints a0 = 1.76, a1 = 24,
    a3 = 840 and ``a2 = a0 k^2 / 3`` = 211.2; a3 differs in the third digit because the paper
    rounds it (its slide-rule value).

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

    Parameters
    ----------
    a0, a2, a3 : float or array [kg m^2], [kg m^2/s^2], [kg m^2/s^3]
        Coefficients of eq. (28) (see :func:`hamabe_coefficients`).
    R : float or array [1/s^2]
        ``-(dT/dalpha) / I_fw`` (eq. 27).
    xi0 : float or array [rad]
        Initial deviation ``alpha1 - alpha0`` from the new equilibrium.
    eta0 : float or array [rad/s]
        Initial speed error ``omega1' - omega0``.

    Returns
    -------
    tuple of ndarray [rad, rad/s, rad/s^2]
        ``(xi(0), xi'(0), xi''(0))``.

    References
    ----------
    [hamabe] Part III, the initial conditions preceding eq. (38).

    Examples
    --------
    Example 3, case a (unloading from 57 deg 20' to 64 deg 40', R = 300/43, kgf-cm-s): the
    paper states xi0 = -0.128 rad and eta0 = -0.4 rad/s; ``xi''(0)`` is
    ``((840 / R)(-0.4) + 3 (211.2)(0.128)) / 1.76``, checked by hand.

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

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28), ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3`` (SI: ``a0`` [kg m^2],
        ``a1`` [kg m^2/s], ``a2`` [kg m^2/s^2], ``a3`` [kg m^2/s^3]; any consistent set, the
        paper's is kgf-cm-s), broadcast against each other.

    Returns
    -------
    ndarray [-]
        The margin; positive is stable (given positive coefficients).

    References
    ----------
    [hamabe] eq. (32); [hurwitz].

    Examples
    --------
    Example 3, case a (a0 = 1.76, a1 = 24, a2 = 211.2, a3 = 840 as the paper prints them):
    stable with a wide margin, ``9 (24)(211.2) / (1.76)(840) - 1`` by hand. A cubic with
    ``a1 = 1/9`` (of a0 = a2 = a3 = 1) sits exactly on the boundary.

    >>> round(float(hurwitz_margin(1.76, 24, 211.2, 840)), 4)   # Example 3, case a
    29.8571
    >>> round(float(hurwitz_margin(1, 1 / 9, 1, 1)), 12)
    0.0
    """
    a0, a1, a2, a3 = as_floats(a0, a1, a2, a3)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 9.0 * a1 * a2 / (a0 * a3) - 1.0


def is_stable(a0, a1, a2, a3):
    """Asymptotic stability of eq. (28): all coefficients of one sign and ``9 a1 a2 > a0 a3``.

    Hamabe, Disturbing Actions of a Shaft Governor, eq. (32) (Hurwitz).  The products are
    compared directly, so no division is involved.  The boundary (margin exactly 0: an undamped
    oscillation) is *not* stable.

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28), ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3`` (SI: ``a0`` [kg m^2],
        ``a1`` [kg m^2/s], ``a2`` [kg m^2/s^2], ``a3`` [kg m^2/s^3]; any consistent set, the
        paper's is kgf-cm-s), broadcast against each other.

    Returns
    -------
    ndarray of bool [-]
        True where every root of (29) has a negative real part.

    References
    ----------
    [hamabe] eq. (32); [hurwitz].

    Examples
    --------
    Example 3, case a (the paper's coefficients; the paper finds it stable); no damping
    (``a1 = 0``) is never stable.

    >>> bool(is_stable(1.76, 24, 211.2, 840)), bool(is_stable(1.76, 0, 211.2, 840))
    (True, False)
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

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28), ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3`` (SI: ``a0`` [kg m^2],
        ``a1`` [kg m^2/s], ``a2`` [kg m^2/s^2], ``a3`` [kg m^2/s^3]; any consistent set, the
        paper's is kgf-cm-s), broadcast against each other.

    Returns
    -------
    ndarray [kg^6 m^12/s^6]
        ``G^2 + 4 H^3``.

    References
    ----------
    [hamabe] Part III, eqs. (33)-(34), (37).

    Examples
    --------
    A triple root s = -1 (hand-checkable: H = G = 0); Example 3, case a with a1 = 15 (the
    paper prints H = 146, G = -7340: a complex pair, so positive).

    >>> float(discriminant(1.0, 1.0, 1.0, 1.0))   # triple root s = -1
    0.0
    >>> bool(discriminant(1.76, 15, 211.2, 840) > 0)
    True
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
    """Roots of the rows of c = (a0, a1, a2, a3) (each shape (n,)), unsorted, (n, 3) complex.

    The work of :func:`cubic_roots` on flat rows: govopt's own numerical method (companion
    matrix and Newton polish) for the cubic (29) of [hamabe], replacing his (39), (41).

    Parameters
    ----------
    c : ndarray [kg m^2 s^-i]
        Shape (4, n): the coefficients ``a0, a1, a2, a3`` of eq. (28) per column.
    polish : int [-]
        Newton steps at most (dimensionless count).

    Returns
    -------
    ndarray [1/s]
        Shape (n, 3), complex; nan rows where ``a0 = 0`` or a coefficient is not finite.

    Examples
    --------
    ``(s + 1)^2 (s + 4)``: the double root is accurate to about ``sqrt(eps)``.

    >>> r = roots_of_rows(np.array([[1.0], [2.0], [3.0], [4.0]]), 3)
    >>> [round(float(x.real), 6) for x in np.sort_complex(r[0])]
    [-4.0, -1.0, -1.0]
    """
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

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28), ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3`` (SI: ``a0`` [kg m^2],
        ``a1`` [kg m^2/s], ``a2`` [kg m^2/s^2], ``a3`` [kg m^2/s^3]; any consistent set, the
        paper's is kgf-cm-s), broadcast against each other.
    polish : int [-]
        Newton steps at most (dimensionless count).

    Returns
    -------
    ndarray [1/s]
        Complex roots, shape ``broadcast.shape + (3,)``.

    References
    ----------
    [hamabe] Part III, eq. (29); the method is govopt's own (his (39), (41) are replaced).

    Examples
    --------
    Example 3, case a: the paper prints -29.1, -10, -1.7 (its -1.7 and -10 come from a
    slide-rule G about 3 % off; the exact cubic gives -1.61 and -10.2), and for a1 = 15 it
    prints -1.5 and -12.043 +- 13.35i.

    >>> [round(float(x.real), 2) for x in cubic_roots(1.76, 24, 211.2, 840)]
    [-29.1, -10.2, -1.61]
    >>> [complex(round(x.real, 2), round(x.imag, 2)) for x in cubic_roots(1.76, 15, 211.2, 840)]
    [(-12.05-13.39j), (-12.05+13.39j), (-1.47+0j)]
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
    """Relative separations |ri - rj| / max(|ri|, |rj|) of the pairs (12, 13, 23), (..., 3).

    govopt's own measure for deciding the repeated roots of Hamabe's eq. (37) ([hamabe]) with a
    tolerance (see :func:`classify`).

    Parameters
    ----------
    r : ndarray [1/s]
        Root triples, shape (..., 3).

    Returns
    -------
    ndarray [-]
        Shape (..., 3), 0 for coinciding roots.

    Examples
    --------
    Roots -1, -1.1, -4 (by hand: 0.1/1.1, 3/4, 2.9/4).

    >>> [round(float(x), 4) for x in pair_separations(np.array([-1, -1.1, -4]))]
    [0.0909, 0.75, 0.725]
    """
    pairs = ((0, 1), (0, 2), (1, 2))
    seps = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for i, j in pairs:
            d = np.abs(r[..., i] - r[..., j])
            s = np.maximum(np.abs(r[..., i]), np.abs(r[..., j]))
            seps.append(np.where(d == 0, 0.0, d / s))
    return np.stack(seps, axis=-1)


def classify_roots(r, rtol):
    """Kind of root triples: ``"real"``, ``"complex"``, ``"repeated"`` or ``"invalid"``.

    The decision of :func:`classify` on roots already found: the sign of Hamabe's eq. (37)
    ([hamabe]) read from the roots, with govopt's own tolerance for "repeated".

    Parameters
    ----------
    r : ndarray [1/s]
        Root triples, shape (..., 3).
    rtol : float [-]
        Relative separation below which two roots count as one (three: ``rtol**(2/3)``).

    Returns
    -------
    ndarray of str [-]
        One kind per triple.

    Examples
    --------
    Example 3, case a (three distinct real roots, as the paper finds), and a double root.

    >>> str(classify_roots(cubic_roots(1.76, 24, 211.2, 840), 1e-6))
    'real'
    >>> str(classify_roots(np.array([-1.0, -1.0, -4.0]), 1e-6))
    'repeated'
    """
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

    Parameters
    ----------
    a0, a1, a2, a3 : float or array [kg m^2 s^-i]
        Coefficients of eq. (28), ``a0 s^3 + 3 a1 s^2 + 3 a2 s + a3`` (SI: ``a0`` [kg m^2],
        ``a1`` [kg m^2/s], ``a2`` [kg m^2/s^2], ``a3`` [kg m^2/s^3]; any consistent set, the
        paper's is kgf-cm-s), broadcast against each other.
    rtol : float [-]
        Relative separation below which roots count as repeated.

    Returns
    -------
    str or ndarray of str [-]
        ``"real"``, ``"complex"``, ``"repeated"`` or ``"invalid"``.

    References
    ----------
    [hamabe] Part III, eq. (37).

    Examples
    --------
    Example 3, case a: with a1 = 24 the paper finds three real roots, with a1 = 15 one real root
    and a complex pair; ``(s + 1)^3`` is a triple root.

    >>> classify(1.76, 24, 211.2, 840), classify(1.76, 15, 211.2, 840), classify(1, 1, 1, 1)
    ('real', 'complex', 'repeated')
    """
    r = cubic_roots(a0, a1, a2, a3)
    kind = classify_roots(r, rtol)
    return str(kind) if kind.ndim == 0 else kind
