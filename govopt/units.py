"""Units at the edges: one pint registry, parsing of spec strings, formatting for reports.

Everything inside govopt is SI (m, kg, s, N, Pa, rad). Spec files carry units as strings that
pint parses, e.g. ``"18 cm"``, ``"4000 kgf/cm^2"``, ``"240 rpm"``, ``"64 deg + 40 arcmin"``;
also as engineers type them: ``"4000 kgf/cm2"`` (a power as a trailing digit), ``"cm²"``,
``"kgf·cm"``, ``"300 rev/min"``, ``"300 RPM"``.
``kgf`` is the standard kilogram-force (9.80665 N); a weight in kgf is turned into a mass with
standard gravity, so a 12 kgf pendulum has a mass of exactly 12 kg. (Hamabe writes g = 981 cm/s^2;
the 0.03 % difference is far below the paper's own rounding.)
"""

from __future__ import annotations

import difflib
import functools
import math
import re
import tokenize

from .limits import MAX_EXPONENT, MAX_QUANTITY_CHARS, magnitude_error, shorten


@functools.cache
def registry():
    """The one pint registry, built on first use: importing pint and parsing its unit
    definitions takes a few tenths of a second, which ``govopt --help`` and every command that
    reads no quantity should not pay. pint's own disk cache of the parsed definitions
    (``cache_folder=":auto:"``) makes later builds fast; without a usable cache folder the
    definitions are parsed afresh."""
    import pint

    try:
        ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except Exception:  # an unwritable or damaged cache folder
        ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.define("@alias revolution = rev = r")  # "300 rev/min", "300 r/min" (DIN 1301)
    ureg.define("@alias revolutions_per_minute = RPM")  # as on rating plates
    return ureg


def __getattr__(name: str):
    """``ureg`` (the registry) and ``Q_`` (its Quantity), built when first asked for."""
    if name == "ureg":
        return registry()
    if name == "Q_":
        return registry().Quantity
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: Standard gravity, m/s^2 (CGPM 1901), used to convert weights to masses.
G_STANDARD = 9.80665

#: SI unit of each dimension name used in specs and reports.
SI_UNITS = {
    "length": "m",
    "angle": "rad",
    "force": "N",
    "mass": "kg",
    "stress": "Pa",
    "angular_velocity": "rad/s",
    "moment": "N*m",
    "inertia": "kg*m^2",
    "torque_per_angle": "N*m/rad",
    "torque_per_length": "N*m/m",
    "linear_damping": "N*s/m",
    "density": "kg/m^3",
    "damping": "N*m*s/rad",
    "time": "s",
    "frequency": "Hz",
    "stiffness": "N/m",
    "dimensionless": "",
}


class UnitError(ValueError):
    """A string that is not a quantity of the expected dimension."""


def parse_quantity(text, dimension: str) -> float:
    """Parse ``text`` (a string with units, or a bare number for dimensionless) into SI.

    Raises :class:`UnitError` with a readable message when the string does not parse (naming
    an unknown unit), is not a real finite number, or has the wrong dimension. An angular
    velocity must name its angle (``rpm``, ``rev/s``, ``rad/s``): pint reads ``"5 Hz"`` as
    5 rad/s, not 5 revolutions per second; a frequency counts revolutions where its unit has
    an angle (:func:`angle_factor`: ``"1400 rpm"`` is 23.3 Hz).

    >>> parse_quantity("300 rev/min", "angular_velocity") == parse_quantity("300 RPM",
    ...                                                                     "angular_velocity")
    True
    >>> parse_quantity("4000 kgf/cm2", "stress")  # 4000 x 9.80665 N / 1e-4 m^2
    392266000.0
    >>> parse_quantity("18 kfg", "force")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    govopt.units.UnitError: cannot parse '18 kfg' ...: unknown unit 'kfg' (did you mean 'kgf'?)
    """
    if isinstance(text, str) and len(text) <= MAX_QUANTITY_CHARS:
        return _parse_text(text, dimension)
    return _parse(text, dimension)


@functools.lru_cache(maxsize=4096)
def _parse_text(text: str, dimension: str) -> float:
    """:func:`_parse` of a string, remembered: a spec's quantities are parsed again for every
    study point and every variant of the spec (pint takes ~1 ms a string); an error is not
    remembered (raised afresh each time)."""
    return _parse(text, dimension)


def _parse(text, dimension: str) -> float:
    """:func:`parse_quantity` itself."""
    name = dimension.replace("_", " ")
    if isinstance(text, bool):
        raise UnitError(f"expected {_a(name)} with units, got {text!r}")
    if isinstance(text, int | float):
        if dimension == "dimensionless":
            return _finite(text, text)
        raise UnitError(f"expected {_a(name)} with units (e.g. '{_example(dimension)}'), "
                        f"got the bare number {text!r}")
    if not isinstance(text, str):
        kind = {list: "a list", tuple: "a list", dict: "a table"}.get(type(text), "a value")
        raise UnitError(f"expected a string with units, got {kind} {shorten(text)}")
    if any("\ud800" <= c <= "\udfff" for c in text):  # from an option's bytes, not UTF-8
        raise UnitError(f"{shorten(text)}: it holds bytes that are not UTF-8 text")
    if len(text) > MAX_QUANTITY_CHARS:  # before pint, whose parser is super-linear
        raise UnitError(f"{shorten(text)}: a quantity of at most {MAX_QUANTITY_CHARS} "
                        f"characters (govopt's limit), got {len(text)}")
    return parse_with_pint(text, dimension)


def parse_with_pint(text: str, dimension: str) -> float:
    """:func:`_parse` of a string through pint."""
    si = SI_UNITS[dimension]
    name = dimension.replace("_", " ")
    import pint

    Q_ = registry().Quantity
    typed = normalise(text)
    try:
        has_unit = strict_units(typed, shown=text)
        q = Q_(typed)
    except UnitError:
        raise
    except pint.UndefinedUnitError as exc:
        raise UnitError(f"cannot parse {text!r} as a quantity: {_unknown(exc)}") from None
    except OverflowError:
        raise UnitError(f"{text!r} is too large a number") from None
    except Exception as exc:  # pint raises many exception types for malformed strings
        raise UnitError(f"cannot parse {text!r} as a quantity: {malformed(exc)}") from None
    if not has_unit and dimension != "dimensionless":
        raise UnitError(f"{text!r} has no unit: expected {_a(name)} such as "
                        f"'{_example(dimension)}'"
                        + (" (pint would read a bare number as radians)"
                           if dimension == "angle" else ""))
    if not isinstance(q, pint.Quantity):  # a bare number in a string
        q = Q_(float(q), "")
    value = _to_si(q, dimension, text)
    if isinstance(value, complex):
        raise UnitError(f"{text!r} is not a real number")
    return _finite(value, text, si)


#: The power of the angle in each dimension's unit (``rad/s``: 1; ``N*m/rad``: -1; none: 0).
#: pint takes the radian for the number 1, so by dimension alone it cannot tell a frequency
#: from an angular velocity, a torque from a torque per radian, a length from a length times an
#: angle: ``"1400 rpm"`` as a frequency would be 146.6 Hz, not 23.3 Hz. govopt counts the angle
#: a written unit holds (the radian's power in its root units) and reads it by one rule,
#: :func:`angle_factor`.
ANGLE_POWER = {"angle": 1, "angular_velocity": 1, "torque_per_angle": -1, "damping": -1}


def angle_power(q) -> float:
    """The power of the angle in a pint quantity's unit (``rpm``: 1, ``kgf*m/deg``: -1, ``Hz``
    and ``J``: 0; ``rad**0.5``: 0.5, which no dimension has)."""
    return float(dict(q.to_root_units().unit_items()).get("radian", 0))


def angle_factor(dimension: str, power: float, text: str, value: float | None = None) -> float:
    """What pint's SI value of a quantity of ``dimension`` whose unit holds an angle to
    ``power`` (:func:`angle_power`; ``value``: that SI value, quoted in a refusal) is multiplied
    by; a :class:`UnitError` saying why where the angle does not fit the dimension. The one
    rule:

    * the angle the dimension has (:data:`ANGLE_POWER`): read as written, angles in radians;
    * a frequency counts cycles: an angle per time in one is counted in revolutions (a cycle is
      one revolution): ``1 rev/min = 1/60 Hz``, ``2 pi rad/s = 1 Hz``;
    * anything else is refused: an angular velocity or a quantity per angle written without
      its angle (``"5 Hz"`` as a speed: pint would take it as 5 rad/s, not 5 rev/s), or an
      angle where the dimension has none (``"18 cm*rad"``, ``"5 N*m/rad"`` as a moment).

    >>> angle_factor("frequency", 1, "1400 rpm") == 1 / (2 * math.pi)
    True
    >>> angle_factor("moment", -1, "5 N*m/rad")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    govopt.units.UnitError: '5 N*m/rad' is per angle, and a moment has none; pint cannot ...
    """
    want = ANGLE_POWER.get(dimension, 0)
    if power == want:
        return 1.0
    if dimension == "frequency" and power == 1:
        return 1.0 / (2.0 * math.pi)
    name = dimension.replace("_", " ")
    example = _example(dimension)
    if dimension == "angular_velocity" and power == 0:
        read = "radians per time" if value is None else f"{value:g} rad/s"
        return _refuse(f"{text!r} names no angle: pint would read it as {read}; write "
                       "revolutions ('300 rpm', '5 rev/s') or radians ('31.4 rad/s')")
    if name == "dimensionless":
        name = "dimensionless number"
    if power == 0:
        read = "the number as radians" if want == 1 else "it per radian"
        return _refuse(f"{text!r} names no angle, which {_a(name)} needs: pint would read "
                       f"{read}; write the angle (e.g. '{example}')")
    what = ("has an angle in its unit" if power > 0 else "is per angle") if want == 0 \
        and abs(power) == 1 else \
        f"has an angle to the power {power:g}"
    has = "has none" if want == 0 else f"has it to the power {want:g}"
    return _refuse(f"{text!r} {what}, and {_a(name)} {has}; pint cannot tell an angle from a "
                   f"plain number, so govopt refuses rather than guess (expected e.g. "
                   f"'{example}')")


def _refuse(message: str):
    raise UnitError(message)


def _to_si(q, dimension: str, text: str) -> float:
    """The pint quantity ``q`` (``text`` as written) in the SI unit of ``dimension``, its angle
    read by :func:`angle_factor`."""
    import pint

    si = SI_UNITS[dimension]
    try:
        value = q.to(si).magnitude if si else q.to("").magnitude
    except OverflowError:  # an exact integer beyond floating point: '10**400 cm'
        raise UnitError(f"{text!r} is too large a number") from None
    except pint.DimensionalityError:
        raise UnitError(
            f"{text!r} is not {_a(dimension.replace('_', ' '))} "
            f"(it has dimension {q.dimensionality}; expected e.g. '{_example(dimension)}')"
        ) from None
    factor = angle_factor(dimension, angle_power(q), text, value)
    return value * factor if factor != 1.0 else value


def convert(magnitude: float, unit: str, si_unit: str) -> float:
    """``magnitude`` in ``unit`` (pint's syntax) in ``si_unit`` (one of :data:`SI_UNITS`), by
    the rule of :func:`angle_factor` (``convert(60, "rpm", "Hz") == 1.0``)."""
    dimension = {v: k for k, v in SI_UNITS.items()}[si_unit]
    q = registry().Quantity(float(magnitude), normalise(unit))
    return _finite(_to_si(q, dimension, f"{magnitude:g} {unit}"), f"{magnitude:g} {unit}",
                   si_unit)


def malformed(exc: Exception) -> str:
    """What is wrong with a quantity string pint's parser raised ``exc`` on, in words (not the
    exception's class: pint's parser raises an AssertionError on an operator with nothing after
    it, the tokenizer a TokenError on an unclosed bracket).

    >>> import tokenize
    >>> malformed(tokenize.TokenError("EOF in multi-line statement"))
    'its parentheses do not match'
    >>> malformed(AssertionError())
    'it is incomplete: an operator or bracket with nothing on one side'
    """
    import tokenize

    if isinstance(exc, tokenize.TokenError):
        return "its parentheses do not match"
    if isinstance(exc, AssertionError | IndexError):
        return "it is incomplete: an operator or bracket with nothing on one side"
    if isinstance(exc, ZeroDivisionError):
        return "it divides by zero"
    if isinstance(exc, UnicodeError):
        return "it holds bytes that are not UTF-8 text"
    return "it is not a number with units (e.g. '18 cm', '64 deg + 40 arcmin')"


def _a(noun: str) -> str:
    """``noun`` with its indefinite article: "an angle", "a length"."""
    return f"{'an' if noun[:1] in 'aeiou' else 'a'} {noun}"


#: A unit name followed by one digit, read as a power where the name with the digit is no unit
#: (``cm2`` -> ``cm^2``, ``s2`` -> ``s^2``); superscripts and the middle dot as pint's syntax.
_POWER = re.compile(r"(?<![\w.])([A-Za-z_]+)([2-9])(?![\w.])")
_SYMBOLS = str.maketrans({"\u00b7": "*", "\u22c5": "*", "\u00b2": "^2", "\u00b3": "^3"})


def normalise(text: str) -> str:
    """``text`` in pint's syntax: powers written as a trailing digit or a superscript, the
    middle dot as a product.

    >>> normalise("4000 kgf/cm2"), normalise("43 kgf\u00b7m\u00b7s\u00b2"), normalise("2 H2O")
    ('4000 kgf/cm^2', '43 kgf*m*s^2', '2 H2O')
    """
    def power(m: re.Match) -> str:
        unit, digit = m[1], m[2]
        return f"{unit}^{digit}" if unit + digit not in ureg and unit in ureg else m[0]

    ureg = registry()
    return _POWER.sub(power, text.translate(_SYMBOLS))


def _unknown(exc) -> str:
    """"unknown unit 'kfg' (did you mean 'kgf'?)" for pint's UndefinedUnitError."""
    names = exc.unit_names if isinstance(exc.unit_names, tuple | list) else (exc.unit_names,)
    unit = str(names[0]) if names else "?"
    close = difflib.get_close_matches(unit, sorted(registry()), n=1, cutoff=0.65)
    return f"unknown unit {unit!r}" + (f" (did you mean {close[0]!r}?)" if close else "")


#: Tokens a quantity may contain besides numbers and names (pint reads others leniently:
#: ``"=18 cm"`` as 18 cm, ``"18 cm;3"`` as 54 cm).
_OPERATORS = {"+", "-", "*", "/", "**", "^", "(", ")"}
_SKIP = {tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER}


def strict_units(text: str, shown: str | None = None) -> bool:
    """Reject what pint would silently reinterpret; return whether ``text`` carries a unit.

    * only numbers, unit names, ``+ - * / ** ^`` and parentheses (``"=18 cm"``, ``"18 cm;3"``,
      ``"18 cm # x"`` are errors, not 18 cm and 54 cm);
    * a number right after a number, a name or ``)`` with no operator (``"18 cm 3"``: pint
      multiplies);
    * a sum or difference of a unit-less number and a quantity: ``"64 deg + 0.01"`` (pint adds
      0.01 *radians*, since an angle is dimensionless to it).

    Messages quote ``shown`` (the text as typed, before :func:`normalise`), else ``text``.

    >>> strict_units("64 deg + 40 arcmin"), strict_units("(64 + 0.5) deg"), strict_units("0.12")
    (True, True, False)
    >>> strict_units("64 deg + 0.01")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    govopt.units.UnitError: '64 deg + 0.01': the number 0.01 has no unit ...
    """
    from pint import pint_eval
    from pint.util import string_preprocessor

    shown = text if shown is None else shown
    previous = None
    for tok in pint_eval.tokenizer(text):
        if tok.type in _SKIP:
            continue
        if tok.type == tokenize.NUMBER and previous is not None and (
                previous.type in (tokenize.NUMBER, tokenize.NAME) or previous.string == ")"):
            raise UnitError(f"{shown!r}: the number {tok.string} follows {previous.string!r} "
                            f"with no operator")
        if tok.type not in (tokenize.NUMBER, tokenize.NAME) and tok.string not in _OPERATORS:
            raise UnitError(f"{shown!r}: unexpected {tok.string!r} (expected a quantity such as "
                            f"'18 cm' or '64 deg + 40 arcmin')")
        previous = tok
    tree = pint_eval.build_eval_tree(pint_eval.tokenizer(string_preprocessor(text)))
    return _has_unit(tree, shown)


def _has_unit(node, text: str) -> bool:
    """Whether an eval-tree node carries a unit; raises on a unit-less term in a sum."""
    if node.right is None and node.operator is None:  # a number or a name
        tok = node.left
        return tok.type == tokenize.NAME and not registry().Quantity(tok.string).unitless
    if node.right is None:  # unary operator
        if node.operator.string not in ("+", "-"):
            raise UnitError(f"{text!r}: unexpected {node.operator.string!r} before "
                            f"{node.left.to_string()}")
        return _has_unit(node.left, text)
    op = node.operator.string if node.operator else "*"
    if op == "**":
        _check_power(node, text)
    left, right = _has_unit(node.left, text), _has_unit(node.right, text)
    if op in ("+", "-") and left != right:
        bare = (node.right if left else node.left).to_string()
        raise UnitError(f"{text!r}: the number {bare} has no unit (pint would take it as "
                        f"dimensionless, i.e. radians in an angle); give every term its unit")
    return left or right if op in ("*", "/") else left


def _check_power(node, text: str) -> None:
    """A power's exponent is a plain number of magnitude at most
    :data:`govopt.limits.MAX_EXPONENT` and its base holds no power: Python's integers are exact,
    so ``9**9**9`` or ``((10**30)**30)**30`` would take minutes and gigabytes, before any
    check of the result.

    >>> strict_units("9**9**9 cm")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    govopt.units.UnitError: '9**9**9 cm': the exponent (9 ** 9) is not a plain number ...
    """
    exp = node.right
    if exp.right is None and exp.operator is not None and exp.operator.string in ("+", "-"):
        exp = exp.left  # a sign
    if exp.right is not None or exp.operator is not None or exp.left.type != tokenize.NUMBER:
        raise UnitError(f"{text!r}: the exponent {node.right.to_string()} is not a plain number "
                        "(write e.g. 'cm^2' or '2.1*10^11 Pa')")
    if abs(float(exp.left.string)) > MAX_EXPONENT:
        raise UnitError(f"{text!r}: an exponent of magnitude at most {MAX_EXPONENT} (govopt's "
                        f"limit), got {exp.left.string}")
    if "**" in node.left.to_string():
        raise UnitError(f"{text!r}: a power of a power ({node.left.to_string()}) is not "
                        "allowed")


def _finite(value, text, unit: str = "") -> float:
    """``value`` as a float, finite and within govopt's range (:mod:`govopt.limits`)."""
    try:
        value = float(value)
    except OverflowError:  # an exact integer beyond floating point
        raise UnitError(f"{shorten(text)} is too large a number") from None
    if not math.isfinite(value):
        raise UnitError(f"{text!r} is not a finite number")
    problem = magnitude_error(value, unit)
    if problem:
        raise UnitError(f"{shorten(text)} {problem}")
    return value


def _example(dimension: str) -> str:
    return {
        "length": "18 cm",
        "angle": "64 deg + 40 arcmin",
        "force": "16 kgf",
        "mass": "12 kg",
        "stress": "4000 kgf/cm^2",
        "angular_velocity": "240 rpm",
        "moment": "22.6 kgf*cm",
        "inertia": "43 kgf*m*s^2",
        "torque_per_angle": "-300 kgf*m/rad",
        "torque_per_length": "-50 kgf*m/cm",
        "linear_damping": "0.5 kgf*s/cm",
        "density": "7850 kg/m^3",
        "damping": "72 kgf*cm*s/rad",
        "time": "0.5 s",
        "frequency": "20 Hz",
        "stiffness": "59.7 kgf/cm",
        "dimensionless": "0.12",
    }[dimension]


def to_unit(value_si: float, dimension: str, unit: str) -> float:
    """Convert an SI value of ``dimension`` into ``unit`` (for reports), the angle by the rule
    of :func:`angle_factor` (a frequency in ``rpm``: revolutions per minute)."""
    one = registry().Quantity(1.0, unit)
    factor = angle_factor(dimension, angle_power(one), unit)
    return registry().Quantity(value_si / factor, SI_UNITS[dimension]).to(unit).magnitude
