"""The continuous bound of a spring governor's design: for each pendulum mass the least spring
(a geometric programme, :class:`~govopt.optimize.spring_gp.SpringGP`) with its stiffness in the
statics window, the dynamics relaxed, so that the best of these bounds every design from below;
and the bound's finite-difference sensitivities to the requirements.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..requirements import (
    requirement_rows,
    search_bound_rows,
)
from ..spec import Requirements, Spec
from .kappa import KappaModel
from .windows import statics_window


def spring_mass_lower_bound(F, per_kappa, k_lo, k_hi, k_s, G, density):
    """Least wire mass of any helical spring with stiffness ``kappa`` in ``[k_lo, k_hi]`` (N/m)
    whose uncorrected stress at the force ``F + per_kappa kappa`` (N, N per N/m) is within
    ``k_s`` (Pa), with shear modulus ``G`` (Pa) and density (kg/m^3): the energy bound, kg.

    With Hamabe's Example 1 formulas, ``kappa = G d^4 / (64 r^3 n)`` and
    ``tau = 16 F r / (pi d^3)``, the energy stored at the force ``F``,
    ``U = F^2 / (2 kappa)``, is ``tau^2 V / (4 G)`` with ``V = pi^2 d^2 r n / 2`` the wire's
    volume. So ``tau <= k_s`` needs ``rho V >= 2 rho G F^2 / (kappa k_s^2)`` whatever ``d, r,
    n`` (Wahl's factor ``K >= 1`` and every other limit only add to it); ``F^2 / kappa`` is
    least at ``kappa = F / per_kappa`` within the band. Arrays broadcast; 0 where ``F <= 0``.

    A spring stressed to exactly ``k_s`` meets the bound (d = 10 mm, r = 50 mm, n = 5):

    >>> from govopt.springs import helical as hx
    >>> G, rho, F = 80e9, 7850.0, 500.0
    >>> kappa, tau = hx.stiffness_r(0.01, 0.05, 5, G), hx.shear_stress_r(F, 0.01, 0.05)
    >>> lb = spring_mass_lower_bound(F, 0.0, kappa, kappa, tau, G, rho)
    >>> bool(np.isclose(lb, hx.wire_mass(0.01, 0.05, 5, rho), rtol=1e-12))
    True
    """
    F, p = np.asarray(F, dtype=float), np.maximum(np.asarray(per_kappa, dtype=float), 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.clip(np.where(p > 0, F / p, np.inf), k_lo, k_hi)
        energy = (F + p * k) ** 2 / k
    return np.where(F > 0, 2.0 * density * G * energy / k_s**2, 0.0)


def gp_values(spec: Spec, req: Requirements, km: KappaModel, i: int, k_lo: float, k_hi: float,
              per: float) -> dict:
    """The spring GP's values for mass row ``i`` with the stiffness in ``[k_lo, k_hi]``: the
    exact force at the outermost configuration ``F = F_n + per kappa`` (a posynomial), the
    bounds and limits, and the body length within the band's largest free length; the allowable
    ``k_s`` is the caller's (a grade's rule or the spec's)."""
    mat = spec.material
    values = dict(kappa_min=k_lo, kappa_max=k_hi, F_max=float(km.force.y[i, -1]),
                  force_per_stiffness=per if per > 0 else None, G=mat.shear_modulus,
                  density=mat.density)
    # the requirement rows' GP limits; the body length at the band's largest free length
    ev = {"l0": float(km.l0.x[i, 0] + km.l0.y[i, 0] / k_hi)}
    values.update({row.gp.limit: row.limit(ev)
                   for row in (*requirement_rows(spec, req), *search_bound_rows(req))
                   if row.gp is not None})
    return values


def continuous_bound(spec: Spec, req: Requirements, km: KappaModel, lo, hi):
    """Least objective over masses with the spring sized by the GP (dynamics relaxed).

    Per mass the GP takes the stiffness band ``[lo, hi]``, the exact force at the outermost
    configuration ``F = F_n + 2 kappa (l_a - l_n)`` (a posynomial in d, r, n) and the body length
    limit at the band's largest free length, so it is a relaxation of the discrete search: its
    best value is a lower bound on every design, continuous or discrete.

    The masses are visited in the order of a lower bound of their objective (the flying and
    central masses plus :func:`spring_mass_lower_bound`), and the visit stops once that bound
    exceeds the best GP optimum found: the result is the one of solving every mass (the least
    objective, ties to the first mass), from a few solves of one shared GP. Where that bound is
    attained by a spring meeting every row of the GP's table
    (:func:`govopt.optimize.gp_table.energy_optimum`: the uncorrected stress and the stiffness
    band bind) that spring is the GP's optimum, certified without a solve (and without cvxpy).
    """
    from .gp_table import complete_values, energy_optimum

    mat = spec.material
    k_s, k_exp = mat.allowable_shear_stress, 0.0
    if mat.grade is not None:  # k_s d^-m above the grade's allowable over the wire bounds
        from ..analysis.spring_screens import allowable_monomial

        k_s, k_exp = allowable_monomial(spec, *req.wire_diameter)
    gp = None
    rows = np.nonzero(lo <= hi)[0]
    k_lo, k_hi = np.maximum(lo[rows], 1e-9), np.minimum(hi[rows], 1e12)
    per_kappa = km.force.x[rows, -1]
    lower = spring_mass_lower_bound(km.force.y[rows, -1], per_kappa, k_lo, k_hi,
                                    k_s * req.wire_diameter[0] ** -k_exp, mat.shear_modulus,
                                    mat.density)
    if req.objective != "spring_mass":
        lower = spec.governor.moving_mass(km.m[rows, 0], km.central[rows, 0], lower)
    best, best_key = None, (math.inf, -1)
    for j in np.argsort(lower, kind="stable"):
        if lower[j] > best_key[0] * (1.0 + 1e-7):  # the GP's optimum cannot be below its bound
            break
        i = int(rows[j])
        per = float(per_kappa[j])
        values = {**gp_values(spec, req, km, i, float(k_lo[j]), float(k_hi[j]), per),
                  "k_s": k_s}
        sol = energy_optimum(complete_values(values, "band"), mat.stress_correction, k_exp)
        if sol is None:  # not certified by the energy bound: the GP (cvxpy) decides
            if gp is None:
                from .spring_gp import cached_gp

                gp = cached_gp("mass", mat.stress_correction, "band", k_exp)
            sol = gp.solve(**values)
        if not sol.ok:
            continue
        m, c = float(km.m[i, 0]), float(km.central[i, 0])
        obj = sol.objective if req.objective == "spring_mass" else \
            spec.governor.moving_mass(m, c, sol.objective)
        if (obj, i) < best_key:
            best_key = (obj, i)
            best = {"objective": obj, f"{spec.governor.mass_key}_mass_kg": m,
                    **({"central_mass_kg": c} if c else {}), "wire_diameter_m": sol.d,
                    "coil_radius_m": sol.r, "active_turns": sol.n, "spring_mass_kg": sol.objective,
                    "stiffness_N_per_m": sol.stiffness, "shear_stress_Pa": sol.stress}
    return best





def sensitivities(spec: Spec, req: Requirements, base: float | None) -> dict[str, float]:
    """Finite-difference sensitivity of the continuous bound ``base`` to each requirement
    (+1 %), as the record states them (:data:`govopt.optimize.record.SENSITIVITY_CONVENTION`:
    requirement -> per cent change of the bound): each perturbed bound re-solved exactly by
    :func:`continuous_bound`, which solves the shared GP only at the masses whose lower bound
    can beat the best (one or two)."""
    out = {}
    speed, mat = spec.speed, spec.material

    def bound_of(s, r):
        _, km, lo, hi, _ = statics_window(s, r)
        b = continuous_bound(s, r, km, lo, hi)
        return None if b is None else b["objective"]

    if req.objective not in ("moving_mass", "spring_mass") or base is None:
        return out
    trials = [
        *([("allowable shear stress k_s", replace(spec, material=replace(
            mat, allowable_shear_stress=mat.allowable_shear_stress * 1.01)), req)]
          if mat.allowable_shear_stress is not None else []),  # a wire grade: per d
        ("irregularity", replace(spec, speed=replace(
            speed, irregularity=speed.irregularity * 1.01)), req),
        ("mean speed", replace(spec, speed=replace(speed, omega_mean=speed.omega_mean * 1.01)),
         req),
    ]
    margin = spec.governor.k2_rule(req.k2_margin)[0]
    if margin:
        trials.append(("k^2 margin", spec, replace(req, k2_margin=margin * 1.01)))
    least = spec.governor.range_rule(req.min_range) if speed.band else 0.0
    if least:
        trials.append(("least range of speed", spec, replace(req, min_range=least * 1.01)))
    for name, s, r in trials:
        b = bound_of(s, r)
        if b is None:
            continue
        out[name] = 100.0 * (b / base - 1.0)
    return out
