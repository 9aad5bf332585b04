"""`govopt spring check` and the springs a maker can make: a given spring reported from the same
rows as a designed one, in the input's units; wire from the grade's standard's table with the
coils on a step, certified by a bounded enumeration; EN 13906-1's solid length with the largest
wire diameter; the mass from the wire's length with the helix rise; one optimisation record."""

import json
import math
import tomllib

import numpy as np
import pytest
from clirun import invoke

from govopt.examples import example
from govopt.report.spring_report import JSON_KEYS
from govopt.springs import compression as hc
from govopt.springs import helical as hx
from govopt.springs import materials as mt

SH = ["--force", "500 N", "--stiffness", "20 N/mm", "--material", "EN10270-1 SH"]
PLAIN = ["--force", "500 N", "--stiffness", "10 N/mm", "--allowable-stress", "600 MPa",
         "--shear-modulus", "81.5 GPa"]


def _run(*args, code=0):
    result = invoke([*map(str, args)])
    assert result.exit_code == code, result.output
    return result


def _json(*args, code=0):
    return json.loads(_run(*args, "--json", code=code).stdout)


@pytest.mark.parametrize("design", [
    [*SH, "--fatigue-min-force", "100 N", "--fatigue-max-force", "300 N"],
    [*SH, "--wire-sizes", "continuous", "--seating", "hinged-hinged"],
    PLAIN,
    ["--force", "300 N", "--min-force", "100 N", "--stiffness", "5 N/mm", "--material",
     "EN10270-1 DH", "--kind", "extension", "--wire-sizes", "continuous"],
    ["--force", "60 lbf", "--stiffness", "40 lbf/in", "--material", "EN10270-1 SH",
     "--ends", "closed", "--min-force", "20 lbf"],
])
def test_a_designed_spring_checked_reproduces_its_own_report(tmp_path, design):
    """`govopt spring -o SPEC` writes the designed spring, its lengths as a drawing gives them
    (4 significant digits, more only where a check would otherwise fail); `govopt spring check
    SPEC` reports the same figures to that precision, the same working points, checks and
    verdicts (the design's report without the optimiser's record), in the same units."""
    spec = tmp_path / "s.toml"
    run = invoke(["spring", *design, "-o", str(spec), "--json"])
    assert run.exit_code in (0, 1), run.output
    designed = json.loads(run.stdout)
    check = invoke(["spring", "check", str(spec), "--json"])
    assert check.exit_code == run.exit_code, check.output
    checked = json.loads(check.stdout)
    assert designed["optimisation"] is not None and checked["optimisation"] is None
    assert (designed["command"], checked["command"]) == ("design", "check")
    written = tomllib.loads(spec.read_text(encoding="utf-8"))["spring"]
    for key, figure in (("wire_diameter", "wire_diameter_m"),
                        ("mean_diameter", "mean_coil_diameter_m"),
                        ("free_length", "free_length_m")):
        digits = written[key].split()[0].lstrip("0.").replace(".", "")
        # a drawing's 4 digits for a stock spring; a continuous optimum on two limits at once
        # (the extension spring: the least index and the hook's stress) may need more
        assert len(digits) <= (4 if "continuous" not in design else 12), written[key]
        assert checked["spring"][figure] == pytest.approx(designed["spring"][figure], rel=5e-4)
    for key in JSON_KEYS:
        if key in ("command", "optimisation", "notes"):
            continue
        if key == "checks":
            assert [(c["name"], c["passed"]) for c in checked[key]] == \
                [(c["name"], c["passed"]) for c in designed[key]]
            for a, b in zip(checked[key], designed[key], strict=True):
                assert a["value"] == pytest.approx(b["value"], rel=DRAWN, abs=1e-9), a["name"]
                assert a["limit"] == pytest.approx(b["limit"], rel=DRAWN, abs=1e-9), a["name"]
            continue
        assert checked[key] == _approx(designed[key]), key
    text_d = invoke(["spring", *design]).stdout.splitlines()
    text_c = invoke(["spring", "check", str(spec)]).stdout.splitlines()
    assert text_c[0] == text_d[0].replace("(designed", "(checked")
    body_d = [line for line in text_d if line.startswith("  ") and "note:" not in line]
    start = next(i for i, line in enumerate(text_d) if line.startswith("Optimisation"))
    end = next(i for i, line in enumerate(text_d) if line.startswith("Checks"))
    kept = text_d[1:start] + text_d[end:]

    def labels(lines):  # the same report: each line's label and unit (its numbers: above)
        return [(line[:42], line.split()[-1]) for line in lines
                if line.strip() and not line.startswith(("wrote", "note", "Checks"))
                and not line.startswith("  ") or line[:42].strip().isalpha()]

    assert labels(text_c[1:]) == labels(kept)
    assert body_d  # (a report, not an empty one)


#: how far the figures of a spring drawn to 4 significant digits lie from the design's: each
#: length within 5e-4 (half a unit of the 4th digit), the rate as D^-3 (1.5e-3), a stress at a
#: length as the deflection there (a difference of lengths: up to a few 1e-3 of it)
DRAWN = 1e-2


def _approx(value):
    """The same JSON, numbers to the drawing's precision (:data:`DRAWN`)."""
    if isinstance(value, dict):
        return {k: _approx(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_approx(v) for v in value]
    if isinstance(value, float):
        return pytest.approx(value, rel=DRAWN, abs=1e-9)
    return value


def test_a_spring_in_inches_and_pounds_force_is_reported_in_them():
    out = _run("spring", "check", "--wire-diameter", "0.105 in", "--outer-diameter", "1.2 in",
               "--active-coils", "10", "--free-length", "3.5 in", "--material", "ASTM A228",
               "--shear-modulus", "11.75e6 psi", "--force", "20 lbf", "--min-force",
               "10 lbf").stdout
    assert " mm" not in out and " MPa" not in out and " N/mm" not in out and " g\n" not in out
    lines = {line[:42].strip(): line for line in out.splitlines() if line.startswith("  ")}
    assert lines["wire diameter d"].endswith("0.105 in")
    assert lines["free length L0"].endswith("3.5 in")
    assert lines["rate R"].endswith("lbf/in")
    assert "psi, margin" in out and " lb\n" in out and "in*lbf" in out
    d, D, n = 0.105, 1.095, 10
    G = 11.75e6
    R = G * d**4 / (8 * D**3 * n)  # lbf/in, Shigley eq. (10-9) in its own units
    assert lines["rate R"].split()[-2] == f"{R:.5g}"


def test_check_needs_the_spring_and_names_what_is_missing():
    base = ["spring", "check", "--wire-diameter", "3 mm", "--material", "EN10270-1 SH",
            "--force", "100 N"]
    r = invoke([*base, "--active-coils", "8", "--free-length", "60 mm"])
    assert r.exit_code == 2 and "--mean-diameter or --outer-diameter: give one" in r.output
    r = invoke([*base, "--mean-diameter", "20 mm", "--free-length", "60 mm"])
    assert r.exit_code == 2 and r.output.startswith("error: --active-coils: required")
    r = invoke([*base, "--mean-diameter", "2 mm", "--active-coils", "8", "--free-length",
                "60 mm"])
    assert r.exit_code == 2 and "--mean-diameter: expected a coil wider than the wire" in r.output
    r = invoke([*base, "--mean-diameter", "20 mm", "--active-coils", "8", "--free-length",
                "60 mm", "--length-2", "40 mm"])
    assert r.exit_code == 2 and "--force and --length-2: give one" in r.output


def test_a_spring_spec_with_a_geometry_is_checked_not_designed(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text('[spring]\nwire_diameter = "3 mm"\nforce = "100 N"\n')
    r = invoke(["spring", str(spec)])
    assert r.exit_code == 2
    assert r.output.startswith(f"error: {spec}: spring.wire_diameter: a spring's geometry: "
                               "check it with 'govopt spring check "), r.output


@pytest.mark.parametrize(("ends", "end_coils", "extra"), [
    ("closed_ground", 2, 0.0), ("closed", 2, 1.5), ("open_ground", 1, 0.0), ("open", 0, 1.0)])
def test_solid_length_is_total_coils_times_the_largest_wire(ends, end_coils, extra):
    """EN 13906-1: L_c = n_t d_max with closed and ground ends, (n_t + 1.5) d_max closed and
    not ground; Shigley Table 10-1 for open ends (n_t = n, L_s = d (n_t + 1)) and open and
    ground (n_t = n + 1, L_s = d n_t). By hand: 9.5 active coils of 2.8 mm EN 10270-1 wire,
    whose tolerance is +-0.030 mm (EN 10270-1, 2.6 < d <= 4.0 mm): d_max = 2.83 mm."""
    out = _json("spring", "check", "--wire-diameter", "2.8 mm", "--mean-diameter", "20 mm",
                "--active-coils", "9.5", "--ends", ends, "--free-length", "60 mm",
                "--material", "EN10270-1 SH", "--force", "100 N")
    n_t = 9.5 + end_coils
    assert out["spring"]["total_coils"] == n_t
    assert out["spring"]["largest_wire_diameter_m"] == pytest.approx(2.83e-3, rel=1e-12)
    assert out["lengths_and_energy"]["solid_length_m"] == pytest.approx(
        (n_t + extra) * 2.83e-3, rel=1e-12)
    if ends == "closed_ground":  # 11.5 x 2.83 mm
        assert out["lengths_and_energy"]["solid_length_m"] == pytest.approx(32.545e-3)
    # the least working length: L_c + S_a with the nominal d in S_a (dynamic: x1.5)
    S_a = 1.5 * 9.5 * (0.0015 * 20**2 / 2.8 + 0.1 * 2.8) * 1e-3
    assert out["lengths_and_energy"]["least_working_length_m"] == pytest.approx(
        (n_t + extra) * 2.83e-3 + S_a, rel=1e-12)


def _coil_by_coil_length(D, n, pitch, end_coils, d, per_turn=4000):
    """The wire's centre line built coil by coil and measured as a polyline: the end coils
    wound at the pitch d (closed ends, coils touching), the active ones at ``pitch``, the
    pitch ramping linearly over the first and last half turn of the active coils (where a real
    spring's closed end runs into its body), a point every 1/per_turn of a turn."""
    half = end_coils / 2.0
    turns = n + end_coils
    theta = np.linspace(0.0, 2 * np.pi * turns, int(per_turn * turns) + 1)
    t = theta / (2 * np.pi)  # turns wound so far
    ramp = np.clip(np.minimum(t - half, turns - half - t) / 0.5, 0.0, 1.0)
    p = d + (pitch - d) * ramp  # the pitch at each point
    z = np.concatenate([[0.0], np.cumsum(p[1:] * np.diff(t))])
    x, y = D / 2 * np.cos(theta), D / 2 * np.sin(theta)
    return float(np.sum(np.sqrt(np.diff(x)**2 + np.diff(y)**2 + np.diff(z)**2)))


@pytest.mark.parametrize("design", [PLAIN, [*SH, "--wire-sizes", "continuous"],
                                    ["--force", "200 N", "--stiffness", "2 N/mm",
                                     "--allowable-stress", "500 MPa", "--shear-modulus",
                                     "79 GPa", "--index-max", "16"]])
def test_mass_is_the_wire_length_with_the_helix_rise(design):
    """The mass is the wire's length with the helix rise (within 0.1 % of a coil-by-coil
    length), which pi D n_t (EN 13906-1's wire length) leaves out by 0.3 % or more."""
    out = _json("spring", *design)
    sp = out["spring"]
    d, D, n, n_t = (sp[k] for k in ("wire_diameter_m", "mean_coil_diameter_m",
                                    "active_coils", "total_coils"))
    rho = out["material"]["density_kg_per_m3"]
    wire = sp["mass_kg"] / (rho * np.pi * d**2 / 4)
    assert wire == pytest.approx(sp["wire_length_m"], rel=1e-12)
    reference = _coil_by_coil_length(D, n, sp["pitch_m"], n_t - n, d)
    assert wire == pytest.approx(reference, rel=1e-3)
    assert wire > np.pi * D * n_t * 1.003
    assert out["optimisation"]["value"] == sp["mass_kg"]


def test_orderable_spring_from_the_grades_table_with_half_turns():
    """500 N at 20 N/mm of EN 10270-1 SH: the continuous optimum has d = 2.852 mm and n = 9.36
    coils; --wire-sizes preferred --coil-step 0.5 returns a wire of the standard's table and
    a half-turn count, certified by bounded enumeration: no spring of the table's wires from
    2 to 4 mm and half-turn counts that passes every check is lighter (every one assessed
    here with the checker's rows)."""
    from govopt.springs.assessment import Loads, Rules, Spring, assess

    out = _json("spring", *SH, "--wire-sizes", "preferred", "--coil-step", "0.5")
    sp, opt = out["spring"], out["optimisation"]
    sizes, source = mt.wire_sizes("EN10270-1 SH")
    assert sp["wire_diameter_m"] in sizes and source.startswith("EN 10270-1")
    assert (2 * sp["active_coils"]).is_integer()
    assert opt["certified"] and opt["gap"] == 0.0 and opt["search"]["springs examined"] > 0
    assert any("wire sizes: EN 10270-1" in note for note in opt["notes"])
    default = _json("spring", *SH)  # with a grade the table and half turns are the default
    assert default["spring"] == out["spring"]
    mat, best = mt.material("EN10270-1 SH"), sp["mass_kg"]
    rules = Rules(index=(4.0, 12.0))
    for w in [x for x in sizes if 2e-3 <= x <= 4e-3]:
        G = float(mat.shear_modulus(w))
        for n in np.arange(3.0, 40.0, 0.5):
            D = (G * w**4 / (8 * 20e3 * n)) ** (1 / 3)
            R = float(hx.stiffness(w, D, n, G))
            Ln = float(hc.min_working_length(w, D, n, n + 2, "closed_ground", True, False,
                                             w + 0.030e-3 if w > 2.6e-3 else w + 0.025e-3))
            spring = Spring("compression", w, D, n, 2.0, Ln + 500.0 / R, "closed_ground")
            a = assess(spring, mat, Loads(0.0, 500.0), rules)
            if not a.failed:
                assert a.value("mass") >= best * (1 - 1e-9), (w, n)
    help_text = " ".join(invoke(["spring", "design", "--help"]).stdout.replace("\u2502", " ")
                         .split())
    assert "data/wire_sizes.toml" in help_text and "EN 10270-1" in help_text


def test_the_literature_problems_and_a_designed_spring_print_the_same_keys():
    keys = None
    for args in (["spring", str(example("belegundu-arora"))],
                 ["spring", str(example("sandgren-1990"))], ["spring", *PLAIN],
                 ["spring", *SH], ["spring", "check", "--wire-diameter", "3 mm",
                                   "--mean-diameter", "20 mm", "--active-coils", "8",
                                   "--free-length", "60 mm", "--material", "EN10270-1 SH",
                                   "--force", "100 N"]):
        out = json.loads(invoke([*args, "--json"]).stdout)
        shape = {k: sorted(v) if isinstance(v, dict) else type(v).__name__
                 for k, v in out.items() if k != "optimisation"}
        assert list(out) == list(JSON_KEYS)
        assert keys is None or shape == keys, args
        keys = shape
        if out["optimisation"] is not None:
            from govopt.optimize.record import KEYS

            assert list(out["optimisation"]) == list(KEYS)
            assert out["optimisation"]["certified"] is True


def test_a_load_cycle_always_has_a_life_infinite_stated_as_such():
    out = _json("spring", *SH, "--fatigue-min-force", "100 N", "--fatigue-max-force", "300 N")
    assert out["fatigue"]["safety_factor"] >= 1.0
    assert out["fatigue"]["life_cycles"] is None
    assert out["fatigue"]["life_cycles_infinite"] == "+inf"
    text = _run("spring", *SH, "--fatigue-min-force", "100 N", "--fatigue-max-force",
                "300 N").stdout
    assert "life                                     infinite" in text


def test_sensitivities_are_dual_elasticities_with_the_stated_sign():
    """d ln(mass) / d ln(limit): the reported elasticity of the allowable stress against
    the mass re-solved with it 1 % higher (a finite difference, here only to test the dual's
    sign and size), and the stiffness's likewise."""
    base = _json("spring", *PLAIN)
    sens = base["optimisation"]["sensitivities"]
    assert "dual-based elasticity" in base["optimisation"]["sensitivity_convention"]
    up = _json("spring", *PLAIN[:5], "606 MPa", *PLAIN[6:])
    fd = math.log(up["optimisation"]["value"] / base["optimisation"]["value"]) / math.log(1.01)
    assert sens["allowable stress"] < 0 and sens["allowable stress"] == pytest.approx(fd,
                                                                                       rel=2e-2)
    stiff = _json("spring", *PLAIN[:3], "10.1 N/mm", *PLAIN[4:])
    fd = math.log(stiff["optimisation"]["value"] / base["optimisation"]["value"]) / math.log(
        1.01)
    assert sens["stiffness"] == pytest.approx(fd, rel=2e-2)


@pytest.mark.parametrize(("extra", "message"), [
    (["--index-min", "13", "--index-max", "12"],
     "error: --index-min 13 and --index-max 12: the least is above the largest"),
    (["--turns-min", "20", "--turns-max", "10"],
     "error: --turns-min 20 and --turns-max 10: the least is above the largest"),
    (["--min-wire-diameter", "5 mm", "--max-wire-diameter", "4 mm"],
     "error: --min-wire-diameter 0.005 m and --max-wire-diameter 0.004 m: the least is above"),
    (["--fatigue-min-force", "100 N", "--fatigue-max-force", "200 N"],
     "error: --fatigue-min-force: a load cycle's fatigue needs a wire grade's fatigue data"),
    (["--tensile-strength", "1500 MPa"],
     "error: --tensile-strength: applies to --material custom only"),
    (["--force", "("], "error: --force: cannot parse '(' as a quantity: its parentheses do "
                        "not match"),
    (["--coil-step", "2"], "error: --coil-step: must lie in (0, 1] (0.25, 0.5 or 1 usual)"),
])
def test_inputs_once_ignored_or_misread_are_refused_by_name(extra, message):
    """Inverted ranges name both options (not an infeasibility diagnosis); fatigue forces
    without a grade and a tensile strength without 'custom' are refused, not ignored; no
    exception's class name in a message."""
    r = invoke(["spring", *PLAIN, *extra])
    assert r.exit_code == 2 and r.output.startswith(message), r.output
    assert "Error)" not in r.output and len(r.output.strip().splitlines()) == 1


@pytest.mark.parametrize(("key", "value"), [
    ("max_free_length", '"1 in"'), ("allowable_stress", '"1000 psi"'),
    ("max_outer_diameter", '"0.3 in"'), ("min_working_deflection", '"100 in"'),
    ("max_preload_deflection", '"0.0001 in"'), ("min_wire_diameter", '"0.6 in"')])
def test_every_infeasible_sandgren_variant_gets_file_key_and_diagnosis(tmp_path, key, value):
    import re

    text = example("sandgren-1990").read_text()
    spec = tmp_path / "variant.toml"
    spec.write_text(re.sub(rf"^{key} = .*$", f"{key} = {value}", text, flags=re.M))
    r = invoke(["spring", str(spec)])
    assert r.exit_code == 2, r.output
    line = r.output.strip()
    assert line.startswith("error: no spring meets these requirements") and \
        f"{spec}: spring.{key}" in line, line
    assert len(line.splitlines()) == 1 and "Error" not in line
