"""Hamabe's shaft governor on the seam (G. Hamabe, *Disturbing Actions of a Shaft Governor*).

Each pendulum (mass ``m``, centre of gravity at ``rho`` from its fulcrum S) swings about S on the
flywheel, ``a = SO`` from the shaft axis; the coordinate is the angle ``alpha = OSP``. The spring
joins the attachments G (``b = SG``) of the two pendulums through O; the valve gear's eccentric is
driven by the lever ``q``. Per pendulum (Hamabe, Part I):

* ``J = m (a^2 + rho^2 - 2 a rho cos(alpha))``, so ``jp = J'/2 = m a rho sin(alpha)`` (eq. 1);
* spring moment ``M_f = kappa (A - B l0)``, exact (eq. 2) or the paper's series (eq. 3),
  :mod:`govopt.governors.shaft.linkage`; the spring force is ``F = 2 kappa (l - l0)``;
* the valve gear's mean reaction ``M_r0 = C_f + omega^2 C_i`` (eq. 11), at the local speed
  (``reaction_speed = "local"``, exact) or at the spec's mean speed (``"mean"``, the paper), with
  its slope in ``alpha`` (``reaction_slope``, which the paper leaves out of k^2);
* ``I = rho^2 m`` (the paper's point mass) unless the design gives the pendulum's inertia;
* the regulating member is the eccentric, whose advance follows ``alpha`` itself (the engine's
  torque slope is given per radian of ``alpha``); Coulomb friction ``M_0`` at the fulcrum.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

from ... import limits
from ...inputs import Analysis
from ...keys import Key, Table
from ...springs import helical as hx
from ...units import G_STANDARD
from ..base import Equation, Governor, Setting, Terms
from ..drawing import Drawing, Part, ball_radius, zigzag
from . import linkage, valvegear

ANGLE_RANGE = dict(low=0.0, high=np.pi, range_text="(0 deg, 180 deg)")


def _angle(name: str, meaning: str, source: str = "Hamabe Fig. 1") -> Key:
    return Key(name, "angle", meaning, source=source, **ANGLE_RANGE)


#: ``[governor]`` of the shaft governor (Hamabe Fig. 1; the pendulum swings about its fulcrum S
#: on the flywheel, O the shaft's axis)
KEYS = (
    Key("a", "length", "fulcrum S to the shaft's axis O (a = SO)", source="Hamabe Fig. 1",
        example="18 cm"),
    Key("rho", "length", "fulcrum S to the pendulum's centre of gravity P (rho = SP)",
        source="Hamabe Fig. 1", example="12 cm"),
    Key("b", "length", "fulcrum S to the spring's attachment G (b = SG), less than a",
        source="Hamabe Fig. 1", example="3 cm"),
    Key("q", "length", "the lever SQ that drives the valve gear's eccentric",
        source="Hamabe Fig. 1, eqs. 4-11", example="5 cm"),
    _angle("alpha_inner", "the angle OSP at the innermost configuration (lowest speed)"),
    _angle("alpha_outer", "the angle OSP at the outermost configuration (highest speed)"),
    _angle("alpha_normal", "the angle OSP at the normal configuration (the normal cut-off), "
                           "between alpha_inner and alpha_outer"),
)

#: ``[valve_gear]``: the valve gear the pendulums drive (Hamabe Part I, eqs. 4-11)
_AN = Analysis()

#: the shaft governor's own ``[analysis]`` settings: its linkage's series form and its valve
#: gear's reaction (the keys of every type are :data:`govopt.spec_keys.ANALYSIS`)
ANALYSIS_KEYS = (
    Key("geometry", "choice", "the spring linkage: \"exact\" (Hamabe eq. 2) or \"series\" "
                              "(eq. 3)", default=_AN.geometry, choices=("exact", "series")),
    Key("reaction_speed", "choice", "the valve gear's inertia reaction at the \"local\" speed "
                                    "or at the \"mean\" speed (the paper's)",
        default=_AN.reaction_speed, choices=("local", "mean"), source="Hamabe eq. 11"),
    Key("reaction_slope", "flag", "the valve gear reaction's slope in k^2 (the paper leaves "
                                  "it out)", default=_AN.reaction_slope),
    Key("valve_table", "choice", "the valve-gear table's interpolant: \"pchip\" (monotone), "
                                 "\"cubic\" (spline) or \"linear\" (the paper's)",
        default=_AN.valve_table, choices=("pchip", "cubic", "linear")),
    Key("harmonics", "count", "harmonics of the valve gear's periodic forcing (Hamabe Part II)",
        default=_AN.harmonics, low=0, high=limits.MAX_HARMONICS + 1,
        range_text=f"[1, {limits.MAX_HARMONICS}] (govopt's limit)"),
)

VALVE_GEAR = Table("valve_gear", "the valve gear the pendulums drive, whose mean reaction "
                                 "loads them (Hamabe Part I, eqs. 4-11, Fig. 6)", (
    Key("eccentricity", "length", "the eccentric's eccentricity e", source="Hamabe Figs. 3-4"),
    Key("offset", "length", "the offset s of the rotating parts' centre of gravity, "
                            "y = e cot(delta) - s cos(delta)",
        nonnegative=True, source="Hamabe Fig. 4"),
    Key("friction", "force", "the valve gear's friction P1 (chiefly the stuffing box's)",
        nonnegative=True, source="Hamabe eq. 5"),
    Key("steam_load", "force", "the unbalanced steam load on the valve spindle P3 (signed)",
        positive=False, source="Hamabe eqs. 7-8"),
    Key("weight", "force", "the weight of the valve, its spindle, the eccentric and its rod "
                           "P4 (signed)", positive=False, source="Hamabe eqs. 7-8"),
    Key("reciprocating", "weight", "the valve gear's reciprocating parts m_v",
        source="Hamabe eq. 6"),
    Key("eccentric", "weight", "the valve gear's rotating parts m_e (eccentric disc and "
                               "strap)", source="Hamabe Part I, force (v)"),
    Key("engine", "choice", "how the engine stands (the valve's weight acts along the valve "
                            "rod only in a vertical engine)",
        default="vertical", choices=("vertical", "horizontal")),
    Key("table", "table", "the valve gear's table: the eccentric's angle delta at each "
                          "configuration alpha ([valve_gear.table])"),
), required=True)

#: ``[valve_gear.table]``: delta(alpha), Hamabe Fig. 6
VALVE_TABLE = Table("valve_gear.table", "the eccentric's angle delta at configurations alpha, "
                                        "covering alpha_inner .. alpha_outer (Hamabe Fig. 6)", (
    Key("alpha", "angle", "configurations alpha, strictly increasing", shape="list",
        source="Hamabe Fig. 6", **ANGLE_RANGE),
    Key("delta", "angle", "the eccentric's angle delta at each alpha", shape="list",
        source="Hamabe Fig. 6", **ANGLE_RANGE),
), required=True)


@dataclass(frozen=True)
class ValveGear:
    """The valve gear driven by the pendulums (Hamabe, Part I eqs. 4-11, Fig. 6), SI."""

    eccentricity: float
    offset: float
    friction: float
    steam_load: float
    weight: float
    reciprocating_mass: float
    eccentric_mass: float
    engine: str
    table_alpha: np.ndarray = field(repr=False)
    table_delta: np.ndarray = field(repr=False)


@dataclass(frozen=True)
class ShaftGovernor(Governor):
    """Shaft-governor linkage (Hamabe, Fig. 1) and its valve gear, SI."""

    #: near its stop, arms near the axis or 90 deg, near isochronism (govopt bench)
    bench_case: ClassVar[tuple] = ("hamabe-a", {}, "analysis.geometry", ("exact", "series"))

    type_name: ClassVar[str] = "shaft"
    title: ClassVar[str] = "Hamabe's shaft governor (Disturbing Actions of a Shaft Governor)"
    coordinate: ClassVar[str] = "angle"
    source: ClassVar[str] = "hamabe"
    friction_key: ClassVar[str] = "design.friction_moment"
    friction_dimension: ClassVar[str] = "moment"
    coordinate_name: ClassVar[str] = "alpha"
    travel: ClassVar[str] = "angle"
    spring: ClassVar[str | None] = "tension"
    mass_key: ClassVar[str] = "pendulum"
    mass_name: ClassVar[str] = "pendulum"
    resonance_ceiling: ClassVar[bool] = True  # the valve gear forces the pendulums
    band_is_range: ClassVar[bool] = False  # Hamabe's irregularity: "at most" delta0
    resonance_source: ClassVar[str] = "Hamabe Part II, case 1"
    free_length_key: ClassVar[str] = "free_half_length"
    free_length_meaning: ClassVar[str] = ("half the spring's free length, l0 (the spring joins "
                                          "the two pendulums' attachments G through the axis)")
    keys: ClassVar[tuple[Key, ...]] = KEYS
    tables: ClassVar[tuple[Table, ...]] = (VALVE_GEAR, VALVE_TABLE)
    analysis_keys: ClassVar[tuple[Key, ...]] = ANALYSIS_KEYS
    example: ClassVar[str] = "hamabe-design"
    spring_length_factor: ClassVar[float] = 2.0
    force_names: ClassVar[tuple[str, str, str]] = ("M_z", "M_f", "M_r0")

    a: float
    rho: float
    b: float
    q: float
    alpha_inner: float
    alpha_outer: float
    alpha_normal: float
    valve_gear: ValveGear | None = None

    @property
    def x_inner(self) -> float:
        return self.alpha_inner

    @property
    def x_outer(self) -> float:
        return self.alpha_outer

    @property
    def x_normal(self) -> float:
        return self.alpha_normal

    @classmethod
    def parse(cls, reader) -> ShaftGovernor:
        """``[governor]`` keys a, rho, b, q, alpha_inner, alpha_outer, alpha_normal, and the
        top-level ``[valve_gear]`` table (``reader.top``)."""
        gov = cls(**reader.read_all(KEYS))
        if not gov.alpha_inner < gov.alpha_normal < gov.alpha_outer:
            reader.fail("alpha_normal", "expected alpha_inner < alpha_normal < alpha_outer")
        if gov.b >= gov.a:
            reader.fail("b", "expected b < a (the spring attachment lies between fulcrum and "
                             "shaft)")
        reader.finish()
        vg = _parse_valve_gear(reader.top.sub("valve_gear", declared=VALVE_GEAR), gov)
        return cls(**{**gov.__dict__, "valve_gear": vg})

    # -- the valve gear's mean reaction (eq. 11) ------------------------------------------------

    def reaction(self, alpha, kind="pchip"):
        """``(C_f, C_i)`` with ``M_r0 = C_f + omega^2 C_i`` at ``alpha`` (Hamabe eq. 11), the
        valve-gear table interpolated as ``kind`` (``[analysis] valve_table``) says."""
        return valvegear.table_reaction(alpha, self.valve_gear, self.q, kind)

    def reaction_slopes(self, alpha, kind="pchip", step: float = 1e-6):
        """``(dC_f/dalpha, dC_i/dalpha)`` (:func:`valvegear.table_reaction_slope`: exact for the
        smooth tables; for ``linear`` a difference, the mean of the two slopes on a row)."""
        return valvegear.table_reaction_slope(alpha, self.valve_gear, self.q, kind, step)

    # -- the seam -------------------------------------------------------------------------------

    def terms(self, x, m, analysis, central=None) -> Terms:
        """Hamabe eqs. (1), (2)/(3), (11); the reaction at the local or the mean speed."""
        x = np.asarray(x, dtype=float)
        jp = m * self.a * self.rho * np.sin(x)
        jpp = m * self.a * self.rho * np.cos(x)
        A, B, A_x, B_x = linkage.spring_moment_coefficients(x, self.a, self.b, analysis.geometry)
        cf, ci = self.reaction(x, analysis.valve_table)
        if analysis.reaction_slope:
            cf_x, ci_x = self.reaction_slopes(x, analysis.valve_table)
        else:
            cf_x, ci_x = 0.0 * cf, 0.0 * ci
        if analysis.reaction_speed == "mean":  # the paper: inertia reactions at omega0
            w0sq = analysis.omega_mean**2
            cf, cf_x, ci, ci_x = cf + w0sq * ci, cf_x + w0sq * ci_x, 0.0 * ci, 0.0 * ci_x
        return Terms(jp=jp, jpp=jpp, cf=cf, cf_x=cf_x, ci=ci, ci_x=ci_x, A=A, B=B, A_x=A_x,
                     B_x=B_x)

    def inertia(self, x, m, central=None):
        """``I = rho^2 m``: the pendulum as a point mass at its centre of gravity (the paper)."""
        return self.rho**2 * m + 0.0 * np.asarray(x, dtype=float)

    def friction(self, x, design=None):
        """Coulomb friction moment ``M_0`` at the fulcrum (Hamabe eq. 42), from the design."""
        M0 = getattr(design, "friction_moment", None) or 0.0
        return M0 + 0.0 * np.asarray(x, dtype=float)

    def excel_design(self, s, res) -> bool:
        """The Design sheet's live formulas for the shaft governor: the linkage (eq. 2 or 3),
        the valve gear's reaction at the range's ends (eq. 11, as constants) and the equilibrium
        speeds (eq. 12), on named input cells (``s`` is the sheet writer of
        :mod:`govopt.report.excel`)."""
        spec, sd, ds, props = res.spec, res.spring, res.design, res.spring_properties
        g, sp, mat, an = self, spec.speed, spec.material, spec.analysis
        st = res.statics
        s.section("Inputs (yellow, in the units beside them): edit them and the formulas below "
                  "follow")
        s.input("wire_diameter", "wire diameter", "d", sd.d, "m", "design.wire_diameter")
        s.input("coil_radius", "mean coil radius", "r", sd.r, "m", "design.coil_radius")
        s.input("turns", "active turns", "n", sd.n, "", "design.active_turns")
        s.input("free_half_length", "free half length of the spring", "l0", sd.l0, "m",
                "design.free_half_length" if ds.free_half_length is not None else
                "govopt: equilibrium at the normal configuration at the mean speed (Hamabe Ex. 1); "
                "an input here")
        s.input("pendulum_weight", "pendulum weight", "W", sd.m * G_STANDARD, "N",
                "design.pendulum_weight (or mass x standard gravity)")
        s.input("std_gravity", "standard gravity", "g_n", G_STANDARD, "m/s^2",
                "CGPM 1901; converts the weight to the mass")
        if ds.flying_inertia is not None:
            s.input("pendulum_inertia", "pendulum moment of inertia about the fulcrum", "I",
                    sd.inertia, "kg*m^2", "design.flying_inertia")
        s.input("dashpot", "dash-pot coefficient", "f", ds.dashpot, "N*m*s/rad",
                "design.dashpot_f (= 3 a1)" if ds.dashpot is not None
                else "not given in the spec (blank: no dash-pot)")
        s.input("friction_moment", "friction moment at the fulcrum", "M_R", ds.friction_moment,
                "N*m", "design.friction_moment" if ds.friction_moment is not None
                else "not given in the spec (blank: friction not modelled)")
        s.input("shear_modulus", "shear modulus", "G", mat.shear_modulus, "Pa",
                "material.shear_modulus")
        s.input("allowable_stress", "allowable shear stress", "k_s", res.allowable_shear_stress,
                "Pa", "material.allowable_shear_stress" if mat.allowable_shear_stress is not None
                else f"material.grade {mat.grade}: the standard's rule at d (not live in d)")
        s.input("density", "density of the wire", "rho_w", mat.density, "kg/m^3",
                "material.density")
        s.input("link_a", "fulcrum S to shaft axis O", "a", g.a, "m", "governor.a")
        s.input("link_rho", "fulcrum S to pendulum centre of gravity P", "rho", g.rho, "m",
                "governor.rho")
        s.input("link_b", "fulcrum S to spring attachment G", "b", g.b, "m", "governor.b")
        s.input("alpha_inner", "innermost configuration", "alpha_i", g.alpha_inner, "rad",
                "governor.alpha_inner")
        s.input("alpha_normal", "normal configuration", "alpha_n", g.alpha_normal, "rad",
                "governor.alpha_normal (for reference; l0 above already holds it)")
        s.input("alpha_outer", "outermost configuration", "alpha_a", g.alpha_outer, "rad",
                "governor.alpha_outer")
        s.input("omega_mean", "mean speed", "omega0", sp.omega_mean, "rad/s", "speed.mean")
        s.input("irregularity_required", "required irregularity (at most)", "delta0",
                sp.irregularity, "", "speed.irregularity")

        s.section("Valve-gear reaction M_r0 = C_f + omega^2 C_i at the ends of the range "
                  "(constants from govopt, Hamabe eq. 11)")
        ends = np.array([g.alpha_inner, g.alpha_outer])
        C_f, C_i = (np.asarray(v, dtype=float)
                    for v in self.reaction(ends, an.valve_table))
        src = "govopt.governors.shaft.reaction(spec, alpha_{}) (valve-gear table interpolated)"
        s.input("reaction_cf_inner", "speed-independent reaction at alpha_i", "C_f,i", C_f[0],
                "N*m", src.format("inner"))
        s.input("reaction_ci_inner", "inertia reaction coefficient at alpha_i", "C_i,i", C_i[0],
                "kg*m^2", src.format("inner"))
        s.input("reaction_cf_outer", "speed-independent reaction at alpha_a", "C_f,a", C_f[1],
                "N*m", src.format("outer"))
        s.input("reaction_ci_outer", "inertia reaction coefficient at alpha_a", "C_i,a", C_i[1],
                "kg*m^2", src.format("outer"))

        s.section("Derived quantities (blue, live formulas) next to govopt's values as written")
        s.formula("pendulum_mass", "pendulum mass", "m", "=pendulum_weight/std_gravity", "kg",
                  sd.m, "m = W / g_n")
        if ds.flying_inertia is None:
            s.formula("pendulum_inertia", "pendulum moment of inertia about the fulcrum", "I",
                      "=link_rho^2*pendulum_mass", "kg*m^2", sd.inertia,
                      "I = rho^2 m (point mass; design.flying_inertia not given)")
        s.helical_spring(sd, props)
        factor, corr = s.stress_factor(mat.stress_correction, props["spring_index"]), \
            mat.stress_correction
        for tag, i, sym in (("inner", 0, "i"), ("outer", -1, "a")):
            s.formula(f"half_length_{tag}", f"spring half length at alpha_{sym}", f"l_{sym}",
                      f"=SQRT(link_a^2+link_b^2-2*link_a*link_b*COS(alpha_{tag}))", "m",
                      st.extra["half length l"][0][i],
                      "l = sqrt(a^2 + b^2 - 2 a b cos(alpha)) (Hamabe eq. 2)")
            s.formula(f"spring_force_{tag}", f"spring force at alpha_{sym}", f"F_{sym}",
                      f"=2*stiffness*(half_length_{tag}-free_half_length)", "N",
                      st.spring_force[i], "F = 2 kappa (l - l0) (Hamabe eq. 2)")
            s.formula(f"shear_stress_{tag}", f"shear stress at alpha_{sym}", f"tau_{sym}",
                      f"=16*ABS(spring_force_{tag})*coil_radius/(PI()*wire_diameter^3)"
                      + factor, "Pa", st.stress[i],
                      "tau = 16 |F| r / (pi d^3)" + (f" x K (stress_correction = '{corr}')"
                                                     if factor else
                                                     " (stress_correction = 'none')"))
        s.formula("max_shear_stress", "largest shear stress over the range", "tau_max",
                  "=MAX(shear_stress_inner,shear_stress_outer)", "Pa", res.max_stress,
                  "|F| is largest at an end of the range (l is monotonic in alpha)")
        s.formula("stress_utilisation", "stress utilisation", "tau_max/k_s",
                  "=max_shear_stress/allowable_stress", "",
                  res.max_stress / res.allowable_shear_stress, "<= 1 required (Hamabe Ex. 1)")
        s.formula("spring_mass", "mass of the active coils", "m_s",
                  "=density*PI()*wire_diameter^2/4*2*PI()*coil_radius*turns", "kg",
                  props["mass_kg"], "rho_w (pi d^2/4)(2 pi r n); ends not included")
        s.formula("surge_frequency", "surge frequency (both ends fixed)", "f_s",
                  "=wire_diameter/(8*PI()*coil_radius^2*turns)*SQRT(shear_modulus/(2*density))",
                  "Hz", props["surge_frequency_Hz"], "d/(8 pi r^2 n) sqrt(G/(2 rho_w)) (Wahl 1944)")
        s.formula("body_length", "solid body length", "(n+1) d", "=(turns+1)*wire_diameter", "m",
                  props["body_length_m"], "(n + 1) d")

        series = an.geometry == "series"
        mean = an.reaction_speed == "mean"
        for tag, i, sym in (("inner", 0, "i"), ("outer", -1, "a")):
            if series:
                c = "SQRT(link_a^2+link_b^2)"
                A = f"2*link_a*link_b*SIN(alpha_{tag})"
                B = f"({A}/{c}+(link_a*link_b)^2*SIN(2*alpha_{tag})/{c}^3)"
                mf = f"=stiffness*({A}-{B}*free_half_length)"
                note = ("M_f = kappa (A - B l0), A = 2 a b sin(alpha), B = A/c + (a b)^2 "
                        "sin(2 alpha)/c^3, c = sqrt(a^2 + b^2) (Hamabe eq. 3, geometry = 'series')")
            else:
                mf = (f"=2*stiffness*(half_length_{tag}-free_half_length)*link_a*link_b"
                      f"*SIN(alpha_{tag})/half_length_{tag}")
                note = ("M_f = 2 kappa (l - l0) a b sin(alpha) / l "
                        "(Hamabe eq. 2, geometry = 'exact')")
            s.formula(f"spring_moment_{tag}", f"spring moment at alpha_{sym}", f"M_f{sym}", mf,
                      "N*m", st.M_f[i], note)
        for tag, i, sym in (("inner", 0, "i"), ("outer", -1, "a")):
            lever = f"pendulum_mass*link_a*link_rho*SIN(alpha_{tag})"
            if mean:
                w = (f"=SQRT((spring_moment_{tag}+reaction_cf_{tag}+omega_mean^2*reaction_ci_{tag})"
                     f"/({lever}))")
                note = ("omega^2 = (M_f + C_f + omega0^2 C_i) / (m a rho sin(alpha)) "
                        "(Hamabe eq. 12, reaction_speed = 'mean')")
            else:
                w = f"=SQRT((spring_moment_{tag}+reaction_cf_{tag})/({lever}-reaction_ci_{tag}))"
                note = ("omega^2 = (M_f + C_f) / (m a rho sin(alpha) - C_i) "
                        "(Hamabe eq. 12, reaction_speed = 'local')")
            s.formula(f"omega_{tag}", f"equilibrium speed at alpha_{sym}", f"omega_{sym}", w,
                      "rad/s", st.omega[i], note)
        for tag, i, sym in (("inner", 0, "i"), ("outer", -1, "a")):
            s.formula(f"rpm_{tag}", f"equilibrium speed at alpha_{sym}", f"N_{sym}",
                      f"=omega_{tag}*30/PI()", "rpm", st.omega[i] * 30.0 / math.pi,
                      "N = 30 omega / pi")
        s.irregularity(res)
        return True

    def vibration(self, spec, sd, k2_normal: float, dashpot: float):
        """Hamabe Part II: the pendulum's vibration under the valve gear's fluctuating reaction
        (:mod:`govopt.governors.shaft.vibration`), with the dash-pot."""
        from . import vibration

        return vibration.vibration(spec, sd, self.alpha_normal, k2_normal, dashpot=dashpot)

    def vibrations(self, spec, sd, k2_normal, dashpot):
        """:meth:`vibration` of N designs at once (:func:`.vibration.vibrations`)."""
        from . import vibration

        return vibration.vibrations(spec, sd, self.alpha_normal, k2_normal, dashpot=dashpot)

    def columns(self, x) -> dict:
        """Half length ``l`` of the spring and its arm ``h = dl/dalpha`` (Hamabe eq. 2)."""
        return {"half length l": (linkage.half_length(x, self.a, self.b), "m"),
                "spring arm h": (linkage.spring_arm(x, self.a, self.b), "m")}

    def spring_force_coefficients(self, x):
        """``F = 2 kappa (l - l0)`` (Hamabe eq. 2): ``A_F = 2 l``, ``B_F = 2``."""
        ell = linkage.half_length(x, self.a, self.b)
        return 2.0 * ell, 2.0 + 0.0 * ell

    # -- the type's method and drawing: what a reader is told (Hamabe's paper) ---------------

    def statics_method(self, spec) -> tuple[Equation, ...]:
        """Hamabe Part I: eqs. 1, 2 (or 3), 11 and 12."""
        if spec.analysis.geometry == "series":
            spring = Equation("statics", "spring moment about the fulcrum, the paper's "
                              "first-order series", "M_f = kappa (A - B l0), A = 2 a b "
                              "sin(alpha), B = A/c + (a b)^2 sin(2 alpha)/c^3, c = sqrt(a^2 + "
                              "b^2)", "hamabe", "eq. 3", ("analysis.geometry",))
        else:
            spring = Equation("statics", "spring moment about the fulcrum, exact geometry",
                              "M_f = F a b sin(alpha) / l", "hamabe", "eq. 2",
                              ("analysis.geometry",))
        return (
            Equation("statics", "centrifugal moment of a pendulum about its fulcrum",
                     "M_z = omega^2 m a rho sin(alpha)", "hamabe", "eq. 1"),
            Equation("statics", "the spring's half length and force",
                     "l = sqrt(a^2 + b^2 - 2 a b cos(alpha)), F = 2 kappa (l - l0)", "hamabe",
                     "eq. 2", name="spring force"),
            spring,
            Equation("statics", "mean reaction of the valve gear through the eccentric's lever "
                     "q, from the valve-gear table delta(alpha)", "M_r0 = C_f + omega^2 C_i",
                     "hamabe", "eq. 11", ("analysis.valve_table", "analysis.reaction_speed",
                                         "analysis.reaction_slope")),
            Equation("statics", "equilibrium of the pendulum: the characteristic",
                     "M_f - M_z + M_r0 = 0", "hamabe", "eq. 12", name="characteristic"))

    def speed_method(self, spec) -> tuple[Equation, ...]:
        """Hamabe Part I: the irregularity."""
        if spec.speed is None:
            return ()
        return (Equation("speed", "irregularity of the governor",
                         "delta = (omega_a - omega_i) / omega0, omega0 the spec's mean speed",
                         "hamabe", "Part I", name="irregularity"),)

    def spring_method(self, spec) -> tuple[Equation, ...]:
        """Hamabe's Example 1 (the free half length from the equilibrium at the normal
        configuration; the stress uncorrected), then the helical spring's own."""
        own = super().spring_method(spec)
        if spec.material is not None and spec.material.stress_correction == "none":
            own = tuple(Equation(e.topic, e.what, e.formula, "hamabe", "Example 1", e.settings,
                                 e.name) if e.name in ("rate", "stress") else e for e in own)
        return (Equation("spring", "free half length from the equilibrium at the normal "
                         "configuration at the mean speed", "F_n = M_f(alpha_n) / h_n, l0 = "
                         "l_n - F_n / (2 kappa), h = a b sin(alpha) / l", "hamabe",
                         "Example 1"),) + own

    def stability_method(self, spec) -> tuple[Equation, ...]:
        """Hamabe Part II: k^2 (eqs. 18-20) and its three cases."""
        return (Equation("stability", "restoring stiffness of the pendulum about an "
                         "equilibrium", "k^2 = (dM_f/dalpha - omega^2 m a rho cos(alpha) + "
                         "dM_r0/dalpha) / I", "hamabe", "eqs. 18-20",
                         ("analysis.reaction_slope",), name="k2"),
                Equation("stability", "stable for k^2 > 0", "k^2 > 0", "hamabe",
                         "Part II, case 3", name="stable"),
                Equation("stability", "clear of resonance with the valve gear's forcing",
                         "k^2 < omega0^2", "hamabe", "Part II, case 2", name="resonance"))

    def friction_method(self, spec) -> tuple[Equation, ...]:
        """Hamabe eq. 42: Coulomb friction at the fulcrum, where the design has it."""
        if not (spec.design is not None and spec.design.friction_moment):
            return ()
        return (Equation("friction", "Coulomb friction moment at the fulcrum: the pendulum "
                         "opens at omega_rise and closes at omega_fall",
                         "omega_rise,fall^2 = (M_f + C_f +- M_0) / (m a rho sin(alpha) - C_i)",
                         "hamabe", "eq. 42", name="band"),) + self.friction_strokes(spec)

    def vibration_method(self, spec) -> tuple[Equation, ...]:
        """Hamabe Part II: the forced vibration under the valve gear, with the dash-pot."""
        if spec.engine is None and not (spec.design is not None and spec.design.dashpot):
            return ()
        return (Equation("vibration", "the pendulum's forced vibration by the valve gear's "
                         "fluctuating reaction: harmonics", "I xi'' + f xi' + I k^2 xi = "
                         "sum_n (A_n cos n theta + B_n sin n theta)", "hamabe", "eqs. 13-22",
                         ("analysis.harmonics",), name="vibration"),
                Equation("vibration", "the dash-pot's damping", "f = 3 a1", "hamabe",
                         "eq. 23"))

    def load_change_method(self, spec) -> tuple[Equation, ...]:
        """Hamabe Part III: eqs. 24-28 and the Hurwitz condition, eq. 32."""
        return (Equation("load change", "governor and engine after a load change",
                         "a0 xi''' + 3 a1 xi'' + 3 a2 xi' + a3 xi = 0 (from eqs. 24-27)",
                         "hamabe", "eq. 28", ("analysis.settling_band",), name="cubic"),
                Equation("load change", "stability of the load change (Hurwitz)",
                         "9 a1 a2 > a0 a3, margin 9 a1 a2 / (a0 a3) - 1", "hamabe", "eq. 32",
                         name="hurwitz"),
                Equation("load change", "Vyshnegradsky's diagram of the same cubic",
                         "lambda^3 + A lambda^2 + B lambda + 1 = 0, stable for A B > 1",
                         "vyshnegradsky"))

    def settings(self, spec) -> list[Setting]:
        """The seam's settings and the paper's: linkage geometry, the valve gear's table and
        reaction, the harmonics of the forced vibration."""
        an = spec.analysis
        own = [Setting("analysis.geometry", an.geometry,
                       "the linkage: exact (eq. 2) or the paper's series (eq. 3)"),
               Setting("analysis.reaction_speed", an.reaction_speed,
                       "the valve gear's inertia reaction at the local or the mean speed"),
               Setting("analysis.reaction_slope", an.reaction_slope,
                       "the valve gear's reaction slope in k^2 (the paper leaves it out)"),
               Setting("analysis.valve_table", an.valve_table,
                       "how the valve-gear table delta(alpha) is interpolated")]
        if self.vibration_method(spec):
            own.append(Setting("analysis.harmonics", an.harmonics,
                               "harmonics kept in the forced vibration"))
        return own + super().settings(spec)

    def free_length_words(self) -> str:
        """The free half length: half the attachments' distance at no force."""
        return ("free half length l0: half the distance between the spring's attachments G "
                "and G' (through the shaft's axis O, Hamabe Fig. 1) at which F = 2 kappa "
                "(l - l0) is zero; the spring's whole length at no force is 2 l0")

    def drawing(self, x, sd) -> Drawing:
        """The pair of pendulums in their plane of rotation (Hamabe Fig. 1): the shaft O at the
        origin, each fulcrum S at ``a`` from it, the pendulum's centre of gravity P at ``rho``
        from S at the angle OSP = alpha, the spring's attachment G at ``b`` on SP, the spring
        G-G' through O (its half length ``l = OG``), the lever SQ (``q``) to the eccentric."""
        x = float(x)
        parts = []
        for sign in (1.0, -1.0):  # the second pendulum: point-symmetric about O
            S = np.array([sign * self.a, 0.0])
            u = sign * np.array([-np.cos(x), np.sin(x)])  # from S along SP
            P, G, Q = S + self.rho * u, S + self.b * u, S - self.q * u
            parts += [Part("link", (tuple(Q), tuple(S), tuple(P))),
                      Part("pivot", (tuple(S),)),
                      Part("mass", (tuple(P),), ball_radius(sd.m))]
            if sign > 0:
                width = 2.0 * sd.r if np.isfinite(sd.r) else 0.1 * self.a
                parts.append(Part("spring", zigzag(tuple(G), tuple(-G), width, 8)))
        parts.append(Part("frame", ((0.0, 0.0),), 0.05 * self.a))
        return Drawing(tuple(parts), "plane of rotation: the shaft O at the origin",
                       ("across the shaft (mm)", "across the shaft (mm)"))


def _parse_valve_gear(vg, geometry) -> ValveGear:
    """``[valve_gear]`` and its table (Hamabe Part I eqs. 4-11, Fig. 6), SI; the table must
    cover the configuration range."""
    v = vg.read_all(VALVE_GEAR.keys[:-1])
    table = vg.sub("table", declared=VALVE_TABLE)
    t_alpha, t_delta = (np.array(x) for x in table.read_all(VALVE_TABLE).values())
    if len(t_alpha) != len(t_delta):
        table.fail("delta", f"expected {len(t_alpha)} values, one per alpha, got {len(t_delta)}")
    if np.any(np.diff(t_alpha) <= 0):
        table.fail("alpha", "expected strictly increasing configurations")
    tol = 1e-9  # rad: rounding of the unit conversions, not an extrapolation
    for key in ("alpha_inner", "alpha_outer"):
        x = getattr(geometry, key)
        if not t_alpha[0] - tol <= x <= t_alpha[-1] + tol:
            table.fail("alpha", f"the table covers {np.degrees(t_alpha[0]):.4g} deg to "
                                f"{np.degrees(t_alpha[-1]):.4g} deg, but governor.{key} = "
                                f"{np.degrees(x):.4g} deg lies outside it (extend the table; "
                                "govopt does not extrapolate the valve gear)")
    table.finish()
    out = ValveGear(
        eccentricity=v["eccentricity"], offset=v["offset"], friction=v["friction"],
        steam_load=v["steam_load"], weight=v["weight"],
        reciprocating_mass=v["reciprocating"], eccentric_mass=v["eccentric"],
        engine=v["engine"], table_alpha=t_alpha, table_delta=t_delta,
    )
    vg.finish()
    return out


def paper_sizing(spec, m: float, r: float) -> dict:
    """Hamabe's spring-sizing procedure of Example 1, step by step (a dict of SI quantities).

    ``omega_i = omega0 (1 - delta0/2)``, ``omega_a = omega0 (1 + delta0/2)``;
    ``M_fi = M_zi - M_r0i``, ``M_fa = M_za - M_r0a`` (eq. 12); ``F = M_f / h`` (eq. 2);
    ``kappa = (F_a - F_i) / (2 (l_a - l_i))``; ``d = (16 F_a r / (pi k_s))^(1/3)``;
    ``n = G d^4 / (64 r^3 kappa)``. The reaction is taken at the mean speed, as in the paper.
    The arms are exact (the paper rounds them to 2.5 and 3.0 cm) and ``d`` is not rounded up.

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor's geometry and valve gear, the analysis'
        ``valve_table``; SI inside).
    m : float [kg]
        Mass of one pendulum.
    r : float [m]
        Mean coil radius of the spring.

    Returns
    -------
    dict [-]
        ``omega_inner``, ``omega_outer`` [rad/s]; ``M_zi``, ``M_za``, ``M_fi``, ``M_fa`` [N m];
        ``h_i``, ``h_a``, ``l_i``, ``l_a`` [m]; ``F_i``, ``F_a`` [N]; ``kappa`` [N/m]; ``d`` [m];
        ``n`` [-].

    References
    ----------
    [hamabe] Part I, eqs. (1), (2), (11), (12) and Example 1.

    Examples
    --------
    Example 1 (a) with the paper's omega0^2 = 630, W = 12 kgf, r = 6 cm. The paper prints
    ``M_zi = 1127`` kgf cm, ``F_a = 606`` kgf (607 unrounded: it takes omega_a^2 = 707 and
    rounds the reaction's terms) and ``d = 1.7`` cm (``1.667`` rounded up); with
    its arms rounded to 2.5 and 3.0 cm it gets kappa = 59.7 kgf/cm, where the exact arms give
    63.1:

    >>> import dataclasses, govopt, govopt.examples
    >>> KGF, CM = 9.80665, 0.01
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> spec = dataclasses.replace(spec, speed=dataclasses.replace(spec.speed,
    ...                                                            omega_mean=np.sqrt(630.0)))
    >>> s = paper_sizing(spec, 12.0, 6 * CM)
    >>> s = {k: float(v) for k, v in s.items()}
    >>> round(s["M_zi"] / (KGF * CM)), round(s["F_a"] / KGF), round(s["d"] / CM, 3)
    (1127, 607, 1.668)
    >>> round(s["kappa"] / (KGF / CM), 1)
    63.1
    """
    from ...analysis import statics

    g, sp, mat = spec.governor, spec.speed, spec.material
    paper = spec.with_analysis(reaction_speed="mean")
    out = {"omega_inner": sp.omega_inner, "omega_outer": sp.omega_outer}
    for tag, alpha, omega in (("i", g.alpha_inner, sp.omega_inner),
                              ("a", g.alpha_outer, sp.omega_outer)):
        out[f"M_z{tag}"] = linkage.centrifugal_moment(alpha, omega, m, g.a, g.rho)
        out[f"M_f{tag}"] = statics.required_spring_moment(paper, alpha, omega, m)
        out[f"h_{tag}"] = linkage.spring_arm(alpha, g.a, g.b)
        out[f"l_{tag}"] = linkage.half_length(alpha, g.a, g.b)
        out[f"F_{tag}"] = out[f"M_f{tag}"] / out[f"h_{tag}"]
    out["kappa"] = (out["F_a"] - out["F_i"]) / (2.0 * (out["l_a"] - out["l_i"]))
    out["d"] = hx.wire_diameter_for_stress(out["F_a"], r, mat.allowable_shear_stress)
    out["n"] = hx.turns_for_stiffness(out["kappa"], out["d"], r, mat.shear_modulus)
    return out


# -- the valve gear through a spec (its fidelity settings) ----------------------------------


def reaction(spec, alpha):
    """``(C_f, C_i)`` [N m, kg m^2] with ``M_r0 = C_f + omega^2 C_i`` at configurations
    ``alpha`` (Hamabe, Part I, eq. 11), ``delta`` from the valve-gear table interpolated as
    ``[analysis] valve_table`` says.

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor's geometry and valve gear, the analysis'
        ``valve_table``; SI inside).
    alpha : float or array [rad]
        Configurations, the angle OSP.

    Returns
    -------
    tuple of float or array [N m, kg m^2]
        ``(C_f, C_i)``.

    References
    ----------
    [hamabe] Part I, eq. (11) and Example 1's table of ``M_r0``.

    Examples
    --------
    Hamabe's Example 1 (a), the bundled spec:

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> KGFCM = 9.80665 * 0.01

    At 50 deg and 80 deg (rows of the table) and omega^2 = 630 the paper prints 59.4 and
    20.8 kgf cm, its terms rounded before adding:

    >>> C_f, C_i = reaction(spec, np.radians([50, 80]))
    >>> [round(float(x), 1) for x in (C_f + 630 * C_i) / KGFCM]
    [59.6, 20.7]
    """
    return spec.governor.reaction(alpha, spec.analysis.valve_table)


def reaction_slopes(spec, alpha, step: float = 1e-6):
    """``(dC_f/dalpha, dC_i/dalpha)`` [N m/rad, kg m^2/rad] at configurations ``alpha``
    (Hamabe, Part I, eq. 11 through the valve-gear table): exact for the smooth tables, a
    difference over ``+-step`` for ``linear`` (:func:`valvegear.table_reaction_slope`).

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor's geometry and valve gear, the analysis'
        ``valve_table``; SI inside).
    alpha : float or array [rad]
        Configurations, the angle OSP.
    step : float [rad]
        Half the difference interval for the ``linear`` table.

    Returns
    -------
    tuple of float or array [N m/rad, kg m^2/rad]
        The slopes of ``C_f`` and ``C_i``.

    References
    ----------
    [hamabe] Part I, eq. (11) and Example 1's table (the slope is govopt's).

    Examples
    --------
    Hamabe's Example 1 (a), the bundled spec:

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> KGFCM = 9.80665 * 0.01

    Their sum at omega^2 = 630 is :func:`reaction_slope`:

    >>> s_f, s_i = reaction_slopes(spec, np.radians(54))
    >>> bool(np.isclose(s_f + 630 * s_i, reaction_slope(spec, np.radians(54), 630.0)))
    True
    """
    return spec.governor.reaction_slopes(alpha, spec.analysis.valve_table, step)


def reaction_slope(spec, alpha, omega2, step: float = 1e-6):
    """``dM_r0/dalpha = dC_f/dalpha + omega^2 dC_i/dalpha`` [N m/rad] at constant speed (Hamabe,
    Part I, eq. 11 through the valve-gear table; :func:`reaction_slopes`).

    Parameters
    ----------
    spec : Spec [-]
        A shaft-governor spec (its governor's geometry and valve gear, the analysis'
        ``valve_table``; SI inside).
    alpha : float or array [rad]
        Configurations, the angle OSP.
    omega2 : float or array [1/s^2]
        Square of the shaft speed.
    step : float [rad]
        Half the difference interval for the ``linear`` table.

    Returns
    -------
    float or array [N m/rad]
        The slope of the mean reaction moment.

    References
    ----------
    [hamabe] Part I, eq. (11) and Example 1's table (the slope is govopt's).

    Examples
    --------
    Hamabe's Example 1 (a), the bundled spec:

    >>> import govopt, govopt.examples
    >>> spec = govopt.load_spec(govopt.examples.example("hamabe-a"))
    >>> KGFCM = 9.80665 * 0.01

    At 54 deg, per degree: the paper's table falls from 59.4 to 49.7 kgf cm over 50 deg to
    57 deg 20', a secant of -1.32 kgf cm/deg; PCHIP's tangent is the same to 0.01:

    >>> round(float(reaction_slope(spec, np.radians(54), 630.0)) / KGFCM * np.pi / 180, 2)
    -1.32
    """
    s_f, s_i = reaction_slopes(spec, alpha, step)
    return s_f + omega2 * s_i
