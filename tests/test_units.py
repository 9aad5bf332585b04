"""Unit independence: the same design whatever units the spec uses."""

import json
import math
import re

import pytest

import govopt
from govopt.units import UnitError, parse_quantity


def _numbers(obj, path=""):
    """Flatten every number in a JSON-able object to {path: value}."""
    if isinstance(obj, dict):
        out = {}
        for k, v in obj.items():
            if k not in ("spec", "name"):
                out.update(_numbers(v, f"{path}.{k}"))
        return out
    if isinstance(obj, list):
        out = {}
        for i, v in enumerate(obj):
            out.update(_numbers(v, f"{path}[{i}]"))
        return out
    if isinstance(obj, int | float) and not isinstance(obj, bool):
        return {path: float(obj)}
    return {}


def test_si_restatement_gives_the_same_results():
    """specs/hamabe-a-si.toml (N, mm, MPa, rad/s) equals specs/hamabe-a.toml
    (kgf, cm) to 1e-9."""
    a = _numbers(govopt.evaluate(govopt.load_spec("specs/hamabe-a.toml")).to_dict())
    b = _numbers(govopt.evaluate(govopt.load_spec("specs/hamabe-a-si.toml")).to_dict())
    assert a.keys() == b.keys()
    assert len(a) > 100
    for key, va in a.items():
        assert b[key] == pytest.approx(va, rel=1e-9, abs=1e-12), key


def test_json_round_trip_is_plain_json():
    res = govopt.evaluate(govopt.load_spec("specs/hamabe-a.toml"))
    text = json.dumps(res.to_dict())
    assert "NaN" not in text


@pytest.mark.parametrize(("text", "dim", "si"), [
    ("18 cm", "length", 0.18),
    ("4000 kgf/cm^2", "stress", 4000 * 9.80665e4),
    ("240 rpm", "angular_velocity", 8 * math.pi),
    ("64 deg + 40 arcmin", "angle", math.radians(64 + 40 / 60)),
    ("43 kgf*m*s^2", "inertia", 43 * 9.80665),
    ("-300 kgf*m/rad", "torque_per_angle", -300 * 9.80665),
    ("72 kgf*cm*s/rad", "damping", 72 * 9.80665 * 0.01),
    ("0.12", "dimensionless", 0.12),
])
def test_parse_quantity(text, dim, si):
    assert parse_quantity(text, dim) == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize(("text", "dim"), [
    ("18 cm", "stress"), ("18", "length"), (18, "length"), ("18 furlongs per", "length"),
    ("nan cm", "length"), ([1], "length"),
])
def test_parse_quantity_rejects(text, dim):
    with pytest.raises(UnitError):
        parse_quantity(text, dim)


# ---------------------------------------------------------------------------------------------
# Units pint cannot tell apart: the angle in a unit, read by one rule (units.angle_factor)

REV = 2 * math.pi  # radians in a revolution, a cycle


@pytest.mark.parametrize(("text", "dim", "si"), [
    # a frequency counts cycles: an angle per time in it is revolutions (1 rev/min = 1/60 Hz)
    ("1400 rpm", "frequency", 1400 / 60),
    ("700 rev/min", "frequency", 700 / 60),
    ("5 rev/s", "frequency", 5.0),
    ("2 cycle/s", "frequency", 2.0),
    ("360 deg/s", "frequency", 1.0),
    ("6.283185307179586 rad/s", "frequency", 1.0),
    ("20 Hz", "frequency", 20.0),
    ("0.05 ms^-1", "frequency", 50.0),
    # an angular velocity and the quantities per angle, as written, angles in radians
    ("60 rpm", "angular_velocity", REV),
    ("-5 kgf*m/deg", "torque_per_angle", -5 * 9.80665 * 180 / math.pi),
    ("3 N*m*s/rev", "damping", 3 / REV),
    # no angle in the unit, none in the dimension: a moment in joules is its newton metres
    ("3 J", "moment", 3.0),
])
def test_an_angle_in_a_unit_converts_by_one_rule(text, dim, si):
    assert parse_quantity(text, dim) == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize(("text", "dim", "words"), [
    ("5 Hz", "angular_velocity", "names no angle: pint would read it as 5 rad/s"),
    ("5 s^-1", "angular_velocity", "names no angle"),
    ("-300 kgf*m", "torque_per_angle", "names no angle, which a torque per angle needs"),
    ("72 kgf*cm*s", "damping", "names no angle, which a damping needs"),
    ("22 kgf*cm/rad", "moment", "is per angle, and a moment has none"),
    ("18 cm*rad", "length", "has an angle in its unit, and a length has none"),
    ("5 deg", "dimensionless", "has an angle in its unit, and a dimensionless number has none"),
    ("2 Hz/rad", "frequency", "is per angle"),
    ("1 N*m*s/rad^2", "damping", "has an angle to the power -2"),
    ("1 m/m", "angle", "names no angle"),
])
def test_an_angle_that_does_not_fit_is_refused_saying_why(text, dim, words):
    with pytest.raises(UnitError, match=re.escape(words)):
        parse_quantity(text, dim)


def test_reports_and_tolerances_convert_by_the_same_rule():
    from govopt.units import convert, to_unit

    assert to_unit(1400 / 60, "frequency", "rpm") == pytest.approx(1400, rel=1e-12)
    assert to_unit(REV, "angular_velocity", "rpm") == pytest.approx(60, rel=1e-12)
    assert convert(60, "rpm", "Hz") == pytest.approx(1.0, rel=1e-12)
    assert convert(10, "deg", "rad") == pytest.approx(math.radians(10), rel=1e-12)
    with pytest.raises(UnitError, match="names no angle"):
        convert(5, "Hz", "rad/s")


def test_a_surge_frequency_in_rpm_is_the_same_requirement_as_in_hz(tmp_path):
    """A spring spec's ``min_surge_frequency`` in rpm designs the spring its value in Hz does
    (read as rad/s it would ask 2 pi times the frequency)."""
    from govopt.spring_command import run

    options = {"force": "606 kgf", "stiffness": "59.7 kgf/cm",
               "allowable_stress": "4000 kgf/cm^2", "shear_modulus": "850000 kgf/cm^2"}
    rpm = run(None, json_out=True, min_surge_frequency="1400 rpm", **options)
    hz = run(None, json_out=True, min_surge_frequency=f"{1400 / 60!r} Hz", **options)
    a, b = json.loads(rpm.text), json.loads(hz.text)
    assert a["dynamics"]["surge_frequency_Hz"] >= 1400 / 60 * (1 - 1e-9)
    for key in ("wire_diameter_m", "mean_coil_diameter_m", "active_coils", "mass_kg"):
        assert a["spring"][key] == pytest.approx(b["spring"][key], rel=1e-6), key


def test_a_study_reads_units_by_the_same_rule():
    """A sweep's ends differing by an angle are refused; a tolerance of a frequency in rpm is
    its value in Hz, of a speed in Hz refused (as in a spec)."""
    import numpy as np

    from govopt.study import StudyError, Sweep, Tolerance

    with pytest.raises(StudyError, match="differ by an angle"):
        Sweep.parse("speed.mean", "4 Hz:250 rpm:3")
    u = np.array([0.0, 0.5, 1.0])  # uniform: -1, 0, +1 half-widths
    band = Tolerance.parse("requirements.min_surge_frequency", "uniform ±60 rpm")
    assert band.draw(20.0, "Hz", u) == pytest.approx([19.0, 20.0, 21.0], rel=1e-12)
    with pytest.raises(StudyError, match="names no angle"):
        Tolerance.parse("speed.mean", "uniform ±5 Hz").draw(25.0, "rad/s", u)


@pytest.mark.parametrize(("text", "words"), [
    ("18 cm (", "its parentheses do not match"), ("18 cm)", "its parentheses do not match"),
    ("18 cm /", "it is incomplete"), ("()", "it is incomplete"), ("+", "it is incomplete"),
    ("18 cm / 0", "it divides by zero"), ("18 \udcff cm", "bytes that are not UTF-8"),
    ([1], "got a list"),
])
def test_a_malformed_quantity_is_told_in_words_not_an_exception_class(text, words):
    with pytest.raises(UnitError, match=re.escape(words)) as err:
        parse_quantity(text, "length")
    assert not re.search(r"\b[A-Z]\w*(Error|Exception)\b|got list", str(err.value))
