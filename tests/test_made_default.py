"""The made governor by default: a spring governor's design is the governor a shop makes to its
tolerances (EN 15800 grade 2 where the spec states none) and a fitter sets, and its verdict is
theirs. For every bundled design spec, every `govopt init --type` template and the tutorial's
spec whose governor has a helical spring: a design that exits 0 is one whose tolerance study
(`govopt study run D.toml --tolerance grade=2 --samples 2000`, which applies the fitter's
setting) shows the yield; a design the fitter may not set, made below `min_yield`, is "FAIL as
made" with exit 1."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from clirun import invoke

import govopt
from govopt import made
from govopt.examples import SPECS
from govopt.stats import wilson

#: the tutorial's edits of the Hartnell template (docs/tutorial.md, step 2)
TUTORIAL = [('name = "hartnell-design"', 'name = "small-engine"'),
            ('ball_arm = "15 cm"', 'ball_arm = "10 cm"'),
            ('sleeve_arm = "9 cm"', 'sleeve_arm = "6 cm"'),
            ('radius_inner = "10 cm"', 'radius_inner = "7 cm"'),
            ('radius_outer = "15 cm"', 'radius_outer = "10 cm"'),
            ('radius_normal = "12.5 cm"', 'radius_normal = "8.5 cm"'),
            ('sleeve_friction = "1.5 kgf"', 'sleeve_friction = "0.5 kgf"'),
            ('spring_length = "10 cm"', 'spring_length = "8 cm"'),
            ('inner = "140 rpm"', 'inner = "300 rpm"'),
            ('outer = "160 rpm"', 'outer = "330 rpm"')]
#: the governor types with a helical spring (whose tolerances EN 15800 gives)
HELICAL = ("shaft", "hartnell", "spring_loaded", "spring_gravity", "traction_coil")
#: what a spec must cost to run here at most before it is marked slow (its design, s)
FAST = ("hartnell-design", "hartnell-tolerances", "spring_loaded-design",
        "template-hartnell", "tutorial")


def _helical_design_specs() -> list[str]:
    out = []
    for path in sorted(SPECS.glob("*design*.toml")):
        spec = govopt.load_spec(path)
        if made.judged_as_made(spec):
            out.append(path.stem)
    return out


CASES = [*_helical_design_specs(), *(f"template-{t}" for t in HELICAL), "tutorial"]


def _written(case: str, folder: Path) -> Path:
    """The spec of ``case`` written into ``folder``."""
    if case.startswith("template-"):
        run = invoke(["init", "--type", case.split("-", 1)[1], "-o", str(folder / "t.toml")])
        assert run.exit_code == 0, run.output
        return folder / "t.toml"
    if case == "tutorial":
        run = invoke(["init", "--type", "hartnell", "-o", str(folder / "t.toml")])
        assert run.exit_code == 0, run.output
        text = (folder / "t.toml").read_text(encoding="utf-8")
        for old, new in TUTORIAL:
            assert old in text, old
            text = text.replace(old, new)
        (folder / "t.toml").write_text(text, encoding="utf-8")
        return folder / "t.toml"
    return Path(shutil.copy(SPECS / f"{case}.toml", folder / f"{case}.toml"))


@pytest.mark.parametrize("case", [c if c in FAST else pytest.param(c, marks=pytest.mark.slow)
                                  for c in CASES])
def test_a_design_that_passes_holds_as_made(case, tmp_path):
    """`govopt design X -o D.toml` exiting 0 implies that the grade-2 tolerance study of D.toml
    (2000 samples, the fitter's setting applied) shows a probability whose 95 % lower bound is
    at least min_yield - 0.02 (the design certifies its own 95 % lower bound >= min_yield on
    these same samples; the drawing's rounding may cost a little of it, hence 0.02)."""
    spec = _written(case, tmp_path)
    out = tmp_path / "D.toml"
    run = invoke(["design", str(spec), "-o", str(out)])
    if run.exit_code != 0:  # infeasible as made: refused with its reason, not a PASS
        assert run.exit_code in (1, 2), run.output
        return
    assert "PASS as made" in run.stdout, run.stdout[:2000]
    min_yield = made.made_requirements(govopt.load_spec(out)).min_yield
    study = invoke(["study", "run", str(out), "--tolerance", "grade=2", "--samples", "2000"],
                   cwd=tmp_path)
    assert study.exit_code in (0, 1), study.output
    found = re.search(r"all requirements hold with probability ([0-9.]+) \(95 % CI "
                      r"([0-9.]+)-([0-9.]+)\)", study.stdout)
    assert found, study.stdout
    p, lo = float(found[1]), float(found[2])
    assert lo >= min_yield - 0.02, (case, p, lo)
    k = round(p * 2000)  # the printed bound is Wilson's of the printed count
    assert wilson(k, 2000)[0] == pytest.approx(lo, abs=1e-4)


def test_a_design_the_fitter_may_not_set_fails_as_made(tmp_path):
    """The bundled Hartnell design's spring, made to grade 2 and not set by the fitter
    (``requirements.fitter = "none"``), falls short of min_yield: the verdict says "FAIL as
    made", names what fails most often and what to change, and the exit code is 1; the nominal
    verdict, asked by name, passes the same design."""
    spec = tmp_path / "h.toml"
    run = invoke(["design", str(SPECS / "hartnell-design.toml"), "-o", str(spec)])
    assert run.exit_code == 0, run.output
    text = spec.read_text(encoding="utf-8")
    text = text.replace("[requirements]\n", '[requirements]\nfitter = "none"\n', 1)
    spec.write_text(text, encoding="utf-8")
    run = invoke(["evaluate", str(spec)])
    assert run.exit_code == 1, run.output
    verdict = next(line for line in run.stdout.splitlines() if "as made" in line)
    assert verdict.startswith("FAIL as made:"), verdict
    assert "most often failing:" in verdict
    assert 'requirements.fitter = \\"sets\\"' not in verdict
    assert 'let the fitter set the spring (requirements.fitter = "sets")' in verdict
    res = govopt.load_spec(spec)
    assert made.fitter_sets(res) == ()
    nominal = spec.read_text(encoding="utf-8").replace(
        '[requirements]\n', '[requirements]\nverdict = "nominal"\n', 1)
    spec.write_text(nominal, encoding="utf-8")
    run = invoke(["evaluate", str(spec)])
    assert run.exit_code == 0, run.output
    assert 'PASS at nominal (requirements.verdict = "nominal")' in run.stdout


def test_the_json_says_whose_verdict(tmp_path):
    """The JSON record says whose verdict it is and whether it passed."""
    import json

    run = invoke(["design", str(SPECS / "hartnell-design.toml"), "--json"])
    assert run.exit_code == 0, run.output
    got = json.loads(run.stdout)
    assert got["verdict"] == {"of": "made", "passed": True}
    y = got["made"]["yield"]
    assert y["required"] == made.DEFAULT_MIN_YIELD and y["meets_required"] is True
    assert got["made"]["tolerances"]["spring_grade"] == made.DEFAULT_GRADE
    assert got["made"]["tolerances"]["set_by_the_fitter"]
