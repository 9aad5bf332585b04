"""The JSON Schema of a spec file, governor or spring, generated from the key declarations
(:mod:`govopt.keys`; :func:`govopt.spec_keys.spec_tables`, :mod:`govopt.spring_keys`): ``govopt
schema`` writes it for TOML editors (Even Better TOML / taplo: completion, hover text and
checking as the file is typed).

Draft-07. A file with ``[governor]`` is a governor spec, any other a spring spec (the command
that reads each refuses the other's keys). The governor branch names the governor types; for
each type an ``if``/``then`` pair closes every table to the type's declared keys (a misspelt key
is an error, as in the parser); the spring branch closes ``[spring]`` to the keys of its form
(:func:`spring_schema`). Quantities must be strings with a unit (a bare number, or a string of
digits, is not a length) of their dimension (:func:`dimension_pattern`: a number and one unit
word govopt reads as that dimension; a unit written as an expression is left to the parser),
choices are enumerations and static ranges are limits. Which keys a spec needs is said as the
parser reads it: required keys, alternatives (``oneOf``: :attr:`govopt.keys.Table.alternatives`),
a table required unless another is there, a table read with another, the material's values its
spring needs. What only the parser can check stays the parser's: the order of a bound's ends
and ranges that depend on other keys (JSON Schema compares no two values), a unit expression's
dimension, and the limits of govopt's work.
"""

from __future__ import annotations

import functools
import json
import math
import re
from pathlib import Path

from .keys import WEIGHT, Key, Table
from .spec_docs import describe

#: a string with a unit: a letter that is not an exponent's ``e``, or a degree, minute or
#: second sign (no look-ahead, which taplo's regular expressions lack)
UNIT_PATTERN = "[A-DF-Za-df-z_°µ'\"%]"
#: the unit words of each dimension, as govopt reads them (:func:`unit_words`, generated:
#: ``python -m govopt.spec_schema --words``; a test fails when it is stale)
WORDS = Path(__file__).parent / "data" / "unit_words.json"
#: SI prefixes, symbols and names (pint reads each before any unit: ``mm``, ``kN``, ``MPa``)
PREFIXES = ("Y", "Z", "E", "P", "T", "G", "M", "k", "h", "da", "d", "c", "m", "µ", "u", "n", "p",
            "f", "a", "yotta", "zetta", "exa", "peta", "tera", "giga", "mega", "kilo", "hecto",
            "deca", "deka", "deci", "centi", "milli", "micro", "nano", "pico", "femto", "atto")
_NUMBER = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"


def unit_words() -> dict[str, list[str]]:
    """Each dimension's single unit words (names and symbols of pint's registry) that govopt's
    own parser reads as a quantity of it (``1 WORD``): ``rpm`` an angular velocity, ``Hz`` not
    (:func:`govopt.units.parse_quantity`). Slow (every unit of the registry, tried in every
    dimension): :data:`WORDS` keeps what it gives."""
    from .units import SI_UNITS, UnitError, parse_quantity, registry

    ureg = registry()
    found: dict[str, set] = {d: set() for d, si in SI_UNITS.items() if si}
    for name in ureg:
        try:
            words = {name, ureg.get_symbol(name)}
        except Exception:  # noqa: BLE001 - a registry entry that is no unit
            continue
        for word in words:
            for dimension, got in found.items():
                try:
                    parse_quantity(f"1 {word}", dimension)
                except (UnitError, ValueError):
                    continue
                got.add(word)
    return {d: sorted(w) for d, w in found.items()}


@functools.cache
def saved_words() -> dict[str, list[str]]:
    """The unit words of each dimension as saved in :data:`WORDS` (govopt/data/unit_words.json,
    written by ``--words`` from :func:`unit_words`), read once."""
    return json.loads(WORDS.read_text(encoding="utf-8"))


def dimension_pattern(dimension: str) -> str | None:
    """A quantity string of ``dimension`` as far as a pattern can say it: a number and one
    unit word of the dimension (an SI prefix allowed, a plural ``s``), or a unit written as an
    expression (a product, quotient, power or sum: the parser alone reads its dimension);
    only an expression where the dimension has no single unit word (an inertia, a damping).
    None for a dimension without units."""
    if dimension not in saved_words():
        return None
    expression = r".*[*/^()+·²³].*|.*\s-\s.*|.*[A-DF-Za-df-z][0-9].*"
    words = saved_words()[dimension]
    if not words:
        return rf"^(?:{expression})$"
    alt = "|".join(re.escape(w) for w in sorted(words, key=len, reverse=True))
    prefixes = "|".join(sorted(PREFIXES, key=len, reverse=True))
    return rf"^(?:{expression}|\s*{_NUMBER}\s*(?:{prefixes})?(?:{alt})(?:e?s)?\s*)$"


def _limits(key: Key) -> dict:
    """JSON Schema limits of a bare number from the declaration's static range (the reader's:
    exclusive ``low`` and ``high`` unless ``high_inclusive``, and positive or not negative)."""
    out = {}
    if key.nonnegative:
        out["minimum"] = 0
    elif key.positive:
        out["exclusiveMinimum"] = 0
    lo = None if callable(key.low) else key.low
    hi = None if callable(key.high) else key.high
    if lo is not None and math.isfinite(lo):
        out["exclusiveMinimum"] = max(lo, out.get("exclusiveMinimum", lo))
    if hi is not None and math.isfinite(hi):
        out["maximum" if key.high_inclusive else "exclusiveMaximum"] = hi
    return out


def _value(key: Key, dimension: str | None) -> dict:
    """The schema of one value of ``key`` (a quantity of ``dimension``, or its kind's)."""
    kind = key.kind
    if kind == "choice":
        return {"enum": list(key.options())}
    if kind == "text":
        return {"type": "string"}
    if kind == "flag":
        return {"type": "boolean"}
    if kind == "table":
        return {"type": "object"}
    if dimension is None or dimension == "dimensionless":
        return {"type": "integer" if kind == "count" else "number", **_limits(key)}
    if dimension_pattern(dimension) is None:
        return {"type": "string", "pattern": UNIT_PATTERN}
    return {"type": "string", "pattern": UNIT_PATTERN,
            "allOf": [{"$ref": f"#/definitions/{dimension}"}]}


def _key_schema(key: Key, name: str) -> dict:
    dimension = ("force" if name.endswith("_weight") else "mass") if key.kind == WEIGHT \
        else key.dimension
    one = _value(key, dimension)
    if key.shape == "pair":
        pair = {"type": "array", "items": one, "minItems": 2, "maxItems": 2}
        schema = {"anyOf": [one, pair]} if key.single else pair
    elif key.shape == "list":
        schema = {"type": "array", "items": one, "minItems": 1}
    else:
        schema = one
    extra = key.options() if key.kind != "choice" else ()
    if extra:
        schema = {"anyOf": [schema, {"enum": list(extra)}]}
    out = {"description": describe(key), **schema}
    default = key.default
    if key.kind in ("choice", "flag", "count", "number") and key.shape == "scalar" \
            and isinstance(default, bool | int | float | str) and not callable(default):
        out["default"] = default
    return out


def table_schema(table: Table, tables: dict[str, Table]) -> dict:
    """The schema of one table: its declared keys only (a sub-table by its own schema)."""
    props, required, rules = {}, [], []
    for key in table.keys:
        for name in key.names:
            sub = tables.get(f"{table.name}.{name}" if table.name else name)
            if key.kind == "table" and sub is not None:
                schema = table_schema(sub, tables)
                props[name] = ({"type": "array", "items": schema, "description": sub.meaning}
                               if sub.array else schema)
            elif key.kind == "table" and not table.name:  # an open table (a study's)
                props[name] = {"type": "object", "description": key.meaning}
            else:
                props[name] = _key_schema(key, name)
        if key.required and not key.when:
            if key.kind == WEIGHT:
                rules.append({"anyOf": [{"required": [n]} for n in key.names]})
            else:
                required.append(key.name)
        if key.kind == WEIGHT:  # one spelling, not both
            rules.append({"not": {"required": list(key.names)}})
        sub = tables.get(key.name) if not table.name else None
        if sub is not None and sub.required_unless:  # [speed] unless only a [design] is read
            rules.append({"if": {"not": {"required": [sub.required_unless]}},
                          "then": {"required": [key.name]}})
        if sub is not None and sub.needs:  # [[load_change]] with [engine]
            rules.append({"if": {"required": [key.name]}, "then": {"required": list(sub.needs)}})
    rules += [alternatives(choice) for choice in table.alternatives]
    out = {"type": "object", "description": table.meaning, "properties": props,
           "additionalProperties": False}
    if table.open:
        out = {"type": "object", "description": table.meaning}
    if required:
        out["required"] = required
    if rules:
        out["allOf"] = rules
    return out


def alternatives(choice: tuple) -> dict:
    """``oneOf`` the groups of a choice (:attr:`govopt.keys.Table.alternatives`): every
    required key of one group, and no key of the others.

    >>> alternatives(((("a",), ("b", "c?"))))["oneOf"][1]
    {'required': ['b'], 'not': {'anyOf': [{'required': ['a']}]}}
    """
    groups = [[n.rstrip("?") for n in group] for group in choice]
    return {"oneOf": [
        {"required": [n for n in group if not n.endswith("?")],
         "not": {"anyOf": [{"required": [n]} for j, other in enumerate(groups) if j != i
                           for n in other]}}
        for i, group in enumerate(choice)]}


def material_rules(helical: bool) -> dict:
    """What ``[material]`` must give, as the parser reads it (:func:`govopt.spec._material`):
    a helical spring's shear values unless a wire grade gives them, a leaf's modulus."""
    if not helical:
        return {"required": ["elastic_modulus"]}
    return {"if": {"not": {"required": ["grade"]}},
            "then": {"required": ["allowable_shear_stress", "shear_modulus"]}}


def governor_schema() -> dict:
    """The schema of a governor spec file: the governor types named, every type's tables closed
    to their declared keys."""
    from .governors import REGISTRY, governor_class
    from .spec_keys import spec_tables

    branches = []
    for name in REGISTRY:
        tables = spec_tables(name)
        then = {**table_schema(tables[""], tables),
                "description": f"{governor_class(name).title}"}
        kind = governor_class(name).declared_spring_kind()
        material = then["properties"]["material"]
        material["allOf"] = [*material.get("allOf", []),
                             material_rules(kind is None or kind.helical)]
        branches.append({
            "if": {"properties": {"governor": {"properties": {"type": {"const": name}},
                                               "required": ["type"]}},
                   "required": ["governor"]},
            "then": then})
    return {
        "description": "a governor spec: the governor, the speeds, the spring's material, a "
                       "design to evaluate or the requirements of one to find",
        "properties": {"governor": {
            "type": "object", "description": "the governor: its type and geometry",
            "properties": {"type": {"enum": list(REGISTRY),
                                    "description": "the governor type: its own keys follow"}},
            "required": ["type"]}},
        "required": ["governor"],
        "allOf": branches,
    }


def spring_schema() -> dict:
    """The schema of a spring spec file (`govopt spring`, `govopt spring check`): its
    ``[spring]`` closed to the keys of its form, told apart as the parser tells them
    (:func:`govopt.spring_keys.form`): ``problem`` names a problem of the literature, a
    spring's geometry makes a spring to check, anything else is a spring to design."""
    from .spring_keys import FORMS, GEOMETRY, PROBLEMS, tables

    def closed(name: str) -> dict:
        found = tables(name)
        return {**table_schema(found[""], found), "description": found["spring"].meaning}

    has = {"problem": {"properties": {"spring": {"required": ["problem"]}}},
           "geometry": {"properties": {"spring": {"anyOf": [{"required": [k.name]}
                                                            for k in GEOMETRY]}}}}
    assert set(FORMS) == {"design", "check", *PROBLEMS}
    return {
        "description": "a spring spec: a spring to design (govopt spring), a problem of the "
                       "literature, or a spring you have (govopt spring check)",
        "required": ["spring"],
        "if": has["problem"], "then": closed(PROBLEMS[0]),
        "else": {"if": has["geometry"], "then": closed("check"), "else": closed("design")},
    }


def schema() -> dict:
    """The JSON Schema (draft-07) of a spec file: a governor spec where it has ``[governor]``,
    else a spring spec (a governor spec's ``[spring]`` is its spring's form, so ``[spring]``
    cannot tell the two apart; ``if``/``then``/``else`` gives an editor the one kind's
    messages, where ``oneOf`` would report every kind's)."""
    return {
        "$schema": "http://json-schema.org/draft-07/schema#",
        "title": "govopt spec",
        "description": "A govopt spec file (TOML with units): a governor spec ([governor]: "
                       "docs/reference/spec.md lists every key) or a spring spec ([spring] "
                       "without [governor], for govopt spring: docs/reference/spring-spec.md).",
        "type": "object",
        "properties": {
            "name": {"type": "string", "description": "the spec's name in reports"},
            "description": {"type": "string",
                            "description": "one line saying what the spec is"},
            "governor": {"type": "object", "description": "a governor spec's governor: its "
                                                          "type and geometry"},
            "spring": {"type": "object", "description": "a spring spec's spring (govopt "
                                                        "spring), or a governor's spring form"}},
        "if": {"required": ["governor"]},
        "then": governor_schema(),
        "else": spring_schema(),
        "definitions": {d: {"description": f"a quantity of {d.replace('_', ' ')}: a number and "
                                           "its unit",
                            "type": "string", "pattern": dimension_pattern(d)}
                        for d in saved_words() if dimension_pattern(d) is not None},
    }


def text() -> str:
    """:func:`schema` as JSON text (indented, keys in declared order)."""
    return json.dumps(schema(), indent=2, ensure_ascii=False) + "\n"


if __name__ == "__main__":  # python -m govopt.spec_schema --words: regenerate WORDS
    import sys

    if sys.argv[1:] != ["--words"]:
        raise SystemExit("usage: python -m govopt.spec_schema --words")
    WORDS.write_text(json.dumps(unit_words(), indent=1, ensure_ascii=False) + "\n",
                     encoding="utf-8")
    print(f"wrote {WORDS}")
