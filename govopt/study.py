"""Batch trade studies: a spec swept over some of its inputs, one row per point, in SQLite.

A study is a spec plus the inputs to vary (:class:`Study`): sweeps of dotted spec keys
(``design.pendulum_weight = 6 kgf:12 kgf:4``, ``speed.irregularity = 0.12,0.104``) combined as
a grid, zipped, or sampled (Latin hypercube, Sobol'), or manufacturing tolerances sampled
around the spec's own design. Each point is the spec with the swept keys replaced and
re-validated (:func:`govopt.spec.with_values`); it is evaluated (:func:`govopt.bulk.
evaluate_many`, vectorised over the points that differ only in their design) or designed
(:func:`govopt.design`, on a process pool or a Dask cluster) and becomes one row: the inputs
as written and in SI, the design, every check's value, margin and verdict, the objective,
status and message. A failed point is a row with its reason; it never stops the study.

Rows go to an SQLite database (:class:`Store`), one per point, keyed by a hash of the point's
canonical inputs and govopt's version, one transaction per chunk in WAL mode: a study killed at
any moment loses at most the chunk in flight, and ``resume`` skips the points already done.
Tables, Pareto fronts (:func:`pareto_front`), tolerance summaries (:func:`tolerance_summary`)
and plots (:mod:`govopt.report.study_plots`) are read back from the database.
"""

from __future__ import annotations

import contextlib
import hashlib
import itertools
import json
import math
import os
import re
import sqlite3
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field, replace
from functools import lru_cache
from pathlib import Path

import numpy as np
import pandas as pd

from . import limits
from .errors import GovoptError
from .reader import read_spec_data
from .spec import Spec, parse_spec, with_values
from .stats import wilson

MODES = ("evaluate", "design")
COMBINE = ("grid", "zip", "lhs", "sobol")
SKIPPABLE = ("dynamics", "vibration", "classic")

#: objectives a Pareto front may name, with their column and sense (any column may be named,
#: minimised, or with a ``max:`` prefix maximised)
OBJECTIVES = {
    "moving_mass": ("moving_mass_kg", "min"), "spring_mass": ("spring_mass_kg", "min"),
    "settling_time": ("settling_time_s", "min"), "vibration": ("vibration_p2p_rad", "min"),
    "irregularity": ("irregularity", "min"), "max_stress": ("max_stress_Pa", "min"),
    "k2_margin": ("margin: k^2 > 0 (stability)", "max"),
}

#: a tolerance band ``+-X`` is read as +-3 standard deviations of a normal scatter (the usual
#: reading of a manufacturing tolerance: 99.73 % of the parts within it), unless ``uniform``
TOLERANCE_SIGMAS = 3.0


class StudyError(GovoptError):
    """A study that cannot run (bad sweep, bad database), with the reason in one line."""


# ---------------------------------------------------------------------------------------------
# The study definition
# ---------------------------------------------------------------------------------------------

_NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


def _scalar(text: str):
    """A sweep value as it would be written in TOML: a number, else the string itself."""
    text = text.strip()
    if _NUMBER.fullmatch(text):
        return int(text) if re.fullmatch(r"[-+]?\d+", text) else float(text)
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    return text


def _quantity(text: str, where: str):
    """``text`` as a pint quantity; an error names ``where`` (``sweep KEY``)."""
    from .units import UnitError, malformed, normalise, registry, strict_units

    if len(text) > limits.MAX_QUANTITY_CHARS:
        raise StudyError(f"{where}: {limits.shorten(text)}: a quantity of at most "
                         f"{limits.MAX_QUANTITY_CHARS} characters (govopt's limit)")
    try:  # what pint would misread, or take minutes over ('9**9**9'), refused first
        strict_units(normalise(text), shown=text)
    except UnitError as exc:
        raise StudyError(f"{where}: cannot read {text!r} as a quantity: {exc}") from None
    try:
        return registry().Quantity(normalise(text))
    except Exception as exc:
        raise StudyError(f"{where}: cannot read {text!r} as a quantity: "
                         f"{malformed(exc)}") from None


def _range_at(start: float, stop: float, unit: str, integer: bool, u) -> tuple:
    """The values of a range ``start``-``stop`` at fractions ``u`` in [0, 1] (as written in
    TOML: whole numbers rounded, numbers, or ``"%.15g unit"``)."""
    v = start + np.asarray(u, dtype=float) * (stop - start)
    if integer:
        return tuple(int(round(x)) for x in v)
    if not unit:
        return tuple(float(x) for x in v)
    return tuple(f"{float(x):.15g} {unit}" for x in v)


class RangeValues(Sequence):
    """The ``num`` values of a range sweep ``START:STOP:NUM``, made as they are taken (a block
    at a time): a million-point sweep holds its fractions (8 bytes a point), never its million
    written values. Equal, value by value, to the tuple ``Sweep.at(np.linspace(0, 1, num))``."""

    def __init__(self, start: float, stop: float, num: int, unit: str = "",
                 integer: bool = False):
        self.start, self.stop, self.num, self.unit, self.integer = (start, stop, int(num), unit,
                                                                    integer)
        self._u = None

    def _fractions(self) -> np.ndarray:
        if self._u is None:
            self._u = np.linspace(0.0, 1.0, self.num)
        return self._u

    def take(self, idx) -> tuple:
        """The values at the positions ``idx`` (an array of indices)."""
        return _range_at(self.start, self.stop, self.unit, self.integer,
                         self._fractions()[np.asarray(idx, dtype=np.intp)])

    def __len__(self) -> int:
        return self.num

    def __getitem__(self, i):
        if isinstance(i, slice):
            return self.take(np.arange(self.num)[i])
        if not -self.num <= i < self.num:
            raise IndexError(i)
        return self.take([i % self.num])[0]

    def __iter__(self):
        for b in range(0, self.num, Study.BLOCK):
            yield from self.take(np.arange(b, min(b + Study.BLOCK, self.num)))

    def _params(self) -> tuple:
        return self.start, self.stop, self.num, self.unit, self.integer

    def __eq__(self, other) -> bool:
        if isinstance(other, RangeValues):
            return self._params() == other._params()
        if isinstance(other, Sequence) and not isinstance(other, str):
            return len(other) == self.num and all(
                a == b for a, b in zip(self, other, strict=True))
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self._params())

    def __repr__(self) -> str:
        return f"RangeValues({self.start!r}, {self.stop!r}, {self.num}, {self.unit!r})"


#: a range sweep of more values than this keeps them as :class:`RangeValues` (made as taken)
LAZY_VALUES = 10_000


def _take(values: Sequence, idx: np.ndarray) -> Sequence:
    """``values`` at the positions ``idx``: a range's made for them only."""
    return values.take(idx) if isinstance(values, RangeValues) else [values[i] for i in idx]


@dataclass(frozen=True)
class Sweep:
    """One swept key: ``values`` (as written in TOML) and, for a range, ``start``/``stop``
    (numbers in ``unit``, for the samplers)."""

    key: str
    values: tuple
    start: float | None = None
    stop: float | None = None
    unit: str = ""
    integer: bool = False

    @classmethod
    def parse(cls, key: str, text) -> Sweep:
        """``START:STOP:NUM`` (a range, with units: ``6 kgf:12 kgf:4``; ``NUM`` may be left out
        for sampled studies), ``v1,v2,...`` (a list; a unit after the last value applies to
        bare numbers before it: ``12,10,8 kgf``), or a TOML list."""
        key = key.strip()
        if not key:
            raise StudyError("sweep: expected KEY=VALUES, got an empty key")
        if isinstance(text, list):
            if not text:
                raise StudyError(f"sweep {key}: expected at least one value")
            return cls(key, tuple(text))
        if isinstance(text, dict):
            unknown = set(text) - {"start", "stop", "num"}
            if unknown or not {"start", "stop"} <= set(text):
                raise StudyError(f"sweep {key}: expected a table {{start, stop, num}}")
            text = f"{text['start']}:{text['stop']}" + (f":{text['num']}" if "num" in text
                                                        else "")
        if not isinstance(text, str):
            return cls(key, (text,))
        if ":" in text:
            parts = text.split(":")
            if len(parts) not in (2, 3):
                raise StudyError(f"sweep {key}: expected START:STOP:NUM, got {text!r}")
            num = None
            if len(parts) == 3:
                try:
                    num = int(parts[2])
                except ValueError:
                    raise StudyError(f"sweep {key}: NUM must be a whole number, got "
                                     f"{parts[2]!r}") from None
                if num < 1:
                    raise StudyError(f"sweep {key}: NUM must be at least 1, got {num}")
                if num > limits.MAX_STUDY_POINTS:  # before np.linspace allocates them
                    raise StudyError(f"sweep {key}: NUM must be at most "
                                     f"{limits.MAX_STUDY_POINTS} (govopt's limit), got {num}")
            a, b = _scalar(parts[0]), _scalar(parts[1])
            if isinstance(a, int | float) and isinstance(b, int | float):
                integer = isinstance(a, int) and isinstance(b, int)
                start, stop, unit = float(a), float(b), ""
            else:
                qa, qb = _quantity(parts[0], f"sweep {key}"), _quantity(parts[1],
                                                                        f"sweep {key}")
                try:
                    start, stop = float(qa.magnitude), float(qb.to(qa.units).magnitude)
                except Exception:
                    raise StudyError(f"sweep {key}: {parts[0]!r} and {parts[1]!r} are not "
                                     "of the same dimension") from None
                from .units import angle_power

                if angle_power(qa) != angle_power(qb):  # '20 Hz:1400 rpm': pint's radian is 1
                    raise StudyError(f"sweep {key}: {parts[0]!r} and {parts[1]!r} differ by an "
                                     "angle, which pint cannot tell from a number; write both "
                                     "ends in the same kind of unit")
                unit, integer = f"{qa.units:~}", False
            sw = cls(key, (), start, stop, unit, integer)
            if num is not None and num > LAZY_VALUES:
                return sw.with_range(num)
            return replace(sw, values=sw.at(np.linspace(0.0, 1.0, num)) if num else ())
        items = [p.strip() for p in text.split(",")]
        if any(not p for p in items):
            raise StudyError(f"sweep {key}: empty value in {text!r}")
        values = [_scalar(p) for p in items]
        last = values[-1]
        if isinstance(last, str) and len(values) > 1:
            m = re.match(r"\s*" + _NUMBER.pattern + r"\s+(.+)$", last)
            if m and all(isinstance(v, int | float) for v in values[:-1]):
                unit = last[m.end(2) if m.group(2) else m.end(1):].strip()
                values = [f"{v} {unit}" for v in values[:-1]] + [last]
        return cls(key, tuple(values))

    def at(self, u) -> tuple:
        """Values at fractions ``u`` in [0, 1] of the range (rounded for integers)."""
        return _range_at(self.start, self.stop, self.unit, self.integer, u)

    def with_range(self, num: int) -> Sweep:
        """This range sweep with its ``num`` values made as they are taken."""
        return replace(self, values=RangeValues(self.start, self.stop, num, self.unit,
                                                self.integer))

    def sample(self, u) -> tuple:
        """Values at uniform fractions ``u`` (a sampler's column): within the range, or
        one of the listed values."""
        if self.start is not None:
            return self.at(u)
        idx = np.minimum((np.asarray(u) * len(self.values)).astype(int), len(self.values) - 1)
        return tuple(self.values[i] for i in idx)


@dataclass(frozen=True)
class Tolerance:
    """Manufacturing scatter of one input around the spec's nominal value: a band ``+-half``
    (relative when ``relative``), read as +-3 sigma of a normal scatter or as uniform."""

    key: str
    half: float
    relative: bool
    unit: str = ""
    distribution: str = "normal"

    @classmethod
    def parse(cls, key: str, text: str) -> Tolerance:
        """``+-X%``, ``±X%``, ``±X unit`` with an optional ``normal`` (default) or ``uniform``
        before it: ``design.wire_diameter=±1%``, ``design.coil_radius=uniform ±0.2 mm``."""
        t = str(text).strip()
        dist = "normal"
        for word in ("normal", "uniform"):
            if t.lower().startswith(word):
                dist, t = word, t[len(word):].strip()
        if t.startswith("±"):
            t = t[1:]
        elif t.startswith("+-") or t.startswith("+/-"):
            t = t[2:] if t.startswith("+-") else t[3:]
        else:
            raise StudyError(f"tolerance {key}: expected ±X% or ±X unit (optionally after "
                             f"'normal' or 'uniform'), got {text!r}")
        t = t.strip()
        if t.endswith("%"):
            try:
                half = float(t[:-1]) / 100.0
            except ValueError:
                raise StudyError(f"tolerance {key}: cannot read {text!r}") from None
            out = cls(key, half, True, "", dist)
        else:
            q = _quantity(t, f"tolerance {key}")
            out = cls(key, float(q.magnitude), False, f"{q.units:~}" if not q.unitless else "",
                      dist)
        if not (math.isfinite(out.half) and out.half > 0):
            raise StudyError(f"tolerance {key}: expected a positive band, got {text!r}")
        return out

    def draw(self, nominal_si: float, si_unit: str, u: np.ndarray) -> np.ndarray:
        """Values (SI) at uniform fractions ``u``: ``nominal + band * z`` with ``z`` normal with
        sigma 1/3 (by the inverse normal CDF) or uniform in [-1, 1]."""
        from scipy.special import ndtri

        half = self.half * abs(nominal_si) if self.relative else self.half
        if not self.relative and self.unit:  # by the spec's rule for units (an angle in it)
            from .units import UnitError, convert

            try:
                half = convert(self.half, self.unit, si_unit)
            except UnitError as exc:
                raise StudyError(f"tolerance {self.key}: {exc}") from None
        z = (ndtri(np.clip(u, 1e-12, 1 - 1e-12)) / TOLERANCE_SIGMAS
             if self.distribution == "normal" else 2.0 * u - 1.0)
        return nominal_si + half * z


def grade_tolerances(spec: Spec, grade: int) -> list[Tolerance]:
    """The spring maker's tolerances of the spec's helical spring for EN 15800 quality grade
    ``grade``: the mean coil diameter ``+-A_D`` (Table 1; on the radius ``+-A_D/2``) and the
    wire diameter after EN 10270-1 (:mod:`govopt.springs.tolerances`)."""
    from .springs import tolerances as tol

    ds = spec.design
    if ds is None or ds.wire_diameter is None or ds.coil_radius is None:
        raise StudyError(f"{spec.path}: tolerance grade: needs a helical spring in [design] "
                         "(wire_diameter, coil_radius)")
    D = 2.0 * ds.coil_radius
    a_d = float(tol.coil_diameter_tolerance(D, D / ds.wire_diameter, grade))
    a_w = float(tol.wire_diameter_tolerance(ds.wire_diameter))
    if not (math.isfinite(a_d) and math.isfinite(a_w)):
        raise StudyError(f"{spec.path}: tolerance grade {grade}: the spring (d = "
                         f"{ds.wire_diameter:.4g} m, D = {D:.4g} m) is outside the EN 15800 / "
                         "EN 10270-1 tables")
    return [Tolerance("design.coil_radius", a_d / 2.0, False, "m"),
            Tolerance("design.wire_diameter", a_w, False, "m")]


@dataclass(frozen=True)
class Study:
    """A spec and what to vary in it; :meth:`points` lists the points, in order."""

    path: str
    data: dict  # the spec's TOML without its [study] table
    sweeps: tuple[Sweep, ...] = ()
    combine: str = "grid"
    samples: int | None = None
    seed: int = 0
    mode: str = "evaluate"
    skip: tuple[str, ...] = ()
    tolerances: tuple[Tolerance, ...] = ()
    pareto: tuple[str, ...] = ()
    name: str = ""
    spec: Spec | None = field(default=None, repr=False, compare=False)

    def __post_init__(self):
        if self.mode not in MODES:
            raise StudyError(f"study mode: expected one of {', '.join(MODES)}, got {self.mode!r}")
        if self.combine not in COMBINE:
            raise StudyError(f"study combination: expected one of {', '.join(COMBINE)}, got "
                             f"{self.combine!r}")
        bad = set(self.skip) - set(SKIPPABLE)
        if bad:
            raise StudyError(f"study skip: expected some of {', '.join(SKIPPABLE)}, got "
                             f"{sorted(bad)}")
        if self.tolerances and self.sweeps:
            raise StudyError("a study either sweeps inputs or samples tolerances, not both")
        if self.tolerances and self.mode != "evaluate":
            raise StudyError("a tolerance study evaluates the spec's design: mode must be "
                             "'evaluate'")
        if not self.sweeps and not self.tolerances:
            raise StudyError("a study needs at least one --sweep (or --tolerance)")
        if len({s.key for s in self.sweeps}) != len(self.sweeps):
            raise StudyError("a key is swept twice")
        if self.samples is not None and (isinstance(self.samples, bool)
                                         or not isinstance(self.samples, int)):
            raise StudyError(f"{self.path}: study.samples: expected a whole number, got "
                             f"{limits.shorten(self.samples)}")
        sampled = bool(self.tolerances) or self.combine in ("lhs", "sobol")
        sizes = [len(s.values) for s in self.sweeps]
        total = (self.samples or 0) if sampled else (
            math.prod(sizes) if self.combine == "grid" else max(sizes, default=0))
        if max(total, self.samples or 0) > limits.MAX_STUDY_POINTS:  # before they are made
            raise StudyError(f"{self.path}: study: at most {limits.MAX_STUDY_POINTS} points "
                             f"(govopt's limit), got {max(total, self.samples or 0):.4g}")
        if not self.tolerances and self.combine in ("grid", "zip"):  # before any point runs
            for s in self.sweeps:
                self._need_values(s)
            if self.combine == "zip" and len(set(sizes)) > 1:
                raise StudyError("--zip needs every sweep to have the same number of values, "
                                 "got " + ", ".join(f"{s.key}: {len(s.values)}"
                                                    for s in self.sweeps))
        if not 2 <= len(self.pareto) <= 3 and self.pareto:
            raise StudyError(f"a Pareto front takes two or three objectives, got "
                             f"{len(self.pareto)}")

    @property
    def keys(self) -> tuple[str, ...]:
        return tuple(s.key for s in self.sweeps) or tuple(t.key for t in self.tolerances)

    def definition(self) -> dict:
        """Everything that defines the study's points and rows (JSON), for the database."""
        return {"name": self.name, "spec_path": self.path, "spec": self.data,
                "mode": self.mode, "combine": self.combine, "samples": self.samples,
                "seed": self.seed, "skip": list(self.skip),
                "sweeps": [s.__dict__ | ({"values": [], "num": len(s.values)}
                                         if isinstance(s.values, RangeValues)
                                         else {"values": list(s.values)})
                           for s in self.sweeps],
                "tolerances": [t.__dict__ for t in self.tolerances],
                "pareto": list(self.pareto), "keys": list(self.keys)}

    @classmethod
    def from_definition(cls, d: dict) -> Study:
        sweeps = tuple(Sweep(**{**s, "values": tuple(s["values"])}) if "num" not in s else
                       Sweep(**{k: v for k, v in s.items() if k != "num"}).with_range(s["num"])
                       for s in d["sweeps"])
        return cls(d["spec_path"], d["spec"], sweeps, d["combine"], d["samples"], d["seed"],
                   d["mode"], tuple(d["skip"]), tuple(Tolerance(**t) for t in d["tolerances"]),
                   tuple(d["pareto"]), d["name"])

    def base(self) -> Spec:
        """The spec itself (validated)."""
        return self.spec if self.spec is not None else _base_spec(_canonical(self.data),
                                                                  self.path)

    def points(self) -> list[dict]:
        """The study's points: dicts of dotted key -> value as written in TOML, in order."""
        return list(self.iter_points())

    def count(self) -> int:
        """How many points :meth:`iter_points` yields (without making them)."""
        if self.tolerances or self.combine in ("lhs", "sobol"):
            return int(self.samples or 0)
        for s in self.sweeps:
            self._need_values(s)
        sizes = [len(s.values) for s in self.sweeps]
        return math.prod(sizes) if self.combine == "grid" else min(sizes, default=0)

    #: points made at once from a sampler's columns (bounded memory whatever the count)
    BLOCK = 8192

    def iter_points(self):
        """:meth:`points` one by one, made as they are taken: a study of a million points
        never holds them all."""
        if self.tolerances:
            yield from self._tolerance_points()
            return
        if self.combine in ("grid", "zip"):
            for s in self.sweeps:
                self._need_values(s)
            if self.combine == "zip" and len({len(s.values) for s in self.sweeps}) != 1:
                raise StudyError("--zip needs every sweep to have the same number of values, got "
                                 + ", ".join(f"{s.key}: {len(s.values)}" for s in self.sweeps))
            # a block of positions at a time (itertools.product would hold every value)
            columns = [s.values for s in self.sweeps]
            sizes = [len(c) for c in columns]
            n = math.prod(sizes) if self.combine == "grid" else sizes[0]
            for b in range(0, n, self.BLOCK):
                flat = np.arange(b, min(b + self.BLOCK, n))
                where = (np.unravel_index(flat, sizes) if self.combine == "grid"
                         else [flat] * len(columns))  # the last key fastest, as a product
                cols = [_take(c, i) for c, i in zip(columns, where, strict=True)]
                for vals in zip(*cols, strict=True):
                    yield dict(zip(self.keys, vals, strict=True))
            return
        u = self._unit_samples(len(self.sweeps))
        for b in range(0, len(u), self.BLOCK):
            cols = [s.sample(u[b:b + self.BLOCK, j]) for j, s in enumerate(self.sweeps)]
            for vals in zip(*cols, strict=True):
                yield dict(zip(self.keys, vals, strict=True))

    def spans(self) -> dict:
        """:func:`_spans` of the whole study (per numeric design key, its smallest and largest
        value), from the sweeps' values, or the samples block by block."""
        if not self.tolerances and self.combine in ("grid", "zip"):
            out = {}
            for s in self.sweeps:  # a key's values in the study are its sweep's (a range's
                values = (s.values[0], s.values[-1]) if isinstance(  # are its ends')
                    s.values, RangeValues) else list(s.values)
                nums = _numbers(values) if s.key.startswith("design.") else None
                if nums is not None:
                    out[s.key] = (float(nums[0].min()), float(nums[0].max()), nums[1])
            return out
        return _merge_spans(_spans(block) for block in _blocks(self.iter_points(), self.BLOCK))

    def _need_values(self, s: Sweep):
        if not s.values:
            raise StudyError(f"sweep {s.key}: a {self.combine} needs NUM in START:STOP:NUM")

    def _unit_samples(self, dim: int) -> np.ndarray:
        """``samples`` points in the unit cube: Latin hypercube or scrambled Sobol' (scipy's
        ``qmc``), seeded, so that a study's points are the same every run."""
        from scipy.stats import qmc

        n = self.samples
        if not n or n < 1:
            raise StudyError(f"--{self.combine if self.combine != 'grid' else 'samples'} needs a "
                             "number of samples >= 1")
        if self.combine == "sobol":
            return qmc.Sobol(d=dim, scramble=True, seed=self.seed).random(n)
        if self.combine != "sobol":  # lhs, and the default of a tolerance study
            return qmc.LatinHypercube(d=dim, seed=self.seed).random(n)
        raise AssertionError(self.combine)

    def _tolerance_points(self):
        base = self.base()
        entries = {e.key: e for e in base.entries}
        found = []
        for t in self.tolerances:
            e = entries.get(t.key)
            if e is None or not isinstance(e.si, float):
                raise StudyError(f"{self.path}: study: tolerance {t.key}: the spec has no "
                                 "numeric value there (give the key as it is written in the "
                                 "spec)")
            found.append(e)
        u = self._unit_samples(len(self.tolerances))
        for b in range(0, len(u), self.BLOCK):
            cols = []
            for j, (t, e) in enumerate(zip(self.tolerances, found, strict=True)):
                values = t.draw(e.si, e.unit, u[b:b + self.BLOCK, j])
                cols.append([f"{float(v)!r} {e.unit}" for v in values] if e.unit
                            else [float(v) for v in values])
            for vals in zip(*cols, strict=True):
                yield dict(zip(self.keys, vals, strict=True))


def _canonical(data) -> str:
    return json.dumps(data, sort_keys=True, separators=(",", ":"), default=str)


@lru_cache(maxsize=8)
def _base_spec(text: str, path: str) -> Spec:
    return parse_spec(json.loads(text), path)


def read_study_file(path: str | Path, max_bytes: int = 1 << 20) -> tuple[dict, dict]:
    """``(spec data, [study] table)`` of a spec file (TOML; the study table may be absent)."""
    # a regular file, bounded, UTF-8, shallow: read as govopt reads every spec
    data = read_spec_data(path, max_bytes=max_bytes)
    table = data.pop("study", {})
    if not isinstance(table, dict):
        raise StudyError(f"{path}: study: expected a table")
    return data, table


def load_study(path: str | Path, *, sweeps: Iterable[str] = (), tolerances: Iterable[str] = (),
               **options) -> Study:
    """:func:`_load_study`, its errors naming the spec file (one line, exit 2)."""
    try:
        return _load_study(path, sweeps=sweeps, tolerances=tolerances, **options)
    except StudyError as exc:
        if str(exc).startswith(f"{path}: "):
            raise
        raise StudyError(f"{path}: study: {exc}") from None


def _load_study(path: str | Path, *, sweeps: Iterable[str] = (), tolerances: Iterable[str] = (),
                **options) -> Study:
    """A study from a spec file's ``[study]`` table and command-line style arguments, which
    take precedence: ``sweeps`` as ``"KEY=VALUES"`` (added to the file's, replacing a key it
    has), ``tolerances`` as ``"KEY=±X%"`` (or ``"grade=N"``: :func:`grade_tolerances`), and
    ``options`` among ``combine``, ``samples``, ``seed``, ``mode``, ``skip``, ``pareto``
    (``None`` keeps the file's or the default)."""
    data, table = read_study_file(path)
    known = {"mode", "combine", "samples", "seed", "skip", "pareto", "sweep", "tolerance",
             "name"}
    unknown = sorted(set(table) - known)
    if unknown:
        raise StudyError(f"{path}: study.{unknown[0]}: unknown key (allowed: "
                         f"{', '.join(sorted(known))})")
    spec = parse_spec(data, str(path))
    for name in ("sweep", "tolerance"):
        if not isinstance(table.get(name, {}), dict):
            raise StudyError(f"{path}: study.{name}: expected a table of KEY = VALUES, got "
                             f"{limits.shorten(table[name])}")
    sw = {k: Sweep.parse(k, v) for k, v in dict(table.get("sweep", {})).items()}
    for text in sweeps:
        key, _, value = str(text).partition("=")
        if not _:
            raise StudyError(f"--sweep: expected KEY=VALUES, got {text!r}")
        sw[key.strip()] = Sweep.parse(key, value)
    for key, s in sw.items():  # a key the spec has no place for fails here, not in every row
        probe = _variant(spec, {key: s.values[0]}) if s.values else spec
        if isinstance(probe, str) and any(t in probe for t in (
                "unknown key", "is not a table", "to replace in the spec", "dotted key path")):
            raise StudyError(probe)
    tol_texts = [(k, v) for k, v in dict(table.get("tolerance", {})).items()]
    for text in tolerances:
        key, _, value = str(text).partition("=")
        if not _:
            raise StudyError(f"--tolerance: expected KEY=±X%, got {text!r}")
        tol_texts.append((key.strip(), value))
    tols: dict[str, Tolerance] = {}
    for key, value in tol_texts:
        if key == "grade":
            try:
                grade = int(value)
            except ValueError:
                raise StudyError(f"tolerance grade: expected 1, 2 or 3, got {value!r}") from None
            if grade not in (1, 2, 3):
                raise StudyError(f"tolerance grade: expected 1, 2 or 3, got {grade}")
            tols.update({t.key: t for t in grade_tolerances(spec, grade)})
        else:
            tols[key] = Tolerance.parse(key, value)
    opts = {k: table.get(k) for k in ("mode", "combine", "samples", "seed", "skip", "pareto")}
    opts.update({k: v for k, v in options.items() if v is not None})
    # only an absent option takes the default ('' is a mode, refused; not the default)
    mode = opts["mode"] if opts["mode"] is not None else (
        "evaluate" if spec.design is not None else "design")
    pareto = opts["pareto"] or ()
    if isinstance(pareto, str):
        pareto = [p for p in pareto.split(",") if p.strip()]
    if not isinstance(pareto, list | tuple) or not all(isinstance(p, str) for p in pareto):
        raise StudyError(f"pareto: expected two or three objective names, got "
                         f"{limits.shorten(pareto)}")
    skip = opts["skip"] or ()
    if isinstance(skip, str):
        skip = [p for p in skip.split(",") if p.strip()]
    if not isinstance(skip, list | tuple) or not all(isinstance(p, str) for p in skip):
        raise StudyError(f"skip: expected names of analyses, got {limits.shorten(skip)}")
    samples = opts["samples"]
    combine = opts["combine"] if opts["combine"] is not None else ("lhs" if tols else "grid")
    if tols and samples is None:
        samples = 1000
    return Study(str(path), data, tuple(sw.values()), combine, samples,
                 int(opts["seed"] or 0), mode, tuple(s.strip() for s in skip),
                 tuple(tols.values()), tuple(p.strip() for p in pareto),
                 str(table.get("name") or spec.name), spec)


# ---------------------------------------------------------------------------------------------
# Evaluating points
# ---------------------------------------------------------------------------------------------

def _hasher(base_digest: str, mode: str, skip: tuple) -> Callable[[dict], str]:
    """The key of a point in the database: SHA-256 of its canonical inputs (the spec's digest,
    the mode and analyses, the swept values as written) and govopt's version."""
    from . import __version__

    prefix = _canonical({"base": base_digest, "mode": mode, "skip": list(skip),
                         "version": __version__}).encode()

    def digest(point: dict) -> str:
        h = hashlib.sha256(prefix)
        h.update(_canonical(point).encode())
        return h.hexdigest()

    return digest


def spec_digest(data: dict) -> str:
    return hashlib.sha256(_canonical(data).encode()).hexdigest()


def _range_fields(s: dict) -> bool:
    """Whether a stored sweep is a range of :class:`RangeValues` (its ends and count, within
    govopt's limit; anything else, as a damaged database's, is hashed as it is)."""
    num = s.get("num")
    return (isinstance(num, int) and not isinstance(num, bool)
            and 1 <= num <= limits.MAX_STUDY_POINTS
            and all(isinstance(s.get(k), int | float) and not isinstance(s.get(k), bool)
                    for k in ("start", "stop"))
            and isinstance(s.get("unit"), str) and isinstance(s.get("integer"), bool))


def study_digest(definition: dict) -> str:
    """The key of a study's definition (:meth:`Study.definition`, as JSON reads it back): the
    SHA-256 of its canonical JSON with every range's values written out (as govopt before
    :class:`RangeValues` stored them: the same study, the same key), hashed a block at a time."""
    d = json.loads(json.dumps(definition, default=str))
    ranges = []
    for s in d.get("sweeps", []) if isinstance(d, dict) and isinstance(
            d.get("sweeps"), list) else []:
        if isinstance(s, dict) and _range_fields(s):
            ranges.append(RangeValues(s["start"], s["stop"], s.pop("num"), s["unit"],
                                      s["integer"]))
            s["values"] = f"\0range{len(ranges) - 1}"
    h = hashlib.sha256()
    parts = re.split(r'"\\u0000range\d+"', _canonical(d))
    for text, values in itertools.zip_longest(parts, ranges):
        h.update(text.encode())
        if values is not None:
            h.update(b"[")
            for b in range(0, len(values), Study.BLOCK):
                block = values.take(np.arange(b, min(b + Study.BLOCK, len(values))))
                h.update((b"," if b else b"") + json.dumps(
                    list(block), separators=(",", ":"))[1:-1].encode())
            h.update(b"]")
    return h.hexdigest()


def _input_columns(spec: Spec, point: dict) -> dict:
    """The point's inputs as written (``KEY``) and in SI (``KEY [unit]``), from the variant's
    parsed entries."""
    entries = {e.key: e for e in spec.entries}
    out = {}
    for key, value in point.items():
        out[key] = value
        e = entries.get(key)
        if e is not None and isinstance(e.si, float):
            out[_si_column(key, e.unit)] = e.si
    return out


def _si_column(key: str, unit: str) -> str:
    return f"{key} [{unit}]" if unit else f"{key} [SI]"


def _error(point: dict, message: str, status: str = "error") -> dict:
    return {**point, "objective_value": math.nan, "status": status, "message": message}


def run_chunk(definition_text: str, items: list[tuple[int, str, dict]],
              spans: dict | None = None) -> tuple:
    """Evaluate or design the points ``items`` (``(idx, hash, point)``) of the study
    ``definition_text`` (JSON of :meth:`Study.definition`); returns ``(layouts, records)`` for
    :meth:`Store.add` (:func:`encode`). ``spans``: the whole study's range of each numeric
    design key (:func:`_spans`). Runs in any process (pool or Dask worker)."""
    study = _study_from_text(definition_text)
    points = [p for _, _, p in items]
    if study.mode == "evaluate":
        frame = _evaluate_points(study, points, spans or {})
    else:
        frame = pd.DataFrame.from_records(_design_points(study, points))
    return encode(frame, [h for _, h, _ in items], [i for i, _, _ in items], study.keys)


@lru_cache(maxsize=4)
def _study_from_text(text: str) -> Study:
    return Study.from_definition(json.loads(text))


#: the spec variants this process has parsed: (id(spec), values) -> (spec, variant or message)
_VARIANTS: dict = {}
#: linear maps of design keys (see :func:`_key_values`): (id(spec), key, unit) -> dict
_LINEAR: dict = {}
_CACHE_SIZE = 512


def _variant(spec: Spec, values: dict):
    """``with_values(spec, values)`` or the SpecError's message, parsed once per process."""
    key = (id(spec), _canonical(values))
    hit = _VARIANTS.get(key)
    if hit is not None and hit[0] is spec:
        return hit[1]
    try:
        out = with_values(spec, values) if values else spec
    except GovoptError as exc:
        out = str(exc)
    if len(_VARIANTS) >= _CACHE_SIZE:
        _VARIANTS.pop(next(iter(_VARIANTS)))
    _VARIANTS[key] = (spec, out)
    return out


def _spans(points: list[dict]) -> dict:
    """Per design key whose values are numbers in one unit: ``(smallest, largest, unit)``."""
    out = {}
    for k in (points[0] if points else {}):
        if k.startswith("design."):
            nums = _numbers([p[k] for p in points])
            if nums is not None:
                out[k] = (float(nums[0].min()), float(nums[0].max()), nums[1])
    return out


def _merge_spans(parts) -> dict:
    """One :func:`_spans` of several (a key in one unit throughout; else left out)."""
    out: dict = {}
    bad = set()
    for part in parts:
        for k, (lo, hi, unit) in part.items():
            old = out.get(k)
            if old is None:
                out[k] = (lo, hi, unit)
            elif old[2] != unit:
                bad.add(k)
            else:
                out[k] = (min(old[0], lo), max(old[1], hi), unit)
    return {k: v for k, v in out.items() if k not in bad}


def _blocks(items, size: int):
    """``items`` in lists of ``size`` (the last shorter)."""
    items = iter(items)
    while block := list(itertools.islice(items, size)):
        yield block


def _evaluate_points(study: Study, points: list[dict], spans: dict | None = None) -> pd.DataFrame:
    """Rows of evaluate-mode points (a frame in the points' order): grouped by their
    non-design values (one spec each), the design values of a group evaluated at once by
    :func:`govopt.bulk.evaluate_many`."""
    from dataclasses import fields as dc_fields

    from .bulk import DESIGN_FIELDS, evaluate_many
    from .spec import Design

    base = study.base()
    kw = {k: k not in study.skip for k in SKIPPABLE}
    keys = list(points[0]) if points else []
    design_keys = [k for k in keys if k.startswith("design.")]
    other_keys = [k for k in keys if not k.startswith("design.")]
    groups: dict[tuple, list[int]] = {}
    for i, p in enumerate(points):
        groups.setdefault(tuple(_canonical(p[k]) for k in other_keys), []).append(i)
    parts = []
    names = [f.name for f in dc_fields(Design)]
    for values_key, idx in groups.items():
        other = {k: json.loads(v) for k, v in zip(other_keys, values_key, strict=True)}
        idx_arr = np.asarray(idx)
        written = pd.DataFrame({k: [points[i][k] for i in idx] for k in keys}, index=idx_arr)
        spec = _variant(base, other)
        if isinstance(spec, str):
            parts.append(written.assign(objective_value=math.nan, status="error", message=spec))
            continue
        combined = len(design_keys) > 1 and isinstance(
            _variant(base, {**other, **{k: points[idx[0]][k] for k in design_keys}}), str)
        if combined and all(not isinstance(_variant(spec, {k: points[idx[0]][k]}), str)
                            for k in design_keys):  # keys the parser refuses together:
            rows = []                                 # each point in full
            rows = []
            for i in idx:
                si = _variant(base, points[i])
                if isinstance(si, str):
                    rows.append(_error(points[i], si))
                else:
                    row = evaluate_many(si, [si.design], **kw).iloc[0].to_dict()
                    rows.append({**_input_columns(si, points[i]), **row})
            parts.append(pd.DataFrame.from_records(rows, index=idx_arr))
            continue
        base_design = spec.design
        values = {f: np.full(len(idx), np.nan if base_design is None or getattr(
            base_design, f) is None else float(getattr(base_design, f))) for f in names}
        si_cols: dict[str, np.ndarray] = {}
        bad = np.full(len(idx), None, dtype=object)
        for k in design_keys:
            fields_k, si_col, si, errors = _key_values(spec, k, list(written[k]),
                                                       (spans or {}).get(k))
            for f, v in fields_k.items():
                values[f] = np.where(np.isnan(v), values[f], v)
            for j, msg in errors.items():
                bad[j] = bad[j] or msg
            if si_col is not None:
                si_cols[si_col] = si
        for k in other_keys:
            e = next((e for e in spec.entries if e.key == k), None)
            if e is not None and isinstance(e.si, float):
                si_cols[_si_column(k, e.unit)] = np.full(len(idx), e.si)
        inputs = pd.concat([written, pd.DataFrame(si_cols, index=idx_arr)], axis=1)
        good = np.array([b is None for b in bad])
        if good.any():
            frame = evaluate_many(spec, {f: values[f][good] for f in DESIGN_FIELDS}, **kw)
            frame.index = idx_arr[good]
            parts.append(pd.concat([inputs.loc[idx_arr[good]], frame], axis=1))
        if not good.all():
            parts.append(written.loc[idx_arr[~good]].assign(
                objective_value=math.nan, status="error", message=list(bad[~good])))
    return pd.concat(parts).sort_index() if parts else pd.DataFrame()


#: distinct values of a design key parsed one by one; more are mapped linearly (_key_values)
EXACT_VALUES = 64

_WRITTEN = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*")


def _numbers(values: list):
    """``(numbers, unit)`` when every value is a number, or a number in one common unit
    (``"12.5 kgf"``); else None."""
    nums, units = [], set()
    for v in values:
        if isinstance(v, bool):
            return None
        if isinstance(v, int | float):
            if not -1e300 < v < 1e300:  # beyond floating point (or NaN): parsed one by one
                return None
            nums.append(float(v))
            units.add("")
            continue
        m = _WRITTEN.fullmatch(v) if isinstance(v, str) else None
        if m is None:
            return None
        nums.append(float(m[1]))
        units.add(m[2])
    return (np.array(nums), units.pop()) if len(units) == 1 else None


def _key_values(spec: Spec, key: str, written: list, span: tuple | None = None):
    """The :class:`~govopt.spec.Design` fields that the design key ``key`` sets, for each of
    the values ``written``: ``(fields, SI column, SI values, errors)`` with ``fields`` a dict of
    field -> array (NaN where unchanged) and ``errors`` index -> the parser's message.

    Up to :data:`EXACT_VALUES` distinct values each give a variant of the spec, parsed in full
    (``spec.with_values``: every check, the exact conversion). Beyond that (a fine range, a
    tolerance study's samples), where every value is a number in one unit, the smallest and the
    largest (and one non-integral value, if any) are parsed in full and the rest mapped
    linearly: a design value's SI form is proportional to the number written (``m = W/g``,
    ``f = 3 a1``, ``d``: pint's unit factor), and the parser's checks on a single value are
    intervals (positive, within a range), so the values between two valid ones are valid.
    ``span`` (the whole study's ``(smallest, largest, unit)``) is probed first, so that a range
    cut into chunks is parsed twice in all. Cross-key checks (a wire thinner than its coil) are
    :func:`govopt.bulk.evaluate_many`'s."""
    from dataclasses import fields as dc_fields

    from .spec import Design

    names = [f.name for f in dc_fields(Design)]
    base = spec.design
    n = len(written)
    if all(isinstance(v, str | int | float) and not isinstance(v, bool) for v in written):
        # NaN is a value of its own (parsed, and refused), not "unchanged"
        codes, uniq = pd.factorize(pd.Series(written, dtype=object), use_na_sentinel=False)
        uvals = list(uniq)
    else:
        codes, uniq = pd.factorize(pd.Series([_canonical(v) for v in written]))
        uvals = [json.loads(t) for t in uniq]

    def changes(variant) -> dict:
        out = {}
        for f in names:
            a_ = None if base is None else getattr(base, f)
            b_ = None if variant.design is None else getattr(variant.design, f)
            if a_ != b_:
                out[f] = math.nan if b_ is None else float(b_)
        return out

    def entry(variant):
        e = next((e for e in variant.entries if e.key == key), None)
        return (None, math.nan) if e is None or not isinstance(e.si, float) else (
            _si_column(key, e.unit), e.si)

    nums = _numbers(uvals) if len(uvals) > EXACT_VALUES else None
    if nums is not None:
        x, unit = nums
        known = _LINEAR.get((id(spec), key, unit))
        if span is not None and span[2] == unit and (known is None or known["spec"] is not spec):
            ends = np.array(span[:2])
            _linear_map(spec, key, unit, ends, [_written(v, unit) for v in ends], changes,
                        entry)
        lin = _linear_map(spec, key, unit, x, uvals, changes, entry)
        if lin is not None:
            slopes, col, si_slope = lin
            return ({f: a * x[codes] for f, a in slopes.items()}, col, si_slope * x[codes], {})
    fields_k = {}
    errors: dict[int, str] = {}
    col, si = None, np.full(n, np.nan)
    for c, value in enumerate(uvals):
        variant = _variant(spec, {key: value})
        rows_c = np.nonzero(codes == c)[0]
        if isinstance(variant, str):
            errors.update({int(j): variant for j in rows_c})
            continue
        for f, v in changes(variant).items():
            fields_k.setdefault(f, np.full(n, np.nan))[rows_c] = v
        col_c, si_c = entry(variant)
        if col_c is not None:
            col = col_c
            si[rows_c] = si_c
    return fields_k, col, si, errors


def _written(x: float, unit: str):
    return float(x) if not unit else f"{float(x)!r} {unit}"


def _linear_map(spec, key, unit, x, uvals, changes, entry):
    """``(field slopes, SI column, SI slope)`` of the values ``x`` of a design key written in
    ``unit``, or None where a probe fails or the map is not linear (see :func:`_key_values`).
    The interval of numbers known valid grows as chunks come; only values outside it are
    probed."""
    ck = (id(spec), key, unit)
    known = _LINEAR.get(ck)
    if known is not None and known["spec"] is not spec:
        known = None
    frac = x != np.round(x)
    probes = []
    for i in (int(np.argmin(x)), int(np.argmax(x))):
        if known is None or not known["lo"] <= x[i] <= known["hi"]:
            probes.append(i)
    if frac.any() and (known is None or not known["fractions"]) and not any(
            frac[i] for i in probes):
        probes.append(int(np.nonzero(frac)[0][0]))
    if known is None and len(probes) < 2:  # all values equal: one parse, then the map
        probes = probes or [0]
    parsed = {i: _variant(spec, {key: uvals[i]}) for i in probes}
    if any(isinstance(v, str) for v in parsed.values()):
        return None
    slopes = dict(known["slopes"]) if known is not None else {}
    col, si_slope = (known["col"], known["si"]) if known is not None else (None, math.nan)
    for i, v in parsed.items():
        if x[i] == 0:
            return None
        for f, want in changes(v).items():
            slope = slopes.setdefault(f, want / x[i])
            if not abs(slope * x[i] - want) <= 1e-12 * abs(want):
                return None
        col_i, si_i = entry(v)
        if col_i is not None:
            col = col_i
            si_slope = si_slope if math.isfinite(si_slope) else si_i / x[i]
    valid = [x[i] for i in parsed] + ([known["lo"], known["hi"]] if known else [])
    if len(_LINEAR) >= _CACHE_SIZE:
        _LINEAR.pop(next(iter(_LINEAR)))
    _LINEAR[ck] = {"spec": spec, "lo": min(valid), "hi": max(valid), "slopes": slopes,
                   "col": col, "si": si_slope,
                   "fractions": bool((known and known["fractions"]) or any(
                       frac[i] for i in parsed))}
    if not (min(valid) <= x.min() and x.max() <= max(valid)):
        return None
    return slopes, col, si_slope


def _design_points(study: Study, points: list[dict]) -> list[dict]:
    """Rows of design-mode points: each designed by :func:`govopt.design` and flattened by
    :func:`govopt.bulk.result_row`, with the optimiser's objective and status."""
    from .bulk import result_row
    from .errors import InfeasibleError
    from .optimize.search import design

    base = study.base()
    rows = []
    for p in points:
        spec = _variant(base, p)
        if isinstance(spec, str):
            rows.append(_error(p, spec))
            continue
        try:
            res = design(spec)
        except InfeasibleError as exc:
            rows.append({**_input_columns(spec, p), "objective_value": math.nan,
                         "status": "infeasible", "message": str(exc)})
            continue
        except GovoptError as exc:
            rows.append({**_input_columns(spec, p), **_error({}, str(exc))})
            continue
        row = {**_input_columns(spec, p), **result_row(res)}
        opt = res.optimisation
        row["objective"] = opt["objective"]["name"]
        row["objective_value"] = float(next(v for k, v in opt["objective"].items()
                                            if k.startswith("value")))
        row["status"] = opt["status"]
        if opt["status"] == "optimal":
            row["message"] = ""
        rows.append(row)
    return rows


# ---------------------------------------------------------------------------------------------
# The store
# ---------------------------------------------------------------------------------------------

_SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS layouts (id TEXT PRIMARY KEY, columns TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS points (
    hash TEXT PRIMARY KEY,
    idx INTEGER NOT NULL,
    status TEXT NOT NULL,
    message TEXT,
    layout TEXT NOT NULL REFERENCES layouts (id),
    numbers BLOB NOT NULL,
    texts TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS points_idx ON points (idx);
"""


def encode(frame: pd.DataFrame, hashes: list[str], idx: list[int], keys=()) -> tuple:
    """Rows of a frame as database records: ``(layouts, records)``. A layout is the list of
    ``[column, kind]`` (kind ``f`` a float, ``b`` a nullable boolean, ``o`` anything else, as
    JSON; the swept keys as written are always ``o``); a record is ``(hash, idx, status,
    message, layout id, numbers, texts)`` with the ``f`` and ``b`` columns as the bytes of a
    float64 array (exact, compact) and the ``o`` columns as a JSON list."""
    frame = frame.reset_index(drop=True)
    layout = []
    dtypes = frame.dtypes.to_dict()
    for c, dt in dtypes.items():
        kind = ("o" if c in keys or c in ("status", "message") else
                "b" if pd.api.types.is_bool_dtype(dt) else
                "f" if pd.api.types.is_float_dtype(dt) or pd.api.types.is_integer_dtype(dt)
                else "o")
        layout.append([c, kind])
    lid = hashlib.sha256(json.dumps(layout).encode()).hexdigest()[:16]
    nums = [c for c, k in layout if k in "fb"]
    objs = [c for c, k in layout if k == "o"]
    matrix = np.empty((len(frame), len(nums)))
    # numpy columns at once (NaN written as np.nan, as a missing value of the others is)
    plain = [j for j, c in enumerate(nums) if isinstance(dtypes[c], np.dtype)]
    if plain:
        matrix[:, plain] = frame[[nums[j] for j in plain]].to_numpy(dtype=float)
        matrix[np.isnan(matrix)] = np.nan
    for j in sorted(set(range(len(nums))) - set(plain)):
        matrix[:, j] = frame[nums[j]].astype("Float64").to_numpy(dtype=float, na_value=np.nan)
    texts = frame[objs].astype(object).where(frame[objs].notna(), None).values.tolist()
    status = frame["status"].astype(str).tolist() if "status" in frame else ["error"] * len(
        frame)
    message = frame["message"].tolist() if "message" in frame else [""] * len(frame)
    records = [(h, int(i), st, msg, lid, np.ascontiguousarray(matrix[r]).tobytes(),
                json.dumps(t, default=_json_default))
               for r, (h, i, st, msg, t) in enumerate(zip(hashes, idx, status, message, texts,
                                                          strict=True))]
    return {lid: layout}, records


def _json_default(o):
    if o is pd.NA:
        return None
    if isinstance(o, np.bool_):
        return bool(o)
    if isinstance(o, np.integer):
        return int(o)
    if isinstance(o, np.floating):
        return float(o)
    return str(o)


def decode(layout: list, numbers: list[bytes], texts: list[str]) -> pd.DataFrame:
    """The frame of records of one layout (the inverse of :func:`encode`)."""
    nums = [c for c, k in layout if k in "fb"]
    matrix = np.frombuffer(b"".join(numbers), dtype=float).reshape(len(numbers), len(nums))
    objs = [json.loads(t) for t in texts]
    cols, j, o = {}, 0, 0
    for c, k in layout:
        if k == "o":
            cols[c] = [row[o] for row in objs]
            o += 1
            continue
        v = matrix[:, j]
        j += 1
        cols[c] = pd.arrays.BooleanArray(v == 1.0, np.isnan(v)) if k == "b" else v
    return pd.DataFrame(cols)


#: the tables of a govopt study database (a file that has them is one)
_TABLES = ("layouts", "meta", "points")
#: seconds a writer waits for another's transaction (a chunk's rows) before giving up
BUSY_SECONDS = 30.0


def _describe(exc: sqlite3.Error) -> str:
    """What an SQLite error means for a study database, in words (one line)."""
    text = str(exc)
    if "malformed" in text or "corrupt" in text:
        return (f"the study database is damaged (SQLite: {text}); 'govopt study run --force' "
                "starts it afresh")
    if "not a database" in text:
        return "not a govopt study database (not an SQLite file)"
    if "locked" in text or "busy" in text:
        return (f"the study database is busy: another process kept it locked for more than "
                f"{BUSY_SECONDS:g} s (SQLite: {text})")
    if "readonly" in text or "read-only" in text:
        return f"the study database cannot be written (SQLite: {text})"
    if "unable to open" in text:
        return f"cannot open the study database (SQLite: {text})"
    return f"study database error (SQLite: {text})"


def _uri(path: Path, **options) -> str:
    from urllib.parse import quote

    query = "&".join(f"{k}={v}" for k, v in options.items())
    return f"file:{quote(str(path.absolute()))}?{query}"


def is_study_database(path: str | Path, *, empty: bool = False) -> bool:
    """Whether ``path`` is a govopt study database (an SQLite file with the study's tables;
    with ``empty``, or with no tables at all: one being created), looked at read-only: nothing
    is written, not even to an empty file. A database another process holds locked for longer
    than :data:`BUSY_SECONDS` counts as one (its writer is govopt's, or the open says why)."""
    try:
        conn = sqlite3.connect(_uri(Path(path), mode="ro"), uri=True, timeout=BUSY_SECONDS)
    except sqlite3.Error:
        return False
    try:
        names = {n for (n,) in conn.execute("SELECT name FROM sqlite_master WHERE type = "
                                            "'table'")}
    except sqlite3.OperationalError as exc:  # busy, locked: being written
        return "locked" in str(exc) or "busy" in str(exc)
    except sqlite3.Error:
        return False
    finally:
        conn.close()
    return set(_TABLES) <= names or (empty and not names)


def check_database(path: str | Path, *, inputs: Iterable = ()) -> Path:
    """Check before a run that ``path`` can be a study's database (one line if not): not the
    spec or another input, a regular file or none, in a folder that exists and can be
    written; an existing file must be a govopt study database (or empty): nothing else is
    ever written into, nor replaced."""
    from .report.files import names_folder, refuse_package

    if str(path) in ("", ".") or Path(path).name in ("", ".", "..") or names_folder(path):
        raise StudyError(f"--db: expected a database file name, got {str(path)!r}")
    refuse_package(path, "the study database")
    path = Path(path)
    for other in inputs:
        with contextlib.suppress(OSError):
            if os.path.realpath(path) == os.path.realpath(other) or (
                    path.exists() and os.path.samefile(path, other)):
                raise StudyError(f"{path}: cannot use as the study database: it is the spec "
                                 f"({other}); give another --db")
    if path.exists() and not path.is_file():
        raise StudyError(f"{path}: cannot use as the study database: not a regular file")
    parent = path.absolute().parent
    if not parent.is_dir():
        raise StudyError(f"{path}: cannot create the study database: folder {path.parent} does "
                         "not exist")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise StudyError(f"{path}: cannot create the study database: folder {path.parent} "
                         "cannot be written (SQLite keeps its journal beside the database)")
    if path.exists():
        if not os.access(path, os.R_OK | os.W_OK):
            raise StudyError(f"{path}: the study database cannot be written (permission "
                             "denied)")
        if path.stat().st_size and not is_study_database(path, empty=True):
            raise StudyError(f"{path}: not a govopt study database (govopt writes only into "
                             "its own databases); give another --db")
    return path


def _front(front: pd.DataFrame | None, part: pd.DataFrame, study: dict) -> pd.DataFrame:
    """The rows on the Pareto front of ``study``'s objectives among the rows of ``front`` (the
    front so far) and the batch ``part``: a row dominated by one of the first is dominated by
    one on their front."""
    both = part if front is None else pd.concat([front, part], ignore_index=True)
    try:
        return both.loc[pareto_front(both, study["pareto"])].reset_index(drop=True)
    except StudyError as exc:  # an objective that is no column: name the spec
        raise StudyError(f"{study.get('spec_path', '?')}: study.{exc}") from None


class Store:
    """A study's SQLite database: ``meta`` (the study's definition, govopt's version),
    ``layouts`` (column lists) and ``points`` (one row per point: hash, index, status, message,
    and the row's values, :func:`encode`).

    WAL journal, one transaction per chunk (:meth:`add`), ``INSERT OR IGNORE`` on the point's
    hash: a process killed at any moment leaves the database as of its last commit, and two
    processes running the same study write each point once. A database belongs to one study
    (:meth:`claim`). ``create=False`` opens it read-only (``show``, ``export``): nothing is
    written, not even to a file that turns out not to be a study database. An SQLite error
    inside ``with Store(...)`` becomes one line naming the file (:class:`StudyError`)."""

    def __init__(self, path: str | Path, *, create: bool = True):
        self.path = Path(path)
        self.digest: str | None = None
        #: meta values read, when opened read-only (nothing changes them then): an old
        #: database's study holds a million-point sweep's values, parsed once
        self._read: dict | None = None if create else {}
        if not create and not self.path.is_file():
            raise StudyError(f"{self.path}: no such study database" if not self.path.exists()
                             else f"{self.path}: not a study database (not a regular file)")
        try:
            if create:
                check_database(self.path)
                self.conn = sqlite3.connect(self.path, timeout=BUSY_SECONDS,
                                            isolation_level=None)
                self.conn.execute("PRAGMA journal_mode=WAL")
                self.conn.execute("PRAGMA synchronous=NORMAL")
                with self._transaction():
                    for statement in _SCHEMA.split(";"):
                        if statement.strip():
                            self.conn.execute(statement)
            else:
                self.conn = self._read_only()
                names = {n for (n,) in self.conn.execute(
                    "SELECT name FROM sqlite_master WHERE type = 'table'")}
                if not set(_TABLES) <= names:
                    self.conn.close()
                    raise StudyError(f"{self.path}: not a govopt study database (no study "
                                     "tables)")
        except sqlite3.Error as exc:
            raise StudyError(f"{self.path}: {_describe(exc)}") from None

    def _read_only(self) -> sqlite3.Connection:
        """A read-only connection; on a read-only folder (no WAL index can be made) the file
        is read as immutable."""
        conn = sqlite3.connect(_uri(self.path, mode="ro"), uri=True, timeout=BUSY_SECONDS)
        try:
            conn.execute("SELECT COUNT(*) FROM sqlite_master").fetchone()
        except sqlite3.OperationalError:
            conn.close()
            conn = sqlite3.connect(_uri(self.path, mode="ro", immutable=1), uri=True)
        return conn

    def close(self):
        self.conn.close()

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, tb):
        self.close()
        if isinstance(exc, sqlite3.Error):
            raise StudyError(f"{self.path}: {_describe(exc)}") from None

    @contextlib.contextmanager
    def _transaction(self):
        """``BEGIN IMMEDIATE ... COMMIT``: the write lock first (waiting up to
        :data:`BUSY_SECONDS` for another writer), so that what is read inside holds."""
        self.conn.execute("BEGIN IMMEDIATE")
        try:
            yield
        except BaseException:
            with contextlib.suppress(sqlite3.Error):
                self.conn.execute("ROLLBACK")
            raise
        self.conn.execute("COMMIT")

    def meta(self, key: str):
        if self._read is not None and key in self._read:
            return self._read[key]
        row = self.conn.execute("SELECT value FROM meta WHERE key = ?", (key,)).fetchone()
        value = None if row is None else json.loads(row[0])
        if self._read is not None:
            self._read[key] = value
        return value

    def _set_meta(self, values: dict) -> None:
        self.conn.executemany("INSERT OR REPLACE INTO meta VALUES (?, ?)",
                              [(k, json.dumps(v)) for k, v in values.items()])

    def set_meta(self, values: dict) -> None:
        with self._transaction():
            self._set_meta(values)

    def _owner(self) -> str | None:
        """The digest of the study this database holds (None: none yet)."""
        digest = self.meta("digest")
        if digest is None:
            old = self.meta("study")
            digest = None if old is None else study_digest(old)
        return digest

    def claim(self, definition: dict, total: int, *, resume: bool = False,
              fresh: bool = False) -> None:
        """Make this database the study ``definition``'s, atomically (under the write lock):
        a database holding another study is refused (``fresh``: emptied first), one holding
        rows of this study needs ``resume``. Rows written later check that it still is
        (:meth:`add`)."""
        from . import __version__

        digest = study_digest(definition)
        with self._transaction():
            if fresh:
                for table in ("points", "layouts", "meta"):
                    self.conn.execute(f"DELETE FROM {table}")
            old = self._owner()
            if old is not None and old != digest:
                study = self.meta("study") or {}
                raise StudyError(f"{self.path}: the database holds another study "
                                 f"({study.get('name')!r}, {study.get('spec_path')}); use "
                                 "another --db, or --force to start afresh")
            n_old = self.count()
            if n_old and not resume:
                raise StudyError(f"{self.path}: the database already holds {n_old} rows; use "
                                 "--resume to continue the study, or --force to start afresh")
            self._set_meta({"study": definition, "digest": digest,
                            "govopt_version": __version__, "total": total})
        self.digest = digest

    def done(self, hashes: Iterable[str] | None = None) -> set[str]:
        """The hashes of the points in the database (of ``hashes`` only, if given)."""
        if hashes is None:
            return {h for (h,) in self.conn.execute("SELECT hash FROM points")}
        hashes, out = list(hashes), set()
        for s in range(0, len(hashes), 900):
            part = hashes[s:s + 900]
            out.update(h for (h,) in self.conn.execute(
                f"SELECT hash FROM points WHERE hash IN ({','.join('?' * len(part))})", part))
        return out

    def count(self) -> int:
        return self.conn.execute("SELECT COUNT(*) FROM points").fetchone()[0]

    def add(self, chunk: tuple) -> None:
        """One chunk ``(layouts, records)`` of :func:`encode`, in one transaction; a point
        already written (by another process running the same study) is kept. After
        :meth:`claim`, refused if the database no longer holds that study."""
        layouts, records = chunk
        with self._transaction():
            if self.digest is not None and self._owner() != self.digest:
                raise StudyError(f"{self.path}: another study took this database over while "
                                 "this one ran (--force); stopped")
            self.conn.executemany("INSERT OR IGNORE INTO layouts VALUES (?, ?)",
                                  [(k, json.dumps(v)) for k, v in layouts.items()])
            self.conn.executemany("INSERT OR IGNORE INTO points VALUES (?, ?, ?, ?, ?, ?, ?)",
                                  records)

    def _layouts(self) -> dict:
        return {k: json.loads(v) for k, v in self.conn.execute("SELECT * FROM layouts")}

    def batches(self, columns: Iterable[str] | None = None, *, batch: int = 20_000):
        """The rows in the study's order, ``batch`` at a time: frames with ``point`` (the
        index) and every column of the study (of all layouts, in :meth:`columns`' order;
        ``columns``: only those), without the Pareto mark (:meth:`pareto`). A study of a million
        points is read a batch at a time, never held (repeated texts such as the status held
        once)."""
        layouts = self._layouts()
        study = self.meta("study") or {}
        want = None if columns is None else {"point", *columns}
        order = ["point"] + [c for c in self.columns(layouts) if want is None or c in want]
        texts_seen: dict = {}
        cursor = self.conn.execute("SELECT idx, layout, numbers, texts FROM points ORDER BY idx")
        while rows := cursor.fetchmany(batch):
            groups: dict[str, tuple[list, list, list]] = {}
            for idx, lid, nums, texts in rows:
                g = groups.setdefault(lid, ([], [], []))
                g[0].append(idx)
                g[1].append(nums)
                g[2].append(texts)
            parts = []
            for lid, (i, n, t) in groups.items():
                part = decode(layouts[lid], n, t)
                part.insert(0, "point", i)
                if want is not None:
                    # a copy: a column of the decoded batch is a view holding all its values
                    part = part[[c for c in part.columns if c in want]].copy()
                    for c in part.columns:
                        if part[c].dtype == object and c not in study.get("keys", ()):
                            part[c] = [texts_seen.setdefault(v, v) if isinstance(v, str) else v
                                       for v in part[c]]
                parts.append(part)
            frame = pd.concat(parts, ignore_index=True) if len(parts) > 1 else parts[0]
            if len(parts) > 1 or list(frame.columns) != order:
                frame = frame.reindex(columns=order)
            if len(parts) > 1:
                frame = frame.sort_values("point", ignore_index=True)
            yield frame

    def objectives(self) -> list[str]:
        """The columns the study's Pareto front reads (none without a front)."""
        study = self.meta("study") or {}
        return ["status", *(objective_column(n)[0] for n in study.get("pareto", ()))] \
            if study.get("pareto") else []

    def pareto(self, *, batch: int = 20_000) -> np.ndarray:
        """The points (indices) on the study's Pareto front, in order, found a batch at a time:
        the front of the rows so far and the next batch is the front of both (a row dominated
        by one of the first is dominated by one on their front)."""
        study = self.meta("study") or {}
        objectives = study.get("pareto") or []
        if not objectives:
            return np.zeros(0, dtype=int)
        front = None
        for part in self.batches(self.objectives(), batch=batch):
            front = _front(front, part, study)
        return np.zeros(0, dtype=int) if front is None else front["point"].to_numpy(dtype=int)

    def table(self, columns: Iterable[str] | None = None, *, batch: int = 20_000
              ) -> pd.DataFrame:
        """Every row, in the study's order (``point`` is its index), with ``pareto`` marked
        where the study names objectives; ``columns``: only those (and what the Pareto front
        needs), read ``batch`` rows at a time (:meth:`batches`). For a whole table; a large
        study is read by :meth:`batches`."""
        study = self.meta("study") or {}
        if columns is not None:
            columns = [*columns, *self.objectives()]
        parts = list(self.batches(columns, batch=batch))
        if not parts:
            return pd.DataFrame()
        frame = pd.concat(parts, ignore_index=True) if len(parts) > 1 else parts[0]
        if study.get("pareto"):
            try:
                frame["pareto"] = pareto_front(frame, study["pareto"])
            except StudyError as exc:  # an objective that is no column: name the spec
                raise StudyError(f"{study.get('spec_path', '?')}: study.{exc}") from None
        return frame

    def columns(self, layouts: dict | None = None) -> list[str]:
        """Every column of the study's rows (of all layouts, the longest's first), in order."""
        layouts = self._layouts() if layouts is None else layouts
        return list(dict.fromkeys(c for lid in sorted(layouts, key=lambda k: -len(layouts[k]))
                                  for c, _ in layouts[lid]))

    def row(self, point: int) -> dict:
        """The row of point ``point`` (an index)."""
        lid, nums, texts = self.conn.execute(
            "SELECT layout, numbers, texts FROM points WHERE idx = ?", (point,)).fetchone()
        layout = json.loads(self.conn.execute("SELECT columns FROM layouts WHERE id = ?",
                                              (lid,)).fetchone()[0])
        return decode(layout, [nums], [texts]).iloc[0].to_dict()

    def integrity(self) -> str:
        return self.conn.execute("PRAGMA integrity_check").fetchone()[0]


# ---------------------------------------------------------------------------------------------
# Running
# ---------------------------------------------------------------------------------------------

@dataclass
class RunReport:
    total: int
    skipped: int
    done: int
    failures: int
    interrupted: bool = False


#: a point that ran: its checks passed (evaluate) or it was designed (design)
PASSED = ("pass", "optimal")


def _reasons(status: str, message: str | None, path: str) -> list[str]:
    """Why one point failed: each failed check of a ``fail`` row (``"fails: a, b"``), else its
    message (an error's or the optimiser's) without the spec's ``path``, which every point
    shares."""
    message = " ".join(str(message or status).split())
    if status == "fail" and message.startswith("fails: "):
        return [f"fails: {name}" for name in message[len("fails: "):].split(", ")]
    return [message.removeprefix(f"{path}: ")]


def outcome(store: Store | str | Path, report: RunReport | None = None) -> tuple[int, str]:
    """The exit status of a study run and its one line for stderr (``""`` when nothing failed).

    Over every row in the database ``store`` (a :class:`Store` or its path; a resumed study
    counts the rows of earlier runs too):

    * 130: the run was interrupted (``report.interrupted``): what is kept and how to resume;
    * 0: at least one point passed (or was designed); failures are counted,
      ``"3 of 10 points failed: most common reason (2 of 3): fails: irregularity"``;
    * 1: every point failed and at least one of them ran (a check failed, or the design was
      infeasible), as ``govopt evaluate`` / ``govopt design`` exit 1 when a check fails;
    * 2: every point was an error (no point could be evaluated: a user's error, as a bad spec;
      the line is ``error: SPEC: ...`` as every exit-2 line);

    a failing line names the most common reason (each failed check of a ``fail`` row counts
    once) and on how many points it occurred.
    """
    if not isinstance(store, Store):
        with Store(store, create=False) as opened:
            return outcome(opened, report)
    if report is not None and report.interrupted:
        return 130, (f"interrupted: {report.skipped + report.done} of {report.total} points are "
                     f"in {store.path}; run again with --resume to finish")
    rows = store.conn.execute(
        "SELECT status, message, COUNT(*) FROM points GROUP BY status, message").fetchall()
    total = sum(n for _, _, n in rows)
    failed = [(st, msg, n) for st, msg, n in rows if st not in PASSED]
    n_failed = sum(n for _, _, n in failed)
    if not n_failed:
        return 0, ""
    path = str((store.meta("study") or {}).get("spec_path", "?"))
    counts: dict[str, int] = {}
    for st, msg, n in failed:
        for reason in _reasons(st, msg, path):
            counts[reason] = counts.get(reason, 0) + n
    reason, n = max(counts.items(), key=lambda kv: kv[1])  # the first of equals: stable
    why = f"most common reason ({n} of {n_failed}): {limits.shorten_values(reason)}"
    if n_failed < total:
        return 0, f"{n_failed} of {total} points failed: {why}"
    if any(st != "error" for st, _, _ in failed):
        return 1, f"all {total} points failed: {why}"
    return 2, f"error: {path}: all {total} points failed (none could be evaluated): {why}"


def default_chunk(study: Study) -> int:
    """Points per chunk (and per database transaction): a vectorised batch for evaluate mode,
    one design at a time for design mode."""
    return 1024 if study.mode == "evaluate" else 1


def run_study(study: Study, db: str | Path, *, workers: int = 1, dask: str | None = None,
              resume: bool = False, fresh: bool = False, chunk: int | None = None,
              progress: Callable[[int, int, int], None] | None = None) -> RunReport:
    """Run ``study`` into the database ``db`` and return what was done.

    ``workers`` > 1: chunks on a process pool; ``dask``: ``"local"`` starts a
    ``dask.distributed.LocalCluster`` of ``workers`` processes, an address
    (``tcp://host:port``) uses a running scheduler. ``resume`` skips the points already in the
    database (which must hold this study); ``fresh`` starts afresh on a database that holds
    rows. ``progress(done, failures, total)`` is called after each chunk. Ctrl-C stops after
    the chunks already finished, which are kept (``interrupted`` in the report).
    """
    check_dask_address(dask)
    db = check_database(db, inputs=[study.path])
    total = study.count()
    definition = json.loads(json.dumps(study.definition(), default=str))
    text = json.dumps(definition, sort_keys=True)
    digest_of = _hasher(spec_digest(study.data), study.mode, tuple(sorted(study.skip)))
    size = chunk or default_chunk(study)
    spans = study.spans() if study.mode == "evaluate" else {}
    with Store(db) as store:
        try:
            store.claim(definition, total, resume=resume, fresh=fresh)
        except sqlite3.DatabaseError as exc:  # damaged: with --force, a new database
            if not fresh or "malformed" not in str(exc):
                raise
            store.close()
            remove_database(db)
            store.conn = Store(db).conn
            store.claim(definition, total, fresh=True)
        del definition  # in the database now (a million-point sweep's values: ~70 MB a copy)
        before = store.count()
        report = RunReport(total, 0, 0, 0)
        report.failures = store.conn.execute(
            "SELECT COUNT(*) FROM points WHERE status NOT IN ('pass', 'optimal')").fetchone()[0]
        # made and hashed as they are taken, never all at once (bounded memory)
        chunks = ([(i, digest_of(p), p) for i, p in block]
                  for block in _blocks(enumerate(study.iter_points()), size))

        def unwritten(c):
            """The points of chunk ``c`` not yet in the database (an earlier run's, resumed,
            or another process's running the same study: they cooperate), each once: a point
            repeated in the chunk (a grid of lists holding a value twice) is the same row,
            which ``INSERT OR IGNORE`` keeps from its first occurrence, so the repeats are not
            computed (skipped, as the points already written)."""
            seen = set(store.done(h for _, h, _ in c))
            out = []
            for item in c:
                if item[1] not in seen:
                    seen.add(item[1])
                    out.append(item)
            report.skipped += len(c) - len(out)
            return out

        def commit(chunk):
            store.add(chunk)
            records = chunk[1]
            report.done += len(records)
            report.failures += sum(r[2] not in ("pass", "optimal") for r in records)
            if progress is not None:
                progress(max(before, report.skipped + report.done), report.failures,
                         report.total)

        if progress is not None:
            progress(before, report.failures, report.total)
        try:
            if dask:
                _run_dask(text, [c for c in map(unwritten, chunks) if c], spans, commit, dask,
                          workers)
            elif workers > 1 and total > size:
                _run_pool(text, chunks, spans, commit, workers, unwritten)
            else:
                for c in chunks:
                    c = unwritten(c)
                    if c:
                        commit(run_chunk(text, c, spans))
        except KeyboardInterrupt:
            report.interrupted = True
        return report


def _ignore_sigint():
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C


def _run_pool(text, chunks, spans, commit, workers, unwritten=lambda c: c):
    """Chunks on a process pool; results committed by this process as they finish; each
    chunk's points filtered by ``unwritten`` when it is sent."""
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

    pool = ProcessPoolExecutor(max_workers=workers, initializer=_ignore_sigint)
    try:
        pending = set()
        queue = (c for c in map(unwritten, chunks) if c)
        for c in itertools.islice(queue, 2 * workers):
            pending.add(pool.submit(run_chunk, text, c, spans))
        while pending:
            finished, pending = wait(pending, return_when=FIRST_COMPLETED)
            for f in finished:
                commit(f.result())
                nxt = next(queue, None)
                if nxt is not None:
                    pending.add(pool.submit(run_chunk, text, nxt, spans))
    except BaseException:
        for p in list(getattr(pool, "_processes", {}).values()):  # stop work in flight now
            p.terminate()
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown()


#: a Dask scheduler's address: ``[protocol://]host:port`` (or an in-process cluster's)
_DASK_ADDRESS = re.compile(r"(?:(?:tcp|tls|ws|wss|ucx)://)?(?:\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+)"
                           r":(\d{1,5})|inproc://[\w.:/-]+")


def check_dask_address(address: str | None) -> None:
    """``--dask``: ``"local"`` or a scheduler's ``[tcp://]HOST:PORT`` (one line if not)."""
    if address is None or address == "local":
        return
    m = _DASK_ADDRESS.fullmatch(str(address))
    if m is None or (m[1] is not None and not 0 < int(m[1]) < 65536):
        raise StudyError(f"--dask: expected 'local' or a scheduler address HOST:PORT or "
                         f"tcp://HOST:PORT, got {limits.shorten(address)}")


def _run_dask(text, chunks, spans, commit, address, workers):
    """Chunks on a Dask cluster: ``"local"`` starts a ``LocalCluster`` (``workers`` processes,
    one thread each), an address uses a running scheduler."""
    try:
        from dask.distributed import Client, LocalCluster, as_completed
    except ImportError:
        raise StudyError("--dask needs dask.distributed (pip install 'dask[distributed]')") \
            from None
    cluster = None
    if address == "local":
        cluster = LocalCluster(n_workers=max(1, workers), threads_per_worker=1,
                               processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        try:
            client = Client(address, timeout=30)
        except OSError as exc:
            raise StudyError(f"--dask {address}: cannot reach the scheduler ({exc})") from None
    try:
        futures = client.map(run_chunk, [text] * len(chunks), chunks,
                             [spans] * len(chunks), pure=False)
        for fut in as_completed(futures):
            commit(fut.result())
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


# ---------------------------------------------------------------------------------------------
# Reading results
# ---------------------------------------------------------------------------------------------

def objective_column(name: str) -> tuple[str, str]:
    """``(column, "min" | "max")`` of an objective name (:data:`OBJECTIVES`, a column, or
    ``max:<column>``)."""
    name = name.strip()
    if name.startswith("max:"):
        return objective_column(name[4:])[0], "max"
    if name.startswith("min:"):
        return objective_column(name[4:])[0], "min"
    return OBJECTIVES.get(name, (name, "min"))


def feasible(frame: pd.DataFrame) -> np.ndarray:
    return frame["status"].isin(["pass", "optimal"]).to_numpy()


def pareto_front(frame: pd.DataFrame, objectives) -> np.ndarray:
    """Whether each row is on the Pareto front of ``objectives`` (minimised; ``max:`` for
    maximised): feasible, finite in every objective, and no other such row at least as good in
    all and better in one."""
    if not feasible(frame).any():  # no row evaluated: no front (nor, maybe, its columns)
        return np.zeros(len(frame), bool)
    cols = []
    for name in objectives:
        col, sense = objective_column(name)
        if col not in frame:
            raise StudyError(f"pareto: no column {col!r} in the study's table (objectives: "
                             f"{', '.join(OBJECTIVES)}, or a column name)")
        v = pd.to_numeric(frame[col], errors="coerce").to_numpy(dtype=float)
        cols.append(-v if sense == "max" else v)
    F = np.column_stack(cols)
    ok = feasible(frame) & np.isfinite(F).all(axis=1)
    out = np.zeros(len(frame), bool)
    idx = np.nonzero(ok)[0]
    if idx.size == 0:
        return out
    P = F[idx]
    order = np.lexsort(P.T[::-1])  # by the first objective, ties by the next
    keep: list[int] = []
    for i in order:  # a row is dominated only by rows before it in this order
        p = P[i]
        if keep:
            K = P[keep]
            if np.any(np.all(K <= p, axis=1) & np.any(K < p, axis=1)) or np.any(
                    np.all(K == p, axis=1)):
                continue
        keep.append(i)
    out[idx[keep]] = True
    return out


#: the columns whose spread a tolerance study reports
SPREAD = ("omega_inner_rad_s", "omega_outer_rad_s", "irregularity", "k2_normal_rad2_s2")


def tolerance_summary(frames) -> dict:
    """Per requirement, the probability it holds over the samples with its 95 % Wilson
    interval (a sample that cannot be evaluated counts as not holding), and the spread of the
    speed range (mean, standard deviation, 2.5 and 97.5 percentiles). ``frames``: the study's
    table, or its batches (:meth:`Store.batches`: counted a batch at a time, the spread's
    columns kept as numbers only)."""
    from .bulk import check_names, passed_column

    if isinstance(frames, pd.DataFrame):
        frames = [frames]
    n = errors = all_k = 0
    holds: dict[str, int] = {}
    values: dict[str, list] = {}
    for frame in frames:
        n += len(frame)
        for name in check_names(frame.columns):
            p = frame[passed_column(name)]
            holds[name] = holds.get(name, 0) + int((p == True).sum())  # noqa: E712 (nullable)
        ok = frame["status"] != "error"
        errors += int((~ok).sum())
        all_k += int((frame["status"] == "pass").sum())
        for col in SPREAD:
            if col in frame:
                values.setdefault(col, []).append(pd.to_numeric(
                    frame.loc[ok, col], errors="coerce").dropna().to_numpy(dtype=float))
    checks = {}
    for name, k in holds.items():
        lo, hi = wilson(k, n)
        checks[name] = {"probability": k / n if n else math.nan, "ci95": [lo, hi], "holds": k,
                        "samples": n}
    lo, hi = wilson(all_k, n)
    spread = {}
    for col, parts in values.items():
        v = np.concatenate(parts)
        if v.size:
            spread[col] = {"mean": float(v.mean()), "std": float(v.std(ddof=1))
                           if v.size > 1 else 0.0,
                           "p2.5": float(np.percentile(v, 2.5)),
                           "p97.5": float(np.percentile(v, 97.5))}
    return {"samples": n, "errors": errors,
            "all_requirements": {"probability": all_k / n if n else math.nan, "ci95": [lo, hi]},
            "checks": checks, "spread": spread}


def _drawn(value) -> str:
    """A swept input as a drawing gives it: a number (or a number and its unit) to 4
    significant digits (``"0.05976 m"``, not ``"0.05975979807254938 m"``); anything else as
    is.

    >>> _drawn("0.05975979807254938 m"), _drawn(0.12), _drawn("exact")
    ('0.05976 m', '0.12', 'exact')
    """
    text = str(value)
    match = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)(\s*.*)", text)
    return f"{float(match[1]):.4g}{match[2]}" if match else text


def _speed_unit(data) -> tuple[str, float]:
    """The unit the spec states its speeds in (``[speed] inner``, ``mean`` or ``outer``, e.g.
    ``"240 rpm"``) and its value of 1 rad/s; rpm where the spec gives none that converts."""
    from .units import to_unit

    speed = data.get("speed") if isinstance(data, dict) else None
    texts = [speed.get(k) for k in ("inner", "mean", "outer")] if isinstance(speed, dict) else []
    parts = next((t.split(None, 1) for t in texts if isinstance(t, str)), [])
    if len(parts) == 2:
        try:
            return parts[1].strip(), float(to_unit(1.0, "angular_velocity", parts[1].strip()))
        except (ValueError, TypeError, AttributeError):  # pint's errors: not a speed unit
            pass
    return "rpm", 30.0 / math.pi


def summary_text(store: Store) -> str:
    """What `govopt study show` prints: the study, its progress, status counts, the best
    feasible point, the Pareto front and, for a tolerance study, the probabilities. The rows
    are read a batch at a time (:meth:`Store.batches`), only the columns shown: a summary of a
    million points holds one batch, the front and the tolerance study's spread."""
    from .bulk import check_names, passed_column

    study = store.meta("study") or {}
    total = store.meta("total") or 0
    needed = ["status", "objective", "objective_value", *store.objectives()]
    tolerances = bool(study.get("tolerances"))
    if tolerances:  # what tolerance_summary reads
        checks = check_names(store.columns())
        needed += [passed_column(c) for c in checks] + [f"margin: {c}" for c in checks] + list(
            SPREAD)
    best = None  # (value, point, objective name): the first of the least
    counts: dict[str, int] = {}  # most first; equals in the order they first occur
    front = None

    def scan():
        nonlocal best, front
        for part in store.batches(needed):
            for k, v in part["status"].value_counts(sort=False).items():
                counts[k] = counts.get(k, 0) + int(v)
            if study.get("pareto"):
                front = _front(front, part, study)
            v = pd.to_numeric(part["objective_value"], errors="coerce")
            ok = feasible(part) & v.notna().to_numpy()
            if ok.any():
                i = int(np.argmin(np.where(ok, v.to_numpy(dtype=float), np.inf)))
                if best is None or v.iloc[i] < best[0]:
                    best = (float(v.iloc[i]), int(part["point"].iloc[i]),
                            part["objective"].iloc[i])
            yield part

    if tolerances:
        summary = tolerance_summary(scan())
    else:
        for _ in scan():
            pass
    n = sum(counts.values())
    lines = [f"study {study.get('name', '?')!r}: {study.get('mode')} mode on "
             f"{study.get('spec_path')}, {', '.join(study.get('keys', []))} "
             f"({study.get('combine')}); govopt {store.meta('govopt_version')}",
             f"points: {n} of {total} done"]
    if not n:
        return "\n".join(lines)
    lines.append("status: " + ", ".join(f"{k} {v}" for k, v in sorted(
        counts.items(), key=lambda kv: -kv[1])))
    if best is not None:
        written = store.row(best[1])
        inputs = ", ".join(f"{k} = {_drawn(written[k])}" for k in study.get("keys", [])
                           if k in written)
        name = best[2] if isinstance(best[2], str) else "objective"
        lines.append(f"best feasible {name}: {best[0]:.6g} at point {best[1]} ({inputs})")
    if study.get("pareto"):
        front = np.zeros(0, dtype=int) if front is None else front["point"].to_numpy(dtype=int)
        lines.append(f"Pareto front ({', '.join(study['pareto'])}): {len(front)} points: "
                     + ", ".join(str(int(i)) for i in front[:20]))
    error = store.conn.execute("SELECT message FROM points WHERE status = 'error' ORDER BY idx "
                               "LIMIT 1").fetchone()
    if error is not None:
        lines.append(f"first error: {error[0]}")
    if tolerances:
        s = summary
        a = s["all_requirements"]
        lines.append(f"tolerance study, {s['samples']} samples: all requirements hold with "
                     f"probability {a['probability']:.4f} (95 % CI {a['ci95'][0]:.4f}-"
                     f"{a['ci95'][1]:.4f})")
        for name, c in s["checks"].items():
            lines.append(f"  {name}: {c['probability']:.4f} ({c['ci95'][0]:.4f}-"
                         f"{c['ci95'][1]:.4f})")
        unit, per = _speed_unit(study.get("spec"))
        for col, v in s["spread"].items():  # speeds in the spec's own unit
            scale, name = ((per, col.replace("_rad_s", f"_{unit}"))
                           if col.endswith("_rad_s") else (1.0, col))
            lines.append(f"  {name}: mean {v['mean'] * scale:.6g}, std {v['std'] * scale:.3g}, "
                         f"95 % of samples in [{v['p2.5'] * scale:.6g}, "
                         f"{v['p97.5'] * scale:.6g}]")
    return "\n".join(lines)


class _MixedColumn(Exception):
    """A column of numbers in an export's first batch holds texts further on (its name)."""


def _text_or_none(v):
    """A cell of a typed export's text column: the value as text, or None where missing."""
    if v is None or v is pd.NA or (isinstance(v, float) and math.isnan(v)):
        return None
    return v if isinstance(v, str) else str(v)


def export(store: Store, path: str | Path, *, overwrite: bool = False,
           batch: int = 20_000) -> Path:
    """Write the study's table as CSV, Parquet or xlsx (by the file's extension), atomically
    (:func:`govopt.report.files.atomic_write`: never a partial file; an existing file replaced
    only with ``overwrite``), ``batch`` rows at a time (:meth:`Store.batches`: a million-point
    study is never held; the Pareto front is found first, :meth:`Store.pareto`). In Parquet and
    xlsx the columns of written inputs and texts are text (inputs written as numbers or
    strings)."""
    from .report.files import atomic_write

    path = Path(path)
    kind = path.suffix.lower()
    if kind not in (".csv", ".parquet", ".xlsx"):
        raise StudyError(f"{path}: expected a .csv, .parquet or .xlsx file")
    study = store.meta("study") or {}
    front = store.pareto(batch=batch) if study.get("pareto") else None
    kinds = {c: k for layout in store._layouts().values() for c, k in layout}
    columns = ["point", *store.columns(), *(["pareto"] if front is not None else [])]

    def frames(text: set | None = None):
        """The table's batches; with ``text`` (typed formats) the columns of texts as text
        (those of texts or mixed values in the first batch, and those in ``text``), booleans
        nullable."""
        first = True
        for part in store.batches(batch=batch):
            if front is not None:
                part["pareto"] = part["point"].isin(front).to_numpy()
            if text is not None:
                for c in part.columns:
                    if kinds.get(c) == "b":
                        part[c] = part[c].astype("boolean")
                        continue
                    if kinds.get(c) != "o":
                        continue
                    if first and part[c].dtype == object:
                        text.add(c)
                    elif c not in text and part[c].dtype == object:  # numbers, then texts
                        raise _MixedColumn(c)
                    if c in text:
                        part[c] = [_text_or_none(v) for v in part[c]]
            first = False
            yield part

    def csv(tmp):
        with open(tmp, "w", newline="", encoding="utf-8") as f:
            first = True
            for part in frames():
                part.to_csv(f, header=first, index=False)
                first = False
            if first:
                pd.DataFrame(columns=columns).to_csv(f, index=False)

    def typed(write_batches):
        """``write_batches(frames)`` again with a column of numbers that turns out to hold
        texts further on written as text throughout (a file's column has one type)."""
        text: set[str] = set()
        while True:
            try:
                return write_batches(frames(text))
            except _MixedColumn as exc:
                text.add(exc.args[0])

    def parquet(tmp):
        import pyarrow as pa
        import pyarrow.parquet as pq

        def write_batches(parts):
            writer = None
            try:
                for part in parts:
                    table = pa.Table.from_pandas(part, preserve_index=False)
                    if writer is None:
                        writer = pq.ParquetWriter(tmp, table.schema)
                    elif not table.schema.equals(writer.schema, check_metadata=False):
                        try:
                            table = table.cast(writer.schema)
                        except (pa.ArrowInvalid, pa.ArrowTypeError, pa.ArrowNotImplementedError):
                            bad = next(f.name for f in writer.schema
                                       if table.schema.field(f.name).type != f.type)
                            raise _MixedColumn(bad) from None
                    writer.write_table(table.replace_schema_metadata(writer.schema.metadata))
                if writer is None:
                    pq.write_table(pa.Table.from_pandas(pd.DataFrame(columns=columns),
                                                        preserve_index=False), tmp)
            finally:
                if writer is not None:
                    writer.close()

        typed(write_batches)

    def xlsx(tmp):
        from openpyxl import Workbook
        from openpyxl.cell import WriteOnlyCell
        from openpyxl.styles import Font

        def write_batches(parts):
            book = Workbook(write_only=True)
            sheet = book.create_sheet("study")
            header = []
            for c in columns:
                cell = WriteOnlyCell(sheet, value=c)
                cell.font = Font(bold=True)
                header.append(cell)
            sheet.append(header)
            try:
                for part in parts:
                    for row in part.astype(object).itertuples(index=False, name=None):
                        sheet.append([None if v is None or v is pd.NA or (
                            isinstance(v, float) and math.isnan(v)) else
                            v.item() if isinstance(v, np.generic) else v for v in row])
            except BaseException:  # the sheet's temporary file closed, then written again
                with contextlib.suppress(Exception):
                    sheet.close()
                raise
            book.save(tmp)

        typed(write_batches)

    write = {".csv": csv, ".parquet": parquet, ".xlsx": xlsx}[kind]
    return atomic_write(path, write, overwrite=overwrite, what="study table")


def remove_database(path: Path) -> None:
    """Remove a study database and its WAL files (regular files only)."""
    for suffix in ("", "-wal", "-shm"):
        p = Path(str(path) + suffix)
        if p.exists() and p.is_file():
            os.unlink(p)
