"""Evaluate a given design: statics, spring, restoring stiffness, and the checks (Hamabe I-III).

Only what the spec asks for is modelled: dynamics run when the spec has engine data, friction
only when the design has a friction moment.
"""

from __future__ import annotations

import numpy as np

from .analysis import statics
from .model import spring
from .result import Check, Result
from .spec import Design, Spec


def spring_properties(spec: Spec, sd: statics.SpringDesign) -> dict[str, float]:
    """Derived spring quantities (SI) for reports: index, Wahl factor, mass, surge frequency."""
    mat = spec.material
    C = spring.spring_index(sd.d, sd.r)
    return {
        "spring_index": C,
        "wahl_factor": float(spring.wahl_factor(C)),
        "mass_kg": spring.wire_mass(sd.d, sd.r, sd.n, mat.density),
        "surge_frequency_Hz": spring.surge_frequency(sd.d, sd.r, sd.n, mat.shear_modulus,
                                                     mat.density),
        "body_length_m": (sd.n + 1.0) * sd.d,
    }


def evaluate(spec: Spec, design: Design | None = None) -> Result:
    """Evaluate ``design`` (default: the spec's own ``[design]``) against the spec."""
    design = design or spec.design
    sd = statics.spring_design(spec, design)
    char = statics.characteristic(spec, sd)
    k2 = statics.restoring_k2(spec, char.alpha, sd, char.omega**2)
    w0sq = spec.speed.omega_mean**2
    checks = [
        Check("shear stress", float(np.max(char.stress)), spec.material.allowable_shear_stress,
              "<=", "Pa", "Hamabe Ex. 1: 16 F r / (pi d^3) <= k_s"),
        Check("irregularity", char.irregularity, spec.speed.irregularity, "<=", "",
              "Hamabe Part I: (omega_a - omega_i) / omega_mean"),
        Check("k^2 > 0 (stability)", float(np.min(k2)), 0.0, ">=", "rad^2/s^2",
              "Hamabe Part II, case 3", scale=w0sq),
        Check("k^2 < omega0^2 (no resonance)", float(np.max(k2)), w0sq, "<=", "rad^2/s^2",
              "Hamabe Part II, case 2"),
    ]
    return Result(spec=spec, design=design, spring=sd, statics=char,
                  spring_properties=spring_properties(spec, sd), checks=checks, k2=k2)
