"""The spring spec's keys declared once (govopt/spring_keys.py): `govopt spring` and `govopt
spring check` read them, their options take name, type and help from them, and the reference
(docs/reference/spring-spec.md), the `govopt init --type spring|spring-check` templates and the
spring branch of `govopt schema` are generated from them."""

import copy
import json
import tomllib
from pathlib import Path

import pytest
import typer
from clirun import invoke

from govopt import spring_command
from govopt.commands import spring as cli
from govopt.examples import SPECS
from govopt.spec_docs import option_help, spring_reference, template
from govopt.spring_keys import CHECK, DESIGN, FORMS, NAME, SANDGREN, TEMPLATES, defaults, form

REFERENCE = Path(__file__).resolve().parents[1] / "docs" / "reference" / "spring-spec.md"
SPRING_SPECS = sorted((SPECS / "springs").glob("*.toml"))


def test_spring_reference_is_generated_from_the_declarations():
    """docs/reference/spring-spec.md is what the declarations give today; regenerate it with
    `python -m govopt.spec_docs docs/reference/spring-spec.md`."""
    assert REFERENCE.read_text(encoding="utf-8") == spring_reference(), (
        "docs/reference/spring-spec.md is stale: run python -m govopt.spec_docs "
        "docs/reference/spring-spec.md")
    governor = REFERENCE.with_name("spec.md").read_text(encoding="utf-8")
    assert "[spring-spec.md](spring-spec.md)" in governor


def test_reference_lists_every_key_of_every_form_with_its_default():
    sections = {part.split("\n", 1)[0]: part
                for part in REFERENCE.read_text(encoding="utf-8").split("\n### ")[1:]}
    for name, (table, _) in FORMS.items():
        rows = sections[f"{name}: [spring]"].splitlines()
        for key in table.keys:
            row = next((r for r in rows if r.startswith(f"| `{key.name}` |")), None)
            assert row is not None, (name, key.name)
            assert (f"| {'required' if key.required else key.default_words()} |") in row, row
    assert "| `name` |" in sections["top level"]


@pytest.mark.parametrize("command, table", [("design", DESIGN), ("check", CHECK)])
def test_every_option_is_a_declared_key_with_its_help(command, table):
    """The command's options are the form's keys (``--max-outer-diameter`` for
    ``max_outer_diameter``) and ``--name``, in declared order, each with the declaration's help;
    nothing of a key is typed in the command."""
    group = typer.main.get_command(cli.app)
    params = [p for p in group.commands[command].params if p.name not in (
        "spec", "json_out", "output", "xlsx", "plots", "replace")]
    assert [p.name for p in params] == [*table.names, "name"]
    for param, key in zip(params, [*table.keys, NAME], strict=True):
        assert param.opts[0] == "--" + key.name.replace("_", "-")
        assert param.help == option_help(key, table).replace("[", r"\[")
    code = getattr(cli, command).__wrapped__.__code__  # the function as written: no key in it
    written = code.co_varnames[:code.co_argcount + code.co_kwonlyargcount]
    assert not set(written) & set(table.names) and "options" in code.co_varnames
    help_text = " ".join(invoke(["spring", command, "--help"]).stdout.replace("\u2502", " ")
                         .split())
    assert "a force, e.g. '500 N'" in help_text.replace("'400 N'", "'500 N'")


def test_options_read_by_their_declarations():
    """A whole-number choice is an integer option; a range closed at its top takes its top
    (1 coil step) and refuses beyond it, in the declaration's words."""
    r = invoke(["spring", "check", "--wire-diameter", "3 mm", "--tolerance-grade", "4"])
    assert r.exit_code == 2 and r.stderr.startswith(
        "error: --tolerance-grade: expected one of 1, 2, 3, got 4"), r.output
    base = ["spring", "--force", "500 N", "--stiffness", "20 N/mm", "--material",
            "EN10270-1 SH", "--json"]
    whole = json.loads(invoke([*base, "--coil-step", "1"]).stdout)
    assert whole["spring"]["active_coils"] == int(whole["spring"]["active_coils"])
    r = invoke([*base, "--coil-step", "1.5"])
    assert r.stderr.startswith("error: --coil-step: must lie in (0, 1] (0.25, 0.5 or 1 "
                               "usual), got 1.5"), r.output


@pytest.mark.parametrize("command, body, message", [
    ("spring", '[spring]\nforce = "500 N"\nforse = "1 N"\n',
     "spring.forse: unknown key (did you mean 'force'? 39 keys allowed here, listed in "
     "docs/reference/spring-spec.md under design: [spring])"),
    ("spring", '[spring]\nforce = "500 N"\nmax_preload_deflection = "1 in"\n',
     "spring.max_preload_deflection: not a key of a spring to design (govopt spring); it is "
     "one of a problem of the literature with its data (govopt spring, with problem = "
     "\"sandgren-1990\")"),
    ("spring", '[spring]\nproblem = "sandgren-1990"\nstifness = "1 N/mm"\n',
     "spring.stifness: unknown key (10 keys allowed here, listed in "
     "docs/reference/spring-spec.md under sandgren-1990: [spring])"),
    ("spring check", '[spring]\nwire_diameter = "3 mm"\nstiffness = "1 N/mm"\n',
     "spring.stiffness: not a key of a spring you have (govopt spring check); it is one of a "
     "spring to design (govopt spring)"),
    ("spring check", '[spring]\nwire_diameter = "3 mm"\nfree_lenght = "1 mm"\n',
     "spring.free_lenght: unknown key (did you mean 'free_length'? 32 keys allowed here, "
     "listed in docs/reference/spring-spec.md under check: [spring])"),
    ("spring", 'nme = "x"\n[spring]\nforce = "500 N"\n',
     "nme: unknown key (did you mean 'name'? allowed here: name, description, spring)"),
    ("spring", '[spring]\nforce = "500 N"\nstiffness = "10 N/mm"\nwire_sizes = "2.5 mm, x"\n',
     "spring.wire_sizes[1]: cannot parse 'x' as a quantity"),
])
def test_a_key_unknown_or_of_another_form_is_named_so(tmp_path, command, body, message):
    """A misspelt key gets its did-you-mean and the reference's section that lists the keys
    (which exists); a key of another form of [spring] is named as that form's."""
    spec = tmp_path / "s.toml"
    spec.write_text(body)
    r = invoke([*command.split(), str(spec)])
    assert r.exit_code == 2 and r.stderr.startswith(f"error: {spec}: {message}"), r.output
    if "listed in" in message:
        section = message.split(" under ")[1].rstrip(")")
        assert f"\n### {section}\n" in REFERENCE.read_text(encoding="utf-8")


def test_every_entry_carries_its_meaning():
    """Every input of a spring spec and every option is recorded with its declaration's
    meaning (the workbook's input labels read it)."""
    for path in SPRING_SPECS:
        *_, entries = spring_command.merged(path, {"life": 1e6} if "500n" in path.stem else {})
        assert entries and all(e.meaning for e in entries), path.name



@pytest.mark.parametrize("command, spec, options", [
    ("design", "spring-500n", ["--max-outer-diameter", "40 mm", "--wire-sizes",
                               "4 mm, 4.5 mm, 5 mm"]),
    ("check", None, ["--wire-diameter", "0.125 in", "--mean-diameter", "0.75 in",
                     "--active-coils", "8", "--free-length", "2.5 in", "--material",
                     "EN10270-1 SH", "--force", "40 lbf"]),
])
def test_workbook_spec_sheet_labels_each_input_with_its_declaration(tmp_path, command, spec,
                                                                    options):
    """The spring workbook's Spec sheet lists every input read, from the file and the options,
    with its declared meaning, as written and in the units the input is written in, and the
    file it came from (or none: the options alone)."""
    import openpyxl

    from govopt.spring_keys import FORMS

    table = FORMS[command][0]
    path = None if spec is None else SPECS / "springs" / f"{spec}.toml"
    book = tmp_path / "s.xlsx"
    args = ["spring", command, *([str(path)] if path else []), *options, "--xlsx", str(book)]
    r = invoke(args)
    assert r.exit_code in (0, 1), r.output
    rows = [r for r in openpyxl.load_workbook(book)["Spec"].iter_rows(min_row=3,
                                                                       values_only=True)]
    inputs = {key: (meaning, written) for key, meaning, written, *_ in rows if written}
    data = {} if path is None else tomllib.loads(path.read_text())
    given = {a[2:].replace("-", "_"): v
             for a, v in zip(options[::2], options[1::2], strict=True)}
    for name, written in {**data.get("spring", {}), **given}.items():
        key = table.key(name)
        label = ("--" + name.replace("_", "-") if name in given else f"spring.{name}")
        if key.shape == "list":
            label, written = f"{label}[0]", written.split(",")[0]
        meaning, shown = inputs[label]
        assert meaning == key.meaning, label
        if key.kind == "number":  # an option's number is the number click read: 8 is 8.0
            assert float(shown) == float(written), label
        else:
            assert shown == str(written), label
    assert len(inputs) == len(data) - ("spring" in data) + sum(
        len(str(v).split(",")) if table.key(k).shape == "list" else 1
        for k, v in {**data.get("spring", {}), **given}.items())
    units = {r[4] for r in rows if r[0] and r[0].endswith(("diameter", "length", "]"))}
    assert units == ({"in"} if spec is None else {"mm"})
    footer = next(r for r in rows if r[0] == "spec file")
    assert footer[1] == (str(path) if path else "none (the command's options alone)")


# -- templates ----------------------------------------------------------------------------------


@pytest.mark.parametrize("name", list(TEMPLATES))
def test_spring_template_is_complete_and_runs_as_written(tmp_path, name):
    """`govopt init --type spring|spring-check` writes every key of its [spring] (its values
    set, the rest commented with their meaning and a value to start from), and its command
    runs it as written: every check passes."""
    form_name, start, _ = TEMPLATES[name]
    table, command = FORMS[form_name]
    run = invoke(["init", "--type", name], cwd=tmp_path)
    assert run.exit_code == 0, run.output
    assert run.stdout.strip().endswith(f"then: {command} {name}.toml")
    path = tmp_path / f"{name}.toml"
    text = path.read_text(encoding="utf-8")
    assert text == template(name)
    for key in table.keys:
        assert f"\n{key.name} = " in text or f"\n# {key.name} = " in text, key.name
    data = tomllib.loads(text)
    values = (tomllib.loads((SPECS / "springs" / f"{start}.toml").read_text())["spring"]
              if isinstance(start, str) else start)
    assert data["spring"] == values and form(data["spring"]) == form_name
    run = invoke([*command.split()[1:], str(path), "--json"], cwd=tmp_path)
    assert run.exit_code == 0, run.output
    out = json.loads(run.stdout)
    assert out["name"] == name and all(c["passed"] for c in out["checks"])


@pytest.mark.parametrize("name", list(TEMPLATES))
def test_a_key_commented_out_takes_its_default(tmp_path, name):
    """Each key the template leaves commented with a default that is a value, written out with
    that value, gives the same spring, figure for figure."""
    form_name, _, _ = TEMPLATES[name]
    table, command = FORMS[form_name]
    path = tmp_path / "t.toml"
    path.write_text(template(name))
    left = json.loads(invoke([*command.split()[1:], str(path), "--json"]).stdout)
    data = tomllib.loads(template(name))
    given = defaults(table)
    assert given and not set(given) & set(data["spring"])  # they are commented
    lines = [f"{k} = {json.dumps(v)}" for k, v in given.items()]
    path.write_text(template(name).replace("[spring]\n", "[spring]\n" + "\n".join(lines) + "\n"))
    written = json.loads(invoke([*command.split()[1:], str(path), "--json"]).stdout)
    for out in (left, written):  # the one figure that is not the spring's: the solver's time
        (out["optimisation"] or {}).pop("solve_time_s", None)
    assert written == left


# -- the schema ---------------------------------------------------------------------------------


def _errors(validator, data) -> list[str]:
    return [e.message for e in validator.iter_errors(data)]


def test_schema_validates_every_bundled_spring_spec_and_template(validator):
    for path in SPRING_SPECS:
        assert not _errors(validator, tomllib.loads(path.read_text())), path.name
    for name in TEMPLATES:
        assert not _errors(validator, tomllib.loads(template(name))), name


@pytest.mark.parametrize("design", [
    ["--force", "500 N", "--stiffness", "10 N/mm", "--allowable-stress", "600 MPa",
     "--shear-modulus", "81.5 GPa"],
    ["--force", "300 N", "--min-force", "100 N", "--stiffness", "5 N/mm", "--material",
     "EN10270-1 DH", "--kind", "extension", "--fatigue-min-force", "100 N",
     "--fatigue-max-force", "300 N"],
])
def test_schema_validates_a_spring_written_with_o(validator, tmp_path, design):
    """`govopt spring -o SPEC` writes a spec of a spring to check: the schema takes it as one."""
    spec = tmp_path / "d.toml"
    assert invoke(["spring", *design, "-o", str(spec)]).exit_code in (0, 1)
    data = tomllib.loads(spec.read_text())
    assert form(data["spring"]) == "check" and not _errors(validator, data)


@pytest.mark.parametrize("spec, change, command", [
    ("spring-500n", lambda s: s.__setitem__("forse", s.pop("force")), "spring"),  # a typo
    ("spring-500n", lambda s: s.__setitem__("force", 500), "spring"),  # a number, no unit
    ("spring-500n", lambda s: s.__setitem__("force", "500"), "spring"),  # digits, no unit
    ("spring-500n", lambda s: s.__setitem__("kind", "torsion"), "spring"),
    ("spring-500n", lambda s: s.__setitem__("coil_step", 1.5), "spring"),  # (0, 1]
    ("spring-500n", lambda s: s.__setitem__("max_preload_deflection", "1 in"), "spring"),
    ("sandgren-1990", lambda s: s.__setitem__("stiffness", "1 N/mm"), "spring"),
    ("sandgren-1990", lambda s: s.__setitem__("problem", "belegundu"), "spring"),
    ("spring-check", lambda s: s.__setitem__("stiffness", "1 N/mm"), "spring check"),
    ("spring-check", lambda s: s.__setitem__("tolerance_grade", 4), "spring check"),
    ("spring-check", lambda s: s.__setitem__("active_coils", "9.5"), "spring check"),
])
def test_schema_refuses_what_the_spring_commands_refuse(validator, tmp_path, spec, change,
                                                        command):
    """A misspelt key, a quantity without a unit, a choice or range outside the declaration, a
    key of another form of [spring]: the schema refuses it, and so does the command."""
    source = template(spec) if spec in TEMPLATES else (SPECS / "springs" / f"{spec}.toml"
                                                        ).read_text()
    data = tomllib.loads(source)
    bad = copy.deepcopy(data)
    change(bad["spring"])
    assert _errors(validator, bad)
    path = tmp_path / "bad.toml"
    lines = [f"{k} = {json.dumps(v)}" for k, v in bad["spring"].items()]
    path.write_text("[spring]\n" + "\n".join(lines) + "\n")
    r = invoke([*command.split(), str(path)])
    assert r.exit_code == 2 and r.stderr.startswith(f"error: {path}: spring."), r.output


def test_schema_tells_a_governor_spec_from_a_spring_spec(validator):
    """A governor spec may have a [spring] (its spring's form): it is a governor spec, read by
    its type's tables; a spring spec with a governor's table is refused."""
    hartnell = tomllib.loads((SPECS / "hartnell-design.toml").read_text())
    hartnell["spring"] = {"ends": "closed", "seating": "hinged-hinged"}
    assert not _errors(validator, hartnell)
    hartnell["spring"]["force"] = "500 N"  # a spring spec's key in a governor's [spring]
    assert _errors(validator, hartnell)
    spring = tomllib.loads((SPECS / "springs" / "spring-500n.toml").read_text())
    assert _errors(validator, {**spring, "speed": {"mean": "100 rpm"}})
    assert _errors(validator, {"name": "nothing"})  # neither [governor] nor [spring]


def test_sandgren_keys_are_the_problems_data():
    """Every data key of Sandgren's problem but ``problem`` maps to one of its symbols."""
    from govopt.optimize import spring_literature as sl

    assert [k.name for k in SANDGREN.keys[1:]] == list(sl.SANDGREN_DATA)
