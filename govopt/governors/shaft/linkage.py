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
    """Half length of the spring, ``l = sqrt(a^2 + b^2 - 2 a b cos(alpha))`` (Hamabe, eq. 2)."""
    return np.sqrt(a**2 + b**2 - 2.0 * a * b * np.cos(alpha))


def spring_arm(alpha, a, b):
    """Arm of the spring force about the fulcrum, ``h = a b sin(alpha) / l`` (Hamabe, eq. 2).

    It is also ``dl/dalpha``.
    """
    return a * b * np.sin(alpha) / half_length(alpha, a, b)


def centrifugal_moment(alpha, omega, m, a, rho):
    """Moment of the centrifugal force about the fulcrum, ``M_z = omega^2 m a rho sin(alpha)``.

    Hamabe, eq. (1): the centrifugal force ``m omega^2 OP`` has the arm ``a rho sin(alpha) / OP``.
    """
    return omega**2 * m * a * rho * np.sin(alpha)


def spring_moment_coefficients(alpha, a, b, geometry: str = "exact"):
    """Return ``(A, B, dA/dalpha, dB/dalpha)`` with ``M_f = kappa (A - B l0)``.

    ``geometry="exact"``: Hamabe eq. (2), ``M_f = 2 kappa (l - l0) a b sin(alpha) / l``.
    ``geometry="series"``: Hamabe eq. (3), ``1/l`` expanded to first order in
    ``2 a b cos(alpha) / c^2``; 2.5 % off in M_f and ~10 % in its slope for b/a = 1/6, kept to
    reproduce the paper.
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
    """Moment of the spring about the fulcrum, ``M_f`` (Hamabe, eq. 2 exact / eq. 3 series).

    ``kappa`` is the force per unit extension of the *whole* spring and ``l0`` its free *half*
    length, so the spring force is ``F = 2 kappa (l - l0)``.
    """
    A, B, _, _ = spring_moment_coefficients(alpha, a, b, geometry)
    return kappa * (A - B * l0)


def spring_moment_slope(alpha, kappa, l0, a, b, geometry: str = "exact"):
    """``dM_f/dalpha`` (Hamabe, eq. 19 uses the series form; the exact form is the default)."""
    _, _, dA, dB = spring_moment_coefficients(alpha, a, b, geometry)
    return kappa * (dA - dB * l0)


def spring_force(alpha, kappa, l0, a, b):
    """Tension in the spring, ``F = 2 kappa (l - l0)`` (Hamabe, eq. 2); always exact geometry."""
    return 2.0 * kappa * (half_length(alpha, a, b) - l0)


def free_half_length(alpha, moment, kappa, a, b, geometry: str = "exact"):
    """Free half length ``l0`` giving spring moment ``moment`` at ``alpha`` (inverse of eq. 2/3).

    Hamabe, Example 1: ``F_n = M_f(alpha_n) / h_n``, ``l0 = l_n - F_n / (2 kappa)``; with the
    exact geometry this is the same formula, with the series the affine form is inverted.
    """
    A, B, _, _ = spring_moment_coefficients(alpha, a, b, geometry)
    return (A - moment / kappa) / B
