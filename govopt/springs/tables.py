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

    The spring standards' tables are written so ("over 8 up to 14"); a value within ``rtol`` of
    a row's upper bound (a converted "9 mm") stays in that row.

    Parameters
    ----------
    uppers : sequence of float [any unit, that of x]
        Inclusive upper bounds of the rows, increasing.
    x : float or array [any unit, that of uppers]
        The values to place.
    rtol : float [-]
        Relative distance from a bound still counted as on it, dimensionless.

    Returns
    -------
    int or array of int [-]
        Row indices, ``len(uppers)`` above the last row.

    References
    ----------
    [en15800] Table 1 (columns by spring index: up to 8, over 8 up to 14, over 14 up to 20);
    [en10270-1] (rows by wire diameter).

    Examples
    --------
    EN 15800 Table 1's index columns: w = 8 is in the first, 11.4 in the second, 14 converted
    with a rounding error still in the second; a 9 mm wire converted from metres stays in the
    "up to 9 mm" row.

    >>> [int(row_index((8.0, 14.0), w)) for w in (8.0, 11.4, 14.000000000000002, 14.01)]
    [0, 1, 1, 2]
    >>> int(row_index([2.6, 4.0, 9.0, 10.0], 9.000000000000002))
    2
    >>> int(row_index([2.6, 4.0, 9.0, 10.0], 9.01))
    3
    """
    x = np.asarray(x, dtype=float)
    return np.searchsorted(np.asarray(uppers, dtype=float), x * (1.0 - rtol), side="left")


def within(x, lo, hi, rtol: float = RTOL):
    """``lo <= x <= hi`` with the same allowance at both ends.

    Parameters
    ----------
    x : float or array [any unit, that of lo and hi]
        The values to test.
    lo : float [any unit, that of x]
        Lowest value of the table's range.
    hi : float [any unit, that of x]
        Highest value of the table's range.
    rtol : float [-]
        Relative allowance at both ends, dimensionless.

    Returns
    -------
    bool or array of bool [-]
        Where ``x`` lies in the range.

    References
    ----------
    [en15800] Table 1 (coil diameters 0.63 to 200 mm).

    Examples
    --------
    EN 15800 Table 1 covers 0.63 to 200 mm: 200 mm converted with a rounding error is inside,
    201 mm is not.

    >>> [bool(within(D, 0.63, 200.0)) for D in (0.63, 200.00000000000003, 201.0)]
    [True, True, False]
    """
    x = np.asarray(x, dtype=float)
    return (x >= lo * (1.0 - rtol)) & (x <= hi * (1.0 + rtol))
