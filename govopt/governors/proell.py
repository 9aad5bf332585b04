"""The Proell governor (textbook ch. 3, section 3.4(c), Figs. 3.1(c), 3.8, 3.9).

A Porter (:mod:`govopt.governors.porter`) whose balls sit not at the joint B of arm and link but at
G on a rigid extension ``BG = extension`` of the lower link CB beyond B (a cranked lever, Example
3). The extension is turned from the line CB produced through ``extension_angle`` towards the
axis; by default the angle that makes BG vertical at the normal configuration, the book's
assumption for Fig. 3.8 ("the extension BG ... is vertical for the given configuration") and
Example 3 ("the arm AB of the cranked lever is vertical" in mid position). An
``extension_angle`` of 0 puts the ball on the straight extension of the link (Fig. 3.1(c)).

The coordinate is still the ball's radius ``r`` (of G); the joint's radius ``r_B`` follows from
``r = r_B + c sin(beta - extension_angle)`` (Newton's method; the derivatives by the chain rule,
in closed form). Per ball, by virtual work::

    omega^2 m r = m g dy_G/dr + (W/2) ds/dr,

which with BG vertical is the book's moment about the instantaneous centre I of the link
(section 3.4(c), eqs. i-v)::

    F DG = w ID + W/2 (ID + DC),   F = (BD/DG) [W/2 (1 + k) + w] tan(alpha).

Classic measures: the extension's factor ``BD/DG`` (:meth:`ProellGovernor.extension_factor`):
for the same height, balls and load, a Proell runs slower than a Porter by ``sqrt(BD/DG)``
(section 3.4(c)), and needs smaller balls for the same speed. Sleeve friction as for the Porter.
"""

from __future__ import annotations

import math
from typing import ClassVar

import numpy as np

from ..keys import Key
from .base import Equation
from .porter import (
    ARM,
    BALL_RANGE,
    ENDS,
    LINK,
    PIVOT_OFFSET,
    SLEEVE_FRICTION,
    SLEEVE_OFFSET,
    BallGovernor,
    K,
    Linkage,
)

EXTENSION = Key("extension", "length", "the extension c = BG of the lower link beyond the joint "
                                       "B to the ball's centre G", source="textbook Fig. 3.8")
EXTENSION_ANGLE = Key("extension_angle", "angle", "the extension's turn from the line CB "
                                                  "produced, towards the axis (0: the ball on "
                                                  "the straight extension, Fig. 3.1(c))",
                      default=None, nonnegative=True, high=math.pi / 2,
                      range_text="[0 deg, 90 deg)",
                      default_text="BG vertical at radius_normal (the book's assumption for "
                                   "Fig. 3.8 and Example 3)", source="textbook 3.4(c)")


class ProellGovernor(BallGovernor):
    """Proell governor (section 3.4(c)): the ball on an extension of the lower link."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("textbook-ex3-proell", {"governor.link": "20 cm",
                                                   "governor.radius_inner": "8 cm",
                                                   "governor.radius_outer": "22 cm"},
                               "governor.k", ("exact", "unity"))

    type_name: ClassVar[str] = "proell"
    title: ClassVar[str] = ("Proell governor (textbook ch. 3, section 3.4(c), Figs. 3.1(c), 3.8, "
                            "3.9)")
    keys: ClassVar[tuple[Key, ...]] = (ARM, LINK, PIVOT_OFFSET, SLEEVE_OFFSET, EXTENSION,
                                       EXTENSION_ANGLE, K, *BALL_RANGE, SLEEVE_FRICTION)
    example: ClassVar[str] = "proell-design"

    @classmethod
    def parse(cls, reader) -> ProellGovernor:
        """Keys: ``arm`` (pivot to joint B), ``link`` (B to the sleeve pin, default ``arm``),
        ``pivot_offset``, ``sleeve_offset`` (default 0), ``extension`` (BG), ``extension_angle``
        (default: BG vertical at ``radius_normal``), ``k``, the radius range and
        ``sleeve_friction``."""
        arm, link, pivot, sleeve, extension, angle, k = reader.read_all(
            (ARM, LINK, PIVOT_OFFSET, SLEEVE_OFFSET, EXTENSION, EXTENSION_ANGLE, K)).values()
        base = Linkage(arm=arm, link=link, pivot_offset=pivot, sleeve_offset=sleeve, k=k)
        if angle is not None:
            linkage = Linkage(arm=arm, link=link, pivot_offset=pivot, sleeve_offset=sleeve,
                              extension=extension, crank=angle, k=k)
            inner, outer, normal = cls._read_range(reader, linkage)
        else:  # BG vertical at the normal configuration: r_B = r there
            got = cls._read_range(reader, base, to_radius=None)
            radii, joints = got if isinstance(got[0], dict) else \
                (dict(zip(ENDS, got, strict=True)), {})
            p_normal = joints.get("normal", radii["normal"])
            if p_normal is None:
                reader.fail("radius_normal", "needed where the ends are given by another "
                            "coordinate: the extension is set vertical there")
            sin_beta = (p_normal - sleeve) / link
            if not (abs(sin_beta) < 1 and 0 < (p_normal - pivot) / arm < 1):
                reader.fail("radius_normal", "the arm and link cannot reach this radius")
            linkage = Linkage(arm=arm, link=link, pivot_offset=pivot, sleeve_offset=sleeve,
                              extension=extension, crank=math.asin(sin_beta), k=k)
            inner, outer, normal = (float(linkage._at_joint(joints[e])["r"]) if e in joints
                                    else radii[e] for e in ENDS)
            inner, outer, normal = cls._ordered(reader, inner, outer, normal)
        friction = reader.read(SLEEVE_FRICTION)
        reader.finish()
        cls._check_reach(reader, linkage, inner, outer)
        return cls(linkage, inner, outer, normal, friction)

    def extension_factor(self, x):
        """The book's ``BD/DG`` (section 3.4(c), eq. ii): the joint B's and the ball G's heights
        above the sleeve pin C, at ball radius ``x`` (m); the factor on a Porter's controlling
        force where BG is vertical."""
        st = self.linkage.state(x)
        lk = self.linkage
        theta = np.arcsin((st["p"] - lk.sleeve_offset) / lk.link)
        bd = lk.link * np.cos(theta)
        return bd / (bd + lk.extension * np.cos(theta - lk.crank))

    # -- the type's method: what a reader is told (textbook 3.4(c)) ---------------------------

    section: ClassVar[str] = "3.4(c)"

    def controlling_force(self) -> Equation:
        """The Proell's controlling force per ball (section 3.4(c) eqs. i-v)."""
        return Equation("statics", "controlling force per ball at G on the link produced: "
                        "moments about the link's instantaneous centre I (by virtual work on "
                        "the exact linkage)", "F = m g dy_G/dr + (W/2) ds/dr; with BG vertical "
                        "F = (BD/DG) [W/2 (1 + k) + w] tan(alpha)", "textbook-ch3",
                        f"{self.section} eqs. (i)-(v)", ("governor.k",),
                        name="controlling force")
