"""Harmonics of the valve gear's reaction on the governor (Hamabe, Part II, eqs. 14-19).

The instantaneous reaction moment ``M_r(theta)`` (:func:`.valvegear.reaction_moment`) as a
Fourier series over the crank angle: exactly, by Gauss-Legendre quadrature on the pieces between
the friction's switches (:func:`piecewise_fourier`, :func:`reaction_harmonics`), and as the
paper's closed-form series (:func:`series_harmonics`, with its signs, :func:`paper_signs`, and
:func:`paper_to_fourier`); the error of truncating it (:func:`truncation_error`), from the mean
square over a revolution (:func:`mean_square_reaction`, Parseval). The forced vibration
(:mod:`govopt.governors.shaft.vibration`) reads them. All SI; functions broadcast over arrays.
"""

from __future__ import annotations

import functools

import numpy as np

from .valvegear import ENGINES, mean_reaction_moment, smooth_force


@functools.lru_cache(maxsize=64)
def _gauss_legendre(n: int):
    x, w = np.polynomial.legendre.leggauss(n)
    x.flags.writeable = False
    w.flags.writeable = False
    return x, w


def quadrature_nodes(n_max: int, spread: float = 0.0) -> int:
    """Gauss-Legendre nodes [-] per half period that integrate ``g(t) cos(n t)``, ``n <= n_max``,
    to machine precision when ``g`` is smooth on the half period with bandwidth
    ``~ 4 + spread n``.

    On a half period ``cos(n t)`` is ``cos(n pi/2 x + c)`` in the Legendre variable ``x``; its
    Legendre coefficients die out past degree ``n pi / 2``, and ``m`` nodes are exact to degree
    ``2 m - 1``; past that they fall off over a further ``~ (n pi/2)^(1/3)`` degrees (the
    transition region of ``J_k(n pi/2)``), hence the margin. The rule is govopt's own; it serves
    the harmonics of the valve gear's reaction, Hamabe's eq. (14).

    Parameters
    ----------
    n_max : int [-]
        Highest harmonic integrated.
    spread : float [-]
        Bandwidth of ``g`` per harmonic order (0 for the reaction itself).

    Returns
    -------
    int [-]
        The number of nodes per half period.

    References
    ----------
    [hamabe] Part II, eq. (14) (the harmonics these nodes compute).

    Examples
    --------
    By hand for ``n_max = 0``: ``k = 6``, ``ceil(6 pi/4 + 4 6^(1/3)) + 24 = ceil(11.98) + 24``:

    >>> quadrature_nodes(0)
    36
    """
    k = (n_max + 6) * (1.0 + spread)
    return int(np.ceil(k * np.pi / 4.0 + 4.0 * k ** (1.0 / 3.0))) + 24


def piecewise_fourier(func, start, n_harmonics: int, nodes: int | None = None):
    """Fourier coefficients of a ``2 pi``-periodic function that is smooth on the two half periods
    ``[start, start + pi]`` and ``[start + pi, start + 2 pi]`` and may jump between them.

    ``func(t, piece)`` is evaluated at Gauss-Legendre nodes ``t`` of shape ``start.shape + (2m,)``
    (its value may have more leading axes: functions sharing their nodes, computed at once)
    with ``piece = +1`` on the first half period and ``-1`` on the second (so a switching term,
    like the valve friction, needs no ``sign`` of a rounded number). Because each half period is
    integrated separately, the jumps cost no accuracy: the coefficients are exact to ~1e-15
    relative, not ``O(1/N)`` as a sampled FFT of a discontinuous function would be. The method is
    govopt's; it computes the series the paper writes in closed form (eqs. 13, 14).

    Parameters
    ----------
    func : callable [units of g]
        ``func(t, piece)``, the function at angles ``t`` [rad].
    start : float or array [rad]
        Where the first half period begins (a jump of ``g``).
    n_harmonics : int [-]
        Highest harmonic returned.
    nodes : int or None [-]
        Nodes per half period (default :func:`quadrature_nodes`).

    Returns
    -------
    tuple of arrays [units of g]
        ``(a, b)`` of shape ``start.shape + (n_harmonics + 1,)`` with
        ``g(t) = a_0 + sum_n [a_n cos(n t) + b_n sin(n t)]`` (``b_0 = 0``).

    References
    ----------
    [hamabe] Part II, eq. (13): the square wave ``sign(cos)`` of the valve friction.

    Examples
    --------
    The square wave ``sign(cos t)`` (+1 on ``[-pi/2, pi/2]``): its series is
    ``(4/pi)[cos t - cos(3t)/3 + ...]``, so ``a_1 = 1.27324``, ``a_3 = -0.42441``, the even ones 0:

    >>> a, b = piecewise_fourier(lambda t, piece: piece + 0 * t, -np.pi / 2, 3)
    >>> [round(float(x), 5) + 0.0 for x in a], float(np.max(np.abs(b))) < 1e-15
    ([0.0, 1.27324, 0.0, -0.42441], True)
    """
    start = np.asarray(start, dtype=float)
    m = nodes or quadrature_nodes(n_harmonics)
    x, w = _gauss_legendre(m)
    u = np.concatenate([x, x + 2.0])
    weights = np.concatenate([w, w]) * (np.pi / 2.0)
    piece = np.concatenate([np.ones(m), -np.ones(m)])
    t = start[..., None] + (np.pi / 2.0) * (u + 1.0)
    gw = func(t, piece) * weights  # may have more leading axes than start (shared nodes)
    orders = np.arange(n_harmonics + 1, dtype=float)
    a = np.empty(np.broadcast_shapes(gw.shape[:-1], start.shape) + (n_harmonics + 1,))
    b = np.empty_like(a)
    block = max(1, int(2e7 // max(t.size, 1)))
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
    """Harmonics [N m] of ``M_r(theta)`` computed numerically from the force models (Hamabe,
    Part II, eq. 14).

    Integrates :func:`reaction_moment` times ``cos(n theta)``, ``sin(n theta)`` over one
    revolution, split at the friction switches ``theta = pi/2 - delta`` and ``3 pi/2 - delta``
    (:func:`piecewise_fourier`), so the result is exact to rounding (~1e-15 relative) and
    independent of the closed-form series (:func:`series_harmonics`), which it checks.

    Convention (the ordinary Fourier one, *not* the paper's alternating signs)::

        M_r(theta) = a_0 + sum_{n >= 1} [a_n cos(n theta) + b_n sin(n theta)]

    so ``a_0 = M_r0`` (eq. 11); :func:`paper_to_fourier` converts the paper's ``A_n, B_n``.

    Parameters
    ----------
    delta : float or array [rad]
        Angular advance of the eccentric.
    omega : float or array [rad/s]
        Shaft speed.
    q, e, s, P1, P3, P4, m_v, m_e : float [m, m, m, N, N, N, kg, kg]
        The valve gear, as in :func:`reaction_moment`.
    n_harmonics : int [-]
        Highest harmonic kept.
    engine : str [-]
        "vertical" (eq. 7) or "horizontal" (eq. 8).

    Returns
    -------
    tuple of arrays [N m]
        ``(a, b)``, each of shape ``broadcast(delta, ...).shape + (n_harmonics + 1,)``.

    References
    ----------
    [hamabe] Part I, eqs. (5)-(9); Part II, eq. (14).

    Examples
    --------
    Hamabe's Example 1 (kgf, cm converted to SI; masses 12 and 6 kgf are 12 and 6 kg;
    omega^2 = 630):

    >>> KGF, CM = 9.80665, 0.01
    >>> VG = dict(q=5 * CM, e=2.6 * CM, s=0.6 * CM, P1=16 * KGF, P3=12 * KGF, P4=16 * KGF,
    ...           m_v=12.0, m_e=6.0)

    At delta = 48 deg 30': ``a_0 = M_r0 = 59.57`` kgf cm (eq. 11) and ``b_1 = B1 = (q/2)(P3 + P4)
    = 2.5 x 28 = 70`` kgf cm, as eq. (14) has it for a vertical engine:

    >>> a, b = reaction_harmonics(np.radians(48.5), np.sqrt(630), n_harmonics=1, **VG)
    >>> round(float(a[0]) / (KGF * CM), 2), round(float(b[1]) / (KGF * CM), 6)
    (59.57, 70.0)
    """
    d, w, q_, e_, s_, p1, p3, p4, mv, me = _broadcast(delta, omega, q, e, s, P1, P3, P4, m_v, m_e)

    def moment(theta, piece):
        # piece +1: theta + delta in (pi/2, 3 pi/2), cos < 0, friction +P1 sin(theta)
        return 0.5 * q_ * (piece * p1 * np.sin(theta)
                           + smooth_force(theta, d, w, e_, s_, p3, p4, mv, me, engine))

    return piecewise_fourier(moment, np.pi / 2.0 - d[..., 0], n_harmonics)


def paper_signs(n_harmonics: int) -> np.ndarray:
    """Signs [-] of eq. (14): ``M_r = A0 + A1 cos + B1 sin - [A2, B2] + [A4, B4] - ...``
    (Hamabe, Part II).

    ``+1`` for ``n = 0`` and odd ``n``; ``(-1)^j`` for ``n = 2 j``.

    Parameters
    ----------
    n_harmonics : int [-]
        Highest harmonic.

    Returns
    -------
    array [-]
        The signs, ``n = 0 .. n_harmonics``.

    References
    ----------
    [hamabe] Part II, eq. (14).

    Examples
    --------
    >>> paper_signs(6).tolist()
    [1.0, 1.0, -1.0, 1.0, 1.0, 1.0, -1.0]
    """
    n = np.arange(n_harmonics + 1)
    return np.where(n % 2 == 0, (-1.0) ** (n // 2), 1.0)


def paper_to_fourier(A, B):
    """The paper's ``(A_n, B_n)`` of eq. (14) to ordinary Fourier ``(a_n, b_n)`` [N m] (and back;
    Hamabe, Part II).

    Parameters
    ----------
    A : array [N m]
        The paper's cosine coefficients, ``n = 0 .. N`` along the last axis.
    B : array [N m]
        The paper's sine coefficients.

    Returns
    -------
    tuple of arrays [N m]
        ``(a, b)``: the signs of :func:`paper_signs` applied.

    References
    ----------
    [hamabe] Part II, eq. (14).

    Examples
    --------
    Harmonic 2 stands behind a minus sign in eq. (14), harmonic 4 behind a plus; applying the
    signs twice gives back the paper's coefficients:

    >>> a, b = paper_to_fourier([1.0, 2.0, 3.0, 0.0, 5.0], [0.0, 2.0, 3.0, 0.0, 5.0])
    >>> a.tolist(), paper_to_fourier(a, b)[0].tolist()
    ([1.0, 2.0, -3.0, 0.0, 5.0], [1.0, 2.0, 3.0, 0.0, 5.0])
    """
    sign = paper_signs(np.shape(A)[-1] - 1)
    return np.asarray(A) * sign, np.asarray(B) * sign


def series_harmonics(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, n_harmonics: int,
                     engine="vertical"):
    """Hamabe's closed-form coefficients [N m] of eq. (14) (from the Fourier series eq. 13).

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
    :func:`reaction_harmonics` to rounding (tests/test_vibration.py).

    Parameters
    ----------
    delta : float or array [rad]
        Angular advance of the eccentric.
    omega : float or array [rad/s]
        Shaft speed.
    q, e, s, P1, P3, P4, m_v, m_e : float [m, m, m, N, N, N, kg, kg]
        The valve gear, as in :func:`reaction_moment`.
    n_harmonics : int [-]
        Highest harmonic kept.
    engine : str [-]
        "vertical" (eq. 7) or "horizontal" (eq. 8).

    Returns
    -------
    tuple of arrays [N m]
        ``(A, B)`` in the paper's convention, ``n = 0 .. n_harmonics`` along the last axis.

    References
    ----------
    [hamabe] Part II, eqs. (13), (14).

    Examples
    --------
    Hamabe's Example 1 (kgf, cm converted to SI; masses 12 and 6 kgf are 12 and 6 kg;
    omega^2 = 630):

    >>> KGF, CM = 9.80665, 0.01
    >>> VG = dict(q=5 * CM, e=2.6 * CM, s=0.6 * CM, P1=16 * KGF, P3=12 * KGF, P4=16 * KGF,
    ...           m_v=12.0, m_e=6.0)

    At delta = 48 deg 30' the series and the numerical harmonics agree, the paper's minus sign
    on harmonic 2 included (A2 = 46.05, B2 = -15.18 kgf cm):

    >>> d, w = np.radians(48.5), np.sqrt(630)
    >>> A, B = series_harmonics(d, w, n_harmonics=2, **VG)
    >>> [round(float(x) / (KGF * CM), 2) for x in (A[2], B[2])]
    [46.05, -15.18]
    >>> a, b = reaction_harmonics(d, w, n_harmonics=2, **VG)
    >>> bool(np.allclose(paper_to_fourier(A, B), (a, b), rtol=0, atol=1e-12))
    True
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
    """Mean square [N^2 m^2] of ``M_r(theta)`` over a revolution, exactly (Hamabe, Part II,
    eq. 14's force model).

    Piecewise Gauss-Legendre of the square of the moment; the integrand is a trigonometric
    polynomial on each half period, so the quadrature is exact. (govopt's; it feeds
    :func:`truncation_error`.)

    Parameters
    ----------
    delta : float or array [rad]
        Angular advance of the eccentric.
    omega : float or array [rad/s]
        Shaft speed.
    q, e, s, P1, P3, P4, m_v, m_e : float [m, m, m, N, N, N, kg, kg]
        The valve gear, as in :func:`reaction_moment`.
    engine : str [-]
        "vertical" (eq. 7) or "horizontal" (eq. 8).

    Returns
    -------
    float or array [N^2 m^2]
        ``mean(M_r^2)`` over ``theta`` in ``[0, 2 pi)``.

    References
    ----------
    [hamabe] Part I, eqs. (5)-(9); Part II, eq. (14).

    Examples
    --------
    A hand check: with only the steam load, ``M_r = (q/2) P3 sin(theta)``, whose mean square is
    ``((q/2) P3)^2 / 2 = (0.025 x 100)^2 / 2 = 3.125`` N^2 m^2:

    >>> round(float(mean_square_reaction(1.0, 25.0, 0.05, 0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0)), 9)
    3.125
    """
    d, w, q_, e_, s_, p1, p3, p4, mv, me = _broadcast(delta, omega, q, e, s, P1, P3, P4, m_v, m_e)

    def square(theta, piece):
        return (0.5 * q_ * (piece * p1 * np.sin(theta)
                            + smooth_force(theta, d, w, e_, s_, p3, p4, mv, me, engine))) ** 2

    a, _ = piecewise_fourier(square, np.pi / 2.0 - d[..., 0], 0, nodes=24)
    return a[..., 0]


def truncation_error(n_harmonics: int, delta, omega, q, e, s, P1, P3, P4, m_v, m_e,
                     engine="vertical"):
    """RMS [N m] of the part of ``M_r(theta)`` left out by keeping harmonics ``0..n_harmonics``
    (Hamabe, Part II, eq. 14; the bound is govopt's).

    Parseval: ``tail^2 = mean(M_r^2) - a_0^2 - (1/2) sum_{n <= N} (a_n^2 + b_n^2)``, with the
    total mean square from :func:`mean_square_reaction` and the kept harmonics from
    :func:`reaction_harmonics`, both exact. Once ``N >= 2`` only the friction's square-wave
    harmonics remain in the tail; ``|c_2j| -> (q P1 |cos delta| / pi) / j`` so
    ``tail_rms -> q P1 |cos delta| / (pi sqrt(N))`` for even ``N``: slow. (The *maximum* of the
    tail does not decay at all: at each friction switch a truncated Fourier series misses half the
    jump, ``(q/2) P1 |cos delta|``, plus Gibbs' overshoot. The pendulum filters the tail by
    ``1/n^2``, so its response converges like ``1/N^2``; see
    :mod:`govopt.governors.shaft.vibration`.)

    Parameters
    ----------
    n_harmonics : int [-]
        Highest harmonic kept.
    delta : float or array [rad]
        Angular advance of the eccentric.
    omega : float or array [rad/s]
        Shaft speed.
    q, e, s, P1, P3, P4, m_v, m_e : float [m, m, m, N, N, N, kg, kg]
        The valve gear, as in :func:`reaction_moment`.
    engine : str [-]
        "vertical" (eq. 7) or "horizontal" (eq. 8).

    Returns
    -------
    float or array [N m]
        The RMS of the neglected tail.

    References
    ----------
    [hamabe] Part II, eqs. (13), (14).

    Examples
    --------
    Hamabe's Example 1 (kgf, cm converted to SI; masses 12 and 6 kgf are 12 and 6 kg;
    omega^2 = 630):

    >>> KGF, CM = 9.80665, 0.01
    >>> VG = dict(q=5 * CM, e=2.6 * CM, s=0.6 * CM, P1=16 * KGF, P3=12 * KGF, P4=16 * KGF,
    ...           m_v=12.0, m_e=6.0)

    At delta = 48 deg 30' with 64 harmonics the tail is within 1 % of its asymptote
    ``q P1 |cos delta| / (pi sqrt(N))``:

    >>> d, N = np.radians(48.5), 64
    >>> tail = truncation_error(N, d, np.sqrt(630), **VG)
    >>> round(float(tail * np.sqrt(N) * np.pi / (VG["q"] * VG["P1"] * np.cos(d))), 3)
    0.992
    """
    a, b = reaction_harmonics(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, n_harmonics, engine)
    total = mean_square_reaction(delta, omega, q, e, s, P1, P3, P4, m_v, m_e, engine)
    kept = a[..., 0] ** 2 + 0.5 * np.sum(a[..., 1:] ** 2 + b[..., 1:] ** 2, axis=-1)
    return np.sqrt(np.maximum(total - kept, 0.0))
