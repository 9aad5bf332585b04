"""A block of a study's points evaluated (or designed) into typed rows.

:func:`run_chunk` is what a worker runs (in this process, a process pool's or a Dask
cluster's): the points of a block are made from the study's definition and their numbers
(:meth:`Study.values`), each becomes the spec with the swept keys replaced and re-validated
(:func:`govopt.spec.with_values`), and is evaluated (:func:`govopt.bulk.evaluate_rows`,
vectorised over the points that differ only in their design) or designed
(:func:`govopt.design`). A point that cannot be evaluated is a row with ``status = "error"``
and the parser's or the evaluator's message; it never stops the study.

A row is typed columns (:class:`Column`: its role, what it is, SI unit, SQL type and the unit
a person reads it in): the inputs as written (numbers in the sweep's unit), the figures of the
row's declaration (:func:`govopt.bulk.row_figures`), every check's value, relative margin and
verdict, the objective, the status and message.
"""

from __future__ import annotations

import json
import math
import re
from collections import OrderedDict
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import pandas as pd

from ..errors import GovoptError
from .definition import SKIPPABLE, Input, Study, study_from_text
from .shown import Shown

#: a column's role in a row
ROLES = ("input", "design", "figure", "check value", "check margin", "check passed",
         "objective", "objective value")
#: distinct values of a design key parsed one by one; more are mapped linearly (_Runner)
EXACT_VALUES = 64
#: spec variants (and linear maps) a process keeps parsed
CACHE_SIZE = 512


@dataclass(frozen=True)
class Column:
    """One column of a study's rows: ``role`` (:data:`ROLES`), ``label`` (the spec key, the
    figure's name or the check's name: with the role, what identifies the column), SI ``unit``
    (``""`` dimensionless; an input's: the unit written), SQL ``type`` (REAL, INTEGER or
    TEXT), what it is (``about``), and the unit a person reads it in (``shown``, with
    ``factor`` SI per shown unit)."""

    role: str
    label: str
    unit: str
    type: str
    about: str = ""
    shown: str = ""
    factor: float = 1.0


def identifier(text: str) -> str:
    """A column name SQL reads without quotes, from a label.

    >>> identifier("k^2 > 0 (stability)"), identifier("design.pendulum_weight")
    ('k2_gt_0_stability', 'design_pendulum_weight')
    >>> identifier("working length >= least length (coil clash)")
    'working_length_ge_least_length_coil_clash'
    """
    t = text.replace("^", "")
    for sign, word in ((">=", " ge "), ("<=", " le "), (">", " gt "), ("<", " lt "),
                       ("=", " eq "), ("%", " percent ")):
        t = t.replace(sign, word)
    t = re.sub(r"[^0-9A-Za-z]+", "_", t).strip("_").lower()
    return t if t and not t[0].isdigit() else f"c_{t}"


@dataclass
class Rows:
    """Rows of some points (``points``: their numbers): ``status`` and ``message`` of each,
    and the ``columns`` with their values (``data``: a float array for a REAL column, an
    object array of numbers, texts and ``None`` for the others)."""

    points: np.ndarray
    status: np.ndarray
    message: np.ndarray
    columns: list[Column]
    data: list[np.ndarray]

    def __len__(self) -> int:
        return len(self.points)

    def failures(self) -> int:
        return int(np.sum(~np.isin(self.status, PASSED)))


#: a point that ran: its checks passed (evaluate) or it was designed (design)
PASSED = ("pass", "optimal")


class _Builder:
    """Rows assembled column by column (missing values NaN or None)."""

    def __init__(self, points):
        self.points = np.asarray(points, dtype=np.int64)
        n = len(self.points)
        self.status = np.full(n, "error", dtype=object)
        self.message = np.full(n, "", dtype=object)
        self.cols: dict[tuple[str, str], tuple[Column, np.ndarray]] = {}

    def put(self, column: Column, pos, values) -> None:
        key = (column.role, column.label)
        if key not in self.cols:
            n = len(self.points)
            data = np.full(n, np.nan) if column.type == "REAL" else np.full(n, None, object)
            self.cols[key] = (column, data)
        self.cols[key][1][pos] = values

    def error(self, pos, exc) -> None:
        self.status[pos] = "error"
        self.message[pos] = str(exc)

    def rows(self) -> Rows:
        cols = list(self.cols.values())
        return Rows(self.points, self.status, self.message, [c for c, _ in cols],
                    [d for _, d in cols])


def _text(v):
    """A value as written, as text (a TOML number or boolean as TOML writes it)."""
    return v if isinstance(v, str) else json.dumps(v)


#: a design key of the spec as its entries name it: ``design.wire_diameter``,
#: ``bounds.wire_diameter[0]``, ``bounds.active_turns.low``, ``catalogue.wire_diameters[2]``
_DESIGN_KEY = re.compile(r"(?:design|bounds|catalogue)\.(\w+)(?:\[\d+\]|\.low|\.high)?")


class _Runner:
    """A study's points into rows, in one process: the spec variants and linear maps it has
    parsed kept by what they are made of (the values written), never by object identity."""

    def __init__(self, study: Study):
        self.study = study
        self.base = study.base()
        self.inputs = study.inputs()
        self.shown = Shown(self.base.entries)
        self.kw = {k: k not in study.skip for k in SKIPPABLE}
        self.variants: OrderedDict = OrderedDict()
        self.linear: OrderedDict = OrderedDict()

    # -- spec variants --

    def variant(self, values: dict):
        """``with_values(base, values)`` (the values as the spec writes them), or the parser's
        error; parsed once a process."""
        from ..spec import with_values

        key = tuple(sorted(values.items()))
        hit = self.variants.get(key)
        if hit is not None:
            self.variants.move_to_end(key)
            return hit
        try:
            out = with_values(self.base, values) if values else self.base
        except GovoptError as exc:
            out = exc
        self.variants[key] = out
        if len(self.variants) > CACHE_SIZE:
            self.variants.popitem(last=False)
        return out

    # -- columns --

    def input_column(self, inp: Input) -> Column:
        if inp.text:
            return Column("input", inp.key, "", "TEXT", "as written")
        kind = "INTEGER" if inp.integer else "REAL"
        if self.study.tolerances:  # drawn in SI: read in the spec's unit for the key
            shown, factor = self._key_unit(inp.key, inp.unit)
            return Column("input", inp.key, inp.unit, kind, "sampled", shown, factor)
        return Column("input", inp.key, inp.unit, kind, "as written", inp.unit, 1.0)

    def _key_unit(self, key: str, si: str) -> tuple[str, float]:
        own = Shown([e for e in self.base.entries if e.key == key]).own.get(si)
        return own or self.shown(si)

    def _design_unit(self, name: str, si: str) -> tuple[str, float]:
        """The unit of a design figure: the one the spec writes that design key in (in
        ``[design]``, ``[bounds]`` or ``[catalogue]``: a wire diameter in mm where the spec's
        other lengths are in cm), else the spec's unit for the quantity."""
        own = Shown([e for e in self.base.entries if (m := _DESIGN_KEY.fullmatch(e.key))
                     and m[1] in (name, f"{name}s")]).own.get(si)
        return own or self.shown(si)

    def put_inputs(self, b: _Builder, values: dict) -> None:
        for inp in self.inputs:
            v = values[inp.key]
            col = self.input_column(inp)
            b.put(col, slice(None), [_text(x) for x in v] if inp.text else
                  (np.asarray(v, dtype=object) if inp.integer else v))

    def put_frame(self, b: _Builder, pos, frame, spec, check_units: dict,
                  objective_unit: str | None = None) -> None:
        """The evaluator's rows ``frame`` (:func:`govopt.bulk.columns`: a dict of columns, or a
        pandas frame of them) at positions ``pos``."""
        from ..bulk import OBJECTIVE_COLUMN, RowFigure, row_figures

        figures = row_figures(spec)
        for c, v in frame.items():
            if c == "status":
                b.status[pos] = np.asarray(v, dtype=object)
            elif c == "message":
                b.message[pos] = ["" if x is None or x is pd.NA else str(x) for x in v]
            elif c == "objective":
                b.put(Column("objective", "objective", "", "TEXT", "the objective's name"),
                      pos, np.asarray(v, dtype=object))
            elif c == "objective_value":
                name = str(np.asarray(frame["objective"], dtype=object)[0]) if (
                    "objective" in frame) else ""
                fig = figures.get(OBJECTIVE_COLUMN.get(name, ""))
                unit = objective_unit if objective_unit is not None else (
                    fig.unit if fig else "")
                b.put(Column("objective value", "objective_value", unit, "REAL",
                             "the objective's value", *self.shown(unit)), pos, _numbers(v))
            elif c.startswith(("value: ", "margin: ", "passed: ")):
                what, _, check = c.partition(": ")
                if what == "passed":
                    b.put(Column("check passed", check, "", "INTEGER",
                                 "1 where the check holds, 0 where it fails"), pos,
                          _verdicts(v))
                elif what == "margin":
                    b.put(Column("check margin", check, "", "REAL",
                                 "relative margin (negative: fails)"), pos, _numbers(v))
                else:
                    unit = check_units.get(check, "")
                    b.put(Column("check value", check, unit, "REAL", "the checked value",
                                 *self.shown(unit)), pos, _numbers(v))
            else:
                fig = figures.get(c)
                if fig is None:  # a figure the declaration does not know (a test finds it)
                    fig = RowFigure(c, "", c, np.asarray(v).dtype == object)
                if fig.text:
                    b.put(Column("figure", fig.name, "", "TEXT", fig.label), pos,
                          [None if x is None or x is pd.NA else str(x) for x in v])
                else:
                    b.put(Column("design" if fig.design else "figure", fig.name, fig.unit,
                                 "REAL", fig.label, *(self._design_unit(fig.name, fig.unit)
                                                      if fig.design else self.shown(fig.unit))),
                          pos, _numbers(v))

    # -- evaluate mode --

    def rows(self, idx) -> Rows:
        values = self.study.values(idx)
        b = _Builder(idx)
        self.put_inputs(b, values)
        if self.study.mode == "evaluate":
            self._evaluate(b, values)
        else:
            self._design(b, values)
        return b.rows()

    def _written(self, key: str, column) -> list:
        return [self.study.toml(key, v) for v in column]

    def _evaluate(self, b: _Builder, values: dict) -> None:
        """Evaluate-mode points: grouped by their non-design values (one spec each), the
        design values of a group evaluated at once (:func:`govopt.bulk.evaluate_rows`)."""
        from ..bulk import evaluate_columns, evaluate_rows

        n = len(b.points)
        keys = list(values)
        design_keys = [k for k in keys if k.startswith("design.")]
        other_keys = [k for k in keys if not k.startswith("design.")]
        other = [self._written(k, values[k]) for k in other_keys]
        groups: dict[tuple, list[int]] = {}
        for i in range(n):
            groups.setdefault(tuple(o[i] for o in other), []).append(i)
        for group, positions in groups.items():
            pos = np.asarray(positions)
            assigned = dict(zip(other_keys, group, strict=True))
            spec = self.variant(assigned)
            if isinstance(spec, GovoptError):
                b.error(pos, spec)
                continue
            if self._refused_together(assigned, design_keys, values, pos[0]):
                for i in pos:  # keys the parser refuses together: each point in full
                    full = self.variant({**assigned, **{k: self.study.toml(k, values[k][i])
                                                        for k in design_keys}})
                    if isinstance(full, GovoptError):
                        b.error([i], full)
                        continue
                    frame, units = evaluate_rows(full, [full.design], **self.kw)
                    self.put_frame(b, [i], frame, full, units)
                continue
            fields = self._design_fields(spec, assigned, design_keys, values, pos)
            if fields is None:
                continue
            arrays, bad = fields
            good = np.array([e is None for e in bad], dtype=bool)
            if good.any():
                cols = {f: a[good] for f, a in arrays.items()}
                if self.study.tolerances:  # each made governor as the fitter sets it
                    from ..bulk import design_arrays
                    from ..made import set_by_the_fitter

                    cols = set_by_the_fitter(spec, cols, design_arrays(spec, [spec.design]))
                out, units = evaluate_columns(spec, cols, **self.kw)
                self.put_frame(b, pos[good], self._set_by_the_fitter(spec, cols, out),
                               spec, units)
            for j in np.nonzero(~good)[0]:
                b.error([pos[j]], bad[j])

    def _set_by_the_fitter(self, spec, cols: dict, out: dict):
        """A tolerance study's made governors as the fitter sets them, where the spec has one
        (``requirements.adjusting_nut``, ``dashpot_valve``): each that fails as made is tried at
        the fitter's settings, least change first, and its row is the governor as set at the
        first that makes every requirement hold (:func:`govopt.made.fit`, as the yield beside
        the verdict counts it); the others as made."""
        from ..bulk import evaluate_rows
        from ..made import fit, fitter_of, holds

        nut, valve = fitter_of(spec.requirements)
        nut = nut if spec.governor.spring is not None else 0.0
        if not self.study.tolerances or not (nut > 0 or valve > 0):
            return out
        frame = pd.DataFrame(out)
        return fit(spec, cols, None, holds(frame), nut, valve, frame=frame,
                   evaluate=lambda rows, _: evaluate_rows(spec, rows, **self.kw)[0])[3]

    def _refused_together(self, assigned: dict, design_keys: list, values: dict, i) -> bool:
        """Whether the design keys' values of point ``i`` are each accepted alone but refused
        together (a wire thicker than its coil)."""
        if len(design_keys) < 2:
            return False
        one = {k: self.study.toml(k, values[k][i]) for k in design_keys}
        if not isinstance(self.variant({**assigned, **one}), GovoptError):
            return False
        return all(not isinstance(self.variant({**assigned, k: v}), GovoptError)
                   for k, v in one.items())

    def _design_fields(self, spec, assigned: dict, design_keys: list, values: dict, pos):
        """The :class:`~govopt.spec.Design` fields of the points ``pos`` of one group, as
        arrays (the group's own design where a key leaves a field), and each point's parser
        error (None where it has none)."""
        from ..bulk import DESIGN_FIELDS

        base = spec.design
        arrays = {f: np.full(len(pos), np.nan if base is None or getattr(base, f) is None
                             else float(getattr(base, f))) for f in DESIGN_FIELDS}
        bad = np.full(len(pos), None, dtype=object)
        for k in design_keys:
            col = values[k]
            col = [col[i] for i in pos] if isinstance(col, list) else np.asarray(col)[pos]
            fields_k, errors = self._key_fields(spec, assigned, k, col)
            for f, v in fields_k.items():
                arrays[f] = np.where(np.isnan(v), arrays[f], v)
            for j, exc in errors.items():
                bad[j] = bad[j] or exc
        return arrays, bad

    def _key_fields(self, spec, assigned: dict, key: str, column):
        """The design fields the key ``key`` sets for each of the values ``column`` (numbers in
        the key's unit, or values as written): ``(fields, errors)``, ``fields`` a dict of field
        -> array (NaN where unchanged), ``errors`` position -> the parser's error.

        Up to :data:`EXACT_VALUES` distinct values each give a variant of the spec, parsed in
        full (every check, the exact conversion). Beyond that (a fine range, a tolerance
        study's samples), the least and largest value of the whole study (and one
        non-integral value) are parsed in full and the rest mapped linearly: a design value's
        SI form is proportional to the number written (``m = W/g``, ``f = 3 a1``, ``d``: the
        unit's factor), and the parser's checks on a single value are intervals (positive,
        within a range), so the values between two valid ones are valid. Cross-key checks (a
        wire thicker than its coil) are the evaluator's."""
        n = len(column)
        numeric = not isinstance(column, list)
        if numeric:
            uniq, codes = np.unique(column, return_inverse=True)
            uvals = list(uniq)
        else:
            codes, uniq = pd.factorize(pd.Series([json.dumps(v) for v in column]))
            uvals = [json.loads(t) for t in uniq]
        if numeric and len(uvals) > EXACT_VALUES:
            lin = self._linear(spec, assigned, key, np.asarray(uniq, dtype=float))
            if lin is not None:
                x = np.asarray(column, dtype=float)
                return {f: a * x for f, a in lin.items()}, {}
        fields: dict[str, np.ndarray] = {}
        errors: dict[int, GovoptError] = {}
        for c, value in enumerate(uvals):
            variant = self.variant({**assigned, key: self.study.toml(key, value) if numeric
                                    else value})
            rows_c = np.nonzero(np.asarray(codes) == c)[0]
            if isinstance(variant, GovoptError):
                errors.update({int(j): variant for j in rows_c})
                continue
            for f, v in _changes(spec, variant).items():
                fields.setdefault(f, np.full(n, np.nan))[rows_c] = v
        return fields, errors

    def _linear(self, spec, assigned: dict, key: str, x: np.ndarray):
        """The field slopes of the numbers ``x`` of a design key (see :meth:`_key_fields`), or
        None where a probe fails or the map is not linear. The interval known valid grows as
        blocks come (the whole study's span probed first); only values outside it are
        probed."""
        ck = (tuple(sorted(assigned.items())), key)
        known = self.linear.get(ck)
        if known is None:
            span = self.study.span(key)
            known = self._probe(spec, assigned, key, np.asarray(span), None) if span else None
            if known is not None:
                self.linear[ck] = known
                if len(self.linear) > CACHE_SIZE:
                    self.linear.popitem(last=False)
        frac = x != np.round(x)
        probes = [i for i in (int(np.argmin(x)), int(np.argmax(x)))
                  if known is None or not known["lo"] <= x[i] <= known["hi"]]
        if frac.any() and (known is None or not known["fractions"]) and not any(
                frac[i] for i in probes):
            probes.append(int(np.nonzero(frac)[0][0]))
        if probes or known is None:
            known = self._probe(spec, assigned, key, x[probes or [0]], known)
            if known is None:
                return None
            self.linear[ck] = known
        if not (known["lo"] <= x.min() and x.max() <= known["hi"]):
            return None
        return known["slopes"]

    def _probe(self, spec, assigned: dict, key: str, x: np.ndarray, known: dict | None):
        """``known`` (a linear map) grown by the values ``x`` parsed in full, or None where one
        is refused or does not fit."""
        slopes = dict(known["slopes"]) if known else {}
        for v in x:
            variant = self.variant({**assigned, key: self.study.toml(key, v)})
            if isinstance(variant, GovoptError) or v == 0:
                return None
            for f, want in _changes(spec, variant).items():
                slope = slopes.setdefault(f, want / v)
                if not abs(slope * v - want) <= 1e-12 * abs(want):
                    return None
        valid = [*x, *([known["lo"], known["hi"]] if known else [])]
        return {"lo": float(min(valid)), "hi": float(max(valid)), "slopes": slopes,
                "fractions": bool((known and known["fractions"]) or np.any(x != np.round(x)))}

    # -- design mode --

    def _design(self, b: _Builder, values: dict) -> None:
        """Design-mode points: each designed by :func:`govopt.design` and flattened by
        :func:`govopt.bulk.result_row`, with the optimiser's objective and status."""
        from ..bulk import result_row
        from ..errors import InfeasibleError
        from ..optimize.search import design

        for i in range(len(b.points)):
            spec = self.variant({k: self.study.toml(k, v[i]) for k, v in values.items()})
            if isinstance(spec, GovoptError):
                b.error([i], spec)
                continue
            try:
                res = design(spec)
            except InfeasibleError as exc:
                b.status[i], b.message[i] = "infeasible", str(exc)
                continue
            except GovoptError as exc:
                b.error([i], exc)
                continue
            row = result_row(res)
            opt = res.optimisation["objective"]
            row["objective"] = opt["name"]
            row["objective_value"] = float(res.optimisation["value"])
            row["status"] = res.optimisation["status"]
            if row["status"] == "optimal":
                row["message"] = ""
            frame = pd.DataFrame({k: [v] for k, v in row.items()})
            self.put_frame(b, [i], frame, spec, res.evaluation.table.units(),
                           objective_unit=opt["unit"])


def _numbers(v) -> np.ndarray:
    """A column's values as floats (NaN where not a number)."""
    if isinstance(v, np.ndarray) and v.dtype.kind in "fiub":
        return v.astype(float)
    return pd.to_numeric(pd.Series(v), errors="coerce").to_numpy(dtype=float)


def _verdicts(v) -> np.ndarray:
    """A check's verdicts as 1, 0 or None (where it does not apply)."""
    if not isinstance(v, pd.arrays.BooleanArray):
        v = pd.Series(v).array
        if not isinstance(v, pd.arrays.BooleanArray):
            v = pd.array(np.asarray(v, dtype=object), dtype="boolean")
    mask = np.asarray(v.isna())
    return np.where(mask, None, v.to_numpy(dtype=bool, na_value=False).astype(int)).astype(
        object)


def _changes(spec, variant) -> dict[str, float]:
    """The design fields ``variant`` sets otherwise than ``spec`` (NaN: unset)."""
    from ..bulk import DESIGN_FIELDS

    a, b = spec.design, variant.design
    out = {}
    for f in DESIGN_FIELDS:
        x = None if a is None else getattr(a, f)
        y = None if b is None else getattr(b, f)
        if x != y:
            out[f] = math.nan if y is None else float(y)
    return out


@lru_cache(maxsize=2)
def _runner(definition_text: str) -> _Runner:
    return _Runner(study_from_text(definition_text))


def clear_caches() -> None:
    """Forget the studies, specs and maps this process has parsed (a benchmark's cold run)."""
    _runner.cache_clear()
    study_from_text.cache_clear()


def run_chunk(definition_text: str, points) -> Rows:
    """The rows of the points ``points`` (an array of their numbers) of the study
    ``definition_text`` (JSON of :meth:`Study.definition`). Runs in any process (the pool's
    or a Dask worker): the points are made here from the definition."""
    return _runner(definition_text).rows(np.asarray(points, dtype=np.int64))
