"""What a study is: a spec and the inputs to vary in it, and the values of its points.

A study (:class:`Study`) is a spec plus sweeps of dotted spec keys (:class:`Sweep`:
``design.pendulum_weight = 6 kgf:12 kgf:4``, ``speed.irregularity = 0.12,0.104``) combined as
a grid, zipped, or sampled (Latin hypercube, Sobol'), or manufacturing tolerances sampled
around the spec's own design (:mod:`govopt.study.tolerances`). Its points are numbered in
order; a point's values are a function of the study's definition and its number
(:meth:`Study.values`), so any process makes any block of points from the definition alone,
and a study of a million points never holds them.

Values are kept as numbers: a numeric sweep holds its values' magnitudes in one unit (the
unit written), a tolerance study its draws in SI; only a sweep of values that are not numbers
in one unit (``exact,series``; ``1 cm, 2 kg``) keeps them as written, and the spec parser reads
each. :meth:`Sweep.toml` writes a value as the spec file would, for the parser, at the one
place a point meets it (:func:`govopt.spec.with_values`).
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from pathlib import Path

import numpy as np

from .. import limits
from ..reader import read_spec_data
from ..spec import Spec, parse_spec
from .errors import StudyError
from .quantities import number_text, quantity
from .sampling import SAMPLERS, check_seed, unit_cube
from .tolerances import Tolerance, check_bands, fixed_free_length, grade_tolerances, nominal

MODES = ("evaluate", "design")
COMBINE = ("grid", "zip", *SAMPLERS)
SKIPPABLE = ("dynamics", "vibration", "classic")
#: the keys of a spec's ``[study]`` table
STUDY_KEYS = ("mode", "combine", "samples", "seed", "skip", "pareto", "sweep", "tolerance",
              "name")
#: samples of a tolerance study when none are asked for
DEFAULT_SAMPLES = 1000

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
#: a number alone, or a number and a unit as a spec writes them (``12.5 kgf``)
_PLAIN = re.compile(_NUMBER)
_WRITTEN = re.compile(rf"\s*({_NUMBER})\s*(.*?)\s*")


def _scalar(text: str):
    """A list item as it would be written in TOML: a number, a boolean, else the text."""
    text = text.strip()
    if _PLAIN.fullmatch(text):
        return int(text) if re.fullmatch(r"[-+]?\d+", text) else float(text)
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    return text


def _is_number(v) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool)


@dataclass(frozen=True)
class Sweep:
    """One swept key: a range (``start``, ``stop`` and ``num`` values, in ``unit``; ``num``
    None for a range only the samplers read) or a list of ``values``. A numeric list holds
    magnitudes in ``unit``; a ``text`` list holds values as written (numbers, booleans, texts),
    each read by the spec parser. ``integer``: whole numbers (rounded in a range)."""

    key: str
    values: tuple = ()
    start: float | None = None
    stop: float | None = None
    num: int | None = None
    unit: str = ""
    integer: bool = False
    text: bool = False

    @property
    def is_range(self) -> bool:
        return self.start is not None

    def __len__(self) -> int:
        return (self.num or 0) if self.is_range else len(self.values)

    @classmethod
    def parse(cls, key: str, text) -> Sweep:
        """``START:STOP:NUM`` (a range, with units: ``6 kgf:12 kgf:4``; ``NUM`` may be left out
        for sampled studies), ``v1,v2,...`` (a list; a unit after the last value applies to
        bare numbers before it: ``12,10,8 kgf``), a TOML list, or a table
        ``{start, stop, num}``."""
        key = key.strip()
        if not key:
            raise StudyError("expected KEY=VALUES, got an empty key", where="sweep")
        where = f"sweep {key}"
        if isinstance(text, list):
            if not text:
                raise StudyError("expected at least one value", where=where)
            return cls.listed(key, text)
        if isinstance(text, dict):
            unknown = set(text) - {"start", "stop", "num"}
            if unknown or not {"start", "stop"} <= set(text):
                raise StudyError("expected a table {start, stop, num}", where=where)
            text = f"{text['start']}:{text['stop']}" + (f":{text['num']}" if "num" in text
                                                        else "")
        if not isinstance(text, str):
            return cls.listed(key, [text])
        if ":" in text:
            return cls._range(key, text, where)
        items = [p.strip() for p in text.split(",")]
        if any(not p for p in items):
            raise StudyError(f"empty value in {limits.shorten(text)}", where=where)
        values = [_scalar(p) for p in items]
        last = values[-1]
        if isinstance(last, str) and len(values) > 1 and all(map(_is_number, values[:-1])):
            m = _WRITTEN.fullmatch(last)
            if m and m[2]:  # '12,10,8 kgf': the unit after the last applies to all
                values = [f"{number_text(v)} {m[2]}" for v in values[:-1]] + [last]
        return cls.listed(key, values)

    @classmethod
    def _range(cls, key: str, text: str, where: str) -> Sweep:
        parts = text.split(":")
        if len(parts) not in (2, 3):
            raise StudyError(f"expected START:STOP:NUM, got {limits.shorten(text)}", where=where)
        num = None
        if len(parts) == 3:
            try:
                num = int(parts[2])
            except ValueError:
                raise StudyError(f"NUM must be a whole number, got {parts[2]!r}",
                                 where=where) from None
            if num < 1:
                raise StudyError(f"NUM must be at least 1, got {num}", where=where)
            if num > limits.MAX_STUDY_POINTS:
                raise StudyError(f"NUM must be at most {limits.MAX_STUDY_POINTS} (govopt's "
                                 f"limit), got {num}", where=where)
        a, b = _scalar(parts[0]), _scalar(parts[1])
        if _is_number(a) and _is_number(b):
            integer = isinstance(a, int) and isinstance(b, int)
            start, stop, unit = float(a), float(b), ""
        else:
            qa, qb = quantity(parts[0], where), quantity(parts[1], where)
            try:
                start, stop = float(qa.magnitude), float(qb.to(qa.units).magnitude)
            except Exception:  # pint's dimensionality error
                raise StudyError(f"{parts[0]!r} and {parts[1]!r} are not of the same "
                                 "dimension", where=where) from None
            from ..units import angle_power

            if angle_power(qa) != angle_power(qb):  # '20 Hz:1400 rpm': pint's radian is 1
                raise StudyError(f"{parts[0]!r} and {parts[1]!r} differ by an angle, which pint "
                                 "cannot tell from a number; write both ends in the same kind "
                                 "of unit", where=where)
            unit, integer = ("" if qa.unitless else f"{qa.units:~}"), False
        if not (math.isfinite(start) and math.isfinite(stop)):
            raise StudyError(f"START and STOP must be finite numbers, got {limits.shorten(text)}",
                             where=where)
        return cls(key, (), start, stop, num, unit, integer)

    @classmethod
    def listed(cls, key: str, values: list) -> Sweep:
        """A list sweep: numbers (``unit`` ''), numbers in one written unit (``"12 kgf"``), or
        else values as written (``text``)."""
        if len(values) > limits.MAX_STUDY_POINTS:
            raise StudyError(f"at most {limits.MAX_STUDY_POINTS} values (govopt's limit), got "
                             f"{len(values)}", where=f"sweep {key}")
        if all(map(_is_number, values)):
            integer = all(isinstance(v, int) for v in values)
            return cls(key, tuple(int(v) if integer else float(v) for v in values),
                       integer=integer)
        written = [_WRITTEN.fullmatch(v) if isinstance(v, str) else None for v in values]
        units = {m[2] for m in written if m is not None}
        if all(m is not None for m in written) and len(units) == 1 and "" not in units:
            unit = units.pop()
            quantity(f"1 {unit}", f"sweep {key}")  # a unit pint reads, with govopt's rules
            return cls(key, tuple(float(m[1]) for m in written), unit=unit)
        return cls(key, tuple(values), text=True)

    # -- values --

    def take(self, idx) -> np.ndarray | list:
        """The values at positions ``idx`` (an array): numbers in :attr:`unit` (a whole-number
        sweep's as integers), or a list of values as written."""
        idx = np.asarray(idx, dtype=np.intp)
        if self.text:
            return [self.values[i] for i in idx]
        if self.is_range:
            n = self.num or 0
            u = idx * (1.0 / (n - 1)) if n > 1 else np.zeros(idx.shape)
            u[idx == n - 1] = 1.0  # np.linspace's values, one by one
            return self.at(u)
        return np.asarray(self.values, dtype=np.int64 if self.integer else float)[idx]

    def at(self, u) -> np.ndarray:
        """A range's values at fractions ``u`` in [0, 1] (rounded for whole numbers)."""
        v = self.start + np.asarray(u, dtype=float) * (self.stop - self.start)
        return np.rint(v).astype(np.int64) if self.integer else v

    def sample(self, u) -> np.ndarray | list:
        """Values at uniform fractions ``u`` (a sampler's column): within the range, or one of
        the listed values."""
        if self.is_range:
            return self.at(u)
        idx = np.minimum((np.asarray(u) * len(self.values)).astype(np.intp),
                         len(self.values) - 1)
        return self.take(idx)

    def span(self) -> tuple[float, float] | None:
        """The least and largest value (numbers), None for values as written."""
        if self.text:
            return None
        if self.is_range:
            ends = self.at([0.0, 1.0])
            return float(min(ends)), float(max(ends))
        return float(min(self.values)), float(max(self.values))

    def toml(self, value):
        """A value as the spec file writes it (what the parser reads): a number, or a number
        and the unit (``"12.5 kgf"``), or the value as written."""
        if self.text:
            return value
        if self.integer:
            return int(value)
        return float(value) if not self.unit else f"{number_text(value)} {self.unit}"

    def repeated(self):
        """A value the sweep holds twice (in a grid, its points would be held twice), or
        None."""
        if self.text:
            seen = set()
            for v in self.values:
                k = json.dumps(v, sort_keys=True)
                if k in seen:
                    return v
                seen.add(k)
            return None
        v = self.take(np.arange(len(self)))
        u, counts = np.unique(v, return_counts=True)
        return None if u.size == len(v) else self.toml(u[np.argmax(counts > 1)])

    def to_json(self) -> dict:
        return {"key": self.key, "values": list(self.values), "start": self.start,
                "stop": self.stop, "num": self.num, "unit": self.unit,
                "integer": self.integer, "text": self.text}

    @classmethod
    def from_json(cls, d: dict) -> Sweep:
        return cls(d["key"], tuple(d["values"]), d["start"], d["stop"], d["num"], d["unit"],
                   d["integer"], d["text"])


@dataclass(frozen=True)
class Input:
    """One varied key of a study's points: its unit (the sweep's written unit; a tolerance
    study's SI unit), whole numbers or not, values as written (``text``)."""

    key: str
    unit: str
    integer: bool = False
    text: bool = False


@dataclass(frozen=True)
class Study:
    """A spec and what to vary in it; points are numbered ``0 .. count() - 1``."""

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
            raise StudyError(f"expected one of {', '.join(MODES)}, got {self.mode!r}",
                             where="mode")
        if self.combine not in COMBINE:
            raise StudyError(f"expected one of {', '.join(COMBINE)}, got {self.combine!r}",
                             where="combination")
        bad = set(self.skip) - set(SKIPPABLE)
        if bad:
            raise StudyError(f"expected some of {', '.join(SKIPPABLE)}, got {sorted(bad)}",
                             where="skip")
        if self.tolerances and self.sweeps:
            raise StudyError("a study either sweeps inputs or samples tolerances, not both")
        if self.tolerances and self.mode != "evaluate":
            raise StudyError("a tolerance study evaluates the spec's design: mode must be "
                             "'evaluate'")
        if not self.sweeps and not self.tolerances:
            raise StudyError("a study needs at least one --sweep (or --tolerance)")
        for what, keys in (("swept", [s.key for s in self.sweeps]),
                           ("toleranced", [t.key for t in self.tolerances])):
            twice = next((k for i, k in enumerate(keys) if k in keys[:i]), None)
            if twice is not None:
                raise StudyError(f"{twice} is {what} twice")
        check_seed(self.seed)
        sampled = self.sampled
        if self.samples is not None or sampled:
            if isinstance(self.samples, bool) or not isinstance(self.samples, int) or \
                    self.samples < 1:
                raise StudyError(f"expected a whole number >= 1, got "
                                 f"{limits.shorten(self.samples)}", where="samples")
            if self.samples > limits.MAX_STUDY_POINTS:
                raise StudyError(f"at most {limits.MAX_STUDY_POINTS} points (govopt's limit), "
                                 f"got {self.samples:.4g}", where="samples")
        if self.tolerances:
            pass
        elif sampled:
            if not any(s.is_range for s in self.sweeps):
                raise StudyError("a sampled study needs at least one range START:STOP (a "
                                 "sample of lists alone repeats points: use a grid)")
        else:
            for s in self.sweeps:
                if s.is_range and s.num is None:
                    raise StudyError(f"a {self.combine} needs NUM in START:STOP:NUM",
                                     where=f"sweep {s.key}")
            sizes = [len(s) for s in self.sweeps]
            total = math.prod(sizes) if self.combine == "grid" else max(sizes)
            if total > limits.MAX_STUDY_POINTS:  # before they are made
                raise StudyError(f"at most {limits.MAX_STUDY_POINTS} points (govopt's limit), "
                                 f"got {total:.4g}")
            if self.combine == "zip" and len(set(sizes)) > 1:
                raise StudyError("--zip needs every sweep to have the same number of values, "
                                 "got " + ", ".join(f"{s.key}: {len(s)}" for s in self.sweeps))
            self._no_repeated_points()
        if not 2 <= len(self.pareto) <= 3 and self.pareto:
            raise StudyError(f"a Pareto front takes two or three objectives, got "
                             f"{len(self.pareto)}", where="pareto")

    def _no_repeated_points(self) -> None:
        """A point held twice is refused: a grid's sweep holding a value twice, a zip's
        values twice in step."""
        if self.combine == "grid":
            for s in self.sweeps:
                v = s.repeated()
                if v is not None:
                    raise StudyError(f"{limits.shorten(v)} is listed twice (each point of a "
                                     "grid is computed once)", where=f"sweep {s.key}")
            return
        if any(s.is_range and len(s) > 1 and s.start != s.stop and not s.integer
               for s in self.sweeps):
            return  # a proper range of numbers: no two points alike
        columns = [s.take(np.arange(len(s))) for s in self.sweeps]
        if not any(s.text for s in self.sweeps):  # numbers: at once
            table = np.column_stack(columns).astype(float)
            _, first, counts = np.unique(table, axis=0, return_index=True, return_counts=True)
            if counts.max() == 1:
                return
            again = np.nonzero(~np.isin(np.arange(len(table)), first))[0][0]
            twin = int(np.nonzero((table == table[again]).all(axis=1))[0][0])
            raise StudyError(f"points {twin} and {int(again)} are the same (each point is "
                             "computed once)")
        rows = zip(*(c if isinstance(c, list) else c.tolist() for c in columns), strict=True)
        seen: dict[str, int] = {}
        for i, row in enumerate(rows):
            k = json.dumps(row)
            if k in seen:
                raise StudyError(f"points {seen[k]} and {i} are the same (each point is "
                                 "computed once)")
            seen[k] = i

    # -- what it is --

    @property
    def sampled(self) -> bool:
        return bool(self.tolerances) or self.combine in SAMPLERS

    @property
    def keys(self) -> tuple[str, ...]:
        return tuple(s.key for s in self.sweeps) or tuple(t.key for t in self.tolerances)

    def inputs(self) -> list[Input]:
        """The varied keys, in order, with their units (a tolerance study's: SI)."""
        if self.tolerances:
            nom = nominal(self.base(), self.tolerances)
            return [Input(t.key, nom[t.key][1]) for t in self.tolerances]
        return [Input(s.key, s.unit, s.integer, s.text) for s in self.sweeps]

    def count(self) -> int:
        """How many points the study has."""
        if self.sampled:
            return int(self.samples or 0)
        sizes = [len(s) for s in self.sweeps]
        return math.prod(sizes) if self.combine == "grid" else min(sizes)

    def definition(self) -> dict:
        """Everything that defines the study's points and rows (JSON), for the database."""
        return {"name": self.name, "spec_path": self.path, "spec": self.data,
                "mode": self.mode, "combine": self.combine, "samples": self.samples,
                "seed": self.seed, "skip": list(self.skip),
                "sweeps": [s.to_json() for s in self.sweeps],
                "tolerances": [t.__dict__ for t in self.tolerances],
                "pareto": list(self.pareto), "keys": list(self.keys)}

    @classmethod
    def from_definition(cls, d: dict) -> Study:
        return cls(d["spec_path"], d["spec"], tuple(Sweep.from_json(s) for s in d["sweeps"]),
                   d["combine"], d["samples"], d["seed"], d["mode"], tuple(d["skip"]),
                   tuple(Tolerance(**t) for t in d["tolerances"]), tuple(d["pareto"]),
                   d["name"])

    def base(self) -> Spec:
        """The spec itself (validated; parsed once a process)."""
        return self.spec if self.spec is not None else _base_spec(canonical(self.data),
                                                                  self.path)

    # -- the points --

    def values(self, idx) -> dict[str, np.ndarray | list]:
        """The values of the points ``idx`` (an array of point numbers), key by key: numbers
        in the key's unit (:meth:`inputs`), or lists of values as written."""
        idx = np.asarray(idx, dtype=np.intp)
        if self.tolerances:
            u = self._cube()[idx]
            nom = nominal(self.base(), self.tolerances)
            return {t.key: t.draw(nom[t.key][0], nom[t.key][1], u[:, j])
                    for j, t in enumerate(self.tolerances)}
        if self.combine in SAMPLERS:
            u = self._cube()[idx]
            return {s.key: s.sample(u[:, j]) for j, s in enumerate(self.sweeps)}
        if self.combine == "grid":  # the last key fastest, as a product
            where = np.unravel_index(idx, [len(s) for s in self.sweeps])
        else:
            where = [idx] * len(self.sweeps)
        return {s.key: s.take(w) for s, w in zip(self.sweeps, where, strict=True)}

    def toml(self, key: str, value):
        """A value of ``key`` as the spec file would write it (for the spec parser)."""
        if self.tolerances:
            unit = self._si_units[key]
            return float(value) if not unit else f"{number_text(value)} {unit}"
        return next(s for s in self.sweeps if s.key == key).toml(value)

    @cached_property
    def _si_units(self) -> dict[str, str]:
        """A tolerance study's keys' SI units."""
        return {i.key: i.unit for i in self.inputs()}

    def points(self) -> list[dict]:
        """Every point as a dict of key -> value as the spec file writes it (a small study's:
        a large one is read a block at a time by :meth:`values`)."""
        n = self.count()
        cols = self.values(np.arange(n))
        return [{k: self.toml(k, cols[k][i]) for k in self.keys} for i in range(n)]

    def span(self, key: str) -> tuple[float, float] | None:
        """The least and largest value of a numeric key over the whole study (in its unit),
        None for values as written."""
        if self.tolerances:
            v = self.values(np.arange(self.count()))[key]
            return float(np.min(v)), float(np.max(v))
        return next(s for s in self.sweeps if s.key == key).span()

    def _cube(self) -> np.ndarray:
        kind = self.combine if self.combine in SAMPLERS else "lhs"
        return unit_cube(kind, int(self.samples), len(self.keys), int(self.seed))


def canonical(data) -> str:
    """JSON of ``data`` with sorted keys and no spaces: equal data, equal text."""
    return json.dumps(data, sort_keys=True, separators=(",", ":"), default=str)


@lru_cache(maxsize=8)
def _base_spec(text: str, path: str) -> Spec:
    return parse_spec(json.loads(text), path)


@lru_cache(maxsize=4)
def study_from_text(text: str) -> Study:
    """The study of a definition's JSON text (made once a process)."""
    return Study.from_definition(json.loads(text))


def read_study_file(path: str | Path, max_bytes: int = 1 << 20) -> tuple[dict, dict]:
    """``(spec data, [study] table)`` of a spec file (TOML; the study table may be absent)."""
    # a regular file, bounded, UTF-8, shallow: read as govopt reads every spec
    data = read_spec_data(path, max_bytes=max_bytes)
    table = data.pop("study", {})
    if not isinstance(table, dict):
        raise StudyError("expected a table", where="study", file=path)
    return data, table


def load_study(path: str | Path, *, sweeps: Iterable[str] = (), tolerances: Iterable[str] = (),
               **options) -> Study:
    """A study from a spec file's ``[study]`` table and command-line style arguments, which
    take precedence: ``sweeps`` as ``"KEY=VALUES"`` (added to the file's, replacing a key it
    has), ``tolerances`` as ``"KEY=±X%"`` (or ``"grade=N"``: :func:`grade_tolerances`; a key
    given also replaces the grade's), and ``options`` among ``combine``, ``samples``,
    ``seed``, ``mode``, ``skip``, ``pareto`` (``None`` keeps the file's or the default). Every
    error is one line naming the spec file."""
    try:
        return _load_study(path, sweeps=sweeps, tolerances=tolerances, **options)
    except StudyError as exc:
        if exc.file:
            raise
        inside = (exc.where or "").startswith(("study", "--"))
        raise (exc if inside else exc.within("study")).at(path) from None


def _present(data: dict, key: str) -> bool:
    """Whether the spec's TOML has a value at the dotted ``key`` (``load_change[0].to``)."""
    node = data
    for part in key.split("."):
        m = re.fullmatch(r"([^\[\]]+)((?:\[\d+\])*)", part)
        if m is None or not isinstance(node, dict) or m[1] not in node:
            return False
        node = node[m[1]]
        for i in re.findall(r"\[(\d+)\]", m[2]):
            if not isinstance(node, list) or int(i) >= len(node):
                return False
            node = node[int(i)]
    return True


def _pairs(texts: Iterable[str], option: str, expected: str) -> list[tuple[str, str]]:
    """``KEY=VALUE`` options as pairs, a key given twice refused."""
    out: list[tuple[str, str]] = []
    for text in texts:
        key, eq, value = str(text).partition("=")
        if not eq:
            raise StudyError(f"expected {expected}, got {limits.shorten(text)}", where=option)
        key = key.strip()
        if any(k == key for k, _ in out):
            raise StudyError(f"{key} is given twice", where=option)
        out.append((key, value))
    return out


def _load_study(path, *, sweeps, tolerances, **options) -> Study:
    data, table = read_study_file(path)
    unknown = sorted(set(table) - set(STUDY_KEYS))
    if unknown:
        raise StudyError(f"unknown key (allowed: {', '.join(sorted(STUDY_KEYS))})",
                         where=f"study.{unknown[0]}", file=path)
    spec = parse_spec(data, str(path))
    for name in ("sweep", "tolerance"):
        if not isinstance(table.get(name, {}), dict):
            raise StudyError(f"expected a table of KEY = VALUES, got "
                             f"{limits.shorten(table[name])}", where=f"study.{name}", file=path)
    sw = {k: Sweep.parse(k, v) for k, v in dict(table.get("sweep", {})).items()}
    for key, value in _pairs(sweeps, "--sweep", "KEY=VALUES"):
        sw[key] = Sweep.parse(key, value)
    for key, s in sw.items():  # a key the spec has no place for fails here, not in every row
        if not _present(data, key) and len(s):
            from ..spec import with_values

            with_values(spec, {key: s.toml(s.take([0])[0])})  # the parser's one line
    tol_texts = list(dict(table.get("tolerance", {})).items())
    tol_texts += _pairs(tolerances, "--tolerance", "KEY=±X%")
    if any(key == "grade" for key, _ in tol_texts):  # made governors: the spring's free length
        data, spec = fixed_free_length(data, spec)
    tols: dict[str, Tolerance] = {}
    for key, value in sorted(tol_texts, key=lambda kv: kv[0] != "grade"):  # a key given
        if key == "grade":                                               # replaces the grade's
            tols.update({t.key: t for t in grade_tolerances(spec, _grade(value))})
        else:
            tols[key] = Tolerance.parse(key, value)
    opts = {k: table.get(k) for k in ("mode", "combine", "samples", "seed", "skip", "pareto")}
    for k in ("samples", "seed"):  # the file's own, named as the file writes them
        if opts[k] is not None and options.get(k) is None:
            _whole(opts[k], f"study.{k}", least=1 if k == "samples" else 0)
    opts.update({k: v for k, v in options.items() if v is not None})
    # only an absent option takes the default ('' is a mode, refused; not the default)
    mode = opts["mode"] if opts["mode"] is not None else (
        "evaluate" if spec.design is not None else "design")
    pareto = _names(opts["pareto"], "pareto", "two or three objective names")
    skip = _names(opts["skip"], "skip", "names of analyses")
    samples = opts["samples"]
    combine = opts["combine"] if opts["combine"] is not None else ("lhs" if tols else "grid")
    if tols and samples is None:
        samples = DEFAULT_SAMPLES
    study = Study(str(path), data, tuple(sw.values()), combine, samples,
                  check_seed(opts["seed"] or 0), mode, skip, tuple(tols.values()), pareto,
                  str(table.get("name") or spec.name), spec)
    if tols:
        nominal(spec, tols.values())  # each toleranced key has a number in the spec
        check_bands(spec, tols.values(), study.toml)  # and every part in its band can be made
    return study


def _grade(value) -> int:
    try:
        grade = int(str(value).strip())
    except ValueError:
        raise StudyError(f"expected 1, 2 or 3, got {value!r}", where="tolerance grade") from None
    if grade not in (1, 2, 3):
        raise StudyError(f"expected 1, 2 or 3, got {grade}", where="tolerance grade")
    return grade


def _whole(value, where: str, least: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < least:
        raise StudyError(f"expected a whole number >= {least}, got {limits.shorten(value)}",
                         where=where)
    return value


def _names(value, where: str, expected: str) -> tuple[str, ...]:
    """A list of names, or a comma-separated text of them."""
    value = value or ()
    if isinstance(value, str):
        value = [p for p in value.split(",") if p.strip()]
    if not isinstance(value, list | tuple) or not all(isinstance(p, str) for p in value):
        raise StudyError(f"expected {expected}, got {limits.shorten(value)}", where=where)
    return tuple(p.strip() for p in value)
