"""The one result type: an evaluated (or optimised) design, flowing to JSON, text, Excel, plots.

A :class:`Result` holds SI numbers only; writers format it and never recompute physics.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .analysis.statics import Characteristic, SpringDesign, classify_k2
from .jsonable import jsonable
from .spec import Design, Spec

#: Relative margin below which a satisfied constraint is reported as active (binding).
ACTIVE_TOL = 1e-3


@dataclass(frozen=True)
class Check:
    """One requirement: ``value`` against ``limit`` in the sense ``"<="`` or ``">="`` (SI)."""

    name: str
    value: float
    limit: float
    sense: str
    unit: str = ""
    source: str = ""
    scale: float | None = None
    #: Pass/fail decided elsewhere (e.g. :func:`govopt.analysis.transient.over_regulates`)
    #: where the margin alone cannot decide it; None: from the margin.
    verdict: bool | None = None

    @property
    def margin(self) -> float:
        """Relative margin: positive when satisfied, ``(limit - value)/|limit|`` for ``<=``
        (divided by ``scale`` instead where the limit is zero)."""
        scale = self.scale or (abs(self.limit) if self.limit != 0 else 1.0)
        diff = self.limit - self.value if self.sense == "<=" else self.value - self.limit
        return diff / scale

    @property
    def passed(self) -> bool:
        return self.margin >= -1e-9 if self.verdict is None else self.verdict

    @property
    def active(self) -> bool:
        return self.passed and self.margin < ACTIVE_TOL

    def to_dict(self) -> dict:
        """JSON-ready; ``value`` and ``limit`` in ``unit`` (the checks differ in units, so the
        unit is a field), infinities as null with a flag (:func:`govopt.jsonable.jsonable`)."""
        return jsonable({"name": self.name, "value": self.value, "limit": self.limit,
                         "sense": self.sense, "unit": self.unit, "margin": self.margin,
                         "passed": self.passed, "active": self.active, "source": self.source})


@dataclass
class Result:
    """Everything govopt knows about one design (SI)."""

    spec: Spec
    design: Design
    spring: SpringDesign
    statics: Characteristic
    spring_properties: dict[str, float]
    checks: list[Check] = field(default_factory=list)
    k2: np.ndarray | None = None
    dynamics: dict[str, Any] = field(default_factory=dict)
    optimisation: dict[str, Any] = field(default_factory=dict)
    kind: str = "evaluation"
    classic: dict[str, Any] = field(default_factory=dict)
    #: the helical spring's sheet for the spring maker, fatigue loads and manufacturing spread
    #: (:class:`govopt.analysis.spring_engineering.SpringReport`); None without a wire spring
    spring_report: Any = None

    @property
    def allowable_shear_stress(self) -> float | None:
        """The static allowable the spring is held to: the spec's ``allowable_shear_stress``,
        else the wire grade's rule at the design's wire diameter (Pa)."""
        mat = self.spec.material
        if mat is None or mat.allowable_shear_stress is not None:
            return None if mat is None else mat.allowable_shear_stress
        rep = self.spring_report
        return None if rep is None else rep.material.get("allowable_static_stress_Pa")

    @property
    def irregularity(self) -> float:
        """Hamabe's ``(omega_a - omega_i) / omega0`` (:attr:`Characteristic.irregularity`)."""
        return self.statics.irregularity

    @property
    def omega_reference(self) -> float:
        """The mean speed omega0 (rad/s) the k^2 margins refer to: the spec's, or, where a spec
        only evaluates a design (no [speed]), the design's speed at the normal configuration."""
        if self.spec.speed is not None:
            return self.spec.speed.omega_mean
        st = self.statics
        return float(np.interp(self.spec.governor.x_normal, st.alpha, st.omega))

    @property
    def max_stress(self) -> float:
        return float(np.max(self.statics.stress))

    def check(self, name: str) -> Check:
        return next(c for c in self.checks if c.name == name)

    def plot(self, kind: str | None = None, ax=None):
        """Draw plot ``kind`` (``"characteristic"``, ``"k2"``, ``"load-change-1"`` ...: see
        :func:`govopt.report.plots.kinds`) on the matplotlib axes ``ax`` (a new figure's if None)
        and return the axes; ``kind=None``: every plot in one new figure, returned."""
        from .report.plots import plot

        return plot(self, kind, ax)

    def _classic_json(self) -> dict:
        """The classic measures with each key's unit in its name: the effort in its force's unit
        (on the regulating member: N m for an angular travel, N for a linear one), the power in
        J, the friction band as a generalised force (N m for an angle coordinate, N for a
        length)."""
        cm = dict(self.classic)
        effort = cm.pop("effort_unit", "N*m").replace("*", "_")
        power = cm.pop("power_unit", "J")
        band = self.spec.governor.key_unit("force")
        renamed = {"effort": f"effort_{effort}", "power": f"power_{power}",
                   "friction_band": f"friction_band_{band}"}
        return {renamed.get(k, k): v for k, v in cm.items()}

    def to_dict(self) -> dict:
        """JSON-ready dict; keys carry their SI unit (``_m``, ``_Pa``, ``_rad_s`` ...)."""
        st, sd, spec = self.statics, self.spring, self.spec
        gov = spec.governor
        stem = gov.coordinate_name.split()[-1]
        q = gov.key_unit("force")  # generalised force unit
        names = [f"{n}_{q}" for n in gov.force_names]
        w0sq = self.omega_reference**2
        rows = []
        k2_case = None if self.k2 is None else classify_k2(self.k2, w0sq)
        for i, a in enumerate(st.alpha):
            key, shown = gov.json_coordinate(stem, a)
            row = {
                key: shown, "omega_rad_s": st.omega[i],
                "rpm": st.omega[i] * 30.0 / math.pi, names[0]: st.M_z[i],
                names[1]: st.M_f[i], names[2]: st.M_r0[i],
            }
            if gov.spring is not None:
                row["spring_force_N"] = st.spring_force[i]
                row["shear_stress_Pa"] = st.stress[i]
            if self.k2 is not None:
                row["k2_rad2_s2"] = self.k2[i]
                row["k2_case"] = str(k2_case[i])
            rows.append(row)
        mk = gov.mass_key
        out = {
            "spec": spec.path,
            "name": spec.name,
            "kind": self.kind,
            "governor_type": spec.governor_type,
            "fidelity": {
                "geometry": spec.analysis.geometry,
                "reaction_speed": spec.analysis.reaction_speed,
                "reaction_slope": spec.analysis.reaction_slope,
                "valve_table": spec.analysis.valve_table,
                **({"stress_correction": spec.material.stress_correction}
                   if spec.material is not None else {}),
            },
            "irregularity": self.irregularity,
            "irregularity_required": spec.speed.irregularity if spec.speed else None,
            "omega_mean_rad_s": spec.speed.omega_mean if spec.speed else None,
            "omega_inner_rad_s": st.omega[0],
            "omega_outer_rad_s": st.omega[-1],
            f"{mk}_mass_kg": sd.m,
            f"{mk}_weight_N": sd.m * 9.80665,
            f"{mk}_inertia_{'kg_m2' if gov.coordinate == 'angle' else 'kg'}": sd.inertia,
        }
        if sd.central:
            out["central_mass_kg"] = sd.central
        if gov.spring is not None:
            out["spring"] = {
                "wire_diameter_m": sd.d,
                "coil_radius_m": sd.r,
                "active_turns": sd.n,
                "stiffness_N_per_m": sd.kappa,
                f"{gov.free_length_key}_m": sd.l0,
                "max_shear_stress_Pa": self.max_stress,
                **self.spring_properties,
            }
        if self.classic:
            out["classic"] = self._classic_json()
        out["characteristic"] = rows
        out["checks"] = [c.to_dict() for c in self.checks]
        if self.k2 is not None:
            out["k2_rad2_s2"] = list(self.k2)
            out["k2_cases"] = {c: int(np.sum(k2_case == c))
                               for c in ("stable", "resonance risk", "unstable")}
        if self.spring_report is not None:
            out["spring_sheet"] = self.spring_report.to_dict()
        found = getattr(spec, "band_spring", None)
        if found:  # the spec gave no spring: the one that floats the governor in its band
            out["band_spring"] = {"stiffness_N_per_m": found["stiffness"],
                                  "free_length_m": found["free_length"],
                                  "force_inner_N": found["force_inner"],
                                  "force_outer_N": found["force_outer"]}
        out.update(self.dynamics)
        out.update(self.optimisation)
        return jsonable(out)
