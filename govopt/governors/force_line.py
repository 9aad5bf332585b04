"""A governor given by its controlling-force line (textbook ch. 3, section 3.3, Fig. 3.2).

The books state many spring-controlled governors by their controlling force alone: per ball, a
straight line ``F = a r + b`` of the ball's radius ``r`` (the controlling-force diagram of
section 3.3), with the mechanism behind it (levers, springs, weights) left out. The balls are in
equilibrium where the line meets the centrifugal force ``m omega^2 r``::

    omega^2 = F / (m r) = a/m + b/(m r)

so the governor is *isochronous* for ``b = 0`` (the line passes through the origin: one speed
over the whole range), *stable* for ``b < 0`` (the speed rises with the radius: section 3.2,
"the controlling force must increase" faster than the radius), and *unstable* for ``b > 0``.
Its isochronism is reported as its stability (:mod:`govopt.analysis.classic`), and the
intercept that makes it isochronous is found by ``govopt solve --unknown
governor.force_intercept --target "range=0 rpm"`` (0, for the line itself; for a mechanism, the
spring's initial force: docs/how-to/textbook-problems.md).

The coordinate is the ball's radius ``x = r`` (m), every generalised force per ball: ``jp = m
r``, ``cf = a r + b``; the regulating member is taken to move with the ball (``s' = 1``: the
line says nothing of the sleeve), so the effort is per unit of the ball's radius.
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from ..keys import Key
from .base import Equation, Governor, Terms
from .porter import RANGE

FORCE_SLOPE = Key("force_slope", "stiffness", "the slope a of the controlling force per ball, "
                                              "F = a r + b", source="textbook 3.3, Fig. 3.2",
                  example="2.4 N/mm")
FORCE_INTERCEPT = Key("force_intercept", "force", "the intercept b of the controlling force "
                                                  "per ball at r = 0 (negative: stable; 0: "
                                                  "isochronous; positive: unstable)",
                      positive=False, source="textbook 3.2, 3.3", example="-60 N")


class ForceLineGovernor(Governor):
    """A governor given by its controlling force per ball, ``F = a r + b`` (section 3.3)."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("force_line-design", {"governor.force_intercept": "-1 N",
                                                 "design.ball_weight": "5 kgf"}, "", ("exact",))

    type_name: ClassVar[str] = "force_line"
    title: ClassVar[str] = ("Governor given by its controlling-force line (textbook ch. 3, "
                            "section 3.3, Fig. 3.2)")
    coordinate: ClassVar[str] = "length"
    coordinate_name: ClassVar[str] = "ball radius"
    coordinate_key: ClassVar[str] = "radius"
    travel: ClassVar[str] = "length"
    mass_key: ClassVar[str] = "ball"
    resonance_ceiling: ClassVar[bool] = False
    keys: ClassVar[tuple[Key, ...]] = (FORCE_SLOPE, FORCE_INTERCEPT, *RANGE)
    example: ClassVar[str] = "force_line-design"

    def bench_reference(self, spec, x):
        """The line's ``omega^2 = (a r + b) / (m r)`` in mpmath (50 digits)."""
        import mpmath as mp

        with mp.workdps(50):
            a, b, m = (mp.mpf(v) for v in (self.slope, self.intercept, spec.design.flying_mass))
            return np.array([float(mp.sqrt((a * mp.mpf(float(r)) + b) / (m * mp.mpf(float(r)))))
                             for r in np.atleast_1d(x)])

    def __init__(self, slope: float, intercept: float, x_inner, x_outer, x_normal):
        self.slope, self.intercept = slope, intercept
        self.x_inner, self.x_outer, self.x_normal = x_inner, x_outer, x_normal

    def __repr__(self):
        return (f"ForceLineGovernor(a={self.slope}, b={self.intercept}, x=({self.x_inner}, "
                f"{self.x_normal}, {self.x_outer}))")

    @classmethod
    def parse(cls, reader) -> ForceLineGovernor:
        """Keys: ``force_slope`` (a), ``force_intercept`` (b) and the radius range.

        >>> from govopt.reader import Reader
        >>> gov = ForceLineGovernor.parse(Reader("line", {"force_slope": "2.4 N/mm",
        ...     "force_intercept": "-60 N", "radius_inner": "10 cm", "radius_outer": "15 cm"},
        ...     "governor", []))
        >>> float(gov.terms(0.1, 5.0).cf)  # 2400 N/m x 0.1 m - 60 N
        180.0
        """
        v = reader.read_all((FORCE_SLOPE, FORCE_INTERCEPT, *RANGE))
        inner, outer, normal = (v[k.name] for k in RANGE)
        if not inner < outer:
            reader.fail("radius_outer", "expected radius_inner < radius_outer")
        if not inner <= normal <= outer:
            reader.fail("radius_normal", "expected radius_inner <= radius_normal <= radius_outer")
        for r in (inner, outer):
            if not v["force_slope"] * r + v["force_intercept"] > 0:
                reader.fail("force_intercept", f"the controlling force must pull the balls "
                                               f"in over the range: a r + b <= 0 at "
                                               f"{r * 100:g} cm")
        reader.finish()
        return cls(v["force_slope"], v["force_intercept"], inner, outer, normal)

    def terms(self, x, m, analysis=None, central=None) -> Terms:
        """Per ball: ``jp = m r``, ``cf = a r + b`` (section 3.3); no spring, no inertia
        reactions."""
        x = np.asarray(x, dtype=float)
        zero = 0.0 * x
        return Terms(jp=m * x, jpp=m + zero, cf=self.slope * x + self.intercept,
                     cf_x=self.slope + zero, ci=zero, ci_x=zero, A=zero, B=zero, A_x=zero,
                     B_x=zero)

    def inertia(self, x, m, central=None):
        """``I = m`` (kg, per ball): the ball's mass along its radius."""
        return m + 0.0 * np.asarray(x, dtype=float)

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """Section 3.3: the line and the equilibrium it gives."""
        return (Equation("statics", "controlling force per ball, given as a line",
                         "F = a r + b", "textbook-ch3", "3.3, Fig. 3.2",
                         name="controlling force"),
                Equation("statics", "equilibrium: the line meets the centrifugal force "
                                    "(isochronous for b = 0, stable for b < 0)",
                         "m omega^2 r = a r + b, omega^2 = a/m + b/(m r)", "textbook-ch3",
                         "3.2, 3.3", name="characteristic"))
