"""A corpus of hostile inputs for the CLI, and its runner.

:func:`corpus` mutates every bundled spec key by key (missing, wrong type, wrong dimension, a
bare number, negative, zero, huge and tiny magnitudes, NaN and infinities, 200 kB strings,
``9**9**9``, control characters, unknown and misspelt keys, empty tables, arrays where scalars
belong, grids and lists past the limits of :mod:`govopt.limits` ...), adds hostile files (not
UTF-8, deeply nested, a device, a folder) and hostile options of ``govopt spring``, and runs
each case in-process through the CLI (:func:`run`) under a time limit. :func:`classify` sorts
the outcomes:

* ``ok``: exit 0 or 1 with a result on stdout (JSON that parses, with ``--json``);
* ``error``: exit 2 and one line ``error: FILE: KEY: ...`` (or ``--option: ...``, or a
  design's diagnosis ``error: FILE: infeasible: ...``) of at most :data:`MAX_LINE` characters
  besides the path (:data:`MAX_DIAGNOSIS` for a diagnosis), no traceback;
* ``unclear``: exit 2, but more than one line, too long, naming neither file nor key, naming
  an exception's class instead of what went wrong, or a diagnosis that says nothing (a
  requirement "conflicting" with itself);
* ``traceback``: anything else (exit 3 too: a user's mistake is not an internal error);
* ``hang``: the time limit ran out;
* ``silent``: ``ok`` on an input that is nonsense (:attr:`Case.nonsense`).
"""

from __future__ import annotations

import copy
import json
import math
import os
import re
import signal
import sys
import time
import tomllib
import warnings
import zlib
from collections.abc import Iterator
from dataclasses import dataclass, field
from functools import cache, partial
from pathlib import Path

import forkcli
from clirun import invoke

ROOT = Path(__file__).resolve().parent.parent
#: longest acceptable error line, besides the spec's path (the user's): an input's error, and
#: a design's diagnosis (which says how far each requirement would have to move)
MAX_LINE, MAX_DIAGNOSIS = 300, 600


def bundled_specs() -> list[Path]:
    """The bundled specs (``specs/`` of the checkout)."""
    found = sorted((ROOT / "specs").glob("*.toml"))
    if not found:
        raise FileNotFoundError("no bundled specs found")
    return found


# ---------------------------------------------------------------------------------------------
# TOML out (with raw tokens such as a 400-digit integer or nan)


@dataclass(frozen=True)
class Raw:
    """A TOML value written as is."""

    text: str


_BARE = re.compile(r"[A-Za-z0-9_-]+")
#: a long string TOML can hold as a literal string ('...'): the same value once read, which
#: tomllib finds with one search where a basic string ("...") costs it a Python loop per
#: character (40 ms for 200 kB: a third of the corpus's time went there)
_LITERAL = re.compile(r"[^'\x00-\x1f\x7f]*")


def _key(k) -> str:
    return k if _BARE.fullmatch(str(k)) else json.dumps(str(k))


def _value(v) -> str:
    if isinstance(v, Raw):
        return v.text
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if v != v else "inf" if v == math.inf else "-inf" if v == -math.inf \
            else repr(v)
    if isinstance(v, str):
        if len(v) > 1000 and _LITERAL.fullmatch(v):
            return f"'{v}'"
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def _is_tables(v) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def to_toml(data: dict, prefix: str = "") -> str:
    """``data`` as TOML text (tables as headers, arrays of tables as ``[[...]]``)."""
    lines = [f"{_key(k)} = {_value(v)}" for k, v in data.items()
             if not isinstance(v, dict) and not _is_tables(v)]
    out = "\n".join(lines) + ("\n" if lines else "")
    for k, v in data.items():
        name = f"{prefix}.{_key(k)}" if prefix else _key(k)
        if isinstance(v, dict):
            out += f"\n[{name}]\n" + to_toml(v, name)
        elif _is_tables(v):
            for item in v:
                out += f"\n[[{name}]]\n" + to_toml(item, name)
    return out


# ---------------------------------------------------------------------------------------------
# Cases


@dataclass(frozen=True)
class Case:
    """One hostile input: CLI ``args`` (``{spec}`` stands for the spec file written from
    ``text``), the mutation ``kind``, the ``key`` it touched and whether it is ``nonsense``
    (exit 0 on it is a silent result)."""

    id: str
    args: tuple[str, ...]
    make: object  # () -> the spec's text (str or bytes), or None: no spec file
    kind: str
    key: str | None
    nonsense: bool
    command: str = "evaluate"
    names_key: bool = True  # the error line must name the file and a key
    gtype: str = ""  # the governor type of the spec mutated
    prepare: object = None  # (spec path) -> None: files the case needs besides the spec


#: mutations whose input is nonsense wherever they apply: accepting one is a silent result
NONSENSE = {
    "wrong_dimension", "bare_number", "bare_number_string", "huge", "huge_int", "tiny",
    "nan", "inf", "neg_inf", "long_sum", "long_digits", "deep_parens", "power_tower",
    "big_exponent", "control_quantity", "unknown_unit", "garbage", "empty_string", "blank",
    "wrong_type", "table_for_scalar", "array_for_scalar", "string_for_number", "unknown_key",
    "misspelt", "bogus_choice", "empty_list", "nested_list", "long_list", "table_as_string",
    "unknown_table", "size_limit", "file", "incomplete", "unbalanced", "divide_by_zero",
    "angle_in_unit", "not_utf8", "band_narrow",
}
#: keys (by name) where a negative value means something: accepting one is right
SIGNED = {
    # Hamabe Part III: the speed fluctuation's Fourier coefficients take either sign
    "speed_fluctuation_E2": "a Fourier coefficient",
    "speed_fluctuation_F2": "a Fourier coefficient",
    # Hamabe eqs. 7-8: forces along the cylinder axis, the sign their direction
    "steam_load": "a force along the cylinder axis, its sign the direction",
    "weight": "the valve gear's weight along the cylinder axis, its sign the direction",
    # the Porter's e_u, e_s: negative across the axis (govopt/governors/porter.py)
    "pivot_offset": "across the axis when negative",
    "sleeve_offset": "across the axis when negative",
}
#: keys (by name) where zero means something (none of it): accepting it is right
ZERO_OK = {
    **SIGNED,
    "offset": "no eccentric offset", "friction": "no valve friction",
    "sleeve_friction": "no sleeve friction", "rod_friction": "no rod friction",
    "friction_moment": "no friction at the fulcrum", "insensibility": "none",
    "dashpot_f": "no dash-pot", "dashpot_a1": "no dash-pot",
    "central_weight": "no central load", "central_mass": "no central load",
    "hinge_radius": "hinges on the axis", "hurwitz_margin": "eq. (32) itself",
    "k2_margin": "k^2 within (0, omega0^2) itself", "surge_detuning": "no detuning asked",
    "overtravel": "none", "inactive_turns": "none", "initial_tension": "none",
    "extension_angle": "no extension", "ball_spring_tension": "unloaded at radius_inner",
    "robust_dashpot": "no tolerance", "robust_masses": "no tolerance",
    "robust_torque_slope": "no tolerance", "adjusting_nut": "not adjusted",
    "dashpot_valve": "not adjusted",
}


#: lists that may be empty: none of it
EMPTY_OK = {"pareto": "no Pareto front"}


def nonsense(kind: str, key: str | None) -> bool:
    """Whether accepting mutation ``kind`` of ``key`` would be a silent result."""
    name = str(key).split(".")[-1].split("[")[0]
    return (kind in NONSENSE and not (kind == "empty_list" and name in EMPTY_OK)) or (
        kind == "negative" and name not in SIGNED) or (kind == "zero" and name not in ZERO_OK)


_TEXT_KEYS = {"name", "description"}
TINY, HUGE = "1e-300", "1e300"
LONG = 200_000  # characters of a "200 kB" string


def _registry():
    from govopt.units import normalise, registry

    return registry(), normalise


def _quantity(text: str):
    """``(magnitude, unit text, is length, SI value of one unit)`` of a quantity string (one
    starting with a number: not a choice such as ``type = "watt"``), else None."""
    if not isinstance(text, str) or not text.lstrip("-+(")[:1].isdigit():
        return None
    ureg, normalise = _registry()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            q = ureg.Quantity(normalise(text))
    except Exception:
        return None
    if not hasattr(q, "units") or q.unitless:
        return None
    si = float(ureg.Quantity(1.0, q.units).to_base_units().magnitude)
    return (float(q.magnitude), f"{q.units:~}", q.dimensionality == ureg.meter.dimensionality,
            si)


def _leaf_mutations(value, key: str) -> Iterator[tuple[str, object]]:
    """``(kind, new value)`` for one leaf value under ``key`` (dotted, last part the name)."""
    name = key.rsplit(".", 1)[-1].split("[")[0]
    q = _quantity(value)
    if isinstance(value, bool):
        yield "wrong_type", "yes"
        yield "string_for_number", 1
        yield "array_for_scalar", [value, value]
        return
    if isinstance(value, int | float):
        v = float(value)
        yield "negative", -v if v else -1
        yield "zero", 0
        yield "huge", 1e300
        yield "huge_int", Raw("1" + "0" * 400)
        yield "tiny", 1e-300
        yield "nan", math.nan
        yield "inf", math.inf
        yield "neg_inf", -math.inf
        yield "string_for_number", "many"
        yield "wrong_type", f"{value} cm"
        yield "fraction", v + 0.5
        yield "array_for_scalar", [value, value]
        yield "table_for_scalar", {"value": value}
        return
    if q is not None:
        mag, unit, is_length, si = q
        sign = -1.0 if mag < 0 else 1.0
        # within govopt's limits (govopt.limits), at their edges: no hang, no traceback
        yield "edge_large", f"{sign * 5e11 / si:.6g} {unit}"
        yield "edge_small", f"{sign * 2e-12 / si:.6g} {unit}"
        yield "wrong_dimension", f"5 {'s' if is_length else 'cm'}"
        yield "bare_number", mag
        yield "bare_number_string", f"{mag:g}"
        yield "negative", f"{-mag if mag else -1:g} {unit}"
        yield "zero", f"0 {unit}"
        yield "huge", f"{HUGE} {unit}"
        yield "huge_int", f"10**400 {unit}"
        yield "tiny", f"{TINY} {unit}"
        yield "nan", f"nan {unit}"
        yield "inf", f"inf {unit}"
        yield "long_sum", " + ".join([f"{mag:g} {unit}"] * (LONG // (len(unit) + 12)))
        yield "long_digits", "1" * LONG + f" {unit}"
        yield "deep_parens", "(" * 3000 + f"{mag:g}" + ")" * 3000 + f" {unit}"
        yield "power_tower", f"9**9**9 {unit}"
        yield "big_exponent", f"2**100000 {unit}"
        yield "control_quantity", f"{mag:g}\x00\x1b[2J {unit}"
        yield "unknown_unit", f"{mag:g} blorps"
        # what pint's parser raises on (say what is wrong, never the exception's class)
        yield "incomplete", f"{mag:g} {unit} /"
        yield "unbalanced", f"({mag:g} {unit}"
        yield "divide_by_zero", f"{mag:g} {unit} / 0"
        # an angle the dimension has not: pint takes the radian for 1 and would not say
        yield "angle_in_unit", f"{mag:g} {unit}*rad^2"
        yield "garbage", f"{mag:g} {unit}; rm -rf /"
        yield "empty_string", ""
        yield "blank", "   "
        yield "wrong_type", True
        yield "array_for_scalar", [value, value]
        yield "table_for_scalar", {"value": value}
        return
    if isinstance(value, str):  # a choice or free text
        text = name in _TEXT_KEYS
        yield ("text" if text else "bogus_choice"), "bogus"
        yield ("text" if text else "empty_string"), ""
        yield ("text_control" if text else "bogus_choice"), "\x07bell\x1b[31m\x00"
        yield ("text_long" if text else "bogus_choice"), "x" * LONG
        yield "wrong_type", 5
        yield "array_for_scalar", [value]
        return


def _list_mutations(value: list) -> Iterator[tuple[str, object]]:
    yield "empty_list", []
    yield "scalar_for_list", value[0]
    yield "three_elements", value + value[:1]
    yield "nested_list", [value]
    yield "long_list", value[:1] * 2000  # past govopt.limits.MAX_LIST_ITEMS, within 1 MiB
    yield "table_for_scalar", {"low": value[0]}


def _walk(node, path: tuple) -> Iterator[tuple[tuple, object]]:
    """Every (path, value) under ``node``, tables and lists included."""
    yield path, node
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _walk(v, (*path, k))
    elif isinstance(node, list):
        for i, v in enumerate(node[:2]):  # the first two items stand for the rest
            yield from _walk(v, (*path, i))


def _dotted(path: tuple) -> str:
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out


def _set(data, path: tuple, value):
    """A copy of ``data`` with ``path`` set to ``value`` (deleted, or its key renamed)."""
    data = copy.deepcopy(data)
    node = data
    for p in path[:-1]:
        node = node[p]
    if value is _DELETE:
        del node[path[-1]]
    elif isinstance(value, _Rename):
        items = list(node.items())
        node.clear()
        node.update((value.to if k == path[-1] else k, v) for k, v in items)
    else:
        node[path[-1]] = value
    return data


_DELETE = object()


@dataclass(frozen=True)
class _Rename:
    to: str


def _misspell(name: str) -> str:
    """A near miss: two letters swapped (or a letter doubled)."""
    if len(name) >= 4:
        i = len(name) // 2
        swapped = name[:i - 1] + name[i] + name[i - 1] + name[i + 1:]
        if swapped != name:
            return swapped
    return name + name[-1]


def _spec_mutations(data: dict) -> Iterator[tuple[str, str, object]]:
    """``(kind, dotted key, a function returning the mutated data)`` for one spec's data."""
    for path, value in _walk(data, ()):
        if not path:
            continue
        key = _dotted(path)
        parent_is_list = isinstance(path[-1], int)
        if not parent_is_list:
            yield "missing", key, partial(_set, data, path, _DELETE)
            yield "misspelt", key, partial(_set, data, path, _Rename(_misspell(str(path[-1]))))
        if isinstance(value, dict):
            yield "empty_table", key, partial(_set, data, path, {})
            yield "unknown_key", key, partial(_set, data, (*path, "bogus_key"), "1 cm")
            yield "table_as_string", key, partial(_set, data, path, "x")
            continue
        if _is_tables(value):
            yield "no_tables", key, partial(_set, data, path, [])
            yield "table_as_string", key, partial(_set, data, path, value[0])
            continue
        if isinstance(value, list):
            for kind, new in _list_mutations(value):
                yield kind, key, partial(_set, data, path, new)
            continue
        for kind, new in _leaf_mutations(value, key):
            yield kind, key, partial(_set, data, path, new)
    yield "unknown_table", "extras", lambda: {**data, "extras": {"x": 1}}


def _size_mutations(data: dict) -> Iterator[tuple[str, str, object]]:
    """Sizes past the limits: grid points, harmonics, load changes, catalogue lists and
    steps, design bounds; as :func:`_spec_mutations`."""
    def table(name: str, **changes):
        return lambda: {**data, name: {**data.get(name, {}), **changes}}

    yield "size_limit", "analysis.points", table("analysis", points=100_000)
    yield "size_limit", "analysis.harmonics", table("analysis", harmonics=1000)
    if data.get("load_change"):
        yield "size_limit", "load_change", lambda: {**data,
                                                    "load_change": data["load_change"] * 200}
    if "requirements" not in data and "bounds" not in data:
        return
    req = data.get("requirements", {})
    if any(k.startswith("robust_") and k not in ("robust_samples", "robust_seed")
           or k == "min_yield" for k in req):  # a robust design (the fitter's keys alone: none)
        # the robust design's work past its limits, counted at each evaluation's cost: the
        # most samples with a forced vibration solved for each, and every tolerance at every
        # setting of both the fitter's adjustments
        yield "size_limit", "requirements.robust_samples", table(
            "requirements", robust_samples=100_000, max_vibration="25 deg")
        yield "size_limit", "requirements", table(
            "requirements", robust_masses=0.02, robust_torque_slope=0.1,
            robust_spring_grade=2, adjusting_nut="2 mm", dashpot_valve=0.2,
            robust_dashpot=0.1, max_vibration="25 deg")
    yield "size_limit", "analysis.harmonics", lambda: {
        **table("analysis", harmonics=1000)(), "requirements": {
            **data.get("requirements", {}), "objective": "vibration"}}
    bounds = data.get("bounds", {})
    if "wire_diameter" in bounds:
        for key, value in (("turn_step", 1e-9), ("coil_radius_step", "1e-9 mm"),
                           ("wire_diameters", [f"{1 + i * 1e-3:.3f} mm"
                                               for i in range(1500)])):
            yield "size_limit", f"catalogue.{key}", table("catalogue", **{key: value})
        for key, value in (("active_turns", [3, 1e9]), ("coil_radius", ["1 cm", "1e9 cm"])):
            yield "size_limit", f"bounds.{key}", table("bounds", **{key: value})
    mass = next((k for k in bounds if k.endswith(("_weight", "_mass"))
                 and not k.startswith("central")), None)
    if mass is not None:
        unit = "kgf" if mass.endswith("_weight") else "kg"
        yield "size_limit", "catalogue.weight_step", table("catalogue", weight_step="1e-9 kgf")
        yield "size_limit", f"bounds.{mass}", table("bounds", **{mass: [f"1 {unit}",
                                                                       f"1e9 {unit}"]})


#: the spec is a FIFO (nothing ever writes to it)
FIFO = object()


def _file_cases() -> Iterator[Case]:
    """Hostile files rather than hostile values."""
    spec = next(p for p in bundled_specs() if p.stem == "hamabe-a-si").read_text()
    files = {
        "empty file": b"",
        "not UTF-8": spec.encode().replace(b"name", b"n\xe9me", 1),
        "UTF-16": spec.encode("utf-16"),
        "binary": bytes(range(256)) * 8,
        "deep arrays": b"a = " + b"[" * 5000 + b"]" * 5000,
        "deep tables": b"a = " + b"{b = " * 3000 + b"1" + b"}" * 3000,
        "larger than 1 MiB": b"#" * (1 << 20) + b"\nname = 'x'\n",
        "malformed TOML": spec.encode() + b"\n[speed\n",
        "TOML array at top": b"governor = [1, 2]\n",
        "400-digit integer": spec.encode().replace(b"irregularity = 0.12",
                                                   b"irregularity = " + b"9" * 400),
        "a governor of no type": b"[governor]\n",
        "nothing but a name": b"name = 'x'\n",
    }
    for label, content in files.items():
        for command in ("evaluate", "design"):
            yield Case(f"file/{label}/{command}", (command, "{spec}"),
                       lambda c=content: c, "file", None,
                       True, command, names_key=False)
    yield Case("file/a FIFO", ("evaluate", "{spec}"), lambda: FIFO, "file", None, True,
               names_key=False)
    for label, path in (("/dev/zero", "/dev/zero"), ("a folder", "/tmp"),
                        ("no such file", "/nonexistent/spec.toml"), ("empty name", "")):
        yield Case(f"file/{label}", ("evaluate", path), None, "file", None, True,
                   names_key=False)
    # an option read by its spec key's rule (one rule, the same words)
    for value in ("1e-300", "0", "2", "nan", "-inf", "lift", "0.01 0.02", "9" * 400):
        for command in ("evaluate", "design"):
            yield Case(f"option/--speed-change {value[:20]}/{command}",
                       (command, "{spec}", "--speed-change", value), lambda: spec.encode(),
                       "option", "--speed-change", True, command, names_key=True)
    for label, target in (("/proc", "/proc/x.toml"), ("a folder", "/tmp"), ("empty name", "")):
        yield Case(f"output/{label}", ("design", "{spec}", "-o", target),
                   lambda: spec.encode(), "file", None, True, "design", names_key=False)


#: ``govopt spring`` options and a valid value of each
SPRING = {"--force": "606 kgf", "--stiffness": "59.7 kgf/cm",
          "--allowable-stress": "4000 kgf/cm^2", "--shear-modulus": "850000 kgf/cm^2",
          "--density": "7850 kg/m^3", "--max-outer-diameter": "15 cm",
          "--max-body-length": "30 cm", "--min-surge-frequency": "40 Hz"}


def _mutated(options: dict, command: tuple[str, ...], tail: tuple[str, ...] = ()
             ) -> Iterator[Case]:
    """Every leaf mutation of each of ``options`` (option -> a valid value) in the command
    line ``command`` with all of them (and ``tail``)."""
    base = [a for k, v in options.items() for a in (k, v)]
    for option, value in options.items():
        for kind, new in _leaf_mutations(value, option):
            if kind in ("array_for_scalar", "table_for_scalar"):
                continue
            args = list(base)
            args[args.index(option) + 1] = str(new)
            yield Case(f"{' '.join(command)}/{option}/{kind}", (*command, *args, *tail), None,
                       kind, option, nonsense(kind, option), "spring")


def _spring_cases() -> Iterator[Case]:
    base = [a for k, v in SPRING.items() for a in (k, v)]
    yield from _mutated(SPRING, ("spring",))
    yield Case("spring/--correction/bogus", ("spring", *base, "--correction", "bogus"), None,
               "bogus_choice", "--correction", True, "spring")
    # an option's bytes that are not UTF-8 (Python hands them on as lone surrogates)
    args = list(base)
    args[args.index("--force") + 1] = "606 \udcffkgf"
    yield Case("spring/--force/not_utf8", ("spring", *args), None, "not_utf8", "--force", True,
               "spring")
    yield from _mutated(SPRING_CHECK, ("spring", "check"), ("--active-coils", "8"))
    yield from _impossible_springs()


#: springs that cannot be (refused, exit 2: nonsense) and springs a load takes past what they
#: can do (a failed check, exit 1): ``(label, the options after the base, nonsense)``
IMPOSSIBLE = (
    ("free length below solid", ("--free-length", "30 mm"), True),
    ("length 2 at the free length", ("--length-2", "60 mm"), True),
    ("cycle past solid", ("--force", "400 N", "--fatigue-min-force", "100 N",
                          "--fatigue-max-force", "560 N"), False),
    ("cycle past L_n", ("--force", "400 N", "--fatigue-min-force", "100 N",
                        "--fatigue-max-force", "500 N"), False),
    ("force past solid", ("--force", "600 N"), False),
    ("life below the data's", ("--force", "400 N", "--fatigue-min-force", "100 N",
                               "--fatigue-max-force", "400 N", "--life", "1000"), False),
    ("closed ends without end coils", ("--force", "400 N", "--total-coils", "9.5"), True),
    ("plain ends, total = active", ("--force", "400 N", "--total-coils", "9.5", "--ends",
                                    "plain"), False),
    ("extension body coils against active", ("--kind", "extension", "--force", "100 N",
                                             "--total-coils", "30", "--free-length", ""),
     True),
    ("extension shorter than its body", ("--kind", "extension", "--force", "100 N",
                                         "--free-length", "1 mm"), True),
    ("extension length below free", ("--kind", "extension", "--length-2", "50 mm",
                                     "--free-length", "80 mm"), True),
    ("extension force below initial tension", ("--kind", "extension", "--force", "100 N",
                                               "--min-force", "5 N", "--initial-tension",
                                               "30 N", "--free-length", ""), False),
    ("extension min force 0", ("--kind", "extension", "--force", "100 N", "--min-force", "0 N",
                               "--free-length", ""), False),
)
#: the spring of the ``spring-check`` template: solid at 533 N, free at 60 mm
_CHECKED = {"--wire-diameter": "3 mm", "--mean-diameter": "16 mm", "--active-coils": "9.5",
            "--free-length": "60 mm", "--material": "EN10270-1 SH"}


def _impossible_springs() -> Iterator[Case]:
    """:data:`IMPOSSIBLE` through the options, and the spring that cannot be in a spec file
    (its error names the file and the key)."""
    for label, extra, nonsense_ in IMPOSSIBLE:
        options = dict(_CHECKED)
        options.update(zip(extra[::2], extra[1::2], strict=True))
        args = [a for k, v in options.items() if v != "" for a in (k, v)]
        yield Case(f"spring check/impossible/{label}", ("spring", "check", *args), None,
                   "impossible_spring", label, nonsense_, "spring")
    text = ('[spring]\nwire_diameter = "3 mm"\nmean_diameter = "16 mm"\nactive_coils = 9.5\n'
            'free_length = "30 mm"\nmaterial = "EN10270-1 SH"\nforce = "100 N"\n')
    yield Case("spring check/impossible/free length below solid in a spec",
               ("spring", "check", "{spec}"), lambda: text, "impossible_spring",
               "spring.free_length", True, "spring")
    long = "s" * 300
    yield Case("spring check/impossible/a 300-character spec name",
               ("spring", "check", f"{long}.toml"), None, "file", None, True, "spring",
               names_key=False)
    yield Case("spring/impossible/extension with the solid length as objective",
               ("spring", "--kind", "extension", "--force", "300 N", "--stiffness", "5 N/mm",
                "--material", "EN10270-1 DH", "--objective", "solid length"), None,
               "impossible_spring", "--objective", True, "spring")


#: ``govopt spring check`` options and a valid value of each (a spring given as it is)
SPRING_CHECK = {"--wire-diameter": "3 mm", "--mean-diameter": "20 mm",
                "--free-length": "60 mm", "--force": "100 N", "--material": "EN10270-1 SH"}


def study_specs() -> list[Path]:
    """The bundled trade-study specs (``studies/`` next to the bundled specs)."""
    return sorted((bundled_specs()[0].parent / "studies").glob("*.toml"))


#: hostile ``govopt study run`` options (each parses as its option's type)
STUDY_OPTIONS = {
    "sweep of 1e8 points": ("--sweep", "design.pendulum_weight=6 kgf:12 kgf:100000000",
                            "--grid"),
    "grid of 1e4 x 1e4 points": ("--sweep", "design.pendulum_weight=6 kgf:12 kgf:10000",
                                 "--sweep", "speed.irregularity=0.05:0.15:10000", "--grid"),
    "sweep of an unknown key": ("--sweep", "design.bogus=1:2:3", "--grid"),
    "sweep without '='": ("--sweep", "design.pendulum_weight"),
    "sweep of 1e300 kgf": ("--sweep", "design.pendulum_weight=1e300 kgf:1e301 kgf:3",
                           "--grid"),
    "sweep of a 200 kB list": ("--sweep", "design.pendulum_weight="
                               + "1 kgf," * 40_000 + "1 kgf", "--grid"),
    "sweep of 9**9**9": ("--sweep", "design.pendulum_weight=9**9**9 kgf:10 kgf:3", "--grid"),
    "sweep NUM 2.5": ("--sweep", "design.pendulum_weight=6 kgf:12 kgf:2.5", "--grid"),
    "lhs of 1e9": ("--sweep", "design.pendulum_weight=6 kgf:12 kgf", "--lhs", "1000000000"),
    "samples of 1e12": ("--tolerance", "design.pendulum_weight=±1%", "--samples",
                        str(10**12)),
    "chunk 0": ("--chunk", "0"), "workers 0": ("--workers", "0"),
    "tolerance garbage": ("--tolerance", "design.pendulum_weight=lots"),
    "pareto of four": ("--pareto", "a,b,c,d"), "mode bogus": ("--mode", "bogus"),
    "skip bogus": ("--skip", "bogus"), "two samplers": ("--lhs", "3", "--sobol", "4"),
    "seed -1": ("--sweep", "design.pendulum_weight=6 kgf:12 kgf", "--lhs", "3", "--seed", "-1"),
    "samples 0": ("--tolerance", "design.pendulum_weight=±1%", "--samples", "0"),
    "a key swept twice": ("--sweep", "design.pendulum_weight=6 kgf", "--sweep",
                          "design.pendulum_weight=7 kgf"),
}


#: tolerance bands that take a part where it cannot be made (a weight or a wire's diameter
#: below zero), each with the words of its refusal: on Hamabe's case c (a spring given)
BAD_BANDS = {
    "wire ±200%": (("--tolerance", "design.wire_diameter=±200%"),
                   "tolerance design.wire_diameter: the band ±200% reaches a value the spec "
                   "refuses (must be positive"),
    "weight ±100%": (("--tolerance", "design.pendulum_weight=±100%"),
                     "tolerance design.pendulum_weight: the band ±100% reaches"),
    "wire ±20 mm": (("--tolerance", "design.wire_diameter=uniform ±20 mm"),
                    "tolerance design.wire_diameter: the band ±20 mm reaches"),
}


def _study_cases() -> Iterator[Case]:
    """Hostile ``[study]`` tables (the rest of a study spec is a spec like the others) and
    options of ``govopt study run``."""
    for path in study_specs():
        data = tomllib.loads(path.read_text())
        args = ("study", "run", "{spec}", "--db", "{spec}.db")
        for ident, kind, key, mutated in _named(path, _spec_mutations(data)):
            if key.startswith("study"):
                yield Case(ident, args, lambda m=mutated: to_toml(m()), kind, key,
                           nonsense(kind, key), "study", gtype=data["governor"]["type"])
        text = path.read_text()
        for label, options in STUDY_OPTIONS.items():
            yield Case(f"{path.stem}/option/{label}", (*args, *options), lambda t=text: t,
                       "option", "study", True, "study")
    case_c = (ROOT / "specs" / "hamabe-c.toml").read_text()
    for label, (options, _) in BAD_BANDS.items():
        yield Case(f"hamabe-c/option/{label}", ("study", "run", "{spec}", "--db", "{spec}.db",
                                                 *options), lambda t=case_c: t, "option", "study",
                   True, "study")


def _db(spec: Path) -> Path:
    return Path(f"{spec}.db")


def _clean(db: Path) -> None:
    for suffix in ("", "-wal", "-shm"):
        Path(str(db) + suffix).unlink(missing_ok=True)


def _foreign_db(spec: Path) -> None:
    """An SQLite database of something else."""
    import sqlite3

    _clean(_db(spec))
    conn = sqlite3.connect(_db(spec))
    conn.execute("CREATE TABLE notes (x)")
    conn.commit()
    conn.close()


def _other_study_db(spec: Path) -> None:
    """A govopt study database holding another study (as a second writer finds it)."""
    from govopt.study import Store

    _clean(_db(spec))
    with Store(_db(spec)) as store:
        store.set_meta({"study": {"name": "another", "spec_path": "other.toml"},
                        "digest": "another", "total": 1})


def _damaged_db(spec: Path) -> None:
    """A govopt study database with garbage past its first page."""
    from govopt.study import Store

    _clean(_db(spec))
    with Store(_db(spec)) as store:
        store.set_meta({"study": {"name": "x", "pad": "x" * 40_000}, "digest": "x"})
        store.conn.execute("PRAGMA wal_checkpoint(TRUNCATE)")
    with open(_db(spec), "r+b") as fh:
        fh.seek(4096)
        fh.write(bytes(range(256)) * 64)


def _truncated_db(spec: Path) -> None:
    """A govopt study database cut to half its length."""
    from govopt.study import Store

    _clean(_db(spec))
    with Store(_db(spec)) as store:
        store.set_meta({"study": {"name": "x", "pad": "x" * 40_000}, "digest": "x"})
    with open(_db(spec), "r+b") as fh:
        fh.truncate(fh.seek(0, 2) // 2)


#: damages of a sound study database (Hamabe's Example 1 as a study, five points): each an SQL
#: script, and the words of the one line that names it damaged
DAMAGES = {
    "no columns table": ("DROP TABLE columns", "no table columns"),
    "a row of NULLs": ("INSERT INTO points (point, status, message) VALUES (NULL, 'pass', '')",
                       "1 row the study did not write, the first point 5"),
    "a row past the total": (
        "INSERT INTO points (point, status, message, design_pendulum_weight, "
        "speed_irregularity, design_wire_diameter, design_active_turns, design_dashpot_a1) "
        "VALUES (7, 'pass', '', 1, 0.1, 1, 8, 1)", "the first point 7"),
    "a row without its inputs": ("DELETE FROM points WHERE point = 4; INSERT INTO points "
                                 "(point, status, message) VALUES (4, 'pass', '')",
                                 "the first point 4"),
    "the total edited": ("UPDATE meta SET value = '2' WHERE key = 'total'",
                         "total 2, but the study has 5 points"),
    "a shown_factor of 0": ("UPDATE columns SET shown_factor = 0 WHERE name = 'omega_inner'",
                            "column omega_inner: shown_factor 0.0, expected a number > 0"),
    "a meta value not JSON": ("UPDATE meta SET value = 'x{' WHERE key = 'total'",
                              "meta 'total' is not JSON"),
    "a column dropped": ("ALTER TABLE points DROP COLUMN omega_inner",
                         "are not those described in columns"),
    "the definition edited": ("UPDATE meta SET value = replace(value, 'hamabe-study', 'x') "
                              "WHERE key = 'study'", "does not match its digest"),
}


@cache
def sound_db() -> Path:
    """A sound study database (Hamabe's Example 1 as a study), made once a process."""
    import tempfile

    from govopt.study import load_study, run_study

    db = Path(tempfile.mkdtemp(prefix="govopt-hostile-")) / "sound.db"
    run_study(load_study(study_specs()[0], skip="vibration,classic"), db)
    return db


def damaged_study_db(sql: str, db: Path) -> None:
    """A copy of :func:`sound_db` at ``db``, damaged by the SQL script ``sql``."""
    import shutil
    import sqlite3

    _clean(db)
    shutil.copy(sound_db(), db)
    conn = sqlite3.connect(db)
    conn.executescript(sql)
    conn.commit()
    conn.close()


def _damage(sql: str, spec: Path) -> None:
    damaged_study_db(sql, _db(spec))


def _empty_file(spec: Path) -> None:
    _clean(_db(spec))
    _db(spec).touch()


def _existing(spec: Path) -> None:
    out = Path(f"{spec}.out")
    out.mkdir(exist_ok=True)
    (out / "speed-vs-error.csv").write_text("keep")


#: study databases and outputs of ``study``, ``init`` and ``bench``: each case
#: (label, command, arguments, what to prepare); ``{db}`` is a database beside the spec
OUTPUT_CASES = (
    ("study/--db is the spec, --force", "study",
     ("study", "run", "{spec}", "--db", "{spec}", "--force"), None),
    ("study/--db a foreign SQLite file", "study", ("study", "run", "{spec}", "--db", "{db}"),
     _foreign_db),
    ("study/--db a foreign SQLite file, --force", "study",
     ("study", "run", "{spec}", "--db", "{db}", "--force"), _foreign_db),
    ("study/--db holding another study", "study", ("study", "run", "{spec}", "--db", "{db}"),
     _other_study_db),
    ("study/--db holding another study, --resume", "study",
     ("study", "run", "{spec}", "--db", "{db}", "--resume"), _other_study_db),
    ("study/--db damaged, --resume", "study",
     ("study", "run", "{spec}", "--db", "{db}", "--resume"), _damaged_db),
    ("study/show damaged", "study", ("study", "show", "{db}"), _damaged_db),
    ("study/export damaged", "study", ("study", "export", "{db}", "--out", "{db}.csv"),
     _damaged_db),
    ("study/show truncated", "study", ("study", "show", "{db}"), _truncated_db),
    ("study/--db truncated, --resume", "study",
     ("study", "run", "{spec}", "--db", "{db}", "--resume"), _truncated_db),
    ("study/show empty file", "study", ("study", "show", "{db}"), _empty_file),
    ("study/export empty file", "study", ("study", "export", "{db}", "--out", "{db}.csv"),
     _empty_file),
    ("study/show a folder", "study", ("study", "show", "/tmp"), None),
    ("study/--db in a missing folder", "study",
     ("study", "run", "{spec}", "--db", "/nonexistent/x.db"), None),
    ("study/--db empty", "study", ("study", "run", "{spec}", "--db", ""), None),
    ("study/--db ending in /", "study", ("study", "run", "{spec}", "--db", "{db}/"), None),
    ("study/--db a device", "study", ("study", "run", "{spec}", "--db", "/dev/null"), None),
    ("study/--out ending in /", "study",
     ("study", "run", "{spec}", "--db", "{db}", "--out", "{db}.csv/"), None),
    ("study/--dask garbage", "study", ("study", "run", "{spec}", "--db", "{db}", "--dask",
                                       "garbage"), None),
    ("study/--dask port 99999", "study",
     ("study", "run", "{spec}", "--db", "{db}", "--dask", "tcp://localhost:99999"), None),
    ("init/-o a missing folder/", "init", ("init", "hamabe-a", "-o", "/nonexistent/new/"),
     None),
    ("init/-o a device", "init", ("init", "hamabe-a", "-o", "/dev/null"), None),
    ("init/-o the existing spec", "init", ("init", "hamabe-a", "-o", "{spec}"), None),
    ("init/-o x.toml/ in a missing folder", "init",
     ("init", "hamabe-a", "-o", "/nonexistent/x.toml/"), None),
    ("init/unknown example", "init", ("init", "bogus"), None),
    ("bench/--out a file", "bench", ("bench", "--quick", "--out", "{spec}"), None),
    ("bench/--out a device", "bench", ("bench", "--quick", "--out", "/dev/null"), None),
    ("bench/--out an impossible folder", "bench",
     ("bench", "--quick", "--out", "/nonexistent/a/b"), None),
    ("bench/--out over existing files", "bench",
     ("bench", "--quick", "--out", "{spec}.out"), _existing),
    # the package's own files, read by every run: never an output (a new name, so that a
    # regression leaves a stray file, not a replaced bundled spec)
    ("output/-o into the package, --force", "design",
     ("design", "{spec}", "-o", str(ROOT / "specs" / "hostile-output.toml"),
      "--force"), None),
    ("init/-o into the package", "init",
     ("init", "hamabe-a", "-o", str(ROOT / "govopt" / "data" / "hostile-output.toml")), None),
)


OUTPUT_CASES += tuple(
    (f"study/{command} {label}", "study", args, partial(_damage, sql))
    for label, (sql, _) in DAMAGES.items()
    for command, args in (("show", ("study", "show", "{db}")),
                          ("export", ("study", "export", "{db}", "--out", "{db}.csv")),
                          ("--resume", ("study", "run", "{spec}", "--db", "{db}", "--resume"))))


def _output_cases() -> Iterator[Case]:
    """Study databases (another study's, a damaged one, an empty file, foreign files) and the
    outputs of ``study``, ``init`` and ``bench``: one line each, nothing lost."""
    text = study_specs()[0].read_text()
    for label, command, args, prepare in OUTPUT_CASES:
        args = tuple(a.replace("{db}", "{spec}.db") if a.startswith("{db}") else a
                     for a in args)
        yield Case(label, args, lambda t=text: t, "option", command, True, command,
                   names_key=False, prepare=prepare)


#: degenerate designs and geometries: a length of the governor a thousand times
#: over, or just below the largest other; a wire as thick as its coil's radius, 0.01 active
#: turns, a free length a thousand times over: a result, or one line naming the keys
def _degenerate_mutations(data: dict) -> Iterator[tuple[str, str, object]]:
    gov, design = data.get("governor", {}), data.get("design", {})
    lengths = {k: q for k, v in gov.items()
               if (q := _quantity(v)) is not None and q[2] and q[0] > 0}
    for key, (mag, unit, _, _) in lengths.items():
        yield "degenerate_long", f"governor.{key}", partial(
            _set, data, ("governor", key), f"{mag * 1000:g} {unit}")
        others = [(m * si, k) for k, (m, _, _, si) in lengths.items() if k != key]
        if others:
            largest, _ = max(others)
            si = lengths[key][3]
            yield "degenerate_near", f"governor.{key}", partial(
                _set, data, ("governor", key), f"{0.9999 * largest / si:.8g} {unit}")
    if "wire_diameter" in design and "coil_radius" in design:
        yield "degenerate_wire", "design.wire_diameter", partial(
            _set, data, ("design", "wire_diameter"), design["coil_radius"])
    if "active_turns" in design:
        yield "degenerate_turns", "design.active_turns", partial(
            _set, data, ("design", "active_turns"), 0.01)
    for key in ("free_length", "free_half_length"):
        q = _quantity(design.get(key))
        if q is not None:
            yield "degenerate_long", f"design.{key}", partial(
                _set, data, ("design", key), f"{q[0] * 1000:g} {q[1]}")
    # no spring given in a band: the spring that floats the governor across it is found
    # (band_spring); across a band narrower than double precision resolves, refused
    speed = data.get("speed", {})
    if "spring_stiffness" in design and "inner" in speed and "outer" in speed:
        def springless(outer=None):
            out = _set(data, ("design", "spring_stiffness"), _DELETE)
            for key in ("free_length", "free_half_length"):
                if key in out["design"]:
                    del out["design"][key]
            if outer is not None:
                out["speed"]["outer"] = outer
            return out

        yield "band_spring", "design.spring_stiffness", springless
        mag, unit, _, _ = _quantity(speed["inner"])
        yield "band_narrow", "speed.outer", partial(springless, f"{mag * (1 + 1e-15)!r} {unit}")


def command_of(data: dict) -> str:
    """The command a bundled spec is for: ``design`` without a ``[design]`` table."""
    return "evaluate" if "design" in data else "design"


def _named(path: Path, mutations) -> Iterator[tuple[str, str, str, object]]:
    """Each mutation with a unique id ``spec/key/kind`` (``#2``, ``#3`` for repeats)."""
    seen: dict[str, int] = {}
    for kind, key, mutated in mutations:
        ident = f"{path.stem}/{key}/{kind}"
        seen[ident] = seen.get(ident, 0) + 1
        yield (ident if seen[ident] == 1 else f"{ident}#{seen[ident]}"), kind, key, mutated


def spec_cases(path: Path) -> Iterator[Case]:
    """Every mutation of one bundled spec, run by the command it is for."""
    data = tomllib.loads(path.read_text())
    command = command_of(data)
    for ident, kind, key, mutated in _named(path, (*_spec_mutations(data),
                                                   *_size_mutations(data),
                                                   *_degenerate_mutations(data))):
        yield Case(ident, (command, "{spec}"), lambda m=mutated: to_toml(m()), kind, key,
                   nonsense(kind, key), command, gtype=data["governor"]["type"])


#: seconds a mutation of these specs that is not refused when read takes here, about (most are
#: refused later, quickly; for the selection's time budget). spring_gravity-design: its design
#: screens 11 M (mass, spring) pairs, ~1.9 s, where a mutation leaves it feasible: 0.6 s on
#: average over its mutations that run (measured; it read 0.15)
RUN_SECONDS = {"hamabe-design-fatigue": 0.5, "hamabe-design": 0.2, "spring_gravity-design": 0.6,
               "hamabe-design-robust": 0.6, "spring_loaded-design-robust": 0.15}


def estimate(case: Case) -> float:
    """Seconds ``case`` takes here, roughly (measured): a case refused when read ~0.012 s;
    one that may run costs its spec's computation."""
    if case.command == "study":
        return 0.02 if case.kind == "option" else 0.8
    if case.kind in NONSENSE:
        return 0.012
    spec = case.id.split("/", 1)[0]
    return RUN_SECONDS.get(spec, 0.1 if case.command in ("design", "spring") else 0.05)


def _marks(case: Case) -> set:
    """What a case stands for in the selection: its (type, command, kind) and (type,
    command, key); a study's mutation, its table key and whether it is nonsense."""
    if case.command == "study":
        return {("study", str(case.key).split("[")[0].split(".")[:2].__str__(), case.nonsense)}
    return {(case.gtype, case.command, "kind", case.kind),
            (case.gtype, case.command, "key", case.key)}


@cache
def _cases() -> tuple[tuple[Case, ...], tuple[Case, ...]]:
    """The cases every selection starts from (built once a process: the cases are immutable):
    the file and option cases, and the pool of spec mutations."""
    fixed = (*_file_cases(), *_spring_cases(),
             *(c for c in _study_cases() if c.kind == "option"), *_output_cases())
    pool = (*(c for p in bundled_specs() for c in spec_cases(p)),
            *(c for c in _study_cases() if c.kind != "option"))
    return fixed, pool


def corpus(budget: int | None = None, seconds: float | None = None) -> list[Case]:
    """The hostile inputs: every bundled spec's mutations, hostile files, and hostile options
    of ``spring`` and ``study run``.

    With ``budget`` (cases) and ``seconds`` (estimated by :func:`estimate`), a deterministic
    selection: the file and option cases; then, cheapest first, a case for every (governor
    type, command, kind) and (type, command, key); then more, in a fixed pseudo-random
    order, while both budgets last."""
    fixed, pool = _cases()
    if budget is None:
        return [*fixed, *pool]
    seconds = math.inf if seconds is None else seconds
    order = sorted(pool, key=lambda c: (estimate(c), zlib.crc32(c.id.encode())))
    covered, chosen, rest = set(), list(fixed), []
    for c in order:
        marks = _marks(c)
        if marks - covered:
            covered |= marks
            chosen.append(c)
        else:
            rest.append(c)
    spent = sum(map(estimate, chosen))
    for c in sorted(rest, key=lambda c: zlib.crc32(c.id.encode())):
        if len(chosen) >= budget:
            break
        if spent + estimate(c) <= seconds:
            chosen.append(c)
            spent += estimate(c)
    return chosen


# ---------------------------------------------------------------------------------------------
# Running and classifying


class Hang(BaseException):
    """The time limit of one case ran out (a BaseException: the CLI's catch-all must not
    swallow it)."""


@dataclass
class Outcome:
    case: Case
    klass: str
    code: int | None
    stdout: str
    stderr: str
    seconds: float
    why: str = ""
    warnings: list[str] = field(default_factory=list)

    def line(self) -> str:
        text = (self.stderr or self.stdout).strip().replace("\n", " | ")
        return (f"{self.klass:9s} {self.case.id[:90]} (exit {self.code}, {self.seconds:.1f} s"
                f"{', ' + self.why if self.why else ''}): {text[:300]}")


def _on_alarm(signum, frame):
    raise Hang()


def _write(case: Case, folder: Path) -> tuple[Path, bool]:
    """Write the case's spec file (or FIFO) into ``folder``: ``(path, written)``."""
    spec = folder / f"case-{zlib.crc32(case.id.encode()):08x}.toml"
    text = case.make() if case.make is not None else None
    spec.unlink(missing_ok=True)
    if text is FIFO:
        os.mkfifo(spec)
    elif isinstance(text, bytes):
        spec.write_bytes(text)
    elif text is not None:
        spec.write_text(text)
    return spec, text is not None


def _args(case: Case, spec: Path, json_out: bool) -> list[str]:
    args = [a.replace("{spec}", str(spec)) for a in case.args]
    return args + (["--json"] if json_out else [])


def run(case: Case, folder: Path, limit: float = 10.0, json_out: bool = False) -> Outcome:
    """Run ``case`` in-process through the CLI (``govopt.cli.main``) with a time limit;
    warnings print as the real CLI prints them (stderr), not into pytest's record."""
    spec, written = _write(case, folder)
    if case.prepare is not None:
        case.prepare(spec)
    json_out = json_out and case.command in ("evaluate", "design", "spring")
    args = _args(case, spec, json_out)
    previous = signal.signal(signal.SIGALRM, _on_alarm)
    t0 = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("always")
            warnings.showwarning = _show_on_stderr
            signal.setitimer(signal.ITIMER_REAL, limit)
            try:
                res = invoke(args)
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0)
    except Hang:
        return Outcome(case, "hang", None, "", "", time.perf_counter() - t0)
    finally:
        signal.signal(signal.SIGALRM, previous)
    out = Outcome(case, "", res.exit_code, res.stdout, res.stderr, time.perf_counter() - t0)
    if res.exception is not None and not isinstance(res.exception, SystemExit):
        out.why = f"{type(res.exception).__name__} escaped the CLI"
    return classify(out, str(spec) if written else None, json_out)


def run_cli(case: Case, folder: Path, limit: float = 60.0, json_out: bool = False,
            fresh: bool = False) -> Outcome:
    """Run ``case`` through the real command line in a process of its own: ``govopt.cli`` run
    as ``__main__`` (the console entry point, its catch-all and its signal handling included),
    forked from a server that has imported govopt already (:mod:`forkcli`), or with ``fresh``
    a new interpreter (``python -m govopt.cli``: its imports on demand too)."""
    import subprocess

    spec, written = _write(case, folder)
    if case.prepare is not None:
        case.prepare(spec)
    json_out = json_out and case.command in ("evaluate", "design", "spring")
    args = _args(case, spec, json_out)
    t0 = time.perf_counter()
    try:
        if fresh:
            p = subprocess.run([sys.executable, "-m", "govopt.cli", *args], capture_output=True,
                               text=True, errors="replace", timeout=limit, cwd=folder,
                               stdin=subprocess.DEVNULL)
        else:
            p = forkcli.run(args, folder, timeout=limit)
    except subprocess.TimeoutExpired:
        return Outcome(case, "hang", None, "", "", time.perf_counter() - t0)
    out = Outcome(case, "", p.returncode, p.stdout, p.stderr, time.perf_counter() - t0)
    return classify(out, str(spec) if written else None, json_out)


def _show_on_stderr(message, category, filename, lineno, file=None, line=None):
    sys.stderr.write(warnings.formatwarning(message, category, filename, lineno, line))


def classify(out: Outcome, spec: str | None, json_out: bool = False) -> Outcome:
    case, err, code = out.case, out.stderr.strip(), out.code
    lines = err.splitlines()
    out.warnings = [x for x in lines if x.startswith("warning:") or "Warning" in x]
    if out.why or "Traceback" in out.stdout + out.stderr or code not in (0, 1, 2):
        out.klass = "traceback"
    elif code in (0, 1):
        ok = bool(out.stdout.strip())
        if ok and json_out:
            try:
                json.loads(out.stdout)
            except ValueError:
                ok, out.why = False, "stdout is not JSON"
        # a study records a point that cannot be evaluated as an error row, and says so
        reported = case.command == "study" and "error" in out.stdout + out.stderr
        out.klass = ("silent" if case.nonsense and not reported else "ok") if ok \
            else "traceback"
    else:
        out.klass, out.why = "error", ""
        first = lines[0] if lines else ""
        # the file's path is the user's (the spec's, or a file named on the command line); a
        # design's diagnosis says how far each requirement is
        paths = [len(a) for a in case.args if a.endswith(FILE_SUFFIXES) and a in first]
        size = len(first) - max([len(spec or ""), *paths])
        limit = MAX_DIAGNOSIS if "infeasible" in first or "the chosen design" in first \
            else MAX_LINE
        if len(lines) != 1:
            out.why = f"{len(lines)} lines on stderr"
        elif not first.startswith("error: "):
            out.why = "not an 'error:' line"
        elif size > limit:
            out.why = f"{size} characters besides the path"
        elif case.names_key and not _names_key(first, spec, case):
            out.why = "names no file and key"
        elif re.search(r"'([^']+)' needs a stiffer spring than '\1'|conflicting ;", first):
            out.why = "a diagnosis that says nothing (a requirement against itself, or none)"
        elif EXCEPTION_NAME.search(first):  # "(AssertionError)": says what failed, not why
            out.why = "names an exception's class instead of what went wrong"
        if out.why:
            out.klass = "unclear"
    return out


#: what a file named on the command line ends with (its name is the user's, however long)
FILE_SUFFIXES = (".toml", ".xlsx", ".json", ".db", ".csv")
#: a Python exception's class in a message (``(AssertionError)``, ``UnicodeEncodeError:``)
EXCEPTION_NAME = re.compile(r"\b[A-Z]\w*(Error|Exception)\b")

#: the tables of a spec, as error messages name them (``speed.mean``, ``[material]``)
TABLES = ("governor", "speed", "design", "material", "engine", "load_change", "analysis",
          "requirements", "bounds", "catalogue", "valve_gear", "spring", "study", "name",
          "description")


def _names_key(line: str, spec: str | None, case: Case) -> bool:
    """``error: FILE: KEY: ...`` (``speed.mean: ...``, ``load_change[0].to: ...``), or a
    diagnosis naming a key or table (``requirements.hurwitz_margin``, ``[[load_change]]``), or
    ``error: --option: ...``."""
    if line.startswith("error: --") or (case.kind == "option" and " --" in line):
        return case.command == "spring" or case.kind == "option"  # an option's error names it
    if case.command == "spring":  # a spring spec's key, or a diagnosis naming the
        # requirements that conflict
        return (spec is not None and line.startswith(f"error: {spec}: spring.")) or \
            line.startswith("error: no spring meets these requirements: infeasible: ")
    if spec is None:
        return True
    if not line.startswith(f"error: {spec}: "):
        return False
    rest = line[len(f"error: {spec}: "):]
    diagnosis = rest.startswith(("infeasible", "the chosen design"))
    if diagnosis:  # a design's diagnosis: the requirements that conflict, in words
        return True
    if not diagnosis and re.match(r"[\w\-]+(\[\d+\])*(\.[\w\-]+(\[\d+\])*)*: ", rest):
        return True
    names = {*TABLES, str(case.key).split(".")[0].split("[")[0]}
    return any(re.search(rf"(^|[\s'(\[]){re.escape(t)}(\[\d+\])?[.:\]]", rest)
               for t in names)


#: summary lines for the terminal report (``tests/conftest.py`` prints them)
SUMMARY: list[str] = []


def summary(outcomes: list[Outcome]) -> dict[str, int]:
    counts = {k: 0 for k in ("ok", "error", "unclear", "traceback", "hang", "silent")}
    for o in outcomes:
        counts[o.klass] += 1
    return counts


def summary_line(outcomes: list[Outcome]) -> str:
    c = summary(outcomes)
    return (f"{len(outcomes)} hostile inputs: {c['traceback']} tracebacks, {c['hang']} hangs, "
            f"{c['silent']} silent results")


if __name__ == "__main__":  # python tests/hostile.py [budget]: run and list the failures
    import tempfile

    budget = int(sys.argv[1]) if len(sys.argv) > 1 else None
    chosen = corpus(budget)
    bad = []
    t_all = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        outcomes = []
        for i, c in enumerate(chosen):
            o = run(c, Path(tmp), json_out=i % 2 == 1)
            outcomes.append(o)
            if o.klass not in ("ok", "error") or o.seconds > 2:
                print(o.line(), flush=True)
    print(summary(outcomes), f"{time.perf_counter() - t_all:.1f} s")
    print(summary_line(outcomes))
