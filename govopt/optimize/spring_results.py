"""The helical spring GP's results and the exact check of a design (numpy only, no cvxpy).

:class:`SpringSolution` (a continuous optimum with its sensitivities), :class:`Diagnosis` (why a
specification is infeasible), :class:`DiscreteSolution` (the best catalogue design) and the
figures they share (:class:`SpringFigures`), recomputed with the exact formulas of
:mod:`govopt.springs.helical`; :func:`check_design`, the same check of any designs (arrays);
:func:`enumerate_wire`, the discrete search's grid for one wire. The geometric programme that
makes them is :mod:`govopt.optimize.spring_gp`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from govopt.springs import helical as hx

from .gp_table import complete_values

#: Objectives the GP can minimise (all are posynomials in ``d, r, n``, non-decreasing in ``n``).
#: ``"mass"`` counts ``n + end_coils`` coils (:class:`SpringGP`); ``"volume"`` is the
#: optimisation literature's ``(n + end_coils) D d^2`` (Belegundu 1982, Arora) and
#: ``"solid length"`` the close-wound length ``(n + end_coils) d``.
#: ``"mass per energy"`` is the mass over the energy stored at ``F_max``, ``F_max^2 / (2 R)``:
#: its least is the most stored energy per mass (a posynomial, ``R`` being a monomial).
OBJECTIVES = ("mass", "stress", "outer diameter", "body length", "volume", "solid length",
              "mass per energy")

#: Statuses that carry a usable design.
SOLVED = ("optimal", "optimal_inaccurate")


def spring_force(v, d, r, n):
    """Spring force for the stress check: ``F_max + force_per_stiffness * kappa``."""
    return v["F_max"] + v["force_per_stiffness"] * hx.stiffness_r(d, r, n, v["G"])


def objective_value(objective, d, r, n, v, correction, end_coils=0.0):
    """The objective evaluated with the exact formulas of :mod:`govopt.springs.helical`."""
    if objective == "mass":
        return hx.wire_mass(d, r, n + end_coils, v["density"])
    if objective == "volume":
        return 2.0 * r * d**2 * (n + end_coils)
    if objective == "solid length":
        return (n + end_coils) * d
    if objective == "stress":
        return hx.shear_stress_r(spring_force(v, d, r, n), d, r, correction)
    if objective == "mass per energy":
        R = hx.stiffness_r(d, r, n, v["G"])
        return hx.wire_mass(d, r, n + end_coils, v["density"]) * 2.0 * R / v["F_max"]**2
    if objective == "outer diameter":
        return 2.0 * r + d
    if objective == "body length":
        return (n + 1.0) * d
    raise ValueError(f"objective must be one of {OBJECTIVES}, got {objective!r}")


# ----------------------------------------------------------------------------------------------
# Results
# ----------------------------------------------------------------------------------------------


@dataclass(kw_only=True)
class SpringFigures:
    """A spring's design and the figures derived from it with :mod:`govopt.springs.helical` (SI)."""

    d: float = math.nan
    r: float = math.nan
    n: float = math.nan
    objective: float = math.nan
    mass: float = math.nan
    stiffness: float = math.nan
    stress: float = math.nan
    wahl_factor: float = math.nan
    index: float = math.nan
    outer_diameter: float = math.nan
    body_length: float = math.nan
    surge_frequency: float = math.nan
    #: inactive coils counted in ``mass`` (end coils, hooks; 0: the active coils only)
    end_coils: float = 0.0

    def set_design(self, d: float, r: float, n: float, v: Mapping[str, float],
                   correction: str) -> None:
        """Set ``d, r, n`` and recompute every derived figure from the exact formulas."""
        self.d, self.r, self.n = d, r, n
        self.mass = float(hx.wire_mass(d, r, n + self.end_coils, v["density"]))
        self.stiffness = float(hx.stiffness_r(d, r, n, v["G"]))
        self.stress = float(hx.shear_stress_r(spring_force(v, d, r, n), d, r, correction))
        self.index = float(hx.spring_index_r(d, r))
        self.wahl_factor = float(hx.wahl_factor(self.index)) if correction == "wahl" else 1.0
        self.outer_diameter = 2.0 * r + d
        self.body_length = (n + 1.0) * d
        self.surge_frequency = float(hx.surge_frequency_r(d, r, n, v["G"], v["density"]))


@dataclass
class SpringSolution(SpringFigures):
    """A continuous GP design (SI) with its sensitivities.

    ``sensitivities[name]`` is ``d log(objective) / d log(limit of constraint name)``: e.g.
    ``{'allowable stress': -0.67}`` means 1 % more allowable stress saves 0.67 % of the mass.
    ``duals`` are the raw log-space multipliers from the solver (``>= 0`` for inequalities).
    ``parameter_sensitivities[p]`` is ``d log(objective) / d log(p)`` for every parameter.
    ``stress`` and ``wahl_factor`` are recomputed with :func:`govopt.springs.helical.shear_stress_r`
    and :func:`~govopt.springs.helical.wahl_factor`, not taken from the auxiliary ``t``.
    """

    status: str
    objective_name: str
    correction: str
    t: float | None = None
    duals: dict[str, float] = field(default_factory=dict)
    sensitivities: dict[str, float] = field(default_factory=dict)
    parameter_sensitivities: dict[str, float] = field(default_factory=dict)
    active: list[str] = field(default_factory=list)
    certificate: dict[str, Any] = field(default_factory=dict)
    solver_status: str | None = None
    solve_time: float = math.nan
    inputs: dict[str, float] = field(default_factory=dict)
    extras: dict[str, float] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        """True when the solve produced a design (optimal, possibly inaccurate)."""
        return self.status in SOLVED


@dataclass
class Diagnosis:
    """Why a specification is infeasible, from a relaxed GP.

    Every limit is multiplied (upper limits) or divided (lower limits, both sides of the stiffness
    equality) by a slack ``s_i >= 1`` and the product of the slacks is minimised.

    ``relaxations[name]`` is the factor to multiply that limit by (``> 1`` raise, ``< 1`` lower)
    in the least total relaxation; ``conflicting`` the constraints with a positive multiplier in
    the relaxed problem (the set that cannot hold together), most important first;
    ``single_fixes[name]`` the factor on that limit alone that restores feasibility when no other
    limit moves (absent when moving that limit alone cannot help).
    """

    feasible: bool
    status: str
    relaxations: dict[str, float] = field(default_factory=dict)
    conflicting: list[str] = field(default_factory=list)
    single_fixes: dict[str, float] = field(default_factory=dict)
    total_relaxation: float = 1.0
    design: dict[str, float] = field(default_factory=dict)
    multipliers: dict[str, float] = field(default_factory=dict)

    def summary(self) -> str:
        if self.feasible:
            return "feasible: no limit needs to move"
        parts = [f"{k} x{v:.4g}" for k, v in self.relaxations.items()]
        fixes = [f"{k} x{v:.4g}" for k, v in sorted(self.single_fixes.items(),
                                                      key=lambda kv: abs(math.log(kv[1])))]
        if not self.conflicting and not parts:  # the relaxation problem itself found nothing
            return ("infeasible: no relaxation of the limits within reach makes a spring "
                    "(are the values' orders of magnitude right?)")
        return ("infeasible: conflicting " + ", ".join(self.conflicting)
                + "; least relaxation " + ", ".join(parts)
                + ("; or alone: " + ", ".join(fixes) if fixes else ""))


@dataclass
class DiscreteSolution(SpringFigures):
    """Best design with a catalogue wire, ``n`` on the turn step and ``r`` on its resolution.

    ``continuous_bound`` is the GP optimum with the same stiffness band, a valid lower bound on
    every discrete design; ``gap = objective / continuous_bound - 1``. ``per_wire`` lists, per
    catalogue diameter, the GP lower bound with that wire, the best discrete objective found with
    it (``None`` if none fits) and whether the wire was skipped because its bound could not beat
    the incumbent.
    """

    status: str
    objective_name: str
    stiffness_error: float = math.nan
    continuous_bound: float = math.nan
    gap: float = math.nan
    candidates_checked: int = 0
    per_wire: list[dict[str, Any]] = field(default_factory=list)
    continuous: SpringSolution | None = None

    @property
    def ok(self) -> bool:
        return self.status == "optimal"


# ----------------------------------------------------------------------------------------------
# Exact check of a design with spring.py
# ----------------------------------------------------------------------------------------------


def check_design(d, r, n, values: Mapping[str, float], correction: str = "wahl",
                 rtol: float = 1e-9, allowable_exponent: float = 0.0
                 ) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """Check designs against every constraint with the exact formulas of ``spring.py``.

    Broadcasts over arrays. ``values`` are the :meth:`SpringGP.solve` keywords (``kappa`` for an
    exact stiffness, or ``kappa_min``/``kappa_max`` for a band). Returns ``(feasible, ratios)``,
    where ``ratios[name] <= 1`` means satisfied (value/limit for upper limits, limit/value for
    lower, ``max(k/kappa, kappa/k)`` for the equality); ``feasible`` allows ``rtol``.
    """
    v = complete_values(values, "band" if "kappa" not in values else "equality")
    d, r, n = (np.asarray(a, dtype=float) for a in (d, r, n))
    k = hx.stiffness_r(d, r, n, v["G"])
    C = hx.spring_index_r(d, r)
    with np.errstate(divide="ignore", invalid="ignore"):
        tau = hx.shear_stress_r(spring_force(v, d, r, n), d, r, correction)
        tau = np.where(C > 1.0, tau, np.inf) if correction != "none" else tau
    ratios: dict[str, np.ndarray] = {}
    if "kappa" in v:
        ratios["stiffness"] = np.maximum(k / v["kappa"], v["kappa"] / k)
    else:
        ratios["minimum stiffness"] = v["kappa_min"] / k
        ratios["maximum stiffness"] = k / v["kappa_max"]
    ratios.update({
        "allowable stress": tau * d**allowable_exponent / v["k_s"],
        "minimum wire diameter": v["d_min"] / d,
        "maximum wire diameter": d / v["d_max"],
        "minimum coil radius": v["r_min"] / r,
        "maximum coil radius": r / v["r_max"],
        "minimum active turns": v["n_min"] / n,
        "maximum active turns": n / v["n_max"],
        "minimum spring index": v["C_min"] / C,
        "maximum spring index": C / v["C_max"],
        "outer diameter": (2.0 * r + d) / v["D_out_max"],
        "body length": (n + 1.0) * d / v["L_body_max"],
        "surge frequency": v["f_surge_min"] / hx.surge_frequency_r(d, r, n, v["G"],
                                                                      v["density"]),
    })
    feasible = np.ones(np.broadcast(d, r, n).shape, dtype=bool)
    for ratio in ratios.values():
        feasible &= ratio <= 1.0 + rtol
    return feasible, ratios






def enumerate_wire(d, v, correction, objective, turn_step, r_step, rtol,
                    max_points: int = 5_000_000, allowable_exponent: float = 0.0,
                    end_coils: float = 0.0):
    """Best ``(objective, mass, d, r, n)`` for one wire over the r grid, or ``None``."""
    G, F, k_s = v["G"], v["F_max"], v["k_s"] * d**-allowable_exponent
    r_lo = max(v["r_min"], v["C_min"] * d / 2.0)
    r_hi = min(v["r_max"], v["C_max"] * d / 2.0, (v["D_out_max"] - d) / 2.0,
               # uncorrected stress <= k_s (Wahl's K > 1 only tightens it)
               math.pi * d**3 * k_s / (16.0 * F),
               # stiffness >= kappa_min with n >= n_min
               (G * d**4 / (64.0 * v["n_min"] * v["kappa_min"])) ** (1.0 / 3.0))
    if r_hi < r_lo * (1 - rtol):
        return None, 0
    j_lo = max(1, math.ceil(r_lo / r_step - 1e-9))
    j_hi = math.floor(r_hi / r_step + 1e-9)
    if j_hi < j_lo:
        return None, 0
    if j_hi - j_lo + 1 > max_points:
        raise ValueError(f"r grid too fine: {j_hi - j_lo + 1} radii for d = {d}")
    r = np.arange(j_lo, j_hi + 1, dtype=float) * r_step
    n_lo = np.maximum(v["n_min"], G * d**4 / (64.0 * r**3 * v["kappa_max"]))
    n = np.maximum(np.ceil(n_lo / turn_step - 1e-9), 1.0) * turn_step
    ok, _ = check_design(d, r, n, v, correction, rtol, allowable_exponent)
    if not ok.any():
        return None, r.size
    r, n = r[ok], n[ok]
    obj = objective_value(objective, d, r, n, v, correction, end_coils) * np.ones_like(r)
    mass = hx.wire_mass(d, r, n + end_coils, v["density"])
    i = int(np.lexsort((mass, obj))[0])
    return (float(obj[i]), float(mass[i]), float(d), float(r[i]), float(n[i])), int(ok.size)
