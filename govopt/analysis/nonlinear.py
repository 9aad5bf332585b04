"""Nonlinear reference for a load change: the full pendulum equation coupled to the flywheel.

Hamabe linearises (Part III, eqs. 23-28): ``sin xi = xi``, ``cos xi = 1``, and drops powers of
``xi`` and ``eta`` above the first. This module keeps everything::

    I alpha'' + f alpha' = M_z(alpha, omega) - M_f(alpha) - M_r0(alpha, omega)
    I_fw omega' = (dT/dalpha) (alpha - alpha0)

* ``M_z = omega^2 m a rho sin(alpha)`` (eq. 1), ``M_f`` the spring moment with the spec's
  geometry (exact eq. 2 by default, the series eq. 3 for the paper's model), ``M_r0`` the valve
  gear's mean reaction (eq. 11, shaft.reaction) with its inertia part at the local or
  the mean speed as the spec says. With ``reaction_slope = false`` the reaction is frozen at its
  value in the new configuration ``alpha0``: Hamabe's own assumption in Part III ("put A0 in place
  of M_r ... constant for all configurations"), which is what leaving ``dM_r0/dalpha`` out of
  ``k^2`` linearises.
* The engine torque is taken linear in ``alpha`` about the new equilibrium, where it balances the
  new load: ``T - T_load = (dT/dalpha)(alpha - alpha0)``. Hamabe notes the T-curve (Fig. 10) is
  very nearly straight, and only ``dT/dalpha`` is given, so this is the engine model of the
  linear theory; the nonlinearity studied here is the governor's.
* Start at the old equilibrium: ``alpha(0) = alpha1``, ``alpha'(0) = 0``,
  ``omega(0) = omega1 (1 + eps)`` with ``omega1`` from the characteristic curve (eq. 12).
  The end state, if the motion is stable, is ``(alpha0, omega0)`` from the same curve.

For any governor type the same holds on the seam (:mod:`govopt.governors.base`): the net
generalised force ``omega^2 jp - kappa (A - B l0) - (cf + omega^2 ci)`` and the engine's torque
linear in the regulating member's travel. The generalised inertia is taken at the new
equilibrium (exact for the shaft governor, whose ``I = rho^2 m`` is constant; for ball governors
``I(x)`` and the ``I'(x) x'^2 / 2`` term it implies are second order in the load change, like
the terms the linear model drops).

Integrated with ``scipy.integrate.solve_ivp`` (DOP853, rtol 1e-10, atol 1e-12 by default).
:func:`linearisation_error` compares with the exact solution of the linear model (eq. 28, by
``expm``; :func:`govopt.analysis.friction.linear_response`). Its error is second order in the
load change (the first neglected terms are ``xi^2``, ``xi eta`` and ``eta^2``), so relative to
``|xi0|`` it grows linearly with the load change -- except with ``valve_table = "linear"``
(the paper's interpolation), where ``M_r0`` has a kink at each table row; if ``alpha0`` is a row
(as in Example 3) the two sides have different slopes and shaft.reaction_slope takes
their mean, which leaves a first-order error floor proportional to the jump in slope. The
default PCHIP table is C^1, so there is no floor.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..inputs import LoadChange, Spec
from . import statics
from .friction import LoadChangeModel, linear_response, load_change_model

__all__ = ["NonlinearResult", "linearisation_error", "net_moment", "nonlinear_load_change"]


def net_moment(spec: Spec, sd: statics.SpringDesign, alpha, omega, alpha_frozen=None):
    """``M_z - M_f - M_r0`` on one pendulum at ``(alpha, omega)`` (eqs. 1, 2/3, 11, 12), N m;
    for any type on the seam ``omega^2 jp - kappa (A - B l0) - (cf + omega^2 ci)``.

    ``alpha_frozen``: evaluate the dead loads (the valve gear's reaction) there instead of at
    ``alpha`` (the paper's constant-reaction assumption).

    Parameters
    ----------
    spec : Spec [-]
        A shaft governor's (or any type's) spec, with its engine and load change(s).
    sd : SpringDesign [-]
        The spring and pendulum (:func:`govopt.analysis.statics.spring_design`).
    alpha : float or array [rad]
        Pendulum angle (the regulating member's coordinate for other types).
    omega : float or array [rad/s]
        Shaft speed.
    alpha_frozen : float [rad], optional
        Where the dead loads are taken instead of at ``alpha``.

    Returns
    -------
    float or ndarray [N m]
        Net moment on one pendulum (generalised force for other types).

    References
    ----------
    [hamabe] eqs. (1), (2)/(3), (11), (12).

    Examples
    --------
    Example 1, case a (``specs/hamabe-a.toml``) at Example 3's new equilibrium, 64 deg 40', and
    its equilibrium speed from eq. (12): no net moment (to rounding); 1 % faster, the
    centrifugal moment, which grows as ``omega^2``, wins.

    >>> import math
    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml")
    >>> sd = statics.spring_design(spec)
    >>> alpha0 = math.radians(64 + 40 / 60)
    >>> omega0 = math.sqrt(statics.omega_squared(spec, alpha0, sd.m, sd.kappa, sd.l0))
    >>> abs(float(net_moment(spec, sd, alpha0, omega0))) < 1e-9
    True
    >>> round(float(net_moment(spec, sd, alpha0, 1.01 * omega0)), 2)
    2.94
    """
    t = statics.terms(spec, alpha, sd.m, sd.central)
    dead = t if alpha_frozen is None else statics.terms(spec, alpha_frozen, sd.m, sd.central)
    return omega**2 * t.jp - sd.kappa * (t.A - t.B * sd.l0) - (dead.cf + omega**2 * dead.ci)


@dataclass(frozen=True)
class NonlinearResult:
    """Nonlinear load change (SI): ``alpha(t)``, ``alpha'(t)``, ``omega(t)`` at times ``t``."""

    t: np.ndarray
    alpha: np.ndarray
    alpha_dot: np.ndarray
    omega: np.ndarray
    model: LoadChangeModel  # the linear model of the same load change (alpha0, omega0, ...)
    nfev: int

    @property
    def xi(self) -> np.ndarray:
        """``alpha - alpha0``."""
        return self.alpha - self.model.alpha0

    @property
    def eta(self) -> np.ndarray:
        """``omega - omega0``."""
        return self.omega - self.model.omega0

    def to_dict(self) -> dict:
        return {"model": "full pendulum equation + linear engine torque, solve_ivp",
                "linear_model": self.model.to_dict(), "t_s": self.t.tolist(),
                "xi_rad": self.xi.tolist(), "xi_dot_rad_per_s": self.alpha_dot.tolist(),
                "omega_rad_per_s": self.omega.tolist(), "nfev": self.nfev}


def _default_times(m: LoadChangeModel, points: int = 2001) -> np.ndarray:
    A = np.array([[0.0, 1.0, 0.0], [-m.k2, -m.f / m.I, m.C / m.I], [-m.R, 0.0, 0.0]])
    lam = np.linalg.eigvals(A)
    slow = float(np.min(np.abs(lam.real[lam.real != 0]))) if np.any(lam.real != 0) else 1.0
    return np.linspace(0.0, 12.0 / slow, points)


def nonlinear_load_change(spec: Spec, sd: statics.SpringDesign | None = None,
                          load_change: LoadChange | None = None, t=None, *,
                          dashpot: float | None = None, method: str = "DOP853",
                          rtol: float = 1e-10, atol: float = 1e-12) -> NonlinearResult:
    """Integrate the full equations of a load change (see the module docstring).

    ``t``: output times (default: 12 time constants of the slowest linear mode, 2001 points).
    ``dashpot`` defaults to the design's (0 when absent). Friction is not modelled here.

    Parameters
    ----------
    spec : Spec [-]
        A shaft governor's (or any type's) spec, with its engine and load change(s).
    sd : SpringDesign [-]
        The spring and pendulum (:func:`govopt.analysis.statics.spring_design`); default: the
        spec's.
    load_change : LoadChange [-]
        From ``alpha1`` to ``alpha0`` (rad); default: the spec's first.
    t : array [s]
        Output times.
    dashpot : float [N m s/rad]
        Dash-pot coefficient ``f`` (generalised for other types).
    method : str [-]
        ``scipy.integrate.solve_ivp``'s method (dimensionless name).
    rtol : float [-]
        Relative tolerance of the integration.
    atol : float [rad]
        Absolute tolerance of the integration (of each state's own unit).

    Returns
    -------
    NonlinearResult [-]
        ``alpha`` [rad], ``alpha'`` [rad/s], ``omega`` [rad/s] at ``t`` [s].

    References
    ----------
    [hamabe] Part III, eqs. (23)-(28) before linearising, with eqs. (1), (2), (11), (12); the
    nonlinear integration is govopt's own.

    Examples
    --------
    Example 3's unloading of case a, 57 deg 20' to 64 deg 40' (``specs/hamabe-a.toml``): the
    paper prints xi0 = -0.128 rad, matched to rounding; after 3 s the pendulum is about
    0.003 rad short of its new configuration and has not passed it (no over-regulation, as the
    paper finds).

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> r = nonlinear_load_change(load_spec(SPECS / "hamabe-a.toml"), t=np.linspace(0, 3, 301))
    >>> round(float(r.xi[0]), 3), round(float(r.xi[-1]), 4), bool((r.xi < 0).all())
    (-0.128, -0.003, True)
    """
    from scipy.integrate import solve_ivp  # imported when used (docs/decisions.md)

    sd = sd or statics.spring_design(spec)
    m = load_change_model(spec, sd, load_change, dashpot=dashpot, friction_moment=0.0)
    t = _default_times(m) if t is None else np.asarray(t, dtype=float)
    frozen = None if spec.analysis.reaction_slope else m.alpha0
    eng = spec.engine
    I, f, a0 = m.I, m.f, m.alpha0
    Tslope_over_Ifw = -m.R  # dT/dx / I_fw (the torque follows the member's travel, eq. 27)

    def rhs(_, y):
        alpha, v, omega = y
        acc = (float(net_moment(spec, sd, alpha, omega, frozen)) - f * v) / I
        return (v, acc, Tslope_over_Ifw * (alpha - a0))

    y0 = (m.alpha1, 0.0, m.omega1 * (1.0 + eng.insensibility))
    sol = solve_ivp(rhs, (float(t[0]), float(t[-1])), y0, method=method, t_eval=t, rtol=rtol,
                    atol=atol, dense_output=False)
    if not sol.success:
        raise RuntimeError(f"nonlinear load change: solve_ivp failed: {sol.message}")
    return NonlinearResult(t=sol.t, alpha=sol.y[0], alpha_dot=sol.y[1], omega=sol.y[2],
                           model=m, nfev=int(sol.nfev))


def linearisation_error(spec: Spec, sd: statics.SpringDesign | None = None,
                        load_change: LoadChange | None = None, t=None, **kwargs) -> dict:
    """Compare the nonlinear reference with the linear model's ``xi(t)`` (eq. 28, exact).

    Both start from the same state; the linear model is :func:`load_change_model` (the exact
    linearisation of :func:`nonlinear_load_change` about ``(alpha0, omega0)``). Returns SI:
    ``xi0``, the largest ``|xi_nonlinear - xi_linear|`` over ``t`` (absolute and relative to
    ``|xi0|``), the time it occurs, the largest speed error difference (absolute, and relative to
    the largest ``|eta|`` of the linear solution) and the nonlinear final state.

    Parameters
    ----------
    spec : Spec [-]
        A shaft governor's (or any type's) spec, with its engine and load change(s).
    sd : SpringDesign [-]
        The spring and pendulum (:func:`govopt.analysis.statics.spring_design`); default: the
        spec's.
    load_change : LoadChange [-]
        From ``alpha1`` to ``alpha0`` (rad); default: the spec's first.
    t : array [s]
        Times compared.
    **kwargs : dict [-]
        Passed to :func:`nonlinear_load_change` (``dashpot`` [N m s/rad], tolerances).

    Returns
    -------
    dict [-]
        Keys named with their SI unit (``max_abs_error_rad``, ``t_max_error_s``, ...).

    References
    ----------
    [hamabe] Part III, eqs. (23)-(28) (the linearisation being checked).

    Examples
    --------
    Example 3's unloading of case a, 7 deg 20' (``specs/hamabe-a.toml``, exact geometry and
    the smooth valve-gear table): the linear model is within a quarter of a percent of
    ``|xi0|`` over 3 s; the error is second order in the load change.

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> e = linearisation_error(load_spec(SPECS / "hamabe-a.toml"), t=np.linspace(0, 3, 301))
    >>> f"{e['max_rel_error']:.2g}", round(e["t_max_error_s"], 2)
    ('0.0024', 0.09)
    """
    nl = nonlinear_load_change(spec, sd, load_change, t, **kwargs)
    m = nl.model
    lin = linear_response(m.I, m.f, m.k2, m.C, m.R, m.xi0, m.eta0, nl.t)
    dxi = nl.xi - lin[:, 0]
    deta = nl.eta - lin[:, 2]
    k = int(np.argmax(np.abs(dxi)))
    eta_scale = float(np.max(np.abs(lin[:, 2]))) or 1.0
    return {
        "load_change_rad": m.alpha0 - m.alpha1, "xi0_rad": m.xi0, "eta0_rad_per_s": m.eta0,
        "max_abs_error_rad": float(abs(dxi[k])),
        "max_rel_error": float(abs(dxi[k]) / abs(m.xi0)) if m.xi0 else math.nan,
        "t_max_error_s": float(nl.t[k]),
        "max_abs_speed_error_rad_per_s": float(np.max(np.abs(deta))),
        "max_rel_speed_error": float(np.max(np.abs(deta)) / eta_scale),
        "final_xi_rad": float(nl.xi[-1]), "final_eta_rad_per_s": float(nl.eta[-1]),
        "t_end_s": float(nl.t[-1]), "nfev": nl.nfev,
    }
