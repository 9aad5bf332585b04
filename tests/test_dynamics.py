"""Dynamics through the evaluator: Example 3 via the bundled specs, k^2 cases, JSON keys."""

import dataclasses
import json

import numpy as np
import pytest
from clirun import invoke
from transient_one import analyse_one

import govopt
from govopt.analysis.transient_cubic import hamabe_initial_conditions

PAPER = {"geometry": "series", "reaction_speed": "mean", "reaction_slope": False}


def paper_result(case):
    spec = govopt.load_spec(f"specs/hamabe-{case}.toml")
    return govopt.evaluate(spec.with_analysis(**PAPER))


@pytest.mark.parametrize(("case", "over"), [("a", False), ("b", False), ("c", False),
                                            ("d", True)])
def test_over_regulation_as_the_paper_says(case, over):
    """Example 3 with the paper's model and dash-pots (a1 = 24, 24, 15, 30): no over-regulation
    for a, b, c; over-regulation for d (one fast real root and a slow complex pair)."""
    lc = paper_result(case).dynamics["load_changes"][0]
    assert lc["stable"]
    assert (lc["over_regulation_rad"] > 1e-6) is over
    if case == "d":
        assert lc["kind"] == "complex"


@pytest.mark.parametrize(("case", "paper_roots"), [
    ("a", [-29.1, -10.0, -1.7]), ("b", [-41.2, -5.46, -2.2]), ("c", [-27.9, -8.48, -2.1])])
def test_example3_roots_from_the_specs(case, paper_roots):
    """The roots from govopt's own k^2 and a3 (not the paper's rounded ones) within 10 %.

    The differences (up to ~9 % on b's middle root) come from the paper's rounded k^2 (330 vs
    our 332), omega0^2 = 630 vs 631.65 and its a3 = 840 vs our 836 for case a; the roots with
    the paper's own coefficients are checked to the paper's digits in test_transient.py.
    """
    lc = paper_result(case).dynamics["load_changes"][0]
    roots = sorted(r for r, i in lc["roots_per_s"])
    np.testing.assert_allclose(roots, sorted(paper_roots), rtol=0.10)


def test_d_prime_paper_slip():
    """d': the paper's k^2 = 233 is a slip; its own spring gives k^2 = 311.

    With 233 the roots are the paper's (-46.28, -2.36 +- 2i) and the pendulum over-regulates,
    as the paper reports; with the consistent 311 all roots are real and it does not.
    """
    lc = paper_result("d-prime").dynamics["load_changes"][0]
    assert lc["k2_rad2_s2"] == pytest.approx(311.4, rel=0.002)
    assert lc["over_regulation_rad"] == 0.0 and lc["kind"] == "real"
    # eq. (28)'s coefficients with their SI units in the keys
    c = {k.split("_")[0]: v for k, v in lc["coefficients"].items()}
    x = lc["initial_state"]
    R = 300 / 43  # same in any units: kgf m / (kgf m s^2)
    eta0 = (c["a0"] * x["xi_ddot_rad_s2"] + 3 * c["a2"] * x["xi_rad"]) * R / c["a3"]
    a2_slip = c["a0"] * 233.0 / 3
    ic = hamabe_initial_conditions(c["a0"], a2_slip, c["a3"], R, x["xi_rad"], eta0)
    res = analyse_one(c["a0"], c["a1"], a2_slip, c["a3"], *ic)
    roots = sorted(np.asarray(res.roots), key=lambda z: z.real)
    assert roots[0].real == pytest.approx(-46.28, rel=0.01)
    assert abs(roots[1].real) == pytest.approx(2.36, rel=0.03)
    assert abs(roots[1].imag) == pytest.approx(2.0, rel=0.07)
    assert res.over_regulation > 0


def test_k2_cases_over_the_range():
    """Hamabe Part II's three cases per configuration, from a stiff to a soft spring."""
    spec = govopt.load_spec("specs/hamabe-a.toml")
    soft = dataclasses.replace(spec.design, active_turns=30.0)
    stiff = dataclasses.replace(spec.design, active_turns=2.0)
    assert govopt.evaluate(spec).to_dict()["k2_cases"]["stable"] == len(
        govopt.evaluate(spec).statics.alpha)
    s = govopt.evaluate(spec, soft)
    assert s.to_dict()["k2_cases"]["unstable"] > 0
    assert not s.check("k^2 > 0 (stability)").passed
    t = govopt.evaluate(spec, stiff)
    assert t.to_dict()["k2_cases"]["resonance risk"] > 0
    assert not t.check("k^2 < omega0^2 (no resonance)").passed


def test_dynamics_json_keys():
    out = json.loads(
        invoke(["evaluate", "specs/hamabe-c.toml", "--json"]).output)
    assert len(out["k2_rad2_s2"]) == len(out["characteristic"])
    assert out["k2_normal_rad2_s2"] > 0
    lc = out["load_changes"][0]
    for key in ("roots_per_s", "hurwitz_margin", "stable", "over_regulation_rad",
                "settling_time_s"):
        assert key in lc
    assert len(lc["roots_per_s"]) == 3 and all(len(r) == 2 for r in lc["roots_per_s"])
    c = lc["coefficients"]  # eq. (28)'s coefficients, each key with its SI unit
    assert set(c) == {"a0_kg_m2", "a1_N_m_s_per_rad", "a2_N_m_per_rad", "a3_N_m_per_rad_s"}
    assert lc["hurwitz_margin"] == pytest.approx(
        9 * c["a1_N_m_s_per_rad"] * c["a2_N_m_per_rad"]
        / (c["a0_kg_m2"] * c["a3_N_m_per_rad_s"]) - 1, rel=1e-12)
    for key in ("peak_to_peak_rad", "harmonics"):
        assert key in out["vibration"]


def test_friction_only_when_asked():
    """The friction model runs only for a design with a friction moment."""
    spec = govopt.load_spec("specs/hamabe-a.toml")
    assert "friction" not in govopt.evaluate(spec).dynamics
    d = dataclasses.replace(spec.design, friction_moment=22.6 * 9.80665 * 0.01)
    res = govopt.evaluate(spec, d)
    assert res.dynamics["friction"][0]["n_strokes"] >= 1
