"""The CLI: readable report, JSON keys that later tools rely on, fidelity flags."""

import json

from typer.testing import CliRunner

from govopt.cli import app

runner = CliRunner()


def test_evaluate_default_prints_report():
    result = runner.invoke(app, ["evaluate"])
    assert result.exit_code == 0, result.output
    assert "hamabe-a" in result.output
    assert "irregularity" in result.output
    assert "Characteristic" in result.output


def test_evaluate_json_keys():
    result = runner.invoke(app, ["evaluate", "specs/hamabe-b.toml", "--json"])
    assert result.exit_code == 0, result.output
    out = json.loads(result.output)
    for key in ("irregularity", "omega_inner_rad_s", "omega_outer_rad_s", "pendulum_mass_kg",
                "spring", "characteristic"):
        assert key in out
    for key in ("wire_diameter_m", "coil_radius_m", "active_turns", "stiffness_N_per_m",
                "free_half_length_m", "max_shear_stress_Pa"):
        assert key in out["spring"]
    row = out["characteristic"][0]
    for key in ("alpha_deg", "omega_rad_s", "spring_force_N", "M_r0_N_m"):
        assert key in row
    assert out["pendulum_mass_kg"] == 10.0
    assert out["spring"]["wire_diameter_m"] == 0.016


def test_geometry_flag_changes_the_model():
    exact = json.loads(runner.invoke(app, ["evaluate", "--json"]).output)
    series = json.loads(runner.invoke(app, ["evaluate", "--json", "--geometry", "series"]).output)
    assert exact["fidelity"]["geometry"] == "exact"
    assert series["fidelity"]["geometry"] == "series"
    assert exact["irregularity"] != series["irregularity"]


def test_bad_flag_value_exits_2():
    result = runner.invoke(app, ["evaluate", "--geometry", "wobbly"])
    assert result.exit_code == 2
