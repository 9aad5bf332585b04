"""What a study found, read from its database: the exit status of a run, Pareto fronts,
tolerance probabilities, and the summary ``govopt study show`` prints, every number with its
unit (the spec's own: :mod:`govopt.study.shown`).

The database is read a batch at a time (:meth:`Store.batches`): a summary of a million points
holds one batch, the front so far and a tolerance study's spread columns.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from .. import limits
from ..stats import wilson
from .pareto import pareto_points

#: the figures whose spread a tolerance study reports
SPREAD = ("omega_inner", "omega_outer", "irregularity", "k2_normal")
#: best points ``study show`` lists
BEST = 5


# ---------------------------------------------------------------------------------------------
# Tolerance studies
# ---------------------------------------------------------------------------------------------

def check_columns(store) -> dict[str, dict[str, str]]:
    """Each check (by name) and its columns: ``{"value": ..., "margin": ..., "passed":
    ...}``."""
    out: dict[str, dict[str, str]] = {}
    for name, role, label in store.conn.execute(
            "SELECT name, role, label FROM columns WHERE role LIKE 'check %' ORDER BY position"):
        out.setdefault(label, {})[role.split()[1]] = name
    return out


def tolerance_summary(frames, checks: dict[str, str]) -> dict:
    """Per requirement (``checks``: name -> its verdict's column), the probability it holds
    over the samples with its 95 % Wilson interval (a sample that cannot be evaluated counts as
    not holding), and the spread of :data:`SPREAD` (mean, standard deviation, 2.5 and 97.5
    percentiles, SI). ``frames``: the study's table, or its batches (counted a batch at a
    time)."""
    if isinstance(frames, pd.DataFrame):
        frames = [frames]
    n = errors = all_k = 0
    holds = dict.fromkeys(checks, 0)
    values: dict[str, list] = {}
    for frame in frames:
        n += len(frame)
        for name, col in checks.items():
            if col in frame:
                holds[name] += int(frame[col].fillna(False).to_numpy(dtype=bool).sum())
        ok = (frame["status"] != "error").to_numpy()
        errors += int((~ok).sum())
        all_k += int((frame["status"] == "pass").sum())
        for col in SPREAD:
            if col in frame:
                v = frame[col].to_numpy(dtype=float)[ok]
                values.setdefault(col, []).append(v[np.isfinite(v)])
    out_checks = {}
    for name, k in holds.items():
        lo, hi = wilson(k, n)
        out_checks[name] = {"probability": k / n if n else math.nan, "ci95": [lo, hi],
                            "holds": k, "samples": n}
    lo, hi = wilson(all_k, n)
    spread = {}
    for col, parts in values.items():
        v = np.concatenate(parts)
        if v.size:
            spread[col] = {"mean": float(v.mean()),
                           "std": float(v.std(ddof=1)) if v.size > 1 else 0.0,
                           "p2.5": float(np.percentile(v, 2.5)),
                           "p97.5": float(np.percentile(v, 97.5))}
    return {"samples": n, "errors": errors,
            "all_requirements": {"probability": all_k / n if n else math.nan, "ci95": [lo, hi]},
            "checks": out_checks, "spread": spread}


# ---------------------------------------------------------------------------------------------
# The run's outcome
# ---------------------------------------------------------------------------------------------

def reasons(store) -> tuple[int, int, list[tuple[str, int]]]:
    """``(points, failed points, reasons)`` over every row: each failed check of a ``fail``
    row counts once (read from the verdict columns), any other failure by its message
    (without the spec's path, which every point shares); most common first."""
    total = store.count()
    counts: dict[str, int] = {}
    path = str(store.study().get("spec_path", "?"))
    passed = [(label, name) for name, label in store.conn.execute(
        "SELECT name, label FROM columns WHERE role = 'check passed' ORDER BY position")]
    if passed:
        sums = store.conn.execute(
            "SELECT " + ", ".join(f'SUM("{n}" = 0)' for _, n in passed)
            + " FROM points WHERE status = 'fail'").fetchone()
        for (label, _), k in zip(passed, sums, strict=True):
            if k:
                counts[f"fails: {label}"] = counts.get(f"fails: {label}", 0) + int(k)
    failed = 0
    for status, message, k in store.conn.execute(
            "SELECT status, message, COUNT(*) FROM points WHERE status NOT IN ('pass', "
            "'optimal') GROUP BY status, message ORDER BY MIN(point)"):
        failed += k
        if status != "fail":
            text = " ".join(str(message or status).split()).removeprefix(f"{path}: ")
            counts[text] = counts.get(text, 0) + k
    ranked = sorted(counts.items(), key=lambda kv: -kv[1])  # stable: the first of equals
    return total, failed, ranked


def outcome(store, report=None) -> tuple[int, str]:
    """The exit status of a study run and its one line for stderr (``""`` when nothing failed).

    Over every row in the database ``store`` (a resumed study counts the rows of earlier runs
    too):

    * 130: the run was interrupted (``report.interrupted``): what is kept and how to resume;
    * 0: at least one point passed (or was designed); failures are counted,
      ``"3 of 10 points failed: most common reason (2 of 3): fails: irregularity"``;
    * 1: every point failed and at least one of them ran (a check failed, or the design was
      infeasible), as ``govopt evaluate`` / ``govopt design`` exit 1 when a check fails;
    * 2: every point was an error (no point could be evaluated: a user's error, as a bad spec;
      the line is ``error: SPEC: ...`` as every exit-2 line).
    """
    if report is not None and report.interrupted:
        return 130, (f"interrupted: {report.skipped + report.done} of {report.total} points are "
                     f"in {store.path}; run again with --resume to finish")
    total, failed, ranked = reasons(store)
    if not failed:
        return 0, ""
    reason, n = ranked[0]
    why = f"most common reason ({n} of {failed}): {limits.shorten_values(reason)}"
    if failed < total:
        return 0, f"{failed} of {total} points failed: {why}"
    errors = store.conn.execute("SELECT COUNT(*) FROM points WHERE status = 'error'").fetchone()[0]
    if errors < total:
        return 1, f"all {total} points failed: {why}"
    path = str(store.study().get("spec_path", "?"))
    return 2, f"error: {path}: all {total} points failed (none could be evaluated): {why}"


# ---------------------------------------------------------------------------------------------
# What `govopt study show` prints
# ---------------------------------------------------------------------------------------------

def number(x, digits: int = 4) -> str:
    """A number to ``digits`` significant digits, as a person reads it.

    >>> number(12.183749), number(0.0001234), number(float("nan"))
    ('12.18', '0.0001234', '-')
    """
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-" if x is None or math.isnan(x) else str(x)
    if isinstance(x, bool | np.bool_):
        return "yes" if x else "no"
    if isinstance(x, int | np.integer):
        return str(int(x))
    if isinstance(x, float | np.floating):
        return f"{float(x):.{digits}g}"
    return str(x)


def with_unit(x, unit: str, digits: int = 4) -> str:
    return number(x, digits) + (f" {unit}" if unit and isinstance(x, int | float | np.number)
                                and not isinstance(x, bool) else "")


def heading(name: str, unit: str) -> str:
    """A column's heading: its name and the unit it is read in (``omega_inner [rpm]``)."""
    return f"{name} [{unit}]" if unit else name


def text_table(frame: pd.DataFrame) -> list[str]:
    """A frame as aligned text lines (numbers right, texts left)."""
    cells = [[str(c) for c in frame.columns]] + [
        [number(v) for v in row] for row in frame.itertuples(index=False, name=None)]
    widths = [max(len(r[j]) for r in cells) for j in range(len(frame.columns))]
    right = [pd.api.types.is_numeric_dtype(frame[c]) for c in frame.columns]
    return ["  ".join(c.rjust(w) if r else c.ljust(w) for c, w, r in
                      zip(row, widths, right, strict=True)).rstrip() for row in cells]


def shown(frame: pd.DataFrame, info: pd.DataFrame) -> pd.DataFrame:
    """The columns of ``frame`` in the units a person reads them in (``info``:
    :meth:`Store.columns`), headed with those units."""
    meta = info.set_index("name")
    out = {}
    for c in frame.columns:
        if c in meta.index and meta.at[c, "type"] == "REAL":
            out[heading(c, meta.at[c, "shown_unit"])] = frame[c].to_numpy(dtype=float) / float(
                meta.at[c, "shown_factor"])
        elif c in meta.index and meta.at[c, "type"] == "INTEGER" and meta.at[c, "shown_unit"]:
            out[heading(c, meta.at[c, "shown_unit"])] = frame[c]
        else:
            out[c] = frame[c]
    return pd.DataFrame(out)


def summary_text(store) -> str:
    """What ``govopt study show`` prints: the study, its progress and status counts, the best
    feasible points as a table in the spec's units, the Pareto front and, for a tolerance
    study, the probability of each requirement and the spread of the speeds."""
    study = store.study()
    total = store.meta("total") or 0
    info = store.columns()
    units = {n: (u, f) for n, u, f in zip(info["name"], info["shown_unit"],
                                           info["shown_factor"], strict=True)}
    tolerances = bool(study.get("tolerances"))
    counts = dict(store.conn.execute("SELECT status, COUNT(*) FROM points GROUP BY status "
                                     "ORDER BY COUNT(*) DESC, MIN(point)").fetchall())
    n = sum(counts.values())
    versions = ", ".join(store.meta("govopt_versions") or [str(store.meta("govopt_version"))])
    keys = study.get("keys", [])
    lines = [f"study {study.get('name', '?')!r}: {study.get('mode')} mode on "
             f"{study.get('spec_path')}; {', '.join(keys)} ({study.get('combine')}); "
             f"written by govopt {versions}",
             f"points: {n} of {total} done"]
    if not n:
        return "\n".join(lines)
    lines.append("status: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    inputs = store.names("input")
    if not tolerances:  # a designed point: its design too
        lines += _best(store, inputs + (store.names("design") if study.get("mode") == "design"
                                        else []), units, info)
    if study.get("pareto"):
        front = pareto_points(store)
        lines.append(f"Pareto front ({', '.join(study['pareto'])}): {len(front)} point"
                     f"{'s' if len(front) != 1 else ''}: "
                     + ", ".join(str(int(i)) for i in front[:20])
                     + (", ..." if len(front) > 20 else ""))
    error = store.conn.execute("SELECT message FROM points WHERE status = 'error' ORDER BY "
                               "point LIMIT 1").fetchone()
    if error is not None:
        lines.append(f"first error: {error[0]}")
    if tolerances:
        lines += _tolerance_lines(store, units)
    return "\n".join(lines)


def _best(store, inputs: list[str], units: dict, info: pd.DataFrame) -> list[str]:
    """The best feasible points (least objective first) as a table in the spec's units."""
    if "objective_value" not in units:
        return []
    best = store.frame(store.conn.execute(
        "SELECT point, " + ", ".join(f'"{c}"' for c in inputs) + ", objective, objective_value "
        "FROM points WHERE status IN ('pass', 'optimal') AND objective_value IS NOT NULL "
        f"ORDER BY objective_value, point LIMIT {BEST}"))
    if best.empty:
        return ["no feasible point"]
    feasible_n = store.conn.execute("SELECT COUNT(*) FROM points WHERE status IN ('pass', "
                                    "'optimal')").fetchone()[0]
    name = str(best["objective"].iloc[0])
    unit, factor = units["objective_value"]
    first = best.iloc[0]
    out = [f"best feasible point: {int(first['point'])}, {name.replace('_', ' ')} "
           f"{with_unit(first['objective_value'] / factor, unit)} ({feasible_n} feasible)"]
    table = shown(best.drop(columns="objective"), info)
    table.columns = [c.replace("objective_value", name, 1) for c in table.columns]
    out.append(f"the {len(best)} best feasible points ({name.replace('_', ' ')} least first), "
               "in the spec's units:")
    out += ["  " + line for line in text_table(table)]
    return out


def _tolerance_lines(store, units: dict) -> list[str]:
    checks = {label: c["passed"] for label, c in check_columns(store).items() if "passed" in c}
    s = tolerance_summary(store.batches(["status", *checks.values(), *SPREAD]), checks)
    a = s["all_requirements"]
    lines = [f"tolerance study, {s['samples']} samples: all requirements hold with probability "
             f"{a['probability']:.4f} (95 % CI {a['ci95'][0]:.4f}-{a['ci95'][1]:.4f})"]
    for name, c in s["checks"].items():
        lines.append(f"  {name}: {c['probability']:.4f} ({c['ci95'][0]:.4f}-"
                     f"{c['ci95'][1]:.4f})")
    for col, v in s["spread"].items():  # in the spec's own units
        unit, factor = units.get(col, ("", 1.0))
        lines.append(f"  {col}: mean {with_unit(v['mean'] / factor, unit, 6)}, std "
                     f"{with_unit(v['std'] / factor, unit, 3)}, 95 % of samples in "
                     f"[{number(v['p2.5'] / factor, 6)}, {number(v['p97.5'] / factor, 6)}]"
                     + (f" {unit}" if unit else ""))
    return lines
