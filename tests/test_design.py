"""The optimiser (issue: govopt design): verified, globally optimal on a grid, diagnosed."""

import dataclasses
import json
import re
from pathlib import Path

import numpy as np
import pytest
from clirun import invoke

import govopt
import govopt.examples
from govopt.analysis import statics
from govopt.optimize import design as dz
from govopt.optimize import windows as wz
from govopt.optimize.kappa import KappaModel
from govopt.springs import helical as hx

SPEC = "specs/hamabe-design.toml"


@pytest.fixture(scope="module")
def spec():
    return govopt.load_spec(SPEC)


@pytest.fixture(scope="module")
def result(spec):
    return dz.design(spec)


def test_design_passes_every_constraint(result):
    failed = [c.name for c in result.checks if not c.passed]
    assert failed == []
    assert result.optimisation["status"] == "optimal"
    # dynamics were verified on the chosen design (not only in the search)
    assert result.dynamics["load_changes"][0]["stable"]
    assert result.dynamics["load_changes"][0]["over_regulation_rad"] == 0.0


def test_design_beats_the_papers_case_a(spec, result):
    """Paper's case a on the same requirements: 12 kgf pendulum + its 17 mm spring.

    It violates the irregularity requirement (0.1244 > 0.12: the paper rounds kappa up from
    63.3 to 64.2 kgf/cm) so it is not even admissible; by moving mass it is also >3x heavier.
    """
    paper = govopt.load_spec("specs/hamabe-a.toml").design
    res = govopt.evaluate(spec.with_design(paper))
    assert not res.check("irregularity").passed
    # the moving mass counts both pendulums of Hamabe's pair (Fig. 1) and the spring
    paper_moving = 2 * res.spring.m + res.spring_properties["mass_kg"]
    ours = result.optimisation["value"]
    assert ours <= paper_moving
    assert ours == pytest.approx(2 * result.spring.m + result.spring_properties["mass_kg"],
                                 rel=1e-12)


def test_continuous_bound_below_discrete(result):
    assert result.optimisation["objective"]["unit"] == "kg"  # the objective with its unit
    bound = result.optimisation["bound"]
    assert bound <= result.optimisation["value"] * (1 + 1e-9)
    assert 0 <= result.optimisation["gap"] < 0.5


def _brute_force(spec, masses, wires, radii, turns):
    """Independent exhaustive search: statics from govopt.analysis.statics (not the optimiser's
    kappa-affine model), spring checks from govopt.springs.helical; dynamics by the same dash-pot
    window as the optimiser. Returns the best moving mass and its design."""
    req = spec.requirements
    G, rho_s = spec.material.shear_modulus, spec.material.density
    M, D, R, N = (a.ravel() for a in np.meshgrid(masses, wires, radii, turns, indexing="ij"))
    kappa = hx.stiffness_r(D, R, N, G)
    m, k = M[:, None], kappa[:, None]
    l0 = statics.free_half_length(spec, m, k)
    grid = wz.Grid.build(spec)
    w2 = statics.omega_squared(spec, grid.alpha, m, k, l0)
    sd = statics.SpringDesign(m, spec.governor.rho**2 * m, k, l0)
    k2 = statics.restoring_k2(spec, grid.alpha, sd, w2)
    w0sq = spec.speed.omega_mean**2
    w = np.sqrt(np.maximum(w2, 1e-300))
    # Hamabe's irregularity, the range over the spec's mean speed (Part I; was the range over
    # the mean of the two extreme speeds, the definition the requirement no longer uses)
    irr = (w[:, -1] - w[:, 0]) / spec.speed.omega_mean
    F = 2 * k * (np.sqrt(spec.governor.a**2 + spec.governor.b**2 - 2 * spec.governor.a
                         * spec.governor.b * np.cos(grid.alpha)) - l0)
    C = 2 * R / D
    margin = 0.05  # Hamabe's band, the shaft governor's default (its valve gear forces it)
    ok = (np.all(w2 > 0, axis=1) & np.all(k2 >= margin * w0sq, axis=1)
          & np.all(k2 <= (1 - margin) * w0sq, axis=1) & (irr <= spec.speed.irregularity)
          & np.all(F >= 0, axis=1) & (l0[:, 0] > 0)
          & (hx.shear_stress_r(F.max(axis=1), D, R) <= spec.material.allowable_shear_stress)
          & (C >= req.spring_index[0]) & (C <= req.spring_index[1]) & ((N + 1) * D <= 2 * l0[:, 0]))
    obj = 2 * M + hx.wire_mass(D, R, N, rho_s)  # both pendulums and the spring
    km = KappaModel.build(spec, masses, grid.alpha)
    for i in np.argsort(np.where(ok, obj, np.inf)):
        if not ok[i]:
            return None
        row = np.array([int(np.argmin(np.abs(masses - M[i])))])
        if wz.dashpot_window(spec, req, km, grid, row, kappa[[i]])["feasible"][0]:
            return obj[i], (M[i], D[i], R[i], N[i])
    return None


def test_never_worse_than_exhaustive_coarse_grid(spec, result):
    """Global optimality: the optimiser's design is never worse than the best of an exhaustive
    search over a coarse grid drawn from the same catalogue (every 1 kgf, every second wire,
    radii every 3 mm, whole turns)."""
    req = spec.requirements
    masses = np.arange(4.0, 16.01, 1.0)
    wires = np.array(req.wire_diameters[::2])
    radii = np.arange(0.030, 0.0801, 0.003)
    turns = np.arange(3.0, 20.01, 1.0)
    best = _brute_force(spec, masses, wires, radii, turns)
    assert best is not None
    assert result.optimisation["value"] <= best[0] * (1 + 1e-12)


def test_written_design_reproduces(tmp_path, result):
    """-o DESIGN.toml: govopt evaluate reproduces the design's figures to 1e-9."""
    out = tmp_path / "design.toml"
    r = invoke(["design", SPEC, "-o", str(out), "--json"])
    assert r.exit_code == 0, r.output
    designed = json.loads(r.stdout)  # "wrote ..." goes to stderr with --json
    ev = json.loads(invoke(["evaluate", str(out), "--json"]).output)
    for key in ("irregularity", "omega_inner_rad_s", "omega_outer_rad_s", "pendulum_mass_kg"):
        assert ev[key] == pytest.approx(designed[key], rel=1e-9)
    for key, value in designed["spring"].items():
        assert ev["spring"][key] == pytest.approx(value, rel=1e-9), key
    assert ev["load_changes"][0]["settling_time_s"] == pytest.approx(
        designed["load_changes"][0]["settling_time_s"], rel=1e-9)
    for key in ("design", "objective", "bound_design", "sensitivities", "status"):
        assert key in designed["optimisation"]  # the optimiser's record (optimize.record)
    # one section each: the checks are the design's constraints, not written twice
    assert "constraints" not in designed and len(designed["checks"]) >= 10
    d = designed["optimisation"]["design"]
    for key in ("pendulum_weight_N", "wire_diameter_m", "coil_radius_m", "active_turns",
                "free_half_length_m", "dashpot_N_m_s_per_rad"):
        assert key in d


def test_sensitivities_in_plain_words(result):
    from govopt.report import sections

    sens = result.optimisation["sensitivities"]  # elasticities: % objective per +1 % limit
    # more allowable stress -> lighter spring (never heavier)
    assert sens["allowable shear stress k_s"] <= 0
    table = next(t for t in sections.optimisation(result) if t.title.startswith("Sensitivities"))
    assert ["allowable shear stress k_s", 1.0] == table.rows[0][:2]


def _infeasible(tmp_path, old, new):
    text = open(SPEC).read()
    assert old in text
    path = tmp_path / "infeasible.toml"
    path.write_text(text.replace(old, new, 1))
    return invoke(["design", str(path)])


def test_infeasible_stress(tmp_path):
    r = _infeasible(tmp_path, '"4000 kgf/cm^2"', '"400 kgf/cm^2"')
    assert r.exit_code == 2, r.output
    assert "allowable shear stress" in r.output and "allowable_shear_stress" in r.output
    assert "Traceback" not in r.output


def test_infeasible_error_carries_its_reason_as_data(tmp_path):
    """The diagnosis is data, not text to read back: the spec, the conflict, each move that
    alone makes a design exist; the one line the CLI prints is composed from them."""
    from govopt.errors import InfeasibleError

    text = open(SPEC).read().replace('"4000 kgf/cm^2"', '"400 kgf/cm^2"', 1)
    path = tmp_path / "infeasible.toml"
    path.write_text(text)
    with pytest.raises(InfeasibleError) as caught:
        dz.design(govopt.load_spec(path))
    e = caught.value
    assert e.file == str(path) and e.reason.startswith("infeasible: ")
    assert e.moves and any(m.startswith("material.allowable_shear_stress 400 kgf/cm^2 -> ")
                           for m in e.moves), e.moves
    assert str(e) == f"{path}: {e.reason}; it becomes feasible if one of these moves: " \
        + "; ".join(e.moves)


def test_infeasible_irregularity_forces_k2_nonpositive(tmp_path):
    r = _infeasible(tmp_path, "irregularity = 0.12", "irregularity = 0.002")
    assert r.exit_code == 2, r.output
    assert "k^2 > 0" in r.output and "irregularity" in r.output


def test_infeasible_overregulation_at_every_damping(tmp_path):
    """A Hurwitz margin so large that every admissible dash-pot over-damps the slow pair into
    an overshooting complex pair: 'no over-regulation' conflicts with eq. (32)."""
    r = _infeasible(tmp_path, "hurwitz_margin = 0.1", "hurwitz_margin = 2000")
    assert r.exit_code == 2, r.output
    assert "over-regulat" in r.output and "eq. (32)" in r.output


def test_kappa_model_matches_statics(spec):
    """The optimiser's affine-in-kappa statics equal the evaluator's to rounding."""
    for kw in ({}, {"geometry": "series", "reaction_speed": "mean", "reaction_slope": False}):
        s = spec.with_analysis(**kw)
        grid = wz.Grid.build(s)
        km = KappaModel.build(s, [5.0, 9.0], grid.alpha)
        for i, m in enumerate((5.0, 9.0)):
            kappa = 30000.0
            l0 = statics.free_half_length(s, m, kappa)
            sd = statics.SpringDesign(m, s.governor.rho**2 * m, kappa, l0)
            w2 = statics.omega_squared(s, grid.alpha, m, kappa, l0)
            np.testing.assert_allclose(km.omega2(kappa)[i], w2, rtol=1e-12)
            np.testing.assert_allclose(km.k2(kappa)[i], statics.restoring_k2(s, grid.alpha, sd, w2),
                                       rtol=1e-11)


def test_dashpot_window_is_bounded_on_both_sides(spec):
    """Too little damping violates eq. (32); too much over-regulates: find both ends."""
    req = dataclasses.replace(spec.requirements, hurwitz_margin=0.0)
    grid = wz.Grid.build(spec)
    km = KappaModel.build(spec, [6.0], grid.alpha)
    lo, hi, _ = km.statics_interval(*wz.k2_limits(spec, req), spec.speed.irregularity)
    kappa = 0.5 * (lo[0] + hi[0])
    win = wz.dashpot_window(spec, req, km, grid, np.array([0]), np.array([kappa]),
                            factors=np.geomspace(1.0, 1e4, 60))
    assert win["feasible"][0]
    a0, a2, a3, _ = wz.load_change_problem(spec, km, grid, np.array([0]), np.array([kappa]))
    f_hurwitz = float(a0[0, 0] * a3[0, 0] / (3 * a2[0, 0]))
    assert win["f_lo"][0] >= f_hurwitz * (1 - 1e-12)
    assert win["f_hi"][0] < f_hurwitz * 1e4  # an upper end exists inside the scanned range


@pytest.mark.parametrize("reaction_speed", ["local", "mean"])
def test_vectorised_load_change_matches_the_evaluator(spec, reaction_speed):
    """The optimiser's vectorised eq. (28) coefficients and initial state equal the evaluator's
    (govopt.analysis.loadchange) for the same design."""
    from govopt.analysis import loadchange

    s = spec.with_analysis(reaction_speed=reaction_speed)
    grid = wz.Grid.build(s)
    km = KappaModel.build(s, [7.0], grid.alpha)
    kappa = 30000.0
    a0, a2, a3, x = wz.load_change_problem(s, km, grid, np.array([0]), np.array([kappa]))
    l0 = statics.free_half_length(s, 7.0, kappa)
    sd = statics.SpringDesign(7.0, s.governor.rho**2 * 7.0, kappa, l0)
    (b0, _, b2, b3), y, _ = loadchange.coefficients(s, sd, s.load_changes[0], 1.0)
    np.testing.assert_allclose([a0[0, 0], a2[0, 0], a3[0, 0]], [b0, b2, b3], rtol=1e-11)
    np.testing.assert_allclose([v[0, 0] for v in x], y, rtol=1e-10, atol=1e-14)


@pytest.mark.parametrize(("old", "new", "key"), [
    ('pendulum_weight = ["4 kgf", "16 kgf"]', 'pendulum_weight = ["4.01 kgf", "4.2 kgf"]',
     "bounds.pendulum_weight"),
    ('wire_diameter = ["5 mm", "25 mm"]', 'wire_diameter = ["30 mm", "40 mm"]',
     "catalogue.wire_diameters"),
    ("active_turns = [3, 20]", "active_turns = [3.1, 3.2]", "bounds.active_turns"),
])
def test_bounds_that_leave_an_empty_grid(tmp_path, old, new, key):
    r = _infeasible(tmp_path, old, new)
    assert r.exit_code == 2, r.output
    assert key in r.output and "Traceback" not in r.output


def test_design_without_engine_says_dynamics_were_not_designed(tmp_path):
    text = open(SPEC).read()
    text = text[:text.index("[engine]")] + text[text.index("[requirements]"):]
    path = tmp_path / "noengine.toml"
    path.write_text(text)
    res = dz.design(govopt.load_spec(path))
    assert res.optimisation["notes"] and "not designed for" in res.optimisation["notes"][0]
    assert all(c.passed for c in res.checks)


@pytest.mark.slow
@pytest.mark.parametrize("inertia", ["4e7 kg m^2", "1e9 kg m^2"])
def test_huge_flywheel_design_agrees_with_evaluate(tmp_path, inertia):
    """A flywheel 1e5-2e6 times Hamabe's (43 kgf m s^2 = 421.7 kg m^2): the slow modes decay
    over ~1e5 s while the pendulum swings at 0.32 s, so no admissible dash-pot's settling is
    decided within the time grid's limit (limits.MAX_TRANSIENT_POINTS; reported 'never'). All
    admissible dash-pots scored inf like the inadmissible ones, and the search took the first
    (eq. 32's least f, which over-regulates): 'the optimiser's model and the evaluator
    disagree'. The chosen dash-pot is now an admissible one and evaluate passes it."""
    text = open(SPEC).read()
    old = 'flywheel_inertia = "43 kgf*m*s^2"'
    assert old in text
    path = tmp_path / "flywheel.toml"
    # the swing under the valve gear is not what this case is about: without the bundled limit
    # the search visits what it did when the case was found (a vibration bound per candidate
    # quadrupled its time)
    vib = 'max_vibration = "25 deg"'
    assert vib in text
    text = text.replace(vib, "")
    path.write_text(text.replace(old, f'flywheel_inertia = "{inertia}"'))
    res = dz.design(govopt.load_spec(path))
    assert [c.name for c in res.checks if not c.passed] == []
    d = res.optimisation["design"]
    f_lo, f_hi = d["dashpot_feasible_range_N_m_s_per_rad"]
    assert f_lo <= d["dashpot_N_m_s_per_rad"] <= f_hi
    lc = res.dynamics["load_changes"][0]
    assert not lc["over_regulates"] and lc["hurwitz_margin"] >= 0.1
    # settling past the time grid comes from the modes' envelope (settling.envelope_settling:
    # ~3e5 s at 4e7 kg m^2, 7.7e6 s at 1e9, checked against mpmath in test_transient.py), so a
    # 10 s limit is infeasible, naming the fastest admissible settling (exit 2, not a 'bug')
    assert 1e5 < lc["settling_time_s"] < 1e8
    # The diagnosis below checks every candidate the search keeps (none settles within 10 s):
    # over the whole catalogue, 37601 candidates and 484 lattice cells at up to 20 000 time
    # points each, 70 s a case. The search's size is not what the case is about, so it runs
    # around the design just found (its wire; its weight, radius and turns and their neighbours).
    w, wire = d["pendulum_weight_N"] / 9.80665, 1e3 * d["wire_diameter_m"]
    r, n = 1e3 * d["coil_radius_m"], d["active_turns"]
    text = path.read_text()
    for key, value in (("pendulum_weight", f'["{w:g} kgf", "{w + 0.25:g} kgf"]'),
                       ("wire_diameters", f'["{wire:g} mm"]'),
                       ("coil_radius", f'["{r - 1:g} mm", "{r + 1:g} mm"]'),
                       ("active_turns", f"[{n - 1:g}, {n + 1:g}]")):
        text, found = re.subn(rf"(?m)^{key} = \[[^]]*\]", f"{key} = {value}", text, count=1)
        assert found, key
    path.write_text(text.replace("hurwitz_margin = 0.1", 'hurwitz_margin = 0.1\n'
                                 'max_settling_time = "10 s"', 1))
    with pytest.raises(govopt.errors.InfeasibleError, match=r"max_settling_time 10 s .* the "
                       r"fastest admissible settling is \d\.\d+e\+0[4-7] s"):
        dz.design(govopt.load_spec(path))


def test_a_design_the_evaluator_fails_is_diagnosed_not_returned(monkeypatch):
    """The final verdict is the evaluator's: a chosen design it fails (forced here by a check
    the search never saw) is no design, and the message is a diagnosis naming the requirement,
    its value, limit and margin, and what to change - not a request to report a bug."""
    from govopt import evaluator
    from govopt.errors import DesignError
    from govopt.verdict import Check

    real = evaluator.evaluate

    def failing(spec, design=None):
        res = real(spec, design)
        res.checks.append(Check("irregularity (tightened)", 0.05, 0.04, "<=", "", ""))
        return res

    monkeypatch.setattr(evaluator, "evaluate", failing)
    spec = govopt.load_spec(govopt.examples.SPECS / "porter-design.toml")
    with pytest.raises(DesignError) as err:
        govopt.design(spec)
    text = str(err.value)
    assert "irregularity (tightened): 0.05 , required <= 0.04 (margin -0.25)" in text
    assert "edge of irregularity (tightened)" in text and "more margin" in text
    assert "bug" not in text


PORTER_INFEASIBLE = {  # speeds, central-load bounds: what no weight pair meets
    "band too narrow": ('inner = "190 rpm"', 'outer = "200 rpm"', None),
    # Hamabe's band asked for: a Porter has no forcing, so it applies only when the spec says
    "k^2 margin": ('inner = "200 rpm"', 'outer = "235.8 rpm"', None, "k2_margin = 0.05\n"),
    "slow": ('inner = "100 rpm"', 'outer = "115 rpm"', None),
    "more central load": ('inner = "190 rpm"', 'outer = "224 rpm"', '["10 kgf", "20 kgf"]'),
    "far more central load": ('inner = "190 rpm"', 'outer = "224 rpm"', '["2 kgf", "10 kgf"]'),
}


def _porter(tmp_path, inner, outer, central, requirements=""):
    text = (Path("specs/porter-design.toml").read_text(encoding="utf-8")
            .replace('inner = "190 rpm"', inner).replace('outer = "224 rpm"', outer)
            .replace("[requirements]\n", "[requirements]\n" + requirements, 1))
    if central:
        text = text.replace('central_weight = ["10 kgf", "100 kgf"]', f"central_weight = {central}")
    path = tmp_path / "porter.toml"
    path.write_text(text, encoding="utf-8")
    return govopt.load_spec(path)


@pytest.mark.parametrize("case", sorted(PORTER_INFEASIBLE))
def test_dead_weight_diagnosis_in_closed_form_is_the_lattice_scans(case, tmp_path, monkeypatch):
    """The Porter's forces are affine in the central load, so the diagnosis finds each ball
    weight's central loads in closed form (an interval) instead of scanning the lattice of
    weight pairs: the same diagnosis, every move included, as the scan gives."""
    from govopt.errors import InfeasibleError

    spec = _porter(tmp_path, *PORTER_INFEASIBLE[case])
    with pytest.raises(InfeasibleError) as closed:
        govopt.design(spec)
    monkeypatch.setattr(type(spec.governor), "central_load_affine", False)
    with pytest.raises(InfeasibleError) as scanned:
        govopt.design(spec)
    assert str(closed.value) == str(scanned.value)
    assert closed.value.moves == scanned.value.moves and closed.value.moves


def test_central_load_intervals_hold_the_pairs_that_meet_the_statics(tmp_path):
    """Each ball weight's closed-form interval of central loads holds exactly the lattice's
    pairs that meet every statics requirement (away from its ends by rounding)."""
    spec = _porter(tmp_path, 'inner = "190 rpm"', 'outer = "224 rpm"', None)
    req, grid = spec.requirements, wz.Grid.build(spec)
    m = wz.mass_grid(req)
    c = wz.grid_steps(0.0, 200.0, req.mass_step)
    lo, hi = wz.central_load_intervals(spec, req, grid, m)
    mm, cc = (a.ravel() for a in np.meshgrid(m, c, indexing="ij"))
    parts = wz.dead_weight_statics(spec, req, grid, mm, cc)[0]
    met = np.logical_and.reduce(list(parts.values())).reshape(m.size, c.size)
    inside = (c >= lo[:, None]) & (c <= hi[:, None])
    near = np.minimum(np.abs(c - lo[:, None]), np.abs(c - hi[:, None])) < 1e-9 * c.max()
    assert met.any() and (~met).any()
    np.testing.assert_array_equal(met[~near], inside[~near])


def test_dead_weight_design_on_an_engine_checks_each_candidates_own_central_load(tmp_path):
    """A Porter on an engine whose first candidates fail the dynamics: each batch of candidates
    is checked with its own central loads (the speed lever of eq. 24 reads them), and no
    dash-pot settling in 1 ms gives a diagnosis, not an error of array shapes."""
    text = (Path("specs/porter-design.toml").read_text(encoding="utf-8")
            .replace('objective = "moving_mass"',
                     'objective = "moving_mass"\nmax_settling_time = "0.001 s"')
            + '\n[engine]\nflywheel_inertia = "50 kg*m^2"\ntorque_slope = "-1000 N*m/m"\n'
              '\n[[load_change]]\nname = "lc"\nfrom = "21 cm"\nto = "23 cm"\n')
    path = tmp_path / "porter-engine-design.toml"
    path.write_text(text, encoding="utf-8")
    run = invoke(["design", str(path)])
    assert run.exit_code == 2, run.stderr
    assert run.stderr.startswith(f"error: {path}: infeasible: ") and "load change" in run.stderr


def test_the_dynamics_stop_at_the_limit_of_work_and_say_so(monkeypatch):
    """The settling-time objective checks 512 candidates best first after ordering them on a
    lattice (~10 s of counted work on Hamabe's problem); with a limit of 2 s the lattice is
    coarsened to fit its share, the visit stops at the limit, and the design is the best of
    those checked, with a note saying so (twenty load changes took 89 s before)."""
    from govopt import limits
    from govopt.optimize import design as dz

    spec = govopt.load_spec("specs/hamabe-design.toml")
    spec = dataclasses.replace(spec, requirements=dataclasses.replace(
        spec.requirements, objective="settling_time"))
    monkeypatch.setattr(limits, "MAX_DESIGN_DYNAMICS_SECONDS", 2.0)
    res = dz.design(spec)
    search = res.optimisation["search"]
    assert search["dynamics_stopped_at_the_work_limit"]
    assert search["dynamics_checked"] < 512 and search["dynamics_work_s"] <= 2.0
    assert any("stopped at govopt's limit of work" in n for n in res.optimisation["notes"])
    assert all(c.passed for c in res.checks)
