"""Answers at any configuration: the textbook's questions asked at a point the problem names
(a ball radius, an arm's angle, a height, a sleeve lift), not only at the characteristic's grid.

A point is given by one of the type's coordinates (:meth:`Governor.coordinates`, each with its
conversion declared beside its physics); :func:`configuration` turns it into the type's own
coordinate ``x`` by bracketed root-finding over the configurations the mechanism can take
(:meth:`Governor.x_domain`). At ``x`` the seam gives, for the design (:func:`at`):

* the equilibrium speeds, frictionless ``omega^2 = Q / (jp - ci)`` and rising and falling
  against the friction band ``F`` (textbook 3.4(b), "Friction at the sleeve"):
  ``omega_rise,fall^2 = (Q +- F) / (jp - ci)``, and the coefficient of insensitiveness
  ``(omega_rise - omega_fall) / omega`` there (Rattan);
* the controlling force ``Q = kappa (A - B l0) + C_f`` (per flying mass; for a ball on a
  radius the book's controlling force, section 3.3), the spring's force and the force on the
  regulating member equivalent to it, ``n Q / s'(x)`` (for a Hartnell whose balls' weight is
  neglected, the spring's force on the sleeve);
* the effort for the spec's speed change ``c`` (Rattan: ``n ((1 + c)^2 - 1) omega^2 (jp - ci)
  / (2 s')``, :mod:`govopt.analysis.classic`) and the power, effort times the member's travel to
  the configuration in equilibrium at ``(1 + c) omega``;
* the forces in the arms, links and pivots the type resolves (:meth:`Governor.link_forces`).
"""

from __future__ import annotations

import numpy as np

from ..errors import GovoptError
from ..units import SI_UNITS
from . import classic, statics


def configuration(gov, name: str, value: float) -> float:
    """The configuration ``x`` (SI, the type's own coordinate) where the coordinate ``name`` is
    ``value`` (SI).

    Brent's method on the coordinate's declared conversion over the configurations the
    mechanism can take (:func:`govopt.governors.base.solve_monotone`); a
    :class:`~govopt.errors.GovoptError` naming the coordinate where none has that value.

    Parameters
    ----------
    gov : Governor [-]
        The governor (its :meth:`coordinates` and :meth:`x_domain`).
    name : str [-]
        The coordinate's name (``"radius"``, ``"angle"``, ``"height"``, ``"lift"`` ...).
    value : float [rad] or [m]
        Its value, SI.

    Returns
    -------
    float [rad] or [m]
        The configuration ``x``.

    References
    ----------
    [textbook-ch3] section 3.4 (Figs. 3.3, 3.4: the arm's angle, the height, the sleeve).

    Examples
    --------
    Example 1's Porter (arms of 30 cm on the axis) with its arms at 45 deg to the axis: by hand
    the ball's radius ``30 sin 45 deg = 21.213 cm``:

    >>> import govopt
    >>> from govopt.examples import example
    >>> gov = govopt.load_spec(example("textbook-ex1-porter")).governor
    >>> round(configuration(gov, "angle", np.radians(45.0)) * 100, 3)
    21.213
    """
    from ..governors.base import solve_monotone

    coords = {c.name: c for c in gov.coordinates()}
    if name not in coords:
        raise GovoptError(f"{name}: not a coordinate of the {gov.type_name} governor; expected "
                          f"one of {', '.join(coords)}")
    lo, hi = gov.x_domain()
    x = solve_monotone(coords[name].value, value, lo, hi)
    if not np.isfinite(x):
        ends = np.asarray(coords[name].value(np.linspace(lo, hi, 257)[1:-1]), dtype=float)
        ends = ends[np.isfinite(ends)]
        shown = (lambda v: f"{np.degrees(v):.4g} deg") if coords[name].dimension == "angle" \
            else (lambda v: f"{1e3 * v:.4g} mm")
        raise GovoptError(f"{name} = {shown(value)}: the {gov.type_name} governor cannot take "
                          f"it (its {name} runs {shown(ends.min())} .. {shown(ends.max())})")
    return x


#: the figures of :func:`at`: name -> (the unit's kind: a dimension of SI_UNITS,
#: "generalised force" (N, or N m about an angle), "travel force" (N, or N m where the
#: regulating member turns), "joule", "" (a bare number)), meaning
FIGURES = {
    "speed": ("angular_velocity", "the equilibrium speed, frictionless"),
    "speed_rising": ("angular_velocity", "the speed at which the governor starts to open "
                                         "against its friction"),
    "speed_falling": ("angular_velocity", "the speed at which it starts to close"),
    "insensitiveness": ("", "(speed_rising - speed_falling) / speed"),
    "controlling_force": ("generalised force", "the restoring generalised force per flying "
                                               "mass (a ball's controlling force)"),
    "spring_force": ("force", "the force in the spring"),
    "sleeve_force": ("travel force", "the force on the regulating member equivalent to the "
                                     "controlling force, n Q / s'"),
    "effort": ("travel force", "the mean force on the regulating member for the speed change"),
    "power": ("joule", "effort times the member's travel for the speed change"),
}


def at(spec, sd, xs) -> dict:
    """Every answer of the module's list at configurations ``xs`` of one design, SI.

    Parameters
    ----------
    spec : Spec [-]
        The governor, its analysis options (``speed_change``).
    sd : SpringDesign [-]
        One design (scalars: kg, N/m, m).
    xs : array [rad] or [m]
        The configurations, in the type's coordinate.

    Returns
    -------
    dict [-]
        ``figures``: name of :data:`FIGURES` -> array over ``xs`` (rad/s, N or N m, J);
        ``links``: the type's link forces (N); ``coordinates``: each coordinate's value (SI);
        ``stable``: whether the characteristic rises there (``k^2 > 0``).

    References
    ----------
    [textbook-ch3] sections 3.3, 3.4(b); [rattan] (insensitiveness, effort and power).

    Examples
    --------
    Example 1's Porter at its inner end r = 20 cm: the book's ``omega^2 = g/h (w + W (1 + k)/2)
    / w`` with ``h = sqrt(30^2 - 20^2)`` cm and k = 0.7198: 177.51 rpm, as its characteristic:

    >>> import govopt
    >>> from govopt.examples import example
    >>> spec = govopt.load_spec(example("textbook-ex1-porter"))
    >>> out = at(spec, statics.spring_design(spec), np.array([0.2]))
    >>> round(float(out["figures"]["speed"][0]) * 30 / np.pi, 2)
    177.51
    """
    gov = spec.governor
    xs = np.asarray(xs, dtype=float)
    t = statics.terms(spec, xs, sd.m, sd.central)
    Q = t.restoring(sd.kappa, sd.l0)
    band = np.broadcast_to(gov.friction(xs, spec.design), xs.shape)
    with np.errstate(invalid="ignore", divide="ignore"):
        w2, rise2, fall2 = (np.broadcast_to((Q + f) / t.lever, xs.shape)
                            for f in (0, band, -band))
        omega, rise, fall = (np.where(v >= 0, np.sqrt(np.abs(v)), np.nan)
                             for v in (w2, rise2, fall2))
        slope = gov.travel_slope(xs)
        n = gov.flying_masses
        AF, BF = gov.spring_force_coefficients(xs)
        if spec.analysis.speed_change == "range":  # from the point to the outermost's speed
            top = statics.terms(spec, gov.x_outer, sd.m, sd.central)
            c = np.sqrt(top.omega_squared(sd.kappa, sd.l0)) / omega - 1.0
        else:
            c = np.full(xs.shape, float(spec.analysis.speed_change))
        effort = n * ((1.0 + c) ** 2 - 1.0) * w2 * t.lever / (2.0 * slope)
        k2 = t.stiffness(sd.kappa, sd.l0, w2)
    power = np.array([effort[i] * _travel_to_stop(spec, sd, float(xs[i]), gov.x_outer,
                                                  float((1 + c[i]) ** 2 * w2[i]))
                      for i in range(xs.size)])
    figures = {"speed": omega, "speed_rising": rise, "speed_falling": fall,
               "insensitiveness": (rise - fall) / omega,
               "controlling_force": np.broadcast_to(Q, xs.shape),
               "spring_force": np.broadcast_to(sd.kappa * (AF - BF * sd.l0), xs.shape),
               "sleeve_force": np.broadcast_to(n * Q / slope, xs.shape),
               "effort": effort, "power": power}
    links = gov.link_forces(xs, sd.m, sd.central, w2, Q)
    coords = {c.name: np.asarray(c.value(xs), dtype=float) for c in gov.coordinates()}
    return {"figures": figures, "links": {k: np.broadcast_to(v, xs.shape)
                                          for k, v in links.items()},
            "coordinates": coords, "stable": np.broadcast_to(k2 > 0, xs.shape)}


def _travel_to_stop(spec, sd, x0: float, x_end: float, target: float) -> float:
    """The member's travel from ``x0`` to the configuration in equilibrium at speed^2
    ``target`` (classic's Newton on the characteristic), or to the outermost configuration
    where that lies beyond it (the member stops there); NaN where ``x0`` is at or past the
    stop or the speed does not rise."""
    if not (np.isfinite(target) and x0 < x_end - 1e-9 * abs(x_end)):
        return float("nan")
    travel = classic.travel_to(spec, sd, x0, x_end, np.array([target]), np.array([True]))[0]
    return float(travel if np.isfinite(travel) else classic.travel_between(spec, x0, x_end))


def unit(gov, kind: str) -> str:
    """The SI unit of a figure's kind (:data:`FIGURES`) for ``gov``."""
    if kind == "generalised force":
        return "N*m" if gov.coordinate == "angle" else "N"
    if kind == "travel force":
        return "N*m" if gov.travel == "angle" else "N"
    return {"": "", "joule": "J"}.get(kind, SI_UNITS.get(kind, kind))
