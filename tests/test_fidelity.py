"""Fidelity by use case: a use case runs only its analyses, each at the
cheapest setting whose measured error fits the tolerance, and says which models it used."""

import dataclasses
from collections import Counter

import pytest

import govopt
from govopt import fidelity
from govopt.analysis import friction, loadchange
from govopt.examples import SPECS
from govopt.governors.shaft import vibration

KGFCM = 9.80665 * 0.01

#: use case -> the analyses beyond the statics it must run (and no others)
EXPECTED = {
    "spring_sizing": set(),
    "vibration": {"vibration"},
    "load_change": {"load_change"},
    "friction": {"friction"},
    "full": {"vibration", "load_change", "friction"},
}


@pytest.fixture(scope="module")
def spec():
    """Hamabe's case a with fulcrum friction (22.6 kgf cm), so every analysis has its data."""
    s = govopt.load_spec(str(SPECS / "hamabe-a.toml"))
    return s.with_design(dataclasses.replace(s.design, friction_moment=22.6 * KGFCM))


@pytest.fixture
def calls(monkeypatch):
    """Count the calls of each analysis's entry point."""
    counts = Counter()

    def counting(module, name, key):
        original = getattr(module, name)

        def wrapper(*args, **kwargs):
            counts[key] += 1
            return original(*args, **kwargs)

        monkeypatch.setattr(module, name, wrapper)

    counting(loadchange, "summary", "load_change")  # evaluate's report of each load change
    counting(vibration, "vibrations", "vibration")  # every design's at once (one, here)
    counting(friction, "friction_load_change", "friction")
    return counts


def test_without_a_use_case_every_analysis_runs(spec, calls):
    res = govopt.evaluate(spec)
    assert set(calls) == EXPECTED["full"]
    assert "use_case" not in res.to_dict()


@pytest.mark.parametrize("use_case", list(EXPECTED))
def test_each_use_case_runs_only_its_analyses(spec, calls, use_case):
    res = govopt.evaluate(spec.with_analysis(use_case=use_case, tolerance=1e-6))
    assert {k for k, v in calls.items() if v} == EXPECTED[use_case]
    out = res.to_dict()
    plan = out["use_case"]
    assert plan["name"] == use_case and plan["tolerance"] == 1e-6
    assert {a["analysis"] for a in plan["analyses"]} == {"statics"} | EXPECTED[use_case]
    assert set(plan["not_run"]) == EXPECTED["full"] - EXPECTED[use_case]
    for a in plan["analyses"]:
        assert a["model"] and a["measured_error"] >= 0 and a["cpu_s_per_evaluation"] > 0
    # what did not run leaves no trace in the result
    assert ("load_changes" in out) == ("load_change" in EXPECTED[use_case])
    assert ("vibration" in out) == ("vibration" in EXPECTED[use_case])
    assert ("friction" in out) == ("friction" in EXPECTED[use_case])


def test_spring_sizing_never_runs_the_friction_model(spec, calls):
    govopt.evaluate(spec.with_analysis(use_case="spring_sizing", tolerance=1e-12))
    assert calls["friction"] == 0 and calls["load_change"] == 0


def test_tolerance_changes_the_settings_chosen(spec, calls):
    """A looser tolerance takes fewer harmonics (cheaper), a tighter one more; each chosen
    setting's measured error fits its tolerance, and the evaluation used that setting."""
    loose = govopt.evaluate(spec.with_analysis(use_case="vibration", tolerance=1e-2))
    tight = govopt.evaluate(spec.with_analysis(use_case="vibration", tolerance=1e-6))
    n_loose, n_tight = (r.spec.analysis.harmonics for r in (loose, tight))
    assert n_loose < n_tight
    for res, tol, n in ((loose, 1e-2, n_loose), (tight, 1e-6, n_tight)):
        vib = next(a for a in res.to_dict()["use_case"]["analyses"] if a["analysis"] ==
                   "vibration")
        assert vib["setting"] == {"harmonics": n} and vib["fits_tolerance"]
        assert vib["measured_error"] <= tol
        assert len(res.to_dict()["vibration"]["harmonics"]) == n  # the evaluation used it
    assert calls["vibration"] == 2


@pytest.mark.parametrize("tol", [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7])
def test_choice_is_the_cheapest_that_fits(tol):
    """Against the measured table directly: no option that fits is cheaper."""
    table = fidelity.measured()
    rows = [table[o.row] for o in fidelity.OPTIONS["vibration"] if o.row in table]
    c = fidelity.choose("vibration", tol)
    fitting = [t for t, e in rows if e <= tol]
    if fitting:
        assert c.fits and c.error <= tol and c.time_s == min(fitting)
    else:  # nothing fits: the most accurate, said so
        assert not c.fits and c.error == min(e for _, e in rows)


def test_nothing_fits_is_reported(spec):
    res = govopt.evaluate(spec.with_analysis(use_case="vibration", tolerance=1e-15))
    vib = next(a for a in res.to_dict()["use_case"]["analyses"] if a["analysis"] == "vibration")
    assert not vib["fits_tolerance"]
    table = fidelity.measured()
    best = min(table[o.row][1] for o in fidelity.OPTIONS["vibration"] if o.row in table)
    assert vib["measured_error"] == best


def test_series_linkage_only_where_the_geometry_matters(spec):
    """The paper's series (eq. 3) is the shaft's linkage: a Porter has no such option."""
    porter = govopt.load_spec(str(SPECS / "porter-design.toml"))
    assert fidelity.OPTIONS["statics"][1].applies(spec)
    assert not fidelity.OPTIONS["statics"][1].applies(porter)
    for tol in (1.0, 1e-6):
        assert fidelity.choose("statics", tol, porter).setting == {"geometry": "exact"}


def test_load_change_reports_the_linear_models_own_error():
    c = fidelity.choose("load_change", 1e-6)
    assert c.fits and c.error <= 1e-12  # the solver against mpmath
    assert "nonlinear" in c.note  # and the linearisation, measured, is said


def test_spec_keys(tmp_path):
    src = open(str(SPECS / "hamabe-a.toml")).read()
    p = tmp_path / "uc.toml"
    p.write_text(src + '\n[analysis]\nuse_case = "vibration"\ntolerance = 1e-4\n')
    s = govopt.load_spec(p)
    assert (s.analysis.use_case, s.analysis.tolerance) == ("vibration", 1e-4)
    p.write_text(src + '\n[analysis]\nuse_case = "fast"\n')
    with pytest.raises(govopt.SpecError, match=r"analysis\.use_case"):
        govopt.load_spec(p)
    p.write_text(src + '\n[analysis]\nuse_case = "full"\ntolerance = -1\n')
    with pytest.raises(govopt.SpecError, match=r"analysis\.tolerance"):
        govopt.load_spec(p)
