"""Requirements that mean the same on every path (issue 20): evaluate, bulk (evaluate_many),
design and studies read one rule for each requirement."""

from pathlib import Path

import pytest
from clirun import invoke

from govopt import evaluate, load_spec
from govopt.bulk import evaluate_many

SPECS = Path(__file__).resolve().parent.parent / "govopt" / "specs"
CLASH = "working length >= least length (coil clash)"

#: the issue's case: a Hartnell governor (textbook Example 4's geometry) with a 4 mm wire,
#: r = 20 mm, 13 turns and no wire grade; at the top of the range the spring would be
#: compressed below its least working length
CLASH_SPEC = """
name = "clash"
[governor]
type = "hartnell"
ball_arm = "7.5 cm"
sleeve_arm = "7.5 cm"
radius_inner = "7.5 cm"
radius_outer = "12 cm"
obliquity = "small_angle"
spring_length = "10 cm"
[speed]
inner = "240 rpm"
outer = "256.8 rpm"
[material]
allowable_shear_stress = "8000 kgf/cm^2"
shear_modulus = "850000 kgf/cm^2"
density = "7.85 g/cm^3"
[design]
ball_weight = "2 kgf"
wire_diameter = "4 mm"
coil_radius = "20 mm"
active_turns = 13
"""


@pytest.fixture
def clash_spec(tmp_path):
    path = tmp_path / "clash.toml"
    path.write_text(CLASH_SPEC)
    return path


def test_coil_clash_is_checked_without_a_grade_or_requirements(clash_spec):
    res = evaluate(load_spec(clash_spec))
    check = next(c for c in res.checks if c.name == CLASH)
    sheet = res.spring_report.sheet
    # the spring sheet's own numbers: the working length at full lift is below the solid length
    assert sheet.L2 < sheet.solid_length
    assert not check.passed and check.value < check.limit
    assert not all(c.passed for c in res.checks)


def test_coil_clash_fails_on_every_path(clash_spec):
    run = invoke(["evaluate", str(clash_spec)])
    assert run.exit_code == 1 and CLASH in run.stdout
    spec = load_spec(clash_spec)
    row = evaluate_many(spec, [spec.design]).iloc[0]
    assert row["status"] == "fail" and CLASH in row["message"]
    assert row[f"passed: {CLASH}"] is False or not row[f"passed: {CLASH}"]
