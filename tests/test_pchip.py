"""The valve table's numpy interpolants equal scipy's.

scipy is the reference and is imported here only. PCHIP (slopes by
``PchipInterpolator._find_derivatives``, end formula included; Hermite coefficients; the
``PPoly`` evaluation) is the default table and is checked to 1e-14 relative (it reproduces
scipy's order of operations, so it agrees to the last bit in practice); the not-a-knot spline
(``CubicSpline``) solves its small system densely where scipy uses a banded solver, so its slopes
may differ by rounding: 1e-14 relative to the table's scale.
"""

import numpy as np
import pytest
from scipy.interpolate import CubicSpline, PchipInterpolator

from govopt.governors.shaft import valvegear as vg

REL = 1e-14  # relative to the largest |value| of the compared quantity

# Hamabe, Example 1 / Fig. 6 (deg): the bundled table.
HAMABE = (np.radians([42.0, 47.0, 52.0, 57.0, 62.0]),
          np.radians([53.0, 50.5, 48.5, 46.5, 44.5]))


def tables():
    """Tables that reach every branch of the slopes: monotone and not, flat secants, sign changes
    at the ends (the ``3 m0`` and ``0`` end cases), uneven rows, 2 to 40 rows."""
    rng = np.random.default_rng(14)
    out = [HAMABE,
           (np.array([50.0, 60.0, 80.0]), np.array([48.0, 60.0, 96.0])),
           (np.array([0.0, 1.0]), np.array([2.0, -1.0])),
           (np.array([0.0, 1.0, 3.0]), np.array([0.0, 5.0, 4.0])),
           (np.array([0.0, 1.0, 2.0, 3.0, 4.0]), np.array([0.0, 0.0, 1.0, 1.0, 0.5])),
           (np.array([0.0, 0.1, 2.0, 2.1, 5.0]), np.array([1.0, -3.0, 2.0, 2.0, -1.0])),
           (np.array([0.0, 1.0, 1.5, 4.0]), np.array([0.0, 3.0, -1.0, 1.0]))]
    for n in (3, 4, 5, 7, 12, 40):
        for _ in range(4):
            x = np.cumsum(rng.uniform(0.05, 2.0, n)) + rng.uniform(-1.0, 1.0)
            y = rng.normal(size=n) if rng.random() < 0.5 else np.cumsum(rng.uniform(0, 1, n))
            out.append((x, y))
    return out


def points(x):
    """Points inside, on every row, at the ends and outside the table (the pieces continue)."""
    span = x[-1] - x[0]
    return np.concatenate([np.linspace(x[0] - 0.2 * span, x[-1] + 0.2 * span, 997), x,
                           np.nextafter(x, -np.inf), np.nextafter(x, np.inf)])


def close(ours, ref):
    scale = max(np.max(np.abs(ref)), 1e-300)
    return np.max(np.abs(np.asarray(ours) - ref)) <= REL * scale


@pytest.mark.parametrize("i", range(len(tables())))
def test_pchip_equals_scipy(i):
    x, y = tables()[i]
    ref = PchipInterpolator(x, y)
    assert close(vg.pchip_slopes(x, y), ref.derivative()(x))
    f, df = vg._smooth_table(tuple(x), tuple(y), "pchip")
    t = points(x)
    assert close(f(t), ref(t)) and close(df(t), ref.derivative()(t))
    assert np.array_equal(f(t), ref(t)), "same operations in the same order: the same bits"


@pytest.mark.parametrize("i", range(len(tables())))
def test_not_a_knot_spline_equals_scipy(i):
    x, y = tables()[i]
    ref = CubicSpline(x, y)
    assert close(vg.not_a_knot_slopes(x, y), ref.derivative()(x))
    f, df = vg._smooth_table(tuple(x), tuple(y), "cubic")
    t = points(x)
    assert close(f(t), ref(t)) and close(df(t), ref.derivative()(t))


@pytest.mark.parametrize("kind", ["pchip", "cubic"])
def test_advance_angle_and_slope_equal_scipy_inside_and_outside(kind):
    """The public functions (clipped into the table, continued along the end tangents) on
    Hamabe's table, against the same construction on scipy's interpolant."""
    x, y = HAMABE
    ref = (PchipInterpolator if kind == "pchip" else CubicSpline)(x, y)
    alpha = np.radians(np.linspace(35.0, 70.0, 701))
    inside = np.clip(alpha, x[0], x[-1])
    expect = ref(inside) + ref.derivative()(inside) * (alpha - inside)
    assert close(vg.advance_angle(alpha, x, y, kind), expect)
    assert close(vg.advance_angle_slope(alpha, x, y, kind), ref.derivative()(inside))
    assert np.ndim(vg.advance_angle(0.9, x, y, kind)) == 0


def test_smooth_tables_refuse_what_scipy_refuses():
    with pytest.raises(ValueError):
        vg._smooth_table((0.0, 1.0, 1.0), (0.0, 1.0, 2.0), "pchip")
    with pytest.raises(ValueError):
        vg._smooth_table((1.0,), (0.0,), "cubic")
    with pytest.raises(ValueError):
        vg._smooth_table((0.0, 1.0), (0.0, 1.0), "akima")
