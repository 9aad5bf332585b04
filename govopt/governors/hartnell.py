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

from ..keys import Key
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


class HartnellGovernor(BellCrankGovernor):
    """Hartnell governor (section 3.5(a), Fig. 3.10): fixed fulcrum, ball above it, compression
    spring on the sleeve."""

    type_name: ClassVar[str] = "hartnell"
    title: ClassVar[str] = "Hartnell governor (textbook ch. 3, section 3.5(a), Fig. 3.10)"
    spring: ClassVar[str | None] = "compression"
    common: ClassVar[tuple[Key, ...]] = common_keys(SLEEVE_ARM, "normal")
    keys: ClassVar[tuple[Key, ...]] = (*common, SPRING_LENGTH)
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
        gov = cls(**common, spring_length=reader.read(SPRING_LENGTH))
        gov.check_spring_length(reader)
        reader.finish()
        return gov

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
                self.lift_equation())
