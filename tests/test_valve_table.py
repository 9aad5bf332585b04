"""The valve-gear table's interpolant: k^2 continuous with the default.

Hamabe's Fig. 6 gives the eccentric's advance delta at five configurations; k^2 (with the
default ``reaction_slope``) uses d delta/d alpha. The paper's linear interpolation makes that
slope, and so k^2, jump at every row: for case d by -8.2 % at 57 deg 20', -5.5 % at the normal
configuration 64 deg 40' (itself a row) and -3.9 % at 73 deg 30'. The default PCHIP table is C^1,
so the jump vanishes to rounding.

How a jump is measured: each one-sided limit of k^2 at a row is extrapolated from three points
on that side (``3 f(h) - 3 f(2h) + f(3h)``, error O(h^3 f''')), with h = 1e-5 rad. Comparing
k^2 at row -+ 1e-7 directly would not do: a continuous k^2 still differs there by
2e-7 dk^2/dalpha (~5e-7 relative for case d), and the linear table's difference quotient (step
1e-6) straddles the row at +-1e-7, so it would show only a tenth of the real jump.
"""

import math
import tomllib
from pathlib import Path

import mpmath
import numpy as np
import pytest

import govopt
from govopt.analysis import nonlinear, statics
from govopt.governors import shaft
from govopt.governors.shaft import valvegear
from govopt.reader import SpecError
from govopt.spec import LoadChange, parse_spec

H = 1e-5  # rad, > the linear table's difference step 1e-6: each point stays on its side


def spec_of(case, **analysis):
    spec = govopt.load_spec(f"specs/hamabe-{case}.toml")
    return spec.with_analysis(**analysis) if analysis else spec


def k2_curve(spec):
    """k^2 along the characteristic of the spec's design (as `evaluate` computes it)."""
    sd = statics.spring_design(spec)

    def k2(alpha):
        alpha = np.asarray(alpha, dtype=float)
        return statics.restoring_k2(spec, alpha, sd,
                                    statics.omega_squared(spec, alpha, sd.m, sd.kappa, sd.l0))
    return k2, sd


def one_sided_limits(f, x, h=H):
    left = 3 * f(x - h) - 3 * f(x - 2 * h) + f(x - 3 * h)
    right = 3 * f(x + h) - 3 * f(x + 2 * h) + f(x + 3 * h)
    return left, right


@pytest.mark.parametrize("case", ["d", "a"])
@pytest.mark.parametrize("kind", [None, "cubic"])  # None: the spec's default
def test_k2_continuous_at_every_row(case, kind):
    spec = spec_of(case) if kind is None else spec_of(case, valve_table=kind)
    assert spec.analysis.reaction_slope
    assert spec.analysis.valve_table == (kind or "pchip")
    k2, _ = k2_curve(spec)
    rows = spec.governor.valve_gear.table_alpha[1:-1]
    left, right = one_sided_limits(k2, rows)
    np.testing.assert_array_less(np.abs(right - left) / np.abs(k2(rows)), 1e-9)
    # the extrapolated limits are k^2 at the row itself (k^2 is continuous there)
    np.testing.assert_allclose(left, k2(rows), rtol=1e-9)


def test_linear_table_jumps_by_the_change_of_secant():
    """Case d with the paper's linear table: the jump of k^2 at each row is exactly
    (dC_f/ddelta + omega^2 dC_i/ddelta) (s_right - s_left) / I, with s the table's secants --
    -8.2 % at 57 deg 20', as the issue says."""
    spec = spec_of("d", valve_table="linear")
    k2, sd = k2_curve(spec)
    vg, g = spec.governor.valve_gear, spec.governor
    rows = vg.table_alpha[1:-1]
    left, right = one_sided_limits(k2, rows)
    secant = np.diff(vg.table_delta) / np.diff(vg.table_alpha)
    w2 = statics.omega_squared(spec, rows, sd.m, sd.kappa, sd.l0)
    dcf, dci = valvegear.mean_reaction_split_slope(vg.table_delta[1:-1], g.q, vg.eccentricity,
                                                   vg.offset, vg.friction,
                                                   vg.reciprocating_mass, vg.eccentric_mass)
    predicted = (dcf + w2 * dci) * np.diff(secant) / sd.inertia
    np.testing.assert_allclose(right - left, predicted, rtol=1e-6)
    rel = (right - left) / ((right + left) / 2)
    np.testing.assert_allclose(rel, [-0.0822, -0.0551, -0.0390], atol=5e-4)


@pytest.mark.parametrize("case", ["d", "a"])
def test_pchip_k2_at_a_row_lies_between_the_linear_one_sided_values(case):
    """PCHIP's slope at a row is a weighted harmonic mean of the two secants, so its k^2 there
    lies between the linear table's left and right limits (k^2 is affine in d delta/d alpha at
    a fixed row)."""
    k2_lin, _ = k2_curve(spec_of(case, valve_table="linear"))
    k2_p, _ = k2_curve(spec_of(case))
    rows = spec_of(case).governor.valve_gear.table_alpha[1:-1]
    left, right = one_sided_limits(k2_lin, rows)
    value = k2_p(rows)
    assert np.all((np.minimum(left, right) < value) & (value < np.maximum(left, right)))


def test_split_slope_matches_mpmath():
    """dC_f/ddelta and dC_i/ddelta (eq. 11 differentiated by hand) against mpmath's numerical
    derivative of eq. (11) at 30 digits, across the table's range of delta."""
    mpmath.mp.dps = 30
    q, e, s, P1, m_v, m_e = 0.05, 0.026, 0.006, 16 * 9.80665, 12.0, 6.0

    def C_f(d):
        return q / 2 * (2 * P1 / mpmath.pi) * mpmath.sin(d)

    def C_i(d):
        return q / 2 * (m_v * e / 2 * mpmath.cot(d) + m_e * (e * mpmath.cot(d)
                                                              - s * mpmath.cos(d)))

    for delta in np.radians([48.5, 58.0, 69.0, 84.0, 90.0, 96.0]):
        dcf, dci = valvegear.mean_reaction_split_slope(delta, q, e, s, P1, m_v, m_e)
        assert dcf == pytest.approx(float(mpmath.diff(C_f, delta)), rel=1e-13, abs=1e-15)
        assert dci == pytest.approx(float(mpmath.diff(C_i, delta)), rel=1e-13)


@pytest.mark.parametrize("kind", ["pchip", "cubic"])
def test_reaction_slope_is_the_derivative_of_the_interpolated_reaction(kind):
    """The analytic dM_r0/dalpha against a fourth-order central difference of the interpolated
    M_r0 (statics.reaction), at points inside each interval (the difference needs a smooth
    neighbourhood: PCHIP's second derivative jumps at the rows). Truncation ~h^4 f^(5) ~ 1e-20,
    rounding ~1e-16 M / h ~ 1e-11 relative."""
    spec = spec_of("d", valve_table=kind)
    ta = spec.governor.valve_gear.table_alpha
    alpha = np.concatenate([ta[:-1] + f * np.diff(ta) for f in (0.1, 0.37, 0.5, 0.83)])
    w2 = spec.speed.omega_mean**2

    def M(a):
        cf, ci = shaft.reaction(spec, a)
        return cf + w2 * ci

    h = 1e-4
    diff = (8 * (M(alpha + h) - M(alpha - h)) - (M(alpha + 2 * h) - M(alpha - 2 * h))) / (12 * h)
    np.testing.assert_allclose(shaft.reaction_slope(spec, alpha, w2), diff, rtol=1e-8)


def test_linear_table_is_the_papers():
    """valve_table = "linear": delta by np.interp (the paper's "interpolate between rows"), the
    reaction's slope the mean of the two sides on a row, as before."""
    spec = spec_of("d", valve_table="linear")
    vg = spec.governor.valve_gear
    a = np.linspace(vg.table_alpha[0], vg.table_alpha[-1], 37)
    np.testing.assert_array_equal(
        valvegear.advance_angle(a, vg.table_alpha, vg.table_delta, "linear"),
        np.interp(a, vg.table_alpha, vg.table_delta))
    row = vg.table_alpha[2]
    w2 = spec.speed.omega_mean**2
    left = shaft.reaction_slope(spec, row - 0.01, w2)
    right = shaft.reaction_slope(spec, row + 0.01, w2)
    assert shaft.reaction_slope(spec, row, w2) == pytest.approx(
        (shaft.reaction_slope(spec, row - 1e-5, w2)
         + shaft.reaction_slope(spec, row + 1e-5, w2)) / 2, rel=1e-4)
    assert abs(right - left) > 0.05 * abs(left)  # a real kink


@pytest.mark.parametrize("kind", ["pchip", "cubic"])
def test_smooth_tables_are_monotone_and_continue_along_their_end_tangents(kind):
    vg = spec_of("d").governor.valve_gear
    ta, td = vg.table_alpha, vg.table_delta
    a = np.linspace(ta[0], ta[-1], 2001)
    delta = valvegear.advance_angle(a, ta, td, kind)
    assert np.all(np.diff(delta) > 0)
    np.testing.assert_allclose(valvegear.advance_angle(ta, ta, td, kind), td, rtol=1e-15)
    for end in (0, -1):
        slope = valvegear.advance_angle_slope(ta[end], ta, td, kind)
        for dx in (-0.05, 0.05):
            x = ta[end] + dx
            if ta[0] <= x <= ta[-1]:
                continue
            assert valvegear.advance_angle(x, ta, td, kind) == pytest.approx(
                td[end] + slope * dx, rel=1e-14)
            assert valvegear.advance_angle_slope(x, ta, td, kind) == slope


def test_pchip_slopes_at_rows_lie_between_the_secants():
    vg = spec_of("d").governor.valve_gear
    ta, td = vg.table_alpha, vg.table_delta
    secant = np.diff(td) / np.diff(ta)
    slope = valvegear.advance_angle_slope(ta[1:-1], ta, td, "pchip")
    assert np.all((secant[:-1] < slope) & (slope < secant[1:]))


def test_smooth_table_removes_the_first_order_floor_at_a_row():
    """Example 3's alpha0 = 64 deg 40' is a row. With the linear table the linearisation error of
    a load change has a floor (~0.5 % of xi0, tests/test_nonlinear.py); with PCHIP the linear
    model is the exact linearisation there too, so the error is second order: doubling a small
    load change quadruples it."""
    spec = spec_of("a")
    alpha0 = spec.governor.valve_gear.table_alpha[2]
    t = np.linspace(0.0, 3.0, 301)
    e = [nonlinear.linearisation_error(spec, load_change=LoadChange("x", alpha0 - math.radians(d),
                                                                    alpha0), t=t)
         for d in (0.25, 0.5)]
    assert e[1]["max_abs_error_rad"] / e[0]["max_abs_error_rad"] == pytest.approx(4.0, rel=0.05)
    assert e[0]["max_rel_error"] < 1e-3  # the linear table's floor is 3e-3 .. 7e-3


# -- spec ---------------------------------------------------------------------------------------

BASE = Path("specs/hamabe-a.toml").read_text(encoding="utf-8")


def _parse(text):
    return parse_spec(tomllib.loads(text), "x.toml")


@pytest.mark.parametrize("old,new,uncovered", [
    ('"50 deg", "57 deg + 20 arcmin"', '"51 deg", "57 deg + 20 arcmin"', "alpha_inner = 50"),
    ('"73 deg + 30 arcmin", "80 deg"]', '"73 deg + 30 arcmin", "79 deg"]', "alpha_outer = 80"),
])
def test_table_that_does_not_cover_the_range_is_an_error(old, new, uncovered):
    assert BASE.count(old) == 1
    with pytest.raises(SpecError, match=r"valve_gear\.table\.alpha: the table covers .*"
                                        f"governor\\.{uncovered} deg lies outside"):
        _parse(BASE.replace(old, new))


def test_load_change_outside_the_table_is_an_error():
    """A load change's from/to must lie in the configuration range, which the table covers."""
    text = BASE.replace('from = "57 deg + 20 arcmin"', 'from = "45 deg"')
    with pytest.raises(SpecError, match=r"load_change\[0\]\.from"):
        _parse(text)


def test_valve_table_setting():
    assert _parse(BASE).analysis.valve_table == "pchip"
    spec = _parse(BASE + '\n[analysis]\nvalve_table = "linear"\n')
    assert spec.analysis.valve_table == "linear"
    with pytest.raises(SpecError, match=r"analysis\.valve_table: expected one of"):
        _parse(BASE + '\n[analysis]\nvalve_table = "spline"\n')


def test_rounding_of_units_is_not_a_gap():
    """The SI spec writes the rows in radians: alpha_inner equals the first row to rounding."""
    spec = govopt.load_spec("specs/hamabe-a-si.toml")  # loads: no SpecError
    assert spec.governor.alpha_inner == pytest.approx(spec.governor.valve_gear.table_alpha[0],
                                                      abs=1e-12)


def test_smooth_tables_refuse_a_table_that_is_not_one():
    """Rows that do not increase, a single row, or an interpolant govopt does not offer."""
    for rows, kind in (((0.0, 1.0, 1.0), "pchip"), ((1.0,), "cubic"), ((0.0, 1.0), "akima")):
        x = np.array(rows)
        with pytest.raises(ValueError):
            valvegear.advance_angle(0.5, x, x, kind)
