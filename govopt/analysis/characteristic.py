"""A design's characteristic over the configuration range and its stability (Hamabe, Part I;
textbook ch. 3, sections 3.2 and 3.7).

:func:`characteristic` solves the statics (:mod:`govopt.analysis.statics`) for the equilibrium
speed at every configuration of the range (:func:`configurations`), or says why a design has
no equilibrium there (:func:`no_equilibrium`); :func:`characteristic_slope`,
:func:`rising_slopes` and :func:`stability` judge whether the speed rises with the
configuration (a stable governor), against a scale (:func:`slope_scale`). Same array
conventions as the statics.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import DesignError
from ..inputs import Spec
from .statics import (
    SLOPE_RTOL,
    SpringDesign,
    configurations,
    required_spring_moment,
    spring_force,
    terms,
)


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
    >>> from govopt.analysis.statics import spring_design, free_half_length, omega_squared
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
    >>> from govopt.analysis.statics import spring_design
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
    >>> from govopt.analysis.statics import spring_design
    >>> sd = spring_design(spec)
    >>> s = characteristic_slope(spec, sd, spec.governor.alpha_normal, spec.speed.omega_mean)
    >>> round(float(s), 2)
    6.14
    """
    t = terms(spec.with_analysis(reaction_slope=True), alpha, sd.m, sd.central)
    return t.stiffness(sd.kappa, sd.l0, omega**2) / (2.0 * omega * t.lever)


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
    >>> from govopt.analysis.statics import spring_design, omega_squared
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
