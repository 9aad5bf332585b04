"""The spring GP's constraint table and its values, in numpy; and its optimum where an energy
bound decides it, without a solver.

The rows of the least-mass helical spring's geometric programme (:mod:`govopt.optimize.spring_gp`,
whose docstring gives each row's source) are functions of ``d, r, n, t`` and the parameter values
``P``: cvxpy builds the GP from them, and :func:`energy_optimum` evaluates them in numpy. The
stiffness and stress rows are the GP's own; the bounds and the spring's requirements (index,
outer diameter, body length, surge) are the GP forms of their requirement rows
(:data:`govopt.requirements.GP_BOUNDS`), which the evaluator checks too. They
live apart from :mod:`~govopt.optimize.spring_gp` so that a design whose continuous bound
:func:`energy_optimum` certifies never imports cvxpy (docs/decisions.md, imports
on demand).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from govopt.requirements import GP_BOUNDS, GPForm
from govopt.springs import helical as hx

#: Stand-ins for "no limit" (the GP needs a positive number for every parameter).
_BIG = 1e6
_TINY = 1e-9

#: Optional limits and their defaults; ``None`` (or ``inf`` / ``0``) means "no limit".
#: ``n_min = 1`` and ``3 <= C <= 20`` are coiling practice (Wahl 1944, ch. 2); pass others freely.
DEFAULT_BOUNDS: dict[str, float | None] = {
    "d_min": None,
    "d_max": None,
    "r_min": None,
    "r_max": None,
    "n_min": 1.0,
    "n_max": None,
    "C_min": 3.0,
    "C_max": 20.0,
    "D_out_max": None,
    "L_body_max": None,
    "f_surge_min": None,
    # force growing with the stiffness itself, F = F_max + force_per_stiffness * kappa: a
    # governor's spring force at its outermost configuration is F_n + 2 kappa (l_a - l_n)
    "force_per_stiffness": None,
}
_UPPER_KEYS = {"d_max", "r_max", "n_max", "C_max", "D_out_max", "L_body_max"}
MATERIAL_KEYS = ("F_max", "k_s", "G", "density")


def stress_g(d, r, n, t, P, correction):
    # F = F_max + force_per_stiffness * kappa(d, r, n): a posynomial (the second term is ~0
    # unless force_per_stiffness is given)
    F = P["F_max"] + P["force_per_stiffness"] * _stiffness_g(d, r, n, P)
    if correction == "none":
        return 16.0 / np.pi * F * r * d**-3
    if correction == "bergstrasser":  # K_B = (C + 0.5)/(C - 0.75) = 1 + 1.25 t, t >= 1/(C - 0.75)
        return 16.0 / np.pi * F * (r * d**-3 + 1.25 * t * r * d**-3)
    # K = 1 + 0.75 t + 0.615 / C with C = 2 r / d, t >= 1 / (C - 1)
    return 16.0 / np.pi * F * (r * d**-3 + 0.75 * t * r * d**-3 + 0.3075 * d**-2)


def _stiffness_g(d, r, n, P):
    return P["G"] * d**4 / (64.0 * r**3 * n)


def gp_constraints(correction: str, stiffness: str,
                   allowable_exponent: float = 0.0) -> list[GPForm]:
    """The constraint table; ``allowable_exponent`` ``m``: the allowable stress is
    ``k_s d^-m`` (a wire grade's ``R_m ~ A d^-m``, a monomial), so the stress limit reads
    ``tau d^m <= k_s``."""
    m = float(allowable_exponent)
    hamabe = "Hamabe, Example 1"
    out = []
    if stiffness == "equality":
        out.append(GPForm("stiffness", "kappa", "equal",
                          lambda d, r, n, t, P: _stiffness_g(d, r, n, P), (("G", 1.0),), hamabe))
    else:
        out.append(GPForm("minimum stiffness", "kappa_min", "lower",
                          lambda d, r, n, t, P: _stiffness_g(d, r, n, P), (("G", 1.0),), hamabe))
        out.append(GPForm("maximum stiffness", "kappa_max", "upper",
                          lambda d, r, n, t, P: _stiffness_g(d, r, n, P), (("G", 1.0),), hamabe))
    stress_src = hamabe + {"wahl": "; Wahl 1944 eq. 2-12",
                           "bergstrasser": "; Bergstraesser, EN 13906-1, Shigley eq. (10-5)"
                           }.get(correction, "")
    out.append(GPForm("allowable stress", "k_s", "upper",
                      lambda d, r, n, t, P: stress_g(d, r, n, t, P, correction) * d**m
                      if m else stress_g(d, r, n, t, P, correction), (("F_max", 1.0),),
                      stress_src))
    # the bounds and the spring's requirements: their rows' GP forms (govopt.requirements)
    out += list(GP_BOUNDS.values())
    return out


def complete_values(values: Mapping[str, float], stiffness: str) -> dict[str, float]:
    """Validate user values, fill the defaults and replace "no limit" by big/tiny numbers."""
    kappa_keys = ("kappa",) if stiffness == "equality" else ("kappa_min", "kappa_max")
    required = kappa_keys + MATERIAL_KEYS
    allowed = set(required) | set(DEFAULT_BOUNDS)
    unknown = set(values) - allowed
    if unknown:
        raise TypeError(f"unknown spring GP values {sorted(unknown)}; allowed: {sorted(allowed)}")
    missing = [k for k in required if values.get(k) is None]
    if missing:
        raise TypeError(f"missing required spring GP values {missing}")
    out: dict[str, float] = {}
    for key in required:
        val = float(values[key])
        if not (math.isfinite(val) and val > 0.0):
            raise ValueError(f"{key} must be positive and finite, got {values[key]!r}")
        out[key] = val
    for key, default in DEFAULT_BOUNDS.items():
        val = values.get(key, default)
        if val is None or (key in _UPPER_KEYS and math.isinf(val)) or \
                (key not in _UPPER_KEYS and val == 0):
            val = _BIG if key in _UPPER_KEYS else _TINY
        val = float(val)
        if not (math.isfinite(val) and val > 0.0):
            raise ValueError(f"{key} must be positive (or None for no limit), got {val!r}")
        out[key] = val
    return out


#: relative rounding allowed on the rows a spring of the energy family meets with equality
_ROUNDING = 1e-12


@dataclass(frozen=True)
class EnergyOptimum:
    """A continuous least-mass spring certified without a solver (:func:`energy_optimum`): the
    fields :func:`govopt.optimize.design.continuous_bound` reads of a GP solution (SI)."""

    d: float
    r: float
    n: float
    objective: float
    stiffness: float
    stress: float
    ok: bool = True


def energy_optimum(values: Mapping[str, float], correction: str = "none",
                   allowable_exponent: float = 0.0, points: int = 2001) -> EnergyOptimum | None:
    """The least-mass spring of the band-mode GP (:func:`gp_constraints`), where the energy bound is
    attained; None where it cannot be shown so (then the GP is solved).

    The bound (:func:`govopt.optimize.design.spring_mass_lower_bound`): with Hamabe's Example 1
    formulas ``kappa = G d^4/(64 r^3 n)`` and ``tau = 16 F r/(pi d^3)`` the wire mass is
    ``2 rho G F^2/(kappa tau^2)``, so ``tau <= k_s`` at ``F = F_max + p kappa`` needs a mass of at
    least ``2 rho G (F_max + p kappa)^2/(kappa k_s^2)``, least at ``kappa* = F_max/p`` clipped to
    the band (``kappa_max`` without ``p``). Every spring with ``kappa = kappa*`` and
    ``tau = k_s`` has exactly that mass: ``r = pi k_s d^3/(16 F)``, ``n = G d^4/(64 r^3 kappa*)``
    for any ``d``. If one such spring meets every row of the table, it is the GP's optimum
    (a feasible point at a lower bound: no solver, no tolerance). Only for the uncorrected
    stress and a constant allowable (``correction="none"``, ``allowable_exponent=0``): with
    Wahl's or Bergstraesser's factor ``K > 1`` the bound is not attained. ``values`` are the GP's
    (:func:`complete_values`); ``d`` is searched on ``points`` log-spaced wires of the bounds, and
    the spring returned is the one with the most relative slack in its least slack row.

    >>> v = complete_values(dict(kappa_min=4e3, kappa_max=6e3, F_max=300.0, k_s=500e6,
    ...                           G=80e9, density=7850.0), "band")
    >>> opt = energy_optimum(v)
    >>> bound = 2 * 7850.0 * 80e9 * 300.0**2 / (6e3 * 500e6**2)
    >>> bool(np.isclose(opt.objective, bound, rtol=1e-12)), bool(np.isclose(opt.stress, 500e6))
    (True, True)
    """
    if correction != "none" or allowable_exponent != 0.0:
        return None
    P = dict(values)
    p, F0, k_s, G = P["force_per_stiffness"], P["F_max"], P["k_s"], P["G"]
    kappa = P["kappa_max"] if p <= 0.0 else min(max(F0 / p, P["kappa_min"]), P["kappa_max"])
    F = F0 + p * kappa
    d = np.geomspace(max(P["d_min"], 1e-6), min(P["d_max"], 1.0), points)
    r = math.pi * k_s * d**3 / (16.0 * F)
    n = G * d**4 / (64.0 * r**3 * kappa)
    # the rows the family meets with equality by construction hold to rounding; every other
    # row must hold with room to spare
    defining = {"allowable stress", "maximum stiffness" if kappa == P["kappa_max"] else "",
                "minimum stiffness" if kappa == P["kappa_min"] else ""}
    slack = np.full(d.shape, np.inf)
    for row in gp_constraints(correction, "band"):
        g = np.asarray(row.g(d, r, n, None, P), dtype=float)
        limit = P[row.limit]
        room = (limit - g) / limit if row.sense == "upper" else (g - limit) / limit
        if row.name in defining:
            room = np.where(room >= -_ROUNDING, np.inf, -np.inf)
        slack = np.minimum(slack, room)
    best = int(np.argmax(slack))
    if not slack[best] > _ROUNDING:  # no spring of the family meets every row
        return None
    d, r, n = float(d[best]), float(r[best]), float(n[best])
    return EnergyOptimum(d=d, r=r, n=n, objective=float(hx.wire_mass(d, r, n, P["density"])),
                         stiffness=float(hx.stiffness_r(d, r, n, G)),
                         stress=float(hx.shear_stress_r(F0 + p * hx.stiffness_r(d, r, n, G),
                                                          d, r, correction)))
