"""Governors made to their tolerances: one tolerance model read by the worst case, the yield's
samples and a tolerance study; the yield beside the verdict; design for a yield; histograms of
degenerate samples."""

import json
import math
import re

import numpy as np
import pytest
from clirun import invoke

import govopt
from govopt import made
from govopt.analysis import tolerance as tm
from govopt.examples import SPECS
from govopt.made_words import percent, yield_words
from govopt.stats import wilson

HARTNELL = SPECS / "hartnell-tolerances.toml"
#: a design of the bundled Hartnell (its spring of EN 10270-1 DH wire, EN 15800 grade 2)
DESIGN = """
[design]
ball_weight = "1 kgf"
wire_diameter = "4 mm"
coil_radius = "17 mm"
active_turns = 9.5
free_length = "14.49 cm"
"""


def _designed(tmp_path, extra: str = "") -> govopt.Spec:
    text = HARTNELL.read_text(encoding="utf-8")
    if extra:
        text = text.replace("[requirements]\n", "[requirements]\n" + extra, 1)
    path = tmp_path / "h.toml"
    path.write_text(text + DESIGN, encoding="utf-8")
    return govopt.load_spec(path)


@pytest.mark.parametrize("extra", ["", "robust_masses = 0.02\n"])
def test_the_worst_case_bounds_every_sample(tmp_path, extra):
    """The worst case over the box (its corners: the speeds are monotone in each toleranced
    quantity) holds every sampled governor's speeds at both ends of the range, as made; the
    box is the model's (the wire after EN 10270-1, the coil and the free length after EN
    15800 grade 2, the masses where spread)."""
    spec = _designed(tmp_path, extra)
    res = govopt.evaluate(spec)
    cols = made.resolved_columns(spec, res)
    bx = tm.stated(spec, cols).known()
    assert bx.active()[:3] == ["wire_diameter", "coil_radius", "free_half_length"]
    assert ("flying_mass" in bx.active()) == bool(extra)
    band = tm.speed_band(spec, cols, bx)
    rows, torque = made.draw(cols, bx, 400, seed=3)
    frame = made.evaluate_at(spec, rows, torque)
    for end in ("inner", "outer"):
        w = frame[f"omega_{end}_rad_s"].to_numpy(dtype=float)
        lo, hi = band[f"{end}_rad_s"]
        # rounding only: the corners are the extremes exactly
        assert np.all(w >= lo * (1 - 1e-12)) and np.all(w <= hi * (1 + 1e-12)), end
        assert w.min() < w.max()  # the samples do spread
    # the corners bound the box's interior: a dense grid of the box's points stays inside
    grid = np.array(np.meshgrid(*[np.linspace(-1, 1, 5)] * len(bx.active()))).reshape(
        len(bx.active()), -1).T
    inner = made.evaluate_at(spec, tm.at(cols, bx, grid), None)["omega_inner_rad_s"]
    assert inner.min() >= band["inner_rad_s"][0] * (1 - 1e-12)
    assert inner.max() <= band["inner_rad_s"][1] * (1 + 1e-12)


def test_a_tolerance_study_samples_the_same_model(tmp_path):
    """`study --tolerance grade=2` draws the model's quantities (the free length included) at
    the yield's points: as made, each row inside the worst case; as the fitter sets it, inside
    the required band (a governor the fitter cannot set stays as made)."""
    from govopt.study import run_study
    from govopt.study.definition import load_study
    from govopt.study.store import Store

    spec = _designed(tmp_path)
    res = govopt.evaluate(spec)
    band = made.with_yield(res).made["speed_band"]
    study = load_study(spec.path, tolerances=["grade=2"], samples=200)
    assert [t.key for t in study.tolerances] == ["design.wire_diameter", "design.coil_radius",
                                                 "design.free_length"]
    run_study(study, tmp_path / "t.db")
    with Store(tmp_path / "t.db") as store:
        table = store.table()
    req = band["required_rad_s"]
    for end in ("inner", "outer"):
        w = table[f"omega_{end}"].to_numpy(dtype=float)  # stored in rad/s
        lo = min(band[f"{end}_rad_s"][0], req[0])
        hi = max(band[f"{end}_rad_s"][1], req[1])
        assert np.all(w >= lo * (1 - 1e-12)) and np.all(w <= hi * (1 + 1e-12)), end


def test_the_yield_is_beside_the_verdict_deterministic_and_declared_once(tmp_path):
    """`evaluate` of a spec naming a wire grade prints the yield in its first lines, with its
    interval, the requirement failing most often and the worst-case band beside the required
    one; the same numbers in the JSON and the figures; the same answer twice (a stated seed)."""
    spec = _designed(tmp_path)
    run = invoke(["evaluate", str(spec.path)])
    assert run.exit_code == 0, run.output
    head = run.stdout.splitlines()[:10]
    line = next(x for x in head if "of made governors pass" in x)
    # the verdict is the made governor's (a wire grade's grade 2, the fitter's setting)
    assert line.startswith("PASS as made: ") and "(95 %: " in line
    assert any("worst-case speeds" in x and "beside the required 290-310 rpm" in x for x in head)
    assert any("Latin hypercube, seed 0" in x for x in head)
    out = json.loads(invoke(["evaluate", str(spec.path), "--json"]).stdout)
    again = json.loads(invoke(["evaluate", str(spec.path), "--json"]).stdout)
    y = out["made"]["yield"]
    assert y == again["made"]["yield"] and y["seed"] == 0
    assert y["samples"] == govopt.spec.Requirements().robust_samples  # as the design certifies
    assert y["ci95"] == list(wilson(y["holds"], y["samples"]))
    assert f"{percent(y['probability'])} of made governors pass" in line
    res = made.with_yield(govopt.evaluate(spec))
    figures = {f.name: f for f in res.figures() if f.group == "made"}
    assert figures["made governors passing"].value == y["probability"]
    fall, rise = out["made"]["speed_band"]["band_rad_s"]
    assert figures["worst-case lowest closing speed"].value == fall
    assert figures["worst-case highest opening speed"].value == rise
    assert fall < res.figure("lowest closing speed").value
    assert rise > res.figure("highest opening speed").value
    rows = res.to_frame()
    assert set(rows.loc[rows["group"] == "made", "name"]) == set(figures)


def test_no_tolerance_no_yield():
    """A spec that states no tolerance (no wire grade, no robust_* spread) is judged as made to
    the default grade (EN 15800 grade 2); asked for the nominal verdict, it reports no yield."""
    import dataclasses

    spec = govopt.load_spec(SPECS / "hamabe-a.toml")
    res = made.with_yield(govopt.evaluate(spec))
    assert res.made["tolerances"]["spring_grade"] == made.DEFAULT_GRADE
    assert res.made["yield"]["required"] == made.DEFAULT_MIN_YIELD
    spec = dataclasses.replace(spec, verdict="nominal")
    res = made.with_yield(govopt.evaluate(spec))
    assert res.made is None and "made" not in res.to_dict()
    assert res.to_dict()["verdict"]["of"] == "nominal"


def test_the_yield_in_words():
    """Near 1 the yield keeps two decimals (99.62 % is not 100 %); a certified yield says
    why it is 1."""
    rec = {"yield": {"probability": 0.9962, "ci95": [0.9921, 0.9981], "most_failing": "x",
                     "required": 0.99, "meets_required": True, "samples": 2000}}
    assert yield_words(rec) == ("99.62 % of made governors pass (95 %: 99.21-99.81 %); most "
                                "often failing: x; required >= 99.0 %: met")
    rec["yield"] |= {"certified": "worst case", "probability": 1.0}
    assert yield_words(rec).startswith("100 % of made governors pass (certified")


def test_min_yield_designs_for_a_yield(tmp_path):
    """`min_yield = 0.99` changes the design; its yield's 95 % Wilson lower bound is at least
    0.99 over the search's samples, and a fresh sample (another seed) of the design holds in at
    least 99 % of 1000 governors."""
    spec = govopt.load_spec(HARTNELL)
    plain = govopt.design(spec)
    text = HARTNELL.read_text(encoding="utf-8").replace(
        "[requirements]\n", "[requirements]\nmin_yield = 0.99\n", 1)
    (tmp_path / "y.toml").write_text(text, encoding="utf-8")
    res = govopt.design(govopt.load_spec(tmp_path / "y.toml"))
    assert res.design != plain.design
    y = res.made["yield"]
    assert y["meets_required"] and y["ci95"][0] >= 0.99 and y["samples"] == 2000
    cols = made.resolved_columns(res.spec, res)
    bx = tm.stated(res.spec, cols).known()
    fresh = made.made_yield(res.spec, cols, bx, 1000, seed=7, fitter=made.fitter_of(
        res.spec.requirements))
    assert fresh["probability"] >= 0.99, fresh


def test_min_yield_that_no_design_reaches_names_what_binds(tmp_path):
    """Without the fitter's setting (``fitter = "none"``, no nut) the spring maker's free
    length spreads the speeds past the band: the diagnosis names the best candidate's yield,
    the requirement failing most often in its own samples and the tolerance that spreads the
    speeds most, and says to let the fitter set the spring."""
    text = HARTNELL.read_text(encoding="utf-8").replace(
        "[requirements]\n", "[requirements]\nmin_yield = 0.999\nrobust_samples = 4000\n"
        'fitter = "none"\n', 1)
    text = "\n".join(x for x in text.splitlines() if not x.startswith("adjusting_nut"))
    (tmp_path / "y.toml").write_text(text, encoding="utf-8")
    run = invoke(["design", str(tmp_path / "y.toml")])
    assert run.exit_code == 2 and run.exception is None, run.output
    err = run.stderr.strip()
    assert err.count("\n") == 0 and "requirements.min_yield" in err
    assert "most often failing there" in err and "free length tolerance alone" in err
    assert 'let the fitter set the spring (requirements.fitter = "sets")' in err
    held = re.search(r"holds in (\d+) of its (\d+) samples \(([0-9.]+) %\)", err)
    worst = [int(k) for k in re.findall(r"\(in (\d+) samples\)", err)]
    assert held and worst and max(worst) <= int(held[2]) - int(held[1])  # its own failures


def test_min_yield_needs_stated_tolerances(tmp_path):
    """With the nominal verdict (no default grade) a yield needs a stated tolerance."""
    text = (SPECS / "hamabe-design.toml").read_text(encoding="utf-8").replace(
        "[requirements]\n", '[requirements]\nmin_yield = 0.9\nverdict = "nominal"\n', 1)
    (tmp_path / "y.toml").write_text(text, encoding="utf-8")
    run = invoke(["design", str(tmp_path / "y.toml")])
    assert run.exit_code == 2 and "requirements.min_yield: the spec states no tolerance" in \
        run.stderr


@pytest.mark.parametrize("values", [
    [2.0] * 50,                              # all equal
    [1.0, 1.0, 2.0, 2.0, 2.0],               # a few distinct values
    [np.nan, 1.0, np.nan, 1.5, np.inf],      # not numbers
    [np.nan, np.nan],                        # none
    [1e6, 1e6 + 1e-7, 1e6],                  # equal to rounding
    [-0.0, 0.0, 0.0],                        # zero
])
def test_histograms_never_fail_on_degenerate_samples(values):
    """The tolerance plot's histograms take any samples: equal ones get one visible bar, no
    finite one none, and matplotlib draws them."""
    import pandas as pd
    from matplotlib.figure import Figure

    from govopt.report.study_plots import histograms

    part = pd.DataFrame({"status": ["pass"] * len(values), "v": values,
                         "m": np.asarray(values) - 1.5})

    def batches():
        return iter([part])

    hist = histograms(batches, {"v": ("v", 1.0, False), "m": ("m", 1.0, True)})
    finite = np.isfinite(np.asarray(values, dtype=float))
    for name in ("v", "m"):
        edges, counts, negative = hist[name]
        assert np.all(np.diff(edges) > 0)
        assert counts.sum() + negative.sum() == finite.sum()
        ax = Figure().add_subplot()
        if edges.size:
            ax.hist(edges[:-1], bins=edges, weights=counts)
    assert math.isfinite(float(hist["v"][1].sum()))


def test_the_yield_plot(tmp_path):
    """The 'yield' plot: the worst case as made, the sampled governors and the yield's words
    in the title."""
    spec = _designed(tmp_path)
    res = made.with_yield(govopt.evaluate(spec))
    from govopt.report.plots import kinds

    assert "yield" in kinds(res)
    ax = res.plot("yield")
    assert "of made governors pass" in ax.get_title()
    labels = ax.get_legend_handles_labels()[1]
    assert "worst case over the tolerance box (as made)" in labels
    samples = res.made["yield"]["samples"]  # set by the fitter before they are evaluated
    assert f"{samples} sampled governors (as made and set)" in labels


@pytest.mark.parametrize("n, dim, seed", [(2000, 4, 0), (7, 1, 3), (500, 6, 12)])
def test_latin_hypercube_is_scipys(n, dim, seed):
    """The yield's Latin hypercube is made with numpy alone and gives scipy's points (so a
    tolerance study and the yield keep drawing the same governors)."""
    from scipy.stats import qmc

    from govopt.stats import latin_hypercube

    assert np.array_equal(latin_hypercube(n, dim, seed),
                          qmc.LatinHypercube(d=dim, seed=seed).random(n))
