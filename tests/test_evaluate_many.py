"""Bulk evaluation (govopt.bulk.evaluate_many): the same figures and margins as govopt.evaluate
for each design, for every governor type; error rows instead of exceptions."""

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from govopt import evaluate, load_spec
from govopt.bulk import (
    DESIGN_FIELDS,
    design_arrays,
    evaluate_many,
    margin_column,
    passed_column,
    result_row,
    value_column,
)
from govopt.spec import Design, with_values

SPECS = Path(__file__).resolve().parent.parent / "specs"
WITH_DESIGN = sorted(p.name for p in SPECS.glob("*.toml") if "[design]" in p.read_text())

#: relative agreement of a bulk figure with evaluate's (both are the same formulas in float64;
#: the vectorised path only reorders a few operations)
RTOL = 1e-12


def _same(a, b) -> bool:
    if isinstance(a, bool | str) or a is None or isinstance(b, bool | str) or b is None:
        na = a is None or (isinstance(a, float) and math.isnan(a)) or a is pd.NA
        nb = b is None or (isinstance(b, float) and math.isnan(b)) or b is pd.NA
        return (na and nb) or a == b
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    if math.isinf(a) or math.isinf(b):
        return a == b
    return abs(a - b) <= RTOL * max(abs(a), abs(b)) or abs(a - b) <= 1e-300


def _assert_row_is(row: dict, ref: dict, i: int) -> None:
    """A bulk row equals evaluate's row ``ref`` of the same design: status, message of an error,
    every figure and check (to rounding), and no column of its own with a value."""
    assert row["status"] == ref["status"], (i, row["message"], ref["message"])
    if ref["status"] == "error":
        assert row["message"] == ref["message"]
        return
    wrong = {k: (ref[k], row.get(k)) for k in ref if not _same(ref[k], row.get(k))}
    assert not wrong, wrong
    extra = [k for k, v in row.items() if k not in ref and not _same(v, None)]
    assert not extra, extra


def _reference(spec, design) -> dict:
    from govopt.errors import GovoptError

    try:
        return result_row(evaluate(spec.with_design(design)))
    except GovoptError as exc:
        return {"status": "error", "message": str(exc)}


def _designs(spec, n, seed):
    """``n`` designs scattered +-30 % around the spec's own (every given field)."""
    rng = np.random.default_rng(seed)
    cols = design_arrays(spec, {"flying_mass": np.full(n, spec.design.flying_mass)})
    for f in DESIGN_FIELDS:
        if f != "friction_moment" and np.isfinite(cols[f]).all():
            cols[f] = cols[f] * rng.uniform(0.7, 1.3, n)
    return cols


@pytest.mark.parametrize("name", WITH_DESIGN)
def test_rows_are_evaluate_rows(name):
    """Every bundled spec with a design, 6 scattered designs: each bulk row has exactly the
    columns of evaluate's row (checks, figures, objective, status, message), equal to 1e-12."""
    spec = load_spec(SPECS / name)
    cols = _designs(spec, 6, seed=len(name))
    frame = evaluate_many(spec, cols)
    assert len(frame) == 6
    for i in range(6):
        design = Design(**{f: None if np.isnan(cols[f][i]) else float(cols[f][i])
                           for f in DESIGN_FIELDS})
        ref = _reference(spec, design)
        _assert_row_is(frame.iloc[i].to_dict(), ref, i)


@pytest.mark.parametrize("change", ["range", 0.05])
@pytest.mark.parametrize("name", ["textbook-ex1-porter.toml", "textbook-ex4-hartnell.toml",
                                  "hamabe-a.toml"])
def test_speed_change_is_the_specs_on_every_path(name, change):
    """The effort and power of a study's rows are for the spec's speed change, as evaluate's
    (they were for a fixed 1 % in bulk whatever [analysis] speed_change said)."""
    spec = load_spec(SPECS / name).with_analysis(speed_change=change)
    cols = _designs(spec, 4, seed=7)
    frame = evaluate_many(spec, cols)
    base = evaluate_many(load_spec(SPECS / name), cols)
    for i in range(4):
        design = Design(**{f: None if np.isnan(cols[f][i]) else float(cols[f][i])
                           for f in DESIGN_FIELDS})
        ref = _reference(spec, design)
        if ref["status"] == "error":
            continue
        for key in ("effort", "power"):
            assert _same(ref[key], frame.iloc[i][key]), (i, key, ref[key], frame.iloc[i][key])
        assert not _same(base.iloc[i]["effort"], frame.iloc[i]["effort"])  # it does move


def test_hamabe_case_a_row():
    """Hamabe case a as one row: the check columns carry evaluate's numbers; the irregularity
    misses 0.12 (the paper rounds its stiffness; exact geometry gives 0.1243: see
    docs/theory/shaft.md, where the paper is wrong), so the row fails on that check alone."""
    spec = load_spec(SPECS / "hamabe-a.toml")
    row = evaluate_many(spec, [spec.design]).iloc[0]
    res = evaluate(spec)
    c = res.check("irregularity")
    assert row[value_column("irregularity")] == pytest.approx(c.value, rel=RTOL)
    assert row[margin_column("irregularity")] == pytest.approx((0.12 - c.value) / 0.12,
                                                               rel=1e-12)
    assert 0.124 < row["irregularity"] < 0.125
    assert row[passed_column("irregularity")] is np.False_ or not row[passed_column("irregularity")]
    assert row["status"] == "fail" and row["message"] == "fails: irregularity"
    # the spring's stiffness G d^4 / (64 r^3 n) (Hamabe Ex. 1), from the design's own numbers
    G = spec.material.shear_modulus
    assert row["stiffness_N_per_m"] == pytest.approx(G * 0.017**4 / (64 * 0.06**3 * 8), rel=1e-14)


def test_inputs_frame_dict_and_designs_agree():
    spec = load_spec(SPECS / "textbook-ex7-spring_loaded.toml")
    masses = np.array([0.9, 1.0, 1.1]) * spec.design.flying_mass
    a = evaluate_many(spec, {"flying_mass": masses})
    b = evaluate_many(spec, pd.DataFrame({"flying_mass": masses}))
    c = evaluate_many(spec, [replace(spec.design, flying_mass=float(m)) for m in masses])
    pd.testing.assert_frame_equal(a, b)
    pd.testing.assert_frame_equal(a, c)
    with pytest.raises(ValueError, match="unknown design columns"):
        evaluate_many(spec, {"pendulum_weight": masses})


def test_error_rows_never_raise():
    """A wire thicker than its coil, a spring too soft to hold the governor (no equilibrium or
    a free length <= 0) and a NaN mass are rows with status 'error', evaluate's own message
    where evaluate gives one; the other rows are unaffected."""
    spec = load_spec(SPECS / "hamabe-a.toml")
    d0 = spec.design
    designs = [d0, replace(d0, wire_diameter=0.13), replace(d0, active_turns=400.0),
               replace(d0, flying_mass=float("nan")), d0]
    frame = evaluate_many(spec, {f: [np.nan if getattr(d, f) is None else getattr(d, f)
                                     for d in designs] for f in DESIGN_FIELDS},
                          vibration=False)
    assert list(frame["status"]) == ["fail", "error", "error", "error", "fail"]
    assert "thinner than the coil diameter" in frame["message"][1]
    assert frame["message"][2] == _reference(spec, designs[2])["message"]
    assert frame["irregularity"][0] == frame["irregularity"][4]
    assert np.isnan(frame["irregularity"][1])


def test_fast_path_is_a_subset():
    """With dynamics, vibration and classic measures off, the remaining columns are the full
    path's, to the bit."""
    spec = load_spec(SPECS / "hamabe-c.toml")
    cols = _designs(spec, 40, seed=3)
    full = evaluate_many(spec, cols)
    fast = evaluate_many(spec, cols, dynamics=False, vibration=False, classic=False)
    assert "settling_time_s" in full and "settling_time_s" not in fast
    assert "power" in full and "power" not in fast
    shared = [c for c in fast.columns if c not in ("status", "message")]
    pd.testing.assert_frame_equal(fast[shared], full[shared])


def test_chunks_do_not_change_rows():
    spec = load_spec(SPECS / "hamabe-d.toml")
    cols = _designs(spec, 25, seed=5)
    a = evaluate_many(spec, cols, vibration=False, chunk=7)
    b = evaluate_many(spec, cols, vibration=False, chunk=1000)
    pd.testing.assert_frame_equal(a, b)


@pytest.mark.parametrize("use_case", ["spring_sizing", "vibration", "load_change"])
def test_use_case_is_honoured(use_case):
    """``[analysis] use_case`` (govopt.fidelity): bulk rows run the use case's analyses at its
    settings, as evaluate does (a spring sizing has no load change columns)."""
    spec = with_values(load_spec(SPECS / "hamabe-a.toml"),
                       {"analysis.use_case": use_case, "analysis.tolerance": 1e-3})
    cols = design_arrays(spec, {"flying_mass": [11.0, 12.5]})
    frame = evaluate_many(spec, cols)
    for i in range(2):
        design = Design(**{f: None if np.isnan(cols[f][i]) else float(cols[f][i])
                           for f in DESIGN_FIELDS})
        ref = _reference(spec, design)
        row = frame.iloc[i].to_dict()
        assert ref["status"] != "error", ref["message"]
        assert all(_same(v, row.get(k)) for k, v in ref.items()), use_case
        assert not [k for k, v in row.items() if k not in ref and not _same(v, None)]
    assert ("settling_time_s" in frame) == (use_case == "load_change")


@pytest.mark.parametrize("name, borrow", [
    ("hamabe-a.toml", None),  # friction moments: Hamabe's strokes (eqs. 42-46) in the core
    ("hamabe-design-fatigue.toml", "hamabe-a.toml"),  # a wire grade's own table, with fatigue
    ("traction-leaf-weights.toml", None),  # a leaf: its own rate, stress and table
])
def test_one_evaluator_no_fallback(name, borrow, monkeypatch):
    """Every design goes through the one evaluator (govopt.evaluator.core): the designs that
    used to be handed to govopt.evaluate one by one (friction in a spec with load changes, a
    graded wire, a leaf spring, an impossible design) are rows of the core, equal to evaluate's
    results, and evaluate is never called."""
    from govopt import evaluator

    spec = load_spec(SPECS / name)
    if borrow:
        spec = spec.with_design(load_spec(SPECS / borrow).design)
    cols = _designs(spec, 5, seed=11)
    if spec.governor.coordinate == "angle":
        cols["friction_moment"] = np.array([0.0, 0.3, 2.0, np.nan, 0.3])
    if spec.governor.spring == "leaf":
        cols["leaf_thickness"][4] = 0.0  # no leaf: the dead loads push it out, an error row
    else:
        cols["flying_mass"][4] *= 40.0  # far too heavy for its spring: an error row
    refs = []
    for i in range(5):
        design = Design(**{f: None if np.isnan(cols[f][i]) else float(cols[f][i])
                           for f in DESIGN_FIELDS})
        refs.append(_reference(spec, design))
    assert refs[4]["status"] == "error"

    def no_fallback(*args, **kwargs):
        raise AssertionError("evaluate_many called govopt.evaluate")

    monkeypatch.setattr(evaluator, "evaluate", no_fallback)
    frame = evaluate_many(spec, cols)
    for i, ref in enumerate(refs):
        _assert_row_is(frame.iloc[i].to_dict(), ref, i)
    if spec.governor.coordinate == "angle":
        assert any(k.startswith("passed: friction:") for k in frame.columns)


def test_more_checks_than_bits_in_an_integer():
    """Twenty load changes (govopt's limit) give a Porter on an engine more than 62 checks: the
    rows' status still names every failing check (the failure bits as Python integers past
    62, not an overflow)."""
    spec = load_spec("specs/porter-engine.toml")  # with sleeve friction: its rows too
    changes = [{"name": f"change {i}", "from": "21 cm", "to": f"{22 + i / 20:.3f} cm"}
               for i in range(20)]
    data = dict(spec.data, load_change=changes,
                governor=dict(spec.data["governor"], sleeve_friction="1 kgf"))
    many = with_values(replace(spec, data=data), {})
    frame = evaluate_many(many, [many.design, many.design])
    names = [c for c in frame.columns if c.startswith("passed: ")]
    assert len(names) > 62
    failing = [c[len("passed: "):] for c in names if frame[c].iloc[0] == False]  # noqa: E712
    assert frame["status"].iloc[0] == ("fail" if failing else "pass")
    for name in failing:
        assert name in frame["message"].iloc[0]
