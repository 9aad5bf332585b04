"""Part II of Hamabe: the valve gear's fluctuating reaction (eq. 14) and the forced vibration of
the pendulum (eqs. 18-22, Example 2), with the dash-pot.

Findings about the paper that these tests pin down (see the individual tests):

- eq. (14)'s closed-form coefficients agree with the force models of Part I to rounding, signs
  included (``B2`` carries ``-m_v omega^2 e / 2``, as first principles give);
- Example 2's table, however, was computed with ``+m_v omega^2 e / 2`` in ``B2``: its ``N2``
  column has the wrong sign, and flipping that one term reproduces it to 1 %;
- the scan lost ``E2, F2``; the table's ``M1, M2, M3`` columns give ``E2 ~ F2 ~ -0.028 rad/s``
  (``E2/omega0 ~ -0.0011``), with which ``M1, M2, M3, M4, N4`` are reproduced to a few per cent;
  ``N3`` then comes out with the opposite sign (a 1e-4 degree term: OCR or a slip);
- case d': the paper's ``k^2 = 233`` is a slip, its own spring gives 311; the printed 11.4 deg
  follows from the slip, the consistent amplitude is 14.2 deg.
"""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate

from govopt.evaluator import evaluate
from govopt.governors.shaft import harmonics as hm
from govopt.governors.shaft import valvegear as vg
from govopt.governors.shaft import vibration as V
from govopt.spec import load_spec

SPECS = Path(__file__).resolve().parent.parent / "specs"
KGF, CM = 9.80665, 0.01
# Example 1's valve gear (kgf, cm -> SI; masses 12 and 6 kgf -> 12 and 6 kg)
VG = dict(q=5 * CM, e=2.6 * CM, s=0.6 * CM, P1=16 * KGF, P3=12 * KGF, P4=16 * KGF, m_v=12.0,
          m_e=6.0)
W0 = math.sqrt(630.0)  # the paper's omega0

#: Example 2's table (degrees): k^2 and M1, N1, M2, N2, M3, N3, M4, N4 over (k^2 - n^2 omega0^2).
PAPER = {
    "a": (360, [0.00235, 8.45, -0.395, -0.35, 0.000118, 0.000112, -0.0174, -0.009]),
    "b": (330, [0.00247, 9.05, -0.473, -0.422, 0.000138, 0.000134, -0.0207, -0.0108]),
    "c": (310, [0.00291, 10.4, -0.604, -0.542, 0.000174, 0.000168, -0.0258, -0.0134]),
    "d": (200, [0.00291, 10.4, -0.783, -0.7, 0.000228, 0.000219, -0.034, -0.0177]),
    "d-prime": (233, [0.00316, 11.4, -0.79, -0.707, 0.00023, 0.00022, -0.0342, -0.0178]),
}
#: Speed fluctuation inferred from the table's M1, M2, M3 columns (least squares gives
#: E2 = -0.029, F2 = -0.027 rad/s); the scan lost the paper's values.
E2_PAPER, F2_PAPER = -0.028, -0.028


def paper_spec(case, reaction_speed="mean"):
    """The bundled spec with the paper's fidelity: series M_f, reaction at the mean speed, no
    reaction slope in k^2."""
    return load_spec(SPECS / f"hamabe-{case}.toml").with_analysis(
        geometry="series", reaction_speed=reaction_speed, reaction_slope=False)


@pytest.fixture(scope="module")
def normal():
    """case -> (spec, result, k^2 at the normal configuration)."""
    out = {}
    for case in PAPER:
        spec = paper_spec(case)
        res = evaluate(spec)
        i = int(np.flatnonzero(np.isclose(res.statics.alpha, spec.governor.alpha_normal))[0])
        out[case] = (spec, res, float(res.k2[i]))
    return out


def B1_estimate(spec, inertia, k2, omega0):
    """The paper's dominant term: ``B1 / (I (omega0^2 - k^2))``, ``B1 = (q/2)(P3 + P4)``."""
    vg = spec.governor.valve_gear
    B1 = 0.5 * spec.governor.q * (vg.steam_load + vg.weight)
    return B1 / (inertia * (omega0**2 - k2))


# ----------------------------------------------------------------------------------------------
# Eq. (14): the reaction moment and its harmonics
# ----------------------------------------------------------------------------------------------

@settings(max_examples=25, deadline=None)
@given(delta=st.floats(0.2, 2.9), w2=st.floats(100.0, 2000.0),
       engine=st.sampled_from(vg.ENGINES))
def test_mean_of_reaction_moment_is_eq11(delta, w2, engine):
    """The mean of M_r(theta) over a revolution is M_r0 of eq. (11), for either engine."""
    w = math.sqrt(w2)
    scale = 0.5 * VG["q"] * (VG["P1"] + VG["P3"] + VG["P4"])
    # friction switches at lo and lo + pi: integrate each half apart (Gauss-Legendre, exact
    # for the trigonometric polynomial on each half; the moment is evaluated with its sign())
    lo = math.pi / 2 - delta
    x, wts = np.polynomial.legendre.leggauss(30)
    mean = sum(np.sum(wts * vg.reaction_moment(lo + (k + (x + 1) / 2) * math.pi, delta, w,
                                               engine=engine, **VG)) * math.pi / 2
               for k in (0, 1)) / (2 * math.pi)
    ref = vg.mean_reaction_moment(delta, w, VG["q"], VG["e"], VG["s"], VG["P1"], VG["m_v"],
                                  VG["m_e"])
    assert abs(mean - ref) <= 1e-12 * scale
    a, _ = hm.reaction_harmonics(delta, w, n_harmonics=0, engine=engine, **VG)
    assert abs(a[0] - ref) <= 1e-12 * scale


def test_paper_coefficients_from_the_model_doc():
    """A2, B2, A4, B4 as printed (eq. 14, signs included) equal the numerical harmonics of the
    force models. Paper's convention: M_r = A0 + B1 sin - [A2 cos2 + B2 sin2] + [A4 cos4 + ...].

    First principles for the one term where a sign slip would hide: the reciprocating inertia
    ``P2' = (m_v w^2 e / sin d) sin(d + t) sin(t) = (m_v w^2 e / 2)[cot d - cot d cos 2t +
    sin 2t]``, so its ``sin 2theta`` term is ``+m_v w^2 e/2`` and, behind the minus sign of
    eq. (14), ``B2`` carries ``-m_v w^2 e / 2`` as printed.
    """
    q, P1, mv, e = VG["q"], VG["P1"], VG["m_v"], VG["e"]
    for delta in np.radians([48.5, 58.0, 69.0, 84.0, 96.0]):
        a, b = hm.reaction_harmonics(delta, W0, n_harmonics=4, **VG)
        fr = (q / 2) * (2 * P1 / np.pi)
        inertia = (q / 2) * mv * W0**2 * e / 2
        A2 = fr * (np.sin(delta) + np.sin(3 * delta) / 3) + inertia / np.tan(delta)
        B2 = fr * (np.cos(delta) + np.cos(3 * delta) / 3) - inertia
        A4 = fr * (np.sin(3 * delta) / 3 + np.sin(5 * delta) / 5)
        B4 = fr * (np.cos(3 * delta) / 3 + np.cos(5 * delta) / 5)
        B1 = (q / 2) * (VG["P3"] + VG["P4"])
        scale = abs(B1)
        np.testing.assert_allclose([a[1], b[1]], [0.0, B1], atol=1e-12 * scale)
        np.testing.assert_allclose([a[2], b[2]], [-A2, -B2], rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose([a[4], b[4]], [A4, B4], rtol=0, atol=1e-12 * scale)
        np.testing.assert_allclose([a[3], b[3]], [0.0, 0.0], atol=1e-12 * scale)


@pytest.mark.parametrize("engine", vg.ENGINES)
def test_series_equals_numerical_harmonics(engine):
    """The general friction term of harmonic 2j, ``(-1)^j (2P1/pi)[sin((2j-1)d)/(2j-1) +
    sin((2j+1)d)/(2j+1)]``, and all the rest of eq. (14), against the numerical harmonics, up to
    order 300 (1e-10 relative to B1; in fact ~1e-13)."""
    deltas = np.radians([10.0, 48.5, 69.0, 96.0, 150.0])
    a, b = hm.reaction_harmonics(deltas, W0, n_harmonics=300, engine=engine, **VG)
    A, B = hm.series_harmonics(deltas, W0, n_harmonics=300, engine=engine, **VG)
    a_s, b_s = hm.paper_to_fourier(A, B)
    scale = 0.5 * VG["q"] * VG["P3"]
    assert np.max(np.abs(a - a_s)) < 1e-10 * scale
    assert np.max(np.abs(b - b_s)) < 1e-10 * scale
    # the general 2j formula written out, j = 7 (order 14), sign (-1)^7 in the paper's series
    d, j = deltas[2], 7
    fr = (VG["q"] / 2) * (2 * VG["P1"] / np.pi)
    A14 = fr * (np.sin(13 * d) / 13 + np.sin(15 * d) / 15)
    B14 = fr * (np.cos(13 * d) / 13 + np.cos(15 * d) / 15)
    assert abs(a[2, 14] - (-1) ** j * A14) < 1e-12 * scale
    assert abs(b[2, 14] - (-1) ** j * B14) < 1e-12 * scale


def test_horizontal_engine_first_harmonic():
    """Horizontal engine (eq. 8): ``P3 sin(theta) - P4 cos(theta)``: A1 = -(q/2) P4 on cos(theta),
    B1 = (q/2) P3; the mean (eq. 11) and every other harmonic are those of the vertical engine."""
    d = np.radians(69.0)
    a_h, b_h = hm.reaction_harmonics(d, W0, n_harmonics=6, engine="horizontal", **VG)
    a_v, b_v = hm.reaction_harmonics(d, W0, n_harmonics=6, engine="vertical", **VG)
    q = VG["q"]
    assert a_h[1] == pytest.approx(-q / 2 * VG["P4"], rel=1e-13)
    assert b_h[1] == pytest.approx(q / 2 * VG["P3"], rel=1e-13)
    mask = np.arange(7) != 1
    np.testing.assert_allclose(a_h[mask], a_v[mask], rtol=0, atol=1e-13)
    np.testing.assert_allclose(b_h[mask], b_v[mask], rtol=0, atol=1e-13)


def test_truncation_error_parseval():
    """RMS of the neglected tail, exactly from Parseval; falls like N^-1/2 (the friction's square
    wave), ``tail * sqrt(N) -> q P1 |cos delta| / pi``; and equals the RMS of the actual
    remainder M_r - (kept harmonics), integrated piecewise."""
    d = np.radians(69.0)
    Ns = [2, 4, 8, 16, 64, 256, 512]
    tails = np.array([hm.truncation_error(N, d, W0, **VG) for N in Ns])
    assert np.all(np.diff(tails) < 0)
    limit = VG["q"] * VG["P1"] * abs(np.cos(d)) / np.pi
    ratio = tails * np.sqrt(Ns) / limit
    assert np.all(np.diff(ratio) > 0) and abs(ratio[-1] - 1) < 2e-3
    # the remainder itself
    N = 6
    a, b = hm.reaction_harmonics(d, W0, n_harmonics=N, **VG)
    n = np.arange(N + 1)

    def remainder_sq(theta, piece):
        full = 0.5 * VG["q"] * piece * VG["P1"] * np.sin(theta) + vg.reaction_moment(
            theta, d, W0, **{**VG, "P1": 0.0})
        kept = np.cos(theta[..., None] * n) @ a + np.sin(theta[..., None] * n) @ b
        return (full - kept) ** 2

    ms, _ = hm.piecewise_fourier(remainder_sq, np.pi / 2 - d, 0, nodes=200)
    assert math.sqrt(ms[0]) == pytest.approx(hm.truncation_error(N, d, W0, **VG), rel=1e-10)


# ----------------------------------------------------------------------------------------------
# Example 2
# ----------------------------------------------------------------------------------------------

def test_example2_k2_at_normal_configuration(normal):
    """k^2 at the normal configuration, paper's fidelity: 362, 332, 314, 200 against the paper's
    360, 330, 310, 200 (within 1.3 %); d': 311, not the paper's 233 (a slip)."""
    for case in ("a", "b", "c", "d"):
        _, _, k2 = normal[case]
        assert k2 == pytest.approx(PAPER[case][0], rel=0.04)
    k2_dp = normal["d-prime"][2]
    assert k2_dp == pytest.approx(312, rel=0.01)
    assert abs(k2_dp / 233 - 1) > 0.3  # the printed 233 does not follow from its own spring


def test_example2_first_harmonic(normal):
    """First-harmonic amplitude = B1 / (I (omega0^2 - k^2)) (exact without speed fluctuation, 1e-3
    with the paper's E2, F2), and against the paper's 8.45, 9.05, 10.4, 10.4 deg.

    Ours (240 rpm: omega0^2 = 631.65; k^2 from the spec): 8.45, 9.12, 10.75, 10.55 deg, i.e.
    +0.0, +0.8, +3.4, +1.5 %. With the paper's rounded k^2 and omega0^2 = 630 the same formula
    gives 8.43, 9.10, 10.67, 10.59: the paper's 10.4 for case c is 2.5 % below its own inputs.
    """
    ours = {"a": 8.447, "b": 9.120, "c": 10.749, "d": 10.554}
    for case, expect in ours.items():
        spec, res, k2 = normal[case]
        a0, w0 = spec.governor.alpha_normal, spec.speed.omega_mean
        est = B1_estimate(spec, res.spring.inertia, k2, w0)
        v = V.vibration(spec, res.spring, a0, k2, w0, dashpot=None)
        assert v.amplitude(1) == pytest.approx(est, rel=1e-12)
        assert v.harmonics[0]["sin_rad"] == pytest.approx(est, rel=1e-12)  # N1/(k^2 - w0^2)
        assert math.degrees(v.amplitude(1)) == pytest.approx(expect, abs=1e-3)
        paper_deg = PAPER[case][1][1]
        assert math.degrees(v.amplitude(1)) == pytest.approx(paper_deg, rel=0.04)
        # the paper's own inputs
        paper_k2 = PAPER[case][0]
        own = math.degrees(B1_estimate(spec, res.spring.inertia, paper_k2, W0))
        assert own == pytest.approx(paper_deg, rel=0.03)
        # with the speed fluctuation the first harmonic hardly changes (factor 1 + E2/4 w0)
        vf = V.vibration(spec, res.spring, a0, k2, w0, dashpot=None,
                         speed_fluctuation=(E2_PAPER, F2_PAPER))
        assert vf.amplitude(1) == pytest.approx(est, rel=1e-3)
        assert vf.amplitude(1) == pytest.approx(
            float(V.first_harmonic_amplitude(spec, a0, k2, res.spring.inertia,
                                             speed_fluctuation=(E2_PAPER, F2_PAPER))), rel=1e-12)


def test_example2_d_prime_slip(normal):
    """d': the paper's 11.4 deg follows from its slipped k^2 = 233 (11.47 deg with omega0^2 =
    630); its own spring gives k^2 = 311 and an amplitude of 14.2 deg, 25 % more."""
    spec, res, k2 = normal["d-prime"]
    inertia, w0 = res.spring.inertia, spec.speed.omega_mean
    slip = math.degrees(B1_estimate(spec, inertia, 233.0, W0))
    assert slip == pytest.approx(11.4, rel=0.01)
    v = V.vibration(spec, res.spring, spec.governor.alpha_normal, k2, w0, dashpot=None)
    consistent = math.degrees(v.amplitude(1))
    assert consistent == pytest.approx(14.22, abs=0.01)
    assert consistent / 11.4 > 1.2


def test_example2_table_and_the_B2_sign_slip():
    """The rest of the table, with the paper's k^2 and omega0^2 = 630 and the inferred E2 = F2 =
    -0.028 rad/s: M1, M2, M3, M4, N4 agree within 5 %; N2 has the opposite sign. Taking the
    reciprocating inertia in B2 as +m_v omega^2 e/2 (against eq. 14 and the force model, see
    test_paper_coefficients_from_the_model_doc) reproduces the paper's N2 to 1 % in all five
    cases, so the table carries that sign slip. N3 (1e-4 deg) comes out with the opposite sign
    to the paper's at the same magnitude."""
    for case, (k2, row) in PAPER.items():
        spec = paper_spec(case, reaction_speed="local")  # valve gear at omega0 = sqrt(630)
        res = evaluate(spec)
        v = V.vibration(spec, res.spring, spec.governor.alpha_normal, float(k2), W0, 4,
                        dashpot=None, speed_fluctuation=(E2_PAPER, F2_PAPER))
        h = v.harmonics
        got = np.degrees([h[0]["cos_rad"], h[0]["sin_rad"], h[1]["cos_rad"], h[1]["sin_rad"],
                          h[2]["cos_rad"], h[2]["sin_rad"], h[3]["cos_rad"], h[3]["sin_rad"]])
        for i in (0, 1, 2, 4, 6, 7):  # M1, N1, M2, M3, M4, N4
            assert got[i] == pytest.approx(row[i], rel=0.05), (case, i)
        assert np.sign(got[3]) == -np.sign(row[3])  # N2: opposite sign
        assert np.sign(got[5]) == -np.sign(row[5])  # N3: opposite sign
        assert abs(got[5]) == pytest.approx(abs(row[5]), rel=0.1)
        vgear = spec.governor.valve_gear
        flip = (0.5 * spec.governor.q * vgear.reciprocating_mass * W0**2 * vgear.eccentricity
                / (res.spring.inertia * (k2 - 4 * W0**2)))
        assert math.degrees(h[1]["sin_rad"] + flip) == pytest.approx(row[3], rel=0.01), case


# ----------------------------------------------------------------------------------------------
# Forcing, response, damping, resonance
# ----------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def case_a():
    spec = load_spec(SPECS / "hamabe-a.toml")
    res = evaluate(spec)
    return spec, res


def test_forcing_without_fluctuation_is_minus_the_reaction(case_a):
    spec, res = case_a
    a0, sd = spec.governor.alpha_normal, res.spring
    a, b = V.forcing_harmonics(spec, a0, sd.m, sd.inertia, n_harmonics=20,
                               speed_fluctuation=(0.0, 0.0))
    vgear, g = spec.governor.valve_gear, spec.governor
    delta = vg.advance_angle(a0, vgear.table_alpha, vgear.table_delta)
    ar, br = hm.reaction_harmonics(delta, spec.speed.omega_mean, g.q, vgear.eccentricity,
                                   vgear.offset, vgear.friction, vgear.steam_load, vgear.weight,
                                   vgear.reciprocating_mass, vgear.eccentric_mass, 20)
    np.testing.assert_allclose(a[1:], -ar[1:], atol=1e-13)
    np.testing.assert_allclose(b[1:], -br[1:], atol=1e-13)
    assert abs(a[0]) < 1e-13


def test_first_harmonic_bessel_and_tangential_inertia(case_a):
    """The vectorised Jacobi-Anger first harmonic equals the numerical one even for a large
    fluctuation; the tangential-inertia option adds exactly (I - m a rho cos a0) omega' to the
    second harmonic and nothing else."""
    spec, res = case_a
    a0, sd = spec.governor.alpha_normal, res.spring
    w0 = spec.speed.omega_mean
    E2, F2 = 1.5, -2.5  # |eta| / omega0 ~ 0.12
    for engine in vg.ENGINES:
        gov = spec.governor
        sp = dataclasses.replace(spec, governor=dataclasses.replace(
            gov, valve_gear=dataclasses.replace(gov.valve_gear, engine=engine)))
        a, b = V.forcing_harmonics(sp, a0, sd.m, sd.inertia, n_harmonics=3,
                                   speed_fluctuation=(E2, F2))
        amp = V.first_harmonic_amplitude(sp, a0, 300.0, sd.inertia, speed_fluctuation=(E2, F2))
        assert float(amp) == pytest.approx(math.hypot(a[1], b[1]) / (sd.inertia * (w0**2 - 300)),
                                           rel=1e-12)
    a, b = V.forcing_harmonics(spec, a0, sd.m, sd.inertia, n_harmonics=6,
                               speed_fluctuation=(E2, F2))
    at, bt = V.forcing_harmonics(spec, a0, sd.m, sd.inertia, n_harmonics=6,
                                 speed_fluctuation=(E2, F2), tangential_inertia=1)
    g = spec.governor
    c = sd.inertia - sd.m * g.a * g.rho * math.cos(a0)
    expect_a = np.zeros(7)
    expect_b = np.zeros(7)
    expect_a[2], expect_b[2] = 2 * w0 * F2 * c, -2 * w0 * E2 * c
    np.testing.assert_allclose(at - a, expect_a, atol=1e-12)
    np.testing.assert_allclose(bt - b, expect_b, atol=1e-12)
    v = V.vibration(spec, sd, a0, tangential_inertia=-1)
    assert 0.2 < v.tangential_inertia_ratio < 0.35  # ~26 % of the centrifugal term


def test_damping_lowers_the_amplitude_and_bounds_resonance(case_a):
    spec, res = case_a
    a0, sd = spec.governor.alpha_normal, res.spring
    w0 = spec.speed.omega_mean
    k2 = float(np.interp(a0, res.statics.alpha, res.k2))
    fs = [0.0, 0.1, 0.5, 2.0, spec.design.dashpot, 20.0]
    amps = [V.vibration(spec, sd, a0, k2, dashpot=f, n_harmonics=6) for f in fs]
    for n in range(1, 7):
        seq = [v.amplitude(n) for v in amps]
        assert all(x >= y for x, y in zip(seq, seq[1:], strict=False))
    p2p = [v.peak_to_peak_rad for v in amps]
    assert all(x > y for x, y in zip(p2p, p2p[1:], strict=False))
    # at exact resonance, damped: finite, |G_1| / (f omega0)
    f = spec.design.dashpot
    v = V.vibration(spec, sd, a0, w0**2, dashpot=f, n_harmonics=6)
    G1 = math.hypot(v.harmonics[0]["moment_cos_N_m"], v.harmonics[0]["moment_sin_N_m"])
    assert not v.resonance and math.isfinite(v.peak_to_peak_rad)
    assert v.amplitude(1) == pytest.approx(G1 / (f * w0), rel=1e-12)
    # the spec's dash-pot (Example 3's a1 = 24 kgf cm s) cuts the swing about fourfold
    undamped = V.vibration(spec, sd, a0, k2, dashpot=None)
    damped = V.vibration(spec, sd, a0, k2)  # dashpot from the design
    assert damped.dashpot == spec.design.dashpot
    assert 3 < undamped.peak_to_peak_rad / damped.peak_to_peak_rad < 6
    assert damped.eccentric_travel_m == pytest.approx(spec.governor.q * damped.peak_to_peak_rad)


def test_undamped_resonance_is_flagged_not_nan(case_a):
    spec, res = case_a
    a0, sd = spec.governor.alpha_normal, res.spring
    w0 = spec.speed.omega_mean
    for n, fluct in ((1, None), (2, None), (3, (0.0, 0.0)), (3, (-0.028, -0.028))):
        v = V.vibration(spec, sd, a0, (n * w0) ** 2, dashpot=None, n_harmonics=6,
                        speed_fluctuation=fluct)
        assert v.resonance and v.resonant_orders == (n,)
        assert v.hamabe_case == 2
        h = v.harmonics[n - 1]
        excited = math.hypot(h["moment_cos_N_m"], h["moment_sin_N_m"]) > 1e-12
        assert h["amplitude_rad"] == (math.inf if excited else 0.0)
        assert (v.peak_to_peak_rad == math.inf) == excited
        values = [x for hh in v.harmonics for x in hh.values() if isinstance(x, float)]
        assert not any(math.isnan(x) for x in values)
        assert not math.isnan(v.peak_to_peak_rad) and not math.isnan(v.truncation_error_rad)
        d = v.to_dict()
        json.dumps(d, allow_nan=False)
        assert d["resonance"] is True and d["resonant_orders"] == [n]
        if excited:  # JSON: an infinity is null with a flag beside it
            assert (d["peak_to_peak_rad"], d["peak_to_peak_rad_infinite"]) == (None, "+inf")
            h = d["harmonics"][n - 1]
            assert (h["amplitude_rad"], h["amplitude_rad_infinite"]) == (None, "+inf")
    # unstable (Case 3) still reports, flagged
    v = V.vibration(spec, sd, a0, -50.0, dashpot=None)
    assert not v.stable and v.hamabe_case == 3 and math.isfinite(v.peak_to_peak_rad)
    # vectorised: resonant entries inf, no NaN
    k2 = np.array([100.0, w0**2, 4 * w0**2, 300.0])
    f = np.array([0.0, 0.0, 0.0, 1.0])
    fh = V.first_harmonic_amplitude(spec, a0, k2, sd.inertia, f)
    assert np.isinf(fh[1]) and np.all(np.isfinite(fh[[0, 2, 3]]))
    pb = V.peak_amplitude_bound(spec, a0, k2, sd.inertia, sd.m, f)
    assert np.all(np.isinf(pb[1:3])) and np.all(np.isfinite(pb[[0, 3]]))
    assert not np.any(np.isnan(fh)) and not np.any(np.isnan(pb))


def test_vectorised_measures_match_vibration(case_a):
    """first_harmonic_amplitude and peak_amplitude_bound over many designs at once agree with
    vibration() design by design; the bound covers half the peak-to-peak, truncation included."""
    spec, res = case_a
    sd = res.spring
    w0 = spec.speed.omega_mean
    alpha = np.radians([52.0, 64.0 + 40 / 60, 78.0])[:, None]
    k2 = np.array([150.0, 350.0, 500.0])[None, :]
    inertia = np.array([0.12, sd.inertia, 0.25])[None, :]
    m = inertia / spec.governor.rho**2
    f = np.array([0.0, 2.0, 7.0])[None, :]
    fh = V.first_harmonic_amplitude(spec, alpha, k2, inertia, f)
    pb = V.peak_amplitude_bound(spec, alpha, k2, inertia, m, f, n_harmonics=8)
    assert fh.shape == pb.shape == (3, 3)
    for i in range(3):
        for j in range(3):
            sdj = dataclasses.replace(sd, m=float(m[0, j]), inertia=float(inertia[0, j]))
            v = V.vibration(spec, sdj, float(alpha[i, 0]), float(k2[0, j]), w0, 8,
                            dashpot=float(f[0, j]))
            assert fh[i, j] == pytest.approx(v.amplitude(1), rel=1e-12)
            total = sum(h["amplitude_rad"] for h in v.harmonics) + v.truncation_error_rad
            assert pb[i, j] == pytest.approx(total, rel=1e-12)
            assert 0.5 * v.peak_to_peak_rad <= pb[i, j]


def test_truncation_estimate_covers_the_left_out_harmonics(case_a):
    """The peak-to-peak with N harmonics is within 2 * truncation_error of the complete one
    (400 harmonics), and the estimate falls towards 1/N^2 (the friction's 1/n coefficients over
    the pendulum's n^2)."""
    spec, res = case_a
    a0, sd = spec.governor.alpha_normal, res.spring
    for f in (None, "design"):
        ref = V.vibration(spec, sd, a0, n_harmonics=400, dashpot=f,
                          speed_fluctuation=(E2_PAPER, F2_PAPER))
        errs = []
        for N in (1, 2, 4, 8, 16, 32):
            v = V.vibration(spec, sd, a0, n_harmonics=N, dashpot=f,
                            speed_fluctuation=(E2_PAPER, F2_PAPER))
            assert abs(v.peak_to_peak_rad - ref.peak_to_peak_rad) <= 2 * v.truncation_error_rad
            errs.append(v.truncation_error_rad)
        assert all(x > y for x, y in zip(errs, errs[1:], strict=False))
        assert 10 < errs[-3] / errs[-1] < 16  # N = 8 -> 32: approaching 1/N^2 from below
        assert ref.truncation_error_rad < 1e-7


def test_steady_response_against_time_integration(case_a):
    """Integrate I xi'' + f xi' + I k^2 xi = G(t) from rest over seven revolutions (the spec's
    dash-pot kills the transient as exp(-f t / 2I) ~ 1e-13), stepping exactly across the
    friction switches, with G built directly from the public force model
    (valvegear.reaction_moment, eqs. 1, 14, 19); the harmonic solution (eq. 22 with damping,
    400 harmonics) agrees to ~1e-7 of the amplitude."""
    spec, res = case_a
    a0, sd = spec.governor.alpha_normal, res.spring
    g, vgear = spec.governor, spec.governor.valve_gear
    w0 = spec.speed.omega_mean
    E2, F2 = -0.028, 0.02
    v = V.vibration(spec, sd, a0, n_harmonics=400, speed_fluctuation=(E2, F2))
    I, f, k2 = sd.inertia, v.dashpot, v.k2
    delta = v.delta
    Mr0 = vg.mean_reaction_moment(delta, w0, g.q, vgear.eccentricity, vgear.offset,
                                  vgear.friction, vgear.reciprocating_mass, vgear.eccentric_mass)
    lever = sd.m * g.a * g.rho * math.sin(a0)
    args = (g.q, vgear.eccentricity, vgear.offset, vgear.friction, vgear.steam_load,
            vgear.weight, vgear.reciprocating_mass, vgear.eccentric_mass)

    def G(t):
        tau = w0 * t
        eta = E2 * math.cos(2 * tau) + F2 * math.sin(2 * tau)
        eta_dot = 2 * w0 * (-E2 * math.sin(2 * tau) + F2 * math.cos(2 * tau))
        theta = tau + E2 / (2 * w0) * math.sin(2 * tau) - F2 / (2 * w0) * math.cos(2 * tau)
        Mr = float(vg.reaction_moment(theta, delta, w0 + eta, *args, omega_dot=eta_dot))
        return lever * ((w0 + eta) ** 2 - w0**2) - (Mr - Mr0)

    def rhs(t, y):
        return [y[1], (G(t) - f * y[1] - I * k2 * y[0]) / I]

    T = 2 * math.pi / w0
    tau_a = float(V._switch_start(V._setup(spec, a0, sd.m, I, None, 0, (E2, F2))))
    stops = [(tau_a + k * math.pi) / w0 for k in range(30)]
    stops = sorted({s for s in stops if 0 < s < 7 * T} | {7 * T})
    y, t, pieces = [0.0, 0.0], 0.0, []
    for s in stops:
        sol = integrate.solve_ivp(rhs, (t, s), y, method="DOP853", rtol=1e-11, atol=1e-13,
                                  dense_output=True)
        pieces.append(sol)
        y, t = sol.y[:, -1], s
    X = np.array([h["cos_rad"] for h in v.harmonics])
    Y = np.array([h["sin_rad"] for h in v.harmonics])
    n = np.arange(1, len(X) + 1)
    tt = np.linspace(6 * T, 7 * T, 97)
    ode = np.array([next(p for p in pieces if p.t[0] <= x <= p.t[-1]).sol(x)[0] for x in tt])
    harmonic = np.cos(np.outer(w0 * tt, n)) @ X + np.sin(np.outer(w0 * tt, n)) @ Y
    harmonic += v.mean_offset_rad
    amplitude = 0.5 * v.peak_to_peak_rad
    assert np.max(np.abs(ode - harmonic)) < 1e-6 * amplitude


def test_peak_to_peak_is_refined_past_the_grid():
    """The peak-to-peak swing is refined by root finding on the derivative, not the FFT grid's
    coarse maximum (brentq once ran with an rtol below its minimum, raised, and the grid value
    was kept silently): on one harmonic it is exactly twice the amplitude."""
    X, Y = np.array([0.3]), np.array([0.4])  # amplitude 0.5, phase off the grid's nodes
    p2p, _, _ = V._peak_to_peak(X, Y)
    assert p2p == pytest.approx(1.0, rel=1e-14)  # the grid alone is ~1e-7 short here


def test_many_designs_at_once_are_each_designs_own_vibration():
    """:func:`vibrations` of many designs (masses, stiffnesses and dash-pots of their own; one
    stiff enough to need a longer explicit tail, one undamped at an exact resonance) gives each
    design the vibration it has alone, and a peak-to-peak that a dense sampling of the kept
    harmonics confirms."""
    from govopt.analysis.statics import SpringDesign

    spec = load_spec(SPECS / "hamabe-a.toml")
    a0, w0 = spec.governor.alpha_normal, spec.speed.omega_mean
    m = np.array([10.0, 12.0, 14.0, 12.0, 11.0])
    inertia = m * spec.governor.rho**2
    k2 = np.array([300.0, 360.0, 500.0, 1600.0 * w0**2, w0**2])
    f = np.array([2.0, 0.0, 5.0, 1.0, 0.0])
    many = V.vibrations(spec, SpringDesign(m, inertia, 0.0, 0.0), a0, k2, dashpot=f)
    assert len(np.unique(V._tail_counts(spec.analysis.harmonics, k2, w0))) == 2
    assert math.isinf(many.peak_to_peak_rad[4]) and many[4].resonant_orders == (1,)
    tau = np.linspace(0.0, 2.0 * np.pi, 200_001)
    for i in range(len(m)):
        one = V.vibration(spec, SpringDesign(m[i], inertia[i], 0.0, 0.0), a0, k2[i],
                          dashpot=f[i])
        both = many[i]
        assert both.harmonics == one.harmonics
        assert both.truncation_error_rad == one.truncation_error_rad
        assert both.peak_to_peak_rad == one.peak_to_peak_rad
        if math.isfinite(one.peak_to_peak_rad):
            _, xi = one.trace(tau.size)
            sampled = xi.max() - xi.min()  # from below, within the grid's (2 pi / 2e5)^2
            assert sampled <= one.peak_to_peak_rad <= sampled * (1.0 + 1e-9)
