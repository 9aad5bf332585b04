"""The textbook's questions at any point and for any unknown (`govopt at`, `govopt solve`, a
ball governor's range by the arm's angle, height, joint radius or lift), each against a hand
calculation from the book's own formulas."""

import json
import math

import pytest
from clirun import invoke

from govopt.examples import SPECS
from govopt.units import G_STANDARD as G

RPM = math.pi / 30.0
PORTER = str(SPECS / "textbook-ex1-porter.toml")
PROELL = str(SPECS / "textbook-ex3-proell.toml")

ANGLES = """name = "porter-angles"
[governor]
type = "porter"
arm = "30 cm"
link = "30 cm"
angle_inner = "30 deg"
angle_outer = "45 deg"
[design]
ball_weight = "6 kgf"
central_weight = "48 kgf"
"""


def _porter_speed(w, W, h, k=1.0):
    """The book's Porter (section 3.4(b), eq. i, equal arms pinned on the axis):
    ``omega^2 = (g / h) (w + W (1 + k) / 2) / w``, rad/s."""
    return math.sqrt(G / h * (w + W * (1.0 + k) / 2.0) / w)


def _json(args):
    run = invoke(args)
    assert run.exit_code == 0, run.stderr
    return json.loads(run.stdout)


def test_a_porter_given_its_arms_angles_gives_both_speeds(tmp_path):
    """Arms of 30 cm at 30 and 45 deg to the axis: h = 30 cos(angle), k = 1; the book's
    formula gives 176.01 and 194.78 rpm (to rounding: the same statics)."""
    spec = tmp_path / "angles.toml"
    spec.write_text(ANGLES, encoding="utf-8")
    char = _json(["evaluate", str(spec), "--json"])["characteristic"]
    for row, angle in ((char[0], 30.0), (char[-1], 45.0)):
        h = 0.3 * math.cos(math.radians(angle))
        assert row["omega_rad_s"] == pytest.approx(_porter_speed(6.0, 48.0, h), rel=1e-12)
    # the same points asked of the bundled Example 1 (radius range 20-25 cm) by --at
    out = _json(["at", str(spec), "--at", "inner", "--at", "angle=45 deg", "--json"])["points"]
    assert out[0]["radius_m"] == pytest.approx(0.3 * 0.5, rel=1e-12)
    assert out[1]["radius_m"] == pytest.approx(0.3 * math.sqrt(0.5), rel=1e-12)
    assert out[1]["speed_rad_s"] == pytest.approx(
        _porter_speed(6.0, 48.0, 0.3 * math.sqrt(0.5)), rel=1e-12)


@pytest.mark.parametrize("point, radius", [
    ("angle=40 deg", 0.3 * math.sin(math.radians(40.0))),     # r = a sin(alpha)
    ("height=20 cm", math.sqrt(0.3**2 - 0.2**2)),              # h = sqrt(a^2 - r^2)
    ("joint_radius=22 cm", 0.22),                              # the ball at the joint
    ("radius=21 cm", 0.21),
])
def test_a_point_by_any_coordinate(point, radius):
    """Example 1's Porter (arms 30 cm on the axis, the ball at the joint)."""
    out = _json(["at", PORTER, "--at", point, "--json"])["points"][0]
    assert out["radius_m"] == pytest.approx(radius, rel=1e-11)


def test_a_lift_counts_from_the_inner_configuration():
    """Example 1: the sleeve pin is at a = b below the pivot per side, so the sleeve's height
    is ``-(sqrt(a^2 - r^2) + sqrt(b^2 - (r - e_s)^2))``; a 5 cm lift from r = 20 cm is the
    radius where that rises by 5 cm (by hand, bisection on the formula)."""
    def z(r):
        return -(math.sqrt(0.09 - r**2) + math.sqrt(0.09 - (r - 0.0376) ** 2))
    lo, hi = 0.2, 0.25
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if z(mid) - z(0.2) < 0.05 else (lo, mid)
    out = _json(["at", PORTER, "--at", "lift=5 cm", "--json"])["points"][0]
    assert out["radius_m"] == pytest.approx(lo, rel=1e-11)
    assert out["lift_m"] == pytest.approx(0.05, rel=1e-11)


def test_the_porters_arm_tension_and_link_force():
    """Example 1 at r = 22 cm: the sleeve hangs on the links, so by hand each link carries
    ``(W/2) / cos(beta)`` and each upper arm ``(w + W/2) / cos(alpha)`` (vertical equilibrium
    of the joint); the pin's force govopt reports comes from the *horizontal* balance at the
    equilibrium speed, so agreement checks the speed as well."""
    out = _json(["at", PORTER, "--at", "radius=22 cm", "--json"])["points"][0]
    sin_a, sin_b = 0.22 / 0.3, (0.22 - 0.0376) / 0.3
    cos_a, cos_b = math.sqrt(1 - sin_a**2), math.sqrt(1 - sin_b**2)
    assert out["arm_tension_N"] == pytest.approx((6 + 24) * G / cos_a, rel=1e-12)
    assert out["pivot_reaction_N"] == out["arm_tension_N"]
    assert out["sleeve_pin_force_N"] == pytest.approx(24 * G / cos_b, rel=1e-12)
    assert out["sleeve_load_N"] == pytest.approx(48 * G, rel=1e-12)
    # the controlling force, the book's [W/2 (1 + k) + w] tan(alpha)
    k = (sin_b / cos_b) / (sin_a / cos_a)
    assert out["controlling_force_N"] == pytest.approx(
        (24 * (1 + k) + 6) * G * sin_a / cos_a, rel=1e-12)


def test_a_proells_extension_for_a_speed():
    """Example 3: 160 rpm at r = 17.5 cm with BG vertical. By hand (section 3.4(c)):
    ``m omega^2 r = (BD/DG) (W/2 (1 + k) + w) tan(alpha)`` with sin(alpha) = (17.5 - 2.5)/25
    = 0.6, k = 1, BD = 25 cos(alpha) = 20 cm, DG = BD + c: c = 20 (28.1 kgf x 0.75) / (m
    omega^2 r) - 20 = 7.1407 cm (the book rounds the force to 15.5 kgf and prints 7.2)."""
    run = _json(["solve", PROELL, "--unknown", "governor.extension", "--target",
                 "speed=160 rpm", "--at", "radius=17.5 cm", "--json"])
    fc = 3.1 * (160 * RPM) ** 2 * 0.175
    by_hand = 0.20 * (28.1 * G * 0.75) / fc - 0.20
    assert run["value"] == pytest.approx(by_hand, rel=1e-10)
    assert run["achieved"] == pytest.approx(160 * RPM, rel=1e-12)
    text = invoke(["solve", PROELL, "--unknown", "governor.extension", "--target",
                   "speed=160 rpm", "--at", "radius=17.5 cm"])
    assert text.exit_code == 0 and text.stdout.startswith("governor.extension = 71.407")


def test_the_sleeve_friction_that_gives_a_range():
    """Example 1 with a sleeve friction R: the range is the outer speed rising (load W + R)
    less the inner falling (W - R), each by the book's ``m omega^2 r = w tan(alpha) + (W +- R)/2
    (tan(alpha) + tan(beta))``; the R govopt finds gives 40 rpm by that hand formula."""
    run = _json(["solve", PORTER, "--unknown", "governor.sleeve_friction", "--target",
                 "range=40 rpm", "--between", "0 N", "200 N", "--json"])
    R = run["value"]

    def speed(r, load):
        ta = r / math.sqrt(0.09 - r**2)
        tb = (r - 0.0376) / math.sqrt(0.09 - (r - 0.0376) ** 2)
        return math.sqrt((6 * G * ta + load / 2 * (ta + tb)) / (6 * r))
    assert speed(0.25, 48 * G + R) - speed(0.20, 48 * G - R) == pytest.approx(40 * RPM,
                                                                              rel=1e-10)


@pytest.mark.parametrize("args, message", [
    (["solve", PORTER, "--unknown", "governor.sleeve_friction", "--target", "range=400 rpm",
      "--between", "0 N", "200 N"], "error: --target range: no governor.sleeve_friction in "
                                    "0 N .. 200 N gives 400 rpm"),
    (["solve", PORTER, "--unknown", "governor.colour", "--target", "speed=1 rpm", "--at",
      "inner"], "error: --unknown governor.colour: not an input"),
    (["solve", PORTER, "--unknown", "governor.arm", "--target", "speed=1 rpm"],
     "error: --target speed: a figure at a point: give the point with --at"),
    (["at", PORTER, "--at", "height=40 cm"], "error: height = 400 mm: the porter governor "
                                             "cannot take it"),
    (["at", PORTER, "--at", "tilt=3 deg"], "error: --at 'tilt=3 deg': expected NAME=VALUE"),
    (["at", PORTER, "--at", "angle=3 cm"], "error: --at 'angle=3 cm': "),
])
def test_questions_without_an_answer_are_one_error_line(args, message):
    run = invoke(args)
    assert run.exit_code == 2 and run.stdout == "", run.stdout
    assert run.stderr.startswith(message), run.stderr
    assert run.stderr.count("\n") == 1


@pytest.mark.parametrize("extra, message", [
    ('radius_inner = "15 cm"\n', "governor.angle_inner: the inner configuration is given "
                                 "twice"),
    ('lift_normal = "50 cm"\n', "governor.lift_normal: the arm and the link cannot take this "
                                "configuration"),
])
def test_a_range_by_another_coordinate_is_checked(tmp_path, extra, message):
    spec = tmp_path / "bad.toml"
    spec.write_text(ANGLES.replace('angle_outer = "45 deg"\n',
                                   'angle_outer = "45 deg"\n' + extra), encoding="utf-8")
    run = invoke(["evaluate", str(spec)])
    assert run.exit_code == 2 and message in run.stderr, run.stderr
