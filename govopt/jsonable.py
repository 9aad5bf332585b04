"""Plain JSON types from numpy results: one rule for every ``to_dict``.

Infinities (an over-regulation that grows without bound, a response that never arrives or
settles) are no JSON numbers: a dict's value ``+-inf`` is written as ``null`` with a flag
beside it, ``"<key>_infinite": "+inf"`` (or ``"-inf"``); in a list, the flag is a list of the
same length (``null`` where the number is finite). NaN (not defined) is ``null`` with no flag.

>>> jsonable({"settling_time_s": float("inf"), "range_m": [0.2, float("-inf")], "x": 1.5})
{'settling_time_s': None, 'settling_time_s_infinite': '+inf', 'range_m': [0.2, None], \
'range_m_infinite': [None, '-inf'], 'x': 1.5}
"""

from __future__ import annotations

import math

import numpy as np


def number(x):
    """A float for JSON: finite as is, NaN and infinities as None (use :func:`jsonable` on the
    enclosing dict to keep an infinity's flag)."""
    x = float(x)
    return x if math.isfinite(x) else None


def _infinite(x) -> str | None:
    """``"+inf"``/``"-inf"`` for an infinite float, else None."""
    if isinstance(x, float | np.floating) and math.isinf(x):
        return "+inf" if x > 0 else "-inf"
    return None


def _all_finite_floats(a: np.ndarray) -> bool:
    return a.dtype.kind == "f" and bool(np.isfinite(a).all())


def jsonable(obj):
    """Numpy scalars and arrays (nested in dicts, lists, tuples) to plain JSON types, with
    infinities as ``null`` and a ``<key>_infinite`` flag (see the module docstring)."""
    if isinstance(obj, dict):
        out = {}
        for k, v in obj.items():
            out[k] = jsonable(v)
            if isinstance(v, np.ndarray):
                if _all_finite_floats(v):  # no flag: nothing infinite
                    continue
                v = v.tolist()
            flag = _infinite(v)
            if flag is None and isinstance(v, list | tuple):
                flags = [_infinite(x) for x in v]
                flag = flags if any(flags) else None
            if flag is not None:
                out[f"{k}_infinite"] = flag
        return out
    if isinstance(obj, list | tuple):
        return [jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        # a float array with every number finite is plain floats as it is (a response's
        # thousands of samples, not a Python call each)
        return obj.tolist() if _all_finite_floats(obj) else jsonable(obj.tolist())
    if isinstance(obj, bool | np.bool_):
        return bool(obj)
    if isinstance(obj, int | np.integer):
        return int(obj)
    if isinstance(obj, float | np.floating):
        return number(obj)
    return obj
