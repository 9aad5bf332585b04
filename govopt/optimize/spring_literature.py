"""The optimisation literature's tension/compression spring (Belegundu 1982; Arora, *Introduction
to Optimum Design*) solved as an exact geometric programme, with a certified lower bound.

Minimise the wire volume ``(N + 2) D d^2`` (``d`` wire, ``D`` mean coil diameter, inches;
``N`` active coils, two end coils) subject to

=====  ==============================================================  =======================
g1     ``1 - D^3 N / (c1 d^4) <= 0``                                   least deflection
g2     ``(4 D^2 - d D) / (12566 (D d^3 - d^4)) + 1/(5108 d^2) - 1 <= 0``  Wahl-corrected stress
g3     ``1 - 140.45 d / (D^2 N) <= 0``                                 least surge frequency
g4     ``(D + d) / 1.5 - 1 <= 0``                                      outside diameter
=====  ==============================================================  =======================

and the usual box ``0.05 <= d <= 2``, ``0.25 <= D <= 1.3``, ``2 <= N <= 15``. The constants
follow from Arora's data: ``P = 10 lbf``, least deflection ``0.5 in``, ``G = 1.15e7 psi``,
``tau_a = 80 000 psi``, mass density ``7.38342e-4 lbf s^2/in^4``, least surge frequency 100 Hz,
``D + d <= 1.5 in``: ``c1 = G delta / (8 P) = 71 875`` (the literature prints 71 785, a
transposition), ``12566 = pi tau_a / (2 P)``, ``5108 = pi tau_a / (8 P 0.615)`` and ``140.45 =
sqrt(G / (2 rho)) / (2 pi f_min)``: see :func:`constants`.

g2 is not a posynomial as printed, but ``(4D - d)/(4(D - d)) = 1 + 0.75/(C - 1)`` (``C = D/d``)
is Wahl's first term: with an auxiliary ``t >= 1/(C - 1)``, written ``1/(t C) + 1/C <= 1``
(as in :mod:`govopt.optimize.spring_gp`), g2 becomes the posynomial
``4 D (1 + 0.75 t) / (12566 d^3) + 1/(5108 d^2) <= 1`` with the same optimum (raising ``t`` only
tightens it). So the problem is an exact GP: its optimum is global and the solver's dual
objective is a certified lower bound.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import cvxpy as cp
import numpy as np

__all__ = ["PRINTED_C1", "SANDGREN", "SANDGREN_WIRES", "BelegunduSpring", "SandgrenSpring",
           "constants", "constraints", "sandgren_constraints", "solve_belegundu",
           "solve_sandgren"]

#: g1's constant as printed in the literature (Belegundu 1982, Arora, and the papers after them)
PRINTED_C1 = 71785.0


def constants(P=10.0, delta=0.5, G=1.15e7, tau_a=80_000.0, rho=7.38342e-4, f_min=100.0):
    """The constants of g1..g3 from the physical data (inch, lbf, s):
    ``c1 = G delta / (8 P)`` (deflection ``8 P D^3 N / (G d^4) >= delta``),
    ``c2 = pi tau_a / (2 P)`` and ``c3 = pi tau_a / (8 P 0.615)`` (Wahl's factor
    ``(4C - 1)/(4C - 4) + 0.615/C`` in ``8 P D K / (pi d^3) <= tau_a``), and
    ``c4 = sqrt(G / (2 rho)) / (2 pi f_min)`` (surge ``d / (2 pi N D^2) sqrt(G/(2 rho))``,
    Wahl 1944 ch. 25)."""
    s = math.pi * tau_a / (8.0 * P)
    return {"c1": G * delta / (8.0 * P), "c2": 4.0 * s, "c3": s / 0.615,
            "c4": math.sqrt(G / (2.0 * rho)) / (2.0 * math.pi * f_min)}


def constraints(d, D, N, c1=PRINTED_C1):
    """``g1..g4`` as printed (``<= 0`` holds) and the objective ``(N + 2) D d^2``."""
    g = np.array([1.0 - D**3 * N / (c1 * d**4),
                  (4 * D**2 - d * D) / (12566.0 * (D * d**3 - d**4)) + 1 / (5108.0 * d**2) - 1,
                  1.0 - 140.45 * d / (D**2 * N),
                  (D + d) / 1.5 - 1.0])
    return g, (N + 2) * D * d**2


@dataclass
class BelegunduSpring:
    d: float
    D: float
    N: float
    objective: float
    lower_bound: float  # the solver's dual objective: no design can do better
    status: str


def solve_belegundu(c1: float = PRINTED_C1) -> BelegunduSpring:
    """The exact GP of the module docstring (inches)."""
    d, D, N, t = (cp.Variable(pos=True) for _ in range(4))
    C = D / d
    cons = [c1 * d**4 / (D**3 * N) <= 1.0,
            4.0 * D * (1.0 + 0.75 * t) / (12566.0 * d**3) + 1.0 / (5108.0 * d**2) <= 1.0,
            1.0 / (t * C) + 1.0 / C <= 1.0,
            D**2 * N / (140.45 * d) <= 1.0, (D + d) / 1.5 <= 1.0,
            d >= 0.05, d <= 2.0, D >= 0.25, D <= 1.3, N >= 2.0, N <= 15.0]
    problem = cp.Problem(cp.Minimize((N + 2.0) * D * d**2), cons)
    opts = {"tol_gap_abs": 1e-12, "tol_gap_rel": 1e-12, "tol_feas": 1e-12}
    data, chain, inverse = problem.get_problem_data("CLARABEL", gp=True, solver_opts=opts)
    raw = chain.solve_via_data(problem, data, False, False, opts)
    problem.unpack_results(raw, chain, inverse)
    # in log space the primal-dual gap bounds log(objective / optimum) (as spring_gp does)
    value = float(problem.value)
    bound = value * math.exp(-abs(float(raw.obj_val) - float(raw.obj_val_dual)))
    return BelegunduSpring(float(d.value), float(D.value), float(N.value), value, bound,
                           problem.status)


# ---------------------------------------------------------------- Sandgren (1990)

#: Sandgren's 42 standard wire diameters (in), as reproduced by the papers after him.
SANDGREN_WIRES = (0.009, 0.0095, 0.0104, 0.0118, 0.0128, 0.0132, 0.014, 0.015, 0.0162, 0.0173,
                  0.018, 0.020, 0.023, 0.025, 0.028, 0.032, 0.035, 0.041, 0.047, 0.054, 0.063,
                  0.072, 0.080, 0.092, 0.105, 0.120, 0.135, 0.148, 0.162, 0.177, 0.192, 0.207,
                  0.225, 0.244, 0.263, 0.283, 0.307, 0.331, 0.362, 0.394, 0.4375, 0.500)
#: The problem's data (lbf, in, psi): largest and preload force, allowable stress, shear
#: modulus, longest free length, least wire, largest outside diameter, largest preload
#: deflection, least working deflection.
SANDGREN = {"F_max": 1000.0, "S": 189e3, "G": 11.5e6, "l_max": 14.0, "d_min": 0.2,
            "D_max": 3.0, "F_load": 300.0, "delta_pm": 6.0, "delta_w": 1.25}


def sandgren_constraints(N, D, d, p=SANDGREN):
    """Sandgren's compression spring (1990, as restated by Deb and Goyal): ``g1..g8 <= 0`` and
    the objective ``pi^2 D d^2 (N + 2) / 4`` (wire volume, in^3). ``g1`` Wahl-corrected stress
    ``8 C_f F_max D / (pi d^3) <= S``; ``g2`` free length ``l_f = F_max/K + 1.05 (N + 2) d <=
    l_max``; ``g3`` ``d >= d_min``; ``g4`` ``D + d <= D_max``; ``g5`` ``C >= 3``; ``g6`` preload
    deflection ``F_load / K <= delta_pm``; ``g7`` ``delta_p + (F_max - F_load)/K + 1.05 (N + 2) d
    <= l_f`` (identically 0: redundant); ``g8`` ``(F_max - F_load)/K >= delta_w``; ``K = G d^4 /
    (8 N D^3)``."""
    C = D / d
    Cf = (4 * C - 1) / (4 * C - 4) + 0.615 / C
    K = p["G"] * d**4 / (8 * N * D**3)
    lf = p["F_max"] / K + 1.05 * (N + 2) * d
    dp = p["F_load"] / K
    g = np.array(np.broadcast_arrays(
                 8 * Cf * p["F_max"] * D / (np.pi * d**3) - p["S"], lf - p["l_max"],
                  p["d_min"] - d, d + D - p["D_max"], 3.0 - C, dp - p["delta_pm"],
                  dp + (p["F_max"] - p["F_load"]) / K + 1.05 * (N + 2) * d - lf,
                  p["delta_w"] - (p["F_max"] - p["F_load"]) / K))
    return g, np.pi**2 * D * d**2 * (N + 2) / 4


@dataclass
class SandgrenSpring:
    N: int
    D: float
    d: float
    objective: float
    checked: int  # (wire, N) pairs examined: every one that could beat the optimum


def solve_sandgren(p=SANDGREN, wires=SANDGREN_WIRES) -> SandgrenSpring:
    """The exact optimum by enumeration, a certificate in itself. For a wire ``d`` and integer
    ``N`` the objective grows with ``D`` and every upper limit (g1, g2, g4, g6) grows with
    ``D``, while the lower limits (g5 ``D >= 3 d``, g8 ``D^3 >= delta_w G d^4 / (8 N (F_max -
    F_load))``) give the least ``D``: that ``D`` is the best for the pair, if feasible. As
    ``D >= 3 d``, no ``N`` with ``pi^2 3 d^3 (N + 2) / 4`` above the incumbent can win, which
    bounds the ``N`` examined per wire; wires under ``d_min`` (g3) are skipped."""
    best = SandgrenSpring(0, math.nan, math.nan, math.inf, 0)
    for d in sorted(wires, reverse=True):
        if d < p["d_min"]:  # g3 holds or fails whatever N and D
            continue
        N = 1
        while (math.pi**2 * 3.0 * d**3 * (N + 2) / 4.0 <= best.objective
               if math.isfinite(best.objective) else N <= 1000):  # none yet: 1000 coils
            D = max(3.0 * d, (p["delta_w"] * p["G"] * d**4
                              / (8.0 * N * (p["F_max"] - p["F_load"]))) ** (1.0 / 3.0))
            g, f = sandgren_constraints(N, D, d, p)
            best.checked += 1
            if (g <= 1e-12).all() and f < best.objective:
                best = SandgrenSpring(N, float(D), d, float(f), best.checked)
            N += 1
    return best
