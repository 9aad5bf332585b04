"""The classic measures of a governor, for every type on the seam.

Sources: the seed textbook chapter (ch. 3) defines the controlling force (3.2: it "must increase"
with the radius), the friction at the sleeve (3.4(b)) and the range of speed (Problem 2: "ratio of
the range of speed to the mean of speed"); it has no sections on stability, effort or power, so
those follow the standard definitions of the governor chapter of S. S. Rattan, *Theory of
Machines* (sensitiveness, stability, isochronism, effort and power of the Porter governor,
``P = c (w + W)`` for equal arms); Hamabe Part I for the irregularity.

All are computed from the characteristic, written once on the seam
(:mod:`govopt.governors.base`), so they mean the same for a Porter and for Hamabe's pendulum:

* **range of speed** ``omega_a - omega_i`` over the configuration range;
* **sensitiveness** ``2 (omega_a - omega_i) / (omega_a + omega_i)``
  (:attr:`statics.Characteristic.sensitiveness`: the range divided by the mean of its ends; the
  *irregularity* requirement divides by the spec's mean speed instead, Hamabe Part I);
* **stability** (Rattan; textbook 3.2): *stable* when the equilibrium speed rises with the
  configuration everywhere (``d omega / dx > 0``), *isochronous* when it is constant,
  *unstable* when it falls somewhere. At equilibrium ``I k^2 = (jp - ci) d(omega^2)/dx``
  (differentiate the characteristic), so with a positive lever the sign of ``d omega/dx`` is
  the sign of ``k^2``;
* **effort** (Rattan): the mean force on the regulating member when the speed changes by
  ``c`` (``[analysis] speed_change``, default 1 %, at the normal configuration; ``"range"``: the
  governor's own change ``c = omega_a / omega_i - 1`` from the innermost configuration, the
  textbook's effort over the range or the lift) with the member held: the generalised force
  grows from 0 to
  ``((1 + c)^2 - 1) omega^2 (jp - ci)``, which each of the ``n`` flying masses puts on the member
  through ``s'(x)``; mean effort ``P = n ((1 + c)^2 - 1) omega^2 (jp - ci) / (2 s')``. For the
  Porter with equal arms this is the book's ``P = c (w + W)`` to first order in ``c``;
* **power** (Rattan): effort times the member's travel for the same speed change: the
  configuration ``x'`` in equilibrium at ``(1 + c) omega`` (a root of the characteristic; over
  the range, the outermost configuration: the whole travel) and
  ``Delta s = int_x^x' s'(u) du`` (Gauss-Legendre, exact to rounding for these smooth
  linkages);
* **friction band** (textbook 3.4(b), "Friction at the sleeve"; Hamabe eq. 42): the speeds at
  which the governor starts to open and to close against the friction band ``F``,
  ``omega_rise,fall^2 = (Q_s + cf +- F) / (jp - ci)``, and the coefficient of insensitiveness
  ``(omega_rise - omega_fall) / omega``.
"""

from __future__ import annotations

import numpy as np

from ..verdict import json_key
from . import statics


def speed_change(spec, wi, wa):
    """The speed change ``c`` of the effort and power and whether it is the range's own
    (``[analysis] speed_change = "range"``: ``wa / wi - 1`` from the innermost configuration,
    ``wi``, ``wa`` in rad/s, arrays broadcast) or a fraction at the normal configuration."""
    change = spec.analysis.speed_change  # Rattan: "a given percentage change of speed"
    if change == "range":
        return np.asarray(wa) / np.asarray(wi) - 1.0, True
    return np.full(np.shape(wi), float(change)), False


def classic_measures(spec, sd: statics.SpringDesign, char: statics.Characteristic,
                     k2=None, design=None) -> dict:
    """The textbook's measures of one design over its range (SI; see the module docstring);
    effort and power at the normal configuration for the spec's speed change (over the range:
    from the innermost configuration to the outermost); the type's geometry (``h``, the arm
    ratio ``k``, the sleeve lift ...: :meth:`Governor.columns`) at the ends of the range and
    the normal configuration."""
    gov, x = spec.governor, char.alpha
    t = statics.terms(spec, x, sd.m, sd.central)
    w2 = char.omega**2
    band = gov.friction(x, design)
    rise = np.sqrt(np.maximum(t.omega_squared(sd.kappa, sd.l0, band), 0.0))
    fall = np.sqrt(np.maximum(t.omega_squared(sd.kappa, sd.l0, -band), 0.0))
    # the characteristic's own slope d omega/dx (exact, the dead loads' slope included) and its
    # secants, at the one tolerance the "characteristic rises" check reads (statics.stability)
    wi, wa = float(char.omega[0]), float(char.omega[-1])
    i_n = int(np.argmin(np.abs(x - gov.x_normal)))
    w0 = spec.speed.omega_mean if spec.speed is not None else float(char.omega[i_n])
    stability = str(statics.stability(statics.rising_slopes(spec, sd, x, char.omega),
                                      statics.slope_scale(spec, w0)))
    c, over_range = speed_change(spec, wi, wa)
    c = float(c)
    at = 0 if over_range else i_n  # the configuration the speed changes from
    grow = (1.0 + c) ** 2 - 1.0
    slope = gov.travel_slope(x)
    effort = gov.flying_masses * grow * w2 * t.lever / (2.0 * slope)
    travel = (travel_between(spec, float(x[0]), float(x[-1])) if over_range else
              _travel(spec, sd, float(x[i_n]), float(x[-1]), (1.0 + c) ** 2 * w2[i_n]))
    return {
        "range_rad_s": wa - wi,
        "range_rpm": (wa - wi) * 30.0 / np.pi,
        "sensitiveness": char.sensitiveness,
        "stability": stability,
        "effort_change": c,
        "effort_over": "range" if over_range else "normal",
        "effort": float(effort[at]),
        "effort_unit": "N*m" if gov.travel == "angle" else "N",
        "power": float(effort[at] * travel),
        "power_unit": "J",
        "friction_band": float(band[i_n]),
        "omega_rise_rad_s": rise.tolist(),
        "omega_fall_rad_s": fall.tolist(),
        "insensitiveness": float(np.max((rise - fall) / char.omega)),
        "geometry": geometry(spec, x[i_n]),
    }


def geometry(spec, x_normal) -> dict:
    """The type's own geometry (:meth:`Governor.columns`: the Porter's height ``h`` and arm
    ratio ``k = tan(beta)/tan(alpha)`` (textbook 3.4(b)), a bell-crank governor's sleeve lift,
    the shaft governor's spring arm ``h`` (Hamabe eq. 2) ...) at the innermost, normal and
    outermost configurations, SI; each name carries its unit (``height_m``, ``k``)."""
    gov = spec.governor
    x = np.array([gov.x_inner, float(x_normal), gov.x_outer])
    out = {}
    for name, (values, unit) in gov.columns(x).items():
        key = json_key(name, unit)
        values = np.broadcast_to(np.asarray(values, dtype=float), x.shape)
        out[key] = dict(zip(("inner", "normal", "outer"), map(float, values), strict=True))
    return out


def travel_between(spec, x0: float, x1):
    """Travel of the regulating member from ``x0`` to ``x1`` (a number or an array of ends):
    ``int s'(u) du`` (Gauss-Legendre, as :func:`_travel`)."""
    x1 = np.asarray(x1, dtype=float)
    nodes, weights = np.polynomial.legendre.leggauss(8)
    u = 0.5 * (x1 - x0)[..., None] * nodes + 0.5 * (x1 + x0)[..., None]
    s = np.broadcast_to(spec.governor.travel_slope(u), u.shape)
    out = 0.5 * (x1 - x0) * np.sum(weights * s, axis=-1)
    return float(out) if out.ndim == 0 else out


def _travel(spec, sd, x0: float, x_end: float, target: float) -> float:
    """Travel of the regulating member from ``x0`` to the equilibrium at speed^2 ``target``
    (``inf`` where the governor reaches the end of its range first)."""
    from .roots import brentq

    def excess(u):
        return float(statics.omega_squared(spec, u, sd.m, sd.kappa, sd.l0, sd.central)) - target

    if not excess(x_end) > 0:
        return float("inf")
    return travel_between(spec, x0, brentq(excess, x0, x_end, xtol=1e-15, rtol=1e-15))
