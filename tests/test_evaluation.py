"""govopt.evaluate with a design passed in (not the spec's own): every analysis reads that
design, not the spec's ``[design]``; check names use the type's own word for its flying mass."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import govopt
from govopt.analysis import friction

SPECS = Path(__file__).resolve().parent.parent / "specs"


def _porter_with_friction(tmp_path):
    text = (SPECS / "porter-engine.toml").read_text().replace(
        'sleeve_offset = "3.76 cm"', 'sleeve_offset = "3.76 cm"\nsleeve_friction = "1 kgf"')
    path = tmp_path / "porter-friction.toml"
    path.write_text(text)
    return govopt.load_spec(path)


def test_friction_run_uses_the_evaluated_design(tmp_path):
    """A dash-pot given with the design (not in the spec's [design]) reaches Hamabe's friction
    transient (eqs. 42-46): its f is the evaluated design's, and evaluate(spec, design) equals
    evaluate(spec.with_design(design))."""
    spec = _porter_with_friction(tmp_path)
    other = replace(spec.design, dashpot=2.0 * spec.design.dashpot)
    res = govopt.evaluate(spec, other)
    fr = res.dynamics["friction"][0]
    assert fr["f_N_s_per_m"] == pytest.approx(other.dashpot, rel=1e-15)
    ref = friction.friction_load_change(spec.with_design(other), None,
                                        spec.load_changes[0]).to_dict()
    assert fr["first_stroke_end_m"] == ref["first_stroke_end_m"]
    same = govopt.evaluate(spec.with_design(other))
    assert [(c.name, c.value) for c in res.checks] == [(c.name, c.value) for c in same.checks]


@pytest.mark.parametrize("name, stem", [("hartnell-design.toml", "ball"),
                                        ("traction-coil-design.toml", "fly"),
                                        ("hamabe-design.toml", "pendulum")])
def test_search_bounds_are_no_checks_and_name_the_types_mass(name, stem):
    """The design's search bounds are not checks of the design (a made part is not held to
    them); its record states every bound searched, the flying mass's under the type's key."""
    from govopt.optimize.design import design

    res = design(govopt.load_spec(SPECS / name))
    names = [c.name for c in res.checks]
    assert not any(n.endswith((">= min", "<= max")) and "index" not in n for n in names)
    assert all(c.group != "bounds" for c in res.checks)
    searched = res.optimisation["search_bounds"]
    assert searched[0]["name"] == f"{stem}_mass"
    assert {b["name"] for b in searched} >= {"wire_diameter", "coil_radius", "active_turns"}
    assert any(n.startswith("search bounds ([bounds]): ") for n in res.optimisation["notes"])


def test_gp_forms_are_the_rows():
    """Each requirement row with a GP form: the form's g at a design is the row's value there,
    with the same sense, and its limit is the GP parameter the design search fills from the
    row's limit (one declaration for the evaluator, the screen and the GP)."""
    from govopt.optimize import gp_table
    from govopt.requirements import SpringFigures, requirement_rows, search_bound_rows

    spec = govopt.load_spec(SPECS / "hamabe-design.toml")
    req, mat = spec.requirements, spec.material
    d, r, n, l0 = 0.004, 0.02, 9.0, 0.05
    ev = SpringFigures(d, r, n, l0, mat, m=1.0)
    P = {"G": mat.shear_modulus, "density": mat.density}
    rows = [row for row in (*requirement_rows(spec, req), *search_bound_rows(req))
            if row.gp is not None]
    assert {row.gp.limit for row in rows} >= {"d_min", "d_max", "r_min", "r_max", "n_min",
                                             "n_max", "C_min", "C_max", "L_body_max"}
    for row in rows:
        g = row.gp.g(d, r, n, None, P)
        assert g == pytest.approx(float(row.value(ev)), rel=1e-14), row.name
        assert row.gp.sense == {"<=": "upper", ">=": "lower"}[row.sense]
    values = gp_table.complete_values(dict(kappa_min=1e3, kappa_max=2e3, F_max=100.0, k_s=5e8,
                                           G=mat.shear_modulus, density=mat.density,
                                           **{row.gp.limit: row.limit(ev) for row in rows}),
                                      "band")
    for row in rows:
        assert values[row.gp.limit] == pytest.approx(float(row.limit(ev)), rel=1e-15)


def test_screen_reads_the_rows():
    """The design screen's spring test (optimize.catalogue_search.spring_checks) holds exactly
    where the spring rows hold: narrowing requirements.spring_index moves both the same way."""
    import numpy as np

    from govopt.optimize.catalogue_search import spring_checks
    from govopt.requirements import SpringFigures, holds, requirement_rows

    spec = govopt.load_spec(SPECS / "hamabe-design.toml")
    req = replace(spec.requirements, spring_index=(6.0, 8.0))
    d = np.full(5, 0.004)
    r = d * np.array([2.0, 3.0, 3.5, 4.0, 5.0])  # C = 4, 6, 7, 8, 10
    n, l0 = np.full(5, 8.0), np.full(5, 1.0)
    ok = spring_checks(spec, req, d, r, n, np.full(5, 1.0), l0)
    rows = [row for row in requirement_rows(spec, req) if row.group == "spring"]
    in_rows = holds(rows, SpringFigures(d, r, n, l0, spec.material))
    assert in_rows.tolist() == [False, True, True, True, False]
    assert not (ok & ~in_rows).any()  # the screen admits nothing the rows reject


def test_diagnosis_names_the_types_weight_key(tmp_path):
    """A Hartnell spec whose ball weights are too light: the diagnosis's move names the spec
    key to widen (bounds.ball_weight), not the shaft governor's pendulum."""
    from govopt.errors import InfeasibleError
    from govopt.optimize.design import design

    text = (SPECS / "hartnell-design.toml").read_text()
    assert 'ball_weight = ["1 kgf", "6 kgf"]' in text
    path = tmp_path / "light.toml"
    path.write_text(text.replace('ball_weight = ["1 kgf", "6 kgf"]',
                                 'ball_weight = ["0.2 kgf", "0.3 kgf"]'))
    with pytest.raises(InfeasibleError) as info:
        design(govopt.load_spec(path))
    assert "bounds.ball_weight 0.2 .. 0.3 kgf -> " in str(info.value)
    assert "pendulum" not in str(info.value)


@pytest.mark.parametrize("name", ["hamabe-a.toml", "hamabe-d.toml", "textbook-ex4-hartnell.toml",
                                  "traction-leaf-weights.toml", "porter-engine.toml"])
def test_evaluate_is_the_one_evaluator(name, monkeypatch):
    """evaluate is govopt.evaluator.core with one design: its checks and report come from the
    core's figures, with no scalar statics, k^2 or load-change computation beside it (the
    former twin) - those entry points may fail and evaluate still gives its checks, the same
    as evaluate_many's row."""
    from govopt.analysis import characteristic as chs
    from govopt.analysis import loadchange, statics
    from govopt.bulk import evaluate_many, value_column

    spec = govopt.load_spec(SPECS / name)
    row = evaluate_many(spec, [spec.design]).iloc[0]

    def second(*args, **kwargs):
        raise AssertionError("a second computation of the design's figures")

    for module, fn in ((statics, "spring_design"), (chs, "characteristic"),
                       (statics, "restoring_k2"), (loadchange, "analyse")):
        monkeypatch.setattr(module, fn, second)
    res = govopt.evaluate(spec)
    assert res.checks
    for c in res.checks:
        assert row[value_column(c.name)] == c.value or (np.isnan(c.value) and np.isnan(
            row[value_column(c.name)])), c.name
