"""The spring spec file's keys, declared once (:mod:`govopt.keys`): the spec `govopt spring`
(design) and `govopt spring check` read, whose ``[spring]`` keys are the commands' options with
underscores (``max_outer_diameter`` is ``--max-outer-diameter``).

Three forms of ``[spring]``, told apart by their keys (:func:`form`):

* :data:`DESIGN`: a spring to design (`govopt spring SPEC`): its forces and stiffness, the wire
  and the rules, the space it works in, the objective, the wire sizes it is ordered in;
* :data:`SANDGREN`: ``problem = "sandgren-1990"``, a problem of the literature with its data;
* :data:`CHECK`: a spring you have (`govopt spring check SPEC`): its geometry
  (:data:`GEOMETRY`), material, loads and rules.

The parser (:mod:`govopt.spring_command`) reads these declarations, and the command's options
take their help from them (:func:`govopt.spec_docs.option_help`); the reference
(``docs/reference/spring-spec.md``), the templates (``govopt init --type spring`` and
``spring-check``) and the JSON Schema (``govopt schema``) are generated from them. Keys a spring
shares with a governor spec's ``[spring]`` form (its end form, seating and initial tension) are
that form's (:data:`govopt.springs.kinds.FORM`).

>>> form({"force": "500 N"}), form({"wire_diameter": "3 mm"}), form({"problem": "x"})
('design', 'check', 'sandgren-1990')
>>> DESIGN.key("coil_step").range_words()
'(0, 1] (0.25, 0.5 or 1 usual)'
"""

from __future__ import annotations

from dataclasses import replace

from .keys import Key, Table
from .springs.kinds import FORM

#: ``objective`` choices and the GP objective each minimises
OBJECTIVES = {"mass": "mass", "volume": "volume", "solid length": "solid length",
              "outer diameter": "outer diameter", "energy per mass": "mass per energy"}
#: the literature's problems a spring spec may state (``problem``)
PROBLEMS = ("sandgren-1990",)


def _grades() -> tuple:
    from .springs import materials

    return materials.GRADES


def _methods() -> tuple:
    from .springs import materials

    return materials.METHODS


def _hooks() -> tuple:
    from .springs import extension as he

    return tuple(he.HOOKS)


# -- keys a designed and a checked spring share -------------------------------------------------

KIND = Key("kind", "choice", "the spring's kind", default="compression",
           choices=("compression", "extension"))
MATERIAL = Key("material", "choice", "the wire grade (govopt/data/spring_materials.toml): its "
                                     "standard gives the allowables per wire diameter, G and the "
                                     "density, and the spring maker's checks run",
               default=None, choices=_grades, example="EN10270-1 SH",
               default_text="none (give allowable_stress and shear_modulus)")
TENSILE_STRENGTH = Key("tensile_strength", "stress", "the wire's tensile strength R_m",
                       default=None, when="with material \"custom\", where it is required",
                       example="1600 MPa")
SHEAR_MODULUS = Key("shear_modulus", "stress", "the shear modulus G (required without a "
                                               "material)",
                    default=None, default_text="the grade's (at the wire's diameter where it "
                                               "steps with it)", example="81.5 GPa")
ALLOWABLE_STRESS = Key("allowable_stress", "stress", "the allowable shear stress k_s (required "
                                                     "without a material; with one, it replaces "
                                                     "the grade's rule)",
                       default=None, default_text="the grade's rule", example="600 MPa")
DENSITY = Key("density", "density", "the wire's density (the spring's mass)", default=None,
              default_text="the grade's, else 7850 kg/m^3")
CORRECTION = Key("correction", "choice", "the correction of the static shear stress",
                 default=None, choices=("wahl", "bergstrasser", "none"),
                 default_text="\"wahl\" (with a material: its rules' choice)",
                 source="Wahl 1944; EN 13906-1")
RULES = Key("rules", "choice", "the allowable-stress and fatigue rules", default="EN13906",
            choices=_methods)
ENDS = replace(FORM.key("ends"), default=None, default_text="\"closed_ground\"",
               when="to compression springs")
SEATING = replace(FORM.key("seating"), when="to compression springs")
LOOPS = Key("loops", "choice", "an extension spring's end loops", default=None, choices=_hooks,
            default_text="\"full_loop\"", source="EN 13906-2", when="to extension springs")
MIN_FORCE = Key("min_force", "force", "the least working force F1, at length_1 (an extension "
                                      "spring's initial tension stays below it)",
                default=None, nonnegative=True, default_text="0 N", example="100 N")
LENGTH_1 = Key("length_1", "length", "the working (installed) length L1 at min_force",
               default=None, when="to compression springs", example="80 mm")
FATIGUE_MIN_FORCE = Key("fatigue_min_force", "force", "the least force of the fatigue load "
                                                      "cycle (with fatigue_max_force and a "
                                                      "material)",
                        default=None, nonnegative=True, default_text="none (no load cycle)",
                        example="100 N")
FATIGUE_MAX_FORCE = Key("fatigue_max_force", "force", "the largest force of the fatigue load "
                                                      "cycle", default=None,
                        default_text="none (no load cycle)", example="400 N")
MIN_FATIGUE_SAFETY = Key("min_fatigue_safety", "number", "the least fatigue safety factor",
                         default=1.0)
LIFE = Key("life", "number", "the required life, load cycles", default=1e7)
PEENED = Key("peened", "flag", "shot-peened wire (its fatigue strength)", default=False)
LOAD = Key("load", "choice", "how the spring is loaded: static (or quasi-static), or dynamic "
                            "(the sum of least gaps S_a x1.5)", default=None,
           choices=("static", "dynamic"), source="EN 13906-1",
           default_text="\"dynamic\" with a load cycle (fatigue_max_force), else \"static\"")
ELASTIC_MODULUS = Key("elastic_modulus", "stress", "the elastic modulus E (buckling; an "
                                                   "extension spring's active coils n_b + G/E)",
                      default=None, default_text="the grade's, else 206 GPa (EN 10270-1 steel's)",
                      example="206 GPa")
INDEX_MIN = Key("index_min", "number", "the least spring index D/d", default=4.0,
                source="EN 13906-1 scope; Shigley's preferred range")

# -- [spring] of a spring to design ---------------------------------------------------------------

#: ``[spring]`` of a spring to design (`govopt spring SPEC`), in reading order (the first
#: length's and force's units written are the report's)
DESIGN = Table("spring", "a spring to design: its forces and stiffness, its wire and rules, the "
                         "space it works in, what to minimise", (
    Key("force", "force", "the largest working force F2, at length_2", example="500 N"),
    Key("stiffness", "stiffness", "the spring's rate R (the least one, with max_stiffness)",
        default=None, default_text="from the forces and the stroke (two of length_1, "
                                   "length_2 and stroke, with min_force)", example="10 N/mm"),
    Key("max_stiffness", "stiffness", "the largest stiffness (a stiffness range: any rate from "
                                      "stiffness to this is accepted)",
        default=None, default_text="none (the stiffness as given)", example="20 N/mm"),
    ALLOWABLE_STRESS, SHEAR_MODULUS, DENSITY, TENSILE_STRENGTH, CORRECTION, MATERIAL, KIND, RULES,
    ENDS, SEATING,
    Key("objective", "choice", "what to minimise (the mass of all coils of wire, the "
                               "optimisation literature's volume (n + end coils) D d^2, the "
                               "solid length, the outer diameter, or the most stored energy per "
                               "mass)", default="mass",
        choices=tuple(OBJECTIVES)),
    INDEX_MIN,
    Key("index_max", "number", "the largest spring index D/d", default=12.0,
        source="Shigley's preferred range; EN 13906-1 allows 20"),
    Key("turns_min", "number", "the least active turns (fewer coil poorly and load unevenly)",
        default=3.0),
    Key("turns_max", "number", "the most active turns", default=None, default_text="none"),
    MIN_FORCE, FATIGUE_MIN_FORCE, FATIGUE_MAX_FORCE, MIN_FATIGUE_SAFETY, LIFE, PEENED,
    Key("max_outer_diameter", "length", "the largest outside diameter D + d (the bore it works "
                                        "in)", default=None, example="40 mm"),
    Key("max_body_length", "length", "the longest close-wound body", default=None,
        example="100 mm"),
    Key("min_surge_frequency", "frequency", "the least surge frequency", default=None,
        source="Wahl 1944 ch. 25", example="40 Hz"),
    Key("min_wire_diameter", "length", "the thinnest wire", default=None, example="2 mm"),
    Key("max_wire_diameter", "length", "the thickest wire", default=None, example="6 mm"),
    Key("min_inside_diameter", "length", "the least inside diameter D - d (over a rod)",
        default=None, example="20 mm"),
    Key("max_free_length", "length", "the longest free length (the least free length that "
                                     "keeps the coils clear at force is taken)",
        default=None, when="to compression springs", example="150 mm"),
    Key("max_solid_length", "length", "the longest solid length", default=None,
        when="to compression springs", example="50 mm"),
    LENGTH_1,
    Key("length_2", "length", "the installed length L2 at force (the coils stay clear there, "
                              "and the free length is L2 + F2 / R)", default=None,
        source="EN 13906-1: L2 >= L_n = L_c + S_a", when="to compression springs",
        example="50 mm"),
    Key("stroke", "length", "the working stroke H = L1 - L2 (the stiffness is then (F2 - F1) "
                              "/ H)",
        default=None, example="30 mm"),
    Key("wire_sizes", "length", "the wires to order from (\"preferred\": the grade's "
                                "standard's diameters, listed with their source in govopt's "
                                "data/wire_sizes.toml: EN 10270-1's nominal sizes, ASTM "
                                "A228's; other grades the ISO 3 R20 series govopt design uses; "
                                "a list of wire diameters; \"continuous\": any wire and coils)",
        shape="list", choices=("preferred", "continuous"), default=None,
        default_text="\"preferred\" with a material, else \"continuous\"",
        example=["2.5 mm", "2.8 mm", "3 mm"]),
    Key("coil_step", "number", "the step of the active coils (an extension spring's body "
                               "coils) with wire sizes to order from",
        default=None, default_text="0.5 with wire sizes to order from", high=1.0,
        high_inclusive=True, range_text="(0, 1] (0.25, 0.5 or 1 usual)", example=0.5),
    LOOPS,
    Key("catalogue", "text", "a maker's catalogue of compression springs to pick from, a CSV "
                             "file (columns part_number, d, D or OD, L0, n, ends, material, "
                             "rate; units in brackets: 'd (mm)'); the lightest spring of it "
                             "that meets the requirements and passes every check; \"sample\": "
                             "govopt's made-up sample", default=None,
        default_text="none (the spring is designed)", example="stock.csv"),
))

# -- [spring] of a problem of the literature ------------------------------------------------------


def _sandgren(name: str, kind: str, meaning: str, example: str) -> Key:
    return Key(name, kind, meaning, default=None, default_text="the problem's",
               source="Sandgren 1990", example=example)


#: ``[spring]`` of Sandgren's (1990) mixed-discrete compression spring (``problem``): its data
SANDGREN = Table("spring", "a problem of the literature with its data: Sandgren's (1990) "
                           "mixed-discrete compression spring, the least wire volume from his "
                           "table of wires with whole coils; a key left out takes the published "
                           "problem's value (the bundled sandgren-1990.toml gives each)", (
    Key("problem", "choice", "the problem", choices=PROBLEMS),
    _sandgren("force", "force", "the largest force F_max", "1000 lbf"),
    _sandgren("min_force", "force", "the preload force F_load", "300 lbf"),
    _sandgren("allowable_stress", "stress", "the allowable Wahl-corrected shear stress S",
              "189000 psi"),
    _sandgren("shear_modulus", "stress", "the shear modulus G", "11.5e6 psi"),
    _sandgren("max_free_length", "length", "the longest free length l_max", "14 in"),
    _sandgren("min_wire_diameter", "length", "the thinnest wire d_min", "0.2 in"),
    _sandgren("max_outer_diameter", "length", "the largest outside diameter D + d", "3 in"),
    _sandgren("max_preload_deflection", "length", "the largest preload deflection F_load / K",
              "6 in"),
    _sandgren("min_working_deflection", "length", "the least working deflection (F_max - "
                                                  "F_load) / K", "1.25 in"),
))

# -- [spring] of a spring you have -----------------------------------------------------------------

#: the geometry of a spring you have (a design spec cannot have it: it is a check's)
GEOMETRY = (
    Key("wire_diameter", "length", "the wire diameter d", example="3 mm"),
    Key("mean_diameter", "length", "the mean coil diameter D (give it or outer_diameter)",
        default=None, default_text="from outer_diameter", example="16 mm"),
    Key("outer_diameter", "length", "the outside diameter D + d, in place of mean_diameter",
        default=None, example="19 mm"),
    Key("active_coils", "number", "the active coils n (required for a compression spring; an "
                                  "extension spring may give total_coils instead)",
        default=None, default_text="an extension spring's from total_coils", example=9.5),
    Key("total_coils", "number", "the total coils n_t (an extension spring's: its body "
                                 "coils)", default=None,
        default_text="n + the end form's inactive coils (an extension spring's from n)",
        example=11.5),
    Key("free_length", "length", "the free length L0 (required for a compression spring; an "
                                 "extension spring's is inside its loops)",
        default=None, default_text="an extension spring's from its loops", example="60 mm"),
    replace(FORM.key("initial_tension"), when="to extension springs", example="20 N"),
)

#: ``[spring]`` of a spring you have (`govopt spring check SPEC`), in reading order
CHECK = Table("spring", "a spring you have: its geometry, material, working forces or lengths, "
                        "load cycle and rules", (
    *GEOMETRY,
    Key("tolerance_grade", "choice", "the spring's EN 15800 quality grade (its tolerances)",
        default=2, choices=(1, 2, 3), source="EN 15800"),
    KIND, MATERIAL, TENSILE_STRENGTH, SHEAR_MODULUS, ELASTIC_MODULUS, ALLOWABLE_STRESS, DENSITY,
    CORRECTION, RULES, ENDS, SEATING, LOAD,
    Key("force", "force", "the largest working force F2 (give it or length_2)", default=None,
        default_text="from length_2 and the rate", example="400 N"),
    MIN_FORCE, LENGTH_1,
    Key("length_2", "length", "the working length L2 (the force there follows from the "
                              "rate; in place of force)", default=None, example="50 mm"),
    FATIGUE_MIN_FORCE, FATIGUE_MAX_FORCE, MIN_FATIGUE_SAFETY, LIFE, PEENED, INDEX_MIN,
    Key("index_max", "number", "the largest spring index D/d", default=20.0,
        source="EN 13906-1 scope"),
    LOOPS,
))

# -- the file ---------------------------------------------------------------------------------

NAME = Key("name", "text", "the spring's name (reports, plot titles)", default="",
           default_text="the file's name (options alone: what the spring is)")
DESCRIPTION = Key("description", "text", "one line saying what the spec is", default="")

#: each form of ``[spring]`` by name (:func:`form`), with the command that reads it
FORMS = {"design": (DESIGN, "govopt spring"), "sandgren-1990": (SANDGREN, "govopt spring"),
         "check": (CHECK, "govopt spring check")}

#: the templates ``govopt init --type NAME`` writes of a spring spec: NAME -> (the form of its
#: ``[spring]``, the values it starts from: a bundled example's name, or the values, and its
#: description); each runs as written
TEMPLATES = {
    "spring": ("design", "spring-500n", "a spring to design"),
    # the spring of docs/how-to/spring.md, checked without its load cycle: every check passes
    "spring-check": ("check", {"wire_diameter": "3 mm", "mean_diameter": "16 mm",
                               "active_coils": 9.5, "free_length": "60 mm",
                               "material": "EN10270-1 SH", "force": "400 N",
                               "min_force": "100 N"}, "a spring you have, to check"),
}


def top_table(spring: str) -> Table:
    """The top level of a spring spec whose ``[spring]`` is ``spring`` (its meaning)."""
    return Table("", "the spring spec file", (NAME, DESCRIPTION, Key("spring", "table", spring)))


def form(spring: dict) -> str:
    """Which ``[spring]`` a spring spec's table is (the name of :data:`FORMS`): a problem's
    where it names one, a check's where it gives a spring's geometry, else a design's."""
    if "problem" in spring:  # an unknown one read as the first, whose reader names them all
        return spring["problem"] if spring["problem"] in PROBLEMS else PROBLEMS[0]
    return "check" if any(k.name in spring for k in GEOMETRY) else "design"


def tables(name: str) -> dict[str, Table]:
    """The tables of a spring spec of form ``name`` (:data:`FORMS`) by path, the top level
    (``""``) first, as :func:`govopt.spec_keys.spec_tables` gives a governor spec's."""
    spring = FORMS[name][0]
    return {"": top_table(spring.meaning), "spring": spring}


def defaults(table: Table) -> dict:
    """The values of ``table``'s keys left out (SI): the declared defaults that are values
    (the others, None, say in words what the command takes)."""
    return {k.name: k.default for k in table.keys
            if not k.required and k.default is not None and not callable(k.default)}


__all__ = ["CHECK", "DESCRIPTION", "DESIGN", "FORMS", "GEOMETRY", "NAME", "OBJECTIVES",
           "PROBLEMS", "SANDGREN", "TEMPLATES", "defaults", "form", "tables", "top_table"]
