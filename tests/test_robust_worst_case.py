"""the worst case over a tolerance box where a check is not monotone in a tolerance -
an inner maximisation, checked against a dense grid and the ordinary evaluator."""

import dataclasses
import itertools

import numpy as np
import pytest
from clirun import invoke

import govopt
from govopt.bulk import design_arrays, evaluate_many, value_column
from govopt.optimize import design as dz
from govopt.optimize import robust as rb
from govopt.spec import Design

ROBUST = "specs/hamabe-design-robust.toml"
#: the robust optimum of hamabe-design-robust (d 10 mm, r 39 mm, n 10; docs/theory/design-search.md)
DESIGN = Design(flying_mass=4.0, wire_diameter=0.01, coil_radius=0.039, active_turns=10.0,
                free_half_length=0.1335489367461029, dashpot=0.9435718922634899)


def test_monotone_and_inner_minimum_on_a_constructed_function():
    """A bowl whose least value is inside the square: every edge through it is not monotone,
    the corners miss it, and the bounded search from the worst probed point finds it (the dense
    grid's least, to the grid's resolution)."""
    def f(t):
        return (t[:, 0] - 0.3) ** 2 + 0.5 * (t[:, 1] + 0.2) ** 2 - 0.1

    grid, along = rb.edges(2)
    values = f(grid.reshape(-1, 2)).reshape(grid.shape[:2])
    assert not rb.monotone(values).all()  # some edges turn back
    corners = np.array(list(itertools.product((-1.0, 1.0), repeat=2)))
    assert f(corners).min() > 0.0  # the corners all "hold"
    start = grid.reshape(-1, 2)[int(np.argmin(values))]
    x, v = rb.inner_minimum(f, start)
    dense = np.array(list(itertools.product(np.linspace(-1, 1, 201), repeat=2)))
    assert v <= f(dense).min() + 1e-6 and v < 0.0  # it fails inside (to the FD gradient's 1e-6)
    assert x == pytest.approx([0.3, -0.2], abs=1e-4)


@pytest.fixture(scope="module")
def box_case():
    """The nominal optimum with its flying mass +-5 % beside EN 15800 grade 2 and the dash-pot
    +-10 %: the irregularity (omega_outer - omega_inner) / omega_mean - each end's speed moves
    with the mass at its own rate (Hamabe eq. 12), and their difference turns back inside the
    box (a physical case, not a constructed one)."""
    spec = govopt.load_spec(ROBUST)
    req = dataclasses.replace(dz.requirements(spec), robust_masses=0.05)
    spec = dataclasses.replace(spec, requirements=req)
    cols = {k: v[:1] for k, v in design_arrays(spec.with_design(DESIGN), [DESIGN]).items()}
    box = rb.candidate_box(spec, req, cols)
    return spec, req, cols, box, rb.worst_case(spec, req, cols, box)


def test_a_check_not_monotone_in_a_tolerance_has_its_worst_case_inside_the_box(box_case):
    """The irregularity is found not monotone in the flying mass; its worst case, by the inner
    maximisation, lies inside the box, is worse than at every corner, and is the worst of a
    dense grid over the box evaluated independently (the bulk evaluator on every point)."""
    spec, req, cols, box, wc = box_case
    assert wc["dims"] == ["coil_radius", "dashpot", "flying_mass"]
    assert "flying_mass" in wc["not_monotone"]["irregularity"]
    irr = wc["frame"][value_column("irregularity")].to_numpy()
    w = int(np.argmax(irr))
    assert wc["found_by"][w] == "inner maximisation"
    assert -0.95 < wc["points"][w][2] < 0.95  # the mass inside its tolerance
    corner = np.array([f == "corner" for f in wc["found_by"]])
    assert irr[w] > irr[corner].max() * (1 + 1e-5)
    # the reference: a dense grid of the box (the dash-pot does not move the statics)
    t = np.array(list(itertools.product(np.linspace(-1, 1, 9), (-1.0, 1.0),
                                        np.linspace(-1, 1, 81))))
    half = {k: v[0] for k, v in box.fields.items()}
    dense = {k: np.repeat(v, len(t)) for k, v in cols.items()}
    for j, name in enumerate(wc["dims"]):
        dense[name] = dense[name] + t[:, j] * half[name]
    ref = evaluate_many(spec.with_design(DESIGN), dense, dynamics=False, vibration=False,
                        classic=False)[value_column("irregularity")]  # a statics figure
    assert irr[w] >= ref.max() * (1 - 1e-9)
    assert irr[w] == pytest.approx(ref.max(), rel=1e-6)  # the grid's step: 1/40 of a half-width
    assert ref.idxmax() not in np.nonzero(np.all(np.abs(t) == 1, axis=1))[0]


def test_a_limit_between_corners_and_inside_fails_inside(box_case):
    """With the irregularity's limit between its worst corner and its worst inside the box, the
    worst case fails though every corner holds - as the ordinary evaluator confirms at the
    corners and at the point found."""
    spec, req, cols, box, wc = box_case
    irr = wc["frame"][value_column("irregularity")].to_numpy()
    corner = np.array([f == "corner" for f in wc["found_by"]])
    limit = 0.5 * (irr.max() + irr[corner].max())
    tight = dataclasses.replace(spec, speed=dataclasses.replace(spec.speed, irregularity=limit))
    again = rb.worst_case(tight, req, cols, box)
    assert not again["holds"]
    margins = again["margins"][:, rb.robust_checks(again["frame"]).index("irregularity")]
    assert np.all(margins[np.array([f == "corner" for f in again["found_by"]])] >= 0)
    w = int(np.argmin(margins))
    half = {k: v[0] for k, v in box.fields.items()}
    made = dataclasses.replace(DESIGN, **{name: getattr(DESIGN, name) + again["points"][w][j]
                                          * half[name] for j, name in enumerate(again["dims"])})
    failed = [c.name for c in govopt.evaluate(tight.with_design(made)).checks
              if not c.passed and not any(b in c.name for b in rb.BOUND_NAMES)]
    assert failed == ["irregularity"]
    for signs in itertools.product((-1.0, 1.0), repeat=3):
        corner_part = dataclasses.replace(DESIGN, **{
            name: getattr(DESIGN, name) + s * half[name]
            for s, name in zip(signs, again["dims"], strict=True)})
        res = govopt.evaluate(tight.with_design(corner_part))
        assert next(c for c in res.checks if c.name == "irregularity").passed


# ------------------------------------------------------------------ other governors, objectives


def _robust_copy(tmp_path, source, lines, name="robust.toml"):
    text = open(source).read().replace("[requirements]\n", "[requirements]\n" + lines, 1)
    path = tmp_path / name
    path.write_text(text)
    return path


def test_dead_weight_robust_design_holds_at_its_mass_corners(tmp_path):
    """A Porter governor (dead weight: no spring) with its balls and central load +-0.5 %: the
    robust design passes every check at each corner of the masses, by the ordinary evaluator;
    the nominal optimum does not (its band is at the spec's edge), so robustness costs."""
    path = _robust_copy(tmp_path, "specs/porter-design.toml", "robust_masses = 0.005\n")
    spec = govopt.load_spec(path)
    res = govopt.design(spec)
    rec = res.optimisation["robust"]
    assert rec["holds_over_the_box"] and rec["monte_carlo"]["probability"] == 1.0
    o = res.optimisation["design"]
    ball, central = o["ball_mass_kg"], o["central_mass_kg"]
    nominal = rec["cost"]["nominal_design"]

    def failures_at_corners(m, c):
        out = set()
        for sm, sc in itertools.product((-1, 1), repeat=2):
            d = Design(flying_mass=m * (1 + 0.005 * sm), central_mass=c * (1 + 0.005 * sc))
            out |= {ck.name for ck in govopt.evaluate(spec.with_design(d)).checks
                    if not ck.passed and not any(b in ck.name for b in rb.BOUND_NAMES)}
        return out

    assert failures_at_corners(ball, central) == set()
    assert failures_at_corners(nominal["ball_mass_kg"], nominal["central_mass_kg"])
    assert rec["cost"]["robust_objective_kg"] > rec["cost"]["nominal_objective_kg"]
    assert rec["speed_band"]["lowest_rad_s"][0] < res.statics.omega[0]


@pytest.mark.parametrize("source, lines, key, words", [
    (ROBUST, 'objective = "settling_time"\n', "requirements.objective",
     "requirements.max_settling_time"),
    ("specs/porter-design.toml", "robust_spring_grade = 2\n",
     "requirements.robust_spring_grade", "no spring"),
    ("specs/porter-design.toml", 'adjusting_nut = "2 mm"\n', "requirements.adjusting_nut",
     "no spring"),
    ("specs/traction-leaf-design.toml", "robust_spring_grade = 2\n",
     "requirements.robust_spring_grade", "leaf spring"),
    ("specs/spring_loaded-design.toml", "robust_dashpot = 0.1\n",
     "requirements.robust_dashpot", "[[load_change]]"),
])
def test_robust_designs_it_cannot_make_are_one_line_errors(tmp_path, source, lines, key, words):
    """Each says which key, why, and what to do instead; exit code 2, no traceback."""
    text = open(source).read()
    if "objective =" in lines:
        text = text.replace('objective = "moving_mass"', lines.strip(), 1)
    else:
        text = text.replace("[requirements]\n", "[requirements]\n" + lines, 1)
    path = tmp_path / "bad.toml"
    path.write_text(text)
    run = invoke(["design", str(path)])
    assert run.exit_code == 2 and run.exception is None
    lines_out = run.stderr.strip().splitlines()
    assert len(lines_out) == 1 and lines_out[0].startswith("error: "), run.stderr
    assert key in lines_out[0] and words in lines_out[0]
