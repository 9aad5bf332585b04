"""The diagnosis names the cause and the change that makes a design exist, in the spec's keys
and the units it wrote them in: a Porter whose sleeve friction spreads its band past the
required 190-224 rpm is told to lower ``governor.sleeve_friction`` (to a value that works, and
only just: a little more does not), ``govopt design --json`` prints that diagnosis as one JSON
object and exits 2, and a failing ``govopt evaluate`` is told the same kind of change."""

from __future__ import annotations

import copy
import json
import re
import tomllib
from pathlib import Path

import pytest
from clirun import invoke

import govopt
from govopt.errors import InfeasibleError
from govopt.spec import parse_spec

SPECS = Path(__file__).resolve().parent.parent / "specs"
PORTER = tomllib.loads((SPECS / "porter-design.toml").read_text(encoding="utf-8"))
#: the bundled Porter design's sleeve friction, and eight times as much: its friction band
#: then spreads wider than 190-224 rpm leaves room for at every weight in the bounds
FRICTION, TOO_MUCH = "1 kgf", "8 kgf"


def _porter(friction: str, bounds: bool = True) -> dict:
    data = copy.deepcopy(PORTER)
    assert data["governor"]["sleeve_friction"] == FRICTION
    data["governor"]["sleeve_friction"] = friction
    if not bounds:
        del data["bounds"]
    return data


def _friction_move(moves: list[str]) -> float:
    """The sleeve friction (kgf) the move lowers it to."""
    move = next(m for m in moves if m.startswith("governor.sleeve_friction "))
    found = re.fullmatch(r"governor\.sleeve_friction 8 kgf -> ([0-9.]+) kgf", move)
    assert found, move
    return float(found[1])


def test_too_much_friction_is_told_to_lower_it():
    """The diagnosis names the friction as the cause and lowers it to a value at which the
    search finds a design; 1 % more friction than that is still infeasible (the bisection
    stops within 0.1 % and the value is rounded down)."""
    with pytest.raises(InfeasibleError) as info:
        govopt.design(parse_spec(_porter(TOO_MUCH), "porter.toml"))
    e = info.value
    assert "governor.sleeve_friction" in e.reason, e.reason
    assert e.moves[0].startswith("governor.sleeve_friction 8 kgf -> "), e.moves
    works = _friction_move(e.moves)
    assert 1.0 < works < 8.0
    res = govopt.design(parse_spec(_porter(f"{works} kgf"), "porter.toml"))
    assert all(c.passed for c in res.checks)
    with pytest.raises(InfeasibleError):
        govopt.design(parse_spec(_porter(f"{works * 1.01:.6g} kgf"), "porter.toml"))
    # the weight bounds' move names the spec's keys and units, not a bare factor
    assert any(m.startswith("bounds.ball_weight 2 .. 10 kgf -> ") and
               "bounds.central_weight 10 .. 100 kgf -> " in m for m in e.moves), e.moves
    # the geometry: a narrower range of radii narrows the band; the radius told works
    outer = next(m for m in e.moves if m.startswith("governor.radius_outer 25 cm -> "))
    data = _porter(TOO_MUCH)
    data["governor"]["radius_outer"] = outer.split(" -> ")[1]
    assert all(c.passed for c in govopt.design(parse_spec(data, "porter.toml")).checks)


def test_a_porter_without_bounds_is_not_told_only_to_move_its_band():
    """Without [bounds] the central load searched is 0: the first move is that bound, so the
    band's end (190 rpm -> 62 rpm) is never the only move."""
    with pytest.raises(InfeasibleError) as info:
        govopt.design(parse_spec(_porter(FRICTION, bounds=False), "porter.toml"))
    moves = info.value.moves
    assert moves and not moves[0].startswith("speed."), moves


def test_design_json_prints_the_diagnosis_and_exits_2(tmp_path):
    """`govopt design --json` on the infeasible Porter prints one JSON object on stdout: the
    status, the reason and the moves (lowering the friction among them); exit 2, the one line
    on stderr."""
    path = tmp_path / "porter.toml"
    data = _porter(TOO_MUCH)
    path.write_text((SPECS / "porter-design.toml").read_text(encoding="utf-8")
                    .replace(f'sleeve_friction = "{FRICTION}"',
                             f'sleeve_friction = "{TOO_MUCH}"'))
    assert govopt.load_spec(path).governor.sleeve_friction > 70.0  # 8 kgf, as in data
    r = invoke(["design", str(path), "--json"])
    assert r.exit_code == 2, r.output
    out = json.loads(r.stdout)
    assert out["status"] == "infeasible" and out["spec"] == str(path)
    assert _friction_move(out["moves"]) == _friction_move(
        pytest.raises(InfeasibleError, govopt.design,
                      parse_spec(data, str(path))).value.moves)
    assert r.stderr.startswith("error: ") and "governor.sleeve_friction" in r.stderr


def test_a_failing_evaluation_is_told_what_to_change(tmp_path):
    """`govopt evaluate` of the Porter designed for 1 kgf of friction, with 8 kgf: both band
    checks fail; it is told to lower the friction, to a value at which every check passes
    (in the JSON, ``diagnosis``)."""
    designed = govopt.design(parse_spec(_porter(FRICTION), "porter.toml")).design
    text = (SPECS / "porter-design.toml").read_text(encoding="utf-8").replace(
        f'sleeve_friction = "{FRICTION}"', f'sleeve_friction = "{TOO_MUCH}"')
    path = tmp_path / "porter.toml"
    path.write_text(text + f'\n[design]\nball_mass = "{designed.flying_mass} kg"\n'
                    f'central_mass = "{designed.central_mass} kg"\n')
    r = invoke(["evaluate", str(path)])
    assert r.exit_code == 1, r.output
    line = next(ln for ln in r.stderr.splitlines() if ln.startswith("it passes if"))
    works = _friction_move(line.split(": ", 1)[1].split("; "))
    fixed = path.read_text().replace(f'sleeve_friction = "{TOO_MUCH}"',
                                     f'sleeve_friction = "{works} kgf"')
    path.write_text(fixed)
    assert all(c.passed for c in govopt.evaluate(govopt.load_spec(path)).checks)
    path.write_text(text + f'\n[design]\nball_mass = "{designed.flying_mass} kg"\n'
                    f'central_mass = "{designed.central_mass} kg"\n')
    r = invoke(["evaluate", str(path), "--json"])
    assert r.exit_code == 1
    diagnosis = json.loads(r.stdout)["diagnosis"]
    assert set(diagnosis["failed"]) == {"lowest speed >= speed.inner",
                                        "highest speed <= speed.outer"}
    assert _friction_move(diagnosis["moves"]) == works
