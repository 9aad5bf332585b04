"""The one result type: an evaluated (or optimised) design, flowing to JSON, text, Excel, plots.

A :class:`Result` holds SI numbers only; writers format it and never recompute physics. Its
checks (:class:`~govopt.verdict.Check`) and figures (:meth:`Result.figures`,
:class:`~govopt.verdict.Figure`) carry their unit, group and source as fields, which every writer
reads (none parses a unit back from a name). In a notebook or a script::

    res = govopt.evaluate(govopt.load_spec("specs/hamabe-a.toml"))
    print(res.summary())      # the answer first: verdict, design, the checks to watch, notes
    res.to_frame()            # checks and figures as a pandas DataFrame, with a unit column
    res.plot("characteristic")  # matplotlib axes (report/plots); res.plot() draws every plot
    res                       # in Jupyter: the summary as HTML (_repr_html_)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .analysis.characteristic import Characteristic
from .analysis.statics import SpringDesign, classify_k2
from .inputs import Design, Spec
from .jsonable import jsonable
from .references import reference
from .units import G_STANDARD
from .verdict import ACTIVE_TOL, Check, Figure, shown

__all__ = ["ACTIVE_TOL", "Check", "Figure", "Result"]

#: the type's geometry among the design's figures (the key of the classic measures' geometry:
#: its label and SI unit): a Porter's height and arm ratio k = tan(beta)/tan(alpha), a ball
#: governor's sleeve lift, the shaft governor's spring arm h
GEOMETRY = {"height_m": ("height h", "m"), "k": ("arm ratio k", ""),
            "sleeve_lift_m": ("sleeve lift", "m"), "spring_arm_h_m": ("spring arm h", "m")}

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
    #: (:class:`govopt.analysis.spring_record.SpringReport`); None without a wire spring
    spring_report: Any = None
    #: governors made to the spec's tolerances (:mod:`govopt.made`): the tolerances, the yield
    #: beside the verdict and the worst-case speed band beside the required one (SI); None
    #: where the spec states no tolerance (or the yield was not asked for)
    made: dict | None = None
    #: the one evaluator's record of this design (:class:`govopt.evaluator.Evaluation` of one
    #: design): its figures and check table, the row a study stores (:func:`govopt.bulk.result_row`)
    evaluation: Any = field(default=None, repr=False)

    @property
    def allowable_shear_stress(self) -> float | None:
        """The static allowable the spring is held to: the spec's ``allowable_shear_stress``,
        else the wire grade's rule at the design's wire diameter (Pa)."""
        mat = self.spec.material
        if mat is None or mat.allowable_shear_stress is not None:
            return None if mat is None else mat.allowable_shear_stress
        rep = self.spring_report
        allowable = None if rep is None else rep.material.get("allowable static stress")
        return None if allowable is None else allowable.value

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

    @property
    def method(self):
        """The governor type's method for this spec (:class:`govopt.governors.base.Method`):
        its equations, sources and fidelity settings, which every writer reads."""
        return self.spec.governor.method(self.spec)

    @property
    def friction_speeds(self) -> tuple[np.ndarray | None, np.ndarray | None]:
        """``(omega_rise, omega_fall)`` over the characteristic's configurations (rad/s): the
        speeds at which the governor opens and closes against its friction band (the classic
        measures'); ``(None, None)`` where the design has no friction."""
        cm = self.classic or {}
        rise, fall = (np.asarray(cm.get(k, []), dtype=float)
                      for k in ("omega_rise_rad_s", "omega_fall_rad_s"))
        if rise.size != self.statics.alpha.size or not np.any(rise > fall):
            return None, None
        return rise, fall

    @property
    def band_extremes(self) -> tuple[tuple[float, str], tuple[float, str]]:
        """``((lowest closing speed, where), (highest opening speed, where))`` (rad/s, and the
        configuration in words: "the inner end", "the outer end" or "ball radius 120.5 mm"):
        the operating band's ends over the whole range, as the band checks read them
        (:func:`govopt.analysis.statics.band_extremes`); without friction the characteristic's
        own lowest and highest speeds."""
        rise, fall = self.friction_speeds
        if rise is None:
            rise = fall = np.asarray(self.statics.omega, dtype=float)
        gov, x = self.spec.governor, np.asarray(self.statics.alpha, dtype=float)

        def where(i: int) -> str:
            if i == 0:
                return "the inner end"
            if i == x.size - 1:
                return "the outer end"
            value, unit = gov.shown(x[i])
            return f"{gov.coordinate_name} {float(value):.4g} {unit}"

        i, j = int(np.argmin(fall)), int(np.argmax(rise))
        return (float(fall[i]), where(i)), (float(rise[j]), where(j))

    def check(self, name: str) -> Check:
        return next(c for c in self.checks if c.name == name)

    def figures(self) -> list[Figure]:
        """The design's reported figures, typed: each a :class:`~govopt.verdict.Figure` with
        its SI value, unit, group (``"design"``, ``"speed"``, ``"spring"``, ``"classic"``,
        ``"made"``: governors made to the spec's tolerances, :func:`govopt.made.figures`),
        symbol and a note (what it means, its source). The text's Design section, the
        notebook's display and :meth:`to_frame` read these fields."""
        st, sd, sp, spec = self.statics, self.spring, self.spring_properties, self.spec
        gov = spec.governor
        out: list[Figure] = []
        opt = self.optimisation or {}
        if opt.get("objective"):
            obj = opt["objective"]
            unit = obj.get("unit", "")
            gap = opt.get("gap")
            out.append(Figure(
                f"objective: {str(obj.get('name', '')).replace('_', ' ')}",
                opt.get("value"), unit, "design",
                note=f"status {opt.get('status')}" + (
                    "" if gap is None else f"; {100 * gap:.3g} % above the continuous bound")))
        if spec.speed is not None:
            eq = self.method.named("irregularity")
            out.append(Figure("irregularity", self.irregularity, "", "speed", symbol="delta",
                              note=f"required <= {spec.speed.irregularity:g}; (omega_a - "
                                   f"omega_i) / omega0, omega0 the mean speed ({eq.cite})"))
            out.append(Figure("mean speed", spec.speed.omega_mean, "rad/s", "speed",
                              symbol="omega0", note="the spec's"))
        out += [Figure("speed at the inner end", float(st.omega[0]), "rad/s", "speed",
                       symbol="omega_i", note=f"{gov.coordinate_name} at its inner end"),
                Figure("speed at the outer end", float(st.omega[-1]), "rad/s", "speed",
                       symbol="omega_a", note=f"{gov.coordinate_name} at its outer end")]
        rise, fall = self.friction_speeds
        if rise is not None:  # where friction acts: the band's extremes over the whole range
            (low, at_low), (high, at_high) = self.band_extremes
            out += [Figure("lowest closing speed", low, "rad/s", "speed", symbol="omega_fall",
                           note=f"falling against friction, at {at_low}: the band's lowest "
                                "speed"),
                    Figure("highest opening speed", high, "rad/s", "speed",
                           symbol="omega_rise", note=f"rising against friction, at {at_high}: "
                                                     "the band's highest speed")]
        inertia = "kg*m^2" if gov.coordinate == "angle" else "kg"
        weight = (f"{gov.mass_name}, its weight" if gov.mass_name.endswith("weight")
                  else f"{gov.mass_name} weight")
        out += [Figure(f"{gov.mass_name} mass", sd.m, "kg", "design", symbol="m",
                       json=f"{gov.mass_key}_mass_kg"),
                Figure(weight, sd.m * G_STANDARD, "N", "design", note=f"{sd.m:.4g} kgf",
                       json=f"{gov.mass_key}_weight_N"),
                Figure(f"{gov.mass_name} inertia", sd.inertia, inertia, "design", symbol="I",
                       json=f"{gov.mass_key}_inertia_{'kg_m2' if inertia != 'kg' else 'kg'}",
                       note="about the coordinate (generalised inertia)")]
        if sd.central:
            out += [Figure("central load", sd.central, "kg", "design", symbol="M",
                           json="central_mass_kg"),
                    Figure("central load weight", sd.central * G_STANDARD, "N", "design",
                           note=f"{sd.central:.4g} kgf")]
        if self.design is not None and self.design.dashpot is not None:
            damping = "N*m*s/rad" if gov.coordinate == "angle" else "N*s/m"
            out.append(Figure("dash-pot", self.design.dashpot, damping, "design", symbol="f",
                              note=f"damps the {gov.coordinate_name}; a1 = f/3"))
        if gov.spring is not None:
            out += [Figure("spring stiffness", sd.kappa, "N/m", "spring", symbol="kappa",
                           note=f"{gov.spring} spring", json="stiffness_N_per_m"),
                    Figure(gov.free_length_key.replace("_", " "), sd.l0, "m", "spring",
                           symbol="l0", json=f"{gov.free_length_key}_m")]
            if not gov.spring_kind.helical:  # the section the design sizes (a leaf's)
                out += [Figure(k.name.replace("_", " "), getattr(self.design, k.name), "m",
                               "spring") for k in gov.spring_kind.section
                        if k.kind == "length" and getattr(self.design, k.name, None) is not None]
        if sp:
            out += [Figure("wire diameter", sd.d, "m", "spring", symbol="d"),
                    Figure("mean coil radius", sd.r, "m", "spring", symbol="r",
                           json="coil_radius_m"),
                    Figure("active turns", sd.n, "", "spring", symbol="n"),
                    Figure("spring index", sp["spring_index"], "", "spring", symbol="C",
                           note="C = 2 r / d"),
                    Figure("Wahl factor", sp["wahl_factor"], "", "spring", symbol="K",
                           source="Wahl 1944"),
                    Figure("spring mass", sp["mass_kg"], "kg", "spring",
                           note="active coils", json="mass_kg"),
                    Figure("surge frequency", sp["surge_frequency_Hz"], "Hz", "spring",
                           source="Wahl 1944"),
                    Figure("max shear stress", self.max_stress, "Pa", "spring", symbol="tau")]
            allowable = self.allowable_shear_stress
            if allowable is not None:
                out.append(Figure("allowable shear stress", allowable, "Pa", "spring"))
        cm = self.classic
        if cm:
            pct = f"{100 * cm['effort_change']:.4g} %"
            change = (f"over the range: a {pct} speed change, innermost to outermost"
                      if cm.get("effort_over") == "range" else
                      f"for a {pct} speed change at the normal configuration")
            out += [Figure("range (classic)", cm["range_rad_s"], "rad/s", "classic",
                           json="range_rad_s"),
                    Figure("sensitiveness", cm["sensitiveness"], "", "classic",
                           note="range / mean of its ends (textbook 3.2)"),
                    Figure("stability", str(cm["stability"]), "", "classic",
                           note="the characteristic's slope"),
                    Figure("effort", cm["effort"], str(cm.get("effort_unit", "N*m")), "classic",
                           note=cm.get("effort_note") or change),
                    Figure("power", cm["power"], str(cm.get("power_unit", "J")), "classic",
                           note=cm.get("power_note") or cm.get("effort_note") or change)]
            for key, (label, unit) in GEOMETRY.items():  # the type's own geometry
                g = (cm.get("geometry") or {}).get(key)
                if g:
                    (lo, u), (hi, _) = shown(g["inner"], unit), shown(g["outer"], unit)
                    out.append(Figure(label, g["normal"], unit, "classic",
                                      note=f"normal; {lo:.4g} .. {hi:.4g}{' ' + u if u else ''} "
                                           "innermost .. outermost"))
            if cm["friction_band"]:
                ends = (f"; {cm['insensitiveness_inner']:.4g} at the inner end, "
                        f"{cm['insensitiveness_outer']:.4g} at the outer"
                        if "insensitiveness_inner" in cm else "")
                out += [Figure("friction band", cm["friction_band"],
                               "N*m" if gov.coordinate == "angle" else "N", "classic",
                               note="referred to the flying mass (a generalised force), not "
                                    "the sleeve's own friction"),
                        Figure("coefficient of insensitiveness", cm["insensitiveness"], "",
                               "classic", note="the largest over the range" + ends)]
        if self.made:  # governors made to the spec's tolerances: the yield beside the verdict
            from .made_words import figures as made_figures

            out += made_figures(self.made)
        return out

    @property
    def verdict_of(self) -> str:
        """Whose verdict this is: ``"made"`` (the governors made to the tolerances and set by
        the fitter: :mod:`govopt.made`, its yield against ``min_yield``) or ``"nominal"`` (the
        nominal design's checks alone)."""
        from .made_words import meets

        return "nominal" if meets(self.made) is None else "made"

    @property
    def passed(self) -> bool:
        """The verdict: every check holds at nominal and, where the verdict is the made
        governor's, its yield meets ``min_yield``."""
        from .made_words import meets

        return all(c.passed for c in self.checks) and meets(self.made) is not False

    def figure(self, name: str) -> Figure:
        """The figure named ``name`` (:meth:`figures`)."""
        return next(f for f in self.figures() if f.name == name)

    def summary(self) -> str:
        """The answer first, as plain text: the verdict, the design in engineering units, the
        failing, binding and tightest checks, and the notes (``govopt evaluate``'s default
        output; :func:`govopt.report.text.format_summary`)."""
        from .report.text import format_summary

        return format_summary(self, colour=False)

    def to_frame(self, engineering: bool = False):
        """The checks and figures as a :class:`pandas.DataFrame`, one row each, with columns
        ``kind`` (``"check"`` or ``"figure"``), ``group``, ``name``, ``value``, ``limit``,
        ``sense``, ``unit``, ``margin``, ``passed``, ``active`` and ``source`` (a figure's
        limit, sense, margin and verdict are empty). Values in SI, or with ``engineering`` in
        the units the reports show (mm, MPa, deg, rpm, N/mm: the ``unit`` column says which).
        pandas is imported here, not with govopt."""
        import pandas as pd

        def conv(value, unit):
            return shown(value, unit) if engineering else (value, unit)

        rows = []
        for c in self.checks:
            value, unit = conv(c.value, c.unit)
            limit, _ = conv(c.limit, c.unit)
            rows.append({"kind": "check", "group": c.group, "name": c.name, "value": value,
                         "limit": limit, "sense": c.sense, "unit": unit, "margin": c.margin,
                         "passed": c.passed, "active": c.active, "source": c.source})
        for f in self.figures():
            value, unit = conv(f.value, f.unit)
            rows.append({"kind": "figure", "group": f.group, "name": f.name, "value": value,
                         "limit": None, "sense": "", "unit": unit, "margin": None,
                         "passed": None, "active": None, "source": f.source or f.note})
        return pd.DataFrame(rows, columns=["kind", "group", "name", "value", "limit", "sense",
                                           "unit", "margin", "passed", "active", "source"])

    def _repr_html_(self) -> str:
        """A notebook's rich display: the summary as HTML tables
        (:func:`govopt.report.text.format_html`)."""
        from .report.text import format_html

        return format_html(self)

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
            "fidelity": {s.key.split(".")[-1]: s.value for s in self.method.settings
                         if s.key.startswith(("analysis.", "material."))
                         and s.key.split(".")[-1] not in ("points", "speed_change",
                                                          "settling_band", "use_case",
                                                          "tolerance", "harmonics")},
            "method": {**self.method.to_dict(), "sources": [
                {"key": k, "citation": reference(k).citation}
                for k in self.method.sources(tuple(c.source for c in self.checks))]},
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
        if self.optimisation:  # the optimiser's record (govopt.optimize.record), as spring's
            out["optimisation"] = self.optimisation
        if self.made is not None:
            out["made"] = self.made
        out["verdict"] = {"of": self.verdict_of, "passed": self.passed}
        return jsonable(out)
