"""The CLI: readable report, JSON keys that later tools rely on, fidelity flags."""

import json

import pytest
from clirun import invoke


def test_evaluate_default_prints_report():
    result = invoke(["evaluate", "--full"])
    # exit 1: case a misses its own irregularity 0.12 (0.123, docs/theory/shaft.md); a failed
    # check exits 1
    assert result.exit_code == 1, result.output
    assert "1 of 8 checks failed: irregularity" in result.stderr
    assert "hamabe-a" in result.output
    assert "irregularity" in result.output
    assert "Characteristic" in result.output


def test_evaluate_json_keys():
    result = invoke(["evaluate", "specs/hamabe-b.toml", "--json"])
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
    exact = json.loads(invoke(["evaluate", "--json"]).output)
    series = json.loads(invoke(["evaluate", "--json", "--geometry", "series"]).output)
    assert exact["fidelity"]["geometry"] == "exact"
    assert series["fidelity"]["geometry"] == "series"
    assert exact["irregularity"] != series["irregularity"]


def test_bad_flag_value_exits_2():
    result = invoke(["evaluate", "--geometry", "wobbly"])
    assert result.exit_code == 2


def test_spring_command_reproduces_hamabe_sizing():
    """govopt spring with the paper's case a numbers (r free, no Wahl): with stiffness and
    stress both active, the active coils' mass is 2 rho G F^2 / (kappa k_s^2) whatever r, a
    lower bound on every spring (the end coils and the helix rise add to it). Between fixed
    plates the stress-limited spring would buckle (EN 13906-1, 9.14, 101 mm of deflection):
    the designer holds its free length to a slenderness that passes, and claims "within X %"
    of the certified bound, not the optimum."""
    args = ["spring", "--force", "606 kgf", "--stiffness", "59.7 kgf/cm", "--allowable-stress",
            "4000 kgf/cm^2", "--shear-modulus", "850000 kgf/cm^2", "--correction", "none",
            "--json"]
    result = invoke(args)
    assert result.exit_code == 0, result.output
    out = json.loads(result.output)
    F, kappa, ks, G = 606 * 9.80665, 59.7 * 980.665, 4000 * 9.80665e4, 850000 * 9.80665e4
    active = 2 * 7850 * G * F**2 / (kappa * ks**2)
    sp, opt = out["spring"], out["optimisation"]
    n, mass = sp["active_coils"], sp["mass_kg"]
    assert mass > active * (n + 2) / n  # the helix rise
    assert active < opt["bound"] < mass == opt["value"] and not opt["certified"]
    assert all(c["passed"] for c in out["checks"])
    buckling = next(c for c in out["checks"] if c["name"].startswith("deflection / buckling"))
    assert buckling["value"] == pytest.approx(1.0, abs=2e-3)  # it binds
    assert out["lengths_and_energy"]["rate_N_per_m"] == pytest.approx(kappa, rel=1e-6)


def test_spring_command_infeasible_and_bad_units():
    args = ["spring", "--force", "606 kgf", "--stiffness", "59.7 kgf/cm", "--allowable-stress",
            "400 kgf/cm^2", "--shear-modulus", "850000 kgf/cm^2", "--max-outer-diameter", "6 cm"]
    result = invoke(args)
    assert result.exit_code == 2
    assert "allowable stress" in result.output and "outer diameter" in result.output
    bad = invoke(["spring", "--force", "606 cm", "--stiffness", "1 N/m",
                              "--allowable-stress", "1 MPa", "--shear-modulus", "1 GPa"])
    assert bad.exit_code == 2 and "--force" in bad.output
