"""Statics of the shaft governor (Hamabe, Part I): characteristic curve, irregularity, spring.

Pure functions of a :class:`~govopt.spec.Spec` (geometry, valve gear, fidelity) and design
arrays. Every design quantity (``m``, ``kappa``, ``l0`` ...) may be a numpy array of shape
``(N, 1)`` to evaluate N designs at once against configurations ``alpha`` of shape ``(K,)``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import DesignError
from ..model import linkage, spring, valvegear
from ..spec import Design, Spec


@dataclass(frozen=True)
class SpringDesign:
    """Pendulum and spring of one design (or many: fields may be arrays), SI."""

    m: np.ndarray | float  # pendulum mass, kg
    inertia: np.ndarray | float  # pendulum moment of inertia about the fulcrum, kg m^2
    kappa: np.ndarray | float  # stiffness of the whole spring, N/m
    l0: np.ndarray | float  # free half length, m
    d: np.ndarray | float = np.nan
    r: np.ndarray | float = np.nan
    n: np.ndarray | float = np.nan


def reaction(spec: Spec, alpha):
    """``(C_f, C_i)`` with ``M_r0 = C_f + omega^2 C_i`` at configurations ``alpha`` (eq. 11)."""
    vg, g = spec.valve_gear, spec.geometry
    delta = valvegear.advance_angle(alpha, vg.table_alpha, vg.table_delta)
    return valvegear.mean_reaction_split(delta, g.q, vg.eccentricity, vg.offset, vg.friction,
                                         vg.reciprocating_mass, vg.eccentric_mass)


def reaction_slope(spec: Spec, alpha, omega2, step: float = 1e-6):
    """``dM_r0/dalpha`` at constant speed, by a difference of eq. (11) through the interpolated
    valve-gear table: exact between rows (the table is piecewise linear), the mean of the two
    slopes on an inner row, one-sided at the table's ends."""
    vg = spec.valve_gear
    hi = np.minimum(alpha + step, vg.table_alpha[-1])
    lo = np.maximum(alpha - step, vg.table_alpha[0])
    lo = np.where(hi - lo > 0, lo, hi - step)  # outside the table: a flat (zero) slope region
    cf_p, ci_p = reaction(spec, hi)
    cf_m, ci_m = reaction(spec, lo)
    return ((cf_p - cf_m) + omega2 * (ci_p - ci_m)) / (hi - lo)


def omega_squared(spec: Spec, alpha, m, kappa, l0):
    """Equilibrium speed squared at configuration ``alpha``: the characteristic curve.

    Hamabe, eq. (12): ``M_f - M_z + M_r0 = 0`` with ``M_z = omega^2 m a rho sin(alpha)`` (eq. 1).
    With ``reaction_speed="mean"`` the valve gear's inertia reactions are taken at the mean speed
    as the paper does; with ``"local"`` (default) at the equilibrium speed itself, which keeps the
    balance exact: ``omega^2 = (M_f + C_f) / (m a rho sin(alpha) - C_i)``.
    """
    g = spec.geometry
    M_f = linkage.spring_moment(alpha, kappa, l0, g.a, g.b, spec.analysis.geometry)
    C_f, C_i = reaction(spec, alpha)
    lever = m * g.a * g.rho * np.sin(alpha)
    if spec.analysis.reaction_speed == "mean":
        return (M_f + C_f + spec.speed.omega_mean**2 * C_i) / lever
    return (M_f + C_f) / (lever - C_i)


def required_spring_moment(spec: Spec, alpha, omega, m):
    """Spring moment that holds configuration ``alpha`` in equilibrium at ``omega`` (eq. 12):
    ``M_f = M_z - M_r0``."""
    g = spec.geometry
    C_f, C_i = reaction(spec, alpha)
    omega_r = spec.speed.omega_mean if spec.analysis.reaction_speed == "mean" else omega
    return linkage.centrifugal_moment(alpha, omega, m, g.a, g.rho) - (C_f + omega_r**2 * C_i)


def free_half_length(spec: Spec, m, kappa):
    """Free half length that puts the normal configuration in equilibrium at the mean speed.

    Hamabe, Example 1: ``F_n = M_f(alpha_n) / h_n``, ``l0 = l_n - F_n / (2 kappa)``.
    """
    g, w0 = spec.geometry, spec.speed.omega_mean
    M_n = required_spring_moment(spec, g.alpha_normal, w0, m)
    return linkage.free_half_length(g.alpha_normal, M_n, kappa, g.a, g.b, spec.analysis.geometry)


def required_spring(spec: Spec, m):
    """Stiffness and free half length that give exactly the spec's speed range.

    Hamabe, Example 1: ``F_i = M_fi / h_i``, ``F_a = M_fa / h_a``,
    ``kappa = (F_a - F_i) / (2 (l_a - l_i))``. Written as two linear equations in ``kappa`` and
    ``kappa l0`` (``M_f = kappa (A - B l0)``), which is the paper's procedure for the exact
    geometry and its analogue for the series. Returns ``(kappa, l0, F_inner, F_outer)``.
    """
    g, sp = spec.geometry, spec.speed
    M_i = required_spring_moment(spec, g.alpha_inner, sp.omega_inner, m)
    M_a = required_spring_moment(spec, g.alpha_outer, sp.omega_outer, m)
    A_i, B_i, _, _ = linkage.spring_moment_coefficients(g.alpha_inner, g.a, g.b,
                                                        spec.analysis.geometry)
    A_a, B_a, _, _ = linkage.spring_moment_coefficients(g.alpha_outer, g.a, g.b,
                                                        spec.analysis.geometry)
    det = A_a * B_i - A_i * B_a
    kappa = (M_a * B_i - M_i * B_a) / det
    kappa_l0 = (M_a * A_i - M_i * A_a) / det
    l0 = kappa_l0 / kappa
    F_i = linkage.spring_force(g.alpha_inner, kappa, l0, g.a, g.b)
    F_a = linkage.spring_force(g.alpha_outer, kappa, l0, g.a, g.b)
    return kappa, l0, F_i, F_a


def restoring_k2(spec: Spec, alpha, sd: SpringDesign, omega2):
    """Restoring stiffness ``k^2`` of the pendulum about configuration ``alpha`` at ``omega^2``.

    Hamabe, eqs. (18)-(20): ``k^2 = (dM_f/dalpha - omega^2 m a rho cos(alpha)) / I``. With
    ``reaction_slope`` (default) the slope of the valve gear's mean reaction ``dM_r0/dalpha``,
    which the paper leaves out, is added: it acts on the pendulum exactly like the spring.
    """
    g = spec.geometry
    slope = linkage.spring_moment_slope(alpha, sd.kappa, sd.l0, g.a, g.b, spec.analysis.geometry)
    slope = slope - omega2 * sd.m * g.a * g.rho * np.cos(alpha)
    if spec.analysis.reaction_slope:
        omega_r2 = spec.speed.omega_mean**2 if spec.analysis.reaction_speed == "mean" else omega2
        slope = slope + reaction_slope(spec, alpha, omega_r2)
    return slope / sd.inertia


def classify_k2(k2, omega0_sq):
    """Hamabe Part II's three cases per configuration: ``"stable"`` (case 1,
    ``0 < k^2 < omega0^2``), ``"resonance risk"`` (case 2, ``k^2 >= omega0^2``: the valve gear's
    harmonics can resonate), ``"unstable"`` (case 3, ``k^2 <= 0``)."""
    k2 = np.asarray(k2, dtype=float)
    return np.where(k2 <= 0, "unstable", np.where(k2 >= omega0_sq, "resonance risk", "stable"))


def spring_design(spec: Spec, design: Design | None = None) -> SpringDesign:
    """The pendulum and spring of a given design, with the free length from equilibrium at the
    normal configuration when the design does not fix it (Hamabe, Example 1)."""
    ds = design or spec.design
    if ds is None:
        raise DesignError(f"{spec.path}: design: missing (the spec has no [design] to evaluate)")
    kappa = spring.stiffness(ds.wire_diameter, ds.coil_radius, ds.active_turns,
                             spec.material.shear_modulus)
    inertia = ds.pendulum_inertia or spec.geometry.rho**2 * ds.pendulum_mass
    l0 = ds.free_half_length
    if l0 is None:
        l0 = float(free_half_length(spec, ds.pendulum_mass, kappa))
    return SpringDesign(ds.pendulum_mass, inertia, kappa, l0, ds.wire_diameter,
                        ds.coil_radius, ds.active_turns)


@dataclass(frozen=True)
class Characteristic:
    """Statics of one design over the configuration range (SI arrays over ``alpha``)."""

    alpha: np.ndarray
    omega: np.ndarray
    M_z: np.ndarray
    M_f: np.ndarray
    M_r0: np.ndarray
    spring_force: np.ndarray
    stress: np.ndarray
    half_length: np.ndarray
    arm: np.ndarray

    @property
    def irregularity(self) -> float:
        """``delta_0 = (omega_a - omega_i) / omega_mean``, mean of the two (Hamabe, Part I)."""
        wi, wa = self.omega[0], self.omega[-1]
        return float(2.0 * (wa - wi) / (wa + wi))


def configurations(spec: Spec, points: int | None = None) -> np.ndarray:
    """Configurations from innermost to outermost, always including the normal one."""
    g = spec.geometry
    alpha = np.linspace(g.alpha_inner, g.alpha_outer, points or spec.analysis.points)
    return np.unique(np.append(alpha, g.alpha_normal))


def characteristic(spec: Spec, sd: SpringDesign, alpha=None) -> Characteristic:
    """Characteristic curve and spring loading of one design (Hamabe, eqs. 1, 2, 11, 12)."""
    g = spec.geometry
    alpha = configurations(spec) if alpha is None else np.asarray(alpha, dtype=float)
    w2 = omega_squared(spec, alpha, sd.m, sd.kappa, sd.l0)
    if np.any(w2 <= 0):
        raise DesignError("no equilibrium speed: the spring pushes the pendulum outward at "
                         f"alpha = {np.degrees(alpha[w2 <= 0][0]):.2f} deg")
    omega = np.sqrt(w2)
    C_f, C_i = reaction(spec, alpha)
    omega_r2 = spec.speed.omega_mean**2 if spec.analysis.reaction_speed == "mean" else w2
    F = linkage.spring_force(alpha, sd.kappa, sd.l0, g.a, g.b)
    return Characteristic(
        alpha=alpha, omega=omega,
        M_z=linkage.centrifugal_moment(alpha, omega, sd.m, g.a, g.rho),
        M_f=linkage.spring_moment(alpha, sd.kappa, sd.l0, g.a, g.b, spec.analysis.geometry),
        M_r0=C_f + omega_r2 * C_i,
        spring_force=F,
        stress=spring.shear_stress(F, sd.d, sd.r, spec.material.stress_correction),
        half_length=linkage.half_length(alpha, g.a, g.b),
        arm=linkage.spring_arm(alpha, g.a, g.b),
    )


def paper_sizing(spec: Spec, m: float, r: float) -> dict:
    """Hamabe's spring-sizing procedure of Example 1, step by step, SI.

    ``omega_i = omega0 (1 - delta0/2)``, ``omega_a = omega0 (1 + delta0/2)``;
    ``M_fi = M_zi - M_r0i``, ``M_fa = M_za - M_r0a`` (eq. 12); ``F = M_f / h`` (eq. 2);
    ``kappa = (F_a - F_i) / (2 (l_a - l_i))``; ``d = (16 F_a r / (pi k_s))^(1/3)``;
    ``n = G d^4 / (64 r^3 kappa)``. The reaction is taken at the mean speed, as in the paper.
    """
    g, sp, mat = spec.geometry, spec.speed, spec.material
    paper = spec.with_analysis(reaction_speed="mean")
    out = {"omega_inner": sp.omega_inner, "omega_outer": sp.omega_outer}
    for tag, alpha, omega in (("i", g.alpha_inner, sp.omega_inner),
                              ("a", g.alpha_outer, sp.omega_outer)):
        out[f"M_z{tag}"] = linkage.centrifugal_moment(alpha, omega, m, g.a, g.rho)
        out[f"M_f{tag}"] = required_spring_moment(paper, alpha, omega, m)
        out[f"h_{tag}"] = linkage.spring_arm(alpha, g.a, g.b)
        out[f"l_{tag}"] = linkage.half_length(alpha, g.a, g.b)
        out[f"F_{tag}"] = out[f"M_f{tag}"] / out[f"h_{tag}"]
    out["kappa"] = (out["F_a"] - out["F_i"]) / (2.0 * (out["l_a"] - out["l_i"]))
    out["d"] = spring.wire_diameter_for_stress(out["F_a"], r, mat.allowable_shear_stress)
    out["n"] = spring.turns_for_stiffness(out["kappa"], out["d"], r, mat.shear_modulus)
    return out
