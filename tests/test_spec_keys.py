"""Every spec key declared once (govopt.keys): the parser reads the declarations, and the
reference, the `govopt init --type` templates and the JSON Schema are generated from them."""

import copy
import json
import tomllib
from pathlib import Path

import pytest
from clirun import invoke

import govopt
from govopt.examples import SPECS
from govopt.governors import REGISTRY, governor_class
from govopt.keys import Key
from govopt.spec import parse_spec
from govopt.spec_keys import spec_tables

REFERENCE = Path(__file__).resolve().parents[1] / "docs" / "reference" / "spec.md"
GOVERNOR_SPECS = sorted([*SPECS.glob("*.toml"), *SPECS.glob("studies/*.toml")])


def test_reference_is_generated_from_the_declarations():
    """docs/reference/spec.md is what the declarations give today; regenerate it with
    `python -m govopt.spec_docs docs/reference/spec.md`."""
    from govopt.spec_docs import reference

    assert REFERENCE.read_text(encoding="utf-8") == reference(), (
        "docs/reference/spec.md is stale: run python -m govopt.spec_docs "
        "docs/reference/spec.md")


def _sections(text: str) -> dict[str, str]:
    """The reference's ``### `` sections by heading."""
    return {part.split("\n", 1)[0]: part for part in text.split("\n### ")[1:]}


def test_reference_lists_every_key_of_every_type():
    """Each type's own sections, or the shared ones, name every table and every key a spec of
    the type may hold, with its default (the default [bounds] and [requirements] among them)."""
    sections = _sections(REFERENCE.read_text(encoding="utf-8"))
    for gtype in REGISTRY:
        for name, table in spec_tables(gtype).items():
            title = f"[[{name}]]" if table.array else f"[{name}]" if name else "top level"
            where = sections.get(f"{gtype}: {title}") or sections[title]
            for key in () if table.open else table.keys:
                row = next((ln for ln in where.splitlines()
                            if ln.startswith(f"| `{key.names[0]}`")), None)
                assert row is not None, (gtype, name, key.name)
                assert key.required or f"| {key.default_words()} |" in row, row
    bounds = sections["hartnell: [bounds]"]
    assert "[0.001, 0.025] m" in bounds and "[2, 20] kg" in bounds  # wire and ball defaults
    assert "| `objective` |" in sections["hartnell: [requirements]"]


def test_every_entry_carries_its_meaning():
    """Every input a bundled spec gives is recorded with its declaration's meaning (the
    workbook's Spec sheet labels it)."""
    for path in GOVERNOR_SPECS:
        spec = govopt.load_spec(path)
        blank = [e.key for e in spec.entries if not e.meaning]
        assert not blank, (path.name, blank)


def test_an_undeclared_key_is_the_parsers_mistake():
    """A table read with its declaration takes only declared keys (the parser cannot read a
    key that the reference, the template and the schema do not know)."""
    from govopt.keys import Table
    from govopt.reader import Reader

    rd = Reader("f", {"a": "1 m"}, "t", [], Table("t", "a table", (Key("b", "length", "b"),)))
    with pytest.raises(AssertionError, match="not declared"):
        rd.quantity("a", "length")


def test_unknown_key_lists_the_allowed_keys_in_full_or_points_to_the_reference(tmp_path):
    """A short table's keys are listed in full; a long one's are pointed to in the reference,
    never cut short."""
    short = (SPECS / "spring_gravity-design.toml").read_text()
    path = tmp_path / "s.toml"
    path.write_text(short.replace('ball_arm = ', 'sleeve_fricton = "1 kgf"\nball_arm = '))
    run = invoke(["design", str(path)])
    line = run.stderr.strip()
    assert run.exit_code == 2 and "did you mean 'sleeve_friction'?" in line
    assert line.endswith(", ".join(spec_tables("spring_gravity")["governor"].names) + ")")
    base = (SPECS / "hartnell-design.toml").read_text()
    path.write_text(base.replace('objective = "moving_mass"', 'objectve = "moving_mass"'))
    line = invoke(["design", str(path)]).stderr.strip()
    assert line.endswith("did you mean 'objective'? 22 keys allowed here, listed in "
                         "docs/reference/spec.md under hartnell: [requirements])"), line
    path.write_text(base + '\n[analysis]\npoints = 31\nponts = 3\n')
    line = invoke(["design", str(path)]).stderr.strip()
    for key in spec_tables("hartnell")["analysis"].names:
        assert key in line
    path.write_text(base.replace("[speed]", "[speed]\nmiddle = \"150 rpm\""))
    line = invoke(["design", str(path)]).stderr.strip()
    assert "allowed here: inner, outer, mean, irregularity)" in line


@pytest.mark.parametrize("gtype", list(REGISTRY))
def test_template_is_complete_and_designs_as_written(tmp_path, gtype):
    """`govopt init --type TYPE` writes every key of the type (its example's values set, the
    rest commented with their meaning), and `govopt design` runs it as written."""
    from govopt.spec_docs import template

    run = invoke(["init", "--type", gtype], cwd=tmp_path)
    assert run.exit_code == 0, run.output
    path = tmp_path / f"{gtype}.toml"
    text = path.read_text(encoding="utf-8")
    assert text == template(gtype)
    for name, table in spec_tables(gtype).items():
        for key in () if table.open else table.keys:
            if key.kind != "table":
                assert any(f"{n} = " in text for n in key.names), (name, key.name)
    data = tomllib.loads(text)
    example = tomllib.loads((SPECS / f"{governor_class(gtype).example}.toml").read_text())
    for k in ("name", "description"):
        data.pop(k), example.pop(k)
    assert data == example  # the values: the bundled design example's, nothing else set
    run = invoke(["design", str(path), "--json"], cwd=tmp_path)
    assert run.exit_code == 0, run.output
    assert json.loads(run.stdout)["optimisation"]["status"] == "optimal"


def test_init_needs_one_of_name_or_type(tmp_path):
    for args in (["init"], ["init", "hamabe-a", "--type", "watt"]):
        run = invoke(args, cwd=tmp_path)
        assert run.exit_code == 2 and run.stderr.startswith("error: init: give"), run.output
    run = invoke(["init", "--type", "steam"], cwd=tmp_path)
    assert run.exit_code == 2 and "--type: expected one of shaft" in run.stderr


def test_schema_validates_every_bundled_governor_spec(validator):
    for path in GOVERNOR_SPECS:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        errors = [e.message for e in validator.iter_errors(data)]
        assert not errors, (path.name, errors[:3])


@pytest.mark.parametrize("change, where", [
    (lambda d: d["governor"].__setitem__("ball_amr", d["governor"].pop("ball_arm")),
     "governor"),  # a misspelt key
    (lambda d: d["governor"].__setitem__("ball_arm", 15), "governor"),  # a bare number
    (lambda d: d["governor"].__setitem__("ball_arm", "15"), "governor"),  # digits, no unit
    (lambda d: d["bounds"].__setitem__("ball_mass", ["1 kg", "2 kg"]), "bounds"),  # both
    (lambda d: d["requirements"].__setitem__("objective", "mass"), "requirements"),
    (lambda d: d["requirements"].__setitem__("k2_margin", 0.7), "requirements"),  # > 0.5
    (lambda d: d.__setitem__("extras", {"x": 1}), None),  # an unknown table
    (lambda d: d["governor"].__setitem__("arm", "30 cm"), "governor"),  # a Porter's key
])
def test_schema_rejects_what_the_parser_rejects(validator, change, where, tmp_path):
    """A misspelt key, a quantity without a unit, a choice or range outside the declaration:
    the schema refuses them, and so does the parser."""
    data = tomllib.loads((SPECS / "hartnell-design.toml").read_text())
    bad = copy.deepcopy(data)
    change(bad)
    errors = list(validator.iter_errors(bad))
    assert errors
    assert where is None or any(where in e.absolute_path or where in list(e.path)
                                or e.absolute_path and e.absolute_path[0] == where
                                for e in errors), [e.message for e in errors]
    with pytest.raises(govopt.SpecError):
        parse_spec(bad, "bad.toml")


def _deletions(data: dict):
    """Every table of ``data`` and every key of each table deleted, one at a time."""
    for table, value in data.items():
        if isinstance(value, dict | list):
            yield f"[{table}]", {k: v for k, v in data.items() if k != table}
        if isinstance(value, dict):
            for key in value:
                bad = copy.deepcopy(data)
                del bad[table][key]
                yield f"{table}.{key}", bad


@pytest.mark.parametrize("gtype", list(REGISTRY))
def test_schema_and_govopt_agree_on_every_deletion_from_a_template(validator, gtype):
    """The schema says what the parser says (it is generated from the same declarations):
    each table and each key of a type's `govopt init` template deleted, the schema refuses
    exactly what govopt refuses: a required key, one of two alternatives (``oneOf``: the
    speed band or the mean speed; a bell crank's outer radius or sleeve lift; a leaf's
    chords, bows or travels), a table required without another (``[speed]`` without
    ``[design]``), a table read with another (``[[load_change]]`` with ``[engine]``), the
    material's values its spring needs. Only a limit of govopt's work, which depends on the
    values (a catalogue grown past its limit once a bound is gone), is the parser's alone."""
    from govopt.spec_docs import template

    data = tomllib.loads(template(gtype))
    assert not list(validator.iter_errors(data))
    disagree = []
    for label, bad in _deletions(data):
        try:
            parse_spec(copy.deepcopy(bad), "bad.toml")
            refused = ""
        except govopt.GovoptError as exc:
            refused = str(exc)
        if bool(refused) != bool(list(validator.iter_errors(bad))) and \
                "govopt's limit" not in refused:
            disagree.append(f"{label}: govopt {'refuses' if refused else 'accepts'} "
                            f"({refused[:120]})")
    assert not disagree, "\n".join(disagree)


#: a unit of each dimension, to write where a key wants another
UNIT_OF = {"length": "cm", "mass": "kg", "force": "kgf", "angle": "deg", "stress": "MPa",
           "angular_velocity": "rpm", "time": "s"}


@pytest.mark.parametrize("gtype", list(REGISTRY))
def test_schema_and_govopt_agree_on_every_wrong_dimension_in_a_template(validator, gtype):
    """Every quantity of a type's template written in a unit of each other dimension (a
    length in kg, a speed in cm, an inertia in kg): the schema refuses it by its dimension's
    pattern (a number and one unit word of the dimension, the words govopt reads:
    govopt/data/unit_words.json), as govopt does."""
    from govopt.spec_docs import template
    from govopt.spec_keys import spec_tables

    data = tomllib.loads(template(gtype))
    tables = spec_tables(gtype)
    disagree, tried = [], 0
    for table, values in data.items():
        if not isinstance(values, dict) or table not in tables:
            continue
        for name, value in values.items():
            if not isinstance(value, str) or " " not in value:
                continue
            try:
                key = tables[table].key(name)
            except KeyError:
                continue
            dimension = ("force" if name.endswith("_weight") else "mass") if \
                key.kind == "weight" else key.dimension
            number = value.split(" ", 1)[0]
            for other, unit in UNIT_OF.items():
                if other == dimension or (dimension == "torque_per_length" and other == "force"):
                    continue  # N*m/m is a force's unit too
                bad = copy.deepcopy(data)
                bad[table][name] = f"{number} {unit}"
                with pytest.raises(govopt.GovoptError):
                    parse_spec(copy.deepcopy(bad), "bad.toml")
                tried += 1
                if not list(validator.iter_errors(bad)):
                    disagree.append(f"{table}.{name} = {bad[table][name]!r}")
    assert tried >= 20 and not disagree, disagree


def test_the_unit_words_are_govopts():
    """govopt/data/unit_words.json (``python -m govopt.spec_schema --words``, slow) holds, for
    each dimension, words govopt reads as it: each listed word parses, an angular velocity
    names its angle (rpm, not Hz), and the patterns take the bundled specs' units."""
    import re as regex

    from govopt.spec_schema import dimension_pattern, saved_words
    from govopt.units import parse_quantity

    words = saved_words()
    for dimension, listed in words.items():
        for word in listed:
            parse_quantity(f"1 {word}", dimension)
    assert "rpm" in words["angular_velocity"] and "Hz" not in words["angular_velocity"]
    assert "kgf" in words["force"] and "kgf" not in words["mass"]
    for dimension, good, bad in (("length", "18 cm", "18 kg"), ("stress", "250 MPa", "250 N"),
                                 ("angular_velocity", "240 rpm", "4 Hz"),
                                 ("length", "0.375 inches", "3 rpm"),
                                 ("inertia", "43 kgf*m*s^2", "43 kg")):
        pattern = dimension_pattern(dimension)
        assert regex.search(pattern, good) and not regex.search(pattern, bad), (good, bad)


def test_schema_command_writes_the_schema(tmp_path):
    from govopt.spec_schema import text

    run = invoke(["schema"])
    assert run.exit_code == 0 and run.stdout == text()
    run = invoke(["schema", "-o", str(tmp_path / "s.json")])
    assert run.exit_code == 0 and (tmp_path / "s.json").read_text(encoding="utf-8") == text()


def _hartnell(**governor) -> dict:
    data = tomllib.loads((SPECS / "hartnell-design.toml").read_text())
    data["governor"].update(governor)
    return {k: v for k, v in data["governor"].items() if v is not None}


def test_sleeve_lift_in_place_of_the_outer_radius():
    """The Hartnell of Example 5: 3 cm of sleeve lift with 15 cm and 9 cm arms is an outer ball
    radius of 10 + (15/9) 3 = 15 cm (the book's h = (b/a)(r_1 - r_2), exact for a 90 deg
    crank), the same governor as radius_outer = 15 cm; with a 110 deg crank (no closed form)
    the sleeve rises by the lift asked at the radius found."""
    spec = tomllib.loads((SPECS / "hartnell-design.toml").read_text())
    by_radius = parse_spec(spec).governor
    lifted = copy.deepcopy(spec)
    del lifted["governor"]["radius_outer"]
    lifted["governor"]["sleeve_lift"] = "3 cm"
    gov = parse_spec(lifted).governor
    assert gov.x_outer == pytest.approx(by_radius.x_outer, rel=1e-15)
    assert gov.x_normal == by_radius.x_normal and gov.crank == by_radius.crank
    assert any(e.key == "governor.sleeve_lift" and e.meaning for e in parse_spec(lifted).entries)
    for crank in ("110 deg", "80 deg"):
        lifted["governor"]["crank_angle"] = crank
        gov = parse_spec(lifted).governor
        assert float(gov.sleeve_lift(gov.x_outer)) == pytest.approx(0.03, rel=1e-12)


@pytest.mark.parametrize("gtype, changes, message", [
    ("hartnell", {"sleeve_lift": "3 cm"}, "give either radius_outer or sleeve_lift"),
    ("hartnell", {"radius_outer": None, "sleeve_lift": "40 cm"}, "cannot lift the sleeve"),
    ("hartnell", {"radius_outer": None}, "radius_outer: missing"),
])
def test_sleeve_lift_errors(gtype, changes, message):
    data = tomllib.loads((SPECS / "hartnell-design.toml").read_text())
    data["governor"] = _hartnell(**changes)
    with pytest.raises(govopt.SpecError, match=message):
        parse_spec(data, "h.toml")


def test_sleeve_lift_for_the_spring_and_gravity_governor():
    """Fulcrum on the sleeve, at radius_inner by default: the lift gives the radius too."""
    data = tomllib.loads((SPECS / "spring_gravity-design.toml").read_text())
    gov = parse_spec(data).governor
    lift = float(gov.sleeve_lift(gov.x_outer))
    del data["governor"]["radius_outer"]
    data["governor"]["sleeve_lift"] = f"{lift} m"
    assert parse_spec(data).governor.x_outer == pytest.approx(gov.x_outer, rel=1e-12)


def test_spring_length_of_the_ball_springs_defaults_to_the_balls_distance():
    """Balls joined directly by springs: their length at radius_inner defaults to 2
    radius_inner (the balls' centres' distance); the lever's spring has no default."""
    data = tomllib.loads((SPECS / "spring_loaded-design.toml").read_text())
    del data["governor"]["spring_length"]
    gov = parse_spec(data).governor
    assert gov.spring_length == 2.0 * gov.x_inner
    lever = tomllib.loads((SPECS / "textbook-ex7-spring_loaded.toml").read_text())
    del lever["governor"]["spring_length"]
    with pytest.raises(govopt.SpecError, match="spring_length: missing"):
        parse_spec(lever, "ex7.toml")


# -- search bounds ----------------------------------------------------------------------------


def test_a_written_design_is_evaluated_without_its_search_bounds(tmp_path):
    """`govopt design hartnell-design.toml -o d.toml && govopt evaluate d.toml`: the design
    file keeps the spec's [bounds] (they are the search's), and neither the design nor its
    evaluation checks the made part against them."""
    out = tmp_path / "d.toml"
    run = invoke(["design", str(SPECS / "hartnell-design.toml"), "-o", str(out), "--json"])
    assert run.exit_code == 0, run.output
    designed = json.loads(run.stdout)
    assert "bounds" in tomllib.loads(out.read_text())
    run = invoke(["evaluate", str(out), "--json"])
    assert run.exit_code == 0, run.output
    evaluated = json.loads(run.stdout)
    for res in (designed, evaluated):
        names = [c["name"] for c in res["checks"]]
        bounds = {f"{x} {s}" for x in ("ball mass", "wire diameter", "coil radius",
                                       "active turns") for s in (">= min", "<= max")}
        assert not bounds & set(names), names
        assert all(c["group"] != "bounds" for c in res["checks"])
    text = invoke(["evaluate", str(out)]).stdout
    assert ">= min" not in text.replace("spring index >= min", "")


def test_design_reports_the_bounds_it_searched_and_a_value_at_one():
    """The design's record lists every bound searched, the defaults marked, and says where the
    design takes the least value the search could give a variable (the Porter's balls at 2 kgf,
    the lower end of bounds.ball_weight)."""
    from govopt.optimize.design import design

    data = tomllib.loads((SPECS / "porter-design.toml").read_text())
    data["bounds"]["ball_weight"] = ["4 kgf", "10 kgf"]
    res = design(parse_spec(data, "porter.toml"))
    searched = {b["name"]: b for b in res.optimisation["search_bounds"]}
    assert searched["ball_mass"]["at"] == "lower" and searched["ball_mass"]["value_kg"] == 4.0
    assert searched["ball_mass"]["key"] == "ball_weight" and searched["ball_mass"]["given"]
    notes = res.optimisation["notes"]
    assert searched["ball_mass"]["held"] == "bound"
    assert "at the lower search bound of ball_mass (4 kgf; [bounds] ball_weight lower end " \
           "4 kgf): widen [bounds] ball_weight to search beyond it" in notes
    assert any(n.startswith("search bounds ([bounds]): ball_mass 4 kg .. 10 kg, central_mass "
                            "10 kg .. 100 kg") for n in notes)
    hartnell = design(govopt.load_spec(SPECS / "hartnell-design.toml"))
    line = next(n for n in hartnell.optimisation["notes"] if n.startswith("search bounds"))
    assert "central_mass 0 kg (default, fixed)" in line  # a default, stated


def test_equal_bounds_fix_a_value():
    """`ball_weight = ["2.5 kgf", "2.5 kgf"]` fixes the balls; a wire fixed off the catalogue
    is that wire."""
    from govopt.optimize.design import design

    data = tomllib.loads((SPECS / "hartnell-design.toml").read_text())
    data["bounds"].update(ball_weight=["2.5 kgf", "2.5 kgf"], wire_diameter=["5.7 mm", "5.7 mm"])
    # the envelope reading: this wire and these balls cannot span 75 % of the band (the range
    # of speed's default), and what is tested here is the bounds, not the band
    data["requirements"]["min_range"] = "envelope"
    res = design(parse_spec(data, "h.toml"))
    assert res.design.flying_mass == pytest.approx(2.5)
    assert res.design.wire_diameter == pytest.approx(0.0057)
    fixed = {b["name"] for b in res.optimisation["search_bounds"] if b["at"] == "fixed"}
    assert fixed >= {"ball_mass", "wire_diameter"}
    data["bounds"]["ball_weight"] = ["3 kgf", "2 kgf"]
    with pytest.raises(govopt.SpecError, match="expected low <= high"):
        parse_spec(data, "h.toml")


def test_porter_without_bounds_is_told_its_central_load_bound(tmp_path):
    """A Porter spec without [bounds] searches a central load of 0 .. 0 kg (the default): no
    ball floats it at 190-224 rpm, and the diagnosis names that bound first, with the central
    load that makes the spec feasible; that bound does, and a little less does not."""
    from govopt.errors import InfeasibleError
    from govopt.optimize.design import design

    data = tomllib.loads((SPECS / "porter-design.toml").read_text())
    del data["bounds"]
    with pytest.raises(InfeasibleError) as info:
        design(parse_spec(data, "porter.toml"))
    message = str(info.value)
    moves = message.split("it becomes feasible if one of these moves: ")[1].split("; ")
    assert moves[0].startswith("bounds.central_weight 0 .. 0 kgf (the default: no central "
                               "load) -> 0 .. "), message
    assert moves[0].endswith(" kgf"), message  # the key is a weight: in kgf, not kg
    upper = float(moves[0].split(" .. ")[-1].removesuffix(" kgf"))
    data["bounds"] = {"central_weight": ["0 kgf", f"{upper} kgf"]}
    assert design(parse_spec(data, "porter.toml")).design.central_mass <= upper
    data["bounds"] = {"central_mass": ["0 kg", f"{upper - 0.5} kg"]}
    with pytest.raises(InfeasibleError):
        design(parse_spec(data, "porter.toml"))


def test_the_shaft_governors_analysis_settings_are_its_own():
    """The valve gear's and the linkage series' settings belong to the shaft governor: a
    Hartnell's template and reference do not offer them, its spec refuses them by name, and
    ``--geometry`` on it says the type has no such setting (exit 2)."""
    from govopt.spec_docs import template
    from govopt.spec_keys import analysis_table, spec_tables

    shaft_only = {"geometry", "reaction_speed", "reaction_slope", "valve_table", "harmonics"}
    assert shaft_only <= set(spec_tables("shaft")["analysis"].names)
    for name in ("hartnell", "porter", "traction_leaf"):
        assert not shaft_only & set(spec_tables(name)["analysis"].names)
        assert "valve" not in template(name).split("[analysis]")[-1].split("[requirements]")[0]
    from govopt.governors import governor_class

    assert "points" in analysis_table(governor_class("watt")).names
    run = invoke(["evaluate", "specs/textbook-ex4-hartnell.toml", "--geometry", "series"])
    assert run.exit_code == 2
    assert "the hartnell governor has no [analysis] geometry" in run.output


def test_a_missing_spec_named_like_a_bundled_example_says_how_to_get_it(tmp_path):
    """A spec file that does not exist but bears a bundled example's name (as a README writes
    ``govopt design hartnell-design.toml``): the one-line error says how to copy it here."""
    run = invoke(["evaluate", "hartnell-design.toml"], cwd=tmp_path)
    assert run.exit_code == 2
    assert "`govopt init hartnell-design` copies it here" in run.output
    other = invoke(["evaluate", "no-such-spec.toml"], cwd=tmp_path)
    assert other.exit_code == 2 and "bundled example" not in other.output
