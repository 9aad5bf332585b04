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
    """Angular advance ``delta`` of the eccentric at configuration ``alpha`` (rad, rad).

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
    overshoot it.

    Below, PCHIP's slopes are 1.0 at 50 deg (its three-point end formula) and 1.409 at 60 deg
    (the weighted harmonic mean of the secants 1.2 and 1.8), so its value halfway, 54 deg
    + 10 deg (1.0 - 1.409)/8, lies 0.51 deg below the chord:

    >>> import numpy as np
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
    """``d delta/d alpha`` of :func:`advance_angle` for a smooth ``kind``, analytically (the
    derivative of the piecewise cubic); the end slope outside the table. Dimensionless.

    The ``"linear"`` table has no derivative at its rows; :func:`govopt.analysis.statics.
    reaction_slope` takes differences for it.
    """
    if kind == "linear":
        raise ValueError("the linear valve table has no derivative at its rows")
    _, df, _, inside = _table(alpha, table_alpha, table_delta, kind)
    return df(inside)


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


def mean_reaction_split_slope(delta, q, e, s, P1, m_v, m_e):
    """``(dC_f/d delta, dC_i/d delta)``: :func:`mean_reaction_split` differentiated analytically
    (Hamabe, eq. 11)::

        dC_f/d delta = (q/2)(2 P1/pi) cos(delta)
        dC_i/d delta = (q/2)[ -(m_v e / 2) / sin^2(delta) + m_e (s sin(delta) - e / sin^2(delta)) ]

    (``d cot/d delta = -1/sin^2``.) N m/rad and kg m^2/rad; SI like :func:`mean_reaction_split`.

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
    """``(C_f, C_i)`` of eq. (11) at configurations ``alpha`` (rad), ``delta`` from the valve-gear
    table of ``vg`` (a :class:`~govopt.spec.ValveGear`) interpolated as ``kind`` says; ``q`` the
    lever SQ (m). N m and kg m^2 (Hamabe, eq. 11 and Fig. 6)."""
    delta = advance_angle(alpha, vg.table_alpha, vg.table_delta, kind)
    return mean_reaction_split(delta, q, vg.eccentricity, vg.offset, vg.friction,
                               vg.reciprocating_mass, vg.eccentric_mass)


def table_reaction_slope(alpha, vg, q, kind="pchip", step=1e-6):
    """``(dC_f/dalpha, dC_i/dalpha)`` of :func:`table_reaction`, N m/rad and kg m^2/rad.

    Smooth tables (``pchip``, ``cubic``): exact, by the chain rule
    ``dC/dalpha = dC/ddelta * ddelta/dalpha`` with both factors analytic
    (:func:`mean_reaction_split_slope`, :func:`advance_angle_slope`).
    ``linear``: a difference of the interpolated eq. (11) over ``+-step`` (rad): exact between
    rows (to ``O(step^2)``), the mean of the two slopes on an inner row, one-sided at the table's
    ends, zero outside it.
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


def _smooth_force(theta, delta, omega, e, s, P3, P4, m_v, m_e, engine, omega_dot=0.0):
    """Sum of the continuous forces along AB: inertia (eq. 6), load (eqs. 7/8), eccentric (eq. 9).

    Reciprocating parts: displacement ``x = (e / sin delta) sin(delta + theta)``, inertia force
    ``-m_v x''`` = ``m_v (e / sin delta) [omega^2 sin(delta + theta) - omega_dot cos(delta +
    theta)]``; at constant speed (``omega_dot = 0``) this is the paper's ``m_v omega^2 x``.
    """
    sd = np.sin(delta)
    inertia = (m_v * e / sd * (omega**2 * np.sin(delta + theta) - omega_dot * np.cos(delta + theta))
               * np.sin(theta))
    eccentric = m_e * omega**2 * (e * np.cos(delta) / sd - s * np.cos(delta))
    return inertia + _load_force(theta, P3, P4, engine) + eccentric


def reaction_moment(theta, delta, omega, q, e, s, P1, P3, P4, m_v, m_e, engine="vertical",
                    omega_dot=0.0):
    """Instantaneous moment of the valve gear on each pendulum, ``M_r(theta)`` (Hamabe, eq. 14).

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
    Broadcasts over arrays; SI.
    """
    friction = -P1 * np.sign(np.cos(theta + delta)) * np.sin(theta)
    return 0.5 * q * (friction + _smooth_force(theta, delta, omega, e, s, P3, P4, m_v, m_e,
                                               engine, omega_dot))


@functools.lru_cache(maxsize=64)
def _gauss_legendre(n: int):
    x, w = np.polynomial.legendre.leggauss(n)
    x.flags.writeable = False
    w.flags.writeable = False
    return x, w


def quadrature_nodes(n_max: int, spread: float = 0.0) -> int:
    """Gauss-Legendre nodes per half period that integrate ``g(t) cos(n t)``, ``n <= n_max``, to
    machine precision when ``g`` is smooth on the half period with bandwidth ``~ 4 + spread n``.

    On a half period ``cos(n t)`` is ``cos(n pi/2 x + c)`` in the Legendre variable ``x``; its
    Legendre coefficients die out past degree ``n pi / 2``, and ``m`` nodes are exact to degree
    ``2 m - 1``; past that they fall off over a further ``~ (n pi/2)^(1/3)`` degrees (the
    transition region of ``J_k(n pi/2)``), hence the margin.
    """
    k = (n_max + 6) * (1.0 + spread)
    return int(np.ceil(k * np.pi / 4.0 + 4.0 * k ** (1.0 / 3.0))) + 24


def piecewise_fourier(func, start, n_harmonics: int, nodes: int | None = None):
    """Fourier coefficients of a ``2 pi``-periodic function that is smooth on the two half periods
    ``[start, start + pi]`` and ``[start + pi, start + 2 pi]`` and may jump between them.

    ``func(t, piece)`` is evaluated at Gauss-Legendre nodes ``t`` of shape ``start.shape + (2m,)``
    with ``piece = +1`` on the first half period and ``-1`` on the second (so a switching term,
    like the valve friction, needs no ``sign`` of a rounded number). Because each half period is
    integrated separately, the jumps cost no accuracy: the coefficients are exact to ~1e-15
    relative, not ``O(1/N)`` as a sampled FFT of a discontinuous function would be.

    Returns ``(a, b)`` of shape ``start.shape + (n_harmonics + 1,)`` with
    ``g(t) = a_0 + sum_n [a_n cos(n t) + b_n sin(n t)]`` (``b_0 = 0``).
    """
    start = np.asarray(start, dtype=float)
    m = nodes or quadrature_nodes(n_harmonics)
    x, w = _gauss_legendre(m)
    u = np.concatenate([x, x + 2.0])
    weights = np.concatenate([w, w]) * (np.pi / 2.0)
    piece = np.concatenate([np.ones(m), -np.ones(m)])
    t = start[..., None] + (np.pi / 2.0) * (u + 1.0)
    gw = func(t, piece) * weights
    orders = np.arange(n_harmonics + 1, dtype=float)
    a = np.empty(start.shape + (n_harmonics + 1,))
    b = np.empty_like(a)
    block = max(1, int(2e7 // max(gw.size, 1)))
    for lo in range(0, n_harmonics + 1, block):
        phase = t[..., None] * orders[lo:lo + block]
        a[..., lo:lo + block] = np.einsum("...k,...kn->...n", gw, np.cos(phase)) / np.pi
        b[..., lo:lo + block] = np.einsum("...k,...kn->...n", gw, np.sin(phase)) / np.pi
    a[..., 0] *= 0.5
    b[..., 0] = 0.0
    return a, b


def _broadcast(*args):
    return [np.asarray(v, dtype=float)[..., None] for v in np.broadcast_arrays(*args)]


def reaction_harmonics(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, n_harmonics: int,
                       engine="vertical"):
    """Harmonics of ``M_r(theta)`` computed numerically from the force models (Hamabe, eq. 14).

    Integrates :func:`reaction_moment` times ``cos(n theta)``, ``sin(n theta)`` over one
    revolution, split at the friction switches ``theta = pi/2 - delta`` and ``3 pi/2 - delta``
    (:func:`piecewise_fourier`), so the result is exact to rounding (~1e-15 relative) and
    independent of the closed-form series (:func:`series_harmonics`), which it checks.

    Convention (the ordinary Fourier one, *not* the paper's alternating signs)::

        M_r(theta) = a_0 + sum_{n >= 1} [a_n cos(n theta) + b_n sin(n theta)]

    so ``a_0 = M_r0`` (eq. 11); :func:`paper_to_fourier` converts the paper's ``A_n, B_n``.
    Returns ``(a, b)``, each of shape ``broadcast(delta, ...).shape + (n_harmonics + 1,)``, N m.
    """
    d, w, q_, e_, s_, p1, p3, p4, mv, me = _broadcast(delta, omega, q, e, s, P1, P3, P4, m_v, m_e)

    def moment(theta, piece):
        # piece +1: theta + delta in (pi/2, 3 pi/2), cos < 0, friction +P1 sin(theta)
        return 0.5 * q_ * (piece * p1 * np.sin(theta)
                           + _smooth_force(theta, d, w, e_, s_, p3, p4, mv, me, engine))

    return piecewise_fourier(moment, np.pi / 2.0 - d[..., 0], n_harmonics)


def paper_signs(n_harmonics: int) -> np.ndarray:
    """Signs of eq. (14): ``M_r = A0 + A1 cos + B1 sin - [A2, B2] + [A4, B4] - ...``.

    ``+1`` for ``n = 0`` and odd ``n``; ``(-1)^j`` for ``n = 2 j``.
    """
    n = np.arange(n_harmonics + 1)
    return np.where(n % 2 == 0, (-1.0) ** (n // 2), 1.0)


def paper_to_fourier(A, B):
    """The paper's ``(A_n, B_n)`` of eq. (14) to ordinary Fourier ``(a_n, b_n)`` (and back)."""
    sign = paper_signs(np.shape(A)[-1] - 1)
    return np.asarray(A) * sign, np.asarray(B) * sign


def series_harmonics(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, n_harmonics: int,
                     engine="vertical"):
    """Hamabe's closed-form coefficients of eq. (14) (from the Fourier series eq. 13).

    In the paper's convention ``M_r = A0 + A1 cos(theta) + B1 sin(theta) - [A2 cos 2theta +
    B2 sin 2theta] + [A4 cos 4theta + B4 sin 4theta] - ...`` (:func:`paper_signs`):

    - ``A0 = M_r0`` (eq. 11);
    - ``B1 = (q/2)(P3 + P4)``, ``A1 = 0`` (vertical engine); ``B1 = (q/2) P3``,
      ``A1 = -(q/2) P4`` (horizontal engine, eq. 8 — the cos(theta) term the paper mentions);
    - ``A2 = (q/2)[(2P1/pi)(sin delta + sin(3delta)/3) + (m_v omega^2 e/2) cot delta]``,
      ``B2 = (q/2)[(2P1/pi)(cos delta + cos(3delta)/3) - m_v omega^2 e/2]``;
    - for ``n = 2j >= 4`` only the friction remains:
      ``A_2j = (q/2)(2P1/pi)[sin((2j-1)delta)/(2j-1) + sin((2j+1)delta)/(2j+1)]``, ``B_2j`` the
      same with ``cos``; odd ``n >= 3`` vanish.

    These follow from ``sign(cos phi) = (4/pi) sum_k (-1)^k cos((2k+1) phi)/(2k+1)`` and
    ``sin(delta + theta) sin(theta) = [cos delta - cos(2 theta + delta)]/2``; they agree with
    :func:`reaction_harmonics` to rounding (tests/test_vibration.py). Returns ``(A, B)``, N m.
    """
    d, w, q_, e_, s_, p1, p3, p4, mv, me = _broadcast(delta, omega, q, e, s, P1, P3, P4, m_v, m_e)
    n = np.arange(n_harmonics + 1)
    shape = np.broadcast_shapes(d.shape[:-1] + (1,), n.shape)
    A = np.zeros(shape)
    B = np.zeros(shape)
    A[..., 0] = mean_reaction_moment(d, w, q_, e_, s_, p1, mv, me)[..., 0]
    if engine not in ENGINES:
        raise ValueError(f"engine must be one of {ENGINES}, got {engine!r}")
    if n_harmonics >= 1:
        if engine == "vertical":
            B[..., 1] = (0.5 * q_ * (p3 + p4))[..., 0]
        else:
            B[..., 1] = (0.5 * q_ * p3)[..., 0]
            A[..., 1] = (-0.5 * q_ * p4)[..., 0]
    j = n[2::2] // 2
    if j.size:
        lo, hi = 2 * j - 1, 2 * j + 1
        fr = 0.5 * q_ * 2.0 * p1 / np.pi
        A[..., 2::2] = fr * (np.sin(lo * d) / lo + np.sin(hi * d) / hi)
        B[..., 2::2] = fr * (np.cos(lo * d) / lo + np.cos(hi * d) / hi)
        inertia = 0.5 * q_ * mv * w**2 * e_ / 2.0
        A[..., 2] += (inertia * np.cos(d) / np.sin(d))[..., 0]
        B[..., 2] -= inertia[..., 0]
    return A, B


def mean_square_reaction(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, engine="vertical"):
    """Mean square of ``M_r(theta)`` over a revolution, exactly (piecewise Gauss-Legendre of the
    square of eq. 14's force model; the integrand is a trigonometric polynomial on each half
    period, so the quadrature is exact)."""
    d, w, q_, e_, s_, p1, p3, p4, mv, me = _broadcast(delta, omega, q, e, s, P1, P3, P4, m_v, m_e)

    def square(theta, piece):
        return (0.5 * q_ * (piece * p1 * np.sin(theta)
                            + _smooth_force(theta, d, w, e_, s_, p3, p4, mv, me, engine))) ** 2

    a, _ = piecewise_fourier(square, np.pi / 2.0 - d[..., 0], 0, nodes=24)
    return a[..., 0]


def truncation_error(n_harmonics: int, delta, omega, q, e, s, P1, P3, P4, m_v, m_e,
                     engine="vertical"):
    """RMS of the part of ``M_r(theta)`` left out by keeping harmonics ``0..n_harmonics``.

    Parseval: ``tail^2 = mean(M_r^2) - a_0^2 - (1/2) sum_{n <= N} (a_n^2 + b_n^2)``, with the
    total mean square from :func:`mean_square_reaction` and the kept harmonics from
    :func:`reaction_harmonics`, both exact. Once ``N >= 2`` only the friction's square-wave
    harmonics remain in the tail; ``|c_2j| -> (q P1 |cos delta| / pi) / j`` so
    ``tail_rms -> q P1 |cos delta| / (pi sqrt(N))`` for even ``N``: slow. (The *maximum* of the
    tail does not decay at all: at each friction switch a truncated Fourier series misses half the
    jump, ``(q/2) P1 |cos delta|``, plus Gibbs' overshoot. The pendulum filters the tail by
    ``1/n^2``, so its response converges like ``1/N^2``; see
    :mod:`govopt.governors.shaft.vibration`.)
    """
    a, b = reaction_harmonics(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, n_harmonics, engine)
    total = mean_square_reaction(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, engine)
    kept = a[..., 0] ** 2 + 0.5 * np.sum(a[..., 1:] ** 2 + b[..., 1:] ** 2, axis=-1)
    return np.sqrt(np.maximum(total - kept, 0.0))
