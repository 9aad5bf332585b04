"""`govopt spring SPEC.toml`: spring spec files with units and the spec error
conventions, options overriding the file, the bundled literature problems, installed lengths
and stroke, the stored-energy objective."""

import json
import math

import pytest
from clirun import invoke
from springjson import fig

from govopt.examples import SPECS, example
from govopt.optimize import spring_literature as sl
from govopt.springs import compression as hc
from govopt.springs import helical as hx
from govopt.springs import tolerances as tl

SPRINGS = SPECS / "springs"
BASE = ["--allowable-stress", "600 MPa", "--shear-modulus", "81.5 GPa"]
IN3 = 0.0254**3


def _json(*args):
    result = invoke(["spring", *map(str, args), "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.output)


def test_spec_file_equals_the_options_and_options_override_it():
    spec = SPRINGS / "spring-500n.toml"
    from_file = _json(spec)
    from_options = _json("--force", "500 N", "--stiffness", "10 N/mm", *BASE)
    # 151.39 g over the wire length pi D n_t; 152.06 g with the helix rise
    assert fig(from_file, "mass_kg") == pytest.approx(0.15206, rel=1e-4)
    for key in ("wire_diameter_m", "mean_coil_diameter_m", "active_coils", "mass_kg"):
        assert fig(from_file, key) == pytest.approx(fig(from_options, key), rel=1e-9), key
    lower = _json(spec, "--allowable-stress", "500 MPa")  # an option wins over the file
    alone = _json("--force", "500 N", "--stiffness", "10 N/mm", "--allowable-stress", "500 MPa",
                  "--shear-modulus", "81.5 GPa")
    assert fig(lower, "mass_kg") == pytest.approx(fig(alone, "mass_kg"), rel=1e-9)
    assert fig(lower, "mass_kg") > fig(from_file, "mass_kg") * 1.2  # m ~ k_s^-1.9


@pytest.mark.parametrize(("body", "expected"), [
    ('[spring]\nforce = "500 m"\n', "spring.force: '500 m' is not a force"),
    ('[spring]\nforse = "500 N"\n', "spring.forse: unknown key (did you mean 'force'?"),
    ('[spring]\nforce = "500 N"\nturns_min = "3"\n',
     "spring.turns_min: expected a finite number, got '3'"),
    ('[spring]\nforce = "500 N"\nkind = "torsion"\n', "spring.kind: expected one of"),
    ('name = "x"\n', "spring: missing (required: a [spring] table)"),
    ('[spring]\nforce = "500 N"\n', "spring.stiffness: required"),
    ('[spring]\nproblem = "belegundu"\n', "spring.problem: expected one of 'sandgren-1990'"),
    ('[spring]\nforce = "500 N"\nstiffness = "10 N/mm"\nshear_modulus = "81.5 GPa"\n',
     "spring.allowable_stress: required"),
])
def test_spec_errors_name_file_and_key(tmp_path, body, expected):
    spec = tmp_path / "s.toml"
    spec.write_text(body)
    result = invoke(["spring", str(spec)])
    assert result.exit_code == 2
    line = result.output.strip()
    assert line.startswith(f"error: {spec}: ") and expected in line, line
    assert len(line.splitlines()) == 1 and sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]


def test_an_option_error_names_the_option_even_with_a_spec():
    result = invoke(["spring", str(SPRINGS / "spring-500n.toml"), "--force", "-1 N"])
    assert result.exit_code == 2 and result.output.startswith("error: --force: must be positive")


def test_belegundu_arora_spec_is_the_literature_problem_from_its_data():
    """The bundled spec states the problem physically (lbf, in, psi, Hz); its optimum is the
    exact GP's with the constants that follow from those data (c1 = 71875), not with the
    printed 71785 (the best known 0.0126652 in^3 is that one's, slightly lower)."""
    out = _json(example("belegundu-arora"))
    data = sl.solve_belegundu(sl.constants()["c1"])
    printed = sl.solve_belegundu()
    opt = out["optimisation"]
    volume = opt["value"] / IN3
    assert volume == pytest.approx(data.objective, rel=1e-4)  # 12566 etc. are printed rounded
    assert fig(out, "wire_diameter_m") / 0.0254 == pytest.approx(data.d, rel=1e-3)
    assert fig(out, "mean_coil_diameter_m") / 0.0254 == pytest.approx(data.D, rel=1e-3)
    assert fig(out, "active_coils") == pytest.approx(data.N, rel=1e-3)
    assert opt["certified"] is True and opt["bound"] <= opt["value"]
    assert printed.objective < volume * (1 - 5e-4)  # the transposed constant's optimum
    # the least deflection (stiffness at most 20 lbf/in) and the stress bind, as in the papers
    assert {"maximum stiffness", "allowable stress"} <= set(opt["active_constraints"])


def test_sandgren_spec_is_the_exact_mixed_discrete_optimum(tmp_path):
    out = _json(example("sandgren-1990"))
    best = sl.solve_sandgren()
    assert (fig(out, "active_coils"), fig(out, "wire_diameter_m")) == (
        best.N, pytest.approx(best.d * 0.0254))
    assert out["optimisation"]["value"] / IN3 == pytest.approx(best.objective, rel=1e-12)
    assert out["optimisation"]["certified"] and out["optimisation"]["gap"] == 0.0
    assert best.d in sl.SANDGREN_WIRES and fig(out, "active_coils") == int(best.N)
    # its own constraints g1..g8 are its checks, all met
    assert [c["name"][:2] for c in out["checks"]] == [f"g{i}" for i in range(1, 9)]
    assert all(c["passed"] for c in out["checks"])
    # the data are the spec's: a lower allowable stress in a copy moves the optimum
    tight = tmp_path / "tight.toml"
    tight.write_text(example("sandgren-1990").read_text().replace('"189000 psi"', '"150000 psi"'))
    moved = _json(tight)
    want = sl.solve_sandgren({**sl.SANDGREN, "S": 150e3})
    assert moved["optimisation"]["value"] / IN3 == pytest.approx(want.objective, rel=1e-12)
    assert moved["optimisation"]["value"] > out["optimisation"]["value"]
    # an option of its own data overrides the file's; another is an error naming it
    more = _json(example("sandgren-1990"), "--force", "2000 lbf")
    assert more["optimisation"]["value"] / IN3 == pytest.approx(
        sl.solve_sandgren({**sl.SANDGREN, "F_max": 2000.0}).objective, rel=1e-12)
    wrong = invoke(["spring", str(example("sandgren-1990")), "--stiffness", "1 N/mm"])
    assert wrong.exit_code == 2 and wrong.output.startswith("error: --stiffness: not a value")
    # data no wire meets: a diagnosis naming the file and its key, exit code 2
    tight.write_text(example("sandgren-1990").read_text().replace('"14 in"', '"1 in"'))
    none = invoke(["spring", str(tight)])
    assert none.exit_code == 2 and "no spring meets these requirements" in none.output
    assert f"{tight}: spring.max_free_length" in none.output, none.output


def test_installed_lengths_and_stroke():
    """L1 80 mm at 200 N, L2 50 mm at 500 N: stiffness (500 - 200)/30 N/mm, free length L2 +
    F2/R, and the coils clear at L2 (EN 13906-1: L_n = L_c + S_a <= L2), a GP row that binds
    when L2 is short."""
    args = ["--force", "500 N", "--min-force", "200 N", "--length-1", "80 mm", "--length-2",
            "50 mm", "--material", "EN10270-1 SH", "--wire-sizes", "continuous"]
    out = _json(*args)
    R = fig(out, "rate_N_per_m")
    assert R == pytest.approx(300.0 / 0.030, rel=1e-6)
    assert fig(out, "free_length_m") == pytest.approx(0.050 + 500.0 / R)
    d, D, n = (fig(out, k) for k in ("wire_diameter_m", "mean_coil_diameter_m", "active_coils"))
    d_max = float(tl.max_wire_diameter(d, "EN10270-1 SH"))  # EN 13906-1: L_c = n_t d_max
    L_n = float(hc.min_working_length(d, D, n, n + 2, "closed_ground", True, False, d_max))
    assert L_n <= 0.050 * (1 + 1e-6) and L_n == pytest.approx(
        fig(out, "least_working_length_m"), rel=1e-12)
    assert "working length" in out["optimisation"]["active_constraints"]
    assert all(c["passed"] for c in out["checks"]), [c["name"] for c in out["checks"]]
    free = _json("--force", "500 N", "--stiffness", "10 N/mm", "--material", "EN10270-1 SH",
                 "--wire-sizes", "continuous")
    assert fig(out, "mass_kg") > fig(free, "mass_kg")  # the short installed length costs mass
    same = _json("--force", "500 N", "--min-force", "200 N", "--stroke", "30 mm",
                 "--length-2", "50 mm", "--material", "EN10270-1 SH", "--wire-sizes",
                 "continuous")
    assert fig(same, "mass_kg") == pytest.approx(fig(out, "mass_kg"), rel=1e-9)


@pytest.mark.parametrize(("extra", "expected"), [
    (["--length-1", "80 mm", "--length-2", "50 mm", "--stroke", "20 mm"],
     "--stroke: expected --length-1 - --length-2 = 30 mm"),
    (["--length-1", "40 mm", "--length-2", "50 mm"], "--length-1: expected longer"),
    (["--length-1", "80 mm", "--length-2", "50 mm", "--stiffness", "20 N/mm"],
     "--stiffness: contradicts the forces and the stroke, which give 10 N/mm"),
    (["--length-1", "80 mm"], "--length-1: give --length-2 or --stroke with it"),
])
def test_stroke_errors(extra, expected):
    result = invoke(["spring", "--force", "500 N", "--min-force", "200 N", *BASE, *extra])
    assert result.exit_code == 2 and expected in result.output, result.output


def test_energy_per_mass_objective():
    """With a stiffness range the most energy per mass F^2 / (2 R m) takes the softest
    spring; its value is the reported design's, and it beats the stiffest end's."""
    args = ["--force", "500 N", "--stiffness", "10 N/mm", "--max-stiffness", "20 N/mm", *BASE]
    out = _json(*args, "--objective", "energy per mass")
    R, m = fig(out, "rate_N_per_m"), fig(out, "mass_kg")
    assert R == pytest.approx(10e3, rel=1e-6)
    opt = out["optimisation"]
    assert opt["objective"] == {"name": "energy per mass", "unit": "J/kg", "sense": "maximise"}
    assert opt["value"] == pytest.approx(500.0**2 / (2 * R * m), rel=1e-9)
    assert opt["certified"] is True
    stiff = _json("--force", "500 N", "--stiffness", "20 N/mm", *BASE)
    assert opt["value"] > fig(stiff, "energy_to_L2_J") / fig(stiff, "mass_kg")
    assert opt["bound_kind"] == "upper"  # a bound on the energy per mass is an upper one
    assert opt["value"] <= opt["bound"] <= opt["value"] * (1 + 1e-6)
    # maximised: the elasticities are of the energy per mass (the stress's raises it)
    assert opt["sensitivities"]["allowable stress"] > 0


def test_init_names_the_spring_command(tmp_path):
    result = invoke(["init", "sandgren-1990", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert "govopt spring" in result.output
    assert (tmp_path / "sandgren-1990.toml").read_bytes() == example("sandgren-1990").read_bytes()


def test_finite_life_is_basquins_line_through_its_two_points():
    """Shigley §6-7: S_f = a N^b through (1e3, 0.9 S_su) and (1e7, S_se); the life at a safety
    s < 1 is where S_f = S_se / s. Its ends: the 1e3-cycle point, and 1e7 as s -> 1."""
    from govopt.springs import fatigue as fat

    Sse, Ssu = 336e6, 1340e6
    assert float(fat.finite_life(Sse / (0.9 * Ssu), Sse, Ssu)) == pytest.approx(1e3, rel=1e-9)
    assert float(fat.finite_life(1 - 1e-9, Sse, Ssu)) == pytest.approx(1e7, rel=1e-6)
    assert math.isinf(fat.finite_life(1.0, Sse, Ssu)) and math.isnan(fat.finite_life(0.1, Sse,
                                                                                     Ssu))
    b = math.log10(Sse / (0.9 * Ssu)) / 4.0
    a = Sse / 1e7**b
    N = float(fat.finite_life(0.7, Sse, Ssu))
    assert a * N**b == pytest.approx(Sse / 0.7, rel=1e-9)


def test_fatigue_below_the_endurance_gives_a_finite_life():
    """A spring allowed a fatigue safety of 0.5 for a required 1e5 cycles (the row's safety at
    that life: the one at the data's 1e7 cycles times the S-N line's strength ratio): the
    verdict gives its estimated life from the safety at 1e7, the JSON the same number."""
    from govopt.springs import fatigue as fat
    from govopt.springs.materials import material

    args = ["--force", "500 N", "--stiffness", "20 N/mm", "--material", "EN10270-1 SH",
            "--fatigue-min-force", "100 N", "--fatigue-max-force", "500 N", "--life", "1e5",
            "--min-fatigue-safety", "0.5"]
    out = _json(*args)
    row = next(c for c in out["checks"] if c["name"] == "body fatigue safety factor")
    assert row["value"] < 1.0
    Sse, Ssu = fat.reversed_endurance(material("EN10270-1 SH"), fig(out, "wire_diameter_m"))
    at_data = row["value"] / float(fat.life_factor(1e5, Sse, Ssu))
    assert at_data < row["value"]
    life = float(fat.finite_life(at_data, Sse, Ssu))
    assert out["fatigue"]["life_cycles"] == pytest.approx(life, rel=1e-9) and 1e3 < life < 1e7
    assert out["fatigue"]["safety_factor"] == row["value"]
    text = invoke(["spring", *args]).output
    assert f"life                                     {life:.5g} cycles" in text


def test_workbook_and_plots(tmp_path):
    """--xlsx: a Summary with the answer, the spring maker's sheet in engineering units, every
    check, the force-length table at the maker's working points, the inputs (Spec); --plots:
    force-length and the fatigue diagram; an existing file is refused before the run without
    --replace, and a failed run writes nothing."""
    import openpyxl

    args = ["--force", "500 N", "--stiffness", "20 N/mm", "--material", "EN10270-1 SH",
            "--fatigue-min-force", "100 N", "--fatigue-max-force", "500 N"]
    book, folder = tmp_path / "s.xlsx", tmp_path / "plots"
    run = invoke(["spring", *args, "--xlsx", str(book), "--plots", str(folder)])
    assert run.exit_code == 0, run.output  # the wire table's best spring passes fatigue too
    out = json.loads(invoke(["spring", *args, "--json"]).stdout)
    wb = openpyxl.load_workbook(book)
    assert wb.sheetnames == ["Summary", "Spring", "Checks", "Force-length", "Spec"]
    answer = {r[0]: r[1:3] for r in wb["Summary"].iter_rows(values_only=True) if r[0]}
    assert answer["wire diameter d"] == (pytest.approx(fig(out, "wire_diameter_m") * 1e3), "mm")
    assert answer["free length L0"] == (pytest.approx(fig(out, "free_length_m") * 1e3), "mm")
    assert answer["claim"][0] == out["optimisation"]["claim"]
    checks = [r for r in wb["Checks"].iter_rows(min_row=3, values_only=True) if r[0]]
    assert [r[0] for r in checks] == [c["name"] for c in out["checks"]]
    table = [r[1:3] for r in wb["Force-length"].iter_rows(min_row=3, values_only=True)
             if isinstance(r[1], float)]
    R = fig(out, "rate_N_per_m")
    assert len(table) >= 3 and all(
        f == pytest.approx(R * (fig(out, "free_length_m") - L / 1e3), abs=1e-6) for L, f in table)
    assert sorted(p.name for p in folder.iterdir()) == [
        f"spring-{k}.{x}" for k in ("fatigue", "force-length") for x in ("png", "svg")]
    again = invoke(["spring", *args, "--xlsx", str(book)])
    assert again.exit_code == 2
    assert again.output.strip() == f"error: {book}: workbook already exists; use --replace to " \
        "replace it"  # this command's option (its --force is the spring's force)
    plot = folder / "spring-force-length.svg"
    mtime = plot.stat().st_mtime_ns
    refused = invoke(["spring", *args, "--plots", str(folder)])
    assert refused.exit_code == 2 and "use --replace" in refused.output
    assert plot.stat().st_mtime_ns == mtime
    assert invoke(["spring", *args, "--xlsx", str(book), "--replace"]).exit_code == 0
    none = tmp_path / "none.xlsx"
    bad = invoke(["spring", *args, "--max-outer-diameter", "1 mm", "--xlsx", str(none)])
    assert bad.exit_code == 2 and not none.exists()


@pytest.mark.parametrize("replace", [[], ["--replace"]])
def test_outputs_that_collide_are_refused_before_anything_is_written(tmp_path, replace):
    """A workbook named as one of the run's plots (or the -o spec as the workbook) is refused
    before the run, --replace or not: nothing written, no file lost."""
    folder = tmp_path / "p"
    folder.mkdir()
    clash = folder / "spring-force-length.png"
    args = ["spring", "--force", "500 N", "--stiffness", "10 N/mm", *BASE]
    result = invoke([*args, "--plots", str(folder), "--xlsx", str(clash), *replace])
    assert result.exit_code == 2, result.output
    assert "another output of this run" in result.output and str(clash) in result.output
    assert list(folder.iterdir()) == []
    same = tmp_path / "x.out"
    result = invoke([*args, "-o", str(same), "--xlsx", str(same), *replace])
    assert result.exit_code == 2 and "another output of this run" in result.output
    assert not same.exists()


@pytest.mark.parametrize("extra", [[], ["--kind", "extension"], ["--length-2", "80 mm"]])
def test_force_length_plot_and_table_read_one_computation(extra):
    """Without a wire grade too, the workbook's force-length table and the plot have the same
    free and solid lengths: the assessment's, also in the JSON; the plot marks the working
    points, not the free length, and carries the spring's name."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from govopt import spring_command
    from govopt.report import spring_outputs as so

    args = dict(force="500 N", stiffness="10 N/mm", allowable_stress="600 MPa",
                shear_modulus="81.5 GPa", name="valve spring",
                **{extra[i][2:].replace("-", "_"): extra[i + 1] for i in range(0, len(extra), 2)})
    out = spring_command.run(**args)
    table = so.force_length_points(out)
    fig_, ax = plt.subplots()
    so.force_length(out, ax)
    line = ax.lines[0].get_xdata()  # the spring's line in mm
    marked = [t.get_text() for t in ax.get_legend().get_texts() if t.get_text()[:1] == "L"]
    title = ax.get_title()
    plt.close(fig_)
    L0 = out.data["spring"]["free_length_m"]
    assert table[0][1] == L0 and line[0] == pytest.approx(L0 * 1e3, rel=1e-15)
    assert title == "valve spring: force against length"
    assert [m.split(",")[0] for m in marked] == ["L2"]  # no least force: L2 only, not L0
    if out.assessment.spring.kind == "compression":
        Lc = out.data["lengths_and_energy"]["solid_length_m"]
        assert table[-1][1] == Lc and line[-1] == pytest.approx(Lc * 1e3, rel=1e-15)
        assert Lc < out.data["lengths_and_energy"]["least_working_length_m"] < L0
    if "--length-2" in extra:
        R = out.data["lengths_and_energy"]["rate_N_per_m"]
        assert L0 == pytest.approx(0.080 + 500.0 / R)


def test_long_installed_lengths_pass_their_solid_stress_and_pitch():
    """L2 120 mm, L1 150 mm: the force at solid length F + R (L2 - L_c) and the free pitch are
    not posynomials; the GP restricts them (F + R (L2 - lam), lam <= L_c; m <= L0/n) so the
    design passes every check (they failed when the GP took the least free length's F_c), and
    the bound is the relaxation's: "optimal within X %", not a global optimum."""
    args = ["--force", "500 N", "--min-force", "200 N", "--length-1", "150 mm", "--length-2",
            "120 mm", "--material", "EN10270-1 SH", "--wire-sizes", "continuous"]
    out = _json(*args)
    rows = {c["name"]: c for c in out["checks"]}
    assert all(c["passed"] for c in out["checks"]), [n for n, c in rows.items() if not c["passed"]]
    d, D, n = (fig(out, k) for k in ("wire_diameter_m", "mean_coil_diameter_m", "active_coils"))
    L_c = float(hc.solid_length(tl.max_wire_diameter(d, "EN10270-1 SH"), n + 2,
                                "closed_ground"))
    F_c = 500.0 + fig(out, "rate_N_per_m") * (0.120 - L_c)  # the force at solid length
    tau_c = float(hx.shear_stress(F_c, d, D))  # EN 13906-1 static: uncorrected
    assert rows["shear stress at solid length"]["value"] == pytest.approx(tau_c, rel=1e-6)
    opt = out["optimisation"]
    assert opt["certified"] is False and opt["bound"] < opt["value"] == fig(out, "mass_kg")
    assert math.isfinite(opt["gap"]) and opt["gap"] > 0
    text = invoke(["spring", *args]).output
    assert f"optimal within {100 * opt['gap']:.3g} % of a certified bound" in text


def test_a_file_that_appears_during_the_run_is_not_replaced_without_replace(tmp_path):
    """The workbook is written with the run's --replace, not always replacing: a file that
    appeared after the check survives, and the message names this command's option."""
    from govopt import spring_command
    from govopt.errors import GovoptError
    from govopt.report import spring_outputs as so
    from govopt.report.files import overwrite_option

    out = spring_command.run(force="500 N", stiffness="10 N/mm", allowable_stress="600 MPa",
                             shear_modulus="81.5 GPa")
    book = tmp_path / "s.xlsx"
    book.write_text("someone else's")
    with overwrite_option("--replace"), pytest.raises(GovoptError, match="use --replace"):
        so.write_workbook(out, book, replace=False)
    assert book.read_text() == "someone else's"
    with pytest.raises(GovoptError, match="use --force"):  # every other command's option
        so.write_workbook(out, book, replace=False)
