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
  (:attr:`chs.Characteristic.sensitiveness`: the range divided by the mean of its ends; the
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
  ``(omega_rise - omega_fall) / omega``: ``insensitiveness`` is the largest over the range, and
  ``insensitiveness_inner`` and ``_outer`` are its values at the ends (the books ask for each;
  at any configuration, :mod:`govopt.analysis.points`).
"""

from __future__ import annotations

import numpy as np

from ..verdict import json_key
from . import characteristic as chs
from . import statics


def speed_change(spec, wi, wa):
    """The speed change ``c`` of the effort and power, and whether it is the range's own.

    ``[analysis] speed_change = "range"``: ``wa / wi - 1`` from the innermost configuration (the
    textbook's effort over the range); else the spec's fraction at the normal configuration
    (Rattan: "a given percentage change of speed").

    Parameters
    ----------
    spec : Spec [-]
        Its analysis options.
    wi : array [rad/s]
        Speed at the innermost configuration, per design.
    wa : array [rad/s]
        Speed at the outermost configuration (broadcast with ``wi``).

    Returns
    -------
    tuple
        ``(c [-], over_range [-])``: the change (dimensionless, per design) and a bool.

    References
    ----------
    [rattan] (effort and power of a governor); [textbook-ch3] section 3.4, Example 1 (the speeds).

    Examples
    --------
    The textbook's Example 1 (Porter): 177.5 to 203.2 rpm over the range (the book prints 178.5
    and 202 rpm, slips of its own arithmetic), so c = 203.2 / 177.5 - 1:

    >>> import govopt
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.parse_spec({"name": "porter-k1", "design": {"ball_weight": "6 kgf",
    ...     "central_weight": "48 kgf"}, "governor": {"type": "porter", "arm": "30 cm",
    ...     "link": "30 cm", "pivot_offset": "0 cm", "sleeve_offset": "0 cm",
    ...     "radius_inner": "15 cm", "radius_outer": "25 cm"}})
    >>> rpm = np.pi / 30
    >>> c, whole = speed_change(spec.with_analysis(speed_change="range"),
    ...                         np.array([177.5 * rpm]), np.array([203.2 * rpm]))
    >>> round(float(c[0]), 4), whole
    (0.1448, True)
    """
    change = spec.analysis.speed_change  # Rattan: "a given percentage change of speed"
    if change == "range":
        return np.asarray(wa) / np.asarray(wi) - 1.0, True
    return np.full(np.shape(wi), float(change)), False


#: the per-design figures of :func:`classic_measures` (a bulk row's classic columns)
CLASSIC_FIGURES = ("range_rad_s", "sensitiveness", "stability", "effort", "power",
                   "friction_band", "insensitiveness")


def classic_measures(spec, sd: statics.SpringDesign, x, omega, t, band, ok) -> dict:
    """The textbook's measures of N designs over their range (see the module docstring), SI.

    Each an array over the designs (:data:`CLASSIC_FIGURES`: range in rad/s, sensitiveness,
    stability, effort in N or N m, power in J, friction band and insensitiveness), and the speeds
    at which each starts to open and close against its friction (``rise``, ``fall``: N x K,
    rad/s). Effort and power at the normal configuration for the spec's speed change (over the
    range: from the innermost configuration to the outermost).

    Parameters
    ----------
    spec : Spec [-]
        The governor, its speeds and analysis options.
    sd : SpringDesign [-]
        The designs (fields of shape ``(N, 1)``: kg, N/m, m).
    x : array [rad] or [m]
        The configurations (K), in the type's coordinate.
    omega : array [rad/s]
        The characteristic, N x K.
    t : Terms [-]
        The seam's generalised forces at ``x`` (:func:`statics.terms`).
    band : array [N m] or [N]
        The friction band at ``x`` (N x K, :meth:`Governor.friction`).
    ok : array of bool [-]
        The designs with a characteristic (the others' travel is not sought).

    Returns
    -------
    dict [-]
        Name -> array over the designs, SI as above.

    References
    ----------
    [textbook-ch3] sections 3.2, 3.4(b); [rattan] (sensitiveness, stability, effort, power).

    Examples
    --------
    A Porter governor with equal arms pinned on the axis, balls 6 kgf, sleeve 48 kgf: the book's
    effort ``P = c (w + W)`` is first order in ``c``; govopt's exact ``((1 + c)^2 - 1) / 2``
    makes it ``c (w + W) (1 + c/2) = 0.01 x 529.56 N x 1.005 = 5.3221 N`` for a 1 % change.

    >>> import govopt
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.parse_spec({"name": "porter-k1", "design": {"ball_weight": "6 kgf",
    ...     "central_weight": "48 kgf"}, "governor": {"type": "porter", "arm": "30 cm",
    ...     "link": "30 cm", "pivot_offset": "0 cm", "sleeve_offset": "0 cm",
    ...     "radius_inner": "15 cm", "radius_outer": "25 cm"}})
    >>> sd = statics.spring_design(spec)
    >>> x = statics.configurations(spec)
    >>> t = statics.terms(spec, x, sd.m, sd.central)
    >>> omega = np.sqrt(t.omega_squared(sd.kappa, sd.l0))[None, :]
    >>> m = classic_measures(spec, sd, x, omega, t, np.zeros_like(omega), np.array([True]))
    >>> round(float(m["effort"][0]), 4), str(m["stability"][0])
    (5.3221, 'stable')
    """
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
        stability = chs.stability(chs.rising_slopes(spec, sd, x, omega),
                                      np.broadcast_to(chs.slope_scale(spec, w0), (n,)))
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
            travel = travel_to(spec, sd, float(x[i_n]), float(x[-1]), target, ok)
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
                "insensitiveness_ends": ((rise - fall) / omega)[:, [0, -1]],
                "rise": rise, "fall": fall, "change": c, "over_range": over_range,
                "at_stop": at_stop,
                "x_normal": float(x[i_n])}


def report(spec, measures: dict, i: int) -> dict:
    """The classic measures of design ``i`` of :func:`classic_measures` as a result reports them.

    SI, units named (``range_rad_s``, ``effort_unit``, ``power_unit``), with the type's geometry
    at the ends and the normal configuration (:func:`geometry`).

    Parameters
    ----------
    spec : Spec [-]
        The governor.
    measures : dict [-]
        :func:`classic_measures`' result (SI).
    i : int [-]
        The design's index (dimensionless).

    Returns
    -------
    dict [-]
        JSON-ready figures, SI.

    References
    ----------
    [textbook-ch3] sections 3.2, 3.4(b); [rattan].

    Examples
    --------
    The equal-arm Porter of :func:`classic_measures`: power is effort times the sleeve's lift
    ``2 h (1 - 1/(1 + c)^2)`` with ``h = 0.2236 m`` at the normal radius 0.2 m, by hand
    ``5.3221 N x 0.008812 m = 0.0469 J``.

    >>> import govopt
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.parse_spec({"name": "porter-k1", "design": {"ball_weight": "6 kgf",
    ...     "central_weight": "48 kgf"}, "governor": {"type": "porter", "arm": "30 cm",
    ...     "link": "30 cm", "pivot_offset": "0 cm", "sleeve_offset": "0 cm",
    ...     "radius_inner": "15 cm", "radius_outer": "25 cm"}})
    >>> sd = statics.spring_design(spec)
    >>> x = statics.configurations(spec)
    >>> t = statics.terms(spec, x, sd.m, sd.central)
    >>> omega = np.sqrt(t.omega_squared(sd.kappa, sd.l0))[None, :]
    >>> m = classic_measures(spec, sd, x, omega, t, np.zeros_like(omega), np.array([True]))
    >>> r = report(spec, m, 0)
    >>> round(r["power"], 4), r["power_unit"], r["effort_unit"]
    (0.0469, 'J', 'N')
    """
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
        "insensitiveness_inner": float(measures["insensitiveness_ends"][i, 0]),
        "insensitiveness_outer": float(measures["insensitiveness_ends"][i, 1]),
        "geometry": geometry(spec, measures["x_normal"]),
    }


def effort_note(measures: dict, i: int) -> str:
    """Why design ``i`` has no effort and power (empty where it has them).

    Over the range (``speed_change = "range"``) the speed must rise from the innermost
    configuration to the outermost; where it falls or stays, no speed change moves the regulating
    member outward, and Rattan's effort ``c (w + W)`` of a falling speed would be a negative
    force, not an effort.

    Parameters
    ----------
    measures : dict [-]
        :func:`classic_measures`' result (its ``change``, dimensionless, and ``over_range``).
    i : int [-]
        The design's index (dimensionless).

    Returns
    -------
    str [-]
        The note, or ``""``.

    References
    ----------
    [rattan] (effort of a governor).

    Examples
    --------
    A speed that falls 2 % over the range:

    >>> print(effort_note({"change": np.array([-0.02]), "over_range": True}, 0))
    not computed: the speed falls over the range (-2 %), so no rise of speed moves the
    regulating member (see stability)
    """
    c = float(measures["change"][i])
    if not measures["over_range"] or c > 0.0:
        return ""
    how = "falls" if c < 0.0 else "does not rise"
    return (f"not computed: the speed {how} over the range ({100.0 * c:.4g} %), so no rise "
            "of speed moves the regulating member (see stability)")


def geometry(spec, x_normal) -> dict:
    """The type's own geometry at the innermost, normal and outermost configurations, SI.

    :meth:`Governor.columns`: the Porter's height ``h`` and arm ratio ``k = tan(beta)/tan(alpha)``
    (textbook 3.4(b)), a bell-crank governor's sleeve lift, the shaft governor's spring arm ``h``
    (Hamabe eq. 2) ...; each name carries its unit (``height_m``, ``k``).

    Parameters
    ----------
    spec : Spec [-]
        The governor.
    x_normal : float [rad] or [m]
        The normal configuration, in the type's coordinate.

    Returns
    -------
    dict [-]
        Name with unit -> ``{"inner", "normal", "outer"}`` floats.

    References
    ----------
    [textbook-ch3] section 3.4(b); [hamabe] Part I, eq. (2).

    Examples
    --------
    The equal-arm Porter (arms 30 cm on the axis) at radius 0.2 m: by hand
    ``h = sqrt(0.3^2 - 0.2^2) = 0.2236 m``, and the sleeve has lifted twice the fall of ``h``
    from the innermost radius 0.15 m (``h = 0.2598 m``): 0.0724 m.

    >>> import govopt
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.parse_spec({"name": "porter-k1", "design": {"ball_weight": "6 kgf",
    ...     "central_weight": "48 kgf"}, "governor": {"type": "porter", "arm": "30 cm",
    ...     "link": "30 cm", "pivot_offset": "0 cm", "sleeve_offset": "0 cm",
    ...     "radius_inner": "15 cm", "radius_outer": "25 cm"}})
    >>> g = geometry(spec, 0.2)
    >>> round(g["height_m"]["normal"], 4), round(g["sleeve_lift_m"]["normal"], 4), g["k"]["normal"]
    (0.2236, 0.0724, 1.0)
    """
    gov = spec.governor
    x = np.array([gov.x_inner, float(x_normal), gov.x_outer])
    out = {}
    for name, (values, unit) in gov.columns(x).items():
        key = json_key(name, unit)
        values = np.broadcast_to(np.asarray(values, dtype=float), x.shape)
        out[key] = dict(zip(("inner", "normal", "outer"), map(float, values), strict=True))
    return out


def travel_between(spec, x0: float, x1):
    """Travel of the regulating member from ``x0`` to ``x1``: ``int s'(u) du``.

    Eight-point Gauss-Legendre quadrature of the type's :meth:`Governor.travel_slope`, exact to
    rounding for these smooth linkages (govopt's own; Rattan's power is effort times this travel).

    Parameters
    ----------
    spec : Spec [-]
        The governor.
    x0 : float [rad] or [m]
        Configuration from which the member moves.
    x1 : float or array [rad] or [m]
        Configuration(s) to which it moves.

    Returns
    -------
    float or array [rad] or [m]
        The member's travel (the sleeve's lift in m; a shaft governor's lever angle in rad).

    References
    ----------
    [rattan] (power of a governor); [textbook-ch3] section 3.4(b) (the Porter's sleeve).

    Examples
    --------
    The equal-arm Porter from radius 0.15 to 0.25 m: by hand the sleeve lifts
    ``2 (sqrt(0.3^2 - 0.15^2) - sqrt(0.3^2 - 0.25^2)) = 0.187953 m``.

    >>> import govopt
    >>> from govopt.analysis import statics
    >>> from govopt.analysis import characteristic as chs
    >>> spec = govopt.parse_spec({"name": "porter-k1", "design": {"ball_weight": "6 kgf",
    ...     "central_weight": "48 kgf"}, "governor": {"type": "porter", "arm": "30 cm",
    ...     "link": "30 cm", "pivot_offset": "0 cm", "sleeve_offset": "0 cm",
    ...     "radius_inner": "15 cm", "radius_outer": "25 cm"}})
    >>> round(travel_between(spec, 0.15, 0.25), 6)
    0.187953
    """
    x1 = np.asarray(x1, dtype=float)
    nodes, weights = np.polynomial.legendre.leggauss(8)
    u = 0.5 * (x1 - x0)[..., None] * nodes + 0.5 * (x1 + x0)[..., None]
    s = np.broadcast_to(spec.governor.travel_slope(u), u.shape)
    out = 0.5 * (x1 - x0) * np.sum(weights * s, axis=-1)
    return float(out) if out.ndim == 0 else out


def travel_to(spec, sd, x0: float, x_end: float, target, ok):
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
