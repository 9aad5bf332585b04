"""Shaft-governor linkage (Hamabe, Part I, Fig. 1): pure, vectorised functions of SI arrays.

Each pendulum swings about its fulcrum S on the flywheel; ``a = SO`` (fulcrum to shaft axis),
``rho = SP`` (fulcrum to the pendulum's centre of gravity), ``b = SG`` (fulcrum to the spring
attachment, on SP), ``alpha`` the angle OSP. The spring joins the attachments G of the two
pendulums through O; ``l`` is its half length.

The spring moment is affine in the free half length ``l0``::

    M_f = kappa * (A(alpha) - B(alpha) * l0)

with ``A = 2 a b sin(alpha)`` and ``B = 2 a b sin(alpha) / l`` for the exact geometry (eq. 2), or
``B = 2 a b sin(alpha) / c + a^2 b^2 sin(2 alpha) / c^3`` for the paper's first-order series
(eq. 3, ``c = sqrt(a^2 + b^2)``). Working with (A, B) gives the moment, its slope and the free
length from one equilibrium without repeating the geometry.
"""

from __future__ import annotations

import numpy as np

GEOMETRIES = ("exact", "series")


def half_length(alpha, a, b):
    """Half length of the spring O-G, ``l = sqrt(a^2 + b^2 - 2 a b cos(alpha))`` [m] (Hamabe,
    Part I, eq. 2).

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    a : float [m]
        Fulcrum S to shaft axis O.
    b : float [m]
        Fulcrum S to the spring attachment G (on SP).

    Returns
    -------
    float or array [m]
        The spring's half length, fulcrum geometry only (the triangle OSG).

    References
    ----------
    [hamabe] Part I, Fig. 1 and eq. (2).

    Examples
    --------
    Hamabe's Example 1 (a = 18, b = 3 cm; kgf and cm converted to SI):

    >>> KGF, CM = 9.80665, 0.01

    The paper's working takes ``l_a - l_i = 1.5`` cm between 50 deg and 80 deg (its
    ``kappa = (606 - 427) / (2 x 1.5)``); the exact triangle gives 1.49 cm:

    >>> [round(float(half_length(np.radians(x), 0.18, 0.03)) / CM, 3) for x in (50, 80)]
    [16.235, 17.727]
    """
    return np.sqrt(a**2 + b**2 - 2.0 * a * b * np.cos(alpha))


def spring_arm(alpha, a, b):
    """Arm of the spring force about the fulcrum, ``h = a b sin(alpha) / l`` [m] (Hamabe, Part I,
    eq. 2).

    It is also ``dl/dalpha``.

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    a : float [m]
        Fulcrum S to shaft axis O.
    b : float [m]
        Fulcrum S to the spring attachment G (on SP).

    Returns
    -------
    float or array [m]
        Perpendicular distance from S to the spring's line OG.

    References
    ----------
    [hamabe] Part I, eq. (2); Example 1 rounds the arms to 2.5 and 3.0 cm.

    Examples
    --------
    Hamabe's Example 1 (a = 18, b = 3 cm; kgf and cm converted to SI):

    >>> KGF, CM = 9.80665, 0.01

    At the innermost (50 deg) and outermost (80 deg) configurations the paper writes 2.5 and
    3.0 cm; the exact arms are 2.548 and 3.000 cm (the paper rounded the first):

    >>> [round(float(spring_arm(np.radians(x), 0.18, 0.03)) / CM, 3) for x in (50, 80)]
    [2.548, 3.0]
    """
    return a * b * np.sin(alpha) / half_length(alpha, a, b)


def centrifugal_moment(alpha, omega, m, a, rho):
    """Moment of the centrifugal force about the fulcrum, ``M_z = omega^2 m a rho sin(alpha)``
    [N m] (Hamabe, Part I, eq. 1).

    The centrifugal force ``m omega^2 OP`` has the arm ``a rho sin(alpha) / OP``; the pendulum is
    a point mass at P.

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    omega : float or array [rad/s]
        Angular speed of the shaft.
    m : float [kg]
        Mass of one pendulum.
    a : float [m]
        Fulcrum S to shaft axis O.
    rho : float [m]
        Fulcrum S to the pendulum's centre of gravity P.

    Returns
    -------
    float or array [N m]
        The moment tending to open the pendulum.

    References
    ----------
    [hamabe] Part I, eq. (1).

    Examples
    --------
    Hamabe's Example 1 (a), W = 12 kgf (m = 12 kg), a = 18, rho = 12 cm: the paper prints
    ``M_zi = 1127`` kgf cm at 50 deg with omega^2 = 557 and ``M_zn = 1506`` at 64 deg 40' with
    omega^2 = 630. Its mass ``0.01223`` kgf s^2/cm is 12/981 rounded (12 kg is 12/980.665,
    0.05 % more: 1128), and its own product for the second is 1504, not 1506:

    >>> KGF, CM = 9.80665, 0.01
    >>> alpha_i, alpha_n = np.radians(50), np.radians(64 + 40 / 60)
    >>> round(centrifugal_moment(alpha_i, np.sqrt(557), 12.0, 0.18, 0.12) / (KGF * CM))
    1128
    >>> round(centrifugal_moment(alpha_n, np.sqrt(630), 12.0, 0.18, 0.12) / (KGF * CM))
    1505
    """
    return omega**2 * m * a * rho * np.sin(alpha)


def spring_moment_coefficients(alpha, a, b, geometry: str = "exact"):
    """Return ``(A, B, dA/dalpha, dB/dalpha)`` with ``M_f = kappa (A - B l0)``: ``A`` [m^2],
    ``B`` [m] and their slopes per radian (Hamabe, Part I, eq. 2 exact / eq. 3 series).

    ``geometry="exact"``: Hamabe eq. (2), ``M_f = 2 kappa (l - l0) a b sin(alpha) / l``.
    ``geometry="series"``: Hamabe eq. (3), ``1/l`` expanded to first order in
    ``2 a b cos(alpha) / c^2``; 2.5 % off in M_f and ~10 % in its slope for b/a = 1/6, kept to
    reproduce the paper. Splitting the moment into ``A`` and ``B`` is govopt's own arrangement
    (the moment is affine in ``l0``), so one equilibrium gives the free length directly.

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    a : float [m]
        Fulcrum S to shaft axis O.
    b : float [m]
        Fulcrum S to the spring attachment G (on SP).
    geometry : str [-]
        ``"exact"`` (eq. 2) or ``"series"`` (eq. 3).

    Returns
    -------
    tuple of float or array [m^2, m, m^2/rad, m/rad]
        ``A = 2 a b sin(alpha)``, ``B``, and their derivatives in ``alpha``.

    References
    ----------
    [hamabe] Part I, eqs. (2) and (3).

    Examples
    --------
    A hand check at alpha = 90 deg, where ``sin(2 alpha) = 0``: both geometries give
    ``A = 2 a b = 0.0108`` m^2 and ``B = 2 a b / sqrt(a^2 + b^2) = 0.05918`` m:

    >>> for geometry in ("exact", "series"):
    ...     A, B, dA, dB = spring_moment_coefficients(np.pi / 2, 0.18, 0.03, geometry)
    ...     print(round(A, 6), round(B, 5), round(abs(dA), 12))
    0.0108 0.05918 0.0
    0.0108 0.05918 0.0
    """
    s, co = np.sin(alpha), np.cos(alpha)
    A = 2.0 * a * b * s
    dA = 2.0 * a * b * co
    if geometry == "exact":
        ell = half_length(alpha, a, b)
        B = A / ell
        dB = 2.0 * a * b * (co / ell - a * b * s**2 / ell**3)
    elif geometry == "series":
        c = np.sqrt(a**2 + b**2)
        B = A / c + (a * b) ** 2 * np.sin(2.0 * alpha) / c**3
        dB = dA / c + 2.0 * (a * b) ** 2 * np.cos(2.0 * alpha) / c**3
    else:
        raise ValueError(f"geometry must be one of {GEOMETRIES}, got {geometry!r}")
    return A, B, dA, dB


def spring_moment(alpha, kappa, l0, a, b, geometry: str = "exact"):
    """Moment of the spring about the fulcrum, ``M_f`` [N m] (Hamabe, Part I, eq. 2 exact /
    eq. 3 series).

    ``kappa`` is the force per unit extension of the *whole* spring and ``l0`` its free *half*
    length, so the spring force is ``F = 2 kappa (l - l0)``.

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    kappa : float [N/m]
        Force per unit extension of the whole spring.
    l0 : float [m]
        Free half length of the spring.
    a : float [m]
        Fulcrum S to shaft axis O.
    b : float [m]
        Fulcrum S to the spring attachment G (on SP).
    geometry : str [-]
        ``"exact"`` (eq. 2) or ``"series"`` (eq. 3).

    Returns
    -------
    float or array [N m]
        The moment closing the pendulum.

    References
    ----------
    [hamabe] Part I, eqs. (2) and (3); Example 1's table of ``F x h = M_f``.

    Examples
    --------
    Hamabe's Example 1 (a): kappa = 64.2 kgf/cm, the free length set by ``M_fn = 1465`` kgf cm
    at 64 deg 40'. The paper's table gives ``M_fa = 1829`` kgf cm at 80 deg (its spring
    extensions read to 0.1 cm); the series of eq. (3) is 2.5 % high at the normal
    configuration:

    >>> KGF, CM = 9.80665, 0.01
    >>> kappa, alpha_n = 64.2 * KGF / CM, np.radians(64 + 40 / 60)
    >>> l0 = free_half_length(alpha_n, 1465 * KGF * CM, kappa, 0.18, 0.03)
    >>> round(spring_moment(np.radians(80), kappa, l0, 0.18, 0.03) / (KGF * CM))
    1830
    >>> exact = spring_moment(alpha_n, kappa, l0, 0.18, 0.03)
    >>> round(float(spring_moment(alpha_n, kappa, l0, 0.18, 0.03, "series") / exact), 3)
    1.025
    """
    A, B, _, _ = spring_moment_coefficients(alpha, a, b, geometry)
    return kappa * (A - B * l0)


def spring_moment_slope(alpha, kappa, l0, a, b, geometry: str = "exact"):
    """``dM_f/dalpha`` [N m/rad] (Hamabe, Part II, eq. 19 uses the series form of eq. 3; the
    exact form of eq. 2 is the default).

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    kappa : float [N/m]
        Force per unit extension of the whole spring.
    l0 : float [m]
        Free half length of the spring.
    a : float [m]
        Fulcrum S to shaft axis O.
    b : float [m]
        Fulcrum S to the spring attachment G (on SP).
    geometry : str [-]
        ``"exact"`` (eq. 2) or ``"series"`` (eq. 3).

    Returns
    -------
    float or array [N m/rad]
        The spring moment's slope, the spring's share of the restoring stiffness ``k^2 I``.

    References
    ----------
    [hamabe] Part I, eqs. (2), (3); Part II, eq. (19).

    Examples
    --------
    Hamabe's Example 1 (a) at the normal configuration (kappa = 64.2 kgf/cm, ``M_fn = 1465``
    kgf cm): the series slope is about 10 % below the exact one for b/a = 1/6, as the model
    notes say:

    >>> KGF, CM = 9.80665, 0.01
    >>> kappa, alpha_n = 64.2 * KGF / CM, np.radians(64 + 40 / 60)
    >>> l0 = free_half_length(alpha_n, 1465 * KGF * CM, kappa, 0.18, 0.03)
    >>> exact = spring_moment_slope(alpha_n, kappa, l0, 0.18, 0.03)
    >>> round(float(spring_moment_slope(alpha_n, kappa, l0, 0.18, 0.03, "series") / exact), 3)
    0.903
    """
    _, _, dA, dB = spring_moment_coefficients(alpha, a, b, geometry)
    return kappa * (dA - dB * l0)


def spring_force(alpha, kappa, l0, a, b):
    """Tension in the spring, ``F = 2 kappa (l - l0)`` [N] (Hamabe, Part I, eq. 2); always exact
    geometry.

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    kappa : float [N/m]
        Force per unit extension of the whole spring.
    l0 : float [m]
        Free half length of the spring.
    a : float [m]
        Fulcrum S to shaft axis O.
    b : float [m]
        Fulcrum S to the spring attachment G (on SP).

    Returns
    -------
    float or array [N]
        The spring's tension (negative if it is shorter than free).

    References
    ----------
    [hamabe] Part I, eq. (2); Example 1's table of ``2 kappa (l - l0)``.

    Examples
    --------
    Hamabe's Example 1 (a), kappa = 64.2 kgf/cm, free length from ``M_fn = 1465`` kgf cm: the
    paper's table prints 508 kgf at 64 deg 40' and 610.7 kgf at 80 deg (its extensions are read
    to 0.1 cm, hence the last digits):

    >>> KGF, CM = 9.80665, 0.01
    >>> kappa, alpha_n = 64.2 * KGF / CM, np.radians(64 + 40 / 60)
    >>> l0 = free_half_length(alpha_n, 1465 * KGF * CM, kappa, 0.18, 0.03)
    >>> [round(float(spring_force(np.radians(x), kappa, l0, 0.18, 0.03)) / KGF, 1)
    ...  for x in (64 + 40 / 60, 80)]
    [508.3, 610.0]
    """
    return 2.0 * kappa * (half_length(alpha, a, b) - l0)


def free_half_length(alpha, moment, kappa, a, b, geometry: str = "exact"):
    """Free half length ``l0`` [m] giving spring moment ``moment`` at ``alpha`` (inverse of
    Hamabe, Part I, eq. 2 / eq. 3).

    Hamabe, Example 1: ``F_n = M_f(alpha_n) / h_n``, ``l0 = l_n - F_n / (2 kappa)``; with the
    exact geometry this is the same formula, with the series the affine form is inverted.

    Parameters
    ----------
    alpha : float or array [rad]
        Angle OSP, the governor's configuration.
    moment : float or array [N m]
        The spring moment wanted there.
    kappa : float [N/m]
        Force per unit extension of the whole spring.
    a : float [m]
        Fulcrum S to shaft axis O.
    b : float [m]
        Fulcrum S to the spring attachment G (on SP).
    geometry : str [-]
        ``"exact"`` (eq. 2) or ``"series"`` (eq. 3).

    Returns
    -------
    float or array [m]
        The spring's free half length.

    References
    ----------
    [hamabe] Part I, eq. (2) and Example 1 (the normal configuration, cut-off 0.25).

    Examples
    --------
    Hamabe's Example 1 (a): ``M_fn = 1465`` kgf cm at 64 deg 40', kappa = 64.2 kgf/cm. The paper
    works it as ``F_n = 1465 / 2.88 = 508`` kgf, ``l_n - l0 = 508 / (2 x 64.2) = 3.96`` cm; here
    ``l_n = 16.935`` cm:

    >>> KGF, CM = 9.80665, 0.01
    >>> alpha_n = np.radians(64 + 40 / 60)
    >>> l0 = free_half_length(alpha_n, 1465 * KGF * CM, 64.2 * KGF / CM, 0.18, 0.03)
    >>> round(float(l0) / CM, 3), round(float(half_length(alpha_n, 0.18, 0.03) - l0) / CM, 2)
    (12.976, 3.96)
    """
    A, B, _, _ = spring_moment_coefficients(alpha, a, b, geometry)
    return (A - moment / kappa) / B
