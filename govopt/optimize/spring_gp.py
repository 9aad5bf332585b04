"""Least-mass helical (governor) spring as an exact geometric programme.

The spring is sized in its three design variables wire diameter ``d``, *mean coil radius* ``r``
(not the diameter) and active turns ``n``; everything is SI. Every requirement is a monomial or a
posynomial in ``(d, r, n)``, so the problem is a geometric programme (GP): convex in
``log d, log r, log n``. A solved GP therefore is a *global* optimum, certified by the solver's
primal-dual gap, and the dual variables are sensitivities
``d log(objective) / d log(limit)``.

Constraints and their sources (the formulas are those of :mod:`govopt.springs.helical`):

=========================  =====================================================================
``stiffness``              ``G d^4 / (64 r^3 n) = kappa`` (monomial equality) — Hamabe, Example 1
                           (``n = G d^4 / (64 r^3 kappa)``). In ``stiffness="band"`` mode
                           ``kappa_min <= G d^4 / (64 r^3 n) <= kappa_max``.
``allowable stress``       ``16 F_max r / (pi d^3) * K <= k_s`` — Hamabe, Example 1
                           (``d = (16 F r / (pi k_s))^(1/3)``) with ``K = 1``
                           (``correction="none"``) or Wahl's factor (Wahl, *Mechanical
                           Springs*, 1944, eq. 2-12)
                           ``K = (4C-1)/(4C-4) + 0.615/C = 1 + 0.75/(C-1) + 0.615/C``,
                           ``C = 2r/d``.
                           ``1/(C-1)`` is not a posynomial, so an auxiliary ``t >= 1/(C-1)`` is
                           written as the posynomial ``1/(t C) + 1/C <= 1``; ``K`` is increasing in
                           ``t``, so ``t = 1/(C-1)`` exactly wherever the stress limit binds.
``wire diameter``          ``d_min <= d <= d_max`` (catalogue range)
``coil radius``            ``r_min <= r <= r_max``
``active turns``           ``n_min <= n <= n_max``
``spring index``           ``C_min <= 2 r / d <= C_max`` (Wahl 1944, ch. 2: coiling practice)
``outer diameter``         ``2 r + d <= D_out_max`` (envelope)
``body length``            ``(n + 1) d <= L_body_max`` (close-wound body must fit)
``surge frequency``        ``d / (8 pi r^2 n) sqrt(G / (2 rho)) >= f_surge_min`` — Wahl 1944,
                           ch. 25 (lowest surge frequency, both ends fixed).
=========================  =====================================================================

Objective: the wire mass ``rho (pi d^2 / 4) (2 pi r (n + Q))`` by default, ``Q`` the inactive
coils (``end_coils``; 0, the active coils only, for the governor's spring; 2 closed end coils
for ``govopt spring``, EN 13906-1 ``n_t = n + 2``): a posynomial, so the GP stays exact; also
the literature's volume ``(n + Q) 2 r d^2``, the solid length ``(n + Q) d``,
``"stress"`` (least corrected stress at ``F_max``), ``"outer diameter"`` and ``"body length"``.

The problem is built once with cvxpy ``Parameter(pos=True)`` for every number (it is DPP), so a
re-solve with new values skips the compilation (measured by ``benchmarks/bench_spring_gp.py``).

Main entry points: :class:`SpringGP` (``solve``, ``diagnose``, ``best_discrete``),
:func:`size_helical_spring`, :func:`best_discrete`; the results they return and the exact check
of a design (:func:`~govopt.optimize.spring_results.check_design`) are in
:mod:`govopt.optimize.spring_results`.
"""

from __future__ import annotations

import math
import threading
import time
import warnings
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import cvxpy as cp
import numpy as np

from govopt.requirements import GPForm
from govopt.springs import helical as hx

from .gp_table import (
    DEFAULT_BOUNDS,
    MATERIAL_KEYS,
    complete_values,
    gp_constraints,
    stress_g,
)
from .spring_results import (
    OBJECTIVES,
    SOLVED,
    Diagnosis,
    DiscreteSolution,
    SpringSolution,
    check_design,
    enumerate_wire,
)

__all__ = [
    "CORRECTIONS",
    "FREE_LENGTH_KEYS",
    "SpringGP",
    "best_discrete",
    "cached_gp",
    "size_helical_spring",
]

#: Stress corrections, as in :func:`govopt.springs.helical.shear_stress_r`.
CORRECTIONS = hx.CORRECTIONS
STIFFNESS_MODES = ("equality", "band")
#: :meth:`SpringGP.solve` keywords of the free-length limit (``free_length=True``)
FREE_LENGTH_KEYS = ("L0_over_D_max", "solid_coils", "k_solid", "s_over_D_max", "Di_min",
                    "L0_max", "Lc_max", "L2", "clear", "Ln_max", "L2_solid", "clear_solid",
                    "pitch_on", "d_tol", "pitch_clear", "pitch_L2", "pitch_F")
#: their values when not given: far outside any spring (the constraint never binds); ``L2``
#: (an installed length at ``F_max``) tiny and ``clear`` 1 (the least free length); the solid
#: length with the nominal wire (``d_tol``, the wire's tolerance, tiny); the helix's pitch that
#: of the least free length (the GP's pitch constraint)
_FREE_LENGTH_DEFAULTS = {"Di_min": 1e-12, "L2": 1e-12, "clear": 1.0, "L2_solid": 1e-12,
                         "clear_solid": 1.0, "pitch_on": 1e-12, "d_tol": 1e-12,
                         "pitch_clear": 1.0, "pitch_L2": 1e-12, "pitch_F": 1.0}


#: Clarabel tolerances tighter than its 1e-8 defaults: same solve time here (a few more
#: iterations), and the KKT residuals of the recovered GP duals drop from ~1e-5 to ~1e-7.
_CLARABEL_OPTS = {"tol_gap_abs": 1e-10, "tol_gap_rel": 1e-10, "tol_feas": 1e-10,
                  "tol_ktratio": 1e-8}



def _default_solver() -> str | None:
    installed = cp.installed_solvers()
    for name in ("CLARABEL", "ECOS", "SCS"):
        if name in installed:
            return name
    return None


# ----------------------------------------------------------------------------------------------
# Constraint table
# ----------------------------------------------------------------------------------------------




def _coils(n, end_coils):
    """``n + end_coils``: every coil of wire (active and inactive ends), a posynomial."""
    return n + end_coils if end_coils else n


def _objective_expr(objective, d, r, n, t, P, correction, end_coils=0.0):
    if objective == "mass":
        return P["density"] * (np.pi**2 / 2.0) * d**2 * r * _coils(n, end_coils)
    if objective == "volume":
        return 2.0 * r * d**2 * _coils(n, end_coils)
    if objective == "solid length":
        return _coils(n, end_coils) * d
    if objective == "stress":
        return stress_g(d, r, n, t, P, correction)
    if objective == "mass per energy":  # m / (F^2 / (2 R)), R = G d^4 / (64 r^3 n)
        return (P["density"] * P["G"] * np.pi**2 / 64.0 * P["F_max"]**-2 * d**6 * r**-2
                * (1.0 + end_coils * n**-1 if end_coils else 1.0))
    if objective == "outer diameter":
        return 2.0 * r + d
    if objective == "body length":
        return (n + 1.0) * d
    raise ValueError(f"objective must be one of {OBJECTIVES}, got {objective!r}")


_OBJECTIVE_EXPS = {"mass": {"density": 1.0}, "stress": {"F_max": 1.0},
                   "mass per energy": {"density": 1.0, "G": 1.0, "F_max": -2.0}}


def _normalise_status(status: str | None) -> str:
    if status in (cp.OPTIMAL, cp.OPTIMAL_INACCURATE):
        return status
    if status in (cp.INFEASIBLE, cp.INFEASIBLE_INACCURATE):
        return "infeasible"
    if status in (cp.UNBOUNDED, cp.UNBOUNDED_INACCURATE):
        return "unbounded"
    return str(status) if status is not None else "solver_error"


# ----------------------------------------------------------------------------------------------
# The parameterised GP
# ----------------------------------------------------------------------------------------------


class SpringGP:
    """Parameterised (DPP) least-mass spring GP, compiled on the first solve, re-solved cheaply.

    >>> gp = SpringGP()                                   # mass objective, Wahl-corrected stress
    >>> sol = gp.solve(kappa=5e3, F_max=200.0, k_s=600e6, G=79.3e9, density=7850.0)
    >>> sol.status, sol.sensitivities['allowable stress'] < 0
    ('optimal', True)

    Values (SI): ``kappa`` (or ``kappa_min`` and ``kappa_max`` with ``stiffness="band"``),
    ``F_max``, ``k_s``, ``G``, ``density`` (required) and the optional limits of
    :data:`DEFAULT_BOUNDS`. Each solve uses exactly the values passed (not earlier ones).
    """

    def __init__(self, objective: str = "mass", correction: str = "wahl",
                 stiffness: str = "equality", solver: str | None = None,
                 solver_opts: Mapping[str, Any] | None = None,
                 allowable_exponent: float = 0.0, end_coils: float = 0.0,
                 free_length: bool = False, solid_exponent: float | None = None,
                 envelope: str | None = None, helix: bool = False):
        if objective not in OBJECTIVES:
            raise ValueError(f"objective must be one of {OBJECTIVES}, got {objective!r}")
        if correction not in CORRECTIONS:
            raise ValueError(f"correction must be one of {CORRECTIONS}, got {correction!r}")
        if stiffness not in STIFFNESS_MODES:
            raise ValueError(f"stiffness must be one of {STIFFNESS_MODES}, got {stiffness!r}")
        if not (math.isfinite(end_coils) and end_coils >= 0.0):
            raise ValueError(f"end_coils must be finite and >= 0, got {end_coils!r}")
        self.objective_name = objective
        #: inactive coils added to ``n`` in the mass, volume and solid-length objectives
        self.end_coils = float(end_coils)
        self.correction = correction
        self.stiffness_mode = stiffness
        self.solver = solver or _default_solver()
        if self.solver is None:
            raise RuntimeError("no conic solver for GPs is installed (need Clarabel, ECOS or SCS)")
        defaults = _CLARABEL_OPTS if self.solver == "CLARABEL" else {}
        self.solver_opts = {**defaults, **(solver_opts or {})}
        self._fallback_opts = {} if defaults and not solver_opts else None
        kappa_keys = ("kappa",) if stiffness == "equality" else ("kappa_min", "kappa_max")
        self.parameter_names = kappa_keys + MATERIAL_KEYS + tuple(DEFAULT_BOUNDS)
        self.params = {k: cp.Parameter(pos=True, name=k) for k in self.parameter_names}
        #: ``m`` of a diameter-dependent allowable ``k_s d^-m`` (0: a constant ``k_s``)
        self.allowable_exponent = float(allowable_exponent)
        self.specs = gp_constraints(correction, stiffness, self.allowable_exponent)
        self.d = cp.Variable(pos=True, name="d")
        self.r = cp.Variable(pos=True, name="r")
        self.n = cp.Variable(pos=True, name="n")
        self.t = cp.Variable(pos=True, name="t") if correction != "none" else None
        self.constraints = {s.name: self._constraint(s) for s in self.specs}
        #: the compression spring's free-length limit (``free_length=True``), see
        #: :meth:`_free_length`; its values are given to :meth:`solve` as keywords
        self.free_length_params = {k: cp.Parameter(pos=True, name=k) for k in FREE_LENGTH_KEYS}
        #: the wire's length with the helix rise in the mass (:meth:`_helix`): the active
        #: coils' pitch ``p``, the length ``w`` of an active coil and ``w_end`` of an end coil;
        #: a drawn spring's solid length (:meth:`_drawn_objective`)
        self.helix = bool(helix) and objective in ("mass", "mass per energy")
        self.drawn = bool(helix) and objective in ("mass", "mass per energy", "solid length")
        self.helix_vars = ([cp.Variable(pos=True, name=k) for k in ("p", "w", "w_end")]
                           if self.helix else [])
        #: the constraints beyond the table, by name (listed in ``active`` when they bind)
        self.named = {**({"free length (buckling)": self._free_length()[0]} if free_length
                         else {}),
                      **({"stress at solid length": self._solid(solid_exponent)[0],
                          "deflection (buckling bound)": self._deflection_bound()}
                         if solid_exponent is not None else {}),
                      **(self._envelope(envelope) if envelope else {})}
        self.internal = self._internal() + list(self.named.values())
        self.objective_expr = self._objective(self.d, self.r, self.n, self.t)
        self.problem = cp.Problem(cp.Minimize(self.objective_expr),
                                  list(self.constraints.values()) + self.internal)
        if not self.problem.is_dgp(dpp=True):  # pragma: no cover - construction guarantees it
            raise AssertionError("spring GP is not DGP/DPP")
        self._relaxed: dict[str, Any] | None = None
        self._band: SpringGP | None = None

    # -- building blocks -----------------------------------------------------------------------

    def _objective(self, d, r, n, t):
        if self.drawn:
            return self._drawn_objective()
        return _objective_expr(self.objective_name, d, r, n, t, self.params, self.correction,
                               self.end_coils)

    def _drawn_objective(self):
        """The designer's objectives (``helix``): the mass (or mass per energy) with the helix
        rise (:meth:`_helix_objective`), the solid length ``(n + solid_coils) d_max`` of the
        end form with the largest wire diameter (EN 13906-1, as :meth:`_working_length`)."""
        if self.objective_name == "solid length":
            Q = self.free_length_params
            return (self.n + Q["solid_coils"]) * (self.d + Q["d_tol"])
        return self._helix_objective()

    def _helix_objective(self):
        """The mass with the wire's helix rise (:func:`govopt.springs.helical.helix_mass`):
        ``rho pi d^2 / 4 (n w + end_coils w_end)``, ``w`` and ``w_end`` the lengths of an
        active and an end coil (:meth:`_helix`); or that mass over the energy stored at
        ``F_max``, ``F_max^2 / (2 R)``. Posynomials: the GP stays exact."""
        d, r, n, P = self.d, self.r, self.n, self.params
        _, w, w_end = self.helix_vars
        Q = self.end_coils
        if self.objective_name == "mass":
            return P["density"] * np.pi / 4.0 * d**2 * (n * w + Q * w_end if Q else n * w)
        # m 2 R / F^2, R = G d^4 / (64 r^3 n)
        return (P["density"] * np.pi * P["G"] / 128.0 * P["F_max"]**-2 * d**6 * r**-3
                * (w + Q * w_end * n**-1 if Q else w))

    def _pitch(self):
        """The active coils' free pitch ``m = (L0 - L_c)/n + d`` (m, EN 13906-1's ``s_c / n +
        d``, :func:`govopt.springs.compression.pitch`), a posynomial: with the least free length
        ``L0 = L_c + S_a + F_max / R`` it is ``S_a / n + F_max / (R n) + d`` (``pitch_clear``
        1, ``pitch_L2`` tiny), whatever the solid length; with an installed length ``L2`` at
        ``F_max`` the pitch ``(L2 - L_c)/n + F_max/(R n) + d`` lies between that (``L2 >=
        L_n``: a relaxation) and ``L2/n + F_max/(R n) + d`` (``pitch_L2 = L2``, ``pitch_clear``
        tiny: a restriction). An extension spring's coils touch: ``pitch_F`` and
        ``pitch_clear`` tiny, the pitch ``d``."""
        d, r, n, P, Q = self.d, self.r, self.n, self.params, self.free_length_params
        return (Q["pitch_clear"] * 1.5 * (0.006 * r**2 / d + 0.1 * d) + Q["pitch_L2"] / n
                + Q["pitch_F"] * 64.0 * P["F_max"] * r**3 / (P["G"] * d**4) + d)

    def _helix(self) -> list:
        """The coils' lengths with the helix rise: ``p >= m`` (:meth:`_pitch`), an active coil
        ``w >= sqrt((2 pi r)^2 + p^2)`` and an end coil, wound at the pitch ``d``, ``w_end >=
        sqrt((2 pi r)^2 + d^2)``, as the posynomials ``((2 pi r)^2 + p^2) / w^2 <= 1``; the
        objective grows with each, so each holds with equality at the optimum."""
        if not self.helix:
            return []
        p, w, w_end = self.helix_vars
        ring = 4.0 * np.pi**2 * self.r**2
        return [self._pitch() <= p, (ring + p**2) / w**2 <= 1.0,
                (ring + self.d**2) / w_end**2 <= 1.0]

    def _internal(self) -> list:
        """Wahl auxiliary ``1/(t C) + 1/C <= 1`` with ``C = 2r/d``, i.e. ``t >= 1/(C - 1)``;
        Bergstraesser's ``1/(t C) + 0.75/C <= 1``, i.e. ``t >= 1/(C - 0.75)``; the helix's
        coil lengths (:meth:`_helix`)."""
        if self.t is None:
            return self._helix()
        if self.correction == "bergstrasser":
            return [self.d / (2.0 * self.r * self.t) + 0.75 * self.d / (2.0 * self.r) <= 1.0,
                    *self._helix()]
        return [self.d / (2.0 * self.r * self.t) + self.d / (2.0 * self.r) <= 1.0,
                *self._helix()]

    def _free_length(self) -> list:
        """``L0 <= L0_over_D_max D`` with ``L0 = (n + solid_coils) d + 1.5 n (0.0015 D^2/d +
        0.1 d) + F_max / R`` (m): the least free length that keeps the coils clear at the
        largest force under dynamic load (EN 13906-1:2013, least working length ``L_n = L_c +
        S_a``, ``S_a`` x1.5 dynamic, cold coiled; ``L_c = (n_t + extra) d``), a posynomial in
        ``d, r, n`` (``F/R = 64 F r^3 n / (G d^4)``). With ``L0_over_D_max`` the EN 13906-1
        9.14 slenderness below which the spring cannot buckle it is a sufficient (posynomial)
        buckling constraint."""
        return [self._least_free_length()
                <= self.free_length_params["L0_over_D_max"] * 2.0 * self.r]

    def _least_free_length(self):
        """The free length ``L0 = clear (L_c + S_a) + L2 + F_max / R`` (m), a posynomial:
        without an installed length (``clear`` 1, ``L2`` tiny) the least that keeps the coils
        clear at ``F_max`` under dynamic load, ``L_c + S_a = (n + solid_coils) d + 1.5 n (0.0015
        D^2/d + 0.1 d)`` (EN 13906-1:2013, least working length ``L_n = L_c + S_a``, ``S_a``
        x1.5 dynamic, cold coiled; ``L_c = (n_t + extra) d``); with the installed length ``L2``
        at ``F_max`` (``clear`` tiny) ``L2 + F_max / R`` (``F/R = 64 F r^3 n / (G d^4)``)."""
        d, r, n, P, Q = self.d, self.r, self.n, self.params, self.free_length_params
        return (Q["clear"] * self._working_length() + Q["L2"]
                + 64.0 * P["F_max"] * r**3 * n / (P["G"] * d**4))

    def _working_length(self):
        """The least working length ``L_n = L_c + S_a`` of :meth:`_least_free_length` (m), the
        solid length with the largest wire diameter ``d + d_tol`` (EN 13906-1; ``d_tol`` the
        wire's tolerance, a constant over a row of the wire standard's table)."""
        d, r, n, Q = self.d, self.r, self.n, self.free_length_params
        return ((n + Q["solid_coils"]) * (d + Q["d_tol"])
                + 1.5 * n * (0.006 * r**2 / d + 0.1 * d))

    def _envelope(self, kind: str) -> dict:
        """The space a spring is built into: inside diameter over a rod ``D - d >= Di_min``
        (the posynomial ``(Di_min + d) / (2 r) <= 1``) and, for a compression spring, the free
        length of :meth:`_least_free_length` ``<= L0_max``, the solid length ``(n +
        solid_coils) d <= Lc_max`` (EN 13906-1:2013, ``L_c = (n_t + extra) d``) and the least
        working length ``L_c + S_a <= Ln_max``, the installed length at ``F_max`` (coils clear,
        EN 13906-1: ``L_n`` is the shortest working length allowed). With ``pitch_on`` 1 (tiny:
        off) the free pitch ``m = (L0 - L_c)/n + d <= 0.7 (D - d)`` (Gutekunst, as
        :func:`govopt.springs.compression.max_pitch`) as the posynomial ``L0/n + 0.7 d <= 1.4 r``,
        a restriction (``m <= L0/n``: the ``solid_coils d / n`` it drops is small)."""
        d, r, n, Q = self.d, self.r, self.n, self.free_length_params
        out = {"inside diameter": (Q["Di_min"] + d) / (2.0 * r) <= 1.0}
        if kind == "compression":
            out["free length"] = self._least_free_length() <= Q["L0_max"]
            out["solid length"] = (n + Q["solid_coils"]) * (d + Q["d_tol"]) <= Q["Lc_max"]
            out["working length"] = self._working_length() <= Q["Ln_max"]
            # m = (L0 - L_c)/n + d = L0/n - solid_coils d/n <= L0/n: a restriction
            out["free pitch"] = (Q["pitch_on"] * (self._least_free_length() / n + 0.7 * d)
                                 <= 1.4 * r)
        return out

    def _deflection_bound(self):
        """``F_max / R <= s_over_D_max D``: with ``s_over_D_max`` the slenderness ``L0_cr / D``
        below which a spring cannot buckle (EN 13906-1:2013, 9.14) every spring that passes
        the buckling check satisfies it: below ``L0_cr`` the deflection is less than the free
        length, and above it ``s_K = L0 0.5/(1 - G/E) (1 - sqrt(1 - u^2))``, ``u = L0_cr/L0``,
        grows with ``u`` to ``0.5 L0_cr / (1 - G/E) < L0_cr`` at ``u = 1`` (G/E < 0.5). A
        monomial constraint: the GP with it and without :meth:`_free_length` is a relaxation
        of buckling, a certified lower bound."""
        d, r, n, P = self.d, self.r, self.n, self.params
        return (64.0 * P["F_max"] * r**3 * n / (P["G"] * d**4)
                <= self.free_length_params["s_over_D_max"] * 2.0 * r)

    def _solid(self, m: float) -> list:
        """The shear stress at solid length ``tau_c d^m <= k_solid`` (EN 13906-1:2013, static
        stress at solid length ``L_c``, allowable ``0.56 R_m(d)`` taken as ``k_solid d^-m``
        like the working one). With the least free length of :meth:`_free_length` the force at
        solid length is ``F_c = F_max + R S_a = F_max + 1.5 G (0.006 d^3/(64 r) + 0.1 d^5 /
        (64 r^3))`` (N), a posynomial; the stress correction is the GP's (as
        :func:`govopt.springs.helical.shear_stress_r`: none, Wahl ``1 + 0.75 t + 0.615/C`` or
        Bergstraesser ``1 + 1.25 t``). With an installed length ``L2`` at ``F_max``
        (``clear_solid`` tiny, ``L2_solid = L2``) the force at solid length ``F_max + R (L2 -
        L_c)`` is bounded by ``F_max + R L2`` (``R L2 = G d^4 L2 / (64 r^3 n)``, a monomial): a
        restriction, as ``- R L_c`` is not a posynomial."""
        d, r, t, P = self.d, self.r, self.t, self.params
        Q = self.free_length_params
        F = (P["F_max"] + Q["clear_solid"] * 1.5 * P["G"]
             * (0.006 * d**3 / (64.0 * r) + 0.1 * d**5 / (64.0 * r**3))
             + P["G"] * d**4 * Q["L2_solid"] / (64.0 * r**3 * self.n))
        base = r * d**-3
        if self.correction == "wahl":
            g = base + 0.75 * t * base + 0.3075 * d**-2
        elif self.correction == "bergstrasser":
            g = base + 1.25 * t * base
        else:
            g = base
        return [16.0 / np.pi * F * g * d**m <= self.free_length_params["k_solid"]]

    def _constraint(self, s: GPForm, slack=None):
        g = s.g(self.d, self.r, self.n, self.t, self.params)
        c = self.params[s.limit]
        if s.sense == "upper":
            return g <= c if slack is None else g <= c * slack
        if s.sense == "lower":
            return g >= c if slack is None else g * slack >= c
        if slack is None:
            return g == c
        return [g <= c * slack, g * slack >= c]

    def values(self, **values) -> dict[str, float]:
        """The complete, validated parameter values a solve with these keywords would use."""
        return complete_values(values, self.stiffness_mode)

    def _assign(self, v: Mapping[str, float]) -> None:
        for k, p in self.params.items():
            p.value = v[k]

    def _run(self, problem: cp.Problem) -> tuple[str, Any, float]:
        """Solve ``problem`` as a GP; returns (status, raw solver output, wall time).

        With the tight default Clarabel tolerances a nearly infeasible problem can run out of
        iterations instead of proving infeasibility; such a solve is repeated once with
        Clarabel's own tolerances.
        """
        t0 = time.perf_counter()
        status, raw = self._run_once(problem, self.solver_opts)
        if status not in (cp.OPTIMAL, "infeasible") and self._fallback_opts is not None:
            status, raw = self._run_once(problem, self._fallback_opts)
        return status, raw, time.perf_counter() - t0

    def _run_once(self, problem: cp.Problem, opts: Mapping[str, Any]) -> tuple[str, Any]:
        opts = dict(opts)
        raw = None
        try:
            data, chain, inverse = problem.get_problem_data(self.solver, gp=True,
                                                            solver_opts=opts)
            raw = chain.solve_via_data(problem, data, False, False, opts)
            with warnings.catch_warnings():  # "may be inaccurate", exp overflow: in the status
                warnings.simplefilter("ignore", UserWarning)
                warnings.simplefilter("ignore", RuntimeWarning)
                problem.unpack_results(raw, chain, inverse)
            status = problem.status
        except cp.error.SolverError:
            status = None
        return _normalise_status(status), raw

    # -- solve ---------------------------------------------------------------------------------

    def solve(self, *, certify: bool = False, **values) -> SpringSolution:
        """Solve for the given values; never raises on infeasibility (``status='infeasible'``).

        ``certificate`` always carries the solver's primal/dual objectives (log space) and gap;
        ``certify=True`` adds an independent KKT check (stationarity, complementary slackness,
        feasibility) evaluated from the cvxpy expressions at the returned point.
        """
        v = self._assign_all(values)
        status, raw, elapsed = self._run(self.problem)
        sol = SpringSolution(status=status, objective_name=self.objective_name,
                             correction=self.correction, solver_status=self.problem.status,
                             solve_time=elapsed, inputs=v, end_coils=self.end_coils)
        sol.certificate = self._solver_certificate(raw, status)
        if status not in SOLVED:
            return sol
        self._fill(sol, v)
        if certify:
            sol.certificate.update(self._kkt())
            sol.certificate["global_optimum"] = bool(
                sol.certificate["global_optimum"]
                and sol.certificate["kkt_stationarity"] <= 1e-5
                and sol.certificate["kkt_complementarity"] <= 1e-6
                and sol.certificate["kkt_primal_infeasibility"] <= 1e-6)
        return sol

    def _assign_all(self, values: dict) -> dict[str, float]:
        """Set the parameters: the :data:`FREE_LENGTH_KEYS` given (or far off, as their
        defaults say) and the table's values (completed, checked); returns the latter."""
        extra = {k: values.pop(k, None) for k in FREE_LENGTH_KEYS}
        for k, p in self.free_length_params.items():
            x = extra[k]
            p.value = float(_FREE_LENGTH_DEFAULTS.get(k, 1e9) if x is None else x)
        v = self.values(**values)
        self._assign(v)
        return v

    def _fill(self, sol: SpringSolution, v: Mapping[str, float]) -> None:
        sol.set_design(*(float(x.value) for x in (self.d, self.r, self.n)), v, self.correction)
        sol.t = float(self.t.value) if self.t is not None else None
        sol.objective = float(self.problem.value)
        psens = dict.fromkeys(self.parameter_names, 0.0)
        psens.update(_OBJECTIVE_EXPS.get(self.objective_name, {}))
        for s in self.specs:
            lam = float(np.asarray(self.constraints[s.name].dual_value))
            sol.duals[s.name] = lam
            exps = s.log_exponents()
            sol.sensitivities[s.name] = lam * exps[s.limit]
            for key, e in exps.items():
                psens[key] += lam * e
        sol.parameter_sensitivities = psens
        _, ratios = check_design(sol.d, sol.r, sol.n, v, self.correction,
                                 allowable_exponent=self.allowable_exponent)
        sol.active = [k for k, q in ratios.items() if q >= 1.0 - 1e-6] + [
            k for k, c in self.named.items() if float(np.asarray(c.dual_value)) > 1e-6]
        for name, c in self.named.items():  # lhs <= rhs, the limit in rhs: -dual
            lam = float(np.asarray(c.dual_value))
            if name == "inside diameter":  # (Di_min + d) / (2 r) <= 1: the limit in lhs
                Di = float(self.free_length_params["Di_min"].value)
                sol.sensitivities[name] = lam * Di / (Di + sol.d)
            else:
                sol.sensitivities[name] = -lam

    def _solver_certificate(self, raw, status) -> dict[str, Any]:
        cert: dict[str, Any] = {"solver": self.solver, "status": status,
                                "global_optimum": False}
        if status not in SOLVED:
            return cert
        pobj = getattr(raw, "obj_val", None)
        dobj = getattr(raw, "obj_val_dual", None)
        if isinstance(raw, dict):  # SCS / ECOS style
            info = raw.get("info", {})
            pobj, dobj = info.get("pobj", pobj), info.get("dobj", dobj)
        if pobj is None or dobj is None or not (math.isfinite(pobj) and math.isfinite(dobj)):
            return cert
        gap = abs(float(pobj) - float(dobj))
        cert.update({
            "primal_objective_log": float(pobj),
            "dual_objective_log": float(dobj),
            "duality_gap_log": gap,
            # objective* >= objective * exp(-gap): a relative suboptimality bound
            "relative_gap": math.expm1(min(gap, 700.0)),
            "primal_residual": float(getattr(raw, "r_prim", math.nan)),
            "dual_residual": float(getattr(raw, "r_dual", math.nan)),
            "iterations": int(getattr(raw, "iterations", -1)),
        })
        if status == cp.OPTIMAL:
            value = self.problem.value
            cert["objective_lower_bound"] = float(value) * math.exp(-gap) if value else math.nan
            cert["global_optimum"] = gap <= 1e-6
        return cert

    def _kkt(self, eps: float = 1e-6) -> dict[str, float]:
        """KKT residuals in log space, evaluated with cvxpy's own expressions.

        In ``y = log x`` the GP is convex, so a point with (numerically) zero residuals is a
        global minimum — independent of the solver's self-reported gap.
        """
        xs = ([self.d, self.r, self.n] + ([self.t] if self.t is not None else [])
              + self.helix_vars)
        saved = [float(x.value) for x in xs]
        cons = list(self.constraints.values()) + self.internal
        duals = np.array([float(np.asarray(c.dual_value)) for c in cons])
        is_eq = np.array([isinstance(c, cp.constraints.Equality) for c in cons])
        obj = self.problem.objective.args[0]

        def h(y):
            for x, yi in zip(xs, y, strict=True):
                x.value = math.exp(yi)
            f = math.log(float(obj.value))
            hs = np.array([math.log(float(c.args[0].value)) - math.log(float(c.args[1].value))
                           for c in cons])
            return f, hs

        try:
            y0 = np.log(saved)
            _, h0 = h(y0)
            grad = np.zeros(len(xs))
            for k in range(len(xs)):
                e = np.zeros(len(xs))
                e[k] = eps
                fp, hp = h(y0 + e)
                fm, hm = h(y0 - e)
                grad[k] = (fp - fm) / (2 * eps) + duals @ (hp - hm) / (2 * eps)
        finally:
            for x, val in zip(xs, saved, strict=True):
                x.value = val
        ineq = ~is_eq
        return {
            "kkt_stationarity": float(np.max(np.abs(grad))),
            "kkt_complementarity": float(np.max(np.abs(duals[ineq] * h0[ineq]), initial=0.0)),
            "kkt_primal_infeasibility": float(max(np.max(h0[ineq], initial=0.0),
                                                  np.max(np.abs(h0[is_eq]), initial=0.0))),
            "kkt_dual_infeasibility": float(max(0.0, -np.min(duals[ineq], initial=0.0))),
        }

    # -- infeasibility diagnosis ---------------------------------------------------------------

    def _limit_names(self) -> list[str]:
        """The limits the diagnosis may move: the table's rows, then the named constraints
        beyond it (the space, the free and solid lengths, buckling's bounds)."""
        return [s.name for s in self.specs] + list(self.named)

    def _relaxed_problem(self) -> dict[str, Any]:
        if self._relaxed is None:
            m = len(self.specs) + len(self.named)
            s = cp.Variable(m, pos=True, name="slack")
            smax = cp.Parameter(m, pos=True, name="slack_max")
            cons_by_name: dict[str, list] = {}
            cons: list = []
            for i, spec in enumerate(self.specs):
                c = self._constraint(spec, slack=s[i])
                c = c if isinstance(c, list) else [c]
                cons_by_name[spec.name] = c
                cons += c
            for i, (name, c) in enumerate(self.named.items(), start=len(self.specs)):
                lhs, rhs = c.args  # posynomial <= monomial: its right side scaled
                cons_by_name[name] = [lhs <= rhs * s[i]]
                cons += cons_by_name[name]
            cons += [s <= smax, s >= 1.0] + self._internal()
            prob = cp.Problem(cp.Minimize(cp.prod(s)), cons)
            if not prob.is_dgp(dpp=True):  # pragma: no cover
                raise AssertionError("relaxed spring GP is not DGP/DPP")
            self._relaxed = {"problem": prob, "s": s, "smax": smax, "cons": cons_by_name}
        return self._relaxed

    def diagnose(self, *, fixed: Iterable[str] = (), max_factor: float = 1e6,
                 **values) -> Diagnosis:
        """Which limits must move, and by what factor, to make the specification feasible.

        Solves the relaxed GP: every limit is scaled by a slack ``s_i in [1, max_factor]`` (upper
        limits multiplied, lower limits divided, the stiffness equality widened both ways) and
        ``prod s_i`` — i.e. ``sum log s_i``, which favours moving few limits — is minimised.
        Limits named in ``fixed`` may not move. Then, for each movable limit, solves again with
        only that one free (``single_fixes``).
        """
        self._assign_all(dict(values))
        rel = self._relaxed_problem()
        fixed = set(fixed)
        names = self._limit_names()
        unknown = fixed - set(names)
        if unknown:
            raise ValueError(f"unknown constraint names {sorted(unknown)}; known: {names}")
        free = np.array([1.0 if nm in fixed else max_factor for nm in names])
        rel["smax"].value = free
        status, _, _ = self._run(rel["problem"])
        diag = Diagnosis(feasible=False, status=status)
        if status not in SOLVED:
            return diag
        s_val = np.asarray(rel["s"].value, dtype=float)
        diag.total_relaxation = float(np.prod(s_val))
        diag.feasible = bool(np.all(s_val <= 1.0 + 1e-6))
        d, r, n = (float(x.value) for x in (self.d, self.r, self.n))
        diag.design = {"d": d, "r": r, "n": n}
        factors = self._limit_factors()
        mult = {nm: float(sum(float(np.asarray(c.dual_value)) for c in rel["cons"][nm]))
                for nm in names}
        diag.multipliers = mult
        if diag.feasible:
            return diag
        diag.relaxations = {nm: factors[nm] for i, nm in enumerate(names)
                            if s_val[i] > 1.0 + 1e-6}
        diag.conflicting = [nm for nm in sorted(names, key=lambda k: -mult[k])
                            if mult[nm] > 1e-6]
        for i, nm in enumerate(names):
            if nm in fixed:
                continue
            only = np.ones(len(names))
            only[i] = max_factor
            rel["smax"].value = only
            st, _, _ = self._run(rel["problem"])
            if st == cp.OPTIMAL:
                diag.single_fixes[nm] = self._limit_factors()[nm]
        return diag

    def _limit_factors(self) -> dict[str, float]:
        """``g / limit`` for every named constraint at the current variable values (the
        constraints beyond the table: left side over right side)."""
        out = {}
        for s in self.specs:
            g = s.g(self.d, self.r, self.n, self.t, self.params)
            out[s.name] = float(g.value) / float(self.params[s.limit].value)
        for name, c in self.named.items():
            lhs, rhs = c.args
            out[name] = float(lhs.value) / float(rhs.value)
        return out

    # -- discrete catalogue --------------------------------------------------------------------

    def best_discrete(self, catalogue_d: Sequence[float], *, turn_step: float = 0.5,
                      r_step: float = 1e-3, stiffness_tol: float = 0.02, prune: bool = True,
                      rtol: float = 1e-9, **values) -> DiscreteSolution:
        """The exact best design with ``d`` from ``catalogue_d``, ``n`` a multiple of
        ``turn_step`` and ``r`` a multiple of ``r_step``.

        An exact stiffness is out of reach with discrete ``(d, r, n)``, so the discrete design
        must have ``|k / kappa - 1| <= stiffness_tol`` (in ``stiffness="band"`` mode the given
        ``kappa_min``/``kappa_max`` are used instead). Method (exact, not heuristic):

        1. the GP with the same stiffness band gives the continuous bound;
        2. per catalogue wire, the GP with ``d`` fixed gives a lower bound; wires are visited in
           order of bound and skipped once the bound exceeds the incumbent (``prune``);
        3. for a visited wire every ``r`` on the grid allowed by the index, radius, envelope,
           stress and stiffness bounds is enumerated; as every objective is non-decreasing in
           ``n`` and every limit on ``n`` is one-sided, the least ``n`` on the turn grid above
           the lower limits is the best ``n`` for that ``(d, r)``;
        4. each candidate is re-checked with :func:`check_design` (``spring.py`` formulas).

        Raises ``ValueError`` if one wire would need more than 5 million radii (``r_step`` far
        too fine for the bounds). Designs are accepted with relative tolerance ``rtol``.
        """
        if self.stiffness_mode == "equality":
            v = self.values(**values)
            if not 0.0 <= stiffness_tol < 1.0:
                raise ValueError(f"stiffness_tol must be in [0, 1), got {stiffness_tol!r}")
            band_values = {k: x for k, x in v.items() if k != "kappa"}
            band_values["kappa_min"] = v["kappa"] * (1.0 - stiffness_tol)
            band_values["kappa_max"] = v["kappa"] * (1.0 + stiffness_tol)
            if self._band is None:
                self._band = SpringGP(self.objective_name, self.correction, "band",
                                      self.solver, self.solver_opts, self.allowable_exponent,
                                      self.end_coils)
            band = self._band
        else:
            band_values = self.values(**values)
            band = self
        if turn_step <= 0 or r_step <= 0:
            raise ValueError("turn_step and r_step must be positive")
        cont = band.solve(**band_values)
        out = DiscreteSolution(status="infeasible", objective_name=self.objective_name,
                               continuous=cont, end_coils=self.end_coils)
        if cont.status == "infeasible":
            return out
        out.continuous_bound = cont.objective if cont.ok else 0.0
        lo, hi = band_values["d_min"] * (1 - rtol), band_values["d_max"] * (1 + rtol)
        wires = sorted({float(w) for w in catalogue_d if lo <= w <= hi})
        table = []
        for w in wires:
            lb = 0.0
            if prune:
                fixed = band.solve(**{**band_values, "d_min": w, "d_max": w})
                if fixed.status == "infeasible":
                    lb = math.inf
                elif fixed.ok:
                    lb = fixed.objective
            table.append({"d": w, "lower_bound": lb, "objective": None, "pruned": False})
        table.sort(key=lambda row: row["lower_bound"])
        best: tuple | None = None
        for row in table:
            incumbent = best[0] if best else math.inf
            if math.isinf(row["lower_bound"]) or row["lower_bound"] > incumbent * (1 + 1e-6):
                row["pruned"] = True
                continue
            cand, count = enumerate_wire(row["d"], band_values, self.correction,
                                          self.objective_name, turn_step, r_step, rtol,
                                          allowable_exponent=self.allowable_exponent,
                                          end_coils=self.end_coils)
            out.candidates_checked += count
            if cand is None:
                continue
            row["objective"] = cand[0]
            if best is None or cand[:2] < best[:2]:
                best = cand
        out.per_wire = sorted(table, key=lambda row: row["d"])
        if best is None:
            return out
        obj, _, d, r, n = best
        v_used = band_values
        out.status = "optimal"
        out.set_design(d, r, n, v_used, self.correction)
        out.objective = obj
        kappa = values.get("kappa") or math.sqrt(v_used["kappa_min"] * v_used["kappa_max"])
        out.stiffness_error = out.stiffness / float(kappa) - 1.0
        if out.continuous_bound > 0:
            out.gap = obj / out.continuous_bound - 1.0
        return out


def best_discrete(solution_bounds: Mapping[str, float] | SpringSolution,
                  catalogue_d: Sequence[float], turn_step: float = 0.5, r_step: float = 1e-3,
                  *, stiffness_tol: float = 0.02, correction: str = "wahl",
                  objective: str = "mass", prune: bool = True) -> DiscreteSolution:
    """Best catalogue design for a specification (see :meth:`SpringGP.best_discrete`).

    ``solution_bounds`` is the dict of :meth:`SpringGP.solve` values, or a continuous
    :class:`SpringSolution` (its ``inputs``, correction and objective are reused).
    """
    if isinstance(solution_bounds, SpringSolution):
        correction = solution_bounds.correction
        objective = solution_bounds.objective_name
        solution_bounds = solution_bounds.inputs
    gp = cached_gp(objective, correction)
    return gp.best_discrete(catalogue_d, turn_step=turn_step, r_step=r_step,
                            stiffness_tol=stiffness_tol, prune=prune, **solution_bounds)


# ----------------------------------------------------------------------------------------------
# Generic sizing entry point
# ----------------------------------------------------------------------------------------------

_local = threading.local()


def cached_gp(objective: str, correction: str, stiffness: str = "equality",
               allowable_exponent: float = 0.0, end_coils: float = 0.0,
               free_length: bool = False, solid_exponent: float | None = None,
               envelope: str | None = None, helix: bool = False) -> SpringGP:
    """One compiled GP per (objective, correction, stiffness mode, allowable exponent) and
    thread (parameters are mutated): every solve sets every parameter, so a shared GP gives the
    same optimum as a fresh one, without the compilation."""
    cache = getattr(_local, "cache", None)
    if cache is None:
        cache = _local.cache = {}
    key = (objective, correction, stiffness, float(allowable_exponent), float(end_coils),
           free_length, solid_exponent, envelope, helix)
    if key not in cache:
        cache[key] = SpringGP(objective, correction, stiffness,
                              allowable_exponent=allowable_exponent, end_coils=end_coils,
                              free_length=free_length, solid_exponent=solid_exponent,
                              envelope=envelope, helix=helix)
    return cache[key]


def size_helical_spring(F_max: float | None = None, stiffness: float | None = None, *,
                        loads: Sequence[float] | None = None, k_s: float, G: float,
                        density: float, correction: str = "wahl", objective: str = "mass",
                        end_coils: float = 0.0, envelope: str | None = None,
                        **bounds) -> SpringSolution:
    """Least-mass helical spring for given loads, material and envelope, as an exact GP.

    Give either ``stiffness`` (N/m) with ``F_max`` (N), or ``loads=(F1, x1, F2, x2)``: two
    working points (force at deflection), from which ``stiffness = (F2 - F1)/(x2 - x1)`` and
    ``F_max = max(|F1|, |F2|, F_max)``; the implied preload ``F1 - stiffness x1`` (initial
    tension of an extension spring) is reported in ``extras``. ``bounds`` are the optional
    limits of :data:`DEFAULT_BOUNDS` (``d_min``, ``D_out_max``, ``L_body_max``, ...).

    The returned ``certificate`` proves global optimality: a GP is convex in log space, so a
    solved status with a small primal-dual gap (``duality_gap_log``, a bound on
    ``log(objective / optimum)``) and small KKT residuals is a global optimum; the entry
    ``global_optimum`` summarises it.
    """
    extras: dict[str, float] = {}
    if loads is not None:
        F1, x1, F2, x2 = (float(x) for x in loads)
        if x2 == x1:
            raise ValueError("loads need two different deflections")
        kappa = (F2 - F1) / (x2 - x1)
        if kappa <= 0:
            raise ValueError(f"loads give a non-positive stiffness {kappa!r}")
        if stiffness is not None and not math.isclose(stiffness, kappa, rel_tol=1e-9):
            raise ValueError(f"stiffness {stiffness!r} contradicts loads (give one of them)")
        F_max = max(abs(F1), abs(F2), F_max or 0.0)
        extras = {"preload": F1 - kappa * x1, "stiffness_from_loads": kappa}
        stiffness = kappa
    if stiffness is None or F_max is None:
        raise TypeError("give F_max and stiffness, or loads=(F1, x1, F2, x2)")
    gp = cached_gp(objective, correction, end_coils=end_coils, envelope=envelope)
    sol = gp.solve(certify=True, kappa=stiffness, F_max=F_max, k_s=k_s, G=G, density=density,
                   **bounds)
    sol.extras = extras
    return sol
