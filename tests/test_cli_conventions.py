"""What an engineer sees: a CLI with the conventions of the tools
engineers use (version, exit codes, plain flags, outputs where asked or here, bundled specs that
ship in a non-editable install), the units people type, and round trips that keep the
engineer's file. CLI points about the process itself (its exit status, a closed pipe, the
version and help of the console entry point, an installed copy) run it in a subprocess; the
others run the CLI in this process, in the folder a user would run it in."""

import dataclasses
import importlib.metadata
import json
import math
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from clirun import invoke

import govopt
from govopt import cli
from govopt.examples import SPECS, examples
from govopt.report.files import READ_BACK_ULPS, design_toml
from govopt.units import G_STANDARD, UnitError, parse_quantity

ROOT = Path(__file__).resolve().parent.parent
CLI = [sys.executable, "-m", "govopt.cli"]
LBF = 0.45359237 * G_STANDARD  # N: the avoirdupois pound (exactly 0.45359237 kg) under g_n
INCH = 0.0254  # m, exactly


def _govopt(*args, cwd, env=None):
    return subprocess.run([*CLI, *map(str, args)], cwd=cwd, capture_output=True, text=True,
                          env=env, timeout=120)


def _files(folder: Path) -> set[Path]:
    return {p for p in folder.rglob("*") if "__pycache__" not in p.parts}


# ------------------------------------------------------------------------------------------
# item 4: CLI conventions


def test_version(tmp_path):
    run = _govopt("--version", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert run.stdout == f"govopt {govopt.__version__}\n"
    assert govopt.__version__ == importlib.metadata.version("govopt")


def test_evaluate_exit_codes(tmp_path):
    """0: every check passed; 1: the report is printed and some check failed (named on
    stderr); 2: bad input (one line). Each a process of its own, forked from one interpreter
    that loaded `govopt evaluate`'s modules once."""
    from forkcli import COMMON, Server

    with Server((*COMMON, "govopt.cli", "govopt.commands.evaluate", "govopt.evaluator"),
                cwd=tmp_path) as server:
        p = server.run("evaluate", SPECS / "hamabe-b.toml")
        assert p.returncode == 0, p.stderr
        assert "FAIL" not in p.stdout and p.stderr == ""
        p = server.run("evaluate", SPECS / "hamabe-a.toml", "--json")
        assert p.returncode == 1, p.stderr
        checks = json.loads(p.stdout)["checks"]  # stdout is the JSON alone
        assert [c["name"] for c in checks if not c["passed"]] == ["irregularity"]  # > 0.12
        p = server.run("evaluate", SPECS / "hamabe-a.toml")
        assert p.returncode == 1 and "FAIL" in p.stdout
        failed, advice = p.stderr.splitlines()  # the failed check, then what makes it pass
        assert failed == f"1 of {len(checks)} checks failed: irregularity"
        assert advice.startswith("it passes if one of these moves: speed.irregularity 0.12 -> ")
        p = server.run("evaluate", tmp_path / "absent.toml")
        assert p.returncode == 2 and p.stderr.startswith("error: ") and p.stdout == ""


def test_no_command_prints_the_help():
    """`govopt` (and `govopt study`) with no command print the help, each command with its
    one-line help, on stdout; exit 2: nothing was run."""
    run = invoke([])
    assert run.exit_code == 2 and run.stderr == ""
    for command, short in (("evaluate", "Evaluate the spec's design"), ("design", "Find the"),
                           ("spring", "Least-mass helical"), ("bench", "Speed against error"),
                           ("examples", "List the bundled"), ("init", "Copy a bundled"),
                           ("study", "Batch trade studies")):
        assert re.search(rf"^[\s│]+{command}\s+{re.escape(short)}", run.stdout, re.M), command
    study = invoke(["study"])
    assert study.exit_code == 2 and re.search(r"^[\s│]+export\s+Export", study.stdout, re.M)


@pytest.mark.parametrize("args", [
    ["evaluate", "--bogus"], ["nosuch"], ["spring", "--force", "1 N"], ["evaluate", "a", "b"],
    ["evaluate", "--geo", "series"],  # no abbreviated options
    ["study", "run", "x.toml", "--lhs", "abc"], ["study", "export", "x.db"], ["--bogus"],
    ["init"], ["evaluate", "--json", "--plots"]])
def test_bad_command_line_is_one_error_line(args):
    run = invoke(args)
    assert run.exit_code == 2 and run.stdout == "" and "Traceback" not in run.stderr, run.output
    assert len(run.stderr.splitlines()) == 1 and run.stderr.startswith("error: "), run.stderr
    assert "--help" in run.stderr  # where to look


def test_an_options_value_may_start_with_a_dash():
    """The word after an option that takes a value is its value (as click read it), even
    `-x`: the command, not the parser, says what is wrong with it."""
    run = invoke(["evaluate", "--geometry", "-x"])
    assert run.exit_code == 2
    assert run.stderr == "error: --geometry: expected 'exact' or 'series', got '-x'\n"


#: commands whose reader may leave early (`govopt design | head -1`), and the exit code each
#: has when its output is read to the end
CLOSED_PIPE = {
    "design": (("design", SPECS / "porter-design.toml"), 0),
    "evaluate, a check fails": (("evaluate", SPECS / "hamabe-a.toml", "--json"), 1),
    "spring check": (("spring", "check", "--wire-diameter", "3 mm", "--mean-diameter", "20 mm",
                      "--free-length", "60 mm", "--force", "100 N", "--active-coils", "8",
                      "--material", "EN10270-1 SH"), 0),
    "schema": (("schema",), 0),
    "examples": (("examples",), 0),
    "study show": (("study", "show", "{db}"), 0),
}


@pytest.mark.parametrize("name", CLOSED_PIPE)
def test_the_exit_code_is_the_commands_own_whatever_its_reader_does(tmp_path, name):
    """One exit-code contract (0 done and passing, 1 a check failed, 2 bad input, 3 govopt's
    fault): a reader that leaves early (stdout closed before the first line is written) changes
    nothing but what is printed: the same code as a run read to the end, every time, nothing
    on stderr but the run's own lines; stdout that cannot be written (a full disk,
    ``/dev/full``) is one line naming it, exit 2."""
    import hostile

    args, code = CLOSED_PIPE[name]
    if "{db}" in args:  # a sound study database (Hamabe's Example 1 as a study)
        args = tuple(str(hostile.sound_db()) if a == "{db}" else a for a in args)
    whole = _govopt(*args, cwd=tmp_path)
    assert whole.returncode == code, whole.stderr
    for _ in range(2):
        p = subprocess.Popen([*CLI, *map(str, args)], cwd=tmp_path, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
        p.stdout.close()  # before anything is written: every write meets a closed pipe
        err = p.stderr.read()
        assert (p.wait(timeout=120), err) == (code, whole.stderr)
    with open("/dev/full", "w") as full:
        p = subprocess.run([*CLI, *map(str, args)], cwd=tmp_path, stdout=full,
                           stderr=subprocess.PIPE, text=True, timeout=120)
    assert (p.returncode, p.stderr) == (
        2, "error: stdout: cannot write the output (no space left on device)\n")


def test_the_reference_documents_exit_codes_and_every_limit():
    """docs/reference/limits-and-exit-codes.md (the README points to it) gives every exit code
    and every limit of govopt/limits.py at its value (``1 000 000`` or ``1e12``)."""
    from govopt import limits

    page = (ROOT / "docs" / "reference" / "limits-and-exit-codes.md").read_text(encoding="utf-8")
    assert "reference/limits-and-exit-codes.md" in (ROOT / "README.md").read_text(
        encoding="utf-8")
    for code in (0, 1, 2, 3):
        assert re.search(rf"^\| {code} \|", page, re.M), code
    for name in dir(limits):
        if name.startswith("MAX_") or name.startswith("MIN_"):
            value = getattr(limits, name)
            shown = {f"{value:,}".replace(",", " "), f"{value:g}".replace("e+", "e"),
                     f"{value:g} s"}
            assert any(s in page for s in shown), (name, value)


def _commands():
    """Every command of the CLI, as the words that name it (``("study", "run")``), as the
    helps list them (a group's help has a Commands panel)."""
    for name in cli.COMMANDS:
        shown = invoke([name, "--help"]).stdout
        panel = shown.split("─ Commands ─", 1)[1] if "─ Commands ─" in shown else ""
        subcommands = re.findall(r"^│ (\w+)\s", panel, re.M)
        yield from ((name, sub) for sub in subcommands) if subcommands else [(name,)]


#: typer's own flags, which typer shows with their type
TYPERS_FLAGS = ("--help", "--install-completion", "--show-completion")


def test_flags_shown_without_a_type(tmp_path):
    """govopt's flags read `--json  Print ...`, as in git or pip, not `--json <bool>`; options
    that take a value name it (`--xlsx <path>`)."""
    run = _govopt("evaluate", "--help", cwd=tmp_path)
    assert run.returncode == 0 and re.search(r"^[\s│]+--json\s+Print", run.stdout, re.M)
    assert re.search(r"--xlsx\s+<path>", run.stdout)
    commands = list(_commands())
    assert {("evaluate",), ("design",), ("examples",), ("init",), ("study", "run"),
            ("study", "export"), ("study", "show")} <= set(commands)
    for command in [(), *commands]:
        shown = invoke([*command, "--help"])
        typed = [line for line in shown.output.splitlines() if "<bool>" in line]
        assert shown.exit_code == 0 and typed, command  # --help itself
        assert all(line.split()[1] in TYPERS_FLAGS for line in typed), (command, typed)


def test_outputs_go_here_never_into_the_package(tmp_path):
    """`govopt design --json -o` writes only the design spec (no workbook unless asked) and says
    on stderr what it wrote where; `govopt design` writes nothing (one rule: files only where
    asked), `govopt design --xlsx` its workbook where asked and says so; nothing is ever
    written inside the package."""
    package = Path(govopt.__file__).resolve().parent
    before = _files(package)
    json_run = invoke(["design", "--json", "-o", "d.toml"], cwd=tmp_path)
    assert json_run.exit_code == 0, json_run.stderr
    assert json.loads(json_run.stdout)["kind"] == "design"
    assert sorted(os.listdir(tmp_path)) == ["d.toml"]
    assert "wrote d.toml" in json_run.stderr  # the path as given
    run = invoke(["design"], cwd=tmp_path)
    assert run.exit_code == 0, run.stderr
    assert sorted(os.listdir(tmp_path)) == ["d.toml"] and "wrote" not in run.stdout
    run = invoke(["design", "--xlsx", "hamabe-design.xlsx"], cwd=tmp_path)
    assert run.exit_code == 0, run.stderr
    assert sorted(os.listdir(tmp_path)) == ["d.toml", "hamabe-design.xlsx"]
    assert run.stdout.rstrip().endswith("wrote hamabe-design.xlsx")
    assert _files(package) == before


def test_examples_and_init(tmp_path):
    listed = invoke(["examples"], cwd=tmp_path)
    assert listed.exit_code == 0, listed.stderr
    names = [line.split()[0] for line in listed.stdout.splitlines()]
    assert names == sorted(p.stem for p in [*SPECS.glob("*.toml"), *SPECS.glob("studies/*"),
                                            *SPECS.glob("springs/*")])
    assert "hamabe-a" in names and "hamabe-study" in names
    assert "Hamabe Example 1, case a" in listed.stdout  # each with its description
    run = invoke(["init", "hamabe-a"], cwd=tmp_path)
    assert run.exit_code == 0, run.stderr
    copy = tmp_path / "hamabe-a.toml"
    assert copy.read_bytes() == (SPECS / "hamabe-a.toml").read_bytes()
    assert "wrote hamabe-a.toml" in run.stdout and "govopt evaluate hamabe-a.toml" in run.stdout
    again = invoke(["init", "hamabe-a"], cwd=tmp_path)
    assert again.exit_code == 2 and "already exists; use --force" in again.stderr
    (tmp_path / "sub").mkdir()
    into = invoke(["init", "hamabe-design.toml", "-o", "sub"], cwd=tmp_path)
    assert into.exit_code == 0 and (tmp_path / "sub" / "hamabe-design.toml").is_file()
    assert "govopt design sub/hamabe-design.toml" in into.stdout  # a design problem
    study = invoke(["init", "hamabe-study", "-o", "sub"], cwd=tmp_path)  # a trade study
    assert study.exit_code == 0, study.stderr
    assert (tmp_path / "sub" / "hamabe-study.toml").read_bytes() == \
        (SPECS / "studies" / "hamabe-study.toml").read_bytes()
    assert "govopt study sub/hamabe-study.toml" in study.stdout
    typo = invoke(["init", "hamabe-z"], cwd=tmp_path)
    assert typo.exit_code == 2 and "did you mean 'hamabe-" in typo.stderr
    assert sorted(os.listdir(tmp_path)) == ["hamabe-a.toml", "sub"]


def test_the_bundled_specs_are_the_checkouts_specs_folder():
    """The suite runs on an editable install of this checkout: `govopt examples` and `govopt
    init` read the repository's top-level specs/ (pyproject.toml maps it to govopt.specs)."""
    assert SPECS.resolve() == ROOT / "specs"
    assert examples()["hamabe-a"] == SPECS / "hamabe-a.toml"


def test_the_listed_packages_are_govopts_folders():
    """pyproject.toml lists the packages (setuptools' find cannot map specs/ into govopt):
    every folder of govopt with an ``__init__.py`` is listed, and govopt.specs maps to specs/."""
    tool = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    folders = {".".join(p.parent.relative_to(ROOT).parts)
               for p in (ROOT / "govopt").rglob("__init__.py")}
    assert set(tool["packages"]) == folders | {"govopt.specs"}
    assert tool["package-dir"] == {"govopt.specs": "specs"}


def test_non_editable_install_ships_the_specs(tmp_path):
    """What a wheel installs (setuptools' build_py: the modules and the package data of
    pyproject.toml), imported from another folder: the bundled specs are there, `govopt
    examples` lists them all, the default spec evaluates, and `govopt init` copies one."""
    site, work = tmp_path / "site", tmp_path / "work"
    work.mkdir()
    build = ("from setuptools import Distribution\n"
             "from setuptools.config.pyprojecttoml import apply_configuration\n"
             "dist = apply_configuration(Distribution(), 'pyproject.toml')\n"
             "dist.script_name = 'setup.py'\n"
             "cmd = dist.get_command_obj('build_py')\n"
             f"cmd.build_lib = {str(site)!r}\n"
             "cmd.ensure_finalized()\n"
             "cmd.run()\n")
    subprocess.run([sys.executable, "-c", build], cwd=ROOT, check=True, capture_output=True,
                   timeout=120)
    env = {**os.environ, "PYTHONPATH": str(site)}
    where = subprocess.run([sys.executable, "-c", "import govopt; print(govopt.__file__)"],
                           cwd=work, env=env, capture_output=True, text=True, check=True)
    assert Path(where.stdout.strip()).parent == site / "govopt"
    assert sorted(p.name for p in (site / "govopt" / "specs").glob("*.toml")) == sorted(
        p.name for p in SPECS.glob("*.toml"))
    from forkcli import Server

    # the installed copy's commands, each a process forked from one interpreter in that
    # environment and folder which imported that copy's govopt.cli
    with Server(("govopt.cli", "govopt.units:ureg"), cwd=work, env=env) as server:
        listed = server.run("examples").stdout
        assert [line.split()[0] for line in listed.splitlines()] == list(examples())
        p = server.run("evaluate", "--json")
        assert p.returncode == 1, p.stderr  # case a's irregularity check fails
        assert json.loads(p.stdout)["name"] == "hamabe-a"
        assert server.run("init", "porter-design").returncode == 0
    assert os.listdir(work) == ["porter-design.toml"]


def test_readme_and_docs_cite_documents_in_the_repository():
    """Every page the README and docs/ name or link exists; nothing points outside the
    repository."""
    pages = [ROOT / "README.md", *(ROOT / "docs").rglob("*.md")]
    for page in pages:
        text = page.read_text(encoding="utf-8")
        for path in re.findall(r"`(docs/[\w./-]+\.md)`", text):
            assert (ROOT / path).is_file(), (page, path)
        for link in re.findall(r"\]\(([\w./-]+\.md)(?:#[\w-]*)?\)", text):
            target = (page.parent / link).resolve()
            assert target.is_file(), (page, link)
        assert "../shared/" not in text and "/work/" not in text, page


# ------------------------------------------------------------------------------------------
# item 5: units people type


@pytest.mark.parametrize(("text", "dimension", "si"), [
    ("300 rev/min", "angular_velocity", 300 * 2 * math.pi / 60),
    ("300 RPM", "angular_velocity", 300 * 2 * math.pi / 60),
    ("4000 kgf/cm2", "stress", 4000 * G_STANDARD / 1e-4),
    ("4000 kgf/cm\u00b2", "stress", 4000 * G_STANDARD / 1e-4),
    ("100 psi", "stress", 100 * LBF / INCH**2),
    ("30 lbf/in", "stiffness", 30 * LBF / INCH),
    ("43 kgf\u00b7m\u00b7s2", "inertia", 43 * G_STANDARD),
    ("7.85 g/cm3", "density", 7850.0),
])
def test_units_people_type(text, dimension, si):
    assert parse_quantity(text, dimension) == pytest.approx(si, rel=1e-14)


@pytest.mark.parametrize(("text", "dimension", "message"), [
    ("18 kfg", "force", "cannot parse '18 kfg' as a quantity: unknown unit 'kfg' "
                        "(did you mean 'kgf'?)"),
    ("300 revs/mn", "angular_velocity", "unknown unit 'mn'"),
    ("18 m", "angular_velocity", "'18 m' is not an angular velocity"),
    ("58 cm", "angle", "'58 cm' is not an angle"),
    (True, "inertia", "expected an inertia with units"),
    ("5 Hz", "angular_velocity", "'5 Hz' names no angle: pint would read it as 5 rad/s"),
])
def test_unit_errors_name_the_unit_grammatically(text, dimension, message):
    with pytest.raises(UnitError, match=re.escape(message)):
        parse_quantity(text, dimension)


def test_a_spec_in_typed_units_reads_the_same(tmp_path):
    base = (SPECS / "hamabe-a.toml").read_text(encoding="utf-8")
    typed = base.replace('"240 rpm"', '"240 rev/min"').replace('"4000 kgf/cm^2"',
                                                                '"4000 kgf/cm2"')
    assert typed.count("rev/min") == 1 and typed.count("kgf/cm2") == 1
    path = tmp_path / "typed.toml"
    path.write_text(typed, encoding="utf-8")
    a, b = govopt.load_spec(SPECS / "hamabe-a.toml"), govopt.load_spec(path)
    assert b.speed == a.speed and b.material == a.material


@pytest.mark.parametrize(("old", "new", "message"), [
    ("irregularity = 0.12", "irregularty = 0.12",
     "speed.irregularity: missing (required); the table has 'irregularty': did you mean "
     "'irregularity'?"),
    ('pendulum_weight = "12 kgf"', 'pendulum_wieght = "12 kgf"',
     "design.pendulum_weight: missing (required); the table has 'pendulum_wieght'"),
    ("dashpot_a1 =", "dashpot_a2 =", "design.dashpot_a2: unknown key (did you mean 'dashpot_a1'?"),
])
def test_misspelt_keys_get_did_you_mean(tmp_path, old, new, message):
    text = (SPECS / "hamabe-a.toml").read_text(encoding="utf-8")
    assert text.count(old) == 1
    path = tmp_path / "typo.toml"
    path.write_text(text.replace(old, new), encoding="utf-8")
    run = invoke(["evaluate", str(path)])
    assert run.exit_code == 2 and run.stdout == ""
    assert run.stderr.startswith(f"error: {path}: {message}")


# ------------------------------------------------------------------------------------------
# item 7: round trips keep the engineer's file


def _with_design():
    """Every bundled spec with a given design (a study's spec is read by `govopt study`)."""
    return [p for p in sorted(SPECS.glob("*.toml"))
            if {"design"} <= (d := tomllib.loads(p.read_text(encoding="utf-8"))).keys()
            and "study" not in d]


@pytest.mark.parametrize("path", _with_design(), ids=lambda p: p.stem)
def test_design_written_back_unchanged_is_the_same_file(path):
    """Writing a spec's own design back changes nothing: every comment, key, unit and digit
    (``"9.510 cm"`` stays) as the engineer wrote it."""
    res = govopt.evaluate(govopt.load_spec(path))
    assert design_toml(res) == path.read_text(encoding="utf-8")


def _reads_back(value: float, target: float) -> bool:
    """Equal up to the unit conversion's own rounding (a product and a quotient: "3.5 kgf" is
    3.4999999999999996 kg), READ_BACK_ULPS units in the last place."""
    return abs(value - target) <= READ_BACK_ULPS * math.ulp(target)


def _shortest(text: str, dimension: str, target: float, scale: float = 1.0) -> bool:
    """``text`` reads back as ``target`` and no number with fewer significant digits in the
    same unit does."""
    number, unit = text.split(" ", 1)
    digits = len(re.sub(r"e.*|[-.]", "", number).strip("0"))
    read = [parse_quantity(f"{float(f'{float(number):.{k}g}')!r} {unit}", dimension) / scale
            for k in range(1, digits + 1)]
    return _reads_back(read[-1], target) and not any(_reads_back(r, target) for r in read[:-1])


def test_changed_design_keeps_comments_order_and_units(tmp_path):
    """A comment with brackets inside [design] (where the regex round trip cut the table
    short), new values in the spec's own units at the shortest exact precision, every other
    line byte for byte; govopt evaluate of the result reproduces the design exactly."""
    text = (SPECS / "hamabe-a.toml").read_text(encoding="utf-8")
    old = 'coil_radius = "6 cm"'
    assert text.count(old) == 1
    text = text.replace(old, "# see [Hamabe, Fig. 1] for r\n" + old)
    path = tmp_path / "spec.toml"
    path.write_text(text, encoding="utf-8")
    spec = govopt.load_spec(path)
    d = dataclasses.replace(spec.design, wire_diameter=0.013, coil_radius=0.0595,
                            free_half_length=0.1234567891234, dashpot=3 * 0.0012345)
    res = govopt.evaluate(spec.with_design(d))
    out = design_toml(res)
    changed = {"wire_diameter": '"1.3 cm"', "coil_radius": '"5.95 cm"',
               "free_half_length": None, "dashpot_a1": None}
    lines, new_lines = text.splitlines(), out.splitlines()
    kept = [ln for ln in lines if not ln.startswith(tuple(changed))]
    assert [ln for ln in new_lines if not ln.startswith(tuple(changed))] == kept
    table = tomllib.loads(out)["design"]
    assert list(table) == ["pendulum_weight", "wire_diameter", "coil_radius", "active_turns",
                           "dashpot_a1", "free_half_length"]  # a new key at the end
    assert f'wire_diameter = {changed["wire_diameter"]}' in out  # the spec's cm
    assert f'coil_radius = {changed["coil_radius"]}  ' in out  # cm, its comment kept
    assert "# mean radius of the coil" in out and "# see [Hamabe, Fig. 1] for r" in out
    assert table["dashpot_a1"].endswith(" kgf*cm*s/rad")  # Hamabe's a1 = f/3, its own unit
    assert table["free_half_length"].endswith(" cm")  # the spec's first length unit
    for key, dimension, target in (("wire_diameter", "length", 0.013),
                                   ("coil_radius", "length", 0.0595),
                                   ("free_half_length", "length", 0.1234567891234),
                                   ("dashpot_a1", "damping", 0.0012345)):
        assert _shortest(table[key], dimension, target), table[key]
    written = tmp_path / "written.toml"
    written.write_text(out, encoding="utf-8")
    again = govopt.evaluate(govopt.load_spec(written)).design
    for field in dataclasses.fields(d):
        a, b = getattr(again, field.name), getattr(res.design, field.name)
        assert a == b if a is None or b is None else _reads_back(a, b), field.name


def test_design_o_writes_the_types_own_keys(tmp_path):
    """`govopt design -o` on a Porter (ball_weight, central_weight: not the shaft's keys that
    the regex writer put in every spec): the file evaluates to the designed governor."""
    run = invoke(["design", SPECS / "porter-design.toml", "-o", "p.toml", "--json"],
                 cwd=tmp_path)
    assert run.exit_code == 0, run.stderr
    designed = json.loads(run.stdout)
    table = tomllib.loads((tmp_path / "p.toml").read_text(encoding="utf-8"))["design"]
    assert sorted(table) == ["ball_weight", "central_weight"]
    for key, value in (("ball_weight", designed["ball_mass_kg"]),
                       ("central_weight", designed["central_mass_kg"])):
        assert table[key].endswith(" kgf")  # the unit of [bounds]
        assert _shortest(table[key], "force", value, G_STANDARD), table[key]
    evaluated = invoke(["evaluate", "p.toml", "--json"], cwd=tmp_path)
    assert evaluated.exit_code == 0, evaluated.stderr
    ev = json.loads(evaluated.stdout)
    for key in ("ball_mass_kg", "central_mass_kg"):
        assert _reads_back(ev[key], designed[key]), key
    for key in ("irregularity", "omega_inner_rad_s", "omega_outer_rad_s"):
        # from masses a few ulps apart: the speeds agree to rounding
        assert ev[key] == pytest.approx(designed[key], rel=1e-14), key


def test_design_o_writes_the_runs_analysis_options(tmp_path):
    """`govopt design -o ... --speed-change range`: the written spec says ``speed_change =
    "range"`` in its ``[analysis]``, so that evaluating it reproduces the report's effort and
    power (over the range, not for the default 1 %)."""
    run = invoke(["design", SPECS / "porter-design.toml", "-o", "p.toml", "--json",
                  "--speed-change", "range"], cwd=tmp_path)
    assert run.exit_code == 0, run.stderr
    designed = json.loads(run.stdout)["classic"]
    written = tomllib.loads((tmp_path / "p.toml").read_text(encoding="utf-8"))
    assert written["analysis"]["speed_change"] == "range"
    evaluated = invoke(["evaluate", "p.toml", "--json"], cwd=tmp_path)
    assert evaluated.exit_code == 0, evaluated.stderr
    again = json.loads(evaluated.stdout)["classic"]
    assert again["effort_over"] == designed["effort_over"] == "range"
    for key in ("effort_change", "effort_N", "power_J"):
        assert again[key] == pytest.approx(designed[key], rel=1e-12), key


# ------------------------------------------------------------------------------------------
# numbers an engineer can draw


def test_design_o_writes_the_design_as_drawn_and_that_design_passes(tmp_path):
    """`govopt design -o`: each designed length and dash-pot rounded to 4 significant digits
    (the catalogue's wire and turns as they are), the report and the JSON are the rounded
    design's, and `govopt evaluate` of the file reproduces them with every check passing."""
    run = invoke(["design", SPECS / "hamabe-design.toml", "-o", "d.toml", "--json"],
                 cwd=tmp_path)
    assert run.exit_code == 0, run.stderr
    designed = json.loads(run.stdout)
    table = tomllib.loads((tmp_path / "d.toml").read_text(encoding="utf-8"))["design"]
    for key in ("free_half_length", "coil_radius", "dashpot_f"):
        number = table[key].split()[0]
        assert len(re.sub(r"[-.]", "", number).strip("0")) <= 4, table[key]
    assert any("rounded to 4 significant digits" in n for n in designed["optimisation"]["notes"])
    evaluated = invoke(["evaluate", "d.toml", "--json"], cwd=tmp_path)
    assert evaluated.exit_code == 0, evaluated.stderr
    ev = json.loads(evaluated.stdout)
    assert all(c["passed"] for c in ev["checks"])
    for key in ("irregularity", "omega_inner_rad_s", "omega_outer_rad_s", "pendulum_mass_kg"):
        assert ev[key] == designed[key], key
    assert ev["spring"]["free_half_length_m"] == designed["spring"]["free_half_length_m"]


def test_a_rounding_that_breaks_a_check_is_not_written(monkeypatch):
    """Where rounding breaks a check the exact design passes, the exact design is written and
    the note names the check and what to do."""
    from govopt.optimize.design import design
    from govopt.report import files

    res = design(govopt.load_spec(SPECS / "hamabe-design.toml"))
    monkeypatch.setattr(files, "DRAWING_DIGITS", (1, None))  # 135.4 mm -> 100 mm: breaks
    text, drawn, note = files.drawn_design(res)
    assert text == design_toml(res) and drawn.design == res.design
    assert note.startswith("design written at full precision") and "evaluate" in note
    broken = note.split("fails ", 1)[1]
    assert re.search(r"\((over|short) by [\d.,]+ %\)", broken), note


def test_shell_completion_completes_commands_and_options(tmp_path):
    """typer's shell completion: the commands, and a command's options, which it
    builds on demand like any other use of that command."""
    env = {**os.environ, "_GOVOPT_COMPLETE": "complete_bash", "COMP_WORDS": "govopt ev",
           "COMP_CWORD": "1"}
    run = _govopt(cwd=tmp_path, env=env)
    assert run.returncode == 0 and run.stdout.split() == ["evaluate"], run.stderr
    env.update(COMP_WORDS="govopt evaluate --ge", COMP_CWORD="2")
    run = _govopt(cwd=tmp_path, env=env)
    assert run.returncode == 0 and run.stdout.split() == ["--geometry"], run.stderr
