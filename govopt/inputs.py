"""The spec's content as plain SI objects, below the physics that reads them.

:mod:`govopt.spec` parses a TOML spec into these; the analyses (:mod:`govopt.analysis`), the
evaluator and the optimiser take them. Nothing here reads a file or imports a governor type, so
the physics never depends on the parser (the file name is added to an error at the edge, by the
parser).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # annotations only: a governor type is a plug above this module, and an
    from .governors.base import Governor  # Entry is what the spec's reader records
    from .reader import Entry



@dataclass(frozen=True)
class Speed:
    """Mean speed ``omega0`` and irregularity ``delta0`` with the paper's split of the range."""

    omega_mean: float
    irregularity: float
    #: the spec states the band ``[speed] inner/outer``: every design keeps its whole operating
    #: band (friction band included) inside it (:data:`govopt.analysis.statics.BAND_INNER`);
    #: ``mean``/``irregularity`` state only Hamabe's irregularity about the mean
    band: bool = False

    @property
    def omega_inner(self) -> float:
        return self.omega_mean * (1.0 - self.irregularity / 2.0)

    @property
    def omega_outer(self) -> float:
        return self.omega_mean * (1.0 + self.irregularity / 2.0)


@dataclass(frozen=True)
class Material:
    """The spring's material (SI): shear values for a helical spring, E for a leaf."""

    allowable_shear_stress: float | None
    shear_modulus: float | None
    density: float
    stress_correction: str
    elastic_modulus: float | None = None
    allowable_bending_stress: float | None = None
    #: spring wire grade (``govopt/data/spring_materials.toml``, e.g. ``"EN10270-1 DH"``): the
    #: allowables follow from the standard's rules per wire diameter (explicit values override)
    #: and the spring engineering checks run (:mod:`govopt.springs.engineering`)
    grade: str | None = None
    tensile_strength: float | None = None  # R_m for grade "custom" (or to override), Pa
    surface: str = "not shot peened"  # the surface the fatigue check assumes
    tolerance_grade: int = 2  # EN 15800 quality grade 1, 2 or 3
    life_cycles: float = 1e7  # required fatigue life
    rules: str = "EN13906"  # allowable-stress and fatigue rules: "EN13906" or "Shigley"


@dataclass(frozen=True)
class SpringForm:
    """``[spring]``: the helical spring's form for the spring engineering checks (SI).

    ``ends`` (:data:`govopt.springs.compression.END_FORMS`) and ``seating``
    (:data:`~govopt.springs.compression.SEATING`) of a compression spring, its ``inactive_turns``
    (``n_t = n + 2`` for closed ends, EN 13906-1), ``overtravel``: the deflection beyond full
    lift (overspeed margin) as a fraction of the working stroke; an extension spring's
    ``initial_tension`` (default: the middle of Shigley's preferred range, at most the least
    working force) and ``hook_bend_radius`` (default ``2 d``)."""

    ends: str = "closed_ground"
    seating: str = "fixed-fixed"
    inactive_turns: float = 2.0
    overtravel: float = 0.1
    initial_tension: float | None = None
    hook_bend_radius: float | None = None


@dataclass(frozen=True)
class Design:
    """A given design: flying mass, spring, central load, dash-pot and friction, SI.

    ``flying_inertia`` overrides the type's generalised inertia; ``friction_moment`` is the
    shaft governor's Coulomb moment at the fulcrum (Hamabe eq. 42)."""

    flying_mass: float  # the flying mass: the pendulum, each ball or each fly weight, kg
    wire_diameter: float | None = None
    coil_radius: float | None = None
    active_turns: float | None = None
    free_half_length: float | None = None  # the spring's free length in the type's own form
    central_mass: float | None = None  # central (sleeve) load, kg
    spring_stiffness: float | None = None  # given directly instead of by wire, coil and turns
    leaf_width: float | None = None  # a leaf spring's section, m
    leaf_thickness: float | None = None
    flying_inertia: float | None = None
    dashpot: float | None = None
    friction_moment: float | None = None


@dataclass(frozen=True)
class Engine:
    flywheel_inertia: float
    torque_slope: float
    insensibility: float = 0.0
    speed_fluctuation_cos: float = 0.0
    speed_fluctuation_sin: float = 0.0


@dataclass(frozen=True)
class LoadChange:
    name: str
    alpha_from: float
    alpha_to: float


@dataclass(frozen=True)
class Analysis:
    """Fidelity settings shared by every analysis."""

    geometry: str = "exact"
    reaction_speed: str = "local"
    #: the spec's mean speed, rad/s: for fidelity options that take a quantity at the mean speed
    #: (Hamabe's ``reaction_speed = "mean"``); set by the parser from [speed]
    omega_mean: float = float("nan")
    reaction_slope: bool = True
    #: interpolant of the valve-gear table: "pchip" (monotone C^1), "cubic" (C^2 spline) or
    #: "linear" (the paper's; d delta/d alpha and so k^2 jump at each row)
    valve_table: str = "pchip"
    points: int = 31
    harmonics: int = 12
    settling_band: float = 0.02
    #: what the evaluation is for (:mod:`govopt.fidelity`): only the analyses it needs run, at
    #: the cheapest settings whose measured error is within ``tolerance``; None: every analysis
    #: the spec has data for, at the settings above
    use_case: str | None = None
    tolerance: float = 1e-6
    #: the speed change ``c`` of the classic effort and power (Rattan: "a given percentage change
    #: of speed"), a fraction, or ``"range"``: the governor's own, from its lowest to its highest
    #: speed (the textbook's problems: a Porter's effort over its range, a Hartnell's over its
    #: lift)
    speed_change: float | str = 0.01


#: ISO 3 R20 preferred numbers, 1 mm to 25 mm: the default catalogue of wire diameters (m).
PREFERRED_WIRE = tuple(x / 1000 for x in (
    1.0, 1.12, 1.25, 1.4, 1.6, 1.8, 2.0, 2.24, 2.5, 2.8, 3.15, 3.55, 4.0, 4.5, 5.0, 5.6, 6.3, 7.1,
    8.0, 9.0, 10.0, 11.2, 12.5, 14.0, 16.0, 18.0, 20.0, 22.4, 25.0))

OBJECTIVES = ("moving_mass", "spring_mass", "settling_time", "vibration")
#: whose verdict (``requirements.verdict``) and what the fitter does (``requirements.fitter``)
VERDICTS, FITTER = ("made", "nominal"), ("sets", "none")


@dataclass(frozen=True)
class Requirements:
    """What `govopt design` must achieve, within which bounds, from which catalogue (SI)."""

    objective: str = "moving_mass"
    k2_margin: float = 0.05
    hurwitz_margin: float = 0.1
    max_settling_time: float | None = None
    max_vibration: float | None = None
    spring_index: tuple[float, float] = (4.0, 16.0)
    max_outer_diameter: float | None = None
    min_surge_frequency: float | None = None
    #: least fatigue safety factor of the spring under the mechanism's own vibration (with a
    #: material grade; None: 1)
    min_fatigue_safety: float | None = None
    #: least relative distance of the surge frequency from each excitation harmonic present
    surge_detuning: float = 0.2
    flying_mass: tuple[float, float] = (2.0, 20.0)  # the flying mass (pendulum, each ball)
    central_mass: tuple[float, float] = (0.0, 0.0)  # central (sleeve) load, kg
    wire_diameter: tuple[float, float] = (0.001, 0.025)
    coil_radius: tuple[float, float] = (0.01, 0.1)
    active_turns: tuple[float, float] = (3.0, 30.0)
    dashpot: tuple[float, float] | None = None
    wire_diameters: tuple[float, ...] = PREFERRED_WIRE
    turn_step: float = 0.5
    coil_radius_step: float = 0.001
    mass_step: float = 0.25
    leaf_width: tuple[float, float] = (0.003, 0.06)  # a leaf's section bounds, m
    leaf_thickness: tuple[float, float] = (0.0002, 0.006)
    max_bow_ratio: float = 0.2  # bow / length: the article's stated range of its eq. 8
    #: robust requirements (:mod:`govopt.optimize.robust`): every check holds over a tolerance
    #: box. The spring's EN 15800 quality grade (coil diameter, free length; the wire per its
    #: EN 10270 grade); None: the spring is taken exact
    robust_spring_grade: int | None = None
    robust_dashpot: float = 0.0  # the dash-pot setting +- this fraction
    robust_masses: float = 0.0  # the flying and central masses +- this fraction
    robust_torque_slope: float = 0.0  # the engine's torque slope +- this fraction
    #: what the fitter adjusts on assembly: the spring's free length by an adjusting nut, +- m
    adjusting_nut: float = 0.0
    #: the fitter sets the dash-pot valve within +- this fraction of the design's setting
    dashpot_valve: float = 0.0
    robust_samples: int = 2000  # Monte-Carlo verification: samples and seed
    robust_seed: int = 0
    #: the least yield of made governors (:mod:`govopt.made`): the design search keeps only
    #: designs whose yield under the stated tolerances is at least this; None: not asked
    min_yield: float | None = None
    #: whose verdict a spring governor's design and evaluation give (:mod:`govopt.made`):
    #: ``"made"``, the governors made to the tolerances and set by the fitter (PASS where their
    #: yield meets ``min_yield``, default :data:`govopt.made.DEFAULT_MIN_YIELD`), or
    #: ``"nominal"``, the nominal design's checks alone
    verdict: str = "made"
    #: whether the fitter sets each made governor as its type declares
    #: (:meth:`govopt.governors.base.Governor.adjustments`): ``"sets"``, or ``"none"``
    fitter: str = "sets"

    @property
    def robust(self) -> bool:
        """Whether the requirements ask for a design over a tolerance box (robust design: a
        ``robust_*`` spread, every check over the box) or for a yield (``min_yield``). The
        fitter's ranges alone (``adjusting_nut``, ``dashpot_valve``) ask for neither: they say
        how a made governor is set, which the yield beside the verdict counts."""
        return (self.robust_spring_grade is not None or self.robust_dashpot > 0
                or self.robust_masses > 0 or self.robust_torque_slope > 0
                or self.min_yield is not None)


@dataclass(frozen=True)
class Spec:
    path: str
    name: str
    governor_type: str
    governor: Governor
    speed: Speed | None
    material: Material | None
    design: Design | None
    engine: Engine | None
    load_changes: tuple[LoadChange, ...]
    analysis: Analysis
    requirements: Requirements | None = None
    entries: tuple[Entry, ...] = field(default=(), repr=False)
    #: the TOML as read (keys as in the file), for :meth:`with_values`; set by :func:`parse_spec`
    data: dict | None = field(default=None, repr=False, compare=False)
    spring_form: SpringForm = field(default_factory=SpringForm)
    #: where ``[design]`` gives no spring and ``[speed]`` a band: the spring that makes the
    #: governor float between the band's speeds (:func:`govopt.spec.band_spring`), SI:
    #: ``stiffness``, ``free_length`` (the type's form), ``force_inner`` and ``force_outer`` (N);
    #: else None
    band_spring: dict | None = field(default=None, compare=False)
    #: ``"nominal"`` where the command line asks for the nominal verdict (``--nominal``),
    #: whatever ``requirements.verdict`` says; else ``"made"`` (:mod:`govopt.made`)
    verdict: str = "made"

    def with_analysis(self, **changes) -> Spec:
        """The same spec with some fidelity settings changed."""
        return replace(self, analysis=replace(self.analysis, **changes))

    def with_design(self, design: Design) -> Spec:
        return replace(self, design=design)

