"""The seam every governor plugs into: nothing outside a type's own module branches on the type,
and every registered type supplies the seam consistently (k^2 against the equilibrium curve)."""

import re
from pathlib import Path

import numpy as np
import pytest

import govopt
from govopt.analysis import statics
from govopt.governors import REGISTRY, governor_class

PACKAGE = Path(govopt.__file__).resolve().parent
SPECS = PACKAGE.parent / "specs"


def test_no_type_branches_outside_the_governors():
    """No ``if type == ...`` (or a type's name or class) outside ``govopt/governors/``."""
    names = "|".join(map(re.escape, REGISTRY))
    pattern = re.compile(rf"""(["'])({names})\1|governor_type\s*[=!]=|type_name\s*[=!]=|"""
                         r"isinstance\([^)]*Governor\)")
    offenders = []
    for path in PACKAGE.rglob("*.py"):
        if "governors" in path.relative_to(PACKAGE).parts:
            continue
        for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if line.strip().startswith((">>>", "...")):
                continue  # a docstring example names a type as data, not as a branch
            if pattern.search(line):
                offenders.append(f"{path.relative_to(PACKAGE)}:{i}: {line.strip()}")
    assert offenders == []


@pytest.mark.parametrize("type_name", sorted(REGISTRY))
def test_registry_classes_supply_the_seam(type_name):
    cls = governor_class(type_name)
    assert cls.type_name == type_name
    assert cls.coordinate in ("angle", "length")
    for method in ("parse", "terms", "inertia"):
        assert getattr(cls, method) is not getattr(govopt.governors.Governor, method)


SPEC_FILES = sorted(p for p in SPECS.glob("*.toml")
                    if "[design]" in p.read_text(encoding="utf-8"))


@pytest.mark.parametrize("path", SPEC_FILES, ids=lambda p: p.stem)
def test_k2_is_the_slope_of_the_characteristic(path):
    """At equilibrium I k^2 = (jp - ci) d(omega^2)/dx at constant design: k^2 from the seam's
    derivatives against a central difference of the characteristic itself (every type)."""
    spec = govopt.load_spec(path)
    sd = statics.spring_design(spec)
    gov = spec.governor
    x = np.linspace(gov.x_inner, gov.x_outer, 9)[1:-1]
    h = 1e-5 * (gov.x_outer - gov.x_inner)

    def w2(u):
        return statics.omega_squared(spec, u, sd.m, sd.kappa, sd.l0, sd.central)

    slope = (w2(x + h) - w2(x - h)) / (2 * h)
    t = statics.terms(spec, x, sd.m, sd.central)
    k2 = statics.restoring_k2(spec, x, sd, w2(x))
    want = t.lever * slope / statics.inertia(spec, sd, x)
    np.testing.assert_allclose(k2, want, rtol=2e-6, atol=1e-9 * np.max(np.abs(want)))


def test_nonlinear_reference_on_a_ball_governor():
    """The load-change model is the exact linearisation for every type: on the Porter driving an
    engine the nonlinear reference departs from it at second order (relative error linear in
    the load change, no first-order floor), and both settle at the new equilibrium."""
    from govopt.analysis import nonlinear
    from govopt.spec import LoadChange

    spec = govopt.load_spec(SPECS / "porter-engine.toml")
    sd = statics.spring_design(spec)
    errs = []
    for d in (0.0005, 0.002):
        e = nonlinear.linearisation_error(spec, sd, LoadChange("x", 0.23 - d, 0.23))
        errs.append(e["max_rel_error"])
        # the run lasts 12 time constants of the slowest mode: e^-12 = 6e-6 of the start is left
        assert abs(e["final_xi_rad"]) < 2e-5 * d
    assert errs[1] / errs[0] == pytest.approx(4.0, rel=0.05)


AFFINE_CENTRAL = [p for p in sorted(SPECS.glob("*.toml"))
                  if governor_class(govopt.load_spec(p).governor.type_name).central_load_affine]


@pytest.mark.parametrize("path", AFFINE_CENTRAL, ids=lambda p: p.stem)
def test_a_declared_affine_central_load_is_affine(path):
    """A type that declares its forces affine in the central load (``central_load_affine``,
    which the dead-weight diagnosis solves in closed form) has terms and inertia affine in it
    and the lever ``jp - ci`` free of it, at every configuration."""
    spec = govopt.load_spec(path)
    gov, x = spec.governor, statics.configurations(spec)
    m = np.array([[1.5], [4.0]])
    at = {c: statics.terms(spec, x, m, np.full_like(m, c)) for c in (0.0, 1.0, 7.5)}
    for name in ("cf", "cf_x", "ci", "ci_x", "jp", "jpp", "A", "B", "A_x", "B_x"):
        t0, t1, t7 = (np.broadcast_to(getattr(at[c], name), (2, x.size)) for c in at)
        np.testing.assert_allclose(t7, t0 + 7.5 * (t1 - t0), rtol=1e-12, atol=1e-12)
    np.testing.assert_array_equal(at[0.0].lever, at[7.5].lever)
    i0, i1, i7 = (gov.inertia(x, m, np.full_like(m, c)) for c in (0.0, 1.0, 7.5))
    np.testing.assert_allclose(i7, i0 + 7.5 * (i1 - i0), rtol=1e-12)
