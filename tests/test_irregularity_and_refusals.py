"""Results to trust: one definition of the irregularity everywhere, no
impossible design passes, no input silently reinterpreted, friction that holds the pendulum."""

from __future__ import annotations

import dataclasses
import json
import math
import re
from pathlib import Path

import numpy as np
import openpyxl
import pytest
from clirun import invoke
from test_excel import SOFFICE, _named_cells, _recalculate  # the suite's LibreOffice helpers

import govopt
import govopt.evaluator
from govopt.analysis import characteristic as chs
from govopt.analysis import friction, statics
from govopt.result import Check
from govopt.units import UnitError, parse_quantity

BASE = Path("specs/hamabe-a.toml").read_text()
KGFCM = 9.80665e-2  # N m


def _spec_file(tmp_path, *edits: tuple[str, str]) -> Path:
    text = BASE
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / "spec.toml"
    path.write_text(text)
    return path


# ------------------------------------------------------------------------------------------
# item 4: one definition of the irregularity


def test_irregularity_is_hamabes_definition():
    """Hamabe, Example 1, case a, closing check: "(26.4 - 23.4) / 25.1 = 0.119", the range over
    the spec's mean speed omega0. The range over the mean of the two extreme speeds (kept as
    `sensitiveness`) is 2 x 3.0 / 49.8 = 0.1205 and does not give the paper's 0.119."""
    res = govopt.evaluate(govopt.load_spec("specs/hamabe-a.toml"))
    paper = dataclasses.replace(res.statics, omega=np.array([23.4, 26.4]), omega_mean=25.1)
    assert paper.irregularity == pytest.approx(3.0 / 25.1, rel=1e-12)
    assert abs(paper.irregularity - 0.119) < 6e-4  # the paper truncates 0.1195
    assert paper.sensitiveness == pytest.approx(6.0 / 49.8, rel=1e-12)
    assert abs(paper.sensitiveness - 0.119) > 1e-3
    # govopt's own case a: the check is the same figure, against the spec's 0.12
    st = res.statics
    check = res.check("irregularity")
    assert check.value == (st.omega[-1] - st.omega[0]) / res.spec.speed.omega_mean
    assert check.limit == 0.12 and "omega0" in check.source


def test_irregularity_agrees_in_json_text_and_excel(tmp_path):
    """A design whose speed range is off-centre (free half length fixed at 12 cm): the
    irregularity (omega_a - omega_i) / omega0 = 0.0983 differs from the sensitiveness 0.0882 by
    10 %, and the JSON, the text report, the check and the recalculated Excel sheet all give the
    first (the sensitiveness is reported under its own name, with the classic measures)."""
    path = _spec_file(tmp_path, ("active_turns = 8",
                                 'active_turns = 8\nfree_half_length = "12 cm"'))
    book = tmp_path / "book.xlsx"
    out = invoke(["evaluate", str(path), "--json", "--xlsx", str(book)])
    # exit 1: this off-centre design over-stresses its spring; a failed check exits 1
    # (a failed check exited 0)
    assert out.exit_code == 1, out.output
    assert [c["name"] for c in json.loads(out.stdout)["checks"] if not c["passed"]] == [
        "shear stress"]
    js = json.loads(out.stdout)
    want = (js["omega_outer_rad_s"] - js["omega_inner_rad_s"]) / js["omega_mean_rad_s"]
    assert js["irregularity"] == pytest.approx(want, rel=1e-14)
    assert js["irregularity"] == pytest.approx(0.0983, abs=1e-4)
    assert js["classic"]["sensitiveness"] == pytest.approx(0.0882, abs=1e-4)
    check = next(c for c in js["checks"] if c["name"] == "irregularity")
    assert check["value"] == js["irregularity"]
    text = invoke(["evaluate", str(path)])
    assert text.exit_code == 1, text.output  # the same failed check
    shown = float(re.search(r"^irregularity\s+([0-9.]+)", text.output, re.M).group(1))
    assert shown == pytest.approx(want, abs=5e-6)  # printed to 5 decimals
    wb = openpyxl.load_workbook(book)
    sheet, ref = _named_cells(wb)["irregularity"]
    assert wb[sheet][ref].value == "=(omega_outer-omega_inner)/omega_mean"
    if SOFFICE is None:
        pytest.skip("LibreOffice (soffice) not on PATH: the formula is not recalculated")
    recalc = _recalculate([book], tmp_path / "out", tmp_path / "profile")[book]
    wv = openpyxl.load_workbook(recalc, data_only=True)
    assert wv[sheet][ref].value == pytest.approx(want, rel=1e-9)


# ------------------------------------------------------------------------------------------
# item 5: impossible designs never pass


@pytest.mark.parametrize("fidelity", [
    {}, {"geometry": "series", "reaction_speed": "mean"}, {"reaction_slope": False},
    {"valve_table": "linear"}])
@pytest.mark.parametrize("case", ["a", "d"])
def test_characteristic_slope_is_the_derivative(case, fidelity):
    """d omega/d alpha = I k^2 / (2 omega L) (eq. 12 differentiated) against a central
    difference of the characteristic, between the valve-gear table's rows (where the
    characteristic is smooth): agreement to the difference's own truncation error."""
    spec = govopt.load_spec(f"specs/hamabe-{case}.toml").with_analysis(**fidelity)
    sd = statics.spring_design(spec)
    gov = spec.governor
    alpha = np.linspace(gov.x_inner + 0.01, gov.x_outer - 0.01, 9)
    alpha = alpha[np.min(np.abs(alpha[:, None] - gov.valve_gear.table_alpha), axis=1) > 1e-3]
    omega = chs.characteristic(spec, sd, alpha).omega
    h = 1e-5
    fd = (chs.characteristic(spec, sd, alpha + h).omega
          - chs.characteristic(spec, sd, alpha - h).omega) / (2 * h)
    np.testing.assert_allclose(chs.characteristic_slope(spec, sd, alpha, omega), fd,
                               rtol=1e-7)


def test_falling_characteristic_fails_where_the_papers_k2_passes(tmp_path):
    """The paper's model (series geometry, reaction at the mean speed, no dM_r0/dalpha in k^2)
    with a 24-turn spring: the speed *falls* from the innermost to the outermost configuration
    (irregularity -0.0024), yet the paper's k^2 stays positive (its k^2 leaves out the falling
    valve-gear reaction). Once reported as PASS everywhere; now the stability check fails."""
    path = _spec_file(tmp_path, ("active_turns = 8", "active_turns = 24"))
    path.write_text(path.read_text() + '\n[analysis]\ngeometry = "series"\n'
                    'reaction_speed = "mean"\nreaction_slope = false\n')
    out = invoke(["evaluate", str(path), "--json"])
    assert out.exit_code == 1, out.output  # a failing design exits 1
    js = json.loads(out.stdout)
    checks = {c["name"]: c for c in js["checks"]}
    assert js["irregularity"] == pytest.approx(-0.0024, abs=1e-4)
    assert checks["irregularity"]["passed"]  # -0.0024 <= 0.12: this check alone passed it
    assert checks["k^2 > 0 (stability)"]["passed"]
    rise = checks["characteristic rises (stable)"]
    secant = (js["omega_outer_rad_s"] - js["omega_inner_rad_s"]) / math.radians(30)
    assert not rise["passed"] and rise["value"] <= secant < 0
    assert js["classic"]["stability"] == "unstable"  # the same slope, the same verdict


def test_free_length_not_positive_is_an_error_with_the_least_stiffness(tmp_path):
    """80 turns: the spring is too soft; equilibrium at the normal configuration would need a
    negative free half length. Exit 2, and the diagnosis's least stiffness is exact."""
    path = _spec_file(tmp_path, ("active_turns = 8", "active_turns = 80"))
    out = invoke(["evaluate", str(path)])
    assert out.exit_code == 2, out.output
    assert "free half length" in out.output and "Traceback" not in out.output
    kappa_min = float(re.search(r"kappa > ([0-9.e+]+) N/m", out.output).group(1))
    spec = govopt.load_spec(path)
    m = spec.design.flying_mass
    assert statics.free_half_length(spec, m, kappa_min * (1 + 1e-5)) > 0
    assert statics.free_half_length(spec, m, kappa_min * (1 - 1e-5)) < 0


@pytest.mark.parametrize("edits", [
    # d^4 overflows a float: "a figure overflows"
    [('"1.7 cm"', '"1e80 m"'), ('"6 cm"', '"1e81 m"')],
    # 1e-300 turns with the free length fixed: infinite stress
    [("active_turns = 8", 'active_turns = 1e-300\nfree_half_length = "13 cm"')],
    # 1e299 turns: a spring of 7e298 kg with a free half length of -5e296 m
    [("active_turns = 8", "active_turns = 1e299")],
])
def test_impossible_designs_exit_2(tmp_path, edits):
    out = invoke(["evaluate", str(_spec_file(tmp_path, *edits))])
    assert out.exit_code == 2, out.output
    # since govopt's limits (govopt/limits.py) these magnitudes are refused when the spec
    # is read, naming the key, before any figure can overflow; either way no result is reported
    assert ("impossible design" in out.output
            or re.search(r"design\.\w+: .* outside govopt's range", out.output)), out.output
    assert "Traceback" not in out.output and "PASS" not in out.output


def test_impossible_design_within_the_limits_exit_2(tmp_path):
    """A spring inside the limits whose figures still make no sense: 1e11 turns (a 7e10 kg
    spring needing a negative free length) is an error with a diagnosis, never a result."""
    out = invoke(["evaluate", str(_spec_file(
        tmp_path, ("active_turns = 8", "active_turns = 1e11")))])
    assert out.exit_code == 2, out.output
    assert "Traceback" not in out.output and "PASS" not in out.output


def test_design_exits_2_when_its_final_verification_fails(monkeypatch):
    """`govopt design` re-evaluates its choice; a failing check there is an error (exit 2)
    naming the check, never an "optimal" design."""
    real = govopt.evaluator.evaluate

    def failing(spec, design=None):
        res = real(spec, design)
        res.checks.append(Check("injected check", 2.0, 1.0, "<=", "m"))
        return res

    monkeypatch.setattr(govopt.evaluator, "evaluate", failing)
    out = invoke(["design", "specs/hamabe-design.toml", "--json"])
    assert out.exit_code == 2, out.output
    assert "final verification" in out.output and "injected check: 2 m" in out.output


# ------------------------------------------------------------------------------------------
# item 6: inputs never silently reinterpreted (the spec-level cases are in test_spec_errors)


@pytest.mark.parametrize(("text", "dim", "message"), [
    ("64 deg + 0.01", "angle", "0.01 has no unit"),
    ("64 deg - 0.01", "angle", "0.01 has no unit"),
    ("1.13", "angle", "has no unit"),
    ("pi / 2", "angle", "has no unit"),
    ("=18 cm", "length", "unexpected '='"),
    ("18 cm;3", "length", "unexpected ';'"),
    ("18 cm 3", "length", "the number 3 follows"),
    ("18 3 cm", "length", "the number 3 follows"),
    ("*18 cm", "length", "unexpected '*'"),
    ("18 cm + 1", "length", "1 has no unit"),
])
def test_strict_quantities(text, dim, message):
    with pytest.raises(UnitError, match=re.escape(message)):
        parse_quantity(text, dim)


@pytest.mark.parametrize(("text", "dim", "si"), [
    ("(64 + 0.5) deg", "angle", math.radians(64.5)),
    ("2 * 30 deg", "angle", math.radians(60)),
    ("1.13 rad", "angle", 1.13),
    ("64 deg + 40 arcmin - 20 arcmin", "angle", math.radians(64 + 20 / 60)),
    ("18 cm / 2", "length", 0.09),
    ("-300 kgf*m/rad", "torque_per_angle", -300 * 9.80665),
    ("0.12", "dimensionless", 0.12),
])
def test_strict_quantities_still_accept_expressions(text, dim, si):
    assert parse_quantity(text, dim) == pytest.approx(si, rel=1e-12)


# ------------------------------------------------------------------------------------------
# item 7: friction that holds the pendulum from the start


def _with_friction(M0):
    spec = govopt.load_spec("specs/hamabe-a.toml")
    return spec.with_design(dataclasses.replace(spec.design, friction_moment=M0))


def test_friction_that_never_lets_go():
    """Stuck from t = 0 to the horizon: a result that says so, with the residual offset (all of
    xi0) and the speed error drifting as eta' = -R xi0 (Hamabe eq. 27)."""
    spec = _with_friction(5000 * KGFCM)
    m = friction.load_change_model(spec)
    r = friction.friction_load_change(spec)
    assert r.outcome == "stuck" and not r.moved and r.strokes == ()
    assert r.first_stroke_end is None and not r.over_regulation and not r.hunting
    xi, v, eta = r.final_state
    assert xi == m.xi0 and v == 0.0
    assert eta == pytest.approx(m.eta0 - m.R * m.xi0 * r.t_horizon, rel=1e-12)
    assert r.note.startswith("the governor does not move")
    json.dumps(r.to_dict())


def test_stuck_threshold_is_the_net_moment_at_the_horizon():
    """Stuck for good exactly when M0 exceeds the net moment C eta - I k^2 xi0 reached at the
    horizon (it grows linearly while the pendulum sticks)."""
    m = friction.load_change_model(_with_friction(22.6 * KGFCM))
    r0 = friction.friction_transient(m.I, m.f, m.k2, m.C, m.R, m.M0, m.xi0, m.eta0)
    t_end = r0.t_horizon
    threshold = abs(m.net0 - m.C * m.R * m.xi0 * t_end)
    runs = {s: friction.friction_transient(m.I, m.f, m.k2, m.C, m.R, threshold * s, m.xi0,
                                           m.eta0, t_end=t_end, max_strokes=1)
            for s in (1 + 1e-6, 1 - 1e-6)}
    assert runs[1 + 1e-6].outcome == "stuck"
    assert runs[1 - 1e-6].moved and runs[1 - 1e-6].outcome != "stuck"


def test_evaluate_reports_a_stuck_pendulum(tmp_path):
    """`govopt evaluate` with a friction moment that holds the pendulum: no crash, a FAIL whose
    value is the residual deviation (the whole load change, 7 deg 20')."""
    path = _spec_file(tmp_path, ('dashpot_a1 = "24 kgf*cm*s/rad"',
                                 'dashpot_a1 = "24 kgf*cm*s/rad"\nfriction_moment = "5000 kgf*cm"'))
    out = invoke(["evaluate", str(path), "--json"])
    assert out.exit_code == 1, out.output  # the failed friction check
    js = json.loads(out.stdout)
    assert js["friction"][0]["outcome"] == "stuck" and js["friction"][0]["moved"] is False
    check = next(c for c in js["checks"]
                 if c["name"] == "friction: the governor follows the load change: unloading")
    assert not check["passed"]
    assert check["value"] == pytest.approx(math.radians(7 + 20 / 60), rel=1e-12)
    text = invoke(["evaluate", str(path), "--full"])  # the friction table's note
    assert text.exit_code == 1 and "the governor does not move" in text.output
