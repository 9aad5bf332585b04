"""Plain JSON types from numpy results: one rule for every ``to_dict``."""

from __future__ import annotations

import math

import numpy as np


def number(x):
    """A float for JSON: finite as is, NaN as None, infinities as the strings "inf" / "-inf"."""
    x = float(x)
    return x if math.isfinite(x) else (None if math.isnan(x) else ("inf" if x > 0 else "-inf"))


def jsonable(obj):
    """Numpy scalars and arrays (nested in dicts, lists, tuples) to plain JSON types."""
    if isinstance(obj, dict):
        return {k: jsonable(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return jsonable(obj.tolist())
    if isinstance(obj, bool | np.bool_):
        return bool(obj)
    if isinstance(obj, int | np.integer):
        return int(obj)
    if isinstance(obj, float | np.floating):
        return number(obj)
    return obj
