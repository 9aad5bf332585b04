"""The Porter governor (textbook ch. 3, section 3.4(b), Figs. 3.1(b), 3.4-3.7), and the linkage it
shares with the Watt (section 3.4(a)) and the Proell (section 3.4(c)) governors.

Each ball hangs from an upper arm ``a`` pivoted at ``pivot_offset`` from the spindle's axis; a
lower (suspension) link ``b`` joins the arm's end B to a pin on the sleeve at ``sleeve_offset``
from the axis. In a Porter the ball sits at B; in a Proell it sits at G on a rigid extension
``c = BG`` of the lower link (:mod:`govopt.governors.proell`). The sleeve carries the central load
``W`` and, where fitted, an auxiliary spring through a lever (Example 2, Fig. 3.7).

The coordinate is the ball's radius of rotation ``x = r`` (m) and every generalised force is *per
ball* (each ball carries half the central load and half the lever's spring force), so
``J = m r^2``, ``jp = m r``, ``jpp = m`` and the equilibrium ``omega^2 m r = Q(r)`` makes the
restoring generalised force ``Q`` the textbook's *controlling force* (section 3.3).

Statics by virtual work (exact geometry, derivatives in closed form). With the pivot at height 0,
``y`` upward, ``sin(alpha) = (r_B - e_u)/a`` and ``sin(beta) = (r_B - e_s)/b`` (the inclinations
of the arm and the link to the vertical, Fig. 3.4)::

    y_B = -a cos(alpha)                         dy_B/dr_B = tan(alpha)
    y_C = y_B - b cos(beta)   (sleeve pin)      dy_C/dr_B = tan(alpha) + tan(beta)
    Q   = m g dy_G/dr + (W/2) ds/dr,            s = y_C - y_C(r_inner) the sleeve lift.

For the Porter (``G = B``) this is the book's instantaneous-centre result
``F = [W/2 (1 + k) + w] tan(alpha)``, ``k = tan(beta)/tan(alpha)`` (section 3.4(b), eq. i), here
derived without the instantaneous centre and with ``k`` varying with the configuration. The book's
``k = 1`` shortcut (exact for equal arms and links hinged at equal offsets, otherwise an
approximation) is the fidelity ``k = "unity"``: the sleeve taken to rise twice as fast as the
ball, ``ds/dr = 2 tan(alpha)``.

Friction at the sleeve (section 3.4(b), "Friction at the sleeve"): a force ``R`` opposing the
sleeve's motion adds ``+-R`` to the central load, i.e. the band ``R/2 |ds/dr|`` per ball.

Neglected, as the book does: the masses of the arms and links (the generalised inertia is the
balls' and the sleeve's, :meth:`BallGovernor.inertia`) and the spindle's own friction.

Classic measures: the book's ``k`` (:meth:`BallGovernor.k_ratio`) and height ``h = r/tan(alpha)``
(:meth:`BallGovernor.height`), beyond the generic equilibrium speed, range, sensitiveness,
stability, effort, power and friction band.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..keys import Key
from ..units import G_STANDARD
from .base import Coordinate, Equation, Governor, Setting, Terms, solve_monotone
from .drawing import Drawing, Part, ball_radius, mirrored, zigzag

K_MODES = ("exact", "unity")
SPRING_KINDS = ("tension", "compression")

#: the linkage's keys shared by the Porter and the Proell (the Watt's suspension differs)
ARM = Key("arm", "length", "the upper arm a, from its pivot to the joint B with the lower link",
          source="textbook Fig. 3.4", example="30 cm")
LINK = Key("link", "length", "the lower (suspension) link b, from the joint B to the sleeve "
                             "pin C", default=lambda v: v["arm"], default_text="arm",
           source="textbook Fig. 3.4")
PIVOT_OFFSET = Key("pivot_offset", "length", "the upper arm's pivot's distance from the "
                                             "spindle's axis", default=0.0, nonnegative=True,
                   source="textbook Figs. 3.4-3.5")
SLEEVE_OFFSET = Key("sleeve_offset", "length", "the sleeve pin's distance from the spindle's "
                                               "axis", default=0.0, nonnegative=True,
                    source="textbook Figs. 3.4-3.5")
K = Key("k", "choice", "the book's k = tan(beta)/tan(alpha): \"exact\" (the linkage's own, "
                       "varying with the configuration) or \"unity\" (the book's k = 1 "
                       "shortcut: the sleeve rises twice as fast as the ball)",
        default="exact", choices=K_MODES, source="textbook 3.4(b), eq. i")
#: the ball radius range (the coordinate) of the ball governors
RANGE = (
    Key("radius_inner", "length", "the balls' radius of rotation at the innermost configuration "
                                  "(sleeve down, lowest speed)", example="20 cm"),
    Key("radius_outer", "length", "the balls' radius of rotation at the outermost configuration "
                                  "(sleeve up, highest speed)", example="25 cm"),
    Key("radius_normal", "length", "the balls' radius at the normal configuration (the load "
                                   "changes' and dynamics' reference), within the range",
        default=lambda v: 0.5 * (v["radius_inner"] + v["radius_outer"]),
        default_text="the mid radius, (radius_inner + radius_outer) / 2"),
)
#: the coordinates a ball governor's configuration may be given by besides the ball's radius
#: (the textbook's problems give each), each a function of the joint radius p = r_B alone, so a
#: Proell's extension does not move them: name -> (dimension, meaning, the figure it is)
BY = {"angle": ("angle", "the upper arm's angle alpha to the spindle's axis", "Fig. 3.4"),
      "height": ("length", "the height h = r_B / tan(alpha): the joint B's depth below the point "
                           "where the upper arm (produced) meets the axis", "Fig. 3.3"),
      "joint_radius": ("length", "the radius r_B of the joint B of the upper arm and the lower "
                                 "link", "Fig. 3.4"),
      "lift": ("length", "the sleeve's lift above its innermost position", "Fig. 3.4")}
ENDS = ("inner", "outer", "normal")
#: the range by another coordinate: ``angle_inner``, ``height_outer``, ``lift_outer`` ...
#: (a lift is counted from the inner end, so it gives the outer and normal ones only)
RANGE_BY = tuple(
    Key(f"{name}_{end}", dim, f"{meaning}, at the {end} configuration: gives radius_{end}",
        default=None, default_text=f"none (radius_{end} gives it)",
        **({"high": math.pi / 2, "range_text": "(0 deg, 90 deg)"} if dim == "angle" else {}),
        source=f"textbook {fig}")
    for name, (dim, meaning, fig) in BY.items() for end in ENDS
    if not (name == "lift" and end == "inner"))
#: the radius range of the ball governors (Watt, Porter, Proell): each end by the ball's radius
#: or one of :data:`BY`
BALL_RANGE = tuple(Key(k.name, k.kind, k.meaning, default=None,
                       default_text=(f"from {k.name.replace('radius', 'angle')}, "
                                     f"{k.name.replace('radius', 'height')}, "
                                     f"{k.name.replace('radius', 'joint_radius')}"
                                     + (f" or {k.name.replace('radius', 'lift')}"
                                        if k.name != "radius_inner" else "")
                                     + ("; else the mid radius" if k.name == "radius_normal"
                                        else "")),
                       example=k.example) for k in RANGE) + RANGE_BY
SLEEVE_FRICTION = Key("sleeve_friction", "force", "the friction force R at the sleeve: the "
                                                  "central load is W + R rising, W - R falling",
                      default=0.0, nonnegative=True,
                      source="textbook 3.4(b), Friction at the sleeve")
#: the Porter's auxiliary spring on the sleeve through a lever (Example 2, Fig. 3.7)
WITH_SPRING = "with spring = \"tension\" or \"compression\""
SPRING_KEYS = (
    Key("spring", "choice", "an auxiliary spring acting on the sleeve through a lever, in "
                            "tension or compression (textbook Example 2, Fig. 3.7); none: a "
                            "dead-weight governor", default=None, default_text="none",
        choices=SPRING_KINDS),
    Key("spring_arm", "length", "the lever's arm from its pivot to the spring", when=WITH_SPRING,
        source="textbook Fig. 3.7"),
    Key("sleeve_arm", "length", "the lever's arm from its pivot to the sleeve", when=WITH_SPRING,
        source="textbook Fig. 3.7"),
    Key("spring_length", "length", "the auxiliary spring's length at the innermost "
                                   "configuration (radius_inner); its free length is designed",
        when=WITH_SPRING),
)


@dataclass(frozen=True)
class Linkage:
    """Upper arm, lower link and (Proell) the ball's extension of the lower link, SI.

    ``arm`` a = pivot to joint B; ``link`` b = B to the sleeve pin C; ``pivot_offset`` e_u and
    ``sleeve_offset`` e_s their distances from the axis (e_u < 0: the pivot is across the axis, the
    arm crossing the spindle, Fig. 3.3(c)); ``extension`` c = BG, the ball on the lower link
    produced beyond B, turned through ``crank`` (rad, towards the axis) from the line CB
    (``c = 0``: the ball at B); ``k``: ``"exact"`` or ``"unity"`` (the book's k = 1).
    """

    arm: float
    link: float
    pivot_offset: float = 0.0
    sleeve_offset: float = 0.0
    extension: float = 0.0
    crank: float = 0.0
    k: str = "exact"

    def _at_joint(self, p):
        """Geometry at the joint radius ``p = r_B`` (m) and its p-derivatives (suffixes 1, 2):
        ball radius ``r`` and height ``y``, sleeve height ``z``."""
        a, b, c = self.arm, self.link, self.extension
        sa = (p - self.pivot_offset) / a
        sb = (p - self.sleeve_offset) / b
        ca, cb = np.sqrt(1.0 - sa**2), np.sqrt(1.0 - sb**2)
        ta, tb = sa / ca, sb / cb
        ya2 = 1.0 / (a * ca**3)  # d(tan alpha)/dp
        b1 = 1.0 / (b * cb)  # d(beta)/dp
        b2 = sb / (b**2 * cb**3)
        th = np.arcsin(sb) - self.crank  # the extension's inclination to the vertical
        st, ct = np.sin(th), np.cos(th)
        geo = dict(
            r=p + c * st, r1=1.0 + c * ct * b1, r2=c * (ct * b2 - st * b1**2),
            y=-a * ca + c * ct, y1=ta - c * st * b1, y2=ya2 - c * (ct * b1**2 + st * b2),
            ta=ta, tb=tb)
        if self.k == "exact":
            geo.update(z=-a * ca - b * cb, z1=ta + tb, z2=ya2 + 1.0 / (b * cb**3))
        else:  # the book's k = 1: the sleeve moves twice as far as the joint B
            geo.update(z=-2.0 * a * ca, z1=2.0 * ta, z2=2.0 * ya2)
        return geo

    def joint_radius(self, x, tol=1e-14):
        """The joint radius ``r_B`` giving the ball radius ``x`` (m): ``x`` itself when the ball
        is at B, else Newton's method on ``r_B + c sin(beta - crank) = x`` (monotone over the
        validated range); NaN where it does not converge."""
        x = np.asarray(x, dtype=float)
        if self.extension == 0.0:
            return x
        lo = max(self.pivot_offset, self.sleeve_offset - self.link)
        hi = min(self.pivot_offset + self.arm, self.sleeve_offset + self.link)
        eps = 1e-12 * (hi - lo)
        p = np.clip(x, lo + eps, hi - eps)
        with np.errstate(invalid="ignore"):
            for _ in range(60):
                g = self._at_joint(p)
                step = (g["r"] - x) / g["r1"]
                p = np.clip(p - step, lo + eps, hi - eps)
                if np.all(np.abs(step) <= tol * self.arm):
                    break
            g = self._at_joint(p)
        ok = (np.abs(g["r"] - x) <= 1e3 * tol * self.arm) & (g["r1"] > 0)
        return np.where(ok, p, np.nan)

    def state(self, x):
        """Geometry at ball radii ``x`` (m) with first and second x-derivatives (suffixes 1, 2)
        of the ball's height ``y`` and the sleeve pin's height ``z`` (m), by the chain rule
        through ``r_B``; also ``p = r_B`` and ``tan(alpha)``, ``tan(beta)``.

        Example 1 (section 3.4(b)) at r = 25 cm: ``k = tan(beta)/tan(alpha)`` and the sleeve's
        rise per unit ball radius ``tan(alpha) + tan(beta) = (1 + k) tan(alpha)``:

        >>> st = Linkage(arm=0.30, link=0.30, sleeve_offset=0.0376).state(0.25)
        >>> round(float(st["tb"] / st["ta"]), 3), round(float(st["z1"]), 4)
        (0.665, 2.5101)
        """
        p = self.joint_radius(x)
        g = self._at_joint(p)
        r1, r2 = g["r1"], g["r2"]
        out = dict(p=p, ta=g["ta"], tb=g["tb"], y=g["y"], z=g["z"])
        for f in ("y", "z"):
            f1, f2 = g[f + "1"], g[f + "2"]
            out[f + "1"] = f1 / r1
            out[f + "2"] = (f2 * r1 - f1 * r2) / r1**3
        return out

    def joint_domain(self) -> tuple[float, float]:
        """The joint radii ``r_B`` (m) the arm and the link can take: the arm inclined outward
        and both short of horizontal."""
        lo = max(self.pivot_offset, self.sleeve_offset - self.link)
        hi = min(self.pivot_offset + self.arm, self.sleeve_offset + self.link)
        return lo, hi

    def by_joint(self, name: str, p):
        """The coordinate ``name`` of :data:`BY` at joint radii ``p`` (m), SI: the arm's angle
        ``alpha = asin((r_B - e_u)/a)``, the height ``r_B / tan(alpha)``, ``r_B`` itself, the
        sleeve pin's height (a lift is its rise from a reference).

        Example 1's Porter (arms of 30 cm on the axis) at r_B = 25 cm: by hand alpha =
        asin(25/30) = 56.44 deg and h = sqrt(30^2 - 25^2) = 16.58 cm:

        >>> lk = Linkage(arm=0.30, link=0.30, sleeve_offset=0.0376)
        >>> round(float(np.degrees(lk.by_joint("angle", 0.25))), 2), round(float(
        ...     lk.by_joint("height", 0.25)), 4)
        (56.44, 0.1658)
        """
        p = np.asarray(p, dtype=float)
        with np.errstate(invalid="ignore", divide="ignore"):
            sa = (p - self.pivot_offset) / self.arm
            if name == "angle":
                return np.arcsin(sa)
            if name == "height":
                return p * np.sqrt(1.0 - sa**2) / sa
            if name == "joint_radius":
                return p
            return self._at_joint(p)["z"]

    def joint_for(self, name: str, value: float, lift_from: float = np.nan) -> float:
        """The joint radius ``r_B`` (m) where the coordinate ``name`` of :data:`BY` is
        ``value`` (SI; a lift counted from the joint radius ``lift_from``): the root of
        :meth:`by_joint` over :meth:`joint_domain`; NaN where the linkage cannot take it."""
        lo, hi = self.joint_domain()
        base = 0.0 if name != "lift" else float(self.by_joint("lift", lift_from))
        return solve_monotone(lambda p: self.by_joint(name, p) - base, value, lo, hi)

    def reach_error(self, xs):
        """Why the ball radii ``xs`` (m) cannot be reached, or ``""``."""
        xs = np.asarray(xs, dtype=float)
        p = self.joint_radius(xs)
        if np.any(~np.isfinite(p)):
            return "the linkage cannot place the ball there"
        sa = (p - self.pivot_offset) / self.arm
        sb = (p - self.sleeve_offset) / self.link
        if np.any(sa <= 0) or np.any(sa >= 1):
            return (f"the arm ({self.arm * 100:g} cm) must be inclined outward, short of "
                    "horizontal, over the whole range")
        if np.any(np.abs(sb) >= 1):
            return f"the link ({self.link * 100:g} cm) cannot reach the sleeve pin"
        if np.any(self._at_joint(p)["r1"] <= 0):
            return "the ball does not move outward as the arms open"
        return ""


class BallGovernor(Governor):
    """A gravity-loaded ball governor on a :class:`Linkage`, per ball, with an optional auxiliary
    spring on the sleeve through a lever (Example 2, Fig. 3.7). Shared by Watt, Porter and Proell.

    The spring (the design spring when fitted) acts on the sleeve through a lever pivoted at one
    end: at ``spring_arm`` from the pivot, the sleeve at ``sleeve_arm``, so the spring's length
    changes by ``lever_ratio = spring_arm / sleeve_arm`` times the sleeve lift (lengthening a
    tension spring, shortening a compression spring) and its force ``P`` loads the sleeve with
    ``lever_ratio P``. ``spring_length`` is its length at the innermost configuration and ``l0``
    its free length: ``P = kappa (L - l0)`` (tension), ``kappa (l0 - L)`` (compression).
    """

    coordinate: ClassVar[str] = "length"
    source: ClassVar[str] = "textbook-ch3"
    friction_key: ClassVar[str] = "governor.sleeve_friction"
    range_keys: ClassVar[tuple[str, str] | None] = ("governor.radius_inner",
                                                    "governor.radius_outer")
    #: each end of the range given once: by the ball's radius or by one other coordinate of
    #: :data:`BY` (``radius_inner`` or ``angle_inner`` ...; a lift gives the outer end only)
    key_alternatives: ClassVar[tuple] = tuple(
        tuple((f"{name}_{end}",) for name in ("radius", *BY)
              if not (name == "lift" and end == "inner"))
        for end in ENDS[:2])
    coordinate_name: ClassVar[str] = "ball radius"
    travel: ClassVar[str] = "length"
    mass_key: ClassVar[str] = "ball"
    free_length_key: ClassVar[str] = "free_length"
    central_load: ClassVar[bool] = True
    central_load_affine: ClassVar[bool] = True  # cf, cf_x and I affine in W; ci = 0 (terms)

    def __init__(self, linkage: Linkage, x_inner, x_outer, x_normal, sleeve_friction=0.0,
                 spring=None, lever_ratio=0.0, spring_length=0.0):
        self.linkage = linkage
        self.x_inner, self.x_outer, self.x_normal = x_inner, x_outer, x_normal
        self.sleeve_friction = sleeve_friction
        self.spring = spring  # this instance's spring (the class attribute's default is None)
        self.lever_ratio, self.spring_length = lever_ratio, spring_length
        self._z_inner = float(linkage.state(x_inner)["z"])

    def __repr__(self):
        return (f"{type(self).__name__}({self.linkage}, x=({self.x_inner}, {self.x_normal}, "
                f"{self.x_outer}), R={self.sleeve_friction}, spring={self.spring})")

    # -- parsing shared by the ball governors -------------------------------------------------

    @staticmethod
    def _read_range(reader, linkage, to_radius="linkage"):
        """``radius_inner``, ``radius_outer``, ``radius_normal`` (default the mid radius), each
        end by the ball's radius or by one of :data:`BY` (``angle_inner``, ``lift_outer`` ...:
        :data:`RANGE_BY`), converted through the joint radius ``r_B``: ``to_radius`` gives the
        ball's radius at a joint radius (``"linkage"``: the linkage's own; None where it is not
        known yet, a Proell's before its extension's angle: then ``(radii, joints)``, the ends
        given by their radius and by their joint radius, are returned instead)."""
        radii = {end: reader.read(key, required=False)
                 for key, end in zip(BALL_RANGE[:3], ENDS, strict=True)}
        joints = {}
        for key in RANGE_BY:
            name, end = key.name.rsplit("_", 1)
            value = reader.read(key)
            if value is None:
                continue
            if radii[end] is not None or end in joints:
                reader.fail(key.name, f"the {end} configuration is given twice: give one of "
                                      f"radius_{end} and the {end} keys of another coordinate")
            ref = joints.get("inner", np.nan)
            if name == "lift" and radii["inner"] is not None:
                if to_radius is None:
                    reader.fail(key.name, "a lift needs the inner configuration by the arm's "
                                          "angle, the height or the joint radius here")
                ref = float(linkage.joint_radius(radii["inner"]))
            p = linkage.joint_for(name, value, ref)
            if not np.isfinite(p):
                reader.fail(key.name, "the arm and the link cannot take this configuration"
                            + (" (a lift counts from the inner configuration)"
                               if name == "lift" else ""))
            joints[end] = p
        for key, end in zip(BALL_RANGE[:2], ENDS[:2], strict=True):
            if radii[end] is None and end not in joints:
                reader.read(key, required=True)  # the "missing" error
        if to_radius is None and joints:
            return radii, joints
        if not callable(to_radius):
            to_radius = lambda p: float(linkage._at_joint(p)["r"])  # noqa: E731
        inner, outer, normal = (to_radius(joints[end]) if end in joints else radii[end]
                                for end in ENDS)
        return BallGovernor._ordered(reader, inner, outer, normal)

    @staticmethod
    def _ordered(reader, inner, outer, normal):
        """The range's ends in order, the normal one by default the mid radius."""
        if normal is None:
            normal = 0.5 * (inner + outer)
        if not inner < outer:
            reader.fail("radius_outer", "expected radius_inner < radius_outer")
        if not inner <= normal <= outer:
            reader.fail("radius_normal", "expected radius_inner <= radius_normal <= radius_outer")
        return inner, outer, normal

    @staticmethod
    def _check_reach(reader, linkage, inner, outer):
        why = linkage.reach_error(np.linspace(inner, outer, 201))
        if why:
            reader.fail("radius_outer" if linkage.reach_error([inner]) == "" else "radius_inner",
                        f"radii {inner * 100:g} cm to {outer * 100:g} cm: {why}")

    @staticmethod
    def _read_spring(reader):
        """``spring`` ("tension" | "compression"), ``spring_arm``, ``sleeve_arm``,
        ``spring_length``; none of them: no auxiliary spring (a dead-weight governor)."""
        kind = reader.read(SPRING_KEYS[0])
        if kind is None:
            for key in SPRING_KEYS[1:]:
                if reader.has(key.name):
                    reader.fail(key.name, f"given without {WITH_SPRING[5:]}")
            return dict(spring=None)
        spring_arm, sleeve_arm, length = reader.read_all(SPRING_KEYS[1:]).values()
        return dict(spring=kind, lever_ratio=spring_arm / sleeve_arm, spring_length=length)

    # -- geometry for reports -----------------------------------------------------------------

    def sleeve_lift(self, x):
        """Rise of the sleeve from the innermost configuration, m, at ball radius ``x`` (m)."""
        return self.linkage.state(x)["z"] - self._z_inner

    def height(self, x):
        """The governor's height ``h = r_B / tan(alpha)`` (m): the joint B's depth below the point
        where the upper arm (produced) meets the axis (section 3.4(a), Fig. 3.3; for the Watt
        and the Porter ``r_B = r``, so ``tan(alpha) = r/h``)."""
        st = self.linkage.state(x)
        return st["p"] / st["ta"]

    def angles(self, x):
        """``(alpha, beta)`` (rad): inclinations of the upper arm and the lower link to the
        vertical (Fig. 3.4) at ball radius ``x`` (m)."""
        st = self.linkage.state(x)
        return np.arctan(st["ta"]), np.arctan(st["tb"])

    def k_ratio(self, x):
        """The book's ``k = tan(beta)/tan(alpha)`` at ball radius ``x`` (section 3.4(b))."""
        st = self.linkage.state(x)
        return st["tb"] / st["ta"]

    def columns(self, x) -> dict:
        """Sleeve lift, height, the arm's and link's inclinations and ``k`` over ``x``."""
        alpha, beta = self.angles(x)
        return {"sleeve lift": (self.sleeve_lift(x), "m"), "height": (self.height(x), "m"),
                "alpha": (alpha, "rad"), "beta": (beta, "rad"), "k": (self.k_ratio(x), "")}

    coordinate_key: ClassVar[str] = "radius"

    def coordinates(self) -> tuple[Coordinate, ...]:
        """The ball's radius and the coordinates of :data:`BY`: the arm's angle to the axis,
        the height, the joint's radius and the sleeve's lift from the innermost
        configuration."""
        lk = self.linkage
        own = super().coordinates()
        by = {"angle": lambda x: lk.by_joint("angle", lk.joint_radius(x)),
              "height": self.height, "joint_radius": lk.joint_radius, "lift": self.sleeve_lift}
        return own + tuple(Coordinate(name, dim, f"{meaning} (textbook {fig})", by[name])
                           for name, (dim, meaning, fig) in BY.items())

    def x_domain(self) -> tuple[float, float]:
        """The ball radii the linkage reaches: those of the joint radii of
        :meth:`Linkage.joint_domain`."""
        lo, hi = self.linkage.joint_domain()
        eps = 1e-9 * (hi - lo)
        return tuple(float(self.linkage._at_joint(p)["r"]) for p in (lo + eps, hi - eps))

    def link_forces(self, x, m, central, omega2, restoring) -> dict:
        """The forces in each ball's arm and link (N), from the statics of the lower link with
        its ball (section 3.4(b); the arm is a two-force member, so its pivot's reaction is its
        tension): the sleeve's load per ball ``V = (Q - m g dy_G/dr) / (ds/dr)`` (its weight,
        the spring's share and the friction, read back from the restoring force ``Q`` of the
        seam), vertically ``T cos(alpha) = m g + V``, so the arm's tension
        ``T = (m g + V) / cos(alpha)`` (the book's ``(w + W/2) / cos(alpha)`` of the Porter);
        horizontally the sleeve pin's force ``H = T sin(alpha) - m omega^2 r`` on the link, the
        pin's force ``sqrt(H^2 + V^2)`` (a straight link's tension ``V / cos(beta)``; signed
        by ``V``: + where the sleeve hangs on the links).

        Example 1's Porter at r = 20 cm (the sleeve 48 kgf, balls 6 kgf): by hand
        ``alpha = asin(20/30)``, ``T = (6 + 24) kgf / cos(alpha) = 40.25 kgf``:

        >>> import govopt
        >>> from govopt.examples import example
        >>> spec = govopt.load_spec(example("textbook-ex1-porter"))
        >>> gov, KGF = spec.governor, 9.80665
        >>> t = gov.terms(0.2, 6.0, spec.analysis, 48.0)
        >>> f = gov.link_forces(0.2, 6.0, 48.0, t.omega_squared(), t.restoring())
        >>> round(float(f["arm tension"]) / KGF, 2)
        40.25
        """
        st = self.linkage.state(x)
        g = G_STANDARD
        V = (np.asarray(restoring, dtype=float) - g * m * st["y1"]) / st["z1"]
        cos_a = 1.0 / np.sqrt(1.0 + st["ta"] ** 2)
        T = (g * m + V) / cos_a
        H = T * st["ta"] * cos_a - m * omega2 * np.asarray(x, dtype=float)
        return {"arm tension": T, "pivot reaction": np.abs(T),
                "sleeve pin force": np.sign(V) * np.hypot(H, V), "sleeve load": 2.0 * V}

    # -- the seam ----------------------------------------------------------------------------

    def terms(self, x, m, analysis=None, central=None) -> Terms:
        """Per ball, by virtual work: ``jp = m r``; ``cf = m g dy_G/dr + (W/2) ds/dr`` with
        ``W = central g`` (section 3.4(b) eq. i, 3.4(c) eq. v); the auxiliary spring
        ``kappa (A - B l0) = P lever_ratio / 2 ds/dr`` (Example 2); ``ci = 0``."""
        x = np.asarray(x, dtype=float)
        st = self.linkage.state(x)
        w_half = 0.0 if central is None else 0.5 * central
        cf = G_STANDARD * (m * st["y1"] + w_half * st["z1"])
        cf_x = G_STANDARD * (m * st["y2"] + w_half * st["z2"])
        zero = 0.0 * x
        if self.spring is None:
            A = B = A_x = B_x = zero
        else:
            sign = 1.0 if self.spring == "tension" else -1.0
            lam, s1, s2 = self.lever_ratio, st["z1"], st["z2"]
            L = self.spring_length + sign * lam * (st["z"] - self._z_inner)
            A, B = sign * L * lam * s1 / 2, sign * lam * s1 / 2
            A_x = lam * (lam * s1**2 + sign * L * s2) / 2
            B_x = sign * lam * s2 / 2
        return Terms(jp=m * x, jpp=m + zero, cf=cf, cf_x=cf_x, ci=zero, ci_x=zero,
                     A=A, B=B, A_x=A_x, B_x=B_x)

    def inertia(self, x, m, central=None):
        """``I = m (1 + (dy_G/dr)^2) + (W/2g) (ds/dr)^2`` (kg, per ball): the ball's kinetic
        energy in the meridian plane (it rises as it moves out) and the sleeve's share; the arms'
        and links' masses neglected as in the book."""
        st = self.linkage.state(x)
        w_half = 0.0 if central is None else 0.5 * central
        return m * (1.0 + st["y1"] ** 2) + w_half * st["z1"] ** 2

    def travel_slope(self, x):
        """``ds/dr``: sleeve lift per unit ball radius (the sleeve is the regulating member)."""
        return self.linkage.state(x)["z1"]

    def friction(self, x, design=None):
        """Sleeve friction ``R`` as a band per ball, ``R/2 |ds/dr|`` (N) (section 3.4(b):
        the central load becomes ``W + R`` rising, ``W - R`` falling)."""
        return 0.5 * self.sleeve_friction * np.abs(self.travel_slope(x))

    def spring_force_coefficients(self, x):
        """The auxiliary spring's force ``P = kappa (A_F - B_F l0)``: ``(L, 1)`` in tension,
        ``(-L, -1)`` in compression; zeros without one."""
        if self.spring is None:
            return super().spring_force_coefficients(x)
        sign = 1.0 if self.spring == "tension" else -1.0
        L = self.spring_length + sign * self.lever_ratio * self.sleeve_lift(x)
        return sign * L, sign + 0.0 * L

    # -- the type's method and drawing: what a reader is told (textbook ch. 3) ---------------

    #: the textbook's section of the type, and whether the spec reads ``governor.k``
    section: ClassVar[str] = "3.4(b)"
    k_setting: ClassVar[bool] = True

    def controlling_force(self) -> Equation:
        """The type's controlling force per ball (the Porter's: section 3.4(b) eq. (i))."""
        return Equation("statics", "controlling force per ball: the ball's weight and half "
                        "the central load W through the sleeve's rise (by virtual work; the "
                        "book's instantaneous centre)", "F = m g dy/dr + (W/2) ds/dr = "
                        "[W/2 (1 + k) + w] tan(alpha), k = tan(beta) / tan(alpha)",
                        "textbook-ch3", f"{self.section} eq. (i)",
                        ("governor.k",) if self.k_setting else (), name="controlling force")

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """The controlling force, the auxiliary spring where fitted (Example 2) and the
        equilibrium of section 3.3."""
        out = (self.controlling_force(),)
        if self.spring is not None:
            law = "kappa (L - l0)" if self.spring == "tension" else "kappa (l0 - L)"
            sign = "+" if self.spring == "tension" else "-"
            out += (Equation("statics", f"auxiliary {self.spring} spring on the sleeve "
                             "through a lever: its force P and its share per ball",
                             f"P = {law}, L = spring_length {sign} (spring_arm / sleeve_arm) s; "
                             "per ball (spring_arm / sleeve_arm) (P/2) ds/dr", "textbook-ch3",
                             "3.4(b) Example 2, Fig. 3.7", name="spring force"),)
        return out + (Equation("statics", "equilibrium: the controlling force balances the "
                               "centrifugal force (the characteristic)", "m omega^2 r = F(r)",
                               "textbook-ch3", "3.3", name="characteristic"),)

    def friction_method(self, spec) -> tuple[Equation, ...]:
        """Friction at the sleeve (section 3.4(b)), where the governor has it."""
        if not self.sleeve_friction:
            return ()
        return (Equation("friction", "friction at the sleeve: a force R opposing its motion, "
                         "the central load W + R rising and W - R falling",
                         "omega_rise,fall^2 m r = F(r) +- (R/2) ds/dr", "textbook-ch3",
                         "3.4(b), friction at the sleeve", name="band"),) + \
            self.friction_strokes(spec)

    def settings(self, spec) -> list[Setting]:
        """The seam's settings and the book's ``k = 1`` shortcut."""
        own = [Setting("governor.k", self.linkage.k, "the sleeve's rise: the exact linkage, or "
                       "the book's k = 1 (the sleeve rising twice as fast as the ball)")]
        return (own if self.k_setting else []) + super().settings(spec)

    def drawing(self, x, sd) -> Drawing:
        """Both halves in the meridian plane, from the linkage the statics use: the upper arm
        from its pivot (at ``pivot_offset`` from the axis) to the joint B, the link from B to
        the sleeve's pin C (at ``sleeve_offset``), the ball at B (a Proell's at G, on the link
        produced), the sleeve at C's height on the spindle; the auxiliary spring, where
        fitted, hangs on the spindle under the sleeve at its own length (its lever is given
        as a ratio only, so it is not drawn)."""
        lk = self.linkage
        p = float(lk.joint_radius(x))
        g = lk._at_joint(p)
        ca = np.sqrt(1.0 - ((p - lk.pivot_offset) / lk.arm) ** 2)
        cb = np.sqrt(1.0 - ((p - lk.sleeve_offset) / lk.link) ** 2)
        B = (p, -lk.arm * ca)
        C = (lk.sleeve_offset, B[1] - lk.link * cb)
        G = (float(g["r"]), float(g["y"]))
        half = max(lk.sleeve_offset, 0.06 * lk.arm)
        tall = 0.12 * lk.arm + (0.1 * lk.arm if sd.central else 0.0)
        sleeve = ((-half, C[1] - 0.5 * tall), (half, C[1] - 0.5 * tall),
                  (half, C[1] + 0.5 * tall), (-half, C[1] + 0.5 * tall),
                  (-half, C[1] - 0.5 * tall))
        parts = [Part("link", ((lk.pivot_offset, 0.0), B, C)),
                 Part("pivot", ((lk.pivot_offset, 0.0),)), Part("pivot", (C,)),
                 Part("mass", (G,), ball_radius(sd.m))]
        if G != B:
            parts.append(Part("link", (B, G)))
        parts = list(mirrored(parts)) + [Part("sleeve", sleeve)]
        low = float(self.linkage.state(self.x_inner)["z"])  # the sleeve's lowest pin height
        bottom = min(C[1], low) - 0.5 * tall
        if self.spring is not None:
            L = float(self.spring_force_coefficients(x)[0]) * (1 if self.spring == "tension"
                                                              else -1)
            top = C[1] - 0.5 * tall
            width = 2.0 * sd.r if np.isfinite(sd.r) else half
            parts.append(Part("spring", zigzag((0.0, top), (0.0, top - L), width)))
            bottom = min(bottom, top - L)
        parts.append(Part("frame", ((0.0, 0.15 * lk.arm), (0.0, bottom - 0.1 * lk.arm))))
        return Drawing(tuple(parts))


class PorterGovernor(BallGovernor):
    """Porter governor (section 3.4(b)): a Watt with a central load on the sleeve; unequal arms
    and offsets allowed (``k`` varies), and an optional auxiliary spring (Example 2, Fig. 3.7)."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("textbook-ex1-porter", {"governor.radius_inner": "4 cm",
                                                   "governor.radius_outer": "29.5 cm"},
                               "governor.k", ("exact", "unity"))

    type_name: ClassVar[str] = "porter"
    title: ClassVar[str] = "Porter governor (textbook ch. 3, section 3.4(b), Figs. 3.1(b), 3.4-3.7)"
    keys: ClassVar[tuple[Key, ...]] = (ARM, LINK, PIVOT_OFFSET, SLEEVE_OFFSET, K, *BALL_RANGE,
                                       SLEEVE_FRICTION, *SPRING_KEYS)
    example: ClassVar[str] = "porter-design"
    optional_spring: ClassVar[str | None] = "tension"

    @classmethod
    def parse(cls, reader) -> PorterGovernor:
        """Keys: ``arm``, ``link`` (default ``arm``), ``pivot_offset``, ``sleeve_offset``
        (default 0), ``k`` ("exact" | "unity"), the radius range, ``sleeve_friction`` and the
        auxiliary spring's keys (:meth:`BallGovernor._read_spring`)."""
        linkage = Linkage(**reader.read_all((ARM, LINK, PIVOT_OFFSET, SLEEVE_OFFSET, K)))
        inner, outer, normal = cls._read_range(reader, linkage)
        friction = reader.read(SLEEVE_FRICTION)
        spring = cls._read_spring(reader)
        reader.finish()
        cls._check_reach(reader, linkage, inner, outer)
        return cls(linkage, inner, outer, normal, friction, **spring)
