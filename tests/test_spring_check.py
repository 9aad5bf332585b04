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
    # the least working length: L_c + S_a with the nominal d in S_a; static without a load
    # cycle, x1.5 under dynamic load (EN 13906-1)
    S_a = 9.5 * (0.0015 * 20**2 / 2.8 + 0.1 * 2.8) * 1e-3
    assert out["lengths_and_energy"]["least_working_length_m"] == pytest.approx(
        (n_t + extra) * 2.83e-3 + S_a, rel=1e-12)
    dynamic = _json("spring", "check", "--wire-diameter", "2.8 mm", "--mean-diameter", "20 mm",
                    "--active-coils", "9.5", "--ends", ends, "--free-length", "60 mm",
                    "--material", "EN10270-1 SH", "--force", "100 N", "--load", "dynamic")
    assert dynamic["lengths_and_energy"]["least_working_length_m"] == pytest.approx(
        (n_t + extra) * 2.83e-3 + 1.5 * S_a, rel=1e-12)


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


# ------------------------------------------------------------------ the check follows the spring

#: the spring of issue reports: 3 mm wire on 24 mm, 10 active coils (12 total, closed and ground
#: ends), 60 mm free, EN 10270-1 SH (d_max = 3.03 mm: L_c = 12 x 3.03 = 36.36 mm)
SOLID = ["spring", "check", "--wire-diameter", "3 mm", "--mean-diameter", "24 mm",
         "--active-coils", "10", "--free-length", "60 mm", "--material", "EN10270-1 SH"]
#: the spring of `govopt init --type spring-check` (3 mm on 16 mm, 9.5 coils, 60 mm free)
TEMPLATE = ["spring", "check", "--wire-diameter", "3 mm", "--mean-diameter", "16 mm",
            "--active-coils", "9.5", "--free-length", "60 mm", "--material", "EN10270-1 SH"]


def _checks(out):
    return {c["name"]: c for c in out["checks"]}


def test_a_spring_loaded_past_solid_fails_and_says_where_it_goes_solid():
    """100-300 N on a spring solid at 36.36 mm: the force at solid R (L0 - L_c) is the row's
    limit (by hand from the reported rate), the row fails; L2 has no length nor stress (the
    spring never gets there); the static stress is the one at solid, 8 F_c D / (pi d^3)."""
    out = _json(*SOLID, "--min-force", "100 N", "--force", "300 N", code=1)
    R = out["lengths_and_energy"]["rate_N_per_m"]
    assert out["lengths_and_energy"]["solid_length_m"] == pytest.approx(36.36e-3, rel=1e-12)
    F_c = R * (60e-3 - 36.36e-3)
    solid = _checks(out)["largest force <= force at solid length"]
    assert not solid["passed"] and solid["value"] == 300.0
    assert solid["limit"] == pytest.approx(F_c, rel=1e-12) and 141.0 < F_c < 141.2
    L2 = next(p for p in out["working_points"] if p["point"] == "L2")
    assert L2["length_m"] is None and L2["stress_Pa"] is None and L2["force_N"] == 300.0
    static = _checks(out)["static shear stress"]
    assert static["value"] == pytest.approx(8 * F_c * 24e-3 / (math.pi * 3e-3**3), rel=1e-12)
    assert out["lengths_and_energy"]["energy_to_L2_J"] is None
    assert any("beyond the solid length" in n for n in out["notes"])
    text = _run(*SOLID, "--min-force", "100 N", "--force", "300 N", code=1).stdout
    assert "largest force <= force at solid length: 300 <= 141.113 N" in text


def test_a_point_past_solid_is_drawn_nowhere(tmp_path):
    """The workbook's force-length table and the maker's sheet give no length at 300 N (the
    spring is solid at 141 N); the sheet's note says so."""
    import openpyxl

    book = tmp_path / "s.xlsx"
    _run(*SOLID, "--min-force", "100 N", "--force", "300 N", "--xlsx", str(book), code=1)
    wb = openpyxl.load_workbook(book)
    names = [r[0] for r in wb["Force-length"].iter_rows(values_only=True)]
    assert "L1" in names and "L2" not in names
    rows = {r[0]: r[1] for r in wb["Spring"].iter_rows(values_only=True) if r and r[0]}
    assert rows["length 2"] == "nan" and "solid at 141.11 N" in rows["notes"]


def test_a_load_cycle_is_checked_at_its_top():
    """The template spring, solid at R (60 - 34.845) mm: a cycle to 560 N goes solid, one
    between the force at L_n (dynamic) and solid clashes its coils; the working force alone
    (400 N) passes both."""
    base = _json(*TEMPLATE, "--force", "400 N", "--fatigue-min-force", "100 N",
                 "--fatigue-max-force", "400 N", code=1)  # (its fatigue fails at 1e7)
    R = base["lengths_and_energy"]["rate_N_per_m"]
    L_n = base["lengths_and_energy"]["least_working_length_m"]
    F_c = R * (60e-3 - base["lengths_and_energy"]["solid_length_m"])
    assert _checks(base)["working length >= least length (coil clash)"]["passed"]
    assert R * (60e-3 - L_n) < 480.0 < F_c < 560.0
    past = _json(*TEMPLATE, "--force", "400 N", "--fatigue-min-force", "100 N",
                 "--fatigue-max-force", "560 N", code=1)
    assert _checks(past)["largest force <= force at solid length"]["value"] == 560.0
    assert not _checks(past)["largest force <= force at solid length"]["passed"]
    clash = _checks(_json(*TEMPLATE, "--force", "400 N", "--fatigue-min-force", "100 N",
                          "--fatigue-max-force", "480 N", code=1))
    row = clash["working length >= least length (coil clash)"]
    assert not row["passed"] and row["value"] == pytest.approx(60e-3 - 480.0 / R, rel=1e-12)


def test_the_required_life_is_taken_as_asked_below_the_datas():
    """A cycle whose estimated life N lies between 1e3 and 1e7 cycles: the fatigue check
    passes a required life below N and fails one above it (the safety at the required life
    on the same S-N line as the estimate); at 1e7 it is the diagram's."""
    cycle = ["--force", "400 N", "--fatigue-min-force", "100 N", "--fatigue-max-force", "400 N"]
    out = _json(*TEMPLATE, *cycle, code=1)
    N = out["fatigue"]["life_cycles"]
    assert 1e3 < N < 1e7 and out["fatigue"]["safety_factor"] < 1.0
    row = "body fatigue safety factor"
    below = _json(*TEMPLATE, *cycle, "--life", f"{N / 2:.0f}")
    above = _json(*TEMPLATE, *cycle, "--life", f"{N * 2:.0f}", code=1)
    assert _checks(below)[row]["passed"] and not _checks(above)[row]["passed"]
    assert below["fatigue"]["life_cycles"] == pytest.approx(N, rel=1e-9)
    assert "at the required life" in _checks(below)[row]["source"]


@pytest.mark.parametrize(("extra", "message"), [
    (["--free-length", "30 mm", "--force", "100 N"],
     "error: --free-length: expected at least the solid length L_c = 34.845 mm"),
    (["--free-length", "60 mm", "--length-2", "60 mm"],
     "error: --length-2: expected a length under load, got the free length (60 mm"),
    (["--free-length", "60 mm", "--length-2", "61 mm"],
     "error: --length-2: expected at most the free length (60 mm"),
    (["--free-length", "60 mm", "--force", "100 N", "--total-coils", "9.5"],
     "error: --total-coils: expected more than the active coils (9.5) with closed_ground ends"),
    (["--kind", "extension", "--force", "100 N", "--free-length", "1 mm"],
     "error: --free-length: expected at least the close-wound body (n_b + 1) d = "),
    (["--kind", "extension", "--force", "100 N", "--total-coils", "30"],
     "error: --total-coils: an extension spring's body coils n_b, whose active coils are n_b + "
     "G/E = 30.3"),
    (["--kind", "extension", "--free-length", "80 mm", "--length-2", "50 mm"],
     "error: --length-2: expected at least the free length (80 mm: an extension spring is "
     "close-wound below it)"),
])
def test_a_spring_that_cannot_be_is_refused_by_name(extra, message):
    """Free length below solid (11.5 x 3.03 mm), a working length at or beyond the free length
    (no force, as --force '0 N'), closed ends without end coils, an extension spring shorter
    than its close-wound body, its body and active coils contradicting each other, its length
    below its free length: exit 2, one line naming the option."""
    args = ["spring", "check", "--wire-diameter", "3 mm", "--mean-diameter", "16 mm",
            "--active-coils", "9.5", "--material", "EN10270-1 SH", *extra]
    r = invoke(args)
    assert r.exit_code == 2 and r.stderr.startswith(message), r.output
    assert len(r.stderr.strip().splitlines()) == 1


def test_free_length_below_solid_in_a_spec_names_the_file_and_key(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text('[spring]\nwire_diameter = "3 mm"\nmean_diameter = "16 mm"\n'
                    'active_coils = 9.5\nfree_length = "30 mm"\nmaterial = "EN10270-1 SH"\n'
                    'force = "100 N"\n')
    r = invoke(["spring", "check", str(spec)])
    assert r.exit_code == 2 and r.stderr.startswith(
        f"error: {spec}: spring.free_length: expected at least the solid length"), r.output


@pytest.mark.parametrize("ends", ["plain", "open"])
def test_plain_and_open_ends_take_total_coils_equal_to_active(ends):
    """Shigley Table 10-1: plain ends N_t = N_a; their solid length d_max (N_t + 1)."""
    out = _json(*TEMPLATE, "--force", "400 N", "--total-coils", "9.5", "--ends", ends)
    assert out["spring"]["total_coils"] == 9.5
    assert out["lengths_and_energy"]["solid_length_m"] == pytest.approx(10.5 * 3.03e-3,
                                                                        rel=1e-12)


def _numbers(tree, path=""):
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from _numbers(v, f"{path}.{k}")
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from _numbers(v, f"{path}[{i}]")
    elif isinstance(tree, float | int) and not isinstance(tree, bool):
        yield path, tree


@pytest.mark.parametrize("extra", [
    ["--min-force", "0 N", "--force", "100 N"],
    ["--min-force", "5 N", "--force", "100 N", "--initial-tension", "30 N"],
    ["--min-force", "5 N", "--force", "20 N", "--initial-tension", "30 N"],
])
def test_an_extension_spring_never_reports_a_negative_force_or_energy(extra):
    """Below its initial tension an extension spring stays closed: no deflection, the wire
    holding F0; the default initial tension is at most the least force (0 N here: the
    preferred range's row fails rather than the spring opening below F0)."""
    out = _json("spring", "check", "--kind", "extension", "--wire-diameter", "2 mm",
                "--mean-diameter", "16 mm", "--active-coils", "10", "--material",
                "EN10270-1 SH", *extra, code=1)
    assert out["spring"]["initial_tension_N"] <= out["working_points"][1]["force_N"]\
        or "--initial-tension" in extra
    negative = [(p, x) for p, x in _numbers({k: out[k] for k in (
        "spring", "lengths_and_energy", "working_points", "tolerances")})
        if x < 0 and ("force" in p or "energy" in p or "deflection" in p or "length" in p)]
    assert not negative, negative
    if "--initial-tension" not in extra:
        assert out["spring"]["initial_tension_N"] == 0.0
        assert any("initial tension not given: 0 N, the least working force" in n
                   for n in out["notes"])


def test_a_tiny_spring_failing_a_check_is_not_certified():
    """1e-9 N at 1e-9 N/mm buckles: exit 1, the record not certified and naming the row."""
    args = ["spring", "--force", "1e-9 N", "--stiffness", "1e-9 N/mm", "--allowable-stress",
            "600 MPa", "--shear-modulus", "81.5 GPa"]
    out = _json(*args, code=1)
    assert out["optimisation"]["certified"] is False
    assert [c["name"] for c in out["checks"] if not c["passed"]] == [
        "deflection / buckling deflection"]
    text = invoke(args)
    assert text.exit_code == 1 and "global optimum certified" not in text.stdout


def test_custom_wire_without_a_least_diameter_is_designed():
    out = _json("spring", "--force", "500 N", "--stiffness", "20 N/mm", "--material", "custom",
                "--tensile-strength", "1600 MPa", "--shear-modulus", "79 GPa")
    assert out["spring"]["wire_diameter_m"] > 1e-3 and not [
        c for c in out["checks"] if not c["passed"]]


@pytest.mark.parametrize(("extra", "message"), [
    (["--kind", "extension", "--objective", "solid length", "--material", "EN10270-1 DH"],
     "error: --objective: a compression spring's"),
])
def test_a_design_refuses_what_its_kind_cannot_do(extra, message):
    r = invoke(["spring", "--force", "300 N", "--stiffness", "5 N/mm", *extra])
    assert r.exit_code == 2 and r.stderr.startswith(message), r.output


def test_a_300_character_file_name_is_a_one_line_error(tmp_path):
    long = str(tmp_path / ("s" * 300))
    for args in (["spring", "check", long + ".toml"],
                 [*TEMPLATE, "--force", "400 N", "--plots", long],
                 ["spring", *SH, "-o", long + ".toml"]):
        r = invoke(args)
        assert r.exit_code == 2 and r.stderr.startswith(f"error: {long}"), r.output
        assert "File name too long" in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_d_max_from_the_grades_standard_or_the_nominal_d_named_so():
    """0.105 in music wire (ASTM A228, over 0.080 to 0.250 in: +-0.001 in) has d_max = 0.106
    in, the solid length n_t d_max; Shigley's A401 fit has no tolerance table here: the nominal
    d, named so and remarked."""
    args = ["spring", "check", "--wire-diameter", "0.105 in", "--outer-diameter", "1.2 in",
            "--active-coils", "10", "--free-length", "3.5 in", "--force", "20 lbf"]
    a228 = _json(*args, "--material", "ASTM A228", "--shear-modulus", "11.75e6 psi")
    assert a228["spring"]["largest_wire_diameter_m"] == pytest.approx(0.106 * 0.0254, rel=1e-12)
    assert a228["lengths_and_energy"]["solid_length_m"] == pytest.approx(12 * 0.106 * 0.0254,
                                                                         rel=1e-12)
    assert a228["tolerances"]["wire_diameter_tolerance_m"] == pytest.approx(0.001 * 0.0254)
    a401 = _json(*args, "--material", "Shigley A401")
    assert a401["spring"]["largest_wire_diameter_m"] == 0.105 * 0.0254
    text = _run(*args, "--material", "Shigley A401").stdout
    assert not [x for x in text.splitlines() if x.startswith("  largest wire diameter d_max")]
    assert "solid length's wire diameter d" in text and "the nominal d, not d_max" in text


def test_the_chosen_correction_factor_is_named_and_used_in_the_table():
    """With Wahl's factor chosen the working points' corrected stresses are Wahl's (by hand:
    K_W = (4w - 1)/(4w - 4) + 0.615/w at w = 16/3), named beside the table."""
    out = _json(*TEMPLATE, "--force", "200 N", "--correction", "wahl", code=1)
    w = 16 / 3
    K = (4 * w - 1) / (4 * w - 4) + 0.615 / w
    L2 = next(p for p in out["working_points"] if p["point"] == "L2")
    assert L2["corrected_stress_Pa"] == pytest.approx(K * L2["stress_Pa"], rel=1e-12)
    text = _run(*TEMPLATE, "--force", "200 N", "--correction", "wahl", code=1).stdout
    assert "tau_k = k tau, k Wahl's (4w - 1)/(4w - 4) + 0.615/w" in text
    default = _run(*TEMPLATE, "--force", "200 N").stdout
    assert "tau_k = k tau, k Bergstraesser's (w + 0.5)/(w - 0.75)" in default


def test_the_elastic_modulus_is_a_key():
    """E sets the buckling deflection (EN 13906-1 9.14, through 1 - G/E ...): a lower E gives
    a smaller one; the figure reports the E given."""
    long = [*TEMPLATE[:-4], "--free-length", "120 mm", "--material", "EN10270-1 SH",
            "--force", "100 N", "--seating", "hinged-hinged"]
    base = _json(*long, code=1)
    low = _json(*long, "--elastic-modulus", "150 GPa", code=1)
    assert low["material"]["elastic_modulus_Pa"] == 150e9
    assert low["dynamics"]["buckling_deflection_m"] < base["dynamics"]["buckling_deflection_m"]
