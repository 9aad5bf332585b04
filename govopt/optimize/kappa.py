"""The shaft governor at fixed pendulum mass as an affine function of the spring stiffness.

With the free length set by equilibrium at the normal configuration and mean speed (Hamabe,
Example 1), every static quantity the design constraints need is affine in the stiffness
``kappa`` at fixed pendulum mass ``m``:

* spring moment ``M_f = kappa (A - B l0)`` with ``kappa l0 = (kappa A_n - M_n) / B_n`` (eqs. 2-3),
  so ``M_f = kappa (A - B A_n / B_n) + M_n B / B_n``;
* spring force ``F = 2 kappa (l - A_n / B_n) + 2 M_n / B_n`` (eq. 2);
* equilibrium speed squared ``omega^2`` (eq. 12: numerator affine, denominator independent of
  kappa);
* restoring stiffness ``k^2`` (eqs. 18-20, plus the reaction slope, itself affine in omega^2).

So each requirement "for every configuration" becomes an interval of admissible ``kappa``, in
closed form, for many masses at once. This is what makes the design search exhaustive and fast.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analysis import statics
from ..spec import Spec


@dataclass(frozen=True)
class Affine:
    """``value = kappa * x + y`` (arrays broadcasting over masses and configurations)."""

    x: np.ndarray
    y: np.ndarray

    def __call__(self, kappa):
        return kappa * self.x + self.y


def _interval(lo, hi, aff: Affine, bound, sense: str):
    """Intersect ``[lo, hi]`` with ``{kappa : aff(kappa) sense bound}`` along the last axis."""
    x, rhs = aff.x, bound - aff.y
    with np.errstate(divide="ignore", invalid="ignore"):
        k = rhs / x
    if sense == ">=":
        lo = np.maximum(lo, np.max(np.where(x > 0, k, -np.inf), axis=-1))
        hi = np.minimum(hi, np.min(np.where(x < 0, k, np.inf), axis=-1))
        bad = np.any((x == 0) & (rhs > 0), axis=-1)
    else:
        hi = np.minimum(hi, np.min(np.where(x > 0, k, np.inf), axis=-1))
        lo = np.maximum(lo, np.max(np.where(x < 0, k, -np.inf), axis=-1))
        bad = np.any((x == 0) & (rhs < 0), axis=-1)
    return np.where(bad, np.inf, lo), hi


@dataclass(frozen=True)
class KappaModel:
    """Statics of the governor for masses ``m`` (shape (M, 1)) at configurations ``alpha``."""

    spec: Spec
    m: np.ndarray
    alpha: np.ndarray
    omega2: Affine
    k2: Affine
    force: Affine
    l0: Affine  # kappa * l0 is affine: stored as (x, y) of kappa*l0
    inertia: np.ndarray
    central: np.ndarray | float | None = None  # the central (sleeve) load's mass, kg
    #: the speed at which each row holds the normal configuration (rad/s, shape (M, 1)); None:
    #: the spec's mean speed for every row
    reference: np.ndarray | None = None

    @classmethod
    def build(cls, spec: Spec, m, alpha, central=None, reference=None) -> KappaModel:
        """On the seam (:mod:`govopt.governors.base`): with ``Q_n`` the spring force that holds
        the normal configuration at the reference speed (the mean speed, Hamabe Example 1, or a
        row's own ``reference``), ``kappa l0 = (kappa A_n - Q_n) / B_n``, so
        ``Q_s = kappa (A - B A_n / B_n) + Q_n B / B_n`` and every figure below is affine."""
        gov = spec.governor
        m = np.asarray(m, dtype=float).reshape(-1, 1)
        alpha = np.asarray(alpha, dtype=float)
        w0 = spec.speed.omega_mean if reference is None else np.asarray(
            reference, dtype=float).reshape(-1, 1)
        t_n = statics.terms(spec, gov.x_normal, m, central)
        M_n = w0**2 * t_n.lever - t_n.cf  # (M, 1)
        A_n, B_n = t_n.A, t_n.B
        t = statics.terms(spec, alpha, m, central)
        mf = Affine(t.A - t.B * A_n / B_n, M_n * t.B / B_n)
        dmf = Affine(t.A_x - t.B_x * A_n / B_n, M_n * t.B_x / B_n)
        w2 = Affine(mf.x / t.lever, (mf.y + t.cf) / t.lever)
        inertia = gov.inertia(alpha, m, central) + 0.0 * w2.x
        soft = t.jpp - t.ci_x  # the centrifugal softening per unit omega^2
        slope_x = dmf.x - w2.x * soft
        slope_y = dmf.y + t.cf_x - w2.y * soft
        A_F, B_F = gov.spring_force_coefficients(alpha)
        force = Affine(A_F - B_F * A_n / B_n + 0.0 * m, B_F * M_n / B_n + 0.0 * alpha)
        l0 = Affine(A_n / B_n + 0.0 * m, -M_n / B_n)
        central = np.zeros_like(m) if central is None else np.broadcast_to(
            np.asarray(central, dtype=float).reshape(-1, 1), m.shape)
        return cls(spec, m, alpha, w2, Affine(slope_x / inertia, slope_y / inertia), force,
                   l0, inertia, central, None if reference is None else w0 + 0.0 * m)

    def free_half_length(self, kappa):
        """``l0 = A_n / B_n - M_n / (B_n kappa)`` (Hamabe, Example 1)."""
        return self.l0.x + self.l0.y / kappa

    def irregularity_interval(self, i_inner: int, i_outer: int, delta: float):
        """Stiffness per mass with Hamabe's irregularity ``(omega_a - omega_i) / omega0 <= delta``
        (Part I, ``omega0`` the spec's mean speed), exactly: ``(lo, hi)``, empty where
        ``lo > hi``.

        With ``P = omega_a^2`` and ``Q = omega_i^2`` affine in ``kappa`` and ``c = delta omega0``,
        ``sqrt(P) <= c + sqrt(Q)`` holds exactly when ``D = P - Q - c^2 <= 0`` (and ``Q >= 0``)
        or ``D^2 <= 4 c^2 Q``: a ray and the interval between the roots of a quadratic. Where both
        are non-empty they meet (at ``D = 0``, ``Q >= 0`` the quadratic is ``-4 c^2 Q <= 0``), so
        the set is their hull.
        """
        c2 = (delta * self.spec.speed.omega_mean) ** 2
        xa, ya = self.omega2.x[:, i_outer], self.omega2.y[:, i_outer]
        xi, yi = self.omega2.x[:, i_inner], self.omega2.y[:, i_inner]
        dx, dy = xa - xi, ya - yi - c2
        whole = (np.full(dx.shape, -np.inf), np.full(dx.shape, np.inf))
        ray = _interval(*whole, Affine(dx[:, None], dy[:, None]), 0.0, "<=")
        ray = _interval(*ray, Affine(xi[:, None], yi[:, None]), 0.0, ">=")
        a, b, c = dx**2, 2.0 * dx * dy - 4.0 * c2 * xi, dy**2 - 4.0 * c2 * yi
        disc = b * b - 4.0 * a * c
        with np.errstate(divide="ignore", invalid="ignore"):
            half = np.sqrt(np.maximum(disc, 0.0)) / (2.0 * a)
            roots = (np.where(disc >= 0, -b / (2.0 * a) - half, np.inf),
                     np.where(disc >= 0, -b / (2.0 * a) + half, -np.inf))
        linear = _interval(*whole, Affine(b[:, None], c[:, None]), 0.0, "<=")  # a = 0
        quad = tuple(np.where(a > 0, r, q) for r, q in zip(roots, linear, strict=True))
        lo = np.min([np.where(p[0] <= p[1], p[0], np.inf) for p in (ray, quad)], axis=0)
        hi = np.max([np.where(p[0] <= p[1], p[1], -np.inf) for p in (ray, quad)], axis=0)
        return lo, hi

    def range_floor(self, share: float, i_inner: int = 0, i_outer: int = -1,
                    iterations: int = 64):
        """The least stiffness per row whose range of speed ``omega_a - omega_i`` (without
        friction) is at least ``share`` of the band ``speed.outer - speed.inner``
        (:func:`govopt.requirements.range_row`).

        The range grows with the stiffness: the normal configuration is held at its reference
        speed, so a stiffer spring turns the characteristic about it, raising ``omega_a`` and
        lowering ``omega_i`` (their squares affine in ``kappa``, slopes of opposite signs); so
        the set is a ray, its end found by bisection up to the stiffness at which
        ``omega_i^2`` reaches 0 (beyond it no equilibrium: another requirement's). ``inf``
        where no stiffness meets it.
        """
        sp = self.spec.speed
        target = share * (sp.omega_outer - sp.omega_inner)
        xi, yi = self.omega2.x[:, i_inner], self.omega2.y[:, i_inner]
        with np.errstate(divide="ignore", invalid="ignore"):
            top = np.where(xi < 0, -yi / xi, 1e12)

        def met(k):
            def root(i):
                return np.sqrt(np.maximum(self.omega2.x[:, i] * k + self.omega2.y[:, i], 0.0))
            return root(i_outer) - root(i_inner) >= target

        lo, hi = np.zeros_like(top), top
        ok = met(hi)
        for _ in range(iterations):
            mid = 0.5 * (lo + hi)
            up = met(mid)
            hi, lo = np.where(up, mid, hi), np.where(up, lo, mid)
        return np.where(ok, hi, np.inf)

    def statics_interval(self, k2_low: float, k2_high: float, delta: float,
                         i_inner: int = 0, i_outer: int = -1, least: float = 0.0):
        """Admissible ``kappa`` per mass: ``k2_low <= k^2 <= k2_high`` and ``omega^2 > 0`` at every
        configuration, irregularity ``<= delta``, spring in tension at the innermost
        configuration, positive free length; with ``least > 0`` the range of speed
        ``omega_a - omega_i >= least omega0`` (:func:`govopt.requirements.range_row`). Returns
        ``(lo, hi)``, empty where ``lo > hi``; and a dict of the interval each requirement
        alone allows (for diagnoses).

        ``least``: the least range of speed's share of the band
        (:func:`govopt.requirements.range_row`; :meth:`range_floor`)."""
        M = self.m.shape[0]
        start = (np.zeros(M), np.full(M, np.inf))
        parts = {
            "k^2 > 0 (stability)": _interval(*start, self.k2, k2_low, ">="),
            "k^2 < omega0^2 (no resonance)": _interval(*start, self.k2, k2_high, "<="),
            "equilibrium speed > 0": _interval(*start, self.omega2, 0.0, ">="),
            "spring in tension": _interval(*start, Affine(self.force.x, self.force.y), 0.0,
                                           ">="),
        }
        for name, (sense, limit) in self.spec.governor.free_length_limits().items():
            # l0 sense limit <=> kappa l0 - limit kappa sense 0 (kappa > 0)
            parts[name] = _interval(*start, Affine(self.l0.x - limit, self.l0.y), 0.0, sense)
        sp = self.spec.speed
        if sp.band:  # the whole operating band inside [speed] inner/outer, friction included,
            # at every configuration (statics.band_extremes): omega_fall^2, omega_rise^2 are
            # affine in kappa, the same slope as omega^2, shifted by -+ F / (jp - ci)
            # (statics.band_speeds_squared)
            t = statics.terms(self.spec, self.alpha, self.m, self.central)
            fall0, rise0 = statics.band_speeds_squared(
                t, 0.0, 0.0, self.spec.governor.friction(self.alpha))
            w0 = t.omega_squared(0.0, 0.0)
            fall = Affine(self.omega2.x, self.omega2.y + (fall0 - w0))
            rise = Affine(self.omega2.x, self.omega2.y + (rise0 - w0))
            parts[statics.BAND_INNER] = _interval(*start, fall, sp.omega_inner**2, ">=")
            parts[statics.BAND_OUTER] = _interval(*start, rise, sp.omega_outer**2, "<=")
        lo_irr, hi_irr = self.irregularity_interval(i_inner, i_outer, delta)
        parts["irregularity"] = (np.maximum(start[0], lo_irr), np.minimum(start[1], hi_irr))
        if sp.band and least > 0:
            from ..requirements import RANGE_OF_SPEED

            parts[RANGE_OF_SPEED] = (self.range_floor(least, i_inner, i_outer), start[1])
        lo = np.max([p[0] for p in parts.values()], axis=0)
        hi = np.min([p[1] for p in parts.values()], axis=0)
        return lo, hi, parts
