"""Margin where the objective is indifferent: choose a free variable in the middle of its window.

Where the objective does not depend on a design variable (the dash-pot, for the mass objectives:
its setting changes neither the pendulum nor the spring), the optimiser is free to put it
anywhere in its feasible window. A value at an end of the window makes the check that bounds
that end binding (Hamabe's eq. 32 at the low end, over-regulation at the high end), so a valve
set a few per cent off fails it. :func:`window_centre` takes instead the admissible value whose
least relative distance to an end of its admissible run is largest: the centre of the window on
a log scale. Every check the variable affects is in the admissibility mask, so a
check that narrows the window (fatigue, vibration, settling) moves the centre with it.
"""

from __future__ import annotations

import numpy as np


def window_centre(values, ok):
    """For each row of ``values`` (candidates x grid, positive and increasing along the grid,
    e.g. dash-pot settings in N m s/rad) and its admissibility mask ``ok``: the index of the
    admissible value farthest, on a log scale, from the ends of its contiguous admissible run
    (ties to the lower index; 0 for a row with none admissible).

    The margin of a value ``f`` in a run ``[f_lo, f_hi]`` is ``min(ln(f/f_lo), ln(f_hi/f))``:
    the largest relative change of the setting, either way, that stays within the run's
    admissible grid values.

    >>> f = np.geomspace(1.0, 100.0, 5)[None, :]  # 1, 3.16, 10, 31.6, 100
    >>> int(window_centre(f, np.array([[True, True, True, True, False]]))[0])
    1
    >>> int(window_centre(f, np.array([[False, True, True, True, True]]))[0])
    2
    """
    logf = np.log(np.asarray(values, dtype=float))
    ok = np.asarray(ok, dtype=bool)
    n, m = ok.shape
    idx = np.broadcast_to(np.arange(m), (n, m))
    # the first and the last index of each value's admissible run
    start = np.maximum.accumulate(np.where(ok, -1, idx), axis=1) + 1
    rev = np.maximum.accumulate(np.where(ok[:, ::-1], -1, idx), axis=1) + 1
    end = m - 1 - rev[:, ::-1]
    start, end = np.minimum(start, m - 1), np.maximum(end, 0)  # (inadmissible values only)
    rows = np.arange(n)[:, None]
    with np.errstate(invalid="ignore"):
        margin = np.minimum(logf - logf[rows, start], logf[rows, end] - logf)
    # to 1e-9 in the log (ties to the lower index whatever the rounding of the grid)
    return np.argmax(np.where(ok, np.round(margin, 9), -np.inf), axis=1)


def margins_to_ends(f: float, f_lo: float, f_hi: float) -> tuple[float, float]:
    """The relative change of a setting ``f`` that reaches each end of its window
    ``[f_lo, f_hi]``: ``(1 - f_lo/f, f_hi/f - 1)`` (the setting may be this much lower, higher)."""
    return 1.0 - f_lo / f, f_hi / f - 1.0
