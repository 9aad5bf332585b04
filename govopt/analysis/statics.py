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
    """The governor type's generalised forces at configurations ``x`` (the seam,
    :mod:`govopt.governors.base`) for flying mass ``m`` and central load ``central``."""
    an = spec.analysis
    if spec.speed is not None and an.omega_mean != spec.speed.omega_mean:
        an = replace(an, omega_mean=spec.speed.omega_mean)  # the reference of "mean" options
    return spec.governor.terms(np.asarray(x, dtype=float), m, an, central)


def omega_squared(spec: Spec, alpha, m, kappa, l0, central=None):
    """Equilibrium speed squared at configuration ``alpha``: the characteristic curve.

    Virtual work (:mod:`govopt.governors.base`): ``omega^2 (jp - ci) = kappa (A - B l0) + cf``.
    For the shaft governor this is Hamabe's eq. (12), ``M_f - M_z + M_r0 = 0`` with
    ``M_z = omega^2 m a rho sin(alpha)`` (eq. 1); with ``reaction_speed="mean"`` the valve gear's
    inertia reactions are taken at the mean speed as the paper does, with ``"local"`` (default) at
    the equilibrium speed itself: ``omega^2 = (M_f + C_f) / (m a rho sin(alpha) - C_i)``.
    """
    return terms(spec, alpha, m, central).omega_squared(kappa, l0)


def required_spring_moment(spec: Spec, alpha, omega, m, central=None):
    """Spring generalised force that holds ``alpha`` in equilibrium at ``omega``:
    ``omega^2 (jp - ci) - cf`` (Hamabe eq. 12: ``M_f = M_z - M_r0``)."""
    t = terms(spec, alpha, m, central)
    return omega**2 * t.lever - t.cf


def free_half_length(spec: Spec, m, kappa, central=None):
    """Free length that puts the normal configuration in equilibrium at the mean speed.

    Hamabe, Example 1: ``F_n = M_f(alpha_n) / h_n``, ``l0 = l_n - F_n / (2 kappa)``; in general
    ``kappa (A_n - B_n l0) = Q_n`` solved for ``l0``.
    """
    gov = spec.governor
    if spec.speed is None:
        raise DesignError(f"design.{gov.free_length_key}: missing, and the spec has "
                          "no [speed] to set it from equilibrium at the normal configuration")
    Q_n = required_spring_moment(spec, gov.x_normal, spec.speed.omega_mean, m, central)
    t = terms(spec, gov.x_normal, m, central)
    return (t.A - Q_n / kappa) / t.B


def spring_force(spec: Spec, x, kappa, l0):
    """Spring force ``F = kappa (A_F - B_F l0)`` (N) at ``x`` (the shaft: ``2 kappa (l - l0)``,
    Hamabe eq. 2)."""
    A_F, B_F = spec.governor.spring_force_coefficients(np.asarray(x, dtype=float))
    return kappa * (A_F - B_F * l0)


def required_spring(spec: Spec, m, central=None):
    """Stiffness and free length that give exactly the spec's speed range.

    Hamabe, Example 1: ``F_i = M_fi / h_i``, ``F_a = M_fa / h_a``,
    ``kappa = (F_a - F_i) / (2 (l_a - l_i))``. Written as two linear equations in ``kappa`` and
    ``kappa l0`` (``Q_s = kappa (A - B l0)``), which is the paper's procedure for the exact
    geometry and its analogue for any type (the textbook's Examples 4 and 8: stiffness and
    initial compression from two speeds). Returns ``(kappa, l0, F_inner, F_outer)``.
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
    """``(omega_fall^2, omega_rise^2)``, (rad/s)^2, at the configurations of the terms ``t``
    (:func:`terms`; last axis): the speeds at which the governor closes and opens against the
    friction band ``friction`` there (generalised forces, the type's
    :meth:`Governor.friction`; textbook 3.4(b)). Arrays broadcast over designs."""
    f = np.asarray(friction, dtype=float)
    return t.omega_squared(kappa, l0, -f), t.omega_squared(kappa, l0, f)


def band_extremes(fall2, rise2):
    """The operating band's lowest and highest speed, rad/s: the least ``omega_fall`` and the
    largest ``omega_rise`` over the configurations (last axis; :func:`band_speeds_squared`).
    Over the whole range, not at its ends: a governor whose speed falls inside the range runs
    below its innermost configuration's speed there. The requirement (where the spec states
    ``[speed] inner/outer``, :attr:`Speed.band`): lowest ``>= omega_inner``, highest
    ``<= omega_outer``.

    >>> band_extremes(np.array([[25.0, 24.0, 26.0]]), np.array([[26.0, 25.0, 27.0]]))
    (array([4.89897949]), array([5.19615242]))
    """
    return (np.sqrt(np.maximum(np.min(fall2, axis=-1), 0.0)),
            np.sqrt(np.max(rise2, axis=-1)))


#: what a spring whose force would have the wrong sign would have to do, by kind
_WRONG_SIGN = {"compression": "a compression spring cannot pull",
               "tension": "a tension spring cannot push", "leaf": "the leaf would bend back"}


def band_spring(spec: Spec, m, central=0.0):
    """The spring that makes the governor float between the band's two speeds (the textbook's
    question, ch. 3, Examples 4 and 8; Hamabe Example 1: :func:`required_spring`), or why no
    spring does it (:class:`DesignError`, the reason in words): a band narrower than govopt
    resolves (its width over the mean speed at most :data:`SLOPE_RTOL`: the governor floating
    across it would be isochronous to rounding, not stable), a rate or free length that is not
    positive and finite, or a force that does not keep the spring loaded in its working sense
    at every configuration (a compression spring that would have to pull). Returns ``(kappa,
    l0, F_inner, F_outer)``."""
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
    """Generalised inertia at ``x``: the design's own value if it gives one, else the type's."""
    if sd.inertia_given:
        return sd.inertia
    return spec.governor.inertia(np.asarray(x, dtype=float), sd.m, sd.central)


def restoring_k2(spec: Spec, alpha, sd: SpringDesign, omega2):
    """Restoring stiffness ``k^2`` about configuration ``alpha`` at ``omega^2``.

    Hamabe, eqs. (18)-(20): ``k^2 = (dM_f/dalpha - omega^2 m a rho cos(alpha)) / I``; in general
    ``I k^2 = kappa (A_x - B_x l0) + cf_x - omega^2 (jpp - ci_x)``. With ``reaction_slope``
    (default) the slope of the valve gear's mean reaction ``dM_r0/dalpha``, which the paper
    leaves out, is included: it acts on the pendulum exactly like the spring.
    """
    t = terms(spec, alpha, sd.m, sd.central)
    return t.stiffness(sd.kappa, sd.l0, omega2) / inertia(spec, sd, alpha)


def classify_k2(k2, omega0_sq):
    """Hamabe Part II's three cases per configuration: ``"stable"`` (case 1,
    ``0 < k^2 < omega0^2``), ``"resonance risk"`` (case 2, ``k^2 >= omega0^2``: the valve gear's
    harmonics can resonate), ``"unstable"`` (case 3, ``k^2 <= 0``)."""
    k2 = np.asarray(k2, dtype=float)
    return np.where(k2 <= 0, "unstable", np.where(k2 >= omega0_sq, "resonance risk", "stable"))


def spring_design(spec: Spec, design: Design | None = None) -> SpringDesign:
    """The flying masses and spring of a given design, with the free length from equilibrium at
    the normal configuration when the design does not fix it (Hamabe, Example 1)."""
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
    """Configurations from innermost to outermost, always including the normal one (in place
    of a grid point within rounding of it: no two rows a rounding error apart, whose secant
    would be noise)."""
    g = spec.governor
    x = np.linspace(g.x_inner, g.x_outer, points or spec.analysis.points)
    near = np.abs(x - g.x_normal) <= 1e-9 * abs(g.x_outer - g.x_inner)
    if np.any(near):
        x[np.argmax(near)] = g.x_normal
        return np.unique(x)
    return np.unique(np.append(x, g.x_normal))


def design_key(spec: Spec, field: str) -> str | None:
    """The ``[design]`` key the spec writes for the design quantity ``field`` (a
    :class:`~govopt.spec.Design` field: ``"design.pendulum_mass"`` where the spec gives the
    mass, ``"design.pendulum_weight"`` where the weight), read from what the spec's reader
    recorded; None where the spec's ``[design]`` does not give it (a design found by the
    search, a study's point): a message then names the quantity, never a key the spec has
    not."""
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
    """Why ``omega^2 = (kappa (A - B l0) + cf) / (jp - ci)`` (:meth:`Terms.omega_squared`) is not
    positive somewhere in the range, naming the spec keys that decide it and which way to move
    them (one line): the regulating gear's inertia above the flying masses' (``jp - ci <= 0``);
    a spring pushing outward: a given free length beyond the bound ``kappa (A - B l0) + cf > 0``
    puts on it at every configuration, or, the free length set at the normal configuration
    (:func:`free_half_length`), a rate above the largest that keeps ``restoring > 0`` (that
    restoring force is linear in ``kappa``); else the dead loads."""
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
    """Characteristic curve and spring loading of one design (Hamabe, eqs. 1, 2, 11, 12; the
    textbook's controlling-force curve, section 3.3), by virtual work on the seam."""
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
    """``d omega / d x`` along the characteristic (rad/s per unit ``x``) at configurations
    ``alpha`` with equilibrium speeds ``omega`` (rad/s): the static stability, > 0 for a stable
    governor (Hamabe, Part III's conclusion: stable "by means of their characteristic curves";
    the textbook, section 3.2: the balls move out as the speed rises).

    Differentiating the equilibrium ``G(x, omega) = kappa (A - B l0) + cf - omega^2 (jp - ci)
    = 0`` (eq. 12 on the seam, :mod:`govopt.governors.base`)::

        d omega / d x = -G_x / G_omega = I k^2 / (2 omega (jp - ci))

    with ``G_x = I k^2`` the constant-speed stiffness of eqs. (18)-(20) *including* the slope of
    the dead loads (the characteristic contains them, whatever the ``reaction_slope`` fidelity
    says for k^2) and ``-G_omega = 2 omega (jp - ci)``. So its sign is that of that k^2 where
    ``jp > ci``.
    """
    t = terms(spec.with_analysis(reaction_slope=True), alpha, sd.m, sd.central)
    return t.stiffness(sd.kappa, sd.l0, omega**2) / (2.0 * omega * t.lever)


#: a slope of the characteristic below this share of ``omega0 / (x_outer - x_inner)`` is flat:
#: rounding, not a rise or a fall (the one tolerance of stability and isochronism; it equals
#: the pass tolerance of a check's margin, so the check and the label agree)
SLOPE_RTOL = 1e-9


def slope_scale(spec: Spec, omega0):
    """The scale of ``d omega / d x`` (rad/s per unit ``x``): the reference speed ``omega0``
    (the spec's mean, else the normal configuration's) over the configuration range."""
    g = spec.governor
    return np.asarray(omega0, dtype=float) / (g.x_outer - g.x_inner)


def rising_slopes(spec: Spec, sd: SpringDesign, alpha, omega):
    """``d omega / d x`` at every configuration (:func:`characteristic_slope`) and the secant
    between neighbours, along the last axis: a fall between two rows cannot pass."""
    slope = np.broadcast_to(characteristic_slope(spec, sd, alpha, omega), np.shape(omega))
    secant = np.diff(omega, axis=-1) / np.diff(alpha)
    return np.concatenate([slope, secant], axis=-1)


def stability(slopes, scale):
    """``"stable"``, ``"isochronous"`` or ``"unstable"`` (Rattan; textbook 3.2) from the slopes
    of the characteristic (:func:`rising_slopes`, last axis) at ``scale``
    (:func:`slope_scale`): unstable where one falls by more than :data:`SLOPE_RTOL` of the
    scale, isochronous where every one is within it, else stable. Decided once, here: the
    "characteristic rises" check and the classic label read it.

    An exactly isochronous governor (controlling force ``c r``) is flat to rounding:

    >>> stability(np.array([1e-15, -2e-15, 0.0]), 10.0)
    array('isochronous', dtype='<U11')
    >>> str(stability(np.array([0.5, -1e-6]), 10.0))
    'unstable'
    """
    s = np.asarray(slopes, dtype=float) / np.asarray(scale, dtype=float)[..., None]
    return np.where((s < -SLOPE_RTOL).any(axis=-1), "unstable",
                    np.where((np.abs(s) <= SLOPE_RTOL).all(axis=-1), "isochronous", "stable"))
