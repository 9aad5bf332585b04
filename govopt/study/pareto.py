"""Pareto fronts of a study's objectives, found a batch of rows at a time."""

from __future__ import annotations

import numpy as np
import pandas as pd

from .errors import StudyError
from .rows import PASSED

#: objectives a Pareto front may name, with their column and sense (any column may be named,
#: minimised, or with a ``max:`` prefix maximised)
OBJECTIVES = {
    "moving_mass": ("moving_mass", "min"), "spring_mass": ("spring_mass", "min"),
    "settling_time": ("settling_time", "min"), "vibration": ("vibration_p2p", "min"),
    "irregularity": ("irregularity", "min"), "max_stress": ("max_stress", "min"),
    "k2_margin": ("margin_k2_gt_0_stability", "max"),
}


def objective_column(name: str) -> tuple[str, str]:
    """``(column, "min" | "max")`` of an objective name (:data:`OBJECTIVES`, a column, or
    ``max:<column>``)."""
    name = name.strip()
    if name.startswith("max:"):
        return objective_column(name[4:])[0], "max"
    if name.startswith("min:"):
        return objective_column(name[4:])[0], "min"
    return OBJECTIVES.get(name, (name, "min"))


def objectives(study: dict) -> list[str]:
    """The columns a study's Pareto front reads (none without a front)."""
    return ["status", *(objective_column(n)[0] for n in study.get("pareto", ()))] \
        if study.get("pareto") else []


def feasible(frame: pd.DataFrame) -> np.ndarray:
    return frame["status"].isin(PASSED).to_numpy()


def pareto_front(frame: pd.DataFrame, objectives) -> np.ndarray:
    """Whether each row is on the Pareto front of ``objectives`` (minimised; ``max:`` for
    maximised): feasible, finite in every objective, and no other such row at least as good in
    all and better in one (of equal rows, the first)."""
    if not feasible(frame).any():  # no row evaluated: no front (nor, maybe, its columns)
        return np.zeros(len(frame), bool)
    cols = []
    for name in objectives:
        col, sense = objective_column(name)
        if col not in frame:
            raise StudyError(f"no column {col!r} in the study's table (objectives: "
                             f"{', '.join(OBJECTIVES)}, or a column's name)", where="pareto")
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


def pareto_mark(frame: pd.DataFrame, study: dict) -> np.ndarray:
    """:func:`pareto_front` of the study's objectives, an error naming the spec."""
    try:
        return pareto_front(frame, study["pareto"])
    except StudyError as exc:
        raise exc.within("study").at(study.get("spec_path", "?")) from None


def front_of(front: pd.DataFrame | None, part: pd.DataFrame, study: dict) -> pd.DataFrame:
    """The rows on the Pareto front among the front so far and the batch ``part``: a row
    dominated by one of the first is dominated by one on their front."""
    both = part if front is None else pd.concat([front, part], ignore_index=True)
    return both.loc[pareto_mark(both, study)].reset_index(drop=True)


def pareto_points(store, *, batch: int | None = None) -> np.ndarray:
    """The points on the study's Pareto front, in order, found a batch at a time."""
    study = store.study()
    if not study.get("pareto"):
        return np.zeros(0, dtype=np.int64)
    front = None
    for part in store.batches(objectives(study), **({'batch': batch} if batch else {})):
        front = front_of(front, part, study)
    return np.zeros(0, dtype=np.int64) if front is None else front["point"].to_numpy(
        dtype=np.int64)
