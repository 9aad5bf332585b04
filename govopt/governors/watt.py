"""The Watt governor (textbook ch. 3, section 3.4(a), Figs. 3.1(a), 3.3).

Each ball hangs from an arm suspended in one of three ways (Fig. 3.3), the ``suspension`` key:

* ``"axis"``: pivoted on the spindle's axis (Fig. 3.3(a));
* ``"collar"``: from a collar at ``pivot_offset`` from the axis on the ball's side, so the arm
  produced meets the axis (Fig. 3.3(b));
* ``"crossed"``: from a collar at ``pivot_offset`` on the far side, the arm crossing the spindle
  (Fig. 3.3(c)).

The sleeve hangs from the balls by links (``link``, default the arm's length, pinned at
``sleeve_offset``, default 0): it is the regulating member. The book neglects its weight, so the
Watt has no central load by default; one may be given (it is then a Porter,
:mod:`govopt.governors.porter`, whose statics this module shares).

With the sleeve neglected, moments about the point O where the arm (produced) meets the axis give,
for every suspension (section 3.4(a), eq. i)::

    (w/g) omega^2 r h = w r,   so   h = g / omega^2,

the height ``h`` being the ball's depth below O (:meth:`.BallGovernor.height`).
With N in rpm, ``h = 900 g / (pi^2 N^2)``; the book prints ``89560/N^2`` cm for g = 981 cm/s^2,
but ``900 x 981 / pi^2 = 89 456`` (:func:`height_constant`).

Classic measures: the height ``h`` against speed (:func:`height_for_speed`), beyond the generic
ones; sleeve friction as for the Porter.
"""

from __future__ import annotations

import math
from typing import ClassVar

import numpy as np

from ..keys import Key
from ..units import G_STANDARD
from .base import Equation
from .porter import ARM, BALL_RANGE, SLEEVE_FRICTION, SLEEVE_OFFSET, BallGovernor, Linkage

SUSPENSIONS = ("axis", "collar", "crossed")

SUSPENSION = Key("suspension", "choice", "how the arms hang: \"axis\" (pivoted on the "
                                         "spindle's axis, Fig. 3.3(a)), \"collar\" (from a "
                                         "collar on the ball's side, Fig. 3.3(b)) or \"crossed\" "
                                         "(the arms crossing the spindle, Fig. 3.3(c))",
                 default="axis", choices=SUSPENSIONS, source="textbook Fig. 3.3")
PIVOT_OFFSET = Key("pivot_offset", "length", "the arms' pivots' distance from the spindle's "
                                             "axis", when="with suspension = \"collar\" or "
                                                          "\"crossed\" (required there)",
                   source="textbook Fig. 3.3(b), (c)")
LINK = Key("link", "length", "the link from the ball's joint to the sleeve pin",
           default=lambda v: v["arm"], default_text="arm", source="textbook Fig. 3.3")


def height_for_speed(omega, g=9.80665):
    """Height of a Watt governor with the sleeve neglected, ``h = g / omega^2`` (m; ``omega`` in
    rad/s, ``g`` in m/s^2), textbook section 3.4(a) eq. (i).

    Parameters
    ----------
    omega : float [rad/s]
        Angular speed of the spindle.
    g : float [m/s^2]
        Acceleration of gravity.

    References
    ----------
    [textbook-ch3] section 3.4(a) eq. (i). The section has no worked speed: the example is a hand
    calculation at 60 rpm with standard gravity (rounded to 0.01 cm; the book's ``89560 / N^2``
    with g = 981 cm/s^2 gives 24.88 cm).

    >>> round(height_for_speed(math.pi * 60 / 30) * 100, 2)  # 60 rpm: 24.84 cm
    24.84
    """
    return g / omega**2


def height_constant(g):
    """``C`` in ``h = C / N^2`` (N in rpm): ``900 g / pi^2``, in the units of ``g`` times rpm^2
    (section 3.4(a)). The book prints 89560 cm rpm^2 for g = 981 cm/s^2; it is 89 456.

    Parameters
    ----------
    g : float [length/s^2]
        Acceleration of gravity, in the length unit wanted for ``h``.

    References
    ----------
    [textbook-ch3] section 3.4(a), the constant of ``h = C / N^2``.

    >>> round(height_constant(981.0)), round(height_constant(980.665))
    (89456, 89426)
    """
    return 900.0 * g / math.pi**2


class WattGovernor(BallGovernor):
    """Watt governor (section 3.4(a)): the three suspensions of Fig. 3.3; no central load unless
    the design gives one."""

    type_name: ClassVar[str] = "watt"
    title: ClassVar[str] = "Watt governor (textbook ch. 3, section 3.4(a), Figs. 3.1(a), 3.3)"
    keys: ClassVar[tuple[Key, ...]] = (ARM, SUSPENSION, PIVOT_OFFSET, LINK, SLEEVE_OFFSET,
                                       *BALL_RANGE, SLEEVE_FRICTION)
    example: ClassVar[str] = "watt-design"
    #: arms from near the axis to near 90 deg (govopt bench), against the book's h = g/omega^2
    bench_case: ClassVar[tuple] = ({"name": "watt-hard", "governor": {
        "type": "watt", "arm": "30 cm", "radius_inner": "0.5 cm", "radius_outer": "29.7 cm"},
        "design": {"ball_weight": "5 kgf"}}, {}, "", ("exact",), "governor.arm")

    def bench_reference(self, spec, x):
        """The book's ``omega^2 = g / h`` (section 3.4(a) eq. i; the sleeve neglected, no
        central load), ``h = sqrt(a^2 - r^2)`` for arms pivoted on the axis, in mpmath (50
        digits); None for another suspension or a central load."""
        import mpmath as mp

        lk = self.linkage
        if lk.pivot_offset != 0.0 or (spec.design.central_mass or 0.0) != 0.0:
            return None
        with mp.workdps(50):
            a = mp.mpf(lk.arm)
            return np.array([float(mp.sqrt(G_STANDARD / mp.sqrt(a**2 - mp.mpf(float(r))**2)))
                             for r in np.atleast_1d(x)])

    @classmethod
    def parse(cls, reader) -> WattGovernor:
        """Keys: ``arm``; ``suspension`` ("axis" | "collar" | "crossed", default "axis") with
        ``pivot_offset`` (required and positive for "collar" and "crossed", absent for "axis");
        ``link`` (default ``arm``), ``sleeve_offset`` (default 0); the radius range and
        ``sleeve_friction``."""
        v = reader.read_all((ARM, SUSPENSION))
        suspension = v["suspension"]
        if suspension == "axis":
            if reader.has("pivot_offset"):
                reader.fail("pivot_offset", "not used with suspension = \"axis\" (Fig. 3.3(a))")
            offset = 0.0
        else:
            offset = reader.read(PIVOT_OFFSET, v)
        reader.read_all((LINK, SLEEVE_OFFSET), v)
        linkage = Linkage(arm=v["arm"], link=v["link"],
                          pivot_offset=-offset if suspension == "crossed" else offset,
                          sleeve_offset=v["sleeve_offset"])
        inner, outer, normal = cls._read_range(reader, linkage)
        friction = reader.read(SLEEVE_FRICTION)
        reader.finish()
        cls._check_reach(reader, linkage, inner, outer)
        gov = cls(linkage, inner, outer, normal, friction)
        gov.suspension = suspension
        return gov

    # -- the type's method: what a reader is told (textbook 3.4(a)) ---------------------------

    section: ClassVar[str] = "3.4(a)"
    k_setting: ClassVar[bool] = False  # the Watt's spec has no k

    def controlling_force(self) -> Equation:
        """The Watt's controlling force per ball, and its height with the sleeve neglected."""
        return Equation("statics", "controlling force per ball: the ball's weight (and the "
                        "sleeve's, where the design gives one) through the arm's slope, by "
                        "virtual work; the sleeve neglected, the height h = g / omega^2",
                        "F = m g dy/dr + (W/2) ds/dr = w tan(alpha) (W = 0); h = g / omega^2",
                        "textbook-ch3", f"{self.section} eq. (i)", name="controlling force")
