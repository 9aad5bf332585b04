"""The load-change transient of one design (Hamabe, Part III, eqs. 27-32) from the statics.

Builds eq. (28)'s coefficients and initial conditions for a load change ``alpha1 -> alpha0`` from
the characteristic curve and the engine data, and analyses the response with the robust solver
of :mod:`govopt.analysis.transient`.
"""

from __future__ import annotations

import numpy as np

from ..spec import LoadChange, Spec
from . import statics
from . import transient as tr


def coefficients(spec: Spec, sd: statics.SpringDesign, lc: LoadChange, f: float):
    """``(a0, a1, a2, a3)`` and the initial state ``(xi, xi', xi'')(0)`` of eq. (28).

    ``a0 = I``, ``3 a1 = f``, ``3 a2 = I k^2(alpha0)``, ``a3 = 2 R omega0 a m rho sin(alpha0)``
    with ``R = -(dT/dalpha) / I_fw`` (eq. 27) and ``omega0`` the equilibrium speed at the new
    configuration; ``xi(0) = alpha1 - alpha0``, ``xi'(0) = 0``,
    ``a0 xi''(0) = (a3 / R) eta0 - 3 a2 xi(0)`` with ``eta0 = omega1 (1 + eps) - omega0``.
    """
    g, eng = spec.geometry, spec.engine
    R = -eng.torque_slope / eng.flywheel_inertia
    w2 = statics.omega_squared(spec, np.array([lc.alpha_from, lc.alpha_to]), sd.m, sd.kappa,
                               sd.l0)
    omega1, omega0 = np.sqrt(w2)
    k2 = statics.restoring_k2(spec, lc.alpha_to, sd, omega0**2)
    a = tr.hamabe_coefficients(sd.inertia, f, k2, R, omega0, g.a, sd.m, g.rho, lc.alpha_to)
    x = tr.hamabe_initial_conditions(a[0], a[2], a[3], R, lc.alpha_from - lc.alpha_to,
                                     omega1 * (1.0 + eng.insensibility) - omega0)
    return tuple(float(v) for v in a), tuple(float(v) for v in x), float(k2)


def analyse(spec: Spec, sd: statics.SpringDesign, lc: LoadChange, f: float,
            samples: int = 200) -> dict:
    """Roots, Hurwitz margin, over-regulation, settling and a response table (SI, JSON-ready)."""
    a, x, k2 = coefficients(spec, sd, lc, f)
    res = tr.analyse(*a, *x, band=spec.analysis.settling_band)
    roots = np.asarray(res.roots, dtype=complex)
    slowest = float(np.min(np.abs(roots.real)))
    horizon = res.settling_time if np.isfinite(res.settling_time) else (
        10.0 / slowest if slowest > 0 else 10.0 * 2 * np.pi / max(float(np.max(roots.imag)), 1e-9))
    t = np.linspace(0.0, 1.5 * horizon, samples)
    xi = tr.transient(*a, *x, t)
    return {
        "name": lc.name,
        "alpha_from_deg": float(np.degrees(lc.alpha_from)),
        "alpha_to_deg": float(np.degrees(lc.alpha_to)),
        "coefficients": {"a0": a[0], "a1": a[1], "a2": a[2], "a3": a[3]},
        "initial_state": {"xi_rad": x[0], "xi_dot_rad_s": x[1], "xi_ddot_rad_s2": x[2]},
        "k2_rad2_s2": k2,
        "roots_per_s": [[float(r.real), float(r.imag)] for r in roots],
        "kind": res.kind,
        "hurwitz_margin": float(res.hurwitz_margin),
        "stable": bool(res.stable),
        # an unstable transient passes its equilibrium without bound
        "over_regulation_rad": float(res.over_regulation) if res.stable else float("inf"),
        "first_arrival_time_s": float(res.first_arrival_time),
        "settling_time_s": float(res.settling_time),
        "settling_band": spec.analysis.settling_band,
        "response": {"t_s": t.tolist(), "xi_rad": np.asarray(xi).tolist()},
    }
