"""Questions the textbook asks, answered directly: which spring floats a governor
between two speeds (a spec with a speed band and no spring), effort and power over a chosen speed
change, and the type's geometry (h, the arm ratio k, the sleeve lift) in the JSON and text."""

import json
import math
import re

import pytest
from clirun import invoke

from govopt.examples import SPECS
from govopt.units import G_STANDARD

KGF = G_STANDARD  # N


def _without_spring(tmp_path, name: str) -> str:
    """The bundled textbook spec ``name`` with its answer (the spring) taken out."""
    text = (SPECS / f"{name}.toml").read_text(encoding="utf-8")
    kept = [ln for ln in text.splitlines()
            if not ln.startswith(("spring_stiffness", "free_length"))]
    assert len(kept) == len(text.splitlines()) - 2
    path = tmp_path / f"{name}-no-spring.toml"
    path.write_text("\n".join(kept) + "\n", encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("name, stiffness_kgf_cm, initial_kgf", [
    ("textbook-ex4-hartnell", 3.572, 19.32),  # the book: 3.57 kg/cm, 19.3 kg
    ("textbook-ex8-spring_gravity", 35.31, 45.03),  # the book: 35.4 kg/cm, 45 kg
])
def test_a_band_without_a_spring_finds_the_spring_and_evaluates_it(tmp_path, name,
                                                                   stiffness_kgf_cm,
                                                                   initial_kgf):
    """The book's answers (to the 4 digits of the bundled specs, which give them), and the
    governor evaluated with that spring floats exactly between the band's speeds."""
    spec = _without_spring(tmp_path, name)
    run = invoke(["evaluate", spec, "--json"])
    assert run.exit_code == 0, run.stderr
    out = json.loads(run.stdout)
    found = out["band_spring"]
    assert found["stiffness_N_per_m"] == pytest.approx(stiffness_kgf_cm * KGF / 0.01, rel=2e-4)
    assert found["force_inner_N"] == pytest.approx(initial_kgf * KGF, rel=2e-4)
    assert all(c["passed"] for c in out["checks"])
    band = {c["name"]: c for c in out["checks"]}
    for check in ("lowest speed >= speed.inner", "highest speed <= speed.outer"):
        assert band[check]["value"] == pytest.approx(band[check]["limit"], rel=1e-12)
    text = invoke(["evaluate", spec])
    assert text.exit_code == 0 and "no spring given: the one that floats the governor" in \
        text.stdout


def test_a_spring_half_given_is_still_an_error(tmp_path):
    """Only a [design] with no spring key at all asks the question; a free length without a
    rate stays the error it was."""
    text = (SPECS / "textbook-ex4-hartnell.toml").read_text(encoding="utf-8")
    path = tmp_path / "half.toml"
    path.write_text(re.sub(r"^spring_stiffness.*\n", "", text, flags=re.M), encoding="utf-8")
    run = invoke(["evaluate", str(path)])
    assert run.exit_code == 2 and run.stderr.startswith("error: ") and run.stdout == ""


PORTER = str(SPECS / "textbook-ex1-porter.toml")


def _classic(*args):
    run = invoke(["evaluate", PORTER, "--json", *args])
    assert run.exit_code == 0, run.stderr
    return json.loads(run.stdout)["classic"]


def test_effort_and_power_over_a_chosen_speed_change(tmp_path):
    """The default 1 %; any c (the effort grows as (1 + c)^2 - 1); the range's own: c =
    omega_a / omega_i - 1 from the innermost configuration, the power the effort times the
    whole sleeve lift; the spec's [analysis] speed_change says the same as the option."""
    one, two = _classic(), _classic("--speed-change", "0.02")
    assert one["effort_change"] == 0.01 and two["effort_change"] == 0.02
    assert two["effort_N"] / one["effort_N"] == pytest.approx((1.02**2 - 1) / (1.01**2 - 1),
                                                              rel=1e-12)
    whole = _classic("--speed-change", "range")
    lift = whole["geometry"]["sleeve_lift_m"]
    assert whole["effort_over"] == "range"
    assert whole["effort_change"] == pytest.approx(whole["range_rad_s"] / one_inner(PORTER),
                                                   rel=1e-12)
    assert whole["power_J"] == pytest.approx(whole["effort_N"] * (lift["outer"] - lift["inner"]),
                                             rel=1e-12)
    text = (SPECS / "textbook-ex1-porter.toml").read_text(encoding="utf-8")
    path = tmp_path / "range.toml"
    path.write_text(text + '\n[analysis]\nspeed_change = "range"\n', encoding="utf-8")
    run = invoke(["evaluate", str(path), "--json"])
    assert json.loads(run.stdout)["classic"] == whole
    report = invoke(["evaluate", str(path), "--section", "design"]).stdout
    assert re.search(r"^effort .* over the range: a 14\.49 % speed change", report, re.M)


def one_inner(spec: str) -> float:
    """The equilibrium speed at the innermost configuration, rad/s (the characteristic's
    first row)."""
    return json.loads(invoke(["evaluate", spec, "--json"]).stdout)["characteristic"][0][
        "omega_rad_s"]


@pytest.mark.parametrize("args, message", [
    (["--speed-change", "2"], "error: --speed-change: must lie in (0, 1) (a fraction of the "
                              "speed, e.g. 0.01), or \"range\", got 2"),
    (["--speed-change", "lift"], "error: --speed-change: expected a number in (0, 1) (a "
                                 "fraction of the speed, e.g. 0.01), or \"range\", got 'lift'"),
])
def test_bad_speed_change_is_one_error_line(args, message):
    run = invoke(["evaluate", PORTER, *args])
    assert run.exit_code == 2 and run.stdout == "" and run.stderr.startswith(message)


@pytest.mark.parametrize("value", ["1e-300", "2", "0", "-0.1", "nan", "lift", "1e300"])
def test_speed_change_option_and_key_are_one_rule(tmp_path, value):
    """``--speed-change X`` is refused exactly where ``[analysis] speed_change = X`` is, with
    the same words (1e-300 is below govopt's range in both)."""
    text = (SPECS / "textbook-ex1-porter.toml").read_text(encoding="utf-8")
    path = tmp_path / "bad.toml"
    written = f'"{value}"' if value == "lift" else value
    path.write_text(text + f"\n[analysis]\nspeed_change = {written}\n", encoding="utf-8")
    key = invoke(["evaluate", str(path)])
    option = invoke(["evaluate", PORTER, "--speed-change", value])
    assert key.exit_code == option.exit_code == 2
    assert key.stderr.replace(f"{path}: analysis.speed_change", "--speed-change") \
        == option.stderr


def test_bad_speed_change_in_the_spec_names_its_key(tmp_path):
    text = (SPECS / "textbook-ex1-porter.toml").read_text(encoding="utf-8")
    path = tmp_path / "bad.toml"
    path.write_text(text + "\n[analysis]\nspeed_change = 1.5\n", encoding="utf-8")
    run = invoke(["evaluate", str(path)])
    assert run.exit_code == 2 and "analysis.speed_change" in run.stderr


def test_height_arm_ratio_and_lift_in_the_json_and_text():
    """The Porter of Example 1, arms of 30 cm pivoted on the axis: h = sqrt(30^2 - r^2) at
    the ends of the range (20 and 25 cm), k = tan(beta)/tan(alpha), the lift the fall of the
    sleeve from the innermost configuration."""
    geometry = _classic()["geometry"]
    h = geometry["height_m"]
    assert h["inner"] == pytest.approx(math.sqrt(0.3**2 - 0.2**2), rel=1e-12)
    assert h["outer"] == pytest.approx(math.sqrt(0.3**2 - 0.25**2), rel=1e-12)
    k = geometry["k"]
    beta, alpha = geometry["beta_rad"], geometry["alpha_rad"]
    for where in ("inner", "normal", "outer"):
        assert k[where] == pytest.approx(math.tan(beta[where]) / math.tan(alpha[where]),
                                         rel=1e-12)
    assert geometry["sleeve_lift_m"]["inner"] == 0.0 < geometry["sleeve_lift_m"]["outer"]
    report = invoke(["evaluate", PORTER, "--section", "design"]).stdout
    for label in ("height h", "arm ratio k", "sleeve lift"):
        assert re.search(rf"^{label}\s+[\d.]+\s+(mm|-)\s+normal; ", report, re.M), label
