"""The governor spec file's tables, declared once (:mod:`govopt.keys`): the shared tables here,
each type's ``[governor]`` keys and own tables in its module (``Governor.keys``,
``Governor.tables``), the spring kinds' keys and the ``[spring]`` form in
:mod:`govopt.springs.kinds`. :func:`spec_tables` puts one type's spec together; the parser
(:mod:`govopt.spec`), the reference (:mod:`govopt.reference`), the templates and the JSON Schema
read it.

Some shared keys depend on the type: the flying mass's name (``ball_weight``,
``pendulum_weight``), the dimensions at its coordinate (an angle or a length: the dash-pot,
the load changes, the engine's torque slope), its spring kind's section, bounds and catalogue;
so the shared tables are built for a type (:func:`spec_tables`), from one declaration.
"""

from __future__ import annotations

import functools
import math

from . import limits
from .inputs import FITTER, OBJECTIVES, VERDICTS, Analysis, Requirements
from .keys import REQUIRED, Key, Table
from .units import G_STANDARD

_REQ, _AN = Requirements(), Analysis()


def _types() -> tuple:
    from .governors import REGISTRY

    return tuple(REGISTRY)


def _grades() -> tuple:
    from .springs import materials

    return materials.GRADES


def _rules() -> tuple:
    from .springs import materials

    return materials.METHODS


def _use_cases() -> tuple:
    from .fidelity import USE_CASES

    return tuple(USE_CASES)


TYPE = Key("type", "choice", "the governor type: its own keys follow in this table",
           choices=_types)

#: ``[speed]``: the speed range to meet, as a band or as a mean speed and irregularity
SPEED = Table("speed", "the speeds the governor must float between: a band (inner, outer) or "
                       "a mean speed and irregularity", (
    Key("inner", "angular_velocity", "the lowest speed of the band, at the innermost "
                                     "configuration: every design keeps its whole operating "
                                     "band (friction included) within inner .. outer",
        when="with outer, in place of mean and irregularity"),
    Key("outer", "angular_velocity", "the highest speed of the band, at the outermost "
                                     "configuration", when="with inner"),
    Key("mean", "angular_velocity", "the mean speed omega0",
        when="with irregularity, in place of inner and outer"),
    Key("irregularity", "number", "the irregularity delta0 = (omega_a - omega_i) / omega0: "
                                  "the design's own is at most this", high=2.0, example=0.12,
        when="with mean"),
), when="required unless the spec only evaluates a given [design]", required_unless="design",
   alternatives=((("inner", "outer"), ("mean", "irregularity")),))


def material_table() -> Table:
    """``[material]``."""
    return Table("material", "the spring's material: shear values for a helical spring (or a "
                             "wire grade, whose standard gives them), E for a leaf", (
        Key("grade", "choice", "a spring wire grade of govopt/data/spring_materials.toml: its "
                               "standard gives the allowables per wire diameter, G and the "
                               "density, and the spring engineering checks run (fatigue, "
                               "tolerances)", default=None, choices=_grades,
            when="to helical springs"),
        Key("tensile_strength", "stress", "the tensile strength R_m", default=None,
            example="1600 MPa",
            when="with grade (required for grade \"custom\")"),
        Key("surface", "choice", "the wire's surface, for the fatigue check",
            default="not shot peened", choices=("not shot peened", "shot peened"),
            when="with grade"),
        Key("tolerance_grade", "choice", "the spring's EN 15800 quality grade", default=2,
            choices=(1, 2, 3), source="EN 15800", when="with grade"),
        Key("life_cycles", "number", "the required fatigue life, load cycles", default=1e7,
            low=1.0, when="with grade"),
        Key("rules", "choice", "the allowable-stress and fatigue rules", default="EN13906",
            choices=_rules, when="with grade"),
        Key("allowable_shear_stress", "stress", "the allowable shear stress k_s of a helical "
                                                "spring (a grade's rule per wire diameter "
                                                "where a grade is given)",
            default=None, source="EN 13906-1", example="400 MPa",
            when="to helical springs (required there without grade)"),
        Key("shear_modulus", "stress", "the shear modulus G", default=None, example="81.5 GPa",
            default_text="the grade's", when="to helical springs (required there without grade)"),
        Key("density", "density", "the wire's or strip's density (the spring's mass)",
            default=7850.0, default_text="the grade's, else 7850 kg/m^3"),
        Key("stress_correction", "choice", "the stress correction of a helical spring's "
                                           "static shear stress",
            default="none", choices=("none", "wahl", "bergstrasser"),
            default_text="\"none\" (with a grade: the rules' static correction)",
            source="Wahl 1944; EN 13906-1"),
        Key("elastic_modulus", "stress", "Young's modulus E of a leaf spring", default=None,
            example="206 GPa", when="to leaf springs (required there)"),
        Key("allowable_bending_stress", "stress", "the allowable bending stress of a leaf "
                                                  "spring", default=None, example="800 MPa",
            when="to leaf springs"),
    ), when="required to design a spring or to evaluate one given by its section")


def _configuration(gov) -> dict:
    """``low``/``high`` of a configuration of ``gov``'s coordinate (an angle within 0 .. 180
    deg)."""
    if gov.coordinate == "angle":
        return dict(low=0.0, high=math.pi, range_text="(0 deg, 180 deg)")
    return {}


def design_table(gov, kind) -> Table:
    """``[design]`` of governor type (class or instance) ``gov`` with a spring of ``kind``
    (:class:`govopt.springs.kinds.SpringKind`, None for none)."""
    angular = gov.coordinate == "angle"
    damping = "damping" if angular else "linear_damping"
    keys = [Key(gov.mass_key, "weight", f"each {gov.mass_name}'s weight (a force) or mass",
                example="12 kgf")]
    if gov.central_load:
        keys.append(Key("central", "weight", "the central (sleeve) load's weight or mass",
                        default=None, default_text="none"))
    if kind is not None:
        spring = "with spring_stiffness or the spring's section"
        keys += [Key("spring_stiffness", "stiffness", "the spring's stiffness kappa, in place of "
                                                      "its section", default=None,
                     when="in place of the section"),
                 *(Key(k.name, k.kind, k.meaning, default=None, source=k.source,
                       example=k.example, when="with [material], in place of spring_stiffness")
                   for k in kind.section),
                 Key(gov.free_length_key, "length", gov.free_length_meaning, default=None,
                     positive=gov.free_length_positive,
                     default_text="the normal configuration in equilibrium at the mean speed",
                     when=spring)]
    keys += [Key(f"{gov.mass_key}_inertia", "inertia" if angular else "mass",
                 f"the {gov.mass_name}'s generalised inertia about the coordinate, in place of "
                 "the type's", default=None, default_text="the type's"),
             Key("dashpot_f", damping, "the dash-pot's coefficient f", default=None,
                 nonnegative=True, default_text="none", source="Hamabe Part III"),
             Key("dashpot_a1", damping, "the load change's a1 = f/3, in place of dashpot_f",
                 default=None, nonnegative=True, default_text="none", source="Hamabe eq. 28")]
    if angular:
        keys.append(Key("friction_moment", "moment", "the Coulomb friction moment M_0 at the "
                                                     "fulcrum", default=None, nonnegative=True,
                        default_text="none", source="Hamabe eq. 42"))
    without = ("; without the spring, the spring that floats the governor between "
               "speed.inner and speed.outer" if kind is not None else "")
    return Table("design", "a given design, to evaluate (govopt evaluate; govopt design -o "
                           f"writes one){without}", tuple(keys),
                 when="read by govopt evaluate")


def engine_table(gov) -> Table:
    """``[engine]`` of governor type ``gov`` (its torque slope per unit of its travel)."""
    per = "angle" if gov.travel == "angle" else "length"
    travel = gov.coordinate_name if per == "angle" else "s (the regulating member's travel)"
    return Table("engine", "the engine the governor regulates, for the load changes and the "
                           "forced vibration", (
        Key("flywheel_inertia", "inertia", "the flywheel's moment of inertia",
            source="Hamabe Part III"),
        Key("torque_slope", f"torque_per_{per}", f"dT/d{travel}: the engine's torque per "
                                                 "unit travel of the regulating member "
                                                 "(negative: the torque falls as the governor "
                                                 "moves out)", positive=False,
            source="Hamabe Part III"),
        Key("insensibility", "number", "the insensibility eps: the load change starts at "
                                       "omega1 (1 + eps)", default=0.0, nonnegative=True,
            high=1.0, source="Hamabe Part III"),
        Key("speed_fluctuation_E2", "angular_velocity", "E2 of the crank's speed fluctuation "
                                                         "omega0 + E2 cos 2 omega0 t + F2 sin 2 "
                                                         "omega0 t", default=0.0,
            positive=False, source="Hamabe Part II"),
        Key("speed_fluctuation_F2", "angular_velocity", "F2 of the crank's speed fluctuation",
            default=0.0, positive=False, source="Hamabe Part II"),
    ))


def load_change_table(gov) -> Table:
    """``[[load_change]]`` of governor type ``gov`` (configurations of its coordinate)."""
    dim = gov.coordinate
    return Table("load_change", "a sudden load change: the governor moves from one "
                                "configuration to another; one table each", (
        Key("name", "text", "its name in reports", default="", default_text="load change N"),
        Key("from", dim, f"the configuration ({gov.coordinate_name}) before the change, within "
                         "the governor's range",
            **_configuration(gov)),
        Key("to", dim, f"the configuration ({gov.coordinate_name}) after it",
            **_configuration(gov)),
    ), array=True, when="read with [engine]", needs=("engine",))


#: ``[analysis]``'s keys of every type; a type adds its own (:attr:`Governor.analysis_keys`:
#: the shaft governor's linkage series and valve-gear settings) in :func:`analysis_table`
ANALYSIS = Table("analysis", "fidelity settings (every default is the exact model)", (
    Key("points", "count", "configurations over the range", default=_AN.points, low=2,
        high=limits.MAX_POINTS + 1, range_text=f"[3, {limits.MAX_POINTS}] (govopt's limit)"),
    Key("settling_band", "number", "the band, a fraction of the load change, within which "
                                   "the governor has settled", default=_AN.settling_band,
        high=1.0),
    Key("use_case", "choice", "what the evaluation is for: only the analyses it needs run, at "
                              "the cheapest settings within tolerance", default=None,
        default_text="none: every analysis the spec has data for", choices=_use_cases),
    Key("tolerance", "number", "the error the use case's settings may have", default=1e-6,
        high=1.0),
    Key("speed_change", "number", "the speed change c of the classic effort and power, a "
                                  "fraction, or \"range\": the governor's own",
        default=_AN.speed_change, high=1.0, choices=("range",),
        range_text="(0, 1) (a fraction of the speed, e.g. 0.01), or \"range\"",
        source="textbook 3.2"),
))


def analysis_table(gov) -> Table:
    """``[analysis]`` of governor type ``gov``: the shared settings and the type's own."""
    if not gov.analysis_keys:
        return ANALYSIS
    return Table(ANALYSIS.name, ANALYSIS.meaning, gov.analysis_keys + ANALYSIS.keys)


def requirements_table(kind) -> Table:
    """``[requirements]`` with the keys of the spring ``kind``."""
    return Table("requirements", "what govopt design must achieve", (
        Key("objective", "choice", "what the design search minimises", default=_REQ.objective,
            choices=OBJECTIVES),
        Key("k2_margin", "number", "the band on k^2: within margin omega0^2 .. (1 - "
                                   "margin) omega0^2 (stable, and clear of resonance with a "
                                   "forcing at the running speed's harmonics)",
            default=_REQ.k2_margin, nonnegative=True, high=0.5, source="Hamabe Part II",
            default_text="0.05 where the type models a forcing at the running speed's "
                         "harmonics; else not applied: only k^2 > 0 (stable, the textbook's "
                         "criterion)"),
        Key("min_range", "number", "the least range of speed (from the sleeve's lowest to its "
                                   "highest position, at nominal, without friction) as a share "
                                   "of the band speed.outer - speed.inner: a narrower range is "
                                   "more sensitive and hunts; \"envelope\": the speeds "
                                   "anywhere inside the band",
            default=_REQ.min_range, nonnegative=True, high=1.0, high_inclusive=True,
            choices=("envelope",),
            range_text="[0, 1], or \"envelope\"",
            default_text="0.5 where the band is the governor's range of speed and a spring "
                         "sets it (the textbook's and the traction governors with a spring); "
                         "else \"envelope\"",
            source="textbook Problems 2 (range of speed); traction article (hunting)"),
        Key("hurwitz_margin", "number", "the margin on the load change's stability condition "
                                        "(Hurwitz)", default=_REQ.hurwitz_margin,
            nonnegative=True, source="Hamabe eq. 32"),
        Key("max_settling_time", "time", "the longest settling time after a load change",
            default=None),
        Key("max_vibration", "angle", "the largest peak-to-peak forced vibration (a type "
                                      "forced at the running speed's harmonics)",
            default=None, source="Hamabe Part II"),
        Key("spring_index", "dimensionless", "the spring index C = 2 r / d", shape="pair",
            default=_REQ.spring_index, source="EN 13906-1 scope: 4 <= w <= 20"),
        Key("max_outer_diameter", "length", "the spring's largest outer diameter 2 r + d",
            default=None),
        Key("min_surge_frequency", "frequency", "the spring's least surge frequency",
            default=None, source="Wahl 1944 ch. 25"),
        Key("min_fatigue_safety", "number", "the spring's least fatigue safety factor under "
                                            "the mechanism's vibration", default=None,
            default_text="1 (with a grade)"),
        Key("surge_detuning", "number", "the surge frequency's least relative distance from "
                                        "each excitation harmonic", default=_REQ.surge_detuning,
            nonnegative=True),
        Key("robust_spring_grade", "count", "robust design: the spring's EN 15800 grade "
                                            "(1, 2 or 3) over whose tolerances every check "
                                            "holds", default=None, low=0.5, high=3.5,
            range_text="1, 2 or 3", source="EN 15800"),
        Key("robust_dashpot", "number", "robust design: the dash-pot setting +- this fraction",
            default=_REQ.robust_dashpot, nonnegative=True, high=0.5),
        Key("robust_masses", "number", "robust design: the flying and central masses +- this "
                                       "fraction", default=_REQ.robust_masses,
            nonnegative=True, high=0.5),
        Key("robust_torque_slope", "number", "robust design: the engine's torque slope +- "
                                             "this fraction",
            default=_REQ.robust_torque_slope, nonnegative=True, high=0.5),
        Key("adjusting_nut", "length", "made governors: the fitter adjusts the spring's free "
                                       "length by a nut, +- this (read by robust design and "
                                       "the yield)", default=_REQ.adjusting_nut,
            nonnegative=True),
        Key("dashpot_valve", "number", "made governors: the fitter sets the dash-pot valve "
                                       "within +- this fraction (read by robust design and "
                                       "the yield)", default=_REQ.dashpot_valve,
            nonnegative=True, high=0.9),
        Key("robust_samples", "count", "robust design: Monte-Carlo verification samples",
            default=_REQ.robust_samples, low=9, high=limits.MAX_ROBUST_SAMPLES + 1,
            range_text=f"[10, {limits.MAX_ROBUST_SAMPLES}]"),
        Key("robust_seed", "count", "robust design: the Monte-Carlo seed (and the seed of the "
                                   "yield's samples)",
            default=_REQ.robust_seed, nonnegative=True),
        Key("min_yield", "number", "the least yield: the share of governors made to the stated "
                                   "tolerances (the wire grade's tolerance_grade, or "
                                   "robust_spring_grade, and the robust_* spreads) that meet "
                                   "every requirement; the design search keeps only designs "
                                   "whose yield is at least this at 95 % confidence",
            default=None, high=1.0, example=0.99, range_text="(0, 1), e.g. 0.99",
            source="the yield's Wilson interval (Wilson 1927)"),
        Key("verdict", "choice", "whose verdict a spring governor gets: made (the governors "
                                 "made to the tolerances and set by the fitter: PASS where "
                                 "their yield meets min_yield, default 0.95) or nominal (the "
                                 "nominal design's checks alone; also --nominal)",
            default=_REQ.verdict, choices=VERDICTS),
        Key("fitter", "choice", "sets: the fitter sets each made governor as its type declares "
                                "(a spring's preload, bringing the inner end of the range to "
                                "the design's speed); none: made governors are taken as made",
            default=_REQ.fitter, choices=FITTER),
        *(kind.requirements if kind is not None else ()),
    ), when="read by govopt design")


def bounds_table(gov, kind) -> Table:
    """``[bounds]`` of governor type ``gov`` with a spring of ``kind``."""
    damping = "damping" if gov.coordinate == "angle" else "linear_damping"
    return Table("bounds", "the search bounds of govopt design (not requirements of a made "
                           "part: a design is not checked against them)", (
        Key(gov.mass_key, "weight", f"each {gov.mass_name}'s weight (or mass) searched",
            shape="pair", default=_REQ.flying_mass),
        *([Key("central", "weight", "the central (sleeve) load's weight (or mass) searched; "
                                    "one value fixes it", shape="pair", single=True,
               nonnegative=True, default=_REQ.central_mass,
               default_text="[0, 0] kg: no central load")]
          if gov.central_load else []),
        Key("dashpot_f", damping, "the dash-pot coefficients searched", shape="pair",
            default=None, default_text="any that meets the load-change requirements"),
        *(kind.bounds if kind is not None else ()),
    ), when="read by govopt design")


def catalogue_table(kind) -> Table:
    """``[catalogue]`` with the keys of the spring ``kind``."""
    return Table("catalogue", "the sizes govopt design may choose from", (
        Key("weight_step", "force", "the step of the flying and central weights",
            default=_REQ.mass_step * G_STANDARD, default_text=f"{_REQ.mass_step:g} kgf"),
        *(kind.catalogue if kind is not None else ()),
    ), when="read by govopt design")


def governor_table(gov) -> Table:
    """``[governor]`` of governor type ``gov``: ``type`` and the type's keys."""
    return Table("governor", gov.title, (TYPE, *gov.keys), required=True,
                 alternatives=gov.key_alternatives)


def top_table(tables) -> Table:
    """The top level of a spec with ``tables`` (:class:`Table` objects; sub-tables such as
    ``valve_gear.table`` are keys of their parent)."""
    return Table("", "the spec file", (
        Key("name", "text", "the spec's name in reports", default="",
            default_text="the file's name"),
        Key("description", "text", "one line saying what the spec is", default=""),
        *(Key(t.name, "table", t.meaning, default=REQUIRED if t.required else None,
              when=t.when) for t in tables if "." not in t.name)))


#: ``[study]``: a trade study's own table, read by govopt study
STUDY = Table("study", "a trade study's sweep and settings (read by govopt study)", open=True)


@functools.cache
def spec_tables(type_name: str) -> dict[str, Table]:
    """Every table of a spec of governor type ``type_name``, by path, the top level (``""``)
    first, in the order a spec writes them: ``[governor]``, the type's own tables,
    ``[speed]``, ``[material]``, ``[design]``, ``[engine]``, ``[[load_change]]``,
    ``[analysis]``, ``[requirements]``, ``[bounds]``, ``[catalogue]``, ``[spring]`` (where
    the type has a helical spring), and ``[study]`` (a trade study's, read by govopt study).

    >>> t = spec_tables("hartnell")
    >>> t["governor"].key("sleeve_lift").kind, "ball_weight" in t["bounds"].names
    ('length', True)
    """
    from .governors import governor_class
    from .springs.kinds import FORM

    gov = governor_class(type_name)
    kind = gov.declared_spring_kind()
    tables = [governor_table(gov), *gov.tables, SPEED, material_table(),
              design_table(gov, kind), engine_table(gov), load_change_table(gov),
              analysis_table(gov), requirements_table(kind), bounds_table(gov, kind),
              catalogue_table(kind)]
    if kind is None or kind.helical:
        tables.append(FORM)
    tables.append(STUDY)
    return {"": top_table(tables), **{t.name: t for t in tables}}


__all__ = ["ANALYSIS", "SPEED", "STUDY", "TYPE", "analysis_table", "bounds_table",
           "catalogue_table", "design_table", "engine_table", "governor_table", "load_change_table",
           "material_table", "requirements_table", "spec_tables", "top_table"]
