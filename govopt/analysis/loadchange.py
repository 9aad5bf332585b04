"""The load-change transient of one design (Hamabe, Part III, eqs. 27-32) from the statics.

Builds eq. (28)'s coefficients and initial conditions for a load change ``alpha1 -> alpha0`` from
the characteristic curve and the engine data, and analyses the response with the robust solver
of :mod:`govopt.analysis.transient_events`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..governors.base import KEY_UNITS
from ..inputs import LoadChange, Spec
from ..jsonable import number
from . import statics, vyshnegradsky
from .over_regulation import over_regulates
from .transient import transient
from .transient_cubic import hamabe_initial_conditions
from .transient_events import analyse_many


def speed_lever(spec: Spec, alpha0, m, central=None):
    """``(d/domega)(net generalised force) / (2 omega) = jp - ci`` at configuration ``alpha0``:
    the lever through which a speed error moves the governor (Hamabe eq. 24 has
    ``m a rho sin(alpha0)``). When the valve gear's inertia reactions follow the local speed
    (``reaction_speed="local"``) they take ``C_i(alpha0)`` off it, which keeps eq. (28) the exact
    linearisation of the full equations; with ``"mean"`` it is the paper's.

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec (its type, engine and load changes).
    alpha0 : float or array [rad]
        The new equilibrium (m for a length coordinate).
    m : float [kg]
        Mass of one flying mass (the pendulum).
    central : float [kg], optional
        Central (sleeve) load of a loaded type.

    Returns
    -------
    float or ndarray [kg m^2]
        ``jp - ci`` (kg m for a length coordinate).

    References
    ----------
    [hamabe] eq. (24).

    Examples
    --------
    Example 1, case a, with the paper's mean-speed reaction at Example 3's 64 deg 40': exactly
    Hamabe's ``m a rho sin(alpha0)`` = 12 kg x 0.18 m x 0.12 m x sin(64 deg 40').

    >>> import math
    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> alpha0 = math.radians(64 + 40 / 60)
    >>> round(float(speed_lever(spec, alpha0, 12.0)), 6)
    0.234274
    >>> round(12 * 0.18 * 0.12 * math.sin(alpha0), 6)
    0.234274
    """
    return statics.terms(spec, alpha0, m, central).lever


def torque_ratio(spec: Spec, x0):
    """``R = -(dT/dx) / I_fw = -(dT/ds) s'(x0) / I_fw`` (Hamabe eq. 27), 1/s^2 per unit ``x``:
    the engine's torque follows the regulating member's travel ``s(x)``.

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec (its type, engine and load changes).
    x0 : float [rad]
        Configuration at which the travel's slope ``s'(x0)`` is taken (m for a length).

    Returns
    -------
    float [1/s^2]
        ``R`` (1/(m s^2) for a length coordinate).

    References
    ----------
    [hamabe] eq. (27).

    Examples
    --------
    Example 3: ``dT/dalpha = -300 kgf m/rad``, ``I_fw = 43 kgf m s^2``, so the paper's
    ``R = 300/43`` = 6.977 1/s^2 (the kgf cancels; the shaft governor's travel is its angle).

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> round(torque_ratio(load_spec(SPECS / "hamabe-a.toml"), 1.0), 4), round(300 / 43, 4)
    (6.9767, 6.9767)
    """
    eng = spec.engine
    return -eng.torque_slope * float(spec.governor.travel_slope(x0)) / eng.flywheel_inertia


@dataclass(frozen=True)
class LoadChangeModel:
    """Coefficients and initial state of Hamabe's linear load-change model (SI).

    ``I xi'' + f xi' + I k^2 xi (+ M0 sign xi') = C eta``, ``eta' = -R xi`` (eqs. 24, 26, 27,
    42); ``a0 = I``, ``3 a1 = f``, ``3 a2 = I k^2``, ``a3 = C R`` (eq. 28).
    """

    I: float  # generalised inertia of the moving parts about the coordinate x, kg m^2
    f: float  # dash-pot coefficient, N m s
    k2: float  # restoring stiffness k^2 at alpha0, 1/s^2
    C: float  # d(net moment)/d omega at (alpha0, omega0), N m s
    R: float  # -(dT/dalpha)/I_fw, 1/s^2
    M0: float  # friction moment at the fulcrum, N m
    xi0: float  # alpha1 - alpha0, rad
    eta0: float  # omega1 (1 + eps) - omega0, rad/s
    alpha0: float = math.nan  # new equilibrium, rad
    alpha1: float = math.nan  # old equilibrium, rad
    omega0: float = math.nan  # equilibrium speed at alpha0, rad/s
    omega1: float = math.nan  # equilibrium speed at alpha1, rad/s
    #: the JSON keys' units at the governor's coordinate (:meth:`Governor.key_units`; above,
    #: the shaft's: for a length coordinate kg, N s/m, N s, rad/(m s^2), N, m)
    units: dict = field(default_factory=lambda: dict(KEY_UNITS["angle"]), repr=False,
                        compare=False)

    @property
    def cubic(self) -> tuple[float, float, float, float]:
        """``(a0, a1, a2, a3)`` of eq. (28)."""
        return self.I, self.f / 3.0, self.I * self.k2 / 3.0, self.C * self.R

    @property
    def net0(self) -> float:
        """Initial net generalised force ``C eta0 - I k^2 xi0`` on the resting flying masses
        (N m about an angle)."""
        return self.C * self.eta0 - self.I * self.k2 * self.xi0

    def to_dict(self) -> dict:
        a0, a1, a2, a3 = self.cubic
        u = self.units
        return {f"I_{u['inertia']}": self.I, f"f_{u['damping']}": self.f, "k2_per_s2": self.k2,
                f"C_{u['lever']}": self.C, f"R_{u['engine']}": self.R,
                f"M0_{u['force']}": self.M0, f"xi0_{u['x']}": self.xi0,
                "eta0_rad_per_s": self.eta0, f"alpha0_{u['x']}": number(self.alpha0),
                f"alpha1_{u['x']}": number(self.alpha1), "omega0_rad_per_s": number(self.omega0),
                "omega1_rad_per_s": number(self.omega1), "a0": a0, "a1": a1, "a2": a2, "a3": a3,
                f"net0_{u['force']}": self.net0}


def load_change_model(spec: Spec, sd: statics.SpringDesign | None = None,
                      load_change: LoadChange | None = None, *, dashpot: float | None = None,
                      friction_moment: float | None = None) -> LoadChangeModel:
    """Hamabe's linear model (eqs. 24-28, 42) of ``load_change`` for one design of ``spec``.

    ``k^2`` is :func:`statics.restoring_k2` at ``alpha0`` with ``omega0^2`` from the
    characteristic curve (:func:`statics.omega_squared`); ``C = 2 omega0 m a rho sin(alpha0)``
    (``dM_z/domega``), less ``2 omega0 C_i(alpha0)`` when the spec takes the valve gear's inertia
    reactions at the local speed (``reaction_speed="local"``), so that the model is the exact
    linearisation of :mod:`govopt.analysis.nonlinear`; with ``"mean"`` (the paper) it is
    Hamabe's ``a3 / R``. ``R = -(dT/dalpha) / I_fw`` (eq. 27). Initial state: ``xi0 = alpha1 -
    alpha0`` and ``eta0 = omega1 (1 + eps) - omega0`` with the insensibility ``eps``. ``dashpot``
    and ``friction_moment`` default to the design's (0 when absent).

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec (its type, engine and load changes).
    sd : SpringDesign [-]
        The spring and flying masses; default: the spec's design.
    load_change : LoadChange [-]
        From ``alpha1`` to ``alpha0`` (rad, or m); default: the spec's first.
    dashpot : float [N m s/rad]
        Dash-pot coefficient ``f`` (N s/m for a length coordinate).
    friction_moment : float [N m]
        Friction moment ``M0`` at the fulcrum (N for a length coordinate).

    Returns
    -------
    LoadChangeModel [-]
        ``I`` [kg m^2], ``f``, ``k2`` [1/s^2], ``C`` [N m s], ``R`` [1/s^2], ``M0``, ``xi0``
        [rad], ``eta0`` [rad/s] and the two equilibria (SI at the type's coordinate).

    References
    ----------
    [hamabe] Part III, eqs. (24)-(28), (42).

    Examples
    --------
    Example 3, case a, with the paper's model: it states ``k^2 = 360`` (Example 2's table) and
    R = 300/43; the spec's series spring gives 362, within 1 % of the paper's.

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> m = load_change_model(spec)
    >>> round(m.k2), round(m.R, 3), round(m.xi0, 4)
    (362, 6.977, -0.128)
    """
    if spec.engine is None:
        raise ValueError("a load change needs [engine] data")
    sd = sd or statics.spring_design(spec)
    if load_change is None:
        if not spec.load_changes:
            raise ValueError("no [[load_change]] given")
        load_change = spec.load_changes[0]
    design = spec.design
    if dashpot is None:
        dashpot = (design.dashpot if design is not None else None) or 0.0
    if friction_moment is None:
        # the type's friction band at the new equilibrium (Hamabe's M_0; sleeve friction R |s'|)
        friction_moment = float(spec.governor.friction(load_change.alpha_to, design))
    eng = spec.engine
    a0, a1 = load_change.alpha_to, load_change.alpha_from
    w0 = math.sqrt(float(statics.omega_squared(spec, a0, sd.m, sd.kappa, sd.l0, sd.central)))
    w1 = math.sqrt(float(statics.omega_squared(spec, a1, sd.m, sd.kappa, sd.l0, sd.central)))
    k2 = float(statics.restoring_k2(spec, a0, sd, w0**2))
    return LoadChangeModel(
        I=float(statics.inertia(spec, sd, a0)), f=float(dashpot), k2=k2,
        C=2.0 * w0 * float(speed_lever(spec, a0, sd.m, sd.central)),
        R=torque_ratio(spec, a0), M0=float(friction_moment),
        xi0=a1 - a0, eta0=w1 * (1.0 + eng.insensibility) - w0,
        alpha0=a0, alpha1=a1, omega0=w0, omega1=w1, units=spec.governor.key_units())


def coefficients(spec: Spec, sd: statics.SpringDesign, lc: LoadChange, f: float):
    """``(a0, a1, a2, a3)``, the initial state ``(xi, xi', xi'')(0)`` of eq. (28), and k^2.

    ``a0 = I``, ``3 a1 = f``, ``3 a2 = I k^2(alpha0)``, ``a3 = C R`` with
    ``C = 2 omega0 m a rho sin(alpha0)`` (see :func:`speed_lever`) and ``R = -(dT/dalpha) / I_fw``
    (eq. 27); ``xi(0) = alpha1 - alpha0``, ``xi'(0) = 0``, ``a0 xi''(0) = (a3 / R) eta0 -
    3 a2 xi(0)`` with ``eta0 = omega1 (1 + eps) - omega0`` (Hamabe, Part III).

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec (its type, engine and load changes).
    sd : SpringDesign [-]
        The spring and flying masses (:func:`govopt.analysis.statics.spring_design`).
    lc : LoadChange [-]
        From ``alpha1`` to ``alpha0`` (rad or m, the type's coordinate).
    f : float [N m s/rad]
        Dash-pot coefficient (N s/m for a length coordinate), ``a1 = f/3``.

    Returns
    -------
    tuple [-]
        ``(a0, a1, a2, a3)`` [kg m^2 s^-i], ``(xi, xi', xi'')(0)`` [rad, rad/s, rad/s^2] and
        ``k^2`` [1/s^2] (for a length coordinate, m and kg in place of rad and kg m^2).

    References
    ----------
    [hamabe] Part III, eqs. (27)-(28) and the initial conditions before eq. (38).

    Examples
    --------
    Example 3, case a, with the paper's model and its dash-pot ``a1 = 24 kgf cm s``: in the
    paper's kgf-cm-s units (1 kgf cm = 0.0980665 N m) it prints a0 = 1.76, a1 = 24,
    a2 = a0 k^2 / 3 = 211.2 (k^2 = 360) and a3 = 840 (slide-rule values; the spec's
    series spring gives k^2 = 362).

    >>> from govopt.analysis import statics
    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> sd = statics.spring_design(spec)
    >>> a, x, k2 = coefficients(spec, sd, spec.load_changes[0], 3 * 24 * 0.0980665)
    >>> [round(c / 0.0980665, 2) for c in a]
    [1.76, 24.0, 212.74, 837.77]
    """
    model = load_change_model(spec, sd, lc, dashpot=f)
    a = model.cubic
    x = hamabe_initial_conditions(a[0], a[2], a[3], model.R, model.xi0, model.eta0)
    return tuple(float(v) for v in a), tuple(float(v) for v in x), model.k2


def coordinate_unit(gov) -> str:
    """The SI unit of a governor's configuration as JSON keys name it: ``"rad"`` for an
    angle, ``"m"`` for a length (:meth:`govopt.governors.base.Governor.key_unit`).

    The unit of Hamabe's ``xi`` ([hamabe] Part III) generalised to the type's coordinate (the
    ball governors' sleeve travel, [textbook-ch3]); a naming helper of govopt's own.

    Parameters
    ----------
    gov : Governor [-]
        A governor type (class or instance).

    Returns
    -------
    str [-]
        ``"rad"`` or ``"m"``.

    Examples
    --------
    >>> from govopt.governors.porter import PorterGovernor
    >>> from govopt.governors.shaft import ShaftGovernor
    >>> coordinate_unit(ShaftGovernor), coordinate_unit(PorterGovernor)
    ('rad', 'm')
    """
    return gov.key_unit("x")


def coefficient_keys(gov) -> tuple[str, str, str, str]:
    """JSON keys of eq. (28)'s ``a0 .. a3`` with their SI units (Hamabe Part III). With ``x``
    the configuration (unit ``u``) and ``Q`` its generalised force (N m for an angle, N for a
    length), ``a0 xi''' + 3 a1 xi'' + 3 a2 xi' + a3 xi = 0`` is in ``Q/s``: ``a0 = I`` (kg m^2
    or kg), ``a1 = f/3`` in ``Q s/u``, ``a2 = I k^2/3`` in ``Q/u``, ``a3 = C R`` in ``Q/(u s)``.

    Parameters
    ----------
    gov : Governor [-]
        A governor type (class or instance).

    Returns
    -------
    tuple of str [-]
        The four keys.

    References
    ----------
    [hamabe] Part III, eq. (28).

    Examples
    --------
    The Porter governor's coordinate is the sleeve's travel (a length, [textbook-ch3]):

    >>> from govopt.governors.porter import PorterGovernor
    >>> coefficient_keys(PorterGovernor)
    ('a0_kg', 'a1_N_s_per_m', 'a2_N_per_m', 'a3_N_per_m_s')
    """
    u = gov.key_units()
    q = f"{u['force']}_per_{u['x']}"
    return f"a0_{u['inertia']}", f"a1_{u['damping']}", f"a2_{q}", f"a3_{q}_s"


def analyse(spec: Spec, sd: statics.SpringDesign, lc: LoadChange, f: float,
            samples: int = 200) -> dict:
    """Roots, Hurwitz margin, over-regulation, settling and a response table (SI, JSON-ready).

    Every key names its SI unit, the configuration's ``u`` = ``rad`` (an angle) or ``m`` (a
    length) from the seam (:func:`coordinate_unit`): ``over_regulation_u``, ``initial_state``
    ``xi_u``, ``xi_dot_u_s``, ``xi_ddot_u_s2``, ``response`` ``xi_u``, and eq. (28)'s
    coefficients (:func:`coefficient_keys`).

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec (its type, engine and load changes).
    sd : SpringDesign [-]
        The spring and flying masses (:func:`govopt.analysis.statics.spring_design`).
    lc : LoadChange [-]
        From ``alpha1`` to ``alpha0`` (rad or m, the type's coordinate).
    f : float [N m s/rad]
        Dash-pot coefficient (N s/m for a length coordinate), ``a1 = f/3``.
    samples : int [-]
        Points of the response table (dimensionless count).

    Returns
    -------
    dict [-]
        JSON-ready; each key names its SI unit.

    References
    ----------
    [hamabe] Part III, eqs. (28), (32), (37); [vyshnegradsky] for the diagram's point.

    Examples
    --------
    Example 3, case a, with the paper's model and dash-pot: three real roots near the paper's
    -29.1, -10, -1.7 (its coefficients are rounded and its slide-rule G is 3 % off, so its slow
    roots are a few per cent off) and no over-regulation, as the paper finds.

    >>> from govopt.analysis import statics
    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> sd = statics.spring_design(spec)
    >>> d = analyse(spec, sd, spec.load_changes[0], 3 * 24 * 0.0980665)
    >>> d["kind"], [round(r, 1) for r, _ in d["roots_per_s"]], d["over_regulates"]
    ('real', [-28.9, -10.4, -1.6], False)
    """
    a, x, k2 = coefficients(spec, sd, lc, f)
    res = analyse_many(*a, *x, band=spec.analysis.settling_band)  # one design: scalars
    return summary(spec, lc, a, x, k2, res, samples)


def summary(spec: Spec, lc: LoadChange, a, x, k2: float, res, samples: int = 200) -> dict:
    """The dict of :func:`analyse` from one design's coefficients ``a`` (eq. 28), initial state
    ``x``, ``k^2`` and its :class:`~govopt.analysis.transient_events.TransientSummary` ``res``: the
    numbers the evaluator computed (:mod:`govopt.evaluator`), with the response table.

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec (its type, engine and load changes).
    lc : LoadChange [-]
        From ``alpha1`` to ``alpha0`` (rad or m, the type's coordinate).
    a : tuple of float [kg m^2 s^-i]
        ``(a0, a1, a2, a3)`` of eq. (28) (kg s^-i for a length coordinate).
    x : tuple of float [rad, rad/s, rad/s^2]
        Initial state ``(xi, xi', xi'')(0)`` (m for a length coordinate).
    k2 : float [1/s^2]
        ``k^2`` at the new equilibrium.
    res : TransientSummary [-]
        The transient's events (:func:`~govopt.analysis.transient_events.analyse_many`).
    samples : int [-]
        Points of the response table (dimensionless count).

    Returns
    -------
    dict [-]
        As :func:`analyse`.

    References
    ----------
    [hamabe] Part III, eqs. (28), (32), (37).

    Examples
    --------
    Example 3, case a, with the paper's coefficients (kgf-cm-s): the Hurwitz margin
    ``9 a1 a2 / (a0 a3) - 1`` = 29.86 by hand, no over-regulation (as the paper finds).

    >>> from govopt.analysis.transient_events import analyse_many
    >>> from govopt.analysis.transient_cubic import hamabe_initial_conditions
    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml")
    >>> a = (1.76, 24.0, 211.2, 840.0)
    >>> x = tuple(float(v) for v in hamabe_initial_conditions(1.76, 211.2, 840.0, 300 / 43,
    ...                                                         -0.128, -0.4))
    >>> d = summary(spec, spec.load_changes[0], a, x, 360.0, analyse_many(*a, *x))
    >>> round(d["hurwitz_margin"], 2), d["over_regulates"], d["stable"]
    (29.86, False, True)
    """
    u = coordinate_unit(spec.governor)
    roots = np.asarray(res.roots, dtype=complex)
    slowest = float(np.min(np.abs(roots.real)))
    horizon = res.settling_time if np.isfinite(res.settling_time) else (
        10.0 / slowest if slowest > 0 else 10.0 * 2 * np.pi / max(float(np.max(roots.imag)), 1e-9))
    t = np.linspace(0.0, 1.5 * horizon, samples)
    xi = transient(*a, *x, t)
    return {
        "name": lc.name,
        # configurations under the type's own name and unit (the shaft: alpha_from_deg ...)
        **dict(spec.governor.json_coordinate(f"{stem}_from", lc.alpha_from)
               for stem in [spec.governor.coordinate_name.split()[-1]]),
        **dict(spec.governor.json_coordinate(f"{stem}_to", lc.alpha_to)
               for stem in [spec.governor.coordinate_name.split()[-1]]),
        "coefficients": dict(zip(coefficient_keys(spec.governor), a, strict=True)),
        "initial_state": {f"xi_{u}": x[0], f"xi_dot_{u}_s": x[1], f"xi_ddot_{u}_s2": x[2]},
        "k2_rad2_s2": k2,
        "roots_per_s": [[float(r.real), float(r.imag)] for r in roots],
        "kind": str(res.kind),
        "hurwitz_margin": float(res.hurwitz_margin),
        "vyshnegradsky": vyshnegradsky.point(*a),
        "stable": bool(res.stable),
        # an unstable transient passes its equilibrium without bound
        f"over_regulation_{u}": float(res.over_regulation) if res.stable else float("inf"),
        # decided for all t >= 0 by the one rule (over_regulation.over_regulates)
        "over_regulates": bool(not res.stable
                               or over_regulates(res.over_regulation_scaled, x[0])),
        f"over_regulation_scaled_{u}": float(res.over_regulation_scaled),
        "first_arrival_time_s": float(res.first_arrival_time),
        "settling_time_s": float(res.settling_time),
        # inf with this set: a stable response whose settling the solver could not place
        # (TransientSummary.truncated), not one that never settles
        "settling_not_decided": bool(res.truncated),
        "settling_band": spec.analysis.settling_band,
        "response": {"t_s": t.tolist(), f"xi_{u}": np.asarray(xi).tolist()},
    }


def no_overregulation_window(spec: Spec, sd: statics.SpringDesign | None = None,
                             load_change: LoadChange | None = None, *, points: int = 241,
                             rtol: float = 1e-12) -> tuple[float, float] | None:
    """The dash-pot coefficients ``f`` (N m s, ``a1 = f/3``) for which ``load_change`` never
    over-regulates, at any ``t >= 0``: ``(f_lo, f_hi)``, or None if there are none.

    Hamabe, Disturbing Actions of a Shaft Governor, Part III, eqs. (28), (32): ``a0``, ``a2``,
    ``a3`` and the initial state do not depend on ``f``.  Eq. (32) needs ``f > a0 a3 / (3 a2)``; for
    large ``f`` the slow roots of ``3 a1 s^2 + 3 a2 s + a3`` form a complex pair (from ``f > 9 a2^2
    / (4 a3)``), which oscillates for ever.  ``points`` log-spaced values from the first to 100
    times the larger of these are decided with
    :func:`~govopt.analysis.over_regulation.over_regulates` (the same rule as
    :func:`govopt.evaluate` and the design search), the widest run of admissible values is taken,
    and each end is bisected on the same rule to ``rtol`` relative (``f_hi = inf`` if the run
    reaches the scan's end).  For Hamabe's cases a and d with the paper's model the ends agree with
    a 50-digit reference to ~1e-9 (tests/test_overregulation.py).

    Parameters
    ----------
    spec : Spec [-]
        The governor's spec (its type, engine and load changes).
    sd : SpringDesign [-]
        The spring and flying masses; default: the spec's design.
    load_change : LoadChange [-]
        The load change; default: the spec's first.
    points : int [-]
        Values of ``f`` scanned (dimensionless count).
    rtol : float [-]
        Relative accuracy of each end.

    Returns
    -------
    tuple of float [N m s/rad] or None
        ``(f_lo, f_hi)`` (N s/m for a length coordinate).

    References
    ----------
    [hamabe] Part III, eqs. (28), (32); the window is govopt's own construction on them.

    Examples
    --------
    Example 3, case a, with the paper's model: its dash-pot ``f = 3 a1 = 72 kgf cm s``
    (7.06 N m s) lies inside the window, as the paper's "no over-regulation" says; the lower
    end lies above the Hurwitz bound ``a0 a3 / (3 a2)``.

    >>> from govopt.examples import SPECS
    >>> from govopt.spec import load_spec
    >>> spec = load_spec(SPECS / "hamabe-a.toml").with_analysis(
    ...     geometry="series", reaction_speed="mean", reaction_slope=False)
    >>> lo, hi = no_overregulation_window(spec)
    >>> round(lo, 3), round(hi, 2), bool(lo < 72 * 0.0980665 < hi)
    (0.687, 12.38, True)
    """
    model = load_change_model(spec, sd, load_change)
    a0, _, a2, a3 = model.cubic
    x = hamabe_initial_conditions(a0, a2, a3, model.R, model.xi0, model.eta0)

    def admissible(f):
        f = np.asarray(f, dtype=float)
        s = analyse_many(a0, f / 3.0, a2, a3, *x, band=spec.analysis.settling_band)
        return s.stable & ~over_regulates(s.over_regulation_scaled, model.xi0)

    f_h = a0 * a3 / (3.0 * a2)
    f = np.geomspace(f_h, 100.0 * max(f_h, 9.0 * a2 * a2 / (4.0 * a3)), points)
    ok = admissible(f)
    if not ok.any():
        return None
    # widest run of admissible grid points
    edges = np.diff(np.concatenate([[0], ok.astype(int), [0]]))
    starts, stops = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0] - 1
    k = int(np.argmax(np.log(f[stops]) - np.log(f[starts])))
    i, j = starts[k], stops[k]
    # bisect both ends at once: lo[0] outside / hi[0] inside (lower end), reverse for the upper
    inside = np.array([f[i], f[j]])
    outside = np.array([f[i - 1] if i > 0 else f_h, f[j + 1] if j + 1 < points else np.inf])
    if not np.isfinite(outside[1]):
        inside[1] = outside[1] = np.inf  # admissible up to the scan's end: no upper end found
    while True:
        act = np.isfinite(outside) & (np.abs(outside - inside) > rtol * inside)
        if not act.any():
            break
        mid = np.sqrt(inside * np.where(act, outside, inside))
        good = admissible(mid)
        inside = np.where(act & good, mid, inside)
        outside = np.where(act & ~good, mid, outside)
    return float(inside[0]), float(inside[1])
