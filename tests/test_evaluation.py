"""govopt.evaluate with a design passed in (not the spec's own): every analysis reads that
design, not the spec's ``[design]``; check names use the type's own word for its flying mass."""

from dataclasses import replace
from pathlib import Path

import pytest

import govopt
from govopt.analysis import friction

SPECS = Path(__file__).resolve().parent.parent / "govopt" / "specs"


def _porter_with_friction(tmp_path):
    text = (SPECS / "porter-engine.toml").read_text().replace(
        'sleeve_offset = "3.76 cm"', 'sleeve_offset = "3.76 cm"\nsleeve_friction = "1 kgf"')
    path = tmp_path / "porter-friction.toml"
    path.write_text(text)
    return govopt.load_spec(path)


def test_friction_run_uses_the_evaluated_design(tmp_path):
    """A dash-pot given with the design (not in the spec's [design]) reaches Hamabe's friction
    transient (eqs. 42-46): its f is the evaluated design's, and evaluate(spec, design) equals
    evaluate(spec.with_design(design))."""
    spec = _porter_with_friction(tmp_path)
    other = replace(spec.design, dashpot=2.0 * spec.design.dashpot)
    res = govopt.evaluate(spec, other)
    fr = res.dynamics["friction"][0]
    assert fr["f_N_s_per_m"] == pytest.approx(other.dashpot, rel=1e-15)
    ref = friction.friction_load_change(spec.with_design(other), None,
                                        spec.load_changes[0]).to_dict()
    assert fr["first_stroke_end_m"] == ref["first_stroke_end_m"]
    same = govopt.evaluate(spec.with_design(other))
    assert [(c.name, c.value) for c in res.checks] == [(c.name, c.value) for c in same.checks]


@pytest.mark.parametrize("name, word", [("hartnell-design.toml", "ball"),
                                        ("traction-coil-design.toml", "fly weight"),
                                        ("hamabe-design.toml", "pendulum")])
def test_mass_bound_checks_name_the_types_mass(name, word):
    """The design's bounds on the flying mass are named with Governor.mass_name."""
    from govopt.optimize.design import design

    res = design(govopt.load_spec(SPECS / name))
    names = [c.name for c in res.checks]
    assert f"{word} mass >= min" in names and f"{word} mass <= max" in names
    if word != "pendulum":
        assert not any("pendulum" in n for n in names)
