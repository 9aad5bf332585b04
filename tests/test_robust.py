"""a design that holds in the shop - the dash-pot in the middle of its window, robust
requirements over a tolerance box, verified independently of the optimiser's worst-case code."""

import dataclasses
import itertools
import json

import numpy as np
import pytest
from clirun import invoke

import govopt
from govopt.bulk import check_names, evaluate_many
from govopt.optimize import design as dz
from govopt.optimize import robust as rb
from govopt.optimize import search
from govopt.optimize.margins import window_centre
from govopt.spec import Design
from govopt.springs import tolerances as tl

SPEC = "specs/hamabe-design.toml"
ROBUST = "specs/hamabe-design-robust.toml"
TEXTBOOK = "specs/spring_loaded-design-robust.toml"


@pytest.fixture(scope="module")
def nominal():
    return search.design(govopt.load_spec(SPEC))


@pytest.fixture(scope="module")
def robust():
    return search.design(govopt.load_spec(ROBUST))


def _design(res) -> Design:
    """The chosen design, from the optimiser's JSON record (SI)."""
    o = res.optimisation["design"]
    key = [k for k in o if k.startswith("dashpot_") and "range" not in k and "margin" not in k]
    f = o[key[0]] if key and o[key[0]] == o[key[0]] else None
    spring = {k[:-2] if k.endswith("_m") else k: v for k, v in o.items()
              if k in ("wire_diameter_m", "coil_radius_m", "active_turns")}
    mass = [v for k, v in o.items() if k.endswith("_mass_kg") and not k.startswith("central")]
    free = [v for k, v in o.items() if k.startswith("free_") and k.endswith("_m")]
    return Design(flying_mass=mass[0], free_half_length=free[0], dashpot=f,
                         central_mass=o.get("central_mass_kg"), **spring)


# ------------------------------------------------------------------ the dash-pot's margin


def test_window_centre_is_the_widest_margin_on_random_masks():
    """Brute force: the picked value is admissible and no admissible value has a larger least
    log-distance to the ends of its admissible run."""
    rng = np.random.default_rng(3)
    f = np.geomspace(0.1, 20.0, 25)
    for _ in range(200):
        ok = rng.random((1, 25)) < rng.uniform(0.2, 0.9)
        j = int(window_centre(f[None, :], ok)[0])
        if not ok.any():
            continue
        assert ok[0, j]

        def margin(i, ok=ok):
            lo = hi = i
            while lo > 0 and ok[0, lo - 1]:
                lo -= 1
            while hi < 24 and ok[0, hi + 1]:
                hi += 1
            return min(np.log(f[i] / f[lo]), np.log(f[hi] / f[i]))

        best = max(margin(i) for i in range(25) if ok[0, i])
        assert margin(j) >= best - 1e-9


def test_default_design_keeps_20_percent_to_each_end_of_the_dashpot_window(nominal):
    d = nominal.optimisation["design"]
    f = d["dashpot_N_m_s_per_rad"]
    f_lo, f_hi = d["dashpot_feasible_range_N_m_s_per_rad"]
    assert f_lo * 1.2 <= f <= f_hi / 1.2
    below = d["dashpot_margin_to_lower_end_percent"]
    above = d["dashpot_margin_to_upper_end_percent"]
    assert below == pytest.approx(100 * (1 - f_lo / f)) and below >= 20
    assert above == pytest.approx(100 * (f_hi / f - 1)) and above >= 20


def test_default_dashpot_set_20_percent_off_still_passes(nominal):
    """The evaluator, not the optimiser, decides: the valve set 20 % high or low still gives
    no over-regulation and eq. (32) with its margin."""
    spec = govopt.load_spec(SPEC)
    base = _design(nominal)
    for x in (0.8, 1.2):
        res = govopt.evaluate(spec.with_design(dataclasses.replace(base,
                                                                   dashpot=base.dashpot * x)))
        assert [c.name for c in res.checks if not c.passed] == []


def test_dashpot_margins_in_text_and_json():
    run = invoke(["design", SPEC, "--json"])
    assert run.exit_code == 0, run.output
    d = json.loads(run.stdout)["optimisation"]["design"]
    assert d["dashpot_margin_to_upper_end_percent"] >= 20
    text = invoke(["design", SPEC, "--full"]).stdout
    assert "dashpot margin to lower end   %" in text and "dashpot margin to upper end   %" in text


# ------------------------------------------------------------------ the robust shaft design


def _corners_and_sample(spec, design, samples=300, seed=7):
    """The EN 15800 grade 2 box of the design's spring (Table 1 directly: the coil diameter
    +-A_D; this material has no wire standard, and an extension spring's free length is not
    toleranced) and the dash-pot +-10 %: its corners and a uniform sample inside, as designs."""
    D = 2.0 * design.coil_radius
    half_r = float(tl.coil_diameter_tolerance(D, D / design.wire_diameter, 2)) / 2.0
    assert half_r > 0
    corners = [dataclasses.replace(design, coil_radius=design.coil_radius + sr * half_r,
                                   dashpot=design.dashpot * (1 + 0.1 * sf))
               for sr, sf in itertools.product((-1, 1), (-1, 1))]
    rng = np.random.default_rng(seed)
    sample = {"coil_radius": design.coil_radius + half_r * rng.uniform(-1, 1, samples),
              "dashpot": design.dashpot * (1 + 0.1 * rng.uniform(-1, 1, samples))}
    return corners, sample


def test_robust_shaft_design_holds_over_the_box_without_adjustment(robust):
    spec = govopt.load_spec(ROBUST)
    design = _design(robust)
    corners, sample = _corners_and_sample(spec, design)
    for c in corners:  # the ordinary evaluator, design by design
        res = govopt.evaluate(spec.with_design(c))
        assert [ck.name for ck in res.checks if not ck.passed] == [], c
    frame = evaluate_many(spec.with_design(design), sample)
    assert (frame["status"] == "pass").all()
    assert len(check_names(frame.columns)) >= 10
    rec = robust.optimisation["robust"]
    assert rec["holds_at_every_corner"] and rec["adjusting_nut"] is None
    assert rec["monte_carlo"]["probability"] == 1.0


def test_the_nominal_optimum_is_not_robust_and_robustness_costs(nominal, robust):
    """The nominal optimum fails at a corner of the same box (so the robust search did work),
    and the robust design's objective is not below the nominal one; the record says by how
    much."""
    spec = govopt.load_spec(ROBUST)
    corners, _ = _corners_and_sample(spec, _design(nominal))
    failed = {ck.name for c in corners for ck in govopt.evaluate(spec.with_design(c)).checks
              if not ck.passed}
    assert failed  # the shear stress at the small coil diameter
    cost = robust.optimisation["robust"]["cost"]
    v_nom = nominal.optimisation["value"]
    v_rob = robust.optimisation["value"]
    assert cost["nominal_objective_kg"] == pytest.approx(v_nom)
    assert cost["robust_objective_kg"] == pytest.approx(v_rob)
    assert v_rob >= v_nom
    assert cost["increase_percent"] == pytest.approx(100 * (v_rob / v_nom - 1))


def test_worst_case_beside_nominal_is_the_evaluators(robust):
    """Each reported worst case is the evaluator's value at one of the box's corners, and it is
    no better than the nominal value."""
    spec = govopt.load_spec(ROBUST)
    design = _design(robust)
    corners, _ = _corners_and_sample(spec, design)
    values = {}
    for c in corners:
        for ck in govopt.evaluate(spec.with_design(c)).checks:
            values.setdefault(ck.name, []).append((ck.margin, ck.value))
    nominal = {ck.name: ck for ck in robust.checks}
    for row in robust.optimisation["robust"]["checks"]:
        worst = min(values[row["check"]])
        assert row["worst_margin"] == pytest.approx(worst[0], rel=1e-6, abs=1e-9)
        assert row["worst_case"] == pytest.approx(worst[1], rel=1e-6, abs=1e-12)
        assert row["nominal"] == pytest.approx(nominal[row["check"]].value, rel=1e-6, abs=1e-12)
        assert row["worst_margin"] <= nominal[row["check"]].margin + 1e-9


def test_monte_carlo_is_seeded_and_its_interval_holds_the_estimate():
    spec = govopt.load_spec(ROBUST)
    req = dz.requirements(spec)
    design = Design(flying_mass=4.0, wire_diameter=0.01, coil_radius=0.039,
                           active_turns=9.5, free_half_length=0.13533890618217037,
                           dashpot=0.8614620504172288)  # the nominal optimum: not robust
    req = dataclasses.replace(req, robust_samples=400, robust_seed=11)
    spec = dataclasses.replace(spec, requirements=req)
    a, b = rb.monte_carlo(spec, req, design), rb.monte_carlo(spec, req, design)
    assert a == b
    assert 0.0 < a["probability"] < 1.0  # some springs within the box fail it
    assert set(a["failing_checks"]) == {"shear stress"}  # the small coil diameters
    assert a["failing_checks"]["shear stress"] == a["samples"] - a["holds"]
    lo, hi = a["ci95"]
    assert lo < a["probability"] < hi


def test_textbook_robust_design_holds_at_its_corners():
    """The spring-loaded robust spec: EN 15800 grade 2 on the coil diameter and an adjusting nut
    of +-3 mm. At either end of the coil tolerance some nut setting within its range passes every
    check (l0 is the whole free length, spring_length_factor 1): searched on a 1/20 mm grid
    through the ordinary evaluator, independently of the optimiser's own corner code."""
    spec = govopt.load_spec(TEXTBOOK)
    res = search.design(spec)
    design = _design(res)
    D = 2.0 * design.coil_radius
    half_r = float(tl.coil_diameter_tolerance(D, D / design.wire_diameter, 2)) / 2.0
    for sr in (-1, 1):
        held = False
        for nut in np.linspace(-0.003, 0.003, 121):
            c = dataclasses.replace(design, coil_radius=design.coil_radius + sr * half_r,
                                    free_half_length=design.free_half_length + nut)
            failed = [ck.name for ck in govopt.evaluate(spec.with_design(c)).checks
                      if not ck.passed and "mass >= min" not in ck.name
                      and "mass <= max" not in ck.name]
            if not failed:
                held = True
                break
        assert held, sr
    rec = res.optimisation["robust"]
    assert rec["cost"]["robust_objective_kg"] >= rec["cost"]["nominal_objective_kg"]


def test_adjusting_nut_and_valve_ranges_are_reported_within_their_ranges(tmp_path):
    text = open(ROBUST).read().replace("# no adjusting_nut: the fitter adjusts nothing",
                                       'adjusting_nut = "2 mm"\nrobust_masses = 0.01\n'
                                       "dashpot_valve = 0.5")
    path = tmp_path / "nut.toml"
    path.write_text(text)
    res = search.design(govopt.load_spec(path))
    nut = res.optimisation["robust"]["adjusting_nut"]
    assert nut["range_m"] == [-0.002, 0.002]
    lo, hi = nut["needed_range_m"]
    assert -0.002 <= lo <= hi <= 0.002
    assert nut["nominal_setting_m"] == 0.0
    assert nut["free_half_length_at_nominal_setting_m"] == \
        res.optimisation["design"]["free_half_length_m"]
    valve = res.optimisation["robust"]["dashpot_valve"]
    f = res.optimisation["design"]["dashpot_N_m_s_per_rad"]
    assert valve["range_N_m_s_per_rad"] == pytest.approx([0.5 * f, 1.5 * f])
    v_lo, v_hi = valve["needed_range_N_m_s_per_rad"]
    assert 0.5 * f <= v_lo <= v_hi <= 1.5 * f
    assert valve["nominal_setting_N_m_s_per_rad"] == f
    assert res.optimisation["robust"]["holds_at_every_corner"]


@pytest.mark.parametrize("line, key", [
    ("robust_spring_grade = 4", "robust_spring_grade"),
    ("robust_dashpot = -0.1", "robust_dashpot"),
    ('adjusting_nut = "2 kg"', "adjusting_nut"),
    ("robust_samples = 2.5", "robust_samples"),
])
def test_bad_robust_keys_are_one_line_errors(tmp_path, line, key):
    text = "".join(t for t in open(ROBUST).read().splitlines(keepends=True)
                   if not t.startswith(key + " "))
    text = text.replace("spring_index = [4, 16]\n", f"spring_index = [4, 16]\n{line}\n", 1)
    path = tmp_path / "bad.toml"
    path.write_text(text)
    run = invoke(["design", str(path)])
    assert run.exit_code == 2 and run.exception is None
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and key in lines[0], run.stderr


def test_robust_text_report():
    run = invoke(["design", ROBUST, "--full"])
    assert run.exit_code == 0, run.output
    assert "Worst case over the tolerance box" in run.stdout
    assert "probability every check holds" in run.stdout
    assert "robustness cost: increase" in run.stdout
    assert "points of the box evaluated" in run.stdout
    assert "checks not monotone in a tolerance" in run.stdout
    assert "found by" in run.stdout


def test_robust_json_says_where_each_worst_case_lies(robust):
    """Each check's worst case: a point of the box in half-widths of every tolerance (within
    -1..1), how it was found, and the tolerances it is not monotone in; the nominal value is
    the evaluator's at nominal parts."""
    rec = robust.optimisation["robust"]
    assert rec["holds_over_the_box"] and rec["points_evaluated"] >= rec["corners"] == 4
    for row in rec["checks"]:
        assert set(row["worst_at"]) == {"coil_radius", "dashpot"}
        assert all(-1.0 <= v <= 1.0 for v in row["worst_at"].values())
        assert row["found_by"] in ("nominal", "corner", "edge", "inner maximisation")
        if row["found_by"] == "corner":
            assert all(abs(v) == 1.0 for v in row["worst_at"].values())
        assert set(row["not_monotone_in"]) <= {"coil_radius", "dashpot"}


def test_speed_band_plot_states_the_cost(robust):
    """The speed-band plot's title gives what robustness cost (the record's increase)."""
    from matplotlib.figure import Figure

    from govopt.report.plots import speed_band

    ax = Figure().add_subplot()
    speed_band(robust, ax)
    more = robust.optimisation["robust"]["cost"]["increase_percent"]
    assert f"robustness cost {more:+.3g} %" in ax.get_title()
    assert more > 0


def test_no_robust_candidate_names_the_check_that_fails(tmp_path):
    """Bounds that admit only the nominal optimum's neighbourhood (d 10 mm, r 39 mm, n <= 9.5):
    it is feasible at nominal values but its stress fails at the small coil diameter."""
    text = open(ROBUST).read()
    for old, new in (('wire_diameter = ["5 mm", "25 mm"]', 'wire_diameter = ["9.5 mm", "10.5 mm"]'),
                     ('coil_radius = ["3 cm", "8 cm"]', 'coil_radius = ["3.85 cm", "3.95 cm"]'),
                     ("active_turns = [3, 20]", "active_turns = [3, 9.5]")):
        assert old in text
        text = text.replace(old, new)
    path = tmp_path / "tight.toml"
    path.write_text(text)
    run = invoke(["design", str(path)])
    assert run.exit_code == 2 and run.exception is None
    assert "infeasible: requirements.robust_*" in run.stderr
    assert "'shear stress' fails at a corner" in run.stderr
    assert len(run.stderr.strip().splitlines()) == 1


def test_speed_band_is_the_spring_sheets_tolerance_spread(robust, tmp_path):
    """Over a box of the spring alone (the dash-pot does not move the statics) the band's ends
    are the spring sheet's EN 15800 spread of the governed speeds (its own corners,
    govopt.analysis.spring_record.spread), and the plot is written."""
    from govopt.report.plot_files import write_plots

    band = robust.optimisation["robust"]["speed_band"]
    sheet = robust.to_dict()["spring_sheet"]["tolerance_spread"]
    inner, outer = sheet["omega_inner_range_rad_s"], sheet["omega_outer_range_rad_s"]
    assert [band["lowest_rad_s"][0], band["highest_rad_s"][0]] == pytest.approx(inner, rel=1e-9)
    assert [band["lowest_rad_s"][-1], band["highest_rad_s"][-1]] == pytest.approx(outer,
                                                                                  rel=1e-9)
    nominal = robust.statics.omega
    assert np.all(np.array(band["lowest_rad_s"]) <= nominal + 1e-12)
    assert np.all(np.array(band["highest_rad_s"]) >= nominal - 1e-12)
    paths = write_plots(robust, tmp_path, formats=("png",))
    assert any(p.name.endswith("speed-band.png") and p.stat().st_size > 0 for p in paths)


def test_robust_record_in_the_workbook(tmp_path):
    import openpyxl

    path = tmp_path / "robust.xlsx"
    run = invoke(["design", TEXTBOOK, "--xlsx", str(path)])
    assert run.exit_code == 0, run.output
    cells = {v for ws in openpyxl.load_workbook(path) for row in ws.iter_rows(values_only=True)
             for v in row if isinstance(v, str)}
    assert "Worst case over the tolerance box (after adjustment)" in cells
    assert "probability every check holds" in cells


# ---------------------------------------------------------------------------------------------
# Work bounded by govopt's limits, each evaluation counted at its cost (limits.evaluation_seconds)


def _with(path: str, text: str):
    """The spec at ``path`` with ``text`` added to its [requirements] table."""
    import tomllib

    from govopt.spec import parse_spec

    data = tomllib.loads(open(path, encoding="utf-8").read())
    data["requirements"].update(tomllib.loads(text))
    return parse_spec(data, path)


def test_an_evaluation_costs_what_its_parts_cost():
    """A forced vibration (design by design) makes each robust evaluation ten times the
    vectorised statics and transients: the vibration limit's samples count at that cost."""
    plain = govopt.load_spec(ROBUST)
    shaking = _with(ROBUST, 'max_vibration = "25 deg"')
    row, vib = (rb.row_seconds(s, dz.requirements(s)) for s in (plain, shaking))
    assert vib > 9 * row
    assert rb.work_errors(plain, dz.requirements(plain)) is None


@pytest.mark.parametrize(("text", "key", "words"), [
    # a vibration limit and the largest sample count: ~7 minutes of samples, refused at once
    ('max_vibration = "25 deg"\nrobust_samples = 100000', "requirements.robust_samples",
     "at most 2241 samples for this spec"),
    # every tolerance and both fitter's adjustments: 81 settings at every corner and edge
    ('max_vibration = "25 deg"\nrobust_masses = 0.02\nrobust_torque_slope = 0.1\n'
     'adjusting_nut = "2 mm"\ndashpot_valve = 0.2', "requirements",
     "the tolerance box of 4 quantities (16 corners) at each of the fitter's 81 settings"),
])
def test_robust_work_past_the_limits_is_refused_before_it_runs(text, key, words):
    spec = _with(ROBUST, text)
    with pytest.raises(govopt.errors.InfeasibleError) as err:
        search.design(spec)
    assert str(err.value).startswith(f"{ROBUST}: {key}: {words}"), str(err.value)


def test_the_search_stops_at_its_limit_with_a_diagnosis(monkeypatch):
    """A search that reaches its limit of work stops and says so (the textbook's robust spring
    governor checks 72 candidates, ~0.56 s of counted work; here the limit is 0.2 s)."""
    monkeypatch.setattr(rb.limits, "MAX_ROBUST_SEARCH_SECONDS", 0.2)
    spec = govopt.load_spec(TEXTBOOK)
    with pytest.raises(govopt.errors.InfeasibleError,
                       match=r"stopped at govopt's limit of work \(~0.2 s\)"):
        rb.robust_search(spec, dz.requirements(spec))


def test_the_verification_stops_adjusting_at_its_limit_and_says_so(monkeypatch):
    """The textbook's robust governor: 2000 samples, then the fitter's nut for those that fail
    (5057 evaluations in all, ~2.1 s counted). With a limit that takes the samples but not the
    adjustments, the failing samples count as failing: the probability is a lower bound, and
    the record says so."""
    spec = govopt.load_spec(TEXTBOOK)
    req = dz.requirements(spec)
    cand, _, _ = rb.robust_search(spec, req)
    design = rb.design_of(spec, cand)
    full = rb.monte_carlo(spec, req, design)
    assert "note" not in full and full["adjusted_by_the_fitter"] > 0
    monkeypatch.setattr(rb.limits, "MAX_MONTE_CARLO_SECONDS",
                        2.05 * req.robust_samples * rb.row_seconds(spec, req))
    cut = rb.monte_carlo(spec, req, design)
    assert "lower bound" in cut["note"]
    assert cut["holds"] < full["holds"] and cut["evaluations"] < full["evaluations"]
