"""Statics of every governor type on the seam (Hamabe, Part I; textbook ch. 3): characteristic
curve, irregularity, spring, k^2.

Pure functions of a :class:`~govopt.spec.Spec` (geometry, valve gear, fidelity) and design
arrays. Every design quantity (``m``, ``kappa``, ``l0`` ...) may be a numpy array of shape
``(N, 1)`` to evaluate N designs at once against configurations ``alpha`` of shape ``(K,)``.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

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
    across it would be isochronous to rounding, not stable), a rate or free length that is not
    positive and finite, or a force that does not keep the spring loaded in its working sense
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
    if not width > SLOPE_RTOL:
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


@dataclass(frozen=True)
class Characteristic:
    """Statics of one design over the configuration range (SI arrays over ``alpha``, the
    configuration ``x``): centrifugal ``M_z = omega^2 jp``, spring ``M_f`` and dead-load
    ``M_r0`` generalised forces (N m for an angle coordinate, N for a length)."""

    alpha: np.ndarray
    omega: np.ndarray
    M_z: np.ndarray
    M_f: np.ndarray
    M_r0: np.ndarray
    spring_force: np.ndarray
    stress: np.ndarray
    #: the type's own geometry columns: name -> (values, SI unit) (the shaft: l, h)
    extra: dict = field(default_factory=dict)
    #: the spec's mean speed omega0, rad/s: the reference of the irregularity (nan: none given)
    omega_mean: float = float("nan")

    @property
    def irregularity(self) -> float:
        """Hamabe's irregularity ``delta_0 = (omega_a - omega_i) / omega0``, ``omega0`` the spec's
        mean speed (Part I, Example 1: (26.4 - 23.4) / 25.1 = 0.119); dimensionless.

        It equals :attr:`sensitiveness` when the range is split as ``omega0 (1 -+ delta_0/2)``.
        """
        return float((self.omega[-1] - self.omega[0]) / self.omega_mean)

    @property
    def sensitiveness(self) -> float:
        """The range of speed over the mean of the two extreme speeds,
        ``2 (omega_a - omega_i) / (omega_a + omega_i)`` (the textbook's ratio of the range of speed
        to the mean speed, ch. 3, Problem 2; often called sensitiveness); dimensionless. Not the
        requirement: that is :attr:`irregularity`."""
        wi, wa = self.omega[0], self.omega[-1]
        return float(2.0 * (wa - wi) / (wa + wi))


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


def design_key(spec: Spec, field: str) -> str | None:
    """The ``[design]`` key the spec writes for the design quantity ``field``, or None.

    A :class:`~govopt.spec.Design` field: ``"design.pendulum_mass"`` where the spec gives the
    mass, ``"design.pendulum_weight"`` where the weight, read from what the spec's reader
    recorded; None where the spec's ``[design]`` does not give it (a design found by the search,
    a study's point): a message then names the quantity, never a key the spec has not. No
    physics: the key names follow the type's spec keys (Hamabe's Example 1 for the shaft).

    Parameters
    ----------
    spec : Spec [-]
        The spec as read.
    field : str [-]
        A :class:`~govopt.spec.Design` field name (dimensionless).

    Returns
    -------
    str or None [-]
        The key as the spec writes it.

    References
    ----------
    [hamabe] Part I, Example 1 (the pendulum given by its weight, W = 12 kgf).

    Examples
    --------

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> design_key(spec, "flying_mass"), design_key(spec, "free_half_length")
    ('design.pendulum_weight', None)
    """
    gov = spec.governor
    forms = {"flying_mass": (f"{gov.mass_key}_weight", f"{gov.mass_key}_mass"),
             "central_mass": ("central_weight", "central_mass"),
             "free_half_length": (gov.free_length_key,),
             "flying_inertia": (f"{gov.mass_key}_inertia",),
             "dashpot": ("dashpot_f", "dashpot_a1")}.get(field, (field,))
    written = {e.key for e in spec.entries}
    return next((f"design.{k}" for k in forms if f"design.{k}" in written), None)


#: how each [design] key of a spring makes it softer (Hamabe eq. 2's rate ``G d^4 / (64 r^3 n)``
#: for a coil, ``E w t^3`` over the cube of the length for a leaf)
SOFTER = (("spring_stiffness", "lower"), ("wire_diameter", "thinner"),
          ("coil_radius", "larger"), ("active_turns", "more"), ("leaf_thickness", "thinner"),
          ("leaf_width", "narrower"))


def no_equilibrium(spec: Spec, sd: SpringDesign, alpha, t, w2) -> str:
    """Why the characteristic has no positive ``omega^2`` somewhere in the range (one line).

    ``omega^2 = (kappa (A - B l0) + cf) / (jp - ci)`` (:meth:`Terms.omega_squared`, Hamabe eq.
    12). The line names the spec keys that decide it and which way to move them: the regulating
    gear's inertia above the flying masses' (``jp - ci <= 0``); a spring pushing outward: a given
    free length beyond the bound ``kappa (A - B l0) + cf > 0`` puts on it at every configuration,
    or, the free length set at the normal configuration (:func:`free_half_length`), a rate above
    the largest that keeps ``restoring > 0`` (that restoring force is linear in ``kappa``); else
    the dead loads. govopt's own diagnosis, built on eq. (12).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds and the spec's keys.
    sd : SpringDesign [-]
        The design (mass in kg, stiffness in N/m, free length in m).
    alpha : array [rad] or [m]
        Configurations, in the type's coordinate.
    t : Terms [-]
        The type's generalised forces at ``alpha`` (:func:`terms`).
    w2 : array [(rad/s)^2]
        The equilibrium speeds squared there, some not positive.

    Returns
    -------
    str [-]
        The message.

    References
    ----------
    [hamabe] Part I, eq. (12).

    Examples
    --------
    Hamabe's Example 1 (a) with a far too stiff spring, free length from the normal
    configuration: the stiff spring pushes the pendulum out at the inner end.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> from dataclasses import replace
    >>> sd = spring_design(spec)
    >>> stiff = replace(sd, kappa=1e7, l0=float(free_half_length(spec, 12.0, 1e7)))
    >>> x = configurations(spec)
    >>> t = terms(spec, x, 12.0)
    >>> print(no_equilibrium(spec, stiff, x, t, t.omega_squared(stiff.kappa, stiff.l0)))
    ... # doctest: +ELLIPSIS
    design: no equilibrium speed at alpha = 50.00 deg: the spring is too stiff ...
    """
    gov, design = spec.governor, spec.design
    angle = gov.coordinate == "angle"

    def at(x):
        return f"{np.degrees(x):.2f} deg" if angle else f"{x:.6g} m"

    bad = ~(w2 > 0)
    i = int(np.argmax(bad))
    head = (f"design: no equilibrium speed at {gov.coordinate_name} = "
            f"{at(alpha[i])}: ")
    lever = np.broadcast_to(t.lever, alpha.shape)
    if np.any(lever <= 0):
        j = int(np.argmax(lever <= 0))
        mass = design_key(spec, "flying_mass")
        return head + (f"the regulating gear's inertia outweighs the flying masses' centrifugal "
                       f"force at {at(alpha[j])}: heavier flying masses"
                       + (f" ({mass})" if mass else "") + ", or a lighter regulating gear (its "
                       "masses and levers in the spec)")
    A, B, cf = (np.broadcast_to(v, alpha.shape) for v in (t.A, t.B, t.cf))
    spring = sd.kappa * (A - B * sd.l0)
    if gov.spring is not None and spring[i] < 0 and sd.kappa > 0:
        key = design_key(spec, "free_half_length") or (
            f"the {gov.free_length_key.replace('_', ' ')}")
        if design is not None and design.free_half_length is not None:
            # restoring > 0  <=>  B l0 < A + cf / kappa
            bound = (A + cf / sd.kappa) / B
            above = B < 0
            if above.all() or not above.any():
                limit = float(np.max(bound) if above.all() else np.min(bound))
                way = "above" if above.all() else "below"
                return head + (f"the spring pushes the governor outward there: {key} = "
                               f"{sd.l0:.4g} m; equilibrium over the whole range needs it "
                               f"{way} {limit:.4g} m")
        elif spec.speed is not None:
            tn = terms(spec, gov.x_normal, sd.m, sd.central)
            Q_n = required_spring_moment(spec, gov.x_normal, spec.speed.omega_mean, sd.m,
                                         sd.central)
            c1 = A - B * tn.A / tn.B  # restoring = kappa c1 + c0 with l0 from the normal
            c0 = B * Q_n / tn.B + cf
            softer = ", ".join(f"{way} {design_key(spec, k)}" for k, way in SOFTER
                               if design_key(spec, k))
            if np.all(c0[c1 < 0] > 0):
                kmax = float(np.min(c0[c1 < 0] / -c1[c1 < 0]))
                return head + (f"the spring is too stiff ({key} from the normal "
                               f"configuration): rate {sd.kappa:.4g} N/m, at most {kmax:.4g} N/m "
                               f"holds the range ({softer or 'a softer spring'}; or [governor])")
            return head + (f"with {key} set at the normal configuration no spring rate holds "
                           "every configuration: the geometry in [governor] or the speeds in "
                           "[speed]")
    return head + ("the dead loads push the governor outward there: lighter loads on the "
                   "regulating gear (the spec's loads and levers)"
                   + (", or a stiffer spring" if gov.spring is not None else ""))


def characteristic(spec: Spec, sd: SpringDesign, alpha=None) -> Characteristic:
    """Characteristic curve and spring loading of one design (a :class:`Characteristic`, SI).

    Hamabe, eqs. (1), (2), (11), (12); the textbook's controlling-force curve, section 3.3; by
    virtual work on the seam. A :class:`DesignError` (:func:`no_equilibrium`) where some
    configuration has no positive equilibrium speed.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds, material and analysis options.
    sd : SpringDesign [-]
        The design (:func:`spring_design`).
    alpha : array [rad] or [m], optional
        Configurations; :func:`configurations` when None.

    Returns
    -------
    Characteristic [-]
        Speeds in rad/s, generalised forces in N m (angle) or N (length), spring force in N,
        stress in Pa.

    References
    ----------
    [hamabe] Part I, eqs. (1), (2), (11), (12); [textbook-ch3] section 3.3.

    Examples
    --------
    Hamabe's Example 1 (a), the paper's spring: the paper's closing check prints an
    irregularity of 0.119 from omega_a^2 = 700, where its own numbers give about 711 (0.123);
    the paper's rounded spring (64.2 kgf/cm where 63.3 is needed) is a little too stiff.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> c = characteristic(spec, spring_design(spec))
    >>> round(c.irregularity, 3), round(float(c.omega[-1] ** 2))
    (0.124, 712)
    """
    gov = spec.governor
    alpha = configurations(spec) if alpha is None else np.asarray(alpha, dtype=float)
    t = terms(spec, alpha, sd.m, sd.central)
    w2 = t.omega_squared(sd.kappa, sd.l0)
    if np.any(w2 <= 0):
        raise DesignError(no_equilibrium(spec, sd, alpha, t, w2))
    omega = np.sqrt(w2)
    F = spring_force(spec, alpha, sd.kappa, sd.l0)
    stress = (gov.spring_stress(alpha, F, sd, spec.material)
              if spec.material is not None else np.full_like(F, np.nan))
    return Characteristic(
        alpha=alpha, omega=omega,
        M_z=w2 * t.jp,
        M_f=sd.kappa * (t.A - t.B * sd.l0) + 0.0 * alpha,
        M_r0=t.cf + w2 * t.ci,
        spring_force=F,
        stress=stress,
        extra=gov.columns(alpha),
        omega_mean=spec.speed.omega_mean if spec.speed is not None else float("nan"),
    )


def characteristic_slope(spec: Spec, sd: SpringDesign, alpha, omega):
    """``d omega / d x`` along the characteristic (rad/s per unit ``x``): the static stability.

    At configurations ``alpha`` with equilibrium speeds ``omega``, > 0 for a stable governor
    (Hamabe, Part III's conclusion: stable "by means of their characteristic curves"; the
    textbook, section 3.2: the balls move out as the speed rises). Differentiating the
    equilibrium ``G(x, omega) = kappa (A - B l0) + cf - omega^2 (jp - ci) = 0`` (eq. 12 on the
    seam, :mod:`govopt.governors.base`)::

        d omega / d x = -G_x / G_omega = I k^2 / (2 omega (jp - ci))

    with ``G_x = I k^2`` the constant-speed stiffness of eqs. (18)-(20) *including* the slope of
    the dead loads (the characteristic contains them, whatever the ``reaction_slope`` fidelity
    says for k^2) and ``-G_omega = 2 omega (jp - ci)``. So its sign is that of that k^2 where
    ``jp > ci``.

    Parameters
    ----------
    spec : Spec [-]
        The governor and its analysis options.
    sd : SpringDesign [-]
        The design (mass in kg, stiffness in N/m, free length in m).
    alpha : array [rad] or [m]
        Configurations, in the type's coordinate.
    omega : array [rad/s]
        Equilibrium speeds there.

    Returns
    -------
    array [rad/s per rad] or [rad/s per m]
        The slope at each configuration.

    References
    ----------
    [hamabe] Part I, eq. (12), Part II, eqs. (18)-(20), Part III; [textbook-ch3] section 3.2.

    Examples
    --------
    Hamabe's Example 1 (a) at the normal configuration: by hand
    ``I k^2 / (2 omega (jp - ci)) = 0.1728 x 413.5 / (2 x 25.133 x 0.2316) = 6.14``.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> sd = spring_design(spec)
    >>> s = characteristic_slope(spec, sd, spec.governor.alpha_normal, spec.speed.omega_mean)
    >>> round(float(s), 2)
    6.14
    """
    t = terms(spec.with_analysis(reaction_slope=True), alpha, sd.m, sd.central)
    return t.stiffness(sd.kappa, sd.l0, omega**2) / (2.0 * omega * t.lever)


#: a slope of the characteristic below this share of ``omega0 / (x_outer - x_inner)`` is flat:
#: rounding, not a rise or a fall (the one tolerance of stability and isochronism; it equals
#: the pass tolerance of a check's margin, so the check and the label agree)
SLOPE_RTOL = 1e-9


def slope_scale(spec: Spec, omega0):
    """The scale of ``d omega / d x`` (rad/s per unit ``x``) that :func:`stability` reads.

    The reference speed ``omega0`` (the spec's mean, else the normal configuration's) over the
    configuration range. govopt's own scale (no source sets one).

    Parameters
    ----------
    spec : Spec [-]
        The governor (its configuration range).
    omega0 : float or array [rad/s]
        Reference speed.

    Returns
    -------
    float or array [rad/s per rad] or [rad/s per m]
        ``omega0 / (x_outer - x_inner)``.

    References
    ----------
    [hamabe] Part I, Example 1 (the range 50 to 80 deg at 240 rpm).

    Examples
    --------
    Hamabe's Example 1: by hand ``25.133 / (30 deg = 0.5236 rad) = 48.0``.

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> round(float(slope_scale(spec, spec.speed.omega_mean)), 3)
    48.0
    """
    g = spec.governor
    return np.asarray(omega0, dtype=float) / (g.x_outer - g.x_inner)


def rising_slopes(spec: Spec, sd: SpringDesign, alpha, omega):
    """The characteristic's slopes: ``d omega / d x`` at every configuration and the secants.

    :func:`characteristic_slope` at every configuration and the secant between neighbours,
    along the last axis (K + K - 1 values): a fall between two rows cannot pass.

    Parameters
    ----------
    spec : Spec [-]
        The governor and its analysis options.
    sd : SpringDesign [-]
        The design (mass in kg, stiffness in N/m, free length in m).
    alpha : array [rad] or [m]
        Configurations, in the type's coordinate (last axis).
    omega : array [rad/s]
        Equilibrium speeds there.

    Returns
    -------
    array [rad/s per rad] or [rad/s per m]
        Slopes then secants.

    References
    ----------
    [hamabe] Part III (stable by the characteristic curve); [textbook-ch3] section 3.2.

    Examples
    --------
    Hamabe's Example 1 (a): the characteristic rises everywhere (as the paper's table).

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("hamabe-a"))
    >>> KGF, CM = 9.80665, 0.01
    >>> sd = spring_design(spec)
    >>> x = configurations(spec, 5)
    >>> s = rising_slopes(spec, sd, x, np.sqrt(omega_squared(spec, x, sd.m, sd.kappa, sd.l0)))
    >>> s.shape, bool((s > 0).all())
    ((11,), True)
    """
    slope = np.broadcast_to(characteristic_slope(spec, sd, alpha, omega), np.shape(omega))
    secant = np.diff(omega, axis=-1) / np.diff(alpha)
    return np.concatenate([slope, secant], axis=-1)


def stability(slopes, scale):
    """``"stable"``, ``"isochronous"`` or ``"unstable"`` from the slopes of the characteristic.

    Rattan; textbook 3.2. From the slopes (:func:`rising_slopes`, last axis) at ``scale``
    (:func:`slope_scale`): unstable where one falls by more than :data:`SLOPE_RTOL` of the
    scale, isochronous where every one is within it, else stable. Decided once, here: the
    "characteristic rises" check and the classic label read it.

    Parameters
    ----------
    slopes : array [rad/s per rad] or [rad/s per m]
        Slopes and secants of the characteristic, last axis.
    scale : float or array [rad/s per rad] or [rad/s per m]
        Their scale.

    Returns
    -------
    array of str [-]
        One label per design.

    References
    ----------
    [textbook-ch3] section 3.2; [rattan].

    Examples
    --------
    An exactly isochronous governor (controlling force ``c r``) is flat to rounding:

    >>> stability(np.array([1e-15, -2e-15, 0.0]), 10.0)
    array('isochronous', dtype='<U11')
    >>> str(stability(np.array([0.5, -1e-6]), 10.0))
    'unstable'
    """
    s = np.asarray(slopes, dtype=float) / np.asarray(scale, dtype=float)[..., None]
    return np.where((s < -SLOPE_RTOL).any(axis=-1), "unstable",
                    np.where((np.abs(s) <= SLOPE_RTOL).all(axis=-1), "isochronous", "stable"))
