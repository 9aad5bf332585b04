"""Fulcrum friction during a load change: Hamabe, Part III, eqs. (42)-(46) (model doc, "Friction
instead of a dash-pot").

The hybrid stick-slip model is checked for what it must conserve (the frictionless linear
solution when M0 = 0, the friction law at every stop and break-away, xi' = 0 at stroke ends, an
independent ODE integration of a stroke) and against the paper's friction example: M0 = 22.6
kgf cm (1.5 % of M_z in case a), no dash-pot, unloading 57 deg 20' -> 64 deg 40'.

Findings, reproduced by the tests below (paper's model: series M_f, reaction at the mean speed,
no dM_r0/dalpha in k^2):

* Cases a, d', d with M0 = 22.6 kgf cm: no over-regulation; the first stroke ends at
  xi = -0.0803, -0.0700, -0.0286 rad. Case d with M0 / 3: ends at -0.0172 rad, still none --
  as the paper says. The threshold for case d is M0 = 5.15 kgf cm; below it the first stroke
  overshoots (M0 = 3 kgf cm ends at +0.018 rad).
* The pendulum never "rests" at an offset: stuck at xi != 0 the speed drifts and friction breaks
  again. After the first stroke it creeps in from one side in self-similar stick-slip cycles
  (each shrinks the offset by a fixed ratio: 0.628 for a, 0.547 for d', 0.224 for d, whatever
  M0), reaching xi = 0 only as t -> oo, with the speed settled at omega0 + M0/C (the friction's
  dead band).
* In the paper's model the pendulum is not in equilibrium at t = 0: its k^2 leaves out
  dM_r0/dalpha while the characteristic curve that gives eta0 includes it, so C eta0 - I k^2 xi0
  is about +12 kgf cm (case a) instead of 0. With consistent statics (exact geometry, reaction
  slope in k^2) it is below 1 kgf cm, the pendulum sticks until the speed error reaches M0/C, and
  after that the first stroke does not depend on M0 at all (the break-away state relative to the
  friction-shifted equilibrium is (xi0, 0, I k^2 xi0 / C)): friction only delays the stroke. So
  M0 decides over-regulation in the paper's example only through that initial imbalance.
  Hamabe's eq. (45) also starts the stroke at t = 0 regardless of the friction band.
"""

import dataclasses
import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import govopt
from govopt.analysis import friction

KGFCM = 9.80665 * 0.01
M0_PAPER = 22.6 * KGFCM


def paper_model(case, M0_kgfcm, dashpot=0.0, consistent=False):
    """The bundled spec with Hamabe's fidelity (or the default, consistent one), no dash-pot."""
    spec = govopt.load_spec(f"specs/hamabe-{case}.toml")
    if not consistent:
        spec = spec.with_analysis(geometry="series", reaction_speed="mean", reaction_slope=False)
    design = dataclasses.replace(spec.design, dashpot=dashpot, friction_moment=M0_kgfcm * KGFCM)
    return spec.with_design(design)


def args(m):
    return m.I, m.f, m.k2, m.C, m.R, m.M0, m.xi0, m.eta0


def assert_friction_law(r, rtol=1e-9):
    """Phases join up; sticks hold |net| <= M0; break-aways at |net| = M0; strokes end at rest."""
    for p, q in zip(r.phases, r.phases[1:], strict=False):
        assert q.t_start == pytest.approx(p.t_end, abs=1e-12)
        assert q.xi_start == pytest.approx(p.xi_end, abs=1e-15)
        assert q.eta_start == pytest.approx(p.eta_end, abs=1e-12)
    scale = max(r.M0, 1e-300)
    for k, p in enumerate(r.phases):
        if p.kind == "stick":
            assert p.direction == 0
            assert abs(p.net_start) <= r.M0 * (1 + 1e-12) + 1e-12 * r.C * abs(p.eta_start)
            if p.complete and math.isfinite(p.t_end):
                assert abs(abs(p.net_end) - r.M0) <= rtol * scale  # break-away
                nxt = r.phases[k + 1]
                assert nxt.kind == "slide" and nxt.direction == np.sign(p.net_end)
                assert nxt.direction == -np.sign(p.xi_start)  # towards the new equilibrium
        else:
            assert p.direction in (-1, 1)
            if p.complete:
                assert abs(p.xi_dot_end) <= 1e-10
                # xi is monotonic within a stroke, in its direction
                assert p.direction * (p.xi_end - p.xi_start) >= -1e-15
                if k + 1 < len(r.phases) and r.phases[k + 1].kind == "slide":
                    # no stop: the net moment overcomes friction the other way at once
                    assert abs(p.net_end) > r.M0 * (1 - 1e-12)
                    assert r.phases[k + 1].direction == np.sign(p.net_end)


# ------------------------------------------------------------------------- exactness checks


def test_expm_matches_scipy_and_mpmath():
    """The numpy-only expm used for the strokes: against mpmath (40 digits) and scipy."""
    import mpmath
    from scipy.linalg import expm as scipy_expm
    mpmath.mp.dps = 40
    m = friction.load_change_model(paper_model("a", 22.6, dashpot=72 * KGFCM))
    for f, s in ((m.f, 1), (0.0, -1)):
        M = friction.slide_matrix(m.I, f, m.k2, m.C, m.R, m.M0, s)
        for t in (0.0, 1e-7, 0.013, 1.0, 20.0):
            exact = np.array(mpmath.expm(mpmath.matrix((M * t).tolist())).tolist(), dtype=float)
            scale = np.max(np.abs(exact))
            ours = friction.expm(M * t)
            assert np.max(np.abs(ours - exact)) <= 5e-12 * scale
            assert np.max(np.abs(ours - scipy_expm(M * t))) <= 5e-12 * scale
    # a Jordan block (repeated eigenvalue) and the batched form
    J = np.array([[-2.0, 1.0, 0.0], [0.0, -2.0, 1.0], [0.0, 0.0, -2.0]])
    t = np.array([0.0, 0.3, 3.0])
    batch = friction.expm(t[:, None, None] * J)
    for k, tk in enumerate(t):
        e = math.exp(-2 * tk)
        np.testing.assert_allclose(batch[k], [[e, tk * e, tk**2 / 2 * e], [0, e, tk * e],
                                              [0, 0, e]], rtol=1e-14, atol=1e-300)
        np.testing.assert_allclose(friction.expm(tk * J), batch[k], rtol=1e-15)



@pytest.mark.parametrize("case,dashpot", [("a", 72 * KGFCM), ("d", 90 * KGFCM), ("a", 0.0)])
def test_zero_friction_reproduces_linear_solution(case, dashpot):
    """M0 = 0: the hybrid solution, stroke after stroke, is the linear solution of eq. (28)."""
    m = friction.load_change_model(paper_model(case, 0.0, dashpot))
    t_end = 6.0 if dashpot else 2.0  # without a dash-pot eq. (28) is unstable: keep it short
    r = friction.friction_transient(*args(m), t_end=t_end, max_strokes=100)
    t = np.linspace(0.0, t_end, 401)
    hybrid = r.state_at(t)
    linear = friction.linear_response(m.I, m.f, m.k2, m.C, m.R, m.xi0, m.eta0, t)
    scale = np.max(np.abs(linear), axis=0)
    assert np.max(np.abs(hybrid - linear) / scale) < 1e-9
    assert_friction_law(r)


def test_zero_friction_strokes_are_the_linear_extrema():
    """M0 = 0, case d with its dash-pot (an oscillating transient): every stroke ends at an
    extremum of the linear xi(t), and xi' = 0 there to 1e-10."""
    m = friction.load_change_model(paper_model("d", 0.0, 90 * KGFCM))
    r = friction.friction_transient(*args(m), t_end=8.0)
    ends = [p for p in r.strokes if p.complete]
    assert len(ends) >= 4
    x = friction.linear_response(m.I, m.f, m.k2, m.C, m.R, m.xi0, m.eta0,
                                 [p.t_end for p in ends])
    assert np.max(np.abs(x[:, 1])) < 1e-10
    np.testing.assert_allclose(x[:, 0], [p.xi_end for p in ends], rtol=0, atol=1e-12)
    assert r.over_regulation  # the paper: case d over-regulates (with a1 = 30, no friction)


@pytest.mark.parametrize("case", ["a", "d-prime", "d"])
def test_friction_law_paper_example(case):
    r = friction.friction_load_change(paper_model(case, 22.6))
    assert r.outcome == "settled"
    assert len(r.sticks) >= 3
    assert_friction_law(r)


def test_stroke_against_independent_integration():
    """The first stroke of case d' (after its initial stick) by solve_ivp with an event."""
    m = friction.load_change_model(paper_model("d-prime", 22.6))
    r = friction.friction_transient(*args(m))
    stick, stroke = r.phases[0], r.phases[1]
    assert stick.kind == "stick" and stroke.kind == "slide" and stroke.direction == 1
    # closed-form break-away: n(t) = n0 - C R xi0 t reaches +M0
    assert stick.t_end == pytest.approx((m.M0 - m.net0) / (-m.C * m.R * m.xi0), rel=1e-13)

    def rhs(_, y):
        xi, v, eta = y
        return v, (m.C * eta - m.I * m.k2 * xi - m.M0) / m.I, -m.R * xi

    def stop(_, y):
        return y[1]
    stop.terminal, stop.direction = True, -1
    sol = solve_ivp(rhs, (stick.t_end, stick.t_end + 5.0), (m.xi0, 0.0, stroke.eta_start),
                    method="DOP853", rtol=1e-12, atol=1e-14, events=stop)
    assert sol.t_events[0][0] == pytest.approx(stroke.t_end, abs=1e-9)
    assert sol.y_events[0][0][0] == pytest.approx(stroke.xi_end, abs=1e-11)
    assert sol.y_events[0][0][2] == pytest.approx(stroke.eta_end, abs=1e-10)


def test_state_at_follows_the_phases():
    m = friction.load_change_model(paper_model("a", 22.6))
    r = friction.friction_transient(*args(m), max_strokes=6)
    for p in r.phases:
        if not p.complete:
            continue
        s = r.state_at([p.t_start, 0.5 * (p.t_start + p.t_end), p.t_end])
        assert s[0, 0] == pytest.approx(p.xi_start, abs=1e-14)
        assert s[2, 0] == pytest.approx(p.xi_end, abs=1e-13)
        assert s[2, 2] == pytest.approx(p.eta_end, abs=1e-12)
        if p.kind == "slide":
            assert p.direction * s[1, 1] > 0  # moving in its direction mid-stroke


# ---------------------------------------------------------------- the paper's friction example


def test_paper_example_no_over_regulation():
    """Hamabe: with M0 = 22.6 kgf cm cases a, d' and d have xi < 0 at the end of the first stroke
    (Figs. 16-18); so does d with about a third of that (Fig. 18a)."""
    found = {}
    for case, M0 in [("a", 22.6), ("d-prime", 22.6), ("d", 22.6), ("d", 22.6 / 3)]:
        r = friction.friction_load_change(paper_model(case, M0))
        assert not r.over_regulation and not r.hunting
        assert r.equilibrium_crossings == 0
        found[case, round(M0, 2)] = r.first_stroke_end
    assert found["a", 22.6] == pytest.approx(-0.0803, abs=1e-4)
    assert found["d-prime", 22.6] == pytest.approx(-0.0700, abs=1e-4)
    assert found["d", 22.6] == pytest.approx(-0.0286, abs=1e-4)
    assert found["d", 7.53] == pytest.approx(-0.0172, abs=1e-4)


def test_paper_example_over_regulation_threshold_case_d():
    """Case d over-regulates once M0 falls below about 5.15 kgf cm (23 % of 22.6): the paper's
    "one third" (7.5 kgf cm) is on the safe side of it."""
    def first_end(M0):
        return friction.friction_load_change(paper_model("d", M0), max_strokes=1).first_stroke_end
    assert first_end(5.3) < 0 < first_end(5.0)
    r = friction.friction_load_change(paper_model("d", 3.0))
    assert r.over_regulation and r.first_stroke_end == pytest.approx(0.0182, abs=2e-4)
    assert r.equilibrium_crossings >= 2 and r.outcome == "settled"  # it still settles
    assert_friction_law(r)


@pytest.mark.parametrize("case,ratio", [("a", 0.6276), ("d-prime", 0.5471), ("d", 0.2238)])
def test_creep_to_equilibrium_is_self_similar(case, ratio):
    """After the first stroke the pendulum creeps to xi = 0 in stick-slip cycles of fixed period
    and fixed contraction (independent of M0, every phase being linear about the friction-shifted
    equilibrium), and the speed settles at omega0 + M0 / C."""
    r1 = friction.friction_load_change(paper_model(case, 22.6))
    r2 = friction.friction_load_change(paper_model(case, 22.6 / 3))
    assert r1.creep_ratio == pytest.approx(ratio, abs=1e-4)
    assert r2.creep_ratio == pytest.approx(r1.creep_ratio, rel=1e-7)
    for r in (r1, r2):
        assert r.outcome == "settled" and abs(r.resting_offset) <= 1e-6 * abs(r.xi0)
        assert r.speed_offset == pytest.approx(r.M0 / r.C, rel=1e-5)
        last = r.strokes[-4:]
        durations = [p.duration for p in last]
        assert np.ptp(durations) < 1e-8 * durations[0]
        assert all(p.direction == 1 for p in last)


def test_sticking_never_final_off_equilibrium():
    """Stuck at xi != 0 the speed drifts at -R xi until the friction breaks: the break-away time
    is finite and closed form."""
    I, f, k2, C, R, M0 = 0.2, 0.0, 400.0, 12.0, 7.0, 2.0
    r = friction.friction_transient(I, f, k2, C, R, M0, -0.01, 0.0, max_strokes=3)
    stick = r.phases[0]
    assert stick.kind == "stick"
    n0 = -I * k2 * -0.01
    assert stick.t_end == pytest.approx((M0 - n0) / (C * R * 0.01), rel=1e-14)
    assert stick.eta_end == pytest.approx(R * 0.01 * stick.t_end, rel=1e-14)
    # exactly at the new equilibrium, inside the band: at rest for good
    r0 = friction.friction_transient(I, f, k2, C, R, M0, 0.0, 0.1)
    assert r0.outcome == "at rest" and r0.phases[-1].t_end == math.inf
    assert r0.resting_offset == 0.0


def test_first_stroke_independent_of_friction_when_starting_at_rest():
    """Consistent statics (the pendulum is in equilibrium before the load change, so its net
    moment is ~0): it sticks until C eta = M0, and the stroke that follows is the same for every
    M0 -- friction delays the first stroke but does not shape it."""
    ends = []
    for M0 in (2.0, 7.53, 22.6):
        spec = paper_model("a", M0, consistent=True)
        m = friction.load_change_model(spec)
        assert abs(m.net0) < 1 * KGFCM < m.M0
        r = friction.friction_transient(*args(m), max_strokes=1)
        assert r.phases[0].kind == "stick"
        ends.append((r.strokes[0].xi_end, r.strokes[0].duration))
    np.testing.assert_allclose(ends, [ends[0]] * 3, rtol=1e-9)
    assert ends[0][0] == pytest.approx(-0.0884, abs=1e-4)  # no over-regulation either


@pytest.mark.parametrize("case", ["a", "d-prime", "d"])
def test_stroke_ratio(case):
    """Every stroke from a stick is the frictionless response from a balanced rest, scaled:
    its ratio xi_end / xi_start is the creep ratio, and (consistent statics, the pendulum
    balanced before the load change) the first stroke's too."""
    m = friction.load_change_model(paper_model(case, 22.6))
    rho = friction.stroke_ratio(m.I, m.f, m.k2, m.C, m.R)
    r = friction.friction_load_change(paper_model(case, 22.6))
    # (deep in the creep xi is 1e-7 of eta's scale: rounding costs digits there)
    assert rho == pytest.approx(r.creep_ratio, rel=1e-7)
    for p, q in zip(r.phases, r.phases[1:], strict=False):
        if p.kind == "stick" and p.complete and q.complete:
            assert q.xi_end / q.xi_start == pytest.approx(rho, rel=1e-6)
    c = friction.load_change_model(paper_model(case, 22.6, consistent=True))
    rc = friction.friction_transient(*args(c), max_strokes=1)
    assert rc.first_stroke_end / c.xi0 == pytest.approx(
        friction.stroke_ratio(c.I, c.f, c.k2, c.C, c.R), rel=1e-8)
    # M0 = 0 from an exactly balanced start: no spurious zero-length strokes
    r0 = friction.friction_transient(m.I, 0.0, m.k2, m.C, m.R, 0.0, -0.1, -0.1 * m.I * m.k2 / m.C,
                                     max_strokes=3)
    assert all(p.duration > 0.05 for p in r0.strokes)


def test_paper_model_starts_out_of_equilibrium():
    """The paper's linear model has C eta0 - I k^2 xi0 = +12.1 kgf cm at t = 0 (case a): its k^2
    lacks dM_r0/dalpha; with the consistent statics the imbalance is second order."""
    paper = friction.load_change_model(paper_model("a", 22.6))
    exact = friction.load_change_model(paper_model("a", 22.6, consistent=True))
    assert paper.net0 / KGFCM == pytest.approx(12.1, abs=0.05)
    assert abs(exact.net0) / KGFCM < 1.0


def test_hunting_with_too_little_friction():
    """No dash-pot and very little friction: eq. (43) is unstable (a1 = 0 fails eq. 32) and the
    friction cannot hold it -- the strokes grow without bound."""
    r = friction.friction_load_change(paper_model("a", 0.3), max_strokes=40)
    assert r.hunting and r.amplitude_growing
    assert r.outcome == "max_strokes"
    assert max(r.amplitudes) > 5 * abs(r.xi0)  # 0.95 rad after 40 strokes (linear model)
    a = r.amplitudes
    assert a[-1] / a[-2] == pytest.approx(1.11, abs=0.01)  # the unstable pair, exp(p pi / q)
    assert_friction_law(r)


def test_friction_with_dashpot():
    """Friction and a dash-pot together (case d, a1 = 30): over-regulation, then sticking."""
    r = friction.friction_load_change(paper_model("d", 22.6, dashpot=90 * KGFCM))
    assert r.over_regulation
    assert any(p.kind == "stick" and p.xi_start > 0 for p in r.phases)
    assert_friction_law(r)


def test_units_invariance_and_json():
    """Same result from the kgf-cm spec and its SI twin; to_dict is JSON-able."""
    a = friction.friction_load_change(govopt.load_spec("specs/hamabe-a.toml"),
                                      friction_moment=M0_PAPER, dashpot=0.0, max_strokes=5)
    b = friction.friction_load_change(govopt.load_spec("specs/hamabe-a-si.toml"),
                                      friction_moment=M0_PAPER, dashpot=0.0, max_strokes=5)
    assert [p.kind for p in a.phases] == [p.kind for p in b.phases]
    np.testing.assert_allclose([p.xi_end for p in a.phases], [p.xi_end for p in b.phases],
                               rtol=1e-6, atol=1e-9)
    d = json.loads(json.dumps(a.to_dict()))
    assert d["n_strokes"] == 5 and d["outcome"] == "max_strokes"
    assert d["phases"][0]["kind"] == "stick"
    json.dumps(friction.load_change_model(govopt.load_spec("specs/hamabe-a.toml")).to_dict())


def _keys(obj) -> set[str]:
    if isinstance(obj, dict):
        return set(obj) | {k for v in obj.values() for k in _keys(v)}
    if isinstance(obj, list):
        return {k for v in obj for k in _keys(v)}
    return set()


def test_friction_keys_follow_the_coordinate(tmp_path):
    """A Porter governor (coordinate: the ball radius, m) with sleeve friction on an engine:
    every friction figure's key names the length's unit (m, m/s, N, kg, N s/m, N s = N per
    rad/s of speed, rad/(m s^2)), not the shaft's (rad, N m, kg m^2); the speed error stays in
    rad/s. The text report shows the first stroke's end in mm."""
    text = open("specs/porter-engine.toml").read().replace(
        'sleeve_offset = "3.76 cm"', 'sleeve_offset = "3.76 cm"\nsleeve_friction = "1 kgf"')
    path = tmp_path / "porter-friction.toml"
    path.write_text(text)
    spec = govopt.load_spec(path)
    res = govopt.evaluate(spec)
    d = json.loads(json.dumps(res.to_dict()))
    fr = d["friction"][0]
    keys = _keys(fr)
    angular = sorted(k for k in keys if k.endswith(("_rad", "_N_m", "_kg_m2", "_N_m_s"))
                     or (k.endswith("_rad_per_s") and not k.startswith(("eta", "speed",
                                                                            "friction_speed"))))
    assert angular == []
    assert {"I_kg", "f_N_s_per_m", "C_N_s", "R_rad_per_m_s2", "M0_N", "xi0_m", "xi_dot0_m_per_s",
            "first_stroke_end_m", "final_xi_m", "resting_offset_m"} <= set(fr)
    assert {"xi_start_m", "net_start_N", "amplitude_m", "xi_dot_end_m_per_s"} <= set(
        fr["phases"][0])
    # the values are the SI figures of the length coordinate: xi0 = 21 cm - 23 cm, the band
    # per ball R/2 |ds/dr| (textbook 3.4(b)) at 23 cm, the dash-pot 400 N s/m as given
    assert fr["xi0_m"] == pytest.approx(-0.02, rel=1e-12)
    assert fr["M0_N"] == pytest.approx(float(spec.governor.friction(0.23)), rel=1e-12)
    assert fr["M0_N"] == pytest.approx(0.5 * 9.80665 * abs(float(
        spec.governor.travel_slope(0.23))), rel=1e-12)
    assert fr["f_N_s_per_m"] == 400.0
    # the speed band M0/C is a speed whatever the coordinate: N / (N s) = 1/s (rad/s)
    assert fr["friction_speed_band_rad_per_s"] == pytest.approx(fr["M0_N"] / fr["C_N_s"],
                                                                rel=1e-12)
    from govopt.report.text import format_result

    line = next(t for t in format_result(res).splitlines() if "first stroke ends" in t)
    assert " mm " in line and " deg " not in line


def test_shaft_friction_keys_are_angular():
    """The shaft governor's friction figures keep the angle's units (rad, N m, kg m^2; the
    dash-pot in N m s/rad as everywhere else)."""
    spec = govopt.load_spec("specs/hamabe-a.toml")
    d = friction.friction_load_change(spec, friction_moment=M0_PAPER, dashpot=0.0,
                                      max_strokes=3).to_dict()
    assert {"I_kg_m2", "f_N_m_s_per_rad", "C_N_m_s", "R_per_s2", "M0_N_m", "xi0_rad",
            "xi_dot0_rad_per_s", "first_stroke_end_rad"} <= set(d)
    assert {"xi_start_rad", "net_start_N_m", "amplitude_rad"} <= set(d["phases"][0])
    assert d["M0_N_m"] == M0_PAPER


def test_stroke_whose_acceleration_vanishes_at_a_step_end_does_not_crash():
    """A traction coil governor's stroke (found by a robust design, fly weights +2 %) in which
    xi'' is ~0 at a step's end: the stepped state and expm(M t) z0 disagreed in its sign, and
    Brent's method was handed a bracket without a sign change (ValueError, a traceback from
    `govopt design`). xi' stays >= 0 on the whole stroke (the modal solution on 200 001 points,
    independent of the stepping), so the stroke runs to its time limit."""
    M = np.array([[0.0, 1.0, 0.0, 0.0],
                  [-857.5684540538409, -26.051839964503284, 2.106507763594993,
                   -1.452480527432],
                  [-661.4173228346457, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]])
    z0 = np.array([-0.0025399999999999937, 0.0, -0.34452441068918144, 1.0])
    t_max = 17.18529679873766
    w, V = np.linalg.eig(M)
    c = np.linalg.solve(V, z0)
    t = np.linspace(0.0, t_max, 200_001)
    v = np.real((V[1] * c)[None, :] * np.exp(np.outer(t, w))).sum(axis=1)
    assert v[1:].min() > 0.0
    tau, z = friction._slide(M, z0, 1, t_max, 0.0035006966454461503)
    assert tau is None and z[1] > -1e-12 * np.abs(v).max()
