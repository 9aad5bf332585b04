"""'No equilibrium speed' names the spec keys that decide it and which way to move them
: a spring too stiff for the range (its largest rate is then enough), a free length
too long, the regulating gear's inertia above the flying masses'."""

import re
from dataclasses import replace
from pathlib import Path

import pytest

from govopt import evaluate, load_spec
from govopt.errors import DesignError

SPECS = Path(__file__).resolve().parent.parent / "specs"


def _variant(tmp_path, name: str, key: str, value: str) -> Path:
    text = (SPECS / name).read_text()
    new, n = re.subn(rf"(?m)^{re.escape(key)}\s*=\s*[^#\n]*", f"{key} = {value} ", text, count=1)
    assert n == 1
    path = tmp_path / f"{key}.toml"
    path.write_text(new)
    return path


def _message(path: Path) -> str:
    with pytest.raises(DesignError) as info:
        evaluate(load_spec(path))
    return str(info.value)


@pytest.mark.parametrize("key, value", [("b", '"17.99 cm"'), ("wire_diameter", '"6 cm"'),
                                        ("active_turns", "0.01")])
def test_a_spring_too_stiff_names_its_keys_and_the_largest_rate(tmp_path, key, value):
    msg = _message(_variant(tmp_path, "hamabe-a.toml", key, value))
    assert "alpha = 50.00 deg: the spring is too stiff" in msg, msg
    for word in ("thinner design.wire_diameter", "larger design.coil_radius",
                 "more design.active_turns", "[governor]"):
        assert word in msg
    kmax = float(re.search(r"at most ([\d.e+]+) N/m", msg)[1])
    # the largest rate is the answer: just below it the range holds, just above it does not
    base = load_spec(_variant(tmp_path, "hamabe-a.toml", "b", '"17.99 cm"') if key == "b"
                     else SPECS / "hamabe-a.toml")

    def rate(k):
        return base.with_design(replace(base.design, spring_stiffness=k))

    ok = rate(0.99 * kmax)
    evaluate(ok)  # no DesignError
    with pytest.raises(DesignError):
        evaluate(rate(1.01 * kmax))


def test_a_free_length_too_long_names_it_and_its_bound(tmp_path):
    msg = _message(_variant(tmp_path, "textbook-ex6-spring_loaded.toml", "free_length",
                            '"100 cm"'))
    assert "design.free_length = 1 m; equilibrium over the whole range needs it below " \
           "0.15 m" in msg, msg


def test_the_regulating_gears_inertia_names_the_flying_mass(tmp_path):
    msg = _message(_variant(tmp_path, "hamabe-a.toml", "q", '"1000 m"'))
    assert "the regulating gear's inertia outweighs the flying masses' centrifugal force" in msg
    assert "heavier flying masses (design.pendulum_weight)" in msg
    # written as a mass, the mass's key is named
    path = tmp_path / "q.toml"
    path.write_text(path.read_text().replace('pendulum_weight = "12 kgf"',
                                             'pendulum_mass = "12 kg"'))
    assert "heavier flying masses (design.pendulum_mass)" in _message(path)


def test_messages_name_the_keys_the_spec_writes():
    """A design the spec's [design] does not give (found by the search, a study's point) is
    diagnosed in words, never under a key the spec has not; a key the spec writes is named as
    written (``pendulum_mass``, not ``pendulum_weight``)."""
    import dataclasses

    from govopt.analysis.characteristic import design_key
    from govopt.evaluator import invalid
    from govopt.spec import Design, load_spec

    search = load_spec("specs/hamabe-design.toml")  # no [design]
    thick = Design(flying_mass=10.0, wire_diameter=0.1, coil_radius=0.04, active_turns=8.0)
    message = invalid(search, thick)
    assert "design.wire_diameter" not in message and "not thinner than the coil" in message
    a = load_spec("specs/hamabe-a.toml")
    assert invalid(a, dataclasses.replace(a.design, wire_diameter=1.0)).startswith(
        f"{a.path}: design.wire_diameter: ")
    assert design_key(a, "flying_mass") == "design.pendulum_weight"
    assert design_key(search, "flying_mass") is None
