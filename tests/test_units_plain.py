"""A plain quantity ("500 N", "10 N/mm") is read without pint (:data:`govopt.units.PLAIN_UNITS`):
the same SI value, bit for bit, and the same error as pint's path, for every unit of the table
and every way of writing the number; and ``govopt spring`` with such options never imports pint."""

import random
import subprocess
import sys
from fractions import Fraction

import pytest

from govopt.units import (
    PLAIN_UNITS,
    SI_UNITS,
    UnitError,
    parse_quantity,
    parse_with_pint,
    plain_si,
    registry,
)

#: each unit from its definition (SI prefixes; the kilogram-force by the CGPM's standard gravity),
#: not from pint
DEFINED = {"N": 1, "kN": 1000, "mN": "0.001", "kgf": "9.80665", "m": 1, "cm": "0.01",
           "mm": "0.001", "um": "1e-6", "Pa": 1, "kPa": 1000, "MPa": 10**6, "GPa": 10**9,
           "N/mm^2": 10**6, "N/mm2": 10**6, "N/m": 1, "N/mm": 1000, "kN/m": 1000, "Hz": 1,
           "kg": 1, "g": "0.001", "s": 1, "ms": "0.001", "rad/s": 1}
UNITS = [(dim, unit) for dim, units in PLAIN_UNITS.items() for unit in units]


@pytest.mark.parametrize("dimension, unit", UNITS)
def test_each_factor_is_pints_and_its_definition(dimension, unit):
    factor = PLAIN_UNITS[dimension][unit]
    pint_unit = unit.replace("N/mm2", "N/mm^2")
    assert factor == registry().Quantity(1, pint_unit).to(SI_UNITS[dimension]).magnitude
    assert factor == float(Fraction(DEFINED[unit]))  # correctly rounded


def _numbers(rng):
    """Numbers as people and programs write them, with pint's own edge cases: leading zeros
    (pint rejects "05" and reads "007.5"), signs, "-0", exponents, huge and tiny values."""
    yield from ["0", "-0", "00", "05", "+5", "-5", "007.5", ".5", "5.", "1e5", "1E+5", "0e0",
                "1e-400", "1e400", "1" * 150, "1" * 150 + ".5", "9" * 20, "0.1", "1_000",
                "inf", "nan", "0x10", "1e", "--5", "5..0"]
    for _ in range(20):
        x = 10 ** rng.uniform(-9, 9) * rng.choice([1, -1])
        yield from [repr(x), f"{x:.3g}", f"{x:.6e}", str(rng.randint(0, 10**7))]


def _outcome(fn, text, dimension):
    try:
        return repr(fn(text, dimension))
    except UnitError as exc:
        return f"error: {exc}"


def _through_plain(text, dimension):
    assert plain_si(text, dimension) is not None, text
    return parse_quantity(text, dimension)


@pytest.mark.parametrize("dimension, unit", UNITS + [("dimensionless", None)])
def test_plain_path_gives_pints_value_or_error(dimension, unit):
    rng = random.Random(f"{dimension} {unit}")
    for number in _numbers(rng):
        for text in ([number] if unit is None else
                     [f"{number} {unit}", f"{number}  {unit}", f" {number} {unit}",
                      f"{number}\t{unit}", f"{number} {unit} "]):
            if plain_si(text, dimension) is None:  # pint's path, nothing to compare
                continue
            assert _outcome(_through_plain, text, dimension) == _outcome(
                parse_with_pint, text, dimension), text
    # the plain forms are taken by the plain path; a unit of another dimension is not
    if unit is not None:
        assert plain_si(f"12.5 {unit}", dimension) is not None
        other = "length" if dimension != "length" else "force"
        assert plain_si(f"12.5 {unit}", other) is None


@pytest.mark.parametrize("text", ["05 N", "1_000 N", "inf N", "12.5N", "12.5 N m", "12.5 N/mm^2",
                                  "(12.5) N", "12.5 newton", "12.5 lbf", "12.5 lbf/in"])
def test_what_is_not_plain_goes_through_pint(text):
    assert plain_si(text, "force") is None


def test_spring_with_plain_options_does_not_import_pint():
    code = ("import sys\nfrom govopt.cli import main\n"
            "sys.argv = ['govopt', 'spring', '--force', '500 N', '--stiffness', '10 N/mm',"
            " '--allowable-stress', '600 MPa', '--shear-modulus', '81.5 GPa', '--json']\n"
            "try:\n    main()\nexcept SystemExit as exc:\n    assert not exc.code, exc.code\n"
            "assert 'pint' not in sys.modules, 'pint imported'\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    assert '"mass"' in out.stdout
