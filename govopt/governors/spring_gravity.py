"""The governor controlled by a spring and gravity together (textbook ch. 3, section 3.5(c),
Figs. 3.12, 3.13).

The bell-crank levers are pivoted at O on the sleeve, which slides on the spindle; a cap is fixed
to the spindle's top and the rollers on the roller arms ``b`` press up against it, so the sleeve
is lifted against a compression spring between the sleeve and the cap and the sleeve's weight
(the dead load ``W``). Each ball hangs on its ball arm ``a`` below O. Geometry and statics:
:mod:`.bellcrank` (the fulcrum rides on the sleeve). Per ball, by virtual work::

    omega^2 m r = m g dy/dr + (W + S)/2 ds/dr       y = s - a cos(theta), ds/dr = b/a (90 deg)

which is the book's moment about the instantaneous centre I of the lever (on the line through O
square to the axis and on the vertical through the roller's centre; at minimum speed, with the
ball arm vertical, I is the roller's centre), section 3.5(c) eq. (i)::

    F CK = w KI + (W + S)/2 OI,    CK = a cos(theta), OI = b cos(theta), KI = OI + a sin(theta).

The spring: one helical compression spring of stiffness ``kappa`` and free length ``l0`` between
the sleeve and the cap, of length ``L = spring_length - s`` (``spring_length``: its length at
``radius_inner``); its initial compression is ``l0 - spring_length``. ``obliquity =
"small_angle"`` keeps the arms' directions fixed (``CK = a``, ``OI = KI = b``, the minimum-speed
figure); the book's Example 8 uses the exact figure (Fig. 3.13).
"""

from __future__ import annotations

from typing import ClassVar

from ..keys import Key
from .base import Equation
from .bellcrank import BellCrankGovernor, common_keys, spring_length_key

ROLLER_ARM = Key("roller_arm", "length", "the bell crank's roller arm b, from the fulcrum O on "
                                         "the sleeve to the roller under the cap",
                 source="textbook 3.5(c), Fig. 3.12")
SPRING_LENGTH = spring_length_key(
    "the compression spring's length between the sleeve and the cap at radius_inner; it "
    "shortens by the sleeve lift. The levers do not fix it (the cap's height does), so it has "
    "no default", source="textbook 3.5(c)")


class SpringGravityGovernor(BellCrankGovernor):
    """Spring-and-gravity governor (section 3.5(c), Fig. 3.12): fulcrum on the sleeve, ball below
    it, rollers under a fixed cap, compression spring plus the sleeve's dead load."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("textbook-ex8-spring_gravity", {}, "governor.obliquity",
                               ("exact", "small_angle"))

    type_name: ClassVar[str] = "spring_gravity"
    title: ClassVar[str] = ("Spring and gravity controlled governor (textbook ch. 3, "
                            "section 3.5(c), Figs. 3.12-3.13)")
    spring: ClassVar[str | None] = "compression"
    fulcrum_on_sleeve: ClassVar[bool] = True
    arm_key: ClassVar[str] = "roller_arm"
    fulcrum_at: ClassVar[str] = "inner"
    common: ClassVar[tuple[Key, ...]] = common_keys(ROLLER_ARM, "inner")
    keys: ClassVar[tuple[Key, ...]] = (*common, SPRING_LENGTH)
    example: ClassVar[str] = "spring_gravity-design"

    @classmethod
    def parse(cls, reader) -> SpringGravityGovernor:
        """Keys: ``ball_arm``, ``roller_arm``, the radius range (or ``sleeve_lift``),
        ``fulcrum_radius`` (O's radius;
        default ``radius_inner``: the ball arm vertical at minimum speed, Fig. 3.13(b)),
        ``crank_angle``, ``obliquity``, ``sleeve_friction``
        (:meth:`~.bellcrank.BellCrankGovernor.read_common`) and ``spring_length`` (the spring's
        length at ``radius_inner``)."""
        common = cls.read_common(reader)
        gov = cls(**common, spring_length=reader.read(SPRING_LENGTH))
        gov.check_spring_length(reader)
        reader.finish()
        return gov

    # -- the type's method: what a reader is told (textbook 3.5(c)) ---------------------------

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """Section 3.5(c): moments about the lever's instantaneous centre."""
        return (Equation("statics", "equilibrium of a lever pivoted on the sleeve: moments "
                         "about its instantaneous centre I (by virtual work, per ball: omega^2 m "
                         "r = m g dy/dr + (W + S)/2 ds/dr)", "F CK = w KI + (W + S)/2 OI, CK = "
                         "a cos(theta), OI = b cos(theta), KI = OI + a sin(theta)",
                         "textbook-ch3", "3.5(c) eq. (i)", ("governor.obliquity",),
                         name="characteristic"),
                Equation("statics", "the compression spring between the sleeve and the cap",
                         "S = kappa (l0 - L), L = spring_length - s", "textbook-ch3",
                         "3.5(c), Example 8", name="spring force"),
                self.lift_equation())
