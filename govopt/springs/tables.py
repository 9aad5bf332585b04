"""One lookup for the spring standards' tables, robust to the rounding of unit conversion.

A table row "up to 9 mm" must hold a wire given as "9 mm": parsed and converted, that is
0.009000000000000001 m, i.e. 9.000000000000002 mm, which a plain ``searchsorted`` puts in the
next row. Values within a relative ``rtol`` (1e-9, far below any tolerance of a spring table)
of a row's upper bound belong to that row.
"""

from __future__ import annotations

import numpy as np

#: relative distance from a row boundary still counted as on it
RTOL = 1e-9


def row_index(uppers, x, rtol: float = RTOL):
    """Index of the row holding ``x`` in a table of rows by increasing *inclusive* upper bound
    ``uppers`` (``x <= uppers[i]``, ``x > uppers[i-1]``); ``len(uppers)`` above the last.

    >>> int(row_index([2.6, 4.0, 9.0, 10.0], 9.000000000000002))
    2
    >>> int(row_index([2.6, 4.0, 9.0, 10.0], 9.01))
    3
    """
    x = np.asarray(x, dtype=float)
    return np.searchsorted(np.asarray(uppers, dtype=float), x * (1.0 - rtol), side="left")


def within(x, lo, hi, rtol: float = RTOL):
    """``lo <= x <= hi`` with the same allowance at both ends."""
    x = np.asarray(x, dtype=float)
    return (x >= lo * (1.0 - rtol)) & (x <= hi * (1.0 + rtol))
