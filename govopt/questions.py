"""The textbook's questions from one spec: answers at the points a problem names
(:func:`answers`, ``govopt at``) and any one input found for one figure's target
(:func:`solve`, ``govopt solve``).

A point is ``NAME=VALUE``: one of the governor type's coordinates (:meth:`Governor.coordinates`:
a ball governor's ``radius``, ``angle``, ``height``, ``joint_radius``, ``lift``) with a quantity
(``angle=30 deg``), or ``inner``, ``normal``, ``outer`` (the spec's range). The answers are
:func:`govopt.analysis.points.at`'s.

An unknown is any numeric input of the spec by its dotted key (``governor.extension``,
``design.ball_weight``, ``governor.sleeve_friction``, ``design.free_length``), found where one
figure meets its target: a figure at a point (:data:`govopt.analysis.points.FIGURES` and the
type's link forces) or over the range (``range``: the outermost speed less the innermost; 0 is
isochronism). The input is varied over a bracket (``between``, or a factor of 8 either side of
its value in the spec), the spec re-validated at each value (:func:`govopt.spec.with_values`,
so a value the spec refuses is skipped), and the root closed by Brent's method
(``scipy.optimize.brentq``) to a relative 1e-12 of the input; a :class:`GovoptError` says what
the figure spans over the bracket where it never meets the target.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import GovoptError
from .keys import WEIGHT
from .units import SI_UNITS, parse_quantity

ENDS = ("inner", "normal", "outer")
#: how a figure's SI unit is shown: SI unit -> (unit shown, factor from SI)
SHOWN = {"rad/s": ("rpm", 30.0 / np.pi), "rad": ("deg", 180.0 / np.pi), "m": ("mm", 1e3)}


def shown(value: float, unit: str) -> tuple[float, str]:
    """``value`` (SI, in ``unit``) as a person reads it: rpm, deg, mm (:data:`SHOWN`)."""
    to, factor = SHOWN.get(unit, (unit, 1.0))
    return value * factor, to
#: figures over the range (no point): name -> (dimension, meaning)
RANGE_FIGURES = {"range": ("angular_velocity", "the range of speed: the outermost configuration's "
                                               "speed rising less the innermost's falling (with "
                                               "no friction, 0 is isochronous)")}


@dataclass(frozen=True)
class Point:
    """A point as written (``text``), its coordinate's ``name`` and ``value`` (SI; None for an
    end of the range)."""

    text: str
    name: str
    value: float | None = None


def parse_point(gov, text: str) -> Point:
    """``NAME=VALUE`` or an end of the range (see the module), checked against ``gov``'s
    coordinates; a :class:`GovoptError` naming what was expected."""
    text = text.strip()
    if text in ENDS:
        return Point(text, text)
    coords = {c.name: c for c in gov.coordinates()}
    name, sep, value = (part.strip() for part in text.partition("="))
    if not sep or name not in coords:
        raise GovoptError(f"--at {text!r}: expected NAME=VALUE with NAME one of "
                          f"{', '.join(coords)} (e.g. '{next(iter(coords))}=...'), or one of "
                          f"{', '.join(ENDS)}")
    try:
        si = parse_quantity(value, coords[name].dimension)
    except ValueError as exc:
        raise GovoptError(f"--at {text!r}: {exc}") from None
    return Point(text, name, si)


def configuration(spec, point: Point) -> float:
    """The configuration ``x`` (SI) of ``point`` in ``spec``'s governor."""
    from .analysis import points

    gov = spec.governor
    if point.value is None:
        return {"inner": gov.x_inner, "normal": gov.x_normal, "outer": gov.x_outer}[point.name]
    return points.configuration(gov, point.name, point.value)


def answers(spec, pts: list[Point]) -> dict:
    """Every answer at the points ``pts`` of ``spec``'s design (see
    :func:`govopt.analysis.points.at`), SI: ``x``, ``figures``, ``links``, ``coordinates``,
    ``stable``, each an array over the points."""
    from .analysis import points, statics

    sd = statics.spring_design(spec)
    xs = np.array([configuration(spec, p) for p in pts])
    return {"x": xs, **points.at(spec, sd, xs)}


def figure_names(gov) -> dict:
    """Every figure a target may name: name -> (dimension or unit kind, at a point?)."""
    from .analysis import points

    out = {name: (kind, True) for name, (kind, _) in points.FIGURES.items()}
    probe = gov.link_forces(np.array([gov.x_normal]), 1.0, 0.0, np.array([1.0]),
                            np.array([1.0]))
    out.update({name.replace(" ", "_"): ("force", True) for name in probe})
    out.update({name: (dim, False) for name, (dim, _) in RANGE_FIGURES.items()})
    return out


def figure_unit(gov, name: str) -> str:
    """The SI unit of the figure ``name`` of :func:`figure_names`."""
    from .analysis import points

    kind = figure_names(gov)[name][0]
    return points.unit(gov, kind)


def dimension_of(unit: str) -> str:
    """The dimension whose SI unit is ``unit`` (``"J"``: a moment's N m; ``""``: a bare
    number)."""
    if unit in ("", "J"):
        return "dimensionless" if not unit else "moment"
    return next(d for d, u in SI_UNITS.items() if u == unit)


def figure(spec, name: str, point: Point | None) -> float:
    """The figure ``name`` of ``spec``'s design (SI), at ``point`` where it is a point's."""
    if name == "range":
        fig = answers(spec, [Point("inner", "inner"), Point("outer", "outer")])["figures"]
        return float(fig["speed_rising"][1] - fig["speed_falling"][0])
    out = answers(spec, [point])
    links = {k.replace(" ", "_"): v for k, v in out["links"].items()}
    return float({**out["figures"], **links}[name][0])


@dataclass(frozen=True)
class Solved:
    """What :func:`solve` found: the input's ``key``, its ``value`` (SI) and ``unit`` (SI),
    the figure's name, target and value there (SI), the spec with the value, the bracket
    searched and the evaluations made."""

    key: str
    value: float
    unit: str
    figure: str
    target: float
    achieved: float
    spec: object
    bracket: tuple[float, float]
    evaluations: int
    roots: int


def key_unit(spec, key: str) -> tuple[str, float | None]:
    """The SI unit of the spec's input ``key`` (dotted) from its declaration, and its value in
    the spec (SI; None where it is not written)."""
    from .spec_keys import spec_tables

    table_name, _, name = key.rpartition(".")
    tables = spec_tables(spec.governor.type_name)
    if table_name not in tables or name not in tables[table_name].names:
        raise GovoptError(f"--unknown {key}: not an input of a {spec.governor.type_name} spec "
                          "(docs/reference/spec.md)")
    declared = tables[table_name].key(name)
    if declared.kind == WEIGHT:
        unit = "N" if name.endswith("_weight") else "kg"
    elif declared.kind in SI_UNITS:
        unit = SI_UNITS[declared.kind]
    elif declared.kind == "number":
        unit = ""
    else:
        raise GovoptError(f"--unknown {key}: a {declared.kind}, not a number to solve for")
    given = next((e.si for e in spec.entries if e.key == key), None)
    return unit, (float(given) if isinstance(given, (int, float)) else None)


def solve(spec, key: str, name: str, target: float, point: Point | None = None,
          between: tuple[float, float] | None = None, samples: int = 33,
          rtol: float = 1e-12) -> Solved:
    """The value of the input ``key`` at which the figure ``name`` (at ``point``) is ``target``
    (SI), by a scan of the bracket for a sign change and Brent's method to the relative
    tolerance ``rtol`` on the input (see the module; ``govopt bench`` measures the setting)."""
    from scipy.optimize import brentq

    from .spec import with_values

    figures = figure_names(spec.governor)
    if name not in figures:
        raise GovoptError(f"--target {name}: expected one of {', '.join(figures)}")
    if figures[name][1] and point is None:
        raise GovoptError(f"--target {name}: a figure at a point: give the point with --at")
    unit, given = key_unit(spec, key)
    if between is None:
        if not given:
            raise GovoptError(f"--unknown {key}: not in the spec (or 0): give the range to "
                              "search with --between LOW HIGH")
        lo, hi = sorted((given / 8.0, given * 8.0))
    else:
        lo, hi = sorted(between)
    count = [0]

    span = max(abs(lo), abs(hi))

    def variant(v: float):
        # a value within 1e-12 of the bracket's span of zero is zero (govopt's limits refuse
        # magnitudes that small, and zero is the root there to the solver's tolerance)
        v = 0.0 if abs(v) <= 1e-12 * span else float(v)
        return with_values(spec, {key: f"{v!r} {unit}" if unit else v})

    def excess(v: float) -> float:
        count[0] += 1
        try:
            return figure(variant(v), name, point) - target
        except GovoptError:
            return float("nan")

    grid = np.geomspace(lo, hi, samples) if lo > 0 and hi / lo > 10 else \
        np.linspace(lo, hi, samples)
    values = np.array([excess(v) for v in grid])
    ok = np.isfinite(values)
    g, f = grid[ok], values[ok]
    cross = np.flatnonzero((np.sign(f[:-1]) * np.sign(f[1:]) <= 0) & (np.diff(np.flatnonzero(
        ok)) == 1))
    if not cross.size:
        fu = figure_unit(spec.governor, name)

        def human(v, u):
            v, u = shown(v, u)
            return f"{v:.6g} {u}".rstrip()
        span = (f"runs {human(np.min(f + target), fu)} .. {human(np.max(f + target), fu)}"
                if f.size else "cannot be evaluated anywhere")
        raise GovoptError(f"--target {name}: no {key} in {human(lo, unit)} .. "
                          f"{human(hi, unit)} gives {human(target, fu)}: the {name} {span} "
                          "over it (widen --between, or the governor cannot do it)")
    i = int(cross[0])
    try:
        root = float(g[i]) if f[i] == 0 else float(brentq(excess, g[i], g[i + 1], xtol=1e-300,
                                                           rtol=rtol))
    except ValueError:  # a value inside the bracket the spec refuses
        raise GovoptError(f"--target {name}: {key} cannot be evaluated everywhere between "
                          f"{g[i]:.6g} and {g[i + 1]:.6g} {unit}, where the root lies: the "
                          "spec refuses a value there (narrow --between)") from None
    root = 0.0 if abs(root) <= 1e-12 * span else root  # as variant() reads it
    solved = variant(root)
    return Solved(key, root, unit, name, target, figure(solved, name, point), solved, (lo, hi),
                  count[0], int(cross.size))
