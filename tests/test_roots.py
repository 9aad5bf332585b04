"""govopt's Brent root finder is scipy's ``brentq`` without its import.

scipy is the reference, imported here only: the same roots to the last bit (the same operations
in the same order), the same number of function calls, the same errors.
"""

import math

import numpy as np
import pytest
from scipy import optimize

from govopt.analysis.roots import RTOL_MIN, brentq

CASES = [  # (f, a, b): smooth, flat, steep, a root at an end, a kink, a jump
    (lambda x: x * x - 2.0, 0.0, 2.0),
    (lambda x: math.cos(x) - x, -1.0, 3.0),
    (lambda x: (x - 1.0) ** 3, -4.0, 2.5),
    (lambda x: (x - 0.3) ** 9, 0.0, 1.0),
    (lambda x: math.exp(20.0 * x) - 5.0, -1.0, 1.0),
    (lambda x: math.atan(1e6 * (x - 1e-3)), -1.0, 1.0),
    (lambda x: x, 0.0, 1.0),
    (lambda x: x - 1.0, 0.0, 1.0),
    (lambda x: abs(x - 0.2) - 0.1 if x > 0.2 else -0.1, 0.0, 1.0),
    (lambda x: 1.0 if x > math.pi / 4 else -1.0, 0.0, 1.0),
    (lambda x: np.float64(math.sin(x)), 3.0, 4.0),
    (lambda x: 1e-300 * (x - 7.0), 0.0, 100.0),
    (lambda x: x**3 - 2 * x - 5, 2.0, 3.0),
    (lambda x: math.tanh(50.0 * (x - 0.123456789)) + 1e-3 * x, -2.0, 5.0),
]
TOLS = [dict(), dict(xtol=1e-15, rtol=1e-15), dict(xtol=1e-300, rtol=RTOL_MIN, maxiter=200),
        dict(xtol=1e-6, rtol=1e-3), dict(xtol=0.5)]


def counted(f):
    def g(x, *args):
        g.calls += 1
        return f(x, *args)
    g.calls = 0
    return g


@pytest.mark.parametrize("tol", TOLS, ids=str)
@pytest.mark.parametrize("i", range(len(CASES)))
def test_same_root_and_calls_as_scipy(i, tol):
    f, a, b = CASES[i]
    for lo, hi in ((a, b), (b, a)):
        ours, ref = counted(f), counted(f)
        try:
            expect = optimize.brentq(ref, lo, hi, **tol)
        except RuntimeError:  # Brent's method is slow on a multiple root: 100 steps too few
            with pytest.raises(RuntimeError):
                brentq(ours, lo, hi, **tol)
        else:
            x = brentq(ours, lo, hi, **tol)
            assert x == expect and type(x) is float
        assert ours.calls == ref.calls


def test_args_are_passed_as_scipy_passes_them():
    f = lambda x, p, q: x * x - p * q  # noqa: E731
    assert brentq(f, 0.0, 5.0, args=(2.0, 3.0)) == optimize.brentq(f, 0.0, 5.0, args=(2.0, 3.0))


@pytest.mark.parametrize("bad, kwargs", [
    ((lambda x: x * x + 1.0, -1.0, 1.0), {}),  # no sign change
    ((lambda x: x, -1.0, 1.0), {"xtol": 0.0}),
    ((lambda x: x, -1.0, 1.0), {"rtol": 4e-16}),  # below 4 eps (vibration.py asks for this)
    ((lambda x: math.nan if x > 0 else -1.0, -1.0, 1.0), {}),
])
def test_same_value_errors(bad, kwargs):
    with pytest.raises(ValueError):
        optimize.brentq(*bad, **kwargs)
    with pytest.raises(ValueError):
        brentq(*bad, **kwargs)


def test_same_error_when_it_runs_out_of_steps():
    f = lambda x: (x - 1.0 / 3.0) ** 3  # noqa: E731
    with pytest.raises(RuntimeError):
        optimize.brentq(f, 0.0, 1.0, xtol=1e-300, maxiter=3)
    with pytest.raises(RuntimeError, match="Failed to converge after 3 iterations"):
        brentq(f, 0.0, 1.0, xtol=1e-300, maxiter=3)
