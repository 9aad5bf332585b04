"""`govopt spring`'s stock design against brute force: over a grid of force, rate and grade
problems, every stock spring (each wire of the grade's table x every coil count on the half turn
x the mean diameter that gives the rate, drawn with the least free length that keeps the coils
clear) is checked with the rows `govopt spring check` reads, and govopt's design is never
heavier than the lightest that passes (nor does it fail a check when one passes).

The enumeration here shares no search code with govopt's: no GP, no bound, no pruning; the
springs are built from the physics functions (EN 13906-1's least working length, the rate
``G d^4 / (8 D^3 n)``), screened with the table's rows over arrays at the checks' own tolerance
(:func:`govopt.verdict.holds`), and the lightest that passes the screen is confirmed with the
scalar checks of :func:`govopt.springs.assessment.table` (`spring check`'s).
"""

import math

import numpy as np
import pytest

from govopt.optimize.spring_catalogue import size_orderable_spring
from govopt.springs import checks as ck
from govopt.springs import compression as hc
from govopt.springs import helical as hx
from govopt.springs import materials as mt
from govopt.springs import tolerances as tl
from govopt.springs.assessment import Loads, Rules, Spring, table
from govopt.verdict import holds

LBF, INCH, PSI = 4.4482216152605, 0.0254, 4.4482216152605 / 0.0254**2
#: `govopt spring`'s defaults (govopt/spring_keys.py): index 4..12, at least 3 active coils
INDEX, N_MIN, STEP = (4.0, 12.0), 3.0, 0.5
#: (grade, its shear modulus given or None, F, R): ASTM A228 with its own moduli (they step
#: with d) and with one given, as the issue's reproduction (11.5e6 psi)
PROBLEMS = [(grade, G, F, F * ratio)
            for grade, G in (("EN10270-1 SH", None), ("EN10270-1 DH", None),
                             ("ASTM A228", None), ("ASTM A228", 11.5e6 * PSI))
            for F, ratio in ((20.0, 1e3), (100.0, 5e3), (100.0, 1e3), (300.0, 20e3),
                             (500.0, 2e3), (500.0, 10e3), (39 * LBF, 22.17 / 39 / INCH),
                             (1000.0, 5e3), (100 * LBF, 0.5 / INCH), (10 * LBF, 0.5 / INCH))]


def _rules():
    return Rules(method="EN13906", correction=None, seating="fixed-fixed", index=INDEX)


def _stock(grade: str, G, F: float, R: float):
    """Every stock spring of the grade for force ``F`` and rate ``R`` (arrays), with its mass."""
    mat = mt.material(grade, G=G)
    wires = np.array([w for w in mt.wire_sizes(grade)[0] if mat.in_range(w)])
    n = np.arange(N_MIN, 400.0 + STEP, STEP)
    d, n = (x.ravel() for x in np.meshgrid(wires, n))
    G = mat.shear_modulus(d)
    D = (G * d**4 / (8.0 * R * n)) ** (1.0 / 3.0)
    C = D / d
    keep = (C >= INDEX[0] * (1 - 1e-9)) & (C <= INDEX[1] * (1 + 1e-9))
    d, n, D = d[keep], n[keep], D[keep]
    d_max = tl.max_wire_diameter(d, grade)
    L0 = hc.min_working_length(d, D, n, n + 2.0, "closed_ground", True, False, d_max) + F / R
    m = hc.pitch(L0, d, n, n + 2.0, "closed_ground", d_max)
    mass = mat.density * np.pi * d**2 / 4.0 * hx.helix_wire_length(D, n, m, 2.0, d)
    return mat, d, D, n, L0, mass


def _passes(mat, d, D, n, L0, F, R, rules):
    kw = dict(mat=mat, d=d, D=D, n=n, n_t=n + 2.0, L0=L0, F1=0.0, F2=F, method=rules.method,
              ends="closed_ground", seating=rules.seating, index_min=INDEX[0],
              index_max=INDEX[1], allowable=None, correction=None)
    ok = np.ones(d.shape, dtype=bool)
    for row, value, limit, _ in ck.rows_over("compression", **kw):
        if "fatigue" not in row.name:
            ok &= holds(value, limit, row.sense)
    return ok


@pytest.mark.slow
@pytest.mark.parametrize(("grade", "G", "F", "R"), PROBLEMS,
                         ids=[f"{g}{'-G' if G else ''}-{F:.4g}N-{R:.4g}N_per_m"
                              for g, G, F, R in PROBLEMS])
def test_stock_design_is_never_heavier_than_brute_force(grade, G, F, R):
    assert len(PROBLEMS) >= 25
    rules = _rules()
    mat, d, D, n, L0, mass = _stock(grade, G, F, R)
    ok = _passes(mat, d, D, n, L0, F, R, rules)
    best = math.inf
    for i in np.argsort(np.where(ok, mass, np.inf)):  # the lightest the scalar checks pass
        if not ok[i]:
            break
        spring = Spring("compression", d[i], D[i], n[i], 2.0, L0[i], "closed_ground")
        if all(c.passed for c in table(spring, mat, Loads(0.0, F), rules)[0]):
            best = float(mass[i])
            break
    sizing = size_orderable_spring(F, R, wires=mt.wire_sizes(grade)[0], coil_step=STEP,
                                   grade=grade, G=G, kind="compression", seating="fixed-fixed",
                                   n_min=N_MIN, C_min=INDEX[0], C_max=INDEX[1])
    if math.isinf(best):  # no stock spring passes: govopt's answer says so
        assert not (sizing.solution.ok and sizing.passed)
        return
    assert sizing.solution.ok and sizing.passed, sizing.diagnosis
    assert sizing.value <= best * (1 + 1e-9)
    assert sizing.record().certified
