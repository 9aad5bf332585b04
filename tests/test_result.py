"""The typed result: checks and figures carry value, unit, group and source as fields;
``Result.summary()``, ``to_frame()``, ``plot()`` and a notebook's ``_repr_html_`` read them; the
checks live on the ground floor (``govopt.verdict``) and nothing imports the result back."""

from __future__ import annotations

import ast
import html
import math
from pathlib import Path

import numpy as np
import pytest

import govopt
import govopt.examples
from govopt.report.text import format_summary
from govopt.verdict import SHOWN, Check, Figure, json_key, shown

SPECS = Path("specs")
ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def hamabe():
    return govopt.evaluate(govopt.load_spec(SPECS / "hamabe-a.toml"))


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """Hamabe case a with a wire grade: the spring engineering tables apply."""
    text = (SPECS / "hamabe-a.toml").read_text().replace(
        "[material]\n", '[material]\ngrade = "EN10270-1 DH"\n')
    path = tmp_path_factory.mktemp("graded") / "graded.toml"
    path.write_text(text)
    return govopt.evaluate(govopt.load_spec(path))


def test_summary_is_the_answer_first(hamabe):
    text = hamabe.summary()
    assert text == format_summary(hamabe, colour=False)
    lines = text.splitlines()
    assert lines[3] == "Verdict"
    failed = [c.name for c in hamabe.checks if not c.passed]
    assert failed and lines[4].startswith(f"FAIL: {len(failed)} of {len(hamabe.checks)}")
    assert "\x1b" not in text and len(lines) <= 70
    # the design in engineering units, read from the figures' fields
    design = {ln.split("   ")[0].strip(): ln for ln in lines if ln.startswith("spring stiffness")}
    assert f"{hamabe.spring.kappa / 1e3:.5g}" in design["spring stiffness"]
    assert "N/mm" in design["spring stiffness"]


def test_figures_carry_units_and_match_the_json(hamabe):
    figures = hamabe.figures()
    assert {f.group for f in figures} >= {"speed", "design", "spring", "classic"}
    by = {f.name: f for f in figures}
    assert by["wire diameter"].unit == "m" and by["wire diameter"].value == hamabe.spring.d
    assert by["spring stiffness"].unit == "N/m"
    assert by["max shear stress"].unit == "Pa"
    assert by["speed at the inner end"].value == pytest.approx(float(hamabe.statics.omega[0]))
    js = hamabe.to_dict()
    flat = {**js, **js["spring"]}
    matched = 0
    for f in figures:  # a figure's JSON key names its unit; the JSON holds the same number
        if f.key in flat and isinstance(f.value, float):
            assert flat[f.key] == pytest.approx(f.value, rel=1e-12), f.name
            matched += 1
    assert matched >= 8
    assert hamabe.figure("pendulum mass").key == "pendulum_mass_kg"


def test_to_frame_has_a_unit_column(hamabe):
    pytest.importorskip("pandas")
    frame = hamabe.to_frame()
    checks = frame[frame["kind"] == "check"]
    assert len(checks) == len(hamabe.checks)
    assert len(frame) == len(hamabe.checks) + len(hamabe.figures())
    for (_, row), c in zip(checks.iterrows(), hamabe.checks, strict=True):
        assert row["name"] == c.name and row["unit"] == c.unit and row["sense"] == c.sense
        assert row["value"] == c.value and row["passed"] == c.passed
        assert row["margin"] == pytest.approx(c.margin)
    eng = hamabe.to_frame(engineering=True)
    stress = eng[eng["name"] == "shear stress"].iloc[0]
    assert stress["unit"] == "MPa"
    assert stress["value"] == pytest.approx(hamabe.check("shear stress").value * 1e-6)
    speed = eng[eng["name"] == "speed at the inner end"].iloc[0]
    assert speed["unit"] == "rpm"
    assert speed["value"] == pytest.approx(float(hamabe.statics.omega[0]) * 30 / math.pi)
    assert not frame[frame["kind"] == "check"]["passed"].all()  # hamabe-a fails irregularity


def test_repr_html_shows_verdict_design_and_every_check(hamabe):
    page = hamabe._repr_html_()
    assert page.startswith("<div>") and page.count("<table>") == 2
    assert "FAIL: 1 of" in page
    for c in hamabe.checks:
        assert f"<td>{html.escape(c.name)}</td>" in page
    assert "<td>N/mm</td>" in page and "<td>MPa</td>" in page


def test_plot_draws_the_result(hamabe):
    pytest.importorskip("matplotlib")
    ax = hamabe.plot("characteristic")
    xs = np.concatenate([np.asarray(line.get_ydata(), float) for line in ax.get_lines()])
    rpm = hamabe.statics.omega * 30.0 / math.pi
    assert np.isclose(xs[:, None], rpm[None, :], rtol=1e-9).any(axis=0).all()
    with pytest.raises(ValueError):
        hamabe.plot(None, ax=ax)


def test_spring_checks_carry_their_group(graded, hamabe):
    spring = [c for c in graded.checks if c.group == "spring"]
    assert spring and all(c.source for c in spring)
    assert "body static shear stress" in {c.name for c in spring}
    # no grade: the spec's allowable and the geometry, not the grade's tables
    plain = {c.name for c in hamabe.checks if c.group == "spring"}
    assert "shear stress" in plain and "body static shear stress" not in plain
    js = graded.to_dict()["checks"]
    assert [c["group"] for c in js] == [c.group for c in graded.checks]


@pytest.mark.parametrize("path", sorted(govopt.examples.SPECS.glob("*.toml")),
                         ids=lambda p: p.stem)
def test_every_check_has_its_requirement_group(path):
    """Every check of every bundled spec with a design says which group of requirements it
    belongs to (the rows of govopt/requirements.py, or the spring's own tables): the search's
    bounds are told from requirements on a made part by the group, not by the name."""
    spec = govopt.load_spec(path)
    if spec.design is None:
        pytest.skip("a design problem: no design to evaluate")
    groups = {c.name: c.group for c in govopt.evaluate(spec).checks}
    assert groups and set(groups.values()) <= {"statics", "dynamics", "spring", "bounds"}, groups


def test_check_and_figure_fields():
    c = Check("solid length", 0.05, 0.06, ">=", "m", "EN 13906-1 9.2", group="spring")
    assert not c.passed and c.margin == pytest.approx(-1 / 6)
    assert c.to_dict()["unit"] == "m" and c.to_dict()["group"] == "spring"
    assert shown(c.value, c.unit) == (pytest.approx(50.0), "mm")
    assert Figure("dashpot", 1.0, "N*m*s/rad").key == "dashpot_N_m_s_per_rad"
    assert json_key("surge frequency", "Hz") == "surge_frequency_Hz"
    assert SHOWN["N/m"] == ("N/mm", 1e-3)


def _imports(path: Path, module: str, modules: set[str]) -> set[str]:
    """The govopt modules ``module`` imports, imports inside functions counted (a
    ``TYPE_CHECKING`` block is no import at run time)."""
    tree = ast.parse(path.read_text())
    skip = {id(x) for n in ast.walk(tree) if isinstance(n, ast.If)
            and "TYPE_CHECKING" in ast.unparse(n.test) for s in n.body for x in ast.walk(s)}
    package = module if path.name == "__init__.py" else module.rsplit(".", 1)[0]
    out = set()
    for n in ast.walk(tree):
        if id(n) in skip:
            continue
        if isinstance(n, ast.ImportFrom):
            base = package.split(".")
            base = base[: len(base) - (n.level - 1)] if n.level else []
            target = ".".join(base + ([n.module] if n.module else [])) if n.level else n.module
            for a in n.names:
                out.add(f"{target}.{a.name}" if f"{target}.{a.name}" in modules else target)
        elif isinstance(n, ast.Import):
            out |= {a.name for a in n.names}
    return {m for m in out if m in modules and m != module}


def test_no_import_cycle_through_the_result():
    """Counting imports inside functions: ``govopt.verdict`` imports nothing of govopt but
    ``govopt.jsonable`` (which imports nothing), and no module the result imports imports the
    result back."""
    files = {}
    for p in (ROOT / "govopt").rglob("*.py"):
        parts = list(p.relative_to(ROOT).with_suffix("").parts)
        files[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = p
    graph = {m: _imports(p, m, set(files)) for m, p in files.items()}
    assert graph["govopt.verdict"] <= {"govopt.jsonable"}
    assert graph["govopt.jsonable"] == set()

    def reach(start):
        seen, todo = set(), [start]
        while todo:
            for d in graph[todo.pop()] - seen - {"govopt"}:  # the package itself: the API
                seen.add(d)
                todo.append(d)
        return seen

    assert "govopt.result" not in reach("govopt.result")
    assert "govopt.report.plots" in reach("govopt.result")  # Result.plot, drawn only
    for m in ("govopt.springs.checks", "govopt.springs.leaf",
              "govopt.analysis.spring_engineering", "govopt.governors.base"):
        assert "govopt.result" not in reach(m), m


@pytest.mark.parametrize("name", ["hartnell-design", "porter-design"])
def test_optimiser_records_are_declared(name):
    """Every number of the optimiser's record has its label and unit declared
    (:func:`govopt.report.sections.recorded_units`): the tables parse no unit from a key."""
    from govopt.report import sections

    res = govopt.design(govopt.load_spec(SPECS / f"{name}.toml"))
    units = sections.recorded_units(res)
    opt = res.optimisation
    keys = [k for k, v in opt["design"].items() if v is not None]
    keys += list(opt["bound_design"] or {})
    assert keys and not [k for k in keys if k not in units]
    rows = {r[0]: r for t in sections.optimisation(res) for r in t.rows
            if t.title == "Chosen design"}
    d = res.design
    assert rows[f"{res.spec.governor.mass_key} mass"][1:] == ["kg", pytest.approx(
        d.flying_mass)]
    if res.spec.governor.spring is not None:
        assert rows["wire diameter"][1:] == ["mm", pytest.approx(d.wire_diameter * 1e3)]
