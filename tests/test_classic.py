"""The classic measures (seed textbook 3.2, 3.4(b); Rattan's definitions of effort and power)
through the seam, for every type."""

import math

import pytest
from mproots import polyroots

import govopt
from govopt.units import G_STANDARD

PORTER = {
    "name": "porter-k1",
    "governor": {"type": "porter", "arm": "30 cm", "link": "30 cm", "pivot_offset": "0 cm",
                 "sleeve_offset": "0 cm", "radius_inner": "15 cm", "radius_outer": "25 cm",
                 "sleeve_friction": "2 kgf"},
    "design": {"ball_weight": "6 kgf", "central_weight": "48 kgf"},
}


def test_porter_effort_and_power_match_the_book():
    """Equal arms pinned on the axis (k = 1): the standard effort P = c (w + W) (Rattan; the
    seed chapter has no section on effort) is first order in c; govopt's exact
    ((1 + c)^2 - 1)/2 replaces c, so the ratio is exactly 1 + c/2. Power = P x with the
    sleeve's lift x = 2 h (1 - 1/(1 + c)^2) (h = g (w + W)/(w omega^2) for k = 1)."""
    res = govopt.evaluate(govopt.parse_spec(PORTER))
    cm = res.classic
    c = cm["effort_change"]
    w, W = 6 * G_STANDARD, 48 * G_STANDARD
    assert cm["effort"] == pytest.approx(c * (w + W) * (1 + c / 2), rel=1e-12)
    # power: the sleeve (s = 2 (l - h) for k = 1) lifts 2 dh; with h = g/omega^2 (w+W)/w the
    # height falls by h (1 - 1/(1 + c)^2) for the same speed change (Rattan, the Porter's power)
    gov = res.spec.governor
    r = gov.x_normal
    h = math.sqrt(0.30**2 - r**2)
    lift = 2 * h * (1 - 1 / (1 + c) ** 2)
    assert cm["power"] == pytest.approx(cm["effort"] * lift, rel=1e-9)
    assert cm["stability"] == "stable"


def test_porter_friction_band_matches_the_book():
    """Friction at the sleeve (3.4(b)): rising with W + R, falling with W - R, k = 1:
    omega^2 = (w + W +- R) g / (w h)."""
    res = govopt.evaluate(govopt.parse_spec(PORTER))
    cm, st = res.classic, res.statics
    w, W, R = 6.0, 48.0, 2.0  # kgf
    for i, r in enumerate(st.alpha):
        h = math.sqrt(0.30**2 - r**2)
        for key, load in (("omega_rise_rad_s", W + R), ("omega_fall_rad_s", W - R)):
            want = math.sqrt((w + load) * G_STANDARD / (w * h))
            assert cm[key][i] == pytest.approx(want, rel=1e-12)
    mid = math.sqrt(cm["omega_rise_rad_s"][0] ** 2)
    assert cm["insensitiveness"] > 0 and mid > 0


def test_watt_is_stable_and_shaft_classic_present():
    res = govopt.evaluate(govopt.load_spec("specs/hamabe-a.toml"))
    assert res.classic["stability"] == "stable"
    assert res.classic["sensitiveness"] == pytest.approx(
        2 * (res.statics.omega[-1] - res.statics.omega[0])
        / (res.statics.omega[-1] + res.statics.omega[0]), rel=1e-15)


def test_vyshnegradsky_point_of_the_load_change():
    """A B - 1 is Hamabe's Hurwitz margin (eq. 32), and the region agrees with the roots."""
    import numpy as np

    res = govopt.evaluate(govopt.load_spec("specs/hamabe-a.toml"))
    lc = res.dynamics["load_changes"][0]
    v = lc["vyshnegradsky"]
    assert v["A"] * v["B"] - 1 == pytest.approx(lc["hurwitz_margin"], rel=1e-12)
    roots = np.array([complex(*r) for r in lc["roots_per_s"]])
    assert (v["region"] == "aperiodic") == bool(np.all(np.abs(roots.imag) < 1e-9))


@pytest.mark.parametrize("seed", range(3))
def test_vyshnegradsky_regions_against_roots(seed):
    """Away from the region boundaries, the closed-form region equals the one read from the
    roots of lambda^3 + A lambda^2 + B lambda + 1 (mpmath, 30 digits)."""
    import mpmath
    import numpy as np

    from govopt.analysis.vyshnegradsky import region

    rng = np.random.default_rng(seed)
    mpmath.mp.dps = 30
    for A, B in rng.uniform(0.05, 8.0, size=(300, 2)):
        roots = polyroots([1, A, B, 1], maxsteps=200, extraprec=60)
        if A * B <= 1:
            want = "unstable"
        else:
            cplx = [r for r in roots if abs(mpmath.im(r)) > 1e-20]
            real = [r for r in roots if abs(mpmath.im(r)) <= 1e-20]
            if not cplx:
                want = "aperiodic"
            else:
                gap = abs(mpmath.re(cplx[0])) - abs(mpmath.re(real[0]))
                if abs(gap) < 1e-6:
                    continue  # on the boundary curve
                want = "oscillatory" if gap < 0 else "monotonic"
        assert region(A, B) == want, (A, B)


def test_no_effort_over_a_range_whose_speed_falls():
    """Over the range (``speed_change = "range"``) the effort and power need a speed that
    rises from the innermost configuration to the outermost: a weak spring with a large initial
    load makes the Hartnell's speed fall (unstable), and the effort of a falling speed would be
    a negative force. Not computed, and the report says why; at a fraction it is computed."""
    from govopt.spec import load_spec, with_values

    base = load_spec("specs/textbook-ex4-hartnell.toml")
    falling = with_values(base, {"design.spring_stiffness": "0.1 kgf/cm",
                                 "design.free_length": "40 cm",
                                 "analysis.speed_change": "range"})
    res = govopt.evaluate(falling)
    cm = res.classic
    assert cm["effort_change"] < 0 and cm["stability"] == "unstable"
    assert math.isnan(cm["effort"]) and math.isnan(cm["power"])
    assert "the speed falls over the range" in cm["effort_note"]
    assert res.figure("effort").note == cm["effort_note"]
    assert res.to_dict()["classic"]["effort_N"] is None
    rising = govopt.evaluate(with_values(base, {"analysis.speed_change": "range"})).classic
    assert rising["effort"] > 0 and rising["power"] > 0 and not rising["effort_note"]


def test_power_to_the_stop_when_the_speed_change_passes_the_outermost():
    """A speed change whose equilibrium lies past the outermost configuration moves the member
    to its stop: the power is the effort times the travel to the stop (finite, and less than
    the work over a longer travel), and the report says so; a small change stays inside."""
    from govopt.analysis.classic import travel_between
    from govopt.spec import load_spec, with_values

    base = load_spec("specs/textbook-ex4-hartnell.toml")
    far = govopt.evaluate(with_values(base, {"analysis.speed_change": 0.5}))
    cm, gov = far.classic, far.spec.governor
    x_n = gov.x_normal  # the textbook's Hartnell: normal configuration at mid-range
    assert cm["power_note"].startswith("to the stop: a 50 % speed change")
    assert far.figure("power").note == cm["power_note"]
    assert cm["power"] == pytest.approx(cm["effort"] * travel_between(far.spec, x_n, gov.x_outer),
                                        rel=1e-12)
    near = govopt.evaluate(with_values(base, {"analysis.speed_change": 0.001})).classic
    assert near["power_note"] == "" and math.isfinite(near["power"])
