"""Bulk evaluation: many designs of one spec at once, vectorised, as one table.

:func:`evaluate_many` gives, for every design, the figures and the checks that
:func:`govopt.evaluate` gives for it (the same names, values and margins: both are the one
evaluator, :func:`govopt.evaluator.core`, this one over chunks of N designs, evaluate over one),
as one row of a pandas frame; :func:`result_row` flattens one :class:`~govopt.result.Result` to
the same row. Studies (:mod:`govopt.study`) are tables of these rows.
"""

from __future__ import annotations

import copy
import sys
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from .evaluator import DESIGN_FIELDS, core, dashpot_column, design_columns
from .requirements import CheckTable
from .result import Result
from .spec import Design, Spec

if TYPE_CHECKING:
    import pandas as pd

#: designs evaluated at once (bounds the memory: ~ CHUNK x configurations x 30 arrays)
CHUNK = 4096

STATUS_PASS, STATUS_FAIL, STATUS_ERROR = "pass", "fail", "error"


# ---------------------------------------------------------------------------------------------
# Columns
# ---------------------------------------------------------------------------------------------

def value_column(check: str) -> str:
    """Column of a check's value (SI) in a row."""
    return f"value: {check}"


def margin_column(check: str) -> str:
    """Column of a check's relative margin (positive when satisfied; ``Check.margin``)."""
    return f"margin: {check}"


def passed_column(check: str) -> str:
    return f"passed: {check}"


def check_names(columns) -> list[str]:
    """The checks present in a table's ``columns``, in order."""
    return [c[len("margin: "):] for c in columns if c.startswith("margin: ")]


class RowFigure(NamedTuple):
    """A figure of a row: a short ``name`` (an identifier), its SI ``unit`` (``""``
    dimensionless), what it is (``label``), whether its values are words (``text``) and
    whether it is one of the design's own numbers (``design``: what a drawing gives)."""

    name: str
    unit: str
    label: str
    text: bool = False
    design: bool = False


def row_figures(spec: Spec) -> dict[str, RowFigure]:
    """Every figure a row of ``spec``'s designs may have (:func:`columns`), by its column: the
    declaration the study's database, exports and plots read their units and names from."""
    gov = spec.governor
    angle = gov.coordinate == "angle"
    x, damping, force = ("rad", "N*m*s/rad", "N*m") if angle else ("m", "N*s/m", "N")
    effort = "N*m" if gov.travel == "angle" else "N"
    free = gov.free_length_key
    rows = [
        (f"{gov.mass_key}_mass_kg", f"{gov.mass_key}_mass", "kg", f"{gov.mass_name} mass"),
        ("central_mass_kg", "central_mass", "kg", "central mass"),
        ("wire_diameter_m", "wire_diameter", "m", "wire diameter"),
        ("coil_radius_m", "coil_radius", "m", "mean coil radius"),
        ("active_turns", "active_turns", "", "active turns"),
        ("stiffness_N_per_m", "stiffness", "N/m", "spring rate"),
        (f"{free}_m", free, "m", free.replace("_", " ")),
        (dashpot_column(gov), "dashpot", damping, "dash-pot coefficient"),
        ("irregularity", "irregularity", "", "irregularity (speed range / mean speed)"),
        ("omega_inner_rad_s", "omega_inner", "rad/s", "speed at the inner end"),
        ("omega_outer_rad_s", "omega_outer", "rad/s", "speed at the outer end"),
        ("omega_normal_rad_s", "omega_normal", "rad/s", "speed at the normal configuration"),
        ("min_spring_force_N", "min_spring_force", "N", "least spring force"),
        ("max_spring_force_N", "max_spring_force", "N", "largest spring force"),
        ("max_stress_Pa", "max_stress", "Pa", "largest shear stress"),
        ("spring_index", "spring_index", "", "spring index D/d"),
        ("wahl_factor", "wahl_factor", "", "Wahl factor"),
        ("surge_frequency_Hz", "surge_frequency", "Hz", "surge frequency"),
        ("body_length_m", "body_length", "m", "close-wound body length"),
        ("spring_mass_kg", "spring_mass", "kg", "spring mass"),
        ("moving_mass_kg", "moving_mass", "kg", f"moving mass ({gov.moving_mass_words()})"),
        ("k2_min_rad2_s2", "k2_min", "rad^2/s^2", "least k^2 over the range"),
        ("k2_max_rad2_s2", "k2_max", "rad^2/s^2", "largest k^2 over the range"),
        ("k2_normal_rad2_s2", "k2_normal", "rad^2/s^2", "k^2 at the normal configuration"),
        ("settling_time_s", "settling_time", "s", "longest settling time"),
        ("vibration_p2p_rad", "vibration_p2p", "rad", "forced vibration, peak to peak"),
        ("range_rad_s", "speed_range", "rad/s", "range of speed"),
        ("sensitiveness", "sensitiveness", "", "sensitiveness"),
        ("stability", "stability", "", "stability", True),
        ("effort", "effort", effort, "effort"),
        ("power", "power", "J", "power"),
        ("friction_band", "friction_band", force, "friction band referred to the flying mass "
                                                  "(not the sleeve's own friction force)"),
        ("insensitiveness", "insensitiveness", "", "coefficient of insensitiveness, the "
                                                   "largest over the range"),
    ]
    for lc in spec.load_changes:
        rows += [(f"hurwitz_margin: {lc.name}", f"hurwitz_margin: {lc.name}", "",
                  f"Hurwitz margin: {lc.name}"),
                 (f"over_regulation: {lc.name}", f"over_regulation: {lc.name}", x,
                  f"over-regulation: {lc.name}"),
                 (f"settling_time_s: {lc.name}", f"settling_time: {lc.name}", "s",
                  f"settling time: {lc.name}")]
    design = {f"{gov.mass_key}_mass_kg", "central_mass_kg", "wire_diameter_m", "coil_radius_m",
              "active_turns", "stiffness_N_per_m", f"{free}_m", dashpot_column(gov)}
    return {key: RowFigure(*rest, design=key in design) for key, *rest in rows}


def _objective_name(spec: Spec) -> str:
    return spec.requirements.objective if spec.requirements is not None else "moving_mass"


# ---------------------------------------------------------------------------------------------
# One Result -> one row
# ---------------------------------------------------------------------------------------------

def result_row(res: Result) -> dict:
    """One flat record of a result (SI): the design, the figures, every check's value, margin
    and verdict, the objective, status and message -- the row :func:`evaluate_many` gives for
    the same design, read from the same columns (:func:`columns` of the evaluator's record)."""
    import pandas as pd  # imported where a frame is built

    row = {}
    for k, v in columns(res.spec, res.evaluation).items():
        x = v[0]
        if x is pd.NA:  # a check that does not apply to this design: not in its row
            continue
        row[k] = x.item() if isinstance(x, np.generic) else x
    return row


#: the objectives of `govopt design` (:func:`govopt.optimize.design.objective_values`) as columns:
#: moving mass ``m + M + spring mass``, spring mass, the longest settling time, the vibration's
#: peak-to-peak
OBJECTIVE_COLUMN = {"moving_mass": "moving_mass_kg", "spring_mass": "spring_mass_kg",
                     "settling_time": "settling_time_s", "vibration": "vibration_p2p_rad"}


# ---------------------------------------------------------------------------------------------
# Designs as arrays
# ---------------------------------------------------------------------------------------------

def design_arrays(spec: Spec, designs) -> dict[str, np.ndarray]:
    """The designs as one float array per :class:`~govopt.spec.Design` field (SI, NaN for
    "not given"). ``designs``: a pandas frame or a dict of arrays (columns named as the fields;
    a missing column takes the spec's own ``[design]`` value), or a sequence of
    :class:`Design`."""
    if isinstance(designs, list | tuple) and designs and isinstance(designs[0], Design):
        return design_columns(designs)
    pandas = sys.modules.get("pandas")  # a frame is pandas', so pandas is loaded already
    if pandas is not None and isinstance(designs, pandas.DataFrame):
        given = {c: designs[c].to_numpy(dtype=float) for c in designs.columns}
    else:
        given = {c: np.asarray(v, dtype=float) for c, v in dict(designs).items()}
    unknown = sorted(set(given) - set(DESIGN_FIELDS))
    if unknown:
        raise ValueError(f"unknown design columns {unknown}; expected some of {DESIGN_FIELDS}")
    n = max((np.size(v) for v in given.values()), default=0)
    base = spec.design
    out = {}
    for f in DESIGN_FIELDS:
        if f in given:
            out[f] = np.broadcast_to(given[f], (n,)).astype(float)
        else:
            v = None if base is None else getattr(base, f)
            out[f] = np.full(n, np.nan if v is None else float(v))
    return out


# ---------------------------------------------------------------------------------------------
# evaluate_many
# ---------------------------------------------------------------------------------------------

def _check_columns(table: CheckTable) -> dict:
    """``value: ``, ``margin: `` and ``passed: `` columns (nullable booleans) of each check."""
    import pandas as pd  # imported where a frame is built

    out = {}
    for name, c in table.columns().items():
        out[value_column(name)] = c.value
        out[margin_column(name)] = c.margin
        out[passed_column(name)] = pd.arrays.BooleanArray(c.passed, ~c.applies)
    return out


def _status(table: CheckTable):
    """``(status, message)`` arrays: "fail" and "fails: <names>" where a check failed."""
    names = table.names
    failed = table.failed()
    wide = len(names) > 62  # past 62 checks the bits are Python integers (20 load changes
    bits = np.zeros(table.n, dtype=object if wide else np.int64)  # give ~70 checks)
    for j in range(len(names)):
        bits = bits + (failed[:, j].astype(object) * (1 << j) if wide
                       else np.where(failed[:, j], 1 << j, 0))
    patterns, inverse = np.unique(bits, return_inverse=True)
    texts = np.array([", ".join(nm for j, nm in enumerate(names) if int(b) >> j & 1)
                      for b in patterns], dtype=object)
    fails = bits != 0
    message = np.where(fails, "fails: " + texts[inverse.reshape(-1)], "")
    return np.where(fails, STATUS_FAIL, STATUS_PASS), message


def evaluate_many(spec: Spec, designs, *, dynamics: bool = True, vibration: bool = True,
                  classic: bool = True, chunk: int = CHUNK) -> pd.DataFrame:
    """Evaluate many designs of ``spec`` at once: one row per design, the columns of
    :func:`result_row` (the figures and checks :func:`govopt.evaluate` gives).

    ``designs``: see :func:`design_arrays`. ``dynamics``: the load-change transients and
    friction runs (Hamabe Part III, eqs. 28-32, 42-46); ``vibration``: the type's periodic
    forcing (Hamabe Part II); ``classic``: range, sensitiveness, stability, effort and power
    (textbook ch. 3). With all three off only the statics, the spring and ``k^2`` are
    evaluated: the fast path. Every design goes through the one evaluator
    (:func:`govopt.evaluator.core`, in chunks of ``chunk`` designs); a design that cannot be
    evaluated (no equilibrium speed, a non-finite figure, a free length <= 0, a wire thicker
    than its coil) is a row with ``status = "error"`` and evaluate's own message, never an
    exception.
    """

    return evaluate_rows(spec, designs, dynamics=dynamics, vibration=vibration,
                         classic=classic, chunk=chunk)[0]


def evaluate_rows(spec: Spec, designs, *, dynamics: bool = True, vibration: bool = True,
                  classic: bool = True, chunk: int = CHUNK) -> tuple[pd.DataFrame, dict]:
    """:func:`evaluate_many` and the SI unit of each of its checks (name -> unit)."""
    import pandas as pd  # imported where a frame is built

    out, units = evaluate_columns(spec, designs, dynamics=dynamics, vibration=vibration,
                                  classic=classic, chunk=chunk)
    return pd.DataFrame(out), units


def evaluate_columns(spec: Spec, designs, *, dynamics: bool = True, vibration: bool = True,
                     classic: bool = True, chunk: int = CHUNK) -> tuple[dict, dict]:
    """:func:`evaluate_rows` as its columns (name -> numpy array, a nullable boolean array for
    a check's verdict), without the frame: what a study's rows are made of."""
    import pandas as pd  # imported where a frame is built

    cols = design_arrays(spec, designs)
    n = len(cols["flying_mass"])
    parts, units = [], {}
    for s in range(0, n, chunk):
        ev = core(spec, {k: v[s:s + chunk] for k, v in cols.items()}, dynamics=dynamics,
                  vibration=vibration, classic=classic)
        units.update(ev.table.units())
        parts.append(columns(spec, ev))
    if len(parts) <= 1:
        return (parts[0] if parts else {}), units
    if any(list(p) != list(parts[0]) for p in parts):  # a check only some chunks have
        frame = pd.concat([pd.DataFrame(p) for p in parts], ignore_index=True)
        return {k: frame[k].array for k in frame.columns}, units
    return {k: _joined([p[k] for p in parts]) for k in parts[0]}, units


def _joined(arrays: list):
    """One column of several chunks (a nullable boolean column stays one)."""
    import pandas as pd  # imported where a frame is built

    if isinstance(arrays[0], pd.arrays.BooleanArray):
        return pd.arrays.BooleanArray(
            np.concatenate([a.to_numpy(dtype=bool, na_value=False) for a in arrays]),
            np.concatenate([np.asarray(a.isna()) for a in arrays]))
    return np.concatenate([np.asarray(a) for a in arrays])


def columns(spec: Spec, ev) -> dict:
    """The columns of the rows of the designs of an :class:`~govopt.evaluator.Evaluation`: the
    design and figures (none for an impossible design), every check's value, margin and verdict,
    the objective, status and message."""
    gov = spec.governor
    bad = ev.impossible
    out = dict(ev.figures)
    table = ev.table
    if bad.any():  # an impossible design's row: its design, no figures, evaluate's message
        keep = {f"{gov.mass_key}_mass_kg", "central_mass_kg", "wire_diameter_m",
                "coil_radius_m", "active_turns", dashpot_column(gov)}
        for k, v in out.items():
            if k not in keep:
                v = np.array(v, dtype=object if np.asarray(v).dtype == object else float)
                v[bad] = np.nan
                out[k] = v
        table = copy.deepcopy(table)
        table.drop(bad)
    out.update(_check_columns(table))
    obj = _objective_name(spec)
    out["objective"] = np.full(ev.n, obj, dtype=object)
    key = OBJECTIVE_COLUMN[obj]
    out["objective_value"] = np.asarray(out[key], dtype=float) if key in out else np.full(
        ev.n, np.nan)
    status, message = _status(table)
    if bad.any():
        status = np.where(bad, STATUS_ERROR, status)
        message = np.where(bad, ev.error, message)
    out["status"], out["message"] = status, message
    return out


__all__ = ["DESIGN_FIELDS", "RowFigure", "design_arrays", "evaluate_columns", "evaluate_many",
           "evaluate_rows", "result_row", "row_figures"]
