"""The spring-loaded governor with the balls connected directly by springs (textbook ch. 3,
section 3.5(b), Fig. 3.11).

Each ball sits on the ball arm ``a`` of a bell crank whose sleeve arm ``b`` works the sleeve
(:mod:`.bellcrank`, as the Hartnell); ``ball_springs`` identical helical tension springs (two in
Fig. 3.11) join the two balls across the spindle, so each spring's length is ``2 r`` plus a
constant (the balls stay level with each other) and each ball is pulled in by the sum ``S`` of
their tensions (section 3.5(b) eq. i, ``S = F``). Two variants (``variant``):

* ``"direct"`` (Fig. 3.11(a)): the ball springs are the design spring: stiffness ``kappa`` and
  free length ``l0`` each, length ``L = spring_length + 2 (r - r_inner)`` (``spring_length``: at
  ``radius_inner``); per ball ``Q = ball_springs kappa (L - l0)`` (plus the weights);
* ``"lever"`` (Fig. 3.11(b)): "since the spring force in this type of governor cannot be adjusted
  it is usual to have a supplementary adjustable spring, which acts on a lever and provides a force
  on the sleeve". The supplementary spring B is the design spring (the one the optimiser sizes,
  as Example 7 asks); the ball springs A are fixed governor keys: ``ball_spring_stiffness`` and
  ``ball_spring_tension`` (each, at ``radius_inner``). B is a tension spring on a lever pivoted at
  one end, at ``lever_spring_arm`` from the pivot, the sleeve at ``lever_sleeve_arm``: its length
  ``L = spring_length + rho s`` with ``rho = lever_spring_arm / lever_sleeve_arm`` (the lever's
  small rotation taken as linear, as the book does) and its force ``P = kappa (L - l0)`` loads the
  sleeve with ``rho P``. Per ball, by virtual work::

      omega^2 m r = m g dy/dr + n T_A(r) + (W + rho P)/2 ds/dr
      T_A(r) = T_A,inner + 2 k_A (r - r_inner)

  the book's moment about the bell crank's fulcrum, ``(W/2) b = (F - S) a`` (Example 7), and about
  the lever's pivot, ``P lever_spring_arm = W_s lever_sleeve_arm``.

The book takes no account of the balls' weight here; ``obliquity = "small_angle"`` keeps the ball
at its height (the book's figure), ``"exact"`` lets it tilt with the arm (:mod:`.bellcrank`).
"""

from __future__ import annotations

from typing import ClassVar

from ..keys import Key
from .base import Equation
from .bellcrank import BellCrankGovernor, common_keys, spring_length_key

VARIANTS = ("direct", "lever")
LEVER = "with variant = \"lever\" (required there)"
SLEEVE_ARM = Key("sleeve_arm", "length", "the bell crank's sleeve arm b, from the fulcrum to the "
                                         "sleeve", source="textbook 3.5(b), Fig. 3.11")
VARIANT = Key("variant", "choice", "\"direct\": the ball springs are the design spring (Fig. "
                                   "3.11(a)); \"lever\": a supplementary spring on a lever "
                                   "loads the sleeve and is the design spring, the ball springs "
                                   "given (Fig. 3.11(b))", default="direct", choices=VARIANTS,
              source="textbook 3.5(b)")
BALL_SPRINGS = Key("ball_springs", "count", "how many identical springs join the two balls",
                   default=2, source="textbook Fig. 3.11")
SPRING_LENGTH = spring_length_key(
    "the design spring's length at radius_inner: each ball spring's (\"direct\"; it lengthens "
    "by twice the balls' outward travel) or the lever's spring's (\"lever\")",
    default=lambda v: 2.0 * v["radius_inner"] if v["variant"] == "direct" else None,
    default_text="with variant = \"direct\", 2 radius_inner: the springs join the balls' "
                 "centres, 2 r apart (give the spring's own length where its hooks or the balls "
                 "take room); required with variant = \"lever\" (the lever's spring has no "
                 "length the geometry fixes)", source="textbook 3.5(b)")
LEVER_KEYS = (
    Key("lever_spring_arm", "length", "the lever's arm from its pivot to the supplementary "
                                      "spring", when=LEVER, source="textbook Fig. 3.11(b)"),
    Key("lever_sleeve_arm", "length", "the lever's arm from its pivot to the sleeve",
        when=LEVER, source="textbook Fig. 3.11(b)"),
    Key("ball_spring_stiffness", "stiffness", "each ball spring's stiffness (the ball springs "
                                              "are given in this variant)", when=LEVER,
        source="textbook 3.5(b), Example 7"),
    Key("ball_spring_tension", "force", "each ball spring's tension at radius_inner",
        nonnegative=True, when=LEVER, source="textbook 3.5(b), Example 7"),
)


class SpringLoadedGovernor(BellCrankGovernor):
    """Balls connected directly by tension springs (section 3.5(b), Fig. 3.11(a)), optionally with
    a supplementary spring on the sleeve through a lever (Fig. 3.11(b))."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("textbook-ex6-spring_loaded", {}, "governor.obliquity",
                               ("exact", "small_angle"))

    type_name: ClassVar[str] = "spring_loaded"
    title: ClassVar[str] = ("Spring-loaded governor, balls connected by springs (textbook ch. 3, "
                            "section 3.5(b), Fig. 3.11)")
    spring: ClassVar[str | None] = "tension"
    common: ClassVar[tuple[Key, ...]] = common_keys(SLEEVE_ARM, "normal")
    keys: ClassVar[tuple[Key, ...]] = (*common, VARIANT, BALL_SPRINGS, SPRING_LENGTH,
                                       *LEVER_KEYS)
    example: ClassVar[str] = "spring_loaded-design"

    def __init__(self, *, variant="direct", ball_springs=2, lever_ratio=0.0,
                 ball_spring_stiffness=0.0, ball_spring_tension=0.0, **common):
        super().__init__(**common)
        self.variant, self.ball_springs, self.lever_ratio = variant, ball_springs, lever_ratio
        self.ball_spring_stiffness = ball_spring_stiffness
        self.ball_spring_tension = ball_spring_tension

    @classmethod
    def parse(cls, reader) -> SpringLoadedGovernor:
        """Keys: ``ball_arm``, ``sleeve_arm``, the radius range, ``fulcrum_radius`` (default: the
        ball arm vertical at ``radius_normal``), ``crank_angle``, ``obliquity``,
        ``sleeve_friction`` (:meth:`~.bellcrank.BellCrankGovernor.read_common`); ``variant``
        ("direct" | "lever"), ``ball_springs`` (default 2), ``spring_length`` (the design
        spring's length at ``radius_inner``) and, for the lever, :data:`LEVER_KEYS`."""
        common = cls.read_common(reader)
        v = {"radius_inner": common["x_inner"]}
        reader.read_all((VARIANT, BALL_SPRINGS), v)
        lever = v["variant"] == "lever"
        extra = dict(variant=v["variant"], ball_springs=v["ball_springs"],
                     spring_length=reader.read(SPRING_LENGTH, v, required=lever or None))
        if lever:
            arm, sleeve, stiffness, tension = reader.read_all(LEVER_KEYS).values()
            extra.update(lever_ratio=arm / sleeve, ball_spring_stiffness=stiffness,
                         ball_spring_tension=tension)
        else:
            for key in LEVER_KEYS:
                if reader.has(key.name):
                    reader.fail(key.name, "belongs to variant = \"lever\" (Fig. 3.11(b))")
        reader.finish()
        return cls(**common, **extra)

    def spring_length_at(self, geo) -> tuple:
        """Direct: the ball springs, ``L = spring_length + 2 (r - r_inner)``, ``ball_springs`` of
        them; lever: spring B, ``L = spring_length + rho s``, one."""
        if self.variant == "direct":
            return self.spring_length + 2.0 * (geo["r"] - self.x_inner), 2.0, 0.0, \
                self.ball_springs
        rho = self.lever_ratio
        return self.spring_length + rho * geo["s"], rho * geo["s1"], rho * geo["s2"], 1

    def fixed_force(self, x, geo) -> tuple:
        """Lever variant: the ball springs A, ``n T_A(r)`` per ball (section 3.5(b) eq. i)."""
        if self.variant == "direct":
            return super().fixed_force(x, geo)
        n, k = self.ball_springs, self.ball_spring_stiffness
        tension = self.ball_spring_tension + 2.0 * k * (x - self.x_inner)
        return n * tension, 2.0 * n * k + 0.0 * x

    # -- the type's method: what a reader is told (textbook 3.5(b)) ---------------------------

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """Section 3.5(b): the ball springs (and the lever's spring B, Example 7)."""
        n = self.ball_springs
        if self.variant == "direct":
            out = (Equation("statics", f"equilibrium of a ball pulled in by the {n} springs "
                            "joining the balls (by virtual work; per ball)", "omega^2 m r = m g "
                            f"dy/dr + {n} kappa (L - l0) + (W/2) ds/dr", "textbook-ch3",
                            "3.5(b) eq. (i)", ("governor.obliquity",), name="characteristic"),
                   Equation("statics", "the ball springs' tension and length",
                            "T = kappa (L - l0), L = spring_length + 2 (r - r_inner)",
                            "textbook-ch3", "3.5(b), Fig. 3.11(a)", name="spring force"))
        else:
            out = (Equation("statics", "equilibrium with the ball springs A and the "
                            "supplementary spring B on a lever (by virtual work; per ball)",
                            f"omega^2 m r = m g dy/dr + {n} T_A(r) + (W + rho P)/2 ds/dr, "
                            "T_A = T_A,inner + 2 k_A (r - r_inner)", "textbook-ch3",
                            "3.5(b) Example 7, Fig. 3.11(b)", ("governor.obliquity",),
                            name="characteristic"),
                   Equation("statics", "the supplementary spring B through its lever",
                            "P = kappa (L - l0), L = spring_length + rho s, rho = "
                            "lever_spring_arm / lever_sleeve_arm", "textbook-ch3",
                            "3.5(b) Example 7", name="spring force"))
        return out + (self.lift_equation(),)

    def spring_between_balls(self) -> bool:
        """The direct variant's springs join the balls (Fig. 3.11(a))."""
        return self.variant == "direct"
