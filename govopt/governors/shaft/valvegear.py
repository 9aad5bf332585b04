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

import functools

import numpy as np

#: Interpolants of the valve-gear table (``[analysis] valve_table``); the first is the default.
VALVE_TABLES = ("pchip", "cubic", "linear")


@functools.lru_cache(maxsize=64)
def _smooth_table(table_alpha: tuple, table_delta: tuple, kind: str):
    """``(delta(alpha), d delta/d alpha)`` as scipy's piecewise cubics, built once per table:
    ``PchipInterpolator`` (Fritsch & Carlson 1980, Brodlie's weights) or ``CubicSpline`` with
    not-a-knot ends (de Boor, ch. IV: the table gives no end slopes or curvatures). scipy is
    imported here, where a smooth table is first used (a shaft governor's statics)."""
    from scipy.interpolate import CubicSpline, PchipInterpolator

    if kind not in ("pchip", "cubic"):
        raise ValueError(f"valve_table must be one of {VALVE_TABLES}, got {kind!r}")
    x, y = np.array(table_alpha), np.array(table_delta)
    if len(x) < 2 or np.any(np.diff(x) <= 0):
        raise ValueError("the valve table needs two or more strictly increasing rows")
    f = PchipInterpolator(x, y) if kind == "pchip" else CubicSpline(x, y)
    return f, f.derivative()


def _table(alpha, table_alpha, table_delta, kind):
    """The interpolant of ``kind`` and ``alpha`` clipped into the table (for the extrapolation)."""
    f, df = _smooth_table(tuple(map(float, table_alpha)), tuple(map(float, table_delta)), kind)
    alpha = np.asarray(alpha, dtype=float)
    return f, df, alpha, np.clip(alpha, table_alpha[0], table_alpha[-1])


def advance_angle(alpha, table_alpha, table_delta, kind="pchip"):
    """Angular advance ``delta`` [rad] of the eccentric at configuration ``alpha`` [rad]
    (Hamabe, Example 1 and Fig. 6).

    Hamabe, Example 1 / Fig. 6 gives ``delta`` at five configurations only (his statics use
    just those rows). Between rows, ``kind`` (``[analysis] valve_table``):

    - ``"pchip"`` (default): monotone piecewise-cubic Hermite (Fritsch-Carlson; scipy's
      ``PchipInterpolator``). C^1, so
      ``d delta/d alpha`` and with it ``k^2`` are continuous; monotone for any monotone table
      (no overshoot between rows); local (a row changes only its two intervals); its slope at a
      row lies between the two neighbouring secants, so ``k^2`` at a row lies between the
      linear table's two one-sided values.
    - ``"cubic"``: not-a-knot cubic spline (C^2; its slope at a row depends on every row;
      scipy's ``CubicSpline``).
    - ``"linear"``: the paper's "interpolate between rows"; ``d delta/d alpha`` jumps at each
      row. Constant outside the table (as before).

    The smooth kinds continue along their end tangents outside the table (C^1 there too); the
    spec checks that the table covers the configuration range, so this only serves dynamics that
    overshoot it. The choice of interpolant is govopt's; the paper only says to interpolate.

    Parameters
    ----------
    alpha : float or array [rad]
        Configuration, the angle OSP.
    table_alpha : array [rad]
        The valve-gear table's configurations, increasing.
    table_delta : array [rad]
        The eccentric's advance at those rows.
    kind : str [-]
        Interpolant between rows: "pchip", "cubic" or "linear".

    Returns
    -------
    float or array [rad]
        The eccentric's angular advance.

    References
    ----------
    [hamabe] Part I, Example 1 (the valve-gear table read from Fig. 6).

    Examples
    --------
    Hamabe's table: 64 deg 40' is a row, where every kind gives its 69 deg:

    >>> import numpy as np
    >>> A = np.radians([50, 57 + 20 / 60, 64 + 40 / 60, 73.5, 80])
    >>> D = np.radians([48.5, 58, 69, 84, 96])
    >>> [round(float(np.degrees(advance_angle(A[2], A, D, k))), 6) for k in VALVE_TABLES]
    [69.0, 69.0, 69.0]

    Below, PCHIP's slopes are 1.0 at 50 deg (its three-point end formula) and 1.409 at 60 deg
    (the weighted harmonic mean of the secants 1.2 and 1.8), so its value halfway, 54 deg
    + 10 deg (1.0 - 1.409)/8, lies 0.51 deg below the chord:

    >>> a, d = np.radians([50.0, 60.0, 80.0]), np.radians([48.0, 60.0, 96.0])
    >>> [round(float(np.degrees(advance_angle(np.radians(55.0), a, d, k))), 2)
    ...  for k in ("linear", "pchip")]
    [54.0, 53.49]
    """
    if kind == "linear":
        return np.interp(alpha, table_alpha, table_delta)
    f, df, alpha, inside = _table(alpha, table_alpha, table_delta, kind)
    return f(inside) + df(inside) * (alpha - inside)


def advance_angle_slope(alpha, table_alpha, table_delta, kind="pchip"):
    """``d delta/d alpha`` [-] of :func:`advance_angle` for a smooth ``kind``, analytically (the
    derivative of the piecewise cubic); the end slope outside the table.

    The ``"linear"`` table has no derivative at its rows; :func:`govopt.analysis.statics.
    reaction_slope` takes differences for it.

    Parameters
    ----------
    alpha : float or array [rad]
        Configuration, the angle OSP.
    table_alpha : array [rad]
        The valve-gear table's configurations, increasing.
    table_delta : array [rad]
        The eccentric's advance at those rows.
    kind : str [-]
        "pchip" or "cubic" ("linear" is refused).

    Returns
    -------
    float or array [-]
        The slope of the table's interpolant, rad per rad.

    References
    ----------
    [hamabe] Part I, Example 1 (the table of Fig. 6); the slope enters ``k^2`` through the
    reaction's slope, Part II, eq. (19).

    Examples
    --------
    A hand check: a table on a straight line (slope 1.2) is reproduced by either smooth kind,
    so the slope is 1.2 everywhere, between rows and beyond them:

    >>> import numpy as np
    >>> a, d = np.radians([50.0, 60.0, 80.0]), np.radians([48.0, 60.0, 84.0])
    >>> [round(float(advance_angle_slope(np.radians(x), a, d, k)), 12)
    ...  for k in ("pchip", "cubic") for x in (55.0, 85.0)]
    [1.2, 1.2, 1.2, 1.2]
    """
    if kind == "linear":
        raise ValueError("the linear valve table has no derivative at its rows")
    _, df, _, inside = _table(alpha, table_alpha, table_delta, kind)
    return df(inside)


def mean_reaction_split(delta, q, e, s, P1, m_v, m_e):
    """Split ``M_r0 = C_f + omega^2 C_i`` into its speed-independent part ``C_f`` [N m] and its
    inertia part ``C_i`` [kg m^2] (Hamabe, Part I, eq. 11).

    Hamabe, eq. (11)::

        M_r0 = (q/2) [ (2 P1/pi) sin(delta) + (m_v omega^2 e / 2) cot(delta)
                       + m_e omega^2 (e cot(delta) - s cos(delta)) ]

    so ``C_f = (q/2)(2 P1/pi) sin(delta)`` and
    ``C_i = (q/2)[ (m_v e / 2) cot(delta) + m_e (e cot(delta) - s cos(delta)) ]``.
    Units check: P1 q is a moment; m omega^2 e q is kg (1/s^2) m m = N m. The split (govopt's
    arrangement of eq. 11) lets the characteristic be solved exactly when the inertia reactions
    follow the local speed.

    Parameters
    ----------
    delta : float or array [rad]
        Angular advance of the eccentric.
    q : float [m]
        Lever SQ of each pendulum, driving the eccentric.
    e : float [m]
        Eccentricity (O to the guide line AB).
    s : float [m]
        Offset of the eccentric's mass (``y = e cot(delta) - s cos(delta)``).
    P1 : float [N]
        Friction force of the valve gear.
    m_v : float [kg]
        Reciprocating mass of the valve gear.
    m_e : float [kg]
        The eccentric's rotating mass.

    Returns
    -------
    tuple of float or array [N m, kg m^2]
        ``(C_f, C_i)``.

    References
    ----------
    [hamabe] Part I, eq. (11) and Example 1.

    Examples
    --------
    Example 1 at delta = 48 deg 30': the paper's terms are 19.1 (friction) and
    22.1 + 22.1 - 3.9 = 40.3 kgf cm (inertia, at omega^2 = 630), rounded before adding; unrounded
    the inertia part is 40.5:

    >>> KGF, CM = 9.80665, 0.01
    >>> C_f, C_i = mean_reaction_split(np.radians(48.5), 5 * CM, 2.6 * CM, 0.6 * CM, 16 * KGF,
    ...                                12.0, 6.0)
    >>> round(float(C_f) / (KGF * CM), 1), round(float(630 * C_i) / (KGF * CM), 1)
    (19.1, 40.5)
    """
    cot = np.cos(delta) / np.sin(delta)
    C_f = 0.5 * q * (2.0 * P1 / np.pi) * np.sin(delta)
    C_i = 0.5 * q * (0.5 * m_v * e * cot + m_e * (e * cot - s * np.cos(delta)))
    return C_f, C_i


def mean_reaction_split_slope(delta, q, e, s, P1, m_v, m_e):
    """``(dC_f/d delta, dC_i/d delta)`` [N m/rad, kg m^2/rad]: :func:`mean_reaction_split`
    differentiated analytically (Hamabe, Part I, eq. 11)::

        dC_f/d delta = (q/2)(2 P1/pi) cos(delta)
        dC_i/d delta = (q/2)[ -(m_v e / 2) / sin^2(delta) + m_e (s sin(delta) - e / sin^2(delta)) ]

    (``d cot/d delta = -1/sin^2``.)

    Parameters
    ----------
    delta : float or array [rad]
        Angular advance of the eccentric.
    q, e, s, P1, m_v, m_e : float [m, m, m, N, kg, kg]
        The valve gear, as in :func:`mean_reaction_split`.

    Returns
    -------
    tuple of float or array [N m/rad, kg m^2/rad]
        The slopes of ``C_f`` and ``C_i`` in ``delta``.

    References
    ----------
    [hamabe] Part I, eq. (11), differentiated (govopt's; the paper's k^2 leaves the reaction's
    slope out).

    Examples
    --------
    Against central differences at delta = 1.1 rad, with Example 1's valve gear in SI:

    >>> import numpy as np
    >>> args, d, h = (0.05, 0.026, 0.006, 157.0, 12.0, 6.0), 1.1, 1e-6
    >>> exact = mean_reaction_split_slope(d, *args)
    >>> diff = [(p - m) / (2 * h) for p, m in zip(mean_reaction_split(d + h, *args),
    ...                                           mean_reaction_split(d - h, *args))]
    >>> bool(np.allclose(exact, diff, rtol=1e-8))
    True
    """
    sd = np.sin(delta)
    dC_f = 0.5 * q * (2.0 * P1 / np.pi) * np.cos(delta)
    dC_i = 0.5 * q * (-0.5 * m_v * e / sd**2 + m_e * (s * sd - e / sd**2))
    return dC_f, dC_i


def table_reaction(alpha, vg, q, kind="pchip"):
    """``(C_f, C_i)`` [N m, kg m^2] of eq. (11) at configurations ``alpha``, ``delta`` from the
    valve-gear table of ``vg`` interpolated as ``kind`` says (Hamabe, Part I, eq. 11 and Fig. 6).

    Parameters
    ----------
    alpha : float or array [rad]
        Configuration, the angle OSP.
    vg : ValveGear [-]
        The spec's valve gear (:class:`~govopt.spec.ValveGear`: forces [N], masses [kg],
        lengths [m], table [rad]).
    q : float [m]
        Lever SQ of each pendulum.
    kind : str [-]
        Interpolant between rows: "pchip", "cubic" or "linear".

    Returns
    -------
    tuple of float or array [N m, kg m^2]
        ``(C_f, C_i)`` with ``M_r0 = C_f + omega^2 C_i``.

    References
    ----------
    [hamabe] Part I, eq. (11) and Example 1's table of ``M_r0``.

    Examples
    --------
    Example 1 (a) at 50 deg (a row, delta = 48 deg 30'), omega^2 = 630: the paper prints
    ``M_r0 = 59.4`` kgf cm, rounding its terms before adding (unrounded 59.57):

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> C_f, C_i = table_reaction(np.radians(50), spec.governor.valve_gear, spec.governor.q)
    >>> round(float(C_f + 630 * C_i) / (9.80665 * 0.01), 2)
    59.57
    """
    delta = advance_angle(alpha, vg.table_alpha, vg.table_delta, kind)
    return mean_reaction_split(delta, q, vg.eccentricity, vg.offset, vg.friction,
                               vg.reciprocating_mass, vg.eccentric_mass)


def table_reaction_slope(alpha, vg, q, kind="pchip", step=1e-6):
    """``(dC_f/dalpha, dC_i/dalpha)`` [N m/rad, kg m^2/rad] of :func:`table_reaction` (Hamabe,
    Part I, eq. 11 through the table of Fig. 6).

    Smooth tables (``pchip``, ``cubic``): exact, by the chain rule
    ``dC/dalpha = dC/ddelta * ddelta/dalpha`` with both factors analytic
    (:func:`mean_reaction_split_slope`, :func:`advance_angle_slope`).
    ``linear``: a difference of the interpolated eq. (11) over ``+-step`` (rad): exact between
    rows (to ``O(step^2)``), the mean of the two slopes on an inner row, one-sided at the table's
    ends, zero outside it.

    Parameters
    ----------
    alpha : float or array [rad]
        Configuration, the angle OSP.
    vg : ValveGear [-]
        The spec's valve gear (:class:`~govopt.spec.ValveGear`: forces [N], masses [kg],
        lengths [m], table [rad]).
    q : float [m]
        Lever SQ of each pendulum.
    kind : str [-]
        Interpolant between rows: "pchip", "cubic" or "linear".
    step : float [rad]
        Half the difference interval of the linear table.

    Returns
    -------
    tuple of float or array [N m/rad, kg m^2/rad]
        The slopes of ``C_f`` and ``C_i`` in ``alpha``.

    References
    ----------
    [hamabe] Part I, eq. (11) and Example 1's table (govopt's slope; the paper's k^2 omits it).

    Examples
    --------
    Example 1 (a) at 54 deg, omega^2 = 630, per degree: the paper's table falls from 59.4 to
    49.7 kgf cm over 50 deg to 57 deg 20', a secant of -1.32 kgf cm/deg from its rounded terms;
    with the linear table the slope there is -1.30, with PCHIP -1.32:

    >>> import govopt, govopt.examples
    >>> g = govopt.load_spec(govopt.examples.example("hamabe-a")).governor
    >>> [round(float(s_f + 630 * s_i) / (9.80665 * 0.01) * np.pi / 180, 2) for s_f, s_i in
    ...  (table_reaction_slope(np.radians(54), g.valve_gear, g.q, k) for k in ("linear", "pchip"))]
    [-1.3, -1.32]
    """
    if kind != "linear":
        delta = advance_angle(alpha, vg.table_alpha, vg.table_delta, kind)
        d_delta = advance_angle_slope(alpha, vg.table_alpha, vg.table_delta, kind)
        dC_f, dC_i = mean_reaction_split_slope(delta, q, vg.eccentricity, vg.offset, vg.friction,
                                               vg.reciprocating_mass, vg.eccentric_mass)
        return dC_f * d_delta, dC_i * d_delta
    hi = np.minimum(alpha + step, vg.table_alpha[-1])
    lo = np.maximum(alpha - step, vg.table_alpha[0])
    lo = np.where(hi - lo > 0, lo, hi - step)  # outside the table: a flat (zero) slope region
    cf_p, ci_p = table_reaction(hi, vg, q, kind)
    cf_m, ci_m = table_reaction(lo, vg, q, kind)
    return (cf_p - cf_m) / (hi - lo), (ci_p - ci_m) / (hi - lo)


def mean_reaction_moment(delta, omega, q, e, s, P1, m_v, m_e):
    """Mean moment [N m] of the valve gear's reaction on each pendulum, ``M_r0`` (Hamabe, Part I,
    eq. 11).

    Parameters
    ----------
    delta : float or array [rad]
        Angular advance of the eccentric.
    omega : float or array [rad/s]
        Shaft speed.
    q, e, s, P1, m_v, m_e : float [m, m, m, N, kg, kg]
        The valve gear, as in :func:`mean_reaction_split`.

    Returns
    -------
    float or array [N m]
        ``M_r0 = C_f + omega^2 C_i`` (:func:`mean_reaction_split`).

    References
    ----------
    [hamabe] Part I, eq. (11) and Example 1.

    Examples
    --------
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


# --------------------------------------------------------------------------------------------
# Part II: the fluctuating reaction, eq. (14)
# --------------------------------------------------------------------------------------------

#: Engine layouts of the valve gear (Hamabe, eqs. 7 and 8).
ENGINES = ("vertical", "horizontal")


def _load_force(theta, P3, P4, engine):
    """Steam load and weight along the guide line AB (Hamabe, eqs. 7, 8).

    Vertical engine, eq. (7): both act along the cylinder axis, ``(P3 + P4) sin(theta)``.
    Horizontal engine, eq. (8): the steam load still acts along the axis, but the weight ``P4``
    (there: the eccentric and the part of the rod's weight carried by the eccentric centre) is
    perpendicular to it, so its component along AB is ``-P4 cos(theta)``:
    ``P3' + P4' = P3 sin(theta) - P4 cos(theta)``. A force along the axis resolves onto AB with
    ``sin(theta)`` (eq. 4); one at right angles to the axis with ``cos(theta)``. The sign of the
    cosine term follows the paper's Fig. 2 (crank angle from the inner dead centre, cylinder on
    the left); for the opposite sense of rotation it flips, which leaves every amplitude, and so
    every result of Part II, unchanged.
    """
    if engine == "vertical":
        return (P3 + P4) * np.sin(theta)
    if engine == "horizontal":
        return P3 * np.sin(theta) - P4 * np.cos(theta)
    raise ValueError(f"engine must be one of {ENGINES}, got {engine!r}")


def smooth_force(theta, delta, omega, e, s, P3, P4, m_v, m_e, engine="vertical",
                 omega_dot=0.0):
    """Sum [N] of the continuous forces along AB: inertia (eq. 6), load (eqs. 7/8) and eccentric
    (eq. 9), the part of :func:`reaction_moment` without the friction that switches (eq. 5).

    Reciprocating parts: displacement ``x = (e / sin delta) sin(delta + theta)``, inertia force
    ``-m_v x''`` = ``m_v (e / sin delta) [omega^2 sin(delta + theta) - omega_dot cos(delta +
    theta)]``; at constant speed (``omega_dot = 0``) this is the paper's ``m_v omega^2 x``.
    The forced vibration (:mod:`govopt.governors.shaft.vibration`) adds its own friction term.

    Parameters
    ----------
    theta : float or array [rad]
        Crank angle from the inner dead centre.
    delta : float or array [rad]
        Angular advance of the eccentric.
    omega : float or array [rad/s]
        Shaft speed.
    e : float [m]
        Eccentricity (O to the guide line AB).
    s : float [m]
        Offset of the eccentric's mass.
    P3 : float [N]
        Steam load on the valve.
    P4 : float [N]
        Weight of the valve gear.
    m_v : float [kg]
        Reciprocating mass of the valve gear.
    m_e : float [kg]
        The eccentric's rotating mass.
    engine : str [-]
        "vertical" (eq. 7) or "horizontal" (eq. 8).
    omega_dot : float [rad/s^2]
        The shaft's angular acceleration (0 in the paper).

    Returns
    -------
    float or array [N]
        The forces along AB, times ``sin(theta)`` where the paper's moment arm has it.

    References
    ----------
    [hamabe] Part I, eqs. (6)-(9).

    Examples
    --------
    Hamabe's Example 1 in SI (as in :func:`reaction_moment`): with the friction ``P1 = 0`` the
    reaction moment is ``q/2`` times this force.

    >>> KGF, CM = 9.80665, 0.01
    >>> VG = dict(e=2.6 * CM, s=0.6 * CM, P3=12 * KGF, P4=16 * KGF, m_v=12.0, m_e=6.0)
    >>> theta, delta, omega = 1.0, np.radians(48.5), np.sqrt(630)
    >>> F = smooth_force(theta, delta, omega, **VG)
    >>> M = reaction_moment(theta, delta, omega, q=5 * CM, P1=0.0, **VG)
    >>> bool(np.isclose(M, 0.5 * 5 * CM * F))
    True
    """
    sd = np.sin(delta)
    inertia = (m_v * e / sd * (omega**2 * np.sin(delta + theta) - omega_dot * np.cos(delta + theta))
               * np.sin(theta))
    eccentric = m_e * omega**2 * (e * np.cos(delta) / sd - s * np.cos(delta))
    return inertia + _load_force(theta, P3, P4, engine) + eccentric


def reaction_moment(theta, delta, omega, q, e, s, P1, P3, P4, m_v, m_e, engine="vertical",
                    omega_dot=0.0):
    """Instantaneous moment [N m] of the valve gear on each pendulum, ``M_r(theta)`` (Hamabe,
    Part II, eq. 14, from the force models of Part I, eqs. 5-9).

    ``M_r = (q/2) (P1' + P2' + P3' + P4' + P5')`` with the force models of Part I (crank angle
    ``theta`` from the inner dead centre):

    - friction, eq. (5): ``P1' = -P1 sign(cos(theta + delta)) sin(theta)`` (it switches where
      the valve reverses, ``theta = pi/2 - delta`` and ``3 pi/2 - delta``);
    - inertia, eq. (6): ``P2' = (m_v omega^2 e / sin delta) sin(delta + theta) sin(theta)``
      (plus ``-(m_v omega_dot e / sin delta) cos(delta + theta) sin(theta)`` when the shaft
      accelerates; the paper's constant speed is ``omega_dot = 0``);
    - steam load and weight, eq. (7): ``(P3 + P4) sin(theta)`` for a vertical engine; eq. (8):
      ``P3 sin(theta) - P4 cos(theta)`` for a horizontal one (see :func:`_load_force`);
    - eccentric, eq. (9): ``P5' = m_e omega^2 (e cot(delta) - s cos(delta))``.

    Its mean over a revolution is :func:`mean_reaction_moment` (eq. 11) for either engine.
    Broadcasts over arrays.

    Parameters
    ----------
    theta : float or array [rad]
        Crank angle from the inner dead centre.
    delta : float or array [rad]
        Angular advance of the eccentric.
    omega : float or array [rad/s]
        Shaft speed.
    q : float [m]
        Lever SQ of each pendulum, driving the eccentric.
    e : float [m]
        Eccentricity (O to the guide line AB).
    s : float [m]
        Offset of the eccentric's mass (``y = e cot(delta) - s cos(delta)``).
    P1 : float [N]
        Friction force of the valve gear.
    P3 : float [N]
        Steam load on the valve.
    P4 : float [N]
        Weight of the valve gear.
    m_v : float [kg]
        Reciprocating mass of the valve gear.
    m_e : float [kg]
        The eccentric's rotating mass.
    engine : str [-]
        "vertical" (eq. 7) or "horizontal" (eq. 8).
    omega_dot : float [rad/s^2]
        The shaft's angular acceleration (0 in the paper).

    Returns
    -------
    float or array [N m]
        The moment of the valve gear on each pendulum.

    References
    ----------
    [hamabe] Part I, eqs. (4)-(9); Part II, eq. (14).

    Examples
    --------
    Hamabe's Example 1 (kgf, cm converted to SI; masses 12 and 6 kgf are 12 and 6 kg;
    omega^2 = 630):

    >>> KGF, CM = 9.80665, 0.01
    >>> VG = dict(q=5 * CM, e=2.6 * CM, s=0.6 * CM, P1=16 * KGF, P3=12 * KGF, P4=16 * KGF,
    ...           m_v=12.0, m_e=6.0)

    The mean over a revolution is eq. (11)'s 59.57 kgf cm at delta = 48 deg 30' (the paper:
    59.4, its terms rounded):

    >>> theta = np.linspace(0, 2 * np.pi, 200000, endpoint=False)
    >>> M = reaction_moment(theta, np.radians(48.5), np.sqrt(630), **VG)
    >>> round(float(np.mean(M)) / (KGF * CM), 2)
    59.57
    """
    friction = -P1 * np.sign(np.cos(theta + delta)) * np.sin(theta)
    return 0.5 * q * (friction + smooth_force(theta, delta, omega, e, s, P3, P4, m_v, m_e,
                                               engine, omega_dot))
