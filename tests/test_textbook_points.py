"""The textbook's questions at any point and for any unknown (`govopt at`, `govopt solve`, a
ball governor's range by the arm's angle, height, joint radius or lift), each against a hand
calculation from the book's own formulas."""

import json
import math
from pathlib import Path

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


def _json(args, codes=(0,)):
    """The command's JSON; ``codes``: the exit codes it may end with (1: a check failed)."""
    run = invoke(args)
    assert run.exit_code in codes, run.stderr
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


HARTNELL = (SPECS / "textbook-ex4-hartnell.toml").read_text(encoding="utf-8")


def _hartnell(tmp_path, *changes, drop=("spring_stiffness", "free_length")):
    text = HARTNELL
    for old, new in changes:
        assert old in text, old
        text = text.replace(old, new)
    lines = [ln for ln in text.splitlines() if not ln.startswith(drop)]
    path = tmp_path / "hartnell.toml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return str(path)


def test_a_hartnell_with_the_balls_below_the_fulcrum(tmp_path):
    """Example 4's governor hung upside down (exact levers, the fulcrum at the mid radius 9.75
    cm, a = b = 7.5 cm): moments about the fulcrum give ``F a cos(theta) = w a sin(theta) +
    (S/2) b cos(theta)``, so ``S = 2 (F - w tan(theta))`` with sin(theta) = -0.3 and 0.3 at
    the ends; the lift ``b (sin theta_o - sin theta_i) = 4.5 cm``, the stiffness ``(S_o -
    S_i) / lift`` and the initial compression ``S_i / kappa``."""
    spec = _hartnell(tmp_path, ('obliquity = "small_angle"', 'ball_position = "below"'))
    out = _json(["evaluate", spec, "--json"])
    w, tan = 2 * G, 0.3 / math.sqrt(1 - 0.09)
    S_i = 2 * (2 * (240 * RPM) ** 2 * 0.075 + w * tan)
    S_o = 2 * (2 * (256.8 * RPM) ** 2 * 0.12 - w * tan)
    kappa = (S_o - S_i) / 0.045
    found = out["band_spring"]
    assert found["stiffness_N_per_m"] == pytest.approx(kappa, rel=1e-12)
    assert found["force_inner_N"] == pytest.approx(S_i, rel=1e-12)
    assert found["free_length_m"] - 0.10 == pytest.approx(S_i / kappa, rel=1e-12)
    # the weights now resist the balls: the same spring above the fulcrum runs faster inside
    assert out["classic"]["stability"] == "stable"


def test_a_falling_speed_pair_is_evaluated_and_unstable(tmp_path):
    """430 rpm at the inner end, 415 at the outer (a maladjusted Hartnell): the spring that
    does it (small-angle statics, a = b: ``S = 2 m omega^2 r``, kappa = (S_o - S_i) / 4.5 cm)
    is found and the governor reported unstable, exit 1 (checks fail), not refused."""
    spec = _hartnell(tmp_path, ('inner = "240 rpm"', 'inner = "430 rpm"'),
                     ('outer = "256.8 rpm"', 'outer = "415 rpm"'))
    run = invoke(["evaluate", spec, "--json"])
    assert run.exit_code == 1, run.stderr
    out = json.loads(run.stdout)
    S_i, S_o = (4 * (n * RPM) ** 2 * r for n, r in ((430, 0.075), (415, 0.12)))
    assert out["band_spring"]["stiffness_N_per_m"] == pytest.approx((S_o - S_i) / 0.045,
                                                                    rel=1e-12)
    assert out["classic"]["stability"] == "unstable"
    failed = {c["name"] for c in out["checks"] if not c["passed"]}
    assert "characteristic rises (stable)" in failed


def test_insensitiveness_at_each_end_and_the_largest(tmp_path):
    """Example 4 with a sleeve friction R = 1 kgf: the band per ball ``(R/2) (b/a)`` against
    the controlling force ``m omega^2 r``, so at each end ``(omega_r - omega_f) / omega`` with
    ``omega_r,f^2 = omega^2 (1 +- (R/2) / (m omega^2 r))``; the largest is the inner end's."""
    spec = _hartnell(tmp_path, ('spring_length = "10 cm"',
                                'spring_length = "10 cm"\nsleeve_friction = "1 kgf"'), drop=())
    classic = _json(["evaluate", spec, "--json"], codes=(0, 1))["classic"]
    ends = {}
    for end, r in (("inner", 0.075), ("outer", 0.12)):
        w = _json(["at", spec, "--at", end, "--json"])["points"][0]["speed_rad_s"]
        f = 0.5 * G / (2 * w**2 * r)
        ends[end] = math.sqrt(1 + f) - math.sqrt(1 - f)
        assert classic[f"insensitiveness_{end}"] == pytest.approx(ends[end], rel=1e-9)
    assert classic["insensitiveness"] == pytest.approx(max(ends.values()), rel=1e-9)


def test_the_hartnells_fulcrum_reaction():
    """Example 4 (small-angle statics) at r = 10 cm: the spring's force S there, the collar's
    force on each roller S/2, and the fulcrum holds ``m omega^2 r`` across and ``w + S/2``
    along the axis."""
    out = _json(["at", str(SPECS / "textbook-ex4-hartnell.toml"), "--at", "radius=10 cm",
                 "--json"])["points"][0]
    S = out["spring_force_N"]
    assert out["roller_force_N"] == pytest.approx(S / 2, rel=1e-12)
    centrifugal = 2 * out["speed_rad_s"] ** 2 * 0.10
    assert centrifugal == pytest.approx(S / 2, rel=1e-12)  # F a = (S/2) b, a = b
    assert out["fulcrum_reaction_N"] == pytest.approx(math.hypot(centrifugal, 2 * G + S / 2),
                                                      rel=1e-12)


def test_the_initial_compression_that_makes_a_hartnell_isochronous(tmp_path):
    """Example 4 (small-angle statics, a = b): the controlling force per ball is S/2 with
    ``S = kappa (l0 - L + (r - r_i))``, a line through the origin (isochronous) exactly when
    ``l0 = L + r_i = 10 + 7.5 = 17.5 cm``; evaluated there the governor is isochronous."""
    run = _json(["solve", str(SPECS / "textbook-ex4-hartnell.toml"), "--unknown",
                 "design.free_length", "--target", "range=0 rpm", "--json"])
    assert run["value"] == pytest.approx(0.175, rel=1e-12)
    text = HARTNELL.replace('free_length = "15.41 cm"', 'free_length = "17.5 cm"')
    spec = tmp_path / "iso.toml"
    spec.write_text(text, encoding="utf-8")
    assert _json(["evaluate", str(spec), "--json"], codes=(1,))["classic"]["stability"] == \
        "isochronous"


def test_bench_has_every_type_against_a_reference_on_a_hard_case():
    """`govopt bench` measures each of the types: the stored table (the last full run) has
    its statics and its solve rows, each error finite; run now, the Watt's exact model agrees
    with the book's closed form ``omega^2 = g / h`` (mpmath) on arms from near the axis to near
    90 deg, and the Porter's k = 1 shortcut is far off there (the sleeve pins off the axis)."""
    from govopt.bench import report, suites
    from govopt.governors import REGISTRY

    stored = report.read_csv(Path(suites.__file__).parents[1] / "data" / "speed-vs-error.csv")
    for gtype in REGISTRY:
        for part in ("statics", "solve"):
            rows = [p for p in stored if p.analysis == f"{gtype}: {part}"]
            assert rows and all(math.isfinite(p.error) for p in rows), (gtype, part)
    live = {(p.analysis, p.setting): p for p in suites.types_suite(True, ("watt", "porter"))}
    assert live[("watt: statics", "exact")].error < 1e-14
    assert live[("porter: statics", "unity")].error > 0.1
    for rtol in (1e-6, 1e-12):  # Brent's tolerance on the input bounds its error
        assert live[("porter: solve", f"rtol {rtol:g}")].error < 10 * rtol


LINE = """name = "line"
[governor]
type = "force_line"
force_slope = "2.4 N/mm"
force_intercept = "{b}"
radius_inner = "10 cm"
radius_outer = "15 cm"
[design]
ball_weight = "5 kgf"
"""


@pytest.mark.parametrize("b, stability", [("-60 N", "stable"), ("0 N", "isochronous"),
                                          ("60 N", "unstable")])
def test_a_governor_given_by_its_controlling_force_line(tmp_path, b, stability):
    """F = 2.4 r - 60 N per ball (r in mm), 5 kg balls: by hand ``omega^2 = (a r + b) / (m r)``
    at the ends; stable for b < 0, isochronous for b = 0, unstable for b > 0 (textbook 3.2)."""
    spec = tmp_path / "line.toml"
    spec.write_text(LINE.format(b=b), encoding="utf-8")
    out = _json(["evaluate", str(spec), "--json"], codes=(0, 1))
    bb = float(b.split()[0])
    for row, r in ((out["characteristic"][0], 0.10), (out["characteristic"][-1], 0.15)):
        assert row["omega_rad_s"] == pytest.approx(math.sqrt((2400 * r + bb) / (5 * r)),
                                                   rel=1e-12)
    assert out["classic"]["stability"] == stability


def test_the_intercept_that_makes_a_force_line_isochronous(tmp_path):
    """Solved for a range of 0 the intercept is 0 (to the solver's tolerance of the bracket)."""
    spec = tmp_path / "line.toml"
    spec.write_text(LINE.format(b="-60 N"), encoding="utf-8")
    run = _json(["solve", str(spec), "--unknown", "governor.force_intercept", "--target",
                 "range=0 rpm", "--between", "-100 N", "50 N", "--json"])
    assert abs(run["value"]) < 1e-9
