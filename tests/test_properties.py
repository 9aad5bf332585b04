"""Property-based tests: valid specs generated across the physical range of
every governor type either evaluate or fail with a classified diagnosis (a GovoptError: exit
2), never another exception; and invariants that hold for every input:

* a spec restated in other units (SI, inch-pound, ...) gives the same design figures;
* the spring's shear stress scales as ``F r / d^3`` (Hamabe, Example 1; the Wahl and
  Bergstraesser factors depend on the index ``2 r / d`` alone);
* a governor whose characteristic rises over the range (the "stable" check) has a
  non-negative irregularity ``(omega_a - omega_i) / omega0``.
"""

import math
import tomllib
import warnings

import numpy as np
import pytest
from hostile import bundled_specs
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from govopt.errors import GovoptError
from govopt.evaluator import evaluate
from govopt.governors import REGISTRY
from govopt.spec import parse_spec
from govopt.springs import helical as hx
from govopt.units import normalise, registry

SPECS = {p.stem: p for p in bundled_specs()}
#: one spec per governor type with a design to evaluate (the Watt's is its design spec with the
#: middle of its ball-weight bounds)
TEMPLATES = {
    "shaft": "hamabe-a", "porter": "porter-engine", "proell": "textbook-ex3-proell",
    "hartnell": "textbook-ex4-hartnell", "spring_loaded": "textbook-ex6-spring_loaded",
    "spring_gravity": "textbook-ex8-spring_gravity",
    "traction_coil": "traction-coil-replacement", "traction_leaf": "traction-leaf-assembly",
    "watt": "watt-design", "force_line": "force_line-design",
}


def _dimension(unit: str):
    """A hashable form of a unit's dimensionality."""
    return tuple(sorted(dict(registry().Quantity(normalise(unit)).dimensionality).items()))


#: the scaled dimensions (named by a unit of each): all quantities of one dimension are scaled
#: by one factor per example, so the spec stays consistent (a geometry scaled as a whole, all
#: loads by one factor ...)
SCALED = {_dimension(u): kind for u, kind in (
    ("m", "length"), ("kg", "mass"), ("N", "force"), ("rpm", "speed"), ("Pa", "stress"),
    ("N*m", "torque"), ("kg*m^2", "inertia"), ("N*s/m", "damping"), ("N*m*s", "damping"),
    ("kg/m^3", "density"), ("N/m", "stiffness"))}


def _template(gtype: str) -> dict:
    data = tomllib.loads(SPECS[TEMPLATES[gtype]].read_text())
    if "design" not in data:  # a design spec: evaluate the middle of its weight bounds
        for key in ("requirements", "bounds", "catalogue"):
            data.pop(key, None)
        data["design"] = {"ball_weight": "5.5 kgf"}
    return data


def _quantity(text):
    """The pint quantity of a quantity string (one that starts with a number: not a choice
    such as ``type = "watt"``), else None."""
    if not isinstance(text, str) or not text.lstrip("-+(")[:1].isdigit():
        return None
    try:
        q = registry().Quantity(normalise(text))
    except Exception:
        return None
    return None if not hasattr(q, "units") or q.unitless else q


def _map_quantities(node, change):
    """A copy of the TOML data with every quantity string ``q`` replaced by ``change(q)``."""
    if isinstance(node, dict):
        return {k: _map_quantities(v, change) for k, v in node.items()}
    if isinstance(node, list):
        return [_map_quantities(v, change) for v in node]
    q = _quantity(node)
    return node if q is None else change(q)


def _scaled(data: dict, factors: dict) -> dict:
    def change(q):
        kind = SCALED.get(tuple(sorted(dict(q.dimensionality).items())))
        return f"{q.magnitude * factors.get(kind, 1.0)!r} {q.units:~}".replace(" ** ", "^")

    return {k: (_map_quantities(v, change) if k != "name" else v) for k, v in data.items()}


def _run(data: dict):
    """Evaluate, or the GovoptError that says why not (any other exception fails the test)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the CLI holds them; here only outcomes count
        try:
            return evaluate(parse_spec(data, "generated.toml"))
        except GovoptError as exc:  # classified: names the file, one line
            assert str(exc).startswith("generated.toml: ") and "\n" not in str(exc), str(exc)
            return exc


factor = st.floats(0.25, 4.0)
factors = st.fixed_dictionaries({k: factor for k in sorted(set(SCALED.values()))})


def test_every_type_has_a_template():
    assert sorted(TEMPLATES) == sorted(REGISTRY)
    for gtype in TEMPLATES:  # unscaled, each evaluates
        assert not isinstance(_run(_template(gtype)), GovoptError), gtype


@pytest.mark.parametrize("gtype", sorted(TEMPLATES))
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(f=factors)
def test_generated_specs_evaluate_or_fail_clearly(gtype, f):
    """Lengths, masses, forces, speeds, stresses ... of one type's spec each scaled by a factor
    in [1/4, 4]: a result, or a GovoptError (exit 2); and where the characteristic rises over
    the range, the irregularity is not negative."""
    out = _run(_scaled(_template(gtype), f))
    if isinstance(out, GovoptError):
        return
    rises = [c for c in out.checks if c.name == "characteristic rises (stable)"]
    if rises and rises[0].passed and math.isfinite(out.irregularity):
        assert out.irregularity >= 0.0
        assert out.statics.omega[-1] >= out.statics.omega[0]


#: other units of each dimension for the restatement
UNITS = {_dimension(units[0]): units for units in (
    ["mm", "m", "inch", "ft"], ["g", "lb", "kg"], ["N", "lbf", "kN", "dyn"],
    ["rad/s", "rev/s", "deg/s"], ["Pa", "psi", "MPa", "kgf/mm^2"],
    ["N*m", "lbf*ft", "kgf*cm"], ["kg*m^2", "lb*ft^2"], ["kg/m^3", "lb/inch^3"],
    ["N/m", "lbf/inch", "kgf/cm"], ["N*s/m", "lbf*s/ft"], ["N*m*s/rad", "kgf*cm*s/rad"])}


@pytest.mark.parametrize("gtype", sorted(TEMPLATES))
@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pick=st.integers(0, 3))
def test_unit_restatements_agree(gtype, pick):
    """The same spec in other units (each quantity converted, to full precision) gives the same
    characteristic and spring, to rounding (1e-9 relative)."""
    data = _template(gtype)

    def change(q):
        units = UNITS.get(tuple(sorted(dict(q.dimensionality).items())))
        if not units or "radian" in str(q.units) or "degree" in str(q.units):
            return f"{q.magnitude!r} {q.units:~}".replace(" ** ", "^")
        unit = units[pick % len(units)]
        return f"{q.to(normalise(unit)).magnitude!r} {unit}"

    restated = {k: (_map_quantities(v, change) if k != "name" else v) for k, v in data.items()}
    a, b = _run(data), _run(restated)
    assert not isinstance(a, GovoptError) and not isinstance(b, GovoptError), (a, b)
    np.testing.assert_allclose(b.statics.omega, a.statics.omega, rtol=1e-9)
    np.testing.assert_allclose(b.statics.alpha, a.statics.alpha, rtol=1e-9)
    if a.spring.kappa is not None and np.isfinite(a.spring.kappa):
        np.testing.assert_allclose(b.spring.kappa, a.spring.kappa, rtol=1e-9)
        np.testing.assert_allclose(np.max(b.statics.stress), np.max(a.statics.stress),
                                   rtol=1e-9)


@settings(max_examples=200, deadline=None)
@given(F=st.floats(1e-2, 1e5), d=st.floats(1e-4, 5e-2), index=st.floats(3.0, 20.0),
       k=st.floats(0.1, 10.0), correction=st.sampled_from(["none", "wahl", "bergstrasser"]))
def test_stress_scales_as_F_r_over_d_cubed(F, d, index, k, correction):
    """``tau = K(C) 16 F r / (pi d^3)`` with ``C = 2 r / d`` (Hamabe Ex. 1; Wahl; EN 13906-1):
    proportional to ``F``, and ``k^-2`` when ``d`` and ``r`` both grow by ``k`` (the index
    kept); uncorrected, exactly ``16 F r / (pi d^3)``."""
    r = index * d / 2.0
    tau = hx.shear_stress_r(F, d, r, correction)
    assume(np.isfinite(tau) and tau > 0)
    assert hx.shear_stress_r(3.0 * F, d, r, correction) == pytest.approx(3.0 * tau, rel=1e-12)
    assert hx.shear_stress_r(F, k * d, k * r, correction) == pytest.approx(tau / k**2,
                                                                              rel=1e-12)
    if correction == "none":
        assert tau == pytest.approx(16.0 * F * r / (math.pi * d**3), rel=1e-14)
    else:
        assert tau > 16.0 * F * r / (math.pi * d**3)  # both factors exceed 1 for C > 1
