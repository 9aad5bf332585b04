"""Textbook ch. 3, section 3.5 on the seam: the Hartnell (Examples 4, 5), the governor with the
balls joined by springs (Examples 6, 7) and the spring-and-gravity governor (Example 8).

Units from first principles: the book writes kg for kgf and g = 981 cm/s^2. A ball of "w kg" is
a mass of w kg (govopt turns kgf into mass with standard gravity, so a w kgf ball is exactly w kg)
and its centrifugal force is ``w omega^2 r / 9.80665`` kgf with r in m (``w omega^2 r / 981`` with
r in cm, the book's, is 0.034 % lower: far below its rounding, but not below a difference of two
nearly equal forces, see Example 7).

Every figure of the statics is checked a second way: the virtual-work controlling force of the
modules against moments about the bell crank's fulcrum (section 3.5(a) eq. i, Example 7) or its
instantaneous centre (section 3.5(c) eq. i), taken here from the lever's coordinates.
"""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from govopt.governors import governor_class
from govopt.governors.hartnell import HartnellGovernor
from govopt.governors.spring_gravity import SpringGravityGovernor
from govopt.governors.spring_loaded import SpringLoadedGovernor
from govopt.reader import Reader, SpecError
from govopt.spec import load_spec
from govopt.units import G_STANDARD as G
from govopt.units import parse_quantity

CM = 0.01
KGF = G  # N
KGF_CM = KGF / CM  # N/m
RPM = math.pi / 30.0  # rad/s
SPECS = Path(__file__).resolve().parent.parent / "specs"


def build(cls, **table):
    return cls.parse(Reader("test.toml", table, "governor", []))


def through(gov, m, xs, omegas, central=None):
    """The design spring ``(kappa, l0)`` making ``xs`` equilibria at ``omegas``: the characteristic
    ``omega^2 lever = kappa A - (kappa l0) B + cf`` is linear in ``kappa`` and ``kappa l0``."""
    ts = [gov.terms(x, m, None, central) for x in xs]
    M = np.array([[float(t.A), -float(t.B)] for t in ts])
    rhs = np.array([w**2 * float(t.lever) - float(t.cf) for t, w in zip(ts, omegas, strict=True)])
    kappa, kl0 = np.linalg.solve(M, rhs)
    return kappa, kl0 / kappa


def spring_force(gov, kappa, l0, x):
    """Force in one design spring (N)."""
    A_F, B_F = gov.spring_force_coefficients(x)
    return kappa * (A_F - B_F * l0)


def rpm(gov, m, x, kappa, l0, central=None, friction=0.0):
    return math.sqrt(gov.terms(x, m, None, central).omega_squared(kappa, l0, friction)) / RPM


# -- the lever's coordinates (second way) ------------------------------------------------------

def lever(a, b, r_f, gamma, x, ball_up):
    """Ball and arm end relative to the fulcrum (R outward, z up) at ball radius ``x``."""
    th = np.arcsin((x - r_f) / a)
    up = 1.0 if ball_up else -1.0
    ball = (a * np.sin(th), up * a * np.cos(th))
    end = (-b * np.sin(gamma - th), up * b * np.cos(gamma - th))
    return ball, end


def moment_about_fulcrum(a, b, r_f, gamma, x, w, P):
    """Controlling force F from moments about a fixed fulcrum (Fig. 3.10): ball force (F, -w),
    the collar's push (0, -P) on the roller: ``x_b (-w) - z_b F + x_e (-P) = 0``."""
    (xb, zb), (xe, _) = lever(a, b, r_f, gamma, x, ball_up=True)
    return (-w * xb - P * xe) / zb


def moment_about_instantaneous_centre(a, b, r_f, gamma, x, w, P):
    """Controlling force F from moments about the lever's instantaneous centre I (Fig. 3.12(b)):
    I on the horizontal through O and the vertical through the roller; the pivot's load (0, -P)
    at O, the ball's (F, -w); the cap's reaction and O's horizontal reaction pass through I."""
    (xb, zb), (xe, _) = lever(a, b, r_f, gamma, x, ball_up=False)
    # about I = (xe, 0): (xb - xe)(-w) - zb F + (0 - xe)(-P) = 0
    return (-(xb - xe) * w + xe * P) / zb


def hartnell_lift(b, r_f, a, gamma, x, x_inner):
    """Sleeve lift: the roller's rise (fixed fulcrum)."""
    return lever(a, b, r_f, gamma, x, True)[1][1] - lever(a, b, r_f, gamma, x_inner, True)[1][1]


def gravity_lift(b, r_f, a, gamma, x, x_inner):
    """Sleeve lift: O's rise, the roller running under the fixed cap."""
    return -lever(a, b, r_f, gamma, x, False)[1][1] + lever(a, b, r_f, gamma, x_inner, False)[1][1]


# -- Example 4 (section 3.5(a)) ----------------------------------------------------------------

EX4 = dict(ball_arm="7.5 cm", sleeve_arm="7.5 cm", radius_inner="7.5 cm", radius_outer="12 cm",
           spring_length="10 cm")


def test_example4_hartnell_initial_load_and_stiffness():
    """Balls 2 kgf, equal arms, 7.5-12 cm, 240 rpm then +7 %: S_2 and k (small angle, as the
    book; the arms' length is not given, only their ratio matters then)."""
    gov = build(HartnellGovernor, **EX4, obliquity="small_angle")
    m, r2, r1, w2, w1 = 2.0, 0.075, 0.12, 240 * RPM, 1.07 * 240 * RPM
    kappa, l0 = through(gov, m, [r2, r1], [w2, w1])
    S2, S1 = spring_force(gov, kappa, l0, r2), spring_force(gov, kappa, l0, r1)
    assert S2 / KGF == pytest.approx(19.3, abs=0.05)  # 19.32 kgf; book 19.3
    assert S1 / KGF == pytest.approx(35.38, abs=0.03)  # 35.40 kgf (g = 9.80665); book 35.38
    assert kappa / KGF_CM == pytest.approx(3.57, abs=0.005)  # 3.572 kgf/cm; book 3.57
    # second way, the book's eqs. (i) S = 2 F a/b, (vii) k = 2 (a/b)^2 (F_1 - F_2)/(r_1 - r_2),
    # (viii) initial compression S_2/k
    F2, F1 = m * w2**2 * r2, m * w1**2 * r1
    assert S2 == pytest.approx(2.0 * F2, rel=1e-12)
    assert kappa == pytest.approx(2.0 * (F1 - F2) / (r1 - r2), rel=1e-12)
    assert l0 - gov.spring_length == pytest.approx(S2 / kappa, rel=1e-12)


def test_example4_exact_obliquity_differs_by_the_balls_weight_only():
    """For a 90 deg crank ds/dr = b/a exactly (eq. vi is exact); the exact obliquity adds only
    the balls' weight, -w tan(theta) per ball (the ball stands above the fulcrum)."""
    exact = build(HartnellGovernor, **EX4)
    small = build(HartnellGovernor, **EX4, obliquity="small_angle")
    x = np.linspace(0.075, 0.12, 9)
    assert np.allclose(exact.travel_slope(x), 1.0, rtol=0, atol=1e-15)
    assert np.allclose(exact.sleeve_lift(x), x - 0.075, rtol=0, atol=1e-15)
    theta = np.arcsin((x - 0.0975) / 0.075)
    te, ts = exact.terms(x, 2.0, None, 3.0), small.terms(x, 2.0, None, 3.0)
    np.testing.assert_allclose(te.cf - ts.cf, -2.0 * G * np.tan(theta), rtol=1e-12, atol=1e-12)
    for key in ("A", "B", "A_x", "B_x", "jp", "jpp"):
        np.testing.assert_allclose(getattr(te, key), getattr(ts, key), rtol=1e-12, atol=1e-12)


# -- Example 5 (section 3.5(a), sleeve friction) ----------------------------------------------

def ex5(obliquity):
    return build(HartnellGovernor, ball_arm="15 cm", sleeve_arm="9 cm", radius_inner="10 cm",
                 radius_outer="15 cm", radius_normal="12.5 cm", sleeve_friction="1.5 kgf",
                 spring_length="10 cm", obliquity=obliquity)


def ex5_free_length(gov, m, kappa):
    """150 rpm at the mean radius with the sleeve rising."""
    x = gov.x_normal
    t = gov.terms(x, m)
    return float((kappa * t.A + t.cf + gov.friction(x) - (150 * RPM) ** 2 * t.lever)
                 / (kappa * t.B))


@pytest.mark.parametrize("obliquity", ["small_angle", "exact"])
def test_example5_hartnell_highest_and_lowest_speeds(obliquity):
    gov = ex5(obliquity)
    m, kappa, R, a, b = 2.7, 8 * KGF_CM, 1.5 * KGF, 0.15, 0.09
    l0 = ex5_free_length(gov, m, kappa)
    S = spring_force(gov, kappa, l0, 0.125)
    assert S / KGF == pytest.approx(26.8, abs=0.02)  # 26.81 kgf; book 26.8 (arms vertical: no
    #                                                  weight moment, both fidelities alike)
    assert gov.sleeve_lift(0.15) - gov.sleeve_lift(0.125) == pytest.approx(0.015, rel=1e-12)
    band = gov.friction
    n1 = rpm(gov, m, 0.15, kappa, l0, friction=band(0.15))  # top, sleeve rising
    n2 = rpm(gov, m, 0.10, kappa, l0, friction=-band(0.10))  # bottom, sleeve falling
    S1, S2 = S + kappa * 0.015, S - kappa * 0.015
    if obliquity == "small_angle":  # the book: F_1 a = (S_1 + R)/2 b, F_2 a = (S_2 - R)/2 b
        assert n1 == pytest.approx(163.4, abs=0.05)  # 163.40 rpm; book 163.4
        assert n2 == pytest.approx(115.0, abs=0.05)  # 114.98 rpm; book 115
        F1, F2 = (S1 + R) / 2 * b / a, (S2 - R) / 2 * b / a
    else:  # moments about the fulcrum with the ball's weight, F a cos + w a sin = P b cos
        F1 = moment_about_fulcrum(a, b, 0.125, math.pi / 2, 0.15, m * G, (S1 + R) / 2)
        F2 = moment_about_fulcrum(a, b, 0.125, math.pi / 2, 0.10, m * G, (S2 - R) / 2)
        assert n1 < 163.4 - 2.0 and n2 > 115.0 + 5.0  # the weight helps the balls out
    assert n1 == pytest.approx(math.sqrt(F1 / (m * 0.15)) / RPM, rel=1e-12)
    assert n2 == pytest.approx(math.sqrt(F2 / (m * 0.10)) / RPM, rel=1e-12)


def test_example5_coefficient_of_insensitiveness():
    """Speeds rising and falling at each radius, (N_rise - N_fall)/N_mean: the book's rule
    (section 3.5(a)) changes the spring force S to S + R rising and S - R falling."""
    gov = ex5("small_angle")
    m, kappa, R = 2.7, 8 * KGF_CM, 1.5 * KGF
    l0 = ex5_free_length(gov, m, kappa)
    for x in (0.10, 0.125, 0.15):
        rise = rpm(gov, m, x, kappa, l0, friction=gov.friction(x))
        fall = rpm(gov, m, x, kappa, l0, friction=-gov.friction(x))
        S = spring_force(gov, kappa, l0, x)
        assert fall / rise == pytest.approx(math.sqrt((S - R) / (S + R)), rel=1e-12)
        if x == 0.125:
            assert rise == pytest.approx(150.0, rel=1e-12)
            assert fall == pytest.approx(141.83, abs=0.005)
            assert (rise - fall) / ((rise + fall) / 2) == pytest.approx(0.0560, abs=5e-5)
    assert np.allclose(gov.friction(np.array([0.1, 0.15])), R / 2 * 9 / 15, rtol=1e-12)


# -- Example 6 (section 3.5(b), Fig. 3.11(a)) --------------------------------------------------

EX6 = dict(variant="direct", ball_arm="7.5 cm", sleeve_arm="7.5 cm", obliquity="small_angle",
           radius_inner="8.5 cm", radius_normal="10 cm", radius_outer="11.5 cm",
           spring_length="15 cm")


def test_example6_balls_joined_by_springs():
    """Two springs of 0.9 kgf/cm each, extended 6.5 cm at r = 10 cm (spring_length 15 cm at
    8.5 cm, so l0 = 15 - 3.5 cm); balls of 1 kgf."""
    gov = build(SpringLoadedGovernor, **EX6)
    kappa, l0, m = 0.9 * KGF_CM, 0.115, 1.0
    t = gov.terms(np.array([0.10, 0.115]), m)
    # second way, eq. (i) S = F: the spring force on each ball is 2 x 0.9 x (extension)
    np.testing.assert_allclose(t.restoring(kappa, l0) / KGF, [11.7, 17.1], rtol=1e-12)
    omega = np.sqrt(t.omega_squared(kappa, l0))
    np.testing.assert_allclose(omega**2 * m * np.array([0.10, 0.115]), [11.7 * KGF, 17.1 * KGF],
                               rtol=1e-12)
    # mid: 33.87 rad/s, 323.5 rpm. The book rounds omega to 34 rad/s before converting and
    # prints 324 rpm (34 x 60/2 pi = 324.7); with its own g = 981, 323.5 rpm all the same.
    assert omega[0] == pytest.approx(33.87, abs=0.005)
    assert omega[0] / RPM == pytest.approx(323.5, abs=0.05)
    # 23 cm circle: 38.19 rad/s, 364.7 rpm. The book prints omega' = 37.2 rad/s, a slip for 38.2
    # (17.1 x 981/11.5 = 1458.7 = 38.19^2; 37.2 rad/s would be 355 rpm), and N' = 364 (364.65).
    assert omega[1] == pytest.approx(38.19, abs=0.005)
    assert omega[1] / RPM == pytest.approx(364.65, abs=0.01)
    # eqs. (ii), (iii): the springs back from the two equilibria
    k_back, l0_back = through(gov, m, [0.10, 0.115], omega)
    assert k_back == pytest.approx(kappa, rel=1e-10)
    assert l0_back == pytest.approx(l0, rel=1e-10)
    A_F, B_F = gov.spring_force_coefficients(0.10)
    assert A_F - B_F * l0 == pytest.approx(0.065, rel=1e-12)  # extended 6.5 cm at mid


# -- Example 7 (section 3.5(b), Fig. 3.11(b)) --------------------------------------------------

EX7 = dict(variant="lever", ball_arm="11 cm", sleeve_arm="11 cm", radius_inner="15 cm",
           radius_outer="17 cm", ball_springs=2, ball_spring_stiffness="8 kgf/cm",
           ball_spring_tension="110 kgf", lever_spring_arm="20 cm", lever_sleeve_arm="30 cm",
           spring_length="25 cm")


def test_example7_supplementary_spring_through_a_lever():
    gov = build(SpringLoadedGovernor, **EX7, obliquity="small_angle")
    m, x0, x1, w0, w1 = 5.45, 0.15, 0.17, 600 * RPM, 630 * RPM
    kappa, l0 = through(gov, m, [x0, x1], [w0, w1])
    P0, P1 = spring_force(gov, kappa, l0, x0), spring_force(gov, kappa, l0, x1)
    assert P0 / KGF == pytest.approx(327.0, abs=0.5)  # 327.3 kgf; book 327
    # 381.6 kgf; the book prints "S_1 = 250 x 30/20 = 381" (250 a slip for its own W_1 = 254)
    # and "the total spring force ... 2 x 142 = 248 kg" (for 284, which it then uses).
    assert P1 / KGF == pytest.approx(381.0, abs=0.7)
    # 40.75 kgf/cm; the book's 40.5 rounds the centrifugal forces to 329 and 411 kgf before the
    # difference (411 - 329) - (284 - 220) = 18 kgf: unrounded 18.08 kgf with its g = 981
    # (40.68 kgf/cm) and 18.11 kgf with g_n = 9.80665 m/s^2, the kgf's own (40.75 kgf/cm).
    assert kappa / KGF_CM == pytest.approx(40.75, abs=0.005)
    # second way, the book's moments: about the bell crank's fulcrum (W/2) b = (F - 2 T_A) a,
    # about the lever's pivot S y = W (x + y); the spring B stretches (2/3) of the lift
    F0, F1 = m * w0**2 * x0, m * w1**2 * x1
    T0, T1 = 110 * KGF, (110 + 8 * 4) * KGF  # spring A lengthens 2 x 2 cm
    W0, W1 = 2 * (F0 - 2 * T0), 2 * (F1 - 2 * T1)
    assert P0 == pytest.approx(W0 * 30 / 20, rel=1e-12)
    assert P1 == pytest.approx(W1 * 30 / 20, rel=1e-12)
    assert kappa == pytest.approx((P1 - P0) / (2 * CM * 20 / 30), rel=1e-12)


# -- Example 8 (section 3.5(c), Figs. 3.12, 3.13) ----------------------------------------------

EX8 = dict(ball_arm="15 cm", roller_arm="7.5 cm", radius_inner="10 cm", radius_outer="11.26 cm",
           spring_length="12 cm")


def test_example8_spring_and_gravity():
    gov = build(SpringGravityGovernor, **EX8)
    m, M, x0, x1, w0, w1 = 2.4, 12.0, 0.10, 0.1126, 240 * RPM, 265 * RPM
    assert gov.sleeve_lift(x1) == pytest.approx(0.0063, rel=1e-12)
    kappa, l0 = through(gov, m, [x0, x1], [w0, w1], central=M)
    S0, S1 = spring_force(gov, kappa, l0, x0), spring_force(gov, kappa, l0, x1)
    assert S0 / KGF == pytest.approx(45.0, abs=0.05)  # 45.03 kgf; book 45
    # 67.28 kgf; the book's 67.4 comes from F_1 = 21.25 kgf, but 2.4/981 x 11.26 x 27.75^2 =
    # 21.21 kgf (21.22 with g_n), and its printed moment equation drops the arm OI = 7.47 cm
    assert S1 / KGF == pytest.approx(67.28, abs=0.01)
    # 35.31 kgf/cm; the book prints (67.5 - 45)/0.63 = 35.4 (that quotient is 35.71; its own
    # 67.4 would give 35.56)
    assert kappa / KGF_CM == pytest.approx(35.31, abs=0.005)
    # initial compression 1.276 cm; the book's 1.27 = 45/35.4
    assert (l0 - gov.spring_length) / CM == pytest.approx(1.276, abs=0.001)
    assert l0 - gov.spring_length == pytest.approx(S0 / kappa, rel=1e-12)
    # second way, the book's moments about I (Fig. 3.13): at minimum speed I is the roller's
    # centre, F 15 = (w + (W + S)/2) 7.5; at 0.63 cm lift OI = sqrt(7.5^2 - 0.63^2),
    # CK = sqrt(15^2 - 1.26^2), KI = OI + 1.26
    w, W = m * G, M * G
    assert m * w0**2 * x0 * 0.15 == pytest.approx((w + (W + S0) / 2) * 0.075, rel=1e-12)
    OI, CK = math.sqrt(0.075**2 - 0.0063**2), math.sqrt(0.15**2 - 0.0126**2)
    KI = OI + 0.0126
    assert m * w1**2 * x1 * CK == pytest.approx(w * KI + (W + S1) / 2 * OI, rel=1e-12)


def test_example8_small_angle_keeps_the_minimum_speed_figure():
    """``small_angle``: CK = a, OI = KI = b at every radius (the book's Fig. 3.13 uses the exact
    figure at the top, so only the bottom agrees)."""
    exact = build(SpringGravityGovernor, **EX8)
    small = build(SpringGravityGovernor, **EX8, obliquity="small_angle")
    m, M, kappa, l0 = 2.4, 12.0, 35.31 * KGF_CM, 0.13276
    te, ts = exact.terms(0.10, m, None, M), small.terms(0.10, m, None, M)
    assert ts.restoring(kappa, l0) == pytest.approx(te.restoring(kappa, l0), rel=1e-12)
    x = 0.1126
    S = spring_force(small, kappa, l0, x)
    assert small.terms(x, m, None, M).restoring(kappa, l0) == pytest.approx(
        (m * G + (M * G + S) / 2) * 0.075 / 0.15, rel=1e-12)
    # the exact figure adds the weight's arm a sin(theta) to KI: w tan(theta) more
    theta = math.asin(0.0126 / 0.15)
    assert exact.terms(x, m, None, M).restoring(kappa, l0) - \
        small.terms(x, m, None, M).restoring(kappa, l0) == pytest.approx(m * G * math.tan(theta),
                                                                         rel=1e-12)


# -- statics a second way, over the range, non-book geometry too ------------------------------

CASES = [
    # (class, governor table, m, central, kappa, l0)
    (HartnellGovernor, dict(ball_arm="15 cm", sleeve_arm="9 cm", radius_inner="10 cm",
                            radius_outer="15 cm", radius_normal="12.5 cm", spring_length="10 cm"),
     2.7, 3.0, 8 * KGF_CM, 0.1185),
    (HartnellGovernor, dict(ball_arm="12 cm", sleeve_arm="8 cm", radius_inner="9 cm",
                            radius_outer="14 cm", fulcrum_radius="10.5 cm", crank_angle="105 deg",
                            spring_length="8 cm"),
     2.0, 5.0, 6 * KGF_CM, 0.10),
    (SpringGravityGovernor, EX8, 2.4, 12.0, 35.31 * KGF_CM, 0.13276),
    (SpringGravityGovernor, dict(ball_arm="12.7 cm", roller_arm="5.08 cm", radius_inner="6.35 cm",
                                 radius_outer="8 cm", fulcrum_radius="7 cm", crank_angle="100 deg",
                                 spring_length="8 cm"),
     1.362, 4.54, 10 * KGF_CM, 0.095),
    (SpringLoadedGovernor, dict(EX7, fulcrum_radius="15.5 cm"), 5.45, 4.0, 40.75 * KGF_CM,
     0.16968),
    (SpringLoadedGovernor, dict(EX6, obliquity="exact", crank_angle="95 deg"), 1.0, 2.0,
     0.9 * KGF_CM, 0.115),
]


def second_way(gov, m, central, kappa, l0, x):
    """The controlling force from moments on the lever's coordinates (not the modules' algebra).
    Small angle: the book's fixed arms (F a = P b, F a = (w + P) b)."""
    c = gov.crank
    a, b, r_f, gamma = c.ball_arm, c.sleeve_arm, c.fulcrum_radius, c.crank_angle
    gravity = isinstance(gov, SpringGravityGovernor)
    lift = (gravity_lift if gravity else hartnell_lift)(b, r_f, a, gamma, x, gov.x_inner)
    if c.obliquity == "small_angle":
        lift = b / a * (x - gov.x_inner)
    w, W = m * G, central * G
    if isinstance(gov, SpringLoadedGovernor) and gov.variant == "lever":
        P_b = kappa * (gov.spring_length + gov.lever_ratio * lift - l0)  # spring B, tension
        sleeve, fixed = W + gov.lever_ratio * P_b, gov.ball_springs * (
            gov.ball_spring_tension + 2 * gov.ball_spring_stiffness * (x - gov.x_inner))
    elif isinstance(gov, SpringLoadedGovernor):
        sleeve = W
        fixed = gov.ball_springs * kappa * (gov.spring_length + 2 * (x - gov.x_inner) - l0)
    else:  # compression spring on the sleeve
        sleeve, fixed = W + kappa * (l0 - (gov.spring_length - lift)), 0.0
    P = sleeve / 2
    if c.obliquity == "small_angle":
        return fixed + ((w + P) if gravity else P) * b / a
    moment = moment_about_instantaneous_centre if gravity else moment_about_fulcrum
    return fixed + moment(a, b, r_f, gamma, x, w, P)


@pytest.mark.parametrize("obliquity", ["exact", "small_angle"])
@pytest.mark.parametrize("case", range(len(CASES)))
def test_virtual_work_matches_moments(case, obliquity):
    cls, table, m, central, kappa, l0 = CASES[case]
    if obliquity == "small_angle" and "crank_angle" in table:
        return  # the book's simplification needs a 90 deg crank (a parse error, tested below)
    gov = build(cls, **dict(table, obliquity=obliquity))
    x = np.linspace(gov.x_inner, gov.x_outer, 11)
    Q = gov.terms(x, m, None, central).restoring(kappa, l0)
    expected = np.array([second_way(gov, m, central, kappa, l0, xi) for xi in x])
    np.testing.assert_allclose(Q, expected, rtol=1e-12, atol=1e-12 * np.max(np.abs(expected)))


# -- derivatives, k^2 and the inertia ----------------------------------------------------------

def central_difference(f, x, h):
    return (f(x + h) - f(x - h)) / (2.0 * h)


@pytest.mark.parametrize("obliquity", ["exact", "small_angle"])
@pytest.mark.parametrize("case", range(len(CASES)))
def test_k2_against_finite_differences(case, obliquity):
    cls, table, m, central, kappa, l0 = CASES[case]
    if obliquity == "small_angle" and "crank_angle" in table:
        return
    gov = build(cls, **dict(table, obliquity=obliquity))
    x = np.linspace(gov.x_inner, gov.x_outer, 7)
    h = 1e-5 * (gov.x_outer - gov.x_inner)

    def terms(y):
        return gov.terms(y, m, None, central)

    t = terms(x)
    for f, f_x in (("cf", "cf_x"), ("A", "A_x"), ("B", "B_x"), ("jp", "jpp")):
        fd = central_difference(lambda y, f=f: getattr(terms(y), f), x, h)
        scale = np.max(np.abs(fd)) + np.max(np.abs(getattr(t, f))) / (gov.x_outer - gov.x_inner)
        np.testing.assert_allclose(getattr(t, f_x), fd, rtol=0, atol=1e-7 * scale)
    np.testing.assert_allclose(gov.travel_slope(x), central_difference(gov.sleeve_lift, x, h),
                               rtol=1e-8)
    omega2 = t.omega_squared(kappa, l0)
    assert np.all(omega2 > 0)
    Ik2 = t.stiffness(kappa, l0, omega2)
    # d/dx [restoring - omega^2 lever] at constant speed
    net = central_difference(lambda y: terms(y).restoring(kappa, l0)
                             - omega2 * terms(y).lever, x, h)
    scale = np.abs(t.cf_x) + np.abs(kappa * (t.A_x - t.B_x * l0)) + omega2 * t.jpp
    np.testing.assert_allclose(Ik2, net, rtol=0, atol=1e-7 * np.max(scale))
    # along the equilibrium curve: I k^2 = lever d(omega^2)/dx
    slope = central_difference(lambda y: terms(y).omega_squared(kappa, l0), x, h)
    np.testing.assert_allclose(Ik2, t.lever * slope, rtol=0, atol=1e-7 * np.max(scale))
    k2 = Ik2 / gov.inertia(x, m, central)
    assert np.all(np.isfinite(k2))


@pytest.mark.parametrize("case", range(len(CASES)))
def test_inertia_is_the_kinetic_energy_of_balls_and_sleeve(case):
    """``I = m |d(ball)/dr|^2 + (M/2) (ds/dr)^2`` with the ball's height from the lever's
    coordinates (it tilts with the arm) and the lift from them too."""
    cls, table, m, central, *_ = CASES[case]
    gov = build(cls, **table)
    c = gov.crank
    a, b, r_f, gamma = c.ball_arm, c.sleeve_arm, c.fulcrum_radius, c.crank_angle
    gravity = isinstance(gov, SpringGravityGovernor)
    lift = gravity_lift if gravity else hartnell_lift

    def ball_height(y):
        z = lever(a, b, r_f, gamma, y, ball_up=not gravity)[0][1]
        return z + (lift(b, r_f, a, gamma, y, gov.x_inner) if gravity else 0.0)

    x = np.linspace(gov.x_inner, gov.x_outer, 5)
    h = 1e-5 * (gov.x_outer - gov.x_inner)
    dz = central_difference(ball_height, x, h)
    ds = central_difference(lambda y: lift(b, r_f, a, gamma, y, gov.x_inner), x, h)
    np.testing.assert_allclose(gov.inertia(x, m, central),
                               m * (1 + dz**2) + central / 2 * ds**2, rtol=1e-8)
    np.testing.assert_allclose(gov.sleeve_lift(x), lift(b, r_f, a, gamma, x, gov.x_inner),
                               rtol=1e-12, atol=1e-15)


# -- the springs' force and the friction band ---------------------------------------------------

def test_spring_force_coefficients_match_the_generalised_force():
    """One spring's force F = kappa (A_F - B_F l0) does the spring's share of the virtual work:
    compression on the sleeve F ds/dr / 2; two ball springs 2 F; spring B rho F ds/dr / 2."""
    x = np.linspace(0.15, 0.17, 5)
    kappa, l0 = 40.75 * KGF_CM, 0.16968
    lev = build(SpringLoadedGovernor, **EX7)
    t = lev.terms(x, 5.45)
    F = spring_force(lev, kappa, l0, x)
    np.testing.assert_allclose(kappa * (t.A - t.B * l0),
                               lev.lever_ratio * F * lev.travel_slope(x) / 2, rtol=1e-12)
    direct = build(SpringLoadedGovernor, **EX6)
    t = direct.terms(x - 0.05, 1.0)
    np.testing.assert_allclose(kappa * (t.A - t.B * l0),
                               2 * spring_force(direct, kappa, l0, x - 0.05), rtol=1e-12)
    ex8 = build(SpringGravityGovernor, **EX8)
    y = np.linspace(0.10, 0.1126, 5)
    t = ex8.terms(y, 2.4)
    F = spring_force(ex8, 35.31 * KGF_CM, 0.13276, y)
    assert np.all(F > 0)  # compressed
    np.testing.assert_allclose(35.31 * KGF_CM * (t.A - t.B * 0.13276),
                               F * ex8.travel_slope(y) / 2, rtol=1e-12)


# -- parsing ------------------------------------------------------------------------------------

@pytest.mark.parametrize("cls, table, message", [
    (HartnellGovernor, dict(EX4, ball_arm="2 cm"), "cannot reach"),
    (HartnellGovernor, dict(EX4, obliquity="small_angle", crank_angle="100 deg"), "90 deg"),
    (HartnellGovernor, dict(EX4, sleeve_arm="15 cm"), "crosses the axis"),
    (HartnellGovernor, dict(EX4, spring_length="4 cm"), "close up"),
    (HartnellGovernor, dict(EX4, radius_outer="7 cm"), "radius_inner < radius_outer"),
    (HartnellGovernor, dict(EX4, colour="red"), "unknown key"),
    (HartnellGovernor, dict(EX4, obliquity="series"), "expected one of"),
    (SpringGravityGovernor, {**{k: v for k, v in EX8.items() if k != "roller_arm"},
                             "sleeve_arm": "7.5 cm"}, "roller_arm: missing"),
    (SpringLoadedGovernor, dict(EX6, lever_spring_arm="20 cm"), "variant = \"lever\""),
    (SpringLoadedGovernor, dict(EX6, ball_springs=1.5), "whole number"),
    (SpringLoadedGovernor, {k: v for k, v in EX7.items() if k != "ball_spring_tension"},
     "ball_spring_tension: missing"),
])
def test_parse_errors(cls, table, message):
    with pytest.raises(SpecError, match=message):
        build(cls, **table)


def test_registry_and_class_attributes():
    for name, cls, spring in (("hartnell", HartnellGovernor, "compression"),
                              ("spring_loaded", SpringLoadedGovernor, "tension"),
                              ("spring_gravity", SpringGravityGovernor, "compression")):
        assert governor_class(name) is cls
        assert cls.type_name == name and cls.spring == spring
        assert cls.coordinate == "length" and cls.coordinate_name == "ball radius"
        assert cls.mass_key == "ball" and "section 3.5" in cls.title


# -- the example specs ---------------------------------------------------------------------------

def spec_parts(name):
    """The example spec's governor (through the type's parse) and its [design] values (SI)."""
    data = tomllib.loads((SPECS / name).read_text())
    table = {k: v for k, v in data["governor"].items() if k != "type"}
    gov = governor_class(data["governor"]["type"]).parse(Reader(name, table, "governor", []))
    design = data["design"]
    mass = parse_quantity(design["ball_weight"], "force") / G
    central = parse_quantity(design["central_weight"], "force") / G \
        if "central_weight" in design else None
    return (gov, mass, central, parse_quantity(design["spring_stiffness"], "stiffness"),
            parse_quantity(design["free_length"], "length"), data)


@pytest.mark.parametrize("name, x, expected_rpm, tol", [
    ("textbook-ex4-hartnell.toml", 0.075, 240.0, 0.05),
    ("textbook-ex4-hartnell.toml", 0.12, 256.8, 0.05),
    ("textbook-ex6-spring_loaded.toml", 0.10, 323.46, 0.02),
    ("textbook-ex6-spring_loaded.toml", 0.115, 364.65, 0.02),
    ("textbook-ex7-spring_loaded.toml", 0.15, 600.0, 0.05),
    ("textbook-ex7-spring_loaded.toml", 0.17, 630.0, 0.05),
    ("textbook-ex8-spring_gravity.toml", 0.10, 240.0, 0.05),
    ("textbook-ex8-spring_gravity.toml", 0.1126, 265.0, 0.05),
])
def test_example_specs_reproduce_their_speeds(name, x, expected_rpm, tol):
    gov, m, central, kappa, l0, data = spec_parts(name)
    assert rpm(gov, m, x, kappa, l0, central) == pytest.approx(expected_rpm, abs=tol)
    if "speed" in data:
        speeds = [parse_quantity(data["speed"][k], "angular_velocity") / RPM
                  for k in ("inner", "outer")]
        inner = math.isclose(x, gov.x_inner, rel_tol=1e-12)
        assert expected_rpm == pytest.approx(speeds[0 if inner else 1], rel=1e-9)


def test_example5_spec_reproduces_the_book():
    gov, m, _, kappa, l0, _ = spec_parts("textbook-ex5-hartnell.toml")
    assert rpm(gov, m, 0.125, kappa, l0, friction=gov.friction(0.125)) == pytest.approx(150.0,
                                                                                          abs=0.01)
    assert rpm(gov, m, 0.15, kappa, l0, friction=gov.friction(0.15)) == pytest.approx(163.4,
                                                                                        abs=0.05)
    assert rpm(gov, m, 0.10, kappa, l0, friction=-gov.friction(0.10)) == pytest.approx(115.0,
                                                                                         abs=0.05)


@pytest.mark.parametrize("name", [
    "textbook-ex4-hartnell.toml", "textbook-ex5-hartnell.toml", "textbook-ex6-spring_loaded.toml",
    "textbook-ex7-spring_loaded.toml", "textbook-ex8-spring_gravity.toml"])
def test_example_specs_load(name):
    spec = load_spec(SPECS / name)
    assert spec.governor.type_name == spec.governor_type
