"""Bell-crank governors of the textbook (ch. 3, section 3.5, Figs. 3.10-3.13): the lever geometry
and the statics shared by the Hartnell (:mod:`.hartnell`), the governor with the balls connected
by springs (:mod:`.spring_loaded`) and the spring-and-gravity governor (:mod:`.spring_gravity`).

Each ball sits at the end of the *ball arm* ``a`` of a bell-crank lever; the other arm ``b`` (the
sleeve arm, or the roller arm) bears on the sleeve or on a cap; the two arms meet at the fulcrum at
the ``crank_angle`` gamma ("usually 90 deg but in practice it may be greater", section 3.5(a)).
In the meridian plane, with ``theta`` the ball arm's inclination to the vertical (positive as the
ball moves out) and the fulcrum at radius ``r_f`` from the axis::

    r = r_f + a sin(theta)                                  the ball radius, the coordinate x
    s = b cos(gamma - theta) - (the same at r_inner)        the sleeve lift
    ds/dr = b sin(gamma - theta) / (a cos(theta))

* Hartnell (Fig. 3.10) and the spring-loaded governor (Fig. 3.11): the fulcrum is fixed on the
  frame; the ball arm stands up from it and the sleeve arm points in to the sleeve, so the rollers
  lift the sleeve as the balls fly out ("the upward pressure of the rollers on the collar of the
  sleeve is balanced by the downward thrust of the helical spring"). The ball's height above the
  fulcrum is ``a cos(theta)``.
* Spring and gravity (Fig. 3.12): the fulcrum O rides on the sleeve, the ball hangs below it and
  the roller arm's roller runs under a cap fixed to the spindle; the roller's height being fixed,
  O (and the sleeve) rises by the same ``s`` and the ball's height is ``s - a cos(theta)``.

For a 90 deg crank ``ds/dr = b/a`` exactly: the book's ``h = (b/a)(r_1 - r_2)`` (section 3.5(a),
eq. vi) is exact, the two arcs' projections scaling alike. The obliquity shows in the balls' weight
(their height changes as the arm tilts) and, for another crank angle, in ``ds/dr`` itself.

Statics by virtual work, per ball (the coordinate is the ball radius, every generalised force is
per ball, so ``J = m r^2``, ``jp = m r``, ``jpp = m``)::

    omega^2 m r = Q(r) = m g dy/dr + (W/2) ds/dr + (N/2) kappa (L - l0) dL/dr  (+ fixed springs)

with ``y`` the ball's height, ``W`` the sleeve's weight (the central load) and ``N`` springs of
stiffness ``kappa`` and free length ``l0`` each of length ``L(r)`` (their strain energy
``N kappa (L - l0)^2 / 2`` shared by the two balls). ``Q`` is the book's controlling force
(section 3.3); moments about the fulcrum (section 3.5(a) eq. i) or the instantaneous centre
(section 3.5(c) eq. i) give the same, as the tests check.

The fidelity ``obliquity = "small_angle"`` is the book's simplification for the Hartnell
("it is assumed that the arms are mutually perpendicular and the lines of action of forces are at
right angles to the arm", "neglecting the effect of pull of gravity on the governor balls"):
``ds/dr = b/a`` and the ball keeps its height relative to the fulcrum, so its weight does no work
about a fixed fulcrum. It needs a 90 deg crank.

Sleeve friction (section 3.4(b), "Friction at the sleeve"; section 3.5(a)): a force ``R`` opposing
the sleeve's motion is added to the spring force rising and subtracted falling: the band
``R/2 |ds/dr|`` per ball.

Neglected, as the book does: the masses of the levers (the generalised inertia is the balls' and
the sleeve's) and the friction of the rollers on the collar or cap.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..keys import Key
from ..units import G_STANDARD
from .base import Coordinate, Equation, Governor, Setting, Terms
from .drawing import Drawing, Part, ball_radius, mirrored, zigzag
from .porter import RANGE

OBLIQUITIES = ("exact", "small_angle")
RIGHT_ANGLE = np.pi / 2
#: the ball radius range as the ball governors give it (:mod:`.porter`); the outer radius may
#: be given by the sleeve's lift instead
RADIUS_INNER, _, RADIUS_NORMAL = RANGE

BALL_ARM = Key("ball_arm", "length", "the bell crank's ball arm a, from the fulcrum to the "
                                     "ball's centre", source="textbook 3.5(a), Fig. 3.10",
               example="15 cm")
RADIUS_OUTER = Key("radius_outer", "length", "the balls' radius of rotation at the outermost "
                                             "configuration (sleeve up, highest speed)",
                   default=None, default_text="from sleeve_lift",
                   when="unless sleeve_lift is given: give one of the two")
SLEEVE_LIFT = Key("sleeve_lift", "length", "the sleeve's lift from the innermost to the "
                                           "outermost configuration, in place of radius_outer "
                                           "(which follows from the levers: (a/b) times the "
                                           "lift for a 90 deg crank)",
                  default=None, when="in place of radius_outer",
                  source="textbook 3.5(a), eq. vi: h = (b/a)(r_1 - r_2)")
CRANK_ANGLE = Key("crank_angle", "angle", "the angle between the bell crank's two arms "
                                          "(\"usually 90 deg but in practice it may be "
                                          "greater\")", default=RIGHT_ANGLE, example="90 deg",
                  default_text="90 deg", low=0.0, high=np.pi, range_text="(0 deg, 180 deg)",
                  source="textbook 3.5(a)")
OBLIQUITY = Key("obliquity", "choice", "\"exact\": the levers' true geometry (the balls' weight "
                                       "works as the arms tilt); \"small_angle\": the book's "
                                       "simplification (arms square to the forces, the balls' "
                                       "weight neglected; a 90 deg crank only)",
                default="exact", choices=OBLIQUITIES, source="textbook 3.5(a)")
SLEEVE_FRICTION = Key("sleeve_friction", "force", "the friction force R at the sleeve, added to "
                                                  "the spring force rising and subtracted "
                                                  "falling", default=0.0, nonnegative=True,
                      source="textbook 3.4(b), 3.5(a)")


def common_keys(arm: Key, fulcrum_at: str) -> tuple[Key, ...]:
    """The ``[governor]`` keys every bell-crank type reads, in order
    (:meth:`BellCrankGovernor.read_common`): the lever's dimensions of the textbook's section 3.5.

    Parameters
    ----------
    arm : Key [-]
        The type's second arm's key (sleeve or roller arm, [m]).
    fulcrum_at : str [-]
        Where the fulcrum's default radius puts the ball arm vertical: "normal" (at
        radius_normal, the book's examples) or "inner" (at radius_inner, Fig. 3.13(b)).

    Returns
    -------
    tuple of Key [-]
        The keys (lengths [m], the crank angle [rad], the friction [N], choices).

    References
    ----------
    [textbook-ch3] section 3.5, Figs. 3.10-3.13.

    Examples
    --------
    >>> from govopt.governors.hartnell import SLEEVE_ARM
    >>> [k.name for k in common_keys(SLEEVE_ARM, "normal")][:4]
    ['ball_arm', 'sleeve_arm', 'radius_inner', 'radius_outer']
    """
    at = "radius_normal" if fulcrum_at == "normal" else "radius_inner"
    fulcrum = Key("fulcrum_radius", "length", "the fulcrum's radius from the spindle's axis",
                  default=lambda v: v[at],
                  default_text=f"{at}: the ball arm vertical there"
                               + (" (the book's examples)" if fulcrum_at == "normal" else
                                  " (at minimum speed, Fig. 3.13(b))"),
                  source="textbook 3.5")
    return (BALL_ARM, arm, RADIUS_INNER, RADIUS_OUTER, SLEEVE_LIFT, CRANK_ANGLE, OBLIQUITY,
            RADIUS_NORMAL, fulcrum, SLEEVE_FRICTION)


def spring_length_key(meaning: str, **kw) -> Key:
    """The bell-crank types' ``spring_length`` key [m]: the design spring's length at
    radius_inner (``meaning`` says where the spring sits), and how to choose it.

    Parameters
    ----------
    meaning : str [-]
        Where the spring sits and how its length changes with the lift.
    **kw : Key options [-]
        Further :class:`~govopt.keys.Key` fields (``source``, ``default``, ``example``).

    Returns
    -------
    Key [m]
        A length key named ``spring_length``.

    References
    ----------
    [textbook-ch3] section 3.5 (a)-(c): the springs of Figs. 3.10-3.13, whose installed length
    each type states.

    Examples
    --------
    >>> key = spring_length_key("the spring's length at radius_inner", source="textbook 3.5(a)")
    >>> key.name, key.kind
    ('spring_length', 'length')
    """
    return Key("spring_length", "length", meaning + ". Only the spring's initial compression "
               "or extension enters the statics (the search designs the free length), but the "
               "spring must fit: a longer spring leaves room for more turns of thinner wire, a "
               "shorter one needs fewer turns of thicker wire; choose the room the frame gives",
               **kw)


@dataclass(frozen=True)
class BellCrank:
    """A bell-crank lever (section 3.5, Figs. 3.10-3.13), SI: ball arm ``a``, sleeve (or roller)
    arm ``b``, fulcrum at radius ``r_f``, arms at ``crank_angle`` (rad); ``obliquity`` "exact" or
    "small_angle" (the book's simplification, 90 deg crank only)."""

    ball_arm: float
    sleeve_arm: float
    fulcrum_radius: float
    crank_angle: float = RIGHT_ANGLE
    obliquity: str = "exact"

    def angle(self, x):
        """The ball arm's inclination to the vertical, ``theta = asin((r - r_f)/a)`` (rad), at
        ball radius ``x`` (m).

        >>> round(float(np.degrees(BellCrank(0.15, 0.09, 0.125).angle(0.15))), 6)  # Example 5
        9.594068
        """
        return np.arcsin((np.asarray(x, dtype=float) - self.fulcrum_radius) / self.ball_arm)

    def state(self, x):
        """At ball radii ``x`` (m): the sleeve arm end's height ``s`` above the fulcrum (m, up to
        a constant) and the ball's height ``z`` above the fulcrum (m), with their first and second
        x-derivatives (suffixes 1, 2); also ``theta``.

        Exact: ``s = b cos(gamma - theta)``, ``z = a cos(theta)``, ``dtheta/dr = 1/(a cos theta)``,
        ``d2theta/dr2 = sin(theta)/(a^2 cos^3 theta)``. Small angle: ``s = (b/a)(r - r_f)``,
        ``z = a``.
        """
        x = np.asarray(x, dtype=float)
        a, b, gamma = self.ball_arm, self.sleeve_arm, self.crank_angle
        sn = (x - self.fulcrum_radius) / a
        theta = np.arcsin(sn)
        if self.obliquity == "small_angle":
            zero = 0.0 * x
            return dict(theta=theta, s=b * sn, s1=b / a + zero, s2=zero,
                        z=a + zero, z1=zero, z2=zero)
        c = np.sqrt(1.0 - sn**2)
        t1, t2 = 1.0 / (a * c), sn / (a**2 * c**3)
        su, cu = np.sin(gamma - theta), np.cos(gamma - theta)
        return dict(theta=theta, s=b * cu, s1=b * su * t1, s2=b * (su * t2 - cu * t1**2),
                    z=a * c, z1=-sn / c, z2=-1.0 / (a * c**3))

    def arm_end_radius(self, x):
        """Radius of the sleeve (roller) arm's end, ``r_f - b sin(gamma - theta)`` (m)."""
        return self.fulcrum_radius - self.sleeve_arm * np.sin(self.crank_angle - self.angle(x))

    def reach_error(self, radii, arm_key="sleeve_arm"):
        """Why the lever cannot take the balls over ``radii`` (m), or ``""``."""
        radii = np.asarray(radii, dtype=float)
        a = self.ball_arm
        if np.any(np.abs(radii - self.fulcrum_radius) >= a):
            return (f"the ball arm ({a * 100:g} cm) cannot reach it from the fulcrum at "
                    f"{self.fulcrum_radius * 100:g} cm")
        theta = self.angle(radii)
        if np.any(theta >= self.crank_angle) or np.any(theta <= self.crank_angle - np.pi):
            return "the sleeve would not rise steadily as the balls fly out"
        if np.any(self.arm_end_radius(radii) < 0.0):
            arm = arm_key.replace("_", " ")
            return f"the {arm} ({self.sleeve_arm * 100:g} cm) crosses the axis"
        return ""


def spring_terms(L, L1, L2, count):
    """Per ball ``(A, B, A_x, B_x)`` [m, -, -, 1/m] of ``count`` springs of length ``L(x)``
    shared by two balls (textbook section 3.5(b), by virtual work).

    ``Q = (count/2) kappa (L - l0) L1 = kappa (A - B l0)`` by virtual work on their strain energy
    ``count kappa (L - l0)^2 / 2`` (tension or compression alike); ``A_x``, ``B_x`` are the
    x-derivatives.

    Parameters
    ----------
    L : float or array [m]
        Each spring's length at ball radius ``x``.
    L1 : float or array [-]
        ``dL/dx``.
    L2 : float or array [1/m]
        ``d2L/dx2``.
    count : int [-]
        Number of springs.

    Returns
    -------
    tuple [m, -, -, 1/m]
        ``(A, B, dA/dx, dB/dx)``, with the force per ball ``Q = kappa (A - B l0)`` [N].

    References
    ----------
    [textbook-ch3] section 3.5(b), Fig. 3.11(a) (the balls joined by springs).

    Examples
    --------
    Two springs joining the balls (Fig. 3.11(a)): ``L = 2 x`` minus the hooks, so ``L1 = 2``:

    >>> spring_terms(0.2, 2.0, 0.0, 2)
    (0.4, 2.0, 4.0, 0.0)

    The textbook's Example 6: 0.9 kgf/cm springs extended 6.5 cm at r = 10 cm (18 cm long, free
    11.5 cm) pull each ball in with ``2 x 0.9 x 6.5 = 11.7`` kgf:

    >>> A, B, _, _ = spring_terms(0.18, 2.0, 0.0, 2)
    >>> round(0.9 * 100 * (A - B * 0.115), 6)  # kgf, kappa in kgf/m
    11.7
    """
    h = 0.5 * count
    return h * L * L1, h * L1, h * (L1 * L1 + L * L2), h * L2


class BellCrankGovernor(Governor):
    """A two-ball bell-crank governor on the seam, per ball (section 3.5). Subclasses set the
    ``spring`` kind and supply the design spring's length (:meth:`spring_length_at`) and any
    fixed springs (:meth:`fixed_force`)."""

    coordinate: ClassVar[str] = "length"
    source: ClassVar[str] = "textbook-ch3"
    friction_key: ClassVar[str] = "governor.sleeve_friction"
    coordinate_name: ClassVar[str] = "ball radius"
    travel: ClassVar[str] = "length"
    mass_key: ClassVar[str] = "ball"
    free_length_key: ClassVar[str] = "free_length"
    key_alternatives: ClassVar[tuple] = (((RADIUS_OUTER.name,), (SLEEVE_LIFT.name,)),)
    central_load: ClassVar[bool] = True
    central_load_affine: ClassVar[bool] = True  # cf, cf_x and I affine in W; ci = 0 (terms)
    #: True where the fulcrum rides on the sleeve and the ball hangs below it (Fig. 3.12)
    fulcrum_on_sleeve: ClassVar[bool] = False
    #: the balls hang below a fixed fulcrum (a Hartnell drawn upside down): the sleeve then
    #: falls as the balls fly out, so the balls' and the sleeve's weights change sign
    ball_below: bool = False
    #: the spec key of the lever's second arm
    arm_key: ClassVar[str] = "sleeve_arm"
    #: the default fulcrum radius: the ball arm vertical at radius "normal" or "inner"
    fulcrum_at: ClassVar[str] = "normal"
    #: the keys every bell-crank type reads first (:func:`common_keys`, :meth:`read_common`)
    common: ClassVar[tuple[Key, ...]] = ()

    def __init__(self, crank: BellCrank, x_inner, x_outer, x_normal, sleeve_friction=0.0,
                 spring_length=0.0):
        self.crank = crank
        self.x_inner, self.x_outer, self.x_normal = x_inner, x_outer, x_normal
        self.sleeve_friction, self.spring_length = sleeve_friction, spring_length
        self._s_inner = float(crank.state(x_inner)["s"])

    def __repr__(self):
        return (f"{type(self).__name__}({self.crank}, x=({self.x_inner}, {self.x_normal}, "
                f"{self.x_outer}), R={self.sleeve_friction}, L={self.spring_length})")

    # -- parsing ------------------------------------------------------------------------------

    @classmethod
    def read_common(cls, reader) -> dict:
        """The keys of :func:`common_keys`: ``ball_arm``, the second arm (:attr:`arm_key`),
        ``radius_inner``, ``radius_outer`` or ``sleeve_lift``, ``crank_angle`` (default 90
        deg), ``obliquity``, ``radius_normal`` (default the mid radius), ``fulcrum_radius``
        (default: the ball arm vertical at :attr:`fulcrum_at`) and ``sleeve_friction``
        (default 0)."""
        keys = cls.common
        v = reader.read_all(keys[:3])
        a, b, inner = v["ball_arm"], v[cls.arm_key], v["radius_inner"]
        if reader.has("radius_outer") and reader.has("sleeve_lift"):
            reader.fail("sleeve_lift", "give either radius_outer or sleeve_lift, not both")
        lift = reader.read(SLEEVE_LIFT, v) if reader.has("sleeve_lift") else None
        outer = reader.read(RADIUS_OUTER, v, required=lift is None)
        gamma, obliquity = reader.read_all((CRANK_ANGLE, OBLIQUITY), v).values()
        if obliquity == "small_angle" and abs(gamma - RIGHT_ANGLE) > 1e-12:
            reader.fail("obliquity", "the book's small-angle simplification assumes a 90 deg "
                                     "crank (give crank_angle = \"90 deg\" or obliquity = "
                                     "\"exact\")")
        placed = keys[7:9]  # radius_normal and fulcrum_radius: defaults from the range
        given = {k.name: reader.read(k, v) for k in placed if reader.has(k.name)}
        if lift is not None:
            v["radius_outer"] = outer = cls._outer_for_lift(reader, v, given, lift)
        elif not inner < outer:
            reader.fail("radius_outer", "expected radius_inner < radius_outer")
        normal, r_f = (given[k.name] if k.name in given else reader.read(k, v)
                       for k in placed)
        if not inner <= normal <= outer:
            reader.fail("radius_normal", "expected radius_inner <= radius_normal <= radius_outer")
        crank = BellCrank(a, b, r_f, gamma, obliquity)
        why = crank.reach_error([inner, outer], cls.arm_key)
        if why:
            reader.fail("radius_outer" if crank.reach_error([inner]) == "" else "radius_inner",
                        f"radii {inner * 100:g} cm to {outer * 100:g} cm: {why}")
        friction = reader.read(SLEEVE_FRICTION)
        return dict(crank=crank, x_inner=inner, x_outer=outer, x_normal=normal,
                    sleeve_friction=friction)

    @classmethod
    def _outer_for_lift(cls, reader, v: dict, given: dict, lift: float) -> float:
        """The outer ball radius (m) at which the sleeve has risen ``lift`` (m) from
        radius_inner, the fulcrum where ``given`` puts it or by default
        (:func:`common_keys`): by bisection on the lift, which rises with the radius while
        the sleeve arm turns towards the sleeve (the closed form ``r_i + (a/b) lift`` for a
        90 deg crank; the bisection ends on it to the last bits)."""
        a, b, inner = v["ball_arm"], v[cls.arm_key], v["radius_inner"]
        gamma, obliquity = v["crank_angle"], v["obliquity"]

        def rise(outer):
            normal = given.get("radius_normal", 0.5 * (inner + outer))
            r_f = given.get("fulcrum_radius", normal if cls.fulcrum_at == "normal" else inner)
            crank = BellCrank(a, b, r_f, gamma, obliquity)
            if crank.reach_error([inner, outer], cls.arm_key):
                return math.nan
            return float(crank.state(outer)["s"] - crank.state(inner)["s"])

        lo, hi = inner, inner + 2.0 * a  # the ball arm reaches at most 2a across its fulcrum
        if math.isnan(rise(hi)):  # the end of the levers' reach (rise is NaN beyond it)
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if mid in (lo, hi):
                    break
                lo, hi = (lo, mid) if math.isnan(rise(mid)) else (mid, hi)
            hi = lo
        if not rise(hi) >= lift:
            reader.fail("sleeve_lift", f"the levers cannot lift the sleeve {lift * 1e3:g} mm "
                                       f"from radius_inner (ball arm {a * 100:g} cm, "
                                       f"{cls.arm_key.replace('_', ' ')} {b * 100:g} cm)")
        lo = inner
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            lo, hi = (mid, hi) if rise(mid) < lift else (lo, mid)
        return hi

    def check_spring_length(self, reader):
        """A compression spring on the sleeve must keep a positive length over the range."""
        if self.spring == "compression" and self.spring_length <= self.sleeve_lift(self.x_outer):
            reader.fail("spring_length", f"the sleeve lifts {self.sleeve_lift(self.x_outer):.4g} "
                                         "m over the range: the spring would close up")

    # -- geometry ------------------------------------------------------------------------------

    def geometry(self, x) -> dict:
        """At ball radii ``x`` (m, also returned as ``r``): the sleeve lift ``s`` (m, from the
        innermost configuration) and the ball's height ``y`` (m, up to a constant), with their
        x-derivatives (suffixes 1, 2); ``theta`` the ball arm's inclination."""
        st = self.crank.state(x)
        s, s1, s2 = st["s"] - self._s_inner, st["s1"], st["s2"]
        if self.fulcrum_on_sleeve:  # the ball hangs a cos(theta) below O, which rises by s
            y, y1, y2 = s - st["z"], s1 - st["z1"], s2 - st["z2"]
        else:
            y, y1, y2 = st["z"], st["z1"], st["z2"]
        return dict(r=np.asarray(x, dtype=float), s=s, s1=s1, s2=s2, y=y, y1=y1, y2=y2,
                    theta=st["theta"])

    def sleeve_lift(self, x):
        """Rise of the sleeve from the innermost configuration (m) at ball radius ``x`` (m); its
        fall where the balls hang below the fulcrum (:attr:`ball_below`)."""
        return self.geometry(x)["s"]

    def height(self, x):
        """Height of the ball's centre above the bell crank's fulcrum (m; negative below it:
        Fig. 3.12) at ball radius ``x`` (m). The book uses no governor height here."""
        z = self.crank.state(x)["z"]
        return -z if self.fulcrum_on_sleeve else z

    def columns(self, x) -> dict:
        """Sleeve lift, the ball arm's inclination and the ball's height over ``x``."""
        return {"sleeve lift": (self.sleeve_lift(x), "m"),
                "ball arm angle": (self.crank.angle(x), "rad"),
                "ball height": (self.height(x), "m")}

    coordinate_key: ClassVar[str] = "radius"

    def coordinates(self) -> tuple[Coordinate, ...]:
        """The ball's radius, the ball arm's inclination to the vertical and the sleeve's lift
        from the innermost configuration (section 3.5, eq. vi)."""
        return super().coordinates() + (
            Coordinate("angle", "angle", "the ball arm's inclination theta to the vertical "
                                         "(textbook 3.5, Fig. 3.10)", self.crank.angle),
            Coordinate("lift", "length", "the sleeve's lift from its innermost position "
                                         "(textbook 3.5(a), eq. vi)", self.sleeve_lift))

    def x_domain(self) -> tuple[float, float]:
        """The ball radii the ball arm reaches about its fulcrum, ``r_f +- a``."""
        cr = self.crank
        return cr.fulcrum_radius - cr.ball_arm, cr.fulcrum_radius + cr.ball_arm

    # -- springs (subclasses) -----------------------------------------------------------------

    def spring_length_at(self, geo) -> tuple:
        """``(L, L1, L2, count)``: the design spring's length (m) and its x-derivatives at the
        geometry ``geo`` (:meth:`geometry`), and how many act in parallel. Default: one
        compression spring on the sleeve, ``L = spring_length - s``."""
        return self.spring_length - geo["s"], -geo["s1"], -geo["s2"], 1

    def fixed_force(self, x, geo) -> tuple:
        """``(cf, cf_x)`` of springs given in the governor table (N, N/m per ball); none."""
        return 0.0 * geo["s"], 0.0 * geo["s"]

    # -- the seam -----------------------------------------------------------------------------

    def terms(self, x, m, analysis=None, central=None) -> Terms:
        """Per ball, by virtual work: ``jp = m r``; ``cf = g (m dy/dr + (W/2) ds/dr)`` plus fixed
        springs; the design spring by :func:`spring_terms`; ``ci = 0``. ``central``: the sleeve's
        mass (kg; None: none)."""
        x = np.asarray(x, dtype=float)
        geo = self.geometry(x)
        half = 0.0 if central is None else 0.5 * central
        fixed, fixed_x = self.fixed_force(x, geo)
        g = -G_STANDARD if self.ball_below else G_STANDARD  # upside down: gravity reversed
        cf = g * (m * geo["y1"] + half * geo["s1"]) + fixed
        cf_x = g * (m * geo["y2"] + half * geo["s2"]) + fixed_x
        A, B, A_x, B_x = spring_terms(*self.spring_length_at(geo))
        zero = 0.0 * x
        return Terms(jp=m * x, jpp=m + zero, cf=cf, cf_x=cf_x, ci=zero, ci_x=zero,
                     A=A + zero, B=B + zero, A_x=A_x + zero, B_x=B_x + zero)

    def inertia(self, x, m, central=None):
        """``I = m (1 + (dy/dr)^2) + (M/2) (ds/dr)^2`` (kg, per ball): the ball's kinetic energy in
        the meridian plane (it rises or falls as the arm tilts) and the sleeve's share; the
        levers' masses neglected as in the book."""
        geo = self.geometry(x)
        half = 0.0 if central is None else 0.5 * central
        return m * (1.0 + geo["y1"] ** 2) + half * geo["s1"] ** 2

    def travel_slope(self, x):
        """``ds/dr``: sleeve lift per unit ball radius (the sleeve is the regulating member)."""
        return self.geometry(x)["s1"]

    def friction(self, x, design=None):
        """Sleeve friction ``R`` as a band per ball, ``R/2 |ds/dr|`` (N) (section 3.5(a): added
        to the spring force rising, subtracted falling)."""
        return 0.5 * self.sleeve_friction * np.abs(self.travel_slope(x))

    def spring_force_coefficients(self, x):
        """Force in one design spring, ``F = kappa (A_F - B_F l0)``: ``(L, 1)`` in tension,
        ``(-L, -1)`` in compression."""
        L = self.spring_length_at(self.geometry(x))[0]
        sign = 1.0 if self.spring == "tension" else -1.0
        return sign * L, sign + 0.0 * L

    # -- the type's method and drawing: what a reader is told (textbook 3.5) ------------------

    def friction_method(self, spec) -> tuple[Equation, ...]:
        """Friction at the sleeve (sections 3.4(b), 3.5(a)), where the governor has it."""
        if not self.sleeve_friction:
            return ()
        return (Equation("friction", "friction at the sleeve: a force R opposing its motion, "
                         "added to the spring force rising and taken off it falling",
                         "omega_rise,fall^2 m r = F(r) +- (R/2) ds/dr", "textbook-ch3",
                         "3.4(b), 3.5(a)", name="band"),) + self.friction_strokes(spec)

    def settings(self, spec) -> list[Setting]:
        """The seam's settings and the book's small-angle simplification."""
        return [Setting("governor.obliquity", self.crank.obliquity, "the levers' obliquity: "
                        "exact, or the book's small-angle simplification (arms at right "
                        "angles to the forces, 90 deg crank)")] + super().settings(spec)

    def lift_equation(self) -> Equation:
        """The sleeve's lift and the balls' radius (section 3.5(a) eq. vi)."""
        return Equation("statics", "the sleeve's lift over the ball's travel",
                        "s = b cos(gamma - theta) - (the same at r_inner); ds/dr = b sin(gamma "
                        "- theta) / (a cos(theta)), b/a for a 90 deg crank", "textbook-ch3",
                        "3.5(a) eq. (vi)", ("governor.obliquity",))

    def drawing(self, x, sd) -> Drawing:
        """Both halves in the meridian plane, from the lever the statics use: the fulcrum at
        ``fulcrum_radius``, the ball arm ``a`` at ``theta`` to the vertical (up from a fixed
        fulcrum; down from one riding on the sleeve, Fig. 3.12), the sleeve (roller) arm ``b``
        at the crank angle to it, the collar or sleeve at the roller's height, and the design
        spring at its length ``L(x)``: on the spindle over the sleeve (Hartnell, spring and
        gravity) or between the balls (balls connected by springs)."""
        cr, x = self.crank, float(x)
        a, b, gamma, rf = cr.ball_arm, cr.sleeve_arm, cr.crank_angle, cr.fulcrum_radius
        st = cr.state(x)
        th = float(st["theta"])
        lift = float(self.sleeve_lift(x))
        if self.fulcrum_on_sleeve:  # O rides on the sleeve, the roller held by the cap
            F = (rf, b * np.cos(gamma - th))
            ball = (rf + a * np.sin(th), F[1] - a * np.cos(th))
            roller = (rf - b * np.sin(gamma - th), 0.0)
            collar = F[1]
        else:
            F = (rf, 0.0)
            ball = (rf + a * np.sin(th), a * np.cos(th))
            roller = (rf - b * np.sin(gamma - th), b * np.cos(gamma - th))
            collar = roller[1]
        half, tall = max(abs(roller[0]), 0.1 * a) if not self.fulcrum_on_sleeve else rf, 0.08 * a
        parts = [Part("link", (ball, F, roller)), Part("pivot", (F,)),
                 Part("mass", (ball,), ball_radius(sd.m))]
        parts = list(mirrored(parts))
        parts.append(Part("sleeve", ((-half, collar - tall), (half, collar - tall),
                                     (half, collar), (-half, collar), (-half, collar - tall))))
        L, _, _, count = self.spring_length_at(self.geometry(x))
        L = float(L)
        width = 2.0 * sd.r if np.isfinite(sd.r) else 0.5 * half
        top = collar + L  # on the spindle over the collar (Hartnell, spring and gravity)
        if self.spring_between_balls():
            parts.append(Part("spring", zigzag((-ball[0], ball[1]), (ball[0], ball[1]),
                                               width)))
            top = collar
        else:
            parts.append(Part("spring", zigzag((0.0, collar), (0.0, top), width)))
        if self.fulcrum_on_sleeve:  # the cap: its rim over the rollers, its top on the spring
            cap = collar - lift + float(self.spring_length)
            parts.append(Part("frame", ((-abs(roller[0]), 0.0), (-abs(roller[0]), cap),
                                        (abs(roller[0]), cap), (abs(roller[0]), 0.0))))
        elif not self.spring_between_balls():  # the stop the spring bears on
            stop = collar - lift + float(self.spring_length)
            parts.append(Part("frame", ((-width, stop), (width, stop))))
        low = min(collar - tall, ball[1]) - 0.2 * a
        parts.append(Part("frame", ((0.0, max(top, ball[1]) + 0.15 * a), (0.0, low))))
        if self.ball_below:  # the same mechanism upside down
            parts = [Part(p.kind, tuple((u, -v) for u, v in p.points), p.size) for p in parts]
        return Drawing(tuple(parts))

    def spring_between_balls(self) -> bool:
        """Whether the design spring joins the balls (drawn between them); default not."""
        return False
