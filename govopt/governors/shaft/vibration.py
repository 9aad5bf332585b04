"""Forced vibration of the pendulum by the valve gear and the flywheel (Hamabe, Part II).

Equation of motion of each pendulum, linearised about its equilibrium ``alpha0`` (Hamabe,
eqs. 16-20, with the dash-pot of eq. 23 added)::

    I xi'' + f xi' + I k^2 xi = G(t),     k^2 = (dM_f/dalpha - omega0^2 m a rho cos alpha0) / I

(``k^2`` from :func:`govopt.analysis.statics.restoring_k2`), driven by the periodic moment

    G = m a rho sin(alpha0) (omega^2 - omega0^2)          centrifugal moment, eq. (1), modulated
        - [M_r(theta, omega, omega') - M_r0]              valve gear, eq. (14), about its mean
        + s_E (I - m a rho cos alpha0) omega'             tangential inertia (optional, s_E = 0)

with the single-cylinder speed fluctuation of eq. (19)::

    omega = omega0 + E2 cos(2 omega0 t) + F2 sin(2 omega0 t)
    theta = omega0 t + (E2 / 2 omega0) sin(2 omega0 t) - (F2 / 2 omega0) cos(2 omega0 t)

``G`` is ``2 pi``-periodic in ``tau = omega0 t``. Its harmonics ``G = G_0 + sum_n [M_n cos(n tau)
+ N_n sin(n tau)]`` (moments, N m; the paper's ``M_n, N_n`` of eq. 20 are these divided by ``I``)
are computed numerically from the force models, split at the two friction switches, so they are
exact to rounding for every order (no expansion in ``E2/omega0``; the paper keeps first order).
The steady response of harmonic ``n`` (eq. 22, plus damping) is::

    xi_n = X_n cos(n tau) + Y_n sin(n tau),   D = k^2 - n^2 omega0^2,   c = f n omega0 / I
    X_n = (D M_n - c N_n) / (I (D^2 + c^2)),  Y_n = (D N_n + c M_n) / (I (D^2 + c^2))
    amplitude = sqrt(M_n^2 + N_n^2) / (I sqrt(D^2 + c^2)),  xi_n = amplitude cos(n tau - phase)

With ``f = 0`` these are the paper's ``M_n / (k^2 - n^2 omega0^2)`` and ``N_n / (...)`` (its
Example 2 table, in degrees). ``G_0`` shifts the mean position by ``G_0 / (I k^2)`` (the paper's
``L``). The eccentric centre moves along its guide by ``q xi``: by virtual work this is the
movement that makes ``(q/2) P`` the moment of a force ``P/2`` on it (Hamabe's eq. 11 derivation),
so the eccentric's travel is ``q`` times the pendulum's swing.

Neglected (all of second order in the small quantities ``xi`` and ``eta = omega - omega0``,
unless stated):

- ``xi^2`` and higher terms of the linearisation (``sin xi ~ xi``, as the paper does; relative
  error ``~ xi^2 / 6``, 0.4 % at the paper's 9 deg amplitudes);
- ``xi eta`` terms: the modulation of the centrifugal stiffness by the speed fluctuation
  (parametric excitation, ``2 omega0 eta m a rho cos(alpha0) xi``) and the change of the valve
  gear's fluctuating reaction with the configuration (``d(M_r - M_r0)/dalpha xi``);
- harmonics of the speed other than the second (``E1, F1`` are small for a single cylinder,
  Hamabe), and the valve gear's own effect on the flywheel;
- the tangential force of the eccentric's rotating mass when the shaft accelerates
  (``m_e omega' rho_2``, relative size ``2 |eta| / omega0`` of the eccentric term: ~0.2 %);
- the pendulum's own tangential inertia ``(I - m a rho cos alpha0) omega'`` when the flywheel
  accelerates. The paper leaves it out; it is first order, about 25 % of the centrifugal term
  ``2 omega0 eta m a rho sin(alpha0)`` for the paper's governor (reported as
  ``tangential_inertia_ratio``). Its sign depends on whether the pendulum's centre of gravity
  leads or trails its fulcrum in the sense of rotation, which a spec does not say; pass
  ``tangential_inertia=+1`` (leads) or ``-1`` (trails) to include it. The speed fluctuation
  itself adds only a few per cent to the valve-gear forcing in Example 2.

Kept, beyond the paper: the full phase modulation of the valve gear by the speed fluctuation
(all orders), the speed dependence of the inertia and eccentric reactions (``omega(t)^2``), the
reciprocating parts' acceleration term ``-m_v omega' x``, and the dash-pot. The valve gear's
inertia reactions run at ``omega0 + eta``, or at ``spec.speed.omega_mean + eta`` when the spec's
``analysis.reaction_speed`` is ``"mean"`` (the paper's choice, as in the statics).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...analysis.statics import SpringDesign, restoring_k2
from ...inputs import Spec
from ...jsonable import jsonable
from . import harmonics, valvegear

#: Relative detuning ``|k^2 - n^2 omega0^2| / max(k^2, n^2 omega0^2)`` below which an undamped
#: harmonic is treated as exactly resonant (amplitude ``inf``).
RESONANCE_RTOL = 1e-9

#: A harmonic whose moment is below this fraction of the largest one is rounding noise (not
#: excited): at an undamped resonance it gets amplitude 0, not ``inf``.
EXCITED_RTOL = 1e-12

#: Harmonics computed explicitly beyond the kept ones for the truncation estimate.
TAIL_EXPLICIT = 32

#: Samples of the steady response over one revolution in :meth:`VibrationResult.trace` (2 deg).
TRACE_SAMPLES = 181


# ---------------------------------------------------------------------------------------------
# The forcing moment
# ---------------------------------------------------------------------------------------------

def _speed_fluctuation(spec: Spec, speed_fluctuation):
    if speed_fluctuation is not None:
        E2, F2 = speed_fluctuation
        return float(E2), float(F2)
    if spec.engine is None:
        return 0.0, 0.0
    return float(spec.engine.speed_fluctuation_cos), float(spec.engine.speed_fluctuation_sin)


def _setup(spec: Spec, alpha0, m, inertia, omega0, tangential_inertia, speed_fluctuation):
    """Broadcast parameters of the forcing ``G(tau)`` (trailing axis added for the nodes)."""
    if tangential_inertia not in (-1, 0, 1):
        raise ValueError(f"tangential_inertia must be -1, 0 or +1, got {tangential_inertia!r}")
    g, vg = spec.governor, spec.governor.valve_gear
    omega0 = spec.speed.omega_mean if omega0 is None else omega0
    # the crank's timing (advance, modulation, switches) needs only alpha0 and omega0: shared by
    # designs that differ in their masses, so the quadrature's nodes are computed once for them
    alpha0, omega0 = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (alpha0, omega0)))
    m, inertia = (np.asarray(v, dtype=float) for v in (m, inertia))
    E2, F2 = _speed_fluctuation(spec, speed_fluctuation)
    if np.any(2.0 * math.hypot(E2, F2) >= omega0):
        raise ValueError("speed fluctuation |E2 + i F2| must be below omega0 / 2 (the crank "
                         "must keep turning forwards)")
    delta = valvegear.advance_angle(alpha0, vg.table_alpha, vg.table_delta,
                                    spec.analysis.valve_table)
    # the valve gear's inertia reactions at the speed the statics uses for them
    omega_r0 = (np.full_like(omega0, spec.speed.omega_mean)
                if spec.analysis.reaction_speed == "mean" else omega0)
    p = {
        "alpha0": alpha0, "delta": delta, "omega0": omega0, "omega_r0": omega_r0,
        "E2": E2, "F2": F2, "eps_E": E2 / (2.0 * omega0), "eps_F": F2 / (2.0 * omega0),
        "lever": m * g.a * g.rho * np.sin(alpha0),
        "euler": tangential_inertia * (inertia - m * g.a * g.rho * np.cos(alpha0)),
        "M_r0": valvegear.mean_reaction_moment(delta, omega_r0, g.q, vg.eccentricity, vg.offset,
                                               vg.friction, vg.reciprocating_mass,
                                               vg.eccentric_mass),
    }
    return p


def _theta(tau, eps_E, eps_F):
    """Crank angle against ``tau = omega0 t`` (Hamabe, eq. 19)."""
    return tau + eps_E * np.sin(2.0 * tau) - eps_F * np.cos(2.0 * tau)


def _forcing(spec: Spec, p: dict, tau, friction_factor=None):
    """``G(tau)``, N m; ``friction_factor`` = ``-sign(cos(theta + delta))`` (computed if None)."""
    x = {k: (v[..., None] if isinstance(v, np.ndarray) else v) for k, v in p.items()}
    g, vg = spec.governor, spec.governor.valve_gear
    w0 = x["omega0"]
    eta = x["E2"] * np.cos(2.0 * tau) + x["F2"] * np.sin(2.0 * tau)
    eta_dot = 2.0 * w0 * (-x["E2"] * np.sin(2.0 * tau) + x["F2"] * np.cos(2.0 * tau))
    theta = _theta(tau, x["eps_E"], x["eps_F"])
    if friction_factor is None:
        friction_factor = -np.sign(np.cos(theta + x["delta"]))
    reaction = 0.5 * g.q * (
        friction_factor * vg.friction * np.sin(theta)
        + valvegear.smooth_force(theta, x["delta"], x["omega_r0"] + eta, vg.eccentricity,
                                 vg.offset, vg.steam_load, vg.weight, vg.reciprocating_mass,
                                 vg.eccentric_mass, vg.engine, omega_dot=eta_dot))
    return x["lever"] * eta * (2.0 * w0 + eta) - (reaction - x["M_r0"]) + x["euler"] * eta_dot


def _switch_start(p: dict):
    """``tau_a`` with ``theta(tau_a) = pi/2 - delta``: the friction switch that starts the half
    period where ``cos(theta + delta) < 0``. ``theta(tau + pi) = theta(tau) + pi``, so the other
    switch is ``tau_a + pi``. Newton on the monotone ``theta(tau)``."""
    target = np.pi / 2.0 - p["delta"]
    tau = target.copy()
    eE, eF = p["eps_E"], p["eps_F"]
    for _ in range(60):
        h = _theta(tau, eE, eF) - target
        dh = 1.0 + 2.0 * eE * np.cos(2.0 * tau) + 2.0 * eF * np.sin(2.0 * tau)
        step = h / dh
        tau = tau - step
        if np.all(np.abs(step) <= 1e-15 * (1.0 + np.abs(tau))):
            break
    return tau


def forcing_harmonics(spec: Spec, alpha0, m, inertia, omega0=None, n_harmonics: int | None = None,
                      *, speed_fluctuation=None, tangential_inertia: int = 0):
    """Harmonics [N m] of the forcing moment ``G(tau)`` (Hamabe, Part II, eqs. 19-21).

    ``(a, b)`` with ``G = a_0 + sum_n [a_n cos(n tau) + b_n sin(n tau)]``, shape
    ``broadcast(alpha0, m, inertia, omega0).shape + (N+1,)``.

    ``a_n, b_n`` are the paper's ``I M_n, I N_n`` (eq. 20, 21); without speed fluctuation
    ``a_n + i b_n = -(reaction harmonic n)`` of
    :func:`govopt.governors.shaft.harmonics.reaction_harmonics`,
    e.g. ``b_1 = -B1``. Exact to rounding for every order (:func:`.harmonics.piecewise_fourier`,
    split at the friction switches in ``tau``). Vectorised over designs and configurations.

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor, valve gear, speed, engine and analysis;
        SI inside).
    alpha0 : float or array [rad]
        The equilibrium configuration vibrated about.
    m : float or array [kg]
        Mass of one pendulum.
    inertia : float or array [kg m^2]
        The pendulum's moment of inertia about its fulcrum.
    omega0 : float or array or None [rad/s]
        Mean shaft speed (default the spec's mean speed).
    n_harmonics : int or None [-]
        Highest harmonic (default the spec's ``analysis.harmonics``).
    speed_fluctuation : tuple of float or None [rad/s]
        ``(E2, F2)`` of eq. (19), overriding the spec's engine.
    tangential_inertia : int [-]
        -1, 0 or +1: the pendulum's tangential inertia left out (0) or taken
        with its centre of gravity trailing (-1) or leading (+1).

    Returns
    -------
    tuple of arrays [N m]
        ``(a, b)``, the cosine and sine moments, orders ``0 .. N`` on the last axis.

    References
    ----------
    [hamabe] Part II, eqs. (14), (19)-(21).

    Examples
    --------
    Hamabe's Example 2, case (a), with the paper's inputs: ``k^2 = 360``, ``omega0^2 = 630``,
    ``I = rho^2 m = 0.1728`` kg m^2 (12 kgf at 12 cm), no speed fluctuation:

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> alpha_n, w0 = spec.governor.alpha_normal, np.sqrt(630.0)

    Without speed fluctuation ``b_1 = -B1 = -(q/2)(P3 + P4) = -70`` kgf cm (eq. 14):

    >>> a, b = forcing_harmonics(spec, alpha_n, 12.0, 0.1728, w0, 2, speed_fluctuation=(0, 0))
    >>> round(float(b[1]) / (9.80665 * 0.01), 6)
    -70.0
    """
    N = spec.analysis.harmonics if n_harmonics is None else int(n_harmonics)
    p = _setup(spec, alpha0, m, inertia, omega0, tangential_inertia, speed_fluctuation)
    return _harmonics(spec, p, N)


def _harmonics(spec: Spec, p: dict, N: int):
    """``(a, b)`` of :func:`forcing_harmonics` from its parameters ``p`` (:func:`_setup`)."""
    spread = 2.0 * float(np.max(np.hypot(p["eps_E"], p["eps_F"])))
    nodes = harmonics.quadrature_nodes(N, spread)

    def g(tau, piece):
        return _forcing(spec, p, tau, piece)

    return harmonics.piecewise_fourier(g, _switch_start(p), N, nodes)


# ---------------------------------------------------------------------------------------------
# Response
# ---------------------------------------------------------------------------------------------

def _f(dashpot):
    return 0.0 if dashpot is None else dashpot


def harmonic_response(a, b, k2, inertia, omega0, dashpot=None, orders=None):
    """Steady response [rad] of ``I xi'' + f xi' + I k^2 xi = a cos(n tau) + b sin(n tau)``
    (Hamabe, Part II, eq. 22, with the dash-pot of eq. 23).

    ``a, b`` have the orders on the last axis (``orders`` default ``0, 1, ...``); ``k2, inertia,
    omega0, dashpot`` broadcast with the leading axes. Returns a dict of arrays: ``cos`` and
    ``sin`` (``X_n, Y_n``, rad), ``amplitude`` (rad), ``phase`` (rad, ``xi_n = amplitude cos(n tau
    - phase)``), ``detuning`` ``(k^2 - n^2 omega0^2) / (n^2 omega0^2)`` and ``resonant`` (bool).

    Exact resonance (``f = 0`` and ``k^2 = n^2 omega0^2`` to :data:`RESONANCE_RTOL`) has no steady
    solution: ``resonant`` is True, the amplitude ``inf`` (0 if that harmonic is not excited, i.e.
    below :data:`EXCITED_RTOL` of the largest),
    ``cos``/``sin`` are ``+-inf`` along the secular growth ``t (a sin - b cos) / (2 I n omega0)``
    and ``phase`` its phase. Never NaN, never raises. ``n = 0`` is the static shift ``a_0 / (I
    k^2)`` (resonant when ``k^2 = 0``).

    Parameters
    ----------
    a : array [N m]
        Cosine moments of the forcing, orders on the last axis.
    b : array [N m]
        Sine moments of the forcing.
    k2 : float or array [1/s^2]
        Restoring stiffness per unit inertia, ``k^2`` (eq. 18).
    inertia : float or array [kg m^2]
        The pendulum's moment of inertia about its fulcrum.
    omega0 : float or array [rad/s]
        Mean shaft speed (``tau = omega0 t``).
    dashpot : float or array or None [N m s/rad]
        Dash-pot coefficient ``f`` (None: undamped, the paper's Part II).
    orders : array or None [-]
        The harmonic orders of the last axis (default ``0, 1, ...``).

    Returns
    -------
    dict of arrays [rad, -]
        ``cos``, ``sin``, ``amplitude``, ``phase`` [rad]; ``detuning`` [-]; ``resonant`` [-].

    References
    ----------
    [hamabe] Part II, eqs. (22), (23).

    Examples
    --------
    Hamabe's Example 2, case (a): ``k^2 = 360``, ``omega0^2 = 630``, ``I = 0.1728`` kg m^2. The
    paper prints 8.45 deg for the first harmonic, ``B1 / (I (omega0^2 - k^2))`` with
    ``B1 = (q/2)(P3 + P4) = 70`` kgf cm; its inputs give 8.43 (the paper's k^2 is rounded):

    >>> B1 = 0.025 * 28 * 9.80665
    >>> r = harmonic_response([0.0, 0.0], [0.0, -B1], 360.0, 0.1728, np.sqrt(630.0))
    >>> round(float(np.degrees(r["amplitude"][1])), 2), round(float(r["detuning"][1]), 4)
    (8.43, -0.4286)

    At resonance (``k^2 = omega0^2``) a dash-pot ``f`` leaves ``B1 / (f omega0)``, by hand
    ``6.8647 / (5 x 25.1) = 0.0547`` rad:

    >>> r = harmonic_response([0.0, 0.0], [0.0, -B1], 630.0, 0.1728, np.sqrt(630.0), 5.0)
    >>> round(float(r["amplitude"][1]), 4)
    0.0547
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    n = np.arange(a.shape[-1], dtype=float) if orders is None else np.asarray(orders, float)
    k2, inertia, omega0, f = (np.asarray(v, dtype=float)[..., None]
                              for v in (k2, inertia, omega0, _f(dashpot)))
    W2 = (n * omega0) ** 2
    D = k2 - W2
    c = f * n * omega0 / inertia
    scale = np.maximum(np.abs(k2), W2)
    resonant = (c == 0) & (np.abs(D) <= RESONANCE_RTOL * scale)
    den = np.where(resonant, 1.0, D**2 + c**2)
    forcing = np.hypot(a, b)
    # a harmonic is excited unless its moment is rounding noise of the largest one
    excited = forcing > EXCITED_RTOL * np.max(forcing, axis=-1, keepdims=True)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        X = np.where(resonant, _signed_inf(-b * excited), (D * a - c * b) / (inertia * den))
        Y = np.where(resonant, _signed_inf(a * excited), (D * b + c * a) / (inertia * den))
        amplitude = np.where(resonant, np.where(excited, np.inf, 0.0),
                             forcing / (inertia * np.sqrt(den)))
        detuning = np.where(W2 > 0, D / np.where(W2 > 0, W2, 1.0), _signed_inf(D))
    phase = np.where(resonant, np.arctan2(a, -b), np.arctan2(Y, X))
    return {"cos": X, "sin": Y, "amplitude": amplitude, "phase": phase,
            "detuning": detuning, "resonant": resonant}


def _signed_inf(x):
    return np.where(x > 0, np.inf, np.where(x < 0, -np.inf, 0.0))


def _tail_integral(K, k2, omega0):
    """``int_K^inf dx / (x (omega0^2 x^2 - k^2)) = -log(1 - r) / (2 k^2)``, ``r = k^2 /
    (omega0 K)^2 < 1``, written stably for ``k^2 -> 0`` (``1 / (2 omega0^2 K^2)``)."""
    r = k2 / (omega0 * K) ** 2
    small = np.abs(r) < 1e-6
    rs = np.where(small, 0.5, r)
    L = np.where(small, 1.0 + r / 2.0 + r**2 / 3.0, -np.log1p(-rs) / rs)
    return L / (2.0 * (omega0 * K) ** 2)


def _tail_count(N, k2, omega0):
    """Last harmonic computed explicitly for the truncation estimate: ``N + max(N, 32)``, and at
    least 1.5 times the order of a resonance ``k / omega0``, so the asymptotic rest is monotone."""
    return int(np.max(_tail_counts(N, k2, omega0)))


def _tail_counts(N, k2, omega0):
    """:func:`_tail_count` of each design of ``k2`` (an integer array)."""
    k = np.sqrt(np.maximum(np.asarray(k2, dtype=float), 0.0)) / omega0
    return np.maximum(N + max(N, TAIL_EXPLICIT), np.ceil(1.5 * k) + 2).astype(np.int64)


def _asymptotic_tail(spec: Spec, p: dict, K, k2, inertia):
    """Estimate of ``sum_{n > K} amplitude_n``: past the smooth part only the friction's jumps
    remain, ``|G_n| <= sum|jumps| / (pi n)`` asymptotically, the two jumps being ``q P1 |cos
    delta|`` each (``P1'`` switches at ``|sin theta| = |cos delta|``); damping ignored (it only
    lowers the amplitudes)."""
    vg = spec.governor.valve_gear
    jumps = 2.0 * spec.governor.q * vg.friction * np.abs(np.cos(p["delta"]))
    return jumps / (np.pi * inertia) * _tail_integral(K, k2, p["omega0"])


def _synthesize(X, Y, tau):
    n = np.arange(1, len(X) + 1)
    ph = np.multiply.outer(tau, n)
    return np.cos(ph) @ X + np.sin(ph) @ Y


def _peak_to_peak(X, Y):
    """Peak-to-peak of ``sum_n X_n cos(n tau) + Y_n sin(n tau)`` (``n = 1..N``) and the
    ``tau`` of its top and bottom: :func:`_peak_to_peak_many` of one."""
    p2p, top, bottom = _peak_to_peak_many(np.atleast_2d(X), np.atleast_2d(Y))
    return float(p2p[0]), float(top[0]), float(bottom[0])


#: designs whose swing is sampled at once (bounds the memory: ~ 2 x 2048 x 16 bytes a design)
_SWING_BLOCK = 256


def _peak_to_peak_many(X, Y):
    """Peak-to-peak of ``sum_n X_n cos(n tau) + Y_n sin(n tau)`` (``n = 1..N``) of each row of
    ``X, Y`` (shape ``(designs, N)``) and the ``tau`` of its top and bottom: sampled by an
    inverse FFT on a fine grid, then the global maximum and minimum refined by a safeguarded
    Newton iteration on the derivative in the bracketing grid cells. Exact to rounding."""
    rows, N = X.shape
    if N == 0:
        return np.zeros(rows), np.zeros(rows), np.zeros(rows)
    L = 1 << max(11, int(math.ceil(math.log2(32 * (N + 1)))))
    i_top, i_bottom = np.empty(rows, np.int64), np.empty(rows, np.int64)
    x_top, x_bottom = np.empty(rows), np.empty(rows)
    for lo in range(0, rows, _SWING_BLOCK):
        sl = slice(lo, lo + _SWING_BLOCK)
        spec = np.zeros((X[sl].shape[0], L // 2 + 1), dtype=complex)
        spec[:, 1:N + 1] = (X[sl] - 1j * Y[sl]) * (L / 2.0)
        x = np.fft.irfft(spec, n=L, axis=-1)
        i_top[sl], i_bottom[sl] = np.argmax(x, axis=1), np.argmin(x, axis=1)
        x_top[sl] = np.take_along_axis(x, i_top[sl, None], axis=1)[:, 0]
        x_bottom[sl] = np.take_along_axis(x, i_bottom[sl, None], axis=1)[:, 0]
    tau = 2.0 * np.pi * np.arange(L) / L
    top, t_top = _refine(X, Y, tau[i_top], x_top, 2.0 * np.pi / L, np.maximum)
    bottom, t_bottom = _refine(X, Y, tau[i_bottom], x_bottom, 2.0 * np.pi / L, np.minimum)
    return top - bottom, t_top, t_bottom


def _refine(X, Y, t0, x0, h, better):
    """The extremum of each row's series near the grid's ``t0`` (value ``x0``): the root of the
    derivative in ``[t0 - h, t0 + h]`` where it changes sign there (Newton, falling back to
    bisection when a step leaves the bracket, to a step of ``1e-13 (1 + |t|)``: the value at a
    stationary point moves by the square of that), the ``better`` of its value and the grid's;
    else the grid's."""
    n = np.arange(1, X.shape[1] + 1)

    def slope(t, X, Y, second=False):
        c, s = np.cos(n * t[:, None]), np.sin(n * t[:, None])
        if second:
            return -np.sum(n * n * (X * c + Y * s), axis=1)
        return np.sum(n * (Y * c - X * s), axis=1)

    lo, hi = t0 - h, t0 + h
    f_lo = slope(lo, X, Y)
    bracket = f_lo * slope(hi, X, Y) < 0
    t = t0.copy()
    todo = np.nonzero(bracket)[0]
    for _ in range(100):
        if not todo.size:
            break
        tt, Xt, Yt = t[todo], X[todo], Y[todo]
        f, fp = slope(tt, Xt, Yt), slope(tt, Xt, Yt, second=True)
        same = np.sign(f) == np.sign(f_lo[todo])
        lo[todo], hi[todo] = np.where(same, tt, lo[todo]), np.where(same, hi[todo], tt)
        with np.errstate(divide="ignore", invalid="ignore"):
            nxt = tt - f / fp
        nxt = np.where((nxt >= lo[todo]) & (nxt <= hi[todo]), nxt, 0.5 * (lo[todo] + hi[todo]))
        nxt = np.where(f == 0, tt, nxt)
        t[todo] = nxt
        tol = 1e-13 * (1.0 + np.abs(tt))
        todo = todo[(np.abs(nxt - tt) > tol) & (hi[todo] - lo[todo] > tol)]
    c, s = np.cos(n * t[:, None]), np.sin(n * t[:, None])
    value = np.sum(X * c + Y * s, axis=1)
    return np.where(bracket, better(value, x0), x0), t


# ---------------------------------------------------------------------------------------------
# Results
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class VibrationResult:
    """Steady forced vibration of one design at one configuration (Hamabe, Part II), SI.

    ``harmonics``: one dict per order ``n = 1..N``: ``order``, ``moment_cos_N_m`` and
    ``moment_sin_N_m`` (``I M_n``, ``I N_n`` of eq. 20), ``cos_rad`` and ``sin_rad`` (``X_n,
    Y_n``; undamped, the paper's ``M_n / (k^2 - n^2 omega0^2)`` and ``N_n / (...)``),
    ``amplitude_rad``, ``phase_rad`` (``xi_n = amplitude cos(n omega0 t - phase)``),
    ``detuning`` and ``resonant``. ``peak_to_peak_rad`` is that of the sum of the kept harmonics
    (``inf`` at an undamped resonance); ``truncation_error_rad`` estimates the largest
    contribution of the harmonics left out (sum of their amplitudes, see :func:`vibration`).
    """

    alpha0: float
    delta: float
    omega0: float
    k2: float
    inertia: float
    dashpot: float
    n_harmonics: int
    speed_fluctuation: tuple[float, float]
    tangential_inertia: int
    tangential_inertia_ratio: float
    harmonics: tuple[dict, ...]
    mean_offset_rad: float
    peak_to_peak_rad: float
    eccentric_travel_m: float
    truncation_error_rad: float
    resonant_orders: tuple[int, ...]
    extrema_tau: tuple[float, float] = field(default=(math.nan, math.nan), repr=False)

    @property
    def resonance(self) -> bool:
        """True when some kept harmonic is exactly resonant and undamped (infinite amplitude)."""
        return bool(self.resonant_orders)

    @property
    def stable(self) -> bool:
        """Hamabe's Case 3: ``k^2 <= 0`` is unstable, the periodic solution then meaningless."""
        return self.k2 > 0

    @property
    def hamabe_case(self) -> int:
        """1: ``0 < k^2 < omega0^2`` (required); 2: ``k^2 >= omega0^2`` (resonance risk);
        3: ``k^2 <= 0`` (unstable)."""
        if self.k2 <= 0:
            return 3
        return 1 if self.k2 < self.omega0**2 else 2

    def amplitude(self, order: int) -> float:
        return self.harmonics[order - 1]["amplitude_rad"]

    def trace(self, samples: int = TRACE_SAMPLES):
        """The steady response over one revolution, ``tau = omega0 t`` from 0 to ``2 pi``:
        ``xi = L + sum_n X_n cos(n tau) + Y_n sin(n tau)`` (Hamabe eq. 22, the kept harmonics;
        ``L`` the mean offset), rad; ``(tau, xi)``, with ``xi`` inf at an undamped resonance."""
        tau = np.linspace(0.0, 2.0 * np.pi, samples)
        X, Y = (np.array([h[k] for h in self.harmonics]) for k in ("cos_rad", "sin_rad"))
        return tau, self.mean_offset_rad + _synthesize(X, Y, tau)

    def to_dict(self) -> dict:
        """JSON-ready dict with SI keys; an infinity as null with a ``<key>_infinite`` flag
        (:func:`govopt.jsonable.jsonable`)."""
        out = {
            "alpha0_rad": self.alpha0,
            "delta_rad": self.delta,
            "omega0_rad_s": self.omega0,
            "k2_rad2_s2": self.k2,
            "inertia_kg_m2": self.inertia,
            "dashpot_N_m_s_per_rad": self.dashpot,
            "n_harmonics": self.n_harmonics,
            "speed_fluctuation_E2_rad_s": self.speed_fluctuation[0],
            "speed_fluctuation_F2_rad_s": self.speed_fluctuation[1],
            "tangential_inertia": self.tangential_inertia,
            "tangential_inertia_ratio": self.tangential_inertia_ratio,
            "mean_offset_rad": self.mean_offset_rad,
            "peak_to_peak_rad": self.peak_to_peak_rad,
            "eccentric_travel_m": self.eccentric_travel_m,
            "truncation_error_rad": self.truncation_error_rad,
            "resonance": self.resonance,
            "resonant_orders": list(self.resonant_orders),
            "stable": self.stable,
            "hamabe_case": self.hamabe_case,
            "harmonics": [dict(h) for h in self.harmonics],
        }
        if np.isfinite(self.peak_to_peak_rad):  # one revolution of the steady response
            tau, xi = self.trace()
            out["response"] = {"crank_angle_rad": tau, "xi_rad": xi}
        return jsonable(out)


def _dashpot(spec: Spec, dashpot):
    if isinstance(dashpot, str):
        if dashpot != "design":
            raise ValueError(f"dashpot must be a number, None or 'design', got {dashpot!r}")
        return 0.0 if spec.design is None or spec.design.dashpot is None else spec.design.dashpot
    return _f(dashpot)


def vibration(spec: Spec, sd: SpringDesign, alpha0: float, k2: float | None = None,
              omega0: float | None = None, n_harmonics: int | None = None, *,
              dashpot: float | None | str = "design", speed_fluctuation=None,
              tangential_inertia: int = 0) -> VibrationResult:
    """Steady forced vibration of the pendulum about ``alpha0`` (Hamabe, Part II, eqs. 18-22,
    Example 2).

    ``k2`` defaults to :func:`~govopt.analysis.statics.restoring_k2` at ``alpha0`` and
    ``omega0`` (default: the spec's mean speed); ``n_harmonics`` to ``spec.analysis.harmonics``.
    ``dashpot``: ``"design"`` takes ``spec.design.dashpot``; a number is ``f`` (N m s/rad);
    ``None`` or 0 is undamped, the paper's Part II. ``speed_fluctuation=(E2, F2)`` overrides the
    spec's engine (rad/s). ``tangential_inertia``: see the module docstring.

    The response is the sum of harmonics ``1..N``; ``peak_to_peak_rad`` is found by sampling and
    root finding (exact for the kept harmonics), ``eccentric_travel_m = q * peak_to_peak_rad``.
    ``truncation_error_rad`` bounds what the left-out harmonics can add to ``|xi - mean|``: the
    sum of their amplitudes, ``N+1 .. N+max(N, 32)`` computed exactly, the rest from the
    friction jumps' ``1/n`` coefficients (an asymptotically tight estimate, ``~ 1/N^2``); the
    peak-to-peak of the complete response lies within ``+- 2 truncation_error_rad``.
    Exact undamped resonance gives ``inf`` and lists the order in ``resonant_orders``.

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor, valve gear, speed, engine and analysis;
        SI inside).
    sd : SpringDesign [-]
        The design (:class:`~govopt.analysis.statics.SpringDesign`: mass [kg], inertia
        [kg m^2], spring [N/m, m]).
    alpha0 : float [rad]
        The equilibrium configuration vibrated about.
    k2 : float or None [1/s^2]
        Restoring stiffness per unit inertia (default from the statics).
    omega0 : float or None [rad/s]
        Mean shaft speed (default the spec's mean speed).
    n_harmonics : int or None [-]
        Highest harmonic (default the spec's ``analysis.harmonics``).
    dashpot : float or None or str [N m s/rad]
        ``f``; ``"design"`` (default) takes the spec's; None is undamped.
    speed_fluctuation : tuple of float or None [rad/s]
        ``(E2, F2)`` of eq. (19), overriding the spec's engine.
    tangential_inertia : int [-]
        -1, 0 or +1: the pendulum's tangential inertia left out (0) or taken
        with its centre of gravity trailing (-1) or leading (+1).

    Returns
    -------
    VibrationResult [rad]
        Harmonics, peak-to-peak, eccentric travel [m], truncation error [rad].

    References
    ----------
    [hamabe] Part II, eqs. (18)-(22), Example 2.

    Examples
    --------
    Hamabe's Example 2, case (a), with the paper's inputs: ``k^2 = 360``, ``omega0^2 = 630``,
    ``I = rho^2 m = 0.1728`` kg m^2 (12 kgf at 12 cm), no speed fluctuation:

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> alpha_n, w0 = spec.governor.alpha_normal, np.sqrt(630.0)

    >>> from govopt.analysis.statics import spring_design
    >>> v = vibration(spec, spring_design(spec), alpha_n, 360.0, w0, dashpot=None,
    ...               speed_fluctuation=(0, 0))

    The paper prints 8.45 deg for the first harmonic, ``B1 / (I (omega0^2 - k^2))`` with
    ``B1 = (q/2)(P3 + P4) = 70`` kgf cm; its inputs give 8.43 (the paper's k^2 is rounded):

    >>> round(float(np.degrees(v.amplitude(1))), 2)
    8.43
    """
    return vibrations(spec, sd, alpha0, k2, omega0, n_harmonics, dashpot=dashpot,
                      speed_fluctuation=speed_fluctuation,
                      tangential_inertia=tangential_inertia)[0]


@dataclass(frozen=True)
class Vibrations:
    """The steady forced vibrations of N designs about one configuration (:func:`vibrations`),
    as arrays over the designs (SI); ``self[i]`` is design ``i``'s :class:`VibrationResult`.

    ``k2``, ``inertia``, ``dashpot``, ``ratio`` (the tangential inertia ratio), ``tail`` (the
    truncation error), ``peak_to_peak_rad``: shape ``(N,)``; ``extrema``: ``(N, 2)``;
    ``a``, ``b`` (the forcing's moments) and ``response`` (:func:`harmonic_response`'s arrays):
    ``(N, n_harmonics + 1)``, orders ``0 .. n_harmonics``."""

    alpha0: float
    delta: float
    omega0: float
    n_harmonics: int
    speed_fluctuation: tuple[float, float]
    tangential_inertia: int
    q: float
    k2: np.ndarray
    inertia: np.ndarray
    dashpot: np.ndarray
    ratio: np.ndarray
    a: np.ndarray
    b: np.ndarray
    response: dict
    peak_to_peak_rad: np.ndarray
    extrema: np.ndarray
    tail: np.ndarray

    def __len__(self) -> int:
        return self.k2.size

    def __getitem__(self, i: int) -> VibrationResult:
        N, r = self.n_harmonics, {k: v[i] for k, v in self.response.items()}
        a, b = self.a[i], self.b[i]
        harmonics = tuple(
            {"order": n, "moment_cos_N_m": float(a[n]), "moment_sin_N_m": float(b[n]),
             "cos_rad": float(r["cos"][n]), "sin_rad": float(r["sin"][n]),
             "amplitude_rad": float(r["amplitude"][n]), "phase_rad": float(r["phase"][n]),
             "detuning": float(r["detuning"][n]), "resonant": bool(r["resonant"][n])}
            for n in range(1, N + 1))
        p2p = float(self.peak_to_peak_rad[i])
        return VibrationResult(
            alpha0=self.alpha0, delta=self.delta, omega0=self.omega0, k2=float(self.k2[i]),
            inertia=float(self.inertia[i]), dashpot=float(self.dashpot[i]), n_harmonics=N,
            speed_fluctuation=self.speed_fluctuation,
            tangential_inertia=self.tangential_inertia,
            tangential_inertia_ratio=float(self.ratio[i]), harmonics=harmonics,
            mean_offset_rad=float(r["cos"][0]), peak_to_peak_rad=p2p,
            eccentric_travel_m=float(self.q * p2p), truncation_error_rad=float(self.tail[i]),
            resonant_orders=tuple(n for n in range(1, N + 1) if r["resonant"][n]),
            extrema_tau=tuple(float(t) for t in self.extrema[i]))


def vibrations(spec: Spec, sd: SpringDesign, alpha0: float, k2=None, omega0: float | None = None,
               n_harmonics: int | None = None, *, dashpot="design", speed_fluctuation=None,
               tangential_inertia: int = 0) -> Vibrations:
    """:func:`vibration` of N designs at once (Hamabe, Part II, eqs. 18-22): ``sd``'s mass and
    inertia, ``k2`` and ``dashpot`` arrays of N (or broadcasting to them), one configuration
    ``alpha0`` and speed ``omega0``. The forcing's harmonics, the responses, the swing's
    extremes and the truncation estimate are computed for all the designs together (the
    quadrature's nodes once); design ``i``'s numbers are :func:`vibration`'s for it.

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (SI inside).
    sd : SpringDesign [-]
        The designs (``m`` [kg], ``inertia`` [kg m^2]: arrays or numbers).
    alpha0 : float [rad]
        The equilibrium configuration vibrated about.
    k2 : float or array or None [1/s^2]
        Restoring stiffness per unit inertia (default from the statics).
    omega0 : float or None [rad/s]
        Mean shaft speed (default the spec's mean speed).
    n_harmonics : int or None [-]
        Highest harmonic (default the spec's ``analysis.harmonics``).
    dashpot : float or array or None or str [N m s/rad]
        ``f``; ``"design"`` (default) takes the spec's; None is undamped.
    speed_fluctuation : tuple of float or None [rad/s]
        ``(E2, F2)`` of eq. (19), overriding the spec's engine.
    tangential_inertia : int [-]
        -1, 0 or +1 (see the module docstring).

    Returns
    -------
    Vibrations [rad]
        The N designs' vibrations (``peak_to_peak_rad`` an array; ``[i]`` one result).

    References
    ----------
    [hamabe] Part II, eqs. (18)-(22), Example 2.

    Examples
    --------
    Hamabe's Example 2, case (a), undamped and without speed fluctuation, at two stiffnesses:
    the first as :func:`vibration` gives it, 8.43 deg for the first harmonic:

    >>> import govopt, govopt.examples
    >>> from govopt.analysis.statics import spring_design
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> v = vibrations(spec, spring_design(spec), spec.governor.alpha_normal, [360.0, 300.0],
    ...                np.sqrt(630.0), dashpot=None, speed_fluctuation=(0, 0))
    >>> len(v), round(float(np.degrees(v[0].amplitude(1))), 2)
    (2, 8.43)
    """
    g = spec.governor
    omega0 = spec.speed.omega_mean if omega0 is None else float(omega0)
    if k2 is None:
        k2 = restoring_k2(spec, alpha0, sd, omega0**2)
    N = spec.analysis.harmonics if n_harmonics is None else int(n_harmonics)
    m, inertia, k2, f = (np.array(v, dtype=float) for v in np.broadcast_arrays(*(
        np.ravel(np.asarray(v, dtype=float)) for v in (sd.m, sd.inertia, k2,
                                                       _dashpot(spec, dashpot)))))
    E2, F2 = _speed_fluctuation(spec, speed_fluctuation)
    p = _setup(spec, alpha0, m, inertia, omega0, tangential_inertia, (E2, F2))
    n = k2.size
    a, b = np.empty((n, N + 1)), np.empty((n, N + 1))
    resp = {k: np.empty((n, N + 1), dtype=bool if k == "resonant" else float)
            for k in ("cos", "sin", "amplitude", "phase", "detuning", "resonant")}
    tail = np.empty(n)
    counts = _tail_counts(N, k2, omega0)
    for K in np.unique(counts):  # the explicit tail's length: one group unless k^2 is large
        rows = np.nonzero(counts == K)[0]
        K = int(K)
        ak, bk = _harmonics(spec, {k: v[rows] if k in ("lever", "euler") else v
                                   for k, v in p.items()}, K)
        r = harmonic_response(ak, bk, k2[rows], inertia[rows], omega0, f[rows])
        a[rows], b[rows] = ak[:, :N + 1], bk[:, :N + 1]
        for k in resp:
            resp[k][rows] = r[k][:, :N + 1]
        tail[rows] = (np.sum(r["amplitude"][:, N + 1:], axis=-1)
                      + _asymptotic_tail(spec, p, K, k2[rows], inertia[rows]))
    p2p = np.full(n, math.inf)
    extrema = np.full((n, 2), math.nan)
    finite = ~np.isinf(resp["amplitude"][:, 1:]).any(axis=1)
    if finite.any():
        p2p[finite], extrema[finite, 0], extrema[finite, 1] = _peak_to_peak_many(
            resp["cos"][finite, 1:], resp["sin"][finite, 1:])
    lever = m * g.a * g.rho
    ratio = np.abs(inertia - lever * math.cos(alpha0)) / (lever * math.sin(alpha0))
    return Vibrations(alpha0=float(alpha0), delta=float(p["delta"]), omega0=omega0,
                      n_harmonics=N, speed_fluctuation=(E2, F2),
                      tangential_inertia=tangential_inertia, q=g.q, k2=k2, inertia=inertia,
                      dashpot=f, ratio=ratio, a=a, b=b, response=resp, peak_to_peak_rad=p2p,
                      extrema=extrema, tail=tail)


# ---------------------------------------------------------------------------------------------
# Vectorised measures for the optimiser
# ---------------------------------------------------------------------------------------------

def first_harmonic_amplitude(spec: Spec, alpha0, k2, inertia, dashpot=None, omega0=None, *,
                             speed_fluctuation=None):
    """Amplitude [rad] of the first harmonic of ``xi``, vectorised over designs/configurations
    (Hamabe, Part II, eq. 22 and Example 2).

    Hamabe, eq. (22) / Example 2: ``N_1 / (k^2 - omega0^2)``, dominated by ``B1 / (I (omega0^2 -
    k^2))``, here with the dash-pot (``dashpot`` = ``f``, None = undamped). The first harmonic
    of ``G`` comes only from the first harmonic of the load terms (``(q/2)[L_c cos(theta) + L_s
    sin(theta)]``, ``L_s = P3 + P4``, ``L_c = 0`` vertical; ``L_s = P3``, ``L_c = -P4``
    horizontal) phase-modulated by eq. (19), ``theta = tau + beta sin(2 tau - psi)``; by
    Jacobi-Anger, exactly::

        sin(theta)|_1 = (J0(beta) + J1(beta) cos psi) sin tau - J1(beta) sin psi cos tau
        cos(theta)|_1 = (J0(beta) - J1(beta) cos psi) cos tau - J1(beta) sin psi sin tau

    (``beta cos psi = E2 / 2 omega0``, ``beta sin psi = F2 / 2 omega0``; first order: the
    paper's ``(1 + E2/4 omega0) B1`` and ``(F2/4 omega0) B1``). All even-order terms (inertia,
    friction, centrifugal, speed) stay even under the modulation. Undamped exact resonance
    gives ``inf``. The Bessel form is govopt's; the paper keeps first order.

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor, valve gear, speed, engine and analysis;
        SI inside).
    alpha0 : float or array [rad]
        The equilibrium configuration vibrated about.
    k2 : float or array [1/s^2]
        Restoring stiffness per unit inertia, ``k^2`` (eq. 18).
    inertia : float or array [kg m^2]
        The pendulum's moment of inertia about its fulcrum.
    dashpot : float or array or None [N m s/rad]
        Dash-pot coefficient ``f`` (None: undamped, the paper's Part II).
    omega0 : float or array or None [rad/s]
        Mean shaft speed (default the spec's mean speed).
    speed_fluctuation : tuple of float or None [rad/s]
        ``(E2, F2)`` of eq. (19), overriding the spec's engine.

    Returns
    -------
    float or array [rad]
        The first harmonic's amplitude.

    References
    ----------
    [hamabe] Part II, eqs. (19), (22), Example 2.

    Examples
    --------
    Hamabe's Example 2, case (a), with the paper's inputs: ``k^2 = 360``, ``omega0^2 = 630``,
    ``I = rho^2 m = 0.1728`` kg m^2 (12 kgf at 12 cm), no speed fluctuation:

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> alpha_n, w0 = spec.governor.alpha_normal, np.sqrt(630.0)

    The paper prints 8.45 deg for the first harmonic, ``B1 / (I (omega0^2 - k^2))`` with
    ``B1 = (q/2)(P3 + P4) = 70`` kgf cm; its inputs give 8.43 (the paper's k^2 is rounded):

    >>> amp = first_harmonic_amplitude(spec, alpha_n, 360.0, 0.1728, omega0=w0)
    >>> round(float(np.degrees(amp)), 2)
    8.43
    """
    vg, q = spec.governor.valve_gear, spec.governor.q
    omega0 = spec.speed.omega_mean if omega0 is None else omega0
    E2, F2 = _speed_fluctuation(spec, speed_fluctuation)
    k2, inertia, omega0, f, alpha0 = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (k2, inertia, omega0, _f(dashpot), alpha0)))
    eE, eF = E2 / (2.0 * omega0), F2 / (2.0 * omega0)
    beta = np.hypot(eE, eF)
    from scipy import special  # imported when used (docs/decisions.md)

    J0 = special.j0(beta)
    J1_over_beta = np.where(beta > 0, special.j1(beta) / np.where(beta > 0, beta, 1.0), 0.5)
    J1c, J1s = J1_over_beta * eE, J1_over_beta * eF  # J1 cos psi, J1 sin psi
    if vg.engine == "vertical":
        Ls, Lc = vg.steam_load + vg.weight, 0.0
    else:
        Ls, Lc = vg.steam_load, -vg.weight
    a1 = -0.5 * q * (Ls * (-J1s) + Lc * (J0 - J1c))
    b1 = -0.5 * q * (Ls * (J0 + J1c) + Lc * (-J1s))
    r = harmonic_response(a1[..., None], b1[..., None], k2, inertia, omega0, f, orders=[1])
    return r["amplitude"][..., 0]


def peak_amplitude_bound(spec: Spec, alpha0, k2, inertia, m, dashpot=None, omega0=None,
                         n_harmonics: int | None = None, *, include_tail: bool = True,
                         speed_fluctuation=None, tangential_inertia: int = 0):
    """Sum of the harmonic amplitudes ``sum_n |xi_n|`` [rad] (Hamabe, Part II, eq. 22 summed):
    an upper bound of the half peak-to-peak (indeed of ``max |xi - mean|``) of the steady
    vibration, vectorised over designs (``alpha0, k2, inertia, m, dashpot, omega0`` broadcast).

    Orders ``1..N`` (default ``spec.analysis.harmonics``); with ``include_tail`` the left-out
    orders are added as in :func:`vibration`, so the bound holds for the complete response.
    ``inf`` at an undamped exact resonance; cost ``O(designs * N^2)``. The bound is govopt's.

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor, valve gear, speed, engine and analysis;
        SI inside).
    alpha0 : float or array [rad]
        The equilibrium configuration vibrated about.
    k2 : float or array [1/s^2]
        Restoring stiffness per unit inertia, ``k^2`` (eq. 18).
    inertia : float or array [kg m^2]
        The pendulum's moment of inertia about its fulcrum.
    m : float or array [kg]
        Mass of one pendulum.
    dashpot : float or array or None [N m s/rad]
        Dash-pot coefficient ``f`` (None: undamped, the paper's Part II).
    omega0 : float or array or None [rad/s]
        Mean shaft speed (default the spec's mean speed).
    n_harmonics : int or None [-]
        Highest harmonic (default the spec's ``analysis.harmonics``).
    include_tail : bool [-]
        Add the left-out orders' estimate.
    speed_fluctuation : tuple of float or None [rad/s]
        ``(E2, F2)`` of eq. (19), overriding the spec's engine.
    tangential_inertia : int [-]
        -1, 0 or +1: the pendulum's tangential inertia left out (0) or taken
        with its centre of gravity trailing (-1) or leading (+1).

    Returns
    -------
    float or array [rad]
        The bound on ``max |xi - mean|``.

    References
    ----------
    [hamabe] Part II, eq. (22) and Example 2.

    Examples
    --------
    Hamabe's Example 2, case (a), with the paper's inputs: ``k^2 = 360``, ``omega0^2 = 630``,
    ``I = rho^2 m = 0.1728`` kg m^2 (12 kgf at 12 cm), no speed fluctuation:

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> alpha_n, w0 = spec.governor.alpha_normal, np.sqrt(630.0)

    The bound lies above the first harmonic's 8.43 deg and above half the actual peak-to-peak
    (8.46 deg, :func:`vibration`):

    >>> bound = peak_amplitude_bound(spec, alpha_n, 360.0, 0.1728, 12.0, omega0=w0,
    ...                              speed_fluctuation=(0, 0))
    >>> round(float(np.degrees(bound)), 2)
    9.03
    """
    N = spec.analysis.harmonics if n_harmonics is None else int(n_harmonics)
    omega0 = spec.speed.omega_mean if omega0 is None else omega0
    given = [np.asarray(v, dtype=float) for v in (k2, inertia, m, _f(dashpot), omega0, alpha0)]
    k2, inertia, m, f, omega0, alpha0 = np.broadcast_arrays(*given)
    K = _tail_count(N, k2, omega0) if include_tail else N
    # the forcing involves neither the spring nor the dash-pot: its harmonics once per (alpha0,
    # m, inertia, omega0) given, spread over the stiffnesses and dash-pots (the same numbers)
    a, b = forcing_harmonics(spec, given[5], given[2], given[1], given[4], K,
                             speed_fluctuation=speed_fluctuation,
                             tangential_inertia=tangential_inertia)
    a, b = (np.broadcast_to(x, k2.shape + x.shape[-1:]) for x in (a, b))
    amp = harmonic_response(a, b, k2, inertia, omega0, f)["amplitude"]
    total = np.sum(amp[..., 1:], axis=-1)
    if include_tail:
        p = _setup(spec, alpha0, m, inertia, omega0, tangential_inertia, speed_fluctuation)
        total = total + _asymptotic_tail(spec, p, K, k2, inertia)
    return total
