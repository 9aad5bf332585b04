"""Statics of every governor type on the seam (Hamabe, Part I; textbook ch. 3): the speed of
equilibrium, the spring a speed range requires, the operating band with friction, k^2. The
characteristic over the range and its stability are :mod:`govopt.analysis.characteristic`.

Pure functions of a :class:`~govopt.spec.Spec` (geometry, valve gear, fidelity) and design
arrays. Every design quantity (``m``, ``kappa``, ``l0`` ...) may be a numpy array of shape
``(N, 1)`` to evaluate N designs at once against configurations ``alpha`` of shape ``(K,)``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import DesignError
from ..inputs import Design, Spec


@dataclass(frozen=True)
class SpringDesign:
    """Flying masses and spring of one design (or many: fields may be arrays), SI."""

    m: np.ndarray | float  # flying mass (pendulum, each ball, each fly weight), kg
    inertia: np.ndarray | float  # generalised inertia at the normal configuration
    kappa: np.ndarray | float  # stiffness of the whole spring, N/m (0: no spring)
    l0: np.ndarray | float  # free length in the type's form (the shaft: half length), m
    d: np.ndarray | float = np.nan
    r: np.ndarray | float = np.nan
    n: np.ndarray | float = np.nan
    central: np.ndarray | float = 0.0  # central (sleeve) load, kg
    inertia_given: bool = True  # the inertia is the design's own, not the type's I(x)
    width: np.ndarray | float = np.nan  # a leaf spring's section, m
    thickness: np.ndarray | float = np.nan


def terms(spec: Spec, x, m, central=None):
    """The type's generalised forces at configurations ``x`` (a :class:`Terms` of the seam).

    The seam of :mod:`govopt.governors.base`: centrifugal ``omega^2 jp``, spring
    ``kappa (A - B l0)``, dead loads ``cf`` and inertia reactions ``omega^2 ci``. For the shaft
    governor ``jp = m a rho sin(alpha)`` (Hamabe eq. 1). With a spec that gives a speed, the
    "mean" fidelity options take the spec's mean speed as their reference.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its analysis options and (optionally) its speeds.
    x : array [rad] or [m]
        Configurations, in the type's coordinate (an angle or a length).
    m : float or array [kg]
        Flying mass (each pendulum, ball or fly weight).
    central : float [kg], optional
        Central (sleeve) load; None for the type's default.

    Returns
    -------
    Terms [-]
        Generalised forces in N m (angle) or N (length) per the factors above.

    References
    ----------
    [hamabe] Part I, eqs. (1), (11), (12); [textbook-ch3] section 3.3 (controlling force).

    Examples
    --------
    Hamabe's Example 1 (a) at the normal configuration: by hand
    ``m a rho sin(alpha_n) = 12 x 0.18 x 0.12 x sin(64 deg 40') = 0.23427 kg m^2``.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> round(float(terms(spec, spec.governor.alpha_normal, 12.0).jp), 5)
    0.23427
    """
    an = spec.analysis
    if spec.speed is not None and an.omega_mean != spec.speed.omega_mean:
        an = replace(an, omega_mean=spec.speed.omega_mean)  # the reference of "mean" options
    return spec.governor.terms(np.asarray(x, dtype=float), m, an, central)


def omega_squared(spec: Spec, alpha, m, kappa, l0, central=None):
    """Equilibrium speed squared at configuration ``alpha``, (rad/s)^2: the characteristic curve.

    Virtual work (:mod:`govopt.governors.base`): ``omega^2 (jp - ci) = kappa (A - B l0) + cf``.
    For the shaft governor this is Hamabe's eq. (12), ``M_f - M_z + M_r0 = 0`` with
    ``M_z = omega^2 m a rho sin(alpha)`` (eq. 1); with ``reaction_speed="mean"`` the valve gear's
    inertia reactions are taken at the mean speed as the paper does, with ``"local"`` (default) at
    the equilibrium speed itself: ``omega^2 = (M_f + C_f) / (m a rho sin(alpha) - C_i)``.

    Parameters
    ----------
    spec : Spec [-]
        The governor and its analysis options.
    alpha : array [rad] or [m]
        Configurations, in the type's coordinate.
    m : float or array [kg]
        Flying mass.
    kappa : float or array [N/m]
        Stiffness of the whole spring (0: no spring).
    l0 : float or array [m]
        Free length in the type's form (the shaft governor: half the spring's length).
    central : float [kg], optional
        Central (sleeve) load.

    Returns
    -------
    array [(rad/s)^2]
        ``omega^2`` at each configuration.

    References
    ----------
    [hamabe] Part I, eqs. (1), (2), (11), (12).

    Examples
    --------
    Hamabe's Example 1 (a), the paper's spring (d 1.7 cm, r 6 cm, 8 turns), at the outermost
    configuration: the paper's own numbers give about 711 (it prints 700, a slip); govopt takes
    omega0 = 240 rpm exactly (the paper rounds omega0^2 to 630) and the exact spring arm.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> sd = spring_design(spec)
    >>> w2 = omega_squared(spec, spec.governor.alpha_outer, sd.m, sd.kappa, sd.l0)
    >>> round(float(w2))
    712
    """
    return terms(spec, alpha, m, central).omega_squared(kappa, l0)


def required_spring_moment(spec: Spec, alpha, omega, m, central=None):
    """Spring generalised force that holds ``alpha`` in equilibrium at ``omega``: N m or N.

    ``omega^2 (jp - ci) - cf`` (Hamabe eq. 12 solved for the spring: ``M_f = M_z - M_r0``).

    Parameters
    ----------
    spec : Spec [-]
        The governor and its analysis options.
    alpha : array [rad] or [m]
        Configurations, in the type's coordinate.
    omega : float or array [rad/s]
        Shaft speed.
    m : float or array [kg]
        Flying mass.
    central : float [kg], optional
        Central (sleeve) load.

    Returns
    -------
    array [N m] or [N]
        The spring's generalised force (a moment for an angle coordinate).

    References
    ----------
    [hamabe] Part I, eqs. (1), (11), (12).

    Examples
    --------
    Hamabe's Example 1 (a) at the normal configuration and omega0 = 240 rpm: by hand
    ``M_z = 631.65 x 0.23427 = 147.98 N m`` less ``M_r0 = 4.02 N m`` (40.98 kgf cm; the paper's
    table prints 40.9), so 143.96 N m = 1468 kgf cm.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> Q = required_spring_moment(spec, spec.governor.alpha_normal, spec.speed.omega_mean, 12.0)
    >>> round(float(Q) / (KGF * CM))
    1468
    """
    t = terms(spec, alpha, m, central)
    return omega**2 * t.lever - t.cf


def free_half_length(spec: Spec, m, kappa, central=None):
    """Free length that puts the normal configuration in equilibrium at the mean speed, m.

    Hamabe, Example 1: ``F_n = M_f(alpha_n) / h_n``, ``l0 = l_n - F_n / (2 kappa)``; in general
    ``kappa (A_n - B_n l0) = Q_n`` solved for ``l0``. A :class:`DesignError` where the spec has
    no ``[speed]``.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds and analysis options.
    m : float or array [kg]
        Flying mass.
    kappa : float or array [N/m]
        Stiffness of the whole spring.
    central : float [kg], optional
        Central (sleeve) load.

    Returns
    -------
    float or array [m]
        Free length in the type's form (the shaft governor: half the spring's length).

    References
    ----------
    [hamabe] Part I, Example 1 (with eqs. 2 and 12).

    Examples
    --------
    Hamabe's Example 1 (a), the paper's spring of 64.19 kgf/cm: the free half length whose
    force at the normal configuration, ``2 kappa (l_n - l0)``, is the paper's F_n (508 kgf,
    :func:`spring_force`).

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> round(float(free_half_length(spec, 12.0, spring_design(spec).kappa)) / CM, 2)
    12.97
    """
    gov = spec.governor
    if spec.speed is None:
        raise DesignError(f"design.{gov.free_length_key}: missing, and the spec has "
                          "no [speed] to set it from equilibrium at the normal configuration")
    Q_n = required_spring_moment(spec, gov.x_normal, spec.speed.omega_mean, m, central)
    t = terms(spec, gov.x_normal, m, central)
    return (t.A - Q_n / kappa) / t.B


def spring_force(spec: Spec, x, kappa, l0):
    """Spring force ``F = kappa (A_F - B_F l0)``, N, at configurations ``x``.

    The shaft governor: ``F = 2 kappa (l - l0)`` (Hamabe eq. 2); other types their own
    :meth:`Governor.spring_force_coefficients`.

    Parameters
    ----------
    spec : Spec [-]
        The governor.
    x : array [rad] or [m]
        Configurations, in the type's coordinate.
    kappa : float or array [N/m]
        Stiffness of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.

    Returns
    -------
    array [N]
        Spring force (tension or compression as the type's spring works).

    References
    ----------
    [hamabe] Part I, eq. (2) and Example 1.

    Examples
    --------
    Hamabe's Example 1 (a) at the normal configuration: the paper prints F_n = 508 kgf; govopt's
    509 takes omega0 = 240 rpm exactly (the paper 630 (rad/s)^2) and the exact spring arm.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> sd = spring_design(spec)
    >>> round(float(spring_force(spec, spec.governor.alpha_normal, sd.kappa, sd.l0)) / KGF)
    509
    """
    A_F, B_F = spec.governor.spring_force_coefficients(np.asarray(x, dtype=float))
    return kappa * (A_F - B_F * l0)


def required_spring(spec: Spec, m, central=None):
    """Stiffness and free length that give exactly the spec's speed range.

    Hamabe, Example 1: ``F_i = M_fi / h_i``, ``F_a = M_fa / h_a``,
    ``kappa = (F_a - F_i) / (2 (l_a - l_i))``. Written as two linear equations in ``kappa`` and
    ``kappa l0`` (``Q_s = kappa (A - B l0)``), which is the paper's procedure for the exact
    geometry and its analogue for any type (the textbook's Examples 4 and 8: stiffness and
    initial compression from two speeds). No check of the result: :func:`band_spring` checks.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds (inner and outer) and analysis options.
    m : float or array [kg]
        Flying mass.
    central : float [kg], optional
        Central (sleeve) load.

    Returns
    -------
    tuple of float or array
        ``(kappa [N/m], l0 [m], F_inner [N], F_outer [N])``.

    References
    ----------
    [hamabe] Part I, Example 1; [textbook-ch3] section 3.5, Examples 4 and 8.

    Examples
    --------
    Hamabe's Example 1 (a), W = 12 kgf, irregularity 0.12, the valve gear's reactions at the
    mean speed as in the paper: the paper prints 59.7 kgf/cm from spring arms rounded to 2.5 and
    3.0 cm; the exact arms (2.548, 3.000 cm) give about 63.1 with omega0^2 = 630, and 63.3 with
    omega0 = 240 rpm exactly (631.65).

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> kappa, l0, F_i, F_a = required_spring(spec.with_analysis(reaction_speed="mean"), 12.0)
    >>> round(float(kappa) / (KGF / CM), 1), round(float(F_a) / KGF)
    (63.3, 609)
    """
    gov, sp = spec.governor, spec.speed
    M_i = required_spring_moment(spec, gov.x_inner, sp.omega_inner, m, central)
    M_a = required_spring_moment(spec, gov.x_outer, sp.omega_outer, m, central)
    t_i = terms(spec, gov.x_inner, m, central)
    t_a = terms(spec, gov.x_outer, m, central)
    det = t_a.A * t_i.B - t_i.A * t_a.B
    kappa = (M_a * t_i.B - M_i * t_a.B) / det
    kappa_l0 = (M_a * t_i.A - M_i * t_a.A) / det
    l0 = kappa_l0 / kappa
    return (kappa, l0, spring_force(spec, gov.x_inner, kappa, l0),
            spring_force(spec, gov.x_outer, kappa, l0))


#: the speed band's two requirements, one rule for every governor type (the names every path
#: reports: evaluate, bulk, the design search and studies)
BAND_INNER = "lowest speed >= speed.inner"
BAND_OUTER = "highest speed <= speed.outer"
BAND_SOURCE = ("[speed] inner/outer: the whole operating band inside the spec's, over the whole "
               "range; with friction the governor closes at omega_fall and opens at omega_rise, "
               "omega^2 = (Q_s + cf -+ F) / (jp - ci)")  # the checks add the type's friction source


def band_speeds_squared(t, kappa, l0, friction=0.0):
    """``(omega_fall^2, omega_rise^2)``, (rad/s)^2, at the configurations of the terms ``t``.

    The speeds at which the governor closes and opens against the friction band ``friction``
    there: ``omega^2 = (Q_s + cf -+ F) / (jp - ci)`` (the textbook's sleeve friction, 3.4(b);
    the friction as the type's :meth:`Governor.friction` gives it, a generalised force). Arrays
    broadcast over designs.

    Parameters
    ----------
    t : Terms [-]
        The type's generalised forces (:func:`terms`; configurations on the last axis).
    kappa : float or array [N/m]
        Stiffness of the whole spring.
    l0 : float or array [m]
        Free length in the type's form.
    friction : float or array [N m] or [N]
        Friction band as a generalised force (0: none).

    Returns
    -------
    tuple of array [(rad/s)^2]
        The closing and the opening speed squared.

    References
    ----------
    [textbook-ch3] section 3.4(b); [hamabe] Part I, eq. (12).

    Examples
    --------
    Hamabe's Example 1 (a) at the normal configuration with a friction moment of 10 kgf cm: by
    hand ``0.98 N m / (jp - ci) = 0.98 / 0.2316 = 4.23 (rad/s)^2`` either side of 631.65.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> sd = spring_design(spec)
    >>> t = terms(spec, spec.governor.alpha_normal, sd.m)
    >>> fall, rise = band_speeds_squared(t, sd.kappa, sd.l0, 10 * KGF * CM)
    >>> round(float(fall), 2), round(float(rise), 2)
    (627.42, 635.89)
    """
    f = np.asarray(friction, dtype=float)
    return t.omega_squared(kappa, l0, -f), t.omega_squared(kappa, l0, f)


def band_extremes(fall2, rise2):
    """The operating band's lowest and highest speed, rad/s.

    The least ``omega_fall`` and the largest ``omega_rise`` over the configurations (last axis;
    :func:`band_speeds_squared`). Over the whole range, not at its ends: a governor whose speed
    falls inside the range runs below its innermost configuration's speed there. The
    requirement (where the spec states ``[speed] inner/outer``, :attr:`Speed.band`): lowest
    ``>= omega_inner``, highest ``<= omega_outer``.

    Parameters
    ----------
    fall2 : array [(rad/s)^2]
        Closing speeds squared, configurations on the last axis.
    rise2 : array [(rad/s)^2]
        Opening speeds squared, likewise.

    Returns
    -------
    tuple of array [rad/s]
        The lowest and the highest speed of each design.

    References
    ----------
    [textbook-ch3] section 3.4(b) (the band friction opens); govopt's own requirement over it.

    Examples
    --------
    A speed that dips inside the range (by hand: sqrt(24) and sqrt(27)):

    >>> band_extremes(np.array([[25.0, 24.0, 26.0]]), np.array([[26.0, 25.0, 27.0]]))
    (array([4.89897949]), array([5.19615242]))
    """
    return (np.sqrt(np.maximum(np.min(fall2, axis=-1), 0.0)),
            np.sqrt(np.max(rise2, axis=-1)))


#: what a spring whose force would have the wrong sign would have to do, by kind
_WRONG_SIGN = {"compression": "a compression spring cannot pull",
               "tension": "a tension spring cannot push", "leaf": "the leaf would bend back"}


def band_spring(spec: Spec, m, central=0.0):
    """The spring that makes the governor float between the band's two speeds, or why none does.

    The textbook's question (ch. 3, Examples 4 and 8; Hamabe Example 1: :func:`required_spring`),
    with the checks: a :class:`DesignError` (the reason in words) for a band narrower than govopt
    resolves (its width over the mean speed at most :data:`SLOPE_RTOL`: the governor floating
    across it would be isochronous to rounding, not stable; a falling band, outer below inner,
    gives the spring of a governor the evaluation reports unstable), a rate or free length that
    is not positive and finite, or a force that does not keep the spring loaded in its working sense
    at every configuration (a compression spring that would have to pull).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds (inner and outer) and analysis options.
    m : float [kg]
        Flying mass.
    central : float [kg], optional
        Central (sleeve) load.

    Returns
    -------
    tuple of float
        ``(kappa [N/m], l0 [m], F_inner [N], F_outer [N])``.

    References
    ----------
    [hamabe] Part I, Example 1; [textbook-ch3] section 3.5, Examples 4 and 8.

    Examples
    --------
    Hamabe's Example 1 (a) with the valve gear's reactions at the local speed (govopt's default;
    the paper's mean-speed reactions give 63.3, :func:`required_spring`): a slightly softer
    spring, positive and loaded at every configuration, so no refusal.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> kappa, l0, F_i, F_a = band_spring(spec, 12.0)
    >>> round(kappa / (KGF / CM), 2), round(l0 / CM, 2)
    (62.73, 12.87)
    """
    gov, sp = spec.governor, spec.speed
    width = (sp.omega_outer - sp.omega_inner) / sp.omega_mean
    if not abs(width) > SLOPE_RTOL:  # a falling band (outer < inner) is evaluated: unstable
        raise DesignError(f"the band is {width:.3g} of the mean speed wide, within govopt's "
                          f"resolution ({SLOPE_RTOL:g}): isochronous to rounding; widen it")
    kappa, l0, f_inner, f_outer = (float(v) for v in required_spring(spec, m, central))
    if not (np.isfinite(kappa) and kappa > 0.0):
        raise DesignError(f"the rate that would is {kappa:.4g} N/m")
    if not np.isfinite(l0) or (gov.free_length_positive and l0 <= 0.0):
        raise DesignError(f"its free length would be {l0:.4g} m")
    x = configurations(spec)
    force = np.broadcast_to(spring_force(spec, x, kappa, l0), x.shape)
    i = int(np.argmin(force))
    if not force[i] >= 0.0:
        where = ("the innermost configuration" if i == 0 else "the outermost configuration"
                 if i == x.size - 1 else "a configuration inside the range")
        raise DesignError(f"its force would be {force[i]:.4g} N at {where} ("
                          f"{gov.spring_loaded_check} needs >= 0): "
                          f"{_WRONG_SIGN.get(gov.spring, 'the spring would unload')}")
    return kappa, l0, f_inner, f_outer


def inertia(spec: Spec, sd: SpringDesign, x):
    """Generalised inertia at ``x``: the design's own value if it gives one, else the type's.

    For the shaft governor the type's is the paper's point mass ``I = rho^2 m`` (Hamabe, Part II,
    eq. 18); a spec may give the pendulum's own.

    Parameters
    ----------
    spec : Spec [-]
        The governor.
    sd : SpringDesign [-]
        The design (its ``inertia`` in kg m^2 or kg, and whether it is the design's own).
    x : array [rad] or [m]
        Configurations, in the type's coordinate.

    Returns
    -------
    float or array [kg m^2] or [kg]
        Inertia for an angle coordinate, mass for a length.

    References
    ----------
    [hamabe] Part II, eqs. (18)-(20).

    Examples
    --------
    Hamabe's Example 1 (a): by hand ``0.12^2 x 12 = 0.1728 kg m^2``.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> round(float(inertia(spec, spring_design(spec), spec.governor.alpha_normal)), 4)
    0.1728
    """
    if sd.inertia_given:
        return sd.inertia
    return spec.governor.inertia(np.asarray(x, dtype=float), sd.m, sd.central)


def restoring_k2(spec: Spec, alpha, sd: SpringDesign, omega2):
    """Restoring stiffness ``k^2``, (rad/s)^2, about configuration ``alpha`` at ``omega^2``.

    Hamabe, eqs. (18)-(20): ``k^2 = (dM_f/dalpha - omega^2 m a rho cos(alpha)) / I``; in general
    ``I k^2 = kappa (A_x - B_x l0) + cf_x - omega^2 (jpp - ci_x)``. With ``reaction_slope``
    (default) the slope of the valve gear's mean reaction ``dM_r0/dalpha``, which the paper
    leaves out, is included: it acts on the pendulum exactly like the spring.

    Parameters
    ----------
    spec : Spec [-]
        The governor and its analysis options.
    alpha : array [rad] or [m]
        Configurations, in the type's coordinate.
    sd : SpringDesign [-]
        The design (mass in kg, stiffness in N/m, free length in m).
    omega2 : float or array [(rad/s)^2]
        Speed squared at which to linearise.

    Returns
    -------
    array [(rad/s)^2]
        ``k^2`` at each configuration.

    References
    ----------
    [hamabe] Part II, eqs. (18)-(20) and Example 2.

    Examples
    --------
    Hamabe's Example 2, case (a), normal configuration: the paper prints k^2 = 360. With the
    paper's own model (the series moment of eq. (3), no slope of the reaction) govopt gives
    362.2 (within 0.6 %); the exact moment of eq. (2) is stiffer (452.4) and the
    reaction's slope, which the paper leaves out, softens it again: 413.5 by default, still
    inside Case 1, ``0 < k^2 < omega0^2 = 631.65``.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> def k2(**fidelity):
    ...     s = spec.with_analysis(**fidelity)
    ...     w2 = s.speed.omega_mean**2
    ...     return round(float(restoring_k2(s, s.governor.alpha_normal, spring_design(s), w2)), 1)
    >>> k2(geometry="series", reaction_slope=False), k2(reaction_slope=False), k2()
    (362.2, 452.4, 413.5)
    """
    t = terms(spec, alpha, sd.m, sd.central)
    return t.stiffness(sd.kappa, sd.l0, omega2) / inertia(spec, sd, alpha)


def classify_k2(k2, omega0_sq):
    """Hamabe Part II's three cases per configuration, as words.

    ``"stable"`` (case 1, ``0 < k^2 < omega0^2``), ``"resonance risk"`` (case 2,
    ``k^2 >= omega0^2``: the valve gear's harmonics can resonate), ``"unstable"`` (case 3,
    ``k^2 <= 0``).

    Parameters
    ----------
    k2 : array [(rad/s)^2]
        Restoring stiffness (:func:`restoring_k2`).
    omega0_sq : float [(rad/s)^2]
        Mean speed squared.

    Returns
    -------
    array of str [-]
        One case per configuration.

    References
    ----------
    [hamabe] Part II, cases 1-3.

    Examples
    --------
    One of each, against the paper's omega0^2 = 630:

    >>> [str(c) for c in classify_k2([-1.0, 360.0, 630.0], 630.0)]
    ['unstable', 'stable', 'resonance risk']
    """
    k2 = np.asarray(k2, dtype=float)
    return np.where(k2 <= 0, "unstable", np.where(k2 >= omega0_sq, "resonance risk", "stable"))


def spring_design(spec: Spec, design: Design | None = None) -> SpringDesign:
    """The flying masses and spring of a given design (a :class:`SpringDesign`, SI).

    The rate from the spring's dimensions where the design does not give it (the shaft
    governor: ``kappa = G d^4 / (64 r^3 n)``), and the free length from equilibrium at the normal
    configuration where the design does not fix it (Hamabe, Example 1: :func:`free_half_length`).
    A :class:`DesignError` where the spec has no ``[design]``.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds and material.
    design : Design [-], optional
        The design to read; the spec's ``[design]`` when None.

    Returns
    -------
    SpringDesign [-]
        Masses in kg, stiffness in N/m, lengths in m, inertia in kg m^2 (angle) or kg (length).

    References
    ----------
    [hamabe] Part I, Example 1.

    Examples
    --------
    Hamabe's Example 1 (a), d 1.7 cm, r 6 cm, 8 turns: the paper prints kappa = 64.2 kgf/cm.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> sd = spring_design(spec)
    >>> round(float(sd.m), 6), round(sd.kappa / (KGF / CM), 2)
    (12.0, 64.19)
    """
    ds = design or spec.design
    if ds is None:
        raise DesignError("design: missing (the spec has no [design] to evaluate)")
    gov = spec.governor
    central = ds.central_mass or 0.0
    d, r, n = (np.nan if v is None else v for v in (ds.wire_diameter, ds.coil_radius,
                                                   ds.active_turns))
    if gov.spring is None:
        kappa, l0 = 0.0, 0.0
    elif ds.spring_stiffness is not None:
        kappa = ds.spring_stiffness
    else:
        kappa = gov.spring_rate(ds, spec.material)
    if gov.spring is not None:
        l0 = ds.free_half_length
        if l0 is None:
            l0 = float(free_half_length(spec, ds.flying_mass, kappa, central))
    given = ds.flying_inertia is not None
    I = ds.flying_inertia if given else float(gov.inertia(gov.x_normal, ds.flying_mass,
                                                            central))
    w, t = (np.nan if v is None else v for v in (ds.leaf_width, ds.leaf_thickness))
    return SpringDesign(ds.flying_mass, I, kappa, l0, d, r, n, central, given, w, t)


def configurations(spec: Spec, points: int | None = None) -> np.ndarray:
    """Configurations from innermost to outermost, always including the normal one.

    The normal configuration replaces a grid point within rounding of it (no two rows a rounding
    error apart, whose secant would be noise), else it is added: ``points`` or ``points + 1``
    values. govopt's own sampling of the range (the paper's Fig. 6 table has five rows).

    Parameters
    ----------
    spec : Spec [-]
        The governor (its range and normal configuration) and analysis options.
    points : int [-], optional
        Grid points over the range (dimensionless); the spec's ``analysis.points`` when None.

    Returns
    -------
    array [rad] or [m]
        Sorted configurations, in the type's coordinate.

    References
    ----------
    [hamabe] Part I, Example 1 (the range 50 to 80 deg, normal 64 deg 40').

    Examples
    --------

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> np.round(np.degrees(configurations(spec, 5)), 2).tolist()
    [50.0, 57.5, 64.67, 65.0, 72.5, 80.0]
    """
    g = spec.governor
    x = np.linspace(g.x_inner, g.x_outer, points or spec.analysis.points)
    near = np.abs(x - g.x_normal) <= 1e-9 * abs(g.x_outer - g.x_inner)
    if np.any(near):
        x[np.argmax(near)] = g.x_normal
        return np.unique(x)
    return np.unique(np.append(x, g.x_normal))


#: a slope of the characteristic below this share of ``omega0 / (x_outer - x_inner)`` is flat:
#: rounding, not a rise or a fall (the one tolerance of stability and isochronism; it equals
#: the pass tolerance of a check's margin, so the check and the label agree)
SLOPE_RTOL = 1e-9


