"""Reactions of the valve gear on the governor (Hamabe, Part I eqs. 4-11, Part II eq. 14).

The eccentric, driven by the lever ``q = SQ`` of each pendulum, carries the valve rod. The forces
on it, resolved along the guide line (eccentricity ``e``, angular advance ``delta``), are
(Hamabe, eqs. 5-9): the valve friction ``P1`` (switching sign with the valve's motion), the
inertia of the reciprocating parts ``m_v``, the steam load ``P3`` and the weight ``P4`` of the
valve gear, and the centrifugal force of the eccentric's own mass ``m_e`` (offset ``s``). Their
moment on each pendulum is ``M_r = (q/2) * sum P'``; its mean over a revolution is ``M_r0``.
All SI; functions broadcast over numpy arrays.
"""

from __future__ import annotations

import numpy as np


def advance_angle(alpha, table_alpha, table_delta):
    """Angular advance ``delta`` of the eccentric at configuration ``alpha``.

    Linear interpolation in the valve-gear table (Hamabe, Fig. 6: "interpolate between rows");
    constant extrapolation outside the table.
    """
    return np.interp(alpha, table_alpha, table_delta)


def mean_reaction_split(delta, q, e, s, P1, m_v, m_e):
    """Split ``M_r0 = C_f + omega^2 C_i`` into its speed-independent and inertia parts.

    Hamabe, eq. (11)::

        M_r0 = (q/2) [ (2 P1/pi) sin(delta) + (m_v omega^2 e / 2) cot(delta)
                       + m_e omega^2 (e cot(delta) - s cos(delta)) ]

    so ``C_f = (q/2)(2 P1/pi) sin(delta)`` and
    ``C_i = (q/2)[ (m_v e / 2) cot(delta) + m_e (e cot(delta) - s cos(delta)) ]``.
    Units check: P1 q is a moment; m omega^2 e q is kg (1/s^2) m m = N m. The split lets the
    characteristic be solved exactly when the inertia reactions follow the local speed.
    """
    cot = np.cos(delta) / np.sin(delta)
    C_f = 0.5 * q * (2.0 * P1 / np.pi) * np.sin(delta)
    C_i = 0.5 * q * (0.5 * m_v * e * cot + m_e * (e * cot - s * np.cos(delta)))
    return C_f, C_i


def mean_reaction_moment(delta, omega, q, e, s, P1, m_v, m_e):
    """Mean moment of the valve gear's reaction on each pendulum, ``M_r0`` (Hamabe, eq. 11).

    Example 1 (kgf, cm; omega^2 = 630): delta = 48 deg 30' gives 59.56 kgf cm; the paper prints
    59.4 because it rounds the terms (19.1 + 22.1 + 22.1 - 3.9) before adding them.

    >>> import numpy as np
    >>> kgf, cm = 9.80665, 0.01
    >>> M = mean_reaction_moment(np.radians(48.5), np.sqrt(630.0), 5 * cm, 2.6 * cm, 0.6 * cm,
    ...                          16 * kgf, 12.0, 6.0)
    >>> round(float(M / (kgf * cm)), 1)
    59.6
    """
    C_f, C_i = mean_reaction_split(delta, q, e, s, P1, m_v, m_e)
    return C_f + omega**2 * C_i
