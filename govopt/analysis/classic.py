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
  textbook's effort over the range or the lift; none where the speed does not rise over the
  range, :func:`effort_note`) with the member held: the generalised force
  grows from 0 to
  ``((1 + c)^2 - 1) omega^2 (jp - ci)``, which each of the ``n`` flying masses puts on the member
  through ``s'(x)``; mean effort ``P = n ((1 + c)^2 - 1) omega^2 (jp - ci) / (2 s')``. For the
  Porter with equal arms this is the book's ``P = c (w + W)`` to first order in ``c``;
* **power** (Rattan): effort times the member's travel for the same speed change: the
  configuration ``x'`` in equilibrium at ``(1 + c) omega`` (a root of the characteristic; over
  the range, the outermost configuration: the whole travel; where ``x'`` lies past the
  outermost configuration, the member stops there and the travel is to the stop) and
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


#: the per-design figures of :func:`classic_measures` (a bulk row's classic columns)
CLASSIC_FIGURES = ("range_rad_s", "sensitiveness", "stability", "effort", "power",
                   "friction_band", "insensitiveness")


def classic_measures(spec, sd: statics.SpringDesign, x, omega, t, band, ok) -> dict:
    """The textbook's measures of N designs over their range (see the module docstring), SI,
    each an array over the designs (:data:`CLASSIC_FIGURES`), and the speeds at which each
    starts to open and close against its friction (``rise``, ``fall``: N x K). ``sd``: the
    designs (fields of shape ``(N, 1)``); ``x``: the configurations (K); ``omega``: the
    characteristic (N x K, rad/s); ``t``: the seam's terms at ``x``; ``band``: the friction band
    at ``x`` (N x K, :meth:`Governor.friction`); ``ok``: the designs with a characteristic
    (the others' travel is not sought). Effort and power at the normal configuration for the
    spec's speed change (over the range: from the innermost configuration to the outermost)."""
    gov = spec.governor
    n = omega.shape[0]
    w2 = omega**2
    with np.errstate(all="ignore"):
        rise = np.sqrt(np.maximum(t.omega_squared(sd.kappa, sd.l0, band), 0.0))
        fall = np.sqrt(np.maximum(t.omega_squared(sd.kappa, sd.l0, -band), 0.0))
        i_n = int(np.argmin(np.abs(x - gov.x_normal)))
        w0 = spec.speed.omega_mean if spec.speed is not None else omega[:, i_n]
        # the characteristic's own slope d omega/dx (exact, the dead loads' slope included) and
        # its secants, at the one tolerance the "characteristic rises" check reads
        stability = statics.stability(statics.rising_slopes(spec, sd, x, omega),
                                      np.broadcast_to(statics.slope_scale(spec, w0), (n,)))
        wi, wa = omega[:, 0], omega[:, -1]
        c, over_range = speed_change(spec, wi, wa)
        grow = (1.0 + c[:, None]) ** 2 - 1.0
        lever = np.broadcast_to(t.lever, (n, x.size))
        effort = gov.flying_masses * grow * w2 * lever / (2.0 * gov.travel_slope(x))
        at = 0 if over_range else i_n  # the configuration the speed changes from
        if over_range:
            travel = np.full(n, travel_between(spec, float(x[0]), float(x[-1])))
        else:
            target = (1.0 + c) ** 2 * w2[:, i_n]
            travel = _travel(spec, sd, float(x[i_n]), float(x[-1]), target, ok)
        # a speed change whose equilibrium lies past the outermost configuration moves the
        # member to its stop: the work is done over the travel to the stop (Rattan: power
        # is the work done at the member for the speed change)
        at_stop = np.asarray(ok & np.isinf(travel) & (not over_range))
        travel = np.where(at_stop, travel_between(spec, float(x[i_n]), float(x[-1])), travel)
        if over_range:  # a speed that does not rise over the range has no effort to move it
            effort = np.where((c > 0.0)[:, None], effort, np.nan)
        return {"range_rad_s": wa - wi, "sensitiveness": 2.0 * (wa - wi) / (wa + wi),
                "stability": np.where(ok, stability, None), "effort": effort[:, at],
                "power": effort[:, at] * travel, "friction_band": band[:, i_n],
                "insensitiveness": ((rise - fall) / omega).max(axis=1),
                "rise": rise, "fall": fall, "change": c, "over_range": over_range,
                "at_stop": at_stop,
                "x_normal": float(x[i_n])}


def report(spec, measures: dict, i: int) -> dict:
    """The classic measures of design ``i`` of :func:`classic_measures` as a result reports
    them (SI; units named), with the type's geometry at the ends and the normal configuration."""
    gov = spec.governor
    return {
        "range_rad_s": float(measures["range_rad_s"][i]),
        "range_rpm": float(measures["range_rad_s"][i]) * 30.0 / np.pi,
        "sensitiveness": float(measures["sensitiveness"][i]),
        "stability": str(measures["stability"][i]),
        "effort_change": float(measures["change"][i]),
        "effort_over": "range" if measures["over_range"] else "normal",
        "effort_note": effort_note(measures, i),
        "effort": float(measures["effort"][i]),
        "effort_unit": "N*m" if gov.travel == "angle" else "N",
        "power": float(measures["power"][i]),
        "power_unit": "J",
        "power_note": (f"to the stop: a {100.0 * float(measures['change'][i]):.4g} % speed change "
                       "from the normal configuration has its equilibrium past the outermost"
                       if measures["at_stop"][i] else ""),
        "friction_band": float(measures["friction_band"][i]),
        "omega_rise_rad_s": measures["rise"][i].tolist(),
        "omega_fall_rad_s": measures["fall"][i].tolist(),
        "insensitiveness": float(measures["insensitiveness"][i]),
        "geometry": geometry(spec, measures["x_normal"]),
    }


def effort_note(measures: dict, i: int) -> str:
    """Why design ``i`` has no effort and power (empty where it has them): over the range
    (``speed_change = "range"``) the speed must rise from the innermost configuration to the
    outermost; where it falls or stays, no speed change moves the regulating member outward,
    and Rattan's effort ``c (w + W)`` of a falling speed would be a negative force, not an
    effort."""
    c = float(measures["change"][i])
    if not measures["over_range"] or c > 0.0:
        return ""
    how = "falls" if c < 0.0 else "does not rise"
    return (f"not computed: the speed {how} over the range ({100.0 * c:.4g} %), so no rise "
            "of speed moves the regulating member (see stability)")


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


def _travel(spec, sd, x0: float, x_end: float, target, ok):
    """Travel of the regulating member of each design from ``x0`` to its configuration ``x1`` in
    equilibrium at speed^2 ``target`` (``inf`` where the governor reaches the end of its range
    first): a safeguarded Newton iteration on the characteristic, whose slope is exact on the
    seam (``d omega^2/dx = I k^2 / (jp - ci)``, the dead loads' slope included), to 1e-15, then
    :func:`travel_between`."""
    exact = spec.with_analysis(reaction_slope=True)
    n = target.shape[0]

    def excess(u):
        t = statics.terms(exact, u[:, None], sd.m, sd.central)
        w2 = np.broadcast_to(t.omega_squared(sd.kappa, sd.l0), (n, 1))[:, 0]
        slope = t.stiffness(sd.kappa, sd.l0, w2[:, None]) / t.lever
        return w2 - target, np.broadcast_to(slope, (n, 1))[:, 0]

    out = np.full(n, np.inf)
    top, _ = excess(np.full(n, x_end))
    go = ok & (top > 0)
    if not go.any():
        return out
    lo, hi = np.full(n, x0), np.full(n, x_end)
    u = np.full(n, 0.5 * (x0 + x_end))
    for _ in range(100):
        f, df = excess(u)
        lo, hi = np.where(f > 0, lo, u), np.where(f > 0, u, hi)
        new = u - f / df
        new = np.where((new > lo) & (new < hi) & np.isfinite(new), new, 0.5 * (lo + hi))
        done = (np.abs(new - u) <= 1e-15 * np.abs(u)) | (f == 0) | (hi - lo <= 4e-16 * np.abs(u))
        u = np.where(done, u, new)
        if done[go].all():
            break
    out[go] = travel_between(spec, x0, u)[go]
    return out
