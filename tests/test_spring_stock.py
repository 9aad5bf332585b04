"""`govopt spring --catalogue FILE.csv`: the lightest spring of a maker's catalogue that meets
the requirements, checked as `govopt spring check` checks it; the catalogue's errors name the
file, the spring and the column (exit code 2)."""

import json

import pytest
from clirun import invoke
from springjson import fig

from govopt import spring_stock as stock
from govopt.springs import materials as mt
from govopt.springs.assessment import Loads, Rules, assess

ASK = ["spring", "--force", "100 N", "--stiffness", "5 N/mm", "--max-stiffness", "7 N/mm"]


def test_the_pick_is_the_lightest_passing_spring_and_spring_check_passes_it(tmp_path):
    result = invoke([*ASK, "--catalogue", "sample", "--json", "-o", str(tmp_path / "s.toml")])
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    assert out["optimisation"]["certified"] and all(c["passed"] for c in out["checks"])
    # every spring of the file, checked here one by one (index 4..12, the design's default)
    rules = Rules(index=(4.0, 12.0))
    passing = []
    for item in stock.read("sample"):
        a = assess(item.spring, mt.material(item.grade), Loads(0.0, 100.0), rules)
        if 5e3 * (1 - 1e-9) <= a.value("rate") <= 7e3 * (1 + 1e-9) and not a.failed:
            passing.append((a.value("mass"), item.part))
    assert len(passing) > 1
    mass = min(passing)[0]
    assert fig(out, "mass_kg") == pytest.approx(mass, rel=1e-12)
    assert any(p in out["name"] for m, p in passing if m == pytest.approx(mass, rel=1e-12))
    checked = invoke(["spring", "check", str(tmp_path / "s.toml")])
    assert checked.exit_code == 0, checked.output


def test_without_a_range_the_stiffness_lies_in_the_made_rate_band():
    """No --max-stiffness: the spring as made (EN 15800's rate band) can have the rate."""
    result = invoke(["spring", "--force", "100 N", "--stiffness", "6 N/mm", "--catalogue",
                     "sample", "--json"])
    assert result.exit_code == 0, result.output
    tol = json.loads(result.stdout)["tolerances"]
    assert tol["rate_least_N_per_m"] <= 6e3 <= tol["rate_largest_N_per_m"]


def test_none_meets_the_requirements_says_why():
    result = invoke(["spring", "--force", "5000 N", "--stiffness", "5 N/mm", "--catalogue",
                     "sample"])
    assert result.exit_code == 2
    assert result.output.startswith("error: no spring of the catalogue meets these "
                                    "requirements (108 springs")
    assert "fails" in result.output


def test_a_spec_names_its_catalogue_beside_it_in_inches(tmp_path):
    (tmp_path / "stock.csv").write_text(
        "part_number,d (in),D (in),L0 (in),n,ends,material,rate (lbf/in)\n"
        "A-1,0.063,0.5,1.5,6,closed_ground,ASTM A228,20\n"
        "A-2,0.072,0.6,1.75,6,closed_ground,ASTM A228,\n", encoding="utf-8")
    (tmp_path / "s.toml").write_text(
        'name = "pick"\n[spring]\nforce = "5 lbf"\nstiffness = "10 lbf/in"\n'
        'max_stiffness = "40 lbf/in"\ncatalogue = "stock.csv"\n', encoding="utf-8")
    result = invoke(["spring", str(tmp_path / "s.toml")])
    assert result.exit_code == 0, result.output
    assert "part A-1" in result.output and "wire diameter d                          0.063 in" \
        in result.output


@pytest.mark.parametrize(("text", "message"), [
    ("part_number,d (mm),L0 (mm),n,ends,material\nX,1,20,5,closed_ground,EN10270-1 SH\n",
     "row 1: expected the columns part_number, d, L0, n, ends, material and D or OD"),
    ("part_number,d,D (mm),L0 (mm),n,ends,material\n",
     "row 1: column 'd': expected its unit in brackets"),
    ("part_number,d (mm),D (mm),L0 (mm),n,ends,material,colour\n",
     "row 1: column 'colour': expected one of part_number"),
    ("part_number,d (mm),D (mm),L0 (mm),n,ends,material\nX,1,8,20,5,closed_ground,steel\n",
     "spring 1: material: expected one of EN10270-1 SM"),
    ("part_number,d (mm),D (mm),L0 (mm),n,ends,material\nX,one,8,20,5,closed_ground,"
     "EN10270-1 SH\n", "spring 1: d: expected a number, got 'one'"),
    ("part_number,d (mm),D (mm),L0 (mm),n,ends,material\nX,1,8,20,5,closed_ground\n",
     "spring 1: expected 7 values, got 6"),
])
def test_a_bad_catalogue_is_refused_naming_the_file_spring_and_column(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text, encoding="utf-8")
    result = invoke([*ASK, "--catalogue", str(path)])
    assert result.exit_code == 2
    assert result.output.startswith(f"error: {path}: {message}"), result.output
    assert "Traceback" not in result.output


def test_a_missing_catalogue_is_exit_2():
    result = invoke([*ASK, "--catalogue", "no-such.csv"])
    assert result.exit_code == 2 and result.output.startswith("error: --catalogue: cannot read")
