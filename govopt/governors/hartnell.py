"""The Hartnell governor (textbook ch. 3, section 3.5(a), Fig. 3.10).

Two bell-crank levers on pins carried by a frame on the spindle; each carries a ball at the end of
its ball arm ``a`` (standing up from the fulcrum) and a roller at the end of its sleeve arm ``b``;
the rollers lift the collar on the sleeve against a helical compression spring round the spindle.
Geometry and statics: :mod:`.bellcrank` (exact obliquity by default; ``obliquity =
"small_angle"`` is the book's simplification). Per ball, by virtual work::

    omega^2 m r = m g dy/dr + (W + S)/2 ds/dr           (+- R/2 ds/dr with sleeve friction)

which, for the book's 90 deg crank, is its moment about the fulcrum
``F a cos(theta) + w a sin(theta) = (S + W)/2 b cos(theta)``, i.e. section 3.5(a) eq. (i)
``F a = (S/2) b`` when the ball's weight is neglected.

The spring: one helical compression spring of stiffness ``kappa`` and free length ``l0``, of
length ``L = spring_length - s`` (``spring_length``: its length with the sleeve down, at
``radius_inner``), pressing the sleeve with ``S = kappa (l0 - L)``; its initial compression is
``l0 - spring_length`` (the book's ``delta = S_2/k``, eq. viii).

Classic measures: the book's spring stiffness ``k = 2 (a/b)^2 (F_1 - F_2)/(r_1 - r_2)``
(eq. vii) and initial compression (eq. viii) are the design spring through two equilibria: the
characteristic is affine in ``kappa`` and ``kappa l0``, so two speeds at two radii fix both.
"""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from ..keys import Key
from ..units import G_STANDARD
from .base import Equation
from .bellcrank import BellCrankGovernor, common_keys, spring_length_key

SLEEVE_ARM = Key("sleeve_arm", "length", "the bell crank's sleeve arm b, from the fulcrum to the "
                                         "roller on the sleeve's collar",
                 source="textbook 3.5(a), Fig. 3.10", example="9 cm")
SPRING_LENGTH = spring_length_key(
    "the compression spring's installed length with the sleeve down (at radius_inner), "
    "between the collar and its seat; it shortens by the sleeve lift. The levers do not fix "
    "it (the frame does), so it has no default", source="textbook 3.5(a)",
    example="10 cm")

BALL_POSITION = Key("ball_position", "choice", "where the balls sit: \"above\" the fulcrum "
                    "(Fig. 3.10) or \"below\" it (the ball arms hanging down: the levers "
                    "upside down, so the sleeve falls as the balls fly out and the balls' and "
                    "the sleeve's weights resist it)", default="above",
                    choices=("above", "below"), source="textbook 3.5(a)")


class HartnellGovernor(BellCrankGovernor):
    """Hartnell governor (section 3.5(a), Fig. 3.10): fixed fulcrum, ball above it, compression
    spring on the sleeve."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("textbook-ex5-hartnell", {}, "governor.obliquity",
                               ("exact", "small_angle"))

    type_name: ClassVar[str] = "hartnell"
    title: ClassVar[str] = "Hartnell governor (textbook ch. 3, section 3.5(a), Fig. 3.10)"
    spring: ClassVar[str | None] = "compression"
    common: ClassVar[tuple[Key, ...]] = common_keys(SLEEVE_ARM, "normal")
    keys: ClassVar[tuple[Key, ...]] = (*common, BALL_POSITION, SPRING_LENGTH)
    example: ClassVar[str] = "hartnell-design"

    @classmethod
    def parse(cls, reader) -> HartnellGovernor:
        """Keys: ``ball_arm``, ``sleeve_arm``, the radius range (or ``sleeve_lift``),
        ``fulcrum_radius`` (default: the ball arm vertical at ``radius_normal``, as in the
        book's examples), ``crank_angle``, ``obliquity``, ``sleeve_friction``
        (:meth:`BellCrankGovernor.read_common`) and ``spring_length`` (the spring's length at
        ``radius_inner``).

        >>> from govopt.reader import Reader
        >>> gov = HartnellGovernor.parse(Reader("ex5", {"ball_arm": "15 cm",
        ...     "sleeve_arm": "9 cm", "radius_inner": "10 cm", "radius_outer": "15 cm",
        ...     "spring_length": "10 cm"}, "governor", []))
        >>> round(float(gov.sleeve_lift(0.15)) * 100, 12)  # cm: (b/a) (r_1 - r_2)
        3.0
        """
        common = cls.read_common(reader)
        below = reader.read(BALL_POSITION) == "below"
        gov = cls(**common, spring_length=reader.read(SPRING_LENGTH))
        gov.ball_below = below
        gov.check_spring_length(reader)
        reader.finish()
        return gov

    def link_forces(self, x, m, central, omega2, restoring) -> dict:
        """The force between each roller and the sleeve's collar and each fulcrum's reaction
        (N), from the bell crank's statics (section 3.5(a)): the collar's force on the roller,
        vertical, ``V = (Q - (+-) m g dy/dr) / (ds/dr)`` (the spring's, the sleeve's weight and
        the friction, read back from the seam's restoring force ``Q``); the fulcrum holds the
        ball's centrifugal force ``m omega^2 r`` across and ``m g + V`` along the axis (``m g
        - V`` with the balls below), so its reaction is ``sqrt((m omega^2 r)^2 + (m g +- V)^2)``.

        Example 4's Hartnell (small-angle statics, weights neglected in the controlling force)
        at the inner end: the spring presses 19.32 kgf, V = 9.66 kgf, the ball's 2 kgf weight
        and its centrifugal force ``2 x (240 pi/30)^2 x 0.075 / g = 9.66`` kgf (a = b), so by
        hand the reaction is ``sqrt(9.66^2 + 11.66^2) = 15.14`` kgf:

        >>> import govopt, numpy as np
        >>> from govopt.examples import example
        >>> spec = govopt.load_spec(example("textbook-ex4-hartnell"))
        >>> gov, KGF = spec.governor, 9.80665
        >>> t = gov.terms(0.075, 2.0, spec.analysis)
        >>> f = gov.link_forces(0.075, 2.0, 0.0, t.omega_squared(3.572 * KGF / 0.01, 0.1541),
        ...                     t.restoring(3.572 * KGF / 0.01, 0.1541))
        >>> round(float(f["fulcrum reaction"]) / KGF, 2)
        15.14
        """
        geo = self.geometry(x)
        sign = -1.0 if self.ball_below else 1.0
        V = (np.asarray(restoring, dtype=float) - sign * G_STANDARD * m * geo["y1"]) / geo["s1"]
        across = m * np.asarray(omega2, dtype=float) * np.asarray(x, dtype=float)
        return {"roller force": V, "fulcrum reaction": np.hypot(across, G_STANDARD * m
                                                                + sign * V),
                "sleeve load": 2.0 * V}

    # -- the type's method: what a reader is told (textbook 3.5(a)) ---------------------------

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """Section 3.5(a): moments about the fulcrum, the spring's force and the lift."""
        return (Equation("statics", "equilibrium of a bell crank: moments about the fulcrum "
                         "(by virtual work on the exact lever, per ball: omega^2 m r = m g dy/dr "
                         "+ (W + S)/2 ds/dr)", "F a cos(theta) + w a sin(theta) = (S + W)/2 b "
                         "cos(theta); the book: F a = (S/2) b", "textbook-ch3",
                         "3.5(a) eq. (i)", ("governor.obliquity",), name="characteristic"),
                Equation("statics", "the compression spring on the sleeve: its force, length "
                         "and initial compression", "S = kappa (l0 - L), L = spring_length - s; "
                         "initial compression l0 - spring_length", "textbook-ch3",
                         "3.5(a) eqs. (vii)-(viii)", name="spring force"),
                self.lift_equation()) + ((Equation(
                    "statics", "the balls below the fulcrum: the levers upside down, the "
                    "sleeve falling as the balls fly out", "omega^2 m r = -m g dy/dr - (W/2) "
                    "ds/dr + (S/2) ds/dr: the weights' moments change sign", "textbook-ch3",
                    "3.5(a)", name="ball below"),) if self.ball_below else ())
