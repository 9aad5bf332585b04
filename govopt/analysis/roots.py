"""Brent's bracketing root finder in plain Python, so that ``govopt evaluate`` never imports
``scipy.optimize`` (its import alone costs about 0.4 s of CPU, several times
the few root solves an evaluation makes).

The steps are those of ``scipy.optimize.brentq`` (Brent, *Algorithms for Minimization without
Derivatives*, 1973, ch. 4, in C. Harris's variant for scipy: inverse quadratic extrapolation
through the last two estimates and the far end of the bracket, a secant when the bracket has just
moved, bisection when a step would not shrink the bracket fast enough), with the same floating-
point operations in the same order, so the roots are scipy's to the last bit
(``tests/test_roots.py`` compares them); and the same arguments, defaults and errors.
"""

from __future__ import annotations

import math

#: The smallest relative tolerance Brent's method can honour in binary64: 4 eps.
RTOL_MIN = 4 * 2.0**-52


def brentq(f, a, b, args=(), xtol=2e-12, rtol=RTOL_MIN, maxiter=100):
    """A root of ``f(x, *args)`` between ``a`` and ``b`` (where ``f`` changes sign), to within
    ``xtol + rtol |x|``. Units: ``x`` and ``xtol`` those of ``a`` and ``b``; ``rtol`` none.

    Raises ``ValueError`` if ``f(a)`` and ``f(b)`` have the same sign, ``f`` returns NaN, ``xtol
    <= 0`` or ``rtol < 4 eps``; ``RuntimeError`` after ``maxiter`` steps without convergence.

    >>> root = brentq(lambda x: x * x - 2.0, 0.0, 2.0, xtol=1e-15)
    >>> abs(root - 2.0 ** 0.5) < 1e-15
    True
    """
    if xtol <= 0:
        raise ValueError(f"xtol too small ({xtol:g} <= 0)")
    if rtol < RTOL_MIN:
        raise ValueError(f"rtol too small ({rtol:g} < {RTOL_MIN:g})")

    def value(x):
        y = f(x, *args)
        if math.isnan(y):
            raise ValueError(f"The function value at x={x} is NaN; solver cannot continue.")
        return float(y)

    # x_cur: the best estimate; x_blk: the other end of the bracket; x_prev: the estimate before
    x_prev, x_cur = float(a), float(b)
    f_prev, f_cur = value(x_prev), value(x_cur)
    if f_prev * f_cur > 0:
        raise ValueError("f(a) and f(b) must have different signs")
    if f_prev == 0:
        return x_prev
    if f_cur == 0:
        return x_cur
    x_blk = f_blk = step_prev = step = 0.0
    for _ in range(maxiter):
        if f_prev != 0 and f_cur != 0 and (f_prev < 0) != (f_cur < 0):  # (not a product,
            # which underflows) the root lies between x_prev and x_cur: the new bracket
            x_blk, f_blk = x_prev, f_prev
            step_prev = step = x_cur - x_prev
        if abs(f_blk) < abs(f_cur):  # keep the smaller |f| at x_cur
            x_prev, x_cur, x_blk = x_cur, x_blk, x_cur
            f_prev, f_cur, f_blk = f_cur, f_blk, f_cur
        tol = (xtol + rtol * abs(x_cur)) / 2
        half = (x_blk - x_cur) / 2  # the bisection step
        if f_cur == 0 or abs(half) < tol:
            return x_cur
        bisect = True
        if abs(step_prev) > tol and abs(f_cur) < abs(f_prev):
            try:
                if x_prev == x_blk:  # secant through the ends of the bracket
                    trial = -f_cur * (x_cur - x_prev) / (f_cur - f_prev)
                else:  # inverse quadratic through the three points
                    d_prev = (f_prev - f_cur) / (x_prev - x_cur)
                    d_blk = (f_blk - f_cur) / (x_blk - x_cur)
                    trial = (-f_cur * (f_blk * d_blk - f_prev * d_prev)
                             / (d_blk * d_prev * (f_blk - f_prev)))
            except ZeroDivisionError:  # in C an inf or NaN, which fails the test below
                trial = math.inf
            if 2 * abs(trial) < min(abs(step_prev), 3 * abs(half) - tol):
                step_prev, step, bisect = step, trial, False
        if bisect:
            step_prev = step = half
        x_prev, f_prev = x_cur, f_cur
        x_cur += step if abs(step) > tol else (tol if half > 0 else -tol)
        f_cur = value(x_cur)
    raise RuntimeError(f"Failed to converge after {maxiter} iterations, value is {x_cur:f}.")
