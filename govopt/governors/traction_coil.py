"""The coil-spring traction-engine governor (the spring-balance governor article,
``/work/shared/seeds/003_*``, Fig. 1) on the seam.

Each of ``n`` fly weights sits at the knee of a toggle: two arms of length ``a`` from the knee to
hinges on two collars on the spindle, the hinges at radius ``r_h`` from its centreline and ``l``
apart along it; one collar is fixed, the other moves the throttle-valve rod. A helical compression
spring round the rod resists the collars' closing. With the weight's offset from the hinge axis
``y`` (the article's ``x``)::

    y = r - r_h,   l = 2 sqrt(a^2 - y^2),   rod travel s = l_1 - l,   ds/dr = 4 y / l

(``l_1``: the hinge spacing with the throttle just fully open). The coordinate is the fly-weight
radius ``r`` (the article's ``r``, measured directly, and the textbook governors' coordinate);
the range runs from the throttle just fully open (``hinge_spacing_open``, the minimum full-power
speed) to just closed (``hinge_spacing_closed``, the minimum no-load speed). The spring's length
is ``d = spring_length - s`` (``spring_length``: its installed length with the throttle fully
open), its force ``P = kappa (l0 - d)``.

Statics by virtual work, per fly weight: ``omega^2 m r = (P/n) ds/dr``, i.e.
``P = n m r omega^2 l / (4 y)``: the article's eq. 1, exact for this toggle at every rod position
(its ``l``, ``x``, ``r`` "vary with the position of the valve rod"; the article approximates
nothing here). Its eqs. 2-4 are the spring through two equilibria: the characteristic is affine
in ``kappa`` and ``kappa l0``, so two speeds at two positions fix both
(:meth:`TractionCoilGovernor.spring_for_speeds`).

The article's constant is wrong for its own units: see :func:`centrifugal_force`. Neglected, as in
the article: friction (unless ``rod_friction`` is given), the arms' masses, and the weights'
own weight (the knee rises ``s/2`` as the collars close).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..keys import Key
from .base import Adjustment, Equation, Governor, Terms
from .drawing import Drawing, Part, ball_radius, mirrored, zigzag

#: what both traction governors read (:class:`FlyWeights`)
N_WEIGHTS = Key("n_weights", "count", "the number of fly weights", source="article 003",
                example=2)
ROD_FRICTION = Key("rod_friction", "force", "the throttle rod's friction (valve and gland), "
                                            "a band about the characteristic",
                   default=0.0, nonnegative=True)
HINGE_RADIUS = Key("hinge_radius", "length", "the hinges' (end attachments') radius from the "
                                             "spindle's centreline r_h", nonnegative=True,
                   source="article 003, Figs. 1-2")


def _spacing(end: str, meaning: str, **kw) -> Key:
    return Key(f"hinge_spacing_{end}", "length", meaning, high=lambda v: 2.0 * v["arm_length"],
               range_text="(0, 2 arm_length)", source="article 003, Fig. 1", **kw)


#: ``[governor]`` of the coil-spring traction governor (article 003, Fig. 1)
KEYS = (
    N_WEIGHTS,
    Key("arm_length", "length", "each toggle arm, from its hinge to the fly weight's centre a",
        source="article 003, Fig. 1"),
    HINGE_RADIUS,
    _spacing("open", "the hinges' spacing along the spindle with the throttle just fully open "
                     "(the article's l_1; the lowest speed)"),
    _spacing("closed", "the hinges' spacing with the throttle just closed (l_2; the highest "
                       "speed), less than hinge_spacing_open"),
    _spacing("normal", "the hinges' spacing at the normal configuration", default=None,
             default_text="the fly weights at the mid radius"),
    Key("spring_length", "length", "the compression spring's installed length round the rod "
                                    "with the throttle fully open; it shortens by the rod's "
                                    "travel. Only its initial compression enters the statics "
                                    "(the search designs the free length), but the spring must "
                                    "fit: a longer spring leaves room for more turns of "
                                    "thinner wire; choose the room the rod gives",
        source="article 003, eqs. 2-4"),
    ROD_FRICTION,
)


def centrifugal_force(m, r, omega):
    """Centrifugal force on a fly weight of mass ``m`` (kg) at radius ``r`` (m) turning at
    ``omega`` (rad/s): ``F = m r omega^2`` (N). The article's eq. 6 (and inside eq. 1).

    Parameters
    ----------
    m : float or array [kg]
        Mass of the fly weight.
    r : float or array [m]
        Radius of its centre of mass.
    omega : float or array [rad/s]
        Angular speed.

    References
    ----------
    [traction-article] eq. 6; the example below is the article's 8 lbf weight at 2.5 in and
    250 rpm (force rounded to 0.001 lbf).

    The article writes ``F = W r N^2 / 2933`` (W in lbf, r in inches, N in rpm, "the constant 2933
    has dimensions of inches"). With ``W = m g``, ``F = (W/g) r (2 pi N / 60)^2``, so the
    constant is ``g / (2 pi / 60 rad/s per rpm)^2`` = 2933.9 *feet* (g = 32.174 ft/s^2) and, with
    ``r`` in inches as the article's table of symbols says, 35,207 in: the article's formula
    gives 12 times the force. Here the specs carry units, so no such constant appears:

    >>> from govopt.units import Q_
    >>> C = Q_(1, "standard_gravity") / Q_(1, "rpm") ** 2
    >>> round(C.to("ft").magnitude, 1), round(C.to("in").magnitude)
    (2933.9, 35207)
    >>> W, r, N = Q_(8, "lbf"), Q_(2.5, "in"), Q_(250, "rpm")  # 8 lbf at 2.5 in, 250 rpm
    >>> m = (W / Q_(1, "standard_gravity")).to("kg").magnitude
    >>> F = centrifugal_force(m, r.to("m").magnitude, N.to("rad/s").magnitude)
    >>> round(Q_(F, "N").to("lbf").magnitude, 3), round(8 * 2.5 * 250**2 / 35207, 3)
    (35.504, 35.504)
    """
    return m * r * omega**2


def toggle_spring_force(F, l, y, n):
    """The spring force ``P = n F l / (4 y)`` [N] balancing ``n`` fly weights on their toggles
    (the article's eq. 1, by virtual work: ``dl = -(4 y / l) dy``).

    Parameters
    ----------
    F : float or array [N]
        Centrifugal force on each fly weight (:func:`centrifugal_force`).
    l : float or array [m]
        Hinge spacing along the spindle.
    y : float or array [m]
        The weight's offset from the hinge axis (the article's ``x``).
    n : int [-]
        Number of fly weights.

    Returns
    -------
    float or array [N]
        The spring's force on the rod.

    References
    ----------
    [traction-article] eq. 1.

    Examples
    --------
    The article gives no worked numbers; the bundled case ``traction-coil-replacement`` (two
    8 lbf weights on 3 in arms, hinges at 0.75 in, spacing 5 in at 220 rpm, 4.75 in at 250 rpm)
    needs 39.93 and 47.53 lbf, as its test works out in lbf, in and rpm:

    >>> import math
    >>> LBF, IN, LB = 4.4482216152605, 0.0254, 0.45359237  # lbf [N], in [m], lb [kg]
    >>> RPM, PSI = 2 * math.pi / 60, 4.4482216152605 / 0.0254**2  # [rad/s], [Pa]
    >>> for l, N in ((5.0, 220), (4.75, 250)):
    ...     y = math.sqrt(3.0**2 - (l / 2) ** 2) * IN
    ...     F = centrifugal_force(8 * LB, 0.75 * IN + y, N * RPM)
    ...     print(round(toggle_spring_force(F, l * IN, y, 2) / LBF, 2))
    39.93
    47.53
    """
    return n * F * l / (4.0 * y)


def spring_rate_and_free_length(P1, d1, P2, d2):
    """The spring through two operating points: rate ``K = (P2 - P1)/(d1 - d2)`` [N/m] and free
    length ``L = (P2 d1 - P1 d2)/(P2 - P1)`` [m] (the article's eqs. 2-4).

    From ``K = P1/(L - d1) = P2/(L - d2)``; eq. 4 checked: it solves eq. 3.

    Parameters
    ----------
    P1 : float [N]
        Spring force at the first operating point.
    d1 : float [m]
        The spring's installed length there.
    P2 : float [N]
        Spring force at the second operating point.
    d2 : float [m]
        The spring's installed length there.

    Returns
    -------
    tuple of float [N/m, m]
        ``(K, L)``.

    References
    ----------
    [traction-article] eqs. 2-4.

    Examples
    --------
    A hand check: 10 N at 0.5 m and 20 N at 0.4 m give 100 N/m and 0.6 m:

    >>> K, L = spring_rate_and_free_length(10.0, 0.5, 20.0, 0.4)
    >>> round(K, 9), round(L, 9)
    (100.0, 0.6)

    The bundled case ``traction-coil-replacement`` (the article gives no worked numbers): 39.9293
    lbf at 4 in, 47.5308 lbf at 3.75 in (:func:`toggle_spring_force`) give 30.406 lbf/in and a
    free length of 5.3132 in:

    >>> LBF, IN = 4.4482216152605, 0.0254
    >>> K, L = spring_rate_and_free_length(39.9293 * LBF, 4.0 * IN, 47.5308 * LBF, 3.75 * IN)
    >>> round(K / (LBF / IN), 3), round(L / IN, 4)
    (30.406, 5.3132)
    """
    return (P2 - P1) / (d1 - d2), (P2 * d1 - P1 * d2) / (P2 - P1)


class FlyWeights(Governor):
    """What the article's two governors share (Figs. 1-2): ``n_weights`` fly weights moving the
    throttle rod, whose travel ``s(r)`` each type's ``geometry(x)["s1"] = ds/dr`` gives, against
    the rod's friction ``rod_friction``; the coordinate is the fly-weight radius.

    No resonance ceiling (:attr:`Governor.resonance_ceiling`): the weights turn on a vertical
    spindle (the article's "vertical throttle valve rod"), so their weight acts along it and
    nothing forces them once per revolution - Hamabe's ``k^2 < omega0^2`` guards his shaft
    governor against its valve gear's harmonics (Part II, case 2), which these governors do not
    have. Kept, it asks for a nearly isochronous governor: the article's own replacement spring
    (``traction-coil-replacement.toml``, 220-250 rpm) has ``k^2`` up to 2.69 ``omega0^2``, and
    the design spec's ceiling forced a spring of 0.61 m free length for a 4 in installed
    length, which buckles (EN 13906-1; the article: "a narrow speed range ... the resulting
    spring will be longer and with lower spring rate")."""

    resonance_ceiling: ClassVar[bool] = False
    source: ClassVar[str] = "traction-article"
    friction_key: ClassVar[str] = "governor.rod_friction"

    @property
    def flying_masses(self) -> int:  # type: ignore[override]
        """The spec's ``n_weights`` fly weights (effort, power and the moving mass)."""
        return self.n_weights

    def inertia(self, x, m, central=None):
        """``I = m (1 + (ds/dr / 2)^2)`` (kg): the weight moves out by ``dr`` and along the
        spindle by half the rod's travel (one collar fixed); arms, rod and spring neglected, as
        in the article."""
        return m * (1.0 + 0.25 * self.geometry(x)["s1"] ** 2)

    def adjustments(self) -> tuple[Adjustment, ...]:
        """The spring's free length, set on the governor so that it begins to open the throttle
        at the design's lowest speed: the article designs from the minimum speeds "to allow
        for speed adjustment by the controller on the governor"."""
        return (Adjustment("the spring's setting (its free length, by the controller's "
                           "adjustment)", "free_half_length", "inner", "traction-article",
                           "design step 1 (speed adjustment on the governor)"),)

    def travel_slope(self, x):
        """``ds/dr``: the throttle rod's travel per unit fly-weight radius."""
        return self.geometry(x)["s1"]

    def friction(self, x, design=None):
        """The rod's friction ``R`` (valve and gland) as a band per weight, ``R/n ds/dr``."""
        return self.rod_friction / self.n_weights * self.travel_slope(x)

    # -- the method's parts the two governors share (what a reader is told) ------------------

    def friction_method(self, spec) -> tuple[Equation, ...]:
        """The rod's friction, where given (the article neglects it; govopt takes it as the
        textbook's friction at the sleeve, on the rod)."""
        if not self.rod_friction:
            return ()
        return (Equation("friction", "the throttle rod's friction R (valve and gland) opposing "
                         "its motion, as the textbook's friction at the sleeve (the article "
                         "neglects friction)", "omega_rise,fall^2 m r = F(r) +- (R/n) ds/dr",
                         "textbook-ch3", "3.4(b), friction at the sleeve", name="band"),) + \
            self.friction_strokes(spec)

    def centrifugal(self) -> Equation:
        """The article's eq. 6 with the constant corrected (:func:`centrifugal_force`)."""
        return Equation("statics", "centrifugal force on a fly weight (the article's constant "
                        "2933 is in feet, not inches: F = m r omega^2 in any consistent units)",
                        "F = m r omega^2 (the article: W r N^2 / 2933)", "traction-article",
                        "eq. 6")


@dataclass(frozen=True)
class TractionCoilGovernor(FlyWeights):
    """Coil-spring traction-engine governor (article 003, Fig. 1), SI; per fly weight."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("traction-coil-replacement-si", {}, "", ("exact",))

    type_name: ClassVar[str] = "traction_coil"
    title: ClassVar[str] = "Coil-spring traction-engine governor (article 003, Fig. 1)"
    coordinate: ClassVar[str] = "length"
    coordinate_name: ClassVar[str] = "fly-weight radius"
    travel: ClassVar[str] = "length"
    spring: ClassVar[str | None] = "compression"
    mass_key: ClassVar[str] = "fly"
    mass_name: ClassVar[str] = "fly weight"
    free_length_key: ClassVar[str] = "free_length"
    keys: ClassVar[tuple[Key, ...]] = KEYS
    example: ClassVar[str] = "traction-coil-design"

    n_weights: int
    arm_length: float
    hinge_radius: float
    spacing_open: float
    spring_length: float
    x_inner: float
    x_outer: float
    x_normal: float
    rod_friction: float = 0.0

    @classmethod
    def parse(cls, reader) -> TractionCoilGovernor:
        """Keys ``n_weights``, ``arm_length`` (each toggle arm, hinge to the weight's centre),
        ``hinge_radius``, ``hinge_spacing_open`` and ``hinge_spacing_closed`` (the article's
        ``l_1``, ``l_2``), ``hinge_spacing_normal`` (default: the mid radius), ``spring_length``
        (installed, throttle fully open), ``rod_friction`` (default 0).

        >>> from govopt.reader import Reader
        >>> gov = TractionCoilGovernor.parse(Reader("ex", {"n_weights": 2, "arm_length": "3 in",
        ...     "hinge_radius": "0.75 in", "hinge_spacing_open": "5 in",
        ...     "hinge_spacing_closed": "4.75 in", "spring_length": "4 in"}, "governor", []))
        >>> round(gov.x_inner / 0.0254, 6)  # r_1 = r_h + sqrt(a^2 - (l_1/2)^2), in
        2.408312
        """
        v = reader.read_all(KEYS[:6])
        n, a, r_h = v["n_weights"], v["arm_length"], v["hinge_radius"]
        spacing = {key: v[f"hinge_spacing_{key}"] for key in ("open", "closed", "normal")}
        if not spacing["closed"] < spacing["open"]:
            reader.fail("hinge_spacing_closed", "expected less than hinge_spacing_open (the "
                                                "collars close as the weights fly out)")
        radius = {k: None if v is None else r_h + np.sqrt(a**2 - 0.25 * v**2)
                  for k, v in spacing.items()}
        normal = radius["normal"] if radius["normal"] is not None \
            else 0.5 * (radius["open"] + radius["closed"])
        if not radius["open"] <= normal <= radius["closed"]:
            reader.fail("hinge_spacing_normal", "expected between the open and closed spacings")
        length, friction = reader.read_all(KEYS[6:]).values()
        gov = cls(n_weights=n, arm_length=a, hinge_radius=r_h, spacing_open=spacing["open"],
                  spring_length=length, x_inner=float(radius["open"]),
                  x_outer=float(radius["closed"]), x_normal=float(normal),
                  rod_friction=friction)
        travel = spacing["open"] - spacing["closed"]
        if gov.spring_length <= travel:
            reader.fail("spring_length", f"the rod travels {travel:.4g} m over the range: the "
                                         "spring would close up")
        reader.finish()
        return gov

    # -- geometry -------------------------------------------------------------------------------

    def geometry(self, x) -> dict:
        """At fly-weight radii ``x`` (m): offset ``y`` from the hinge axis, hinge spacing ``l``,
        rod travel ``s`` from the throttle fully open with ``s1 = ds/dr``, ``s2 = d2s/dr2``, and
        the spring's length ``d`` (all m)."""
        y = np.asarray(x, dtype=float) - self.hinge_radius
        l = 2.0 * np.sqrt(self.arm_length**2 - y**2)
        s = self.spacing_open - l
        return dict(y=y, l=l, s=s, s1=4.0 * y / l, s2=4.0 / l + 16.0 * y**2 / l**3,
                    d=self.spring_length - s)

    def columns(self, x) -> dict:
        g = self.geometry(x)
        return {"hinge spacing": (g["l"], "m"), "rod travel": (g["s"], "m"),
                "spring length": (g["d"], "m")}

    # -- the seam -------------------------------------------------------------------------------

    def terms(self, x, m, analysis=None, central=None) -> Terms:
        """Per fly weight: ``jp = m r``; the spring ``(P/n) ds/dr`` with ``P = kappa (l0 - d)``,
        ``d' = -s'``: ``A = -d s'/n``, ``B = -s'/n``; no dead loads."""
        x = np.asarray(x, dtype=float)
        g, n = self.geometry(x), self.n_weights
        zero = 0.0 * x
        return Terms(jp=m * x, jpp=m + zero, cf=zero, cf_x=zero, ci=zero, ci_x=zero,
                     A=-g["d"] * g["s1"] / n, B=-g["s1"] / n,
                     A_x=(g["s1"] ** 2 - g["d"] * g["s2"]) / n, B_x=-g["s2"] / n)

    def spring_force_coefficients(self, x):
        """``P = kappa (l0 - d)``: ``(A_F, B_F) = (-d, -1)``."""
        d = self.geometry(x)["d"]
        return -d, -1.0 + 0.0 * d

    # -- the type's method and drawing: what a reader is told (the article, Fig. 1) -----------

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """The article's eqs. 1-4 and 6 on the toggle of Fig. 1."""
        return (self.centrifugal(),
                Equation("statics", "the toggle: the weight's offset y from the hinge axis, the "
                         "hinge spacing l and the rod's travel s", "y = r - r_h, l = 2 sqrt(a^2 "
                         "- y^2), s = l_1 - l, ds/dr = 4 y / l", "traction-article", "Fig. 1"),
                Equation("statics", "the spring's force balancing n fly weights (by virtual "
                         "work, exact at every rod position): the characteristic",
                         "P = n F l / (4 y), i.e. omega^2 m r = (P/n) ds/dr", "traction-article",
                         "eq. 1", name="characteristic"),
                Equation("statics", "the spring's force and length; the spring through two "
                         "operating points", "P = kappa (l0 - d), d = spring_length - s; K = "
                         "P / (L - d)", "traction-article", "eqs. 2-4", name="spring force"))

    def drawing(self, x, sd) -> Drawing:
        """One toggle each side in the meridian plane (Fig. 1): the fixed collar's hinge at
        height 0 and the moving collar's ``l`` above it, both at ``hinge_radius``, the arms to
        the fly weight at the knee, and the spring round the rod at its length ``d`` under the
        moving collar (its foot fixed: ``l - d`` is the same at every position)."""
        g = self.geometry(float(x))
        r, l, d = float(x), float(g["l"]), float(g["d"])
        rh = self.hinge_radius
        parts = [Part("link", ((rh, 0.0), (r, 0.5 * l), (rh, l))),
                 Part("pivot", ((rh, 0.0),)), Part("pivot", ((rh, l),)),
                 Part("mass", ((r, 0.5 * l),), ball_radius(sd.m))]
        parts = list(mirrored(parts))
        tall = 0.1 * self.arm_length
        for y, kind in ((0.0, "frame"), (l, "sleeve")):  # the fixed and the moving collar
            parts.append(Part(kind, ((-rh, y - tall / 2), (rh, y - tall / 2), (rh, y + tall / 2),
                                     (-rh, y + tall / 2), (-rh, y - tall / 2))))
        width = 2.0 * sd.r if np.isfinite(sd.r) else rh
        parts.append(Part("spring", zigzag((0.0, l - d), (0.0, l), width)))
        low = min(0.0, l - d) - tall
        parts.append(Part("frame", ((0.0, low - 0.2 * self.arm_length),
                                    (0.0, self.spacing_open + 0.3 * self.arm_length))))
        return Drawing(tuple(parts))

    # -- the article's shop methods -------------------------------------------------------------

    def spring_for_speeds(self, m, omega_open, omega_closed):
        """The article's replacement spring (its steps 1-3): the force ``P`` of eq. 1 with the
        throttle just fully open at ``omega_open`` and just closed at ``omega_closed`` (rad/s),
        fly-weight mass ``m`` (kg), then eqs. 3-4: ``(kappa, l0)`` (N/m, m)."""
        g = self.geometry([self.x_inner, self.x_outer])
        P = toggle_spring_force(centrifugal_force(m, np.array([self.x_inner, self.x_outer]),
                                                  np.array([omega_open, omega_closed])),
                                g["l"], g["y"], self.n_weights)
        K, L = spring_rate_and_free_length(P[0], g["d"][0], P[1], g["d"][1])
        return float(K), float(L)

    def fly_mass_for_spring(self, kappa, l0, omega_closed):
        """The article's fly weight from a measured spring: ``P_2 = kappa (l0 - d_2)`` (eq. 3 at
        condition 2, throttle just closed) and eq. 1 solved for the mass (kg)."""
        g = self.geometry(self.x_outer)
        P2 = kappa * (l0 - g["d"])
        return float(P2 * 4.0 * g["y"] / (self.n_weights * g["l"] * self.x_outer
                                          * omega_closed**2))
