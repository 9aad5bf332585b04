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

import numpy as np

from ._cvxpy import cvxpy as cp

__all__ = ["PRINTED_C1", "BelegunduSpring", "constants", "constraints", "solve_belegundu"]

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
