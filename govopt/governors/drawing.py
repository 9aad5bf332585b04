"""A governor drawn to scale (:meth:`govopt.governors.base.Governor.drawing`): its parts
(:class:`Part`, :class:`Drawing`) and the drawing conventions the types share: a spring's zigzag
(:func:`zigzag`), a flying mass's ball (:func:`ball_radius`), the other half of a governor drawn
in its meridian plane (:func:`mirrored`). Imports nothing of govopt."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Part:
    """One part of a governor's drawing in its own plane (SI, m): ``kind`` is ``"link"``
    (a polyline of bars or arms), ``"mass"`` (a ball or pendulum: a circle of ``size`` radius
    at the one point), ``"pivot"`` (a fulcrum or hinge: a point), ``"sleeve"`` (a closed
    polyline), ``"spring"`` (a coil's zigzag polyline) or ``"frame"`` (the spindle, the shaft,
    fixed collars and caps)."""

    kind: str
    points: tuple[tuple[float, float], ...]
    size: float = 0.0


@dataclass(frozen=True)
class Drawing:
    """A governor drawn to scale at one configuration: its parts in the plane the type states
    (``plane``: the meridian plane of the spindle, ``r`` across and height up, or the shaft
    governor's plane of rotation), with axis titles ``axes``."""

    parts: tuple[Part, ...]
    plane: str = "meridian plane: radius from the spindle's axis, height"
    axes: tuple[str, str] = ("radius (mm)", "height (mm)")


def zigzag(start, end, width: float, coils: float = 6.0) -> tuple[tuple[float, float], ...]:
    """A spring drawn from ``start`` to ``end``: a zigzag of ``coils`` turns, ``width`` across
    (its coil diameter), straight ends of a tenth of its length.

    A drawing convention of govopt's (no source).

    Parameters
    ----------
    start, end : tuple of float [m]
        The spring's ends in the drawing's plane.
    width : float [m]
        Its coil diameter.
    coils : float [-]
        Turns drawn (two zigs each).

    Returns
    -------
    tuple of (float, float) [m]
        The polyline's points.

    Examples
    --------
    Three turns: the two ends, two points where the straight ends meet the coil, six zigs:

    >>> len(zigzag((0.0, 0.0), (0.0, 1.0), 0.1, coils=3))
    10
    """
    p, q = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    axis = q - p
    length = float(np.hypot(*axis))
    if length == 0.0:
        return (tuple(p), tuple(q))
    across = np.array([-axis[1], axis[0]]) / length * 0.5 * width
    n = max(1, int(round(2 * coils)))
    points = [p, p + 0.1 * axis]
    for k in range(n):
        points.append(p + (0.1 + 0.8 * (k + 0.5) / n) * axis + (1 if k % 2 == 0 else -1) * across)
    points += [p + 0.9 * axis, q]
    return tuple((float(x), float(y)) for x, y in points)


def ball_radius(mass: float, density: float = 7850.0) -> float:
    """The radius [m] of a steel ball of ``mass``: how the drawings show a flying mass,
    ``r = (3 m / (4 pi rho))^(1/3)``.

    A drawing convention of govopt's (the volume of a sphere; no source sizes the balls).

    Parameters
    ----------
    mass : float [kg]
        The flying mass (a negative one is drawn as a point).
    density : float [kg/m^3]
        The ball's density (steel, 7850).

    Returns
    -------
    float [m]
        The ball's radius.

    Examples
    --------
    By hand: 4 kg of steel gives ``r^3 = 3 x 4 / (4 pi 7850) = 1.2165e-4`` m^3, r = 49.5 mm:

    >>> round(ball_radius(4.0) * 1e3, 1)
    49.5
    """
    return float((3.0 * max(mass, 0.0) / (4.0 * np.pi * density)) ** (1.0 / 3.0))


def mirrored(parts) -> tuple[Part, ...]:
    """``parts`` and their mirror images across the spindle's axis (``r -> -r``): the other
    half of a governor drawn in its meridian plane (the frame is drawn once).

    A drawing convention of govopt's (no source).

    Parameters
    ----------
    parts : sequence of Part [m]
        One half of the drawing, points in metres.

    Returns
    -------
    tuple of Part [m]
        The parts, then the mirror images of those that are not ``"frame"``.

    Examples
    --------
    >>> half = (Part("mass", ((0.1, 0.2),), 0.02), Part("frame", ((0.0, 0.0), (0.0, 0.3))))
    >>> [(p.kind, p.points) for p in mirrored(half)][2]
    ('mass', ((-0.1, 0.2),))
    """
    out = list(parts)
    for p in parts:
        if p.kind != "frame":
            out.append(Part(p.kind, tuple((-x, y) for x, y in p.points), p.size))
    return tuple(out)
